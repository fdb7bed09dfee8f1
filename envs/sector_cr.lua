-- BlueSky-Gym SectorCREnv-v0 as one Lua file over squawk's C++ kernels.
--
-- Facts from TUDelft-CNS-ATM/bluesky-gym at aed26d6
-- (bluesky_gym/envs/sector_cr_env.py cited as L<line>, common/functions.py as
-- fn:<line>; the registration in bluesky_gym/__init__.py); nothing is copied.
-- A random convex-ish polygon of 2400-3750 NM^2 around TU Delft; 5 or more
-- A320s (density ~ N(0.005, 0.001) per NM^2) start inside it at 350 m and
-- CAS 150 m/s, each heading for its own point on the border. The agent
-- (KL001) turns by up to 22.5 deg and changes speed by up to 20/3 m/s per
-- step of 5 x 1 s; it pays 0.1 per radian off its waypoint bearing and 1 per
-- intruder within 5 NM. The episode is truncated (never terminated) when
-- the agent leaves the sector, or after 200 steps.
-- Units: NM in the sector's flat frame (x north, y east), metres, m/s.

local C = require("traffic_cr")
local Draws = require("gym_draws")
local F = require("gym_functions")
local geo = squawk.geo

local AC_DENSITY_MU, AC_DENSITY_SIGMA = 0.005, 0.001  -- [AC/NM^2] L11-12 ("normal" mode, L97-99)
local POLY_AREA_MIN, POLY_AREA_MAX = 2400, 3750      -- [NM^2] L14
local CENTER_LAT, CENTER_LON = 51.990426702297746, 4.376124857109851  -- [deg] L15
local ALTITUDE = 350  -- L16: "FL", passed raw to traf.cre (L210): 350 m; the inside tests
                      -- (L135, L202) pass FL350 in m, within the area's +-1e9 m
local AC_SPD = 150                                   -- [m/s CAS] L19
local ACTOR = "KL001"                                -- L21
local NM2KM = 1.852                                  -- L24
local INTRUSION_DISTANCE = 5                         -- [NM] L28
local ACTION_FREQUENCY = 5                           -- L31, 1 s steps ('DT 1;FF', L76)
local NUM_AC_STATE = 4                               -- L32
local INTRUSION_PENALTY = -1                         -- L34
local D_HEADING, D_VELOCITY = 22.5, 20 / 3           -- [deg], [m/s] per unit of action, L35-36

local S = {
  id = "SectorCREnv-v0",
  source = "bluesky-gym@aed26d6 bluesky_gym/envs/sector_cr_env.py",
  -- spaces.Dict (L51-64) flattened as gymnasium does: keys sorted; 31 numbers.
  observation = {
    {name = "airspeed", size = 1},               -- (tas - 150) / 6 [m/s] (L302)
    {name = "cos(drift)", size = 1},             -- cos(heading - bearing to waypoint) (L264)
    {name = "cos(track)", size = NUM_AC_STATE},  -- cos of the relative velocity's angle (L293-294)
    {name = "distances", size = NUM_AC_STATE},   -- (d - 50000) / 15000, d [m] flat (L274, L309)
    {name = "sin(drift)", size = 1},             -- (L265)
    {name = "sin(track)", size = NUM_AC_STATE},  -- (L295)
    {name = "vx_r", size = NUM_AC_STATE},        -- north relative velocity / 32 [m/s] (L289, L305)
    {name = "vy_r", size = NUM_AC_STATE},        -- east relative velocity / 66 [m/s] (L290, L306)
    {name = "x_r", size = NUM_AC_STATE},         -- north offset / 13000 [m] (L283, L303)
    {name = "y_r", size = NUM_AC_STATE},         -- east offset / 13000 [m] (L284, L304)
  },
  action = {low = {-1, -1}, high = {1, 1}},      -- spaces.Box(-1, 1, (2,)) (L66)
  max_episode_steps = 200,  -- __init__.py register("SectorCREnv-v0", ..., max_episode_steps=200)
}

