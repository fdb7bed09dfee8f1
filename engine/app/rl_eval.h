// The evaluation half of `squawk eval` shared by every policy kind (MLP,
// baselines, GPT-2): the flags, the run, the printed Table 3 columns.
#pragma once

#include <string>

#include "app/cli.h"
#include "env/vec_env.h"
#include "rl/policy.h"
#include "script/scenario.h"

namespace squawk::app {

struct EvalRequest {
  long long episodes = 1000;  // [-]
  long long seed = 0;
  int envs = 64;               // [-] environments stepped together
  bool greedy = false;         // the mode instead of a sample
  bool json = false;           // one JSON object instead of the table
  std::string record;          // JSON-lines recording of every episode, "" = none
};

// --episodes and --seed (defaults: the scenario's evaluation settings),
// --envs (64), --greedy, --json, --record. Errors name the flag.
Result<EvalRequest> eval_request(const Args& args, const script::Scenario& sc);

// Runs the scenario's evaluation episodes with `policy` on `envs` and prints
// success rate, mean episode reward and its standard deviation (or JSON with
// success_rate, mean_reward, std_reward, episodes). `label` names the policy.
int run_eval(rl::Policy& policy, env::VecEnv& envs, const script::Scenario& sc,
             const EvalRequest& req, const std::string& label);

}  // namespace squawk::app
