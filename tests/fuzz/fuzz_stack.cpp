// libFuzzer target: one TrafScript line against a small traffic picture.
// Checks the contract that a failed command leaves the whole state (snapshot)
// byte-identical, on top of ASan/UBSan's memory and UB checks.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "command/stack.h"

namespace {

const squawk::command::Stack& base() {
  static const squawk::command::Stack stack = [] {
    squawk::command::Stack s(1);
    (void)s.exec("CRE KL204 B744 52 4 90 FL200 250; CRE AF1 A320 52.1 4.1 270 FL210 M.78");
    (void)s.exec("DEFWPT ALPHA 52 4.5; KL204 ADDWPT ALPHA FL200; KL204 ADDWPT 52.2 4.8");
    (void)s.exec("ASAS ON; KL204 ATALT FL210 ECHO up");
    return s;
  }();
  return stack;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 512) return 0;
  const std::string line(reinterpret_cast<const char*>(data), size);
  squawk::command::Stack s = base();
  (void)s.check(line);
  // One command at a time, so a failure can be compared with the state just before it.
  const std::string before = s.snapshot();
  auto r = s.exec(line.substr(0, line.find(';')));
  if (!r && s.snapshot() != before) {
    std::fprintf(stderr, "failed command changed the state: %s\n", line.c_str());
    std::abort();
  }
  if (r && s.sim().n() <= 50) s.step();
  return 0;
}
