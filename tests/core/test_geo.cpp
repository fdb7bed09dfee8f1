// geo.h against BlueSky's formulas (docs/bluesky_facts.md §1.4, §5). Reference
// values were computed with numpy from the formulas in _geo.py and the gym's
// get_point_at_distance; the BlueSky-Gym trace gives one real waypoint.
#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>

#include "core/geo.h"
#include "core/units.h"

using namespace squawk;

TEST_CASE("kwikqdrdist matches BlueSky's flat-earth formula") {
  struct Case {
    double lata, lona, latb, lonb, qdr, dist;
  };
  const Case cases[] = {
      {52, 4, 53, 5, 31.331442664473, 70.290696287355},
      {52, 4, 51.5, 3.2, 224.728003470884, 42.254897356053},
      {10, 179.5, 10.5, -179.5, 63.064463503286, 66.271613710171},  // across the date line
      {-33.9, 151.2, -34.2, 150.8, 227.848712170929, 26.840100569630},
  };
  for (const auto& c : cases) {
    auto r = geo::kwikqdrdist(c.lata, c.lona, c.latb, c.lonb);
    CHECK(r.qdr_deg == doctest::Approx(c.qdr).epsilon(1e-12));
    CHECK(r.dist_nm == doctest::Approx(c.dist).epsilon(1e-12));
    CHECK(geo::kwikdist_nm(c.lata, c.lona, c.latb, c.lonb) == doctest::Approx(c.dist).epsilon(1e-12));
  }
}

TEST_CASE("kwikpos matches BlueSky's flat-earth step (60 NM per degree)") {
  auto p = geo::kwikpos(52, 4, 45, 10);
  CHECK(p.lat_deg == doctest::Approx(52.117851130198).epsilon(1e-12));
  CHECK(p.lon_deg == doctest::Approx(4.191421966326).epsilon(1e-12));
  p = geo::kwikpos(52, 4, 200, 25.5);
  CHECK(p.lat_deg == doctest::Approx(51.600630636166).epsilon(1e-12));
  CHECK(p.lon_deg == doctest::Approx(3.763898559941).epsilon(1e-12));
  p = geo::kwikpos(0, 179.9, 90, 30);  // longitude wraps into [-180, 180)
  CHECK(p.lon_deg == doctest::Approx(-179.6).epsilon(1e-12));
}

TEST_CASE("great-circle destination reproduces BlueSky-Gym's waypoint") {
  // Trace seed 42: ownship at (52, 4), waypoint due north at 53.13314522;
  // the gym draws an integer km distance, here 126 km (R = 6371 km).
  auto p = geo::gc_destination(52.0, 4.0, 0.0, 126000.0);
  CHECK(p.lat_deg == doctest::Approx(53.13314522).epsilon(1e-9));
  CHECK(p.lon_deg == doctest::Approx(4.0).epsilon(1e-12));
  // Distance and bearing invert the destination.
  auto q = geo::gc_destination(40.0, -74.0, 63.0, 250000.0);
  CHECK(geo::gc_distance_m(40.0, -74.0, q.lat_deg, q.lon_deg) == doctest::Approx(250000.0).epsilon(1e-9));
  CHECK(geo::gc_bearing_deg(40.0, -74.0, q.lat_deg, q.lon_deg) == doctest::Approx(63.0).epsilon(1e-9));
}

TEST_CASE("angle wrapping") {
  CHECK(geo::wrap360(-90) == 270);
  CHECK(geo::wrap360(720.5) == doctest::Approx(0.5));
  CHECK(geo::wrap360(-1e-17) < 360.0);
  CHECK(geo::wrap180(190) == -170);
  CHECK(geo::wrap180(-180) == 180);
  CHECK(geo::wrap180(180) == 180);
  // The gym's wrap only folds once.
  CHECK(geo::gym_wrap180(200) == -160);
  CHECK(geo::gym_wrap180(-200) == 160);
  CHECK(geo::gym_wrap180(600) == 240);
}

TEST_CASE("unit conversions use BlueSky's constants") {
  CHECK(units::kt_to_ms(250) == doctest::Approx(128.611));
  CHECK(units::fl_to_m(100) == doctest::Approx(3048.0));
  CHECK(units::fpm_to_ms(2000) == doctest::Approx(10.16));
  CHECK(units::nm_to_m(5) == 9260.0);
  CHECK(units::ms_to_kt(units::kt_to_ms(123.4)) == doctest::Approx(123.4));
  // Turn rate at 89 m/s with 25 deg bank (bluesky_gym_measured.md: 2.944 deg/s).
  const double rate = units::rad_to_deg(units::kG0 * std::tan(units::deg_to_rad(25)) / 89.0);
  CHECK(rate == doctest::Approx(2.944).epsilon(1e-3));
}

TEST_CASE("qdrdist on cached latitude trigonometry equals qdrdist on the latitudes bit for bit") {
  // Same hemisphere, across the equator, at the poles, across the antimeridian.
  const double pts[][4] = {{52.3, 4.8, 40.6, -73.8}, {-33.9, 151.2, 51.5, -0.5}, {89.9, 10.0, -89.9, -170.0},
                           {0.0, 179.9, 0.0, -179.9}, {-12.0, -45.0, -12.0, -45.0}, {35.5, 139.8, 1.4, 103.9}};
  for (const auto& p : pts) {
    const geo::QdrDist a = geo::qdrdist(p[0], p[1], p[2], p[3]);
    const geo::QdrDist b = geo::qdrdist(geo::lat_trig(p[0]), p[1], geo::lat_trig(p[2]), p[3]);
    CHECK(a.qdr_deg == b.qdr_deg);
    CHECK(a.dist_nm == b.dist_nm);
  }
}

TEST_CASE("wrap360 and wrap180 of angles within one turn skip fmod and give its values") {
  for (const double d : {-359.999, -180.0, -1e-300, -0.0, 0.0, 1e-300, 90.0, 180.0, 359.999999999999, 719.5, -725.0}) {
    double r = std::fmod(d, 360.0);
    if (r < 0) r += 360.0;
    if (r >= 360.0) r -= 360.0;
    CHECK(geo::wrap360(d) == r);
    CHECK(geo::wrap180(d) == (r > 180.0 ? r - 360.0 : r));
  }
}
