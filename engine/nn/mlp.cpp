#include "nn/mlp.h"

#include <cmath>
#include <string>

#include "nn/gemm.h"

namespace squawk::nn {

Result<Mlp> Mlp::make(std::vector<int> sizes) {
  if (sizes.size() < 2) return Status::invalid("Mlp: need at least {in, out} layer sizes");
  for (size_t i = 0; i < sizes.size(); ++i)
    if (sizes[i] <= 0)
      return Status::invalid("Mlp: layer size #" + std::to_string(i) + " is " +
                             std::to_string(sizes[i]) + ", expected a positive integer");
  return Mlp(std::move(sizes));
}

Mlp::Mlp(std::vector<int> sizes) : sizes_(std::move(sizes)) {
  for (size_t l = 0; l + 1 < sizes_.size(); ++l) {
    offsets_.push_back(num_params_);
    num_params_ += static_cast<size_t>(sizes_[l + 1]) * (static_cast<size_t>(sizes_[l]) + 1);
  }
}

void Mlp::init(std::span<float> params, Rng& rng) const {
  for (size_t l = 0; l + 1 < sizes_.size(); ++l) {
    const double bound = 1.0 / std::sqrt(static_cast<double>(sizes_[l]));
    const size_t n = static_cast<size_t>(sizes_[l + 1]) * (static_cast<size_t>(sizes_[l]) + 1);
    for (size_t i = 0; i < n; ++i)
      params[offsets_[l] + i] = static_cast<float>(rng.uniform(-bound, bound));
  }
}

void Mlp::forward(std::span<const float> params, const float* x, int batch, float* y,
                  MlpCache* cache) const {
  const size_t layers = sizes_.size() - 1;
  MlpCache local;
  MlpCache& c = cache ? *cache : local;
  c.batch = batch;
  c.acts.resize(layers);
  c.acts[0].assign(x, x + static_cast<size_t>(batch) * static_cast<size_t>(sizes_[0]));
  for (size_t l = 0; l < layers; ++l) {
    const int in = sizes_[l], out = sizes_[l + 1];
    const float* w = params.data() + w_offset(l);
    const float* b = params.data() + b_offset(l);
    const bool last = l + 1 == layers;
    float* z = y;
    if (!last) {
      c.acts[l + 1].resize(static_cast<size_t>(batch) * static_cast<size_t>(out));
      z = c.acts[l + 1].data();
    }
    gemm(false, true, batch, out, in, 1.0f, c.acts[l].data(), in, w, in, 0.0f, z, out);
    for (int r = 0; r < batch; ++r) {
      float* row = z + static_cast<size_t>(r) * static_cast<size_t>(out);
      for (int k = 0; k < out; ++k) {
        row[k] += b[k];
        if (!last && row[k] < 0.0f) row[k] = 0.0f;
      }
    }
  }
}

void Mlp::backward(std::span<const float> params, const MlpCache& cache, const float* dy,
                   std::span<float> grads) const {
  const int batch = cache.batch;
  const size_t layers = sizes_.size() - 1;
  std::vector<float> delta(dy, dy + static_cast<size_t>(batch) * static_cast<size_t>(sizes_.back()));
  std::vector<float> prev;
  for (size_t l = layers; l-- > 0;) {
    const int in = sizes_[l], out = sizes_[l + 1];
    const float* a = cache.acts[l].data();
    gemm(true, false, out, in, batch, 1.0f, delta.data(), out, a, in, 1.0f,
         grads.data() + w_offset(l), in);
    float* gb = grads.data() + b_offset(l);
    for (int r = 0; r < batch; ++r)
      for (int k = 0; k < out; ++k) gb[k] += delta[static_cast<size_t>(r) * static_cast<size_t>(out) + static_cast<size_t>(k)];
    if (l == 0) break;
    prev.resize(static_cast<size_t>(batch) * static_cast<size_t>(in));
    gemm(false, false, batch, in, out, 1.0f, delta.data(), out, params.data() + w_offset(l), in,
         0.0f, prev.data(), in);
    // ReLU gradient: the stored activation is zero where the unit was off.
    for (size_t i = 0; i < prev.size(); ++i)
      if (a[i] <= 0.0f) prev[i] = 0.0f;
    delta.swap(prev);
  }
}

}  // namespace squawk::nn
