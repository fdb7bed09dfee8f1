// Affine layer in GPT-2's Conv1D layout, forward and backward (llm.c style).
//
// Shape legend: N rows (B*T positions), IC input channels, OC output channels.
// Layout: inp [N,IC], weight [IC,OC] (row-major, Hugging Face Conv1D order),
// bias [OC] or null, out [N,OC]. All buffers are float32, row-major.
#pragma once

namespace squawk::nn {

// out = inp @ weight + bias.
void linear_forward(float* out, const float* inp, const float* weight, const float* bias, int N,
                    int IC, int OC);

// Accumulates gradients: dinp += dout @ weight^T, dweight += inp^T @ dout,
// dbias += column sums of dout. Any of dinp, dweight, dbias may be null.
void linear_backward(float* dinp, float* dweight, float* dbias, const float* dout, const float* inp,
                     const float* weight, int N, int IC, int OC);

}  // namespace squawk::nn
