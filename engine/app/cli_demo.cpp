// squawk demo: the paper's team loop end to end. The deconfliction agent
// decides on the HorizontalCR environment's observation; its decision is said
// in controller English by the Lua template prompts/advisory.lua; the
// translator turns the English into TrafScript; the simulator's command stack
// executes it, and the simulator flies the traffic.
//
// Two worlds run side by side: the environment (the agent's observation and
// the paper's rules) and the Simulation (what the TrafScript commands act
// on). The environment flies exactly the heading the simulator was told, so
// the two stay together; the summary prints their largest difference.
// Automatic steering toward the waypoint (paper rules: no conflict predicted)
// reaches the simulator as a plain HDG command, marked "autopilot".
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <set>
#include <sstream>

#include "app/cli.h"
#include "app/rl_eval.h"
#include "app/team_loop.h"
#include "app/subcommands.h"
#include "app/vm_options.h"
#include "command/stack.h"
#include "core/files.h"
#include "core/geo.h"
#include "core/paths.h"
#include "core/text.h"
#include "core/units.h"
#include "env/horizontal_cr.h"
#include "env/recorder.h"
#include "script/advisory.h"
#include "script/policy_factory.h"
#include "script/scenario.h"
#include "script/translate_graph.h"
#include "viz/scene.h"

namespace squawk::app {

namespace {

constexpr const char* kOwn = kTeamOwnship;

class Demo : public env::EpisodeObserver {
 public:
  Demo(command::Stack& stack, bool quiet, env::EpisodeObserver* recorder)
      : stack_(stack), quiet_(quiet), recorder_(recorder) {}

  void log(const char* hop, const std::string& what) {
    if (!quiet_) std::printf("[t=%5.0f s] %-10s %s\n", stack_.sim().simt(), hop, what.c_str());
  }

  // Runs a TrafScript line on the simulator, logging it under `hop`.
  Status exec(const char* hop, const std::string& line) {
    auto r = stack_.exec(line);
    if (!r.is_ok()) {
      log(hop, line + "  -> ERROR " + r.status().message());
      return r.status();
    }
    log(hop, line + (r->empty() ? "" : "  -> " + *r));
    return Status::ok();
  }

  void on_reset(const env::HorizontalCrEnv& e) override {
    if (recorder_) recorder_->on_reset(e);
  }
  void on_end(const env::HorizontalCrEnv& e, const env::EpisodeStats& st) override {
    if (recorder_) recorder_->on_end(e, st);
  }

  // Every environment step: automatic steering becomes an HDG command; then
  // the simulator flies the same step and is compared with the environment.
  void on_step(const env::HorizontalCrEnv& e, const env::StepInfo& info) override {
    if (recorder_) recorder_->on_step(e, info);
    if (!info.agent) {
      char line[64];
      std::snprintf(line, sizeof line, "HDG %s %.2f", kOwn, geo::wrap360(info.hdg_cmd));
      if (!exec("autopilot", line).is_ok()) failed_ = true;
    }
    const double t_end = stack_.sim().simt() + e.config().dt * e.config().substeps;
    if (!stack_.run_until(t_end).is_ok()) failed_ = true;
    observe(e);
  }

  // Conflicts and losses of separation the simulator's detector reports for
  // the ownship; track length; agreement with the environment; one frame.
  void observe(const env::HorizontalCrEnv& e) {
    const auto& t = stack_.sim().traffic();
    const int own = stack_.sim().index_of(kOwn);
    for (const auto& c : stack_.sim().conflicts())
      if (c.own == own) conflicts_.insert(t.id[static_cast<size_t>(c.intruder)]);
    for (const auto& l : stack_.sim().los())
      if (l.own == own || l.intruder == own)
        los_.insert(t.id[static_cast<size_t>(l.own == own ? l.intruder : l.own)]);
    const size_t o = static_cast<size_t>(own);
    if (have_last_) flown_m_ += geo::gc_distance_m(last_lat_, last_lon_, t.lat[o], t.lon[o]);
    last_lat_ = t.lat[o], last_lon_ = t.lon[o], have_last_ = true;
    for (int i = 0; i < static_cast<int>(e.fleet().size()); ++i) {
      const size_t k = static_cast<size_t>(i);
      worst_m_ = std::max(worst_m_, geo::gc_distance_m(t.lat[k], t.lon[k], e.fleet().lat(i), e.fleet().lon(i)));
    }
    viz::Frame f;
    f.t = stack_.sim().simt();
    for (int i = 0; i < t.n(); ++i) {
      const size_t k = static_cast<size_t>(i);
      f.aircraft.push_back({t.id[k], t.lat[k], t.lon[k], t.hdg[k], {}, false});
    }
    f.note = note_;
    note_.clear();
    scene.frames.push_back(std::move(f));
  }

