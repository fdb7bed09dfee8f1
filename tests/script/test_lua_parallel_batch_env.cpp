// Multi-agent Lua environments (script/lua_parallel_env.h) as a batch for
// parameter sharing (script/lua_parallel_batch_env.h): every agent's
// trajectory an episode for the learner, numbered by sector episode and
// agent, the same whatever the slots; the learner sees each trajectory; a
// checkpoint of the wrong observation size refused by name; broken files
// named.
#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "rl/checkpoint.h"
#include "rl/mlp_policy.h"
#include "rl/play.h"
#include "rl/vpg.h"
#include "scratch_dir.h"
#include "script/grid_policy.h"
#include "script/lua_batch_env.h"
#include "script/lua_parallel_batch_env.h"

using namespace squawk;

namespace {

std::string repo(const char* rel) {
  return std::string(SQUAWK_TEST_DATA) + "/../../" + rel;
}

const std::string kSector = repo("envs/sector_multi.lua");

std::unique_ptr<script::LuaParallelBatchEnv> batch(int slots, std::vector<int> agents) {
  auto b = script::LuaParallelBatchEnv::make(kSector, {}, slots, 5, std::move(agents));
  REQUIRE_MESSAGE(b.is_ok(), b.status().message());
  return std::move(*b);
}

// The grid class agent number k takes at step t of its trajectory.
int class_of(uint64_t k, int t) {
  return static_cast<int>((k * 7 + static_cast<uint64_t>(t) * 3) % 25);
}

// Plays episodes first..first+count-1 of `seed` with class_of; returns the total reward per number.
std::map<uint64_t, double> play_classes(script::LuaParallelBatchEnv& b, uint64_t seed,
                                        uint64_t first, uint64_t count) {
  std::vector<int> step_of(static_cast<size_t>(b.size()), 0);
  rl::Driver d;
  d.choose = [&](rl::Turn& t) {
    for (size_t r = 0; r < t.slots.size(); ++r) {
      const int s = t.slots[r];
      t.actions[r].value = static_cast<float>(
          script::grid_value(class_of(b.episode(s), step_of[static_cast<size_t>(s)]++), 25));
    }
    return Status::ok();
  };
  d.after = [&](const rl::Turn& t) {
    for (size_t r = 0; r < t.slots.size(); ++r)
      if (t.dones[r]) step_of[static_cast<size_t>(t.slots[r])] = 0;
    return true;
  };
  auto played = rl::play(b, seed, first, count, d);
  REQUIRE_MESSAGE(played.is_ok(), played.status().message());
  CHECK(*played);
  std::map<uint64_t, double> got;
  for (const env::EpisodeStats& e : b.completed()) {
    CHECK(e.steps > 0);
    CHECK(e.reached != e.truncated);
    CHECK(got.count(e.index) == 0);
    got[e.index] = e.total_reward;
  }
  return got;
}

}  // namespace

TEST_CASE("each agent's trajectory is one numbered episode, as the file stepped alone gives it") {
  // Sector episode e of seed 30 stepped directly, every agent commanded by class_of.
  auto one = script::LuaParallelEnv::load(kSector, {});
  REQUIRE_MESSAGE(one.is_ok(), one.status().message());
  script::LuaParallelEnv& e = **one;
  std::map<uint64_t, double> want;
  std::vector<double> act(2);
  for (uint64_t sector = 0; sector < 2; ++sector) {
    const Status reset = e.reset(30 + sector, 3);
    REQUIRE_MESSAGE(reset.is_ok(), reset.message());
    const std::vector<std::string> names = e.agents();
    REQUIRE(names.size() == 3);
    for (int t = 0; !e.agents().empty(); ++t) {
      std::vector<int> commanded;
      std::vector<std::vector<double>> commands(e.agents().size(), std::vector<double>(2));
      std::vector<uint64_t> number;
      for (size_t p = 0; p < e.agents().size(); ++p) {
        const auto a = static_cast<uint64_t>(std::find(names.begin(), names.end(), e.agents()[p]) -
                                             names.begin());
        number.push_back(sector * 3 + a);
        script::grid_action(e.spec(), 5, class_of(number.back(), t), commands[p]);
        commanded.push_back(static_cast<int>(p));
      }
      std::vector<script::AgentStep> out;
      REQUIRE(e.step(commanded, commands, out).is_ok());
      REQUIRE(out.size() == number.size());
      for (size_t p = 0; p < out.size(); ++p) want[number[p]] += out[p].reward;
    }
  }
  REQUIRE(want.size() == 6);
  for (int slots : {1, 3}) {
    auto b = batch(slots, {3});
    CHECK(b->size() == 3 * slots);
    CHECK(play_classes(*b, 30, 0, 6) == want);
    CHECK(b->sector_episodes() == 2);
  }
  // A range that splits sector episodes: only its agents are rows (the others fly uncommanded).
  auto b = batch(2, {3});
  const auto part = play_classes(*b, 30, 1, 4);
  std::vector<uint64_t> numbers;
  for (const auto& [k, r] : part) numbers.push_back(k);
  CHECK(numbers == std::vector<uint64_t>{1, 2, 3, 4});
}

