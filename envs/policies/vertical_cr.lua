-- A scripted controller for VerticalCREnv-v0 (envs/vertical_cr.lua), for
-- `squawk env run envs/vertical_cr.lua --policy script:envs/policies/vertical_cr.lua`.
--
-- DescentEnv's rule (envs/policies/descent.lua), and one more a controller
-- would give: when an intruder is within 5 NM, or closing and will be within
-- 5 NM within the next two steps at its present closing rate, and it is
-- vertically closer than 1000 ft plus one step of full-rate climb, climb or
-- descend away from it at the full rate (away: down when it is above, up
-- when below). The nearest such intruder decides.
-- Observation (envs/vertical_cr.lua, 39 numbers): altitude 1,
-- altitude_difference 2-6, cos_difference_pos 7-11, intruder_distance
-- 12-16, runway_distance 17, sin_difference_pos 18-22, target_altitude 23,
-- vz 24, x/y/z_difference_speed 25-39. Intruder i keeps its slot.
-- Units: metres, seconds, m/s.

local Descent = require("descent")

local NUM_INTRUDERS = 5
local ZONE_M = 5 * 1852                  -- [m] horizontal intrusion distance (vertical_cr.lua L20)
local MARGIN_M = 1000 * 0.3048 + 12.5 * 30  -- [m] 1000 ft plus one step at the full rate
local LOOKAHEAD_STEPS = 2

local P = setmetatable({env = "VerticalCREnv-v0"}, {__index = Descent})

function P:reset(seed)
  Descent.reset(self, seed)
  self.prev_dist = {}
end

-- The altitude difference [m] (intruder minus ownship) of the nearest
-- intruder that threatens, or nil.
function P:threat(obs)
  local nearest, dh
  for i = 1, NUM_INTRUDERS do
    local d = obs[11 + i] * 200 * 1000   -- [m] (intruder_distance: km / 200)
    local ad = obs[1 + i] * 3000         -- [m] (altitude_difference: m / 3000)
    local closing = self.prev_dist[i] and self.prev_dist[i] - d or 0
    self.prev_dist[i] = d
    local soon = d < ZONE_M or (closing > 0 and d - LOOKAHEAD_STEPS * closing < ZONE_M)
    if soon and math.abs(ad) < MARGIN_M and (not nearest or d < nearest) then
      nearest, dh = d, ad
    end
  end
  return dh
end

-- The ownship's altitude, runway distance and target altitude [m] from the observation; shared with
-- envs/policies/vertical_cr_steady.lua.
function P.ownship(obs)
  return 1500 + 3000 * obs[1], (100 + 200 * obs[17]) * 1000, 1500 + 3000 * obs[23]
end

function P:act(obs)
  local alt, runway_m, target = P.ownship(obs)
  local rate = self:descent_rate(alt, runway_m, target)
  local dh = self:threat(obs)
  if dh then rate = dh > 0 and -12.5 or 12.5 end
  return {Descent.rate_action(rate)}
end

return P
