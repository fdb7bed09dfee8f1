-- VerticalCREnv-v0 (envs/vertical_cr.lua) with what its scripted rule
-- (envs/policies/vertical_cr.lua) remembers from the step before appended to
-- the observation, so that a policy of one observation sees it too. The
-- episodes, rewards, infos and the first 39 observation numbers are the base
-- environment's; the id is the base's, so the rule runs on this file as it is.
-- Appended (40-45), in the base observation's units, 0 on the reset's
-- observation (the rule's "no previous step"):
--   intruder_closing 40-44: intruder_distance before the step minus after
--     it (km / 200 per step; positive when closing),
--   runway_step 45: runway_distance before the step minus after it
--     (km / 200 per step: the ground speed over one 30 s step).

local Base = require("vertical_cr")

local NUM_INTRUDERS = 5
local DISTANCE = 12  -- 1-based index of intruder_distance's first number
local RUNWAY = 17    -- 1-based index of runway_distance

local observation = {}
for i, slice in ipairs(Base.observation) do observation[i] = slice end
observation[#observation + 1] = {name = "intruder_closing", size = NUM_INTRUDERS}
observation[#observation + 1] = {name = "runway_step", size = 1}

local H = setmetatable({observation = observation}, {__index = Base})

-- obs with the differences to the previous observation appended; remembers obs.
function H:extend(obs)
  local prev = self.prev_obs
  local out = {}
  for i = 1, #obs do out[i] = obs[i] end
  for i = 0, NUM_INTRUDERS - 1 do
    out[#out + 1] = prev and prev[DISTANCE + i] - obs[DISTANCE + i] or 0
  end
  out[#out + 1] = prev and prev[RUNWAY] - obs[RUNWAY] or 0
  self.prev_obs = obs
  return out
end

function H:reset(seed, options)
  self.prev_obs = nil
  local obs, info = Base.reset(self, seed, options)
  return self:extend(obs), info
end

function H:step(action)
  local obs, reward, terminated, truncated, info = Base.step(self, action)
  return self:extend(obs), reward, terminated, truncated, info
end

return H
