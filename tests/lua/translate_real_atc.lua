-- Real controller transcripts (../shared/corpora/atc_real_utterances.tsv,
-- labelled with command types, no expected TrafScript): the offline grammar
-- never issues a command of a type the label does not list. A label of what
-- squawk does not simulate (CONTACT, SQUAWK, APPROACH, QNH, IDENT) allows no
-- command of its own. Skips when ../shared is absent.
local grammar = require("translate.grammar")
local nodes = require("translate.nodes")

local PATH = "../shared/corpora/atc_real_utterances.tsv"
-- label -> the registry commands it allows
local ALLOWS = {
  ALT = { "ALT" }, VS = { "VS", "ALT" }, HDG = { "HDG" }, HDG_REL = { "HDG" }, HDG_PRESENT = { "HDG" },
  SPD = { "SPD" }, SPD_REL = { "SPD" }, MACH = { "SPD" }, SPD_CANCEL = { "SPD" },
  DIRECT = { "DIRECT", "ADDWPT", "LNAV" }, ROUTE = { "DIRECT", "ADDWPT", "LNAV" }, QUERY = { "POS" },
  REPORT = { "POS" },
}

local ok, text = pcall(function()
  local f = assert(io.open(PATH, "r"))
  local t = f:read("a")
  f:close()
  return t
end)
if not ok or not text then
  print("skipped: " .. PATH .. " is absent or not readable (the shared corpora live beside the repository)")
  return
end

local n, issued, outside = 0, 0, {}
for line in text:gmatch("[^\n]+") do
  local id, utterance, _, _, _, labels = line:match("^([^\t]*)\t([^\t]*)\t([^\t]*)\t([^\t]*)\t([^\t]*)\t([^\t]*)$")
  if id and id ~= "id" then
    n = n + 1
    local allowed = {}
    for label in labels:gmatch("[^;]+") do
      for _, c in ipairs(ALLOWS[label] or {}) do allowed[c] = true end
    end
    local r = grammar.translate(utterance, { aircraft = {}, waypoints = {} })
    for _, cmd in ipairs(r.commands or {}) do
      issued = issued + 1
      -- a conditional's own command and the command it runs both count
      for word in cmd:gmatch("%S+") do
        local name = nodes.canonical_name(word)
        if name and name ~= "ATALT" and name ~= "ATSPD" and name ~= "ATDIST" and not allowed[name] then
          outside[#outside + 1] = string.format("%s [%s]: %s -> %s", id, labels, utterance, cmd)
          break
        end
      end
    end
  end
end
print(string.format("%s: %d utterances, %d commands issued, %d of a type the label does not list", PATH, n, issued,
  #outside))
for _, o in ipairs(outside) do print("  " .. o) end
check(n >= 200, "the corpus has its 210 utterances, read " .. n)
check_eq(#outside, 0, "commands of a type the label does not list")
