#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/geo.h"
#include "core/units.h"
#include "sim/simulation.h"

using namespace squawk;
using namespace squawk::sim;

namespace {
Waypoint wpt(const char* name, double lat, double lon, double alt = kNoConstraint, double spd = kNoConstraint) {
  Waypoint w;
  w.name = name;
  w.lat = lat;
  w.lon = lon;
  w.alt = alt;
  w.spd = spd;
  return w;
}
double dist_m(const Traffic& t, int i, const Waypoint& w) {
  return units::nm_to_m(geo::kwikdist_nm(t.lat[i], t.lon[i], w.lat, w.lon));
}
}  // namespace

TEST_CASE("LNAV flies a 3-waypoint route and switches at each waypoint") {
  Simulation sim;
  const double alt0 = units::fl_to_m(30);
  REQUIRE(sim.create("KL1", "A320", 52.0, 4.0, 0.0, alt0, 150.0).is_ok());
  const std::vector<Waypoint> wps = {wpt("ONE", 52.3, 4.0), wpt("TWO", 52.3, 4.5, units::fl_to_m(50)),
                                     wpt("THREE", 52.0, 4.5)};
  for (const Waypoint& w : wps) REQUIRE(sim.add_waypoint("KL1", w).is_ok());
  const Traffic& t = sim.traffic();
  CHECK(t.lnav[0] == 1);  // the first waypoint switches LNAV on
  REQUIRE(sim.set_vnav("KL1", true).is_ok());
  const double radius = t.tas[0] * t.tas[0] / (units::kG0 * std::tan(25.0 * units::kDeg));
  std::vector<double> switch_dist, switch_radius;
  std::vector<double> min_dist(3, 1e12);
  int active = t.route[0].active();
  CHECK(active == 0);
  double alt_at_two = -1;
  while (sim.simt() < 3000.0 && t.lnav[0]) {
    const int before = t.route[0].active();
    const double turndist = t.turndist[0];
    sim.step();
    for (int k = 0; k < 3; ++k) min_dist[k] = std::min(min_dist[k], dist_m(t, 0, wps[k]));
    const int now = t.route[0].active();
    if (now != before) {
      switch_dist.push_back(dist_m(t, 0, wps[before]));
      switch_radius.push_back(turndist);
      if (before == 1) alt_at_two = t.alt[0];
      CHECK((now == before + 1 || now == -1));
    }
  }
  REQUIRE(switch_dist.size() == 3);
  // About 90 deg course changes at ONE and TWO: the switch happens at the turn
  // distance fixed when the waypoint became active (R tan(dpsi/2), R from the
  // TAS then), within one step of flight.
  CHECK(switch_dist[0] == doctest::Approx(switch_radius[0]).epsilon(0.003));
  CHECK(switch_dist[1] == doctest::Approx(switch_radius[1]).epsilon(0.003));
  CHECK(switch_radius[0] == doctest::Approx(radius).epsilon(0.02));
  // The corner is cut; the last waypoint is flown over.
  CHECK(min_dist[0] < radius);
  CHECK(min_dist[2] < 100.0);
  CHECK(switch_dist[2] < 1.02 * radius);
  CHECK(t.lnav[0] == 0);
  CHECK(t.vnav[0] == 0);
  CHECK(t.route[0].active() == -1);
  // VNAV climbs at once (1500 ft/min): level at TWO's constraint well before TWO.
  CHECK(alt_at_two == doctest::Approx(units::fl_to_m(50)));
}

TEST_CASE("VNAV descends from the top of descent on a 3000 ft / 10 NM path") {
  Simulation sim;
  const double alt0 = units::fl_to_m(100), alt1 = units::fl_to_m(40);
  REQUIRE(sim.create("KL1", "A320", 52.0, 4.0, 0.0, alt0, 150.0).is_ok());
  const Waypoint w = wpt("LOW", 53.0, 4.0, alt1);
  REQUIRE(sim.add_waypoint("KL1", w).is_ok());
  REQUIRE(sim.set_vnav("KL1", true).is_ok());
  const Traffic& t = sim.traffic();
  const double tod = (alt0 - alt1) / kVnavSteepness;  // 18 000 ft * 10 NM / 3000 ft = 20 NM
  CHECK(tod == doctest::Approx(units::nm_to_m(20.0)));
  double dist_at_tod = -1, alt_halfway = -1;
  while (t.lnav[0] && sim.simt() < 2000.0) {
    sim.step();
    if (dist_at_tod < 0 && t.vs[0] < 0.0) dist_at_tod = dist_m(t, 0, w);
    if (alt_halfway < 0 && dist_m(t, 0, w) < 0.5 * tod) alt_halfway = t.alt[0];
  }
  CHECK(dist_at_tod == doctest::Approx(tod).epsilon(0.01));
  CHECK(alt_halfway == doctest::Approx(0.5 * (alt0 + alt1)).epsilon(0.03));
  // The path gradient brings it down to (about) the constraint at the waypoint.
  CHECK(t.alt[0] == doctest::Approx(alt1).epsilon(0.02));
}

