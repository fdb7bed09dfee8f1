-- envs/horizontal_cr.lua (the Lua form of HorizontalCR) beyond the doctest's
-- bit-for-bit comparison (tests/script/test_horizontal_cr_lua.cpp), whose
-- settings ask the agent in every episode: with waypoints 20-60 km out, many
-- paper episodes need no decision and end inside reset; their single step must
-- return the reward of those automatic steps and the episode's end, and the
-- first step of the others must carry those before it. A reward
-- declared as a Lua function replaces Eq. 1-4; a bad declaration is refused by name.
local E = squawk.gym.load("envs/horizontal_cr.lua")
check_eq(E.id, "HorizontalCR-paper-v0")

local function copy(t)
  local c = {}
  for k, v in pairs(t) do c[k] = type(v) == "table" and copy(v) or v end
  return c
end

local decl = copy(E.declaration)
decl.env.waypoint_km, decl.env.lookahead_s = {20, 60}, 300
local lua_env = E.with{declaration = decl}
local cpp = squawk.env.new(decl)

local without, with = 0, 0
for seed = 1, 60 do
  local obs, info = lua_env:reset(seed)
  local ask, pending = cpp:reset(seed)
  check_eq(info.decision, ask, "seed " .. seed)
  local want = cpp:flat()
  for k = 1, 28 do check_eq(obs[k], want[k], "seed " .. seed .. " obs " .. k) end
  if not ask then
    without = without + 1
    local _, r, term, trunc = lua_env:step({1})
    check_eq(r, pending, "a no-decision episode pays its automatic steps at its one step")
    check_eq(r, cpp:stats().total_reward)
    check(term and not trunc, "seed " .. seed .. ": reached inside reset")
  else
    with = with + 1
    local total, first = 0, true
    repeat
      local a = (seed % 5 - 2) / 2
      local o, r, term, trunc = lua_env:step({a})
      local rc, done, cut = cpp:step(a)
      if first and pending ~= 0 then rc = pending + rc end
      first = false
      check_eq(r, rc, "seed " .. seed)
      check_eq(term, done and not cut)
      check_eq(trunc, cut)
      want = cpp:flat()
      for k = 1, 28 do check_eq(o[k], want[k]) end
      total = total + r
    until term or trunc
    check_near(total, cpp:stats().total_reward, 1e-12, "the step rewards sum to the episode's return")
  end
end
check(without >= 10 and with >= 10, "both kinds of episode covered: " .. without .. " without, " .. with .. " with")

-- A Lua reward function: f.step counts the env steps of the episode.
local gym = squawk.gym.load("envs/horizontal_cr_gym.lua")
local counted = copy(gym.declaration)
counted.reward = function(f) return f.step + (f.reached and 1000 or 0) end
local g = gym.with{declaration = counted}
g:reset(3)
for k = 1, 5 do
  local _, r = g:step({0})
  check_eq(r, k, "the declared function pays f.step")
end

local ok, err = pcall(function()
  local bad = copy(gym.declaration)
  bad.rules = "arcade"
  gym.with{declaration = bad}:reset(1)
end)
check(not ok and err:find("'rules' is 'arcade'", 1, true), err)
ok, err = pcall(function()
  local bad = copy(gym.declaration)
  bad.env.intruders = 0
  gym.with{declaration = bad}:reset(1)
end)
check(not ok and err:find("intruders", 1, true), err)
