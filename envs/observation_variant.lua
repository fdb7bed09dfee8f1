-- An observation variant of an environment (docs/gym_envs.md): the base environment's episodes,
-- actions and rewards, with every observation passed through `map(obs)` on reset and step. `slices`
-- ({name = ..., size = n} each) are appended to the base's observation declaration, in the order
-- `map` appends their numbers. Not an environment itself.
local V = {}

function V.of(Base, map, slices)
  local observation = {}
  for i, slice in ipairs(Base.observation) do observation[i] = slice end
  for _, slice in ipairs(slices) do observation[#observation + 1] = slice end
  local X = setmetatable({observation = observation}, {__index = Base})
  function X:reset(seed, options)
    local obs, info = Base.reset(self, seed, options)
    return map(obs), info
  end
  function X:step(action)
    local obs, reward, terminated, truncated, info = Base.step(self, action)
    return map(obs), reward, terminated, truncated, info
  end
  return X
end

return V
