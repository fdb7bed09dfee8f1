-- BlueSky-Gym MergeEnv-v0 as one Lua file over squawk's C++ kernels.
--
-- Facts from TUDelft-CNS-ATM/bluesky-gym at aed26d6
-- (bluesky_gym/envs/merge_env.py cited as L<line>, common/functions.py as
-- fn:<line>; the registration in bluesky_gym/__init__.py); nothing is copied.
-- An arrival stream: 19 A320s at 10 000 m and CAS 100 m/s fly a route to a
-- fix 200 km north of a runway near Amsterdam, then to the runway. The
-- agent (KL001) starts 50-200 km beyond the fix within +-15 deg of north,
-- and steers by up to 15 deg and 20 m/s per step of 10 x 5 s. It earns 1
-- when it comes within 10 NM of the fix, pays 0.1 per radian off the
-- bearing to its aim point (the fix, then the runway) and 1 per intruder
-- within 4 NM; the episode ends within 20 NM of the runway after the fix,
-- or after 50 steps. Units: degrees, metres, m/s, NM as named.

local C = require("traffic_cr")
local Draws = require("gym_draws")
local geo = squawk.geo

local DISTANCE_MARGIN = 10                           -- L12: "km", compared with NM (L260-264)
local REACH_REWARD = 1                               -- L13
local INTRUSION_PENALTY = -1                         -- L16
local INTRUSION_DISTANCE = 4                         -- [NM] L18
local SPAWN_DISTANCE_MIN, SPAWN_DISTANCE_MAX = 50, 200        -- [km] L20-21
local INTRUDER_DISTANCE_MIN, INTRUDER_DISTANCE_MAX = 20, 500  -- [km] L23-24
local D_HEADING, D_SPEED = 15, 20                    -- [deg], [m/s] per unit of action L26-27;
                                                     -- D_HEADING is also the spawn sector half-width (L114, L149)
local AC_SPD = 100                                   -- [m/s CAS] L29
local AC_ALT = 10000                                 -- [m] L118, L153
local NM2KM = 1.852                                  -- L31
local ACTION_FREQUENCY = 10                          -- L34, 5 s steps ('DT 5;FF', L85)
local NUM_AC = 20                                    -- L36, the agent included
local NUM_AC_STATE = 5                               -- L37
local RWY_LAT, RWY_LON = 52.36239301495972, 4.713195734579777  -- [deg] L40-41
local ACID = "KL001"

-- fn:24-42 get_point_at_distance (km, a 6371 km sphere) is squawk.geo.destination (m).
local function point_at_distance(lat, lon, d_km, bearing)
  return geo.destination(lat, lon, bearing, d_km * 1000)
end

local FIX_LAT, FIX_LON = point_at_distance(RWY_LAT, RWY_LON, 200, 0)  -- L43-45: 200 "NM", in km

local M = {
  id = "MergeEnv-v0",
  source = "bluesky-gym@aed26d6 bluesky_gym/envs/merge_env.py",
  -- spaces.Dict (L58-73) flattened as gymnasium does: keys sorted; 40 numbers.
  observation = {
    {name = "airspeed", size = 1},               -- tas [m/s], unscaled (L190, L223)
    {name = "cos(drift)", size = 1},             -- cos(heading - bearing to the aim point) (L185)
    {name = "cos(track)", size = NUM_AC_STATE},  -- cos of the relative velocity's angle (L213-214)
    {name = "distances", size = NUM_AC_STATE},   -- kwikdist [NM] / 250 (L194, L232)
    {name = "faf_reached", size = 1},            -- 0 before the fix, 1 after (L225)
    {name = "sin(drift)", size = 1},             -- (L186)
    {name = "sin(track)", size = NUM_AC_STATE},  -- (L215)
    {name = "vx_r", size = NUM_AC_STATE},        -- north relative velocity / 150 [m/s] (L209, L228)
    {name = "vy_r", size = NUM_AC_STATE},        -- east relative velocity / 150 [m/s] (L210, L229)
    {name = "waypoint_dist", size = 1},          -- distance to the aim point [NM] / 250 (L188, L224)
    {name = "x_r", size = NUM_AC_STATE},         -- north offset / 1e6 [m] (L202-203, L226)
    {name = "y_r", size = NUM_AC_STATE},         -- east offset / 1e6 [m] (L204, L227)
  },
  action = {low = {-1, -1}, high = {1, 1}},      -- spaces.Box(-1, 1, (2,)) (L75)
  max_episode_steps = 50,   -- __init__.py register("MergeEnv-v0", ..., max_episode_steps=50)
}

