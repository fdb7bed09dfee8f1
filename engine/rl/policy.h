// Policy: what the learner and the evaluator drive. Batched.
//
// Shapes: obs [n, obs_size()] row-major floats (the flat observation of
// env/observation.h), one ActionSample per row.
// An action's `value` is what the environment receives (units of 45 deg,
// clipped to [-1, 1] by the environment); `index` is the class of a discrete
// head (-1 for continuous heads, whose `value` is the raw Gaussian sample).
// A continuous head over D > 1 components (a diagonal Gaussian) puts
// component 0 in `value` and components 1..D-1 in `more` (component()).
// `slots` names the VecEnv slot of each row, for policies that read the
// environment's state rather than the observation (MVP).
// Trainable policies expose one contiguous parameter buffer and its gradient
// buffer (same length) for nn::Adam and checkpoints.
#pragma once

#include <array>
#include <span>
#include <string>

#include "core/rng.h"
#include "core/status.h"

namespace squawk::rl {

inline constexpr int kMaxActionSize = 4;  // [-] components of a continuous action at most

struct ActionSample {
  int index = -1;      // [-] class of a discrete head, -1 when continuous
  float value = 0.0f;  // [-] action in units of the env's heading step (component 0)
  std::array<float, kMaxActionSize - 1> more{};  // [-] components 1.. of a vector action

  float component(int j) const { return j == 0 ? value : more[static_cast<size_t>(j - 1)]; }
  float& component(int j) { return j == 0 ? value : more[static_cast<size_t>(j - 1)]; }
};

class Policy {
 public:
  virtual ~Policy() = default;
  virtual std::string name() const = 0;
  virtual int obs_size() const = 0;

  // Fills out[0..n) for obs [n, obs_size]. greedy: the distribution's mode
  // instead of a sample. rngs: the rows' random streams, one per row (size n:
  // row r draws from rngs[r] only, so a row's sample does not depend on the
  // other rows) or one the rows draw from in turn (size 1); see row_rng().
  virtual void act(std::span<const float> obs, int n, std::span<const int> slots, std::span<Rng> rngs,
                   bool greedy, std::span<ActionSample> out) = 0;

  // A policy whose decisions can fail (a Lua prompt template) keeps the first
  // failure here; callers check it after a run.
  virtual Status error() const { return Status::ok(); }

  virtual bool trainable() const { return false; }
  virtual std::span<float> params() { return {}; }
  virtual std::span<float> grads() { return {}; }
  // Adds to grads() the gradient of
  //   L = -sum_r coef[r] log pi(a_r | s_r) - ent_coef sum_r H(pi(. | s_r))
  // over the n rows, and returns the mean entropy of those rows (0 when n = 0:
  // a rank of a data-parallel job with no samples still calls it before the
  // optimiser step, so a policy that caches results of its parameters drops them).
  virtual float accumulate_gradient(std::span<const float> /*obs*/, int /*n*/,
                                    std::span<const ActionSample> /*actions*/,
                                    std::span<const float> /*coef*/, float /*ent_coef*/) {
    return 0.0f;
  }
  // Policies that can score given actions (the clipped-ratio learner needs
  // it) return true and fill out[r] = log pi(actions[r] | obs row r).
  virtual bool has_log_probs() const { return false; }
  // A discrete head's action value per class index (what act() puts in
  // ActionSample::value); empty for continuous heads.
  virtual std::span<const double> action_values() const { return {}; }
  virtual void log_probs(std::span<const float> /*obs*/, int /*n*/,
                         std::span<const ActionSample> /*actions*/, std::span<float> /*out*/) {}
};

// The stream row r draws from under act()'s `rngs` contract.
inline Rng& row_rng(std::span<Rng> rngs, int r) { return rngs.size() == 1 ? rngs[0] : rngs[static_cast<size_t>(r)]; }

// Ok when `policy` reads observations of `obs_size` values, else an error
// naming both sizes.
Status check_obs_size(const Policy& policy, int obs_size);

}  // namespace squawk::rl
