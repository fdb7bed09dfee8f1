#include "rl/baseline_policies.h"

#include <cstdio>
#include <limits>

namespace squawk::rl {

std::string ConstantPolicy::name() const {
  if (value_ == 0.0f) return "zero";
  char buf[32];
  std::snprintf(buf, sizeof buf, when_ == When::always ? "constant:%g" : "turn-hold:%g",
                static_cast<double>(value_));
  return buf;
}

void ConstantPolicy::act(std::span<const float> obs, int n, std::span<const int> /*slots*/, std::span<Rng> /*rngs*/,
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
                    std::span<Rng> /*rngs*/, bool /*greedy*/, std::span<ActionSample> out) {
  for (int r = 0; r < n; ++r) {
    const auto i = static_cast<size_t>(r);
    out[i] = {-1, static_cast<float>(envs_.env(slots[i]).mvp_action())};
  }
}

namespace {
// Base rule b of a lookahead branch: actions[b], or MVP for b = actions.size().
double base_action(const env::HorizontalCrEnv& e, const std::vector<double>& actions, size_t b) {
  return b < actions.size() ? actions[b] : e.mvp_action();
}

double branch_score(env::HorizontalCrEnv e, double first, const std::vector<double>& actions, size_t b) {
  e.set_observer(nullptr);  // a branch is no episode a recorder should see
  e.step(first);
  while (!e.done()) e.step(base_action(e, actions, b));
  const env::EpisodeStats& s = e.stats();
  return (s.success ? 0.0 : -1e6) + s.total_reward - s.intrusions;
}
}  // namespace

void LookaheadPolicy::act(std::span<const float> /*obs*/, int n, std::span<const int> slots,
                          std::span<Rng> /*rngs*/, bool /*greedy*/, std::span<ActionSample> out) {
  for (int r = 0; r < n; ++r) {
    const env::HorizontalCrEnv& e = envs_.env(slots[static_cast<size_t>(r)]);
    double best = -std::numeric_limits<double>::infinity();
    size_t pick = 0;
    for (size_t a = 0; a < actions_.size(); ++a)
      for (size_t b = 0; b <= actions_.size(); ++b) {
        const double v = branch_score(e, actions_[a], actions_, b);
        if (v > best) {
          best = v;
          pick = a;
        }
      }
    out[static_cast<size_t>(r)] = {static_cast<int>(pick), static_cast<float>(actions_[pick])};
  }
}

}  // namespace squawk::rl
