// squawk render / squawk plot: SVG pictures of episodes and training curves.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <vector>

#include "app/cli.h"
#include "app/out_guard.h"
#include "app/subcommands.h"
#include "command/conformance.h"
#include "command/stack.h"
#include "core/files.h"
#include "core/paths.h"
#include "core/text.h"
#include "env/horizontal_cr.h"
#include "env/recorder.h"
#include "script/scenario.h"
#include "viz/chart.h"
#include "viz/csv.h"
#include "viz/scene.h"
#include "viz/traffic_scene.h"

namespace fs = std::filesystem;

namespace squawk::app {

namespace {

// What every SVG squawk draws begins with (viz/svg.cpp): such a file may be
// replaced without --force.
constexpr const char* kSvgPrefix = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg ";

int write_output(const std::string& subcommand, const std::string& out, const std::string& svg, bool force) {
  if (out == "-") {
    std::fputs(svg.c_str(), stdout);
    return kExitOk;
  }
  if (Status st = check_overwrite(out, kSvgPrefix, force); !st.is_ok()) return usage_error(subcommand, st.message());
  Status st = files::write_atomic(out, svg);
  if (!st.is_ok()) return failure(st);
  std::printf("wrote %s\n", out.c_str());
  return kExitOk;
}

// The first column of `t` whose name is in `names`, or -1.
int find_column(const viz::Table& t, std::initializer_list<const char*> names) {
  for (const char* n : names)
    if (int c = t.column(n); c >= 0) return c;
  return -1;
}

}  // namespace

// The recording of a scenario's first evaluation episode, as drawn at reset.
Result<std::string> scenario_start(const std::string& path, const script::VmOptions& vmo) {
  SQUAWK_ASSIGN_OR_RETURN(script::Scenario sc, script::load_scenario(path, vmo));
  SQUAWK_ASSIGN_OR_RETURN(env::HorizontalCrEnv e, env::HorizontalCrEnv::make(sc.eval_env));
  std::ostringstream out;
  env::JsonlRecorder rec(out);
  Rng rng(vmo.seed);
  SQUAWK_RETURN_IF_ERROR(e.reset_to(e.draw_setup(rng)).status());
  rec.on_reset(e);
  return out.str();
}

// A scenario file's traffic from t = 0 to `at` [s]; failed commands are
// summarised on stderr as `squawk scn` counts them.
Result<viz::Scene> scn_scene(const std::string& path, double at, const script::VmOptions& vmo) {
  command::Stack stack(vmo.seed);
  if (!vmo.navdata_dir.empty()) {
    SQUAWK_ASSIGN_OR_RETURN(auto db, command::NavDb::load_cached(vmo.navdata_dir));
    stack.set_navdb(std::move(db));
  }
  stack.set_base_dir(paths::dirname(path));
  SQUAWK_RETURN_IF_ERROR(stack.load_scenario(path));
  SQUAWK_ASSIGN_OR_RETURN(viz::Scene scene, viz::traffic_scene(stack, at));
  const command::Tally& t = stack.tally();
  if (const long failed = command::total_count(t.failed); failed > 0) {
    std::fprintf(stderr, "%s: %ld scenario commands failed up to t = %.0f s (squawk scn lists them), first:\n",
                 path.c_str(), failed, at);
    for (size_t k = 0; k < std::min<size_t>(3, t.first_failures.size()); ++k)
      std::fprintf(stderr, "  %s\n", t.first_failures[k].c_str());
  }
  scene.title = fs::path(path).filename().string() + ": traffic at t = " + text::fmt_double(at, 0) + " s";
  scene.subtitle = std::to_string(scene.frames.back().aircraft.size()) + " aircraft, tracks from t = 0";
  return scene;
}

int cmd_render(const ArgV& argv) {
  auto args = Args::parse(argv, {{"--out", "--frame", "--size", "--episode", "--seed", "--at", "--navdata"}, {"--force"}});
  if (!args) return usage_error("render", args.status().message());
  if (args->positional().size() != 1)
    return usage_error("render", "expected one EPISODE.jsonl, SCENARIO.lua or SCENARIO.scn");
  auto seed = args->get_int("--seed", 0);
  if (!seed || *seed < 0) return usage_error("render", "--seed expects a non-negative integer");
  script::VmOptions vmo_value;
  vmo_value.seed = static_cast<uint64_t>(*seed);
  const char* nav_env = std::getenv("SQUAWK_NAVDATA");
  vmo_value.navdata_dir = args->get_or("--navdata", nav_env ? nav_env : "");
  const script::VmOptions* vmo = &vmo_value;
  const std::string in = args->positional()[0];
  const std::string ext = fs::path(in).extension().string();
  auto frame = args->get_int("--frame", -1);
  if (!frame) return usage_error("render", frame.status().message());
  auto episode = args->get_int("--episode", -1);
  if (!episode) return usage_error("render", episode.status().message());
  auto size = args->get_double("--size", 720);
  if (!size || *size < 100 || *size > 8000)
    return usage_error("render", "--size expects pixels between 100 and 8000");
  auto at = args->get_double("--at", 0);
  if (!at || !(*at >= 0 && *at <= 86400)) return usage_error("render", "--at expects seconds from 0 to 86400");
  if (args->has("--at") && ext != ".scn") return usage_error("render", "--at applies to a .scn scenario only");

  Result<viz::Scene> scene = Status::internal("unset");
  if (ext == ".scn") {
    scene = scn_scene(in, *at, *vmo);
  } else {
    auto text = ext == ".lua" ? scenario_start(in, *vmo) : files::read(in);
    if (!text) return failure(text.status());
    scene = viz::parse_episode_jsonl(*text, *episode);
    if (scene) {
      const std::string name = fs::path(in).filename().string();
      scene->title = ext == ".lua" ? name + ", seed " + std::to_string(vmo->seed) + ": start of its evaluation episode"
                                   : name + ": " + scene->title;
    }
  }
  if (!scene) return failure(scene.status().with_context(in));
  if (Status st = viz::check_frame(*scene, *frame); !st.is_ok()) return usage_error("render", "--frame: " + st.message());
  const std::string out = args->get_or("--out", fs::path(in).replace_extension(".svg").string());
  return write_output("render", out, viz::render_scene(*scene, {*size, static_cast<int>(*frame)}), args->has("--force"));
}

int cmd_plot(const ArgV& argv) {
  auto args = Args::parse(argv, {{"--out"}, {"--force"}});
  if (!args) return usage_error("plot", args.status().message());
  if (args->positional().empty()) return usage_error("plot", "expected RUN_DIR or FILE.csv, one or more");
  // Every CSV of every RUN_DIR, then the files named, each drawn as one line.
  std::vector<std::string> csvs;
  std::error_code ec;
  for (const auto& target : args->positional()) {
    if (fs::is_directory(target, ec)) {
      std::vector<std::string> in_dir;
      for (const auto& e : fs::directory_iterator(target, ec))
        if (e.path().extension() == ".csv") in_dir.push_back(e.path().string());
      if (in_dir.empty()) return failure(Status::not_found("no CSV log in '" + target + "'"));
      std::sort(in_dir.begin(), in_dir.end());
      csvs.insert(csvs.end(), in_dir.begin(), in_dir.end());
    } else if (fs::is_regular_file(target, ec)) {
      csvs.push_back(target);
    } else {
      return failure(Status::not_found("no CSV file or run folder '" + target + "'"));
    }
  }
  const std::string target = args->positional()[0];

  viz::Panel success{"Average success rate", "episodes trained", "success rate", {}, true, 0, 1};
  viz::Panel reward{"Average reward", "episodes trained", "mean episode reward", {}, false, 0, 0};
  const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"};
  size_t used = 0;
  for (const auto& path : csvs) {
    auto text = files::read(path);
    if (!text) return failure(text.status());
    auto table = viz::parse_csv(*text);
    if (!table) return failure(table.status().with_context(path));
    const int x = find_column(*table, {"episodes", "episode", "episodes_trained"});
    const int s = find_column(*table, {"eval_success_rate", "success_rate", "success"});
    const int r = find_column(*table, {"eval_mean_reward", "mean_reward", "reward"});
    if (x < 0 || (s < 0 && r < 0)) {
      std::fprintf(stderr, "plot: skipped %s: no episodes column with success_rate or mean_reward\n", path.c_str());
      continue;
    }
    // A run's log.csv is named after its run folder; NAME.log.csv after NAME.
    std::string label = fs::path(path).stem().string();
    if (label == "log") label = fs::absolute(path).parent_path().filename().string();
    if (label.size() > 4 && label.substr(label.size() - 4) == ".log") label.resize(label.size() - 4);
    const std::string colour = colours[used++ % 5];
    if (s >= 0) success.series.push_back({label, table->values(x), table->values(s), colour});
    if (r >= 0) reward.series.push_back({label, table->values(x), table->values(r), colour});
  }
  if (used == 0)
    return failure(Status::invalid("no CSV in '" + target +
                                   "' has an episodes column and a success_rate or mean_reward column"));
  const bool one = args->positional().size() == 1;
  const std::string out = args->get_or(
      "--out", !one ? std::string("curves.svg")
               : fs::is_directory(target, ec) ? (fs::path(target) / "curves.svg").string()
                                              : fs::path(target).replace_extension(".svg").string());
  return write_output("plot", out, viz::panels_svg({success, reward}), args->has("--force"));
}

}  // namespace squawk::app
