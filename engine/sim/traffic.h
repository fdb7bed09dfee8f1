// Traffic: all aircraft state as a structure of arrays.
//
// Contract:
// - Every per-aircraft vector has size n(); index i is the same aircraft in
//   all of them. Creation appends; deletion erases in place so the remaining
//   aircraft keep their relative order (BlueSky's ordering: the first created
//   aircraft stays index 0).
// - Ids are upper-case and unique; index_of() maps id -> index in O(1).
// - Fields are written by Simulation only; readers (env, commands, Lua) may
//   read them directly. Angles in degrees unless the name says rad.
// - uid is a creation serial number, never reused, used to follow pairs of
//   aircraft across deletions.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/geo.h"
#include "sim/openap_perf.h"
#include "sim/performance.h"
#include "sim/route.h"

namespace squawk::sim {

struct Traffic {
  // Identity
  std::vector<std::string> id;       // upper-case callsign
  std::vector<std::string> type;     // upper-case ICAO type designator
  std::vector<uint64_t> uid;         // creation serial

  // State
  std::vector<double> lat, lon;      // [deg]
  std::vector<double> alt;           // [m]
  std::vector<double> hdg, trk;      // [deg] in [0, 360)
  std::vector<double> tas, cas, gs;  // [m/s]
  std::vector<double> mach;          // [-]
  std::vector<double> gsnorth, gseast;  // [m/s]
  std::vector<double> vs;            // [m/s] current vertical speed
  std::vector<double> coslat;        // [-] cos(lat), kept current
  std::vector<double> sinlat;        // [-] sin(lat), kept current with coslat

  // Autopilot selections (what the pilot flies when no resolution is active)
  std::vector<double> sel_hdg;       // [deg] selected heading/track
  std::vector<int8_t> sel_turn;      // [-] commanded turn direction to sel_hdg: -1 left, +1 right,
                                     // 0 the short way; back to 0 once the heading is captured
  std::vector<double> sel_alt;       // [m] selected altitude
  std::vector<double> sel_spd;       // CAS [m/s] or Mach (is_mach), the selected speed
  std::vector<double> sel_vs;        // [m/s] selected |vertical speed|; 0 = class default
  std::vector<double> bank;          // [rad] bank angle used for turns (default 25 deg)
  std::vector<double> tan_bank;      // [-] tan(bank), set with bank
  std::vector<uint8_t> lnav, vnav;   // 0/1 switches
  std::vector<Route> route;

  // Performance
  std::vector<PerfClass> perf_class;
  std::vector<PerfLimits> perf;      // limits in force (class table, or OpenAP updated at 1 Hz)
  std::vector<const OpenapType*> oap;  // OpenAP data of the type; null: class model (performance.h)
  std::vector<FlightPhase> phase;    // OpenAP flight phase (kNA under the class model)
  std::vector<double> ax;            // [m/s^2] longitudinal acceleration of the last step

  // VNAV (BlueSky's active-waypoint data, set when a waypoint becomes active)
  std::vector<double> wp_lat, wp_lon;  // [deg] last active waypoint (0, 0 before any, as in BlueSky)
  std::vector<double> dist2wp;       // [m] distance to it at the last step: -999 before the first
                                     // step, NaN when not kept (no LNAV; computed on demand)
  std::vector<double> nextaltco;     // [m] next altitude constraint (< -0.1: none)
  std::vector<double> dist2vs;       // [m] distance to the active waypoint where climb/descent starts
  std::vector<double> wp_vs;         // [m/s] signed V/S planned for this leg
  std::vector<double> vnav_vs;       // [m/s] V/S last used by VNAV
  std::vector<double> turndist;      // [m] fly-by turn anticipation distance at the active waypoint
  std::vector<double> curlegdir;     // [deg] bearing to the active waypoint when it became active
  std::vector<double> turnspd;       // BlueSky's stored turn speed: the TAS [m/s] at the last DIRECT
                                     // (ADDWPT, DEST, LNAV ON), < 0 after a waypoint switch
  std::vector<double> oldturnspd;    // turn speed of the waypoint just passed (< 0: none); VNAV
                                     // selects it as CAS while turning onto the new leg
  std::vector<uint8_t> vnav_spd;     // VNAV speed mode (on with VNAV ON, off with SPD)
  std::vector<double> leg_spd;       // speed constraint of the leg flown (CAS/Mach; < 0: none)
  std::vector<double> next_spd;      // speed constraint at the active waypoint (< 0: none)
  std::vector<uint8_t> in_area;      // inside the deletion area at its last check

  // Conflict resolution output (mvp.h), followed while cr_active is set
  std::vector<uint8_t> cr_active;    // 0/1
  std::vector<double> cr_trk;        // [deg]
  std::vector<double> cr_tas;        // [m/s]
  std::vector<double> cr_vs;         // [m/s]
  std::vector<double> cr_alt;        // [m]

  // Caches kept by Simulation::step (derived state, not observable):
  std::vector<double> sin_hdg, cos_hdg;  // [-] of hdg
  std::vector<geo::LatTrig> wp_trig;   // latitude trigonometry of the autopilot's last waypoint (keyed by .rad)
  std::vector<double> tgt_tas;       // [m/s] TAS meant by sel_spd at tgt_tas_alt
  std::vector<double> tgt_tas_alt;   // [m] altitude at which tgt_tas was computed (NaN: stale)
  std::vector<double> tgt_tas_sel;   // [m] OpenAP: target altitude at which the limits were applied
  std::vector<uint8_t> vnav_vs_on;   // VNAV flies vnav_vs to nextaltco this step (set by the autopilot)

  std::unordered_map<std::string, int> index;  // id -> index

  int n() const { return static_cast<int>(id.size()); }
  // Index of `acid` (case-insensitive), or -1.
  int index_of(std::string_view acid) const;

  // Appends one aircraft with every field given a neutral value (zeros,
  // empty route, switches off, bank 25 deg); the caller fills the state.
  // Precondition: `acid` (upper-case) is not present.
  int append(const std::string& acid, const std::string& actype, uint64_t serial);
  // Erases aircraft i, keeping the others' order and the id map consistent.
  void erase(int i);
  void clear();
};

}  // namespace squawk::sim
