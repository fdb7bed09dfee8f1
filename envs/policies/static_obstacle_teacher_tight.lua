-- The cloning teacher envs/policies/static_obstacle_teacher.lua with a clearance of
-- MARGIN_KM from each enclosing circle instead of the rule's 1 NM: with the polygon inscribed
-- in its circle, a smaller margin costs few areas and shortens the detours that run
-- episodes into the 100-step limit (docs/gym_envs.md, "What the StaticObstacle rule gets wrong").
local MARGIN_KM = 0.5  -- [km]

local P = require("static_obstacle_teacher")
P.margin_km = MARGIN_KM
return P
