-- A scripted controller for DescentEnv-v0 (envs/descent.lua), for
-- `squawk env run envs/descent.lua --policy script:envs/policies/descent.lua`.
--
-- The rule a controller would give: hold the target altitude, and start down
-- when a steady glide to the runway needs 90 % of the maximum descent rate;
-- then fly the glide that is AIM_ALT above the runway's height when the
-- episode ends (at the end of the step that passes the runway), recomputed
-- each step. The ground speed is the runway distance flown since the last step.
-- Observation (envs/descent.lua): altitude, runway_distance, target_altitude,
-- vz, scaled as declared there. Action: vertical speed / 12.5 m/s.
-- Units: metres, seconds, m/s.

local MAX_RATE = 12.5        -- [m/s] the action's scale (descent.lua ACTION_2_MS)
local STEP_S = 30            -- [s] one env step (30 x 1 s)
local MIN_RATE = 0.2         -- [m/s] below 0.1 m/s BlueSky flies its default 7.6 m/s instead
local AIM_ALT = 100          -- [m] above the runway at the runway: a margin over the crash at 0
local START_SHARE = 0.9      -- start down when the glide needs this share of MAX_RATE

local P = {env = "DescentEnv-v0"}

function P:reset(seed)
  self.prev_runway, self.descending = nil, false
end

-- The action that flies vertical speed `rate` [m/s], kept clear of BlueSky's
-- "no rate selected" band and inside [-1, 1].
local function rate_action(rate)
  if math.abs(rate) < MIN_RATE then rate = rate < 0 and -MIN_RATE or MIN_RATE end
  return math.max(-1, math.min(1, rate / MAX_RATE))
end

-- The glide [m/s, downwards] that is `aim` [m] above the runway's height when the episode ends (after
-- the step that passes the runway), once the descent has started, else nil. The descent starts when
-- that glide needs `start_share` of MAX_RATE and then stays started. Keeps the runway distance of the
-- step before in self (the ground speed); shared with envs/policies/vertical_cr_steady.lua.
function P:glide(alt, runway_m, aim, start_share)
  local gs = self.prev_runway and (self.prev_runway - runway_m) / STEP_S
  self.prev_runway = runway_m
  if gs and gs > 0 then
    local time_left = math.ceil(runway_m / (gs * STEP_S)) * STEP_S
    local glide = (alt - aim) / time_left
    if glide >= start_share * MAX_RATE or self.descending then
      self.descending = true
      return glide
    end
  end
  self.descending = false
  return nil
end

-- The descent rule on altitude, runway distance and target [m]; shared with
-- envs/policies/vertical_cr.lua.
function P:descent_rate(alt, runway_m, target)
  local glide = self:glide(alt, runway_m, AIM_ALT, START_SHARE)
  if glide then return -glide end
  return (target - alt) / STEP_S                      -- back to the target within one step
end

function P:act(obs)
  local alt = 1500 + 3000 * obs[1]
  local runway_m = (100 + 200 * obs[2]) * 1000
  local target = 1500 + 3000 * obs[3]
  return {rate_action(self:descent_rate(alt, runway_m, target))}
end

P.rate_action = rate_action
return P
