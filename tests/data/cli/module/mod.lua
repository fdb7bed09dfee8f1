-- A module whose function fails on line 7.
local M = {}

function M.run(x)
  local y = x * 2
  if y > 1 then
    error("value too large: " .. y)
  end
  return y
end

return M
