#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "core/geo.h"
#include "core/rng.h"
#include "core/units.h"
#include "sim/atmosphere.h"
#include "sim/conflict.h"
#include "sim/simulation.h"

using namespace squawk;
using namespace squawk::sim;
using units::kDeg;

namespace {
struct RefConf {
  bool conflict = false;
  bool los = false;
  double tcpa = 0, dcpa = 0, tlos = 0, qdr = 0, dist = 0;
};

// BlueSky statebased.py for one ordered pair, written from the formulas
// (docs/bluesky_facts.md §3.2) with the trig kwikqdrdist and per-pair scalars: a different
// code path from the detector's SoA loop.
RefConf ref_pair(const Traffic& t, int i, int j, const CdSettings& s) {
  const geo::QdrDist qd = geo::kwikqdrdist(t.lat[i], t.lon[i], t.lat[j], t.lon[j]);
  const double dist = qd.dist_nm * 1852.0;
  const double qdr = qd.qdr_deg * kDeg;
  const double dx = dist * std::sin(qdr), dy = dist * std::cos(qdr);
  const double du = t.gs[j] * std::sin(t.trk[j] * kDeg) - t.gs[i] * std::sin(t.trk[i] * kDeg);
  const double dv = t.gs[j] * std::cos(t.trk[j] * kDeg) - t.gs[i] * std::cos(t.trk[i] * kDeg);
  const double dv2 = std::max(du * du + dv * dv, 1e-6);
  const double vrel = std::sqrt(dv2);
  const double tcpa = -(du * dx + dv * dy) / dv2;
  const double dcpa2 = std::fabs(dist * dist - tcpa * tcpa * dv2);
  const double R = s.rpz, H = s.hpz;
  const bool hor = dcpa2 < R * R;
  const double dtin = std::sqrt(std::max(0.0, R * R - dcpa2)) / vrel;
  const double tinhor = hor ? tcpa - dtin : 1e8;
  const double touthor = hor ? tcpa + dtin : -1e8;
  const double dalt = t.alt[i] - t.alt[j];
  const double dvs = t.vs[i] - t.vs[j];
  const double hi = (dalt + H) / (-dvs), lo = (dalt - H) / (-dvs);  // IEEE inf when dvs = 0
  const double tinver = std::min(hi, lo), toutver = std::max(hi, lo);
  const double tin = std::max(tinver, tinhor), tout = std::min(toutver, touthor);
  RefConf r;
  r.conflict = hor && tin <= tout && tout > 0 && tin < s.dtlook;
  r.los = dist < R && std::fabs(dalt) < H;
  r.tcpa = tcpa;
  r.dcpa = std::sqrt(dcpa2);
  r.tlos = tin;
  r.qdr = qd.qdr_deg;
  r.dist = dist;
  return r;
}

// n aircraft in a 2 x 2 deg box around (52, 4), 3 flight levels, random
// tracks, speeds and vertical speeds (a third level).
Traffic random_traffic(int n, uint64_t seed) {
  Rng rng(seed);
  Traffic t;
  for (int i = 0; i < n; ++i) {
    t.append("AC" + std::to_string(i), "A320", static_cast<uint64_t>(i + 1));
    t.lat[i] = rng.uniform(51.0, 53.0);
    t.lon[i] = rng.uniform(3.0, 5.0);
    t.alt[i] = units::fl_to_m(static_cast<double>(rng.uniform_int(0, 2)) * 10.0 + 100.0) + rng.uniform(-50, 50);
    t.trk[i] = t.hdg[i] = rng.uniform(0.0, 360.0);
    t.gs[i] = t.tas[i] = rng.uniform(100.0, 250.0);
    t.vs[i] = rng.uniform() < 0.3 ? rng.uniform(-10.0, 10.0) : 0.0;
    t.gsnorth[i] = t.gs[i] * std::cos(t.trk[i] * kDeg);
    t.gseast[i] = t.gs[i] * std::sin(t.trk[i] * kDeg);
  }
  return t;
}
}  // namespace

