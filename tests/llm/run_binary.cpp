#include "run_binary.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>

#include "core/files.h"

namespace squawk::testing {

bool binary_built() { return files::exists(SQUAWK_BINARY); }

RunOutput run_squawk(const std::string& args, const std::string& input) {
  const std::string in_path = "/tmp/squawk_test_input_" + std::to_string(::getpid()) + ".txt";
  std::ofstream(in_path) << input;
  std::string cmd = "env -u SQUAWK_LLM_URL -u SQUAWK_LLM_MODEL -u SQUAWK_LLM_API timeout 60 ";
  cmd.append(SQUAWK_BINARY).append(" ").append(args).append(" < ").append(in_path).append(" 2>&1");
  RunOutput r;
  if (FILE* p = ::popen(cmd.c_str(), "r")) {
    char buf[4096];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
    const int status = ::pclose(p);
    r.rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::remove(in_path.c_str());
  return r;
}

}  // namespace squawk::testing
