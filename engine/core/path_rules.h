// PathRules: the sandbox's one read check and one write check.
//
// Every path a sandboxed script can make squawk open (Lua APIs, `require`,
// TrafScript commands run from Lua, file names stored inside checkpoints)
// goes through check_read or check_write; docs/sandbox_audit.md lists them.
//
// A path is judged by where it really leads: real_path() resolves every
// symbolic link on it, on the final name and on every parent, including
// links whose target does not exist yet (a dangling link is followed to
// where a write would create the file), and applies ".." after the link
// before it, as the kernel does. The allowed folders are resolved the same
// way. Paths under /proc (the process's environment, file descriptors,
// memory) are refused whatever folders are allowed.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/status.h"

namespace squawk::paths {

// The absolute path `p` leads to with every symbolic link on it resolved
// (relative paths against the current folder). Names that do not exist stay
// as written. Error when links nest more than 40 deep (a loop).
Result<std::string> real_path(const std::string& p);

class PathRules {
 public:
  // Rules that refuse every read and write.
  PathRules() = default;
  // Rules that allow everything (--unsafe).
  static PathRules unrestricted();

  // Allows reads inside folder `dir` (and its sub-folders); "" is ignored.
  void allow_read(const std::string& dir);
  // The one folder writes may go to ("" = none).
  void allow_write(const std::string& dir);

  // Ok when `path` may be read; else an error naming `what`, the path and
  // how to allow it (--allow-read DIR, --unsafe).
  Status check_read(const std::string& path, std::string_view what) const;
  // check_read of folder `dir`, then of every symbolic link inside it (to
  // 8 levels, 100 000 entries at most): for loaders that read a folder's files.
  Status check_read_folder(const std::string& dir, std::string_view what) const;
  // Ok when `path` may be created or written; else an error naming `what`,
  // the path and the output folder (--out DIR).
  Status check_write(const std::string& path, std::string_view what) const;
  // The read / write check on the file open descriptor `fd` refers to (the
  // path the kernel resolved when it was opened, read from /proc/self/fd):
  // run after opening a checked path, it refuses a file reached through a
  // link swapped in between the check by name and the open. `shown` is the
  // name in the error; a deleted file and an fd without a path are refused.
  Status check_read_fd(int fd, const std::string& shown, std::string_view what) const;
  Status check_write_fd(int fd, const std::string& shown, std::string_view what) const;

  bool unrestricted_all() const { return all_; }
  // The readable folders, resolved.
  const std::vector<std::string>& read_dirs() const { return read_; }
  // The writable folder as given ("" = none).
  const std::string& write_dir() const { return write_given_; }

 private:
  bool all_ = false;
  std::vector<std::string> read_;  // resolved folders
  std::string write_;              // resolved folder, "" = none
  std::string write_given_;
};

}  // namespace squawk::paths
