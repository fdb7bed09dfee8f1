// LuaTeacher: a scripted controller (script/lua_policy.h, envs/policies/*.lua)
// as an rl::Policy on a LuaBatchEnv, the teacher of imitation (rl/imitation.h)
// for `squawk train --env ENV.lua --imitate POLICY.lua`.
//
// One instance of the file per slot of `envs`, each in its own Vm; an
// instance is reset (P:reset(seed), the seed the slot's episode was reset
// with) before the first decision of each episode its slot plays, so it
// decides exactly as `squawk env run ENV.lua --policy script:POLICY.lua`
// does on the same episode (from the observation rounded to floats).
// act() ignores greedy and rngs (the rule is deterministic) and answers in
// the batch's action numbers: continuous batches take the Box action mapped
// linearly onto [-1, 1] (box_action()'s inverse, index -1); grid batches the
// class of the grid point nearest to it per component (index and
// grid_value). act() is valid only for rows of `envs`'s waiting slots during
// its run. The first failure stays in error().
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rl/policy.h"
#include "script/lua_batch_env.h"
#include "script/lua_policy.h"

namespace squawk::script {

class LuaTeacher final : public rl::Policy {
 public:
  // Loads `path` once per slot of `envs` (which must outlive the teacher).
  static Result<std::unique_ptr<LuaTeacher>> load(const std::string& path, const VmOptions& options,
                                                  const LuaBatchEnv& envs);

  std::string name() const override { return "script:" + path_; }
  int obs_size() const override { return envs_.obs_size(); }
  void act(std::span<const float> obs, int n, std::span<const int> slots, std::span<Rng> rngs,
           bool greedy, std::span<rl::ActionSample> out) override;
  Status error() const override { return error_; }
  std::span<const double> action_values() const override { return values_; }

 private:
  LuaTeacher(std::string path, std::vector<std::unique_ptr<LuaPolicy>> rules,
             const LuaBatchEnv& envs);
  // The batch's action number (and class) of the Box action `a`.
  rl::ActionSample encode(std::span<const double> a) const;

  std::string path_;
  std::vector<std::unique_ptr<LuaPolicy>> rules_;  // per slot
  const LuaBatchEnv& envs_;
  std::vector<double> values_;  // grid_values(classes), empty when continuous
  std::vector<double> obs_, action_;
  Status error_;
};

}  // namespace squawk::script
