// The horizontal closest-approach kernel of BlueSky's state-based conflict
// detection (traffic/asas/statebased.py; docs/bluesky_facts.md §3.2),
// the one copy sim/conflict (all pairs) and env/cpa (the ownship's pairs) use.
//
// Inputs in a local east-north plane: (dx, dy) = intruder position relative
// to the ownship [m], (du, dv) = intruder velocity minus ownship velocity
// [m/s], r = protected-zone radius [m].
#pragma once

#include <algorithm>
#include <cmath>

namespace squawk::cpa {

struct Horizontal {
  double dv2 = 0.0;     // [m^2/s^2] |relative velocity|^2, floored at 1e-6 as BlueSky
  double tcpa = 0.0;    // [s] time to closest approach (negative: past)
  double dcpa2 = 0.0;   // [m^2] squared distance at closest approach
  bool enters = false;  // dcpa2 < r^2: the straight-line tracks meet inside the zone
  double t_in = 0.0;    // [s] entry time when `enters` (else 0)
  double t_out = 0.0;   // [s] exit time when `enters` (else 0)
};

inline Horizontal horizontal(double dx, double dy, double du, double dv, double r) {
  Horizontal h;
  h.dv2 = std::max(du * du + dv * dv, 1e-6);
  h.tcpa = -(du * dx + dv * dy) / h.dv2;
  h.dcpa2 = std::fabs(dx * dx + dy * dy - h.tcpa * h.tcpa * h.dv2);
  const double r2 = r * r;
  h.enters = h.dcpa2 < r2;
  if (h.enters) {
    const double dt = std::sqrt(std::max(0.0, r2 - h.dcpa2)) / std::sqrt(h.dv2);
    h.t_in = h.tcpa - dt;
    h.t_out = h.tcpa + dt;
  }
  return h;
}

}  // namespace squawk::cpa
