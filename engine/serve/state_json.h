// JSON views of a live simulation for the radar scope and its HTTP API.
//
// state_json(stack) is the body of GET /api/state (and of each push-stream
// event), aviation units at this edge:
//   simt [s], running (bool), fast (bool), dtmult [-],
//   asas {on, reso, rpz_nm, hpz_ft, dtlook_s},
//   aircraft [sim/fields.h's kAircraft: {id, type, lat, lon [deg], alt_ft,
//              hdg_deg, ..., route [kWaypoint {name, lat, lon, alt_ft, ...}], ...}]
//              (a field that does not apply is null),
//   conflicts [kConflict {own, intruder, tcpa_s, tlos_s, dcpa_nm, dist_nm}
//              + cpa [[lat, lon], [lat, lon]]]  each pair once (own's id
//              before the intruder's), cpa = where each aircraft will be at
//              the closest approach if both keep their present ground
//              velocity (from the present state),
//   los [kLos {own, intruder, dist_nm, dalt_ft}]  each pair once,
//   conflict_cap  sim::cap_notice ("" unless detections hit the pair cap,
//               --max-conflict-pairs: then the lists above are incomplete).
// Conflicts and losses of separation are the simulator's last detection
// while the clock runs, and detected on the present state while it is held
// (so a paused start shows the predicted conflicts at t = 0).
// navdata_json(db, box, limit, kinds) lists the airports, navaids (VOR,
// NDB, DME, TACAN) and fixes inside the box that `kinds` asks for, at most
// `limit` of them (in that order): {airports: [[id, lat, lon]], navaids:
// [[id, lat, lon, type]], fixes: [[id, lat, lon]], truncated}.
#pragma once

#include <nlohmann/json.hpp>

#include "command/navdb.h"
#include "command/stack.h"

namespace squawk::serve {

nlohmann::json state_json(const command::Stack& stack);

struct GeoBox {
  double lat0 = -90, lat1 = 90;    // [deg] south, north
  double lon0 = -180, lon1 = 180;  // [deg] west, east
};
struct NavKinds {
  bool airports = true, navaids = true, fixes = true;
};
nlohmann::json navdata_json(const command::NavDb* db, const GeoBox& box, size_t limit, NavKinds kinds = {});

}  // namespace squawk::serve
