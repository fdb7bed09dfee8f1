-- A trivially learnable environment for the learner's tests: each step shows
-- a sign s (+1 or -1, drawn from the episode's seed) and pays -(a - s)^2 for
-- the action a in [-1, 1]; four steps an episode. Best return 0 (a = s every
-- step); uniform random actions on a 5-level grid average -6.
local E = {
  id = "Sign-v0",
  observation = {{name = "sign", size = 1}},
  action = {low = {-1}, high = {1}},
  max_episode_steps = 4,
}

local function draw() return math.random(0, 1) * 2 - 1 end

function E:reset(seed)
  math.randomseed(seed)
  self.sign = draw()
  return {self.sign}
end

function E:step(action)
  local reward = -(action[1] - self.sign) ^ 2
  self.sign = draw()
  return {self.sign}, reward, false, false
end

return E
