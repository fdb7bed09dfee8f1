// squawk.sim: a simulation driven by TrafScript, from Lua.
//
//   squawk.sim.new([{seed = 0, navdata = dir}]) -> sim
//       navdata defaults to the VM's --navdata / $SQUAWK_NAVDATA (none: named
//       places are errors). Scenario files load relative to the script folder.
//   sim:exec(line)       -> ok, message   (TrafScript; `;` separates commands)
//   sim:check(line)      -> ok, message   (parse-only validation, nothing runs)
//   sim:airports_named(name [, lat, lon, within_nm]) -> { "EHAM", ... }  airports of the navdata
//                           whose name is `name` or starts with its words, within within_nm of
//                           lat, lon [deg] when given ({} without navdata)
//   sim:airports_of_city(name [, lat, lon, within_nm]) -> { "EDDF", ... }  large airports whose
//                           name starts with the words of `name` and goes on ("Frankfurt")
//   sim:airports_with_words(words [, lat, lon, within_nm]) -> { "KMDW", ... }  airports whose name
//                           holds the words of `words` among others ("Midway": CHICAGO MIDWAY INTL)
//   sim:airports_beside_navaids(name [, lat, lon, within_nm]) -> { "LFBO", ... }  the large (else
//                           medium) airports within 10 nm of a navaid called `name` ("Toulouse")
//   sim:airport_class(id) -> "LARGE" | "MEDIUM" | "SMALL" | ""  airports.dat's class
//   sim:navaids_named(name, lat, lon, within_nm [, types]) -> { "SFO", ... }, { {lat, lon}, ... }
//                           idents of the navaids called `name` within within_nm of lat, lon [deg],
//                           nearest first, and their positions [deg]; of the navdata types in
//                           `types` ("VOR TACAN") only, when given
//   sim:navaids_with_words(words, lat, lon, within_nm [, types]) -> the same for the navaids whose
//                           name holds `words` as a run of whole words ("rockford": RFD
//                           "CHICAGO/ROCKFORD")
//   sim:airports_coded(code, lat, lon) -> { "KJFK", ... }  airports whose ICAO code is one letter
//                           before the three-letter `code` within 10 nm of the navaid or fix `code`
//                           nearest lat, lon [deg] (the airport people name by the code of its
//                           VOR: JFK -> KJFK)
//   sim:airports_beside(ident, lat, lon, within_nm) -> { "LFML", ... }  airports within
//                           within_nm of the navaid or fix `ident` nearest lat, lon [deg], nearest
//                           first ({} without it: the airport a navaid named after a city is on)
//   sim:waypoints_at(lat, lon) -> { "5420N", "54N20", ... }  names of the waypoints defined
//   (DEFWPT),
//                           then of the fixes and navaids, at exactly lat, lon [deg] (the named
//                           points of a position said in degrees: NAT points, a scenario's own)
//   sim:reference()      -> lat, lon [deg]  the reference position the next command starts from
//                           (command/args.h: a navaid or fix name is the one nearest it)
//   sim:locate(text [, lat, lon]) -> lat, lon [deg], or nil, message: where a position argument
//                           `text` ("LAM", "EHAM", "52 4", an aircraft) resolves from the
//                           reference, or from lat, lon when given; nothing changes
//   sim:load(file)       -> ok, message   (IC: reset, then the .scn file; PCALLs
//                                          in it are found from its folder)
//   sim:step([n = 1])                     (n steps: due commands, dynamics, conditions)
//   sim:run_until(t) / sim:run_for(s)     [s]
//   sim:time() -> s;  sim:dt() -> s;  sim:count() -> number of aircraft
//   sim:aircraft()       -> { aircraft, ... }: each a table of sim/fields.h's
//                           kAircraft (id, type, lat, lon, alt_ft, ..., route = {
//                           kWaypoint tables }, ...); fields that do not apply are nil
//   sim:get(acid)        -> one such table, or nil
//   sim:conflicts()      -> { kConflict tables {own=, intruder=, tcpa_s=, tlos_s=, dcpa_nm=,
//                           dist_nm=}, ... }  (each pair in both orders)
//   sim:los()            -> { kLos tables {own=, intruder=, dist_nm=, dalt_ft=}, ... }
//   sim:totals()         -> {conflicts=, los=, capped=}  (pairs entered since reset;
//                           capped: sim::cap_notice when detections hit the cap)
//   sim:output()         -> { line, ... }     (ECHO / queued failures since last call)
//   sim:tally()          -> {executed=, skipped=, failed=, first_failures={...},
//                            failed_by_reason={[reason]=n}}  (scenario commands since IC)
//   sim:run_state()      -> "hold" | "op" | "ff", ff_end [s] or nil
//   sim:dtmult()         -> the DTMULT real-time multiplier
//   Kernels for environments (SI units, no TrafScript text; envs/*.lua):
//   sim:create{id=, type=, lat=, lon=, hdg_deg= 0, alt_m= 0, spd=}  (BlueSky's
//                           traf.cre: spd is CAS [m/s], or Mach when < 2)
//   sim:creconfs{id=, type=, target=, dpsi_deg=, dcpa_m=, tlosh_s=, dh_m=?, tlosv_s=?, spd=?}
//                           (BlueSky's traf.creconfs: an intruder in conflict with target)
//   sim:select_vertical(acid, alt_m, vs_ms)   (the autopilot's selected altitude and
//                           vertical speed, as BlueSky-Gym writes traf.selalt/selvs)
//   sim:values(acid)     -> lat, lon, alt_m, hdg_deg, tas_ms, gs_ms, vs_ms, cas_ms
//                           (several results, no table; errors on an unknown acid)
//   sim:delete_all()                       (every aircraft goes; clock and settings stay)
//   sim:copy()           -> an independent copy
//   sim:snapshot()       -> string            (the full state as bytes)
//   squawk.sim.commands() -> { {name=, aliases={...}, args=, usage=, help=}, ... }
//   squawk.sim.types() -> { {designator=, title= (OpenAP's name, "Boeing 777-300ER"; nil
//       for synonyms and the class model), model = "openap"|"class", class=, vmax_kt= (the
//       class model's CAS limit [kt]; nil for OpenAP)}, ... }: the OpenAP data of
//       $SQUAWK_OPENAP / --openap, then the class model's named designators
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "command/conformance.h"
#include "command/line.h"
#include "command/registry.h"
#include "command/stack.h"
#include "core/geo.h"
#include "core/paths.h"
#include "core/text.h"
#include "core/units.h"
#include "script/bindings.h"
#include "script/lua_fields.h"
#include "script/lua_util.h"
#include "script/vm.h"
#include "sim/atmosphere.h"
#include "sim/fields.h"
#include "sim/openap_data.h"
#include "sim/performance.h"

