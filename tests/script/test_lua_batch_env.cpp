// Lua environments as a batch for the learner (script/lua_batch_env.h): the
// action grid, episodes identical to the single-instance driver whatever the
// number of slots, errors that end a run, the MLP learner raising the
// return of a trivially learnable file (tests/data/gym/sign.lua), and the
// imitation of a scripted rule (tests/data/gym/sign_half.lua) on it.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "../small_gaussian.h"
#include "rl/evaluator.h"
#include "rl/imitation.h"
#include "rl/mlp_policy.h"
#include "rl/obs_norm.h"
#include "rl/play.h"
#include "rl/train_run.h"
#include "rl/vpg.h"
#include "scratch_dir.h"
#include "script/lua_batch_env.h"
#include "script/lua_teacher.h"

using namespace squawk;

namespace {

std::string repo(const char* rel) {
  return std::string(SQUAWK_TEST_DATA) + "/../../" + rel;
}

std::unique_ptr<script::LuaBatchEnv> batch(const std::string& path, int slots, int levels) {
  auto b = script::LuaBatchEnv::make(path, {}, slots, levels);
  REQUIRE_MESSAGE(b.is_ok(), b.status().message());
  return std::move(*b);
}

// The grid class of episode k's step t in the tests below.
int class_of(uint64_t k, int t, int classes) {
  return static_cast<int>((k * 7 + static_cast<uint64_t>(t) * 3) % static_cast<uint64_t>(classes));
}

// The learner settings of the small training tests: 640 episodes, 16 an update, 4
// environments, Adam 1e-2, no value network, no evaluation during training.
rl::TrainConfig small_run() {
  rl::TrainConfig tc;
  tc.episodes = 640;
  tc.episodes_per_update = 16;
  tc.num_envs = 4;
  tc.lr = tc.lr_final = 1e-2;
  tc.value_hidden = {};
  tc.eval_every = 0;
  return tc;
}

}  // namespace

TEST_CASE("the action grid: K levels per component, component j from digit j of the class") {
  script::LuaEnvSpec s;
  s.id = "Box2";
  s.action_low = {-1, 0};
  s.action_high = {1, 10};
  auto c = script::grid_classes(s, 5);
  REQUIRE(c);
  CHECK(*c == 25);
  std::vector<double> a(2);
  script::grid_action(s, 5, 0, a);
  CHECK(a == std::vector<double>{-1, 0});
  script::grid_action(s, 5, 24, a);
  CHECK(a == std::vector<double>{1, 10});
  script::grid_action(s, 5, 7, a);  // digits 2, 1
  CHECK(a == std::vector<double>{0, 2.5});
  CHECK(script::grid_value(0, 25) == -1.0);
  CHECK(script::grid_value(24, 25) == 1.0);
  CHECK(script::grid_class(static_cast<float>(script::grid_value(7, 25)), 25) == 7);
  CHECK(script::grid_class(0.05, 25) == -1);
  CHECK(script::grid_class(1.0, 25) == 24);
  auto k = script::grid_levels(s, 25);
  REQUIRE(k);
  CHECK(*k == 5);
  CHECK(script::grid_levels(s, 24).status().message().find(
            "24 action classes does not fit Box2's 2") != std::string::npos);
  CHECK(script::grid_classes(s, 1).status().message().find("expected at least 2") !=
        std::string::npos);
  CHECK(script::grid_classes(s, 100).status().message().find("more than 4096 classes") !=
        std::string::npos);
}

