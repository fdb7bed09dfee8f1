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
// LNAV passage rule (BlueSky's ActiveWaypoint.reached and calcturn): when a
// waypoint becomes active, the turn distance is fixed from the TAS then,
// R = tas^2 / (g0 tan(bank)) and the course change dpsi at the waypoint:
// R tan(|dpsi|/2) for a fly-by, 0 for a fly-over or the last waypoint, and
// the leg direction curlegdir is the bearing to it then. The aircraft
// switches to the next waypoint when dist < turn distance, or when the
// bearing to the waypoint is more than 90 deg off curlegdir (passed), or
// when it is within 4 s of flight and more than 90 deg off the track.
#pragma once

#include <limits>
#include <string>
#include <string_view>
#include <unordered_map>
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
  // Command lines (TrafScript, one command each, as stored by AT acid wp DO)
  // that the command layer runs, in order, each time the aircraft passes this
  // waypoint (Simulation::passages()).
  std::vector<std::string> commands = {};

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
  // route had no active waypoint, or when the destination was active (the
  // active index stays where the new waypoint lands, as in BlueSky). Errors: empty name, non-finite or
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
  // Appends `line` to the commands of the waypoint named `name` (the first
  // of that name). Errors: NotFound naming `name`; an empty line.
  Status add_command(std::string_view name, std::string line);
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

  // BlueSky's flight-plan altitude target of waypoint k: the first waypoint
  // at or after k with an altitude constraint (toalt [m], NaN when none) and
  // the route distance xtoalt [m] from waypoint k to it (WGS-84 legs).
  struct AltTarget {
    double toalt;
    double xtoalt;
  };
  AltTarget alt_target(int k) const;

  // ADDWPT acid FLYOVER / FLYBY: the mode of waypoints added from now on.
  void set_flyover_mode(bool on) { flyover_mode_ = on; }
  bool flyover_mode() const { return flyover_mode_; }

  // Moves to the next waypoint; returns false (active() becomes -1) when the
  // active waypoint was the last one.
  bool advance();

  // Appends a deterministic byte image of the route to `out` (for snapshots).
  void serialize(std::string& out) const;

 private:
  Status validate(const Waypoint& wp) const;
  // Every change of wps_ goes through these: they keep the indexes below.
  void place(int at, Waypoint wp);
  void drop(int k);
  void count(const Waypoint& wp, int delta);
  std::vector<Waypoint> wps_;
  // Indexes that keep ADDWPT bursts linear: waypoints per (upper-case) name,
  // waypoints with an altitude constraint, and leg k -> k+1 lengths [m]
  // (NaN until alt_target needs one; same size as wps_).
  std::unordered_map<std::string, int> names_;
  int n_alt_ = 0;
  mutable std::vector<double> leg_;
  int active_ = -1;
  bool flyover_mode_ = false;
  std::string dest_;
  std::string orig_name_;
  double orig_lat_ = 0.0;  // [deg]
  double orig_lon_ = 0.0;  // [deg]
};

// The LNAV passage test described at the top of this file. dist [m] and qdr
// [deg] from aircraft to the active waypoint; curlegdir [deg]; trk [deg];
// gs [m/s]; turndist [m].
bool waypoint_reached(double dist, double qdr, double curlegdir, double trk, double gs, double turndist);
// Turn distance [m] at a waypoint: tas [m/s], bank [rad], qdr [deg] to it,
// next_qdr [deg] of the following leg, flyby false for a fly-over.
double turn_distance(double tas, double bank, double qdr, double next_qdr, bool flyby);

}  // namespace squawk::sim
