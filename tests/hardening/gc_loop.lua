-- Issue 52 point 3: a finalizer that never ends. Lua runs finalizers with
-- hooks off; squawk runs them in a coroutine, so the budget still stops it,
-- whether it runs at a collection (arg[1] == "collect") or at shutdown.
setmetatable({}, { __gc = function() while true do end end })
if arg[1] == "collect" then collectgarbage() end
print("script done")
