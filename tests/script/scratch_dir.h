// A per-test scratch folder under the system's temporary directory.
//
// Contract: scratch_dir("name") returns TMP/squawk-test-name, created if
// missing; the same name gives the same folder within and across runs, so
// a test writes the files it reads there before reading them.
#pragma once

#include <filesystem>
#include <string>

namespace squawk::test {

inline std::filesystem::path scratch_dir(const std::string& name) {
  std::filesystem::path d = std::filesystem::temp_directory_path() / ("squawk-test-" + name);
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace squawk::test
