-- The offline grammar (translate/grammar.lua): utterance -> TrafScript or a
-- question, with and without a world (the traffic it translates against).
local grammar = require("translate.grammar")

local function plane(id, hdg, alt_ft, kt, route)
  return { id = id, type = "A320", lat = 52, lon = 4, hdg_deg = hdg, alt_ft = alt_ft, cas_kt = kt, route = route or {} }
end
local function text(r) return r.ask and ("ASK " .. r.ask) or table.concat(r.commands, " ; ") end
local function tr(s, world) return text(grammar.translate(s, world)) end
local function asks(s, world) return grammar.translate(s, world).ask ~= nil end
-- the world of a TrafScript setup, as the graph's offline node builds it
local nodes = require("translate.nodes")
local function world_of(setup)
  local sim = squawk.sim.new()
  for _, line in ipairs(nodes.split_commands(setup)) do check(sim:exec(line)) end
  return nodes.world(sim, nodes.defined_waypoints(setup))
end
do -- altitudes: flight levels, feet, thousands, 30k, metres
  check_eq(tr("KLM123 climb flight level three five zero"), "ALT KLM123 FL350")
  check_eq(tr("Delta three six two, descend and maintain four thousand"), "ALT DAL362 4000")
  check_eq(tr("American four seven, climb and maintain one one thousand"), "ALT AAL47 11000")
  check_eq(tr("Descend AC02 to 15k ft"), "ALT AC02 15000")
  check_eq(tr("clim AC04 to FL 290"), "ALT AC04 FL290")
  check_eq(tr("I'd like aircraft TEST2 to cruise at 41,000 ft"), "ALT TEST2 41000")
  check_eq(tr("Bring AC03 up to thirty-seven thousand feet"), "ALT AC03 37000")
  check_eq(tr("Climb AC01 to 28000 ft at 1500 fpm"), "ALT AC01 28000 1500")
  check_eq(tr("change AC02 vertical speed to -1000 fpm"), "VS AC02 -1000")
  check_eq(tr("Make AC01 descend at 1500 feet per minute"), "VS AC01 -1500")
end

do -- speeds: knots and Mach in every common form
  check_eq(tr("KLM one two three, reduce speed to two two zero knots"), "SPD KLM123 220")
  check_eq(tr("Have AC01 fly at M.78"), "SPD AC01 M0.78")
  check_eq(tr("Speedbird seven, reduce speed to mach point seven eight"), "SPD BAW7 M0.78")
  check_eq(tr("Set AC04's speed to 0.79 Mach"), "SPD AC04 M0.79")
  check_eq(tr("slow AC03 to 180 kts"), "SPD AC03 180")
end

do -- a level condition in non-native English: "when pass FL250" is "when passing FL250"
  check_eq(tr("KLM123 descend FL200, when pass FL250 reduce speed 250"), "ALT KLM123 FL200 ; ATALT KLM123 FL250 SPD KLM123 250")
  check_eq(tr("KLM123 climb to FL300 and when pass FL280 turn left heading 050"),
    "ALT KLM123 FL300 ; ATALT KLM123 FL280 HDG KLM123 50 LEFT")
end

do -- ICAO telephony designators: Loganair is "Logan", TUI Airways "Tomjet"
  check_eq(tr("Logan two one alpha, climb flight level one zero zero"), "ALT LOG21A FL100")
  check_eq(tr("Tomjet 3 kilo xray turn left heading 250"), "HDG TOM3KX 250 LEFT")
  check_eq(tr("Azul 4410 climb flight level 310"), "ALT AZU4410 FL310")
  check_eq(tr("Korean Air 85 reduce speed 250 knots"), "SPD KAL85 250")
  -- "give me the position/status" asks for what the aircraft is doing
  check_eq(tr("KLM123 give me the position please"), "POS KLM123")
  check_eq(tr("give me KLM123's status"), "POS KLM123")
  local w = { aircraft = { plane("LOG12", 90, 7000, 220), plane("KLM12", 90, 9000, 250) } }
  check_eq(tr("Logan one two descend altitude five thousand feet", w), "ALT LOG12 5000")
end

do -- a typed flight number with letters after the airline name; glued units stay units
  check_eq(tr("Ryanair 8UK, fly heading 210, speed 230"), "HDG RYR8UK 210 ; SPD RYR8UK 230")
  check_eq(tr("speedbird 22mx climb FL300"), "ALT BAW22MX FL300")
  check_eq(tr("KLM1023 speed 250kt"), "SPD KLM1023 250")
  check_eq(tr("KLM1023 climb 30k"), "ALT KLM1023 30000")
end

do -- headings: absolute, compass words, ATC digits
  check_eq(tr("Shamrock four five kilo, turn left heading three one zero"), "HDG EIN45K 310 LEFT")
  check_eq(tr("Point AC01 due south"), "HDG AC01 180")
  check_eq(tr("Make AC03 fly north-east"), "HDG AC03 45")
  -- the sixteen-point compass: a cardinal and the intercardinal after it
  check_eq(tr("Make AC03 fly west-south-west"), "HDG AC03 247.5")
  check_eq(tr("AC01 head north north east"), "HDG AC01 22.5")
  check_eq(tr("steer AC02 north-northwest"), "HDG AC02 337.5")
  check_eq(tr("Point AC01 east south east"), "HDG AC01 112.5")
  check_eq(tr("Set the heading of aircraft TEST3 to one hundred and twenty degrees"), "HDG TEST3 120")
end

do -- DIRECT switches LNAV on: "resume own navigation" said with a direct-to is that DIRECT
  local w = { aircraft = { plane("AC01", 90, 25000, 280, { "ARTIP", "SUGOL" }) } }
  check_eq(tr("AC01 resume own navigation direct SUGOL", w), "DIRECT AC01 SUGOL")
  check_eq(tr("AC01, resume your own navigation, then route direct ARTIP", w), "DIRECT AC01 ARTIP")
  check_eq(tr("AC01 resume own navigation", w), "LNAV AC01 ON")
