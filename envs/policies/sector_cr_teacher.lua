-- A teacher for SectorCREnv-v0 (envs/sector_cr.lua): a look-ahead controller
-- that is a function of the observation alone (no memory, so an MLP can clone
-- it), for `squawk train --imitate` and as a stronger scripted baseline than
-- envs/policies/sector_cr.lua, which it differs from in three ways: it knows
-- which way is "away" instead of trying, it changes speed, and it weighs
-- every candidate action by the intrusions it predicts.
--
-- The ownship's heading is not observed, but its velocity follows from the
-- intruders': every intruder flies at one constant TAS W (same CAS, same
-- level), so for intruder k with relative velocity r_k (intruder minus
-- ownship), |v + r_k|^2 = W^2 with v = V u, V the ownship's TAS (observed) and
-- u its unit heading vector: 2 V (r_k . u) - W^2 = -V^2 - |r_k|^2, linear in
-- (u_n, u_e, W^2); solved by least squares over the four intruders, u then
-- normalised.
--
-- Each candidate action (heading -1, -1/2, 0, 1/2, 1 and the waypoint
-- steering; CAS -1, 0, 1) changes the ownship's velocity at once; each
-- intruder then keeps its relative velocity, and the cost is
--   sum over intruders of the time within ZONE_M + MARGIN_M, discounted by
--   exp(-t / TAU_S), in steps of 5 s
--   + DRIFT_STEPS x 0.1 x |drift after the turn| [rad]
--   - SPEED_BONUS x the CAS action (the reward pays per step and nothing for
--   arriving, so a faster flight out of the sector is worth something).
-- The action with the smallest cost is returned.
-- Observation (envs/sector_cr.lua, 31 numbers): airspeed 1, cos(drift) 2,
-- cos(track) 3-6, distances 7-10, sin(drift) 11, sin(track) 12-15, vx_r
-- 16-19 (/32 m/s), vy_r 20-23 (/66 m/s), x_r 24-27, y_r 28-31 (/13000 m);
-- x north, y east, intruder minus ownship. Units: metres, seconds, degrees.

local N = 4                 -- intruders observed
local D_HEADING = 22.5      -- [deg per unit of action] (sector_cr.lua)
local D_CAS = 20 / 3        -- [m/s per unit of action] (sector_cr.lua)
local ZONE_M = 5 * 1852     -- [m] intrusion distance (sector_cr.lua)
local MARGIN_M = 0.5 * 1852 -- [m] kept beyond the zone
local TAU_S = 150           -- [s] discount time of a predicted intrusion
local HORIZON_S = 600       -- [s] look-ahead
local STEP_S = 5            -- [s] one env step
local DRIFT_STEPS = 10      -- [steps] a drift is paid for
local SPEED_BONUS = 0.05    -- [reward per unit of CAS action]

local P = {env = "SectorCREnv-v0"}

-- The ownship's unit heading vector (north, east) from the observation, or nil
-- when the intruders' relative velocities do not determine it.
local function heading_vector(obs, V)
  -- Normal equations of rows (2 V r_n, 2 V r_e, -1) . (u_n, u_e, W2) = -V^2 - |r|^2.
  local A = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}
  local b = {0, 0, 0}
  for k = 1, N do
    local rn, re = obs[15 + k] * 32, obs[19 + k] * 66
    local row = {2 * V * rn, 2 * V * re, -1}
    local rhs = -V * V - rn * rn - re * re
    for i = 1, 3 do
      for j = 1, 3 do A[i][j] = A[i][j] + row[i] * row[j] end
      b[i] = b[i] + row[i] * rhs
    end
  end
  -- Cramer's rule on the 3 x 3 system.
  local function det(m)
    return m[1][1] * (m[2][2] * m[3][3] - m[2][3] * m[3][2]) - m[1][2] * (m[2][1] * m[3][3] - m[2][3] * m[3][1]) +
           m[1][3] * (m[2][1] * m[3][2] - m[2][2] * m[3][1])
  end
  local d = det(A)
  if math.abs(d) < 1e-9 * (math.abs(A[1][1] * A[2][2] * A[3][3]) + 1e-300) then return nil end
  local u = {}
  for c = 1, 2 do
    local m = {{A[1][1], A[1][2], A[1][3]}, {A[2][1], A[2][2], A[2][3]}, {A[3][1], A[3][2], A[3][3]}}
    for i = 1, 3 do m[i][c] = b[i] end
    u[c] = det(m) / d
  end
  local norm = math.sqrt(u[1] * u[1] + u[2] * u[2])
  if norm < 1e-6 then return nil end
  return u[1] / norm, u[2] / norm
end

-- The discounted time [s] within radius R of an intruder at relative position
-- (x, y) [m] moving at relative velocity (vx, vy) [m/s], over [0, HORIZON_S].
local function time_inside(x, y, vx, vy, R)
  local a, b, c = vx * vx + vy * vy, x * vx + y * vy, x * x + y * y - R * R
  local t1, t2
  if a < 1e-9 then
    if c >= 0 then return 0 end
    t1, t2 = 0, HORIZON_S
  else
    local disc = b * b - a * c
    if disc <= 0 then return 0 end
    local s = math.sqrt(disc)
    t1, t2 = math.max(0, (-b - s) / a), math.min(HORIZON_S, (-b + s) / a)
    if t2 <= t1 then return 0 end
  end
  return TAU_S * (math.exp(-t1 / TAU_S) - math.exp(-t2 / TAU_S))
end

-- The predicted intrusion cost [intruder-steps, discounted] of heading action
-- `ah` and CAS action `av` (at once, then straight), the ownship's unit
-- heading vector (un, ue) and TAS V [m/s] given.
local function intrusion_cost(obs, un, ue, V, ah, av)
  local d = math.rad(ah * D_HEADING)
  local cn, ce = un * math.cos(d) - ue * math.sin(d), un * math.sin(d) + ue * math.cos(d)
  local v = V + av * D_CAS
  local dn, de = V * un - v * cn, V * ue - v * ce   -- old minus new ownship velocity
  local total = 0
  for k = 1, N do
    local x, y = obs[23 + k] * 13000, obs[27 + k] * 13000
    total = total + time_inside(x, y, obs[15 + k] * 32 + dn, obs[19 + k] * 66 + de, ZONE_M + MARGIN_M) / STEP_S
  end
  return total
end

function P:act(obs)
  local drift = math.deg(math.atan(obs[11], obs[2]))   -- heading - bearing to the waypoint
  local steer = math.max(-1, math.min(1, -drift / D_HEADING))
  local V = 150 + 6 * obs[1]
  local un, ue = heading_vector(obs, V)
  if not un then return {steer, 1} end
  local best, best_action = math.huge, {steer, 1}
  for _, ah in ipairs({steer, -1, -0.5, 0, 0.5, 1}) do
    for _, av in ipairs({1, 0, -1}) do
      local c = intrusion_cost(obs, un, ue, V, ah, av) +
                DRIFT_STEPS * 0.1 * math.abs(math.rad(drift + ah * D_HEADING)) - SPEED_BONUS * av
      if c < best - 1e-9 then best, best_action = c, {ah, av} end
    end
  end
  return best_action
end

P.heading_vector, P.intrusion_cost = heading_vector, intrusion_cost

return P
