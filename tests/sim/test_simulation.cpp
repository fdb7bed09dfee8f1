#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core/geo.h"
#include "core/rng.h"
#include "core/units.h"
#include "sim/simulation.h"

using namespace squawk;
using namespace squawk::sim;

TEST_CASE("clock: no drift after 10^6 steps") {
  Simulation sim;
  double naive = 0.0;
  for (int k = 0; k < 1000000; ++k) {
    sim.step();
    naive += kDefaultDt;
  }
  CHECK(sim.ticks() == 1000000);
  CHECK(sim.simt() == 50000.0);           // exact
  CHECK(std::fabs(naive - 50000.0) > 0.0);  // what summing dt would have given
  // Changing dt rebases; time stays exact on each grid.
  REQUIRE(sim.set_dt(5.0).is_ok());
  for (int k = 0; k < 1000; ++k) sim.step();
  CHECK(sim.simt() == 55000.0);
  CHECK(!sim.set_dt(0.0).is_ok());
  CHECK(!sim.set_dt(NAN).is_ok());
  CHECK(sim.dt() == 5.0);
}

TEST_CASE("run_for / run_until land on the dt grid") {
  Simulation sim;
  REQUIRE(sim.run_for(10.0).is_ok());
  CHECK(sim.ticks() == 200);
  CHECK(sim.simt() == 10.0);
  REQUIRE(sim.run_until(10.02).is_ok());  // the next step would end at 10.05
  CHECK(sim.ticks() == 200);
  REQUIRE(sim.run_until(10.03).is_ok());
  CHECK(sim.ticks() == 201);
  CHECK(!sim.run_for(-1.0).is_ok());
  CHECK(!sim.run_until(INFINITY).is_ok());
}

TEST_CASE("HOLD, OP and FF with and without end time") {
  Simulation sim;
  CHECK(sim.run_state() == RunState::kHold);
  CHECK(sim.advance(1.0, 1000) == 0);  // held
  sim.op();
  CHECK(sim.advance(0.12, 1000) == 2);  // 0.12 s of wall time -> 2 steps, 0.02 carried
  CHECK(sim.advance(0.03, 1000) == 1);
  REQUIRE(sim.fast_forward(30.0).is_ok());
  const double t0 = sim.simt();
  CHECK(sim.advance(0.0, 100) == 100);  // step budget respected
  CHECK(sim.fast());
  sim.advance(0.0, 1000000);
  CHECK(sim.simt() == doctest::Approx(t0 + 30.0));
  CHECK(!sim.fast());
  CHECK(sim.run_state() == RunState::kOp);
  REQUIRE(sim.fast_forward(std::nullopt).is_ok());
  CHECK(sim.advance(0.0, 5000) == 5000);  // no end time: runs until told
  CHECK(sim.fast());
  sim.hold();
  CHECK(!sim.fast());
  CHECK(sim.advance(10.0, 1000) == 0);
  CHECK(!sim.fast_forward(-1.0).is_ok());
}

TEST_CASE("OP ends fast-time and sets DTMULT 1, as BlueSky; so does the end of an FF with a time") {
  Simulation sim;
  REQUIRE(sim.fast_forward(std::nullopt).is_ok());
  sim.set_dtmult(4.0);
  sim.op();
  CHECK(!sim.fast());
  CHECK(!sim.ff_end());
  CHECK(sim.run_state() == RunState::kOp);
  CHECK(sim.dtmult() == 1.0);
  CHECK(sim.advance(0.1, 1000) == 2);  // real time: 0.1 s of wall time -> 2 steps of 0.05 s
  sim.set_dtmult(4.0);
  sim.hold();
  CHECK(sim.dtmult() == 4.0);  // HOLD keeps the multiplier
  REQUIRE(sim.fast_forward(10.0).is_ok());
  CHECK(sim.dtmult() == 4.0);  // FF keeps it while it runs
  sim.advance(0.0, 1000000);
  CHECK(!sim.fast());
  CHECK(sim.run_state() == RunState::kOp);  // a held clock runs on after FF, as BlueSky
  CHECK(sim.dtmult() == 1.0);
}

