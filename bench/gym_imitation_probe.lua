-- How closely a cloned MLP reproduces the scripted rule it was cloned from,
-- measured on one environment file, per action component:
--   rule states   the rule flies episodes SEED .. SEED+EPISODES-1; at every
--                 decision the clone's greedy action is compared with the rule's
--   clone states  the clone flies (greedy) the same episodes and a second
--                 instance of the rule labels every decision (DAgger's view)
--   replay        every rule-state observation is given again to a fresh rule
--                 instance (reset with the episode's seed, no earlier decision):
--                 the share of decisions it answers differently is the share the
--                 rule decides from something the observation lacks (memory)
--   jumps         every rule-state observation, each number moved by
--                 N(0, (EPS * its spread over the rule's states)^2): the share of
--                 decisions where the rule's action moves by more than 0.5 of
--                 the [-1, 1] range (a discontinuity within EPS of the state;
--                 both answers from fresh instances), beside the clone's share
--   noise         the rule flown with N(0, s^2) added to every action component
--                 (clipped to [-1, 1]) for s in NOISE: its mean return, what an
--                 imitator with that error and no bias would reach
-- Per component: the mean and root mean square of |clone - rule| and the share
-- within 0.1, in action units ([-1, 1]: StaticObstacle's heading unit is 45 deg).
-- With `trace=K1,K2,...` the two flights of those episodes side by side, step by
-- step: each policy's action, and (with `id=ACID`, a file whose env.sim flies
-- that aircraft) both headings [deg].
-- usage: squawk run bench/gym_imitation_probe.lua ENV.lua mlp:CKPT script:RULE.lua [EPISODES [SEED]]
--          [trace=K,...] [id=ACID] [eps=EPS] [noise=S,...] [--openap DIR] [--allow-read DIR]
local usage = "usage: squawk run bench/gym_imitation_probe.lua ENV.lua mlp:CKPT script:RULE.lua [EPISODES [SEED]] ..."
local env_file, clone_spec, rule_spec = assert(arg[1], usage), assert(arg[2], usage), assert(arg[3], usage)
assert(clone_spec:sub(1, 4) == "mlp:" and rule_spec:sub(1, 7) == "script:", usage)
local episodes, seed = tonumber(arg[4] or 100), tonumber(arg[5] or 0)
local opt = {}
for i = 6, #arg do
  local k, v = arg[i]:match("^(%w+)=(.*)$")
  if k then opt[k] = v end
end
local function list(s)
  local t = {}
  for x in (s or ""):gmatch("[^,]+") do t[#t + 1] = tonumber(x) end
  return t
end
local traced = {}
for _, k in ipairs(list(opt.trace)) do traced[k] = true end
local eps = tonumber(opt.eps or 0.01)
local noises = opt.noise and list(opt.noise) or {0.02, 0.05, 0.1, 0.2}

local gym = require("gym_load")
local load = gym.load

local function rule_for(s)
  local r = load(rule_spec:sub(8))
  if r.reset then r:reset(s) end
  return r
end

local function copy(t)
  local c = {}
  for i, v in ipairs(t) do c[i] = v end
  return c
end

local function heading(env)
  if not (opt.id and env.sim) then return nil end
  local _, _, _, hdg = env.sim:values(opt.id)
  return hdg
end

-- Flies episode s with `flier` (a policy) and calls on_step(obs, action, env) before each step.
-- Returns the return and the number of steps.
local function fly(env, flier, s, on_step)
  local obs = env:reset(s)
  local total, steps = 0, 0
  for t = 1, env.max_episode_steps do
    local a = flier:act(obs)
    if on_step then on_step(obs, a, env) end
    local o, r, terminated, truncated = env:step(a)
    total, steps, obs = total + r, t, o
    if terminated or truncated then break end
  end
  return total, steps
end

-- Accumulates per-component |a - b|.
local function errors()
  return {n = 0, sum = {}, sq = {}, near = {}}
end
local function add(e, a, b)
  e.n = e.n + 1
  for i = 1, #a do
    local d = math.abs(a[i] - b[i])
    e.sum[i] = (e.sum[i] or 0) + d
    e.sq[i] = (e.sq[i] or 0) + d * d
    e.near[i] = (e.near[i] or 0) + (d <= 0.1 and 1 or 0)
  end
end
local function report(name, e)
  local parts = {}
  for i = 1, #e.sum do
    parts[#parts + 1] = string.format("component %d: mean %.3f, rms %.3f, within 0.1 %.3f", i, e.sum[i] / e.n,
                                      math.sqrt(e.sq[i] / e.n), e.near[i] / e.n)
  end
  print(string.format("%s (%d decisions): %s", name, e.n, table.concat(parts, "; ")))
end

local env = load(env_file)
local clone = squawk.gym.mlp(clone_spec:sub(5), env, {seed = 0, greedy = true})

-- Rule states: the rule flies, the clone answers; kept for the replay and jump probes.
local on_rule, states = errors(), {}
local rule_total, clone_total = 0, 0
for k = 0, episodes - 1 do
  local s = seed + k
  local rule = rule_for(s)
  rule_total = rule_total + fly(env, rule, s, function(obs, a)
    local c = clone:act(obs)
    add(on_rule, c, a)
    states[#states + 1] = {obs = copy(obs), action = copy(a), clone = c, seed = s}
  end)
end
report("rule states, |clone - rule|", on_rule)

-- The rule-state error of component 1 by the size of the rule's own action there.
local buckets = {{0, 0.05}, {0.05, 0.5}, {0.5, 0.999}, {0.999, math.huge}}
local parts = {}
for _, b in ipairs(buckets) do
  local n, sum = 0, 0
  for _, st in ipairs(states) do
    local m = math.abs(st.action[1])
    if m >= b[1] and m < b[2] then n, sum = n + 1, sum + math.abs(st.clone[1] - st.action[1]) end
  end
  parts[#parts + 1] = string.format("[%g, %g): %.3f of decisions, mean %.3f", b[1], b[2], n / #states,
                                    n > 0 and sum / n or 0)
end
print("rule states, component 1 by the rule's |action|: " .. table.concat(parts, "; "))

-- Clone states: the clone flies, a rule instance that has seen every one of its states labels them.
local on_clone, firsts = errors(), {}
for k = 0, episodes - 1 do
  local s = seed + k
  local rule = rule_for(s)
  local t, first = 0, nil
  clone_total = clone_total + fly(env, clone, s, function(obs, a)
    local label = rule:act(obs)
    add(on_clone, a, label)
    t = t + 1
    for i = 1, #a do
      if not first and math.abs(a[i] - label[i]) > 0.1 then first = {t, math.abs(label[1]) > 0.1} end
    end
  end)
  firsts[#firsts + 1] = first or {math.huge, false}
end
report("clone states, |clone - rule|", on_clone)
-- Divergence: the first decision of each clone flight more than 0.1 from the rule's label there.
table.sort(firsts, function(x, y) return x[1] < y[1] end)
local at_first, turning, never = 0, 0, 0
for _, f in ipairs(firsts) do
  if f[1] == 1 then at_first = at_first + 1 end
  if f[1] == math.huge then never = never + 1 elseif f[2] then turning = turning + 1 end
end
local median = firsts[(#firsts + 1) // 2][1]
print(string.format("divergence: the clone first leaves the rule's label by more than 0.1 at step %s (median over %d "
                    .. "episodes); at step 1 in %d, never in %d; the rule was turning (|label 1| > 0.1) there in %d",
                    median == math.huge and "never" or tostring(median), #firsts, at_first, never, turning))
print(string.format("mean return over %d episodes: rule %.3f, clone (greedy) %.3f", episodes, rule_total / episodes,
                    clone_total / episodes))

-- Replay: a fresh rule instance for every decision.
local differ = 0
for _, st in ipairs(states) do
  local a = rule_for(st.seed):act(copy(st.obs))
  for i = 1, #a do
    if math.abs(a[i] - st.action[i]) > 1e-9 then
      differ = differ + 1
      break
    end
  end
end
print(string.format("replay: a fresh rule answers %d of %d rule-state observations differently (%.3f)", differ,
                    #states, differ / #states))

-- Jumps: the rule's and the clone's answer to a slightly moved observation.
math.randomseed(seed)
local function gauss()
  return math.sqrt(-2 * math.log(1 - math.random())) * math.cos(2 * math.pi * math.random())
end
local size = #states[1].obs
local mean, sd = {}, {}
for j = 1, size do
  local m, q = 0, 0
  for _, st in ipairs(states) do m = m + st.obs[j] end
  m = m / #states
  for _, st in ipairs(states) do q = q + (st.obs[j] - m) ^ 2 end
  mean[j], sd[j] = m, math.sqrt(q / #states)
end
local rule_jumps, clone_jumps = 0, 0
for _, st in ipairs(states) do
  local moved = {}
  for j = 1, size do moved[j] = st.obs[j] + eps * sd[j] * gauss() end
  local a, b = rule_for(st.seed):act(copy(st.obs)), rule_for(st.seed):act(copy(moved))  -- fresh: no memory between
  local c, d = clone:act(copy(st.obs)), clone:act(moved)
  local rj, cj = false, false
  for i = 1, #a do
    rj = rj or math.abs(a[i] - b[i]) > 0.5
    cj = cj or math.abs(c[i] - d[i]) > 0.5
  end
  rule_jumps = rule_jumps + (rj and 1 or 0)
  clone_jumps = clone_jumps + (cj and 1 or 0)
end
print(string.format("jumps: each number moved by %.3g of its spread, the action moves by more than 0.5 in %.4f of rule "
                    .. "states (rule) and %.4f (clone)", eps, rule_jumps / #states, clone_jumps / #states))

-- Noise: the rule flown with noisy actions.
for _, sigma in ipairs(noises) do
  local total = 0
  for k = 0, episodes - 1 do
    local s = seed + k
    local rule = rule_for(s)
    local noisy = {act = function(_, obs)
      local a = rule:act(obs)
      for i = 1, #a do a[i] = math.max(-1, math.min(1, a[i] + sigma * gauss())) end
      return a
    end}
    total = total + fly(env, noisy, s)
  end
  print(string.format("noise: the rule with N(0, %.3g^2) on every action component: mean return %.3f", sigma,
                      total / episodes))
end

-- Trace: the two flights of one episode side by side.
for k = 0, episodes - 1 do
  local s = seed + k
  if traced[s] then
    local by_rule, by_clone = {}, {}
    local r_total, r_steps = fly(env, rule_for(s), s, function(_, a, e) by_rule[#by_rule + 1] = {a, heading(e)} end)
    local labeller = rule_for(s)
    local c_total, c_steps = fly(env, clone, s, function(obs, a, e)
      by_clone[#by_clone + 1] = {a, heading(e), labeller:act(obs)}
    end)
    print(string.format("trace seed %d: rule %.3f in %d steps, clone %.3f in %d steps", s, r_total, r_steps, c_total,
                        c_steps))
    print("step | rule action | rule hdg | clone action | clone hdg | rule's label at the clone's state")
    local function fmt(a)
      if not a then return "-" end
      local p = {}
      for i = 1, #a do p[i] = string.format("%+.2f", a[i]) end
      return table.concat(p, " ")
    end
    for t = 1, math.max(#by_rule, #by_clone) do
      local r, c = by_rule[t] or {}, by_clone[t] or {}
      local function deg(h) return h and string.format("%6.1f", h) or "-" end
      print(string.format("%3d | %s | %s | %s | %s | %s", t, fmt(r[1]), deg(r[2]), fmt(c[1]), deg(c[2]), fmt(c[3])))
    end
  end
end
