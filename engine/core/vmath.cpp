#include "core/vmath.h"

#include <cmath>

#if defined(__x86_64__) && defined(__AVX2__) && defined(__GLIBC__) && __GLIBC_PREREQ(2, 35)
#define SQUAWK_LIBMVEC 1
#include <immintrin.h>

// glibc's libmvec, AVX2 variants (x86-64 vector function ABI): 4 doubles a call.
extern "C" __m256d _ZGVdN4v_sin(__m256d);
extern "C" __m256d _ZGVdN4v_cos(__m256d);
extern "C" __m256d _ZGVdN4vv_atan2(__m256d, __m256d);
#endif

namespace squawk::vmath {

#ifdef SQUAWK_LIBMVEC
namespace {
// out = f(x * scale) in groups of four; the tail through a buffer padded
// with zeros.
template <class F>
void map1(F f, const double* x, double scale, double* out, int n) {
  const __m256d s = _mm256_set1_pd(scale);
  int i = 0;
  for (; i + 4 <= n; i += 4) _mm256_storeu_pd(out + i, f(_mm256_mul_pd(_mm256_loadu_pd(x + i), s)));
  if (i == n) return;
  double a[4] = {0.0, 0.0, 0.0, 0.0}, r[4];
  for (int k = 0; i + k < n; ++k) a[k] = x[i + k];
  _mm256_storeu_pd(r, f(_mm256_mul_pd(_mm256_loadu_pd(a), s)));
  for (int k = 0; i + k < n; ++k) out[i + k] = r[k];
}
}  // namespace

void sin(const double* x, double scale, double* out, int n) {
  map1([](__m256d v) { return _ZGVdN4v_sin(v); }, x, scale, out, n);
}
void cos(const double* x, double scale, double* out, int n) {
  map1([](__m256d v) { return _ZGVdN4v_cos(v); }, x, scale, out, n);
}

void atan2(const double* y, const double* x, double* out, int n) {
  int i = 0;
  for (; i + 4 <= n; i += 4) _mm256_storeu_pd(out + i, _ZGVdN4vv_atan2(_mm256_loadu_pd(y + i), _mm256_loadu_pd(x + i)));
  if (i == n) return;
  double a[4] = {0.0, 0.0, 0.0, 0.0}, b[4] = {1.0, 1.0, 1.0, 1.0}, r[4];
  for (int k = 0; i + k < n; ++k) a[k] = y[i + k], b[k] = x[i + k];
  _mm256_storeu_pd(r, _ZGVdN4vv_atan2(_mm256_loadu_pd(a), _mm256_loadu_pd(b)));
  for (int k = 0; i + k < n; ++k) out[i + k] = r[k];
}

bool uses_libmvec() { return true; }
#else
void sin(const double* x, double scale, double* out, int n) {
  for (int k = 0; k < n; ++k) out[k] = std::sin(x[k] * scale);
}
void cos(const double* x, double scale, double* out, int n) {
  for (int k = 0; k < n; ++k) out[k] = std::cos(x[k] * scale);
}
void atan2(const double* y, const double* x, double* out, int n) {
  for (int k = 0; k < n; ++k) out[k] = std::atan2(y[k], x[k]);
}
bool uses_libmvec() { return false; }
#endif

}  // namespace squawk::vmath
