-- Lua instructions per request of the offline translation graph, over the utterances
-- build/bench_translate times (../shared/corpora nl2trafscript_dev.tsv and vice_trafscript.tsv,
-- each against its case's setup): a count hook on every instruction, so the figure is exact and
-- holds on a loaded machine, where wall times do not. Each request is translated once first
-- (not counted), as the bench warms it. Prints the mean per request, then the TOP functions by
-- the instructions run in them (not in what they call), as file:line-defined; then the 50th, 99th
-- percentile and largest instructions of one request, and the TAIL requests that run the most (the
-- tail bench_translate's p99 reads), each with its words and instructions per word: a request far above
-- its length's share costs more than linearly in it.
-- usage: squawk run --unsafe bench/translate_instructions.lua [TOP] [TAIL]   (--unsafe: the debug
--   library; the corpora must be in ../shared/corpora; TAIL defaults to 10)
local graph = require("translate.graph")
local top = tonumber(arg and arg[1]) or 25
local tail = tonumber(arg and arg[2]) or 10
assert(debug and debug.sethook, "run with --unsafe: the count hook needs the debug library")

local per_function, total, requests = {}, 0, 0
local per_request = {}  -- {instructions, words, utterance}
local getinfo = debug.getinfo
local function count()
  total = total + 1
  local info = getinfo(2, "S")
  local key = info.short_src:match("[^/]*$") .. ":" .. info.linedefined
  per_function[key] = (per_function[key] or 0) + 1
end

require("translate_cases").each(function(utterance, opts)
  local before = total
  debug.sethook(count, "", 1)
  local r = graph.translate(utterance, opts)
  debug.sethook()
  requests = requests + 1
  per_request[requests] = { total - before, select(2, utterance:gsub("%S+", "")), utterance }
  return r
end)

print(string.format("%d requests, %.0f Lua instructions per request", requests, total / requests))
local rows = {}
for key, n in pairs(per_function) do rows[#rows + 1] = { key, n } end
table.sort(rows, function(a, b) return a[2] > b[2] end)
for k = 1, math.min(top, #rows) do
  print(string.format("%6.2f %%  %7.0f  %s", 100 * rows[k][2] / total, rows[k][2] / requests, rows[k][1]))
end
table.sort(per_request, function(a, b) return a[1] > b[1] end)
local function quantile(q) return per_request[#per_request - math.min(#per_request - 1, math.floor(q * #per_request))][1] end
print(string.format("instructions per request: p50 %d  p99 %d  max %d", quantile(0.5), quantile(0.99), per_request[1][1]))
for k = 1, math.min(tail, #per_request) do
  local p = per_request[k]
  local text = #p[3] > 90 and p[3]:sub(1, 87) .. "..." or p[3]
  print(string.format("%8d  %3d words  %5.0f per word  %s", p[1], p[2], p[1] / math.max(1, p[2]), text))
end
