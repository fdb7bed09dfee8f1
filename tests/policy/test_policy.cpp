// GPT-2 prompt policy: template rendering, prefix cache, batching, gradients,
// imitation, checkpoints, and `squawk train --policy gpt2 --resume` after a kill.
#include <doctest/doctest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "../finite_difference.h"
#include "core/files.h"
#include "env/observation.h"
#include "env/vec_env.h"
#include "gpt2/model.h"
#include "nn/categorical.h"
#include "nn/gemm.h"
#include "rl/imitation.h"
#include "rl/mirror.h"
#include "rl/prompt_checkpoint.h"
#include "rl/prompt_policy.h"
#include "rl/vpg.h"
#include "script/prompt_renderer.h"

using namespace squawk;

namespace {

const std::string kRoot = std::string(SQUAWK_TEST_DATA) + "/../..";

env::Observation sample_obs(int salt) {
  env::Observation o;
  for (int i = 0; i < 5; ++i) {
    const double a = 0.37 * (i + 1) + 0.11 * salt;
    o.intruder_distance.push_back(0.1 + 0.05 * i + 0.01 * salt);
    o.cos_difference_pos.push_back(std::cos(a));
    o.sin_difference_pos.push_back(std::sin(a));
    o.x_difference_speed.push_back(-0.3 + 0.1 * i);
    o.y_difference_speed.push_back(0.2 - 0.07 * i * salt);
  }
  o.waypoint_distance = 0.8 - 0.1 * salt;
  o.cos_drift = std::cos(0.2 * salt);
  o.sin_drift = std::sin(0.2 * salt);
  return o;
}

std::vector<float> flat_rows(int n) {
  std::vector<float> flat(static_cast<size_t>(n) * 28);
  for (int r = 0; r < n; ++r) env::flatten(sample_obs(r), std::span<float>(flat).subspan(static_cast<size_t>(r) * 28, 28));
  return flat;
}

// A short template in C++ so the byte-level tiny model fits it in 256 positions.
const std::string kPrefix = "obs:";
Result<std::string> short_render(const env::Observation& o) {
  std::string s = kPrefix;
  char buf[32];
  auto add = [&](double v) {
    std::snprintf(buf, sizeof buf, " %.1f", v);
    s += buf;
  };
  for (double v : o.intruder_distance) add(v);
  for (double v : o.cos_difference_pos) add(v);
  for (double v : o.sin_difference_pos) add(v);
  add(o.cos_drift);
  add(o.sin_drift);
  return s + "\nact:";
}

std::unique_ptr<rl::PromptPolicy> tiny_policy(const std::string& head, int blocks, uint64_t seed = 7,
                                              bool embeddings = false, bool mirror = false) {
  gpt2::Config cfg = gpt2::Config::tiny();
  auto extras = head == "action" ? rl::PromptPolicy::head_extras(cfg.n_embd, 5) : std::vector<gpt2::TensorSpec>{};
  auto m = gpt2::Model::create(cfg, extras);
  REQUIRE(m.is_ok());
  Rng rng(seed);
  m->init_random(rng, 0.2f);
  rl::PromptPolicySpec spec;
  spec.head = head;
  spec.trainable_blocks = blocks;
  spec.train_embeddings = embeddings;
  if (mirror) spec.mirror = env::observation_mirror(5, 1.0);
  auto p = rl::PromptPolicy::make(std::move(*m), gpt2::Tokenizer::bytes_only(), kPrefix, short_render, spec);
  REQUIRE(p.is_ok());
  Rng head_rng(seed + 1);
  (*p)->init_head(head_rng);
  return std::move(*p);
}

// L = -sum_r coef[r] log pi(a_r|s_r) - ent sum_r H(pi(.|s_r)) from the inference path.
double policy_loss(rl::PromptPolicy& p, const std::vector<float>& obs, int n, const std::vector<int>& a,
                   const std::vector<float>& coef, float ent) {
  std::vector<float> z, logp(5);
  REQUIRE(p.logits(obs, n, z).is_ok());
  double loss = 0.0;
  for (int r = 0; r < n; ++r) {
    nn::log_softmax(std::span<const float>(z).subspan(static_cast<size_t>(r) * 5, 5), logp);
    loss -= coef[static_cast<size_t>(r)] * logp[static_cast<size_t>(a[static_cast<size_t>(r)])];
    loss -= ent * nn::categorical_entropy(logp);
  }
  return loss;
}

}  // namespace

