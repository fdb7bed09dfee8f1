// Headless run of one scenario file: the engine of `squawk scn` and of the
// conformance sweep over BlueSky's scenario folder.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "command/navdb.h"
#include "command/stack.h"
#include "core/status.h"
#include "sim/openap_data.h"

namespace squawk::command {

struct ScenarioRunOptions {
  std::optional<double> until;  // [s] stop time; default: the last queued command time
  double max_sim_time = 3600.0;  // [s] sim-time cap on the default stop time (--max-sim-time)
  double max_wall_s = 600.0;     // [s] wall-clock cap on the whole run, 0 = none (--max-time)
  std::shared_ptr<const NavDb> navdb;  // may be null
  uint64_t seed = 0;
  int64_t max_conflict_pairs = sim::CdSettings{}.max_pairs;  // pairs stored per detection (--max-conflict-pairs)
  // Performance data: unset, the process default (SQUAWK_OPENAP / --openap);
  // set, that data (null: squawk's class model).
  std::optional<std::shared_ptr<const sim::OpenapData>> openap;
};

struct ScenarioRunResult {
  double end_time = 0.0;  // [s] sim time reached
  Tally tally;            // commands executed / skipped / failed
  int aircraft = 0;       // aircraft at the end
  int64_t conflicts = 0;  // conflict pairs entered (when detection was on)
  int64_t los = 0;        // losses of separation entered
  std::string cap_notice;  // sim::cap_notice: "" unless detections hit max_conflict_pairs
  double wall_s = 0.0;    // [s] wall-clock time of the run
};

// Loads `path` (IC) and runs it to `until`, or until every queued command has
// run (following PCALL/SCHEDULE additions) or max_sim_time is reached. `stack` receives
// the final state. Error: the file cannot be found or read, or the run took
// longer than max_wall_s of wall-clock time (kTimeout, naming the sim time).
Result<ScenarioRunResult> run_scenario(const std::string& path, const ScenarioRunOptions& opts, Stack& stack);

}  // namespace squawk::command
