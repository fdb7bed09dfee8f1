-- The translation graph: English request -> TrafScript, as nodes and edges.
--
-- A graph is a set of named nodes and labelled edges. A node is a function
-- node(state, ctx) -> label that reads and writes `state` and says where to go;
-- the edge (node, label) names the next node; the node "done" ends the run.
-- Every node visit appends {node = name, said = text} to state.trace, so each
-- request leaves a readable account of its path (format_trace prints it).
-- A run stops after ctx.max_steps visits (an error in the trace, never a hang).
--
-- Graphs (modes), after paper §III.B and Table 2:
--   offline: offline (the grammar, translate/grammar.lua) -> validate -> execute
--            -> done; no retrieval
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
--   A question about an inexactly heard callsign carries result.confirm =
--   {id =, heard =}.
--   dialogue(opts) -> d   a conversation: d:say(text) -> result as translate()
--       returns it. A result that asks keeps its partial request in d.pending
--       ({question =, request =}) and the next say() answers it: a line with
--       no instruction word of its own (or one that does not translate alone)
--       is joined to the pending request ("KL204 descend" -> "to what
--       altitude?" -> "flight level 100" -> ALT KL204 FL100; result.answered
--       holds the question answered); say("cancel") drops it (result.cancelled).
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

local function common_tail(g, retry_node)
  return g:node("validate", nodes.validate)
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
    :edge("ask", "done")
end

M.modes = {}

function M.modes.offline()
  return common_tail(M.new_graph("offline"), "done")
end

function M.modes.single()
  local g = M.new_graph("retrieve")
    :node("retrieve", nodes.retrieve)
    :node("single", nodes.single)
    :edge("retrieve", "single")
    :edge("single", "ok", "validate")
    :edge("single", "ask", "done")
    :edge("single", "llm_failed", "offline")
  return common_tail(g, "single")
end

function M.modes.multi(opts)
  local g = M.new_graph("retrieve")
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
  return common_tail(g, "fill")
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

function M.translate(text, opts)
  opts = opts or {}
  local llm = opts.llm
  if llm == nil and opts.mode ~= "offline" then llm = default_llm() end
  local mode = opts.mode or (llm and "multi" or "offline")
  if not M.modes[mode] then
    error("translate: mode '" .. tostring(mode) .. "' is not one of offline, single, multi")
  end
  local requested = mode
  if mode ~= "offline" and not llm then mode = "offline" end
  local sim, setup_notes = opts.sim, {}
  if not sim then
    sim = squawk.sim.new()
    for _, line in ipairs(nodes.split_commands(opts.setup or "")) do
      local ok, msg = sim:exec(line)
      if not ok then setup_notes[#setup_notes + 1] = "setup line skipped: " .. msg end
    end
  end
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
  }
  local state = { request = text, trace = {}, retries = 0, mode = mode }
  nodes.say(state, "start", string.format("mode %s, %s", mode, llm and llm:describe() or "no LLM")
    .. (requested ~= mode and (" (" .. requested .. " needs an LLM: set SQUAWK_LLM_URL)") or ""))
  for _, note in ipairs(setup_notes) do nodes.say(state, "setup", note) end
  M.modes[mode](opts):run(state, ctx)
  local result = { trace = state.trace, mode = mode, error = state.error }
  if state.ask then
    result.ask, result.confirm = state.ask, state.confirm
  else
    result.commands = state.commands or {}
  end
  return result
end

local Dialogue = {}
Dialogue.__index = Dialogue

function M.dialogue(opts)
  return setmetatable({ opts = opts or {}, pending = nil }, Dialogue)
end

local CANCEL = { cancel = true, ["never mind"] = true, nevermind = true, ["forget it"] = true, abort = true }

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
  if pending and pending.confirm and grammar.lexicon_says(text, "yes") then
    local opts = setmetatable({ confirmed = { [pending.confirm.id] = true } }, { __index = self.opts })
    local r = M.translate(pending.request, opts)
    r.answered = pending.question
    self.pending = r.ask and { question = r.ask, request = pending.request, confirm = r.confirm } or nil
    return r
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
  self.pending = r.ask and { question = r.ask, request = request, confirm = r.confirm } or nil
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
