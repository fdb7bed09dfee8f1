// Adam optimiser over one contiguous float buffer of parameters.
//
// Contract: params and grads are views of equal length that stay valid for the
// optimiser's lifetime; step() applies one update (Kingma & Ba, with bias
// correction) and leaves grads untouched (callers zero them).
// State (m, v, t) is exposed for checkpoints.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace squawk::nn {

struct AdamConfig {
  float lr = 3e-4f;
  float beta1 = 0.9f;
  float beta2 = 0.999f;
  float eps = 1e-8f;
  float weight_decay = 0.0f;  // decoupled (AdamW) when > 0
  float grad_clip = 0.0f;     // clip the global L2 norm of grads when > 0
};

class Adam {
 public:
  Adam(std::span<float> params, std::span<const float> grads, AdamConfig cfg = {});
  // One update; returns the global gradient L2 norm before clipping.
  float step();

  AdamConfig& config() { return cfg_; }
  long long t() const { return t_; }
  std::vector<float>& m() { return m_; }
  std::vector<float>& v() { return v_; }
  void set_t(long long t) { t_ = t; }

 private:
  std::span<float> params_;
  std::span<const float> grads_;
  AdamConfig cfg_;
  std::vector<float> m_, v_;
  long long t_ = 0;
};

}  // namespace squawk::nn
