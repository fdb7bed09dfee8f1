-- SectorCREnv-v0 (envs/sector_cr.lua) with conflict geometry appended to the
-- observation: numbers computed from the 31 BlueSky-Gym numbers alone (no
-- extra information), so that an MLP reads the avoidance instead of learning
-- the closest-approach algebra and the ownship's heading. The episodes,
-- rewards, infos and the first 31 observation numbers are the base
-- environment's; the id is the base's, so the rules run on this file as they are.
--
-- The ownship's heading is recovered from the intruders' relative velocities
-- (envs/policies/sector_cr_teacher.lua, heading_vector; all intruders fly at
-- one TAS); "along" is along that heading, "right" across it. Appended:
--   per intruder (the base's order, nearest first), 32-59:
--     tcpa 32-35: time to closest approach [s / 300], 0 when it is past,
--     dcpa 36-39: the miss distance [m / 9260 (5 NM)],
--     inside 40-43: 1 within 5 NM now,
--     along 44-47, right 48-51: relative position [m / 13000],
--     v_along 52-55, v_right 56-59: relative velocity [m/s / 66];
--   summaries, 60-76:
--     heading_known 60: 1 when the heading could be recovered (the per-intruder
--       frame numbers and the costs are 0 otherwise),
--     cost 61-75: the teacher's predicted intrusion cost (intruder-steps,
--       discounted, / 10) of each action of the 5-level heading grid
--       (-1, -1/2, 0, 1/2, 1; 61-65 at CAS action -1, 66-70 at 0, 71-75 at +1),
--     inside_count 76: intruders within 5 NM now / 4.

local Base = require("sector_cr")
local Teacher = require("policies.sector_cr_teacher")

local N = 4
local ZONE_M = 5 * 1852          -- [m]
local TCPA_SCALE = 300           -- [s]
local POS_SCALE, VEL_SCALE = 13000, 66  -- [m], [m/s]
local COST_SCALE = 10            -- [intruder-steps]

local slices = {}
for _, name in ipairs({"tcpa", "dcpa", "inside", "along", "right", "v_along", "v_right"}) do
  slices[#slices + 1] = {name = name, size = N}
end
slices[#slices + 1] = {name = "heading_known", size = 1}
slices[#slices + 1] = {name = "cost", size = 15}
slices[#slices + 1] = {name = "inside_count", size = 1}

local X
X = require("observation_variant").of(Base, function(obs) return X.features(obs) end, slices)

-- The base observation `obs` (31 numbers) with the numbers above appended.
function X.features(obs)
  local out = {}
  for i = 1, #obs do out[i] = obs[i] end
  local V = 150 + 6 * obs[1]
  local un, ue = Teacher.heading_vector(obs, V)
  local per = {{}, {}, {}, {}, {}, {}, {}}
  local inside_count = 0
  for k = 1, N do
    local x, y = obs[23 + k] * 13000, obs[27 + k] * 13000
    local vx, vy = obs[15 + k] * 32, obs[19 + k] * 66
    local a = vx * vx + vy * vy
    local tcpa = a > 1e-9 and math.max(0, -(x * vx + y * vy) / a) or 0
    local cx, cy = x + vx * tcpa, y + vy * tcpa
    local inside = (x * x + y * y < ZONE_M * ZONE_M) and 1 or 0
    inside_count = inside_count + inside
    per[1][k], per[2][k], per[3][k] = tcpa / TCPA_SCALE, math.sqrt(cx * cx + cy * cy) / ZONE_M, inside
    if un then
      per[4][k], per[5][k] = (x * un + y * ue) / POS_SCALE, (-x * ue + y * un) / POS_SCALE
      per[6][k], per[7][k] = (vx * un + vy * ue) / VEL_SCALE, (-vx * ue + vy * un) / VEL_SCALE
    else
      per[4][k], per[5][k], per[6][k], per[7][k] = 0, 0, 0, 0
    end
  end
  for _, block in ipairs(per) do
    for k = 1, N do out[#out + 1] = block[k] end
  end
  out[#out + 1] = un and 1 or 0
  for _, av in ipairs({-1, 0, 1}) do
    for _, ah in ipairs({-1, -0.5, 0, 0.5, 1}) do
      out[#out + 1] = un and Teacher.intrusion_cost(obs, un, ue, V, ah, av) / COST_SCALE or 0
    end
  end
  out[#out + 1] = inside_count / N
  return out
end

return X