TEST_CASE("a batch plays the same episodes as one instance stepped alone, whatever its slots") {
  const std::string path = repo("envs/descent.lua");
  auto one = script::LuaEnv::load(path, {});
  REQUIRE(one);
  const int levels = 5;
  std::vector<double> want;  // returns of episodes 0..5 of seed 40
  std::vector<double> act(1);
  for (uint64_t k = 0; k < 6; ++k) {
    REQUIRE((*one)->reset(40 + k).is_ok());
    double total = 0;
    for (int t = 0;; ++t) {
      script::grid_action((*one)->spec(), levels, class_of(k, t, levels), act);
      auto r = (*one)->step(act);
      REQUIRE(r);
      total += r->reward;
      if (r->terminated || r->truncated) break;
    }
    want.push_back(total);
  }
  for (int slots : {1, 4}) {
    auto b = batch(path, slots, levels);
    std::vector<int> step_of(static_cast<size_t>(slots), 0);
    rl::Driver d;
    d.choose = [&](rl::Turn& t) {
      for (size_t r = 0; r < t.slots.size(); ++r) {
        const int s = t.slots[r];
        t.actions[r].value = static_cast<float>(script::grid_value(
            class_of(b->episode(s), step_of[static_cast<size_t>(s)]++, levels), levels));
      }
      return Status::ok();
    };
    d.after = [&](const rl::Turn& t) {
      for (size_t r = 0; r < t.slots.size(); ++r)
        if (t.dones[r]) step_of[static_cast<size_t>(t.slots[r])] = 0;
      return true;
    };
    auto played = rl::play(*b, 40, 0, 6, d);
    REQUIRE_MESSAGE(played.is_ok(), played.status().message());
    CHECK(*played);
    std::vector<double> got(6, NAN);
    for (const env::EpisodeStats& e : b->completed()) {
      got[e.index] = e.total_reward;
      CHECK(e.steps > 0);
      CHECK(e.reached != e.truncated);
    }
    CHECK(got == want);
  }
}

TEST_CASE("an action off the grid or a Lua error ends the run with the file's name") {
  auto b = batch(repo("tests/data/gym/sign.lua"), 2, 3);
  rl::Driver d;
  d.choose = [](rl::Turn& t) {
    for (auto& a : t.actions) a.value = 0.5f;  // classes -1, 0, 1
    return Status::ok();
  };
  auto r = rl::play(*b, 0, 0, 4, d);
  REQUIRE_FALSE(r.is_ok());
  CHECK(r.status().message().find("sign.lua: action 0.5") != std::string::npos);
  CHECK(r.status().message().find("3-point action grid (-1 + 2 c / 2)") != std::string::npos);

  const std::string broken = (test::scratch_dir("lua_batch_env") / "broken.lua").string();
  std::ofstream(broken) << "return {id = 'Broken-v0', observation = {{name = 'x', size = 1}},\n"
                           "  action = {low = {-1}, high = {1}}, max_episode_steps = 5,\n"
                           "  reset = function() return {0} end,\n"
                           "  step = function(self, a) error('no step here') end}\n";
  auto e = batch(broken, 2, 3);
  d.choose = [](rl::Turn& t) {
    for (auto& a : t.actions) a.value = 1.0f;
    return Status::ok();
  };
  r = rl::play(*e, 0, 0, 4, d);
  REQUIRE_FALSE(r.is_ok());
  CHECK(r.status().message().find("no step here") != std::string::npos);
  CHECK(e->finished());

  // The learner stops on it too, with the same message.
  rl::MlpPolicySpec spec;
  spec.obs_size = 1;
  spec.hidden = {4};
  spec.action_values = script::grid_values(3);
  Rng init(0);
  auto p = rl::MlpPolicy::make(spec, init);
  REQUIRE(p);
  rl::TrainConfig tc;
  tc.episodes = 8;
  tc.episodes_per_update = 4;
  tc.num_envs = 2;
  rl::Trainer tr(**p, *e, tc, 0);
  rl::TrainProgress progress;
  auto ended = rl::run_training(tr, **p, *e, tc, 0, progress, {},
                                [](const rl::UpdateReport&) -> Result<bool> { return true; });
  REQUIRE_FALSE(ended.is_ok());
  CHECK(ended.status().message().find("no step here") != std::string::npos);
  CHECK(progress.episodes == 0);
}

