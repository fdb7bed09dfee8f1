-- The planning teacher (envs/policies/vertical_cr_teacher.lua) and the steady teacher
-- (envs/policies/vertical_cr_steady.lua) for VerticalCREnv-v0 on observations built by hand: the
-- ownship level at 3000 m on its target altitude (unless a case moves the target), heading north.
local function teacher()
  return squawk.gym.load(squawk.home .. "/envs/policies/vertical_cr_teacher.lua")
end
local rule = squawk.gym.load(squawk.home .. "/envs/policies/vertical_cr.lua")
local GS = 172  -- [m/s] about the true airspeed of 150 m/s CAS at 3000 m

-- The 39 numbers of envs/vertical_cr.lua. Each intruder: distance [km], bearing from the nose
-- [deg], altitude above the ownship [m], heading [deg], ground speed [m/s]. Intruders not given
-- fly 200 km behind, 3000 m above, in the ownship's direction and at its speed.
local function observation(runway_km, intruders)
  local obs = {(3000 - 1500) / 3000}
  obs[17] = (runway_km - 100) / 200
  obs[23] = (3000 - 1500) / 3000
  obs[24] = 0
  for i = 1, 5 do
    local it = intruders[i] or {200, 180, 3000, 0, GS}
    local d, brg, dh, hdg, gs = it[1], it[2], it[3], it[4], it[5]
    local b, dpsi = math.rad(-brg), math.rad(-hdg)   -- heading 0 minus the bearing; minus the heading
    obs[1 + i] = dh / 3000
    obs[6 + i] = math.cos(b)
    obs[11 + i] = d / 200
    obs[17 + i] = math.sin(b)
    obs[24 + i] = -math.cos(dpsi) * gs / 150
    obs[29 + i] = (GS - math.sin(dpsi) * gs) / 150
    obs[34 + i] = 0
  end
  return obs
end

local function act(obs)
  local t = teacher()
  t:reset(0)
  return t:act(obs)[1]
end

local HOLD = 0.625 / 12.5  -- the teacher's hold: its vertical speed reversed at 0.625 m/s (up from 0)

-- Far from the runway with no intruder near: hold the target.
check_near(act(observation(150, {})), HOLD, 1e-12, "holds the target")

-- An intruder head-on at the same altitude closes about 9.5 km a step. 25 km ahead it is within
-- the teacher's zone (5 NM and 4 km) at the end of the second step, and leaving its 1000 ft and
-- 250 m takes most of the full rate for those two steps; the rule, with no previous distance to
-- read a closing rate from, holds. 40 km ahead there are three steps: a gentler start.
local head_on = {{25, 0, 0, 180, 150}}
check(math.abs(act(observation(150, head_on))) >= 0.5, "away from the head-on intruder 25 km ahead")
rule:reset(0)
check(math.abs(rule:act(observation(150, head_on))[1]) < 0.02, "the rule holds on its first look")
local early = act(observation(150, {{40, 0, 0, 180, 150}}))
check(math.abs(early) > HOLD and math.abs(early) < 0.5, "a gentle start for the intruder 40 km ahead")
-- 17 km ahead and 600 m above it is clear of the zone and the margin: hold; 400 m above it is
-- not: away from it, down.
check_near(act(observation(150, {{17, 0, 600, 180, 150}})), HOLD, 1e-12, "600 m above: hold")
check(act(observation(150, {{17, 0, 400, 180, 150}})) < -0.2, "400 m above: down")

-- The descent as late as possible: 60 km out (about 12 steps) there is time to hold; 35 km out
-- (about 7 steps) 2880 m to lose (to the 120 m aim) needs most of the full rate from now on.
check_near(act(observation(60, {})), HOLD, 1e-12, "60 km out: hold")
check(act(observation(35, {})) <= -0.5, "35 km out: descend")

-- The steady teacher (envs/policies/vertical_cr_steady.lua): the rule's avoidance held at the edge
-- of an intruder's band (its altitude ± 1000 ft and 150 m: 455 m) instead of the rule's full rate
-- away and back. Each case is a fresh policy's first look (no closing rate, no ground speed yet).
local function steady()
  local t = squawk.gym.load(squawk.home .. "/envs/policies/vertical_cr_steady.lua")
  t:reset(0)
  return t
end
local function rule_act(obs)
  rule:reset(0)
  return rule:act(obs)[1]
end
local STEADY_HOLD = 1.25 / 12.5

-- No intruder near, on the target: hold.
check_near(steady():act(observation(150, {}))[1], STEADY_HOLD, 1e-12, "steady: holds the target")
-- On the target with an intruder 500 m below within the zone: outside its band, so hold; the rule
-- climbs away at the full rate.
local below = {{8, 0, -500, 180, 150}}
check_near(steady():act(observation(150, below))[1], STEADY_HOLD, 1e-12, "steady: holds 500 m above an intruder")
check_eq(rule_act(observation(150, below)), 1, "the rule climbs away")
-- 500 m above the target, where an intruder flies within the zone: the way back is in its band, so
-- the teacher stops at the band's edge (45 m down); the rule climbs away again at the full rate,
-- and one step later, 875 m above it, would fly back at the full rate: its flipping.
local at_target = observation(150, {{8, 0, -500, 180, 150}})
at_target[23] = (2500 - 1500) / 3000
local edge = steady():act(at_target)[1]
check(edge < 0 and edge > -0.2, "steady: stops at the band's edge: " .. edge)
check_eq(rule_act(at_target), 1, "the rule climbs away from the target")
local clear = observation(150, {{8, 0, -875, 180, 150}})
clear[23] = (2125 - 1500) / 3000
check_eq(rule_act(clear), -1, "875 m above: the rule flies back at the full rate")
-- Once the intruder is past (12 km behind, opening) the way back is free.
local past = observation(150, {{12, 180, -500, 0, 100}})
past[23] = (2500 - 1500) / 3000
check(steady():act(past)[1] < -0.3, "steady: back towards the target once the intruder is past")
-- An intruder at the same altitude within the zone: to the nearer edge of its band at the full
-- rate (455 m in one step needs more than it).
check_eq(math.abs(steady():act(observation(150, {{8, 0, 0, 180, 150}}))[1]), 1, "steady: out of the band")

-- The descent: from the second look (the ground speed from the runway distance flown), down when
-- reaching 100 m at the runway needs the full rate: 35 km out, not 55.
local function second_look(first_km, km)
  local t = steady()
  t:act(observation(first_km, {}))
  return t:act(observation(km, {}))[1]
end
check(math.abs(second_look(60, 55)) <= STEADY_HOLD, "steady: 55 km out: hold")
check_eq(second_look(40, 35), -1, "steady: 35 km out: descend at the full rate")
