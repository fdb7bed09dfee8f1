-- BlueSky-Gym's PlanWaypointEnv-v0 and StaticObstacleEnv-v0 in Lua
-- (envs/plan_waypoint.lua, envs/static_obstacle.lua): the declared spaces,
-- and episodes built from chosen draws (options.draws, the values numpy
-- would draw) whose rewards and ends are known in advance.
local geo = squawk.geo

-- squawk.geo.polygons: a set of polygons read once, counted per point
local square = {0, 0, 0, 1, 1, 1, 1, 0}
local set = geo.polygons({square, {0.5, 0.5, 0.5, 2, 2, 2, 2, 0.5}, {5, 5, 5, 6, 6, 5}})
check_eq(set:count_inside(0.25, 0.25), 1)
check_eq(set:count_inside(0.75, 0.75), 2, "inside the two overlapping squares")
check_eq(set:count_inside(5.2, 5.2), 1, "inside the triangle")
check_eq(set:count_inside(3, 3), 0)
check_eq(geo.polygons({}):count_inside(0, 0), 0, "an empty set contains nothing")
local ok, err = pcall(geo.polygons, {square, {0, 0, 1}})
check(not ok and err:find("polygon 2 needs lat, lon pairs of at least 3 points, got 3 numbers"), err)
ok, err = pcall(geo.polygons, {square, {0, 0, 1, "x", 2, 2}})
check(not ok and err:find("polygon 2%[4%] is not a number"), err)
ok, err = pcall(geo.polygons, {7})
check(not ok and err:find("polygon 1 is not a table"), err)
ok, err = pcall(set.count_inside, {}, 0, 0)
check(not ok, "count_inside on something that is not a polygon set is an error")

