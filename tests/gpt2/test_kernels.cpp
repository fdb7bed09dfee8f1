// Optimised kernels against their plain-loop references, and the element-wise
// ops against finite differences.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/rng.h"
#include "nn/attention.h"
#include "nn/gelu.h"
#include "nn/gemm.h"
#include "nn/layernorm.h"

using namespace squawk;

namespace {

std::vector<float> randn(size_t n, uint64_t seed, double sd = 1.0) {
  Rng rng(seed);
  std::vector<float> v(n);
  for (float& x : v) x = static_cast<float>(rng.normal(0.0, sd));
  return v;
}

float max_diff(const std::vector<float>& a, const std::vector<float>& b) {
  REQUIRE(a.size() == b.size());
  float m = 0.0f;
  for (size_t i = 0; i < a.size(); ++i) m = std::max(m, std::fabs(a[i] - b[i]));
  return m;
}

// 3 sequences of 5 rows, 4 heads; mode 0 without a prefix, 1 with a cached
// prefix of 4 rows, 2 with that prefix inline.
nn::AttentionShape shape_of_mode(int mode) {
  nn::AttentionShape s;
  s.B = 3, s.T = 5, s.C = 16, s.NH = 4;
  s.P = mode == 0 ? 0 : 4;
  s.inline_prefix = mode == 2;
  return s;
}

}  // namespace

TEST_CASE("gemm equals the plain-loop reference for every transpose") {
  const int m = 37, n = 29, k = 53;
  for (int ta = 0; ta < 2; ++ta)
    for (int tb = 0; tb < 2; ++tb) {
      auto a = randn(static_cast<size_t>(m) * k, 1), b = randn(static_cast<size_t>(k) * n, 2);
      auto c1 = randn(static_cast<size_t>(m) * n, 3), c2 = c1;
      const int lda = ta ? m : k, ldb = tb ? k : n;
      nn::gemm(ta, tb, m, n, k, 0.7f, a.data(), lda, b.data(), ldb, 0.3f, c1.data(), n);
      nn::gemm_ref(ta, tb, m, n, k, 0.7f, a.data(), lda, b.data(), ldb, 0.3f, c2.data(), n);
      CHECK(max_diff(c1, c2) < 1e-4f);
    }
}

TEST_CASE("bf16 rounding is to nearest, ties to even, and the vector path equals the scalar one") {
  CHECK(nn::to_bf16(1.0f) == 0x3f80);
  CHECK(nn::from_bf16(0x3f80) == 1.0f);
  // 1 + 2^-8 lies halfway between 1 and 1 + 2^-7: even (1) wins; 1 + 3*2^-8 rounds up to 1 + 2^-6.
  CHECK(nn::from_bf16(nn::to_bf16(1.0f + 0x1p-8f)) == 1.0f);
  CHECK(nn::from_bf16(nn::to_bf16(1.0f + 3 * 0x1p-8f)) == 1.0f + 0x1p-6f);
  CHECK(nn::from_bf16(nn::to_bf16(1.0f + 0x1p-8f + 0x1p-20f)) == 1.0f + 0x1p-7f);
  CHECK(std::isnan(nn::from_bf16(nn::to_bf16(std::nanf("")))));
  CHECK(std::isinf(nn::from_bf16(nn::to_bf16(3.4e38f))));  // rounds past the largest bf16
  auto x = randn(53, 4);
  x[5] = std::nanf("");
  x[17] = -INFINITY;
  std::vector<nn::bf16> v(x.size());
  nn::to_bf16(x.data(), x.size(), v.data());
  for (size_t i = 0; i < x.size(); ++i) {
    INFO("element " << i << " = " << x[i]);
    if (std::isnan(x[i])) CHECK(std::isnan(nn::from_bf16(v[i])));
    else CHECK(v[i] == nn::to_bf16(x[i]));
  }
}

