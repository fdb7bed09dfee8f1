#include "rl/mirror.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace squawk::rl {

Status validate_mirror(const env::ObservationMirror& m, int obs_size, std::span<const double> action_values) {
  const auto d = static_cast<size_t>(obs_size);
  if (m.scale.size() != d || m.offset.size() != d)
    return Status::invalid("mirror map of " + std::to_string(m.scale.size()) + " scales and " +
                           std::to_string(m.offset.size()) + " offsets: expected " + std::to_string(d) +
                           " each (the observation size)");
  for (size_t i = 0; i < d; ++i) {
    const float s = m.scale[i], b = m.offset[i];
    if ((s != 1.0f && s != -1.0f) || !std::isfinite(b) || std::fabs(s * b + b) > 1e-6f)
      return Status::invalid("mirror map entry " + std::to_string(i) + " (scale " + std::to_string(s) +
                             ", offset " + std::to_string(b) +
                             ") is not its own inverse: expected scale +-1, and offset 0 where scale is 1");
  }
  const size_t K = action_values.size();
  for (size_t k = 0; k < K; ++k)
    if (action_values[k] != -action_values[K - 1 - k])
      return Status::invalid("mirror symmetry needs symmetric action values (a_k = -a_{K-1-k}), but action " +
                             std::to_string(k) + " is " + std::to_string(action_values[k]) + " and action " +
                             std::to_string(K - 1 - k) + " is " + std::to_string(action_values[K - 1 - k]));
  return Status::ok();
}

void mirror_rows(const env::ObservationMirror& m, std::span<const float> obs, int n, std::vector<float>& rows) {
  const size_t d = m.scale.size(), half = static_cast<size_t>(n) * d;
  rows.resize(2 * half);
  std::copy(obs.begin(), obs.begin() + static_cast<long>(half), rows.begin());
  for (size_t r = 0; r < static_cast<size_t>(n); ++r)
    for (size_t i = 0; i < d; ++i) rows[half + r * d + i] = m.scale[i] * obs[r * d + i] + m.offset[i];
}

void mirror_combine(std::span<const float> raw, int n, int K, std::span<float> logits) {
  const auto k = static_cast<size_t>(K), rows = static_cast<size_t>(n);
  for (size_t r = 0; r < rows; ++r)
    for (size_t a = 0; a < k; ++a) logits[r * k + a] = raw[r * k + a] + raw[(rows + r) * k + (k - 1 - a)];
}

void mirror_spread(std::span<const float> dlogits, int n, int K, std::span<float> draw) {
  const auto k = static_cast<size_t>(K), rows = static_cast<size_t>(n);
  for (size_t r = 0; r < rows; ++r)
    for (size_t a = 0; a < k; ++a) {
      draw[r * k + a] = dlogits[r * k + a];
      draw[(rows + r) * k + (k - 1 - a)] = dlogits[r * k + a];
    }
}

}  // namespace squawk::rl
