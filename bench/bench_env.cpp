// Environment throughput: env steps per second of HorizontalCrEnv under both
// rule sets, on one thread and on two (one environment per thread), next to a
// same-run reference: a plain re-statement of the same BlueSky update that
// recomputes every cos/sin/atan2 the way the Python code does, and the real
// BlueSky-Gym's measured 119-132 env steps/s on this machine
// (docs/bluesky_facts.md §6). One env step = 10 x 5 s sub-steps.
// Beside it, environments written in Lua over the same kernels
// (script/lua_env.h): BlueSky-Gym's DescentEnv-v0 (envs/descent.lua; one env
// step = 30 x 1 s simulator steps of one aircraft through the full
// Simulation, OpenAP when SQUAWK_OPENAP names its data) and VerticalCREnv-v0
// (envs/vertical_cr.lua, six aircraft), PlanWaypointEnv-v0 (envs/plan_waypoint.lua),
// StaticObstacleEnv-v0 (envs/static_obstacle.lua, ten polygons tested after
// every simulator step), SectorCREnv-v0 (envs/sector_cr.lua) and MergeEnv-v0
// (envs/merge.lua), each against BlueSky-Gym's measured figure
// (docs/gym_envs.md, bench/gym_ref/compare.py).
// HorizontalCR's Lua form (envs/horizontal_cr.lua, envs/horizontal_cr_gym.lua:
// the declaration compiled into the same C++ kernel) runs beside the C++ form
// on the same episodes and actions, timed in this thread's CPU seconds (the
// machine is shared), with the ratio; the reward sums must agree exactly.
// Prints figures only; no timing is asserted anywhere.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <thread>
#include <vector>

#include <lua.hpp>

#include "core/geo.h"
#include "core/paths.h"
#include "core/rng.h"
#include "core/units.h"
#include "env/horizontal_cr.h"
#include "script/lua_env.h"
#include "script/scenario.h"
#include "script/vm.h"

using namespace squawk;
using Clock = std::chrono::steady_clock;

