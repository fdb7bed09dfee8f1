// Simulation throughput: aircraft-steps per second with conflict detection
// off, every asas_dt = 1 s (BlueSky's default; every 20th step at dt 0.05 s)
// and every step, for 100, 1000 and 5000 aircraft; one thread (the simulator
// is single-threaded). Also BlueSky-Gym's scene (6 aircraft, dt 5 s) and, as a
// same-run reference, a per-pair CD using the trig kwikqdrdist.
//
// Rates are per second of this thread's CPU time (CLOCK_THREAD_CPUTIME_ID),
// so other processes on a shared machine do not deflate them; the wall-clock
// share (cpu / wall) of each row is printed alongside.
//
// Usage: bench_sim [CPU seconds per row, default 1.0]
#include <time.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "core/geo.h"
#include "core/rng.h"
#include "core/units.h"
#include "sim/conflict.h"
#include "sim/openap_data.h"
#include "sim/simulation.h"

using namespace squawk;
using namespace squawk::sim;
using Clock = std::chrono::steady_clock;

namespace {
double wall_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

double thread_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct Rate {
  double per_cpu_s;  // [1/s] events per CPU second
  double cpu_share;  // [-] CPU time / wall time over the measurement
};

// Calls f() until `budget` CPU seconds (and at least 3 calls) have passed.
template <class F>
Rate measure(F&& f, double budget) {
  int64_t calls = 0;
  const auto w0 = Clock::now();
  const double c0 = thread_cpu_s();
  double cpu = 0.0;
  do {
    f();
    ++calls;
    cpu = thread_cpu_s() - c0;
  } while (cpu < budget || calls < 3);
  return {static_cast<double>(calls) / cpu, cpu / wall_since(w0)};
}

// n aircraft in a 3 x 3 deg box, flight levels 100-300 every 1000 ft, 20 %
// climbing or descending.
// Performance model: `openap` (null: the class model).
Simulation make_sim(int n, uint64_t seed, std::shared_ptr<const OpenapData> openap = nullptr) {
  Simulation sim(seed);
  sim.set_openap(std::move(openap));
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
  std::printf("%8s  %-22s %14s %16s %10s %9s\n", "aircraft", "conflict detection", "steps/s", "aircraft-steps/s",
              "conf pairs", "cpu/wall");
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
      const Rate r = measure([&] { sim.step(); }, budget);
      std::printf("%8d  %-22s %14.1f %16.3e %10zu %9.2f\n", n, m.name, r.per_cpu_s, r.per_cpu_s * n,
                  sim.conflicts().size(), r.cpu_share);
    }
  }

  // The same traffic with OpenAP performance (SQUAWK_OPENAP) beside the class model.
  if (const auto oap = default_openap()) {
    std::printf("\nperformance model (CD every 1 s): class vs OpenAP (%s)\n", oap->dir().c_str());
    std::printf("%8s  %-10s %14s %16s %9s\n", "aircraft", "model", "steps/s", "aircraft-steps/s", "ratio");
    for (int n : {100, 1000, 5000}) {
      double base = 0.0;
      for (const bool use : {false, true}) {
        Simulation sim = make_sim(n, 42, use ? oap : nullptr);
        sim.set_cd(true);
        const Rate r = measure([&] { sim.step(); }, budget);
        if (!use) base = r.per_cpu_s;
        std::printf("%8d  %-10s %14.1f %16.3e %9.2f\n", n, use ? "OpenAP" : "class", r.per_cpu_s, r.per_cpu_s * n,
                    base / r.per_cpu_s);
      }
    }
  } else {
    std::printf("\n(set SQUAWK_OPENAP=DIR to time the OpenAP performance model beside the class model)\n");
  }

  // The RL environment's shape: BlueSky-Gym's scene (ownship at altitude 0,
  // five CRECONFS intruders, ground cap, dt 5 s, CD off), a new HDG every
  // 10 steps as the env's actions.
  {
    Simulation sim(7);
    sim.set_openap(nullptr);  // the env shape uses the class model with the ground cap
    (void)sim.set_dt(5.0);
    PerformanceOptions po;
    po.ground_cap = true;
    (void)sim.set_performance_options(po);
    (void)sim.create("KL001", "A320", 52.0, 4.0, 0.0, 0.0, 150.0);
    for (int k = 0; k < 5; ++k)
      (void)sim.creconfs(std::to_string(k), "A320", "KL001", 60.0 * (k + 1), 1852.0 * k, 300.0 + 100.0 * k);
    int64_t steps = 0;
    const Rate r = measure(
        [&] {
          if (steps++ % 10 == 0) (void)sim.set_heading("KL001", (steps % 20 == 1) ? 30.0 : 330.0);
          sim.step();
        },
        budget);
    std::printf("\nenv shape (6 aircraft, dt 5 s, CD off, HDG every 10 steps): %.3e steps/s = %.3f us/step (cpu/wall %.2f)\n",
                r.per_cpu_s, 1e6 / r.per_cpu_s, r.cpu_share);
    std::printf("  (BlueSky measured ~800 us per sim step for this env: facts/bluesky_gym_measured.md)\n");
  }

  // Same-run reference: one detection at 1000 aircraft, SoA loop vs per-pair trig path.
  {
    Simulation sim = make_sim(1000, 42);
    CdSettings s;
    s.enabled = true;
    ConflictDetector cd;
    const Rate soa = measure([&] { cd.detect(sim.traffic(), s); }, budget);
    int nref = 0;
    const Rate ref = measure([&] { nref = reference_cd(sim.traffic(), s); }, budget);
    std::printf("\none detection, 1000 aircraft: SoA loop %.2f ms (%zu pairs), per-pair trig reference %.2f ms (%d pairs): %.1fx\n",
                1e3 / soa.per_cpu_s, cd.pairs().size(), 1e3 / ref.per_cpu_s, nref, soa.per_cpu_s / ref.per_cpu_s);
  }
  return 0;
}
