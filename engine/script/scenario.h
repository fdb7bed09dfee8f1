// Scenario files for the conflict-resolution environment: a Lua file that
// returns a table of parameters (scenarios/horizontal_cr.lua documents every
// key). Loading runs the file in a sandboxed Vm and fills C++ configs; a
// `reward` given as a Lua function replaces the built-in reward, wrapped as a
// std::function that keeps the Vm alive.
//
// Table layout (units in the key names; unknown keys are errors):
//   rules   = "paper" | "gym"
//   env     = { intruders, own_speed_ms, speed_cap_ms, accel_ms2, bank_deg,
//               dt_s, substeps, start_lat, start_lon, dpsi_deg = {lo, hi},
//               cpa_nm = {lo, hi}, tlos_s = {lo, hi}, waypoint_km = {lo, hi},
//               zone_radius_nm, reach_radius_km, heading_step_deg, max_steps,
//               lookahead_s, mvp_margin }
//   eval    = same keys as env (overrides for evaluation) plus episodes, seed
//   reward  = { reach, drift_per_rad, intrusion, w_i, w_d, w_h, clear_bonus,
//               drift_limit_deg, drift_beyond, exp_rate, delta_norm_deg,
//               intrusion_at = "step_end"|"substep" }
//             or function(f) -> number, f = { step, intrusions,
//               substep_intrusions, cpa_ratio, drift_deg, heading_change_deg,
//               waypoint_distance_m, reached }
//   A scenario may require("name") a scenario beside it and change it.
//   policy  = { hidden = {..}, head = "categorical"|"gaussian", actions = {..},
//               init_log_std }
//   train   = { estimator, episodes, episodes_per_update, num_envs, lr, lr_final, gamma,
//               entropy_coef, entropy_final, lambda, epochs, minibatches, clip,
//               grad_clip, branch_fraction, eval_every, eval_episodes, seed }
// An environment file in the gym contract that declares a HorizontalCR
// environment (envs/horizontal_cr.lua: a table with `declaration` = {rules,
// env, reward}) loads as a scenario of that declaration for training and
// evaluation alike, with the default policy and training settings.
// A Lua reward function that raises an error makes that step's reward 0 and
// records the first error in reward_error(); callers check it.
#pragma once

#include <memory>
#include <string>

#include "core/status.h"
#include "env/horizontal_cr.h"
#include "rl/mlp_policy.h"
#include "rl/vpg.h"
#include "script/vm.h"

namespace squawk::script {

struct Scenario {
  std::string path;
  env::HorizontalCrConfig train_env;  // env table (training and the default)
  env::HorizontalCrConfig eval_env;   // env table + eval overrides
  long long eval_episodes = 1000;     // [-]
  uint64_t eval_seed = 0;
  rl::MlpPolicySpec policy;
  rl::TrainConfig train;
  bool lua_reward = false;            // reward replaced by a Lua function
  std::shared_ptr<Vm> vm;             // alive while a Lua reward may be called
  std::shared_ptr<Status> reward_status;  // first Lua reward error, ok otherwise

  Status reward_error() const { return reward_status ? *reward_status : Status::ok(); }
};

Result<Scenario> load_scenario(const std::string& path, const VmOptions& options);

// Reads the fields rules, env and reward of the table at idx (the layout
// above) over the values already in c; throws ArgError naming the culprit.
// A reward function is wrapped to run in `vm` (kept alive by the wrapper),
// its first error going to *reward_status; returns true in that case.
bool read_environment_fields(lua_State* L, int idx, env::HorizontalCrConfig& c,
                             std::shared_ptr<Vm> vm, std::shared_ptr<Status> reward_status);

}  // namespace squawk::script
