-- Issue 52 point 2: a translate.repl module whose sessions raise on every
-- method lookup but `opening` (an error object whose __tostring raises):
-- each line typed into the REPL must become a clean error message.
local M = {}
local raising = setmetatable({}, {__tostring = function() error("again") end})
function M.new()
  return setmetatable({}, {__index = function(_, key)
    if key == "opening" then return function() return "hostile session" end end
    error(raising)
  end})
end
return M
