// Diagonal Gaussian N(mu, sigma^2) in one dimension, parametrised by the mean
// and log sigma (the usual continuous-action policy head).
//
//   log p(a)          = -0.5 ((a - mu)/sigma)^2 - log sigma - 0.5 log(2 pi)
//   d log p / d mu    = (a - mu) / sigma^2
//   d log p / d log s = ((a - mu)/sigma)^2 - 1
//   H                 = 0.5 log(2 pi e) + log sigma,  dH / d log s = 1
#pragma once

#include "core/rng.h"

namespace squawk::nn {

struct GaussianGrad {
  float d_mu = 0.0f;
  float d_log_std = 0.0f;
};

float gaussian_log_prob(float a, float mu, float log_std);
float gaussian_entropy(float log_std);
float gaussian_sample(float mu, float log_std, Rng& rng);
// coef * d log p(a) + ent_coef * dH, with respect to mu and log sigma.
GaussianGrad gaussian_grad(float a, float mu, float log_std, float coef, float ent_coef);

}  // namespace squawk::nn
