-- squawk.rl.train / squawk.rl.evaluate: a tiny MLP run through the CLI's learner.
local S = "scenarios/horizontal_cr.lua"
local seen = {}
local r = squawk.rl.train{
  scenario = S, policy = "mlp", seed = 5, episodes = 64, episodes_per_update = 16, envs = 8,
  eval_every = 32, eval_episodes = 8,
  on_update = function(u) seen[#seen + 1] = u end,
}
check_eq(r.ended, "finished", "a run to its end")
check_eq(r.episodes, 64, "episodes trained")
check_eq(r.updates, 4, "64 episodes at 16 per update")
check_eq(#seen, 4, "on_update once per update")
for i, u in ipairs(seen) do
  check_eq(u.update, i, "updates are counted from 1")
  check_eq(u.episodes, 16 * i, "episodes so far")
  check(u.samples > 0, "every batch has decisions")
  check(u.success_rate >= 0 and u.success_rate <= 1, "success is a share: " .. u.success_rate)
  check(u.mean_return == u.mean_return and u.mean_return < 10, "finite return: " .. u.mean_return)
  check(u.entropy > 0 and u.entropy <= math.log(5) + 1e-9, "categorical entropy over 5 actions: " .. u.entropy)
  check(u.grad_norm > 0, "a step was taken")
end
check(seen[1].eval == nil and seen[2].eval ~= nil and seen[4].eval ~= nil, "evaluations at 32 and 64 episodes")
check_eq(seen[2].eval.episodes, 8, "eval_episodes")
check(r.eval and r.eval.success_rate == seen[4].eval.success_rate, "the result carries the last evaluation")

-- The same seed gives the same numbers; false from on_update stops after that update.
local again = {}
local s = squawk.rl.train{
  scenario = S, policy = "mlp", seed = 5, episodes = 64, episodes_per_update = 16, envs = 8,
  eval_every = 32, eval_episodes = 8,
  on_update = function(u) again[#again + 1] = u; return u.update < 2 end,
}
check_eq(s.ended, "stopped", "on_update returned false")
check_eq(s.updates, 2, "stopped after the second update")
for i = 1, 2 do
  check_eq(again[i].mean_return, seen[i].mean_return, "update " .. i .. " repeats bit for bit")
  check_eq(again[i].entropy, seen[i].entropy, "update " .. i .. " entropy repeats")
end

-- An error in the callback ends the run with it; bad keys name themselves.
local ok, err = pcall(squawk.rl.train, {scenario = S, episodes = 16, episodes_per_update = 16, envs = 4,
                                        on_update = function() error("curriculum says no") end})
check(not ok and tostring(err):find("on_update: .*curriculum says no"), tostring(err))
ok, err = pcall(squawk.rl.train, {scenario = S, policy = "tree"})
check(not ok and tostring(err):find("only \"mlp\" and \"gpt2\" train"), tostring(err))
ok, err = pcall(squawk.rl.train, {scenario = S, estimator = "sgd"})
check(not ok and tostring(err):find("estimator 'sgd'"), tostring(err))
ok, err = pcall(squawk.rl.train, {scenario = S, episodes = 16, save = "/tmp/x.ckpt"})
check(not ok and tostring(err):find("out"), "saving needs --out: " .. tostring(err))

-- squawk.rl.evaluate is the CLI's evaluator (squawk.env.evaluate is the same function).
local e = squawk.rl.evaluate{scenario = S, policy = "zero", episodes = 20, seed = 1}
local f = squawk.env.evaluate{scenario = S, policy = "zero", episodes = 20, seed = 1}
check_eq(e.episodes, 20, "evaluated episodes")
check_eq(e.mean_reward, f.mean_reward, "one evaluator")
check_eq(e.actions["-1"] + e.actions["-0.5"] + e.actions["0.5"] + e.actions["1"], 0, "zero never turns")
check_eq(e.most_frequent_share, 1, "zero plays one action")
