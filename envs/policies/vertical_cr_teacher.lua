-- A planning teacher for VerticalCREnv-v0 (envs/vertical_cr.lua), used to clone an MLP
-- (`squawk train --imitate`); the scripted baseline stays envs/policies/vertical_cr.lua.
--
-- Each step it plans the whole remaining vertical profile by dynamic programming over the
-- reward's own terms, predicted from the observation: the altitude shaping −|target − alt|/600
-- a step, −50 per intruder within 5 NM and 1000 ft at a step's end, and the final −alt/60 at the
-- step that passes the runway (or −100 on the ground), and flies the plan's first step. The
-- intruders fly straight and level (envs/vertical_cr.lua): each one's position and velocity
-- relative to the ownship are read from its distance, bearing and x/y/z_difference_speed, and
-- extrapolated; the ownship flies north at the true airspeed of its 150 m/s CAS (ISA,
-- compressible) times the observed ratio of runway distance flown to it (smoothed). The plan's
-- altitudes lie on a grid of GRID_M from the present altitude, one step's change at most the full
-- rate (375 m); the first step's vertical speed is chosen finer (RATE_STEP) and flown through the
-- simulator's V/S ramp (1.524 m/s², engine/sim/simulation.cpp). For a clone it keeps margins
-- beyond the intrusion zone, aims above SAFE_M at the runway and holds at ±HOLD_RATE.
-- Observation: envs/policies/vertical_cr.lua's comment. Units: metres, seconds, m/s; km where named.

local Descent = require("descent")

