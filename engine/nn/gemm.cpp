// GCC 12 reports -Wmaybe-uninitialized falsely inside Eigen's AVX-512 product kernels.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include "nn/gemm.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cstring>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#ifdef SQUAWK_HAVE_BLAS
#include <cblas.h>
#endif
#ifdef SQUAWK_HAVE_DNNL
#include <omp.h>

#include <oneapi/dnnl/dnnl.hpp>
#endif
#if defined(__AVX512BF16__) && defined(__AVX512F__)
#include <immintrin.h>
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
std::atomic<Precision> g_precision{Precision::kFp32};

bool blas() { return g_use_blas; }

// Adds one product's FLOPs and time to the running totals when it ends.
class Tally {
 public:
  Tally(int m, int n, int k) : flops_(2 * static_cast<int64_t>(m) * n * std::max(k, 0)) {}
  ~Tally() {
    const auto dt = std::chrono::steady_clock::now() - t0_;
    g_flops += flops_;
    g_nanos += std::chrono::duration_cast<std::chrono::nanoseconds>(dt).count();
  }
  Tally(const Tally&) = delete;
  Tally& operator=(const Tally&) = delete;

 private:
  int64_t flops_;
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

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

// C *= beta (k = 0: the product adds nothing).
void scale_c(int m, int n, float beta, float* c, int ldc) {
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) c[static_cast<int64_t>(i) * ldc + j] *= beta;
}

// The fp32 product without the tally; m, n, k > 0.
void sgemm(bool ta, bool tb, int m, int n, int k, float alpha, const float* a, int lda,
           const float* b, int ldb, float beta, float* c, int ldc) {
#ifdef SQUAWK_HAVE_BLAS
  if (blas()) {
    cblas_sgemm(CblasRowMajor, ta ? CblasTrans : CblasNoTrans, tb ? CblasTrans : CblasNoTrans, m, n,
                k, alpha, a, lda, b, ldb, beta, c, ldc);
    return;
  }
#endif
  gemm_eigen(ta, tb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
}

// Copies the rows x cols matrix x (leading dimension ld) into out, compact.
void widen(const bf16* x, int rows, int cols, int ld, std::vector<float>& out) {
  out.resize(static_cast<size_t>(rows) * cols);
  for (int r = 0; r < rows; ++r)
    for (int j = 0; j < cols; ++j)
      out[static_cast<size_t>(r) * cols + j] = from_bf16(x[static_cast<int64_t>(r) * ld + j]);
}

// gemm_bf16 through the fp32 backend: exact products, fp32 sums.
void bf16_emulated(bool ta, bool tb, int m, int n, int k, float alpha, const bf16* a, int lda,
                   const bf16* b, int ldb, float beta, float* c, int ldc) {
  thread_local std::vector<float> af, bf;
  const int ar = ta ? k : m, ac = ta ? m : k, br = tb ? n : k, bc = tb ? k : n;
  widen(a, ar, ac, lda, af);
  widen(b, br, bc, ldb, bf);
  sgemm(ta, tb, m, n, k, alpha, af.data(), ac, bf.data(), bc, beta, c, ldc);
}

#ifdef SQUAWK_HAVE_DNNL
// oneDNN matmul primitives, one per shape (the library picks its kernel,
// AMX or AVX512-BF16, for the exact shape; making one costs about a
// millisecond, running a cached one nothing extra). Products of at most
// kFewRows rows (KV-cache decode, the last block's last rows) share one
// primitive with the row count left to run time: oneDNN then runs its
// gemm:jit kernel, measured 2.7x faster than the fixed-shape brgemm at one
// row on AVX512-BF16 (72 vs 27 GFLOP/s, 1x2304x768) and as fast at 32.
constexpr int kFewRows = 16;
struct Key {
  int m, n, k, lda, ldb, ldc;
  bool ta, tb;
  float alpha, beta;
  bool operator==(const Key&) const = default;
};
struct KeyHash {
  size_t operator()(const Key& x) const {
    size_t h = 0;
    for (int64_t v : {int64_t{x.m}, int64_t{x.n}, int64_t{x.k}, int64_t{x.lda}, int64_t{x.ldb},
                      int64_t{x.ldc}, int64_t{x.ta} * 2 + x.tb,
                      int64_t{std::bit_cast<uint32_t>(x.alpha)},
                      int64_t{std::bit_cast<uint32_t>(x.beta)}})
      h = h * 1000003u ^ std::hash<int64_t>()(v);
    return h;
  }
};
// Shapes held at most; the cache starts over past it (a batch of new shapes
// costs their creation once more).
constexpr size_t kMaxPrimitives = 1024;

struct Dnnl {
  dnnl::engine eng{dnnl::engine::kind::cpu, 0};
  std::mutex mu;
  std::unordered_map<Key, dnnl::matmul, KeyHash> cache;

  dnnl::matmul get(const Key& x) {
    std::lock_guard lock(mu);
    if (auto it = cache.find(x); it != cache.end()) return it->second;
    using dt = dnnl::memory::data_type;
    const dnnl::memory::dim m = x.m == 0 ? DNNL_RUNTIME_DIM_VAL : x.m;
    const dnnl::memory::desc ad({m, x.k}, dt::bf16,
                                x.ta ? dnnl::memory::dims{1, x.lda} : dnnl::memory::dims{x.lda, 1});
    const dnnl::memory::desc bd({x.k, x.n}, dt::bf16,
                                x.tb ? dnnl::memory::dims{1, x.ldb} : dnnl::memory::dims{x.ldb, 1});
    const dnnl::memory::desc cd({m, x.n}, dt::f32, dnnl::memory::dims{x.ldc, 1});
    dnnl::primitive_attr attr;
    if (x.alpha != 1.0f) attr.set_output_scales(0, {x.alpha});
    if (x.beta != 0.0f) {
      dnnl::post_ops po;
      po.append_sum(x.beta);
      attr.set_post_ops(po);
    }
    const dnnl::matmul::primitive_desc pd(dnnl::matmul::desc(ad, bd, cd), attr, eng);
    if (cache.size() >= kMaxPrimitives) cache.clear();
    return cache.emplace(x, dnnl::matmul(pd)).first->second;
  }
};

Dnnl& dnnl_state() {
  static Dnnl d;
  return d;
}

// False when oneDNN refused the shape (the caller then emulates).
bool bf16_dnnl(bool ta, bool tb, int m, int n, int k, float alpha, const bf16* a, int lda,
               const bf16* b, int ldb, float beta, float* c, int ldc) {
  try {
    Dnnl& d = dnnl_state();
    const Key key{m <= kFewRows ? 0 : m, n, k, lda, ldb, ldc, ta, tb, alpha, beta};  // m = 0: at run time
    dnnl::matmul mm = d.get(key);
    using dt = dnnl::memory::data_type;
    // Descriptors of the memory handed over: the same as the primitive's.
    const dnnl::memory am({{m, k}, dt::bf16, ta ? dnnl::memory::dims{1, lda} : dnnl::memory::dims{lda, 1}},
                          d.eng, const_cast<bf16*>(a));
    const dnnl::memory bm({{k, n}, dt::bf16, tb ? dnnl::memory::dims{1, ldb} : dnnl::memory::dims{ldb, 1}},
                          d.eng, const_cast<bf16*>(b));
    const dnnl::memory cm({{m, n}, dt::f32, dnnl::memory::dims{ldc, 1}}, d.eng, c);
    dnnl::stream s(d.eng);
    mm.execute(s, {{DNNL_ARG_SRC, am}, {DNNL_ARG_WEIGHTS, bm}, {DNNL_ARG_DST, cm}});
    s.wait();
    return true;
  } catch (const dnnl::error&) {
    return false;
  }
}

bool dnnl_has_bf16_units() {
  const unsigned isa = static_cast<unsigned>(dnnl_get_effective_cpu_isa());
  const unsigned bf16 = dnnl_cpu_isa_avx512_core_bf16;
  return (isa & bf16) == bf16;
}
#endif

}  // namespace

