-- The shortest-tour teacher for PlanWaypointEnv-v0 (envs/policies/plan_waypoint_tour.lua)
-- against the nearest-neighbour rule (envs/policies/plan_waypoint.lua) on observations built by
-- hand: heading north, waypoints given by their distance [km] and bearing [deg].
local tour = squawk.gym.load(squawk.home .. "/envs/policies/plan_waypoint_tour.lua")
local rule = squawk.gym.load(squawk.home .. "/envs/policies/plan_waypoint.lua")

-- The 20 numbers of envs/plan_waypoint.lua for an aircraft heading north; `reached` lists the
-- waypoints already reached (their first three numbers read 0).
local function observation(waypoints, reached)
  local obs = {}
  for i, w in ipairs(waypoints) do
    local done = reached and reached[i] or false
    local drift = math.rad(-w[2])   -- heading 0 minus the bearing
    obs[i] = done and 0 or math.cos(drift)
    obs[5 + i] = done and 0 or math.sin(drift)
    obs[10 + i] = done and 0 or w[1] / 75
    obs[15 + i] = done and 1 or 0
  end
  return obs
end

-- On a line east-west: 10 km east, then 11 km west, 35, 45 and 55 km east. Nearest first flies
-- 10 + 21 + 46 + 10 + 10 = 97 km; west first 11 + 21 + 25 + 10 + 10 = 77 km.
local line = {{10, 90}, {11, 270}, {35, 90}, {45, 90}, {55, 90}}
check_eq(rule:act(observation(line))[1], 1, "the rule turns right, to the nearest (east)")
check_eq(tour:act(observation(line))[1], -1, "the tour turns left, to the west one first")
-- With the west one reached, the nearest open one is also the tour's first.
check_eq(tour:act(observation(line, {false, true, false, false, false}))[1], 1)

-- Three ahead (20, 25, 30 km) and two behind (40, 45 km): ahead first flies 30 + 75 = 105 km,
-- behind first 45 + 75 = 120 km and a turn; the heading is held: action 0.
local ahead = {{40, 180}, {20, 0}, {45, 180}, {25, 0}, {30, 0}}
check_near(tour:act(observation(ahead))[1], 0, 1e-12, "straight on to the waypoint ahead")

-- A bearing 30 deg right of the heading turns by 30 / 45 of the full action, as the rule does.
local right = {{10, 30}, {10, 30}, {10, 30}, {10, 30}, {10, 30}}
check_near(tour:act(observation(right))[1], 30 / 45, 1e-12)
check_near(rule:act(observation(right))[1], 30 / 45, 1e-12)

-- All reached: no turn.
check_eq(tour:act(observation(line, {true, true, true, true, true}))[1], 0)
