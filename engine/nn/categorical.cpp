#include "nn/categorical.h"

#include <algorithm>
#include <cmath>

namespace squawk::nn {

void log_softmax(std::span<const float> logits, std::span<float> logp) {
  const float mx = *std::max_element(logits.begin(), logits.end());
  double sum = 0.0;
  for (float z : logits) sum += std::exp(static_cast<double>(z - mx));
  const float lse = mx + static_cast<float>(std::log(sum));
  for (size_t k = 0; k < logits.size(); ++k) logp[k] = logits[k] - lse;
}

int categorical_sample(std::span<const float> logp, Rng& rng) {
  const double u = rng.uniform();
  double acc = 0.0;
  for (size_t k = 0; k < logp.size(); ++k) {
    acc += std::exp(static_cast<double>(logp[k]));
    if (u < acc) return static_cast<int>(k);
  }
  return static_cast<int>(logp.size()) - 1;  // u beyond the rounded total
}

int categorical_argmax(std::span<const float> logp) {
  return static_cast<int>(std::max_element(logp.begin(), logp.end()) - logp.begin());
}

float categorical_entropy(std::span<const float> logp) {
  double h = 0.0;
  for (float lp : logp) h -= std::exp(static_cast<double>(lp)) * lp;
  return static_cast<float>(h);
}

void categorical_grad(std::span<const float> logp, int action, float coef, float ent_coef,
                      std::span<float> dz) {
  const float h = ent_coef != 0.0f ? categorical_entropy(logp) : 0.0f;
  for (size_t k = 0; k < logp.size(); ++k) {
    const float p = std::exp(logp[k]);
    float g = coef * ((static_cast<int>(k) == action ? 1.0f : 0.0f) - p);
    if (ent_coef != 0.0f) g += ent_coef * (-p * (logp[k] + h));
    dz[k] += g;
  }
}

}  // namespace squawk::nn
