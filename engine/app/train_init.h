// train_init: `squawk train --env ENV.lua --init CKPT` starts the learner from
// a checkpoint's policy (a clone, DIR/cloned.ckpt, or a trained policy) instead
// of a fresh network, its value baseline first fitted to that policy's returns.
#pragma once

#include <memory>
#include <string>

#include "core/status.h"
#include "env/batch_env.h"
#include "rl/imitation.h"
#include "rl/mlp_policy.h"
#include "rl/vpg.h"
#include "script/lua_batch_env.h"

namespace squawk::app {

struct InitPolicy {
  rl::MlpPolicySpec spec;
  std::unique_ptr<rl::MlpPolicy> policy;
};

// The policy of checkpoint `path` for environment `es` under the run's head
// (`wanted`: its Gaussian action size, or the grid's action values); error
// naming the file and what differs (observation size, head, grid).
Result<InitPolicy> init_policy(const std::string& path, const script::LuaEnvSpec& es,
                               const rl::MlpPolicySpec& wanted);

// Fits the trainer's value baseline (when it has one) to the discounted returns
// of `flights` (ic.epochs passes in batches of ic.batch, seed ic.seed); prints
// the fit, naming whose returns they are ("the teacher's"), unless `quiet`.
Status fit_value(rl::Trainer& trainer, const rl::TeacherFlights& flights,
                 const rl::ImitationConfig& ic, const char* whose, bool quiet);

// fit_value to the discounted returns of `policy`'s own greedy flights (ic.episodes episodes of
// ic.seed; ic.epochs passes in batches of ic.batch), as --imitate fits it to the rule's; prints the
// fit unless `quiet`.
Status fit_value_to_policy(rl::MlpPolicy& policy, env::BatchEnv& envs,
                           const rl::ImitationConfig& ic, rl::Trainer& trainer, bool quiet);

}  // namespace squawk::app
