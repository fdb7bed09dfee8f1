// Environments written as one Lua file (script/lua_env.h): the contract the
// driver enforces, and BlueSky-Gym's DescentEnv-v0 (envs/descent.lua) run for
// whole episodes: observation shape, reward bounds, both ways an episode
// ends, the step count it ends at, and determinism per seed. Without OpenAP
// data the aircraft fly squawk's class model; every assertion holds for both.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/rng.h"
#include "scratch_dir.h"
#include "script/lua_env.h"
#include "script/lua_policy.h"

using namespace squawk;
namespace fs = std::filesystem;

namespace {

std::string repo(const char* rel) {
  return std::string(SQUAWK_TEST_DATA) + "/../../" + rel;
}

std::unique_ptr<script::LuaEnv> load(const char* rel) {
  auto e = script::LuaEnv::load(repo(rel), {});
  REQUIRE_MESSAGE(e.is_ok(), e.status().message());
  return std::move(*e);
}

std::unique_ptr<script::LuaEnv> descent() {
  return load("envs/descent.lua");
}

struct Episode {
  std::vector<std::vector<double>> obs;  // reset's, then one per step
  std::vector<double> rewards;
  bool terminated = false, truncated = false;
};

// One episode with action `a` each step, or uniform in [-1, 1] when a is NaN.
Episode run(script::LuaEnv& e, uint64_t seed, double a, Rng& rng) {
  Episode ep;
  REQUIRE(e.reset(seed).is_ok());
  ep.obs.push_back(e.observation());
  while (true) {
    const double act = std::isnan(a) ? rng.uniform(-1.0, 1.0) : a;
    auto r = e.step(std::vector<double>{act});
    REQUIRE_MESSAGE(r.is_ok(), r.status().message());
    ep.obs.push_back(e.observation());
    ep.rewards.push_back(r->reward);
    if (r->terminated || r->truncated) {
      ep.terminated = r->terminated;
      ep.truncated = r->truncated;
      return ep;
    }
  }
}

fs::path write(const char* name, const std::string& text) {
  const fs::path p = test::scratch_dir("lua_env") / name;
  std::ofstream(p) << text;
  return p;
}

constexpr const char* kCounter = R"(
local E = {id = "Counter-v0", observation = {{name = "n", size = 2}}, action = {low = {-1}, high = {1}},
           max_episode_steps = 3}
function E:reset(seed) self.n = seed; return {self.n, 0} end
function E:step(a) self.n = self.n + a[1]; return {self.n, a[1]}, a[1], false, false end
return E
)";

}  // namespace

TEST_CASE("DescentEnv-v0 declares BlueSky-Gym's spaces and episode limit") {
  auto e = descent();
  const auto& s = e->spec();
  CHECK(s.id == "DescentEnv-v0");
  CHECK(s.observation_size == 4);
  REQUIRE(s.observation.size() == 4);
  CHECK(s.observation[0].name == "altitude");  // gymnasium's sorted Dict keys
  CHECK(s.observation[1].name == "runway_distance");
  CHECK(s.observation[2].name == "target_altitude");
  CHECK(s.observation[3].name == "vz");
  CHECK(s.action_low == std::vector<double>{-1});
  CHECK(s.action_high == std::vector<double>{1});
  CHECK(s.max_episode_steps == 300);
}

TEST_CASE("DescentEnv-v0 random episodes: start, reward bounds, termination at the runway") {
  auto e = descent();
  Rng rng(7);
  int passed = 0, crashed = 0;
  for (uint64_t seed = 0; seed < 8; ++seed) {
    const Episode ep = run(*e, seed, NAN, rng);
    const auto& o0 = ep.obs[0];
    REQUIRE(o0.size() == 4);
    const double alt0 = o0[0] * 3000 + 1500, target = o0[2] * 3000 + 1500;
    CHECK(alt0 >= 2000);
    CHECK(alt0 <= 3999);
    CHECK(std::fabs(alt0 - std::round(alt0)) < 1e-9);  // np.random.randint draws whole metres
    CHECK(target - alt0 >= -500);
    CHECK(target - alt0 <= 499);
    CHECK(o0[1] == doctest::Approx(0.5));  // 200 km to go: (200 - 100) / 200
    CHECK(o0[3] == 0.0);                   // level at the start
    CHECK(ep.terminated);
    CHECK_FALSE(ep.truncated);
    for (size_t k = 0; k + 1 < ep.rewards.size(); ++k) {
      const double alt = ep.obs[k + 1][0] * 3000 + 1500;
      CHECK(ep.rewards[k] == doctest::Approx(-std::fabs(target - alt) / 600).epsilon(1e-9));
      CHECK(ep.obs[k + 1][2] == o0[2]);  // the target altitude stays
    }
    const auto& last = ep.obs.back();
    const double alt_end = last[0] * 3000 + 1500;
    if (alt_end <= 0) {  // touched the ground
      CHECK(ep.rewards.back() == -100.0);
      ++crashed;
    } else {  // passed the runway, 200 km at 150 m/s CAS (155-175 m/s true) in 30 s steps
      CHECK(last[1] <= -0.5);
      CHECK(ep.rewards.size() >= 35);
      CHECK(ep.rewards.size() <= 50);
      CHECK(ep.rewards.back() == doctest::Approx(-alt_end / 60).epsilon(1e-9));
      ++passed;
    }
  }
  CHECK(passed > 0);  // both endings occur under random actions
  CHECK(crashed > 0);
}

