// The evaluation half of `squawk eval` shared by every policy kind (MLP,
// baselines, GPT-2): the flags, the run, the printed Table 3 columns.
#pragma once

#include <string>

#include "app/cli.h"
#include "env/vec_env.h"
#include "rl/policy.h"
#include "script/policy_factory.h"
#include "script/scenario.h"

namespace squawk::app {

struct EvalRequest {
  long long episodes = 1000;  // [-]
  long long seed = 0;
  int envs = 64;               // [-] environments stepped together
  bool greedy = false;         // the mode instead of a sample
  bool json = false;           // one JSON object instead of the table
  std::string record;          // JSON-lines recording of every episode, "" = none
  long long show_prompt = 0;   // [-] gpt2: print the prompts of the first N decisions
};

// --episodes and --seed (defaults: the scenario's evaluation settings),
// --envs (64), --greedy, --json, --record, --show-prompt. Errors name the flag.
Result<EvalRequest> eval_request(const Args& args, const script::Scenario& sc);

// script::PolicyOptions from --checkpoint, --seed and the GPT-2 policy flags
// (--model builds a fresh head on that base instead of a checkpoint).
Result<script::PolicyOptions> policy_options(const Args& args, long long seed);

// Empty when `made` was trained on `sc`'s rules and observation size (or its
// training scenario is unknown); otherwise a warning naming both rule sets.
std::string trained_elsewhere(const script::MadePolicy& made, const script::Scenario& sc,
                              const script::VmOptions& vm);

// One line on what success means under the scenario's rules, as the rule
// set's source defines it.
std::string success_definition(const script::Scenario& sc);

// Runs the scenario's evaluation episodes with `made.policy` on `envs` and
// prints success rate, mean episode reward and its standard deviation, the
// action histogram and the prompt file (or JSON with success_rate,
// mean_reward, std_reward, episodes, reached_rate, decisions, actions,
// most_frequent_share).
int run_eval(script::MadePolicy& made, env::VecEnv& envs, const script::Scenario& sc, const EvalRequest& req,
             const script::VmOptions& vm);

}  // namespace squawk::app
