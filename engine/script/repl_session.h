// ReplSession: the Lua side of `squawk repl` (scripts/translate/repl.lua,
// module `translate.repl`), driven line by line from C++.
//
// Contract: open() creates the module's session in `vm` with the scenario
// (empty: none), translation mode (empty: the graph's default) and running
// clock (multiplier of real time; 0: stopped); handle() passes one input line
// and returns the text to print and whether the user asked to quit; tick()
// advances the running clock by `wall_s` seconds of real time and returns
// what happened ("" when nothing); complete() lists the completions of a
// word. Lua errors come back as Status with the traceback; the session
// stays usable after an error in one line. An English line is translated as
// one request (script/translate_graph.h: the collector stopped for the
// translation only); collect_after_reply() takes the step it owes, and is
// called once the reply and the next prompt are shown.
#pragma once

#include <string>
#include <vector>

#include "core/status.h"
#include "script/vm.h"

namespace squawk::script {

struct ReplReply {
  std::string text;
  bool quit = false;
};

// Pushes `module`.new{scenario, mode, seed = vm's seed, clock} (fields left
// out when empty / 0): the session object of translate.repl or
// translate.session. On error the stack is as it was.
Status push_new_session(Vm& vm, const char* module, const std::string& scenario, const std::string& mode,
                        double clock = 0.0);

class ReplSession {
 public:
  static Result<ReplSession> open(Vm& vm, const std::string& scenario, const std::string& mode,
                                  double clock = 0.0);
  Result<ReplReply> handle(const std::string& line);
  Result<std::string> banner();
  Result<std::string> opening();  // what loading the scenario did
  Result<std::string> tick(double wall_s);
  Result<std::vector<std::string>> complete(const std::string& prefix);
  // script::collect_after_reply on the session's VM (nothing when no step is owed).
  void collect_after_reply();

 private:
  explicit ReplSession(Vm& vm) : vm_(&vm) {}
  // Calls session:<method>(args...) with results left on the Lua stack; the
  // pushers push the arguments.
  Status call(const char* method, int nargs, int nresults);
  // session:<method>() -> string.
  Result<std::string> text_of(const char* method);
  Vm* vm_;
};

}  // namespace squawk::script
