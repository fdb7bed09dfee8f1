-- The controller's session (translate.session) and its text front end
-- (translate.repl): clock commands, conflicts, state after commands,
-- scenario failures and ECHO lines, errors that leave the session alive,
-- completion, the running clock, and a clarification answered.
local session = require("translate.session")
local repl = require("translate.repl")

local function find(text, what)
  return text:find(what, 1, true) ~= nil
end

local function kinds(events)
  local k = {}
  for _, e in ipairs(events) do k[e.kind] = (k[e.kind] or 0) + 1 end
  return k
end

-- FF with a time moves the clock at once and says so; the clock stays stopped.
do
  local s = session.new({ mode = "offline" })
  local r = s:command("!CRE KL204 A320 52 4 90 FL250 280")
  check(r.results[1].ok, r.results[1].message)
  r = s:command("!FF 300")
  check(r.results[1].ok)
  check_eq(s.sim:time(), 300)
  check(r.clock and find(r.clock, "fast-forwarded 300 s"), r.clock)
  check_eq(s:state().clock.state, "hold")
  r = s:command("fast forward 5 minutes")
  check_eq(r.commands[1], "FF 300")
  check_eq(s.sim:time(), 600)
  -- OP starts the running clock; tick() then moves time by wall x DTMULT.
  r = s:command("!OP")
  check(find(r.clock, "clock running at 1 x real time"), r.clock)
  s:tick(2.0)
  check_eq(s.sim:time(), 602)
  r = s:command("pause the simulation")
  check_eq(r.commands[1], "HOLD")
  check(find(r.clock, "HOLD"), r.clock)
  s:tick(5.0)
  check_eq(s.sim:time(), 602)
  check(find(s:set_clock(10), "10 x real time"))
  s:tick(1.5)
  check_eq(s.sim:time(), 617)
  -- A long pause of the terminal counts as kMaxTickWall.
  s:tick(3600)
  check_eq(s.sim:time(), 617 + 10 * session.kMaxTickWall)
  s:set_clock(nil)
  s:tick(1.0)
  check_eq(s.sim:time(), 617 + 10 * session.kMaxTickWall)
  -- HOLD (or its alias) when already stopped still says where the clock is.
  r = s:command("!PAUSE")
  check(r.clock and find(r.clock, "clock stopped (HOLD"), tostring(r.clock))
  -- A bad FF changes nothing and says why.
  r = s:command("!FF -5")
  check(not r.results[1].ok)
  check_eq(s.sim:time(), 667)
end

-- OP is BlueSky's: it ends fast-time and runs at real time (DTMULT 1);
-- :clock X runs at X all the same; an FF with a time ends at real time.
do
  local s = session.new({ mode = "offline" })
  local r = s:command("!FF")
  check_eq(s:state().clock.state, "ff")
  r = s:command("!OP")
  check_eq(s:state().clock.state, "op")
  check(find(r.clock, "clock running at 1 x real time"), r.clock)
  local t0 = s.sim:time()
  s:tick(2.0)
  check_eq(s.sim:time(), t0 + 2)
  s:command("!DTMULT 4")
  s:command("!OP")
  check_eq(s.sim:dtmult(), 1)
  check(find(s:set_clock(4), "4 x real time"))
  check_eq(s.sim:dtmult(), 4)
  t0 = s.sim:time()
  s:tick(1.0)
  check_eq(s.sim:time(), t0 + 4)
  r = s:command("!FF 60")
  check(find(r.clock, "fast-forwarded 60 s"), r.clock)
  check_eq(s:state().clock.state, "op")
  check_eq(s.sim:dtmult(), 1)
end

