// Learner tests: gradients against finite differences, checkpoints, exact
// reproducibility and resumption of training.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "../env/paper_settings.h"
#include "../finite_difference.h"
#include "../small_gaussian.h"
#include "core/files.h"
#include "env/vec_env.h"
#include "nn/categorical.h"
#include "nn/gaussian.h"
#include "nn/mlp.h"
#include "rl/baseline_policies.h"
#include "rl/checkpoint.h"
#include "rl/evaluator.h"
#include "rl/mlp_policy.h"
#include "rl/vpg.h"

using namespace squawk;

namespace {

// Loss L(params) = sum_b sum_k c[b,k] y[b,k] for fixed c, so dL/dy = c.
double mlp_loss(const nn::Mlp& m, const std::vector<float>& p, const std::vector<float>& x, int batch,
                const std::vector<float>& c) {
  std::vector<float> y(static_cast<size_t>(batch * m.out_dim()));
  m.forward(p, x.data(), batch, y.data(), nullptr);
  double l = 0.0;
  for (size_t i = 0; i < y.size(); ++i) l += static_cast<double>(c[i]) * y[i];
  return l;
}

std::string temp_path(const char* name) {
  return (std::filesystem::temp_directory_path() / name).string();
}

}  // namespace

TEST_CASE("MLP backward matches central finite differences") {
  auto m = nn::Mlp::make({4, 6, 5, 3});
  REQUIRE(m);
  CHECK(m->num_params() == (4 * 6 + 6) + (6 * 5 + 5) + (5 * 3 + 3));
  Rng rng(3);
  std::vector<float> p(m->num_params()), g(m->num_params(), 0.0f);
  m->init(p, rng);
  const int batch = 3;
  std::vector<float> x(12), c(9);
  for (auto& v : x) v = static_cast<float>(rng.uniform(-1, 1));
  for (auto& v : c) v = static_cast<float>(rng.uniform(-1, 1));
  nn::MlpCache cache;
  std::vector<float> y(9);
  m->forward(p, x.data(), batch, y.data(), &cache);
  m->backward(p, cache, c.data(), g);
  double worst = 0.0;
  for (size_t i = 0; i < p.size(); ++i) {
    const float h = 1e-3f, keep = p[i];
    p[i] = keep + h;
    const double lp = mlp_loss(*m, p, x, batch, c);
    p[i] = keep - h;
    const double lm = mlp_loss(*m, p, x, batch, c);
    p[i] = keep;
    const double fd = (lp - lm) / (2 * h);
    worst = std::max(worst, std::fabs(fd - g[i]));
  }
  CHECK(worst < 5e-3);  // float32 central differences, h = 1e-3
  CHECK_FALSE(nn::Mlp::make({4}));
  CHECK_FALSE(nn::Mlp::make({4, 0, 2}));
}

TEST_CASE("paper-sized MLP policy has about 12,000 parameters") {
  Rng rng(0);
  auto p = rl::MlpPolicy::make({}, rng);
  REQUIRE(p);
  CHECK((*p)->params().size() == 12581);
}

TEST_CASE("categorical and Gaussian log-prob gradients match finite differences") {
  const std::vector<float> z = {0.3f, -1.2f, 2.0f, 0.1f, -0.4f};
  std::vector<float> lp(5), dz(5, 0.0f);
  nn::log_softmax(z, lp);
  nn::categorical_grad(lp, 2, 1.0f, 0.5f, dz);
  auto obj = [&](std::vector<float> zz) {
    std::vector<float> l(5);
    nn::log_softmax(zz, l);
    return static_cast<double>(l[2]) + 0.5 * nn::categorical_entropy(l);
  };
  for (size_t k = 0; k < 5; ++k) {
    auto zp = z, zm = z;
    zp[k] += 1e-3f;
    zm[k] -= 1e-3f;
    CHECK(dz[k] == doctest::Approx((obj(zp) - obj(zm)) / 2e-3).epsilon(1e-2));
  }
  const nn::GaussianGrad g = nn::gaussian_grad(0.4f, 0.1f, -0.7f, 1.0f, 0.0f);
  const double h = 1e-3;
  CHECK(g.d_mu == doctest::Approx((nn::gaussian_log_prob(0.4f, 0.1f + h, -0.7f) -
                                   nn::gaussian_log_prob(0.4f, 0.1f - h, -0.7f)) / (2 * h)).epsilon(1e-2));
  CHECK(g.d_log_std == doctest::Approx((nn::gaussian_log_prob(0.4f, 0.1f, -0.7f + h) -
                                        nn::gaussian_log_prob(0.4f, 0.1f, -0.7f - h)) / (2 * h)).epsilon(1e-2));
}

