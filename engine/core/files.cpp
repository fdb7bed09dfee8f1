#include "core/files.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/path_rules.h"

namespace squawk::files {

Result<std::string> read(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    return Status::io_error("cannot read '" + path + "': not a regular file (a folder or device)");
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::io_error("cannot open '" + path + "': " + std::strerror(errno));
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) return Status::io_error("cannot read '" + path + "'");
  return ss.str();
}

Result<std::unique_ptr<AtomicWriter>> AtomicWriter::open(const std::string& path) {
  SQUAWK_ASSIGN_OR_RETURN(std::string target, paths::real_path(path));
  std::unique_ptr<AtomicWriter> w(new AtomicWriter());
  w->path_ = path;
  w->target_ = target;
  struct stat st {};
  const bool present = ::stat(target.c_str(), &st) == 0;
  if (present && !S_ISREG(st.st_mode)) {
    if (!S_ISFIFO(st.st_mode) && !S_ISCHR(st.st_mode))
      return Status::io_error("cannot write '" + path + "': it is " +
                              (S_ISDIR(st.st_mode) ? "a folder" : "a block device or socket") +
                              " (squawk writes regular files, FIFOs and character devices)");
    w->out_.open(target, std::ios::binary | std::ios::out | std::ios::trunc);  // in place
  } else {
    w->tmp_ = target + ".tmp." + std::to_string(::getpid());
    w->out_.open(w->tmp_, std::ios::binary | std::ios::out | std::ios::trunc);
  }
  if (!w->out_)
    return Status::io_error("cannot create '" + (w->tmp_.empty() ? path : w->tmp_) + "': " + std::strerror(errno));
  return w;
}

AtomicWriter::~AtomicWriter() {
  if (!done_ && !tmp_.empty()) {
    out_.close();
    ::unlink(tmp_.c_str());
  }
}

Status AtomicWriter::commit() {
  done_ = true;
  out_.flush();
  const bool wrote = static_cast<bool>(out_);
  const int err = errno;
  out_.close();
  if (!wrote || out_.fail()) {
    if (!tmp_.empty()) ::unlink(tmp_.c_str());
    return Status::io_error("cannot write '" + path_ + "': " + std::strerror(err ? err : EIO) +
                            (tmp_.empty() ? "" : " (the previous file is unchanged)"));
  }
  if (tmp_.empty()) return Status::ok();
  const int fd = ::open(tmp_.c_str(), O_RDONLY);
  const bool synced = fd >= 0 && ::fsync(fd) == 0;
  if (fd >= 0) ::close(fd);
  if (!synced) {
    ::unlink(tmp_.c_str());
    return Status::io_error("cannot flush '" + tmp_ + "' to disk (the previous file is unchanged)");
  }
  struct stat st {};  // the target may have become something else meanwhile
  if (::lstat(target_.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    ::unlink(tmp_.c_str());
    return Status::io_error("cannot write '" + path_ + "': it is no longer a regular file");
  }
  if (std::rename(tmp_.c_str(), target_.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(tmp_.c_str());
    return Status::io_error("cannot rename '" + tmp_ + "' to '" + target_ + "': " + why);
  }
  return Status::ok();
}

Status write_atomic(const std::string& path, const std::string& data) {
  SQUAWK_ASSIGN_OR_RETURN(std::unique_ptr<AtomicWriter> w, AtomicWriter::open(path));
  w->out().write(data.data(), static_cast<std::streamsize>(data.size()));
  return w->commit();
}

bool exists(const std::string& path) {
  std::error_code ec;
  return std::filesystem::exists(path, ec);
}

Status make_dirs(const std::string& path) {
  std::error_code ec;
  std::filesystem::create_directories(path, ec);
  if (ec) return Status::io_error("cannot create folder '" + path + "': " + ec.message());
  return Status::ok();
}

}  // namespace squawk::files
