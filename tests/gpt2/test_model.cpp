// GPT-2 model: forward against an independent numpy implementation, KV cache
// against the full forward, tail backward and the read-out loss against finite
// differences.
#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../finite_difference.h"
#include "core/rng.h"
#include "gpt2/checkpoint.h"
#include "gpt2/model.h"
#include "gpt2/readout.h"
#include "nn/adam.h"
#include "nn/gemm.h"

using namespace squawk;
using namespace squawk::gpt2;

namespace {

// A model whose every parameter is random (LayerNorm weights around 1), so that
// every term of the forward pass matters.
Model random_model(const Config& cfg, uint64_t seed, const std::vector<TensorSpec>& extras = {}) {
  auto m = Model::create(cfg, extras);
  REQUIRE(m.is_ok());
  Rng rng(seed);
  for (const TensorSpec& t : m->layout().tensors()) {
    const bool ln = t.name.find("ln_") != std::string::npos && t.name.find(".weight") != std::string::npos;
    for (float& v : m->tensor(t.name)) v = static_cast<float>((ln ? 1.0 : 0.0) + rng.normal(0.0, 0.2));
  }
  return std::move(m).value();
}

std::string temp_dir(const std::string& tag) {
  auto p = std::filesystem::temp_directory_path() /
           ("squawk_gpt2_" + tag + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(p);
  return p.string();
}

std::string run_capture(const std::string& cmd) {
  std::string out;
  FILE* f = ::popen(cmd.c_str(), "r");
  if (!f) return out;
  char buf[65536];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) out.append(buf, n);
  ::pclose(f);
  return out;
}

bool python_has_numpy() {
  return std::system("/usr/bin/python3 -c 'import numpy' >/dev/null 2>&1") == 0;
}

float max_abs_diff(const std::vector<float>& a, const std::vector<float>& b) {
  REQUIRE(a.size() == b.size());
  float m = 0.0f;
  for (size_t i = 0; i < a.size(); ++i) m = std::max(m, std::fabs(a[i] - b[i]));
  return m;
}

const Config kSmall{3, 4, 32, 48, 61, 1e-5f};

// Runs the GPT-2 engine's products at p until the end of the scope.
class PrecisionScope {
 public:
  explicit PrecisionScope(nn::Precision p) { nn::set_gemm_precision(p); }
  ~PrecisionScope() { nn::set_gemm_precision(nn::Precision::kFp32); }
  PrecisionScope(const PrecisionScope&) = delete;
  PrecisionScope& operator=(const PrecisionScope&) = delete;
};

// Largest |x| of a vector, the scale errors are read against.
float max_abs(const std::vector<float>& v) {
  float m = 0.0f;
  for (float x : v) m = std::max(m, std::fabs(x));
  return m;
}

}  // namespace

TEST_CASE("forward logits equal the independent numpy GPT-2") {
  if (!python_has_numpy()) {
    MESSAGE("skipped: /usr/bin/python3 lacks numpy");
    return;
  }
  const Config cfg{2, 4, 64, 64, 257, 1e-5f};
  Model model = random_model(cfg, 7);
  const std::string dir = temp_dir("numpy");
  REQUIRE(save_model(dir, model).is_ok());
  const std::vector<int> tokens = {256, 72, 101, 108, 108, 111, 32, 75, 76, 77, 0, 255, 3, 200, 17, 9};
  std::string arg;
  for (int t : tokens) arg.append(arg.empty() ? "" : ",").append(std::to_string(t));
  const std::string out = run_capture("/usr/bin/python3 " SQUAWK_SOURCE_DIR
                                      "/tests/gpt2/numpy_ref.py " + dir + " " + arg);
  const auto j = nlohmann::json::parse(out, nullptr, false);
  REQUIRE_MESSAGE(!j.is_discarded(), "numpy_ref.py printed: " << out.substr(0, 300));
  std::vector<float> want;
  for (const auto& row : j["logits"])
    for (const auto& v : row) want.push_back(v.get<float>());
  auto loaded = load_model(dir);
  REQUIRE(loaded.is_ok());
  std::vector<float> got, got16;
  REQUIRE(loaded->logits_all(tokens, got).is_ok());
  const float diff = max_abs_diff(got, want);
  MESSAGE("max |squawk - numpy| over " << got.size() << " logits (max |logit| " << max_abs(want) << "): fp32 " << diff);
  CHECK(diff < 1e-4f);
  {
    const PrecisionScope bf16(nn::Precision::kBf16);
    REQUIRE(loaded->logits_all(tokens, got16).is_ok());
  }
  const float diff16 = max_abs_diff(got16, want);
  MESSAGE("bf16 products: " << diff16);
  // This model's weights (std 0.2, LayerNorm gains around 1) make logits and
  // attention far hotter than GPT-2's; bf16's 8-bit mantissa then costs ~1 %.
  CHECK(diff16 < 2e-2f * max_abs(want));
  CHECK(diff16 > 1e-4f);  // the bf16 path ran
  std::filesystem::remove_all(dir);
}

