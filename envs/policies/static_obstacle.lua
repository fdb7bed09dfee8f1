-- A scripted controller for StaticObstacleEnv-v0 (envs/static_obstacle.lua),
-- for `squawk env run envs/static_obstacle.lua --policy script:envs/policies/static_obstacle.lua`.
--
-- Fly the heading nearest the waypoint's bearing whose straight line out to
-- the waypoint clears every restricted area's enclosing circle (the radius
-- the observation gives) by MARGIN_KM; try headings every 5 deg either side.
-- Inside an area's margin already, a heading is clear of that area when it
-- points away from its centre (within ESCAPE_DEG of straight out). When no heading is clear, turn fully away from
-- the nearest area. The speed goes up by the full step every step: at the
-- start speed (CAS 150 m/s, about 155 m/s true at 350 m) the 100 steps of
-- 10 s cover about 155 km, short of the farthest waypoints (169 km) and of
-- any detour.
-- Observation (envs/static_obstacle.lua, 43 numbers): area bearing cos 1-10,
-- waypoint drift cos 11, waypoint distance 12 (km / 170), waypoint drift
-- sin 13, area distance 14-23 (km / 170), area radius 24-33 (NM / 50), area
-- bearing sin 34-43; both bearings as heading minus bearing to it.
-- Action: heading change / 45 deg, speed change / (20/3 m/s).
-- Units: degrees, km.

local NUM_AREAS = 10
local D_HEADING = 45     -- [deg per unit of action] (static_obstacle.lua)
local MARGIN_KM = 1.852  -- [km] clearance kept from an enclosing circle (1 NM)
local TRY_STEP = 5       -- [deg] between the headings tried
local ESCAPE_DEG = 90    -- [deg] from straight out of a circle the aircraft is in
local SPEED_UP = 1       -- the speed action: + 20/3 m/s CAS every step

-- margin_km, escape_deg: MARGIN_KM and ESCAPE_DEG as fields, so that a teacher file
-- (envs/policies/static_obstacle_teacher.lua) or bench/gym_static_obstacle_outcomes.lua can fly
-- the rule with others; blocked: after act, whether no heading was clear.
local P = {env = "StaticObstacleEnv-v0", margin_km = MARGIN_KM, escape_deg = ESCAPE_DEG, blocked = false}

-- Bearing of a point relative to the heading [deg, + to the right] from the
-- observation's cos and sin of (heading - bearing).
local function relative(c, s)
  return -math.deg(math.atan(s, c))
end

-- Whether flying `turn` [deg] from the present heading for `length` [km]
-- keeps out of the circle at relative bearing `rel` [deg], distance `d`
-- and radius `r` [km] grown by `margin` [km]; inside it, whether the heading
-- lies within `escape` [deg] of straight out.
local function clear(turn, length, rel, d, r, margin, escape)
  local a = math.rad(rel - turn)
  local along, across = d * math.cos(a), math.abs(d * math.sin(a))
  local R = r + margin
  if d < R then return along <= -d * math.cos(math.rad(escape)) end
  if along <= 0 or across >= R then return true end
  return along - math.sqrt(R * R - across * across) >= length
end

function P:act(obs)
  local goal = relative(obs[11], obs[13])
  local length = obs[12] * 170
  local areas, nearest = {}, nil
  for i = 1, NUM_AREAS do
    local a = {rel = relative(obs[i], obs[33 + i]), d = obs[13 + i] * 170, r = obs[23 + i] * 50 * 1.852}
    areas[i] = a
    if not nearest or a.d - a.r < nearest.d - nearest.r then nearest = a end
  end
  local function all_clear(turn)
    for _, a in ipairs(areas) do
      if not clear(turn, length, a.rel, a.d, a.r, self.margin_km, self.escape_deg) then return false end
    end
    return true
  end
  local turn
  for k = 0, 180 // TRY_STEP do
    for _, t in ipairs({goal - k * TRY_STEP, goal + k * TRY_STEP}) do
      t = (t + 180) % 360 - 180
      if not turn and all_clear(t) then turn = t end
    end
  end
  self.blocked = not turn
  if not turn then turn = nearest.rel > 0 and -D_HEADING or D_HEADING end
  return {math.max(-1, math.min(1, turn / D_HEADING)), SPEED_UP}
end

return P