TEST_CASE(
    "the Gaussian MLP policy's gradient (network and log sigmas) matches finite differences") {
  // D = 1 (the gym rules' head) and D = 2, 3 (the diagonal head of the two-component Boxes):
  // log pi sums the components' log densities, H their entropies.
  for (const int d : {1, 2, 3}) {
    CAPTURE(d);
    rl::MlpPolicySpec spec;
    spec.obs_size = 3;
    spec.hidden = {8, 8};
    spec.head = "gaussian";
    spec.action_size = d;
    Rng init(5);
    auto made = rl::MlpPolicy::make(spec, init);
    REQUIRE(made);
    rl::MlpPolicy& p = **made;
    const int n = 4;
    const std::vector<float> rows = {0.2f, -0.5f, 1.0f,  -0.3f, 0.8f, 0.1f,
                                     0.6f, 0.4f,  -0.9f, -0.1f, 0.0f, 0.7f};
    std::vector<rl::ActionSample> acts = {{-1, 0.9f}, {-1, -0.4f}, {-1, 0.1f}, {-1, -1.3f}};
    for (int r = 0; r < n; ++r)
      for (int j = 1; j < d; ++j)
        acts[static_cast<size_t>(r)].component(j) = 0.3f * static_cast<float>(j - r);
    // Distinct log sigmas, so a component's gradient landing on another's would show.
    std::span<float> log_std = p.params().last(static_cast<size_t>(d));
    for (int j = 0; j < d; ++j)
      log_std[static_cast<size_t>(j)] = -0.5f + 0.2f * static_cast<float>(j);
    const std::vector<float> coef = {0.8f, -1.1f, 0.5f, 0.3f};
    const float ent = 0.1f;
    std::fill(p.grads().begin(), p.grads().end(), 0.0f);
    const float mean_entropy = p.accumulate_gradient(rows, n, acts, coef, ent);
    const std::vector<float> g(p.grads().begin(), p.grads().end());
    // L = -sum coef log pi(a|s) - ent sum H, from log_probs and the log sigma parameters alone.
    auto entropy = [&] {
      double h = 0.0;
      for (float ls : log_std) h += nn::gaussian_entropy(ls);
      return h;
    };
    CHECK(mean_entropy == doctest::Approx(entropy()));
    auto loss = [&] {
      std::vector<float> lp(n);
      p.log_probs(rows, n, acts, lp);
      double l = 0.0;
      for (size_t r = 0; r < lp.size(); ++r) l -= coef[r] * lp[r] + ent * entropy();
      return l;
    };
    std::span<float> theta = p.params();
    int large = 0;
    for (size_t i = 0; i < theta.size(); ++i) {
      // eps 1e-3: at 1e-2 some ReLU inputs of this small net change sign. The
      // float log-probabilities (of order 1) leave about 5e-5 of rounding in
      // each difference, hence the absolute floor 0.02 x 5e-3.
      const double fd = central_difference(theta[i], 1e-3f, loss);
      CAPTURE(i);
      CHECK(g[i] == doctest::Approx(fd).epsilon(0.02).scale(5e-3));
      large += std::fabs(fd) > 1e-3;
    }
    CHECK(large > static_cast<int>(theta.size()) / 4);
    for (size_t j = 0; j < static_cast<size_t>(d); ++j)
      CHECK(g[g.size() - 1 - j] != 0.0f);  // each log sigma learns
  }
}

