// Observation normalisation for the MLP policy (MlpPolicySpec::obs_mean /
// obs_std): per-feature statistics of the observations a policy meets.
//
// observation_stats() plays episodes 0..episodes-1 of `seed` on `envs` with
// `policy` sampling (its episode streams seeded by seed ^ kObsNormSalt,
// episode_streams.h) and returns, per observation feature, the mean and the
// population standard deviation over every decision's observation (rows of
// every waiting slot at every turn). A feature whose deviation is below 1e-6
// (a constant) gets 1, so normalising only shifts it. Errors: episodes < 1,
// the environment's or the policy's failure.
#pragma once

#include <cstdint>
#include <vector>

#include "core/status.h"
#include "env/batch_env.h"
#include "rl/policy.h"

namespace squawk::rl {

inline constexpr uint64_t kObsNormSalt = 0x0B5A0B5Aull;

struct ObservationStats {
  std::vector<double> mean, std;  // [obs_size] each
};

Result<ObservationStats> observation_stats(Policy& policy, env::BatchEnv& envs, uint64_t seed,
                                           long long episodes);

}  // namespace squawk::rl
