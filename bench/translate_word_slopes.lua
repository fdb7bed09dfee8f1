-- Where the cost per word of the offline translation goes: a count hook sampling every STEP Lua instructions
-- (default 7) over the utterances bench/translate_instructions.lua reads; each sample is charged to the function
-- running (self) and to every distinct function on the stack (inclusive), per request; then for each function a
-- least-squares fit of its instructions per request against the request's words (instructions = a + slope x
-- words). Prints the TOP functions (default 20) by inclusive slope, then by self slope, as file:line-defined
-- with the function's name where Lua knows it. Sampled, so each figure is an estimate; and the figures are
-- relative: at 7 the hook fires about 1.7 times as often as every 7th instruction (57 174 "instructions" per
-- request against translate_instructions.lua's exact 33 751 on main f043f4f7), so scale them by the exact mean
-- over the mean printed here.
-- usage: squawk run --unsafe bench/translate_word_slopes.lua [TOP] [STEP]   (with SQUAWK_NAVDATA set)
local graph = require("translate.graph")
local top = tonumber(arg and arg[1]) or 20
local step = tonumber(arg and arg[2]) or 7
assert(debug and debug.sethook, "run with --unsafe: the count hook needs the debug library")

local getinfo = debug.getinfo
local names = {}             -- key -> a name Lua gave the function
local incl, self_ = {}, {}   -- key -> {request index -> samples}
local request = 0
local seen = {}
local function sample()
  local level = 2
  local first = true
  for k in pairs(seen) do seen[k] = nil end
  while true do
    local info = getinfo(level, "Sn")
    if not info then break end
    if info.what == "Lua" then
      local key = info.short_src:match("[^/]*$") .. ":" .. info.linedefined
      if not names[key] and info.name then names[key] = info.name end
      if first then
        local t = self_[key] or {}
        self_[key] = t
        t[request] = (t[request] or 0) + 1
        first = false
      end
      if not seen[key] then
        seen[key] = true
        local t = incl[key] or {}
        incl[key] = t
        t[request] = (t[request] or 0) + 1
      end
    end
    level = level + 1
  end
end

local words = {}
require("translate_cases").each(function(utterance, opts)
  request = request + 1
  words[request] = select(2, utterance:gsub("%S+", ""))
  debug.sethook(sample, "", step)
  local r = graph.translate(utterance, opts)
  debug.sethook()
  return r
end)

-- the fit over the requests of at most 60 words (the one request of 219 words, a stutter, would lead the fit)
local n, sx, sxx = 0, 0, 0
for r = 1, request do
  if words[r] <= 60 then n, sx, sxx = n + 1, sx + words[r], sxx + words[r] * words[r] end
end
local function fit(t)
  local sy, sxy = 0, 0
  for r = 1, request do
    if words[r] <= 60 then
      local y = (t[r] or 0) * step
      sy, sxy = sy + y, sxy + words[r] * y
    end
  end
  local slope = (n * sxy - sx * sy) / (n * sxx - sx * sx)
  return slope, (sy - slope * sx) / n, sy / n
end
local function report(title, by)
  local rows = {}
  for key, t in pairs(by) do
    local slope, a, mean = fit(t)
    rows[#rows + 1] = { key, slope, a, mean }
  end
  table.sort(rows, function(x, y) return x[2] > y[2] end)
  print(title)
  print("  slope/word  intercept  mean/request  function")
  for k = 1, math.min(top, #rows) do
    local r = rows[k]
    print(string.format("  %9.1f  %9.0f  %12.0f  %s %s", r[2], r[3], r[4], r[1], names[r[1]] or ""))
  end
end
local all = {}
for r = 1, request do all[r] = 0 end
for _, t in pairs(self_) do for r, v in pairs(t) do all[r] = all[r] + v end end
local slope, a, mean = fit(all)
print(string.format("%d requests (%d of at most 60 words fitted), sampled every %d instructions", request, n, step))
print(string.format("all: %.0f + %.0f per word (mean %.0f per request)", a, slope, mean))
report("inclusive (the function and what it calls):", incl)
report("self (the function's own instructions):", self_)
