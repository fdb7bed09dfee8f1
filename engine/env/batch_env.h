// BatchEnv: a batch of environment slots stepped together, what rl::play,
// the evaluator and the learner drive. Two kinds: VecEnv (the compiled
// HorizontalCR kernel, env/vec_env.h) and script::LuaBatchEnv (environments
// written as Lua files, script/lua_batch_env.h).
//
// A run is a sequence of numbered episodes: start(seed, first, count) hands
// out episodes first..first+count-1 to the slots in order; a slot whose
// episode ends takes the next one and goes idle when none is left. Which
// episode number k of seed s is (its draws) is the implementation's, stated
// in its header; it never depends on the number of slots.
// Contract: observations() has one row of obs_size() floats per entry of
// waiting(), in the same order; step() takes one action of action_size()
// numbers per waiting slot (rl::ActionSample::component(0..): the
// implementation says what they mean) and writes each row's reward and
// whether its episode ended.
// An implementation whose step can fail (a Lua error) keeps the first error
// in error(), ends the run (finished() true) and does nothing more until the
// next start(); callers check error() after every step.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/status.h"
#include "env/horizontal_cr.h"

namespace squawk::env {

class VecEnv;

class BatchEnv {
 public:
  virtual ~BatchEnv() = default;

  virtual void start(uint64_t seed, uint64_t first_episode, uint64_t count) = 0;
  virtual int size() const = 0;      // [-] slots
  virtual int obs_size() const = 0;  // [-] floats per observation row

  // Slots waiting for a decision (ascending) and their observations [n, obs_size].
  virtual const std::vector<int>& waiting() const = 0;
  virtual std::span<const float> observations() const = 0;
  // Numbers per action: 1 unless an implementation takes vectors.
  virtual int action_size() const { return 1; }
  // actions [n, action_size()] row-major: row r goes to slot waiting()[r];
  // writes its reward and whether that slot's episode ended (1) into
  // rewards[r] / dones[r].
  virtual void step(std::span<const double> actions, std::span<double> rewards,
                    std::span<uint8_t> dones) = 0;
  // True when every episode of the run has ended (or the run failed).
  virtual bool finished() const = 0;
  // Ended episodes in the order they ended; the caller may clear it. Fields an
  // implementation does not know stay at their defaults (its header says which).
  virtual std::vector<EpisodeStats>& completed() = 0;
  // Total env steps taken since construction.
  virtual long long env_steps() const = 0;
  // The number of the episode `slot` plays (valid while it waits).
  virtual uint64_t episode(int slot) const = 0;
  // The first failure of the current run; ok for implementations that cannot fail.
  virtual Status error() const { return Status::ok(); }
  // The compiled HorizontalCR batch when this is one (what branching
  // learners and state-reading policies need), else nullptr.
  virtual VecEnv* horizontal() { return nullptr; }
};

}  // namespace squawk::env
