-- The session behind `squawk serve`: one simulation and one conversation with
-- the translation graph, driven command by command from C++
-- (engine/script/serve_session.h). Kept small on purpose: the REPL session
-- (translate.repl) and this one share the graph and the squawk.sim API.
--
--   session.new{scenario = path|nil, mode = "offline"|"single"|"multi"|nil, seed = n}
--       -> session (raises when the scenario does not load); session.sim is
--          the squawk.sim the server flies.
--   session:command(text) -> reply
--       text "!CMD" runs TrafScript as typed; anything else is English for
--       the graph (a pending question is answered by the next text, "cancel"
--       drops it). reply = { text = what was typed, commands = { TrafScript
--       lines }, ok = boolean, message = output or the first error,
--       ask = question (nothing ran), cancelled = boolean, trace = text }.
-- Commands run in order and stop at the first failure (earlier ones keep
-- their effect; the failing one leaves the simulation as it was).
local graph = require("translate.graph")

local M = {}
local Session = {}
Session.__index = Session

local function trim(s)
  return (s:gsub("^%s+", ""):gsub("%s+$", ""))
end

function M.new(opts)
  opts = opts or {}
  local self = setmetatable({ sim = squawk.sim.new({ seed = opts.seed or 0 }) }, Session)
  self.dialogue = graph.dialogue({ sim = self.sim, mode = opts.mode })
  if opts.scenario and opts.scenario ~= "" then
    local ok, msg = self.sim:load(opts.scenario)
    if not ok then error("serve: scenario '" .. opts.scenario .. "' did not load: " .. msg, 0) end
  end
  return self
end

-- Runs TrafScript lines on the simulation; ok and the joined output, or false
-- and the first error.
function Session:run(cmds)
  local out = {}
  for _, c in ipairs(cmds) do
    local ok, msg = self.sim:exec(c)
    if not ok then return false, msg end
    if msg and msg ~= "" then out[#out + 1] = msg end
  end
  return true, table.concat(out, "\n")
end

function Session:command(text)
  text = trim(text)
  if text == "" then return { text = text, commands = {}, ok = false, message = "empty command" } end
  if text:sub(1, 1) == "!" then
    local line = trim(text:sub(2))
    local ok, msg = self:run({ line })
    return { text = text, commands = { line }, ok = ok, message = msg }
  end
  local r = self.dialogue:say(text)
  local reply = { text = text, commands = r.commands or {}, cancelled = r.cancelled or false,
                  trace = graph.format_trace(r.trace) }
  if r.ask then
    reply.ok, reply.ask = false, r.ask
  elseif r.error then
    reply.ok, reply.message = false, "could not translate: " .. r.error
  elseif r.cancelled then
    reply.ok, reply.message = true, "question dropped"
  else
    reply.ok, reply.message = self:run(reply.commands)
  end
  return reply
end

M.Session = Session
return M
