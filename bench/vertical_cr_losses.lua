-- Where VerticalCREnv-v0's reward goes under one policy. Episode k is seed SEED + k, played as
-- bench/gym_paired.lua plays it (mlp: greedy; script: reset with the episode's seed). Each step's
-- reward is split into its three terms (envs/vertical_cr.lua): the intrusion penalty (−50 per
-- intruder within 5 NM and 1000 ft), the altitude shaping before the runway (−|target − alt|/600)
-- and the final term at the end (−alt/60 at the runway, −100 for a crash). The shaping is split
-- again at the policy's top of descent (the first step of the last run of steps that end lower
-- than they started and below the target): "hold" before it, "dive" from it on. Each episode
-- is put in the first class that fits:
--   crash      the aircraft touched the ground
--   intrusion  at least one intrusion step
--   high       it passed the runway above 1000 ft (305 m: not a success)
--   success    the rest
-- For each class: episodes, mean return and its terms, mean final altitude [m], and for a
-- script: policy with a `threat` method (envs/policies/vertical_cr.lua) the mean number of
-- steps it flew away from an intruder and, for "high", how many of them avoided one within
-- the last 10 steps (the avoidance left it too high to glide down).
-- With `v`, one line per episode; with `env=FILE` the episodes are FILE's (a file with the same
-- episodes and a longer observation, such as envs/vertical_cr_history.lua, for a checkpoint
-- trained on it).
-- usage: squawk run bench/vertical_cr_losses.lua POLICY [EPISODES [SEED]] [v] [env=FILE] [--openap DIR] [--allow-read DIR]
local usage = "usage: squawk run bench/vertical_cr_losses.lua POLICY [EPISODES [SEED]] [v] [env=FILE]"
local spec = assert(arg[1], usage)
local episodes, seed = tonumber(arg[2] or 200), tonumber(arg[3] or 0)
local verbose, env_file = false, "envs/vertical_cr.lua"
for i = 4, #arg do
  if arg[i] == "v" then verbose = true end
  env_file = arg[i]:match("^env=(.*)$") or env_file
end
local SUCCESS_MAX_ALT, LATE_STEPS = 1000 * 0.3048, 10

local gym = require("gym_load")

local classes = {"crash", "intrusion", "high", "success"}
local sum = {}
for _, c in ipairs(classes) do
  sum[c] = {n = 0, ret = 0, intr = 0, hold = 0, dive = 0, final = 0, alt = 0, avoid = 0, late = 0}
end
local all = {n = 0, ret = 0, intr = 0, hold = 0, dive = 0, final = 0, alt = 0, avoid = 0, late = 0}

local function play(s)
  local env = gym.load(env_file)
  local policy = gym.policy(spec, env)
  local avoided = false
  if type(policy.threat) == "function" then
    local threat = policy.threat
    policy.threat = function(self, obs)
      local dh = threat(self, obs)
      avoided = dh ~= nil
      return dh
    end
  end
  local obs = env:reset(s)
  if policy.reset then policy:reset(s) end
  local ep = {ret = 0, intr = 0, final = 0, avoid = 0, last_avoid = nil, steps = 0}
  local shaping, alts = {}, {env.altitude}
  local prev_intrusions = 0
  for t = 1, env.max_episode_steps do
    avoided = false
    local o, r, terminated, truncated = env:step(policy:act(obs))
    obs, ep.steps = o, t
    if avoided then ep.avoid, ep.last_avoid = ep.avoid + 1, t end
    local intr = -50 * (env.total_intrusions - prev_intrusions)
    prev_intrusions = env.total_intrusions
    ep.ret, ep.intr = ep.ret + r, ep.intr + intr
    alts[t + 1] = env.altitude
    if terminated then
      ep.final = r - intr
      shaping[t] = 0
    else
      shaping[t] = r - intr
    end
    if terminated or truncated then break end
  end
  -- top of descent: the start of the last run of descending steps that ends below the target
  local tod = ep.steps + 1
  for t = ep.steps, 1, -1 do
    if alts[t + 1] < alts[t] - 1 then tod = t else break end
  end
  ep.hold, ep.dive = 0, 0
  for t = 1, ep.steps do
    if t < tod then ep.hold = ep.hold + shaping[t] else ep.dive = ep.dive + shaping[t] end
  end
  ep.alt, ep.tod = env.final_altitude, tod
  ep.class = env.final_altitude < 0 and "crash" or env.total_intrusions > 0 and "intrusion"
      or env.final_altitude > SUCCESS_MAX_ALT and "high" or "success"
  ep.late = ep.last_avoid and ep.steps - ep.last_avoid < LATE_STEPS and 1 or 0
  return ep
end

for k = 0, episodes - 1 do
  local ep = play(seed + k)
  for _, acc in ipairs({sum[ep.class], all}) do
    acc.n = acc.n + 1
    for _, key in ipairs({"ret", "intr", "hold", "dive", "final", "alt", "avoid", "late"}) do
      acc[key] = acc[key] + ep[key]
    end
  end
  if verbose then
    print(string.format("seed %d: %s return %.2f (intrusion %.0f, hold %.2f, dive %.2f, final %.2f) alt %.0f m, "
                        .. "%d steps, top of descent %d, avoid %d (last %s)", seed + k, ep.class, ep.ret, ep.intr,
                        ep.hold, ep.dive, ep.final, ep.alt, ep.steps, ep.tod, ep.avoid, tostring(ep.last_avoid)))
  end
end

print(string.format("%s, %d episodes from seed %d", spec, episodes, seed))
print("class      episodes  return  intrusion    hold    dive   final  final alt  avoid steps  late avoid")
local function row(name, a)
  if a.n == 0 then return print(string.format("%-10s %8d", name, 0)) end
  print(string.format("%-10s %8d %7.2f %10.2f %7.2f %7.2f %7.2f %8.0f m %12.2f %11d", name, a.n, a.ret / a.n,
                      a.intr / a.n, a.hold / a.n, a.dive / a.n, a.final / a.n, a.alt / a.n, a.avoid / a.n, a.late))
end
for _, c in ipairs(classes) do row(c, sum[c]) end
row("all", all)
print(string.format("share of the mean return: intrusion %.2f, hold %.2f, dive %.2f, final %.2f (per episode)",
                    all.intr / all.n, all.hold / all.n, all.dive / all.n, all.final / all.n))
