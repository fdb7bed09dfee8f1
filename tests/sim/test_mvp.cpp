#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "core/geo.h"
#include "core/units.h"
#include "sim/atmosphere.h"
#include "sim/simulation.h"

using namespace squawk;
using namespace squawk::sim;

namespace {
// Two aircraft head-on at FL100, 40 NM apart on the 52 N parallel.
Simulation head_on(bool reso) {
  Simulation sim;
  sim.set_cd(true);
  if (reso) sim.set_reso(true);
  REQUIRE(sim.create("A", "A320", 52.0, 4.0, 90.0, units::fl_to_m(100), 150.0).is_ok());
  REQUIRE(sim.create("B", "A320", 52.0, 4.0 + 40.0 / 60.0 / std::cos(52.0 * units::kDeg), 270.0,
                     units::fl_to_m(100), 150.0)
              .is_ok());
  return sim;
}

double hdist_m(const Traffic& t) { return units::nm_to_m(geo::kwikdist_nm(t.lat[0], t.lon[0], t.lat[1], t.lon[1])); }
}  // namespace

TEST_CASE("MVP moves two head-on aircraft apart and they resume after CPA") {
  Simulation off = head_on(false);
  double min_off = 1e9;
  for (int k = 0; k < 20 * 600; ++k) {
    off.step();
    min_off = std::min(min_off, hdist_m(off.traffic()));
  }
  CHECK(min_off < 200.0);  // unresolved: they meet

  Simulation sim = head_on(true);
  const Traffic& t = sim.traffic();
  double min_d = 1e9;
  bool turned = false, resumed_a = false;
  double cpa_time = -1;
  for (int k = 0; k < 20 * 900; ++k) {
    sim.step();
    min_d = std::min(min_d, hdist_m(t));
    if (t.cr_active[0] && std::fabs(geo::wrap180(t.hdg[0] - 90.0)) > 5.0) turned = true;
    if (cpa_time < 0 && t.lon[0] > t.lon[1]) cpa_time = sim.simt();
    if (cpa_time > 0 && !t.cr_active[0] && !t.cr_active[1]) resumed_a = true;
  }
  CHECK(turned);
  // Resolution aims at rpz * 1.05 at CPA; turn dynamics eat some of it.
  CHECK(min_d > 0.9 * sim.cd_settings().rpz);
  CHECK(cpa_time > 0);
  CHECK(resumed_a);
  // Back on the selected headings, no resolution pairs left.
  CHECK(t.hdg[0] == 90.0);
  CHECK(t.hdg[1] == 270.0);
  CHECK(sim.cr().reso_pairs().empty());
  CHECK(sim.conflicts().empty());
  // They pass on opposite sides: the head-on guard pushes perpendicular.
  CHECK(sim.cd().total_los() == 0);
}

TEST_CASE("MVP: resolution velocity of one pair follows the docs/bluesky_facts.md §3.3 formula") {
  Simulation sim = head_on(true);
  REQUIRE(sim.move("B", 52.05, 4.0 + 40.0 / 60.0 / std::cos(52.0 * units::kDeg)).is_ok());
  sim.step();  // detection + resolution at t = 0 on the initial state
  REQUIRE(sim.conflicts().size() == 2);
  const ConflictPair& c = sim.conflicts()[0];
  const Traffic& t = sim.traffic();
  // Reference written here: drel, vrel, dcpa at tcpa, erratum branch (outside the zone).
  const double rpz_m = sim.cd_settings().rpz * sim.cr_settings().resofach;
  const double q = c.qdr * units::kDeg;
  const double drel_e = std::sin(q) * c.dist, drel_n = std::cos(q) * c.dist;
  // Velocities at detection: east/west at the creation TAS.
  const double tas = cas_to_tas(150.0, units::fl_to_m(100));
  const double vrel_e = -2.0 * tas, vrel_n = 0.0;
  const double dcpa_e = drel_e + vrel_e * c.tcpa, dcpa_n = drel_n + vrel_n * c.tcpa;
  const double dabs = std::hypot(dcpa_e, dcpa_n);
  const double err = std::cos(std::asin(rpz_m / c.dist) - std::asin(dabs / c.dist));
  const double k = (rpz_m / err - dabs) / (std::fabs(c.tcpa) * dabs);
  const double ve = tas - k * dcpa_e, vn = -k * dcpa_n;
  CHECK(t.cr_active[0] == 1);
  CHECK(t.cr_trk[0] == doctest::Approx(geo::wrap360(std::atan2(ve, vn) / units::kDeg)).epsilon(1e-9));
  CHECK(t.cr_tas[0] == doctest::Approx(std::hypot(ve, vn)).epsilon(1e-9));
}

TEST_CASE("switching ASAS off clears pairs and resolutions") {
  Simulation sim = head_on(true);
  REQUIRE(sim.run_for(60.0).is_ok());
  // Resolved (no conflict predicted any more) but not yet past CPA.
  CHECK(sim.conflicts().empty());
  CHECK(!sim.cr().reso_pairs().empty());
  CHECK(sim.traffic().cr_active[0] == 1);
  sim.set_cd(false);
  CHECK(sim.conflicts().empty());
  CHECK(sim.traffic().cr_active[0] == 0);
  CHECK(sim.cr().reso_pairs().empty());
}

TEST_CASE("without PASTCPA, resolution is flown only while a conflict is detected") {
  Simulation sim = head_on(true);
  CHECK(sim.cr_settings().resume);
  sim.set_reso_resume(false);
  int releases = 0;
  uint8_t prev = 0;
  for (int k = 0; k < 20 * 300; ++k) {
    sim.step();
    const uint8_t now = sim.traffic().cr_active[0];
    CHECK(now == sim.cd().inconf()[0]);
    releases += prev && !now;
    prev = now;
  }
  // Once the new velocity clears the conflict the aircraft turns back, which
  // re-creates it: the release happens before CPA (BlueSky's chatter with
  // RESNAV OFF).
  CHECK(releases >= 1);
  CHECK(sim.cr().reso_pairs().empty());
}