TEST_CASE("drawn agent counts: numbers past an episode's agents are never played") {
  auto b = batch(2, {2, 3});
  const auto got = play_classes(*b, 5, 0, 12);  // four sector episodes of 2 or 3 agents
  CHECK(b->sector_episodes() == 4);
  std::map<uint64_t, int> per_sector;
  for (const auto& [k, r] : got) ++per_sector[k / 3];
  REQUIRE(per_sector.size() == 4);
  int twos = 0;
  for (const auto& [sector, n] : per_sector) {
    CHECK((n == 2 || n == 3));
    twos += n == 2;
  }
  for (const auto& [k, r] : got)
    if (per_sector[k / 3] == 2) CHECK(k % 3 != 2);
  CHECK(twos > 0);
  CHECK(twos < 4);
  CHECK(play_classes(*batch(3, {2, 3}), 5, 0, 12) == got);
}

TEST_CASE("the shared-parameter learner sees every agent's trajectory, deterministically") {
  auto params_after = [](int slots) {
    auto b = batch(slots, {2});
    rl::MlpPolicySpec spec;
    spec.obs_size = b->obs_size();
    spec.hidden = {8};
    spec.action_values = script::grid_values(b->classes());
    Rng init(4);
    auto p = rl::MlpPolicy::make(spec, init);
    REQUIRE(p);
    rl::TrainConfig tc;
    tc.estimator = "ppo";
    tc.episodes = 12;
    tc.episodes_per_update = 4;  // two sector episodes of 2 agents
    tc.num_envs = slots;
    tc.value_hidden = {8};
    rl::Trainer tr(**p, *b, tc, 0);
    for (int u = 0; u < 3; ++u) {
      const rl::UpdateStats st = tr.update();
      CHECK(st.episodes == 4);
      long long steps = 0;
      std::vector<uint64_t> numbers;
      for (const env::EpisodeStats& e : b->completed()) {
        steps += e.steps;
        numbers.push_back(e.index);
      }
      std::sort(numbers.begin(), numbers.end());
      const auto k0 = static_cast<uint64_t>(4 * u);
      CHECK(numbers == std::vector<uint64_t>{k0, k0 + 1, k0 + 2, k0 + 3});
      CHECK(st.samples == steps);
      CHECK(st.samples > 4);
    }
    REQUIRE(b->error().is_ok());
    CHECK(b->sector_episodes() == 6);
    return std::vector<float>((*p)->params().begin(), (*p)->params().end());
  };
  const std::vector<float> a = params_after(1);
  CHECK(a == params_after(2));
}

TEST_CASE("a checkpoint of the wrong observation size is refused by name") {
  auto b = batch(1, {2});
  rl::Checkpoint ck;
  ck.spec.obs_size = 28;
  ck.spec.hidden = {4};
  ck.spec.action_values = script::grid_values(25);
  Rng init(0);
  auto p = rl::MlpPolicy::make(ck.spec, init);
  REQUIRE(p);
  ck.params.assign((*p)->params().begin(), (*p)->params().end());
  ck.progress.scenario = "scenarios/horizontal_cr.lua";
  const std::string path = (test::scratch_dir("lua_parallel_batch_env") / "obs28.ckpt").string();
  REQUIRE(rl::save_checkpoint(path, ck).is_ok());
  auto g = script::load_grid_policy(path, b->spec());
  REQUIRE_FALSE(g.is_ok());
  CHECK(g.status().message().find(
            "obs28.ckpt: the policy reads 28 observation numbers; SectorMultiCR-v0 gives 31 "
            "(trained on scenarios/horizontal_cr.lua)") != std::string::npos);
}

TEST_CASE("a broken multi-agent file and a single-agent one are named") {
  auto single = script::LuaParallelEnv::load(repo("envs/sector_cr.lua"), {});
  REQUIRE_FALSE(single.is_ok());
  CHECK(single.status().message().find("sector_cr.lua: not a multi-agent environment") !=
        std::string::npos);
  auto is = script::is_parallel_env(kSector, {});
  REQUIRE(is);
  CHECK(*is);

  const std::string broken = (test::scratch_dir("lua_parallel_batch_env") / "short.lua").string();
  std::ofstream(broken)
      << "return {id = 'Short-v0', parallel = true, observation = {{name = 'x', size = 2}},\n"
         "  action = {low = {-1}, high = {1}}, max_episode_steps = 5,\n"
         "  reset = function(self) self.agents = {'A', 'B'}; return {A = {0, 0}, B = {0, 0}} end,\n"
         "  step = function(self, acts)\n"
         "    return {A = {0, 0}, B = {0}}, {A = 0, B = 0}, {A = false, B = false},\n"
         "           {A = false, B = false}\n"
         "  end}\n";
  auto b = script::LuaParallelBatchEnv::make(broken, {}, 1, 3, {2});
  REQUIRE_MESSAGE(b.is_ok(), b.status().message());
  rl::Driver d;
  d.choose = [](rl::Turn& t) {
    for (auto& a : t.actions) a.value = 0.0f;
    return Status::ok();
  };
  auto r = rl::play(**b, 0, 0, 2, d);
  REQUIRE_FALSE(r.is_ok());
  CHECK(r.status().message().find("short.lua: step: observations.B has 1 numbers; the declared "
                                  "observation has 2") != std::string::npos);
  CHECK((*b)->finished());
}
