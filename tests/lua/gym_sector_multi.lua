-- envs/sector_multi.lua: PettingZoo's parallel shape (tables keyed by agent),
-- agents leaving as they exit the sector, and MVP beating "do nothing".
local env = squawk.gym.load(squawk.home .. "/envs/sector_multi.lua")
check_eq(env.parallel, true)
local obs, infos = env:reset(7, {num_agents = 5})
check_eq(#env.agents, 5)
check_eq(#env.possible_agents, 5)
for _, a in ipairs(env.agents) do
  check_eq(#obs[a], 31, "SectorCREnv's observation per agent: " .. a)
  check(type(infos[a]) == "table")
end
check(obs.AG0[2] > 0.9999, "cos(drift): each agent starts toward its waypoint")
local ok, err = pcall(env.reset, env, 1, {num_agents = 1})
check(not ok and err:find("num_agents"), err)

-- one commanded agent turns; the others keep their headings
local before = {}
for _, a in ipairs(env.agents) do before[a] = select(4, env.sim:values(a)) end
local o, rewards, terms, truncs = env:step({AG1 = {1, 0}})
for _, a in ipairs(env.possible_agents) do
  check(o[a] and rewards[a] and terms[a] ~= nil and truncs[a] ~= nil, "every agent answered: " .. a)
end
local turned = math.abs(squawk.geo.wrap180(select(4, env.sim:values("AG1")) - before.AG1))
check(turned > 5, "AG1 turned, by " .. turned)
check_near(select(4, env.sim:values("AG2")), before.AG2, 1e-9, "AG2 kept its heading")

-- flying on, agents leave one by one and the episode ends before the limit
local steps, left = 1, 0
while #env.agents > 0 do
  local _, _, t = env:step({})
  for _, done in pairs(t) do if done then left = left + 1 end end
  steps = steps + 1
end
check_eq(left, 5, "every agent terminated on leaving the sector")
check(steps < env.max_episode_steps, "before the time limit: " .. steps)
check_eq(env:stats().exited, 5)

-- MVP against doing nothing, 10 agents, 4 episodes
local function los(resolution)
  local total = 0
  for k = 0, 3 do
    env:reset(k, {num_agents = 10, resolution = resolution})
    while #env.agents > 0 do env:step({}) end
    total = total + env:stats().los
  end
  return total
end
local none, mvp = los(nil), los("MVP")
check(none > 0, "10 agents on straight tracks lose separation")
check(mvp < none, "MVP loses separation less often: " .. mvp .. " vs " .. none)