TEST_CASE("KV-cached forward equals the full forward") {
  Model model = random_model(kSmall, 11);
  const std::vector<int> prefix = {5, 9, 2, 44, 60, 1, 7};
  const std::vector<std::vector<int>> suffixes = {{3, 4, 5}, {8}, {10, 11, 12, 13, 14}};
  PrefixCache cache;
  REQUIRE(model.extend(cache, prefix).is_ok());
  CHECK(cache.len == 7);
  std::vector<float> cached, full, one;
  REQUIRE(model.forward_last(cache, suffixes, cached).is_ok());
  std::vector<std::vector<int>> whole;
  for (const auto& s : suffixes) {
    whole.push_back(prefix);
    whole.back().insert(whole.back().end(), s.begin(), s.end());
  }
  REQUIRE(model.forward_last({}, whole, full).is_ok());
  CHECK(max_abs_diff(cached, full) < 1e-5f);

  SUBCASE("token-by-token extension matches too") {
    PrefixCache inc;
    std::vector<float> h;
    for (int t : whole[2]) REQUIRE(model.extend(inc, std::vector<int>{t}, &h).is_ok());
    std::vector<float> want(full.begin() + 2 * kSmall.n_embd, full.end());
    CHECK(max_abs_diff(h, want) < 1e-5f);
  }
  SUBCASE("head logits equal the LM logits at the last position") {
    std::vector<float> all, picked;
    REQUIRE(model.logits_all(whole[0], all).is_ok());
    const std::vector<int> ids = {0, 17, 60};
    REQUIRE(model.head_logits(std::span<const float>(full.data(), kSmall.n_embd), ids, picked).is_ok());
    const size_t last = (whole[0].size() - 1) * kSmall.vocab_size;
    for (size_t j = 0; j < ids.size(); ++j) CHECK(picked[j] == doctest::Approx(all[last + ids[j]]).epsilon(1e-4));
    // Its backward: d(sum_j w_j logit_j)/dhidden = sum_j w_j wte[ids_j].
    const std::vector<float> w = {0.5f, -2.0f, 1.5f};
    std::vector<float> dh(kSmall.n_embd, 0.0f);
    REQUIRE(model.head_logits_backward(w, ids, dh).is_ok());
    auto wte = model.tensor("wte.weight");
    for (int c = 0; c < kSmall.n_embd; ++c) {
      const float want = 0.5f * wte[c] - 2.0f * wte[17 * kSmall.n_embd + c] + 1.5f * wte[60 * kSmall.n_embd + c];
      CHECK(dh[c] == doctest::Approx(want).epsilon(1e-5));
    }
    std::vector<float> lm;
    REQUIRE(model.lm_logits(std::span<const float>(full.data(), kSmall.n_embd), lm).is_ok());
    CHECK(lm[17] == doctest::Approx(all[last + 17]).epsilon(1e-4));
  }
}

