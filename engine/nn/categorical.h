// Categorical distribution over K classes given unnormalised logits.
//
// Shapes: logits [K] for one row; batched callers loop over rows.
// Gradients are with respect to the logits:
//   d log p(a) / d z_k = 1[k = a] - p_k
//   d H / d z_k        = -p_k (log p_k + H),  H = -sum_k p_k log p_k
#pragma once

#include <span>

#include "core/rng.h"

namespace squawk::nn {

// log p [K] = log_softmax(logits), computed stably (max subtracted).
void log_softmax(std::span<const float> logits, std::span<float> logp);
// Draws a class from exp(logp) by inversion of one Rng::uniform().
int categorical_sample(std::span<const float> logp, Rng& rng);
// Index of the largest log-probability (first one on ties).
int categorical_argmax(std::span<const float> logp);
// H = -sum p log p.
float categorical_entropy(std::span<const float> logp);
// Adds  coef * d log p(a)/dz + ent_coef * dH/dz  to dz [K].
void categorical_grad(std::span<const float> logp, int action, float coef, float ent_coef,
                      std::span<float> dz);

}  // namespace squawk::nn
