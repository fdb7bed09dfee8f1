// Reference policies with no parameters.
//   ZeroPolicy: never turns (action 0).
//   MvpPolicy:  BlueSky's MVP resolution steering the ownship
//     (HorizontalCrEnv::mvp_action, a continuous action in [-1, 1]); it reads
//     the true state of the VecEnv slot of each row, not the observation.
#pragma once

#include "env/vec_env.h"
#include "rl/policy.h"

namespace squawk::rl {

class ZeroPolicy : public Policy {
 public:
  explicit ZeroPolicy(int obs_size) : obs_size_(obs_size) {}
  std::string name() const override { return "zero"; }
  int obs_size() const override { return obs_size_; }
  void act(std::span<const float> obs, int n, std::span<const int> slots, Rng& rng, bool greedy,
           std::span<ActionSample> out) override;

 private:
  int obs_size_;
};

class MvpPolicy : public Policy {
 public:
  explicit MvpPolicy(const env::VecEnv& envs) : envs_(envs) {}
  std::string name() const override { return "mvp"; }
  int obs_size() const override { return envs_.obs_size(); }
  void act(std::span<const float> obs, int n, std::span<const int> slots, Rng& rng, bool greedy,
           std::span<ActionSample> out) override;

 private:
  const env::VecEnv& envs_;
};

}  // namespace squawk::rl