TEST_CASE("create validates and names the culprit") {
  Simulation sim;
  REQUIRE(sim.create("kl204", "b744", 52.0, 4.0, 370.0, 3000.0, 0.8).is_ok());
  const Traffic& t = sim.traffic();
  CHECK(t.id[0] == "KL204");
  CHECK(t.type[0] == "B744");
  CHECK(t.hdg[0] == doctest::Approx(10.0));
  CHECK(t.mach[0] == doctest::Approx(0.8));
  CHECK(sim.index_of("Kl204") == 0);
  Status dup = sim.create("KL204", "A320", 52.0, 4.0, 0.0, 0.0, 150.0);
  CHECK(dup.message() == "KL204: an aircraft with this id already exists");
  CHECK(sim.create("X1", "A320", 91.0, 4.0, 0.0, 0.0, 150.0).message().find("latitude") != std::string::npos);
  CHECK(!sim.create("X1", "A320", 52.0, 190.0, 0.0, 0.0, 150.0).is_ok());
  CHECK(!sim.create("X1", "A320", 52.0, 4.0, NAN, 0.0, 150.0).is_ok());
  CHECK(!sim.create("X1", "A320", 52.0, 4.0, 0.0, 99999.0, 150.0).is_ok());
  CHECK(!sim.create("X1", "A320", 52.0, 4.0, 0.0, 0.0, -5.0).is_ok());
  CHECK(!sim.create("", "A320", 52.0, 4.0, 0.0, 0.0, 150.0).is_ok());
  CHECK(!sim.create("A B", "A320", 52.0, 4.0, 0.0, 0.0, 150.0).is_ok());
  CHECK(!sim.create("X1", "", 52.0, 4.0, 0.0, 0.0, 150.0).is_ok());
  CHECK(sim.n() == 1);
  CHECK(sim.set_heading("NOPE", 90).message() == "NOPE: no aircraft with this id");
  CHECK(sim.set_heading("NOPE", 90).code() == Code::kNotFound);
}

TEST_CASE("delete keeps arrays dense and in order") {
  Simulation sim;
  for (const char* id : {"A", "B", "C", "D"}) REQUIRE(sim.create(id, "A320", 52.0, 4.0, 0.0, 0.0, 150.0).is_ok());
  REQUIRE(sim.remove("b").is_ok());
  const Traffic& t = sim.traffic();
  CHECK(t.n() == 3);
  CHECK(t.id == std::vector<std::string>{"A", "C", "D"});
  CHECK(t.index_of("C") == 1);
  CHECK(t.index_of("D") == 2);
  CHECK(t.index_of("B") == -1);
  CHECK(t.lat.size() == 3);
  CHECK(t.route.size() == 3);
  CHECK(!sim.remove("B").is_ok());
  sim.delete_all();
  CHECK(sim.n() == 0);
  REQUIRE(sim.create("A", "A320", 52.0, 4.0, 0.0, 0.0, 150.0).is_ok());
}

namespace {
Waypoint waypoint(const char* name, double lat, double lon) {
  Waypoint w;
  w.name = name;
  w.lat = lat;  // [deg]
  w.lon = lon;  // [deg]
  return w;
}

Simulation busy_sim() {
  Simulation sim(7);
  sim.set_reso(true);
  REQUIRE(sim.create("A", "A320", 52.0, 4.0, 90.0, 3000.0, 150.0).is_ok());
  REQUIRE(sim.create("B", "A320", 52.0, 4.4, 270.0, 3000.0, 150.0).is_ok());
  REQUIRE(sim.create("C", "AT72", 52.2, 4.2, 180.0, 2000.0, 110.0).is_ok());
  REQUIRE(sim.add_waypoint("C", waypoint("WP", 52.5, 4.5)).is_ok());
  REQUIRE(sim.set_altitude("A", 4000.0, 5.0).is_ok());
  REQUIRE(sim.run_for(30.0).is_ok());
  return sim;
}
}  // namespace

TEST_CASE("copy is deep and snapshot bytes track state") {
  Simulation a = busy_sim();
  Simulation b = a;
  CHECK(a.snapshot() == b.snapshot());
  a.step();
  CHECK(a.snapshot() != b.snapshot());
  b.step();
  CHECK(a.snapshot() == b.snapshot());  // deterministic
  REQUIRE(b.set_heading("C", 200.0).is_ok());
  CHECK(a.snapshot() != b.snapshot());
  CHECK(a.traffic().sel_hdg[2] != 200.0);  // the copy does not share state
  Simulation c = a;
  c.rng().next_u64();
  CHECK(c.snapshot() != a.snapshot());  // the RNG state is part of the image
}

