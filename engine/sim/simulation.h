// Simulation: the traffic simulator (BlueSky-compatible dynamics, clock, run
// state, conflict detection and resolution).
//
// Contract:
// - Clock: an integer tick count and a step dt (default 0.05 s, BlueSky's
//   simdt). simt() = t_base + ticks_since_base * dt, so time never drifts;
//   set_dt() rebases t_base at the current time.
// - step() advances one dt in BlueSky's order: OpenAP performance update
//   (every 1 s of sim time, openap_perf.h), autopilot (LNAV/VNAV),
//   conflict detection and MVP (every asas_dt of sim time, when enabled),
//   choice of autopilot or resolution targets, performance limits (OpenAP:
//   at the selected altitude), airspeed (+-axmax, snapping to the target),
//   heading (turn rate g0 tan(bank)/TAS with the new TAS, snapping to the
//   target), vertical speed (altitude select with a time-based capture band
//   of 1.05 dt max(|vs target|, |vs|), V/S ramped at 300 ft/min per s), then
//   the flat-earth position update with R = 6 371 000 m (docs/bluesky_facts.md §1.8).
//   Wind (wind.h): above 50 ft the ground velocity is TAS along the heading
//   plus the wind; the autopilot's selected heading is a track, flown with
//   the wind-correction angle asin(Vw sin(trk - wind dir) / TAS), and a
//   resolution ground speed becomes the TAS that gives it. No wind: gs = tas
//   and trk = hdg.
// - Performance model: the class table of performance.h, or OpenAP per type
//   when OpenAP data is set (set_openap; by default the data named by
//   SQUAWK_OPENAP, see openap_data.h).
//   No heap allocation happens in step() once buffers have grown.
// - Every operation that can fail validates all its arguments first and
//   leaves the simulation unchanged on error; the message starts with the
//   aircraft id (or the setting) and names the expected form.
// - Aircraft ids are case-insensitive and stored upper-case.
// - Copying a Simulation makes an independent deep copy.
// - snapshot() is a deterministic byte image of all observable state (clock,
//   run state, settings, every aircraft field, routes, conflict and
//   resolution state, RNG state as its next draws): equal bytes iff equal
//   state. Caches derived from the state are left out.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/rng.h"
#include "core/status.h"
#include "sim/atmosphere.h"
#include "sim/conflict.h"
#include "sim/mvp.h"
#include "sim/openap_data.h"
#include "sim/performance.h"
#include "sim/route.h"
#include "sim/shapes.h"
#include "sim/traffic.h"
#include "sim/wind.h"

namespace squawk::sim {

inline constexpr double kDefaultDt = 0.05;              // [s] BlueSky simdt
inline constexpr double kDefaultBankDeg = 25.0;         // [deg] BlueSky ap.bankdef
// [m/s] vertical speed used when none is selected (1500 ft/min).
inline constexpr double kDefaultVs = 1500.0 * 0.3048 / 60.0;

// [-] VNAV descent path gradient: 3000 ft per 10 NM (BlueSky's steepness).
inline constexpr double kVnavSteepness = 3000.0 * 0.3048 / (10.0 * 1852.0);

enum class RunState { kHold = 0, kOp = 1 };

class Simulation {
 public:
  explicit Simulation(uint64_t seed = 0);

  // --- Clock and run state -------------------------------------------------
  double simt() const { return t_base_ + static_cast<double>(ticks_since_base_) * dt_; }  // [s]
  int64_t ticks() const { return ticks_; }  // steps taken since reset
  double dt() const { return dt_; }         // [s]
  // Error unless 0 < dt <= 60 s and finite.
  Status set_dt(double dt);
  RunState run_state() const { return run_state_; }
  // Run in real time (BlueSky OP): ends fast-time and sets dtmult() to 1.
  void op();
  void hold();  // pause (BlueSky HOLD); ends fast-time, dtmult() kept
  // Fast-time: with a duration [s] >= 0, until simt() + duration; without,
  // until hold() or op(). Also sets the run state OP; dtmult() kept.
  Status fast_forward(std::optional<double> duration);
  bool fast() const { return ff_; }
  std::optional<double> ff_end() const { return ff_end_; }  // [s]
  // DTMULT: the multiple of real time an interactive clock runs at in OP [-]
  // (> 0; 1 after reset and op()). advance() does not read it.
  double dtmult() const { return dtmult_; }
  void set_dtmult(double m) { dtmult_ = m; }
  // Steps as the run state asks, at most max_steps: HOLD none; FF until the
  // end time, which then does op() as BlueSky does (real time, dtmult() 1);
  // OP real-time, wall_s seconds of wall clock worth of steps (the fraction
  // of a step is carried over).
  // Returns the number of steps taken.
  int64_t advance(double wall_s, int64_t max_steps);

