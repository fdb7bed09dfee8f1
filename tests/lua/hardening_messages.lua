-- Error messages name the function and show numbers as numbers (issue 12 point 18).
local s = squawk.sim.new{}
local ok, err = pcall(s.exec, {}, "ECHO x")
check(not ok)
check(tostring(err):find("'squawk.sim.Sim:exec'", 1, true) ~= nil, tostring(err))
ok, err = pcall(squawk.sim.new, 5)
check(tostring(err):find("'squawk.sim.new'", 1, true) ~= nil, tostring(err))
ok, err = pcall(squawk.translate.offline, "KL1 climb FL300", { aircraft = { { id = "KL1", alt_ft = 1e308 } } })
check(not ok and tostring(err):find("field 'alt_ft': expected a number in [-2000, 100000], got 1e+308", 1, true) ~= nil, tostring(err))
ok, err = pcall(squawk.translate.offline, "KL1 turn left heading 270", { aircraft = { { id = "KL1", hdg_deg = 0 / 0 } } })
check(not ok and tostring(err):find("got NaN", 1, true) ~= nil, tostring(err))
ok, err = pcall(squawk.env.evaluate, { scenario = "scenarios/horizontal_cr.lua", episodes = 0 / 0 })
check(not ok and tostring(err):find("got NaN", 1, true) ~= nil, tostring(err))
check(tostring(err):find("-9223372036854775808", 1, true) == nil)
