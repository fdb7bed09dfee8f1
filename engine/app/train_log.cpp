#include "app/train_log.h"

#include <cstdlib>
#include <sstream>

#include "core/files.h"

namespace squawk::app {

Status trim_log(const std::string& path, long long episodes) {
  SQUAWK_ASSIGN_OR_RETURN(std::string text, files::read(path));
  std::istringstream in(text);
  std::string line, out;
  bool header = true;
  while (std::getline(in, line)) {
    if (header || std::strtoll(line.c_str(), nullptr, 10) <= episodes) out += line + "\n";
    header = false;
  }
  return files::write_atomic(path, out);
}

}  // namespace squawk::app
