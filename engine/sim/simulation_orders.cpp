// Simulation orders: the validated commands that change the traffic,
// the clock, autopilots, routes and conflict settings (simulation.h).
// Each validates every argument before it changes anything.
#include "sim/simulation.h"

#include <algorithm>
#include <cmath>

#include "core/geo.h"
#include "core/text.h"
#include "core/units.h"
#include "sim/atmosphere.h"

namespace squawk::sim {

using units::kDeg;

namespace {
constexpr double kMinAlt = -300.0;    // [m] lowest accepted altitude
constexpr double kMaxAlt = 30000.0;   // [m] highest accepted altitude

std::string num(double v) { return text::fmt_double(v, 6); }

// "<ACID>: <what>" as an invalid-argument Status.
Status bad(std::string_view who, const std::string& what) {
  std::string m(who);
  m.append(": ").append(what);
  return Status::invalid(std::move(m));
}

Status check_latlon(std::string_view who, double lat, double lon) {
  if (!std::isfinite(lat) || lat < -90.0 || lat > 90.0)
    return bad(who, "latitude " + num(lat) + " is not in [-90, 90] deg");
  if (!std::isfinite(lon) || lon < -180.0 || lon > 180.0)
    return bad(who, "longitude " + num(lon) + " is not in [-180, 180] deg");
  return Status::ok();
}

Status check_alt(std::string_view who, double alt) {
  if (!std::isfinite(alt) || alt < kMinAlt || alt > kMaxAlt)
    return bad(who, "altitude " + num(alt) + " m is not in [-300, 30000] m");
  return Status::ok();
}

Status check_positive(std::string_view who, const char* what, double v) {
  if (!std::isfinite(v) || v <= 0.0) {
    std::string m(what);
    m.append(" ").append(num(v)).append(" must be a positive number");
    return bad(who, m);
  }
  return Status::ok();
}

// Sets field to v when v is a positive number; leaves it unchanged otherwise.
Status assign_positive(std::string_view who, const char* what, double v, double& field) {
  SQUAWK_RETURN_IF_ERROR(check_positive(who, what, v));
  field = v;
  return Status::ok();
}

// Speeds may be 0 (a parked or holding aircraft, as BlueSky allows), not negative.
Status check_speed(std::string_view who, double v) {
  if (!std::isfinite(v) || v < 0.0) {
    std::string m("speed ");
    m.append(num(v)).append(" must be 0 or a positive CAS or Mach");
    return bad(who, m);
  }
  return Status::ok();
}

Status check_finite(std::string_view who, const char* what, double v) {
  if (!std::isfinite(v)) {
    std::string m(what);
    m.append(" must be a finite number");
    return bad(who, m);
  }
  return Status::ok();
}
}  // namespace

constexpr double kMinDt = 0.001;  // [s] smallest time step: finer ones never finish a run

// --- Clock and run state ----------------------------------------------------

Status Simulation::set_dt(double dt) {
  if (!std::isfinite(dt) || dt < kMinDt || dt > 60.0)
    return bad("DT", "time step " + num(dt) + " s is not in [0.001, 60] s");
  t_base_ = simt();
  ticks_since_base_ = 0;
  dt_ = dt;
  return Status::ok();
}

void Simulation::op() {
  run_state_ = RunState::kOp;
  ff_ = false;
  ff_end_.reset();
  dtmult_ = 1.0;
}

void Simulation::hold() {
  run_state_ = RunState::kHold;
  ff_ = false;
  ff_end_.reset();
}

Status Simulation::fast_forward(std::optional<double> duration) {
  if (duration && (!std::isfinite(*duration) || *duration < 0.0))
    return bad("FF", "duration " + num(*duration) + " s must be a finite number >= 0");
  ff_ = true;
  ff_end_.reset();
  if (duration) ff_end_ = simt() + *duration;
  run_state_ = RunState::kOp;
  return Status::ok();
}

Status Simulation::run_for(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0)
    return bad("RUN", "duration " + num(seconds) + " s must be a finite number >= 0");
  return run_until(simt() + seconds);
}

Status Simulation::run_until(double t_end) {
  if (!std::isfinite(t_end)) return bad("RUN", "end time must be a finite number of seconds");
  while (simt() + 0.5 * dt_ <= t_end) step();
  return Status::ok();
}

