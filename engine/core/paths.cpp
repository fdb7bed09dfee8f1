#include "core/paths.h"

#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;

namespace squawk::paths {

namespace {

constexpr const char kHomeTag[] = "@home/";

bool is_home(const fs::path& dir) {
  std::error_code ec;
  return fs::is_directory(dir / "scripts", ec) && fs::is_directory(dir / "prompts", ec);
}

// The home found from the executable's location (or the current folder).
std::string find_home() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path dir = exe.parent_path();
    for (const fs::path& cand : {dir.parent_path(), dir.parent_path() / "share" / "squawk", dir})
      if (is_home(cand)) return cand.lexically_normal().string();
  }
  return ".";  // the current folder, when it is a home, else nothing found
}

}  // namespace

std::string home() {
  if (const char* env = std::getenv("SQUAWK_HOME"); env && *env) return env;
  static const std::string found = find_home();
  return found;
}

std::string resource(const std::string& rel) { return home() + "/" + rel; }

std::string portable(const std::string& p) {
  if (p.empty() || !is_within(p, home())) return p;
  const fs::path rel = fs::path(absolute(p)).lexically_relative(absolute(home()));
  return kHomeTag + rel.string();
}

std::string resolve(const std::string& stored) {
  if (stored.rfind(kHomeTag, 0) != 0) return stored;
  return resource(stored.substr(sizeof kHomeTag - 1));
}

std::string absolute(const std::string& p) {
  std::error_code ec;
  fs::path r = fs::weakly_canonical(fs::absolute(p, ec), ec);
  if (ec) r = fs::absolute(p).lexically_normal();
  return r.string();
}

bool is_within(const std::string& p, const std::string& dir) {
  const fs::path a = absolute(p), d = absolute(dir);
  auto ai = a.begin();
  for (auto di = d.begin(); di != d.end(); ++di, ++ai) {
    if (di->empty()) continue;  // trailing slash
    if (ai == a.end() || *ai != *di) return false;
  }
  return true;
}

std::string dirname(const std::string& p) {
  fs::path parent = fs::path(p).parent_path();
  return parent.empty() ? "." : parent.string();
}

}  // namespace squawk::paths
