// The squawk command line: subcommand table, argument parsing, exit codes.
//
// Exit codes: 0 ok, 1 failure (a test failed, a script errored, a command
// failed), 2 usage error (unknown subcommand or flag, missing argument).
// Each subcommand lives in app/cli_<area>.cpp and is listed once in
// subcommands.cpp.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/status.h"

namespace squawk::app {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFail = 1;
inline constexpr int kExitUsage = 2;

int run_cli(int argc, char** argv);

// Parsed arguments of one subcommand. Flags are `--name value`,
// `--name=value` or bare switches; `--` ends flag parsing.
class Args {
 public:
  struct Spec {
    std::vector<std::string> value_flags;  // e.g. "--seed"
    std::vector<std::string> bool_flags;   // e.g. "--json"
    // When true, unknown flags are kept as positionals instead of failing
    // (used by `run`, whose script receives them in `arg`).
    bool pass_unknown = false;
  };
  static Result<Args> parse(const std::vector<std::string>& argv, const Spec& spec);

  const std::vector<std::string>& positional() const { return positional_; }
  bool has(const std::string& flag) const { return values_.count(flag) > 0; }
  std::optional<std::string> get(const std::string& flag) const;
  std::string get_or(const std::string& flag, const std::string& fallback) const;
  // Integer / real value of a flag; an unparsable value is a usage error.
  Result<long long> get_int(const std::string& flag, long long fallback) const;
  Result<double> get_double(const std::string& flag, double fallback) const;
  // Every flag given, name -> value ("1" for a switch).
  const std::map<std::string, std::string>& flags() const { return values_; }

 private:
  std::vector<std::string> positional_;
  std::map<std::string, std::string> values_;
};

struct Subcommand {
  const char* name;
  const char* synopsis;  // one line, shown by --help
  const char* help;      // full text, shown by `squawk help NAME`
  int (*run)(const std::vector<std::string>& args);
};
const std::vector<Subcommand>& subcommands();

// --verbose, accepted by every subcommand (run_cli removes it): Lua errors
// keep their traceback. Without it an error shows as `file:line: message`.
void set_verbose(bool on);
// `message` as the user sees it: without the Lua traceback ("\nstack
// traceback:" and after) unless --verbose was given.
std::string shown_error(const std::string& message);

// Prints "squawk NAME: message" plus a hint to stderr and returns kExitUsage.
int usage_error(const std::string& subcommand, const std::string& message);
// Prints "squawk: message" to stderr and returns kExitFail.
int failure(const Status& st);

}  // namespace squawk::app
