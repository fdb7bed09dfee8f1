// Mlp: a stack of fully connected layers with ReLU between them (none after
// the last), batched, with a hand-written backward pass.
//
// Shapes (row-major, B = batch): input x [B, sizes[0]], output y [B, sizes.back()].
// Parameters live in one caller-owned float buffer so an optimiser (nn::Adam)
// and a checkpoint can see them as one span. Layout, for each layer l in order:
//   W_l [sizes[l+1], sizes[l]] (row-major, out x in), then b_l [sizes[l+1]].
// The layer computes y = x W_l^T + b_l.
// Contract: params/grads spans passed to the methods have num_params() floats.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "core/rng.h"
#include "core/status.h"

namespace squawk::nn {

// Activations kept by forward() for backward(); reused between calls.
struct MlpCache {
  int batch = 0;
  std::vector<std::vector<float>> acts;  // acts[l]: input of layer l [B, sizes[l]] (after ReLU)
};

class Mlp {
 public:
  // sizes: {in, hidden..., out}; at least two entries, all positive.
  static Result<Mlp> make(std::vector<int> sizes);

  const std::vector<int>& sizes() const { return sizes_; }
  int in_dim() const { return sizes_.front(); }
  int out_dim() const { return sizes_.back(); }
  size_t num_params() const { return num_params_; }

  // PyTorch's nn.Linear default: W and b ~ U(-1/sqrt(fan_in), 1/sqrt(fan_in)).
  void init(std::span<float> params, Rng& rng) const;

  // y [B, out] = mlp(x [B, in]). With a cache, keeps what backward() needs.
  void forward(std::span<const float> params, const float* x, int batch, float* y,
               MlpCache* cache) const;
  // Given dL/dy [B, out] for the batch of the last forward(cache), adds
  // dL/dparams to grads.
  void backward(std::span<const float> params, const MlpCache& cache, const float* dy,
                std::span<float> grads) const;

 private:
  explicit Mlp(std::vector<int> sizes);
  size_t w_offset(size_t l) const { return offsets_[l]; }
  size_t b_offset(size_t l) const {
    return offsets_[l] + static_cast<size_t>(sizes_[l + 1]) * static_cast<size_t>(sizes_[l]);
  }

  std::vector<int> sizes_;
  std::vector<size_t> offsets_;  // start of W_l in the parameter buffer
  size_t num_params_ = 0;
};

}  // namespace squawk::nn