TEST_CASE("bad inputs to the model are errors") {
  Model model = random_model(kSmall, 3);
  std::vector<float> h;
  PrefixCache cache;
  CHECK_FALSE(model.forward_last(cache, {}, h).is_ok());
  CHECK_FALSE(model.forward_last(cache, {{}}, h).is_ok());
  auto st = model.forward_last(cache, {{1, 61}}, h);
  CHECK(st.message().find("outside the vocabulary") != std::string::npos);
  CHECK_FALSE(model.forward_last(cache, {std::vector<int>(49, 1)}, h).is_ok());
  REQUIRE(model.extend(cache, std::vector<int>(40, 1)).is_ok());
  CHECK_FALSE(model.forward_last(cache, {std::vector<int>(9, 1)}, h).is_ok());
  CHECK_FALSE(model.backward(std::vector<float>(32, 0.0f)).is_ok());
  REQUIRE(model.set_trainable_blocks(1).is_ok());
  CHECK_FALSE(model.backward(std::vector<float>(32, 0.0f)).is_ok());
  CHECK_FALSE(model.set_trainable_blocks(4).is_ok());
  PrefixCache other;
  other.len = 3;
  CHECK_FALSE(model.forward_last(other, {{1}}, h).is_ok());
}

// Checks every trainable tensor of a model with the last k blocks (and the
// embeddings when `embeddings`) trainable: the gradient from products at
// `prec` against fp32 central differences, |analytic - fd| <= atol + rtol |fd|.
static void check_tail_gradients(int k, bool embeddings, nn::Precision prec = nn::Precision::kFp32,
                                 double atol = 2e-3, double rtol = 2e-2) {
  const std::vector<TensorSpec> extras = {{"head.weight", {32, 3}, 0, 0}};
  Model model = random_model(kSmall, 5, extras);
  REQUIRE(model.set_trainable_blocks(k, embeddings).is_ok());
  const std::vector<int> prefix = {4, 8, 15, 16, 23};
  const std::vector<std::vector<int>> seqs = {{42, 1, 2}, {7}, {9, 9, 30, 31}};
  PrefixCache cache;
  REQUIRE(model.extend(cache, prefix).is_ok());
  const int C = kSmall.n_embd, A = 3, B = 3;
  Rng rng(99);
  std::vector<double> r(static_cast<size_t>(B) * A);
  for (double& v : r) v = rng.normal();
  // Loss = sum(R .* tanh(hidden @ head)): exercises the head tensor too.
  auto loss_and_dhidden = [&](std::vector<float>* dhidden) {
    std::vector<float> hidden;
    REQUIRE(model.forward_train(cache, seqs, hidden).is_ok());
    auto head = model.tensor("head.weight");
    double loss = 0.0;
    if (dhidden) dhidden->assign(hidden.size(), 0.0f);
    auto ghead = model.grad("head.weight");
    for (int b = 0; b < B; ++b)
      for (int a = 0; a < A; ++a) {
        double z = 0.0;
        for (int c = 0; c < C; ++c) z += static_cast<double>(hidden[b * C + c]) * head[c * A + a];
        const double th = std::tanh(z);
        loss += r[b * A + a] * th;
        if (dhidden) {
          const double dz = r[b * A + a] * (1.0 - th * th);
          for (int c = 0; c < C; ++c) {
            (*dhidden)[b * C + c] += static_cast<float>(dz * head[c * A + a]);
            ghead[c * A + a] += static_cast<float>(dz * hidden[b * C + c]);
          }
        }
      }
    return loss;
  };
  model.zero_grads();
  std::vector<float> dh;
  {
    const PrecisionScope scope(prec);
    loss_and_dhidden(&dh);
    REQUIRE(model.backward(dh).is_ok());
  }
  std::vector<float> analytic(model.grads().begin(), model.grads().end());
  double worst = 0.0;

  const size_t start = model.params().size() - model.grads().size();
  int checked = 0, tensors = 0;
  for (const TensorSpec& t : model.layout().tensors()) {
    if (t.offset < start) continue;
    ++tensors;
    Rng pick(t.offset);
    // Embedding rows that the prompt reads: its tokens, and positions 0..P+T-1.
    const std::vector<int> rows = t.name == "wte.weight"   ? std::vector<int>{4, 23, 42, 7, 31, 9}
                                  : t.name == "wpe.weight" ? std::vector<int>{0, 4, 5, 6, 8, 2}
                                                           : std::vector<int>{};
    for (int s = 0; s < (rows.empty() ? 4 : 6); ++s) {
      const size_t i = t.offset + (rows.empty() ? static_cast<size_t>(pick.uniform_int(0, static_cast<int64_t>(t.size) - 1))
                                                : static_cast<size_t>(rows[s]) * C + static_cast<size_t>(pick.uniform_int(0, C - 1)));
      const double fd =
          central_difference(model.params()[i], 1e-2f, [&] { return loss_and_dhidden(nullptr); });
      const double an = analytic[i - start];
      INFO(t.name << "[" << (i - t.offset) << "]: analytic " << an << ", finite difference " << fd);
      CHECK(std::fabs(an - fd) <= atol + rtol * std::fabs(fd));
      worst = std::max(worst, std::fabs(an - fd) / (atol + rtol * std::fabs(fd)));
      ++checked;
    }
  }
  CHECK(tensors == k * 12 + 2 + 1 + (embeddings ? 2 : 0));
  MESSAGE(checked << " finite-difference checks over " << tensors << " trainable tensors, "
                  << std::string(nn::precision_name(prec)) << " products; worst error " << worst << " of the tolerance");

  // The training forward equals the inference forward.
  std::vector<float> a, b;
  REQUIRE(model.forward_train(cache, seqs, a).is_ok());
  REQUIRE(model.forward_last(cache, seqs, b).is_ok());
  CHECK(max_abs_diff(a, b) < 1e-5f);
}

