// Runs the built squawk binary (SQUAWK_BINARY) for end-to-end tests, with no
// LLM configured from the environment and a 60 s limit.
#pragma once

#include <string>

namespace squawk::testing {

// True when the binary exists (tests skip otherwise).
bool binary_built();
struct RunOutput {
  std::string out;  // stdout and stderr together
  int rc = -1;      // exit status
};

// Runs `squawk ARGS` with `input` on stdin.
RunOutput run_squawk(const std::string& args, const std::string& input);

}  // namespace squawk::testing
