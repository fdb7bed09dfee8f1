// Row-major single-precision matrix products, the one place squawk calls BLAS.
//
// Backend: OpenBLAS's cblas_sgemm when CMake found BLAS (SQUAWK_HAVE_BLAS),
// else Eigen. OpenBLAS was measured faster on this project's AVX-512 machine
// (about 155 vs 135 GFLOP/s on one core for 2048^3, unloaded) and threads by
// itself; Eigen would need OpenMP for that. `squawk gpt2 bench` reports both.
// All matrices are row-major with explicit leading dimensions (elements).
#pragma once

#include <cstdint>

namespace squawk::nn {

// C[m,n] = alpha * op(A) * op(B) + beta * C, op(X) = X or X^T.
// A is [m,k] (or [k,m] when trans_a), B is [k,n] (or [n,k] when trans_b).
void gemm(bool trans_a, bool trans_b, int m, int n, int k, float alpha, const float* a, int lda,
          const float* b, int ldb, float beta, float* c, int ldc);

// Plain-loop reference of gemm() for tests (double accumulation).
void gemm_ref(bool trans_a, bool trans_b, int m, int n, int k, float alpha, const float* a, int lda,
              const float* b, int ldb, float beta, float* c, int ldc);

// "openblas" or "eigen": the backend gemm() uses now.
const char* gemm_backend();
// Selects the backend by name; false (and no change) for "openblas" when the
// executable does not link it, or for an unknown name.
bool set_gemm_backend(const char* name);
// Threads the gemm backend may use (OpenBLAS only, whose default is its
// OPENBLAS_NUM_THREADS or every core; Eigen runs on one).
void set_num_threads(int n);
int num_threads();

// Running totals over every gemm() call in this process: floating-point
// operations (2mnk each) and wall time spent inside them [s].
struct GemmStats {
  int64_t flops = 0;
  double seconds = 0.0;
};
GemmStats gemm_stats();
void reset_gemm_stats();

}  // namespace squawk::nn
