// GCC 12 reports -Wmaybe-uninitialized falsely inside Eigen's AVX-512 product kernels.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include "nn/gemm.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <string_view>

#include <Eigen/Core>

#ifdef SQUAWK_HAVE_BLAS
#include <cblas.h>
#endif

namespace squawk::nn {

namespace {

std::atomic<int64_t> g_flops{0};
std::atomic<int64_t> g_nanos{0};
#ifdef SQUAWK_HAVE_BLAS
constexpr bool kHaveBlas = true;
#else
constexpr bool kHaveBlas = false;
#endif
bool g_use_blas = kHaveBlas;

bool blas() { return g_use_blas; }

using RowMat = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using ConstMap = Eigen::Map<const RowMat, 0, Eigen::OuterStride<>>;
using MutMap = Eigen::Map<RowMat, 0, Eigen::OuterStride<>>;

void gemm_eigen(bool ta, bool tb, int m, int n, int k, float alpha, const float* a, int lda,
                const float* b, int ldb, float beta, float* c, int ldc) {
  ConstMap A(a, ta ? k : m, ta ? m : k, Eigen::OuterStride<>(lda));
  ConstMap B(b, tb ? n : k, tb ? k : n, Eigen::OuterStride<>(ldb));
  MutMap C(c, m, n, Eigen::OuterStride<>(ldc));
  if (beta == 0.0f) C.setZero();
  else if (beta != 1.0f) C *= beta;
  if (!ta && !tb) C.noalias() += alpha * (A * B);
  else if (ta && !tb) C.noalias() += alpha * (A.transpose() * B);
  else if (!ta && tb) C.noalias() += alpha * (A * B.transpose());
  else C.noalias() += alpha * (A.transpose() * B.transpose());
}

}  // namespace

void gemm(bool trans_a, bool trans_b, int m, int n, int k, float alpha, const float* a, int lda,
          const float* b, int ldb, float beta, float* c, int ldc) {
  if (m <= 0 || n <= 0) return;
  const auto t0 = std::chrono::steady_clock::now();
  if (k <= 0) {
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < n; ++j) c[static_cast<int64_t>(i) * ldc + j] *= beta;
#ifdef SQUAWK_HAVE_BLAS
  } else if (blas()) {
    cblas_sgemm(CblasRowMajor, trans_a ? CblasTrans : CblasNoTrans, trans_b ? CblasTrans : CblasNoTrans,
                m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
#endif
  } else {
    gemm_eigen(trans_a, trans_b, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
  }
  const auto dt = std::chrono::steady_clock::now() - t0;
  g_flops += 2 * static_cast<int64_t>(m) * n * std::max(k, 0);
  g_nanos += std::chrono::duration_cast<std::chrono::nanoseconds>(dt).count();
}

void gemm_ref(bool trans_a, bool trans_b, int m, int n, int k, float alpha, const float* a, int lda,
              const float* b, int ldb, float beta, float* c, int ldc) {
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < n; ++j) {
      double acc = 0.0;
      for (int p = 0; p < k; ++p) {
        const float av = trans_a ? a[static_cast<int64_t>(p) * lda + i] : a[static_cast<int64_t>(i) * lda + p];
        const float bv = trans_b ? b[static_cast<int64_t>(j) * ldb + p] : b[static_cast<int64_t>(p) * ldb + j];
        acc += static_cast<double>(av) * bv;
      }
      float& cv = c[static_cast<int64_t>(i) * ldc + j];
      cv = static_cast<float>(alpha * acc + (beta == 0.0f ? 0.0 : static_cast<double>(beta) * cv));
    }
  }
}

const char* gemm_backend() { return blas() ? "openblas" : "eigen"; }

bool set_gemm_backend(const char* name) {
  const std::string_view n = name;
  if (n == "eigen") g_use_blas = false;
  else if (n == "openblas" && kHaveBlas) g_use_blas = true;
  else return false;
  return true;
}

void set_num_threads(int n) {
#ifdef OPENBLAS_VERSION
  openblas_set_num_threads(std::max(1, n));
#else
  (void)n;
#endif
}

int num_threads() {
#ifdef OPENBLAS_VERSION
  if (blas()) return openblas_get_num_threads();
#endif
  return 1;
}

GemmStats gemm_stats() {
  return {g_flops.load(), static_cast<double>(g_nanos.load()) * 1e-9};
}

void reset_gemm_stats() {
  g_flops = 0;
  g_nanos = 0;
}

}  // namespace squawk::nn
