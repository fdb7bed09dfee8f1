-- The grammar is Lua data checked against the command registry: a phrase
-- added at run time translates with no rebuild, and a rule naming an
-- unknown command, argument or intent is an error naming its file:line.
local grammar = require("translate.grammar")
local graph = require("translate.graph")

local sim = squawk.sim.new()
check(sim:exec("CRE KL204 A320 52 4 90 FL250 280"))
local function say(text) return graph.translate(text, { sim = sim, mode = "offline" }) end

-- "stop the film" is not in the shipped grammar: it asks.
check(say("stop the film").ask ~= nil, "unknown phrasing asks")
-- One line adds it (as it would in scripts/translate/rules.lua) ...
grammar.rule { "film", "hold", prev = { 2, "stop" } }
local r = say("stop the film")
check_eq(r.commands and r.commands[1], "HOLD", "the new phrase translates")
-- ... and a new wording for a command with arguments.
check(say("KL204 swing onto 270").ask ~= nil, "a verb it does not know asks")
grammar.rule { "swing", "hdg" }
check_eq(say("KL204 swing onto 270").commands[1], "HDG KL204 270")
-- A new intent for a registry command, with its handler.
grammar.handler("bye", function(g, s)
  local id = g:acid(s, "be deleted")
  if id then g:emit("DEL " .. id) end
end)
grammar.intent "farewell" { cmd = "DEL", args = { "acid" }, handler = "bye", single = true }
grammar.rule { "farewell", "farewell" }
check_eq(say("farewell KL204").commands[1], "DEL KL204")

-- The registry check: unknown command, unknown argument, unknown intent,
-- each an error at the line that named it (this file).
local ok, msg = pcall(function() grammar.intent "warp" { cmd = "WARP", args = { "acid" }, handler = "bye" } end)
check(not ok and msg:find("unknown command 'WARP'", 1, true) ~= nil, msg)
check(msg:find("translate_grammar_extend.lua:%d+") ~= nil, "names file:line: " .. tostring(msg))
ok, msg = pcall(function() grammar.intent "alt2" { cmd = "ALT", args = { "acid", "flavour" }, handler = "altitude" } end)
check(not ok and msg:find("ALT has no argument 'flavour'", 1, true) ~= nil, msg)
check(msg:find("translate_grammar_extend.lua:%d+") ~= nil, "names file:line: " .. tostring(msg))
ok, msg = pcall(function() grammar.rule { "zap", "teleport" } end)
check(not ok and msg:find("unknown intent 'teleport'", 1, true) ~= nil, msg)
ok, msg = pcall(function() grammar.intent "nohandler" { cmd = "HOLD", handler = "nowhere" } end)
check(not ok and msg:find("no handler 'nowhere'", 1, true) ~= nil, msg)
ok, msg = pcall(function() grammar.rule { "zap", "hold", near = { 2, "@no_such_list" } } end)
check(not ok and msg:find("lexicon.no_such_list", 1, true) ~= nil, msg)

-- Every shipped intent names registry commands (checked at load; listed here).
for name, spec in pairs(grammar.intents) do
  for _, c in ipairs(spec.cmds or { spec.cmd }) do
    check(pcall(grammar.check_command, c, {}, 1), name .. " -> " .. c)
  end
end
