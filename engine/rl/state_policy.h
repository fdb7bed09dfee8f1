// StatePolicy: the base of policies that decide from the true state of the
// VecEnv slot of each row (act()'s `slots`), not from the observation rows:
// MVP, the lookahead planner, one rollout step (baseline_policies.h,
// branch_returns.h). They hold the VecEnv they read; it must outlive them.
// obs_size() is the VecEnv's unless a derived policy reads rows of its own.
#pragma once

#include "env/vec_env.h"
#include "rl/policy.h"

namespace squawk::rl {

class StatePolicy : public Policy {
 public:
  explicit StatePolicy(const env::VecEnv& envs) : envs_(envs) {}
  int obs_size() const override { return envs_.obs_size(); }

 protected:
  const env::VecEnv& envs_;
};

}  // namespace squawk::rl
