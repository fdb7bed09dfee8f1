// squawk repl: English (or TrafScript) in, translation and state out.
//
// With a terminal on stdin it uses readline (line editing, history kept in
// ~/.squawk_history, Tab completes callsigns and commands, Ctrl-C clears the
// line) and prints a banner and a prompt; between keystrokes the running
// clock (`--clock X`, `:clock X`, OP) advances the simulation and what it
// reports (conflicts, ECHO lines) appears above the prompt. From a pipe it
// reads plain lines and prints only the replies, so sessions can be
// scripted; the running clock then advances between lines.
#include <signal.h>
#include <sys/select.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <readline/history.h>
#include <readline/readline.h>

#include "app/cli.h"
#include "app/subcommands.h"
#include "app/vm_options.h"
#include "command/conformance.h"
#include "command/navdb.h"
#include "command/stack.h"
#include "core/files.h"
#include "core/paths.h"
#include "core/text.h"
#include "llm/llm_config.h"
#include "script/repl_session.h"

namespace squawk::app {

namespace {

constexpr const char* kPrompt = "squawk> ";
constexpr double kTickS = 0.25;  // [s] wall time between clock ticks while waiting for keys

std::string history_path() {
  const char* home = std::getenv("HOME");
  return home && *home ? std::string(home) + "/.squawk_history" : std::string();
}

// Wall-clock seconds since the previous call (0 on the first).
class WallClock {
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double s = last_ ? std::chrono::duration<double>(now - *last_).count() : 0.0;
    last_ = now;
    return s;
  }

 private:
  std::optional<std::chrono::steady_clock::time_point> last_;
};

// Prints a reply (or the Lua error) for one line; returns false on quit.
bool reply_to(script::ReplSession& session, const std::string& line, int& status) {
  auto reply = session.handle(line);
  if (!reply) {
    std::fprintf(stderr, "%s\n", shown_error(reply.status().message()).c_str());
    status = kExitFail;
    return true;
  }
  if (!reply->text.empty()) std::printf("%s\n", reply->text.c_str());
  std::fflush(stdout);
  return !reply->quit;
}

void print_tick(script::ReplSession& session, double wall_s) {
  auto text = session.tick(wall_s);
  if (!text) std::fprintf(stderr, "%s\n", shown_error(text.status().message()).c_str());
  else if (!text->empty()) std::printf("%s\n", text->c_str());
}

// --- Terminal mode: readline's callback interface in a select() loop --------

struct Terminal {
  script::ReplSession* session = nullptr;
  WallClock clock;
  int status = kExitOk;
  bool done = false;
};
Terminal* g_term = nullptr;
volatile sig_atomic_t g_sigint = 0;

void on_sigint(int) { g_sigint = 1; }

void on_line(char* raw) {
  Terminal& t = *g_term;
  if (!raw) {  // Ctrl-D
    std::printf("\n");
    t.done = true;
    return;
  }
  const std::string line = raw;
  if (!line.empty()) add_history(raw);
  std::free(raw);
  print_tick(*t.session, t.clock.lap());
  if (!reply_to(*t.session, line, t.status)) t.done = true;
}

std::vector<std::string> g_matches;

char* next_match(const char*, int state) {
  static size_t k = 0;
  if (state == 0) k = 0;
  return k < g_matches.size() ? ::strdup(g_matches[k++].c_str()) : nullptr;
}

char** complete(const char* text, int, int) {
  rl_attempted_completion_over = 1;  // never fall back to file names
  auto words = g_term->session->complete(text);
  g_matches = words ? *words : std::vector<std::string>{};
  return rl_completion_matches(text, next_match);
}

int run_terminal(script::ReplSession& session) {
  Terminal term;
  term.session = &session;
  g_term = &term;
  struct sigaction sa {};
  sa.sa_handler = on_sigint;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0;  // no SA_RESTART: select() returns at once
  sigaction(SIGINT, &sa, nullptr);
  rl_catch_signals = 0;
  rl_attempted_completion_function = complete;
  rl_callback_handler_install(kPrompt, on_line);
  term.clock.lap();
  while (!term.done) {
    fd_set in;
    FD_ZERO(&in);
    FD_SET(STDIN_FILENO, &in);
    timeval tv{0, static_cast<suseconds_t>(kTickS * 1e6)};
    const int n = select(STDIN_FILENO + 1, &in, nullptr, nullptr, &tv);
    if (g_sigint) {  // Ctrl-C: drop the line being typed, new prompt
      g_sigint = 0;
      rl_free_line_state();
      rl_replace_line("", 0);
      std::printf("^C\n");
      rl_on_new_line();
      rl_redisplay();
      continue;
    }
    if (n > 0) {
      rl_callback_read_char();  // (a whole line: on_line replied, readline shows the prompt again)
      session.collect_after_reply();
      continue;
    }
    if (n == 0) {  // no key: let the running clock move, print above the prompt
      auto text = session.tick(term.clock.lap());
      if (text && !text->empty()) {
        rl_clear_visible_line();
        std::printf("%s\n", text->c_str());
        rl_forced_update_display();
      }
    }
  }
  rl_callback_handler_remove();
  g_term = nullptr;
  return term.status;
}

// The session when the REPL's Lua (the translation graph, its grammar) does
// not load: the scenario on a bare command stack, `!CMD` run as typed, English
// refused with the reason. Exit 1 at the end: the session was degraded.
int run_trafscript_only(const std::string& scenario, const script::VmOptions& o, const Status& why) {
  std::fprintf(stderr, "squawk repl: the translator did not load (%s); only !TrafScript works in this session\n",
               shown_error(why.message()).c_str());
  command::Stack stack(o.seed);
  if (!o.navdata_dir.empty()) {  // navdata that does not load: named places fail, each saying so
    if (auto db = command::NavDb::load_cached(o.navdata_dir); db) stack.set_navdb(*db);
  }
  if (!scenario.empty()) {
    if (Status st = stack.load_scenario(scenario); !st.is_ok()) return failure(st);
    stack.process_due();
    for (const auto& line : stack.take_output()) std::printf("  %s\n", line.c_str());
    const command::Tally& t = stack.tally();
    std::printf("  scenario commands so far: %ld executed, %ld skipped, %ld failed\n", t.executed,
                command::total_count(t.skipped), command::total_count(t.failed));
  }
  const bool tty = ::isatty(STDIN_FILENO) != 0;
  std::string line;
  while ((tty ? std::printf("%s", kPrompt) : 0, std::fflush(stdout), std::getline(std::cin, line))) {
    const std::string typed(text::trim(line));
    if (typed.empty()) continue;
    if (typed == "quit" || typed == "exit" || typed == ":q") break;
    if (typed[0] != '!') {
      std::fprintf(stderr, "English needs the translator, which did not load; type !CMD for TrafScript\n");
      continue;
    }
    auto r = stack.exec(typed.substr(1));
    if (!r) std::fprintf(stderr, "%s\n", r.status().message().c_str());
    else std::printf("  ok: %s%s%s\n", std::string(text::trim(typed.substr(1))).c_str(), r->empty() ? "" : "\n  ",
                     r->c_str());
    std::fflush(stdout);
  }
  return kExitFail;
}

// echo: each line read is printed before its reply (a transcript of the session).
int run_pipe(script::ReplSession& session, bool echo) {
  WallClock clock;
  clock.lap();
  std::string line;
  int status = kExitOk;
  while (std::getline(std::cin, line)) {
    print_tick(session, clock.lap());
    if (echo && !text::trim(line).empty())
      std::printf("%s\n", std::string(text::trim(line)).c_str());
    if (!reply_to(session, line, status)) break;
    session.collect_after_reply();  // (the reply is flushed)
  }
  return status;
}

}  // namespace