-- One aircraft at distance [km] and bearing [deg] from the fix, heading
-- bearing - 180 (L114-118, L149-153; traf.cre keeps the heading unwrapped).
function M:spawn(id, dmin, dmax)
  local bearing = C.uniform(self.draws, -D_HEADING, D_HEADING)
  local distance = C.uniform(self.draws, dmin, dmax)
  local lat, lon = point_at_distance(FIX_LAT, FIX_LON, distance, bearing)
  self.sim:create{id = id, type = "A320", lat = lat, lon = lon, hdg_deg = bearing - 180, alt_m = AC_ALT,
                  spd = AC_SPD}
end

function M:reset(seed, options)
  self.sim = self.sim or squawk.sim.new{dt_s = 5}
  self.sim:delete_all()
  self.draws = Draws.new(seed, options and options.draws)
  self.wpt_reach, self.faf_reached = 0, 0
  self.total_reward, self.total_intrusions = 0, 0
  self:spawn(ACID, SPAWN_DISTANCE_MIN, SPAWN_DISTANCE_MAX)
  -- L147-157: the stream, each on a route to the fix with the runway as destination.
  self.ids = {}
  for i = 0, NUM_AC - 2 do
    local id = "INT" .. i
    self.ids[#self.ids + 1] = id
    self:spawn(id, INTRUDER_DISTANCE_MIN, INTRUDER_DISTANCE_MAX)
    assert(self.sim:exec(string.format("ADDWPT %s %.17g %.17g", id, FIX_LAT, FIX_LON)))
    assert(self.sim:exec(string.format("DEST %s %.17g %.17g", id, RWY_LAT, RWY_LON)))
  end
  assert(self.sim:exec("RESO OFF"))
  return self:observe(), self:info()
end

-- L159-235.
function M:observe()
  local lat, lon, _, hdg, tas = self.sim:values(ACID)
  local aim_lat, aim_lon = FIX_LAT, FIX_LON
  if self.wpt_reach ~= 0 then aim_lat, aim_lon = RWY_LAT, RWY_LON end
  local drift
  drift, self.waypoint_dist = C.drift(hdg, lat, lon, aim_lat, aim_lon)
  self.drift = drift
  local rel = {}
  for i, id in ipairs(self.ids) do
    local ilat, ilon, _, ihdg, itas = self.sim:values(id)
    local brg, dist = geo.kwikqdrdist(lat, lon, ilat, ilon)
    local m = dist * NM2KM * 1000
    rel[i] = {m * math.cos(math.rad(brg)), m * math.sin(math.rad(brg)), ihdg, itas,
              geo.kwikdist(lat, lon, ilat, ilon)}
  end
  local t = C.nearest({hdg, tas}, rel, NUM_AC_STATE)
  local d = math.rad(drift)
  local function scale(s) return function(v) return v / s end end
  return C.flat{
    tas, math.cos(d), t.cos, C.map(t.dist, scale(250)), self.wpt_reach, math.sin(d), t.sin,
    C.map(t.vx, scale(150)), C.map(t.vy, scale(150)), self.waypoint_dist / 250,
    C.map(t.x, scale(1000000)), C.map(t.y, scale(1000000)),
  }
end

function M:info()
  -- info.success: no intruder within 4 NM at any step of the episode.
  return {total_reward = self.total_reward, faf_reach = self.faf_reached,
          total_intrusions = self.total_intrusions, success = self.total_intrusions == 0}
end

-- L256-267: the fix reached pays once; then the runway within 2 margins ends it.
function M:check_waypoint()
  if self.waypoint_dist < DISTANCE_MARGIN and self.wpt_reach ~= 1 then
    self.wpt_reach, self.faf_reached = 1, 1
    return REACH_REWARD, false
  elseif self.waypoint_dist < 2 * DISTANCE_MARGIN and self.wpt_reach == 1 then
    self.faf_reached = 2
    return 0, true
  end
  return 0, false
end

-- L131-145, L245-254.
function M:step(action)
  C.command(self.sim, ACID, action, D_HEADING, D_SPEED)
  self.sim:step(ACTION_FREQUENCY)
  local obs = self:observe()
  local reach, done = self:check_waypoint()
  local n = C.intrusions(self.sim, ACID, self.ids, INTRUSION_DISTANCE)
  self.total_intrusions = self.total_intrusions + n
  local reward = reach + C.drift_reward(self.drift) + n * INTRUSION_PENALTY
  self.total_reward = self.total_reward + reward
  return obs, reward, done, false, self:info()
end

return M
