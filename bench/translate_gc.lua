-- What the Lua collector costs a translation as a person sees it: the CPU time of each request of the corpora
-- build/bench_translate times (../shared/corpora nl2trafscript_dev.tsv and vice_trafscript.tsv, each against its
-- case's setup, translated once first as the bench warms it) under three designs, each over the whole corpus in
-- its own pass, the passes taken in turn (A B C A B C ...) so that a loaded machine weighs on each alike:
--   A  the VM's own generational collector (engine/script/vm.cpp: a minor cycle after each 10 % of growth),
--      running inside the request;
--   B  the collector stopped during the request and one minor step run after the reply is produced;
--   C  stopped during the request, a minor step after the reply only once the heap grew 10 % since the last one.
-- Prints per design: the latency of one request (p50, p99, max over every request of every pass), the step after
-- the reply (B, C: p50, p99, max, and how many), the mean cost per request with the steps (the throughput), and the
-- memory a request allocates (KB, with the collector stopped: p50, p99, max) and the heap at the end. CPU time
-- (os.clock), not wall time: preemption by other work on the machine is not counted.
-- usage: squawk run --unsafe bench/translate_gc.lua [PASSES]   (--unsafe: the corpora in ../shared/corpora; PASSES
--   of each design, default 3)
local graph = require("translate.graph")
local passes = tonumber(arg and arg[1]) or 3
local clock = os.clock

local cases = {}
require("translate_cases").each(function(utterance, opts)
  cases[#cases + 1] = { utterance = utterance, opts = opts }
  return graph.translate(utterance, opts)
end)

local designs = { "A", "B", "C" }
local latency, steps, total, kb = {}, {}, {}, {}
for _, d in ipairs(designs) do latency[d], steps[d], total[d], kb[d] = {}, {}, 0, {} end

local base = collectgarbage("count")  -- (C: the heap after its last step, KB)
local function pass(d)
  for _, c in ipairs(cases) do
    if d == "A" then
      local t0 = clock()
      graph.translate(c.utterance, c.opts)
      local t = clock() - t0
      latency.A[#latency.A + 1], total.A = t, total.A + t
    else
      collectgarbage("stop")
      local k0 = collectgarbage("count")
      local t0 = clock()
      graph.translate(c.utterance, c.opts)
      local t = clock() - t0
      kb[d][#kb[d] + 1] = collectgarbage("count") - k0
      collectgarbage("restart")
      local s = 0
      if d == "B" or collectgarbage("count") > 1.1 * base then
        local s0 = clock()
        collectgarbage("step", 0)
        s = clock() - s0
        steps[d][#steps[d] + 1] = s
        base = collectgarbage("count")
      end
      latency[d][#latency[d] + 1], total[d] = t, total[d] + t + s
    end
  end
end
for _ = 1, passes do
  for _, d in ipairs(designs) do
    if d == "C" then
      collectgarbage("step", 0)
      base = collectgarbage("count")
    end
    pass(d)
  end
end

local function q(t, p)
  if #t == 0 then return 0 end
  local s = table.move(t, 1, #t, 1, {})
  table.sort(s)
  return s[math.min(#s, math.floor(p * #s) + 1)]
end
print(string.format("%d requests x %d passes per design (CPU ms)", #cases, passes))
for _, d in ipairs(designs) do
  local l, s, n = latency[d], steps[d], #latency[d]
  print(string.format("%s  request p50 %.3f  p99 %.3f  max %.3f | step after the reply: %d, p50 %.3f  p99 %.3f  max %.3f"
    .. " | mean with steps %.3f ms/request", d, 1e3 * q(l, 0.5), 1e3 * q(l, 0.99), 1e3 * q(l, 1), #s,
    1e3 * q(s, 0.5), 1e3 * q(s, 0.99), 1e3 * q(s, 1), 1e3 * total[d] / n))
end
print(string.format("KB allocated per request (collector stopped): p50 %.0f  p99 %.0f  max %.0f ; heap at the end %.0f KB",
  q(kb.B, 0.5), q(kb.B, 0.99), q(kb.B, 1), collectgarbage("count")))