  // One step of dt.
  void step();
  // The waypoints with commands (Waypoint::commands) that aircraft passed in
  // the last step(), in aircraft order: the command layer runs them (a
  // caller that steps with run_for / run_until / advance sees only the last
  // step's). Output of the step, not state: left out of snapshot().
  struct Passage {
    std::string acid;
    std::string wpt;
    std::vector<std::string> commands;
  };
  const std::vector<Passage>& passages() const { return passages_; }
  // Steps while simt() + dt/2 <= t_end, i.e. the steps that end at or before
  // t_end on the dt grid. Error when t_end is not finite or seconds < 0.
  Status run_for(double seconds);
  Status run_until(double t_end);

  // Clears traffic, conflicts and settings, time 0, dt default, HOLD
  // (BlueSky RESET). The RNG is reseeded with `seed`.
  void reset(uint64_t seed = 0);
  // Deletes every aircraft and the conflict/resolution state (cumulative
  // counts included); clock, run state and settings stay (BlueSky's
  // traf.reset(), what BlueSky-Gym calls on every episode).
  void delete_all();

  // --- Traffic --------------------------------------------------------------
  // Creates an aircraft (BlueSky CRE). casmach: CAS [m/s] or Mach (is_mach).
  // hdg is wrapped into [0, 360). Errors: empty or duplicate id (naming it),
  // lat outside [-90, 90], lon outside [-180, 180], non-finite values, alt
  // outside [-300, 30000] m, speed < 0 (0 is allowed, as in BlueSky).
  Status create(std::string_view acid, std::string_view actype, double lat, double lon,
                double hdg_deg, double alt_m, double casmach);
  // Creates an intruder in conflict with `target` (BlueSky CRECONFS, facts
  // §1.3): relative track dpsi [deg], dcpa [m] >= 0, tlosh [s] > 0 to
  // horizontal loss of separation at the current rpz. Optional vertical
  // geometry: dh [m] altitude offset and tlosv [s] (default tlosh), giving
  // vs = vs_target - sign(dh) (|dh| - hpz) / tlosv. Optional spd: intruder
  // CAS [m/s] or Mach (default: the target's ground speed). The intruder
  // selects the target's altitude. Positions use kwikpos, as BlueSky does,
  // so the detector sees tLOS/dcpa within ~0.1 % (equator) to ~1 % (60 deg).
  Status creconfs(std::string_view acid, std::string_view actype, std::string_view target,
                  double dpsi_deg, double dcpa_m, double tlosh_s,
                  std::optional<double> dh_m = std::nullopt,
                  std::optional<double> tlosv_s = std::nullopt,
                  std::optional<double> spd = std::nullopt);
  Status remove(std::string_view acid);
  // BlueSky MOVE: new position, optionally altitude (also selected), heading
  // (also selected), speed (CAS/Mach, also selected) and vertical speed.
  Status move(std::string_view acid, double lat, double lon,
              std::optional<double> alt_m = std::nullopt,
              std::optional<double> hdg_deg = std::nullopt,
              std::optional<double> casmach = std::nullopt,
              std::optional<double> vs = std::nullopt);

  // --- Autopilot ------------------------------------------------------------
  // HDG: selected heading [deg], any finite value, wrapped; switches LNAV off.
  // With wind (above 50 ft) the track that heading gives now is selected.
  // turn: -1 left, +1 right (a squawk extension: the aircraft turns that way
  // even when the other way is shorter, until the heading is captured),
  // 0 the short way (BlueSky's HDG).
  Status set_heading(std::string_view acid, double hdg_deg, int turn = 0);
  // ALT: selected altitude [m] in [-300, 30000], optional |vs| [m/s] > 0;
  // switches VNAV off.
  Status set_altitude(std::string_view acid, double alt_m, std::optional<double> vs = std::nullopt);
  // VS: selected vertical speed magnitude [m/s] (sign ignored; the aircraft
  // climbs or descends toward its selected altitude); switches VNAV off.
  Status set_vs(std::string_view acid, double vs);
  // The autopilot's selected altitude and vertical speed written as
  // BlueSky-Gym's environments write bs.traf.selalt / selvs (no ALT command):
  // any finite altitude [m] (a target above the performance ceiling is
  // bounded by it, as every selected altitude is), vs [m/s] whose magnitude
  // is flown (<= 0.1 m/s: the default, as BlueSky); VNAV off.
  Status select_vertical(std::string_view acid, double alt_m, double vs);
  // SPD: selected CAS [m/s] or Mach, >= 0. With VNAV on, passing a waypoint
  // with a speed constraint replaces it.
  Status set_speed(std::string_view acid, double casmach);
  // BANK: bank angle [deg] in (0, 90).
  Status set_bank(std::string_view acid, double bank_deg);
  // LNAV / VNAV switches. Turning on needs a route with an active waypoint;
  // VNAV on also turns LNAV on. While VNAV is on it sets sel_alt and sel_vs
  // from the active waypoint's altitude constraint (rule in simulation.cpp).
  Status set_lnav(std::string_view acid, bool on);
  Status set_vnav(std::string_view acid, bool on);

