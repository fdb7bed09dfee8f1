-- The cloning teacher envs/policies/static_obstacle_teacher_tight.lua with every
-- selected heading turn of more than SAT_DEG labelled as the full turn (-1 or 1).
-- In one env step (10 s at about 1.6 deg/s) the aircraft turns at most about
-- 16 deg, so any larger selected turn flies the same step: this teacher flies
-- exactly as the tight one (every one of 1000 episodes of seeds 0 and 5000; with
-- 15 deg, 9 of 100 differ), and a clone's mean may err by up to 0.6 on such a turn
-- without changing the flight (docs/gym_envs.md, "A StaticObstacle MLP from
-- saturated labels (measured)"). Its labels are for cloning only. Units: degrees.
local SAT_DEG = 17  -- [deg] a larger selected turn is labelled +-45 deg (action +-1)
local D_HEADING = 45  -- [deg per unit of action] (envs/static_obstacle.lua)

local Tight = require("static_obstacle_teacher_tight")
-- A table of its own over the tight teacher's fields, so that the module tables
-- the teachers share keep their act.
local P = setmetatable({env = Tight.env}, {__index = Tight})
function P:act(obs)
  local a = Tight.act(self, obs)
  if math.abs(a[1]) * D_HEADING > SAT_DEG then a[1] = a[1] > 0 and 1 or -1 end
  return a
end
return P
