-- squawk.sim loading a shipped .scn: timed commands, conditions, resolution.
local sim = squawk.sim.new{}
local ok, msg = sim:load(squawk.home .. "/scenarios/demo_conflict.scn")
check(ok, msg)
check_eq(sim:count(), 2)
check_eq(sim:time(), 0)

sim:run_until(10)
-- MVP is on: the crossing pair was detected and is being resolved, so
-- KL204 deviates from its initial heading (90 deg).
check_eq(sim:totals().conflicts, 1)
check(math.abs(sim:get("KL204").hdg_deg - 90) > 1, "KL204 turned away")

sim:run_until(600)
local out = sim:output()
check_eq(out[1], "one minute: resolution under way")
check_eq(out[2], "KL204 is within 10 NM of EXIT1")
check_eq(out[3], "end of the demo")
check_eq(sim:totals().los, 0)

-- A missing file is an error message, not a crash.
ok, msg = sim:load("no_such_file.scn")
check(not ok)
check(msg:find("no scenario file", 1, true) ~= nil, msg)