  // --- Routes ---------------------------------------------------------------
  // ADDWPT: appends (before the destination). The first waypoint of an empty
  // route becomes active and switches LNAV on (as BlueSky).
  Status add_waypoint(std::string_view acid, Waypoint wp);
  Status add_waypoint_after(std::string_view acid, std::string_view ref, Waypoint wp);
  Status add_waypoint_before(std::string_view acid, std::string_view ref, Waypoint wp);
  Status delete_waypoint(std::string_view acid, std::string_view name);
  // AT acid wp DO: appends a command line to waypoint `name`'s commands.
  Status add_waypoint_command(std::string_view acid, std::string_view name, std::string line);
  // ADDWPT acid FLYOVER / FLYBY: mode of the waypoints added from now on.
  Status set_flyover_mode(std::string_view acid, bool flyover);
  // DELRTE: empties the route and switches LNAV and VNAV off.
  Status delete_route(std::string_view acid);
  // DIRECT: makes `name` active and switches LNAV on.
  Status direct_to(std::string_view acid, std::string_view name);
  Status set_dest(std::string_view acid, Waypoint dest);
  Status set_orig(std::string_view acid, Waypoint orig);

  // --- Conflict detection and resolution ------------------------------------
  const CdSettings& cd_settings() const { return cds_; }
  const CrSettings& cr_settings() const { return crs_; }
  // ASAS / CDMETHOD ON|OFF. Off clears current pairs and resolutions.
  void set_cd(bool on);
  Status set_rpz(double rpz_m);        // > 0
  Status set_hpz(double hpz_m);        // > 0
  Status set_dtlook(double dtlook_s);  // > 0
  Status set_asas_dt(double asas_dt_s);  // > 0
  // Conflict (and LoS) pairs stored per detection (CdSettings::max_pairs), >= 1.
  Status set_cd_max_pairs(int64_t n);
  // Detection by the all-pairs reference instead of the grid (same results).
  void set_cd_all_pairs(bool on) { cds_.all_pairs = on; }
  // RESO MVP|OFF. On also switches detection on (resolution needs it).
  void set_reso(bool on);
  Status set_resofach(double f);  // >= 1
  Status set_resofacv(double f);  // >= 1
  void set_reso_vertical(bool on);
  // RESNAV PASTCPA|OFF (on by default).
  void set_reso_resume(bool on);
  const ConflictDetector& cd() const { return cd_; }
  const MvpResolver& cr() const { return cr_; }
  const std::vector<ConflictPair>& conflicts() const { return cd_.pairs(); }
  const std::vector<LosPair>& los() const { return cd_.los(); }

  // --- Performance ----------------------------------------------------------
  // OpenAP data for every aircraft (existing ones are re-initialised);
  // null selects the class model.
  void set_openap(std::shared_ptr<const OpenapData> data);
  const std::shared_ptr<const OpenapData>& openap() const { return openap_; }
  const PerformanceOptions& performance_options() const { return perf_opts_; }
  // Error when a value is not finite or not positive.
  Status set_performance_options(const PerformanceOptions& opts);

  // --- Named shapes and the deletion area (BlueSky BOX/CIRCLE/POLY, AREA) ----
  const ShapeSet& shapes() const { return shapes_; }
  Status define_shape(const std::string& name, Shape shape) { return shapes_.define(name, std::move(shape)); }
  // False when there is no such shape. Deleting the deletion area's shape
  // leaves AREA on with nothing inside (BlueSky then deletes every aircraft
  // that was inside at the last check).
  bool delete_shape(const std::string& name) { return shapes_.remove(name); }
  // AREA: every 1 s of sim time (after the step), aircraft that were inside
  // the named shape at the previous check and are outside now are deleted;
  // aircraft never inside stay. set_area(box) defines the shape DELAREA, as
  // BlueSky does. Errors: no shape `name`; a bad box (see ShapeSet::define).
  Status set_area(const std::string& name);
  Status set_area(double lat0, double lon0, double lat1, double lon1, double top = 1e9, double bottom = -1e9);
  void area_off() { area_active_ = false; }
  bool area_active() const { return area_active_; }
  const std::string& area_name() const { return area_name_; }

