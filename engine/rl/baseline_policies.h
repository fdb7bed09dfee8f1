// Reference policies with no parameters.
//   ConstantPolicy: plays one action value whatever the state (0 = never
//     turn); the baselines that reveal a policy which learned one constant turn.
//     With When::on_track, the turn-hold rule: the value while the ownship
//     flies at its waypoint (|drift| < 2.5 deg, read from cos_drift in the flat
//     observation), otherwise hold the heading (0); the rule-based baseline of
//     "turn off the conflict once, then wait it out".
//   MvpPolicy:  BlueSky's MVP resolution steering the ownship
//     (HorizontalCrEnv::mvp_action, a continuous action in [-1, 1]); it reads
//     the true state of the VecEnv slot of each row, not the observation.
//   LookaheadPolicy: a planner over the simulator, the reference for what a
//     policy of this state can reach. At each decision it copies the slot's
//     environment and, for every action a of `actions` and every base rule b
//     (each constant action of `actions`, and MVP), plays a and then b at
//     every later decision to the episode's end; it takes the a of the best
//     branch, scored by success first, then the episode's reward minus its
//     intrusion count. Deterministic; it reads the true state and the future
//     (the intruders fly straight), so it is no learnable policy of the
//     observation: an upper reference, not a baseline to beat.
//     Cost: K (K + 1) rollouts to the episode's end per decision.
#pragma once

#include <vector>

#include "rl/policy.h"
#include "rl/state_policy.h"

namespace squawk::rl {

class ConstantPolicy : public Policy {
 public:
  enum class When { always, on_track };
  // value: [-] in units of the heading step; obs_size = 3 + 5 n.
  ConstantPolicy(int obs_size, float value, When when = When::always)
      : obs_size_(obs_size), value_(value), when_(when) {}
  std::string name() const override;
  int obs_size() const override { return obs_size_; }
  void act(std::span<const float> obs, int n, std::span<const int> slots, std::span<Rng> rngs, bool greedy,
           std::span<ActionSample> out) override;

 private:
  int obs_size_;
  float value_;
  When when_;
};

class MvpPolicy : public StatePolicy {
 public:
  using StatePolicy::StatePolicy;
  std::string name() const override { return "mvp"; }
  void act(std::span<const float> obs, int n, std::span<const int> slots, std::span<Rng> rngs, bool greedy,
           std::span<ActionSample> out) override;
};

class LookaheadPolicy : public StatePolicy {
 public:
  // actions: [-] the discrete action values, units of the heading step.
  LookaheadPolicy(const env::VecEnv& envs, std::vector<double> actions)
      : StatePolicy(envs), actions_(std::move(actions)) {}
  std::string name() const override { return "lookahead"; }
  void act(std::span<const float> obs, int n, std::span<const int> slots, std::span<Rng> rngs, bool greedy,
           std::span<ActionSample> out) override;

 private:
  std::vector<double> actions_;
};

}  // namespace squawk::rl