TEST_CASE("a diagonal Gaussian samples each component from its own mean and sigma") {
  auto made = small_gaussian(2);
  REQUIRE(made);
  rl::MlpPolicy& p = **made;
  CHECK(p.params().size() == static_cast<size_t>((2 * 4 + 4) + (4 * 2 + 2) + 2));
  std::span<float> log_std = p.params().last(2);
  CHECK(log_std[0] == -0.5f);
  CHECK(log_std[1] == -0.5f);
  log_std[0] = std::log(0.1f);
  log_std[1] = std::log(2.0f);
  const std::vector<float> obs = {0.3f, -0.7f};
  std::vector<float> mu;
  p.forward(obs, 1, mu);
  REQUIRE(mu.size() == 2);
  rl::ActionSample greedy;
  p.act(obs, 1, {}, {}, true, {&greedy, 1});
  CHECK(greedy.index == -1);
  CHECK(greedy.component(0) == mu[0]);
  CHECK(greedy.component(1) == mu[1]);
  Rng rng(11);
  const int m = 4000;
  double s[2] = {0, 0}, ss[2] = {0, 0};
  for (int t = 0; t < m; ++t) {
    rl::ActionSample a;
    p.act(obs, 1, {}, {&rng, 1}, false, {&a, 1});
    for (int j = 0; j < 2; ++j) {
      const double x = a.component(j) - mu[static_cast<size_t>(j)];
      s[j] += x;
      ss[j] += x * x;
    }
  }
  // Each component's sample mean within 4 standard errors of its mean, its deviation within 5 %.
  CHECK(std::fabs(s[0] / m) < 4 * 0.1 / std::sqrt(m));
  CHECK(std::fabs(s[1] / m) < 4 * 2.0 / std::sqrt(m));
  CHECK(std::sqrt(ss[0] / m) == doctest::Approx(0.1).epsilon(0.05));
  CHECK(std::sqrt(ss[1] / m) == doctest::Approx(2.0).epsilon(0.05));
  rl::MlpPolicySpec wide = p.spec();
  wide.action_size = rl::kMaxActionSize + 1;
  CHECK(wide.validate().message() == "gaussian policy action_size 5: expected 1..4");
  rl::MlpPolicySpec cat;
  cat.action_size = 2;
  CHECK(cat.validate().message().find("a categorical head acts through action_values") !=
        std::string::npos);
}

TEST_CASE("checkpoint round trip and clear errors on damaged files") {
  Rng rng(1);
  auto p = rl::MlpPolicy::make({}, rng);
  REQUIRE(p);
  rl::Checkpoint c;
  c.spec = (*p)->spec();
  c.params.assign((*p)->params().begin(), (*p)->params().end());
  c.has_adam = true;
  c.adam_t = 7;
  c.adam_m.assign(c.params.size(), 0.5f);
  c.adam_v.assign(c.params.size(), 0.25f);
  c.progress.episodes = 1234;
  c.progress.interval_return = -0.1 / 3.0;  // not exact in decimal: the JSON must round-trip it
  c.progress.interval_success = 2.5;
  c.progress.interval_updates = 3;
  c.value_params.assign(10, 0.125f);
  c.value_m.assign(10, 1.0f);
  c.value_v.assign(10, 2.0f);
  c.value_t = 3;
  const std::string path = temp_path("squawk_test_rl.ckpt");
  REQUIRE(rl::save_checkpoint(path, c).is_ok());
  auto back = rl::load_checkpoint(path);
  REQUIRE(back);
  CHECK(back->params == c.params);
  CHECK(back->adam_v == c.adam_v);
  CHECK(back->adam_t == 7);
  CHECK(back->progress.episodes == 1234);
  CHECK(back->progress.interval_return == c.progress.interval_return);
  CHECK(back->progress.interval_success == 2.5);
  CHECK(back->progress.interval_updates == 3);
  CHECK(back->value_params == c.value_params);
  CHECK(back->value_v == c.value_v);
  CHECK(back->value_t == 3);
  auto q = rl::policy_from_checkpoint(*back);
  REQUIRE(q);
  CHECK(std::vector<float>((*q)->params().begin(), (*q)->params().end()) == c.params);

  auto data = files::read(path);
  REQUIRE(data);
  REQUIRE(files::write_atomic(path, data->substr(0, data->size() - 10)).is_ok());
  auto cut = rl::load_checkpoint(path);
  REQUIRE_FALSE(cut);
  CHECK(cut.status().message().find("expected") != std::string::npos);
  // A header claiming more parameters than the file holds is refused before
  // anything is allocated (10^12 floats would be 4 TB).
  const size_t nl2 = data->find('\n', data->find('\n') + 1);
  nlohmann::json h = nlohmann::json::parse(data->substr(data->find('\n') + 1, nl2 - data->find('\n') - 1));
  for (const char* key : {"num_params", "num_value_params"}) {
    nlohmann::json big = h;
    big[key] = 1000000000000ULL;
    REQUIRE(files::write_atomic(path, data->substr(0, data->find('\n') + 1) + big.dump() + data->substr(nl2)).is_ok());
    auto huge = rl::load_checkpoint(path);
    REQUIRE_FALSE(huge);
    CHECK_MESSAGE(huge.status().message().find(std::string(key) + " = 1000000000000 but the file holds") !=
                      std::string::npos,
                  huge.status().message());
  }
  // Integers given as floats beyond any integer type are refused by name
  // (converting 1e300 to int is undefined behaviour).
  for (const char* key : {"obs_size", "num_params", "adam_t", "episodes"}) {
    nlohmann::json bad = h;
    bad[key] = 1e300;
    REQUIRE(files::write_atomic(path, data->substr(0, data->find('\n') + 1) + bad.dump() + data->substr(nl2)).is_ok());
    auto r = rl::load_checkpoint(path);
    REQUIRE_FALSE(r);
    CHECK_MESSAGE(r.status().message().find(std::string(key) + " = 1e+300: expected a whole number") != std::string::npos,
                  r.status().message());
  }
  REQUIRE(files::write_atomic(path, "not a checkpoint").is_ok());
  CHECK(rl::load_checkpoint(path).status().message().find("first line") != std::string::npos);
  std::remove(path.c_str());
  CHECK(rl::load_checkpoint(path).status().code() != Code::kOk);
}

