-- Replays recorded episodes through an environment written in Lua and prints
-- what it observes, for bench/gym_ref/compare.py.
--
--   squawk run bench/gym_ref/replay.lua ENV.lua TRACE.txt --allow-read DIR_OF_TRACE
--
-- TRACE.txt: per episode a line `episode K key=value ...` (reset's options:
-- a number, or numbers separated by commas as an array, e.g.
-- draws=3012,-312), then one line
-- `action a1 [a2 ...]` per step. Output, one line per observation:
--   obs K STEP o1 ... on | reward R terminated T truncated U
-- (STEP 0 is the observation reset returns, with reward 0), and last
--   time SECONDS steps N   (CPU time spent in env:step, for env steps/s).
local env_path, trace_path = arg[1], arg[2]
assert(env_path and trace_path, "usage: replay.lua ENV.lua TRACE.txt")
local env = squawk.gym.load(env_path)

local function emit(k, step, obs, reward, terminated, truncated)
  local parts = {}
  for i, v in ipairs(obs) do parts[i] = string.format("%.17g", v) end
  print(string.format("obs %d %d %s | reward %.17g terminated %s truncated %s", k, step,
                      table.concat(parts, " "), reward, tostring(terminated), tostring(truncated)))
end

local k, step = nil, 0
local step_s, nsteps = 0, 0  -- CPU seconds inside env:step, and the steps
for line in io.lines(trace_path) do
  local head, rest = line:match("^(%S+)%s*(.*)$")
  if head == "episode" then
    local opts = {}
    local id, kv = rest:match("^(%S+)%s*(.*)$")
    for key, v in kv:gmatch("(%w[%w_]*)=(%S+)") do
      if v:find(",") then
        local list = {}
        for x in v:gmatch("[^,]+") do list[#list + 1] = tonumber(x) end
        opts[key] = list
      else
        opts[key] = tonumber(v)
      end
    end
    k, step = tonumber(id), 0
    emit(k, 0, (env:reset(k, opts)), 0, false, false)
  elseif head == "action" then
    local a = {}
    for v in rest:gmatch("%S+") do a[#a + 1] = tonumber(v) end
    step = step + 1
    local t0 = os.clock()
    local obs, reward, terminated, truncated = env:step(a)
    step_s, nsteps = step_s + os.clock() - t0, nsteps + 1
    emit(k, step, obs, reward, terminated, truncated)
  end
end
print(string.format("time %.17g steps %d", step_s, nsteps))
