-- VerticalCREnv-v0 with the rule's memory (envs/vertical_cr_history.lua, 45 numbers) and, per
-- intruder, the geometry of its straight-line conflict computed from those numbers: no
-- information beyond them. The episodes, rewards and infos are the base environment's, the id
-- is the base's. Each intruder flies at its observed relative position and velocity; the
-- ownship's ground speed is the last step's runway distance flown (runway_step), or
-- NOMINAL_GS_MS on the reset's observation. Appended (46-65), 5 numbers each, intruder i
-- in slot i:
--   cpa_time 46-50: steps until the closest approach, in [0, MAX_STEPS], / 10 (0 when opening),
--   cpa_distance 51-55: the horizontal distance at the closest approach, / 5 NM (the
--     intrusion distance: below 1 it passes inside the zone),
--   cpa_altitude_difference 56-60: the intruder's altitude minus the ownship's at the closest
--     approach, both vertical speeds held, / 3000 m (as altitude_difference),
--   threat 61-65: 1 when it is within 5 NM now or at some time in the next THREAT_STEPS steps,
--     else 0.
-- Units: km, m, m/s, steps of 30 s.

local History = require("vertical_cr_history")

local NUM_INTRUDERS = 5
local STEP_S = 30            -- [s] one env step
local ZONE_KM = 5 * 1.852    -- [km] horizontal intrusion distance
local NOMINAL_GS_MS = 165    -- [m/s] about the ownship's ground speed at 150 m/s CAS (reset only)
local MAX_STEPS = 20         -- [steps] cpa_time's cap
local THREAT_STEPS = 2       -- [steps] the rule's look-ahead

local observation = {}
for i, slice in ipairs(History.observation) do observation[i] = slice end
for _, name in ipairs({"cpa_time", "cpa_distance", "cpa_altitude_difference", "threat"}) do
  observation[#observation + 1] = {name = name, size = NUM_INTRUDERS}
end

local C = setmetatable({observation = observation}, {__index = History})

-- The conflict numbers of intruder i (1-based) from the 45-number observation `o`: cpa time
-- [steps], cpa distance [km], altitude difference at it [m], threat (0 or 1).
function C.conflict(o, i)
  local step_km = 200 * o[45]
  local gs = step_km > 0 and step_km * 1000 / STEP_S or NOMINAL_GS_MS         -- [m/s]
  local d = o[11 + i] * 200                                                   -- [km]
  local e, n = -d * o[17 + i], d * o[6 + i]                                   -- [km] right, ahead
  local ve = (150 * o[29 + i] - gs) * STEP_S / 1000                          -- [km/step]
  local vn = (-150 * o[24 + i] - gs) * STEP_S / 1000
  local v2 = ve * ve + vn * vn
  local t = v2 > 0 and math.max(0, math.min(MAX_STEPS, -(e * ve + n * vn) / v2)) or 0
  local function dist(s) return math.sqrt((e + ve * s) ^ 2 + (n + vn * s) ^ 2) end
  local dh = 3000 * o[1 + i] + o[34 + i] * STEP_S * t                         -- [m]
  local threat = (d < ZONE_KM or dist(math.min(t, THREAT_STEPS)) < ZONE_KM) and 1 or 0
  return t, dist(t), dh, threat
end

function C:extend(obs)
  local out = History.extend(self, obs)
  local t, m, h, th = {}, {}, {}, {}
  for i = 1, NUM_INTRUDERS do t[i], m[i], h[i], th[i] = C.conflict(out, i) end
  for i = 1, NUM_INTRUDERS do out[#out + 1] = t[i] / 10 end
  for i = 1, NUM_INTRUDERS do out[#out + 1] = m[i] / ZONE_KM end
  for i = 1, NUM_INTRUDERS do out[#out + 1] = h[i] / 3000 end
  for i = 1, NUM_INTRUDERS do out[#out + 1] = th[i] end
  return out
end

return C
