#include "command/conformance.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "core/text.h"

namespace fs = std::filesystem;

namespace squawk::command {

namespace {

std::vector<std::pair<std::string, long>> by_count(const std::map<std::string, long>& m) {
  std::vector<std::pair<std::string, long>> v(m.begin(), m.end());
  std::stable_sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  return v;
}

// Markdown table cells must not contain '|'.
std::string cell(std::string s) {
  std::replace(s.begin(), s.end(), '|', '/');
  return s;
}

}  // namespace

long total_count(const std::map<std::string, long>& m) {
  long n = 0;
  for (const auto& [k, v] : m) n += v;
  return n;
}

ConformanceReport run_conformance(const std::string& dir, const ScenarioRunOptions& opts,
                                  const std::function<void(const std::string&)>& progress) {
  ConformanceReport rep;
  std::vector<std::string> paths;
  std::error_code ec;
  for (const auto& e : fs::recursive_directory_iterator(dir, ec))
    if (e.is_regular_file() && text::lower(e.path().extension().string()) == ".scn") paths.push_back(e.path().string());
  std::sort(paths.begin(), paths.end());
  rep.files = static_cast<int>(paths.size());
  for (const auto& p : paths) {
    Stack stack;
    auto r = run_scenario(p, opts, stack);
    if (!r) {
      ++rep.load_errors[r.status().message()];
      continue;
    }
    ++rep.loaded;
    if (stack.queued() == 0 || r->end_time + 0.5 * stack.sim().dt() >= opts.max_sim_time) ++rep.fully_run;
    rep.executed += r->tally.executed;
    for (const auto& [k, v] : r->tally.skipped) rep.skipped[k] += v;
    for (const auto& [k, v] : r->tally.failed) rep.failed[k] += v;
    rep.sim_s += r->end_time;
    rep.wall_s += r->wall_s;
    if (progress) {
      char buf[512];
      std::snprintf(buf, sizeof buf, "%-64s t=%8.1f s %7ld ok %6ld skipped %6ld failed %7.2f s", p.c_str(),
                    r->end_time, r->tally.executed, total_count(r->tally.skipped), total_count(r->tally.failed),
                    r->wall_s);
      progress(buf);
    }
  }
  return rep;
}

std::string conformance_markdown(const ConformanceReport& r) {
  std::string out;
  char buf[512];
  out.append("| files | loaded | fully run | commands executed | skipped | failed | sim time | wall time |\n");
  out.append("|---|---|---|---|---|---|---|---|\n");
  std::snprintf(buf, sizeof buf, "| %d | %d | %d | %ld | %ld | %ld | %.0f s | %.1f s |\n", r.files, r.loaded,
                r.fully_run, r.executed, total_count(r.skipped), total_count(r.failed), r.sim_s, r.wall_s);
  out.append(buf);
  out.append("\n| skipped command (not in squawk) | count |\n|---|---|\n");
  for (const auto& [k, v] : by_count(r.skipped)) out.append("| " + cell(k) + " | " + std::to_string(v) + " |\n");
  out.append("\n| failure reason | count |\n|---|---|\n");
  for (const auto& [k, v] : by_count(r.failed)) out.append("| " + cell(k) + " | " + std::to_string(v) + " |\n");
  for (const auto& [k, v] : r.load_errors)
    out.append("| (file not loaded) " + cell(k) + " | " + std::to_string(v) + " |\n");
  return out;
}

}  // namespace squawk::command
