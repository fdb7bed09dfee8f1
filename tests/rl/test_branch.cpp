// Simulation-based learners and references: branch returns (the "vine"
// estimator's Q) and the lookahead planner.
#include <doctest/doctest.h>

#include <vector>

#include "../env/paper_settings.h"
#include "env/vec_env.h"
#include "rl/baseline_policies.h"
#include "rl/branch_returns.h"
#include "rl/evaluator.h"
#include "rl/mlp_policy.h"

using namespace squawk;

namespace {

// The paper scenario's evaluation settings (scenarios/horizontal_cr.lua).
env::HorizontalCrConfig eval_config() {
  return test::paper_eval_config(true);
}

}  // namespace

TEST_CASE("branch returns are each action's discounted return under the greedy continuation") {
  auto v = env::VecEnv::make(eval_config(), 4);
  REQUIRE(v);
  v->start(11, 0, 4);
  REQUIRE(!v->waiting().empty());
  std::vector<env::HorizontalCrEnv> snaps;
  for (int s : v->waiting()) snaps.push_back(v->env(s));
  const std::vector<double> values = {-1, -0.5, 0, 0.5, 1};
  rl::ConstantPolicy hold_right(28, 0.5f);
  const double gamma = 0.9;
  auto q = rl::branch_returns(hold_right, snaps, values, gamma);
  REQUIRE(q);
  REQUIRE(q->size() == snaps.size() * values.size());
  bool differ = false;
  for (size_t i = 0; i < snaps.size(); ++i)
    for (size_t j = 0; j < values.size(); ++j) {
      env::HorizontalCrEnv e = snaps[i];
      double g = e.step(values[j]), d = gamma;
      while (!e.done()) {
        g += d * e.step(0.5);
        d *= gamma;
      }
      CHECK((*q)[i * values.size() + j] == doctest::Approx(g).epsilon(1e-12));
      differ |= (*q)[i * values.size() + j] != (*q)[i * values.size()];
    }
  CHECK(differ);  // the actions lead to different outcomes
  // The snapshots themselves are untouched.
  for (size_t i = 0; i < snaps.size(); ++i) CHECK_FALSE(snaps[i].done());
}

TEST_CASE("the lookahead planner resolves what the rules and MVP do not") {
  auto v = env::VecEnv::make(eval_config(), 8);
  REQUIRE(v);
  rl::LookaheadPolicy planner(*v, {-1, -0.5, 0, 0.5, 1});
  rl::ConstantPolicy right(28, 0.5f);
  rl::MvpPolicy mvp(*v);
  auto p = rl::evaluate(planner, *v, {200, 2024, false});
  auto c = rl::evaluate(right, *v, {200, 2024, false});
  auto m = rl::evaluate(mvp, *v, {200, 2024, false});
  REQUIRE(p);
  REQUIRE(c);
  REQUIRE(m);
  MESSAGE("lookahead " << p->success_rate << " / " << p->mean_reward << ", constant +0.5 " << c->success_rate
                       << " / " << c->mean_reward << ", mvp " << m->success_rate << " / " << m->mean_reward);
  CHECK(p->success_rate >= 0.98);
  CHECK(p->success_rate > m->success_rate);
  CHECK(p->mean_reward > c->mean_reward + 1.0);
  CHECK(p->mean_reward > m->mean_reward);
  auto again = rl::evaluate(planner, *v, {200, 2024, false});
  REQUIRE(again);
  CHECK(again->mean_reward == p->mean_reward);  // deterministic
}

TEST_CASE("one rollout step improves a policy, using its own continuations") {
  auto v = env::VecEnv::make(eval_config(), 8);
  REQUIRE(v);
  Rng init(2024);
  auto base = rl::MlpPolicy::make({}, init);
  REQUIRE(base);
  Rng init2(2024);
  auto same = rl::MlpPolicy::make({}, init2);
  REQUIRE(same);
  rl::RolloutPolicy improved(*v, std::move(*same));
  CHECK(improved.name() == "rollout:mlp");
  auto b = rl::evaluate(**base, *v, {200, 2024, true});
  auto r = rl::evaluate(improved, *v, {200, 2024, false});
  REQUIRE(b);
  REQUIRE(r);
  CHECK(improved.error().is_ok());
  MESSAGE("greedy untrained MLP " << b->success_rate << " / " << b->mean_reward << ", one rollout step "
                                  << r->success_rate << " / " << r->mean_reward);
  CHECK(r->success_rate > b->success_rate + 0.05);
  CHECK(r->mean_reward > b->mean_reward + 1.0);
}

namespace {
// Counts what a recorder would write.
struct CountingObserver : env::EpisodeObserver {
  int resets = 0, steps = 0, ends = 0;
  void on_reset(const env::HorizontalCrEnv&) override { ++resets; }
  void on_step(const env::HorizontalCrEnv&, const env::StepInfo&) override { ++steps; }
  void on_end(const env::HorizontalCrEnv&, const env::EpisodeStats&) override { ++ends; }
};
}  // namespace

TEST_CASE("planning branches are invisible to an episode's observer") {
  auto v = env::VecEnv::make(eval_config(), 4);
  REQUIRE(v);
  CountingObserver seen;
  for (int s = 0; s < v->size(); ++s) v->env(s).set_observer(&seen);
  rl::LookaheadPolicy planner(*v, {-1, -0.5, 0, 0.5, 1});
  Rng init(3);
  auto base = rl::MlpPolicy::make({}, init);
  REQUIRE(base);
  rl::RolloutPolicy rollout(*v, std::move(*base));
  for (rl::Policy* p : {static_cast<rl::Policy*>(&planner), static_cast<rl::Policy*>(&rollout)}) {
    seen = {};
    auto r = rl::evaluate(*p, *v, {20, 2024, false});
    REQUIRE(r);
    CHECK(seen.resets == 20);
    CHECK(seen.ends == 20);
    CHECK(seen.steps == static_cast<int>(r->env_steps));  // one per step really flown
  }
}

TEST_CASE("a rollout step reports its base's observation size, so a mismatched base is refused") {
  env::HorizontalCrConfig three = eval_config();
  three.num_intruders = 3;  // rows of 3 + 5 * 3 = 18 values
  auto v = env::VecEnv::make(three, 2);
  REQUIRE(v);
  Rng init(1);
  auto base = rl::MlpPolicy::make({}, init);  // reads 28 values
  REQUIRE(base);
  rl::RolloutPolicy improved(*v, std::move(*base));
  CHECK(improved.obs_size() == 28);
  CHECK_FALSE(rl::check_obs_size(improved, v->obs_size()).is_ok());
  CHECK_FALSE(rl::evaluate(improved, *v, {2, 1, false}));
  rl::LookaheadPolicy planner(*v, {-1, -0.5, 0, 0.5, 1});
  CHECK(planner.obs_size() == 18);
}
