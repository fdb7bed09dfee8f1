// squawk repl: English (or TrafScript) in, translation and state out.
//
// With a terminal on stdin it uses readline (line editing, history kept in
// ~/.squawk_history) and prints a banner and a prompt; from a pipe it reads
// plain lines and prints only the replies, so sessions can be scripted.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

#include <readline/history.h>
#include <readline/readline.h>

#include "app/cli.h"
#include "app/subcommands.h"
#include "app/vm_options.h"
#include "core/files.h"
#include "core/paths.h"
#include "llm/llm_config.h"
#include "script/repl_session.h"

namespace squawk::app {

namespace {

constexpr const char* kPrompt = "squawk> ";

std::string history_path() {
  const char* home = std::getenv("HOME");
  return home && *home ? std::string(home) + "/.squawk_history" : std::string();
}

// One input line; false at end of input.
bool next_line(bool tty, std::string& line) {
  if (!tty) return static_cast<bool>(std::getline(std::cin, line));
  char* raw = readline(kPrompt);
  if (!raw) return false;
  line = raw;
  if (!line.empty()) add_history(raw);
  std::free(raw);
  return true;
}

}  // namespace

int cmd_repl(const ArgV& argv) {
  Args::Spec spec = with_vm_flags({});
  for (const char* f : {"--mode", "--llm-url", "--llm-model", "--llm-api"}) spec.value_flags.emplace_back(f);
  auto args = Args::parse(argv, spec);
  if (!args) return usage_error("repl", args.status().message());
  if (args->positional().size() > 1) return usage_error("repl", "expected at most one SCENARIO");
  auto opts = vm_options(*args);
  if (!opts) return usage_error("repl", opts.status().message());
  // The LLM flags travel as the environment the translation graph reads.
  for (const auto& [flag, var] : {std::pair{"--llm-url", "SQUAWK_LLM_URL"}, std::pair{"--llm-model", "SQUAWK_LLM_MODEL"},
                                  std::pair{"--llm-api", "SQUAWK_LLM_API"}})
    if (auto v = args->get(flag)) ::setenv(var, v->c_str(), 1);
  if (auto llm = llm::config_from_env(); !llm && llm.status().code() != Code::kNotFound)
    return usage_error("repl", llm.status().message());
  opts->max_instructions = 0;  // an interactive session has no instruction budget

  const std::string scenario = args->positional().empty() ? "" : paths::absolute(args->positional()[0]);
  if (!scenario.empty() && !files::exists(scenario))
    return failure(Status::not_found("no scenario file '" + args->positional()[0] + "'"));
  script::Vm vm(*opts);
  auto session = script::ReplSession::open(vm, scenario, args->get_or("--mode", ""));
  if (!session) return failure(session.status());

  const bool tty = ::isatty(STDIN_FILENO) != 0;
  const std::string history = history_path();
  if (tty) {
    if (!history.empty()) read_history(history.c_str());
    if (auto b = session->banner(); b.is_ok()) std::printf("%s\n", b->c_str());
  }
  std::string line;
  int status = kExitOk;
  while (next_line(tty, line)) {
    auto reply = session->handle(line);
    if (!reply) {
      std::fprintf(stderr, "%s\n", reply.status().message().c_str());
      status = kExitFail;
      continue;
    }
    if (!reply->text.empty()) std::printf("%s\n", reply->text.c_str());
    std::fflush(stdout);
    if (reply->quit) break;
  }
  if (tty && !history.empty()) write_history(history.c_str());
  return status;
}

}  // namespace squawk::app
