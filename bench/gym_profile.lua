-- What one policy does on an environment with intruders, over the same
-- episodes as `squawk env run ENV --policy P --seed SEED --episodes N` (episode
-- k is seed SEED + k; mlp: checkpoints greedy, script: rules reset with the
-- episode's seed, as bench/gym_paired.lua plays them). Prints: success (the
-- last info's `success`), the mean return and its parts (the intrusion part is
-- PENALTY per intruder-step, counted from the growth of `info.total_intrusions`;
-- the rest is every other term), the mean length, where the intruder-steps
-- fall (the step of the episode, and whether the episode already had one at
-- its first step: an aircraft that starts within the zone), and the action
-- shares per component (the lower / middle / upper third of its box).
-- usage: squawk run bench/gym_profile.lua ENV.lua POLICY [EPISODES [SEED [PENALTY]]] [--openap DIR]
--   [--allow-read DIR]   (PENALTY: the reward per intruder-step, -1 for SectorCR; default -1)
local usage = "usage: squawk run bench/gym_profile.lua ENV.lua POLICY [EPISODES [SEED [PENALTY]]]"
local env_file, spec = assert(arg[1], usage), assert(arg[2], usage)
local episodes, seed, penalty = tonumber(arg[3] or 200), tonumber(arg[4] or 0), tonumber(arg[5] or -1)

local gym = require("gym_load")

-- Step buckets [first, last] for where the intruder-steps fall.
local buckets = {{1, 1}, {2, 10}, {11, 30}, {31, 60}, {61, 100}, {101, 200}}
local by_bucket = {}
for b = 1, #buckets do by_bucket[b] = 0 end
local shares, components
local n_success, sum_r, sum_r2, sum_steps, sum_intr = 0, 0, 0, 0, 0
local start_episodes, start_intr, later_only_episodes, n_steps = 0, 0, 0, 0

for k = 0, episodes - 1 do
  local env = gym.load(env_file)
  local policy = gym.policy(spec, env)
  local obs, info = env:reset(seed + k)
  if policy.reset then policy:reset(seed + k) end
  local low, high = env.action.low, env.action.high
  if not shares then
    components, shares = #low, {}
    for c = 1, components do shares[c] = {0, 0, 0} end
  end
  local total, prev_intr, steps, first_step_intr, episode_intr = 0, info.total_intrusions or 0, 0, false, 0
  for t = 1, env.max_episode_steps do
    local a = policy:act(obs)
    for c = 1, components do
      local u = (a[c] - low[c]) / (high[c] - low[c])
      local third = u < 1 / 3 and 1 or (u <= 2 / 3 and 2 or 3)
      shares[c][third] = shares[c][third] + 1
    end
    local o, r, terminated, truncated, i = env:step(a)
    local n = (i.total_intrusions or 0) - prev_intr
    prev_intr = i.total_intrusions or 0
    if n > 0 then
      if t == 1 then first_step_intr = true end
      for b, range in ipairs(buckets) do
        if t >= range[1] and t <= range[2] then by_bucket[b] = by_bucket[b] + n end
      end
    end
    episode_intr = episode_intr + n
    total, steps, obs, info = total + r, t, o, i
    if terminated or truncated then break end
  end
  n_steps = n_steps + steps
  if info.success then n_success = n_success + 1 end
  sum_r, sum_r2, sum_steps, sum_intr = sum_r + total, sum_r2 + total * total, sum_steps + steps, sum_intr + episode_intr
  if first_step_intr then
    start_episodes, start_intr = start_episodes + 1, start_intr + episode_intr
  elseif episode_intr > 0 then
    later_only_episodes = later_only_episodes + 1
  end
end

local mean = sum_r / episodes
local sd = math.sqrt(math.max(0, sum_r2 / episodes - mean * mean))
print(string.format("%s: success %.1f %%, mean return %.3f (sd %.2f), intrusion part %.3f, the rest %.3f, mean length %.1f",
                    spec, 100 * n_success / episodes, mean, sd, penalty * sum_intr / episodes,
                    mean - penalty * sum_intr / episodes, sum_steps / episodes))
print(string.format("intruder-steps: %.2f an episode; %d episodes with one at step 1 (%.2f intruder-steps an episode there), %d more with one later",
                    sum_intr / episodes, start_episodes, start_episodes > 0 and start_intr / start_episodes or 0,
                    later_only_episodes))
local parts = {}
for b, range in ipairs(buckets) do
  parts[#parts + 1] = string.format("%d-%d %.2f", range[1], range[2], by_bucket[b] / episodes)
end
print("intruder-steps an episode by step: " .. table.concat(parts, ", "))
parts = {}
for c = 1, components do
  parts[#parts + 1] = string.format("%.2f/%.2f/%.2f", shares[c][1] / n_steps, shares[c][2] / n_steps, shares[c][3] / n_steps)
end
print("action shares (lower/middle/upper third): " .. table.concat(parts, "; "))
