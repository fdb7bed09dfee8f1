#include "rl/play.h"

#include <vector>

namespace squawk::rl {

Result<bool> play(env::BatchEnv& envs, uint64_t seed, uint64_t first, uint64_t count,
                  const Driver& driver) {
  envs.completed().clear();
  envs.start(seed, first, count);
  SQUAWK_RETURN_IF_ERROR(envs.error());  // a reset can fail (a Lua file)
  std::vector<int> slots;
  std::vector<ActionSample> acts;
  std::vector<double> actions, rewards;
  std::vector<uint8_t> dones;
  const auto d = static_cast<size_t>(envs.action_size());
  while (!envs.finished()) {
    slots = envs.waiting();
    const size_t n = slots.size();
    acts.assign(n, ActionSample{});
    actions.resize(n * d);
    rewards.assign(n, 0.0);
    dones.assign(n, 0);
    Turn turn{slots, envs.observations(), acts, rewards, dones};
    SQUAWK_RETURN_IF_ERROR(driver.choose(turn));
    for (size_t r = 0; r < n; ++r)
      for (size_t j = 0; j < d; ++j) actions[r * d + j] = acts[r].component(static_cast<int>(j));
    envs.step(actions, rewards, dones);
    SQUAWK_RETURN_IF_ERROR(envs.error());
    turn.obs = {};
    if (driver.after && !driver.after(turn)) return false;
  }
  return true;
}

std::function<Status(Turn&)> policy_choice(Policy& policy, env::BatchEnv& envs,
                                           EpisodeStreams& streams, bool greedy) {
  return [&policy, &envs, &streams, greedy](Turn& t) {
    policy.act(t.obs, static_cast<int>(t.slots.size()), t.slots, streams.rows(envs), greedy,
               t.actions);
    streams.keep(envs);
    return Status::ok();
  };
}

}  // namespace squawk::rl
