-- BlueSky-Gym StaticObstacleEnv-v0 as one Lua file over squawk's C++ kernels.
--
-- Every number below is a fact read from TUDelft-CNS-ATM/bluesky-gym at
-- aed26d6 (bluesky_gym/envs/static_obstacle_env.py, cited as L<line>, and
-- bluesky_gym/envs/common/functions.py, cited as F<line>; the registration in
-- bluesky_gym/__init__.py); nothing is copied.
-- One A320 (KL001) at 52 N 4 E, altitude 350 m, CAS 150 m/s, flies to one
-- waypoint 100-169 km away past ten random polygons (restricted areas) whose
-- centres lie 20-149 km away. The action (two numbers in [-1, 1]) turns the
-- selected heading by 45 deg per unit from the current heading and changes
-- the selected CAS by 20/3 m/s per unit, held for up to 10 one-second
-- simulator steps. After every simulator step: +1 when the waypoint was
-- within 5 km, -0.01 per radian between heading and the bearing to the
-- waypoint, -5 per restricted area the aircraft is inside; the episode ends
-- on the waypoint or inside an area, and the step returns that simulator
-- step's reward alone (L134-149). Units: km, NM, degrees as named.
--
-- The waypoint and drift terms read the observation taken at the end of the
-- previous env step (L293-294 use what _get_obs stored, and _get_obs runs
-- only at the end of a step, L140/L145): the waypoint is counted one step
-- after the aircraft came within 5 km of it, as in BlueSky-Gym.

local geo = squawk.geo
local Draws = require("gym_draws")
local F = require("gym_functions")

local DISTANCE_MARGIN = 5                     -- [km] L10
local REACH_REWARD = 1                        -- L12
local DRIFT_PENALTY = -0.01                   -- [1/rad] L13
local RESTRICTED_AREA_INTRUSION_PENALTY = -5  -- L14
local WAYPOINT_DISTANCE_MIN, WAYPOINT_DISTANCE_MAX = 100, 170  -- [km] L18-19; also the distance scale (L273, L277)
local OBSTACLE_DISTANCE_MIN, OBSTACLE_DISTANCE_MAX = 20, 150   -- [km] L21-22
local D_HEADING = 45                          -- [deg per unit] L24
local D_SPEED = 20 / 3                        -- [m/s per unit] L25 (added to CAS in m/s, L340-342)
local AC_SPD = 150                            -- L27, passed raw to traf.cre (L104): CAS 150 m/s
local ALTITUDE = 350                          -- L28, passed raw to traf.cre's acalt: 350 m
local NM2KM = 1.852                           -- L30
local MPS2KT = 1.94384                        -- L31, the SPD command's knots (L342)
local ACTION_FREQUENCY = 10                   -- L33
local NUM_OBSTACLES = 10                      -- L35
local AREA_MIN, AREA_MAX = 50, 1000           -- [NM^2] L38 OBSTACLE_AREA_RANGE; 50 is also the radius scale (L276)
local LAT0, LON0 = 52, 4                      -- traf.cre's default position (L104)
local SIM_DT = 1                              -- [s] 'DT 1;FF' (L81)
local ACID = "KL001"

local E = {
  id = "StaticObstacleEnv-v0",
  source = "bluesky-gym@aed26d6 bluesky_gym/envs/static_obstacle_env.py",
  -- spaces.Dict (L58-69) flattened as gymnasium does: keys sorted; 43 numbers.
  observation = {
    {name = "cos_difference_restricted_area_pos", size = NUM_OBSTACLES},  -- cos(wrap(hdg - qdr_i)) (L265-269)
    {name = "destination_waypoint_cos_drift", size = 1},    -- cos(wrap(hdg - qdr_wpt)) (L254-258)
    {name = "destination_waypoint_distance", size = 1},     -- km / 170 (L251, L273)
    {name = "destination_waypoint_sin_drift", size = 1},    -- sin(wrap(hdg - qdr_wpt)) (L259)
    {name = "restricted_area_distance", size = NUM_OBSTACLES},  -- km to the centre / 170 (L262-263, L277)
    {name = "restricted_area_radius", size = NUM_OBSTACLES},    -- R [NM] / 50 (L153, L276)
    {name = "sin_difference_restricted_area_pos", size = NUM_OBSTACLES},  -- sin(wrap(hdg - qdr_i)) (L270)
  },
  action = {low = {-1, -1}, high = {1, 1}},  -- spaces.Box(-1, 1, (2,)) (L71): heading, speed
  max_episode_steps = 100,                   -- __init__.py register("StaticObstacleEnv-v0", ..., max_episode_steps=100)
}

