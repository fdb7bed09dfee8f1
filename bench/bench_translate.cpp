// Offline translation latency: each utterance of the corpora (the shared dev
// and vice corpora when ../shared is present, else a built-in set) through
// the whole translation graph (scripts/translate/graph.lua in offline mode:
// the Lua grammar over the C++ extractors, validation and execution on a
// scratch copy), against the traffic of its case's setup. Prints p50, p99
// and the worst per-utterance time, as wall time, as this thread's CPU time
// (preemption not counted), and as each utterance's best wall time over
// the reps (its own cost, which holds on a shared, loaded machine).
// The collector is stopped during each request and its garbage taken by one
// minor step after the reply (script::collect_after_reply, as a person's
// think time would pay it): the latencies are the request's alone; the
// step's time, the throughput with the steps and the memory a request
// allocates are printed beside them. Each utterance is timed in two VMs in
// turn: the REPL's and serve's (no instruction budget), whose figures are the
// latency a person sees, and a script call's (the default budget, kept by
// Lua's count hook, which traps every VM instruction). Asserts nothing.
// --slowest K lists the K utterances with the highest best-of-reps time.
//   bench_translate [CORPUS.tsv ...] [--reps N] [--slowest K]
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "command/stack.h"
#include "core/files.h"
#include "script/translate_graph.h"
#include "translate/corpus.h"
#include "translate/stack_world.h"

using namespace squawk;
using Clock = std::chrono::steady_clock;

namespace {

double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

double quantile(const std::vector<double>& v, double q) {
  return v.empty() ? 0.0 : v[std::min(v.size() - 1, static_cast<size_t>(q * v.size()))];
}

// The latencies of one VM configuration over every utterance and rep [ms], the collector's step
// after each reply [ms] and the garbage it took [KB].
struct Series {
  explicit Series(const char* title) : title(title) {}

  const char* title;
  std::vector<double> ms, cpu, best, steps, kb;
  double total_ms = 0.0;

  // Times `reps` translations of `utterance` after one that warms it; returns the best wall time
  // [ms].
  double time(script::Vm& vm, command::Stack& stack, const std::string& utterance, int reps,
              int& failures) {
    (void)script::run_translation_graph(vm, utterance, {"offline", "", &stack});  // warm
    (void)script::collect_after_reply(vm);
    double fastest = 1e300;
    for (int r = 0; r < reps; ++r) {
      const auto t0 = Clock::now();
      const double c0 = thread_cpu_ms();
      auto tr = script::run_translation_graph(vm, utterance, {"offline", "", &stack});
      cpu.push_back(thread_cpu_ms() - c0);
      ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
      const auto step = script::collect_after_reply(vm);
      steps.push_back(step.ms);
      kb.push_back(step.freed_kb);
      total_ms += ms.back() + steps.back();
      fastest = std::min(fastest, ms.back());
      failures += !tr.is_ok();
    }
    best.push_back(fastest);
    return fastest;
  }

  void print(int reps) {
    for (auto* v : {&ms, &cpu, &best, &steps, &kb}) std::sort(v->begin(), v->end());
    const auto row = [](const char* what, const std::vector<double>& v, const char* unit) {
      std::printf("  %-28s p50 %.3f %s   p99 %.3f %s   max %.3f %s\n", what, quantile(v, 0.5), unit,
                  quantile(v, 0.99), unit, v.empty() ? 0.0 : v.back(), unit);
    };
    std::printf("%s\n", title);
    row("wall per utterance", ms, "ms");
    row("CPU  per utterance", cpu, "ms");
    char best_of[40];
    std::snprintf(best_of, sizeof best_of, "best of %d reps", reps);
    row(best_of, best, "ms");
    row("collection after the reply", steps, "ms");
    std::printf("  throughput with the collection  %.3f ms per request (%.0f requests/s)\n",
                ms.empty() ? 0.0 : total_ms / ms.size(),
                total_ms > 0 ? 1e3 * ms.size() / total_ms : 0.0);
    row("garbage per request", kb, "KB");
  }
};

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> paths;
  int reps = 5;
  int slowest = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--reps" && i + 1 < argc) reps = std::max(1, std::atoi(argv[++i]));
    else if (a == "--slowest" && i + 1 < argc)
      slowest = std::max(0, std::atoi(argv[++i]));
    else paths.push_back(a);
  }
  if (paths.empty())
    for (const char* name : {"nl2trafscript_dev.tsv", "vice_trafscript.tsv"}) {
      const std::string p = std::string("../shared/corpora/") + name;
      if (files::exists(p)) paths.push_back(p);
    }
  std::vector<translate::CorpusCase> cases;
  for (const auto& p : paths) {
    auto c = translate::read_corpus(p);
    if (!c) {
      std::fprintf(stderr, "bench_translate: %s\n", c.status().message().c_str());
      return 1;
    }
    cases.insert(cases.end(), c->begin(), c->end());
  }
  if (cases.empty()) {
    const char* setup = "CRE KL204 A320 52 4 90 FL250 280 ; CRE BAW123 A320 51.5 0 270 FL300 300";
    for (const char* u : {"KL204 climb flight level three five zero", "speedbird one two three turn left heading 270",
                          "KL204 reduce speed to two one zero knots", "fast forward 2 minutes",
                          "Create AC01, an A320 at 52N 4E heading 90 at FL250 and 280 knots",
                          "turn BAW123 left 20 degrees", "KL204 descend", "pause the simulation"})
      cases.push_back({"b", setup, u, "", "bench"});
  }
  // The REPL's and serve's VM (no instruction budget: no count hook, cli_repl.cpp, cli_serve.cpp)
  // and a script call's (the default budget: Lua's count hook, which traps every instruction), each
  // utterance timed in both in turn, so both see the same minutes of the host.
  script::VmOptions interactive_options;
  interactive_options.max_instructions = 0;
  script::Vm interactive{interactive_options};
  script::Vm budgeted{script::VmOptions{}};
  Series live("as the REPL and serve run it (no instruction budget)");
  Series scripted("as a script call runs it (the default instruction budget)");
  std::vector<std::pair<double, const std::string*>> by_utterance;
  int failures = 0;
  for (const auto& c : cases) {
    command::Stack stack;
    if (!translate::setup_stack(stack, c.setup).is_ok()) continue;
    const double fastest = live.time(interactive, stack, c.utterance, reps, failures);
    (void)scripted.time(budgeted, stack, c.utterance, reps, failures);
    by_utterance.emplace_back(fastest, &c.utterance);
  }
  std::printf("offline translation graph: %zu utterances x %d reps (%s), graph errors %d\n",
              by_utterance.size(), reps, paths.empty() ? "built-in set" : "corpora", failures);
  live.print(reps);
  scripted.print(reps);
  std::sort(by_utterance.rbegin(), by_utterance.rend());
  std::printf("slowest, best of %d reps, as the REPL runs it:\n", reps);
  for (int k = 0; k < slowest && k < static_cast<int>(by_utterance.size()); ++k)
    std::printf("  %8.3f ms  %s\n", by_utterance[k].first, by_utterance[k].second->c_str());
  return 0;
}
