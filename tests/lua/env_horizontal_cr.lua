-- squawk.env from Lua: one paper-rules episode, the structured observation,
-- and the evaluator with the never-turn policy.
local env = squawk.env.new("scenarios/horizontal_cr.lua", "eval")
local ask = env:reset(11)
local o = env:observation()
check_eq(#o.intruder_distance, 5)
check_eq(#env:flat(), 28)
-- One shape: every field an array, the single values as one-element arrays.
check_eq(#o.cos_drift, 1)
check_eq(#o.waypoint_distance, 1)
check_near(o.cos_drift[1] * o.cos_drift[1] + o.sin_drift[1] * o.sin_drift[1], 1, 1e-9)
local total, steps = 0, 0
while ask do
  local r, done = env:step(0.5)
  total = total + r
  steps = steps + 1
  ask = not done
end
local s = env:stats()
check(s.reached or s.truncated, "episode ended")
check_eq(s.decisions, steps)
check(s.steps >= s.decisions, "automatic steps are counted too")
local st = env:state()
check_eq(#st.intruders, 5)
check(st.t > 0)

local a = squawk.env.evaluate{ scenario = "scenarios/horizontal_cr.lua", policy = "zero", episodes = 50, seed = 1 }
local b = squawk.env.evaluate{ scenario = "scenarios/horizontal_cr.lua", policy = "zero", episodes = 50, seed = 1 }
check_eq(a.episodes, 50)
check_eq(a.mean_reward, b.mean_reward)
check(a.success_rate < 0.2, "never turning collides")
check(a.actions["0"] > 0 and a.actions["0.5"] == 0, "never turning plays 0 only")
check_eq(a.most_frequent_share, 1)
-- make_policy from Lua: a constant turn, and the GPT-2 prompt policy.
local c = squawk.env.evaluate{ scenario = "scenarios/horizontal_cr.lua", policy = "constant:-0.5", episodes = 20, seed = 1 }
check(c.actions["-0.5"] > 0 and c.actions["0"] == 0, "constant:-0.5 plays -0.5 only")
local g = squawk.env.evaluate{ scenario = "scenarios/horizontal_cr.lua", policy = "gpt2", episodes = 4, seed = 1 }
check_eq(g.episodes, 4)
-- The shipped fine-tuned GPT-2 decides by the state: no single greedy action dominates.
local gg = squawk.env.evaluate{ scenario = "scenarios/horizontal_cr.lua", policy = "gpt2", episodes = 20, seed = 3, greedy = true }
check(gg.most_frequent_share < 0.8, "shipped gpt2 greedy share " .. gg.most_frequent_share)
check(gg.actions["0"] > 0 and gg.actions["0.5"] > 0 and gg.actions["-0.5"] > 0, "turns both ways and holds")
-- So does the mirror-symmetric one (table3's row beyond the paper).
local gm = squawk.env.evaluate{ scenario = "scenarios/horizontal_cr.lua", policy = "gpt2", greedy = true,
  checkpoint = "models/horizontal_cr_gpt2_tiny_mirror.ckpt", episodes = 20, seed = 3 }
check(gm.most_frequent_share < 0.8, "shipped mirror gpt2 greedy share " .. gm.most_frequent_share)
check(gm.actions["0"] > 0 and gm.actions["0.5"] > 0 and gm.actions["-0.5"] > 0, "mirror gpt2 turns both ways and holds")
local bad_ok, bad = pcall(squawk.env.evaluate, { scenario = "scenarios/horizontal_cr.lua", policy = "constant:3" })
check(not bad_ok and tostring(bad):find("%[%-1, 1%]"), tostring(bad))
local ok, err = pcall(squawk.env.new, "scenarios/no/such.lua")
check(not ok and tostring(err):find("no scenario file"), tostring(err))
