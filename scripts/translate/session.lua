-- A controller's session: one simulation, English or TrafScript in, what
-- happened out, with a clock. `squawk repl` formats it as text
-- (translate.repl); `squawk serve` calls the same methods and sends the
-- tables as JSON. Nothing here prints.
--
--   session.new{scenario = path|nil, mode = "offline"|"single"|"multi"|nil,
--               seed = n, clock = multiplier|nil}  -> s
--       Loads the scenario (raises when the file does not load) and runs its
--       t = 0 commands; s.load_report says what they did (see report below).
--       clock: start the running clock at that multiple of real time.
--   s:command(text, opts) -> reply
--       text: English (translated through graph.dialogue, then run) or
--       "!CMD" (TrafScript run as typed). opts (optional) = {
--         client = key: whose dialogue (a question raised for one client is
--                  answered only by that client's next line; nil: the
--                  session's own, s.dialogue),
--         selected = callsign: a line that names no aircraft and does not
--                  translate by itself (a question or an error) is
--                  translated again as "CALLSIGN line" }. reply = {
--         text = the input, kind = "english" | "trafscript",
--         commands = { "HDG KL204 180", ... }   the TrafScript that ran, in
--                   order; an FF with an end before another clock command
--                   ("FF 120 ; HOLD") runs to its end before that command
--         results = { {cmd =, ok =, message =}, ... }  one per command run;
--                   the first failure stops the rest
--         ask = question (the translator needs more; the next command()
--               may answer it, "cancel" drops it),
--         ignorable = the leftover word the question names, when "ignore
--               it" may answer it (graph.lua, Dialogue:say),
--         cancelled = true (a question was dropped) | false (a cancel with
--               nothing pending), cancel_note = what was dropped, or
--               "nothing to cancel",
--         error = why nothing ran (translation failed, or a runtime error
--                 in a graph node; the session and simulation go on),
--         note = what the request asked that squawk does not simulate
--                (a holding pattern, an approach clearance, a transponder
--                code, a frequency); the rest of the request ran,
--         clock = a sentence when the command changed the run state
--                 (HOLD, OP, FF, DTMULT),
--         events = { event, ... } what happened while time moved (FF),
--         touched = { id, ... } aircraft named or created by the commands,
--         deleted = { id, ... },
--         addressed = callsign when opts.selected was put in front }
--   s:tick(wall_s) -> { event, ... }
--       The running clock: advances by wall_s x multiplier when running (OP),
--       to the FF end time at once in fast-time, not at all in HOLD; wall_s
--       counts up to kMaxTickWall.
--   s:run(seconds) -> { event, ... }      advance now, whatever the clock
--   s:set_clock(multiplier|nil) -> sentence   nil: stop (HOLD)
--   s:state() -> { simt =, clock = {state = "hold"|"op"|"ff", multiplier =,
--                  ff_end =?}, aircraft = { sim:aircraft() entries, each
--                  with conflict = {ids in conflict} }, conflicts = { sim:conflicts()
--                  entries {own =, intruder =, tcpa_s =, tlos_s =, dcpa_nm =, dist_nm =},
--                  each pair once (own < intruder), soonest tlos_s first },
--                  los = { sim:los() entries {own =, intruder =, dist_nm =, dalt_ft =},
--                  each pair once } }
--   s:complete(prefix) -> sorted words: callsigns, TrafScript command names
--       and aliases (also as !NAME), and the REPL's :commands
--   event = { t = s, kind = "conflict" | "conflict_reminder" | "conflict_end" | "los" | "los_end"
--             | "echo" | "failure", text = sentence, own =?, intruder =? }
--   report (load_report, and failure summaries) = { executed =, skipped =,
--             failed =, first = {first failure messages}, reasons = {
--             {reason =, count =}, ... } }
local graph = require("translate.graph")
local nodes = require("translate.nodes")

local M = {}
local Session = {}
Session.__index = Session

M.kFirstShown = 3     -- failures quoted in a summary
M.kChunk = 1.0        -- [s] sim time between conflict checks while advancing
M.kOpenFfRate = 60.0  -- FF without an end time: sim seconds per wall second
M.kMaxTickWall = 5.0  -- [s] most wall time one tick accounts for (a stopped
                      -- terminal must not make the simulation jump hours)
M.kMaxDialogues = 64  -- client dialogues kept (command() opts.client)
M.kReminders = { 120, 60 }  -- [s] tLOS at which a standing conflict is announced again (descending)
M.kMaxFfCpu = 0.5     -- [s] processor time one call spends on an FF with an end;
                      -- the rest of a long FF runs on the following ticks (HOLD stops it)
M.kMaxFfCpuBefore = 5.0  -- [s] the same for an FF said before another clock command
                         -- ("FF 120 ; HOLD"), which runs only once the FF has ended

local function pair_key(a, b)
  if a > b then a, b = b, a end
  return a .. " & " .. b, a, b
end

function M.new(opts)
  opts = opts or {}
  local self = setmetatable({ sim = squawk.sim.new({ seed = opts.seed or 0 }), mode = opts.mode }, Session)
  self.dialogue = graph.dialogue({ sim = self.sim, mode = self.mode })
  self.dialogues = {}  -- client key -> dialogue (opts.client of command())
  self.conflicts, self.los = {}, {}
  if opts.scenario and opts.scenario ~= "" then
    local ok, msg = self.sim:load(opts.scenario)
    if not ok then error("session: scenario '" .. opts.scenario .. "' did not load: " .. msg, 0) end
    -- The load reports its failures in load_report, the rest as events.
    self.load_events = {}
    for _, e in ipairs(self:run(0)) do
      if e.kind ~= "failure" then self.load_events[#self.load_events + 1] = e end
    end
    self.load_report = M.report(self.sim:tally(), { executed = 0, skipped = 0, failed = 0, failed_by_reason = {} })
  end
  if opts.clock then self:set_clock(opts.clock) end
  return self
end

-- What the queued commands did between two sim:tally() readings.
function M.report(now, before)
  local r = {
    executed = now.executed - before.executed,
    skipped = now.skipped - before.skipped,
    failed = now.failed - before.failed,
    first = {},
    reasons = {},
  }
  for i = before.failed + 1, math.min(now.failed, #now.first_failures) do
    if #r.first < M.kFirstShown then r.first[#r.first + 1] = now.first_failures[i] end
  end
  for reason, n in pairs(now.failed_by_reason) do
    local d = n - (before.failed_by_reason[reason] or 0)
    if d > 0 then r.reasons[#r.reasons + 1] = { reason = reason, count = d } end
  end
  table.sort(r.reasons, function(a, b)
    if a.count ~= b.count then return a.count > b.count end
    return a.reason < b.reason
  end)
  return r
end

-- Diffs the pairs of `list` ({own =, intruder =, ...}) against the known set
-- `known` (key -> true); appends an event when one starts (start(c, key)
-- gives its text) or ends; returns the new set.
local function diff(known, list, t, events, kind, start, ended)
  local now = {}
  for _, c in ipairs(list) do
    local key, a, b = pair_key(c.own, c.intruder)
    if not now[key] then
      now[key] = true
      if not known[key] then
        events[#events + 1] = { t = t, kind = kind, own = a, intruder = b, text = start(c, key) }
      end
    end
  end
  for key in pairs(known) do
    if not now[key] then
      local a, b = key:match("^(.-) & (.*)$")
      events[#events + 1] = { t = t, kind = kind .. "_end", own = a, intruder = b, text = string.format(ended, key) }
    end
  end
  return now
end

-- The detector's conflicts and losses of separation. At t = 0 the detector
-- has not run yet (it runs as the clock steps), so they are read from a copy
-- of the simulation stepped once: a paused start shows what is predicted.
function Session:detected()
  if self.sim:time() > 0 then return self.sim:conflicts(), self.sim:los() end
  local probe = self.sim:copy()
  probe:step()
  return probe:conflicts(), probe:los()
end

-- The smallest of kReminders at or above tlos [s], or nil.
local function reminder_level(tlos)
  local level
  for _, th in ipairs(M.kReminders) do
    if tlos > 0 and tlos <= th then level = th end
  end
  return level
end

-- Compares the detector's conflicts and losses of separation with the known
-- ones; a known conflict whose tLOS falls to a kReminders mark is announced
-- again (kind "conflict_reminder"), once per mark.
function Session:diff_pairs(events)
  local t = self.sim:time()
  local known = self.conflicts
  local text = function(c, key)
    return string.format("conflict %s: loss of separation in %.0f s, closest %.2f NM in %.0f s", key, c.tlos_s or 0 / 0,
      c.dcpa_nm, c.tcpa_s)
  end
  local conflicts, los = self:detected()
  self.conflicts = diff(known, conflicts, t, events, "conflict", text, "conflict %s ended")
  local reminded, before = {}, self.reminded or {}
  for _, c in ipairs(conflicts) do
    local key, a, b = pair_key(c.own, c.intruder)
    if reminded[key] == nil then
      local level, prev = reminder_level(c.tlos_s or math.huge), before[key]
      if known[key] and level and (not prev or level < prev) then
        events[#events + 1] = { t = t, kind = "conflict_reminder", own = a, intruder = b, text = "still " .. text(c, key) }
        prev = level
      end
      reminded[key] = known[key] and (prev or false) or (level or false)
    end
  end
  self.reminded = reminded
  self.los = diff(self.los, los, t, events, "los", function(l, key)
    return string.format("LOSS OF SEPARATION %s: %.2f NM, %.0f ft apart", key, l.dist_nm, math.abs(l.dalt_ft))
  end, "separation regained %s")
  -- Detections that hit the pair cap: said once (again after a RESET).
  local capped = self.sim:totals().capped
  if capped and not self.cap_noted then events[#events + 1] = { t = t, kind = "conflict_cap", text = capped } end
  self.cap_noted = capped ~= nil
end

-- Moves ECHO output into events and queued-command failures into `failures`.
function Session:collect_output(events, failures)
  for _, line in ipairs(self.sim:output()) do
    if line:match("^t=[%d%.]+ s: ") then
      failures[#failures + 1] = line
    else
      events[#events + 1] = { t = self.sim:time(), kind = "echo", text = line }
    end
  end
end

-- Advances `seconds` of sim time in chunks, reporting what happened; the
-- failures of queued commands come last, as one summary event.
-- Runs `seconds` of sim time, or until os.clock() passes `deadline` (optional).
function Session:advance(seconds, events, deadline)
  local tally, failures = self.sim:tally(), {}
  local t_end = self.sim:time() + seconds
  repeat
    local left = t_end - self.sim:time()
    -- At least one step per chunk: with DT above 2 * kChunk a chunk shorter
    -- than a step would never move the clock.
    self.sim:run_for(math.max(0, math.min(math.max(M.kChunk, self.sim:dt()), left)))
    self:collect_output(events, failures)
    self:diff_pairs(events)
  until t_end - self.sim:time() < 0.5 * self.sim:dt() or (deadline and os.clock() > deadline)
  if #failures > 0 then
    local r = M.report(self.sim:tally(), tally)
    r.failed = #failures
    r.first = { table.unpack(failures, 1, math.min(#failures, M.kFirstShown)) }
    local text = string.format("%d scenario command%s failed", r.failed, r.failed == 1 and "" or "s")
    events[#events + 1] = { t = self.sim:time(), kind = "failure", text = text, report = r }
  end
  return events
end

function Session:run(seconds)
  return self:advance(seconds, {})
end

-- Fast-time with an end: run to it now; then a clock running before FF runs
-- on at real time (OP: DTMULT 1, as BlueSky's FF end), a held one stays held.
-- At most kMaxFfCpu of processor time per call: a longer FF stays in
-- fast-time and goes on at the next call (the session's tick), so one
-- "FF 1e9" cannot hold the simulation's thread for days.
function Session:finish_fast_forward(events, resume, cpu_s)
  local state, ff_end = self.sim:run_state()
  if state ~= "ff" or not ff_end then return nil end
  self.ff_resume = resume or self.ff_resume or "op"
  local t0 = self.sim:time()
  self:advance(math.max(0, ff_end - t0), events, os.clock() + (cpu_s or M.kMaxFfCpu))
  if ff_end - self.sim:time() >= 0.5 * self.sim:dt() then
    return string.format("fast-forwarding: t = %.1f s -> %.1f s of %.1f s (goes on while the session runs; HOLD stops it)",
      t0, self.sim:time(), ff_end)
  end
  -- OP ends fast-time at real time (DTMULT 1), as BlueSky's FF end does;
  -- a clock held before FF stays held.
  self.sim:exec(self.ff_resume == "op" and "OP" or "HOLD")
  self.ff_resume = nil
  return string.format("fast-forwarded %.0f s: t = %.1f s -> %.1f s", self.sim:time() - t0, t0, self.sim:time())
end

function Session:clock_text()
  local state, ff_end = self.sim:run_state()
  if state == "hold" then
    return "clock stopped (HOLD; OP runs it in real time): time moves with :run and FF"
  end
  if state == "ff" then
    return ff_end and string.format("fast-time until t = %.0f s", ff_end)
      or string.format("fast-time until HOLD or OP (%g x real time)", M.kOpenFfRate)
  end
  return string.format("clock running at %g x real time", self.sim:dtmult())
end

function Session:set_clock(multiplier)
  if multiplier == nil then
    self.sim:exec("HOLD")
  else
    self.sim:exec("OP")  -- OP sets DTMULT 1 (as BlueSky): the multiplier comes after it
    local ok, msg = self.sim:exec("DTMULT " .. multiplier)
    if not ok then return msg end
  end
  return self:clock_text()
end

function Session:tick(wall_s)
  wall_s = math.min(wall_s, M.kMaxTickWall)
  local events = {}
  local state, ff_end = self.sim:run_state()
  if state == "op" then
    self:advance(wall_s * self.sim:dtmult(), events)
  elseif state == "ff" and ff_end then
    self:finish_fast_forward(events)
  elseif state == "ff" then
    self:advance(wall_s * M.kOpenFfRate, events)
  end
  return events
end

-- Whether a TrafScript line sets the run state (OP, HOLD, FF, DTMULT or an alias).
local clock_commands = { OP = true, HOLD = true, FF = true, DTMULT = true }
local function clock_command(line)
  local first = line:match("^%s*([%w_]+)")
  return first ~= nil and clock_commands[nodes.canonical_name(first) or ""] == true
end

local function words_upper(line)
  local w = {}
  for word in line:gmatch("[^%s,;]+") do w[#w + 1] = word:upper() end
  return w
end

function Session:run_commands(cmds, reply)
  local before = {}
  for _, a in ipairs(self.sim:aircraft()) do before[a.id] = true end
  local touched = {}
  local state_before = self.sim:run_state()
  local clock_changed = false
  for i, c in ipairs(cmds) do
    local ok, msg = self.sim:exec(c)
    reply.results[#reply.results + 1] = { cmd = c, ok = ok, message = msg or "" }
    if not ok then break end
    clock_changed = clock_changed or clock_command(c)
    for _, w in ipairs(words_upper(c)) do
      if self.sim:get(w) then touched[w] = true end
    end
    -- ("FF 120 ; HOLD", fast-forward two minutes, then hold: a fast-forward with an end said before another clock
    -- command runs to its end first, as said; the clock command would end it at once)
    local later = false
    for k = i + 1, #cmds do later = later or clock_command(cmds[k]) end
    local state, ff_end = self.sim:run_state()
    if later and state == "ff" and ff_end then
      self:finish_fast_forward(reply.events, state_before == "op" and "op" or "hold", M.kMaxFfCpuBefore)
    end
  end
  -- Commands due now (IC, a scenario's first lines) run before anything is shown.
  self:advance(0, reply.events)
  local state = self.sim:run_state()
  if state == "ff" then
    local _, ff_end = self.sim:run_state()
    if ff_end then
      reply.clock = self:finish_fast_forward(reply.events, state_before == "op" and "op" or "hold")
    else
      reply.clock = self:clock_text()
    end
  elseif clock_changed or state ~= state_before then
    reply.clock = self:clock_text()
  end
  for _, a in ipairs(self.sim:aircraft()) do
    if touched[a.id] or not before[a.id] then reply.touched[#reply.touched + 1] = a.id end
    before[a.id] = nil
  end
  for id in pairs(before) do reply.deleted[#reply.deleted + 1] = id end
  table.sort(reply.deleted)
end

-- The dialogue of `client` (nil: the session's own), made on first use; of
-- more than kMaxDialogues clients the one unheard from longest is forgotten
-- (a page reloaded many times must not grow the session without end).
function Session:dialogue_for(client)
  if client == nil or client == "" then return self.dialogue end
  self.heard = (self.heard or 0) + 1
  local d = self.dialogues[client]
  if not d then
    d = graph.dialogue({ sim = self.sim, mode = self.mode })
    self.dialogues[client] = d
    self.ndialogues = (self.ndialogues or 0) + 1
    if self.ndialogues > M.kMaxDialogues then
      local oldest, when = nil, math.huge
      for key, other in pairs(self.dialogues) do
        if other ~= d and other.heard < when then oldest, when = key, other.heard end
      end
      self.dialogues[oldest] = nil
      self.ndialogues = self.ndialogues - 1
    end
  end
  d.heard = self.heard
  return d
end

-- Whether a word of `text` is the callsign of an aircraft in the simulation.
function Session:names_aircraft(text)
  for _, w in ipairs(words_upper(text)) do
    if self.sim:get(w) then return true end
  end
  return false
end

-- The translation of an English line through dialogue d: d:say(text), and, when that asks or
-- fails and the line names no aircraft, d:say("SELECTED text"). Returns ok, r as pcall gives
-- them, and the callsign put in front (nil when none). Runs inside squawk.translate.request.
local function translate_line(self, d, text, opts)
  local pending = d.pending
  local ok, r = pcall(d.say, d, text)
  local sel = opts and opts.selected
  if ok and (r.ask or r.error) and not pending and sel and self.sim:get(sel) and not self:names_aircraft(text) then
    local asked = d.pending
    d.pending = nil
    local ok2, r2 = pcall(d.say, d, sel .. " " .. text)
    if ok2 and not r2.error then return ok2, r2, sel end
    d.pending = asked
  end
  return ok, r, nil
end

function Session:command(text, opts)
  text = text:gsub("^%s+", ""):gsub("%s+$", "")
  local reply = { text = text, commands = {}, results = {}, events = {}, touched = {}, deleted = {} }
  if text:sub(1, 1) == "!" then
    reply.kind = "trafscript"
    if text:sub(2):match("^%s*$") then
      reply.error = "nothing to run: type TrafScript after !, e.g. !HDG KL204 270"
      return reply
    end
    reply.commands = { text:sub(2) }
    self:run_commands(reply.commands, reply)
    return reply
  end
  reply.kind = "english"
  if text == "" then return reply end
  local d = self:dialogue_for(opts and opts.client)
  -- One request for the collector (stopped while it translates); the commands run after it.
  local ok, r
  ok, r, reply.addressed = squawk.translate.request(translate_line, self, d, text, opts)
  if not ok then
    d.pending = nil
    reply.error = "the translator failed: " .. tostring(r) .. " (nothing ran; the simulation is unchanged)"
    return reply
  end
  self.last = r
  reply.trace, reply.note = r.trace, r.note
  if r.ask then
    reply.ask, reply.ignorable = r.ask, r.ignorable
    return reply
  end
  if r.cancelled ~= nil then
    reply.cancelled, reply.cancel_note = r.cancelled, r.said
    return reply
  end
  if r.error then
    reply.error = r.error
    return reply
  end
  reply.commands = r.commands
  self:run_commands(r.commands, reply)
  return reply
end

function Session:state()
  local st = { simt = self.sim:time(), aircraft = self.sim:aircraft(), conflicts = {}, los = {} }
  local state, ff_end = self.sim:run_state()
  st.clock = { state = state, multiplier = self.sim:dtmult(), ff_end = ff_end }
  local with = {}
  local conflicts, los = self:detected()
  for _, c in ipairs(conflicts) do
    if c.own < c.intruder then
      st.conflicts[#st.conflicts + 1] = c
      with[c.own] = with[c.own] or {}
      with[c.intruder] = with[c.intruder] or {}
      table.insert(with[c.own], c.intruder)
      table.insert(with[c.intruder], c.own)
    end
  end
  table.sort(st.conflicts, function(x, y) return (x.tlos_s or math.huge) < (y.tlos_s or math.huge) end)
  for _, l in ipairs(los) do
    if l.own < l.intruder then st.los[#st.los + 1] = l end
  end
  for _, a in ipairs(st.aircraft) do a.conflict = with[a.id] or {} end
  return st
end

M.meta_commands = { ":help", ":state", ":run", ":clock", ":trace", ":mode", ":quit" }

function Session:complete(prefix)
  local bang = prefix:sub(1, 1) == "!"
  local p = (bang and prefix:sub(2) or prefix):upper()
  local seen, out = {}, {}
  local function add(word, shown)
    if word:upper():sub(1, #p) == p and not seen[shown] then
      seen[shown] = true
      out[#out + 1] = shown
    end
  end
  if prefix:sub(1, 1) == ":" then
    for _, m in ipairs(M.meta_commands) do
      if m:sub(1, #prefix) == prefix then out[#out + 1] = m end
    end
    return out
  end
  for _, a in ipairs(self.sim:aircraft()) do add(a.id, (bang and "!" or "") .. a.id) end
  for _, c in ipairs(squawk.sim.commands()) do
    add(c.name, (bang and "!" or "") .. c.name)
    for _, alias in ipairs(c.aliases) do add(alias, (bang and "!" or "") .. alias) end
  end
  table.sort(out)
  return out
end

M.Session = Session
return M
