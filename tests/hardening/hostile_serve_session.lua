-- Issue 52 point 2: a translate.session module whose replies hold tables that
-- raise when C++ reads them (ServeSession, squawk serve). command(text)
-- returns, by text: "reply" a reply whose every field raises; "commands" a
-- commands list whose length raises; "results" a result whose fields raise;
-- "events" an event whose fields raise. tick() returns an events list whose
-- length raises. Every one must come back as an error Status.
local function raising() return setmetatable({}, {__index = function() error({}) end}) end
local M = {}
function M.new()
  local s = { sim = squawk.sim.new{} }
  function s.command(_, text)
    if text == "reply" then return raising() end
    if text == "commands" then return { commands = setmetatable({}, {__len = function() error(nil) end}) } end
    if text == "results" then return { commands = { "ECHO hi" }, results = { raising() } } end
    if text == "events" then return { commands = { "ECHO hi" }, events = { raising() } } end
    return { commands = { "ECHO hi" }, results = { { ok = true, message = "" } } }
  end
  function s.tick() return setmetatable({}, {__len = function() error(42) end}) end
  return s
end
return M
