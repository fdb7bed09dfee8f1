// The command registry: THE single list of TrafScript commands. The console,
// the .scn runner, Lua (squawk.sim / squawk.stack), the RAG documents
// (`squawk commands --json`) and the translator's validator all read it.
//
// Each command is declared once (in commands_*.cpp): name, BlueSky aliases,
// argument type list in BlueSky's notation (args.h), usage, a help paragraph
// in our own words, examples, and the handler. A handler receives arguments
// that are already parsed and checked; it must validate anything else before
// changing state, so a failed command leaves the simulation as it was.
#pragma once

#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "command/args.h"
#include "core/status.h"

namespace squawk::command {

class Stack;

// The parsed arguments of one call, with the stack they act on.
struct Call {
  Stack& stack;
  std::string_view name;            // canonical command name
  const std::vector<ArgValue>& args;

  bool has(size_t i) const { return i < args.size() && args[i].present; }
  // Argument i, or an absent value when it was omitted or not given.
  const ArgValue& operator[](size_t i) const;
  // The first aircraft index of argument i (precondition: has(i), type acid).
  int acid(size_t i) const { return args[i].acids.front(); }
};

// Returns the text to show the user (may be empty) or an error.
using Handler = Result<std::string> (*)(Call& call);

struct CommandDecl {
  std::string name;                  // upper case
  std::vector<std::string> aliases;  // upper case
  std::string args;                  // type list, e.g. "acid,alt,[vspd]"
  std::string usage;                 // e.g. "ALT acid,alt,[vspd]"
  std::string help;                  // one paragraph, our own words
  std::vector<std::string> examples;
  Handler handler = nullptr;
  Signature signature;               // parsed from `args` when registered
  bool all_aircraft = false;         // acid arguments may be `*` (every aircraft)
};

class Registry {
 public:
  // The registry with every squawk command (built once, thread-safe).
  static const Registry& instance();

  const std::vector<CommandDecl>& commands() const { return commands_; }
  // Finds a command by name or alias (case-insensitive); null when unknown.
  const CommandDecl* find(std::string_view name) const;
  // The command name or alias closest to an unknown `name` (case-insensitive
  // edit distance at most 1, or 2 for names of 5+ letters); "" when none is.
  std::string closest(std::string_view name) const;

  // JSON array of {name, aliases, args, usage, help, examples}.
  std::string to_json() const;
  // Plain-text help for one command, or the command list when name is empty.
  // Error: unknown name.
  Result<std::string> help(std::string_view name) const;

 private:
  Registry();
  std::vector<CommandDecl> commands_;
  std::unordered_map<std::string, size_t> index_;  // name or alias -> commands_ index
};

// Declarations contributed by each commands_*.cpp (called by Registry()).
void add_traffic_commands(std::vector<CommandDecl>& out);
void add_route_commands(std::vector<CommandDecl>& out);
void add_sim_commands(std::vector<CommandDecl>& out);
void add_asas_commands(std::vector<CommandDecl>& out);
void add_perf_commands(std::vector<CommandDecl>& out);
void add_shape_commands(std::vector<CommandDecl>& out);

}  // namespace squawk::command
