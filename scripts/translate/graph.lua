-- The translation graph: English request -> TrafScript, as nodes and edges.
--
-- A graph is a set of named nodes and labelled edges. A node is a function
-- node(state, ctx) -> label that reads and writes `state` and says where to go;
-- the edge (node, label) names the next node; the node "done" ends the run.
-- Every node visit appends {node = name, said = text} to state.trace, so each
-- request leaves a readable account of its path (format_trace prints it).
-- A run stops after ctx.max_steps visits (an error in the trace, never a hang).
--
-- Graphs (modes), after paper §III.B and Table 2; each starts at `typed`: a
-- request that is already TrafScript ("FF 60", "HOLD", "HDG KL204 270", any
-- case) goes straight to validate, and the trace says so (result.typed):
--   offline: offline (the grammar, translate/grammar.lua) -> validate -> execute
--            -> done; no retrieval. A request naming only what squawk does
--            not simulate (a holding pattern, an approach clearance, a
--            transponder code, a frequency) ends with no command and
--            result.note saying so; in a mixed request the note comes with
--            the commands of the rest
--   single:  retrieve -> single (one LLM call) -> validate -> execute -> done;
--            a rejected command goes back to `single` with the simulator's
--            error, up to ctx.max_retries times
--   multi:   retrieve -> select -> verify -> fill -> validate -> execute -> done;
--            verify NO -> ask; a rejected command goes back to `fill` with the
--            error, up to ctx.max_retries times. With opts.verify = false the
--            selector feeds the filler directly, as in the paper's Table 2 runs
-- In the LLM modes any server failure goes to the `offline` node (the
-- embedded grammar translator), so a request is always answered.
--
-- Module API (the contract engine/script/translate_graph.h relies on):
--   translate(text, opts) -> {commands = {...}} or {ask = "..."}, plus
--       .trace, .mode, .error (when no valid command came out)
--     opts.mode     "offline" | "single" | "multi"; default multi with an LLM,
--                   else offline; single/multi without an LLM run offline
--                   (the trace says so, result.mode is "offline")
--     opts.sim      a squawk.sim to translate against (read, never changed:
--                   candidates run on a copy); default a new sim with opts.setup
--     opts.setup    TrafScript run on the new sim when opts.sim is absent; a
--                   line the sim rejects is skipped and noted in the trace
--     opts.waypoints names of user waypoints (DEFWPT) in opts.sim; those
--                   defined in opts.setup are found by themselves
--     opts.llm      a squawk.llm client; default squawk.llm.from_env()
--     opts.verify   false: multi mode without the verifier node
--     opts.k        documents retrieved (default 5)
--     opts.max_retries  feedback rounds (default 3)
--     opts.on_token streaming callback passed to the LLM
--     opts.confirmed {[callsign] = true}: inexactly heard callsigns the
--                   speaker confirmed (the dialogue sets it after "yes")
--     opts.ignored  {[word] = true}: leftover words the speaker said carry
--                   nothing (the dialogue sets it after "ignore it")
--   A question about an inexactly heard callsign carries result.confirm =
--   {id =, heard =}; one about an airline said alone as the addressee also
--   {choices = {callsign, ...}} (with id only when one fits): the next say()
--   of one of those callsigns alone confirms it. Commands that need a yes first (confirmation(): several
--   aircraft deleted, RESET, IC, conflict detection/resolution off; the
--   grammar's confirm_first: a relative turn of more than 180 degrees, an
--   airport found by name only far away) come back as a yes/no question with
--   result.confirm = {commands =}, every command of the request, and no
--   result.commands.
--   dialogue(opts) -> d   a conversation: d:say(text) -> result as translate()
--       returns it. A result that asks keeps its partial request in d.pending
--       ({question =, request =}) and the next say() answers it: a line with
--       no instruction word of its own (or one that does not translate alone)
--       is joined to the pending request ("KL204 descend" -> "to what
--       altitude?" -> "flight level 100" -> ALT KL204 FL100; result.answered
--       holds the question answered); say("cancel") drops it (result.cancelled).
--       A question about a leftover plain word carries result.ignorable = the
--       word: an answer from lexicon.ignore ("ignore it", "nothing") reads the
--       request again with that word explained (validated as any request).
--       After a question with result.confirm.commands the next say() runs
--       them on "yes"
--       (result.confirmed), drops them on "no" (result.cancelled) and on
--       anything else drops them and reads that line as a new request
--       (result.dropped names the request dropped).
--       opts as translate(); every front end (REPL, serve, C++ through
--       script::GraphDialogue, scripts) talks through this.
--   new_graph(start), modes[name](opts) -> graph, format_trace(trace), nodes
local nodes = require("translate.nodes")
local grammar = require("translate.grammar")