TEST_CASE("DescentEnv-v0 full descent crashes with -100; full climb passes the runway high") {
  auto e = descent();
  Rng rng(1);
  const Episode down = run(*e, 3, -1.0, rng);
  CHECK(down.terminated);
  CHECK(down.rewards.back() == -100.0);
  CHECK(down.obs.back()[0] * 3000 + 1500 <= 0.0);
  CHECK(down.rewards.size() <= 13);                // at most 4000 m at 12.5 m/s, 30 s per step
  CHECK(down.obs[2][3] == doctest::Approx(-2.5));  // -12.5 m/s once the ramp is done
  const Episode up = run(*e, 3, 1.0, rng);
  CHECK(up.terminated);
  CHECK(up.obs.back()[0] > up.obs[0][0]);
  CHECK(up.rewards.back() < -50.0);  // -altitude / 60 above 3000 m
}

TEST_CASE("info.success at an episode's last step: the scripted descent lands, a dive does not") {
  auto e = descent();
  auto policy = script::LuaPolicy::load(repo("envs/policies/descent.lua"), {}, e->spec());
  REQUIRE_MESSAGE(policy.is_ok(), policy.status().message());
  std::vector<double> a(1);
  for (uint64_t seed : {3, 4}) {
    REQUIRE(e->reset(seed).is_ok());
    REQUIRE((*policy)->reset(seed).is_ok());
    while (true) {
      REQUIRE((*policy)->act(e->observation(), a).is_ok());
      CHECK(a[0] >= -1.0);
      CHECK(a[0] <= 1.0);
      auto r = e->step(a);
      REQUIRE(r.is_ok());
      if (!r->terminated) {
        CHECK(!r->success.has_value());
        continue;
      }
      REQUIRE(r->success.has_value());
      CHECK(*r->success);  // passed the runway airborne, at most 1000 ft above it
      CHECK(e->observation()[0] * 3000 + 1500 > 0.0);
      CHECK(e->observation()[0] * 3000 + 1500 <= 304.8);
      break;
    }
  }
  REQUIRE(e->reset(3).is_ok());
  while (true) {
    auto r = e->step(std::vector<double>{-1.0});
    REQUIRE(r.is_ok());
    if (r->terminated) {
      CHECK(r->success == std::optional<bool>(false));  // the ground
      break;
    }
  }
  // A policy for another environment is refused by name.
  auto merge = load("envs/merge.lua");
  auto wrong = script::LuaPolicy::load(repo("envs/policies/descent.lua"), {}, merge->spec());
  REQUIRE(!wrong.is_ok());
  CHECK(wrong.status().message().find("written for DescentEnv-v0, not MergeEnv-v0") !=
        std::string::npos);
}

TEST_CASE("DescentEnv-v0 is deterministic per seed") {
  auto a = descent();
  auto b = descent();
  Rng ra(5), other(9), rb(5);
  const Episode x = run(*a, 11, NAN, ra);
  run(*b, 4, NAN, other);  // b has lived through another episode first
  const Episode y = run(*b, 11, NAN, rb);
  CHECK(x.obs == y.obs);
  CHECK(x.rewards == y.rewards);
  Rng rc(5);
  const Episode z = run(*a, 12, NAN, rc);
  CHECK(z.obs[0] != x.obs[0]);
}

