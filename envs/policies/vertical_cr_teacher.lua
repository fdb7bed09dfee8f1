-- A planning teacher for VerticalCREnv-v0 (envs/vertical_cr.lua), used to clone an MLP
-- (`squawk train --imitate`); the scripted baseline stays envs/policies/vertical_cr.lua.
--
-- Each step it plans the whole remaining vertical profile by dynamic programming over the
-- reward's own terms, predicted from the observation: the altitude shaping −|target − alt|/600
-- a step, −50 per intruder within 5 NM and 1000 ft at a step's end, and the final −alt/60 at the
-- step that passes the runway (or −100 on the ground), and flies the plan's first step. The
-- intruders fly straight and level (envs/vertical_cr.lua): each one's position and velocity
-- relative to the ownship are read from its distance, bearing and x/y/z_difference_speed, and
-- extrapolated; the ownship flies north at the ground speed measured over the last step, scaled
-- with altitude by the true airspeed of a constant CAS (ISA density). The plan's altitudes lie
-- on a grid of GRID_M from the present altitude, one step's change at most the full rate (375 m);
-- the first step's vertical speed is chosen finer (RATE_STEP) and flown through the simulator's
-- V/S ramp (1.524 m/s², engine/sim/simulation.cpp). Observation: envs/policies/vertical_cr.lua's
-- comment. Units: metres, seconds, m/s; km where named.

local Descent = require("descent")

