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

-- envs/vertical_cr_glide.lua: the history's 45 numbers, then the steps left
-- at the last step's ground speed (/ 40) and the glide to the runway's height
-- (action units); the episodes are the history's.
local glide = squawk.gym.load(squawk.home .. "/envs/vertical_cr_glide.lua")
check_eq(glide.id, base.id)
size = 0
for _, slice in ipairs(glide.observation) do size = size + slice.size end
check_eq(size, 47)
for seed = 3, 4 do
  local oh, og = hist:reset(seed), glide:reset(seed)
  check_eq(#og, 47)
  for i = 1, 45 do check_eq(og[i], oh[i]) end
  check_eq(og[46], 0, "no ground speed at reset"); check_eq(og[47], 0)
  local t, th, tg = 0, false, false
  repeat
    t = t + 1
    local a = act(oh, t)
    local nh, rh, uh
    nh, rh, th, uh = hist:step(a)
    local ng, rg, ug
    ng, rg, tg, ug = glide:step(a)
    check_eq(rg, rh, "reward, seed " .. seed .. " step " .. t); check_eq(tg, th); check_eq(ug, uh)
    for i = 1, 45 do check_eq(ng[i], nh[i]) end
    local runway_km, alt = 100 + 200 * ng[17], 1500 + 3000 * ng[1]
    if runway_km > 0 then
      -- 4.2-5.4 km a step (the ground speed changes with altitude): the steps left
      check(ng[46] * 40 > runway_km / 5.4 and ng[46] * 40 < runway_km / 4.2, "steps left, step " .. t)
      -- flying the glide for the steps left reaches the runway's height
      check_near(alt + ng[47] * 12.5 * 30 * ng[46] * 40, 0, 1e-6, "glide, step " .. t)
      check(ng[47] < 0 or alt <= 0, "a glide down while airborne: " .. ng[47])
    end
    oh = nh
  until th or uh
  check_eq(t > 30, true)
end
