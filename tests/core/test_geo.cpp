// geo.h against BlueSky's formulas (docs/bluesky_facts.md §1.4, §5). Reference
// values were computed with numpy from the formulas in _geo.py and the gym's
// get_point_at_distance; the BlueSky-Gym trace gives one real waypoint.
#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>
#include <vector>

#include "core/geo.h"
#include "core/units.h"
#include "core/vmath.h"

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

TEST_CASE("vmath sin, cos and atan2 are within 4 ulp of libm and independent of position in the array") {
  // 203 arguments (50 groups of four and a tail of 3), over several turns and both signs.
  std::vector<double> x(203), y(203), s(203), c(203), a(203);
  for (size_t k = 0; k < x.size(); ++k) {
    x[k] = -20.0 + 0.1973 * static_cast<double>(k);
    y[k] = 3.0 * std::sin(0.37 * static_cast<double>(k)) + (k % 7 == 0 ? 0.0 : 1e-3);
  }
  vmath::sin(x.data(), 1.0, s.data(), 203);
  vmath::cos(x.data(), 1.0, c.data(), 203);
  vmath::atan2(y.data(), x.data(), a.data(), 203);
  auto ulps = [](double got, double want) {
    return std::fabs(got - want) / (std::nextafter(std::fabs(want), INFINITY) - std::fabs(want));
  };
  for (size_t k = 0; k < x.size(); ++k) {
    CHECK(ulps(s[k], std::sin(x[k])) <= 4.0);
    CHECK(ulps(c[k], std::cos(x[k])) <= 4.0);
    CHECK(ulps(a[k], std::atan2(y[k], x[k])) <= 4.0);
  }
  // The tail element alone, and at a group's start, gives the same bits.
  double one = 0.0;
  vmath::sin(&x[202], 1.0, &one, 1);
  CHECK(one == s[202]);
  vmath::sin(&x[200], 1.0, &one, 1);
  CHECK(one == s[200]);
  // scale multiplies before the function: sin(deg * kDeg).
  const double deg = 33.3;
  vmath::sin(&deg, units::kDeg, &one, 1);
  CHECK(ulps(one, std::sin(deg * units::kDeg)) <= 4.0);
  if (!vmath::uses_libmvec()) CHECK(s[17] == std::sin(x[17]));
}

TEST_CASE("qdrdist_n equals qdrdist within libmvec's error, bit for bit without it") {
  // 150 pairs (two blocks of 64 and a tail): same hemisphere, across the equator and the antimeridian, near the poles.
  const int n = 150;
  std::vector<double> la(n), sa(n), ca(n), lona(n), lb(n), sb(n), cb(n), lonb(n), qdr(n), dist(n);
  for (int k = 0; k < n; ++k) {
    const double lat_a = 89.9 * std::sin(1.3 * k), lat_b = 89.9 * std::cos(0.7 * k + 0.2);
    lona[k] = 179.9 * std::sin(2.1 * k + 0.5);
    lonb[k] = k % 5 == 0 ? lona[k] + 0.01 : 179.9 * std::cos(1.7 * k);
    const geo::LatTrig ta = geo::lat_trig(lat_a), tb = geo::lat_trig(lat_b);
    la[k] = ta.rad, sa[k] = ta.sin, ca[k] = ta.cos, lb[k] = tb.rad, sb[k] = tb.sin, cb[k] = tb.cos;
  }
  geo::qdrdist_n({la.data(), sa.data(), ca.data(), lona.data(), lb.data(), sb.data(), cb.data(), lonb.data(),
                  qdr.data(), dist.data()},
                 n);
  int crossing = 0;
  for (int k = 0; k < n; ++k) {
    const geo::QdrDist r = geo::qdrdist({la[k], sa[k], ca[k]}, lona[k], {lb[k], sb[k], cb[k]}, lonb[k]);
    crossing += la[k] * lb[k] < 0.0;
    if (vmath::uses_libmvec()) {
      CHECK(std::fabs(geo::wrap180(qdr[k] - r.qdr_deg)) < 1e-11);
      CHECK(std::fabs(dist[k] - r.dist_nm) <= 1e-13 * r.dist_nm);
    } else {
      CHECK(qdr[k] == r.qdr_deg);
      CHECK(dist[k] == r.dist_nm);
    }
  }
  CHECK(crossing > 20);
}
