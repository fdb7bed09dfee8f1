#include "command/scenario_run.h"

#include <algorithm>
#include <chrono>

#include "core/paths.h"

namespace squawk::command {

Result<ScenarioRunResult> run_scenario(const std::string& path, const ScenarioRunOptions& opts, Stack& stack) {
  const auto t0 = std::chrono::steady_clock::now();
  stack = Stack(opts.seed);
  if (opts.openap) stack.sim().set_openap(*opts.openap);
  stack.set_navdb(opts.navdb);
  stack.set_base_dir(paths::dirname(path));
  SQUAWK_RETURN_IF_ERROR(stack.load_scenario(path));
  if (opts.until) {
    SQUAWK_RETURN_IF_ERROR(stack.run_until(*opts.until));
  } else {
    // Until every queued command has run (PCALL and SCHEDULE may queue more)
    // or max_time; each round advances at least one step.
    while (stack.queued() > 0 && stack.sim().simt() < opts.max_time) {
      const double target = std::min(*stack.last_queued_time(), opts.max_time);
      SQUAWK_RETURN_IF_ERROR(stack.run_until(std::max(target, stack.sim().simt() + stack.sim().dt())));
    }
  }
  ScenarioRunResult r;
  r.end_time = stack.sim().simt();
  r.tally = stack.tally();
  r.aircraft = stack.sim().n();
  r.conflicts = stack.sim().cd().total_conflicts();
  r.los = stack.sim().cd().total_los();
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace squawk::command