TEST_CASE("the MLP learner raises the return of a Lua environment (sign.lua: random -6, best 0)") {
  auto train_envs = batch(repo("tests/data/gym/sign.lua"), 4, 5);
  auto eval_envs = batch(repo("tests/data/gym/sign.lua"), 4, 5);
  rl::MlpPolicySpec spec;
  spec.obs_size = 1;
  spec.hidden = {16};
  spec.action_values = script::grid_values(5);
  Rng init(3);
  auto p = rl::MlpPolicy::make(spec, init);
  REQUIRE(p);
  rl::TrainConfig tc = small_run();
  tc.eval_episodes = 100;
  auto before = rl::evaluate(**p, *eval_envs, {100, 7, false});
  REQUIRE(before);
  CHECK(before->mean_reward < -3.0);
  rl::Trainer tr(**p, *train_envs, tc, 0);
  rl::TrainProgress progress;
  const rl::EvalResult* last = nullptr;
  rl::EvalResult kept;
  auto ended = rl::run_training(tr, **p, *eval_envs, tc, 7, progress, {},
                                [&](const rl::UpdateReport& u) -> Result<bool> {
                                  if (u.eval) {
                                    kept = *u.eval;
                                    last = &kept;
                                  }
                                  return true;
                                });
  REQUIRE_MESSAGE(ended.is_ok(), ended.status().message());
  CHECK(progress.episodes == 640);
  REQUIRE(last);
  MESSAGE("sign.lua: mean return " << before->mean_reward << " before, " << last->mean_reward
                                   << " after 40 updates");
  CHECK(last->mean_reward > -0.5);
  CHECK(last->mean_steps == 4.0);
}

TEST_CASE(
    "continuous actions (levels 0): each number clipped to [-1, 1] and mapped onto its Box "
    "component") {
  script::LuaEnvSpec s;
  s.action_low = {0, -2};
  s.action_high = {10, 2};
  std::vector<double> a(2);
  const std::vector<double> v1 = {-0.5, 0.5}, v2 = {3.0, -7.0};
  script::box_action(s, v1, a);
  CHECK(a[0] == 2.5);
  CHECK(a[1] == 1.0);
  script::box_action(s, v2, a);
  CHECK(a[0] == 10.0);
  CHECK(a[1] == -2.0);
  // sign.lua pays -(a - s)^2: the action 0.25 costs 0.5625 on s = 1 and
  // 1.5625 on s = -1, and 9 (clipped to 1) costs 0 and 4.
  auto e = batch(repo("tests/data/gym/sign.lua"), 2, 0);
  CHECK(e->continuous());
  CHECK(e->classes() == 0);
  for (double v : {0.25, 9.0}) {
    e->start(0, 0, 2);
    std::vector<float> signs(e->observations().begin(), e->observations().end());
    REQUIRE(signs.size() == 2);
    const std::vector<double> acts(2, v);
    std::vector<double> rewards(2);
    std::vector<uint8_t> dones(2);
    e->step(acts, rewards, dones);
    REQUIRE(e->error().is_ok());
    const double a = std::min(v, 1.0);
    for (size_t r = 0; r < 2; ++r)
      CHECK(rewards[r] == doctest::Approx(-(a - signs[r]) * (a - signs[r])));
  }
  // Sign2-v0 (tests/data/gym/sign2.lua): two numbers per slot, row-major;
  // the second maps [-1, 1] onto [0, 10].
  auto two = batch(repo("tests/data/gym/sign2.lua"), 2, 0);
  CHECK(two->action_size() == 2);
  two->start(0, 0, 2);
  const std::vector<float> signs(two->observations().begin(), two->observations().end());
  REQUIRE(signs.size() == 4);
  const std::vector<double> acts = {0.5, -1.0, 9.0, 0.2};  // slot 0: (0.5, 0); slot 1: (1, 6)
  std::vector<double> rewards(2);
  std::vector<uint8_t> dones(2);
  two->step(acts, rewards, dones);
  REQUIRE(two->error().is_ok());
  const double want[2][2] = {{0.5, -1.0}, {1.0, 0.2}};
  for (size_t r = 0; r < 2; ++r)
    CHECK(rewards[r] ==
          doctest::Approx(-(want[r][0] - signs[2 * r]) * (want[r][0] - signs[2 * r]) -
                          (want[r][1] - signs[2 * r + 1]) * (want[r][1] - signs[2 * r + 1])));
  // A grid batch takes one number (the class) per slot.
  CHECK(batch(repo("tests/data/gym/sign2.lua"), 1, 3)->action_size() == 1);
  const std::string five = (test::scratch_dir("lua_batch_env") / "five.lua").string();
  std::ofstream(five) << "return {id = 'Five-v0', observation = {{name = 'x', size = 1}},\n"
                         "  action = {low = {-1, -1, -1, -1, -1}, high = {1, 1, 1, 1, 1}},\n"
                         "  max_episode_steps = 1,\n"
                         "  reset = function(self, seed) return {0} end,\n"
                         "  step = function(self, a) return {0}, 0, true, false end}\n";
  auto wide = script::LuaBatchEnv::make(five, {}, 1, 0);
  REQUIRE_FALSE(wide);
  CHECK_MESSAGE(wide.status().message().find(
                    "continuous actions need a Box of at most 4 components; Five-v0 has 5") !=
                    std::string::npos,
                wide.status().message());
}