TEST_CASE(
    "obs_mean / obs_std: the network reads the normalised observation; checkpoints keep them") {
  rl::MlpPolicySpec plain;
  plain.obs_size = 2;
  plain.hidden = {5};
  plain.head = "gaussian";
  plain.action_size = 2;
  rl::MlpPolicySpec normed = plain;
  normed.obs_mean = {1.0, -2.0};
  normed.obs_std = {0.5, 4.0};
  Rng r1(9), r2(9);
  auto a = rl::MlpPolicy::make(plain, r1);
  auto b = rl::MlpPolicy::make(normed, r2);
  REQUIRE(a);
  REQUIRE(b);
  const std::vector<float> obs = {1.5f, 2.0f, 0.0f, -6.0f};       // two rows
  const std::vector<float> by_hand = {1.0f, 1.0f, -2.0f, -1.0f};  // (obs - mean) / std
  std::vector<float> ya, yb;
  (*a)->forward(by_hand, 2, ya);
  (*b)->forward(obs, 2, yb);
  CHECK(ya == yb);
  // The gradient is the plain network's on the normalised rows (mean and std are not parameters).
  std::vector<rl::ActionSample> acts(2);
  acts[0].value = 0.3f;
  acts[0].more[0] = -0.2f;
  acts[1].value = -0.6f;
  acts[1].more[0] = 0.9f;
  const std::vector<float> coef = {0.7f, -0.4f};
  for (auto* p : {&**a, &**b}) std::fill(p->grads().begin(), p->grads().end(), 0.0f);
  (*a)->accumulate_gradient(by_hand, 2, acts, coef, 0.05f);
  (*b)->accumulate_gradient(obs, 2, acts, coef, 0.05f);
  CHECK(std::vector<float>((*a)->grads().begin(), (*a)->grads().end()) ==
        std::vector<float>((*b)->grads().begin(), (*b)->grads().end()));
  const std::string path = temp_path("squawk_test_rl_norm.ckpt");
  rl::Checkpoint c;
  c.spec = normed;
  c.params.assign((*b)->params().begin(), (*b)->params().end());
  REQUIRE(rl::save_checkpoint(path, c).is_ok());
  auto back = rl::load_checkpoint(path);
  REQUIRE(back);
  CHECK(back->spec.obs_mean == normed.obs_mean);
  CHECK(back->spec.obs_std == normed.obs_std);
  std::remove(path.c_str());
  rl::MlpPolicySpec bad = normed;
  bad.obs_std = {0.5};
  CHECK(bad.validate().message() ==
        "policy obs_mean / obs_std hold 2 / 1 numbers: expected obs_size = 2 each");
  bad.obs_std = {0.5, 0.0};
  CHECK(bad.validate().message().find("obs_std[1] = 0.000000") != std::string::npos);
}

