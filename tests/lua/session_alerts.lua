-- Alerts that stay until resolved: a standing conflict is announced when it
-- starts and again when its time to loss of separation falls to 120 s and
-- to 60 s (session.kReminders), once each.
local repl = require("translate.repl")

local function count(text, what)
  local n = 0
  for _ in text:gmatch(what) do n = n + 1 end
  return n
end

do
  local r = repl.new({ mode = "offline" })
  r:handle("!CRE BAW1 B744 52 3.2 90 FL300 280")
  r:handle("!CRE DLH2 A320 52 4.8 270 FL300 280")
  local text = r:handle("!ASAS ON")  -- predicted at once (t = 0, clock held): LoS in 2xx s
  check(text:match("%] conflict BAW1 & DLH2: loss of separation in 2%d%d s") ~= nil, text)
  text = r:handle(":run 250")
  check(text:match("still conflict BAW1 & DLH2: loss of separation in 1[012]%d s") ~= nil, text)
  check(text:match("still conflict BAW1 & DLH2: loss of separation in [56]%d s") ~= nil, text)
  check_eq(count(text, "still conflict"), 2)
  check(text:find("LOSS OF SEPARATION BAW1 & DLH2", 1, true) ~= nil, text)
  text = r:handle(":run 100")
  check(text:find("conflict BAW1 & DLH2 ended", 1, true) ~= nil, text)
  check_eq(count(text, "still conflict"), 0)
end
