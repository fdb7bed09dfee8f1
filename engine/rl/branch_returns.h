// Branch returns: Q estimates for every action of a state, by simulation.
//
// For each snapshot s_i (an environment copied just before an agent step) and
// each action value a_j of a discrete policy, a copy of s_i takes a_j and then
// follows `policy`'s greedy action at every later decision until its episode
// ends. The discounted sum of the rewards env::HorizontalCrEnv::step returns,
//   Q[i, j] = sum_{k>=0} gamma^k r_k   (k counts agent decisions, r_0 the reward of a_j),
// is the same reward-to-go the learner uses for sampled trajectories. The
// environment is deterministic, so Q[i, j] has no sampling noise: it is the
// value of a_j followed by the current greedy policy (a "vine" estimate).
// Shapes: snapshots [n], action_values [K], result [n, K] row-major.
// The branches run without the snapshots' observers (recorders see only the
// episodes really flown).
// Cost: n K continuations, each batched with all others at every decision.
//
// RolloutPolicy: one step of policy improvement over a discrete `base` policy
// (Bertsekas' rollout algorithm): at each decision, Q of every action of the
// base by branch_returns with gamma = 1 (the episode's return from here, the
// quantity evaluation reports), and the best action; ties go to the lowest
// class. It reads the true state of the VecEnv slot of each row and the
// future, like LookaheadPolicy (baseline_policies.h): a reference for what
// the base policy's own continuations allow, not a policy of the observation.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/status.h"
#include "env/horizontal_cr.h"
#include "rl/policy.h"
#include "rl/state_policy.h"

namespace squawk::rl {

Result<std::vector<double>> branch_returns(Policy& policy, std::span<const env::HorizontalCrEnv> snapshots,
                                           std::span<const double> action_values, double gamma);

class RolloutPolicy : public StatePolicy {
 public:
  // `base` must have a discrete head (non-empty action_values()).
  RolloutPolicy(const env::VecEnv& envs, std::unique_ptr<Policy> base)
      : StatePolicy(envs), base_(std::move(base)) {}
  std::string name() const override { return "rollout:" + base_->name(); }
  // The base's size, so check_obs_size() refuses a base built for other rows.
  int obs_size() const override { return base_->obs_size(); }
  void act(std::span<const float> obs, int n, std::span<const int> slots, std::span<Rng> rngs, bool greedy,
           std::span<ActionSample> out) override;
  Status error() const override { return error_.is_ok() ? base_->error() : error_; }

 private:
  std::unique_ptr<Policy> base_;
  Status error_;
};

}  // namespace squawk::rl
