-- BlueSky-Gym PlanWaypointEnv-v0 as one Lua file over squawk's C++ kernels.
--
-- Every number below is a fact read from TUDelft-CNS-ATM/bluesky-gym at
-- aed26d6 (bluesky_gym/envs/plan_waypoint_env.py, cited as L<line>; the
-- registration in bluesky_gym/__init__.py); nothing is copied.
-- One A320 (KL001) at 52 N 4 E, altitude 0, heading north at CAS 150 m/s;
-- five waypoints at a whole number of km in [0, 74] and a whole bearing in
-- [0, 358] deg from it (great circle, R 6371 km). The action in [-1, 1]
-- turns the selected heading by 45 deg per unit from the current heading,
-- held for 10 one-second simulator steps. A waypoint closer than 5 km after
-- a step pays +1 once; the episode ends when all five are reached. Nothing
-- else is paid: no time or distance cost. Units: km, degrees as named.
--
-- As in BlueSky-Gym, the aircraft is deleted only when an episode ends with
-- all waypoints reached (L189-192): after an episode cut by the 300-step
-- limit, reset keeps the aircraft where it is (traf.cre refuses an existing
-- callsign) and draws the new waypoints around it (L161-163, L199-212).

local geo = squawk.geo
local Draws = require("gym_draws")

local DISTANCE_MARGIN = 5                     -- [km] L10
local WAYPOINT_DISTANCE_MIN, WAYPOINT_DISTANCE_MAX = 0, 75  -- [km] L11-12; randint: [0, 74] (L204)
local NUM_WAYPOINTS = 5                       -- L14
local REACH_REWARD = 1                        -- L16
local AC_SPD = 150                            -- L17, passed raw to traf.cre (L161): CAS 150 m/s
local D_HEADING = 45                          -- [deg per unit of action] L19
local ACTION_FREQUENCY = 10                   -- L21, bs.sim.step() calls per env step (L176-178)
local SIM_DT = 1                              -- [s] 'DT 1;FF' (L68)
local NM2KM = 1.852                           -- L92
local ACID = "KL001"

local E = {
  id = "PlanWaypointEnv-v0",
  source = "bluesky-gym@aed26d6 bluesky_gym/envs/plan_waypoint_env.py",
  -- spaces.Dict (L49-56) flattened as gymnasium does: keys sorted; 20 numbers.
  -- A reached waypoint reads 0 in the first three (L117-119).
  observation = {
    {name = "cos_difference", size = NUM_WAYPOINTS},     -- cos(wrap(hdg - qdr_i)) (L109-112)
    {name = "sin_difference", size = NUM_WAYPOINTS},     -- sin(wrap(hdg - qdr_i)) (L113)
    {name = "waypoint_distance", size = NUM_WAYPOINTS},  -- km / 75 (L106, L117)
    {name = "waypoint_reached", size = NUM_WAYPOINTS},   -- 0 or 1 (L120)
  },
  action = {low = {-1}, high = {1}},         -- spaces.Box(-1, 1, (1,)) (L58)
  max_episode_steps = 300,                   -- __init__.py register("PlanWaypointEnv-v0", ..., max_episode_steps=300)
}

-- L199-212: per waypoint a distance [km] and a bearing [deg] drawn from the
-- aircraft's position.
function E:generate_waypoints()
  local lat, lon = self.sim:values(ACID)
  self.wpt_lat, self.wpt_lon, self.wpt_reach = {}, {}, {}
  for i = 1, NUM_WAYPOINTS do
    local dis_km = self.draws:randint(WAYPOINT_DISTANCE_MIN, WAYPOINT_DISTANCE_MAX)
    local hdg = self.draws:randint(0, 359)
    self.wpt_lat[i], self.wpt_lon[i] = geo.destination(lat, lon, hdg, dis_km * 1000)  -- F24-42
    self.wpt_reach[i] = 0
  end
end

-- L85-123: distance and relative bearing of each waypoint, zeroed once reached.
function E:observe()
  local lat, lon, _, hdg = self.sim:values(ACID)
  self.hdg = hdg
  local c, s, d, reached = {}, {}, {}, {}
  self.wpt_dis = {}
  for i = 1, NUM_WAYPOINTS do
    local qdr, dist_nm = geo.kwikqdrdist(lat, lon, self.wpt_lat[i], self.wpt_lon[i])
    self.wpt_dis[i] = dist_nm * NM2KM
    local drift = math.rad(geo.gym_wrap180(hdg - qdr))
    local open = 1 - self.wpt_reach[i]
    c[i], s[i], d[i] = open * math.cos(drift), open * math.sin(drift), open * self.wpt_dis[i] / WAYPOINT_DISTANCE_MAX
    reached[i] = self.wpt_reach[i]
  end
  local obs = {}
  for _, t in ipairs({c, s, d, reached}) do
    for _, v in ipairs(t) do obs[#obs + 1] = v end
  end
  return obs
end

function E:info()
  -- info.success: all five waypoints reached (the episode's termination).
  return {total_reward = self.total_reward, waypoints_completed = self.waypoints_completed,
          success = self.waypoints_completed == NUM_WAYPOINTS}
end

function E:reset(seed, options)
  self.sim = self.sim or squawk.sim.new{dt_s = SIM_DT}
  self.draws = Draws.new(seed, options and options.draws)
  self.total_reward, self.waypoints_completed = 0, 0
  -- traf.cre defaults (L161): 52 N 4 E, heading 0, altitude 0; a no-op when KL001 still flies.
  if self.sim:count() == 0 then
    self.sim:create{id = ACID, type = "A320", lat = 52, lon = 4, hdg_deg = 0, alt_m = 0, spd = AC_SPD}
  end
  self:generate_waypoints()
  return self:observe(), self:info()
end

-- L214-226: +1 for each waypoint first seen within 5 km, by the distances of
-- the observation just taken (which therefore still shows it unreached).
function E:reward()
  local r = 0
  for i = 1, NUM_WAYPOINTS do
    if self.wpt_dis[i] < DISTANCE_MARGIN and self.wpt_reach[i] ~= 1 then
      self.waypoints_completed = self.waypoints_completed + 1
      self.wpt_reach[i] = 1
      r = r + REACH_REWARD
    end
  end
  self.total_reward = self.total_reward + r
  for i = 1, NUM_WAYPOINTS do
    if self.wpt_reach[i] == 0 then return r, false end   -- L142-145
  end
  return r, true
end

function E:step(action)
  -- L147-153: HDG to the current heading + 45 deg per unit, unwrapped (BlueSky's HDG takes it modulo 360).
  assert(self.sim:exec(string.format("HDG %s %.17g", ACID, self.hdg + action[1] * D_HEADING)))
  self.sim:step(ACTION_FREQUENCY)
  local obs = self:observe()
  local reward, terminated = self:reward()
  if terminated then self.sim:delete_all() end   -- L189-192
  return obs, reward, terminated, false, self:info()
end

return E
