-- Shared by the bench/translate_*.lua tools: the requests build/bench_translate times, every case of
-- ../shared/corpora nl2trafscript_dev.tsv and vice_trafscript.tsv, each against a fresh simulation built from its
-- case's setup (the corpora must be there; the tools run with --unsafe).
local graph = require("translate.graph")
local nodes = require("translate.nodes")
local M = {}

M.corpora = { "../shared/corpora/nl2trafscript_dev.tsv", "../shared/corpora/vice_trafscript.tsv" }

-- Calls fn(utterance, opts) for each case in corpus order, after one translation of it that warms the graph as the
-- bench does (not for fn to measure); opts are the offline options of the case's simulation. fn's result is the
-- case's translation for squawk.translate.evaluate's scoring.
function M.each(fn)
  for _, path in ipairs(M.corpora) do
    squawk.translate.evaluate(path, function(c)
      local sim = squawk.sim.new()
      for _, line in ipairs(nodes.split_commands(c.setup)) do sim:exec(line) end
      local opts = { mode = "offline", sim = sim, waypoints = nodes.defined_waypoints(c.setup) }
      graph.translate(c.utterance, opts)
      return fn(c.utterance, opts)
    end)
  end
end

return M
