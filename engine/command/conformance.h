// Conformance sweep: runs every file under a folder (BlueSky's scenario/)
// headless and totals what happened, for `squawk scn DIR --conformance` and
// the conformance test.
#pragma once

#include <functional>
#include <map>
#include <string>

#include "command/scenario_run.h"

namespace squawk::command {

struct ConformanceReport {
  int files = 0;
  int loaded = 0;         // files found and read
  int fully_run = 0;      // ran until every queued command ran, or to max_sim_time
  long executed = 0;      // commands that succeeded
  std::map<std::string, long> skipped;  // by command name
  std::map<std::string, long> failed;   // by reason (values blanked)
  std::map<std::string, long> load_errors;
  double sim_s = 0.0;     // [s] total simulated time
  double wall_s = 0.0;    // [s] total wall-clock time
};

// Runs every .scn file (any case) under `dir` (sorted paths). `progress`, when set,
// receives one line per file.
ConformanceReport run_conformance(const std::string& dir, const ScenarioRunOptions& opts,
                                  const std::function<void(const std::string&)>& progress = {});

// Markdown tables: totals, skipped commands by name, failures by reason.
std::string conformance_markdown(const ConformanceReport& r);

long total_count(const std::map<std::string, long>& m);

}  // namespace squawk::command
