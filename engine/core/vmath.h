// Elementwise sin, cos and atan2 over arrays of doubles.
//
// Builds that target AVX2 on x86-64 glibc (SQUAWK_NATIVE on an AVX2 machine)
// call glibc's vector math library (libmvec: _ZGVdN4v_sin, _ZGVdN4v_cos,
// _ZGVdN4vv_atan2), four elements per call; other builds (SQUAWK_NATIVE=OFF,
// the sanitizer build) call std:: per element. libmvec is not bit-identical
// to libm: glibc states at most 4 ulp for these. An element's result depends
// only on its own inputs (a partial last group of four is padded), so it is
// the same whatever n and position in the array.
#pragma once

namespace squawk::vmath {

// out[k] = sin(x[k] * scale), k < n. x and out may be the same array.
void sin(const double* x, double scale, double* out, int n);
// out[k] = cos(x[k] * scale), k < n.
void cos(const double* x, double scale, double* out, int n);
// out[k] = atan2(y[k], x[k]), k < n. out may be y or x.
void atan2(const double* y, const double* x, double* out, int n);
// Whether this build calls libmvec (else std:: per element).
bool uses_libmvec();

}  // namespace squawk::vmath
