-- Where a PlanWaypointEnv-v0 policy misses: episode k (seed SEED + k) played
-- on a freshly loaded envs/plan_waypoint.lua, as bench/gym_paired.lua plays
-- it, and for each episode the geometry the policy met: the straight-line
-- tour from the start through the waypoints in the order it reached them, in
-- nearest-neighbour order and in the shortest of the 120 orders, the distance
-- it flew, its turning, and the waypoints left at the end.
-- usage: squawk run bench/plan_waypoint_misses.lua POLICY [EPISODES [SEED [v]]] [--openap DIR] [--allow-read DIR]
--   POLICY as bench/gym_paired.lua takes it (script:FILE or mlp:CKPT, greedy).
-- Prints one line per missed episode (with `v`, per episode), then a summary:
-- successes, the distance one episode allows (300 steps of 10 s at the
-- ground speed flown), and how the missed episodes' tours compare with it.
-- Units: km, degrees.
local usage = "usage: squawk run bench/plan_waypoint_misses.lua POLICY [EPISODES [SEED [v]]]"
local policy_spec = assert(arg[1], usage)
local episodes, seed, verbose = tonumber(arg[2] or 1000), tonumber(arg[3] or 0), arg[4] == "v"

local gym = require("gym_load")
local geo = squawk.geo
local ENV_FILE, ACID, NM2KM = "envs/plan_waypoint.lua", "KL001", 1.852

local function dist_km(lat1, lon1, lat2, lon2)
  local _, d = geo.kwikqdrdist(lat1, lon1, lat2, lon2)
  return d * NM2KM
end

-- The straight-line length [km] from point 0 through the points in `order`
-- (indices into pts, point 0 the start).
local function tour(pts, order)
  local len, cur = 0, pts[0]
  for _, i in ipairs(order) do
    len = len + dist_km(cur[1], cur[2], pts[i][1], pts[i][2])
    cur = pts[i]
  end
  return len
end

local function permutations(n)
  local out, used, cur = {}, {}, {}
  local function rec()
    if #cur == n then out[#out + 1] = {table.unpack(cur)} return end
    for i = 1, n do
      if not used[i] then
        used[i], cur[#cur + 1] = true, i
        rec()
        used[i], cur[#cur] = false, nil
      end
    end
  end
  rec()
  return out
end
local ORDERS = permutations(5)

-- Nearest-neighbour order of pts[1..5] from pts[0] (straight lines).
local function nn_order(pts)
  local order, open, cur = {}, {true, true, true, true, true}, pts[0]
  for _ = 1, 5 do
    local best, bd
    for i = 1, 5 do
      if open[i] then
        local d = dist_km(cur[1], cur[2], pts[i][1], pts[i][2])
        if not best or d < bd then best, bd = i, d end
      end
    end
    order[#order + 1], open[best], cur = best, false, pts[best]
  end
  return order
end

local function play(k)
  local env = gym.load(ENV_FILE)
  local policy = gym.policy(policy_spec, env)
  local obs = env:reset(k)
  if policy.reset then policy:reset(k) end
  local lat, lon, _, hdg = env.sim:values(ACID)
  local pts = {[0] = {lat, lon}}
  for i = 1, 5 do pts[i] = {env.wpt_lat[i], env.wpt_lon[i]} end
  local reached_order, flown, turned, gs_sum, gs_n, steps, total, info = {}, 0, 0, 0, 0, 0, 0, nil
  local acts = {0, 0, 0}   -- actions below -1/3, between, above 1/3
  for t = 1, env.max_episode_steps do
    local before = {}
    for i = 1, 5 do before[i] = env.wpt_reach[i] end
    local a = policy:act(obs)[1]
    local third = a < -1 / 3 and 1 or a > 1 / 3 and 3 or 2
    acts[third] = acts[third] + 1
    local o, r, terminated, truncated, i = env:step({a})
    obs, total, steps, info = o, total + r, t, i
    for w = 1, 5 do
      if before[w] == 0 and env.wpt_reach[w] == 1 then reached_order[#reached_order + 1] = w end
    end
    if env.sim:count() > 0 then
      local la, lo, _, h, _, g = env.sim:values(ACID)
      flown = flown + dist_km(lat, lon, la, lo)
      turned = turned + math.abs(geo.gym_wrap180(h - hdg))
      gs_sum, gs_n = gs_sum + g, gs_n + 1
      lat, lon, hdg = la, lo, h
    end
    if terminated or truncated then break end
  end
  local open_d = {}
  for w = 1, 5 do
    if env.wpt_reach[w] == 0 then open_d[#open_d + 1] = string.format("%.1f", dist_km(lat, lon, pts[w][1], pts[w][2])) end
  end
  local best_len = math.huge
  for _, o in ipairs(ORDERS) do best_len = math.min(best_len, tour(pts, o)) end
  return {
    total = total, steps = steps, success = info.success, reached = #reached_order,
    nn = tour(pts, nn_order(pts)), best = best_len,
    flown = flown, turned = turned, gs = gs_sum / math.max(gs_n, 1), acts = acts,
    open_d = table.concat(open_d, " "), order = table.concat(reached_order, ""),
  }
end

local n_ok, sum_total, miss, allowance_sum, act_sum = 0, 0, {}, 0, {0, 0, 0}
for k = 0, episodes - 1 do
  local e = play(seed + k)
  sum_total = sum_total + e.total
  allowance_sum = allowance_sum + e.gs * 3000 / 1000
  for c = 1, 3 do act_sum[c] = act_sum[c] + e.acts[c] end
  if e.success then n_ok = n_ok + 1 else miss[#miss + 1] = e end
  if verbose or not e.success then
    print(string.format("seed %d: %s reached %d in %d steps (order %s); tours nn %.0f best %.0f km; flown %.0f km; "
                        .. "turned %.0f deg; open waypoints at %s km", seed + k, e.success and "ok" or "MISS",
                        e.reached, e.steps, e.order, e.nn, e.best, e.flown, e.turned, e.open_d))
  end
end
local allowance = allowance_sum / episodes
local acts_n = act_sum[1] + act_sum[2] + act_sum[3]
print(string.format("%s: mean %.3f; all five in %d of %d; one episode allows %.0f km (300 steps at the mean ground speed)",
                    policy_spec, sum_total / episodes, n_ok, episodes, allowance))
print(string.format("action shares (< -1/3, between, > 1/3): %.3f/%.3f/%.3f", act_sum[1] / acts_n,
                    act_sum[2] / acts_n, act_sum[3] / acts_n))
local nn_over, best_fits = 0, 0
for _, e in ipairs(miss) do
  if e.nn > allowance then nn_over = nn_over + 1 end
  if e.best < allowance then best_fits = best_fits + 1 end
end
print(string.format("missed %d: nearest-neighbour straight tour longer than the allowance in %d; shortest order shorter than it in %d",
                    #miss, nn_over, best_fits))