TEST_CASE("prompts/observation.lua renders the paper's template") {
  auto r = script::PromptRenderer::load(kRoot + "/prompts/observation.lua", {});
  REQUIRE_MESSAGE(r.is_ok(), r.status().message());
  env::Observation o = sample_obs(1);
  o.sin_drift = -0.001;
  auto text = (*r)->render(o);
  REQUIRE(text.is_ok());
  CHECK(text->rfind((*r)->prefix(), 0) == 0);
  CHECK(text->rfind("You are a decision support system that aids in avoiding collisions between the ownship "
                    "and intruders as the ownship navigates to reach a waypoint.",
                    0) == 0);
  // The paper's request first, then the observation, which ends the prompt.
  const char* lines[] = {"Please provide a decision on whether to turn left or right or remain unchanged to avoid "
                         "a collision with the intruder aircraft.",
                         "The decision should be one of the following: [-1 for left, -0.5 for slightly left, 0 for "
                         "unchanged, 0.5 for slightly right, 1 for right].",
                         "Only provide the decision as output. Here is the observation from the environment:",
                         "1. The intruder distances are [+0.11, +0.16, +0.21, +0.26, +0.31].",
                         "2. The cosines of the bearing angle differences are [",
                         "3. The sines of the bearing angle differences are [",
                         "4. The differences in the x-component of the speed are [-0.30, -0.20, -0.10, +0.00, +0.10].",
                         "5. The differences in the y-component of the speed are [",
                         "6. The distances to each waypoint are [+0.70].",
                         "7. The cosines of the drift angles are [+0.98].",
                         "8. The sines of the drift angles are [0.00].\n"};
  size_t at = 0;
  for (const char* line : lines) {
    const size_t pos = text->find(line, at);
    CHECK_MESSAGE(pos != std::string::npos, line);
    if (pos != std::string::npos) at = pos;
  }
  CHECK(text->size() == at + std::string_view(lines[std::size(lines) - 1]).size());
  auto bad = script::PromptRenderer::load(kRoot + "/prompts/no_such_template.lua", {});
  CHECK_FALSE(bad.is_ok());
}

TEST_CASE("prefix-cached logits equal an uncached forward of the whole prompt") {
  auto p = tiny_policy("action", 1);
  const std::vector<float> obs = flat_rows(3);
  std::vector<float> z;
  REQUIRE(p->logits(obs, 3, z).is_ok());
  for (int r = 0; r < 3; ++r) {
    auto suffix = p->suffix_tokens(std::span<const float>(obs).subspan(static_cast<size_t>(r) * 28, 28));
    REQUIRE(suffix.is_ok());
    std::vector<int> all = p->prefix_tokens();
    all.insert(all.end(), suffix->begin(), suffix->end());
    std::vector<float> hidden;
    REQUIRE(p->model().forward_last(gpt2::PrefixCache{}, {all}, hidden).is_ok());
    const auto w = p->model().tensor("policy.head.weight");
    const auto b = p->model().tensor("policy.head.bias");
    for (int k = 0; k < 5; ++k) {
      double acc = b[static_cast<size_t>(k)];
      for (size_t c = 0; c < hidden.size(); ++c) acc += hidden[c] * w[c * 5 + static_cast<size_t>(k)];
      CHECK(z[static_cast<size_t>(r) * 5 + static_cast<size_t>(k)] == doctest::Approx(acc).epsilon(1e-4));
    }
  }
}

