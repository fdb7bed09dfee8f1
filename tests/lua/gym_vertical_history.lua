-- envs/vertical_cr_history.lua: VerticalCREnv-v0 with the previous step's
-- intruder distances and runway distance appended as differences. Its
-- episodes (rewards, ends, infos, the first 39 observation numbers) are the
-- base environment's under the same actions, and the appended numbers are
-- the differences the scripted rule computes from its memory.
local base = squawk.gym.load(squawk.home .. "/envs/vertical_cr.lua")
local hist = squawk.gym.load(squawk.home .. "/envs/vertical_cr_history.lua")
check_eq(hist.id, base.id, "the same environment, so the rule's env check passes")
check_eq(hist.max_episode_steps, base.max_episode_steps)
check_eq(#hist.action.low, 1)
local size = 0
for _, slice in ipairs(hist.observation) do size = size + slice.size end
check_eq(size, 45)
check_eq(hist.observation[12].name, "intruder_closing"); check_eq(hist.observation[13].name, "runway_step")

-- An observation-driven action (toward the target altitude, away from a close
-- intruder), so that any difference in the first 39 numbers changes the episode.
local function act(obs, t)
  local a = (obs[23] - obs[1]) * 10
  for i = 12, 16 do
    if obs[i] < 0.05 and math.abs(obs[i - 10]) < 0.1 then a = obs[i - 10] > 0 and -1 or 1 end
  end
  if t > 30 then a = -1 end
  return {math.max(-1, math.min(1, a))}
end

for seed = 0, 2 do
  local ob = base:reset(seed)
  local oh = hist:reset(seed)
  check_eq(#oh, 45)
  for i = 1, 39 do check_eq(oh[i], ob[i], "reset obs[" .. i .. "] seed " .. seed) end
  for i = 40, 45 do check_eq(oh[i], 0, "no previous step at reset") end
  local total, t, last = 0, 0, nil
  repeat
    t = t + 1
    local prev = oh
    local nb, rb, tb, ub, ib = base:step(act(ob, t))
    local nh, rh, th, uh, ih = hist:step(act(oh, t))
    check_eq(rh, rb, "reward, seed " .. seed .. " step " .. t)
    check_eq(th, tb); check_eq(uh, ub)
    check_eq(ih.total_intrusions, ib.total_intrusions); check_eq(ih.success, ib.success)
    for i = 1, 39 do check_eq(nh[i], nb[i], "obs[" .. i .. "] seed " .. seed .. " step " .. t) end
    for i = 0, 4 do check_eq(nh[40 + i], prev[12 + i] - nh[12 + i], "closing of intruder " .. i) end
    check_eq(nh[45], prev[17] - nh[17])
    -- about 160 m/s of ground speed for 30 s: 4.8 km, 0.024 in km / 200
    check(nh[45] > 0.02 and nh[45] < 0.03, "runway_step " .. nh[45])
    total = total + rh
    ob, oh, last = nb, nh, ih
  until tb or ub
  check_eq(total, last.total_reward)
  check(t > 30, "the episode flies to the runway: " .. t .. " steps")
end
