-- A shortest-tour controller for PlanWaypointEnv-v0 (envs/plan_waypoint.lua),
-- a teacher for cloning beside the nearest-neighbour rule
-- (envs/policies/plan_waypoint.lua), whose misses are tours too long for the
-- 300 steps (docs/gym_envs.md, "PlanWaypoint: where the rule misses").
--
-- Each step, from the observation alone: every order of the waypoints not yet
-- reached is scored by its straight-line length from the aircraft plus a turn
-- cost, and the aircraft turns towards the first waypoint of the cheapest
-- order by the whole bearing difference (at most the action's 45 deg), as the
-- rule turns towards the nearest. The turn cost of a heading change of theta
-- [rad] is TURN_RADIUS * (theta - sin theta): the length a turn at that radius
-- adds to a straight leg towards a far point; it is charged on the first leg
-- (from the current heading) and at each waypoint (between legs).
-- Observation (20 numbers): cos_difference 1-5, sin_difference 6-10 (of
-- heading minus the bearing to the waypoint), waypoint_distance 11-15
-- (km / 75), waypoint_reached 16-20. Action: heading change / 45 deg.

local NUM_WAYPOINTS = 5
local D_HEADING = 45            -- [deg per unit of action] (plan_waypoint.lua)
local DISTANCE_SCALE = 75       -- [km] per unit of waypoint_distance
local TURN_RADIUS = 1.73        -- [km] at the 89 m/s TAS flown, 25 deg bank: v^2 / (g tan 25)

local P = {env = "PlanWaypointEnv-v0"}

local function turn_cost(theta)
  return TURN_RADIUS * (theta - math.sin(theta))
end

-- The absolute angle [rad] in [0, pi] between directions (ax, ay) and (bx, by).
local function angle(ax, ay, bx, by)
  return math.abs(math.atan(ax * by - ay * bx, ax * bx + ay * by))
end

function P:act(obs)
  -- Open waypoints in the aircraft's frame [km]: x to the right, y ahead.
  local xs, ys, open = {}, {}, {}
  for i = 1, NUM_WAYPOINTS do
    if obs[15 + i] == 0 then
      local d = obs[10 + i] * DISTANCE_SCALE
      local rel = -math.atan(obs[5 + i], obs[i])   -- bearing - heading [rad]
      open[#open + 1] = i
      xs[i], ys[i] = d * math.sin(rel), d * math.cos(rel)
    end
  end
  if #open == 0 then return {0} end
  local best_first, best_cost
  local used = {}
  -- Depth-first over the orders of the open waypoints: cost so far, position, direction.
  local function search(n, cost, x, y, dx, dy, first)
    if best_cost and cost >= best_cost then return end
    if n == #open then
      best_first, best_cost = first, cost
      return
    end
    for _, i in ipairs(open) do
      if not used[i] then
        local lx, ly = xs[i] - x, ys[i] - y
        local len = math.sqrt(lx * lx + ly * ly)
        local c = cost + len + (len > 0 and turn_cost(angle(dx, dy, lx, ly)) or 0)
        used[i] = true
        search(n + 1, c, xs[i], ys[i], len > 0 and lx or dx, len > 0 and ly or dy, first or i)
        used[i] = false
      end
    end
  end
  search(0, 0, 0, 0, 0, 1, nil)
  local drift = math.deg(math.atan(obs[5 + best_first], obs[best_first]))   -- heading - bearing [deg]
  return {math.max(-1, math.min(1, -drift / D_HEADING))}
end

return P