local NUM_INTRUDERS = 5
local MAX_RATE, STEP_S = 12.5, 30         -- [m/s], [s] the action's scale and one env step
local ZONE_KM = 5 * 1.852                 -- [km] horizontal intrusion distance
local VERT_M = 1000 * 0.3048              -- [m] vertical intrusion distance
local H_MARGIN_KM, V_MARGIN_M = 0.5, 15   -- prediction margins on the intrusion zone
local INTRUSION, CRASH = 50, 100          -- costs (the reward's magnitudes)
local SHAPING, FINAL = 1 / 600, 1 / 60    -- [1/m] altitude costs before and at the runway
local SAFE_M = 40                         -- [m] a final altitude below this counts as a crash
local GRID_M, MOVES = 75, 5               -- [m] plan grid; a full-rate step moves MOVES levels (375 m)
local CEILING_M = 1200                    -- [m] the plan stays below max(alt, target) + this
local RATE_STEP = 0.5                     -- [m/s] first-step vertical speed resolution
local VS_ACCEL = 1.524                    -- [m/s^2] the simulator's V/S ramp
local CAS, CAS_GAIN = 150, 0.3            -- [m/s] the ownship's CAS before a step is measured; smoothing

local P = {env = "VerticalCREnv-v0"}

function P:reset(seed)
  self.prev_runway, self.prev_alt, self.cas = nil, nil, nil
end

-- True airspeed over CAS at altitude h [m] (ISA troposphere, incompressible).
local function tas_factor(h)
  return (1 - 2.25577e-5 * math.max(h, 0)) ^ (-4.25588 / 2)
end

-- The altitude change [m] over one step from vertical speed v0 when v1 is selected.
local function step_change(v0, v1)
  local v, dh = v0, 0
  for _ = 1, STEP_S do
    local dv = v1 - v
    v = math.abs(dv) > VS_ACCEL and v + (dv > 0 and VS_ACCEL or -VS_ACCEL) or v1
    dh = dh + v
  end
  return dh
end

function P:act(obs)
  local alt = 1500 + 3000 * obs[1]
  local runway_km = 100 + 200 * obs[17]
  local target = 1500 + 3000 * obs[23]
  local vz = 5 * obs[24]
  -- Ground speed [m/s] = cas * tas_factor(alt), cas measured over the steps flown (smoothed).
  if self.prev_runway then
    local measured = (self.prev_runway - runway_km) * 1000 / STEP_S / tas_factor((self.prev_alt + alt) / 2)
    self.cas = self.cas and self.cas + CAS_GAIN * (measured - self.cas) or measured
  end
  self.prev_runway, self.prev_alt = runway_km, alt
  local gs = (self.cas or CAS) * tas_factor(alt)
  local function own_step_km(h) return gs * tas_factor(h) / tas_factor(alt) * STEP_S / 1000 end

  -- Steps until the runway is passed, descending at the full rate as late as possible.
  local n = math.max(1, math.ceil(runway_km / own_step_km(alt)))
  for _ = 1, 2 do
    local dist, k = 0, 0
    repeat
      k = k + 1
      dist = dist + own_step_km(math.min(alt, MAX_RATE * STEP_S * (n - k)))
    until dist >= runway_km or k > 200
    n = k
  end

  -- Intruders: position [km] relative to the ownship (east, north), velocity [km/step], altitude [m], V/S.
  local intr = {}
  for i = 1, NUM_INTRUDERS do
    local d = obs[11 + i] * 200
    intr[i] = {e = -d * obs[17 + i], n = d * obs[6 + i],
               ve = (150 * obs[29 + i] - gs) * STEP_S / 1000, vn = -150 * obs[24 + i] * STEP_S / 1000,
               alt = alt + 3000 * obs[1 + i], vs = obs[34 + i] + vz}
  end
  -- Intruders within the zone at the end of step k when the ownship is at h [m].
  local function intrusions(k, h)
    local c = 0
    for _, it in ipairs(intr) do
      if math.abs(it.alt + it.vs * STEP_S * k - h) < VERT_M + V_MARGIN_M then
        local north = k * own_step_km((alt + h) / 2)
        local e, nn = it.e + it.ve * k, it.n + it.vn * k - north
        if e * e + nn * nn < (ZONE_KM + H_MARGIN_KM) ^ 2 then c = c + 1 end
      end
    end
    return c
  end
  local function cost(k, h)
    local c = INTRUSION * intrusions(k, h)
    if k < n then return c + math.abs(target - h) * SHAPING end
    if h < SAFE_M then return c + CRASH end
    return c + h * FINAL
  end

  -- Grid levels j: altitude alt + GRID_M * j, in [0, max(alt, target) + CEILING_M]. A level is
  -- held in one of three modes: 1 after a step below the full rate, 2 and 3 after one at the full
  -- rate down and up. One step moves at most MOVES - 1 levels from mode 1 (the V/S ramp from
  -- level flight loses about 50 m of a full-rate step); a full-rate step from mode 2 or 3 in the
  -- same direction moves MOVES levels.
  local jmin = -math.floor(alt / GRID_M)
  local jmax = math.floor((math.max(alt, target) + CEILING_M - alt) / GRID_M)
  -- The least cost over the moves from level j in mode `mode` into V (a table of three by level).
  local function best_move(V, j, mode)
    local best = math.huge
    for m = math.max(jmin, j - MOVES + 1), math.min(jmax, j + MOVES - 1) do
      if V[1][m] < best then best = V[1][m] end
    end
    local down, up = mode == 2 and MOVES or MOVES - 1, mode == 3 and MOVES or MOVES - 1
    if j - down >= jmin and V[2][j - down] < best then best = V[2][j - down] end
    if j + up <= jmax and V[3][j + up] < best then best = V[3][j + up] end
    return best
  end
  -- V[mode][j]: the least cost from the end of step k on (step k's own cost included), k = n .. 2.
  local V = {{}, {}, {}}
  for j = jmin, jmax do
    local c = cost(n, alt + GRID_M * j)
    V[1][j], V[2][j], V[3][j] = c, c, c
  end
  for k = n - 1, 2, -1 do
    local W = {{}, {}, {}}
    for j = jmin, jmax do
      local c = cost(k, alt + GRID_M * j)
      for mode = 1, 3 do W[mode][j] = c + best_move(V, j, mode) end
    end
    V = W
  end
  -- The continuation after step 1 that ends at altitude h in `mode`: V (k = 2) from the nearest level.
  local function after(h, mode)
    if n == 1 then return 0 end
    local j = math.max(jmin, math.min(jmax, math.floor((h - alt) / GRID_M + 0.5)))
    return best_move(V, j, mode)
  end

  local best_rate, best = 0, math.huge
  for r = -MAX_RATE, MAX_RATE + 1e-9, RATE_STEP do
    local h = math.max(0, alt + step_change(vz, r))
    local mode = r <= -MAX_RATE and 2 or r >= MAX_RATE and 3 or 1
    local c = cost(1, h) + after(h, mode) + 1e-6 * math.abs(r)
    if c < best then best_rate, best = r, c end
  end
  return {Descent.rate_action(best_rate)}
end

return P
