#include "env/vec_env.h"

namespace squawk::env {

uint64_t episode_seed(uint64_t seed, uint64_t episode) {
  return seed * 0x9E3779B97F4A7C15ull + (episode + 1) * 0xD1B54A32D192ED03ull;
}

Result<VecEnv> VecEnv::make(const HorizontalCrConfig& config, int num_envs) {
  if (num_envs < 1)
    return Status::invalid("VecEnv: number of environments is " + std::to_string(num_envs) +
                           ", expected at least 1");
  std::vector<HorizontalCrEnv> envs;
  for (int i = 0; i < num_envs; ++i) {
    SQUAWK_ASSIGN_OR_RETURN(HorizontalCrEnv e, HorizontalCrEnv::make(config));
    envs.push_back(std::move(e));
  }
  return VecEnv(std::move(envs));
}

VecEnv::VecEnv(std::vector<HorizontalCrEnv> envs)
    : envs_(std::move(envs)), busy_(envs_.size(), 0), obs_size_(envs_[0].observation_size()) {}

void VecEnv::start(uint64_t seed, uint64_t first_episode, uint64_t count) {
  seed_ = seed;
  next_ = first_episode;
  end_ = first_episode + count;
  for (int s = 0; s < size(); ++s) {
    busy_[static_cast<size_t>(s)] = 0;
    refill(s);
  }
  collect_waiting();
}

void VecEnv::refill(int slot) {
  HorizontalCrEnv& e = env(slot);
  busy_[static_cast<size_t>(slot)] = 0;
  while (next_ < end_) {
    const uint64_t k = next_++;
    Rng rng(episode_seed(seed_, k));
    const bool decide = e.reset(rng, k);
    env_steps_ += e.stats().steps;
    if (decide) {
      busy_[static_cast<size_t>(slot)] = 1;
      return;
    }
    completed_.push_back(e.stats());
  }
}

void VecEnv::collect_waiting() {
  waiting_.clear();
  for (int s = 0; s < size(); ++s)
    if (busy_[static_cast<size_t>(s)]) waiting_.push_back(s);
  obs_.resize(waiting_.size() * static_cast<size_t>(obs_size_));
  for (size_t r = 0; r < waiting_.size(); ++r)
    env(waiting_[r]).observe_flat(
        std::span<float>(obs_).subspan(r * static_cast<size_t>(obs_size_), static_cast<size_t>(obs_size_)));
}

void VecEnv::step(std::span<const double> actions, std::span<double> rewards,
                  std::span<uint8_t> dones) {
  for (size_t r = 0; r < waiting_.size(); ++r) {
    const int s = waiting_[r];
    HorizontalCrEnv& e = env(s);
    const int before = e.stats().steps;
    rewards[r] = e.step(actions[r]);
    dones[r] = e.done() ? 1 : 0;
    env_steps_ += e.stats().steps - before;
    if (e.done()) {
      completed_.push_back(e.stats());
      refill(s);
    }
  }
  collect_waiting();
}

}  // namespace squawk::env
