#include "core/path_rules.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <deque>
#include <filesystem>

namespace fs = std::filesystem;

namespace squawk::paths {

namespace {

constexpr int kMaxLinks = 40;  // as the kernel's ELOOP limit
constexpr long kMaxFolderEntries = 100'000;
constexpr int kMaxFolderDepth = 8;

// Pushes the components of `p` (no root, no empty or "." names) in front of `todo`.
void push_front_components(const fs::path& p, std::deque<std::string>& todo) {
  std::vector<std::string> parts;
  for (const auto& c : p.relative_path())
    if (!c.empty() && c != ".") parts.push_back(c.string());
  todo.insert(todo.begin(), parts.begin(), parts.end());
}

// True when `p` (resolved, absolute) is folder `dir` (resolved) or inside it.
bool within(const std::string& p, const std::string& dir) {
  if (dir == "/") return true;
  return p.compare(0, dir.size(), dir) == 0 && (p.size() == dir.size() || p[dir.size()] == '/');
}

bool under_proc(const std::string& p) { return within(p, "/proc"); }

// real_path; *via_proc tells whether the walk passed through /proc (where
// /proc/self/fd/N links lead back out to the file the process holds open).
Result<std::string> resolve(const std::string& p, bool* via_proc) {
  *via_proc = false;
  if (p.empty()) return Status::invalid("empty path");
  std::deque<std::string> todo;
  fs::path done = "/";
  if (fs::path(p).is_relative()) {
    std::error_code ec;
    const fs::path cwd = fs::current_path(ec);
    if (ec) return Status::io_error("cannot read the current folder: " + ec.message());
    push_front_components(cwd, todo);  // cwd is already free of links
  }
  std::deque<std::string> rest;
  push_front_components(fs::path(p), rest);
  todo.insert(todo.end(), rest.begin(), rest.end());
  int links = 0;
  while (!todo.empty()) {
    const std::string c = todo.front();
    todo.pop_front();
    if (c == "..") {
      done = done.parent_path();
      continue;
    }
    const fs::path next = done / c;
    if (under_proc(next.string())) *via_proc = true;
    struct stat st {};
    if (::lstat(next.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) {
      if (++links > kMaxLinks)
        return Status::invalid("path '" + p + "': more than 40 symbolic links (a loop?)");
      std::error_code ec;
      const fs::path target = fs::read_symlink(next, ec);
      if (ec) return Status::io_error("path '" + p + "': cannot read link '" + next.string() + "': " + ec.message());
      if (target.is_absolute()) done = "/";
      push_front_components(target, todo);
    } else {
      done = next;
    }
  }
  return done.string();
}

}  // namespace

Result<std::string> real_path(const std::string& p) {
  bool via_proc = false;
  return resolve(p, &via_proc);
}

PathRules PathRules::unrestricted() {
  PathRules r;
  r.all_ = true;
  return r;
}

void PathRules::allow_read(const std::string& dir) {
  if (dir.empty()) return;
  auto r = real_path(dir);
  if (r.is_ok()) read_.push_back(*r);
}

void PathRules::allow_write(const std::string& dir) {
  write_given_ = dir;
  write_.clear();
  if (dir.empty()) return;
  auto r = real_path(dir);
  if (r.is_ok()) write_ = *r;
}

Status PathRules::check_read(const std::string& path, std::string_view what) const {
  if (all_) return Status::ok();
  const std::string head = std::string(what) + " '" + path + "': reading it is not allowed: ";
  bool via_proc = false;
  auto r = resolve(path, &via_proc);
  if (!r.is_ok()) return Status::invalid(head + r.status().message());
  if (via_proc)
    return Status::invalid(head + "it leads through /proc, which scripts never read (run with --unsafe)");
  for (const auto& dir : read_)
    if (within(*r, dir)) return Status::ok();
  return Status::invalid(head + (*r != path ? "it leads to '" + *r + "'; " : std::string()) +
                         "the sandbox reads only the script's folder, squawk's scripts/prompts/scenarios/envs/models, "
                         "--out, --navdata and folders named with --allow-read DIR (or run with --unsafe)");
}

Status PathRules::check_read_folder(const std::string& dir, std::string_view what) const {
  SQUAWK_RETURN_IF_ERROR(check_read(dir, what));
  if (all_) return Status::ok();
  std::error_code ec;
  fs::recursive_directory_iterator it(dir, ec), end;
  long entries = 0;
  for (; !ec && it != end; it.increment(ec)) {
    if (++entries > kMaxFolderEntries)
      return Status::invalid(std::string(what) + " '" + dir + "': more than 100000 entries to check");
    if (it.depth() >= kMaxFolderDepth) it.disable_recursion_pending();
    if (it->is_symlink(ec)) SQUAWK_RETURN_IF_ERROR(check_read(it->path().string(), what));
  }
  return Status::ok();
}

Status PathRules::check_write(const std::string& path, std::string_view what) const {
  if (all_) return Status::ok();
  const std::string head = std::string(what) + " '" + path + "': writing it is not allowed: ";
  if (write_.empty())
    return Status::invalid(head + "the sandbox writes only inside the output folder given with --out DIR "
                                  "(or run with --unsafe)");
  bool via_proc = false;
  auto r = resolve(path, &via_proc);
  if (!r.is_ok()) return Status::invalid(head + r.status().message());
  if (via_proc || !within(*r, write_))
    return Status::invalid(head + (*r != path ? "it leads to '" + *r + "', " : std::string()) +
                           "outside the output folder '" + write_given_ + "'");
  return Status::ok();
}

namespace {

// The path descriptor `fd` was opened as ("" when it has none: a deleted
// file, a pipe or socket, no /proc).
std::string fd_path(int fd) {
  char link[64], target[4096];
  std::snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
  const ssize_t n = ::readlink(link, target, sizeof target - 1);
  if (n <= 0) return "";
  target[n] = '\0';
  const std::string out(target, static_cast<size_t>(n));
  if (out[0] != '/' || out.ends_with(" (deleted)")) return "";
  return out;
}


// check_read_fd / check_write_fd: `check` (check_read or check_write) applied
// to the path the kernel resolved for the open descriptor; `verb` names it.
Status check_opened(const PathRules& rules, Status (PathRules::*check)(const std::string&, std::string_view) const,
                    std::string_view verb, int fd, const std::string& shown, std::string_view what) {
  const std::string real = fd_path(fd);
  const std::string head = std::string(what) + " '" + shown + "': " + std::string(verb) + " it is not allowed: ";
  if (real.empty()) return Status::invalid(head + "the file opened has no path");
  const Status st = (rules.*check)(real, what);
  if (st.is_ok()) return st;
  return Status::invalid(head + "the file opened is '" + real + "' (a link changed after the check)");
}

}  // namespace

Status PathRules::check_read_fd(int fd, const std::string& shown, std::string_view what) const {
  if (all_) return Status::ok();
  return check_opened(*this, &PathRules::check_read, "reading", fd, shown, what);
}

Status PathRules::check_write_fd(int fd, const std::string& shown, std::string_view what) const {
  if (all_) return Status::ok();
  return check_opened(*this, &PathRules::check_write, "writing", fd, shown, what);
}

}  // namespace squawk::paths
