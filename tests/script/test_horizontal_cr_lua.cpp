// envs/horizontal_cr.lua and envs/horizontal_cr_gym.lua (the Lua form of the
// HorizontalCR environment, docs/gym_envs.md) against the C++ environment as
// `squawk train`/`squawk eval` build it from scenarios/horizontal_cr.lua
// (evaluation settings) and scenarios/horizontal_cr_gym.lua: for the same seed
// and the same action sequence, every observation, reward and episode end
// must be identical, bit for bit, through the LuaEnv driver that
// `squawk env run` and bench_env use.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "core/rng.h"
#include "env/horizontal_cr.h"
#include "script/lua_env.h"
#include "script/scenario.h"

using namespace squawk;

namespace {

std::string repo(const char* rel) {
  return std::string(SQUAWK_TEST_DATA) + "/../../" + rel;
}

struct Tally {
  int episodes_without_decision = 0;
  int steps = 0;
  int truncated = 0;
};

// `episodes` episodes, seeds 1000..; actions drawn from Rng(seed + 7) among
// the paper's five bins, or uniform in [-1, 1] (continuous).
Tally compare(const char* lua_file, const char* scenario, int episodes, bool continuous) {
  auto lua = script::LuaEnv::load(repo(lua_file), {});
  REQUIRE_MESSAGE(lua.is_ok(), lua.status().message());
  auto sc = script::load_scenario(repo(scenario), {});
  REQUIRE_MESSAGE(sc.is_ok(), sc.status().message());
  auto cpp = env::HorizontalCrEnv::make(sc->eval_env);
  REQUIRE(cpp.is_ok());
  const int n = cpp->observation_size();
  REQUIRE((*lua)->spec().observation_size == n);
  std::vector<float> flat(static_cast<size_t>(n));
  auto same_observation = [&](int step) {
    cpp->observe_flat(flat);
    const std::vector<double>& o = (*lua)->observation();
    for (int k = 0; k < n; ++k) {
      const auto kk = static_cast<size_t>(k);
      INFO("step " << step << " observation[" << k << "]");
      REQUIRE(o[kk] == static_cast<double>(flat[kk]));
    }
  };
  Tally t;
  for (int ep = 0; ep < episodes; ++ep) {
    const uint64_t seed = 1000 + static_cast<uint64_t>(ep);
    INFO(lua_file << " seed " << seed);
    Rng actions(seed + 7);
    Rng draw(seed);
    const bool ask = cpp->reset(draw);
    double pending = cpp->stats().total_reward;
    REQUIRE((*lua)->reset(seed).is_ok());
    same_observation(0);
    t.episodes_without_decision += !ask;
    for (int step = 1;; ++step) {
      const double a = continuous ? actions.uniform(-1.0, 1.0)
                                  : -1.0 + 0.5 * static_cast<double>(actions.uniform_int(0, 4));
      auto r = (*lua)->step(std::vector<double>{a});
      REQUIRE_MESSAGE(r.is_ok(), r.status().message());
      double expected = pending;
      if (ask || step > 1) {
        expected = cpp->step(a);
        if (pending != 0.0) expected = pending + expected;
      }
      pending = 0.0;
      same_observation(step);
      REQUIRE(r->reward == expected);
      ++t.steps;
      const bool cut = cpp->stats().truncated;
      REQUIRE(r->truncated == cut);
      REQUIRE(r->terminated == (cpp->done() && !cut));
      if (cpp->done()) {
        t.truncated += cut;
        break;
      }
    }
  }
  return t;
}

}  // namespace

TEST_CASE("envs/horizontal_cr.lua flies the C++ environment's paper episodes bit for bit") {
  const Tally t = compare("envs/horizontal_cr.lua", "scenarios/horizontal_cr.lua", 200, false);
  // Under these settings every episode asks the agent; episodes that end
  // inside reset are compared in tests/lua/gym_horizontal_cr.lua.
  CHECK(t.episodes_without_decision == 0);
  CHECK(t.steps > 400);
}

TEST_CASE(
    "envs/horizontal_cr_gym.lua flies HorizontalCREnv-v0's episodes as the C++ environment does") {
  const Tally t =
      compare("envs/horizontal_cr_gym.lua", "scenarios/horizontal_cr_gym.lua", 40, true);
  CHECK(t.episodes_without_decision == 0);
  CHECK(t.steps > 40 * 20);
}

TEST_CASE(
    "an environment file loads as a scenario of its declaration (squawk train/eval "
    "envs/horizontal_cr.lua)") {
  for (const auto& [file, scenario] :
       {std::pair{"envs/horizontal_cr.lua", "scenarios/horizontal_cr.lua"},
        std::pair{"envs/horizontal_cr_gym.lua", "scenarios/horizontal_cr_gym.lua"}}) {
    INFO(file);
    auto declared = script::load_scenario(repo(file), {});
    REQUIRE_MESSAGE(declared.is_ok(), declared.status().message());
    auto sc = script::load_scenario(repo(scenario), {});
    REQUIRE(sc.is_ok());
    CHECK(declared->policy.head == sc->policy.head);
    auto a = env::HorizontalCrEnv::make(declared->eval_env);
    auto b = env::HorizontalCrEnv::make(sc->eval_env);
    REQUIRE((a.is_ok() && b.is_ok()));
    for (uint64_t seed = 1; seed <= 30; ++seed) {
      Rng ra(seed), rb(seed);
      bool ask = a->reset(ra);
      REQUIRE(ask == b->reset(rb));
      for (int k = 0; ask; ++k) {
        const double act = 0.5 * static_cast<double>(k % 3 - 1);
        REQUIRE(a->step(act) == b->step(act));
        ask = !a->done();
      }
      CHECK(b->done());
      CHECK(a->stats().total_reward == b->stats().total_reward);
      CHECK(a->stats().steps == b->stats().steps);
    }
  }
}
