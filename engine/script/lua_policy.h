// LuaPolicy: a scripted controller for a LuaEnv, written as one Lua file
// (envs/policies/*.lua), driven from C++ (`squawk env run --policy script:FILE`).
//
// The file returns a table P (docs/gym_envs.md):
//   P.env           string (optional): the id of the environment it reads;
//                   load refuses another environment
//   P:act(obs)   -> action: obs is a fresh array of the environment's
//                   observation_size numbers, action an array of action_size
//                   finite numbers inside the declared Box
//   P:reset(seed)   (optional) called before each episode with its seed
// The file runs in its own sandboxed Vm (it cannot see the environment's
// state) with a fresh instruction budget per call; errors name the file, the
// function and the value.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/status.h"
#include "script/lua_env.h"
#include "script/vm.h"

namespace squawk::script {

class LuaPolicy {
 public:
  // Loads `path` in a fresh Vm with `options` for an environment of `spec`.
  static Result<std::unique_ptr<LuaPolicy>> load(const std::string& path, const VmOptions& options,
                                                 const LuaEnvSpec& spec);
  ~LuaPolicy();
  LuaPolicy(const LuaPolicy&) = delete;
  LuaPolicy& operator=(const LuaPolicy&) = delete;

  // P:reset(seed) when the file has one.
  Status reset(uint64_t seed);
  // P:act(obs) into `action` (action_size numbers).
  Status act(std::span<const double> obs, std::span<double> action);
  const std::string& path() const { return path_; }

 private:
  LuaPolicy(std::string path, std::unique_ptr<Vm> vm, LuaEnvSpec spec)
      : path_(std::move(path)), vm_(std::move(vm)), spec_(std::move(spec)) {}
  Status read_fields();

  std::string path_;
  std::unique_ptr<Vm> vm_;
  LuaEnvSpec spec_;
  bool has_reset_ = false;
};

}  // namespace squawk::script
