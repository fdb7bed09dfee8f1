#include "rl/obs_norm.h"

#include <algorithm>
#include <cmath>

#include "rl/episode_streams.h"
#include "rl/play.h"

namespace squawk::rl {

Result<ObservationStats> observation_stats(Policy& policy, env::BatchEnv& envs, uint64_t seed,
                                           long long episodes) {
  if (episodes < 1)
    return Status::invalid("observation statistics need at least 1 episode, got " +
                           std::to_string(episodes));
  const auto d = static_cast<size_t>(envs.obs_size());
  std::vector<double> sum(d, 0.0), sq(d, 0.0);
  long long rows = 0;
  EpisodeStreams streams(seed ^ kObsNormSalt);
  auto act = policy_choice(policy, envs, streams, false);
  Driver driver{[&](Turn& t) {
                  for (size_t i = 0; i < t.obs.size(); ++i) {
                    const double x = t.obs[i];
                    sum[i % d] += x;
                    sq[i % d] += x * x;
                  }
                  rows += static_cast<long long>(t.slots.size());
                  return act(t);
                },
                {}};
  SQUAWK_RETURN_IF_ERROR(play(envs, seed, 0, static_cast<uint64_t>(episodes), driver).status());
  SQUAWK_RETURN_IF_ERROR(policy.error());
  envs.completed().clear();
  ObservationStats s{std::vector<double>(d, 0.0), std::vector<double>(d, 1.0)};
  if (rows == 0) return s;
  for (size_t j = 0; j < d; ++j) {
    s.mean[j] = sum[j] / static_cast<double>(rows);
    const double var = sq[j] / static_cast<double>(rows) - s.mean[j] * s.mean[j];
    const double sd = std::sqrt(std::max(var, 0.0));
    s.std[j] = sd < 1e-6 ? 1.0 : sd;
  }
  return s;
}

}  // namespace squawk::rl
