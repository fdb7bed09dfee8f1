-- envs/sector_cr_features.lua with the teacher's per-action costs (observation
-- numbers 61-75) held at 0: the same 76 numbers otherwise, so that a clone on
-- it shows what an MLP learns from the conflict geometry alone (docs/gym_envs.md,
-- "SectorCR: a look-ahead teacher and its clone on conflict features").

local Features = require("sector_cr_features")

local COSTS_FIRST, COSTS_LAST = 61, 75

local function without_costs(obs)
  for i = COSTS_FIRST, COSTS_LAST do obs[i] = 0 end
  return obs
end

return require("observation_variant").of(Features, without_costs, {})
