// File helpers behind one small interface: whole-file read and atomic write.
#pragma once

#include <fstream>
#include <memory>
#include <string>

#include "core/status.h"

namespace squawk::files {

// Reads a whole file as bytes. Error names the path and the OS reason.
Result<std::string> read(const std::string& path);
// A file being written safely. The target is where `path` leads (symbolic
// links resolved). A regular file or a new name: the bytes go to a temporary
// file in the target's folder, and commit() flushes, syncs and renames it
// over the target, so a crash or a failed write (ENOSPC, EIO) leaves the
// previous file as it was. A FIFO or character device (a terminal,
// /dev/null, /dev/full) is written in place. A folder, block device or socket
// is refused. Every failed write is an error naming the path; an uncommitted
// writer removes its temporary file.
class AtomicWriter {
 public:
  static Result<std::unique_ptr<AtomicWriter>> open(const std::string& path);
  ~AtomicWriter();
  AtomicWriter(const AtomicWriter&) = delete;
  AtomicWriter& operator=(const AtomicWriter&) = delete;

  std::ostream& out() { return out_; }
  Status commit();

 private:
  AtomicWriter() = default;
  std::string path_;    // as given, for messages
  std::string target_;  // where the links lead
  std::string tmp_;     // "" when written in place
  std::ofstream out_;
  bool done_ = false;
};

// Writes `data` to `path` through an AtomicWriter.
Status write_atomic(const std::string& path, const std::string& data);
bool exists(const std::string& path);
// Creates a folder and its parents (ok if it exists).
Status make_dirs(const std::string& path);

}  // namespace squawk::files
