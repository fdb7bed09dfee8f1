-- The text front end of `squawk repl`: a translate.session (the session
-- logic: simulation, dialogue, commands, results, conflicts, echo lines,
-- running clock; `squawk serve` calls the same session) formatted as lines.
--
--   repl.new{scenario =, mode =, seed =, clock =} -> r   (as session.new;
--       r.session is the session)
--   r:handle(line) -> text to print, quit (boolean)
--   r:tick(wall_s) -> text of what happened while the running clock moved
--       ("" when nothing did); the C++ loop calls it between keystrokes
--   r:opening()    -> what loading the scenario did ("" without a scenario)
--   r:banner()     -> greeting for interactive use
--   r:complete(prefix) -> completions of the word being typed
-- Lines: English text is translated and run; `!CMD` runs raw TrafScript;
-- `:help`, `:state`, `:run SECONDS`, `:clock [X|off]`, `:trace`, `:mode M`,
-- `:quit`. Translation never changes the simulation; only the shown
-- commands do.
local graph = require("translate.graph")
local session = require("translate.session")

local M = {}
local Repl = {}
Repl.__index = Repl

local HELP = [[
  English text      translate to TrafScript, show it, run it, show what changed
  !CMD              run TrafScript as typed, e.g. !HDG KL204 270, !FF 300, !HOLD
  :state            the clock, the aircraft (current -> selected values, route, AT ... DO commands)
                    and the conflicts (tLOS, tCPA, dCPA)
  :run SECONDS      advance the simulation now, reporting conflicts and ECHO lines
  :clock X | off    run the clock at X times real time (OP), or stop it (HOLD)
  :trace            the translation graph's path for the last request
  :mode M           translation mode: offline, single or multi
  :help             this text
  :quit             leave (end of input does too); quit, exit and help work
                    without the colon
  A question back (?) is answered by the next line; "cancel" drops it.
  Tab completes callsigns and commands; Ctrl-C clears the line.]]

function M.new(opts)
  return setmetatable({ session = session.new(opts) }, Repl)
end

local function fmt_speed(a)
  if a.sel_mach then return string.format("M%.2f", a.sel_mach) end
  return string.format("%.0f kt", a.sel_cas_kt or 0)
end