TEST_CASE("property: a failed operation leaves the state byte for byte unchanged") {
  Simulation sim = busy_sim();
  const std::string before = sim.snapshot();
  Rng rng(11);
  const std::vector<std::function<Status(Simulation&)>> bad_ops = {
      [](Simulation& s) { return s.create("A", "A320", 52, 4, 0, 0, 150); },
      [](Simulation& s) { return s.create("Z", "A320", 52, 4, 0, 0, -1); },
      [](Simulation& s) { return s.creconfs("Z", "A320", "A", 90, -1, 100); },
      [](Simulation& s) { return s.creconfs("Z", "A320", "Q", 90, 0, 100); },
      [](Simulation& s) { return s.creconfs("Z", "A320", "A", 90, 0, 100, 1e9); },
      [](Simulation& s) { return s.remove("Q"); },
      [](Simulation& s) { return s.move("A", 95, 4); },
      [](Simulation& s) { return s.move("A", 52, 4, 1e6); },
      [](Simulation& s) { return s.move("A", 52, 4, 100.0, NAN); },
      [](Simulation& s) { return s.move("A", 52, 4, 100.0, 10.0, -1.0); },
      [](Simulation& s) { return s.set_heading("A", INFINITY); },
      [](Simulation& s) { return s.set_altitude("A", -5000); },
      [](Simulation& s) { return s.set_altitude("A", 3000, 0.0); },
      [](Simulation& s) { return s.set_vs("A", NAN); },
      [](Simulation& s) { return s.set_speed("A", -10); },
      [](Simulation& s) { return s.set_bank("A", 95); },
      [](Simulation& s) { return s.set_lnav("A", true); },
      [](Simulation& s) { return s.set_vnav("B", true); },
      [](Simulation& s) { return s.direct_to("C", "NOPE"); },
      [](Simulation& s) { return s.delete_waypoint("C", "NOPE"); },
      [](Simulation& s) { return s.add_waypoint_after("C", "NOPE", Waypoint{"X", 52, 4}); },
      [](Simulation& s) { return s.set_dest("C", Waypoint{"X", 100, 4}); },
      [](Simulation& s) { return s.set_rpz(-1); },
      [](Simulation& s) { return s.set_hpz(0); },
      [](Simulation& s) { return s.set_dtlook(NAN); },
      [](Simulation& s) { return s.set_asas_dt(-2); },
      [](Simulation& s) { return s.set_resofach(0.5); },
      [](Simulation& s) { return s.set_resofacv(NAN); },
      [](Simulation& s) { return s.set_dt(-1); },
      [](Simulation& s) { return s.fast_forward(-3.0); },
      [](Simulation& s) { return s.run_for(NAN); },
      [](Simulation& s) { return s.set_performance_options(PerformanceOptions{true, -1.0, 89.0, 2.0}); },
  };
  for (int k = 0; k < 300; ++k) {
    const size_t which = static_cast<size_t>(rng.uniform_int(0, static_cast<int64_t>(bad_ops.size()) - 1));
    const Status st = bad_ops[which](sim);
    CHECK_MESSAGE(!st.is_ok(), "op " << which);
    CHECK_MESSAGE(!st.message().empty(), "op " << which);
    REQUIRE_MESSAGE(sim.snapshot() == before, "op " << which << " changed the state: " << st.message());
  }
}

TEST_CASE("the autopilot's distance to the waypoint is BlueSky's qdrdist of the current position, after MOVE too") {
  // The autopilot reads the latitude's sine and cosine kept by the step and
  // by MOVE; a stale cache would move dist2wp off the direct formula by a
  // step's travel (several metres here). The step's vectorised trigonometry (vmath.h)
  // is within a few ulp of it: 1e-6 m.
  Simulation sim(3);
  REQUIRE(sim.create("A", "A320", 51.0, 2.0, 45.0, 9000.0, 130.0).is_ok());
  const Waypoint w = waypoint("FAR", 60.0, 25.0);
  REQUIRE(sim.add_waypoint("A", w).is_ok());
  const Traffic& t = sim.traffic();
  const auto direct = [&] { return units::nm_to_m(geo::qdrdist(t.lat[0], t.lon[0], w.lat, w.lon).dist_nm); };
  for (int k = 0; k < 3; ++k) {
    const double before = direct();
    sim.step();  // the autopilot runs on the position before this step's move
    CHECK(std::fabs(t.dist2wp[0] - before) < 1e-6);
  }
  REQUIRE(sim.move("A", -20.0, 100.0).is_ok());
  const double moved = direct();
  sim.step();
  CHECK(std::fabs(t.dist2wp[0] - moved) < 1e-6);
}
