// ServeSession: the Lua side of `squawk serve` (scripts/serve/session.lua,
// module `serve.session`), driven command by command from C++.
//
// Contract: open() creates the module's session in `vm` with the scenario
// (empty: none) and translation mode (empty: the graph's default). stack() is
// the simulation the session's translator and commands act on; it lives as
// long as the session (the Lua value is kept in the registry) and is used
// only on the thread that owns `vm`. command() passes one line (English or
// "!TrafScript") and returns what happened; a Lua error comes back as a Status
// with its traceback and the session stays usable.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "command/stack.h"
#include "core/status.h"
#include "script/vm.h"

namespace squawk::script {

struct CommandReply {
  std::string text;                   // what was typed
  std::vector<std::string> commands;  // TrafScript lines run (or that would have run)
  bool ok = false;                    // every command ran
  std::string message;                // output, or the first error
  std::string ask;                    // the translator's question; nothing ran
  bool cancelled = false;             // a pending question was dropped
  std::string trace;                  // the translation graph's path, one node a line
};

class ServeSession {
 public:
  static Result<std::unique_ptr<ServeSession>> open(Vm& vm, const std::string& scenario, const std::string& mode);
  ~ServeSession();
  ServeSession(const ServeSession&) = delete;
  ServeSession& operator=(const ServeSession&) = delete;

  command::Stack& stack() { return *stack_; }
  Result<CommandReply> command(const std::string& text);

 private:
  ServeSession(Vm& vm, command::Stack* stack) : vm_(&vm), stack_(stack) {}
  Vm* vm_;
  command::Stack* stack_;
};

}  // namespace squawk::script
