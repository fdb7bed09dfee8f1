// Mirror-symmetric discrete policies. A policy with a mirror M (an affine
// involution of the observation, env::observation_mirror) and symmetric
// action values (a_k = -a_{K-1-k}) computes its logits as
//   z(o)[k] = f(o)[k] + f(M o)[K-1-k]
// where f is the underlying network. Then pi(a_k | o) = pi(a_{K-1-k} | M o):
// the policy turns the mirror image of an encounter the mirror way, by
// construction, with the parameters of f alone (no more of them). Evaluating
// z costs two rows of f per observation.
//
// Shapes: obs [n, D]; rows [2n, D] (the n observations, then their n
// images); raw [2n, K] (f on rows); logits [n, K].
#pragma once

#include <span>
#include <vector>

#include "core/status.h"
#include "env/observation.h"

namespace squawk::rl {

// Ok when `m` fits observations of obs_size values (scale +-1, m(m(o)) = o)
// and the action values are symmetric; the error names what does not fit.
Status validate_mirror(const env::ObservationMirror& m, int obs_size, std::span<const double> action_values);

// rows = [obs; M obs] for obs [n, D].
void mirror_rows(const env::ObservationMirror& m, std::span<const float> obs, int n, std::vector<float>& rows);

// Forward: logits[r, k] = raw[r, k] + raw[n + r, K-1-k].
void mirror_combine(std::span<const float> raw, int n, int K, std::span<float> logits);

// Backward of mirror_combine: draw [2n, K] from dlogits [n, K].
void mirror_spread(std::span<const float> dlogits, int n, int K, std::span<float> draw);

}  // namespace squawk::rl
