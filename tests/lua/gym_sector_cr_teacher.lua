-- envs/policies/sector_cr_teacher.lua and envs/sector_cr_features.lua: the
-- teacher recovers the ownship's heading from the observation alone, its
-- episodes beat the scripted rule's, and the feature variant's episodes are the
-- base environment's with the conflict geometry appended (worked out by hand
-- on one observation), and envs/sector_cr_geometry.lua's are those without the costs.
local base = squawk.gym.load(squawk.home .. "/envs/sector_cr.lua")
local feat = squawk.gym.load(squawk.home .. "/envs/sector_cr_features.lua")
local geom = squawk.gym.load(squawk.home .. "/envs/sector_cr_geometry.lua")
local teacher = squawk.gym.load(squawk.home .. "/envs/policies/sector_cr_teacher.lua")
local rule = squawk.gym.load(squawk.home .. "/envs/policies/sector_cr.lua")

check_eq(feat.id, base.id, "the same environment, so the rules' env check passes")
local size = 0
for _, slice in ipairs(feat.observation) do size = size + slice.size end
check_eq(size, 76)

-- The heading recovered from the intruders' relative velocities is the simulator's; the variant's
-- episodes are the base's under the teacher's actions.
local steps, worst, turned, sped = 0, 0, 0, 0
for seed = 0, 2 do
  local ob = base:reset(seed)
  local of = feat:reset(seed)
  local og = geom:reset(seed)
  for i = 1, 31 do check_eq(of[i], ob[i], "reset obs[" .. i .. "] seed " .. seed) end
  repeat
    local _, _, _, hdg = base.sim:values("KL001")
    local un, ue = teacher.heading_vector(ob, 150 + 6 * ob[1])
    worst = math.max(worst, math.abs((math.deg(math.atan(ue, un)) - hdg + 540) % 360 - 180))
    check_eq(of[60], 1, "heading known")
    local a = teacher:act(of)
    if math.abs(a[1]) == 1 then turned = turned + 1 end
    if a[2] == 1 then sped = sped + 1 end
    local nb, rb, tb, ub = base:step(a)
    local nf, rf, tf, uf = feat:step(a)
    local ng, rg = geom:step(a)
    check_eq(rg, rf, "geometry variant's reward, seed " .. seed)
    for i = 1, 76 do check_eq(ng[i], (i >= 61 and i <= 75) and 0 or nf[i], "geometry variant's obs[" .. i .. "]") end
    check_eq(rf, rb, "reward, seed " .. seed)
    check_eq(tf, tb); check_eq(uf, ub)
    for i = 1, 31 do check_eq(nf[i], nb[i], "obs[" .. i .. "] seed " .. seed) end
    ob, of, steps = nb, nf, steps + 1
  until tb or ub
end
check(worst < 1e-6, "heading recovered within 1e-6 deg: " .. worst)
check(turned > 0 and sped > 0, "the teacher turns at full rate and speeds up: " .. turned .. ", " .. sped .. " of " .. steps)

-- The teacher's return against the rule's over 30 episodes (seed 500 000 + k).
local function play(policy, seed)
  local obs = base:reset(seed)
  if policy.reset then policy:reset(seed) end
  local total = 0
  for _ = 1, base.max_episode_steps do
    local o, r, terminated, truncated = base:step(policy:act(obs))
    obs, total = o, total + r
    if terminated or truncated then break end
  end
  return total
end
local gain = 0
for k = 0, 29 do gain = gain + play(teacher, 500000 + k) - play(rule, 500000 + k) end
check(gain > 30, "the teacher beats the rule by more than 1 an episode: " .. gain / 30)

-- One observation by hand: the ownship flies north (heading 0) at TAS 150 m/s, the waypoint dead
-- ahead; intruder 1 is 20 km ahead flying south at 150 m/s (closing at 300 m/s, head-on), intruder
-- 2 60 km east flying east, 3 60 km west flying west, 4 70 km behind flying north-east (relative
-- velocities of four directions, which the heading recovery needs).
local obs = {}
for i = 1, 31 do obs[i] = 0 end
obs[2] = 1
local function intruder(k, x, y, vx, vy)
  obs[15 + k], obs[19 + k], obs[23 + k], obs[27 + k] = vx / 32, vy / 66, x / 13000, y / 13000
end
intruder(1, 20000, 0, -300, 0)
intruder(2, 0, 60000, -150, 150)
intruder(3, 0, -60000, -150, -150)
local c45 = 150 * math.sqrt(0.5)
intruder(4, -70000, 0, c45 - 150, c45)
local x = feat.features(obs)
local function near(got, want, what) check(math.abs(got - want) < 1e-6, what .. ": " .. got .. " against " .. want) end
near(x[32], (20000 / 300) / 300, "intruder 1's time to closest approach")
near(x[36], 0, "intruder 1's miss distance")
check_eq(x[40], 0, "intruder 1 not inside 5 NM")
near(x[44], 20000 / 13000, "intruder 1 ahead"); near(x[48], 0, "not to the side")
near(x[52], -300 / 66, "closing along the heading"); near(x[56], 0, "no crossing speed")
near(x[49], 60000 / 13000, "intruder 2 to the right")
check_eq(x[60], 1)
-- straight on at CAS action 0 (68) meets intruder 1; a full turn (66, 70) passes it by more
check(x[68] > x[70] and x[68] > x[66], "a turn lowers the predicted intrusion: " .. x[68] .. " " .. x[66] .. " " .. x[70])
local a = teacher:act(obs)
check(math.abs(a[1]) >= 0.5, "the teacher turns away from a head-on intruder: " .. a[1])