-- L151-164: an area [NM^2] in [100, 999] gives the circle's radius R [NM];
-- points on it are added until the polygon covers 50 NM^2, then turned into
-- lat, lon around the centre. Returns {lat1, lon1, lat2, ...} and R.
function E:generate_polygon(clat, clon)
  local r = math.sqrt(self.draws:randint(AREA_MIN * 2, AREA_MAX) / math.pi)
  local p = {}
  for i = 1, 3 do p[i] = F.random_point_on_circle(r, self.draws) end
  F.sort_points_clockwise(p)
  while F.polygon_area(p) < AREA_MIN do
    p[#p + 1] = F.random_point_on_circle(r, self.draws)
    F.sort_points_clockwise(p)
  end
  local coords = {}
  for _, q in ipairs(p) do
    coords[#coords + 1], coords[#coords + 2] = F.nm_to_latlong(clat, clon, q)
  end
  return coords, r
end

-- L166-191, L220-231: ten centres (distance [km], bearing [deg] from the
-- start, great circle), then each one's polygon.
function E:generate_obstacles()
  local clat, clon = {}, {}
  for i = 1, NUM_OBSTACLES do
    local dis_km = self.draws:randint(OBSTACLE_DISTANCE_MIN, OBSTACLE_DISTANCE_MAX)
    clat[i], clon[i] = geo.destination(LAT0, LON0, self.draws:randint(0, 360), dis_km * 1000)
  end
  self.obst_lat, self.obst_lon, self.polygons, self.radius = clat, clon, {}, {}
  for i = 1, NUM_OBSTACLES do
    self.polygons[i], self.radius[i] = self:generate_polygon(clat[i], clon[i])
  end
  self.areas = geo.polygons(self.polygons)   -- tested after every simulator step
end

-- L193-218: a waypoint 100-169 km away outside every area (at most 1000 tries).
function E:generate_waypoint()
  for _ = 1, 1000 do
    local dis_km = self.draws:randint(WAYPOINT_DISTANCE_MIN, WAYPOINT_DISTANCE_MAX)
    local lat, lon = geo.destination(LAT0, LON0, self.draws:randint(0, 360), dis_km * 1000)
    if self.areas:count_inside(lat, lon) == 0 then
      self.wpt_lat, self.wpt_lon = lat, lon
      return
    end
  end
  error("StaticObstacleEnv-v0: no waypoint outside the obstacles in 1000 tries (L213-214)")
end

-- L233-282; keeps the waypoint distance [km] and drift [deg] the reward reads.
function E:observe()
  local lat, lon, _, hdg = self.sim:values(ACID)
  local qdr, dist_nm = geo.kwikqdrdist(lat, lon, self.wpt_lat, self.wpt_lon)
  self.wpt_dis = dist_nm * NM2KM
  self.drift = geo.gym_wrap180(hdg - qdr)
  local c, d, r, s = {}, {}, {}, {}
  for i = 1, NUM_OBSTACLES do
    local oq, od = geo.kwikqdrdist(lat, lon, self.obst_lat[i], self.obst_lon[i])
    local b = math.rad(geo.gym_wrap180(hdg - oq))
    c[i], s[i], d[i] = math.cos(b), math.sin(b), od * NM2KM / WAYPOINT_DISTANCE_MAX
    r[i] = self.radius[i] / AREA_MIN
  end
  local drift = math.rad(self.drift)
  local obs = {}
  local function add(t) for _, v in ipairs(t) do obs[#obs + 1] = v end end
  add(c)
  obs[#obs + 1] = math.cos(drift)
  obs[#obs + 1] = self.wpt_dis / WAYPOINT_DISTANCE_MAX
  obs[#obs + 1] = math.sin(drift)
  add(d); add(r); add(s)
  return obs
end

function E:info()
  -- info.success: the waypoint reached without entering a restricted area.
  return {total_reward = self.total_reward, waypoint_reached = self.waypoint_reached, crashed = self.crashed,
          success = self.waypoint_reached == 1 and self.crashed == 0,
          average_drift = self.drift_n > 0 and self.drift_sum / self.drift_n or nil}
end

function E:reset(seed, options)
  self.sim = self.sim or squawk.sim.new{dt_s = SIM_DT}
  self.sim:delete_all()                                  -- L96
  self.draws = Draws.new(seed, options and options.draws)
  self.total_reward, self.waypoint_reached, self.crashed = 0, 0, 0
  self.drift_sum, self.drift_n = 0, 0
  self:generate_obstacles()
  self:generate_waypoint()
  -- L104, L119-121: BlueSky-Gym creates KL001 heading north, then sets its heading and selected
  -- track to the bearing of the waypoint; nothing in between reads the heading.
  local qdr = geo.kwikqdrdist(LAT0, LON0, self.wpt_lat, self.wpt_lon)
  self.sim:create{id = ACID, type = "A320", lat = LAT0, lon = LON0, hdg_deg = qdr, alt_m = ALTITUDE, spd = AC_SPD}
  return self:observe(), self:info()
end

-- L292-336: one simulator step's reward and whether the episode ends.
function E:reward()
  local r, done = 0, false
  if self.wpt_dis < DISTANCE_MARGIN and self.waypoint_reached ~= 1 then
    self.waypoint_reached = 1
    r, done = REACH_REWARD, true
  end
  local drift = math.abs(math.rad(self.drift))
  self.drift_sum, self.drift_n = self.drift_sum + drift, self.drift_n + 1
  r = r + drift * DRIFT_PENALTY
  local lat, lon = self.sim:values(ACID)
  local inside = self.areas:count_inside(lat, lon)
  if inside > 0 then
    done, self.crashed = true, 1
    r = r + inside * RESTRICTED_AREA_INTRUSION_PENALTY  -- the intrusion terms summed apart, as L295-297 do
  end
  return r, done
end

function E:step(action)
  -- L338-345: HDG to the wrapped current heading + 45 deg per unit; SPD to (CAS + 20/3 m/s per unit) in knots.
  local _, _, _, hdg, _, _, _, cas = self.sim:values(ACID)
  assert(self.sim:exec(string.format("HDG %s %.17g", ACID, geo.gym_wrap180(hdg + action[1] * D_HEADING))))
  assert(self.sim:exec(string.format("SPD %s %.17g", ACID, (cas + action[2] * D_SPEED) * MPS2KT)))
  local reward, done
  for _ = 1, ACTION_FREQUENCY do                         -- L134-143
    self.sim:step(1)
    reward, done = self:reward()
    if done then break end
  end
  local obs = self:observe()
  self.total_reward = self.total_reward + reward
  return obs, reward, done, false, self:info()
end

return E
