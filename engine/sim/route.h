// Route: an aircraft's flight plan (waypoints with optional altitude/speed
// constraints, an active waypoint, origin and destination).
//
// Contract:
// - Waypoint names are stored upper-case; look-ups are case-insensitive and
//   find the first waypoint with that name.
// - The destination, when set, is always the last waypoint; waypoints added
//   with add() go before it (as BlueSky's ADDWPT does).
// - active() is the index of the waypoint being flown to, or -1 when the
//   route is empty or completed.
// - Every mutator validates first; on error the route is unchanged and the
//   message names the waypoint and what was expected.
//
// LNAV passage rule (BlueSky's ActiveWaypoint.reached): with turn radius
// R = tas^2 / (g0 tan(bank)) and course change dpsi at the waypoint (0 for a
// fly-over or the last waypoint), the aircraft switches to the next waypoint
// when dist < R tan(|dpsi|/2), or when the waypoint is behind it
// (|trk - qdr| > 90 deg) and dist < 1.02 R.
#pragma once

#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "core/status.h"

namespace squawk::sim {

inline constexpr double kNoConstraint = std::numeric_limits<double>::quiet_NaN();

struct Waypoint {
  std::string name;              // upper-case
  double lat = 0.0;              // [deg]
  double lon = 0.0;              // [deg]
  double alt = kNoConstraint;    // [m] altitude constraint, NaN when none
  double spd = kNoConstraint;    // CAS [m/s] or Mach (see atmosphere.h is_mach), NaN when none
  bool flyover = false;          // true: fly over it (no turn anticipation)

  bool has_alt() const { return alt == alt; }
  bool has_spd() const { return spd == spd; }
};

class Route {
 public:
  const std::vector<Waypoint>& waypoints() const { return wps_; }
  int size() const { return static_cast<int>(wps_.size()); }
  bool empty() const { return wps_.empty(); }
  int active() const { return active_; }
  const Waypoint* active_waypoint() const { return active_ >= 0 ? &wps_[active_] : nullptr; }
  // Index of the first waypoint named `name` (case-insensitive), or -1.
  int find(std::string_view name) const;

  // Appends `wp` (before the destination, if any). Becomes active when the
  // route had no active waypoint. Errors: empty name, non-finite or
  // out-of-range lat/lon, negative altitude or speed constraint.
  Status add(Waypoint wp);
  // Inserts after / before the waypoint named `ref`. Errors: as add(), and
  // NotFound naming `ref`; insert_after the destination is refused.
  Status insert_after(std::string_view ref, Waypoint wp);
  Status insert_before(std::string_view ref, Waypoint wp);
  // Deletes the named waypoint; the active index follows its waypoint, and
  // when the active waypoint itself is deleted the next one becomes active.
  Status remove(std::string_view name);
  // Empties the route, including origin and destination.
  void clear();
  // Makes the named waypoint active (BlueSky's DIRECT).
  Status direct_to(std::string_view name);
  // Sets the destination: replaces a previous destination waypoint, else
  // appends `dest` as the last waypoint.
  Status set_dest(Waypoint dest);
  // Sets the origin (not a waypoint to fly to; kept for display and RTE).
  Status set_orig(Waypoint orig);
  const std::string& dest() const { return dest_; }  // empty when unset
  const std::string& orig() const { return orig_name_; }
  double orig_lat() const { return orig_lat_; }  // [deg]
  double orig_lon() const { return orig_lon_; }  // [deg]

  // Moves to the next waypoint; returns false (active() becomes -1) when the
  // active waypoint was the last one.
  bool advance();

  // Appends a deterministic byte image of the route to `out` (for snapshots).
  void serialize(std::string& out) const;

 private:
  Status validate(const Waypoint& wp) const;
  std::vector<Waypoint> wps_;
  int active_ = -1;
  std::string dest_;
  std::string orig_name_;
  double orig_lat_ = 0.0;  // [deg]
  double orig_lon_ = 0.0;  // [deg]
};

// The LNAV passage test described at the top of this file.
// dist [m] and qdr [deg] from aircraft to the active waypoint; next_qdr [deg]
// the course of the following leg (equal to qdr when there is none or the
// waypoint is a fly-over); trk [deg]; tas [m/s]; bank [rad].
bool waypoint_reached(double dist, double qdr, double next_qdr, double trk, double tas, double bank);

}  // namespace squawk::sim
