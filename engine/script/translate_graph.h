// Calling the Lua translation graph (scripts/translate/graph.lua, the
// `translate.graph` module) from C++: the one path every C++ entry point
// (squawk translate, eval-translate, demo) takes, so an edit to the graph,
// its nodes or the grammar files reaches them all.
//
// Contract of the module (see graph.lua):
//   translate(text, {mode =, sim =, setup =}) -> {commands = {...}} | {ask = "..."}, .error
//   dialogue({mode =, sim =}) -> d;  d:say(text) -> the same shape
// run_translation_graph() loads the module into `vm` (once per Vm) and calls
// it; a Lua error (including one raised while loading graph.lua), a missing
// module or a result of another shape comes back as a Status naming the
// problem. `sim`, when given, is copied into the VM; the graph never changes
// it (candidates run on scratch copies), so the caller's Stack is untouched.
#pragma once

#include <string>

#include "command/stack.h"
#include "core/status.h"
#include "rag/document.h"
#include "script/vm.h"
#include "translate/translation.h"

namespace squawk::script {

inline constexpr const char* kTranslationGraphModule = "translate.graph";

struct GraphRequest {
  std::string mode = "offline";          // offline | single | multi
  std::string setup;                      // TrafScript run on a new sim when `sim` is null
  const command::Stack* sim = nullptr;    // the traffic to translate against (copied)
  bool verify = true;                     // multi mode: false drops the verifier node (paper Table 2)
};

Result<translate::Translation> run_translation_graph(Vm& vm, const std::string& text, const GraphRequest& req);

// Reads a graph result table (translate()'s shape) at the stack top, leaving
// it there; a result of another shape comes back as a Status.
Result<translate::Translation> read_graph_result(lua_State* L);

// Pushes the translate.graph module (loaded once per Lua state through the
// sandbox's require); raises the Lua error of a module that fails to load.
void push_graph_module(lua_State* L);

// The grammar's retrieval documents (translate.grammar.documents()): the
// words of its rules and `words` lines, per registry command.
Result<std::vector<rag::Document>> grammar_documents(Vm& vm);

// A conversation through graph.dialogue(): a question keeps its partial
// command and the next say() may answer it; "cancel" drops it. The Vm must
// outlive the dialogue.
class GraphDialogue {
 public:
  // Fails (a Status) when the graph cannot be loaded.
  static Result<GraphDialogue> open(Vm& vm, const GraphRequest& req);
  GraphDialogue(GraphDialogue&& o) noexcept : vm_(o.vm_), ref_(o.ref_) { o.ref_ = -1; }
  GraphDialogue(const GraphDialogue&) = delete;
  GraphDialogue& operator=(const GraphDialogue&) = delete;
  GraphDialogue& operator=(GraphDialogue&&) = delete;
  ~GraphDialogue();
  Result<translate::Translation> say(const std::string& text);

 private:
  GraphDialogue(Vm& vm, int ref) : vm_(&vm), ref_(ref) {}
  Vm* vm_;
  int ref_;  // registry reference of the Lua dialogue object
};

}  // namespace squawk::script
