-- envs/sector_cr_features.lua with the teacher's per-action costs (observation
-- numbers 61-75) held at 0: the same 76 numbers otherwise, so that a clone on
-- it shows what an MLP learns from the conflict geometry alone (docs/gym_envs.md,
-- "SectorCR: a look-ahead teacher and its clone on conflict features").

local Features = require("sector_cr_features")

local COSTS_FIRST, COSTS_LAST = 61, 75

local G = setmetatable({}, {__index = Features})

local function without_costs(obs)
  for i = COSTS_FIRST, COSTS_LAST do obs[i] = 0 end
  return obs
end

function G:reset(seed, options)
  local obs, info = Features.reset(self, seed, options)
  return without_costs(obs), info
end

function G:step(action)
  local obs, reward, terminated, truncated, info = Features.step(self, action)
  return without_costs(obs), reward, terminated, truncated, info
end

return G
