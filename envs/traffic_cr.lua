-- What BlueSky-Gym's SectorCREnv-v0 and MergeEnv-v0 share, for envs/sector_cr.lua
-- and envs/merge.lua (required by them; not an environment itself).
--
-- Facts from TUDelft-CNS-ATM/bluesky-gym at aed26d6, cited as file:line
-- (sector_cr_env.py, merge_env.py, common/functions.py); nothing is copied.
-- Units: degrees, metres, m/s, knots and NM as named.

local geo = squawk.geo

local M = {}

local MPS2KT = 1.94384  -- sector_cr_env.py:25, merge_env.py:32 (BlueSky's own is 1/0.514444)

-- numpy's np.random.uniform(lo, hi) / Python's random.uniform(lo, hi), lo +
-- (hi - lo) u, and np.random.normal(mu, sigma) (Box-Muller), from a
-- gym_draws object: the engine's seeded generator, or the values a recorded
-- BlueSky-Gym episode drew (options.draws), in order.
function M.uniform(draws, lo, hi)
  return draws:replayed() or lo + (hi - lo) * math.random()
end

function M.normal(draws, mu, sigma)
  local v = draws:replayed()
  if v then return v end
  local u1, u2 = 1 - math.random(), math.random()
  return mu + sigma * math.sqrt(-2 * math.log(u1)) * math.cos(2 * math.pi * u2)
end

-- Drift: the heading minus the bearing to the aim point, wrapped once into
-- [-180, 180] (sector_cr_env.py:258-262, merge_env.py:177-183; kwikqdrdist's
-- bearing is in [0, 360)). Returns drift [deg] and the distance [NM].
function M.drift(hdg, lat, lon, aim_lat, aim_lon)
  local qdr, dist = geo.kwikqdrdist(lat, lon, aim_lat, aim_lon)
  return geo.gym_wrap180(hdg - qdr), dist
end

-- The drift penalty: |drift| [rad] x -0.1 (sector_cr_env.py:323-326, merge_env.py:269-272).
function M.drift_reward(drift_deg)
  return math.abs(math.rad(drift_deg)) * -0.1
end

-- The action (sector_cr_env.py:314-321, merge_env.py:285-292): a[1] turns the
-- selected heading by a[1] x d_hdg [deg] from the current heading, a[2]
-- selects CAS + a[2] x d_spd [m/s], both as TrafScript HDG and SPD in knots
-- converted with BlueSky-Gym's factor. "%.17g" round-trips the double that
-- BlueSky-Gym's f-string prints.
function M.command(sim, acid, action, d_hdg, d_spd)
  local _, _, _, hdg, _, _, _, cas = sim:values(acid)
  local heading = geo.gym_wrap180(hdg + action[1] * d_hdg)
  local speed = (cas + action[2] * d_spd) * MPS2KT
  assert(sim:exec(string.format("HDG %s %.17g", acid, heading)))
  assert(sim:exec(string.format("SPD %s %.17g", acid, speed)))
end

-- The relative-traffic part of the observation (sector_cr_env.py:270-297,
-- merge_env.py:191-217): intruders ordered by `dist` (ascending; ties cannot
-- occur in floating point draws), the `n` nearest kept. own = {hdg, tas};
-- rel[i] = {dx, dy, hdg, tas, dist} of intruder i in metres (x north, y east).
-- Returns arrays x_r, y_r, vx_r, vy_r [m, m/s], cos/sin of the relative
-- track and the distances, unscaled.
function M.nearest(own, rel, n)
  local order = {}
  for i = 1, #rel do order[i] = i end
  table.sort(order, function(a, b) return rel[a][5] < rel[b][5] end)
  local vx = math.cos(math.rad(own[1])) * own[2]
  local vy = math.sin(math.rad(own[1])) * own[2]
  local o = {x = {}, y = {}, vx = {}, vy = {}, cos = {}, sin = {}, dist = {}}
  for k = 1, math.min(n, #rel) do
    local r = rel[order[k]]
    local dvx = math.cos(math.rad(r[3])) * r[4] - vx
    local dvy = math.sin(math.rad(r[3])) * r[4] - vy
    local track = math.atan(dvy, dvx)
    o.x[k], o.y[k], o.vx[k], o.vy[k] = r[1], r[2], dvx, dvy
    o.cos[k], o.sin[k], o.dist[k] = math.cos(track), math.sin(track), r[5]
  end
  return o
end

-- Intrusions: intruders within `radius_nm` of the ownship by kwikqdrdist
-- (sector_cr_env.py:328-338, merge_env.py:274-283). Returns their count.
function M.intrusions(sim, acid, ids, radius_nm)
  local lat, lon = sim:values(acid)
  local n = 0
  for _, id in ipairs(ids) do
    local ilat, ilon = sim:values(id)
    local _, d = geo.kwikqdrdist(lat, lon, ilat, ilon)
    if d < radius_nm then n = n + 1 end
  end
  return n
end

-- Appends the arrays of `parts` (each an array, or a number) to one flat array.
function M.flat(parts)
  local out = {}
  for _, p in ipairs(parts) do
    if type(p) == "number" then
      out[#out + 1] = p
    else
      for _, v in ipairs(p) do out[#out + 1] = v end
    end
  end
  return out
end

-- Each element of `t` mapped through f.
function M.map(t, f)
  local out = {}
  for i, v in ipairs(t) do out[i] = f(v) end
  return out
end

return M
