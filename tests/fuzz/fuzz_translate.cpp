// libFuzzer target: the translation graph (offline mode: the Lua grammar
// over the C++ extractors) and the scorer on arbitrary bytes.
// Invariants: no crash, no sanitizer report, the graph never fails, and
// every answer is exactly one of a question, an error, or a non-empty list
// of non-empty commands.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "command/stack.h"
#include "script/translate_graph.h"
#include "translate/scorer.h"
#include "translate/stack_world.h"

using namespace squawk;

namespace {

script::Vm& vm() {
  static script::Vm v{script::VmOptions{}};
  return v;
}

const command::Stack& traffic() {
  static const command::Stack s = [] {
    command::Stack st;
    if (!translate::setup_stack(st, "CRE KLM123 B738 52 4 90 FL250 280 ; CRE DAL1153 B738 52 5 90 FL250 280 ; "
                                    "CRE AC01 B738 52 6 90 FL250 280 ; DEFWPT ALPHA 52.5 4.5 ; ADDWPT AC01 ALPHA")
             .is_ok())
      std::abort();
    return st;
  }();
  return s;
}

void check(const Result<translate::Translation>& r) {
  if (!r.is_ok()) std::abort();
  const auto& t = *r;
  const int outcomes = (t.asked() ? 1 : 0) + (!t.error.empty() ? 1 : 0) + (t.issued() ? 1 : 0);
  if (outcomes != 1) std::abort();
  for (const auto& c : t.commands)
    if (c.empty()) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  auto bare = script::run_translation_graph(vm(), text, {"offline", "", nullptr});
  check(bare);
  auto seen = script::run_translation_graph(vm(), text, {"offline", "", &traffic()});
  check(seen);
  (void)translate::score_case(seen->text(), seen->asked(), text);
  (void)translate::score_case(text, false, bare->text());
  return 0;
}
