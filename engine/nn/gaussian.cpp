#include "nn/gaussian.h"

#include <cmath>

namespace squawk::nn {

namespace {
constexpr float kHalfLog2Pi = 0.91893853320467274f;  // 0.5 log(2 pi)
}

float gaussian_log_prob(float a, float mu, float log_std) {
  const float z = (a - mu) * std::exp(-log_std);
  return -0.5f * z * z - log_std - kHalfLog2Pi;
}

float gaussian_entropy(float log_std) { return 0.5f + kHalfLog2Pi + log_std; }

float gaussian_sample(float mu, float log_std, Rng& rng) {
  return mu + std::exp(log_std) * static_cast<float>(rng.normal());
}

GaussianGrad gaussian_grad(float a, float mu, float log_std, float coef, float ent_coef) {
  const float inv_var = std::exp(-2.0f * log_std);
  const float d = a - mu;
  return {coef * d * inv_var, coef * (d * d * inv_var - 1.0f) + ent_coef};
}

}  // namespace squawk::nn
