-- envs/static_obstacle_features.lua: StaticObstacleEnv-v0 with per-area geometry
-- appended. Its episodes (rewards, ends, infos, the first 43 observation numbers)
-- are the base environment's under the same actions; the appended numbers do not
-- depend on the order the ten areas are listed in; on a hand-made observation they
-- are the circles' geometry worked out by hand.
local base = squawk.gym.load(squawk.home .. "/envs/static_obstacle.lua")
local feat = squawk.gym.load(squawk.home .. "/envs/static_obstacle_features.lua")
check_eq(feat.id, base.id, "the same environment, so the rules' env check passes")
check_eq(feat.max_episode_steps, base.max_episode_steps)
local size = 0
for _, slice in ipairs(feat.observation) do size = size + slice.size end
check_eq(size, 145)
check_eq(feat.observation[8].name, "blocked_lo"); check_eq(feat.observation[#feat.observation].name, "clear_right")

-- An action read from the appended numbers (towards the nearer edge of the nearest area blocking
-- the line to the waypoint, else towards the waypoint), so that the variant's episode depends on them.
local function act(obs)
  local turn = obs[134]
  if obs[135] == 1 then turn = turn + (math.abs(obs[137]) < math.abs(obs[138]) and obs[137] - 0.05 or obs[138] + 0.05) end
  return {math.max(-1, math.min(1, turn)), 1}
end

-- obs with the ten areas listed in another order (area i moved to slot order[i]).
local function permuted(obs, order)
  local out = {}
  for i = 1, #obs do out[i] = obs[i] end
  for _, start in ipairs({1, 14, 24, 34}) do
    for i = 1, 10 do out[start + order[i] - 1] = obs[start + i - 1] end
  end
  return out
end
local order = {3, 7, 1, 10, 5, 2, 9, 4, 8, 6}

local steps, blocked = 0, 0
for seed = 0, 4 do
  local ob = base:reset(seed)
  local of = feat:reset(seed)
  check_eq(#of, 145)
  for i = 1, 43 do check_eq(of[i], ob[i], "reset obs[" .. i .. "] seed " .. seed) end
  repeat
    local a = act(of)
    steps, blocked = steps + 1, blocked + of[135]
    local p = feat.extend(permuted(of, order))
    for i = 44, 145 do check_eq(p[i], of[i], "appended obs[" .. i .. "] with the areas permuted") end
    local nb, rb, tb, ub, ib = base:step(a)
    local nf, rf, tf, uf, inf = feat:step(a)
    check_eq(rf, rb, "reward, seed " .. seed .. " step " .. steps)
    check_eq(tf, tb); check_eq(uf, ub)
    check_eq(inf.success, ib.success); check_eq(inf.crashed, ib.crashed)
    for i = 1, 43 do check_eq(nf[i], nb[i], "obs[" .. i .. "] seed " .. seed) end
    of = nf
  until tb or ub
end
check(blocked > 10 and blocked < steps, "the line to the waypoint is blocked on some steps: " .. blocked .. " of " .. steps)

-- One observation by hand: the waypoint 10 deg right at 100 km; area A 8 deg right (2 deg left of
-- the waypoint) at 50 km, radius 10 km (it blocks the line and the heading); area D 25 deg right at
-- 60 km, radius 6 km (its blocked headings overlap A's); area B 90 deg right at 30 km, radius 5 km;
-- area C 150 deg right at 3 km, radius 5 km (the aircraft inside it); six more 160 km behind,
-- radius 1 km (out of reach). Interval edges are relative to the waypoint's bearing.
local R = 50 * 1.852  -- [km per unit of radius]
local obs = {}
for i = 1, 43 do obs[i] = 0 end
obs[11], obs[12], obs[13] = math.cos(math.rad(-10)), 100 / 170, math.sin(math.rad(-10))
local function area(i, th, d, r)  -- th [deg, + right] = -(heading - bearing)
  obs[i], obs[33 + i] = math.cos(math.rad(-th)), math.sin(math.rad(-th))
  obs[13 + i], obs[23 + i] = d / 170, r / R
end
area(1, 90, 30, 5)   -- B
area(2, 150, 3, 5)   -- C
area(3, 25, 60, 6)   -- D
for i = 4, 9 do area(i, 180, 160, 1 + i / 10) end
area(10, 8, 50, 10)  -- A
local x = feat.extend(obs)
local function near(got, want, what) check(math.abs(got - want) < 1e-9, what .. ": " .. got .. " against " .. want) end
local wa, wb, wd = math.deg(math.asin(10 / 50)), math.deg(math.asin(5 / 30)), math.deg(math.asin(6 / 60))
-- sorted: A (holds the waypoint's bearing), D (15 - wd from it), C (50), B (80 - wb), then the rest
near(x[44], (-2 - wa) / 45, "A's left edge"); near(x[54], (-2 + wa) / 45, "A's right edge")
near(x[45], (15 - wd) / 45, "D's left edge"); near(x[55], (15 + wd) / 45, "D's right edge")
near(x[46], (140 - 90) / 45, "C's left edge (inside: the headings towards its centre)")
near(x[47], (80 - wb) / 45, "B's left edge"); near(x[57], (80 + wb) / 45, "B's right edge")
near(x[48], 170 / 45, "out of reach: no interval, its bearing"); near(x[58], 170 / 45, "out of reach")
check_eq(x[64], 1); check_eq(x[65], 0); check_eq(x[66], 1); check_eq(x[67], 0)  -- blocks_goal: A, C (from inside)
check_eq(x[74], 1); check_eq(x[75], 0); check_eq(x[76], 1); check_eq(x[77], 0)  -- blocks_heading: A, C
near(x[84], (50 * math.sin(math.rad(2)) - 10) / 50, "A's goal clearance")
near(x[85], (60 * math.sin(math.rad(15)) - 6) / 50, "D's goal clearance")
near(x[86], (3 - 5) / 50, "C's goal clearance: the segment starts inside")
near(x[87], (30 * math.sin(math.rad(80)) - 5) / 50, "B's goal clearance")
near(x[94], (50 * math.sin(math.rad(8)) - 10) / 50, "A's heading clearance")
near(x[97], (30 - 5) / 50, "B's heading clearance (from the start of the segment)")
near(x[104], 50 * math.cos(math.rad(8)) / 170, "A's distance along the heading")
near(x[107], 0, "B abeam")
near(x[116], (3 - 5) / 170, "C's edge distance, inside")
check_eq(x[124], 0); check_eq(x[125], 0); check_eq(x[126], 1); check_eq(x[127], 0)  -- inside: C alone
near(x[134], 10 / 45, "the waypoint's bearing"); check_eq(x[135], 1)
check_eq(x[136], -1, "the nearest blocker outside its circle is A, its centre left of the line")
near(x[137], x[44], "the blocker's left edge"); near(x[138], x[54], "its right edge")
near(x[139], 50 * math.cos(math.rad(2)) / 170, "its distance along the line")
check_eq(x[140], 1, "the heading's blocker is A, its centre right of the heading")
near(x[141], x[104], "A's distance along the heading")
check_eq(x[142], 1); near(x[143], -30 / 45, "straight out of C: 30 deg left")
near(x[144], x[44], "clear on the left past A"); near(x[145], x[55], "clear on the right past A and D")
-- With the waypoint's line clear (A, D and B moved out of reach), no union holds it.
area(10, 180, 160, 2); area(3, 180, 160, 3); area(1, 180, 160, 4)
x = feat.extend(obs)
check_eq(x[135], 0); check_eq(x[144], 0); check_eq(x[145], 0)