TEST_CASE("batched decisions equal one-at-a-time decisions") {
  for (const char* head : {"action", "lm"}) {
    auto p = tiny_policy(head, 1);
    const std::vector<float> obs = flat_rows(5);
    std::vector<float> batched;
    REQUIRE(p->logits(obs, 5, batched).is_ok());
    p->set_chunk_rows(1);
    for (int r = 0; r < 5; ++r) {
      std::vector<float> one;
      REQUIRE(p->logits(std::span<const float>(obs).subspan(static_cast<size_t>(r) * 28, 28), 1, one).is_ok());
      for (int k = 0; k < 5; ++k)
        CHECK(one[static_cast<size_t>(k)] ==
              doctest::Approx(batched[static_cast<size_t>(r) * 5 + static_cast<size_t>(k)]).epsilon(1e-4));
    }
    std::vector<float> spread;
    for (float v : batched) spread.push_back(v - batched[0]);
    CHECK(std::abs(spread[1]) + std::abs(spread[6]) > 1e-4);  // rows and actions differ
  }
}

TEST_CASE("log_probs are the log-softmax of the logits at the given actions (both heads)") {
  for (const char* head : {"action", "lm"}) {
    CAPTURE(head);
    auto p = tiny_policy(head, 1);
    REQUIRE(p->has_log_probs());
    const std::vector<float> obs = flat_rows(3);
    std::vector<float> z;
    REQUIRE(p->logits(obs, 3, z).is_ok());
    const std::vector<rl::ActionSample> acts = {{4, 1.0f}, {0, -1.0f}, {2, 0.0f}};
    std::vector<float> lp(3);
    p->log_probs(obs, 3, acts, lp);
    REQUIRE(p->error().is_ok());
    for (size_t r = 0; r < 3; ++r) {
      std::vector<float> ref(5);
      nn::log_softmax(std::span<const float>(z).subspan(r * 5, 5), ref);
      CHECK(lp[r] == doctest::Approx(ref[static_cast<size_t>(acts[r].index)]).epsilon(1e-6));
    }
  }
}

TEST_CASE("the clipped-ratio learner trains the prompt policy: one epoch is the improved step") {
  auto run = [](const std::string& estimator, int epochs) {
    auto p = tiny_policy("action", 1);
    rl::TrainConfig tc;
    tc.estimator = estimator;
    tc.epochs = epochs;
    tc.episodes_per_update = 2;
    tc.num_envs = 2;
    tc.seed = 3;
    REQUIRE(rl::check_learner(*p, tc).is_ok());
    auto v = env::VecEnv::make(env::HorizontalCrConfig{}, tc.num_envs);
    REQUIRE(v);
    rl::Trainer tr(*p, *v, tc, 0);
    CHECK(tr.update().samples > 0);
    REQUIRE(p->error().is_ok());
    return std::vector<float>(p->params().begin(), p->params().end());
  };
  const auto improved = run("improved", 1);
  CHECK(run("ppo", 1) == improved);
  const auto three = run("ppo", 3);
  CHECK(three != improved);
  CHECK(run("ppo", 3) == three);
}

TEST_CASE("three updates of the tiny prompt policy with bf16 products stay near fp32's") {
  // The same seeds at each precision; returns the parameters before and after.
  auto run = [](nn::Precision prec) {
    nn::set_gemm_precision(prec);
    auto p = tiny_policy("action", 2, 7, true);
    const std::vector<float> before(p->params().begin(), p->params().end());
    rl::TrainConfig tc;
    tc.estimator = "ppo";
    tc.epochs = 2;
    tc.episodes_per_update = 2;
    tc.num_envs = 2;
    tc.seed = 3;
    auto v = env::VecEnv::make(env::HorizontalCrConfig{}, tc.num_envs);
    REQUIRE(v);
    rl::Trainer tr(*p, *v, tc, 0);
    for (int u = 0; u < 3; ++u) CHECK(tr.update().samples > 0);
    nn::set_gemm_precision(nn::Precision::kFp32);
    REQUIRE(p->error().is_ok());
    return std::pair{before, std::vector<float>(p->params().begin(), p->params().end())};
  };
  const auto [p0, p32] = run(nn::Precision::kFp32);
  const auto [p0b, p16] = run(nn::Precision::kBf16);
  REQUIRE(p0 == p0b);
  // The bf16 run's step against fp32's: |p16 - p32| / |p32 - p0| and the cosine of the two steps.
  double diff = 0.0, step = 0.0, step16 = 0.0, dot = 0.0;
  for (size_t i = 0; i < p0.size(); ++i) {
    const double a = p32[i] - p0[i], b = p16[i] - p0[i];
    diff += (b - a) * (b - a);
    step += a * a;
    step16 += b * b;
    dot += a * b;
  }
  const double rel = std::sqrt(diff / step), cosine = dot / std::sqrt(step * step16);
  MESSAGE("3 updates, " << p0.size() << " parameters: |bf16 - fp32| / |fp32 step| = " << rel
                        << ", cosine of the steps " << cosine);
  CHECK(rel > 1e-6);  // the bf16 products ran
  CHECK(rel < 0.1);
  CHECK(cosine > 0.99);
}

