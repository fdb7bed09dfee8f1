-- BlueSky-Gym VerticalCREnv-v0 as one Lua file: the descent of envs/descent.lua
-- with five intruders in conflict, and a penalty per intrusion.
--
-- Facts from TUDelft-CNS-ATM/bluesky-gym at aed26d6
-- (bluesky_gym/envs/vertical_cr_env.py, cited as L<line>; nothing copied).
-- The ownship, the action (vertical speed 12.5 m/s per unit, 30 x 1 s steps),
-- the altitude reward terms and the termination are DescentEnv's, with the
-- same constants (L15-17, L24-42); what is new: at reset five A320s are
-- created in conflict with the ownship (BlueSky's creconfs), each at its own
-- altitude offset, flying level; each step costs -50 per intruder within
-- 5 NM horizontally and 1000 ft vertically. BlueSky-Gym clears the traffic
-- at every reset (L260). Units: metres, m/s, km as named.

local Descent = require("descent")
local geo = squawk.geo

local ACID = "KL001"
local NM = 1852                               -- [m]
local NM2KM = 1.852                           -- L12
local INTRUSION_PENALTY = -50                 -- L14, per intruder per step
local INTRUSION_DISTANCE = 5                  -- [NM] L20
local VERTICAL_MARGIN = 1000 * 0.3048         -- [m] L21
local ALT_STD = 3000                          -- [m] L25
local DEFAULT_RWY_DIS = 200                   -- [km] L30; also the intruder distance scale (L171)
local ACTION_2_MS = 12.5                      -- [m/s] L34
local AC_SPD = 150                            -- [m/s] L40; the speed scale of x/y differences (L175-176)
local NUM_INTRUDERS = 5                       -- L44 (it replaces L19's 3)
local TLOSV = 100000000000.                   -- [s] L195: no vertical convergence

-- Python's int(): toward zero.
local function int(x) return x >= 0 and math.floor(x) or math.ceil(x) end

local V = setmetatable({
  id = "VerticalCREnv-v0",
  source = "bluesky-gym@aed26d6 bluesky_gym/envs/vertical_cr_env.py",
  -- spaces.Dict (L66-82) flattened as gymnasium does: keys sorted; 39 numbers.
  observation = {
    {name = "altitude", size = 1},                     -- (alt - 1500) / 3000 (L160)
    {name = "altitude_difference", size = NUM_INTRUDERS},  -- (alt_i - alt) / 3000 (L138, L174)
    {name = "cos_difference_pos", size = NUM_INTRUDERS},   -- cos(wrap(hdg - qdr_i)) (L144-147)
    {name = "intruder_distance", size = NUM_INTRUDERS},    -- km / 200 (L134-136, L171)
    {name = "runway_distance", size = 1},              -- (d - 100) / 200 (L157, L163)
    {name = "sin_difference_pos", size = NUM_INTRUDERS},   -- sin(wrap(hdg - qdr_i)) (L148)
    {name = "target_altitude", size = 1},              -- (target - 1500) / 3000 (L162)
    {name = "vz", size = 1},                           -- vs / 5 (L161)
    {name = "x_difference_speed", size = NUM_INTRUDERS},   -- -cos(hdg - hdg_i) gs_i / 150 (L150-151, L175)
    {name = "y_difference_speed", size = NUM_INTRUDERS},   -- (gs - sin(hdg - hdg_i) gs_i) / 150 (L152, L176)
    {name = "z_difference_speed", size = NUM_INTRUDERS},   -- vs_i - vs [m/s], unscaled (L139, L177)
  },
  max_episode_steps = 300,  -- __init__.py register("VerticalCREnv-v0", ..., max_episode_steps=300)
}, {__index = Descent})

-- L182-199: per intruder dpsi [deg], cpa [NM], tlosh [s] and an altitude
-- offset dH [m] drawn below the target altitude when the loss of separation
-- comes after the average top of descent, else around it.
function V:generate_conflicts()
  local _, _, altitude, _, _, spd = self.sim:values(ACID)
  for i = 0, NUM_INTRUDERS - 1 do
    local dpsi = self:randint(45, 315)
    local cpa = self:randint(0, INTRUSION_DISTANCE)
    local tlosh = self:randint(100, int((DEFAULT_RWY_DIS * 0.9) * 1000 / spd))
    local average_tod = (DEFAULT_RWY_DIS * 1000 / spd) - 2 * self.target_alt / ACTION_2_MS
    local dH
    if tlosh > average_tod then
      dH = self:randint(int(-altitude + 500), int((self.target_alt - altitude) + 100))
    else
      dH = self:randint(int((self.target_alt - altitude) - 500), int((self.target_alt - altitude) + 500))
    end
    local id = tostring(i)
    self.sim:creconfs{id = id, type = "A320", target = ACID, dpsi_deg = dpsi, dcpa_m = cpa * NM,
                      tlosh_s = tlosh, dh_m = dH, tlosv_s = TLOSV}
    -- L198-199: the intruder holds ownship altitude + dH (selaltcmd without a V/S)
    self.sim:select_vertical(id, altitude + dH, 0)
  end
end

function V:reset(seed, options)
  self:start(seed, options)
  self.total_intrusions = 0
  self:generate_conflicts()
  return self:observe(), self:info()
end

function V:observe()
  local own = Descent.observe(self)  -- altitude, runway_distance, target_altitude, vz
  local lat, lon, _, hdg, _, gs = self.sim:values(ACID)
  local ad, c, d, sn, x, y, z = {}, {}, {}, {}, {}, {}, {}
  for i = 1, NUM_INTRUDERS do
    local ilat, ilon, ialt, ihdg, _, igs, ivs = self.sim:values(tostring(i - 1))
    local qdr, dist = geo.kwikqdrdist(lat, lon, ilat, ilon)
    d[i] = dist * NM2KM / DEFAULT_RWY_DIS
    local b = math.rad(geo.gym_wrap180(hdg - qdr))
    c[i], sn[i] = math.cos(b), math.sin(b)
    ad[i] = (ialt - self.altitude) / ALT_STD
    local dh = math.rad(hdg - ihdg)
    x[i] = -math.cos(dh) * igs / AC_SPD
    y[i] = (gs - math.sin(dh) * igs) / AC_SPD
    z[i] = ivs - self.vz
  end
  local obs = {own[1]}
  local function add(t) for _, v in ipairs(t) do obs[#obs + 1] = v end end
  add(ad); add(c); add(d)
  obs[#obs + 1] = own[2]
  add(sn)
  obs[#obs + 1] = own[3]
  obs[#obs + 1] = own[4]
  add(x); add(y); add(z)
  return obs
end

-- L229-239: horizontal kwikqdrdist distance and altitude difference.
function V:intrusion_reward()
  local lat, lon, alt = self.sim:values(ACID)
  local r = 0
  for i = 0, NUM_INTRUDERS - 1 do
    local ilat, ilon, ialt = self.sim:values(tostring(i))
    local _, dist = geo.kwikqdrdist(lat, lon, ilat, ilon)
    if dist < INTRUSION_DISTANCE and math.abs(alt - ialt) < VERTICAL_MARGIN then
      self.total_intrusions = self.total_intrusions + 1
      r = r + INTRUSION_PENALTY
    end
  end
  return r
end

-- L212-227: intrusions plus DescentEnv's altitude terms.
function V:reward()
  local int_penalty = self:intrusion_reward()
  local alt_penalty, done = self:altitude_reward()
  local r = alt_penalty + int_penalty
  self.total_reward = self.total_reward + r
  return r, done
end

function V:info()
  -- info.success: DescentEnv's (a finished descent) with no intrusion on the way.
  return {total_reward = self.total_reward, total_intrusions = self.total_intrusions,
          final_altitude = self.final_altitude, success = self:landed() and self.total_intrusions == 0}
end

return V
