// ScopeTeammate: the deconfliction agent as the scope's AI teammate
// (`squawk serve --agent`), the demo's loop (team_loop.h) on a live clock.
//
// start() sets the simulator up with the episode of the seed (the demo's
// episode) and keeps the environment beside it. tick() runs after every
// advance of the live clock:
//  - when the simulator reaches the environment's time and the agent must
//    decide, the decision is phrased (prompts/advisory.lua) and returned as
//    an advisory; the controller accepts (the English goes through the
//    translator and runs) or rejects it;
//  - one decision step later (heading_per_action step, dt x substeps of sim
//    time) the environment flies the heading the simulator's ownship has
//    selected by then, whoever selected it, and runs on to the next conflict;
//    its automatic steering toward the waypoint reaches the simulator as HDG
//    commands queued at their times (logged as autopilot).
// The environment applies each heading from the start of its step, so a late
// decision leaves it slightly ahead of the simulator; it is the agent's view.
//
// What the controller sees is made believable without changing the
// episode: the intruders "0".."n-1" fly as airline callsigns and types
// (kIntruders) and every aircraft at FL kLevel with the CAS that gives the
// environment's true airspeed there, so the tracks are the environment's.
// An advisory is offered only when it differs from the last one offered
// (turn, heading or traffic named); the same advice stays pending instead of
// expiring and coming back. Traffic information names the most urgent
// conflict within kTrafficInfoNm, or none.
#pragma once

#include <memory>
#include <string>
#include <utility>

#include "app/team_loop.h"
#include "env/horizontal_cr.h"
#include "script/advisory.h"
#include "serve/live_sim.h"

namespace squawk::app {

struct TeammateOptions {
  std::string scenario;    // Lua scenario with the environment ("" = scenarios/horizontal_cr.lua)
  std::string policy = "mlp";
  std::string checkpoint;  // "" = the shipped one
  std::string advisory;    // phrase template ("" = prompts/advisory.lua)
};

class ScopeTeammate : public serve::Teammate, private env::EpisodeObserver {
 public:
  static Result<std::unique_ptr<ScopeTeammate>> make(const TeammateOptions& opts, const script::VmOptions& vm);
  // Runs the episode's set-up commands on `stack`. Error names the command.
  Status start(command::Stack& stack);
  Result<Output> tick(command::Stack& stack) override;

 private:
  ScopeTeammate(env::HorizontalCrEnv e, std::unique_ptr<rl::Policy> policy, script::AdvisoryPhraser phraser,
                uint64_t seed)
      : env_(std::move(e)), policy_(std::move(policy)), phraser_(std::move(phraser)), rng_(seed) {}
  void on_reset(const env::HorizontalCrEnv&) override {}
  void on_step(const env::HorizontalCrEnv& e, const env::StepInfo& info) override;
  void on_end(const env::HorizontalCrEnv&, const env::EpisodeStats&) override {}

  env::HorizontalCrEnv env_;
  std::unique_ptr<rl::Policy> policy_;
  script::AdvisoryPhraser phraser_;
  Rng rng_;
  command::Stack* stack_ = nullptr;  // during tick(): where automatic steering is queued
  Output* out_ = nullptr;            // during tick(): where notes go
  bool decided_ = false;             // an advisory for the environment's present step was given
  bool ended_ = false;               // the end of the episode was reported
  std::string offered_;              // turn, heading and traffic of the last advisory offered
};

inline constexpr double kLevel = 240;           // [FL] of every aircraft of the episode
inline constexpr double kTrafficInfoNm = 15.0;  // [NM] farthest traffic named in an advisory
// The intruders' callsigns and types, in the order of the environment's intruders (cycled).
inline constexpr std::pair<const char*, const char*> kIntruders[] = {
    {"DLH4AX", "A320"}, {"BAW8CK", "A319"}, {"EZY67K", "A320"}, {"AFR1122", "A321"}, {"RYR55T", "B738"},
    {"SAS902", "A20N"}, {"TRA5521", "B738"}, {"EWG7KL", "A319"}, {"AUA321", "A320"}, {"IBE3154", "A321"}};
// Rewrites a team_setup_commands() CRE line "CRE id type lat lon hdg alt tas_kt"
// (altitude 0, so CAS = TAS) for the scope: intruder `index` (-1: the
// ownship, which keeps its callsign) becomes kIntruders' callsign and type,
// at FL kLevel with the CAS of the same TAS. Other lines come back as given.
std::string believable_cre(const std::string& line, int index);

}  // namespace squawk::app
