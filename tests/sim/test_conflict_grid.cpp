// The grid detector (ConflictDetector::detect) against the all-pairs
// reference (detect_all_pairs) on random, clustered and whole-world traffic,
// including the poles and the antimeridian, and the pair cap.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/rng.h"
#include "core/units.h"
#include "sim/conflict.h"

using namespace squawk;
using namespace squawk::sim;
using units::kDeg;

namespace {
enum class Kind { kRandom, kClustered, kWorld };

void put(Traffic& t, Rng& rng, double lat, double lon) {
  const int i = t.n();
  t.append("AC" + std::to_string(i), "A320", static_cast<uint64_t>(i + 1));
  t.lat[i] = std::clamp(lat, -90.0, 90.0);
  lon = std::fmod(lon + 540.0, 360.0) - 180.0;  // into [-180, 180)
  t.lon[i] = lon;
  // Three levels, a fifth climbing or descending; some pairs share a velocity.
  t.alt[i] = units::fl_to_m(300.0 + 10.0 * static_cast<double>(rng.uniform_int(0, 2)));
  t.vs[i] = rng.uniform() < 0.2 ? rng.uniform(-15.0, 15.0) : 0.0;
  const double gs = rng.uniform() < 0.05 ? 0.0 : rng.uniform(60.0, 300.0);
  const double trk = rng.uniform() < 0.1 ? 90.0 : rng.uniform(0.0, 360.0);
  t.gs[i] = t.tas[i] = gs;
  t.trk[i] = t.hdg[i] = trk;
  t.gsnorth[i] = gs * std::cos(trk * kDeg);
  t.gseast[i] = gs * std::sin(trk * kDeg);
}

// Adds a head-on partner to the last aircraft, at a share of the reach
// rpz + 2 gs dtlook ahead of it (same speed and level): a conflict that
// starts late in the look-ahead, at the edge of what the grid must hold.
void partner(Traffic& t, Rng& rng, const CdSettings& s) {
  const int i = t.n() - 1;
  const double d = rng.uniform(0.9, 1.0) * (s.rpz + 2.0 * t.gs[i] * std::max(s.dtlook, 0.0));
  const double trk = t.trk[i] * kDeg;
  const double lat = t.lat[i] + d * std::cos(trk) / units::kREarth / kDeg;
  const double lon = t.lon[i] + d * std::sin(trk) / units::kREarth / kDeg / std::cos(t.lat[i] * kDeg);
  if (!(std::fabs(lat) < 90.0) || !std::isfinite(lon)) return;
  put(t, rng, lat, lon);
  const int j = t.n() - 1;
  t.alt[j] = t.alt[i];
  t.vs[j] = t.vs[i];
  t.gs[j] = t.tas[j] = t.gs[i];
  t.trk[j] = t.hdg[j] = std::fmod(t.trk[i] + 180.0 + rng.uniform(-1.0, 1.0), 360.0);
  t.gsnorth[j] = t.gs[j] * std::cos(t.trk[j] * kDeg);
  t.gseast[j] = t.gs[j] * std::sin(t.trk[j] * kDeg);
}

// n aircraft (about) of the given kind, a tenth with a head-on partner at
// the reach. kRandom: a box of random size anywhere
// (poles and antimeridian included); kClustered: a few tight clusters;
// kWorld: uniform over the sphere, plus clusters on the antimeridian and
// within a degree of both poles, and aircraft exactly at +-90 / -180 / 180.
Traffic make(Kind kind, int n, Rng& rng, const CdSettings& s) {
  Traffic t;
  if (kind == Kind::kRandom) {
    const double lat0 = rng.uniform(-90.0, 90.0), lon0 = rng.uniform(-180.0, 180.0), w = rng.uniform(0.2, 25.0);
    for (int i = 0; i < n; ++i) put(t, rng, lat0 + rng.uniform(-w, w), lon0 + rng.uniform(-w, w));
  } else if (kind == Kind::kClustered) {
    const int k = static_cast<int>(rng.uniform_int(1, 6));
    for (int i = 0; i < n; ++i) {
      Rng c(static_cast<uint64_t>(i % k) + 1000);  // cluster centre from its number
      const double lat0 = c.uniform(-80.0, 80.0), lon0 = c.uniform(-180.0, 180.0), w = c.uniform(0.01, 0.5);
      put(t, rng, lat0 + rng.uniform(-w, w), lon0 + rng.uniform(-w, w));
    }
  } else {
    for (int i = 0; i < n; ++i) {
      const int pick = static_cast<int>(rng.uniform_int(0, 9));
      if (pick == 0) {
        put(t, rng, rng.uniform(-60.0, 60.0), 180.0 + rng.uniform(-1.0, 1.0));
      } else if (pick == 1) {
        put(t, rng, (rng.uniform() < 0.5 ? -1.0 : 1.0) * rng.uniform(89.0, 90.0), rng.uniform(-180.0, 180.0));
      } else if (pick == 2) {
        put(t, rng, (rng.uniform() < 0.5 ? -90.0 : 90.0), rng.uniform() < 0.5 ? -180.0 : 0.0);
        t.lon[t.n() - 1] = rng.uniform() < 0.5 ? 180.0 : t.lon[t.n() - 1];
      } else {
        put(t, rng, std::asin(rng.uniform(-1.0, 1.0)) / kDeg, rng.uniform(-180.0, 180.0));
      }
    }
  }
  for (int i = 0, n0 = t.n(); i < n0; ++i) {
    if (rng.uniform() >= 0.1) continue;
    // Re-add aircraft i's state as the last one, then its partner.
    put(t, rng, t.lat[i], t.lon[i]);
    partner(t, rng, s);
  }
  return t;
}

// Every field of both detectors' results, exactly.
void require_same(const ConflictDetector& a, const ConflictDetector& b) {
  REQUIRE(a.pairs().size() == b.pairs().size());
  for (size_t k = 0; k < a.pairs().size(); ++k) {
    const ConflictPair &p = a.pairs()[k], &q = b.pairs()[k];
    REQUIRE(p.own == q.own);
    REQUIRE(p.intruder == q.intruder);
    REQUIRE(std::fabs(p.tcpa - q.tcpa) <= 1e-9);
    REQUIRE(std::fabs(p.dcpa - q.dcpa) <= 1e-9);
    REQUIRE(std::fabs(p.tlos - q.tlos) <= 1e-9);
    REQUIRE(std::fabs(p.qdr - q.qdr) <= 1e-9);
    REQUIRE(std::fabs(p.dist - q.dist) <= 1e-9);
  }
  REQUIRE(a.los().size() == b.los().size());
  for (size_t k = 0; k < a.los().size(); ++k) {
    REQUIRE(a.los()[k].own == b.los()[k].own);
    REQUIRE(a.los()[k].intruder == b.los()[k].intruder);
    REQUIRE(a.los()[k].dist == b.los()[k].dist);
    REQUIRE(a.los()[k].dalt == b.los()[k].dalt);
  }
  REQUIRE(a.inconf() == b.inconf());
  REQUIRE(a.total_conflicts() == b.total_conflicts());
  REQUIRE(a.total_los() == b.total_los());
}
}  // namespace

