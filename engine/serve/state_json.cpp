#include "serve/state_json.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/cpa.h"
#include "core/units.h"
#include "serve/fields_json.h"
#include "sim/atmosphere.h"
#include "sim/conflict.h"

namespace squawk::serve {

namespace {

using nlohmann::json;

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

// Whether (own, intruder) is the order a pair is reported in: own's id first.
bool first_of_pair(const sim::Traffic& t, int own, int intruder) {
  return t.id[static_cast<size_t>(own)] < t.id[static_cast<size_t>(intruder)];
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
  for (int i = 0; i < t.n(); ++i)
    aircraft.push_back(fields_json(sim::fields::kAircraft, sim::fields::AircraftRow{t, i}));
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
    if (!first_of_pair(t, c.own, c.intruder)) continue;  // each pair is reported in both orders
    json j = fields_json(sim::fields::kConflict, sim::fields::ConflictRow{t, c});
    j["cpa"] = cpa_points(t, static_cast<size_t>(c.own), static_cast<size_t>(c.intruder));
    conflicts.push_back(std::move(j));
  }
  out["conflicts"] = std::move(conflicts);
  json los = json::array();
  for (const auto& l : det.los())
    if (first_of_pair(t, l.own, l.intruder))
      los.push_back(fields_json(sim::fields::kLos, sim::fields::LosRow{t, l}));
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
