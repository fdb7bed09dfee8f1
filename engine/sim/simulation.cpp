// Simulation step: the clock, performance, autopilot (LNAV/VNAV), conflict
// detection and resolution, and kinematics (simulation.h); the snapshot.
#include "sim/simulation.h"

#include <algorithm>
#include <cmath>

#include "core/geo.h"
#include "core/text.h"
#include "core/units.h"
#include "core/vmath.h"
#include "sim/atmosphere.h"
#include "sim/byte_image.h"

namespace squawk::sim {

using units::kDeg;
using units::kREarth;

namespace {
constexpr double kTasEps = 1e-6;      // [m/s] floor of TAS in the turn rate
constexpr double kPerfDt = 1.0;       // [s] BlueSky's performance_dt
constexpr double kOnLegDeg = 2.0;        // [deg] track within this of the leg: on the leg
constexpr double kNoTurnSpd = -990.0;    // turn speed after a waypoint switch (none)
constexpr double kPassedTurnSpd = -998.0;  // turn speed once on the new leg (used up)

// Heading that flies track trk_deg at TAS tas in wind w (BlueSky's APorASAS).
double wind_heading(double trk_deg, double tas, const WindNE& w) {
  const double vw = std::hypot(w.north, w.east);
  const double drift = trk_deg * kDeg - std::atan2(w.east, w.north);
  const double steer = std::asin(std::clamp(vw * std::sin(drift) / std::max(0.001, tas), -1.0, 1.0));
  return geo::wrap360(trk_deg + steer / kDeg);
}
constexpr double kMinSelVs = 0.1;     // [m/s] a selected V/S at or below this means the default
constexpr double kVsAccel = 300.0 * units::kFpm;  // [m/s^2] V/S ramp, and the band within which it snaps
}  // namespace

Simulation::Simulation(uint64_t seed) : openap_(default_openap()), rng_(seed) {}

// --- Clock ------------------------------------------------------------------

int64_t Simulation::advance(double wall_s, int64_t max_steps) {
  if (run_state_ == RunState::kHold || max_steps <= 0) return 0;
  int64_t k = 0;
  if (ff_) {
    while (k < max_steps) {
      if (ff_end_ && simt() + 0.5 * dt_ > *ff_end_) {
        op();
        break;
      }
      step();
      ++k;
    }
    return k;
  }
  if (std::isfinite(wall_s) && wall_s > 0.0) wall_carry_ += wall_s;
  const int64_t due = static_cast<int64_t>(std::floor(wall_carry_ / dt_ + 1e-9));  // 1e-9: rounding of the carry
  k = std::min(due, max_steps);
  wall_carry_ = k < due ? 0.0 : wall_carry_ - static_cast<double>(k) * dt_;
  for (int64_t s = 0; s < k; ++s) step();
  return k;
}

// --- Step ---------------------------------------------------------------------

void Simulation::step() {
  passages_.clear();
  if (openap_ && simt() + 1e-9 >= next_perf_t_) {
    update_perf();
    next_perf_t_ += kPerfDt;
    if (next_perf_t_ <= simt()) next_perf_t_ = simt() + kPerfDt;
  }
  if (traf_.n() > 0) {
    update_autopilot();
    if (cds_.enabled && simt() + 1e-9 >= next_asas_t_) {
      update_asas();
      next_asas_t_ += cds_.asas_dt;
      if (next_asas_t_ <= simt()) next_asas_t_ = simt() + cds_.asas_dt;
    }
    update_kinematics();
  }
  if (simt() + 1e-9 >= next_area_t_) {
    if (area_active_) update_area();
    next_area_t_ += kPerfDt;
    if (next_area_t_ <= simt()) next_area_t_ = simt() + kPerfDt;
  }
  ++ticks_;
  ++ticks_since_base_;
}

void Simulation::update_asas() {
  if (cds_.all_pairs) cd_.detect_all_pairs(traf_, cds_);
  else cd_.detect(traf_, cds_);
  if (crs_.enabled) cr_.resolve(traf_, cd_, cds_, crs_, perf_opts_);
}

void Simulation::update_area() {
  Traffic& t = traf_;
  const Shape* area = shapes_.find(area_name_);
  for (int i = t.n() - 1; i >= 0; --i) {
    const bool in = area != nullptr && area->contains(t.lat[i], t.lon[i], t.alt[i]);
    const bool was = t.in_area[i] != 0;
    t.in_area[i] = in;
    if (was && !in) {
      cr_.on_erase(t.uid[i]);
      cd_.on_erase(i);
      t.erase(i);
    }
  }
}

void Simulation::select_speed(int i, double casmach) {
  if (traf_.sel_spd[i] == casmach) return;
  traf_.sel_spd[i] = casmach;
  traf_.tgt_tas_alt[i] = std::nan("");
}

void Simulation::update_perf() {
  Traffic& t = traf_;
  for (int i = 0; i < t.n(); ++i) {
    if (!t.oap[i]) continue;
    const double vmin = t.perf[i].vmin, vmax = t.perf[i].vmax;
    openap_update(*t.oap[i], t.tas[i], t.vs[i], t.alt[i], t.phase[i], t.perf[i]);
    if (t.perf[i].vmin != vmin || t.perf[i].vmax != vmax) t.tgt_tas_alt[i] = std::nan("");
  }
}

void Simulation::init_perf(int i) {
  Traffic& t = traf_;
  t.perf_class[i] = perf_class_of(t.type[i]);
  t.phase[i] = FlightPhase::kNA;
  if (openap_) {
    const OpenapType* o = openap_->find(t.type[i]);
    t.oap[i] = o;
    t.perf[i] = PerfLimits{o->vminer, o->vmaxer, -o->vsmax, o->vsmax, o->hmax, o->axmax0, o->mmo};
  } else {
    t.oap[i] = nullptr;
    t.perf[i] = perf_limits(t.perf_class[i]);
  }
  t.tgt_tas_alt[i] = std::nan("");
}

void Simulation::set_openap(std::shared_ptr<const OpenapData> data) {
  openap_ = std::move(data);
  next_perf_t_ = simt();
  for (int i = 0; i < traf_.n(); ++i) init_perf(i);
}

void Simulation::start_leg(int i, bool passing) {
  Traffic& t = traf_;
  const Route& r = t.route[i];
  const int a = r.active();
  if (a < 0) return;
  const Waypoint& wp = r.waypoints()[a];
  const geo::QdrDist qd = geo::qdrdist(t.lat[i], t.lon[i], wp.lat, wp.lon);
  t.wp_lat[i] = wp.lat;
  t.wp_lon[i] = wp.lon;
  t.curlegdir[i] = qd.qdr_deg;
  double next_qdr = qd.qdr_deg;
  if (a + 1 < r.size()) {
    const Waypoint& nx = r.waypoints()[a + 1];
    next_qdr = geo::qdrdist(wp.lat, wp.lon, nx.lat, nx.lon).qdr_deg;
  }
  const Route::AltTarget at = r.alt_target(a);
  const double toalt = at.toalt >= 0.0 ? at.toalt : -999.0;  // NaN (none) and negative: no constraint
  auto turn = [&] { t.turndist[i] = turn_distance(t.tas[i], t.bank[i], qd.qdr_deg, next_qdr, !wp.flyover); };
  if (passing) {
    turn();
    t.oldturnspd[i] = t.turnspd[i];
    t.turnspd[i] = kNoTurnSpd;
    // Speed constraints are "from" speeds: the one of the waypoint passed
    // holds on the new leg.
    t.leg_spd[i] = t.next_spd[i];
    t.next_spd[i] = wp.has_spd() ? wp.spd : -999.0;
    if (t.vnav_spd[i] && t.leg_spd[i] >= 0.0) select_speed(i, t.leg_spd[i]);
  } else {
    t.turnspd[i] = t.tas[i];
    double spd = wp.has_spd() ? wp.spd : -999.0;
    if (is_mach(spd)) spd = mach_to_cas(spd, wp.has_alt() ? wp.alt : t.alt[i]);
    t.next_spd[i] = spd;
  }
  t.nextaltco[i] = at.toalt == at.toalt ? at.toalt : -999.0;
  compute_vnav(i, toalt, at.xtoalt);
  if (!passing) turn();
}

// BlueSky's ComputeVNAV (simulation.h): descend from the top of
// descent on the 3000 ft / 10 NM path (now, over the rest of the leg, when
// already past it), climb at once at max(steepness * gs, what reaches the
// constraint in time).
void Simulation::compute_vnav(int i, double toalt, double xtoalt) {
  Traffic& t = traf_;
  if (toalt < 0.0 || !t.vnav[i]) {
    t.dist2vs[i] = -999999.0;
    return;
  }
  double d2wp = t.dist2wp[i];
  if (d2wp != d2wp) d2wp = units::nm_to_m(geo::qdrdist(t.lat[i], t.lon[i], t.wp_lat[i], t.wp_lon[i]).dist_nm);
  const double gs = std::max(0.01, t.gs[i]);
  if (t.alt[i] > toalt + 2.0 * units::kFt) {
    if (t.vs[i] > 0.0001) t.vnav_vs[i] = 0.0, t.sel_alt[i] = t.alt[i];
    t.nextaltco[i] = toalt;
    d2wp = units::nm_to_m(geo::kwikdist_nm(t.lat[i], t.lon[i], t.wp_lat[i], t.wp_lon[i]));
    t.dist2wp[i] = d2wp;
    const double descdist = (t.alt[i] - toalt) / kVnavSteepness;
    t.dist2vs[i] = descdist - xtoalt;
    if (d2wp - 1.02 * t.turndist[i] < t.dist2vs[i]) {
      t.wp_vs[i] = (t.alt[i] - toalt) / std::max(0.01, d2wp / gs);
    } else if (xtoalt < descdist) {
      t.wp_vs[i] = -kVnavSteepness * (t.gs[i] + (t.gs[i] < 0.2 * t.tas[i] ? t.tas[i] : 0.0));
    } else {
      t.wp_vs[i] = 0.0;
    }
  } else if (t.alt[i] < toalt - 9.9 * units::kFt) {
    if (t.vs[i] < -0.0001) t.vnav_vs[i] = 0.0, t.sel_alt[i] = t.alt[i];
    t.nextaltco[i] = toalt;
    t.dist2vs[i] = 99999.0;
    const double t2go = std::max(0.1, d2wp + xtoalt) / gs;
    t.wp_vs[i] = std::max(kVnavSteepness * t.gs[i], (toalt - t.alt[i]) / t2go);
  } else {
    t.dist2vs[i] = -999.0;
  }
}

const geo::LatTrig& Simulation::wp_trig(int i, double lat_deg) {
  geo::LatTrig& c = traf_.wp_trig[i];
  if (c.rad != lat_deg * kDeg) c = geo::lat_trig(lat_deg);
  return c;
}

// LNAV: fly to the active waypoint (WGS-84 bearing), switch at passage
// (route.h). VNAV: between waypoints, fly wp_vs to the next altitude
// constraint once past the top of descent (or at once when climbing).
// Passing a waypoint with a speed constraint selects it.
void Simulation::update_autopilot() {
  Traffic& t = traf_;
  const int n = t.n();
  // qdrdist to the active waypoint for every aircraft at once (vectorised
  // trigonometry, geo::qdrdist_n); aircraft without one get their own position.
  ApScratch& s = ap_;
  for (auto* v : {&s.la, &s.lb, &s.sb, &s.cb, &s.lonb, &s.qdr_deg, &s.dist_nm}) v->resize(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    s.la[i] = t.lat[i] * kDeg;
    const Waypoint* wp = t.lnav[i] ? t.route[i].active_waypoint() : nullptr;
    const geo::LatTrig b = wp ? wp_trig(i, wp->lat) : geo::LatTrig{s.la[i], t.sinlat[i], t.coslat[i]};
    s.lb[i] = b.rad, s.sb[i] = b.sin, s.cb[i] = b.cos;
    s.lonb[i] = wp ? wp->lon : t.lon[i];
  }
  geo::qdrdist_n({s.la.data(), t.sinlat.data(), t.coslat.data(), t.lon.data(), s.lb.data(), s.sb.data(), s.cb.data(),
                  s.lonb.data(), s.qdr_deg.data(), s.dist_nm.data()},
                 n);
  for (int i = 0; i < n; ++i) {
    t.vnav_vs_on[i] = 0;
    if (!t.lnav[i]) {
      if (t.dist2wp[i] == -999.0) t.dist2wp[i] = std::nan("");
      continue;
    }
    Route& r = t.route[i];
    const Waypoint* wp = r.active_waypoint();
    if (!wp) {
      t.lnav[i] = t.vnav[i] = 0;
      continue;
    }
    geo::QdrDist qd{s.qdr_deg[i], s.dist_nm[i]};
    t.dist2wp[i] = units::nm_to_m(qd.dist_nm);
    if (waypoint_reached(t.dist2wp[i], qd.qdr_deg, t.curlegdir[i], t.trk[i], t.gs[i], t.turndist[i])) {
      if (!wp->commands.empty()) passages_.push_back({t.id[i], wp->name, wp->commands});
      if (!r.advance()) {
        t.lnav[i] = t.vnav[i] = 0;
        continue;
      }
      wp = r.active_waypoint();
      const geo::LatTrig here{s.la[i], t.sinlat[i], t.coslat[i]};
      qd = geo::qdrdist(here, t.lon[i], wp_trig(i, wp->lat), wp->lon);
      t.dist2wp[i] = units::nm_to_m(qd.dist_nm);
      start_leg(i, true);
    }
    t.sel_hdg[i] = qd.qdr_deg;
    t.sel_turn[i] = 0;
    // VNAV speed: reach the active waypoint's constraint there (start when
    // the distance to it is what the speed change takes at axmax), else
    // hold the leg's constraint.
    if (t.vnav_spd[i] && t.vnav[i]) {
      bool use_next = false;
      if (t.next_spd[i] > -990.0) {
        const double v1 = casormach_to_tas(t.next_spd[i], t.alt[i]), v0 = t.tas[i];
        use_next = t.dist2wp[i] < 0.5 * std::fabs(v1 * v1 - v0 * v0) / std::max(0.001, t.perf[i].axmax);
      }
      if (use_next) select_speed(i, t.next_spd[i]);
      else if (t.leg_spd[i] >= 0.0) select_speed(i, t.leg_spd[i]);
    }
    // Turning onto the new leg after a switch, VNAV speed mode selects the
    // stored turn speed (BlueSky keeps it as the selected speed afterwards).
    if (t.oldturnspd[i] > 0.0) {
      if (std::fabs(geo::wrap180(t.trk[i] - qd.qdr_deg)) < kOnLegDeg) {
        t.oldturnspd[i] = kPassedTurnSpd;
      } else if (t.vnav_spd[i] && t.vnav[i]) {
        select_speed(i, t.oldturnspd[i]);
      }
    }
    if (t.vnav[i]) {
      const double co = t.nextaltco[i];
      if (co >= -0.1 && ((t.alt[i] > co && t.dist2wp[i] < t.dist2vs[i] + t.turndist[i]) || t.alt[i] < co)) {
        t.vnav_vs_on[i] = 1;
        t.vnav_vs[i] = t.wp_vs[i];
        t.sel_alt[i] = co;
      }
    }
  }
}

void Simulation::refresh_speed_outputs(int i, const Atmos& a) {
  traf_.cas[i] = tas_to_cas(traf_.tas[i], a);
  traf_.mach[i] = traf_.tas[i] / speed_of_sound(a);
}

// Selected speed -> TAS target, limited to [vmin, vmax] CAS (ground cap
// included), at the aircraft's current altitude (class model).
void Simulation::retarget(int i, const Atmos& a) {
  Traffic& t = traf_;
  double vmax = t.perf[i].vmax;
  if (perf_opts_.ground_cap && t.alt[i] <= perf_opts_.ground_alt) vmax = std::min(vmax, perf_opts_.ground_vmax);
  const double spd = t.sel_spd[i];
  double cas = spd;
  if (is_mach(spd)) {
    const double tas = spd * speed_of_sound(a);
    cas = tas_to_cas(tas, a);
    if (cas >= t.perf[i].vmin && cas <= vmax) {
      t.tgt_tas[i] = tas;
      t.tgt_tas_alt[i] = t.alt[i];
      return;
    }
  }
  t.tgt_tas[i] = cas_to_tas(std::clamp(cas, t.perf[i].vmin, vmax), a);
  t.tgt_tas_alt[i] = t.alt[i];
}

void Simulation::set_lat_cache(int i) {
  const double r = traf_.lat[i] * kDeg;
  traf_.coslat[i] = std::cos(r);
  traf_.sinlat[i] = std::sin(r);
}

void Simulation::set_heading_cache(int i) {
  const double h = traf_.hdg[i] * kDeg;
  traf_.sin_hdg[i] = std::sin(h);
  traf_.cos_hdg[i] = std::cos(h);
}

void Simulation::update_kinematics() {
  Traffic& t = traf_;
  const int n = t.n();
  const double dt = dt_;
  const bool windy = wind_.dim() > 0;
  for (int i = 0; i < n; ++i) {
    const bool cr = t.cr_active[i] != 0;
    const bool cr_vert = cr && crs_.vertical;
    const PerfLimits& lim = t.perf[i];
    const OpenapType* oap = t.oap[i];

    // Targets (APorASAS), then the performance limits.
    const double alt_t = std::min(cr_vert ? t.cr_alt[i] : t.sel_alt[i], lim.hmax);
    double vs_t = cr_vert                ? std::fabs(t.cr_vs[i])
                  : t.vnav_vs_on[i]      ? std::fabs(t.vnav_vs[i])
                  : t.sel_vs[i] > kMinSelVs ? t.sel_vs[i]
                                         : kDefaultVs;
    const WindNE w = windy ? wind_.at(t.lat[i], t.lon[i], t.alt[i]) : WindNE{};
    double cr_tas = cr ? t.cr_tas[i] : 0.0;
    if (cr && windy) {
      const double c = t.cr_trk[i] * kDeg;
      cr_tas = std::hypot(cr_tas * std::cos(c) - w.north, cr_tas * std::sin(c) - w.east);
    }
    double tas_t, axmax;
    if (oap) {
      if (cr) {
        tas_t = openap_limit_tas(lim, cr_tas, alt_t);
      } else {
        // Cached while altitude, target altitude, selected speed and envelope stay.
        if (!(t.tgt_tas_alt[i] == t.alt[i] && t.tgt_tas_sel[i] == alt_t)) {
          t.tgt_tas[i] = openap_limit_tas(lim, casormach_to_tas(t.sel_spd[i], t.alt[i]), alt_t);
          t.tgt_tas_alt[i] = t.alt[i];
          t.tgt_tas_sel[i] = alt_t;
        }
        tas_t = t.tgt_tas[i];
      }
      vs_t = openap_limit_vs(*oap, lim, t.phase[i], vs_t, t.ax[i], t.tas[i]);
      axmax = lim.axmax;
    } else {
      const bool ground = perf_opts_.ground_cap && t.alt[i] <= perf_opts_.ground_alt;
      axmax = ground ? perf_opts_.ground_axmax : lim.axmax;
      if (!(t.tgt_tas_alt[i] == t.alt[i])) retarget(i, isa(t.alt[i]));
      tas_t = cr ? cr_tas : t.tgt_tas[i];
      vs_t = std::min(vs_t, alt_t > t.alt[i] ? lim.vsmax : -lim.vsmin);
    }

    // Airspeed: +-axmax, snapping to the target within one step.
    const double old_tas = t.tas[i], old_alt = t.alt[i];
    const double dspd = tas_t - t.tas[i];
    if (std::fabs(dspd) > axmax * dt) {
      t.ax[i] = std::copysign(axmax, dspd);
      t.tas[i] += t.ax[i] * dt;
    } else {
      t.ax[i] = 0.0;
      t.tas[i] = tas_t;
    }

    // Heading: turn rate g0 tan(bank) / TAS, snapping within one step.
    double hdg_t = cr ? t.cr_trk[i] : t.sel_hdg[i];
    if (windy) hdg_t = wind_heading(hdg_t, t.tas[i], w);
    if (t.hdg[i] != hdg_t) {
      const double rate = t.tan_bank[i] * units::kG0 / std::max(t.tas[i], kTasEps) / kDeg;  // [deg/s]
      double dh = geo::wrap180(hdg_t - t.hdg[i]);
      // a commanded direction (HDG ... LEFT/RIGHT) goes the long way round when it must
      const int turn = cr ? 0 : t.sel_turn[i];
      if (turn > 0 && dh < 0.0) dh += 360.0;
      if (turn < 0 && dh > 0.0) dh -= 360.0;
      const double lim_h = rate * dt;
      const bool captured = std::fabs(dh) <= lim_h;
      t.hdg[i] = captured ? hdg_t : geo::wrap360(t.hdg[i] + std::copysign(lim_h, dh));
      if (captured) t.sel_turn[i] = 0;
    } else if (t.sel_turn[i] != 0) {
      t.sel_turn[i] = 0;
    }

    // Vertical: altitude select with a time-based capture band, V/S ramp.
    const double dalt = alt_t - t.alt[i];
    if (dalt != 0.0 || t.vs[i] != 0.0) {
      const bool sel = std::fabs(dalt) > 1.05 * std::max(std::fabs(dt * vs_t), std::fabs(dt * t.vs[i]));
      const double target_vs = sel ? std::copysign(vs_t, dalt) : 0.0;
      const double dvs = target_vs - t.vs[i];
      t.vs[i] = std::fabs(dvs) > kVsAccel ? t.vs[i] + std::copysign(kVsAccel, dvs) * dt : target_vs;
      t.alt[i] = sel ? std::nearbyint((t.alt[i] + t.vs[i] * dt) * 1e6) / 1e6 : alt_t;
    }
    if (t.alt[i] != old_alt) {
      const Atmos a = isa(t.alt[i]);
      if (!oap) retarget(i, a);
      refresh_speed_outputs(i, a);
    } else if (t.tas[i] != old_tas) {
      refresh_speed_outputs(i, isa(t.alt[i]));
    }
  }

  // Heading trigonometry of every aircraft, vectorised (vmath.h).
  vmath::sin(t.hdg.data(), kDeg, t.sin_hdg.data(), n);
  vmath::cos(t.hdg.data(), kDeg, t.cos_hdg.data(), n);

  // Ground speed (wind above 50 ft) and flat-earth position update: latitude,
  // its trigonometry (vectorised), then longitude.
  for (int i = 0; i < n; ++i) {
    t.gsnorth[i] = t.tas[i] * t.cos_hdg[i];
    t.gseast[i] = t.tas[i] * t.sin_hdg[i];
    if (windy && t.alt[i] > kWindMinAlt) {
      const WindNE wn = wind_.at(t.lat[i], t.lon[i], t.alt[i]);
      t.gsnorth[i] += wn.north;
      t.gseast[i] += wn.east;
      t.gs[i] = std::hypot(t.gsnorth[i], t.gseast[i]);
      t.trk[i] = geo::wrap360(std::atan2(t.gseast[i], t.gsnorth[i]) / kDeg);
    } else {
      t.gs[i] = t.tas[i];
      t.trk[i] = t.hdg[i];
    }
    t.lat[i] += dt * t.gsnorth[i] / kREarth / kDeg;
  }
  vmath::sin(t.lat.data(), kDeg, t.sinlat.data(), n);
  vmath::cos(t.lat.data(), kDeg, t.coslat.data(), n);
  for (int i = 0; i < n; ++i) {
    double lon = t.lon[i] + dt * t.gseast[i] / t.coslat[i] / kREarth / kDeg;
    if (lon >= 180.0) lon -= 360.0;
    else if (lon < -180.0) lon += 360.0;
    t.lon[i] = lon;
  }
}

// --- Snapshot -------------------------------------------------------------------

std::string Simulation::snapshot() const {
  using bytes::put;
  using bytes::put_vec;
  std::string out;
  put(out, dt_), put(out, t_base_), put(out, ticks_since_base_), put(out, ticks_), put(out, next_asas_t_);
  put<int32_t>(out, static_cast<int32_t>(run_state_));
  put<uint8_t>(out, ff_), put<uint8_t>(out, ff_end_.has_value()), put(out, ff_end_.value_or(0.0));
  put<uint8_t>(out, cds_.enabled), put(out, cds_.rpz), put(out, cds_.hpz), put(out, cds_.dtlook);
  put(out, cds_.asas_dt);
  put<uint8_t>(out, crs_.enabled), put(out, crs_.resofach), put(out, crs_.resofacv);
  put<uint8_t>(out, crs_.vertical), put<uint8_t>(out, crs_.resume);
  put<uint8_t>(out, perf_opts_.ground_cap), put(out, perf_opts_.ground_alt);
  put(out, perf_opts_.ground_vmax), put(out, perf_opts_.ground_axmax);
  put(out, next_uid_);
  put(out, next_perf_t_);
  put(out, next_area_t_);
  put<uint8_t>(out, area_active_);
  bytes::put_str(out, area_name_);
  shapes_.put(out);
  bytes::put_str(out, openap_ ? openap_->dir() : std::string());
  Rng probe = rng_;  // the RNG state, observed through its next draws
  for (int k = 0; k < 4; ++k) put(out, probe.next_u64());
  put(out, probe.normal());

  const Traffic& t = traf_;
  put<int64_t>(out, t.n());
  for (int i = 0; i < t.n(); ++i) {
    bytes::put_str(out, t.id[i]);
    bytes::put_str(out, t.type[i]);
    t.route[i].serialize(out);
    put<int32_t>(out, static_cast<int32_t>(t.perf_class[i]));
    const PerfLimits& p = t.perf[i];
    put(out, p.vmin), put(out, p.vmax), put(out, p.vsmin), put(out, p.vsmax), put(out, p.hmax), put(out, p.axmax);
    put(out, p.mmo);
    bytes::put_str(out, t.oap[i] ? t.oap[i]->name : std::string());
    put<uint8_t>(out, static_cast<uint8_t>(t.phase[i]));
  }
  put_vec(out, t.uid);
  for (const auto* v : {&t.lat, &t.lon, &t.alt, &t.hdg, &t.trk, &t.tas, &t.cas, &t.gs, &t.mach, &t.gsnorth,
                        &t.gseast, &t.vs, &t.sel_hdg, &t.sel_alt, &t.sel_spd, &t.sel_vs, &t.bank, &t.cr_trk,
                        &t.cr_tas, &t.cr_vs, &t.cr_alt, &t.ax, &t.wp_lat, &t.wp_lon, &t.dist2wp,
                        &t.nextaltco, &t.dist2vs, &t.wp_vs, &t.vnav_vs, &t.turndist, &t.curlegdir, &t.turnspd,
                        &t.oldturnspd, &t.leg_spd, &t.next_spd})
    put_vec(out, *v);
  put_vec(out, t.lnav), put_vec(out, t.vnav), put_vec(out, t.cr_active), put_vec(out, t.vnav_spd);
  put_vec(out, t.in_area), put_vec(out, t.sel_turn);
  cd_.serialize(out);
  cr_.serialize(out);
  wind_.serialize(out);
  return out;
}

}  // namespace squawk::sim
