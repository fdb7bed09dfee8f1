#include "command/scenario_run.h"

#include <algorithm>
#include <chrono>

#include "core/paths.h"
#include "core/text.h"

namespace squawk::command {

namespace {
constexpr int kSlice = 100;  // steps between wall-clock checks
}  // namespace

Result<ScenarioRunResult> run_scenario(const std::string& path, const ScenarioRunOptions& opts, Stack& stack) {
  const auto t0 = std::chrono::steady_clock::now();
  stack = Stack(opts.seed);
  if (opts.openap) stack.sim().set_openap(*opts.openap);
  SQUAWK_RETURN_IF_ERROR(stack.sim().set_cd_max_pairs(opts.max_conflict_pairs));
  stack.set_navdb(opts.navdb);
  stack.set_base_dir(paths::dirname(path));
  if (opts.max_wall_s > 0)
    stack.set_deadline(t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                std::chrono::duration<double>(opts.max_wall_s)));
  SQUAWK_RETURN_IF_ERROR(stack.load_scenario(path));
  // Runs to `target` in slices of kSlice steps; the stack reads the clock
  // inside long bursts of queued commands too.
  auto run_to = [&](double target) -> Status {
    while (true) {
      const double before = stack.sim().simt();
      const Status st = stack.run_until(std::min(target, before + kSlice * stack.sim().dt()));
      if (!st.is_ok() && st.code() != Code::kTimeout) return st;
      if (!st.is_ok())
        return Status::timeout(path + ": stopped at t = " + text::fmt_double(stack.sim().simt(), 2) +
                               " s after " + text::fmt_double(opts.max_wall_s, 1) +
                               " s of wall-clock time (--max-time)");
      if (stack.sim().simt() == before) return Status::ok();  // target reached
    }
  };
  if (opts.until) {
    SQUAWK_RETURN_IF_ERROR(run_to(*opts.until));
  } else {
    // Until every queued command has run (PCALL and SCHEDULE may queue more)
    // or max_sim_time; each round advances at least one step.
    while (stack.queued() > 0 && stack.sim().simt() < opts.max_sim_time) {
      const double target = std::min(*stack.last_queued_time(), opts.max_sim_time);
      SQUAWK_RETURN_IF_ERROR(run_to(std::max(target, stack.sim().simt() + stack.sim().dt())));
    }
  }
  ScenarioRunResult r;
  r.end_time = stack.sim().simt();
  r.tally = stack.tally();
  r.aircraft = stack.sim().n();
  r.conflicts = stack.sim().cd().total_conflicts();
  r.los = stack.sim().cd().total_los();
  r.cap_notice = sim::cap_notice(stack.sim().cd(), stack.sim().cd_settings().max_pairs);
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace squawk::command
