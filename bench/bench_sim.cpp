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
// Whole-world traffic first (scenarios/whole_world.lua on BlueSky's
// airports.dat from $SQUAWK_NAVDATA or ../shared/bluesky/navdata; uniform over
// the sphere without it): simulated seconds per CPU second (x real time) at
// 3 750 and 25 000 aircraft with the grid detector and the all-pairs
// reference, detection cost, heap bytes per aircraft, the growth exponent of
// the cost of a simulated second with N, and two simulations side by side on
// two threads. Each whole-world rate is the best of --repeat runs (default 3)
// of a third of the budget each, the least disturbed on a shared machine;
// the load average is printed before and after.
//
// Usage: bench_sim [CPU seconds per row, default 1.0] [--world-only] [--repeat N]
#include <malloc.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "command/stack.h"
#include "core/files.h"
#include "core/geo.h"
#include "core/paths.h"
#include "core/rng.h"
#include "core/text.h"
#include "core/units.h"
#include "sim/conflict.h"
#include "sim/openap_data.h"
#include "sim/simulation.h"
#include "script/vm.h"

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
// Heap bytes in use (glibc), for bytes per aircraft.
double heap_bytes() {
  const struct mallinfo2 m = mallinfo2();
  return static_cast<double>(m.uordblks + m.hblkhd);
}

std::string navdata_dir() {
  if (const char* e = std::getenv("SQUAWK_NAVDATA"); e && *e) return e;
  const std::string shared = paths::home() + "/../shared/bluesky/navdata";
  return files::exists(shared + "/airports.dat") ? shared : "";
}

// A stack holding n whole-world flights (all airborne, no later commands),
// detection every 1 s with 5 NM / 1000 ft / 300 s, class performance model.
// With navdata: scenarios/whole_world.lua (seed 1) written to `tmp` and
// loaded; without: uniform over the sphere.
std::unique_ptr<command::Stack> world(int n, const std::string& nav, const std::string& tmp) {
  auto st = std::make_unique<command::Stack>(1);
  sim::Simulation& sim = st->sim();
  sim.set_openap(nullptr);
  if (!nav.empty()) {
    script::VmOptions vo;
    vo.seed = 1;
    vo.out_dir = tmp;
    vo.navdata_dir = nav;
    script::Vm vm(vo);
    const std::string name = "world_" + std::to_string(n) + ".scn";
    const Status gen = vm.run_file(paths::resource("scenarios/whole_world.lua"), {std::to_string(n), "0", name, "quiet"});
    if (!gen.is_ok()) {
      std::fprintf(stderr, "bench_sim: %s\n", gen.message().c_str());
      std::exit(1);
    }
    st->set_base_dir(tmp);
    const Status load = st->load_scenario(tmp + "/" + name);
    const Status run = load.is_ok() ? st->run_until(0.0) : load;
    if (!run.is_ok()) {
      std::fprintf(stderr, "bench_sim: %s\n", run.message().c_str());
      std::exit(1);
    }
  } else {
    Rng rng(1);
    for (int i = 0; i < n; ++i)
      (void)sim.create("W" + std::to_string(i), "A320", std::asin(rng.uniform(-1.0, 1.0)) / units::kDeg,
                       rng.uniform(-180.0, 180.0), rng.uniform(0.0, 360.0),
                       units::fl_to_m(300.0 + 10.0 * static_cast<double>(rng.uniform_int(0, 9))), 230.0);
  }
  sim.set_cd(true);
  (void)sim.set_asas_dt(1.0);
  return st;
}

int g_repeat = 3;  // --repeat: runs per whole-world rate, the best kept

// The load average (1, 5, 15 min) from /proc/loadavg, or "unknown".
std::string load_average() {
  const Result<std::string> s = files::read("/proc/loadavg");
  if (!s.is_ok()) return "unknown";
  const std::vector<std::string> f = text::split(*s, ' ');
  return f.size() >= 3 ? f[0] + " " + f[1] + " " + f[2] : "unknown";
}

// Simulated seconds per CPU second: whole simulated seconds (20 steps, one
// detection each) until `budget` CPU seconds have passed.
Rate real_time_once(sim::Simulation& sim, double budget) {
  const int steps = static_cast<int>(std::lround(1.0 / sim.dt()));
  const auto w0 = Clock::now();
  const double c0 = thread_cpu_s();
  double cpu = 0.0;
  int secs = 0;
  do {
    for (int k = 0; k < steps; ++k) sim.step();
    ++secs;
    cpu = thread_cpu_s() - c0;
  } while (cpu < budget);
  return {secs / cpu, cpu / wall_since(w0)};
}

// The best of g_repeat real_time_once runs of budget / g_repeat each, the
// simulation running on from one to the next.
Rate real_time(sim::Simulation& sim, double budget) {
  Rate best{0.0, 0.0};
  for (int k = 0; k < g_repeat; ++k) {
    const Rate r = real_time_once(sim, budget / g_repeat);
    if (r.per_cpu_s > best.per_cpu_s) best = r;
  }
  return best;
}

// Least-squares slope of log y against log x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0, my = 0;
  for (size_t k = 0; k < x.size(); ++k) mx += std::log(x[k]), my += std::log(y[k]);
  mx /= static_cast<double>(x.size()), my /= static_cast<double>(x.size());
  double sxy = 0, sxx = 0;
  for (size_t k = 0; k < x.size(); ++k) {
    const double dx = std::log(x[k]) - mx;
    sxy += dx * (std::log(y[k]) - my), sxx += dx * dx;
  }
  return sxy / sxx;
}

