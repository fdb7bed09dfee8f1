// Simulation throughput: aircraft-steps per second with conflict detection
// off, every asas_dt = 1 s (BlueSky's default; every 20th step at dt 0.05 s)
// and every step, for 100, 1000 and 5000 aircraft; one thread (the simulator
// is single-threaded). Also the env's shape (6 aircraft, dt 5 s) and, as a
// same-run reference, a per-pair CD using the trig kwikqdrdist.
//
// Usage: bench_sim [seconds per row, default 1.0]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/geo.h"
#include "core/rng.h"
#include "core/units.h"
#include "sim/conflict.h"
#include "sim/simulation.h"

using namespace squawk;
using namespace squawk::sim;
using Clock = std::chrono::steady_clock;

namespace {
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// n aircraft in a 3 x 3 deg box, flight levels 100-300 every 1000 ft, 20 %
// climbing or descending.
Simulation make_sim(int n, uint64_t seed) {
  Simulation sim(seed);
  Rng rng(seed);
  for (int i = 0; i < n; ++i) {
    const double alt = units::fl_to_m(100.0 + 10.0 * static_cast<double>(rng.uniform_int(0, 20)));
    const std::string id = "AC" + std::to_string(i);
    (void)sim.create(id, "A320", rng.uniform(50.5, 53.5), rng.uniform(2.5, 5.5), rng.uniform(0.0, 360.0), alt,
                     rng.uniform(120.0, 160.0));
    if (rng.uniform() < 0.2) (void)sim.set_altitude(id, alt + rng.uniform(-3000.0, 3000.0));
  }
  return sim;
}

// Steps `sim` for about `budget` seconds; returns steps per second.
double steps_per_s(Simulation& sim, double budget) {
  int64_t steps = 0;
  const auto t0 = Clock::now();
  double el = 0.0;
  do {
    sim.step();
    ++steps;
    el = seconds_since(t0);
  } while (el < budget || steps < 3);
  return static_cast<double>(steps) / el;
}

// Reference CD: per ordered pair, trig kwikqdrdist + the same formulas.
int reference_cd(const Traffic& t, const CdSettings& s) {
  int nconf = 0;
  const double kDeg = units::kDeg;
  for (int i = 0; i < t.n(); ++i)
    for (int j = 0; j < t.n(); ++j) {
      if (i == j) continue;
      const geo::QdrDist qd = geo::kwikqdrdist(t.lat[i], t.lon[i], t.lat[j], t.lon[j]);
      const double dist = qd.dist_nm * 1852.0, q = qd.qdr_deg * kDeg;
      const double dx = dist * std::sin(q), dy = dist * std::cos(q);
      const double du = t.gs[j] * std::sin(t.trk[j] * kDeg) - t.gs[i] * std::sin(t.trk[i] * kDeg);
      const double dv = t.gs[j] * std::cos(t.trk[j] * kDeg) - t.gs[i] * std::cos(t.trk[i] * kDeg);
      const double dv2 = std::max(du * du + dv * dv, 1e-6);
      const double tcpa = -(du * dx + dv * dy) / dv2;
      const double dcpa2 = std::fabs(dist * dist - tcpa * tcpa * dv2);
      if (dcpa2 >= s.rpz * s.rpz) continue;
      const double dtin = std::sqrt(s.rpz * s.rpz - dcpa2) / std::sqrt(dv2);
      const double dalt = t.alt[i] - t.alt[j], dvs = t.vs[i] - t.vs[j];
      const double hi = (dalt + s.hpz) / -dvs, lo = (dalt - s.hpz) / -dvs;
      const double tin = std::max(std::min(hi, lo), tcpa - dtin);
      const double tout = std::min(std::max(hi, lo), tcpa + dtin);
      nconf += tin <= tout && tout > 0 && tin < s.dtlook;
    }
  return nconf;
}
}  // namespace

int main(int argc, char** argv) {
  const double budget = argc > 1 ? std::atof(argv[1]) : 1.0;
  std::printf("squawk sim benchmark, 1 thread, dt 0.05 s, %.1f s per row\n\n", budget);
  std::printf("%8s  %-22s %14s %16s %10s\n", "aircraft", "conflict detection", "steps/s", "aircraft-steps/s",
              "conf pairs");
  for (int n : {100, 1000, 5000}) {
    struct Mode {
      const char* name;
      bool cd;
      double asas_dt;
    };
    for (const Mode m : {Mode{"off", false, 1.0}, Mode{"every 1 s (BlueSky)", true, 1.0},
                         Mode{"every step", true, kDefaultDt}}) {
      Simulation sim = make_sim(n, 42);
      sim.set_cd(m.cd);
      (void)sim.set_asas_dt(m.asas_dt);
      const double sps = steps_per_s(sim, budget);
      std::printf("%8d  %-22s %14.1f %16.3e %10zu\n", n, m.name, sps, sps * n, sim.conflicts().size());
    }
  }

  // The RL environment's shape: 6 aircraft, dt 5 s, CD off.
  {
    Simulation sim = make_sim(6, 7);
    (void)sim.set_dt(5.0);
    const double sps = steps_per_s(sim, budget);
    std::printf("\nenv shape (6 aircraft, dt 5 s, CD off): %.3e steps/s = %.3f us/step\n", sps, 1e6 / sps);
    std::printf("  (BlueSky measured ~800 us per sim step for this env: facts/bluesky_gym_measured.md)\n");
  }

  // Same-run reference: one detection at 1000 aircraft, SoA loop vs per-pair trig path.
  {
    Simulation sim = make_sim(1000, 42);
    CdSettings s;
    s.enabled = true;
    ConflictDetector cd;
    int reps = 0;
    auto t0 = Clock::now();
    do {
      cd.detect(sim.traffic(), s);
      ++reps;
    } while (seconds_since(t0) < budget);
    const double soa = seconds_since(t0) / reps;
    int reps_ref = 0, nref = 0;
    t0 = Clock::now();
    do {
      nref = reference_cd(sim.traffic(), s);
      ++reps_ref;
    } while (seconds_since(t0) < budget);
    const double ref = seconds_since(t0) / reps_ref;
    std::printf("\none detection, 1000 aircraft: SoA loop %.2f ms (%zu pairs), per-pair trig reference %.2f ms (%d pairs): %.1fx\n",
                soa * 1e3, cd.pairs().size(), ref * 1e3, nref, ref / soa);
  }
  return 0;
}
