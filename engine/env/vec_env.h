// VecEnv: N copies of HorizontalCrEnv stepped together, for batched policies:
// the compiled env::BatchEnv (env/batch_env.h).
//
// A run is a sequence of numbered episodes. Episode k of a run with seed s
// draws its scenario from Rng(episode_seed(s, k)), so an episode is the same
// whatever the number of slots, and one seed gives one sequence of episodes.
// start() hands out episodes first..first+count-1 to the slots in order; a
// slot whose episode ends takes the next one (episodes that end without a
// decision, possible under the paper rules, are completed on the way), and
// goes idle when none is left.
// Contract: observations() has one row of obs_size() floats per entry of
// waiting(), in the same order; step() takes one action per waiting slot.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/rng.h"
#include "env/batch_env.h"
#include "env/horizontal_cr.h"

namespace squawk::env {

uint64_t episode_seed(uint64_t seed, uint64_t episode);

class VecEnv final : public BatchEnv {
 public:
  static Result<VecEnv> make(const HorizontalCrConfig& config, int num_envs);

  void start(uint64_t seed, uint64_t first_episode, uint64_t count) override;
  int size() const override { return static_cast<int>(envs_.size()); }
  int obs_size() const override { return obs_size_; }

  // Slots waiting for a decision (ascending) and their observations [n, obs_size].
  const std::vector<int>& waiting() const override { return waiting_; }
  std::span<const float> observations() const override { return obs_; }

  // actions[r] (units of the heading step) goes to slot waiting()[r]; writes
  // its reward and whether that slot's episode ended (1) into rewards[r] / dones[r].
  void step(std::span<const double> actions, std::span<double> rewards,
            std::span<uint8_t> dones) override;

  // True when every episode of the batch has ended.
  bool finished() const override { return waiting_.empty(); }
  // Stats of ended episodes in the order they ended; the caller may clear it.
  std::vector<EpisodeStats>& completed() override { return completed_; }
  // Total env steps (agent and automatic) taken since make().
  long long env_steps() const override { return env_steps_; }
  uint64_t episode(int slot) const override { return env(slot).stats().index; }
  VecEnv* horizontal() override { return this; }

  HorizontalCrEnv& env(int slot) { return envs_[static_cast<size_t>(slot)]; }
  const HorizontalCrEnv& env(int slot) const { return envs_[static_cast<size_t>(slot)]; }

 private:
  explicit VecEnv(std::vector<HorizontalCrEnv> envs);
  // Gives `slot` episodes until one needs a decision or none is left.
  void refill(int slot);
  void collect_waiting();

  std::vector<HorizontalCrEnv> envs_;
  std::vector<uint8_t> busy_;
  std::vector<int> waiting_;
  std::vector<float> obs_;
  std::vector<EpisodeStats> completed_;
  int obs_size_ = 0;
  uint64_t seed_ = 0, next_ = 0, end_ = 0;
  long long env_steps_ = 0;
};

}  // namespace squawk::env