TEST_CASE("grid CD finds exactly the all-pairs conflicts on random, clustered and whole-world traffic") {
  int64_t conflicts = 0, los = 0, across_antimeridian = 0, polar = 0, examined = 0, all_pairs = 0;
  for (uint64_t seed = 1; seed <= 240; ++seed) {
    Rng rng(seed);
    const Kind kind = static_cast<Kind>(seed % 3);
    const int n = static_cast<int>(rng.uniform_int(0, kind == Kind::kWorld ? 600 : 300));
    CdSettings s;
    s.enabled = true;
    const double looks[] = {300.0, 300.0, 60.0, 0.0, 1200.0};
    s.dtlook = looks[seed % 5];
    if (seed % 7 == 0) s.rpz = 50.0 * 1852.0;
    Traffic t = make(kind, n, rng, s);
    CAPTURE(seed);
    CAPTURE(n);
    ConflictDetector grid, ref;
    // Two detections with the traffic moved between them, for the counts.
    for (int round = 0; round < 2; ++round) {
      grid.detect(t, s);
      ref.detect_all_pairs(t, s);
      require_same(grid, ref);
      examined += grid.examined();
      all_pairs += ref.examined();
      for (int i = 0; i < t.n(); ++i) {
        t.lat[i] = std::clamp(t.lat[i] + 60.0 * t.gsnorth[i] / units::kREarth / kDeg, -90.0, 90.0);
        t.lon[i] = std::fmod(t.lon[i] + 60.0 * t.gseast[i] / units::kREarth / kDeg + 540.0, 360.0) - 180.0;
      }
    }
    conflicts += static_cast<int64_t>(grid.pairs().size());
    los += static_cast<int64_t>(grid.los().size());
    for (const ConflictPair& p : grid.pairs()) {
      across_antimeridian += std::fabs(t.lon[p.own] - t.lon[p.intruder]) > 180.0;
      polar += std::fabs(t.lat[p.own]) > 88.0;
    }
  }
  // The comparison is not vacuous: conflicts and LoS were found, some across
  // the antimeridian and near the poles, and the grid pruned most pairs.
  CHECK(conflicts > 1000);
  CHECK(los > 100);
  CHECK(across_antimeridian > 10);
  CHECK(polar > 10);
  CHECK(examined < all_pairs / 2);
}