local NUM_INTRUDERS = 5
local MAX_RATE, STEP_S = 12.5, 30         -- [m/s], [s] the action's scale and one env step
local ZONE_KM = 5 * 1.852                 -- [km] horizontal intrusion distance
local VERT_M = 1000 * 0.3048              -- [m] vertical intrusion distance
local H_MARGIN_KM, V_MARGIN_M = 4.0, 250  -- margins on the intrusion zone (prediction, a clone's error)
local INTRUSION, CRASH = 50, 100          -- costs (the reward's magnitudes)
local SHAPING, FINAL = 1 / 600, 1 / 60    -- [1/m] altitude costs before and at the runway
local SAFE_M = 120                        -- [m] a final altitude below this counts as a crash (margin for a clone)
local GRID_M, MOVES = 75, 5               -- [m] plan grid; a full-rate step moves MOVES levels (375 m)
local CEILING_M = 1200                    -- [m] the plan stays below max(alt, target) + this
local RATE_STEP = 0.5                     -- [m/s] first-step vertical speed resolution
local HOLD_RATE = 0.625                   -- [m/s] the hold's vertical speed (action 0.05)
local VS_ACCEL = 1.524                    -- [m/s^2] the simulator's V/S ramp
local CAS = 150                           -- [m/s] the ownship's calibrated airspeed (descent.lua)
local SCALE, SCALE_GAIN = 0.97, 0.3       -- observed over true ground speed: first guess, smoothing

local P = {env = "VerticalCREnv-v0"}

function P:reset(seed)
  self.prev_runway, self.prev_alt, self.scale = nil, nil, SCALE
end

-- True airspeed [m/s] at altitude h [m] of the ownship's CAS (ISA troposphere, compressible).
local function tas(h)
  local T = 288.15 - 0.0065 * math.max(h, 0)
  local p = 101325 * (T / 288.15) ^ 5.25588
  local qc = 101325 * ((1 + 0.2 * (CAS / 340.294) ^ 2) ^ 3.5 - 1)
  return math.sqrt(5 * ((qc / p + 1) ^ (2 / 7) - 1)) * math.sqrt(1.4 * 287.05287 * T)
end

-- The altitude change [m] over one step from vertical speed v0 when v1 is selected (also
-- envs/policies/vertical_cr_steady.lua's).
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
  -- Ground speed [m/s] as the observation measures it: the true airspeed times the ratio of the
  -- runway distance flown to it over the steps flown (smoothed; about 0.97).
  if self.prev_runway then
    local measured = (self.prev_runway - runway_km) * 1000 / STEP_S / tas((self.prev_alt + alt) / 2)
    self.scale = self.scale + SCALE_GAIN * (measured - self.scale)
  end
  self.prev_runway, self.prev_alt = runway_km, alt
  local gs = self.scale * tas(alt)
  local function own_step_km(h) return self.scale * tas(h) * STEP_S / 1000 end

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
  -- Grid levels j: altitude alt + GRID_M * j, in [0, max(alt, target) + CEILING_M]. A level is
  -- held in one of three modes: 1 after a step below the full rate, 2 and 3 after one at the full
  -- rate down and up. One step moves at most MOVES - 1 levels from mode 1 (the V/S ramp from
  -- level flight loses about 50 m of a full-rate step); a full-rate step from mode 2 or 3 in the
  -- same direction moves MOVES levels.
  local jmin = -math.floor(alt / GRID_M)
  local jmax = math.floor((math.max(alt, target) + CEILING_M - alt) / GRID_M)
  -- The cost of altitude h [m] at the end of step k: the altitude term, and INTRUSION for each
  -- intruder within the zone (margins included); cost(k) of every level, cost_at(k, h) of one.
  local band, zone2 = VERT_M + V_MARGIN_M, (ZONE_KM + H_MARGIN_KM) ^ 2
  local function altitude_cost(k, h)
    if k < n then return math.abs(target - h) * SHAPING end
    return h < SAFE_M and CRASH or h * FINAL
  end
  local function inside(it, ih, k, h)
    if math.abs(ih - h) >= band then return false end
    local e, nn = it.e + it.ve * k, it.n + it.vn * k - k * own_step_km((alt + h) / 2)
    return e * e + nn * nn < zone2
  end
  local function cost_at(k, h)
    local c = altitude_cost(k, h)
    for _, it in ipairs(intr) do
      if inside(it, it.alt + it.vs * STEP_S * k, k, h) then c = c + INTRUSION end
    end
    return c
  end
  local function cost(k)
    local c = {}
    for j = jmin, jmax do c[j] = altitude_cost(k, alt + GRID_M * j) end
    for _, it in ipairs(intr) do
      local ih = it.alt + it.vs * STEP_S * k
      for j = math.max(jmin, math.ceil((ih - band - alt) / GRID_M)), math.min(jmax, math.floor((ih + band - alt) / GRID_M)) do
        if inside(it, ih, k, alt + GRID_M * j) then c[j] = c[j] + INTRUSION end
      end
    end
    return c
  end
  -- The least cost over the moves from level j into V (three tables by level), by the mode j is
  -- held in: B[mode][j].
  local function best_moves(V)
    local V1, V2, V3 = V[1], V[2], V[3]
    local B1, B2, B3 = {}, {}, {}
    for j = jmin, jmax do
      local best = math.huge
      for m = math.max(jmin, j - MOVES + 1), math.min(jmax, j + MOVES - 1) do
        if V1[m] < best then best = V1[m] end
      end
      local down4, down5 = V2[j - MOVES + 1] or math.huge, V2[j - MOVES] or math.huge
      local up4, up5 = V3[j + MOVES - 1] or math.huge, V3[j + MOVES] or math.huge
      B1[j] = math.min(best, down4, up4)
      B2[j] = math.min(best, down5, up4)
      B3[j] = math.min(best, down4, up5)
    end
    return {B1, B2, B3}
  end
  -- V[mode][j]: the least cost from the end of step k on (step k's own cost included), k = n .. 2.
  local last = cost(n)
  local V = {last, last, last}
  for k = n - 1, 2, -1 do
    local B = best_moves(V)
    local c, W1, W2, W3 = cost(k), {}, {}, {}
    for j = jmin, jmax do
      W1[j], W2[j], W3[j] = c[j] + B[1][j], c[j] + B[2][j], c[j] + B[3][j]
    end
    V = {W1, W2, W3}
  end
  -- The continuation after step 1 that ends at altitude h in `mode`: V (k = 2) from the nearest level.
  local B = n > 1 and best_moves(V)
  local function after(h, mode)
    if n == 1 then return 0 end
    local j = math.max(jmin, math.min(jmax, math.floor((h - alt) / GRID_M + 0.5)))
    return B[mode][j]
  end

  local best_rate, best = 0, math.huge
  for r = -MAX_RATE, MAX_RATE + 1e-9, RATE_STEP do
    local h = math.max(0, alt + step_change(vz, r))
    local mode = r <= -MAX_RATE and 2 or r >= MAX_RATE and 3 or 1
    local c = cost_at(1, h) + after(h, mode) + 1e-6 * math.abs(r)
    if c < best then best_rate, best = r, c end
  end
  -- A hold (a rate under HOLD_RATE) reverses the present vertical speed at HOLD_RATE: an action
  -- a clone can read from vz, where one near 0 averages into the default 7.6 m/s band.
  if math.abs(best_rate) < HOLD_RATE then best_rate = vz > 0 and -HOLD_RATE or HOLD_RATE end
  return {Descent.rate_action(best_rate)}
end

P.step_change = step_change
return P
