// ReplSession: the Lua side of `squawk repl` (scripts/translate/repl.lua,
// module `translate.repl`), driven line by line from C++.
//
// Contract: open() creates the module's session in `vm` with the scenario
// (empty: none) and translation mode (empty: the graph's default); handle()
// passes one input line and returns the text to print and whether the user
// asked to quit. Lua errors come back as Status with the traceback; the
// session stays usable after an error in one line.
#pragma once

#include <string>

#include "core/status.h"
#include "script/vm.h"

namespace squawk::script {

struct ReplReply {
  std::string text;
  bool quit = false;
};

class ReplSession {
 public:
  static Result<ReplSession> open(Vm& vm, const std::string& scenario, const std::string& mode);
  Result<ReplReply> handle(const std::string& line);
  Result<std::string> banner();

 private:
  explicit ReplSession(Vm& vm) : vm_(&vm) {}
  // Calls session:<method>(arg) with results left on the Lua stack.
  Status call(const char* method, const std::string* arg, int nresults);
  Vm* vm_;
};

}  // namespace squawk::script
