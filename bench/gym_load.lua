-- Shared by the bench/gym_*.lua tools: a fresh load of an environment or rule file, and a policy
-- from its command-line spec.
local M = {}

-- An environment and a rule may each require a module of the same name from their own folders
-- (envs/descent.lua, envs/policies/descent.lua): every load starts without the modules an earlier
-- one cached (those loaded before this module stay).
local preloaded = { [(...)] = true }
for name in pairs(package.loaded) do preloaded[name] = true end
function M.load(path)
  for name in pairs(package.loaded) do
    if not preloaded[name] then package.loaded[name] = nil end
  end
  return squawk.gym.load(path)
end

-- "script:FILE" (a Lua rule, freshly loaded) or "mlp:CKPT" (the checkpoint's MLP on env, greedy).
function M.policy(spec, env)
  if spec:sub(1, 7) == "script:" then return M.load(spec:sub(8)) end
  if spec:sub(1, 4) == "mlp:" then return squawk.gym.mlp(spec:sub(5), env, {seed = 0, greedy = true}) end
  error("policy " .. spec .. ": expected script:FILE or mlp:CKPT")
end

return M
