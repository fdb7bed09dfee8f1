#include "env/reward.h"

#include <cmath>

#include "core/units.h"

namespace squawk::env {

double gym_reward(const RewardWeights& w, const StepFacts& f) {
  double r = f.reached ? w.reach : 0.0;
  r += w.drift_per_rad * std::fabs(units::deg_to_rad(f.drift));
  r += w.intrusion * f.intrusions;
  return r;
}

double paper_reward(const RewardWeights& w, const StepFacts& f) {
  if (f.intrusions > 0 || (w.intrusion_at_substeps && f.substep_intrusions > 0))
    return -1.0 + w.w_i * std::fabs(f.cpa_ratio);
  const double drift = std::fabs(f.drift);
  const double r_drift = drift <= w.drift_limit
                             ? w.w_d * (std::exp(w.exp_rate * drift / w.delta_norm) - 1.0)
                             : w.drift_beyond;
  const double r_hdg =
      w.w_h * (std::exp(w.exp_rate * std::fabs(f.heading_change) / w.delta_norm) - 1.0);
  return w.clear_bonus + r_drift + r_hdg;
}

}  // namespace squawk::env
