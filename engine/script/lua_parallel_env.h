// LuaParallelEnv: a multi-agent environment written as one Lua file in
// PettingZoo's parallel API shape (envs/sector_multi.lua, docs/gym_envs.md),
// driven from C++.
//
// The file declares `parallel = true` and LuaEnv's fields (script/lua_env.h),
// its observation and action per agent, and
//   E:reset(seed, {num_agents = n}) -> observations [, infos]
//   E:step(actions)                 -> observations, rewards, terminations, truncations [, infos]
// with tables keyed by agent name; E.agents lists the agents still flying
// (read after every call, in its order). reset's observations hold every
// agent of E.agents; step's results hold every agent that was in E.agents
// before the step, and an agent whose termination or truncation is true
// leaves. actions[name] is an array of action_size numbers; an agent absent
// from `actions` gets no command. infos[name].success (optional boolean), read
// when the agent leaves, says whether it met the file's notion of success. The
// driver adds the TimeLimit: after max_episode_steps steps every agent still
// in E.agents is truncated. Each call runs under a fresh instruction budget;
// errors name the file, the function, the agent and the value.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/status.h"
#include "script/lua_env.h"
#include "script/vm.h"

namespace squawk::script {

// What one step did to one agent of the step's agents().
struct AgentStep {
  double reward = 0.0;
  bool terminated = false;
  bool truncated = false;       // the file's own, or the driver's TimeLimit
  std::optional<bool> success;  // infos[name].success when the agent left
};

class LuaParallelEnv {
 public:
  // Loads `path` in a fresh Vm with `options`; error unless the file declares parallel = true.
  static Result<std::unique_ptr<LuaParallelEnv>> load(const std::string& path,
                                                      const VmOptions& options);
  ~LuaParallelEnv();
  LuaParallelEnv(const LuaParallelEnv&) = delete;
  LuaParallelEnv& operator=(const LuaParallelEnv&) = delete;

  const LuaEnvSpec& spec() const { return spec_; }
  const std::string& path() const { return path_; }
  // E:reset(seed, {num_agents = n}): agents() then holds E.agents, observation(r) theirs.
  Status reset(uint64_t seed, int num_agents);
  // E:step(actions) with actions[name(a)] = commands[a] for the entries of
  // `commanded` (indices into agents(), commands[a] action_size numbers);
  // out[a] is what happened to agents()[a] as they were before the step
  // (out: that many entries); then agents() is the new E.agents, exactly
  // those that neither terminated nor truncated, with their observations.
  Status step(std::span<const int> commanded, std::span<const std::vector<double>> commands,
              std::vector<AgentStep>& out);
  // The agents flying, in E.agents' order, and their observations [obs_size] each.
  const std::vector<std::string>& agents() const { return agents_; }
  std::span<const double> observation(size_t a) const;
  // Per agent of agents(): its position in agents() before the last step (after reset: its own).
  const std::vector<int>& kept() const { return kept_; }
  int steps() const { return steps_; }  // steps since the last reset
  Vm& vm() { return *vm_; }

 private:
  LuaParallelEnv(std::string path, std::unique_ptr<Vm> vm)
      : path_(std::move(path)), vm_(std::move(vm)) {}
  // Reads E.agents into agents_.
  Status read_agents(const char* fn);
  // Reads obs[name] of every agent of `names` from the table at `idx` into obs_.
  Status read_observations(int idx, const std::vector<std::string>& names, const char* fn);

  std::string path_;
  std::unique_ptr<Vm> vm_;
  LuaEnvSpec spec_;
  std::vector<std::string> agents_;
  std::vector<double> obs_;  // [agents_, obs_size]
  std::vector<int> kept_;    // [agents_]
  int steps_ = 0;
  bool started_ = false;
};

// Whether the environment file at `path` declares parallel = true (loads it in a Vm with
// `options`).
Result<bool> is_parallel_env(const std::string& path, const VmOptions& options);

}  // namespace squawk::script
