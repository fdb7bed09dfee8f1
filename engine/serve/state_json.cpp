#include "serve/state_json.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/cpa.h"
#include "core/units.h"
#include "sim/atmosphere.h"
#include "sim/conflict.h"

namespace squawk::serve {

namespace {

using nlohmann::json;

json nan_to_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json aircraft_json(const sim::Traffic& t, size_t i) {
  json a = {{"id", t.id[i]},
            {"type", t.type[i]},
            {"lat", t.lat[i]},
            {"lon", t.lon[i]},
            {"alt_ft", units::m_to_ft(t.alt[i])},
            {"hdg_deg", t.hdg[i]},
            {"trk_deg", t.trk[i]},
            {"cas_kt", units::ms_to_kt(t.cas[i])},
            {"tas_kt", units::ms_to_kt(t.tas[i])},
            {"gs_kt", units::ms_to_kt(t.gs[i])},
            {"vs_fpm", units::ms_to_fpm(t.vs[i])},
            {"sel_hdg_deg", t.sel_hdg[i]},
            {"sel_turn", t.sel_turn[i] < 0 ? json("LEFT") : t.sel_turn[i] > 0 ? json("RIGHT") : json(nullptr)},
            {"sel_alt_ft", units::m_to_ft(t.sel_alt[i])},
            {"lnav", t.lnav[i] != 0},
            {"vnav", t.vnav[i] != 0},
            {"resolving", t.cr_active[i] != 0}};
  if (sim::is_mach(t.sel_spd[i])) {
    a["sel_cas_kt"] = nullptr;
    a["sel_mach"] = t.sel_spd[i];
  } else {
    a["sel_cas_kt"] = units::ms_to_kt(t.sel_spd[i]);
  }
  const sim::Route& r = t.route[i];
  json route = json::array();
  for (const auto& w : r.waypoints())
    route.push_back({{"name", w.name}, {"lat", w.lat}, {"lon", w.lon},
                     {"alt_ft", w.has_alt() ? json(units::m_to_ft(w.alt)) : json(nullptr)}});
  a["route"] = std::move(route);
  a["active_wpt"] = r.active_waypoint() ? json(r.active_waypoint()->name) : json(nullptr);
  return a;
}

// Where aircraft a and b are at their closest approach if both keep their
// present ground velocity, from the present state (flat earth around the
// pair's mean latitude); the detector's tcpa may be up to asas_dt older.
json cpa_points(const sim::Traffic& t, size_t a, size_t b) {
  using units::kDeg, units::kREarth;
  const double coslat = std::cos(0.5 * (t.lat[a] + t.lat[b]) * kDeg);
  const cpa::Horizontal h = cpa::horizontal((t.lon[b] - t.lon[a]) * kDeg * kREarth * coslat,
                                            (t.lat[b] - t.lat[a]) * kDeg * kREarth,
                                            t.gseast[b] - t.gseast[a], t.gsnorth[b] - t.gsnorth[a], 0.0);
  // A pair with (almost) no relative velocity is at its closest now.
  const double tc = h.dv2 > 1e-6 ? std::max(0.0, h.tcpa) : 0.0;  // [s]
  auto at = [&](size_t i) {
    return json::array({t.lat[i] + t.gsnorth[i] * tc / kREarth / kDeg,
                        t.lon[i] + t.gseast[i] * tc / (kREarth * coslat) / kDeg});
  };
  return json::array({at(a), at(b)});
}

// The pair's ids in order (a < b) and its indices in that order.
std::pair<size_t, size_t> ordered(const sim::Traffic& t, int own, int intruder) {
  const auto a = static_cast<size_t>(own), b = static_cast<size_t>(intruder);
  return t.id[a] < t.id[b] ? std::pair{a, b} : std::pair{b, a};
}

}  // namespace

json state_json(const command::Stack& stack) {
  const sim::Simulation& s = stack.sim();
  const sim::Traffic& t = s.traffic();
  const auto& cd = s.cd_settings();
  json out = {{"simt", s.simt()},
              {"running", s.run_state() == sim::RunState::kOp},
              {"fast", s.fast()},
              {"dtmult", stack.dtmult()},
              {"asas",
               {{"on", cd.enabled},
                {"reso", s.cr_settings().enabled},
                {"rpz_nm", units::m_to_nm(cd.rpz)},
                {"hpz_ft", units::m_to_ft(cd.hpz)},
                {"dtlook_s", cd.dtlook}}}};
  const command::Trails& trails = stack.trails();
  out["trail"] = {{"on", trails.on}, {"dt_s", trails.dt}, {"colour", trails.colour}};
  json aircraft = json::array();
  for (int i = 0; i < t.n(); ++i) aircraft.push_back(aircraft_json(t, static_cast<size_t>(i)));
  out["aircraft"] = std::move(aircraft);

  // With the clock held the pairs are detected afresh on the present state:
  // the simulator's detector runs only as time moves, so at t = 0 of a paused
  // start, or after a command given in HOLD, its pairs are missing or stale.
  sim::ConflictDetector fresh;
  const bool held = s.run_state() == sim::RunState::kHold && !s.fast();
  if (held && cd.enabled) fresh.detect(t, cd);
  const sim::ConflictDetector& det = held && cd.enabled ? fresh : s.cd();
  json conflicts = json::array();
  for (const auto& c : det.pairs()) {
    const auto [a, b] = ordered(t, c.own, c.intruder);
    if (static_cast<size_t>(c.own) != a) continue;  // each pair is reported in both orders
    conflicts.push_back({{"ids", {t.id[a], t.id[b]}},
                         {"tcpa_s", c.tcpa},
                         {"dcpa_nm", units::m_to_nm(c.dcpa)},
                         {"tlos_s", nan_to_null(c.tlos)},
                         {"dist_nm", units::m_to_nm(c.dist)},
                         {"cpa", cpa_points(t, a, b)}});
  }
  out["conflicts"] = std::move(conflicts);
  json los = json::array();
  for (const auto& l : det.los()) {
    const auto [a, b] = ordered(t, l.own, l.intruder);
    if (static_cast<size_t>(l.own) != a) continue;
    los.push_back({{"ids", {t.id[a], t.id[b]}}, {"dist_nm", units::m_to_nm(l.dist)}, {"dalt_ft", units::m_to_ft(l.dalt)}});
  }
  std::string capped = sim::cap_notice(s.cd(), cd.max_pairs);
  if (capped.empty() && held && cd.enabled) capped = sim::cap_notice(fresh, cd.max_pairs);
  out["conflict_cap"] = capped;
  out["los"] = std::move(los);
  return out;
}

json navdata_json(const command::NavDb* db, const GeoBox& box, size_t limit, NavKinds kinds) {
  json out = {{"airports", json::array()}, {"navaids", json::array()}, {"fixes", json::array()}, {"truncated", false}};
  if (!db) return out;
  size_t n = 0;
  // Appends the points of `pts` in the box whose type `want` accepts.
  auto add = [&](const std::vector<command::NavPoint>& pts, json& list, auto want, bool with_type) {
    for (const auto& p : pts) {
      if (!want(p) || p.lat < box.lat0 || p.lat > box.lat1 || p.lon < box.lon0 || p.lon > box.lon1) continue;
      if (n == limit) {
        out["truncated"] = true;
        return;
      }
      list.push_back(with_type ? json::array({p.id, p.lat, p.lon, p.type}) : json::array({p.id, p.lat, p.lon}));
      ++n;
    }
  };
  const auto any = [](const command::NavPoint&) { return true; };
  const auto fix = [](const command::NavPoint& p) { return p.type == "FIX"; };
  const auto navaid = [](const command::NavPoint& p) { return p.type != "FIX"; };
  if (kinds.airports) add(db->airports(), out["airports"], any, false);
  if (kinds.navaids) add(db->waypoints(), out["navaids"], navaid, true);
  if (kinds.fixes) add(db->waypoints(), out["fixes"], fix, false);
  return out;
}

}  // namespace squawk::serve
