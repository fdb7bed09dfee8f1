// GCC 12 reports -Wmaybe-uninitialized falsely inside Eigen's AVX-512 kernels.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include "nn/gelu.h"

#include <cmath>

#include <Eigen/Core>

namespace squawk::nn {

namespace {
constexpr float kSqrt2OverPi = 0.7978845608028654f;
constexpr float kCubic = 0.044715f;
using ConstArr = Eigen::Map<const Eigen::ArrayXf>;
using Arr = Eigen::Map<Eigen::ArrayXf>;
}  // namespace

// Eigen's vectorised tanh (a rational approximation accurate to a few float
// ulps) keeps GELU from dominating the non-matmul time of a forward pass.
void gelu_forward(float* out, const float* inp, size_t n) {
  ConstArr x(inp, static_cast<Eigen::Index>(n));
  Arr(out, static_cast<Eigen::Index>(n)) =
      0.5f * x * (1.0f + (kSqrt2OverPi * (x + kCubic * x.cube())).tanh());
}

void gelu_backward(float* dinp, const float* inp, const float* dout, size_t n) {
  const auto len = static_cast<Eigen::Index>(n);
  ConstArr x(inp, len), dy(dout, len);
  const Eigen::ArrayXf th = (kSqrt2OverPi * (x + kCubic * x.cube())).tanh();
  Arr(dinp, len) += (0.5f * (1.0f + th) +
                     0.5f * x * (1.0f - th.square()) * kSqrt2OverPi * (1.0f + 3.0f * kCubic * x.square())) *
                    dy;
}

}  // namespace squawk::nn