end

do -- relative instructions use the current state
  local w = { aircraft = { plane("AC01", 90, 25000, 280), plane("AC02", 20, 26000, 290) } }
  check_eq(tr("turn AC01 left 20 degrees", w), "HDG AC01 70 LEFT")
  check_eq(tr("Turn AC02 left by 40 degrees", w), "HDG AC02 340 LEFT")
  check_eq(tr("Turn AC01 30 degrees to the right", w), "HDG AC01 120 RIGHT")
  check_eq(tr("Climb AC01 by 2000 feet", w), "ALT AC01 27000")
  check_eq(tr("Slow AC01 down by 20 knots", w), "SPD AC01 260")
  check_eq(tr("Increase the speed of AC01 by 10%", w), "SPD AC01 308")
  -- knots added to an aircraft holding a Mach number are asked about, knots to one holding knots are not
  local m = world_of("CRE AAL1 B77W 52 4 120 FL350 M.82 ; CRE BAW1 A320 52 5 90 FL200 280")
  check_eq(tr("increase AAL1 speed by 20 knots", m), "ASK AAL1 holds M0.82: what speed should it fly, in knots or as a Mach number?")
  check_eq(tr("AAL1 ten knots slower", m), "ASK AAL1 holds M0.82: what speed should it fly, in knots or as a Mach number?")
  check_eq(tr("BAW1 speed up by 20 knots", m), "SPD BAW1 300")
  -- a reversal with no way said asks which way (either is as short); with the way, the way
  check_eq(tr("Turn AC01 around", w), "ASK Should AC01 turn around to the left or to the right?")
  check_eq(tr("Turn AC01 around to the left", w), "HDG AC01 270 LEFT")
  check_eq(tr("Give AC02 the same heading as AC01", w), "HDG AC02 90")
  -- without a world there is no current heading to turn from
  check(asks("turn AC01 left 20 degrees"))
end

do -- positions: lat/lon in written forms, types, creation
  check_eq(tr("Create AC01, an A320 at 52N 4E heading 90 at FL250 and 280 knots"), "CRE AC01 A320 52 4 90 FL250 280")
  check_eq(tr("Add a Boeing 737-800 named KL1 at 52 deg 18 min N, 4 deg 45 min E heading 90 at 30k ft, 250 kt"), "CRE KL1 B738 52.3 4.75 90 30000 250")
  check_eq(tr("Move AC01 to N52.3 E4.76"), "MOVE AC01 52.3 4.76")
  check_eq(tr("Define waypoint EXIT1 at 53.2 north 2.1 east"), "DEFWPT EXIT1 53.2 2.1")
  check_eq(tr("add a 747-400 with id CX520 at 0 0, heading 0, FL200, 400 knots"), "CRE CX520 B744 0 0 0 FL200 400")
end

do -- telephony callsigns become ICAO callsigns
  check_eq(tr("speedbird 123 turn right heading 090"), "HDG BAW123 90 RIGHT")
  check_eq(tr("Lufthansa four alpha bravo, fly heading zero niner zero"), "HDG DLH4AB 90")
  check_eq(tr("Easy four fife bravo, descend flight level two zero zero"), "ALT EZY45B FL200")
end

do -- several instructions in one utterance keep their order
  check_eq(tr("Speedbird one two three, turn left heading two four zero, descend altitude eight thousand feet, " .. "reduce speed two one zero knots"), "HDG BAW123 240 LEFT ; ALT BAW123 8000 ; SPD BAW123 210")
  check_eq(tr("Turn on conflict detection and use MVP for resolution"), "ASAS ON ; RESO MVP")
  check_eq(tr("Reset, then set seed 99 and a time step of 0.05 seconds"), "RESET ; SEED 99 ; DT 0.05")
  check_eq(tr("Set AC01 and AC02 to FL300"), "ALT AC01 FL300 ; ALT AC02 FL300")
  check_eq(tr("AC02: heading 180, FL200, 250 kts"), "HDG AC02 180 ; ALT AC02 FL200 ; SPD AC02 250")
  check_eq(tr("When AC01 reaches FL200, set its speed to 280 knots"), "ATALT AC01 FL200 SPD AC01 280")
  -- "then" waits for the instruction before it; ", then" after a comma lists the next one
  check_eq(tr("Delta 30, descend and maintain 4000 then reduce speed to 210"), "ALT DAL30 4000 ; ATALT DAL30 4000 SPD DAL30 210")
  check_eq(tr("Delta 30, descend and maintain 4000, then reduce speed to 210"), "ALT DAL30 4000 ; SPD DAL30 210")
end

do -- experimenter requests
  -- faster with no rate and no duration: DTMULT by how much, or FF for how long? (asked)
  check((tr("Can you speed this simulation up?")):match("^ASK") ~= nil, "speed up with no rate nor duration")
  check_eq(tr("Fast-forward 10 minutes"), "FF 600")
  check_eq(tr("Pause the simulation"), "HOLD")
  check_eq(tr("Slow the sim down to half speed"), "DTMULT 0.5")
  check_eq(tr("Load the scenario super16.scn and then set the random seed to 7"), "IC super16.scn ; SEED 7")
  check_eq(tr("Print \"phase 2\" to the console"), "ECHO phase 2")
  check_eq(tr("run at double speed"), "DTMULT 2")
  check_eq(tr("speed the simulation up 10 times"), "DTMULT 10")
  -- a multiplier said of the sim's speed
  check_eq(tr("Double the sim speed."), "DTMULT 2")
  check_eq(tr("could you double the simulation speed"), "DTMULT 2")
  check((tr("speed up the sim")):match("^ASK") ~= nil, "speed up with no rate nor duration")
  check_eq(tr("turn off CD"), "ASAS OFF")
  check_eq(tr("What is the altitude of KLM123?"), "POS KLM123")
  local w = { aircraft = { plane("AC01", 90, 25000, 280), plane("AC02", 20, 26000, 290) } }
  check_eq(tr("Delete all aircraft", w), "DEL AC01 ; DEL AC02")
