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

// The collector around a request (RequestCollection, the one owner of this pattern; used by
// run_translation_graph, GraphDialogue::open and say, and squawk.translate.request, through which
// the REPL's and serve's session (scripts/translate/session.lua) translate a person's English
// line): the VM's collector is stopped for the translation, so no collection runs inside a
// request's latency, and restarted after it; the request's garbage (over the bench's corpora ~70
// KB a request, p99 ~140 KB, at most ~1 MB) is then owed. collect_after_reply(vm) takes it, one
// minor step of the generational collector (p50 ~0.05 ms on a quiet machine), and is for a
// caller that shows the reply to a person, after showing it: the think time before the next
// request pays it (squawk repl: after the reply and the next prompt are printed; squawk serve:
// on the simulation's thread once the reply is handed to the HTTP thread). A request that finds
// a step still owed takes it first, as the collector inside the request did before, so the heap
// never holds more than one request's garbage beyond the collector's own policy. Only the
// translation is a request: the commands it gives, a simulation line (`:run 10`), a tick or a
// script run with the collector in its normal mode. Returns the step's time and the heap it freed
// (zeros when none was owed).
struct ReplyCollection {
  double ms = 0.0;        // [ms] wall time of the step
  double freed_kb = 0.0;  // [KB] the Lua heap before the step less the heap after it
};
ReplyCollection collect_after_reply(Vm& vm);

// The scope of one translation request. Construction, when the collector is running: takes a
// step still owed, marks a step owed (Vm::collection_owed) and stops the collector; destruction
// restarts it, whether the request returned, asked or failed. When the collector is already
// stopped (an enclosing request, or a script that stopped it) the scope does nothing, so requests
// nest and a script's choice stands. Neither allocates nor raises a Lua error: it may live outside
// a pcall, around one (never across a longjmp: destroy it before raising).
class RequestCollection {
 public:
  explicit RequestCollection(Vm& vm);
  ~RequestCollection();
  RequestCollection(const RequestCollection&) = delete;
  RequestCollection& operator=(const RequestCollection&) = delete;

 private:
  lua_State* L_;
  bool restart_;  // the collector was running at construction
};

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