TEST_CASE(
    "the Gaussian head learns a Lua environment's continuous action (sign.lua, sign2.lua: best "
    "0)") {
  for (const std::string file : {"sign.lua", "sign2.lua"}) {
    CAPTURE(file);
    auto train_envs = batch(repo(("tests/data/gym/" + file).c_str()), 4, 0);
    auto eval_envs = batch(repo(("tests/data/gym/" + file).c_str()), 4, 0);
    rl::MlpPolicySpec spec;
    spec.obs_size = train_envs->obs_size();
    spec.hidden = {16};
    spec.head = "gaussian";
    spec.action_size = train_envs->action_size();
    Rng init(3);
    auto p = rl::MlpPolicy::make(spec, init);
    REQUIRE(p);
    rl::TrainConfig tc = small_run();
    tc.estimator = "ppo";
    auto before = rl::evaluate(**p, *eval_envs, {100, 7, true});
    REQUIRE(before);
    CHECK(before->mean_reward < -2.0);
    rl::Trainer tr(**p, *train_envs, tc, 0);
    rl::TrainProgress progress;
    auto ended = rl::run_training(tr, **p, *eval_envs, tc, 7, progress, {},
                                  [](const rl::UpdateReport&) -> Result<bool> { return true; });
    REQUIRE_MESSAGE(ended.is_ok(), ended.status().message());
    auto after = rl::evaluate(**p, *eval_envs, {100, 7, true});
    REQUIRE(after);
    MESSAGE(file << ", Gaussian head (mean action): " << before->mean_reward << " before, "
                 << after->mean_reward << " after 40 updates");
    CHECK(after->mean_reward > -0.5 * spec.action_size);
  }
}

