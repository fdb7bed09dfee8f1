-- Point 17: prints the home squawk found and checks its files are there.
print("home=" .. squawk.home)
local f = assert(io.open(squawk.home .. "/prompts/observation.lua"))
f:close()
local env = squawk.env.new(squawk.home .. "/scenarios/horizontal_cr.lua")
print("ok")
