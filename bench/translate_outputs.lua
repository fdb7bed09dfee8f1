-- Every case of the given corpora translated as eval-translate translates it (one VM, the case's setup run on a
-- fresh simulation, offline mode), one line per case written to OUT: id, the commands issued, the commands a yes
-- would run, the question, the note and the error, tab-separated; prints right, asked and wrong per corpus. Two
-- trees' outputs diffed (each tree's build/squawk reads its own scripts/) show whether a change of the Lua changed
-- any translation at all, not only the scores: a speed pass must leave the file byte for byte as it was.
-- usage: squawk run --unsafe --max-instructions 0 bench/translate_outputs.lua OUT CORPUS.tsv [CORPUS.tsv ...]
--   (--unsafe: OUT is written outside the sandbox's out folder)
local graph = require("translate.graph")
local out = assert(io.open(assert(arg[1], "usage: translate_outputs.lua OUT CORPUS.tsv ..."), "w"))
local function flat(t) if type(t) ~= "table" then return "" end return table.concat(t, " ; ") end
for k = 2, #arg do
  local path = arg[k]
  local rep = squawk.translate.evaluate(path, function(c)
    local r = graph.translate(c.utterance, { mode = "offline", setup = c.setup, verify = true })
    out:write(c.id, "\t", flat(r.commands), "\t", r.confirm and flat(r.confirm.commands) or "", "\t",
      tostring(r.ask or ""), "\t", tostring(r.note or ""), "\t", tostring(r.error or ""), "\n")
    return r
  end)
  print(path:match("[^/]*$"), rep.cases, rep.right, rep.asked, rep.wrong)
end
out:close()