TEST_CASE("bf16 gemm equals the plain-loop reference on the rounded operands for every transpose") {
  INFO("bf16 library: " << std::string(nn::bf16_library()));
  const int m = 37, n = 29, k = 53;
  for (int ta = 0; ta < 2; ++ta)
    for (int tb = 0; tb < 2; ++tb)
      for (const auto& [alpha, beta] : {std::pair{1.0f, 0.0f}, std::pair{0.7f, 0.3f}, std::pair{1.0f, 1.0f}}) {
        INFO("ta " << ta << " tb " << tb << " alpha " << alpha << " beta " << beta);
        auto a = randn(static_cast<size_t>(m) * k, 1), b = randn(static_cast<size_t>(k) * n, 2);
        std::vector<nn::bf16> a16(a.size()), b16(b.size());
        nn::to_bf16(a.data(), a.size(), a16.data());
        nn::to_bf16(b.data(), b.size(), b16.data());
        auto c1 = randn(static_cast<size_t>(m) * n, 3), c2 = c1, c3 = c1, c4 = c1, c5 = c1;
        const int lda = ta ? m : k, ldb = tb ? k : n;
        nn::gemm_bf16(ta, tb, m, n, k, alpha, a16.data(), lda, b16.data(), ldb, beta, c1.data(), n);
        nn::gemm_bf16_ref(ta, tb, m, n, k, alpha, a16.data(), lda, b16.data(), ldb, beta, c2.data(), n);
        CHECK(max_diff(c1, c2) < 1e-4f);
        // The fp32-operand entry point rounds A and B (or takes B pre-rounded) the same way.
        nn::gemm(nn::Precision::kBf16, ta, tb, m, n, k, alpha, a.data(), lda, b.data(), ldb, beta, c3.data(), n);
        nn::gemm(nn::Precision::kBf16, ta, tb, m, n, k, alpha, a.data(), lda, b.data(), ldb, beta, c4.data(), n,
                 b16.data());
        CHECK(max_diff(c3, c2) < 1e-4f);
        CHECK(max_diff(c4, c2) < 1e-4f);
        // And it is not the fp32 product: bf16 rounding shows (|error| ~ 2^-9 sqrt(k)).
        nn::gemm_ref(ta, tb, m, n, k, alpha, a.data(), lda, b.data(), ldb, beta, c5.data(), n);
        CHECK(max_diff(c3, c5) > 1e-3f);
        CHECK(max_diff(c3, c5) < 0.1f);
      }
}

TEST_CASE("bf16 gemm with leading dimensions wider than the matrices") {
  const int m = 5, n = 7, k = 9, lda = 12, ldb = 10, ldc = 11;
  auto a = randn(static_cast<size_t>(m) * lda, 5), b = randn(static_cast<size_t>(k) * ldb, 6);
  std::vector<nn::bf16> a16(a.size()), b16(b.size());
  nn::to_bf16(a.data(), a.size(), a16.data());
  nn::to_bf16(b.data(), b.size(), b16.data());
  auto c1 = randn(static_cast<size_t>(m) * ldc, 7), c2 = c1;
  nn::gemm_bf16(false, false, m, n, k, 1.0f, a16.data(), lda, b16.data(), ldb, 1.0f, c1.data(), ldc);
  nn::gemm_bf16_ref(false, false, m, n, k, 1.0f, a16.data(), lda, b16.data(), ldb, 1.0f, c2.data(), ldc);
  CHECK(max_diff(c1, c2) < 1e-4f);  // includes the columns past n, which both leave alone
}

TEST_CASE("precision names parse, and the fastest precision is bf16 exactly where it is native") {
  CHECK(*nn::parse_precision("bf16") == nn::Precision::kBf16);
  CHECK(*nn::parse_precision("fp32") == nn::Precision::kFp32);
  auto bad = nn::parse_precision("fp16");
  REQUIRE_FALSE(bad.is_ok());
  CHECK(bad.status().message().find("'fp16' is neither bf16 nor fp32") != std::string::npos);
  CHECK(std::string(nn::precision_name(nn::fastest_precision())) == (nn::bf16_native() ? "bf16" : "fp32"));
  MESSAGE("bf16 library: " << std::string(nn::bf16_library()) << "; fastest precision: "
                           << std::string(nn::precision_name(nn::fastest_precision())));
}

