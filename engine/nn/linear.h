// Affine layer in GPT-2's Conv1D layout, forward and backward (llm.c style).
//
// Shape legend: N rows (B*T positions), IC input channels, OC output channels.
// Layout: inp [N,IC], weight [IC,OC] (row-major, Hugging Face Conv1D order),
// bias [OC] or null, out [N,OC]. All buffers are float32, row-major.
//
// The overloads with a Precision run their matrix products at it (nn/gemm.h):
// in bf16 the operands are rounded to bf16 and accumulate in fp32; weight16,
// when given, is the weight already rounded (same layout), else the weight is
// rounded at each call. The bias and the gradient sums stay fp32.
#pragma once

#include "nn/gemm.h"

namespace squawk::nn {

// out = inp @ weight + bias.
void linear_forward(float* out, const float* inp, const float* weight, const float* bias, int N,
                    int IC, int OC);
void linear_forward(Precision p, float* out, const float* inp, const float* weight,
                    const bf16* weight16, const float* bias, int N, int IC, int OC);

// Accumulates gradients: dinp += dout @ weight^T, dweight += inp^T @ dout,
// dbias += column sums of dout. Any of dinp, dweight, dbias may be null.
void linear_backward(float* dinp, float* dweight, float* dbias, const float* dout, const float* inp,
                     const float* weight, int N, int IC, int OC);
void linear_backward(Precision p, float* dinp, float* dweight, float* dbias, const float* dout,
                     const float* inp, const float* weight, const bf16* weight16, int N, int IC,
                     int OC);

}  // namespace squawk::nn