local M = {}
M.nodes = nodes

local Graph = {}
Graph.__index = Graph

function M.new_graph(start)
  return setmetatable({ start = start, fns = {}, edges = {} }, Graph)
end

function Graph:node(name, fn)
  self.fns[name] = fn
  return self
end

-- edge(from, to) is the unconditional edge; edge(from, label, to) a labelled one.
function Graph:edge(from, label, to)
  if to == nil then label, to = "next", label end
  self.edges[from] = self.edges[from] or {}
  self.edges[from][label] = to
  return self
end

function Graph:run(state, ctx)
  local current = self.start
  for _ = 1, ctx.max_steps do
    if current == "done" then return state end
    local fn = self.fns[current]
    if not fn then error("translation graph: no node '" .. tostring(current) .. "'") end
    local label = fn(state, ctx) or "next"
    local out = self.edges[current] or {}
    local nxt = out[label] or out.next
    if not nxt then
      error(string.format("translation graph: node '%s' returned '%s' and has no such edge", current, label))
    end
    current = nxt
  end
  nodes.say(state, "graph", "stopped after " .. ctx.max_steps .. " steps")
  state.error = state.error or "the translation graph ran out of steps"
  return state
end

-- Every mode starts at `typed` (TrafScript passes through as typed); English
-- goes on to the mode's own first node.
local function common_tail(g, retry_node, english)
  return g:node("typed", nodes.typed)
    :edge("typed", "trafscript", "validate")
    :edge("typed", "english", english)
    :edge("typed", "ask", "done")
    :node("validate", nodes.validate)
    :node("execute", nodes.execute)
    :node("offline", nodes.offline)
    :node("ask", nodes.ask)
    :edge("validate", "ok", "execute")
    :edge("validate", "retry", retry_node)
    :edge("validate", "fail", "done")
    :edge("validate", "ask", "done")
    :edge("execute", "ok", "done")
    :edge("execute", "retry", retry_node)
    :edge("execute", "fail", "done")
    :edge("offline", "ok", "validate")
    :edge("offline", "ask", "done")
    :edge("offline", "note", "done")
    :edge("ask", "done")
end

M.modes = {}

function M.modes.offline()
  return common_tail(M.new_graph("typed"), "done", "offline")
end

function M.modes.single()
  local g = M.new_graph("typed")
    :node("retrieve", nodes.retrieve)
    :node("single", nodes.single)
    :edge("retrieve", "single")
    :edge("single", "ok", "validate")
    :edge("single", "ask", "done")
    :edge("single", "llm_failed", "offline")
  return common_tail(g, "single", "retrieve")
end

function M.modes.multi(opts)
  local g = M.new_graph("typed")
    :node("retrieve", nodes.retrieve)
    :node("select", nodes.select)
    :node("verify", nodes.verify)
    :node("fill", nodes.fill)
    :edge("retrieve", "select")
    :edge("select", "ok", opts.verify == false and "fill" or "verify")
    :edge("select", "llm_failed", "offline")
    :edge("verify", "yes", "fill")
    :edge("verify", "no", "ask")
    :edge("verify", "llm_failed", "offline")
    :edge("fill", "ok", "validate")
    :edge("fill", "ask", "done")
    :edge("fill", "llm_failed", "offline")
  return common_tail(g, "fill", "retrieve")
end

local cached_llm, llm_checked = nil, false
local function default_llm()
  if not llm_checked then
    llm_checked = true
    cached_llm = squawk.llm.from_env()
  end
  return cached_llm
end

local cached_index
local function default_index()
  cached_index = cached_index or squawk.rag.index({ docs = grammar.documents() })
  return cached_index
end

local cached_prompts
local function default_prompts()
  cached_prompts = cached_prompts or squawk.load_config("prompts/translator.lua")
  return cached_prompts
