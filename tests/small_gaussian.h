// The tests' small diagonal Gaussian policy: 2 observations, one hidden layer
// of 4, 2 actions (24 parameters; log sigma starts at -0.5), initialised from
// `seed`.
#pragma once

#include <cstdint>
#include <memory>

#include "core/rng.h"
#include "core/status.h"
#include "rl/mlp_policy.h"

inline squawk::Result<std::unique_ptr<squawk::rl::MlpPolicy>> small_gaussian(uint64_t seed) {
  squawk::rl::MlpPolicySpec spec;
  spec.obs_size = 2;
  spec.hidden = {4};
  spec.head = "gaussian";
  spec.action_size = 2;
  squawk::Rng init(seed);
  return squawk::rl::MlpPolicy::make(spec, init);
}