  // --- Wind -----------------------------------------------------------------
  const WindField& wind() const { return wind_; }
  // BlueSky WIND lat,lon,dir,spd (every altitude) or WIND lat,lon,alt,dir,spd,...
  Status add_wind_uniform(double lat, double lon, double dir_deg, double spd) {
    return wind_.add_uniform(lat, lon, dir_deg, spd);
  }
  Status add_wind_profile(double lat, double lon, const std::vector<WindSample>& samples) {
    return wind_.add_profile(lat, lon, samples);
  }
  void clear_wind() { wind_.clear(); }

  // --- Access ---------------------------------------------------------------
  const Traffic& traffic() const { return traf_; }
  int n() const { return traf_.n(); }
  int index_of(std::string_view acid) const { return traf_.index_of(acid); }
  Rng& rng() { return rng_; }

  std::string snapshot() const;

 private:
  Result<int> lookup(std::string_view acid) const;
  Status check_new_id(std::string_view acid, std::string_view actype) const;
  // Appends a validated aircraft flying at `tas` [m/s] with selected speed
  // sel_spd (CAS or Mach); returns its index.
  int add_aircraft(std::string_view acid, std::string_view actype, double lat, double lon,
                   double hdg_deg, double alt_m, double tas, double sel_spd);
  // Runs a route mutation of aircraft `acid` and updates LNAV/VNAV: on when
  // the route gains its first active waypoint, off when none is left.
  template <class Op>
  Status route_op(std::string_view acid, Op&& op, bool direct = false);
  void init_perf(int i);
  void update_perf();
  // A waypoint became active (BlueSky's direct / waypoint switch): leg
  // direction, turn distance, next altitude constraint and the VNAV plan.
  // `passing`: the turn distance is computed before the VNAV plan (switch)
  // rather than after it (DIRECT, ADDWPT, VNAV ON), as in BlueSky.
  void start_leg(int i, bool passing);
  // BlueSky's ComputeVNAV: dist2vs and wp_vs for the constraint toalt [m]
  // xtoalt [m] beyond the active waypoint.
  void compute_vnav(int i, double toalt, double xtoalt);
  void update_autopilot();
  // Sets the selected speed of aircraft i (invalidating its target cache).
  void select_speed(int i, double casmach);
  void update_asas();
  void update_kinematics();
  // cas and mach from tas at the atmosphere `a` of the aircraft's altitude.
  void refresh_speed_outputs(int i, const Atmos& a);
  void retarget(int i, const Atmos& a);
  void set_heading_cache(int i);
  // Sets coslat and sinlat of aircraft i from its latitude.
  void set_lat_cache(int i);
  // Latitude trigonometry of lat_deg (aircraft i's active waypoint), from
  // Traffic::wp_trig while the latitude is the one it was computed for.
  const geo::LatTrig& wp_trig(int i, double lat_deg);

  // Per-step scratch of update_autopilot (one entry per aircraft, not state):
  // the active waypoint's latitude [rad], its sine and cosine, its longitude
  // [deg], and qdrdist from the aircraft to it; la: the aircraft's latitude [rad].
  struct ApScratch {
    std::vector<double> la, lb, sb, cb, lonb, qdr_deg, dist_nm;
  } ap_;
  std::vector<Passage> passages_;

  Traffic traf_;
  ConflictDetector cd_;
  MvpResolver cr_;
  CdSettings cds_;
  CrSettings crs_;
  PerformanceOptions perf_opts_;
  std::shared_ptr<const OpenapData> openap_;
  WindField wind_;
  ShapeSet shapes_;
  bool area_active_ = false;
  std::string area_name_;  // the deletion area's shape
  double next_area_t_ = 0.0;  // [s] sim time of the next area check
  void update_area();
  Rng rng_;
  uint64_t next_uid_ = 1;

  double dt_ = kDefaultDt;        // [s]
  double t_base_ = 0.0;           // [s] time at the last dt change
  int64_t ticks_since_base_ = 0;  // steps since the last dt change
  int64_t ticks_ = 0;             // steps since reset
  double next_asas_t_ = 0.0;      // [s] sim time of the next detection
  double next_perf_t_ = 0.0;      // [s] sim time of the next performance update
  RunState run_state_ = RunState::kHold;
  bool ff_ = false;
  std::optional<double> ff_end_;  // [s]
  double dtmult_ = 1.0;           // [-]
  double wall_carry_ = 0.0;       // [s] real time not yet stepped (not observable)
};

}  // namespace squawk::sim
