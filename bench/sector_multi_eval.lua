-- The multi-agent sector (envs/sector_multi.lua) for 2, 5, 10 and 20 agents:
-- "do nothing" (no agent is ever commanded), MVP (the simulator's horizontal
-- MVP resolution, no agent commands) and, given a checkpoint of
-- `squawk train --env envs/sector_multi.lua`, that MLP acting for every agent
-- (one policy shared by all; sampled from Rng(SEED), its mode with "greedy").
--
--   squawk run bench/sector_multi_eval.lua [EPISODES=50] [SEED=0] [CKPT [greedy]]
--       --max-instructions 0 [--openap DIR] [--allow-read DIR-OF-CKPT]
--
-- Per row: losses of separation (pairs of aircraft entering 5 NM) per agent
-- flight hour, agent success (left the sector without a loss of separation,
-- share of all agents), episode success (no loss of separation at all), the
-- mean episode reward per agent, the mean steps an agent flies before it
-- leaves (or the episode ends), and env steps/s (one step moves every agent;
-- CPU time of the whole row, the policy's included). For the MLP, what it
-- does: per action component the share of commands at each of its grid
-- levels (heading -22.5 .. +22.5 deg, CAS -20/3 .. +20/3 m/s).
local episodes = tonumber(arg[1]) or 50
local seed0 = tonumber(arg[2]) or 0
local checkpoint = arg[3]
local greedy = arg[4] == "greedy"
local env = squawk.gym.load(squawk.home .. "/envs/sector_multi.lua")

-- chooser(obs_of_agent) -> action or nil (no command); `seen` collects the actions.
local function mlp_chooser(seen)
  local policy = squawk.gym.mlp(checkpoint, env, {seed = seed0, greedy = greedy})
  return function(obs)
    local a = policy:act(obs)
    for j, v in ipairs(a) do
      seen[j] = seen[j] or {}
      seen[j][v] = (seen[j][v] or 0) + 1
    end
    seen.n = (seen.n or 0) + 1
    return a
  end
end

local function evaluate(n, resolution, choose)
  local hours, los, agents, clean, clean_eps, reward, steps, agent_steps = 0, 0, 0, 0, 0, 0, 0, 0
  local t0 = os.clock()
  for k = 0, episodes - 1 do
    local obs = env:reset(seed0 + k, {num_agents = n, resolution = resolution})
    while #env.agents > 0 do
      local actions = {}
      if choose then
        for _, a in ipairs(env.agents) do actions[a] = choose(obs[a]) end
      end
      agent_steps = agent_steps + #env.agents
      local rewards
      obs, rewards = env:step(actions)
      for _, r in pairs(rewards) do reward = reward + r end
      steps = steps + 1
    end
    local s = env:stats()
    hours, los, agents, clean = hours + s.flight_hours, los + s.los, agents + s.agents, clean + s.exited_clean
    if s.los == 0 then clean_eps = clean_eps + 1 end
  end
  local secs = os.clock() - t0
  return {los_per_hour = los / hours, agent_success = clean / agents, episode_success = clean_eps / episodes,
          reward = reward / agents, sps = steps / secs, agent_steps = agent_steps / agents}
end

local rows = {{"do nothing", nil}, {"MVP", "MVP"}}
if checkpoint then rows[3] = {greedy and "MLP (greedy)" or "MLP", nil, true} end
print(string.format("SectorMultiCR-v0 (envs/sector_multi.lua): %d episodes per row from seed %d%s", episodes,
                    seed0, checkpoint and (", MLP " .. checkpoint) or ""))
print("| agents | policy | LoS per flight hour | agent success | episode success | reward per agent | steps per agent | env steps/s |")
print("|---|---|---|---|---|---|---|---|")
local behaviour = {}
for _, n in ipairs({2, 5, 10, 20}) do
  for _, b in ipairs(rows) do
    local seen = {}
    local r = evaluate(n, b[2], b[3] and mlp_chooser(seen) or nil)
    print(string.format("| %d | %s | %.3f | %.3f | %.3f | %.2f | %.1f | %.0f |", n, b[1], r.los_per_hour,
                        r.agent_success, r.episode_success, r.reward, r.agent_steps, r.sps))
    if b[3] then behaviour[#behaviour + 1] = {n = n, seen = seen} end
  end
end
for _, b in ipairs(behaviour) do
  local parts = {}
  for j, name in ipairs({"heading", "CAS"}) do
    local levels = {}
    for v in pairs(b.seen[j] or {}) do levels[#levels + 1] = v end
    table.sort(levels)
    local shares = {}
    for _, v in ipairs(levels) do
      shares[#shares + 1] = string.format("%+.2f: %.0f %%", v, 100 * b.seen[j][v] / b.seen.n)
    end
    parts[#parts + 1] = name .. " " .. table.concat(shares, ", ")
  end
  print(string.format("MLP at %d agents: %s", b.n, table.concat(parts, "; ")))
end
