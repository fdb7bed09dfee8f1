-- A scripted rule for tests/data/gym/sign.lua, the teacher of the imitation
-- tests: half the shown sign (-0.25 a step, -1 an episode). It counts its
-- steps since P:reset and fails past the episode's four, so a driver that
-- does not reset it before every episode is caught.
local P = {env = "Sign-v0"}

function P:reset(seed)
  self.steps = 0
end

function P:act(obs)
  assert(self.steps, "act before reset")
  self.steps = self.steps + 1
  assert(self.steps <= 4, "five steps since reset: the episode has four")
  return {0.5 * obs[1]}
end

return P
