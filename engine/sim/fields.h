// The field lists of what crosses the C++ / Lua / JSON boundary: an aircraft
// (with its route's waypoints), a conflict pair and a loss-of-separation
// pair. Each list is declared once here; Lua's tables (script/bind_sim.cpp:
// sim:aircraft(), sim:get(), sim:conflicts(), sim:los()), serve's JSON
// (serve/state_json.cpp) and through them the scope (web/) and the
// translator's view of the traffic (scripts/translate) are built by walking
// it, so every field has the same name and unit everywhere. The other types
// that cross (command reply, step result, observation, advisory) have their
// lists in script/*_fields.h over this Field and Value; script/lua_fields.h
// and serve/fields_json.h are the one Lua and the one JSON walker.
//
// Contract: Traffic and the detector hold SI (m, m/s, s, deg); a getter
// converts to the unit its field's name ends in (the edge's aviation units:
// _ft, _kt, _fpm, _nm, _s, _deg; lat/lon [deg]; mach [-]). A value that does
// not apply is Absent: nil in Lua, null in JSON. Adding a field is one line
// in its list.
#pragma once

#include <cmath>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/units.h"
#include "sim/atmosphere.h"
#include "sim/conflict.h"
#include "sim/route.h"
#include "sim/traffic.h"

namespace squawk::sim::fields {

struct Absent {};
// One field's value: a number, a count (an integer in Lua and JSON), a flag,
// a text, a route (a list of waypoints, written with kWaypoint), a list of
// texts, a list of numbers or nothing.
using Value = std::variant<Absent, double, long long, bool, std::string_view, const Route*,
                           const std::vector<std::string>*, std::span<const double>>;

template <class Row>
struct Field {
  const char* name;  // the key in Lua tables and JSON objects
  const char* unit;  // the unit of the value ("" for texts, flags and lists)
  Value (*get)(const Row& row);
};

// An aircraft is a row of Traffic: (traffic, index).
struct AircraftRow {
  const Traffic& t;
  int i;
};
// A pair of the detector, with the traffic its indices point into.
struct ConflictRow {
  const Traffic& t;
  const ConflictPair& c;
};
struct LosRow {
  const Traffic& t;
  const LosPair& l;
};

inline Value finite_or_absent(double v) {
  return std::isfinite(v) ? Value(v) : Value(Absent{});
}

using A = AircraftRow;
// clang-format off
inline constexpr Field<A> kAircraft[] = {
    {"id", "", [](const A& r) -> Value { return std::string_view(r.t.id[r.i]); }},
    {"type", "", [](const A& r) -> Value { return std::string_view(r.t.type[r.i]); }},
    {"lat", "deg", [](const A& r) -> Value { return r.t.lat[r.i]; }},
    {"lon", "deg", [](const A& r) -> Value { return r.t.lon[r.i]; }},
    {"alt_ft", "ft", [](const A& r) -> Value { return units::m_to_ft(r.t.alt[r.i]); }},
    {"hdg_deg", "deg", [](const A& r) -> Value { return r.t.hdg[r.i]; }},
    {"trk_deg", "deg", [](const A& r) -> Value { return r.t.trk[r.i]; }},
    {"tas_kt", "kt", [](const A& r) -> Value { return units::ms_to_kt(r.t.tas[r.i]); }},
    {"cas_kt", "kt", [](const A& r) -> Value { return units::ms_to_kt(r.t.cas[r.i]); }},
    {"gs_kt", "kt", [](const A& r) -> Value { return units::ms_to_kt(r.t.gs[r.i]); }},
    {"mach", "", [](const A& r) -> Value { return r.t.mach[r.i]; }},
    {"vs_fpm", "fpm", [](const A& r) -> Value { return units::ms_to_fpm(r.t.vs[r.i]); }},
    // The performance model's ceiling (PerfLimits::hmax).
    {"ceiling_ft", "ft", [](const A& r) -> Value { return units::m_to_ft(r.t.perf[r.i].hmax); }},
    {"lnav", "", [](const A& r) -> Value { return r.t.lnav[r.i] != 0; }},
    {"vnav", "", [](const A& r) -> Value { return r.t.vnav[r.i] != 0; }},
    {"sel_hdg_deg", "deg", [](const A& r) -> Value { return r.t.sel_hdg[r.i]; }},
    // "LEFT" / "RIGHT" while a commanded turn direction holds.
    {"sel_turn", "", [](const A& r) -> Value {
       const int d = r.t.sel_turn[r.i];
       return d == 0 ? Value(Absent{}) : Value(std::string_view(d < 0 ? "LEFT" : "RIGHT")); }},
    {"sel_alt_ft", "ft", [](const A& r) -> Value { return units::m_to_ft(r.t.sel_alt[r.i]); }},
    // 0: the performance class's default rate.
    {"sel_vs_fpm", "fpm", [](const A& r) -> Value { return units::ms_to_fpm(r.t.sel_vs[r.i]); }},
    // The selected speed is a CAS or a Mach number: one of the two is absent.
    {"sel_cas_kt", "kt", [](const A& r) -> Value {
       const double s = r.t.sel_spd[r.i];
       return is_mach(s) ? Value(Absent{}) : Value(units::ms_to_kt(s)); }},
    {"sel_mach", "", [](const A& r) -> Value {
       const double s = r.t.sel_spd[r.i];
       return is_mach(s) ? Value(s) : Value(Absent{}); }},
    // Following a conflict resolution (MVP).
    {"resolving", "", [](const A& r) -> Value { return r.t.cr_active[r.i] != 0; }},
    {"route", "", [](const A& r) -> Value { return &r.t.route[r.i]; }},
    {"active_wpt", "", [](const A& r) -> Value {
       const Waypoint* w = r.t.route[r.i].active_waypoint();
       return w ? Value(std::string_view(w->name)) : Value(Absent{}); }},
    {"orig", "", [](const A& r) -> Value {
       const std::string& s = r.t.route[r.i].orig();
       return s.empty() ? Value(Absent{}) : Value(std::string_view(s)); }},
    {"dest", "", [](const A& r) -> Value {
       const std::string& s = r.t.route[r.i].dest();
       return s.empty() ? Value(Absent{}) : Value(std::string_view(s)); }},
};

using W = Waypoint;
inline constexpr Field<W> kWaypoint[] = {
    {"name", "", [](const W& w) -> Value { return std::string_view(w.name); }},
    {"lat", "deg", [](const W& w) -> Value { return w.lat; }},
    {"lon", "deg", [](const W& w) -> Value { return w.lon; }},
    {"alt_ft", "ft", [](const W& w) -> Value {
       return w.has_alt() ? Value(units::m_to_ft(w.alt)) : Value(Absent{}); }},
    // The speed constraint is a CAS or a Mach number (or none).
    {"cas_kt", "kt", [](const W& w) -> Value {
       return w.has_spd() && !is_mach(w.spd) ? Value(units::ms_to_kt(w.spd)) : Value(Absent{}); }},
    {"mach", "", [](const W& w) -> Value {
       return w.has_spd() && is_mach(w.spd) ? Value(w.spd) : Value(Absent{}); }},
    // The command lines run when the aircraft passes it (AT acid wp DO), in order.
    {"commands", "", [](const W& w) -> Value { return &w.commands; }},
};

using C = ConflictRow;
inline constexpr Field<C> kConflict[] = {
    {"own", "", [](const C& r) -> Value { return std::string_view(r.t.id[r.c.own]); }},
    {"intruder", "", [](const C& r) -> Value { return std::string_view(r.t.id[r.c.intruder]); }},
    {"tcpa_s", "s", [](const C& r) -> Value { return r.c.tcpa; }},
    {"tlos_s", "s", [](const C& r) -> Value { return finite_or_absent(r.c.tlos); }},
    {"dcpa_nm", "nm", [](const C& r) -> Value { return units::m_to_nm(r.c.dcpa); }},
    {"dist_nm", "nm", [](const C& r) -> Value { return units::m_to_nm(r.c.dist); }},
};

using L = LosRow;
inline constexpr Field<L> kLos[] = {
    {"own", "", [](const L& r) -> Value { return std::string_view(r.t.id[r.l.own]); }},
    {"intruder", "", [](const L& r) -> Value { return std::string_view(r.t.id[r.l.intruder]); }},
    {"dist_nm", "nm", [](const L& r) -> Value { return units::m_to_nm(r.l.dist); }},
    // Altitude of own minus the intruder's.
    {"dalt_ft", "ft", [](const L& r) -> Value { return units::m_to_ft(r.l.dalt); }},
};
// clang-format on

}  // namespace squawk::sim::fields
