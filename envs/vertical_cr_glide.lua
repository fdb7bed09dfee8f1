-- VerticalCREnv-v0 with the rule's memory (envs/vertical_cr_history.lua, 45
-- numbers) and two numbers the rule (envs/policies/vertical_cr.lua) computes
-- from it by division, which an MLP fits poorly: the episodes, rewards and
-- infos are the base environment's, the id is the base's. Appended (46-47),
-- 0 on the reset's observation (no ground speed yet) and while the last
-- step did not bring the runway closer:
--   runway_steps 46: runway distance / the last step's runway distance flown,
--     over 40 (the steps left at this ground speed; about 1 at the start),
--   glide 47: the vertical speed that reaches the runway's height as the
--     aircraft passes it at this ground speed, -altitude / (steps left x 30 s),
--     in action units (/ 12.5 m/s; the action it needs, unclipped).

local History = require("vertical_cr_history")

local STEP_S = 30        -- [s] one env step
local ACTION_2_MS = 12.5 -- [m/s] per unit of action
local STEPS_SCALE = 40   -- [steps] runway_steps' scale

local observation = {}
for i, slice in ipairs(History.observation) do observation[i] = slice end
observation[#observation + 1] = {name = "runway_steps", size = 1}
observation[#observation + 1] = {name = "glide", size = 1}

local G = setmetatable({observation = observation}, {__index = History})

function G:extend(obs)
  local out = History.extend(self, obs)
  local alt = 1500 + 3000 * out[1]          -- [m] (altitude: (alt - 1500) / 3000)
  local runway_km = 100 + 200 * out[17]     -- [km] (runway_distance: (d - 100) / 200)
  local step_km = 200 * out[45]             -- [km] runway_step
  local steps = step_km > 0 and runway_km / step_km or 0
  out[#out + 1] = steps / STEPS_SCALE
  out[#out + 1] = steps > 0 and -alt / (steps * STEP_S) / ACTION_2_MS or 0
  return out
end

return G
