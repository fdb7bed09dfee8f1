// The 28-value observation of BlueSky-Gym's HorizontalCREnv-v0
// (docs/bluesky_facts.md §1.4), shared by both rule sets.
//
// Structured form: the eight named fields, each per intruder i (or one value
// for the waypoint). Distances are scaled by 150 km and speeds by 150 m/s:
//   intruder_distance[i]  = dist(own, int_i) [km] / 150
//   cos/sin_difference_pos[i] = cos/sin(hdg_own - qdr(own -> int_i))
//   x_difference_speed[i] = -cos(hdg_own - hdg_i) gs_i / 150
//   y_difference_speed[i] = (gs_own - sin(hdg_own - hdg_i) gs_i) / 150
//   waypoint_distance     = dist(own, wpt) [km] / 150
//   cos/sin_drift         = cos/sin(hdg_own - qdr(own -> wpt))
// Flat form (what an MLP sees): the keys in alphabetical order, as Gymnasium's
// Dict flattens them: cos_difference_pos[5], cos_drift, intruder_distance[5],
// sin_difference_pos[5], sin_drift, waypoint_distance, x_difference_speed[5],
// y_difference_speed[5]  ->  5+1+5+5+1+1+5+5 = 28 floats for 5 intruders.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/status.h"

namespace squawk::env {

struct Observation {
  std::vector<double> intruder_distance;   // [-] km / 150
  std::vector<double> cos_difference_pos;  // [-]
  std::vector<double> sin_difference_pos;  // [-]
  std::vector<double> x_difference_speed;  // [-] (m/s) / 150
  std::vector<double> y_difference_speed;  // [-] (m/s) / 150
  double waypoint_distance = 0.0;          // [-] km / 150
  double cos_drift = 1.0;                  // [-]
  double sin_drift = 0.0;                  // [-]

  int num_intruders() const { return static_cast<int>(intruder_distance.size()); }
};

// 3 + 5 * num_intruders.
constexpr int observation_size(int num_intruders) { return 3 + 5 * num_intruders; }

// Writes the flat form into out (observation_size(n) floats).
void flatten(const Observation& o, std::span<float> out);
// Rebuilds the structured form from a flat one; the size must be 3 + 5n.
Result<Observation> unflatten(std::span<const float> flat);

// The mirror image of an encounter: every position reflected in the plane of
// the ownship's meridian, so each heading and bearing h becomes -h (the
// waypoint lies due north, on that plane). In the observation this negates
// sin_difference_pos and sin_drift and maps
//   y_difference_speed = (gs_own - sin(dh) gs_i) / v_s  ->  2 gs_own / v_s - y_difference_speed
// (dh changes sign); the other fields are unchanged. As an affine map on the
// flat form, m = scale * o + offset (both observation_size(n) long, scale
// +-1), its own inverse. Exact while the ownship's ground speed is gs_own.
struct ObservationMirror {
  std::vector<float> scale, offset;
  bool empty() const { return scale.empty(); }
};
// own_speed_ratio = gs_own / v_s, the ownship's ground speed over the
// observation's speed normaliser.
ObservationMirror observation_mirror(int num_intruders, double own_speed_ratio);
// The eight field names in the paper's prompt order (§III.C.3).
const std::vector<std::string>& observation_field_names();

}  // namespace squawk::env
