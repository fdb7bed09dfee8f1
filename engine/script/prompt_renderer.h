// PromptRenderer: the observation prompt template of a Lua file (e.g.
// prompts/observation.lua) behind a C++ call, for the GPT-2 prompt policy.
//
// The file runs once in its own sandboxed Vm and must return a table with
//   prefix   string: the text every prompt starts with (cached by the policy)
//   render   function(obs) -> string, obs = the eight named fields of
//            env::Observation as arrays of numbers (single values as
//            one-element arrays), keys as in env/observation.h.
// render() checks that each prompt starts with `prefix`. Errors name the file
// and carry Lua's message and traceback.
#pragma once

#include <memory>
#include <string>

#include "core/status.h"
#include "env/observation.h"
#include "script/vm.h"

struct lua_State;

namespace squawk::script {

// Pushes the observation as the table render() receives (and env:observation()
// returns): the eight named fields of env/observation.h, each an array of
// numbers (the single values as one-element arrays). One shape for both.
void push_observation(lua_State* L, const env::Observation& obs);

class PromptRenderer {
 public:
  static Result<std::shared_ptr<PromptRenderer>> load(const std::string& path, const VmOptions& options);
  ~PromptRenderer();
  PromptRenderer(const PromptRenderer&) = delete;
  PromptRenderer& operator=(const PromptRenderer&) = delete;

  const std::string& prefix() const { return prefix_; }
  const std::string& path() const { return path_; }
  Result<std::string> render(const env::Observation& obs);

 private:
  PromptRenderer(std::string path, std::unique_ptr<Vm> vm) : path_(std::move(path)), vm_(std::move(vm)) {}

  std::string path_;
  std::unique_ptr<Vm> vm_;
  int render_ref_ = -1;  // registry reference of the render function
  std::string prefix_;
};

}  // namespace squawk::script
