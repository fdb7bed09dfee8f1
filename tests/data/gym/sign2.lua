-- Two-component Sign-v0 for the diagonal Gaussian head's tests: each step
-- shows two signs s1, s2 (+1 or -1, drawn from the episode's seed) and pays
-- -(a1 - s1)^2 - ((a2 - 5) / 5 - s2)^2 for the action (a1, a2) in the Box
-- [-1, 1] x [0, 10]; four steps an episode. Best return 0 (a1 = s1 and
-- a2 = 5 + 5 s2 every step).
local E = {
  id = "Sign2-v0",
  observation = {{name = "signs", size = 2}},
  action = {low = {-1, 0}, high = {1, 10}},
  max_episode_steps = 4,
}

local function draw() return math.random(0, 1) * 2 - 1 end

function E:reset(seed)
  math.randomseed(seed)
  self.s1, self.s2 = draw(), draw()
  return {self.s1, self.s2}
end

function E:step(action)
  local reward = -(action[1] - self.s1) ^ 2 - ((action[2] - 5) / 5 - self.s2) ^ 2
  self.s1, self.s2 = draw(), draw()
  return {self.s1, self.s2}, reward, false, false
end

return E