  command::Stack& stack_;
  bool quiet_;
  env::EpisodeObserver* recorder_;
  bool failed_ = false;
  std::set<std::string> conflicts_, los_;
  double flown_m_ = 0, worst_m_ = 0;
  double last_lat_ = 0, last_lon_ = 0;
  bool have_last_ = false;
  std::string note_;
  viz::Scene scene;
};

std::string fmt(const char* f, double a, double b = 0, double c = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, a, b, c);
  return buf;
}

}  // namespace

int cmd_demo(const ArgV& argv) {
  auto args = Args::parse(argv, with_vm_flags({{"--policy", "--checkpoint", "--scenario", "--record",
                                                "--svg", "--advisory"},
                                               {"--quiet"}}));
  if (!args) return usage_error("demo", args.status().message());
  if (!args->positional().empty()) return usage_error("demo", "takes no positional arguments");
  auto vmo = vm_options(*args);
  if (!vmo) return usage_error("demo", vmo.status().message());
  const std::string policy_kind = args->get_or("--policy", "mlp");
  if (policy_kind != "mlp" && policy_kind != "gpt2")
    return usage_error("demo", "--policy '" + policy_kind + "': expected mlp or gpt2");
  const bool quiet = args->has("--quiet");
  const auto wall0 = std::chrono::steady_clock::now();

  auto sc = script::load_scenario(args->get_or("--scenario", paths::resource("scenarios/horizontal_cr.lua")), *vmo);
  if (!sc) return failure(sc.status());
  auto made = env::HorizontalCrEnv::make(sc->eval_env);
  if (!made) return failure(made.status());
  env::HorizontalCrEnv& e = made.value();
  const auto& cfg = e.config();

  // The agent: the shipped trained MLP, or the fine-tuned GPT-2 prompt policy.
  auto agent = load_team_policy(policy_kind, *sc, args->get_or("--checkpoint", ""), *vmo);
  if (!agent) return failure(agent.status());
  if (std::string w = trained_elsewhere(*agent, *sc, *vmo); !w.empty())
    std::fprintf(stderr, "squawk demo: warning: %s\n", w.c_str());
  std::unique_ptr<rl::Policy> policy = std::move(agent->policy);
  auto phraser = script::AdvisoryPhraser::load(args->get_or("--advisory", paths::resource("prompts/advisory.lua")), *vmo);
  if (!phraser) return failure(phraser.status());

  // The first episode of the seed's sequence in which the agent has to act.
  Rng rng(vmo->seed);
  auto setup = first_agent_episode(e, rng);
  if (!setup) return failure(setup.status());

  // The simulator: same time step, BlueSky's ground-phase speed cap, CD on.
  command::Stack stack(vmo->seed);
  if (Status st = apply_env_limits(stack, cfg); !st.is_ok()) return failure(st);
  std::ostringstream recording;
  env::JsonlRecorder recorder(recording);
  Demo demo(stack, quiet, args->has("--record") ? &recorder : nullptr);
  if (!quiet)
    std::printf("squawk demo: %s agent on %s (%s), seed %llu\n", policy_kind.c_str(), sc->path.c_str(),
                cfg.rules == env::Rules::kGym
                    ? "gym rules: the agent decides at every step"
                    : fmt("paper rules, look-ahead %.0f s", cfg.lookahead).c_str(),
                static_cast<unsigned long long>(vmo->seed));
  bool ok = true;
  for (const auto& line : team_setup_commands(cfg, *setup)) ok = ok && demo.exec("sim", line).is_ok();
  if (!ok) return failure(Status::internal("the simulator refused the scenario set-up"));
  demo.scene.title = "squawk demo, seed " + std::to_string(vmo->seed);
  demo.scene.wpt_lat = e.waypoint_lat();
  demo.scene.wpt_lon = e.waypoint_lon();
  demo.scene.rpz_nm = cfg.zone_radius / units::kNm;
  demo.scene.wpt_radius_km = cfg.reach_radius / 1000.0;
  demo.log("waypoint", fmt("%.5f %.5f, %.1f km north", e.waypoint_lat(), e.waypoint_lon(),
                           geo::gc_distance_m(cfg.start_lat, cfg.start_lon, e.waypoint_lat(), e.waypoint_lon()) / 1000));
  demo.observe(e);
  demo.on_reset(e);
  e.set_observer(&demo);

  script::Vm translator_vm(*vmo);  // runs the translation graph (scripts/translate/graph.lua)
  int decisions = 0, untranslated = 0;
  while (!e.done() && !demo.failed_) {
    const double hdg_now = e.fleet().hdg(0);
    const script::Advisory adv = agent_advisory(*policy, e, stack.sim(), rng);
    auto english = phraser->phrase(adv);
    if (!english) return failure(english.status());
    ++decisions;
    demo.log("agent", fmt("action %+.2f: heading %03.0f -> %03.0f", adv.action, hdg_now, adv.heading));
    demo.log("advisory", "\"" + *english + "\"");
    demo.note_ = *english;
    auto translated = script::run_translation_graph(translator_vm, *english, {"offline", "", &stack});
    if (!translated) return failure(translated.status());
    const translate::Translation& tr = *translated;
    if (!tr.issued()) {
      ++untranslated;
      demo.log("translator", tr.text() + " (no command; heading kept)");
    } else {
      demo.log("translator", tr.text());
      for (const auto& cmd : tr.commands)
        if (!demo.exec("sim", cmd).is_ok()) ++untranslated;
    }
    (void)script::collect_after_reply(translator_vm);  // (the translation is logged)
    e.step(env_action(e, stack.sim()));
  }
  if (demo.failed_) return failure(Status::internal("the simulator failed during the episode"));

  const auto& st = e.stats();
  const double direct = geo::gc_distance_m(cfg.start_lat, cfg.start_lon, e.waypoint_lat(), e.waypoint_lon()) -
                        geo::gc_distance_m(demo.last_lat_, demo.last_lon_, e.waypoint_lat(), e.waypoint_lon());
  size_t resolved = 0;
  for (const auto& id : demo.conflicts_) resolved += demo.los_.count(id) == 0;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  std::printf("\nsummary\n");
  std::printf("  agent decisions           %d (advisories the translator could not turn into a command: %d)\n",
              decisions, untranslated);
  std::printf("  conflicts met             %zu (intruders the simulator's detector flagged for %s)\n",
              demo.conflicts_.size(), kOwn);
  std::printf("  conflicts resolved        %zu\n", resolved);
  std::printf("  losses of separation      %zu\n", demo.los_.size());
  std::printf("  extra track length        %.1f km (flown %.1f km, direct %.1f km)\n",
              (demo.flown_m_ - direct) / 1000, demo.flown_m_ / 1000, direct / 1000);
  std::printf("  waypoint reached          %s after %.0f s of flight; episode %s (%s)\n",
              st.reached ? "yes" : "no", stack.sim().simt(), st.success ? "successful" : "failed",
              success_definition(*sc).c_str());
  std::printf("  environment vs simulator  %.3f m largest position difference\n", demo.worst_m_);
  std::printf("  wall time                 %.2f s\n", wall);

  if (auto rec = args->get("--record")) {
    if (Status s = files::write_atomic(*rec, recording.str()); !s.is_ok()) return failure(s);
    std::printf("  recorded episode          %s\n", rec->c_str());
  }
  if (auto svg = args->get("--svg")) {
    if (Status s = files::write_atomic(*svg, viz::render_scene(demo.scene)); !s.is_ok()) return failure(s);
    std::printf("  picture                   %s\n", svg->c_str());
  }
  return untranslated == 0 ? kExitOk : kExitFail;
}

}  // namespace squawk::app
