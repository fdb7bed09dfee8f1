// The pair kernels of BlueSky's state-based conflict detection and MVP
// resolution, the one copy that sim/ (every pair), env/ (the ownship's pairs)
// and serve/ (the scope's CPA marks) use:
//   horizontal()     closest approach and zone entry/exit
//                    (traffic/asas/statebased.py; docs/bluesky_facts.md §3.2);
//   mvp_horizontal() MVP's horizontal velocity change
//                    (traffic/asas/mvp.py MVP(); docs/bluesky_facts.md §3.3).
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

struct Push {
  double e = 0.0;  // [m/s] east
  double n = 0.0;  // [m/s] north
};

// BlueSky's dv_mvp for one pair, which the ownship subtracts from its ground
// velocity: the intruder's displacement at CPA, (dx, dy) + (du, dv)·tcpa,
// pushed out to `rpz` over |tcpa| (floored at 1 ms, so a CPA now gives a
// large but finite push), with the erratum correction when the pair is
// outside the zone and the 10 m head-on guard (which turns the displacement
// perpendicular to the line of sight; the intrusion depth is taken before it,
// as mvp.py does). dist = |(dx, dy)| [m] as the caller measured it (> 0);
// tcpa [s]; rpz = zone radius times the resolution margin [m].
inline Push mvp_horizontal(double dx, double dy, double dist, double du, double dv, double tcpa,
                           double rpz) {
  const double atcpa = std::max(std::fabs(tcpa), 1e-3);
  double ce = dx + du * tcpa, cn = dy + dv * tcpa;
  double dabs = std::hypot(ce, cn);
  const double intrusion = rpz - dabs;
  if (dabs <= 10.0) {
    dabs = 10.0;
    ce = dy / dist * 10.0;
    cn = -dx / dist * 10.0;
  }
  double k;
  if (rpz < dist && dabs < dist) {
    const double erratum = std::cos(std::asin(rpz / dist) - std::asin(dabs / dist));
    k = (rpz / erratum - dabs) / (atcpa * dabs);
  } else {
    k = intrusion / (atcpa * dabs);
  }
  return {k * ce, k * cn};
}

}  // namespace squawk::cpa
