// The pieces of the paper's team loop (agent -> advisory English ->
// translator -> simulator) shared by `squawk demo` and the scope's AI
// teammate (`squawk serve --agent`).
//
// The agent decides on the HorizontalCR environment's observation; the
// simulator (a command::Stack) flies the same episode: ownship kTeamOwnship
// and intruders "0".."n-1", created by team_setup_commands(). The environment
// is kept in step by flying, each step, the heading the simulator was told
// (env_action()).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "command/stack.h"
#include "core/rng.h"
#include "core/status.h"
#include "env/horizontal_cr.h"
#include "rl/policy.h"
#include "script/advisory.h"
#include "script/policy_factory.h"
#include "script/scenario.h"
#include "script/vm.h"

namespace squawk::app {

inline constexpr const char* kTeamOwnship = "KL001";

// The agent for `sc`: "mlp" (trained MLP) or "gpt2" (fine-tuned GPT-2 prompt
// policy) from `checkpoint` ("" = the shipped one), built by
// script::make_policy. Errors name the kind or file and say how to train one.
Result<script::MadePolicy> load_team_policy(const std::string& kind, const script::Scenario& sc,
                                            const std::string& checkpoint, const script::VmOptions& vm);

// The first episode of rng's sequence in which the agent has to act (the
// environment is left reset to it). Error after 1000 draws without one.
Result<env::EpisodeSetup> first_agent_episode(env::HorizontalCrEnv& e, Rng& rng);

// The simulator's side of the episode: speed cap as the environment's
// limits, then DT, ZONER, DTLOOK, ASAS ON and the CRE lines (run them in order).
Status apply_env_limits(command::Stack& stack, const env::HorizontalCrConfig& cfg);
std::vector<std::string> team_setup_commands(const env::HorizontalCrConfig& cfg, const env::EpisodeSetup& setup);

// The agent's greedy decision on the environment's observation, as the
// advisory the phrase template says (traffic: the ownship's most urgent
// conflict in the simulator).
script::Advisory agent_advisory(rl::Policy& policy, const env::HorizontalCrEnv& e, const sim::Simulation& sim,
                                Rng& rng);

// The environment action that flies the heading the simulator's ownship has
// selected [-] (units of heading_per_action).
double env_action(const env::HorizontalCrEnv& e, const sim::Simulation& sim);

}  // namespace squawk::app