TEST_CASE("tail backward matches finite differences for every trainable tensor") {
  SUBCASE("no block: ln_f and the head") { check_tail_gradients(0, false); }
  SUBCASE("last 2 of 3 blocks") { check_tail_gradients(2, false); }
  SUBCASE("every block and the embeddings") { check_tail_gradients(3, true); }
  // bf16 products, fp32 finite differences: tolerances stated in docs/gpt2_bf16.md.
  SUBCASE("bf16: last 2 of 3 blocks") { check_tail_gradients(2, false, nn::Precision::kBf16, 2e-2, 5e-2); }
  SUBCASE("bf16: every block and the embeddings") {
    check_tail_gradients(3, true, nn::Precision::kBf16, 2e-2, 5e-2);
  }
  SUBCASE("the embeddings need every block") {
    Model model = random_model(kSmall, 5);
    CHECK(model.set_trainable_blocks(2, true).message().find("needs all 3 blocks") != std::string::npos);
  }
}

// The next-token loss from products at `prec`: equal to the cross-entropy of
// logits_all at the same precision (relative loss_eps), its gradient against
// fp32 central differences within atol + rtol |fd|.
static void check_lm_loss(nn::Precision prec, double loss_eps, double atol, double rtol) {
  Model model = random_model(kSmall, 8);
  const std::vector<std::vector<int>> seqs = {{3, 9, 27, 20, 1, 5}, {60, 2, 2}, {7, 7, 7, 7}};
  CHECK(model.lm_loss_backward(seqs, 0).status().message().find("embeddings trainable") != std::string::npos);
  REQUIRE(model.set_trainable_blocks(kSmall.n_layer, true).is_ok());
  CHECK_FALSE(model.lm_loss_backward(seqs, 6).is_ok());  // nothing after position 6
  const int from = 1;
  // The loss from logits_all: -log softmax over the tied head, predicted tokens only.
  auto reference = [&]() {
    double sum = 0.0;
    int n = 0;
    for (const auto& s : seqs) {
      std::vector<float> z;
      REQUIRE(model.logits_all(s, z).is_ok());
      const int V = kSmall.vocab_size;
      for (size_t t = from; t + 1 < s.size(); ++t) {
        const float* row = z.data() + t * V;
        double m = row[0], e = 0.0;
        for (int v = 0; v < V; ++v) m = std::max(m, static_cast<double>(row[v]));
        for (int v = 0; v < V; ++v) e += std::exp(row[v] - m);
        sum += std::log(e) + m - row[s[t + 1]];
        ++n;
      }
    }
    return sum / n;
  };
  model.zero_grads();
  {
    const PrecisionScope scope(prec);
    auto loss = model.lm_loss_backward(seqs, from);
    REQUIRE(loss.is_ok());
    CHECK(*loss == doctest::Approx(reference()).epsilon(loss_eps));
  }
  const std::vector<float> analytic(model.grads().begin(), model.grads().end());
  const int C = kSmall.n_embd;
  int checked = 0;
  for (const TensorSpec& t : model.layout().tensors()) {
    Rng pick(t.offset + 1);
    for (int s = 0; s < 3; ++s) {
      const size_t r = t.name == "wte.weight"   ? static_cast<size_t>(std::vector<int>{9, 2, 7}[s])
                       : t.name == "wpe.weight" ? static_cast<size_t>(s + 1)
                                                : 0;
      const size_t i = t.offset + (t.name.rfind("w", 0) == 0 ? r * C + static_cast<size_t>(pick.uniform_int(0, C - 1))
                                                             : static_cast<size_t>(pick.uniform_int(0, static_cast<int64_t>(t.size) - 1)));
      const double fd = central_difference(model.params()[i], 1e-2f, reference);
      INFO(t.name << "[" << (i - t.offset) << "]: analytic " << analytic[i] << ", finite difference " << fd);
      CHECK(std::fabs(analytic[i] - fd) <= atol + rtol * std::fabs(fd));
      ++checked;
    }
  }
  CHECK(checked == 3 * static_cast<int>(model.layout().tensors().size()));
}