TEST_CASE("a diagonal Gaussian checkpoint keeps its components; one without action_size has 1") {
  const std::string path = temp_path("squawk_test_rl_gauss.ckpt");
  for (const int d : {1, 2}) {
    CAPTURE(d);
    rl::MlpPolicySpec spec;
    spec.obs_size = 3;
    spec.hidden = {4};
    spec.head = "gaussian";
    spec.action_size = d;
    Rng rng(4);
    auto p = rl::MlpPolicy::make(spec, rng);
    REQUIRE(p);
    rl::Checkpoint c;
    c.spec = spec;
    c.params.assign((*p)->params().begin(), (*p)->params().end());
    REQUIRE(rl::save_checkpoint(path, c).is_ok());
    auto back = rl::load_checkpoint(path);
    REQUIRE(back);
    CHECK(back->spec.action_size == d);
    auto q = rl::policy_from_checkpoint(*back);
    REQUIRE(q);
    CHECK(std::vector<float>((*q)->params().begin(), (*q)->params().end()) == c.params);
    // Checkpoints written before the key existed are one-component heads.
    auto data = files::read(path);
    REQUIRE(data);
    const size_t nl1 = data->find('\n'), nl2 = data->find('\n', nl1 + 1);
    nlohmann::json h = nlohmann::json::parse(data->substr(nl1 + 1, nl2 - nl1 - 1));
    REQUIRE(h.erase("action_size") == 1);
    REQUIRE(
        files::write_atomic(path, data->substr(0, nl1 + 1) + h.dump() + data->substr(nl2)).is_ok());
    auto old = rl::load_checkpoint(path);
    REQUIRE(old);
    CHECK(old->spec.action_size == 1);
    if (d == 1) {
      CHECK(rl::policy_from_checkpoint(*old).is_ok());
    } else {
      auto wrong = rl::policy_from_checkpoint(*old);
      REQUIRE_FALSE(wrong);
      CHECK(wrong.status().message().find("its spec needs") != std::string::npos);
    }
  }
  std::remove(path.c_str());
}

TEST_CASE("training is reproducible and a resumed run continues exactly") {
  env::HorizontalCrConfig ec;
  rl::TrainConfig tc;
  tc.episodes_per_update = 8;
  tc.num_envs = 4;
  tc.seed = 9;
  auto train = [&](int first, int count, std::vector<float> params, rl::Checkpoint* adam_in,
                   rl::Checkpoint* adam_out) {
    Rng init(0);
    auto p = rl::MlpPolicy::make({}, init);
    REQUIRE(p);
    if (!params.empty()) std::copy(params.begin(), params.end(), (*p)->params().begin());
    auto v = env::VecEnv::make(ec, tc.num_envs);
    REQUIRE(v);
    rl::Trainer tr(**p, *v, tc, first);
    if (adam_in) {
      tr.adam().m() = adam_in->adam_m;
      tr.adam().v() = adam_in->adam_v;
      tr.adam().set_t(adam_in->adam_t);
      tr.value_params() = adam_in->value_params;
      tr.value_adam()->m() = adam_in->value_m;
      tr.value_adam()->v() = adam_in->value_v;
      tr.value_adam()->set_t(adam_in->value_t);
    }
    for (int i = 0; i < count; ++i) CHECK(tr.update().episodes == 8);
    if (adam_out) {
      adam_out->adam_m = tr.adam().m();
      adam_out->adam_v = tr.adam().v();
      adam_out->adam_t = tr.adam().t();
      adam_out->value_params = tr.value_params();
      adam_out->value_m = tr.value_adam()->m();
      adam_out->value_v = tr.value_adam()->v();
      adam_out->value_t = tr.value_adam()->t();
    }
    return std::vector<float>((*p)->params().begin(), (*p)->params().end());
  };
  const auto straight = train(0, 4, {}, nullptr, nullptr);
  CHECK(straight == train(0, 4, {}, nullptr, nullptr));
  rl::Checkpoint mid;
  const auto half = train(0, 2, {}, nullptr, &mid);
  CHECK(half != straight);
  CHECK(train(2, 2, half, &mid, nullptr) == straight);
}