void world_section(double budget) {
  const std::string nav = navdata_dir();
  const std::string tmp = "/tmp/squawk_bench_sim_" + std::to_string(::getpid());
  (void)files::make_dirs(tmp);
  std::printf("whole-world traffic (%s), dt 0.05 s, CD every 1 s, 5 NM / 1000 ft, 300 s look-ahead, 1 thread, "
              "best of %d, load average %s\n",
              nav.empty() ? "uniform over the sphere: set SQUAWK_NAVDATA for scenarios/whole_world.lua"
                          : ("scenarios/whole_world.lua seed 1, " + nav).c_str(),
              g_repeat, load_average().c_str());
  std::printf("%8s  %-10s %12s %14s %9s %16s %11s %11s %9s\n", "aircraft", "detection", "x real time",
              "ms/detection", "CD share", "pairs examined", "conf pairs", "bytes/ac", "cpu/wall");
  std::vector<double> ns, grid_cost, ap_ns, ap_cost;
  double rt_grid_3750 = 0.0;
  for (const int n : {1000, 2000, 3750, 8000, 16000, 25000}) {
    const double h0 = heap_bytes();
    auto st = world(n, nav, tmp);
    st->sim().step();  // the first detection sizes the detector's buffers
    const double bytes = (heap_bytes() - h0) / n;
    const sim::Simulation& start = st->sim();
    // Both detectors on the same state: the same pairs, then their cost.
    sim::ConflictDetector grid, all;
    grid.detect(start.traffic(), start.cd_settings());
    all.detect_all_pairs(start.traffic(), start.cd_settings());
    bool same = grid.pairs().size() == all.pairs().size() && grid.los().size() == all.los().size();
    for (size_t k = 0; same && k < grid.pairs().size(); ++k) {
      const sim::ConflictPair &p = grid.pairs()[k], &q = all.pairs()[k];
      same = p.own == q.own && p.intruder == q.intruder && p.tcpa == q.tcpa && p.dcpa == q.dcpa && p.tlos == q.tlos;
    }
    if (!same) {
      std::fprintf(stderr, "bench_sim: grid and all-pairs detection differ at %d aircraft\n", n);
      std::exit(1);
    }
    const bool shown = n == 3750 || n == 25000;
    for (const bool ap : {false, true}) {
      if (ap && n > 8000 && n != 25000) continue;  // the reference is O(N^2): its fit stops at 8000
      sim::ConflictDetector& cd = ap ? all : grid;
      const Rate det = measure([&] { ap ? cd.detect_all_pairs(start.traffic(), start.cd_settings())
                                        : cd.detect(start.traffic(), start.cd_settings()); },
                               std::min(budget, 0.3));
      sim::Simulation sim = start;  // each method runs from the same state
      sim.set_cd_all_pairs(ap);
      const Rate rt = real_time(sim, budget);
      (ap ? ap_ns : ns).push_back(n);
      (ap ? ap_cost : grid_cost).push_back(1.0 / rt.per_cpu_s);
      if (!ap && n == 3750) rt_grid_3750 = rt.per_cpu_s;
      if (shown)
        std::printf("%8d  %-10s %12.1f %14.3f %8.1f%% %16lld %11zu %11.0f %9.2f\n", n, ap ? "all pairs" : "grid",
                    rt.per_cpu_s, 1e3 / det.per_cpu_s, 100.0 * rt.per_cpu_s / det.per_cpu_s,
                    static_cast<long long>(cd.examined()), cd.pairs().size() / 2, bytes, rt.cpu_share);
    }
  }
  if (ap_ns.back() == 25000) ap_ns.pop_back(), ap_cost.pop_back();
  std::printf("growth of the CPU time of a simulated second with N: grid N^%.2f (N = 1000..25000), "
              "all pairs N^%.2f (N = 1000..8000)\n", slope(ns, grid_cost), slope(ap_ns, ap_cost));

  // Two independent simulations of 3750 aircraft, one per thread.
  {
    auto a = world(3750, nav, tmp), b = world(3750, nav, tmp);
    Rate ra{}, rb{};
    const auto w0 = Clock::now();
    std::thread ta([&] { ra = real_time(a->sim(), budget); });
    std::thread tb([&] { rb = real_time(b->sim(), budget); });
    ta.join();
    tb.join();
    const double wall = wall_since(w0);
    std::printf("2 threads, one simulation of 3750 aircraft each: %.1f and %.1f x real time per CPU second "
                "(1 thread: %.1f), cpu/wall %.2f and %.2f, %.1f s wall\n",
                ra.per_cpu_s, rb.per_cpu_s, rt_grid_3750, ra.cpu_share, rb.cpu_share, wall);
  }
  std::error_code ec;
  std::filesystem::remove_all(tmp, ec);
  std::printf("load average after the whole-world rows: %s\n\n", load_average().c_str());
}
}  // namespace

int main(int argc, char** argv) {
  const double budget = argc > 1 ? std::atof(argv[1]) : 1.0;
  bool world_only = false;
  for (int k = 2; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--world-only") {
      world_only = true;
    } else if (a == "--repeat" && k + 1 < argc && std::atoi(argv[k + 1]) > 0) {
      g_repeat = std::atoi(argv[++k]);
    } else {
      std::fprintf(stderr, "bench_sim: unknown argument '%s'; usage: bench_sim [CPU s per row] [--world-only] "
                           "[--repeat N]\n", a.c_str());
      return 2;
    }
  }
  world_section(budget);
  if (world_only) return 0;
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
    std::printf("  (BlueSky measured ~800 us per sim step for this env: docs/bluesky_facts.md §6)\n");
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
