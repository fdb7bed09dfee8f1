// The act -> step loop (rl/play.h) and the training schedule over it (rl/train_run.h).
#include <doctest/doctest.h>

#include <set>
#include <vector>

#include "../env/paper_settings.h"
#include "env/vec_env.h"
#include "rl/baseline_policies.h"
#include "rl/mlp_policy.h"
#include "rl/play.h"
#include "rl/train_run.h"

using namespace squawk;

namespace {

env::HorizontalCrConfig paper_env() {
  return test::paper_eval_config(false);
}

}  // namespace

TEST_CASE("play runs every episode once, turn by turn, and hands each its rewards and end") {
  auto v = env::VecEnv::make(paper_env(), 4);
  REQUIRE(v);
  const auto d = static_cast<size_t>(v->obs_size());
  long long turns = 0, rows = 0, ends = 0;
  double reward = 0.0;  // summed over the rows
  rl::Driver driver;
  driver.choose = [&](rl::Turn& t) {
    ++turns;
    rows += static_cast<long long>(t.slots.size());
    CHECK(t.obs.size() == t.slots.size() * d);
    CHECK(t.actions.size() == t.slots.size());
    for (size_t r = 1; r < t.slots.size(); ++r) CHECK(t.slots[r - 1] < t.slots[r]);
    for (rl::ActionSample& a : t.actions) a.value = 0.5f;
    return Status::ok();
  };
  driver.after = [&](const rl::Turn& t) {
    CHECK(t.obs.empty());  // the step replaced the observations
    for (size_t r = 0; r < t.slots.size(); ++r) {
      CHECK(t.actions[r].value == 0.5f);
      reward += t.rewards[r];
      ends += t.dones[r];
    }
    return true;
  };
  auto done = rl::play(*v, 7, 10, 12, driver);
  REQUIRE(done);
  CHECK(*done);
  REQUIRE(v->completed().size() == 12);
  std::set<uint64_t> index;
  long long decisions = 0, with_rows = 0;
  for (const env::EpisodeStats& e : v->completed()) {
    index.insert(e.index);
    with_rows += e.decisions > 0;
    decisions += e.decisions;
  }
  CHECK(index.size() == 12);
  CHECK(*index.begin() == 10);
  CHECK(*index.rbegin() == 21);
  CHECK(rows == decisions);  // one row per decision
  CHECK(ends == with_rows);  // every episode with a decision ends on a row
  CHECK(turns >= rows / 4);  // at most 4 slots per turn
  CHECK(reward < 0.0);       // drift and intrusions cost
}

TEST_CASE("play stops when after() says so, and passes choose()'s error on") {
  auto v = env::VecEnv::make(paper_env(), 4);
  REQUIRE(v);
  int turns = 0;
  rl::Driver stop{[](rl::Turn&) { return Status::ok(); },
                  [&](const rl::Turn&) { return ++turns < 3; }};
  auto r = rl::play(*v, 1, 0, 50, stop);
  REQUIRE(r);
  CHECK_FALSE(*r);
  CHECK(turns == 3);
  CHECK(v->completed().size() < 50);
  rl::Driver fail{[](rl::Turn&) { return Status::invalid("no decision here"); }, {}};
  auto e = rl::play(*v, 1, 0, 5, fail);
  REQUIRE_FALSE(e);
  CHECK(e.status().message() == "no decision here");
}

TEST_CASE("policy_choice gives each episode its own stream, whatever the number of slots") {
  Rng init(3);
  auto p = rl::MlpPolicy::make({}, init);
  REQUIRE(p);
  // The sampled actions of every episode, in order, for 1 and 5 slots.
  auto actions_by_episode = [&](int slots) {
    auto v = env::VecEnv::make(paper_env(), slots);
    REQUIRE(v);
    rl::EpisodeStreams streams(11);
    std::vector<std::vector<int>> by(6);
    const auto choose = rl::policy_choice(**p, *v, streams, false);
    rl::Driver d{[&](rl::Turn& t) {
                   SQUAWK_RETURN_IF_ERROR(choose(t));
                   for (size_t r = 0; r < t.slots.size(); ++r)
                     by[v->env(t.slots[r]).stats().index].push_back(t.actions[r].index);
                   return Status::ok();
                 },
                 {}};
    REQUIRE(rl::play(*v, 2, 0, 6, d));
    return by;
  };
  const auto one = actions_by_episode(1), five = actions_by_episode(5);
  CHECK(one == five);
  size_t decisions = 0;
  for (const auto& e : one) decisions += e.size();
  CHECK(decisions > 0);
}

TEST_CASE("run_training evaluates on schedule, reports every update, and stops when asked") {
  env::HorizontalCrConfig ec = paper_env();
  rl::TrainConfig cfg;
  cfg.episodes = 48;
  cfg.episodes_per_update = 8;
  cfg.num_envs = 4;
  cfg.eval_every = 16;
  cfg.eval_episodes = 6;
  cfg.value_hidden = {8};
  auto train_envs = env::VecEnv::make(ec, cfg.num_envs);
  auto eval_envs = env::VecEnv::make(ec, cfg.num_envs);
  REQUIRE(train_envs);
  REQUIRE(eval_envs);
  // The whole run, and the same run stopped by on_update after its 3rd update.
  auto run = [&](long long stop_after, std::vector<double>& returns,
                 std::vector<long long>& evals) {
    Rng init(4);
    auto p = rl::MlpPolicy::make({}, init);
    REQUIRE(p);
    rl::Trainer trainer(**p, *train_envs, cfg, 0);
    rl::TrainProgress progress;
    auto end =
        rl::run_training(trainer, **p, *eval_envs, cfg, 99, progress, {},
                         [&](const rl::UpdateReport& u) -> Result<bool> {
                           returns.push_back(u.stats.mean_return);
                           CHECK(u.progress.updates == static_cast<long long>(returns.size()));
                           CHECK(u.progress.episodes == 8 * u.progress.updates);
                           if (u.eval) {
                             evals.push_back(u.progress.episodes);
                             CHECK(u.eval->episodes == 6);
                           }
                           return u.progress.updates != stop_after;
                         });
    REQUIRE(end);
    return *end;
  };
  std::vector<double> all, part;
  std::vector<long long> all_evals, part_evals;
  CHECK(run(0, all, all_evals) == rl::RunEnd::kFinished);
  CHECK(all.size() == 6);
  CHECK(all_evals == std::vector<long long>{16, 32, 48});
  CHECK(run(3, part, part_evals) == rl::RunEnd::kStopped);
  REQUIRE(part.size() == 3);
  for (size_t i = 0; i < 3; ++i) CHECK(part[i] == all[i]);  // the same seed, the same numbers
  CHECK(part_evals == std::vector<long long>{16});
}
