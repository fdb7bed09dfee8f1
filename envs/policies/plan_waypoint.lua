-- A scripted controller for PlanWaypointEnv-v0 (envs/plan_waypoint.lua), for
-- `squawk env run envs/plan_waypoint.lua --policy script:envs/policies/plan_waypoint.lua`.
--
-- Nearest neighbour: turn towards the nearest waypoint not yet reached, by
-- the whole bearing difference (at most the action's 45 deg).
-- Observation (envs/plan_waypoint.lua, 20 numbers): cos_difference 1-5,
-- sin_difference 6-10 (of heading minus the bearing to the waypoint),
-- waypoint_distance 11-15 (km / 75), waypoint_reached 16-20.
-- Action: heading change / 45 deg. Units: degrees, km.

local NUM_WAYPOINTS = 5
local D_HEADING = 45   -- [deg per unit of action] (plan_waypoint.lua)

local P = {env = "PlanWaypointEnv-v0"}

function P:act(obs)
  local best, best_d
  for i = 1, NUM_WAYPOINTS do
    local d = obs[10 + i]
    if obs[15 + i] == 0 and (not best or d < best_d) then best, best_d = i, d end
  end
  if not best then return {0} end
  local drift = math.deg(math.atan(obs[5 + best], obs[best]))   -- heading - bearing [deg]
  return {math.max(-1, math.min(1, -drift / D_HEADING))}
end

return P