TEST_CASE("next-token loss: gradient matches finite differences, and it equals the logits' cross-entropy") {
  SUBCASE("fp32") { check_lm_loss(nn::Precision::kFp32, 1e-5, 2e-3, 2e-2); }
  SUBCASE("bf16 products") { check_lm_loss(nn::Precision::kBf16, 1e-3, 2e-2, 5e-2); }
}

TEST_CASE("bf16: KV-cached decode, token by token, equals the bf16 full forward and is near fp32") {
  Model model = random_model(kSmall, 11);
  const std::vector<int> seq = {5, 9, 2, 44, 60, 1, 7, 10, 11, 12};
  std::vector<float> full16, full32, h;
  REQUIRE(model.forward_last({}, {seq}, full32).is_ok());
  const PrecisionScope bf16(nn::Precision::kBf16);
  REQUIRE(model.forward_last({}, {seq}, full16).is_ok());
  PrefixCache inc;
  for (int t : seq) REQUIRE(model.extend(inc, std::vector<int>{t}, &h).is_ok());
  const float d_cache = max_abs_diff(h, full16), d_fp32 = max_abs_diff(full16, full32);
  MESSAGE("bf16 decode vs bf16 full forward " << d_cache << ", bf16 vs fp32 " << d_fp32 << " (max |hidden| "
                                              << max_abs(full32) << ")");
  CHECK(d_cache < 1e-2f);
  CHECK(d_fp32 < 5e-2f);
  CHECK(d_fp32 > 1e-5f);  // the bf16 path ran
}

TEST_CASE("bf16: the model rounds again weights written through its accessors or by an optimiser") {
  Model model = random_model(kSmall, 12);
  REQUIRE(model.set_trainable_blocks(1).is_ok());
  const std::span<float> trainable = model.trainable_params();  // held, as Adam holds it
  const std::vector<std::vector<int>> seqs = {{5, 9, 2, 44}, {60, 1}};
  const PrecisionScope bf16(nn::Precision::kBf16);
  // The bf16 forward of a fresh copy of the model's current parameters.
  auto fresh = [&] {
    Model copy = random_model(kSmall, 12);
    std::copy(model.params().begin(), model.params().end(), copy.params().begin());
    std::vector<float> h;
    REQUIRE(copy.forward_last({}, seqs, h).is_ok());
    return h;
  };
  std::vector<float> h0, h1, h2;
  REQUIRE(model.forward_last({}, seqs, h0).is_ok());
  for (float& w : model.tensor("h.0.attn.c_attn.weight")) w *= 1.5f;  // frozen block 0
  REQUIRE(model.forward_last({}, seqs, h1).is_ok());
  CHECK(max_abs_diff(h1, h0) > 1e-3f);
  CHECK(max_abs_diff(h1, fresh()) == 0.0f);
  for (float& w : trainable) w *= 0.5f;  // an optimiser step through the held span
  REQUIRE(model.forward_last({}, seqs, h2).is_ok());
  CHECK(max_abs_diff(h2, h1) > 1e-3f);
  CHECK(max_abs_diff(h2, fresh()) == 0.0f);
}

