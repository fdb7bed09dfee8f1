-- A scripted controller for SectorCREnv-v0 (envs/sector_cr.lua), for
-- `squawk env run envs/sector_cr.lua --policy script:envs/policies/sector_cr.lua`.
--
-- Fly to the waypoint (turn by the whole drift, at most the action's 22.5
-- deg) unless one of the four nearest intruders is in conflict: its straight
-- line brings it within 5 NM plus MARGIN_M within LOOKAHEAD_S, or it is
-- inside 5 NM and closing. Then turn away at the full rate. The observation
-- gives the traffic in the north/east frame but not the ownship's own
-- heading, so which way is "away" is found by trying: turn right first, keep
-- the direction while the smallest predicted miss distance grows, turn the
-- other way when it shrank since the last step. The speed is left alone.
-- Observation (envs/sector_cr.lua, 31 numbers): airspeed 1, cos(drift) 2,
-- cos(track) 3-6, distances 7-10, sin(drift) 11, sin(track) 12-15, vx_r
-- 16-19 (/32 m/s), vy_r 20-23 (/66 m/s), x_r 24-27, y_r 28-31 (/13000 m);
-- x north, y east, intruder minus ownship. Units: metres, seconds, degrees.

local N = 4                       -- intruders observed
local D_HEADING = 22.5            -- [deg per unit of action] (sector_cr.lua)
local ZONE_M = 5 * 1852           -- [m] intrusion distance (sector_cr.lua L28)
local MARGIN_M = 1852             -- [m] kept beyond the zone
local LOOKAHEAD_S = 300           -- [s]

local P = {env = "SectorCREnv-v0"}

function P:reset(seed)
  self.dir, self.prev_miss = 1, nil
end

-- The smallest predicted miss distance [m] among intruders in conflict, or nil.
local function worst_conflict(obs)
  local worst
  for k = 1, N do
    local x, y = obs[23 + k] * 13000, obs[27 + k] * 13000
    local vx, vy = obs[15 + k] * 32, obs[19 + k] * 66
    local tcpa, dcpa = squawk.geo.cpa(x, y, vx, vy, ZONE_M + MARGIN_M)
    local dist = math.sqrt(x * x + y * y)
    local conflict = (tcpa > 0 and tcpa < LOOKAHEAD_S and dcpa < ZONE_M + MARGIN_M) or
                     (dist < ZONE_M and tcpa > 0)
    if conflict and (not worst or dcpa < worst) then worst = dcpa end
  end
  return worst
end

function P:act(obs)
  local miss = worst_conflict(obs)
  if not miss then
    self.prev_miss = nil
    local drift = math.deg(math.atan(obs[11], obs[2]))   -- heading - bearing to the waypoint
    return {math.max(-1, math.min(1, -drift / D_HEADING)), 0}
  end
  if self.prev_miss and miss < self.prev_miss then self.dir = -self.dir end
  self.prev_miss = miss
  return {self.dir, 0}
end

return P
