-- A scripted rule for tests/data/gym/sign2.lua, the teacher of the
-- two-component imitation test: half the first sign, and the second
-- component always at the top of its range (10, like a rule that always
-- speeds up): -0.25 a step for the first, 0 or -4 for the second.
local P = {env = "Sign2-v0"}

function P:act(obs)
  return {0.5 * obs[1], 10}
end

return P
