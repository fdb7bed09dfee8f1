#include "rl/baseline_policies.h"

namespace squawk::rl {

void ZeroPolicy::act(std::span<const float> /*obs*/, int n, std::span<const int> /*slots*/,
                     Rng& /*rng*/, bool /*greedy*/, std::span<ActionSample> out) {
  for (int r = 0; r < n; ++r) out[static_cast<size_t>(r)] = {-1, 0.0f};
}

void MvpPolicy::act(std::span<const float> /*obs*/, int n, std::span<const int> slots,
                    Rng& /*rng*/, bool /*greedy*/, std::span<ActionSample> out) {
  for (int r = 0; r < n; ++r) {
    const auto i = static_cast<size_t>(r);
    out[i] = {-1, static_cast<float>(envs_.env(slots[i]).mvp_action())};
  }
}

}  // namespace squawk::rl
