-- What the slowest requests of the offline translator have in common: the utterances build/bench_translate times
-- (../shared/corpora nl2trafscript_dev.tsv and vice_trafscript.tsv, each against its case's setup, translated once
-- first as the bench warms it), counted by a count hook on every Lua instruction (exact, load-independent), split
-- by the function they run in (self, not what it calls; file:line-defined, or file:line with `lines`).
-- Prints the least-squares fit of instructions against the words of a request (fixed + per word) with the mean per
-- band of length; then the SLOW requests (the slowest after the first SKIP, whose words are far out of the rest)
-- against as many around the median, per word: a function whose share per word is well above the median's grows
-- faster than the request's length (work per clause or per retry, a scan of the words per word); the TOP such.
-- usage: squawk run --unsafe bench/translate_tail.lua [SLOW] [TOP] [lines] [SKIP]   (--unsafe: the debug library;
--   SLOW 50, TOP 30, SKIP 1 by default)
local graph = require("translate.graph")
local nodes = require("translate.nodes")
local slow = tonumber(arg and arg[1]) or 50
local top = tonumber(arg and arg[2]) or 30
local by_line = arg and arg[3] == "lines"
local skip = tonumber(arg and arg[4]) or 1
assert(debug and debug.sethook, "run with --unsafe: the count hook needs the debug library")

local getinfo = debug.getinfo
local cur, total = nil, 0
local function count()
  total = total + 1
  local info = getinfo(2, by_line and "Sl" or "S")
  local key = info.short_src:match("[^/]*$") .. ":" .. (by_line and info.currentline or info.linedefined)
  cur[key] = (cur[key] or 0) + 1
end

local reqs = {}  -- {n = instructions, w = words, u = utterance, f = {key = instructions}}
for _, path in ipairs({ "../shared/corpora/nl2trafscript_dev.tsv", "../shared/corpora/vice_trafscript.tsv" }) do
  squawk.translate.evaluate(path, function(c)
    local sim = squawk.sim.new()
    for _, line in ipairs(nodes.split_commands(c.setup)) do sim:exec(line) end
    local opts = { mode = "offline", sim = sim, waypoints = nodes.defined_waypoints(c.setup) }
    graph.translate(c.utterance, opts)
    cur = {}
    local before = total
    debug.sethook(count, "", 1)
    local r = graph.translate(c.utterance, opts)
    debug.sethook()
    reqs[#reqs + 1] = { n = total - before, w = select(2, c.utterance:gsub("%S+", "")), u = c.utterance, f = cur }
    return r
  end)
end
table.sort(reqs, function(a, b) return a.n > b.n end)

-- instructions = fixed + per_word * words, over all but the SKIP longest-running
local sx, sy, sxx, sxy, m = 0, 0, 0, 0, 0
local bands = {}
for k = skip + 1, #reqs do
  local r = reqs[k]
  sx, sy, sxx, sxy, m = sx + r.w, sy + r.n, sxx + r.w * r.w, sxy + r.w * r.n, m + 1
  local b = (r.w - 1) // 4
  bands[b] = bands[b] or { 0, 0 }
  bands[b][1], bands[b][2] = bands[b][1] + 1, bands[b][2] + r.n
end
local per_word = (m * sxy - sx * sy) / (m * sxx - sx * sx)
print(string.format("%d requests: instructions = %.0f + %.0f per word (least squares, the %d slowest left out)", #reqs,
  (sy - per_word * sx) / m, per_word, skip))
for b = 0, 40 do
  if bands[b] then
    print(string.format("  %2d-%2d words: %3d requests, mean %6.0f", 4 * b + 1, 4 * b + 4, bands[b][1], bands[b][2] / bands[b][1]))
  end
end

local function sum(lo, hi)
  local f, words, n = {}, 0, 0
  for i = lo, hi do
    local r = reqs[i]
    words, n = words + r.w, n + r.n
    for k, v in pairs(r.f) do f[k] = (f[k] or 0) + v end
  end
  return f, words, n
end
local sf, sw, sn = sum(skip + 1, skip + slow)
local mid = #reqs // 2
local mf, mw, mn = sum(mid - slow // 2, mid - slow // 2 + slow - 1)
print(string.format("slowest %d: %.1f words, %.0f instructions a request, %.0f per word; median %d: %.1f words, %.0f, %.0f per word",
  slow, sw / slow, sn / slow, sn / sw, slow, mw / slow, mn / slow, mn / mw))
local rows = {}
for k, v in pairs(sf) do rows[#rows + 1] = { k, v / sw, (mf[k] or 0) / mw } end
table.sort(rows, function(a, b) return a[2] - a[3] > b[2] - b[3] end)
print("  per word: slowest  median  (the functions whose share per word grows the most)")
for k = 1, math.min(top, #rows) do
  print(string.format("  %8.1f %7.1f  %s", rows[k][2], rows[k][3], rows[k][1]))
end
