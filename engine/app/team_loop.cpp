#include "app/team_loop.h"

#include <cmath>
#include <cstdio>

#include "core/geo.h"
#include "core/paths.h"
#include "core/units.h"
#include "env/vec_env.h"

namespace squawk::app {

namespace {

std::string fmt(const char* f, double a, double b = 0, double c = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, a, b, c);
  return buf;
}

// The ownship's most urgent conflict: intruder, clock position, distance.
std::optional<script::Advisory::Traffic> nearest_conflict(const sim::Simulation& sim) {
  const auto& t = sim.traffic();
  const int own = sim.index_of(kTeamOwnship);
  const sim::ConflictPair* best = nullptr;
  for (const auto& c : sim.conflicts())
    if (c.own == own && (!best || c.tlos < best->tlos)) best = &c;
  if (!best) return std::nullopt;
  const double rel = geo::wrap360(best->qdr - t.hdg[static_cast<size_t>(own)]);
  int clock = static_cast<int>(std::lround(rel / 30.0)) % 12;
  if (clock == 0) clock = 12;
  return script::Advisory::Traffic{t.id[static_cast<size_t>(best->intruder)], clock, best->dist / units::kNm};
}

}  // namespace

Result<script::MadePolicy> load_team_policy(const std::string& kind, const script::Scenario& sc,
                                            const std::string& checkpoint, const script::VmOptions& vm) {
  const char* hint =
      "the agent needs a trained policy (train one with `squawk train scenarios/horizontal_cr.lua "
      "--policy mlp|gpt2 --out DIR`, then pass --checkpoint DIR/policy.ckpt)";
  // Only agents that decide on the observation alone: the VecEnv below dies here.
  if (kind != "mlp" && kind != "gpt2") return Status::invalid("policy '" + kind + "': expected mlp or gpt2");
  auto one_env = env::VecEnv::make(sc.eval_env, 1);
  if (!one_env) return one_env.status();
  script::PolicyOptions popts;
  popts.checkpoint = checkpoint;
  auto made = script::make_policy(kind, sc, *one_env, popts, vm);
  if (!made) return made.status().with_context(hint);
  return made;
}

Result<env::EpisodeSetup> first_agent_episode(env::HorizontalCrEnv& e, Rng& rng) {
  for (int tries = 0; tries < 1000; ++tries) {
    env::EpisodeSetup setup = e.draw_setup(rng);
    auto r = e.reset_to(setup);
    if (!r) return r.status();
    if (*r) return setup;
  }
  return Status::internal("no episode in 1000 needed the agent");
}

Status apply_env_limits(command::Stack& stack, const env::HorizontalCrConfig& cfg) {
  if (cfg.limits.speed_cap <= 0) return Status::ok();
  sim::PerformanceOptions perf;
  perf.ground_cap = true;
  perf.ground_vmax = cfg.limits.speed_cap;
  perf.ground_axmax = cfg.limits.accel;
  return stack.sim().set_performance_options(perf);
}

std::vector<std::string> team_setup_commands(const env::HorizontalCrConfig& cfg, const env::EpisodeSetup& setup) {
  std::vector<std::string> lines = {
      fmt("DT %g", cfg.dt), fmt("ZONER %g", cfg.zone_radius / units::kNm), fmt("DTLOOK %g", cfg.lookahead), "ASAS ON",
      std::string("CRE ") + kTeamOwnship + " A320 " +
          fmt("%.8f %.8f 0 0 %.6f", cfg.start_lat, cfg.start_lon, units::ms_to_kt(cfg.own_speed))};
  for (size_t i = 0; i < setup.intruders.size(); ++i) {
    const auto& in = setup.intruders[i];
    lines.push_back("CRE " + std::to_string(i) + " A320 " + fmt("%.8f %.8f %.4f", in.lat, in.lon, geo::wrap360(in.hdg)) +
                    fmt(" 0 %.6f", units::ms_to_kt(in.tas)));
  }
  return lines;
}

script::Advisory agent_advisory(rl::Policy& policy, const env::HorizontalCrEnv& e, const sim::Simulation& sim,
                                Rng& rng) {
  std::vector<float> obs(static_cast<size_t>(e.observation_size()));
  e.observe_flat(obs);
  rl::ActionSample a;
  const int slot = 0;
  policy.act(obs, 1, {&slot, 1}, {&rng, 1}, /*greedy=*/true, {&a, 1});
  const double hdg_now = e.fleet().hdg(0);
  int target = static_cast<int>(std::lround(geo::wrap360(hdg_now + a.value * e.config().heading_per_action)));
  if (target <= 0) target += 360;
  return script::Advisory{kTeamOwnship, a.value, target, hdg_now,
                          a.value > 0 ? "right" : (a.value < 0 ? "left" : "none"), nearest_conflict(sim)};
}

double env_action(const env::HorizontalCrEnv& e, const sim::Simulation& sim) {
  const double hdg_sel = sim.traffic().sel_hdg[static_cast<size_t>(sim.index_of(kTeamOwnship))];
  return geo::wrap180(hdg_sel - e.fleet().hdg(0)) / e.config().heading_per_action;
}

}  // namespace squawk::app
