// The learner and the evaluator drive environments through env::BatchEnv
// (env/batch_env.h). A batch that only forwards the interface to a VecEnv
// (no access to the compiled kernel behind it) must train and evaluate
// exactly as the VecEnv itself: nothing in rl/ reaches past the interface
// except vine's branching. (Before and after the interface came in, this
// build's parameters after three updates of vpg, improved, ppo and vine were
// checked equal by hash; the hash itself depends on the build's flags.)
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "env/vec_env.h"
#include "rl/evaluator.h"
#include "rl/mlp_policy.h"
#include "rl/vpg.h"

using namespace squawk;

namespace {

class Forwarding final : public env::BatchEnv {
 public:
  explicit Forwarding(env::VecEnv& v) : v_(v) {}
  void start(uint64_t seed, uint64_t first, uint64_t count) override {
    v_.start(seed, first, count);
  }
  int size() const override { return v_.size(); }
  int obs_size() const override { return v_.obs_size(); }
  const std::vector<int>& waiting() const override { return v_.waiting(); }
  std::span<const float> observations() const override { return v_.observations(); }
  void step(std::span<const double> a, std::span<double> r, std::span<uint8_t> d) override {
    v_.step(a, r, d);
  }
  bool finished() const override { return v_.finished(); }
  std::vector<env::EpisodeStats>& completed() override { return v_.completed(); }
  long long env_steps() const override { return v_.env_steps(); }
  uint64_t episode(int slot) const override { return v_.episode(slot); }

 private:
  env::VecEnv& v_;
};

// Parameters after three updates of `estimator`, then the figures of a
// sampled 40-episode evaluation, through the VecEnv or the forwarding batch.
std::vector<double> trained(const std::string& estimator, env::Rules rules, bool forward) {
  env::HorizontalCrConfig ec;
  ec.rules = rules;
  rl::TrainConfig tc;
  tc.estimator = estimator;
  tc.episodes_per_update = 8;
  tc.num_envs = 4;
  tc.seed = 5;
  tc.epochs = 2;
  tc.minibatches = 2;
  rl::MlpPolicySpec spec;
  if (rules == env::Rules::kGym) spec.head = "gaussian";
  Rng init(1);
  auto p = rl::MlpPolicy::make(spec, init);
  REQUIRE(p);
  auto v = env::VecEnv::make(ec, tc.num_envs);
  REQUIRE(v);
  Forwarding f(*v);
  env::BatchEnv& envs = forward ? static_cast<env::BatchEnv&>(f) : *v;
  rl::Trainer tr(**p, envs, tc, 0);
  std::vector<double> out;
  for (int i = 0; i < 3; ++i) out.push_back(tr.update().mean_return);
  for (float x : (*p)->params()) out.push_back(x);
  auto ev = rl::evaluate(**p, envs, {40, 77, false});
  REQUIRE(ev);
  for (double x :
       {ev->mean_reward, ev->std_reward, ev->success_rate, ev->mean_steps, ev->separation_median})
    out.push_back(x);
  for (long long c : ev->action_counts) out.push_back(static_cast<double>(c));
  return out;
}

}  // namespace

TEST_CASE(
    "training and evaluation through the BatchEnv interface alone equal the VecEnv's, bit for "
    "bit") {
  for (const char* est : {"vpg", "improved", "ppo"}) {
    CAPTURE(est);
    CHECK(trained(est, env::Rules::kPaper, true) == trained(est, env::Rules::kPaper, false));
  }
  CHECK(trained("improved", env::Rules::kGym, true) ==
        trained("improved", env::Rules::kGym, false));
}
