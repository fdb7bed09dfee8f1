-- A scripted controller for MergeEnv-v0 (envs/merge.lua), for
-- `squawk env run envs/merge.lua --policy script:envs/policies/merge.lua`.
--
-- The rules an approach controller merging into a stream would give:
-- heading: fly to the aim point (the fix, then the runway; turn by the whole
--   drift, at most the action's 15 deg), unless an intruder is in conflict
--   (its straight line comes within 4 NM plus MARGIN_M within LOOKAHEAD_S);
--   then turn away from it as MVP would: towards the side opposite the
--   intruder's position at closest approach;
-- speed: keep SPACING_M from the aircraft in the lane (within 4 NM of the
--   ownship's track): slow down by the full step while one ahead is closer,
--   speed up by the full step while one behind is closer and gaining;
--   otherwise return to the starting airspeed; never below MIN_SPEED_SHARE
--   of it.
-- The observation gives the traffic in the north/east frame and the drift,
-- not the heading; the stream flows south along the fix-runway line (the
-- fix lies due north of the runway and every aircraft starts within 15 deg
-- of north of the fix), so the heading is taken as 180 deg + drift.
-- Observation (envs/merge.lua, 40 numbers): airspeed 1 (TAS m/s), cos(drift)
-- 2, cos(track) 3-7, distances 8-12, faf_reached 13, sin(drift) 14,
-- sin(track) 15-19, vx_r 20-24, vy_r 25-29 (/150 m/s), waypoint_dist 30,
-- x_r 31-35, y_r 36-40 (/1e6 m); x north, y east, intruder minus ownship.
-- Units: metres, seconds, degrees, m/s.

local N = 5                        -- intruders observed
local D_HEADING, D_SPEED = 15, 20  -- [deg], [m/s CAS] per unit of action (merge.lua)
local ZONE_M = 4 * 1852            -- [m] intrusion distance (merge.lua L18)
local MARGIN_M = 1852              -- [m] kept beyond the zone
local LOOKAHEAD_S = 300            -- [s]
local SPACING_M = 2 * ZONE_M       -- [m] in trail
local MIN_SPEED_SHARE = 0.8
local START_CAS = 100              -- [m/s] every aircraft's CAS at the start (merge.lua L29)

local P = {env = "MergeEnv-v0"}

function P:reset(seed)
  self.tas0 = nil
end

local function clamp(v) return math.max(-1, math.min(1, v)) end

function P:act(obs)
  local tas = obs[1]
  self.tas0 = self.tas0 or tas
  local drift = math.deg(math.atan(obs[14], obs[2]))   -- heading - bearing to the aim point
  local h = math.rad(180 + drift)
  local ux, uy = math.cos(h), math.sin(h)              -- own direction, north/east
  local turn = clamp(-drift / D_HEADING)
  local speed = clamp((self.tas0 - tas) * (START_CAS / self.tas0) / D_SPEED)   -- TAS error as CAS
  local worst, leader, follower
  for k = 1, N do
    local x, y = obs[30 + k] * 1e6, obs[35 + k] * 1e6
    local vx, vy = obs[19 + k] * 150, obs[24 + k] * 150
    local tcpa, dcpa = squawk.geo.cpa(x, y, vx, vy, ZONE_M + MARGIN_M)
    if tcpa > 0 and tcpa < LOOKAHEAD_S and dcpa < ZONE_M + MARGIN_M and (not worst or dcpa < worst.dcpa) then
      worst = {dcpa = dcpa, mx = x + vx * tcpa, my = y + vy * tcpa}
    end
    local along, across = x * ux + y * uy, math.abs(x * uy - y * ux)
    if across < ZONE_M and math.abs(along) < SPACING_M then
      if along > 0 then
        leader = true
      elseif vx * ux + vy * uy > 0 then   -- behind and gaining on us
        follower = true
      end
    end
  end
  if worst then
    -- the intruder at closest approach lies right of the track (m . right > 0): turn left
    local right = worst.mx * -uy + worst.my * ux
    turn = right > 0 and -1 or 1
  end
  if leader then speed = -1 elseif follower then speed = 1 end
  if tas < MIN_SPEED_SHARE * self.tas0 then speed = math.max(speed, 0) end
  return {turn, speed}
end

return P
