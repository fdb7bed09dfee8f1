// LuaEnv: a Gymnasium-shaped environment written as one Lua file (envs/*.lua)
// over the engine's C++ kernels (squawk.sim, squawk.geo), driven from C++.
//
// The file returns a table E (the contract, docs/gym_envs.md):
//   E.id                 string, e.g. "DescentEnv-v0"
//   E.source             string (optional): the definition it follows
//   E.observation        array of {name = "altitude", size = 1}: the flat
//                        observation's slices, in order
//   E.action             {low = {..}, high = {..}}: a Box of #low numbers
//   E.max_episode_steps  whole number >= 1 (gymnasium's TimeLimit)
//   E:reset(seed, options) -> obs [, info]
//   E:step(action)         -> obs, reward, terminated, truncated [, info]
// obs is an array of observation_size finite numbers; action an array of
// action_size numbers. info.success (optional boolean), read at an episode's
// last step, says whether the episode met the environment's own notion of
// success (each file documents it). The driver adds the TimeLimit: truncated once
// max_episode_steps steps ran without termination. Every call into the file
// runs under the Vm's budget (a fresh one per call); Lua errors and contract
// violations come back as Status naming the file, the function and the value.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/status.h"
#include "script/vm.h"

namespace squawk::script {

struct LuaEnvSpec {
  struct Field {
    std::string name;
    int size = 0;
  };
  std::string id;
  std::string source;
  std::vector<Field> observation;
  int observation_size = 0;                     // sum of the fields' sizes
  std::vector<double> action_low, action_high;  // the Box, action_size each
  int max_episode_steps = 0;
  bool parallel = false;  // E.parallel: multi-agent (script/lua_parallel_env.h)
  int action_size() const { return static_cast<int>(action_low.size()); }
};

struct LuaStep {
  double reward = 0.0;
  bool terminated = false;
  bool truncated = false;  // the file's own, or the driver's TimeLimit
  // info.success of the episode's last step (terminated or truncated);
  // empty on other steps and when the file's info has no `success`.
  std::optional<bool> success;
};

// The declaration of the environment table at stack index `idx` (id, source,
// parallel, observation, action, max_episode_steps; the stack is left as it
// was); errors name `path` and the field that is missing or malformed.
Result<LuaEnvSpec> read_env_spec(lua_State* L, int idx, const std::string& path);
// Stores the table's reset and step functions at `idx` in the registry under
// the two keys (read once, so no metamethod of the table runs outside a
// protected call); error naming `path` unless both are functions.
Status store_env_functions(lua_State* L, int idx, const std::string& path, const char* reset_key,
                           const char* step_key);

class LuaEnv {
 public:
  // Loads `path` in a fresh Vm with `options`; errors name the file and the
  // declaration that is missing or malformed.
  static Result<std::unique_ptr<LuaEnv>> load(const std::string& path, const VmOptions& options);
  ~LuaEnv();
  LuaEnv(const LuaEnv&) = delete;
  LuaEnv& operator=(const LuaEnv&) = delete;

  const LuaEnvSpec& spec() const { return spec_; }
  const std::string& path() const { return path_; }
  // E:reset(seed); the observation is then observation().
  Status reset(uint64_t seed);
  // E:step(action); error when action has not action_size numbers.
  Result<LuaStep> step(std::span<const double> action);
  const std::vector<double>& observation() const { return obs_; }
  int steps() const { return steps_; }  // steps since the last reset
  Vm& vm() { return *vm_; }

 private:
  LuaEnv(std::string path, std::unique_ptr<Vm> vm) : path_(std::move(path)), vm_(std::move(vm)) {}
  Status read_spec();
  // Reads the observation array at stack index `idx` into obs_.
  Status read_observation(int idx, const char* fn);
  // The per-step path of read_observation: a table without metatable of
  // observation_size finite numbers, read raw; false (obs_ partly written)
  // sends the caller to the checked path, which names what is wrong.
  bool read_plain_observation(int idx);
  // info.success of the info table at stack index `idx` (absent: none).
  Status read_success(int idx, LuaStep& r);

  std::string path_;
  std::unique_ptr<Vm> vm_;
  LuaEnvSpec spec_;
  std::vector<double> obs_;
  int steps_ = 0;
  bool started_ = false;  // reset has succeeded at least once
};

}  // namespace squawk::script
