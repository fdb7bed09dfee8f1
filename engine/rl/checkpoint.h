// Checkpoints of an MLP policy and its optimiser, written atomically
// (core/files.h write_atomic: temp file + rename) and read back with checks.
//
// Format (version 1):
//   line 1: "squawk-checkpoint 1"
//   line 2: a JSON object: policy spec (obs_size, hidden, head, action_values),
//           num_params, has_adam, adam_t, and the training progress
//           (episodes, updates, seed, estimator, scenario, wall_s, and the
//           open log interval's interval_return, interval_success,
//           interval_updates)
//   then raw little-endian float32: params[num_params], and when has_adam
//   Adam's m[num_params] and v[num_params]; then, when num_value_params > 0,
//   the learner's value baseline: params, Adam m, Adam v (num_value_params each).
// Errors name the file and what was expected vs found.
#pragma once

#include <string>
#include <vector>

#include "core/status.h"
#include "rl/mlp_policy.h"

namespace squawk::rl {

struct TrainProgress {
  long long episodes = 0;  // [-] training episodes finished
  long long updates = 0;   // [-] optimiser steps taken
  unsigned long long seed = 0;
  std::string estimator;   // "vpg" | "improved" | "ppo" | "vine"
  std::string scenario;    // the scenario file trained on
  double wall_s = 0.0;     // [s] training wall time so far
  // The open log.csv interval, whose row averages the training columns over
  // its updates, so that a resumed run writes the row an uninterrupted one
  // would: sums of the updates' mean returns and success rates, and their count.
  double interval_return = 0.0;
  double interval_success = 0.0;
  long long interval_updates = 0;
};

// The learner's state every checkpoint kind carries, so that --resume
// continues exactly: parameters, Adam moments (when has_adam), the value
// baseline of the improved estimator with its Adam state (empty when none),
// and the training counters.
struct TrainState {
  std::vector<float> params;
  bool has_adam = false;
  long long adam_t = 0;
  std::vector<float> adam_m, adam_v;
  std::vector<float> value_params, value_m, value_v;
  long long value_t = 0;
  TrainProgress progress;
};

struct Checkpoint : TrainState {
  MlpPolicySpec spec;
};

Status save_checkpoint(const std::string& path, const Checkpoint& ckpt);
Result<Checkpoint> load_checkpoint(const std::string& path);

// A policy with the checkpoint's spec and parameters; error when the
// parameter count does not fit the spec.
Result<std::unique_ptr<MlpPolicy>> policy_from_checkpoint(const Checkpoint& ckpt);

}  // namespace squawk::rl
