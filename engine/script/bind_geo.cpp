// squawk.geo: the geometry kernels environments call per step (BlueSky's
// flat-earth formulas, great circles, the CPA kernel, polygon tests).
// Angles in degrees, distances as each name says.
//
//   squawk.geo.kwikqdrdist(lat1, lon1, lat2, lon2) -> qdr_deg, dist_nm
//   squawk.geo.kwikdist(lat1, lon1, lat2, lon2)    -> dist_nm
//   squawk.geo.kwikpos(lat, lon, qdr_deg, dist_nm) -> lat, lon
//   squawk.geo.destination(lat, lon, bearing_deg, dist_m) -> lat, lon  (great circle, R 6371 km)
//   squawk.geo.wrap180(deg) -> (-180, 180];  wrap360(deg) -> [0, 360)
//   squawk.geo.gym_wrap180(deg) -> BlueSky-Gym's one-shot wrap (a > 180: a - 360; a < -180: a +
//   360) squawk.geo.cpa(dx, dy, du, dv, r) -> tcpa_s, dcpa_m, t_in_s, t_out_s
//       relative position (dx east, dy north) [m] and velocity [m/s] of the
//       intruder, protected radius r [m]; t_in/t_out are nil when the tracks
//       do not meet inside r (core/cpa.h, BlueSky's state-based detection)
//   squawk.geo.inside(lat, lon, {lat1, lon1, lat2, lon2, ...}) -> boolean
//       the point inside the polygon (even-odd rule, BlueSky's POLY test)
//   squawk.geo.polygons({{lat1, lon1, ...}, ...}) -> a polygon set, read once
//       set:count_inside(lat, lon) -> how many of its polygons contain the
//       point (the same test; for environments that test fixed areas every step)
#include <cmath>
#include <vector>

#include "core/cpa.h"
#include "core/geo.h"
#include "script/bindings.h"
#include "script/lua_util.h"
#include "sim/shapes.h"

