// Calling the Lua translation graph (scripts/translate/graph.lua, the
// `translate.graph` module) from C++: what `squawk eval-translate --mode
// single|multi` uses. The graph is the LLM-backed translator; the offline
// grammar is one of its nodes.
//
// Contract of the module: it returns a table with a function
//   translate(text, {mode = "single" | "multi", setup = "CMD ; CMD"})
//     -> {commands = {"CMD", ...}} or {ask = "question"}
// run_translation_graph() loads the module into `vm` (once per Vm) and calls
// it; a Lua error, a missing module or a result of another shape comes back
// as a Status naming the case's problem.
#pragma once

#include <string>

#include "core/status.h"
#include "script/vm.h"
#include "translate/offline_translator.h"

namespace squawk::script {

inline constexpr const char* kTranslationGraphModule = "translate.graph";

Result<translate::Translation> run_translation_graph(Vm& vm, const std::string& text, const std::string& mode,
                                                     const std::string& setup);

}  // namespace squawk::script
