// LuaParallelBatchEnv: `num_envs` instances of one multi-agent environment
// file (script/lua_parallel_env.h) as an env::BatchEnv for parameter sharing:
// every agent of every instance is a row of the batch, and one agent's
// trajectory, from the reset to its termination or truncation, is one episode
// for the learner (as PettingZoo's parameter-sharing PPO treats it). One
// policy acts for all agents; the agents differ only in what they observe.
//
// Numbering: with A = max(agent_counts), learner episode k is agent a = k mod A
// of sector episode e = k div A. Sector episode e of seed s resets an
// instance with seed s + e and num_agents = agent_counts[i], i drawn from
// Rng(episode_seed(s ^ kAgentCountSalt, e)) (always 0 with one count); its
// agent a is the a-th name of E.agents after that reset. Numbers whose agent
// a >= num_agents are never played (the learner sees no sample of them;
// completed() leaves them out). start(seed, first, count) plays the sector
// episodes that hold any of first..first+count-1; an agent of such an episode
// whose number is outside that range flies uncommanded (absent from the
// actions table) and is no row, so that a batch whose bounds are multiples of
// A plays whole sector episodes. A sector episode ends for the batch when
// none of its agents in range is flying. Slot of agent a of instance i:
// i A + a; size() = num_envs A.
// Observations: each agent's numbers as floats; actions: a class of the
// action grid, as LuaBatchEnv (script/lua_batch_env.h).
// completed(): per agent trajectory, index (k), total_reward, decisions and
// steps (its length), reached (terminated), truncated (cut without
// termination) and success (its infos[name].success when it left; false when
// absent); min_separation stays 0. env_steps() counts sector steps.
// Errors (a Lua error, a broken return, an action off the grid) end the run:
// error() names the file, the function, the agent and the value.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/status.h"
#include "env/batch_env.h"
#include "script/lua_env.h"
#include "script/lua_parallel_env.h"
#include "script/vm.h"

namespace squawk::script {

inline constexpr uint64_t kAgentCountSalt = 0xA6E27C0DEull;

class LuaParallelBatchEnv final : public env::BatchEnv {
 public:
  // Loads `path` num_envs times (each instance its own Vm with `options`);
  // agent_counts: the num_agents a sector episode draws from (each >= 1).
  static Result<std::unique_ptr<LuaParallelBatchEnv>> make(const std::string& path,
                                                           const VmOptions& options, int num_envs,
                                                           int levels,
                                                           std::vector<int> agent_counts);

  const LuaEnvSpec& spec() const { return envs_[0].env->spec(); }
  int levels() const { return levels_; }
  int classes() const { return classes_; }
  int max_agents() const { return max_agents_; }
  // Sector episodes played since construction (each counted at its reset).
  long long sector_episodes() const { return sector_episodes_; }

  void start(uint64_t seed, uint64_t first_episode, uint64_t count) override;
  int size() const override { return static_cast<int>(envs_.size()) * max_agents_; }
  int obs_size() const override { return spec().observation_size; }
  const std::vector<int>& waiting() const override { return waiting_; }
  std::span<const float> observations() const override { return obs_; }
  void step(std::span<const double> actions, std::span<double> rewards,
            std::span<uint8_t> dones) override;
  bool finished() const override { return waiting_.empty(); }
  std::vector<env::EpisodeStats>& completed() override { return completed_; }
  long long env_steps() const override { return env_steps_; }
  uint64_t episode(int slot) const override;
  Status error() const override { return error_; }

 private:
  struct Instance {
    std::unique_ptr<LuaParallelEnv> env;
    bool busy = false;
    uint64_t sector = 0;                     // the sector episode it plays
    std::vector<int> agent;                  // per entry of env->agents(): its agent number a
    std::vector<env::EpisodeStats> running;  // per agent number: its trajectory so far
  };
  LuaParallelBatchEnv(std::vector<Instance> envs, int levels, int classes,
                      std::vector<int> agent_counts);
  // The learner's number of agent a of sector episode e.
  uint64_t number(uint64_t e, int a) const {
    return e * static_cast<uint64_t>(max_agents_) + static_cast<uint64_t>(a);
  }
  bool in_range(uint64_t e, int a) const { return number(e, a) >= first_ && number(e, a) < end_; }
  // Resets instance i with the next sector episode holding an agent in range, or leaves it idle.
  void refill(size_t i);
  void collect_waiting();
  void fail(Status st);

  std::vector<Instance> envs_;
  int levels_ = 0, classes_ = 0, max_agents_ = 0;
  std::vector<int> agent_counts_;
  std::vector<int> waiting_;
  std::vector<float> obs_;
  std::vector<int> row_entry_;  // per row: its position in its instance's env->agents()
  std::vector<env::EpisodeStats> completed_;
  std::vector<std::vector<double>> commands_;  // per entry of an instance's agents(): its action
  std::vector<int> commanded_;
  std::vector<AgentStep> out_;
  Status error_;
  uint64_t seed_ = 0, first_ = 0, end_ = 0, next_sector_ = 0, end_sector_ = 0;
  long long env_steps_ = 0, sector_episodes_ = 0;
};

}  // namespace squawk::script
