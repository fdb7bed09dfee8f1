// EpisodeStreams: one random stream per episode of a BatchEnv run. Episode k
// draws its policy samples from Rng(episode_seed(seed, k)) alone, so they do
// not depend on its slot, on the episodes beside it, or on the process of a
// data-parallel job that plays it (dist/comm.h): a batch of numbered episodes
// is the same however many slots or ranks share it.
// Use: before each Policy::act on envs.waiting(), rows(envs) gives the
// waiting slots' streams in order (a slot that began a new episode starts
// that episode's stream); pass them as act()'s rngs, then keep(envs) before
// envs.step().
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/rng.h"
#include "env/batch_env.h"

namespace squawk::rl {

class EpisodeStreams {
 public:
  explicit EpisodeStreams(uint64_t seed) : seed_(seed) {}

  // The streams of envs.waiting(), one per row.
  std::span<Rng> rows(const env::BatchEnv& envs);
  // Stores the streams rows() returned, as the policy left them, back to their slots.
  void keep(const env::BatchEnv& envs);

 private:
  uint64_t seed_;
  std::vector<Rng> slot_rng_;          // per slot
  std::vector<uint64_t> slot_episode_; // [-] the episode each slot's stream belongs to
  std::vector<uint8_t> slot_set_;      // 1 once the slot has a stream
  std::vector<Rng> rows_;
};

}  // namespace squawk::rl