-- One aircraft: current values, "-> selected" where the autopilot is going elsewhere.
local function fmt_aircraft(a)
  local s = string.format("  %-8s %-4s %8.4f %9.4f  hdg %5.1f", a.id, a.type or "?", a.lat, a.lon, a.hdg_deg)
  if a.lnav and a.active_wpt then
    s = s .. " -> " .. a.active_wpt
  elseif a.sel_hdg_deg and math.abs((a.sel_hdg_deg - a.hdg_deg + 180) % 360 - 180) > 0.5 then
    s = s .. string.format(" -> %.0f", a.sel_hdg_deg) .. (a.sel_turn and (" " .. a.sel_turn) or "")
  end
  s = s .. string.format("  alt %6.0f ft", a.alt_ft)
  if a.sel_alt_ft and math.abs(a.sel_alt_ft - a.alt_ft) > 10 then
    s = s .. string.format(" -> %.0f", a.sel_alt_ft)
  end
  s = s .. string.format("  CAS %4.0f kt", a.cas_kt)
  if a.sel_mach or (a.sel_cas_kt and math.abs(a.sel_cas_kt - a.cas_kt) > 1) then
    s = s .. " -> " .. fmt_speed(a)
  end
  s = s .. string.format("  VS %5.0f fpm", a.vs_fpm or 0)
  if a.resolving then s = s .. "  MVP" end
  if a.conflict and #a.conflict > 0 then s = s .. "  CONFLICT " .. table.concat(a.conflict, ",") end
  if a.route and #a.route > 0 then
    local names = {}
    for _, w in ipairs(a.route) do
      names[#names + 1] = w.name .. (w.name == a.active_wpt and "*" or "")
    end
    s = s .. "\n      route " .. table.concat(names, " ") .. (a.lnav and "  (LNAV on, * active)" or "  (LNAV off)")
    -- the commands a waypoint runs when passed (AT acid wp DO), in order
    for _, w in ipairs(a.route) do
      if w.commands and #w.commands > 0 then
        s = s .. "\n      at " .. w.name .. " do: " .. table.concat(w.commands, "; ")
      end
    end
  end
  return s
end

local function fmt_time(t)
  return string.format("[t=%6.0f s]", t)
end

function M.format_events(events)
  local out = {}
  for _, e in ipairs(events) do
    out[#out + 1] = "  " .. fmt_time(e.t) .. " " .. e.text
    if e.report then
      for _, x in ipairs(e.report.reasons) do out[#out + 1] = string.format("      %6d  %s", x.count, x.reason) end
      for _, f in ipairs(e.report.first) do out[#out + 1] = "      " .. f end
      if e.report.failed > #e.report.first then
        out[#out + 1] = string.format("      ... %d more", e.report.failed - #e.report.first)
      end
    end
  end
  return table.concat(out, "\n")
end

local function fmt_report(r)
  local lines = { string.format("  scenario commands so far: %d executed, %d skipped, %d failed",
    r.executed, r.skipped, r.failed) }
  for _, x in ipairs(r.reasons) do lines[#lines + 1] = string.format("    %6d  %s", x.count, x.reason) end
  if #r.first > 0 then lines[#lines + 1] = "  first failures:" end
  for _, f in ipairs(r.first) do lines[#lines + 1] = "    " .. f end
  return table.concat(lines, "\n")
end

function Repl:state_text()
  local st = self.session:state()
  local lines = { string.format("  t = %.1f s, %d aircraft, %s", st.simt, #st.aircraft, self.session:clock_text()) }
  for _, a in ipairs(st.aircraft) do lines[#lines + 1] = fmt_aircraft(a) end
  if #st.conflicts == 0 then
    lines[#lines + 1] = "  conflicts: none"
  else
    lines[#lines + 1] = string.format("  conflicts: %d   %-17s %8s %8s %9s %9s", #st.conflicts, "pair",
      "tLOS", "tCPA", "dCPA", "now")
    for _, c in ipairs(st.conflicts) do
      lines[#lines + 1] = string.format("               %-17s %6.0f s %6.0f s %6.2f NM %6.2f NM",
        c.own .. " & " .. c.intruder, c.tlos_s or 0 / 0, c.tcpa_s, c.dcpa_nm, c.dist_nm)
    end
  end
  for _, l in ipairs(st.los) do
    lines[#lines + 1] = string.format("  LOSS OF SEPARATION %s & %s: %.2f NM, %.0f ft", l.own, l.intruder, l.dist_nm,
      math.abs(l.dalt_ft))
  end
  return table.concat(lines, "\n")
end

function Repl:opening()
  local s = self.session
  if not s.load_report then return "" end
  local text = fmt_report(s.load_report)
  local ev = M.format_events(s.load_events or {})
  return ev ~= "" and (text .. "\n" .. ev) or text
end

function Repl:banner()
  local llm = self.session.mode ~= "offline" and squawk.llm.from_env() or nil
  return "squawk repl: English or !TrafScript; :help for more. Translator: "
    .. (llm and llm:describe() or "offline grammar (set SQUAWK_LLM_URL for an LLM)")
end

function Repl:complete(prefix)
  return self.session:complete(prefix)
end

function Repl:tick(wall_s)
  return M.format_events(self.session:tick(wall_s))
end

-- The reply of one command as lines.
function Repl:format_reply(r)
  if r.ask and r.ignorable then return "? " .. r.ask .. "   (answer, say ignore if it means nothing, or cancel)" end
  if r.ask then return "? " .. r.ask .. "   (answer, or say cancel)" end
  if r.cancelled then return "  cancelled (" .. (r.cancel_note or "dropped the question") .. ")" end
  if r.cancelled == false then return "  nothing to cancel: no question was pending" end
  if r.error and r.kind == "trafscript" then return "  " .. r.error end
  if r.error then return "  could not translate: " .. r.error .. "\n  (:trace shows how it went)" end
  local out = {}
  if r.kind == "english" and #r.commands > 0 then out[1] = "> " .. table.concat(r.commands, " ; ") end
  if r.note then out[#out + 1] = "  " .. r.note end
  for _, res in ipairs(r.results) do
    if not res.ok then
      out[#out + 1] = "  error: " .. res.message
    elseif res.message ~= "" then
      out[#out + 1] = "  " .. res.message:gsub("\n", "\n  ")
    elseif r.kind == "trafscript" then
      out[#out + 1] = "  ok: " .. res.cmd
    end
  end
  if r.clock then out[#out + 1] = "  " .. r.clock end
  local ev = M.format_events(r.events)
  if ev ~= "" then out[#out + 1] = ev end
  if #r.touched > 0 then
    local set = {}
    for _, id in ipairs(r.touched) do set[id] = true end
    for _, a in ipairs(self.session:state().aircraft) do
      if set[a.id] then out[#out + 1] = fmt_aircraft(a) end
    end
  end
  for _, id in ipairs(r.deleted) do out[#out + 1] = "  deleted " .. id end
  return table.concat(out, "\n")
end

function Repl:meta(cmd, arg)
  local s = self.session
  if cmd == "help" then return HELP end
  if cmd == "state" then return self:state_text() end
  if cmd == "trace" then
    return s.last and graph.format_trace(s.last.trace) or "  no request yet"
  end
  if cmd == "run" then
    local secs = tonumber(arg)
    if not secs or secs < 0 or secs > 86400 then
      return "  :run expects a number of seconds from 0 to 86400, e.g. :run 60"
    end
    local ev = M.format_events(s:run(secs))
    return (ev ~= "" and (ev .. "\n") or "") .. self:state_text()
  end
  if cmd == "clock" then
    if arg == "" then return "  " .. s:clock_text() end
    if arg == "off" then return "  " .. s:set_clock(nil) end
    local x = tonumber(arg)
    if not x or x <= 0 or x > 1000 then return "  :clock expects a multiplier of real time (0 to 1000] or off" end
    return "  " .. s:set_clock(x)
  end
  if cmd == "mode" then
    if not graph.modes[arg] then return "  :mode expects offline, single or multi" end
    if arg ~= "offline" then
      local llm, why = squawk.llm.from_env()
      if not llm then
        return "  :mode " .. arg .. " needs an LLM server: " .. tostring(why)
          .. "; set SQUAWK_LLM_URL or start the repl with --llm-url. The mode stays " .. (s.mode or "offline") .. "."
      end
    end
    s.mode = arg
    s.dialogue.opts.mode = arg
    return "  mode " .. arg
  end
  return "  unknown command ':" .. tostring(cmd) .. "'; :help lists them"
end

function Repl:handle(line)
  line = line:gsub("^%s+", ""):gsub("%s+$", "")
  if line == "" then return "", false end
  local word = line:lower()
  if word == "quit" or word == "exit" then return "", true end
  if word == "help" then return HELP, false end
  if line:sub(1, 1) == ":" then
    local cmd, arg = line:match("^:(%S+)%s*(.*)$")
    if cmd == "quit" or cmd == "q" or cmd == "exit" then return "", true end
    return self:meta(cmd, arg or ""), false
  end
  return self:format_reply(self.session:command(line)), false
end

M.Repl = Repl
return M
