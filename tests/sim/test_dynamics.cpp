#include <doctest/doctest.h>

#include <cmath>

#include "core/geo.h"
#include "core/units.h"
#include "sim/simulation.h"

using namespace squawk;
using namespace squawk::sim;
using units::kDeg;

namespace {
// Turn rate [deg/s] of BlueSky's model, written out here as the reference.
double turn_rate_deg(double tas, double bank_deg) {
  return std::tan(bank_deg * kDeg) * 9.80665 / tas / kDeg;
}
}  // namespace

TEST_CASE("90 deg turn at 150 m/s takes 90 / (g tan 25 / TAS) seconds") {
  Simulation sim;
  REQUIRE(sim.create("KL1", "A320", 52.0, 4.0, 0.0, 0.0, 150.0).is_ok());
  REQUIRE(sim.set_heading("KL1", 90.0).is_ok());
  const double expect = 90.0 / turn_rate_deg(150.0, 25.0);  // 51.5 s
  CHECK(turn_rate_deg(150.0, 25.0) == doctest::Approx(1.747).epsilon(1e-3));
  const Traffic& t = sim.traffic();
  double done_at = -1;
  while (sim.simt() < 100.0) {
    sim.step();
    if (done_at < 0 && t.hdg[0] == 90.0) done_at = sim.simt();
  }
  CHECK(done_at == doctest::Approx(expect).epsilon(0.002));
  CHECK(t.trk[0] == 90.0);
  // Halfway through, the heading has moved at exactly the turn rate.
  Simulation s2;
  REQUIRE(s2.create("KL1", "A320", 52.0, 4.0, 10.0, 0.0, 150.0).is_ok());
  REQUIRE(s2.set_heading("KL1", 300.0).is_ok());  // shortest way: left through north
  REQUIRE(s2.run_for(20.0).is_ok());
  CHECK(s2.traffic().hdg[0] == doctest::Approx(geo::wrap360(10.0 - 20.0 * turn_rate_deg(150.0, 25.0))));
}

TEST_CASE("climb to FL100 at a selected vertical speed: 300 ft/min/s ramp, then dh / vs") {
  Simulation sim;
  REQUIRE(sim.create("KL1", "A320", 52.0, 4.0, 0.0, units::fl_to_m(50), 150.0).is_ok());
  const double vs = units::fpm_to_ms(2000);
  REQUIRE(sim.set_altitude("KL1", units::fl_to_m(100), vs).is_ok());
  const Traffic& t = sim.traffic();
  double done_at = -1;
  while (sim.simt() < 400.0) {
    sim.step();
    // V/S grows by 300 ft/min per second until within 300 ft/min of the target.
    if (sim.simt() < 5.0) CHECK(t.vs[0] == doctest::Approx(units::fpm_to_ms(300) * sim.simt()));
    if (sim.simt() > 6.0 && sim.simt() < 100.0) CHECK(t.vs[0] == doctest::Approx(vs));
    if (done_at < 0 && t.alt[0] == units::fl_to_m(100)) done_at = sim.simt();
  }
  const double dh = units::fl_to_m(100) - units::fl_to_m(50);
  // The ramp costs about half its 6 s; the last step snaps to the target
  // (capture band 1.05 dt |vs|).
  CHECK(done_at > dh / vs + 2.0);
  CHECK(done_at < dh / vs + 4.0);
  CHECK(t.vs[0] == 0.0);
  CHECK(t.alt[0] == units::fl_to_m(100));
  // A later ALT without V/S keeps the selected V/S (BlueSky's selvs).
  REQUIRE(sim.set_altitude("KL1", units::fl_to_m(90)).is_ok());
  REQUIRE(sim.run_for(10.0).is_ok());
  CHECK(t.vs[0] == doctest::Approx(-vs));
  // With no V/S ever selected, the default is 1500 ft/min.
  REQUIRE(sim.create("KL2", "A320", 52.0, 4.0, 0.0, units::fl_to_m(50), 150.0).is_ok());
  REQUIRE(sim.set_altitude("KL2", units::fl_to_m(90)).is_ok());
  REQUIRE(sim.run_for(10.0).is_ok());
  CHECK(t.vs[1] == doctest::Approx(units::fpm_to_ms(1500)));
}

