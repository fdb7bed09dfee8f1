-- Where the wall time of the offline translation goes, by Lua function: a count hook every STEP Lua instructions
-- (default 10) charges the CPU time since the hook last returned (os.clock) to the function running (self) and to
-- every distinct function on the stack (inclusive), over the utterances bench/translate_instructions.lua reads. The
-- time of a C function (a string pattern, a simulator call) is charged to the Lua function that called it, as the
-- hook fires only in Lua code; the hook's own time is left out. Prints the TOP functions (default 40) by inclusive,
-- then by self time, as file:line-defined with the name Lua knows, in per cent of the time in graph.translate.
-- Sampled and slowed by the hook, so the figures are shares, not latencies (build/bench_translate measures those).
-- usage: squawk run --unsafe bench/translate_wall_profile.lua [TOP] [STEP]   (with SQUAWK_NAVDATA set)
local graph = require("translate.graph")
local top = tonumber(arg and arg[1]) or 40
local step = tonumber(arg and arg[2]) or 10
assert(debug and debug.sethook, "run with --unsafe: the count hook needs the debug library")

local getinfo, clock = debug.getinfo, os.clock
local self_time, inclusive, names = {}, {}, {}
local last = 0.0
local seen = {}
local function sample()
  local dt = clock() - last
  for k in pairs(seen) do seen[k] = nil end
  local level = 2
  while true do
    local info = getinfo(level, "Sn")
    if not info then break end
    local key = info.what == "C" and ("[C] " .. tostring(info.name))
      or (info.short_src:match("[^/]*$") .. ":" .. info.linedefined)
    if not names[key] and info.name then names[key] = info.name end
    if level == 2 then self_time[key] = (self_time[key] or 0) + dt end
    if not seen[key] then
      seen[key] = true
      inclusive[key] = (inclusive[key] or 0) + dt
    end
    level = level + 1
  end
  last = clock()
end

local root = "graph.lua:" .. debug.getinfo(graph.translate, "S").linedefined
require("translate_cases").each(function(utterance, opts)
  last = clock()
  debug.sethook(sample, "", step)
  local r = graph.translate(utterance, opts)
  debug.sethook()
  return r
end)
local total = inclusive[root] or 0

local function report(title, by)
  local rows = {}
  for key, t in pairs(by) do rows[#rows + 1] = { key, t } end
  table.sort(rows, function(a, b) return a[2] > b[2] end)
  print(title)
  for i = 1, math.min(top, #rows) do
    print(string.format("  %5.1f %%  %-28s %s", 100 * rows[i][2] / total, rows[i][1], names[rows[i][1]] or ""))
  end
end
print(string.format("%.3f s charged to graph.translate (the hook's own time left out)", total))
report("inclusive", inclusive)
report("self", self_time)