void Simulation::reset(uint64_t seed) {
  auto data = openap_;  // the performance model survives RESET, as in BlueSky
  const int64_t max_pairs = cds_.max_pairs;  // a command-line setting, as the model
  *this = Simulation(seed);
  openap_ = std::move(data);
  cds_.max_pairs = max_pairs;
}

void Simulation::delete_all() {
  traf_.clear();
  cd_.clear(true);
  cr_.clear();
}

Status Simulation::set_area(const std::string& name) {
  if (!shapes_.find(name)) return bad("AREA", "no shape " + text::quoted(name) + " (define it with BOX, CIRCLE or POLY)");
  area_name_ = name;
  area_active_ = true;
  return Status::ok();
}

Status Simulation::set_area(double lat0, double lon0, double lat1, double lon1, double top, double bottom) {
  SQUAWK_RETURN_IF_ERROR(shapes_.define("DELAREA", Shape{Shape::Kind::kBox, {lat0, lon0, lat1, lon1}, top, bottom}));
  return set_area("DELAREA");
}

// --- Traffic ------------------------------------------------------------------

Result<int> Simulation::lookup(std::string_view acid) const {
  const int i = traf_.index_of(acid);
  if (i < 0) {
    std::string m(text::upper(text::trim(acid)));
    m.append(": no aircraft with this id");
    return Status::not_found(std::move(m));
  }
  return i;
}

Status Simulation::check_new_id(std::string_view acid, std::string_view actype) const {
  const std::string id = text::upper(text::trim(acid));
  if (id.empty()) return bad("CRE", "empty aircraft id; expected a callsign such as KL204");
  for (char c : id)
    if (c == ',' || c == ';' || c <= ' ') return bad(id, "aircraft id must not contain spaces, ',' or ';'");
  if (traf_.index_of(id) >= 0) return bad(id, "an aircraft with this id already exists");
  if (text::trim(actype).empty()) return bad(id, "empty aircraft type; expected an ICAO type such as A320");
  return Status::ok();
}

int Simulation::add_aircraft(std::string_view acid, std::string_view actype, double lat, double lon,
                             double hdg_deg, double alt_m, double tas, double sel_spd) {
  const std::string type = text::upper(text::trim(actype));
  const int i = traf_.append(text::upper(text::trim(acid)), type, next_uid_++);
  Traffic& t = traf_;
  t.lat[i] = lat;
  t.lon[i] = lon;
  t.alt[i] = alt_m;
  t.hdg[i] = t.trk[i] = t.sel_hdg[i] = geo::wrap360(hdg_deg);
  t.tas[i] = t.gs[i] = tas;
  t.sel_alt[i] = alt_m;
  t.sel_spd[i] = sel_spd;
  init_perf(i);
  set_lat_cache(i);
  set_heading_cache(i);
  t.gsnorth[i] = tas * t.cos_hdg[i];
  t.gseast[i] = tas * t.sin_hdg[i];
  if (wind_.dim() > 0 && alt_m > kWindMinAlt) {  // the autopilot holds the track it starts on
    const WindNE w = wind_.at(lat, lon, alt_m);
    t.gsnorth[i] += w.north;
    t.gseast[i] += w.east;
    t.gs[i] = std::hypot(t.gsnorth[i], t.gseast[i]);
    t.trk[i] = t.sel_hdg[i] = geo::wrap360(std::atan2(t.gseast[i], t.gsnorth[i]) / kDeg);
  }
  refresh_speed_outputs(i, isa(alt_m));
  return i;
}

Status Simulation::create(std::string_view acid, std::string_view actype, double lat, double lon,
                          double hdg_deg, double alt_m, double casmach) {
  SQUAWK_RETURN_IF_ERROR(check_new_id(acid, actype));
  const std::string id = text::upper(text::trim(acid));
  SQUAWK_RETURN_IF_ERROR(check_latlon(id, lat, lon));
  SQUAWK_RETURN_IF_ERROR(check_finite(id, "heading", hdg_deg));
  SQUAWK_RETURN_IF_ERROR(check_alt(id, alt_m));
  SQUAWK_RETURN_IF_ERROR(check_speed(id, casmach));
  add_aircraft(id, actype, lat, lon, hdg_deg, alt_m, casormach_to_tas(casmach, alt_m), casmach);
  return Status::ok();
}

