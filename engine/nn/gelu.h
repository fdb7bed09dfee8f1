// GPT-2's GELU, the tanh approximation ("gelu_new"):
//   gelu(x) = 0.5 x (1 + tanh(sqrt(2/pi) (x + 0.044715 x^3))).
// Element-wise over n floats.
#pragma once

#include <cstddef>

namespace squawk::nn {

void gelu_forward(float* out, const float* inp, size_t n);
// Accumulates dinp += gelu'(inp) * dout.
void gelu_backward(float* dinp, const float* inp, const float* dout, size_t n);

}  // namespace squawk::nn
