// One ownship/intruder pair in the ownship's local east-north plane: its
// closest approach with BlueSky's conflict test, and MVP's velocity change
// for the ownship (docs/bluesky_facts.md §3.2-3.3), both computed by the
// pair kernels of core/cpa.h that sim/ uses too.
//
// Inputs: p = intruder position relative to the ownship [m] (east, north);
//         w = intruder velocity minus ownship velocity [m/s] (east, north).
#pragma once

namespace squawk::env {

struct Vec2 {
  double x = 0.0;  // [m] or [m/s] east
  double y = 0.0;  // [m] or [m/s] north
};

struct Cpa {
  double tcpa = 0.0;   // [s] time to closest approach (negative: past)
  double dcpa = 0.0;   // [m] distance at closest approach
  double t_in = 1e8;   // [s] time the pair enters the zone (1e8 when it never does)
  double t_out = -1e8; // [s] time it leaves it (-1e8 when it never enters)
  // BlueSky's conflict test: enters within the look-ahead and not yet out.
  bool conflict(double lookahead) const { return t_in <= t_out && t_out > 0.0 && t_in < lookahead; }
};

// radius: protected-zone radius [m].
Cpa closest_approach(Vec2 p, Vec2 w, double radius);

// The ownship's velocity change [m/s] that MVP asks for this pair, i.e. the
// negative of BlueSky's dv_mvp (which it subtracts from the ownship).
// radius: zone radius times the resolution margin (resofach) [m].
Vec2 mvp_velocity_change(Vec2 p, Vec2 w, double tcpa, double radius);

}  // namespace squawk::env