Status Simulation::creconfs(std::string_view acid, std::string_view actype, std::string_view target,
                            double dpsi_deg, double dcpa_m, double tlosh_s, std::optional<double> dh_m,
                            std::optional<double> tlosv_s, std::optional<double> spd) {
  SQUAWK_ASSIGN_OR_RETURN(const int o, lookup(target));
  SQUAWK_RETURN_IF_ERROR(check_new_id(acid, actype));
  const std::string id = text::upper(text::trim(acid));
  SQUAWK_RETURN_IF_ERROR(check_finite(id, "dpsi", dpsi_deg));
  if (!std::isfinite(dcpa_m) || dcpa_m < 0.0) return bad(id, "dcpa " + num(dcpa_m) + " m must be >= 0");
  SQUAWK_RETURN_IF_ERROR(check_positive(id, "tlosh", tlosh_s));
  if (dh_m) SQUAWK_RETURN_IF_ERROR(check_finite(id, "dH", *dh_m));
  if (tlosv_s) SQUAWK_RETURN_IF_ERROR(check_positive(id, "tlosv", *tlosv_s));
  if (spd) SQUAWK_RETURN_IF_ERROR(check_positive(id, "spd", *spd));
  const Traffic& t = traf_;
  const double alt_o = t.alt[o];
  double alt = alt_o, vs = 0.0;
  if (dh_m) {
    alt = alt_o + *dh_m;
    const double tv = tlosv_s.value_or(tlosh_s);
    vs = t.vs[o] - std::copysign(1.0, *dh_m) * (std::fabs(*dh_m) - cds_.hpz) / tv;
  }
  SQUAWK_RETURN_IF_ERROR(check_alt(id, alt));
  const double pzr = cds_.rpz;
  const double trk_o = t.trk[o] * kDeg, trk = trk_o + dpsi_deg * kDeg;
  const double gs_o = t.gs[o], gs = spd ? casormach_to_tas(*spd, alt) : gs_o;
  const double gsn = gs * std::cos(trk), gse = gs * std::sin(trk);
  const double vreln = gs_o * std::cos(trk_o) - gsn, vrele = gs_o * std::sin(trk_o) - gse;
  const double vrel = std::hypot(vreln, vrele);
  const double drelcpa = tlosh_s * vrel + (dcpa_m > pzr ? 0.0 : std::sqrt(pzr * pzr - dcpa_m * dcpa_m));
  const double dist = std::hypot(drelcpa, dcpa_m);
  if (!(dist > 0.0)) return bad(id, "the requested geometry puts the intruder on top of " + t.id[o]);
  const double rd = drelcpa / dist, rx = dcpa_m / dist;
  const double brn = std::atan2(-rx * vreln + rd * vrele, rd * vreln + rx * vrele) / kDeg;
  const geo::LatLon pos = geo::kwikpos(t.lat[o], t.lon[o], brn, units::m_to_nm(dist));
  SQUAWK_RETURN_IF_ERROR(check_latlon(id, pos.lat_deg, pos.lon_deg));
  const double hdg = std::atan2(gse, gsn) / kDeg;
  // BlueSky converts the ground speed to CAS with its scalar atmosphere and
  // creates the aircraft at that CAS, whose TAS comes from the vectorised one.
  const double cas = tas_to_cas(gs, isa_layered(alt));
  const int i = add_aircraft(id, actype, pos.lat_deg, pos.lon_deg, hdg, alt, cas_to_tas(cas, alt), cas);
  traf_.sel_alt[i] = alt_o;
  traf_.sel_vs[i] = std::fabs(vs);
  traf_.vs[i] = vs;
  return Status::ok();
}

Status Simulation::remove(std::string_view acid) {
  SQUAWK_ASSIGN_OR_RETURN(const int i, lookup(acid));
  cr_.on_erase(traf_.uid[i]);
  cd_.on_erase(i);
  traf_.erase(i);
  return Status::ok();
}

