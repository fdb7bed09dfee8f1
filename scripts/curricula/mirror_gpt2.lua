-- The mirror-symmetric GPT-2's fine-tuning recipe (docs/conflict_resolution.md,
-- "The commands, for seed S"): stages A-C as squawk.rl.train calls, each the
-- `squawk train` command of that stage (same flags, same code: the same seed
-- gives the same numbers).
--
--   squawk run scripts/curricula/mirror_gpt2.lua [SEED] [STAGES] [STOP_A] --out DIR
--     SEED    the run's seed (default 3, the shipped checkpoint's)
--     STAGES  which stages to run, in order (default "ABC"; "B" needs DIR/a.ckpt, "C" DIR/b.ckpt)
--     STOP_A  where stage A ends (default 8192; the schedules still span 20 480 episodes)
-- Writes DIR/a.ckpt, DIR/b.ckpt, DIR/c.ckpt (policy and learner state) and
-- prints every update and evaluation as `squawk train --policy gpt2` does.
local seed = tonumber(arg[1]) or 3
local stages = arg[2] or "ABC"
local stop_a = tonumber(arg[3]) or 8192
local out = squawk.out_dir
assert(out and out ~= "", "mirror_gpt2.lua: give --out DIR for the stages' checkpoints")

local common = {
  scenario = "scenarios/horizontal_cr_substep.lua", policy = "gpt2",
  model = "models/horizontal_cr_gpt2_tiny_pretrained", mirror = true, train_embeddings = true, blocks = 2,
  estimator = "ppo", epochs = 4, episodes_per_update = 32, envs = 32, seed = seed,
  eval_every = 1024, eval_episodes = 100,
}

-- common's keys with `stage`'s on top, and a reporter that prints as the CLI does.
local function recipe(name, stage)
  local t = {}
  for k, v in pairs(common) do t[k] = v end
  for k, v in pairs(stage) do t[k] = v end
  t.on_update = function(u)
    print(string.format("%s update %d: %d episodes, %d decisions, return %.3f, success %.1f %%, entropy %.3f",
                        name, u.update, u.episodes, u.samples, u.mean_return, 100 * u.success_rate, u.entropy))
    if u.eval then
      print(string.format("%s %d episodes: eval success %.1f %%, mean reward %.3f (%d episodes), most frequent action %.1f %%",
                          name, u.episodes, 100 * u.eval.success_rate, u.eval.mean_reward, u.eval.episodes,
                          100 * u.eval.most_frequent_share))
    end
  end
  return t
end

local runs = {
  A = recipe("A", {lr = 3e-4, entropy = 0.05, entropy_final = 0.002, episodes = 20480, stop_at = stop_a,
                   save = out .. "/a.ckpt"}),
  B = recipe("B", {lr = 6e-5, lr_final = 6e-5, entropy = 0.002, entropy_final = 0.002, episodes = 20480,
                   resume = out .. "/a.ckpt", save = out .. "/b.ckpt"}),
  C = recipe("C", {lr = 6e-5, lr_final = 3e-6, entropy = 0.002, entropy_final = 0, episodes = 8192,
                   init = out .. "/b.ckpt", save = out .. "/c.ckpt"}),
}
for name in stages:gmatch(".") do
  local stage = assert(runs[name], "mirror_gpt2.lua: stage '" .. name .. "': expected A, B or C")
  local r = squawk.rl.train(stage)
  print(string.format("stage %s %s: %d episodes, %d updates, %.0f s", name, r.ended, r.episodes, r.updates, r.wall_s))
end
