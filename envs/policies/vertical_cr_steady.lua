-- A rule-like teacher for VerticalCREnv-v0 (envs/vertical_cr.lua), for cloning an MLP
-- (`squawk train --imitate`); the scripted baseline stays envs/policies/vertical_cr.lua.
--
-- The rule's pieces with what costs it reward (docs/gym_envs.md, "VerticalCR: where the rule
-- loses") taken out, each still a threshold on one intruder or a closed form:
--   the wanted altitude: back to the target over RETURN_STEPS steps (a hold reverses the present
--     vertical speed at HOLD_RATE), or the descent: from the step where reaching AIM_M at the
--     runway needs START_SHARE of the full rate, that glide;
--   the avoidance: an intruder threatens as in the rule (within 5 NM, or closing and within 5 NM
--     in LOOKAHEAD_STEPS steps at its present closing rate; the closing rate from the step
--     before) and has a band, its altitude ± SEP_M. When the wanted altitude is inside a band,
--     the aircraft flies to the band edge outside every band that is nearest its present
--     altitude, as fast as the full rate allows, and stays there until the intruder is past,
--     where the rule flies away at the full rate and back at the full rate.
-- The vertical speed that reaches an altitude is chosen through the simulator's V/S ramp
-- (1.524 m/s², engine/sim/simulation.cpp). For a clone it keeps 150 m beyond the 1000 ft and
-- holds at ±1.25 m/s (action ±0.1), clear of BlueSky's "no rate selected" band.
-- Observation: envs/policies/vertical_cr.lua's comment.
-- Units: metres, seconds, m/s.

local Descent = require("descent")
local Rule = require("vertical_cr")
local step_change = require("vertical_cr_teacher").step_change

local NUM_INTRUDERS = 5
local MAX_RATE, STEP_S = 12.5, 30      -- [m/s], [s] the action's scale and one env step
local ZONE_M = 5 * 1852                -- [m] horizontal intrusion distance
local SEP_M = 1000 * 0.3048 + 150       -- [m] the band kept clear around an intruder's altitude
local LOOKAHEAD_STEPS = 2
local RETURN_STEPS = 2                 -- steps to get back to the target
local HOLD_RATE = 1.25                -- [m/s] the hold's vertical speed
local AIM_M = 100                      -- [m] above the runway's height at the runway
local START_SHARE = 1.0                -- start down when the glide needs this share of MAX_RATE
local RATE_STEP = 0.25                 -- [m/s] resolution of the chosen vertical speed

local P = {env = "VerticalCREnv-v0"}

function P:reset(seed)
  self.prev_runway, self.prev_dist, self.descending = nil, {}, false
end

-- The wanted altitude [m] at the step's end without intruders; updates the ground speed memory.
function P:wanted(alt, runway_m, target)
  local glide = Descent.glide(self, alt, runway_m, AIM_M, START_SHARE)
  if glide then return alt - glide * STEP_S end
  return alt + (target - alt) / RETURN_STEPS
end

-- The altitudes [m] of the intruders that threaten (the rule's test without its altitude
-- margin); remembers the distances.
function P:threats(obs)
  local alt = 1500 + 3000 * obs[1]
  local out = {}
  for i = 1, NUM_INTRUDERS do
    local d = obs[11 + i] * 200 * 1000   -- [m]
    local closing = self.prev_dist[i] and self.prev_dist[i] - d or 0
    self.prev_dist[i] = d
    if d < ZONE_M or (closing > 0 and d - LOOKAHEAD_STEPS * closing < ZONE_M) then
      out[#out + 1] = alt + obs[1 + i] * 3000
    end
  end
  return out
end

-- The altitude [m] to fly to: `want` when it is outside every band (an intruder altitude in
-- `threats` ± SEP_M), else the band edge outside every band that is nearest the present altitude
-- `alt` (a quarter of the distance to `want` breaks ties).
local function clear_of(threats, alt, want)
  local function clear(h)
    for _, ih in ipairs(threats) do
      if math.abs(h - ih) < SEP_M - 1e-6 then return false end  -- an edge is clear
    end
    return true
  end
  if clear(want) then return want end
  local best, best_cost = want, math.huge
  for _, ih in ipairs(threats) do
    for _, h in ipairs({ih - SEP_M, ih + SEP_M}) do
      local c = math.abs(h - alt) + 0.25 * math.abs(h - want)
      if h >= 0 and clear(h) and c < best_cost then best, best_cost = h, c end
    end
  end
  return best
end

function P:act(obs)
  local alt, runway_m, target = Rule.ownship(obs)
  local vz = 5 * obs[24]
  local wanted = self:wanted(alt, runway_m, target)
  local threats = self:threats(obs)
  local goal = clear_of(threats, alt, wanted)
  -- the vertical speed whose step ends nearest the altitude to fly to
  local best_rate, best = 0, math.huge
  for r = -MAX_RATE, MAX_RATE + 1e-9, RATE_STEP do
    local miss = math.abs(alt + step_change(vz, r) - goal)
    if miss < best then best_rate, best = r, miss end
  end
  if math.abs(best_rate) < HOLD_RATE then best_rate = vz > 0 and -HOLD_RATE or HOLD_RATE end
  return {Descent.rate_action(best_rate)}
end

return P