Status Simulation::move(std::string_view acid, double lat, double lon, std::optional<double> alt_m,
                        std::optional<double> hdg_deg, std::optional<double> casmach,
                        std::optional<double> vs) {
  SQUAWK_ASSIGN_OR_RETURN(const int i, lookup(acid));
  const std::string& id = traf_.id[i];
  SQUAWK_RETURN_IF_ERROR(check_latlon(id, lat, lon));
  if (alt_m) SQUAWK_RETURN_IF_ERROR(check_alt(id, *alt_m));
  if (hdg_deg) SQUAWK_RETURN_IF_ERROR(check_finite(id, "heading", *hdg_deg));
  if (casmach) SQUAWK_RETURN_IF_ERROR(check_speed(id, *casmach));
  if (vs) SQUAWK_RETURN_IF_ERROR(check_finite(id, "vertical speed", *vs));
  Traffic& t = traf_;
  t.lat[i] = lat;
  t.lon[i] = lon;
  set_lat_cache(i);
  if (alt_m) t.alt[i] = t.sel_alt[i] = *alt_m;
  if (hdg_deg) {
    t.hdg[i] = t.trk[i] = t.sel_hdg[i] = geo::wrap360(*hdg_deg);
    t.sel_turn[i] = 0;
    set_heading_cache(i);
  }
  if (casmach) {
    t.sel_spd[i] = *casmach;
    t.tas[i] = t.gs[i] = casormach_to_tas(*casmach, t.alt[i]);
  }
  if (vs) {
    t.vs[i] = *vs;
    t.vnav[i] = 0;
  }
  t.gsnorth[i] = t.tas[i] * t.cos_hdg[i];
  t.gseast[i] = t.tas[i] * t.sin_hdg[i];
  t.tgt_tas_alt[i] = std::nan("");
  refresh_speed_outputs(i, isa(t.alt[i]));
  return Status::ok();
}

// --- Autopilot ----------------------------------------------------------------

Status Simulation::set_heading(std::string_view acid, double hdg_deg, int turn) {
  SQUAWK_ASSIGN_OR_RETURN(const int i, lookup(acid));
  SQUAWK_RETURN_IF_ERROR(check_finite(traf_.id[i], "heading", hdg_deg));
  const Traffic& t = traf_;
  double trk = hdg_deg;
  if (wind_.dim() > 0 && t.alt[i] > kWindMinAlt) {
    const WindNE w = wind_.at(t.lat[i], t.lon[i], t.alt[i]);
    const double h = hdg_deg * kDeg;
    trk = std::atan2(t.tas[i] * std::sin(h) + w.east, t.tas[i] * std::cos(h) + w.north) / kDeg;
  }
  traf_.sel_hdg[i] = geo::wrap360(trk);
  traf_.sel_turn[i] = static_cast<int8_t>(turn > 0 ? 1 : turn < 0 ? -1 : 0);
  traf_.lnav[i] = traf_.vnav[i] = 0;
  return Status::ok();
}

Status Simulation::set_altitude(std::string_view acid, double alt_m, std::optional<double> vs) {
  SQUAWK_ASSIGN_OR_RETURN(const int i, lookup(acid));
  SQUAWK_RETURN_IF_ERROR(check_alt(traf_.id[i], alt_m));
  if (vs) SQUAWK_RETURN_IF_ERROR(check_positive(traf_.id[i], "vertical speed", std::fabs(*vs)));
  traf_.sel_alt[i] = alt_m;
  if (vs) traf_.sel_vs[i] = std::fabs(*vs);
  traf_.vnav[i] = 0;
  return Status::ok();
}

Status Simulation::set_vs(std::string_view acid, double vs) {
  SQUAWK_ASSIGN_OR_RETURN(const int i, lookup(acid));
  SQUAWK_RETURN_IF_ERROR(check_finite(traf_.id[i], "vertical speed", vs));
  traf_.sel_vs[i] = std::fabs(vs);
  traf_.vnav[i] = 0;
  return Status::ok();
}

Status Simulation::select_vertical(std::string_view acid, double alt_m, double vs) {
  SQUAWK_ASSIGN_OR_RETURN(const int i, lookup(acid));
  SQUAWK_RETURN_IF_ERROR(check_finite(traf_.id[i], "selected altitude", alt_m));
  SQUAWK_RETURN_IF_ERROR(check_finite(traf_.id[i], "vertical speed", vs));
  traf_.sel_alt[i] = alt_m;
  traf_.sel_vs[i] = std::fabs(vs);
  traf_.vnav[i] = 0;
  return Status::ok();
}