namespace {

constexpr double kBlueSkyGymRandom = 119.3;  // env steps/s, measured (random actions)
constexpr double kBlueSkyGymZero = 132.2;    // env steps/s, measured (zero action)
// env steps/s of BlueSky-Gym's DescentEnv-v0 on the real BlueSky (bench/gym_ref/compare.py, step() only),
// measured at load average 16 on the 2-core machine; HorizontalCREnv's figures above were taken idle.
constexpr double kBlueSkyGymDescent = 5.9;
constexpr double kBlueSkyGymVerticalCr = 13.4;  // VerticalCREnv-v0, the same way, load average 17-20
// PlanWaypointEnv-v0 and StaticObstacleEnv-v0 (one env step = 10 x 1 s simulator steps), the same
// way, 30 episodes each, load average 7-20 (docs/gym_envs.md).
constexpr double kBlueSkyGymPlanWaypoint = 32.4;
constexpr double kBlueSkyGymStaticObstacle = 27.0;
// SectorCREnv-v0 and MergeEnv-v0 on the real BlueSky, measured the same way (compare.py,
// random/zero/-1 episodes together, step() only), load average 14 on the 2-core machine.
constexpr double kBlueSkyGymSectorCr = 34.0;
constexpr double kBlueSkyGymMerge = 21.4;

struct Run {
  long long steps = 0;
  long long episodes = 0;
  double seconds = 0.0;
  double checksum = 0.0;  // keeps the work observable
};

env::HorizontalCrConfig config(env::Rules rules) {
  env::HorizontalCrConfig c;
  c.rules = rules;
  if (rules == env::Rules::kPaper) {
    c.tlos = {300, 1000};
    c.lookahead = 600;
  }
  return c;
}

// Steps one environment with uniform random (or zero) actions for `seconds`.
Run drive(env::Rules rules, bool random_actions, double seconds, uint64_t seed) {
  auto e = env::HorizontalCrEnv::make(config(rules));
  Rng rng(seed);
  Run r;
  const auto t0 = Clock::now();
  uint64_t k = 0;
  while (true) {
    Rng ep(seed * 1000003 + k++);
    bool ask = e->reset(ep, k);
    while (ask) {
      r.checksum += e->step(random_actions ? rng.uniform(-1.0, 1.0) : 0.0);
      ask = !e->done();
    }
    r.steps += e->stats().steps;
    ++r.episodes;
    r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    if (r.seconds >= seconds) return r;
  }
}

// Steps a Lua environment with uniform random (or zero) actions for `seconds`.
Run drive_lua(const std::string& file, bool random_actions, double seconds, uint64_t seed) {
  auto e = script::LuaEnv::load(paths::resource(file), {});
  Run r;
  if (!e) {
    std::fprintf(stderr, "bench_env: %s\n", e.status().message().c_str());
    return r;
  }
  Rng rng(seed);
  std::vector<double> action((*e)->spec().action_size());
  const auto t0 = Clock::now();
  for (uint64_t k = 0;; ++k) {
    if (!(*e)->reset(seed + k).is_ok()) return r;
    while (true) {
      for (double& a : action) a = random_actions ? rng.uniform(-1.0, 1.0) : 0.0;
      auto s = (*e)->step(action);
      if (!s) return r;
      r.checksum += s->reward;
      if (s->terminated || s->truncated) break;
    }
    r.steps += (*e)->steps();
    ++r.episodes;
    r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    if (r.seconds >= seconds) return r;
  }
}

// The reference: the same flat-earth update and gym observation written the
// direct way (cos(lat), kwikqdrdist with atan2, cos/sin of every angle).
Run reference_gym(double seconds, uint64_t seed) {
  auto e = env::HorizontalCrEnv::make(config(env::Rules::kGym));
  Rng rng(seed);
  Run r;
  const double dt = 5.0, tan_bank = std::tan(25 * units::kDeg);
  const auto t0 = Clock::now();
  uint64_t k = 0;
  std::vector<double> lat(6), lon(6), hdg(6), tas(6), sel(6), obs(28);
  while (true) {
    Rng ep(seed * 1000003 + k++);
    const env::EpisodeSetup s = e->draw_setup(ep);
    lat[0] = 52;
    lon[0] = 4;
    hdg[0] = 0;
    tas[0] = 150;
    sel[0] = 0;
    for (int i = 0; i < 5; ++i) {
      lat[i + 1] = s.intruders[i].lat;
      lon[i + 1] = s.intruders[i].lon;
      hdg[i + 1] = s.intruders[i].hdg;
      tas[i + 1] = s.intruders[i].tas;
      sel[i + 1] = geo::wrap360(hdg[i + 1]);
    }
    for (int step = 0; step < 300; ++step) {
      sel[0] = geo::wrap360(hdg[0] + 45.0 * rng.uniform(-1.0, 1.0));
      for (int sub = 0; sub < 10; ++sub)
        for (int i = 0; i < 6; ++i) {
          const double target = std::min(150.0, 89.0);
          tas[i] = std::fabs(target - tas[i]) > 2 * dt ? tas[i] + std::copysign(2 * dt, target - tas[i]) : target;
          const double rate = units::rad_to_deg(units::kG0 * tan_bank / tas[i]);
          const double del = geo::wrap180(sel[i] - hdg[i]);
          hdg[i] = geo::wrap360(std::fabs(del) > dt * rate ? hdg[i] + std::copysign(dt * rate, del) : sel[i]);
          lat[i] += units::rad_to_deg(dt * tas[i] * std::cos(hdg[i] * units::kDeg) / units::kREarth);
          lon[i] += units::rad_to_deg(dt * tas[i] * std::sin(hdg[i] * units::kDeg) /
                                      std::cos(lat[i] * units::kDeg) / units::kREarth);
        }
      for (int i = 0; i < 5; ++i) {
        const auto qd = geo::kwikqdrdist(lat[0], lon[0], lat[i + 1], lon[i + 1]);
        const double b = geo::gym_wrap180(hdg[0] - qd.qdr_deg) * units::kDeg;
        const double dh = (hdg[0] - hdg[i + 1]) * units::kDeg;
        obs[i] = qd.dist_nm * 1.852 / 150;
        obs[5 + i] = std::cos(b);
        obs[10 + i] = std::sin(b);
        obs[15 + i] = -std::cos(dh) * tas[i + 1] / 150;
        obs[20 + i] = (tas[0] - std::sin(dh) * tas[i + 1]) / 150;
      }
      const auto w = geo::kwikqdrdist(lat[0], lon[0], s.waypoint_lat, s.waypoint_lon);
      obs[25] = w.dist_nm * 1.852 / 150;
      obs[26] = std::cos((hdg[0] - w.qdr_deg) * units::kDeg);
      obs[27] = std::sin((hdg[0] - w.qdr_deg) * units::kDeg);
      r.checksum += obs[0] + obs[27];
      ++r.steps;
      if (w.dist_nm * 1.852 < 5) break;
    }
    ++r.episodes;
    r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    if (r.seconds >= seconds) return r;
  }
}

void print(const char* name, const Run& r, double reference) {
  const double sps = static_cast<double>(r.steps) / r.seconds;
  std::printf("  %-56s %12.0f env steps/s  %8.0f episodes/s  %8.0fx BlueSky-Gym\n", name, sps,
              static_cast<double>(r.episodes) / r.seconds, sps / reference);
}

Run two_threads(env::Rules rules, double seconds) {
  Run a, b;
  std::thread t([&] { a = drive(rules, true, seconds, 1); });
  b = drive(rules, true, seconds, 2);
  t.join();
  return {a.steps + b.steps, a.episodes + b.episodes, std::max(a.seconds, b.seconds), a.checksum + b.checksum};
}

// CPU seconds of the calling thread.
double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Episodes 0..episodes-1 of the C++ environment `scenario` (its evaluation
// settings), seed k, actions uniform in [-1, 1] from Rng(k + 7); the reward
// sum adds each step() the way the Lua form returns it (the automatic steps
// before the first decision with the first step's reward).
Run drive_cpp_form(const env::HorizontalCrConfig& c, long long episodes) {
  auto e = env::HorizontalCrEnv::make(c);
  Run r;
  const double t0 = cpu_seconds();
  for (long long k = 0; k < episodes; ++k) {
    Rng ep(static_cast<uint64_t>(k)), act(static_cast<uint64_t>(k) + 7);
    bool ask = e->reset(ep);
    double pending = e->stats().total_reward;
    if (!ask) r.checksum += pending;
    while (ask) {
      double reward = e->step(act.uniform(-1.0, 1.0));
      if (pending != 0.0) reward = pending + reward;
      pending = 0.0;
      r.checksum += reward;
      ask = !e->done();
    }
    r.steps += e->stats().steps;
    ++r.episodes;
  }
  r.seconds = cpu_seconds() - t0;
  return r;
}

// The same episodes and actions through the Lua form and the LuaEnv driver.
Run drive_lua_form(const std::string& file, long long episodes) {
  auto e = script::LuaEnv::load(paths::resource(file), {});
  Run r;
  if (!e) {
    std::fprintf(stderr, "bench_env: %s\n", e.status().message().c_str());
    return r;
  }
  std::vector<double> action(1);
  const double t0 = cpu_seconds();
  for (long long k = 0; k < episodes; ++k) {
    Rng act(static_cast<uint64_t>(k) + 7);
    if (!(*e)->reset(static_cast<uint64_t>(k)).is_ok()) return r;
    while (true) {
      action[0] = act.uniform(-1.0, 1.0);
      auto s = (*e)->step(action);
      if (!s) return r;
      r.checksum += s->reward;
      if (s->terminated || s->truncated) break;
    }
    ++r.episodes;
  }
  r.seconds = cpu_seconds() - t0;
  return r;
}

// C++ form (the scenario file) and Lua form of one rule set, three
// alternating rounds of the episodes the C++ form runs in `seconds`; the
// fastest round of each counts. The Lua form runs two ways: stepped through
// the LuaEnv driver (one Lua call per decision, as `squawk env run` does), and
// its declaration compiled into the kernel (as `squawk train`/`eval` load it).
void form_rows(const char* name, const char* scenario, const char* lua_file, double seconds) {
  auto sc = script::load_scenario(paths::resource(scenario), {});
  auto declared = script::load_scenario(paths::resource(lua_file), {});
  for (const auto* loaded : {&sc, &declared})
    if (!*loaded) {
      std::fprintf(stderr, "bench_env: %s\n", loaded->status().message().c_str());
      return;
    }
  long long episodes = 16;
  while (drive_cpp_form(sc->eval_env, episodes).seconds < seconds / 4) episodes *= 2;
  Run cpp, lua, compiled;
  cpp.seconds = lua.seconds = compiled.seconds = 1e300;
  for (int round = 0; round < 3; ++round) {
    const Run c = drive_cpp_form(sc->eval_env, episodes), l = drive_lua_form(lua_file, episodes),
              d = drive_cpp_form(declared->eval_env, episodes);
    cpp = c.seconds < cpp.seconds ? c : cpp;
    lua = l.seconds < lua.seconds ? l : lua;
    compiled = d.seconds < compiled.seconds ? d : compiled;
  }
  lua.steps = cpp.steps;  // the same episodes (the reward sums below agree)
  const auto row = [&](const std::string& form, const Run& r) {
    std::printf("  %-30s %-44s %10.0f env steps/s (CPU) %7.0f episodes/s  reward sum %.17g\n", name,
                form.c_str(), static_cast<double>(r.steps) / r.seconds,
                static_cast<double>(r.episodes) / r.seconds, r.checksum);
  };
  const auto ratio = [&](const std::string& form, const Run& r) {
    std::printf("  %-30s %-44s %.2f x the C++ form's CPU time (%+.1f %% steps/s), rewards %s\n",
                name, form.c_str(), r.seconds / cpp.seconds,
                100.0 * (cpp.seconds / r.seconds - 1.0),
                r.checksum == cpp.checksum && r.episodes == cpp.episodes ? "identical" : "DIFFER");
  };
  row(std::string("C++ form, ") + scenario, cpp);
  row(std::string(lua_file) + ", stepped", lua);
  row(std::string(lua_file) + ", compiled", compiled);
  ratio(std::string(lua_file) + ", stepped", lua);
  ratio(std::string(lua_file) + ", compiled", compiled);
  std::printf("  %-30s %lld episodes per round, fastest of 3 rounds\n", name, episodes);
}

// The multi-agent sector (envs/sector_multi.lua, PettingZoo's parallel shape,
// which the single-agent LuaEnv refuses) with `agents` agents, each given a
// uniform random action every step, episodes until `seconds` of wall time.
// One env step moves every agent 5 s.
Run drive_multi(int agents, double seconds) {
  script::VmOptions o;
  o.max_instructions = 0;  // one call runs the whole loop
  script::Vm vm(o);
  const std::string path = paths::resource("envs/sector_multi.lua");
  vm.add_script_folder(paths::dirname(path));
  char code[1024];
  std::snprintf(code, sizeof code, R"(
    local env = squawk.gym.load([[%s]])
    local t0, steps, episodes, k = os.clock(), 0, 0, 0
    while os.clock() - t0 < %g do
      env:reset(k, {num_agents = %d})
      while #env.agents > 0 do
        local actions = {}
        for _, a in ipairs(env.agents) do actions[a] = {2 * math.random() - 1, 2 * math.random() - 1} end
        env:step(actions)
        steps = steps + 1
      end
      episodes, k = episodes + 1, k + 1
    end
    BENCH_STEPS, BENCH_EPISODES = steps, episodes)",
                path.c_str(), seconds, agents);
  Run r;
  const auto t0 = Clock::now();
  if (const Status st = vm.run_string(code, "bench_env multi"); !st.is_ok()) {
    std::fprintf(stderr, "bench_env: %s\n", st.message().c_str());
    return r;
  }
  r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  lua_State* L = vm.state();
  lua_getglobal(L, "BENCH_STEPS");
  r.steps = lua_tointeger(L, -1);
  lua_getglobal(L, "BENCH_EPISODES");
  r.episodes = lua_tointeger(L, -1);
  lua_pop(L, 2);
  return r;
}

// The traffic environments with heading and speed actions (envs/sector_cr.lua:
// 5 x 1 s simulator steps of 5-26 aircraft per env step; envs/merge.lua:
// 10 x 5 s of 20 aircraft on routes).
void traffic_rows(double seconds) {
  std::printf(
      "Lua traffic environments (sector: 5 x 1 s simulator steps of 5-26 aircraft per env step; "
      "merge: 10 x 5 s of 20):\n");
  print("SectorCREnv-v0 (envs/sector_cr.lua), random, 1 thread",
        drive_lua("envs/sector_cr.lua", true, seconds, 1), kBlueSkyGymSectorCr);
  print("MergeEnv-v0 (envs/merge.lua), random, 1 thread",
        drive_lua("envs/merge.lua", true, seconds, 1), kBlueSkyGymMerge);
  const Run multi = drive_multi(10, seconds);
  std::printf("  %-56s %12.0f env steps/s  %8.0f episodes/s  (no BlueSky-Gym counterpart)\n",
              "SectorMultiCR (envs/sector_multi.lua), 10 agents, random",
              multi.steps / multi.seconds, multi.episodes / multi.seconds);
}

}  // namespace

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 2.0;
  const bool forms_only =
      argc > 2 && std::string(argv[2]) == "forms";  // bench_env S forms: those rows alone
  std::printf("bench_env: %.1f s per row; one env step = 10 sub-steps of 5 s, 6 aircraft\n", seconds);
  std::printf(
      "HorizontalCR, C++ form and Lua form (same episodes and random actions, 1 thread, CPU "
      "time):\n");
  form_rows("paper rules (Table 3 eval)", "scenarios/horizontal_cr.lua", "envs/horizontal_cr.lua",
            seconds);
  form_rows("gym rules (HorizontalCREnv-v0)", "scenarios/horizontal_cr_gym.lua",
            "envs/horizontal_cr_gym.lua", seconds);
  if (forms_only) return 0;
  std::printf("gym rules (HorizontalCREnv-v0, ground cap 89 m/s):\n");
  print("random actions, 1 thread", drive(env::Rules::kGym, true, seconds, 1), kBlueSkyGymRandom);
  print("zero action, 1 thread", drive(env::Rules::kGym, false, seconds, 1), kBlueSkyGymZero);
  print("random actions, 2 threads (1 env each)", two_threads(env::Rules::kGym, seconds), kBlueSkyGymRandom);
  print("reference: direct trig, random, 1 thread", reference_gym(seconds, 1), kBlueSkyGymRandom);
  std::printf("paper rules (evaluation settings; agent and automatic steps counted):\n");
  print("random actions, 1 thread", drive(env::Rules::kPaper, true, seconds, 1), kBlueSkyGymRandom);
  print("zero action, 1 thread", drive(env::Rules::kPaper, false, seconds, 1), kBlueSkyGymZero);
  print("random actions, 2 threads (1 env each)", two_threads(env::Rules::kPaper, seconds), kBlueSkyGymRandom);
  std::printf("Lua environments (one env step = 30 x 1 s simulator steps; OpenAP: %s):\n",
              std::getenv("SQUAWK_OPENAP") ? "on" : "off, class model");
  print("DescentEnv-v0 (envs/descent.lua), random, 1 thread", drive_lua("envs/descent.lua", true, seconds, 1),
        kBlueSkyGymDescent);
  print("DescentEnv-v0 (envs/descent.lua), zero, 1 thread", drive_lua("envs/descent.lua", false, seconds, 1),
        kBlueSkyGymDescent);
  print("VerticalCREnv-v0 (envs/vertical_cr.lua), random, 1 thread",
        drive_lua("envs/vertical_cr.lua", true, seconds, 1), kBlueSkyGymVerticalCr);
  std::printf("Lua environments, horizontal (one env step = 10 x 1 s simulator steps):\n");
  print("PlanWaypointEnv-v0 (envs/plan_waypoint.lua), random, 1 thread",
        drive_lua("envs/plan_waypoint.lua", true, seconds, 1), kBlueSkyGymPlanWaypoint);
  print("StaticObstacleEnv-v0 (envs/static_obstacle.lua), random, 1 thread",
        drive_lua("envs/static_obstacle.lua", true, seconds, 1), kBlueSkyGymStaticObstacle);
  traffic_rows(seconds);
  return 0;
}
