// LuaBatchEnv: `num_envs` instances of one environment file written in Lua
// (script/lua_env.h), each in its own sandboxed Vm, as an env::BatchEnv that
// rl::play, the evaluator and the learner drive.
//
// Episodes: episode k of seed s resets its slot's instance with seed s + k
// (as `squawk env run --seed s` numbers them) and runs until the file
// terminates or truncates it (its own flag, or max_episode_steps).
// Observations: the file's numbers as floats.
// Actions: the declared Box discretised into K = levels evenly spaced values
// per component, low .. high (K >= 2; an odd K holds the box's centre); an
// action is a class c = 0 .. C - 1 of the grid of C = K^d points (d =
// action_size), component j at level (c / K^j) mod K (grid_action()). step()
// takes class c as the number grid_value(c, C) = -1 + 2 c / (C - 1): a
// categorical head whose action_values are grid_values(C) gives exactly
// that, and for a one-component Box [-1, 1] the number is the action itself.
// Continuous (levels 0, a Box of d <= rl::kMaxActionSize components):
// action_size() is d and step() takes d numbers v per slot, each clipped to
// [-1, 1] and mapped linearly onto its component's [low, high] (box_action();
// a Gaussian head's raw sample).
// completed(): index, total_reward, decisions and steps (both the episode's
// length in steps), truncated (cut without termination) and reached (the file
// terminated it); success stays false and min_separation 0 (the files define
// neither).
// Errors (a Lua error, a broken return, an action index off the grid) end
// the run: error() names the file, the function and the value.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/status.h"
#include "env/batch_env.h"
#include "script/lua_env.h"
#include "script/vm.h"

namespace squawk::script {

inline constexpr int kMaxGridClasses = 4096;  // [-] K^d at most (the categorical head's width)

// K^d for K = levels and d = spec's action_size; error unless levels >= 2
// and K^d <= kMaxGridClasses.
Result<int> grid_classes(const LuaEnvSpec& spec, int levels);
// The K with K^d == classes (d = spec's action_size), or an error naming both.
Result<int> grid_levels(const LuaEnvSpec& spec, int classes);
// Writes the Box action of grid class `index` (0 <= index < K^d) into out [d].
void grid_action(const LuaEnvSpec& spec, int levels, int index, std::span<double> out);
// Continuous actions: out[j] = low_j + (high_j - low_j) (clip(v[j], -1, 1) + 1) / 2
// for each of spec's d Box components (v and out have size d).
void box_action(const LuaEnvSpec& spec, std::span<const double> v, std::span<double> out);
// Ok when a continuous head can drive spec's Box (1 to rl::kMaxActionSize
// components), else an error naming the file and the count.
Status check_continuous(const LuaEnvSpec& spec, const std::string& path);
// Class c of C as the number in [-1, 1] that step() takes, and all C of them in order.
double grid_value(int c, int classes);
std::vector<double> grid_values(int classes);
// The class whose grid_value is within 1e-4 of v, or -1.
int grid_class(double v, int classes);

class LuaBatchEnv final : public env::BatchEnv {
 public:
  // Loads `path` num_envs times (each instance its own Vm with `options`).
  // levels 0: continuous actions (check_continuous()).
  static Result<std::unique_ptr<LuaBatchEnv>> make(const std::string& path,
                                                   const VmOptions& options, int num_envs,
                                                   int levels);

  const LuaEnvSpec& spec() const { return envs_[0]->spec(); }
  int levels() const { return levels_; }
  int classes() const { return classes_; }  // 0 when continuous
  bool continuous() const { return levels_ == 0; }

  void start(uint64_t seed, uint64_t first_episode, uint64_t count) override;
  int size() const override { return static_cast<int>(envs_.size()); }
  int obs_size() const override { return spec().observation_size; }
  int action_size() const override { return continuous() ? spec().action_size() : 1; }
  const std::vector<int>& waiting() const override { return waiting_; }
  std::span<const float> observations() const override { return obs_; }
  void step(std::span<const double> actions, std::span<double> rewards,
            std::span<uint8_t> dones) override;
  bool finished() const override { return waiting_.empty(); }
  std::vector<env::EpisodeStats>& completed() override { return completed_; }
  long long env_steps() const override { return env_steps_; }
  uint64_t episode(int slot) const override { return running_[static_cast<size_t>(slot)].index; }
  Status error() const override { return error_; }
  // The episode `slot` plays (valid while it waits): the steps it has taken
  // and the seed its instance was reset with (seed s + k, as above).
  long long steps(int slot) const { return running_[static_cast<size_t>(slot)].steps; }
  uint64_t reset_seed(int slot) const { return seed_ + running_[static_cast<size_t>(slot)].index; }

 private:
  LuaBatchEnv(std::vector<std::unique_ptr<LuaEnv>> envs, int levels, int classes);
  // Resets `slot` with the next episode, or leaves it idle when none is left.
  void refill(int slot);
  void collect_waiting();
  void fail(Status st);

  std::vector<std::unique_ptr<LuaEnv>> envs_;
  int levels_ = 0, classes_ = 0;
  std::vector<uint8_t> busy_;
  std::vector<env::EpisodeStats> running_;  // per slot: the episode it plays
  std::vector<int> waiting_;
  std::vector<float> obs_;
  std::vector<double> action_;  // [d] the decoded action
  std::vector<env::EpisodeStats> completed_;
  Status error_;
  uint64_t seed_ = 0, next_ = 0, end_ = 0;
  long long env_steps_ = 0;
};

}  // namespace squawk::script
