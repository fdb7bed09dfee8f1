-- StaticObstacleEnv-v0 (envs/static_obstacle.lua) with per-area geometry in the
-- aircraft's frame appended to the observation: numbers computed from the 43
-- BlueSky-Gym numbers alone (no extra information), so that an MLP reads whether
-- a line passes through a circle instead of learning that test once per slot.
-- The episodes, rewards, infos and the first 43 observation numbers are the base
-- environment's; the id is the base's, so the rules run on this file as they are.
--
-- Geometry (flat, as envs/policies/static_obstacle.lua's): area i's centre at
-- relative bearing th_i [deg, + right of the heading] and distance d_i [km], its
-- enclosing circle of radius r_i [km]; the waypoint at relative bearing g and
-- distance L [km]. A heading is blocked by area i when its segment of length L
-- (the line out to the waypoint's distance) meets the circle; the blocked headings
-- of an area outside its circle are th_i +- w_i (w_i the half-width: asin(r/d)
-- when the tangent point lies within L, else where the segment's end touches the
-- circle; none when d - r >= L); inside it (d < r), th_i +- 90 (every heading
-- with a component towards the centre).
--
-- Appended, ten areas per block in ascending order of their blocked interval's
-- angular distance from the waypoint's bearing (0 when it holds it; areas with
-- no blocked interval after all the others, by d - r), 44-133:
--   blocked_lo, blocked_hi 44-63: the blocked interval's edges relative to the
--     waypoint's bearing, wrap(th_i - g) -+ w_i [deg] / 45 (action units; the
--     heading that clears it on one side is g plus one of them); wrap(th_i - g) / 45
--     for both when none. Relative to the waypoint, not the heading: an area
--     behind the aircraft that a long turn must clear would jump by 360 deg as
--     its bearing crosses 180 deg off the heading,
--   blocks_goal 64-73: 1 when the segment to the waypoint meets the circle,
--   blocks_heading 74-83: 1 when the present heading's segment of length L does,
--   goal_clearance 84-93: the distance from the circle to the segment out to the
--     waypoint [km / 50], negative when it passes through,
--   heading_clearance 94-103: the same for the present heading's segment,
--   along_heading 104-113: d_i cos(th_i) [km / 170], ahead positive,
--   edge_distance 114-123: d_i - r_i [km / 170], negative inside,
--   inside 124-133: 1 inside the circle;
-- then summaries, 134-145:
--   goal_bearing 134: g / 45; goal_blocked 135: 1 when an area the aircraft is
--   outside of blocks the segment to the waypoint; of the nearest such area along
--   it (0 when none):
--   its side 136 (+1 centre right of the line, -1 left), blocked_lo 137,
--   blocked_hi 138, distance along the line 139 [km / 170]; of the nearest such
--   area blocking the present heading (0 when none): side 140, distance along 141;
--   inside_any 142: 1 inside a circle; escape_bearing 143: straight out of the
--   deepest such circle (the most inside relative to its radius), relative to
--   the heading / 45 (0 when none); clear_left 144, clear_right 145: the edges of
--   the union of blocked intervals (of the areas the aircraft is outside of) that
--   holds the waypoint's bearing, relative to it / 45, capped at -+180 deg (0 for
--   both when the bearing is clear): the nearest headings either side whose
--   segment misses every circle, the search the rules run (without their margin,
--   their 5 deg grid and their escape from inside a circle).

local Base = require("static_obstacle")

local NUM_AREAS = 10
local D_HEADING = 45     -- [deg per unit of action] (static_obstacle.lua)
local DIST_SCALE = 170   -- [km] the base observation's distance scale
local CLEAR_SCALE = 50   -- [km] of a clearance
local RADIUS_SCALE = 50 * 1.852  -- [km per unit of restricted_area_radius]
local NO_INTERVAL = 1000 -- [deg] sort key offset of an area with no blocked heading