namespace squawk::script {

namespace {

// Pushes a pair of results (qdr and distance, or latitude and longitude).
int push_two(lua_State* L, double a, double b) {
  lua_pushnumber(L, a);
  lua_pushnumber(L, b);
  return 2;
}

// Four numeric arguments, named for the messages of a wrong call.
struct Four {
  double a, b, c, d;
};
Four four(lua_State* L, const char* n1, const char* n2, const char* n3, const char* n4) {
  return {arg_number(L, 1, n1), arg_number(L, 2, n2), arg_number(L, 3, n3), arg_number(L, 4, n4)};
}

int l_kwikqdrdist(lua_State* L) {
  const Four x = four(L, "lat1", "lon1", "lat2", "lon2");
  const auto r = geo::kwikqdrdist(x.a, x.b, x.c, x.d);
  return push_two(L, r.qdr_deg, r.dist_nm);
}

int l_kwikdist(lua_State* L) {
  const Four x = four(L, "lat1", "lon1", "lat2", "lon2");
  lua_pushnumber(L, geo::kwikdist_nm(x.a, x.b, x.c, x.d));
  return 1;
}

int l_kwikpos(lua_State* L) {
  const Four x = four(L, "lat", "lon", "qdr_deg", "dist_nm");
  const auto p = geo::kwikpos(x.a, x.b, x.c, x.d);
  return push_two(L, p.lat_deg, p.lon_deg);
}

int l_destination(lua_State* L) {
  const Four x = four(L, "lat", "lon", "bearing_deg", "dist_m");
  const auto p = geo::gc_destination(x.a, x.b, x.c, x.d);
  return push_two(L, p.lat_deg, p.lon_deg);
}

// wrap180, wrap360, gym_wrap180: one angle [deg] in, one out.
template <double (*wrap)(double)>
int l_wrap(lua_State* L) {
  lua_pushnumber(L, wrap(arg_number(L, 1, "deg")));
  return 1;
}

int l_cpa(lua_State* L) {
  const double r = arg_number(L, 5, "r");
  if (!(r > 0)) throw ArgError("squawk.geo.cpa: radius r must be > 0 m");
  const cpa::Horizontal h = cpa::horizontal(arg_number(L, 1, "dx"), arg_number(L, 2, "dy"),
                                            arg_number(L, 3, "du"), arg_number(L, 4, "dv"), r);
  lua_pushnumber(L, h.tcpa);
  lua_pushnumber(L, std::sqrt(h.dcpa2));
  if (!h.enters) return 2;
  lua_pushnumber(L, h.t_in);
  lua_pushnumber(L, h.t_out);
  return 4;
}

// The polygon {lat1, lon1, lat2, lon2, ...} at `idx`; `what` names it in errors.
sim::Shape read_polygon(lua_State* L, int idx, const std::string& what) {
  if (lua_type(L, idx) != LUA_TTABLE) throw ArgError(what + " is not a table of lat, lon numbers");
  const lua_Integer n = length(L, idx);
  if (n < 6 || n % 2 != 0)
    throw ArgError(what + " needs lat, lon pairs of at least 3 points, got " + std::to_string(n) +
                   " numbers");
  sim::Shape poly;
  poly.kind = sim::Shape::Kind::kPoly;
  poly.coords.reserve(static_cast<size_t>(n));
  for (lua_Integer k = 1; k <= n; ++k) {
    get_index(L, idx, k);
    if (!lua_isnumber(L, -1)) throw ArgError(what + "[" + std::to_string(k) + "] is not a number");
    poly.coords.push_back(lua_tonumber(L, -1));
    lua_pop(L, 1);
  }
  return poly;
}

int l_inside(lua_State* L) {
  const double lat = arg_number(L, 1, "lat"), lon = arg_number(L, 2, "lon");
  luaL_checktype(L, 3, LUA_TTABLE);
  lua_pushboolean(L, read_polygon(L, 3, "squawk.geo.inside: polygon").contains(lat, lon, 0.0));
  return 1;
}

constexpr const char* kPolygonsMt = "squawk.geo.Polygons";
using Polygons = std::vector<sim::Shape>;

int l_polygons(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  const lua_Integer n = length(L, 1);
  Polygons set;
  set.reserve(static_cast<size_t>(n));
  for (lua_Integer k = 1; k <= n; ++k) {
    get_index(L, 1, k);
    set.push_back(
        read_polygon(L, lua_gettop(L), "squawk.geo.polygons: polygon " + std::to_string(k)));
    lua_pop(L, 1);
  }
  new_object<Polygons>(L, kPolygonsMt, std::move(set));
  return 1;
}

int l_count_inside(lua_State* L) {
  const Polygons& set = *arg_object<Polygons>(L, 1, kPolygonsMt);
  const double lat = arg_number(L, 2, "lat"), lon = arg_number(L, 3, "lon");
  lua_Integer count = 0;
  for (const sim::Shape& p : set) count += p.contains(lat, lon, 0.0) ? 1 : 0;
  lua_pushinteger(L, count);
  return 1;
}

}  // namespace

void bind_geo(lua_State* L) {
  static const luaL_Reg fns[] = {{"kwikqdrdist", guarded<l_kwikqdrdist>},
                                 {"kwikdist", guarded<l_kwikdist>},
                                 {"kwikpos", guarded<l_kwikpos>},
                                 {"destination", guarded<l_destination>},
                                 {"wrap180", guarded<l_wrap<geo::wrap180>>},
                                 {"wrap360", guarded<l_wrap<geo::wrap360>>},
                                 {"gym_wrap180", guarded<l_wrap<geo::gym_wrap180>>},
                                 {"cpa", guarded<l_cpa>},
                                 {"inside", guarded<l_inside>},
                                 {"polygons", guarded<l_polygons>},
                                 {nullptr, nullptr}};
  static const luaL_Reg polygon_methods[] = {{"count_inside", guarded<l_count_inside>},
                                             {nullptr, nullptr}};
  define_class(L, kPolygonsMt, polygon_methods);
  push_squawk_subtable(L, "geo");
  luaL_setfuncs(L, fns, 0);
  lua_pop(L, 1);
}

}  // namespace squawk::script
