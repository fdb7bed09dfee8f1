// Per-step rewards of the horizontal conflict-resolution environment.
//
// gym rules: BlueSky-Gym HorizontalCREnv-v0 (docs/bluesky_facts.md §1.6), once per
//   env step:  reach (+1 the step the waypoint is reached)
//            + drift_per_rad * |drift| [rad]
//            + intrusion * (number of intruders inside the protected zone).
// paper rules: the paper's Eq. 1-4:
//   r = r_intrusion + r_drift + r_hdg                                   (Eq. 1)
//   r_intrusion = -1 + w_i |CPA / min dist|  if an intrusion is detected,
//                 clear_bonus otherwise                                 (Eq. 2)
//   r_drift = w_d (exp(0.8 delta) - 1), delta = |drift| / 45 deg, if |drift| <= 90 deg,
//             drift_beyond otherwise                                    (Eq. 3)
//   r_hdg   = w_h (exp(0.8 delta) - 1), delta = |dhdg| / 45 deg         (Eq. 4)
//   r_drift and r_hdg are zero while an intrusion is detected.
// Decisions squawk makes where the paper is silent (kept consistent with the
// environment, horizontal_cr.h):
//   "intrusion detected" = some intruder closer than the protected-zone radius
//     (5 NM, horizontal) at the end of the step; with intrusion_at_substeps,
//     also at any 5 s sub-step of the step (the intrusion success counts);
//   CPA = the predicted distance at closest approach [m] between the ownship
//     (current velocity) and the intruding intruder; with several intruders
//     inside the zone, the smallest such CPA (a sub-step intrusion with none
//     inside at the step end: the smallest over all intruders, at most the
//     radius); "min dist" = the zone radius, so cpa_ratio = CPA / radius lies
//     in [0, 1];
//   drift = ownship heading - bearing to the waypoint, in (-180, 180] deg;
//   dhdg = signed heading change over the step (heading after - before).
#pragma once

namespace squawk::env {

struct RewardWeights {
  // gym rules
  double reach = 1.0;            // [-] once, when the waypoint is reached
  double drift_per_rad = -0.1;   // [1/rad] times |drift|
  double intrusion = -1.0;       // [-] per intruder inside the zone
  // paper rules (Eq. 1-4)
  double w_i = 0.4;              // [-] Eq. 2 weight of |CPA / min dist|
  double w_d = -0.005;           // [-] Eq. 3 drift weight
  double w_h = -0.01;            // [-] Eq. 4 heading-change weight
  double clear_bonus = 0.02;     // [-] Eq. 2 reward of a step without intrusion
  double drift_limit = 90.0;     // [deg] Eq. 3 beyond this |drift| ...
  double drift_beyond = -0.5;    // [-] ... the drift term is this constant
  double exp_rate = 0.8;         // [-] Eq. 3-4 exponent factor
  double delta_norm = 45.0;      // [deg] Eq. 3-4 normaliser of delta
  bool intrusion_at_substeps = false;  // Eq. 2 detection: step end only (false) or any sub-step too
};

// What a reward function sees after one env step.
struct StepFacts {
  int step = 0;                      // [-] env steps taken in the episode (1 after the first)
  int intrusions = 0;                // [-] intruders inside the zone at the step end
  int substep_intrusions = 0;        // [-] sub-steps of this step with an intruder inside (paper rules)
  double cpa_ratio = 0.0;            // [-] smallest CPA / zone radius over those; 0 when none
  double drift = 0.0;                // [deg] heading - bearing to waypoint, (-180, 180]
  double heading_change = 0.0;       // [deg] signed, over the step
  double waypoint_distance = 0.0;    // [m]
  bool reached = false;              // waypoint reached at this step
};

double gym_reward(const RewardWeights& w, const StepFacts& f);
double paper_reward(const RewardWeights& w, const StepFacts& f);

}  // namespace squawk::env