TEST_CASE("policy-loss gradient matches finite differences (both heads, tail of 2 blocks, embeddings)") {
  for (const char* head : {"action", "lm", "action+embeddings", "lm+mirror"}) {
    CAPTURE(head);
    const bool emb = std::string(head) == "action+embeddings", mirror = std::string(head) == "lm+mirror";
    auto p = tiny_policy(emb ? "action" : mirror ? "lm" : head, 2, 7, emb, mirror);
    const int n = 3;
    const std::vector<float> obs = flat_rows(n);
    const std::vector<int> a = {0, 3, 4};
    const std::vector<float> coef = {0.7f, -1.3f, 0.4f};
    const float ent = 0.2f;
    std::vector<rl::ActionSample> acts;
    for (int x : a) acts.push_back({x, 0.0f});
    std::fill(p->grads().begin(), p->grads().end(), 0.0f);
    p->accumulate_gradient(obs, n, acts, coef, ent);
    REQUIRE(p->error().is_ok());
    const std::vector<float> g(p->grads().begin(), p->grads().end());
    std::span<float> theta = p->params();
    // Indices spread over the tail: first block's weights, the last block, ln_f, the head.
    const size_t sz = theta.size();
    int checked = 0, large = 0;
    std::vector<size_t> at = {size_t{5}, sz / 7, sz / 3, sz / 2 + 11, sz - 400, sz - 130, sz - 70, sz - 3};
    if (emb) {
      // wte rows of the digits the prompts contain, wpe rows of the suffix.
      const auto& cfg = p->model().config();
      const auto C = static_cast<size_t>(cfg.n_embd);
      auto ids = p->tokenizer().encode("0.5");
      REQUIRE(ids.is_ok());
      const size_t wpe = static_cast<size_t>(cfg.vocab_size) * C;
      at = {static_cast<size_t>((*ids)[0]) * C + 3, static_cast<size_t>((*ids)[1]) * C + 17,
            static_cast<size_t>((*ids)[2]) * C + 40, wpe + p->prefix_tokens().size() * C + 1,
            wpe + (p->prefix_tokens().size() + 6) * C + 9, wpe + 2 * C + 5, sz - 130, sz - 3};
    }
    for (size_t i : at) {
      const double fd = central_difference(theta[i], 1e-2f, [&] {
        p->invalidate_cache();
        return policy_loss(*p, obs, n, a, coef, ent);
      });
      p->invalidate_cache();
      CAPTURE(i);
      CHECK(g[i] == doctest::Approx(fd).epsilon(0.03).scale(1e-3));
      ++checked;
      if (std::abs(fd) > 1e-3) ++large;
    }
    CHECK(checked == 8);
    CHECK(large >= 4);
  }
}

TEST_CASE("a mirror-symmetric prompt policy reads the mirror image's prompt and turns the mirror way") {
  const int n = 3;
  const std::vector<float> rows = flat_rows(n);
  std::vector<float> both;
  rl::mirror_rows(env::observation_mirror(5, 1.0), rows, n, both);
  for (const char* head : {"action", "lm"})
    for (bool mirror : {true, false}) {
      CAPTURE(head);
      CAPTURE(mirror);
      auto p = tiny_policy(head, 2, 7, false, mirror);
      std::vector<float> z;  // [2n, 5]: the rows, then their images
      REQUIRE(p->logits(both, 2 * n, z).is_ok());
      double worst = 0.0;  // largest |z(o)[a] - z(M o)[4 - a]|
      for (size_t i = 0; i < static_cast<size_t>(n) * 5; ++i)
        worst = std::max(worst, std::fabs(static_cast<double>(z[i]) - z[n * 5 + i - i % 5 + 4 - i % 5]));
      CHECK((mirror ? worst < 1e-4 : worst > 1e-3));
    }
}

