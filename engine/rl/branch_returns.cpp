#include "rl/branch_returns.h"

namespace squawk::rl {

Result<std::vector<double>> branch_returns(Policy& policy, std::span<const env::HorizontalCrEnv> snapshots,
                                           std::span<const double> action_values, double gamma) {
  const size_t k = action_values.size();
  const size_t n = snapshots.size() * k;
  std::vector<env::HorizontalCrEnv> branches;
  branches.reserve(n);
  std::vector<double> q(n, 0.0), discount(n, gamma);
  for (const env::HorizontalCrEnv& s : snapshots)
    for (size_t j = 0; j < k; ++j) {
      branches.push_back(s);
      q[branches.size() - 1] = branches.back().step(action_values[j]);
    }
  const int obs = branches.empty() ? 0 : branches[0].observation_size();
  std::vector<int> live;
  std::vector<float> rows;
  std::vector<ActionSample> acts;
  Rng unused(0);  // greedy decisions draw nothing
  for (;;) {
    live.clear();
    for (size_t b = 0; b < n; ++b)
      if (!branches[b].done()) live.push_back(static_cast<int>(b));
    if (live.empty()) break;
    rows.resize(live.size() * static_cast<size_t>(obs));
    for (size_t r = 0; r < live.size(); ++r)
      branches[static_cast<size_t>(live[r])].observe_flat(
          std::span<float>(rows).subspan(r * static_cast<size_t>(obs), static_cast<size_t>(obs)));
    acts.resize(live.size());
    policy.act(rows, static_cast<int>(live.size()), live, unused, true, acts);
    SQUAWK_RETURN_IF_ERROR(policy.error());
    for (size_t r = 0; r < live.size(); ++r) {
      const auto b = static_cast<size_t>(live[r]);
      q[b] += discount[b] * branches[b].step(acts[r].value);
      discount[b] *= gamma;
    }
  }
  return q;
}

}  // namespace squawk::rl
