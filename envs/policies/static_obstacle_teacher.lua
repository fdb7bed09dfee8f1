-- A teacher for cloning StaticObstacleEnv-v0 (`squawk train --imitate` with
-- this file): the scripted rule envs/policies/static_obstacle.lua, except that
-- inside an area's enclosing circle (grown by the margin) a heading is clear of
-- that area only within ESCAPE_DEG of straight out, where the rule allows any
-- heading that points away from the centre (up to 90 deg off straight out, a
-- chord that can stay inside the circle for tens of km). Its labels are for
-- cloning only; the rule stays the baseline a trained policy is compared with
-- (docs/gym_envs.md, "What the StaticObstacle rule gets wrong").
local ESCAPE_DEG = 30  -- [deg]

local P = require("static_obstacle")
P.escape_deg = ESCAPE_DEG
return P
