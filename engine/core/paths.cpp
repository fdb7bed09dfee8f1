#include "core/paths.h"

#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;

namespace squawk::paths {

std::string home() {
  if (const char* h = std::getenv("SQUAWK_HOME"); h && *h) return h;
#ifdef SQUAWK_SOURCE_DIR
  std::error_code ec;
  if (fs::exists(fs::path(SQUAWK_SOURCE_DIR) / "scripts", ec)) return SQUAWK_SOURCE_DIR;
#endif
  return ".";
}

std::string resource(const std::string& rel) { return home() + "/" + rel; }

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
