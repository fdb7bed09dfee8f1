#include "rl/evaluator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "dist/comm.h"
#include "rl/episode_streams.h"
#include "rl/play.h"

namespace squawk::rl {

int action_bin(double value) {
  int best = 0;
  for (int k = 1; k < static_cast<int>(kActionBins.size()); ++k)
    if (std::abs(value - kActionBins[static_cast<size_t>(k)]) <
        std::abs(value - kActionBins[static_cast<size_t>(best)]))
      best = k;
  return best;
}

long long EvalResult::decisions() const {
  long long n = 0;
  for (long long c : action_counts) n += c;
  return n;
}

double EvalResult::most_frequent_share() const {
  const long long n = decisions();
  if (n == 0) return 0.0;
  return static_cast<double>(*std::max_element(action_counts.begin(), action_counts.end())) /
         static_cast<double>(n);
}

namespace {

// Every rank's episodes (the fields the figures read) in episode order, and
// the action counts summed over the ranks. Each episode's values come from
// the one rank that played it, the others add zeros: the sums are exact.
std::vector<env::EpisodeStats> gather(const std::vector<env::EpisodeStats>& mine, long long episodes,
                                      std::array<long long, kActionBins.size()>& counts) {
  constexpr size_t kFields = 6;
  const auto n = static_cast<size_t>(episodes);
  std::vector<double> table(n * kFields + counts.size(), 0.0);
  for (const env::EpisodeStats& e : mine) {
    double* row = &table[static_cast<size_t>(e.index) * kFields];
    row[0] = e.success;
    row[1] = e.reached;
    row[2] = e.decisions;
    row[3] = e.steps;
    row[4] = e.total_reward;
    row[5] = e.min_separation;
  }
  for (size_t k = 0; k < counts.size(); ++k) table[n * kFields + k] = static_cast<double>(counts[k]);
  dist::sum(table);
  std::vector<env::EpisodeStats> all(n);
  for (size_t i = 0; i < n; ++i) {
    const double* row = &table[i * kFields];
    all[i].index = i;
    all[i].success = row[0] != 0.0;
    all[i].reached = row[1] != 0.0;
    all[i].decisions = static_cast<int>(row[2]);
    all[i].steps = static_cast<int>(row[3]);
    all[i].total_reward = row[4];
    all[i].min_separation = row[5];
  }
  for (size_t k = 0; k < counts.size(); ++k) counts[k] = static_cast<long long>(table[n * kFields + k]);
  return all;
}

}  // namespace

Result<EvalResult> evaluate(Policy& policy, env::BatchEnv& envs, const EvalOptions& opts,
                            const std::function<void(long long, long long)>& progress) {
  if (opts.episodes < 1)
    return Status::invalid("evaluation needs at least 1 episode, got " + std::to_string(opts.episodes));
  if (policy.obs_size() != envs.obs_size())
    return Status::invalid("policy '" + policy.name() + "' expects " + std::to_string(policy.obs_size()) +
                           " observation values, the environment gives " + std::to_string(envs.obs_size()));
  const auto t0 = std::chrono::steady_clock::now();
  const long long steps0 = envs.env_steps();
  EpisodeStreams streams(opts.seed ^ kEvalPolicySalt);
  const dist::Share part = dist::share(static_cast<uint64_t>(opts.episodes));
  EvalResult res;
  Driver driver{policy_choice(policy, envs, streams, opts.greedy), [&](const Turn& t) {
                  for (const ActionSample& a : t.actions)
                    ++res.action_counts[static_cast<size_t>(action_bin(a.value))];
                  if (progress)
                    progress(
                        std::min(opts.episodes,
                                 static_cast<long long>(envs.completed().size()) * dist::size()),
                        opts.episodes);
                  return true;
                }};
  SQUAWK_RETURN_IF_ERROR(play(envs, opts.seed, part.first, part.count, driver).status());
  std::vector<env::EpisodeStats> eps = gather(envs.completed(), opts.episodes, res.action_counts);
  res.episodes = static_cast<long long>(eps.size());
  double sum = 0.0;
  for (const auto& e : eps) {
    res.success_rate += e.success;
    res.reached_rate += e.reached;
    res.mean_decisions += e.decisions;
    res.mean_steps += e.steps;
    sum += e.total_reward;
  }
  const double n = static_cast<double>(eps.size());
  res.mean_reward = sum / n;
  double var = 0.0;
  for (const auto& e : eps) var += (e.total_reward - res.mean_reward) * (e.total_reward - res.mean_reward);
  res.std_reward = std::sqrt(var / n);
  res.success_rate /= n;
  res.reached_rate /= n;
  res.mean_decisions /= n;
  res.mean_steps /= n;
  std::vector<double> sep;
  for (const auto& e : eps) sep.push_back(e.min_separation);
  std::sort(sep.begin(), sep.end());
  if (!sep.empty()) {
    res.separation_median = sep[sep.size() / 2];
    res.separation_p5 = sep[sep.size() / 20];
  }
  double steps = static_cast<double>(envs.env_steps() - steps0);
  dist::sum(std::span<double>(&steps, 1));
  res.env_steps = static_cast<long long>(steps);
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  envs.completed().clear();
  return res;
}

}  // namespace squawk::rl