TEST_CASE("observation_stats: each number's mean and deviation over the episodes' decisions") {
  // sign2.lua's observations do not depend on the actions: the statistics of
  // the policy's episodes are those of the same episodes played with zeros.
  auto envs = batch(repo("tests/data/gym/sign2.lua"), 3, 0);
  auto p = small_gaussian(1);
  REQUIRE(p);
  auto stats = rl::observation_stats(**p, *envs, 5, 50);
  REQUIRE_MESSAGE(stats.is_ok(), stats.status().message());
  double sum[2] = {0, 0}, sq[2] = {0, 0};
  long long rows = 0;
  rl::Driver zeros{[&](rl::Turn& t) {
                     for (size_t i = 0; i < t.obs.size(); ++i) {
                       sum[i % 2] += t.obs[i];
                       sq[i % 2] += t.obs[i] * t.obs[i];
                     }
                     rows += static_cast<long long>(t.slots.size());
                     return Status::ok();
                   },
                   {}};
  REQUIRE(rl::play(*envs, 5, 0, 50, zeros).value_or(false));
  CHECK(rows == 200);  // 50 episodes of 4 steps
  for (size_t j = 0; j < 2; ++j) {
    const double mean = sum[j] / rows;
    CHECK(stats->mean[j] == doctest::Approx(mean));
    CHECK(stats->std[j] == doctest::Approx(std::sqrt(sq[j] / rows - mean * mean)));
    CHECK(std::fabs(stats->mean[j]) < 0.3);  // signs of +-1, drawn evenly
    CHECK(stats->std[j] > 0.9);
  }
  CHECK(rl::observation_stats(**p, *envs, 5, 0).status().message() ==
        "observation statistics need at least 1 episode, got 0");
}

// sign_half.lua plays half the sign: -0.25 a step. A student cloned from it
// greedily plays that too (its mean reward is the rule's, -1 an episode,
// where the untrained Gaussian head's is below -2), whatever the head.
TEST_CASE("imitation clones a Lua rule on a Lua environment, Gaussian and grid heads") {
  for (const int levels : {0, 5}) {
    CAPTURE(levels);
    auto envs = batch(repo("tests/data/gym/sign.lua"), 3, levels);
    auto teacher = script::LuaTeacher::load(repo("tests/data/gym/sign_half.lua"), {}, *envs);
    REQUIRE_MESSAGE(teacher.is_ok(), teacher.status().message());
    CHECK(std::vector<double>((*teacher)->action_values().begin(),
                              (*teacher)->action_values().end()) ==
          (levels ? script::grid_values(5) : std::vector<double>{}));
    rl::MlpPolicySpec spec;
    spec.obs_size = 1;
    spec.hidden = {16};
    if (levels)
      spec.action_values = script::grid_values(5);
    else
      spec.head = "gaussian";
    Rng init(5);
    auto p = rl::MlpPolicy::make(spec, init);
    REQUIRE(p);
    auto before = rl::evaluate(**p, *envs, {40, 9, true});
    REQUIRE(before);
    rl::ImitationConfig ic;
    ic.episodes = 40;  // 160 decisions a round
    ic.rounds = 2;
    ic.epochs = 20;
    ic.batch = 16;
    ic.lr = 1e-2f;
    ic.holdout = 10;
    rl::TeacherFlights flights;
    rl::ImitationEpoch last;
    Status st = rl::imitate(
        **p, **teacher, *envs, ic,
        [&](const rl::ImitationEpoch& e) {
          last = e;
          return Status::ok();
        },
        &flights);
    REQUIRE_MESSAGE(st.is_ok(),
                    st.message());  // sign_half.lua fails unless reset before every episode
    CHECK(last.round == 1);
    CHECK_FALSE(last.teacher_flew);
    CHECK(last.decisions == 320);
    CHECK(last.agreement == 1.0);
    CHECK(last.action_error < (levels ? 1e-6 : 0.05));
    // round 0's flights: 40 episodes of four steps at -0.25
    CHECK(flights.lengths == std::vector<int>(40, 4));
    CHECK(flights.rewards == std::vector<double>(160, -0.25));
    CHECK(flights.obs.size() == 160);
    auto after = rl::evaluate(**p, *envs, {40, 9, true});
    REQUIRE(after);
    MESSAGE("sign.lua cloned from sign_half.lua (levels " << levels << "): " << before->mean_reward
                                                          << " -> " << after->mean_reward);
    CHECK(after->mean_reward == doctest::Approx(-1.0).epsilon(0.05));
    if (!levels) CHECK(before->mean_reward < -1.5);

    // The value baseline fitted to those flights' returns (gamma 0.5: -0.25 (1 + 0.5 + ...)).
    rl::TrainConfig tc;
    tc.estimator = "ppo";
    tc.gamma = 0.5;
    tc.value_hidden = {16};
    tc.lr = 1e-2;
    rl::Trainer tr(**p, *envs, tc, 0);
    auto fit = tr.pretrain_value(flights, 40, 16, 3);
    REQUIRE_MESSAGE(fit.is_ok(), fit.status().message());
    MESSAGE("value fit: " << fit->before << " -> " << fit->after);
    CHECK(fit->after < 0.01);
    CHECK(fit->after < fit->before / 10);
    rl::TeacherFlights broken = flights;
    broken.lengths.pop_back();
    auto bad = tr.pretrain_value(broken, 1, 16, 3);
    REQUIRE_FALSE(bad);
    CHECK(bad.status().message() ==
          "value pretraining: 160 observation numbers, 160 rewards and 156 steps in "
          "the episode lengths (expected obs_size x steps, steps, steps)");
  }
}