TEST_CASE("GPT-2 small with GPT-2's random initialisation: bf16 logits within 2e-2 of fp32") {
  auto m = Model::create(Config::gpt2_small());
  REQUIRE(m.is_ok());
  Rng rng(124);
  m->init_random(rng);
  const std::vector<int> tokens = {464, 3290, 318, 257, 1332, 286, 262, 6459, 50256, 0, 17, 9999};
  std::vector<float> z32, z16;
  REQUIRE(m->logits_all(tokens, z32).is_ok());
  {
    const PrecisionScope bf16(nn::Precision::kBf16);
    REQUIRE(m->logits_all(tokens, z16).is_ok());
  }
  const float diff = max_abs_diff(z16, z32);
  MESSAGE("GPT-2 small, " << tokens.size() << " tokens x " << Config::gpt2_small().vocab_size
                          << " logits: max |bf16 - fp32| " << diff << ", max |logit| " << max_abs(z32));
  CHECK(diff < 2e-2f);
  CHECK(diff > 1e-5f);  // the bf16 path ran
}

TEST_CASE("Adam on the trainable tail and a head fits a small target") {
  const int C = kSmall.n_embd, A = 2;
  const std::vector<TensorSpec> extras = {{"head.weight", {C, A}, 0, 0}};
  Model model = random_model(kSmall, 21, extras);
  REQUIRE(model.set_trainable_blocks(1).is_ok());
  nn::Adam adam(model.trainable_params(), model.grads(), {1e-2f});
  PrefixCache cache;
  REQUIRE(model.extend(cache, std::vector<int>{1, 2, 3, 4}).is_ok());
  const std::vector<std::vector<int>> seqs = {{10, 11}, {12}, {13, 14, 15}};
  const float target[3][2] = {{1.0f, -1.0f}, {-0.5f, 0.5f}, {0.0f, 2.0f}};
  auto step = [&]() {
    std::vector<float> hidden;
    model.zero_grads();
    REQUIRE(model.forward_train(cache, seqs, hidden).is_ok());
    auto w = model.tensor("head.weight");
    auto gw = model.grad("head.weight");
    std::vector<float> dh(hidden.size(), 0.0f);
    double loss = 0.0;
    for (int b = 0; b < 3; ++b)
      for (int a = 0; a < A; ++a) {
        double y = 0.0;
        for (int c = 0; c < C; ++c) y += static_cast<double>(hidden[b * C + c]) * w[c * A + a];
        const double e = y - target[b][a];
        loss += e * e;
        for (int c = 0; c < C; ++c) {
          gw[c * A + a] += static_cast<float>(2 * e * hidden[b * C + c]);
          dh[b * C + c] += static_cast<float>(2 * e * w[c * A + a]);
        }
      }
    REQUIRE(model.backward(dh).is_ok());
    adam.step();
    return loss;
  };
  const double first = step();
  double last = first;
  for (int i = 0; i < 60; ++i) last = step();
  MESSAGE("loss " << first << " -> " << last << " after 60 Adam steps");
  CHECK(last < 0.05 * first);
  // Only the tail moved: the embeddings and block 0..L-2 are as loaded.
  Model fresh = random_model(kSmall, 21, extras);
  const size_t tail = model.params().size() - model.grads().size();
  CHECK(std::equal(fresh.params().begin(), fresh.params().begin() + static_cast<long>(tail), model.params().begin()));
}

