-- Point 6: a coroutine that catches the limit error does not reset it.
local n = 0
while true do
  local co = coroutine.wrap(function() while true do n = n + 1 end end)
  pcall(co)
end