TEST_CASE("attention kernel equals the plain-loop reference, with and without a prefix") {
  for (int mode = 0; mode < 3; ++mode) {
    const nn::AttentionShape s = shape_of_mode(mode);
    const int R = s.rows(), C = s.C;
    auto qkv = randn(static_cast<size_t>(R) * 3 * C, 10 + mode);
    auto kext = randn(static_cast<size_t>(s.P) * C, 20), vext = randn(static_cast<size_t>(s.P) * C, 21);
    std::vector<float> out1(static_cast<size_t>(R) * C), out2 = out1;
    std::vector<float> att1(nn::attention_probs_size(s)), att2 = att1;
    nn::attention_forward(out1.data(), att1.data(), qkv.data(), kext.data(), vext.data(), C, s);
    nn::attention_forward_ref(out2.data(), att2.data(), qkv.data(), kext.data(), vext.data(), C, s);
    CHECK(max_diff(out1, out2) < 1e-5f);
    CHECK(max_diff(att1, att2) < 1e-6f);
    auto dout = randn(out1.size(), 30);
    std::vector<float> d1(qkv.size(), 0.0f), d2 = d1;
    nn::attention_backward(d1.data(), dout.data(), att1.data(), qkv.data(), kext.data(), vext.data(), C, s);
    nn::attention_backward_ref(d2.data(), dout.data(), att2.data(), qkv.data(), kext.data(), vext.data(), C, s);
    CHECK(max_diff(d1, d2) < 1e-5f);
    // Finite differences of sum(out .* dout) against the reference backward.
    Rng pick(mode);
    for (int trial = 0; trial < 12; ++trial) {
      const size_t i = static_cast<size_t>(pick.uniform_int(0, static_cast<int64_t>(qkv.size()) - 1));
      auto f = [&](float delta) {
        auto q = qkv;
        q[i] += delta;
        std::vector<float> o(out1.size());
        nn::attention_forward_ref(o.data(), nullptr, q.data(), kext.data(), vext.data(), C, s);
        double acc = 0.0;
        for (size_t j = 0; j < o.size(); ++j) acc += static_cast<double>(o[j]) * dout[j];
        return acc;
      };
      const double fd = (f(1e-3f) - f(-1e-3f)) / 2e-3;
      CHECK(std::fabs(fd - d2[i]) < 2e-3 + 1e-2 * std::fabs(fd));
    }
  }
}

TEST_CASE("attention over a subset of the queries equals those rows of the full attention") {
  for (int mode = 0; mode < 3; ++mode) {
    const nn::AttentionShape s = shape_of_mode(mode);
    const int R = s.rows(), C = s.C, base = s.inline_prefix ? s.P : 0;
    // The last row of sequence 0, a middle row of sequence 1, the first of sequence 2.
    const std::vector<int> rows = {base + 4, base + 5 + 2, base + 10};
    const int Q = static_cast<int>(rows.size());
    auto qkv = randn(static_cast<size_t>(R) * 3 * C, 40 + mode);
    auto kext = randn(static_cast<size_t>(s.P) * C, 50), vext = randn(static_cast<size_t>(s.P) * C, 51);
    std::vector<float> full(static_cast<size_t>(R) * C), att(nn::attention_probs_size(s));
    nn::attention_forward_ref(full.data(), att.data(), qkv.data(), kext.data(), vext.data(), C, s);
    std::vector<float> part(static_cast<size_t>(Q) * C), patt(nn::attention_rows_probs_size(s, Q));
    nn::attention_forward_rows(part.data(), patt.data(), qkv.data(), kext.data(), vext.data(), C, s, rows);
    std::vector<float> want;
    for (int r : rows) want.insert(want.end(), full.begin() + r * C, full.begin() + (r + 1) * C);
    CHECK(max_diff(part, want) < 1e-5f);
    // Backward: the full backward with a gradient on the chosen rows only.
    auto dpart = randn(part.size(), 60 + mode);
    std::vector<float> dfull(full.size(), 0.0f);
    for (int q = 0; q < Q; ++q)
      std::copy(dpart.begin() + q * C, dpart.begin() + (q + 1) * C, dfull.begin() + rows[q] * C);
    std::vector<float> d1(qkv.size(), 0.0f), d2 = d1;
    nn::attention_backward_ref(d1.data(), dfull.data(), att.data(), qkv.data(), kext.data(), vext.data(), C, s);
    nn::attention_backward_rows(d2.data(), dpart.data(), patt.data(), qkv.data(), kext.data(), vext.data(), C, s, rows);
    CHECK(max_diff(d1, d2) < 1e-5f);
  }
}

