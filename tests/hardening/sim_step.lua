-- Point 6: long C calls are charged to the budget.
local s = squawk.sim.new{}
s:exec("CRE KL2 B738 52 4 90 FL200 250")
s[arg[1]](s, tonumber(arg[2]))