local slices = {}
for _, name in ipairs({"blocked_lo", "blocked_hi", "blocks_goal", "blocks_heading", "goal_clearance",
                       "heading_clearance", "along_heading", "edge_distance", "inside"}) do
  slices[#slices + 1] = {name = name, size = NUM_AREAS}
end
for _, name in ipairs({"goal_bearing", "goal_blocked", "goal_blocker_side", "goal_blocker_lo", "goal_blocker_hi",
                       "goal_blocker_along", "heading_blocker_side", "heading_blocker_along", "inside_any",
                       "escape_bearing", "clear_left", "clear_right"}) do
  slices[#slices + 1] = {name = name, size = 1}
end

local X
X = require("observation_variant").of(Base, function(obs) return X.extend(obs) end, slices)

-- Relative bearing [deg, + right] from the observation's cos and sin of (heading - bearing).
local function relative(c, s)
  return -math.deg(math.atan(s, c))
end

local function wrap(deg)
  return (deg + 180) % 360 - 180
end

-- The segment of length `len` [km] at bearing `dir` [deg] against a circle at
-- bearing `th` [deg], distance `d` and radius `r` [km]: the distance from the
-- circle to the segment [km] (negative: the segment passes inside, down to -r),
-- the centre's distance along the segment's line [km] and its side (+1 right).
local function segment(dir, len, th, d, r)
  local a = math.rad(th - dir)
  local along, across = d * math.cos(a), d * math.sin(a)
  local t = math.max(0, math.min(len, along))
  local gap = math.sqrt((along - t) ^ 2 + across ^ 2) - r
  return gap, along, across >= 0 and 1 or -1
end

-- Half-width [deg] of the headings whose segment of length `len` meets a circle
-- at distance d > r; nil when none does.
local function half_width(d, r, len)
  if d - r >= len then return nil end
  if d * d - r * r <= len * len then return math.deg(math.asin(r / d)) end
  return math.deg(math.acos(math.max(-1, math.min(1, (len * len + d * d - r * r) / (2 * len * d)))))
end

-- The edges [deg] of the union of the intervals {lo, hi} (relative to the waypoint's
-- bearing) that holds 0, capped at -+180; 0, 0 when no interval holds it.
local function clear_edges(intervals)
  local left, right, grown = 0, 0, true
  while grown do
    grown = false
    for _, iv in ipairs(intervals) do
      if iv.lo <= right and iv.hi >= left and (iv.lo < left or iv.hi > right) then
        left, right, grown = math.min(left, iv.lo), math.max(right, iv.hi), true
      end
    end
  end
  return math.max(-180, left), math.min(180, right)
end

-- The 43 base numbers with the 102 above appended.
function X.extend(obs)
  local g, len = relative(obs[11], obs[13]), obs[12] * DIST_SCALE
  local areas = {}
  for i = 1, NUM_AREAS do
    local th, d, r = relative(obs[i], obs[33 + i]), obs[13 + i] * DIST_SCALE, obs[23 + i] * RADIUS_SCALE
    local a = {th = th, d = d, r = r, inside = d < r}
    local w = a.inside and 90 or half_width(d, r, len)
    local off = wrap(th - g)
    if w then
      a.lo, a.hi, a.key = off - w, off + w, math.max(0, math.abs(off) - w)
    else
      a.lo, a.hi, a.key = off, off, NO_INTERVAL + d - r
    end
    a.goal_gap, a.goal_along, a.goal_side = segment(g, len, th, d, r)
    a.hdg_gap, a.hdg_along, a.hdg_side = segment(0, len, th, d, r)
    areas[i] = a
  end
  table.sort(areas, function(p, q)
    if p.key ~= q.key then return p.key < q.key end
    return p.d - p.r < q.d - q.r
  end)
  local out = {}
  for i = 1, #obs do out[i] = obs[i] end
  local function block(f)
    for _, a in ipairs(areas) do out[#out + 1] = f(a) end
  end
  block(function(a) return a.lo / D_HEADING end)
  block(function(a) return a.hi / D_HEADING end)
  block(function(a) return a.goal_gap < 0 and 1 or 0 end)
  block(function(a) return a.hdg_gap < 0 and 1 or 0 end)
  block(function(a) return a.goal_gap / CLEAR_SCALE end)
  block(function(a) return a.hdg_gap / CLEAR_SCALE end)
  block(function(a) return a.hdg_along / DIST_SCALE end)
  block(function(a) return (a.d - a.r) / DIST_SCALE end)
  block(function(a) return a.inside and 1 or 0 end)
  local goal_blocker, hdg_blocker, deepest
  for _, a in ipairs(areas) do
    if a.inside then
      if not deepest or a.d / a.r < deepest.d / deepest.r then deepest = a end
    else
      if a.goal_gap < 0 and (not goal_blocker or a.goal_along < goal_blocker.goal_along) then goal_blocker = a end
      if a.hdg_gap < 0 and (not hdg_blocker or a.hdg_along < hdg_blocker.hdg_along) then hdg_blocker = a end
    end
  end
  out[#out + 1] = g / D_HEADING
  out[#out + 1] = goal_blocker and 1 or 0
  if goal_blocker then
    local b = goal_blocker
    for _, v in ipairs({b.goal_side, b.lo / D_HEADING, b.hi / D_HEADING, b.goal_along / DIST_SCALE}) do
      out[#out + 1] = v
    end
  else
    for _ = 1, 4 do out[#out + 1] = 0 end
  end
  out[#out + 1] = hdg_blocker and hdg_blocker.hdg_side or 0
  out[#out + 1] = hdg_blocker and hdg_blocker.hdg_along / DIST_SCALE or 0
  out[#out + 1] = deepest and 1 or 0
  out[#out + 1] = deepest and wrap(deepest.th + 180) / D_HEADING or 0
  local outside = {}
  for _, a in ipairs(areas) do
    if not a.inside and a.lo < a.hi then outside[#outside + 1] = a end
  end
  local left, right = clear_edges(outside)
  out[#out + 1] = left / D_HEADING
  out[#out + 1] = right / D_HEADING
  return out
end

return X
