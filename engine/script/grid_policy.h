// A checkpoint of `squawk train --env` (app/cli_train_env.h) read for an
// environment file: a categorical MLP whose classes are the points of the
// file's action grid, or a Gaussian MLP over the continuous Box, one mean
// and log sigma per component (script/lua_batch_env.h).
#pragma once

#include <memory>
#include <span>
#include <string>

#include "core/status.h"
#include "rl/mlp_policy.h"
#include "script/lua_env.h"

namespace squawk::script {

struct GridPolicy {
  std::unique_ptr<rl::MlpPolicy> mlp;
  int levels = 0;  // [-] grid levels per action component (0: the Gaussian head)
};

// Loads the checkpoint at `path` for `spec` (per agent for a multi-agent
// file). Errors name the file and what does not fit: the observation size
// (with the environment the checkpoint was trained on), a Gaussian head over
// another number of action components, a categorical head that is not over a grid,
// or a grid that does not fit spec's action.
Result<GridPolicy> load_grid_policy(const std::string& path, const LuaEnvSpec& spec);

// The environment's action for the policy's `choice`: its grid point, or
// the Gaussian sample's components clipped to [-1, 1] and mapped onto the Box.
void policy_action(const LuaEnvSpec& spec, const GridPolicy& pol, const rl::ActionSample& choice,
                   std::span<double> out);

}  // namespace squawk::script