namespace {
// A teacher with the paper's five classes that always holds its heading (class 2).
class HoldTeacher : public rl::Policy {
 public:
  explicit HoldTeacher(bool discrete) : values_(discrete ? std::vector<double>{-1, -0.5, 0, 0.5, 1} : std::vector<double>{}) {}
  std::string name() const override { return "hold"; }
  int obs_size() const override { return 28; }
  void act(std::span<const float>, int n, std::span<const int>, std::span<Rng>, bool, std::span<rl::ActionSample> out) override {
    for (int r = 0; r < n; ++r) out[static_cast<size_t>(r)] = {values_.empty() ? -1 : 2, 0.0f};
  }
  std::span<const double> action_values() const override { return values_; }

 private:
  std::vector<double> values_;
};

int greedy_holds(rl::PromptPolicy& p, const std::vector<float>& rows, int n) {
  std::vector<rl::ActionSample> a(static_cast<size_t>(n));
  const std::vector<int> slots(static_cast<size_t>(n), 0);
  Rng rng(1);
  p.act(rows, n, slots, {&rng, 1}, true, a);
  return static_cast<int>(std::count_if(a.begin(), a.end(), [](const rl::ActionSample& s) { return s.index == 2; }));
}
}  // namespace

TEST_CASE("imitation clones the teacher's greedy class into the prompt policy, round after round") {
  auto student = tiny_policy("action", 2);
  const int n = 16;
  const std::vector<float> rows = flat_rows(n);
  REQUIRE(greedy_holds(*student, rows, n) < n);  // not already the teacher
  HoldTeacher teacher(true);
  auto envs = env::VecEnv::make(env::HorizontalCrConfig{}, 2);
  REQUIRE(envs);
  rl::ImitationConfig c{.episodes = 2, .rounds = 2, .epochs = 3, .batch = 8, .lr = 3e-3f, .holdout = 1};
  std::vector<rl::ImitationEpoch> seen;
  REQUIRE(rl::imitate(*student, teacher, *envs, c, [&](const rl::ImitationEpoch& e) {
            seen.push_back(e);
            return Status::ok();
          }).is_ok());
  REQUIRE(seen.size() == 6);
  CHECK(seen.front().teacher_flew);
  CHECK_FALSE(seen.back().teacher_flew);
  CHECK(seen.back().decisions > seen.front().decisions);
  CHECK(seen.back().agreement == 1.0);
  CHECK(greedy_holds(*student, rows, n) == n);

  HoldTeacher continuous(false);
  Status st = rl::imitate(*student, continuous, *envs, c, [](const rl::ImitationEpoch&) { return Status::ok(); });
  CHECK(st.message().find("the teacher hold has a continuous action") != std::string::npos);
  CHECK(st.message().find("(expected the same kind)") != std::string::npos);
  st = rl::imitate(*student, teacher, *envs, c, [](const rl::ImitationEpoch&) { return Status::io_error("disk full"); });
  CHECK(st.message() == "disk full");
}