namespace {

struct Trained {
  std::vector<float> params;  // the policy's parameters after training
  long long adam_steps = 0;   // [-] policy Adam steps taken
  int samples = 0;            // [-] agent steps in the batches
};

// `updates` updates of a fresh paper-sized MLP under tc.
Trained train_fresh(const rl::TrainConfig& tc, int updates) {
  env::HorizontalCrConfig ec;
  Rng init(0);
  auto p = rl::MlpPolicy::make({}, init);
  REQUIRE(p);
  auto v = env::VecEnv::make(ec, tc.num_envs);
  REQUIRE(v);
  rl::Trainer tr(**p, *v, tc, 0);
  Trained t;
  for (int i = 0; i < updates; ++i) {
    const rl::UpdateStats st = tr.update();
    CHECK(st.samples > 0);
    CHECK(st.entropy > 0.0);
    t.samples += st.samples;
  }
  t.params.assign((*p)->params().begin(), (*p)->params().end());
  t.adam_steps = tr.adam().t();
  return t;
}

std::vector<float> trained_params(const rl::TrainConfig& tc, int updates) { return train_fresh(tc, updates).params; }

}  // namespace

TEST_CASE("MLP log_probs are the log-softmax of the logits at the given actions") {
  Rng init(4);
  auto p = rl::MlpPolicy::make({}, init);
  REQUIRE(p);
  std::vector<float> obs(3 * 28);
  for (size_t i = 0; i < obs.size(); ++i) obs[i] = static_cast<float>(std::sin(0.37 * static_cast<double>(i)));
  std::vector<float> logits;
  (*p)->forward(obs, 3, logits);
  for (int a = 0; a < 5; ++a) {
    std::vector<rl::ActionSample> acts(3, rl::ActionSample{a, 0.0f});
    std::vector<float> lp(3);
    (*p)->log_probs(obs, 3, acts, lp);
    for (size_t r = 0; r < 3; ++r) {
      std::vector<float> ref(5);
      nn::log_softmax(std::span<const float>(logits).subspan(r * 5, 5), ref);
      CHECK(lp[r] == doctest::Approx(ref[static_cast<size_t>(a)]).epsilon(1e-6));
    }
  }
}