namespace squawk::script {

namespace {

constexpr const char* kSimMt = "squawk.sim.Sim";

command::Stack* self(lua_State* L) { return arg_object<command::Stack>(L, 1, kSimMt); }

// The folder of the running script (for IC / PCALL names), else ".".
std::string script_dir(lua_State* L) {
  lua_Debug ar;
  if (lua_getstack(L, 1, &ar) && lua_getinfo(L, "S", &ar) && ar.source[0] == '@')
    return paths::dirname(ar.source + 1);
  return ".";
}

int push_outcome(lua_State* L, const Result<std::string>& r) {
  lua_pushboolean(L, r.is_ok());
  const std::string& msg = r.is_ok() ? r.value() : r.status().message();
  lua_pushlstring(L, msg.data(), msg.size());
  return 2;
}

void push_aircraft(lua_State* L, const sim::Traffic& t, int i) {
  push_fields(L, sim::fields::kAircraft, sim::fields::AircraftRow{t, i});
}

constexpr long long kMaxSteps = 1'000'000'000;  // per step call
constexpr long long kSlice = 100;                // steps between budget charges

// [instructions] charged per simulation step: the work grows with the traffic.
long long step_cost(const command::Stack& s) { return 10 + 10LL * s.sim().n(); }

// Stack::run_until(t_end) in slices of kSlice steps, each charged to the budget.
void run_charged(lua_State* L, command::Stack& s, double t_end) {
  if (!std::isfinite(t_end)) throw ArgError("time " + std::to_string(t_end) + " s is not finite");
  while (s.sim().simt() + 0.5 * s.sim().dt() <= t_end) {
    charge(L, kSlice * step_cost(s));
    const double before = s.sim().simt();
    check_status(s.run_until(std::min(t_end, before + kSlice * s.sim().dt())));
    if (s.sim().simt() == before) break;  // the slice is below the clock's resolution
  }
  check_status(s.run_until(t_end));
}

int l_new(lua_State* L) {
  const bool opts = lua_istable(L, 1);
  if (!opts && !lua_isnoneornil(L, 1)) throw ArgError(type_error(L, 1, "options", "table or nil"));
  // Whole numbers a double holds exactly (NaN and fractions refused).
  const long long seed = opts ? field_count(L, 1, "seed", 0, 0, 1LL << 53) : 0;
  std::string nav = Vm::of(L).options().navdata_dir;
  if (opts) nav = field_string(L, 1, "navdata", nav);
  std::shared_ptr<const command::NavDb> db;
  if (!nav.empty()) {
    check_status(Vm::of(L).rules().check_read_folder(nav, "squawk.sim.new{navdata}"));
    auto loaded = command::NavDb::load_cached(nav);
    check_status(loaded.status());
    db = *loaded;
  }
  const std::string dir = script_dir(L);
  command::Stack* s = new_object<command::Stack>(L, kSimMt, static_cast<uint64_t>(seed));
  s->set_navdb(std::move(db));
  s->set_base_dir(dir);
  s->set_path_rules(&Vm::of(L).rules());  // the Vm outlives the sim (its userdata dies with the state)
  check_status(s->sim().set_cd_max_pairs(Vm::of(L).options().max_conflict_pairs));
  // dt_s [s]: the simulation step, as TrafScript's DT (default 0.05)
  if (opts) check_status(s->sim().set_dt(field_number(L, 1, "dt_s", s->sim().dt())));
  return 1;
}

int l_exec(lua_State* L) {
  command::Stack* s = self(L);
  return push_outcome(L, s->exec(arg_string(L, 2, "line")));
}

enum class AirportsBy { kName, kCity, kNavaid, kWords };

// airports_named, airports_of_city, airports_beside_navaids or airports_with_words (by): ids, near
// lat/lon when given
int push_airports(lua_State* L, AirportsBy by) {
  command::Stack* s = self(L);
  const std::string name = arg_string(L, 2, "name");
  const bool near = !lua_isnoneornil(L, 3);
  const double lat = near ? arg_number(L, 3, "lat") : 0.0,
               lon = near ? arg_number(L, 4, "lon") : 0.0;
  const double within = near ? arg_number(L, 5, "within_nm") : 0.0;
  lua_newtable(L);
  if (!s->navdb()) return 1;
  int k = 0;
  const command::NavDb& db = *s->navdb();
  for (const command::NavPoint* a : by == AirportsBy::kCity     ? db.airports_of_city(name)
                                    : by == AirportsBy::kNavaid ? db.airports_beside_navaids(name)
                                    : by == AirportsBy::kWords  ? db.airports_with_words(name)
                                                                : db.airports_named(name)) {
    if (near && geo::kwikdist_nm(lat, lon, a->lat, a->lon) > within) continue;
    lua_pushstring(L, a->id.c_str());
    lua_rawseti(L, -2, ++k);
  }
  return 1;
}

int l_airports_named(lua_State* L) {
  return push_airports(L, AirportsBy::kName);
}
int l_airports_of_city(lua_State* L) {
  return push_airports(L, AirportsBy::kCity);
}
int l_airports_beside_navaids(lua_State* L) {
  return push_airports(L, AirportsBy::kNavaid);
}
int l_airports_with_words(lua_State* L) {
  return push_airports(L, AirportsBy::kWords);
}

int l_airport_class(lua_State* L) {
  command::Stack* s = self(L);
  const std::string id = text::upper(arg_string(L, 2, "id"));
  lua_pushstring(L, s->navdb() ? s->navdb()->airport_class(id).c_str() : "");
  return 1;
}

int l_airports_coded(lua_State* L) {
  command::Stack* s = self(L);
  const std::string code = text::upper(arg_string(L, 2, "code"));
  const double lat = arg_number(L, 3, "lat"), lon = arg_number(L, 4, "lon");
  lua_newtable(L);
  if (!s->navdb() || code.size() != 3) return 1;
  const command::NavPoint* w = s->navdb()->waypoint(code, lat, lon);
  if (!w) return 1;
  int k = 0;
  for (char c = 'A'; c <= 'Z'; ++c) {
    const command::NavPoint* a = s->navdb()->airport(std::string(1, c) + code);
    if (!a || geo::kwikdist_nm(a->lat, a->lon, w->lat, w->lon) > 10.0) continue;
    lua_pushstring(L, a->id.c_str());
    lua_rawseti(L, -2, ++k);
  }
  return 1;
}

int l_airports_beside(lua_State* L) {
  command::Stack* s = self(L);
  const std::string ident = text::upper(arg_string(L, 2, "ident"));
  const double lat = arg_number(L, 3, "lat"), lon = arg_number(L, 4, "lon"),
               within = arg_number(L, 5, "within_nm");
  lua_newtable(L);
  const command::NavPoint* w = s->navdb() ? s->navdb()->waypoint(ident, lat, lon) : nullptr;
  if (!w) return 1;
  std::vector<std::pair<double, const command::NavPoint*>> found;  // [NM], airport
  for (const command::NavPoint& a : s->navdb()->airports()) {
    const double d = geo::kwikdist_nm(a.lat, a.lon, w->lat, w->lon);
    if (d <= within) found.emplace_back(d, &a);
  }
  std::sort(found.begin(), found.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  int k = 0;
  for (const auto& [d, a] : found) {
    lua_pushstring(L, a->id.c_str());
    lua_rawseti(L, -2, ++k);
  }
  return 1;
}

int navaids(lua_State* L, bool run) {
  command::Stack* s = self(L);
  const std::string name = arg_string(L, 2, "name");
  const double lat = arg_number(L, 3, "lat"), lon = arg_number(L, 4, "lon"),
               within = arg_number(L, 5, "within_nm");
  const std::string types = lua_isnoneornil(L, 6) ? std::string() : arg_string(L, 6, "types");
  lua_newtable(L);
  lua_newtable(L);
  if (!s->navdb()) return 2;
  int k = 0;
  for (const command::NavPoint* p : s->navdb()->navaids_named(name, lat, lon, within, types, run)) {
    ++k;
    lua_pushstring(L, p->id.c_str());
    lua_rawseti(L, -3, k);
    lua_createtable(L, 2, 0);
    lua_pushnumber(L, p->lat);
    lua_rawseti(L, -2, 1);
    lua_pushnumber(L, p->lon);
    lua_rawseti(L, -2, 2);
    lua_rawseti(L, -2, k);
  }
  return 2;
}

int l_navaids_named(lua_State* L) {
  return navaids(L, false);
}
int l_navaids_with_words(lua_State* L) {
  return navaids(L, true);
}

int l_waypoints_at(lua_State* L) {
  command::Stack* s = self(L);
  const double lat = arg_number(L, 2, "lat"), lon = arg_number(L, 3, "lon");
  lua_newtable(L);
  constexpr double kSameDeg = 1e-6;  // fix.dat writes six decimals
  int k = 0;
  for (const auto& [name, p] : s->user_waypoints()) {
    if (std::abs(p.lat - lat) > kSameDeg || std::abs(p.lon - lon) > kSameDeg) continue;
    lua_pushstring(L, name.c_str());
    lua_rawseti(L, -2, ++k);
  }
  if (!s->navdb()) return 1;
  for (const command::NavPoint& w : s->navdb()->waypoints()) {
    if (std::abs(w.lat - lat) > kSameDeg || std::abs(w.lon - lon) > kSameDeg) continue;
    lua_pushstring(L, w.id.c_str());
    lua_rawseti(L, -2, ++k);
  }
  return 1;
}

int l_reference(lua_State* L) {
  const command::GeoPoint ref = self(L)->reference();
  lua_pushnumber(L, ref.lat);
  lua_pushnumber(L, ref.lon);
  return 2;
}

int l_locate(lua_State* L) {
  command::Stack* s = self(L);
  const std::string text = arg_string(L, 2, "text");
  command::ParseContext ctx = s->parse_context();
  if (!lua_isnoneornil(L, 3)) ctx.ref = {arg_number(L, 3, "lat"), arg_number(L, 4, "lon")};
  command::ArgReader r(text);
  auto p = command::parse_position(r, ctx, ctx.ref);
  if (p && !r.at_end()) p = Status::invalid("more than one position in " + text::quoted(text));
  if (!p) {
    lua_pushnil(L);
    lua_pushstring(L, p.status().message().c_str());
    return 2;
  }
  lua_pushnumber(L, p->pos.lat);
  lua_pushnumber(L, p->pos.lon);
  return 2;
}

int l_check(lua_State* L) {
  command::Stack* s = self(L);
  const Status st = s->check(arg_string(L, 2, "line"));
  return push_outcome(L, st.is_ok() ? Result<std::string>(std::string()) : Result<std::string>(st));
}

// The scenario's own folder becomes the base for the PCALLs inside it.
int l_load(lua_State* L) {
  command::Stack* s = self(L);
  const std::string file = arg_string(L, 2, "file");
  if (auto found = s->find_scenario(file); found.is_ok()) s->set_base_dir(paths::dirname(*found));
  const Status st = s->load_scenario(file);
  return push_outcome(L, st.is_ok() ? Result<std::string>(std::string()) : Result<std::string>(st));
}

int l_step(lua_State* L) {
  command::Stack* s = self(L);
  const long long n = opt_count(L, 2, "n", 1, 0, kMaxSteps);
  for (long long k = 0; k < n; ++k) {
    if (k % kSlice == 0) charge(L, kSlice * step_cost(*s));
    s->step();
  }
  return 0;
}

int l_run_until(lua_State* L) {
  command::Stack* s = self(L);
  run_charged(L, *s, arg_number(L, 2, "t"));
  return 0;
}

int l_run_for(lua_State* L) {
  command::Stack* s = self(L);
  const double d = arg_number(L, 2, "seconds");
  if (!(d >= 0)) throw ArgError("seconds must be >= 0");
  run_charged(L, *s, s->sim().simt() + d);
  return 0;
}

int l_time(lua_State* L) {
  lua_pushnumber(L, self(L)->sim().simt());
  return 1;
}

int l_dt(lua_State* L) {
  lua_pushnumber(L, self(L)->sim().dt());
  return 1;
}

int l_count(lua_State* L) {
  lua_pushinteger(L, self(L)->sim().n());
  return 1;
}

int l_aircraft(lua_State* L) {
  const sim::Traffic& t = self(L)->sim().traffic();
  lua_createtable(L, t.n(), 0);
  for (int i = 0; i < t.n(); ++i) {
    push_aircraft(L, t, i);
    lua_seti(L, -2, i + 1);
  }
  return 1;
}

int l_get(lua_State* L) {
  const sim::Traffic& t = self(L)->sim().traffic();
  const int i = t.index_of(arg_string(L, 2, "acid"));
  if (i < 0) {
    lua_pushnil(L);
    return 1;
  }
  push_aircraft(L, t, i);
  return 1;
}

// Each of the detector's pairs in `list` as a table of `fields`.
template <class Pair, class Row, size_t N>
int push_pairs(lua_State* L, const sim::Traffic& t, const std::vector<Pair>& list,
               const sim::fields::Field<Row> (&fields)[N]) {
  lua_createtable(L, static_cast<int>(list.size()), 0);
  for (size_t k = 0; k < list.size(); ++k) {
    push_fields(L, fields, Row{t, list[k]});
    lua_seti(L, -2, static_cast<lua_Integer>(k + 1));
  }
  return 1;
}

int l_conflicts(lua_State* L) {
  const sim::Simulation& s = self(L)->sim();
  return push_pairs(L, s.traffic(), s.conflicts(), sim::fields::kConflict);
}

int l_los(lua_State* L) {
  const sim::Simulation& s = self(L)->sim();
  return push_pairs(L, s.traffic(), s.los(), sim::fields::kLos);
}

int l_totals(lua_State* L) {
  const sim::Simulation& s = self(L)->sim();
  lua_createtable(L, 0, 3);
  lua_pushinteger(L, s.cd().total_conflicts());
  lua_setfield(L, -2, "conflicts");
  lua_pushinteger(L, s.cd().total_los());
  lua_setfield(L, -2, "los");
  const std::string capped = sim::cap_notice(s.cd(), s.cd_settings().max_pairs);
  if (!capped.empty()) set_string(L, "capped", capped);
  return 1;
}

int l_output(lua_State* L) {
  const auto lines = self(L)->take_output();
  lua_createtable(L, static_cast<int>(lines.size()), 0);
  for (size_t k = 0; k < lines.size(); ++k) {
    lua_pushlstring(L, lines[k].data(), lines[k].size());
    lua_seti(L, -2, static_cast<lua_Integer>(k + 1));
  }
  return 1;
}

int l_tally(lua_State* L) {
  const command::Tally& t = self(L)->tally();
  lua_createtable(L, 0, 5);
  lua_pushinteger(L, t.executed);
  lua_setfield(L, -2, "executed");
  lua_pushinteger(L, command::total_count(t.skipped));
  lua_setfield(L, -2, "skipped");
  lua_pushinteger(L, command::total_count(t.failed));
  lua_setfield(L, -2, "failed");
  lua_createtable(L, static_cast<int>(t.first_failures.size()), 0);
  for (size_t k = 0; k < t.first_failures.size(); ++k) {
    lua_pushlstring(L, t.first_failures[k].data(), t.first_failures[k].size());
    lua_seti(L, -2, static_cast<lua_Integer>(k + 1));
  }
  lua_setfield(L, -2, "first_failures");
  lua_createtable(L, 0, static_cast<int>(t.failed.size()));
  for (const auto& [reason, n] : t.failed) {
    lua_pushinteger(L, n);
    lua_setfield(L, -2, reason.c_str());
  }
  lua_setfield(L, -2, "failed_by_reason");
  return 1;
}

int l_run_state(lua_State* L) {
  const sim::Simulation& s = self(L)->sim();
  lua_pushstring(L, s.fast() ? "ff" : s.run_state() == sim::RunState::kOp ? "op" : "hold");
  if (s.ff_end()) lua_pushnumber(L, *s.ff_end());
  else lua_pushnil(L);
  return 2;
}

int l_dtmult(lua_State* L) {
  lua_pushnumber(L, self(L)->dtmult());
  return 1;
}

int l_create(lua_State* L) {
  command::Stack* s = self(L);
  luaL_checktype(L, 2, LUA_TTABLE);
  const std::string id = field_string(L, 2, "id", "");
  const std::string type = field_string(L, 2, "type", "");
  const double lat = field_number(L, 2, "lat", NAN), lon = field_number(L, 2, "lon", NAN);
  const double spd = field_number(L, 2, "spd", NAN);
  if (std::isnan(lat) || std::isnan(lon) || std::isnan(spd))
    throw ArgError("sim:create: fields lat, lon [deg] and spd (CAS m/s or Mach) are required");
  check_status(s->sim().create(id, type, lat, lon, field_number(L, 2, "hdg_deg", 0.0),
                               field_number(L, 2, "alt_m", 0.0), spd));
  return 0;
}

std::optional<double> opt_field(lua_State* L, int idx, const char* key) {
  const double v = field_number(L, idx, key, NAN);
  return std::isnan(v) ? std::nullopt : std::optional<double>(v);
}

int l_creconfs(lua_State* L) {
  command::Stack* s = self(L);
  luaL_checktype(L, 2, LUA_TTABLE);
  const double dpsi = field_number(L, 2, "dpsi_deg", NAN), dcpa = field_number(L, 2, "dcpa_m", NAN),
               tlosh = field_number(L, 2, "tlosh_s", NAN);
  if (std::isnan(dpsi) || std::isnan(dcpa) || std::isnan(tlosh))
    throw ArgError("sim:creconfs: fields dpsi_deg, dcpa_m and tlosh_s are required");
  check_status(s->sim().creconfs(field_string(L, 2, "id", ""), field_string(L, 2, "type", ""),
                                 field_string(L, 2, "target", ""), dpsi, dcpa, tlosh, opt_field(L, 2, "dh_m"),
                                 opt_field(L, 2, "tlosv_s"), opt_field(L, 2, "spd")));
  return 0;
}

int l_select_vertical(lua_State* L) {
  command::Stack* s = self(L);
  check_status(s->sim().select_vertical(arg_string(L, 2, "acid"), arg_number(L, 3, "alt_m"),
                                        arg_number(L, 4, "vs_ms")));
  return 0;
}

int l_values(lua_State* L) {
  const sim::Simulation& s = self(L)->sim();
  const std::string acid = arg_string(L, 2, "acid");
  const int i = s.index_of(acid);
  if (i < 0) throw ArgError("sim:values: no aircraft '" + acid + "'");
  const sim::Traffic& t = s.traffic();
  for (double v : {t.lat[i], t.lon[i], t.alt[i], t.hdg[i], t.tas[i], t.gs[i], t.vs[i], t.cas[i]})
    lua_pushnumber(L, v);
  return 8;
}

int l_delete_all(lua_State* L) {
  self(L)->sim().delete_all();
  return 0;
}

int l_copy(lua_State* L) {
  const command::Stack& s = *self(L);
  new_object<command::Stack>(L, kSimMt, s);
  return 1;
}

int l_snapshot(lua_State* L) {
  const std::string snap = self(L)->snapshot();
  lua_pushlstring(L, snap.data(), snap.size());
  return 1;
}

// squawk.sim.types(): the types the performance models know.
int l_types(lua_State* L) {
  lua_newtable(L);
  int k = 0;
  auto push = [&](std::string_view designator, const std::string& title, const char* model,
                  const char* cls, double vmax_mps) {
    lua_createtable(L, 0, 5);
    set_string(L, "designator", std::string(designator));
    if (!title.empty()) set_string(L, "title", title);
    set_string(L, "model", model);
    set_string(L, "class", cls);
    if (vmax_mps > 0) {
      lua_pushnumber(L, vmax_mps / units::kKt);
      lua_setfield(L, -2, "vmax_kt");
    }
    lua_rawseti(L, -2, ++k);
  };
  if (const auto oap = sim::default_openap())
    for (const auto& [designator, title] : oap->titles())
      push(designator, title, "openap", "jet", 0);
  for (const auto& [designator, cls] : sim::class_model_types())
    push(designator, "", "class", sim::perf_class_name(cls), sim::perf_limits(cls).vmax);
  return 1;
}

int l_commands(lua_State* L) {
  const auto& cmds = command::Registry::instance().commands();
  lua_createtable(L, static_cast<int>(cmds.size()), 0);
  for (size_t k = 0; k < cmds.size(); ++k) {
    const auto& d = cmds[k];
    lua_createtable(L, 0, 5);
    set_string(L, "name", d.name);
    set_string(L, "args", d.args);
    set_string(L, "usage", d.usage);
    set_string(L, "help", d.help);
    lua_createtable(L, static_cast<int>(d.aliases.size()), 0);
    for (size_t a = 0; a < d.aliases.size(); ++a) {
      lua_pushstring(L, d.aliases[a].c_str());
      lua_seti(L, -2, static_cast<lua_Integer>(a + 1));
    }
    lua_setfield(L, -2, "aliases");
    lua_seti(L, -2, static_cast<lua_Integer>(k + 1));
  }
  return 1;
}

}  // namespace

void bind_sim(lua_State* L) {
  static const luaL_Reg methods[] = {
      {"exec", guarded<l_exec>},
      {"check", guarded<l_check>},
      {"airports_named", guarded<l_airports_named>},
      {"airports_of_city", guarded<l_airports_of_city>},
      {"airports_with_words", guarded<l_airports_with_words>},
      {"airports_beside_navaids", guarded<l_airports_beside_navaids>},
      {"airport_class", guarded<l_airport_class>},
      {"navaids_named", guarded<l_navaids_named>},
      {"navaids_with_words", guarded<l_navaids_with_words>},
      {"airports_coded", guarded<l_airports_coded>},
      {"airports_beside", guarded<l_airports_beside>},
      {"waypoints_at", guarded<l_waypoints_at>},
      {"reference", guarded<l_reference>},
      {"locate", guarded<l_locate>},
      {"load", guarded<l_load>},
      {"step", guarded<l_step>},
      {"run_until", guarded<l_run_until>},
      {"run_for", guarded<l_run_for>},
      {"time", guarded<l_time>},
      {"dt", guarded<l_dt>},
      {"count", guarded<l_count>},
      {"aircraft", guarded<l_aircraft>},
      {"get", guarded<l_get>},
      {"conflicts", guarded<l_conflicts>},
      {"los", guarded<l_los>},
      {"totals", guarded<l_totals>},
      {"output", guarded<l_output>},
      {"copy", guarded<l_copy>},
      {"tally", guarded<l_tally>},
      {"run_state", guarded<l_run_state>},
      {"dtmult", guarded<l_dtmult>},
      {"create", guarded<l_create>},
      {"select_vertical", guarded<l_select_vertical>},
      {"values", guarded<l_values>},
      {"delete_all", guarded<l_delete_all>},
      {"creconfs", guarded<l_creconfs>},
      {"snapshot", guarded<l_snapshot>},
      {nullptr, nullptr},
  };
  define_class(L, kSimMt, methods);
  push_squawk_subtable(L, "sim");
  lua_pushcfunction(L, guarded<l_new>);
  lua_setfield(L, -2, "new");
  lua_pushcfunction(L, guarded<l_commands>);
  lua_setfield(L, -2, "commands");
  lua_pushcfunction(L, guarded<l_types>);
  lua_setfield(L, -2, "types");
  lua_pop(L, 1);
}

}  // namespace squawk::script
