-- The paired comparison of two policies on one environment, in one process:
-- episode k (seed SEED + k, k = 0 .. EPISODES-1) is played by each policy on
-- a freshly loaded environment, as `squawk env run ENV --policy P --seed SEED+k --episodes 1`
-- plays it (mlp: checkpoints greedy: their mean or mode; script: rules reset
-- with the episode's seed), and the per-episode differences A - B are
-- summarised: their mean, its standard error (sd / sqrt(n)), and in how many
-- episodes A is better, equal, worse. With `v`, one line per episode: each
-- policy's return, steps and its last info's numbers and flags.
-- usage: squawk run bench/gym_paired.lua ENV.lua POLICY_A POLICY_B [EPISODES [SEED [v]]] [--openap DIR]
--   [--allow-read DIR] (the folder of an mlp: checkpoint outside the sandbox's folders)
local usage = "usage: squawk run bench/gym_paired.lua ENV.lua POLICY_A POLICY_B [EPISODES [SEED [v]]]"
local env_file, policy_a, policy_b = assert(arg[1], usage), assert(arg[2], usage), assert(arg[3], usage)
local episodes, seed, verbose = tonumber(arg[4] or 200), tonumber(arg[5] or 0), arg[6] == "v"

local gym = require("gym_load")
local load, policy_for = gym.load, gym.policy

-- The return, steps and last info of episode `s` under `spec`.
local function play(spec, s)
  local env = load(env_file)
  local policy = policy_for(spec, env)
  local obs, info = env:reset(s)
  if policy.reset then policy:reset(s) end
  local total, steps = 0, 0
  for t = 1, env.max_episode_steps do
    local o, r, terminated, truncated, i = env:step(policy:act(obs))
    total, steps, obs, info = total + r, t, o, i
    if terminated or truncated then break end
  end
  return total, steps, info
end

local function shown(info)
  local keys = {}
  for k, v in pairs(info) do
    if k ~= "total_reward" and (type(v) == "number" or type(v) == "boolean") then keys[#keys + 1] = k end
  end
  table.sort(keys)
  local parts = {}
  for _, k in ipairs(keys) do parts[#parts + 1] = k .. " " .. tostring(info[k]) end
  return table.concat(parts, ", ")
end

local d, sum_a, sum_b, better, worse = {}, 0, 0, 0, 0
for k = 0, episodes - 1 do
  local ra, na, ia = play(policy_a, seed + k)
  local rb, nb, ib = play(policy_b, seed + k)
  d[#d + 1] = ra - rb
  sum_a, sum_b = sum_a + ra, sum_b + rb
  if ra - rb > 1e-9 then better = better + 1 elseif ra - rb < -1e-9 then worse = worse + 1 end
  if verbose then
    print(string.format("seed %d: A %.3f (%d steps; %s) B %.3f (%d steps; %s) A - B %+.3f", seed + k, ra, na,
                        shown(ia), rb, nb, shown(ib), ra - rb))
  end
end
local mean = 0
for _, x in ipairs(d) do mean = mean + x end
mean = mean / episodes
local sq = 0
for _, x in ipairs(d) do sq = sq + (x - mean) ^ 2 end
local se = episodes > 1 and math.sqrt(sq / (episodes - 1) / episodes) or 0
print(string.format("A %s: mean %.3f; B %s: mean %.3f", policy_a, sum_a / episodes, policy_b, sum_b / episodes))
print(string.format("A - B over %d paired episodes: mean %+.3f, standard error %.3f; A better in %d, equal in %d, worse in %d",
                    episodes, mean, se, better, episodes - better - worse, worse))