// The student and the cloning both sign2 tests below use: a [2] -> 16 -> [2] Gaussian MLP,
// 40 episodes a round, 2 rounds of 20 epochs in batches of 16, the last `held` parameters held.
static Result<std::unique_ptr<rl::MlpPolicy>> sign2_student() {
  rl::MlpPolicySpec spec;
  spec.obs_size = 2;
  spec.hidden = {16};
  spec.head = "gaussian";
  spec.action_size = 2;
  spec.init_log_std = -1.0;
  Rng init(5);
  return rl::MlpPolicy::make(spec, init);
}
static rl::ImitationConfig sign2_imitation(size_t held) {
  rl::ImitationConfig ic;
  ic.episodes = 40;
  ic.rounds = 2;
  ic.epochs = 20;
  ic.batch = 16;
  ic.lr = 1e-2f;
  ic.holdout = 10;
  ic.held_tail = held;
  return ic;
}
// What rl::imitate answers when it refuses `config` for a small Gaussian student (nothing is
// fitted).
static std::string imitation_refused(rl::Policy& teacher, env::BatchEnv& envs,
                                     const rl::ImitationConfig& config) {
  auto p = small_gaussian(1);
  REQUIRE(p);
  return rl::imitate(**p, teacher, envs, config, {}).message();
}

// sign2_half.lua: half the first sign and the second component always at 10,
// the top of [0, 10]. The teacher's label carries both components (each on
// [-1, 1]); cloned with its log sigmas held (held_tail), the student plays the
// rule's reward and keeps its log sigmas bit for bit; with them learned, the
// constant component's sigma collapses.
TEST_CASE("imitation of a two-component rule: every component labelled, log sigma held") {
  auto envs = batch(repo("tests/data/gym/sign2.lua"), 3, 0);
  auto teacher = script::LuaTeacher::load(repo("tests/data/gym/sign2_half.lua"), {}, *envs);
  REQUIRE_MESSAGE(teacher.is_ok(), teacher.status().message());
  auto rule = rl::evaluate(**teacher, *envs, {40, 9, true});
  REQUIRE(rule);
  for (const size_t held : {size_t{2}, size_t{0}}) {
    CAPTURE(held);
    auto p = sign2_student();
    REQUIRE(p);
    const std::vector<float> log_std_before((*p)->params().end() - 2, (*p)->params().end());
    rl::ImitationConfig ic = sign2_imitation(held);
    rl::ImitationEpoch last;
    Status st = rl::imitate(**p, **teacher, *envs, ic, [&](const rl::ImitationEpoch& e) {
      last = e;
      return Status::ok();
    });
    REQUIRE_MESSAGE(st.is_ok(), st.message());
    const std::vector<float> log_std_after((*p)->params().end() - 2, (*p)->params().end());
    auto after = rl::evaluate(**p, *envs, {40, 9, true});
    REQUIRE(after);
    MESSAGE("sign2.lua cloned from sign2_half.lua, held "
            << held << ": " << after->mean_reward << " (rule " << rule->mean_reward
            << "), log sigma " << log_std_after[0] << ", " << log_std_after[1]);
    if (held) {
      CHECK(log_std_after == log_std_before);
      CHECK(last.agreement == 1.0);
      CHECK(after->mean_reward == doctest::Approx(rule->mean_reward).epsilon(0.02));
    } else {
      CHECK(log_std_after[1] < log_std_before[1] - 1.0);  // the constant component's sigma shrinks
    }
  }
  rl::ImitationConfig too_many;
  too_many.held_tail = 1000;
  CHECK(imitation_refused(**teacher, *envs, too_many) ==
        "imitation: held_tail 1000 exceeds the student's 24 parameters");
}

