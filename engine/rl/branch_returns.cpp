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
      branches.back().set_observer(nullptr);  // a branch is no episode a recorder should see
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
    policy.act(rows, static_cast<int>(live.size()), live, {&unused, 1}, true, acts);
    SQUAWK_RETURN_IF_ERROR(policy.error());
    for (size_t r = 0; r < live.size(); ++r) {
      const auto b = static_cast<size_t>(live[r]);
      q[b] += discount[b] * branches[b].step(acts[r].value);
      discount[b] *= gamma;
    }
  }
  return q;
}

void RolloutPolicy::act(std::span<const float> /*obs*/, int n, std::span<const int> slots, std::span<Rng> /*rngs*/,
                        bool /*greedy*/, std::span<ActionSample> out) {
  std::vector<env::HorizontalCrEnv> snaps;
  snaps.reserve(static_cast<size_t>(n));
  for (int r = 0; r < n; ++r) snaps.push_back(envs_.env(slots[static_cast<size_t>(r)]));
  const std::span<const double> values = base_->action_values();
  auto q = branch_returns(*base_, snaps, values, 1.0);
  if (!q && error_.is_ok()) error_ = q.status();
  const size_t k = values.size();
  for (size_t r = 0; r < static_cast<size_t>(n); ++r) {
    size_t best = 0;
    for (size_t j = 1; q && j < k; ++j)
      if ((*q)[r * k + j] > (*q)[r * k + best]) best = j;
    out[r] = {static_cast<int>(best), static_cast<float>(values[best])};
  }
}

}  // namespace squawk::rl
