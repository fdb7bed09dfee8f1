// ServeSession: the controller's session (scripts/translate/session.lua,
// module `translate.session`, the one behind `squawk repl`) driven from C++
// for `squawk serve`.
//
// Contract: open() creates the module's session in `vm` with the scenario
// (empty: none) and translation mode (empty: the graph's default). stack() is
// the simulation the session's translator and commands act on; it lives as
// long as the session (the Lua value is kept in the registry) and is used
// only on the thread that owns `vm`. command() passes one line (English or
// "!TrafScript") from one client and returns what happened; tick() advances the clock as the
// run state asks (session:tick); both report what happened meanwhile as
// events. A Lua error comes back as a Status with its traceback and the
// session stays usable. command() translates an English line as one request
// (script/translate_graph.h: the collector stopped for the translation only);
// collect_after_reply() takes the step it owes, once the reply has left the
// VM's thread.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "command/stack.h"
#include "core/status.h"
#include "script/vm.h"

namespace squawk::script {

// Something that happened while time moved: kind "conflict", "conflict_end",
// "los", "los_end", "echo" or "failure" (session.lua documents them).
struct SessionEvent {
  double t = 0;  // [s] sim time
  std::string kind;
  std::string text;
};

struct CommandReply {
  std::string text;                   // what was typed
  std::vector<std::string> commands;  // TrafScript lines run (or that would have run)
  bool ok = false;                    // every command ran
  std::string message;                // output, or the first error
  std::string ask;                    // the translator's question; nothing ran
  bool cancelled = false;             // a pending question was dropped
  std::string trace;                  // the translation graph's path, one node a line
  std::vector<SessionEvent> events;   // what happened while the command ran (FF)
  std::string addressed;              // the selected callsign put in front of the line, or ""
};

// Who says a line (session.lua's command() opts).
struct CommandOptions {
  std::string client;    // whose dialogue: a question raised for one client is answered only by its next line
  std::string selected;  // callsign a line naming no aircraft is for when it does not translate by itself
};

class ServeSession {
 public:
  static Result<std::unique_ptr<ServeSession>> open(Vm& vm, const std::string& scenario, const std::string& mode);
  ~ServeSession();
  ServeSession(const ServeSession&) = delete;
  ServeSession& operator=(const ServeSession&) = delete;

  command::Stack& stack() { return *stack_; }
  Result<CommandReply> command(const std::string& text, const CommandOptions& opts = {});
  // session:tick(wall_s): OP advances wall_s x DTMULT, FF to its end, HOLD not at all [s].
  Result<std::vector<SessionEvent>> tick(double wall_s);
  // script::collect_after_reply on the session's VM (nothing when no step is owed).
  void collect_after_reply();

 private:
  ServeSession(Vm& vm, command::Stack* stack) : vm_(&vm), stack_(stack) {}
  // Pushes session.<method> and the session (protected read); on error the
  // stack is as it was.
  Status push_method(const char* method);
  Vm* vm_;
  command::Stack* stack_;
};

}  // namespace squawk::script