TEST_CASE("speed change at the acceleration limit") {
  Simulation sim;
  REQUIRE(sim.create("KL1", "A320", 52.0, 4.0, 0.0, 0.0, 150.0).is_ok());
  REQUIRE(sim.set_speed("KL1", 170.0).is_ok());
  REQUIRE(sim.run_for(20.0).is_ok());
  const PerfLimits& p = perf_limits(PerfClass::kJet);
  CHECK(sim.traffic().tas[0] == doctest::Approx(150.0 + 20.0 * p.axmax));
  REQUIRE(sim.run_for(25.0).is_ok());
  CHECK(sim.traffic().tas[0] == doctest::Approx(170.0));
  CHECK(sim.traffic().cas[0] == doctest::Approx(170.0));
  // The class limit caps the selected speed.
  REQUIRE(sim.set_speed("KL1", 400.0).is_ok());
  REQUIRE(sim.run_for(200.0).is_ok());
  CHECK(sim.traffic().cas[0] == doctest::Approx(p.vmax));
}

TEST_CASE("ground cap reproduces BlueSky-Gym's measured 150 -> 89 m/s at 2 m/s^2") {
  Simulation sim;
  REQUIRE(sim.set_dt(5.0).is_ok());
  PerformanceOptions po;
  po.ground_cap = true;
  REQUIRE(sim.set_performance_options(po).is_ok());
  REQUIRE(sim.create("KL001", "A320", 52.0, 4.0, 0.0, 0.0, 150.0).is_ok());
  const double expect[] = {140, 130, 120, 110, 100, 90, 89, 89};
  for (double v : expect) {
    sim.step();
    CHECK(sim.traffic().tas[0] == doctest::Approx(v));
  }
  // Measured turn: 14.72 deg per 5 s step at 89 m/s (2.944 deg/s).
  REQUIRE(sim.set_heading("KL001", 45.0).is_ok());
  sim.step();
  CHECK(sim.traffic().hdg[0] == doctest::Approx(14.72).epsilon(1e-3));
  sim.step();
  sim.step();
  sim.step();
  CHECK(sim.traffic().hdg[0] == 45.0);
}

TEST_CASE("flat-earth position update with R = 6371 km") {
  Simulation sim;
  REQUIRE(sim.create("N", "A320", 52.0, 4.0, 0.0, 0.0, 150.0).is_ok());
  REQUIRE(sim.create("E", "A320", 52.0, 4.0, 90.0, 0.0, 150.0).is_ok());
  REQUIRE(sim.run_for(100.0).is_ok());
  const Traffic& t = sim.traffic();
  CHECK(t.lat[0] == doctest::Approx(52.0 + 15000.0 / 6371000.0 / kDeg).epsilon(1e-12));
  CHECK(t.lon[0] == doctest::Approx(4.0).epsilon(1e-12));
  // Eastward: lat stays, lon advances by dx / (R cos lat) each step.
  double lon = 4.0;
  for (int k = 0; k < 2000; ++k) lon += 0.05 * 150.0 / std::cos(52.0 * kDeg) / 6371000.0 / kDeg;
  CHECK(t.lat[1] == doctest::Approx(52.0).epsilon(1e-12));
  // CAS 150 -> TAS goes through pow(), 3e-10 off 150 m/s; hence 1e-9.
  CHECK(t.lon[1] == doctest::Approx(lon).epsilon(1e-9));
  CHECK(t.gsnorth[0] == doctest::Approx(150.0));
  CHECK(t.gseast[1] == doctest::Approx(150.0));
}