TEST_CASE("route edits, DIRECT, DEST and ORIG") {
  Simulation sim;
  REQUIRE(sim.create("KL1", "B744", 52.0, 4.0, 0.0, 3000.0, 150.0).is_ok());
  REQUIRE(sim.set_dest("KL1", wpt("EHAM", 52.31, 4.76)).is_ok());
  const Route& r = sim.traffic().route[0];
  CHECK(r.dest() == "EHAM");
  CHECK(r.active() == 0);
  CHECK(sim.traffic().lnav[0] == 1);
  REQUIRE(sim.add_waypoint("KL1", wpt("spy", 52.5, 4.8)).is_ok());  // goes before EHAM
  REQUIRE(sim.add_waypoint_before("KL1", "SPY", wpt("A", 52.1, 4.1)).is_ok());
  REQUIRE(sim.add_waypoint_after("KL1", "A", wpt("B", 52.2, 4.2)).is_ok());
  std::vector<std::string> names;
  for (const Waypoint& w : r.waypoints()) names.push_back(w.name);
  CHECK(names == std::vector<std::string>{"A", "B", "SPY", "EHAM"});
  // BlueSky: a waypoint appended while the destination is active lands at the
  // active index, so SPY became active and stays so as A and B go before it.
  CHECK(r.active() == 2);
  REQUIRE(sim.direct_to("KL1", "b").is_ok());
  CHECK(r.active() == 1);
  REQUIRE(sim.delete_waypoint("KL1", "A").is_ok());
  CHECK(r.active() == 0);
  CHECK(r.waypoints()[0].name == "B");
  REQUIRE(sim.set_orig("KL1", wpt("EHRD", 51.96, 4.44)).is_ok());
  CHECK(r.orig() == "EHRD");

  // Failures name the culprit and change nothing.
  const std::string before = sim.snapshot();
  Status st = sim.direct_to("KL1", "NOWHERE");
  CHECK(st.code() == Code::kNotFound);
  CHECK(st.message() == "KL1: waypoint 'NOWHERE' is not in the route");
  CHECK(!sim.add_waypoint_after("KL1", "EHAM", wpt("X", 52, 4)).is_ok());
  CHECK(!sim.add_waypoint("KL1", wpt("BAD", 95.0, 4.0)).is_ok());
  CHECK(!sim.add_waypoint("KL1", wpt("", 50.0, 4.0)).is_ok());
  CHECK(!sim.add_waypoint("KL1", wpt("NEG", 50.0, 4.0, kNoConstraint, -3.0)).is_ok());
  CHECK(!sim.delete_waypoint("KL1", "NOWHERE").is_ok());
  CHECK(!sim.add_waypoint("XX9", wpt("C", 50.0, 4.0)).is_ok());
  CHECK(sim.snapshot() == before);

  REQUIRE(sim.delete_route("KL1").is_ok());
  CHECK(r.empty());
  CHECK(r.dest().empty());
  CHECK(sim.traffic().lnav[0] == 0);
  CHECK(sim.set_lnav("KL1", true).message().find("LNAV needs a route") != std::string::npos);
}

TEST_CASE("waypoint_reached: turn anticipation and passing") {
  const double bank = 25.0 * units::kDeg, tas = 150.0;
  const double r = tas * tas / (units::kG0 * std::tan(bank));
  // 90 deg turn at a fly-by waypoint: switch inside R tan 45 = R; fly-over: 0.
  const double td = turn_distance(tas, bank, 0.0, 90.0, true);
  CHECK(td == doctest::Approx(r));
  CHECK(turn_distance(tas, bank, 0.0, 90.0, false) == 0.0);
  CHECK(waypoint_reached(0.99 * r, 0.0, 0.0, 0.0, tas, td));
  CHECK(!waypoint_reached(1.01 * r, 0.0, 0.0, 0.0, tas, td));
  // Straight on: only once passed (bearing > 90 deg off the leg direction)...
  CHECK(!waypoint_reached(10.0, 0.0, 0.0, 0.0, tas, 0.0));
  CHECK(waypoint_reached(10.0, 180.0, 0.0, 0.0, tas, 0.0));
  CHECK(waypoint_reached(2.0 * r, 180.0, 0.0, 0.0, tas, 0.0));
  // ...or within 4 s of flight and behind the track.
  CHECK(waypoint_reached(3.9 * tas, 100.0, 100.0, 0.0, tas, 0.0));
  CHECK(!waypoint_reached(4.1 * tas, 100.0, 100.0, 0.0, tas, 0.0));
}