Status Simulation::set_speed(std::string_view acid, double casmach) {
  SQUAWK_ASSIGN_OR_RETURN(const int i, lookup(acid));
  SQUAWK_RETURN_IF_ERROR(check_speed(traf_.id[i], casmach));
  traf_.sel_spd[i] = casmach;
  traf_.vnav_spd[i] = 0;
  traf_.tgt_tas_alt[i] = std::nan("");
  return Status::ok();
}

Status Simulation::set_bank(std::string_view acid, double bank_deg) {
  SQUAWK_ASSIGN_OR_RETURN(const int i, lookup(acid));
  if (!std::isfinite(bank_deg) || bank_deg <= 0.0 || bank_deg >= 90.0)
    return bad(traf_.id[i], "bank angle " + num(bank_deg) + " deg is not in (0, 90) deg");
  traf_.bank[i] = bank_deg * kDeg;
  traf_.tan_bank[i] = std::tan(traf_.bank[i]);
  return Status::ok();
}

Status Simulation::set_lnav(std::string_view acid, bool on) {
  SQUAWK_ASSIGN_OR_RETURN(const int i, lookup(acid));
  if (on && traf_.route[i].active() < 0)
    return bad(traf_.id[i], "LNAV needs a route with a waypoint to fly to (add one with ADDWPT)");
  if (on && !traf_.lnav[i]) {
    traf_.lnav[i] = 1;
    start_leg(i, false);
  }
  traf_.lnav[i] = on;
  if (!on) traf_.vnav[i] = 0;
  return Status::ok();
}

Status Simulation::set_vnav(std::string_view acid, bool on) {
  SQUAWK_ASSIGN_OR_RETURN(const int i, lookup(acid));
  if (on && traf_.route[i].active() < 0)
    return bad(traf_.id[i], "VNAV needs a route with a waypoint to fly to (add one with ADDWPT)");
  traf_.vnav[i] = on;
  traf_.vnav_spd[i] = on;
  if (on) {
    traf_.lnav[i] = 1;
    const Route& r = traf_.route[i];
    const Route::AltTarget at = r.alt_target(r.active());
    compute_vnav(i, at.toalt >= 0.0 ? at.toalt : -999.0, at.xtoalt);
    traf_.nextaltco[i] = at.toalt == at.toalt ? at.toalt : -999.0;
  }
  return Status::ok();
}

// --- Routes -------------------------------------------------------------------

// Runs a route mutation; LNAV and VNAV go off when no active waypoint is
// left. With `direct` (waypoints added, as BlueSky's ADDWPT ends with a
// DIRECT to the active waypoint) LNAV goes on and the leg is restarted.
template <class Op>
Status Simulation::route_op(std::string_view acid, Op&& op, bool direct) {
  SQUAWK_ASSIGN_OR_RETURN(const int i, lookup(acid));
  Route& r = traf_.route[i];
  const Status st = op(r);
  if (!st.is_ok()) return st.with_context(traf_.id[i]);
  if (r.active() < 0) {
    traf_.lnav[i] = traf_.vnav[i] = 0;
  } else if (direct) {
    traf_.lnav[i] = 1;
    start_leg(i, false);
  }
  return Status::ok();
}

