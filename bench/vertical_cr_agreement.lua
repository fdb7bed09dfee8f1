-- How closely a VerticalCREnv-v0 policy flies a scripted teacher on its own flights. Episode k is
-- seed SEED + k on a freshly loaded ENV (as bench/gym_paired.lua plays it; mlp: greedy); at every
-- step the teacher (reset with the episode's seed, so its memory follows the policy's flight) is
-- asked for its action on the same observation, and the policy's action (clipped to [-1, 1]) is
-- flown. Printed: the decisions; the share the policy flies inside BlueSky's "no rate selected"
-- band (|action| < 0.008, flown as the default 7.6 m/s); the share within 0.05 of the teacher; the
-- mean |difference|; and of the decisions where the teacher flies |action| >= 0.3 (an avoidance
-- or the dive), how many the policy flies at the opposite sign or 0.
-- usage: squawk run bench/vertical_cr_agreement.lua POLICY TEACHER ENV.lua [EPISODES [SEED]] [--openap DIR] [--allow-read DIR]
local usage = "usage: squawk run bench/vertical_cr_agreement.lua POLICY TEACHER ENV.lua [EPISODES [SEED]]"
local spec, teacher_file, env_file = assert(arg[1], usage), assert(arg[2], usage), assert(arg[3], usage)
local episodes, seed = tonumber(arg[4] or 200), tonumber(arg[5] or 0)
local DEFAULT_BAND, NEAR, STRONG = 0.008, 0.05, 0.3

local gym = require("gym_load")

local n, band, near, diff, strong, opposite = 0, 0, 0, 0, 0, 0
for k = 0, episodes - 1 do
  local env = gym.load(env_file)
  local policy = gym.policy(spec, env)
  local teacher = gym.load(teacher_file)
  local obs = env:reset(seed + k)
  if policy.reset then policy:reset(seed + k) end
  teacher:reset(seed + k)
  for _ = 1, env.max_episode_steps do
    local a = math.max(-1, math.min(1, policy:act(obs)[1]))
    local ta = teacher:act(obs)[1]
    n, diff = n + 1, diff + math.abs(a - ta)
    if math.abs(a) < DEFAULT_BAND then band = band + 1 end
    if math.abs(a - ta) < NEAR then near = near + 1 end
    if math.abs(ta) >= STRONG then
      strong = strong + 1
      if a * ta <= 0 then opposite = opposite + 1 end
    end
    local o, _, terminated, truncated = env:step({a})
    obs = o
    if terminated or truncated then break end
  end
end
print(string.format("%s against %s, %d episodes from seed %d: %d decisions", spec, teacher_file, episodes, seed, n))
print(string.format("in the default-rate band %.3f; within %.2f of the teacher %.3f; mean |difference| %.3f",
                    band / n, NEAR, near / n, diff / n))
print(string.format("teacher |action| >= %.1f: %d decisions, the policy at the opposite sign or 0 in %d (%.3f)", STRONG,
                    strong, opposite, strong > 0 and opposite / strong or 0))
