-- squawk.translate: the offline grammar, its world views and the corpus scorer.
local tr = squawk.translate

-- No world: absolute instructions translate, relative ones ask.
local r = tr.offline("KLM one two three, climb flight level three five zero")
check_eq(r.commands[1], "ALT KLM123 FL350")
check_eq(r.ask, nil)
r = tr.offline("turn AC01 left 20 degrees")
check_eq(#r.commands, 0)
check(r.ask ~= nil, "a relative turn without a world asks")

-- A squawk.sim object as the world: current heading and spoken callsigns.
local sim = squawk.sim.new()
check(sim:exec("CRE DAL1153 B738 40 -74 90 5000 250"))
r = tr.offline("Delta eleven fifty three turn left twenty degrees", sim)
check_eq(r.commands[1], "HDG DAL1153 70")
check_eq(sim:aircraft()[1].hdg_deg, 90, "the sim is only read")

-- A plain table as the world.
r = tr.offline("Slow AC01 down by 20 knots", { aircraft = { { id = "AC01", cas_kt = 280, hdg_deg = 90 } } })
check_eq(r.commands[1], "SPD AC01 260")
check(not pcall(tr.offline, "climb", { aircraft = { { type = "A320" } } }), "an aircraft without id is an error")
check(not pcall(tr.offline, "climb", 42), "a number is no world")

-- Several instructions, in order; a question when a value is missing.
r = tr.offline("Pause the simulation and delete AC02")
check_eq(table.concat(r.commands, " ; "), "HOLD ; DEL AC02")
check(tr.offline("Change the speed").ask ~= nil)

-- The scorer follows the corpus rules.
check(tr.score("ALT KL1 30000", false, "ALT KL1 FL300"))
check(tr.score("", true, "ASK"))
check(not tr.score("SPD KL1 250", false, "SPD KL1 M0.78"))
check(not pcall(tr.corpus, "/nonexistent/corpus.tsv"), "a missing corpus is an error")