TEST_CASE("read-out loss: gradients of model and probe match finite differences, weight scales the model's") {
  Model model = random_model(kSmall, 13);
  REQUIRE(model.set_trainable_blocks(kSmall.n_layer, true).is_ok());
  PrefixCache cache;
  REQUIRE(model.extend(cache, std::vector<int>{5, 6, 7}).is_ok());
  const std::vector<std::vector<int>> seqs = {{11, 12}, {13}, {14, 15, 16}};
  const int D = 4;
  Rng rng(3);
  std::vector<float> targets(seqs.size() * D);
  for (float& t : targets) t = static_cast<float>(rng.normal());
  Readout probe = Readout::make(kSmall.n_embd, D, rng);
  const float weight = 0.5f;
  model.zero_grads();
  auto loss = readout_loss_backward(model, cache, seqs, targets, probe, weight);
  REQUIRE(loss.is_ok());
  // The inference forward gives the same loss, and the loss is the mean square by hand.
  auto same = readout_loss(model, cache, seqs, targets, probe);
  REQUIRE(same.is_ok());
  CHECK(*same == doctest::Approx(*loss).epsilon(1e-5));
  std::vector<float> hidden;
  REQUIRE(model.forward_last(cache, seqs, hidden).is_ok());
  double by_hand = 0.0;
  const int C = kSmall.n_embd;
  for (size_t b = 0; b < seqs.size(); ++b)
    for (int d = 0; d < D; ++d) {
      double y = probe.params[static_cast<size_t>(C) * D + d];
      for (int c = 0; c < C; ++c) y += static_cast<double>(hidden[b * C + c]) * probe.params[c * D + d];
      by_hand += (y - targets[b * D + d]) * (y - targets[b * D + d]);
    }
  CHECK(*loss == doctest::Approx(by_hand / (seqs.size() * D)).epsilon(1e-5));

  const std::vector<float> model_grad(model.grads().begin(), model.grads().end());
  const std::vector<float> probe_grad = probe.grads;
  // The inference loss with the prefix cache rebuilt for the current parameters.
  auto fresh_loss = [&]() {
    PrefixCache c;
    REQUIRE(model.extend(c, cache.tokens).is_ok());
    return *readout_loss(model, c, seqs, targets, probe);
  };
  int checked = 0;
  for (const TensorSpec& t : model.layout().tensors()) {
    if (t.name == "wte.weight" || t.name == "wpe.weight") continue;  // Model::backward's own test covers them
    Rng pick(t.offset + 7);
    for (int s = 0; s < 2; ++s) {
      const auto i = t.offset + static_cast<size_t>(pick.uniform_int(0, static_cast<int64_t>(t.size) - 1));
      const double fd = weight * central_difference(model.params()[i], 1e-2f, fresh_loss);
      INFO(t.name << "[" << (i - t.offset) << "]: analytic " << model_grad[i] << ", finite difference " << fd);
      CHECK(std::fabs(model_grad[i] - fd) <= 2e-3 + 2e-2 * std::fabs(fd));
      ++checked;
    }
  }
  for (size_t i : {size_t{0}, size_t{37}, static_cast<size_t>(C) * D + 2}) {
    const double fd = central_difference(probe.params[i], 1e-2f, fresh_loss);
    INFO("probe[" << i << "]: analytic " << probe_grad[i] << ", finite difference " << fd);
    CHECK(std::fabs(probe_grad[i] - fd) <= 2e-3 + 2e-2 * std::fabs(fd));
    ++checked;
  }
  CHECK(checked == 2 * (static_cast<int>(model.layout().tensors().size()) - 2) + 3);

  // Shapes that do not fit are errors that say what was expected.
  auto short_targets = readout_loss(model, cache, seqs, std::vector<float>(5), probe);
  CHECK(short_targets.status().message() == "read-out targets hold 5 values; 3 sequences of 4 expected");
  Readout narrow = Readout::make(16, D, rng);
  CHECK(readout_loss_backward(model, cache, seqs, targets, narrow, 1.0f).status().message().find(
            "the model is 32 channels wide") != std::string::npos);
}
