-- Point 1: an LLM client finalized from inside its own on_token callback
-- (reachable only with --unsafe, through the debug library).
local c = squawk.llm.client{ url = arg[1], model = "m" }
local tokens = 0
local reply, err = c:chat("hi", { on_token = function()
  tokens = tokens + 1
  debug.getmetatable(c).__gc(c)
end })
print("tokens " .. tokens .. " reply " .. tostring(reply))
local ok, e = pcall(c.chat, c, "hi")
print("after: " .. tostring(ok) .. " " .. tostring(e))
