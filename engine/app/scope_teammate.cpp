#include "app/scope_teammate.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <vector>

#include "core/geo.h"
#include "core/paths.h"
#include "core/units.h"
#include "sim/atmosphere.h"
#include "script/scenario.h"

namespace squawk::app {

namespace {
constexpr double kEps = 1e-6;  // [s] clock comparisons

// The most urgent conflict of the ownship within kTrafficInfoNm, as traffic
// information: clock position from the ownship's heading, distance now.
std::optional<script::Advisory::Traffic> traffic_info(const sim::Simulation& sim) {
  const auto& t = sim.traffic();
  const int own = sim.index_of(kTeamOwnship);
  const sim::ConflictPair* best = nullptr;
  for (const auto& c : sim.conflicts())
    if (c.own == own && c.dist <= kTrafficInfoNm * units::kNm && (!best || c.tlos < best->tlos)) best = &c;
  if (!best) return std::nullopt;
  int clock = static_cast<int>(std::lround(geo::wrap360(best->qdr - t.hdg[static_cast<size_t>(own)]) / 30.0)) % 12;
  if (clock == 0) clock = 12;
  return script::Advisory::Traffic{t.id[static_cast<size_t>(best->intruder)], clock, best->dist / units::kNm};
}
}  // namespace

std::string believable_cre(const std::string& line, int index) {
  std::istringstream in(line);
  std::vector<std::string> w;
  for (std::string tok; in >> tok;) w.push_back(tok);
  if (w.size() != 8 || w[0] != "CRE") return line;
  const double alt = units::fl_to_m(kLevel);
  const double cas_kt = units::ms_to_kt(sim::tas_to_cas(units::kt_to_ms(std::strtod(w[7].c_str(), nullptr)), alt));
  if (index >= 0) {
    const auto& [callsign, type] = kIntruders[static_cast<size_t>(index) % std::size(kIntruders)];
    w[1] = callsign;
    w[2] = type;
  }
  char tail[64];
  std::snprintf(tail, sizeof tail, "FL%.0f %.6f", kLevel, cas_kt);
  return w[0] + " " + w[1] + " " + w[2] + " " + w[3] + " " + w[4] + " " + w[5] + " " + tail;
}

Result<std::unique_ptr<ScopeTeammate>> ScopeTeammate::make(const TeammateOptions& opts, const script::VmOptions& vm) {
  auto sc = script::load_scenario(opts.scenario.empty() ? paths::resource("scenarios/horizontal_cr.lua") : opts.scenario, vm);
  if (!sc) return sc.status();
  auto e = env::HorizontalCrEnv::make(sc->eval_env);
  if (!e) return e.status();
  auto agent = load_team_policy(opts.policy, *sc, opts.checkpoint, vm);
  if (!agent) return agent.status();
  auto phraser =
      script::AdvisoryPhraser::load(opts.advisory.empty() ? paths::resource("prompts/advisory.lua") : opts.advisory, vm);
  if (!phraser) return phraser.status();
  return std::unique_ptr<ScopeTeammate>(
      new ScopeTeammate(std::move(*e), std::move(agent->policy), std::move(*phraser), vm.seed));
}

Status ScopeTeammate::start(command::Stack& stack) {
  auto setup = first_agent_episode(env_, rng_);
  if (!setup) return setup.status();
  SQUAWK_RETURN_IF_ERROR(apply_env_limits(stack, env_.config()));
  int intruder = -1;  // the CRE lines come ownship first, then the intruders in order
  for (const auto& line : team_setup_commands(env_.config(), *setup)) {
    const bool cre = line.rfind("CRE ", 0) == 0;
    auto r = stack.exec(cre ? believable_cre(line, intruder++) : line);
    if (!r) return r.status().with_context("teammate set-up");
  }
  char wpt[96];
  std::snprintf(wpt, sizeof wpt, "DEFWPT GOAL %.6f %.6f; ADDWPT %s GOAL", env_.waypoint_lat(), env_.waypoint_lon(),
                kTeamOwnship);
  if (auto r = stack.exec(wpt); !r) return r.status().with_context("teammate set-up");
  // The waypoint is shown as the ownship's route; the environment steers.
  if (auto r = stack.exec(std::string("LNAV ") + kTeamOwnship + " OFF"); !r) return r.status();
  env_.set_observer(this);
  return Status::ok();
}

void ScopeTeammate::on_step(const env::HorizontalCrEnv& e, const env::StepInfo& info) {
  if (info.agent || !stack_) return;
  const double step_s = e.config().dt * e.config().substeps;
  char line[64];
  std::snprintf(line, sizeof line, "HDG %s %.2f", kTeamOwnship, geo::wrap360(info.hdg_cmd));
  stack_->schedule(e.sim_time() - step_s, line);
  if (out_) out_->notes.push_back(std::string(line) + " (steering to the waypoint)");
}

Result<serve::Teammate::Output> ScopeTeammate::tick(command::Stack& stack) {
  Output out;
  if (stack.sim().index_of(kTeamOwnship) < 0) {
    if (!ended_) out.notes.push_back(std::string(kTeamOwnship) + " is gone; the teammate stops");
    ended_ = true;
    return out;
  }
  if (env_.done()) {
    if (!ended_)
      out.notes.push_back(env_.stats().reached ? "the agent's episode is over: waypoint reached"
                                               : "the agent's episode is over: step limit");
    ended_ = true;
    return out;
  }
  const double t = stack.sim().simt();
  const double step_s = env_.config().dt * env_.config().substeps;
  if (!decided_ && t + kEps >= env_.sim_time()) {
    script::Advisory advice = agent_advisory(*policy_, env_, stack.sim(), rng_);
    advice.traffic = traffic_info(stack.sim());
    const std::string key = advice.turn + " " + std::to_string(advice.heading) + " " +
                            (advice.traffic ? advice.traffic->id : std::string());
    if (key != offered_) {
      auto english = phraser_.phrase(advice);
      if (!english) return english.status();
      out.advisories.push_back(*english);
      offered_ = key;
    }
    decided_ = true;
  } else if (decided_ && t + kEps >= env_.sim_time() + step_s) {
    stack_ = &stack;
    out_ = &out;
    env_.step(env_action(env_, stack.sim()));
    stack_ = nullptr;
    out_ = nullptr;
    decided_ = false;
  }
  return out;
}

}  // namespace squawk::app
