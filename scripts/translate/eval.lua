-- Accuracy of the translation graph on a corpus, scored with the corpus rules.
--   squawk run scripts/translate/eval.lua CORPUS.tsv [offline|single|multi] [--failures] [--no-verify]
-- Each case runs on a fresh simulation after its setup. Prints the accuracy
-- overall and for ASK cases, and with --failures every case it got wrong.
-- --no-verify drops the verifier node from the multi-agent graph.
local graph = require("translate.graph")

local path, mode = arg[1], arg[2]
if not path then error("usage: squawk run scripts/translate/eval.lua CORPUS.tsv [offline|single|multi] [--failures]", 0) end
if mode and mode:sub(1, 2) == "--" then mode = nil end
local show_failures, verify = false, true
for _, a in ipairs(arg) do
  show_failures = show_failures or a == "--failures"
  if a == "--no-verify" then verify = false end
end

local cases = squawk.translate.corpus(path)
local correct, asks, asks_right, errors = 0, 0, 0, 0
for _, c in ipairs(cases) do
  local r = graph.translate(c.utterance, { mode = mode, setup = c.setup, verify = verify })
  local produced = r.commands and table.concat(r.commands, " ; ") or ""
  local ok = squawk.translate.score(produced, r.ask ~= nil, c.expected)
  if ok then correct = correct + 1 end
  if c.expected == "ASK" then
    asks = asks + 1
    if ok then asks_right = asks_right + 1 end
  end
  if r.error then errors = errors + 1 end
  if show_failures and not ok then
    print(string.format("%s  %s\n    want %s\n    got  %s%s", c.id, c.utterance, c.expected,
      r.ask and ("ASK " .. r.ask) or produced, r.error and ("\n    error " .. r.error) or ""))
  end
end
print(string.format("cases %d, correct %d, accuracy %.3f; ASK %d/%d; rejected by validation %d (mode %s)",
  #cases, correct, correct / #cases, asks_right, asks, errors, mode or "default"))
