#include "script/lua_parallel_batch_env.h"

#include <algorithm>

#include "core/rng.h"
#include "env/vec_env.h"
#include "script/lua_batch_env.h"

namespace squawk::script {

Result<std::unique_ptr<LuaParallelBatchEnv>> LuaParallelBatchEnv::make(
    const std::string& path, const VmOptions& options, int num_envs, int levels,
    std::vector<int> agent_counts) {
  if (num_envs < 1)
    return Status::invalid(path + ": number of environments is " + std::to_string(num_envs) +
                           ", expected at least 1");
  if (agent_counts.empty())
    return Status::invalid(path + ": no agent count given, expected at least one");
  for (const int n : agent_counts)
    if (n < 1 || n > 4096)
      return Status::invalid(path + ": agent count " + std::to_string(n) + ", expected 1..4096");
  std::vector<Instance> envs(static_cast<size_t>(num_envs));
  for (Instance& inst : envs) {
    SQUAWK_ASSIGN_OR_RETURN(inst.env, LuaParallelEnv::load(path, options));
  }
  SQUAWK_ASSIGN_OR_RETURN(const int classes, grid_classes(envs[0].env->spec(), levels));
  return std::unique_ptr<LuaParallelBatchEnv>(
      new LuaParallelBatchEnv(std::move(envs), levels, classes, std::move(agent_counts)));
}

LuaParallelBatchEnv::LuaParallelBatchEnv(std::vector<Instance> envs, int levels, int classes,
                                         std::vector<int> agent_counts)
    : envs_(std::move(envs)),
      levels_(levels),
      classes_(classes),
      max_agents_(*std::max_element(agent_counts.begin(), agent_counts.end())),
      agent_counts_(std::move(agent_counts)) {}

uint64_t LuaParallelBatchEnv::episode(int slot) const {
  const Instance& inst = envs_[static_cast<size_t>(slot / max_agents_)];
  return number(inst.sector, slot % max_agents_);
}

void LuaParallelBatchEnv::fail(Status st) {
  error_ = std::move(st);
  waiting_.clear();
  obs_.clear();
}

void LuaParallelBatchEnv::start(uint64_t seed, uint64_t first_episode, uint64_t count) {
  const auto a = static_cast<uint64_t>(max_agents_);
  seed_ = seed;
  first_ = first_episode;
  end_ = first_episode + count;
  next_sector_ = first_ / a;
  end_sector_ = (end_ + a - 1) / a;
  error_ = Status::ok();
  for (size_t i = 0; i < envs_.size() && error_.is_ok(); ++i) refill(i);
  if (error_.is_ok()) collect_waiting();
}

void LuaParallelBatchEnv::refill(size_t i) {
  Instance& inst = envs_[i];
  inst.busy = false;
  while (next_sector_ < end_sector_) {
    const uint64_t e = next_sector_++;
    int n = agent_counts_[0];
    if (agent_counts_.size() > 1) {
      Rng draw(env::episode_seed(seed_ ^ kAgentCountSalt, e));
      n = agent_counts_[static_cast<size_t>(
          draw.uniform_int(0, static_cast<int64_t>(agent_counts_.size()) - 1))];
    }
    if (number(e, 0) >= end_ || number(e, n - 1) < first_) continue;  // no agent in range
    if (Status st = inst.env->reset(seed_ + e, n); !st.is_ok()) return fail(std::move(st));
    const auto flying = inst.env->agents().size();
    if (flying != static_cast<size_t>(n))
      return fail(Status::invalid(inst.env->path() + ": reset: E.agents holds " +
                                  std::to_string(flying) + " agents; num_agents was " +
                                  std::to_string(n)));
    ++sector_episodes_;
    inst.sector = e;
    inst.agent.resize(flying);
    inst.running.assign(flying, env::EpisodeStats{});
    for (size_t p = 0; p < flying; ++p) {
      inst.agent[p] = static_cast<int>(p);
      inst.running[p].index = number(e, static_cast<int>(p));
    }
    inst.busy = true;
    return;
  }
}

void LuaParallelBatchEnv::collect_waiting() {
  waiting_.clear();
  row_entry_.clear();
  const auto d = static_cast<size_t>(obs_size());
  obs_.clear();
  for (size_t i = 0; i < envs_.size(); ++i) {
    const Instance& inst = envs_[i];
    if (!inst.busy) continue;
    // Rows of one instance in ascending slot order (E.agents may list them in any).
    std::vector<std::pair<int, int>> rows;  // (agent number, entry in env->agents())
    for (size_t p = 0; p < inst.agent.size(); ++p)
      if (in_range(inst.sector, inst.agent[p]))
        rows.emplace_back(inst.agent[p], static_cast<int>(p));
    std::sort(rows.begin(), rows.end());
    for (const auto& [a, p] : rows) {
      waiting_.push_back(static_cast<int>(i) * max_agents_ + a);
      row_entry_.push_back(p);
    }
  }
  obs_.resize(waiting_.size() * d);
  for (size_t r = 0; r < waiting_.size(); ++r) {
    const Instance& inst = envs_[static_cast<size_t>(waiting_[r] / max_agents_)];
    const std::span<const double> o = inst.env->observation(static_cast<size_t>(row_entry_[r]));
    for (size_t j = 0; j < d; ++j) obs_[r * d + j] = static_cast<float>(o[j]);
  }
}

void LuaParallelBatchEnv::step(std::span<const double> actions, std::span<double> rewards,
                               std::span<uint8_t> dones) {
  size_t r = 0;
  while (r < waiting_.size()) {
    const auto i = static_cast<size_t>(waiting_[r] / max_agents_);
    Instance& inst = envs_[i];
    LuaParallelEnv& e = *inst.env;
    // This instance's rows are r .. r_end - 1.
    size_t r_end = r;
    while (r_end < waiting_.size() && static_cast<size_t>(waiting_[r_end] / max_agents_) == i)
      ++r_end;
    commands_.resize(inst.agent.size());
    commanded_.clear();
    for (size_t q = r; q < r_end; ++q) {
      const int c = grid_class(actions[q], classes_);
      if (c < 0)
        return fail(Status::invalid(e.path() + ": action " + std::to_string(actions[q]) +
                                    " is not a class of the " + std::to_string(classes_) +
                                    "-point action grid (-1 + 2 c / " +
                                    std::to_string(classes_ - 1) + ")"));
      const auto p = static_cast<size_t>(row_entry_[q]);
      commands_[p].resize(static_cast<size_t>(spec().action_size()));
      grid_action(spec(), levels_, c, commands_[p]);
      commanded_.push_back(row_entry_[q]);
    }
    if (Status st = e.step(commanded_, commands_, out_); !st.is_ok()) return fail(std::move(st));
    ++env_steps_;
    for (size_t q = r; q < r_end; ++q) {
      const AgentStep& o = out_[static_cast<size_t>(row_entry_[q])];
      env::EpisodeStats& ep = inst.running[static_cast<size_t>(waiting_[q] % max_agents_)];
      ++ep.steps;
      ep.decisions = ep.steps;
      ep.total_reward += o.reward;
      rewards[q] = o.reward;
      const bool done = o.terminated || o.truncated;
      dones[q] = done ? 1 : 0;
      if (!done) continue;
      ep.reached = o.terminated;
      ep.truncated = !o.terminated;
      ep.success = o.success.value_or(false);
      completed_.push_back(ep);
    }
    // The agents still flying, by number; the sector episode ends with its last agent in range.
    std::vector<int> agent(e.agents().size());
    bool any = false;
    for (size_t k = 0; k < agent.size(); ++k) {
      agent[k] = inst.agent[static_cast<size_t>(e.kept()[k])];
      any = any || in_range(inst.sector, agent[k]);
    }
    inst.agent = std::move(agent);
    if (!any) {
      refill(i);
      if (!error_.is_ok()) return;
    }
    r = r_end;
  }
  collect_waiting();
}

}  // namespace squawk::script
