#include "script/lua_teacher.h"

#include <algorithm>
#include <cmath>

namespace squawk::script {

Result<std::unique_ptr<LuaTeacher>> LuaTeacher::load(const std::string& path,
                                                     const VmOptions& options,
                                                     const LuaBatchEnv& envs) {
  std::vector<std::unique_ptr<LuaPolicy>> rules;
  for (int s = 0; s < envs.size(); ++s) {
    SQUAWK_ASSIGN_OR_RETURN(auto p, LuaPolicy::load(path, options, envs.spec()));
    rules.push_back(std::move(p));
  }
  return std::unique_ptr<LuaTeacher>(new LuaTeacher(path, std::move(rules), envs));
}

LuaTeacher::LuaTeacher(std::string path, std::vector<std::unique_ptr<LuaPolicy>> rules,
                       const LuaBatchEnv& envs)
    : path_(std::move(path)),
      rules_(std::move(rules)),
      envs_(envs),
      values_(envs.continuous() ? std::vector<double>{} : grid_values(envs.classes())),
      obs_(static_cast<size_t>(envs.obs_size())),
      action_(static_cast<size_t>(envs.spec().action_size())) {}

rl::ActionSample LuaTeacher::encode(std::span<const double> a) const {
  const LuaEnvSpec& spec = envs_.spec();
  // Component j's position in its Box, 0 (low) .. 1 (high).
  const auto unit = [&](size_t j) {
    const double w = spec.action_high[j] - spec.action_low[j];
    return w > 0.0 ? std::clamp((a[j] - spec.action_low[j]) / w, 0.0, 1.0) : 0.5;
  };
  if (envs_.continuous()) {  // every component, each mapped onto [-1, 1]
    rl::ActionSample s{-1, 0.0f};
    for (size_t j = 0; j < a.size(); ++j)
      s.component(static_cast<int>(j)) = static_cast<float>(2.0 * unit(j) - 1.0);
    return s;
  }
  const int k = envs_.levels();
  int c = 0, place = 1;
  for (size_t j = 0; j < a.size(); ++j, place *= k)
    c += place * static_cast<int>(std::lround(unit(j) * (k - 1)));
  return {c, static_cast<float>(grid_value(c, envs_.classes()))};
}

void LuaTeacher::act(std::span<const float> obs, int n, std::span<const int> slots,
                     std::span<Rng> /*rngs*/, bool /*greedy*/, std::span<rl::ActionSample> out) {
  const size_t d = obs_.size();
  for (int r = 0; r < n && error_.is_ok(); ++r) {
    const int slot = slots[static_cast<size_t>(r)];
    LuaPolicy& rule = *rules_[static_cast<size_t>(slot)];
    if (envs_.steps(slot) == 0) error_ = rule.reset(envs_.reset_seed(slot));
    std::copy_n(obs.begin() + static_cast<long>(static_cast<size_t>(r) * d), d, obs_.begin());
    if (error_.is_ok()) error_ = rule.act(obs_, action_);
    if (error_.is_ok()) out[static_cast<size_t>(r)] = encode(action_);
  }
}

}  // namespace squawk::script
