-- The nodes of the translation graph (see translate/graph.lua for the graph).
--
-- Each node is node(state, ctx) -> edge label. `state` holds the request and
-- what the nodes found: docs (retrieved), cmd (selected command), candidate
-- (the TrafScript line to try), feedback {previous, error}, retries, source
-- ("llm" or "offline"), and at the end commands or ask, and error. `ctx`
-- holds the collaborators: llm (or nil), sim (never changed), index, prompts,
-- k, max_retries. Every node records what it did with say().
local grammar = require("translate.grammar")
local schema = require("translate.schema")
local lexicon = require("translate.lexicon")
local typos = require("translate.typos")
local types = require("translate.types")

local M = {}

function M.say(state, node, text)
  state.trace[#state.trace + 1] = { node = node, said = text }
end

-- ${name} placeholders replaced literally from `vars` (missing: empty).
function M.render(template, vars)
  return (template:gsub("%${([%w_]+)}", function(k)
    local v = vars[k]
    return v == nil and "" or tostring(v)
  end))
end

-- The text inside the last \boxed{...} (braces balanced), trimmed; nil if none.
function M.boxed(reply)
  local start, pos = nil, 1
  while true do
    local s, e = reply:find("\\boxed{", pos, true)
    if not s then break end
    start, pos = e + 1, e + 1
  end
  if not start then return nil end
  local depth, i = 1, start
  while i <= #reply do
    local c = reply:sub(i, i)
    if c == "{" then depth = depth + 1 elseif c == "}" then depth = depth - 1 end
    if depth == 0 then break end
    i = i + 1
  end
  return (reply:sub(start, i - 1):gsub("^%s+", ""):gsub("%s+$", ""))
end

local function trim(s) return (s:gsub("^%s+", ""):gsub("%s+$", "")) end

-- "CMD a ; CMD b" -> {"CMD a", "CMD b"} (empty parts dropped).
function M.split_commands(line)
  local out = {}
  for part in (line .. ";"):gmatch("([^;]*);") do
    part = trim(part)
    if part ~= "" then out[#out + 1] = part end
  end
  return out
end

-- Known command names and aliases -> canonical name, from the registry.
local canonical
local function canonical_name(word)
  if not canonical then
    canonical = {}
    for _, c in ipairs(squawk.sim.commands()) do
      canonical[c.name:upper()] = c.name
      for _, a in ipairs(c.aliases or {}) do canonical[a:upper()] = c.name end
    end
  end
  return canonical[(word or ""):upper()]
end
M.canonical_name = canonical_name

-- Registry name -> the command's usage line, from the registry (read once: a call of squawk.sim.commands()
-- builds every command's table, some 40 us); a name the registry lacks is its own usage.
local usages
local function usage_of(name)
  if not usages then
    usages = {}
    for _, c in ipairs(squawk.sim.commands()) do usages[c.name] = c.usage end
  end
  return usages[name] or name
end
M.usage_of = usage_of

-- One line per aircraft: what the LLM needs to fill relative values.
function M.state_lines(sim)
  local lines = {}
  for _, a in ipairs(sim:aircraft()) do
    lines[#lines + 1] = string.format("%s %s at %.4f %.4f, heading %.0f, altitude %.0f ft, CAS %.0f kt",
      a.id, a.type or "?", a.lat, a.lon, a.hdg_deg, a.alt_ft, a.cas_kt)
  end
  return table.concat(lines, "\n")
end

local function content(state)
  local blocks = {}
  for _, d in ipairs(state.docs or {}) do blocks[#blocks + 1] = d.text end
  return table.concat(blocks, "\n\n")
end

-- The selected command's document (retrieved, or looked up by name).
local function command_context(state, ctx)
  for _, d in ipairs(state.docs or {}) do
    if d.command == state.cmd then return d.text end
  end
  for _, d in ipairs(ctx.index:search(state.cmd, ctx.k)) do
    if d.command == state.cmd then return d.text end
  end
  return usage_of(state.cmd)
end

-- Asks the LLM (with a registry JSON schema when `shape` is given); returns
-- the reply, or nil after recording the failure.
local function ask_llm(state, ctx, node, prompt, shape)
  local reply, info = ctx.llm:chat(prompt, { on_token = ctx.on_token, schema = shape })
  if not reply then
    M.say(state, node, "LLM failed, falling back to the offline translator: " .. tostring(info))
    return nil
  end
  M.say(state, node, "LLM replied: " .. reply)
  return reply
end

local function with_feedback(prompt, state, ctx)
  if not state.feedback then return prompt end
  return prompt .. M.render(ctx.prompts.feedback, state.feedback)
end

-- Reads a candidate line (or a question) out of an LLM reply: the schema's
-- JSON shape, else \boxed{...} or the first line.
local function take_candidate(state, reply)
  local json_line, json_ask = schema.read(reply)
  if json_ask then
    state.ask = json_ask
    return "ask"
  end
  if json_line then
    state.candidate, state.source = json_line, "llm"
    return "ok"
  end
  local line = M.boxed(reply) or trim(reply:match("[^\n]+") or "")
  if line:upper():sub(1, 3) == "ASK" then
    local q = trim(line:sub(4))
    state.ask = q ~= "" and q or "Some required information is missing: could you give the missing values?"
    return "ask"
  end
  state.candidate, state.source = line, "llm"
  return "ok"
end

function M.retrieve(state, ctx)
  state.docs = ctx.index:search(state.request, ctx.k)
  local names = {}
  for _, d in ipairs(state.docs) do names[#names + 1] = string.format("%s %.2f", d.command, d.score) end
  M.say(state, "retrieve", "top " .. ctx.k .. ": " .. (#names > 0 and table.concat(names, ", ") or "nothing"))
  return "next"
end

function M.select(state, ctx)
  local reply = ask_llm(state, ctx, "select",
    M.render(ctx.prompts.selector, { content = content(state), request = state.request }))
  if not reply then return "llm_failed" end
  local word = (M.boxed(reply) or reply):match("[%a][%w]*")
  local name = canonical_name(word)
  if not name then
    name = state.docs[1] and state.docs[1].command
    if not name then
      M.say(state, "select", "no known command in the reply and nothing retrieved")
      return "llm_failed"
    end
    M.say(state, "select", string.format("'%s' is not a command; taking the best retrieved, %s", tostring(word), name))
  end
  state.cmd = name
  M.say(state, "select", "command " .. name)
  return "ok"
end

function M.verify(state, ctx)
  local reply = ask_llm(state, ctx, "verify", M.render(ctx.prompts.verifier,
    { cmd = state.cmd, context = command_context(state, ctx), request = state.request }))
  if not reply then return "llm_failed" end
  local up = reply:upper()
  local yes, no = up:find("%f[%a]YES%f[%A]"), up:find("%f[%a]NO%f[%A]")
  if no and (not yes or no < yes) then return "no" end
  if not yes then M.say(state, "verify", "neither YES nor NO; going on as if YES") end
  return "yes"
end

function M.ask(state, ctx)
  state.ask = M.render(ctx.prompts.ask, { cmd = state.cmd, usage = usage_of(state.cmd) })
  M.say(state, "ask", state.ask)
  return "done"
end

-- What the offline grammar makes of the request, offered to the LLM nodes.
local function grammar_reading(state, ctx)
  if not state.reading then
    local world = M.world(ctx.sim, ctx.waypoints)
    local tr = grammar.translate(state.request, world)
    state.reading = tr.ask and ("a question: " .. tr.ask) or table.concat(tr.commands, " ; ")
  end
  return M.render(ctx.prompts.grammar or "", { reading = state.reading })
end

function M.fill(state, ctx)
  local prompt = M.render(ctx.prompts.state, { state = M.state_lines(ctx.sim) })
    .. M.render(ctx.prompts.parameters,
      { cmd = state.cmd, context = command_context(state, ctx), request = state.request })
    .. grammar_reading(state, ctx)
  local reply = ask_llm(state, ctx, "fill", with_feedback(prompt, state, ctx), schema.for_commands({ state.cmd }))
  if not reply then return "llm_failed" end
  local label = take_candidate(state, reply)
  M.say(state, "fill", label == "ask" and ("asks: " .. state.ask) or ("candidate: " .. state.candidate))
  return label
end

function M.single(state, ctx)
  local prompt = M.render(ctx.prompts.single,
    { content = content(state), state = M.state_lines(ctx.sim), request = state.request })
    .. grammar_reading(state, ctx)
  local reply = ask_llm(state, ctx, "single", with_feedback(prompt, state, ctx), schema.for_commands())
  if not reply then return "llm_failed" end
  local label = take_candidate(state, reply)
  M.say(state, "single", label == "ask" and ("asks: " .. state.ask) or ("candidate: " .. state.candidate))
  return label
end

-- Names defined by DEFWPT commands in a TrafScript line.
function M.defined_waypoints(line)
  local names = {}
  for _, c in ipairs(M.split_commands(line)) do
    local cmd, name = c:match("^(%S+)[%s,]+([^%s,]+)")
    if cmd and cmd:upper() == "DEFWPT" then names[#names + 1] = name end
  end
  return names
end

-- lookup(name, lat, lon, nm, types) read once per world (per request: the navdata does not change while it
-- is read) and arguments; each call gets fresh copies of the one or two lists it returned.
local function remembered(lookup)
  local seen = {}  -- seen[name]: the calls made with that name, {lat =, lon =, nm =, types =, lists}
  local function copy(list) return list and table.move(list, 1, #list, 1, {}) end
  return function(name, lat, lon, nm, types)
    local calls = seen[name]
    if not calls then
      calls = {}
      seen[name] = calls
    end
    local hit
    for _, c in ipairs(calls) do
      if c.lat == lat and c.lon == lon and c.nm == nm and c.types == types then hit = c break end
    end
    if not hit then
      hit = { lat = lat, lon = lon, nm = nm, types = types }
      hit[1], hit[2] = lookup(name, lat, lon, nm, types)
      calls[#calls + 1] = hit
    end
    return copy(hit[1]), copy(hit[2])
  end
end

-- What the offline grammar may know of the simulation: the aircraft
-- (sim:aircraft() tables, the route as waypoint names), the user waypoints,
-- the clock's run state ("hold", "op" or "ff": sim:run_state()), and the
-- navdata's airports by name and by three-letter code.
function M.world(sim, waypoints)
  local aircraft = sim:aircraft()
  for _, a in ipairs(aircraft) do
    local names = {}
    for _, w in ipairs(a.route or {}) do names[#names + 1] = w.name end
    a.route = names
  end
  return { aircraft = aircraft, waypoints = waypoints or {}, run_state = (sim:run_state()),
           airports_named = remembered(function(name, lat, lon, nm) return sim:airports_named(name, lat, lon, nm) end),
           airports_of_city = function(name, lat, lon, nm) return sim:airports_of_city(name, lat, lon, nm) end,
           airports_with_words = function(words, lat, lon, nm) return sim:airports_with_words(words, lat, lon, nm) end,
           navaids_with_words = function(words, lat, lon, nm) return (sim:navaids_with_words(words, lat, lon, nm)) end,
           airports_beside_navaids = function(name, lat, lon, nm)
             return sim:airports_beside_navaids(name, lat, lon, nm)
           end,
           airport_class = function(id) return sim:airport_class(id) end,
           navaids_named = remembered(function(name, lat, lon, nm, types)
             return sim:navaids_named(name, lat, lon, nm, types)
           end),
           airports_coded = function(code, lat, lon) return sim:airports_coded(code, lat, lon) end,
           airports_beside = function(id, lat, lon, nm) return sim:airports_beside(id, lat, lon, nm) end,
           waypoints_at = function(lat, lon) return sim:waypoints_at(lat, lon) end,
           -- the position (lat, lon) of the fix, navaid or airport of that ident the navdata (or a DEFWPT)
           -- holds, where no aircraft bears it and it is no navaid's or airport's name ("dover": the DVR
           -- VOR, not the fix DOVER), else nil (POS reads it and changes nothing)
           place_known = function(name)
             local lat, lon = sim:locate(name)
             if not lat or sim:get(name) or #sim:navaids_named(name, 0, 0, 1e5) > 0
                 or #sim:airports_named(name) > 0 then
               return nil
             end
             return lat, lon
           end,
           -- the conflict resolution method set now ("OFF", "MVP"), read by RESO with no argument on a copy
           -- (the simulation is left as it was), or nil when it cannot be read
           reso_method = function()
             local ok, said = sim:copy():exec("RESO")
             return ok and type(said) == "string" and said:match("^RESO%s+(%u+)") or nil
           end,
           -- the conflict detection method set now ("OFF", "STATEBASED"), read by ASAS with no argument on a copy,
           -- or nil when it cannot be read
           detection = function()
             local ok, said = sim:copy():exec("ASAS")
             return ok and type(said) == "string" and said:match("^CDMETHOD%s+(%u+)") or nil
           end,
           -- a setting's value now, in its command's unit (DTLOOK s, ZONER NM, ZONEDH ft, DTMULT), read on a copy
           -- (the simulation is left as it was), or nil when it cannot be read
           setting = function(cmd)
             if cmd == "DTMULT" then return sim:dtmult() end
             local ok, said = sim:copy():exec(cmd)
             return ok and type(said) == "string" and tonumber(said:match("^%S+%s+(%d+%.?%d*)")) or nil
           end,
           -- a user waypoint's position (as a position argument resolves it now): lat, lon or nil
           user_waypoint_at = function(name) return sim:locate(name) end,
           -- where position argument `text` resolves (sim:locate) when the commands of `prior` (a
           -- TrafScript line, may be nil) have run first, or from lat, lon when given: lat, lon, or nil
           -- when it does not resolve or `prior` fails; the simulation is left as it was
           locate = function(text, prior, lat, lon)
             local s = sim
             if prior and prior ~= "" then
               s = sim:copy()
               if not s:exec(prior) then return nil end
             end
             local plat, plon = s:locate(text, lat, lon)
             return plat, plon
           end }
end

function M.offline(state, ctx)
  local world = M.world(ctx.sim, ctx.waypoints)
  world.confirmed, world.ignored = ctx.confirmed, ctx.ignored
  local tr = grammar.translate(state.request, world)
  if tr.ask then
    state.ask, state.confirm, state.ignorable = tr.ask, tr.confirm, tr.ignorable
    M.say(state, "offline", "asks: " .. tr.ask)
    return "ask"
  end
  state.note, state.confirm_first = tr.note, tr.confirm_first
  if tr.note then M.say(state, "offline", "not simulated: " .. tr.note) end
  if tr.note and #tr.commands == 0 then
    state.commands = {}
    return "note"
  end
  state.candidate, state.source = table.concat(tr.commands, " ; "), "offline"
  M.say(state, "offline", "candidate: " .. (state.candidate ~= "" and state.candidate or "(nothing)"))
  return "ok"
end

-- A request that is already TrafScript ("FF 60", "HOLD", "hdg kl204 270";
-- several joined by ';'): every part names a registry command (first word,
-- or second after a callsign) and the registry's parser accepts it on a
-- scratch copy. It runs as typed; anything else is English.
-- Words of English glue that no TrafScript argument is (a command with a
-- free-text argument would take "open the scenario demo.scn" as typed).
local GLUE = { the = true, a = true, an = true, to = true, of = true, from = true, ["and"] = true, ["then"] = true,
  ["for"] = true, with = true, by = true, into = true, please = true, file = true, scenario = true,
  aircraft = true, plane = true, flight = true, this = true, that = true, all = true, now = true,
  -- (prepositions no argument is: "create KLM1234 at SPY" is English, not CRE of a type "AT";
  -- "at" stays the AT command's own name, has_english_word)
  at = true, over = true, near = true, via = true, towards = true, toward = true }

local keywords
local function keyword_set()
  if not keywords then
    keywords = {}
    for _, w in ipairs(lexicon.keywords) do keywords[w] = true end
  end
  return keywords
end

-- A registry command's name typed with one slip of the fingers, first in a line whose other words are that
-- command's arguments ("atl ezy45hm fl120": ALT; "crete ein7ts a320 53.5 6.0 180 fl300 270": CREATE, CRE): the
-- line with that name, when exactly one registry name or alias of three letters or more lies one edit from the
-- word (a letter left out, added, changed for its neighbour on the keyboard, or two neighbours swapped; the first
-- letter kept, or the first two swapped) and the line with its command parses on `scratch` (a simulation, or a
-- function giving one, called only when a word is looked up there); else nil. A word of English glue, of the
-- grammar's keywords or of the lexicon ("trial" is no TRAIL), or an aircraft's id, is no slip.
local command_names, command_lead
-- True when lower-case letters x and y are neighbours on a QWERTY keyboard (same row or the rows above and below).
local KEY_ROWS = { "qwertyuiop", "asdfghjkl", "zxcvbnm" }
function M.keys_beside(x, y)
  local function at(ch)
    for r, row in ipairs(KEY_ROWS) do
      local c = row:find(ch, 1, true)
      if c then return r, c end
    end
  end
  local rx, cx = at(x)
  local ry, cy = at(y)
  if not rx or not ry then return false end
  return math.abs(rx - ry) <= 1 and math.abs((cx + rx * 0.5) - (cy + ry * 0.5)) <= 1
end
function M.command_slip(c, scratch)
  local word, args = c:match("^%s*([%a]+)([%s,].*)$")
  local lw = word and word:lower()
  if not lw or #lw < 3 or canonical_name(lw) or GLUE[lw] or keyword_set()[lw] or typos.lexicon_word(lw) then
    return nil
  end
  if type(scratch) == "function" then scratch = scratch() end
  if scratch:get(word) then
    return nil
  end
  if not command_names then
    command_names = {}
    for _, cmd in ipairs(squawk.sim.commands()) do
      if #cmd.name >= 3 then command_names[#command_names + 1] = cmd.name:lower() end
      for _, a in ipairs(cmd.aliases or {}) do
        if #a >= 3 and a:match("^%a+$") then command_names[#command_names + 1] = a:lower() end
      end
    end
    -- (the names' positions in command_names by their first letter, and by their first two letters: the only
    -- names a word can be one slip from, its first letter kept or its first two swapped)
    command_lead = { first = {}, two = {} }
    for k, n in ipairs(command_names) do
      for key, by in pairs({ [n:sub(1, 1)] = command_lead.first, [n:sub(1, 2)] = command_lead.two }) do
        by[key] = by[key] or {}
        by[key][#by[key] + 1] = k
      end
    end
  end
  local function one_edit(a, b)  -- a typed, b a name: one edit apart (Damerau), a ~= b
    if math.abs(#a - #b) > 1 then return false end
    local i = 1
    while i <= #a and i <= #b and a:sub(i, i) == b:sub(i, i) do i = i + 1 end
    if #a == #b then
      -- (a letter changed only for its neighbour on the keyboard: "ZONEDZ" is no slip of ZONEDH)
      return (a:sub(i + 1) == b:sub(i + 1) and M.keys_beside(a:sub(i, i), b:sub(i, i)))
        or (a:sub(i, i) == b:sub(i + 1, i + 1) and a:sub(i + 1, i + 1) == b:sub(i, i) and a:sub(i + 2) == b:sub(i + 2))
    end
    return #a > #b and a:sub(i + 1) == b:sub(i) or #a < #b and a:sub(i) == b:sub(i + 1)
  end
  local found
  -- (the names that keep the word's first letter or swap its first two, in command_names' order)
  local kept, swapped = command_lead.first[lw:sub(1, 1)] or {}, command_lead.two[lw:sub(2, 2) .. lw:sub(1, 1)] or {}
  local i, j = 1, 1
  while kept[i] or swapped[j] do
    local k
    if swapped[j] == nil or (kept[i] and kept[i] <= swapped[j]) then
      k = kept[i]
      if swapped[j] == k then j = j + 1 end
      i = i + 1
    else
      k = swapped[j]
      j = j + 1
    end
    local n = command_names[k]
    local name = #n - #lw <= 1 and #lw - #n <= 1 and one_edit(lw, n) and canonical_name(n)
    -- (a command of free text parses whatever follows: "eco mode on" is no ECHO)
    if name and M.free_text(name) then return nil end
    if name and name ~= found then
      if found or not scratch:check(name .. args) then
        if found and scratch:check(name .. args) then return nil end
      else
        found = name
      end
    end
  end
  return found and found .. args or nil
end

-- A conditional's command typed without the aircraft ("atalt ana257 fl080
-- spd 210", "BAW8CK at SUGOL do ALT FL200") gets the condition's aircraft
-- ("... SPD ANA257 210", "... DO ALT BAW8CK FL200", as the registry's AT
-- would run it) when only that makes it parse; otherwise the line c
-- unchanged (a carried command that parses neither way is then asked about
-- in M.typed), less a link word ("then", "and") said before a carried
-- command that parses. AT's DO (or STACK) is written in capitals. name: c's
-- registry name.
local NESTED_AT = { ATALT = 4, ATSPD = 4, ATDIST = 5, AT = 5 }
local LINKED = { ["then"] = true, ["and"] = true }
function M.complete_nested(c, name, scratch)
  local k = NESTED_AT[name]
  if not k then return c end
  local w = {}
  for x in c:gmatch("[^%s,]+") do w[#w + 1] = x end
  if name == "AT" then
    local stored = w[4] and w[4]:upper()
    if stored ~= "DO" and stored ~= "STACK" then return c end
    w[4] = stored
    c = table.concat(w, " ")
  end
  if name == "ATDIST" and tonumber(w[3]) then k = 6 end  -- a lat/lon position: two words
  -- ("atdist dlh4 norku 15 then spd 240": a link word before the carried command is English glue, left out when
  -- the command after it parses)
  local linked = w[k] and LINKED[w[k]:lower()] and table.remove(w, k)
  if #w < k or not canonical_name(w[k]) then return c end
  local nested = table.concat(w, " ", k)
  local with_acid = w[k] .. " " .. w[2] .. (#w > k and " " .. table.concat(w, " ", k + 1) or "")
  if scratch:check(nested) then return linked and table.concat(w, " ") or c end
  if not scratch:check(with_acid) then return c end
  return table.concat(w, " ", 1, k - 1) .. " " .. with_acid
end

-- The command a condition command carries as its last argument ("ATALT KL204 FL080 SPD KL204
-- 210" -> "SPD KL204 210") and the position of its first word in the line, or nil when the
-- command's usage ends in no command.
local function carried_command(name, line)
  local args = {}
  for w in ((usage_of(name) or ""):match("^%S+%s+(.*)$") or ""):gmatch("[^,]+") do args[#args + 1] = w end
  if args[#args] ~= "command" then return nil end
  local words = {}
  for w in line:gmatch("[^%s,]+") do words[#words + 1] = w end
  return table.concat(words, " ", #args + 1), #args + 1
end

-- Numbers said in words: no TrafScript argument is one ("create Pegasus nine delta lima" is a callsign spelled,
-- not CRE of type NINE at a place DELTA).
local SPOKEN_NUMBERS = {}
for w in ("zero one two three four five six seven eight nine niner tree fower fife ten eleven twelve thirteen "
    .. "fourteen fifteen sixteen seventeen eighteen nineteen twenty thirty forty fifty sixty seventy eighty ninety "
    .. "hundred thousand"):gmatch("%a+") do
  SPOKEN_NUMBERS[w] = true
end

-- True when an argument of the command `name` typed in `line` is an English word of the grammar.
local ECHO_PLACES = { console = true, log = true, screen = true, display = true }
local function has_english_word(line, name)
  -- ("echo test start please": a courtesy word closing ECHO's text is said to us, not printed: English)
  local last = name == "ECHO" and line:lower():match("%s(%a+)[%s%.!]*$")
  if last == "please" or last == "pls" or last == "thanks" then return true end
  -- ("Echo the text Phase two starts to the console.", "echo 'F1 done' to the log", "echo hello world on the screen":
  -- where the words go, said after them, is English)
  local into = name == "ECHO" and line:lower():match("%s(%a+)%s+the%s+%a+[%s%.!]*$")
  if (into == "to" or into == "on" or into == "in") and ECHO_PLACES[last] then return true end
  -- ("echo a message on screen: welcome students": the words before a colon name where the text after it goes)
  for w in (name == "ECHO" and line:lower():match("^%s*%a+%s+([%a%s]+):") or ""):gmatch("%a+") do
    if ECHO_PLACES[w] or w == "message" or w == "note" or w == "text" then return true end
  end
  -- ("rpz +2", "dtlook +60": a value typed with a plus is a change from the value now, read by the grammar)
  if name ~= "ECHO" and line:find("%s%+%d") then return true end
  local n = 0
  local all = {}
  for w in line:gmatch("[^%s,]+") do all[#all + 1] = w:lower() end
  for w in line:gmatch("[^%s,]+") do
    n = n + 1
    local lw = w:lower()
    -- a number said in words, or a letter of the spelling alphabet beside another or beside a number in words,
    -- as an argument: a callsign or a value spelled out ("create Pegasus nine delta lima"), English
    local spelled = function(x) return x and (SPOKEN_NUMBERS[x] or lexicon.phonetic[x]) end
    if n > 1 and name ~= "ECHO" and (SPOKEN_NUMBERS[lw]
        or (lexicon.phonetic[lw] and (spelled(all[n - 1]) and n > 2 or spelled(all[n + 1])))) then
      return true
    end
    local turn_word = name == "HDG" and n == 4 and (lw == "left" or lw == "right")
    -- ("WZZ1234 speed +20": a change said with its sign, which SPD / ALT / HDG would read as a value)
    if n > 1 and lw:match("^%+%d") and (name == "SPD" or name == "ALT" or name == "HDG") then return true end
    -- ("klm12 move up", "move klm12 down": "up" or "down" typed in lower case where MOVE's position stands is a
    -- climb or descent, not the NDB of that ident; "MOVE KLM12 UP" in capitals stays TrafScript)
    if name == "MOVE" and n == 3 and (w == "up" or w == "down") then return true end
    local own_name = lw:upper() == name
    -- a field word typed short ("cre KL204 b738 lfpo hdg 060": "hdg" for heading) is English too
    local short = #lw > 1 and lexicon.shorthand[lw]
    if name ~= "ECHO" and ((GLUE[lw] and not own_name) or (n > 1 and not turn_word
        and (keyword_set()[lw] or lexicon.compass[lw] or (short and keyword_set()[short])))) then
      return true
    end
  end
  return false
end

-- True when registry command `name` takes an argument of free text ("string": ECHO's text, a carried command, a
-- file name), which keeps its case.
local free_text
function M.free_text(name)
  if not free_text then
    free_text = {}
    for _, c in ipairs(squawk.sim.commands()) do free_text[c.name] = (c.args or ""):find("string", 1, true) ~= nil end
  end
  return free_text[name] ~= false
end

-- The question when a speed typed as SPD's (line c, its registry name `name`) or as CRE's last value lies far
-- outside what the aircraft can fly; else nil. `copy`: a function giving the scratch simulation.
-- A value of the form "M..." or under 1 is a Mach number: one of 1 or more is asked ("M1.5"), but "M78", two digits
-- from 40 with no point, is Mach .78 typed short: nil, "english" (the grammar reads it). Any other is knots
-- (CAS): over lexicon.typed_speed.max_kt is asked for every aircraft, and over types.too_fast's limit for a piston,
-- turboprop or helicopter; under lexicon.typed_speed.min_kt, for a jet
-- (a type the performance models class as no piston, turboprop or helicopter) in the air, or any aircraft flying
-- lexicon.typed_speed.fast_kt or more; a value with a decimal point from 1 to that minimum is asked for every
-- aircraft. A value of two digits from 50, or three from 500, is asked as the Mach number it may be ("78": .78?).
function M.typed_speed_question(c, name, copy)
  local w = {}
  for x in c:gmatch("[^%s,]+") do w[#w + 1] = x end
  local id, actype, v, alt_ft, cas_kt
  if name == "SPD" and #w == 3 then
    local a = copy():get(w[2])
    if not a then return nil end
    id, actype, v, alt_ft, cas_kt = w[2]:upper(), a.type, w[3], a.alt_ft or 0, a.cas_kt or 0
  elseif name == "CRE" and #w == 8 then
    local alt = w[7]:upper()
    alt_ft = alt:match("^FL(%d+)$") and tonumber(alt:sub(3)) * 100 or tonumber(alt)
    if not alt_ft or alt_ft <= 0 then return nil end
    id, actype, v, cas_kt = w[2]:upper(), w[3]:upper(), w[8], 0
  else
    return nil
  end
  local T = lexicon.typed_speed
  local said = name == "SPD" and string.format("%s flies %s kt", id, math.floor(cas_kt + 0.5))
    or string.format("%s would be created at %s ft", id, math.floor(alt_ft + 0.5))
  local mach = v:match("^[Mm](.*)$")
  if mach then
    local m = tonumber(mach)
    if m and m >= 1 then
      -- ("m84": Mach typed short with its point left out, which the grammar reads as Mach .84)
      if mach:match("^[4-9]%d$") then return nil, "english" end
      local guess = mach:match("^([5-9]%d)$")
      return string.format("%s, and I read Mach %s, which no %s flies. %s", said, mach, actype,
        guess and ("Did you mean Mach ." .. guess .. ", or another speed?") or "What speed should it fly?")
    end
    return nil
  end
  local kt = tonumber(v)
  if not kt or kt < 1 then return nil end
  local jet = types.slow_class(actype) == nil
  local slow = types.too_fast(actype, kt)
  local why
  if kt > T.max_kt then
    why = string.format("%s kt, faster than any airliner flies", v)
  elseif slow then
    why = types.too_fast_words(v, actype, slow)
  elseif kt < T.min_kt and (v:find(".", 1, true) or (jet and alt_ft > 0) or cas_kt >= T.fast_kt) then
    why = v:find(".", 1, true) and string.format("%s, which is neither a Mach number nor a speed in knots", v)
      or string.format("%s kt, slower than %s %s can fly", v, actype:match("^[AEIOU]") and "an" or "a", actype)
  end
  if not why then return nil end
  local guess = jet and (v:match("^([5-9]%d)$") or v:match("^([5-9]%d)0$"))
  return string.format("%s, and I read %s. %s", said, why,
    guess and ("Did you mean Mach ." .. guess .. ", or another speed?") or "What speed should it fly?")
end

-- The question when a level typed as ALT's (line c, its registry name `name`) is a bare number of feet below
-- lexicon.typed_level.min_ft ("klm12 alt 350": 350 ft, or FL350 typed short?); else nil. A value with "FL", a
-- decimal point or a unit, or of lexicon.typed_level.min_ft or more ("ALT KLM12 3500"), stays as typed; 0 too.
-- The flight level is offered when it lies within lexicon.typed_level.max_fl. `copy`: the scratch simulation.
function M.typed_level_question(c, name, copy)
  if name ~= "ALT" then return nil end
  local w = {}
  for x in c:gmatch("[^%s,]+") do w[#w + 1] = x end
  local v = w[3] and w[3]:match("^%d+$") and tonumber(w[3])
  local T = lexicon.typed_level
  if not v or v < 1 or v >= T.min_ft or (w[4] and not w[4]:match("^[%+%-]?%d+$")) then return nil end
  local a = copy():get(w[2])
  if not a then return nil end
  local id = w[2]:upper()
  local offer = v <= T.max_fl and string.format("Did you mean FL%03d, or %d ft?", v, v)
    or "What level should it fly?"
  return string.format("%s is at %d ft, and I read %d ft, below any level an aircraft is cleared to. %s", id,
    math.floor((a.alt_ft or 0) + 0.5), v, offer)
end

-- The arguments of a command written as a function call ("TRA6XN, 'EHAM'", "'KLM77','B738',52.3"), as one line
-- with the arguments apart by spaces: each argument is one word, or one word in single or double quotes (the
-- word inside); nil when an argument is empty, holds a space or a quote inside its quotes, or a quote is left
-- open. Arguments with no quote at all keep their commas as typed (BlueSky reads them as separators).
function M.call_arguments(inner)
  if not inner:find("[\"']") then return inner end
  local out = {}
  for arg in (inner .. ","):gmatch("([^,]*),") do
    arg = trim(arg)
    local q, word = arg:match("^([\"'])(.*)%1$")
    if q then arg = word end
    if arg == "" or arg:find("[%s\"']") then return nil end
    out[#out + 1] = arg
  end
  return table.concat(out, " ")
end

function M.typed(state, ctx)
  local cmds = M.split_commands(state.request)
  if #cmds == 0 then return "english" end
  -- a copy of ctx.sim, made when first read (most English ends before)
  local scratch
  local function copy()
    scratch = scratch or ctx.sim:copy()
    return scratch
  end
  -- true when `line` (a command that shows a state) checks against the copy: it becomes the candidate, traced `why`
  local function shown_by(line, why)
    if not copy():check(line) then return false end
    state.candidate, state.source = line, "typed"
    M.say(state, "typed", why .. ": shown by " .. line)
    return true
  end
  -- "zoner?", "reso?": a setting's command name asked about alone is that command with no argument, which
  -- shows the setting (only a command whose arguments are all optional; "hold?" runs nothing)
  local asked = #cmds == 1 and cmds[1]:match("^%s*([%a_]+)%s*%?%s*$")
  local shown = asked and canonical_name(asked)
  if shown and (usage_of(shown) or ""):match("^%S+%s+%[") and shown_by(shown, "a setting asked about") then
    return "trafscript"
  end
  -- "dlh2ta lnav?", "vnav klm12?": an aircraft's switch asked about with its command name, the aircraft before or
  -- after it, is that command with the aircraft alone, which shows it (only a command whose arguments after the
  -- aircraft are all optional: "LNAV acid,[ON/OFF]"; "klm12 alt?" is English)
  local w1, w2
  if #cmds == 1 then w1, w2 = cmds[1]:match("^%s*([%w_]+)[%s,]+([%w_]+)%s*%?%s*$") end
  local asked_name = w1 and (canonical_name(w1) or canonical_name(w2))
  local asked_acid = asked_name and (canonical_name(w1) and w2 or w1)
  if asked_name and not (canonical_name(w1) and canonical_name(w2))
      and (usage_of(asked_name) or ""):match("^%S+%s+acid,%[") and copy():get(asked_acid) then
    if shown_by(asked_name .. " " .. asked_acid:upper(), "an aircraft's setting asked about") then
      return "trafscript"
    end
  end
  for k, c in ipairs(cmds) do
    -- a question, or a thousands separator ("alt KL204 12,000": a number of its own, in a line that separates its
    -- other words by spaces), is English
    if c:find("[?!]") or (c:find("%f[%w]%d%d?%d?,%d%d%d%f[^%w]") and trim(c):find("%s")) then return "english" end
    -- "cre(klm15,a320,52.3,4.5,90,fl100,250)", "ALT(KLM12, FL200)": a registry command written as a function call,
    -- its arguments in brackets, is that command with those arguments (then checked as any typed line)
    local called, inner = c:match("^%s*([%a_]+)%s*%(([^()]*)%)%s*$")
    if called and canonical_name(called) and inner:find("%S") then
      -- ("direct(TRA6XN, 'EHAM')", "at(KLM12, 'SPY', 'spd', 220)": an argument in quotes, as a script writes a
      -- string, is the word inside; the call's arguments are one per comma, so they run apart by spaces)
      local unquoted = M.call_arguments(inner)
      if not unquoted and not M.free_text(canonical_name(called)) then return "english" end
      c = called .. " " .. (unquoted or inner)
      cmds[k] = c
    end
    -- "ALT,DLH4AX,FL220", "alt, klm12, fl220": BlueSky's separators, whitespace with at most one comma, are one
    -- space here, so that the line reads as the same command; an argument left out (",,") keeps its commas, and
    -- a command of free text (ECHO's text, a carried command) keeps them after its first argument
    if c:find(",", 1, true) and not c:find(",%s*,") then
      local words = {}
      for w in c:gmatch("[^%s,]+") do words[#words + 1] = w end
      local named = canonical_name(words[1]) or canonical_name(words[2])
      if named and not M.free_text(named) then
        c = table.concat(words, " ")
        cmds[k] = c
      end
    end
    local first, second, rest = c:match("^([%w_]+)[%s,]*([%w_]*)(.*)$")
    if not first then return "english" end
    -- a letter of the spelling alphabet that is also a command's name, followed by another letter
    -- ("Echo Charlie Kilo Juliett Bravo, climb ..."), spells a callsign: English, not ECHO
    if lexicon.phonetic[first:lower()] and lexicon.phonetic[second:lower()] then return "english" end
    if not canonical_name(first) and not canonical_name(second) then
      local fixed = M.command_slip(c, copy)
      if not fixed then return "english" end
      c = fixed
      cmds[k] = c
      first, second, rest = c:match("^([%w_]+)[%s,]*([%w_]*)(.*)$")
    end
    if not canonical_name(first) then
      -- "KL204 HDG 045": BlueSky's callsign-first form, run command first
      if not copy():get(first) then return "english" end
      c = second .. " " .. first .. rest
      cmds[k] = c
    end
    -- an argument that is an English word of the grammar ("turn KL204 north": heading 360, not the
    -- bearing to a waypoint NORTH) makes the line English
    local name = canonical_name(c:match("^([%w_]+)"))
    c = NESTED_AT[name] and M.complete_nested(c, name, copy()) or c
    cmds[k] = c
    -- the command a condition carries is TrafScript too ("SCHEDULE 60 HOLD"): its name is no
    -- English word; one that does not parse ("ana257 atalt fl080 spd 210": SPD names no
    -- aircraft) is asked about, never run nor read as English
    local inner, inner_at = carried_command(name, c)
    if inner then
      local ok, why = copy():check(inner)
      if not canonical_name(inner:match("^([%w_]+)")) then return "english" end
      -- ("schedule a pause at 20 min": English glue where the time should be)
      local head = {}
      for w in c:gmatch("[^%s,]+") do head[#head + 1] = w end
      if has_english_word(table.concat(head, " ", 1, inner_at - 1), name) then return "english" end
      if not ok then
        state.ask = string.format("%s carries '%s', which is not a command it can run (%s). What should it run?",
          name, inner, why)
        M.say(state, "typed", "asks: " .. state.ask)
        return "ask"
      end
    end
    local words = {}
    for w in c:gmatch("[^%s,]+") do words[#words + 1] = w end
    if has_english_word(table.concat(words, " ", 1, (inner_at or #words + 1) - 1), name)
        or (inner and has_english_word(inner, canonical_name(inner:match("^([%w_]+)")))) then
      return "english"
    end
    if not copy():check(c) then return "english" end
    -- "KL204 turn 30 right" is a turn of 30 degrees in English, heading 030 in TrafScript:
    -- a turn of one or two digits, with a side or none ("exp1 turn 30": 30 degrees or heading
    -- 030?), typed with the English word "turn", is English
    local turn_typed = name == "HDG" and c:match("^(%S+)"):lower() == "turn" and c:match("^(%S+)") ~= "TURN"
    -- "wzz6lj turn 250 left": three digits with no leading zero and a side read as a turn of that many
    -- degrees as well as the heading: asked ("turn 090 left", a leading zero, is the heading)
    local who, deg, way = c:match("^%S+[%s,]+(%S+)[%s,]+([1-3]%d%d)[%s,]+([LlRr]%a*)%s*$")
    if turn_typed and who and tonumber(deg) <= 360 then
      state.ask = string.format("Should %s turn %s by %s degrees, or fly heading %s?",
        who:upper(), way:sub(1, 1):lower() == "l" and "left" or "right", deg, deg)
      M.say(state, "typed", "asks: " .. state.ask)
      return "ask"
    end
    if turn_typed
        and (c:match("^%S+[%s,]+%S+[%s,]+%d%d?[%s,]+[LlRr]%a*%s*$") or c:match("^%S+[%s,]+%S+[%s,]+%d%d?%s*$")) then
      return "english"
    end
    -- "dlh3gm hdg 27", "hdg 2", "hdg 07": a heading typed with one or two digits, in lower case, is English (027 or
    -- 270? 007 or 070? asked there); "DLH3GM HDG 27" in capitals stays TrafScript, heading 027
    local verb = c:match("^(%S+)")
    if name == "HDG" and verb ~= verb:upper() and (c:match("^%S+[%s,]+%S+[%s,]+[0-3]?%d%f[^%w.]"))
        and tonumber(c:match("^%S+[%s,]+%S+[%s,]+(%d+)")) <= 36 then
      return "english"
    end
    -- ("kl204 hdg -30", "heading +20": a signed heading in lower case is a turn by that much, English)
    if name == "HDG" and verb ~= verb:upper() and c:match("^%S+[%s,]+%S+[%s,]+[%+%-]%d") then return "english" end
    -- "cre tst9 a320 48 11 90 fl200 25": an aircraft created in the air below lexicon.min_airborne_kt
    -- is English (its speed asked about there)
    if name == "CRE" then
      local alt, spd = c:match("(%S+)[%s,]+(%d+)%s*$")
      local level = alt and tonumber((alt:gsub("^[Ff][Ll]", "")))
      if level and level > 0 and tonumber(spd) < lexicon.min_airborne_kt then return "english" end
    end
    -- ("spd 25": a speed of knots below it, no Mach number, is English too; so is a vertical speed typed
    -- below lexicon.min_typed_fpm, "vs 15": hundreds of ft/min with the zeros left out?)
    local typed_kt = name == "SPD" and tonumber(c:match("^%S+[%s,]+%S+[%s,]+(%d+)%s*$"))
    if typed_kt and typed_kt >= 1 and typed_kt < lexicon.min_airborne_kt then return "english" end
    -- a speed far outside what the aircraft flies ("spd klm12 78" to an A320, "KLM12 SPD 780"): asked, naming why
    local far, english
    if name == "SPD" or name == "CRE" then far, english = M.typed_speed_question(c, name, copy) end
    if english then return "english" end
    if far then
      state.ask = far
      M.say(state, "typed", "asks: " .. state.ask)
      return "ask"
    end
    -- a level typed as a bare number of feet too low to be meant ("klm12 alt 350"): asked, offering the flight level
    local low = M.typed_level_question(c, name, copy)
    if low then
      state.ask = low
      M.say(state, "typed", "asks: " .. state.ask)
      return "ask"
    end
    local typed_fpm = name == "VS" and tonumber(c:match("^%S+[%s,]+%S+[%s,]+([%-%+]?%d+)%s*$"))
    if typed_fpm and typed_fpm ~= 0 and math.abs(typed_fpm) < lexicon.min_typed_fpm then return "english" end
    -- ("ff 5": a fast-forward in lower case shorter than lexicon.ff_bare_min_s is English, seconds or minutes
    -- asked there; "FF 5" in capitals stays TrafScript, five seconds)
    local typed_s = name == "FF" and verb ~= verb:upper() and tonumber(c:match("^%S+[%s,]+(%d+%.?%d*)%s*$"))
    if typed_s and typed_s > 0 and typed_s < lexicon.ff_bare_min_s then return "english" end
    -- a heading beyond 360 is wrapped by TrafScript but asked about in English
    local h = canonical_name(c:match("^([%w_]+)")) == "HDG" and tonumber(c:match("^[%w_]+[%s,]+[%w_]+[%s,]+([%d%.]+)"))
    if h and h > 360 then return "english" end
    -- and it runs: "turn KL204 north" parses (a name is a bearing) but names nothing
    if not copy():exec(c) then return "english" end
    -- shown with its registry name: "delete KL204" -> "DEL KL204"; the arguments in capitals, as the registry
    -- reads ids, places and keywords ("tfl7gh dest ehbk" -> "DEST TFL7GH EHBK"), unless one is free text (a
    -- string: ECHO's text, a carried command, a file name)
    local args = c:match("^[%w_]+(.*)$")
    if not M.free_text(name) then
      -- ("addwpt KLM12 'SPY'": a word in quotes is the word, as the registry reads it)
      args = (args:upper() .. " "):gsub("([%s,])([\"'])([^%s,\"']+)%2([%s,])", "%1%3%4"):sub(1, -2)
    end
    -- (ECHO's text typed whole in one pair of quotes, "echo 'run 3 start'", is the words inside: the quotes
    -- delimit the text, as in a script)
    if name == "ECHO" then
      local q, inner = args:match("^%s+([\"'])(.-)%1%s*$")
      if q and inner:find("%S") and not inner:find(q, 1, true) then args = " " .. inner end
    end
    cmds[k] = name .. args
  end
  state.candidate, state.source = table.concat(cmds, " ; "), "typed"
  M.say(state, "typed", "TrafScript typed in English mode: runs as that command: " .. state.candidate)
  return "trafscript"
end

-- A rejected candidate: back to the producing LLM node with the error while
-- retries last, else the end with state.error set.
local function rejected(state, ctx, node, msg)
  state.feedback = { previous = state.candidate, error = msg }
  state.commands = M.split_commands(state.candidate or "")
  if state.source == "llm" and state.retries < ctx.max_retries then
    state.retries = state.retries + 1
    M.say(state, node, string.format("rejected (retry %d of %d): %s", state.retries, ctx.max_retries, msg))
    return "retry"
  end
  state.error = msg
  M.say(state, node, "rejected, giving up: " .. msg)
  return "fail"
end

-- The registry's own parser and then the command itself, command by command,
-- on one scratch copy where the earlier commands of the line have run (so
-- "CRE X ... ; HDG X 90" checks); the real sim is untouched. The outputs
-- wait in state.outputs for the execute node.
-- A command that parses but that the simulator refuses when it runs (IC of a
-- scenario file that is not there, CRE of a callsign in use) says what the
-- speaker asked for: it is the translation, and the refusal is its result
-- where it runs (the REPL shows "error: ..."). Only an LLM with retries left
-- is sent back to try again.
-- A simulation setting: a registry command whose arguments are numbers only ("ZONER [float]", "DT
-- [float/txt,float]", "SEED int"), no aircraft, place or text.
local settings
local function is_setting(name)
  if not settings then
    settings = {}
    for _, c in ipairs(squawk.sim.commands()) do
      local numeric, other = false, false
      for a in (c.args or ""):gmatch("[%a]+") do
        if a == "float" or a == "int" or a == "time" then numeric = true elseif a ~= "txt" then other = true end
      end
      settings[c.name] = numeric and not other
    end
  end
  return settings[name] == true
end

-- Two commands read from English that set the same target of one aircraft now to different values ("ALT
-- KLM12 FL350 ; ALT KLM12 FL370", a level described and a level cleared): the two, or nil ("19000 ; FL190",
-- one value said twice, is no contradiction). Typed TrafScript runs as typed.
local ONE_TARGET = { ALT = true, HDG = true, SPD = true, VS = true }
local function target_value(c)
  local v = (c:match("^%S+%s+%S+%s+(%S+)") or ""):upper()
  return v:match("^FL(%d+)$") and tonumber(v:match("^FL(%d+)$")) * 100 or tonumber(v) or v
end
local function contradicting(cmds)
  local seen = {}
  for _, c in ipairs(cmds) do
    local name, acid = canonical_name(c:match("^(%S+)")), c:match("^%S+%s+(%S+)")
    if name and ONE_TARGET[name] and acid then
      local key = name .. " " .. acid:upper()
      if seen[key] and target_value(seen[key]) ~= target_value(c) then return seen[key], c end
      seen[key] = c
    end
  end
  return nil
end

function M.validate(state, ctx)
  local cmds = M.split_commands(state.candidate or "")
  if #cmds == 0 then return rejected(state, ctx, "validate", "no command was produced") end
  local first, second
  if state.source ~= "typed" then first, second = contradicting(cmds) end
  if first and state.source == "llm" then
    return rejected(state, ctx, "validate", string.format("'%s' and '%s' set the same target", first, second))
  elseif first then
    state.ask = string.format("I have both '%s' and '%s'. Which one do you mean?", first, second)
    M.say(state, "validate", "asks: " .. state.ask)
    return "ask"
  end
  local scratch = ctx.sim:copy()
  local outputs = {}
  for _, c in ipairs(cmds) do
    if not canonical_name(c:match("^([^%s,]+)")) and not canonical_name(c:match("^[^%s,]+[%s,]+([^%s,]+)")) then
      return rejected(state, ctx, "validate", string.format("'%s': unknown command", c))
    end
    local ok, msg = scratch:check(c)
    if not ok then return rejected(state, ctx, "validate", msg) end
    ok, msg = scratch:exec(c)
    if not ok and state.source == "llm" and state.retries < ctx.max_retries then
      return rejected(state, ctx, "validate", msg)
    end
    -- a setting read from English with a value the simulator refuses ("set the time step to 0") is
    -- asked about, naming the refusal; typed TrafScript runs as typed
    if not ok and state.source == "offline" and is_setting(canonical_name(c:match("^(%S+)"))) then
      state.ask = string.format("squawk would refuse %s (%s). What value should it be?", c,
        (msg:gsub("^[^:]*:%s*", ""):gsub("^%u+:%s*", "")))
      M.say(state, "validate", "asks: " .. state.ask)
      return "ask"
    end
    if not ok then msg = "the simulator will refuse it: " .. msg end
    if msg and msg ~= "" then outputs[#outputs + 1] = msg end
  end
  state.outputs = outputs
  M.say(state, "validate", "parses and runs: " .. table.concat(cmds, " ; "))
  return "ok"
end

-- Accepts the line validate ran on its scratch copy.
function M.execute(state)
  state.commands = M.split_commands(state.candidate)
  state.error = nil
  local outputs = state.outputs or {}
  M.say(state, "execute", "ran on a scratch copy: ok" .. (#outputs > 0 and ("; " .. table.concat(outputs, " / ")) or ""))
  return "ok"
end

return M
