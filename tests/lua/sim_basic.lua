-- squawk.sim: TrafScript in, aircraft state and conflicts out.
local sim = squawk.sim.new{seed = 1}

local ok, msg = sim:exec("CRE KL204 B744 52.0 4.0 90 FL200 250")
check(ok, msg)
check_eq(sim:count(), 1)

local a = sim:get("KL204")
check_near(a.alt_ft, 20000, 1e-6)
check_near(a.hdg_deg, 90, 1e-9)
check_near(a.cas_kt, 250, 1e-6)

-- A bad argument: an error naming it, nothing changed.
local before = sim:snapshot()
ok, msg = sim:exec("ALT KL204 FL9X")
check(not ok)
check(msg:find("altitude 'FL9X'", 1, true) ~= nil, msg)
check(sim:snapshot() == before, "state unchanged after a failed command")

-- Heading change: turn rate g0 tan(25 deg) / TAS (BlueSky), so 90 deg takes
-- 90 / rate seconds at this TAS.
check(sim:exec("KL204 HDG 180"))
local tas = sim:get("KL204").tas_kt * 0.514444
local rate = math.deg(9.80665 * math.tan(math.rad(25)) / tas)
sim:run_for(10)
check_near(sim:time(), 10, 1e-9)
check_near(sim:get("KL204").hdg_deg, 90 + 10 * rate, 0.5)
sim:run_until(200)
check_near(sim:get("KL204").hdg_deg, 180, 1e-6)

-- Timed commands and ECHO output.
check(sim:exec("DELAY 5 ECHO five seconds later"))
sim:run_for(5)
local out = sim:output()
check_eq(#out, 1)
check_eq(out[1], "five seconds later")

-- A conflict set up with CRECONFS is detected with ASAS on.
check(sim:exec("ASAS ON; CRECONFS INT1 A320 KL204 90 0 120"))
sim:run_for(2)
local c = sim:conflicts()
check_eq(#c, 2)
check_near(c[1].tlos_s, 118, 3)
check(c[1].dcpa_nm < 0.05)

-- Copies are independent.
local scratch = sim:copy()
check(scratch:exec("DEL *"))
check_eq(scratch:count(), 0)
check_eq(sim:count(), 2)

-- The registry is visible from Lua.
local names = {}
for _, cmd in ipairs(squawk.sim.commands()) do names[cmd.name] = cmd end
check(names.CRE ~= nil and names.ADDWPT ~= nil and names.CRECONFS ~= nil)
check_eq(names.HDG.aliases[1], "HEADING")

-- squawk.sim.new{dt_s}: the step in seconds, as TrafScript's DT
local s5 = squawk.sim.new{dt_s = 5}
local ok5, dt5 = s5:exec("DT")
check(ok5 and dt5:find("dt 5 s", 1, true) ~= nil, dt5)
check(not pcall(squawk.sim.new, {dt_s = -1}), "a negative step is refused")

-- A route waypoint's stored commands (AT acid wp DO) are in its route table, in order.
local sr = squawk.sim.new()
for _, l in ipairs({ "CRE KL204 B744 52 4 90 FL200 250", "DEFWPT ALPHA 52 4.3", "ADDWPT KL204 ALPHA",
    "AT KL204 ALPHA DO ALT KL204 FL80", "AT KL204 ALPHA DO SPD 220" }) do
  check(sr:exec(l), l)
end
local wp1 = sr:get("KL204").route[1]
check_eq(wp1.name, "ALPHA")
check_eq(table.concat(wp1.commands, " | "), "ALT KL204 FL80 | KL204 SPD 220")
