// Row-major matrix products, the one place squawk calls BLAS or a bf16 library.
//
// fp32 backend: OpenBLAS's cblas_sgemm when CMake found BLAS
// (SQUAWK_HAVE_BLAS), else Eigen. OpenBLAS was measured faster on this
// project's AVX-512 machine (about 155 vs 135 GFLOP/s on one core for 2048^3,
// unloaded) and threads by itself; Eigen would need OpenMP for that.
//
// bf16 backend: oneDNN's matmul primitive when CMake found oneDNN
// (SQUAWK_HAVE_DNNL): bf16 operands, fp32 accumulation and output. It uses
// AVX512-BF16 (vdpbf16ps) or AMX-BF16 tiles where the CPU has them. Without
// oneDNN, gemm_bf16 widens its operands to fp32 and calls the fp32 backend:
// the same products (a product of two bf16 values is exact in fp32), no
// faster. Measured choice among oneDNN, OpenBLAS sbgemm and Eigen::bfloat16:
// docs/gpt2_bf16.md. `squawk gpt2 bench` reports both precisions.
//
// All matrices are row-major with explicit leading dimensions (elements).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/status.h"

namespace squawk::nn {

// A bfloat16 value as its 16 bits: the high half of an IEEE-754 float32.
using bf16 = uint16_t;

// Rounds to the nearest bf16, ties to even (NaN stays NaN).
bf16 to_bf16(float x);
float from_bf16(bf16 x);
// out[i] = to_bf16(x[i]) for i < n.
void to_bf16(const float* x, size_t n, bf16* out);

// C[m,n] = alpha * op(A) * op(B) + beta * C, op(X) = X or X^T, all fp32.
// A is [m,k] (or [k,m] when trans_a), B is [k,n] (or [n,k] when trans_b).
void gemm(bool trans_a, bool trans_b, int m, int n, int k, float alpha, const float* a, int lda,
          const float* b, int ldb, float beta, float* c, int ldc);

// The same product with bf16 A and B, fp32 accumulation and fp32 C.
void gemm_bf16(bool trans_a, bool trans_b, int m, int n, int k, float alpha, const bf16* a, int lda,
               const bf16* b, int ldb, float beta, float* c, int ldc);

// Precision of a product's operands: fp32, or rounded to bf16 (mixed
// precision: fp32 accumulation and result either way).
enum class Precision { kFp32, kBf16 };
const char* precision_name(Precision p);  // "fp32" or "bf16"
// "fp32" or "bf16"; anything else is an error naming it.
Result<Precision> parse_precision(std::string_view s);

// gemm() at precision p with fp32 operands. In bf16 A and B are rounded to
// bf16 first; b16, when given, is B already rounded (to_bf16 of the same
// elements in the same layout, leading dimension ldb), which spares the
// rounding of a weight matrix used many times.
void gemm(Precision p, bool trans_a, bool trans_b, int m, int n, int k, float alpha, const float* a,
          int lda, const float* b, int ldb, float beta, float* c, int ldc,
          const bf16* b16 = nullptr);

// Precision of the GPT-2 engine's matrix products in this process (read by
// gpt2::Model at each forward). Starts as fp32; the command line sets it.
Precision gemm_precision();
void set_gemm_precision(Precision p);
// Whether bf16 products run on bf16 hardware through the bf16 library (then
// they are faster than fp32); false without oneDNN or on a CPU without
// AVX512-BF16 or AMX-BF16, where gemm_bf16 is correct but no faster.
bool bf16_native();
// The fastest precision here: bf16 when bf16_native(), else fp32.
Precision fastest_precision();
// "oneDNN 2.6.3 on AVX512-BF16" or similar, or "none (bf16 emulated in fp32)".
const char* bf16_library();
// Sets the process precision from a request (--precision; absent: the
// fastest here) and returns the one line to print at start. bf16 requested
// where it is not native runs fp32, and the line says why.
std::string use_precision(std::optional<Precision> requested);

// Plain-loop references of gemm() and gemm_bf16() for tests (double accumulation).
void gemm_ref(bool trans_a, bool trans_b, int m, int n, int k, float alpha, const float* a, int lda,
              const float* b, int ldb, float beta, float* c, int ldc);
void gemm_bf16_ref(bool trans_a, bool trans_b, int m, int n, int k, float alpha, const bf16* a,
                   int lda, const bf16* b, int ldb, float beta, float* c, int ldc);

// "openblas" or "eigen": the fp32 backend gemm() uses now.
const char* gemm_backend();
// Selects the fp32 backend by name; false (and no change) for "openblas" when
// the executable does not link it, or for an unknown name.
bool set_gemm_backend(const char* name);
// Threads the backends may use (OpenBLAS, whose default is its
// OPENBLAS_NUM_THREADS or every core, and oneDNN's OpenMP; Eigen runs on one).
void set_num_threads(int n);
int num_threads();

// Running totals over every gemm() and gemm_bf16() call in this process:
// floating-point operations (2mnk each) and wall time spent inside them [s]
// (rounding to bf16 included).
struct GemmStats {
  int64_t flops = 0;
  double seconds = 0.0;
};
GemmStats gemm_stats();
void reset_gemm_stats();

}  // namespace squawk::nn