TEST_CASE("layernorm and gelu backward match finite differences") {
  const int N = 3, C = 7;
  auto x = randn(N * C, 40), w = randn(C, 41), b = randn(C, 42), dy = randn(N * C, 43);
  std::vector<float> y(N * C), mean(N), rstd(N);
  nn::layernorm_forward(y.data(), mean.data(), rstd.data(), x.data(), w.data(), b.data(), N, C, 1e-5f);
  std::vector<float> dx(N * C, 0.0f), dw(C, 0.0f), db(C, 0.0f);
  nn::layernorm_backward(dx.data(), dw.data(), db.data(), dy.data(), x.data(), w.data(), mean.data(),
                         rstd.data(), N, C);
  auto loss = [&](const std::vector<float>& xx, const std::vector<float>& ww) {
    std::vector<float> yy(N * C);
    nn::layernorm_forward(yy.data(), nullptr, nullptr, xx.data(), ww.data(), b.data(), N, C, 1e-5f);
    double acc = 0.0;
    for (int i = 0; i < N * C; ++i) acc += static_cast<double>(yy[i]) * dy[i];
    return acc;
  };
  for (int i = 0; i < N * C; ++i) {
    auto xp = x, xm = x;
    xp[i] += 1e-3f;
    xm[i] -= 1e-3f;
    CHECK(dx[i] == doctest::Approx((loss(xp, w) - loss(xm, w)) / 2e-3).epsilon(1e-2).scale(1.0));
  }
  for (int i = 0; i < C; ++i) {
    auto wp = w, wm = w;
    wp[i] += 1e-3f;
    wm[i] -= 1e-3f;
    CHECK(dw[i] == doctest::Approx((loss(x, wp) - loss(x, wm)) / 2e-3).epsilon(1e-2).scale(1.0));
  }
  std::vector<float> g(1), gd(1, 0.0f);
  for (float v : {-3.0f, -0.5f, 0.0f, 0.7f, 2.5f}) {
    const float one = 1.0f;
    std::vector<float> vp = {v + 1e-3f}, vm = {v - 1e-3f}, yp(1), ym(1);
    nn::gelu_forward(yp.data(), vp.data(), 1);
    nn::gelu_forward(ym.data(), vm.data(), 1);
    gd[0] = 0.0f;
    nn::gelu_backward(gd.data(), &v, &one, 1);
    CHECK(gd[0] == doctest::Approx((yp[0] - ym[0]) / 2e-3).epsilon(2e-3).scale(1.0));
  }
  // Published value: gelu_new(1) = 0.5 (1 + tanh(sqrt(2/pi) * 1.044715)) = 0.841192.
  const float x1 = 1.0f;
  nn::gelu_forward(g.data(), &x1, 1);
  CHECK(g[0] == doctest::Approx(0.8411920).epsilon(1e-6));
}
