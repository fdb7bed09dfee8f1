-- How StaticObstacleEnv-v0's episodes end under one policy, and why the areas are entered.
-- Episode k is seed SEED + k, played as bench/gym_paired.lua plays it (mlp: greedy; script:
-- reset with the episode's seed). Every episode ends at the waypoint, in an area (the one whose
-- polygon holds the aircraft) or at the 100-step limit. Each area episode is put in the first
-- class that fits, read from envs/static_obstacle.lua's state (centres, enclosing radii R,
-- polygons) and the rule's geometry (an area is avoided by its circle of R + MARGIN km):
--   start     the start lies within R + MARGIN of the entered area's centre
--   waypoint  the waypoint lies within R + MARGIN of the entered area's centre (no line to it
--             clears that circle)
--   blocked   a policy with a `blocked` flag (envs/policies/static_obstacle.lua) found no clear
--             heading at one of the 3 steps before the entry
--   turning   none of those: the heading changed by more than 15 deg over the 3 steps before
--             the entry (the line chosen was clear; the arc flown to reach it was not)
--   straight  the rest
-- For each class: the episodes, the entry step (mean), the clearance of the start from the
-- entered area's circle (d - R, km, mean), and the heading still to turn at the entry (deg).
-- For the start class also: in how many one of four constant actions (full turn left or right,
-- full slow-down or speed-up) keeps out of every area for 6 steps (an escape exists).
-- Limit episodes: the start distance to the waypoint, the distance left and flown (km, means).
-- With `v`, one line per episode. With `margin=KM` a script: policy with a `margin_km` field
-- flies with that margin (also MARGIN of the classes; default 1.852 km, the rule's own), with
-- `escape=DEG` one with an `escape_deg` field with that one (envs/policies/static_obstacle.lua).
-- With `env=FILE` the policy flies that observation variant of the environment (one that appends
-- numbers to the observation and keeps the episodes, as envs/static_obstacle_features.lua).
-- usage: squawk run bench/gym_static_obstacle_outcomes.lua POLICY [EPISODES [SEED]] [v] [margin=KM] [escape=DEG]
--          [env=FILE] [--openap DIR] [--allow-read DIR]
local usage = "usage: squawk run bench/gym_static_obstacle_outcomes.lua POLICY [EPISODES [SEED]] [v] [margin=KM] [escape=DEG] [env=FILE]"
local spec = assert(arg[1], usage)
local episodes, seed = tonumber(arg[2] or 200), tonumber(arg[3] or 0)
local verbose, margin, escape, env_file = false, nil, nil, "envs/static_obstacle.lua"
for i = 4, #arg do
  if arg[i] == "v" then verbose = true end
  local m, e, f = arg[i]:match("^margin=(.*)$"), arg[i]:match("^escape=(.*)$"), arg[i]:match("^env=(.*)$")
  if m then margin = assert(tonumber(m), usage) end
  if e then escape = assert(tonumber(e), usage) end
  if f then env_file = f end
end
local MARGIN = margin or 1.852  -- [km]
local NM2KM, ACID, TURNED_DEG, ESCAPE_STEPS = 1.852, "KL001", 15, 6

local gym = require("gym_load")
local geo = squawk.geo

local function wrap(deg) return (deg + 180) % 360 - 180 end

local classes = {"start", "waypoint", "blocked", "turning", "straight"}
local area = {}
for _, c in ipairs(classes) do area[c] = {n = 0, step = 0, clear0 = 0, lag = 0, escape = 0} end

-- Whether one of the four constant full actions keeps episode `s` out of every area for ESCAPE_STEPS.
local function escapes(s)
  for _, a in ipairs({{-1, -1}, {1, -1}, {-1, 1}, {1, 1}}) do
    local env = gym.load("envs/static_obstacle.lua")
    env:reset(s)
    local ok = true
    for _ = 1, ESCAPE_STEPS do
      local _, _, terminated = env:step(a)
      if env.crashed == 1 then ok = false end
      if terminated then break end
    end
    if ok then return true end
  end
  return false
end
local reached, limit = 0, {n = 0, start = 0, left = 0, flown = 0}
local total, blocked_steps, steps_all = 0, 0, 0

for k = 0, episodes - 1 do
  local s = seed + k
  local env = gym.load(env_file)
  local policy = gym.policy(spec, env)
  if margin then policy.margin_km = margin end
  if escape then policy.escape_deg = escape end
  local obs, info = env:reset(s)
  if policy.reset then policy:reset(s) end
  local lat0, lon0 = env.sim:values(ACID)
  local _, wpt0 = geo.kwikqdrdist(lat0, lon0, env.wpt_lat, env.wpt_lon)
  local singles, clear0, clear_wpt = {}, {}, {}
  for i = 1, #env.polygons do
    singles[i] = geo.polygons({env.polygons[i]})
    local _, d0 = geo.kwikqdrdist(lat0, lon0, env.obst_lat[i], env.obst_lon[i])
    local _, dw = geo.kwikqdrdist(env.wpt_lat, env.wpt_lon, env.obst_lat[i], env.obst_lon[i])
    clear0[i] = (d0 - env.radius[i]) * NM2KM
    clear_wpt[i] = (dw - env.radius[i]) * NM2KM
  end
  local ret, steps, flown, last_blocked, lag = 0, 0, 0, -100, 0
  local headings = {}  -- [deg] at the start of each step
  local lat, lon = lat0, lon0
  for t = 1, env.max_episode_steps do
    local a = policy:act(obs)
    if policy.blocked then last_blocked, blocked_steps = t, blocked_steps + 1 end
    local _, _, _, hdg = env.sim:values(ACID)
    headings[t] = hdg
    local selected = wrap(hdg + a[1] * 45)
    local o, r, terminated, truncated, i = env:step(a)
    local nlat, nlon, _, nhdg = env.sim:values(ACID)
    local _, dnm = geo.kwikqdrdist(lat, lon, nlat, nlon)
    flown, lat, lon = flown + dnm * NM2KM, nlat, nlon
    lag = math.abs(wrap(selected - nhdg))
    ret, steps, obs, info = ret + r, t, o, i
    if terminated or truncated then break end
  end
  total, steps_all = total + ret, steps_all + steps
  local _, left = geo.kwikqdrdist(lat, lon, env.wpt_lat, env.wpt_lon)
  local outcome
  if info.crashed == 1 then
    local j
    for i = 1, #singles do
      if singles[i]:count_inside(lat, lon) > 0 then j = j or i end
    end
    local _, _, _, hdg = env.sim:values(ACID)
    local turned = math.abs(wrap(hdg - headings[math.max(1, steps - 2)]))
    local c
    if clear0[j] < MARGIN then c = "start"
    elseif clear_wpt[j] < MARGIN then c = "waypoint"
    elseif steps - last_blocked < 3 then c = "blocked"
    elseif turned > TURNED_DEG then c = "turning"
    else c = "straight" end
    local a = area[c]
    a.n, a.step, a.clear0, a.lag = a.n + 1, a.step + steps, a.clear0 + clear0[j], a.lag + lag
    local escape = c == "start" and escapes(s)
    if escape then a.escape = a.escape + 1 end
    outcome = string.format("area %d (%s; start %.1f km from its circle, waypoint %.1f; turned %.0f deg in the last 3 steps%s)",
                            j, c, clear0[j], clear_wpt[j], turned, escape and "; an escape exists" or "")
  elseif info.waypoint_reached == 1 then
    reached, outcome = reached + 1, "waypoint"
  else
    limit.n, limit.start, limit.left, limit.flown =
      limit.n + 1, limit.start + wpt0 * NM2KM, limit.left + left * NM2KM, limit.flown + flown
    outcome = string.format("limit (%.1f km left of %.1f; %.1f flown)", left * NM2KM, wpt0 * NM2KM, flown)
  end
  if verbose then
    print(string.format("seed %d: %.3f, %d steps, %s; heading still to turn %.1f deg", s, ret, steps, outcome, lag))
  end
end

print(string.format("%s: mean %.3f over %d episodes (seed %d), %.1f steps; waypoint %d, limit %d, area %d",
                    spec, total / episodes, episodes, seed, steps_all / episodes, reached, limit.n,
                    episodes - reached - limit.n))
print(string.format("no clear heading (rule's blocked flag) on %d of %d steps", blocked_steps, steps_all))
for _, c in ipairs(classes) do
  local a = area[c]
  if a.n > 0 then
    print(string.format("  area, %-8s %3d: entry step %.1f, start %.1f km from the circle, heading still to turn %.1f deg%s",
                        c, a.n, a.step / a.n, a.clear0 / a.n, a.lag / a.n,
                        c == "start" and string.format("; an escape exists in %d", a.escape) or ""))
  end
end
if limit.n > 0 then
  print(string.format("  limit %d: waypoint %.1f km at the start, %.1f km left, %.1f km flown", limit.n,
                      limit.start / limit.n, limit.left / limit.n, limit.flown / limit.n))
end