local COS_CENTER = math.cos(math.rad(CENTER_LAT))

-- fn:98-114 and fn:116-132: the sector's flat frame [NM] <-> lat/lon [deg].
local function nm_to_latlon(x, y)
  return F.nm_to_latlong(CENTER_LAT, CENTER_LON, {x, y})
end
local function latlon_to_nm(lat, lon)
  return (lat - CENTER_LAT) * 60, (lon - CENTER_LON) * 60 * COS_CENTER
end

-- fn:150-177: initial great-circle bearing [deg, 0..360) from one point to another.
local function get_hdg(lat1, lon1, lat2, lon2)
  lat1, lon1, lat2, lon2 = math.rad(lat1), math.rad(lon1), math.rad(lat2), math.rad(lon2)
  local dlon = lon2 - lon1
  local x = math.sin(dlon) * math.cos(lat2)
  local y = math.cos(lat1) * math.sin(lat2) - math.sin(lat1) * math.cos(lat2) * math.cos(dlon)
  return math.fmod(math.deg(math.atan(x, y)) + 360, 360)
end

-- L140-159: three points on the circle of area 3750 NM^2, more until the
-- polygon they span has 2400 NM^2; the area "airspace" in lat/lon.
function S:generate_polygon()
  local r = math.sqrt(POLY_AREA_MAX / math.pi)
  local p = {}
  for k = 1, 3 do p[k] = F.random_point_on_circle(r, self.draws) end
  F.sort_points_clockwise(p)
  local area = F.polygon_area(p)
  while area < POLY_AREA_MIN do
    p[#p + 1] = F.random_point_on_circle(r, self.draws)
    F.sort_points_clockwise(p)
    area = F.polygon_area(p)
  end
  self.poly_area, self.poly_points, self.poly = area, p, {}
  for _, q in ipairs(p) do
    local lat, lon = nm_to_latlon(q[1], q[2])
    self.poly[#self.poly + 1], self.poly[#self.poly + 2] = lat, lon
  end
end

-- fn:134-148.
local function euclid(x1, y1, x2, y2)
  local dx, dy = x2 - x1, y2 - y1
  return math.sqrt(dx * dx + dy * dy)
end

-- L161-187: one waypoint per aircraft at sorted uniform arc lengths along the border.
function S:generate_waypoints()
  local p, edges, perim = self.poly_points, {}, 0
  for i = 1, #p do
    local a, b = p[i], p[i % #p + 1]
    local len = euclid(a[1], a[2], b[1], b[2])
    edges[i] = {a, b, len}
    perim = perim + len
  end
  local d = {}
  for k = 1, self.num_ac do d[k] = C.uniform(self.draws, 0, perim) end
  table.sort(d)
  self.wpts = {}
  local current, e = 0, 1
  for k, dk in ipairs(d) do
    while dk > current + edges[e][3] do
      current = current + edges[e][3]
      e = e + 1
    end
    local a, b, len = edges[e][1], edges[e][2], edges[e][3]
    local frac = (dk - current) / len
    self.wpts[k] = {a[1] + frac * (b[1] - a[1]), a[2] + frac * (b[2] - a[2])}
  end
end

-- The name of aircraft k (1-based): the agent, then "1", "2", ... (L210, L216).
function S:acid(k)
  return k == 1 and ACTOR or tostring(k - 1)
end

-- L189-216: starts uniform in the bounding box, kept when inside the sector;
-- each aircraft heads for its own waypoint. Aircraft 0 is the agent.
function S:generate_ac()
  local min_x, min_y, max_x, max_y = math.huge, math.huge, -math.huge, -math.huge
  for _, q in ipairs(self.poly_points) do
    min_x, max_x = math.min(min_x, q[1]), math.max(max_x, q[1])
    min_y, max_y = math.min(min_y, q[2]), math.max(max_y, q[2])
  end
  local starts = {}
  while #starts < self.num_ac do
    local x = C.uniform(self.draws, min_x, max_x)
    local y = C.uniform(self.draws, min_y, max_y)
    local lat, lon = nm_to_latlon(x, y)
    if geo.inside(lat, lon, self.poly) then starts[#starts + 1] = {lat, lon} end
  end
  self.acids, self.ids = {}, {}
  for k, s in ipairs(starts) do
    local id = self:acid(k)
    self.acids[k] = id
    if k > 1 then self.ids[#self.ids + 1] = id end
    local wlat, wlon = nm_to_latlon(self.wpts[k][1], self.wpts[k][2])
    self.sim:create{id = id, type = "A320", lat = s[1], lon = s[2], hdg_deg = get_hdg(s[1], s[2], wlat, wlon),
                    alt_m = ALTITUDE, spd = AC_SPD}
  end
end

function S:reset(seed, options)
  self.sim = self.sim or squawk.sim.new{dt_s = 1}
  self.sim:delete_all()
  self.draws = Draws.new(seed, options and options.draws)
  self.total_reward, self.total_intrusions = 0, 0
  self:generate_polygon()
  -- L97-99: int(max(ceil(density * area), NUM_AC_STATE + 1))
  local density = C.normal(self.draws, AC_DENSITY_MU, AC_DENSITY_SIGMA)
  self.num_ac = math.floor(math.max(math.ceil(density * self.poly_area), NUM_AC_STATE + 1))
  self:generate_waypoints()
  self:generate_ac()
  return self:observe(), self:info()
end

-- L236-312: the observation of aircraft `own` flying to waypoint `wpt`
-- ({x, y} NM) among the aircraft named in `others`, and its drift [deg].
function S:observe_aircraft(own, wpt, others)
  local lat, lon, _, hdg, tas = self.sim:values(own)
  local wlat, wlon = nm_to_latlon(wpt[1], wpt[2])
  local drift = C.drift(hdg, lat, lon, wlat, wlon)
  local ox, oy = latlon_to_nm(lat, lon)
  ox, oy = ox * NM2KM * 1000, oy * NM2KM * 1000
  local rel = {}
  for i, id in ipairs(others) do
    local ilat, ilon, _, ihdg, itas = self.sim:values(id)
    local x, y = latlon_to_nm(ilat, ilon)
    x, y = x * NM2KM * 1000, y * NM2KM * 1000
    rel[i] = {x - ox, y - oy, ihdg, itas, euclid(ox, oy, x, y)}
  end
  local t = C.nearest({hdg, tas}, rel, NUM_AC_STATE)
  local d = math.rad(drift)
  return C.flat{
    (tas - 150) / 6, math.cos(d), t.cos,
    C.map(t.dist, function(v) return (v - 50000.) / 15000. end),
    math.sin(d), t.sin,
    C.map(t.vx, function(v) return v / 32 end), C.map(t.vy, function(v) return v / 66 end),
    C.map(t.x, function(v) return v / 13000 end), C.map(t.y, function(v) return v / 13000 end),
  }, drift
end

function S:observe()
  local obs
  obs, self.drift = self:observe_aircraft(ACTOR, self.wpts[1], self.ids)
  return obs
end

function S:info()
  -- info.success: no intruder within 5 NM at any step of the episode.
  return {total_reward = self.total_reward, total_intrusions = self.total_intrusions,
          success = self.total_intrusions == 0}
end

-- L116-131, L226-234, L133-138.
function S:step(action)
  C.command(self.sim, ACTOR, action, D_HEADING, D_VELOCITY)
  self.sim:step(ACTION_FREQUENCY)
  local obs = self:observe()
  local n = C.intrusions(self.sim, ACTOR, self.ids, INTRUSION_DISTANCE)
  self.total_intrusions = self.total_intrusions + n
  local reward = C.drift_reward(self.drift) + n * INTRUSION_PENALTY
  self.total_reward = self.total_reward + reward
  local lat, lon = self.sim:values(ACTOR)
  local outside = not geo.inside(lat, lon, self.poly)
  return obs, reward, false, outside, self:info()
end

return S