int cmd_repl(const ArgV& argv) {
  Args::Spec spec = with_vm_flags({{}, {"--echo"}});
  for (const char* f : {"--mode", "--llm-url", "--llm-model", "--llm-api", "--clock"})
    spec.value_flags.emplace_back(f);
  auto args = Args::parse(argv, spec);
  if (!args) return usage_error("repl", args.status().message());
  if (args->positional().size() > 1) return usage_error("repl", "expected at most one SCENARIO");
  auto opts = vm_options(*args);
  if (!opts) return usage_error("repl", opts.status().message());
  auto clock = args->get_double("--clock", 0.0);
  if (!clock || *clock < 0 || *clock > 1000)
    return usage_error("repl", "--clock expects a multiplier of real time from 0 (stopped) to 1000");
  // The LLM flags travel as the environment the translation graph reads.
  for (const auto& [flag, var] : {std::pair{"--llm-url", "SQUAWK_LLM_URL"}, std::pair{"--llm-model", "SQUAWK_LLM_MODEL"},
                                  std::pair{"--llm-api", "SQUAWK_LLM_API"}})
    if (auto v = args->get(flag)) ::setenv(var, v->c_str(), 1);
  if (auto llm = llm::config_from_env(); !llm && llm.status().code() != Code::kNotFound)
    return usage_error("repl", llm.status().message());
  opts->max_instructions = 0;  // an interactive session has no instruction budget

  auto named = named_scenario(*args, *opts);
  if (!named) return failure(named.status());
  const std::string& scenario = *named;
  script::Vm vm(*opts);
  auto session = script::ReplSession::open(vm, scenario, args->get_or("--mode", ""), *clock);
  if (!session) return run_trafscript_only(scenario, *opts, session.status());

  const bool tty = ::isatty(STDIN_FILENO) != 0;
  if (tty)
    if (auto b = session->banner(); b.is_ok()) std::printf("%s\n", b->c_str());
  if (auto o = session->opening(); o.is_ok() && !o->empty()) std::printf("%s\n", o->c_str());
  std::fflush(stdout);
  if (!tty) return run_pipe(*session, args->has("--echo"));
  const std::string history = history_path();
  if (!history.empty()) read_history(history.c_str());
  const int status = run_terminal(*session);
  if (!history.empty()) write_history(history.c_str());
  return status;
}

}  // namespace squawk::app
