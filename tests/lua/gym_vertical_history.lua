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

-- envs/vertical_cr_conflicts.lua: the history's 45 numbers, then per intruder the closest
-- approach of its straight line (time / 10 steps, distance / 5 NM, altitude difference / 3000 m)
-- and a threat flag (within 5 NM now or within two steps); the episodes are the history's.
local conflicts = squawk.gym.load(squawk.home .. "/envs/vertical_cr_conflicts.lua")
check_eq(conflicts.id, base.id)
size = 0
for _, slice in ipairs(conflicts.observation) do size = size + slice.size end
check_eq(size, 65)
check_eq(conflicts.observation[14].name, "cpa_time"); check_eq(conflicts.observation[17].name, "threat")
local ZONE = 5 * 1.852 / 200   -- the intrusion distance in intruder_distance's units
for seed = 5, 6 do
  local oh, oc = hist:reset(seed), conflicts:reset(seed)
  local seen, t, th, tc = {oc}, 0, false, false
  repeat
    t = t + 1
    local a = act(oh, t)
    local nh, rh, uh, nc, rc, uc
    nh, rh, th, uh = hist:step(a)
    nc, rc, tc, uc = conflicts:step(a)
    check_eq(rc, rh, "reward, seed " .. seed .. " step " .. t); check_eq(tc, th); check_eq(uc, uh)
    for i = 1, 45 do check_eq(nc[i], nh[i]) end
    for i = 1, 5 do
      if nc[11 + i] < ZONE then check_eq(nc[60 + i], 1, "within 5 NM: a threat") end
      check(nc[45 + i] >= 0 and nc[45 + i] <= 2 and nc[50 + i] >= 0, "cpa time and distance in range")
    end
    seen[#seen + 1] = nc
    oh = nh
  until th or uh
  -- Where the closest approach is predicted 2-8 steps ahead, the intruder comes nearest within a
  -- step of it (the intruders fly straight and level), and not much further than predicted (the
  -- steps sample the line every 30 s: at most half a step of closing, about 5 km, on top).
  local checked = 0
  for s = 1, #seen do
    for i = 1, 5 do
      local steps = seen[s][45 + i] * 10
      if steps >= 2 and steps <= 8 and s + 9 <= #seen then
        local nearest, at = math.huge, 0
        for u = s, s + 9 do
          if seen[u][11 + i] < nearest then nearest, at = seen[u][11 + i], u - s end
        end
        check(math.abs(at - steps) <= 1, "closest approach at step " .. at .. ", predicted " .. steps)
        check(nearest * 200 <= seen[s][50 + i] * 5 * 1.852 + 5, "nearest distance within the prediction")
        checked = checked + 1
      end
    end
  end
  check(checked > 5, "closest approaches checked: " .. checked)
end