TEST_CASE("the driver adds the TimeLimit and checks what the file returns") {
  auto e = script::LuaEnv::load(write("counter.lua", kCounter).string(), {});
  REQUIRE(e.is_ok());
  REQUIRE((*e)->reset(2).is_ok());
  CHECK((*e)->observation() == std::vector<double>{2, 0});
  for (int k = 1; k <= 3; ++k) {
    auto r = (*e)->step(std::vector<double>{0.5});
    REQUIRE(r.is_ok());
    CHECK(r->reward == 0.5);
    CHECK(r->truncated == (k == 3));
  }
  CHECK((*e)->observation() == std::vector<double>{3.5, 0.5});
  auto bad = (*e)->step(std::vector<double>{0.5, 1});
  REQUIRE_FALSE(bad.is_ok());
  CHECK(bad.status().message().find("action has 2 numbers, expected 1") != std::string::npos);

  std::string wrong = kCounter;
  wrong.replace(wrong.find("return {self.n, a[1]}"), 21, "return {self.n}");
  auto w = script::LuaEnv::load(write("wrong.lua", wrong).string(), {});
  REQUIRE(w.is_ok());
  REQUIRE((*w)->reset(0).is_ok());
  auto r = (*w)->step(std::vector<double>{1});
  REQUIRE_FALSE(r.is_ok());
  CHECK(r.status().message().find(
            "the observation has 1 numbers; the declared observation has 2") != std::string::npos);

  std::string no_action = kCounter;
  no_action.replace(no_action.find("action = {low = {-1}, high = {1}},"), 35, "");
  auto n = script::LuaEnv::load(write("no_action.lua", no_action).string(), {});
  REQUIRE_FALSE(n.is_ok());
  CHECK(n.status().message().find("field 'action' must be {low = {..}, high = {..}}") !=
        std::string::npos);
}

TEST_CASE("a multi-agent file is refused by the single-agent driver, by name") {
  auto e = script::LuaEnv::load(repo("envs/sector_multi.lua"), {});
  REQUIRE_FALSE(e.is_ok());
  CHECK(e.status().message().find(
            "sector_multi.lua: field 'parallel' = true: a multi-agent environment") !=
        std::string::npos);
}

TEST_CASE("VerticalCREnv-v0: DescentEnv plus five intruders in conflict, -50 per intrusion") {
  auto e = load("envs/vertical_cr.lua");
  const auto& s = e->spec();
  CHECK(s.id == "VerticalCREnv-v0");
  CHECK(s.observation_size == 39);
  REQUIRE(s.observation.size() == 11);
  CHECK(s.observation[1].name == "altitude_difference");
  CHECK(s.observation[10].name == "z_difference_speed");
  CHECK(s.action_low == std::vector<double>{-1});  // DescentEnv's action, inherited
  CHECK(s.max_episode_steps == 300);
  Rng rng(3);
  int intrusions = 0;
  for (uint64_t seed = 0; seed < 6; ++seed) {
    const Episode ep = run(*e, seed, NAN, rng);
    REQUIRE(ep.obs[0].size() == 39);
    for (int i = 0; i < 5; ++i) {
      const double dist_km = ep.obs[0][11 + i] * 200;  // intruder_distance
      CHECK(dist_km >
            9.26);  // outside 5 NM: each intruder is 100-900 s from its loss of separation
      CHECK(dist_km < 400);
      CHECK(std::hypot(ep.obs[0][6 + i], ep.obs[0][17 + i]) ==
            doctest::Approx(1.0));  // cos^2 + sin^2
    }
    CHECK(ep.terminated);
    const double target = ep.obs[0][22] * 3000 + 1500;
    for (size_t k = 0; k + 1 < ep.rewards.size(); ++k) {
      const double alt = ep.obs[k + 1][0] * 3000 + 1500;
      const double intrusion = ep.rewards[k] + std::fabs(target - alt) / 600;
      const double n = -intrusion / 50;  // whole intruders inside the zone
      CHECK(n == doctest::Approx(std::round(n)).epsilon(1e-9));
      CHECK(n >= -1e-9);
      CHECK(n <= 5 + 1e-9);
      intrusions += static_cast<int>(std::lround(n));
    }
  }
  CHECK(intrusions > 0);  // the conflicts are real: random flying meets some
  auto f = load("envs/vertical_cr.lua");
  Rng ra(2), rb(2);
  const Episode x = run(*e, 21, NAN, ra), y = run(*f, 21, NAN, rb);
  CHECK(x.obs == y.obs);
  CHECK(x.rewards == y.rewards);
}
