-- BlueSky-Gym DescentEnv-v0 as one Lua file over squawk's C++ kernels.
--
-- Every number below is a fact read from TUDelft-CNS-ATM/bluesky-gym at
-- aed26d6 (bluesky_gym/envs/descent_env.py, cited as L<line>; the
-- registration in bluesky_gym/__init__.py); nothing is copied.
-- One A320 (KL001) starts at 52 N 4 E heading north at 150 m/s CAS and an
-- altitude drawn in [2000, 3999] m; the target altitude is that plus
-- [-500, 499] m. The action in [-1, 1] is a vertical speed of 12.5 m/s per
-- unit, held for 30 one-second simulator steps. The episode ends when the
-- aircraft passes the runway, 200 km flown from its start (reward -altitude/60),
-- or touches the ground (-100); before that each step pays -|target - altitude|/600.
-- Units: metres, m/s, km as named.

local geo = squawk.geo

local ALT_MEAN, ALT_STD = 1500, 3000          -- [m] L10-11, observation normalisation
local VZ_MEAN, VZ_STD = 0, 5                  -- [m/s] L12-13
local RWY_DIS_MEAN, RWY_DIS_STD = 100, 200    -- [km] L14-15
local ACTION_2_MS = 12.5                      -- [m/s per unit of action] L17
local ALT_DIF_REWARD_SCALE = -5 / 3000        -- [1/m] L19
local CRASH_PENALTY = -100                    -- L20
local RWY_ALT_DIF_REWARD_SCALE = -50 / 3000   -- [1/m] L21
local ALT_MIN, ALT_MAX = 2000, 4000           -- [m] L23-24, np.random.randint(ALT_MIN, ALT_MAX) (L169): [2000, 3999]
local TARGET_ALT_DIF = 500                    -- [m] L25, randint(-500, 500) (L170): [-500, 499]
local AC_SPD = 150                            -- L27, passed raw to traf.cre (L172): CAS 150 m/s
local ACTION_FREQUENCY = 30                   -- L29, bs.sim.step() calls per env step (L187-189)
local SIM_DT = 1                              -- [s] 'DT 1;FF' (L71)
local DEFAULT_RWY_DIS = 200                   -- [km] L94
local RWY_LAT, RWY_LON = 52, 4                -- [deg] L95-96; also traf.cre's default position
local NM2KM = 1.852                           -- L97
local CLIMB_ALT, DESCEND_ALT = 1000000, 0     -- [m] selected altitude for a climb / descent (L155, L158)
local ACID = "KL001"
-- info.success (squawk's definition; BlueSky-Gym has none): the aircraft
-- passed the runway airborne, at most 1000 ft above it (the vertical margin
-- of VerticalCREnv, L21 there): a finished descent, not a crash or a fly-over.
local SUCCESS_MAX_ALT = 1000 * 0.3048         -- [m]

local Descent = {
  id = "DescentEnv-v0",
  source = "bluesky-gym@aed26d6 bluesky_gym/envs/descent_env.py",
  -- spaces.Dict (L52-59) flattened as gymnasium does: keys sorted.
  observation = {
    {name = "altitude", size = 1},          -- (alt - 1500) / 3000, alt [m] (L104)
    {name = "runway_distance", size = 1},   -- (d - 100) / 200, d [km] to go (L101, L107)
    {name = "target_altitude", size = 1},   -- (target - 1500) / 3000 (L106)
    {name = "vz", size = 1},                -- vs / 5, vs [m/s] (L105)
  },
  action = {low = {-1}, high = {1}},        -- spaces.Box(-1, 1, (1,)) (L61)
  max_episode_steps = 300,                  -- __init__.py register(..., max_episode_steps=300)
}

-- The observation and the values the reward reads (L99-101).
function Descent:observe()
  local lat, lon, alt, _, _, _, vs = self.sim:values(ACID)
  self.altitude, self.vz = alt, vs
  self.runway_distance = DEFAULT_RWY_DIS - geo.kwikdist(RWY_LAT, RWY_LON, lat, lon) * NM2KM
  return {
    (alt - ALT_MEAN) / ALT_STD,
    (self.runway_distance - RWY_DIS_MEAN) / RWY_DIS_STD,
    (self.target_alt - ALT_MEAN) / ALT_STD,
    (vs - VZ_MEAN) / VZ_STD,
  }
end

-- Whether the episode so far meets info.success (above).
function Descent:landed()
  return self.final_altitude > 0 and self.final_altitude <= SUCCESS_MAX_ALT
end

function Descent:info()
  return {total_reward = self.total_reward, final_altitude = self.final_altitude, success = self:landed()}
end

-- numpy's np.random.randint(lo, hi): a whole number in [lo, hi). The
-- episode's draws come from the engine's generator seeded at reset, or, to
-- replay a recorded BlueSky-Gym episode, from options.draws in order.
function Descent:randint(lo, hi)
  if self.draws then
    self.ndraws = self.ndraws + 1
    return assert(self.draws[self.ndraws], "options.draws ran out")
  end
  return math.random(lo, hi - 1)
end

-- The sim (kept across episodes, as BlueSky-Gym keeps BlueSky's) and the
-- ownship of a new episode (L161-173).
function Descent:start(seed, options)
  self.sim = self.sim or squawk.sim.new{dt_s = SIM_DT}
  -- BlueSky-Gym's descent never clears traffic at reset; it deletes the
  -- aircraft when an episode terminates (L200-203). Clearing here also
  -- covers an episode cut by the 300-step limit, which the descent never
  -- reaches (it passes the runway within about 45 steps).
  self.sim:delete_all()
  math.randomseed(seed)
  self.draws, self.ndraws = options and options.draws, 0
  self.total_reward, self.final_altitude = 0, 0
  local alt_init = self:randint(ALT_MIN, ALT_MAX)
  self.target_alt = alt_init + self:randint(-TARGET_ALT_DIF, TARGET_ALT_DIF)
  -- traf.cre defaults: 52 N 4 E, heading 0 (L172; docs/bluesky_facts.md §1.3); VNAV off (L173).
  self.sim:create{id = ACID, type = "A320", lat = RWY_LAT, lon = RWY_LON, hdg_deg = 0,
                  alt_m = alt_init, spd = AC_SPD}
end

function Descent:reset(seed, options)
  self:start(seed, options)
  return self:observe(), self:info()
end

-- L127-143: shaping while airborne before the runway, then one final term
-- (the altitude terms; an environment built on this one adds its own).
function Descent:altitude_reward()
  local r, done
  if self.runway_distance > 0 and self.altitude > 0 then
    r, done = math.abs(self.target_alt - self.altitude) * ALT_DIF_REWARD_SCALE, false
  elseif self.altitude <= 0 then
    r, done = CRASH_PENALTY, true
    self.final_altitude = -100
  else
    r, done = self.altitude * RWY_ALT_DIF_REWARD_SCALE, true
    self.final_altitude = self.altitude
  end
  return r, done
end

function Descent:reward()
  local r, done = self:altitude_reward()
  self.total_reward = self.total_reward + r
  return r, done
end

function Descent:step(action)
  -- L145-159: climb to a high or descend to a zero selected altitude at
  -- |a| * 12.5 m/s (a magnitude <= 0.1 m/s flies BlueSky's default 1500 ft/min).
  local vs = action[1] * ACTION_2_MS
  self.sim:select_vertical(ACID, vs >= 0 and CLIMB_ALT or DESCEND_ALT, vs)
  self.sim:step(ACTION_FREQUENCY)
  local obs = self:observe()
  local reward, terminated = self:reward()
  if terminated then self.sim:delete_all() end
  return obs, reward, terminated, false, self:info()
end

return Descent
