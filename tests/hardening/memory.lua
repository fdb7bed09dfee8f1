-- Issue 52 point 3: a script that grows its heap without end meets --max-memory.
local t = {}
for i = 1, 1e9 do t[i] = ("x"):rep(100) .. i end
