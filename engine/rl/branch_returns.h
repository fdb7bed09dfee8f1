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
// Cost: n K continuations, each batched with all others at every decision.
#pragma once

#include <span>
#include <vector>

#include "core/status.h"
#include "env/horizontal_cr.h"
#include "rl/policy.h"

namespace squawk::rl {

Result<std::vector<double>> branch_returns(Policy& policy, std::span<const env::HorizontalCrEnv> snapshots,
                                           std::span<const double> action_values, double gamma);

}  // namespace squawk::rl
