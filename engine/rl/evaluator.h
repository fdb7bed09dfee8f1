// Evaluation: runs a fixed, numbered set of episodes (0..episodes-1 of the
// given seed, see env/vec_env.h) with a policy and reports Table 3's columns.
//
// success_rate: fraction of episodes whose EpisodeStats::success is set.
// mean_reward / std_reward: mean and population standard deviation (ddof 0)
// of the episode returns (EpisodeStats::total_reward).
// action_counts: how many decisions took each of kActionBins, every action
// value binned to the nearest bin (a continuous MVP action lands in one of the
// five classes); most_frequent_share() is the largest count over the total,
// the figure that shows a policy playing one action whatever the state.
// Episode k's policy samples come from Rng(episode_seed(seed ^
// kEvalPolicySalt, k)) (episode_streams.h), so one seed fixes the whole
// evaluation on one build, whatever the number of slots.
// In a data-parallel job (dist/comm.h) each rank plays its share of the
// episodes (dist::share) and every rank returns the figures of all of them,
// the same as one process gives.
#pragma once

#include <cstdint>
#include <array>
#include <functional>

#include "env/batch_env.h"
#include "rl/policy.h"

namespace squawk::rl {

inline constexpr uint64_t kEvalPolicySalt = 0xE7A1D5EEDull;
// [-] the paper's five actions, in units of the heading step.
inline constexpr std::array<double, 5> kActionBins = {-1.0, -0.5, 0.0, 0.5, 1.0};

// Index into kActionBins of the bin nearest to `value` (ties go to the lower bin).
int action_bin(double value);

struct EvalOptions {
  long long episodes = 1000;  // [-]
  uint64_t seed = 0;
  bool greedy = false;        // take the mode instead of sampling
};

struct EvalResult {
  long long episodes = 0;
  double success_rate = 0.0;    // [-] 0..1
  double mean_reward = 0.0;     // [-]
  double std_reward = 0.0;      // [-]
  double mean_decisions = 0.0;  // [-] agent steps per episode
  double mean_steps = 0.0;      // [-] env steps per episode
  double reached_rate = 0.0;    // [-] 0..1
  // Per-episode closest separation (EpisodeStats::min_separation) over the
  // episodes: median and 5th percentile (nearest rank) [m].
  double separation_median = 0.0;
  double separation_p5 = 0.0;
  long long env_steps = 0;      // [-]
  double wall_s = 0.0;          // [s]
  std::array<long long, kActionBins.size()> action_counts{};  // [-] decisions per bin

  long long decisions() const;
  double most_frequent_share() const;  // [-] 0..1, 0 without decisions
};

// progress(done, total) is called after every batched step when given (in a
// job of several ranks, done is this rank's count times the number of ranks).
Result<EvalResult> evaluate(Policy& policy, env::BatchEnv& envs, const EvalOptions& opts,
                            const std::function<void(long long, long long)>& progress = {});

}  // namespace squawk::rl