TEST_CASE("CD on 10 000 random pairs agrees with a per-pair reference implementation") {
  const int n = 142;  // 142 * 141 / 2 = 10 011 unordered pairs
  CdSettings s;
  s.enabled = true;
  int total_conf = 0, total_los = 0;
  for (uint64_t seed : {1u, 2u, 3u}) {
    const Traffic t = random_traffic(n, seed);
    ConflictDetector cd;
    cd.detect(t, s);
    std::map<std::pair<int, int>, ConflictPair> got;
    for (const ConflictPair& p : cd.pairs()) got[{p.own, p.intruder}] = p;
    std::map<std::pair<int, int>, LosPair> got_los;
    for (const LosPair& p : cd.los()) got_los[{p.own, p.intruder}] = p;
    int nconf = 0, nlos = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        if (i == j) continue;
        const RefConf r = ref_pair(t, i, j, s);
        nconf += r.conflict;
        nlos += r.los;
        const auto it = got.find({i, j});
        CHECK_MESSAGE((it != got.end()) == r.conflict, "pair " << i << "," << j);
        CHECK((got_los.count({i, j}) == 1) == r.los);
        if (it == got.end() || !r.conflict) continue;
        const ConflictPair& p = it->second;
        CHECK(p.tcpa == doctest::Approx(r.tcpa).epsilon(1e-7));
        CHECK(p.dcpa == doctest::Approx(r.dcpa).epsilon(1e-6));
        CHECK(p.tlos == doctest::Approx(r.tlos).epsilon(1e-7));
        CHECK(p.dist == doctest::Approx(r.dist).epsilon(1e-9));
        CHECK(geo::wrap180(p.qdr - r.qdr) == doctest::Approx(0.0).epsilon(1e-7));
      }
    CHECK(static_cast<int>(cd.pairs().size()) == nconf);
    CHECK(static_cast<int>(cd.los().size()) == nlos);
    CHECK(cd.unique_conflicts().size() * 2 == cd.pairs().size());
    CHECK(cd.total_conflicts() == nconf / 2);
    total_conf += nconf;
    total_los += nlos;
    // Pairs are sorted by ownship then intruder, as BlueSky's confpairs.
    CHECK(std::is_sorted(cd.pairs().begin(), cd.pairs().end(),
                         [](const auto& a, const auto& b) { return std::make_pair(a.own, a.intruder) < std::make_pair(b.own, b.intruder); }));
  }
  // The data exercises both outcomes.
  CHECK(total_conf > 100);
  CHECK(total_los > 10);
}

TEST_CASE("CD vertical window: level aircraft 2000 ft apart are never in conflict") {
  Simulation sim;
  sim.set_cd(true);
  REQUIRE(sim.create("A", "A320", 52.0, 4.0, 90.0, units::fl_to_m(100), 150.0).is_ok());
  REQUIRE(sim.create("B", "A320", 52.0, 4.5, 270.0, units::fl_to_m(120), 150.0).is_ok());
  sim.step();
  CHECK(sim.conflicts().empty());
  // Same level: a head-on conflict with tcpa = dist / 300.
  REQUIRE(sim.move("B", 52.0, 4.5, units::fl_to_m(100), std::nullopt, 150.0).is_ok());
  REQUIRE(sim.run_for(1.0).is_ok());
  REQUIRE(sim.conflicts().size() == 2);
  const ConflictPair& p = sim.conflicts()[0];
  CHECK(p.own == 0);
  CHECK(p.qdr == doctest::Approx(90.0).epsilon(1e-3));
  CHECK(p.dcpa == doctest::Approx(0.0).epsilon(1e-3));
  const double closing = sim.traffic().tas[0] + sim.traffic().tas[1];  // CAS 150 at FL100: TAS 174
  CHECK(closing == doctest::Approx(2.0 * cas_to_tas(150.0, units::fl_to_m(100))));
  CHECK(p.tcpa == doctest::Approx(p.dist / closing).epsilon(1e-6));
  CHECK(p.tlos == doctest::Approx((p.dist - 9260.0) / closing).epsilon(1e-6));
  CHECK(sim.conflicts()[1].qdr == doctest::Approx(270.0).epsilon(1e-3));
}

