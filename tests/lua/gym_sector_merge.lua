-- The contract and the behaviour of envs/sector_cr.lua and envs/merge.lua
-- without the reference (bench/gym_ref/compare.py checks them against
-- BlueSky-Gym on BlueSky): shapes, reproducible resets, the reward terms,
-- truncation on leaving the sector, termination at the runway.

local function near_all(a, b)
  for i = 1, #a do if a[i] ~= b[i] then return false end end
  return #a == #b
end

-- SectorCREnv-v0
local sector = squawk.gym.load(squawk.home .. "/envs/sector_cr.lua")
check_eq(sector.id, "SectorCREnv-v0")
check_eq(sector.max_episode_steps, 200)
local obs = sector:reset(3)
check_eq(#obs, 31, "1 airspeed + 2 drift + 7 x 4 intruders")
check(near_all(obs, (sector:reset(3))), "a reset is a function of its seed")
check(not near_all(obs, (sector:reset(4))), "another seed, another sector")
obs = sector:reset(3)
check(obs[1] > 0.2 and obs[1] < 0.7, "airspeed: (tas - 150) / 6, TAS a little above CAS 150 m/s at 350 m")
check(obs[2] > 0.9999, "cos(drift): every aircraft starts toward its waypoint, got " .. obs[2])
local d = {obs[7], obs[8], obs[9], obs[10]}   -- distances, nearest first
check(d[1] <= d[2] and d[2] <= d[3] and d[3] <= d[4], "intruders ordered by distance")
check(sector.num_ac >= 5, "at least NUM_AC_STATE + 1 aircraft")
-- straight ahead: drift stays ~0 (reward ~0 without intrusions) until the
-- agent crosses the border at its waypoint, which truncates (never terminates)
local steps, truncated, reward, term = 0, false, 0, false
repeat
  obs, reward, term, truncated = sector:step({0, 0})
  steps = steps + 1
  check_eq(term, false, "SectorCR never terminates")
  check(reward <= 0, "rewards are penalties")
until truncated or steps == 200
check(truncated, "flying to a waypoint on the border leaves the sector")
check(steps > 1 and steps < 200, "left after " .. steps .. " steps")
-- a hard turn drifts and pays 0.1 per radian
sector:reset(3)
for _ = 1, 4 do obs, reward = sector:step({1, 0}) end
local drift = math.atan(obs[11], obs[2])           -- sin(drift), cos(drift)
check(math.abs(drift) > 0.5, "turning 22.5 deg per step drifts")
check(reward <= -0.1 * math.abs(drift) + 1e-12, "drift penalty")

-- MergeEnv-v0, on chosen draws: the agent 50 km north of the fix on its
-- meridian, INT0 on the same spot (an intrusion every step), the other 18
-- 500 km out on the stream's edges.
local merge = squawk.gym.load(squawk.home .. "/envs/merge.lua")
check_eq(merge.id, "MergeEnv-v0")
check_eq(merge.max_episode_steps, 50)
local draws = {0, 50, 0, 50}
for i = 1, 18 do draws[#draws + 1] = i % 2 == 0 and 15 or -15; draws[#draws + 1] = 500 end
obs = merge:reset(0, {draws = draws})
check_eq(#obs, 40, "4 own + waypoint_dist + 7 x 5 intruders")
check_near(obs[2], 1, 1e-9, "cos(drift): heading for the fix")
check_eq(obs[13], 0, "faf_reached")
check_near(obs[30] * 250 * 1.852, 50, 0.5, "waypoint_dist: 50 km to the fix, in NM / 250")
check_near(obs[3 + 5], 0, 1e-12, "INT0 on top of the agent: distance 0")
local reach_step, done_step
for k = 1, 50 do
  local r, t, tr, info
  obs, r, t, tr, info = merge:step({0, 0})
  check_eq(tr, false)
  if t then done_step = k; break end
  if info.faf_reach == 1 and not reach_step then
    reach_step = k
    check(r > -0.5, "the fix pays 1 against INT0's intrusion, got " .. r)
  elseif not reach_step then
    check(r < -0.9, "INT0 flies with the agent: one intrusion every step before the fix, got " .. r)
  end
end
check(reach_step and reach_step <= 5, "within 10 NM of the fix within 5 steps of 50 s")
check_eq(obs[13], 1, "faf_reached after the fix")
check(done_step and done_step > reach_step and done_step < 50, "terminated 20 NM before the runway")
obs = merge:reset(1)
check(near_all(obs, (merge:reset(1))), "a merge reset is a function of its seed")
