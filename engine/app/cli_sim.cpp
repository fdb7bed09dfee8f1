// squawk scn / squawk commands.
#include <cstdio>
#include <cstdlib>
#include <map>

#include <nlohmann/json.hpp>

#include "app/cli.h"
#include "app/subcommands.h"
#include "app/vm_options.h"
#include "command/registry.h"
#include "command/conformance.h"
#include "command/scenario_run.h"
#include "core/text.h"
#include "core/units.h"

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

void print_counts(const char* title, const std::map<std::string, long>& m) {
  if (m.empty()) return;
  std::printf("%s:\n", title);
  for (const auto& [name, n] : m) std::printf("  %6ld  %s\n", n, name.c_str());
}

int run_one(const std::string& file, const Args& args, const command::ScenarioRunOptions& opts) {
  command::Stack stack;
  auto r = command::run_scenario(file, opts, stack);
  if (!r) return failure(r.status());
  if (args.has("--dump-json")) {  // stdout holds only the JSON: failures go to stderr
    for (const auto& line : r->tally.first_failures) std::fprintf(stderr, "%s\n", line.c_str());
    const long failed = command::total_count(r->tally.failed);
    if (failed > static_cast<long>(r->tally.first_failures.size()))
      std::fprintf(stderr, "(%ld failures in all)\n", failed);
    if (!r->cap_notice.empty()) std::fprintf(stderr, "note: %s\n", r->cap_notice.c_str());
    std::printf("%s\n", final_state_json(stack).c_str());
    return r->tally.failed.empty() ? kExitOk : kExitFail;
  }
  for (const auto& line : stack.take_output()) std::printf("%s\n", line.c_str());
  std::printf("scenario %s: ran to t = %.2f s in %.2f s wall\n", file.c_str(), r->end_time, r->wall_s);
  std::printf("commands: %ld executed, %ld skipped, %ld failed\n", r->tally.executed, command::total_count(r->tally.skipped),
              command::total_count(r->tally.failed));
  print_counts("skipped (BlueSky display and plugin commands squawk does not implement), by name", r->tally.skipped);
  print_counts("failed, by reason", r->tally.failed);
  std::printf("aircraft: %d; conflicts: %lld; losses of separation: %lld\n", r->aircraft,
              static_cast<long long>(r->conflicts), static_cast<long long>(r->los));
  if (!r->cap_notice.empty()) std::printf("note: %s\n", r->cap_notice.c_str());
  return r->tally.failed.empty() ? kExitOk : kExitFail;
}

}  // namespace

int cmd_scn(const ArgV& argv) {
  Args::Spec spec;
  spec.value_flags = {"--until", "--navdata", "--seed", "--max-time", "--max-sim-time", "--max-conflict-pairs"};
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
  auto max_sim = args->get_double("--max-sim-time", opts.max_sim_time);
  if (!max_sim || !(*max_sim > 0)) return usage_error("scn", "--max-sim-time expects seconds > 0");
  opts.max_sim_time = *max_sim;
  auto max_wall = args->get_double("--max-time", opts.max_wall_s);
  if (!max_wall || !(*max_wall >= 0)) return usage_error("scn", "--max-time expects seconds >= 0 (0 = no limit)");
  opts.max_wall_s = *max_wall;
  auto seed = args->get_int("--seed", 0);
  if (!seed || *seed < 0) return usage_error("scn", "--seed expects an integer >= 0");
  opts.seed = static_cast<uint64_t>(*seed);
  auto cap = args->get_int("--max-conflict-pairs", opts.max_conflict_pairs);
  if (!cap || *cap < 1) return usage_error("scn", "--max-conflict-pairs expects a count >= 1");
  opts.max_conflict_pairs = *cap;
  auto db = navdb_from(*args);
  if (!db) return failure(db.status());
  opts.navdb = *db;
  const std::string& target = args->positional()[0];
  if (args->has("--conformance")) {
    const auto rep = command::run_conformance(target, opts, [](const std::string& line) {
      std::fprintf(stderr, "%s\n", line.c_str());
    });
    if (rep.files == 0) return failure(Status::not_found("no .scn files under " + text::quoted(target)));
    std::fputs(command::conformance_markdown(rep).c_str(), stdout);
    return rep.loaded == rep.files ? kExitOk : kExitFail;
  }
  if (Status st = check_scn_file(target, true); !st.is_ok()) return usage_error("scn", st.message());
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
