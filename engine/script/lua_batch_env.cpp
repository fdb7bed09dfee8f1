#include "script/lua_batch_env.h"

#include <algorithm>
#include <cmath>

#include "rl/policy.h"

namespace squawk::script {

Result<int> grid_classes(const LuaEnvSpec& spec, int levels) {
  if (levels < 2)
    return Status::invalid("action levels " + std::to_string(levels) +
                           ": expected at least 2 per component");
  long long c = 1;
  for (int j = 0; j < spec.action_size(); ++j) {
    c *= levels;
    if (c > kMaxGridClasses)
      return Status::invalid(spec.id + ": " + std::to_string(levels) + " levels for each of " +
                             std::to_string(spec.action_size()) +
                             " action components make more than " +
                             std::to_string(kMaxGridClasses) + " classes");
  }
  return static_cast<int>(c);
}

Result<int> grid_levels(const LuaEnvSpec& spec, int classes) {
  const int d = spec.action_size();
  const auto k = static_cast<int>(std::lround(std::pow(static_cast<double>(classes), 1.0 / d)));
  if (k >= 2) {
    auto c = grid_classes(spec, k);
    if (c && *c == classes) return k;
  }
  return Status::invalid("a policy of " + std::to_string(classes) +
                         " action classes does not fit " + spec.id + "'s " + std::to_string(d) +
                         " action components (expected K^" + std::to_string(d) +
                         " classes, K >= 2 levels each)");
}

void grid_action(const LuaEnvSpec& spec, int levels, int index, std::span<double> out) {
  for (size_t j = 0; j < out.size(); ++j) {
    const int level = index % levels;
    index /= levels;
    const double lo = spec.action_low[j], hi = spec.action_high[j];
    out[j] = level == levels - 1 ? hi : lo + (hi - lo) * level / (levels - 1);
  }
}

void box_action(const LuaEnvSpec& spec, std::span<const double> v, std::span<double> out) {
  for (size_t j = 0; j < out.size(); ++j) {
    const double u = (std::clamp(v[j], -1.0, 1.0) + 1.0) / 2.0;
    out[j] = spec.action_low[j] + (spec.action_high[j] - spec.action_low[j]) * u;
  }
}

Status check_continuous(const LuaEnvSpec& spec, const std::string& path) {
  if (spec.action_size() <= rl::kMaxActionSize) return Status::ok();
  return Status::invalid(path + ": continuous actions need a Box of at most " +
                         std::to_string(rl::kMaxActionSize) + " components; " + spec.id + " has " +
                         std::to_string(spec.action_size()));
}

double grid_value(int c, int classes) {
  return -1.0 + 2.0 * c / (classes - 1);
}

std::vector<double> grid_values(int classes) {
  std::vector<double> v(static_cast<size_t>(classes));
  for (int c = 0; c < classes; ++c) v[static_cast<size_t>(c)] = grid_value(c, classes);
  return v;
}

int grid_class(double v, int classes) {
  if (!(v >= -1.5 && v <= 1.5)) return -1;
  const auto c = static_cast<int>(std::lround((v + 1.0) * (classes - 1) / 2.0));
  return c >= 0 && c < classes && std::abs(grid_value(c, classes) - v) < 1e-4 ? c : -1;
}

Result<std::unique_ptr<LuaBatchEnv>> LuaBatchEnv::make(const std::string& path,
                                                       const VmOptions& options, int num_envs,
                                                       int levels) {
  if (num_envs < 1)
    return Status::invalid(path + ": number of environments is " + std::to_string(num_envs) +
                           ", expected at least 1");
  std::vector<std::unique_ptr<LuaEnv>> envs;
  for (int i = 0; i < num_envs; ++i) {
    SQUAWK_ASSIGN_OR_RETURN(auto e, LuaEnv::load(path, options));
    envs.push_back(std::move(e));
  }
  const LuaEnvSpec& spec = envs[0]->spec();
  if (levels == 0) {
    SQUAWK_RETURN_IF_ERROR(check_continuous(spec, path));
    return std::unique_ptr<LuaBatchEnv>(new LuaBatchEnv(std::move(envs), 0, 0));
  }
  SQUAWK_ASSIGN_OR_RETURN(const int classes, grid_classes(spec, levels));
  return std::unique_ptr<LuaBatchEnv>(new LuaBatchEnv(std::move(envs), levels, classes));
}

LuaBatchEnv::LuaBatchEnv(std::vector<std::unique_ptr<LuaEnv>> envs, int levels, int classes)
    : envs_(std::move(envs)),
      levels_(levels),
      classes_(classes),
      busy_(envs_.size(), 0),
      running_(envs_.size()),
      action_(static_cast<size_t>(envs_[0]->spec().action_size())) {}

void LuaBatchEnv::fail(Status st) {
  error_ = std::move(st);
  waiting_.clear();
  obs_.clear();
}

void LuaBatchEnv::start(uint64_t seed, uint64_t first_episode, uint64_t count) {
  seed_ = seed;
  next_ = first_episode;
  end_ = first_episode + count;
  error_ = Status::ok();
  for (int s = 0; s < size() && error_.is_ok(); ++s) refill(s);
  if (error_.is_ok()) collect_waiting();
}

void LuaBatchEnv::refill(int slot) {
  const auto i = static_cast<size_t>(slot);
  busy_[i] = 0;
  if (next_ >= end_) return;
  const uint64_t k = next_++;
  if (Status st = envs_[i]->reset(seed_ + k); !st.is_ok()) return fail(std::move(st));
  running_[i] = env::EpisodeStats{};
  running_[i].index = k;
  busy_[i] = 1;
}

void LuaBatchEnv::collect_waiting() {
  waiting_.clear();
  for (int s = 0; s < size(); ++s)
    if (busy_[static_cast<size_t>(s)]) waiting_.push_back(s);
  const auto d = static_cast<size_t>(obs_size());
  obs_.resize(waiting_.size() * d);
  for (size_t r = 0; r < waiting_.size(); ++r) {
    const std::vector<double>& o = envs_[static_cast<size_t>(waiting_[r])]->observation();
    for (size_t j = 0; j < d; ++j) obs_[r * d + j] = static_cast<float>(o[j]);
  }
}

void LuaBatchEnv::step(std::span<const double> actions, std::span<double> rewards,
                       std::span<uint8_t> dones) {
  for (size_t r = 0; r < waiting_.size(); ++r) {
    const int s = waiting_[r];
    const auto i = static_cast<size_t>(s);
    LuaEnv& e = *envs_[i];
    if (continuous()) {
      box_action(e.spec(), actions.subspan(r * action_.size(), action_.size()), action_);
    } else {
      const int c = grid_class(actions[r], classes_);
      if (c < 0)
        return fail(Status::invalid(e.path() + ": action " + std::to_string(actions[r]) +
                                    " is not a class of the " + std::to_string(classes_) +
                                    "-point action grid (-1 + 2 c / " +
                                    std::to_string(classes_ - 1) + ")"));
      grid_action(e.spec(), levels_, c, action_);
    }
    auto res = e.step(action_);
    if (!res) return fail(res.status());
    env::EpisodeStats& ep = running_[i];
    ++env_steps_;
    ++ep.steps;
    ep.decisions = ep.steps;
    ep.total_reward += res->reward;
    rewards[r] = res->reward;
    const bool done = res->terminated || res->truncated;
    dones[r] = done ? 1 : 0;
    if (!done) continue;
    ep.reached = res->terminated;
    ep.truncated = !res->terminated;
    completed_.push_back(ep);
    refill(s);
    if (!error_.is_ok()) return;
  }
  collect_waiting();
}

}  // namespace squawk::script
