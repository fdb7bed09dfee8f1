// Layer normalisation over the channel axis, forward and backward.
//
// Shape legend: N rows, C channels. inp/out [N,C]; weight, bias [C];
// mean, rstd [N] (per-row statistics kept for backward; may be null in
// forward when no backward follows). y = (x - mean) * rstd * weight + bias with
// rstd = 1 / sqrt(var + eps), var the biased variance (as PyTorch).
#pragma once

namespace squawk::nn {

void layernorm_forward(float* out, float* mean, float* rstd, const float* inp, const float* weight,
                       const float* bias, int N, int C, float eps);

// Accumulates dinp, dweight, dbias (dweight/dbias may be null).
void layernorm_backward(float* dinp, float* dweight, float* dbias, const float* dout,
                        const float* inp, const float* weight, const float* mean, const float* rstd,
                        int N, int C);

}  // namespace squawk::nn
