-- Point 6: short coroutines must not escape the instruction budget.
while true do
  coroutine.resume(coroutine.create(function() for _ = 1, 100 do end end))
end
