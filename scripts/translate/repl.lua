-- The REPL session behind `squawk repl`: one simulation, English in,
-- TrafScript shown and executed, the changed state shown.
--
--   repl.new{scenario = path|nil, mode = "offline"|"single"|"multi"|nil, seed = n}
--       -> session (raises when the scenario does not load)
--   session:handle(line) -> text to print, quit (boolean)
--   session:banner()     -> greeting for interactive use
-- Lines: English text is translated (translate.graph) and run; `!CMD` runs
-- raw TrafScript; `:help`, `:state`, `:run SECONDS`, `:trace`, `:mode M`,
-- `:quit`. Translation never changes the simulation; only the shown commands do.
local graph = require("translate.graph")

local M = {}
local Session = {}
Session.__index = Session

local HELP = [[
  English text      translate to TrafScript, show it, run it, show what changed
  !CMD              run TrafScript as typed, e.g. !HDG KL204 270
  :state            list the aircraft and the simulation time
  :run SECONDS      advance the simulation, then list the aircraft
  :trace            the translation graph's path for the last request
  :mode M           translation mode: offline, single or multi
  :help             this text
  :quit             leave (end of input does too)]]

function M.new(opts)
  opts = opts or {}
  local self = setmetatable({ sim = squawk.sim.new({ seed = opts.seed or 0 }), mode = opts.mode }, Session)
  self.dialogue = graph.dialogue({ sim = self.sim, mode = self.mode })
  if opts.scenario and opts.scenario ~= "" then
    local ok, msg = self.sim:load(opts.scenario)
    if not ok then error("repl: scenario '" .. opts.scenario .. "' did not load: " .. msg, 0) end
  end
  return self
end

local function fmt_aircraft(a)
  return string.format("  %-8s %-4s %8.4f %9.4f  hdg %5.1f  alt %6.0f ft  CAS %4.0f kt  VS %5.0f fpm",
    a.id, a.type or "?", a.lat, a.lon, a.hdg_deg, a.alt_ft, a.cas_kt, a.vs_fpm or 0)
end

function Session:state_text()
  local lines = { string.format("  t = %.1f s, %d aircraft", self.sim:time(), self.sim:count()) }
  for _, a in ipairs(self.sim:aircraft()) do lines[#lines + 1] = fmt_aircraft(a) end
  return table.concat(lines, "\n")
end

function Session:banner()
  local llm = self.mode ~= "offline" and squawk.llm.from_env() or nil
  return "squawk repl: English or !TrafScript; :help for more. Translator: "
    .. (llm and llm:describe() or "offline grammar (set SQUAWK_LLM_URL for an LLM)")
end

-- Runs command lines on the real sim; returns the report and what changed.
function Session:run_commands(cmds)
  local before = {}
  for _, a in ipairs(self.sim:aircraft()) do before[a.id:upper()] = a end
  local out = {}
  local touched = {}
  for _, c in ipairs(cmds) do
    local ok, msg = self.sim:exec(c)
    if not ok then
      out[#out + 1] = "  error: " .. msg
      break
    end
    if msg and msg ~= "" then out[#out + 1] = "  " .. msg:gsub("\n", "\n  ") end
    for word in c:gmatch("%S+") do touched[word:upper()] = true end
  end
  local after = {}
  for _, a in ipairs(self.sim:aircraft()) do
    local id = a.id:upper()
    after[id] = true
    if not before[id] then
      out[#out + 1] = "  created" .. fmt_aircraft(a):sub(2)
    elseif touched[id] then
      out[#out + 1] = fmt_aircraft(a)
    end
  end
  for id in pairs(before) do
    if not after[id] then out[#out + 1] = "  deleted " .. id end
  end
  return table.concat(out, "\n")
end

function Session:handle(line)
  line = line:gsub("^%s+", ""):gsub("%s+$", "")
  if line == "" then return "", false end
  if line:sub(1, 1) == "!" then
    return self:run_commands({ line:sub(2) }), false
  end
  if line:sub(1, 1) == ":" then
    local cmd, arg = line:match("^:(%S+)%s*(.*)$")
    if cmd == "quit" or cmd == "q" or cmd == "exit" then return "", true end
    if cmd == "help" then return HELP, false end
    if cmd == "state" then return self:state_text(), false end
    if cmd == "trace" then
      return self.last and graph.format_trace(self.last.trace) or "  no request yet", false
    end
    if cmd == "run" then
      local s = tonumber(arg)
      if not s or s < 0 or s > 86400 then
        return "  :run expects a number of seconds from 0 to 86400, e.g. :run 60", false
      end
      self.sim:run_for(s)
      return self:state_text(), false
    end
    if cmd == "mode" then
      if not graph.modes[arg] then return "  :mode expects offline, single or multi", false end
      self.mode = arg
      self.dialogue.opts.mode = arg
      return "  mode " .. arg, false
    end
    return "  unknown command ':" .. tostring(cmd) .. "'; :help lists them", false
  end
  local r = self.dialogue:say(line)
  self.last = r
  if r.ask then return "? " .. r.ask, false end
  if r.error then
    return "  could not translate: " .. r.error .. "\n  (:trace shows how it went)", false
  end
  local text = table.concat(r.commands, " ; ")
  return "> " .. text .. "\n" .. self:run_commands(r.commands), false
end

M.Session = Session
return M