end

-- "seed 7, mcre 20, ff 10 min": a list whose every comma-separated clause
-- opens with a registry command word (name or alias; a leading "then"/"and"
-- skipped) that a pronoun does not follow -> the clauses, else nil ("speed it
-- up a bit, run it at twice real time" is English: no argument is a pronoun).
local LINKS = { ["then"] = true, ["and"] = true }
local PRONOUNS = require("translate.lexicon").pronouns
local PHONETIC = require("translate.lexicon").phonetic
-- a clause opening with "at" or a condition word ("at 30 minutes, pause") is English: a time or a
-- condition for the clause after it, no AT/AFTER/BEFORE command of its own
local CONDITION_OPENERS = { at = true }
for _, w in ipairs(require("translate.lexicon").accounted.condition) do CONDITION_OPENERS[w] = true end
-- ("cre UAL1542 A320 at 42.05 -89.2, hdg 095 alt FL200": a heading, altitude or speed clause after a
-- creation gives the new aircraft's fields, English for one creation; "..., alt UAL1542 FL300", naming
-- its callsign, is a command of its own; so after a move: "Move Nordland 501 to Samara airport at 3000 feet,
-- heading 150, speed 200" gives the moved aircraft's fields)
local CREATION_FIELDS = { HDG = true, ALT = true, SPD = true }
function M.command_clauses(text)
  local parts = {}
  local prev, created
  for part in (text .. ","):gmatch("([^,;]*)[,;]") do
    part = part:gsub("^%s+", ""):gsub("%s+$", "")
    local first, rest = part:match("^(%S+)%s*(.*)$")
    while first and LINKS[first:lower()] do first, rest = rest:match("^(%S+)%s*(.*)$") end
    local cmd = first and nodes.canonical_name(first:gsub("[%p]+$", ""))
    if not cmd or CONDITION_OPENERS[first:lower()] then return nil end
    local arg = (rest:match("^(%S+)") or ""):lower():gsub("[%p]+$", "")
    -- ("Echo India Alpha Bravo Charlie, speed ninety knots": a letter of the spelling alphabet that names a command,
    -- another letter after it, spells a callsign: English, no ECHO)
    if PHONETIC[first:lower()] and PHONETIC[arg] then return nil end
    if (prev == "CRE" or prev == "MOVE") and CREATION_FIELDS[cmd] and arg ~= created then return nil end
    prev, created = cmd, arg
    if PRONOUNS[(rest:match("^(%S+)") or ""):lower():gsub("[%p]+$", "")] then return nil end
    parts[#parts + 1] = first .. (rest ~= "" and (" " .. rest) or "")
  end
  return #parts >= 2 and parts or nil
end

-- A list of command clauses (M.command_clauses) said as one aircraft's instructions ("alt klm12 fl240, spd 260, dct
-- sugol"): true when every clause's command instructs an aircraft (its first argument), none creating or deleting
-- one, exactly one flying aircraft is named in the request, and a clause names none; such a list is read
-- whole as English, where each clause takes that aircraft. Otherwise false, and the first clause instructing a flying
-- aircraft that names none when the request names one ("del klm12, spd 250"), which is asked, never given to an
-- aircraft left alone.
-- (commands that make or remove one; a move's fields said after it, "move X to LAM, heading 270", are the move's)
local PLACING = { CRE = true, CRECONFS = true, DEL = true }
function M.one_aircraft_list(parts, sim)
  local named, count, bare, other = {}, 0, nil, false
  for _, part in ipairs(parts) do
    local own = false
    for w in part:gmatch("[%w]+") do
      local id = #w > 2 and w:find("%d") and sim:get(w) and w:upper()
      if id then
        own = true
        if not named[id] then named[id], count = true, count + 1 end
      end
    end
    local cmd = nodes.canonical_name(part:match("^[%w_]+"))
    local usage = nodes.usage_of(cmd) or ""
    -- (a command of no argument with words after it, "continue heading for dlh4", is English, no such command)
    local worded = not usage:find("%s") and part:find("^[%w_]+%s+%w")
    local instructs = usage:match("^%S+%s+acid") ~= nil
    if PLACING[cmd] or not (instructs or worded) then other = true end
    if instructs and not own and not (cmd == "CRE" or cmd == "CRECONFS") then bare = bare or part end
  end
  if count == 1 and bare and not other then return true end
  return false, count > 0 and bare or nil
end

-- The simulator a request is translated against: opts.sim, else a new one after opts.setup's commands; and
-- notes naming the setup lines that did not run.
local function simulator(opts)
  if opts.sim then return opts.sim, {} end
  local sim, notes = squawk.sim.new(), {}
  for _, line in ipairs(nodes.split_commands(opts.setup or "")) do
    local ok, msg = sim:exec(line)
    if not ok then notes[#notes + 1] = "setup line skipped: " .. msg end
  end
  return sim, notes
end

function M.translate(text, opts)
  opts = opts or {}
  -- a list of command clauses: each translated on the state the ones before it leave (the setup's traffic
  -- too: "pause, then move IBE32 to ...")
  -- ("Speed... Speedbird 8CK, turn left ...": a word cut off where the request opens is dropped first)
  -- ("rfach 1.25, rfacv unchanged": a clause keeping settings as they are is dropped first)
  -- ("ff 15min, dt 0.1 first": the clause said to come first is put first)
  if not opts.in_list then text = grammar.first_said_first(grammar.kept_settings(grammar.cut_off_openings(text))) end
  -- ("hold on" alone: a wait as likely as a pause, asked; grammar.bare_hold_on)
  if not opts.in_list and grammar.bare_hold_on(text) then
    local q = "'hold on' may ask me to wait, or to pause the simulation. Should I pause it (HOLD)?"
    return { ask = q, trace = { { node = "offline", said = "asks: " .. q } }, mode = opts.mode or "offline" }
  end
  local parts = not opts.in_list and M.command_clauses(text)
  local whole, bare = false, nil
  if parts then whole, bare = M.one_aircraft_list(parts, simulator(opts)) end
  if whole then parts = nil end
  if bare then
    local q = string.format("Which aircraft is '%s' for? Please give its callsign.", bare)
    return { ask = q, trace = { { node = "list", said = "asks: " .. q } }, mode = opts.mode or "offline" }
  end
  if parts then
    local scratch = simulator(opts):copy()
    local all, trace, seen = {}, {}, {}
    for k, part in ipairs(parts) do
      local r = M.translate(part, setmetatable({ sim = scratch, in_list = true }, { __index = opts }))
      for _, t in ipairs(r.trace or {}) do trace[#trace + 1] = { node = t.node, said = "[" .. part .. "] " .. t.said } end
      if r.ask or r.error then
        r.trace = trace
        return r
      end
      -- ("trails on, dt 5s", "trails on; DT 5": a clause of a bare "dt" and its time straight after the trails were
      -- switched may be their own interval, TRAIL ON dt, or the simulation's step: asked, as in one clause; both typed
      -- as TrafScript, in capitals, "TRAIL ON, DT 5", are the two commands)
      local step = #r.commands == 1 and r.commands[1]:match("^DT ([%d%.]+)$")
      local typed = part:match("^DT%s") and (parts[k - 1] or ""):match("^TRAIL ON$")
      if step and not typed and (all[#all] or ""):match("^TRAIL ON$") and part:lower():match("^dt%f[%A]") then
        local q = string.format("Is %s s the trails' interval (TRAIL ON %s) or the simulation's time step (DT %s)?",
          step, step, step)
        trace[#trace + 1] = { node = "list", said = "asks: " .. q }
        return { ask = q, trace = trace, mode = opts.mode or "offline" }
      end
      -- (the same command in two clauses, "hold on, pause", runs once)
      for _, c in ipairs(r.commands) do
        if not seen[c:upper()] then
          all[#all + 1], seen[c:upper()] = c, true
          scratch:exec(c)
        end
      end
    end
    -- ("dtmult 8, then dtmult 4": one setting given two values in a row is asked, as in English)
    local q = grammar.setting_twice(all)
    if q then
      trace[#trace + 1] = { node = "list", said = "asks: " .. q }
      return { ask = q, trace = trace, mode = opts.mode or "offline" }
    end
    return { commands = all, trace = trace, mode = opts.mode or "offline" }
  end
  local llm = opts.llm
  if llm == nil and opts.mode ~= "offline" then llm = default_llm() end
  local mode = opts.mode or (llm and "multi" or "offline")
  if not M.modes[mode] then
    error("translate: mode '" .. tostring(mode) .. "' is not one of offline, single, multi")
  end
  local requested = mode
  if mode ~= "offline" and not llm then mode = "offline" end
  local sim, setup_notes = simulator(opts)
  local waypoints = {}
  for _, w in ipairs(opts.waypoints or {}) do waypoints[#waypoints + 1] = w end
  for _, w in ipairs(nodes.defined_waypoints(opts.setup or "")) do waypoints[#waypoints + 1] = w end
  local ctx = {
    llm = llm,
    sim = sim,
    index = opts.index or (mode ~= "offline" and default_index() or nil),
    prompts = opts.prompts or default_prompts(),
    k = opts.k or 5,
    max_retries = opts.max_retries or 3,
    max_steps = opts.max_steps or 40,
    on_token = opts.on_token,
    waypoints = waypoints,
    confirmed = opts.confirmed,
    ignored = opts.ignored,
  }
  local state = { request = text, trace = {}, retries = 0, mode = mode }
  nodes.say(state, "start", string.format("mode %s, %s", mode, llm and llm:describe() or "no LLM")
    .. (requested ~= mode and (" (" .. requested .. " needs an LLM: set SQUAWK_LLM_URL)") or ""))
  for _, note in ipairs(setup_notes) do nodes.say(state, "setup", note) end
  M.modes[mode](opts):run(state, ctx)
  local result = { trace = state.trace, mode = mode, error = state.error, note = state.note,
                   typed = state.source == "typed" or nil }
  if state.ask then
    result.ask, result.confirm, result.ignorable = state.ask, state.confirm, state.ignorable
  else
    -- destructive or global commands wait for a yes: the question carries
    -- the commands that the yes runs (Dialogue:answer)
    local commands = state.commands or {}
    local q = #commands > 0 and state.confirm_first or M.confirmation(commands, sim)
    if q then
      nodes.say(state, "confirm", "asks first: " .. q)
      result.ask, result.confirm = q, { commands = commands }
    else
      result.commands = commands
    end
  end
  return result
end

local Dialogue = {}
Dialogue.__index = Dialogue

function M.dialogue(opts)
  return setmetatable({ opts = opts or {}, pending = nil }, Dialogue)
end

local CANCEL = { cancel = true, ["never mind"] = true, nevermind = true, ["forget it"] = true, abort = true }

-- The question a line of commands needs before it runs, or nil: deleting
-- several aircraft, RESET, IC (a new scenario replaces the traffic), and
-- conflict detection or resolution off for every aircraft; so too when one of
-- them is carried by a command that runs it later ("SCHEDULE 01:00:00 RESET",
-- "DELAY 600 DEL *", "AT KL204 SPY DO RESO OFF").
-- (CARRIERS: how many words a carrying command takes before the command it carries)
local CARRIERS = { SCHEDULE = 2, DELAY = 2, ATALT = 3, ATSPD = 3, ATDIST = 4 }
function M.confirmation(cmds, sim)
  local deleted = {}
  for _, c in ipairs(cmds) do
    local words = {}
    for w in c:gmatch("[^%s,]+") do words[#words + 1] = w end
    local name = nodes.canonical_name(words[1]) or ""
    while CARRIERS[name] or (name == "AT" and words[4] and words[4]:upper() == "DO") do
      words = { table.unpack(words, (CARRIERS[name] or 4) + 1) }
      name = nodes.canonical_name(words[1] or "") or ""
    end
    if name == "RESET" then return "Reset the simulation? Every aircraft and queued command goes. (yes or no)" end
    if name == "IC" then
      return string.format("Load scenario %s? It replaces the present traffic. (yes or no)", words[2] or "")
    end
    if (name == "RESO" or name == "CDMETHOD") and words[2] and words[2]:upper() == "OFF" then
      return "Switch conflict " .. (name == "RESO" and "resolution" or "detection")
        .. " off for every aircraft? (yes or no)"
    end
    if name == "DEL" then
      for k = 2, #words do
        if words[k] == "*" then
          for _, a in ipairs(sim:aircraft()) do deleted[#deleted + 1] = a.id end
        elseif words[k]:upper() ~= "WIND" then
          deleted[#deleted + 1] = words[k]:upper()
        end
      end
    end
  end
  if #deleted >= 2 then
    return string.format("Delete %d aircraft (%s)? (yes or no)", #deleted, table.concat(deleted, ", "))
  end
  return nil
end

-- The answer to a pending question joins the request it answers ("KL204
-- descend" + "flight level 100"); a line with an instruction word of its own
-- that translates by itself is a new request and drops the question.
function Dialogue:say(text)
  local pending = self.pending
  local key = text:lower():gsub("[%p%s]+", " "):gsub("^ ", ""):gsub(" $", "")
  if CANCEL[key] then
    self.pending = nil
    return { commands = {}, cancelled = pending ~= nil, trace = {}, mode = self.opts.mode or "offline",
             said = pending and ("dropped: " .. pending.request) or "nothing to cancel" }
  end
  -- a yes/no question about commands already worked out: yes runs them,
  -- anything else drops them (a new request is then read as such)
  if pending and pending.confirm and pending.confirm.commands then
    self.pending = nil
    local trace = {}
    if grammar.lexicon_says(text, "yes") then
      nodes.say({ trace = trace }, "confirm", "confirmed: " .. table.concat(pending.confirm.commands, " ; "))
      return { commands = pending.confirm.commands, confirmed = true, answered = pending.question, trace = trace,
               mode = self.opts.mode or "offline" }
    end
    if grammar.lexicon_says(text, "no") then
      return { commands = {}, cancelled = true, trace = trace, mode = self.opts.mode or "offline",
               said = "dropped: " .. pending.request }
    end
    local r = self:say(text)
    r.dropped = pending.request
    return r
  end
  -- a question naming the callsigns an airline said alone may mean (confirm.choices): one of them answers it
  for _, id in ipairs(pending and pending.confirm and pending.confirm.choices or {}) do
    if key == id:lower() then
      local confirmed = { [id] = true }
      for k in pairs(pending.confirmed or {}) do confirmed[k] = true end
      return self:again(pending, setmetatable({ confirmed = confirmed, ignored = pending.ignored }, { __index = self.opts }))
    end
  end
  if pending and pending.confirm and pending.confirm.id and grammar.lexicon_says(text, "yes") then
    local confirmed = { [pending.confirm.id] = true }
    for k in pairs(pending.confirmed or {}) do confirmed[k] = true end
    local opts = setmetatable({ confirmed = confirmed, ignored = pending.ignored }, { __index = self.opts })
    return self:again(pending, opts)
  end
  if pending and pending.ignorable and grammar.lexicon_says(text, "ignore") then
    local ignored = { [pending.ignorable] = true }
    for w in pairs(pending.ignored or {}) do ignored[w] = true end
    return self:again(pending, setmetatable({ ignored = ignored, confirmed = pending.confirmed }, { __index = self.opts }))
  end
  local r, request = nil, text
  local own = not pending or grammar.has_instruction(text)
  if own then r = M.translate(text, self.opts) end
  if pending and (not r or r.ask or r.error) then
    local joined = pending.request .. " " .. text
    local j = M.translate(joined, self.opts)
    if not r or (j.commands and not j.error) then
      r, request = j, joined
      r.answered = pending.question
    end
  end
  self.pending = r.ask and { question = r.ask, request = request, confirm = r.confirm, ignorable = r.ignorable }
    or nil
  return r
end

-- The pending request read again with the speaker's answer in `opts` (a callsign
-- confirmed, a word ignored); a new question keeps what was answered so far.
function Dialogue:again(pending, opts)
  local r = M.translate(pending.request, opts)
  r.answered = pending.question
  self.pending = r.ask and { question = r.ask, request = pending.request, confirm = r.confirm,
    ignorable = r.ignorable, ignored = opts.ignored, confirmed = opts.confirmed } or nil
  return r
end

function M.format_trace(trace)
  local lines = {}
  for i, t in ipairs(trace or {}) do
    lines[#lines + 1] = string.format("%2d %-9s %s", i, t.node, (t.said:gsub("\n", "\n             ")))
  end
  return table.concat(lines, "\n")
end

return M
