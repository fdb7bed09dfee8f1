#include "nn/adam.h"

#include <cmath>

namespace squawk::nn {

Adam::Adam(std::span<float> params, std::span<const float> grads, AdamConfig cfg)
    : params_(params), grads_(grads), cfg_(cfg), m_(params.size(), 0.0f), v_(params.size(), 0.0f) {}

float Adam::step() {
  double sq = 0.0;
  for (float g : grads_) sq += static_cast<double>(g) * g;
  const float norm = static_cast<float>(std::sqrt(sq));
  const float scale = (cfg_.grad_clip > 0 && norm > cfg_.grad_clip) ? cfg_.grad_clip / norm : 1.0f;
  ++t_;
  const float b1 = cfg_.beta1, b2 = cfg_.beta2;
  const float c1 = 1.0f - static_cast<float>(std::pow(b1, static_cast<double>(t_)));
  const float c2 = 1.0f - static_cast<float>(std::pow(b2, static_cast<double>(t_)));
  const float lr = cfg_.lr, eps = cfg_.eps, wd = cfg_.weight_decay;
  const size_t n = params_.size();
  float* p = params_.data();
  const float* g = grads_.data();
  float* m = m_.data();
  float* v = v_.data();
  for (size_t i = 0; i < n; ++i) {
    const float gi = g[i] * scale;
    m[i] = b1 * m[i] + (1.0f - b1) * gi;
    v[i] = b2 * v[i] + (1.0f - b2) * gi * gi;
    const float mhat = m[i] / c1, vhat = v[i] / c2;
    p[i] -= lr * (mhat / (std::sqrt(vhat) + eps) + wd * p[i]);
  }
  return norm;
}

}  // namespace squawk::nn
