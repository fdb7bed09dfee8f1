-- How close SectorCREnv-v0's intruders come under one policy: every
-- intruder-step (one of the four observed intruders within 5 NM after a step;
-- envs/sector_cr.lua's observation: distances 7-10 as (d - 50000) / 15000 m,
-- relative velocity 16-19 (/32 m/s, north) and 20-23 (/66 m/s, east)), counted
-- per episode by distance (under 2 NM, 2-4, 4-4.8, 4.8-5) and the share with a
-- relative speed under 30 m/s (traffic flying nearly the same course and
-- speed, which a turn of 22.5 deg separates slowly and a speed change quickly).
-- Episode k is seed SEED + k, played as bench/gym_paired.lua plays it (mlp:
-- greedy; script: reset with the episode's seed).
-- usage: squawk run bench/gym_sector_close.lua POLICY [EPISODES [SEED]] [--openap DIR] [--allow-read DIR]
local usage = "usage: squawk run bench/gym_sector_close.lua POLICY [EPISODES [SEED]]"
local spec = assert(arg[1], usage)
local episodes, seed = tonumber(arg[2] or 200), tonumber(arg[3] or 0)
local ZONE_NM, SLOW_MS = 5, 30

local gym = require("gym_load")

local limits = {2, 4, 4.8, ZONE_NM}  -- [NM] upper edges of the distance bins
local bins, slow = {0, 0, 0, 0}, 0
for k = 0, episodes - 1 do
  local env = gym.load("envs/sector_cr.lua")
  local policy = gym.policy(spec, env)
  local obs = env:reset(seed + k)
  if policy.reset then policy:reset(seed + k) end
  for _ = 1, env.max_episode_steps do
    local o, _, terminated, truncated = env:step(policy:act(obs))
    for i = 1, 4 do
      local d = (o[6 + i] * 15000 + 50000) / 1852
      if d < ZONE_NM then
        local b = 1
        while d >= limits[b] do b = b + 1 end
        bins[b] = bins[b] + 1
        local vx, vy = o[15 + i] * 32, o[19 + i] * 66
        if math.sqrt(vx * vx + vy * vy) < SLOW_MS then slow = slow + 1 end
      end
    end
    obs = o
    if terminated or truncated then break end
  end
end
local total = bins[1] + bins[2] + bins[3] + bins[4]
print(string.format("%s: %.2f intruder-steps an episode; under 2 NM %.2f, 2-4 NM %.2f, 4-4.8 NM %.2f, 4.8-5 NM %.2f; relative speed under 30 m/s %.2f",
                    spec, total / episodes, bins[1] / episodes, bins[2] / episodes, bins[3] / episodes,
                    bins[4] / episodes, slow / episodes))