Status Simulation::add_waypoint(std::string_view acid, Waypoint wp) {
  return route_op(acid, [&](Route& r) { return r.add(std::move(wp)); }, true);
}
Status Simulation::add_waypoint_after(std::string_view acid, std::string_view ref, Waypoint wp) {
  return route_op(acid, [&](Route& r) { return r.insert_after(ref, std::move(wp)); }, true);
}
Status Simulation::add_waypoint_before(std::string_view acid, std::string_view ref, Waypoint wp) {
  return route_op(acid, [&](Route& r) { return r.insert_before(ref, std::move(wp)); }, true);
}
Status Simulation::set_flyover_mode(std::string_view acid, bool flyover) {
  SQUAWK_ASSIGN_OR_RETURN(const int i, lookup(acid));
  traf_.route[i].set_flyover_mode(flyover);
  return Status::ok();
}
Status Simulation::delete_waypoint(std::string_view acid, std::string_view name) {
  return route_op(acid, [&](Route& r) { return r.remove(name); });
}
Status Simulation::add_waypoint_command(std::string_view acid, std::string_view name,
                                        std::string line) {
  return route_op(acid, [&](Route& r) { return r.add_command(name, std::move(line)); });
}
Status Simulation::delete_route(std::string_view acid) {
  return route_op(acid, [](Route& r) {
    r.clear();
    return Status::ok();
  });
}
Status Simulation::direct_to(std::string_view acid, std::string_view name) {
  return route_op(acid, [&](Route& r) { return r.direct_to(name); }, true);
}
// BlueSky's DEST: the destination carries a 0 ft altitude constraint unless
// one is given; as the only waypoint it switches LNAV and VNAV on, so the
// aircraft descends to it on the VNAV path.
Status Simulation::set_dest(std::string_view acid, Waypoint dest) {
  SQUAWK_ASSIGN_OR_RETURN(const int i, lookup(acid));
  if (!dest.has_alt()) dest.alt = 0.0;
  const bool only = traf_.route[i].empty();
  SQUAWK_RETURN_IF_ERROR(route_op(acid, [&](Route& r) { return r.set_dest(std::move(dest)); }, true));
  if (only) {
    traf_.vnav[i] = 1;
    start_leg(i, false);
  }
  return Status::ok();
}
Status Simulation::set_orig(std::string_view acid, Waypoint orig) {
  return route_op(acid, [&](Route& r) { return r.set_orig(std::move(orig)); });
}

// --- Conflict detection and resolution ------------------------------------------

void Simulation::set_cd(bool on) {
  cds_.enabled = on;
  next_asas_t_ = simt();
  if (!on) {
    cd_.clear(false);
    cr_.clear();
    std::fill(traf_.cr_active.begin(), traf_.cr_active.end(), 0);
  }
}

Status Simulation::set_rpz(double rpz_m) { return assign_positive("ZONER", "radius [m]", rpz_m, cds_.rpz); }
Status Simulation::set_hpz(double hpz_m) { return assign_positive("ZONEDH", "half height [m]", hpz_m, cds_.hpz); }
Status Simulation::set_dtlook(double dtlook_s) {
  return assign_positive("DTLOOK", "look-ahead time [s]", dtlook_s, cds_.dtlook);
}
Status Simulation::set_asas_dt(double asas_dt_s) {
  SQUAWK_RETURN_IF_ERROR(assign_positive("ASAS", "update interval [s]", asas_dt_s, cds_.asas_dt));
  next_asas_t_ = simt();
  return Status::ok();
}

Status Simulation::set_cd_max_pairs(int64_t n) {
  if (n < 1) return Status::invalid("conflict pair cap " + std::to_string(n) + ": expected a count >= 1");
  cds_.max_pairs = n;
  return Status::ok();
}

void Simulation::set_reso(bool on) {
  crs_.enabled = on;
  if (on && !cds_.enabled) set_cd(true);
  if (!on) {
    cr_.clear();
    std::fill(traf_.cr_active.begin(), traf_.cr_active.end(), 0);
  }
}
Status Simulation::set_resofach(double f) {
  if (!std::isfinite(f) || f < 1.0) return bad("RFACH", "factor " + num(f) + " must be a number >= 1");
  crs_.resofach = f;
  return Status::ok();
}
Status Simulation::set_resofacv(double f) {
  if (!std::isfinite(f) || f < 1.0) return bad("RFACV", "factor " + num(f) + " must be a number >= 1");
  crs_.resofacv = f;
  return Status::ok();
}
void Simulation::set_reso_vertical(bool on) { crs_.vertical = on; }
void Simulation::set_reso_resume(bool on) { crs_.resume = on; }

Status Simulation::set_performance_options(const PerformanceOptions& o) {
  SQUAWK_RETURN_IF_ERROR(check_positive("PERF", "ground_alt", o.ground_alt));
  SQUAWK_RETURN_IF_ERROR(check_positive("PERF", "ground_vmax", o.ground_vmax));
  SQUAWK_RETURN_IF_ERROR(check_positive("PERF", "ground_axmax", o.ground_axmax));
  perf_opts_ = o;
  std::fill(traf_.tgt_tas_alt.begin(), traf_.tgt_tas_alt.end(), std::nan(""));
  return Status::ok();
}

}  // namespace squawk::sim
