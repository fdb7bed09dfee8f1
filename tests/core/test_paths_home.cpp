// The squawk home and portable paths (issue 12 point 17).
#include <doctest/doctest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include "core/paths.h"

using namespace squawk;

TEST_CASE("paths inside the home are stored relative to it and resolve in another home") {
  namespace fs = std::filesystem;
  const fs::path a = fs::temp_directory_path() / ("squawk_home_a_" + std::to_string(::getpid()));
  const fs::path b = fs::temp_directory_path() / ("squawk_home_b_" + std::to_string(::getpid()));
  for (const auto& h : {a, b}) {
    fs::create_directories(h / "scripts");
    fs::create_directories(h / "prompts");
  }
  const char* old = std::getenv("SQUAWK_HOME");
  const std::string saved = old ? old : "";
  setenv("SQUAWK_HOME", a.c_str(), 1);
  const std::string stored = paths::portable((a / "prompts" / "observation.lua").string());
  CHECK(stored == "@home/prompts/observation.lua");
  CHECK(paths::portable("/etc/hosts") == "/etc/hosts");
  setenv("SQUAWK_HOME", b.c_str(), 1);  // the checkpoint moved to another checkout
  CHECK(paths::resolve(stored) == (b / "prompts" / "observation.lua").string());
  CHECK(paths::resolve("/etc/hosts") == "/etc/hosts");
  if (saved.empty()) unsetenv("SQUAWK_HOME");
  else setenv("SQUAWK_HOME", saved.c_str(), 1);
  fs::remove_all(a);
  fs::remove_all(b);
}

TEST_CASE("without SQUAWK_HOME the home is found from the executable, not the build tree") {
  const char* old = std::getenv("SQUAWK_HOME");
  const std::string saved = old ? old : "";
  unsetenv("SQUAWK_HOME");
  // Test binaries live in build/ of this checkout: the home is its parent.
  const std::string exe = std::filesystem::read_symlink("/proc/self/exe").parent_path().parent_path().string();
  CHECK(paths::home() == std::filesystem::path(exe).lexically_normal().string());
  if (!saved.empty()) setenv("SQUAWK_HOME", saved.c_str(), 1);
}