TEST_CASE("CRECONFS: the detector sees the requested tLOS and dcpa") {
  // kwikpos places the intruder with 60 NM/deg and cos(lat_own); the detector
  // measures with 60.04 NM/deg and cos(mean lat), as in BlueSky. At the
  // equator only the 0.07 % scale differs; at 52 N the cosine adds up to
  // 0.5 % of the east-west offset.
  struct Case {
    double lat, tol_t, tol_d;  // [deg], relative, [m]
  };
  for (const Case c : {Case{0.0, 1.5e-3, 10.0}, Case{52.0, 1e-2, 300.0}})
    for (double dpsi : {45.0, 90.0, 180.0, 250.0, 314.0})
      for (double dcpa_nm : {0.0, 2.0, 4.0}) {
        Simulation sim;
        sim.set_cd(true);
        REQUIRE(sim.create("KL001", "A320", c.lat, 4.0, 0.0, 0.0, 150.0).is_ok());
        const double tlosh = 200.0;
        REQUIRE(sim.creconfs("0", "A320", "KL001", dpsi, units::nm_to_m(dcpa_nm), tlosh).is_ok());
        sim.step();
        REQUIRE(sim.conflicts().size() == 2);
        const ConflictPair& p = sim.conflicts()[0];
        CHECK(p.tlos == doctest::Approx(tlosh).epsilon(c.tol_t));
        CHECK(std::fabs(p.dcpa - units::nm_to_m(dcpa_nm)) < c.tol_d);
        const Traffic& t = sim.traffic();
        CHECK(t.gs[1] == doctest::Approx(t.gs[0]));
        CHECK(geo::wrap180(t.trk[1] - dpsi) == doctest::Approx(0.0).epsilon(1e-6));
      }
  // Flying it out: separation is lost at tLOS.
  Simulation sim;
  REQUIRE(sim.create("KL001", "A320", 0.0, 4.0, 0.0, 0.0, 150.0).is_ok());
  REQUIRE(sim.creconfs("0", "A320", "KL001", 120.0, units::nm_to_m(1.0), 200.0).is_ok());
  const Traffic& t = sim.traffic();
  double lost = -1;
  while (sim.simt() < 300.0 && lost < 0) {
    sim.step();
    if (geo::kwikdist_nm(t.lat[0], t.lon[0], t.lat[1], t.lon[1]) < 5.0) lost = sim.simt();
  }
  CHECK(lost == doctest::Approx(200.0).epsilon(3e-3));
  // Bad requests fail and name the culprit; nothing is created.
  CHECK(sim.creconfs("1", "A320", "NOPE", 90, 0, 100).message() == "NOPE: no aircraft with this id");
  CHECK(!sim.creconfs("1", "A320", "KL001", 90, -5, 100).is_ok());
  CHECK(!sim.creconfs("0", "A320", "KL001", 90, 0, 100).is_ok());
  CHECK(sim.n() == 2);
}

TEST_CASE("CRECONFS with a vertical offset closes in at the requested rate") {
  Simulation sim;
  sim.set_cd(true);
  REQUIRE(sim.create("OWN", "A320", 52.0, 4.0, 0.0, units::fl_to_m(100), 150.0).is_ok());
  REQUIRE(sim.creconfs("INT", "A320", "OWN", 90.0, 0.0, 200.0, units::ft_to_m(3000), 200.0).is_ok());
  const Traffic& t = sim.traffic();
  const double hpz = sim.cd_settings().hpz;
  CHECK(t.vs[1] == doctest::Approx(-(units::ft_to_m(3000) - hpz) / 200.0));
  CHECK(t.sel_alt[1] == doctest::Approx(t.alt[0]));
  sim.step();
  REQUIRE(sim.conflicts().size() == 2);
  CHECK(sim.conflicts()[0].tlos == doctest::Approx(200.0).epsilon(3e-3));
}