bf16 to_bf16(float x) {
  uint32_t u = std::bit_cast<uint32_t>(x);
  if ((u & 0x7fffffffu) > 0x7f800000u) return static_cast<bf16>((u >> 16) | 0x40u);  // quiet NaN
  u += 0x7fffu + ((u >> 16) & 1u);
  return static_cast<bf16>(u >> 16);
}

float from_bf16(bf16 x) { return std::bit_cast<float>(static_cast<uint32_t>(x) << 16); }

void to_bf16(const float* x, size_t n, bf16* out) {
  size_t i = 0;
#if defined(__AVX512BF16__) && defined(__AVX512F__)
  for (; i + 16 <= n; i += 16) {
    const __m256bh v = _mm512_cvtneps_pbh(_mm512_loadu_ps(x + i));
    std::memcpy(out + i, &v, sizeof v);
  }
#endif
  for (; i < n; ++i) out[i] = to_bf16(x[i]);
}

void gemm(bool trans_a, bool trans_b, int m, int n, int k, float alpha, const float* a, int lda,
          const float* b, int ldb, float beta, float* c, int ldc) {
  if (m <= 0 || n <= 0) return;
  const Tally tally(m, n, k);
  if (k <= 0) scale_c(m, n, beta, c, ldc);
  else sgemm(trans_a, trans_b, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
}

void gemm_bf16(bool trans_a, bool trans_b, int m, int n, int k, float alpha, const bf16* a, int lda,
               const bf16* b, int ldb, float beta, float* c, int ldc) {
  if (m <= 0 || n <= 0) return;
  const Tally tally(m, n, k);
  if (k <= 0) {
    scale_c(m, n, beta, c, ldc);
    return;
  }
#ifdef SQUAWK_HAVE_DNNL
  if (bf16_dnnl(trans_a, trans_b, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc)) return;
#endif
  bf16_emulated(trans_a, trans_b, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
}

const char* precision_name(Precision p) { return p == Precision::kBf16 ? "bf16" : "fp32"; }

Result<Precision> parse_precision(std::string_view s) {
  if (s == "fp32") return Precision::kFp32;
  if (s == "bf16") return Precision::kBf16;
  return Status::invalid("precision '" + std::string(s) + "' is neither bf16 nor fp32");
}

void gemm(Precision p, bool trans_a, bool trans_b, int m, int n, int k, float alpha, const float* a,
          int lda, const float* b, int ldb, float beta, float* c, int ldc, const bf16* b16) {
  if (p == Precision::kFp32) {
    gemm(trans_a, trans_b, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
    return;
  }
  if (m <= 0 || n <= 0 || k <= 0) {
    gemm_bf16(trans_a, trans_b, m, n, k, alpha, nullptr, 1, nullptr, 1, beta, c, ldc);
    return;
  }
  // Operands rounded into compact buffers (leading dimension = columns).
  thread_local std::vector<bf16> a16, bc16;
  const auto round = [](const float* x, int rows, int cols, int ld, std::vector<bf16>& out) {
    out.resize(static_cast<size_t>(rows) * cols);
    for (int r = 0; r < rows; ++r)
      to_bf16(x + static_cast<int64_t>(r) * ld, static_cast<size_t>(cols), out.data() + static_cast<size_t>(r) * cols);
  };
  const auto t0 = std::chrono::steady_clock::now();
  const int ac = trans_a ? m : k, bc = trans_b ? k : n;
  round(a, trans_a ? k : m, ac, lda, a16);
  if (!b16) round(b, trans_b ? n : k, bc, ldb, bc16);
  g_nanos += std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count();
  gemm_bf16(trans_a, trans_b, m, n, k, alpha, a16.data(), ac, b16 ? b16 : bc16.data(), b16 ? ldb : bc,
            beta, c, ldc);
}

Precision gemm_precision() { return g_precision.load(); }
void set_gemm_precision(Precision p) { g_precision = p; }

bool bf16_native() {
#ifdef SQUAWK_HAVE_DNNL
  static const bool native = dnnl_has_bf16_units();
  return native;
#else
  return false;
#endif
}

Precision fastest_precision() { return bf16_native() ? Precision::kBf16 : Precision::kFp32; }

const char* bf16_library() {
#ifdef SQUAWK_HAVE_DNNL
  static const std::string name = [] {
    const dnnl_version_t* v = dnnl_version();
    const unsigned isa = static_cast<unsigned>(dnnl_get_effective_cpu_isa());
    const unsigned amx = dnnl_cpu_isa_avx512_core_amx;
    const char* units = (isa & amx) == amx    ? "AMX-BF16"
                        : dnnl_has_bf16_units() ? "AVX512-BF16"
                                                : "no bf16 instructions";
    return "oneDNN " + std::to_string(v->major) + "." + std::to_string(v->minor) + "." +
           std::to_string(v->patch) + " on " + units;
  }();
  return name.c_str();
#else
  return "none (bf16 emulated in fp32)";
#endif
}

std::string use_precision(std::optional<Precision> requested) {
  const Precision p = requested.value_or(fastest_precision());
  if (p == Precision::kBf16 && !bf16_native()) {
    set_gemm_precision(Precision::kFp32);
    return std::string("precision: fp32; bf16 was asked for, but this CPU or build has no native bf16 "
                       "products (bf16 library: ") + bf16_library() + ")";
  }
  set_gemm_precision(p);
  std::string line = std::string("precision: ") + precision_name(p);
  if (p == Precision::kBf16) line += std::string(" products with fp32 accumulation, ") + bf16_library();
  line += requested ? " (--precision)" : " (the fastest here; --precision bf16|fp32 chooses)";
  return line;
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

void gemm_bf16_ref(bool trans_a, bool trans_b, int m, int n, int k, float alpha, const bf16* a,
                   int lda, const bf16* b, int ldb, float beta, float* c, int ldc) {
  std::vector<float> af, bf;
  widen(a, trans_a ? k : m, trans_a ? m : k, lda, af);
  widen(b, trans_b ? n : k, trans_b ? k : n, ldb, bf);
  gemm_ref(trans_a, trans_b, m, n, k, alpha, af.data(), trans_a ? m : k, bf.data(), trans_b ? k : n,
           beta, c, ldc);
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
#endif
#ifdef SQUAWK_HAVE_DNNL
  omp_set_num_threads(std::max(1, n));
#endif
  (void)n;
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
