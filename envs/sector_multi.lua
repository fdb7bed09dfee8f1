-- A multi-agent sector: BlueSky-Gym's SectorCREnv-v0 (envs/sector_cr.lua)
-- with every aircraft controlled, in PettingZoo's parallel API shape.
--
--   E:reset(seed, {num_agents = n, resolution = "MVP"?}) -> observations, infos
--   E:step(actions) -> observations, rewards, terminations, truncations, infos
--
-- Each table is keyed by agent name ("AG0" .. "AG<n-1>"); E.agents lists the
-- agents still flying, E.possible_agents all of them (both set by reset).
-- The sector, the starts and the waypoints are SectorCREnv's with n aircraft
-- (its minimum of 5 does not apply); every aircraft is an agent with
-- SectorCREnv's 31-number observation (itself and its 4 nearest other agents,
-- padded with absent ones when fewer fly),
-- its 2-number action (heading +-22.5 deg, CAS +-20/3 m/s; an agent absent
-- from `actions` gets no command and keeps its selections) and its reward
-- (-0.1 per radian of drift, -1 per other aircraft within 5 NM). An agent
-- terminates when it leaves the sector (it has crossed the border, near its
-- waypoint when it flew there) and its aircraft is removed; every agent still
-- flying is truncated at step max_episode_steps (the file applies the limit
-- itself, as the C++ driver script/lua_parallel_env.h does). resolution = "MVP" switches on
-- the simulator's conflict detection (5 NM, 300 s look-ahead) and horizontal
-- MVP resolution, the baseline a policy must beat.
-- infos[agent].success, when the agent leaves: it left the sector (terminated)
-- without a loss of separation.
-- E:stats() after an episode: flight hours, losses of separation (pairs of
-- aircraft entering 5 NM), agents that left the sector and those that left
-- without a loss of separation. Units: as envs/sector_cr.lua.

local S = require("sector_cr")
local C = require("traffic_cr")
local Draws = require("gym_draws")
local geo = squawk.geo

local ACTION_FREQUENCY = 5                 -- 1 s steps, as SectorCREnv (sector_cr_env.py:31)
local D_HEADING, D_VELOCITY = 22.5, 20 / 3 -- sector_cr_env.py:35-36
local INTRUSION_DISTANCE = 5               -- [NM] sector_cr_env.py:28
local INTRUSION_PENALTY = -1               -- sector_cr_env.py:34

local M = setmetatable({
  id = "SectorMultiCR-v0",
  source = "envs/sector_cr.lua (bluesky-gym@aed26d6 sector_cr_env.py) with every aircraft an agent",
  observation = S.observation,             -- per agent
  action = S.action,                       -- per agent
  max_episode_steps = S.max_episode_steps, -- 200 steps of 5 s
  parallel = true,                         -- PettingZoo's parallel API (tables keyed by agent)
}, {__index = S})

function M:acid(k)
  return "AG" .. (k - 1)
end

