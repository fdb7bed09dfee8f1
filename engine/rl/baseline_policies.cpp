#include "rl/baseline_policies.h"

#include <cstdio>

namespace squawk::rl {

std::string ConstantPolicy::name() const {
  if (value_ == 0.0f) return "zero";
  char buf[32];
  std::snprintf(buf, sizeof buf, when_ == When::always ? "constant:%g" : "turn-hold:%g",
                static_cast<double>(value_));
  return buf;
}

void ConstantPolicy::act(std::span<const float> obs, int n, std::span<const int> /*slots*/, Rng& /*rng*/,
                         bool /*greedy*/, std::span<ActionSample> out) {
  // Flat layout (env/observation.h): cos_difference_pos[k] then cos_drift.
  const auto d = static_cast<size_t>(obs_size_);
  const auto cos_drift = static_cast<size_t>((obs_size_ - 3) / 5);
  const float on_track = 0.99905f;  // cos(2.5 deg)
  for (int r = 0; r < n; ++r) {
    const auto i = static_cast<size_t>(r);
    const bool turn = when_ == When::always || obs[i * d + cos_drift] > on_track;
    out[i] = {-1, turn ? value_ : 0.0f};
  }
}

void MvpPolicy::act(std::span<const float> /*obs*/, int n, std::span<const int> slots,
                    Rng& /*rng*/, bool /*greedy*/, std::span<ActionSample> out) {
  for (int r = 0; r < n; ++r) {
    const auto i = static_cast<size_t>(r);
    out[i] = {-1, static_cast<float>(envs_.env(slots[i]).mvp_action())};
  }
}

}  // namespace squawk::rl