end

do -- a missing callsign or value is asked for, never guessed
  check(asks("KLM one two three, climb"))
  check(asks("Change the speed"))
  check(asks("Speedbird one two three, turn left"))
  check(asks("Create a new aircraft called TST01"))
  check(asks("Set the simulation time step"))
  check(asks("Add a waypoint for AC01"))
  local two = { aircraft = { plane("AC01", 90, 25000, 280), plane("AC02", 20, 26000, 290) } }
  check(asks("Turn the aircraft to heading 270", two))
  local one = { aircraft = { plane("TEST9", 90, 25000, 280) } }
  check_eq(tr("Turn the aircraft to heading 270", one), "HDG TEST9 270")
  local t = grammar.translate("Set the altitude of AC01")
  check_eq(#t.commands, 0)
  check(t.ask:find("AC01", 1, true) ~= nil, "the question names the aircraft")
end

do -- spoken callsigns are matched to the aircraft that exist
  local w = world_of("CRE DAL1153 B738 40 -74 360 5000 250 ; CRE AVA847 A320 40.5 -74 90 11000 250")
  -- digits heard that are not the aircraft's ask while another aircraft flies
  check_eq(tr("12,153, climbing, maintain one two twelve thousand.", w), "ASK Did you mean DAL1153? I heard 12153.")
  check_eq(tr("Abiont eight forty seven descend and maintain four thousand", w), "ALT AVA847 4000")
  check_eq(tr("Delta eleven fifty three turn right heading zero one zero", w), "HDG DAL1153 10 RIGHT")
end

do -- waypoints are matched by sound
  local w = world_of("CRE ACA326 B738 40 -74 360 12000 250 ; DEFWPT GAYEL 40.5 -73.5 ; ADDWPT ACA326 GAYEL")
  check_eq(tr("Air Canada three twenty six cleared direct Gale", w), "DIRECT ACA326 GAYEL")
  check_eq(tr("Air Canada three twenty six proceed direct", w), "DIRECT ACA326 GAYEL")
end

do -- callsigns restarted, corrected or heard without their letters
  local w = world_of("CRE DAL646 B738 40 -74 360 5000 250 ; CRE RPA1411 E170 40.5 -74 90 5000 250 ; "
    .. "CRE DLH4130 A320 41 -74 90 5000 250 ; CRE BAW96CA A320 41 -73 90 5000 250 ; CRE DAL84 A320 41 -72 0 9000 250")
  check_eq(tr("Delta Sixty Delta Six Forty Six maintain three thousand", w), "ALT DAL646 3000")
  check_eq(tr("Brickyard Eleven correction fourteen eleven descend maintain three thousand", w), "ALT RPA1411 3000")
  check_eq(tr("lufthansa thirty one correction lufthansa forty one thirty turn left heading two seven zero", w),
    "HDG DLH4130 270 LEFT")
  -- letters left unheard while other aircraft fly: asked, never taken
  check_eq(tr("speedbird nine six right heading zero nine zero", w), "ASK Did you mean BAW96CA? I heard BAW96.")
  check_eq(tr("speedbird nine six charlie alpha right heading zero nine zero", w), "HDG BAW96CA 90 RIGHT")
  -- the digits differ: still a question, and a list of aircraft is no restart
  check(asks("Delta Ninety Four maintain two one zero knots", w), "DAL94 is not DAL84")
  check(asks("speedbird nine six charlie bravo right heading zero nine zero", w), "BAW96CB is not BAW96CA")
  check_eq(tr("DAL646 and DAL84 climb to FL300", w), "ALT DAL646 FL300 ; ALT DAL84 FL300")
  check_eq(tr("JetBlue eight tier thirteen speed two zero zero", world_of("CRE JBU813 A320 40 -74 0 9000 250")),
    "SPD JBU813 200")
  check_eq(tr("Brickyard eight in eighty two descend and maintain five thousand",
    world_of("CRE RPA1882 E170 40 -74 0 9000 250")), "ALT RPA1882 5000")
end

do -- values as speech recognition writes them
  local w = world_of("CRE SWA5578 B738 40 -74 360 5000 250 ; CRE TAP9148 A320 41 -74 90 9000 250")
  check_eq(tr("Southwest fifty five seventy eight turn left heading three f four zero", w), "HDG SWA5578 340 LEFT")
  check_eq(tr("Southwest fifty five seventy eight maintain one nine-year zero knots", w), "SPD SWA5578 190")
  check_eq(tr("Southwest fifty five seventy eight reduce speed to two once", w), "SPD SWA5578 210")
  check_eq(tr("Portugal 91-48 heavy at 5000 reduce speed to 21-0", w), "ATALT TAP9148 5000 SPD TAP9148 210")
  check_eq(tr("Southwest fifty five seventy eight fly heading to niner zero", w), "HDG SWA5578 290")
  check_eq(tr("Southwest fifty five seventy eight fly heading T seven zero", w), "HDG SWA5578 270")
  check_eq(tr("Southwest fifty five seventy eight maintain two one, uh, turn knots", w), "SPD SWA5578 210")
  check_eq(tr("Southwest fifty five seventy eight descend to disregard maintain one eighty knots", w), "SPD SWA5578 180")
  check_eq(tr("Southwest fifty five seventy eight descend and maintain two thousand seven hundred ten", w),
    "ALT SWA5578 2700")
  check_eq(tr("Southwest fifty five seventy eight climb and maintain one three thousand, zero niner zero", w),
    "ALT SWA5578 13000 ; HDG SWA5578 90")
  -- a word the recogniser garbled ("rioted" for "right heading") is asked about, never skipped
  check_eq(tr("Land Juliett fifty five seventy eight rioted in two seven zero",
    world_of("CRE SWA5578 B738 40 -74 360 5000 250")), "ASK I have HDG SWA5578 270. What does 'rioted' mean?")
  check_eq(tr("Boeing 787-9"):find("DTMULT"), nil)
  check_eq(tr("Southwest fifty five seventy eight mark point six seven", w), "SPD SWA5578 M0.67")
  -- a stutter is repaired, a compound number is not cut ("seventy six thousand" is no 6000)
  check_eq(tr("Southwest fifty five seventy eight climb and maintain one four fourteen thousand", w), "ALT SWA5578 14000")
  check(asks("Southwest fifty five seventy eight climb and maintain seventy six thousand", w), "76000 ft is asked")
end

do -- one instruction for two aircraft, each with its own value; 'by' before the verb is not relative
  local w = world_of("CRE EZY45 A320 51 2 45 FL280 290 ; CRE AFR1234 A321 49 2 180 FL350 300")
  check_eq(tr("turn EZY45 to 010 and AFR1234 to 200", w), "HDG EZY45 10 ; HDG AFR1234 200")
  check_eq(tr("EZY45 and AFR1234 climb to FL360", w), "ALT EZY45 FL360 ; ALT AFR1234 FL360")
  check_eq(tr("EZY45 time by departure descend one two thousand", w), "ALT EZY45 12000")
  check_eq(tr("EZY45 climb by 2000 feet", w), "ALT EZY45 30000")
  -- keeping a value: "hold" with a value noun is no pause of the simulation
  check_eq(tr("EZY45, hold present heading", w), "HDG EZY45 45")
  check_eq(tr("EZY45 maintain present speed", w), "SPD EZY45 290")
  check_eq(tr("hold the simulation", w), "HOLD")
  -- a holding pattern is neither a pause of the simulation nor a kept altitude: squawk says it does not simulate it
  local function not_simulated(s, what)
    local r = grammar.translate(s, w)
    check(#r.commands == 0 and r.note ~= nil and r.note:find(what, 1, true) ~= nil, s .. " -> " .. tostring(r.note))
  end
  not_simulated("EZY45 hold", "holding patterns")
  not_simulated("EZY45 hold at present position", "holding patterns")
  not_simulated("EZY45 hold over SQK01 as published", "holding patterns ('hold over SQK01 as published')")
  not_simulated("EZY45 cleared ILS approach runway 27", "approach clearances")
  not_simulated("EZY45 squawk 7700", "transponder codes ('squawk 7700')")
  not_simulated("EZY45 contact Amsterdam approach 121.2", "radio frequencies")
  -- in a mixed request the rest is translated and the note comes with it
  local mixed = grammar.translate("EZY45 contact approach 119.7 and descend FL100", w)
  check_eq(text(mixed), "ALT EZY45 FL100")
  check(mixed.note ~= nil and mixed.note:find("radio frequencies", 1, true) ~= nil, "the frequency is named")
  check_eq(tr("hold the sim and EZY45 maintain present heading", w), "HOLD ; HDG EZY45 45")
  -- an aircraft named just before an instruction word is that instruction's
  check_eq(tr("EZY45 turn left heading 300 and AFR1234 descend FL200", w), "HDG EZY45 300 LEFT ; ALT AFR1234 FL200")
  check_eq(tr("pause the simulation and EZY45 turn left heading 300", w), "HOLD ; HDG EZY45 300 LEFT")
  -- a change from the present heading is each aircraft's own; the aircraft named together stay together
  check_eq(tr("EZY45 and AFR1234 turn left 20 degrees", w), "HDG EZY45 25 LEFT ; HDG AFR1234 160 LEFT")
  check_eq(tr("EZY45 and AFR1234 maintain present heading", w), "HDG EZY45 45 ; HDG AFR1234 180")
  check_eq(tr("EZY45 and AFR1234 turn around right", w), "HDG EZY45 225 RIGHT ; HDG AFR1234 360 RIGHT")
  check_eq(tr("EZY45 and AFR1234 maintain present speed", w), "SPD EZY45 290 ; SPD AFR1234 300")
  check_eq(tr("EZY45 left 30 degrees", w), "HDG EZY45 15 LEFT")
end

do -- the display's trails: on/off with the point interval, a colour per aircraft
  local w = { aircraft = { plane("KLM123", 90, 25000, 280) } }
  check_eq(tr("Show aircraft trails"), "TRAIL ON")
  check_eq(tr("Hide the trails"), "TRAIL OFF")
  check_eq(tr("turn on trails every 5 seconds"), "TRAIL ON 5")
  check_eq(tr("start it in real time again and turn the trails off"), "OP ; TRAIL OFF")
  -- ("run it in real time again" is "back to real time": with the clock's state unknown, asked)
  check(asks("run it in real time again and turn the trails off"), "real time again, the clock unknown")
  check_eq(tr("show the trail of KLM123 in red", w), "TRAIL KLM123 RED")
  check(asks("make the trail yellow"), "a colour needs an aircraft")
end

do -- bad input never crashes and gets a question
  for _, s in ipairs({ "", " .. ", ";;;", "\"", "\xC2\xB0\xC2\xB0", "FL", "M.", "N", "one hundred thousand thousand",
                        "direct direct direct", "12,", "AC01'", "-", "\xff\xfe" }) do
    local t = grammar.translate(s)
    check((t.ask ~= nil) ~= (#t.commands > 0), "a question or commands for " .. s)
  end
end

do -- navigation and simulation phrases: own navigation, direct to a new fix, run for a time
  local w = { aircraft = { plane("KLM123", 90, 25000, 280, { "SPY" }) }, waypoints = { "SUGOL", "SPY" } }
  check_eq(tr("KLM123 resume own navigation", w), "LNAV KLM123 ON")
  -- DIRECT needs the fix in the route: one the route lacks is added first.
  check_eq(tr("KLM123 fly direct SUGOL", w), "ADDWPT KLM123 SUGOL ; DIRECT KLM123 SUGOL")
  check_eq(tr("KLM123 proceed direct SPY", w), "DIRECT KLM123 SPY")
  check_eq(tr("Run the simulation for ten minutes"), "FF 600")
  check_eq(tr("Run the sim"), "OP")
  -- a simulator instructor's words: the exercise is the simulation, "jump forward" fast-forwards
  check_eq(tr("pause the exercise"), "HOLD")
  check_eq(tr("OK, continue the exercise please"), "OP")
  check_eq(tr("jump ahead ten minutes"), "FF 600")
  check_eq(tr("bin KLM123 please"), "DEL KLM123")
  check_eq(tr("Run the simulation at 5x real time"), "DTMULT 5")
end

do -- polite sentences and hurried shorthand (round 5 and 6 classes)
  local w = { aircraft = { plane("KLM123", 90, 25000, 280), plane("AFR55", 180, 30000, 300) } }
  -- "and then" and a plain bare "then" list the next instruction; after "descend and maintain" (a
  -- level held until reached) a bare "then" waits for it
  check_eq(tr("AFR55, reduce to 250 knots please, and then turn left heading 120", w),
    "SPD AFR55 250 ; HDG AFR55 120 LEFT")
  check_eq(tr("AFR55 descend FL200 then speed 260", w), "ALT AFR55 FL200 ; SPD AFR55 260")
  check_eq(tr("AFR55 descend and maintain FL200 then reduce speed 260", w),
    "ALT AFR55 FL200 ; ATALT AFR55 FL200 SPD AFR55 260")
  -- a reason names other aircraft as context: they are given nothing
  check_eq(tr("Descend AFR55 to FL240 so that it passes under KLM123", w), "ALT AFR55 FL240")
  check_eq(tr("Slow KLM123 to 240 knots because AFR55 is right behind it", w), "SPD KLM123 240")
  -- typed "desc"/"clb": the verb, and the sign of a rate
  check_eq(tr("afr55 desc 9000 hdg 200", w), "ALT AFR55 9000 ; HDG AFR55 200")
  check_eq(tr("klm123 desc rate 1800", w), "VS KLM123 -1800")
  check_eq(tr("klm123 clb rate 1200", w), "VS KLM123 1200")
  -- creating a callsign that already flies would replace it: asked
  check(asks("create an A320 called AFR55 at 51.5 N 2.5 E heading 090 FL120 250 knots", w), "existing callsign")
  -- a setting reset is that setting; "until I say stop" ends a run, it pauses nothing
  check_eq(tr("please reset the protected zone radius to 4 nm"), "ZONER 4")
  check_eq(tr("Could you run in fast time until I say stop?"), "FF")
  check_eq(tr("fast forward a quarter of an hour"), "FF 900")
  check_eq(tr("skip ahead half an hour please"), "FF 1800")
  check_eq(tr("now let it run again"), "OP")
  -- info and routes in few words
  check_eq(tr("afr55 route pls", w), "LISTRTE AFR55")
  check_eq(tr("Can I see the route of KLM123?", w), "LISTRTE KLM123")
  check_eq(tr("show me the position of AFR55 please", w), "POS AFR55")
  check_eq(tr("send AFR55 straight to SPY", { aircraft = w.aircraft, waypoints = { "SPY" } }), "ADDWPT AFR55 SPY ; DIRECT AFR55 SPY")
  check_eq(tr("cre dal9 b738 41.2 -73.5 hdg 090 fl80 230"), "CRE DAL9 B738 41.2 -73.5 90 FL80 230")
  -- shapes and the deletion area; several waypoints defined in one sentence
  check_eq(tr("please turn the deletion area off"), "AREA OFF")
  check_eq(tr("Set the deletion area to 50 N 2 E to 52 N 6 E"), "AREA 50 2 52 6")
  check_eq(tr("make a circle named APP around 51.5, 3.2 with a radius of 15 nm"), "CIRCLE APP 51.5 3.2 15")
  check_eq(tr("define a box called EAST from 51 N 4 E to 53 N 7 E between FL 50 and FL 250"),
    "BOX EAST 51 4 53 7 FL250 FL50")
  check_eq(tr("put a circle called OUT around 52 north 4 east with a 30 mile radius and make it the deletion area"),
    "CIRCLE OUT 52 4 30 ; AREA OUT")
  check_eq(tr("Define waypoints P1 at 51.2, 3.4 and P2 at 51.6, 3.9"), "DEFWPT P1 51.2 3.4 ; DEFWPT P2 51.6 3.9")
  check_eq(tr("could you define a new waypoint named MID at 51.7 north 3.3 east"), "DEFWPT MID 51.7 3.3")
  check_eq(tr("add a fix called EDGE at 50.5 N, 2.5 E"), "DEFWPT EDGE 50.5 2.5")
  -- the simulation's rate in words
  check_eq(tr("make the sim rate 6 times please"), "DTMULT 6")
  check_eq(tr("run the sim at four times normal speed"), "DTMULT 4")
  check_eq(tr("let the simulation go three times as fast"), "DTMULT 3")
  check_eq(tr("put the speed multiplier to 5"), "DTMULT 5")
  check_eq(tr("simulation speed x4"), "DTMULT 4")
  check_eq(tr("sim speed x3", w), "DTMULT 3")  -- with traffic, "x3" is no unknown callsign
  check_eq(tr("back to normal speed for the simulation"), "DTMULT 1")
  -- information requests said as wishes
  check_eq(tr("I want to look at AFR55's position", w), "POS AFR55")
  check_eq(tr("tell me KLM123's present altitude please", w), "POS KLM123")
  check_eq(tr("where's the Airbus, AFR55?", w), "POS AFR55")
  check_eq(tr("please show me where SPY is", { aircraft = w.aircraft, waypoints = { "SPY" } }), "POS SPY")
  -- a navaid's kind is no place of its own (navdata holds a fix named VOR)
  local wv = { aircraft = w.aircraft, waypoints = { "VOR", "PAM" } }
  check_eq(tr("show me where the Pampus VOR, PAM, is", wv), "POS PAM")
  check(asks("where is the Spijkerboor VOR?", wv), "a navaid by a name squawk cannot place asks")
  -- own navigation, vertical navigation, deletions in few words
  -- (with a route to navigate by; with none, asked)
  local wr = { aircraft = { plane("KLM123", 90, 25000, 280), plane("AFR55", 180, 30000, 300, { "SPY" }) } }
  check_eq(tr("let AFR55 resume its own route navigation", wr), "LNAV AFR55 ON")
  check(asks("let AFR55 resume its own route navigation", w), "own navigation with no route asks")
  check_eq(tr("put KLM123 back on lnav", w), "LNAV KLM123 ON")
  check_eq(tr("AFR55 should follow its route vertically as well", w), "VNAV AFR55 ON")
  check_eq(tr("afr55 leaving my sector, drop it", w), "DEL AFR55")
  check_eq(tr("afr55 drop it to FL150", w), "ALT AFR55 FL150")
  check_eq(tr("rmv klm123", w), "DEL KLM123")
  check_eq(tr("delete AFR55, I will re-create it later", w), "DEL AFR55")
  -- random traffic; a plural type is that type, unless an aircraft has that id
  check_eq(tr("please generate 12 random aircraft"), "MCRE 12")
  check_eq(tr("add four random E190 at FL150 please"), "MCRE 4 E190 FL150")
  check_eq(tr("seed 3, then spawn 8 random aircraft"), "SEED 3 ; MCRE 8")
  check_eq(tr("create six random B738s"), "MCRE 6 B738")
  check_eq(tr("add 5 random A320s at FL300 all going to EHAM"), "MCRE 5 A320 FL300 * EHAM")
  check(asks("create six random B738s", { aircraft = { { id = "B738S", lat = 52, lon = 4 } } }), "B738S flies")
  check_eq(tr("run ahead 90 seconds"), "FF 90")
  -- a count of aircraft with no callsign is random traffic; a duration right after "run"/"step" is FF
  check_eq(tr("spawn 7 planes"), "MCRE 7")
  check_eq(tr("generate 12 agents at FL200 doing 260 knots"), "MCRE 12 * FL200 260")
  check_eq(tr("create 4 aircraft, type A321, all bound to EGLL"), "MCRE 4 A321 * * EGLL")
  check_eq(tr("set seed 11 and step the simulation 45 seconds"), "SEED 11 ; FF 45")
  check_eq(tr("add 3 jets then run 5 minutes"), "MCRE 3 ; FF 300")
  check_eq(tr("HOLD then FF 90"), "HOLD ; FF 90")
  check_eq(tr("switch to MVP please"), "RESO MVP")
  -- "it" after a definition is the waypoint just defined, and is never matched to a name
  local ww = { aircraft = w.aircraft, waypoints = { "EXIT1", "SPY" } }
  check_eq(tr("define a waypoint Q1 at 51.1, 3.1 and add it to AFR55's route", ww), "DEFWPT Q1 51.1 3.1 ; ADDWPT AFR55 Q1")
  check_eq(tr("define Q2 at 51.3 N 3.6 E, then add it at the end of the route of KLM123 after SPY", ww),
    "DEFWPT Q2 51.3 3.6 ; ADDWPT KLM123 Q2,,,SPY")
  check_eq(tr("klm123 add EXIT1 before SPY", ww), "ADDWPT KLM123 EXIT1,,,,SPY")
  -- a level condition said with "it passes / reaches / leaves"
  check_eq(tr("please descend AFR55 to FL150 and once it reaches FL250 slow it to 260 knots", w),
    "ALT AFR55 FL150 ; ATALT AFR55 FL250 SPD AFR55 260")
  -- "down to" straight after the callsign is the instruction word; the level said first never waits
  check_eq(tr("please take AFR55 down to FL150 and once it reaches FL250 slow it to 260 knots", w),
    "ALT AFR55 FL150 ; ATALT AFR55 FL250 SPD AFR55 260")
  check_eq(tr("AFR55 descend FL100, when it leaves FL200 turn right heading 220", w),
    "ALT AFR55 FL100 ; ATALT AFR55 FL200 HDG AFR55 220 RIGHT")
  check_eq(tr("hold the sim, then let me look at the route of AFR55", ww), "HOLD ; LISTRTE AFR55")
  local r = grammar.translate("add it to AFR55's route", ww)
  check(r.ask ~= nil and not r.ask:find("EXIT1", 1, true), tostring(r.ask))
end

do -- a place named that no command carries is asked about by name; one a direct-to passes, or an abbreviation, is not
  local w = { aircraft = { plane("KLM12", 110, 27000, 300, { "LAMSO", "SUGOL" }) },
    waypoints = { "LAMSO", "SUGOL", "ARTIP" } }
  check_eq(tr("klm12 dc sugol fl230", w), "ASK I have ALT KLM12 FL230. What does 'sugol' mean?")
  check_eq(tr("KLM12 climb FL300 for EHAM", w), "ASK I have ALT KLM12 FL300. What does 'EHAM' mean?")
  check_eq(tr("KLM12 skip LAMSO, route direct SUGOL", w), "DIRECT KLM12 SUGOL")
  check_eq(tr("KLM12 turn left heading 360, maintain VFR", w), "HDG KLM12 360 LEFT")
  check_eq(tr("KLM12 after LAMSO add the waypoint ARTIP", w), "ADDWPT KLM12 ARTIP,,,LAMSO")
  -- (a place the route holds already, inserted again beside another, is asked: cycle 79)
  check_eq(tr("KLM12 after LAMSO add the waypoint SUGOL", w),
    "ASK SUGOL is already on the route of KLM12. Should it be added a second time?")
end

do -- a distance from a place before an instruction is its condition (ATDIST, NM); one past a place is asked
  local w = { aircraft = { plane("KLM12", 110, 27000, 300, { "LAMSO", "SUGOL" }) }, waypoints = { "LAMSO", "SUGOL" } }
  check_eq(tr("KLM12, when fifteen miles from SUGOL descend flight level eight zero", w),
    "ATDIST KLM12 SUGOL 15 ALT KLM12 FL80")
  check_eq(tr("KLM12 within 10 NM of LAMSO reduce speed 250", w), "ATDIST KLM12 LAMSO 10 SPD KLM12 250")
  check_eq(tr("KLM12 alt 8000 at 30nm from SUGOL", w), "ATDIST KLM12 SUGOL 30 ALT KLM12 8000")
  check(asks("KLM12 ten miles past SUGOL descend flight level eight zero", w), "a distance past a place is asked")
end

do -- turn letters typed before "hdg" or after its value; "by N" turns by N; "the heading of N ... right" is a heading
  local w = { aircraft = { plane("RYR5FE", 120, 25000, 280) } }
  check_eq(tr("ryr5fe lt hdg 250", w), "HDG RYR5FE 250 LEFT")
  check_eq(tr("ryr5fe hdg 060 l fl150", w), "HDG RYR5FE 60 LEFT ; ALT RYR5FE FL150")
  check_eq(tr("ryr5fe rt hdg 120 fl350", w), "HDG RYR5FE 120 RIGHT ; ALT RYR5FE FL350")
  check_eq(tr("ryr5fe turn right by 20", w), "HDG RYR5FE 140 RIGHT")
  local long = grammar.translate("ryr5fe turn right by 200 and climb FL300", w)
  check((long.confirm_first or ""):find("the long way round", 1, true) ~= nil, "a turn by more than 180 is confirmed")
  check_eq(table.concat(long.commands, " ; "), "HDG RYR5FE 320 RIGHT ; ALT RYR5FE FL300")
  check_eq(tr("RYR5FE please go to the heading of 200 degree on the right side", w), "HDG RYR5FE 200 RIGHT")
  check_eq(tr("bring RYR5FE round left onto two nine zero and down to eight thousand feet", w),
    "HDG RYR5FE 290 LEFT ; ALT RYR5FE 8000")
end

do -- the sign of a vertical speed said after it; "a thousand" is one thousand
  local w = { aircraft = { plane("GLO1420", 90, 25000, 280) } }
  check_eq(tr("For GLO 1420 the vertical speed must be 1800 feet per minute descending", w), "VS GLO1420 -1800")
  check_eq(tr("GLO1420 vs 1800 fpm climbing", w), "VS GLO1420 1800")
  check_eq(tr("GLO1420 descend to 9000 with a thousand foot a minute descent", w), "ALT GLO1420 9000 1000")
end

do -- a keyword in capitals is that word ("RPZ"); "advise when able direct X" is no clearance; a visual approach is not simulated
  local w = { aircraft = { plane("UAL9", 90, 25000, 280, { "BENKY" }) }, waypoints = { "BENKY" } }
  check_eq(tr("turn resolution on and set RPZ to 5 NM", w), "RESO MVP ; ZONER 5")
  check_eq(tr("UAL9 CLIMB FL300", w), "ALT UAL9 FL300")
  check_eq(tr("UAL9, fly heading zero seven zero, advise when able direct BENKY", w), "HDG UAL9 70")
  local r = grammar.translate("UAL9, cleared for the FMS bridge visual runway two eight right", w)
  check(#r.commands == 0 and r.note ~= nil, "a visual approach is named as not simulated")
end

do -- a new waypoint put at a position; glued typed forms; a turn letter after a level
  check_eq(tr("put a waypoint called TEST1 at 52.3 north 4.7 east"), "DEFWPT TEST1 52.3 4.7")
  check_eq(tr("waypoint TEST1 at 52.3N 4.7E please"), "DEFWPT TEST1 52.3 4.7")
  local w = { aircraft = { plane("KLM12", 110, 27000, 300) } }
  check_eq(tr("klm12fl240", w), "ALT KLM12 FL240")
  check_eq(tr("klm12 m78", w), "SPD KLM12 M0.78")
  check_eq(tr("klm12 spd280", w), "SPD KLM12 280")
  check_eq(tr("klm12 fl 310 rt 160", w), "ALT KLM12 FL310 ; HDG KLM12 160 RIGHT")
  check_eq(tr("put a new aircraft TEST9 A320 at 52 north 4 east"), "CRE TEST9 A320 52 4")
end

do -- a route said as places in order: each added, the last airport after "to" the destination
  local w = { aircraft = { plane("EZY45", 45, 30000, 290) }, waypoints = { "TEST1", "LAMSO", "SUGOL" } }
  check_eq(tr("route EZY45 via TEST1 to EHAM", w), "ADDWPT EZY45 TEST1 ; DEST EZY45 EHAM")
  check_eq(tr("give EZY45 a route: LAMSO then SUGOL", w), "ADDWPT EZY45 LAMSO ; ADDWPT EZY45 SUGOL")
  check_eq(tr("route EZY45 via TEST1, LAMSO and SUGOL to EHAM", w),
    "ADDWPT EZY45 TEST1 ; ADDWPT EZY45 LAMSO ; ADDWPT EZY45 SUGOL ; DEST EZY45 EHAM")
end

do -- "cross X at <level or speed>": an AT constraint at a waypoint of the route; off the route it is asked
  local w = { aircraft = { plane("AAL2307", 90, 15000, 280, { "CAMRN" }) }, waypoints = { "CAMRN", "OTHER" } }
  check_eq(tr("American twenty-three oh seven, cross CAMRN at one one thousand.", w), "AT AAL2307 CAMRN ALT 11000")
  check_eq(tr("AAL2307 cross CAMRN at and maintain flight level one two zero", w), "AT AAL2307 CAMRN ALT FL120")
  check_eq(tr("AAL2307 cross CAMRN at 250 knots", w), "AT AAL2307 CAMRN SPD 250")
  check(asks("AAL2307 cross OTHER at one one thousand", w), "a crossing off the route is asked")
  -- the same constraint said as the level to be at, named after the waypoint, or as a level/speed pair
  check_eq(tr("AAL2307 to be at CAMRN at FL120", w), "AT AAL2307 CAMRN ALT FL120")
  check_eq(tr("AAL2307 should be at 9000 feet over CAMRN", w), "AT AAL2307 CAMRN ALT 9000")
  check_eq(tr("American 2307, at CAMRN be at flight level one two zero", w), "AT AAL2307 CAMRN ALT FL120")
  check_eq(tr("AAL2307 CAMRN speed restriction 230 knots", w), "AT AAL2307 CAMRN SPD 230")
  check_eq(tr("AAL2307 at CAMRN FL100 220", w), "AT AAL2307 CAMRN ALT FL100 ; AT AAL2307 CAMRN SPD 220")
  check(asks("AAL2307 to be at FL120 over OTHER", w), "a level to be at off the route is asked")
  check(asks("AAL2307 at CAMRN FL100 heading 220", w), "a heading at a waypoint is asked")
  check(asks("AAL2307 be at FL120 over CAMRN and 250 knots", w), "values on both sides of the waypoint are asked")
  -- the constraints at a waypoint asked for: AT with no value shows them
  check_eq(tr("show me the constraints AAL2307 has at CAMRN", w), "AT AAL2307 CAMRN")
  check_eq(tr("what restrictions does American 2307 have at CAMRN?", w), "AT AAL2307 CAMRN")
  check(asks("show me the constraints AAL2307 has at OTHER", w), "a waypoint off the route is asked about")
end

do -- "fast-forward" after the simulation is named is fast-forward, not a faster clock
  check_eq(tr("pause the sim, then fast-forward 10 minutes"), "HOLD ; FF 600")
end

do -- a typed ".78" beside other values is a Mach number
  local w = { aircraft = { plane("DLH402", 90, 25000, 280) } }
  check_eq(tr("dlh402 fl250 .78", w), "ALT DLH402 FL250 ; SPD DLH402 M0.78")
end

do -- sim control and questions in other words; a route cleared; "fly to" a known waypoint is a direct-to
  local w = { aircraft = { plane("KLM12", 110, 27000, 300, { "SUGOL" }) }, waypoints = { "TEST1", "SUGOL" } }
  check_eq(tr("run it"), "OP")
  check_eq(tr("and go again"), "OP")
  check_eq(tr("ok, carry on, unfreeze"), "OP")
  check_eq(tr("speed up 10x"), "DTMULT 10")
  check_eq(tr("speed the sim up, times three"), "DTMULT 3")
  check_eq(tr("what's klm12 doing", w), "POS KLM12")
  check_eq(tr("route of klm12?", w), "LISTRTE KLM12")
  check_eq(tr("Could you add TEST1 to the route of KLM12?", w), "ADDWPT KLM12 TEST1")
  check(tr("Could you add SUGOL to the route of KLM12?", w):find("already on the route", 1, true) ~= nil,
    "a waypoint the route holds is asked before it is added again")
  check_eq(tr("clear the route of KLM12", w), "DELRTE KLM12")
  check_eq(tr("remove SUGOL from the route of KLM12", w), "DELWPT KLM12 SUGOL")
  check_eq(tr("KLM12, fly to TEST1 please", w), "ADDWPT KLM12 TEST1 ; DIRECT KLM12 TEST1")
end

do -- an aircraft that flies put at a position is moved; sent to an airport, its destination
  local w = { aircraft = { plane("N345CS", 90, 5000, 120), plane("AAL100", 90, 5000, 250) } }
  check_eq(tr("Put the Cessna N345CS at 42.0 -88.3, 3000 feet.", w), "MOVE N345CS 42 -88.3 3000")
  check_eq(tr("put N345CS over SPY at fl200", w), "MOVE N345CS SPY FL200")
  check_eq(tr("Send AAL100 to KBOS and have it climb to 10,000.", w), "DEST AAL100 KBOS ; ALT AAL100 10000")
  check(asks("Put a new Cessna N999 at 42.0 -88.3", w), "a callsign that does not fly is not moved")
end

do -- a question about a setting gives the bare command, which shows it
  check_eq(tr("Is conflict detection switched on?"), "ASAS")
  check_eq(tr("what's the current zone radius?"), "ZONER")
  check_eq(tr("What look-ahead time are we using at the moment?"), "DTLOOK")
  check_eq(tr("which resolution method is active?"), "RESO")
  check_eq(tr("set the zone radius to 5 nm"), "ZONER 5")
  check_eq(tr("switch conflict detection on"), "ASAS ON")
end

do -- "turning" is a turn
  local w = { aircraft = { plane("JJP503", 300, 25000, 280) } }
  check_eq(tr("Can you make JJP503 turning left for 90 degree?", w), "HDG JJP503 210 LEFT")
end

do -- typed shorthand for two aircraft, each with a value of its own unit; a bare fragment still asks
  local w = { aircraft = { plane("KLM12", 110, 27000, 300), plane("EZY45", 45, 30000, 290) } }
  check_eq(tr("klm12 fl250 ezy45 fl310", w), "ALT KLM12 FL250 ; ALT EZY45 FL310")
  check_eq(tr("KLM12 turn right heading 160 EZY45 2", w), "ASK I have HDG KLM12 160 RIGHT. What does 'EZY45 2' mean?")
end

do -- a level typed digit by digit
  local w = { aircraft = { plane("VLG23KA", 90, 30000, 280) } }
  check_eq(tr("vlg23ka fl 3 4 0", w), "ALT VLG23KA FL340")
end

do -- where several aircraft are: each shown
  local w = { aircraft = { plane("TEST01", 90, 20000, 250), plane("TEST03", 90, 20000, 250) } }
  check_eq(tr("Pause it and show me where TEST01 and TEST03 are.", w), "HOLD ; POS TEST01 ; POS TEST03")
end

do -- a waypoint added at a decimal position with no aircraft is defined; the sim sped up "to N times"
  check_eq(tr("add a waypoint BRAVO 51.75 -1.25"), "DEFWPT BRAVO 51.75 -1.25")
  check_eq(tr("speed the sim up to twenty times real time"), "DTMULT 20")
end