// sign2_half.lua's second component is always at the edge of the box (+1):
// fitted as labelled the clone's mean stays at 1, fitted at saturated_label
// 1.5 it goes past the edge (flown clipped, the rule's action), while the
// first component's labels (+-0.5, inside the box) are fitted as they are.
TEST_CASE("imitation with saturated_label: a label at the box edge is fitted past it") {
  auto envs = batch(repo("tests/data/gym/sign2.lua"), 3, 0);
  auto teacher = script::LuaTeacher::load(repo("tests/data/gym/sign2_half.lua"), {}, *envs);
  REQUIRE_MESSAGE(teacher.is_ok(), teacher.status().message());
  const std::vector<float> obs = {1, 1, 1, -1, -1, 1, -1, -1};  // [4, 2] every pair of signs
  const std::vector<int> slots = {0, 1, 2, 3};
  for (const float saturated : {1.0f, 1.5f}) {
    CAPTURE(saturated);
    auto p = sign2_student();
    REQUIRE(p);
    rl::ImitationConfig ic = sign2_imitation(2);
    ic.saturated_label = saturated;
    rl::ImitationEpoch last;
    Status st = rl::imitate(**p, **teacher, *envs, ic, [&](const rl::ImitationEpoch& e) {
      last = e;
      return Status::ok();
    });
    REQUIRE_MESSAGE(st.is_ok(), st.message());
    CHECK(last.agreement == 1.0);  // the clipped action is the rule's either way
    std::vector<rl::ActionSample> means(4);
    Rng rng(1);
    (*p)->act(obs, 4, slots, {&rng, 1}, true, means);
    for (size_t r = 0; r < 4; ++r) {
      CAPTURE(r);
      CHECK(means[r].component(0) == doctest::Approx(0.5 * obs[2 * r]).epsilon(0.1));
      CHECK(means[r].component(1) == doctest::Approx(saturated).epsilon(0.05));
    }
  }
  rl::ImitationConfig below;
  below.saturated_label = 0.9f;
  CHECK(imitation_refused(**teacher, *envs, below) ==
        "imitation: saturated_label 0.900000 (expected >= 1, and 1 for a discrete head)");
}

TEST_CASE("imitation refuses a teacher and a student of different kinds") {
  auto envs = batch(repo("tests/data/gym/sign.lua"), 2, 0);
  auto teacher = script::LuaTeacher::load(repo("tests/data/gym/sign_half.lua"), {}, *envs);
  REQUIRE(teacher);
  rl::MlpPolicySpec spec;
  spec.obs_size = 1;
  spec.hidden = {4};
  Rng init(1);
  auto p = rl::MlpPolicy::make(spec, init);
  REQUIRE(p);
  Status st = rl::imitate(**p, **teacher, *envs, {},
                          [](const rl::ImitationEpoch&) { return Status::ok(); });
  CHECK(st.message() == "imitation: the teacher script:" + repo("tests/data/gym/sign_half.lua") +
                            " has a continuous action, the student mlp has discrete classes "
                            "(expected the same kind)");
}