TEST_CASE("the clipped-ratio learner, GAE(lambda) and the entropy schedule") {
  rl::TrainConfig tc;
  tc.episodes_per_update = 8;
  tc.num_envs = 4;
  tc.seed = 5;
  const auto improved = trained_params(tc, 2);
  SUBCASE("ppo with one epoch is the improved estimator's step (ratio 1, nothing clipped)") {
    rl::TrainConfig c = tc;
    c.estimator = "ppo";
    c.epochs = 1;
    CHECK(trained_params(c, 2) == improved);
    c.epochs = 4;
    const auto four = trained_params(c, 2);
    CHECK(four != improved);
    CHECK(trained_params(c, 2) == four);
  }
  SUBCASE("ppo minibatches: epochs x parts Adam steps per batch, never more parts than samples") {
    rl::TrainConfig c = tc;
    c.estimator = "ppo";
    c.epochs = 2;
    const auto whole = trained_params(c, 2);
    c.minibatches = 3;
    const auto parts = trained_params(c, 2);
    CHECK(parts != whole);
    CHECK(trained_params(c, 2) == parts);  // the shuffle is the run's, not the clock's
    CHECK(train_fresh(c, 2).adam_steps == 2 * 2 * 3);
    c.minibatches = 1024;
    const Trained one = train_fresh(c, 1);
    REQUIRE(one.samples < 1024);
    CHECK(one.adam_steps == 2LL * one.samples);  // one sample per part
    c.minibatches = 100000;
    CHECK_FALSE(c.validate().is_ok());
    c.minibatches = 0;
    CHECK(c.validate().message().find("minibatches") != std::string::npos);
  }
  SUBCASE("lambda 1 is reward-to-go minus V; lambda < 1 changes the advantages") {
    rl::TrainConfig c = tc;
    c.lambda = 0.9;
    CHECK(trained_params(c, 2) != improved);
  }
  SUBCASE("an entropy schedule to the same value changes nothing; to another value it does") {
    rl::TrainConfig c = tc;
    c.entropy_final = c.entropy_coef;
    CHECK(trained_params(c, 2) == improved);
    c.entropy_final = 0.5;
    CHECK(trained_params(c, 2) != improved);
  }
  SUBCASE("vine: deterministic, its own step, and only for scoring discrete policies") {
    rl::TrainConfig c = tc;
    c.estimator = "vine";
    c.branch_fraction = 0.5;
    const auto vine = trained_params(c, 2);
    CHECK(vine != improved);
    CHECK(trained_params(c, 2) == vine);
    rl::ConstantPolicy fixed(28, 0.5f);
    CHECK(rl::check_learner(fixed, c).message().find("vine") != std::string::npos);
    rl::MlpPolicySpec gauss;
    gauss.head = "gaussian";
    Rng init(1);
    auto g = rl::MlpPolicy::make(gauss, init);
    REQUIRE(g);
    CHECK(rl::check_learner(**g, c).message().find("discrete") != std::string::npos);
    c.branch_fraction = 0.0;
    CHECK_FALSE(c.validate().is_ok());
  }
  SUBCASE("ppo needs a policy that scores its actions, and sane settings") {
    rl::TrainConfig c = tc;
    c.estimator = "ppo";
    rl::ConstantPolicy fixed(28, 0.5f);
    const Status st = rl::check_learner(fixed, c);
    CHECK_FALSE(st.is_ok());
    CHECK(st.message().find("ppo") != std::string::npos);
    c.clip = 0.0;
    CHECK_FALSE(c.validate().is_ok());
    c.clip = 0.2;
    c.lambda = 1.5;
    CHECK_FALSE(c.validate().is_ok());
    c.lambda = 0.95;
    c.entropy_final = -0.1;
    CHECK_FALSE(c.validate().is_ok());
  }
}

TEST_CASE("the action histogram counts every decision in the nearest of the five bins") {
  CHECK(rl::action_bin(-1.0) == 0);
  CHECK(rl::action_bin(-0.3) == 1);
  CHECK(rl::action_bin(0.1) == 2);
  CHECK(rl::action_bin(0.5) == 3);
  CHECK(rl::action_bin(7.0) == 4);
  env::HorizontalCrConfig ec;
  auto v = env::VecEnv::make(ec, 8);
  REQUIRE(v);
  rl::ConstantPolicy left(v->obs_size(), -0.5f);
  auto r = rl::evaluate(left, *v, {40, 1, false});
  REQUIRE(r);
  CHECK(r->decisions() > 0);
  CHECK(r->action_counts[1] == r->decisions());
  CHECK(r->most_frequent_share() == 1.0);
  CHECK(r->decisions() == std::llround(r->mean_decisions * 40));
  Rng init(2);
  auto p = rl::MlpPolicy::make({}, init);
  REQUIRE(p);
  auto m = rl::evaluate(**p, *v, {40, 1, false});
  REQUIRE(m);
  CHECK(m->most_frequent_share() < 1.0);  // an untrained MLP samples several actions
}

