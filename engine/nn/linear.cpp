#include "nn/linear.h"

namespace squawk::nn {

void linear_forward(float* out, const float* inp, const float* weight, const float* bias, int N,
                    int IC, int OC) {
  linear_forward(Precision::kFp32, out, inp, weight, nullptr, bias, N, IC, OC);
}

void linear_forward(Precision p, float* out, const float* inp, const float* weight,
                    const bf16* weight16, const float* bias, int N, int IC, int OC) {
  if (bias) {
    for (int n = 0; n < N; ++n)
      for (int o = 0; o < OC; ++o) out[static_cast<long>(n) * OC + o] = bias[o];
  }
  gemm(p, false, false, N, OC, IC, 1.0f, inp, IC, weight, OC, bias ? 1.0f : 0.0f, out, OC, weight16);
}

void linear_backward(float* dinp, float* dweight, float* dbias, const float* dout, const float* inp,
                     const float* weight, int N, int IC, int OC) {
  linear_backward(Precision::kFp32, dinp, dweight, dbias, dout, inp, weight, nullptr, N, IC, OC);
}

void linear_backward(Precision p, float* dinp, float* dweight, float* dbias, const float* dout,
                     const float* inp, const float* weight, const bf16* weight16, int N, int IC,
                     int OC) {
  if (dinp) gemm(p, false, true, N, IC, OC, 1.0f, dout, OC, weight, OC, 1.0f, dinp, IC, weight16);
  if (dweight) gemm(p, true, false, IC, OC, N, 1.0f, inp, IC, dout, OC, 1.0f, dweight, OC);
  if (dbias) {
    for (int n = 0; n < N; ++n)
      for (int o = 0; o < OC; ++o) dbias[o] += dout[static_cast<long>(n) * OC + o];
  }
}

}  // namespace squawk::nn