TEST_CASE("grid CD across the pole: pairs whose longitudes differ by exactly 180 deg") {
  // Both orders of such a pair wrap the longitude difference to -180, so the
  // grid's pass 1 is not symmetric there; the pair must still match. 500
  // aircraft over the globe make the grid fine.
  int conflicts = 0;
  for (uint64_t seed = 1; seed <= 100; ++seed) {
    Rng rng(seed);
    Traffic t;
    for (int i = 0; i < 500; ++i) put(t, rng, std::asin(rng.uniform(-1.0, 1.0)) / kDeg, rng.uniform(-180.0, 180.0));
    const double side = rng.uniform() < 0.5 ? -1.0 : 1.0;
    const double lon = -0.5 * static_cast<double>(rng.uniform_int(0, 360));  // lon + 180 exact
    put(t, rng, side * rng.uniform(89.9, 89.99), lon);
    put(t, rng, side * rng.uniform(89.9, 89.99), lon + 180.0);
    for (int i = 500; i < 502; ++i) t.alt[i] = 10000.0, t.vs[i] = 0.0;
    CdSettings s;
    s.enabled = true;
    s.dtlook = rng.uniform(0.0, 100.0);
    ConflictDetector grid, ref;
    grid.detect(t, s);
    ref.detect_all_pairs(t, s);
    CAPTURE(seed);
    require_same(grid, ref);
    conflicts += static_cast<int>(grid.pairs().size());
  }
  CHECK(conflicts > 20);
}

TEST_CASE("grid CD on whole-world traffic examines a small share of the pairs") {
  Rng rng(5);
  Traffic t;
  for (int i = 0; i < 20000; ++i) put(t, rng, std::asin(rng.uniform(-1.0, 1.0)) / kDeg, rng.uniform(-180.0, 180.0));
  CdSettings s;
  s.enabled = true;
  ConflictDetector cd;
  cd.detect(t, s);
  const double all = 20000.0 * 19999.0 / 2.0;
  CHECK(static_cast<double>(cd.examined()) < 0.02 * all);
  CHECK_FALSE(cd.truncated());
}

TEST_CASE("traffic outside the grid's domain falls back to all pairs with the same results") {
  Rng rng(9);
  CdSettings s;
  s.enabled = true;
  Traffic t = make(Kind::kClustered, 200, rng, s);
  t.lon[3] = 200.0;  // outside [-180, 180]
  t.gseast[7] = std::nan("");
  ConflictDetector grid, ref;
  grid.detect(t, s);
  ref.detect_all_pairs(t, s);
  require_same(grid, ref);
  CHECK(grid.examined() == ref.examined());
}

TEST_CASE("conflict bookkeeping is capped at max_pairs and says so") {
  // 1500 aircraft at one point, level, all in LoS with each other: 1.1 M pairs.
  Traffic t;
  Rng rng(1);
  for (int i = 0; i < 1500; ++i) {
    put(t, rng, 52.0, 4.0);
    t.alt[i] = 3000.0;
    t.vs[i] = 0.0;
  }
  CdSettings s;
  s.enabled = true;
  ConflictDetector cd;
  cd.detect(t, s);
  CHECK(cd.truncated());
  CHECK(static_cast<int64_t>(cd.pairs().size()) == 2 * s.max_pairs);
  CHECK(static_cast<int64_t>(cd.los().size()) == 2 * s.max_pairs);
  s.max_pairs = 10;
  cd.detect(t, s);
  CHECK(cd.truncated());
  CHECK(cd.pairs().size() == 20);
  CHECK(cd.los().size() == 20);
  // Under the cap nothing is flagged.
  Traffic few;
  for (int i = 0; i < 4; ++i) put(few, rng, 52.0, 4.0);
  cd.detect(few, s);
  CHECK_FALSE(cd.truncated());
}