TEST_CASE("LoS and cumulative counts follow pairs in and out of conflict") {
  Simulation sim;
  sim.set_cd(true);
  REQUIRE(sim.create("A", "A320", 52.0, 4.0, 90.0, 3000.0, 150.0).is_ok());
  REQUIRE(sim.create("B", "A320", 52.0, 4.3, 270.0, 3000.0, 150.0).is_ok());
  int max_los = 0;
  for (int k = 0; k < 3000; ++k) {
    sim.step();
    max_los = std::max<int>(max_los, static_cast<int>(sim.los().size()));
  }
  CHECK(max_los == 2);
  CHECK(sim.cd().total_conflicts() == 1);
  CHECK(sim.cd().total_los() == 1);
  CHECK(sim.conflicts().empty());  // they have passed each other
  REQUIRE(sim.remove("A").is_ok());
  CHECK(sim.traffic().index_of("B") == 0);
}

TEST_CASE("detection runs every asas_dt of sim time, and on every step when asas_dt <= dt") {
  Simulation sim;
  sim.set_cd(true);
  REQUIRE(sim.create("A", "A320", 52.0, 4.0, 90.0, 3000.0, 150.0).is_ok());
  REQUIRE(sim.create("B", "A320", 52.0, 4.5, 270.0, 3000.0, 150.0).is_ok());
  sim.step();  // detection at t = 0
  REQUIRE(sim.conflicts().size() == 2);
  const double d0 = sim.conflicts()[0].dist;
  REQUIRE(sim.run_until(0.96).is_ok());  // steps starting at 0.05 .. 0.90: no detection
  CHECK(sim.conflicts()[0].dist == d0);
  sim.step();  // starts at t = 0.95 (< 1 s): still none
  CHECK(sim.conflicts()[0].dist == d0);
  sim.step();  // starts at t = 1.0: detection on the state at 1.0
  const double closing = sim.traffic().tas[0] + sim.traffic().tas[1];
  CHECK(sim.conflicts()[0].dist == doctest::Approx(d0 - closing * 1.0).epsilon(1e-6));
  REQUIRE(sim.set_asas_dt(0.01).is_ok());
  const double d1 = sim.conflicts()[0].dist;
  sim.step();
  sim.step();
  CHECK(sim.conflicts()[0].dist == doctest::Approx(d1 - closing * 0.1).epsilon(1e-6));
}

TEST_CASE("deleting an aircraft re-indexes the current pairs") {
  Simulation sim;
  sim.set_cd(true);
  REQUIRE(sim.create("A", "A320", 52.0, 4.0, 90.0, 3000.0, 150.0).is_ok());
  REQUIRE(sim.create("X", "A320", 10.0, 4.0, 0.0, 3000.0, 150.0).is_ok());  // far away
  REQUIRE(sim.create("B", "A320", 52.0, 4.5, 270.0, 3000.0, 150.0).is_ok());
  sim.step();
  REQUIRE(sim.conflicts().size() == 2);
  CHECK(sim.conflicts()[0].intruder == 2);
  REQUIRE(sim.remove("X").is_ok());
  REQUIRE(sim.conflicts().size() == 2);
  CHECK(sim.conflicts()[0].own == 0);
  CHECK(sim.conflicts()[0].intruder == 1);
  CHECK(sim.cd().inconf().size() == 2);
  REQUIRE(sim.remove("A").is_ok());
  CHECK(sim.conflicts().empty());
  sim.step();
}
