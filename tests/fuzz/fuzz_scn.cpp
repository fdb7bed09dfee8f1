// libFuzzer target: the .scn reader on arbitrary bytes, and the parsed
// entries checked against a small stack (parse-only).
#include <cstdint>
#include <string>

#include "command/scn.h"
#include "command/stack.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 2048) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const squawk::command::ScnFile f = squawk::command::parse_scn(text);
  static const squawk::command::Stack stack = [] {
    squawk::command::Stack s(1);
    (void)s.exec("CRE KL204 B744 52 4 90 FL200 250");
    return s;
  }();
  double last = -1e18;
  for (size_t k = 0; k < f.entries.size(); ++k) {
    if (f.entries[k].time < last) __builtin_trap();  // must be sorted
    last = f.entries[k].time;
    if (k < 4) (void)stack.check(f.entries[k].command);
  }
  return 0;
}
