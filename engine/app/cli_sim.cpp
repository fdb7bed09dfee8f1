// squawk scn / squawk commands.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>

#include <nlohmann/json.hpp>

#include "app/cli.h"
#include "app/subcommands.h"
#include "command/registry.h"
#include "command/scenario_run.h"
#include "core/text.h"
#include "core/units.h"

namespace fs = std::filesystem;

namespace squawk::app {

namespace {

Result<std::shared_ptr<const command::NavDb>> navdb_from(const Args& args) {
  std::string dir;
  if (auto nav = args.get("--navdata")) dir = *nav;
  else if (const char* env = std::getenv("SQUAWK_NAVDATA"); env && *env) dir = env;
  if (dir.empty()) return std::shared_ptr<const command::NavDb>();
  return command::NavDb::load(dir);
}

std::string final_state_json(const command::Stack& stack) {
  const sim::Traffic& t = stack.sim().traffic();
  nlohmann::json ac = nlohmann::json::array();
  for (int i = 0; i < t.n(); ++i) {
    ac.push_back({{"id", t.id[i]},
                  {"type", t.type[i]},
                  {"lat", t.lat[i]},
                  {"lon", t.lon[i]},
                  {"alt_ft", units::m_to_ft(t.alt[i])},
                  {"hdg_deg", t.hdg[i]},
                  {"tas_kt", units::ms_to_kt(t.tas[i])},
                  {"cas_kt", units::ms_to_kt(t.cas[i])},
                  {"gs_kt", units::ms_to_kt(t.gs[i])},
                  {"vs_fpm", units::ms_to_fpm(t.vs[i])}});
  }
  nlohmann::json out = {{"simt", stack.sim().simt()}, {"aircraft", ac}};
  return out.dump(2);
}

long total(const std::map<std::string, long>& m) {
  long n = 0;
  for (const auto& [k, v] : m) n += v;
  return n;
}

// Entries of a count map, largest first.
std::vector<std::pair<std::string, long>> by_count(const std::map<std::string, long>& m) {
  std::vector<std::pair<std::string, long>> v(m.begin(), m.end());
  std::stable_sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  return v;
}

void print_counts(const char* title, const std::map<std::string, long>& m, size_t limit) {
  if (m.empty()) return;
  std::printf("%s:\n", title);
  size_t k = 0;
  for (const auto& [name, n] : by_count(m)) {
    if (k++ == limit) {
      std::printf("  ... %zu more\n", m.size() - limit);
      break;
    }
    std::printf("  %6ld  %s\n", n, name.c_str());
  }
}

int run_one(const std::string& file, const Args& args, const command::ScenarioRunOptions& opts) {
  command::Stack stack;
  auto r = command::run_scenario(file, opts, stack);
  if (!r) return failure(r.status());
  if (args.has("--dump-json")) {
    std::printf("%s\n", final_state_json(stack).c_str());
    return r->tally.failed.empty() ? kExitOk : kExitFail;
  }
  for (const auto& line : stack.take_output()) std::printf("%s\n", line.c_str());
  std::printf("scenario %s: ran to t = %.2f s in %.2f s wall\n", file.c_str(), r->end_time, r->wall_s);
  std::printf("commands: %ld executed, %ld skipped, %ld failed\n", r->tally.executed, total(r->tally.skipped),
              total(r->tally.failed));
  print_counts("skipped (not squawk commands), by name", r->tally.skipped, 1000);
  print_counts("failed, by reason", r->tally.failed, 1000);
  std::printf("aircraft: %d; conflicts: %lld; losses of separation: %lld\n", r->aircraft,
              static_cast<long long>(r->conflicts), static_cast<long long>(r->los));
  return r->tally.failed.empty() ? kExitOk : kExitFail;
}

// Runs every file under `dir` and prints the conformance table (Markdown).
int run_conformance(const std::string& dir, const command::ScenarioRunOptions& opts) {
  std::vector<std::string> paths;
  std::error_code ec;
  for (const auto& e : fs::recursive_directory_iterator(dir, ec))
    if (e.is_regular_file()) paths.push_back(e.path().string());
  if (ec || paths.empty()) return failure(Status::not_found("no files under " + text::quoted(dir)));
  std::sort(paths.begin(), paths.end());
  int loaded = 0, full = 0;
  long executed = 0;
  double sim_s = 0, wall_s = 0;
  std::map<std::string, long> skipped, failed, load_errors;
  for (const auto& p : paths) {
    command::Stack stack;
    auto r = command::run_scenario(p, opts, stack);
    if (!r) {
      ++load_errors[r.status().message()];
      continue;
    }
    ++loaded;
    if (r->end_time + 0.5 * stack.sim().dt() >= opts.max_time || stack.queued() == 0) ++full;
    executed += r->tally.executed;
    for (const auto& [k, v] : r->tally.skipped) skipped[k] += v;
    for (const auto& [k, v] : r->tally.failed) failed[k] += v;
    sim_s += r->end_time;
    wall_s += r->wall_s;
    std::fprintf(stderr, "%-60s t=%8.1f s  %6ld ok %5ld skipped %5ld failed  %.2f s\n", p.c_str(), r->end_time,
                 r->tally.executed, total(r->tally.skipped), total(r->tally.failed), r->wall_s);
  }
  std::printf("| files | loaded | fully run | commands executed | skipped | failed | sim time | wall time |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  std::printf("| %zu | %d | %d | %ld | %ld | %ld | %.0f s | %.1f s |\n\n", paths.size(), loaded, full, executed,
              total(skipped), total(failed), sim_s, wall_s);
  std::printf("| skipped command (not in squawk) | count |\n|---|---|\n");
  for (const auto& [k, v] : by_count(skipped)) std::printf("| %s | %ld |\n", k.c_str(), v);
  std::printf("\n| failure reason | count |\n|---|---|\n");
  for (const auto& [k, v] : by_count(failed)) std::printf("| %s | %ld |\n", k.c_str(), v);
  for (const auto& [k, v] : load_errors) std::printf("| (file not loaded) %s | %ld |\n", k.c_str(), v);
  return loaded == static_cast<int>(paths.size()) ? kExitOk : kExitFail;
}

}  // namespace

int cmd_scn(const ArgV& argv) {
  Args::Spec spec;
  spec.value_flags = {"--until", "--navdata", "--seed", "--max-time"};
  spec.bool_flags = {"--dump-json", "--conformance"};
  auto args = Args::parse(argv, spec);
  if (!args) return usage_error("scn", args.status().message());
  if (args->positional().size() != 1) return usage_error("scn", "expected one FILE.scn (or DIR with --conformance)");
  command::ScenarioRunOptions opts;
  if (args->has("--until")) {
    auto u = args->get_double("--until", 0.0);
    if (!u || *u < 0) return usage_error("scn", "--until expects seconds >= 0");
    opts.until = *u;
  }
  auto max_time = args->get_double("--max-time", opts.max_time);
  if (!max_time || *max_time <= 0) return usage_error("scn", "--max-time expects seconds > 0");
  opts.max_time = *max_time;
  auto seed = args->get_int("--seed", 0);
  if (!seed || *seed < 0) return usage_error("scn", "--seed expects an integer >= 0");
  opts.seed = static_cast<uint64_t>(*seed);
  auto db = navdb_from(*args);
  if (!db) return failure(db.status());
  opts.navdb = *db;
  const std::string& target = args->positional()[0];
  if (args->has("--conformance")) return run_conformance(target, opts);
  return run_one(target, *args, opts);
}

int cmd_commands(const ArgV& argv) {
  Args::Spec spec;
  spec.bool_flags = {"--json"};
  auto args = Args::parse(argv, spec);
  if (!args) return usage_error("commands", args.status().message());
  const command::Registry& reg = command::Registry::instance();
  if (args->has("--json")) {
    std::printf("%s\n", reg.to_json().c_str());
    return kExitOk;
  }
  if (args->positional().size() > 1) return usage_error("commands", "expected at most one command name");
  auto text = reg.help(args->positional().empty() ? "" : args->positional()[0]);
  if (!text) return failure(text.status());
  std::fputs(text->c_str(), stdout);
  return kExitOk;
}

}  // namespace squawk::app
