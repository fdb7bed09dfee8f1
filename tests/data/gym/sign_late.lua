-- A scripted rule for tests/data/gym/sign.lua that decides from memory: half
-- the sign shown one step earlier (0 at an episode's first step), so a fresh
-- instance given one of its later observations answers differently (0). The
-- replay probe of bench/gym_imitation_probe.lua counts those decisions.
local P = {env = "Sign-v0"}

function P:reset(seed)
  self.previous = 0
end

function P:act(obs)
  local a = 0.5 * self.previous
  self.previous = obs[1]
  return {a}
end

return P