TEST_CASE("gpt2 policy checkpoints round-trip and reject damaged files") {
  auto p = tiny_policy("action", 1);
  rl::PromptCheckpoint c;
  c.source = "tiny";
  c.model_seed = 7;
  c.config_json = "{}";
  c.spec = p->spec();
  c.spec.train_embeddings = true;
  c.spec.mirror = env::observation_mirror(5, 1.0);
  c.vocab_json = p->tokenizer().vocab_json();
  c.merges_txt = p->tokenizer().merges_txt();
  c.params.assign(p->params().begin(), p->params().end());
  c.has_adam = true;
  c.adam_t = 3;
  c.adam_m.assign(c.params.size(), 0.5f);
  c.adam_v.assign(c.params.size(), 0.25f);
  c.value_params = {1.0f, -2.0f, 3.0f};
  c.value_m = {0.1f, 0.2f, 0.3f};
  c.value_v = {0.4f, 0.5f, 0.6f};
  c.value_t = 5;
  c.progress.episodes = 96;
  c.progress.updates = 3;
  const std::string path = "/tmp/squawk_test_policy.ckpt";
  REQUIRE(rl::save_prompt_checkpoint(path, c).is_ok());
  auto back = rl::load_prompt_checkpoint(path);
  REQUIRE(back.is_ok());
  CHECK(back->params == c.params);
  CHECK(back->adam_v == c.adam_v);
  // The value baseline travels with it, so --resume continues exactly.
  CHECK(back->value_params == c.value_params);
  CHECK(back->value_m == c.value_m);
  CHECK(back->value_v == c.value_v);
  CHECK(back->value_t == 5);
  CHECK(back->progress.episodes == 96);
  CHECK(back->spec.trainable_blocks == 1);
  CHECK(back->spec.train_embeddings);
  CHECK(back->spec.mirror.offset == c.spec.mirror.offset);
  CHECK(back->vocab_json == c.vocab_json);
  auto data = files::read(path);
  REQUIRE(data.is_ok());
  REQUIRE(files::write_atomic(path, data->substr(0, data->size() - 4)).is_ok());
  auto cut = rl::load_prompt_checkpoint(path);
  REQUIRE_FALSE(cut.is_ok());
  CHECK(cut.status().message().find("bytes of tensors") != std::string::npos);
  std::remove(path.c_str());
}

TEST_CASE("squawk train --policy gpt2 --resume continues after a kill") {
  if (!files::exists(SQUAWK_BINARY)) {
    MESSAGE("skipped: " << SQUAWK_BINARY << " is not built");
    return;
  }
  const std::string dir = "/tmp/squawk_test_policy_resume";
  REQUIRE(std::system(("rm -rf " + dir).c_str()) == 0);
  const std::string ckpt = dir + "/checkpoint.ckpt";
  const std::string base = std::string(SQUAWK_BINARY) + " train " + kRoot +
                           "/scenarios/horizontal_cr.lua --policy gpt2 --model tiny --out " + dir +
                           " --envs 4 --episodes-per-update 4 --eval-every 0 --eval-episodes 4 --quiet";
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", ("exec " + base + " --episodes 400 > /dev/null 2>&1").c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  // Kill it as soon as the first checkpoint exists (mid-run: 400 episodes take far longer).
  long long first = 0;
  int status = 0;
  bool exited = false;
  for (int i = 0; i < 1200 && first == 0 && !exited; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (auto c = rl::load_prompt_checkpoint(ckpt); c.is_ok()) first = c->progress.episodes;
    exited = waitpid(pid, &status, WNOHANG) == pid;
  }
  if (!exited) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
  }
  REQUIRE_MESSAGE(first > 0, "no checkpoint from: " << base);
  auto killed = rl::load_prompt_checkpoint(ckpt);
  REQUIRE(killed.is_ok());
  const long long at_kill = killed->progress.episodes;
  CHECK(at_kill < 400);
  CHECK(killed->progress.updates == at_kill / 4);
  const long long target = at_kill + 8;
  // --resume takes the run's flags (run.json); --stop-at ends it 8 episodes on.
  REQUIRE(std::system((base + " --episodes 400 --resume --stop-at " + std::to_string(target) + " > /dev/null 2>&1").c_str()) == 0);
  auto done = rl::load_prompt_checkpoint(ckpt);
  REQUIRE(done.is_ok());
  CHECK(done->progress.episodes == target);
  CHECK(done->progress.updates == target / 4);
  CHECK(done->adam_t == killed->adam_t + 2);
  CHECK(done->params != killed->params);
  auto log = files::read(dir + "/log.csv");
  REQUIRE(log.is_ok());
  CHECK(log->find(std::to_string(target) + ",") != std::string::npos);
}