-- Head-on at FL300 with ASAS ON: the conflict is reported when it starts and
-- ends, and :state lists it with tLOS, tCPA and dCPA.
do
  local r = repl.new({ mode = "offline" })
  r:handle("!CRE BAW1 B744 52 4 90 FL300 280")
  r:handle("!CRE DLH2 A320 52 4.8 270 FL300 280")
  local text = r:handle("!ASAS ON")
  check(find(text, "ok: ASAS ON"), text)
  -- Predicted at once, at t = 0 with the clock held.
  check(find(text, "conflict BAW1 & DLH2: loss of separation in"), text)
  text = r:handle(":run 30")
  check(find(text, "tLOS"), text)
  check(text:match("BAW1 & DLH2%s+%d+ s%s+%d+ s%s+0%.%d%d NM") ~= nil, text)
  check(find(text, "CONFLICT DLH2"), text)
  local st = r.session:state()
  check_eq(#st.conflicts, 1)
  local c = st.conflicts[1]
  check_eq(c.own, "BAW1")
  check_eq(c.intruder, "DLH2")
  check(c.tlos_s > 0 and c.tcpa_s > c.tlos_s and c.dcpa_nm < 0.1, "tlos/tcpa/dcpa")
  text = r:handle(":run 200")
  check(find(text, "LOSS OF SEPARATION BAW1 & DLH2"), text)
  check(find(text, "conflict BAW1 & DLH2 ended"), text)
  check(find(text, "conflicts: none"), text)
end

-- After a command the state shows where the aircraft is going: selected
-- heading, altitude and speed, the route and its active waypoint.
do
  local r = repl.new({ mode = "offline" })
  r:handle("!CRE KL204 A320 52 4 90 FL250 280")
  local text = r:handle("KL204 turn left heading 180")
  check(find(text, "> HDG KL204 180"), text)
  check(find(text, "hdg  90.0 -> 180"), text)
  text = r:handle("!ALT KL204 FL300")
  check(find(text, "alt  25000 ft -> 30000"), text)
  text = r:handle("!SPD KL204 300")
  check(find(text, "CAS  280 kt -> 300 kt"), text)
  text = r:handle("!ADDWPT KL204 53 5")
  check(find(text, "hdg  90.0 -> KL204001"), text)
  check(find(text, "route KL204001*  (LNAV on, * active)"), text)
  local a = r.session:state().aircraft[1]
  check_eq(a.sel_hdg_deg ~= nil, true)
  check_eq(a.active_wpt, "KL204001")
  check_eq(#a.route, 1)
  -- the commands a waypoint runs when passed (AT acid wp DO), under the route
  text = r:handle("!AT KL204 KL204001 DO ALT KL204 FL100")
  check(find(text, "at KL204001 do: ALT KL204 FL100"), text)
end

-- A scenario whose commands fail is summarised like `squawk scn`; its ECHO
-- lines and later failures appear while time runs.
do
  local r = repl.new({ scenario = squawk.home .. "/tests/lua/repl_failures.scn", mode = "offline" })
  local open = r:opening()
  check(find(open, "2 failed"), open)
  check(find(open, "DEST: argument 2"), open)
  check(find(open, "first failures:"), open)
  check_eq(r.session.sim:count(), 2)
  local text = r:handle(":run 45")
  check(find(text, "half a minute in"), text)
  check(find(text, "1 scenario command failed"), text)
  check(find(text, "ORIG DLH2 QQXC"), text)
  local ev = kinds(r.session:run(1))
  check_eq(ev.failure, nil)
end

-- ECHO lines of the shipped demo scenario during :run.
do
  local r = repl.new({ scenario = squawk.home .. "/scenarios/demo_conflict.scn", mode = "offline" })
  local text = r:handle(":run 70")
  check(find(text, "one minute: resolution under way"), text)
end

-- A runtime error in a graph node is reported; the session and the
-- simulation go on.
do
  local nodes = require("translate.nodes")
  local r = repl.new({ mode = "offline" })
  r:handle("!CRE KL204 A320 52 4 90 FL250 280")
  local before = r.session.sim:snapshot()
  local saved = nodes.offline
  nodes.offline = function() error("boom in a node") end
  local ok, text = pcall(r.handle, r, "KL204 climb to FL300")
  nodes.offline = saved
  check(ok, text)
  check(find(text, "the translator failed"), text)
  check(find(text, "boom in a node"), text)
  check_eq(r.session.sim:snapshot(), before)
  text = r:handle("KL204 climb to FL300")
  check(find(text, "> ALT KL204 FL300"), text)
end

-- Completion: callsigns, command names and aliases (also after !), :commands.
do
  local s = session.new({ mode = "offline" })
  s:command("!CRE KL204 A320 52 4 90 FL250 280")
  s:command("!CRE KLM12 A320 52 5 90 FL250 280")
  local c = s:complete("KL")
  check_eq(table.concat(c, " "), "KL204 KLM12")
  check_eq(table.concat(s:complete("!HD"), " "), "!HDG")
  check_eq(table.concat(s:complete(":st"), " "), ":state")
  check(#s:complete("P") >= 2, "PAUSE, PCALL, POS ...")
end

-- A question back and its answer, through the dialogue.
do
  local r = repl.new({ mode = "offline" })
  r:handle("!CRE KL204 A320 52 4 90 FL250 280")
  local text = r:handle("KL204 turn to heading")
  check(text:sub(1, 2) == "? ", text)
  text = r:handle("cancel")
  check(find(text, "cancelled"), text)
  check(r:handle("KL204 turn to heading"):sub(1, 2) == "? ")
  text = r:handle("180")
  check(find(text, "> HDG KL204 180"), text)
  check(find(text, "hdg  90.0 -> 180"), text)
  check(not r.session.dialogue.pending)
end

-- The squawk.sim fields the session reads.
do
  local sim = squawk.sim.new()
  check(sim:exec("CRE KL204 A320 52 4 90 FL250 M.78"))
  check(sim:exec("ADDWPT KL204 52.5 4.5 FL300"))
  check(sim:exec("ADDWPT KL204 53 5"))
  local a = sim:get("KL204")
  check_eq(a.sel_mach, 0.78)
  check_eq(a.sel_cas_kt, nil)
  check_eq(#a.route, 2)
  check_eq(a.route[1].name, "KL204001")
  check(math.abs(a.route[1].alt_ft - 30000) < 1e-6, "altitude constraint in ft")
  check_eq(a.route[2].alt_ft, nil)
  check_eq(a.active_wpt, "KL204001")
  check_eq(sim:run_state(), "hold")
  check(sim:exec("FF 30"))
  local state, ff_end = sim:run_state()
  check_eq(state, "ff")
  check_eq(ff_end, 30)
  check(sim:exec("OP"))
  check_eq(sim:run_state(), "op")
  check(sim:exec("DTMULT 3"))
  check_eq(sim:dtmult(), 3)
  local t = sim:tally()
  check_eq(t.failed, 0)
  check_eq(#t.first_failures, 0)
end

-- "fast forward 2 minutes" with traffic whose callsign ends in 2: a time, not DLH2.
do
  local r = repl.new({ mode = "offline" })
  r:handle("!CRE DLH2 A320 52 4.8 270 FL300 280")
  local text = r:handle("fast forward 2 minutes")
  check(find(text, "> FF 120"), text)
  check(find(text, "fast-forwarded 120 s"), text)
end

-- "fast forward 2 minutes then pause" (FF 120 ; HOLD): the fast-forward runs to its end before the HOLD said after
-- it, from a stopped clock or a running one; the HOLD alone would have ended it at once, the clock never moved.
for _, start in ipairs({ "!HOLD", "!OP" }) do
  local s = session.new({ mode = "offline" })
  s:command("!CRE KLM12 B738 52 4 090 FL200 250")
  s:command(start)
  local t0 = s:state().simt
  local r = s:command("fast forward 2 minutes then pause")
  check_eq(table.concat(r.commands, " ; "), "FF 120 ; HOLD")
  check_eq(s:state().simt - t0, 120)
  check_eq(s:state().clock.state, "hold")
end
