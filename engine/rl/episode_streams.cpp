#include "rl/episode_streams.h"

#include "env/vec_env.h"

namespace squawk::rl {

std::span<Rng> EpisodeStreams::rows(const env::BatchEnv& envs) {
  const auto slots = static_cast<size_t>(envs.size());
  if (slot_rng_.size() != slots) {
    slot_rng_.assign(slots, Rng());
    slot_episode_.assign(slots, 0);
    slot_set_.assign(slots, 0);
  }
  rows_.clear();
  for (int s : envs.waiting()) {
    const auto i = static_cast<size_t>(s);
    const uint64_t k = envs.episode(s);
    if (!slot_set_[i] || slot_episode_[i] != k) {
      slot_rng_[i] = Rng(env::episode_seed(seed_, k));
      slot_episode_[i] = k;
      slot_set_[i] = 1;
    }
    rows_.push_back(slot_rng_[i]);
  }
  return rows_;
}

void EpisodeStreams::keep(const env::BatchEnv& envs) {
  const std::vector<int>& waiting = envs.waiting();
  for (size_t r = 0; r < waiting.size() && r < rows_.size(); ++r) slot_rng_[static_cast<size_t>(waiting[r])] = rows_[r];
}

}  // namespace squawk::rl
