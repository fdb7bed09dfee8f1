-- Baselines of the multi-agent sector (envs/sector_multi.lua): "do nothing"
-- (no agent is ever commanded) and MVP (the simulator's horizontal MVP
-- resolution, no agent commands), for 2, 5, 10 and 20 agents.
--
--   squawk run bench/sector_multi_eval.lua [EPISODES=50] [SEED=0] --max-instructions 0 [--openap DIR]
--
-- Per row: losses of separation (pairs of aircraft entering 5 NM) per agent
-- flight hour, agent success (left the sector without a loss of separation,
-- share of all agents), episode success (no loss of separation at all), the
-- mean episode reward per agent, and env steps/s (one step moves every agent).
local episodes = tonumber(arg[1]) or 50
local seed0 = tonumber(arg[2]) or 0
local env = squawk.gym.load(squawk.home .. "/envs/sector_multi.lua")

local function evaluate(n, resolution)
  local hours, los, agents, clean, clean_eps, reward, steps = 0, 0, 0, 0, 0, 0, 0
  local t0 = os.clock()
  for k = 0, episodes - 1 do
    env:reset(seed0 + k, {num_agents = n, resolution = resolution})
    while #env.agents > 0 do
      local _, rewards = env:step({})
      for _, r in pairs(rewards) do reward = reward + r end
      steps = steps + 1
    end
    local s = env:stats()
    hours, los, agents, clean = hours + s.flight_hours, los + s.los, agents + s.agents, clean + s.exited_clean
    if s.los == 0 then clean_eps = clean_eps + 1 end
  end
  local secs = os.clock() - t0
  return {los_per_hour = los / hours, agent_success = clean / agents, episode_success = clean_eps / episodes,
          reward = reward / agents, sps = steps / secs}
end

print(string.format("SectorMultiCR-v0 (envs/sector_multi.lua): %d episodes per row from seed %d", episodes, seed0))
print("| agents | baseline | LoS per flight hour | agent success | episode success | reward per agent | env steps/s |")
print("|---|---|---|---|---|---|---|")
for _, n in ipairs({2, 5, 10, 20}) do
  for _, b in ipairs({{"do nothing", nil}, {"MVP", "MVP"}}) do
    local r = evaluate(n, b[2])
    print(string.format("| %d | %s | %.3f | %.3f | %.3f | %.2f | %.0f |", n, b[1], r.los_per_hour, r.agent_success,
                        r.episode_success, r.reward, r.sps))
  end
end
