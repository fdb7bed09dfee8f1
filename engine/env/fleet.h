// Fleet: the few aircraft of one conflict-resolution episode, moved with
// BlueSky's own update equations (bluesky/traffic/traffic.py update_airspeed,
// update_groundspeed, update_pos; docs/bluesky_facts.md §1.8), with no wind, no
// autopilot beyond "fly this heading at this speed", at a fixed time step.
//
// Per step of dt seconds, for each aircraft, in BlueSky's order:
//   1. speed: tas moves toward sel_tas by at most accel*dt, else snaps to it;
//   2. heading: turn rate = g0 tan(bank) / max(tas, 0.01) [rad/s] (with the
//      new tas); hdg moves toward sel_hdg the short way by at most rate*dt,
//      else snaps to it; hdg is kept in [0, 360);
//   3. position (flat earth): lat += deg(dt gs_north / R); lon += deg(dt gs_east /
//      cos(lat_new) / R), R = 6371000 m.
// The speed target is min(sel_tas, speed_cap) when speed_cap > 0: BlueSky's
// OpenAP model puts aircraft at 0 m in its ground phase, whose A320 limit is
// 89 m/s (docs/bluesky_facts.md §6).
// This is a lean twin of the general simulator for the environment's hot path:
// cos/sin of heading and latitude are carried along and rotated by the step's
// latitude change instead of being recomputed (error ~1e-16 per step).
// Index 0 is the ownship by convention of the environment, not of this class.
#pragma once

#include <cstddef>
#include <vector>

namespace squawk::env {

struct FleetLimits {
  double accel = 2.0;        // [m/s^2] longitudinal acceleration magnitude
  double bank = 25.0;        // [deg] bank angle of turns
  double speed_cap = 89.0;   // [m/s] TAS ceiling; <= 0 means none
};

class Fleet {
 public:
  void clear();
  // Adds an aircraft; returns its index. Angles [deg], speeds [m/s].
  int add(double lat, double lon, double hdg, double tas);
  size_t size() const { return lat_.size(); }

  // Commands (BlueSky HDG / SPD): target heading [deg] any value (taken
  // mod 360) and target TAS [m/s].
  void set_heading(int i, double hdg_deg);
  void set_speed(int i, double tas);

  // One update of every aircraft over dt [s].
  void step(double dt, const FleetLimits& lim);

  double lat(int i) const { return lat_[static_cast<size_t>(i)]; }      // [deg]
  double lon(int i) const { return lon_[static_cast<size_t>(i)]; }      // [deg]
  double hdg(int i) const { return hdg_[static_cast<size_t>(i)]; }      // [deg] true heading = track
  double tas(int i) const { return tas_[static_cast<size_t>(i)]; }      // [m/s] = ground speed
  double sel_hdg(int i) const { return sel_hdg_[static_cast<size_t>(i)]; }  // [deg]
  double cos_hdg(int i) const { return cos_hdg_[static_cast<size_t>(i)]; }
  double sin_hdg(int i) const { return sin_hdg_[static_cast<size_t>(i)]; }
  double cos_lat(int i) const { return cos_lat_[static_cast<size_t>(i)]; }
  double sin_lat(int i) const { return sin_lat_[static_cast<size_t>(i)]; }
  double gs_north(int i) const { return tas(i) * cos_hdg(i); }  // [m/s]
  double gs_east(int i) const { return tas(i) * sin_hdg(i); }   // [m/s]

 private:
  std::vector<double> lat_, lon_, hdg_, tas_, sel_hdg_, sel_tas_;
  std::vector<double> cos_hdg_, sin_hdg_, cos_lat_, sin_lat_;
  // Latitude increment [rad] of the last step and its cos/sin.
  std::vector<double> dlat_, cos_dlat_, sin_dlat_;
  double bank_ = -1.0;         // [deg] bank angle rate_factor_ was computed for
  double rate_factor_ = 0.0;   // [deg/s * m/s] turn rate times TAS
};

}  // namespace squawk::env