-- PlanWaypoint: waypoint 1 under the aircraft, 2 at 3 km east, 3-5 at 74 km.
local pw = squawk.gym.load(squawk.home .. "/envs/plan_waypoint.lua")
check_eq(pw.id, "PlanWaypointEnv-v0"); check_eq(pw.max_episode_steps, 300)
check_eq(#pw.action.low, 1)
local draws = {0, 0, 3, 90, 74, 180, 74, 270, 74, 45}
local obs = pw:reset(0, {draws = draws})
check_eq(#obs, 20)
check_near(obs[11], 0, 1e-12, "waypoint 1 at distance 0")
check_near(obs[12], 3 / 75, 1e-3, "waypoint 2 at 3 km, scaled by 75 km")
check_near(obs[2], 0, 1e-3, "waypoint 2 about due east: cos(hdg 0 - qdr 90) = 0")
check_near(obs[7], -1, 1e-6, "sin(0 - 90) = -1")
for i = 16, 20 do check_eq(obs[i], 0, "nothing reached at reset") end
-- 10 s north at CAS 150 m/s: both within 5 km; the observation is the one taken before they count
local o, r, term, trunc = pw:step({0})
check_eq(r, 2, "+1 for each of the two waypoints within 5 km"); check_eq(term, false); check_eq(trunc, false)
check_eq(o[16], 0, "the step's observation shows them before they are counted")
o = pw:step({0})
check_eq(o[16], 1); check_eq(o[17], 1); check_eq(o[18], 0)
check_eq(o[1], 0, "a reached waypoint reads 0"); check_eq(o[11], 0)
-- +1 turns the selected heading 45 deg right of the current heading
o, r = pw:step({1})
local _, _, _, hdg = pw.sim:values("KL001")
check(hdg > 10 and hdg <= 45, "turning right toward 45 deg, at " .. hdg)
check_eq(r, 0, "no reward without a waypoint")
-- a reset that follows an unfinished episode keeps the aircraft where it is (traf.cre refuses KL001)
local lat_before = pw.sim:values("KL001")
pw:reset(1, {draws = draws})
check_eq((pw.sim:values("KL001")), lat_before, "the aircraft stays")
-- the episode ends when all five are reached, and the aircraft is deleted
obs = pw:reset(2, {draws = {0, 0, 1, 0, 2, 0, 3, 0, 4, 0}})
o, r, term = pw:step({0})
check_eq(r, 5); check_eq(term, true)
check_eq(pw.sim:count(), 0, "deleted at the end")
-- random draws from a seed: the same seed, the same episode
local a = pw:reset(7)
local b = pw:reset(7)
check_eq(#a, 20)
for i = 1, 20 do check_eq(a[i], b[i], "component " .. i) end
for i = 11, 15 do check(a[i] >= 0 and a[i] < 76 / 75, "waypoint distances within 75 km") end

-- StaticObstacle: the ten areas behind the aircraft (149 km south), the waypoint 100 km north.
local so = squawk.gym.load(squawk.home .. "/envs/static_obstacle.lua")
check_eq(so.id, "StaticObstacleEnv-v0"); check_eq(so.max_episode_steps, 100)
check_eq(#so.action.low, 2)
local function draws_with(first_centre_km, first_bearing)
  local d = {}
  for i = 1, 10 do
    d[#d + 1] = i == 1 and first_centre_km or 149
    d[#d + 1] = i == 1 and first_bearing or 180
  end
  for _ = 1, 10 do  -- area 500 NM^2: R = 12.6 NM; an equilateral triangle covers 207 NM^2 > 50
    d[#d + 1] = 500; d[#d + 1] = 0.0; d[#d + 1] = 1 / 3; d[#d + 1] = 2 / 3
  end
  d[#d + 1] = 100; d[#d + 1] = 0   -- waypoint 100 km north
  return d
end
obs = so:reset(0, {draws = draws_with(149, 180)})
check_eq(#obs, 43)
check_near(obs[12], 100 / 170, 1e-3, "waypoint 100 km away, scaled by 170 km")
check_near(obs[11], 1, 1e-12, "heading at the waypoint: cos drift 1")
check_near(obs[14], 149 / 170, 1e-3, "area centre 149 km away")
check_near(obs[24], math.sqrt(500 / math.pi) / 50, 1e-12, "radius R / 50 NM")
check_near(obs[1], -1, 1e-9, "area dead astern: cos -1")
local steps, total = 0, 0
repeat
  o, r, term = so:step({0, 0})
  steps, total = steps + 1, total + r
  if not term then check_eq(r, 0, "flying straight at the waypoint costs nothing") end
until term or steps >= 100
check_eq(term, true, "reaches the waypoint")
check_eq(r, 1, "+1 at the waypoint")
check(steps > 55 and steps < 75, "100 km at about 160 m/s TAS: " .. steps .. " steps")
-- an area 20 km ahead: flying straight into it ends the episode with -5
so:reset(0, {draws = draws_with(20, 0)})
steps = 0
repeat
  o, r, term = so:step({0, 0})
  steps = steps + 1
until term or steps >= 100
check_eq(r, -5, "inside a restricted area"); check_eq(term, true)
check(steps < 10, "the area's edge is 20 km - 12.6 NM ahead: " .. steps .. " steps")
-- the speed action: +1 selects CAS + 20/3 m/s
so:reset(0, {draws = draws_with(149, 180)})
local cas0 = select(8, so.sim:values("KL001"))
for _ = 1, 5 do so:step({0, 1}) end
check(select(8, so.sim:values("KL001")) > cas0 + 5, "accelerates")
-- seeded draws: ten areas and a waypoint outside all of them
obs = so:reset(3)
for i = 1, 10 do
  check(geo.inside(so.wpt_lat, so.wpt_lon, so.polygons[i]) == false, "waypoint outside area " .. i)
  check(obs[23 + i] >= math.sqrt(100 / math.pi) / 50 and obs[23 + i] < math.sqrt(1000 / math.pi) / 50, "radius " .. i)
end

-- The rule (envs/policies/static_obstacle.lua) and its cloning teacher inside an area's enclosing
-- circle: the start 5 km from the centre of a 23.3 km circle (R = 12.6 NM) at bearing 80 deg, the
-- waypoint north. The rule takes the heading nearest the waypoint's that points away from the
-- centre (at least 90 deg off its bearing: 350-345 deg, a turn of 10-15 deg left, a chord of
-- 45 km in the circle); the teacher only one within 30 deg of straight out (bearing 260 deg:
-- 290 deg at nearest, 70 deg left, a full turn).
obs = so:reset(0, {draws = draws_with(5, 80)})
check(obs[14] * 170 < obs[24] * 50 * 1.852, "the start lies inside area 1's circle")
local rule = squawk.gym.load(squawk.home .. "/envs/policies/static_obstacle.lua")
local teacher = squawk.gym.load(squawk.home .. "/envs/policies/static_obstacle_teacher.lua")
check_eq(rule.escape_deg, 90); check_eq(teacher.escape_deg, 30)
local ra, ta = rule:act(obs), teacher:act(obs)
check(ra[1] <= -10 / 45 + 1e-9 and ra[1] >= -15 / 45 - 1e-9, "the rule turns 10-15 deg left: " .. ra[1])
check_eq(ta[1], -1, "the teacher turns fully left")
check_eq(rule.blocked, false); check_eq(teacher.blocked, false)
check_eq(ra[2], 1); check_eq(ta[2], 1)

-- The saturated teacher (envs/policies/static_obstacle_teacher_sat.lua) flies as the tight one,
-- step for step, and labels every turn of more than 17 deg as the full turn: two environments
-- of the same seed, each flown by one teacher, stay equal.
local tight = squawk.gym.load(squawk.home .. "/envs/policies/static_obstacle_teacher_tight.lua")
local sat = squawk.gym.load(squawk.home .. "/envs/policies/static_obstacle_teacher_sat.lua")
local so2 = squawk.gym.load(squawk.home .. "/envs/static_obstacle.lua")
local widened, labels = 0, 0
for seed = 0, 9 do
  local oa, ob = so:reset(seed), so2:reset(seed)
  for _ = 1, 100 do
    local ta, sa = tight:act(oa), sat:act(ob)
    check_eq(sa[2], ta[2])
    if math.abs(ta[1]) * 45 <= 17 then
      check_eq(sa[1], ta[1], "a turn within one step's reach is kept")
    else
      check_eq(sa[1], ta[1] > 0 and 1 or -1, "a longer turn is labelled full")
      if math.abs(ta[1]) < 1 then widened = widened + 1 end
    end
    labels = labels + 1
    local ra, terma, rb, termb
    oa, ra, terma = so:step(ta)
    ob, rb, termb = so2:step(sa)
    check_eq(rb, ra); check_eq(termb, terma)
    for i = 1, #oa do check_eq(ob[i], oa[i], "observation " .. i) end
    if terma then break end
  end
end
check(widened > 0, "some turns of 17-45 deg were widened: " .. widened .. " of " .. labels)