-- SectorCREnv's observation holds the NEAREST nearest other aircraft; with
-- fewer flying (fewer than 5 agents, or late in an episode), each of its
-- per-neighbour slices is padded to NEAREST entries with an absent
-- neighbour: 100 km north of the agent at its velocity (relative velocity 0:
-- cos 1, sin 0), so every agent always observes 31 numbers.
local NEAREST = S.observation[3].size
local ABSENT = {cos = 1, dist = (100000 - 50000) / 15000, sin = 0, vx = 0, vy = 0, x = 100000 / 13000, y = 0}
local function padded(obs, others)
  local k = math.min(others, NEAREST)
  if k == NEAREST then return obs end
  local out, i = {}, 0
  local function copy(n)
    for _ = 1, n do
      i = i + 1
      out[#out + 1] = obs[i]
    end
  end
  local function slice(absent)
    copy(k)
    for _ = k + 1, NEAREST do out[#out + 1] = absent end
  end
  copy(2)                      -- airspeed, cos(drift)
  slice(ABSENT.cos)
  slice(ABSENT.dist)
  copy(1)                      -- sin(drift)
  slice(ABSENT.sin)
  slice(ABSENT.vx)
  slice(ABSENT.vy)
  slice(ABSENT.x)
  slice(ABSENT.y)
  return out
end

-- The observations of every agent still flying.
function M:observe_all()
  local obs = {}
  self.drifts = {}
  for _, a in ipairs(self.agents) do
    local others = {}
    for _, b in ipairs(self.agents) do
      if b ~= a then others[#others + 1] = b end
    end
    obs[a], self.drifts[a] = self:observe_aircraft(a, self.wpts[self.index[a]], others)
    obs[a] = padded(obs[a], #others)
  end
  return obs
end

function M:reset(seed, options)
  options = options or {}
  local n = options.num_agents or 10
  assert(math.type(n) == "integer" and n >= 2, "options.num_agents: a whole number >= 2")
  self.sim = self.sim or squawk.sim.new{dt_s = 1}
  self.sim:delete_all()
  if options.resolution == "MVP" then
    assert(self.sim:exec("ZONER 5; DTLOOK 300; CDMETHOD ON; RESO MVP; RMETHV OFF"))
  else
    assert(options.resolution == nil, "options.resolution: \"MVP\" or nil")
    assert(self.sim:exec("RESO OFF; CDMETHOD OFF"))
  end
  self.draws = Draws.new(seed, options and options.draws)
  self:generate_polygon()
  self.num_ac = n
  self:generate_waypoints()
  self:generate_ac()
  self.agents, self.possible_agents, self.index = {}, {}, {}
  for k, id in ipairs(self.acids) do
    self.agents[k], self.possible_agents[k], self.index[id] = id, id, k
  end
  self.steps = 0
  self.los_pairs = {}       -- "a|b" -> true while a and b are within 5 NM
  self.agent_los = {}       -- agent -> losses of separation it took part in
  self.stat = {flight_hours = 0, los = 0, exited = 0, exited_clean = 0, agents = n}
  local infos = {}
  for _, a in ipairs(self.agents) do infos[a] = {} end
  return self:observe_all(), infos
end

-- Pairs within 5 NM now: per agent the count, and new losses of separation.
function M:separation()
  local count, pos, now = {}, {}, {}
  for _, a in ipairs(self.agents) do
    count[a] = 0
    pos[a] = {self.sim:values(a)}
  end
  for i, a in ipairs(self.agents) do
    for j = i + 1, #self.agents do
      local b = self.agents[j]
      local _, d = geo.kwikqdrdist(pos[a][1], pos[a][2], pos[b][1], pos[b][2])
      if d < INTRUSION_DISTANCE then
        count[a], count[b] = count[a] + 1, count[b] + 1
        local key = a < b and a .. "|" .. b or b .. "|" .. a
        now[key] = true
        if not self.los_pairs[key] then
          self.stat.los = self.stat.los + 1
          self.agent_los[a] = (self.agent_los[a] or 0) + 1
          self.agent_los[b] = (self.agent_los[b] or 0) + 1
        end
      end
    end
  end
  self.los_pairs = now
  return count
end

function M:step(actions)
  for _, a in ipairs(self.agents) do
    local act = actions[a]
    if act then C.command(self.sim, a, act, D_HEADING, D_VELOCITY) end
  end
  self.sim:step(ACTION_FREQUENCY)
  self.steps = self.steps + 1
  self.stat.flight_hours = self.stat.flight_hours + #self.agents * ACTION_FREQUENCY / 3600
  local obs = self:observe_all()
  local count = self:separation()
  local rewards, terms, truncs, infos, flying = {}, {}, {}, {}, {}
  local limit = self.steps >= self.max_episode_steps
  for _, a in ipairs(self.agents) do
    rewards[a] = C.drift_reward(self.drifts[a]) + count[a] * INTRUSION_PENALTY
    local lat, lon = self.sim:values(a)
    terms[a] = not geo.inside(lat, lon, self.poly)
    truncs[a] = limit and not terms[a]
    infos[a] = {intrusions = count[a], los = self.agent_los[a] or 0}
    if terms[a] or truncs[a] then infos[a].success = terms[a] and not self.agent_los[a] end
    if terms[a] then
      self.stat.exited = self.stat.exited + 1
      if not self.agent_los[a] then self.stat.exited_clean = self.stat.exited_clean + 1 end
      assert(self.sim:exec("DEL " .. a))
    elseif not truncs[a] then
      flying[#flying + 1] = a
    end
  end
  self.agents = flying
  return obs, rewards, terms, truncs, infos
end

function M:stats()
  return self.stat
end

return M
