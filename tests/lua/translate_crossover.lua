-- Crossover requests: the first words of one request of tests/data joined to the last words of another,
-- a request with two neighbouring words swapped, and a request begun mid-way (a word of one request, then a
-- few words from the middle of another), through the translation graph offline. Every
-- request, however odd, gets exactly one answer (commands, a question, or a note of what squawk does not
-- simulate) and never raises: no stack overflow, no error in a rule or a handler.
local graph = require("translate.graph")

local sim = squawk.sim.new()
for _, line in ipairs({ "CRE KLM12 A320 52 4 090 FL200 250", "CRE BAW968 A320 52.6 9.0 010 FL180 280",
    "CRE DLH4AX A321 52.4 4.4 090 FL300 280", "DEFWPT HZA 52.3 4.6", "ADDWPT KLM12 HZA" }) do
  check(sim:exec(line), line)
end

-- the requests (third column) of every round in tests/data, split into words
local requests = {}
for r = 1, 200 do
  local f = io.open(string.format("tests/data/translate_round%d.tsv", r))
  if f then
    for line in f:lines() do
      local said = line:match("^[^\t]*\t[^\t]*\t([^\t]*)\t")
      local words = {}
      for w in (said or ""):gmatch("%S+") do words[#words + 1] = w end
      if #words > 1 and line:sub(1, 3) ~= "id\t" then requests[#requests + 1] = words end
    end
    f:close()
  end
end
check(#requests > 1000, "tests/data's rounds read: " .. #requests .. " requests")

-- a linear congruential generator: the same requests on every run
local state = 12345
local function rand(n)
  state = (state * 1103515245 + 12345) % 2147483648
  return state % n + 1
end
local function join(words, b, e, out)
  for k = b, e do out[#out + 1] = words[k] end
  return out
end

local N = 4000
local failed = 0
for _ = 1, N do
  local a, b = requests[rand(#requests)], requests[rand(#requests)]
  local words = join(b, rand(#b), #b, join(a, 1, rand(#a), {}))
  if rand(3) == 1 then
    local s = rand(#b)
    words = join(b, s, math.min(#b, s + rand(5)), { a[rand(#a)] })
  elseif rand(2) == 1 then
    local k = rand(#words - 1)
    words[k], words[k + 1] = words[k + 1], words[k]
  end
  local text = table.concat(words, " ")
  local ok, r = pcall(graph.translate, text, { sim = sim, mode = "offline" })
  local answers = ok and ((r.ask and 1 or 0) + ((r.commands and #r.commands > 0) and 1 or 0)) or 0
  local fine = ok and (answers == 1 or (answers == 0 and r.note ~= nil) or r.error ~= nil)
  if not fine then
    failed = failed + 1
    check(false, text .. " => " .. (ok and "no single answer" or tostring(r)))
  end
end
print(string.format("crossover: %d requests, %d without a single answer", N, failed))