TEST_CASE("the turn-hold rule turns only while flying at the waypoint") {
  rl::ConstantPolicy rule(28, 0.5f, rl::ConstantPolicy::When::on_track);
  CHECK(rule.name() == "turn-hold:0.5");
  std::vector<float> obs(2 * 28, 0.0f);
  obs[5] = 1.0f;             // row 0: cos_drift = 1, on track
  obs[28 + 5] = 0.99f;       // row 1: about 8 deg off track
  std::vector<rl::ActionSample> out(2);
  Rng rng(1);
  rule.act(obs, 2, std::vector<int>{0, 1}, {&rng, 1}, false, out);
  CHECK(out[0].value == 0.5f);
  CHECK(out[1].value == 0.0f);
  // In the paper setup it turns once per conflict and then holds: far more
  // holds than turns, and it still clears most conflicts.
  env::HorizontalCrConfig ec = test::paper_eval_config(false);
  auto v = env::VecEnv::make(ec, 8);
  REQUIRE(v);
  auto r = rl::evaluate(rule, *v, {100, 2024, false});
  REQUIRE(r);
  CHECK(r->action_counts[3] > 0);
  CHECK(r->action_counts[2] > 3 * r->action_counts[3]);
  CHECK(r->action_counts[0] + r->action_counts[1] + r->action_counts[4] == 0);
  CHECK(r->success_rate > 0.85);
}

TEST_CASE("evaluation is deterministic for a seed and rejects a mismatched policy") {
  env::HorizontalCrConfig ec = test::paper_eval_config(false);
  auto v = env::VecEnv::make(ec, 16);
  REQUIRE(v);
  Rng init(5);
  auto p = rl::MlpPolicy::make({}, init);
  REQUIRE(p);
  auto a = rl::evaluate(**p, *v, {100, 3, false});
  auto b = rl::evaluate(**p, *v, {100, 3, false});
  REQUIRE(a);
  REQUIRE(b);
  CHECK(a->mean_reward == b->mean_reward);
  CHECK(a->std_reward == b->std_reward);
  CHECK(a->success_rate == b->success_rate);
  CHECK(a->episodes == 100);
  rl::MlpPolicySpec small;
  small.obs_size = 13;
  auto q = rl::MlpPolicy::make(small, init);
  REQUIRE(q);
  CHECK_FALSE(rl::evaluate(**q, *v, {10, 3, false}));
}

TEST_CASE("the shipped checkpoints resolve conflicts on the paper's evaluation settings") {
  const std::string path = std::string(SQUAWK_TEST_DATA) + "/../../models/horizontal_cr_mlp.ckpt";
  auto c = rl::load_checkpoint(path);
  REQUIRE_MESSAGE(c, c.status().message());
  auto p = rl::policy_from_checkpoint(*c);
  REQUIRE(p);
  CHECK((*p)->params().size() == 12581);
  env::HorizontalCrConfig ec =
      test::paper_eval_config(true);  // scenarios/horizontal_cr.lua, eval table
  auto v = env::VecEnv::make(ec, 32);
  REQUIRE(v);
  auto trained = rl::evaluate(**p, *v, {300, 2024, false});
  Rng init(2024);
  auto fresh = rl::MlpPolicy::make({}, init);
  REQUIRE(fresh);
  auto untrained = rl::evaluate(**fresh, *v, {300, 2024, false});
  REQUIRE(trained);
  REQUIRE(untrained);
  MESSAGE("shipped " << trained->success_rate << ", untrained " << untrained->success_rate);
  CHECK(trained->success_rate >= 0.93);
  CHECK(trained->success_rate > untrained->success_rate + 0.15);
  CHECK(trained->mean_reward > untrained->mean_reward);

  // The mirror-symmetric MLP (README: 97.7 % on these 1000 episodes with eval's sampling): same size, above the plain one.
  auto m = rl::load_checkpoint(std::string(SQUAWK_TEST_DATA) + "/../../models/horizontal_cr_mlp_mirror.ckpt");
  REQUIRE_MESSAGE(m, m.status().message());
  CHECK_FALSE(m->spec.mirror.empty());
  auto pm = rl::policy_from_checkpoint(*m);
  REQUIRE(pm);
  CHECK((*pm)->params().size() == 12581);
  auto plain = rl::evaluate(**p, *v, {1000, 2024, false});
  auto mirrored = rl::evaluate(**pm, *v, {1000, 2024, false});
  REQUIRE(plain);
  REQUIRE(mirrored);
  MESSAGE("1000 episodes: plain " << plain->success_rate << ", mirror-symmetric " << mirrored->success_rate);
  CHECK(mirrored->success_rate >= 0.97);
  CHECK(mirrored->success_rate > plain->success_rate);
  CHECK(mirrored->mean_reward > plain->mean_reward);
}
