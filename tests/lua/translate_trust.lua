-- English a controller can trust (docs/translator_trust.md): every value
-- accounted for, turns the way they were said, TrafScript passed through,
-- destructive requests confirmed, what squawk does not simulate named, and
-- inexact callsigns asked about.
local graph = require("translate.graph")

local function said(r)
  return r.ask and ("ASK " .. r.ask) or table.concat(r.commands or {}, " ; ")
end
-- A simulator set up by TrafScript lines (each must run), and a function that translates a text
-- offline against it, returning what squawk says: "ASK ..." or the commands joined by " ; ".
local function set_up(s, lines)
  for _, line in ipairs(lines) do
    check(s:exec(line), line)
  end
  return s, function(text) return said(graph.translate(text, { sim = s, mode = "offline" })) end
end
local function scene(lines) return set_up(squawk.sim.new(), lines) end
-- The same over BlueSky's navdata at ../shared/bluesky/navdata; nil after saying which checks ("why")
-- are skipped when it is absent.
local function navscene(lines, why)
  local ok, s = pcall(squawk.sim.new, { navdata = "../shared/bluesky/navdata" })
  if not ok then
    print("skipped: " .. why .. " need BlueSky's navdata at ../shared/bluesky/navdata")
    return nil
  end
  return set_up(s, lines)
end
-- What squawk said (`said`'s text) is a question; `why` names the case in a failure.
local function asked(text, why) check(text:match("^ASK") ~= nil, why) end

local sim = scene({ "CRE BAW8CK A320 52.0 4.0 025 FL200 250", "CRE KLM1234 B738 52.2 4.2 300 FL250 280",
    "CRE DLH4AX A321 52.4 4.4 090 FL300 280", "CRE KLM77 B738 52.1 4.5 180 FL150 250" })
local function tr(text) return graph.translate(text, { sim = sim, mode = "offline" }) end

-- 1. every value accounted for: a fragment left over is asked about, by name, and nothing runs
local r = tr("KLM1234 turn right heading 160 DLH4AX 2")
check_eq(said(r), "ASK I have HDG KLM1234 160 RIGHT. What does 'DLH4AX 2' mean?")
check_eq(r.commands, nil)
-- an instruction dropped is asked about too (a level said after a speed with no verb of its own)
r = tr("KLM1234 reduce speed 250 knots 12 thousand")
check(r.ask ~= nil and r.ask:find("'12 thousand'", 1, true) ~= nil, said(r))
-- "and" with a callsign and a value of its own is a second instruction of the same kind
check_eq(said(tr("turn KLM1234 to 010 and DLH4AX to 200")), "HDG KLM1234 10 ; HDG DLH4AX 200")
-- several instructions, none dropped
check_eq(said(tr("KLM1234 climb FL300 and reduce speed 250 knots")), "ALT KLM1234 FL300 ; SPD KLM1234 250")

-- typed shorthand: a letter-prefixed value is an instruction wherever it stands in the line,
-- each value used once; a leftover token with a digit in it is asked about by name
check_eq(said(tr("klm77 fl120 s230")), "ALT KLM77 FL120 ; SPD KLM77 230")
check_eq(said(tr("dlh4ax h 150 fl250")), "HDG DLH4AX 150 ; ALT DLH4AX FL250")
check_eq(said(tr("klm1234 r 010")), "HDG KLM1234 10 RIGHT")
check_eq(said(tr("baw8ck l320 s240")), "HDG BAW8CK 320 LEFT ; SPD BAW8CK 240")
check_eq(said(tr("klm77 fl110 rod 1200")), "ALT KLM77 FL110 ; VS KLM77 -1200")
check_eq(said(tr("dlh4ax roc 800")), "VS DLH4AX 800")
check_eq(said(tr("klm77 fl120 q9")), "ASK I have ALT KLM77 FL120. What does 'q9' mean?")
check_eq(said(tr("klm77 fl120 6")), "ASK I have ALT KLM77 FL120. What does '6' mean?")
-- an aircraft named that no command carries: the request was not all understood
check_eq(said(tr("freeze the simulation, KLM77 looks fine")), "ASK I have HOLD. What does 'KLM77' mean?")
check_eq(said(tr("freeze the simulation and then tell me where KLM77 is")), "HOLD ; POS KLM77")
check_eq(said(tr("where's DLH4AX?")), "POS DLH4AX")
check_eq(said(tr("KLM1234 climb FL320 to avoid a conflict with KLM77")), "ALT KLM1234 FL320")
-- a duration said but not understood asks; a time no command carries is a leftover
check_eq(said(tr("please fast forward the sim")), "FF")
check_eq(said(tr("fast forward a little while")), "ASK For how long should the simulation fast-forward? Please give a time.")
check_eq(said(tr("after 10 minutes remove KLM77")), "DELAY 600 DEL KLM77")
check_eq(said(tr("KLM1234 climb FL300 and in 2 minutes KLM77 descend FL100")),
  "ALT KLM1234 FL300 ; DELAY 120 ALT KLM77 FL100")
check_eq(said(tr("dtmult 6 and show trails")), "DTMULT 6 ; TRAIL ON")
-- a second thing said in one breath is made too, or asked about, never dropped
check_eq(said(tr("define waypoint P1 at 51.0 3.0 and P2 at 51.5 3.5")), "DEFWPT P1 51 3 ; DEFWPT P2 51.5 3.5")
check_eq(said(tr("define waypoint P1 at 51.0 3.0 and P2")), "ASK Where is waypoint P2? Please give a latitude and longitude.")
-- a position typed as whole degrees after the hemisphere, then minutes; a waypoint's type said "make it a ..."
check_eq(said(tr("define waypoint P1 at N52 30.0 E004 45.0 and make it a fix")), "DEFWPT P1 52.5 4.75 FIX")
check_eq(said(tr("define waypoint P1 at S33 57 W070 06, make it a VOR")), "DEFWPT P1 -33.95 -70.1 VOR")
check_eq(said(tr("cre KLM12 B738 N52 18.0 E004 30.0 090 FL100 250")), "CRE KLM12 B738 52.3 4.5 90 FL100 250")
r = tr("klm77 fl120 sq 1234")
check(said(r) == "ALT KLM77 FL120" and r.note:find("transponder codes", 1, true) ~= nil, said(r))
check_eq(said(tr("klm1234 fl280 h320")), "ALT KLM1234 FL280 ; HDG KLM1234 320")
check_eq(said(tr("dlh4ax fl310 m.80")), "ALT DLH4AX FL310 ; SPD DLH4AX M0.8")
check_eq(said(tr("klm77 lt 15 deg")), "HDG KLM77 165 LEFT")
check_eq(said(tr("dlh4ax rt 40\u{B0}")), "HDG DLH4AX 130 RIGHT")
check_eq(said(tr("KLM1234 25 degrees left")), "HDG KLM1234 275 LEFT")
check_eq(said(tr("klm77 rte?")), "LISTRTE KLM77")
check_eq(said(tr("klm77 pos?")), "POS KLM77")
-- a typed callsign split after its airline is that aircraft only when the joined id is exact
check(said(tr("klm 1243 fl310")):find("^ASK") ~= nil, said(tr("klm 1243 fl310")))
check_eq(said(tr("klm 1234 fl310")), "ALT KLM1234 FL310")
-- a correction followed by its new value: the value after it counts, however it is said
check_eq(said(tr("KLM77 descend flight level one three zero correction one one zero")), "ALT KLM77 FL110")
check_eq(said(tr("BAW8CK speed two two zero knots correction two four zero")), "SPD BAW8CK 240")
check_eq(said(tr("KLM77 turn left heading one nine her five")), "HDG KLM77 195 LEFT")
check_eq(said(tr("make the simulation speed four times")), "DTMULT 4")
-- sim control said in other words; RESO's one method is what "on" means
check_eq(said(tr("please skip two hours forward")), "FF 7200")
check_eq(said(tr("advance the sim fast for 2 minutes")), "FF 120")
check_eq(said(tr("go on with the sim please")), "OP")
check_eq(said(tr("set the time speed factor to 5")), "DTMULT 5")
check_eq(said(tr("switch resolution on")), "RESO MVP")
check_eq(said(tr("zone 4nm")), "ZONER 4")
r = tr("KLM1234 climb FL300, expedite through FL270")
check(said(r) == "ALT KLM1234 FL300" and r.note:find("expedite", 1, true) ~= nil, said(r))
check_eq(said(tr("KLM77 report me your altitude")), "POS KLM77")
-- false friends and prepositions of other languages: "actual" is the present value, "sink to a
-- level" a descent, "feet for minute" a rate; a large step in feet is the cleared altitude
check_eq(said(tr("KLM1234 keep the actual heading")), "HDG KLM1234 300")
check_eq(said(tr("KLM77 sink to flight level 90")), "ALT KLM77 FL90")
check_eq(said(tr("DLH4AX descend 12000 feet")), "ALT DLH4AX 12000")
check_eq(said(tr("BAW8CK descend flight level 150 with 1800 feet for minute")), "ALT BAW8CK FL150 1800")

-- every word accounted for (lexicon.accounted): a negation or a condition no command carries, and a word
-- squawk does not know, are asked about by name and nothing runs
check_eq(said(tr("KLM1234 don't climb FL340")), "ASK I have ALT KLM1234 FL340. What does 'don't' mean?")
check_eq(said(tr("DLH4AX never turn left heading 200")), "ASK I have HDG DLH4AX 200 LEFT. What does 'never' mean?")
check_eq(said(tr("descend KLM77 to FL100 unless you hear otherwise")),
  "ASK I have ALT KLM77 FL100. What does 'unless' mean?")
check_eq(said(tr("KLM1234 climb FL340 after the sim restarts")),
  "ASK I have ALT KLM1234 FL340. What does 'after' mean?")
check_eq(said(tr("if the clock runs, DLH4AX descend FL200")), "ASK I have ALT DLH4AX FL200. What does 'if' mean?")
r = tr("KLM1234 climb FL340 gently")
check_eq(said(r), "ASK I have ALT KLM1234 FL340. What does 'gently' mean?")
check_eq(r.commands, nil)
check_eq(said(tr("BAW8CK wobble heading 090")), "ASK I have HDG BAW8CK 90. What does 'wobble' mean?")
-- polite and radiotelephony framing is accounted for: closed-class words, courtesy, "good day", a
-- polite "if" ("if that's alright", "I'd appreciate it if ... could"), "when you get a chance"
check_eq(said(tr("could you please climb KLM1234 to FL340, thanks")), "ALT KLM1234 FL340")
check_eq(said(tr("DLH4AX, good day, turn left heading 200")), "HDG DLH4AX 200 LEFT")
check_eq(said(tr("I'd appreciate it if KLM77 could descend to FL100")), "ALT KLM77 FL100")
check_eq(said(tr("KLM77 reduce speed to 220 knots if that's alright")), "SPD KLM77 220")
check_eq(said(tr("when you get a chance, would you have BAW8CK climb to FL240")), "ALT BAW8CK FL240")
check_eq(said(tr("I think DLH4AX should go a bit faster, maybe 300 knots")), "SPD DLH4AX 300")
-- a condition carried by a conditional command explains its word; a comment or a purpose with no
-- instruction, value or aircraft in it explains itself; inflections of known words are known
check_eq(said(tr("KLM1234 descend FL200, when passing FL220 reduce speed 250")),
  "ALT KLM1234 FL200 ; ATALT KLM1234 FL220 SPD KLM1234 250")
check_eq(said(tr("delete KLM77, we don't need it any more")), "DEL KLM77")
check_eq(said(tr("pause the simulation so I can brief the participants")), "HOLD")
check_eq(said(tr("KLM1234 keeping FL250, turn left heading 200")), "ALT KLM1234 FL250 ; HDG KLM1234 200 LEFT")
check_eq(said(tr("DLH4AX descend FL200, rate 2000 feet per minute or greater")), "ALT DLH4AX FL200 2000")

-- 2. turns the way they were said; relative turns in whole degrees; past 180 degrees asks yes/no
check_eq(said(tr("BAW8CK turn right heading 300")), "HDG BAW8CK 300 RIGHT")
check_eq(said(tr("BAW8CK turn left heading 020")), "HDG BAW8CK 20 LEFT")
check_eq(said(tr("BAW8CK fly heading 300")), "HDG BAW8CK 300")
check_eq(said(tr("KLM1234 turn left ten degrees")), "HDG KLM1234 290 LEFT")
r = tr("KLM1234 turn left 200 degrees")
check(r.ask ~= nil and r.ask:find("left by 200 degrees", 1, true) ~= nil, said(r))
check_eq(r.confirm and r.confirm.commands[1], "HDG KLM1234 100 LEFT")

-- 4. TrafScript typed in English mode runs as typed, and the trace says so
for _, typed in ipairs({ "FF 60", "HOLD", "op", "HDG KLM1234 270", "hdg klm1234 270 right", "KLM1234 ALT FL100" }) do
  r = tr(typed)
  check(r.typed == true, typed .. " passes through")
  check(r.trace[2] and r.trace[2].node == "typed", typed .. ": the trace names the typed node")
end
check_eq(said(tr("KLM1234 ALT FL100")), "ALT KLM1234 FL100")
check_eq(said(tr("FF 60")), "FF 60")
-- English that happens to start with a command word stays English
check(not tr("turn KLM1234 north").typed, "a compass word is English")
-- a conditional's command typed without its aircraft gets the condition's
check_eq(said(tr("klm1234 atalt fl080 spd 210")), "ATALT klm1234 fl080 spd klm1234 210")
check(not tr("delete the aircraft").typed, "glue words are English")
-- a callsign spelled in the phonetic alphabet that starts with a command's name (ECHO) is English;
-- ECHO with a message stays TrafScript
do
  local ga = squawk.sim.new()
  check(ga:exec("CRE ECKJB P28A 40.8 -3.9 180 6500 110"))
  check(ga:exec("CRE EDFXA C172 40.9 -3.8 090 4500 100"))
  local function gt(text) return graph.translate(text, { sim = ga, mode = "offline" }) end
  check_eq(said(gt("Echo Charlie Kilo Juliett Bravo, climb to seven thousand five hundred feet")), "ALT ECKJB 7500")
  check_eq(said(gt("echo charlie kilo juliett bravo reduce speed nine zero knots")), "SPD ECKJB 90")
  check_eq(said(gt("Echo Delta Foxtrot Xray Alfa turn left heading two seven zero")), "HDG EDFXA 270 LEFT")
  check(not gt("Echo Delta Foxtrot Xray Alfa, descend three thousand feet").typed, "a spelled callsign is English")
  check(gt("ECHO hello world").typed == true, "ECHO with a message runs as typed")
  check(gt("echo sector Bravo opens").typed == true, "a message that spells nothing runs as typed")
end
-- a preposition is no argument: "create X at Y" is English (CRE would take "AT" for the type)
check(not tr("create KLM77 at 52 4").typed, "a preposition is English")
check(tr("create KLM77 at 52 4").ask ~= nil, "a create with no type asks")
do  -- (the AT command's own name stays TrafScript)
  local routed = squawk.sim.new()
  check(routed:exec("CRE KL9 A320 52 4 90 FL250 280"))
  check(routed:exec("DEFWPT WP1 52.1 4.5"))
  check(routed:exec("ADDWPT KL9 WP1"))
  local rt = graph.translate("at KL9 WP1 ALT FL120", { sim = routed, mode = "offline" })
  check(rt.typed == true, "AT typed runs as typed")
  check_eq(said(rt), "AT KL9 WP1 ALT FL120")
end
-- a condition's command is TrafScript too: run as typed when it parses, asked about when not
check_eq(said(tr("SCHEDULE 60 HOLD")), "SCHEDULE 60 HOLD")
check_eq(said(tr("delay 60 hdg klm1234 270 right")), "DELAY 60 hdg klm1234 270 right")
check_eq(said(tr("klm1234 atalt fl080 spd klm1234 210")), "ATALT klm1234 fl080 spd klm1234 210")
r = tr("klm1234 atalt fl080 spd")  -- parses neither as typed nor with the aircraft filled in
check(#(r.commands or {}) == 0 and (r.ask or ""):find("ATALT carries 'spd'", 1, true) ~= nil, said(r))

-- 5. destructive and global requests wait for a yes
local function dialogue() return graph.dialogue({ sim = sim, mode = "offline" }) end
local d = dialogue()
r = d:say("delete all aircraft")
check(r.ask ~= nil and r.ask:find("Delete 4 aircraft", 1, true) ~= nil, said(r))
check_eq(r.commands, nil)
r = d:say("yes")
check_eq(said(r), "DEL BAW8CK ; DEL KLM1234 ; DEL DLH4AX ; DEL KLM77")
check(r.confirmed == true, "the yes is recorded")
d = dialogue()
check(d:say("reset the simulation").ask ~= nil, "RESET asks")
r = d:say("no")
check(r.cancelled == true and #r.commands == 0, "no drops it")
d = dialogue()
check(d:say("RESO OFF").ask ~= nil, "resolution off for everyone asks, typed or said")
r = d:say("KLM1234 climb FL300")
check_eq(said(r), "ALT KLM1234 FL300")
check(r.dropped ~= nil, "another request drops the question and is read as itself")
d = dialogue()
check_eq(said(d:say("delete KLM77")), "DEL KLM77")
d = dialogue()
check(d:say("KLM1234 turn left 200 degrees").ask ~= nil, "the long turn asks")
check_eq(said(d:say("affirm")), "HDG KLM1234 100 LEFT")
-- a yes runs the whole request, not only what was asked about, and each question is asked once
d = dialogue()
check(d:say("KLM1234 turn left 200 degrees and climb FL300").ask ~= nil, "the long turn asks")
check_eq(said(d:say("yes")), "HDG KLM1234 100 LEFT ; ALT KLM1234 FL300")
d = dialogue()
check(d:say("KLM1243 turn left 200 degrees and climb FL300").ask:find("Did you mean KLM1234", 1, true) ~= nil,
  "the callsign is asked about first")
check(said(d:say("yes")):find("long way round", 1, true) ~= nil, "then the long turn")
check_eq(said(d:say("yes")), "HDG KLM1234 100 LEFT ; ALT KLM1234 FL300")

-- 6. what squawk does not simulate is named, the rest runs
r = tr("KLM1234 squawk 7700")
check(#r.commands == 0 and r.note:find("transponder codes", 1, true) ~= nil, tostring(r.note))
check_eq(r.error, nil)
r = tr("KLM1234 contact approach 119.7 and descend FL100")
check_eq(said(r), "ALT KLM1234 FL100")
check(r.note:find("radio frequencies", 1, true) ~= nil, tostring(r.note))
r = tr("KLM1234, cleared for the river visual runway two eight right")
check(#r.commands == 0 and (r.note or ""):find("approach clearances", 1, true) ~= nil, said(r))

-- 3. callsigns exact or asked: a transposed or shortened typed callsign names the candidates
r = tr("KLM1243 climb flight level 300")
check_eq(r.ask, "Did you mean KLM1234? There is no KLM1243.")
check_eq(r.confirm and r.confirm.id, "KLM1234")
r = tr("KLM7 climb FL300")
check_eq(r.ask, "Did you mean KLM77? There is no KLM7.")
check_eq(tr("KLM climb FL300").ask, "Which KLM: KLM1234 or KLM77?")
d = dialogue()
d:say("KLM1243 climb flight level 300")
check_eq(said(d:say("yes")), "ALT KLM1234 FL300")
-- a spoken callsign whose digits differ from the only fitting aircraft asks while others fly
r = tr("KLM one two four three climb flight level 300")
check(r.ask ~= nil and r.ask:find("KLM1234", 1, true) ~= nil, said(r))
-- with one aircraft in the sky too: a callsign close to it (transposed digits, a digit or its
-- last letters unheard, letters that spell none) is asked about, an exact one is taken
local lone = squawk.sim.new()
check(lone:exec("CRE ACA851 A320 52 4 090 FL200 250"))
local _, one = set_up(lone, {})
check(one("air canada eight one five climb FL300"):find("^ASK Did you mean ACA851%? I heard ACA81") ~= nil, "transposed")
check_eq(one("air canada eight five climb FL300"), "ASK Did you mean ACA851? I heard ACA85.")
check_eq(one("ACA815 climb FL300"), "ASK Did you mean ACA851? There is no ACA815.")
check_eq(one("air canada eight five one climb FL300"), "ALT ACA851 FL300")
check_eq(one("ACA851 climb FL300"), "ALT ACA851 FL300")
-- an airline's two-letter code is a partial callsign squawk has no table for: asked, alone or not
check_eq(one("The AC 851 should descend on FL120"), "ASK Did you mean ACA851? I heard AC851.")
-- an aircraft's exact id glued to a level or a shorthand value is the id and the value
check_eq(one("aca851fl240"), "ALT ACA851 FL240")
check_eq(one("ACA851S250"), "SPD ACA851 250")
check_eq(one("aca85fl240"):find("^ASK") ~= nil, true)
-- a corrected callsign: the one after the correction is instructed, never the one before it
local azu, cor = scene({ "CRE AZU4014 A320 52 4 090 FL200 250", "CRE AZU4041 A320 52.2 4 090 FL200 250",
    "CRE KLM12 B738 52.4 4 090 FL200 250", "CRE KLM21 B738 52.6 4 090 FL200 250" })
check_eq(cor("azul four zero one four correction four zero four one reduce speed two two zero"), "SPD AZU4041 220")
check_eq(cor("AZU4014 correction 4041 reduce speed 220"), "SPD AZU4041 220")
check_eq(cor("KLM12 correction KLM21 climb FL300"), "ALT KLM21 FL300")
check_eq(cor("KLM12 climb FL300, correction KLM21"), "ALT KLM21 FL300")
check_eq(cor("KLM12 descend FL120 correction FL110"), "ALT KLM12 FL110")
check_eq(cor("AZU4014 correction 4099 reduce speed 220"), "ASK There is no aircraft AZU4099. Which aircraft do you mean?")
-- fixes: a name that only sounds like one of several known names is confirmed, never substituted
local wsim = sim:copy()
check(wsim:exec("DEFWPT SQK01 52.3 4.3"))
check(wsim:exec("DEFWPT SPIKE 52.5 4.5"))
r = graph.translate("KLM1234 direct to sparky", { sim = wsim, mode = "offline", waypoints = { "SQK01", "SPIKE" } })
check_eq(r.ask, "Did you mean SPIKE? I heard 'sparky'.")
-- the only name known that sounds like the word said is confirmed too, never substituted
local osim = sim:copy()
check(osim:exec("DEFWPT WAVEY 52.3 4.3"))
r = graph.translate("KLM1234 direct way", { sim = osim, mode = "offline", waypoints = { "WAVEY" } })
check_eq(r.ask, "Did you mean WAVEY? I heard 'way'.")
check_eq(said(graph.translate("KLM1234 direct wavey", { sim = osim, mode = "offline", waypoints = { "WAVEY" } })),
  "ADDWPT KLM1234 WAVEY ; DIRECT KLM1234 WAVEY")
-- the spelling fixer turns no command's name and no word of what is not simulated into another
-- word: "delrte" is no "delete" (DEL would delete the aircraft), "holding" no "heading"
check_eq(said(tr("delrte for KLM1234")), "DELRTE KLM1234")
check(said(tr("KLM1234 holding 270")):find("HDG", 1, true) == nil, said(tr("KLM1234 holding 270")))
check_eq(said(tr("KLM1234 headng 270")), "HDG KLM1234 270")
-- a command's name said with its value: each value is the dimension named last before it
check_eq(said(tr("zoner 3 zonedh 500")), "ZONER 3 ; ZONEDH 500")
check_eq(said(tr("zonedh 300 zoner 3")), "ZONEDH 300 ; ZONER 3")
-- an airport said by its name is the navdata's airport (when navdata is loaded)
if #sim:airports_named("schiphol") == 1 then
  check_eq(said(graph.translate("KLM1234 direct to Schiphol", { sim = wsim, mode = "offline",
    waypoints = { "SQK01", "SPIKE" } })), "ADDWPT KLM1234 EHAM ; DIRECT KLM1234 EHAM")
  -- a word of a longer name ("Point Reyes": Reyes Airport is in Bolivia) names no airport; a
  -- navaid said by its navdata name near the aircraft is that navaid
  local us = squawk.sim.new()
  check(us:exec("CRE JBU1116 A320 37.75 -122.55 300 FL150 280"))
  check(us:exec("CRE FDX1288 B763 40.6 -73.9 090 FL150 280"))
  local _, ustr = set_up(us, {})
  check_eq(ustr("JetBlue 1116 proceed direct Point Reyes"), "ADDWPT JBU1116 PYE ; DIRECT JBU1116 PYE")
  check_eq(ustr("FedEx 1288 proceed direct Canarsie"), "ADDWPT FDX1288 CRI ; DIRECT FDX1288 CRI")
  -- (Canarsie is 2000 NM from JBU1116: no navaid of that name near it)
  check(ustr("JetBlue 1116 proceed direct Canarsie"):find("CRI", 1, true) == nil, "far navaid")
  -- a place where an aircraft is put or moved is named like one it is sent to: a navaid of that
  -- name near the traffic; an airport of that name near the aircraft before one far away
  check_eq(ustr("create UAL9 a B738 at Canarsie heading 090 FL200 280 knots"), "CRE UAL9 B738 CRI 90 FL200 280")
  -- "at Kennedy": the airport beside the navaid of that name, as "at JFK" is (over it: the navaid)
  check_eq(ustr("create UAL9 a B738 at Kennedy heading 090 3000 feet 200 knots"), "CRE UAL9 B738 KJFK 90 3000 200")
  check_eq(ustr("create UAL9 a B738 over Kennedy heading 090 3000 feet 200 knots"), "CRE UAL9 B738 JFK 90 3000 200")
  -- "International" as the navdata writes it (INTL)
  local den = squawk.sim.new()
  check(den:exec("CRE EJA882 C68A 39.6 -103.8 270 FL410 M.80"))
  check_eq(said(graph.translate("Execjet 882 your new destination is Denver International", { sim = den,
    mode = "offline" })), "DEST EJA882 KDEN")
  check_eq(ustr("FedEx 1288 your new destination is LaGuardia"), "DEST FDX1288 KLGA")
  check_eq(said(graph.translate("create AAL7 an A321 at Kennedy, heading 040, 3000 feet, 210 knots",
    { sim = squawk.sim.new(), mode = "offline" })), "CRE AAL7 A321 KJFK 40 3000 210")
  check_eq(ustr("move JetBlue 1116 to Point Reyes at FL120"), "MOVE JBU1116 PYE FL120")
  -- with no traffic: an airport of that name first, else the one navaid of that name anywhere
  local empty = squawk.sim.new()
  local _, etr = set_up(empty, {})
  check_eq(etr("create UAL9 a B738 at Canarsie heading 090 FL200 280 knots"), "CRE UAL9 B738 CRI 90 FL200 280")
  check_eq(etr("create KLM5 a B738 at Schiphol heading 090 FL100 250 knots"), "CRE KLM5 B738 EHAM 90 FL100 250")
  local uk = squawk.sim.new()
  check(uk:exec("CRE BAW12 A320 52.2 -1.2 090 FL150 280"))
  check(uk:exec("CRE LOG5 DH8D 56.2 -3.7 045 FL70 220"))
  local _, ukt = set_up(uk, {})
  check_eq(ukt("Speedbird 12 destination Birmingham"), "DEST BAW12 EGBB")
  check_eq(ukt("Logan 5 resume own navigation direct Perth"), "ADDWPT LOG5 PTH ; DIRECT LOG5 PTH")
  -- a city said before the name of an airport near the aircraft, naming none itself ("Bergen Flesland",
  -- FLESLAND in the navdata); far from the aircraft the longer name is still no airport
  local no = squawk.sim.new()
  check(no:exec("CRE KLM1149 B738 59.4 10.8 010 FL140 290"))
  check_eq(said(graph.translate("KLM1149 is diverting to Bergen Flesland, change his destination",
    { sim = no, mode = "offline" })), "DEST KLM1149 ENBR")
  check(ustr("FedEx 1288 new destination Bergen Flesland"):find("ENBR", 1, true) == nil, "far airport")
  -- a navaid's two-word name near the aircraft before an airport named by its first word ("Zurich
  -- East" is the ZUE VOR, not Zurich airport and a word more)
  local ch = squawk.sim.new()
  check(ch:exec("CRE SWR12 A320 47.3 8.3 090 FL150 280"))
  local _, cht = set_up(ch, {})
  check(cht("swiss one two proceed direct zurich east"):find("DIRECT SWR12 ZUE", 1, true) ~= nil)
  check(cht("swiss one two proceed direct zurich"):find("DIRECT SWR12 LSZH", 1, true) ~= nil)
  -- an airport meant by its three-letter code beside its VOR (JFK -> KJFK), near or far; a large airport's
  -- IATA code (names.iata_airports) is that airport though another navaid of the code is nearer (LHR: the
  -- Lahr NDB)
  check_eq(ustr("set FDX1288's origin to JFK"), "ORIG FDX1288 KJFK")
  check_eq(ustr("JBU1116 destination SFO"), "DEST JBU1116 KSFO")
  check_eq(ukt("set the origin of BAW12 to JFK"), "ORIG BAW12 KJFK")
  check_eq(ukt("BAW12 destination LHR"), "DEST BAW12 EGLL")
  -- "send X to <airport by name>" is a destination
  check_eq(ukt("send Speedbird 12 to Gatwick"), "DEST BAW12 EGKK")
  check_eq(etr("create KLM5 a B738 at JFK heading 090 FL100 250 knots"), "CRE KLM5 B738 KJFK 90 FL100 250")
  check_eq(etr("create KLM5 a B738 over JFK heading 090 FL100 250 knots"), "CRE KLM5 B738 JFK 90 FL100 250")
  -- a destination said after a route's last place is issued, or asked about, never dropped
  check_eq(ukt("route BAW12 via DTY and then on to Heathrow"), "ADDWPT BAW12 DTY ; DEST BAW12 EGLL")
  check_eq(ustr("route FDX1288 via CRI to JFK"), "ADDWPT FDX1288 CRI ; DEST FDX1288 KJFK")
  local r2 = graph.translate("route BAW12 via DTY and on to Gotham City", { sim = uk, mode = "offline" })
  check(r2.ask ~= nil and r2.ask:find("'Gotham City'", 1, true) ~= nil, said(r2))
  -- an ICAO code spelled in the phonetic alphabet names the navdata's airport; one it lacks is asked about
  check_eq(ukt("Speedbird 12 destination echo golf papa foxtrot"), "DEST BAW12 EGPF")
  check_eq(ukt("set the origin of BAW12 to echo golf kilo kilo"), "ORIG BAW12 EGKK")
  check(ukt("BAW12 destination echo xray yankee zulu"):find("^ASK") ~= nil, "no such airport")
  -- a city whose airports the navdata names otherwise ("London": HEATHROW, GATWICK, beside the LONDON
  -- VOR) is no far airport that bears the name (CYXU, Ontario), nor one of its airports: asked which
  local lr = graph.translate("BAW12 destination London", { sim = uk, mode = "offline" })
  check(#(lr.commands or {}) == 0 and (lr.ask or ""):find("EGLL or", 1, true) ~= nil
    and lr.ask:find("CYXU", 1, true) == nil, said(lr))
  check_eq(ukt("BAW12 destination Gatwick"), "DEST BAW12 EGKK")
  check_eq(ukt("Speedbird 12 your destination Glasgow, echo golf papa foxtrot"), "DEST BAW12 EGPF")
  local gr = squawk.sim.new()
  check(gr:exec("CRE AEE601 A320 38.5 23.0 090 FL300 280"))
  -- ("Athens", the city English names otherwise: its airport ELEFTHERIOS VENIZELOS, lexicon.city_airports)
  check_eq(said(graph.translate("AEE601 destination Athens", { sim = gr, mode = "offline" })), "DEST AEE601 LGAV")
else
  print("skipped: airport names need navdata (SQUAWK_NAVDATA)")
end

-- spoken telephony split by speech recognition matches when every character does; a
-- partial flight number asks while other aircraft fly
local csim, ctr = scene({ "CRE BAW456 A320 51.5 0.2 090 FL150 250", "CRE RYR7TK B738 51.7 0.4 270 FL190 270",
    "CRE EZY33 A319 51.2 0.1 180 FL110 240", "CRE N77AB C172 51.3 0.5 000 3000 100" })
check_eq(ctr("speed bird four five six turn left heading one two zero"), "HDG BAW456 120 LEFT")
check_eq(ctr("ryan air seven tango kilo climb flight level two one zero"), "ALT RYR7TK FL210")
check_eq(ctr("easy jet three three reduce speed two two zero"), "SPD EZY33 220")
check_eq(ctr("speed bird four five turn left heading one two zero"), "ASK Did you mean BAW456? I heard BAW45.")
check_eq(ctr("ryan air seven tango climb flight level two one zero"), "ASK Did you mean RYR7TK? I heard RYR7T.")
check_eq(ctr("BA 456 climb FL300"), "ASK Did you mean BAW456? I heard BA456.")
-- two spoken digits are a light aircraft's speed, an airliner's cut off
check_eq(ctr("november seven seven alpha bravo reduce speed eight zero knots"), "SPD N77AB 80")
check(ctr("speed bird four five six reduce speed eight zero knots"):find("^ASK What speed") ~= nil, "cut off")

-- values as people write and say them: space-grouped thousands, rates in feet a minute and
-- metres per second (negative when said so), minutes and seconds, "flightlevel", a route
-- point's level kept as ADDWPT's altitude
check_eq(said(tr("KLM77 descend to 9 000 feet")), "ALT KLM77 9000")
check_eq(said(tr("KLM1234 vertical speed minus 5 metres per second")), "VS KLM1234 -984")
-- metres and kilometres convert without rounding beyond the unit said: whole feet, tenths of a mile
check_eq(said(tr("KLM1234 descend to 3000 metres")), "ALT KLM1234 9843")
-- a level in metres said in words is the whole number said, converted exactly; one that is not whole
-- hundreds of metres is asked about; feet, knots and headings said the same way keep their whole number
check_eq(said(tr("KLM1234 descend to seven thousand two hundred metres")), "ALT KLM1234 23622")
check_eq(said(tr("DLH4AX climb and maintain one zero thousand one hundred meters")), "ALT DLH4AX 33136")
check_eq(said(tr("KLM77 descend to nine hundred metres QNH one zero one six")), "ALT KLM77 2953")
check_eq(said(tr("KLM77 descend to two thousand one hundred metres on QNH 1018")), "ALT KLM77 6890")
check_eq(said(tr("KLM1234 descend to seven thousand two hundred and fifty metres")),
  "ASK Which altitude for KLM1234? I heard 7250 metres.")
check_eq(said(tr("KLM77 descend to eight thousand one hundred feet")), "ALT KLM77 8100")
check_eq(said(tr("KLM77 reduce speed two hundred twenty knots, turn left heading two hundred seventy")),
  "SPD KLM77 220 ; HDG KLM77 270 LEFT")
-- the same level restated in the other unit ("that is", "which is", "i.e."): the flight level or feet
-- said count when they agree within 100 ft (China's metric table), else squawk asks
check_eq(said(tr("DLH4AX descend to eight thousand nine hundred metres, that is flight level two niner one")),
  "ALT DLH4AX FL291")
check_eq(said(tr("DLH4AX descend to FL266, which is 8100 metres")), "ALT DLH4AX FL266")
check(said(tr("DLH4AX descend to 8900 metres, i.e. FL271")):find("^ASK Which level for DLH4AX") ~= nil,
  "a restatement that disagrees is asked about")
-- metres per second beyond any climb rate are an airspeed
check_eq(said(tr("KLM1234 set the airspeed to 120 metres per second")), "SPD KLM1234 233")
check_eq(said(tr("KLM1234 fly 100 m/s")), "SPD KLM1234 194")
check_eq(said(tr("KLM1234 climb with 10 m/s")), "VS KLM1234 1969")
check_eq(said(tr("KLM1234 at 15 km from SPIKE descend to FL80")), "ATDIST KLM1234 SPIKE 8.1 ALT KLM1234 FL80")
check_eq(said(tr("BAW8CK climb at 2500 feet a minute")), "VS BAW8CK 2500")
check_eq(said(tr("fast forward two minutes fifteen")), "FF 135")
check_eq(said(tr("DLH4AX descend flightlevel two eight zero")), "ALT DLH4AX FL280")
check_eq(said(tr("KLM77 add waypoint 52.3 4.6 to the route at flight level 90")), "ADDWPT KLM77 52.3 4.6 FL90")

-- a route point said with its level or its place in the route keeps them as ADDWPT's arguments;
-- "then direct" after a value instruction is the next instruction, not held behind it
local rsim = sim:copy()
check(rsim:exec("DEFWPT RIVER 52.3 4.3"))
check(rsim:exec("DEFWPT HILLS 52.6 4.6"))
check(rsim:exec("ADDWPT KLM77 HILLS"))
local function rtr(text) return said(graph.translate(text, { sim = rsim, mode = "offline", waypoints = { "RIVER", "HILLS" } })) end
check_eq(rtr("KLM77 please add the point RIVER at flight level 140"), "ADDWPT KLM77 RIVER FL140")
check_eq(rtr("add RIVER to the route of KLM77 after HILLS"), "ADDWPT KLM77 RIVER,,,HILLS")
check_eq(rtr("KLM77 put RIVER in the flight plan before HILLS"), "ADDWPT KLM77 RIVER,,,,HILLS")
check_eq(rtr("KLM77 descend flight level 100 and then direct HILLS"), "ALT KLM77 FL100 ; DIRECT KLM77 HILLS")
check_eq(rtr("klm77 dir HILLS"), "DIRECT KLM77 HILLS")
-- a creation at a named place reads every labelled value
check_eq(rtr("create KLM88 A320 over RIVER heading 090 FL 150 speed 260"), "CRE KLM88 A320 RIVER 90 FL150 260")
-- a level or speed tied to a waypoint is asked, never issued at once
r = graph.translate("KLM77 be at flight level 110 over RIVER", { sim = rsim, mode = "offline", waypoints = { "RIVER", "HILLS" } })
check(r.ask ~= nil and r.ask:find("happen at RIVER", 1, true) ~= nil, said(r))
-- a spoken flight level below any transition altitude lost a digit: asked
r = tr("DLH4AX descend flight level one five")
check(r.ask ~= nil and r.ask:find("FL15", 1, true) ~= nil, said(r))
check_eq(said(tr("run the simulation speed at three times")), "DTMULT 3")

-- a report the pilot makes and an orbit are named as not simulated; a correction with nothing
-- after it asks
r = tr("KLM77 report reaching flight level 120")
check(#r.commands == 0 and r.note ~= nil and r.note:find("position reports", 1, true) ~= nil, said(r))
r = tr("BAW8CK make a right 360")
check(#r.commands == 0 and r.note ~= nil and r.note:find("orbits", 1, true) ~= nil, said(r))
r = tr("DLH4AX descend flight level two six zero, correction")
check(r.ask ~= nil and r.ask:find("correction", 1, true) ~= nil, said(r))
-- an instruction after "then" waits for an orbit or a hold, which squawk does not fly: asked, never sent now
r = tr("BAW8CK make one orbit to the right, then resume own navigation")
check(r.ask ~= nil and r.ask:find("orbits", 1, true) ~= nil, said(r))
r = tr("BAW8CK orbit left and then descend flight level one two zero")
check(r.ask ~= nil and r.ask:find("waits for it", 1, true) ~= nil, said(r))
r = tr("DLH4AX enter the hold, then turn left heading two seven zero")
check(r.ask ~= nil and r.ask:find("holding patterns", 1, true) ~= nil, said(r))
-- a caution to the pilot ("similar callsign", "wake turbulence") is named, the instruction beside it runs
r = tr("DLH4AX caution similar callsign, descend flight level two four zero")
check_eq(said(r), "ALT DLH4AX FL240")
check(r.note ~= nil and r.note:find("cautions", 1, true) ~= nil, said(r))
check_eq(said(tr("BAW8CK turn right heading zero niner zero, caution wake turbulence")), "HDG BAW8CK 90 RIGHT")
-- a condition on what is not simulated ("when passing FL250 contact ...") goes with it; the rest runs
r = tr("DLH4AX descend flight level one niner zero, when passing flight level two five zero contact radar one two zero decimal eight")
check_eq(said(r), "ALT DLH4AX FL190")
check(r.note ~= nil and r.note:find("radio frequencies", 1, true) ~= nil, said(r))
check_eq(said(tr("BAW8CK climb FL300, once reaching FL250 squawk 7000")), "ALT BAW8CK FL300")
-- the aircraft climbed "through" another's level is other traffic, never the one instructed
check_eq(said(tr("make BAW8CK climb through DLH4AX's level, up to FL360")), "ALT BAW8CK FL360")
-- radiotelephony's "I say again" repeats the value said before it
check_eq(said(tr("DLH4AX negative, flight level two six zero, I say again two six zero, descend")), "ALT DLH4AX FL260")
check_eq(said(tr("BAW8CK turn left heading one two zero, I say again, heading one two zero")), "HDG BAW8CK 120 LEFT")

-- units people type: km/h is a speed in knots, metres an altitude in feet
check_eq(said(tr("KLM1234 speed 500 km/h")), "SPD KLM1234 270")
check_eq(said(tr("KLM1234 reduce speed to 400 kph")), "SPD KLM1234 216")

-- traffic information describes another aircraft: named, never an instruction
r = tr("KLM1234, turn right heading 023, traffic 2 o'clock, 36 miles")
check_eq(said(r), "HDG KLM1234 23 RIGHT")
check(r.note ~= nil and r.note:find("traffic information ('traffic 2 o'clock, 36 miles')", 1, true) ~= nil, tostring(r.note))

-- the same command in two command clauses ("hold on, pause") runs once
check_eq(said(tr("hold on, pause")), "HOLD")

-- a turn of one or two digits with a side and no "heading" is degrees of turn, also with the
-- English word "turn" in callsign-first order; the registry's name in capitals stays TrafScript
check_eq(said(tr("DLH4AX turn 20 left")), "HDG DLH4AX 70 LEFT")
check_eq(said(tr("TURN DLH4AX 20 LEFT")), "HDG DLH4AX 20 LEFT")
check_eq(said(tr("KLM77 turn left twenty")), "HDG KLM77 160 LEFT")
-- a bare number after a side that would be a heading the long way round is asked, not guessed
r = tr("BAW8CK turn left 200")
check(r.ask ~= nil and r.ask:find("by 200 degrees, or fly heading 200", 1, true) ~= nil, said(r))
check_eq(said(tr("BAW8CK turn left heading 200")), "HDG BAW8CK 200 LEFT")
-- "plus or minus N" is a size either side, never a negative value
check_eq(said(tr("set the vertical separation to plus or minus 800 ft")), "ZONEDH 800")
-- a vertical separation and its half said together set the half; two heights that disagree are asked
check_eq(said(tr("vertical separation 2000 ft, half height 1000 ft")), "ZONEDH 1000")
check_eq(said(tr("set the zone half height to 500 feet, that is 1000 feet separation")), "ZONEDH 500")
do
  local r = tr("zonedh 1000 and half height 300")
  check(r.commands == nil and r.ask ~= nil and r.ask:find("1000 or 300", 1, true) ~= nil, said(r))
end

-- a clock started at a rate: OP and the rate, neither dropped
check_eq(said(tr("resume the simulation at x3")), "OP ; DTMULT 3")
check_eq(said(tr("resume at double speed")), "OP ; DTMULT 2")
-- a family said as its number after an article is that type; the orbit "a 360" stays an orbit
check_eq(said(tr("add a 757 called TST9 at 52.1 north 4.3 east heading 270 FL320 450 knots")),
  "CRE TST9 B752 52.1 4.3 270 FL320 450")
-- "insert" before a new callsign or a type creates it; before a waypoint and a route it adds the waypoint
check_eq(said(tr("insert TST7 B736 at 52.2 4.4 heading 180 FL110 260")), "CRE TST7 B736 52.2 4.4 180 FL110 260")
check_eq(said(tr("insert an A320 TST8 at 52.2 4.4 heading 090 FL150 280")), "CRE TST8 A320 52.2 4.4 90 FL150 280")
r = tr("BAW8CK make a 360")
check(#r.commands == 0 and r.note ~= nil and r.note:find("orbits", 1, true) ~= nil, said(r))
-- a word in a reason starts no instruction ("so we get the same run": no OP); "the random
-- generator" is what a seed seeds, not random traffic
check_eq(said(tr("KLM77 climb FL300 so we get the same run each time")), "ALT KLM77 FL300")
check_eq(said(tr("seed the random number generator with 7")), "SEED 7")
-- the clock is the simulation's: started, stopped, started at a rate
check_eq(said(tr("stop the clock")), "HOLD")
check_eq(said(tr("start the clock at 2x")), "OP ; DTMULT 2")

-- speech-recognition output (R15's classes; docs/translator_trust.md "Speech recognition")
local asr, heard = scene({ "CRE AAL100 B738 40.5 -73.5 090 FL240 280", "CRE DLH400 A321 50.0 8.5 180 FL300 290",
    "CRE DLH40 A320 50.2 8.6 270 FL200 260", "CRE BAW78 A319 51.5 0.0 090 11000 250",
    "CRE BAW789 A320 51.6 0.1 270 FL250 280", "CRE KLM544 B738 52.3 4.7 045 FL150 260" })
local function asks(text, part)
  local s = heard(text)
  check(s:sub(1, 4) == "ASK " and (not part or s:find(part, 1, true) ~= nil), text .. " -> " .. s)
end
-- sound-alike instruction words (lexicon.heard_as), only where the instruction word is expected
check_eq(heard("DLH40 turn write heading one two zero"), "HDG DLH40 120 RIGHT")
check_eq(heard("DLH40 rite heading zero six zero"), "HDG DLH40 60 RIGHT")
check_eq(heard("AAL100 decent flight level two zero zero"), "ALT AAL100 FL200")
check_eq(heard("AAL100 turn left heading two seven zero the send flight level two two zero"),
  "HDG AAL100 270 LEFT ; ALT AAL100 FL220")
check_eq(heard("DLH400 head in two four zero"), "HDG DLH400 240")
check_eq(heard("DLH400 speed two niner zero nuts"), "SPD DLH400 290")
check(not heard("write the heading down for DLH400"):find("RIGHT", 1, true))
check(not heard("BAW78 the send key is stuck"):find("ALT", 1, true))
-- flight numbers said as numbers; digits heard as words; digits left after a near callsign
check_eq(heard("american one hundred climb flight level two six zero"), "ALT AAL100 FL260")
check_eq(heard("lufthansa four hundred reduce speed two five zero knots"), "SPD DLH400 250")
check_eq(heard("klm five four for descend flight level one two zero"), "ALT KLM544 FL120")
asks("lufthansa four zero seven climb flight level three one zero", "DLH407")
-- a hesitation inside a callsign both of whose readings fly, or inside a two-digit heading, asks
asks("speedbird seven eight um niner descend flight level two one zero", "BAW789")
check_eq(heard("speedbird seven eight niner descend flight level two one zero"), "ALT BAW789 FL210")
asks("AAL100 turn left heading um three four", "headings have three digits")
check_eq(heard("AAL100 turn left heading three four"), "HDG AAL100 340 LEFT")
-- "two" straight after climb/descend may be "to": the reading the verb allows, asked when both are
check_eq(heard("BAW78 descend two six thousand"), "ALT BAW78 6000")
asks("AAL100 descend two two thousand", "to 22000 ft or to 2000 ft")
check_eq(heard("AAL100 climb two six thousand"), "ALT AAL100 26000")
-- "say heading" asks for a report (POS); a value after the state word is the instruction's value
check_eq(heard("AAL100 say heading"), "POS AAL100")
check_eq(heard("say altitude, DLH400"), "POS DLH400")
check_eq(heard("AAL100 say heading three three zero"), "HDG AAL100 330")
-- a turn direction corrected is the one turned
check_eq(heard("DLH40 turn right, correction, turn left heading one five zero"), "HDG DLH40 150 LEFT")
check_eq(heard("AAL100 climb two flight level two eight zero"), "ALT AAL100 FL280")
check_eq(heard("DLH40 turn left two heading one one zero"), "HDG DLH40 110 LEFT")
-- spoken numbers: digits said singly or grouped after "thousand" are the next value; a heading said
-- digit by digit is three digits when an altitude follows it
check_eq(heard("create TST1 b738 at 52.1 4.3 heading two seven zero one two thousand two five zero knots"),
  "CRE TST1 B738 52.1 4.3 270 12000 250")
check_eq(heard("create TST2 b738 at 52.1 4.3 heading 090 nine thousand one eighty knots"),
  "CRE TST2 B738 52.1 4.3 90 9000 180")
check_eq(heard("AAL100 descend four thousand five hundred"), "ALT AAL100 4500")
-- R17's classes (docs/translator_trust.md "Speech recognition"): European radiotelephony read by a recogniser
do
  local eu = scene({ "CRE AFR28 A320 48.5 2.5 200 FL240 280", "CRE IBE3KT A321 40.4 -3.6 090 9000 250",
      "CRE SAS4472 A20N 55.6 12.6 130 FL350 M.78", "CRE SAS447 A320 55.7 12.7 300 FL310 280",
      "CRE KLM61M B738 52.3 4.7 010 FL150 260", "CRE AUA27D A320 48.1 16.5 240 FL120 250",
      "CRE EWG7FX A320 50.9 7.1 120 FL200 270", "DEFWPT ROK 48.9 2.4", "ADDWPT AFR28 ROK" })
  local function eut(text)
    local r = graph.translate(text, { sim = eu, mode = "offline" })
    return said(r), r.note
  end
  local function eu_asks(text, part)
    local s = eut(text)
    check(s:sub(1, 4) == "ASK " and (not part or s:find(part, 1, true) ~= nil), text .. " -> " .. s)
  end
  -- a readback asked for after an instruction is the pilot's report: noted, no POS; alone it is POS
  local out, note = eut("air france two eight descend flight level one nine zero report level")
  check_eq(out, "ALT AFR28 FL190")
  check(note ~= nil and note:find("report level", 1, true) ~= nil, tostring(note))
  check_eq(eut("iberia three kilo tango turn left heading zero six zero and report heading"), "HDG IBE3KT 60 LEFT")
  check_eq(eut("air france two eight report speed"), "POS AFR28")
  -- "to" before two spoken digits: a heading asks when "two" and a lost final zero both give one; a
  -- level takes the reading the verb allows from the present level, and asks when both or neither fit
  eu_asks("klm six one mike turn right heading to three zero", "230 or 300")
  check_eq(eut("klm six one mike turn right heading to eight zero"), "HDG KLM61M 280 RIGHT")
  check_eq(eut("air france two eight climb flight level too six zero"), "ALT AFR28 FL260")
  check_eq(eut("air france two eight descend flight level to five zero"), "ALT AFR28 FL50")
  check_eq(eut("air france two eight descend flight level to one zero"), "ALT AFR28 FL210")  -- (no FL010)
  eu_asks("air france two eight maintain flight level to niner zero", "FL290 or FL90")
  -- digits the recogniser wrote apart after "flight level" or "heading" are one value
  check_eq(eut("air france two eight descend flight level 1 70"), "ALT AFR28 FL170")
  check_eq(eut("klm six one mike fly heading 0 4 5"), "HDG KLM61M 45")
  -- an abbreviation spelled letter by letter is that word; an altitude with its QNH is a level
  out, note = eut("iberia three kilo tango descend altitude six thousand feet q n h one zero one five")
  check_eq(out, "ALT IBE3KT 6000")
  check(note ~= nil and note:find("altimeter", 1, true) ~= nil, tostring(note))
  check_eq(eut("iberia three kilo tango descend 3000 feet qnh 1015"), "ALT IBE3KT 3000")
  check_eq(eut("air france two eight descend f l one niner zero"), "ALT AFR28 FL190")
  out, note = eut("klm six one mike cleared i l s approach runway two four")
  check_eq(out, "")
  check(note ~= nil and note:find("approach clearances", 1, true) ~= nil, tostring(note))
  -- a digit heard as a word inside a callsign ("for", "to") or a letter said by its name ("kay") is
  -- that digit or letter only when the callsign read so is exactly an aircraft's
  check_eq(eut("scandinavian for four seven two climb flight level three seven zero"), "ALT SAS4472 FL370")
  check_eq(eut("austrian to seven delta reduce speed two two zero knots"), "SPD AUA27D 220")
  check_eq(eut("iberia three kay tango descend altitude five thousand feet"), "ALT IBE3KT 5000")
  check_eq(eut("austrian two seven uh delta descend flight level one zero zero"), "ALT AUA27D FL100")
  check_eq(eut("eurowings seven fox trot x ray climb flight level two two zero"), "ALT EWG7FX FL220")
  eu_asks("austrian to seven echo reduce speed two two zero knots")
  -- a fix spelled in the phonetic alphabet is the known name it spells, never a near one
  check_eq(eut("air france two eight proceed direct romeo oscar kilo"), "DIRECT AFR28 ROK")
  eu_asks("air france two eight proceed direct romeo oscar lima")
end
-- aircraft types with their digits said as words, where traffic is created
check_eq(heard("create TST3 airbus a three two one at 52.1 4.3 heading 090 FL200 250 knots"),
  "CRE TST3 A321 52.1 4.3 90 FL200 250")
check_eq(heard("create TST4 boeing seven three seven eight hundred at 52.1 4.3 heading 090 FL200 250 knots"),
  "CRE TST4 B738 52.1 4.3 90 FL200 250")
check_eq(heard("create TST5 e one seventy five at 52.1 4.3 heading 090 FL200 250 knots"),
  "CRE TST5 E75L 52.1 4.3 90 FL200 250")
-- (a family reads as its typed name does)
check_eq(heard("spawn TST6 an a three thirty at 52.1 4.3 heading 090 FL200 250 knots"),
  heard("spawn TST6 an a330 at 52.1 4.3 heading 090 FL200 250 knots"))
check(heard("spawn TST6 an a330 at 52.1 4.3 heading 090 FL200 250 knots"):find("^CRE TST6 A33"))
-- an aircraft named by "the" and its airline alone (telephony, or a name it is known by) is the
-- one aircraft of that airline flying; with two it asks which, with none it asks; a callsign cut
-- short in radiotelephony ("Lufthansa, descend") and other traffic named that way are no reference
do
  local fleet, ft = scene({ "CRE KLM1234 B738 52.2 4.2 300 FL250 280", "CRE KLM77 B738 52.1 4.5 180 FL150 250",
      "CRE DLH4AX A321 52.4 4.4 090 FL300 280", "CRE BAW123 A320 52.0 4.0 025 FL200 250",
      "CRE EZY45 A319 52.1 3.8 060 FL180 270", "CRE N123AB C172 52.3 4.6 090 3500 110" })
  check_eq(ft("would you mind asking the Lufthansa to come down to FL 260?"), "ALT DLH4AX FL260")
  check_eq(ft("I'd like the easyJet on heading 120, thanks"), "HDG EZY45 120")
  check_eq(ft("could the BA slow to 230 knots please"), "SPD BAW123 230")
  check_eq(ft("please have the British Airways climb to FL 220"), "ALT BAW123 FL220")
  check_eq(ft("could the KLM climb to FL 300?"), "ASK Which KLM: KLM1234 or KLM77?")
  check_eq(ft("can the Ryanair descend to FL 100?"), "ASK No Ryanair aircraft is flying. Which aircraft do you mean?")
  check_eq(ft("Lufthansa, descend FL 200"), "ASK Which aircraft should change altitude? Please give its callsign.")
  check_eq(ft("please turn the easyJet left 20 degrees, it's getting close to the Lufthansa"), "HDG EZY45 40 LEFT")
  -- an airline said alone as a clause's aircraft, beside another clause's, is the one aircraft of it
  -- flying (never the aircraft named before or after); with two of it flying it asks which
  check_eq(ft("EZY45 heading 180, Lufthansa heading 270"), "HDG EZY45 180 ; HDG DLH4AX 270")
  check_eq(ft("Speedbird right heading 010, and EZY45 left heading 300"),
    "HDG BAW123 10 RIGHT ; HDG EZY45 300 LEFT")
  check_eq(ft("BAW123 climb FL 240 and KLM descend FL 140"), "ASK Which KLM: KLM1234 or KLM77?")
  -- an airline said alone, capitalised, opening a request of several instructions or aircraft, is the
  -- one aircraft of it flying; one instruction to it alone is a callsign cut short, asked about; a
  -- callsign in its clause is the one meant
  check_eq(ft("Lufthansa, turn left heading 250 and climb FL 320"), "HDG DLH4AX 250 LEFT ; ALT DLH4AX FL320")
  check_eq(ft("easyJet: speed 280, then descend to FL 150"), "SPD EZY45 280 ; ALT EZY45 FL150")
  check_eq(ft("Speedbird heading 090, easyJet heading 270"), "HDG BAW123 90 ; HDG EZY45 270")
  check_eq(ft("Lufthansa, mach .78"), "ASK Which aircraft should change speed? Please give its callsign.")
  check_eq(ft("KLM, turn right heading 300 and descend FL 200"), "ASK Which KLM: KLM1234 or KLM77?")
  check_eq(ft("Ryanair, heading 300 and FL 200"):find("^ASK") ~= nil, true)
  check_eq(ft("Lufthansa EZY45 heading 090 and climb FL 300"),
    "ASK Which Lufthansa aircraft do you mean? Please give its callsign.")
  -- in lower case an airline's word may be English ("easy", "delta"): asked about
  check_eq(ft("lufthansa, turn left heading 250 and climb FL 320"):find("^ASK") ~= nil, true)
  check_eq(ft("EZY45 heading 180, the Lufthansa heading 270"), "HDG EZY45 180 ; HDG DLH4AX 270")
  -- the purpose said after the instruction (", that should ...", ", I want X to ...", "so he/she ...")
  -- names other traffic, never an aircraft instructed
  check_eq(ft("turn the easyJet right heading 100, that should put him across the Lufthansa's track"),
    "HDG EZY45 100 RIGHT")
  check_eq(ft("slow the easyJet to 240, I want the BA to catch him"), "SPD EZY45 240")
  check_eq(ft("EZY45 climb FL 250 so he crosses the Lufthansa"), "ALT EZY45 FL250")
  -- "so" straight after an instruction, before an aircraft, is the purpose; "so" opening a clause is a filler
  check_eq(ft("slow EZY45 to 240 kt so the BA catches up"), "SPD EZY45 240")
  check_eq(ft("EZY45 climb FL 260 so BAW123 can pass below"), "ALT EZY45 FL260")
  check_eq(ft("ok, so EZY45 climb FL 260"), "ALT EZY45 FL260")
  check(ft("climb to FL 250 so she crosses the Lufthansa"):find("^ASK") ~= nil, "the Lufthansa is no aircraft instructed")
  check_eq(ft("EZY45 climb FL 200 to stay behind the BA"), "ALT EZY45 FL200")
  -- a new aircraft of an airline is no reference to the one flying
  check_eq(ft("add a Lufthansa A320, DLH9CK, at 52.5 north 4.1 east heading 090 FL 200 250 knots"),
    "CRE DLH9CK A320 52.5 4.1 90 FL200 250")
  -- by type or maker, when no callsign is said and one aircraft of it flies
  check_eq(ft("could you turn the Cessna right onto heading 180?"), "HDG N123AB 180 RIGHT")
  -- (two Boeings flying: asked, naming both)
  check_eq(ft("please slow the Boeing down to 240 knots"),
    "ASK Which Boeing do you mean: KLM1234 or KLM77? Please give its callsign.")
  -- an airline said with a number that is not the aircraft's airline asks, never takes the number alone
  check_eq(ft("Scooter 77 climb FL 200"), "ASK Did you mean KLM77? I heard TGW77.")
  -- the request's own words, read as English: "say" before a value, "heading into", "is a bit slow"
  check_eq(ft("I'd like KLM77 to head south, say heading 180, thanks"), "HDG KLM77 180")
  check_eq(ft("turn DLH4AX right 30 degrees, it's heading into the other traffic"), "HDG DLH4AX 120 RIGHT")
  check_eq(ft("EZY45 is a bit slow, could you speed it up by 20 knots?"), "SPD EZY45 290")
  -- a condition naming the level just cleared ("when it gets there") waits for it
  check_eq(ft("could you climb BAW123 to FL 240, and once it's there, slow it to 250 knots"),
    "ALT BAW123 FL240 ; ATALT BAW123 FL240 SPD BAW123 250")
  -- a flight level is never relative, whatever "current" or "by" follows
  check_eq(ft("descend KLM77 to flight level one two zero and keep its current heading"),
    "ALT KLM77 FL120 ; HDG KLM77 180")
  -- "N feet from where it is now" is a change from the present level
  check_eq(ft("could you have the Lufthansa descend 2000 feet from where it is now?"), "ALT DLH4AX 28000")
  -- a reversal with no way said asks which way
  check_eq(ft("please turn KLM77 around"), "ASK Should KLM77 turn around to the left or to the right?")
  -- "the scenario" spoken of is no file to load; destinations asked about are shown
  check_eq(ft("please remove the Cessna from the scenario"), "DEL N123AB")
  check_eq(ft("what's the easyJet's destination?"), "DEST EZY45")
  -- "where is X going?" asks the destination; "where is X?" and "where it's going" in passing do not
  check_eq(ft("where is the easyJet going?"), "DEST EZY45")
  check_eq(ft("where's BAW123 headed to?"), "DEST BAW123")
  check_eq(ft("where is BAW123?"), "POS BAW123")
  check_eq(ft("could the BA climb to FL 240, it's too low for where it's going"), "ALT BAW123 FL240")
  check_eq(ft("add SUGOL to the easyJet's route and send it direct there"), "ADDWPT EZY45 SUGOL ; DIRECT EZY45 SUGOL")
  -- a callsign typed apart after its letters; positions, routes and states asked after in passing
  check_eq(ft("could you please descend EZY 45 to FL 150?"), "ALT EZY45 FL150")
  check_eq(ft("where's the SUGOL intersection?"), "POS SUGOL")
  check_eq(ft("please check the Lufthansa's route"), "LISTRTE DLH4AX")
  check_eq(ft("can you tell me what the Cessna is doing right now?"), "POS N123AB")
  check_eq(ft("could you put the Cessna back on the same heading as the Lufthansa?"), "HDG N123AB 90")
  -- a new aircraft introduced by its airline and model number, the callsign after: the number is the type
  check_eq(ft("could we add a Delta 757, DAL77, at 52.6 north 4.9 east heading 180 FL 240 and 280 knots?"),
    "CRE DAL77 B752 52.6 4.9 180 FL240 280")
  -- (a 737 without its variant, with an airline or not, is asked: writers read it B737 or B738)
  check_eq(ft("let's start with a Ryanair 737, RYR12, at 52.7 north 4.1 east, heading west, FL 300 at 290 knots"),
    "ASK Which variant of the 737 is meant: B733, B734, B735, B736, B737, B738, B739?")
  -- a place corrected in the request is the one after the correction, or asked, never the first
  r = graph.translate("I'd like an aircraft SWR18, an A320, at SUGOL... no, sorry, at ARTIP, heading 090, "
    .. "FL 100, 250 knots", { sim = fleet, mode = "offline" })
  check(r.ask ~= nil or said(r):find("ARTIP", 1, true) ~= nil, said(r))
  -- a number with a unit after "the" and an airline is the value, no flight number
  check_eq(ft("could you turn the Lufthansa 30 degrees to the left please"), "HDG DLH4AX 60 LEFT")
  check_eq(ft("could the easyJet 20 knots faster please"), "SPD EZY45 290")
  -- a navaid said by its one-word name added to a route
  if #fleet:airports_named("schiphol") == 1 then
    check_eq(ft("could we add Pampus to the end of the KLM77's route?"), "ADDWPT KLM77 PAM")
  end
  -- the clock, said politely
  check_eq(ft("please carry on with the simulation"), "OP")
  check_eq(ft("could you slow everything down to half speed?"), "DTMULT 0.5")
  check_eq(ft("set the look-ahead time for conflict detection to 240 seconds"), "DTLOOK 240")
end

-- An experimenter's command box: sim control, creating and moving traffic, CD/CR settings
do
  local box, bt = scene({ "DEFWPT TULIP 52.3 4.6", "DEFWPT DAHLI 52.5 4.8", "CRE KL204 A320 52.0 4.0 090 FL250 280",
      "CRE EZY45 A319 52.0 5.0 270 FL250 280", "CRE BAW123 B738 52.4 4.5 180 FL310 300", "ADDWPT BAW123 TULIP",
      "ADDWPT BAW123 DAHLI", "CRE WZZ1234 A321 52.5 4.6 200 FL340 290" })
  -- the clock said as a clause of its own in a list runs; "KL204, resume" starts no clock
  check_eq(bt("pause, BAW123 direct DAHLI, then go"), "HOLD ; DIRECT BAW123 DAHLI ; OP")
  check_eq(bt("reso MVP, pz 4 nm, then carry on"), "RESO MVP ; ZONER 4 ; OP")
  check_eq(bt("fine, carry on, run it"), "OP")
  -- "run" said alone as the last clause starts the clock; a callsign before it is no clause of its own
  check_eq(bt("Hold. KL204 heading 120. Run."), "HOLD ; HDG KL204 120 ; OP")
  check_eq(bt("EZY45 climb FL300, then run"), "ALT EZY45 FL300 ; OP")
  check(bt("KL204, run."):find("^ASK") ~= nil, bt("KL204, run."))
  -- an airline said alone beside a resolved aircraft names no one aircraft: asked, never dropped
  check(bt("remove the easyjet and the lufthansa"):find("^ASK No lufthansa aircraft") ~= nil,
    bt("remove the easyjet and the lufthansa"))
  -- "down/up N feet" is a change; "N right" after the callsign is a turn; a swapped letter pair is a typo
  check_eq(bt("BAW123 down 3000 feet"), "ALT BAW123 28000")
  check_eq(bt("KL204 20 left and up 2000 ft"), "HDG KL204 70 LEFT ; ALT KL204 27000")
  check_eq(bt("EZY45 trun lfet heading 200"), "HDG EZY45 200 LEFT")
  check_eq(bt("KL204 up to 300"), "ALT KL204 FL300")
  check_eq(bt("KL204 +10 kts"), "SPD KL204 290")
  check_eq(bt("KL204 speed +10"), "SPD KL204 290")  -- a signed value with no unit is a change too, never 10 kt
  check(bt("KL204 to two eight zero"):find("^ASK Heading 280 or flight level 280") ~= nil, bt("KL204 to two eight zero"))
  -- an aircraft the verb instructs is no context; one the aircraft is sent to meet is
  check_eq(bt("for the conflict, get EZY45 up to FL310 to meet KL204"), "ALT EZY45 FL310")
  -- route: a speed after "and" and a verb of its own; a speed with no level keeps ADDWPT's place
  check_eq(bt("route KL204 via TULIP and DAHLI and give it 260 knots"),
    "ADDWPT KL204 TULIP ; ADDWPT KL204 DAHLI ; SPD KL204 260")
  check_eq(bt("KL204 add a waypoint at 52.2 4.4 at 250 knots"), "ADDWPT KL204 52.2 4.4,,250")
  check_eq(bt("take DAHLI out of BAW123's route"), "DELWPT BAW123 DAHLI")
  check_eq(bt("drop DAHLI from the speedbird's route"), "DELWPT BAW123 DAHLI")
  -- waypoints: a name in capitals after the noun, degrees and decimal minutes, "and send X to it"
  check_eq(bt("define a fix HOTEL at 52 15.0 N 004 45.0 E"), "DEFWPT HOTEL 52.25 4.75")
  check_eq(bt("define MID1 at 52.2 4.5 and route EZY45 through it"), "DEFWPT MID1 52.2 4.5 ; ADDWPT EZY45 MID1")
  -- CD/CR settings in words
  check_eq(bt("vertical reso safety factor 1.2"), "RFACV 1.2")
  check_eq(bt("set the horizontal resolution factor to 1.1"), "RFACH 1.1")
  check(bt("resolution factor 1.3"):find("^ASK Should the horizontal or the vertical") ~= nil, "which factor")
  check_eq(bt("allow vertical manoeuvres in the MVP resolutions"), "RMETHV V/S")
  check_eq(bt("resolutions horizontal only please, no vertical"), "RMETHV OFF")
  check_eq(bt("aircraft resume nav once past cpa"), "RESNAV PASTCPA")
  check_eq(bt("switch on conflict detection with 3 nm and 800 ft"), "ASAS ON ; ZONER 3 ; ZONEDH 800")
  check_eq(bt("what's the look-ahead now"), "DTLOOK")
  check_eq(bt("lateral sep to 4 nm"), "ZONER 4")
  -- timed instructions: by the clock (SCHEDULE) or from now (DELAY); one opening the request times all
  check_eq(bt("at 15 minutes turn KL204 right heading 150"), "SCHEDULE 00:15:00 HDG KL204 150 RIGHT")
  -- a time typed h:mm:ss is the clock's time; never dropped
  check_eq(bt("pause the sim automatically at 00:25:00"), "SCHEDULE 00:25:00 HOLD")
  check_eq(bt("at 1:02:30 KL204 climb FL300"), "SCHEDULE 01:02:30 ALT KL204 FL300")
  check_eq(bt("fast forward 0:05:00"), "FF 300")
  check_eq(bt("freeze the sim when the clock reaches 1 hour"), "SCHEDULE 01:00:00 HOLD")
  check_eq(bt("after 90 seconds KL204 climb FL300 and EZY45 descend FL200"),
    "DELAY 90 ALT KL204 FL300 ; DELAY 90 ALT EZY45 FL200")
  check_eq(bt("make it 3x"), "DTMULT 3")
  check_eq(bt("skip ahead three and a half minutes"), "FF 210")
  check_eq(bt("ff an hour and a half"), "FF 5400")
  check_eq(bt("fast forward 2 min then slow the clock to real time"), "FF 120 ; DTMULT 1")
  -- positions from an aircraft: a distance and a compass point
  check_eq(bt("move KL204 30 nm north"), "MOVE KL204 52.499663 4")
  check_eq(bt("shift EZY45 10 miles south of where it is now"), "MOVE EZY45 51.833446 5")
  check_eq(bt("create KL205 A320 20 nm east of KL204 with the same heading, level and speed"),
    "CRE KL205 A320 51.998761 4.541048 90 FL250 280")
  check_eq(bt("another Wizz: WZZ99, A321, 52.1 4.1, hdg 180, same FL as WZZ1234, 280 knots"),
    "CRE WZZ99 A321 52.1 4.1 180 FL340 280")
  check_eq(bt("callsign SAS11, A320, FL300, M.78, heading 045, at 52.6 4.2"), "CRE SAS11 A320 52.6 4.2 45 FL300 M0.78")
  check_eq(bt("add 3 random B738s at FL200"), "MCRE 3 B738 FL200")
  check_eq(bt("make 2 more random ones"), "MCRE 2")
  -- an intruder set up against an aircraft, and a new aircraft instructed later in the request
  check_eq(bt("make a conflict for EZY45: intruder INT9 A320, crossing from 45 degrees, cpa 0.5, los in 120 s"),
    "CRECONFS INT9 A320 EZY45 45 0.5 120")
  check(bt("spawn an intruder for EZY45: INT8, A320, cpa 1, los in 100 s"):find("^ASK At what angle") ~= nil,
    "an intruder's angle asked")
  check_eq(bt("create KL210 A320 at 52.2 4.2 heading 90 FL200 250 and send it to TULIP"),
    "CRE KL210 A320 52.2 4.2 90 FL200 250 ; ADDWPT KL210 TULIP")
  -- conditions, levels of others, queries
  check_eq(bt("when BAW123 is 15 miles from DAHLI, descend it to FL250"), "ATDIST BAW123 DAHLI 15 ALT BAW123 FL250")
  check_eq(bt("put EZY45 at the same level as BAW123"), "ALT EZY45 FL310")
  check_eq(bt("KL204 keep it at FL250 and 260 kts"), "ALT KL204 FL250 ; SPD KL204 260")
  check_eq(bt("destination of BAW123?"), "DEST BAW123")
  check_eq(bt("bin the wizz"), "DEL WZZ1234")
  -- a note for the log, a wind where the verb places it
  check_eq(bt("write a note in the log: trial 4 begins"), "ECHO trial 4 begins")
  check_eq(bt("set a wind at 52.2 4.2, FL200, from 300 at 35 knots"), "WIND 52.2 4.2 FL200 300 35")
  check(bt("add wind at 52.2 4.2"):find("^ASK From which direction") ~= nil, "a wind with no direction asked")
  -- a city said in capitals is its large airport; a small field far away is none a name means
  if #box:airports_named("schiphol") == 1 then
    check_eq(bt("KL204 is going to Frankfurt"), "DEST KL204 EDDF")
    check_eq(bt("change EZY45's destination to Brussels"), "DEST EZY45 EBBR")
    -- (nor a small field far away: "Amsterdam" is the airport beside the AMSTERDAM VOR)
    check_eq(bt("EZY45 origin Amsterdam"), "ORIG EZY45 EHAM")
  end
  -- a time opening the next instruction's clause is that instruction's wait (30000 is no heading 120)
  check_eq(bt("KL204 climb FL300 and in 2 minutes EZY45 climb FL280"), "ALT KL204 FL300 ; DELAY 120 ALT EZY45 FL280")
end

-- Setting up the experiment (R29, R25, R27, R23): TrafScript names typed inside English, in any case, name
-- their commands (a capitalised one is no waypoint); several settings in one line; the PZ, the resolution
-- method and factors, the wind, the time step and the clock said the ways experimenters say them
do
  local lab = squawk.sim.new()
  check(lab:exec("CRE SAS421 A320 55.9 12.2 180 FL140 280"))
  check(lab:exec("CRE NAX3412 B38M 55.2 12.9 340 FL120 270"))
  local _, lt = set_up(lab, {})
  check_eq(lt("conflict detection ON, reso MVP, rmethv off, rfach 1.05"), "ASAS ON ; RESO MVP ; RMETHV OFF ; RFACH 1.05")
  check_eq(lt("DT 0.2 and DTMULT 4"), "DT 0.2 ; DTMULT 4")
  check_eq(lt("DTMULT 4 and DT 0.2"), "DTMULT 4 ; DT 0.2")
  check_eq(lt("set the DTLOOK to 300"), "DTLOOK 300")
  check_eq(lt("RFACH 1.2 and RMETHV OFF"), "RFACH 1.2 ; RMETHV OFF")
  check_eq(lt("set pzr 4 and pzdh 900"), "ZONER 4 ; ZONEDH 900")
  check_eq(lt("set rfacv to 1.1"), "RFACV 1.1")
  check_eq(lt("MCRE 12 then FF 120"), "MCRE 12 ; FF 120")
  check_eq(lt("zoner 5, dtlook 300, then resume at 5x"), "ZONER 5 ; DTLOOK 300 ; OP ; DTMULT 5")
  -- a bare number before the zone's word is not its value; one with a unit straight before it is
  check(lt("Run 2 setup: ZONER 5"):find("ZONER 2", 1, true) == nil, lt("Run 2 setup: ZONER 5"))
  check_eq(lt("switch conflict detection on, with a 3 mile PZ"), "ASAS ON ; ZONER 3")
  check_eq(lt("set a 4 nm protected zone"), "ZONER 4")
  check_eq(lt("For this run I want a 3 nm, 1000 ft zone"), "ZONER 3 ; ZONEDH 1000")
  -- horizontal-only resolutions are RMETHV OFF; vertical-only is no method squawk has: asked
  check_eq(lt("horizontal resolutions only"), "RMETHV OFF")
  check(lt("vertical resolutions only"):find("^ASK") ~= nil, lt("vertical resolutions only"))
  check(lt("only vertical resolutions please"):find("^ASK") ~= nil, lt("only vertical resolutions please"))
  check_eq(lt("Resolution method MVP, horizontal factor 1.2"), "RESO MVP ; RFACH 1.2")
  check_eq(lt("reso MVP with a vertical factor of 1.1"), "RESO MVP ; RFACV 1.1")
  check_eq(lt("and MVP on"), "RESO MVP")
  check_eq(lt("enable conflict detection and resolution"), "ASAS ON ; RESO MVP")
  check_eq(lt("switch on detection and resolution"), "ASAS ON ; RESO MVP")
  -- the wind: where it blows from said after "from" or "of", before "at" and its speed, or as a compass point
  check_eq(lt("Wind from 270 at 40 kt at FL200 over 55.5 12.5"), "WIND 55.5 12.5 FL200 270 40")
  check_eq(lt("set a wind of 270 at 40 knots around 50.9 4.5"), "WIND 50.9 4.5 270 40")
  check_eq(lt("wind of 250 degrees, 30 knots at 52 4"), "WIND 52 4 250 30")
  check_eq(lt("wind from the west at 20 knots at 52.1 4.2"), "WIND 52.1 4.2 270 20")
  check(lt("wind from 270 at 40 knots"):find("^ASK Where should the wind be") ~= nil, "a wind with no place asked")
  -- the time step: "the step" as a noun, a fraction of a second said in words
  check_eq(lt("set the time step to a tenth of a second"), "DT 0.1")
  check_eq(lt("time step half a second"), "DT 0.5")
  check_eq(lt("Pause, and set the step to 0.2 s"), "HOLD ; DT 0.2")
  check_eq(lt("the simulation step 0.1"), "DT 0.1")
  check_eq(lt("step the sim 30 seconds"), "FF 30")
  -- the clock moved on by a time: "play it forward", "roll it on", "step forward"
  check_eq(lt("Play it forward 3 minutes."), "FF 180")
  check_eq(lt("step forward 10 seconds"), "FF 10")
  check_eq(lt("roll the sim on 10 minutes"), "FF 600")
  check_eq(lt("push the clock ahead 2 minutes"), "FF 120")
  -- the clock at a simulation time (SCHEDULE): "hold the sim" is the pause, no holding pattern
  check_eq(lt("Hold the sim at 30 minutes sim time."), "SCHEDULE 00:30:00 HOLD")
  check_eq(lt("hold the clock at 45 minutes"), "SCHEDULE 00:45:00 HOLD")
  check_eq(lt("at 30 minutes, pause"), "SCHEDULE 00:30:00 HOLD")
  check_eq(lt("at 30 minutes sim time, pause the sim"), "SCHEDULE 00:30:00 HOLD")
  check_eq(lt("seed 7, mcre 20, ff 10 min"), "SEED 7 ; MCRE 20 ; FF 600")
  -- the clock started, said as letting it go; the speaker's own reset in a clause of time is no RESET
  check_eq(lt("let it go"), "OP")
  check_eq(lt("ok, let it run"), "OP")
  check_eq(lt("let the sim run"), "OP")
  check_eq(lt("pause the sim for a sec while I reset the eye tracker"), "HOLD")
  check(lt("pause and reset"):find("^ASK Reset the simulation") ~= nil, lt("pause and reset"))
  -- the clock's rate as a noun, a setting's size
  check_eq(lt("DT 0.05 and a speed-up of 8"), "DT 0.05 ; DTMULT 8")
  check_eq(lt("speed up by a factor of 3"), "DTMULT 3")
  check_eq(lt("vertical size of the PZ, 800 feet either side"), "ZONEDH 800")
  check_eq(lt("PZ size 4 nm"), "ZONER 4")
  -- one instruction word before digits is that instruction, no misheard airline; digits with a
  -- distance unit are no flight number
  check(lab:exec("CRE VLG1234 A320 40.6 -0.9 260 FL350 280"))
  check(lab:exec("CRE TST3 B738 51.8 4.0 360 FL300 260"))
  check_eq(lt("seed 1234 please"), "SEED 1234")
  check_eq(lt("make the protected zone 3 miles and the vertical half-height 900 feet"), "ZONER 3 ; ZONEDH 900")
  -- shapes: a polygon's corners, a line's two ends, levels as two or as one and the surface
  check_eq(lt("Polygon LTMA: 51.2 -1.0, 51.9 -1.0, 51.9 0.8, 51.2 0.8."), "POLY LTMA 51.2 -1 51.9 -1 51.9 0.8 51.2 0.8")
  check_eq(lt("make a polygon named SEC with corners 52N 4E, 53N 4E, 53N 6E and 52N 6E"), "POLY SEC 52 4 53 4 53 6 52 6")
  check_eq(lt("define a polygon called P1 with corners 52 4, 53 4, 53 6 between FL100 and FL300"),
    "POLYALT P1 FL300 FL100 52 4 53 4 53 6")
  check_eq(lt("Draw a reference line REF1 from 55.68 -3.27 to 56.12 -3.20."), "LINE REF1 55.68 -3.27 56.12 -3.2")
  check_eq(lt("Circle SCTMA at 55.9 -3.4 radius 30 NM, from the surface up to FL195."), "CIRCLE SCTMA 55.9 -3.4 30 FL195 0")
  check_eq(lt("box B1 from 52 4 to 53 6 from the ground up to 5000 ft"), "BOX B1 52 4 53 6 5000 0")
  check(lt("a circle named C1 around 52 4 radius 10 nm up to FL100"):find("^ASK Between which two levels") ~= nil,
    "one level of a shape with no surface said is asked")
  -- the deletion area by a shape's name; what a setting does, said in the passive, instructs nobody
  check(lab:exec("BOX SECT1 59.5 10 60.5 12.5 FL660 FL245"))
  check_eq(lt("Use SECT1 as the deletion area."), "AREA SECT1")
  check_eq(lt("make SECT1 the deletion area"), "AREA SECT1")
  check_eq(lt("Use the SECT1 box as experiment area, so anything leaving it gets deleted."), "AREA SECT1")
  check_eq(lt("delete the deletion area"), "AREA OFF")
  check_eq(lt("remove the experiment area"), "AREA OFF")
  check_eq(lt("circle C1 centred on 52 4, radius 20 nm"), "CIRCLE C1 52 4 20")
  -- more ways of the same settings: the clock, the wind straight after its word, CR by its letters
  check_eq(lt("skip 5 minutes"), "FF 300")
  check_eq(lt("carry on"), "OP")
  check_eq(lt("wind 270 at 30 kt at 52 4"), "WIND 52 4 270 30")
  check_eq(lt("random seed 42"), "SEED 42")
  local r = graph.translate("CD on, CR off", { sim = lab, mode = "offline" })
  check_eq(r.confirm and table.concat(r.confirm.commands, " ; "), "ASAS ON ; RESO OFF")
  -- a setting's value the simulator refuses is asked about, naming the refusal, never sent
  check_eq(lt("set the time step to 0 seconds"),
    "ASK squawk would refuse DT 0 (time step 0 s is not in [0.001, 60] s). What value should it be?")
  check(lt("set the look-ahead to 0"):find("^ASK squawk would refuse DTLOOK 0") ~= nil, lt("set the look-ahead to 0"))
  check(lt("rfach 0.5 please"):find("^ASK squawk would refuse RFACH 0.5") ~= nil, lt("rfach 0.5 please"))
  check(lt("set the sim speed to 0 times real time"):find("^ASK squawk would refuse DTMULT 0") ~= nil, "DTMULT 0 asked")
  -- a waypoint defined for this run, deleted with no aircraft named, is undefined where it was defined;
  -- one on an aircraft's route, or with an aircraft named, leaves that route
  check(lab:exec("DEFWPT VALA 55.55 12.40"))
  check(lab:exec("DEFWPT VALB 55.75 12.95"))
  check(lab:exec("ADDWPT SAS421 VALB"))
  local function wt(text) return said(graph.translate(text, { sim = lab, mode = "offline", waypoints = { "VALA", "VALB" } })) end
  check_eq(wt("Delete my waypoint VALA, we're not using it."), "DEFWPT VALA 55.55 12.4 DELETE")
  check_eq(wt("remove the fix VALA"), "DEFWPT VALA 55.55 12.4 DELETE")
  check(wt("delete waypoint VALB"):find("^ASK Which aircraft") ~= nil, wt("delete waypoint VALB"))
  check_eq(wt("SAS421 delete waypoint VALB"), "DELWPT SAS421 VALB")
end

-- R20's classes (an ATC training lab): a self-correction said in words replaces the value (and
-- the turn's direction) before it; a speaker's label is no part of the request; "when you reach"
-- a level makes the instruction wait for it; a plain "then" lists the next instruction, the
-- formal "descend and maintain ... then" waits; a waypoint's type said as what it is; "resume own
-- navigation" with no route is asked about; a flight number's letters said apart; an airline's 738
do
  local lab, lt = scene({ "CRE KLM1234 B738 52.6 4.2 140 FL250 290", "CRE RYR81JC B738 51.2 0.4 310 FL110 250",
      "CRE EIN44 A320 51.75 4.45 315 FL320 290", "CRE BAW123 A321 52.2 3.9 060 FL120 250",
      "DEFWPT ALPHA 52.0 4.0", "ADDWPT RYR81JC ALPHA" })
  check_eq(lt("KLM1234 speed 280, no wait, 270"), "SPD KLM1234 270")
  check_eq(lt("KLM1234 climb to FL300... sorry FL310"), "ALT KLM1234 FL310")
  check_eq(lt("RYR81JC descend to four thousand feet, no sorry, five thousand"), "ALT RYR81JC 5000")
  check_eq(lt("KLM1234 turn right heading 200 ... actually make that 210"), "HDG KLM1234 210 RIGHT")
  check_eq(lt("KLM1234 turn right heading 300, oh no, left heading 100"), "HDG KLM1234 100 LEFT")
  check_eq(lt("instructor: KLM1234 climb FL300"), "ALT KLM1234 FL300")
  check_eq(lt("Controller here - BAW123 speed 220"), "SPD BAW123 220")
  -- a label of two role words, and the simulator's or pilot's labels: "op" is no OP command
  check_eq(lt("sim op: BAW123 speed 220"), "SPD BAW123 220")
  check_eq(lt("Operator: delete KLM1234"), "DEL KLM1234")
  check_eq(lt("pilot: EIN44 descend FL280"), "ALT EIN44 FL280")
  check_eq(lt("simulator operator - BAW123 heading 100"), "HDG BAW123 100")
  check_eq(lt("operator, delete KLM1234"), "DEL KLM1234")
  check_eq(lt("Operator please give BAW123 heading 100"), "HDG BAW123 100")
  check_eq(lt("EIN44 when you reach FL300 turn left heading 200"), "ATALT EIN44 FL300 HDG EIN44 200 LEFT")
  check_eq(lt("EIN44 once you reach flight level 300 reduce speed 250"), "ATALT EIN44 FL300 SPD EIN44 250")
  check_eq(lt("BAW123 slow to 230 then climb FL150"), "SPD BAW123 230 ; ALT BAW123 FL150")
  check_eq(lt("BAW123 climb FL150 then speed 280"), "ALT BAW123 FL150 ; SPD BAW123 280")
  check_eq(lt("BAW123 climb and maintain FL150 then increase speed to 280"),
    "ALT BAW123 FL150 ; ATALT BAW123 FL150 SPD BAW123 280")
  check_eq(lt("define waypoint DELTA at 51.9 4.1 as a fix"), "DEFWPT DELTA 51.9 4.1 FIX")
  check_eq(lt("create a waypoint called ECHO at 52.1 4.3, type VOR"), "DEFWPT ECHO 52.1 4.3 VOR")
  check_eq(lt("define a fix GOLF at 52.2 4.4"), "DEFWPT GOLF 52.2 4.4")
  check_eq(lt("BAW123 resume own navigation"),
    "ASK BAW123 has no route to navigate by. Which waypoint or heading should it fly?")
  check_eq(lt("BAW123 lnav on"), "LNAV BAW123 ON")
  check_eq(lt("RYR81JC resume own navigation"), "LNAV RYR81JC ON")
  check_eq(lt("RYR81JC go back on your route"), "LNAV RYR81JC ON")
  check_eq(lt("RYR81JC rejoin the route please"), "LNAV RYR81JC ON")
  check_eq(lt("ryanair 81 JC turn left heading 250"), "HDG RYR81JC 250 LEFT")
  check_eq(lt("add a Ryanair 738, RYR22AB, at 51.5 0.5, heading 090, FL200, 250 knots"),
    "CRE RYR22AB B738 51.5 0.5 90 FL200 250")
  check_eq(lt("add a 737-700 called TST4 at ALPHA heading 225 at FL320 doing 280 knots"),
    "CRE TST4 B737 ALPHA 225 FL320 280")
  -- an intruder's time: after "loss of separation", or the one time said with no vertical part
  check_eq(lt("make an intruder named INT7, A320, against BAW123, at 60 degrees, cpa 1, separation lost in 240 seconds"),
    "CRECONFS INT7 A320 BAW123 60 1 240")
  check_eq(lt("add an intruder for KLM1234: INT8 A321, 30 degrees, cpa 0.5 nm, 150 s"), "CRECONFS INT8 A321 KLM1234 30 0.5 150")
  check(lt("add an intruder for KLM1234: INT9 A321, 30 degrees, cpa 0.5 nm"):find("^ASK In how many seconds") ~= nil,
    "an intruder with no time asks for it")
end

-- North American traffic (R19): a Canadian registration spelled or hyphenated, a maker before it; a
-- military telephony; a new aircraft of an airline already flying, its flight number said in words
do
  local na, nt = scene({ "CRE CFABC C172 43.7 -79.2 090 3000 100", "CRE ASA331 B739 46.6 -122.6 350 FL200 290",
      "CRE RCH451 C17 40.4 -74.6 045 FL240 300", "CRE NAVY21 C130 41.7 -88.9 020 9000 250",
      "CRE DLH4AX A321 52.4 4.4 090 FL300 280" })
  check_eq(nt("C-FABC descend to two thousand five hundred"), "ALT CFABC 2500")
  check_eq(nt("Cessna Charlie Foxtrot Alpha Bravo Charlie, fly heading two seven zero"), "HDG CFABC 270")
  check_eq(nt("what's the position of Charlie Foxtrot Alpha Bravo Charlie?"), "POS CFABC")
  check_eq(nt("Reach four five one, climb flight level two six zero"), "ALT RCH451 FL260")
  check_eq(nt("remove Navy two one"), "DEL NAVY21")
  -- a designator written with its hyphen
  check_eq(nt("create RCH9 a C-17 at 52 4, heading 090, FL100, 250 knots"), "CRE RCH9 C17 52 4 90 FL100 250")
  check_eq(nt("create RCH10, C-130, at 52 4, heading 090, FL100, 250 knots"), "CRE RCH10 C130 52 4 90 FL100 250")
  check_eq(nt("Create Alaska five twelve, a B739, over SPY, FL240, heading 350, 290 knots"),
    "CRE ASA512 B739 SPY 350 FL240 290")
  check_eq(nt("create Alaska twenty-two oh seven, a B739, over SPY, FL240, heading 350, 290 knots"),
    "CRE ASA2207 B739 SPY 350 FL240 290")
  -- the flight number of an aircraft flying creates nothing new
  check(nt("create Alaska three three one, a B739, over SPY, FL240, heading 350, 290 knots"):find("^ASK") ~= nil,
    "an aircraft that flies is not created again")
end

-- An experimenter's words (R22): an agent is an aircraft; "the DLH", an airline's designator alone,
-- names its one aircraft flying (two KLM aircraft: asked); "go east" is a heading; "drop" an aircraft
-- with nothing after it deletes it
check_eq(said(tr("have the DLH agent go southwest")), "HDG DLH4AX 225")
check(said(tr("have the KLM agent go southwest")):find("^ASK") ~= nil, "two KLM aircraft fly")
check_eq(said(tr("BAW8CK go west, then down to FL150")), "HDG BAW8CK 270 ; ALT BAW8CK FL150")
check_eq(said(tr("drop the DLH agent")), "DEL DLH4AX")
check_eq(said(tr("drop BAW8CK to FL180")), "ALT BAW8CK FL180")
-- no instruction of a line dropped: the method named with detection, a position logged after a
-- level, a rate said with a level given without a verb; a full turn is an orbit, not a heading
check_eq(said(tr("switch on state-based conflict detection")), "ASAS STATEBASED")
check_eq(said(tr("DLH4AX up to FL340 and record its position")), "ALT DLH4AX FL340 ; POS DLH4AX")
check_eq(said(tr("BAW8CK go to FL240 at 1500 fpm and 270 knots")), "ALT BAW8CK FL240 1500 ; SPD BAW8CK 270")
r = tr("BAW8CK turn around completely, 360 to the left")
check(#(r.commands or {}) == 0 and (r.note or ""):find("orbits", 1, true) ~= nil, said(r))
-- a condition said with no comma ends at its value, and an instruction must follow it
check_eq(said(tr("when DLH4AX reaches FL320 slow it to 250 knots")), "ATALT DLH4AX FL320 SPD DLH4AX 250")
check_eq(said(tr("once BAW8CK slows to 230 turn it left heading 300")), "ATSPD BAW8CK 230 HDG BAW8CK 300 LEFT")
check(said(tr("when DLH4AX reaches FL320")):find("^ASK") ~= nil, "a condition with nothing to do asks")
-- a data scientist's words: a position's labels, a turn by "rotate"/"nudge", an episode, a path
check_eq(said(tr("move DLH4AX to lat 52.5 lon 4.1")), "MOVE DLH4AX 52.5 4.1")
check_eq(said(tr("nudge DLH4AX 20 degrees right")), "HDG DLH4AX 110 RIGHT")
check_eq(said(tr("remove BAW8CK from this episode")), "DEL BAW8CK")
check_eq(said(tr("dump the state of DLH4AX")), "POS DLH4AX")
-- routes printed, places pointed at, an arrow, "the Lufthansa one", cruise at a speed, a circle at a
-- position, a heading by "facing", the clock's rate as "times real time"
check_eq(said(tr("print the flight plan of DLH4AX")), "LISTRTE DLH4AX")
check_eq(said(tr("DLH4AX -> SPY")), "ADDWPT DLH4AX SPY ; DIRECT DLH4AX SPY")
check_eq(said(tr("point the DLH at SPY")), "ADDWPT DLH4AX SPY ; DIRECT DLH4AX SPY")
check_eq(said(tr("could the lufthansa one descend to FL260")), "ALT DLH4AX FL260")
check(said(tr("the lufthansa one two three, descend FL260")):find("^ASK") ~= nil, "a flight number said in words")
check_eq(said(tr("DLH4AX cruise at mach .78")), "SPD DLH4AX M0.78")
check_eq(said(tr("make a circular area C9 around 52.2, 4.4 with a 15 nm radius")), "CIRCLE C9 52.2 4.4 15")
check_eq(said(tr("create ABC12 A320 at 52.1 4.1 facing north at FL200 doing 250")), "CRE ABC12 A320 52.1 4.1 360 FL200 250")
check_eq(said(tr("set the speed to 4 times real time")), "DTMULT 4")
-- a level by "go to" and a bare thousand; a route waypoint forgotten; route following stopped; a
-- position appended as a waypoint; a bracketed remark; an arrow after a setting's name is no direct-to
check_eq(said(tr("BAW8CK go to 9000")), "ALT BAW8CK 9000")
check(said(tr("BAW8CK go to 270")):find("^ASK") ~= nil, "a bare 270 after 'go to' is no level")
check_eq(said(tr("stop DLH4AX following its flight plan")), "LNAV DLH4AX OFF")
check_eq(said(tr("append 52.3, 4.9 as a waypoint for DLH4AX")), "ADDWPT DLH4AX 52.3 4.9")
check_eq(said(tr("DLH4AX heading 120 (it should pass behind the KLM)")), "HDG DLH4AX 120")
check_eq(said(tr("DLH4AX: alt -> FL310, spd -> 260")), "ALT DLH4AX FL310 ; SPD DLH4AX 260")
do
  local rs = squawk.sim.new()
  check(rs:exec("CRE AB12 A320 52 4 090 FL200 250"))
  check(rs:exec("DEFWPT WP1 52.1 4.5"))
  check(rs:exec("DEFWPT WP2 52.2 4.8"))
  check(rs:exec("ADDWPT AB12 WP1"))
  local _, rt = set_up(rs, {})
  check_eq(rt("AB12 forget WP1"), "DELWPT AB12 WP1")
  check(rt("AB12 forget WP2"):find("^ASK") ~= nil, "a waypoint off the route is not forgotten")
end
-- an "expect" is information, not a clearance: named as not simulated, never a turn or a level
r = tr("DLH4AX expect runway 27 right")
check(#(r.commands or {}) == 0 and (r.note or ""):find("expected clearances", 1, true) ~= nil, said(r))
r = tr("DLH4AX descend FL240, expect ILS runway 06")
check_eq(said(r), "ALT DLH4AX FL240")
check((r.note or ""):find("expect ILS runway 06", 1, true) ~= nil, tostring(r.note))
-- a climb or descent left to the pilot with no level said is asked about, never dropped
check(said(tr("DLH4AX maintain present level, descend when ready")):find("^ASK To what level should DLH4AX descend") ~= nil,
  "a discretionary descent with no level asks")
check(said(tr("BAW8CK climb at your discretion")):find("^ASK") ~= nil, "no level")
check_eq(said(tr("DLH4AX descend at pilot's discretion, maintain FL240")), "ALT DLH4AX FL240")
-- "cross FIX at ALT and SPD": one AT constraint each at a waypoint of the route; off the route, asked
do
  local cs, ct = scene({ "CRE AB12 A320 52 4 090 FL200 250", "DEFWPT WP1 52.1 4.5", "DEFWPT WP2 52.2 4.8",
      "ADDWPT AB12 WP1" })
  check_eq(ct("AB12 cross WP1 at FL150 and 240 knots"), "AT AB12 WP1 ALT FL150 ; AT AB12 WP1 SPD 240")
  check_eq(ct("AB12 cross WP1 at mach .74"), "AT AB12 WP1 SPD M0.74")
  check(ct("AB12 cross WP2 at FL150 and 240 knots"):find("^ASK") ~= nil, "WP2 is not on the route")
  check(ct("AB12 cross WP1 at FL150, 240 knots, 3000 ft"):find("^ASK") ~= nil, "two levels for one fix")
  check_eq(ct("set the constraint at WP1 to FL160 for AB12"), "AT AB12 WP1 ALT FL160")
end
-- a turn or a change of speed said by its direction alone beside a complete instruction is asked
-- about, never dropped; a compass point after "then" is a heading
check(said(tr("DLH4AX go left then climb FL320")):find("^ASK What heading") ~= nil, "the turn is asked about")
check(said(tr("DLH4AX go faster and descend FL200")):find("^ASK What speed") ~= nil, "the speed is asked about")
check(said(tr("DLH4AX fly north and slow down")):find("^ASK What speed") ~= nil, "the speed is asked about")
check_eq(said(tr("DLH4AX climb to FL320, then south")), "ALT DLH4AX FL320 ; HDG DLH4AX 180")
check_eq(said(tr("get DLH4AX to climb to FL350 at 1000 fpm, we want a slow climb")), "ALT DLH4AX FL350 1000")
-- a readback corrected: the value after "not" is the one ruled out, the one before it stands
check_eq(said(tr("DLH4AX readback incorrect, descend flight level two four zero, not two three zero")), "ALT DLH4AX FL240")
check_eq(said(tr("BAW8CK I said heading 310, not 300")), "HDG BAW8CK 310")
check(said(tr("DLH4AX do not descend")):find("^ASK") ~= nil, "a negated instruction is never run")
check(said(tr("DLH4AX descend FL240, not before SPY")):find("^ASK") ~= nil, "a negated condition is asked about")
-- detection "every N seconds" is its interval (DT ASAS), switched on only when said; "call sign" is
-- the callsign
check_eq(said(tr("run conflict detection every 3 seconds")), "DT ASAS 3")
check_eq(said(tr("switch on conflict detection every 5 seconds")), "ASAS ON ; DT ASAS 5")
check_eq(said(tr("create a new aircraft, type A320, call sign TST1, at 52.0 4.0, heading 090, FL200, 250 knots")),
  "CRE TST1 A320 52 4 90 FL200 250")
-- a heading changed by an amount: more (increase, plus, add) turns right, less (decrease, minus,
-- subtract) left, from the present heading (DLH4AX flies 090); never the amount as a heading
check_eq(said(tr("increase the heading of DLH4AX by 30")), "HDG DLH4AX 120 RIGHT")
check_eq(said(tr("DLH4AX heading minus 20")), "HDG DLH4AX 70 LEFT")
check_eq(said(tr("subtract 45 from DLH4AX's heading")), "HDG DLH4AX 45 LEFT")
check_eq(said(tr("add 15 to the heading of DLH4AX")), "HDG DLH4AX 105 RIGHT")
do -- a waypoint of the route said straight after "delete"/"remove" is taken off the route
  local ds, dt = scene({ "CRE AB12 A320 52 4 090 FL200 250", "DEFWPT WP1 52.1 4.5", "ADDWPT AB12 WP1" })
  check_eq(dt("AB12 delete WP1"), "DELWPT AB12 WP1")
  check_eq(dt("remove WP1 from AB12"), "DELWPT AB12 WP1")
  check_eq(dt("delete AB12"), "DEL AB12")
end
-- "position of X?" and "X position?" ask for its position; "triple seven" / "double two" are digits said
-- again; "Sky Dubai" is flydubai's telephony
check_eq(said(tr("Position of DLH4AX?")), "POS DLH4AX")
check_eq(said(tr("BAW8CK position?")), "POS BAW8CK")
do
  local ms = squawk.sim.new()
  check(ms:exec("CRE MSR777 B738 30.9 30.8 135 FL260 280"))
  check(ms:exec("CRE FDB22 B738 25.0 56.9 250 FL280 270"))
  local _, mt = set_up(ms, {})
  check_eq(mt("Egyptair triple seven, climb flight level two eight zero"), "ALT MSR777 FL280")
  check_eq(mt("Sky Dubai double two, descend flight level two four zero"), "ALT FDB22 FL240")
  check_eq(mt("set the simulation to double speed"), "DTMULT 2")
end
-- South Asian and East African airlines by their ICAO telephony (PIA is "Pakistan", Biman "Bangladesh",
-- Air Tanzania "Tanzania", SriLankan "Srilankan")
do
  local sa, st = scene({ "CRE PIA207 B738 24.9 67.2 90 FL200 280", "CRE BBC85 B738 23.8 90.4 90 FL200 280",
      "CRE ATC412 A320 -6.9 39.2 90 FL200 280", "CRE ALK226 A320 7.2 79.9 90 FL200 280" })
  check_eq(st("Pakistan two zero seven, climb flight level two four zero"), "ALT PIA207 FL240")
  check_eq(st("remove Bangladesh 85"), "DEL BBC85")
  check_eq(st("Tanzania 412 turn left heading 300"), "HDG ATC412 300 LEFT")
  check_eq(st("SriLankan 226 reduce speed 250 knots"), "SPD ALK226 250")
  -- the telephony said with "Airways" or "Airlines"; "route of" opening a request naming only the aircraft
  check_eq(st("Pakistan Airlines 207 descend FL180"), "ALT PIA207 FL180")
  check_eq(st("create Tanzania Airways 77, A320, at HTDA heading 090, 6000 feet, 220 knots"),
    "CRE ATC77 A320 HTDA 90 6000 220")
  check_eq(st("route of Pakistan 207 please"), "LISTRTE PIA207")
  check_eq(st("route of ALK226"), "LISTRTE ALK226")
end
-- Latin American and Iberian airlines by their telephony or the name they fly under
do
  local la = squawk.sim.new()
  check(la:exec("CRE ARG1303 B738 -34.6 -58.4 90 FL200 280"))
  check(la:exec("CRE GLO1120 B738 -23.4 -46.5 90 FL200 280"))
  local _, lt = set_up(la, {})
  check_eq(lt("Aerolineas Argentinas one three zero three, descend flight level one two zero"), "ALT ARG1303 FL120")
  check_eq(lt("Gol one one two zero, turn right heading zero niner zero"), "HDG GLO1120 90 RIGHT")
  check_eq(lt("create Aerosky one one five, A320, at -33.4 -70.8, heading 350, FL100, 250 knots"),
    "CRE SKU115 A320 -33.4 -70.8 350 FL100 250")
end
-- the wind at a position asked for is GETWIND; text in single quotes is quoted text
check_eq(said(tr("what's the wind at 52.1, 4.3?")), "GETWIND 52.1 4.3")
check_eq(said(tr("show me the wind at 52.1 4.3 at FL200")), "GETWIND 52.1 4.3 FL200")
check_eq(said(tr("print 'run 3 started' to the log")), "ECHO run 3 started")
-- digits said in Spanish or Portuguese beside another digit or a spelled letter are those digits;
-- one alone is a word squawk does not know, asked about
check_eq(said(tr("KLM uno dos tres cuatro, descend flight level two four zero")), "ALT KLM1234 FL240")
check_eq(said(tr("KLM siete siete reduce speed dos dos cero knots")), "SPD KLM77 220")
check_eq(said(tr("KLM one dois três quatro climb flight level três meia zero")), "ALT KLM1234 FL360")
check_eq(said(tr("Speedbird ocho charlie kilo turn left heading cero nueve cero")), "HDG BAW8CK 90 LEFT")
check_eq(said(tr("KLM77 descend flight level one two zero, gracias")), "ALT KLM77 FL120")
check_eq(said(tr("freeze the simulation, momentito, por favor")), "HOLD")
check_eq(said(tr("KLM77 tres descend flight level one two zero")),
  "ASK I have ALT KLM77 FL120. What does 'tres' mean?")
check(said(tr("delete the pilots' aircraft DLH4AX")):find("^ASK") ~= nil, "an apostrophe opens no quote")
-- the performance model by name: PERF CLASS / PERF OPENAP; none or both named is asked
check_eq(said(tr("switch to the class-based performance model")), "PERF CLASS")
check_eq(said(tr("use OpenAP for the performance")), "PERF OPENAP")
check(said(tr("change the performance model")):find("^ASK") ~= nil, "no model named")
-- an instruction with no value in a clause of its own after another is asked about, never dropped
check(said(tr("DLH4AX heading 270 and climb")):find("^ASK What altitude") ~= nil, "the climb is asked about")
check(said(tr("DLH4AX descend FL200 and increase speed")):find("^ASK What speed") ~= nil, "the speed is asked about")
check(said(tr("DLH4AX speed 250, then left")):find("^ASK What heading") ~= nil, "the turn is asked about")
check_eq(said(tr("DLH4AX climb and maintain FL320")), "ALT DLH4AX FL320")
check(said(tr("DLH4AX climb and turn right heading 300")):find("^ASK What altitude") ~= nil, "the climb is asked about")
check(said(tr("DLH4AX turn right, descend FL200")):find("^ASK What heading") ~= nil, "the turn is asked about")
check_eq(said(tr("DLH4AX turn left and fly heading 200")), "HDG DLH4AX 200 LEFT")
-- UK and Nordic radiotelephony (R24): a runway's side is part of its name, never a turn's direction;
-- "make" alone is no self-correction; a waypoint put after another one of the route, the verb before
-- or after "after X"; a route said to go on as it already does ("direct TWEED then GIRVA") is no
-- instruction of its own, a place that does not follow so is asked about
do
  local setup = "DEFWPT TWEED 55.6 -2.5 ; DEFWPT GIRVA 55.2 -4.9 ; DEFWPT STIRA 56.0 -4.0 ; DEFWPT FYNER 56.1 -5.2 ; "
    .. "DEFWPT KORAK 53.2 -8.0 ; CRE KLM1276 B738 55.4 -2.6 290 FL240 300 ; ADDWPT KLM1276 TWEED ; "
    .. "ADDWPT KLM1276 GIRVA ; ADDWPT KLM1276 STIRA ; CRE LOG34 AT76 55.8 -4.5 320 FL110 220 ; ADDWPT LOG34 FYNER ; "
    .. "CRE WIF512 DH8D 56.3 -3.4 120 FL080 220"
  local uk = squawk.sim.new()
  for _, line in ipairs(require("translate.nodes").split_commands(setup)) do check(uk:exec(line)) end
  local function ut(text) return said(graph.translate(text, { sim = uk, mode = "offline", setup = setup })) end
  check_eq(ut("KLM1276, you will get vectors for runway zero one left, turn right heading two three zero"),
    "HDG KLM1276 230 RIGHT")
  check_eq(ut("KLM1276 expect runway 27 right, turn left heading 180"), "HDG KLM1276 180 LEFT")
  check_eq(ut("KLM1276 turn left heading 200, vectors ILS runway two three centre"), "HDG KLM1276 200 LEFT")
  local r = graph.translate("KLM1276, make one left hand orbit for spacing", { sim = uk, mode = "offline", setup = setup })
  check(#r.commands == 0 and r.note ~= nil and r.note:find("orbits", 1, true) ~= nil, said(r))
  check_eq(ut("KLM1276 speed 250, make that 240"), "SPD KLM1276 240")
  check_eq(ut("KLM1276, after TWEED add KORAK to your routing"), "ADDWPT KLM1276 KORAK,,,TWEED")
  check_eq(ut("KLM1276 after GIRVA route KORAK then STIRA"), "ADDWPT KLM1276 KORAK,,,GIRVA")
  check_eq(ut("KLM1276 route direct TWEED then GIRVA, descend flight level two zero zero"),
    "DIRECT KLM1276 TWEED ; ALT KLM1276 FL200")
  check_eq(ut("KLM1276 direct GIRVA then STIRA"), "DIRECT KLM1276 GIRVA")
  check_eq(ut("KLM1276 direct TWEED then STIRA"), "ASK I have DIRECT KLM1276 TWEED. What does 'STIRA' mean?")
  check_eq(ut("LOG34, after FYNER proceed direct KORAK"), "ADDWPT LOG34 KORAK,,,FYNER")
  -- a value instruction's verb after a waypoint added is no constraint of it (asked, never absorbed);
  -- a value's noun is
  check(ut("KLM1276 add KORAK to your route, after that climb FL300"):find("^ASK I have ADDWPT KLM1276 KORAK%.")
    ~= nil, ut("KLM1276 add KORAK to your route, after that climb FL300"))
  check_eq(ut("add waypoint KORAK to KLM1276 route at flight level 300 speed 250"), "ADDWPT KLM1276 KORAK FL300 250")
  check_eq(ut("KLM1276 resume own navigation to GIRVA"), "DIRECT KLM1276 GIRVA")
  check_eq(ut("KLM1276 resume own navigation, climb FL300"), "LNAV KLM1276 ON ; ALT KLM1276 FL300")
  -- a correction's verb gives the direction ("negative" as "correction"); a value after "not", straight
  -- after the one meant and ending its clause, says which is not meant; anywhere else it is asked about
  check_eq(ut("KLM1276 climb flight level two six zero, negative, descend, descend flight level two two zero"),
    "ALT KLM1276 FL220")
  check_eq(ut("KLM1276 descend FL200 correction climb FL260"), "ALT KLM1276 FL260")
  check_eq(ut("KLM1276 climb FL300, negative"),
    "ASK You said 'negative' with nothing after it. What is the corrected instruction?")
  check_eq(ut("KLM1276, negative, climb flight level three one zero, not three zero zero"), "ALT KLM1276 FL310")
  check_eq(ut("KLM1276 it was heading one one zero, not one zero zero"), "HDG KLM1276 110")
  check_eq(ut("KLM1276 climb FL310 not 300 speed 250"),
    "ASK I have ALT KLM1276 FL310 ; SPD KLM1276 250. What does '300' mean?")
  check_eq(ut("KLM1276 climb without restriction flight level three zero zero"), "ALT KLM1276 FL300")
  check_eq(ut("KLM1276 climb FL300 without a level off"), "ASK I have ALT KLM1276 FL300. What does 'without' mean?")
  check_eq(ut("KLM1276 climb FL300 without delay"), "ALT KLM1276 FL300")  -- (urgency, as "expedite")
  -- an aircraft shown, its route shown with the callsign said in words; the clock
  check_eq(ut("show me KLM one two seven six"), "POS KLM1276")
  check_eq(ut("show me KLM one two seven six's route"), "LISTRTE KLM1276")
  check_eq(ut("show me Wideroe five one two"), "POS WIF512")  -- (Widerøe's telephony, names.lua)
  check_eq(ut("jump us forward ten minutes"), "FF 600")
  check_eq(ut("run it at twice real time"), "DTMULT 2")
  check_eq(ut("speed it up, double"), "DTMULT 2")
  -- a list of commands, each clause opening with a command word, is read clause by clause; a pronoun
  -- after the word makes it English, read whole
  check_eq(ut("seed 7, mcre 3, ff 10 min"), "SEED 7 ; MCRE 3 ; FF 600")
  check_eq(ut("speed it up a bit, run it at twice real time"), "DTMULT 2")
  check(graph.command_clauses("speed it up a bit, run it at twice real time") == nil, "a pronoun after a command word")
  check_eq(#graph.command_clauses("seed 7, mcre 3, ff 10 min"), 3)
  -- a clause that is only a linking word ("hold, and", speech's empty clauses) is no command: read whole
  check(graph.command_clauses("hold, and") == nil, "a clause of a linking word alone")
  check_eq(ut("hold, and"), "HOLD")
  -- a type's letters before its digits said as words ("CRJ nine"), a maker before its model ("Saab three
  -- forty"); a new aircraft's callsign said in words before its type
  check_eq(ut("create SAS32AB, a CRJ nine, at TWEED, flight level one zero zero, heading zero nine zero, "
    .. "two five zero knots"), "CRE SAS32AB CRJ9 TWEED 90 FL100 250")
  check_eq(ut("add a Loganair six two one, Saab three forty, at FYNER, flight level eight zero, heading three one "
    .. "zero, two hundred knots"), "CRE LOG621 SF34 FYNER 310 FL80 200")
  -- a coordinate typed in digits with its point said, before a hemisphere; a heading's "point 5" is asked
  check_eq(ut("create BAW9 A320 at 55 decimal 5 north 4 point 25 west heading 020 FL270 280 knots"),
    "CRE BAW9 A320 55.5 -4.25 20 FL270 280")
  check_eq(ut("KLM1276 heading 270 point 5"), "ASK I have HDG KLM1276 270. What does '5' mean?")
end
-- An experiment session set up at the command box (R23)
do
  local ex, et = scene({ "CRE KLM1234 B738 52.2 4.2 300 FL250 280", "CRE DLH4AX A321 52.4 4.4 090 FL300 280",
      "CRE KLM77 B738 52.1 4.5 180 FL150 250" })
  -- the addressee is named before the instruction; traffic named in its purpose is context
  check_eq(et("DLH4AX descend FL240 to put it level with KLM77"), "ALT DLH4AX FL240")
  check_eq(et("KLM77 turn left heading 200 to separate from KLM1234"), "HDG KLM77 200 LEFT")
  check_eq(et("KLM1234 heading 090 to cross behind DLH4AX"), "HDG KLM1234 90")
  check_eq(et("DLH4AX heading 270 - should pass behind KLM77"), "HDG DLH4AX 270")
  -- a registry name typed inside English names its command ("rmethv off"); one no intent reads
  -- is asked about, never dropped beside what was read
  check_eq(et("rmethv off - horizontal resolutions only"), "RMETHV OFF")
  local r = graph.translate("pcall foo.scn and ff 60", { sim = ex, mode = "offline" })
  check(r.ask ~= nil and r.ask:find("'pcall'", 1, true) ~= nil, said(r))
  -- the clock resumed at a rate
  check_eq(et("resume at 3 times real time"), "OP ; DTMULT 3")
  check_eq(et("continue the simulation at twice real time"), "OP ; DTMULT 2")
  check_eq(et("speed up the sim by a factor of 5"), "DTMULT 5")
  -- "both" after the values of two aircraft; a value clause before the first instruction word
  check_eq(et("KLM1234 FL300 and DLH4AX FL310, both 260 knots"),
    "ALT KLM1234 FL300 ; ALT DLH4AX FL310 ; SPD KLM1234 260 ; SPD DLH4AX 260")
  check(et("KLM1234 FL300, DLH4AX FL310, KLM77 FL320, both 260 knots"):find("^ASK Which two") ~= nil,
    "'both' with three aircraft named asks")
  check_eq(et("KLM77 FL140, then fast forward 2 minutes"), "ALT KLM77 FL140 ; FF 120")
  -- a level arrow, from the one to the other
  check_eq(et("KLM77 FL150 -> FL170"), "ALT KLM77 FL170")
  check_eq(et("KLM77 from FL150 to FL130, speed 240"), "ALT KLM77 FL130 ; SPD KLM77 240")
  -- a new aircraft in notebook shorthand, no verb; a compass point as its heading
  check_eq(et("EZY12 A320 52.3 4.6 hdg 270 FL200 250"), "CRE EZY12 A320 52.3 4.6 270 FL200 250")
  check_eq(et("ac: EZY13 A319, 52.1 4.1, heading 045, FL180, 240 kts"), "CRE EZY13 A319 52.1 4.1 45 FL180 240")
  check_eq(et("create EZY14 A320 at 52.0 4.0, eastbound, FL200, 250 knots"), "CRE EZY14 A320 52 4 90 FL200 250")
  check_eq(et("create EZY15 A320 located at 52.0 4.0 on a southerly heading, FL200, 250 knots"),
    "CRE EZY15 A320 52 4 180 FL200 250")
  -- random traffic with its type, level and speed; the detection method; a lookahead before its noun
  check_eq(et("spawn 4 random A320s at FL250, speed 260"), "MCRE 4 A320 FL250 260")
  check_eq(et("seed 7 then 12 random ac"), "SEED 7 ; MCRE 12")
  check_eq(et("conflict detection state-based"), "ASAS STATEBASED")
  check_eq(et("a 240 s lookahead, then detection on"), "DTLOOK 240 ; ASAS ON")
  check_eq(et("print run 3 started to the console"), "ECHO run 3 started")
  check_eq(et("remove KLM77, not required any more"), "DEL KLM77")
  -- a level or speed at a waypoint of the aircraft's route is AT; at another, squawk asks
  check(ex:exec("DEFWPT TULIP 52.5 4.6"))
  check(ex:exec("ADDWPT KLM77 TULIP"))
  local function wt(text) return said(graph.translate(text, { sim = ex, mode = "offline", waypoints = { "TULIP" } })) end
  check_eq(wt("KLM77 at TULIP descend FL100"), "AT KLM77 TULIP DO ALT KLM77 FL100")
  check_eq(wt("KLM77 at TULIP speed 220"), "AT KLM77 TULIP SPD 220")
  check(wt("DLH4AX at TULIP speed 220"):find("^ASK Should that happen at TULIP") ~= nil, "TULIP is no waypoint of DLH4AX")
end

-- Places of the navdata said the way an experimenter writes them (R23): accents, a city before
-- the airport's name, a navaid's kind, a route as a list
do
  local nav, pt = navscene({ "CRE KLM1234 B738 52.2 4.2 300 FL250 280" }, "R23 place names")
  if nav then
    check_eq(pt("KLM1234 destination Düsseldorf"), "DEST KLM1234 EDDL")
    check_eq(pt("KLM1234 dest Amsterdam Schiphol"), "DEST KLM1234 EHAM")
    check_eq(pt("create KLM5 B738 @ Eelde VOR hdg 090 FL100 250kt"), "CRE KLM5 B738 EEL 90 FL100 250")
    check_eq(pt("KLM1234 route: SPY, PAM"), "ADDWPT KLM1234 SPY ; ADDWPT KLM1234 PAM")
    check_eq(pt("give KLM1234 a route through SPY and PAM"), "ADDWPT KLM1234 SPY ; ADDWPT KLM1234 PAM")
    check_eq(pt("KLM1234 add PAM, dest Bremen"), "ADDWPT KLM1234 PAM ; DEST KLM1234 EDDW")
  end
end

-- Places by name where an aircraft is sent, put or routed (sentences written here, R25/R29's classes):
-- a waypoint added with the level it is crossed at, an airport's name of three words, "going to" and a
-- route's "land it at" an airport as the destination, "put X over" a navaid's nav.dat name
do
  local nav, pt = navscene({ "CRE SWR38F A320 47.8 8.4 090 FL250 280", "CRE AFR12 A320 48.9 2.6 180 FL200 260" }, "place names")
  if nav then
    check_eq(pt("SWR38F add TRA at 9000 ft"), "ADDWPT SWR38F TRA 9000")
    check_eq(pt("SWR38F, add TRA at flight level one eight zero, 250 knots"), "ADDWPT SWR38F TRA FL180 250")
    check_eq(pt("AFR12 origin Charles de Gaulle, destination Orly"), "ORIG AFR12 LFPG ; DEST AFR12 LFPO")
    check_eq(pt("create AFR9 A320 at 48.5 2.5 heading 090 FL100 250 knots going to Orly"),
      "CRE AFR9 A320 48.5 2.5 90 FL100 250 ; DEST AFR9 LFPO")
    check_eq(pt("route SWR38F via TRA and land it at Zurich"), "ADDWPT SWR38F TRA ; DEST SWR38F LSZH")
    check_eq(pt("put SWR38F over Trasadingen at FL200 heading 180"), "MOVE SWR38F TRA FL200 180")
    -- a landing said alone is a landing clearance, not simulated: asked about, never a destination
    check(pt("SWR38F land at Zurich"):find("^ASK") ~= nil)
    -- a city the navdata names no airport by, where an airport is meant: the airport beside its navaids
    check_eq(pt("SWR38F origin Bern"), "ORIG SWR38F LSZB")
    check(nav:exec("CRE AFR77 A320 43.8 1.6 180 FL150 250"))
    check_eq(pt("AFR77 change destination to Toulouse"), "DEST AFR77 LFBO")
    check_eq(pt("AFR77 destination Toulouse, and descend FL 100"), "DEST AFR77 LFBO ; ALT AFR77 FL100")
  end
end

-- Brands and type families (names.lua's brands, types.nicknames): "the Transavia" is the one aircraft
-- flying as TRA or TVF, a callsign said with the brand's name is its aircraft of those characters,
-- "the Citation" the one Cessna business jet flying
do
  local sky, st = scene({ "CRE TVF33KP B738 49.0 2.5 045 FL250 280", "CRE EZS1419 A320 47.5 8.0 090 FL300 280",
      "CRE N525TX C525 49.2 4.2 270 FL280 250", "CRE JAF2RK B738 50.9 4.5 180 FL310 280",
      "CRE B744X B744 51.0 3.0 090 FL350 290", "CRE SWR12 A320 47.4 8.5 270 FL320 280" })
  check_eq(st("speed the Transavia up to 310"), "SPD TVF33KP 310")
  check_eq(st("please bring the easyJet down to FL 200"), "ALT EZS1419 FL200")
  -- (Transavia France's telephony is FRANCE SOLEIL: the brand said with the flight is confirmed, point 3)
  check_eq(st("Transavia three three kilo papa, climb flight level two niner zero"), "ASK Did you mean TVF33KP? I heard TRA33KP.")
  check_eq(st("clear the Jetairfly's route"), "DELRTE JAF2RK")
  check_eq(st("Topswiss, left heading 030 and descend FL 200"), "HDG EZS1419 30 LEFT ; ALT EZS1419 FL200")
  -- (a callsign of no aircraft of the brand is still asked about)
  check(st("Transavia three three kilo alpha, climb flight level two niner zero"):find("^ASK") ~= nil)
  check_eq(st("could the Citation descend to 20,000 feet please?"), "ALT N525TX 20000")
  check_eq(st("turn the Citation right heading 010"), "HDG N525TX 10 RIGHT")
  check_eq(st("the jumbo, climb FL 370"), "ALT B744X FL370")
  check(st("the Dreamliner climb FL 370"):find("^ASK") ~= nil, "no 787 flies")
end

-- Lab talk of an experimenter at the scope (round 27's classes, sentences written here)
do
  local lab = scene({ "CRE RYR81JC B738 52.0 4.0 010 FL320 280", "CRE AEA44 B738 52.3 4.3 135 FL300 290",
      "CRE IBE2604 A321 52.5 4.6 035 FL330 290", "DEFWPT WPA 52.6 4.9", "ADDWPT AEA44 WPA" })
  local function lt(text) return said(graph.translate(text, { sim = lab, mode = "offline", waypoints = { "WPA" } })) end
  -- a speed verb's particle with its aircraft between is no change of level
  check_eq(lt("slow the Ryanair down to 250"), "SPD RYR81JC 250")
  check_eq(lt("could you slow it down to 240, RYR81JC"), "SPD RYR81JC 240")
  check_eq(lt("bring the Ryanair down to FL250"), "ALT RYR81JC FL250")
  -- an intruder from the right crosses at 360 - angle, the side alone at 90; the noun alone sets one up;
  -- a bare number after "at" is the angle, never the closest approach
  check_eq(lt("put an intruder on AEA44, T1, A320, from the right at ninety, CPA 1.5 nm, loss in 360 seconds"),
    "CRECONFS T1 A320 AEA44 270 1.5 360")
  check_eq(lt("intruder on the Europa: T2, B738, from its left, cpa zero, tlos 200"), "CRECONFS T2 B738 AEA44 90 0 200")
  check_eq(lt("an intruder for RYR81JC please, T3, A321, from the right at 30 degrees, 2 miles CPA, 300 s"),
    "CRECONFS T3 A321 RYR81JC 330 2 300")
  check_eq(lt("intruder on RYR81JC, T4, A320, head-on, cpa 0, 240 seconds, 1000 feet below with vertical loss at "
    .. "180 s, 250 knots"), "CRECONFS T4 A320 RYR81JC 180 0 240 -1000 180 250")
  -- the clock: a duration after "run (fast) for", "an hour"; "start again" as a clause of its own
  check_eq(lt("set the seed to 99 and run fast for an hour"), "SEED 99 ; FF 3600")
  check_eq(lt("fast forward a minute"), "FF 60")
  check_eq(lt("pause, time step 0.2, then start again"), "HOLD ; DT 0.2 ; OP")
  -- a constraint at a waypoint of the route is AT, never a move; without a value it is asked
  check_eq(lt("put a constraint on AEA44 at WPA, FL250"), "AT AEA44 WPA ALT FL250")
  check(lt("put a constraint on AEA44 at WPA"):find("^ASK") ~= nil)
  -- the aircraft compared with is not the subject
  check_eq(lt("put RYR81JC on the same level as the Iberia, FL330, so they meet"), "ALT RYR81JC FL330")
  -- a climb or descent stopped by a vertical speed; back on the route
  check_eq(lt("stop the Ryanair's climb, vertical speed zero"), "VS RYR81JC 0")
  check_eq(lt("put AEA44 back on its route"), "LNAV AEA44 ON")
  -- a callsign no aircraft has, placed with its type, is created
  check_eq(lt("place TAP9, A320, at 52.1 N 4.2 E heading 090, FL200 and 250 knots"), "CRE TAP9 A320 52.1 4.2 90 FL200 250")
  -- accounted: a hyphen's prefix, an experimenter watching, a setting shrunk, a purpose after a comma
  check_eq(lt("RYR81JC descend FL300, we need it co-altitude with the Europa"), "ALT RYR81JC FL300")
  check_eq(lt("ok let's watch the effect: fast forward 2 minutes"), "FF 120")
  check_eq(lt("shrink the PZ to 3 nm"), "ZONER 3")
  check_eq(lt("time step 0.5, we don't need fine resolution today"), "DT 0.5")
  -- random traffic: the count after, a count that reads like a flight number, plural designators
  check_eq(lt("random traffic, 15 aircraft"), "MCRE 15")
  check_eq(lt("12 random aircraft, all B738s"), "MCRE 12 B738")
  -- an aircraft kept out of the way of is context; the interval of conflict detection
  check_eq(lt("RYR81JC climb FL340 to get out of the way of AEA44"), "ALT RYR81JC FL340")
  check_eq(lt("conflict detection update interval 3 seconds"), "DT ASAS 3")
  -- switched back on whatever went off before; a waypoint flown via is added with its level and speed
  check_eq(lt("AEA44 is drifting off its route, put it back on LNAV"), "LNAV AEA44 ON")
  check_eq(lt("have RYR81JC fly via WPA at FL300 and 270 knots"), "ADDWPT RYR81JC WPA FL300 270")
  -- an airline after the article, its new callsign after a place, is a new aircraft
  check_eq(lt("make a Ryanair at WPA, RYR12, B738, heading east, FL300, 280 knots"), "CRE RYR12 B738 WPA 90 FL300 280")
  -- an aircraft after a comma with a clause of its own is talked about, not addressed
  check_eq(lt("AEA44 reduce to 240, the Ryanair will come right over it"), "SPD AEA44 240")
  check_eq(lt("AEA44 descend FL280, the Ryanair is right behind"), "ALT AEA44 FL280")
  check_eq(lt("descend FL280, Ryanair eight one juliet charlie"), "ALT RYR81JC FL280")
  -- "straight to" is a direct-to; "the airport" is the aircraft's destination
  check_eq(lt("send RYR81JC straight to WPA"), "ADDWPT RYR81JC WPA ; DIRECT RYR81JC WPA")
end

-- R28's classes (second-language radiotelephony in south-east Europe): airlines by their ICAO
-- telephony (names.lua), another airline's telephony asked about, never matched by its digits alone;
-- a callsign heard with a wrong last digit and corrected; radar identification stated to the pilot
do
  local see, se = scene({ "CRE TVS421 B738 49.5 15.5 300 FL110 250", "CRE ASL354 A319 45.6 20.1 170 FL230 280",
      "CRE ASL7TG AT76 44.0 21.5 320 FL140 210", "CRE LZB118 A320 42.7 23.4 090 FL200 270",
      "CRE WZZ1235 A21N 47.4 19.2 260 FL350 280" })
  check_eq(se("Skytravel four two one, descend flight level one zero zero"), "ALT TVS421 FL100")
  check_eq(se("Air Serbia seven tango golf, speed two one zero"), "SPD ASL7TG 210")
  check_eq(se("Flying Bulgaria one one eight climb FL240"), "ALT LZB118 FL240")
  check_eq(se("Jat three five four, turn left heading one two zero"), "ASK Did you mean ASL354? I heard JAT354.")
  check_eq(se("Wizz Air one two three four, correction, Wizz Air one two three five, climb flight level three six zero"),
    "ALT WZZ1235 FL360")
  check_eq(se("Wizz Air one two three four correction one two three five descend FL300"), "ALT WZZ1235 FL300")
  check_eq(se("Wizz Air one two three four... correction, Wizz Air one two three five, descend FL300"),
    "ALT WZZ1235 FL300")
  check_eq(se("Wizz Air one two three four, descend FL300"), "ASK Did you mean WZZ1235? I heard WZZ1234.")
  check_eq(se("Skytravel four two one, Prague Radar, identified, climb flight level one three zero"), "ALT TVS421 FL130")
  check_eq(se("Air Serbia three five four, Beograd Control, radar identified, descend FL190"), "ALT ASL354 FL190")
  -- an instruction taken back by a self-correction before the same instruction again: the second counts,
  -- the first one's place is accounted for; before another instruction, the place is still asked about
  check(see:exec("DEFWPT ROMBA 45.0 20.5"))
  check(see:exec("DEFWPT TISAK 45.2 20.7"))
  local function sw(text)
    return said(graph.translate(text, { sim = see, mode = "offline", waypoints = { "ROMBA", "TISAK" } }))
  end
  check_eq(sw("Air Serbia 354 add ROMBA and then... no, add TISAK to your route"), "ADDWPT ASL354 TISAK")
  check_eq(sw("Air Serbia 354 add ROMBA ... sorry, add TISAK to the route"), "ADDWPT ASL354 TISAK")
  check_eq(sw("Air Serbia 354 add ROMBA, no, climb FL250"), "ASK I have ALT ASL354 FL250. What does 'ROMBA' mean?")
  -- "when level" (and "once level", "when you are level") at a level is the condition, as "when reaching"
  check_eq(se("Air Serbia three five four when level flight level two three zero, speed Mach seven six"),
    "ATALT ASL354 FL230 SPD ASL354 M0.76")
  check_eq(se("Air Serbia 354, when you are level FL230 reduce speed 250"), "ATALT ASL354 FL230 SPD ASL354 250")
  check_eq(se("Air Serbia 354 once level FL230 turn right heading 200"), "ATALT ASL354 FL230 HDG ASL354 200 RIGHT")
  check_eq(se("Air Serbia 354 flight level 230 speed 250"), "ALT ASL354 FL230 ; SPD ASL354 250")
end

-- R19's class: a US registration said after its aircraft's type or maker instead of "November" (FAA
-- phraseology), anywhere in the request, is that aircraft only when the digits and letters are exactly
-- its id; a near one is asked about
do
  local ga, g = scene({ "CRE N4417P PA28 47.7 -122.2 180 4500 110", "CRE N62TX C182 47.5 -122.0 090 5500 120",
      "CRE ASA331 B739 46.6 -122.6 350 FL200 290" })
  check_eq(g("Please delete Cherokee four four one seven papa"), "DEL N4417P")
  check_eq(g("turn Skylane six two tango x-ray left heading 270"), "HDG N62TX 270 LEFT")
  check_eq(g("Skylane six two tango x-ray, climb 7500"), "ALT N62TX 7500")
  check(g("remove Cherokee four four one eight papa"):find("^ASK") ~= nil, g("remove Cherokee four four one eight papa"))
end

-- R16's class: a step of a size said in everyday words is a change from the present level: "drop 4000
-- feet", "another thousand feet", "a further 500 ft"; "drop to 4000 feet" is the level
do
  local st = squawk.sim.new()
  check(st:exec("CRE OAL240 A320 38 23.5 090 FL280 280"))
  check(st:exec("CRE N52RG C172 38.2 23.7 090 3500 100"))
  local _, s = set_up(st, {})
  check_eq(s("could you get the Olympic to drop 4000 feet please"), "ALT OAL240 24000")
  check_eq(s("OAL240 drop to 4000 feet"), "ALT OAL240 4000")
  check_eq(s("N52RG go up another thousand feet"), "ALT N52RG 4500")
  check_eq(s("N52RG descend another five hundred feet"), "ALT N52RG 3000")
  check_eq(s("N52RG climb a further 1000 feet"), "ALT N52RG 4500")
  -- each aircraft with its own value after "at", no instruction word: each its own
  check_eq(s("could we have the Olympic at FL 300, please, and N52RG at FL 100?"),
    "ALT OAL240 FL300 ; ALT N52RG FL100")
  check_eq(s("OAL240 at FL300, N52RG at 90 knots"), "ALT OAL240 FL300 ; SPD N52RG 90")
  -- the experiment a request is made for frames it and instructs nothing
  check_eq(s("for this trial I'd like the Olympic to turn right heading 120"), "HDG OAL240 120 RIGHT")
  check_eq(s("the participant needs the Olympic at FL 260 please"), "ALT OAL240 FL260")
  check_eq(s("OAL240 climb FL300 gently"), "ASK I have ALT OAL240 FL300. What does 'gently' mean?")
end

-- R30's classes (Gulf and Asian radiotelephony): a level instruction said before a crossing restriction
-- runs with it, never dropped for it; a garbled airline word before more digits than an aircraft's
-- flight number is asked about, never matched to the shorter number
do
  local asia, at = scene({ "CRE UAE512 B77W 25.3 55.6 090 FL200 300", "DEFWPT DESDI 25.5 56.0", "ADDWPT UAE512 DESDI",
      "CRE GIA412 B738 -4.90 106.80 190 FL170 280", "CRE QFA41 A333 -7.80 107.80 320 FL230 300" })
  -- (a bound is no exact constraint: asked first, the yes runs the instruction and the exact constraint)
  local bounded = graph.translate("Emirates five one two, descend to flight level one two zero, cross DESDI at or below "
    .. "flight level one five zero", { sim = asia, mode = "offline" })
  check_eq(table.concat(bounded.confirm.commands, " ; "), "ALT UAE512 FL120 ; AT UAE512 DESDI ALT FL150")
  check_eq(at("UAE512 descend FL120 and cross DESDI at 250 knots"), "ALT UAE512 FL120 ; AT UAE512 DESDI SPD 250")
  check(at("UAE512 cross DESDI at or below FL150"):find("^ASK squawk can set only an exact constraint at DESDI") ~= nil)
  check_eq(at("Kanuda four one two maintain flight level one seven zero"), "ASK Did you mean QFA41? I heard KANUDA412.")
  check_eq(at("Indonesia four one two maintain flight level one seven zero"), "ALT GIA412 FL170")
end

-- Creating aircraft the way experimenters say it (round 29's classes, sentences written here): a
-- degrees-and-minutes position with its hemisphere anywhere, an impossible one asked about; values said
-- before the callsign; the type before the callsign; a designator's digits after an airline; a label
-- sentence or the aircraft an intruder is for before a colon; CRE's order typed bare
do
  local lab, cr = scene({ "CRE KLM1234 B738 52.2 4.2 300 FL250 280", "CRE DLH4AX A321 52.4 4.4 090 FL300 280",
      "CRE KLM77 B738 52.1 4.5 180 FL150 250" })
  -- minutes of 60 or more, or degrees beyond a pole or the antimeridian: asked, never re-read
  check_eq(cr("create AB1 A320 at N55 75 W003 20 heading 090 FL200 250"),
    "ASK 'N55 75 W003 20' is no position: minutes run from 0 to 59. Which latitude and longitude do you mean?")
  check(cr("spawn XY12 B738 at 52 80N 004 10E, heading 180, FL100, 250 kt"):find("^ASK '52 80N' is no position") ~= nil)
  check(cr("create XY12 B738 at 51 degrees 65 minutes north 3 degrees 10 minutes east heading 090")
    :find("^ASK '51 degrees 65 minutes north' is no position") ~= nil)
  check(cr("create XY12 B738 at 95 N 4 E heading 090 FL100 250"):find("^ASK '95 N' is no latitude") ~= nil)
  check(cr("create XY12 B738 at 52 N 200 E heading 090 FL100 250"):find("^ASK '200 E' is no longitude") ~= nil)
  -- the same forms with minutes that exist: signed decimal degrees
  check_eq(cr("create XY12 B738 at 52 30N 004 45E heading 090 FL100 250"), "CRE XY12 B738 52.5 4.75 90 FL100 250")
  check_eq(cr("put XY12, a B738, at 48 degrees 30 north 2 degrees 15 west, heading 270, FL120, 250 knots"),
    "CRE XY12 B738 48.5 -2.25 270 FL120 250")
  check_eq(cr("cre XY12 B738 52 15N 004 30W 270 12000 250"), "CRE XY12 B738 52.25 -4.5 270 12000 250")
  -- values before the creation, for no aircraft named, are the new aircraft's; a verb before them is not
  check_eq(cr("FL 250, 280 knots, heading 180 - create XY12, A320, at 52 N 4 E"), "CRE XY12 A320 52 4 180 FL250 280")
  check_eq(cr("Speed 250, FL100, heading 090: spawn XY13 B738 at 52.5 4.5"), "CRE XY13 B738 52.5 4.5 90 FL100 250")
  check(cr("climb to FL300 and create XY13 B738 at 52.5 4.5 heading 090 FL100 250"):find("^ASK") ~= nil)
  -- the type first, or an airline and a designator's digits after an article, then the callsign
  check_eq(cr("A320 XY14 at 52.1 4.1 heading 090 FL100 250"), "CRE XY14 A320 52.1 4.1 90 FL100 250")
  check_eq(cr("create a Ryanair 319, RYR1AB, at 52 4 heading 090 FL100 250"), "CRE RYR1AB A319 52 4 90 FL100 250")
  check_eq(cr("create a Norwegian 737-800, NAX55, at 60 10 heading 090 FL200 280"), "CRE NAX55 B738 60 10 90 FL200 280")
  -- a sentence or label before it that names no value ("one" is the aircraft) and no other aircraft
  check_eq(cr("Now the second aircraft. XY15 A320 at 52.3 4.3 heading 180 FL200 280"),
    "CRE XY15 A320 52.3 4.3 180 FL200 280")
  check_eq(cr("a fast one: XY16 B738 at 52.4 4.4 heading 090 FL300 300 kt"), "CRE XY16 B738 52.4 4.4 90 FL300 300")
  check_eq(cr("an intruder for KLM77: XY22 A320 at 52.3 4.6 heading 270 FL150"), "CRE XY22 A320 52.3 4.6 270 FL150")
  check_eq(cr("Set up a head-on for DLH4AX: create XY23 A321 at 52.4 4.9 heading 270 FL300 280"),
    "CRE XY23 A321 52.4 4.9 270 FL300 280")
  check_eq(cr("To set up an overtake: KLM77 reduce speed 220"), "SPD KLM77 220")
  check_eq(cr("create XY33 C172 at 52 4 heading due west at 3000 ft, 100 knots"), "CRE XY33 C172 52 4 270 3000 100")
  -- CRECONFS typed with its argument names; random traffic "for extra load" loads no file
  check_eq(cr("creconfs XY20 A320 KLM77 dpsi 90 cpa 0.5 tlos 300"), "CRECONFS XY20 A320 KLM77 90 0.5 300")
  check_eq(cr("spawn 10 random aircraft for extra load"), "MCRE 10")
  local nav, nt = navscene({ "CRE KLM1234 B738 52.2 4.2 300 FL250 280" }, "creations at navdata places")
  if nav then
    -- the destination and the route said after the creation
    check_eq(nt("create XY30 A320 at SPY heading 090 FL100 250, going to Schiphol"),
      "CRE XY30 A320 SPY 90 FL100 250 ; DEST XY30 EHAM")
    check_eq(nt("create XY30 A320 at SPY heading 090 FL100 250, bound for EDDF"),
      "CRE XY30 A320 SPY 90 FL100 250 ; DEST XY30 EDDF")
    check_eq(nt("create XY31 A320 at SPY heading 090 FL100 250, routing PAM then EEL"),
      "CRE XY31 A320 SPY 90 FL100 250 ; ADDWPT XY31 PAM ; ADDWPT XY31 EEL")
    check_eq(nt("create XY31 A320 at SPY heading 090 FL100 250, route PAM, dest EHAM"),
      "CRE XY31 A320 SPY 90 FL100 250 ; ADDWPT XY31 PAM ; DEST XY31 EHAM")
    check_eq(nt("create XY31 A320 at SPY heading 090 FL100 250, then give it PAM at FL80"),
      "CRE XY31 A320 SPY 90 FL100 250 ; ADDWPT XY31 PAM FL80")
    -- created at a fix with no verb, the fix typed in lower case in CRE's place
    check_eq(nt("a Ryanair 738, RYR9XY, at PAM heading 225 FL 110 250 knots"), "CRE RYR9XY B738 PAM 225 FL110 250")
    check_eq(nt("XY40 A320 at SPY heading 270 FL200 280kt, and XY41 A320 at PAM heading 090 FL200 280kt"),
      "CRE XY40 A320 SPY 270 FL200 280 ; CRE XY41 A320 PAM 90 FL200 280")
    check_eq(nt("cre xy32 a320 spy hdg 90 fl100 250kt"), "CRE XY32 A320 SPY 90 FL100 250")
    -- a navaid said by its name that stands on an airport (Marseille's NDB MJ, 0.2 NM from LFML) is the airport
    check_eq(table.concat(nav:airports_beside("MJ", 43.4, 5.2, 1), " "), "LFML")
    check_eq(#nav:airports_beside("NOSUCH", 43.4, 5.2, 1), 0)
    check(nav:exec("CRE AFR6202 A320 44.7 3.4 165 FL300 280"))
    check_eq(nt("new Air France, AFR7710, A319, at Marseille, heading 270, 5000 feet, 220 knots"),
      "CRE AFR7710 A319 LFML 270 5000 220")
  end
end

-- Experimenters' asides and self-corrections (R29, R25): a remark about the experiment after a dash, in
-- brackets, after a comma with its own subject, a lead-in before a colon or after "reason:" is set
-- aside when it holds no value, place, instruction word, negation or "also"; an aircraft it names is
-- context. A self-correction takes back what it follows: a cut-off instruction, the names said again
-- after "just", the kinds of command "just the ..." does not name; anything else is asked about.
do
  local lab, ex = scene({ "CRE NAX12 B738 60.1 11.0 090 FL120 280", "CRE ICE44 B752 60.3 12.0 270 FL90 290",
      "CRE FIN7 A320 60.0 11.5 180 FL200 300", "DEFWPT OSLOA 60.2 11.2", "DEFWPT OSLOB 60.4 11.4" })
  -- remarks after a dash, in brackets, after a comma
  check_eq(ex("NAX12 descend FL80 - we'd like it under ICE44's band for this run"), "ALT NAX12 FL80")
  check_eq(ex("FIN7 right 40 degrees - stress test of the bank model"), "HDG FIN7 220 RIGHT")
  check_eq(ex("Move FIN7 to 60.05 11.6 - it began slightly too far east"), "MOVE FIN7 60.05 11.6")
  check_eq(ex("vertical half-height 900 ft (sensitivity study for the thesis)"), "ZONEDH 900")
  check_eq(ex("Fast-forward 5 minutes, we only need the cruise part"), "FF 300")
  check_eq(ex("skip ahead 2 minutes so the tracks stabilise"), "FF 120")
  check_eq(ex("Freeze the sim - I need to look at the geometry before the merge"), "HOLD")
  check_eq(ex("hide the trails, too messy"), "TRAIL OFF")
  -- lead-ins before a colon, and a reason given with its label
  check_eq(ex("For the level-bust test: FIN7 descend FL150"), "ALT FIN7 FL150")
  check_eq(ex("To set up a crossing encounter: NAX12 heading 180"), "HDG NAX12 180")
  check_eq(ex("NAX12 - climb to FL140, reason: clear the overlap with ICE44"), "ALT NAX12 FL140")
  check_eq(ex("Add an intruder for ICE44: TST9 A320 at 60.2 12.4 heading 090 FL90 280 kts"),
    "CRE TST9 A320 60.2 12.4 90 FL90 280")
  -- an aside that adds, negates or names a value, a place or another instruction is asked about
  -- (another aircraft with "as well" or "same for" gets the instruction too: G:same_for)
  check_eq(ex("NAX12 climb FL200 - ICE44 as well"), "ALT NAX12 FL200 ; ALT ICE44 FL200")
  check_eq(ex("NAX12 climb FL200, same for ICE44"), "ALT NAX12 FL200 ; ALT ICE44 FL200")
  asked(ex("NAX12 climb FL200 - and ICE44 descend"), "NAX12 climb FL200 - and ICE44 descend")
  asked(ex("NAX12 climb FL200 (not ICE44)"), "NAX12 climb FL200 (not ICE44)")
  asked(ex("NAX12 climb FL200 - don't let it level off"), "NAX12 climb FL200 - don't let it level off")
  asked(ex("NAX12 climb FL200 (via OSLOA)"), "NAX12 climb FL200 (via OSLOA)")
  asked(ex("NAX12 climb FL200 - when ICE44 passes"), "NAX12 climb FL200 - when ICE44 passes")
  asked(ex("reason: ICE44, NAX12 descend FL100"), "reason: ICE44, NAX12 descend FL100")
  asked(ex("NAX12 climb FL200 - we want ICE44 lower"), "NAX12 climb FL200 - we want ICE44 lower")
  asked(ex("NAX12 climb FL200, we want ICE44 down"), "NAX12 climb FL200, we want ICE44 down")
  asked(ex("NAX12 climb FL200 - hold ICE44"), "NAX12 climb FL200 - hold ICE44")
  -- self-corrections
  check_eq(ex("FIN7 direct... no wait, heading 200 for now, we'll send it back to the route later"), "HDG FIN7 200")
  check_eq(ex("NAX12 direct... sorry, turn left heading 010 and climb FL150"), "HDG NAX12 10 LEFT ; ALT NAX12 FL150")
  check_eq(ex("NAX12 route: OSLOA, then OSLOB... no wait, only OSLOA at FL130"), "ADDWPT NAX12 OSLOA FL130")
  check_eq(ex("FIN7 descend FL150 and turn right heading 250... actually no, just the descent"), "ALT FIN7 FL150")
  check_eq(ex("FIN7 descend FL150 and turn right heading 250, sorry, only the turn"), "HDG FIN7 250 RIGHT")
  check_eq(ex("FIN7 descend FL150 and direct... no, just the descent"), "ALT FIN7 FL150")
  asked(ex("FIN7 descend FL150 and turn right heading 250... actually no, just the first one"), "FIN7 descend FL150 and turn right heading 250... actually no, just the first one")
  asked(ex("FIN7 descend FL150 and turn right heading 250, sorry, only the speed"), "FIN7 descend FL150 and turn right heading 250, sorry, only the speed")
  check_eq(ex("FIN7 turn left... I mean right heading 250"), "HDG FIN7 250 RIGHT")
  check_eq(ex("NAX12 direct OSLOA... no, make it heading 030"), "HDG NAX12 30")
  check_eq(ex("NAX12 climb FL150, no wait, descend FL100"), "ALT NAX12 FL100")
  check_eq(ex("NAX12 climb FL150, sorry, and turn left heading 030"), "ALT NAX12 FL150 ; HDG NAX12 30 LEFT")
  check_eq(ex("For the overtake case, FIN7 speed 320"), "SPD FIN7 320")
  -- "for" an aircraft opening the request, then another named: only the other is instructed
  check_eq(ex("For ICE44, NAX12 speed 320"), "SPD NAX12 320")
  check_eq(ex("for spacing on ICE44, FIN7 reduce 250"), "SPD FIN7 250")
  check_eq(ex("for ICE44, climb FL300"), "ALT ICE44 FL300")
  check_eq(ex("ICE44, NAX12 speed 320"), "SPD ICE44 320 ; SPD NAX12 320")
  -- a remark that wants something "to" be done by an aircraft or an airline is asked about
  asked(ex("NAX12 climb FL190, we want the Icelandair to descend"), "NAX12 climb FL190, we want the Icelandair to descend")
  asked(ex("NAX12 climb FL190, I need ICE44 to turn"), "NAX12 climb FL190, I need ICE44 to turn")
  asked(ex("NAX12 climb FL190, we want Finnair to slow down"), "NAX12 climb FL190, we want Finnair to slow down")
  asked(ex("NAX12 climb FL190, we want Finnair lower"), "NAX12 climb FL190, we want Finnair lower")
  check_eq(ex("NAX12 climb FL190, I want the Icelandair to catch him"), "ALT NAX12 FL190")
  -- a type said again after a correction replaces it
  check_eq(ex("create TST1 B738... sorry A320, at 60.2 11.6 heading 200 FL100 250 kts"),
    "CRE TST1 A320 60.2 11.6 200 FL100 250")
  check_eq(ex("create TST1 type A320, I mean B752, at 60.2 11.6 heading 200 FL100 250 kts"),
    "CRE TST1 B752 60.2 11.6 200 FL100 250")
  -- a climb or descent after a creation's level with no level of its own is not dropped
  asked(ex("create TST1 A320 at 60.2 11.6 heading 200 FL100 250 kts going to climb"), "create TST1 A320 at 60.2 11.6 heading 200 FL100 250 kts going to climb")
  asked(ex("create TST1 A320 at 60.2 11.6 heading 200 FL100 250 kts, will descend"), "create TST1 A320 at 60.2 11.6 heading 200 FL100 250 kts, will descend")
  check_eq(ex("create TST1 A320 at 60.2 11.6 heading 200 FL100 250 kts then climb FL200"),
    "CRE TST1 A320 60.2 11.6 200 FL100 250 ; ALT TST1 FL200")
end
-- telephony: "Alpine" is easyJet Europe (EJU), "Topswiss" easyJet Switzerland (EZS); "Lauda" names both
-- Lauda Air (LDA) and Lauda Motion (LDM), so a callsign said with it is the one of them whose characters fit
do
  local lab, ex = scene({ "CRE EJU74QP A320 47.6 12.8 300 FL200 270", "CRE EZS12 A320 47.8 12.8 300 FL220 270",
      "CRE LDM82Y A320 47.3 16.0 020 FL200 280" })
  check_eq(ex("Alpine seven four quebec papa turn left heading 270"), "HDG EJU74QP 270 LEFT")
  check_eq(ex("Topswiss one two descend FL150"), "ALT EZS12 FL150")
  check_eq(ex("Lauda 82Y reduce 230"), "SPD LDM82Y 230")
  check(ex("Lauda eight three yankee descend FL100"):find("^ASK") ~= nil)
  -- a word naming a place's role before "point" or "fix" and the place's name
  check(lab:exec("DEFWPT MRG01 47.5 13.0"))
  check(lab:exec("ADDWPT EJU74QP MRG01"))
  check_eq(ex("EJU74QP direct to the merge point MRG01"), "DIRECT EJU74QP MRG01")
  check_eq(ex("EJU74QP proceed to the metering fix MRG01"), "DIRECT EJU74QP MRG01")
end
-- a name an airport and a navaid near the aircraft both bear, in a direct-to: the one its route holds,
-- else asked about; "Virgin" names Virgin Atlantic (VIR) and Virgin Australia (VOZ): a callsign said with
-- it is the one flying, a new one takes the airline of the one flying, else is asked about
do
  local nav, ex = navscene({ "CRE QFA520 B738 -27.9 152.4 050 FL160 280", "ADDWPT QFA520 BN",
        "CRE VOZ817 B738 -34.4 150.5 040 FL240 300", "ADDWPT VOZ817 YSSY", "CRE RXA64 SF34 -37.4 144.0 100 FL170 240" }, "city names in a direct-to")
  if nav then
    check_eq(ex("Qantas 520 track direct Brisbane"), "DIRECT QFA520 BN")
    check_eq(ex("Qantas 520, proceed direct to Brisbane, descend FL120"), "DIRECT QFA520 BN ; ALT QFA520 FL120")
    check_eq(ex("Virgin 817 cleared direct Sydney"), "DIRECT VOZ817 YSSY")
    check(ex("Rex 64 direct Melbourne"):find("^ASK Which place is meant: the ML navaid or the YMML airport") ~= nil)
    -- a navaid's kind typed in capitals after the name is no waypoint of its own
    check_eq(ex("Qantas 520, track direct to the Brisbane VOR"), "DIRECT QFA520 BN")
    check_eq(ex("Rex 64 direct Melbourne VOR"), "ADDWPT RXA64 ML ; DIRECT RXA64 ML")
    check_eq(ex("Virgin eight one seven climb flight level three one zero"), "ALT VOZ817 FL310")
    -- greetings of the region carry nothing
    check_eq(ex("Qantas 520, kia ora, climb flight level two four zero"), "ALT QFA520 FL240")
    check_eq(ex("G'day mate, Virgin 817 reduce speed two eight zero"), "SPD VOZ817 280")
    check_eq(ex("Rex 64 howzit, turn left heading 090"), "HDG RXA64 90 LEFT")
    check_eq(ex("create Virgin 1219 a B738 at -37.5 145.2 heading 330 FL110 250 knots"),
      "CRE VOZ1219 B738 -37.5 145.2 330 FL110 250")
    local empty = squawk.sim.new()
    check(said(graph.translate("new aircraft Virgin 44, A333, at 51.2 -0.5, heading 270, FL200, 280 knots",
      { sim = empty, mode = "offline" })):find("^ASK Which airline is the new Virgin 44 of: VIR or VOZ") ~= nil)
  end
end

-- a North American study (R33): a rate's sign is the motion it names; flight rules carry no altitude; a bare
-- altitude after "at" constrains an added waypoint; a written designator beats a spoken family name; a
-- creation's fields after a comma stay its own; "back to real time rate" sets the rate, no start
do
  local lab, ex = scene({ "CRE DAL889 B738 42.0 -88.0 090 FL200 280", "CRE N731RS C172 42.2 -88.2 180 3000 100",
      "DEFWPT LANDR 42.3 -87.5" })
  check_eq(ex("Delta 889 increase your rate of descent to two thousand five hundred"), "VS DAL889 -2500")
  check_eq(ex("DAL889 reduce your rate of climb to 500 fpm"), "VS DAL889 500")
  check_eq(ex("DAL889 reduce rate of descent to 1000 feet per minute"), "VS DAL889 -1000")
  asked(ex("N731RS maintain VFR at or below 4500"), "N731RS maintain VFR at or below 4500")
  asked(ex("N731RS maintain VFR on top"), "N731RS maintain VFR on top")
  check_eq(ex("add LANDR to Delta 889's route at 15000 and 250 knots"), "ADDWPT DAL889 LANDR 15000 250")
  check_eq(ex("DAL889 add LANDR to the route at 12000"), "ADDWPT DAL889 LANDR 12000")
  check_eq(ex("need a United triple seven, UAL9, B77W, FL260, 310 knots, heading 265, 41.98 -87.4"),
    "CRE UAL9 B77W 41.98 -87.4 265 FL260 310")
  check_eq(ex("create a Delta Airbus, DAL7, A321, at 41.9 -87.9 heading 090 FL200 280 knots"),
    "CRE DAL7 A321 41.9 -87.9 90 FL200 280")
  check_eq(ex("cre UAL1542 A320 at 42.05 -89.2, hdg 095 alt FL200 spd 280"), "CRE UAL1542 A320 42.05 -89.2 95 FL200 280")
  check_eq(ex("create UAL15 A320 at 42.05 -89.2, heading 095, altitude FL200, speed 280"),
    "CRE UAL15 A320 42.05 -89.2 95 FL200 280")
  check_eq(ex("cre KL1 B738 42 -88 90 FL200 250, alt KL1 FL300"), "CRE KL1 B738 42 -88 90 FL200 250 ; ALT KL1 FL300")
  -- a creation's one bare number of whole hundreds (1000 to 60000), no altitude said, is its altitude
  check_eq(ex("Porter 345, Q400, DH8D, at 43.55 -79.2, 6000, heading two six zero, two ten knots"),
    "CRE POE345 DH8D 43.55 -79.2 260 6000 210")
  check_eq(ex("create FFT221 A320 at 42.1 -88.1 heading 350, give him 8000 and 220 knots"),
    "CRE FFT221 A320 42.1 -88.1 350 8000 220")
  asked(ex("create FFT222 A320 at 42.1 -88.1 heading 350, 8000, 9000, 220 knots"), "create FFT222 A320 at 42.1 -88.1 heading 350, 8000, 9000, 220 knots")
  check_eq(ex("creating Westjet 611, B737, 43.75 -80.20, heading 100, FL140, 270"), "CRE WJA611 B737 43.75 -80.2 100 FL140 270")
  check_eq(ex("now spawning SWA12, B737, 42.5 -88.5, heading 180, FL200, 280 knots"), "CRE SWA12 B737 42.5 -88.5 180 FL200 280")
  check_eq(ex("set the seed to 7 before creating anything"), "SEED 7")
  -- the people in the room, addressed, carry nothing
  check_eq(ex("ok observers, I'm going to start the clock now"), "OP")
  check_eq(ex("alright folks, DAL889 climb FL240"), "ALT DAL889 FL240")
  check_eq(ex("back to real time rate please, multiplier 1"), "DTMULT 1")
  check_eq(ex("ok, back to real time rate"), "DTMULT 1")
end
-- North Atlantic oceanic R/T (R35): the caller's own station in the addressing position carries nothing;
-- "unable" takes its value back; "report level" and "advise when able to resume" ask for a report; a
-- flight number typed digit by digit; a rate glued to its unit; a compass point agreeing with the heading
do
  local lab, ex = scene({ "CRE EIN105 A332 53.0 -13.0 270 FL360 M.82", "CRE TAP237 A21N 38.0 -25.0 240 FL360 M.79",
      "CRE WJA3 B38M 55.8 -7.0 280 FL340 300" })
  check_eq(ex("Shamrock one zero five, Shanwick, climb flight level three eight zero"), "ALT EIN105 FL380")
  check_eq(ex("WestJet 3, Scottish Control, turn right heading 310"), "HDG WJA3 310 RIGHT")
  -- (a unit word that is an instruction word elsewhere names the unit: no POS for "Information")
  check_eq(ex("WestJet 3, Scottish Information, climb FL360"), "ALT WJA3 FL360")
  check_eq(ex("Santa Maria, Air Portugal 237, descend FL340"), "ALT TAP237 FL340")
  check_eq(ex("shamrock one zero five, shanwick, descend flight level three four zero"), "ALT EIN105 FL340")
  check_eq(ex("Air Portugal 237, Gander Oceanic, Mach decimal eight zero"), "SPD TAP237 M0.8")
  check_eq(ex("Air Portugal 237, Santa Maria Radio, position report received, climb FL380"), "ALT TAP237 FL380")
  check_eq(ex("create TAP9 A339 at 38N020W heading 240 FL360 Mach .80"), "CRE TAP9 A339 38 -20 240 FL360 M0.8")
  -- the station straight after the callsign, before its comma; a city by its English name (Delhi,
  -- Dar es Salaam) names its unit as the navdata's airport names it
  check_eq(ex("WestJet 3 Scottish Control, turn right heading 310"), "HDG WJA3 310 RIGHT")
  check_eq(ex("Air Portugal 237 Santa Maria, descend FL340"), "ALT TAP237 FL340")
  check_eq(ex("Delhi, WestJet 3, climb FL360"), "ALT WJA3 FL360")
  check_eq(ex("Shamrock 105 Dar es Salaam control, climb FL380"), "ALT EIN105 FL380")
  asked(ex("Shamrock 105 Ryanair, climb FL380"), "Shamrock 105 Ryanair, climb FL380")
  -- a place word anywhere else is still asked about
  asked(ex("Shamrock 105 climb FL380 Shanwick"), "Shamrock 105 climb FL380 Shanwick")
  asked(ex("Shamrock 105, Shanwick climb FL380"), "Shamrock 105, Shanwick climb FL380")
  check_eq(ex("Shamrock 105, unable FL380, maintain flight level three six zero"), "ALT EIN105 FL360")
  asked(ex("Shamrock 105 unable FL380"), "Shamrock 105 unable FL380")
  asked(ex("Shamrock 105, if unable FL380, maintain FL360"), "Shamrock 105, if unable FL380, maintain FL360")
  -- a position no command carries is asked about, also beside a relative word or "by"
  asked(ex("Shamrock 105, climb FL380, cross 30 West at or above FL370"), "Shamrock 105, climb FL380, cross 30 West at or above FL370")
  asked(ex("Shamrock 105, climb to reach FL380 by 20 West"), "Shamrock 105, climb to reach FL380 by 20 West")
  check_eq(ex("Shamrock 105 unable direct MALOT, turn left heading 250"), "HDG EIN105 250 LEFT")
  check_eq(ex("WJA3 climb to FL360, not above"), "ALT WJA3 FL360")
  asked(ex("WJA3 climb FL380, not above FL370"), "WJA3 climb FL380, not above FL370")
  check_eq(ex("Air Portugal 237, Mach decimal seven eight approved"), "SPD TAP237 M0.78")
  check_eq(ex("Shamrock one zero five, report level"), "POS EIN105")
  check_eq(ex("EIN105 report your level"), "POS EIN105")
  check_eq(ex("WJA3 turn left 30 degrees for weather, advise when able to resume"), "HDG WJA3 250 LEFT")
  check_eq(ex("WJA3 climb FL380 at 1500ft/min"), "ALT WJA3 FL380 1500")
  check_eq(ex("create Shamrock 1 2 3, A333, at 52 North 15 West, heading 270, FL370, Mach .82"),
    "CRE EIN123 A333 52 -15 270 FL370 M0.82")
  check_eq(ex("add an eastbound, EIN77, A333, at 52 North 30 West, heading 080, FL350"),
    "CRE EIN77 A333 52 -30 80 FL350")
  asked(ex("add a westbound, EIN77, A333, at 52 North 30 West, heading 080, FL350"), "add a westbound, EIN77, A333, at 52 North 30 West, heading 080, FL350")
  check_eq(ex("Shamrock 105, climb FL380, at 20 West contact Shanwick on 127.9"), "ALT EIN105 FL380")
  check_eq(ex("add Shamrock 22 as an A330, same position as Air Portugal 237, FL320, Mach .80, heading 240"),
    "CRE EIN22 A332 TAP237 240 FL320 M0.8")
  check_eq(ex("Shamrock 105 vectors to avoid the danger area, turn left heading 250"), "HDG EIN105 250 LEFT")
  -- what the run should reach, after a clock rate or a jump in time: a remark
  check_eq(ex("run at four times speed until the eastbounds reach the boundary"), "DTMULT 4")
  asked(ex("fast forward until Shamrock 105 reaches the boundary"), "fast forward until Shamrock 105 reaches the boundary")
  asked(ex("fast forward two minutes until not conflicting"), "fast forward two minutes until not conflicting")
end
-- oceanic points said in degrees: the named point the navdata holds there (NAT "55N30"), the one of
-- several the route holds, else asked; raw coordinates where the command takes them; a name several
-- navaids bear, one of them in the route ("Stornoway": STN), is that one; a station the navdata names
do
  local nav, ex = navscene({ "CRE BAW117 B772 55.0 -12.0 270 FL350 M.84", "ADDWPT BAW117 55N20",
        "ADDWPT BAW117 55N30", "CRE ICE455 B38M 57.5 -3.5 310 FL300 290", "ADDWPT ICE455 STN" }, "oceanic points")
  if nav then
    -- sim:waypoints_at: the idents at exactly a position (both of 53N 50W's), none beside it
    check_eq(table.concat(nav:waypoints_at(55, -30), " "), "55N30")
    local two = nav:waypoints_at(53, -50)
    table.sort(two)
    check_eq(table.concat(two, " "), "5350N 53N50")
    check_eq(#nav:waypoints_at(55.01, -30), 0)
    check_eq(ex("Speedbird 117 proceed direct 55 North 30 West"), "DIRECT BAW117 55N30")
    check_eq(ex("BAW117 direct 54 north 40 west"), "ADDWPT BAW117 54N40 ; DIRECT BAW117 54N40")
    check_eq(ex("Speedbird 117, direct 55 30 North 30 West... correction, 55 North 20 West"), "DIRECT BAW117 55N20")
    check(ex("BAW117 direct 53 north 50 west"):find("^ASK Which point at 53 %-50 is meant") ~= nil)
    check(ex("BAW117 direct 55 30 north 40 west"):find("^ASK No named point lies at 55.5 %-40") ~= nil)
    check_eq(ex("Speedbird 117, add 55 North 40 West after 55 North 30 West"), "ADDWPT BAW117 55 -40,,,55N30")
    check_eq(ex("add 56 North 50 West to the end of Speedbird 117's route"), "ADDWPT BAW117 56 -50")
    check_eq(ex("remove 55 North 20 West from Speedbird 117's routing"), "DELWPT BAW117 55N20")
    check_eq(ex("Speedbird 117 delete 55 North 30 West"), "DELWPT BAW117 55N30")
    check_eq(ex("Speedbird 117 proceed direct 55N030W"), "DIRECT BAW117 55N30")
    -- a second position after the point is no part of it: asked about, never dropped
    check(ex("BAW117 direct 55 north 30 west, then 55 north 40 west"):find("^ASK") ~= nil)
    check_eq(ex("Iceair 455, direct Stornoway"), "DIRECT ICE455 STN")
    check_eq(ex("Iceair 455, Dublin, climb FL320"), "ALT ICE455 FL320")
  end
end


-- the experimenter's language (cycle 16): a new aircraft said with no verb, its callsign first ("is a",
-- an article or the designator's digits between it and the type) or after a short lead-in; a callsign
-- said and then written as the same id is one aircraft
do
  local lab, ex = scene({ "CRE DAL889 B738 42.0 -88.0 090 FL200 280", "CRE N731RS C172 42.2 -88.2 180 3000 100" })
  check_eq(ex("Frontier 12 is an A320, 9000 ft, 240 kt, at 42.1N 87.9W heading 180"),
    "CRE FFT12 A320 42.1 -87.9 180 9000 240")
  check_eq(ex("ok now Alaska 33, a B739, 41.7 -87.6, heading 020, FL200 and 290"),
    "CRE ASA33 B739 41.7 -87.6 20 FL200 290")
  check_eq(ex("Delta 41, three two one, A321, at 42.4 north 88.1 west, FL150 heading 090 speed 260"),
    "CRE DAL41 A321 42.4 -88.1 90 FL150 260")
  check_eq(ex("and a little Cessna 152, N52KT, 42.0 -88.3, 3500 ft, heading 270, 95 knots"),
    "CRE N52KT C152 42 -88.3 270 3500 95")
  check_eq(ex("next one is SKW20 E175 at 42.2 -87.8 heading 300, FL110, 250 knots"),
    "CRE SKW20 E75L 42.2 -87.8 300 FL110 250")
  check_eq(ex("could we have an Alaska B738 ASA51 at 41.6 -88.4, FL230 heading 045 at 280 kt"),
    "CRE ASA51 B738 41.6 -88.4 45 FL230 280")
  check_eq(ex("create Delta 77, DAL77, an A320 at 42.3 -87.9, FL180, heading 200, 270 knots"),
    "CRE DAL77 A320 42.3 -87.9 200 FL180 270")
  check_eq(ex("spawn United 5K, that's UAL5K, a B738 at 41.8 -88.0 heading 010 FL160 250 knots"),
    "CRE UAL5K B738 41.8 -88 10 FL160 250")
  -- digits that are no designator's, said after the creation, are asked about
  asked(ex("create UAL455 B739 at 40.5 north 104.1 west, FL190 heading 225 speed 280 739"), "create UAL455 B739 at 40.5 north 104.1 west, FL190 heading 225 speed 280 739")
  -- a lead-in that instructs is no lead-in
  asked(ex("please descend UAL88 B738 at 41.6 -88.4, FL230 heading 045 at 280 kt"), "please descend UAL88 B738 at 41.6 -88.4, FL230 heading 045 at 280 kt")
  -- a remark in a sentence of its own, "one" standing for the aircraft in a remark, the experimenter's own
  -- doing after "then I'll", what a setting is for ("for when we ..."): set aside; one that instructs is asked
  check_eq(ex("create SKW9 E175 at 42.2 -87.8 heading 300 FL110 250 knots. Second arrival of the evening wave."),
    "CRE SKW9 E75L 42.2 -87.8 300 FL110 250")
  check_eq(ex("Warm-up pair first. SKW10 E175 at 42.2 -87.8 heading 300 FL110 250 knots"),
    "CRE SKW10 E75L 42.2 -87.8 300 FL110 250")
  check_eq(ex("cre SKW11 E175 42.2 -87.8 300 FL110 250 - the slow one of the stream"),
    "CRE SKW11 E75L 42.2 -87.8 300 FL110 250")
  check_eq(ex("fast forward 2 minutes then I'll explain the display to the visitors"), "FF 120")
  check_eq(ex("set the sim rate to 3 for when we reconvene"), "DTMULT 3")
  asked(ex("DAL889 climb FL240. Then N731RS."), "DAL889 climb FL240. Then N731RS.")
  check_eq(ex("DAL889 climb FL240. N731RS as well."), "ALT DAL889 FL240 ; ALT N731RS FL240")
  asked(ex("fast forward 2 minutes then I'll climb DAL889"), "fast forward 2 minutes then I'll climb DAL889")
  asked(ex("cre SKW12 E175 42.2 -87.8 300 FL110 250 - the one at FL300"), "cre SKW12 E175 42.2 -87.8 300 FL110 250 - the one at FL300")
  -- a type, maker or family said before the callsign of a flying aircraft of that type describes it
  check_eq(ex("where's the Cessna N731RS now"), "POS N731RS")
  check_eq(ex("delete the Skyhawk N731RS"), "DEL N731RS")
  asked(ex("delete the Baron N731RS"), "delete the Baron N731RS")
  -- requests for information: a flight plan pulled up, "route for X?", an aircraft shown in a clause of its own,
  -- the positions of two aircraft
  check_eq(ex("pull up Delta 889's flight plan"), "LISTRTE DAL889")
  check_eq(ex("bring up DAL889's route please"), "LISTRTE DAL889")
  check_eq(ex("route for Delta 889?"), "LISTRTE DAL889")
  check_eq(ex("freeze, and show me Delta 889"), "HOLD ; POS DAL889")
  check_eq(ex("can you give me DAL889's and N731RS's positions"), "POS DAL889 ; POS N731RS")
  -- a value said again after a self-correction replaces the one before it; "scratch that, just <the
  -- instruction again>" takes back what it follows
  check_eq(ex("Delta 889 slow to 240... no, make it 230"), "SPD DAL889 230")
  check_eq(ex("DAL889 descend to 11 thousand ft, sorry, 12 thousand"), "ALT DAL889 12000")
  check_eq(ex("DAL889 climb FL260 until further advised... scratch that, just climb FL260"), "ALT DAL889 FL260")
  asked(ex("DAL889 turn left heading 200... no, make it 190 and 230 knots"), "DAL889 turn left heading 200... no, make it 190 and 230 knots")
  -- a fix or point said new or named at a position is defined; the plural lists several
  check_eq(ex("new fix MRG2 at 42.5 N 87.9 W"), "DEFWPT MRG2 42.5 -87.9")
  check_eq(ex("we need a reference point named HOLDPT at 42.0N, 88.0W"), "DEFWPT HOLDPT 42 -88")
  check_eq(ex("waypoints: EN1 at 42.1 -88.1 and EN2 at 42.2 -88.2"), "DEFWPT EN1 42.1 -88.1 ; DEFWPT EN2 42.2 -88.2")
  asked(ex("DAL889 fix at 42.5 N 87.9 W"), "DAL889 fix at 42.5 N 87.9 W")
  -- a position written with a slash; a compass point that agrees with the heading said describes it
  check_eq(ex("new ac: SKW14 E175 42.35/-87.95 hdg 050 FL190 spd 275"), "CRE SKW14 E75L 42.35 -87.95 50 FL190 275")
  check_eq(ex("create SKW15 E175 at 42.3 -87.9, northbound, so heading 010, FL150, 260 knots"),
    "CRE SKW15 E75L 42.3 -87.9 10 FL150 260")
  asked(ex("create SKW16 E175 at 42.3 -87.9, southbound, heading 010, FL150, 260 knots"), "create SKW16 E175 at 42.3 -87.9, southbound, heading 010, FL150, 260 knots")
  -- typed turn shorthand before "hdg"; a Pilatus by its name (PCnn -> Pilatus PC-nn)
  check_eq(ex("dal889 lft hdg 100"), "HDG DAL889 100 LEFT")
  check_eq(ex("DAL889 rgt hdg 300"), "HDG DAL889 300 RIGHT")
  check_eq(ex("creating N48PC, Pilatus PC-12, 42.1 -88.1, heading 010, 9500 feet, 190 knots"),
    "CRE N48PC PC12 42.1 -88.1 10 9500 190")
  -- the traffic on the display named as a place ("on the board", "from the scene")
  check_eq(ex("put an Alaska B738 on the board, ASA70, FL150, heading 090, 270 knots, lat 42.1 lon -87.5"),
    "CRE ASA70 B738 42.1 -87.5 90 FL150 270")
  check_eq(ex("take N731RS out of the scene please"), "DEL N731RS")
end

-- a creation at a named place: the place said after "at"/"over" is the position, over one named before it
do
  local lab = scene({ "DEFWPT GATEA 52.1 4.1", "DEFWPT GATEB 52.3 4.4", "CRE KLM12 B738 52 4 90 FL200 250" })
  local function ex(text)
    return said(graph.translate(text, { sim = lab, mode = "offline", waypoints = { "GATEA", "GATEB" } }))
  end
  check_eq(ex("GATEB arrival: create TST7 A320 at GATEA heading 100 FL230 270 kts"):match("^ASK I have CRE TST7 A320 GATEA"),
    "ASK I have CRE TST7 A320 GATEA")
  check_eq(ex("create TST8 A320 over GATEB heading 100 FL230 270 kts"), "CRE TST8 A320 GATEB 100 FL230 270")
end

-- Cycle 16, radiotelephony typed as heard: instructions for several aircraft in one line, each opened by
-- its callsign after a semicolon, full stop, comma or "and", are each aircraft's (never one merged
-- instruction, never a value moved to the other aircraft); "I'm deleting ..." is a deletion said as done
do
  local rt, ex = scene({ "CRE AUA123 A320 48.1 16.5 090 FL200 280", "CRE DLH6CK A320 48.3 16.2 180 FL240 300",
      "CRE UAL1542 B738 47.9 16.8 270 FL180 260" })
  check_eq(ex("AUA123 climb FL250; DLH6CK descend FL200"), "ALT AUA123 FL250 ; ALT DLH6CK FL200")
  check_eq(ex("Austrian 123 descend flight level one five zero. Lufthansa six charlie kilo climb flight level three one zero."),
    "ALT AUA123 FL150 ; ALT DLH6CK FL310")
  check_eq(ex("AUA123 speed 250 knots; DLH6CK speed 260 knots"), "SPD AUA123 250 ; SPD DLH6CK 260")
  check_eq(ex("AUA123 reduce 250 kts; DLH6CK 260 kts"), "SPD AUA123 250 ; SPD DLH6CK 260")
  check_eq(ex("AUA123 left heading 200 and I'm deleting United 1542 now"), "HDG AUA123 200 LEFT ; DEL UAL1542")
  check_eq(ex("removing UAL1542"), "DEL UAL1542")
  check_eq(ex("AUA123 reduce 250 DLH6CK reduce 240"), "SPD AUA123 250 ; SPD DLH6CK 240")
  check_eq(ex("AUA123 left 040 DLH6CK right 250"), "HDG AUA123 40 LEFT ; HDG DLH6CK 250 RIGHT")
  check_eq(ex("AUA123 climb unrestricted FL250"), "ALT AUA123 FL250")
  -- a registration or callsign spelled in the phonetic alphabet with its digits said is that aircraft exactly
  check(rt:exec("CRE HK5012 C208 48.0 16.0 180 13000 150"))
  check_eq(ex("Hotel Kilo five zero one two, turn right heading two two zero"), "HDG HK5012 220 RIGHT")
  check_eq(ex("hotel kilo 5012 descend 9000 feet"), "ALT HK5012 9000")
  check_eq(ex("Delta Lima Hotel six Charlie Kilo descend FL150"), "ALT DLH6CK FL150")
  check(ex("Hotel Kilo five zero one three, turn right heading two two zero"):find("^ASK") ~= nil)
  check(rt:exec("DEL HK5012"))
  -- a callsign taken back ("sorry", "no, I mean", "correction") is never instructed; two said plainly both are
  check_eq(ex("DLH6CK, sorry, AUA123 descend FL150"), "ALT AUA123 FL150")
  check_eq(ex("Lufthansa six charlie kilo, no, I mean Austrian 123, turn left heading 200"), "HDG AUA123 200 LEFT")
  check_eq(ex("DLH6CK oh sorry AUA123 reduce speed 250"), "SPD AUA123 250")
  check_eq(ex("DLH6CK and AUA123 descend FL150"), "ALT DLH6CK FL150 ; ALT AUA123 FL150")
  -- radiotelephony's framing of a clearance carries nothing more: given again ("recleared"), urgent ("without
  -- delay"), in force "till further advised" (and its variants); what a vector is for ("vectors for runway
  -- 28") is named as not simulated beside the heading; a turn side typed without vowels is that side
  check_eq(ex("Austrian 123 recleared flight level 250"), "ALT AUA123 FL250")
  check_eq(ex("AUA123 re-cleared FL250"), "ALT AUA123 FL250")
  check_eq(ex("AUA123 descend flight level 150 without delay"), "ALT AUA123 FL150")
  check_eq(ex("DLH6CK maintain 280 knots or greater till further advised"), "SPD DLH6CK 280")
  check_eq(ex("DLH6CK keep 280 knots until further advise"), "SPD DLH6CK 280")
  local v = graph.translate("AUA123 turn right heading 330, vectors for runway two eight", { sim = rt, mode = "offline" })
  check(said(v) == "HDG AUA123 330 RIGHT" and (v.note or ""):find("approaches to a runway", 1, true) ~= nil, said(v))
  local st = graph.translate("AUA123 turn right heading 190, report steady", { sim = rt, mode = "offline" })
  check(said(st) == "HDG AUA123 190 RIGHT" and (st.note or ""):find("position reports", 1, true) ~= nil, said(st))
  local cr = graph.translate("AUA123 climb FL250, cancel speed restriction", { sim = rt, mode = "offline" })
  check(said(cr) == "ALT AUA123 FL250" and (cr.note or ""):find("restrictions lifted", 1, true) ~= nil, said(cr))
  check_eq(ex("AUA123 turn lft heading 200"), "HDG AUA123 200 LEFT")
  check_eq(ex("dlh6ck hdg 120 rgt"), "HDG DLH6CK 120 RIGHT")
  check(ex("AUA123 vectors heading 200 please, traffic"):find("approaches", 1, true) == nil)
  -- a hand-off said with another verb before a frequency of the air band is named as not simulated
  local h = graph.translate("AUA123 descend FL150, call Vienna on 129.2", { sim = rt, mode = "offline" })
  check(said(h) == "ALT AUA123 FL150" and (h.note or ""):find("radio frequencies", 1, true) ~= nil, said(h))
  check_eq(ex("AUA123 descend FL150 and switch to approach 119.1"), "ALT AUA123 FL150")
  check(ex("AUA123 go to 250"):find("radio", 1, true) == nil)
  -- another aircraft said with "same", "too", "as well" or after "same for" gets the instructions again;
  -- where the request instructed several aircraft, which is asked
  check_eq(ex("AUA123 reduce speed 250, DLH6CK the same"), "SPD AUA123 250 ; SPD DLH6CK 250")
  check_eq(ex("AUA123 descend FL150 and reduce 250, same for Lufthansa six charlie kilo"),
    "ALT AUA123 FL150 ; SPD AUA123 250 ; ALT DLH6CK FL150 ; SPD DLH6CK 250")
  check_eq(ex("AUA123 turn left heading 200, DLH6CK too"), "HDG AUA123 200 LEFT ; HDG DLH6CK 200 LEFT")
  check(ex("AUA123 FL150, DLH6CK FL160, UAL1542 same"):find("^ASK Which instruction should UAL1542") ~= nil)
  check_eq(ex("AUA123 climb FL300, the same level as DLH6CK"), "ALT AUA123 FL300")
  -- the same aircraft said again is one instruction; a callsign straight after a value, with no instruction
  -- word after it, is still asked about
  check_eq(ex("AUA123 climb, AUA123 climb FL250"), "ALT AUA123 FL250")
  check_eq(ex("AUA123 speed 250 kts DLH6CK speed 260 kts"), "SPD AUA123 250 ; SPD DLH6CK 260")
  check(ex("AUA123 turn right heading 160 DLH6CK 2"):find("^ASK") ~= nil)
end

-- an airport said by a distinctive part of its navdata name is the one airport near the aircraft whose name
-- holds it ("Midway": CHICAGO MIDWAY INTL, "Kennedy": JOHN F KENNEDY INTL, "Love Field": DALLAS LOVE FLD);
-- several are named in the question; none there (or a name that only says what kind of field) is asked about
do
  local us = squawk.sim.new()
  if #us:airports_with_words("midway") >= 1 then
    for _, line in ipairs({ "CRE ENY3410 E145 41.9 -87.9 090 9000 250", "CRE JBU615 A320 40.5 -73.5 090 9000 250",
        "CRE SWA22 B737 32.5 -97.0 090 9000 250" }) do
      check(us:exec(line))
    end
    local _, ex = set_up(us, {})
    check_eq(ex("destination for Envoy 3410 is Midway"), "DEST ENY3410 KMDW")
    check_eq(ex("jetblue six fifteen change destination to kennedy"), "DEST JBU615 KJFK")
    check_eq(ex("JBU615 destination la guardia"), "DEST JBU615 KLGA")
    check_eq(ex("Southwest 22 is going to Love Field"), "DEST SWA22 KDAL")
    check(ex("ENY3410 destination Love Field"):find("^ASK") ~= nil)  -- Dallas is far from Chicago
    check(ex("ENY3410 destination international"):find("^ASK") ~= nil)
    check(ex("ENY3410 destination Ohare Midway"):find("^ASK") ~= nil)
    check_eq(#us:airports_with_words("county regional"), 0)
  else
    print("skipped: airports by a part of their name need navdata (SQUAWK_NAVDATA)")
  end
end

-- Everyday words of visiting researchers (R36): "to" makes a heading of a turn's degrees; a fix said as what
-- a new waypoint is; the clock run fast or back at normal speed; a waypoint flown to "directly"; a
-- self-correction followed by "just" and another instruction; a level said as a condition after the
-- instruction; greetings in German and the study told as a story; "the British one"; places flown over
-- that the request asks to add; a heading towards a place
do
  local lab = scene({ "CRE DLH5TX A320 48.4 11.2 090 FL240 280", "CRE BAW77 A320 48.6 10.0 100 FL300 280",
      "CRE EZY9 A319 48.1 12.0 270 FL220 260", "DEFWPT TESTA 48.3 11.9", "DEFWPT TESTB 48.0 12.3" })
  local function ex(text) return said(graph.translate(text, { sim = lab, mode = "offline", waypoints = { "TESTA", "TESTB" } })) end
  check_eq(ex("could the Lufthansa please turn left to 200 degrees"), "HDG DLH5TX 200 LEFT")
  check_eq(ex("the easyJet should descend to FL200 and turn right to 030 degrees"), "ALT EZY9 FL200 ; HDG EZY9 30 RIGHT")
  check_eq(ex("please define a waypoint GATE2 at 47.9 N 12.1 E, which is a fix"), "DEFWPT GATE2 47.9 12.1 FIX")
  check_eq(ex("please run the simulation fast until I tell you to stop"), "FF")
  check_eq(ex("run the sim fast for five minutes"), "FF 300")
  check_eq(ex("switch the simulation back to normal speed, real time please"), "DTMULT 1")
  check_eq(ex("the Lufthansa should fly to TESTA directly"), "ADDWPT DLH5TX TESTA ; DIRECT DLH5TX TESTA")
  check_eq(ex("the Lufthansa should fly to our waypoint TESTB"), "ADDWPT DLH5TX TESTB ; DIRECT DLH5TX TESTB")
  check_eq(ex("the easyJet should climb to FL260 and then go directly to TESTB? Sorry, I mean just turn to heading 300."),
    "ALT EZY9 FL260 ; HDG EZY9 300")
  check_eq(ex("the Lufthansa should slow to 250 knots once it reaches flight level 150"), "ATALT DLH5TX FL150 SPD DLH5TX 250")
  check_eq(ex("turn the easyJet to heading 090, but only when it is at FL210"), "ATALT EZY9 FL210 HDG EZY9 90")
  check_eq(ex("Grüß Gott, could the easyJet climb to flight level 300, bitte?"), "ALT EZY9 FL300")
  check_eq(ex("Entschuldigung, the Lufthansa should go to FL250, danke"), "ALT DLH5TX FL250")
  check_eq(ex("in our story the easyJet is too slow, please give it 290 knots"), "SPD EZY9 290")
  check_eq(ex("please let the British one climb to FL340"), "ALT BAW77 FL340")
  check_eq(ex("for my study the easyJet should fly over TESTA and then over TESTB, please add these to its route"),
    "ADDWPT EZY9 TESTA ; ADDWPT EZY9 TESTB")
  check_eq(ex("please make the Lufthansa fly towards TESTB"), "HDG DLH5TX TESTB")
  check_eq(ex("the easyJet should turn left in the direction of TESTA"), "HDG EZY9 TESTA LEFT")
  -- "fly at" a level is the level flown, no condition on what follows; "fly to heading" no destination
  check_eq(ex("the easyJet should fly at 30000 ft and heading 090"), "ALT EZY9 30000 ; HDG EZY9 90")
  check_eq(ex("please let the Lufthansa fly to heading 045"), "HDG DLH5TX 45")
  check_eq(ex("please create two waypoints: WPA at 48.2 11.1 and WPB at 48.4 11.8"),
    "DEFWPT WPA 48.2 11.1 ; DEFWPT WPB 48.4 11.8")
  check_eq(ex("please create a small Cessna 172, N77AB, at 48.2 11.3 heading 090 at 3000 feet and 100 knots"),
    "CRE N77AB C172 48.2 11.3 90 3000 100")
  check(ex("set the speed of both Lufthansa planes to 240 knots"):find("^ASK Which two aircraft does 'both Lufthansa' mean") ~= nil)
  -- with the navdata: a city English names otherwise than the navdata ("Munich": MUNCHEN; "Vienna": its
  -- airport SCHWECHAT), in every command that takes a place; a name said again is the same place
  if #lab:airports_named("munchen") == 1 then
    check_eq(ex("I would like the easyJet to land in Vienna, please set that as its destination"), "DEST EZY9 LOWW")
    check_eq(ex("please move the Lufthansa to the Munich airport"), "MOVE DLH5TX EDDM")
    check_eq(ex("create DLH8 A320 over Nuremberg airport, FL120, heading 180, 250 knots"), "CRE DLH8 A320 EDDN 180 FL120 250")
    check_eq(ex("the Lufthansa should go to Stuttgart, so Stuttgart is its destination"), "DEST DLH5TX EDDS")
    check_eq(ex("please turn the easyJet towards Munich airport"), "HDG EZY9 EDDM")
    check_eq(ex("the British Airways should fly over the Kempten VOR, KPT, please add it to its route"), "ADDWPT BAW77 KPT")
    check_eq(ex("please make a wind from 250 degrees with 30 knots at Salzburg"), "WIND LOWS 250 30")
    check_eq(ex("what is the wind at Linz airport at flight level 100?"), "GETWIND LOWL FL100")
    check_eq(ex("where is Munich airport?"), "POS EDDM")
    check_eq(ex("when the easyJet is 15 miles from Munich airport, please let it descend to FL120"),
      "ATDIST EZY9 EDDM 15 ALT EZY9 FL120")
    check_eq(ex("please tell me where the Kempten VOR is"), "POS KPT")
  else
    print("skipped: city names of airports need navdata (SQUAWK_NAVDATA)")
  end
end

-- Cycle 17 (terse lowercase shorthand at a simulator's command box): field words typed short make a
-- line English, a bound at a waypoint is confirmed before an exact constraint is set, typed letter
-- swaps, lowercase place names in a place's slot, and a waypoint added with its level and speed
do
  local lab = scene({ "CRE AFR56BQ A320 52.0 4.0 090 FL200 280", "CRE KLM88V E190 51.9 5.6 300 FL140 250",
      "DEFWPT TESTA 52.3 4.5", "ADDWPT KLM88V TESTA" })
  local function tr38(text) return graph.translate(text, { sim = lab, mode = "offline", waypoints = { "TESTA" } }) end
  local function ex(text) return said(tr38(text)) end
  -- "hdg"/"spd" typed among TrafScript's arguments: the English reading, with the field's value
  check_eq(ex("cre ewg12 a320 52.5 4.5 hdg 060"), "CRE EWG12 A320 52.5 4.5 60")
  check_eq(ex("cre ewg13 a320 52.5 4.5 spd 250 hdg 100"):match("^ASK") and "ask" or "issued", "ask")
  -- a bound ("at or above", "or below", "at least") is no exact AT constraint: asked first, the yes sets it
  local r = tr38("klm88v cross testa at or above fl150")
  check(r.ask ~= nil and r.ask:find("exactly FL150", 1, true) ~= nil, said(r))
  check_eq(r.confirm.commands[1], "AT KLM88V TESTA ALT FL150")
  r = tr38("KLM88V cross TESTA at or below FL150")
  check(r.ask ~= nil and r.ask:find("only an exact constraint at TESTA", 1, true) ~= nil, said(r))
  check_eq(r.confirm.commands[1], "AT KLM88V TESTA ALT FL150")
  r = tr38("KLM88V cross TESTA at least 250 knots")
  check(r.ask ~= nil and r.ask:find("exactly 250 knots", 1, true) ~= nil, said(r))
  check_eq(ex("KLM88V cross TESTA at FL150"), "AT KLM88V TESTA ALT FL150")
  -- two letters swapped or the vowels left out before a value
  check_eq(ex("afr56bq hgd 240"), "HDG AFR56BQ 240")
  check_eq(ex("klm88v sdp 230"), "SPD KLM88V 230")
  check_eq(ex("afr56bq rdc 250 kts"), "SPD AFR56BQ 250")
  check_eq(ex("klm88v drct testa"), "DIRECT KLM88V TESTA")
  -- "v/s" for the vertical speed, "clr rte" for clearing the route, written abbreviations of known words
  check_eq(ex("afr56bq v/s 1500 down"), "VS AFR56BQ -1500")
  check_eq(ex("klm88v clr rte"), "DELRTE KLM88V")
  asked(ex("klm88v clr route as filed"))
  check_eq(ex("afr56bq inc spd 300"), "SPD AFR56BQ 300")
  check_eq(ex("afr56bq hdg 200 vect ils"), "HDG AFR56BQ 200")
  check_eq(ex("afr56bq r 20 degs"), "HDG AFR56BQ 110 RIGHT")
  -- "sim x4" is the multiplier; a setting's command name asked about alone shows it
  check_eq(ex("sim x4"), "DTMULT 4")
  check_eq(ex("def wp gate7 at 52.25N 004.10E"), "DEFWPT GATE7 52.25 4.1")
  check_eq(ex("klm88v spd 240 .. corr 230"), "SPD KLM88V 230")
  check_eq(ex("zoner?"), "ZONER")
  check_eq(ex("dt ?"), "DT")
  -- a waypoint added with the level (and a bare speed straight after it); any other value is asked about
  check_eq(ex("afr56bq add testa fl60 210"), "ADDWPT AFR56BQ TESTA FL60 210")
  check_eq(ex("afr56bq add testa fl80"), "ADDWPT AFR56BQ TESTA FL80")
  r = tr38("afr56bq add testa fl60 500")
  check(r.ask ~= nil and r.ask:find("'500'", 1, true) ~= nil, said(r))
  r = tr38("AFR56BQ add TESTA, hdg 210")
  check(r.ask ~= nil and r.commands == nil, said(r))
  -- with the navdata: a lowercase fix, navaid or airport name typed in a place's slot is that place
  if lab:exec("POS BETUS") then
    check_eq(ex("afr56bq add betus"), "ADDWPT AFR56BQ BETUS")
    check_eq(ex("klm88v add betus after testa"), "ADDWPT KLM88V BETUS,,,TESTA")
    check_eq(ex("klm88v add spy before testa"), "ADDWPT KLM88V SPY,,,,TESTA")
    check_eq(ex("afr56bq clb fl240 then dct spy"), "ALT AFR56BQ FL240 ; ADDWPT AFR56BQ SPY ; DIRECT AFR56BQ SPY")
    check_eq(ex("cre ewg77 a320 at betus hdg 120 fl240 spd 280"), "CRE EWG77 A320 BETUS 120 FL240 280")
    check_eq(ex("create ewg78 a320 over spy, hdg 260, fl200, 260 kts"), "CRE EWG78 A320 SPY 260 FL200 260")
    -- a capital anywhere leaves the line as typed
    asked(ex("AFR56BQ add betus"), ex("AFR56BQ add betus"))
  else
    print("skipped: lowercase place names need navdata (SQUAWK_NAVDATA)")
  end
end

-- Cycle 18: a name the navdata gives to two airports, written with one's ICAO code beside it, is that
-- airport; the name alone is asked about
do
  local east = squawk.sim.new()
  check(east:exec("CRE CPA520 A333 34.9 138.5 060 FL300 280"))
  local _, ex = set_up(east, {})
  if #east:airports_named("munchen") == 1 then
    check_eq(ex("Cathay 520 destination Haneda, RJTT"), "DEST CPA520 RJTT")
    check_eq(ex("CPA520 destination Haneda (RJTY)"), "DEST CPA520 RJTY")
    check(ex("Cathay 520 destination Haneda"):find("^ASK Which airport is 'haneda'") ~= nil, "the name alone")
  else
    print("skipped: airports sharing a name need navdata (SQUAWK_NAVDATA)")
  end
end

-- a note's text after its colon is the note, whole (no setting inside it is run); a bare number left after
-- MOVE's position is its altitude when it reads as one, else asked; "on the ground" in a creation is 0 ft and
-- 0 kt; a correction naming "just"/"only" some of the aircraft takes back the others (and, with a value after,
-- the values said before)
do
  local s40, ex = scene({ "CRE KLM77 B738 52.1 4.5 180 FL150 250", "CRE DLH4AX A321 52.4 4.4 090 FL300 280",
      "CRE NKS409 A320 52.0 4.0 025 FL200 250", "CRE BAW8CK A320 52.2 4.2 300 FL250 280" })
  check_eq(ex("note for the log: run 4, MVP on, PZ 5 nm"), "ECHO run 4 , MVP on , PZ 5 nm")
  check_eq(ex("log: reso off now, dt 0.5 and FF 10 min"), "ECHO reso off now , dt 0.5 and FF 10 min")
  check_eq(ex("move KLM77 to 52.3, 4.6 and keep it at 4000"), "MOVE KLM77 52.3 4.6 4000")
  check_eq(ex("teleport DLH4AX to 52.5 4.1 at 12000"), "MOVE DLH4AX 52.5 4.1 12000")
  check_eq(ex("reposition KLM77 at 52.3 4.6, 250"),
    "ASK To move KLM77 I did not place '250'. Is it an altitude, heading or speed?")
  check_eq(ex("create KLM900, B738, at 52.3 4.7, heading 240, on the ground"), "CRE KLM900 B738 52.3 4.7 240 0 0")
  check_eq(ex("spawn DLH900 A320 at 52.31 4.76 hdg 180 on ground"), "CRE DLH900 A320 52.31 4.76 180 0 0")
  check(ex("create KLM901 B738 at 52.3 4.7 heading 240 FL100 on the ground"):match("^ASK .*on the ground") ~= nil)
  check_eq(ex("KLM77 and DLH4AX climb FL320, sorry, just DLH4AX"), "ALT DLH4AX FL320")
  check_eq(ex("put KLM77 and BAW8CK at FL180 ... actually only BAW8CK, FL190"), "ALT BAW8CK FL190")
  check_eq(ex("descend the Spirit and KLM77 to FL140, no wait, only the Spirit to FL120"), "ALT NKS409 FL120")
  -- business and general-aviation designators written, "King Air 350/200" said; a family's name said with a
  -- designator of that family describes it, with another it is asked about
  check_eq(ex("create a Citation, EJA412, C56X, at 52.3 4.7 heading 030, 5000 ft, 210 kts"),
    "CRE EJA412 C56X 52.3 4.7 30 5000 210")
  check_eq(ex("create N441CP, a King Air 350, at 52.2 4.6 heading 270 at 8000 feet and 230 knots"),
    "CRE N441CP B350 52.2 4.6 270 8000 230")
  check(ex("create a Citation, EJA413, B738, at 52.3 4.7 heading 030, 5000 ft, 210 kts"):match("'Citation'") ~= nil)
  -- "vectors for <anything>" says what a vector is for: noted, the heading flown
  local r40 = graph.translate("KLM77 turn right heading 090, vectors for Rotterdam, descend 5000", { sim = s40, mode = "offline" })
  check_eq(said(r40), "HDG KLM77 90 RIGHT ; ALT KLM77 5000")
  check(r40.note ~= nil and r40.note:find("vectors for Rotterdam", 1, true) ~= nil, tostring(r40.note))
  check_eq(ex("DLH4AX left heading 200, vectors for spacing"), "HDG DLH4AX 200 LEFT")
  -- "down to"/"up to" opening a clause after another instruction, a level after "to", changes level
  check_eq(ex("KLM77 left 110, down to 3000"), "HDG KLM77 110 LEFT ; ALT KLM77 3000")
  check_eq(ex("BAW8CK heading 310, then up to FL280"), "HDG BAW8CK 310 ; ALT BAW8CK FL280")
  check(ex("KLM77 slow to 180, down to 250"):match("^ASK .*'250'") ~= nil)
end

-- Cycle 19 (R41, US Center and TRACON phraseology): a crossing restriction is AT wherever it is said in the
-- line; a role of two words addressed before a comma is a label; "pilot's discretion" after a level; "restart
-- the clock" runs it on; "respectively" pairs the values with the aircraft in order; "MD-11"; a family of
-- several common variants said alone is asked about
do
  local s41, ex = scene({ "CRE UPS2931 MD11 33.2 -85.1 045 FL200 300", "DEFWPT HONIE 33.5 -84.8",
      "ADDWPT UPS2931 HONIE", "CRE ASA1294 B739 33.95 -117.2 265 FL190 290", "CRE UAL1562 B739 33.7 -117.6 315 FL190 250" })
  check_eq(ex("UPS 2931 proceed direct HONIE, cross HONIE at one four thousand"),
    "DIRECT UPS2931 HONIE ; AT UPS2931 HONIE ALT 14000")
  check_eq(ex("UPS2931 turn left heading 030, then cross HONIE at and maintain FL150"),
    "HDG UPS2931 30 LEFT ; AT UPS2931 HONIE ALT FL150")
  check_eq(ex("UPS2931 cross HONIE at 250 knots"), "AT UPS2931 HONIE SPD 250")
  check_eq(ex("pseudo-pilot, delete UPS 2931"), "DEL UPS2931")
  check_eq(ex("pseudo pilot, remove Alaska 1294 from the exercise"), "DEL ASA1294")
  check_eq(ex("Alaska 1294 descend and maintain flight level one six zero, pilot's discretion"), "ALT ASA1294 FL160")
  check_eq(ex("Alaska 1294 descend and maintain FL160 at pilots discretion"), "ALT ASA1294 FL160")
  check_eq(ex("Alaska 1294 descend at pilot's discretion"),
    "ASK To what level should ASA1294 descend? Please give a level or an altitude.")
  check_eq(ex("restart the clock, we're good"), "OP")
  check_eq(ex("start the sim clock again"), "OP")
  check(ex("restart the exercise") ~= "OP", "a restarted exercise is no OP")
  check_eq(ex("Alaska 1294 and United 1562, descend and maintain one zero thousand and niner thousand respectively"),
    "ALT ASA1294 10000 ; ALT UAL1562 9000")
  check_eq(ex("United 1562 and Alaska 1294 turn left heading 270 and 250 respectively"),
    "HDG UAL1562 270 LEFT ; HDG ASA1294 250 LEFT")
  check_eq(ex("Alaska 1294 and United 1562 reduce speed to 250 and 220 knots respectively"),
    "SPD ASA1294 250 ; SPD UAL1562 220")
  asked(ex("Alaska 1294 and United 1562 descend to FL150, FL140 and FL130 respectively"))
  check_eq(ex("create FDX1400 MD-11 at 33.9 north 117.5 west heading 270 FL190 300 knots"),
    "CRE FDX1400 MD11 33.9 -117.5 270 FL190 300")
  check(ex("create UPS2120 Boeing 767 at 32.9 north 97.4 west heading 180 FL220 300 knots"):match("^ASK Which variant") ~= nil)
  check(ex("create a United 787, UAL9, at 40 north 70 west heading 090 FL300 300 knots"):match("^ASK Which variant") ~= nil)
  check_eq(ex("create UAL9 767-300 at 40 north 70 west heading 090 FL300 300 knots"), "CRE UAL9 B763 40 -70 90 FL300 300")
  check_eq(ex("create UAL10 a 757 at 40 north 70 west heading 090 FL300 300 knots"), "CRE UAL10 B752 40 -70 90 FL300 300")
  check_eq(ex("create UAL11 a 777 at 40 north 70 west heading 090 FL300 300 knots"), "CRE UAL11 B772 40 -70 90 FL300 300")
  -- a multi-word navaid name is the navaid, never the fix named like one of its words; a VOR said by its
  -- name after "cross" is a crossing restriction there
  local nav, pt = navscene({ "CRE AAL2307 A321 33.5 -97.8 135 FL200 300", "ADDWPT AAL2307 UKW", "ADDWPT AAL2307 CREEK",
        "CRE UPS1284 B752 32.2 -96.3 330 FL240 310", "ADDWPT UPS1284 CQY" }, "R41 navaid names")
  if nav then
    check_eq(pt("UPS 1284 proceed direct Cedar Creek"), "DIRECT UPS1284 CQY")
    check(pt("UPS 1284 proceed direct Fox Creek"):match("^ASK Which place is 'Fox Creek'") ~= nil)
    check_eq(pt("American 2307, Fort Worth Center, cross Bowie at and maintain one three thousand"),
      "AT AAL2307 UKW ALT 13000")
    check_eq(pt("UPS 1284 cross Cedar Creek at flight level two one zero"), "AT UPS1284 CQY ALT FL210")
    check_eq(pt("move American 2307 to Cedar Creek"), "MOVE AAL2307 CQY")
    check_eq(pt("create FDX77 B752 over Cedar Creek heading 090 FL200 300 knots"), "CRE FDX77 B752 CQY 90 FL200 300")
    check(pt("create FDX78 B752 over Fox Creek heading 090 FL200 300 knots"):match("^ASK Which place is 'Fox Creek'") ~= nil)
    -- (a fix said whole after "cross" stays that fix, though a navaid bears its name)
    check_eq(pt("American 2307 cross CREEK at one two thousand"), "AT AAL2307 CREEK ALT 12000")
  end
end

-- Cycle 19 (R42's classes, docs/translator_trust.md "Speech recognition"): a digit's homophone inside a
-- callsign is that digit only where the callsign so read is exactly one aircraft's; a telephony run into its
-- number is that aircraft; a route's name split into syllables is joined when the words spell it (or it
-- with one silent letter more); a near miss is asked about
do
  local s42, ex = scene({ "CRE WZZ2LP A321 42.3 12.4 200 FL260 280", "CRE DLH400 B744 42.5 12.0 270 FL330 300",
      "CRE DLH44 A320 42.1 12.9 180 FL120 250", "CRE BAW4 A320 42.0 12.2 090 FL200 250",
      "CRE BAW42 A320 42.2 12.6 090 FL220 250", "DEFWPT TOBIX 42.6 12.8", "DEFWPT ASBIN 42.7 12.1",
      "ADDWPT WZZ2LP TOBIX", "ADDWPT WZZ2LP ASBIN" })
  check_eq(ex("wizz air to lima papa turn left heading one zero zero"), "HDG WZZ2LP 100 LEFT")
  check_eq(ex("lufthansa for hundred climb flight level three five zero"), "ALT DLH400 FL350")
  check_eq(ex("lufthansa for for descend flight level one zero zero"), "ALT DLH44 FL100")
  check_eq(ex("lufthansa for oh oh climb flight level three five zero"), "ALT DLH400 FL350")
  -- (BAW4 flies: "to" after its number stays a preposition, and the level is read)
  check_eq(ex("speedbird four climb to two four zero"), "ALT BAW4 FL240")
  check(ex("speedbird four to turn left heading one zero zero") ~= "HDG BAW42 100 LEFT", "BAW4 flies")
  check_eq(ex("speedbird42 turn right heading two seven zero"), "HDG BAW42 270 RIGHT")
  check_eq(ex("wizzair2lp turn right heading two seven zero"), "HDG WZZ2LP 270 RIGHT")
  asked(ex("speedbird43 turn right heading two seven zero"), "no BAW43 flies")
  check_eq(ex("wizz air two lima papa direct toe bix"), "DIRECT WZZ2LP TOBIX")
  check_eq(ex("wizz air two lima papa proceed direct as bin"), "DIRECT WZZ2LP ASBIN")
  asked(ex("wizz air two lima papa direct toe bax"), "a near miss is asked about")
  -- a digit's homophone inside a level's or heading's three spoken digits is that digit; a level heard as
  -- "zero" alone is asked about
  check_eq(ex("wizz air two lima papa climb flight level three for zero"), "ALT WZZ2LP FL340")
  check_eq(ex("lufthansa four hundred turn left heading won eight zero"), "HDG DLH400 180 LEFT")
  check_eq(ex("lufthansa four hundred turn right heading two ate zero"), "HDG DLH400 280 RIGHT")
  asked(ex("lufthansa four hundred descend flight level for zero"), "no level 0")
  asked(ex("lufthansa four hundred descend flight level to for zero"), "FL240 or FL040")
end

-- Cycle 19: a navaid's name of three words or more said whole is that navaid, the navdata's short form of it
-- too ("San Sebastian de los Reyes": "S.S. REYES", SSY); its first two words alone name two others, asked about
do
  local mad = squawk.sim.new()
  check(mad:exec("CRE AEA051 B738 40.0 -3.5 350 FL120 250"))
  local _, ex = set_up(mad, {})
  if #mad:navaids_named("s s reyes", 40, -3.5, 100) == 1 then
    check_eq(ex("europa zero five one proceed direct san sebastian de los reyes"), "ADDWPT AEA051 SSY ; DIRECT AEA051 SSY")
    check_eq(ex("AEA051 direct San Sebastian de los Reyes, then climb FL240"),
      "ADDWPT AEA051 SSY ; DIRECT AEA051 SSY ; ALT AEA051 FL240")
    check(ex("europa zero five one proceed direct san sebastian"):match("^ASK Which navaid") ~= nil, "SSN or HIG")
  else
    print("skipped: navaid names need navdata (SQUAWK_NAVDATA)")
  end
end

-- Cycle 20 (R43's classes, docs/translator_trust.md "ICAO English as a second language"): a QFE height is
-- asked about; a navaid's kind after its name is that place (a MOVE keeps its level); a destination set is no
-- waypoint as well; metric flight levels; "occupy" a level; bounds without "than"; a limit that ends at a place;
-- "be at FIX FL80"; the region's airline telephony; a flight number said as "seventeen hundred"
do
  local s43 = squawk.sim.new()
  for _, line in ipairs({ "CRE AFL1700 A321 55.9 37.4 240 FL150 280", "CRE SBI1042 A320 55.1 37.9 350 FL120 250",
      "CRE TGZ751 A320 55.4 37.0 060 FL170 290", "CRE CSN6023 A330 55.2 38.3 090 FL280 290",
      "DEFWPT TKTX 55.5 37.6", "DEFWPT PETKX 55.6 37.8", "DEFWPT VAKNX 55.3 37.2", "ADDWPT AFL1700 PETKX",
      "ADDWPT SBI1042 VAKNX" }) do
    check(s43:exec(line))
  end
  local _, ex = set_up(s43, {})
  check(ex("Aeroflot 1700 descend to height 600 metres on QFE"):match("^ASK.*QFE") ~= nil, "a QFE height is asked")
  check(ex("SBI1042 descend height 900 m QFE"):match("^ASK.*QFE") ~= nil, "a QFE height is asked")
  check_eq(ex("SBI1042 descend 4000 feet QNH 1003"), "ALT SBI1042 4000")
  check_eq(ex("instructor: Siberian 1042 relocate to TKTX VOR at flight level 200"), "MOVE SBI1042 TKTX FL200")
  check_eq(ex("move Georgian 751 to TKTX NDB at 9000 feet"), "MOVE TGZ751 TKTX 9000")
  check_eq(ex("China Southern 6023 descend flight level 8100 metres"), "ALT CSN6023 26575")
  check_eq(ex("CSN6023 occupy flight level 9500 m"), "ALT CSN6023 31168")
  check_eq(ex("China Southern 6023, climb 10700 metres, flight level three five one"), "ALT CSN6023 FL351")
  asked(ex("China Southern 6023, climb 10700 metres, flight level 330"), "they differ")
  check_eq(ex("Siberian 1042 occupy FL110"), "ALT SBI1042 FL110")
  check_eq(ex("Georgian 751, occupy 3600 metres"), "ALT TGZ751 11811")
  check_eq(ex("Siberian 1042 climb FL160 rate not less 1500 feet per minute"), "ALT SBI1042 FL160 1500")
  check_eq(ex("Georgian 751 maintain flight level 170 until further"), "ALT TGZ751 FL170")
  check_eq(ex("Georgian 751 descend FL150, not above speed 250"), "ALT TGZ751 FL150 ; SPD TGZ751 250")
  check_eq(ex("Siberian 1042 keep speed 280 until VAKNX"), "SPD SBI1042 280")
  check_eq(ex("Siberian 1042 speed 220 till VAKNX then reduce 180"), "SPD SBI1042 220 ; AT SBI1042 VAKNX DO SPD SBI1042 180")
  asked(ex("Siberian 1042 maintain 170 knots until VAKNX then contact tower"), "'then' waits")
  check_eq(ex("Aeroflot 1700, be at PETKX flight level eight zero"), "AT AFL1700 PETKX ALT FL80")
  check_eq(ex("Siberian 1042 after VAKNX expect vectors, now keep speed 280"), "SPD SBI1042 280")
  check_eq(ex("Siberian 1042 after VAKNX descend FL100"), "AT SBI1042 VAKNX DO ALT SBI1042 FL100")
  check_eq(ex("Aeroflot seventeen hundred turn left heading 120"), "HDG AFL1700 120 LEFT")
  check_eq(ex("What is position of Siberian 1042?"), "POS SBI1042")
  check_eq(ex("instructor here, remove Georgian 751, he is landed"), "DEL TGZ751")
  check_eq(ex("create Ural 2790, A320, at PETKX, heading 360, flight level 110, speed 250"),
    "CRE SVR2790 A320 PETKX 360 FL110 250")
  check_eq(ex("Create Air Astana 145 A321 at TKTX heading 120 FL 170 speed 270"), "CRE KZR145 A321 TKTX 120 FL170 270")
  check_eq(ex("create UZB3021 B752 at TKTX heading 080 altitude 0 speed 0"), "CRE UZB3021 B752 TKTX 80 0 0")
  local bru = squawk.sim.new()
  if #bru:airports_named("yuzhny") == 1 then
    local _, nb = set_up(bru, { "CRE THY398 A321 53.1 28.9 320 FL240 290", "DEFWPT DELOX 53.3 28.5",
      "ADDWPT THY398 DELOX" })
    check_eq(nb("Turkish 398, after DELOX proceed to Minsk, set destination UMMS"), "DEST THY398 UMMS")
    check_eq(nb("make aircraft UZB3021 Boeing 757 at Tashkent airport, heading 080, altitude zero, speed zero"),
      "CRE UZB3021 B752 UTTT 80 0 0")
  else
    print("skipped: airports by their city need navdata (SQUAWK_NAVDATA)")
  end
end

-- Cycle 20 (translate44): a pilot's readback, question and the words a pseudo-pilot types
do
  local nb = squawk.sim.new()
  for _, line in ipairs({ "CRE FIN7 A320 60.0 24.0 090 FL260 280", "CRE KLM1153 B738 59.5 10.5 040 FL170 280" }) do
    check(nb:exec(line))
  end
  local _, ex = set_up(nb, {})
  local function asks(text, part)
    local got = ex(text)
    check(got:match("^ASK") ~= nil and got:find(part, 1, true) ~= nil, text .. " -> " .. got)
  end
  -- a readback's speed participle carries its value; a number said after an instruction word that no
  -- command carries is asked about, never dropped
  check_eq(ex("KLM1153 reducing 250 and descending FL130"), "SPD KLM1153 250 ; ALT KLM1153 FL130")
  check_eq(ex("KLM1153 descending FL130, increasing to 280 knots"), "ALT KLM1153 FL130 ; SPD KLM1153 280")
  check_eq(ex("slowing 220, KLM1153"), "SPD KLM1153 220")
  asks("KLM1153 descend FL130, frobbing 250", "'250'")
  asks("KLM1153 descend FL130 and 250", "'250'")
  -- a pilot's question back: a repeat asked for, or whether a clearance stands, is no instruction
  asks("say again the level for FIN7?", "asks for a repeat")
  asks("FIN7 say that again, heading?", "asks for a repeat")
  asks("say again the speed, KLM1153", "asks for a repeat")
  asks("FIN7 confirm cleared FL200?", "asks whether a clearance stands")
  asks("KLM1153 confirm heading 270?", "asks whether a clearance stands")
  -- (the controller's own repeat, and a state question with no value, read as before)
  check_eq(ex("FIN7 descend FL240, I say again, FL240"), "ALT FIN7 FL240")
  check_eq(ex("FIN7 confirm level?"), "POS FIN7")
  -- the level a readback leaves is no instruction: the one after "for" is
  check_eq(ex("FIN7 leaving FL260 for FL200"), "ALT FIN7 FL200")
  check_eq(ex("left heading 210 and leaving FL260 for FL200, FIN7"), "HDG FIN7 210 LEFT ; ALT FIN7 FL200")
  check_eq(ex("FIN7 right heading 120, out of FL260 for FL240"), "HDG FIN7 120 RIGHT ; ALT FIN7 FL240")
  check_eq(ex("FIN7 turn left heading 200 and from FL260 to FL220"), "HDG FIN7 200 LEFT ; ALT FIN7 FL220")
  -- a word inside a callsign gives no direction ("3UP" is no climb)
  local up = squawk.sim.new()
  check(up:exec("CRE RYR3UP B738 57.3 23.4 140 FL150 280"))
  check(up:exec("CRE EZY4DN A320 57.0 23.0 140 FL150 280"))
  check_eq(said(graph.translate("Ryanair 3UP descend FL90", { sim = up, mode = "offline" })), "ALT RYR3UP FL90")
  check_eq(said(graph.translate("Easy 4DN climb FL200", { sim = up, mode = "offline" })), "ALT EZY4DN FL200")
  asked(said(graph.translate("Ryanair 3UP climb FL90", { sim = up, mode = "offline" })),
    "a climb to a lower level is still asked about")
  -- the clock sped up by a factor typed "x2"; a person in the room opens a remark after a comma
  check_eq(ex("speed the sim up x2"), "DTMULT 2")
  check_eq(ex("speed up the simulation x4"), "DTMULT 4")
  check_eq(ex("freeze the sim, trainee needs a break"), "HOLD")
  check_eq(ex("pause, instructor wants to brief the student"), "HOLD")
  -- a readback's callsign at the end, after a typed level: the words before the level are no garbled callsign
  local sas = squawk.sim.new()
  for _, line in ipairs({ "CRE SAS123 A20N 59.5 19.6 270 FL150 290", "CRE FIN7 A320 60.0 24.0 090 FL260 280",
      "CRE ICE306 B752 61.2 9.2 100 FL280 290" }) do
    check(sas:exec(line))
  end
  local _, rb = set_up(sas, {})
  check_eq(rb("descend FL120, Finnair 7"), "ALT FIN7 FL120")
  check_eq(rb("climb to FL300 Finnair 7"), "ALT FIN7 FL300")
  -- an airline's name squawk does not know, before the new callsign it opens, names the new aircraft's airline
  check_eq(rb("create a second Norstar, NSZ88, B738 at 59.0 17.0 heading 020 FL200 290 knots"),
    "CRE NSZ88 B738 59 17 20 FL200 290")
  check(rb("create a Foobar, NSZ88, B738 at 59.0 17.0 heading 020 FL200 290 knots"):match("^ASK.*'Foobar'") ~= nil,
    "a word that does not open the callsign is asked about")
  check_eq(rb("right heading 060, descend FL120, FIN7"), "HDG FIN7 60 RIGHT ; ALT FIN7 FL120")
end

-- Cycle 20: a city's one airport said by the city's name (lexicon.city_airports), far from the aircraft too;
-- an airport the navdata marks closed is no destination
do
  local os = squawk.sim.new()
  check(os:exec("CRE KLM1153 B738 59.5 10.5 040 FL170 280"))
  local _, ex = set_up(os, {})
  if #os:airports_named("gardermoen") == 1 then
    check_eq(ex("KLM1153 origin Amsterdam, destination Oslo Gardermoen"), "ORIG KLM1153 EHAM ; DEST KLM1153 ENGM")
    check_eq(ex("KLM1153 destination Oslo"), "DEST KLM1153 ENGM")
    check_eq(ex("KLM1153 origin Copenhagen"), "ORIG KLM1153 EKCH")
    -- (Stockholm Tullinge, ESCN, is closed: Arlanda or Bromma is asked about, never the closed field)
    asked(ex("KLM1153 destination Stockholm"), "no closed airport")
    -- (a name borne only far away, CYXU in Canada, is never offered where the region's airports lie by
    -- navaids of the name: London's are asked about)
    local london = ex("KLM1153 destination London")
    check(london:match("^ASK Which airport is 'London'") ~= nil and london:find("EGLL", 1, true) ~= nil, london)
  else
    print("skipped: airports by city need navdata (SQUAWK_NAVDATA)")
  end
end

-- Cycle 21 (R48): the machine teammate addressed before the request is a label ("AI, ...", "teammate: ...",
-- "ok AI, ...", "AI what's ..."), never an instruction of its own; the teammate's own plans are asked about;
-- a diversion to an airport is its new destination; the clock run "for" a time; study people open a remark
do
  local tm = squawk.sim.new()
  for _, line in ipairs({ "CRE KLM1234 B738 52 4 090 FL300 280", "CRE RYR5GH B738 52.1 4.2 090 FL280 280",
      "CRE QTR8 B77W 52.4 4 090 FL350 280" }) do
    check(tm:exec(line))
  end
  local _, ex = set_up(tm, {})
  check_eq(ex("AI, climb KLM1234 to FL340"), "ALT KLM1234 FL340")
  check_eq(ex("teammate: RYR5GH speed 250"), "SPD RYR5GH 250")
  check_eq(ex("hey AI, KLM1234 heading 200"), "HDG KLM1234 200")
  check_eq(ex("assistant please give RYR5GH heading 120"), "HDG RYR5GH 120")
  check_eq(ex("ok teammate, can you descend the KLM to FL200 for me?"), "ALT KLM1234 FL200")
  check_eq(ex("the Qatar Airways climb FL370"), "ALT QTR8 FL370")
  -- (no concrete instruction: asked, never a clearance invented; "AI" in the callsign position is no label)
  asked(ex("teammate, what's your plan for the KLM?"), "the teammate's plan is no route")
  asked(ex("AI, you handle the Ryanair from now on"), "no clearance invented")
  asked(ex("AI 101 climb FL300"), "a callsign AI 101 is no addressee")
  asked(ex("the AI climbs KLM1234"), "the AI named inside the request is asked about")
  check_eq(ex("run it for 90 seconds"), "FF 90")
  check_eq(ex("set the sim running"), "OP")
  check_eq(ex("place an easyJet, EZY12, A320, at 52 4 heading 090 FL200 250 knots"), "CRE EZY12 A320 52 4 90 FL200 250")
  check_eq(ex("freeze the sim, participant needs a break"), "HOLD")
  asked(ex("divert KLM1234 around the weather"), "a diversion to no airport is asked about")
  if #tm:airports_named("eindhoven") == 1 then
    check_eq(ex("divert KLM1234 to Eindhoven"), "DEST KLM1234 EHEH")
    check_eq(ex("RYR5GH diverting to Rotterdam"), "DEST RYR5GH EHRD")
  else
    print("skipped: diversions by city need navdata (SQUAWK_NAVDATA)")
  end
end

-- Cycle 21 (R47, West and Central African controllers): "rejoin X" flies to X; a place in the approach sequence
-- and traffic information past the other aircraft's name are named, never asked about; the region's airlines by
-- telephony or name anywhere in the request; a station named by its navaid; a city's one airport
do
  local af = squawk.sim.new()
  for _, line in ipairs({ "CRE ARA512 B737 6.5 3.5 090 FL200 280", "CRE SKK602 B737 6.6 3.6 270 FL220 280",
      "CRE VRE701 A320 6.4 3.4 180 FL240 270", "CRE AFW401 DH8D 6.3 3.3 000 FL140 230",
      "DEFWPT KISMO 6.9 3.9", "ADDWPT ARA512 KISMO" }) do
    check(af:exec(line))
  end
  local _, ex = set_up(af, {})
  check_eq(ex("ARA512 rejoin KISMO"), "DIRECT ARA512 KISMO")
  check_eq(ex("ARA512 descend FL150, rejoin the route at KISMO"), "ALT ARA512 FL150 ; DIRECT ARA512 KISMO")
  check_eq(ex("ARA512 you are rejoining your track at KISMO"), "DIRECT ARA512 KISMO")
  check_eq(ex("ARA512 reduce speed 250 knots, you are number two"), "SPD ARA512 250")
  check_eq(ex("ARA512 you're number three behind the ASKY, reduce speed 220 knots"), "SPD ARA512 220")
  check_eq(ex("ARA512 maintain FL200, number one in sequence"), "ALT ARA512 FL200")
  check_eq(ex("ARA512 turn left heading 160, traffic a Dash 8 at your two o'clock"), "HDG ARA512 160 LEFT")
  check_eq(said(graph.translate("wind at 6.5 north 3.3 east from two two zero at 15 knots", { mode = "offline" })),
    "WIND 6.5 3.3 220 15")
  check_eq(said(graph.translate("a wind over 12N 8.5E, from 050 degrees, 20 knots", { mode = "offline" })),
    "WIND 12 8.5 50 20")
  check_eq(ex("List the route for Arik 512"), "LISTRTE ARA512")
  check_eq(ex("delete ASKY 602"), "DEL SKK602")
  check_eq(ex("what's the speed of Cote d'Ivoire 701"), "POS VRE701")
  check_eq(ex("Approach, Blue Marlin four zero one, climb flight level one six zero"), "ALT AFW401 FL160")
  if #af:airports_named("murtala muhammed") == 1 then
    check_eq(ex("Kano, Arik five one two, climb flight level two four zero"), "ALT ARA512 FL240")
    check_eq(ex("Lome: ASKY 602 descend FL180"), "ALT SKK602 FL180")
    check_eq(ex("ARA512 new destination Lagos"), "DEST ARA512 DNMM")
    check_eq(ex("SKK602 new destination Abidjan"), "DEST SKK602 DIAP")
  else
    print("skipped: stations and cities by navdata names need navdata (SQUAWK_NAVDATA)")
  end
end

-- Cycle 21 (R45): a speed said after a level's "thousand" is a value of its own; homophones inside a
-- thousands; an airline's telephony run into its number in a creation is the ICAO code and number
do
  local ns = squawk.sim.new()
  check(ns:exec("CRE SWG412 B738 42.9 -80.1 040 FL260 280"))
  local _, tr = set_up(ns, {})
  check(not tr("SWG412 speed one zero thousand two hundred and fifty knots"):match("SPD SWG412 10250"),
    "no speed of thousands of knots")
  check_eq(tr("sunwing four twelve descend and maintain one to thousand"), "ALT SWG412 12000")
  check_eq(tr("sunwing four twelve descend and maintain won for thousand"), "ALT SWG412 14000")
  check_eq(tr("sunwing four twelve descend to four thousand"), "ALT SWG412 4000")
  check_eq(tr("sunwing four twelve reduce speed to too fifty"), "SPD SWG412 250")
  check_eq(tr("create a new aircraft delta1022 b739 at 41.3 north 71.6 west heading 250 flight level 200 at 280 knots"),
    "CRE DAL1022 B739 41.3 -71.6 250 FL200 280")
  check_eq(tr("make united77 a320 at 41.3 north 71.6 west heading 090 flight level 240 at 280 knots"),
    "CRE UAL77 A320 41.3 -71.6 90 FL240 280")
end

-- Cycle 21 (R45): "to" before a latitude or longitude is the preposition when "two" would pass the pole or
-- the antimeridian; "flight level too one zero" is FL210, no flight level lying below 3000 ft
do
  local ps = squawk.sim.new()
  check(ps:exec("CRE UAL9 B738 40.5 -74.0 090 FL300 280"))
  local _, tp = set_up(ps, {})
  check_eq(tp("move united nine to four zero point eight north seven four point two west"), "MOVE UAL9 40.8 -74.2")
  check_eq(tp("united nine descend and maintain flight level too one zero"), "ALT UAL9 FL210")
  asked(tp("united nine descend and maintain flight level to eight zero"),
    "FL280 or FL080 both lie below FL300: asked")
end

-- Cycle 21 (R45): an airport's ICAO code spelled letter by letter ("c y v r") is that code
do
  local as = squawk.sim.new()
  check(as:exec("CRE WJA123 B38M 48.6 -122.3 300 FL200 280"))
  local _, ta = set_up(as, {})
  if as:airport_class("CYVR") ~= "" then
    check_eq(ta("give westjet one twenty three destination c y v r"), "DEST WJA123 CYVR")
    check_eq(ta("westjet one twenty three origin k s e a"), "ORIG WJA123 KSEA")
    check(ta("westjet one twenty three destination c y v q r"):match("^DEST WJA123 CYVR") == nil,
      "five letters spell no airport code")
  else
    print("skipped: spelled airport codes need navdata (SQUAWK_NAVDATA)")
  end
end

-- Cycle 21 (R46): "go higher to N" is a level; a value said after a word of direction or motion is never
-- dropped in silence when another instruction is read
do
  local hs = squawk.sim.new()
  check(hs:exec("CRE SWR12 A320 47.55 8.30 90 FL240 280"))
  local _, hi = set_up(hs, {})
  check_eq(hi("SWR12 go higher to 36000 and turn right 30 degrees"), "ALT SWR12 36000 ; HDG SWR12 120 RIGHT")
  check_eq(hi("take SWR12 higher to FL360"), "ALT SWR12 FL360")
  check_eq(hi("SWR12 go lower to 8000 and turn left 20 degrees"), "ALT SWR12 8000 ; HDG SWR12 70 LEFT")
  check(hi("SWR12 go higher 36000 and turn right 30 degrees"):match("^ASK.*'36000'") ~= nil,
    "a level after an unread direction word is asked about, not dropped")
  check(hi("SWR12 higher please 36000 and turn right 30 degrees"):match("^ASK.*'36000'") ~= nil,
    "a level after an unread direction word is asked about, not dropped")
  -- "goes to"/"heads to" an airport, said as a fact, is the destination; a level after it is no airport
  if #hs:airports_named("zurich") > 0 then
    check_eq(hi("SWR12 goes to EDDF"), "DEST SWR12 EDDF")
    check_eq(hi("SWR12 heads to LSZH"), "DEST SWR12 LSZH")
  end
  check_eq(hi("SWR12 goes to FL300"), "ALT SWR12 FL300")
  -- "follow your route (again)" is the route's lateral navigation back on
  check(hs:exec("ADDWPT SWR12 47.6 9.0"))
  check_eq(hi("SWR12 follow your route again"), "LNAV SWR12 ON")
  check_eq(hi("please have SWR12 follow the route"), "LNAV SWR12 ON")
end

-- An amount before the comparative ("1000 feet lower", "2000 ft up") is a change of level, never a cleared
-- altitude of that many feet; "minus 20 knots" is slower (the direction word gives the sign, not the number's)
do
  local _, ex = scene({ "CRE EWG7YC A320 53 9 090 FL330 280", "CRE CFG1TK A320 53 8 090 FL300 300" })
  check_eq(ex("EWG7YC 1000 feet lower please"), "ALT EWG7YC 32000")
  check_eq(ex("EWG7YC 2000 ft down"), "ALT EWG7YC 31000")
  check_eq(ex("EWG7YC 1000 feet higher"), "ALT EWG7YC 34000")
  check_eq(ex("EWG7YC descend to 11000 feet"), "ALT EWG7YC 11000")
  check_eq(ex("CFG1TK minus 20 knots"), "SPD CFG1TK 280")
  check_eq(ex("CFG1TK speed minus 15 kts"), "SPD CFG1TK 285")
  check_eq(ex("CFG1TK 10 knots faster"), "SPD CFG1TK 310")
end

-- CRECONFS's optional arguments by their names ("dh 1000", "tlosv 200") are read, and a value of the
-- description read as no argument is asked about, never dropped; "dh" beside the protected zone is its
-- half height
do
  local _, ex = scene({ "CRE KLM77 B738 52 4 090 FL200 250" })
  check_eq(ex("creconfs XY20 A320 KLM77 dpsi 90 cpa 0.5 tlos 300 dh 1000 tlosv 200"),
    "CRECONFS XY20 A320 KLM77 90 0.5 300 1000 200")
  check_eq(ex("creconfs XY20 A320 KLM77 dpsi 90 cpa 0.5 tlos 300 dh 1000"), "CRECONFS XY20 A320 KLM77 90 0.5 300 1000")
  check(ex("creconfs XY20 A320 KLM77 dpsi 90 cpa 0.5 tlos 300 7777"):match("^ASK .*'7777'") ~= nil, "a stray value")
  check_eq(ex("add a conflict for KLM77: XY21, A320, head-on (180), 1 nm CPA, 240 s to LoS"),
    "CRECONFS XY21 A320 KLM77 180 1 240")
  check_eq(ex("pz 5 nm, dh 1000, lookahead 300"), "ZONER 5 ; ZONEDH 1000 ; DTLOOK 300")
end

-- A turn side with a bare number and no "heading" ("r 360", "l 200", "right 360"), typed as shorthand too, that
-- would be a heading the long way round asks whether it is a turn by that many degrees (a "360" an orbit) or the
-- heading; the short way round it is the heading. "turn 30" with no side asks: 30 degrees, or heading 030?
do
  local _, ex = scene({ "CRE EIN9QT A320 53 -6 150 FL090 250", "CRE RYR3MX B738 53 -5 060 FL070 240" })
  check(ex("EIN9QT right 360"):match("^ASK Should EIN9QT turn right by 360 degrees, or fly heading 360") ~= nil,
    ex("EIN9QT right 360"))
  check(ex("ryr3mx l 210"):match("^ASK .*the long way round") ~= nil, ex("ryr3mx l 210"))
  check_eq(ex("ryr3mx r 200"), "HDG RYR3MX 200 RIGHT")
  check_eq(ex("ein9qt l 090"), "HDG EIN9QT 90 LEFT")
  check_eq(ex("ein9qt rt hdg 360"), "HDG EIN9QT 360 RIGHT")
  check(ex("ein9qt turn 40"):match("^ASK Should EIN9QT turn left or right by 40 degrees") ~= nil, ex("ein9qt turn 40"))
  check(ex("turn ryr3mx twenty"):match("^ASK Should RYR3MX turn left or right") ~= nil, ex("turn ryr3mx twenty"))
  check_eq(ex("ein9qt turn 40 left"), "HDG EIN9QT 110 LEFT")
  check_eq(ex("RYR3MX turn 240"), "HDG RYR3MX 240")
  check_eq(ex("TURN RYR3MX 30"), "HDG RYR3MX 30")  -- TrafScript in capitals: heading 030
end

-- Numbers whose kind or size the typing leaves open: a heading typed with two digits and no leading zero
-- ("hdg 27": 027 or 270?), a bare three-digit number kept or maintained ("keep it at 230": a level or a
-- speed, unless it is the aircraft's own present one), a side and a heading straight behind ("turn right
-- 270" from 090: a reversal or a turn of 270 degrees?), one or two typed digits after a level verb ("climb
-- 25") are asked, naming the readings; three typed digits led by zero after a level verb are a flight level
-- ("descend 070")
do
  local _, ex = scene({ "CRE TST7K A320 45 9 090 FL080 250", "CRE TST8M A320 45 10 200 FL240 280" })
  check(ex("tst7k hdg 27"):match("^ASK What heading should TST7K fly: 027 or 270%?") ~= nil, ex("tst7k hdg 27"))
  check(ex("tst7k heading 12 please"):match("^ASK .*012 or 120") ~= nil, ex("tst7k heading 12 please"))
  check_eq(ex("TST7K HDG 27"), "HDG TST7K 27")  -- TrafScript in capitals: heading 027
  check_eq(ex("tst7k hdg 95"), "HDG tst7k 95")  -- typed TrafScript: no other reading
  check_eq(ex("tst7k hdg 027"), "HDG tst7k 027")
  check(ex("tst7k keep it at 230"):match("^ASK Should TST7K fly FL230 or 230 knots%?") ~= nil, ex("tst7k keep it at 230"))
  check(ex("tst8m maintain 310"):match("^ASK .*FL310 or 310 knots") ~= nil, ex("tst8m maintain 310"))
  check_eq(ex("tst8m maintain 240"), "ALT TST8M FL240")  -- its own level
  check_eq(ex("tst7k keep it at 250"), "SPD TST7K 250")  -- its own speed
  check_eq(ex("tst7k maintain 230 kts"), "SPD TST7K 230")
  check_eq(ex("tst7k maintain two three zero"), "SPD TST7K 230")
  check_eq(ex("tst8m descend 070"), "ALT TST8M FL70")
  check_eq(ex("tst7k climb 090"), "ALT TST7K FL90")
  -- one or two typed digits after a level verb: hundreds or thousands of feet? (it was a change of 25 ft)
  check(ex("tst7k climb 25"):match("^ASK What altitude should TST7K climb to: 2500 ft or 25000 ft%?") ~= nil,
    ex("tst7k climb 25"))
  check(ex("tst8m descend 8"):match("^ASK .*8000 ft%?") ~= nil, ex("tst8m descend 8"))
  check_eq(ex("tst8m descend 8 thousand"), "ALT TST8M 8000")
  check(ex("tst7k turn right 270"):match("^ASK Should TST7K turn right by 270 degrees, or turn right onto heading 270") ~= nil,
    ex("tst7k turn right 270"))
  check_eq(ex("tst7k turn right heading 270"), "HDG TST7K 270 RIGHT")
  check_eq(ex("tst8m l 170"), "HDG TST8M 170 LEFT")
end

-- Settings typed key=value, as in a config or a log ("seed=7", "dt=0.5, dtmult=4", "reso=mvp"): the
-- setting and its value, as with a space between; a key that names no setting is still asked about
do
  local _, ex = scene({ "CRE TST7K A320 45 9 090 FL080 250" })
  check_eq(ex("seed=7"), "SEED 7")
  check_eq(ex("dt=0.5, dtmult=4"), "DT 0.5 ; DTMULT 4")
  check_eq(ex("reso=mvp"), "RESO MVP")
  check_eq(ex("pz=5nm"), "ZONER 5")
  check_eq(ex("ff=90"), "FF 90")
  check_eq(ex("tst7k spd=230"), "SPD TST7K 230")
  check(ex("q=5"):match("^ASK ") ~= nil, ex("q=5"))
  check_eq(ex("log: reward spike at t=300"), "ECHO reward spike at t=300")  -- no setting's key: as typed
  check_eq(ex("note: seed=42 baseline"), "ECHO seed=42 baseline")
end

-- "both" with no aircraft named before it is the two aircraft flying when only two fly ("turn both 20
-- right", "where are they both"); with three or more it still asks which two
do
  local _, ex = scene({ "CRE TST7K A320 45 9 090 FL080 250", "CRE TST8M A320 45 10 200 FL240 280" })
  check_eq(ex("turn both 30 left"), "HDG TST7K 60 LEFT ; HDG TST8M 170 LEFT")
  check_eq(ex("where are they both"), "POS TST7K ; POS TST8M")
  check_eq(ex("both of them descend fl070"), "ALT TST7K FL70 ; ALT TST8M FL70")
  local _, ex3 = scene({ "CRE TST7K A320 45 9 090 FL080 250", "CRE TST8M A320 45 10 200 FL240 280",
    "CRE TST9Q A320 45 11 200 FL240 280" })
  check(ex3("turn both 30 left"):match("^ASK Which two aircraft does 'both' mean") ~= nil, ex3("turn both 30 left"))
end

-- A question about where an aircraft is ("where is ryanair", "wheres the speedbird", "what's Ryanair doing")
-- names the one aircraft of that airline flying, also without "the": a question, no cut-short callsign
-- given an instruction ("ryanair climb fl200" still asks); typed chat shorthand ("rn", "lol", "thx") and a
-- fault or a break given as the reason ("its bugged", "need coffee") carry no instruction
do
  local _, ex = scene({ "CRE RYR4TK B738 45 9 090 FL080 250", "CRE BAW77 A320 45 10 200 FL240 280",
    "CRE EZY12 A320 45 11 200 FL240 280", "CRE EZY34 A320 45 11.5 200 FL240 280" })
  check_eq(ex("where is ryanair"), "POS RYR4TK")
  check_eq(ex("wheres the speedbird"), "POS BAW77")
  check_eq(ex("what's ryanair doing rn"), "POS RYR4TK")
  check(ex("where is easyjet"):match("^ASK Which ") ~= nil, ex("where is easyjet"))
  check(ex("ryanair climb fl200"):match("^ASK ") ~= nil, ex("ryanair climb fl200"))
  check_eq(ex("baw77 fl250 lol"), "ALT BAW77 FL250")
  check_eq(ex("remove ezy12 its bugged"), "DEL EZY12")
  check_eq(ex("freeze the sim, need coffee"), "HOLD")
  check(ex("baw77 fl250 banana"):match("^ASK .*'banana'") ~= nil, ex("baw77 fl250 banana"))
end

-- A note opening the request, its one sentence the whole request ("note: run 3, seed 42, no reso",
-- "comment: first episode"), is text for the log; a note beside an instruction stays a remark
do
  local _, ex = scene({ "CRE TST7K A320 45 9 090 FL080 250" })
  check_eq(ex("note: run 2, baseline"), "ECHO run 2 , baseline")
  check_eq(ex("comment: first episode"), "ECHO first episode")
  check_eq(ex("note to self: episode 3 is the head-on one. set lookahead 120"), "DTLOOK 120")
  check_eq(ex("tst7k descend fl070, comment: lose the overlap"), "ALT TST7K FL70")
end

-- A shape's name given in words ("name MXP1", "call it REF2", "name it C3") is its name, also when a place
-- is said by its name too; that place is accounted for when it lies at one of the points given in figures
-- (within 0.1 degree), and asked about when it does not
do
  local _, ex = navscene({}, "places named at a shape's points")
  if ex then
    check_eq(ex("circle round EHAM, name AMSCTR, 52.309 4.764 radius 12nm"), "CIRCLE AMSCTR 52.309 4.764 12")
    check_eq(ex("line from EHAM to EDDF, call it AMSFRA: 52.309 4.764 50.033 8.570"),
      "LINE AMSFRA 52.309 4.764 50.033 8.57")
    check(ex("circle round EDDF, name AMSCTR, 52.309 4.764 radius 12nm"):match("^ASK .*'EDDF'") ~= nil,
      ex("circle round EDDF, name AMSCTR, 52.309 4.764 radius 12nm"))
  end
  local _, ex2 = scene({})
  check_eq(ex2("box named ZONE1 52 4 53 5"), "BOX ZONE1 52 4 53 5")
end

-- Random traffic and the clock in an experimenter's notes: the count of a type after "random traffic,",
-- the destination after "heading for" / "bound for" (a place after a verb of going that names nothing
-- is asked), a multiplier typed alone as a clause ("then x4", ", 4x") the clock's rate
do
  local _, ex = scene({ "DEFWPT MYFIX 45 9" })
  check_eq(ex("random traffic, 6 a320 at fl300 going to MYFIX"), "MCRE 6 A320 FL300 * MYFIX")
  check_eq(ex("make 5 random ones all heading for MYFIX"), "MCRE 5 * * * MYFIX")
  check(ex("make 5 random ones bound for atlantis"):match("^ASK .*'atlantis'") ~= nil, ex("make 5 random ones bound for atlantis"))
  check_eq(ex("20 random aircraft to fill the sky"), "MCRE 20")
  check_eq(ex("seed 3 then 10 random b738 then x8"), "SEED 3 ; MCRE 10 B738 ; DTMULT 8")
  check_eq(ex("pause, 2x"), "HOLD ; DTMULT 2")
end

-- Areas and winds typed as notes: "restrict sim area to box 45 6 48 13" (two corners after the sim's
-- area, "box" its form), a wind's position typed straight after "wind"; a waypoint's position said after
-- "at" before the verb ("ezy1 at 45.8 8.9 insert wpt"); "add X then direct it" flies to X
do
  local _, ex = scene({ "CRE TST7K A320 45 9 090 FL080 250", "DEFWPT MYFIX 45.5 9.5", "DEFWPT OTHFX 45.7 9.9",
    "ADDWPT TST7K MYFIX" })
  check_eq(ex("restrict sim area to box 44 8 46 10"), "AREA 44 8 46 10")
  check_eq(ex("limit the area to 44 8 46 10"), "AREA 44 8 46 10")
  check_eq(ex("wind 45.2 9.4 FL100 from 250 at 30 kts"), "WIND 45.2 9.4 FL100 250 30")
  check_eq(ex("tst7k at 45.3 9.2 insert wpt"), "ADDWPT TST7K 45.3 9.2")
  check_eq(ex("tst7k add OTHFX then direct it"), "ADDWPT TST7K OTHFX ; DIRECT TST7K OTHFX")
  check(ex("tst7k add OTHFX then direct MYFIX"):match("^ASK .*'OTHFX'") ~= nil, ex("tst7k add OTHFX then direct MYFIX"))
end
do
  local _, ex = navscene({ "CRE TST7K A320 46.4 6.6 090 FL080 250" }, "navaid names with Saint")
  if ex then check_eq(ex("tst7k direct saint prex"), "ADDWPT TST7K SPR ; DIRECT TST7K SPR") end
end

-- A brand several airlines fly under said alone in a question ("where is the netjets": NJE or EJA), and a
-- second speaker's label with an assent after the request ("student: ... climb fl150? engineer: yes do
-- it"): the request as said; a label followed by anything but assent is read as typed
do
  local _, ex = scene({ "CRE NJE318 C56X 47.3 10.75 090 FL230 250", "CRE ITY2011 A319 41.85 11.8 070 FL090 240" })
  check_eq(ex("where is the netjets"), "POS NJE318")
  check_eq(ex("student: ity2011 climb fl150? engineer: yes do it"), "ALT ITY2011 FL150")
  check_eq(ex("ity2011 climb fl150. instructor: ok go ahead"), "ALT ITY2011 FL150")
  check(ex("ity2011 climb fl150? engineer: maybe later"):match("^ASK ") ~= nil, ex("ity2011 climb fl150? engineer: maybe later"))
end

-- A state word typed with "?" after an aircraft and no value ("swr84c altitude?", "afr1442 speed?") asks for
-- its state (POS), as does "how high is afr1442" typed without "?"; with no "?", or an instruction's
-- shorthand ("fl?"), it stays an instruction that lacks its value
do
  local _, ex = scene({ "CRE SWR84C A320 46.5 6.7 250 FL140 270" })
  check_eq(ex("swr84c altitude?"), "POS SWR84C")
  check_eq(ex("swr84c speed?"), "POS SWR84C")
  check(ex("swr84c fl?"):match("^ASK ") ~= nil, ex("swr84c fl?"))
  check_eq(ex("how high is swr84c"), "POS SWR84C")
  check(ex("swr84c altitude"):match("^ASK What altitude") ~= nil, ex("swr84c altitude"))
  check(ex("swr84c climb?"):match("^ASK What altitude") ~= nil, ex("swr84c climb?"))
end

-- A learning environment's words for the simulation ("reset env", "pause the environment"), "realtime" as
-- one word; trails neither shown nor hidden ("clear trails") are asked about (it showed them), hidden when
-- "hide" opens their clause after another instruction
do
  local _, ex = scene({ "CRE TST7K A320 45 9 090 FL080 250" })
  check_eq(ex("pause env"), "HOLD")
  check(ex("reset env"):match("^ASK Reset the simulation") ~= nil, ex("reset env"))
  check_eq(ex("realtime speed"), ex("real time speed"))
  check(ex("clear trails"):match("^ASK Should the trails be shown") ~= nil, ex("clear trails"))
  check_eq(ex("show trails"), "TRAIL ON")
  check_eq(ex("trails every 5 seconds"), "TRAIL ON 5")
  check_eq(ex("dtmult 6 and hide trails"), "DTMULT 6 ; TRAIL OFF")  -- (it showed them)
  check_eq(ex("ff 2m"), "FF 120")
  check_eq(ex("could you draw trails behind the aircraft"), "TRAIL ON")
end

-- "back to real time" with no word that starts the clock, on a held clock: its rate back to 1 (DTMULT 1);
-- "real time speed" is the rate; "run it in real time again" returns to real time as "back to real time" does
-- (Cycle 40, d82); "start it in real time again" starts it
do
  local _, ex = scene({})
  check_eq(ex("back to real time"), "DTMULT 1")
  check_eq(ex("ok go back to real time pls"), "DTMULT 1")
  check_eq(ex("back to real time speed"), "DTMULT 1")
  check_eq(ex("run it in real time again"), "DTMULT 1")
  check_eq(ex("start it in real time again"), "OP")
  check_eq(ex("ok run"), "OP")
end

-- A state asked for with its typed short name after "say"/"report" ("say alt", "report lvl", "say spd"), and
-- "where" typed after the callsign, show the aircraft (POS); "say alt 5000" is a level
do
  local _, ex = scene({ "CRE SHT4KD A320 55 -3 300 FL110 250", "CRE LOG22 E145 56 -4 150 FL140 260" })
  check_eq(ex("sht4kd say lvl"), "POS SHT4KD")
  check_eq(ex("report hdg log22"), "POS LOG22")
  check_eq(ex("say spd sht4kd"), "POS SHT4KD")
  check_eq(ex("log22 where?"), "POS LOG22")
  check_eq(ex("log22 where now"), "POS LOG22")
  check_eq(ex("sht4kd say alt 5000"), "ALT SHT4KD 5000")
  check(ex("log22 where to"):match("^ASK ") ~= nil, ex("log22 where to"))
  check_eq(ex("log22 say fl"), "POS LOG22")
  check_eq(ex("log22 say fl 150"), "ALT LOG22 FL150")
end

-- Typed short forms and slips of the lab's keyboard: "lef" a turn side, "dtc" a direct-to, "prot zone" the
-- protected zone, "acft" aircraft, "cre N random" random traffic (MCRE)
do
  local _, ex = scene({ "CRE EZY7LP A320 53 -3 130 FL150 280", "DEFWPT KOBAL 53.2 -2.8" })
  check_eq(ex("ezy7lp turn lef 30"), "HDG EZY7LP 100 LEFT")
  check_eq(ex("ezy7lp lef hdg 090"), "HDG EZY7LP 90 LEFT")
  check_eq(ex("ezy7lp dtc KOBAL fl 120"), "ADDWPT EZY7LP KOBAL ; DIRECT EZY7LP KOBAL ; ALT EZY7LP FL120")
  check_eq(ex("prot zone 4 nm"), "ZONER 4")
  check_eq(ex("cre 8 random acft"), "MCRE 8")
  check(ex("ezy7lp turn lef"):match("^ASK ") ~= nil, ex("ezy7lp turn lef"))
end

-- A condition said after the instruction it holds: "reduce 180 kts when level" waits for the level cleared
-- before it (ATALT), "dct KOBAL, once there FL80" is the constraint at the waypoint flown to (AT ... ALT); a
-- turn tied there asks. "at 10 from KOBAL" (a bare number between "at" and "from" a place) is a distance, NM
do
  local _, ex = scene({ "CRE LOG7Y E145 53 -3 150 FL140 260", "DEFWPT KOBAL 53.2 -2.8", "ADDWPT LOG7Y KOBAL" })
  check_eq(ex("log7y desc fl90 and reduce 200 kts when lvl"), "ALT LOG7Y FL90 ; ATALT LOG7Y FL90 SPD LOG7Y 200")
  check_eq(ex("log7y climb fl160, speed 280 once it's level"), "ALT LOG7Y FL160 ; ATALT LOG7Y FL160 SPD LOG7Y 280")
  check(ex("log7y desc fl90 and turn left 20 when level"):match("^ASK ") ~= nil,
    ex("log7y desc fl90 and turn left 20 when level"))
  check_eq(ex("log7y dct KOBAL, once there fl 80"), "DIRECT LOG7Y KOBAL ; AT LOG7Y KOBAL ALT FL80")
  check_eq(ex("log7y dct KOBAL when there 210 kts"), "DIRECT LOG7Y KOBAL ; AT LOG7Y KOBAL SPD 210")
  check(ex("log7y dct KOBAL and once there turn right 30"):match("^ASK ") ~= nil,
    ex("log7y dct KOBAL and once there turn right 30"))
  check_eq(ex("log7y at 15 from KOBAL desc fl100"), "ATDIST LOG7Y KOBAL 15 ALT LOG7Y FL100")
  check_eq(ex("log7y reduce 220 at 8 from KOBAL"), "ATDIST LOG7Y KOBAL 8 SPD LOG7Y 220")
  check(ex("log7y at 5000 from KOBAL desc fl100"):match("^ATDIST") == nil, "no distance of 5000 NM")
end

-- A wind written as direction/speed ("270/25", "090/15kt") and placed at a bare decimal latitude and longitude;
-- "schedule 00:10:00 ..." opening a request runs it then (SCHEDULE)
do
  local _, ex = scene({ "CRE EXP4 A320 53 -5 000 FL230 260" })
  check_eq(ex("wind at 52.1 -7.3 240/30"), "WIND 52.1 -7.3 240 30")
  check_eq(ex("set wind 090/15kt at 51.9 -8.0"), "WIND 51.9 -8 90 15")
  check_eq(ex("wind at 52.1 -7.3 from 240 at 30 kts"), "WIND 52.1 -7.3 240 30")
  check_eq(ex("schedule 00:05:00 exp4 fl250"), "SCHEDULE 00:05:00 ALT EXP4 FL250")
  check_eq(ex("schedule 00:12:30 exp4 speed 240"), "SCHEDULE 00:12:30 SPD EXP4 240")
end

-- An airport's ICAO code typed in lower case after orig/origin/dest ("orig eidw dest egcc") is that airport;
-- "dest eidw -> einn" changes the destination to the second; an unknown code is asked about
do
  local s, ex = navscene({ "CRE EIN6TR A320 53.5 -6.5 090 FL200 280" }, "lower-case airport codes")
  if s then
    check_eq(ex("ein6tr orig eidw dest egcc"), "ORIG EIN6TR EIDW ; DEST EIN6TR EGCC")
    check_eq(ex("ein6tr dest: einn spd 250"), "DEST EIN6TR EINN ; SPD EIN6TR 250")
    check_eq(ex("ein6tr dest eidw -> egcc"), "DEST EIN6TR EGCC")
    check(ex("ein6tr dest qqqz"):match("^ASK ") ~= nil, ex("ein6tr dest qqqz"))
  end
end

-- "Jet2" (Channex, EXS) before a flight number is that airline ("jet2 44m", "Jet 2 four four mike"); an aircraft
-- whose id is JET2 keeps it. "pos NAME" in a line that names an aircraft type is where a new aircraft is placed.
-- "dct LANAK then TWEED", LANAK ending the route: the places after it are added after it; one the route already
-- holds earlier is asked about
do
  local _, ex = scene({ "CRE EXS31K B738 54 -3 250 FL200 280", "CRE JET2 A320 54 -4 100 FL100 250",
      "DEFWPT KOBAL 54.2 -2.8", "DEFWPT TULIX 54.4 -2.5", "ADDWPT EXS31K KOBAL" })
  check_eq(ex("jet2 31k left 10"), "HDG EXS31K 240 LEFT")
  check_eq(ex("Jet 2 three one kilo climb FL240"), "ALT EXS31K FL240")
  check_eq(ex("jet2 climb fl300"), "ALT JET2 FL300")
  check_eq(ex("a321 EXS9 fl 150 pos KOBAL hdg 090 250kt"), "CRE EXS9 A321 KOBAL 90 FL150 250")
  check_eq(ex("exs31k dct KOBAL then TULIX"), "DIRECT EXS31K KOBAL ; ADDWPT EXS31K TULIX")
  check_eq(ex("exs31k dct kobal then tulix"), "DIRECT EXS31K KOBAL ; ADDWPT EXS31K TULIX")
  check_eq(ex("exs31k dct kobal then climb fl220"), "DIRECT EXS31K KOBAL ; ALT EXS31K FL220")
  check(ex("exs31k dct TULIX then KOBAL"):match("^ASK .*'KOBAL'") ~= nil, ex("exs31k dct TULIX then KOBAL"))
end
-- Round 52's classes (human-factors researchers over Scandinavia and the Baltic: polite full sentences,
-- aircraft by airline or nickname, greetings in their own languages)
do
  local _, ex = scene({ "CRE TEST07 B738 59.4 18.7 300 FL100 250", "CRE DLH4AX A321 52.4 4.4 090 FL300 280",
    "CRE SAS1421 A320 55 12 010 FL120 280", "CRE WIF3 CRJ9 60 10 110 FL080 220" })
  -- an aircraft named by its callsign's letters before an aircraft noun ("our test aircraft": TEST07)
  check_eq(ex("could you turn our test aircraft left heading 200"), "HDG TEST07 200 LEFT")
  check_eq(ex("the test plane should climb to FL140, please"), "ALT TEST07 FL140")
  check_eq(ex("please set the test aircraft's speed to 230 knots"), "SPD TEST07 230")
  asked(ex("climb the test to FL140"), "the letters with no aircraft noun name nothing")
  -- "the SAS one": "one" with no digit after it is the pronoun, no flight number 1
  check_eq(ex("could you bring the SAS one down to FL90"), "ALT SAS1421 FL90")
  check_eq(ex("the SAS one, turn it right heading 090 please"), "HDG SAS1421 90 RIGHT")
  check_eq(ex("reduce the SAS one to 210 knots"), "SPD SAS1421 210")
  check_eq(ex("the SAS one four two one, descend FL90"), "ALT SAS1421 FL90")
  -- a relative turn said in words after an airline is no flight number
  check_eq(ex("turn the Lufthansa fifteen degrees right"), "HDG DLH4AX 105 RIGHT")
  check_eq(ex("could the Lufthansa go twenty five degrees left"), "HDG DLH4AX 65 LEFT")
  -- greetings and thanks in the Nordic and Baltic languages, and their hesitations
  check_eq(ex("Hej, could the Lufthansa climb to FL320? Tack."), "ALT DLH4AX FL320")
  check_eq(ex("Labdien, ehm, the Lufthansa should reduce to 250 knots, paldies"), "SPD DLH4AX 250")
  check_eq(ex("Hei, the German one, the Lufthansa, heading 120 please. Kiitos!"), "HDG DLH4AX 120")
  -- a question of how fast or how high an aircraft flies shows it
  check_eq(ex("How fast is the Lufthansa flying at the moment?"), "POS DLH4AX")
  check_eq(ex("how high is our test aircraft now?"), "POS TEST07")
  -- knots taken off the speed flown
  check_eq(ex("the Lufthansa is a bit fast, could you take off 20 knots?"), "SPD DLH4AX 260")
  check_eq(ex("knock 15 knots off the Lufthansa's speed"), "SPD DLH4AX 265")
  -- a regional family named without its variant
  check_eq(ex("could the CRJ descend to 6000 feet"), "ALT WIF3 6000")
  -- a human-factors study's words around an instruction
  check_eq(ex("pause the sim please, the participant is filling in the NASA-TLX"), "HOLD")
  check_eq(ex("the eye tracker is calibrated now, please run the sim again"), "OP")
  -- the clock: "start it again" with no aircraft named, real time beside a normal rate, a note for the log
  check_eq(ex("could you start it again? the participant is ready"), "OP")
  check_eq(ex("normal speed again, please, and real time"), "DTMULT 1")
  check_eq(ex("please write 'block 2 begins' into the log"), "ECHO block 2 begins")
  -- a question about a setting, a remark after it; an instruction after it still asks
  check_eq(ex("Is conflict detection on at the moment? The alerts seem quiet."), "ASAS")
  asked(ex("Is conflict detection on? Please switch it on if not."), "a condition after it")
  -- a trailing level condition with its own subject; said with a participle it is read as before
  check_eq(ex("slow the Lufthansa to 240 knots once it reaches FL250 on the way down"),
    "ATALT DLH4AX FL250 SPD DLH4AX 240")
  check_eq(ex("DLH4AX descend FL200, reduce to 240 knots once it passes FL250"),
    "ALT DLH4AX FL200 ; ATALT DLH4AX FL250 SPD DLH4AX 240")
  asked(ex("pause the sim once it reaches FL100"), "a trailing condition with no aircraft's command")
  -- CRECONFS's closest point, said in words, and "a conflicting aircraft"
  check_eq(ex("create a conflicting aircraft against the Lufthansa: INT5, an A320, at 45 degrees, 1 mile at "
    .. "closest point, 200 seconds to loss of separation"), "CRECONFS INT5 A320 DLH4AX 45 1 200")
end
do
  local _, ex = scene({ "CRE TEST07 B738 59.4 18.7 300 FL100 250", "CRE TEST08 B738 59.5 18.7 300 FL100 250",
    "CRE SAS1421 A320 55 12 010 FL120 280", "CRE SAS88 A320 56 12 010 FL160 280" })
  asked(ex("could you turn our test aircraft left heading 200"), "two test aircraft")
  check(ex("bring the SAS one down to FL90"):match("^ASK Which SAS") ~= nil, "two SAS")
  -- the airline said again with its flight number in the same sentence names that one
  check_eq(ex("the SAS up north, SAS 88, should climb to FL200"), "ALT SAS88 FL200")
  asked(ex("the SAS should climb to FL200, SAS88 too"), "an instruction between")
end
do
  local _, ex = navscene({ "CRE BTI1AA BCS3 57.5 20.0 120 FL350 280", "ADDWPT BTI1AA EDERA", "ADDWPT BTI1AA EDISA",
    "CRE FIN2BB A321 58.6 21.5 220 FL350 270", "ADDWPT FIN2BB NATAN", "ADDWPT FIN2BB MILTA", "ADDWPT FIN2BB EDISA",
    "CRE SAS5 A320 59.4 18.2 010 FL120 280", "CRE NAX741 B738 59.7 10.9 030 FL090 250" }, "round 52's classes")
  if ex then
    -- "both the Finnair and the airBaltic": the two aircraft named, no two of one airline
    check_eq(ex("Both the Finnair and the airBaltic should descend to flight level 300."),
      "ALT FIN2BB FL300 ; ALT BTI1AA FL300")
    check(ex("both Finnair planes descend FL300"):match("^ASK Which two") ~= nil, "one Finnair flying")
    check_eq(ex("could the Finnair fly its own route again?"), "LNAV FIN2BB ON")
    -- a direct-to for every aircraft named together
    check_eq(ex("the airBaltic and the Finnair should both go direct to EDISA"),
      "DIRECT BTI1AA EDISA ; DIRECT FIN2BB EDISA")
    -- a remark after a query naming places is its reason; one with an instruction or a value is not
    check_eq(ex("where is the Finnair now? has it passed NATAN already?"), "POS FIN2BB")
    check_eq(ex("show me the airBaltic's route, I want to check that EDERA comes first"), "LISTRTE BTI1AA")
    asked(ex("where is the Finnair? is it at FL300 yet?"), "a value in the remark")
    -- a condition at a waypoint of the route runs its instruction there (AT acid wp DO), a heading too; a
    -- place off the route is asked
    check_eq(ex("when the Finnair passes MILTA, it should climb to FL370"), "AT FIN2BB MILTA DO ALT FIN2BB FL370")
    check_eq(ex("once the Finnair gets to MILTA, reduce to 250 knots"), "AT FIN2BB MILTA DO SPD FIN2BB 250")
    check_eq(ex("when the Finnair passes MILTA, turn it left heading 180"), "AT FIN2BB MILTA DO HDG FIN2BB 180 LEFT")
    asked(ex("when the Finnair passes EDERA, climb to FL370"), "off the route")
    check_eq(ex("the Finnair should climb to FL370 and, when it is at MILTA, slow to 250 knots"),
      "ALT FIN2BB FL370 ; AT FIN2BB MILTA DO SPD FIN2BB 250")
    asked(ex("the Finnair should climb to FL370 and, when it is at EDERA, slow to 250 knots"),
      "a condition mid-request at a place off the route")
    -- a place said after a correction replaces the one before it (it was dropped in silence)
    check_eq(ex("the Finnair direct NATAN, correction, MILTA"), "DIRECT FIN2BB MILTA")
    check_eq(ex("could the Finnair go straight to NATAN... no, sorry, EDISA"), "DIRECT FIN2BB EDISA")
    -- the letter of a contraction before a number is no shorthand ("when it's 15 miles": no speed)
    check_eq(ex("could the airBaltic descend to 8000 feet when it's 15 miles from EDISA?"),
      "ATDIST BTI1AA EDISA 15 ALT BTI1AA 8000")
    -- "when it's there" after a direct-to: a level or a speed at that place; a heading there asks
    check_eq(ex("the Finnair direct MILTA, and when it's there climb to FL370"),
      "DIRECT FIN2BB MILTA ; AT FIN2BB MILTA ALT FL370")
    asked(ex("the Finnair direct MILTA and when it's there turn left heading 100"),
      "a heading once there")
    -- a place in a reason is no condition at it
    check_eq(ex("could the airBaltic fly 260 knots and the Finnair 280 knots, so they reach EDISA together"),
      "SPD BTI1AA 260 ; SPD FIN2BB 280")
    -- a navaid's name after its ident, when the navdata gives it that name
    check_eq(ex("NAX741 direct GRM, the Gardermoen VOR"), "ADDWPT NAX741 GRM ; DIRECT NAX741 GRM")
    check(ex("NAX741 direct GRM, the Oslo VOR"):match("^ASK .*'Oslo'") ~= nil, "another navaid's name")
    -- the one navaid near the aircraft by its name, never a fix of that ident on another continent; the place
    -- said before "directly"
    check_eq(ex("SAS5 direct TEBBY"), "ADDWPT SAS5 TEB ; DIRECT SAS5 TEB")
    check_eq(ex("SAS5, go to ARL directly please"), "ADDWPT SAS5 ARL ; DIRECT SAS5 ARL")
    -- the city a place lies by ("near Riga"), when one of the city's airports is near it; another city asks
    check_eq(ex("create BTI9ZZ BCS3 at the RIX VOR near Riga, heading 270, FL240, 290 knots"),
      "CRE BTI9ZZ BCS3 RIX 270 FL240 290")
    check(ex("create BTI9ZZ BCS3 at the RIX VOR near Oslo, heading 270, FL240, 290 knots"):match("^ASK .*'Oslo'") ~= nil,
      "a city far from the place")
    -- an airline said before a new callsign of its own describes it; "one more" creates
    check_eq(ex("please create the SAS flight SAS9, an A320, at Arlanda, heading 180, FL100, 250 knots"),
      "CRE SAS9 A320 ESSA 180 FL100 250")
    check_eq(ex("could you create an SAS A321 for us, callsign SAS10, at 59 north 18 east, heading 090, FL110, 260 knots"),
      "CRE SAS10 A321 59 18 90 FL110 260")
    check_eq(ex("make one more A320 at the Trosa VOR heading 090, FL120, 240 knots, callsign EXP5"),
      "CRE EXP5 A320 TRS 90 FL120 240")
  end
end
-- A new aircraft placed along another's track ("12 nm ahead of PH101", "right behind PH101 at 8 nm"):
-- the position d NM along that aircraft's heading (or its reverse), the course, level and speed said
-- against its own ("reciprocal heading", "coming the other way", "same track"; "2000 feet below"; "20 kts
-- quicker"); a course not said, or no callsign and type, is asked
do
  local _, ex = scene({ "CRE PH101 A320 51.0 3.0 090 FL220 260", "CRE SAS7 B738 50.0 6.0 180 FL300 300" })
  check_eq(ex("spawn an intruder 12 nm ahead of PH101, reciprocal heading, same altitude, call it TX1, type B738, 250 kt"),
    "CRE TX1 B738 50.99957 3.317587 270 FL220 250")
  check_eq(ex("TX2 A321 30 nm behind SAS7 on the same track, 2000 feet below, 20 kts quicker"),
    "CRE TX2 A321 50.499663 6 180 FL280 320")
  check_eq(ex("intruder TX3, E190, 10 nm ahead of SAS7, coming the other way, FL300, 280 kt"),
    "CRE TX3 E190 49.833446 6 0 FL300 280")
  check_eq(ex("TX4 A320 right behind PH101 at 8 nm, same course, same level, same speed"),
    "CRE TX4 A320 50.999809 2.788275 90 FL220 260")
  check_eq(ex("spawn TX6 A320 20 nm in front of SAS7, head-on, same level, 280 kt"), "CRE TX6 A320 49.666891 6 0 FL300 280")
  -- (37 km is read as 19.98 NM, to 0.01 NM)
  check_eq(ex("TX7 A320 37 km ahead of PH101, opposite direction, FL220, 280 kt"), "CRE TX7 A320 50.998807 3.528777 270 FL220 280")
  check_eq(ex("put an intruder 15 nm ahead of SAS7"), "ASK To create the aircraft I need its callsign, aircraft type. What should they be?")
  check_eq(ex("TX5 A320 15 nm ahead of SAS7 at FL300, 280 kt"), "ASK What heading should TX5 have?")
end

-- CRECONFS said the researcher's way: "conflict on X: ...", "a converger for X", "a conflicting A320", its
-- name typed short ("crecons", "creconf") with its values bare in the command's order, "400 s to loss";
-- a value not said is still asked for
do
  local _, ex = scene({ "CRE PH101 A320 51.0 3.0 090 FL220 260", "CRE SAS7 B738 50.0 6.0 180 FL300 300" })
  check_eq(ex("creconf TX7 A320 PH101 45 2 300"), "CRECONFS TX7 A320 PH101 45 2 300")
  check_eq(ex("crecons TX7 A320 PH101 45 2 300 1000 100 250"), "CRECONFS TX7 A320 PH101 45 2 300 1000 100 250")
  check_eq(ex("crecons TX7 A320 PH101 45 2"), "ASK At what angle, in degrees, should TX7 cross the track of PH101?")
  check_eq(ex("conflict on SAS7: TX8, A319, dpsi 60, cpa 1, tlosh 200"), "CRECONFS TX8 A319 SAS7 60 1 200")
  check_eq(ex("a converger for PH101: TX9, B738, 20 degrees, cpa 0.5 nm, 300 s to loss"),
    "CRECONFS TX9 B738 PH101 20 0.5 300")
  check_eq(ex("give PH101 a conflicting A320, TX10, 90 deg, passing 2 nm, 120 seconds to loss of separation"),
    "CRECONFS TX10 A320 PH101 90 2 120")
  check_eq(ex("conflict on SAS7: TX8, A319, dpsi 60, cpa 1"), "ASK In how many seconds should TX8 lose separation with SAS7?")
  check_eq(ex("set up a crossing conflict for SAS7: intruder TX11, A321, 90 deg, cpa 1, tlosh 300"),
    "CRECONFS TX11 A321 SAS7 90 1 300")
  asked(ex("there is a conflict between SAS7 and PH101"), "a conflict described sets up nothing")
end

-- The researcher's settings and remarks: "mvp" alone as an item of a list of detection settings is RESO MVP
-- (alone as a request it is asked); "note to self: ..." is the speaker's own to the end of its sentence, the
-- sentence after it is read; "and see if ..." after an instruction is the check the experimenter will make
do
  local _, ex = scene({ "CRE PH101 A320 51.0 3.0 090 FL220 260", "CRE SAS7 B738 50.0 6.0 180 FL300 300" })
  check_eq(ex("zoner 4, dtlook 200 and mvp"), "ZONER 4 ; DTLOOK 200 ; RESO MVP")
  check_eq(ex("asas on, mvp"), "ASAS ON ; RESO MVP")
  asked(ex("mvp"), "the method named alone")
  check_eq(ex("PZ 5 NM; DH 1000 ft; lookahead 300 s; MVP"), "ZONER 5 ; ZONEDH 1000 ; DTLOOK 300 ; RESO MVP")
  check_eq(ex("cd statebased, cr mvp, pz 5"), "ASAS STATEBASED ; RESO MVP ; ZONER 5")
  -- "mvp" is accounted for only by a command that carries it: never dropped
  check_eq(ex("dtlook 300 with mvp"), "ASK I have DTLOOK 300. What does 'mvp' mean?")
  check_eq(ex("let MVP use vertical speed in the resolutions"), "RMETHV V/S")
  check_eq(ex("note to self: seed 9 diverged. dt 0.5"), "DT 0.5")
  asked(ex("note to myself: try pz 4 next"), "a note to self runs nothing")
  check_eq(ex("note for the log: pz 4 from now"), "ECHO pz 4 from now")
  -- "after a resolution ... resume nav once past CPA" says when navigation resumes (RESNAV), no method
  check_eq(ex("after a resolution aircraft should resume nav once past CPA"), "RESNAV PASTCPA")
  check_eq(ex("resolution method MVP, then resume nav past CPA"), "RESO MVP ; RESNAV PASTCPA")
  check_eq(ex("ff 3 min and see if SAS7 and PH101 lose separation"), "FF 180")
  check_eq(ex("SAS7 left 20, see whether that clears PH101"), "HDG SAS7 160 LEFT")
end

-- MOVE's values in its order, as CRE's: the last bare value after the level and heading is the speed; "reset
-- X to <position>" moves X (a bare value with no level and heading before it is still asked)
do
  local _, ex = scene({ "CRE PH101 A320 51.0 3.0 090 FL220 260", "CRE SAS7 B738 50.0 6.0 180 FL300 300" })
  check_eq(ex("move SAS7 to 50.2 6.1, FL310, heading 200, 290"), "MOVE SAS7 50.2 6.1 FL310 200 290")
  check_eq(ex("move SAS7 to 50.2 6.1, FL310, 290"), "ASK To move SAS7 I did not place '290'. Is it an altitude, heading or speed?")
  check_eq(ex("reset PH101 to 51.0, 3.0, FL220, heading 090, 260 kts"), "MOVE PH101 51 3 FL220 90 260")
  asked(ex("reset PH101"), "reset with an aircraft and no position")
end

-- Southern European controllers' and instructors' phrasing (R49): "make it N" after a value corrects it;
-- "until further advice" keeps the value in force; "which ... is set/active" shows the setting; "add WPT
-- to/for ACID" adds the waypoint to that aircraft's route (a clause that goes on past the aircraft is asked)
do
  local _, ex = scene({ "CRE PH101 A320 51.0 3.0 090 FL220 260", "CRE SAS7 B738 50.0 6.0 180 FL300 300",
    "DEFWPT ROSSA 51.2 3.4" })
  check_eq(ex("PH101 speed 240 knots, make it 230"), "SPD PH101 230")
  asked(ex("PH101 speed 240 knots, make it 230 and climb FL300"), "a value not said alone")
  check_eq(ex("PH101 speed 240 knots, make it 230 please"), "SPD PH101 230")
  -- "minimum clean speed" names the speed by the configuration: the value said is flown, none said is asked
  check_eq(ex("PH101 reduce minimum clean speed, 210 knots"), "SPD PH101 210")
  asked(ex("PH101 reduce minimum clean speed"), "no speed said")
  -- the new callsign's airline by its name before it ("put an ITA, ITY77 A320, ...": ITA Airways)
  check_eq(ex("put an ITA, ITY77 A320, at 43.9 N 7.9 E, heading 240, FL130, 270 kt"), "CRE ITY77 A320 43.9 7.9 240 FL130 270")
  -- a wind's direction in degrees and speed in knots said after its position and level, no "from"
  check_eq(ex("wind at 51.5 north 3.5 east, FL150, 250 degrees 30 knots"), "WIND 51.5 3.5 FL150 250 30")
  asked(ex("wind at 51.5 north 3.5 east, 250 degrees"), "no wind speed")
  -- the new callsign's airline said before it in a lead-in ("first aircraft Air Malta AMC412 A320 ...")
  check_eq(ex("first aircraft Speedbird BAW9 A320 51.5N 3.5E heading 100 level 190 speed 280"),
    "CRE BAW9 A320 51.5 3.5 100 FL190 280")
  check_eq(ex("PH101 climb FL240, make it snappy"), "ALT PH101 FL240")  -- (as "make it quick" is)
  check_eq(ex("PH101 maintain 250 knots until further advice"), "SPD PH101 250")
  check_eq(ex("which time step is set"), "DT")
  check_eq(ex("which resolution method is active"), "RESO")
  check_eq(ex("add ROSSA to PH101"), "ADDWPT PH101 ROSSA")
  check_eq(ex("instructor: add ROSSA for SAS7"), "ADDWPT SAS7 ROSSA")
  check_eq(ex("add ROSSA to PH101 and descend FL200"), "ADDWPT PH101 ROSSA ; ALT PH101 FL200")
  asked(ex("add ROSSA to PH101 after SAS7"), "a clause going on past the aircraft")
end

-- A station named like an airline's telephony in a hand-off ("contact Brussels one two seven decimal one") is
-- part of what squawk does not simulate, never an aircraft left over; "the same flight level as X" is X's level
do
  local _, ex = scene({ "CRE PH101 A320 51.0 3.0 090 FL220 260", "CRE SAS7 B738 50.0 6.0 180 FL300 300" })
  check_eq(ex("PH101 descend FL200, contact Brussels one two seven decimal one"), "ALT PH101 FL200")
  check_eq(ex("put PH101 at the same flight level as SAS7"), "ALT PH101 FL300")
  asked(ex("PH101 descend FL200, BEL127 climb FL250"), "an aircraft no one flies, instructed")
end

-- A pair created in one request by a researcher: a title before the colon ("symmetric geometry:") names the
-- scenario; values said after "both"/"all" at the end are each new aircraft's (with an aircraft named after
-- "both", whose values follow is asked); "closer" describes a move whose position is said
do
  local _, ex = scene({ "CRE PH101 A320 51.0 3.0 090 FL220 260" })
  check_eq(ex("symmetric geometry: TX1 A320 at 52.0 4.0 heading 090 and TX2 A320 at 52.0 5.0 heading 270, both FL300, 280 kt"),
    "CRE TX1 A320 52 4 90 FL300 280 ; CRE TX2 A320 52 5 270 FL300 280")
  check(ex("write a note in the log: trial 4 begins"):match("^ECHO") ~= nil, "an instruction before a colon is no title")
  check_eq(ex("overtake: TX1 A320 at 52.0 4.0 heading 090 and TX2 A320 at 52.0 4.5 heading 090, both FL300, TX1 at 300 kt"),
    "ASK Which of the new aircraft do the values after 'both' belong to?")
  asked(ex("don't: PH101 climb FL300"), "a negation before the colon is no title")
  check_eq(ex("move PH101 closer: 51.2 3.3, FL220, heading 090, 250"), "MOVE PH101 51.2 3.3 FL220 90 250")
  asked(ex("move PH101 closer"), "closer, no position")
end

-- Two aircraft swap their levels, headings or speeds ("swap the levels of A and B", "A and B swap headings"):
-- after a yes, each flies the other's present value; one aircraft, or three, is asked
do
  local s = scene({ "CRE PH101 A320 51.0 3.0 090 FL220 260", "CRE SAS7 B738 50.0 6.0 180 FL300 300",
    "CRE TX1 A320 50.5 4.0 270 FL260 280" })
  local _, ex = set_up(s, {})
  local function swapped(text)
    local r = graph.translate(text, { sim = s, mode = "offline" })
    check(r.ask ~= nil and r.ask:match("^Swap the ") ~= nil and r.confirm ~= nil, text)
    return table.concat(r.confirm and r.confirm.commands or {}, " ; ")
  end
  check_eq(swapped("swap the levels of PH101 and SAS7"), "ALT PH101 FL300 ; ALT SAS7 FL220")
  check_eq(swapped("PH101 and SAS7 swap headings"), "HDG PH101 180 ; HDG SAS7 90")
  check_eq(swapped("exchange the speeds of PH101 and TX1"), "SPD PH101 280 ; SPD TX1 260")
  asked(ex("swap the levels of PH101"), "one aircraft")
  asked(ex("swap the levels of PH101, SAS7 and TX1"), "three aircraft")
end
-- Places given to an aircraft after the verb ("add SUDIK to air malta 77", "add X for Y", a list with
-- "then"), and a fix written as a proper name in a line with capitals ("Add Willo to Ryanair 4KP's route")
-- when the navdata holds it near the traffic; a name it does not hold, or no such aircraft, still asks
do
  local s, ex = navscene({ "CRE RYR4KP B738 50.9 -0.5 090 FL200 260", "CRE EZY77 A320 51.2 0.3 270 FL180 250" },
    "places given to an aircraft by 'to'/'for'")
  if s then
    check_eq(ex("Add Willo to Ryanair 4KP's route"), "ADDWPT RYR4KP WILLO")
    check_eq(ex("please add Willo to RYR4KP"), "ADDWPT RYR4KP WILLO")
    check_eq(ex("add WILLO for easy 77"), "ADDWPT EZY77 WILLO")
    check_eq(ex("add WILLO then MAY to EZY77"), "ADDWPT EZY77 WILLO ; ADDWPT EZY77 MAY")
    check_eq(ex("add WILLO, MAY to easy seven seven"), "ADDWPT EZY77 WILLO ; ADDWPT EZY77 MAY")
    check_eq(ex("Easy 77 direct Willo"), "ADDWPT EZY77 WILLO ; DIRECT EZY77 WILLO")
    asked(ex("add WILLO to KLM999"), "no such aircraft")
    asked(ex("Add Banana to EZY77's route"), "no such place")
    -- (in a line with capitals a fix's name in lower case is a word, not read as the place)
    asked(ex("add willo to RYR4KP"), "lower case in a line with capitals")
  end
end

-- Airlines said by their telephony or their own name in Asia, the Middle East, Africa and cargo ("Garuda
-- 412", "IndiGo 2231", "Connie 412"), where aircraft of other airlines share the flight number
do
  local _, ex = scene({ "CRE GIA412 B738 -5 107 190 FL170 280", "CRE IGO412 A20N 19 73 100 FL300 280",
    "CRE CKS412 B744 40 -80 090 FL330 290", "CRE VJC412 A321 10 106 010 FL250 280", "CRE KLM412 B738 52 4 090 FL200 250" })
  check_eq(ex("Garuda four one two, maintain flight level one seven zero"), "ALT GIA412 FL170")
  check_eq(ex("indigo 412 descend FL240"), "ALT IGO412 FL240")
  check_eq(ex("Connie four twelve, climb flight level three five zero"), "ALT CKS412 FL350")
  check_eq(ex("Vietjet 412 turn left heading 320"), "HDG VJC412 320 LEFT")
  asked(ex("Bamboo 412 descend FL240"), "an airline with no aircraft flying asks")
end

-- A level passed, left or reached before the instruction that waits for it, with the instruction's own
-- lead words between ("when passing FL90 fly heading 090", "after passing FL100 resume own navigation direct
-- HEMEL"): ATALT; without the condition word, or with no instruction after the level, it is no condition
do
  local _, ex = scene({ "CRE SAS77 A320 59 11 090 FL80 250", "DEFWPT NIBAX 59.5 12.0", "ADDWPT SAS77 NIBAX",
    "CRE FIN3 A320 60 24 180 FL150 280" })
  check_eq(ex("SAS77 climb FL130, when passing FL100 fly heading 120"), "ALT SAS77 FL130 ; ATALT SAS77 FL100 HDG SAS77 120")
  check_eq(ex("Scandinavian seven seven, climb flight level one three zero, after passing flight level one one zero resume "
    .. "own navigation direct NIBAX"), "ALT SAS77 FL130 ; ATALT SAS77 FL110 DIRECT SAS77 NIBAX")
  check_eq(ex("SAS77 climb FL130, when passing FL100 proceed direct NIBAX"), "ALT SAS77 FL130 ; ATALT SAS77 FL100 DIRECT SAS77 NIBAX")
  check_eq(ex("FIN3 descend FL90, leaving FL120 fly heading 200"), "ALT FIN3 FL90 ; ATALT FIN3 FL120 HDG FIN3 200")
  check_eq(ex("SAS77 climb FL130, resume own navigation direct NIBAX"), "ALT SAS77 FL130 ; DIRECT SAS77 NIBAX")
  check_eq(ex("SAS77 climb FL130, when passing FL100 resume own navigation"),
    "ALT SAS77 FL130 ; ATALT SAS77 FL100 LNAV SAS77 ON")
end

-- A distance from a navaid said by its name before the instruction that waits for it ("when 15 miles from
-- Mayfield descend FL120"): ATDIST at the navaid; a name the navdata does not hold asks
do
  local s, ex = navscene({ "CRE RYR4KP B738 50.9 -0.5 090 FL200 260", "CRE EZY77 A320 51.2 0.3 270 FL180 250" },
    "distances from navaids said by name")
  if s then
    check_eq(ex("EZY77 when 15 miles from Mayfield descend FL120"), "ATDIST EZY77 MAY 15 ALT EZY77 FL120")
    check_eq(ex("Easy 77, when 25 miles from Detling reduce speed 250 knots"), "ATDIST EZY77 DET 25 SPD EZY77 250")
    check_eq(ex("RYR4KP at 10 miles from Mayfield turn left heading 040"), "ATDIST RYR4KP MAY 10 HDG RYR4KP 40 LEFT")
    asked(ex("EZY77 when 20 miles from Banana descend FL120"), "no such navaid")
  end
end

-- A hold at a fix said with a clearance ("descend FL100 and hold at KUDES", "expect holding over ARSOT"): the
-- hold is named as not simulated and the clearance runs; the fix is no constraint's place. A clearance
-- after "then" waits for the hold, and is asked about
do
  local s, ex = scene({ "CRE AUA61 A320 47.5 9.5 090 FL200 280", "DEFWPT MOLIX 47.8 10.0", "ADDWPT AUA61 MOLIX" })
  local r = graph.translate("Austrian six one, descend flight level one one zero and hold at MOLIX", { sim = s, mode = "offline" })
  check_eq(said(r), "ALT AUA61 FL110")
  check(r.note ~= nil and r.note:find("holding patterns ('hold at MOLIX')", 1, true) ~= nil, tostring(r.note))
  check_eq(ex("AUA61 hold over MOLIX, descend FL110"), "ALT AUA61 FL110")
  check_eq(ex("AUA61 expect holding at MOLIX, turn left heading 010"), "HDG AUA61 10 LEFT")
  check_eq(ex("AUA61 cross MOLIX at FL110"), "AT AUA61 MOLIX ALT FL110")
  check(ex("AUA61 hold at MOLIX then descend FL110"):match("^ASK .*waits for it") ~= nil, "after the hold")
end

-- "until further advice", "unless otherwise advised": a value kept in force, explained with it; a level said
-- before a climb or descent that has no value of its own, a comma between ("negative, flight level 280,
-- descend"), is that verb's; a level the aircraft is not on that side of still asks
do
  local _, ex = scene({ "CRE TAP55 A320 39 -9 180 FL300 290" })
  check_eq(ex("TAP55 speed 280 knots until further advice"), "SPD TAP55 280")
  check_eq(ex("Air Portugal five five, maintain flight level three zero zero until further clearance"), "ALT TAP55 FL300")
  check_eq(ex("TAP55 maintain 270 knots unless otherwise advised"), "SPD TAP55 270")
  check_eq(ex("Air Portugal five five, negative, flight level two six zero, descend"), "ALT TAP55 FL260")
  check_eq(ex("TAP55, flight level 260, descend now"), "ALT TAP55 FL260")
  check_eq(ex("TAP55 FL260, descend, heading 200"), "ALT TAP55 FL260 ; HDG TAP55 200")
  check(ex("TAP55 FL260, climb"):match("^ASK TAP55 is at 30000 ft") ~= nil, "a climb to a lower level")
  asked(ex("TAP55 speed 280 knots until further rubbish"), "an unknown word after 'further'")
end

-- "what's CALLSIGN doing?" with the callsign said in words of any length
do
  local _, ex = scene({ "CRE QFA141 B738 -29 153 90 FL200 300", "CRE KLM12 A320 -28 152 90 FL200 300" })
  check_eq(ex("What's Qantas one four one doing?"), "POS QFA141")
  check_eq(ex("what is Qantas one four one doing"), "POS QFA141")
  check_eq(ex("what's KLM one two doing"), "POS KLM12")
end

-- A supervisor's sim control as heard: "fast forward to minutes" (a recogniser's "to" for "two" before a unit,
-- no number said), "fast forward, I'll tell you when to stop" (fast time until stopped), "stop a moment the
-- simulation" (the while said before the object); a duration still not understood asks
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 300" })
  check_eq(ex("fast forward to minutes"), "FF 120")
  check_eq(ex("fast forward too minutes please"), "FF 120")
  check_eq(ex("Fast forward, I'll tell you when to stop"), "FF")
  check_eq(ex("fast forward, we tell you when"), "FF")
  check_eq(ex("stop a moment the simulation"), "HOLD")
  check_eq(ex("stop for a minute the sim please"), "HOLD")
  check(ex("fast forward to"):match("^ASK For how long") ~= nil, "no unit after 'to'")
  check(ex("KLM12 stop climbing in the sim"):match("^HOLD") == nil, "a climb stopped is no pause")
end

-- "maintain FL130, do not descend": a climb or descent refused after a level maintained, its clause ending
-- there, says that level again; a refusal with more words ("below FL120", "yet") or after no maintain asks
do
  local _, ex = scene({ "CRE IGO77 A320 19 73 090 FL130 280" })
  check_eq(ex("IFLY seven seven, negative, maintain flight level one three zero, do not descend"), "ALT IGO77 FL130")
  check_eq(ex("IGO77 maintain FL130, don't climb"), "ALT IGO77 FL130")
  check(ex("IGO77 maintain FL130, do not descend below FL120"):match("^ASK .*'not'") ~= nil, "a bound refused")
  check(ex("IGO77 maintain FL130, do not descend yet"):match("^ASK .*'not'") ~= nil, "a refusal for now")
  check(ex("IGO77 turn left heading 100, do not descend"):match("^ASK .*'not'") ~= nil, "no level maintained")
end

-- A neo said apart from its model ("Airbus 320 neo", "A321 neo", "a three twenty neo") is the neo's designator,
-- never the older model's with "neo" dropped
do
  local _, ex = scene({ "CRE KLM1 A320 52 4 090 FL200 250" })
  check_eq(ex("create KZR30 Airbus 320 neo at 52.5 4.5 heading 290 FL150 250 knots"), "CRE KZR30 A20N 52.5 4.5 290 FL150 250")
  check_eq(ex("create KZR31 A321 neo at 52.5 4.5 heading 290 FL150 250 knots"), "CRE KZR31 A21N 52.5 4.5 290 FL150 250")
  check_eq(ex("create KZR32 a three twenty neo at 52.5 4.5 heading 290 FL150 250 knots"), "CRE KZR32 A20N 52.5 4.5 290 FL150 250")
  check_eq(ex("create KZR33 Airbus 320 at 52.5 4.5 heading 290 FL150 250 knots"), "CRE KZR33 A320 52.5 4.5 290 FL150 250")
end
-- A navaid said by its name and its kind ("over the Hamburg VOR at FL120") is the place, never an approach
-- clearance; a name that no navaid of that kind bears places nothing
do
  local nav, ex = navscene({}, "navaids by name and kind")
  if nav then
    -- (in an empty scene LAM and NIK resolve from 0 0 to other navaids of those idents: the navaid named is
    -- given by its position; "Creation places and the reference position" below)
    check_eq(ex("please create DLH42 A320 right over the Lambourne VOR at FL240, heading 180, 280 knots"),
      "CRE DLH42 A320 51.646111 0.151667 180 FL240 280")
    check_eq(ex("new aircraft KLM5 B738 sitting on the Nicky VOR, flight level 200, heading 270, 260 kts"),
      "CRE KLM5 B738 51.162498 4.189167 270 FL200 260")
    local _, near = navscene({ "CRE BAW1 A320 51.5 -0.3 090 FL200 250" }, "navaids by name and kind")
    check_eq(near("please create DLH42 A320 right over the Lambourne VOR at FL240, heading 180, 280 knots"),
      "CRE DLH42 A320 LAM 180 FL240 280")
    asked(ex("create XY12 A320 above the Lambourne NDB at FL100 heading 090 250 kts"),
      "no NDB bears the name: asked")
  end
end

-- "send/route/reroute X to" an airport said by its name or its city's (lexicon.city_airports) is its
-- destination; a fix after "to" is no destination, and "route X via A and on to B" lists the route first
do
  local nav, ex = navscene({ "CRE DAL88 A321 41.5 -71.5 045 FL200 280", "CRE RYR4TK B738 50.8 4.0 135 FL240 270" },
    "destinations by city")
  if nav then
    check_eq(ex("please send DAL88 to Boston"), "DEST DAL88 KBOS")
    check_eq(ex("reroute DAL88 to Boston"), "DEST DAL88 KBOS")
    check_eq(ex("route RYR4TK to Charleroi please"), "DEST RYR4TK EBCI")
    check_eq(ex("Ryanair four tango kilo, send him to Ostend"), "DEST RYR4TK EBOS")
    asked(ex("route DAL88 to MERIT"), "a fix after 'to' is no destination")
    check_eq(ex("route DAL88 via MERIT and on to Boston"), "ADDWPT DAL88 MERIT ; DEST DAL88 KBOS")
  end
end

-- The clock in a list of steps: a factor said before its word after "then" ("pause, then 3x speed") is the
-- rate, and "run it and fast forward N" starts the clock and moves it on; "run it fast for N" stays one jump
do
  local _, ex = scene({ "CRE KLM77 B738 52 4 090 FL200 250" })
  check_eq(ex("freeze it, set seed 7, then 4x speed"), "HOLD ; SEED 7 ; DTMULT 4")
  check_eq(ex("pause and then 2 times speed please"), "HOLD ; DTMULT 2")
  check_eq(ex("right, run it and fast forward 90 seconds"), "OP ; FF 90")
  check_eq(ex("run the sim and ff 2 min"), "OP ; FF 120")
  check_eq(ex("run the simulation fast for 45 seconds"), "FF 45")
  asked(ex("pause, then speed"), "no factor said: asked")
end

-- Destinations and origins as researchers type them: an ICAO code in lower case straight after the word
-- ("orig eddf, dest eham"), and each place said before "as its origin/destination"; an unknown name asks
do
  local nav, ex = navscene({ "CRE KLM601 B738 51.0 6.0 300 FL250 280" }, "airports typed and said as")
  if nav then
    check_eq(ex("KLM601 orig eddf, dest eham"), "ORIG KLM601 EDDF ; DEST KLM601 EHAM")
    check_eq(ex("KLM601 destination is ebbr"), "DEST KLM601 EBBR")
    asked(ex("KLM601 destination lane"), "a word that is no airport code asks")
    check_eq(ex("give KLM601 Gatwick as its origin and Heathrow as its destination"),
      "ORIG KLM601 EGKK ; DEST KLM601 EGLL")
    check_eq(ex("KLM601 should get a route via SPY and Eindhoven as its destination"),
      "ADDWPT KLM601 SPY ; DEST KLM601 EHEH")
    asked(ex("give KLM601 Gatwick as its origin and Frobnitz as its destination"),
      "an unknown name asks")
  end
end

-- Several aircraft created in one request: a count of them before a colon ("two aircraft please: ...") is
-- no value when it matches the callsigns after it, "and then" opens the next one, values after "both" at
-- the end are every one's, "same level and speed" are the ones created before it; one left without a
-- level asks
do
  local _, ex = scene({})
  check_eq(ex("two aircraft please: AB1 A320 at 51.0 3.0 heading 045 FL200 250, and AB2 B738 at 51.5 3.0 heading 135 FL220 260"),
    "CRE AB1 A320 51 3 45 FL200 250 ; CRE AB2 B738 51.5 3 135 FL220 260")
  asked(ex("3 aircraft: AB1 A320 at 51.0 3.0 heading 045 FL200 250"), "three announced, one given")
  check_eq(ex("create AB1 A320 at 51.0 3.0 hdg 045 FL200 250 and then AB2 B738 at 51.5 3.0 hdg 135 FL220 260"),
    "CRE AB1 A320 51 3 45 FL200 250 ; CRE AB2 B738 51.5 3 135 FL220 260")
  check_eq(ex("two aircraft crossing: AB1 A320 at 51.0 3.0 heading 090 and AB2 A320 at 50.7 3.5 heading 000, both FL250 at 270 kts"),
    "CRE AB1 A320 51 3 90 FL250 270 ; CRE AB2 A320 50.7 3.5 0 FL250 270")
  check_eq(ex("create AB1, an A320, at 51.0 3.0 heading 090 at FL250 and 270 knots, and AB2, also an A320, at 51.0 4.0 heading 270, same level and speed"),
    "CRE AB1 A320 51 3 90 FL250 270 ; CRE AB2 A320 51 4 270 FL250 270")
  asked(ex("create AB1 A320 at 51.0 3.0 heading 090 and AB2 A320 at 50.7 3.5 heading 000 FL250 270 kts"),
    "the first one's level unsaid: asked")
end

-- A message or note for the screen: the text after "message ...:" or after "saying" / "that says", as typed;
-- "saying" with nothing after it asks
do
  local _, ex = scene({ "CRE KLM77 B738 52 4 090 FL200 250" })
  check_eq(ex("could you write a message for the pilots: break after this run"), "ECHO break after this run")
  check_eq(ex("observers, note the conflict between KLM77 and the tanker"):match("^ECHO"), nil)
  check_eq(ex("put a note on the screen saying trial 4 of 8"), "ECHO trial 4 of 8")
  check_eq(ex("display a message that says conflict block starts"), "ECHO conflict block starts")
  asked(ex("leave a message saying"), "no text: asked")
end

-- "step size" / "step length" is the simulation's time step (DT), a noun, never a jump of the clock
do
  local _, ex = scene({ "CRE KLM77 B738 52 4 090 FL200 250" })
  check_eq(ex("step size 0.25 s"), "DT 0.25")
  check_eq(ex("make the step length 1 second"), "DT 1")
  asked(ex("step size please"), "no value: asked")
end

-- CRECONFS against an aircraft named by its airline ("against the Lufthansa"): the target is that airline's
-- one aircraft and the values after it are read as with a callsign (the airline's words end the target;
-- this raised a Lua error before); bare values not straight after the target are asked about
do
  local _, ex = scene({ "CRE DLH4AX A320 52 4 090 FL300 280", "CRE KLM12 B738 52.5 4.5 180 FL300 280" })
  check_eq(ex("creconfs against the Lufthansa: INT1, A320, 90 degrees, cpa 1 nm, 200 s"),
    "CRECONFS INT1 A320 DLH4AX 90 1 200")
  check_eq(ex("conflict against the Lufthansa: INT2 B738 crossing at 60 degrees, passing 2 miles, los in 300 s"),
    "CRECONFS INT2 B738 DLH4AX 60 2 300")
  asked(ex("crecons the Lufthansa INT3 A320 270 1 180"), "bare values apart from the target")
end

-- A condition at a waypoint opening the clause after the callsign, "at" and the waypoint said by its ident,
-- spelled in the phonetic alphabet or by its navaid's name: the instruction runs there (AT acid wp DO) when the
-- waypoint is on the aircraft's route, "at" or "after" it, a heading too; a spelling that names no waypoint of
-- the route is asked about, naming the place (the spelled place was dropped before: the speed ran at once)
do
  local _, ex = scene({ "DEFWPT OKLAB 49.9 13.6", "DEFWPT VEMIS 50.1 14.0", "CRE CSA752 A319 49.85 13.30 050 FL140 280",
    "ADDWPT CSA752 OKLAB" })
  check_eq(ex("CSA seven five two, at Oscar Kilo Lima Alpha Bravo reduce speed two two zero"),
    "AT CSA752 OKLAB DO SPD CSA752 220")
  check_eq(ex("CSA seven five two, after Oscar Kilo Lima Alpha Bravo descend flight level one two zero"),
    "AT CSA752 OKLAB DO ALT CSA752 FL120")
  check(ex("CSA seven five two, at Victor Echo Mike India Sierra speed two two zero"):match("^ASK Which waypoint is VEMIS")
    ~= nil, "a spelled waypoint off the route: asked")
  asked(ex("CSA seven five two, at Oscar Kilo Lima speed two two zero"), "a spelling of no waypoint")
  check_eq(ex("CSA seven five two, after OKLAB turn left heading 300"), "AT CSA752 OKLAB DO HDG CSA752 300 LEFT")
end
do
  local _, ex = navscene({ "CRE AUA123 A320 48.50 15.60 110 FL110 270", "ADDWPT AUA123 WGM" },
    "a condition at a navaid said by its name")
  if ex then
    check_eq(ex("Austrian one two three, at Wagram descend flight level eight zero"), "AT AUA123 WGM DO ALT AUA123 FL80")
  end
end

-- "when able" / "when ready" before a direct-to said with a heading for the same aircraft: the direct-to is flown
-- later, when the pilot can; issued at once it would end the heading, so it is asked about. A level or a direct-to
-- alone "when able" is still given.
do
  local _, ex = scene({ "DEFWPT MADOR 48.4 16.9", "CRE EWG8TC A320 48.60 16.70 200 FL100 260", "ADDWPT EWG8TC MADOR" })
  check(ex("Eurowings eight tango charlie, fly heading one six zero, when ready proceed direct MADOR")
    :match("^ASK Should EWG8TC keep its heading") ~= nil, "heading now, direct-to later: asked")
  check_eq(ex("EWG8TC when able direct MADOR"), "DIRECT EWG8TC MADOR")
  check_eq(ex("EWG8TC direct MADOR, descend FL80 when able"), "DIRECT EWG8TC MADOR ; ALT EWG8TC FL80")
end

-- "start ... from file X": a scenario file to load (IC, confirmed first), never the clock started (OP); a file
-- name that is no scenario file is asked for
do
  local s, ex = scene({ "CRE KLM77 B738 52 4 090 FL200 250" })
  local r = graph.translate("start the afternoon exercise from file westbound.scn", { sim = s, mode = "offline" })
  check_eq(r.confirm and table.concat(r.confirm.commands, " ; "), "IC westbound.scn")
  check_eq(ex("start the afternoon exercise from file westbound"), "ASK Which scenario file should I load?")
  check_eq(ex("start the exercise"), "OP")
end

-- "conflict detection look ahead N minutes": detection names whose look-ahead is set, no switch; with an on or
-- off word it switches too
do
  local _, ex = scene({ "CRE KLM77 B738 52 4 090 FL200 250" })
  check_eq(ex("conflict detection lookahead two minutes"), "DTLOOK 120")
  check_eq(ex("enable conflict detection, look ahead two minutes"), "ASAS ON ; DTLOOK 120")
end

-- Greetings and thanks in the Central European languages ("dobrý den", "dzień dobry", "szia", "jó napot",
-- "děkuji") are courtesy, no words left over
do
  local _, ex = scene({ "CRE AUA456 B772 47.70 16.30 350 7000 210" })
  check_eq(ex("Austrian four five six, dobrý den, climb flight level one two zero"), "ALT AUA456 FL120")
  check_eq(ex("Austrian four five six, jó napot, climb flight level one two zero, děkuji"), "ALT AUA456 FL120")
  check_eq(ex("Austrian four five six, szia, turn left heading three two zero"), "HDG AUA456 320 LEFT")
end

-- "when reaching" alone after a level: the instruction waits for that level (ATALT); with no level before, asked
do
  local _, ex = scene({ "CRE SWR1530 A320 47.54 18.49 090 FL90 250" })
  check_eq(ex("Swiss one five three zero, climb flight level one two zero, when reaching increase speed two eight zero"),
    "ALT SWR1530 FL120 ; ATALT SWR1530 FL120 SPD SWR1530 280")
  asked(ex("Swiss one five three zero, when reaching increase speed two eight zero"),
    "no level to reach: asked")
end

-- "what is <callsign said in words> doing" shows the aircraft (POS), also when the callsign's reference takes in
-- the question's words
do
  local _, ex = scene({ "CRE LOT28 E195 51.30 20.70 010 FL130 270", "CRE WZZ1WA A321 52.40 19.80 090 FL100 250" })
  check_eq(ex("what is LOT two eight doing"), "POS LOT28")
  check_eq(ex("instructor: what is Wizz one whiskey alpha doing"), "POS WZZ1WA")
end

-- A distance from a navaid said by a two-word name ("ten miles from Zurich East") is ATDIST there
do
  local _, ex = navscene({ "CRE EDW12 A320 47.35 9.10 290 FL90 240" }, "distances from two-word navaid names")
  if ex then
    check_eq(ex("Edelweiss one two, twelve miles from Zurich East reduce speed two one zero"),
      "ATDIST EDW12 ZUE 12 SPD EDW12 210")
  end
end

-- Type names said as words ("Embraer one ninety five", "A three nineteen", "A three twenty one neo") where traffic
-- is set up with "new traffic", "set up" or "put" as well as "create"
do
  local _, ex = scene({ "CRE KLM77 B738 52 4 090 FL200 250" })
  check_eq(ex("new traffic: KLM88, A three nineteen, at 52.5 4.5, heading 180, FL150, 250 knots"),
    "CRE KLM88 A319 52.5 4.5 180 FL150 250")
  check_eq(ex("set up KLM89, Embraer one ninety five, at 52.6 4.6, heading 090, FL120, 240 knots"),
    "CRE KLM89 E195 52.6 4.6 90 FL120 240")
  check_eq(ex("put KLM90, A three twenty one neo, at 52.7 4.7, heading 270, FL140, 260 knots"),
    "CRE KLM90 A21N 52.7 4.7 270 FL140 260")
end

-- An instruction corrected by the next one of its family ("climb four thousand... negative, maintain seven
-- thousand") is not read: no question about the value taken back (a climb below the aircraft), the correction
-- stands; a value alone corrected under the same verb is still checked
do
  local _, ex = scene({ "CRE AUA456 B772 47.70 16.30 350 7000 210" })
  check_eq(ex("Austrian four five six, climb three thousand... negative, maintain seven thousand"), "ALT AUA456 7000")
  check_eq(ex("AUA456 descend 9000, correction, climb 9000"), "ALT AUA456 9000")
  check(ex("AUA456 descend 5000... correction, 9000"):match("^ASK AUA456 is at 7000 ft") ~= nil, "still a descent")
end

-- "put (in) X before/after Y": a waypoint put next to one of the route (ADDWPT), as with "add"; "put in X" with
-- no place beside it is asked
do
  local _, ex = scene({ "DEFWPT ROTAX 47.8 18.6", "DEFWPT ERGAN 47.9 18.9", "CRE WZZ2231 A21N 47.95 18.50 130 FL120 270",
    "ADDWPT WZZ2231 ERGAN" })
  check_eq(ex("Wizz two two three one, put in ROTAX before ERGAN"), "ADDWPT WZZ2231 ROTAX,,,,ERGAN")
  check_eq(ex("WZZ2231 put ROTAX after ERGAN"), "ADDWPT WZZ2231 ROTAX,,,ERGAN")
  asked(ex("Wizz two two three one, put in ROTAX"), "no place beside it: asked")
end

-- A level said after a correction replaces the level said before it, so it is never read as a step
-- ("climb 9000... correction, 5000" from 7000 is a climb to 5000: the verb contradicts it, asked; it
-- was cleared as 12000); without a correction a small typed amount after "climb" below the aircraft is asked
-- (to that level, or by that much?)
do
  local _, ex = scene({ "CRE AUA456 A320 48 16 090 7000 250" })
  check(ex("AUA456 climb 9000... correction, 5000"):match("^ASK .*climb to 5000") ~= nil, "corrected below")
  asked(ex("AUA456 climb 9000 feet, correction, 5000 feet"), "corrected below, in feet")
  check_eq(ex("AUA456 climb 9000, correction 8000"), "ALT AUA456 8000")
  check(ex("AUA456 climb 2000"):match("^ASK AUA456 is at 7000 ft: climb to 2000 ft, or by 2000 ft%?") ~= nil, "to or by")
end
-- Values written with slashes between ("280/FL250/250kt") are values apart, each accounted for; a fraction stays
-- whole and words with slashes are no values
do
  local _, ex = scene({ "CRE KLM77 B738 52 4 090 FL200 250" })
  check_eq(ex("BAW91 A320 51.5N 003.2E 120/FL240/260kt"), "CRE BAW91 A320 51.5 3.2 120 FL240 260")
  check_eq(ex("create DLH3 A321 52.1/4.4 hdg 200/fl180"), "CRE DLH3 A321 52.1 4.4 200 FL180")
  asked(ex("BAW92 A320 51.5N 003.2E 120/FL240/zz9"), "a part squawk cannot read is asked about")
end

-- "sim step 0.5 s": the simulation's step, a noun after "sim", is the time step; "step" alone with a time still
-- moves the clock on
do
  local _, ex = scene({ "CRE KLM77 B738 52 4 090 FL200 250" })
  check_eq(ex("sim step 0.2 s"), "DT 0.2")
  check_eq(ex("simulation step to 1 s"), "DT 1")
  check_eq(ex("step the sim 45 seconds"), "FF 45")
end

-- A question about what was done ("which one did we use yesterday?") is no instruction, whatever words it holds
do
  local _, ex = scene({ "CRE KLM77 B738 52 4 090 FL200 250" })
  check(ex("conflict resolution -- which method did Jan pick on Monday?"):find("question, no instruction", 1, true),
    "a question about the past: asked")
  asked(ex("did KLM77 get the descent to FL150?"), "asked")
  check_eq(ex("what's the reso method?"), "RESO")
end

-- "forget the KLM": an aircraft named after "forget" is left out of the request; when nothing is left, asked
do
  local _, ex = scene({ "CRE KLM77 B738 52 4 090 FL200 250", "CRE DLH4AX A321 52.4 4.4 090 FL300 280" })
  check_eq(ex("DLH4AX and KLM77 -- no, forget the KLM. Just DLH4AX heading 300"), "HDG DLH4AX 300")
  check_eq(ex("KLM77 and DLH4AX descend FL180, forget DLH4AX"), "ALT KLM77 FL180")
  asked(ex("KLM77 speed 220, forget about KLM77"), "nothing left: asked")
end

-- Aircraft described ("X and Y are level at 300", "the Lufthansa keeps FL300", "the KLM's there") are not
-- instructed by the description; a value said outside it, after another aircraft was addressed, is asked about;
-- the aircraft described alone still gets the instruction after it
do
  local _, ex = scene({ "CRE KLM77 B738 52 4 090 FL200 250", "CRE DLH4AX A321 52.4 4.4 090 FL300 280",
    "CRE BAW8CK A320 52.0 4.0 025 FL280 250" })
  check_eq(ex("KLM77 and DLH4AX are level at 300 on crossing tracks, good. Take BAW8CK up to 300 as well."),
    "ALT BAW8CK FL300")
  check_eq(ex("BAW8CK climb FL300 and the Lufthansa keeps FL300 -- the vertical geometry we want"), "ALT BAW8CK FL300")
  asked(ex("BAW8CK descend FL240... no wait, the KLM's there. Make it FL250"),
    "the correction after a described aircraft: asked")
  check_eq(ex("KLM77 is too low, climb FL240"), "ALT KLM77 FL240")
  check_eq(ex("DLH4AX is cleared to FL340"), "ALT DLH4AX FL340")
end

-- "direct X, FL340 at X": a level or speed tied to a waypoint in a direct's clause is asked about, never issued
-- at once
do
  local _, ex = scene({ "DEFWPT WPA 52.5 4.5", "CRE KLM77 B738 52 4 090 FL200 250" })
  check(ex("KLM77 direct WPA, FL240 at WPA"):find("Should that happen at WPA", 1, true), "asked")
  check_eq(ex("KLM77 direct WPA, FL240"), "ADDWPT KLM77 WPA ; DIRECT KLM77 WPA ; ALT KLM77 FL240")
end

-- Random traffic "all inbound X": X is MCRE's destination
do
  local _, ex = scene({ "DEFWPT WPA 52.5 4.5", "CRE KLM77 B738 52 4 090 FL200 250" })
  check_eq(ex("add 5 random B738s at FL250 doing 260 knots, all inbound WPA"), "MCRE 5 B738 FL250 260 WPA")
  check_eq(ex("add 5 random B738s at FL250, all inbound to WPA"), "MCRE 5 B738 FL250 * WPA")
end

-- Spanish and French phraseology: "rumbo"/"cap" heading, "nivel de vuelo"/"niveau" flight level, "descienda"/
-- "descendez", "suba"/"montez" before their values; French digits beside another digit; French courtesy words.
-- A word of them with no value after it stays a word and is asked about
do
  local _, ex = scene({ "CRE VLG1005 A320 41 1 090 FL350 280", "CRE TVF4120 B738 44 1 090 FL200 280" })
  check_eq(ex("Vueling uno cero cero cinco, rumbo uno cuatro cero"), "HDG VLG1005 140")
  check_eq(ex("VLG1005 descienda nivel de vuelo dos ocho cero"), "ALT VLG1005 FL280")
  check_eq(ex("France Soleil quatre un deux zero, montez niveau 240, merci"), "ALT TVF4120 FL240")
  check_eq(ex("TVF4120 cap 090, bonjour"), "HDG TVF4120 90")
  asked(ex("VLG1005 rumbo"), "no value: asked")
end

-- "asas dt 2 sec", "detection dt 1.5 s": conflict detection's interval (DT ASAS), never the simulation's time
-- step with detection switched on; without a value, asked
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 090 FL300 280" })
  check_eq(ex("asas dt 2 sec"), "DT ASAS 2")
  check_eq(ex("detection dt 1.5 s"), "DT ASAS 1.5")
  check_eq(ex("set the time step to 0.1 s"), "DT 0.1")
  asked(ex("asas dt"), "no interval said")
end

-- A level left or passed before a vertical speed, or before an imperative climb or descent with a rate
-- ("leaving 11000 descend at 1000 feet per minute", "leaving FL110 vertical speed 1000 down"): the rate
-- waits for the level (ATALT); it was read as the level to descend to, or dropped. A participle stays a
-- pilot's report ("passing FL355 descending FL340")
do
  local _, ex = scene({ "CRE JZA8156 DH8D 45 -75 090 13000 250" })
  check_eq(ex("JZA8156 leaving 11000 descend at 1000 fpm"), "ATALT JZA8156 11000 VS JZA8156 -1000")
  check_eq(ex("Jazz 8156 leaving one one thousand descend at one thousand feet per minute"),
    "ATALT JZA8156 11000 VS JZA8156 -1000")
  check_eq(ex("JZA8156 leaving FL110 vertical speed 1000 down"), "ATALT JZA8156 FL110 VS JZA8156 -1000")
  check_eq(ex("JZA8156 passing 11000 reduce speed 210"), "ATALT JZA8156 11000 SPD JZA8156 210")
end

-- A number said straight after an aircraft flying ("at" between or not) and closed by a comma or "and"
-- ("KLM12 330, turn left 090", "AEA6062 at 330, direct XING2") is a value said for it: carried or asked
-- about, never dropped in silence (numbers before any instruction were taken for callsign noise)
do
  local _, ex = scene({ "CRE AEA6062 B738 42 2 090 FL300 280", "DEFWPT XING2 42.2 2.5", "ADDWPT AEA6062 XING2",
    "CRE KLM12 B738 42 3 090 FL300 280" })
  check(ex("KLM12 330, turn left 090"):match("^ASK .*'330'") ~= nil, "a number before the instruction")
  check(ex("AEA6062 at 330, direct XING2"):match("^ASK .*'at 330'") ~= nil, "a number after 'at' before a direct")
  check(ex("KLM12 330 and turn left 090"):match("^ASK .*'330'") ~= nil, "a number before 'and'")
  check_eq(ex("KLM12 250 kts, turn left 090"), "SPD KLM12 250 ; HDG KLM12 90 LEFT")
end

-- A sim supervisor's label ("sup:", "sim sup:", "sup,") is no part of the request
do
  local _, ex = scene({ "CRE WJA88 B738 50 -100 090 FL300 280" })
  check_eq(ex("sup: pause the simulation"), "HOLD")
  check_eq(ex("sim sup: WestJet 88 climb FL340"), "ALT WJA88 FL340")
  check_eq(ex("sup, fast forward two minutes"), "FF 120")
  asked(ex("sup"), "a label alone says nothing")
end

-- The wrong value a pilot read back, named after the corrected instruction ("..., you said seven",
-- "..., readback was one one thousand"), is dropped; the instruction stands. Not at the start of a request,
-- nor with other words after the values
do
  local _, ex = scene({ "CRE ROU1766 A320 45 -75 090 FL200 280" })
  check_eq(ex("Rouge 1766 negative, climb and maintain flight level two four zero, you read back two two zero"),
    "ALT ROU1766 FL240")
  check_eq(ex("ROU1766 readback incorrect, turn left heading 150, you said 160."), "HDG ROU1766 150 LEFT")
  check_eq(ex("ROU1766 reduce speed 250, your readback was two six zero"), "SPD ROU1766 250")
  asked(ex("ROU1766 you said seven"), "no instruction before it")
  asked(ex("ROU1766 climb FL240, you said 220 so climb FL250"), "more after the values")
end

-- A Canadian registration said after the aircraft's maker or model without its C ("Cessna Foxtrot Alpha
-- Bravo Kilo" for the C172 C-FABK) is that aircraft when no aircraft is the four letters themselves; the
-- letters alone, another maker, or other nationality letters are still asked about
do
  local _, ex = scene({ "CRE CFABK C172 45 -75 090 3000 100", "CRE GOBCD C152 45.2 -75 090 3000 90" })
  check_eq(ex("Cessna Foxtrot Alpha Bravo Kilo turn right heading 120"), "HDG CFABK 120 RIGHT")
  check_eq(ex("Golf Oscar Bravo Charlie Delta descend 2500"), "ALT GOBCD 2500")
  asked(ex("Foxtrot Alpha Bravo Kilo climb to 4500"), "the letters alone")
  asked(ex("Piper Foxtrot Alpha Bravo Kilo climb to 4500"), "another maker")
  asked(ex("Cessna Oscar Bravo Charlie Delta descend 2500"), "no Canadian registration")
end

-- A new aircraft said with its airline whole and a flight number no aircraft of it has ("Jazz 7455" with
-- JZA7721 flying) is a new callsign, no slip: "new target, ...", a request opening with it and its type; a
-- Boeing family said as its number ("seven forty-seven", "seven thirty-seven max eight") and "Airbus three
-- nineteen" are types where traffic is created
do
  local _, ex = scene({ "CRE JZA7721 DH8D 45 -75 090 9000 240", "CRE WJA12 B738 45.5 -75 090 FL250 280",
    "DEFWPT DOTTY 45.3 -75.3" })
  check_eq(ex("new target: Jazz 7310, DH8D, over DOTTY, heading 180, 8000, 220 knots"),
    "CRE JZA7310 DH8D DOTTY 180 8000 220")
  check_eq(ex("Jazz 7310, DH8D, at DOTTY, heading 180, 8000, 220 knots"), "CRE JZA7310 DH8D DOTTY 180 8000 220")
  check_eq(ex("Jazz 7721 heading 180"), "HDG JZA7721 180")
  check_eq(ex("WJA12 new target altitude FL300"), "ALT WJA12 FL300")
  check_eq(ex("create WestJet 99, seven thirty-seven max eight, at DOTTY, heading 270, FL200, 280 knots"),
    "CRE WJA99 B38M DOTTY 270 FL200 280")
  check_eq(ex("create WestJet 99, Airbus three nineteen, at DOTTY, heading 270, FL200, 280 knots"),
    "CRE WJA99 A319 DOTTY 270 FL200 280")
  asked(ex("create WestJet 99, seven thirty seven, at DOTTY, heading 270, FL200, 280 knots"),
    "a family names no one variant")
end

-- An airline's ICAO code typed apart from its flight number where the request names the airline ("a Porter
-- Dash 8, POE 77"): one callsign; a code the request does not name stays apart and is asked about
do
  local _, ex = scene({ "CRE WJA12 B738 45.5 -75 090 FL250 280", "DEFWPT DOTTY 45.3 -75.3" })
  check_eq(ex("add a Porter DH8D, POE 77, at DOTTY, heading 090, 8000, 220 knots"), "CRE POE77 DH8D DOTTY 90 8000 220")
  asked(ex("add a DH8D, POE 77, at DOTTY, heading 090, 8000, 220 knots"), "no airline named")
end

-- "knock out" an aircraft, nothing after it: deleted; with an instruction after it, no deletion
do
  local _, ex = scene({ "CRE WJA12 B738 45.5 -75 090 FL250 280", "CRE CFABK C172 45 -75 090 3000 100" })
  check_eq(ex("sup: knock out WestJet 12"), "DEL WJA12")
  check_eq(ex("knock out the Cessna please"), "DEL CFABK")
  asked(ex("knock out WJA12 and climb"), "an instruction after it")
end

-- The conflict probe named as a look-ahead's owner; "triple speed"
do
  local _, ex = scene({ "CRE WJA88 B738 50 -100 090 FL300 280" })
  check_eq(ex("probe look-ahead three minutes"), "DTLOOK 180")
  check_eq(ex("set the look ahead on the conflict probe to 4 minutes"), "DTLOOK 240")
  asked(ex("probe WJA88"), "a probe with no look-ahead")
  check_eq(ex("triple speed please"), "DTMULT 3")
  check_eq(ex("run the sim at quadruple speed"), "DTMULT 4")
end

-- An airport said as its city and a part of its navdata name ("Montreal Mirabel" -> CYMX "MONTREAL INTL
-- MIRABEL", "Toronto City Centre" -> CYTZ beside the TORONTO VOR); a city whose large airports the navdata
-- names otherwise ("Montreal": CYMX, CYUL) is asked about, and so is a name the city does not hold
do
  local nav, ex = navscene({ "CRE ACA1 A320 45.3 -74.5 090 FL200 280", "CRE WJA2 B738 43.9 -79.9 090 FL200 280" },
    "airports said as city and name")
  if nav then
    check_eq(ex("ACA1 origin Montreal Mirabel"), "ORIG ACA1 CYMX")
    check_eq(ex("WJA2 destination Toronto City Centre"), "DEST WJA2 CYTZ")
    check_eq(ex("ACA1 destination Montreal"), "ASK Which airport is 'montreal': CYMX or CYUL?")
    check(ex("ACA1 destination Ottawa Trudeau"):match("^ASK .*'Trudeau'") ~= nil, "Trudeau is no Ottawa airport")
  end
  -- (an airport named after the city anchors it: KDCA lies 10 NM from KIAD "WASHINGTON DULLES INTL"; a word
  -- inside one airport's name names no city)
  nav, ex = navscene({ "CRE ACA4 A320 38.8 -77.3 090 FL200 280", "CRE AAL2 A321 41.5 -87.5 090 FL200 280" },
    "airports said as city and name")
  if nav then
    check_eq(ex("ACA4 destination Washington Reagan"), "DEST ACA4 KDCA")
    asked(ex("AAL2 destination Ohare Midway"), "Ohare is no city")
  end
end

-- A crossing restriction at a distance from a place ("cross 12 miles west of YUL at 9000") is ATDIST there
-- with its level or speed; a place squawk does not know is asked about
do
  local nav, ex = navscene({ "CRE ACA1 A320 45.3 -74.5 090 FL200 280" }, "crossing restrictions at a distance")
  if nav then
    check_eq(ex("ACA1 cross one two miles west of YUL at 9000"), "ATDIST ACA1 YUL 12 ALT ACA1 9000")
    check_eq(ex("ACA1 cross 15 miles from YUL at 250 knots"), "ATDIST ACA1 YUL 15 SPD ACA1 250")
    check_eq(ex("ACA1 cross two five miles south east of YUL at one zero thousand"), "ATDIST ACA1 YUL 25 ALT ACA1 10000")
    check_eq(ex("ACA1 cross 18 DME west of YUL at 7000"), "ATDIST ACA1 YUL 18 ALT ACA1 7000")
    check(ex("ACA1 cross 20 miles from Gotham at 9000"):match("^ASK .*'Gotham'") ~= nil, "an unknown place")
  end
  -- (a city of two large airports, "Seattle": KSEA and KBFI, is the navaid of its name the route holds)
  nav, ex = navscene({ "CRE ASA9 B739 47.9 -122.4 180 FL200 280", "ADDWPT ASA9 SEA" }, "crossing restrictions at a distance")
  if nav then
    check_eq(ex("ASA9 cross one two miles north of Seattle at 9000"), "ATDIST ASA9 SEA 12 ALT ASA9 9000")
    check(ex("ASA9 destination Seattle"):match("^ASK Which airport") ~= nil, "two large airports")
  end
end

-- A place said after "over" that an airport other than a large one and a navaid beside it name under other
-- idents ("over Sherbrooke": the medium CYSC, the YSC VORTAC) is asked about where traffic is created; "at
-- Sherbrooke" is the airport, "the Sherbrooke VOR" the navaid, "over Ottawa" the large CYOW, "the Ottawa VOR"
-- the VOR YOW, not the DME IOW of that name
do
  local nav, ex = navscene({}, "places an airport and a navaid name")
  if nav then
    check(ex("create JZA55 DH8D over Sherbrooke heading 090 7000 200 knots"):match("^ASK Which place is meant") ~= nil,
      "airport or navaid")
    check_eq(ex("create JZA55 DH8D at Sherbrooke heading 090 7000 200 knots"), "CRE JZA55 DH8D CYSC 90 7000 200")
    check_eq(ex("create JZA55 DH8D over the Sherbrooke VOR heading 090 7000 200 knots"), "CRE JZA55 DH8D YSC 90 7000 200")
    check_eq(ex("where is the Ottawa VOR"), "POS YOW")
    check_eq(ex("create JZA55 DH8D over Ottawa heading 090 7000 200 knots"), "CRE JZA55 DH8D CYOW 90 7000 200")
  end
end

-- A correction with no instruction word before it that says its verb again ("add ALPHA then BRAVO, actually
-- just add CHARL at the end of the route"): the words from the verb's first saying are taken back
do
  local _, ex = scene({ "CRE WJA12 B738 45.5 -75 090 FL250 280", "DEFWPT ALPHA 45.6 -74.8", "DEFWPT BRAVO 45.7 -74.6",
    "DEFWPT CHARL 45.8 -74.4" })
  check_eq(ex("WJA12 add ALPHA then BRAVO, actually just add CHARL at the end of the route"), "ADDWPT WJA12 CHARL")
  check_eq(ex("WJA12 add ALPHA and BRAVO, sorry, add CHARL to the end of his route"), "ADDWPT WJA12 CHARL")
  asked(ex("WJA12 add ALPHA then BRAVO, actually just CHARL"), "no verb said again")
  -- (a correction whose "just" is followed by a verb before the aircraft, with no aircraft before it: asked)
  asked(ex("add the ALPHA gate... actually no, just give WJA12 the destination CYUL instead"),
    "a correction naming its aircraft after a verb")
end

-- A place corrected after the same word ("until ALPHA... correction, until BRAVO", "via ALPHA, sorry, via
-- BRAVO"): the first place is taken back; a place said after a correction without its word is still asked
do
  local _, ex = scene({ "CRE WJA12 B738 45.5 -75 090 FL250 280", "DEFWPT ALPHA 45.6 -74.8", "DEFWPT BRAVO 45.7 -74.6",
    "ADDWPT WJA12 ALPHA", "ADDWPT WJA12 BRAVO" })
  check_eq(ex("WJA12 maintain 270 knots until ALPHA... correction, until BRAVO"), "SPD WJA12 270")
  check_eq(ex("WJA12 proceed direct ALPHA, sorry, direct BRAVO"), "DIRECT WJA12 BRAVO")
  check(ex("WJA12 maintain 270 knots until ALPHA... correction, BRAVO"):match("^ASK .*'ALPHA'") ~= nil,
    "no word said again")
end
-- An experiment's label opening a sentence before the request ("exp ATC-NL-BE, run 4.", "Block C:",
-- "session 3, block B."): label words each with an identifier, set aside; one with a unit is no label,
-- and a label alone instructs nothing
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 090 FL300 280" })
  check_eq(ex("exp ATC-NL-BE, run 4. KLM12 climb FL340"), "ALT KLM12 FL340")
  check_eq(ex("Block C: KLM12 speed 250"), "SPD KLM12 250")
  check_eq(ex("session 3, block B. cre EZY9 A320 52.5 4.5 180 FL250 260"), "CRE EZY9 A320 52.5 4.5 180 FL250 260")
  check(ex("run 5 min. KLM12 climb FL340"):match("FF 300") ~= nil, "a time is no label")
  asked(ex("exp ATC-NL-BE, run 4."), "a label alone instructs nothing")
end

-- Route building in an experimenter's shorthand: "route KLM12: ALFA BRAVO" (the aircraft straight after
-- "route", places one after another), "KLM12 route ALFA then BRAVO", "KLM12: wpt ALFA", "add wpts ALFA and
-- BRAVO", a level and a bare speed with a comma between ("add ALFA at FL320, 280"), the aircraft after all
-- the values ("add ALFA at FL340 270 kt to KLM12"), "drop ALFA from KLM12" (DELWPT), "squeeze BRAVO in
-- after ALFA". A number that is no speed is still asked about, and an aircraft dropped is no waypoint.
do
  local _, ex = scene({ "DEFWPT ALFA 52.2 4.5", "DEFWPT BRAVO 52.4 4.9", "DEFWPT CHARL 52.6 5.2",
    "CRE KLM12 B738 52 4 090 FL300 280", "CRE EZY9 A320 52.5 4.5 180 FL250 260", "ADDWPT EZY9 ALFA",
    "ADDWPT EZY9 CHARL" })
  check_eq(ex("route KLM12: ALFA BRAVO CHARL"), "ADDWPT KLM12 ALFA ; ADDWPT KLM12 BRAVO ; ADDWPT KLM12 CHARL")
  check_eq(ex("KLM12 route ALFA then BRAVO"), "ADDWPT KLM12 ALFA ; ADDWPT KLM12 BRAVO")
  check_eq(ex("KLM12: wpt BRAVO then CHARL"), "ADDWPT KLM12 BRAVO ; ADDWPT KLM12 CHARL")
  check_eq(ex("KLM12 add wpts ALFA and CHARL"), "ADDWPT KLM12 ALFA ; ADDWPT KLM12 CHARL")
  check_eq(ex("KLM12: add BRAVO at FL320, 280"), "ADDWPT KLM12 BRAVO FL320 280")
  check(ex("KLM12: add BRAVO at FL320, 20"):match("^ASK .*'20'") ~= nil, "20 is no speed")
  check_eq(ex("add BRAVO at FL340 270 kt to KLM12"), "ADDWPT KLM12 BRAVO FL340 270")
  check_eq(ex("drop CHARL from EZY9"), "DELWPT EZY9 CHARL")
  check_eq(ex("take ALFA off the EZY9"), "DELWPT EZY9 ALFA")
  check_eq(ex("squeeze BRAVO in after ALFA on EZY9"), "ADDWPT EZY9 BRAVO,,,ALFA")
  check(ex("drop EZY9 from the list"):match("DELWPT") == nil, "an aircraft dropped is no waypoint")
end

-- A new aircraft's fields written with spaced slashes between ("EZY12 / A319 / 51.2 N 0.3 W / 270 /
-- FL120 / 250 kt"): each slash separates fields as a comma does
do
  local _, ex = scene({})
  check_eq(ex("EZY12 / A319 / 51.2 N 0.3 W / 270 / FL120 / 250 kt"), "CRE EZY12 A319 51.2 -0.3 270 FL120 250")
  check_eq(ex("KLM7 / B738 / 52.1 4.6 / hdg 090 / FL300 / 280"), "CRE KLM7 B738 52.1 4.6 90 FL300 280")
end

-- Words of an experimenter's aside beside an instruction: the effect a value should have said as "to"
-- and a verb with "it" or "them" ("to make it a triple", "to get them closer"), how hard a turn is flown
-- ("hard left"), "whatever type", a colleague in the room ("colleague's asking something"). A verb of an
-- instruction in that clause is still no aside, and a turn with no heading still asks.
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 090 FL300 280", "CRE EZY9 A320 52.5 4.5 180 FL250 260" })
  check_eq(ex("climb KLM12 to 340 to make it a quadruple"), "ALT KLM12 FL340")
  check_eq(ex("descend EZY9 to FL230 to get them closer"), "ALT EZY9 FL230")
  asked(ex("climb KLM12 to 340 to make it climb FL360"), "an instruction in the clause")
  check_eq(ex("KLM12 hard right heading 140"), "HDG KLM12 140 RIGHT")
  asked(ex("KLM12 turn hard"), "no heading")
  check_eq(ex("mcre 5, whatever type, FL280, 260 kt"), "MCRE 5 * FL280 260")
  asked(ex("KLM12, EZY9... whichever one is the A320, climb 360"), "a choice left open")
  check_eq(ex("pause the sim, colleague's got a question"), "HOLD")
end

-- Values written the way French and Spanish experimenters write them: a fraction of a mile in words
-- ("CPA half a mile", "a quarter of a mile": 0.5 and 0.25 nm) and a number with a space before its last
-- three digits when its unit follows ("8 500 m", "12 000 ft"); three digits before the space stay apart
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 090 FL300 280" })
  check_eq(ex("creconfs against KLM12: EZY3, A320, 90 degree angle, CPA half a mile, 200 s"),
    "CRECONFS EZY3 A320 KLM12 90 0.5 200")
  check_eq(ex("creconfs against KLM12: EZY3, A320, 45 degrees, cpa a quarter of a mile, 150 s"),
    "CRECONFS EZY3 A320 KLM12 45 0.25 150")
  check_eq(ex("KLM12 descend 7 500 m"), "ALT KLM12 24606")
  check_eq(ex("KLM12 descend 12 000 ft"), "ALT KLM12 12000")
  asked(ex("KLM12 heading 270 200 ft"), "a heading and a number apart")
end

-- A new aircraft's heading said as a number straight after its compass word ("northbound 010",
-- "westerly 260"): the number, when within 90 degrees of the point; one that is not is asked about
do
  local _, ex = scene({ "DEFWPT ALFA 52.2 4.5" })
  check_eq(ex("EZY3, A320, over ALFA, northbound 010, FL300 at 270"), "CRE EZY3 A320 ALFA 10 FL300 270")
  check_eq(ex("EZY3, A320, over ALFA, westerly 260, FL300 at 270"), "CRE EZY3 A320 ALFA 260 FL300 270")
  asked(ex("EZY3, A320, over ALFA, northbound 170, FL300 at 270"), "170 is no northbound heading")
end

-- A conflict set up with its intruder introduced as "new" or "new one" ("creconfs: new one EZY3, A320,
-- target KLM12, ..."): the new aircraft is the intruder, no creation of its own, and "one" no value
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 090 FL300 280" })
  check_eq(ex("creconfs: new one EZY3, A320, target KLM12, 60 degree angle, cpa 1 nm, 200 s"),
    "CRECONFS EZY3 A320 KLM12 60 1 200")
  check_eq(ex("creconfs: new EZY3, A320, target KLM12, 60 degree angle, cpa 1 nm, 200 s"),
    "CRECONFS EZY3 A320 KLM12 60 1 200")
  check(ex("creconfs: new one EZY3, A320, target KLM12, 60 degree angle, cpa 1 nm, 200 s, 7"):match("^ASK .*'7'")
    ~= nil, "a value left over")
end

-- Traffic information followed by an instruction after a comma ("traffic eleven o'clock, turn left 20
-- degrees"): the clause opening with an imperative verb (lexicon.clause_verbs) is an instruction; the
-- traffic's own description ("eastbound, altitude indicates FL330", "climbing through") instructs nobody
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 090 FL300 280" })
  check_eq(ex("KLM12, traffic ten o'clock, 6 miles, turn right 30 degrees"), "HDG KLM12 120 RIGHT")
  check_eq(ex("KLM12, traffic two o'clock opposite direction, descend FL280"), "ALT KLM12 FL280")
  check_eq(ex("KLM12 traffic two o'clock, 5 miles, eastbound, altitude indicates FL310"), "")
  check_eq(ex("KLM12 traffic one o'clock, climbing through FL290"), "")
end

-- "check KLM12": an aircraft alone after "check" (as after "show") is shown where it is; with more
-- said after it, it is no request to show
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 090 FL300 280" })
  check_eq(ex("check KLM12"), "POS KLM12")
  check(ex("check KLM12 is at FL310"):match("^POS") == nil, "a statement to check is no request to show")
end

-- Origin and destination written as one setting with a slash ("orig/dest KLM12: EHAM -> EGLL",
-- "origin/destination KLM12 EHAM EGLL"): the aircraft, then the two airports in that order; one airport
-- only is asked about
do
  local s, ex = navscene({ "CRE KLM12 B738 52 4 090 FL300 280" }, "orig/dest written as one setting")
  if s then
    check_eq(ex("orig/dest KLM12: EHAM -> EGLL"), "ORIG KLM12 EHAM ; DEST KLM12 EGLL")
    check_eq(ex("origin/destination KLM12 EHAM EGLL"), "ORIG KLM12 EHAM ; DEST KLM12 EGLL")
    asked(ex("orig/dest KLM12: EHAM"), "one airport for two settings")
  end
end

-- The traffic a turn is made toward ("turn left 20 into the easyJet", "turn right 30 towards EZY9") is
-- context, never instructed nor asked about
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 090 FL300 280", "CRE EZY9 A320 52.5 4.5 180 FL300 260" })
  check_eq(ex("KLM12 turn left 20 into the easyJet 9"), "HDG KLM12 70 LEFT")
  check_eq(ex("KLM12 turn right 30 towards EZY9"), "HDG KLM12 120 RIGHT")
  -- (the aircraft whose route a waypoint goes into is addressed: "insert ALFA into EZY9's route after BRAVO")
  local _, routed = scene({ "DEFWPT ALFA 52.2 4.5", "DEFWPT BRAVO 52.4 4.9", "CRE EZY9 A320 52.5 4.5 180 FL300 260",
    "ADDWPT EZY9 BRAVO" })
  check_eq(routed("insert ALFA into EZY9's route after BRAVO"), "ADDWPT EZY9 ALFA,,,BRAVO")
  local r = ex("KLM12 turn left 20 into EZY9 and EZY9 climb FL340")
  check(r:match("^ASK") ~= nil or r == "HDG KLM12 70 LEFT ; ALT EZY9 FL340", "EZY9's climb never given to KLM12: " .. r)
end

-- Conflict resolution's safety factor said as a margin in percent ("give the horizontal resolutions a 20
-- percent margin": RFACH 1.2); a margin with no percent, or with no direction, is asked about
do
  local _, ex = scene({})
  check_eq(ex("give the horizontal resolutions a 15 percent margin"), "RFACH 1.15")
  check_eq(ex("give the horizontal resolutions a 25% margin"), "RFACH 1.25")
  check_eq(ex("vertical resolution margin factor 1.08"), "RFACV 1.08")
  asked(ex("give the horizontal resolutions a 20 margin"), "no percent")
  asked(ex("give the resolutions a 20 percent margin"), "no direction")
end

-- "point KLM12 at the Spijkerboor VOR": a navaid said by its name with its kind after it, after "point ...
-- at", is flown to directly, as its code is; a name alone there is still asked about
do
  local s, ex = navscene({ "CRE KLM12 B738 52 4 090 FL300 280" }, "pointing at a navaid by its name")
  if s then
    check_eq(ex("point KLM12 at the Spijkerboor VOR"), "ADDWPT KLM12 SPY ; DIRECT KLM12 SPY")
    asked(ex("point KLM12 at the Nowhereville VOR"), "no such navaid")
  end
end

-- A Mach number said with no verb straight after a level passed or reached ("climb FL360, passing FL340
-- Mach .80", "when passing FL340 M.80") waits for that level (ATALT); after "reaching" alone ("on reaching
-- Mach .80") for the level just cleared; said with no condition it is a speed at once
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 090 FL300 280" })
  check_eq(ex("KLM12 climb FL360, passing FL340 Mach .80"), "ALT KLM12 FL360 ; ATALT KLM12 FL340 SPD KLM12 M0.8")
  check_eq(ex("KLM12 climb FL360 when passing FL340 M.80, heading 120"),
    "ALT KLM12 FL360 ; ATALT KLM12 FL340 SPD KLM12 M0.8 ; HDG KLM12 120")
  check_eq(ex("KLM12 climb FL360, on reaching Mach .80"), "ALT KLM12 FL360 ; ATALT KLM12 FL360 SPD KLM12 M0.8")
  check_eq(ex("KLM12 descend FL240, reaching reduce 250 knots"), "ALT KLM12 FL240 ; ATALT KLM12 FL240 SPD KLM12 250")
  check_eq(ex("KLM12 climb FL360 Mach .80"), "ALT KLM12 FL360 ; SPD KLM12 M0.8")
  -- (a level after "passing" with no instruction before it, "KLM12 passing FL340 Mach .80", is no level to fly)
  asked(ex("KLM12 passing FL340 Mach .80"), "a level passed")
  check_eq(ex("KLM12 passing FL340 reduce 250 knots"), "ATALT KLM12 FL340 SPD KLM12 250")
  -- (a report asked for is no condition of the Mach said after it)
  check(ex("KLM12 climb FL360 report reaching, Mach .80"):find("ATALT", 1, true) == nil, "a report asked for")
end

-- A climb or descent to be level by a waypoint of the route ("descend FL240 level by ALFA", "descend to
-- reach FL240 by ALFA", "be level FL240 by ALFA"): the level cleared now and the AT constraint there (the
-- constraint alone moves an aircraft with VNAV off nowhere); with VNAV on, a descent is the constraint alone,
-- which VNAV plans to meet. A waypoint off the route, or another value said after it, is asked about
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 090 FL300 280", "DEFWPT ALFA 52.1 4.5", "DEFWPT BRAVO 52.3 4.9",
    "ADDWPT KLM12 ALFA" })
  local both = "ALT KLM12 FL240 ; AT KLM12 ALFA ALT FL240"
  check_eq(ex("KLM12 descend FL240 level by ALFA"), both)
  check_eq(ex("KLM12 descend to reach FL240 by ALFA"), both)
  check_eq(ex("KLM12, be level FL240 by ALFA"), both)
  check_eq(ex("KLM12 descend FL240 to be level at ALFA"), both)
  check_eq(ex("klm12 desc FL240 to be lvl by ALFA"), both)
  check_eq(ex("KLM12 descend FL240, to be level by ALFA"), both)
  asked(ex("KLM12 descend FL240 by ALFA"), "no 'level' or 'reach': by the waypoint or a change?")
  asked(ex("KLM12 descend FL240 level by BRAVO"), "BRAVO is off the route")
  asked(ex("KLM12 descend FL240 level by ALFA 250 knots"), "a speed after the waypoint")
  local _, vx = scene({ "CRE KLM12 B738 52 4 090 FL300 280", "DEFWPT ALFA 52.1 4.5", "ADDWPT KLM12 ALFA",
    "VNAV KLM12 ON" })
  check_eq(vx("KLM12 descend FL240 level by ALFA"), "AT KLM12 ALFA ALT FL240")
  check_eq(vx("KLM12 climb FL340 level by ALFA"), "ALT KLM12 FL340 ; AT KLM12 ALFA ALT FL340")
end

-- A navaid said exactly by its name near the aircraft ("direct Pampus": PAM) is that navaid, before a
-- waypoint of the route that only sounds like it (PAMPAS); the waypoint said as spelled stays the waypoint
do
  local s, ex = navscene({ "CRE KLM12 B738 52 4 090 FL300 280", "DEFWPT PAMPAS 52.1 4.3", "ADDWPT KLM12 PAMPAS" },
    "a navaid's name before a sound-alike waypoint")
  if s then
    check_eq(ex("KLM12 direct Pampus"), "ADDWPT KLM12 PAM ; DIRECT KLM12 PAM")
    check_eq(ex("KLM12 direct PAMPAS"), "DIRECT KLM12 PAMPAS")
  end
end

-- A clause of its own after an instruction's value, "at", a route waypoint and a value straight after it, no
-- verb ("descend FL260, at ALFA FL240", "... then at ALFA 250 knots"): a constraint there (AT); a waypoint off
-- the route is still asked about; an instruction there with a verb starts there (AT DO)
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 090 FL300 280", "DEFWPT ALFA 52.1 4.5", "DEFWPT BRAVO 52.3 4.9",
    "ADDWPT KLM12 ALFA" })
  check_eq(ex("KLM12 descend FL260, at ALFA FL240"), "ALT KLM12 FL260 ; AT KLM12 ALFA ALT FL240")
  check_eq(ex("KLM12 descend FL260 then at ALFA 250 knots"), "ALT KLM12 FL260 ; AT KLM12 ALFA SPD 250")
  asked(ex("KLM12 descend FL260, at BRAVO FL240"), "BRAVO is off the route")
  check_eq(ex("KLM12 descend FL260, at ALFA turn left heading 200"), "ALT KLM12 FL260 ; AT KLM12 ALFA DO HDG KLM12 200 LEFT")
  asked(ex("KLM12 descend FL260, at ALFA FL240, 250 knots"), "a speed in a clause after it")
  -- (after a direct-to, "at ALFA FL240" is asked about, never a level given now)
  asked(ex("KLM12 direct ALFA, at ALFA FL240"), "a level at the waypoint flown to")
end

-- "when level" before a heading after a climb or descent ("descend FL260 and when level turn right heading
-- 140"): it waits for the level (ATALT), as a speed does; a turn by degrees there is asked about, and "then"
-- alone lists the next instruction
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 090 FL300 280" })
  check_eq(ex("KLM12 descend FL260 and when level turn right heading 140"),
    "ALT KLM12 FL260 ; ATALT KLM12 FL260 HDG KLM12 140 RIGHT")
  check_eq(ex("KLM12 descend FL260, when level reduce 250 knots"), "ALT KLM12 FL260 ; ATALT KLM12 FL260 SPD KLM12 250")
  asked(ex("KLM12 descend FL260, when level turn left 20 degrees"), "a turn by degrees")
  check_eq(ex("KLM12 descend FL260 then turn left heading 200"), "ALT KLM12 FL260 ; HDG KLM12 200 LEFT")
end

-- A distance from a place opening the clause of a second instruction of the same kind ("descend FL260, 20
-- miles before ALFA descend FL240"): the second waits for it (ATDIST), the first runs now; a distance past
-- a place is no such condition and is asked about
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 090 FL300 280", "DEFWPT ALFA 52.1 4.5", "ADDWPT KLM12 ALFA" })
  check_eq(ex("KLM12 descend FL260, 20 miles before ALFA descend FL240"),
    "ALT KLM12 FL260 ; ATDIST KLM12 ALFA 20 ALT KLM12 FL240")
  check_eq(ex("KLM12 descend FL260, at 20 miles from ALFA reduce 250 knots"),
    "ALT KLM12 FL260 ; ATDIST KLM12 ALFA 20 SPD KLM12 250")
  asked(ex("KLM12 descend FL260, 20 miles past ALFA descend FL240"), "past a place")
  -- (a level to be reached by a distance before a place is no condition of reaching that distance)
  asked(ex("KLM12 descend to be level FL240 20 miles before ALFA"), "level by a distance")
  asked(ex("KLM12 descend FL240, level 20 miles before ALFA"), "level by a distance")
end

-- Telephony designators of TUI's airlines said in full ("tuijet" TUI, "beauty" JAF), before any verb: the
-- aircraft of that airline and flight number
do
  local _, ex = scene({ "CRE TUI7RB B738 52 4 090 FL300 280", "CRE JAF2PL B738 52.3 4.3 180 FL320 280" })
  check_eq(ex("remove tuijet seven romeo bravo"), "DEL TUI7RB")
  check_eq(ex("beauty 2PL descend FL280"), "ALT JAF2PL FL280")
  asked(ex("remove tuijet 9ZZ"), "no such TUI flight")
end

-- "say again your speed": the controller asking the aircraft to say its own value again is a report asked
-- for (POS), as "say your speed" is; "say again the level" stays a question back, asked about
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 090 FL300 280" })
  check_eq(ex("KLM12 say again your level"), "POS KLM12")
  check_eq(ex("KLM12, say again your heading please"), "POS KLM12")
  asked(ex("KLM12 say again the level"), "a pilot's question back")
end

-- "pop up N random aircraft": random traffic (MCRE), as "spawn" is; "pop up" with a callsign creates it
do
  local _, ex = scene({})
  check_eq(ex("pop up twelve random aircraft"), "MCRE 12")
  check_eq(ex("pop up KLM12 B738 at 52 4 heading 090 FL300 250 knots"), "CRE KLM12 B738 52 4 90 FL300 250")
end

-- Route waypoints listed after a removal ("delete ALFA and BRAVO", "remove ALFA, BRAVO"): each removed; one
-- off the route is asked about
do
  local _, ex = scene({ "DEFWPT ALFA 52.1 4.5", "DEFWPT BRAVO 52.3 4.9", "DEFWPT CHARL 52.5 5.2",
    "CRE KLM12 B738 52 4 090 FL300 280", "ADDWPT KLM12 ALFA", "ADDWPT KLM12 BRAVO" })
  check_eq(ex("KLM12 delete ALFA and BRAVO"), "DELWPT KLM12 ALFA ; DELWPT KLM12 BRAVO")
  check_eq(ex("KLM12 remove ALFA, BRAVO, then climb FL320"), "DELWPT KLM12 ALFA ; DELWPT KLM12 BRAVO ; ALT KLM12 FL320")
  asked(ex("KLM12 delete ALFA and CHARL"), "CHARL is off the route")
end

-- "rejoin own navigation at BRAVO": the waypoint the route is rejoined at is flown to directly, as after
-- "rejoin the route at"; with no waypoint it is LNAV
do
  local _, ex = scene({ "DEFWPT ALFA 52.1 4.5", "DEFWPT BRAVO 52.3 4.9", "CRE KLM12 B738 52 4 090 FL300 280",
    "ADDWPT KLM12 ALFA", "ADDWPT KLM12 BRAVO", "LNAV KLM12 OFF" })
  check_eq(ex("KLM12 rejoin own navigation at BRAVO"), "DIRECT KLM12 BRAVO")
  check_eq(ex("KLM12 rejoin your own navigation at BRAVO, descend FL280"), "DIRECT KLM12 BRAVO ; ALT KLM12 FL280")
  check_eq(ex("KLM12 rejoin own navigation"), "LNAV KLM12 ON")
end

-- A level said after "until" ends the instruction before it: after a vertical rate ("climb FL360 rate 2000 or
-- greater until passing FL340") the rate is held to the level cleared; after a speed ("maintain Mach .80
-- until passing FL340") it is asked about, never a level to fly
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 090 FL300 280" })
  check_eq(ex("KLM12 climb FL360 rate 2000 or greater until passing FL340"), "ALT KLM12 FL360 2000")
  check_eq(ex("KLM12 climb FL360, 1500 fpm until reaching FL340"), "ALT KLM12 FL360 1500")
  local r = ex("KLM12 maintain Mach .80 until passing FL340")
  check(r:match("^ASK") ~= nil and r:find("until passing", 1, true) ~= nil, r)
  -- (with no level cleared before it, the level after "until" is the one to fly)
  check(ex("KLM12 rate of descent 2000 feet per minute until FL260"):find("FL260", 1, true) ~= nil, "the level to fly")
end
-- A speed to hold "by the time" a level is passed, said after it ("should be at 230 knots by the time it
-- reaches FL150", "speed 240 by FL120"): the speed waits for the level (ATALT), no level clearance; a moment
-- that is no level ("by the time it's established") is asked about
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 090 FL300 280" })
  check_eq(ex("KLM12 should be doing 230 knots by the time it's through FL150"), "ATALT KLM12 FL150 SPD KLM12 230")
  check_eq(ex("KLM12 reduce to 230 kt by the time it reaches FL150"), "ATALT KLM12 FL150 SPD KLM12 230")
  check_eq(ex("KLM12 reduce to 230 kt by the time it gets to FL150"), "ATALT KLM12 FL150 SPD KLM12 230")
  check_eq(ex("KLM12 speed 240 by FL120"), "ATALT KLM12 FL120 SPD KLM12 240")
  check_eq(ex("KLM12 descend by 3000 feet"), "ALT KLM12 27000")
  asked(ex("KLM12 230 knots by the time it's established"), "no level to wait for")
end

-- The clock started by "go on" or "keep going" said as a clause of its own ("fine, go on, and run at 3x")
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 090 FL300 280" })
  check_eq(ex("fine, go on, and run at 3x"), "OP ; DTMULT 3")
  check_eq(ex("alright, keep going, then fast forward 2 minutes"), "OP ; FF 120")
  check_eq(ex("go on"), "OP")
  check_eq(ex("KLM12 go on heading 120"), "HDG KLM12 120")
end

-- An airspace designer's words for putting a design to the test ("we're evaluating reduced separation", "a
-- freighter", "a quick look"): no instruction of their own; a note said to need no action is the speaker's
-- own, no text for the log, and what it names is still accounted for or asked about
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 090 FL300 280" })
  check_eq(ex("We're evaluating closer spacing, so set the horizontal separation radius to 4 miles"), "ZONER 4")
  check_eq(ex("Quick check before we start: what's on KLM12's route?"), "LISTRTE KLM12")
  check_eq(ex("create a B744 freighter, CLX7, at 52.1 4.3, heading 180, FL240, 260 knots"),
    "CRE CLX7 B744 52.1 4.3 180 FL240 260")
  check_eq(ex("designer's note, no action: KLM12 is the slow one. KLM12 climb FL320"), "ALT KLM12 FL320")
  asked(ex("note, no action: KLM12 flies the ZZZZZ branch. KLM12 climb FL320"),
    "a name in the note is asked about")
end

-- An airspace design's new points: a gate, entry or exit said new at a position is a waypoint defined
-- ("place the new arrival gate GATEN at ..."), and "it" after such a definition is the new waypoint
-- ("define NEWPT at ..., then slot it in before BRAVO"); a point with no name is asked about
do
  local _, ex = scene({ "DEFWPT BRAVO 52.4 4.9", "CRE EZY9 A320 52.5 4.5 180 FL300 260", "ADDWPT EZY9 BRAVO" })
  check_eq(ex("place the new arrival gate GATEN at 52.9 4.8"), "DEFWPT GATEN 52.9 4.8")
  check_eq(ex("create a new exit EXITW at 52.1 3.5"), "DEFWPT EXITW 52.1 3.5")
  check_eq(ex("define NEWPT at 52.45 4.7, then slot it in before BRAVO on EZY9"),
    "DEFWPT NEWPT 52.45 4.7 ; ADDWPT EZY9 NEWPT,,,,BRAVO")
  check_eq(ex("define NEWPT 52.45 4.7 and put it after BRAVO on EZY9"), "DEFWPT NEWPT 52.45 4.7 ; ADDWPT EZY9 NEWPT,,,BRAVO")
  asked(ex("place the new gate at 52.9 4.8"), "a gate with no name")
  asked(ex("put it after BRAVO on EZY9"), "'it' with nothing defined")
end

-- Small set-up phrasings of a test conductor: the route "given" to the speaker is shown; a level left
-- with the one it is cleared to ("leave FL140 for 8000 feet"); how an aircraft came to be, said as the
-- reason for deleting it, is no creation, nor "place" a noun a move; ZONER's name typed apart ("zone r")
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 090 FL140 280", "CRE EZY9 A320 52.5 4.5 180 FL300 260" })
  check_eq(ex("give me the route of KLM12"), "LISTRTE KLM12")
  check_eq(ex("KLM12 leave FL140 for 8000 feet"), "ALT KLM12 8000")
  asked(ex("KLM12 leave FL140"), "a level left with none to go to")
  check_eq(ex("remove EZY9, it was generated at the wrong level"), "DEL EZY9")
  check_eq(ex("delete KLM12, it's sitting in the wrong place"), "DEL KLM12")
  check_eq(ex("zone r 6 nm and zone dh 1200 ft"), "ZONER 6 ; ZONEDH 1200")
  check_eq(ex("KLM12 r 30"), "HDG KLM12 120 RIGHT")
end

-- An airport setting said with the one it replaces after "not", "instead of" or "rather than" ("origin
-- EDDM, not EDDF"): the first is set, the replaced one no candidate; said with no other airport, asked
-- about; and a value said apologetically twice ("... in decimal, if it helps") is courtesy
do
  local _, ex = navscene({ "CRE DLH4 A320 50.5 9.0 090 FL200 250", "ORIG DLH4 EDDF" }, "airports replaced")
  if ex then
    check_eq(ex("DLH4's origin should be EDDM, not EDDF"), "ORIG DLH4 EDDM")
    check_eq(ex("DLH4 destination EDDH rather than EDDL"), "DEST DLH4 EDDH")
    asked(ex("DLH4's origin should not be EDDF"), "only the replaced airport")
  end
  local _, ex2 = scene({})
  check_eq(ex2("new fix GAMMA at 52 30.0 N 4 15.0 E, that's 52.5 4.25 in decimal if that helps"), "DEFWPT GAMMA 52.5 4.25")
end

-- A crossing restriction with a bare number in hundreds of feet ("cross BRAVO at 7000"), BRAVO on the
-- route, is its level (`AT ... ALT`); a bare number under 1000 ("cross BRAVO at 240") is still asked about
do
  local _, ex = scene({ "DEFWPT BRAVO 52.4 4.9", "CRE EZY9 A320 52.5 4.5 180 FL100 260", "ADDWPT EZY9 BRAVO" })
  check_eq(ex("EZY9 cross BRAVO at 7000"), "AT EZY9 BRAVO ALT 7000")
  asked(ex("EZY9 cross BRAVO at 240"), "a bare number under 1000 at a crossing")
end

-- An airport's own navdata name said elsewhere in the request than beside its code ("one more departure out
-- of Schiphol: KLM9 ... at EHAM") is accounted for by the code issued; another airport's name is asked about
do
  local s, ex = navscene({}, "an airport's name apart from its code")
  if s then
    check_eq(ex("one more departure out of Schiphol: KLM9 B738 at EHAM heading 240 altitude 3000 ft speed 200"),
      "CRE KLM9 B738 EHAM 240 3000 200")
    asked(ex("one more departure out of Eindhoven: KLM9 B738 at EHAM heading 240 altitude 3000 ft speed 200"),
      "another airport's name")
  end
end

-- A direction word straight after a vertical speed's number gives its sign ("vertical speed 1500 descending",
-- "vs 1500 descent"); a climbing word keeps it positive
do
  local _, ex = scene({ "CRE LAN77 A320 -33 -70.8 090 FL150 250" })
  check_eq(ex("LAN77 vertical speed 1500 descending"), "VS LAN77 -1500")
  check_eq(ex("LAN77 vs 2000 descent"), "VS LAN77 -2000")
  check_eq(ex("LAN77 vertical speed 1200 climbing"), "VS LAN77 1200")
  check_eq(ex("LAN77 vertical speed 1500 descending to FL100"), "VS LAN77 -1500 ; ALT LAN77 FL100")
end

-- "when you reach (it)", "once it reaches that" opening the clause after a level cleared wait for that level,
-- as "when reaching" does
do
  local _, ex = scene({ "CRE LAN78 A320 -33 -70.8 090 FL150 250" })
  check_eq(ex("LAN78 descend FL100 and when you reach it reduce 220"), "ALT LAN78 FL100 ; ATALT LAN78 FL100 SPD LAN78 220")
  check_eq(ex("LAN78 climb FL190, once it reaches that, turn left heading 200"),
    "ALT LAN78 FL190 ; ATALT LAN78 FL190 HDG LAN78 200 LEFT")
  check_eq(ex("LAN78 descend FL100, when reaching reduce 220"), "ALT LAN78 FL100 ; ATALT LAN78 FL100 SPD LAN78 220")
end

-- Cycle 28 (R60, instructors of ab-initio courses in South America, English their second language).
-- South American airlines by the names said there: "JetSMART 77", "the Flybondi", "the Sky" (one flying);
-- "the LATAM" with two of the brand flying (TAM and LAN) asks which
do
  local _, ex = scene({ "CRE JAT77 A320 -33.2 -70.5 180 FL150 250", "CRE FBZ10 B738 -34.5 -58.7 090 FL120 250",
    "CRE TAM20 A320 -23.5 -46.6 030 FL200 280", "CRE LAN30 A321 -33.5 -70.9 350 FL180 270",
    "CRE SKU40 A320 -33.1 -71.0 200 FL100 240" })
  check_eq(ex("JetSMART 77 descend FL100"), "ALT JAT77 FL100")
  check_eq(ex("could the Flybondi climb FL160"), "ALT FBZ10 FL160")
  check_eq(ex("Sky 40 turn left heading 170"), "HDG SKU40 170 LEFT")
  check_eq(ex("slow the Sky to 210 knots"), "SPD SKU40 210")
  check(ex("the LATAM descend FL150"):match("^ASK Which LATAM") ~= nil, "two LATAM aircraft")
  -- (an airline capitalised after "for", ending its clause, is its one aircraft; two of it, asked)
  check_eq(ex("climb FL190 for Flybondi"), "ALT FBZ10 FL190")
  asked(ex("climb FL190 for LATAM"), "two LATAM aircraft after 'for'")
end
-- ... and a name that is also a fix far from the traffic (LATAM, a fix in France) is the airline
do
  local _, ex = navscene({ "CRE TAM21 A320 -23.5 -46.6 030 FL200 280", "CRE GLO22 B738 -23.3 -46.2 210 FL200 280" },
    "an airline's name that is a far fix")
  if ex then
    check_eq(ex("turn the LATAM left ten degrees"), "HDG TAM21 20 LEFT")
    check_eq(ex("GLO22 turn right heading 250 to avoid the LATAM"), "HDG GLO22 250 RIGHT")
  end
end

-- A level said after "at" in a sentence of its own before the instruction ("both at FL150 head on. X turn
-- ...") describes the traffic: no level is given; any other value there is asked about
do
  local _, ex = scene({ "CRE TAM88 A320 -23.4 -45.9 270 FL150 280", "CRE GLO89 B738 -23.4 -47.3 090 FL150 280" })
  check_eq(ex("look: they are both at FL150. TAM88 turn left 20 degrees"), "HDG TAM88 250 LEFT")
  check_eq(ex("FL130. TAM88 turn left 20 degrees"), "ASK I have HDG TAM88 250 LEFT. What does 'fl 130' mean?")
  check_eq(ex("TAM88 FL160 turn left 20 degrees"), "ALT TAM88 FL160 ; HDG TAM88 250 LEFT")
end

-- A bare number of three digits after "turn" and a side, no "heading" ("turn right 150" from 090): heading
-- 150 or a turn of 150 degrees? Asked. "onto 150", typed shorthand ("r 150") and a leading zero are headings
do
  local _, ex = scene({ "CRE LAN9 A320 -33.0 -71.0 090 FL150 250" })
  check_eq(ex("LAN9 turn right 150"), "ASK Should LAN9 turn right by 150 degrees, or fly heading 150?")
  check_eq(ex("LAN9 turn right onto 150"), "HDG LAN9 150 RIGHT")
  check_eq(ex("lan9 r 150"), "HDG LAN9 150 RIGHT")
  check_eq(ex("LAN9 turn right 120"), "ASK Should LAN9 turn right by 120 degrees, or fly heading 120?")
  check_eq(ex("LAN9 turn right 15"), "HDG LAN9 105 RIGHT")
  check_eq(ex("LAN9 turn right heading 150"), "HDG LAN9 150 RIGHT")
end

-- "climb 2000 feet" at FL200 with no "by" (to a level below, or by that much?) is asked, for one aircraft or
-- several ("both climb 2000 feet"); "by" said, each climbs that much
do
  local _, ex = scene({ "CRE ARG1 B738 -34.0 -60.0 090 FL200 280", "CRE ARG2 B738 -34.5 -59.0 270 FL200 280" })
  asked(ex("ARG1 climb 2000 feet"), "a climb to below the aircraft, no 'by': to or by?")
  check(ex("both climb 2000 feet"):match("^ASK Should ARG1 and ARG2 each climb by 2000 ft") ~= nil, "a step for two")
  check_eq(ex("both climb by 2000 feet"), "ALT ARG1 22000 ; ALT ARG2 22000")
end

-- The look-ahead set "for the detection", the setting said up to ten words before, switches nothing on
do
  local _, ex = scene({})
  check_eq(ex("look ahead time of 4 minutes for the conflict detection"), "DTLOOK 240")
  check_eq(ex("switch on detection and look ahead 4 minutes"), "ASAS ON ; DTLOOK 240")
end

-- A city named as a destination with no airport of its name near the aircraft is the region's: the one
-- bearing the name, else beside navaids of the name ("Cordoba" from Chile: SACO by the CORDOBA VOR, never
-- LEBA "CORDOBA" in Spain); several of the region are asked about; the place shown likewise; a created
-- aircraft's destination is looked for from where it is created
do
  local _, ex = navscene({ "CRE LAN31 A320 -33.0 -71.5 090 FL200 280", "CRE GLO32 B738 -23.6 -46.7 200 FL150 280" },
    "a destination in the aircraft's region")
  if ex then
    check_eq(ex("LAN31 destination Cordoba"), "DEST LAN31 SACO")
    check_eq(ex("where is Cordoba airport?"), "POS SACO")
    check_eq(ex("GLO32 destination Porto Alegre"), "ASK Which airport is 'Porto Alegre': SBCO or SBPA?")
    check_eq(ex("create LAN801 A320 at SCEL heading 090 FL100 250, destination Cordoba"),
      "CRE LAN801 A320 SCEL 90 FL100 250 ; DEST LAN801 SACO")
  end
  local _, ex2 = navscene({ "CRE IBE5 A320 40.4 -3.6 180 FL200 280" }, "a destination near the aircraft")
  if ex2 then check_eq(ex2("IBE5 destination Cordoba"), "DEST IBE5 LEBA") end
end

-- An airport said as such by its city's navaids ("show me Ezeiza airport": SAEZ "MINISTRO PISTARINI" by the
-- EZEIZA VOR) is shown; where an aircraft "will land at" or "should go to" an airport is its destination,
-- the one said after "not" replaced; "land at" alone is a landing clearance, asked
do
  local _, ex = navscene({ "CRE FBZ9 B738 -34.6 -58.2 270 FL080 250" }, "airports by their city's navaids")
  if ex then
    check_eq(ex("show me Ezeiza airport"), "POS SAEZ")
    check_eq(ex("FBZ9 will land at Ezeiza, not Aeroparque"), "DEST FBZ9 SAEZ")
    check_eq(ex("FBZ9 should go to Rosario"), "DEST FBZ9 SAAR")
    asked(ex("FBZ9 land at Rosario"), "a landing clearance alone")
  end
end

-- Spanish and Portuguese discourse markers and words for the class, said in English ("bueno, ...", "chicas,
-- ...", "ok pessoal, ..."), carry nothing
do
  local _, ex = scene({ "CRE AZU5 E195 -23.0 -47.0 240 FL110 260" })
  check_eq(ex("bueno, AZU5 descend FL080"), "ALT AZU5 FL80")
  check_eq(ex("chicas, AZU5 turn left heading 200"), "HDG AZU5 200 LEFT")
  check_eq(ex("vamos, AZU5 reduce speed 220 knots"), "SPD AZU5 220")
end

-- The clock in second-language English: "un-pause", "speed the sim to x4", "go forward 45 seconds"; an
-- instruction word after "the" that a verb of description follows ("the descent is too slow") is a noun
do
  local _, ex = scene({})
  check_eq(ex("un-pause the simulation"), "OP")
  check_eq(ex("speed the sim to x4"), "DTMULT 4")
  check_eq(ex("go forward 45 seconds"), "FF 45")
  check_eq(ex("make the sim 2 times faster, the descent is too slow"), "DTMULT 2")
end

-- Conflict settings said in passing: a module named ("switch on the conflict detection module"), when
-- navigation resumes ("resolution only past CPA"), the kind of resolution named after an instruction
-- ("climb FL160, vertical resolution"); "maintain 250" after a speed named and no level is the speed
do
  local _, ex = scene({ "CRE TAM90 A320 -23.4 -45.9 270 FL150 280" })
  check_eq(ex("switch on the conflict detection module"), "ASAS ON")
  check_eq(ex("resolution only past CPA please"), "RESNAV PASTCPA")
  check_eq(ex("TAM90 climb FL160, vertical resolution"), "ALT TAM90 FL160")
  check_eq(ex("TAM90 keep the speed... no, just maintain 250"), "SPD TAM90 250")
  asked(ex("TAM90 maintain 250"), "maintain 250 with nothing named")
end

-- Aircraft named before the last "so" or sentence end before an instruction, another named after it, are
-- talked about, not instructed ("X and Y are converging, so Y turn right heading 360"); with none named after
-- it, those before are the instruction's
do
  local _, ex = scene({ "CRE ARG5 B738 -34.0 -60.0 090 FL200 280", "CRE FBZ6 B738 -34.5 -59.0 270 FL200 280" })
  check_eq(ex("ARG5 and FBZ6 are head on, so FBZ6 turn left heading 200"), "HDG FBZ6 200 LEFT")
  check_eq(ex("ARG5 is too fast. FBZ6 turn left heading 200"), "HDG FBZ6 200 LEFT")
  check_eq(ex("ARG5 and FBZ6 turn left heading 200"), "HDG ARG5 200 LEFT ; HDG FBZ6 200 LEFT")
end

-- A direct-to for an aircraft created in the same request (no route yet) adds the waypoint first
do
  local _, ex = scene({ "DEFWPT PAMPA -34.0 -58.0" })
  check_eq(ex("create ARG77 B738 at -34.5 -58.5 heading 030 FL090 250 kt and route direct PAMPA"),
    "CRE ARG77 B738 -34.5 -58.5 30 FL90 250 ; ADDWPT ARG77 PAMPA ; DIRECT ARG77 PAMPA")
end

-- A waypoint's position corrected in the same breath ("at 34.5 S 58.8 W, no, at -34.50 -58.83") is the one
-- said after the correction, in either notation
do
  local _, ex = scene({})
  check_eq(ex("new waypoint PAMPA at 33.5 S 60.8 W, no, at -33.60 -60.90"), "DEFWPT PAMPA -33.6 -60.9")
  check_eq(ex("new waypoint PAMPA at 33 30 S 60 48 W, no wait, at 33.6 S 60.9 W"), "DEFWPT PAMPA -33.6 -60.9")
  check_eq(ex("new waypoint PAMPA at 33.5 S 60.8 W"), "DEFWPT PAMPA -33.5 -60.8")
end

-- More South American telephonies: "Boliviana 612" (BOV), "Passaredo 2240" (VOEPASS, PTB)
do
  local _, ex = scene({ "CRE BOV612 B738 -17.6 -63.1 090 FL200 250", "CRE PTB2240 AT76 -22.0 -47.0 180 FL150 220" })
  check_eq(ex("Boliviana 612 climb FL240"), "ALT BOV612 FL240")
  check_eq(ex("Passaredo 2240 descend FL110"), "ALT PTB2240 FL110")
end

-- Second-language phrasings of ordinary requests: "increase the level to FL130" (the level named after the
-- verb), "which is the altitude of X?" (a question), "return to the route" (LNAV; a place after it is asked)
do
  local _, ex = scene({ "CRE GLO7 B738 -23.5 -46.9 270 FL090 250", "DEFWPT TEXAS -23.0 -46.0", "ADDWPT GLO7 TEXAS" })
  check_eq(ex("GLO7 increase the level to FL130"), "ALT GLO7 FL130")
  check_eq(ex("GLO7 reduce 220 level FL080"), "SPD GLO7 220 ; ALT GLO7 FL80")
  check_eq(ex("which is the altitude of GLO7?"), "POS GLO7")
  check_eq(ex("GLO7 return to the route"), "LNAV GLO7 ON")
  asked(ex("GLO7 return to the route at TEXAS"), "a place to rejoin at")
end

-- A vertical speed's sign from its whole clause ("descend with vertical speed 2000", "vertical speed 2000
-- feet per minute for descend" descend); "rise to FL200" climbs
do
  local _, ex = scene({ "CRE JAT9 A320 -33.2 -70.4 240 FL150 270", "DEFWPT KALUX -33.0 -70.0" })
  check_eq(ex("JAT9 descend with vertical speed 2000"), "VS JAT9 -2000")
  check_eq(ex("JAT9 vertical speed 1500 feet per minute for descend"), "VS JAT9 -1500")
  check_eq(ex("JAT9 climb with vertical speed 1500"), "VS JAT9 1500")
  -- ("go to X" is a direct-to, a waypoint added or a destination as writers mean it: asked)
  asked(ex("JAT9 go to the waypoint KALUX"), "go to a waypoint")
  check_eq(ex("JAT9 rise to FL200"), "ALT JAT9 FL200")
end

-- A condition of the level reached ("on reaching", "when level", "when you reach it", "once there") is
-- carried or asked, never dropped: after a level cleared it holds a speed, a heading, a switch of navigation
-- or a direct-to (ATALT); said after its instruction it holds it the same; with no level before it, or
-- before a turn by degrees, it is asked about
do
  local _, ex = scene({ "CRE SAS31 A320 55.6 12.6 090 FL150 250", "DEFWPT KOBRA 55.8 13.4", "ADDWPT SAS31 KOBRA" })
  check_eq(ex("sas31 climb FL190 on reaching resume own navigation"),
    "ALT SAS31 FL190 ; ATALT SAS31 FL190 LNAV SAS31 ON")
  check_eq(ex("SAS31 descend FL110, when level own nav"), "ALT SAS31 FL110 ; ATALT SAS31 FL110 LNAV SAS31 ON")
  check_eq(ex("SAS31 descend FL110, on reaching direct KOBRA"),
    "ALT SAS31 FL110 ; ATALT SAS31 FL110 DIRECT SAS31 KOBRA")
  check_eq(ex("SAS31 climb FL190, slow to 230 once you get there"),
    "ALT SAS31 FL190 ; ATALT SAS31 FL190 SPD SAS31 230")
  check_eq(ex("SAS31 climb FL190, speed 230 when you're level"), "ALT SAS31 FL190 ; ATALT SAS31 FL190 SPD SAS31 230")
  asked(ex("SAS31 slow to 230 when you reach it"), "no level before 'when you reach it'")
  asked(ex("SAS31 speed 230 once there"), "no level before 'once there'")
  asked(ex("SAS31 on reaching slow to 230"), "no level before 'on reaching'")
  asked(ex("SAS31 when you reach it, slow to 230"), "no level before 'when you reach it'")
  asked(ex("SAS31 climb FL190, on reaching turn right 30 degrees"), "a turn by degrees")
  asked(ex("SAS31 direct KOBRA, slow to 230 when you get there"), "no level before it")
  -- (said after its instruction with "on reaching"; a level said in the condition holds a switch of navigation)
  check_eq(ex("SAS31 descend FL110, own nav on reaching"), "ALT SAS31 FL110 ; ATALT SAS31 FL110 LNAV SAS31 ON")
  check_eq(ex("SAS31 on reaching FL170 resume own navigation"), "ATALT SAS31 FL170 LNAV SAS31 ON")
  asked(ex("SAS31 slow to 230 on reaching"), "no level before 'on reaching'")
  check_eq(ex("SAS31 climb FL190, slow to 230 after reaching"), "ALT SAS31 FL190 ; ATALT SAS31 FL190 SPD SAS31 230")
  check_eq(ex("SAS31 climb FL190, slow to 230 reaching"), "ALT SAS31 FL190 ; ATALT SAS31 FL190 SPD SAS31 230")
  -- (a report asked for is no condition)
  check(ex("SAS31 climb FL190, report reaching"):find("ATALT", 1, true) == nil, "a report asked for")
  -- ("when you get to FL170": the level reached, never a level to fly and the speed at once)
  check_eq(ex("SAS31 when you get to FL170 slow to 230"), "ATALT SAS31 FL170 SPD SAS31 230")
  check_eq(ex("SAS31 once it gets to FL170 resume own navigation"), "ATALT SAS31 FL170 LNAV SAS31 ON")
  check_eq(ex("SAS31 slow to 230 once you get to FL170"), "ATALT SAS31 FL170 SPD SAS31 230")
  -- (the listener's convenience is no condition)
  check_eq(ex("SAS31 slow to 230 when you get a chance"), "SPD SAS31 230")
end

-- Text-ATC typed abbreviations of instruction words ("trn lft 15", "red 220", "desc pd FL150", "expd desc",
-- "maint 280 kts", "til") are read as the words where a word beside them shows the instruction; elsewhere
-- they stay as typed ("trail red" is a colour, "direct TRN" a place); a typed hesitation ("err") is one
do
  local _, ex = scene({ "CRE SAS32 A320 55.6 12.6 090 FL150 250", "CRE SAS33 A320 55.9 12.9 270 FL150 250" })
  check_eq(ex("sas32 trn lft 15"), "HDG SAS32 75 LEFT")
  check_eq(ex("sas32 trn rt hdg 120"), "HDG SAS32 120 RIGHT")
  check_eq(ex("sas32 red 220"), "SPD SAS32 220")
  check_eq(ex("sas32 hdg 120, red 210, desc FL90"), "HDG SAS32 120 ; SPD SAS32 210 ; ALT SAS32 FL90")
  check_eq(ex("sas32 desc pd FL100"), "ALT SAS32 FL100")
  check_eq(ex("sas32 expd desc 3000 fpm"), "VS SAS32 -3000")
  check_eq(ex("sas32 desc FL100 expd"), "ALT SAS32 FL100")
  check_eq(ex("sas32 mach .. err spd 240"), "SPD SAS32 240")
  check(ex("sas32 trail red"):match("^TRAIL ") ~= nil, "a trail's colour")
  check_eq(ex("sas32 dm FL100"), "ALT SAS32 FL100")
  check_eq(ex("sas32 rv hdg 200"), "HDG SAS32 200")
  check_eq(ex("sas32 fh 200"), "HDG SAS32 200")
  check_eq(ex("sas32 tl hdg 060"), "HDG SAS32 60 LEFT")
  asked(ex("sas32 red"), "'red' with no value is no speed")
  asked(ex("sas32 pd"), "'pd' alone")
  asked(ex("sas32 cm FL100"), "a climb to a level below the aircraft")
end

-- A value held "until established" on the approach ("maint 8000 til established") is flown now, its end not
-- kept (named as not simulated), when the limit ends the request; an instruction after it, which waits for
-- it, is asked about (a limit at a distance, "until 4 dme", is read so too: Cycle 32's block). "maintain 280 or
-- greater" is a speed
do
  local _, ex = scene({ "CRE SAS34 A320 55.6 12.6 090 FL150 250" })
  check_eq(ex("SAS34 heading 200, maint 4000 til established"), "HDG SAS34 200 ; ALT SAS34 4000")
  check_eq(ex("SAS34 maintain 180 knots until established on the localizer"), "SPD SAS34 180")
  check_eq(ex("SAS34 maintain 230 or greater"), "SPD SAS34 230")
  asked(ex("SAS34 maintain 180 knots until established, then descend 3000"),
    "an instruction waiting for the limit")
  check_eq(ex("sas34 red 160 kts until 4 dme"), "SPD SAS34 160")
end

-- The online network's words for a pilot gone, given as the reason for removing the aircraft ("pilot dc'd",
-- "he's disconnected", "pilot went afk") carry nothing; "say route" lists the route; "sim run", ".hold" (a
-- text client's dot command) run and hold the clock; the wind told to an aircraft addressed is no WIND
do
  local _, ex = scene({ "CRE SAS35 A320 55.6 12.6 090 FL150 250", "DEFWPT KOBRA 55.8 13.4", "ADDWPT SAS35 KOBRA" })
  check_eq(ex("del sas35, pilot dc'd"), "DEL SAS35")
  check_eq(ex("remove sas35 from the scope, he's disconnected"), "DEL SAS35")
  check_eq(ex("delete sas35 pilot went afk"), "DEL SAS35")
  check_eq(ex("remove sas35, connection lost"), "DEL SAS35")
  -- (said to an aircraft, "resume normal speed" lifts its speed restriction, no simulation rate)
  check_eq(ex("sas35 resume normal speed, descend FL100"), "ALT SAS35 FL100")
  check_eq(ex("resume normal speed"), "DTMULT 1")
  check_eq(ex("sas35 resume normal navigation"), "LNAV SAS35 ON")
  check_eq(ex("sas35 dct KOBRA, rest of route unchanged"), "DIRECT SAS35 KOBRA")
  check_eq(ex("sas35 say route"), "LISTRTE SAS35")
  check_eq(ex("sim run"), "OP")
  check_eq(ex("sim stop"), "HOLD")
  check_eq(ex(".hold"), "HOLD")
  check_eq(ex("scandinavian 35, wind 240 at 12, reduce 200"), "SPD SAS35 200")
  asked(ex("sas35 pilot went afk"), "a reason with no instruction")
end

-- A clause opening "at WPT" before a climb, descent or speed change with a bare number ("at KOBRA desc
-- 4000", "at KOBRA reduce 210") runs there (AT acid wp DO), the number read as the instruction alone reads it
do
  local _, ex = scene({ "CRE SAS36 A320 55.6 12.6 090 7000 250", "DEFWPT KOBRA 55.8 13.4", "DEFWPT LUPUS 55.1 13.0",
    "ADDWPT SAS36 KOBRA" })
  check_eq(ex("SAS36 at KOBRA desc 4000"), "AT SAS36 KOBRA DO ALT SAS36 4000")
  check_eq(ex("SAS36 at KOBRA reduce to 210"), "AT SAS36 KOBRA DO SPD SAS36 210")
  asked(ex("SAS36 at LUPUS desc 4000"), "a waypoint off the route")
  asked(ex("SAS36 at KOBRA descend 40"), "a bare number under 1000")
end

-- Creation places and the reference position: a place where traffic is created is issued by its ident
-- only where the simulator, from the reference it has when the CRE runs, resolves the ident to the place
-- meant; otherwise the airport the name means or a question naming the place
do
  local r
  local s, ex = navscene({}, "creation places and the reference position")
  if s then
    -- an empty scene resolves from 0 0: LAM there is the LICA 28 ILS, so the LAMBOURNE VOR is given by its
    -- position, which no reference moves
    check_eq(ex("spawn RYR4TT, an A320, at Lambourne heading 090 FL150 at 250 knots"),
      "CRE RYR4TT A320 51.646111 0.151667 90 FL150 250")
    -- a navaid whose ident the simulator takes from 0 0 is issued (OCK: the OCKHAM VOR)
    check_eq(ex("spawn BAW7Q, an A320, over Ockham heading 090 FL150 at 250 knots"), "CRE BAW7Q A320 OCK 90 FL150 250")
    -- a navaid said by its name that stands on a large airport is the airport: EZE is on SAEZ
    check_eq(ex("put ARG77, a B738, at Ezeiza, heading 200, FL050, 220 knots"), "CRE ARG77 B738 SAEZ 200 FL50 220")
    -- the AEROPARQUE NDB's ident N is another N NDB from 0 0: the airport that bears the name beside it
    check_eq(ex("create FBZ10 B738 at Aeroparque heading 090 FL040 200 knots"), "CRE FBZ10 B738 SABE 90 FL40 200")
    -- the one airport named SANTIAGO (LEST, Spain) where SANTIAGO navaids stand in Chile and elsewhere too
    r = ex("create JAT9 A320 at Santiago airport heading 350 FL060 210 knots")
    check(r:match("^ASK") and r:find("LEST", 1, true) ~= nil and r:find("SCEL", 1, true) ~= nil, r)
    -- a navaid said with its kind is the navaid, never the airport: KAS from 0 0 is the KASANE NDB, so the
    -- KASTRUP VOR by its position, never EKCH
    check_eq(ex("add SAS3 A320 at the Kastrup VOR heading 180 FL110 260 knots"),
      "CRE SAS3 A320 55.590519 12.613603 180 FL110 260")
    -- a name that names one airport and no navaid far from it stays issued; other large airports of the
    -- city around it are no other place ("Gatwick": EGLC within lexicon.navaid_range_nm)
    check_eq(ex("create KLM5 B738 at Schiphol heading 090 FL100 250 knots"), "CRE KLM5 B738 EHAM 90 FL100 250")
    check_eq(ex("create EZY5 A320 at Gatwick heading 260 3000 ft 200 knots"), "CRE EZY5 A320 EGKK 260 3000 200")
  end
  -- traffic over London: the reference is there, and LAM is the Lambourne VOR
  local s2, ex2 = navscene({ "CRE BAW1 A320 51.5 -0.3 090 FL200 250" }, "creation places near traffic")
  if s2 then
    check_eq(ex2("spawn RYR4TT, an A320, at Lambourne heading 090 FL150 at 250 knots"), "CRE RYR4TT A320 LAM 90 FL150 250")
    check_eq(ex2("create EZY9 A319 over LAM heading 180 FL120 250 knots"), "CRE EZY9 A319 LAM 180 FL120 250")
    -- typed as its ident with traffic flying elsewhere than the reference: the one nearest the traffic
    -- is meant, and the simulator would take the other one
    local s3, ex3 = navscene({ "CRE BAW2 A320 51.5 -0.3 090 FL200 250", "NEAR 39 16 ECHO reference in Italy" },
      "creation places near traffic")
    r = ex3("create EZY9 A319 over LAM heading 180 FL120 250 knots")
    check(r:match("^ASK Which LAM is meant") ~= nil, r)
    -- the translator's look-ups leave the simulation's reference where the scene left it
    local lat, lon = s2:reference()
    check(math.abs(lat - 51.5) < 1e-9 and math.abs(lon + 0.3) < 1e-9, lat .. " " .. lon)
  end
end

-- Typed slips that must never run as a guess (R61): digits typed apart after "hdg" in groups other
-- than single digits, a fix name with two letters swapped, two callsigns side by side, a value's name
-- cut off at the end, an aircraft created in the air too slow to fly; a comma typed against a callsign
-- still lists it
do
  local _, ex = scene({ "CRE KLM77 B738 52.1 4.5 180 FL150 250", "CRE BAW8CK A320 52.0 4.0 025 FL200 250",
    "DEFWPT TOLIP 52.3 4.6", "ADDWPT KLM77 TOLIP" })
  check_eq(ex("klm77 hdg 1 8 0"), "HDG KLM77 180")
  asked(ex("klm77 hdg 1 80"), ex("klm77 hdg 1 80"))
  -- (a level's figures apart after "fl", one then two, join into the level: cycle 47)
  check_eq(ex("klm77 fl 1 20"), "ALT KLM77 FL120")
  check_eq(ex("klm77 dct tolip"), "DIRECT klm77 tolip")
  check_eq(ex("klm77 dct tolpi"), "ASK Did you mean TOLIP? I heard 'tolpi'.")
  check_eq(ex("klm77 baw8ck descend fl90"), "ASK Which aircraft do you mean: KLM77, BAW8CK or both?")
  check_eq(ex("klm77 and baw8ck descend fl90"), "ALT KLM77 FL90 ; ALT BAW8CK FL90")
  check_eq(ex("klm77 fl140 ,baw8ck fl160"), "ALT KLM77 FL140 ; ALT BAW8CK FL160")
  check_eq(ex("klm77,baw8ck fl170"), "ALT KLM77 FL170 ; ALT BAW8CK FL170")
  check_eq(ex("klm77 fl170,spd 230"), "ALT KLM77 FL170 ; SPD KLM77 230")
  check(ex("klm77 descend fl100, then level"):match("^ASK I have ALT KLM77 FL100%. 'level' ends") ~= nil,
    ex("klm77 descend fl100, then level"))
  check(ex("klm77 hdg 200 and spd"):match("^ASK I have HDG KLM77 200%. 'spd' ends") ~= nil, ex("klm77 hdg 200 and spd"))
  check(ex("klm77 descend fl120 hdg"):match("^ASK I have ALT KLM77 FL120%. 'hdg' ends") ~= nil, ex("klm77 descend fl120 hdg"))
  asked(ex("klm77 spd 30"), ex("klm77 spd 30"))
  check_eq(ex("spd klm77 0.78"), "SPD klm77 0.78")
  -- a heading of one digit and a vertical speed under lexicon.min_typed_fpm, typed, are asked
  check(ex("klm77 hdg 3"):match("^ASK What heading") ~= nil, ex("klm77 hdg 3"))
  check(ex("klm77 vs -12"):match("^ASK What vertical speed") ~= nil, ex("klm77 vs -12"))
  check_eq(ex("klm77 vs -1200"), "VS klm77 -1200")
  check_eq(ex("klm77 hdg 007"), "HDG klm77 007")
  asked(ex("cre tst5 b738 52 4 180 fl100 30"), ex("cre tst5 b738 52 4 180 fl100 30"))
  check(ex("create tst5 b738 at 52 4 heading 180 fl100 speed 30 knots"):match("^ASK TST5 would fly at 30 kt") ~= nil,
    ex("create tst5 b738 at 52 4 heading 180 fl100 speed 30 knots"))
  check_eq(ex("cre tst6 b738 52 4 180 fl100 300"), "CRE tst6 b738 52 4 180 fl100 300")
end

-- A typed correction (R61): "err" and "sry" are "sorry", "hmm no" is a correction run: the
-- value or fix after them replaces the one before; one left alone at the end corrects nothing
do
  local _, ex = scene({ "CRE KLM77 B738 52.1 4.5 180 FL150 250", "DEFWPT TOLIP 52.3 4.6", "DEFWPT MAVOR 52.4 4.7",
    "ADDWPT KLM77 TOLIP", "ADDWPT KLM77 MAVOR" })
  check_eq(ex("klm77 fl170 err fl190"), "ALT KLM77 FL190")
  check_eq(ex("klm77 hdg 240 sry 250"), "HDG KLM77 250")
  check_eq(ex("klm77 spd 230 hmm no 240"), "SPD KLM77 240")
  check_eq(ex("klm77 dct tolip err mavor"), "DIRECT KLM77 MAVOR")
  check_eq(ex("klm77 hdg 240 err"), "HDG KLM77 240")
  asked(ex("klm77 hdg 240 err 250 270"), ex("klm77 hdg 240 err 250 270"))
end

-- What squawk does not simulate, typed short (R61): "squak"/"sqwk" is a transponder code, a controller
-- position after "contact" ("director") no direct-to; the simulated part of the request stands
do
  local _, ex = scene({ "CRE KLM77 B738 52.1 4.5 180 FL150 250" })
  check_eq(ex("klm77 sqwk 4410 and descend fl120"), "ALT KLM77 FL120")
  check_eq(ex("klm77 climb fl190 then contact director 119.45"), "ALT KLM77 FL190")
  check(ex("klm77 squak"):match("^ASK") ~= nil or ex("klm77 squak") == "", ex("klm77 squak"))
end

-- Values typed with a slip (R61): a letter O for a zero in a value of three figures ("hdg 3o0"), a Mach
-- number typed alone after the callsign (".78"), as it is after a level; a sign typed before a vertical
-- speed ("vs +1200"); "kits" for kts
do
  local _, ex = scene({ "CRE KLM77 B738 52.1 4.5 180 FL150 250" })
  check_eq(ex("klm77 hdg 3o0"), "HDG KLM77 300")
  check_eq(ex("klm77 spd 24O"), "SPD KLM77 240")
  check_eq(ex("klm77 .78"), "SPD KLM77 M0.78")
  -- a plus typed before a vertical speed is its sign; "kits" after a speed is knots
  check_eq(ex("klm77 fl190 vs +1200"), "ALT KLM77 FL190 ; VS KLM77 1200")
  check_eq(ex("klm77 spd 230 kits"), "SPD KLM77 230")
  check_eq(ex("klm77 spd +20"), "SPD KLM77 270")  -- a signed speed with no unit: 20 kt faster
  check(ex("klm77 climb fl200 .78"):match("^ALT KLM77 FL200") ~= nil, ex("klm77 climb fl200 .78"))
end

-- A callsign typed against its instruction word (R61): "klm77climb fl190" is "klm77 climb fl190"; a word
-- that only starts with a callsign and goes on with no instruction word is not cut
do
  local _, ex = scene({ "CRE KLM77 B738 52.1 4.5 180 FL150 250" })
  check_eq(ex("klm77climb fl190"), "ALT KLM77 FL190")
  check_eq(ex("klm77hdg 250"), "HDG KLM77 250")
  asked(ex("klm77xyz climb fl190"), ex("klm77xyz climb fl190"))
end

-- "back to real time" said after the rate typed as 1 explains it (R61); after another rate it is still asked
do
  local _, ex = scene({ "CRE KLM77 B738 52.1 4.5 180 FL150 250" })
  check_eq(ex("dtmult 1, back to real time"), "DTMULT 1")
  asked(ex("dtmult 4 back to real time"), ex("dtmult 4 back to real time"))
end

-- Cycle 29 (R62): a bare spoken "maintain NNN" is the level kept when it is the aircraft's own present
-- level and not its present speed; otherwise a speed as before, and a value said with "knots" a speed
do
  local _, ex = scene({ "CRE TAI611 A320 14.0 -89.0 090 FL310 320", "CRE AVA44 B738 13.0 -88.0 180 FL240 250" })
  check_eq(ex("Taca six one one maintain three one zero, traffic two o'clock"), "ALT TAI611 FL310")
  check_eq(ex("Taca six one one maintain two eight zero"), "SPD TAI611 280")
  check_eq(ex("Taca six one one maintain three one zero knots"), "SPD TAI611 310")
  -- (a level that is also its present speed: the speed reading stands, no level guessed)
  check_eq(ex("Avianca four four maintain two five zero"), "SPD AVA44 250")
end

-- Cycle 29 (R62): Spanish clearance words a controller mixes into English ("descienda y mantenga ... pies",
-- "mantenga", "vire izquierda", "reduzca ... nudos"), the Caribbean "yuh", and typed "dsnd", "clmb"
do
  local _, ex = scene({ "CRE AMX318 B738 19.4 -99.1 030 FL180 280", "CRE VOI27 A320 20.0 -100.0 200 FL200 290",
    "DEFWPT ALPHA 20.5 -100.2", "ADDWPT VOI27 ALPHA" })
  check_eq(ex("Aeromexico tres uno ocho, descienda y mantenga uno cero mil pies"), "ALT AMX318 10000")
  check_eq(ex("Aeromexico 318, mantenga flight level one six zero, reduce two five zero"),
    "ALT AMX318 FL160 ; SPD AMX318 250")
  check_eq(ex("Volaris 27 vire izquierda rumbo uno ocho cero"), "HDG VOI27 180 LEFT")
  check_eq(ex("Volaris 27 reduzca dos cuatro cero nudos"), "SPD VOI27 240")
  check_eq(ex("Volaris 27 yuh cleared to descend flight level one two zero"), "ALT VOI27 FL120")
  check_eq(ex("Volaris 27 proceda directo a ALPHA"), "DIRECT VOI27 ALPHA")
  check_eq(ex("Aeromexico 318 mantenga rumbo actual"), "HDG AMX318 30")
  check_eq(ex("Aeromexico 318 mantenga velocidad actual"), "SPD AMX318 280")
  asked(ex("Aeromexico 318 rumbo actual"), "rumbo actual with no verb")
  check_eq(ex("amx318 dsnd 9000"), "ALT AMX318 9000")
  check_eq(ex("voi27 clmb fl240"), "ALT VOI27 FL240")
  -- where the class stops: a Spanish verb with no value of its own after it is asked about
  asked(ex("Volaris 27 mantenga"), "mantenga with nothing after it")
  asked(ex("Volaris 27 vire, uh"), "vire with nothing after it")
end

-- Cycle 29 (R62): three digits alone after a level passed, left or reached ("passing two two zero increase
-- Mach .78") are a flight level the next instruction waits for; after "at" they are still asked about
do
  local _, ex = scene({ "CRE CMP77 B738 9.0 -79.0 090 FL200 280" })
  check_eq(ex("Copa 77 climb flight level three one zero, passing two four zero increase mach point seven eight"),
    "ALT CMP77 FL310 ; ATALT CMP77 FL240 SPD CMP77 M0.78")
  check_eq(ex("Copa 77 climb FL310, leaving 250 reduce 270 knots"), "ALT CMP77 FL310 ; ATALT CMP77 FL250 SPD CMP77 270")
  asked(ex("Copa 77 climb flight level three one zero, at two two zero reduce two five zero knots"),
    "at three digits")
end

-- Cycle 29 (R62): a limit ending on the approach followed by the approach clearance ("until established,
-- cleared ILS runway 10") is named, not flown; an instruction after it still asks
do
  local _, ex = scene({ "CRE NKS88 A320 18.2 -65.4 280 12000 250" })
  check_eq(ex("Spirit eight eight descend and maintain two thousand until established, cleared ILS runway two six"),
    "ALT NKS88 2000")
  check(ex("Spirit eight eight descend and maintain two thousand until established, turn left heading 250"):match("^ASK")
    ~= nil, "an instruction after the limit")
end

-- Cycle 29 (R62): the Caribbean's, Central America's and Mexico's airlines by telephony (Cubana, Arajet,
-- LIAT, Bahamas, Cayman, TACA, Aeroenlaces, ...) and "Spirit" for Spirit Wings, anywhere in the request;
-- a flight number of none of their aircraft still asks
do
  local _, ex = scene({ "CRE CUB215 A320 22.0 -82.0 090 FL200 280", "CRE DWI33 B738 18.5 -69.0 180 FL150 250",
    "CRE LIA360 AT76 13.0 -61.0 010 9000 200", "CRE NKS902 A320 18.3 -65.0 270 FL120 250",
    "CRE BHS71 B737 25.0 -77.4 150 FL170 260" })
  check_eq(ex("instructor: remove Cubana two one five"), "DEL CUB215")
  check_eq(ex("clear the route of Arajet 33"), "DELRTE DWI33")
  check_eq(ex("LIAT three sixty climb one one thousand"), "ALT LIA360 11000")
  check_eq(ex("take out Spirit nine zero two"), "DEL NKS902")
  check_eq(ex("Bahamas seven one turn right heading two zero zero"), "HDG BHS71 200 RIGHT")
  asked(ex("Cubana two one six descend flight level one eight zero"), "CUB216 flies not")
end

-- Cycle 29 (R62): an aircraft and "route", a verb of showing after it ("route please, show it") lists the route;
-- anything more after it still asks
do
  local _, ex = scene({ "CRE CMP902 B738 9.0 -79.0 090 FL200 280" })
  check_eq(ex("Copa 902 route please, show it"), "LISTRTE CMP902")
  check_eq(ex("cmp902 route, display"), "LISTRTE CMP902")
  asked(ex("Copa 902 route, show it to the students"), "more after the verb")
end

-- Cycle 29 (R62): the region's stations said by their city alone after the callsign ("Iberia 6621, Havana,
-- ...", "Kingston"), and its cities as destinations
do
  local s, ex = navscene({ "CRE IBE6621 A332 23.5 -80.0 250 FL330 290", "CRE BWA9 B738 17.5 -76.0 280 FL200 280" },
    "the region's stations by their city")
  if s then
    check_eq(ex("Iberia 6621, Havana, descend flight level two eight zero"), "ALT IBE6621 FL280")
    check_eq(ex("Caribbean nine, Kingston, turn left heading two five zero"), "HDG BWA9 250 LEFT")
    check_eq(ex("BWA9 new destination Montego Bay"), "DEST BWA9 MKJS")
    -- (a name that is no station nor city there is still asked about)
    asked(ex("Iberia 6621, Habanero, descend flight level two eight zero"), "no station")
  end
end

-- Cycle 29 (R62): a type's variant said after "dash" ("Boeing seven three seven dash eight hundred"), and
-- "Airbus three three zero three hundred" keeping its variant (A333, never the family's A332); "dash" with
-- a variant digit alone ("seven three seven dash eight") is still asked about
do
  local _, ex = scene({})
  check_eq(ex("create CMP71, Boeing seven three seven dash eight hundred, at 9 north 79 west, heading 090, FL240, 290 knots"),
    "CRE CMP71 B738 9 -79 90 FL240 290")
  check_eq(ex("create IBE44, Airbus three three zero three hundred, at 20 north 70 west, heading 270, FL350, 280 knots"),
    "CRE IBE44 A333 20 -70 270 FL350 280")
  check_eq(ex("create IBE45, Airbus three three zero dash two hundred, at 20 north 71 west, heading 270, FL330, 280 knots"),
    "CRE IBE45 A332 20 -71 270 FL330 280")
  asked(ex("create CMP72, Boeing seven three seven dash eight, at 9 north 78 west, heading 090, FL240, 290 knots"),
    "dash eight")
end

-- Cycle 30 (R63): "request your <state>" is the controller asking the aircraft's own value (a report), never an
-- instruction to keep it; "request" with an instruction's value after it is still no report
do
  local _, ex = scene({ "CRE SVA117 B77W 24.0 39.0 140 FL330 290" })
  check_eq(ex("Saudia 117 request your present heading"), "POS SVA117")
  check_eq(ex("SVA117 request your level"), "POS SVA117")
  check(ex("Saudia 117 request heading 150"):match("^POS") == nil, "a value after the state word")
end

-- Cycle 30 (R63): a Mach number written with a decimal comma ("mach 0,78"), as French and Arabic write decimals;
-- a comma after another first digit is no decimal
do
  local _, ex = scene({ "CRE DAH2050 A332 36.5 3.0 090 FL350 280" })
  check_eq(ex("Air Algerie 2050 mach 0,81"), "SPD DAH2050 M0.81")
  check_eq(ex("DAH2050 maintain mach 0,8"), "SPD DAH2050 M0.8")
  asked(ex("DAH2050 mach 1,81"), "1,81 is no Mach number")
end

-- Cycle 30 (R63): typed thousands and hundreds, "8 thousand 500 feet", "6 thousand 5 hundred": one altitude; a
-- bare number after "thousand" with no feet is still another value
do
  local _, ex = scene({ "CRE RJA214 A320 31.0 36.0 180 12000 250" })
  check_eq(ex("Jordanian 214 descend 8 thousand 500 feet"), "ALT RJA214 8500")
  check_eq(ex("RJA214 descend to 6 thousand 5 hundred"), "ALT RJA214 6500")
  check(ex("RJA214 descend 8 thousand 300 knots"):match("^ALT RJA214 8000") ~= nil
    or ex("RJA214 descend 8 thousand 300 knots"):match("^ASK") ~= nil, "300 knots is no hundreds")
end

-- Cycle 30 (R63): the Middle East's and North Africa's airlines by telephony and name ("Nile Bird", "Nas",
-- "Nouvelair", "Arabia Maroc"); a flight number no aircraft flies is still asked about
do
  local _, ex = scene({ "CRE NIA330 A320 30.0 31.0 300 FL170 270", "CRE KNE88 A320 24.5 46.5 010 FL250 280",
    "CRE LBT702 A320 36.0 10.0 350 FL110 250", "CRE MAC41 A320 33.5 -7.5 030 FL130 260",
    "CRE RAM1190 E190 32.6 -7.9 030 6000 210" })
  check_eq(ex("Nile Bird 330 climb flight level 210"), "ALT NIA330 FL210")
  check_eq(ex("position of Nas 88"), "POS KNE88")
  check_eq(ex("Nouvelair 702 turn left heading 300"), "HDG LBT702 300 LEFT")
  check_eq(ex("Arabia Maroc 41 descend flight level 90"), "ALT MAC41 FL90")
  check_eq(ex("move Royal Maroc 1190 to 33.1 -7.6"), "MOVE RAM1190 33.1 -7.6")
  check_eq(ex("Royal Maroc 1190 turn right heading 060"), "HDG RAM1190 60 RIGHT")
  check_eq(ex("create Nouvelair 703 A320 at 36.2 10.1 heading 180 FL100 240"), "CRE LBT703 A320 36.2 10.1 180 FL100 240")
  asked(ex("Nile Bird 331 climb flight level 210"), "no such flight")
end

-- Cycle 30 (R63): "run x4": the clock's multiplier typed straight after "run", nothing after it; "put ... back to
-- normal speed" is the clock's rate
do
  local _, ex = scene({ "CRE RAM77 B738 33.0 -7.0 090 FL200 280" })
  check_eq(ex("run x4"), "DTMULT 4")
  check(ex("run x4 RAM77"):match("^DTMULT 4$") == nil, "more after the multiplier")
  -- "put the sim back to normal speed": the clock's rate, no aircraft put back; an aircraft put back still moves
  check_eq(ex("put the sim back to normal speed"), "DTMULT 1")
  check_eq(ex("put RAM77 back to 33.2 -7.1"), "MOVE RAM77 33.2 -7.1")
end

-- Cycle 30 (R63): "wind at LAT LON [level]" opening the request with nothing else: the wind there, shown (GETWIND);
-- a direction and speed told after it set it (WIND)
do
  local _, ex = scene({ "CRE MSR808 A320 30.0 31.0 300 FL170 270" })
  check_eq(ex("wind at 29.8 32.1 FL240"), "GETWIND 29.8 32.1 FL240")
  check_eq(ex("winds over 31N 30E?"), "GETWIND 31 30")
  check_eq(ex("wind at 29.8 32.1 FL240 from 310 at 30 kts"), "WIND 29.8 32.1 FL240 310 30")
end

-- Cycle 30 (R64): a crossing said after a direct ("direct ALFA, cross it at FL150") is the AT constraint at
-- the waypoint flown to; "direct ALFA, then at ALFA climb ..." (the instruction in the next clause) runs
-- from the waypoint on (Cycle 37: AT acid wp DO), never at once
do
  local _, ex = scene({ "DEFWPT RIVKA 52.3 4.8", "CRE KLM88 A320 52.0 4.0 090 FL250 280", "ADDWPT KLM88 RIVKA" })
  check_eq(ex("KLM88 go direct RIVKA, cross it at FL170"), "DIRECT KLM88 RIVKA ; AT KLM88 RIVKA ALT FL170")
  check_eq(ex("KLM88 direct RIVKA, cross at 9000"), "DIRECT KLM88 RIVKA ; AT KLM88 RIVKA ALT 9000")
  check_eq(ex("KLM88 direct RIVKA, then at RIVKA descend FL120"), "DIRECT KLM88 RIVKA ; AT KLM88 RIVKA DO ALT KLM88 FL120")
end

-- Cycle 30 (R64): a simulation time typed h:mm:ss before a colon ("schedule at 00:15:00: ...") is the time of
-- the SCHEDULE, never dropped
do
  local _, ex = scene({ "CRE KLM88 A320 52.0 4.0 090 FL250 280" })
  check_eq(ex("schedule at 00:20:00: KLM88 climb to FL300"), "SCHEDULE 00:20:00 ALT KLM88 FL300")
  check_eq(ex("at 01:05:30: KLM88 speed 250"), "SCHEDULE 01:05:30 SPD KLM88 250")
end

-- Cycle 30 (R64): metres per minute are a rate, never a level ("climb 1200 m/min": asked); a level in metres
-- above FL450 (13716 m) is asked ("16000 m"), one below it converted
do
  local _, ex = scene({ "CRE KLM88 A320 52.0 4.0 090 FL250 280" })
  check(ex("have KLM88 climb 1200 m/min"):match("^ASK .*metres per min") ~= nil, "m/min")
  asked(ex("KLM88 climb 900 metres per minute"), "metres per minute")
  check(ex("KLM88 climb 16000 m"):match("^ASK Which altitude for KLM88") ~= nil, "16000 m")
  check_eq(ex("KLM88 climb 11600 m"), "ALT KLM88 38058")
end

-- Cycle 30 (R64): fast-forward "until" a time typed after it ("until t=30 min") is asked for a duration, never
-- run as fast-time until stopped; "until I say stop" is still FF alone
do
  local _, ex = scene({ "CRE KLM88 A320 52.0 4.0 090 FL250 280" })
  check(ex("FF until t=30 min"):match("^ASK For how long") ~= nil, "until t=30")
  asked(ex("fast forward until sim time 00:45:00"), "until a clock time")
  check_eq(ex("fast forward until I say stop"), "FF")
end

-- Cycle 30 (R64): a time typed in two parts ("at 10:30", "schedule at 00:15: ...") is hours and minutes or
-- minutes and seconds: asked, never dropped; "ff 2:30" is still fast-forward's own time
do
  local _, ex = scene({ "CRE KLM88 A320 52.0 4.0 090 FL250 280" })
  check(ex("at 11:45 KLM88 climb FL300"):match("^ASK .*'11:45'") ~= nil, "at hh:mm")
  check(ex("schedule at 00:25: KLM88 speed 250"):match("^ASK .*'00:25'") ~= nil, "schedule at mm:ss:")
  check(ex("ff 2:30"):match("^FF") ~= nil, "ff m:ss")
end

-- Cycle 30 (R64): "kill" before a route noun clears the route ("kill the whole route on KLM88"); "kill KLM88"
-- alone still deletes the aircraft, and a waypoint named still deletes only it
do
  local _, ex = scene({ "DEFWPT ALFA 52.3 4.8", "CRE KLM88 A320 52.0 4.0 090 FL250 280", "ADDWPT KLM88 ALFA" })
  check_eq(ex("kill the entire route on KLM88"), "DELRTE KLM88")
  check_eq(ex("kill ALFA from the route of KLM88"), "DELWPT KLM88 ALFA")
end

-- An altimeter setting is its word and one value: what follows it after a comma is read ("descend 3000 feet
-- QNH 1021, 180 knots" keeps its speed, never dropped); a bare number after it is still asked about
do
  local _, ex = scene({ "CRE NOZ77 DH8D 60.2 5.1 090 FL100 250" })
  check_eq(ex("NOZ77 descend 3000 feet QNH 1021, 180 knots"), "ALT NOZ77 3000 ; SPD NOZ77 180")
  check_eq(ex("NOZ77 descend 3000 feet QNH 1021"), "ALT NOZ77 3000")
  asked(ex("NOZ77 descend 3000 feet QNH 1021, 180"), "a bare number after the setting")
end

-- Cycle 32 (R66): a 737 said without its variant ("a 737", "a Spirit 737", "Boeing seven three seven") is
-- asked about as the 767 and 787 are: writers read it B737 or B738; a variant said or written is that one
do
  local _, ex = scene({ "CRE NKS44 A320 35.0 -97.0 090 FL150 280" })
  local which = "ASK Which variant of the 737 is meant: B733, B734, B735, B736, B737, B738, B739?"
  check_eq(ex("add a Spirit 737, NKS9, at 35.2 -97.1 heading 180 FL200 280 knots"), which)
  check_eq(ex("put in a boeing seven three seven called TST3 at 35.2 -97.1 heading 180 FL200 280 knots"), which)
  check_eq(ex("add a Boeing 737-900, NKS10, at 35.2 -97.1 heading 180 FL200 280 knots"),
    "CRE NKS10 B739 35.2 -97.1 180 FL200 280")
  check_eq(ex("add a Spirit 738, NKS11, at 35.2 -97.1 heading 180 FL200 280 knots"),
    "CRE NKS11 B738 35.2 -97.1 180 FL200 280")
end

-- Cycle 32 (R66): a rate said as a number and "a minute" or "per minute" without its feet is a vertical speed
-- [ft/min] ("climb at 1800 a minute", "descend at 3000 per minute down to 8000"); a number under 100 a
-- minute is no climb rate and is still asked about
do
  local _, ex = scene({ "CRE NKS44 A320 35.0 -97.0 090 FL150 280" })
  check_eq(ex("NKS44 climb and maintain flight level two zero zero, climb at 1800 a minute"), "ALT NKS44 FL200 1800")
  check_eq(ex("NKS44 descend at 3000 per minute down to eight thousand"), "ALT NKS44 8000 3000")
  asked(ex("NKS44 climb FL200 at 40 a minute"), "40 a minute is no climb rate")
end

-- Cycle 32 (R66): a level the next instruction waits for, said as "when you reach 12000" (Reach, RCH, is the
-- verb there, no callsign) or "when out of FL160" (a level left): ATALT; "out of" with no level still asks
do
  local _, ex = scene({ "CRE DAL19 A320 35.0 -97.0 090 FL200 300" })
  check_eq(ex("DAL19 descend to 12000 and when you reach 12000 turn right heading 180"),
    "ALT DAL19 12000 ; ATALT DAL19 12000 HDG DAL19 180 RIGHT")
  check_eq(ex("DAL19 descend and maintain one one thousand, once out of one four thousand reduce to 250"),
    "ALT DAL19 11000 ; ATALT DAL19 14000 SPD DAL19 250")
  asked(ex("DAL19 descend to 11000, when out of fuel slow to 250"), "out of no level")
end

-- Cycle 32 (R66): "is X still climbing?", "what's X up to": a question about what an aircraft is doing, no
-- value said, is its report (POS); with a level said it is still the climb
do
  local _, ex = scene({ "CRE SKW44 CRJ9 35.0 -97.0 090 8000 250" })
  check_eq(ex("is skywest 44 still descending?"), "POS SKW44")
  check_eq(ex("so what is SKW44 up to?"), "POS SKW44")
  check_eq(ex("SKW44 climbing FL200"), "ALT SKW44 FL200")
end

-- Cycle 32 (R66): the clock started by "start it" or "go ahead and start it" said alone (OP); a time's "mark"
-- ("pause it at the 20 minute mark") is the time's noun; "start it" with an aircraft named is no clock
do
  local _, ex = scene({ "CRE SKW44 CRJ9 35.0 -97.0 090 8000 250" })
  check_eq(ex("ok go ahead and start it"), "OP")
  check_eq(ex("start it please"), "OP")
  check_eq(ex("freeze it at the 35 minute mark"), "SCHEDULE 00:35:00 HOLD")
  asked(ex("SKW44 go ahead and start it"), "start it with an aircraft named")
end

-- Cycle 32 (R66): the digits of one Airbus or Boeing designator in the plural where random traffic is made
-- ("6 random 738s", "319s") are that designator; a family's number ("737s", "767s") names no one variant and
-- is still asked about
do
  local _, ex = scene({ "CRE SKW44 CRJ9 35.0 -97.0 090 8000 250" })
  check_eq(ex("add 6 random 738s at FL310"), "MCRE 6 B738 FL310")
  check_eq(ex("generate 4 random 319s"), "MCRE 4 A319")
  -- ("throw in": a verb of framing, as "put in")
  local _, ex2 = scene({ "CRE SKW44 CRJ9 35.0 -97.0 090 8000 250", "CRE SKW45 CRJ9 35.5 -97.0 090 9000 250" })
  check_eq(ex2("throw in 5 random 320s at FL280"), "MCRE 5 A320 FL280")
  asked(ex("add 6 random 767s at FL310"), "a family in the plural")
end

-- Cycle 32 (R66): a remark on the traffic before a comma ("traffic alert, DAL2104 turn left ...") leaves the
-- aircraft opening the next clause, its instruction straight after it, the one instructed; an aircraft after
-- "avoid the traffic," with no instruction of its own is still asked about
do
  local _, ex = scene({ "CRE DAL2104 A320 35.0 -97.0 090 FL250 280", "CRE AAL31 A320 35.1 -97.2 270 FL250 280" })
  check_eq(ex("traffic alert, DAL2104 turn right heading 180 now"), "HDG DAL2104 180 RIGHT")
  check_eq(ex("conflict alert, american 31 descend FL230"), "ALT AAL31 FL230")
  asked(ex("climb FL270 to avoid the traffic, AAL31"), "the aircraft after the comma, no instruction after it")
end

-- Cycle 32 (R65): Scandinavian telephony ("Viking": Sunclass; "Braathens") is a callsign's airline wherever the
-- callsign stands, after a verb too ("remove Viking 815"); the airline said before a typed callsign is its name;
-- a flight number no aircraft of that airline flies is still asked about
do
  local _, ex = scene({ "CRE VKG815 A321 57.0 11.0 090 FL200 300", "CRE BRX7PA AT76 58.0 12.0 180 7000 210" })
  check_eq(ex("remove Viking 815"), "DEL VKG815")
  check_eq(ex("move Braathens 7PA to 57.5 11.5"), "MOVE BRX7PA 57.5 11.5")
  check_eq(ex("Braathens seven papa alpha say altitude"), "POS BRX7PA")
  check_eq(ex("create Sunclass VKG22 A320 56.1 12.2 heading 045 FL 150 speed 280"), "CRE VKG22 A320 56.1 12.2 45 FL150 280")
  asked(ex("delete Viking 816"), "no such Viking flying")
end

-- Cycle 32 (R65): "own navigation" with a waypoint straight after it ("own navigation ALFA") resumes the route
-- there, a direct-to, as "own navigation to ALFA" does; a waypoint set off by a comma is still asked about
do
  local _, ex = scene({ "DEFWPT ALFA 60.3 24.9", "DEFWPT BRAVO 60.2 24.7", "CRE FIN4TK A320 60.5 25.5 250 FL110 270",
    "ADDWPT FIN4TK ALFA", "ADDWPT FIN4TK BRAVO" })
  check_eq(ex("FIN4TK own navigation BRAVO"), "DIRECT FIN4TK BRAVO")
  check_eq(ex("FIN4TK speed 220, resume own navigation ALFA"), "SPD FIN4TK 220 ; DIRECT FIN4TK ALFA")
  check_eq(ex("FIN4TK own navigation"), "LNAV FIN4TK ON")
  asked(ex("FIN4TK resume own navigation, BRAVO"), "a waypoint after a comma")
end

-- Cycle 32 (R65): "descend 3000 feet" typed from below FL120, in a terminal area, is the approach altitude
-- cleared; from higher up it is still asked whether to or by, and "from where it is" is still a step
do
  local _, ex = scene({ "CRE SAS77K A320 55.6 12.6 090 9000 230", "CRE SAS88 A320 55.9 12.9 180 FL160 280" })
  check_eq(ex("SAS77K descend 2000 feet, speed 180 knots"), "ALT SAS77K 2000 ; SPD SAS77K 180")
  check_eq(ex("SAS77K descend 3000 feet from where it is"), "ALT SAS77K 6000")
  check(ex("SAS88 descend 3000 ft"):match("^ASK Should SAS88 descend to 3000 ft or by 3000 ft") ~= nil, "from FL160")
end

-- Cycle 32 (R65): "cross WPT FL120", "cross WPT 5000 feet": a crossing with "at" left out, a level or a speed
-- straight after a waypoint of the route and ending the request, is its AT constraint; a waypoint off the route,
-- or another value after a comma, is still asked about
do
  local _, ex = scene({ "DEFWPT ALFA 60.3 24.9", "DEFWPT BRAVO 60.2 24.7", "CRE FIN4TK A320 60.5 25.5 250 FL150 270",
    "ADDWPT FIN4TK ALFA" })
  check_eq(ex("FIN4TK cross ALFA flight level 90"), "AT FIN4TK ALFA ALT FL90")
  check_eq(ex("FIN4TK cross ALFA 6000 ft"), "AT FIN4TK ALFA ALT 6000")
  check_eq(ex("FIN4TK cross ALFA 230 knots"), "AT FIN4TK ALFA SPD 230")
  asked(ex("FIN4TK cross BRAVO FL90"), "a waypoint off the route")
  asked(ex("FIN4TK cross ALFA FL90, speed 250 knots"), "a speed after a comma: now or at ALFA?")
end

-- Cycle 32 (R65): a speed held "until 4 miles", "till 6 DME", said last (an approach clearance after it at
-- most), is flown now and its end at the distance named as not simulated; a value after it ("until 5 DME then
-- 150"), a bare number ("until 4") or a limit beyond the final approach's 3 to 6 miles is still asked about
do
  local _, ex = scene({ "CRE NOZ41 B738 59.9 10.9 010 6000 210" })
  check_eq(ex("NOZ41 reduce 180 knots till 6 DME"), "SPD NOZ41 180")
  check_eq(ex("NOZ41 speed 170 until four miles final, cleared ILS 19R"), "SPD NOZ41 170")
  asked(ex("NOZ41 speed 170 until 5 DME then 150"), "a speed after the limit")
  asked(ex("NOZ41 speed 170 until 4"), "no distance named")
  asked(ex("NOZ41 reduce 240 knots until 9 miles"), "a limit beyond the final approach")
end

-- Cycle 32 (R65): the "conflict probe" is conflict detection, switched or set to a method ("switch the conflict
-- probe to state based"); with its look-ahead said it names that setting's owner, no switch
do
  local _, ex = scene({ "CRE SAS34 A320 55.6 12.6 090 FL150 250" })
  check_eq(ex("set the conflict probe to state-based"), "ASAS STATEBASED")
  check_eq(ex("conflict probe on please"), "ASAS ON")
  check_eq(ex("conflict probe look-ahead 4 minutes"), "DTLOOK 240")
end

-- Cycle 32 (R65): TrafScript's ECHO opening the request after a speaker's label ("supervisor: echo ...") prints
-- the words after it as typed, a time among them too; "echo" before spelled letters is still a registration
do
  local _, ex = scene({ "CRE EKLM C172 52.0 4.0 090 3000 100" })
  check_eq(ex("supervisor: echo break ends in 10 minutes"), "ECHO break ends in 10 minutes")
  check_eq(ex("echo kilo lima mike climb 4500 ft"), "ALT EKLM 4500")
  asked(ex("instructor: echo"), "no text")
end

-- Cycle 32 (R65): a request opening with the wind at a named place, where it blows from told after it ("wind
-- at Arlanda 270 degrees 25 knots", "wind over ALFA from 250 at 20 knots"), sets the wind there; with no
-- direction told it is no setting (asked)
do
  local _, ex = scene({ "DEFWPT ALFA 60.3 24.9", "CRE FIN4TK A320 60.5 25.5 250 FL110 270" })
  check_eq(ex("supervisor: wind over ALFA from 250 at 20 knots"), "WIND ALFA 250 20")
  check_eq(ex("wind at ALFA 300 degrees 15 knots"), "WIND ALFA 300 15")
  asked(ex("wind at ALFA 300 degrees"), "no speed told")
  local _, nx = navscene({ "CRE FIN4TK A320 60.5 25.5 250 FL110 270" }, "winds at an airport by its name")
  if nx then check_eq(nx("wind at Arlanda 270 degrees 25 knots"), "WIND ESSA 270 25") end
end

-- Cycle 32 (R54, R64): a condition of reaching a level said with "hit" ("when you hit FL120 slow to 250",
-- "when it hits that, speed 250") or with "when at" and "set" before the instruction waits for that level;
-- "hit FL120" with no condition word is no condition
do
  local _, ex = scene({ "CRE UAL9 B738 37.9 -122.5 140 10000 250" })
  check_eq(ex("UAL9: when you hit FL120 reduce to 240"), "ATALT UAL9 FL120 SPD UAL9 240")
  check_eq(ex("UAL9 once at 11000 set speed 230"), "ATALT UAL9 11000 SPD UAL9 230")
  check_eq(ex("UAL9 climb FL140, when it hits that slow to 230"), "ALT UAL9 FL140 ; ATALT UAL9 FL140 SPD UAL9 230")
  check_eq(ex("UAL9 hit FL120 and slow to 240"), "ALT UAL9 FL120 ; SPD UAL9 240")
end

-- Cycle 32 (R64): a signed value with no unit after the value's name is a change ("spd -15", "altitude +1500",
-- "descend -1000", "hdg +25"); a sign against the verb ("climb -1000") is asked; typed TrafScript in capitals
-- keeps its own reading
do
  local _, ex = scene({ "CRE SKW7 CRJ9 37.5 -121.9 270 7000 220" })
  check_eq(ex("SKW7 spd -15"), "SPD SKW7 205")
  check_eq(ex("SKW7 altitude +1500"), "ALT SKW7 8500")
  check_eq(ex("SKW7 descend -1000"), "ALT SKW7 6000")
  check_eq(ex("SKW7 hdg +25"), "HDG SKW7 295 RIGHT")
  check_eq(ex("SKW7 heading -40"), "HDG SKW7 230 LEFT")
  asked(ex("SKW7 climb -1000"), "a sign against the verb")
end

-- Cycle 32 (R64): a heading said before its name ("fly a 240 heading", "the 090 heading") and a position typed
-- as "lat,lon" with no space ("37.2,-121.4")
do
  local _, ex = scene({ "CRE SKW7 CRJ9 37.5 -121.9 270 7000 220" })
  check_eq(ex("give SKW7 a 240 heading"), "HDG SKW7 240")
  check_eq(ex("SKW7 back on the 090 heading"), "HDG SKW7 90")
  check_eq(ex("create QXE4 type DH8D at 37.2,-121.4, heading 090, 5000 ft, 200 kt"), "CRE QXE4 DH8D 37.2 -121.4 90 5000 200")
  asked(ex("SKW7 a heading"), "a heading with no value")
end

-- Cycle 32 (R64): a change said with "more"/"less" after its amount and unit, or "gain"/"lose" before it
-- ("15 kt less", "lose 1500 ft", "gain 1000 feet"); "more or less" and "less than" are no change, and a signed
-- vertical speed stays a rate
do
  local _, ex = scene({ "CRE SKW7 CRJ9 37.5 -121.9 270 7000 220" })
  check_eq(ex("SKW7 speed 15 kt less"), "SPD SKW7 205")
  check_eq(ex("SKW7 10 knots more"), "SPD SKW7 230")
  check_eq(ex("SKW7 has to lose 1500 ft"), "ALT SKW7 5500")
  check_eq(ex("SKW7 gain 1000 feet"), "ALT SKW7 8000")
  check_eq(ex("SKW7 vertical speed -1500"), "VS SKW7 -1500")
  asked(ex("SKW7 speed 20 kt less than the leader"), "less than: a bound, not a change")
end

-- Cycle 32 (R64): a level said after a vertical speed with "to" or "target" is the level it flies to ("800 fpm
-- down to 5000", "vs 1500 up, target 9000"): a VS and an ALT; a level on the other side from the rate's
-- direction is asked
do
  local _, ex = scene({ "CRE SKW7 CRJ9 37.5 -121.9 270 7000 220" })
  check_eq(ex("SKW7 800 fpm down to 5000"), "VS SKW7 -800 ; ALT SKW7 5000")
  check_eq(ex("SKW7 vs 1500 up, target 9000"), "VS SKW7 1500 ; ALT SKW7 9000")
  check_eq(ex("SKW7 vs 1500"), "VS SKW7 1500")
  asked(ex("SKW7 vs 1500 up to 5000"), "a climb to a lower level")
end

-- Cycle 32 (R64): "time compression", "time acceleration" name the simulation's rate ("8x time compression",
-- "time acceleration 2x"); said with no rate it is asked
do
  local _, ex = scene({ "CRE SKW7 CRJ9 37.5 -121.9 270 7000 220", "CRE UAL5 B738 37.0 -122.0 100 8000 250" })
  check_eq(ex("8x time compression please"), "DTMULT 8")
  check_eq(ex("time acceleration 2x, SKW7 descend 5000"), "DTMULT 2 ; ALT SKW7 5000")
  asked(ex("more time compression"), "no rate said")
end

-- Cycle 32 (R64): the reproducibility a request is made for is a remark ("seed 13 for repeatability", "keep
-- it deterministic"); the word alone is no instruction, asked
do
  local _, ex = scene({ "CRE SKW7 CRJ9 37.5 -121.9 270 7000 220" })
  check_eq(ex("seed 13 for repeatability"), "SEED 13")
  asked(ex("reproducible"), "a remark alone")
end

-- A bare number right after a verb that introduces a value (lexicon.clause_verbs: "fly 270") before another
-- instruction is a value of its own: carried by a command or asked about, never dropped ("fly 270 and
-- maintain 9000" gave the level alone); "turn 270 and maintain 9000" is both instructions
do
  local _, ex = scene({ "CRE UAL456 B738 37.0 -122.0 090 FL100 280" })
  asked(ex("UAL456 fly 270 and maintain 9000"), "heading or level 270, dropped before")
  asked(ex("UAL456 fly 270, then descend 9000"), "the same after a comma and then")
  check_eq(ex("UAL456 turn 270 and maintain 9000"), "HDG UAL456 270 ; ALT UAL456 9000")
  check_eq(ex("UAL456 fly heading 270 and maintain 9000"), "HDG UAL456 270 ; ALT UAL456 9000")
end

-- Cycle 32 (R66): "separation" with a distance or height said just before it ("a 4 nm separation", "2000 ft
-- separation vertically") sets the protected zone; with an aircraft named it is no setting (asked)
do
  local _, ex = scene({ "CRE AFR61 A320 48.9 2.5 270 FL120 260", "CRE AFR62 A320 48.9 2.9 270 FL120 260" })
  check_eq(ex("we run a 4 nm separation laterally"), "ZONER 4")
  check_eq(ex("let's try 2000 ft separation vertically"), "ZONEDH 2000")
  asked(ex("AFR61 keep 6 miles separation from AFR62"), "an aircraft kept apart")
end

-- Cycle 32 (R66): "resolution" straight after "for"/"after" with CPA said just before it names whose end the
-- aircraft resume past ("resume nav past CPA for resolution"), no resolution setting; said on its own after a
-- comma it is still a setting
do
  local _, ex = scene({ "CRE IBE31 A320 40.4 -3.6 090 FL200 260" })
  check_eq(ex("let them resume navigation past CPA after resolution"), "RESNAV PASTCPA")
  check_eq(ex("resolution MVP, then resume nav past cpa"), "RESO MVP ; RESNAV PASTCPA")
end

-- Cycle 32 (R66): a navaid said by its two-word navdata name after "add" and before "to" ("add point reyes to
-- UAL812's route") is added to the route; two words naming no navaid near the traffic are asked about
do
  local _, nx = navscene({ "CRE UAL812 B738 37.6 -122.4 300 FL120 250" }, "two-word navaid names")
  if nx then
    check_eq(nx("please add point reyes to UAL812's route"), "ADDWPT UAL812 PYE")
    asked(nx("add point blank to the route of UAL812"), "no navaid of that name")
  end
end

-- Cycle 32 (R66): a level said as what the aircraft is going to level at ("is gonna level at niner thousand",
-- "will level at FL110") is the level cleared; a bare number too small for a level ("level at 40") is asked
do
  local _, ex = scene({ "CRE RYR45 B738 53.4 -6.3 090 FL090 260" })
  check_eq(ex("ryanair 45 is gonna level at one one thousand, keep him there"), "ALT RYR45 11000")
  check_eq(ex("RYR45 is going to level at FL130"), "ALT RYR45 FL130")
  check_eq(ex("RYR45 will level at 7000 then turn right heading 120"), "ALT RYR45 7000 ; HDG RYR45 120 RIGHT")
  asked(ex("RYR45 level at 40"), "no level")
end

-- Cycle 32 (R65, R66): a typed ident of letters and digits that no aircraft bears, said with an aircraft flying
-- named, is the navdata's fix near the traffic ("SAS4102 direct BR421"), no callsign; one no place bears
-- is still asked about, and digits with an "x" typed onto them are a rate ("go 2x"), no callsign
do
  local _, nx = navscene({ "CRE SAS4102 A320 60.55 4.80 140 FL130 280", "ADDWPT SAS4102 ELDOS" },
    "fix idents with digits")
  if nx then
    check_eq(nx("SAS4102 proceed direct BR421"), "ADDWPT SAS4102 BR421 ; DIRECT SAS4102 BR421")
    check_eq(nx("SAS4102 add BR421 then ELDOS to the route"), "ADDWPT SAS4102 BR421 ; ADDWPT SAS4102 ELDOS")
    asked(nx("SAS4102 direct BR499"), "no place of that ident")
    asked(nx("BR421 climb FL200"), "no aircraft named")
  end
  local _, ex = scene({ "CRE KLM12 B738 52.0 4.0 090 FL100 250" })
  check_eq(ex("ok go 3x"), "DTMULT 3")
  -- ("so the ..." opening the request, after fillers only, is no reason: the instruction after it is read)
  check_eq(ex("ok so the sim is kinda sluggish, go 3x"), "DTMULT 3")
  check_eq(ex("seed 7 so the runs are repeatable"), "SEED 7")
end

-- A speaker's label of two words written with no colon, as speech recognition gives it ("sim op delete
-- speedbird one one", "sim operator pause the simulation"), is no part of the request: "op" in it is no OP
do
  local _, ex = scene({ "CRE BAW11 A320 1.0 1.0 000 FL100 250" })
  check_eq(ex("sim op delete speedbird one one"), "DEL BAW11")
  check_eq(ex("sim operator pause the simulation"), "HOLD")
  check_eq(ex("pseudo pilot speedbird one one climb flight level one two zero"), "ALT BAW11 FL120")
  check_eq(ex("sim op"), "OP")
end

-- Cycle 33 (R67): airlines of the Asia-Pacific area by their ICAO telephony ("velocity", "hong kong shuttle"
-- run together or apart, "jetstar asia"), and "jetstar" alone before a flight number naming whichever
-- Jetstar airline flies it; a flight number none of them flies is still asked about, and "velocity" before
-- a speed is still the speed noun
do
  local _, ex = scene({ "CRE VOZ456 B738 -27.4 153.1 180 FL200 280", "CRE HKE521 A320 22.3 114.2 090 FL150 250",
    "CRE JSA77 A320 1.4 104.0 270 FL120 250", "CRE JST915 A321 -37.7 144.8 000 FL100 250" })
  check_eq(ex("velocity four five six climb flight level two four zero"), "ALT VOZ456 FL240")
  check_eq(ex("hongkong shuttle five two one turn left heading two seven zero"), "HDG HKE521 270 LEFT")
  check_eq(ex("hong kong shuttle five two one reduce speed two two zero knots"), "SPD HKE521 220")
  check_eq(ex("jetstar asia seven seven descend five thousand feet"), "ALT JSA77 5000")
  check_eq(ex("jetstar seven seven descend five thousand feet"), "ALT JSA77 5000")
  check_eq(ex("jetstar nine one five climb flight level one three zero"), "ALT JST915 FL130")
  check_eq(ex("HKE521 velocity 240 knots"), "SPD HKE521 240")
  local _, ex2 = scene({ "CRE HKE521 A320 22.3 114.2 090 FL150 250" })
  check_eq(ex2("please reduce the velocity of HKE521 to 220 knots"), "SPD HKE521 220")
  asked(ex("velocity four five seven climb flight level two four zero"), "no Velocity 457 flies")
  asked(ex("jetstar nine one six climb flight level one three zero"), "no Jetstar 916 flies")
end

-- Cycle 33 (R67): a new aircraft's type designator spelled in the phonetic alphabet, its digits said singly
-- ("bravo seven three eight", "bravo seven seven whiskey"), is that designator when squawk knows it; a
-- spelling of none is still asked about
do
  local _, ex = scene({})
  check_eq(ex("create qantas nine eight bravo seven eight niner at one decimal zero north one zero three decimal "
    .. "five east heading zero nine zero flight level two zero zero two eight zero knots"),
    "CRE QFA98 B789 1 103.5 90 FL200 280")
  check_eq(ex("sim op create singapore four one bravo seven seven whiskey at one decimal two north one zero four "
    .. "decimal zero east heading one eight zero flight level three one zero two niner zero knots"),
    "CRE SIA41 B77W 1.2 104 180 FL310 290")
  asked(ex("create qantas nine eight bravo seven eight three at one decimal zero north one zero three decimal "
    .. "five east heading zero nine zero flight level two zero zero two eight zero knots"), "no type B783")
end

-- Cycle 33 (R67): "maintain heading", "keep your heading", said with no value, is the heading the aircraft
-- flies; a heading said with it is that heading, and "maintain" alone still asks what is kept
do
  local _, ex = scene({ "CRE ANZ88 A320 -36.9 174.8 135 FL110 250" })
  check_eq(ex("new zealand eight eight maintain heading"), "HDG ANZ88 135")
  check_eq(ex("new zealand eight eight keep your heading and climb flight level one five zero"),
    "HDG ANZ88 135 ; ALT ANZ88 FL150")
  check_eq(ex("new zealand eight eight maintain heading one five zero"), "HDG ANZ88 150")
  asked(ex("new zealand eight eight maintain"), "nothing said to keep")
end

-- Cycle 33 (R67): South-East Asian cities whose one large airport the navdata names otherwise ("Manila" is
-- NINOY AQUINO INTL, "Jakarta" SOEKARNO HATTA INTL) are that airport; a city of two airports is still asked
do
  local _, nx = navscene({ "CRE PAL215 A321 14.0 121.5 180 FL200 280", "CRE GIA702 A333 -6.5 107.0 180 FL200 280" },
    "South-East Asian cities")
  if nx then
    check_eq(nx("philippine two one five set destination manila"), "DEST PAL215 RPLL")
    check_eq(nx("garuda seven zero two divert to jakarta"), "DEST GIA702 WIII")
    asked(nx("garuda seven zero two divert to tokyo"), "two airports")
  end
end

-- Cycle 33 (R67): knots said after a word speech recognition writes for "to" or "two" ("reduce speed too two
-- zero knots") are no change of speed (the assigned speed's first digit may be lost): asked; "reduce speed
-- two zero knots" with nothing before it is still 20 kt slower
do
  local _, ex = scene({ "CRE MAS52 A333 3.0 101.5 045 FL110 260" })
  asked(ex("malaysian five two reduce speed too two zero knots"), "too before two digits")
  check_eq(ex("malaysian five two reduce speed two zero knots"), "SPD MAS52 240")
  check_eq(ex("malaysian five two reduce speed too two two zero knots"), "SPD MAS52 220")
end

-- Cycle 33 (R68): a speed's level after "above" or "below" ("Mach .80 above FL310", "speed 240 below FL90") is
-- the level the speed waits for (ATALT), never a level to fly; "not below" is no such condition and is asked
do
  local _, ex = scene({ "CRE IBE33 A321 40.0 -3.0 045 FL250 290" })
  check_eq(ex("IBE33 Mach .80 above FL310"), "ATALT IBE33 FL310 SPD IBE33 M0.8")
  check_eq(ex("IBE33 speed 240 below FL90"), "ATALT IBE33 FL90 SPD IBE33 240")
  check_eq(ex("IBE33 220 kt below FL120, thanks"), "ATALT IBE33 FL120 SPD IBE33 220")
  check_eq(ex("IBE33 climb FL330 and Mach .80 above FL310"), "ALT IBE33 FL330 ; ATALT IBE33 FL310 SPD IBE33 M0.8")
  asked(ex("IBE33 speed 260 not below FL110"), "a limit, no condition")
  asked(ex("IBE33 below FL110"), "no verb, no speed")
  -- (two speeds, the level holding only the second: asked, never the level flown nor the condition on both)
  asked(ex("IBE33 speed 280 kt, Mach .79 above FL290"), "two speeds, one level")
end

-- Cycle 33 (R68): a distance from a place opening a clause after the instruction's value ("descend FL90 and
-- from 12 NM before GOLFA 200 kt") holds the value after it alone, not the instruction before
do
  local _, ex = scene({ "CRE BEE7Q DH8D 50.0 -4.0 090 FL140 240", "DEFWPT GOLFA 50.1 -3.0" })
  check_eq(ex("BEE7Q descend FL90 and from 12 NM before GOLFA 200 kt"),
    "ALT BEE7Q FL90 ; ATDIST BEE7Q GOLFA 12 SPD BEE7Q 200")
  check_eq(ex("BEE7Q descend FL90, at 15 NM from GOLFA 210 kt"), "ALT BEE7Q FL90 ; ATDIST BEE7Q GOLFA 15 SPD BEE7Q 210")
  check_eq(ex("BEE7Q 20 NM before GOLFA descend FL90"), "ATDIST BEE7Q GOLFA 20 ALT BEE7Q FL90")
end

-- Cycle 33 (R68): "climb 4000 ft" or more in feet below the aircraft is a cleared altitude on the wrong side,
-- asked, never a climb by that much; so is a small amount ("climb 2000 ft"); "up 4000" and "by 5000" are steps
do
  local _, ex = scene({ "CRE VLG3C A320 41.0 2.0 300 FL80 230" })
  asked(ex("VLG3C climb 5000 ft"), "a level below, said after climb")
  asked(ex("VLG3C climb 4000 ft"), "a level below, said after climb")
  asked(ex("VLG3C climb 2000 ft"), "a small amount below the aircraft, no 'by': to or by?")
  check_eq(ex("VLG3C climb by 5000 ft"), "ALT VLG3C 13000")
end

-- Cycle 33 (R68): a creation "ready for departure" or "ready for take-off" is on the ground (altitude 0, speed
-- 0), as "on the ground" is; with a level said too, asked
do
  local _, ex = scene({})
  check_eq(ex("create BEL4Q A319 at 50.9 4.5 heading 250 ready for departure"), "CRE BEL4Q A319 50.9 4.5 250 0 0")
  check_eq(ex("create BEL4Q A319 at 50.9 4.5 heading 250, ready for take off"), "CRE BEL4Q A319 50.9 4.5 250 0 0")
  asked(ex("create BEL4Q A319 at 50.9 4.5 heading 250 ready for departure FL90"), "ground and a level")
end

-- Cycle 33 (R68): flight-deck words: "engage"/"disengage" switch a navigation mode on/off ("engage LNAV",
-- "VNAV disengaged"); a selector named after the value's name ("HDG SEL 270", "SPD SEL 240") is that value;
-- "V/S +1800" is a climb of 1800 ft/min; "engage" with no mode named is still asked
do
  local _, ex = scene({ "CRE SAS5N A20N 59.0 17.0 200 FL240 280" })
  check_eq(ex("SAS5N engage LNAV"), "LNAV SAS5N ON")
  check_eq(ex("SAS5N VNAV disengaged"), "VNAV SAS5N OFF")
  check_eq(ex("SAS5N disengage LNAV and HDG SEL 230"), "LNAV SAS5N OFF ; HDG SAS5N 230")
  check_eq(ex("SAS5N SPD SEL 240 and ALT SEL FL200"), "SPD SAS5N 240 ; ALT SAS5N FL200")
  check_eq(ex("SAS5N V/S +1800"), "VS SAS5N 1800")
  check_eq(ex("SAS5N V/S -1200"), "VS SAS5N -1200")
  asked(ex("SAS5N engage"), "no mode named")
end

-- Cycle 33 (R68): the held value named by "once you have it" ("slow to 240 kt and once you have it V/S -1500":
-- ATSPD), and a speed with "when passing" and a level after it inside a level clearance ("climb FL190, Mach
-- .75 when passing FL170": ATALT); "once you have it" with nothing before it is still asked
do
  local _, ex = scene({ "CRE DLH9P A320 50.0 8.0 090 FL150 290" })
  check_eq(ex("DLH9P slow to 240 kt and once you have it V/S -1500"), "SPD DLH9P 240 ; ATSPD DLH9P 240 VS DLH9P -1500")
  check_eq(ex("DLH9P climb FL190, Mach .75 when passing FL170"), "ALT DLH9P FL190 ; ATALT DLH9P FL170 SPD DLH9P M0.75")
  asked(ex("DLH9P once you have it descend FL100"), "nothing held before it")
end

-- Cycle 33 (R68): sim control in pilot terms: "sim speed half" / "sim speed 3" is the clock's rate; "for
-- debrief" names the session's step (a purpose); the FMS's "FPLN" and "the route page" show the route
do
  local _, ex = scene({ "CRE AFR9T A321 45.0 5.0 090 FL300 280" })
  check_eq(ex("sim speed half"), "DTMULT 0.5")
  check_eq(ex("sim speed 3"), "DTMULT 3")
  check_eq(ex("pause the sim for debriefing"), "HOLD")
  check_eq(ex("AFR9T show me the FPLN"), "LISTRTE AFR9T")
  check_eq(ex("AFR9T give me the route page"), "LISTRTE AFR9T")
  asked(ex("AFR9T give me the page"), "no page named")
end

-- Cycle 33 (R68): a role's "note:" before the request ("pseudo-pilot note: ...") is a speaker's label, no
-- ECHO ("note: ..." alone stays a note); a vertical rate's bound typed before its value ("RoD max 1800") is
-- that rate
do
  local _, ex = scene({ "CRE TVS2K B738 49.0 14.0 300 FL200 270" })
  check_eq(ex("pseudo-pilot note: TVS2K climb FL240"), "ALT TVS2K FL240")
  check_eq(ex("note: TVS2K is slow today"), "ECHO TVS2K is slow today")
  check_eq(ex("TVS2K RoD max 1800"), "VS TVS2K -1800")
  check_eq(ex("TVS2K RoC min 700"), "VS TVS2K 700")
  asked(ex("TVS2K RoD max"), "no rate said")
end

-- Cycle 33 (R68): "overhead" names the place of a wind as "over" does; "at sim time 00:05:00" is the clock's
-- time a command is scheduled for; "sim time 00:05:00" with no "at" is still asked
do
  local _, ex = scene({ "DEFWPT WINDY 50.9 4.5" })
  check_eq(ex("what's the wind at FL120 overhead WINDY?"), "GETWIND WINDY FL120")
  check_eq(ex("at sim time 00:05:00 freeze"), "SCHEDULE 00:05:00 HOLD")
  asked(ex("sim time 00:05:00 freeze"), "no 'at' before the time")
end

-- Cycle 33 (R68): quoted text put "on the screen" is an ECHO, as for the log; the French "monte" before a
-- level is a climb ("monte FL150"), "monte" alone still asked
do
  local _, ex = scene({ "CRE AFR3Z A320 44.0 1.0 090 FL100 250" })
  check_eq(ex("put 'Block B start' on the screen"), "ECHO Block B start")
  check_eq(ex("AFR3Z monte FL140 merci"), "ALT AFR3Z FL140")
  asked(ex("AFR3Z monte"), "no level said")
end

-- Cycle 33 (R68): "vector to X" after a heading tells the pilot where the vector leads: the heading is flown,
-- no direct-to; said alone it sends nothing
do
  local vsim, ex = scene({ "CRE SAS7V CRJ9 55.0 12.0 020 FL130 270", "DEFWPT VECTA 55.5 12.5" })
  check_eq(ex("SAS7V turn left heading 350, vector to VECTA"), "HDG SAS7V 350 LEFT")
  local r = graph.translate("SAS7V vector to VECTA", { sim = vsim, mode = "offline" })
  check(#(r.commands or {}) == 0, "a vector alone sends nothing")
end

-- Cycle 33 (R68): a waypoint added "at the end" (of the route, where ADDWPT puts it) is an ADDWPT; "at the
-- start" is still asked
do
  local _, ex = scene({ "CRE CFG2E A321 53.0 9.0 200 FL300 280", "DEFWPT ENDPT 52.0 8.0" })
  check_eq(ex("CFG2E add ENDPT at the end"), "ADDWPT CFG2E ENDPT")
  asked(ex("CFG2E add ENDPT at the start"), "not the end of the route")
end

-- Cycle 33 (R68): "direct" closing the clause after "to" and a place ("to DIRPT direct") flies direct to that
-- place, the word itself no place's name heard
do
  local _, ex = scene({ "CRE EZY4D A320 52.0 4.6 180 FL190 290", "DEFWPT DIRPT 51.5 4.6" })
  check_eq(ex("EZY4D to DIRPT direct"), "ADDWPT EZY4D DIRPT ; DIRECT EZY4D DIRPT")
  asked(ex("EZY4D to direct"), "no place said")
end

-- Cycle 33 (R68): a flight path angle ("FPA -3") is not simulated: its value is accounted for and the rest of
-- the request runs; "FPA" with no value is asked about
do
  local _, ex = scene({ "CRE HOP3F E145 47.0 2.0 270 FL60 220" })
  check_eq(ex("HOP3F FPA -3 and speed 170"), "SPD HOP3F 170")
  asked(ex("HOP3F FPA and speed 170"), "no angle said")
end

-- Cycle 34 (R69): an "expect" clause announces all of its instruction words, up to its first comma ("expect to
-- resume own navigation to X" sends no direct-to); an instruction after the comma is still given
do
  local _, ex = scene({ "CRE SXS5E B738 40.0 30.0 090 FL210 280", "DEFWPT EXPTA 40.5 31.0",
    "ADDWPT SXS5E EXPTA" })
  check_eq(ex("SXS5E descend flight level 150, expect to resume own navigation to EXPTA in a few minutes"),
    "ALT SXS5E FL150")
  check_eq(ex("SXS5E expect to be given direct EXPTA later, turn right heading 120"), "HDG SXS5E 120 RIGHT")
end

-- Cycle 34 (R69): what a person did, said in the past tense ("the trainee cleared him direct X"), is a report,
-- no instruction; "cleared" after the callsign is still the clearance
do
  local _, ex = scene({ "CRE AEE7N A320 38.0 23.0 180 FL250 290", "DEFWPT NARRA 37.5 23.2",
    "DEFWPT NARRB 37.0 23.4", "ADDWPT AEE7N NARRA", "ADDWPT AEE7N NARRB" })
  check_eq(ex("remove NARRA from the route of AEE7N, the trainee already cleared him direct NARRB"),
    "DELWPT AEE7N NARRA")
  check_eq(ex("AEE7N cleared direct NARRB"), "DIRECT AEE7N NARRB")
end

-- Cycle 34 (R69): a speed said with no verb after a crossing's level and a comma or "and" ("cross X at FL110,
-- speed 250 knots") is the crossing's or one for now: asked; "and 250 knots" in the crossing is its own
do
  local _, ex = scene({ "CRE TAP3X A320 39.0 -8.0 000 FL250 290", "DEFWPT CROSA 40.0 -8.0",
    "ADDWPT TAP3X CROSA" })
  asked(ex("TAP3X cross CROSA at flight level 120, speed 240 knots"), "the speed's place not said")
  asked(ex("TAP3X cross CROSA at flight level 120 and speed 240 knots"), "the speed's place not said")
  check_eq(ex("TAP3X cross CROSA at flight level 120 and 240 knots"),
    "AT TAP3X CROSA ALT FL120 ; AT TAP3X CROSA SPD 240")
  check_eq(ex("TAP3X cross CROSA at flight level 120, reduce speed 240 knots"),
    "AT TAP3X CROSA ALT FL120 ; SPD TAP3X 240")
end

-- Cycle 34 (R69): "speed up the simulation" with no rate and no duration is asked (DTMULT by how much, or FF
-- for how long?); with either it is that command, and "fast forward" alone is fast time with no end
do
  local _, ex = scene({})
  asked(ex("Could you speed the simulation up a little?"), "no rate nor duration")
  check_eq(ex("speed the simulation up by a factor of three"), "DTMULT 3")
  check_eq(ex("speed up the simulation for ten minutes"), "FF 600")
  check_eq(ex("fast forward"), "FF")
end

-- Cycle 34 (R69): simulation control said the instructor's way: the sim's speed "back to normal, real time" is
-- DTMULT 1; "instructor to sim operator:" and "exercise note:" are labels; the exercise "interrupted" is a pause
do
  local _, ex = scene({})
  check_eq(ex("put the sim speed back to real time"), "DTMULT 1")
  check_eq(ex("Supervisor to pseudo pilot: pause the simulation"), "HOLD")
  check_eq(ex("Scenario note: pause the simulation."), "HOLD")
  check_eq(ex("we interrupt the exercise here"), "HOLD")
  asked(ex("Budget note: pause the simulation."), "no role's nor exercise's note")
end

-- Cycle 34 (R69): a speed instruction and, after it, one that waits for a level passed ("reduce speed 250 knots,
-- when passing FL150 reduce speed 210 knots") are two instructions, the second waiting for that level only; a
-- correction between two speeds still keeps the last
do
  local _, ex = scene({ "CRE SWR4P A320 47.0 8.0 270 FL220 290" })
  check_eq(ex("SWR4P descend FL120, speed 260 knots, when passing FL160 reduce speed 230 knots"),
    "ALT SWR4P FL120 ; SPD SWR4P 260 ; ATALT SWR4P FL160 SPD SWR4P 230")
  check_eq(ex("SWR4P speed 260 knots, correction, speed 240 knots"), "SPD SWR4P 240")
end

-- Cycle 34 (R69): a limit that ends at a place or a distance ("until 5 miles final") may be
-- followed by a clause of its own opened by an imperative verb after a comma: that instruction is given; after
-- "then" it waits for the limit's end, still asked
do
  local _, ex = scene({ "CRE AUA9L A320 48.0 16.0 290 FL90 240" })
  check_eq(ex("AUA9L speed 170 knots until 4 miles final, descend to 3000 feet"), "SPD AUA9L 170 ; ALT AUA9L 3000")
  asked(ex("AUA9L speed 170 knots until 4 miles final, then descend to 3000 feet"), "waits for the limit's end")
end

-- Cycle 34 (R70): verb-final deletion: the verb closing the clause acts on the object before it ("waypoint X
-- delete" takes the waypoint off the route, "route clear" the route); a deletion after a noun that is no
-- aircraft is asked, never the aircraft deleted
do
  local _, ex = scene({ "CRE HVN7D A321 21.0 105.8 090 FL250 280", "DEFWPT PHOWP 21.2 106.2",
    "DEFWPT QUAWP 21.4 106.6", "ADDWPT HVN7D PHOWP", "ADDWPT HVN7D QUAWP" })
  check_eq(ex("HVN7D waypoint QUAWP erase"), "DELWPT HVN7D QUAWP")
  check_eq(ex("HVN7D waypoint PHOWP remove please"), "DELWPT HVN7D PHOWP")
  check_eq(ex("HVN7D route all delete"), "DELRTE HVN7D")
  asked(ex("HVN7D level delete"), "a level is no object of a deletion")
  asked(ex("HVN7D route is clear"), "a route described, no deletion")
  asked(ex("HVN7D route clear of weather"), "words after the verb")
end

-- Cycle 34 (R70): a state word said before "tell me" / "let me know" (verb-final order) asks for the report
do
  local _, ex = scene({ "CRE TGW5R A320 1.3 103.9 180 FL330 290" })
  check_eq(ex("TGW5R present speed let me know"), "POS TGW5R")
  check_eq(ex("TGW5R heading tell me"), "POS TGW5R")
  check_eq(ex("TGW5R climb FL350"), "ALT TGW5R FL350")
end

-- Cycle 34 (R70): the pause left ("from pause") is no new one; the simulation named before "stop" pauses it;
-- a courtesy word closing ECHO's text is not printed
do
  local _, ex = scene({})
  check_eq(ex("resume from pause"), "OP")
  check_eq(ex("simulation stop for a second"), "HOLD")
  check_eq(ex("echo baseline done please"), "ECHO baseline done")
  check_eq(ex("echo please wait"), "ECHO please wait")
end

-- Cycle 34 (R70): "speed 300 to 260 reduce", "heading 090 to 110 change": two values with "to" between, the
-- first the aircraft's present one, give the value it leaves and the one it flies to; a first value that is
-- not the present one is asked about
do
  local _, ex = scene({ "CRE CPA9V A333 22.3 114.2 270 FL310 290" })
  check_eq(ex("CPA9V speed 290 to 250 reduce"), "SPD CPA9V 250")
  check_eq(ex("CPA9V heading 270 to 300 change"), "HDG CPA9V 300")
  check_eq(ex("CPA9V FL310 to FL270 descend"), "ALT CPA9V FL270")
  asked(ex("CPA9V heading 180 to 300 change"), "180 is not its heading")
  asked(ex("CPA9V speed 240 to 250 reduce"), "240 is not its speed")
end

-- Cycle 34 (R70): a verb of showing closing the request after the noun ("route list please", "position
-- check") shows it; a verb followed by more words is not read so
do
  local _, ex = scene({ "CRE JJA4Q B738 33.5 126.5 010 FL280 280" })
  check_eq(ex("JJA4Q route list please"), "LISTRTE JJA4Q")
  check_eq(ex("JJA4Q position check"), "POS JJA4Q")
  asked(ex("JJA4Q route check twice"), "words after the verb")
end

-- Cycle 34 (R70): a direct-to in verb-final order: "go PLACE direct", "to PLACE direct go", "to PLACE go
-- straight" fly direct to the place said before the word; no place said is still asked
do
  local _, ex = scene({ "CRE ASV3G A320 24.0 121.0 045 FL240 270", "DEFWPT NORWP 24.5 121.5",
    "DEFWPT EASWP 24.2 122.0", "ADDWPT ASV3G NORWP", "ADDWPT ASV3G EASWP" })
  check_eq(ex("ASV3G go EASWP direct"), "DIRECT ASV3G EASWP")
  check_eq(ex("ASV3G to EASWP direct go"), "DIRECT ASV3G EASWP")
  check_eq(ex("ASV3G to NORWP go straight please"), "DIRECT ASV3G NORWP")
  asked(ex("ASV3G go straight"), "no place said")
end

-- Cycle 34 (R70): "maintain" / "keep" said after the value with its unit (verb-final order) keeps that value;
-- a bare number before it is still asked
do
  local _, ex = scene({ "CRE TTW6M A320 25.0 121.2 200 FL230 260" })
  check_eq(ex("TTW6M mach 0.78 maintain please"), "SPD TTW6M M0.78")
  check_eq(ex("TTW6M FL230 keep"), "ALT TTW6M FL230")
  asked(ex("TTW6M 290 maintain"), "a number with no unit")
end

-- Cycle 34 (R70): in a list of instructions each said verb-final ("heading 070, FL240 climb, speed 300"), the
-- value with its unit just before a verb, after a comma closing the instruction before, is that verb's
do
  local _, ex = scene({ "CRE EVA3L B789 25.1 121.2 090 FL200 280" })
  check_eq(ex("EVA3L heading 120, FL260 climb, speed 300"), "HDG EVA3L 120 ; ALT EVA3L FL260 ; SPD EVA3L 300")
  check_eq(ex("EVA3L FL260 climb, 250 knots reduce"), "ALT EVA3L FL260 ; SPD EVA3L 250")
  asked(ex("EVA3L heading 120, climb, speed 300"), "no level said")
end

-- Cycle 34 (R70): "pause release", "release the pause": the pause ended (OP), no new one
do
  local _, ex = scene({})
  check_eq(ex("release the pause"), "OP")
  check_eq(ex("pause release"), "OP")
  check_eq(ex("pause"), "HOLD")
end

-- Cycle 35 (R71): a navaid named after a city whose airport lies beside it under a longer name ("Sanford":
-- the SFB NDB, KSFB "ORLANDO SANFORD INTL") in a direct-to is the one of the two the route holds, else asked;
-- the navaid's kind said ("the Sanford NDB") is the navaid
do
  local _, ex = navscene({ "CRE ASH88 E75L 29.20 -81.10 200 8000 240", "ADDWPT ASH88 KSFB",
    "CRE EJA301 C680 29.00 -81.40 120 7000 230", "CRE LOF22 E145 28.90 -81.60 090 6000 220", "ADDWPT LOF22 SFB" },
    "a city's navaid and airport")
  if ex then
    check_eq(ex("ASH88 go direct Sanford"), "DIRECT ASH88 KSFB")
    check_eq(ex("LOF22 direct Sanford"), "DIRECT LOF22 SFB")
    asked(ex("EJA301 direct Sanford"), "neither in the route")
    check_eq(ex("EJA301 direct the Sanford NDB"), "ADDWPT EJA301 SFB ; DIRECT EJA301 SFB")
  end
end

-- Cycle 35 (R71): FAA typed shorthand: "pd FIX" proceed direct (the fix in capitals), "rs 250" reduce speed,
-- "exp" expect before an approach or runway, "hvy", "9 thsnd", "adn"; "descend pd 6000" stays pilot's discretion and
-- "pd" before a word in lower case is asked
do
  local _, ex = scene({ "CRE ASQ77 CRJ9 33.0 -84.0 090 12000 280", "DEFWPT WOBBL 33.2 -83.5", "ADDWPT ASQ77 WOBBL" })
  check_eq(ex("ASQ77 pd WOBBL"), "DIRECT ASQ77 WOBBL")
  check_eq(ex("ASQ77 rs 230"), "SPD ASQ77 230")
  check_eq(ex("ASQ77 dm 9 thsnd, rs 240"), "ALT ASQ77 9000 ; SPD ASQ77 240")
  check_eq(ex("ASQ77 desend adn maintain 7000"), "ALT ASQ77 7000")
  check_eq(ex("ASQ77 dm 8000 exp ILS rwy 27"), "ALT ASQ77 8000")
  check_eq(ex("ASQ77 hvy descend 1500 fpm"), "VS ASQ77 -1500")
  check_eq(ex("ASQ77 descend pd 6000"), "ALT ASQ77 6000")
  asked(ex("ASQ77 pd wobbl"), "a fix in lower case after pd")
end

-- Cycle 35 (R71): "until established" closing with the approach clearance, its kind, runway and the airport
-- named last ("cleared RNAV 22R Jacksonville") is not simulated; a word after the airport is still asked
do
  local _, ex = navscene({ "CRE FDX77 B763 30.3 -81.9 180 5000 210" }, "an approach's airport")
  if ex then
    check_eq(ex("FDX77 maintain 3000 until established, cleared RNAV 26 Jacksonville"), "ALT FDX77 3000")
    check_eq(ex("FDX77 maintain 2500 until established, cleared ILS 8L Jacksonville"), "ALT FDX77 2500")
    asked(ex("FDX77 maintain 3000 until established, cleared RNAV 26 Jacksonville quickly"), "a word after")
  end
end

-- Cycle 35 (R71): an airspace infringed given as the reason for a removal ("busted the charlie") is set aside;
-- three single digits typed apart before "knots" are one speed, two of them or digits before another word
-- are not joined
do
  local _, ex = scene({ "CRE N733QB C172 28.0 -82.0 270 2500 100", "CRE ASQ5 CRJ7 28.3 -82.3 090 9000 250" })
  check_eq(ex("remove N733QB, busted the charlie"), "DEL N733QB")
  check_eq(ex("ASQ5 busted his altitude, descend 8000"), "ALT ASQ5 8000")
  check_eq(ex("ASQ5 maintain 2 3 0 knots"), "SPD ASQ5 230")
  check_eq(ex("ASQ5 reduce 1 9 0 kts"), "SPD ASQ5 190")
  asked(ex("ASQ5 maintain 2 3 knots"), "two digits apart")
end

-- Cycle 35 (R71): at a waypoint of the route, "reduce speed to 190" (a bare number after "speed to") is the
-- speed to fly from there (AT acid wp DO), as "reduce speed 190" is; a waypoint off the route is still asked
do
  local _, ex = scene({ "CRE ASH4 E75L 29.0 -81.0 200 9000 240", "DEFWPT TWIRL 28.8 -81.1", "DEFWPT FARFX 27.0 -80.0",
    "ADDWPT ASH4 TWIRL" })
  check_eq(ex("ASH4 at TWIRL reduce speed to 190"), "AT ASH4 TWIRL DO SPD ASH4 190")
  asked(ex("ASH4 at FARFX reduce speed to 190"), "off the route")
end

-- Cycle 35 (R71): "when level at 8000" opening a clause is a level condition ("level" after "when"/"once" and
-- before "at" is no instruction of its own); "level at 8000" alone is still the level
do
  local _, ex = scene({ "CRE ASH9 B739 27.7 -81.1 350 11000 250" })
  check_eq(ex("ASH9 when level at 9000 reduce 200"), "ATALT ASH9 9000 SPD ASH9 200")
  check_eq(ex("ASH9 once level at 9000 speed 210"), "ATALT ASH9 9000 SPD ASH9 210")
  check_eq(ex("ASH9 level at 9000"), "ALT ASH9 9000")
end

-- Cycle 35 (R72): roles of a conflict study declared before the instruction ("intruder is X", "subject
-- aircraft X", "X is the intruder") say which aircraft "the intruder" / "the subject aircraft" means; the
-- declaration instructs no one, nor does a sentence that only describes the pair ("both FL310")
do
  local _, ex = scene({ "CRE CSA4K A320 50.0 14.0 090 FL300 270", "CRE TVS22 B738 50.1 14.6 270 FL300 270" })
  check_eq(ex("The subject aircraft is CSA4K and the intruder is TVS22. Please turn the intruder right by 20 degrees."),
    "HDG TVS22 290 RIGHT")
  check_eq(ex("Intruder TVS22, subject CSA4K, both at FL300. The subject aircraft shall descend to FL280."),
    "ALT CSA4K FL280")
  check_eq(ex("TVS22 is the intruder; the intruder shall climb FL320"), "ALT TVS22 FL320")
  check_eq(ex("The subject aircraft CSA4K and the intruder TVS22 are converging; turn CSA4K left 10 degrees."),
    "HDG CSA4K 80 LEFT")
  -- a role no declaration binds, or one declared for both aircraft, names no one
  asked(ex("Intruder CSA4K, intruder TVS22. Turn the intruder left 20 degrees."), "a role declared twice")
end

-- Cycle 35 (R72): the direction an instruction stops is not the one it gives ("stop the climb and descend")
do
  local _, ex = scene({ "CRE HVN7Q A321 50.0 14.0 090 FL250 270" })
  check_eq(ex("HVN7Q stop your climb and descend at 800 feet per minute"), "VS HVN7Q -800")
  check_eq(ex("HVN7Q cease the descent, climb with 1200 feet per minute"), "VS HVN7Q 1200")
end

-- Cycle 35 (R72): verbs that switch off ("disconnect", "disable", "inhibit") are never dropped
do
  local _, ex = scene({ "CRE AMC55 A320 50.0 14.0 090 FL250 270" })
  check_eq(ex("please disconnect the LNAV of AMC55"), "LNAV AMC55 OFF")
  check_eq(ex("inhibit VNAV for AMC55"), "VNAV AMC55 OFF")
  check_eq(ex("disable the vertical resolution manoeuvres"), "RMETHV OFF")
  check_eq(ex("enable vertical resolution manoeuvres"), "RMETHV V/S")
end

-- Cycle 35 (R72): a crossing at a fix that is not named is asked, never flown as a level at once
do
  local _, ex = scene({ "CRE AMC56 A320 50.0 14.0 090 FL250 270" })
  asked(ex("AMC56 shall cross the waypoint at FL200"), "no fix named")
  asked(ex("AMC56 to cross the fix at 250 knots"), "no fix named")
end

-- Cycle 35 (R72): "provide / give the [actual] position, level and speed of X" asks for its state (POS)
do
  local _, ex = scene({ "CRE AMC57 A320 50.0 14.0 090 FL250 270" })
  check_eq(ex("Kindly provide the present altitude of AMC57."), "POS AMC57")
  check_eq(ex("give me heading and speed for AMC57 please"), "POS AMC57")
  asked(ex("give AMC57 the speed"), "no value said")
end

-- Cycle 35 (R72): a replay is the simulation ("pause the replay", "remove X from the replay"); "Mach number
-- 0.78" is a Mach number, no approach sequence; a number after "number" alone is still a sequence
do
  local _, ex = scene({ "CRE AMC58 A320 50.0 14.0 090 FL330 270" })
  check_eq(ex("Kindly pause the replay."), "HOLD")
  check_eq(ex("please take AMC58 out of the replay"), "DEL AMC58")
  check_eq(ex("run the replay 3 times faster"), "DTMULT 3")
  check_eq(ex("AMC58 shall maintain Mach number 0.79"), "SPD AMC58 M0.79")
  check_eq(ex("AMC58 number 2 for the approach"), "")  -- (not simulated: nothing sent)
end

-- Cycle 35 (R72): "the complete route" is the whole route; a speed said "indicated" is the speed flown
do
  local _, ex = scene({ "CRE AMC59 A320 50.0 14.0 090 FL330 270", "DEFWPT CMPA 50.2 14.5", "ADDWPT AMC59 CMPA" })
  check_eq(ex("kindly delete the complete route of AMC59"), "DELRTE AMC59")
  check_eq(ex("AMC59 shall fly 260 knots indicated"), "SPD AMC59 260")
  asked(ex("AMC59 complete"), "no instruction")
end

-- Cycle 35 (R72): "the closest point of approach" is the CPA
do
  local _, ex = scene({ "CRE AMC60 A320 50.0 14.0 090 FL330 270" })
  check_eq(ex("aircraft shall resume navigation once past the Closest Point of Approach"), "RESNAV PASTCPA")
  check_eq(ex("resume navigation past the cpa"), "RESNAV PASTCPA")
end

-- Cycle 35 (R72): "resolution" naming what an aircraft's instruction is for ("for the resolution manoeuvre",
-- "Resolution:" heading the request) sets no method; said alone with a method it still does
do
  local _, ex = scene({ "CRE AMC61 A320 50.0 14.0 090 FL330 270" })
  check_eq(ex("As the resolution manoeuvre AMC61 shall turn 20 degrees left."), "HDG AMC61 70 LEFT")
  check_eq(ex("Resolution: AMC61 shall descend to FL310."), "ALT AMC61 FL310")
  check_eq(ex("Resolution: MVP"), "RESO MVP")
end

-- Cycle 36 (R74): the roles of a learning study ("ownship", "own ship", "ego") declared before the
-- instruction, a dash setting the declarations apart; a role mentioned (with or without "the") names its
-- aircraft and the declarations address no one. A role declared for two is still asked.
do
  local _, ex = scene({ "CRE ANZ33 B789 -30.0 150.0 090 FL370 290", "CRE TGW8 A320 -30.2 150.6 270 FL370 280" })
  check_eq(ex("ownship ANZ33, intruder TGW8 - turn ownship left heading 030"), "HDG ANZ33 30 LEFT")
  check_eq(ex("own ship TGW8, intruder ANZ33 - climb own ship to FL390"), "ALT TGW8 FL390")
  check_eq(ex("ego ANZ33 and intruder TGW8: the intruder descend FL330"), "ALT TGW8 FL330")
  check_eq(ex("subject ANZ33, intruder TGW8, slow the subject to 250 knots"), "SPD ANZ33 250")
  asked(ex("ownship ANZ33, ownship TGW8 - ownship heading 200"), "ownship declared for two")
end

-- Cycle 36 (R74): an intruder (CRECONFS) set up where two aircraft flying are named ("a conflict pair
-- with ..."): its one target is not said, so it is asked
do
  local _, ex = scene({ "CRE ANZ34 B789 -30.0 150.0 090 FL370 290", "CRE TGW9 A320 -30.2 150.6 270 FL370 280" })
  asked(ex("make ANZ34 a conflict pair with TGW9, B738 intruder IN2 at 60 degrees, CPA 0, 240 s to LoS"),
    "two targets")
  check_eq(ex("intruder on ANZ34: IN3, B738, 60 degrees, CPA 0, 240 s to LoS"), "CRECONFS IN3 B738 ANZ34 60 0 240")
end

-- Cycle 36 (R74): Australian slang for starting the run and random traffic: "kick off the episode", "let it
-- rip" (no aircraft named) are OP; "chuck in 6 random aircraft" is MCRE. Where the class stops it is asked.
do
  local _, ex = scene({ "CRE ANZ35 B789 -30.0 150.0 090 FL370 290" })
  check_eq(ex("kick off the sim"), "OP")
  check_eq(ex("RESO MVP then let it rip"), "RESO MVP ; OP")
  check_eq(ex("chuck in 6 random aircraft"), "MCRE 6")
  asked(ex("kick off"), "no simulation said")
  asked(ex("ANZ35 let it rip"), "an aircraft named")
end

-- Cycle 36 (R74): an aircraft flying "popped over to" a position is moved there (MOVE); "pop" without
-- "over to" is still asked
do
  local _, ex = scene({ "CRE ANZ36 B789 -30.0 150.0 090 FL370 290" })
  check_eq(ex("pop ANZ36 over to -29.5 151.25"), "MOVE ANZ36 -29.5 151.25")
  asked(ex("pop ANZ36 to -29.5 151.25"), "no 'over to'")
end

-- Cycle 36 (R74): an aircraft "pointed to" a number of degrees flies that heading; the number without
-- "degrees" is still asked
do
  local _, ex = scene({ "CRE ANZ37 B789 -30.0 150.0 090 FL370 290" })
  check_eq(ex("point ANZ37 to 215 degrees"), "HDG ANZ37 215")
  asked(ex("point ANZ37 to 215"), "no degrees")
end

-- Cycle 36 (R74): "agent" as a study role (mentioned with or without "the"), and a role set beside its
-- callsign by punctuation alone ("..., TGW10 the intruder: ..."); a callsign and role inside an instruction
-- ("turn TGW10 the intruder left") is still that instruction's addressee
do
  local _, ex = scene({ "CRE ANZ38 B789 -30.0 150.0 090 FL370 290", "CRE TGW10 A320 -30.2 150.6 270 FL370 280" })
  check_eq(ex("agent ANZ38, intruder TGW10 - give agent heading 120"), "HDG ANZ38 120")
  check_eq(ex("ANZ38 is the agent, TGW10 the intruder: descend the intruder FL330"), "ALT TGW10 FL330")
  check_eq(ex("turn TGW10 the intruder left heading 200"), "HDG TGW10 200 LEFT")
  check_eq(ex("create 4 agents"), "MCRE 4")
end

-- Cycle 36 (R73): a heading said as three digits one by one over 360 is asked, never re-read as fewer
do
  local _, ex = scene({ "CRE JSY7Q DH8D 50.0 -2.0 090 FL120 240" })
  asked(ex("JSY7Q turn left heading five one zero"), "a heading of 510")
  asked(ex("JSY7Q fly heading three eight zero"), "a heading of 380")
  check_eq(ex("JSY7Q turn left heading three five zero"), "HDG JSY7Q 350 LEFT")
end

-- Cycle 36 (R73): UK telephonies "Stobart" (STK) and "Jersey" (BEE) name their airline, also inside a
-- clause ("add X to Stobart ...'s route": the route edit, not the route shown)
do
  local _, ex = scene({ "CRE STK2KP AT72 54.0 -3.0 090 FL100 220", "CRE BEE3M DH8D 54.2 -3.2 090 FL110 230",
    "DEFWPT TSTWP 54.3 -2.5" })
  check_eq(ex("add TSTWP to Stobart two kilo papa's route"), "ADDWPT STK2KP TSTWP")
  check_eq(ex("insert TSTWP into Jersey three mike's route"), "ADDWPT BEE3M TSTWP")
  check_eq(ex("show Stobart two kilo papa's route"), "LISTRTE STK2KP")
  asked(ex("add TSTWP to Stobart two kilo's route"), "no such Stobart")
end

-- Cycle 36 (R73): "own navigation" with a navaid said by its name is a direct-to there; a name that is
-- no navaid near the aircraft is still asked
do
  local _, ex = navscene({ "CRE KLM55 B738 52.6 4.6 090 FL120 250", "ADDWPT KLM55 SPY", "ADDWPT KLM55 PAM" },
    "own navigation to a navaid by name")
  if ex then
    check_eq(ex("KLM55, own navigation Spijkerboor"), "DIRECT KLM55 SPY")
    check_eq(ex("KLM55 resume own navigation to Pampus"), "DIRECT KLM55 PAM")
    asked(ex("KLM55, own navigation Blorpton"), "no navaid of that name")
  end
end

-- Cycle 36 (R73): "level by" a navaid said by its name is the AT constraint at that navaid's ident (beside the level
-- cleared now); a name that is no navaid near the traffic is still asked
do
  local _, ex = navscene({ "CRE KLM56 B738 52.6 4.6 090 FL120 250", "ADDWPT KLM56 SPY", "ADDWPT KLM56 PAM" },
    "level by a navaid by name")
  if ex then
    check_eq(ex("KLM56, descend flight level niner zero, level by Spijkerboor"), "ALT KLM56 FL90 ; AT KLM56 SPY ALT FL90")
    check_eq(ex("KLM56 descend FL80 level by Pampus"), "ALT KLM56 FL80 ; AT KLM56 PAM ALT FL80")
    asked(ex("KLM56 descend FL90, level by Blorpton"), "no navaid of that name")
  end
end

-- Cycle 36 (R73): "what's X's route" / "what's the <airline> routing", the noun ending the request, shows the
-- route; the airline alone with two of its aircraft flying is still asked
do
  local _, ex = scene({ "CRE EZY7K A319 51.2 0.6 240 FL130 260", "CRE RYR4TM B738 51.4 -1.0 070 FL170 290",
    "CRE RYR6PQ B738 51.6 -1.2 070 FL190 290" })
  check_eq(ex("what's Easy seven kilo's route"), "LISTRTE EZY7K")
  check_eq(ex("what's the Easy routing?"), "LISTRTE EZY7K")
  asked(ex("what's the Ryanair routing"), "two Ryanair aircraft")
end

-- an amount followed by "faster"/"slower" is a change of the present speed, never the new speed
do
  local _, ex = scene({ "CRE EZY41K A320 51.0 0.5 090 FL200 250", "CRE SAS9TR B738 51.2 0.7 270 FL220 280" })
  check_eq(ex("tell the easy to go 60 faster"), "SPD EZY41K 310")
  check_eq(ex("SAS9TR 30 knots slower please"), "SPD SAS9TR 250")
  check_eq(ex("make EZY41K 120 slower"), "SPD EZY41K 130")
  -- no aircraft named among two: asked
  asked(ex("go 40 faster"), "no callsign among two aircraft")
end

-- a level said group-wise after climb/descend ("one hundred sixty") is that flight level from the flight levels
do
  local _, ex = scene({ "CRE AEE47L A320 50.5 3.0 180 FL130 270", "CRE TAP12C A321 50.9 3.4 000 4000 220" })
  check_eq(ex("AEE47L climb one hundred ninety"), "ALT AEE47L FL190")
  check_eq(ex("AEE47L descend to one hundred ten"), "ALT AEE47L FL110")
  -- from 4000 ft (feet or a level?) and a level not of whole tens: asked
  asked(ex("TAP12C climb one hundred twenty"), "group-wise level from below 10000 ft")
  asked(ex("AEE47L climb one hundred fifty five"), "a level not of whole tens")
end

-- Cycle 36 (R76): an airline said alone in lower case opening a clause whose instruction names no
-- aircraft is asked about, never given the aircraft named in another clause; written with a capital,
-- with more than one kind of instruction, it names the one aircraft of that airline flying
do
  local _, ex = scene({ "CRE DLH4KP A320 50.1 8.6 090 FL250 280", "CRE KLM82T B738 52.3 4.8 180 FL180 260" })
  asked(ex("lufthansa please climb to FL300 and the klm descend to FL150"), "lufthansa in lower case, alone")
  asked(ex("klm turn left heading 200, DLH4KP climb FL310"), "klm in lower case, alone")
  check_eq(ex("Lufthansa turn left heading 100 and climb to FL300"), "HDG DLH4KP 100 LEFT ; ALT DLH4KP FL300")
  check_eq(ex("climb to FL300, DLH4KP"), "ALT DLH4KP FL300")
end

-- Cycle 36 (R75): switching the lateral (horizontal) resolutions is RMETHH, a command squawk lacks: asked,
-- never RMETHV switched instead; switching the vertical ones is still RMETHV
do
  local _, ex = scene({ "CRE KLM83 B738 52.3 4.8 180 FL180 260" })
  asked(ex("switch off horizontal resolutions, resolve in the vertical only"), "lateral resolutions switched off")
  asked(ex("no lateral resolution manoeuvres please"), "lateral resolutions switched off")
  asked(ex("lateral resolutions off"), "lateral resolutions switched off")
  check_eq(ex("turn off vertical resolutions, horizontal only"), "RMETHV OFF")
  check_eq(ex("vertical resolutions off, lateral only"), "RMETHV OFF")
  check_eq(ex("resolutions horizontal only please, no vertical"), "RMETHV OFF")
end

-- Cycle 37 (cond): conditions on a level, a speed or a distance, as people say them
do
  local _, ex = scene({ "CRE SWR41 A320 47.0 8.0 090 FL110 250", "CRE EZS77 A319 47.3 8.4 270 FL220 290",
      "DEFWPT TOBLA 47.5 8.9", "ADDWPT EZS77 TOBLA" })
  -- said after the callsign: "when/once/as soon as", who reaches it, a verb of reaching, the value
  check_eq(ex("EZS77 when you're down to FL180 slow to 260"), "ATALT EZS77 FL180 SPD EZS77 260")
  check_eq(ex("EZS77 once you hit FL190 go 270 knots"), "ATALT EZS77 FL190 SPD EZS77 270")
  check_eq(ex("EZS77, as soon as you're through FL200, reduce 270"), "ATALT EZS77 FL200 SPD EZS77 270")
  check_eq(ex("SWR41 once it's slowed to 220 descend to 8000"), "ATSPD SWR41 220 ALT SWR41 8000")
  check_eq(ex("SWR41 when at 230 knots descend to 9000"), "ATSPD SWR41 230 ALT SWR41 9000")
  -- in the middle, the verb of the speed and its article between the level and "speed"
  check_eq(ex("SWR41 climb FL170 and when he gets to FL150 bring the speed back to 240"),
    "ALT SWR41 FL170 ; ATALT SWR41 FL150 SPD SWR41 240")
  check_eq(ex("SWR41 climb FL170, as soon as it's through FL140 speed 240"),
    "ALT SWR41 FL170 ; ATALT SWR41 FL140 SPD SWR41 240")
  -- after the instruction: a level passed, crossed or dropped below, or a speed slowed to (ATSPD)
  check_eq(ex("EZS77 reduce to 260 after it drops below FL170"), "ATALT EZS77 FL170 SPD EZS77 260")
  check_eq(ex("SWR41 descend to 8000 once it has slowed to 230"), "ATSPD SWR41 230 ALT SWR41 8000")
  check_eq(ex("crossing FL180 EZS77 reduce 260"), "ATALT EZS77 FL180 SPD EZS77 260")
  check_eq(ex("SWR41 climb to FL150 and then slow to 230 after it levels"), "ALT SWR41 FL150 ; ATALT SWR41 FL150 SPD SWR41 230")
  check_eq(ex("once EZS77 is passing FL190 bring it back to 260 knots"), "ATALT EZS77 FL190 SPD EZS77 260")
  check_eq(ex("SWR41 climb FL150 and when passing FL130 it shall reduce the speed to 230"),
    "ALT SWR41 FL150 ; ATALT SWR41 FL130 SPD SWR41 230")
  check_eq(ex("SWR41 climb FL150, at FL130 it shall reduce to 230"), "ALT SWR41 FL150 ; ATALT SWR41 FL130 SPD SWR41 230")
  check_eq(ex("leaving FL210 EZS77 reduce 280"), "ATALT EZS77 FL210 SPD EZS77 280")
  -- a distance before or after a fix: "prior to", and a descent said "start (going) down"
  check_eq(ex("12 miles before TOBLA, EZS77 should start going down to FL150"), "ATDIST EZS77 TOBLA 12 ALT EZS77 FL150")
  check_eq(ex("20 miles prior to TOBLA EZS77 reduce 250"), "ATDIST EZS77 TOBLA 20 SPD EZS77 250")
  check_eq(ex("EZS77 start down to FL150 when 15 miles out of TOBLA"), "ATDIST EZS77 TOBLA 15 ALT EZS77 FL150")
  -- where the class stops: a level the aircraft will not pass (it is at FL110, cleared to FL170; EZS77 at
  -- FL220 cleared to FL190), a condition with no value, a condition carrying no instruction of its aircraft
  asked(ex("SWR41 climb FL170 and when it passes FL100 reduce 230"), "a level below the climb")
  asked(ex("EZS77 descend FL190 and once through FL150 reduce 250"), "a level below the descent")
  asked(ex("EZS77 when you're down a bit slow to 250"), "a condition with no level")
  asked(ex("EZS77 slow to 250 when you're down a bit"), "a condition with no level, after")
  asked(ex("EZS77 when passing one eight thousand resume normal speed"), "no instruction of the aircraft")
  asked(ex("a few miles before TOBLA EZS77 descend FL150"), "no distance")
  -- the listener's convenience is no condition
  check_eq(ex("EZS77 when you get a chance reduce 270"), "SPD EZS77 270")
end

-- Cycle 37 (resid): a waypoint put next to another said by its navaid's name ("insert Detling after
-- Ockham"), into "route of" an aircraft, or stuck on the route's end; a kind of navaid said after an
-- ident ("the DET VOR") is no waypoint of its own; a place next to it that names nothing is asked about
do
  local _, ex = navscene({ "CRE EZY12 A320 51.2 -0.3 090 FL150 260", "ADDWPT EZY12 OCK", "ADDWPT EZY12 SFD" },
    "waypoints said by their navaid's name")
  if ex then
    check_eq(ex("EZY12 insert Detling after Ockham"), "ADDWPT EZY12 DET,,,OCK")
    check_eq(ex("EZY12, after Seaford add Detling"), "ADDWPT EZY12 DET,,,SFD")
    check_eq(ex("add DET into route of EZY12"), "ADDWPT EZY12 DET")
    check_eq(ex("tack DET onto the end of EZY12's route"), "ADDWPT EZY12 DET")
    check_eq(ex("add the DET VOR to EZY12's route"), "ADDWPT EZY12 DET")
    check_eq(ex("please append the DET VOR at the end of the route of EZY12"), "ADDWPT EZY12 DET")
    asked(ex("EZY12 insert Detling after lunch"), "a place next to it that names nothing")
    asked(ex("EZY12 stick to the route"), "keeping the route adds nothing")
  end
end

-- Cycle 37 (resid): "remove the trails" switches the trails off, no aircraft deleted ("remove" an aircraft
-- still deletes it; "clear the trails" is still asked)
do
  local _, ex = scene({ "CRE KLM51 B738 52.0 4.0 090 FL200 250", "CRE AFR7 A320 52.3 4.4 270 FL220 260" })
  check_eq(ex("remove the trails"), "TRAIL OFF")
  check_eq(ex("please remove all the aircraft trails"), "TRAIL OFF")
  check_eq(ex("show the trails so we can follow the trajectories"), "TRAIL ON")
  check_eq(ex("remove KLM51"), "DEL KLM51")
  asked(ex("clear the trails"), "shown or hidden not said")
end

-- Cycle 37 (resid): a wind named by where it blows from ("set a northwesterly at 35 knots over ...",
-- lexicon.wind_points), and "wind set at ...", the verb after the noun; with an aircraft named it is no wind set
do
  local _, ex = scene({ "CRE KLM51 B738 52.0 4.0 090 FL200 250", "CRE AFR7 A320 52.3 4.4 270 FL220 260" })
  check_eq(ex("set a northwesterly at 35 knots over 51.5 3.5, FL200"), "WIND 51.5 3.5 FL200 315 35")
  check_eq(ex("set a south-westerly at 20 knots over 51.5 3.5"), "WIND 51.5 3.5 225 20")
  check_eq(ex("add an easterly of 15 knots at 51.5 3.5"), "WIND 51.5 3.5 90 15")
  check_eq(ex("wind set at 51.5 3.5 from 200 degrees 30 knots"), "WIND 51.5 3.5 200 30")
  check(not ex("KLM51 expect a westerly at 40 knots"):match("^WIND"), "a wind told to an aircraft sets none")
end

-- Cycle 37 (resid): the experimenter's console and clock: "the scenario" as the object of a verb of the clock
-- is the simulation running (no file loaded); words sent "to/in the console" are ECHOed as typed, after "the
-- text"; "load the scenario" still asks which file
do
  local _, ex = scene({ "CRE KLM51 B738 52.0 4.0 090 FL200 250" })
  check_eq(ex("fast forward the scenario by 3 minutes"), "FF 180")
  check_eq(ex("please freeze the scenario"), "HOLD")
  asked(ex("load the scenario"), "no file named")
  check_eq(ex("please echo the text TRIAL 7 BEGIN to the console"), "ECHO TRIAL 7 BEGIN")
  check_eq(ex("print batch_9_done in the console"), "ECHO batch_9_done")
end

-- Cycle 37 (resid): a kind of navaid said after its name or ident ("the Siedlce VOR SIE", "the SIE VOR") is
-- no place of its own where an aircraft is moved; "the VOR" alone names none (asked); "keep everything else"
-- carries nothing
do
  local _, ex = navscene({ "CRE SAS31 A320 52.2 20.9 090 FL250 260" }, "a navaid's kind after its name")
  if ex then
    check_eq(ex("move SAS31 to the Siedlce VOR SIE, keep everything else"), "MOVE SAS31 SIE")
    check_eq(ex("move SAS31 to the SIE VOR"), "MOVE SAS31 SIE")
    check_eq(ex("move SAS31 to the Siedlce VOR"), "MOVE SAS31 SIE")
    asked(ex("move SAS31 to the VOR"), "no navaid named")
  end
end

-- Cycle 37 (resid): "create a circle/box NAME ..." makes the shape, no aircraft; "create a circle" with nothing
-- else is asked
do
  local _, ex = scene({ "CRE KLM51 B738 52.0 4.0 090 FL200 250" })
  check_eq(ex("create a circle area ZONE4 centred at 51.5 N 4.2 E with radius 15 NM"), "CIRCLE ZONE4 51.5 4.2 15")
  check_eq(ex("create a box B2 51 3 51.5 3.5"), "BOX B2 51 3 51.5 3.5")
  asked(ex("create a circle"), "no name, centre or radius")
end

-- Cycle 37 (resid): typed typos of "trail" and "dtmult" (lexicon.spelling.targets) are read as those words;
-- the words one letter away that mean something of their own ("trial") are kept
do
  local _, ex = scene({ "CRE KLM51 B738 52.0 4.0 090 FL200 250" })
  check_eq(ex("tral on"), "TRAIL ON")
  check_eq(ex("dtmul 6"), "DTMULT 6")
  asked(ex("trial on"), "a trial is no trail")
end

-- Cycle 37 (resid): an aircraft taken off the scope ("take KLM51 off the scope", "klm51 off the screen") is
-- deleted; "KLM51 is off the scope" (a report) is asked
do
  local _, ex = scene({ "CRE KLM51 B738 52.0 4.0 090 FL200 250", "CRE AFR7 A320 52.3 4.4 270 FL220 260" })
  check_eq(ex("take KLM51 off the scope"), "DEL KLM51")
  check_eq(ex("instructor: afr7 off the screen"), "DEL AFR7")
  asked(ex("KLM51 is off the scope"), "a report, no request")
end

-- Cycle 37 (resid): "sorry, typo" is a self-correction's word: the value said after it replaces the one before
do
  local _, ex = scene({ "CRE KLM51 B738 52.0 4.0 090 FL200 250" })
  check_eq(ex("KLM51 climb FL240, sorry typo, FL260"), "ALT KLM51 FL260")
  check_eq(ex("KLM51, typo, KLM51 heading 150"), "HDG KLM51 150")
  asked(ex("KLM51 climb FL240 typo FL260"), "no mark sets the correction apart")
end

-- Cycle 37 (resid): a conflict made with "relative heading N degrees" crosses at N; "one intruder" is the one
-- aircraft made; with no angle said it is asked
do
  local _, ex = scene({ "CRE KLM51 B738 52.0 4.0 090 FL200 250" })
  check_eq(ex("create one intruder INT7, B738, versus KLM51 with relative heading 60 degrees, CPA 0.5 nm and 200 "
    .. "seconds to loss of separation"), "CRECONFS INT7 B738 KLM51 60 0.5 200")
  asked(ex("create one intruder INT8 B738 versus KLM51, CPA 0.5 nm, 200 seconds to loss of separation"), "no angle")
end

-- Cycle 37 (resid): the capitalised name of an exercise or scenario ("the Lisbon exercise") names the run, no
-- place: it carries nothing; "load the Lisbon scenario" still asks which file
do
  local _, ex = scene({ "CRE KLM51 B738 52.0 4.0 090 FL200 250" })
  check_eq(ex("run the Lisbon exercise at three times real time"), "DTMULT 3")
  check_eq(ex("pause the Lisbon simulation"), "HOLD")
  asked(ex("load the Lisbon scenario"), "no file named")
end

-- Cycle 37 (resid): a place's name set apart by a comma before its latitude ("at Ghent, 51.1 N 3.7 E") is the
-- position said after it; a name alone beside a bare decimal pair is still asked
do
  local _, ex = scene({ "CRE KLM51 B738 52.0 4.0 090 FL200 250" })
  check_eq(ex("what is the wind at Ghent, 51.1 N 3.7 E?"), "GETWIND 51.1 3.7")
  check_eq(ex("create KLM52 B738 at Ghent, 51.1 N 3.7 E, heading 090, FL100, 250 knots"),
    "CRE KLM52 B738 51.1 3.7 90 FL100 250")
  asked(ex("what is the wind at Ghent, 51.1 3.7?"), "a bare pair beside a name")
end

-- Cycle 37 (resid): "move X to FL360, same position" moves it where it is now, at the level said; "the same
-- position as Y" (another aircraft's) is asked
do
  local _, ex = scene({ "CRE KLM51 B738 52.0 4.0 090 FL200 250", "CRE AFR7 A320 52.3 4.4 270 FL220 260" })
  check_eq(ex("move KLM51 to FL300, same position"), "MOVE KLM51 52 4 FL300")
  asked(ex("move KLM51 to the same position as AFR7"), "another aircraft's position")
end

-- Cycle 37 (resid): "track to WAYPOINT" (Australian) is a direct-to; "track to" an airport is asked
do
  local _, ex = scene({ "CRE QFA33 B738 -27.0 153.0 180 FL300 280", "DEFWPT KOALA -27.5 153.2",
    "ADDWPT QFA33 KOALA" })
  check_eq(ex("QFA33 track to KOALA then descend FL240"), "DIRECT QFA33 KOALA ; ALT QFA33 FL240")
  asked(ex("QFA33 track to YBBN"), "an airport tracked to")
end

-- Cycle 37 (resid): "put A to FL320 and B to FL360", with no instruction word, gives each aircraft its own
-- level, never the first level to both; "put A and B to FL360" gives both the one level
do
  local _, ex = scene({ "CRE KLM51 B738 52.0 4.0 090 FL200 250", "CRE AFR7 A320 52.3 4.4 270 FL220 260" })
  check_eq(ex("put KLM51 to FL240 and AFR7 to FL260"), "ALT KLM51 FL240 ; ALT AFR7 FL260")
  check_eq(ex("set KLM51 to FL240, AFR7 to FL260"), "ALT KLM51 FL240 ; ALT AFR7 FL260")
  check_eq(ex("put KLM51 and AFR7 to FL300"), "ALT KLM51 FL300 ; ALT AFR7 FL300")
end

-- Cycle 37 (ref): an aircraft named by its type, family, maker or nickname alone ("the 777", "the triple
-- seven", "the dash 8", "the MAX") is the one aircraft flying of a type it names (opening the request with no
-- "the", "Cessna, heading 045", it is a call by type with no registration, asked: cycle 42);
-- with several of them flying the question names them; with none, or a designator no aircraft flies, asked
do
  local _, ex = scene({ "CRE GLA40 B77W 44.0 -79.0 300 FL220 290", "CRE SKV15 B738 44.2 -79.4 070 FL140 260",
    "CRE LIN31 DH8C 44.1 -79.2 180 7000 210", "CRE AVN2 A319 44.3 -79.1 230 FL170 270",
    "CRE GKPQR C172 44.4 -79.3 090 3000 100" })
  check_eq(ex("take the triple seven down to 12000"), "ALT GLA40 12000")
  check_eq(ex("the 777 turn left heading 250"), "HDG GLA40 250 LEFT")
  check_eq(ex("where is the Boeing 777"), "POS GLA40")
  -- the Dash 8 family is every Dash 8, the DH8C too
  check_eq(ex("the dash 8, speed 190"), "SPD LIN31 190")
  asked(ex("dash 8 climb to 9000"), "a type called with no registration")
  asked(ex("dash to FL300"), "'dash' without its 8 is no Dash 8")
  check_eq(ex("the Dash-8 descend to 5000"), "ALT LIN31 5000")
  check_eq(ex("slow the dash to 200"), "SPD LIN31 200")
  asked(ex("Cessna, heading 045"), "a maker called with no registration")
  check_eq(ex("the 737 climb FL200"), "ALT SKV15 FL200")
  -- two Boeings: the maker alone, a size word with it, asked naming both
  check_eq(ex("the Boeing descend FL120"), "ASK Which Boeing do you mean: GLA40 or SKV15? Please give its callsign.")
  check_eq(ex("the big boeing go left heading 250"),
    "ASK Which big boeing do you mean: GLA40 or SKV15? Please give its callsign.")
  -- a variant's designator is that variant only (a B772 is no B77W); a family none flies is asked
  asked(ex("the B772 climb FL300"), "B772 said, only a B77W flying")
  asked(ex("the 747 climb FL300"), "no 747 flying")
  asked(ex("the MAX climb FL300"), "no 737 MAX flying")
  -- "Cessna" before its model number is a type said, never the addressee cut short: still no registration
  asked(ex("Cessna 172 climb to 4000"), "a type said in full called with no registration")
  -- a callsign said: the type words are no reference
  check_eq(ex("SKV15 climb FL200, the 777 is above"), "ALT SKV15 FL200")
  -- a type word in a creation keeps its meaning
  check_eq(ex("create a 777 called GLA41 at 44.5 -79.5 heading 240, 3000 ft, 180 kts"),
    "CRE GLA41 B772 44.5 -79.5 240 3000 180")
end
do
  local _, ex = scene({ "CRE GLA40 B77W 44.0 -79.0 300 FL220 290", "CRE GLA41 B772 44.2 -79.4 070 FL140 260",
    "CRE SKV15 B738 44.3 -79.1 230 FL170 270", "CRE SKV16 B38M 44.1 -79.2 180 FL190 280" })
  -- two 777s: the family, said by its number or as "triple seven", is asked about, naming both
  check_eq(ex("the 777 descend to FL200"), "ASK Which 777 do you mean: GLA40 or GLA41? Please give its callsign.")
  asked(ex("bring the triple seven down to 11000"), "two 777s flying")
  -- a 737 MAX is a 737: "the 737" fits both 737s, "the MAX" the one MAX
  check_eq(ex("the 737 turn right 20"), "ASK Which 737 do you mean: SKV15 or SKV16? Please give its callsign.")
  check_eq(ex("the max, heading 150"), "HDG SKV16 150")
  check_eq(ex("the max climb to FL220"), "ALT SKV16 FL220")
  check_eq(ex("give the MAX a yellow trail"), "TRAIL SKV16 YELLOW")
  -- "max" as an adjective is no aircraft
  asked(ex("climb at the max rate"), "max rate, no aircraft named")
  asked(ex("give me the max speed"), "max speed, no aircraft named")
end
-- an airline said alone before one instruction, with one aircraft of it flying, is still a callsign cut
-- short and asked (the rounds disagree: docs/translator_trust.md); two of it flying: asked, naming both
do
  local _, ex = scene({ "CRE POE412 DH8D 43.6 -79.4 180 6000 200", "CRE WJA58 B737 43.5 -79.9 070 FL120 260",
    "CRE WJA59 B38M 43.7 -79.6 250 FL160 270" })
  asked(ex("Porter, climb to 8000 feet"), "airline alone, one aircraft of it")
  check_eq(ex("the Westjet climb FL200"), "ASK Which Westjet: WJA58 or WJA59?")
  check_eq(ex("the Porter climb to 8000 feet"), "ALT POE412 8000")
end

-- Cycle 37 (tr79): a self-correction before a setting said again after a verb of setting ("..., no, set the
-- zone radius to ...") takes back the value corrected; never both issued
do
  local _, ex = scene({ "CRE KLM83 B738 52.3 4.8 180 FL180 260" })
  check_eq(ex("zone radius four miles... no, set the zone radius to six miles"), "ZONER 6")
  check_eq(ex("separation 2000 feet, half height two thousand... sorry, set zone half height to one thousand feet"),
    "ZONEDH 1000")
  check_eq(ex("KLM83 climb FL240... no, set heading 090"), "HDG KLM83 90")
  -- a setting added after the first, with no correction, stands beside it
  check_eq(ex("zone radius 4 nm and set half height 800 ft"), "ZONER 4 ; ZONEDH 800")
end

-- Cycle 37 (tr79): greetings, thanks, farewells and "please" in the controller's own language are courtesy;
-- a word of them that names a fix of the scene is that fix, and said elsewhere it is asked about
do
  local _, ex = scene({ "CRE AEE47L A320 38.0 23.5 090 FL150 280", "CRE ITY88 A320 42.6 11.8 150 FL240 290",
    "DEFWPT SALAM 38.2 24.0", "ADDWPT ITY88 SALAM" })
  check_eq(ex("AEE47L climb flight level one nine zero, kalispera"), "ALT AEE47L FL190")
  check_eq(ex("ITY88 buonasera, reduce speed two hundred forty, grazie mille"), "SPD ITY88 240")
  check_eq(ex("AEE47L turn left heading 200, tesekkurler, iyi ucuslar"), "HDG AEE47L 200 LEFT")
  check_eq(ex("arigato, AEE47L descend FL120"), "ALT AEE47L FL120")
  check_eq(ex("ITY88 direct SALAM"), "DIRECT ITY88 SALAM")
  -- SALAM is a fix on ITY88's route: said after an instruction it is asked about, never dropped as a greeting
  asked(ex("ITY88 descend FL200, salam"), "a courtesy word that is a fix of the scene")
  -- one word of a farewell of two ("kalo taxidi") alone is no courtesy
  asked(ex("AEE47L climb FL200, kalo"), "half a farewell")
end

-- Cycle 37 (tr79): speaker labels in the speaker's language ("istruttore:", "supervisore:", "piloto:"), and a
-- creation said with the verb in that language when an aircraft type follows and no aircraft flying is named
do
  local _, ex = scene({ "CRE NOS55 B738 42.0 12.0 150 FL240 290" })
  check_eq(ex("istruttrice: NOS55 climb FL300"), "ALT NOS55 FL300")
  check_eq(ex("superviseur: delete NOS55"), "DEL NOS55")
  check_eq(ex("supervisore: crea AZA77 A320 at 41.5 12.5 heading 090 FL200 250"), "CRE AZA77 A320 41.5 12.5 90 FL200 250")
  check_eq(ex("Ausbilder: erstelle DLH12 A321 at 41 12 heading 180 FL220 260"), "CRE DLH12 A321 41 12 180 FL220 260")
  asked(ex("crea NOS55 A320"), "the foreign verb before an aircraft flying")
  asked(ex("crea a conflict"), "the foreign verb with no type")
end

-- Cycle 37 (tr79): the telephony of the airlines of Italy and Greece ("Moonflower" is Neos)
do
  local _, ex = scene({ "CRE NOS721 B738 42.6 11.8 150 FL240 290", "CRE ELB204 A320 38.0 23.5 090 FL150 280" })
  check_eq(ex("where is Moonflower seven two one"), "POS NOS721")
  check_eq(ex("Ellinair two zero four descend FL100"), "ALT ELB204 FL100")
end

-- Cycle 37 (tr79): reasons said with an instruction: an aircraft "not needed (anymore)" before its removal,
-- and "vectors" with the place they lead to named straight after it; a value in such a clause is still asked
do
  local _, ex = scene({ "CRE SXS81 B738 40.1 23.1 100 FL300 280", "CRE ELB12 A320 40.5 23.5 100 FL200 250" })
  check_eq(ex("SXS81 isn't required any more, delete it"), "DEL SXS81")
  check_eq(ex("Ellinair twelve not needed anymore, remove it please"), "DEL ELB12")
  asked(ex("SXS81 is not cleared, remove it"), "a negation that is no reason of lexicon.unneeded")
  check_eq(ex("ELB12 turn left heading 250, vectors Thessaloniki"), "HDG ELB12 250 LEFT")
  check_eq(ex("ELB12 fly heading 030, vectoring Larissa, descend FL90"), "HDG ELB12 30 ; ALT ELB12 FL90")
  asked(ex("ELB12 turn left heading 250, vectors 5"), "a number after vectors")
end

-- Cycle 37 (tr79): values said without their unit where the construction places them: a number said group-wise
-- in words ("one hundred twenty") between a creation's heading and speed, or after a move's position for an
-- aircraft at flight levels, is the flight level; "at" and a number of whole hundreds after a cleared level is the
-- rate of climb or descent
do
  local _, ex = scene({ "CRE SXS81 B738 40.1 23.1 100 FL300 280", "CRE EXV12 A320 40.5 23.5 100 6000 220" })
  check_eq(ex("create OAL70 A320 at 39.5 22.5, heading two one zero, one hundred forty, two hundred thirty knots"),
    "CRE OAL70 A320 39.5 22.5 210 FL140 230")
  asked(ex("create OAL70 A320 at 39.5 22.5, heading two one zero, one hundred forty"), "no speed said to place it")
  check_eq(ex("move SXS81 to 40.3 23.4, two hundred ten"), "MOVE SXS81 40.3 23.4 FL210")
  asked(ex("move EXV12 to 40.3 23.4, one hundred ten"), "a group-wise number for an aircraft at 6000 ft")
  check_eq(ex("SXS81 descend flight level two four zero at two thousand"), "ALT SXS81 FL240 2000")
  check_eq(ex("SXS81 descend FL240 at 1500"), "ALT SXS81 FL240 1500")
  asked(ex("SXS81 descend FL240 at 250"), "a speed-sized number after the level")
  asked(ex("SXS81 descend FL240 at 1500 feet"), "a number in feet after the level")
  -- a level said group-wise after a direct-to, in its own clause
  local _, ex2 = scene({ "CRE SXS82 B738 40.1 23.1 100 FL300 280", "DEFWPT ARSOS 40.9 23.9", "ADDWPT SXS82 ARSOS" })
  check_eq(ex2("SXS82 direct ARSOS, climb three hundred forty"), "DIRECT SXS82 ARSOS ; ALT SXS82 FL340")
end
-- Cycle 37 (tr80): "fly to" an airport said as an order may be a direct-to or a destination: asked;
-- said as a plan ("will fly to"), or with the destination named, it is the destination
do
  local _, ex = navscene({ "CRE KLM57 B738 52.6 4.6 090 FL120 250" }, "fly to an airport")
  if ex then
    asked(ex("KLM57 fly to EHAM"), "fly to an airport, as an order")
    asked(ex("klm57 please fly to amsterdam"), "fly to an airport by name, as an order")
    check_eq(ex("KLM57 will fly to Amsterdam, EHAM"), "DEST KLM57 EHAM")
    check_eq(ex("KLM57 fly to EHAM, that's the new destination"), "DEST KLM57 EHAM")
    check_eq(ex("KLM57 is going to EHAM"), "DEST KLM57 EHAM")
  end
end

-- Cycle 37 (tr80): a game programmer's words: despawn (DEL), tp (MOVE), rotate clockwise (a right turn),
-- rotation (the heading), vertical velocity and "go vertical N up/down" (VS), banking (BANK), hit play (OP),
-- tick rate in Hz (DT, its inverse), the hitbox (the protected zone), auto resolution, debug info and an
-- aircraft's state printed (POS), a trail given (TRAIL ON), "jump ahead to"/"cut the corner to" a waypoint
-- (DIRECT), "right on top of" a point (MOVE) and a value said "-ish" (read as said, as "roughly 250" is)
do
  local _, ex = scene({ "CRE KLM58 B738 52.6 4.6 090 FL120 250", "DEFWPT GAME1 52.7 4.9", "DEFWPT GAME2 52.9 5.2",
    "ADDWPT KLM58 GAME1", "ADDWPT KLM58 GAME2" })
  check_eq(ex("despawn KLM58"), "DEL KLM58")
  check_eq(ex("tp KLM58 to GAME2"), "MOVE KLM58 GAME2")
  check_eq(ex("teleport KLM58 right on top of GAME1"), "MOVE KLM58 GAME1")
  check_eq(ex("rotate KLM58 30 degrees clockwise"), "HDG KLM58 120 RIGHT")
  check_eq(ex("KLM58 rotate 45 anticlockwise"), "HDG KLM58 45 LEFT")
  check_eq(ex("KLM58 rotation 270"), "HDG KLM58 270")
  check_eq(ex("KLM58 vertical velocity -1000"), "VS KLM58 -1000")
  check_eq(ex("KLM58 go vertical 900 down"), "VS KLM58 -900")
  check_eq(ex("KLM58 banking 20 degrees"), "BANK KLM58 20")
  check_eq(ex("alright, press play"), "OP")
  check_eq(ex("tick rate 5 hz"), "DT 0.2")
  asked(ex("tick rate 0 hz"), "no rate")
  check_eq(ex("make the hitbox radius 4 nm"), "ZONER 4")
  check_eq(ex("set the vertical hitbox to 800 ft"), "ZONEDH 800")
  check_eq(ex("turn on auto conflict resolution"), "RESO MVP")
  check_eq(ex("show me debug info for KLM58"), "POS KLM58")
  check_eq(ex("print the state of KLM58"), "POS KLM58")
  check_eq(ex("give all the planes a trail"), "TRAIL ON")
  check_eq(ex("KLM58 jump ahead to GAME2"), "DIRECT KLM58 GAME2")
  check_eq(ex("have KLM58 cut the corner to GAME2"), "DIRECT KLM58 GAME2")
  check_eq(ex("KLM58 speed 230-ish"), "SPD KLM58 230")
  check_eq(ex("destroy KLM58"), "DEL KLM58")
  check_eq(ex("warp KLM58 to GAME1"), "MOVE KLM58 GAME1")
  check_eq(ex("yaw KLM58 left 20"), "HDG KLM58 70 LEFT")
  check_eq(ex("KLM58 rotate to 300"), "HDG KLM58 300")
  check_eq(ex("set the timescale to 3"), "DTMULT 3")
  -- where the class stops: no place to jump to is a fast-forward's missing time; a word not understood asks
  asked(ex("jump ahead a bit"), "no time, no place")
  asked(ex("KLM58 go vertical"), "no vertical speed")
  asked(ex("set KLM58 rotation speed to 140"), "a take-off's rotation speed is no heading nor speed")
end

-- Cycle 37 (tr80): random traffic of a family flown in several variants ("5 random 737s") asks which variant,
-- as a creation does; a model's name in the plural ("737-800s") is that model; a word with digits that names
-- no type is asked about, never dropped; a family's nickname said with no type ("a dreamliner") is asked
-- about, naming its designators
do
  local _, ex = scene({ "CRE KLM59 B738 52.6 4.6 090 FL120 250" })
  asked(ex("spawn 6 random 737s"), "a family in the plural")
  asked(ex("generate 4 random 787 aircraft"), "a family")
  check_eq(ex("spawn 3 random 737-800s"), "MCRE 3 B738")
  check_eq(ex("spawn 3 random A321s"), "MCRE 3 A321")
  asked(ex("spawn 3 random zz-900s"), "no type of that name")
  asked(ex("create a dreamliner DLH7 at 52.0 4.0 heading 090 FL200 280 knots"), "the 787 family's nickname")
  check_eq(ex("create a dreamliner DLH7 B789 at 52.0 4.0 heading 090 FL200 280 knots"),
    "CRE DLH7 B789 52 4 90 FL200 280")
end

-- Cycle 37 (tr80): an airport's name said beside its code ("st hubert, CYHU") is accounted for by the code;
-- a name of another airport is still asked about; "come from" an airport's code is the origin; "wind check at"
-- a place is GETWIND there; "stop X (from) following its waypoints" is LNAV off
do
  local _, ex = navscene({ "CRE JZA77 DH8D 45.4 -73.7 090 6000 220", "ADDWPT JZA77 CYHU" }, "a name beside its code")
  if ex then
    check_eq(ex("JZA77 is now headed to st hubert, CYHU, make that the destination"), "DEST JZA77 CYHU")
    asked(ex("JZA77 is now headed to mirabel, CYHU, make that the destination"), "another airport's name")
    check_eq(ex("have JZA77 come from st hubert, CYHU"), "ORIG JZA77 CYHU")
    asked(ex("have JZA77 come from the south"), "no airport after from")
    check_eq(ex("wind check at CYHU"), "GETWIND CYHU")
    check_eq(ex("JZA77 stop following your waypoints"), "LNAV JZA77 OFF")
    asked(ex("JZA77 don't stop following your waypoints"), "a negated stop")
  end
end

-- Cycle 37 (atdo): an instruction said with its verb, to start at a waypoint of the route ("at FIX descend",
-- "after FIX climb", "after passing FIX", "when X gets to FIX ..."), is BlueSky's AT acid wp DO with the
-- full command; a value said there with no verb, or a crossing, stays the AT constraint; a waypoint off the
-- route is asked about, naming it
do
  local s, ex = scene({ "CRE SAS31 A320 55.0 12.0 090 FL240 280", "DEFWPT OLMAK 55.0 12.6", "DEFWPT TUREN 55.0 13.2",
    "DEFWPT VISBO 55.4 12.4", "ADDWPT SAS31 OLMAK", "ADDWPT SAS31 TUREN" })
  check_eq(ex("SAS31 at OLMAK descend flight level nine zero"), "AT SAS31 OLMAK DO ALT SAS31 FL90")
  check_eq(ex("SAS31, after TUREN climb to FL260"), "AT SAS31 TUREN DO ALT SAS31 FL260")
  check_eq(ex("SAS31 after passing OLMAK reduce speed to 230 knots"), "AT SAS31 OLMAK DO SPD SAS31 230")
  check_eq(ex("SAS31 when at TUREN descend FL200"), "AT SAS31 TUREN DO ALT SAS31 FL200")
  check_eq(ex("when SAS31 gets to OLMAK slow it to 240"), "AT SAS31 OLMAK DO SPD SAS31 240")
  check_eq(ex("once SAS31 passes TUREN, have it climb to flight level 300"), "AT SAS31 TUREN DO ALT SAS31 FL300")
  -- the command checks and runs on the simulator: stored on the waypoint, run when it is passed
  check(s:exec("AT SAS31 OLMAK DO ALT SAS31 FL90"), "AT DO runs")
  -- no verb, or a crossing: the constraint at the waypoint
  check_eq(ex("SAS31 at OLMAK FL150"), "AT SAS31 OLMAK ALT FL150")
  check_eq(ex("SAS31 cross TUREN at FL180"), "AT SAS31 TUREN ALT FL180")
  check_eq(ex("SAS31 at OLMAK speed 250"), "AT SAS31 OLMAK SPD 250")
  -- off the route: asked, naming the waypoint
  local off = ex("SAS31 at VISBO descend FL100")
  asked(off, "a waypoint off the route")
  check(off:find("VISBO is not on SAS31's route", 1, true) ~= nil, off)
  off = ex("when SAS31 passes VISBO descend FL100")
  check(off:find("VISBO is not on SAS31's route", 1, true) ~= nil, off)
  -- "until FIX then ...": the value now, the instruction after "then" from the waypoint on
  check_eq(ex("SAS31 maintain 260 knots until OLMAK then descend FL200"), "SPD SAS31 260 ; AT SAS31 OLMAK DO ALT SAS31 FL200")
  -- (a level kept that the aircraft flies changes nothing: no command, G:kept_until; another level is flown)
  check_eq(ex("SAS31 keep FL240 till TUREN then reduce 220"), "AT SAS31 TUREN DO SPD SAS31 220")
  check_eq(ex("SAS31 keep FL250 till TUREN then reduce 220"), "ALT SAS31 FL250 ; AT SAS31 TUREN DO SPD SAS31 220")
  off = ex("SAS31 maintain 260 knots until VISBO then descend FL200")
  check(off:find("VISBO is not on SAS31's route", 1, true) ~= nil, off)
  -- "direct FIX, then at FIX climb ...": the direct-to now, the next instruction from the waypoint on
  check_eq(ex("SAS31 direct TUREN, then at TUREN climb FL280"), "DIRECT SAS31 TUREN ; AT SAS31 TUREN DO ALT SAS31 FL280")
  -- taken back, or said "now": never tied to the waypoint
  check(not ex("SAS31, after passing OLMAK descend... correction, descend now to FL150"):find("DO", 1, true),
    "a corrected instruction at a waypoint")
  -- a word of courtesy between the callsign and the waypoint (Greek too)
  check_eq(ex("SAS31, parakaló, after TUREN climb FL260"), "AT SAS31 TUREN DO ALT SAS31 FL260")
  check_eq(ex("SAS31, kiitos, at OLMAK descend FL100"), "AT SAS31 OLMAK DO ALT SAS31 FL100")
  -- the condition of passing the waypoint said after the instruction's value; "at FIX" alone there is asked
  check_eq(ex("SAS31 descend FL150 when passing TUREN"), "AT SAS31 TUREN DO ALT SAS31 FL150")
  check_eq(ex("SAS31 reduce 230 once it reaches OLMAK."), "AT SAS31 OLMAK DO SPD SAS31 230")
  local at_end = ex("SAS31 reduce 230 at OLMAK")
  check(at_end:match("^ASK Should that happen at OLMAK%?") ~= nil, at_end)
  off = ex("SAS31 descend FL150 when passing VISBO")
  check(off:find("VISBO is not on SAS31's route", 1, true) ~= nil, off)
  -- another aircraft's instruction at the waypoint is asked about, never tied to it
  asked(ex("CRE KLM9 B738 54.0 12.0 090 FL200 250 ; when SAS31 gets to OLMAK, KLM9 descend FL150"), "another aircraft")
end

-- Cycle 38 (clock): "back to real time" is read from the clock's state. In fast-time OP (only OP ends
-- it, at DTMULT 1); running or held, DTMULT 1 (the rate: a held clock stays held); an FF said before it
-- in the same request is fast-time. Words that start the clock still start it (OP).
do
  local _, fast = scene({ "CRE PTR61 A320 48 11 270 FL210 260", "FF" })
  check_eq(fast("right, go back to real time now"), "OP")
  check_eq(fast("back to realtime please"), "OP")
  check_eq(fast("real time speed again"), "OP")
  local _, held = scene({ "CRE PTR61 A320 48 11 270 FL210 260" })
  check_eq(held("right, go back to real time now"), "DTMULT 1")
  check_eq(held("skip ahead ten minutes, then back to real time"), "FF 600 ; OP")
  check_eq(held("let it run, back to real time"), "OP")
  local quick, at4 = scene({ "CRE PTR61 A320 48 11 270 FL210 260", "OP", "DTMULT 4" })
  check_eq(at4("ok, back to real time"), "DTMULT 1")
  check_eq(quick:dtmult(), 4)  -- translating runs nothing
  -- a clock state not known (a world without one) is asked
  local grammar = require("translate.grammar")
  local r = grammar.translate("back to real time", { aircraft = {}, waypoints = {} })
  check(r.ask ~= nil and r.ask:find("(OP)", 1, true) ~= nil and r.ask:find("(DTMULT 1)", 1, true) ~= nil,
    tostring(r.ask))
end

-- Cycle 38 (fix78): a compass point leaned toward ("more to the north", "a bit further east", "north a
-- little", "northwards") names no heading: asked; a compass point said plainly ("fly west") is its heading
do
  local _, ex = scene({ "CRE NLX40 B738 52.3 4.8 200 FL220 270" })
  local q = ex("turn NLX40 somewhat more to the west")
  check(q:find("'more to the west' names no heading", 1, true) ~= nil, q)
  asked(ex("NLX40, turn a little further south"), "a little further south")
  asked(ex("NLX40 come north slightly"), "north slightly")
  asked(ex("could NLX40 go a touch farther east"), "farther east")
  asked(ex("make NLX40 head southwards"), "southwards")
  asked(ex("create NLX41, an A320 at SPY, FL90, 230 kt, flying westwards"), "westwards in a creation")
  check_eq(ex("NLX40 fly west"), "HDG NLX40 270")
  check_eq(ex("NLX40 turn left to the south"), "HDG NLX40 180 LEFT")
end

-- Cycle 38 (fix78): numbered steps ("1. ... 2. ...", "Step 1: ... Step 2: ...", "1) ...", "(1) ...") and an
-- answer's label ("Q2b answer:") are structure: each step an instruction for the aircraft it names or the one
-- before; a number that breaks the count from 1 is no marker
do
  local _, ex = scene({ "CRE NLX40 B738 52.3 4.8 200 FL220 270", "CRE EWG9 A320 52.1 4.1 020 FL180 250" })
  check_eq(ex("1. climb NLX40 to FL260 2. speed 250 knots 3. turn right heading 240"),
    "ALT NLX40 FL260 ; SPD NLX40 250 ; HDG NLX40 240 RIGHT")
  check_eq(ex("Step 1: EWG9 heading 045. Step 2: descend FL120."), "HDG EWG9 45 ; ALT EWG9 FL120")
  check_eq(ex("1) EWG9 speed 220 kt 2) NLX40 descend to FL200"), "SPD EWG9 220 ; ALT NLX40 FL200")
  check_eq(ex("(1) NLX40 climb FL300 (2) EWG9 left heading 330"), "ALT NLX40 FL300 ; HDG EWG9 330 LEFT")
  check_eq(ex("Q4b answer: NLX40 reduces to 240 knots"), "SPD NLX40 240")
  check_eq(ex("Question 5: EWG9 climb to FL200"), "ALT EWG9 FL200")
  check_eq(ex("step one: NLX40 speed 240. step two: EWG9 climb FL220"), "SPD NLX40 240 ; ALT EWG9 FL220")
  check_eq(ex("1 - EWG9 turn left heading 300 2 - NLX40 descend FL180"), "HDG EWG9 300 LEFT ; ALT NLX40 FL180")
  check_eq(ex("1: NLX40 climb FL250 2: speed 260 knots"), "ALT NLX40 FL250 ; SPD NLX40 260")
  -- one step marked with no punctuation is no list ("step 1 second": the clock stepped on)
  check_eq(ex("step 1 second"), "FF 1")
  -- a count that does not start at 1, or skips, leaves the number in the sentence: asked
  asked(ex("NLX40 turn left 2. climb"), "a number after a turn")
  asked(ex("1. NLX40 climb to FL300 3. turn left"), "a count that skips")
end

-- Cycle 38 (fix78): textbook words. "bank (left) to heading N" is a turn ("bank angle 25" stays BANK); an
-- aircraft's data shown is POS; a conflict resolved or separation gained by an aircraft's instruction is its
-- purpose (no RESO, no ZONEDH); "place" a type with a new callsign creates it
do
  local _, ex = scene({ "CRE NLX40 B738 52.3 4.8 200 FL220 270", "CRE EWG9 A320 52.1 4.1 020 FL180 250" })
  check_eq(ex("NLX40, bank right onto heading 250"), "HDG NLX40 250 RIGHT")
  check_eq(ex("bank EWG9 to heading 100"), "HDG EWG9 100")
  check_eq(ex("NLX40 bank angle 20 degrees"), "BANK NLX40 20")
  check_eq(ex("display the data for EWG9"), "POS EWG9")
  check_eq(ex("can you show me NLX40's flight data"), "POS NLX40")
  check_eq(ex("solve the conflict by turning EWG9 left to heading 320"), "HDG EWG9 320 LEFT")
  check_eq(ex("NLX40 climb FL260 to resolve this conflict"), "ALT NLX40 FL260")
  check_eq(ex("EWG9 descend to FL160 to ensure vertical separation"), "ALT EWG9 FL160")
  check_eq(ex("place an Airbus A321 with callsign DLH7Q at 52.5 4.5, heading 180, FL150, 260 knots"),
    "CRE DLH7Q A321 52.5 4.5 180 FL150 260")
  check_eq(ex("place NLX40 at 52.0 4.0"), "MOVE NLX40 52 4")
  -- with no instruction for an aircraft, the setting is still asked or set
  asked(ex("resolve the conflict"), "a resolution with no method")
  check_eq(ex("set vertical separation to 1000 ft"), "ZONEDH 1000")
end

-- Cycle 38 (fix78): "descend 2000 feet" typed after the verb, from the flight levels or lower down, for one
-- aircraft or several, is asked: to or by?
do
  local _, ex = scene({ "CRE NLX40 B738 52.3 4.8 200 FL310 270", "CRE EWG9 A320 52.1 4.1 020 FL150 250" })
  asked(ex("NLX40 descend 3000 ft"), "to or by from FL310 (cycle 44: a step to some writers, the approach altitude to others)")
  asked(ex("EWG9 descend 3000 ft"), "to or by from FL150")
  asked(ex("NLX40 and EWG9 descend 2000 feet"), "to or by for two aircraft")
  check_eq(ex("NLX40 descend to 3000 ft"), "ALT NLX40 3000")
end

-- Cycle 38 (fix77): what a heading is flown for ("vectors to rejoin the track at FIX", "heading 200 to intercept
-- the airway at FIX") names a place where the vector ends, no direct-to: the heading alone is flown. A clause
-- of its own ("then rejoin the route at FIX", "cleared to rejoin ...") is still a direct-to.
do
  local _, ex = scene({ "CRE TUI4KM B738 51.0 8.0 270 FL240 280", "DEFWPT MOKSA 51.3 7.2", "ADDWPT TUI4KM MOKSA" })
  check_eq(ex("TUI4KM turn right heading 310, vectors to rejoin the airway at MOKSA"), "HDG TUI4KM 310 RIGHT")
  check_eq(ex("TUI4KM fly heading 250 to intercept the route at MOKSA"), "HDG TUI4KM 250")
  check_eq(ex("TUI4KM heading 250 vectoring to join the track at MOKSA, descend FL200"),
    "HDG TUI4KM 250 ; ALT TUI4KM FL200")
  check_eq(ex("TUI4KM heading 250, then rejoin the route at MOKSA"), "HDG TUI4KM 250 ; DIRECT TUI4KM MOKSA")
  check_eq(ex("TUI4KM climb FL260, cleared to rejoin the route at MOKSA"), "ALT TUI4KM FL260 ; DIRECT TUI4KM MOKSA")
end

-- Cycle 38 (fix77): the world's air forces ("<nation> air force" and "<nation> airforce", names.lua's air_forces)
-- and military transport telephony ("Ascot", "Rafair", "Cotam", "Canforce") are read as their ICAO prefixes; a
-- callsign flown under the word itself ("ASCOT41") is still that callsign, and a number no aircraft flies is asked.
do
  local _, ex = scene({ "CRE NAF330 C130 52.0 5.0 090 FL180 250", "CRE RRR2201 A332 52.5 4.0 270 FL300 290",
    "CRE ASCOT41 C130 52.2 4.5 180 FL150 230", "CRE FAF1704 A400 52.8 5.5 010 FL260 280" })
  check_eq(ex("Netherlands Air Force 330, climb FL200"), "ALT NAF330 FL200")
  check_eq(ex("where is netherlands airforce three three zero"), "POS NAF330")
  check_eq(ex("Ascot 2201 descend flight level 280"), "ALT RRR2201 FL280")
  check_eq(ex("Ascot 41 turn left heading 150"), "HDG ASCOT41 150 LEFT")
  check_eq(ex("French Air Force 1704, reduce speed 250"), "SPD FAF1704 250")
  asked(ex("Netherlands Air Force 303 climb FL200"), "an air force callsign no aircraft flies")
  asked(ex("Ascot, climb FL310"), "Ascot said alone, two aircraft fly under it")
end

-- Cycle 38 (fix77): military and exercise words. "angels N" is N thousand feet; "track NNN" (up to 360) a
-- heading; "knots IAS" the speed; a serial is the exercise's run ("resume the serial", "serial 2:" a label);
-- "separation minima"; "set up trails" shows them; "dt multiplier" is DTMULT; a box named after a colon; "after
-- FIX" closing the request starts the instruction there; a navaid of the route said by name is removed from it;
-- the flight number said again after the callsign is the same aircraft. Where each stops, it asks.
do
  local _, ex = scene({ "CRE CFC4410 C130 52.0 6.0 090 FL180 250", "CRE TRA62K B738 52.4 5.0 270 FL330 280",
    "DEFWPT LOBAR 52.1 6.6", "DEFWPT TOMVA 52.3 7.2",
    "ADDWPT CFC4410 LOBAR", "ADDWPT CFC4410 TOMVA" })
  check_eq(ex("Canforce 4410 descend angels one five"), "ALT CFC4410 15000")
  check_eq(ex("CFC4410 climb to angels 21"), "ALT CFC4410 21000")
  asked(ex("CFC4410 climb angels twenty one"), "angels said as a compound number")
  check_eq(ex("CFC4410 track 135"), "HDG CFC4410 135")
  check_eq(ex("CFC4410 climb FL200 and fly track 070"), "ALT CFC4410 FL200 ; HDG CFC4410 70")
  asked(ex("CFC4410 track 520"), "a track past 360")
  check_eq(ex("CFC4410 increase to 280 knots IAS"), "SPD CFC4410 280")
  check_eq(ex("resume the serial"), "OP")
  check_eq(ex("serial two: CFC4410 climb FL200"), "ALT CFC4410 FL200")
  check_eq(ex("horizontal separation minima 3 NM"), "ZONER 3")
  check_eq(ex("please set up trails"), "TRAIL ON")
  check_eq(ex("set dt multiplier 4"), "DTMULT 4")
  check_eq(ex("draw the box: AREA7 from 52.0N 005.0E to 52.5N 006.0E"), "BOX AREA7 52 5 52.5 6")
  check_eq(ex("CFC4410 climb FL220 after TOMVA"), "AT CFC4410 TOMVA DO ALT CFC4410 FL220")
  asked(ex("CFC4410 climb FL220 after departure"), "after no waypoint")
  -- ("after FIX" closing an expected clearance is no condition on the instruction before it)
  check_eq(ex("CFC4410 descend FL160, expect lower after TOMVA"), "ALT CFC4410 FL160")
  check_eq(ex("Canforce 4410, 4410, reduce 230 knots"), "SPD CFC4410 230")
end
do
  local _, ex = navscene({ "CRE GAF620 A400 53.0 8.2 090 FL200 250", "ADDWPT GAF620 BMN", "ADDWPT GAF620 DLE",
    "CRE GAF163 A332 53.7 8.4 200 FL270 290", "ADDWPT GAF163 WSR" }, "navaids of the route by name")
  if ex then
    check_eq(ex("GAF620, remove Leine from the route please"), "DELWPT GAF620 DLE")
    check_eq(ex("German Air Force 620 delete Bremen from its route"), "DELWPT GAF620 BMN")
    asked(ex("GAF620 remove Weser from the route"), "a navaid another aircraft's route holds")
    check_eq(ex("German Air Force 163 descend FL250 after Weser"), "AT GAF163 WSR DO ALT GAF163 FL250")
  end
end

-- Cycle 38 (fix77): military types at creation by the names their air forces give them ("C-17", "KC-135", "E-3",
-- "A400M", "C-130"); each is modelled (the class model flies an unlisted designator as a jet, the A400 and C130 as
-- turboprops); a type squawk has no name for is asked about.
do
  local _, ex = scene({ "CRE KLM1234 B738 52.2 4.2 300 FL250 280" })
  check_eq(ex("create RCH612, C-17, 53 5, heading 090, FL300, 300 knots"), "CRE RCH612 C17 53 5 90 FL300 300")
  check_eq(ex("put a tanker in: QID31, KC-135, 54 6, heading 180, FL260, 310 knots"),
    "CRE QID31 K35R 54 6 180 FL260 310")
  check_eq(ex("new track NATO05, E-3, 53.5 6.5, heading 045, FL300, 280 knots"),
    "CRE NATO05 E3TF 53.5 6.5 45 FL300 280")
  check_eq(ex("create BAF605 A400M at 51 4 heading 270 FL180 240 knots"), "CRE BAF605 A400 51 4 270 FL180 240")
  check_eq(ex("create CTM1001, a C-130, 50 3, heading 010, FL160, 220 knots"), "CRE CTM1001 C130 50 3 10 FL160 220")
  asked(ex("create FAF2201, Rafale, 50 3, heading 010, FL160, 420 knots"), "a fighter squawk has no name for")
end

-- Cycle 38 (fix77): a telephony word glued to a new callsign's number ("speedbird44") is the airline's prefix,
-- but not where an aircraft flies with that word as its id's prefix ("ascot43" with ASCOT41 flying), nor typed in
-- capitals as an id ("REACH77").
do
  local _, ex = scene({ "CRE ASCOT41 C130 52.6 7.6 030 FL160 230", "CRE BAW12 A320 52.0 4.0 090 FL300 280" })
  check_eq(ex("create ASCOT42 C130 at 52 7 heading 060 FL140 220 knots"), "CRE ASCOT42 C130 52 7 60 FL140 220")
  check_eq(ex("create speedbird44 A320 at 52 6 heading 090 FL200 250 knots"), "CRE BAW44 A320 52 6 90 FL200 250")
  check_eq(ex("create ascot43 C130 at 52 6 heading 090 FL200 250 knots"), "CRE ASCOT43 C130 52 6 90 FL200 250")
  -- typed in capitals, the id as typed; with no aircraft of its prefix flying too
  check_eq(ex("create REACH77, C-17, at 52 6, heading 090, FL300, 300 knots"), "CRE REACH77 C17 52 6 90 FL300 300")
end

-- Cycle 39 (lead): a bare value between the callsign and the instruction word ("BAW256 9 climb FL300",
-- "BAW256, 345, climb FL300") is explained by nothing and asked about by name, never dropped; the flight
-- number said again ("DLH9CK, 9CK, reduce 250") is the callsign's
do
  local _, ex = scene({ "CRE BAW256 B738 52 4 090 FL200 250", "CRE DLH9CK A320 52 5 090 FL200 250" })
  asked(ex("BAW256 9 climb FL300"), "a stray number before the verb")
  asked(ex("BAW256, 345, climb FL300"), "a stray number set off by commas")
  asked(ex("BAW256 one two three turn left heading 300"), "stray digits said as words")
  check_eq(ex("BAW256 climb FL300"), "ALT BAW256 FL300")
  check_eq(ex("Lufthansa 9CK, 9CK, reduce 250"), "SPD DLH9CK 250")
end

-- Cycle 39 (fix79): a navaid said by its navdata name in capitals ("LIMA" is the LIM VOR-DME over Peru, not
-- the Italian airfield of that ident) is its ident for every place argument; a place of that ident near the
-- traffic elsewhere than the navaid (the fix LAMAR 40 NM from the LAMAR VOR, LAA) is asked about
do
  local _, ex = navscene({ "CRE LPE77 A320 -12.3 -76.9 330 FL150 250", "CRE SKU301 A20N -11.8 -77.4 150 FL200 280" },
    "navaid names in capitals")
  if ex then
    check_eq(ex("LPE77, when 15 miles from LIMA, descend FL100"), "ATDIST LPE77 LIM 15 ALT LPE77 FL100")
    check_eq(ex("where is the LIMA VOR?"), "POS LIM")
    check_eq(ex("SKU301 proceed direct LIMA"), "ADDWPT SKU301 LIM ; DIRECT SKU301 LIM")
    check_eq(ex("LPE77 add LIMA to the route"), "ADDWPT LPE77 LIM")
    -- a waypoint being defined under that name is no navaid
    check_eq(ex("define waypoint LIMA at 12 south 77 west"), "DEFWPT LIMA -12 -77")
  end
  local _, far = navscene({ "CRE N123AB C172 38.3 -102.9 090 8000 110" }, "a navaid name that a fix bears")
  if far then
    check(far("N123AB direct LAMAR"):match("^ASK .*LAA") ~= nil, "the fix LAMAR or the LAMAR VOR")
  end
end

-- Cycle 39 (fix79): the country airlines of a group by the name said with the country ("LAN Ecuador 1422":
-- LNE, "LAN Peru": LPE) and by their ICAO telephony ("Aerolane", "Aerorepublica")
do
  local _, ex = scene({ "CRE LNE902 A320 -0.8 -78.9 045 FL190 280", "CRE LAN902 B788 -1.5 -79.5 200 FL300 290",
    "CRE RPB55 A320 4.8 -73.8 250 FL150 240" })
  check_eq(ex("set the destination of the LAN Ecuador 902 to SEQU"), "DEST LNE902 SEQU")
  check_eq(ex("aerolane nine zero two climb flight level two one zero"), "ALT LNE902 FL210")
  check_eq(ex("LAN nine zero two descend flight level two six zero"), "ALT LAN902 FL260")
  check_eq(ex("aerorepublica five five turn right heading zero nine zero"), "HDG RPB55 90 RIGHT")
  -- the group's name alone with a flight number two of its airlines fly is asked
  asked(ex("LATAM 902 climb FL320"), "LATAM 902: LAN or LNE")
end

-- Cycle 39 (fix79): "be level FL190 over PUNPU", "to reach ... overhead X": a level to be reached over a
-- waypoint of the route is the level cleared now and its AT constraint; over a waypoint off the route it is asked
do
  local _, ex = scene({ "CRE CMP40 B738 9.4 -79.0 210 FL260 290", "DEFWPT KARIN 8.9 -79.3", "DEFWPT TOMAS 9.9 -79.9",
    "ADDWPT CMP40 KARIN" })
  check_eq(ex("CMP40 be level flight level one seven zero over KARIN"), "ALT CMP40 FL170 ; AT CMP40 KARIN ALT FL170")
  check_eq(ex("CMP40 descend to reach FL150 overhead KARIN"), "ALT CMP40 FL150 ; AT CMP40 KARIN ALT FL150")
  asked(ex("CMP40 be level FL170 over TOMAS"), "over a waypoint off the route")
end

-- Cycle 39 (fix79): "to" between a callsign's digits said in words and a latitude in words is the preposition
-- when the digits with it would make no latitude ("move the Avianca two four to nine north": 2429 north)
do
  local _, ex = scene({ "CRE AVA36 A320 8.4 -79.3 350 FL200 280", "CRE AVA3628 A319 9.4 -79.6 170 FL220 280" })
  check_eq(ex("move the Avianca three six to eight north seventy eight west"), "MOVE AVA36 8 -78")
  check_eq(ex("move Avianca three six to one zero point five north, seventy nine west"), "MOVE AVA36 10.5 -79")
  -- digits that with it still make a latitude stay the digit: another callsign
  check_eq(ex("Avianca three six two eight climb flight level two four zero"), "ALT AVA3628 FL240")
end

-- Cycle 39 (fix79): "put the simulation at times four": a multiplier said of the simulation, "times" before or
-- after its number, no aircraft named
do
  local _, ex = scene({ "CRE CMP40 B738 9.4 -79.0 210 FL260 290" })
  check_eq(ex("put the simulation at times four"), "DTMULT 4")
  check_eq(ex("simulation times two please"), "DTMULT 2")
  -- an aircraft named: no clock's rate
  asked(ex("put CMP40 at times four"), "an aircraft at times four")
end

-- Cycle 39 (fix79): a city whose name lexicon.city_airports gives is its one large airport ("Bogota" is SKBO,
-- not the medium EL DORADO in Venezuela); a navaid's kind said before its name (the Spanish order, "the VOR
-- Bogota", "from VOR BOG") names the navaid, no approach clearance
do
  local _, ex = navscene({}, "a city's large airport")
  if ex then
    check_eq(ex("set the wind at Bogota at FL120 to 250 degrees 15 knots"), "WIND SKBO FL120 250 15")
  end
  local _, ava = navscene({ "CRE AVA77 A320 4.9 -74.4 135 FL190 280" }, "the kind before a navaid's name")
  if ava then
    check_eq(ava("AVA77 proceed to the VOR Bogota"), "ADDWPT AVA77 BOG ; DIRECT AVA77 BOG")
    check_eq(ava("AVA77 at two zero miles from the VOR Bogota descend one four thousand feet"),
      "ATDIST AVA77 BOG 20 ALT AVA77 14000")
    asked(ava("AVA77 direct to Bogota"), "the city: the BOG VOR or SKBO")
    -- "VOR approach" stays an approach clearance, not simulated: no place
    check_eq(ava("AVA77 cleared VOR approach runway 13L"), "")
  end
end

-- Cycle 39 (fix79): English typed by Spanish speakers: "procede direct" (as "proceder" is spelled), "expedite
-- your/the descent to ...", the digit "fiver"; "is for traffic", "until further advise" are reasons and
-- limits, no values
do
  local _, ex = scene({ "CRE AVA51 A320 4.9 -74.4 135 FL190 280", "DEFWPT GAVIN 5.2 -74.0", "ADDWPT AVA51 GAVIN" })
  check_eq(ex("AVA51 procede direct GAVIN"), "DIRECT AVA51 GAVIN")
  check_eq(ex("AVA51 expedite your descent to flight level one one zero"), "ALT AVA51 FL110")
  asked(ex("AVA51 expedite your descent"), "a descent with no level")
  check_eq(ex("AVA51 reduce to two fiver zero knots"), "SPD AVA51 250")
  check_eq(ex("AVA51 turn to the left heading tree four zero, is for traffic"), "HDG AVA51 340 LEFT")
  check_eq(ex("AVA51 maintain flight level one niner zero until further advise"), "ALT AVA51 FL190")
end

-- Cycle 39 (fix80a): a turn's side corrected after its angle ("20 degrees left, sorry, right"; "left, um,
-- right": hesitations alone between two sides) turns that many degrees the corrected way
do
  local _, ex = scene({ "CRE NLX40 B738 52.3 4.8 200 FL220 270", "CRE EWG9 A320 52.1 4.1 020 FL180 250" })
  check_eq(ex("EWG9 turn 20 degrees left, sorry, right"), "HDG EWG9 40 RIGHT")
  check_eq(ex("EWG9 turn 20 degrees left, um, right"), "HDG EWG9 40 RIGHT")
  check_eq(ex("turn NLX40 right 30, I mean left"), "HDG NLX40 170 LEFT")
  -- the same side said again after a hesitation is no correction
  check_eq(ex("EWG9 turn 20 degrees left, er, left"), "HDG EWG9 360 LEFT")
end

-- Cycle 39 (fix80a): a value straight after an aircraft and "to", closed by "and" or a comma, is said for it:
-- never dropped beside the instruction after it ("the Ryanair to 110 and 230 knots"); digits with no unit
-- are asked about
do
  local _, ex = scene({ "CRE NLX40 B738 52.3 4.8 200 FL220 270" })
  asked(ex("NLX40 to two four zero and two five zero knots"), "a level or heading said bare after 'to'")
  asked(ex("NLX40 to two four zero, and two five zero knots"), "the same with a comma")
  check_eq(ex("NLX40 to FL240 and 250 knots"), "ALT NLX40 FL240 ; SPD NLX40 250")
end

-- Cycle 39 (fix80a): aircraft described ("where is the Iberia") are never a place of that name (navdata's
-- IBERIA airfield): one that fits is shown, several are asked about
do
  local _, ex = navscene({ "CRE IBE31 A320 40.5 -3.5 180 FL150 250", "CRE IBE77 A321 40.2 -3.2 320 FL120 240",
    "CRE AEA12 B738 40.6 -2.9 250 FL200 280" }, "aircraft described, never a place")
  if ex then
    asked(ex("where is the Iberia"), "two Iberias")
    asked(ex("where is Iberia"), "two Iberias, no article")
    check_eq(ex("where is the Air Europa"), "POS AEA12")
  end
end

-- Cycle 39 (fix80a): "..., no, just the heading" takes back what was said after the kept instruction's clause
-- (a condition and its instruction), not only the other kinds of command
do
  local _, ex = scene({ "CRE NLX40 B738 52.3 4.8 200 FL220 270", "CRE EWG9 A320 52.1 4.1 020 FL180 250" })
  check_eq(ex("EWG9 heading 090 and at FL200 speed 230, actually no, just the heading"), "HDG EWG9 90")
  check_eq(ex("NLX40 turn left heading 150, and at FL200 reduce 240, hmm no, only the heading"), "HDG NLX40 150 LEFT")
  asked(ex("EWG9 heading 090, no, just the climb"), "the kept kind never said")
end

-- Cycle 39 (fix80a): new aircraft listed each get their own fields (a value equal to another field's is read
-- in its place: "hdg 250 FL250 250"); a lead-in clause naming nothing, up to its comma, labels the list
do
  local _, ex = scene({})
  check_eq(ex("two aircraft: XY1 A320 52.0 4.0 hdg 250 FL250 250, XY2 A320 52.5 4.0 hdg 090 FL250 290"),
    "CRE XY1 A320 52 4 250 FL250 250 ; CRE XY2 A320 52.5 4 90 FL250 290")
  check_eq(ex("let's do a crossing pair, XY4 B738 at 52.0 4.0 heading 180 FL300 280 and XY5 B738 at 51.5 4.5 "
    .. "heading 360 FL300 280"), "CRE XY4 B738 52 4 180 FL300 280 ; CRE XY5 B738 51.5 4.5 360 FL300 280")
  -- with the speed said, a value said again is a repeat
  check_eq(ex("create XY7 A320 at 52.0 4.0, heading 240 so 240, FL100, 200 kt"), "CRE XY7 A320 52 4 240 FL100 200")
  -- a lead-in that names an aircraft flying is no label
  ex = select(2, scene({ "CRE NLX40 B738 52.3 4.8 200 FL220 270" }))
  asked(ex("NLX40 first, XY6 B738 at 52.0 4.0 heading 180 FL300 280"), "an aircraft before the new one")
end

-- Cycle 39 (fix80a): corrections read: "flew" (a wish's past tense), a heading cancelled ("undo", "cancel")
-- by the route resumed, an expected clearance up to a comma before a value for now; a heading cancelled with
-- nothing in its place is still asked
do
  local _, ex = scene({ "CRE NLX40 B738 52.3 4.8 200 FL220 270", "CRE EWG9 A320 52.1 4.1 020 FL180 250",
    "DEFWPT WPA 52.6 5.0", "ADDWPT NLX40 WPA" })
  check_eq(ex("EWG9, I'd prefer it flew heading 100"), "HDG EWG9 100")
  check_eq(ex("undo the heading on NLX40, back on its route please"), "LNAV NLX40 ON")
  check_eq(ex("cancel the vectors for NLX40 and resume own navigation"), "LNAV NLX40 ON")
  asked(ex("cancel the heading on NLX40 and climb FL260"), "a heading cancelled, a climb given")
  check_eq(ex("EWG9 expect further climb in ten minutes, for now FL200"), "ALT EWG9 FL200")
  check_eq(ex("EWG9 expect higher in ten minutes, FL240"), "")
end

-- Cycle 39 (fix80a): a list of simulation commands and instructions ("pause, then move ...") is translated on
-- the traffic its setup creates, as one request is
do
  local function set(text, setup) return said(graph.translate(text, { setup = setup, mode = "offline" })) end
  check_eq(set("hold, then move NLX40 to 52.2 4.2", "CRE NLX40 B738 52.3 4.8 200 FL220 270"),
    "HOLD ; MOVE NLX40 52.2 4.2")
  asked(set("hold, then move XX99 to 52.2 4.2", "CRE NLX40 B738 52.3 4.8 200 FL220 270"), "no such aircraft")
end

-- Cycle 39 (lead): a self-correction in words closing the request ("turn left 20, sorry", "climb FL300, no
-- wait", "..., make that") takes the instruction back with nothing in its place: asked, naming the words; a
-- hesitation alone ("uh"), a courtesy, "I mean" pointing back ("the Wideroe, I mean") or "from scratch" is none
do
  local _, ex = scene({ "CRE EWG9 A320 52 4 090 FL200 250" })
  check_eq(ex("EWG9 turn left 20, sorry"),
    "ASK You said 'sorry' with nothing after it. What is the corrected instruction?")
  asked(ex("EWG9 climb FL300, no wait"), "'no wait' closing the request")
  asked(ex("EWG9 climb FL300, make that"), "'make that' closing the request")
  check_eq(ex("clear the sim and start over from scratch"):match("^ASK You said") == nil, true)
  check_eq(ex("EWG9 climb FL300, no wait, FL320"), "ALT EWG9 FL320")
  check_eq(ex("EWG9 climb FL300 uh"), "ALT EWG9 FL300")
  check_eq(ex("EWG9 climb FL300 thanks"), "ALT EWG9 FL300")
  check_eq(ex("sorry, EWG9 climb FL300"), "ALT EWG9 FL300")
end

-- Cycle 39 (fix80b): wishes and their tails. A deadline at a part of the airspace squawk does not simulate
-- ("before it reaches the boundary") is met by the instruction flown now; one at a place, a time or with an
-- instruction of its own is asked. "nice and gentle" is how it is flown; "can it fly .80" a Mach number;
-- separation from a named aircraft the purpose of the level given (a height of separation from one asked); a
-- level wanted when an aircraft reaches a waypoint the constraint there; "N miles out from FIX" ATDIST; "and once
-- level, Mach .80" the speed waiting for the level given
do
  local _, ex = scene({ "DEFWPT LUMEK 52.1 4.6", "DEFWPT ORVAL 52.3 5.0", "CRE TAP21 A320 52.0 4.0 090 FL300 270",
    "ADDWPT TAP21 LUMEK", "ADDWPT TAP21 ORVAL", "CRE SAS77 B738 52.4 4.2 180 FL340 280",
    "CRE RYR3 B738 52.2 4.8 270 FL320 260" })
  check_eq(ex("TAP21 climb FL320 before it crosses the sector boundary"), "ALT TAP21 FL320")
  check_eq(ex("I'd want SAS77 at FL360 before the French border"), "ALT SAS77 FL360")
  asked(ex("TAP21 climb FL320 before LUMEK"), "a deadline at a waypoint")
  asked(ex("TAP21 climb FL320 before it turns at the boundary"), "a deadline holding an instruction")
  asked(ex("TAP21 climb FL320 before 5 minutes"), "a deadline in time")
  check_eq(ex("SAS77 descend at 1200 feet a minute, nice and smooth"), "VS SAS77 -1200")
  check_eq(ex("could SAS77 fly .80"), "SPD SAS77 M0.8")
  check_eq(ex("could SAS77 fly point seven eight"), "SPD SAS77 M0.78")
  check_eq(ex("SAS77, point seven six"), "SPD SAS77 M0.76")
  asked(ex("SAS77 heading 200 point seven"), "a fraction after another value")
  check_eq(ex("SAS77 to FL300, 250 on the heading, and 260 knots"), "ALT SAS77 FL300 ; HDG SAS77 250 ; SPD SAS77 260")
  asked(ex("SAS77 20 on the heading"), "two digits before 'on the heading'")
  check_eq(ex("let's give TAP21 some vertical separation from the Ryanair, take it to FL280"), "ALT TAP21 FL280")
  check_eq(ex("SAS77 climb FL360 for separation from RYR3"), "ALT SAS77 FL360")
  asked(ex("give TAP21 2000 ft of separation from RYR3"), "a height of separation from an aircraft")
  check_eq(ex("when TAP21 gets to ORVAL I'd like it at FL280"), "AT TAP21 ORVAL ALT FL280")
  check_eq(ex("when TAP21 reaches ORVAL, it should be at 250 knots"), "AT TAP21 ORVAL SPD 250")
  check_eq(ex("when TAP21 gets to ORVAL descend it to FL280"), "AT TAP21 ORVAL DO ALT TAP21 FL280")
  check_eq(ex("once TAP21 is 15 miles out from ORVAL, descend FL280"), "ATDIST TAP21 ORVAL 15 ALT TAP21 FL280")
  check_eq(ex("SAS77 descend FL300 and once level, Mach .74"), "ALT SAS77 FL300 ; ATALT SAS77 FL300 SPD SAS77 M0.74")
  asked(ex("SAS77 once level, Mach .74"), "no level given to wait for")
  -- a rate with no direction said descends to the level given below the aircraft (never climbs away from it)
  check_eq(ex("TAP21, be at FL280 by ORVAL, rate 1500"), "AT TAP21 ORVAL ALT FL280 ; VS TAP21 -1500")
  check_eq(ex("SAS77 FL360, rate 1500"), "ALT SAS77 FL360 ; VS SAS77 1500")
end

-- Cycle 39 (fix80b): aircraft described and what is asked about them. "lose", "take out" and "get ... off the
-- screen" delete the aircraft described; "tell me about" it is POS; what is left of its route LISTRTE; a position
-- "relative to" a place POS; "the Nostrum" Air Nostrum; an airline in the plural ("the two Vuelings", "both
-- Vuelings") each of it flying when the count fits, else asked; a city named for its airport the destination;
-- a place by its name ending a route ("via BIDAC then Bilbao") the route's next place
do
  local _, ex = scene({ "DEFWPT LUMEK 52.1 4.6", "CRE VLG21 A320 52.0 4.0 090 FL300 270",
    "CRE VLG88 A321 52.4 4.2 180 FL340 280", "CRE ANE40 CRJ9 52.2 4.8 270 FL220 240",
    "CRE EZY9 A319 52.6 4.4 010 FL280 260", "CRE AEA3 B738 52.3 3.8 150 FL260 250" })
  check_eq(ex("lose the Nostrum"), "DEL ANE40")
  check_eq(ex("take out the easyJet"), "DEL EZY9")
  check_eq(ex("get the Air Europa off the display"), "DEL AEA3")
  check_eq(ex("ANE40 lose 20 knots"), "SPD ANE40 220")
  check_eq(ex("tell us about the Nostrum"), "POS ANE40")
  asked(ex("tell me about the Vueling"), "two Vuelings fly")
  check_eq(ex("what has EZY9 got left on its route"), "LISTRTE EZY9")
  check_eq(ex("what's left of the easyJet's flight plan"), "LISTRTE EZY9")
  check_eq(ex("where's EZY9 relative to LUMEK"), "POS EZY9")
  check_eq(ex("both Vuelings, speed 240"), "SPD VLG21 240 ; SPD VLG88 240")
  check_eq(ex("the two Vuelings descend FL200"), "ALT VLG21 FL200 ; ALT VLG88 FL200")
  check_eq(ex("both Vuelings, VLG21 FL200 and VLG88 FL220"), "ALT VLG21 FL200 ; ALT VLG88 FL220")
  asked(ex("the three Vuelings, speed 240"), "three Vuelings, two flying")
  -- other traffic said in the plural is never instructed
  check_eq(ex("turn EZY9 left 20, away from the Vuelings"), "HDG EZY9 350 LEFT")
  check_eq(ex("climb EZY9 above the two Vuelings to FL350"), "ALT EZY9 FL350")
  check_eq(ex("EZY9 climb FL350 to stay clear of the Vuelings"), "ALT EZY9 FL350")
  check_eq(ex("EZY9 climb FL350 because the Vuelings are close"), "ALT EZY9 FL350")
  asked(ex("the three ryanairs, speed 240"), "a count of an airline none of which flies, never a callsign's digits")
  local nav, nex = navscene({ "CRE EZY9 A319 43.0 2.5 010 FL280 260", "CRE AEA3 B738 43.9 -0.5 250 FL240 260" },
    "a city's airport as destination and a place by its name in a route")
  if nav then
    check_eq(nex("the easyJet's going to Carcassonne"), "DEST EZY9 LFMK")
    check_eq(nex("EZY9's going to Perpignan"), "DEST EZY9 LFMP")
    check_eq(nex("route AEA3 via LAPOS and then Bilbao"), "ADDWPT AEA3 LAPOS ; ADDWPT AEA3 LEBB")
    asked(nex("route AEA3 via LAPOS then Bilbao then SOSTO"), "a name between the route's places")
  end
end

-- Cycle 39 (fix80b): settings said by purpose. "shorten the look-ahead", a factor said after "resolution
-- margin" (RFACH/RFACV; no vertical resolutions), the resolver's vertical speed (RMETHV; "only" vertical is
-- asked, squawk's resolutions are never vertical alone), "climb/descend via the route" (VNAV; via a SID or STAR
-- asked)
do
  local _, ex = scene({ "CRE SAS77 B738 52.4 4.2 180 FL340 280" })
  check_eq(ex("could we shorten the look-ahead to 4 minutes"), "DTLOOK 240")
  check_eq(ex("set the vertical resolution margin to 1.3"), "RFACV 1.3")
  check_eq(ex("horizontal resolution margin 1.15"), "RFACH 1.15")
  check_eq(ex("vertical resolution margin 10 percent"), "RFACV 1.1")
  check_eq(ex("the resolver may use vertical speed"), "RMETHV V/S")
  asked(ex("the resolver should only use vertical speed changes"), "vertical-only resolutions")
  check_eq(ex("SAS77 descend via its route"), "VNAV SAS77 ON")
  asked(ex("SAS77 descend via the STAR"), "a STAR, which squawk does not fly")
  check_eq(ex("SAS77 climb via the route to FL360"), "ALT SAS77 FL360")
end

-- Cycle 40 (d84): "lateral nav" and "vertical nav" are LNAV and VNAV ("nav" is navigation's short word), so a
-- switch said before another instruction is issued, never dropped; the mode with no on or off is asked
do
  local _, ex = scene({ "CRE QTR7 A320 25.0 55.0 090 FL150 260" })
  check_eq(ex("QTR7 lateral nav off, fly heading 040"), "LNAV QTR7 OFF ; HDG QTR7 40")
  check_eq(ex("QTR7 vertical nav off, climb FL170"), "VNAV QTR7 OFF ; ALT QTR7 FL170")
  check_eq(ex("QTR7 vertical nav on"), "VNAV QTR7 ON")
  asked(ex("QTR7 lateral nav"), "a navigation mode with no on or off")
end

-- Cycle 40 (d84): Indian airlines by their names: "Akasa" and "Akasa Air" (AKJ), "Air India Express" (AXB), so
-- the words around such a callsign stay the instruction's ("add a waypoint to Akasa 1401's route" is no listing
-- of its route); a flight number no aircraft has is still asked
do
  local _, ex = scene({ "CRE AKJ1401 B38M 12.9 77.6 040 FL150 270", "CRE AXB1721 B738 13.1 80.2 200 FL190 280" })
  check_eq(ex("Air India Express 1721 reduce two six zero knots"), "SPD AXB1721 260")
  check_eq(ex("Akasa Air 1401, descend flight level one one zero"), "ALT AKJ1401 FL110")
  asked(ex("Akasa 1410 descend FL110"), "an Akasa flight number none flies")
  local nav, nex = navscene({ "CRE AKJ1401 B38M 12.9 77.6 040 FL150 270" }, "a waypoint added to an Akasa's route")
  if nav then
    check_eq(nex("add GURAS to Akasa 1401's route"), "ADDWPT AKJ1401 GURAS")
  end
end

-- Cycle 40 (d84): Indian English "revert" (reply) before "your" or "with" asks the aircraft's own value, as
-- "report your level" (POS); "revert to heading 270" is no such request and stays asked; "sir" and "madam"
-- address the listener and carry nothing
do
  local _, ex = scene({ "CRE SEJ811 B738 19.1 72.9 090 FL160 270" })
  check_eq(ex("SpiceJet 811 revert your level"), "POS SEJ811")
  check_eq(ex("SpiceJet 811, revert with your present speed"), "POS SEJ811")
  check_eq(ex("SpiceJet 811 report with your heading"), "POS SEJ811")
  asked(ex("SpiceJet 811 revert to heading 270"), "'revert to': going back, not a reply")
  asked(ex("SpiceJet 811 revert your level FL150"), "a value after the request for a reply")
  check_eq(ex("sir where is SpiceJet 811 showing"), "POS SEJ811")
  check_eq(ex("SpiceJet 811 climb FL180 sir"), "ALT SEJ811 FL180")
end

-- Cycle 40 (d81): a speed in another unit is its conversion to the nearest knot, never rounded to tens nor
-- re-read as knots (km/h, m/s); a metric level said as digits one by one before "hundred" is asked
do
  local _, ex = scene({ "CRE CSN512 A320 30.0 114.0 090 FL250 280", "CRE CCA88 B738 31.0 115.0 180 FL200 270" })
  check_eq(ex("CSN512 reduce speed to four hundred kilometres per hour"), "SPD CSN512 216")
  check_eq(ex("CSN512 speed four four zero kilometers per hour"), "SPD CSN512 238")
  check_eq(ex("CCA88 reduce to 390 km/h"), "SPD CCA88 211")
  check_eq(ex("CCA88 speed one two five metres per second"), "SPD CCA88 243")
  asked(ex("CCA88 speed 2000 km/h"), "1080 kt: no speed an airliner flies")
  check_eq(ex("CCA88 reduce speed two five zero knots"), "SPD CCA88 250")
  asked(ex("CSN512 climb to eight six hundred metres"), "digits one by one before hundred: 8600 m or a slip?")
  check_eq(ex("CSN512 climb to eight thousand six hundred metres"), "ALT CSN512 28215")
  check_eq(ex("CSN512 climb to eight six zero zero metres"), "ALT CSN512 28215")
  check_eq(ex("CSN512 climb to eighty six hundred metres"), "ALT CSN512 28215")
end

-- Cycle 40 (d81): a metric level or a flight level said with "standard" ("9800 metres, standard", "on standard
-- pressure"): flown on the standard setting, as every level is; "standard" after feet, or naming something else,
-- is still asked
do
  local _, ex = scene({ "CRE CXA71 B738 25.0 118.0 045 FL250 280" })
  check_eq(ex("CXA71 climb to eight four zero zero metres, standard"), "ALT CXA71 27559")
  check_eq(ex("CXA71 descend and maintain 6600 metres on standard pressure"), "ALT CXA71 21654")
  check_eq(ex("CXA71 climb flight level 310 standard"), "ALT CXA71 FL310")
  asked(ex("CXA71 descend to 4000 feet standard"), "standard after an altitude in feet")
  asked(ex("CXA71 climb to 8400 metres standard rate"), "a standard rate, no altimeter setting")
  check_eq(ex("CXA71 descend to six five hundred metres, correct, six thousand five hundred metres"), "ALT CXA71 21325")
end

-- Cycle 40 (d81): mainland China's airlines by telephony, after a verb too ("delete Lucky Air ...", "where is Shun
-- Feng ..."); an airline said with no aircraft of its number flying is still asked
do
  local _, ex = scene({ "CRE LKE5203 A320 25.0 102.0 090 FL250 280", "CRE CSS3301 B752 23.0 113.0 180 FL200 270",
      "CRE CAO808 B744 31.0 121.0 270 FL300 280", "CRE CCA977 A332 40.0 116.0 000 FL320 290" })
  check_eq(ex("sim op: delete Lucky Air five two zero three"), "DEL LKE5203")
  check_eq(ex("where is Shun Feng three three zero one"), "POS CSS3301")
  check_eq(ex("remove air china cargo eight zero eight"), "DEL CAO808")
  check_eq(ex("Air China 977 climb to 10100 metres"), "ALT CCA977 33136")
  asked(ex("delete Lucky Air five two zero four"), "no Lucky Air 5204 flies")
end

-- Cycle 40 (d81): a crossing's value said with its noun after "at" ("cross FIX at speed 250 knots") is the
-- constraint; so is a plain number of knots after the noun (Cycle 41, d87), one no speed is still asked
do
  local _, ex = scene({ "CRE CES771 A320 31.0 121.0 090 FL250 280", "ADDWPT CES771 52.0 4.0", "DEFWPT DUMIX 31.2 121.8",
      "ADDWPT CES771 DUMIX" })
  check_eq(ex("CES771 cross DUMIX at speed 250 knots"), "AT CES771 DUMIX SPD 250")
  check_eq(ex("CES771 cross DUMIX at speed 250 knots, descend FL200"), "AT CES771 DUMIX SPD 250 ; ALT CES771 FL200")
  check_eq(ex("CES771 cross DUMIX at speed 250"), "AT CES771 DUMIX SPD 250")
  asked(ex("CES771 cross DUMIX at speed 25"), "a plain number after the noun that is no speed")
end

-- Cycle 40 (d81): "cancel your route" deletes the route (DELRTE); a waypoint named with it, a negation, or route
-- restrictions are not this
do
  local _, ex = scene({ "CRE CSC4417 A320 30.5 104.0 090 FL250 280", "DEFWPT BOTAN 30.6 104.5", "ADDWPT CSC4417 BOTAN" })
  check_eq(ex("CSC4417 cancel your route"), "DELRTE CSC4417")
  check_eq(ex("cancel the route of CSC4417"), "DELRTE CSC4417")
  asked(ex("CSC4417 cancel the route via BOTAN"), "a waypoint named: which part?")
  asked(ex("CSC4417 don't cancel your route"), "a negation")
  check(not ex("CSC4417 cancel route restrictions"):find("DELRTE", 1, true), "restrictions lifted, no route deleted")
end

-- Cycle 40 (d82): terse setting notes. A distance and a height paired before the zone's word ("a 4nm / 800ft
-- zone", "4 nm and 800 ft zone", "4 nm by 800 ft PZ") are both the zone's (ZONER and ZONEDH), after other
-- settings too; a bare number or a flight level before it is not
do
  local _, ex = scene({ "CRE SAS77 B738 52.4 4.2 180 FL340 280" })
  check_eq(ex("detection on, reso mvp, 4nm / 800ft zone, 3 min lookahead"),
    "ASAS ON ; RESO MVP ; ZONER 4 ; ZONEDH 800 ; DTLOOK 180")
  check_eq(ex("resolution MVP, 4 nm and 800 ft zone"), "RESO MVP ; ZONER 4 ; ZONEDH 800")
  check_eq(ex("mvp resolution, a 4 nm by 800 ft pz"), "RESO MVP ; ZONER 4 ; ZONEDH 800")
  asked(ex("resolution MVP, FL100 / 4 nm zone"), "a flight level is no half height of the zone")
end

-- Cycle 40 (d82): "real time again" is "back to real time": read from the clock's state, fast time OP, else
-- DTMULT 1 (a held clock stays held); a word that starts the clock with it still starts it
do
  local _, ex = scene({})
  check_eq(ex("real time again please"), "DTMULT 1")
  check_eq(ex("could you run the sim in real time again"), "DTMULT 1")
  check_eq(ex("ff 60; run it in real time again"), "FF 60 ; OP")
  check_eq(ex("resume in real time again"), "OP")
end

-- Cycle 40 (d82): an A320neo is an A320: "the A320" with an A320 and an A20N flying asks which, naming both;
-- "the A320neo" is the neo; "the A320" with only the neo flying is the neo
do
  local _, ex = scene({ "CRE FIN12 A320 60 24 090 FL200 250", "CRE FIN34 A20N 60.3 24.5 270 FL220 260",
    "CRE FIN56 A321 60.6 24.9 180 FL240 270" })
  check(ex("the A320 hdg 170"):match("^ASK .*FIN12.*FIN34") ~= nil, ex("the A320 hdg 170"))
  check_eq(ex("the A320neo hdg 170"), "HDG FIN34 170")
  check_eq(ex("the A321 hdg 170"), "HDG FIN56 170")
  local _, ex2 = scene({ "CRE FIN34 A20N 60.3 24.5 270 FL220 260", "CRE FIN56 A321 60.6 24.9 180 FL240 270" })
  check_eq(ex2("the A320 hdg 170"), "HDG FIN34 170")
end

-- Cycle 40 (d82): an arrow typed before a word that opens an instruction (a value's name, a verb of climb or
-- descent, a turn) separates it, no direct-to: "FIN12 -> hdg 250", "passing FL150 -> spd 260"; before a place's
-- name it is still the direct-to, and before another word it is still asked
do
  local _, ex = scene({ "CRE FIN12 A320 60 24 090 FL200 250" })
  check_eq(ex("FIN12 -> hdg 250"), "HDG FIN12 250")
  check_eq(ex("FIN12 -> desc FL90"), "ALT FIN12 FL90")
  check_eq(ex("FIN12 -> turn left 20"), "HDG FIN12 70 LEFT")
  check_eq(ex("FIN12 passing FL150 -> spd 260"), "ATALT FIN12 FL150 SPD FIN12 260")
  check_eq(ex("FIN12 once slowed to 230 kt -> descend FL120"), "ATSPD FIN12 230 ALT FIN12 FL120")
  asked(ex("FIN12 -> hold"), "an arrow before a word of no instruction is a direct-to, to no place")
end

-- Cycle 40 (d82): a height typed with its unit in feet before the instruction word of a terse note ("FIN12:
-- 9000ft, spd 220") is the level to fly, as a flight level there is; after "below"/"above" it is not
do
  local _, ex = scene({ "CRE FIN12 A320 60 24 090 FL200 250" })
  check_eq(ex("FIN12: 9000ft, spd 220"), "ALT FIN12 9000 ; SPD FIN12 220")
  check_eq(ex("FIN12 7000 ft spd 210"), "ALT FIN12 7000 ; SPD FIN12 210")
  check_eq(ex("FIN12 spd 220, 9000ft"), "SPD FIN12 220 ; ALT FIN12 9000")
  check(not ex("FIN12 below 9000 ft spd 220"):find("ALT FIN12 9000", 1, true), ex("FIN12 below 9000 ft spd 220"))
  asked(ex("FIN12: 9000, spd 220"), "a bare number before the speed is no level")
end

-- Cycle 40 (d82): an arrow between two values after the name of a heading or speed ("hdg 220 -> 250", "spd 280
-- -> 250") is a change from the one to the other: the second is flown
do
  local _, ex = scene({ "CRE FIN12 A320 60 24 220 FL200 280" })
  check_eq(ex("FIN12 hdg 220 -> 250"), "HDG FIN12 250")
  check_eq(ex("FIN12 heading 220->240"), "HDG FIN12 240")
  check_eq(ex("FIN12 spd 280 -> 250"), "SPD FIN12 250")
  asked(ex("FIN12 fl 200 -> 150"), "digits after an arrow with no level's name are no flight level")
end

-- Cycle 40 (d82): a callsign alone with a question mark ("LOT55?") is shown as the callsign alone is (POS);
-- another word beside it is still read or asked
do
  local _, ex = scene({ "CRE LOT55 E195 55.2 24.0 090 FL340 290" })
  check_eq(ex("LOT55?"), "POS LOT55")
  check_eq(ex("lot55 ?"), "POS LOT55")
  asked(ex("LOT55 blue?"), "a word beside the callsign that names nothing")
end

-- Cycle 40 (d82): typed "x" before a fix's ident is "cross", an at sign typed apart is "at": "FIN12 x ALPHA @
-- FL200" is the constraint at the fix; "x" before anything else stays as typed
do
  local _, ex = scene({ "CRE FIN12 A320 60 24 090 FL240 280", "DEFWPT ALPHA 60.1 25", "ADDWPT FIN12 ALPHA" })
  check_eq(ex("FIN12 x ALPHA @ FL200"), "AT FIN12 ALPHA ALT FL200")
  check_eq(ex("FIN12 @ FL200"), "ALT FIN12 FL200")
  check_eq(ex("FIN12 x ALPHA at 250 kt"), "AT FIN12 ALPHA SPD 250")
  asked(ex("FIN12 x alpha"), "a lower-case x before a lower-case name is no crossing")
end

-- Cycle 40 (d83a): a line dictated to a voice assistant. The assistant named after a greeting ("hey squawk",
-- "ok computer") is the line's addressee, never a transponder code that swallows the condition after it; a
-- place spelled letter by letter ("cross s p y at ...") is the ident the route or the navdata holds, else
-- asked, naming the letters, and the instruction it anchors is never sent alone; "real time" said bare is
-- the clock's rate; "for times" is "four times"
do
  local _, ex = scene({ "CRE KLM55 B738 52.3 4.7 090 FL150 280" })
  check_eq(ex("hey squawk KLM55 descend FL100"), "ALT KLM55 FL100")
  check_eq(ex("ok computer, KLM55 turn left heading 250"), "HDG KLM55 250 LEFT")
  check_eq(ex("hey squawk run the simulation at for times real time"), "DTMULT 4")
  check_eq(ex("real time please"), "DTMULT 1")
  check_eq(ex("KLM55 squawk 4721"), "")
  -- a transponder code or a frequency ends before a condition that anchors the instruction said after it
  check_eq(ex("KLM55 squawk 4721 when passing FL120 reduce 250"), "ATALT KLM55 FL120 SPD KLM55 250")
  asked(ex("KLM55 at x q z descend FL100"), "a place spelled in letters no route or navdata holds")
  asked(ex("KLM55 when 20 miles from uh x q z descend FL100"), "a distance from letters nothing read")
  local nav, nex = navscene({ "CRE KLM55 B738 52.3 4.7 090 FL150 280", "ADDWPT KLM55 SPY" },
    "spelled idents read from the route and the navdata")
  if nav then
    check_eq(nex("hey squawk KLM55 when 20 miles from SPY descend FL100"), "ATDIST KLM55 SPY 20 ALT KLM55 FL100")
    check_eq(nex("hey squawk KLM55 at s p y descend FL100"), "AT KLM55 SPY DO ALT KLM55 FL100")
    check_eq(nex("KLM55 cross s p y at FL120"), "AT KLM55 SPY ALT FL120")
    check_eq(nex("KLM55 direct p a m"), nex("KLM55 direct PAM"))
    check_eq(nex("KLM55 squawk 4721 when 20 miles from SPY descend FL100"), "ATDIST KLM55 SPY 20 ALT KLM55 FL100")
    asked(nex("squawk KLM55 at SPY descend FL100"), "'squawk' before the callsign, no greeting: the place kept")
  end
end

-- Cycle 40 (d83a): dictation's spoken punctuation and digits said apart. "comma", "period", "question mark",
-- "new line" dictated are the marks ("a period of" stays a word); two digits apart before "thousand" are one
-- count of thousands; a wind's direction said digit by digit after "to" or "from" is one direction
do
  local _, ex = scene({ "CRE KLM55 B738 52.3 4.7 090 FL150 280", "CRE DLH12 A320 52.5 4.9 270 FL200 280" })
  check_eq(ex("KLM55 descend to 1 2 thousand comma reduce speed to 250 knots period"),
    "ALT KLM55 12000 ; SPD KLM55 250")
  check_eq(ex("where is KLM55 question mark"), "POS KLM55")
  check_eq(ex("KLM55 descend to 1 1 thousand new line DLH12 climb flight level 2 4 0"),
    "ALT KLM55 11000 ; ALT DLH12 FL240")
  check_eq(ex("set the wind at 52 comma 4 to 2 7 0 at 30 knots"), "WIND 52 4 270 30")
  asked(ex("KLM55 descend to 0 1 thousand"), "a count of thousands opening with zero stays apart")
  asked(ex("KLM55 descend 9000 after a period of ten minutes"), "'a period of' is no full stop")
end

-- Cycle 40 (d83a): a speed's digits said in groups after a speed word ("reduce to 2 5 0", "speed 2 40") are
-- one speed of 100 to 399; an instruction of the same aircraft after one tied to a waypoint ("after SPY descend
-- FL180 and slow to 290") is asked (wait for the waypoint too, or now?), never sent now
do
  local _, ex = scene({ "CRE KLM55 B738 52.3 4.7 090 FL150 280" })
  check_eq(ex("KLM55 reduce to 2 5 0"), "SPD KLM55 250")
  check_eq(ex("KLM55 speed 2 40 comma descend 9000"), "SPD KLM55 240 ; ALT KLM55 9000")
  check_eq(ex("KLM55 slow to 1 80 knots"), "SPD KLM55 180")
  asked(ex("KLM55 reduce to 2 5"), "two digits are no speed")
  asked(ex("KLM55 reduce speed 2 5 0 0"), "a digit after the three")
  local nav, nex = navscene({ "CRE KLM55 B738 52.3 4.7 090 FL150 280", "ADDWPT KLM55 SPY" },
    "an instruction after one tied to a waypoint of the route")
  if nav then
    asked(nex("KLM55 after SPY descend FL120 and slow to 2 9 0"), "the speed after the waypoint's instruction")
    check_eq(nex("KLM55 descend FL120 and after SPY slow to 2 9 0"), "ALT KLM55 FL120 ; AT KLM55 SPY DO SPD KLM55 290")
  end
end

-- Cycle 40 (d83a): a decimal said with "point" ("52 point 4", "mach point 7 8", "0 point 5") is the number
-- written, one or two digits after the point
do
  local _, ex = scene({ "CRE KLM55 B738 52.3 4.7 090 FL150 280" })
  check_eq(ex("move KLM55 to 52 point 4 comma 4 point 9"), "MOVE KLM55 52.4 4.9")
  check_eq(ex("KLM55 mach point 7 8"), ex("KLM55 mach .78"))
  check_eq(ex("set time step to 0 point 5 seconds"), "DT 0.5")
  asked(ex("KLM55 mach point 7"), "one digit after 'mach point' is no Mach number")
end

-- Cycle 40 (hzA): a level after "below" or "above" before the instruction word, with no verb of its own, is a
-- condition or a limit, never a clearance: asked ("below FL90 spd 220"); a level with its verb is still flown
do
  local _, ex = scene({ "CRE KLM12 B738 52.3 4.7 090 FL150 280" })
  asked(ex("KLM12 below FL80 spd 210"), "a level after 'below' is no level to fly")
  asked(ex("KLM12 above FL110 reduce speed 260"), "a level after 'above' is no level to fly")
  asked(ex("KLM12 below 7000 ft speed 210"), "a height after 'below' is no level to fly")
  check_eq(ex("KLM12 descend FL80 spd 210"), "ALT KLM12 FL80 ; SPD KLM12 210")
  check_eq(ex("KLM12 reduce speed 210 below FL80"), "ATALT KLM12 FL80 SPD KLM12 210")
end

-- Cycle 40 (hzA): a hold said to an aircraft takes time: an instruction after it with "then", "after that" or
-- "afterwards" waits for the hold squawk does not fly, so it is asked, never sent now
do
  local _, ex = scene({ "CRE KLM55 B738 52.3 4.7 090 FL150 280" })
  asked(ex("KLM55 hold for a period of five minutes then climb FL170"), "after a hold of a period")
  asked(ex("KLM55 hold for twenty minutes, after that turn left heading 040"), "'after that' waits too")
  asked(ex("KLM55 hold for five minutes and then reduce speed 230"), "'and then' waits too")
end

-- Cycle 40 (hzA): a rate whose words name the other way than the level given ("FL300, rate of climb 2500" to an
-- aircraft above FL300; "descend FL120, rate of climb 1500") is asked; a rate the same way is read
do
  local _, ex = scene({ "CRE AFR7312 A320 52.0 4.0 090 FL350 280" })
  asked(ex("AFR7312 FL310, rate of climb 1800"), "a climb rate to a lower level")
  asked(ex("AFR7312 FL390 rate of descent 1500"), "a descent rate to a higher level")
  asked(ex("AFR7312 descend FL310 rate of climb 1800"), "ALT's rate named the other way")
  check_eq(ex("AFR7312 FL310, rate of descent 1800"), "ALT AFR7312 FL310 ; VS AFR7312 -1800")
  check_eq(ex("AFR7312 FL390, rate of climb 1500"), "ALT AFR7312 FL390 ; VS AFR7312 1500")
  check_eq(ex("AFR7312 descend FL310 at 1800 feet per minute"), "ALT AFR7312 FL310 1800")
end

-- Cycle 40 (hzB): a clause between punctuation of two known words or more closed by "off" or "on" ("lateral
-- drift off") that nothing read is asked about by name, never dropped while the rest runs; one word and the
-- switch ("level off"), a switch squawk reads ("lnav off") and a clause with an instruction in it stand
do
  local _, ex = scene({ "CRE QTR7 B77W 52.0 4.0 025 FL200 250" })
  check_eq(ex("QTR7 lateral drift off, fly heading 040"), "ASK I have HDG QTR7 40. What does 'lateral drift off' mean?")
  check_eq(ex("QTR7 turn left heading 300, cabin pressure warning off"),
    "ASK I have HDG QTR7 300 LEFT. What does 'cabin pressure warning off' mean?")
  check_eq(ex("QTR7 descend FL150, level off"), "ALT QTR7 FL150")
  check_eq(ex("QTR7 lnav off, fly heading 040"), "LNAV QTR7 OFF ; HDG QTR7 40")
  check_eq(ex("QTR7 fly heading 040, vnav on"), "HDG QTR7 40 ; VNAV QTR7 ON")
  check_eq(ex("QTR7 turn heading 040, carry on"), "HDG QTR7 40 ; OP")
end

-- Cycle 40 (hzB): an instruction tied to a waypoint of the route that reads as a condition of its own ("I want
-- it at FL250 and heading 200": ATALT ... HDG ...) is asked, never nested in AT ... DO
do
  local nav, nex = navscene({ "CRE AFR1234 A320 52.2 4.2 300 FL250 280", "ADDWPT AFR1234 GIROM" },
    "a condition inside an instruction tied to a waypoint")
  if nav then
    asked(nex("when AFR1234 gets to GIROM I want it at FL250 and heading 200"), "a condition nested in AT ... DO")
    check_eq(nex("when AFR1234 gets to GIROM turn heading 200"), "AT AFR1234 GIROM DO HDG AFR1234 200")
  end
end

-- Cycle 40 (hzC): a destination or origin said for several aircraft ("for KLM12 and EZY45") is set for each
-- one named, never for the first alone
do
  local nav, nex = navscene({ "CRE KLM12 B738 52.0 4.0 090 FL200 250", "CRE EZY45 A320 52.2 4.4 180 FL150 240",
    "CRE TRA6 B738 52.4 4.6 270 FL120 240" }, "a destination for several aircraft")
  if nav then
    check_eq(nex("Make EGLL the destination for KLM12 and EZY45"), "DEST KLM12 EGLL ; DEST EZY45 EGLL")
    check_eq(nex("TRA6, EZY45 and KLM12 origin EHAM"), "ORIG TRA6 EHAM ; ORIG EZY45 EHAM ; ORIG KLM12 EHAM")
    check_eq(nex("KLM12 destination EGLL, EZY45 descend FL100"), "DEST KLM12 EGLL ; ALT EZY45 FL100")
  end
end

-- Cycle 40 (hzC): a time after "in"/"after" before the simulation's speed set ("in 90 seconds, set the simulation
-- speed to 3") waits as any instruction's does: never a fast-forward of that time (the rate itself is asked)
do
  local _, ex = scene({ "CRE KLM12 B738 52.0 4.0 090 FL200 250" })
  asked(ex("In 90 seconds, set the simulation speed to 3"), "a delay before the simulation's speed")
  asked(ex("set the sim speed to 4 after 2 minutes"), "a delay after the simulation's speed")
  check_eq(ex("speed up the simulation for 5 minutes"), "FF 300")
  check_eq(ex("fast forward 300 seconds"), "FF 300")
end

-- Cycle 40 (hzC): VNAV named as a switch beside "follow its route (again)" is one more instruction: the route is
-- flown (LNAV) too; the route followed "vertically" or by its altitudes is VNAV alone
do
  local _, ex = scene({ "DEFWPT HZC1 52.5 4.5", "CRE KLM12 B738 52.0 4.0 090 FL200 250", "ADDWPT KLM12 HZC1" })
  check_eq(ex("KLM12 should follow its route again with VNAV engaged"), "LNAV KLM12 ON ; VNAV KLM12 ON")
  check_eq(ex("KLM12 follow the route again and engage VNAV"), "LNAV KLM12 ON ; VNAV KLM12 ON")
  check_eq(ex("KLM12 should follow its route vertically"), "VNAV KLM12 ON")
  check_eq(ex("KLM12 follow the altitudes of its route, vnav on"), "VNAV KLM12 ON")
end

-- Cycle 40 (hzC): an instruction whose value is named by what it is ("minimum clean speed", "max speed"), no
-- number squawk can give, is asked, never dropped beside a report or another instruction
do
  local _, ex = scene({ "CRE EZY45 A320 52.2 4.4 180 FL150 240" })
  asked(ex("EZY45 for spacing reduce to minimum clean speed, say altitude"), "a speed named by what it is")
  asked(ex("EZY45 reduce to max speed, turn left heading 090"), "a speed named by what it is, beside a heading")
  check_eq(ex("EZY45 reduce to minimum clean speed, 210 knots"), "SPD EZY45 210")
end

-- Cycle 41 (d87): a condition of passing a waypoint opening the clause ("when passing FIX", "on passing FIX",
-- "after leaving FIX", "leave FIX heading 200") starts the instruction said after it there (AT ... DO); a value
-- with no verb after "leave FIX" other than a heading is asked, as is a waypoint off the route
do
  local _, ex = scene({ "DEFWPT DQA 41.2 29.2", "DEFWPT DQB 41.4 29.4", "DEFWPT DQC 41.6 29.6",
    "CRE TKZ31 A321 41.0 29.0 045 FL180 280", "ADDWPT TKZ31 DQA", "ADDWPT TKZ31 DQB" })
  check_eq(ex("TKZ31 leave DQA heading 090"), "AT TKZ31 DQA DO HDG TKZ31 90")
  -- (after "leave FIX" only a heading straight after it waits; "leave FIX, fly heading" may be now: asked)
  asked(ex("TKZ31 leave DQB, fly heading 120"), "a heading after 'leave FIX' and a comma")
  asked(ex("TKZ31 leaving DQB turn right heading 120"), "a turn after 'leaving FIX'")
  check_eq(ex("TKZ31 when passing DQA descend flight level 150"), "AT TKZ31 DQA DO ALT TKZ31 FL150")
  check_eq(ex("TKZ31 on passing DQB reduce speed 240 knots"), "AT TKZ31 DQB DO SPD TKZ31 240")
  check_eq(ex("TKZ31 after leaving DQA climb FL200"), "AT TKZ31 DQA DO ALT TKZ31 FL200")
  asked(ex("TKZ31 leave DQA flight level 150"), "a level with no verb after 'leave FIX'")
  asked(ex("TKZ31 when passing DQC descend FL150"), "a waypoint off the route")
  check_eq(ex("TKZ31 leaving FL170 turn left heading 300"), "ATALT TKZ31 FL170 HDG TKZ31 300 LEFT")
  -- ("passing FIX" and "over"/"overhead FIX" open the clause as "at FIX" does; a verb in -ing after a bare
  -- "passing" is a pilot's report, asked; "abeam FIX" is no passing of it; a level with no verb after "over
  -- FIX" is the constraint there, as after "at")
  check_eq(ex("TKZ31 passing DQB descend FL140"), "AT TKZ31 DQB DO ALT TKZ31 FL140")
  check_eq(ex("TKZ31 overhead DQA turn left heading 330"), "AT TKZ31 DQA DO HDG TKZ31 330 LEFT")
  check_eq(ex("TKZ31 over DQB reduce speed 230"), "AT TKZ31 DQB DO SPD TKZ31 230")
  check_eq(ex("TKZ31 leaving DQB heading 250"), "AT TKZ31 DQB DO HDG TKZ31 250")
  asked(ex("TKZ31 passing DQB descending FL140"), "a pilot's report of passing a waypoint")
  check_eq(ex("TKZ31 over DQB FL140"), "AT TKZ31 DQB ALT FL140")
  asked(ex("TKZ31 abeam DQB descend FL140"), "abeam a waypoint")
  check_eq(ex("TKZ31 after overflying DQA climb FL220"), "AT TKZ31 DQA DO ALT TKZ31 FL220")
  check_eq(ex("TKZ31 on reaching DQB reduce speed 220"), "AT TKZ31 DQB DO SPD TKZ31 220")
  check_eq(ex("TKZ31 once past DQA turn right heading 070"), "AT TKZ31 DQA DO HDG TKZ31 70 RIGHT")
  asked(ex("TKZ31 when reaching DQB FL140"), "a level with no verb after 'when reaching FIX'")
end

-- Cycle 41 (d87): a crossing with "at" left out and the speed said with its noun ("cross FIX speed 250",
-- "cross FIX FL150 speed 250") is the constraint there; a number after "speed" that is no speed is asked, never
-- a level; a speed after "cross FIX at FL150" with no verb of its own is asked (there or now)
do
  local _, ex = scene({ "DEFWPT DQA 41.2 29.2", "CRE TKZ31 A321 41.0 29.0 045 FL180 280", "ADDWPT TKZ31 DQA" })
  check_eq(ex("TKZ31 cross DQA speed 260"), "AT TKZ31 DQA SPD 260")
  check_eq(ex("TKZ31 cross DQA speed two four zero knots"), "AT TKZ31 DQA SPD 240")
  check_eq(ex("TKZ31 cross DQA flight level 160 speed 240"), "AT TKZ31 DQA ALT FL160 ; AT TKZ31 DQA SPD 240")
  asked(ex("TKZ31 cross DQA speed 24"), "a number after 'speed' that is no speed")
  asked(ex("TKZ31 cross DQA at speed 3000"), "a number after 'speed' that is no speed, never a level")
  asked(ex("TKZ31 cross DQA at FL160 speed 240"), "a speed after the crossing's level, there or now")
  asked(ex("TKZ31 cross DQA FL160, speed 240"), "a speed after a comma")
  -- (a bound after the value, "or above", "or less": the exact constraint is confirmed first)
  check(ex("TKZ31 cross DQA flight level 160 or above"):find("exactly FL160", 1, true) ~= nil, "a level's bound")
  check(ex("TKZ31 cross DQA speed 240 knots or less"):find("exactly 240 knots", 1, true) ~= nil, "a speed's bound")
end

-- Cycle 41 (d87): "proceed to" a level is a climb or descent to it; "proceed to" a waypoint stays the direct-to
do
  local _, ex = scene({ "DEFWPT DQA 41.2 29.2", "DEFWPT DQB 41.4 29.4", "CRE TKZ31 A321 41.0 29.0 045 FL180 280",
    "ADDWPT TKZ31 DQA", "ADDWPT TKZ31 DQB" })
  check_eq(ex("TKZ31 proceed to flight level 210"), "ALT TKZ31 FL210")
  check_eq(ex("TKZ31 after DQA proceed to FL140"), "AT TKZ31 DQA DO ALT TKZ31 FL140")
  check_eq(ex("TKZ31 proceed to DQB"), "DIRECT TKZ31 DQB")
  asked(ex("TKZ31 proceed to"), "nothing proceeded to")
end

-- Cycle 41 (d87): Fokker's airliners (F28, F50, F70, F100) are types by their maker's name ("the Fokker",
-- "the Fokker 100"); a Fokker type none flies is asked
do
  local _, ex = scene({ "CRE KFK20 F100 35.6 50.9 090 FL090 240", "CRE IRZ40 A320 35.1 51.0 030 FL200 290" })
  check_eq(ex("the Fokker descend flight level 70"), "ALT KFK20 FL70")
  check_eq(ex("the Fokker 100 turn left heading 200"), "HDG KFK20 200 LEFT")
  asked(ex("the Fokker 70 descend FL80"), "no Fokker 70 flies")
end

-- Cycle 41 (d87): a question of where an aircraft is, said before a callsign whose airline squawk does not
-- know by name ("where is Serene eight four two"), is its position (POS); "give me your speed" asks for the
-- aircraft's state; a callsign no aircraft has is still asked
do
  local _, ex = scene({ "CRE SEP842 B738 31.9 74.7 230 FL170 280", "CRE PIA305 A320 32.0 74.0 170 FL130 260" })
  check_eq(ex("where is Serene eight four two"), "POS SEP842")
  check_eq(ex("show me Serene eight four two"), "POS SEP842")
  check_eq(ex("tell me where Serene eight four two is"), "POS SEP842")
  check_eq(ex("SEP842 give me your speed"), "POS SEP842")
  check_eq(ex("PIA305 give me your present level and heading"), "POS PIA305")
  check_eq(ex("SEP842 give me speed 250"), "SPD SEP842 250")
  asked(ex("where is Serene four four two"), "no such flight number flies")
end

-- Cycle 41 (resid2): a verb after "is to", "should" or "have X" ("At FIX, X is to slow down to 220 knots", "should
-- begin its descent") and a condition "once past FIX" make the instruction start at the waypoint (AT ... DO);
-- "is slow" said of an aircraft stays a description, and a value with no verb stays the constraint
do
  local _, ex = scene({ "DEFWPT RSA 52.5 4.5", "DEFWPT RSB 52.8 4.8", "CRE KLM12 B738 52.0 4.0 090 FL200 250",
    "ADDWPT KLM12 RSA", "ADDWPT KLM12 RSB" })
  check_eq(ex("At RSA, KLM12 is to slow down to 230 knots."), "AT KLM12 RSA DO SPD KLM12 230")
  check_eq(ex("KLM12 is to slow to 230 knots"), "SPD KLM12 230")
  check_eq(ex("At RSB KLM12 should commence its descent to FL120"), "AT KLM12 RSB DO ALT KLM12 FL120")
  check_eq(ex("KLM12 begin descent to FL150"), "ALT KLM12 FL150")
  check_eq(ex("Once past RSA, have KLM12 slow to 210 knots"), "AT KLM12 RSA DO SPD KLM12 210")
  check_eq(ex("KLM12 when past RSB descend FL100"), "AT KLM12 RSB DO ALT KLM12 FL100")
  check_eq(ex("at RSA KLM12 FL180"), "AT KLM12 RSA ALT FL180")
  asked(ex("KLM12 is a bit slow"), "a description, no instruction")
  asked(ex("Once past RSA, KLM12 FL180"), "a value with no verb after 'once past'")
end

-- Cycle 41 (resid2): a confirmation question followed by the instruction itself ("confirm heading 180? Fly
-- heading 180") reads the instruction; "confirm level 290? Maintain" keeps the level asked about; the question
-- alone, or followed by what is no instruction with its value, is still asked
do
  local _, ex = scene({ "CRE KLM12 B738 52.0 4.0 090 FL290 250", "CRE AFR77 A320 52.2 4.2 180 FL250 260" })
  check_eq(ex("KLM12, confirm heading 090? Turn right heading 120"), "HDG KLM12 120 RIGHT")
  check_eq(ex("AFR77 confirm you are descending to FL230? Descend FL230"), "ALT AFR77 FL230")
  check_eq(ex("KLM12 confirm level 290? Maintain."), "ALT KLM12 FL290")
  asked(ex("KLM12, confirm level 290?"), "the question alone")
  asked(ex("KLM12, confirm level 290? Maintain speed"), "a bare 'maintain' with more after it")
  asked(ex("AFR77 confirm speed 260? Maintain"), "'maintain' after a speed asked about")
end

-- Cycle 41 (resid2): traffic information told after an instruction by the way the other aircraft flies ("traffic
-- opposite direction FL340", "traffic crossing left to right, a Volotea at 350") instructs nobody: its level is
-- no value; an instruction after it with its own verb is read
do
  local _, ex = scene({ "CRE KLM12 B738 52.0 4.0 090 FL290 250" })
  check_eq(ex("KLM12 descend flight level two seven zero, traffic opposite direction two six zero"), "ALT KLM12 FL270")
  check_eq(ex("KLM12 maintain FL290, traffic converging from the right, an easyJet at three one zero"),
    "ALT KLM12 FL290")
  check_eq(ex("KLM12 descend FL270, traffic crossing at FL260, turn left heading 060"),
    "ALT KLM12 FL270 ; HDG KLM12 60 LEFT")
  asked(ex("KLM12 descend FL270 and 260 for the traffic"), "a level with no verb beside traffic")
end

-- Cycle 41 (resid2): an aircraft described by "the", its airline and its type ("the Emirates A380", "the Jetstar
-- A320") is the one aircraft of that airline flying of that type; two of them, or none, are asked
do
  local _, ex = scene({ "CRE EZY45 A320 52.0 4.0 090 FL290 250", "CRE EZY46 A321 52.2 4.2 180 FL250 260",
    "CRE EZY47 A321 52.4 4.4 270 FL230 260", "CRE DLH4 A388 52.6 4.6 000 FL380 290" })
  check_eq(ex("The easyJet A320 should descend to FL250."), "ALT EZY45 FL250")
  check_eq(ex("the Lufthansa A380 is to climb to FL400"), "ALT DLH4 FL400")
  asked(ex("the easyJet A321 descend FL200"), "two of the airline flying of that type")
  asked(ex("the easyJet 777 descend FL200"), "none of the airline flying of that type")
end

-- Cycle 41 (resid2): an airline said alone as an addressee ("Ryanair descend ..."), whose one aircraft flying the
-- request also names by its full callsign, is a callsign cut short: asked, never that aircraft; named by "the"
-- it stays the aircraft described
do
  local _, ex = scene({ "CRE RYR77 B738 52.0 4.0 090 FL290 250", "CRE KLM12 B738 52.2 4.2 180 FL250 260" })
  asked(ex("Ryanair climb to FL310 and RYR77 speed 240"), "the airline alone beside its aircraft's callsign")
  asked(ex("KLM12 turn left heading 200, RYR77 speed 240, Ryanair descend FL250"), "the same, said last")
  check_eq(ex("Ryanair climb to FL310 and KLM12 speed 240"), "ALT RYR77 FL310 ; SPD KLM12 240")
end

-- Cycle 41 (resid2): "say distance to FIX" asks the aircraft's position (POS), the place part of the question;
-- "accelerate the time four times" is the clock's rate (DTMULT), an aircraft's acceleration stays its speed
do
  local _, ex = scene({ "DEFWPT RSC 52.5 4.5", "CRE KLM12 B738 52.0 4.0 090 FL290 250" })
  check_eq(ex("KLM12, say distance to RSC"), "POS KLM12")
  check_eq(ex("KLM12 report your distance from RSC, then climb FL310"), "POS KLM12 ; ALT KLM12 FL310")
  check_eq(ex("please accelerate the simulation three times"), "DTMULT 3")
  check_eq(ex("KLM12 accelerate to 280 knots"), "SPD KLM12 280")
  asked(ex("accelerate the time"), "a rate not said")
end

-- Cycle 41 (resid2): after a creation that holds its level, speed or heading, a verb of its own that sets that value
-- again ("..., and instruct it to climb to FL280") is an instruction to the new aircraft; a creation without
-- that value still takes it
do
  local _, ex = scene({ "DEFWPT RSD 52.5 4.5" })
  check_eq(ex("Create KLM88 (B738) at RSD, heading 090, 4000 feet, 200 knots, and instruct it to climb to FL150."),
    "CRE KLM88 B738 RSD 90 4000 200 ; ALT KLM88 FL150")
  check_eq(ex("create KLM88 B738 at RSD heading 090 FL100 250 knots and have it turn right heading 120"),
    "CRE KLM88 B738 RSD 90 FL100 250 ; HDG KLM88 120 RIGHT")
  check_eq(ex("create KLM88 B738 at RSD heading 090 250 knots and climb FL120"), "CRE KLM88 B738 RSD 90 FL120 250")
end

-- Cycle 41 (resid2): "over FIX" opening a clause reads as "at FIX" (a verb: the instruction there, AT ... DO; a
-- value with no verb: the constraint there); "after FIX speed 250 knots", a value with its noun after the
-- waypoint, is the instruction there (no constraint can be met once it is passed); a bare level after it is asked
do
  local _, ex = scene({ "DEFWPT RSE 52.5 4.5", "CRE KLM12 B738 52.0 4.0 090 FL290 250", "ADDWPT KLM12 RSE" })
  check_eq(ex("KLM12 over RSE reduce speed two three zero"), "AT KLM12 RSE DO SPD KLM12 230")
  check_eq(ex("KLM12 over RSE FL200"), "AT KLM12 RSE ALT FL200")
  check_eq(ex("KLM12, after RSE speed two one zero knots"), "AT KLM12 RSE DO SPD KLM12 210")
  check_eq(ex("KLM12 after RSE descend FL180"), "AT KLM12 RSE DO ALT KLM12 FL180")
  asked(ex("KLM12 after RSE FL180"), "a bare level after the waypoint")
end

-- Cycle 41 (resid2): a value's three digits said one by one and transcribed as numerals apart ("heading 2 7 0",
-- "flight level 1 9 0", "2 niner zero") are one value, as the same digits said in words; a lone digit, or one
-- that punctuation parts, stays as it was
do
  local _, ex = scene({ "CRE UAL1298 B738 52.0 4.0 090 FL150 250", "CRE KLM12 B738 52.2 4.2 180 FL250 260" })
  check_eq(ex("united 1298 turn left heading 2 7 0"), "HDG UAL1298 270 LEFT")
  check_eq(ex("KLM12 climb flight level 2 9 0 comma speed 2 8 zero"), "ALT KLM12 FL290 ; SPD KLM12 280")
  check_eq(ex("KLM12 fly heading 1 niner 0"), "HDG KLM12 190")
  asked(ex("KLM12 fly heading 2"), "a lone digit for a heading")
  asked(ex("KLM12 turn left heading 2, 7 0"), "digits that a comma parts")
end

-- Cycle 41 (resid2): "give the position of X" asks for X's position (POS), a place's too; a crossing's value said
-- straight after the waypoint with its bound ("cross RSF FL120 or below") is the bounded constraint, confirmed
-- before it is set exactly, as "cross RSF at FL120 or below" is
do
  local s, ex = scene({ "DEFWPT RSF 52.5 4.5", "CRE KLM12 B738 52.0 4.0 090 FL290 250", "ADDWPT KLM12 RSF" })
  check_eq(ex("Give the position of KLM12."), "POS KLM12")
  check_eq(ex("give the position of RSF"), "POS RSF")
  local r = graph.translate("KLM12 cross RSF FL120 or below", { sim = s, mode = "offline" })
  check(r.ask ~= nil and r.ask:find("exactly FL120", 1, true) ~= nil, said(r))
  check_eq(ex("KLM12 cross RSF FL120"), "AT KLM12 RSF ALT FL120")
end

-- Cycle 41 (d88a): a time of day in a clause of record or comparison after an instruction ("as the controller did
-- at 09:14:30", "as logged at ...", "..., as recorded") schedules nothing: after a word of record in an aside that
-- holds nothing else it is set aside, else asked about; a time said as when to act still schedules
do
  local _, ex = scene({ "DEFWPT DGA1 52.5 4.5", "CRE KLM12 B738 52.0 4.0 090 FL200 250", "CRE EZY45 A320 52.2 4.4 180 FL150 240" })
  check_eq(ex("KLM12 should be told to climb to FL240, as the trainee did at 09:14:30"), "ALT KLM12 FL240")
  check_eq(ex("Reduce EZY45 to 220 knots, as logged at 11:02:10."), "SPD EZY45 220")
  asked(ex("KLM12 climb FL240, as the trainee will do in 2 minutes"), "a time to come in the remark")
  asked(ex("KLM12 climb FL240, which is at 09:14:30"), "a time in a remark with no word of record")
  asked(ex("KLM12 climb FL240, as the trainee did at 09:14:30 at 250 knots"), "a value beside the time of record")
  asked(ex("As recorded at 11:02:10, EZY45 reduce speed to 220 knots"), "a time of the record before the instruction")
  asked(ex("KLM12 climb FL240 at 09:14:30, as recorded"), "a time followed by a remark of record")
  asked(ex("Put EZY45 back at FL150, which was its level at 10:00:00"), "a time in a clause of record")
  check_eq(ex("KLM12 climb FL240 at 09:14:30"), "SCHEDULE 09:14:30 ALT KLM12 FL240")
  check_eq(ex("at 09:14:30 EZY45 reduce speed to 220 knots"), "SCHEDULE 09:14:30 SPD EZY45 220")
end

-- Cycle 41 (d88a): a relative clause telling what was done before ("from the point at which it was halted", "where it
-- was paused") instructs nothing: its verb is no second instruction, nor its "at" a rate; one holding a value or
-- another instruction word is asked
do
  local _, ex = scene({ "CRE KLM12 B738 52.0 4.0 090 FL200 250" })
  check_eq(ex("Resume the simulation from where it was paused"), "OP")
  check_eq(ex("Resume the exercise from the moment at which it was frozen"), "OP")
  check_eq(ex("resume the simulation at 3x"), "OP ; DTMULT 3")
  asked(ex("Resume the simulation from the point at which it was paused at 01:00:00"), "a value in the past clause")
  asked(ex("Turn KLM12 left heading 090, which was the heading it flew when it was cleared to descend."),
    "an instruction word in the past clause")
end

-- Cycle 41 (d88a): a remark after a complete instruction opening with "as", "which" or "according" (", as the
-- recording shows", ", which is what the supervisor wanted") is set aside when it holds no value, place, aircraft or
-- instruction word; one holding a value or an aircraft is asked about
do
  local _, ex = scene({ "CRE KLM12 B738 52.0 4.0 090 FL200 250", "CRE EZY45 A320 52.2 4.4 180 FL150 240" })
  check_eq(ex("Climb KLM12 to FL260, as the recording shows."), "ALT KLM12 FL260")
  check_eq(ex("Turn EZY45 right heading 200, which is what the supervisor would have preferred."), "HDG EZY45 200 RIGHT")
  check_eq(ex("Set the protected zone radius to 4 nautical miles, as the STCA of that centre would have used."), "ZONER 4")
  asked(ex("Climb KLM12 to FL260, which matches the climb of the other one."), "an aircraft meant in the remark")
  asked(ex("Climb KLM12 to FL260, as the recording shows, and reduce speed."), "an instruction after the remark")
end

-- Cycle 41 (d88a): a clearance quoted whole in double quotes that the words outside give again ("replay it", "must now be
-- given", "should be entered") is the request, for the aircraft named outside when it names none; an outside aircraft
-- other than the quote's, a value, a place, a condition, a negation or an instruction outside keeps the whole read
-- (asked)
do
  local _, ex = scene({ "DEFWPT DGA1 52.5 4.5", "CRE KLM12 B738 52.0 4.0 090 FL200 250",
    "CRE EZY45 A320 52.2 4.4 180 FL150 240" })
  check_eq(ex('The tape has "KLM12, descend flight level one six zero"; replay it.'), "ALT KLM12 FL160")
  check_eq(ex('The instruction given to EZY45 at 10:05:00, "turn left heading one two zero", should now be entered.'),
    "HDG EZY45 120 LEFT")
  check_eq(ex('Her next call, "KLM12, reduce speed two two zero knots, climb flight level two one zero", must now be given.'),
    "SPD KLM12 220 ; ALT KLM12 FL210")
  asked(ex('The call to EZY45 was "KLM12, descend flight level one six zero"; replay it.'), "two aircraft")
  asked(ex('The tape has "KLM12, descend flight level one six zero", but replay it with 150.'), "a change outside")
  asked(ex('The tape has "descend flight level one six zero"; replay it and pause the simulation.'),
    "an instruction outside")
  asked(ex('The tape has "KLM12, descend flight level one six zero" over DGA1; replay it.'), "a place outside")
  asked(ex('The tape has "KLM12, descend flight level one six zero" once level; replay it.'), "a condition outside")
  check_eq(ex('echo "KLM12 descend FL160" to the log'), 'ECHO "KLM12 descend FL160" to the log')
end

-- Cycle 41 (d88b): a report's narration of a clearance to replay ("X was subsequently given a speed
-- reduction to 250 knots", "the Lufthansa was then instructed to descend"), its words of the reconstruction
-- ("an additional aircraft"), and Portugalia (PGA) by its telephony
do
  local _, ex = scene({ "CRE IBE7721 A320 40.9 -3.5 190 FL150 280", "CRE DLH604 A321 41.2 -3.1 100 FL200 290",
    "CRE PGA2044 E195 41.3 -8.2 270 9000 260" })
  check_eq(ex("IBE7721 was subsequently given a speed reduction to 230 knots."), "SPD IBE7721 230")
  check_eq(ex("The Lufthansa was thereafter instructed to climb to flight level 240."), "ALT DLH604 FL240")
  check_eq(ex("Lufthansa 604 was then given a climb to FL220; please enter that."), "ALT DLH604 FL220")
  check_eq(ex("Remove Portugalia 2044."), "DEL PGA2044")
  check_eq(ex("Create an additional aircraft, IBE118, type A319, at 40.5 north 3.2 west, heading 045, FL090, 220 knots."),
    "CRE IBE118 A319 40.5 -3.2 45 FL90 220")
  -- still asked: narration with no value given, and a word of the report that is not narration
  asked(ex("IBE7721 was subsequently given a speed reduction."), "a reduction with no speed")
  asked(ex("DLH604 was then given a descent to FL120 by mistake, contrary to procedure."), "a remark beside it")
end

-- Cycle 41 (d88b): a report requested as what is needed or wanted ("I need the position of X", "we want the
-- level and speed of X"), and where an aircraft is, asked to be indicated
do
  local _, ex = scene({ "CRE TAP2210 A320 38.5 -9.1 350 FL080 250", "CRE EZY31K A320 41.0 -3.0 100 FL200 280" })
  check_eq(ex("I need the position of TAP2210."), "POS TAP2210")
  check_eq(ex("We want the level and speed of EZY31K, please."), "POS EZY31K")
  check_eq(ex("Please indicate where EZY31K is."), "POS EZY31K")
  -- still asked: something to be done with the state, not a report of it
  asked(ex("I need the position of TAP2210 changed"), "a state wanted changed")
end

-- Cycle 41 (d88b): a creation said as a report writer says it: the CRJ1000 by name, a registration named
-- ("registration ECXYZ"), the callsign said by its telephony and then written ("Binter 406, call sign
-- IBB406"), and "we begin (the reconstruction) with" a new aircraft and its type
do
  local _, ex = scene({ "CRE IBE7721 A320 40.9 -3.5 190 FL150 280" })
  check_eq(ex("Create an Air Nostrum CRJ1000, callsign ANE301, at 40.1 north 3.2 west, heading 300, FL110, 250 knots."),
    "CRE ANE301 CRJX 40.1 -3.2 300 FL110 250")
  check_eq(ex("Create a Cessna 152, registration ECXYZ, at 38.6 north 9.1 west, heading 090, 3000 feet, 90 knots."),
    "CRE ECXYZ C152 38.6 -9.1 90 3000 90")
  check_eq(ex("Create Binter 406, call sign IBB406, an ATR 72-600, at 41.5 north, 8.4 west, heading 200, FL120, 230 knots."),
    "CRE IBB406 AT76 41.5 -8.4 200 FL120 230")
  check_eq(ex("We begin the reconstruction with IBE905, an Airbus A321, at 40.8 north 3.7 west, heading 010, FL130, 270 knots."),
    "CRE IBE905 A321 40.8 -3.7 10 FL130 270")
  -- still asked: the telephony and the written callsign disagree (which one is meant)
  asked(ex("Create Binter 406, call sign IBB460, an ATR 72-600, at 41.5 north, 8.4 west, heading 200, FL120, 230 knots."),
    "a spoken and a written callsign that differ")
end

-- Cycle 41 (d88b): trails asked for as something added ("add trail lines so the tracks can be compared") are
-- shown; a request that says neither shown nor hidden is still asked
do
  local _, ex = scene({ "CRE IBE7721 A320 40.9 -3.5 190 FL150 280" })
  check_eq(ex("Add trail lines so that the two tracks can be compared later."), "TRAIL ON")
  check_eq(ex("add trails every 20 seconds"), "TRAIL ON 20")
  check_eq(ex("remove the trails"), "TRAIL OFF")
  asked(ex("clear trails"), "trails neither shown nor hidden")
end

-- Cycle 41 (d88b): an obligation a report states ("X is required to cross CNR at FL120", "X is obliged to
-- turn left heading 200") is the instruction, as "X is to ..." is; "is required" with nothing to do is asked
do
  local _, ex = scene({ "DEFWPT DBB1 40.5 -3.5", "CRE IBE7721 A320 40.9 -3.5 190 FL150 280", "ADDWPT IBE7721 DBB1" })
  check_eq(ex("IBE7721 is required to cross DBB1 at flight level 130."), "AT IBE7721 DBB1 ALT FL130")
  check_eq(ex("IBE7721 is obliged to turn left heading 200."), "HDG IBE7721 200 LEFT")
  asked(ex("IBE7721 is required"), "an obligation with nothing to do")
  asked(ex("IBE7721 is expected at FL200"), "an expectation, no obligation")
end

-- Cycle 42 (g89a): a type or maker word used as the callsign with no registration ("Bonanza, climb ...",
-- "Skylane turn left ...") is asked, as an airline said without its flight number, with one aircraft of the
-- type flying too; "the Bonanza" described stays read when exactly one fits
do
  local _, ex = scene({ "CRE N47BZ BE35 40.1 -105.1 090 6500 140", "CRE N918SL C182 40.3 -105.3 180 5500 130",
    "CRE UAL415 A320 40.5 -105.5 270 FL150 280" })
  check_eq(ex("Bonanza, climb and maintain eight thousand"),
    "ASK Which aircraft is 'Bonanza'? Please give its callsign (or its registration's last three characters after its type).")
  asked(ex("Skylane turn left heading 200"), "a nickname opening the request, no registration")
  asked(ex("Cessna, reduce speed 110"), "a maker opening the request, no registration")
  check_eq(ex("the Bonanza, climb and maintain eight thousand"), "ALT N47BZ 8000")
  check_eq(ex("where is the Skylane"), "POS N918SL")
end

-- Cycle 42 (g89a): FAA abbreviated civil callsigns: a prefix (November or N, or the aircraft's maker, model or
-- nickname: "Bonanza", "Cessna", "Skylane", "King Air") and the last three characters of a US registration or
-- more, in digits, letters or phonetics, or the whole registration, name the one aircraft whose registration
-- ends so when the prefix fits its type; two that end so, a prefix that does not fit, or a bare suffix are asked
do
  local _, ex = scene({ "CRE N47BZ BE35 40.1 -105.1 090 6500 140", "CRE N918SL C182 40.3 -105.3 180 5500 130",
    "CRE N218SL C172 40.4 -105.2 180 4500 110", "CRE N64KA BE20 40.6 -105.6 200 9500 210",
    "CRE UAL415 A320 40.5 -105.5 270 FL150 280" })
  check_eq(ex("Bonanza 7BZ, turn right heading 140"), "HDG N47BZ 140 RIGHT")
  check_eq(ex("Bonanza seven bravo zulu descend and maintain five thousand"), "ALT N47BZ 5000")
  check_eq(ex("November seven bravo zulu, reduce speed 120"), "SPD N47BZ 120")
  check_eq(ex("Skylane 918SL climb 7500"), "ALT N918SL 7500")
  check_eq(ex("King Air four kilo alpha, say altitude"), "POS N64KA")
  check_eq(ex("King Air 64KA descend 8000"), "ALT N64KA 8000")
  -- the whole registration after its type, said or typed
  check_eq(ex("Bonanza November four seven bravo zulu, climb 8500"), "ALT N47BZ 8500")
  check_eq(ex("Skylane N918SL turn left heading 090"), "HDG N918SL 90 LEFT")
  -- still asked: two registrations end with "8SL" (both Cessnas; one a Skylane); a type word that does not fit;
  -- a bare suffix
  check_eq(ex("Cessna eight sierra lima climb 6000"),
    "ASK Which aircraft is 'Cessna eight sierra lima': N918SL or N218SL? Please give its callsign.")
  asked(ex("Skylane 8SL climb 6000"), "two registrations end with 8SL, one of them a Skylane")
  asked(ex("November eight sierra lima, climb 6000"), "two US registrations end with 8SL")
  asked(ex("Bonanza 4KA climb 10000"), "a Bonanza prefix before a King Air's letters")
  check_eq(ex("Piper 7BZ climb 8000"), "ASK Which aircraft is 'Piper 7BZ'? N47BZ ends with 7BZ but is a BE35. "
    .. "Please give its callsign.")
  asked(ex("seven bravo zulu, turn right heading 140"), "a bare suffix")
end

-- Cycle 42 (g89b): "let it run" / "let the sim run" said as a clause of its own, with a rate after it, starts the
-- clock (OP) and sets the rate after it (OP sets DTMULT 1); a rate said as the run's manner ("let it run at 3x")
-- or of the simulation with no "let ... run" stays the rate alone
do
  local _, ex = scene({ "CRE N77QP C172 33.6 -111.9 090 4500 100" })
  check_eq(ex("let the simulation run, times six"), "OP ; DTMULT 6")
  check_eq(ex("let it run. x3"), "OP ; DTMULT 3")
  check_eq(ex("let it run at 3x"), "DTMULT 3")
  check_eq(ex("let it run"), "OP")
  check_eq(ex("run the simulation at times six"), "DTMULT 6")
  asked(ex("let the simulation run, much faster"), "a rate with no factor")
end

-- Cycle 42 (g89b): "cross the NAME VOR at ...": a navaid said by its name and its kind after "cross" is the
-- constraint's waypoint (the kind, read as an ident of its own, names no other place); a kind that no navaid
-- of that name bears is asked
do
  local _, ex = navscene({ "CRE N4471T PA28 33.3 -111.6 270 5500 110", "ADDWPT N4471T PXR" },
    "crossing a navaid said with its kind")
  if ex then
    check_eq(ex("N4471T, cross the Phoenix VORTAC at four thousand five hundred"), "AT N4471T PXR ALT 4500")
    check_eq(ex("N4471T cross Phoenix VOR at 100 knots"), "AT N4471T PXR SPD 100")
    asked(ex("N4471T cross the Phoenix NDB at 4500"), "no NDB of that name")
  end
end

-- Cycle 42 (g89b): "maintain VFR at 5500" names the altitude to fly (ALT); a level that VFR limits, "at or
-- below", "on top", stays asked
do
  local _, ex = scene({ "CRE N4471T PA28 33.3 -111.6 270 5500 110", "DEFWPT PRAC1 33.4 -111.7" })
  check_eq(ex("N4471T maintain VFR at three thousand five hundred"), "ALT N4471T 3500")
  check_eq(ex("N4471T proceed direct PRAC1, maintain VFR at 6500"), "ADDWPT N4471T PRAC1 ; DIRECT N4471T PRAC1 ; ALT N4471T 6500")
  asked(ex("N4471T maintain VFR at or above 4500"), "a VFR limit, no altitude")
  asked(ex("N4471T maintain VFR"), "VFR alone")
end

-- Cycle 42 (g89b): "the separation bubble", "the safety bubble" is the protected zone (ZONER by its radius);
-- a bubble said alone names no setting and is asked
do
  local _, ex = scene({ "CRE N4471T PA28 33.3 -111.6 270 5500 110" })
  check_eq(ex("set the separation bubble to 4 nm"), "ZONER 4")
  check_eq(ex("make the safety bubble radius 2.5 nautical miles"), "ZONER 2.5")
  asked(ex("make the bubble 4 nm"), "a bubble that is no separation's")
end

-- Cycle 42 (g89b): "after/at/over FIX direct WPT": a request that opens with a waypoint of the route and gives a
-- direct-to to the next waypoint of the route after it starts the direct-to there (AT acid FIX DO DIRECT ...); a
-- place off the route, a shortcut past waypoints of the route (which are left out?) and an instruction said
-- after the direct-to are asked
do
  local _, ex = scene({ "DEFWPT PRAC1 33.4 -111.7", "DEFWPT PRAC2 33.5 -111.8", "DEFWPT PRAC3 33.6 -111.6",
    "DEFWPT PRAC4 33.7 -111.9", "CRE N4471T PA28 33.3 -111.6 270 5500 110", "ADDWPT N4471T PRAC1",
    "ADDWPT N4471T PRAC2", "ADDWPT N4471T PRAC4" })
  check_eq(ex("N4471T, after PRAC1 proceed direct PRAC2"), "AT N4471T PRAC1 DO DIRECT N4471T PRAC2")
  check_eq(ex("N4471T over PRAC1, direct PRAC2 please"), "AT N4471T PRAC1 DO DIRECT N4471T PRAC2")
  asked(ex("N4471T after PRAC3 direct PRAC2"), "a waypoint off the route")
  asked(ex("N4471T after PRAC1 direct PRAC4"), "a shortcut past PRAC2")
  asked(ex("N4471T after PRAC1, direct PRAC2, climb to 6500"), "whether the climb is now or there")
end

-- Cycle 42 (g89b): Burbank is named by its city where the navdata names its airport after a person (KBUR,
-- BOB HOPE); Los Angeles, a city of several large airports, stays asked
do
  local _, ex = navscene({ "CRE N4471T C172 34.1 -118.5 090 3500 100" }, "Burbank by its city")
  if ex then
    check_eq(ex("N4471T, destination Burbank"), "DEST N4471T KBUR")
    asked(ex("N4471T, your destination is Los Angeles"), "a city of several large airports")
  end
end

-- Cycle 42 (g89b): random traffic "at 4500": after the count, a bare number of whole hundreds after "at" is the
-- altitude in feet, as in a creation; a bare number with no "at", or no altitude's size, is asked
do
  local _, ex = scene({})
  check_eq(ex("put in six random Cessna 172s at 3500 and 95 knots"), "MCRE 6 C172 3500 95")
  asked(ex("put in six random Cessna 172s, 3500"), "a bare number, no 'at'")
  asked(ex("put in six random Cessna 172s at 350"), "no altitude's size")
end

-- Cycle 42 (g89b): a vertical speed said unsigned after an altitude in feet ("descend to 2500, vertical speed
-- 500") takes the way to that altitude, as after a flight level; said alone it is the rate as given
do
  local _, ex = scene({ "CRE N4471T C172 33.3 -111.6 270 5500 110" })
  check_eq(ex("N4471T descend to three thousand, vertical speed 600"), "ALT N4471T 3000 ; VS N4471T -600")
  check_eq(ex("N4471T climb to 7500, vertical speed 400"), "ALT N4471T 7500 ; VS N4471T 400")
  check_eq(ex("N4471T maintain 4000, vertical speed 700"), "ALT N4471T 4000 ; VS N4471T -700")
  asked(ex("N4471T maintain 4000, rate of climb 700"), "a climb rate toward a lower altitude")
end

-- Cycle 42 (g89b): "hold your altitude", "maintain present altitude" said to several aircraft: each keeps its
-- own current level; a verb of keeping with no "your" or "present" ("hold altitude") is still asked
do
  local _, ex = scene({ "CRE N4471T C172 33.3 -111.6 270 5500 110", "CRE N9920K SR22 33.5 -111.8 090 8500 150" })
  check_eq(ex("N4471T and N9920K, hold your altitude"), "ALT N4471T 5500 ; ALT N9920K 8500")
  check_eq(ex("N9920K keep your altitude"), "ALT N9920K 8500")
  check_eq(ex("N4471T, N9920K, maintain present altitude"), "ALT N4471T 5500 ; ALT N9920K 8500")
  asked(ex("N4471T hold altitude"), "no level said and none named as its own")
end

-- Cycle 42 (g90): a maker's name ("the Embraer", "the Bombardier") names every type of that maker, its
-- designators written otherwise too (E75L is an E175): "the X" is read only when exactly one aircraft of any
-- type of that maker flies, and asked about, naming them, when several do
do
  local _, ex = scene({ "CRE JIA77 E75L 35.9 -81.6 130 FL200 280", "CRE ASH3 E145 34.2 -80.6 340 FL170 260",
    "CRE FFT9 A320 35.0 -80.0 090 FL300 280" })
  local q = ex("remove the Embraer")
  check(q:find("JIA77", 1, true) ~= nil and q:find("ASH3", 1, true) ~= nil, q)
  check_eq(ex("the Airbus descend to FL260"), "ALT FFT9 FL260")
  local _, ex2 = scene({ "CRE JIA77 E75L 35.9 -81.6 130 FL200 280", "CRE FFT9 A320 35.0 -80.0 090 FL300 280" })
  check_eq(ex2("the Embraer climb to FL240"), "ALT JIA77 FL240")
  local _, ex3 = scene({ "CRE JZA1 CRJ9 45.0 -75.0 090 FL240 280", "CRE JZA2 DH8D 45.3 -75.4 270 FL160 240" })
  asked(ex3("drop the Bombardier"), "a CRJ900 and a Q400 are both Bombardiers")
end

-- Cycle 42 (g90): "to the east", "towards the north west" is the compass point's heading, as "fly west" is
-- (most writers read it so); a heading said with the direction ("to the south, heading 170") is that heading
do
  local _, ex = scene({ "CRE UAL88 B739 40.0 -88.0 180 FL300 290" })
  check_eq(ex("have United 88 turn over to the east please"), "HDG UAL88 90")
  check_eq(ex("UAL88 turn right towards the north west"), "HDG UAL88 315 RIGHT")
  check_eq(ex("UAL88 turn left to the south, heading 170"), "HDG UAL88 170 LEFT")
  check_eq(ex("UAL88 heading west"), "HDG UAL88 270")
  check_eq(ex("UAL88 turn east"), "HDG UAL88 90")
end

-- Cycle 42 (g90): a city's name after "over" that several large airports bear and a navaid beside them bears
-- too ("over Spartanburg": KSPA, GREENVILLE SPARTANBURG INTL, the SPA VORTAC) is asked about where traffic is
-- created; "Spartanburg airport" is the airport, "the Spartanburg VOR" the navaid, "over Ottawa" (one large
-- airport of the name) still the airport
do
  local nav, ex = navscene({}, "a city's name several large airports bear")
  if nav then
    check(ex("add Delta 9, DAL9, a 737-800, over Spartanburg heading 180 FL200 250 knots"):match("^ASK Which place is meant")
      ~= nil, "airport or navaid")
    check_eq(ex("add Delta 9, DAL9, a 737-800, over Spartanburg airport heading 180 FL200 250 knots"),
      "CRE DAL9 B738 KSPA 180 FL200 250")
    check_eq(ex("create JZA55 DH8D over Ottawa heading 090 7000 200 knots"), "CRE JZA55 DH8D CYOW 90 7000 200")
  end
end

-- Cycle 42 (g90): a demonstration's remarks to its audience ("make it snappy", "for realism", "for fun", "watch
-- the data block", "here's the fun part") account for no instruction and are set aside; a block of levels
-- ("block FL200 to FL240") and a data block to show are still asked
do
  local _, ex = scene({ "CRE ASA31 B739 47.4 -122.3 180 FL240 290" })
  check_eq(ex("Alaska 31 down to FL180 and make it snappy"), "ALT ASA31 FL180")
  check_eq(ex("for realism, ASA31 reduce speed to 250 knots"), "SPD ASA31 250")
  check_eq(ex("ASA31 turn left heading 150 just for fun"), "HDG ASA31 150 LEFT")
  check_eq(ex("ASA31 climb to flight level 280, keep an eye on his data block"), "ALT ASA31 FL280")
  check_eq(ex("now the fun part: ASA31 descend to FL200"), "ALT ASA31 FL200")
  asked(ex("ASA31 climb block FL250 to FL270"), "a block of levels")
  asked(ex("show the data block for ASA31"), "a data block to show")
end

-- Cycle 42 (g90): "take him up to 340", "take her down to 240": "take" before "up"/"down" and a level is a change
-- of level, as "bring him up to" is; a speed or heading said with it stays that value, a "take up" with no level
-- is asked
do
  local _, ex = scene({ "CRE SKW77 CRJ9 41.9 -87.9 270 FL260 280" })
  check_eq(ex("SkyWest 77, take him up to 310"), "ALT SKW77 FL310")
  check_eq(ex("take SKW77 down to one four thousand"), "ALT SKW77 14000")
  check_eq(ex("SKW77 take the speed up to 300"), "SPD SKW77 300")
  asked(ex("SKW77 take it up to 300 knots"), "a speed after 'take it up'")
  asked(ex("SKW77, take him up"), "no level")
end

-- Cycle 42 (g90): "go to 250 knots", "go Mach point eight": a speed with its unit after "go" is a speed
-- instruction, and after a level passed ("when you're passing FL300 go Mach .8") it waits for that level; a bare
-- number after "go to" is no speed
do
  local _, ex = scene({ "CRE FDX5 B763 35.0 -90.0 090 FL250 300" })
  check_eq(ex("FedEx 5 climb to FL350 and when you're passing FL310 go Mach point seven eight"),
    "ALT FDX5 FL350 ; ATALT FDX5 FL310 SPD FDX5 M0.78")
  check_eq(ex("FDX5 descend FL150, when he's passing FL200 go to 260 knots"),
    "ALT FDX5 FL150 ; ATALT FDX5 FL200 SPD FDX5 260")
  check_eq(ex("FDX5 go to 270 knots"), "SPD FDX5 270")
  asked(ex("FDX5 go to 270"), "a bare number after 'go to'")
end

-- Cycle 42 (g90): the resolution watched after an instruction ("fast forward two minutes and watch the
-- resolution kick in") is what the run will show, no method to set; "watch the resolution" alone is still asked
do
  local _, ex = scene({ "CRE KAL9 B77W 37.0 127.0 090 FL330 300", "CRE AAR2 A333 37.0 127.6 270 FL330 300" })
  check_eq(ex("now fast forward two minutes and watch the resolution kick in"), "FF 120")
  check_eq(ex("KAL9 descend FL310, then see the resolution"), "ALT KAL9 FL310")
  asked(ex("watch the resolution"), "no instruction before it")
end

-- Cycle 42 (g90): a waypoint reached said after the aircraft's callsign ("DAL415, when you get to ERLIN, go direct
-- ATL", "... once you pass ERLIN turn left ...") is the condition, AT ... DO, as "when DAL415 reaches ERLIN" is;
-- a waypoint off the route, or one only seen, is still asked
do
  local _, ex = scene({ "DEFWPT KOLBY 45.0 -93.0", "DEFWPT LAKER 45.5 -92.5", "DEFWPT OFFRT 44.0 -94.0",
    "CRE SCX31 B738 44.5 -93.5 045 FL240 280", "ADDWPT SCX31 KOLBY", "ADDWPT SCX31 LAKER" })
  check_eq(ex("Sun Country 31, when you get to KOLBY, proceed direct LAKER"), "AT SCX31 KOLBY DO DIRECT SCX31 LAKER")
  check_eq(ex("SCX31 once you pass KOLBY descend to FL180"), "AT SCX31 KOLBY DO ALT SCX31 FL180")
  check_eq(ex("SCX31 when you're down to FL200 reduce to 250 knots"), "ATALT SCX31 FL200 SPD SCX31 250")
  asked(ex("SCX31 when you reach OFFRT descend to FL180"), "a waypoint off the route")
  asked(ex("SCX31 when you see KOLBY descend to FL180"), "a waypoint seen, not reached")
end

-- Cycle 42 (g90): "drop in a ...", "pop in an ..." with a new callsign or a type after the article puts an aircraft
-- in (a creation); "drop" of a flying aircraft's level, or "drop in" with no new aircraft, is not one
do
  local _, ex = scene({ "DEFWPT BANTY 41.0 -81.0", "CRE RPA61 E75L 41.2 -81.3 090 FL200 270" })
  check_eq(ex("drop in an A320, JBU718, over BANTY, heading 270, FL150, 260 knots"), "CRE JBU718 A320 BANTY 270 FL150 260")
  check_eq(ex("pop in a CRJ900, ENY33, at BANTY, heading 180, 9000 feet, 240 knots"), "CRE ENY33 CRJ9 BANTY 180 9000 240")
  check_eq(ex("RPA61 drop in altitude to FL160"), "ALT RPA61 FL160")
  check(not ex("drop in a few more aircraft"):match("^CRE"), "no new aircraft named")
end

-- Cycle 42 (hz41): an aircraft named in a comparison ("as X did", "as did X", "like X", "same as X", "as with
-- X") is not instructed; one after "as" or "as for" that is no comparison ("as X passes") is asked about
do
  local _, ex = scene({ "CRE SAS310 A320 55.0 12.0 090 FL200 250", "CRE BEE71 DH8D 55.2 12.2 090 FL180 220" })
  check_eq(ex("Climb SAS310 to FL270, as BEE71 did"), "ALT SAS310 FL270")
  check_eq(ex("climb SAS310 to FL270 as BEE71 did"), "ALT SAS310 FL270")
  check_eq(ex("Climb SAS310 to FL270, as did BEE71"), "ALT SAS310 FL270")
  check_eq(ex("SAS310 up to FL270, just like BEE71"), "ALT SAS310 FL270")
  check_eq(ex("SAS310 climb FL270 like BEE71"), "ALT SAS310 FL270")
  check_eq(ex("SAS310 climb FL270, as with BEE71"), "ALT SAS310 FL270")
  -- a wish is no comparison, and an aircraft added is still instructed
  check_eq(ex("we would like BEE71 at FL190"), "ALT BEE71 FL190")
  check_eq(ex("climb SAS310 to FL270, BEE71 as well"), "ALT SAS310 FL270 ; ALT BEE71 FL270")
  asked(ex("climb SAS310 to FL270 as BEE71 passes"), "'as' and an aircraft: a time or an aircraft added?")
  asked(ex("climb SAS310 to FL270, as for BEE71"), "'as for' an aircraft after the instruction")
  asked(ex("climb SAS310 to FL270 as BEE71 will"), "'as' and what an aircraft will do")
  asked(ex("speed SAS310 230 while BEE71 holds"), "'while' and an aircraft")
  asked(ex("SAS310 speed 230 and fly heading 200 while BEE71 holds"), "'while' and an aircraft, second instruction")
  asked(ex("descend and maintain flight level 110 SAS310 with BEE71"), "'with' and a second aircraft")
  -- "as for X, ..." opening an instruction of its own names its aircraft
  check_eq(ex("SAS310 climb FL270; as for BEE71, descend it to FL150"), "ALT SAS310 FL270 ; ALT BEE71 FL150")
end

-- Cycle 42 (hz41): ", which should also be done for X" (a relative clause with "also", "too", "likewise" or
-- "same" and an aircraft) gives the instruction to that aircraft too; a clause of what the instruction should
-- bring about names traffic that is not instructed
do
  local _, ex = scene({ "CRE SAS310 A320 55.0 12.0 090 FL200 250", "CRE BEE71 DH8D 55.2 12.2 090 FL180 220" })
  check_eq(ex("Climb SAS310 to FL270, which should also be done for BEE71"), "ALT SAS310 FL270 ; ALT BEE71 FL270")
  check_eq(ex("SAS310 speed 230, that should apply to BEE71 too"), "SPD SAS310 230 ; SPD BEE71 230")
  check_eq(ex("Climb SAS310 to FL270, which should keep it clear of BEE71"), "ALT SAS310 FL270")
end

-- Cycle 42 (hz41): traffic "ahead of", "in front of", "below", "above", "clear of" or "away from" which an
-- instruction places an aircraft, or "instead of" which it is given, is not instructed
do
  local _, ex = scene({ "CRE SAS310 A320 55.0 12.0 090 FL200 250", "CRE BEE71 DH8D 55.2 12.2 090 FL180 220" })
  check_eq(ex("BEE71 climb to 19000 feet and then maintain flight level 190 below SAS310"),
    "ALT BEE71 19000 ; ALT BEE71 FL190")
  check_eq(ex("BEE71 reduce speed to 200 knots instead of SAS310"), "SPD BEE71 200")
  check_eq(ex("SAS310 descend to FL150 clear of the BEE71"), "ALT SAS310 FL150")
  check_eq(ex("climb to FL250 SAS310 away from BEE71"), "ALT SAS310 FL250")
  check_eq(ex("climb SAS310 to FL270 ahead of BEE71"), "ALT SAS310 FL270")
  check_eq(ex("SAS310 increase speed to 280 kt and fly heading 100 ahead of the BEE71"),
    "SPD SAS310 280 ; HDG SAS310 100")
  check_eq(ex("SAS310 speed 280 to stay in front of BEE71"), "SPD SAS310 280")
end

-- Cycle 42 (hz41): a level said as an offset from another aircraft ("1000 ft below X") that is 10000 ft or more,
-- under the ground, or against the verb's direction is asked, never sent
do
  local _, ex = scene({ "CRE SAS310 A320 55.0 12.0 090 FL200 250", "CRE BEE71 DH8D 55.2 12.2 090 FL150 220" })
  check_eq(ex("SAS310 descend to 1000 ft above BEE71"), "ALT SAS310 16000")
  check_eq(ex("BEE71 climb to 1000 feet below SAS310"), "ALT BEE71 19000")
  asked(ex("climb BEE71 to 23000 feet below SAS310"), "an offset under the ground")
  asked(ex("BEE71 descend to 1000 feet below SAS310"), "a descent to a level above")
  asked(ex("SAS310 climb to 2000 ft above BEE71"), "a climb to a level below")
end

-- Cycle 42 (hz41): "expect" then an aircraft and "to" ("expect X to climb to FL200") is the speaker's expectation
-- of that aircraft, neither sent nor set aside as an expected clearance: asked; "X expect FL200" stays the
-- expected clearance squawk does not simulate
do
  local _, ex = scene({ "CRE SAS310 A320 55.0 12.0 090 FL200 250", "CRE BEE71 DH8D 55.2 12.2 090 FL180 220" })
  check_eq(ex("expect BEE71 to climb to FL240"),
    "ASK Is 'expect BEE71' an instruction to send now, or what you expect to happen? Please say the instruction itself.")
  asked(ex("we'd expect SAS310 to descend to FL150 and BEE71 to climb FL240"), "an expectation of two aircraft")
  local r = graph.translate("BEE71 expect FL240 in 10 miles", { sim = squawk.sim.new(), mode = "offline" })
  check(r.note and r.note:find("expected clearances", 1, true) ~= nil, tostring(r.note))
end

-- Cycle 42 (hz41): what is said not to be needed ("no need to climb", "no need for the descent", "you don't have
-- to resume own navigation") is no instruction and is asked; "don't resume own navigation" still switches it off
do
  local _, ex = scene({ "CRE SAS310 A320 55.0 12.0 090 FL200 250", "CRE BEE71 DH8D 55.2 12.2 090 FL180 220" })
  asked(ex("SAS310 no need to climb to FL240"), "no need to climb")
  asked(ex("there's no need to delete BEE71"), "no need to delete")
  asked(ex("BEE71, no need to turn left heading 090"), "no need to turn")
  asked(ex("you don't have to resume own navigation BEE71"), "a route not needed is not switched off")
  check_eq(ex("BEE71 don't resume own navigation"), "LNAV BEE71 OFF")
end

-- Cycle 42 (hz41): a direct-to negated by "not", "don't" or "never" before its verb ("do not go direct X") is
-- asked; "not" before a place with no verb between ("direct B, not A", "not to A but direct B") is the place
-- passed over
do
  local _, ex = scene({ "DEFWPT HZQ1 55.3 12.6", "DEFWPT HZQ2 54.9 12.0", "CRE SAS310 A320 55.0 12.0 090 FL200 250",
    "ADDWPT SAS310 HZQ1", "ADDWPT SAS310 HZQ2" })
  asked(ex("do not direct HZQ1 SAS310."), "a direct-to negated")
  asked(ex("SAS310 never go direct HZQ2"), "a direct-to negated by 'never'")
  check_eq(ex("SAS310 direct HZQ2, not HZQ1"), "DIRECT SAS310 HZQ2")
  check_eq(ex("SAS310 not to HZQ1 but direct HZQ2"), "DIRECT SAS310 HZQ2")
end

-- Cycle 42 (hz41): a group ("both", "all aircraft", "everyone") said before the instruction word in its own clause
-- is never one aircraft named before or after it: asked, unless the aircraft instructed together before are the
-- group
do
  local _, ex = scene({ "CRE SAS310 A320 55.0 12.0 090 FL200 250", "CRE BEE71 DH8D 55.2 12.2 090 FL180 220",
    "CRE FIN5 A321 55.1 12.4 270 FL160 260" })
  asked(ex("SAS310 heading 100. both climb to FL300"), "'both' after one aircraft")
  asked(ex("SAS310 heading 100. all aircraft climb to FL300"), "'all aircraft' after one aircraft")
  asked(ex("everyone climb to FL350 then BEE71 descend to FL120"), "'everyone' before an aircraft named later")
  check_eq(ex("SAS310 and BEE71 heading 100, both climb FL300"),
    "HDG SAS310 100 ; HDG BEE71 100 ; ALT SAS310 FL300 ; ALT BEE71 FL300")
  check_eq(ex("SAS310, BEE71 and FIN5 heading 100, all climb FL300"),
    "HDG SAS310 100 ; HDG BEE71 100 ; HDG FIN5 100 ; ALT SAS310 FL300 ; ALT BEE71 FL300 ; ALT FIN5 FL300")
end

-- Cycle 42 (hz41): a phrase of what squawk does not simulate ("hold ...", "do a 360") never takes a negation
-- after it: "hold present level, do not climb to FL350" asks about the "not", never climbs
do
  local _, ex = scene({ "CRE SAS310 A320 55.0 12.0 090 FL200 250" })
  asked(ex("SAS310 hold present level, do not climb to FL350"), "a negation after a hold")
  asked(ex("do not heading 360 SAS310"), "'do not' is no orbit")
  asked(ex("SAS310 squawk 7000, never climb above FL300"), "a negation after a squawk code")
  asked(ex("SAS310 cancel speed restriction but no need to climb to FL300"), "'no need' after a restriction lifted")
end

-- Cycle 42 (hz41): an aircraft in a clause after a comma that words of its own follow, with no value and no
-- instruction word ("..., keep X as is", "..., X no change", "..., X will follow", ", as for X, no change"), is
-- talked about, never given the instruction before the comma; "..., X too" and "..., X at 90 knots" still are
do
  local _, ex = scene({ "DEFWPT HZQ1 55.3 12.6", "CRE SAS310 A320 55.0 12.0 090 FL200 250",
    "CRE BEE71 DH8D 55.2 12.2 090 FL180 220" })
  check_eq(ex("SAS310 proceed direct HZQ1, keep BEE71 as is"), "ADDWPT SAS310 HZQ1 ; DIRECT SAS310 HZQ1")
  check_eq(ex("SAS310 speed 280 and direct HZQ1, as for BEE71, no change"),
    "SPD SAS310 280 ; ADDWPT SAS310 HZQ1 ; DIRECT SAS310 HZQ1")
  check_eq(ex("climb to FL250 SAS310, BEE71 will follow"), "ALT SAS310 FL250")
  asked(ex("SAS310 speed 280 and direct HZQ1, BEE71 no change"), "an aircraft with no change said")
  check_eq(ex("SAS310 climb FL300 and turn left heading 270, BEE71 too"),
    "ALT SAS310 FL300 ; HDG SAS310 270 LEFT ; ALT BEE71 FL300 ; HDG BEE71 270 LEFT")
  check_eq(ex("SAS310 at FL300, BEE71 at 190 knots"), "ALT SAS310 FL300 ; SPD BEE71 190")
end

-- Cycle 43 (k89): a type's model name that the performance data (OpenAP's titles, else another designator's
-- pattern) gives to another designator is that designator: "E175", "Embraer 175", "E-175" are the E75L (no ICAO
-- designator is E175); E170, E190 and E195 are their own; "the E175" still describes an aircraft flying as one
do
  local _, ex = scene({ "CRE LOT455 E175 52.2 4.6 040 FL150 270", "CRE KLM9 E190 52.0 4.0 180 FL200 270" })
  check_eq(ex("add RPA702, an E175, at 52.4 4.9, heading 210, FL160, 260 knots"), "CRE RPA702 E75L 52.4 4.9 210 FL160 260")
  check_eq(ex("new traffic: Embraer 175 RPA703 at 52.4 4.9 heading 210 at 9000 feet 240 knots"),
    "CRE RPA703 E75L 52.4 4.9 210 9000 240")
  check_eq(ex("create RPA704 E-175 at 52.4 4.9 heading 210 FL160 260 knots"), "CRE RPA704 E75L 52.4 4.9 210 FL160 260")
  check_eq(ex("spawn 4 random E175s"), "MCRE 4 E75L")
  check_eq(ex("add KLM705, an E170, at 52.4 4.9, heading 210, FL160, 260 knots"), "CRE KLM705 E170 52.4 4.9 210 FL160 260")
  check_eq(ex("add KLM706, an Embraer 190, at 52.4 4.9, heading 210, FL160, 260 knots"), "CRE KLM706 E190 52.4 4.9 210 FL160 260")
  check_eq(ex("add KLM707, an E195, at 52.4 4.9, heading 210, FL160, 260 knots"), "CRE KLM707 E195 52.4 4.9 210 FL160 260")
  check_eq(ex("the E175 climb to FL240"), "ALT LOT455 FL240")
  asked(ex("add KLM708, an Embraer, at 52.4 4.9, heading 210, FL160, 260 knots"), "a maker names no one type")
end

-- Cycle 43 (k89): an unpause to come, said by its speaker ("when I unpause", "until we resume"), starts nothing
-- now: "pause until I resume" is the pause alone; a rate said with it is asked (OP, which unpauses, runs at
-- DTMULT 1, so a rate set before it would not hold), as is anything else said to happen then
do
  local _, ex = scene({ "CRE KLM9 E190 52.0 4.0 180 FL200 270" })
  check_eq(ex("freeze the sim until we unpause"), "HOLD")
  check_eq(ex("pause the simulation"), "HOLD")
  check_eq(ex("unpause at 3x"), "OP ; DTMULT 3")
  local q = ex("hold the clock and run at 4x once we resume")
  check(q:match("^ASK") and q:find("1x", 1, true) ~= nil, q)
  asked(ex("once I unpause, make it 3x"), "a rate for an unpause to come")
  asked(ex("pause it, and when I resume"), "nothing said to happen now")
end

-- Cycle 43 (k89): a family's name of two words said where traffic is created ("a King Air") is read whole, as
-- one word is ("a caravan"): with several designators of the family known it is asked, naming them; a variant
-- said ("King Air 350") or a designator written is that type
do
  local _, ex = scene({ "CRE N61TX C172 33.8 -118.3 315 2500 95" })
  local q = ex("create a King Air, N481KA, at 33.9 -118.1, heading 090, 8000, 210 knots")
  check(q:match("^ASK") and q:find("BE20", 1, true) and q:find("B350", 1, true), q)
  check_eq(ex("add a King Air 350, N481KA, at 33.9 -118.1, heading 090, 8000, 210 knots"),
    "CRE N481KA B350 33.9 -118.1 90 8000 210")
  check_eq(ex("spawn a King Air, N481KA, BE20, at 33.9 -118.1, heading 090, 8000, 210 knots"),
    "CRE N481KA BE20 33.9 -118.1 90 8000 210")
end

-- Cycle 43 (k89): a wind as it is reported, "wind 250 at 12" (three digits, "at", a bare number of knots), is its
-- direction and speed, as "250 at 12 knots" is; a direction of fewer digits or a speed past 200 is no such report
do
  local _, ex = scene({ "DEFWPT LAKEY 45.0 -93.0" })
  check_eq(ex("wind 250 at 12 at 45.1 -93.2"), "WIND 45.1 -93.2 250 12")
  check_eq(ex("wind 040 at 8 over LAKEY"), "WIND LAKEY 40 8")
  asked(ex("wind 25 at 12 over LAKEY"), "two digits are no reported direction")
  asked(ex("wind 250 at 320 over LAKEY"), "320 is no wind speed in knots")
end
-- with no aircraft to place it near, the whole name of one airport that is the city of other large airports too
-- ("Phoenix": ZJSY "PHOENIX INTL" in China, KPHX "PHOENIX SKY HARBOR INTL") is asked after "at" as after "over";
-- the airport's full name is that one
do
  local _, ex = navscene({}, "a city's name of several large airports")
  if ex then
    local q = ex("wind 250 at 12 at Phoenix")
    check(q:match("^ASK") and q:find("KPHX", 1, true) and q:find("ZJSY", 1, true), q)
    asked(ex("create N41PX C172 at Phoenix heading 090 5500 100 knots"), "Phoenix is two large airports")
    check_eq(ex("wind 250 at 12 over Phoenix Sky Harbor"), "WIND KPHX 250 12")
  end
end

-- Cycle 43 (k89): a bare registration suffix typed after the request's first word ("relocate 7QX to ...", "from
-- 7QX's route") is asked about, naming the one aircraft whose US registration ends with it (or the several);
-- the registration said whole is read
do
  local _, ex = scene({ "CRE N517QX C172 40.1 -105.1 090 6500 100", "CRE N88TR SR22 40.3 -105.3 180 8500 150",
    "CRE N44TR P28A 40.2 -105.0 270 7500 95", "DEFWPT BOLDR 40.2 -105.2", "ADDWPT N517QX BOLDR" })
  local q = ex("relocate 7QX to 40.0 north 105.0 west")
  check(q:match("^ASK") and q:find("N517QX", 1, true) ~= nil, q)
  q = ex("take BOLDR out of 7QX's route")
  check(q:match("^ASK") and q:find("N517QX", 1, true) ~= nil, q)
  q = ex("remove 8TR")
  check(q:match("^ASK") and q:find("N88TR", 1, true) ~= nil and q:find("N44TR", 1, true) == nil, q)
  check_eq(ex("relocate N517QX to 40.0 north 105.0 west"), "MOVE N517QX 40 -105")
  check_eq(ex("take BOLDR out of N517QX's route"), "DELWPT N517QX BOLDR")
end

-- Cycle 43 (k89): a designator's letter said apart from its digits typed, where traffic is created ("an e 190",
-- "a b 738"), is that type when squawk knows it; "a 320" (an article) and digits no type has are not
do
  local _, ex = scene({})
  check_eq(ex("create RPA12 an e 175 at 41.0 -87.0 heading 090 9000 feet 240 knots"), "CRE RPA12 E75L 41 -87 90 9000 240")
  check_eq(ex("create DLH5 a b 738 at 50.0 8.0 heading 090 FL200 250 knots"), "CRE DLH5 B738 50 8 90 FL200 250")
  asked(ex("create RPA13 an e 555 at 41.0 -87.0 heading 090 9000 feet 240 knots"), "no type is E555")
end

-- Cycle 43 (k9192): the run taken up again ("resume run", "continue the run") is OP, said alone or as a clause
-- of its own; "resume run" after a callsign is no clock started
do
  local _, ex = scene({ "CRE SIA22 A359 1.3 103.9 090 FL310 290" })
  check_eq(ex("resume run"), "OP")
  check_eq(ex("ok, continue the run please"), "OP")
  check_eq(ex("SIA22 turn left heading 050, then resume the run"), "HDG SIA22 50 LEFT ; OP")
  asked(ex("SIA22 resume run"), "a callsign before 'resume run'")
end

-- Cycle 43 (k9192): the discourse particles of Singapore and Malaysian English ("ok lah", "can lah") carry no
-- instruction, and the courtesy of Thai, Malay and Filipino controllers ("terima kasih", "sawasdee khrap") is
-- courtesy; a word that is neither is still asked about
do
  local _, ex = scene({ "CRE SIA22 A359 1.3 103.9 090 FL310 290" })
  check_eq(ex("SIA22 ok lah, descend FL250"), "ALT SIA22 FL250")
  check_eq(ex("SIA22 turn right heading 140 can lah"), "HDG SIA22 140 RIGHT")
  check_eq(ex("SIA22 sawasdee khrap, climb FL330, terima kasih"), "ALT SIA22 FL330")
  asked(ex("SIA22 ok lah, descend FL250 mampu"), "an unknown word after the particle")
end

-- Cycle 43 (k9192): text for the screen or the log said after a colon ("write on the screen: ...", "show on the
-- scope: ...") is ECHO of that text; a colon with no screen or log named before it is no ECHO
do
  local _, ex = scene({ "CRE SIA22 A359 1.3 103.9 090 FL310 290" })
  check_eq(ex("write on the screen: second block begins"), "ECHO second block begins")
  check_eq(ex("please show in the log: SIA22 handed over"), "ECHO SIA22 handed over")
  asked(ex("write this down: second block"), "no screen or log named")
end

-- Cycle 43 (k9192): "departure airport" / "departure aerodrome" with an airport named is the origin (ORIG);
-- with no airport, or no aircraft of several, it is asked
do
  local _, ex = scene({ "CRE SIA22 A359 1.3 103.9 090 FL310 290", "CRE MAS7 B738 2.7 101.7 180 FL200 270" })
  check_eq(ex("SIA22 set departure airport WSSS"), "ORIG SIA22 WSSS")
  check_eq(ex("make the departure aerodrome of SIA22 WMKK"), "ORIG SIA22 WMKK")
  asked(ex("set departure airport WSSS"), "no aircraft named")
  asked(ex("SIA22 set departure airport"), "no airport named")
end

-- Cycle 43 (k9192): "cap" before a number is French for heading, but not after "red": "Red Cap" is AirAsia's
-- telephony ("delete the red cap 712", "remove red cap 6015"); a "cap" of its own before a number is still heading
do
  local _, ex = scene({ "CRE AXM712 A320 2.3 101.4 040 FL130 260", "CRE AXM6015 A320 3.6 101.5 170 FL200 290" })
  check_eq(ex("delete the red cap 712"), "DEL AXM712")
  check_eq(ex("red cap 712 climb FL200, then remove red cap 6015"), "ALT AXM712 FL200 ; DEL AXM6015")
  check_eq(ex("red cap 6015 cap 090"), "HDG AXM6015 90")
  asked(ex("red cap 712 turn red cap 090"), "a heading said as the airline")
end

-- Cycle 43 (k9192): "be over FIX at ALT" / "be overhead FIX FL070" is the crossing constraint there (AT ... ALT),
-- as "be at FIX at ALT" is; "be over FIX" with no value, or with a verb after it, is still asked
do
  local _, ex = scene({ "DEFWPT TOLAK 47.6 9.3", "DEFWPT MEROS 47.4 9.0", "CRE SWR7 A20N 47.8 9.6 240 FL110 250",
    "ADDWPT SWR7 TOLAK", "ADDWPT SWR7 MEROS" })
  check_eq(ex("SWR7 be over TOLAK at 9000 feet"), "AT SWR7 TOLAK ALT 9000")
  check_eq(ex("SWR7 please be overhead MEROS at FL070 and 210 knots"), "AT SWR7 MEROS ALT FL70 ; AT SWR7 MEROS SPD 210")
  asked(ex("SWR7 be over TOLAK"), "no value to meet there")
  asked(ex("SWR7 be over TOLAK and descend"), "a verb with no value")
end

-- Cycle 43 (k9192): a value said again "exactly" after a self-correction ("at or below FL090, sorry make it
-- exactly FL090") replaces the value and takes back the bound said before it; a new value with no "exactly" after
-- a bound still leaves the bound to confirm
do
  local _, ex = scene({ "DEFWPT PAKSE 14.0 100.5", "CRE THA9 A359 13.9 100.9 230 FL150 280", "ADDWPT THA9 PAKSE" })
  check_eq(ex("THA9 cross PAKSE at or below FL120, sorry make it exactly FL120"), "AT THA9 PAKSE ALT FL120")
  check_eq(ex("THA9 cross PAKSE at or above FL100, no wait, make it exactly FL110"), "AT THA9 PAKSE ALT FL110")
  check_eq(ex("THA9 reduce speed 250, sorry make it exactly 240"), "SPD THA9 240")
  asked(ex("THA9 cross PAKSE at or below FL120, sorry make it FL110"), "the bound not taken back")
end

-- Cycle 43 (k9192): a new aircraft's callsign said as a registration in capitals ("D-EABC", "DEABC") straight
-- after or before its type, and a designator written as one word with the type named after "type" ("create
-- BCS1 type B744"), are the callsign; a fix's name there, or no such word, is still asked
do
  local _, ex = scene({ "DEFWPT TOLAK 47.6 9.3" })
  check_eq(ex("please create a Piper PA28 D-EFGH at 49.5 8.4, heading 090, 2500 ft, 95 knots"),
    "CRE DEFGH PA28 49.5 8.4 90 2500 95")
  check_eq(ex("create HB-KLM C172 at 47.5 8.5"), "CRE HBKLM C172 47.5 8.5")
  check_eq(ex("create A20N1 type A388 at 47.0 8.0"), "CRE A20N1 A388 47 8")
  asked(ex("create a C172 TOLAK at 49.9 8.6"), "a fix's name after the type")
  asked(ex("create a C172 at 49.9 8.6"), "no callsign")
end

-- Cycle 43 (k9192): "never mind" after punctuation is a self-correction: what it follows is taken back and what
-- is said after it stands ("direct KALOP... never mind, just heading 300"); closing the request it is asked
do
  local _, ex = scene({ "DEFWPT KALOP 13.9 100.7", "CRE NOK55 B738 13.6 101.1 290 FL180 290", "ADDWPT NOK55 KALOP" })
  check_eq(ex("NOK55 direct KALOP... never mind, just heading 300"), "HDG NOK55 300")
  check_eq(ex("NOK55 delete waypoint, never mind, turn left heading 250"), "HDG NOK55 250 LEFT")
  check_eq(ex("NOK55 climb FL200, never mind, descend FL140"), "ALT NOK55 FL140")
  asked(ex("NOK55 climb FL200, never mind"), "nothing after 'never mind'")
  -- ("forget that", "nevermind" the same)
  check_eq(ex("NOK55 climb FL200... forget that, just heading 300"), "HDG NOK55 300")
  check_eq(ex("NOK55 turn left heading 200, nevermind, 210"), "HDG NOK55 210 LEFT")
  asked(ex("NOK55 climb FL200, forget that"), "nothing after 'forget that'")
end

-- Cycle 43 (k9192): a speed condition said by its noun ("when reaching speed 250", "when DLH4AB reaches speed 250,")
-- is ATSPD, as "when reaching 250 knots" is; the condition with no instruction after it is still asked
do
  local _, ex = scene({ "CRE AUA31 A320 48.1 16.5 270 FL240 280" })
  check_eq(ex("AUA31 when reaching speed 260 descend flight level 180"), "ATSPD AUA31 260 ALT AUA31 FL180")
  check_eq(ex("when AUA31 reaches speed 260, turn right heading 300"), "ATSPD AUA31 260 HDG AUA31 300 RIGHT")
  asked(ex("AUA31 when reaching speed 260"), "no instruction after the condition")
end

-- Cycle 43 (k9192): "after FIX direct WPT" with waypoints of the route between the two is asked by name (the
-- shortcut flown from FIX, or the waypoints between deleted?); to the next waypoint it is AT ... DO DIRECT
do
  local _, ex = scene({ "DEFWPT KOTAB 3.3 101.9", "DEFWPT SIBEK 3.2 101.7", "DEFWPT RAWAN 3.1 101.5",
    "CRE MAS88 B738 3.5 102.1 200 FL160 280", "ADDWPT MAS88 KOTAB", "ADDWPT MAS88 SIBEK", "ADDWPT MAS88 RAWAN" })
  check_eq(ex("MAS88 after KOTAB direct RAWAN"), "ASK Should MAS88 fly direct RAWAN once past KOTAB, leaving out SIBEK "
    .. "of its route (AT MAS88 KOTAB DO DIRECT MAS88 RAWAN), or delete SIBEK from the route?")
  check_eq(ex("MAS88 after KOTAB direct SIBEK"), "AT MAS88 KOTAB DO DIRECT MAS88 SIBEK")
end

-- Cycle 43 (k9192): "cancel FIX" said with a direct-to past FIX on the route ("direct LEMON now, cancel GRANT") is
-- what the direct-to does; a waypoint after the direct-to's is still asked
do
  local _, ex = scene({ "DEFWPT TAPAK 14.0 100.8", "DEFWPT LUMOT 14.1 100.6", "CRE THA5 A359 13.9 100.9 230 FL150 280",
    "ADDWPT THA5 TAPAK", "ADDWPT THA5 LUMOT" })
  check_eq(ex("THA5 direct to LUMOT now, cancel TAPAK"), "DIRECT THA5 LUMOT")
  check_eq(ex("THA5 direct LUMOT, cancel TAPAK and descend FL100"), "DIRECT THA5 LUMOT ; ALT THA5 FL100")
  asked(ex("THA5 direct TAPAK, cancel LUMOT"), "a waypoint after the direct-to's")
end

-- Cycle 43 (cpp43): a place name said with no traffic to place it near is also its city's: the large airports
-- whose names start with it are candidates beside the airports of that name, several asked ("Phoenix": ZJSY
-- "PHOENIX INTL" or KPHX "PHOENIX SKY HARBOR INTL"); a name one airport bears, or traffic beside one, decides
do
  local _, ex = navscene({}, "a city's airports anywhere")
  if ex then
    local q = ex("wind from 250 at 20 knots over Phoenix")
    check(q:find("ZJSY", 1, true) ~= nil and q:find("KPHX", 1, true) ~= nil, q)
    asked(ex("create AAL7 A320 at Phoenix heading 090 FL100 250 knots"), "two airports of the name")
    check_eq(ex("wind from 250 at 20 knots at Phoenix Sky Harbor"), "WIND KPHX 250 20")
    check_eq(ex("wind from 250 at 20 knots at Denver"), "WIND KDEN 250 20")
  end
  local _, near = navscene({ "CRE AAL1 A320 33.5 -112.2 090 FL100 250" }, "a city's airport near the traffic")
  if near then
    check_eq(near("create AAL7 A320 at Phoenix heading 090 FL100 250 knots"), "CRE AAL7 A320 KPHX 90 FL100 250")
  end
end

-- Cycle 43 (cpp43): an aircraft created "at CODE", a code a navaid bears that after one letter names an airport
-- standing off it (farther than lexicon.on_airport_nm: the LAX VORTAC and KLAX), is two places, asked; "airport"
-- or the navaid's kind said decides; a navaid on its airport ("at JFK") is one place, the airport
do
  local _, ex = navscene({}, "a navaid's code and its airport")
  if ex then
    local q = ex("put in AAL8, a B738, at LAX, heading 250, FL100, 250 knots")
    check(q:find("^ASK") ~= nil and q:find("KLAX", 1, true) ~= nil, q)
    check_eq(ex("put in AAL8, a B738, at LAX airport, heading 250, FL100, 250 knots"), "CRE AAL8 B738 KLAX 250 FL100 250")
    check_eq(ex("put in AAL8, a B738, at the LAX VOR, heading 250, FL100, 250 knots"), "CRE AAL8 B738 LAX 250 FL100 250")
    check_eq(ex("put in AAL8, a B738, at JFK, heading 250, FL100, 250 knots"), "CRE AAL8 B738 KJFK 250 FL100 250")
  end
end

-- Cycle 43 (cpp43): a fraction after a whole number ("two and a half", "one and a half thousand", "five and a
-- quarter") is read with it; after a multiplier, a flight level or a heading it is no value's and is asked
do
  local _, ex = scene({ "CRE SWA40 B737 36.0 -115.0 090 FL80 250" })
  check_eq(ex("make the protected zone radius four and a half nautical miles"), "ZONER 4.5")
  check_eq(ex("zone radius 3 and a quarter nm"), "ZONER 3.25")
  check_eq(ex("set the separation radius to six and a quarter miles"), "ZONER 6.25")
  check_eq(ex("SWA40 descend to two and a half thousand feet"), "ALT SWA40 2500")
  check_eq(ex("jump ahead four minutes and a half"), "FF 270")
  check_eq(ex("jump ahead four and a half minutes"), "FF 270")
  asked(ex("SWA40 climb to six thousand and a half"), "a fraction after thousand")
  asked(ex("SWA40 climb to FL120 and a half"), "a flight level has no fraction")
end

-- Cycle 43 (k90): "nav" is navigation's short word after "put ... back on its own" (LNAV ON, no move);
-- "put X back at" a position is still the move, "put X back on nav" with no "own" still asked
do
  local _, ex = scene({ "DEFWPT TOLKA 40.0 -100.0", "CRE FFT88 A20N 40.5 -100.5 090 FL280 270", "ADDWPT FFT88 TOLKA" })
  check_eq(ex("ok now I'll put FFT88 back on its own nav"), "LNAV FFT88 ON")
  check_eq(ex("put Frontier 88 back on its own nav, LNAV on"), "LNAV FFT88 ON")
  check_eq(ex("put FFT88 back at 40.2 -100.2"), "MOVE FFT88 40.2 -100.2")
  asked(ex("put FFT88 back on nav"), "no 'own' before 'nav'")
end

-- Cycle 43 (k90): "stop it / everything for a moment" with no aircraft named pauses the run (HOLD); with an
-- aircraft named, or with no while said, it is asked
do
  local _, ex = scene({ "CRE FFT88 A20N 40.5 -100.5 090 FL280 270" })
  check_eq(ex("ok stop it for a second, I want to explain the picture"), "HOLD")
  check_eq(ex("stop everything for a minute"), "HOLD")
  asked(ex("FFT88 stop it for a moment"), "an aircraft named")
  asked(ex("stop it"), "no while said")
end

-- Cycle 43 (k90): the run resumed, said in the passive of the simulation named before it ("the exercise can be
-- resumed from where it stopped") starts the clock (OP); the passive of an aircraft's route is no OP
do
  local _, ex = scene({ "DEFWPT TOLKA 40.0 -100.0", "CRE FFT88 A20N 40.5 -100.5 090 FL280 270", "ADDWPT FFT88 TOLKA" })
  check_eq(ex("The exercise can now be resumed from where it was frozen."), "OP")
  check_eq(ex("the simulation is to be resumed now"), "OP")
  check(not ex("FFT88's route can be resumed now"):match("^OP"), "an aircraft's route resumed")
end

-- Cycle 43 (k90): an airline's name said, then straight after it (a comma, a hesitation) a flying aircraft's exact
-- callsign ("Frontier, uh, FFT88 climb ..."), names that aircraft, also where the name is another airline's and none
-- of that airline flies; with one of the named airline flying, or no comma between, it is still asked
do
  local _, ex = scene({ "CRE FFT88 A20N 40.5 -100.5 090 FL280 270", "CRE SKW3411 CRJ7 40.0 -101.0 270 FL300 280",
    "CRE SKW3412 CRJ7 40.2 -101.2 270 FL320 280" })
  check_eq(ex("Frontier, uh, FFT88 climb to FL320"), "ALT FFT88 FL320")
  check_eq(ex("Alaska, um, SKW3411, descend to FL260"), "ALT SKW3411 FL260")
  asked(ex("SkyWest, uh, FFT88 climb to FL320"), "a SkyWest aircraft flies")
  asked(ex("Frontier FFT88 SKW3411 climb to FL320"), "nothing between the name and two callsigns")
end

-- Cycle 43 (k90): a city or airport named to describe an aircraft or airspace ("a Munich arrival", "the arrival
-- into Oslo", "the Lisbon TMA") is explained, no place instructed; a city said with no such word around it, or where
-- the aircraft comes from ("inbound from ..."), is still asked; a place beside another "in relation to" it is framing
do
  local _, ex = scene({ "DEFWPT ROKKI 48.0 11.0", "CRE DLH4AX A321 48.3 11.3 200 FL210 280", "ADDWPT DLH4AX ROKKI" })
  check_eq(ex("ok so here we have a Munich arrival, DLH4AX, bring him down to FL150"), "ALT DLH4AX FL150")
  check_eq(ex("DLH4AX is on the arrival into Munich, have it cross ROKKI at FL120"), "AT DLH4AX ROKKI ALT FL120")
  check_eq(ex("set the protected zone radius to 3 nm, as used in the Lisbon TMA"), "ZONER 3")
  asked(ex("DLH4AX descend FL150 Munich"), "a city with no word of description")
  asked(ex("DLH4AX inbound from Oslo, descend FL150"), "the place it comes from")
  check_eq(ex("where is ROKKI in relation to the traffic? just its position please"), "POS ROKKI")
  local _, nx = navscene({ "CRE AAL61 A321 35.6 -80.6 200 FL230 300" }, "a city by the navdata's airport names")
  if nx then
    check_eq(nx("this is a Charlotte arrival, American 61, descend to FL190"), "ALT AAL61 FL190")
    asked(nx("American 61 descend to FL190 Charlotte"), "a city with no word of description")
  end
end

-- Cycle 43 (k90): an airport's own name the navdata does not give, said with its city ("Barcelona El Prat"), is that
-- airport; said alone where the grammar has no airport phrase for it, it is still asked
do
  local _, ex = navscene({ "CRE VLG77 A320 41.0 2.0 045 FL100 250" }, "an airport's own name")
  if ex then
    check_eq(ex("VLG77's destination is now Barcelona El Prat"), "DEST VLG77 LEBL")
    asked(ex("VLG77 destination Prat"), "a part of the name alone")
  end
end

-- Cycle 43 (k90): a distance said after "at" in nautical miles ("At fifteen nautical miles from TOLKA, ...") is the
-- distance of an ATDIST condition, its "at" and number no callsign; with no instruction after it, it is still asked
do
  local _, ex = scene({ "DEFWPT TOLKA 40.0 -100.0", "CRE FFT88 A20N 40.5 -100.5 090 FL280 270", "ADDWPT FFT88 TOLKA",
    "CRE SKW3411 CRJ7 40.0 -101.0 270 FL300 280" })
  check_eq(ex("At fifteen nautical miles from TOLKA, Frontier 88 should slow to 250 knots."),
    "ATDIST FFT88 TOLKA 15 SPD FFT88 250")
  check_eq(ex("FFT88, at 20 nautical miles from TOLKA descend FL200"), "ATDIST FFT88 TOLKA 20 ALT FFT88 FL200")
  asked(ex("At fifteen nautical miles from TOLKA, Frontier 88"), "no instruction")
end

-- Cycle 43 (k90): an aircraft described "from" its airline ("the regional jet from Delta, climb ...") names that
-- airline's one aircraft flying; with two of it flying, or none, it is asked
do
  local _, ex = scene({ "CRE DAL3301 CRJ9 39.0 -86.0 090 FL200 280", "CRE UAL7 B738 39.5 -86.5 270 FL330 300",
    "CRE UAL8 B738 39.2 -86.2 270 FL350 300" })
  check_eq(ex("the regional jet from Delta, descend to FL160"), "ALT DAL3301 FL160")
  check_eq(ex("the plane from Delta turn left heading 040"), "HDG DAL3301 40 LEFT")
  asked(ex("the jet from United, descend to FL300"), "two United aircraft flying")
  asked(ex("the jet from Frontier, descend to FL300"), "no Frontier aircraft flying")
end

-- Cycle 43 (k90): the reason an instruction is taken back, said after the correction ("... no wait, it's already on
-- the route, add ..."), belongs to the correction; with no correction word, or a value in the reason, it is asked
do
  local _, ex = scene({ "DEFWPT TOLKA 40.0 -100.0", "DEFWPT BIRDO 40.2 -100.2", "DEFWPT MESSA 40.4 -100.4",
    "CRE FFT88 A20N 40.5 -100.5 090 FL280 270", "ADDWPT FFT88 TOLKA", "ADDWPT FFT88 MESSA" })
  check_eq(ex("FFT88 add TOLKA... oh wait it's in there already, add BIRDO before MESSA"), "ADDWPT FFT88 BIRDO,,,,MESSA")
  check_eq(ex("FFT88 climb FL340, no wait, it's too high, descend FL260"), "ALT FFT88 FL260")
  asked(ex("FFT88 add TOLKA, it's in there already, add BIRDO before MESSA"), "no correction word")
  asked(ex("FFT88 add TOLKA... no wait it's at FL200, add BIRDO before MESSA"), "a value in the reason")
end

-- Cycle 43 (hz43): a self-correction that puts an instruction of another kind in the place of one issued
-- ("climb FL200, no wait, heading 300") takes it back or adds to it, which is not knowable: asked, naming both;
-- of the same kind the corrected value alone is read, and "and" after it adds
do
  local _, ex = scene({ "CRE TAP18 A320 38.8 -9.1 040 FL150 260" })
  check_eq(ex("TAP18 climb FL240, no wait, heading 310"),
    "ASK Should I do 'heading 310' instead of 'climb fl 240', or as well?")
  asked(ex("TAP18 climb FL240, no, heading 310"), "'no' before a heading")
  asked(ex("TAP18 descend FL120, correction, turn left 280"), "'correction' before a turn")
  asked(ex("TAP18 reduce 230, negative, heading 010"), "'negative' before a heading")
  check_eq(ex("TAP18 turn right heading 090, sorry, descend FL110"),
    "ASK Should I do 'descend fl 110' instead of 'heading 090', or as well?")
  check_eq(ex("TAP18 climb FL240, no wait, FL250"), "ALT TAP18 FL250")
  check_eq(ex("TAP18 heading 310 correction 320"), "HDG TAP18 320")
  check_eq(ex("TAP18 climb FL240, sorry, descend FL100"), "ALT TAP18 FL100")
  check_eq(ex("TAP18 climb FL240, sorry, and heading 310"), "ALT TAP18 FL240 ; HDG TAP18 310")
  -- (the value said again before the next instruction, or no instruction with a value after the correction word)
  check_eq(ex("TAP18 climb FL240, I say again two four zero, reduce 230"), "ALT TAP18 FL240 ; SPD TAP18 230")
  check_eq(ex("TAP18 descend FL120, no speed restrictions"), "ALT TAP18 FL120")
  -- (words that take back, "never mind", "forget that", "scratch that", leave the instruction said after them)
  check_eq(ex("TAP18 climb FL240, never mind, heading 310"), "HDG TAP18 310")
  check_eq(ex("TAP18 climb FL240, oh forget that, speed 220"), "SPD TAP18 220")
  check_eq(ex("TAP18 climb FL240, scratch that, FL230"), "ALT TAP18 FL230")
end

-- Cycle 43 (hz43): a rate said after the clock's start with no "at" ("resume and go 4x", "unpause and run 5 times")
-- is DTMULT after OP, never dropped
do
  local _, ex = scene({})
  check_eq(ex("resume and go 4x"), "OP ; DTMULT 4")
  check_eq(ex("unpause and go 5 times"), "OP ; DTMULT 5")
  check_eq(ex("unpause and run at 6 times"), "OP ; DTMULT 6")
  check_eq(ex("continue at double speed"), "OP ; DTMULT 2")
  check_eq(ex("resume and go"), "OP")
  asked(ex("resume and go 4 qz"), "a word not understood after the start")
end

-- Cycle 43 (hz43b): a level, speed or heading said after a copula describing the present ("is at", "are head on
-- at", "are both at", "'s at", "is maintaining", "currently at") issues nothing, even where the aircraft is named
-- again with an instruction of its own; an instruction ("is to climb", "is cleared to"), a shorthand value and a
-- condition ("when ... is at") are still read, and a description alone is asked
do
  local _, ex = scene({ "CRE SAS31 A320 55.0 10.0 090 FL330 280", "CRE SAS32 A320 55.0 11.0 270 FL330 280",
    "CRE NAX7 B738 55.5 10.5 180 FL290 270" })
  check_eq(ex("SAS31 and SAS32 are nose to nose at FL330, climb SAS31 to FL350"), "ALT SAS31 FL350")
  check_eq(ex("SAS31 and SAS32 are head on at FL330, climb SAS31 to FL350"), "ALT SAS31 FL350")
  check_eq(ex("NAX7 is at FL290, descend NAX7 to FL250"), "ALT NAX7 FL250")
  check_eq(ex("NAX7's at FL290, descend NAX7 to FL250"), "ALT NAX7 FL250")
  check_eq(ex("SAS31 and NAX7 are converging at FL310, turn NAX7 right heading 220"), "HDG NAX7 220 RIGHT")
  check_eq(ex("SAS31 and SAS32 are both level at FL330, climb SAS32 to FL370"), "ALT SAS32 FL370")
  check_eq(ex("NAX7 is currently maintaining 270 knots, slow NAX7 to 240 knots"), "SPD NAX7 240")
  check_eq(ex("NAX7 currently at FL290, descend NAX7 to FL250"), "ALT NAX7 FL250")
  check_eq(ex("NAX7 is at FL290, turn NAX7 left heading 290"), "HDG NAX7 290 LEFT")
  check_eq(ex("NAX7 is cleared to FL310"), "ALT NAX7 FL310")
  check_eq(ex("NAX7 FL250"), "ALT NAX7 FL250")
  check_eq(ex("when NAX7 is at FL250, turn left heading 100"), "ATALT NAX7 FL250 HDG NAX7 100 LEFT")
  check_eq(ex("when NAX7's at FL250, turn left heading 100"), "ATALT NAX7 FL250 HDG NAX7 100 LEFT")
  asked(ex("NAX7 is at FL290"), "a description alone")
  asked(ex("NAX7's at FL290"), "a contracted description alone")
  asked(ex("NAX7 is at FL290, NAX7"), "a description with the callsign again and no instruction")
end

-- Cycle 43 (lead): two commands read from English that set the same target of one aircraft now (a level described
-- and a level cleared, a heading said twice) are asked, naming both; typed TrafScript runs as typed
do
  local _, ex = scene({ "CRE KLM12 B738 52.0 4.0 090 FL300 250", "CRE EZY45 A320 52.2 4.4 180 FL300 240" })
  local q = ex("we have KLM12 at FL350, climb KLM12 to FL370")
  check(q:find("'ALT KLM12 FL350' and 'ALT KLM12 FL370'", 1, true) ~= nil, q)
  asked(ex("KLM12's heading 090, turn KLM12 left heading 060"), "two headings for one aircraft")
  check_eq(ex("KLM12 climb FL370, EZY45 climb FL350"), "ALT KLM12 FL370 ; ALT EZY45 FL350")
  check_eq(ex("KLM12 climb FL370 and reduce 230"), "ALT KLM12 FL370 ; SPD KLM12 230")
  check_eq(ex("ALT KLM12 FL350 ; ALT KLM12 FL370"), "ALT KLM12 FL350 ; ALT KLM12 FL370")
end

-- Cycle 44 (hz44): a climb to a value below the aircraft, or a descent to one above it, with no "by" said, is
-- asked (to that level, or by that much?), never read as a step; "by", "up", "another" say the step
do
  local _, ex = scene({ "CRE PHLOW C172 52.0 4.0 090 2500 100", "CRE KLM61 B738 52.2 4.2 270 FL240 280",
    "CRE TRA7 B738 52.4 4.4 180 FL330 280" })
  local q = ex("PHLOW climb 2000")
  check(q:match("^ASK PHLOW is at 2500 ft: climb to 2000 ft, or by 2000 ft%?") ~= nil, q)
  asked(ex("PHLOW climb 1500 feet"), "a climb to below, in feet")
  asked(ex("KLM61 climb 1000 ft"), "a small amount from the flight levels")
  asked(ex("PHLOW descend 3000"), "a descent to above the aircraft")
  asked(ex("PHLOW descend to 3200 ft"), "a descent to a little above the aircraft")
  check_eq(ex("PHLOW climb 4500"), "ALT PHLOW 4500")
  check_eq(ex("PHLOW climb by 1500 feet"), "ALT PHLOW 4000")
  check_eq(ex("KLM61 up 2000 feet"), "ALT KLM61 26000")
  check_eq(ex("KLM61 climb another 1000 feet"), "ALT KLM61 25000")
  -- "descend 3000 feet" from the flight levels: the step to some, the approach altitude to others
  asked(ex("TRA7, descend 2000 feet"), "to or by from FL330")
  asked(ex("TRA7 cleared ILS runway two seven, descend 3000 feet"), "to or by after an approach clearance")
  check_eq(ex("TRA7 descend to 3000 feet"), "ALT TRA7 3000")
  check_eq(ex("TRA7 descend by 3000 feet"), "ALT TRA7 30000")
  check_eq(ex("TRA7 runway two seven, descend one zero thousand"), "ALT TRA7 10000")
end

-- Cycle 44 (hz44): a value's name glued to its value by a dot ("mach.78", "mach0.78", "fl.250") is the name and
-- the value; a word holding a digit and a mark that nothing read ("mach,78", "zz.80") is asked about by name
do
  local _, ex = scene({ "CRE SWR83 A333 47.0 8.0 090 FL350 290" })
  check_eq(ex("swr83 turn left heading 100 and mach.81"), "HDG SWR83 100 LEFT ; SPD SWR83 M0.81")
  check_eq(ex("swr83 mach0.79"), "SPD SWR83 M0.79")
  check_eq(ex("swr83 fl.370 and heading 120"), "ALT SWR83 FL370 ; HDG SWR83 120")
  check_eq(ex("swr83 heading 100 and mach,81"), "ASK I have HDG SWR83 100. What does 'mach,81' mean?")
  check_eq(ex("swr83 heading 100 zz.80"), "ASK I have HDG SWR83 100. What does 'zz.80' mean?")
end

-- Cycle 44 (hz44): a level said after "through" ("expedite climb through FL200") is one to pass: with no level
-- to fly to it is asked; with one ("through FL180 to FL120") the aircraft flies to that one
do
  local _, ex = scene({ "CRE DLH5T A320 50.0 8.5 180 FL280 280" })
  local q = ex("DLH5T descend through flight level one eight zero")
  check(q:find("'through flight level one eight zero' is a level to pass", 1, true) ~= nil, q)
  asked(ex("DLH5T descend thru FL180"), "through, typed thru")
  asked(ex("DLH5T climb through 30000 feet"), "through, in feet")
  check_eq(ex("DLH5T descend through FL180 to FL120"), "ALT DLH5T FL120")
end

-- Cycle 44 (hz44): a hedge straight after a value, closing its clause ("fl200 perhaps", "heading 090 I guess")
-- is asked, naming the hedge; a hedge before the value is courtesy, a loose value ("ish", "about", "or so") is
-- the value said
do
  local _, ex = scene({ "CRE AFR71 A320 45.0 5.0 090 FL300 280" })
  local q = ex("afr71 descend fl220 perhaps")
  check(q:find("You said 'perhaps' after", 1, true) ~= nil, q)
  asked(ex("afr71 heading 140 i guess"), "I guess")
  asked(ex("afr71 speed 250 probably, and heading 140"), "a hedge closing its clause before a comma")
  asked(ex("afr71 descend fl220 maybe?"), "a hedge before a question mark")
  check_eq(ex("afr71 descend fl220 or so"), "ALT AFR71 FL220")
  check_eq(ex("afr71 speed 250ish"), "SPD AFR71 250")
  check_eq(ex("could you maybe descend afr71 to fl220"), "ALT AFR71 FL220")
  check_eq(ex("afr71 a bit slower, maybe 260 knots"), "SPD AFR71 260")
end

-- Cycle 44 (f96): a distress or urgency call acknowledged ("roger Mayday", "pan pan acknowledged", "roger the
-- emergency"), a request granted ("emergency descent approved", "deviation approved") ending its clause, and a
-- controller's questions of an aircraft in distress ("say fuel remaining") carry no command: the instructions
-- beside them are read alone. A call with no acknowledgement, or a grant with a value in its clause, asks.
do
  local _, ex = scene({ "CRE UAL418 B739 40.5 -74.5 090 FL280 290", "CRE EXS22M B738 53.2 -2.1 180 FL200 270" })
  check_eq(ex("United 418 roger your Mayday, descend and maintain one two thousand"), "ALT UAL418 12000")
  check_eq(ex("Jet2 22 mike, pan pan received, turn right heading 150"), "HDG EXS22M 150 RIGHT")
  check_eq(ex("United 418, copy, Mayday, turn left heading 020 descend FL150"), "HDG UAL418 20 LEFT ; ALT UAL418 FL150")
  check_eq(ex("united four one eight roger mayday descend flight level one six zero"), "ALT UAL418 FL160")
  check_eq(ex("United 418 understood the emergency, fly heading 330"), "HDG UAL418 330")
  check_eq(ex("Jet2 22M emergency descent approved, descend FL120"), "ALT EXS22M FL120")
  check_eq(ex("United 418 deviations approved, when able turn right heading 090"), "HDG UAL418 90 RIGHT")
  check_eq(ex("Jet2 22M roger pan, say persons on board, descend FL100"), "ALT EXS22M FL100")
  asked(ex("United 418 Mayday, descend FL150"), "a call with no acknowledgement")
  asked(ex("United 418 roger Mayday"), "an acknowledgement alone")
  asked(ex("United 418 roger the emergency descent FL150"), "an acknowledgement running into a descent")
  asked(ex("Jet2 22M emergency descent, descend FL120"), "an emergency descent not granted")
  asked(ex("United 418 deviation approved 20 degrees right"), "a deviation granted with a value")
  asked(ex("United 418 Mayday relay, descend FL150"), "a relay")
end

-- Cycle 44 (f96): what "unable" refuses (a value, a direct-to, "that heading", "higher", or nothing before a
-- comma), with a reason after it ending its clause, is set aside; the instruction after it is read alone.
-- "unable" of the pilot ("if unable", "when unable") or before anything else asks.
do
  local _, ex = scene({ "CRE UAL418 B739 40.5 -74.5 090 FL280 290", "CRE EXS22M B738 53.2 -2.1 180 FL200 270" })
  check_eq(ex("United 418 unable FL320 due to traffic, maintain FL280, turn left heading 060"),
    "ALT UAL418 FL280 ; HDG UAL418 60 LEFT")
  check_eq(ex("United 418 unable higher because of crossing traffic, fly heading 100"), "HDG UAL418 100")
  check_eq(ex("Jet2 22M unable your request, reduce speed 250 knots"), "SPD EXS22M 250")
  check_eq(ex("Jet2 22M unable, turn right heading 200"), "HDG EXS22M 200 RIGHT")
  check_eq(ex("Jet2 22M unable due weather, descend FL160"), "ALT EXS22M FL160")
  asked(ex("Jet2 22M unable direct to nowhere, turn right heading 200"), "a refusal of no place")
  asked(ex("Jet2 22M unable to comply, turn right heading 200"), "unable before something else")
  asked(ex("Jet2 22M, if unable FL240, turn right heading 200"), "the pilot's unable")
  -- (the traffic's level, "traffic at FL230", is traffic information)
  check_eq(ex("Jet2 22M unable FL240 due traffic at FL230, turn right heading 200"), "HDG EXS22M 200 RIGHT")
  asked(ex("Jet2 22M unable FL240 due FL230, turn right heading 200"), "a reason naming a value")
  asked(ex("Jet2 22M unable"), "unable alone")
end

-- Cycle 44 (f96): "fox", the older alphabet's word for F, is that letter of a callsign; a callsign it makes that
-- no aircraft bears is asked, as with "foxtrot"
do
  local _, ex = scene({ "CRE DLH7F A320 50.0 8.0 090 FL280 290", "CRE BAW51 B738 51.2 -0.1 180 FL200 270" })
  check_eq(ex("Lufthansa seven fox, climb flight level three one zero"), "ALT DLH7F FL310")
  check_eq(ex("lufthansa 7 fox turn right heading 120"), "HDG DLH7F 120 RIGHT")
  asked(ex("Speedbird 51 fox, climb FL240"), "a letter no aircraft's callsign holds")
end

-- Cycle 44 (f96): a sim operator's words: "inject" an aircraft (CRE), "drop X from the exercise" (DEL), "speed it
-- up to times N" (DTMULT), "stand by", "resolution advisories" (RESO); a route's edits: "take out FIX" (DELWPT),
-- "read me back your route" (LISTRTE), "flight plan cancel, delete the route" (DELRTE); CityJet by its name
do
  local _, ex = scene({ "CRE BCY41 E190 53.4 -6.0 320 FL120 250", "CRE EIN88 A320 53.6 -6.8 090 FL300 280",
      "DEFWPT LIFFY 53.5 -5.5", "DEFWPT NIMAT 53.6 -4.5", "ADDWPT EIN88 LIFFY", "ADDWPT EIN88 NIMAT" })
  check_eq(ex("inject Ryanair 7TK, B738, at 53.2 -6.4 heading 180 FL240 290 kts"), "CRE RYR7TK B738 53.2 -6.4 180 FL240 290")
  check_eq(ex("exercise control: drop Cityjet 41 from the sim"), "DEL BCY41")
  check_eq(ex("City Ireland four one, descend FL100"), "ALT BCY41 FL100")
  check_eq(ex("speed it up to times 3"), "DTMULT 3")
  check_eq(ex("pause the simulation, stand by"), "HOLD")
  check_eq(ex("resolution advisories on, MVP"), "RESO MVP")
  check_eq(ex("Shamrock 88 take out NIMAT"), "DELWPT EIN88 NIMAT")
  check_eq(ex("Shamrock 88 take LIFFY out"), "DELWPT EIN88 LIFFY")
  check_eq(ex("Shamrock 88 read back your routing"), "LISTRTE EIN88")
  check_eq(ex("Shamrock 88, flight plan cancelled, delete the route"), "DELRTE EIN88")
  asked(ex("inject a fault into Shamrock 88"), "an injection of no aircraft")
  asked(ex("drop Cityjet 41 from the list"), "dropped from no run")
  asked(ex("speed it up to times 3, Shamrock 88"), "an aircraft named beside the rate")
  asked(ex("Shamrock 88 traffic advisory, climb FL320"), "an advisory of no resolution")
  asked(ex("Shamrock 88 flight plan cancel, climb FL320"), "a plan cancelled with no deletion")
  asked(ex("Shamrock 88 read back your heading"), "a readback of no route")
end

-- Cycle 44 (f9599): a new aircraft's callsign by its airline's telephony ("Air Crete", whose "Crete" is no typo
-- for "create"; "Mozambique", "Israir", "Arkia") or by the airline's ICAO code written in capitals apart from
-- its flight number ("LAM 733"); a code squawk knows no airline by is asked
do
  local _, ex = scene({ "CRE SEH902 A320 35.3 25.2 090 FL200 260", "CRE OAL61 A320 37.9 23.7 270 FL150 250" })
  check_eq(ex("create Air Crete seven one two, A321, at 35.0 24.0, heading 090, FL140, 250 knots"),
    "CRE SEH712 A321 35 24 90 FL140 250")
  check_eq(ex("delete Air Crete nine zero two"), "DEL SEH902")
  check_eq(ex("create Mozambique 733 B737 at -19.8 34.8 heading 010 FL190 280 knots"),
    "CRE LAM733 B737 -19.8 34.8 10 FL190 280")
  check_eq(ex("create Israir 88 A320 at 31.9 34.9 heading 180 FL100 250 knots"), "CRE ISR88 A320 31.9 34.9 180 FL100 250")
  check_eq(ex("create LAM 733 B737 at -19.8 34.8 heading 010 FL190 280 knots"), "CRE LAM733 B737 -19.8 34.8 10 FL190 280")
  check_eq(ex("create DTA 12, A332, at -8.9 13.2, heading 200, FL310, 290 knots"), "CRE DTA12 A332 -8.9 13.2 200 FL310 290")
  asked(ex("create QQX 733 B737 at -19.8 34.8 heading 010 FL190 280 knots"), "an ICAO code squawk knows no airline by")
end

-- Cycle 44 (f9599): a Boeing family said digit by digit ("triple seven", "seven four seven") or typed ("777") with
-- a variant said straight after it ("300ER", "200 LR", "four hundred") is that variant where traffic is created;
-- the family so said alone names no type
do
  local _, ex = scene({})
  check_eq(ex("create UAE44 triple seven 200LR at 25.2 55.3 heading 300 FL350 mach .84"),
    "CRE UAE44 B77L 25.2 55.3 300 FL350 M0.84")
  check_eq(ex("create UAE45 777 300 ER at 25.2 55.3 heading 300 FL350 mach .84"), "CRE UAE45 B77W 25.2 55.3 300 FL350 M0.84")
  check_eq(ex("create KLM46 seven four seven four hundred at 52.3 4.8 heading 270 FL330 290 knots"),
    "CRE KLM46 B744 52.3 4.8 270 FL330 290")
  asked(ex("create UAE47 triple seven at 25.2 55.3 heading 300 FL350 mach .84"), "a family with no variant said")
end

-- Cycle 44 (f9599): Portuguese "um" (one) inside digits said in Portuguese ("nível dois um zero"); with no
-- Portuguese digit beside it "um" stays a hesitation
do
  local _, ex = scene({ "CRE TAP441 A320 38.7 -9.1 180 FL330 270" })
  check_eq(ex("TAP441 descend nível dois um zero"), "ALT TAP441 FL210")
  check_eq(ex("TAP441 descend flight level dois uma zero"), "ALT TAP441 FL210")
  asked(ex("TAP441 descend flight level um um zero"), "'um' with no Portuguese digit beside it")
end

-- Cycle 44 (f9599): a family's number said after "the" that the callsign matcher heard as a slip for a callsign
-- ("the seven four seven" with CLX7447 flying) is the aircraft described when exactly one of that family flies;
-- with none or two of it flying the slip is asked about
do
  local _, ex = scene({ "CRE CLX7447 B738 49.6 6.2 090 FL200 280", "CRE CLX790 B744 49.8 6.0 270 FL310 290" })
  check_eq(ex("the seven four seven, climb FL350"), "ALT CLX790 FL350")
  check_eq(ex("the 747 turn left heading 240"), "HDG CLX790 240 LEFT")
  local _, ex2 = scene({ "CRE CLX7447 B738 49.6 6.2 090 FL200 280", "CRE CLX790 B744 49.8 6.0 270 FL310 290",
    "CRE GTI8 B748 49.9 6.4 180 FL330 290" })
  asked(ex2("the seven four seven, climb FL350"), "two of the family flying")
end

-- Cycle 44 (f9599): a level said bare after "passing" (or "leaving", "reaching") after a climb or descent, then
-- the rate made smaller or larger ("reduce rate to 1000"), waits for that level (ATALT ... VS), the rate's sign
-- the way to the level cleared
do
  local _, ex = scene({ "CRE GLO77 B738 -23.5 -46.6 090 FL100 260" })
  check_eq(ex("GLO77 climb FL 260, passing 180 reduce rate to fifteen hundred"),
    "ALT GLO77 FL260 ; ATALT GLO77 FL180 VS GLO77 1500")
  check_eq(ex("GLO77 descend FL 60, leaving FL80 increase your rate to 2000"),
    "ALT GLO77 FL60 ; ATALT GLO77 FL80 VS GLO77 -2000")
  check_eq(ex("GLO77 climb FL260, reduce rate to 1500"), "ALT GLO77 FL260 1500")
  asked(ex("GLO77 climb FL 260, passing 90 reduce rate to fifteen hundred"), "a level the climb will not pass")
end

-- Cycle 44 (f9599): "thousand feet" said bare (no number before it) is one thousand feet; a fraction or count
-- before it keeps its own reading
do
  local _, ex = scene({ "CRE AEE61 A320 37.9 23.7 090 FL120 250" })
  check_eq(ex("set the vertical protected zone thousand feet"), "ZONEDH 1000")
  check_eq(ex("AEE61 descend to one and a half thousand feet"), "ALT AEE61 1500")
  asked(ex("AEE61 climb to thousand feet"), "'to thousand' may be 'two thousand'")
end

-- Cycle 44 (f9599): a navaid said by its name that several navaids of one station bear (within
-- lexicon.navaid_station_nm of each other: Rhodes's NDB ROS, VOR-DME RDS and TACAN ROD) is the station's VOR
do
  local s, ex = navscene({ "CRE OAL90 A320 36.2 27.5 090 FL150 260" }, "a station's navaids by name")
  if s then
    check_eq(ex("OAL90 direct RODOS"), "ADDWPT OAL90 RDS ; DIRECT OAL90 RDS")
  end
end

-- Cycle 44 (f98): "instead" ending the instruction's clause or before the value it took fills a correction
-- ("no, climb SAS31 instead, FL350"); an instruction to a pronoun is still asked
do
  local _, ex = scene({ "CRE SAS31 A320 55.0 10.0 090 FL330 280", "CRE NAX7 B738 55.5 10.5 180 FL290 270" })
  check_eq(ex("no, climb SAS31 instead, FL350"), "ALT SAS31 FL350")
  check_eq(ex("negative, turn NAX7 instead heading 200"), "HDG NAX7 200")
  asked(ex("no, climb it instead, FL350"), "a pronoun with two aircraft flying")
  asked(ex("climb SAS31 instead to FL350 unless NAX7 objects"), "a condition after 'instead'")
end

-- Cycle 44 (f98): "give the Vueling 25 right": typed degrees (1 to 180) after "the" and an airline, then a turn's
-- side with no number after it, are the turn's value when no aircraft has that callsign; an airline called bare
-- with the number, a callsign that flies, a number after the side and two of the airline flying are not read so
do
  local _, ex = scene({ "CRE VLG12 A320 41.0 2.0 100 FL300 280", "CRE IBE33 A321 41.5 2.5 200 FL320 280",
    "CRE IBE4 A320 41.3 2.8 300 FL280 270", "CRE AEA61 B738 41.2 2.2 010 FL260 270" })
  check_eq(ex("give the Vueling 25 right"), "HDG VLG12 125 RIGHT")
  check_eq(ex("the Vueling 25 degrees left please"), "HDG VLG12 75 LEFT")
  check_eq(ex("give the Air Europa 10 left"), "HDG AEA61 360 LEFT")
  asked(ex("give Vueling 25 right"), "an airline called bare with its number")
  asked(ex("turn the Vueling 25 right 30"), "a number after the side")
  asked(ex("give the Iberia 25 right"), "two of the airline flying")
  local _, ex2 = scene({ "CRE VLG30 A320 41.5 2.5 200 FL320 280", "CRE IBE33 A321 41.0 2.0 100 FL300 280" })
  asked(ex2("give the Vueling 30 right"), "the callsign VLG30 flies")
end

-- Cycle 44 (f98): "the Airbus 321": an Airbus family's number said without its letter names its one aircraft
-- flying; two of it flying are asked
do
  local _, ex = scene({ "CRE VLG12 A320 41.0 2.0 100 FL300 280", "CRE IBE33 A321 41.5 2.5 200 FL320 280",
    "CRE RYR4 B738 41.3 2.8 300 FL280 270", "CRE EZY9 A320 41.1 2.1 010 FL260 270" })
  check_eq(ex("get rid of the Airbus 321"), "DEL IBE33")
  check_eq(ex("climb the Airbus 321 to FL360"), "ALT IBE33 FL360")
  asked(ex("get rid of the Airbus 320"), "two A320s flying")
end

-- Cycle 44 (f98): a clause opening the request that describes aircraft with "is"/"are", no value, ended by a comma,
-- before an instruction naming its own aircraft after its word, is talked about; with no aircraft after the
-- instruction word it is still asked
do
  local _, ex = scene({ "CRE SAS31 A320 55.0 10.0 090 FL330 280", "CRE NAX7 B738 55.5 10.5 270 FL330 270" })
  check_eq(ex("SAS31 and NAX7 are nose to nose, descend the Norwegian to FL310"), "ALT NAX7 FL310")
  check_eq(ex("SAS31 is closing on NAX7, climb SAS31 to FL350"), "ALT SAS31 FL350")
  asked(ex("SAS31 and NAX7 are nose to nose, descend to FL310"), "no aircraft after the instruction word")
end

-- Cycle 44 (f98): "head on with X", "converging with X" after a creation or an instruction name the traffic met
do
  local _, ex = scene({ "CRE SAS31 A320 55.0 10.0 090 FL330 280" })
  check_eq(ex("create NAX9 B738 at 55.0 11.0 heading 270 FL330 speed 270, head on with SAS31"),
    "CRE NAX9 B738 55 11 270 FL330 270")
  check_eq(ex("create NAX9 B738 at 55.5 10.5 heading 180 FL330 speed 270 converging with SAS31"),
    "CRE NAX9 B738 55.5 10.5 180 FL330 270")
end

-- Cycle 44 (f98): "SAS 1402 and 1420": typed digits after a callsign and "and" that are, with its airline, another
-- aircraft flying name it too; digits no aircraft has are asked
do
  local _, ex = scene({ "CRE SAS1402 A320 55.0 10.0 090 FL330 280", "CRE SAS1420 A320 55.5 10.5 270 FL310 270" })
  check_eq(ex("SAS 1402 and 1420, both climb FL370"), "ALT SAS1402 FL370 ; ALT SAS1420 FL370")
  check_eq(ex("SAS1402 and 1420 reduce 250"), "SPD SAS1402 250 ; SPD SAS1420 250")
  asked(ex("SAS 1402 and 1440, both climb FL370"), "digits of no aircraft")
end

-- Cycle 44 (f98): "drop X at LAT LON" moves the aircraft; "drop X at FL80" stays a descent
do
  local _, ex = scene({ "CRE NAX7 B738 55.5 10.5 270 FL330 270" })
  check_eq(ex("drop NAX7 at 55.1 10.2"), "MOVE NAX7 55.1 10.2")
  check_eq(ex("drop NAX7 at FL250"), "ALT NAX7 FL250")
end

-- Cycle 44 (f98): "resume the scenario" starts the clock; "resolve past CPA" is RESNAV PASTCPA
do
  local _, ex = scene({})
  check_eq(ex("resume the scenario please"), "OP")
  check_eq(ex("continue scenario"), "OP")
  check_eq(ex("resolve past CPA"), "RESNAV PASTCPA")
  check_eq(ex("resolve with MVP"), "RESO MVP")
end

-- Cycle 44 (f98): with callsigns said, "the TYPE" opening a clause with its instruction word straight after names
-- the one aircraft of that type; two of it flying, or no instruction after it, are asked
do
  local _, ex = scene({ "CRE SAS31 A320 55.0 10.0 090 FL330 280", "CRE NAX7 B77W 55.5 10.5 270 FL330 270",
    "CRE NAX8 B738 55.2 10.2 180 FL300 270", "CRE SAS40 B738 55.3 10.6 010 FL280 270" })
  check_eq(ex("SAS31 turn left 10, and the 777 turn left 10 as well"), "HDG SAS31 80 LEFT ; HDG NAX7 260 LEFT")
  check_eq(ex("SAS31 climb FL350 then the 777 descend FL310"), "ALT SAS31 FL350 ; ALT NAX7 FL310")
  asked(ex("SAS31 turn left 10, and the 737 turn left 10 as well"), "two 737s flying")
  asked(ex("SAS31 turn left 10, and the 777 as well"), "no instruction word after the type")
end

-- Cycle 44 (f97): a typing slip in a request that is otherwise asked about (translate/typos.lua): a word no list
-- knows, one edit from an instruction word, is read as each known word one edit from it; the reading stands when
-- every reading that issues commands issues the same ones and one of them is the instruction word's. Two words
-- typed together ("turnleft") are read apart. Words in capitals and places near the traffic stay as typed.
do
  local _, ex = scene({ "CRE BAW8CK A320 52.0 4.0 025 FL200 250", "CRE KLM1234 B738 52.2 4.2 300 FL250 280",
    "CRE DLH4AX A321 52.4 4.4 090 FL300 280", "CRE KLM77 B738 52.1 4.5 180 FL150 250", "DEFWPT WP1 52.1 4.1" })
  check_eq(ex("KLM77 tun left heading 200"), "HDG KLM77 200 LEFT")
  check_eq(ex("KLM77 descend FL100 nad reduce 220"), "ALT KLM77 FL100 ; SPD KLM77 220")
  check_eq(ex("KLM1234 climb FL300 tehn turn left heading 200"), "ALT KLM1234 FL300 ; HDG KLM1234 200 LEFT")
  check_eq(ex("KLM77 descend FL100 at 1800 fpn"), "ALT KLM77 FL100 1800")
  check_eq(ex("add WP1 to KLM77 ruote"), "ADDWPT KLM77 WP1")
  check_eq(ex("BAW8CK turnleft heading 090"), "HDG BAW8CK 90 LEFT")
  check_eq(ex("KLM77 righthdg 300"), "HDG KLM77 300 RIGHT")
  -- (in capitals a word is a name; two edits from "turn" is no slip; a reading only by a word of no instruction,
  -- "abv", is no answer)
  check_eq(ex("KLM77 TUN left heading 200"), "ASK I have HDG KLM77 200 LEFT. What does 'TUN' mean?")
  check_eq(ex("KLM77 tum right 20 degrees"), "ASK I have HDG KLM77 200 RIGHT. What does 'tum' mean?")
  asked(ex("KLM77 climb FL200 abd 250"), "a slip whose only reading is 'abv'")
end
-- (a navaid of the slip's letters near the traffic, TUN at Tulln, keeps it as typed)
do
  local _, ex = navscene({ "CRE AUA12 A320 48.2 16.2 090 FL150 250" }, "a slip that is a navaid near the traffic")
  if ex then asked(ex("AUA12 tun left heading 200"), "TUN is a navaid near the traffic") end
end

-- Cycle 44 (f97): values typed with a slip: a comma after "FL" ("fl,110") or, after a verb of a level change, a space
-- inside its three figures ("climb FL3 10", "climb fl 3 20"; a unit after the figures keeps them apart),
-- "mach.79", a plus after "vertical speed" (the sign of a climb; after "speed" alone it is still a change of speed),
-- a comma with no space after a value
do
  local _, ex = scene({ "CRE BAW8CK A320 52.0 4.0 025 FL200 250", "CRE KLM1234 B738 52.2 4.2 300 FL250 280",
    "CRE DLH4AX A321 52.4 4.4 090 FL300 280", "CRE KLM77 B738 52.1 4.5 180 FL150 250" })
  check_eq(ex("KLM77 descend fl,110"), "ALT KLM77 FL110")
  check_eq(ex("KLM1234 climb FL3 10"), "ALT KLM1234 FL310")
  check_eq(ex("klm1234 climb fl 3 20"), "ALT KLM1234 FL320")
  check(ex("KLM77 descend fl 1 20 kts") ~= "ALT KLM77 FL120", "a unit after the figures keeps them apart")
  check_eq(ex("klm77 fl 2 40"), "ALT KLM77 FL240")  -- (with no verb too: cycle 47)
  check_eq(ex("DLH4AX mach.79"), "SPD DLH4AX M0.79")
  check_eq(ex("DLH4AX climb FL320 and mach.80"), "ALT DLH4AX FL320 ; SPD DLH4AX M0.8")
  check_eq(ex("BAW8CK vertical speed +900"), "VS BAW8CK 900")
  check_eq(ex("BAW8CK speed +20"), "SPD BAW8CK 270")
  check_eq(ex("KLM1234 heading 200,climb FL300"), "HDG KLM1234 200 ; ALT KLM1234 FL300")
end

-- Cycle 44 (f97): "add point LAT,LON to X's route": a point given by decimal degrees is the waypoint added; with no
-- route and no aircraft said it is asked
do
  local _, ex = scene({ "CRE KLM77 B738 52.1 4.5 180 FL150 250" })
  check_eq(ex("add point 52.15,4.35 to KLM77's route"), "ADDWPT KLM77 52.15 4.35")
  check_eq(ex("add point 52.15 4.35 to the route of KLM77"), "ADDWPT KLM77 52.15 4.35")
  asked(ex("add point 52.15,4.35"), "a point with no route")
end

-- Cycle 44 (f97): "the 321": a designator's digits after "the" describe the one aircraft of that type flying, not a
-- callsign heard inexactly; with several of the type flying it is asked
do
  local _, ex = scene({ "CRE BAW8CK A320 52.0 4.0 025 FL200 250", "CRE KLM1234 B738 52.2 4.2 300 FL250 280",
    "CRE DLH4AX A321 52.4 4.4 090 FL300 280", "CRE KLM77 B738 52.1 4.5 180 FL150 250" })
  check_eq(ex("the 321 descend FL250"), "ALT DLH4AX FL250")
  check_eq(ex("the 320 turn left heading 100"), "HDG BAW8CK 100 LEFT")
  asked(ex("the 738 climb FL330"), "two 738s flying")
end

-- Cycle 45 (s103b): the operational reason said after a comma behind a complete instruction ("inbound to ...",
-- "sequencing into ...", "<airport> metering", "ride reports") is set aside, the place it names too; a place
-- after a comma with no reason's word, or with "at" and no reason, is still asked
do
  local _, ex = scene({ "CRE KLM77 B738 52.1 4.5 180 FL150 250", "CRE SAS31 A320 55.0 10.0 090 FL330 280" })
  check_eq(ex("KLM77 descend FL90, he's inbound to AMS"), "ALT KLM77 FL90")
  check_eq(ex("KLM77 reduce 230, sequencing into LHR"), "SPD KLM77 230")
  check_eq(ex("KLM77 slow to 220, CDG metering"), "SPD KLM77 220")
  check_eq(ex("SAS31 down to FL310, ride reports"), "ALT SAS31 FL310")
  asked(ex("KLM77 descend FL90, AMS"), "a place after a comma with no reason word")
  asked(ex("KLM77 descend FL90, SAS31 inbound"), "an aircraft in the clause")
  asked(ex("KLM77 descend FL90, flow restricted to 240"), "a value in the clause")
  asked(ex("KLM77 descend FL90, inbound from Vigo"), "where it comes from: no reason")
end

-- Cycle 45 (s103b): a telephone call as the reason for a pause or a break ("pause the sim, phone"); "ETA" with
-- the aircraft alone asks its state (POS)
do
  local _, ex = scene({ "CRE KLM77 B738 52.1 4.5 180 FL150 250" })
  check_eq(ex("freeze the sim, phone"), "HOLD")
  check_eq(ex("sorry phone - KLM77 climb FL170"), "ALT KLM77 FL170")
  check_eq(ex("KLM77 ETA?"), "POS KLM77")
  check_eq(ex("eta klm77"), "POS KLM77")
  asked(ex("ETA"), "no aircraft named")
end

-- Cycle 45 (s103b): an Airbus family's number after "the" without its letter ("the 350", "the 321") describes the
-- one aircraft of that family flying, beside a level of the same digits; two of the family, or "to the 350", are
-- not read so
do
  local _, ex = scene({ "CRE DLH47 A359 50.0 8.0 045 FL370 280", "CRE UAE9 A388 50.2 8.7 300 FL360 290",
    "CRE DLH9 A321 50.1 8.9 270 FL120 250", "CRE BER2 A21N 50.4 8.1 090 FL140 250" })
  check_eq(ex("the 350 descend to FL350"), "ALT DLH47 FL350")
  check_eq(ex("the 380 level 310"), "ALT UAE9 FL310")
  check_eq(ex("slow the 380 down, 270"), "SPD UAE9 270")
  asked(ex("the 321 climb 160"), "two A321 family aircraft flying")
  asked(ex("climb to the 350"), "a level after 'to the', no aircraft")
end

-- Cycle 45 (s103b): "the Qatar" (the airline's name, its telephony Qatari) describes its one aircraft flying;
-- "get rid of" stays the removal where a navaid RID is in the scene
do
  local _, ex = scene({ "DEFWPT RID 50.0 8.5", "CRE QTR15 A359 25.6 54.6 120 FL380 280",
    "CRE CFG1 A20N 50.5 8.6 180 FL340 270", "CRE CFG2 A20N 50.6 8.7 180 FL320 270", "ADDWPT CFG1 RID" })
  check_eq(ex("the Qatar down to 360"), "ALT QTR15 FL360")
  check_eq(ex("get rid of CFG2"), "DEL CFG2")
  check_eq(ex("CFG1 direct RID"), "DIRECT CFG1 RID")
  asked(ex("get rid of the condor"), "two Condor aircraft flying")
  asked(ex("Qatar descend 360"), "an airline called without its number")
end

-- Cycle 45 (s103b): a rate in whole hundreds straight after "at" following a flight level said bare ("descend 340
-- at 1500") is the vertical speed, as after "FL340"; a number out of the rates' range there is still asked
do
  local _, ex = scene({ "CRE QTR15 A359 25.6 54.6 120 FL380 280" })
  check_eq(ex("QTR15 descend 340 at 1500"), "ALT QTR15 FL340 1500")
  check_eq(ex("QTR15 M.80, descend 320 at 2000"), "SPD QTR15 M0.8 ; ALT QTR15 FL320 2000")
  asked(ex("QTR15 descend 340 at 15000"), "no rate of that size")
end

-- Cycle 45 (s103b): a bare number closing a list of one aircraft's instructions after a comma or "then" is the one
-- value left it: feet with no level given ("speed 210 then 7000"), a speed after a level and a direct-to or
-- heading ("direct FINGR, FL170, 250"); where a heading or a speed both remain, or a level was given, it is asked
do
  local _, ex = scene({ "DEFWPT FINGR 33.0 -97.0", "CRE SWA38 B737 33.0 -96.6 270 FL190 270",
    "CRE ENY35 E75L 32.6 -97.6 045 8000 230", "ADDWPT SWA38 FINGR" })
  check_eq(ex("SWA38 direct FINGR, FL170, 250"), "DIRECT SWA38 FINGR ; ALT SWA38 FL170 ; SPD SWA38 250")
  check_eq(ex("SWA38 heading 240, FL170, 260"), "HDG SWA38 240 ; ALT SWA38 FL170 ; SPD SWA38 260")
  check_eq(ex("ENY35 speed 210 then 6000"), "SPD ENY35 210 ; ALT ENY35 6000")
  asked(ex("SWA38 FL170, 250"), "a heading or a speed")
  asked(ex("SWA38 descend FL170, 2000"), "a level given: a rate or another level")
  asked(ex("ENY35 speed 210, 070"), "a heading or a level")
  asked(ex("SWA38 direct FINGR, FL170, speed 250, 7000"), "a level given")
end

-- Cycle 45 (s103b): "drag X to LAT LON ..." moves the aircraft (as "drop X at" does); "speed x10" opening the request
-- alone is the clock's rate; "whats" typed without its apostrophe is "what's"; the aircraft's or the simulation's
-- ability ("if the sim lets him", "if performance allows") is courtesy, as "if able"
do
  local _, ex = scene({ "DEFWPT DERLA 25.0 55.0", "CRE SWA38 B737 33.0 -96.6 270 FL190 270" })
  check_eq(ex("drag SWA38 to 33.1 -96.9 FL180 heading 270"), "MOVE SWA38 33.1 -96.9 FL180 270")
  check_eq(ex("drag SWA38 to FL180"), "ALT SWA38 FL180")
  check_eq(ex("speed x10"), "DTMULT 10")
  asked(ex("SWA38 speed x10"), "an aircraft's speed with no value")
  check_eq(ex("whats DERLA's position"), "POS DERLA")
  check_eq(ex("whats SWA38 doing"), "POS SWA38")
  check_eq(ex("SWA38 up to 390 if the sim lets him"), "ALT SWA38 FL390")
  check_eq(ex("SWA38 climb FL390 if performance allows"), "ALT SWA38 FL390")
  asked(ex("SWA38 climb FL390 if DERLA"), "a place after 'if'")
end

-- Cycle 45 (s103b): turbulence said beside an instruction to a named aircraft is its reason ("..., turbulence",
-- "for turbulence"), no switch of the simulation's noise; said alone, or switched, it stays NOISE
do
  local _, ex = scene({ "CRE KLM77 B738 52.1 4.5 180 FL150 250" })
  check_eq(ex("KLM77 descend FL130, turbulence"), "ALT KLM77 FL130")
  check_eq(ex("KLM77 descend FL130 for turbulence"), "ALT KLM77 FL130")
  check_eq(ex("KLM77 descend FL130, moderate chop"), "ALT KLM77 FL130")
  check_eq(ex("turbulence on"), "NOISE ON")
  check_eq(ex("switch off the turbulence"), "NOISE OFF")
end

-- Cycle 45 (s103b): a bare number of feet (whole hundreds, 1000 or more) to "be at" by a waypoint of the route is
-- the crossing's level, as after "cross"; a bare 250 there (a speed or FL250) is asked
do
  local _, ex = scene({ "DEFWPT ANVIX 25.4 55.2", "CRE FDB21 B38M 25.3 54.8 090 FL220 280", "ADDWPT FDB21 ANVIX" })
  check_eq(ex("FDB21 be at 15000 at ANVIX"), "AT FDB21 ANVIX ALT 15000")
  check_eq(ex("FDB21 should be at 16000 at ANVIX"), "AT FDB21 ANVIX ALT 16000")
  asked(ex("FDB21 be at 250 at ANVIX"), "a speed or a level")
end

-- Cycle 45 (s102): an "expect" phrase ends after a runway designator: an imperative verb after it is an instruction
do
  local _, ex = scene({ "CRE TAP212 A320 38.9 -9.0 180 FL150 250" })
  check_eq(ex("TAP212 expect ILS runway 21 left descend 9000"), "ALT TAP212 9000")
  check_eq(ex("TAP212 expect runway 03 turn right heading 220"), "HDG TAP212 220 RIGHT")
  -- (the expectation alone sends nothing; an expected descent is no clearance)
  check_eq(ex("TAP212 expect ILS runway 21 left"), "")
  check_eq(ex("TAP212 expect descent to 9000 in 10 miles"), "")
end

-- Cycle 45 (s102): "dt look 180" is DTLOOK typed apart, never the time step
do
  local _, ex = scene({})
  check_eq(ex("dt look 240 seconds"), "DTLOOK 240")
  check_eq(ex("dt lookahead 4 minutes"), "DTLOOK 240")
  check_eq(ex("dt 0.2"), "DT 0.2")
end

-- Cycle 45 (s102): "simulation speed one half", "sim speed a quarter": a fraction in words is the clock's rate
do
  local _, ex = scene({})
  check_eq(ex("simulation speed one half"), "DTMULT 0.5")
  check_eq(ex("sim speed a quarter"), "DTMULT 0.25")
  check_eq(ex("simulation speed two and a half"), "DTMULT 2.5")
  check_eq(ex("simulation speed one and a half"), "DTMULT 1.5")
end

-- Cycle 45 (s102): "the Airbus three thirty": a family's number said in words after its maker describes it
do
  local _, ex = scene({ "CRE TAP212 A320 38.9 -9.0 180 FL150 250", "CRE TAP88 A332 39.0 -9.2 000 FL300 280",
    "CRE RYR5E B738 39.1 -9.1 090 FL200 260" })
  check_eq(ex("the airbus three thirty descend flight level two eight zero"), "ALT TAP88 FL280")
  check_eq(ex("the airbus three three zero descend fl280"), "ALT TAP88 FL280")
  check_eq(ex("the boeing seven thirty seven climb fl240"), "ALT RYR5E FL240")
  asked(ex("the airbus descend fl280"), "two Airbuses flying")
  asked(ex("the airbus three forty descend fl280"), "no A340 flying")
end

-- Cycle 45 (s102): "crea"/"crear" (a creation in the speaker's language) reads a type said in words or apart
-- as "create" does; the callsign's digits stay its flight number
do
  local _, ex = scene({ "DEFWPT TOLKA 40.0 -100.0" })
  check_eq(ex("crea iberia 777 boeing 737 800 at TOLKA heading 090 fl160 250"), "CRE IBE777 B738 TOLKA 90 FL160 250")
  check_eq(ex("crear iberia 320 boeing seven three seven eight hundred at TOLKA heading 090 fl160 250"),
    "CRE IBE320 B738 TOLKA 90 FL160 250")
  asked(ex("crea iberia 777 boeing 737 at TOLKA heading 090 fl160 250"), "a 737 of no variant")
end

-- Cycle 45 (s102): "add CANES then COTOS": places listed after "add", "then", "and" or a comma between, are
-- added in order; a place that is an English word only by a false "-es" ending ("canes") is a name
do
  local _, ex = scene({ "DEFWPT TOLKA 40.0 -100.0", "DEFWPT BIRDO 40.2 -100.2", "DEFWPT MESSA 40.4 -100.4",
    "CRE FFT88 A20N 40.5 -100.5 090 FL280 270" })
  check_eq(ex("FFT88 add TOLKA then BIRDO"), "ADDWPT FFT88 TOLKA ; ADDWPT FFT88 BIRDO")
  check_eq(ex("FFT88 add TOLKA and BIRDO then MESSA"), "ADDWPT FFT88 TOLKA ; ADDWPT FFT88 BIRDO ; ADDWPT FFT88 MESSA")
  check_eq(ex("FFT88 add TOLKA then BIRDO, climb fl300"), "ADDWPT FFT88 TOLKA ; ADDWPT FFT88 BIRDO ; ALT FFT88 FL300")
  asked(ex("FFT88 add TOLKA then bogus"), "a name no place bears")
  local _, nx = navscene({ "CRE AEA77 B738 40.1 -3.0 300 FL150 260" }, "lower-case fix names near the traffic")
  if nx then
    check_eq(nx("air europa 77 add canes then cotos"), "ADDWPT AEA77 CANES ; ADDWPT AEA77 COTOS")
    check_eq(nx("air europa 77 add canes"), "ADDWPT AEA77 CANES")
  end
end

-- Cycle 45 (s102): "reduce 270 after GAVOL speed 250": a waypoint passed between two instructions of one kind is the
-- second's condition (AT ... DO), never the two merged
do
  local _, ex = scene({ "DEFWPT TOLKA 40.0 -100.0", "CRE FFT88 A20N 40.5 -100.5 090 FL280 270", "ADDWPT FFT88 TOLKA" })
  check_eq(ex("FFT88 reduce 260 after TOLKA speed 240"), "SPD FFT88 260 ; AT FFT88 TOLKA DO SPD FFT88 240")
  check_eq(ex("FFT88 descend fl250 after TOLKA descend fl200"), "ALT FFT88 FL250 ; AT FFT88 TOLKA DO ALT FFT88 FL200")
  check_eq(ex("FFT88 reduce 260 after TOLKA"), "AT FFT88 TOLKA DO SPD FFT88 260")
  asked(ex("FFT88 reduce 260 after TOLKA 240"), "a value with no instruction word after the waypoint")
end
-- Cycle 45 (es102): Spanish said whole is read word for word as its English (lexicon.said_whole.spanish): turns with
-- their side and degrees, levels, rates, crossings, the experimenter's commands; a Spanish word the table does
-- not know is asked
do
  local _, ex = scene({ "CRE IBE52 A320 40.5 -3.6 200 FL180 280", "CRE AVA81 A320 4.5 -74.0 100 FL160 260",
    "DEFWPT TORMO 40.7 -3.7", "ADDWPT IBE52 TORMO" })
  check_eq(ex("iberia 52 vire a la derecha rumbo 250"), "HDG IBE52 250 RIGHT")
  check_eq(ex("avianca 81 gire por la izquierda rumbo 040"), "HDG AVA81 40 LEFT")
  check_eq(ex("avianca 81 derecha 15 grados"), "HDG AVA81 115 RIGHT")
  check_eq(ex("avianca 81 gire 25 grados izquierda"), "HDG AVA81 75 LEFT")
  check_eq(ex("iberia 52 baje a nivel 90"), "ALT IBE52 FL90")
  check_eq(ex("iberia 52 descienda con régimen 1500 pies por minuto"), "VS IBE52 -1500")
  check_eq(ex("iberia 52 cruce tormo a nivel 150"), "AT IBE52 TORMO ALT FL150")
  check_eq(ex("borre el avianca 81"), "DEL AVA81")
  check_eq(ex("donde esta el iberia 52"), "POS IBE52")
  check_eq(ex("iberia 52 listar ruta"), "LISTRTE IBE52")
  check_eq(ex("mueva avianca 81 a 4.9 -74.3 nivel 120"), "MOVE AVA81 4.9 -74.3 FL120")
  check_eq(ex("corre la simulación"), "OP")
  check_eq(ex("adelanta 5 minutos"), "FF 300")
  check_eq(ex("zona protegida cinco millas"), "ZONER 5")
  check(ex("reinicia la simulación"):match("^ASK Reset the simulation%?") ~= nil, "a reset confirmed first")
  check_eq(ex("cual es el nivel del avianca 81"), "POS AVA81")
  check_eq(ex("avianca 81 virar izquierda rumbo 350"), "HDG AVA81 350 LEFT")
  check_eq(ex("iberia 52 suba nivel 200 y mantenga velocidad 250"), "ALT IBE52 FL200 ; SPD IBE52 250")
  check_eq(ex("iberia 52 mantenga rumbo actual"), "HDG IBE52 200")
  asked(ex("iberia 52 rumbo actual"), "rumbo actual with no verb")
  -- ("urgente", "inmediatamente": Spanish the table does not know)
  asked(ex("iberia 52 vire a la derecha rumbo 250 urgente"), "a Spanish word unknown to the table")
  asked(ex("avianca 81 descienda inmediatamente nivel 100"), "a Spanish word unknown to the table")
  -- (the joining words are English outside a Spanish sentence: "a" stays the article)
  check_eq(ex("iberia 52 descend to flight level 120, a bit quicker please"), "ALT IBE52 FL120")
end

-- Cycle 45 (es102): a new aircraft said with a brand's name takes the brand's airline flying in the scene
-- ("crear latam 4411" with LAN flying is LAN4411)
do
  local _, ex = navscene({ "CRE LAN3095 A320 4.9 -74.4 130 FL200 280", "CRE AVA93 A319 4.5 -74.0 310 FL160 260" },
    "a new aircraft of a brand at a fix")
  if ex then
    check_eq(ex("crear latam 4411 airbus 320 en gavol rumbo 150 nivel 220 280 nudos"),
      "CRE LAN4411 A320 GAVOL 150 FL220 280")
  end
end

-- Cycle 45 (s103a): an airline's IATA designator typed in capitals against a flight number ("QF12") is the
-- aircraft flying under its ICAO prefix with the same characters; anything else is asked, and two letters that
-- squawk reads otherwise (a command, a setting, a type) or that an aircraft flies under are never an airline's
do
  local _, ex = scene({ "CRE QFA12 B789 50.0 8.0 090 FL300 280", "CRE SIA3TK A359 50.2 8.2 270 FL340 280",
    "CRE VIR77 A35K 50.4 8.4 180 FL360 280", "CRE DTA515 B77W 50.6 8.6 090 FL320 280",
    "CRE PGT12 A20N 50.8 8.8 090 FL200 250" })
  check_eq(ex("QF12 descend FL260 for the sequence"), "ALT QFA12 FL260")
  check_eq(ex("SQ3TK turn left heading 240"), "HDG SIA3TK 240 LEFT")
  check_eq(ex("QFA12 climb FL320"), "ALT QFA12 FL320")
  -- (the ICAO designator plus the characters typed flies no aircraft: asked, naming the aircraft one slip away)
  check_eq(ex("QF13 descend FL260"), "ASK Did you mean QFA12? There is no QF13.")
  check_eq(ex("SQ3TX descend FL260"), "ASK Did you mean SIA3TK? There is no SQ3TX.")
  -- (lower case is no IATA designator typed: asked)
  asked(ex("qf12 descend FL260"), "an IATA code in lower case")
  -- (VS is the vertical speed command and DT a registry name: Virgin's and TAAG's codes are never read)
  asked(ex("VS77 climb FL380"), "VS is a command")
  asked(ex("DT515 climb FL340"), "DT is a registry name")
  -- (FL and a type designator stay what they are: "PC12" is the Pilatus, not Pegasus 12)
  check_eq(ex("QF12 FL280"), "ALT QFA12 FL280")
  asked(ex("PC12 climb FL240"), "PC12 is a type")
  -- (the id after a creation verb is the new aircraft's, as typed)
  check_eq(ex("create QF12, a B738 at 51 9 heading 090 FL100 250 knots"), "CRE QF12 B738 51 9 90 FL100 250")
end
do
  -- (an aircraft flying under the two letters themselves: no IATA reading, the near callsigns asked)
  local _, ex = scene({ "CRE QFA12 B789 50.0 8.0 090 FL300 280", "CRE QF13 C172 50.2 8.2 270 5000 110" })
  check_eq(ex("QF12 descend FL260"), "ASK Did you mean QFA12 or QF13? There is no QF12.")
  check_eq(ex("QF13 climb 6000"), "ALT QF13 6000")
end
-- every IATA designator names an airline names.lua knows by its telephony or its name
do
  local names = require("translate.names")
  local known = {}
  for _, a in ipairs(names.airlines) do known[a[2]] = true end
  for _, a in ipairs(names.common) do known[a[2]] = true end
  for code, icao in pairs(names.iata) do
    check(code:match("^%u%u$") ~= nil and known[icao], "names.iata " .. code .. " -> " .. icao)
  end
end

-- Cycle 45 (s103a): a diversion said by airline operations: "divert" with or without "to", "send it to", a large
-- airport's IATA code typed in capitals (names.iata_airports) or a city; three capitals not in that list (or
-- without navdata) are asked; a reason after the comma ("DOH closed", "wx at DFW", "crew sick") is no
-- instruction, condition or place
do
  local s, ex = scene({ "CRE DLH77 A359 50.0 8.0 090 FL350 280", "CRE SWA88 B737 32.8 -97.0 180 FL200 270" })
  -- (three capitals that are no listed airport's code are asked, never guessed; so is any without navdata)
  check_eq(ex("DLH77 divert XQZ"), "ASK Which airport is 'XQZ'? Please give its ICAO code.")
  check_eq(ex("SWA88 send it to ACT"), "ASK Which airport is 'ACT'? Please give its ICAO code.")
  if s:airport_class("EDDH") == "" then
    check_eq(ex("DLH77 divert to HAM"), "ASK Which airport is 'HAM'? Please give its ICAO code.")
  end
end
do
  local _, ex = navscene({ "CRE DLH77 A359 50.0 8.0 090 FL350 280", "CRE UAE9 A388 25.0 55.0 270 FL360 290",
    "CRE SWA88 B737 32.8 -97.0 180 FL200 270" }, "diversions by city and IATA code")
  if ex then
    check_eq(ex("UAE9 divert SHJ"), "DEST UAE9 OMSJ")
    check_eq(ex("DLH77 divert to HAM, pax medical"), "DEST DLH77 EDDH")
    check_eq(ex("send it to HOU, SWA88"), "DEST SWA88 KHOU")
    check_eq(ex("SWA88 send him to AUS instead"), "DEST SWA88 KAUS")
    check_eq(ex("divert SWA88 SAT"), "DEST SWA88 KSAT")
    check_eq(ex("DLH77 destination MUC"), "DEST DLH77 EDDM")
    check_eq(ex("DLH77 divert Cologne"), "DEST DLH77 EDDK")
    check_eq(ex("SWA88 divert to Austin"), "DEST SWA88 KAUS")
    check_eq(ex("DLH77 divert FRA"), "DEST DLH77 EDDF")  -- (the airport, not the FRA VOR)
    -- (a reason after the comma, places in it included, is no second destination nor a condition)
    check_eq(ex("UAE9 divert to AUH, DXB fog"), "DEST UAE9 OMAA")
    check_eq(ex("DLH77 divert to Stuttgart, FRA closed"), "DEST DLH77 EDDS")
    check_eq(ex("SWA88 divert DAL, wx at DFW"), "DEST SWA88 KDAL")
    check_eq(ex("SWA88 divert to IAH, storms over DAL"), "DEST SWA88 KIAH")
    -- (the place alone after the comma names the airport again: no reason; "Louisville" alone is KLOU or KSDF)
    check_eq(ex("SWA88 divert to Louisville, KSDF"), "DEST SWA88 KSDF")
    -- (an instruction, an aircraft or a value after the comma is no reason; a clause opening with "at" or
    -- "after" says where, asked)
    check_eq(ex("DLH77 divert to HAM, descend FL200"), "DEST DLH77 EDDH ; ALT DLH77 FL200")
    asked(ex("DLH77 divert to HAM, FL200"), "a value after the comma")
    asked(ex("DLH77 divert to HAM, at KERAX"), "where the diversion starts")
    asked(ex("DLH77 divert to HAM, after KERAX"), "when the diversion starts")
    -- (a listed code whose airport the navdata lacks, Hamad OTHH: asked)
    asked(ex("DLH77 divert DOH"), "an airport the navdata lacks")
  end
end
-- every IATA airport code is three capitals and names an ICAO code of four
do
  for code, icao in pairs(require("translate.names").iata_airports) do
    check(code:match("^%u%u%u$") ~= nil and icao:match("^%u%u%u%u$") ~= nil, "names.iata_airports " .. code)
  end
end

-- Cycle 45 (hz45): a word of lexicon.heard_as left as it was heard (its neighbours did not fit: "climb FL300
-- niveau") or a name particle outside a name read is no word squawk knows: asked, never set aside (Spanish
-- said whole is read through lexicon.said_whole.spanish)
do
  local _, ex = scene({ "CRE IBE3241 A320 40.6 -3.8 200 FL180 280", "CRE VLG12 A320 40.8 -3.4 160 FL240 290" })
  check_eq(ex("iberia 3241 gire a la derecha rumbo 250"), "HDG IBE3241 250 RIGHT")
  check_eq(ex("IBE3241 climb FL300 niveau"), "ASK I have ALT IBE3241 FL300. What does 'niveau' mean?")
  check_eq(ex("IBE3241 descend FL120 la"), "ASK I have ALT IBE3241 FL120. What does 'la' mean?")
  -- where the neighbours fit, the heard form is read as the word it means
  check_eq(ex("iberia 3241 vire izquierda rumbo 170"), "HDG IBE3241 170 LEFT")
  check_eq(ex("vueling 12 ascienda nivel 300"), "ALT VLG12 FL300")
end

-- Cycle 45 (hz45): two callsigns or values joined by "or" are a choice squawk does not make: asked; a bound after
-- "or" ("or above", "or less") is no choice
do
  local _, ex = scene({ "CRE AMX450 B738 20.0 -99.0 020 FL120 250", "CRE AMX405 B738 20.3 -99.2 200 FL140 250" })
  asked(ex("aeromexico four zero five or four five zero descend fl 100"), "two callsigns said as digits, with 'or'")
  asked(ex("AMX405 or AMX450 turn left heading 300"), "two callsigns typed, with 'or'")
  asked(ex("AMX405 climb FL200 or FL210"), "two levels with 'or'")
  asked(ex("AMX450 turn right heading 060 or 070"), "two headings with 'or'")
  check_eq(ex("AMX450 climb FL200 or above"), "ALT AMX450 FL200")
  check_eq(ex("AMX405 reduce 230 or less"), "SPD AMX405 230")
end

-- Cycle 45 (hz45): a value said after "from", "out of" or "leaving" is the one the aircraft leaves: a command
-- issued with it is asked; with the value it flies to said as well, that one is issued
do
  local _, ex = scene({ "CRE EIN77 A320 53.0 -8.0 090 FL340 280", "CRE RYR9K B738 53.2 -7.5 270 FL200 250" })
  asked(ex("bring Shamrock 77 down from FL340"), "a descent from the level flown, no target")
  asked(ex("RYR9K slow down from 250"), "a speed left, no target")
  asked(ex("RYR9K climb out of FL200"), "a level left, no target")
  check_eq(ex("EIN77 descend from FL340 to FL300"), "ALT EIN77 FL300")
  check_eq(ex("RYR9K reduce from 250 to 220"), "SPD RYR9K 220")
  check_eq(ex("RYR9K turn away from heading 180 left heading 200"), "HDG RYR9K 200 LEFT")
end

-- Cycle 45 (hz45): a number with a decimal fraction is no level: an altitude read from one is asked; a
-- position's degrees, a Mach number and a converted unit stay read
do
  local _, ex = scene({ "CRE TRA7M B738 52.2 3.8 045 FL90 240" })
  asked(ex("take TRA7M down to 61.4"), "a level with a decimal")
  asked(ex("TRA7M descend 45.5"), "a level with a decimal")
  check_eq(ex("drop TRA7M at 52.4 4.1"), "MOVE TRA7M 52.4 4.1")
  check_eq(ex("TRA7M mach 0.74"), "SPD TRA7M M0.74")
end

-- Cycle 45 (hz45): digits after "and" that, with the airline of a callsign said, name another aircraft flying may
-- be that aircraft or a value: asked, whatever was read
do
  local _, ex = scene({ "CRE KLM2156 E190 52.6 5.9 240 FL100 250", "CRE KLM2165 E190 52.8 4.3 150 FL110 250" })
  asked(ex("KLM2156 descend and 2165"), "digits of another KLM after 'and'")
  asked(ex("KLM2156 reduce 220 and 2165"), "digits of another KLM after 'and', a value before")
  check_eq(ex("KLM2156 and 2165 descend FL80"), "ALT KLM2156 FL80 ; ALT KLM2165 FL80")
end

-- Cycle 45 (hz45): "resume the run" opening a request before "and" or a mark starts the clock with the
-- instruction after it; a clock verb no instruction was read from is asked, never set aside
do
  local _, ex = scene({ "CRE BAW41 A320 51.5 0.0 090 FL200 250" })
  check_eq(ex("continue the run and descend BAW41 FL150"), "OP ; ALT BAW41 FL150")
  check_eq(ex("resume the run, then BAW41 reduce 220"), "OP ; SPD BAW41 220")
  check_eq(ex("resume all of it and BAW41 climb FL240"), "ASK I have ALT BAW41 FL240. What does 'resume' mean?")
  asked(ex("restart the run and turn BAW41 left heading 010"), "restart, no command read")
  -- said straight before an instruction of its own, the verb is that instruction's manner
  check_eq(ex("BAW41 resume climb FL240"), "ALT BAW41 FL240")
  check_eq(ex("BAW41 turn left 20 degrees, advise when able to resume"), "HDG BAW41 70 LEFT")
end

-- Cycle 45 (hz45): with exactly one aircraft flying, another airline's callsign said to create an aircraft is the
-- new callsign (the matcher had tied it to the one aircraft)
do
  local _, ex = scene({ "CRE SEH311 A320 36.0 25.0 090 FL200 250" })
  check_eq(ex("create Aegean 718 A321 at 37.5 23.5 heading 180 FL240 270"), "CRE AEE718 A321 37.5 23.5 180 FL240 270")
  check_eq(ex("create Lufthansa 90 B738 at 37.0 24.0 heading 090 FL300 280"), "CRE DLH90 B738 37 24 90 FL300 280")
  asked(ex("Aegean 718 climb FL300"), "no Aegean flying: asked")
end

-- Cycle 45 (hz45): a word speech recognition writes for a digit ("won", "ate") is read only inside a callsign;
-- anywhere else it is asked about
do
  local _, ex = scene({ "CRE DLH123 A320 52.0 4.0 090 FL200 250", "CRE KLM12 B738 52.0 4.6 090 FL200 250" })
  check_eq(ex("KLM12 reduce 240 ate"), "ASK I have SPD KLM12 240. What does 'ate' mean?")
  check_eq(ex("lufthansa won two three climb FL300"), "ALT DLH123 FL300")
end

-- Cycle 45 (hz45): a value, then "or" and an instruction of its own, and a turn "left or right", are choices: asked
do
  local _, ex = scene({ "CRE KLM12 B738 52.0 4.6 090 FL200 250" })
  asked(ex("KLM12 descend FL150 or turn right heading 120"), "a level or a turn")
  asked(ex("KLM12 turn right or left heading 040"), "either side")
  check_eq(ex("KLM12 descend FL150 or below"), "ALT KLM12 FL150")
end

-- Cycle 45 (hz45): "start the run and ..." starts the clock, "stop the run and ..." stops it, with the instruction
do
  local _, ex = scene({ "CRE KLM12 B738 52.0 4.6 090 FL200 250" })
  check_eq(ex("start the run and KLM12 reduce 230"), "OP ; SPD KLM12 230")
  check_eq(ex("stop the run, KLM12 heading 300"), "HOLD ; HDG KLM12 300")
  check_eq(ex("hold the run and KLM12 descend FL120"), "HOLD ; ALT KLM12 FL120")
end

-- Cycle 45 (hz45): digits of another aircraft of the callsign's airline after "then", "also" or a comma are asked
-- as after "and"
do
  local _, ex = scene({ "CRE KLM2156 E190 52.6 5.9 240 FL100 250", "CRE KLM2165 E190 52.8 4.3 150 FL110 250" })
  asked(ex("KLM2156 descend then 2165"), "digits of another KLM after 'then'")
  asked(ex("KLM2156 descend, 2165"), "digits of another KLM after a comma")
  check_eq(ex("KLM2156 descend FL90, KLM2165 FL80"), "ALT KLM2156 FL90 ; ALT KLM2165 FL80")
end

-- Cycle 46 (hz46): a word of an airline's name of several words ("el" of "El Al", "lingus", "royal", "express") or an
-- airline's ICAO prefix said as a word is accounted for only inside the name said whole or beside a callsign of that
-- airline; anywhere else it is asked about, never set aside. A name of one word and the fillers ("a lot") stay read.
do
  local _, ex = scene({ "CRE ELY12 B738 32.0 34.9 090 FL200 250", "CRE EIN55 A320 53.4 -6.3 270 FL220 260",
    "CRE KLM12 B738 52.0 4.6 090 FL200 250" })
  check_eq(ex("KLM12 climb FL300 el"), "ASK I have ALT KLM12 FL300. What does 'el' mean?")
  check_eq(ex("lingus KLM12 climb FL300"), "ASK I have ALT KLM12 FL300. What does 'lingus' mean?")
  asked(ex("KLM12 reduce 230 royal"), "a word of 'Royal Air Maroc' alone")
  asked(ex("KLM12 descend FL150 express"), "a word of an airline's name alone")
  asked(ex("KLM12 descend FL150 aal"), "an ICAO prefix said as a word")
  -- said whole, the name is read; beside a callsign of its airline, a word of its name describes it
  check_eq(ex("El Al one two climb FL300"), "ALT ELY12 FL300")
  check_eq(ex("the Aer Lingus turn left heading 200"), "HDG EIN55 200 LEFT")
  check_eq(ex("Aer Lingus EIN55 turn left heading 200"), "HDG EIN55 200 LEFT")
  check_eq(ex("KLM12 speed it up a lot, 300 knots"), "SPD KLM12 300")
  -- an ocean a position is said over is a region, known apart from "Virgin Atlantic"
  check_eq(ex("create VIR8 A333 over the Pacific at 30N 150W heading 270 FL380 Mach .82"),
    "CRE VIR8 A333 30 -150 270 FL380 M0.82")
  -- an airline said whole that no command carries is asked in lower case too where the name is no English word
  check_eq(ex("KLM12 climb FL300 el al"), "ASK I have ALT KLM12 FL300. What does 'el' mean?")
  check_eq(ex("KLM12 climb FL300 lufthansa"), "ASK I have ALT KLM12 FL300. What does 'lufthansa' mean?")
  check_eq(ex("KLM12 climb FL300, traffic Aer Lingus crossing left to right"), "ALT KLM12 FL300")
end

-- Cycle 46 (hz46): a particle of a place's name straight before the place read ("direct El Palomar") is the name's;
-- alone it is asked
do
  local _, ex = navscene({ "CRE FBZ5120 B738 -34.90 -57.60 290 FL100 250", "ADDWPT FBZ5120 PAL" },
    "a navaid named with its particle")
  if ex then
    check_eq(ex("FBZ5120 proceed direct El Palomar"), "DIRECT FBZ5120 PAL")
    asked(ex("FBZ5120 climb FL120 el"), "a particle alone")
  end
end

-- Cycle 46 (fr101): French said whole is read word for word as its English through the same mechanism as
-- Spanish (lexicon.said_whole.french): verbs in the formal and familiar imperative, sides, "niveau", "cap",
-- "vitesse", units and French number words in a French sentence; a French word the table does not know is asked
do
  local _, ex = scene({ "CRE AFR346 A320 45.5 -73.6 090 FL150 280", "CRE TSC77 A321 46.8 -71.2 200 9000 250" })
  check_eq(ex("AFR346 montez au niveau 210"), "ALT AFR346 FL210")
  check_eq(ex("Air France 346, descendez niveau 090 et réduisez 240"), "ALT AFR346 FL90 ; SPD AFR346 240")
  check_eq(ex("AFR346 virez à droite cap 140"), "HDG AFR346 140 RIGHT")
  check_eq(ex("AFR346 tourne à gauche cap 320"), "HDG AFR346 320 LEFT")
  check_eq(ex("TSC77 vitesse deux cent dix noeuds"), "SPD TSC77 210")
  check_eq(ex("TSC77 descendez 7000 pieds"), "ALT TSC77 7000")
  check_eq(ex("TSC77, prenez le cap 150 à droite"), "HDG TSC77 150 RIGHT")
  check_eq(ex("accélère fois quatre"), "DTMULT 4")
  -- English with one French level word before its value, and a French courtesy
  check_eq(ex("Transat 77 climb to niveau one-two-zero, merci"), "ALT TSC77 FL120")
  check_eq(ex("AFR346 monte FL250"), "ALT AFR346 FL250")
  -- the experimenter in French
  check_eq(ex("pause s'il vous plaît"), "HOLD")
  -- a French word the table does not know is asked, never set aside
  asked(ex("AFR346 montez niveau 210 rapidement"), "an unknown French word")
  asked(ex("AFR346 virez à gauche cap 300 doucement"), "an unknown French word")
  -- outside a French sentence the joining words stay English or are asked
  check_eq(ex("AFR346 climb FL300 et"), "ASK I have ALT AFR346 FL300. What does 'et' mean?")
  -- Spanish said whole is unchanged
  check_eq(ex("TSC77 vire a la izquierda rumbo 170"), "HDG TSC77 170 LEFT")
end

-- Cycle 46 (fr101): Canada's regional airlines by telephony (Pascan, Air Inuit, Calm Air, Perimeter, Air North):
-- read after a verb and described with the aircraft's type; an unknown number of theirs is asked
do
  local _, ex = scene({ "CRE PSC77 PC12 46.8 -71.4 090 8000 200", "CRE AIE55 DH8C 46.9 -71.1 200 FL110 230",
    "CRE CAV9 ATR72 58.7 -94.1 180 FL150 250" })
  check_eq(ex("delete Pascan 77"), "DEL PSC77")
  check_eq(ex("the Air Inuit Dash 8, increase to 250 knots"), "SPD AIE55 250")
  check_eq(ex("calm air nine descend FL100"), "ALT CAV9 FL100")
  check_eq(ex("create Pascan 88, PC-12, at CYQB, heading 120, 6000 feet, 190 knots"), "CRE PSC88 PC12 CYQB 120 6000 190")
  asked(ex("Pascan 78 descend 5000"), "a Pascan flight not flying")
end

-- Cycle 46 (fr101): "show me IDENT" with no traffic: an ident the navdata holds is shown where it is; one it does
-- not hold is asked
do
  local _, ex = navscene({}, "idents shown with no traffic")
  if ex then
    check_eq(ex("show me EHAM"), "POS EHAM")
    check_eq(ex("show SPY"), "POS SPY")
    asked(ex("show me QQXZV"), "an ident the navdata does not hold")
  end
end

-- Cycle 46 (fr101): "back to real time, speed one": one after "speed" beside real time, no aircraft named, is the
-- clock's rate; another number there is asked
do
  local _, ex = scene({ "CRE KLM12 B738 52.0 4.6 090 FL200 250", "CRE KLM14 B738 52.2 4.8 090 FL220 250" })
  check_eq(ex("ok back to real time now, speed one"), "DTMULT 1")
  check_eq(ex("real time again, speed 1"), "DTMULT 1")
  asked(ex("back to real time, speed 240"), "a speed beside real time with no aircraft")
end

-- Cycle 46 (fr101): a flight number said in hundreds after the airline ("four hundred twelve", "four-hundred-
-- twelve", "six hundred and five") is its three digits when exactly one aircraft flying is so named; else asked
do
  local _, ex = scene({ "CRE ACA412 A320 45.6 -73.3 250 FL110 280", "CRE ACA605 A320 45.9 -73.6 250 FL130 280",
    "CRE JZA731 DH8D 45.3 -74.1 060 8000 220" })
  check_eq(ex("Air Canada four-hundred-twelve, you turn left heading 200"), "HDG ACA412 200 LEFT")
  check_eq(ex("Air Canada six hundred and five climb FL150"), "ALT ACA605 FL150")
  check_eq(ex("Jazz seven hundred thirty-one descend 5000"), "ALT JZA731 5000")
  asked(ex("Air Canada four hundred thirteen, turn left heading 200"), "a flight number in hundreds no aircraft has")
  asked(ex("ACA412 descend four hundred twelve"), "hundreds that are no flight number")
end

-- Cycle 46 (fr101): "report the field in sight" after an instruction is a sighting the pilot reports, set aside to
-- the end of its clause; an instruction after it is read; alone it is asked
do
  local _, ex = scene({ "CRE PSC77 PC12 46.8 -71.4 090 8000 200", "CRE PSC78 PC12 46.9 -71.5 090 9000 200" })
  check_eq(ex("PSC77 descend 3000, report the runway in sight"), "ALT PSC77 3000")
  check_eq(ex("PSC77 turn right heading 120, report traffic in sight"), "HDG PSC77 120 RIGHT")
  check_eq(ex("PSC77 descend 3000, report the field in sight, then turn left heading 200"),
    "ALT PSC77 3000 ; HDG PSC77 200 LEFT")
  asked(ex("PSC77 report the field in sight"), "a sighting alone")
end

-- Cycle 46 (s100): a protocol's step label opening the text ("Step 7:", "Step 1b:", "step 4 -", "7:", "Step 7" before
-- an instruction) is set apart whole at any number and never gives a value; "step 5 seconds" stays the time step
do
  local _, ex = scene({ "CRE AC001 B744 52.0 4.0 090 FL300 300" })
  check_eq(ex("Step 9: set the time multiplier to 3"), "DTMULT 3")
  check_eq(ex("Step 3b: AC001 descend FL200"), "ALT AC001 FL200")
  check_eq(ex("step 5 - AC001 turn left heading 250"), "HDG AC001 250 LEFT")
  check_eq(ex("8: set the lookahead to 240 s"), "DTLOOK 240")
  check_eq(ex("Step 6 set the time multiplier to 2"), "DTMULT 2")
  check_eq(ex("Step 4: AC001 reduce speed 250 Step 5: AC001 descend FL250"), "SPD AC001 250 ; ALT AC001 FL250")
  check(not ex("step 5 seconds"):find("DTMULT", 1, true), "a time step is no label")
end

-- Cycle 46 (s100): "run" ending the text after another instruction ("... and run", "... then run it") starts the
-- clock (OP); with a rate after it, "and run at 4x", it stays the rate's
do
  local _, ex = scene({ "CRE AC001 B744 52.0 4.0 090 FL300 300" })
  check_eq(ex("set the time multiplier to 6 and run"), "DTMULT 6 ; OP")
  check_eq(ex("AC001 climb FL340 then run it"), "ALT AC001 FL340 ; OP")
  check_eq(ex("lookahead 240 s and then run the simulation"), "DTLOOK 240 ; OP")
  check(not ex("set the time multiplier to 6 and run at 3x"):find("OP", 1, true), "a rate after 'run' is no start")
end

-- Cycle 46 (s100): "at speed N" after the callsign and before an instruction is a condition on reaching that speed
-- (ATSPD), never an order to fly it; with "and" or "then" between, it is asked
do
  local _, ex = scene({ "CRE AC001 B744 52.0 4.0 090 FL300 300" })
  check_eq(ex("AC001 at speed 270 climb FL340"), "ATSPD AC001 270 ALT AC001 FL340")
  check_eq(ex("AC001 at speed 280 knots, turn right heading 120"), "ATSPD AC001 280 HDG AC001 120 RIGHT")
  check_eq(ex("AC001 at 260 knots descend FL240"), "ATSPD AC001 260 ALT AC001 FL240")
  check_eq(ex("AC001 at mach .8 climb FL340"), "ATSPD AC001 M0.8 ALT AC001 FL340")
  asked(ex("AC001 at 260 knots then descend FL240"), "'then' between the speed and the instruction")
  asked(ex("AC001 at speed 270 and climb FL340"), "'and' between the speed and the instruction")
  check_eq(ex("AC001 at speed 270"), "SPD AC001 270")
  check_eq(ex("AC001 climb FL340 at speed 270"), "ALT AC001 FL340 ; SPD AC001 270")
end

-- Cycle 46 (s100): a researcher's notation: "CAS" after a speed (squawk's speeds are calibrated), "HPZ" the
-- protected zone's half height, "verify <aircraft> state", "what's <aircraft>'s current FL" (POS)
do
  local _, ex = scene({ "CRE AC001 B744 52.0 4.0 090 FL300 300" })
  check_eq(ex("AC001 speed 280 kts CAS"), "SPD AC001 280")
  check_eq(ex("set HPZ to 1500 ft"), "ZONEDH 1500")
  check_eq(ex("verify AC001 state (alt, spd, hdg)"), "POS AC001")
  check_eq(ex("what's AC001's current FL?"), "POS AC001")
  check_eq(ex("what is the present FL of AC001"), "POS AC001")
  asked(ex("what FL should AC001 get"), "an FL asked for with no 'current'")
end

-- Cycle 46 (s100): a researcher's symbols and labels: "t_lookahead = 480 s", "R_pz = 9.26 km" (a letter or two and a
-- subscript before a value: the setting named); "CR: MVP" (the letters as a label); a remark naming a phase of the
-- flight ("for the cruise segment") after a setting
do
  local _, ex = scene({ "CRE AC001 B744 52.0 4.0 090 FL300 300" })
  check_eq(ex("t_lookahead = 360 s"), "DTLOOK 360")
  check_eq(ex("R_pz = 5 nm"), "ZONER 5")
  check_eq(ex("CR: MVP"), "RESO MVP")
  check_eq(ex("dtmult 10 for the climb phase"), "DTMULT 10")
  asked(ex("x_foo = 300"), "a symbol naming no setting")
  asked(ex("dtmult 10 for the climb FL200"), "an instruction in the remark")
end

-- Cycle 46 (s100): "at t=N s" / "at time N s" opening or closing an instruction is the simulation's time
-- (SCHEDULE); a bare number after "t=" with no unit stays asked
do
  local _, ex = scene({ "CRE AC001 B744 52.0 4.0 090 FL300 300" })
  check_eq(ex("at t=90 s, AC001 turn left heading 200"), "SCHEDULE 00:01:30 HDG AC001 200 LEFT")
  check_eq(ex("at t = 3 min AC001 descend FL250"), "SCHEDULE 00:03:00 ALT AC001 FL250")
  check_eq(ex("AC001 turn left heading 200 at time 240 s"), "SCHEDULE 00:04:00 HDG AC001 200 LEFT")
  asked(ex("at t=90 AC001 descend FL250"), "a time with no unit")
end

-- Cycle 46 (s100): a level in kilometres straight after "climb (to)" or "descend (to)" is that many metres; a
-- distance in kilometres elsewhere is no level
do
  local _, ex = scene({ "CRE AC001 B744 52.0 4.0 090 FL300 300" })
  check_eq(ex("AC001 climb to 11 km"), "ALT AC001 36089")
  check_eq(ex("AC001 descend to 8.5 km"), "ALT AC001 27887")
  -- (a distance no command carries is asked, never read as a level nor dropped)
  check_eq(ex("AC001 descend to FL250 within 10 km"), "ASK I have ALT AC001 FL250. What does '10 km' mean?")
  asked(ex("AC001 descend to 60 km"), "no level is 60 km")
end

-- Cycle 46 (s100): the protected zone's whole height said "total" is twice ZONEDH's half; "±N ft" is the half itself;
-- two halves that differ are asked
do
  local _, ex = scene({ "CRE AC001 B744 52.0 4.0 090 FL300 300" })
  check_eq(ex("PZ height 1600 ft total"), "ZONEDH 800")
  check_eq(ex("PZ height ±900 ft"), "ZONEDH 900")
  check_eq(ex("PZ height 3000 ft total (±1500 ft)"), "ZONEDH 1500")
  asked(ex("PZ height 3000 ft total (±1000 ft)"), "two halves that differ")
end

-- Cycle 46 (s100): "configure" frames settings as "set" does; alone it is asked
do
  local _, ex = scene({ "CRE AC001 B744 52.0 4.0 090 FL300 300" })
  check_eq(ex("configure the lookahead to 240 s and RPZ 4 nm"), "DTLOOK 240 ; ZONER 4")
  asked(ex("AC001 configure"), "no setting named")
end

-- Cycle 46 (s100): a label naming a conflict before the command's name typed with its values ("conflict pair:
-- CRECONFS ...") sets up that one conflict
do
  local _, ex = scene({ "CRE AC001 B744 52.0 4.0 090 FL300 300" })
  check_eq(ex("conflict pair: CRECONFS INT4 B738 on AC001, 45 deg, CPA 1, 240 s"), "CRECONFS INT4 B738 AC001 45 1 240")
  asked(ex("conflict pair: CRECONFS on AC001, 45 deg, CPA 1, 240 s"), "no intruder named")
end

-- Cycle 46 (hz47): an instruction word left with no value beside a complete instruction ("climb FL300 reduce",
-- "turn KLM12 climb FL300"), one said straight after the value that changes the other way ("climb FL300 descend",
-- "... down") or stops the run ("... stop"), or a turn's side after a value that is no heading ("... left") is
-- asked, naming what was issued; words that belong to the instruction read stay read.
do
  local _, ex = scene({ "CRE KLM12 B738 52.0 4.6 090 FL200 250" })
  check_eq(ex("KLM12 climb FL300 reduce"),
    "ASK I have ALT KLM12 FL300. What speed should KLM12 fly? Please give knots or a Mach number.")
  check_eq(ex("KLM12 descend FL150 turn"), "ASK I have ALT KLM12 FL150. What heading should KLM12 fly?")
  asked(ex("slow down KLM12 climb FL300"), "a speed change with no value before the instruction")
  asked(ex("KLM12 climb FL300 heading"), "a value name with no value")
  check_eq(ex("KLM12 climb FL300 descend"), "ASK I have ALT KLM12 FL300. What does 'descend' mean?")
  asked(ex("KLM12 climb FL300 down"), "a change the other way after the value")
  check_eq(ex("KLM12 climb FL300 left"), "ASK I have ALT KLM12 FL300. What does 'left' mean?")
  asked(ex("KLM12 reduce 230 stop"), "a stop after a speed")
  asked(ex("KLM12 speed 240 climb"), "a climb with no level after a speed")
  -- the words of the instruction read, and a rate said with no value as its manner
  check_eq(ex("KLM12 climb and maintain FL300"), "ALT KLM12 FL300")
  check_eq(ex("KLM12 climb FL300 then maintain"), "ALT KLM12 FL300")
  check_eq(ex("KLM12 speed 240, maintain"), "SPD KLM12 240")
  check_eq(ex("KLM12 turn right heading 120"), "HDG KLM12 120 RIGHT")
  check_eq(ex("KLM12 increase speed 280"), "SPD KLM12 280")
  check_eq(ex("KLM12 descend now FL150"), "ALT KLM12 FL150")
  check_eq(ex("KLM12 descend FL150, expedite"), "ALT KLM12 FL150")
  check_eq(ex("KLM12 turn left heading 200, expedite"), "HDG KLM12 200 LEFT")
  check_eq(ex("KLM12 vertical speed 1500 feet per minute down"), "VS KLM12 -1500")
  check_eq(ex("KLM12 climb FL300, no speed restriction"), "ALT KLM12 FL300")
  check_eq(ex("KLM12 say altitude"), "POS KLM12")
  check_eq(ex("KLM12 climb FL300 and reduce speed 240"), "ALT KLM12 FL300 ; SPD KLM12 240")
  check_eq(ex("KLM12 increase the heading by 20"), "HDG KLM12 110 RIGHT")
  check_eq(ex("KLM12 turn left heading 050, standby for descent"), "HDG KLM12 50 LEFT")
  check_eq(ex("KLM12 turn left heading 050, don't descend"), "ASK I have HDG KLM12 50 LEFT. What does 'don't' mean?")
end

-- Cycle 46 (hz48): a bare number after "at" or "at time" before the instruction is asked, with its "at", never
-- dropped; with a unit it is read (a time: SCHEDULE; a speed: ATSPD)
do
  local _, ex = scene({ "CRE AC001 B744 52.0 4.0 090 FL300 300", "CRE AC002 A320 52.3 4.3 180 FL280 280" })
  check_eq(ex("at 90 AC001 turn left heading 200"), "ASK I have HDG AC001 200 LEFT. What does 'at 90' mean?")
  check_eq(ex("at time 300 AC002 climb FL320"), "ASK I have ALT AC002 FL320. What does 'at time 300' mean?")
  check_eq(ex("AC002 at 270 climb FL320"), "ASK I have ALT AC002 FL320. What does 'at 270' mean?")
  asked(ex("at 7 AC001 descend FL250"), "a single digit after at")
  check_eq(ex("at 90 seconds AC001 turn left heading 200"), "SCHEDULE 00:01:30 HDG AC001 200 LEFT")
  check_eq(ex("AC002 at 330, climb FL320"), "ASK I have ALT AC002 FL320. What does 'at 330' mean?")
end

-- Cycle 46 (hz48): a speed after "at" opening the request, the aircraft said after it, is a condition on reaching
-- that speed (ATSPD), as after the callsign; the condition ends at the speed
do
  local _, ex = scene({ "CRE AC001 B744 52.0 4.0 090 FL300 300", "CRE AC002 A320 52.3 4.3 180 FL280 280" })
  check_eq(ex("at 260 knots AC002 descend FL240"), "ATSPD AC002 260 ALT AC002 FL240")
  check_eq(ex("at speed 280, AC001 turn right heading 120"), "ATSPD AC001 280 HDG AC001 120 RIGHT")
  check_eq(ex("at mach .80 AC001 climb FL340"), "ATSPD AC001 M0.8 ALT AC001 FL340")
  check_eq(ex("AC002 at 260 knots descend FL240, then turn left heading 150"),
    "ATSPD AC002 260 ALT AC002 FL240 ; ATSPD AC002 260 HDG AC002 150 LEFT")
  asked(ex("at speed 280 then AC001 turn right heading 120"), "flown now or a condition")
  asked(ex("at 260 knots AC002 descend FL240 and AC001 climb FL320"), "the condition's aircraft only")
end

-- Cycle 46 (hz48): the clock's rate is the value after the instruction word, never a bare number after "at"
-- before it; two rates for the one clock are asked
do
  local _, ex = scene({})
  check_eq(ex("at 600 dtmult 3"), "ASK I have DTMULT 3. What does 'at 600' mean?")
  check_eq(ex("dtmult 6 and run at 2x"), "ASK Which rate should the simulation run at: 6 or 2 times real time?")
  asked(ex("set the multiplier to 5 and then 10 times"), "two rates")
  check_eq(ex("run the sim at 3x"), "DTMULT 3")
  check_eq(ex("dtmult 5, dtmult 5"), "DTMULT 5")
end

-- Cycle 46 (hz48): a rate ("3x") no command carries is asked, never dropped
do
  local _, ex = scene({ "CRE AC001 B744 52.0 4.0 090 FL300 300" })
  check_eq(ex("run the sim at 3x and AC001 descend FL250"), "ASK I have ALT AC001 FL250. What does '3 x' mean?")
  asked(ex("at 3x AC001 descend FL250"), "a rate opening the request")
  check_eq(ex("run at 3x, AC001 descend FL250"), "DTMULT 3 ; ALT AC001 FL250")
end

-- Cycle 46 (hz48): a value said loosely after "at" ("at about 120", "at around 260 knots") is read as the value said
do
  local _, ex = scene({ "CRE AC001 B744 52.0 4.0 090 FL300 300", "CRE AC002 A320 52.3 4.3 180 FL280 280" })
  check_eq(ex("at around 90 AC001 turn left heading 200"),
    "ASK I have HDG AC001 200 LEFT. What does 'at around 90' mean?")
  check_eq(ex("at about 260 knots AC002 descend FL240"), "ATSPD AC002 260 ALT AC002 FL240")
  check_eq(ex("AC002 at roughly 260 knots descend FL240"), "ATSPD AC002 260 ALT AC002 FL240")
  check_eq(ex("@ 90 AC001 turn left heading 200"), "ASK I have HDG AC001 200 LEFT. What does 'at 90' mean?")
end

-- Cycle 46 (hz48): a second rate said in words ("twice") is a second rate too; one after a time said waits for it
do
  local _, ex = scene({})
  check_eq(ex("time acceleration 6 and run it at twice real time"),
    "ASK Which rate should the simulation run at: 6 or 2 times real time?")
  check_eq(ex("dtmult 3 and run at triple speed"), "DTMULT 3")
  asked(ex("dtmult 6, and in 90 seconds dtmult 1"), "a rate after a time is no second rate now")
end

-- Cycle 46 (lead): a moment named by its unit before the number ("at minute 5", "at second 30") is no time
-- squawk reads: asked with its "at", never dropped; "at 5 minutes" is the schedule
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250", "CRE BAW1 B738 52.2 4.2 270 FL220 250" })
  asked(ex("at minute 5 KLM12 descend FL150"), "a minute named before its number")
  asked(ex("at second 30 KLM12 descend FL150"), "a second named before its number")
  check_eq(ex("at 5 minutes KLM12 descend FL150"), "SCHEDULE 00:05:00 ALT KLM12 FL150")
end

-- Cycle 47 (hz49): an instruction word said bare beside value instructions (alone in its clause: after the value
-- or the callsign, before the next instruction) is accounted for: what squawk does not simulate is named beside the
-- instruction flown, a word whose value is a place asks for the place, a word that may change what is flown is
-- asked; straight before an instruction word it is that instruction's manner, and said with its own words it is read
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 90 FL250 280", "CRE DLH4AX A321 52.4 4.4 090 FL300 280" })
  -- not simulated: the note beside the instruction
  local sim2 = scene({ "CRE KLM12 B738 52 4 90 FL250 280" })
  local function tr2(text) return graph.translate(text, { sim = sim2, mode = "offline" }) end
  for text, what in pairs({ ["KLM12 descend FL200 then hold"] = "holding patterns ('hold')",
      ["KLM12 turn right heading 140, report"] = "position reports ('report')",
      ["KLM12 reduce speed 240 and squawk"] = "transponder codes ('squawk')",
      ["KLM12 heading 120 vectors"] = "radar vectors ('vectors')",
      ["KLM12 descend FL120, approach"] = "approach clearances ('approach')" }) do
    local r = tr2(text)
    check(r.ask == nil and #r.commands == 1 and r.note and r.note:find(what, 1, true) ~= nil, text)
  end
  -- a place missing, a meaning asked
  check_eq(ex("KLM12 descend FL200 and cross"),
    "ASK I have ALT KLM12 FL200. Which place goes with 'cross'? Please say it with the place.")
  check_eq(ex("KLM12 turn left heading 300, then join"),
    "ASK I have HDG KLM12 300 LEFT. Which place goes with 'join'? Please say it with the place.")
  check_eq(ex("KLM12 speed 250 then establish"), "ASK I have SPD KLM12 250. What does 'establish' mean?")
  check_eq(ex("KLM12 climb FL320 cleared"), "ASK I have ALT KLM12 FL320. What does 'cleared' mean?")
  check_eq(ex("KLM12 descend FL150 then stop"), "ASK I have ALT KLM12 FL150. What does 'stop' mean?")
  check_eq(ex("hold KLM12 descend FL150"), "ASK I have ALT KLM12 FL150. What does 'hold' mean?")
  asked(ex("KLM12 tower, descend FL150"), "a station named bare before the instruction")
  asked(ex("KLM12 descend FL150 and DLH4AX climb FL340 then enter"), "a word of meaning after two instructions")
  -- read: the instruction's manner, a phrase of its own, a filler
  check_eq(ex("KLM12 continue climb FL300"), "ALT KLM12 FL300")
  check_eq(ex("KLM12 descend FL200 stop descent"), "ALT KLM12 FL200")
  check_eq(ex("KLM12 climb FL300, squawk 1234"), "ALT KLM12 FL300")
  check_eq(ex("KLM12 climb FL300 then maintain"), "ALT KLM12 FL300")
  check_eq(ex("KLM12 climb FL300 please, thanks"), "ALT KLM12 FL300")
  check_eq(ex("Approach, KLM12 climb FL300"), "ALT KLM12 FL300")
  check_eq(ex("fast forward 2 minutes then hold"), "FF 120 ; HOLD")
  check_eq(ex("vector KLM12 left heading 200"), "HDG KLM12 200 LEFT")
end

-- Cycle 47 (hz49): one setting given two values as a sequence ("dtmult 8, and then 4x") is asked: which value, and
-- from when; a fast-forward between them is the time, and the same value twice is one
do
  local _, ex = scene({})
  check_eq(ex("dtmult 6, and then 3x"), "ASK I have DTMULT 6 ; DTMULT 3. Which rate should the simulation run at: 6 or "
    .. "3, and from when? Please say the time of the second (\"in 5 minutes\") or one value.")
  asked(ex("run the sim at 10x then 2x"), "two rates in a row")
  asked(ex("zoner 4 then zoner 6"), "two radii in a row")
  check_eq(ex("dtmult 6, ff 120, dtmult 2"), "DTMULT 6 ; FF 120 ; DTMULT 2")
  check_eq(ex("dtmult 4, then dtmult 4"), "DTMULT 4")
end

-- Cycle 47 (hz49): a level's figures split by a space after "FL" or "flight level" are one level when they join into
-- three figures, with or without a verb; a level of one or two figures under FL20 is asked, never issued
do
  local _, ex = scene({ "CRE KLM77 B738 52.1 4.5 180 FL090 250" })
  check_eq(ex("KLM77 fl 1 30"), "ALT KLM77 FL130")
  check_eq(ex("KLM77 climb flight level 2 10"), "ALT KLM77 FL210")
  check_eq(ex("KLM77 climb FL 2 6 0"), "ALT KLM77 FL260")
  check_eq(ex("KLM77 fl 1 3"), "ASK Which level should KLM77 fly? 'FL13' is 1300 ft, and a flight level has three "
    .. "figures: please say it again.")
  asked(ex("KLM77 descend FL 7"), "a level of one figure")
  asked(ex("KLM77 fl 1 20 knots"), "a unit after the figures keeps them apart")
  check_eq(ex("KLM77 descend FL80"), "ALT KLM77 FL80")
end

-- Cycle 47 (hz49): a bare number straight after "fly", said to one aircraft, is asked as a heading or a level,
-- naming both; with its unit or value name it is read
do
  local _, ex = scene({ "CRE QTR1015 B77W 52.3 4.2 270 FL200 280" })
  check_eq(ex("QTR1015 fly 120"), "ASK Should QTR1015 fly heading 120 or flight level 120? Please say which.")
  check_eq(ex("QTR1015 please fly 080"), "ASK Should QTR1015 fly heading 080 or flight level 080? Please say which.")
  asked(ex("QTR1015 fly 390"), "above 360 no heading")
  check_eq(ex("QTR1015 fly heading 120"), "HDG QTR1015 120")
  check_eq(ex("QTR1015 fly FL120"), "ALT QTR1015 FL120")
end

-- Cycle 47 (f107): a speed or level held "until" a place the aircraft's route does not pass, or until a distance
-- from a place, is asked (ATDIST would start it there); a bound said with it ("or more") changes nothing
do
  local _, ex = navscene({ "CRE SWR41 A320 50.6 7.4 110 FL150 300", "ADDWPT SWR41 TAU",
    "CRE CFG7 A321 50.3 10.2 270 FL230 290", "ADDWPT CFG7 KERAX" }, "limits that end at a place")
  if ex then
    asked(ex("SWR41 maintain two six zero knots or more until KERAX"), "a limit at a place off the route")
    asked(ex("SWR41 keep FL150 till KERAX"), "a level's limit at a place off the route")
    check_eq(ex("SWR41 keep speed 260 knots or greater till TAU"), "SPD SWR41 260")
    check_eq(ex("CFG7 maintain 270 knots or more until KERAX"), "SPD CFG7 270")
    asked(ex("SWR41 maintain two six zero knots until 25 miles from FFM"), "a limit at a distance from a place")
    asked(ex("SWR41 until 25 miles from TAU maintain FL160"), "a limit at a distance said first")
    check_eq(ex("SWR41 speed 270 until 12 miles from TAU, then reduce 230"),
      "SPD SWR41 270 ; ATDIST SWR41 TAU 12 SPD SWR41 230")
    check_eq(ex("SWR41 when 25 miles from TAU reduce 240"), "ATDIST SWR41 TAU 25 SPD SWR41 240")
    -- (a distance the limit lasts, "for the next 15 miles", is asked by name too)
    check_eq(ex("SWR41 keep 280 knots or more for the next 15 miles"), "ASK I have SPD SWR41 280. What does '15 miles' mean?")
    asked(ex("SWR41 turn right heading 160 for eight miles"), "a heading flown for a distance")
    -- ("hold" and a value straight after it keeps the value; "hold at TAU" is still the holding pattern)
    check_eq(ex("SWR41 hold two five zero knots"), "SPD SWR41 250")
    check_eq(ex("SWR41 hold FL150"), "ALT SWR41 FL150")
    check_eq(ex("SWR41 hold at TAU"), "")
  end
end

-- Cycle 47 (f107): a distance or waypoint condition measured from a place said by a name that an airport and
-- several navaids near the aircraft bear ("Frankfurt": EDDF; FFM, FW, FR, FRD) is asked, naming them; a code
-- stays exact, and the navaid the route holds is the one meant
do
  local _, ex = navscene({ "CRE SWR41 A320 50.6 7.4 110 FL150 300", "ADDWPT SWR41 TAU",
    "CRE CFG7 A321 50.3 9.4 270 FL230 290", "ADDWPT CFG7 FFM" }, "a place by a name several places bear")
  if ex then
    local q = ex("SWR41 when forty miles from Frankfurt descend FL90")
    check(q:find("EDDF", 1, true) ~= nil and q:find("FFM", 1, true) ~= nil, q)
    asked(ex("SWR41 slow to 230 knots 25 miles from Frankfurt"), "a distance from a name several places bear")
    check_eq(ex("SWR41 40 miles from FFM descend FL90"), "ATDIST SWR41 FFM 40 ALT SWR41 FL90")
    check_eq(ex("SWR41 40 miles from EDDF descend FL90"), "ATDIST SWR41 EDDF 40 ALT SWR41 FL90")
    check_eq(ex("CFG7 twenty miles from Frankfurt reduce 240"), "ATDIST CFG7 FFM 20 SPD CFG7 240")
  end
end

-- Cycle 47 (f107): a waypoint condition opened by "leave" (a heading after it) or "reaching", in any clause, the
-- fix said by its code or a navaid's name ("Taunus" for TAU), is AT ... DO when the fix is on the route; asked
-- otherwise, and after "leaving" with no heading
do
  local _, ex = navscene({ "CRE SWR41 A320 50.6 7.4 110 FL150 300", "ADDWPT SWR41 TAU",
    "CRE EXS12 B738 51.3 0.3 270 FL120 280", "ADDWPT EXS12 BIG" }, "waypoint conditions by name")
  if ex then
    check_eq(ex("EXS12 reduce 230 knots, leave BIG heading 250"), "SPD EXS12 230 ; AT EXS12 BIG DO HDG EXS12 250")
    check_eq(ex("EXS12 descend FL90 and leave BIG heading 300"), "ALT EXS12 FL90 ; AT EXS12 BIG DO HDG EXS12 300")
    check_eq(ex("SWR41 reaching Taunus slow to 220"), "AT SWR41 TAU DO SPD SWR41 220")
    check_eq(ex("SWR41 reaching TAU descend flight level one two zero"), "AT SWR41 TAU DO ALT SWR41 FL120")
    check_eq(ex("SWR41 descend FL120, reaching Taunus reduce 200"), "ALT SWR41 FL120 ; AT SWR41 TAU DO SPD SWR41 200")
    check_eq(ex("SWR41 speed 240, after Taunus speed 210 knots"), "SPD SWR41 240 ; AT SWR41 TAU DO SPD SWR41 210")
    asked(ex("SWR41 leaving Taunus reduce 200"), "after leaving, only a heading is flown from the place")
    asked(ex("EXS12 reduce 230 knots, leave OCK heading 250"), "a fix off the route")
    asked(ex("SWR41 reaching KERAX reduce 200"), "a fix off the route")
  end
end

-- Cycle 47 (f107): a speed or level said with no verb that a correction takes back ("Mach .72, correction, 260
-- knots") gives way to the value of its kind after the correction; "when level" is the level cleared, also after
-- another instruction of the kind that waits; "no restriction on speed" beside instructions is set aside
do
  local _, ex = scene({ "CRE TAP44 A320 52 4 090 FL120 280", "CRE VLG9 A321 52.2 4.3 180 FL200 290" })
  check_eq(ex("TAP44 descend FL90 then mach point seven two, correction, two six zero knots"),
    "ALT TAP44 FL90 ; SPD TAP44 260")
  check_eq(ex("TAP44 turn left heading 200, 250 knots, correction, 230 knots"), "HDG TAP44 200 LEFT ; SPD TAP44 230")
  check_eq(ex("VLG9 descend FL150, speed 260, once level reduce 240"),
    "ALT VLG9 FL150 ; SPD VLG9 260 ; ATALT VLG9 FL150 SPD VLG9 240")
  check_eq(ex("VLG9 descend FL150 reduce 260 and when you're level reduce 240"),
    "ALT VLG9 FL150 ; SPD VLG9 260 ; ATALT VLG9 FL150 SPD VLG9 240")
  asked(ex("VLG9 speed 260, when level reduce 240"), "no level cleared for 'when level'")
  check_eq(ex("TAP44 descend FL90, no restrictions on your speed"), "ALT TAP44 FL90")
  check_eq(ex("TAP44 descend FL90, no restriction on speed, then turn right heading 100"),
    "ALT TAP44 FL90 ; HDG TAP44 100 RIGHT")
  asked(ex("TAP44 reduce 250, descend FL90, no restriction on speed"), "a speed given and lifted")
  asked(ex("TAP44 no restriction on speed"), "nothing simulated said")
end

-- Cycle 47 (f107): "thereafter" or "after that" straight after a crossing ("cross LAM FL110, thereafter descend
-- FL80") starts the next instruction at the crossing's waypoint (AT ... DO); "then" keeps its reading
do
  local _, ex = navscene({ "CRE BEL5 A320 51.5 0.8 260 FL130 290", "ADDWPT BEL5 LAM" }, "crossings then thereafter")
  if ex then
    check_eq(ex("BEL5 cross LAM flight level one two zero, thereafter descend when ready FL90"),
      "AT BEL5 LAM ALT FL120 ; AT BEL5 LAM DO ALT BEL5 FL90")
    check_eq(ex("BEL5 cross LAM at 250 knots, after that slow to 220"), "AT BEL5 LAM SPD 250 ; AT BEL5 LAM DO SPD BEL5 220")
    check_eq(ex("BEL5 cross LAM at FL120, then descend FL90"), "AT BEL5 LAM ALT FL120 ; ALT BEL5 FL90")
    asked(ex("BEL5 cross LAM at FL120, thereafter descend FL90 and reduce 220"), "the speed now or after LAM")
    asked(ex("BEL5 cross BIG FL120, thereafter descend FL90"), "a crossing off the route")
  end
end

-- Cycle 47 (f107): an aircraft described by its family ("the E-jet") or by a Boeing 7x7's or an Airbus A3xx's first
-- two digits said in words after "the" ("the seven three": B73x) is read when exactly one flying fits, asked
-- otherwise
do
  local _, ex = scene({ "CRE SAS12 E195 55.6 12.6 180 FL110 250", "CRE NAX3 B738 55.8 12.2 090 FL150 270",
    "CRE TAP7 A332 55.2 12.9 330 FL230 290", "CRE AEE9 A320 55.4 12.1 010 FL190 280", "CRE VOE1 A320 55.3 12.4 200 FL170 280" })
  check_eq(ex("where is the ejet"), "POS SAS12")
  check_eq(ex("the E-jet, descend FL90"), "ALT SAS12 FL90")
  check_eq(ex("the seven three, turn left heading 050"), "HDG NAX3 50 LEFT")
  check_eq(ex("the three three, climb FL250"), "ALT TAP7 FL250")
  asked(ex("the three twenty, reduce 240"), "two A320s")
  asked(ex("the seven seven, reduce 240"), "no 777 flying")
  -- (an ERJ is given the name too: with an ERJ 145 and an E175 flying, "the E-jet" is asked)
  local _, ex2 = scene({ "CRE KLM7 E145 52 4 090 FL150 250", "CRE WIF2 E75L 52.3 4.2 270 FL170 260" })
  asked(ex2("the E-jet, slow to 240"), "two Embraer jets")
end

-- Cycle 47 (f105): German words in a German-speaking controller's English (lexicon.said_whole.german): the
-- verbs, "bitte", "weiter", "neues Flugzeug", "zwo" and cities by their German names; a German word not in the
-- table is still asked about
do
  local _, ex = scene({ "CRE DLH7RM A320 48.5 11.0 090 FL200 280", "CRE AUA55 E195 48.1 16.0 270 FL120 250" })
  check_eq(ex("DLH7RM sinken Sie auf flight level one seven zero bitte"), "ALT DLH7RM FL170")
  check_eq(ex("AUA55 steigen flight level zwo vier null"), "ALT AUA55 FL240")
  check_eq(ex("DLH7RM descend flight level one zwo zero, danke"), "ALT DLH7RM FL120")
  check_eq(ex("AUA55 drehen Sie rechts heading zwo acht null"), "HDG AUA55 280 RIGHT")
  check_eq(ex("weiter"), "OP")
  check_eq(ex("neues Flugzeug DLH8 A320 at 48.2 11.5 heading 180 FL150 speed 250"), "CRE DLH8 A320 48.2 11.5 180 FL150 250")
  check_eq(ex("DLH7RM sinken flight level one seven zero schnell"),
    "ASK I have ALT DLH7RM FL170. What does 'schnell' mean?")
  asked(ex("AUA55 steigen"), "a German verb with no level")
  local nav, nex = navscene({ "CRE DLH7RM A320 48.5 11.0 090 FL200 280", "CRE AUA55 E195 48.1 16.0 270 FL120 250",
    "CRE SWR9 A320 46.6 6.6 200 FL110 250" },
    "German city names")
  if nav then
    check_eq(nex("AUA55 destination Wien"), "DEST AUA55 LOWW")
    check_eq(nex("DLH7RM destination München bitte"), "DEST DLH7RM EDDM")
    check_eq(nex("SWR9 destination genf"), "DEST SWR9 LSGG")
  end
end

-- Cycle 47 (f105): a callsign's words run together or split apart by a recogniser ("edelweissthree two",
-- "euro wings"): read only when exactly one aircraft flying fits every word, matched exactly
do
  local _, ex = scene({ "CRE EDW32 A320 47.3 8.5 090 FL200 280", "CRE EWG7XR A319 48.2 11.5 270 FL150 250",
    "CRE EWG7X A319 48.6 11.9 090 FL170 250" })
  check_eq(ex("edelweissthree two climb flight level two four zero"), "ALT EDW32 FL240")
  check_eq(ex("eurowings sevenxray romeo reduce speed two two zero"), "SPD EWG7XR 220")
  check_eq(ex("edel weiss three two turn left heading one two zero"), "HDG EDW32 120 LEFT")
  asked(ex("edelweissthree three climb flight level two four zero"), "no aircraft EDW33")
  check_eq(ex("eurowingsseven xray climb flight level two four zero"), "ALT EWG7X FL240")
  asked(ex("eurowingsseven climb flight level two four zero"), "no aircraft EWG7")
end

-- Cycle 47 (f105): a fix's name in lower case after "add waypoint", "add the fix", "where is": the place's slot goes
-- on over the noun naming it; a name the navdata lacks near the traffic is still asked
do
  local nav, ex = navscene({ "CRE CFG9 B738 49.9 8.2 180 FL200 280" }, "fixes named in lower case")
  if nav then
    check_eq(ex("condor nine add waypoint rosig"), "ADDWPT CFG9 ROSIG")
    check_eq(ex("condor nine add the fix rosig then rolsa"), "ADDWPT CFG9 ROSIG ; ADDWPT CFG9 ROLSA")
    check_eq(ex("where is rolsa"), "POS ROLSA")
    check_eq(ex("where's rosig"), "POS ROSIG")
    asked(ex("condor nine add waypoint qqxzv"), "no such fix")
    asked(ex("where is qqxzv"), "no such fix")
  end
end

-- Cycle 47 (f105): an aircraft described by its maker (the CSeries is a Bombardier too) or by its designator said in
-- words after "the" ("the a three twenty one", "the b seven eight nine"): read when exactly one aircraft fits
do
  local _, ex = scene({ "CRE SWR77X BCS1 47.3 8.5 090 FL200 280", "CRE DLH2AB A321 48.2 11.5 270 FL150 250",
    "CRE DLH3CD A320 48.6 11.9 090 FL170 250", "CRE EZY41 A320 48.1 11.2 090 FL130 250", "CRE UAL90 B789 48.0 11.0 090 FL330 280" })
  check_eq(ex("the bombardier turn left heading two two zero"), "HDG SWR77X 220 LEFT")
  check_eq(ex("the a three twenty one climb flight level two one zero"), "ALT DLH2AB FL210")
  check_eq(ex("the b seven eight nine reduce speed two five zero"), "SPD UAL90 250")
  check_eq(ex("the a three twenty turn right heading three zero zero"),
    "ASK Which a three twenty do you mean: DLH3CD or EZY41? Please give its callsign.")
  asked(ex("the a climb flight level two one zero"), "a designator's letter alone")
end

-- Cycle 47 (f105): a rate in metres per minute said with "with" or "at" after climb or descend is the vertical
-- speed in ft/min; said bare after the verb it is still asked (a level or a rate?)
do
  local _, ex = scene({ "CRE AUA71 A320 48.1 16.0 270 FL200 250" })
  check_eq(ex("AUA71 descend with 600 metres per minute"), "VS AUA71 -1969")
  check_eq(ex("AUA71 climb at eight hundred meters per minute"), "VS AUA71 2625")
  asked(ex("AUA71 descend 600 metres per minute"), "metres per minute after the verb alone")
end

-- Cycle 47 (f105): a speaker's role opening the line without its colon ("instructor run") is the label
do
  local _, ex = scene({ "CRE AUA71 A320 48.1 16.0 270 FL200 250" })
  check_eq(ex("instructor run"), "OP")
  check_eq(ex("supervisor AUA71 descend flight level one eight zero"), "ALT AUA71 FL180")
  asked(ex("instructor"), "a label alone")
end

-- Cycle 47 (f106): instructor commentary after a complete instruction, no instruction of its own: the same action
-- described again (", give her a decent climb" after a climb) and the speaker's own intention after a condition
-- (", then once past X we'll turn him back") are set aside; a clause that could instruct is asked
do
  local _, ex = scene({ "CRE AB101 A320 52.0 4.0 090 FL280 280", "CRE CD202 B738 52.3 4.4 270 FL300 280",
    "CRE EF303 A321 51.8 4.2 360 FL260 260" })
  check_eq(ex("AB101 left forty degrees, give her a good vector away"), "HDG AB101 50 LEFT")
  check_eq(ex("CD202 climb FL340, give him a decent climb"), "ALT CD202 FL340")
  check_eq(ex("AB101 turn right thirty, then once clear of CD202 we'll bring her back"), "HDG AB101 120 RIGHT")
  check_eq(ex("AB101 turn right thirty, when well past CD202 I will put her back on the route"), "HDG AB101 120 RIGHT")
  check_eq(ex("let's give EF303 a tiny nudge left, ten degrees"), "HDG EF303 350 LEFT")
  -- (a noun of another kind than the instruction's, a value, another aircraft, a second verb of instruction)
  asked(ex("CD202 climb FL340, give him a vector off"), "a turn described after a climb")
  asked(ex("AB101 turn right thirty, then once clear of CD202 I'll climb her to FL320"), "a value in the intention")
  asked(ex("AB101 turn right thirty, then once clear of CD202 we'll bring EF303 back"), "another aircraft")
  asked(ex("AB101 turn right thirty, then once clear of CD202 turn her back"), "an instruction after a condition")
end

-- Cycle 47 (f106): two aircraft shown together ("show me both of them, X and Y", "X and Y are converging, show me
-- the both of them") and "what's X at": each aircraft's position (POS); "both" with three named is asked
do
  local _, ex = scene({ "CRE AB101 A320 52.0 4.0 090 FL280 280", "CRE CD202 B738 52.3 4.4 270 FL300 280",
    "CRE EF303 A321 51.8 4.2 360 FL260 260" })
  check_eq(ex("display both of them, CD202 and EF303"), "POS CD202 ; POS EF303")
  check_eq(ex("AB101 and EF303 are converging, show me the both of them"), "POS AB101 ; POS EF303")
  check_eq(ex("show us them, AB101 and CD202"), "POS AB101 ; POS CD202")
  check_eq(ex("what is CD202 at now?"), "POS CD202")
  asked(ex("AB101, CD202 and EF303, show me both of them"), "both said of three")
end

-- Cycle 47 (f106): the clock and the resolver in a class's words: "play" and "go" said over again start the clock
-- (OP); "the resolver" is the conflict resolution (RESO); a route resumed after CPA, no aircraft named, is how
-- aircraft resume after a resolution (RESNAV PASTCPA); one aircraft's return after CPA is asked
do
  local _, ex = scene({ "CRE AB101 A320 52.0 4.0 090 FL280 280", "CRE CD202 B738 52.3 4.4 270 FL300 280" })
  check_eq(ex("ok, play"), "OP")
  check_eq(ex("AB101 descend FL240, play"), "ALT AB101 FL240 ; OP")
  check_eq(ex("go, go, go!"), "OP")
  check_eq(ex("put the resolver on please"), "RESO MVP")
  check_eq(ex("once they're past the CPA put them back on course"), "RESNAV PASTCPA")
  check_eq(ex("after CPA let them resume their routes"), "RESNAV PASTCPA")
  asked(ex("AB101 go go go"), "an aircraft told to go")
  asked(ex("after AB101 passes CPA put it back on its route"), "one aircraft's return after CPA")
end

-- Cycle 47 (f106): a new aircraft's fields in any order with no verb, its callsign named as such ("..., callsign
-- X, type, at lat lon"), is the creation; a field said again after a correction ("northbound... no wait
-- southbound", "heading 100, sorry, 280") replaces the one before it; a correction between fields of different
-- kinds is asked
do
  local _, ex = scene({ "CRE AB101 A320 52.0 4.0 090 FL280 280" })
  check_eq(ex("heading 135, 240 knots, FL250, callsign NEW42, B738, at 51.5 3.5"), "CRE NEW42 B738 51.5 3.5 135 FL250 240")
  check_eq(ex("heading 010 FL200 callsign NEW43 E190 position 52.5 3.9 250 knots"), "CRE NEW43 E190 52.5 3.9 10 FL200 250")
  check_eq(ex("create NEW44 A321 at 51.9 3.8, northbound... no wait southbound, FL300, 280 knots"),
    "CRE NEW44 A321 51.9 3.8 180 FL300 280")
  check_eq(ex("create NEW45 A321 at 51.9 3.8, heading 100, sorry, 280, FL300, 280 knots"),
    "CRE NEW45 A321 51.9 3.8 280 FL300 280")
  asked(ex("create NEW46 A321 at 51.9 3.8, heading 100, FL300 no wait 280 knots"), "a correction between kinds")
  asked(ex("FL310, heading 090, callsign NEW47, at 51.5 3.5"), "no type said")
  asked(ex("AB101 FL310, heading 090, callsign NEW48, A319, at 51.5 3.5"), "an aircraft flying named")
end

-- Cycle 47 (f106): a rate said as the most to fly ("but not above 1500 feet a minute", "not exceeding 2000 fpm") is
-- the vertical speed the level carries; "not above" a level or a speed is asked. A wind's position, then its
-- direction and speed as a wind is reported ("wind 52.5 3.1 250 at 35"), is WIND
do
  local _, ex = scene({ "CRE AB101 A320 52.0 4.0 090 FL280 280" })
  check_eq(ex("AB101 climb FL350 but not above 1200 feet a minute"), "ALT AB101 FL350 1200")
  check_eq(ex("AB101 descend FL200, not exceeding 2500 fpm"), "ALT AB101 FL200 2500")
  asked(ex("AB101 climb FL350 but not above FL330"), "not above a level")
  asked(ex("AB101 climb FL350 but not above 260 knots"), "not above a speed")
  check_eq(ex("wind 52.5 3.1 250 at 35"), "WIND 52.5 3.1 250 35")
  check_eq(ex("wind at 52.5 3.1, 250 at 35 knots"), "WIND 52.5 3.1 250 35")
  asked(ex("wind 52.5 3.1 250 at 350 knots"), "a wind too strong to be one")
end

-- Cycle 47 (f106): a heading said after a turn's degrees in the same instruction ("left 40 degrees then 300") is a
-- second heading, asked; one that the turn reaches ("left 40 degrees to 050") restates it
do
  local _, ex = scene({ "CRE AB101 A320 52.0 4.0 090 FL280 280" })
  check_eq(ex("AB101 left 40 degrees to 050"), "HDG AB101 50 LEFT")
  asked(ex("AB101 left 40 degrees then 300"), "a second heading after the turn")
  asked(ex("AB101 turn right 20 degrees, to 200"), "a heading the turn does not reach")
  -- ("vector to N": a heading, never a place the vector leads to, set aside)
  asked(ex("AB101 left 40, give her a vector to 300"), "a second heading after 'vector to'")
  check_eq(ex("AB101 turn left heading 030, vectors to 030"), "HDG AB101 30 LEFT")
end

-- Cycle 47 (f104): terse command words chained with commas, one aircraft named: a later clause naming none takes it
-- (read whole as English); with none or several named, or a deletion in the list, such a clause is asked
do
  local _, ex = scene({ "CRE AC101 A320 52.0 4.0 090 FL300 280", "CRE AC202 B738 52.3 4.3 180 FL200 250",
    "DEFWPT WP1 52.2 4.5" })
  check_eq(ex("alt ac101 fl280, spd 250, hdg 120"), "ALT AC101 FL280 ; SPD AC101 250 ; HDG AC101 120")
  check_eq(ex("vs of ac202 to -1000, alt fl150 and dct wp1"),
    "VS AC202 -1000 ; ALT AC202 FL150 ; ADDWPT AC202 WP1 ; DIRECT AC202 WP1")
  check_eq(ex("spd ac202 240, hdg 100"), "SPD AC202 240 ; HDG AC202 100")
  -- (a condition's carried command after "then" or "and" takes the condition's aircraft, as typed without it)
  check_eq(ex("atalt ac101 fl280 then spd 240"), "ATALT ac101 fl280 spd ac101 240")
  check_eq(ex("atspd ac202 230 and alt fl120"), "ATSPD ac202 230 alt ac202 fl120")
  check_eq(ex("alt ac101 fl280, spd ac202 240, hdg 100"), "ASK Which aircraft is 'hdg 100' for? Please give its callsign.")
  check_eq(ex("del ac101, spd 250"), "ASK Which aircraft is 'spd 250' for? Please give its callsign.")
  check_eq(ex("move ac101 52.1 4.1, hdg 100"), "MOVE AC101 52.1 4.1 30000 100")
  check_eq(ex("cre ac303 a320 52.5 4.5 090 fl200 250, hold, spd ac101 250, hdg 100"),
    "ASK Which aircraft is 'hdg 100' for? Please give its callsign.")
  asked(ex("hold, spd 250"), "no aircraft named in the list")
  check_eq(ex("seed 7, mcre 20, ff 10 min"), "SEED 7 ; MCRE 20 ; FF 600")
end

-- Cycle 47 (f104): a place's name said beside its code is accounted for when it is the navdata's name of that code
-- (a navaid's, an airport's or words of it, its city), in any case; another name is asked; "the hlz vor" in lower
-- case is the navaid of that ident near the traffic
do
  local _, ex = navscene({ "CRE AC301 A320 52.5 9.5 090 FL200 280", "CRE AC302 C172 52.3 10.4 300 3000 100" },
    "a place's name beside its code")
  if ex then
    check_eq(ex("ac301 dct nienburg, NIE"), "ADDWPT AC301 NIE ; DIRECT AC301 NIE")
    check_eq(ex("ac301 direct NIE nienburg"), "ADDWPT AC301 NIE ; DIRECT AC301 NIE")
    check_eq(ex("ac302 heads to wolfsburg EDVE"), "DEST AC302 EDVE")
    check_eq(ex("ac302 dest EDDH, hamburg"), "DEST AC302 EDDH")
    check_eq(ex("where's the hlz vor"), "POS HLZ")
    check_eq(ex("ac301 direct to celle NIE"),
      "ASK I have ADDWPT AC301 NIE ; DIRECT AC301 NIE. What does 'celle' mean?")
    asked(ex("ac302 is going to bremen EDVE"), "a name of another airport than the code's")
  end
end

-- Cycle 47 (f104): field phrasing of route commands ("orig of X is eddh", "X goes to eddv"), a wind typed in
-- TrafScript's order after its position, a fix made with its name in lower case
do
  local _, ex = scene({ "CRE AC101 A320 52.0 4.0 090 FL300 280" })
  check_eq(ex("wind at 51.9 4.1, 090 15"), "WIND 51.9 4.1 90 15")
  check_eq(ex("wind at 51.9 4.1, 090 at 15"), "WIND 51.9 4.1 90 15")
  asked(ex("wind at 51.9 4.1, 15 090"), "a speed before the direction is no wind typed")
  asked(ex("wind at 51.9 4.1, 090 15 and ac101 climb fl310"), "a wind typed must end the request")
  check_eq(ex("make a fix rotte at 51.95, 4.4"), "DEFWPT ROTTE 51.95 4.4")
  check_eq(ex("make a fix here at 51.95, 4.4"), "ASK What should the waypoint be called, and where is it?")
end
do
  local _, ex = navscene({ "CRE AC301 A320 52.5 9.5 090 FL200 280", "CRE AC302 C172 52.3 10.4 300 3000 100" },
    "airport codes typed in lower case")
  if ex then
    check_eq(ex("orig of ac301 is eddh"), "ORIG AC301 EDDH")
    check_eq(ex("ac302's orig is edve"), "ORIG AC302 EDVE")
    check_eq(ex("ac302 goes to eddv"), "DEST AC302 EDDV")
    asked(ex("ac302 goes to home"), "no airport after 'goes to'")
  end
end

-- Cycle 47 (f104): self-corrections and trailing comments: "just the <kind>" closing the request after a pause keeps
-- the commands of that kind; said with more after it, it is asked; a place named after dest/orig, then a correction
-- and another place, is the corrected one
do
  local _, ex = scene({ "CRE AC101 A320 52.0 4.0 090 FL300 280", "CRE AC202 B738 52.3 4.3 180 FL200 250",
    "DEFWPT WP1 52.2 4.5" })
  check_eq(ex("hdg ac101 to 200, then dct wp1 when abeam, uh just the hdg for now"), "HDG AC101 200")
  check_eq(ex("ac101 fl280 and spd 250, just the spd"), "SPD AC101 250")
  check_eq(ex("alt ac202 fl150, spd 220, um only the alt"), "ALT AC202 FL150")
  check_eq(ex("ac101 fl280 and spd 250, just the spd for now, and hdg 100"),
    "ASK What stands after 'just the spd for now'? Please say the instruction again in full.")
end
do
  local _, ex = navscene({ "CRE AC301 A320 52.5 9.5 090 FL200 280", "CRE AC302 C172 52.3 10.4 300 3000 100" },
    "a destination corrected by name")
  if ex then
    check_eq(ex("ac302 dest bremen? no hamburg"), "DEST AC302 EDDH")
    check_eq(ex("ac302 orig hannover, sorry, EDVE"), "ORIG AC302 EDVE")
    asked(ex("ac302 dest bremen? no hamburg and fl300"), "a correction with more after it")
  end
end

-- Cycle 47 (f104): short German and Dutch asides of acknowledgement are accounted for alone in their clause; after
-- a value ("hdg 180 ist gut") they say the value is kept (the hz50 block below): a value the aircraft does not fly
-- is asked
do
  local _, ex = scene({ "CRE AC101 A320 52.0 4.0 090 FL300 280" })
  check_eq(ex("alles klar, ac101 descend fl250"), "ALT AC101 FL250")
  check_eq(ex("ac101 descend fl250, ist gut"), "ALT AC101 FL250")
  check_eq(ex("prima. ac101 hdg 120"), "HDG AC101 120")
  check_eq(ex("ac101 spd 250, is goed"), "SPD AC101 250")
  check_eq(ex("ac101, hdg 120 ist gut, just descend fl250"),
    "ASK 'heading 120 ist gut': AC101 does not fly 120 now. Should it be given 120, or keep what it flies?")
  check_eq(ex("ac101, hdg 090 ist gut, just descend fl250"), "ALT AC101 FL250")
  asked(ex("ac101 descend fl250 gut"), "an aside straight after a value")
end

-- Cycle 47 (hz50): a value said to be kept ("FL330 is fine", "speed 260 is ok", "keep FL330, just ...") beside
-- another instruction is no instruction when it is what the aircraft flies; another value there is asked
do
  local _, ex = scene({ "CRE AC010 A320 51.0 3.0 045 FL330 260", "CRE AC011 B738 51.2 3.3 200 FL250 280" })
  check_eq(ex("AC010 FL330 is good, just turn right heading 070"), "HDG AC010 70 RIGHT")
  check_eq(ex("AC010, speed 260 is ok, descend FL300"), "ALT AC010 FL300")
  check_eq(ex("AC010 descend FL300, two six zero knots is fine"), "ALT AC010 FL300")
  check_eq(ex("AC010 heading 045 looks alright, reduce speed 240"), "SPD AC010 240")
  check_eq(ex("AC010 flight level three three zero stays, speed 240"), "SPD AC010 240")
  check_eq(ex("AC010 FL330 ist gut, nur heading 070"), "HDG AC010 70")
  check_eq(ex("AC010 keep FL330, only speed 240"), "SPD AC010 240")
  check_eq(ex("AC010 should keep it at FL330 but slow down to 240 knots"), "SPD AC010 240")
  check_eq(ex("AC010 leave FL330 as it is, turn right heading 070"), "HDG AC010 70 RIGHT")
  check_eq(ex("AC010 heading 045 and FL330 are good, speed 240"), "SPD AC010 240")
  check_eq(ex("AC010 FL330 okay, AC011 FL250 okay, AC010 speed 240"), "SPD AC010 240")
  check_eq(ex("AC010 FL330 is all right, speed 240"), "SPD AC010 240")
  -- (the callsign said for the kept value alone is no part of the next aircraft's instruction)
  check_eq(ex("AC010 FL330 is fine, AC011 heading 150"), "HDG AC011 150")
  -- the value is not what it flies, or no aircraft holds it: asked, never issued
  asked(ex("AC010 FL310 is fine, just turn right heading 070"), "a level it does not fly said to be fine")
  asked(ex("AC010 keep 250 knots, only heading 070"), "a speed it does not fly said to be kept")
  asked(ex("FL330 is fine, just heading 070"), "a value kept by no aircraft named")
  -- an instruction's own value and "keep" with no "just" stay instructions
  check_eq(ex("AC010 descend FL300 okay"), "ALT AC010 FL300")
  check_eq(ex("AC010 keep 260 knots and descend FL300"), "SPD AC010 260 ; ALT AC010 FL300")
end

-- Cycle 47 (hz50): fast time "until" an event is asked (FF runs for a time, or with no end until the speaker
-- stops it)
do
  local _, ex = scene({ "CRE AC010 A320 51.0 3.0 045 FL330 260", "CRE AC011 B738 51.2 3.3 200 FL330 280" })
  asked(ex("fast forward till the two of them get close"), "fast time until an event")
  asked(ex("ff until the CPA"), "fast time until the closest point")
  asked(ex("skip ahead until something happens, then hold"), "fast time until something happens")
  asked(ex("run it fast until the conflict shows up"), "fast time until a conflict")
  check_eq(ex("fast forward until I tell you to stop"), "FF")
  check_eq(ex("ff till further notice"), "FF")
  check_eq(ex("fast forward 4 minutes"), "FF 240")
end

-- Cycle 47 (hz50): a latitude and longitude said digit by digit with a decimal mark each and nothing between
-- them: read when every way the digits between the marks split gives the same position, else asked naming them
do
  local _, ex = scene({ "CRE AC010 A320 51.0 3.0 045 FL330 260" })
  check_eq(ex("move AC010 to five one decimal two zero six decimal four"), "MOVE AC010 51.2 6.4")
  check_eq(ex("move AC010 to five one point two zero zero six point four"), "MOVE AC010 51.2 6.4")
  check_eq(ex("move AC010 to five one decimal two six decimal four"), "MOVE AC010 51.2 6.4")
  local q = ex("move AC010 to five one decimal two four one two decimal five")
  check(q:find("'two four one two'", 1, true) ~= nil and q:find("51.24 12.5 or 51.241 2.5", 1, true) ~= nil, q)
  asked(ex("define waypoint WPX at four nine point three one three point one"), "49.3 13.1 or 49.31 3.1")
  -- the other ways a position is said still read
  check_eq(ex("move AC010 to five one decimal two four, one two decimal five"), "MOVE AC010 51.24 12.5")
  check_eq(ex("move AC010 to five one decimal two four north zero one two decimal five east"), "MOVE AC010 51.24 12.5")
  check_eq(ex("move AC010 to fifty one point two four twelve point five"), "MOVE AC010 51.24 12.5")
  check_eq(ex("move AC010 to 51.24 12.5"), "MOVE AC010 51.24 12.5")
  check_eq(ex("AC010 mach point seven eight"), "SPD AC010 M0.78")
end

-- Cycle 47 (hz50): an airline said alone whose name is also a word (or a word's start or end) of another flying
-- aircraft's airline name fits both: asked
do
  local _, ex = scene({ "CRE SWR120 A320 46.4 6.5 220 FL110 250", "CRE EZS77AB A320 46.5 5.7 140 FL130 270",
    "CRE AFR22 A319 45.9 6.3 350 FL090 240" })
  check_eq(ex("turn the Swiss right heading 300"), "ASK Which Swiss: SWR120 or EZS77AB?")
  asked(ex("Swiss, climb flight level 150"), "Swiss alone with TOPSWISS flying")
  check_eq(ex("the topswiss climb flight level 150"), "ALT EZS77AB FL150")
  check_eq(ex("Swiss one two zero climb FL150"), "ALT SWR120 FL150")
  check_eq(ex("the Air France descend FL080"), "ALT AFR22 FL80")
  local _, ex2 = scene({ "CRE SWR120 A320 46.4 6.5 220 FL110 250", "CRE SUI4 C130 46.5 5.7 140 FL130 270" })
  asked(ex2("the swiss descend FL090"), "Swiss with a Swiss Air Force aircraft flying")
end

-- Cycle 47 (g108): "cancel that" (or "cancel" before a comma) straight after a value takes it back as a
-- self-correction: the instruction after it stands when it is of the same kind ("maintain" going by its value);
-- of another kind, or with nothing after it, it is asked
do
  local _, ex = scene({ "CRE AC1 A320 52 4 090 FL250 280", "CRE AC2 B738 52.5 4.5 180 FL300 M.78" })
  check_eq(ex("AC1 reduce speed 230 knots, cancel that, maintain 260 knots"), "SPD AC1 260")
  check_eq(ex("AC1 descend flight level one two zero cancel that descend flight level one four zero"), "ALT AC1 FL140")
  check_eq(ex("AC1 fly heading 200 cancel that, fly heading 220"), "HDG AC1 220")
  check_eq(ex("AC2 mach .80, cancel, mach .76"), "SPD AC2 M0.76")
  check_eq(ex("AC1 climb FL270 cancel that, FL290"), "ALT AC1 FL290")
  -- ("maintain" goes by its value: a speed after a level is another kind)
  asked(ex("AC1 climb FL300, cancel that, maintain 250 knots"), "a speed after a level taken back")
  asked(ex("AC1 climb FL300, cancel that, reduce 250 knots"), "another kind after cancel that")
  asked(ex("AC1 descend FL200, cancel that"), "cancel that with nothing after it")
  asked(ex("AC1 reduce 240 knots cancel that speed"), "cancel that speed: what is cancelled")
  -- ("cancel" with no value before it is no correction)
  check_eq(ex("AC1 descend FL200, cancel your route"), "ALT AC1 FL200 ; DELRTE AC1")
end

-- Cycle 47 (g108): "delete <name>" with the name of a navaid the one aircraft named holds on its route, ending
-- the request or its clause, is that waypoint deleted (DELWPT), never the aircraft; a name off its route, or a
-- list of names, is asked
do
  local _, ex = navscene({ "CRE KLM77 B738 55.8 -2.0 270 FL300 280", "ADDWPT KLM77 NEW", "ADDWPT KLM77 TLA",
    "ADDWPT KLM77 DCS" }, "a navaid's name on the route deleted")
  if ex then
    check_eq(ex("KLM77 delete Newcastle"), "DELWPT KLM77 NEW")
    check_eq(ex("KLM77 remove Dean Cross, descend FL280"), "DELWPT KLM77 DCS ; ALT KLM77 FL280")
    check_eq(ex("KLM77 delete Talla please"), "DELWPT KLM77 TLA")
    asked(ex("KLM77 delete Perth"), "a navaid's name off the route")
    asked(ex("KLM77 delete Talla and Perth"), "two names, one off the route")
    check_eq(ex("delete KLM77"), "DEL KLM77")
  end
end

-- Cycle 47 (g108): a level condition said after the instruction it governs ("reduce 260 knots passing FL240") and
-- a condition's instruction followed, after a comma, by another ("when passing FL260 reduce 270 knots, turn right
-- heading 220"): the condition holds its own instruction only; with "and"/"then" after the comma it is asked
do
  local _, ex = scene({ "CRE AC1 A320 52 4 090 FL250 280", "CRE AC2 B738 52.5 4.5 180 FL300 M.78" })
  check_eq(ex("AC2 descend FL180, reduce 260 knots passing FL240"), "ALT AC2 FL180 ; ATALT AC2 FL240 SPD AC2 260")
  check_eq(ex("AC2 descend FL180, turn left heading 150 reaching FL260"),
    "ALT AC2 FL180 ; ATALT AC2 FL260 HDG AC2 150 LEFT")
  check_eq(ex("AC2 when passing FL260 reduce 270 knots, turn right heading 220"),
    "ATALT AC2 FL260 SPD AC2 270 ; HDG AC2 220 RIGHT")
  check_eq(ex("AC1 on passing FL200 reduce 250 knots, descend FL150"), "ATALT AC1 FL200 SPD AC1 250 ; ALT AC1 FL150")
  -- (the condition before a comma still holds everything after it)
  check_eq(ex("AC1 when passing FL200, reduce 250 knots, turn left heading 060"),
    "ATALT AC1 FL200 SPD AC1 250 ; ATALT AC1 FL200 HDG AC1 60 LEFT")
  asked(ex("AC2 when passing FL260 reduce 270 knots, then descend FL200"), "then after a condition's instruction")
  asked(ex("AC2 when passing FL260 reduce 270 knots, and turn right heading 220"), "and after a condition's instruction")
end

-- Cycle 47 (g108): route editing by place names: "put <navaid's name> in the route" adds it; "move X to <Fix>"
-- (a fix's name written as a proper name, near the aircraft) moves it there; a list of names one of which squawk
-- cannot place is asked about that name; a word that names no place near is asked
do
  local _, ex = navscene({ "CRE EIN77 A320 53.6 -5.0 090 FL90 250", "ADDWPT EIN77 DUB",
    "CRE BEE12 DH8D 53.3 -2.8 270 FL80 220", "ADDWPT BEE12 POL" }, "route editing by place names")
  if ex then
    check_eq(ex("BEE12 put Wallasey in the route"), "ADDWPT BEE12 WAL")
    check_eq(ex("BEE12 put Wallasey into its route please"), "ADDWPT BEE12 WAL")
    check_eq(ex("move EIN77 to Boyne"), "MOVE EIN77 BOYNE")
    check_eq(ex("move EIN77 to Boyne at FL120"), "MOVE EIN77 BOYNE FL120")
    asked(ex("move EIN77 to Nowhere"), "a proper name that names no fix near")
    local q = ex("BEE12 add Talla and Sumin to the route")
    check(q:find("'Talla'", 1, true) ~= nil and q:find("ADDWPT BEE12 SUMIN", 1, true) ~= nil, q)
  end
end

-- Cycle 47 (hz52): a navigation switch typed by its TrafScript name in a terse line ("lnav on", "vnav off") is an
-- instruction said: kept beside a direct-to (which turns LNAV on too); a level, speed or heading with its own unit
-- after the switch is an instruction of its own; a bare number there is asked. "resume own navigation direct X",
-- said in words, stays the direct-to alone.
do
  local _, ex = scene({ "CRE KLM12 A320 52.0 4.0 090 FL250 280", "DEFWPT TOPAX 52.1 4.6", "ADDWPT KLM12 TOPAX" })
  check_eq(ex("klm12 lnav on, dct topax"), "LNAV KLM12 ON ; DIRECT KLM12 TOPAX")
  check_eq(ex("lnav klm12 on and then direct topax"), "LNAV KLM12 ON ; DIRECT KLM12 TOPAX")
  check_eq(ex("klm12 resume own navigation direct topax"), "DIRECT KLM12 TOPAX")
  check_eq(ex("klm12 vnav off fl180"), "VNAV KLM12 OFF ; ALT KLM12 FL180")
  check_eq(ex("vnav klm12 on, spd 250"), "VNAV KLM12 ON ; SPD KLM12 250")
  check_eq(ex("klm12 lnav off, hdg 120, fl200"), "LNAV KLM12 OFF ; HDG KLM12 120 ; ALT KLM12 FL200")
  asked(ex("klm12 lnav off 9000"), "a bare number after a navigation switch")
end

-- Cycle 47 (hz52): a distance said in kilometres is its conversion to 0.01 NM (9 km = 4.86 NM, not the tenth 4.9);
-- a protected zone radius said in metres is converted the same; one in feet, or a half height said as a
-- distance, is asked
do
  local _, ex = scene({ "CRE KLM12 A320 52.0 4.0 090 FL250 280" })
  check_eq(ex("zoner 7 km"), "ZONER 3.78")
  check_eq(ex("protected zone radius 11 kilometres"), "ZONER 5.94")
  check_eq(ex("zoner 10 km"), "ZONER 5.4")
  check_eq(ex("pz radius 6500 m"), "ZONER 3.51")
  check_eq(ex("zonedh 300 m"), "ZONEDH 984")
  asked(ex("zoner 3000 ft"), "a zone radius in feet")
  asked(ex("zonedh 0.5 km"), "a zone half height as a distance")
end

-- Cycle 47 (hz52): a place's name that navaids bear, beside a large or medium airport the navdata names otherwise
-- (Lille: the LL NDB, LFQQ "LESQUIN"), is asked the same for every command that takes a place (GETWIND, MOVE,
-- CRE at, DIRECT), with or without an aircraft sent there; a code stays exact
do
  local _, ex = navscene({ "CRE AFR12 A321 50.4 3.3 330 FL210 270" }, "a place a navaid and an airport share")
  if ex then
    local q = ex("getwind at Lille")
    check(q:match("^ASK") and q:find("LFQQ", 1, true) and q:find("LL", 1, true), q)
    asked(ex("what's the wind over lille"), "a wind at a shared place name")
    asked(ex("move AFR12 to Lille"), "a move to a shared place name")
    asked(ex("AFR12 direct Lille"), "a direct-to a shared place name")
    check_eq(ex("getwind at LFQQ"), "GETWIND LFQQ")
    check_eq(ex("getwind at Frankfurt"), "GETWIND EDDF")
  end
end

-- Cycle 47 (hz51): one setting given two values in a row in a list of typed command clauses is asked, as in English;
-- a fast-forward between them makes them one after the other
do
  local _, ex = scene({ "CRE AC101 A320 52.0 4.0 090 FL300 280" })
  asked(ex("dtmult 6, then dtmult 2"), "two rates typed in a row")
  asked(ex("ZONER 4 ; ZONER 6"), "two zone radii typed in a row")
  check_eq(ex("dtmult 6, ff 120, dtmult 2"), "DTMULT 6 ; FF 120 ; DTMULT 2")
  check_eq(ex("dtmult 6, ALT AC101 FL320"), "DTMULT 6 ; ALT AC101 FL320")
end

-- Cycle 47 (hz51): "resume"/"continue" closing a request after an aircraft's instruction most likely tells the aircraft
-- to resume something: asked, naming it; the simulation named, or no aircraft instructed, stays OP
do
  local _, ex = scene({ "CRE AC101 A320 52.0 4.0 090 FL300 280" })
  check_eq(ex("ac101 reduce 240 and then resume"), "ASK I have SPD AC101 240. Should AC101 resume something of its "
    .. "own (its navigation, its normal speed), or the simulation resume? Please say which.")
  asked(ex("ac101 heading 200, then continue please"), "continue after a heading")
  check_eq(ex("ac101 reduce 240, then resume the simulation"), "SPD AC101 240 ; OP")
  check_eq(ex("pause, then resume"), "HOLD ; OP")
  check_eq(ex("ac101 reduce 240 then run"), "SPD AC101 240 ; OP")
  check_eq(ex("pause, ac101 reduce 240, then resume"), "HOLD ; SPD AC101 240 ; OP")
  check_eq(ex("remove ac101 and continue"), "DEL AC101 ; OP")
end

-- Cycle 47 (hz51): a verb of showing after an instruction is never dropped: the aircraft named alone after it are
-- shown (POS); "both", "them" or anything else no command was read from is asked
do
  local _, ex = scene({ "CRE AC101 A320 52.0 4.0 090 FL300 280", "CRE AC202 B738 52.3 4.3 180 FL200 250" })
  asked(ex("ac101 descend fl260, show me both"), "both after an instruction naming one aircraft")
  asked(ex("ac202 heading 050 and let me see them"), "them after an instruction")
  check_eq(ex("ac101 descend fl260 then display ac202"), "ALT AC101 FL260 ; POS AC202")
  check_eq(ex("ac101 descend fl260 then show me ac101 and ac202"), "ALT AC101 FL260 ; POS AC101 ; POS AC202")
  check_eq(ex("ac101 descend fl260 and show trails"), "ALT AC101 FL260 ; TRAIL ON")
end

-- Cycle 47 (hz51): a question about an aircraft ("is X at FL300?", "what's X at FL300", "does X climb FL340?") is no
-- instruction: alone it is read as POS of the aircraft; with an instruction for it elsewhere it is asked
do
  local _, ex = scene({ "CRE AC101 A320 52.0 4.0 090 FL300 280", "CRE AC202 B738 52.3 4.3 180 FL200 250" })
  check_eq(ex("is ac202 at fl200?"), "POS AC202")
  check_eq(ex("whats ac101 at fl310"), "POS AC101")
  check_eq(ex("are ac101 and ac202 on heading 180?"), "POS AC101 ; POS AC202")
  check_eq(ex("does ac202 descend to fl150?"), "POS AC202")
  check_eq(ex("ac101, are you at fl300?"), "POS AC101")
  check_eq(ex("is that ac202 at 250 knots?"), "POS AC202")
  asked(ex("ac101 climb fl320, is ac202 at fl200?"), "a question after an instruction")
  asked(ex("is ac202 at fl200? descend it to fl180"), "an instruction after a question")
  check_eq(ex("have ac202 descend fl180"), "ALT AC202 FL180")
  check_eq(ex("are you at fl200, ac202?"), "POS AC202")
  check_eq(ex("what about ac101 at fl310"), "POS AC101")
  asked(ex("ac101 climb fl320, are you at fl200 ac202?"), "a question with its aircraft called at its end, after an instruction")
end

-- Cycle 47 (hz51): a speed restriction lifted, then a speed given in the same request contradict: asked which stands;
-- a speed given first and the restriction lifted after it ("speed 290, no speed restriction") is read
do
  local _, ex = scene({ "CRE AC101 A320 52.0 4.0 090 FL300 280" })
  check_eq(ex("ac101 no restrictions on your speed, slow to 230"),
    "ASK I have SPD AC101 230. Which stands: 'no restrictions on your speed', or the speed given?")
  asked(ex("ac101 no speed restriction, speed 230"), "no speed restriction, then a speed")
  asked(ex("ac101 cancel speed restriction, 230 knots"), "a speed after a comma is no part of the cancelled restriction")
  asked(ex("ac101 resume normal speed, 230 knots"), "normal speed resumed, then a speed")
  check_eq(ex("ac101 increase speed 300 knots, no speed restriction"), "SPD AC101 300")
  check_eq(ex("ac101 descend fl200, no speed restriction"), "ALT AC101 FL200")
end

-- Cycle 47 (g109a): an experimenter's typed shorthand of the command words ("head", "incr", "decr", "trn" before a
-- callsign and a side, "rm" opening the line, "del rte", "lvl?", "vert sep"), read as the words where the word
-- beside it fits; elsewhere it stays as typed (and asked)
do
  local _, ex = scene({ "CRE AB123 A320 51.0 3.0 090 FL250 280", "CRE PHXYZ C172 51.2 3.4 270 3000 100" })
  check_eq(ex("ab123 head 145"), "HDG AB123 145")
  check_eq(ex("ab123 incr 300"), "SPD AB123 300")
  check_eq(ex("ab123 decr to 250"), "SPD AB123 250")
  check_eq(ex("trn ab123 lft 15 degs"), "HDG AB123 75 LEFT")
  check_eq(ex("rm phxyz"), "DEL PHXYZ")
  check_eq(ex("ab123 del rte"), "DELRTE AB123")
  check_eq(ex("ab123 lvl?"), "POS AB123")
  check_eq(ex("ab123 lvl 310"), "ALT AB123 FL310")
  check_eq(ex("vert sep 1500 ft"), "ZONEDH 1500")
  check_eq(ex("ab123 desc fl180 exp"), "ALT AB123 FL180")
  asked(ex("ab123 desc fl180 exp rate"), "'exp' not closing its clause")
  -- where the word beside it does not fit, the shorthand is no command word
  asked(ex("ab123 rm"), "'rm' not opening the line")
  asked(ex("trn ab123 25"), "'trn' with no side")
  asked(ex("ab123 head for it"), "'head' with no number")
end
do
  local _, ex = navscene({ "CRE AB123 A320 51.0 3.0 090 FL250 280" }, "a fix typed in lower case after 'add'")
  if ex then
    -- (ECHOS, a fix near the traffic, typed as if the plural of the command word "echo")
    check_eq(ex("ab123 add echos"), "ADDWPT AB123 ECHOS")
    asked(ex("ab123 add echo"), "'echo' is a command word")
  end
end

-- Cycle 47 (g109a): a rate multiplier typed "xN" or "Nx" alone in its clause, or before "speed" or "rate" ending
-- it, is the simulation's rate (DTMULT) when no aircraft of that id flies; with one flying it stays the aircraft
do
  local _, ex = scene({ "CRE AB123 A320 51.0 3.0 090 FL250 280" })
  check_eq(ex("x8 speed"), "DTMULT 8")
  check_eq(ex("x3 and op"), "DTMULT 3 ; OP")
  check_eq(ex("2x rate then op"), "DTMULT 2 ; OP")
  check_eq(ex("x6, op"), "DTMULT 6 ; OP")
  local _, ex2 = scene({ "CRE X8 C172 51.0 3.0 090 3000 100" })
  asked(ex2("x8 speed"), "an aircraft X8 flies: its speed, no value")
  asked(ex2("x8 and op"), "an aircraft X8 flies")
end

-- Cycle 47 (g109a): a bare number of hundreds of feet in four or five figures, in a terse typed list of an
-- aircraft's values all labelled but it, is the level; a second bare number, another word, a level or code said,
-- or a number of no hundreds is asked
do
  local _, ex = scene({ "CRE AB123 A320 51.0 3.0 090 FL250 280", "CRE PHXYZ C172 51.2 3.4 270 3000 100" })
  check_eq(ex("phxyz 4500 h300 95kt"), "ALT PHXYZ 4500 ; HDG PHXYZ 300 ; SPD PHXYZ 95")
  check_eq(ex("ab123 spd 250, 14000"), "SPD AB123 250 ; ALT AB123 14000")
  check_eq(ex("ab123 9000 vs -2000"), "ALT AB123 9000 ; VS AB123 -2000")
  asked(ex("ab123 9000"), "a bare number alone")
  check_eq(ex("ab123 9000 210 kts"), "ALT AB123 9000 ; SPD AB123 210")
  asked(ex("ab123 9000 210 hdg 100"), "no label on 210 either: two bare numbers")
  asked(ex("ab123 9050 hdg 120"), "no hundreds of feet")
  asked(ex("ab123 9000 hdg 120 if able"), "other words beside the list")
  asked(ex("phxyz 4500 sq 7000 hdg 200"), "a transponder code said")
end

-- Cycle 47 (g109a): an experiment's id before a colon opening the line ("run4:", "c2:") is a label set apart,
-- unless its letters open an aircraft's id that flies; a value ruled out after "not" with an apology closing it
-- leaves the value before it
do
  local _, ex = scene({ "CRE AB123 A320 51.0 3.0 090 FL250 280", "CRE CD45 C172 51.2 3.4 270 3000 100" })
  check_eq(ex("run4: ab123 hdg 170"), "HDG AB123 170")
  check_eq(ex("trial12b: ab123 spd 240"), "SPD AB123 240")
  asked(ex("ab12: fl300"), "letters of AB123: a callsign typed short")
  asked(ex("cd4: hdg 100"), "letters of CD45")
  check_eq(ex("ab123 fl310 not 290 oops"), "ALT AB123 FL310")
  check_eq(ex("ab123 hdg 120 not 210 sorry"), "HDG AB123 120")
  check_eq(ex("ab123 fl310 not 290 sorry, cd45 hdg 080"), "ALT AB123 FL310 ; HDG CD45 80")
  check_eq(ex("zz9: cd45 hdg 080"), "HDG CD45 80")
  asked(ex("zz9: x3 and op"), "no aircraft after an id of no experiment's letters")
  asked(ex("ab123 fl310 sorry"), "an apology with no value ruled out")
end

-- Cycle 47 (g109b): a request that sends nothing always says why: a question naming what it needs, or the note
-- naming what squawk does not simulate (eval-translate lists a note-only outcome as "ASK " with no text: it is
-- the note's); swept over corpora here, over every corpus once by hand
do
  local nodes = require("translate.nodes")
  local NAV = "../shared/bluesky/navdata"
  local has_nav = pcall(squawk.sim.new, { navdata = NAV })
  local silent = {}
  local function sweep(path)
    squawk.translate.evaluate(path, function(c)
      local sim = has_nav and squawk.sim.new({ navdata = NAV }) or squawk.sim.new()
      for _, line in ipairs(nodes.split_commands(c.setup)) do sim:exec(line) end
      local r = graph.translate(c.utterance, { mode = "offline", sim = sim, waypoints = nodes.defined_waypoints(c.setup) })
      if #(r.commands or {}) == 0 and (r.ask or "") == "" and (r.note or "") == "" and not r.error then
        silent[#silent + 1] = c.utterance
      end
      return r
    end)
  end
  for _, f in ipairs({ "tests/data/translate_fresh.tsv", "tests/data/translate_round107.tsv",
      "tests/data/translate_round106.tsv", "tests/data/translate_round93.tsv" }) do
    sweep(f)
  end
  check_eq(table.concat(silent, " | "), "")
end

-- Cycle 47 (g109b): "hold at FIX <level>": the level with its unit said straight after the fix (or after a comma
-- or "at") is flown, the hold named as not simulated; a bare number there is asked; a hold alone sends nothing
-- and says so
do
  local s, ex = scene({ "CRE PHABC C172 52.3 4.9 250 3000 100", "CRE TRA55 B738 52.1 4.6 080 FL140 250",
    "DEFWPT KUMBA 52.4 5.1", "DEFWPT TULIP 52.0 4.4", "ADDWPT TRA55 TULIP" })
  local r = graph.translate("phabc hold over kumba 2500 ft", { sim = s, mode = "offline" })
  check_eq(said(r), "ALT PHABC 2500")
  check(r.note ~= nil and r.note:find("holding patterns ('hold over KUMBA')", 1, true) ~= nil, tostring(r.note))
  check_eq(ex("TRA55 hold at TULIP, FL110"), "ALT TRA55 FL110")
  -- (the level the aircraft flies is the hold's: nothing to send, the hold noted)
  r = graph.translate("TRA55 hold at TULIP, FL140", { sim = s, mode = "offline" })
  check(#r.commands == 0 and (r.note or ""):find("hold at TULIP, fl 140", 1, true) ~= nil, tostring(r.note))
  check_eq(ex("tra55 holding over tulip at fl120"), "ALT TRA55 FL120")
  check_eq(ex("tra55 hold at tulip fl 90 then hdg 200"), "ASK " .. "squawk does not simulate holding patterns ('hold at TULIP'), "
    .. "and what is said after it waits for it: please give that instruction when it applies.")
  asked(ex("tra55 hold at tulip FL100, then turn left heading 300"), "an instruction after the hold and its level")
  local q = ex("phabc hold at kumba 2500")
  check(q:find("Is '2500' the altitude to fly at KUMBA?", 1, true) ~= nil, q)
  r = graph.translate("tra55 hold at tulip, expect further clearance at one five", { sim = s, mode = "offline" })
  check(#r.commands == 0 and (r.note or ""):find("holding patterns", 1, true) ~= nil, said(r))
end

-- Cycle 47 (g109b): two aircraft in one typed line: a callsign and a value with its unit, then "and" or straight
-- another flying aircraft with its own instruction: each instruction goes to the callsign said before it; an
-- aircraft that is not flying is asked about
do
  local _, ex = scene({ "CRE DLH4 A321 50.1 8.6 300 FL280 290", "CRE AUA61 A320 50.3 8.9 120 FL240 270",
    "CRE SAS7 B738 50.0 8.2 200 FL330 280" })
  check_eq(ex("dlh4 fl260 and aua61 hdg 090 lt"), "ALT DLH4 FL260 ; HDG AUA61 90 LEFT")
  check_eq(ex("sas7 m.76 and dlh4 descend fl250"), "SPD SAS7 M0.76 ; ALT DLH4 FL250")
  check_eq(ex("aua61 230kt sas7 hdg 160"), "SPD AUA61 230 ; HDG SAS7 160")
  check_eq(ex("dlh4 fl260 and dlh4 hdg 320"), "ALT DLH4 FL260 ; HDG DLH4 320")
  asked(ex("dlh4 fl260 and aua16 hdg 090"), "the second aircraft is not flying")
end

-- Cycle 47 (g109b): terse waypoint conditions. A heading after "at/over/after FIX", or a speed after "after FIX",
-- is no constraint the waypoint carries: the instruction there (AT ... DO) when FIX is on the route; a level with
-- no verb stays the constraint ("over FIX FL140") or is asked ("after FIX FL140"); a level or speed after "then"
-- tied to a direct-to's waypoint runs there; "thru" is "through"; "till" a level is "to" it after a rate
do
  local _, ex = scene({ "CRE EWG9 A320 51.5 7.0 090 FL300 280", "DEFWPT LOMKI 51.6 7.6", "DEFWPT ROTEN 51.7 8.4",
    "ADDWPT EWG9 LOMKI", "ADDWPT EWG9 ROTEN", "DEFWPT OFFRT 50.0 6.0" })
  check_eq(ex("ewg9 after lomki 240kt"), "AT EWG9 LOMKI DO SPD EWG9 240")
  check_eq(ex("ewg9 after roten m.74"), "AT EWG9 ROTEN DO SPD EWG9 M0.74")
  check_eq(ex("ewg9 over roten hdg 130"), "AT EWG9 ROTEN DO HDG EWG9 130")
  check_eq(ex("ewg9 at lomki hdg 045"), "AT EWG9 LOMKI DO HDG EWG9 45")
  check_eq(ex("ewg9 over lomki fl260"), "AT EWG9 LOMKI ALT FL260")
  check_eq(ex("ewg9 at lomki 250kt"), "AT EWG9 LOMKI SPD 250")
  asked(ex("ewg9 after lomki fl260"), "a level with no verb after the waypoint is passed")
  asked(ex("ewg9 after offrt 240kt"), "a waypoint off the route")
  check_eq(ex("ewg9 dct roten then fl240 at roten"), "DIRECT EWG9 ROTEN ; AT EWG9 ROTEN DO ALT EWG9 FL240")
  check_eq(ex("ewg9 direct roten then at roten 260kt"), "DIRECT EWG9 ROTEN ; AT EWG9 ROTEN DO SPD EWG9 260")
  asked(ex("ewg9 dct roten, fl240 at roten"), "no 'then': met there or flown there")
  asked(ex("ewg9 dct roten then fl240 at lomki"), "a waypoint the direct-to does not fly to")
  check_eq(ex("ewg9 once thru fl250 reduce 250"), "ATALT EWG9 FL250 SPD EWG9 250")
  asked(ex("ewg9 passing thru fl250 reduce 250"), "a pilot's report of the level passed, or a condition")
  check_eq(ex("ewg9 vs -1500 till fl200"), "VS EWG9 -1500 ; ALT EWG9 FL200")
  asked(ex("ewg9 m.78 till fl200"), "a speed ended at a level")
end

-- Cycle 47 (g109b): a new aircraft's callsign typed as a registration in lower case beside its type, opening with a
-- nationality mark of two letters ("new c172 ooxyz ...": OO-XYZ), is its callsign; a word with no such mark is still
-- asked for. "wind LAT LON [level]?" typed with nothing else asks for the wind there (GETWIND)
do
  local _, ex = scene({ "CRE KLM12 B738 52 4 90 FL250 280" })
  check_eq(ex("new pa28 phxyz 52.1 4.9 3000ft hdg 120 100kt"), "CRE PHXYZ PA28 52.1 4.9 120 3000 100")
  check_eq(ex("cre c152 oeabc 47.2 11.3 4500ft hdg 270 90kt"), "CRE OEABC C152 47.2 11.3 270 4500 90")
  check_eq(ex("new c172 PHABC 52.0 5.0 2000ft hdg 090 95kt"), "CRE PHABC C172 52 5 90 2000 95")
  asked(ex("new c172 qwxyz 52.0 5.0 2000ft hdg 090 95kt"), "five letters with no nationality mark")
  asked(ex("new c172 bravo 52.0 5.0 2000ft hdg 090 95kt"), "a word squawk knows")
  check_eq(ex("wind 52.2 4.1 fl150?"), "GETWIND 52.2 4.1 FL150")
  check_eq(ex("winds 52.2 4.1"), "GETWIND 52.2 4.1")
  check_eq(ex("wind at 52.2 4.1 fl150 please"), "GETWIND 52.2 4.1 FL150")
  asked(ex("wind 52.2 4.1 fl150 klm12"), "an aircraft named after the wind's position")
end

-- Cycle 47 (hz53): a bare number in a terse list after a value typed with its own unit and before the next
-- instruction word ("fl100 6000 hdg 220") is a value no command carries: asked by name, never dropped; a single
-- digit there stays callsign noise, and a bare altitude after a speed stays the level
do
  local _, ex = scene({ "CRE BEE7 DH8D 50.9 -1.4 090 FL080 220" })
  check_eq(ex("bee7 fl110 5000 hdg 250"), "ASK I have ALT BEE7 FL110 ; HDG BEE7 250. What does '5000' mean?")
  check_eq(ex("bee7 m.60 310 hdg 250"), "ASK I have SPD BEE7 M0.6 ; HDG BEE7 250. What does '310' mean?")
  check_eq(ex("bee7 fl110 270 and h250"), "ASK I have ALT BEE7 FL110 ; HDG BEE7 250. What does '270' mean?")
  check_eq(ex("bee7 fl110 hdg 250"), "ALT BEE7 FL110 ; HDG BEE7 250")
  check_eq(ex("bee7 s210 7000 hdg 250"), "SPD BEE7 210 ; ALT BEE7 7000 ; HDG BEE7 250")
end

-- Cycle 47 (hz53): beside value instructions, which read no place, a condition on a place said with a word of
-- passage ("passing", "abeam", "past", "approaching", "reaching", "overhead", "leaving"; "over", "at", "by" before a
-- place's noun: "the beacon", "the VOR", "the marker") that nothing read is asked, named to the end of its clause;
-- a level after "passing" stays the level waited for
do
  local _, ex = scene({ "CRE EXS3 B738 53.4 -2.3 270 FL190 290" })
  check_eq(ex("exs3 slow to 220 knots abeam the NDB"), "ASK I have SPD EXS3 220. What does 'abeam the NDB' mean?")
  check_eq(ex("exs3 descend FL120 overhead the beacon"),
    "ASK I have ALT EXS3 FL120. What does 'overhead the beacon' mean?")
  check_eq(ex("exs3 over the VOR turn right heading 330"),
    "ASK I have HDG EXS3 330 RIGHT. What does 'over the VOR' mean?")
  check_eq(ex("exs3 reduce 230 knots approaching the marker"),
    "ASK I have SPD EXS3 230. What does 'approaching the marker' mean?")
  check_eq(ex("exs3 left heading 240 passing it"), "ASK I have HDG EXS3 240 LEFT. What does 'passing it' mean?")
  check_eq(ex("exs3 reduce 230 knots passing FL170"), "ATALT EXS3 FL170 SPD EXS3 230")
end

-- Cycle 47 (hz53): beside value instructions, a word of going on ("continue", "resume", "back on/to") whose clause
-- holds no instruction word or value of its own ("then continue on course", "continue as filed", "back on track")
-- is asked, named to the end of its clause; "continue climb", "continue on heading 200" stay the instruction's
-- manner, and "resume own navigation" stays LNAV ON
do
  local _, ex = scene({ "CRE SWR8 A320 47.4 8.5 180 FL230 270", "DEFWPT ROLSA 46.9 8.3", "ADDWPT SWR8 ROLSA" })
  check_eq(ex("swr8 turn left heading 140, then continue on course"),
    "ASK I have HDG SWR8 140 LEFT. What does 'continue on course' mean?")
  check_eq(ex("swr8 reduce 240 knots, continue as filed"), "ASK I have SPD SWR8 240. What does 'continue as filed' mean?")
  check_eq(ex("swr8 heading 150 then back on track"), "ASK I have HDG SWR8 150. What does 'back on track' mean?")
  check_eq(ex("swr8 fl210 then continue on the approach"),
    "ASK I have ALT SWR8 FL210. What does 'continue on the approach' mean?")
  check_eq(ex("swr8 continue descent FL210"), "ALT SWR8 FL210")
  check_eq(ex("swr8 continue on heading 150"), "HDG SWR8 150")
  check_eq(ex("swr8 heading 150 then resume own navigation"), "HDG SWR8 150 ; LNAV SWR8 ON")
end

-- Cycle 48 (hz54): "report level" alone asks the level flown now, as "say altitude" and "report your level" do
-- (POS); "report reaching/passing" and "report level" after an instruction stay the pilot's later report, no POS
do
  local _, ex = scene({ "CRE SHT4 A320 55.9 -4.4 090 FL140 260", "CRE LOG71 DH8D 56.3 -3.9 200 FL90 220" })
  check_eq(ex("Shuttle 4 report level"), "POS SHT4")
  check_eq(ex("log71 report level please"), "POS LOG71")
  check_eq(ex("sht4 report your level"), "POS SHT4")
  check_eq(ex("sht4 say altitude"), "POS SHT4")
  check_eq(ex("log71 report your present level"), "POS LOG71")
  check_eq(ex("log71 descend FL70, report level"), "ALT LOG71 FL70")
  check_eq(ex("sht4 report reaching"), "")
  check_eq(ex("sht4 report level FL150"), "")  -- the pilot's report of a level (not simulated), no ALT
  asked(ex("report level"), "no aircraft named")
end

-- Cycle 48 (hz54): two aircraft in one line, each with its own instruction: after "and", "then", a comma or straight
-- after the first's value, another flying aircraft with a value of its own unit straight after it is its own request
-- ("klm33 hdg 100 and ryr8 fl310"), also after an instruction with no value (a direct-to, a navigation switch); a
-- bare value there takes the instruction before ("turn X to 010 and Y to 200"); a value said after another aircraft
-- in the first instruction's clause ("avoiding RYR8 FL310") may be either's: asked
do
  local _, ex = scene({ "CRE TAP12 A320 41.2 -8.7 300 FL250 280", "CRE IBE31 A321 40.9 -8.2 020 FL330 300",
    "CRE VLG7 A320 41.5 -8.9 180 FL180 260", "DEFWPT ODEMI 41.6 -8.4", "ADDWPT TAP12 ODEMI" })
  check_eq(ex("tap12 hdg 320 and ibe31 fl290"), "HDG TAP12 320 ; ALT IBE31 FL290")
  check_eq(ex("tap12 hdg 320, ibe31 fl290"), "HDG TAP12 320 ; ALT IBE31 FL290")
  check_eq(ex("tap12 hdg 320 ibe31 fl290"), "HDG TAP12 320 ; ALT IBE31 FL290")
  check_eq(ex("tap12 hdg 320 then ibe31 fl290"), "HDG TAP12 320 ; ALT IBE31 FL290")
  check_eq(ex("tap12 reduce 250 and ibe31 to fl290"), "SPD TAP12 250 ; ALT IBE31 FL290")
  check_eq(ex("tap12 climb fl300 and ibe31 280 kts and vlg7 hdg 150"),
    "ALT TAP12 FL300 ; SPD IBE31 280 ; HDG VLG7 150")
  check_eq(ex("tap twelve turn left heading three two zero and iberia three one flight level two niner zero"),
    "HDG TAP12 320 LEFT ; ALT IBE31 FL290")
  check_eq(ex("tap12 dct odemi and ibe31 fl290"), "DIRECT TAP12 ODEMI ; ALT IBE31 FL290")
  check_eq(ex("tap12 lnav off and ibe31 fl290"), "LNAV TAP12 OFF ; ALT IBE31 FL290")
  check_eq(ex("tap12 hdg 320 and ibe31 to 010"), "HDG TAP12 320 ; HDG IBE31 10")
  check_eq(ex("tap12 speed 250 and ibe31 mach .78"), "SPD TAP12 250 ; SPD IBE31 M0.78")
  asked(ex("tap12 hdg 320 avoiding ibe31 fl290"), "a level after the other aircraft may be either's")
  asked(ex("tap12 hdg 320 behind ibe31 at 280 kts"), "a speed after the other aircraft may be either's")
  asked(ex("tap12 hdg 320 and ibe31"), "the second aircraft has no instruction of its own")
  -- an aircraft described by its value and a copula after it ("IBE31 at FL290 is traffic") is not instructed
  check_eq(ex("tap12 descend fl230, ibe31 at fl290 is traffic"), "ALT TAP12 FL230")
  check_eq(ex("tap12 descend fl230 and ibe31 fl290 is converging"), "ALT TAP12 FL230")
  asked(ex("ibe31 at fl290 is traffic"), "a description alone instructs nobody")
end

-- Cycle 48 (hz54): a verb of passing a waypoint straight after an instruction's value, with no "when" ("reduce
-- 250 knots passing LOMKI", "descend FL200 overflying X", "reaching X") is the waypoint the instruction waits
-- for (AT acid wp DO), as "when passing" is; off the route it is asked. A value counted from what the aircraft
-- flies now ("left 20 degrees", "reduce 20 knots") is never run later at a waypoint, and a second value beside
-- the one tied there ("fl200 250 kts passing X") is asked: which of them waits
do
  local _, ex = scene({ "CRE AEE9 A320 38.1 23.5 040 FL270 290", "DEFWPT PIKAD 38.4 23.9", "ADDWPT AEE9 PIKAD",
    "DEFWPT TOBIL 37.5 23.0" })
  check_eq(ex("aee9 reduce 250 knots passing PIKAD"), "AT AEE9 PIKAD DO SPD AEE9 250")
  check_eq(ex("aee9 reduce speed two five zero passing pikad"), "AT AEE9 PIKAD DO SPD AEE9 250")
  check_eq(ex("aee9 descend fl180 overflying PIKAD"), "AT AEE9 PIKAD DO ALT AEE9 FL180")
  check_eq(ex("aee9 turn right heading 090 reaching PIKAD"), "AT AEE9 PIKAD DO HDG AEE9 90 RIGHT")
  check_eq(ex("aee9 reduce 250 when passing PIKAD"), "AT AEE9 PIKAD DO SPD AEE9 250")
  asked(ex("aee9 reduce 250 knots passing TOBIL"), "a waypoint off the route")
  asked(ex("aee9 turn left 20 degrees passing PIKAD"), "a turn counted from the heading now, run later")
  asked(ex("aee9 reduce 20 knots after PIKAD"), "a speed counted from the speed now, run later")
  asked(ex("aee9 fl180 250 kts passing PIKAD"), "a second value beside the one tied to the waypoint")
  asked(ex("aee9 reduce 250 knots abeam PIKAD"), "abeam is no passing over")
end

-- Cycle 48 (hz54): a wait ("in 2 min", "after 2 minutes") goes only where it was said. Opening the clause of the
-- next instruction (after a comma, "and" or "then") it is that instruction's; closing an instruction's clause it is
-- that one's; said before every instruction (also straight after the callsign, when no other aircraft is named)
-- it times them all; said between two instructions with nothing to part it from either it is asked
do
  local _, ex = scene({ "CRE BEL5 A319 50.9 4.5 200 FL230 270", "CRE TUI3 B738 51.1 4.1 090 FL310 290" })
  check_eq(ex("bel5 descend fl150, in 3 minutes turn right heading 250"), "ALT BEL5 FL150 ; DELAY 180 HDG BEL5 250 RIGHT")
  check_eq(ex("bel5 descend fl150 and in 3 minutes turn right heading 250"), "ALT BEL5 FL150 ; DELAY 180 HDG BEL5 250 RIGHT")
  check_eq(ex("bel5 descend fl150 in 3 minutes, turn right heading 250"), "DELAY 180 ALT BEL5 FL150 ; HDG BEL5 250 RIGHT")
  check_eq(ex("bel5 fl150, in 3 min hdg 250"), "ALT BEL5 FL150 ; DELAY 180 HDG BEL5 250")
  check_eq(ex("bel5 fl150 in 3 min, hdg 250"), "DELAY 180 ALT BEL5 FL150 ; HDG BEL5 250")
  check_eq(ex("bel5 fl150 in 3 min and s250"), "DELAY 180 ALT BEL5 FL150 ; SPD BEL5 250")
  check_eq(ex("bel5 in three minutes fl150 hdg 250"), "DELAY 180 ALT BEL5 FL150 ; DELAY 180 HDG BEL5 250")
  check_eq(ex("bel5, in 3 minutes descend fl150 and turn right heading 250"),
    "DELAY 180 ALT BEL5 FL150 ; DELAY 180 HDG BEL5 250 RIGHT")
  check_eq(ex("bel5 in 3 minutes descend fl150 and tui3 turn left heading 040"),
    "DELAY 180 ALT BEL5 FL150 ; HDG TUI3 40 LEFT")
  check_eq(ex("bel5 fl150 hdg 250 in 3 min"), "DELAY 180 ALT BEL5 FL150 ; DELAY 180 HDG BEL5 250")
  check_eq(ex("bel5 in 3 min fl150, then ff 60"), "DELAY 180 ALT BEL5 FL150 ; FF 60")
  asked(ex("bel5 fl150 in 3 min hdg 250"), "a wait between two values")
  asked(ex("bel5 fl one five zero in three minutes heading two five zero"), "the same in words")
  asked(ex("bel5 descend fl150 in 3 minutes turn right heading 250"), "a wait between two instructions")
  asked(ex("bel5 descend fl150 after 3 minutes turn right heading 250"), "'after' likewise")
end

-- Cycle 48 (hz54): DIRECT switches LNAV on, so an aircraft's LNAV OFF and its direct-to, in either order and in any
-- words, undo each other (before the direct-to the switch is lost, after it the aircraft no longer flies to the
-- waypoint): asked, naming both. LNAV ON beside a direct-to, VNAV OFF beside one, and LNAV OFF of another aircraft
-- stand
do
  local _, ex = scene({ "CRE HOP3 E145 50.6 3.0 180 12000 250", "DEFWPT ARTOV 50.8 3.3", "ADDWPT HOP3 ARTOV",
    "CRE TVF8 B738 50.2 2.6 045 FL350 290", "ADDWPT TVF8 ARTOV" })
  local q = "ASK DIRECT HOP3 ARTOV switches LNAV on again. Should HOP3 fly direct to ARTOV along its route (LNAV on), "
    .. "or leave its route (LNAV off)?"
  check_eq(ex("hop3 lnav off dct artov"), q)
  check_eq(ex("hop3 dct artov, then lnav off"), q)
  check_eq(ex("hop3 switch off lateral navigation and proceed direct artov"), q)
  check_eq(ex("hop3 own navigation off direct artov fl100"), q)
  check_eq(ex("hop3 lnav on dct artov"), "LNAV HOP3 ON ; DIRECT HOP3 ARTOV")
  check_eq(ex("hop3 vnav off dct artov"), "VNAV HOP3 OFF ; DIRECT HOP3 ARTOV")
  check_eq(ex("hop3 lnav off and tvf8 dct artov"), "LNAV HOP3 OFF ; DIRECT TVF8 ARTOV")
  check_eq(ex("hop3 lnav off heading 200"), "LNAV HOP3 OFF ; HDG HOP3 200")
end

-- Cycle 48 (f113): a limit "until" a distance in DME typed in capitals ("maintain 4000 until 10 DME") names no
-- place: a navaid's kind alone is no waypoint, so the limit is one at a distance, flown and its end named only at
-- the final approach's 3 to 6 miles, else asked; a waypoint of the route after "until" stays a place
do
  local _, ex = scene({ "CRE KAL7 B738 37.4 126.4 180 FL140 270", "DEFWPT ALFA 37.1 126.5", "ADDWPT KAL7 ALFA" })
  check_eq(ex("KAL7 maintain 4000 until 10 DME"), "ASK I have ALT KAL7 4000. What does '10 DME' mean?")
  asked(ex("KAL7 maintain 250 knots till 12 DME"), "a speed held to 12 DME")
  asked(ex("KAL7 reduce 180 knots to 10 DME"), "a speed held to 10 DME, said with 'to'")
  asked(ex("KAL7 maintain 4000 until the VOR"), "a navaid's kind alone is no place")
  check_eq(ex("KAL7 speed 160 until 4 DME"), "SPD KAL7 160")
  check_eq(ex("KAL7 maintain 5000 until ALFA"), "ALT KAL7 5000")
end

-- Cycle 48 (f113): a callsign said with a brand's name (names.lua's brands) is an aircraft of a brand airline
-- only when that airline bears the name: its own telephony is the name or begins with it ("Jetstar Asia"), or
-- squawk knows none for it; Jetstar Japan, "Orange Liner", is never "Jetstar 503", nor the Shuttle "Speedbird 12"
do
  local _, ex = scene({ "CRE JJP503 A320 36.1 140.2 160 FL130 270", "CRE JSA142 A320 1.3 103.9 090 FL150 270",
    "CRE TVF33KP B738 48.7 2.4 180 FL200 280", "CRE SHT12 A320 51.5 -0.4 300 FL100 250",
    "CRE EJU45 A320 47.4 8.5 090 FL250 280" })
  check_eq(ex("Jetstar 503 descend 7000"), "ASK Did you mean JJP503? I heard JST503.")
  check_eq(ex("Orange Liner 503 descend 7000"), "ALT JJP503 7000")
  check_eq(ex("Jetstar 142 descend FL120"), "ALT JSA142 FL120")
  check_eq(ex("Transavia 33KP descend FL150"), "ASK Did you mean TVF33KP? I heard TRA33KP.")
  check_eq(ex("France Soleil 33KP descend FL150"), "ALT TVF33KP FL150")
  asked(ex("Speedbird 12 climb FL120"), "the Shuttle's aircraft called by the Speedbird telephony")
  asked(ex("Easy 45 descend FL200"), "easyJet Europe (Alpine) called Easy")
  check_eq(ex("Alpine 45 descend FL200"), "ALT EJU45 FL200")
end

-- Cycle 48 (f113): "report level FL150", "report level at FL210", "report heading 090": the report of a value the
-- aircraft will reach, no clearance to it (nothing sent, named as not simulated); "report your level" still
-- asks for the state, and a clearance before it is flown
do
  local s, ex = scene({ "CRE UAL32 B789 35.9 140.6 060 FL150 290", "CRE TZP102 B788 35.6 140.8 090 FL190 300" })
  local function none(text, why)
    local r = graph.translate(text, { sim = s, mode = "offline" })
    check(r.ask == nil and #(r.commands or {}) == 0 and (r.note or ""):find("position reports", 1, true) ~= nil, why)
  end
  none("United 32 report level flight level one five zero", "a report of the level flown")
  none("United 32 report level at FL210", "a report of a level to come")
  none("United 32 report heading 090", "a report of a heading")
  check_eq(ex("United 32 report your level"), "POS UAL32")
  check_eq(ex("United 32 climb FL210, report level FL210"), "ALT UAL32 FL210")
end

-- Cycle 48 (f113): Japanese and Korean carriers by their ICAO telephony (Solaseed "New Sky", Air Busan, T'way
-- "Teeway", Jin Air, Japan Transocean "Jai Ocean", ZIPAIR "Zippy"); a number none of them flies is asked
do
  local _, ex = scene({ "CRE SNJ52 B738 33.2 130.8 320 FL130 260", "CRE ABL142 A321 34.7 129.35 135 FL180 280",
    "CRE TWB701 B738 34.0 126.1 160 FL160 280", "CRE JNA305 B738 32.7 126.4 010 FL200 290" })
  check_eq(ex("New Sky 52 turn left heading two niner zero"), "HDG SNJ52 290 LEFT")
  check_eq(ex("delete Teeway 701"), "DEL TWB701")
  check_eq(ex("Jin Air 305, climb FL250. Air Busan 142, descend FL160."), "ALT JNA305 FL250 ; ALT ABL142 FL160")
  check_eq(ex("create Jin Air 603, B738, 33.5 126.5, heading 070, 5000 ft, 210 knots"),
    "CRE JNA603 B738 33.5 126.5 70 5000 210")
  asked(ex("New Sky 53 climb FL150"), "a New Sky number no aircraft has")
end

-- Cycle 48 (f113): "until WPT, then ..." with a comma or "and" before "then" ends the first instruction at the
-- waypoint and starts the next there (AT acid WPT DO); a waypoint off the route is still asked
do
  local _, ex = scene({ "CRE CPA596 A359 34.65 136.3 265 FL200 290", "DEFWPT ALFA 34.6 135.9", "DEFWPT BRAVO 34.9 135.5",
    "ADDWPT CPA596 ALFA" })
  check_eq(ex("CPA596 maintain FL200 until ALFA, then descend FL150"), "ALT CPA596 FL200 ; AT CPA596 ALFA DO ALT CPA596 FL150")
  check_eq(ex("CPA596 speed 250 until ALFA and then reduce 220"), "SPD CPA596 250 ; AT CPA596 ALFA DO SPD CPA596 220")
  asked(ex("CPA596 speed 250 until BRAVO, then reduce 220"), "a waypoint off the route")
end

-- Cycle 48 (f113): "when reaching maintain speed 270" after a descent: "maintain" straight before "speed" is that
-- speed's verb, so it waits for the level as "when reaching reduce speed 270" does; said with no level before it
-- the condition is still asked
do
  local _, ex = scene({ "CRE JAL917 B763 27.6 127.7 180 FL260 300" })
  check_eq(ex("JAL917 descend FL240, when reaching maintain speed 270"),
    "ALT JAL917 FL240 ; ATALT JAL917 FL240 SPD JAL917 270")
  check_eq(ex("JAL917 maintain present speed"), "SPD JAL917 300")
  asked(ex("JAL917 turn left heading 090, when reaching maintain speed 270"), "no level to reach")
end

-- Cycle 48 (f113): "downward" and "upward" give a vertical speed its sign as "down" and "up" do; against the
-- level cleared it is asked
do
  local _, ex = scene({ "CRE JJP503 A320 36.1 140.2 160 FL130 270" })
  check_eq(ex("JJP503 vertical speed one thousand five hundred downward"), "VS JJP503 -1500")
  check_eq(ex("JJP503 rate 2000 upwards"), "VS JJP503 2000")
  asked(ex("JJP503 climb FL200, vertical speed 1500 downward"), "a descent rate for a climb")
end

-- Cycle 48 (f113): "set" before a setting's word and spoken digits ("set wind two five zero ...") is the verb,
-- never a garbled callsign's words; with two aircraft flying, "set heading two five zero" asks which one
do
  local _, ex = scene({ "CRE JTA2 B738 25.6 127.95 330 FL150 260", "CRE JAL917 B763 27.6 127.7 180 FL260 300",
    "DEFWPT ALFA 26.2 127.6" })
  check_eq(ex("set wind two five zero degrees three zero knots over ALFA"), "WIND ALFA 250 30")
  check_eq(ex("set heading two five zero"), "ASK Which aircraft should turn? Please give its callsign.")
end

-- Cycle 48 (f113): two creations, the second's callsign said with an airline whose telephony opens with "All" ("All
-- Nippon 201"): that word is the callsign's, no value shared by "all" the new aircraft
do
  local _, ex = scene({})
  check_eq(ex("create AAR102 A388 at 35.7 140.4 heading 220 FL100 250 knots, and All Nippon 201, B788, at 34.4 135.2, "
    .. "heading 050, FL100, 250 knots"), "CRE AAR102 A388 35.7 140.4 220 FL100 250 ; CRE ANA201 B788 34.4 135.2 50 FL100 250")
  check_eq(ex("create AAA1 A320 at 53 7 heading 090 and All Nippon 201 A320 at 52.7 7.5 heading 000, both FL300 at 280 kts"),
    "CRE AAA1 A320 53 7 90 FL300 280 ; CRE ANA201 A320 52.7 7.5 0 FL300 280")
end

-- Cycle 48 (f110): a level after "at" opening a clause after "then", "and" or a comma, straight before a speed or
-- heading ("climb FL160 then at FL160 speed 280", "..., at FL160 280 knots"), is what that instruction waits for
-- (ATALT); one said again before any other instruction is asked, never dropped because the level cleared carries
-- its value
do
  local _, ex = scene({ "CRE MSR71 A320 30.1 31.4 090 FL120 260" })
  check_eq(ex("msr71 climb FL160 then at FL160 speed 280"), "ALT MSR71 FL160 ; ATALT MSR71 FL160 SPD MSR71 280")
  check_eq(ex("msr71 climb FL160 and at FL140 turn left heading 200"),
    "ALT MSR71 FL160 ; ATALT MSR71 FL140 HDG MSR71 200 LEFT")
  check_eq(ex("msr71 climb FL160, then at FL160 mach .74"), "ALT MSR71 FL160 ; ATALT MSR71 FL160 SPD MSR71 M0.74")
  check_eq(ex("msr71 climb FL160, at FL160 280 knots"), "ALT MSR71 FL160 ; ATALT MSR71 FL160 SPD MSR71 280")
  check_eq(ex("msr71 climb FL160, at FL160 vertical speed 500"),
    "ASK I have ALT MSR71 FL160 ; VS MSR71 500. What does 'at fl 160' mean?")
  check_eq(ex("msr71 climb FL160 and 280 knots"), "ALT MSR71 FL160 ; SPD MSR71 280")
end

-- Cycle 48 (f110): "thousand feet" opening the text or a clause after a mark is one thousand feet ("..., 3 mile
-- radius, thousand feet"); a word of scale ("thousand", "hundred") that no value holds, after an instruction, is
-- asked, never dropped; a family's variant said in hundreds after its tens ("a three thirty three hundred") is
-- that variant
do
  local _, ex = scene({ "CRE MSR71 A320 30.1 31.4 090 FL120 260" })
  check_eq(ex("asas on, 3 mile radius, thousand feet"), "ASAS ON ; ZONER 3 ; ZONEDH 1000")
  check_eq(ex("thousand feet vertical separation, 3 nm radius"), "ZONEDH 1000 ; ZONER 3")
  check_eq(ex("msr71 descend FL100, thousand feet per minute"), "ALT MSR71 FL100 1000")
  check_eq(ex("msr71 descend FL100, thousand"), "ASK I have ALT MSR71 FL100. What does 'thousand' mean?")
  check_eq(ex("asas on, radius 3 nm, hundred"), "ASK I have ASAS ON ; ZONER 3. What does 'hundred' mean?")
  check_eq(ex("create MSR72 a three thirty three hundred at 30 31 heading 090 FL100 250 knots"),
    "CRE MSR72 A333 30 31 90 FL100 250")
end

-- Cycle 48 (f110): a new aircraft at a fix, a navaid or a user waypoint that stands off every airport, with neither
-- altitude nor speed said, would stand there at 0 ft and 0 kt: asked; at an airport (or a navaid on one), typed as a
-- latitude and longitude, or said to be on the ground, it is created as said
do
  local s = scene({ "CRE MSR71 A320 30.1 31.4 090 FL120 260", "DEFWPT GATE7 30.4 31.9" })
  local function ex(text) return said(graph.translate(text, { sim = s, mode = "offline", waypoints = { "GATE7" } })) end
  check_eq(ex("create MSR72 A320 at GATE7 heading 090"),
    "ASK What altitude and speed should MSR72 have at GATE7? With none said it would stand there at 0 ft and 0 kt.")
  asked(ex("create MSR72 A320 at GATE7"), "no heading, altitude or speed at a user waypoint")
  check_eq(ex("create MSR72 A320 at GATE7 heading 090 FL100"), "CRE MSR72 A320 GATE7 90 FL100")
  check_eq(ex("create MSR72 A320 at GATE7 heading 090 on the ground"), "CRE MSR72 A320 GATE7 90 0 0")
  check_eq(ex("create MSR72 A320 at 30.4 31.9 heading 090"), "CRE MSR72 A320 30.4 31.9 90")
  local _, nav = navscene({ "CRE ABY571 A320 25.33 55.6 80 4000 210" }, "creations at a fix and at an airport")
  if nav then
    asked(nav("spawn ABY9 A320 over TUKLA heading 270"), "a fix off every airport")
    check_eq(nav("spawn ABY9 A320 at OMDB heading 270"), "CRE ABY9 A320 OMDB 270")
    check_eq(nav("spawn ABY9 A320 at KOK heading 270"), "CRE ABY9 A320 KOK 270")  -- (the KOK VOR stands on EBFN)
  end
end

-- Cycle 48 (f110): a flight number's letters typed in capitals after its digits said as words ("Emirates seven
-- KD") are read with them when exactly one aircraft's id ends so; other letters or digits are asked
do
  local _, ex = scene({ "CRE UAE7KD B77W 25.1 55.2 090 FL200 280", "CRE UAE7 A388 25.3 55.4 180 FL300 290" })
  check_eq(ex("Emirates seven KD climb FL240"), "ALT UAE7KD FL240")
  check_eq(ex("Emirates seven KD turn left heading 050"), "HDG UAE7KD 50 LEFT")
  check_eq(ex("Emirates seven climb FL310"), "ALT UAE7 FL310")
  asked(ex("Emirates seven KB climb FL340"), "letters no aircraft has")
  asked(ex("Emirates eight KD climb FL240"), "digits no aircraft has")
end

-- Cycle 48 (f110): a speed condition in the middle of a request ("reduce speed 250, when speed 250 descend FL120",
-- "once at 260 knots turn right") is what the instruction after it waits for (ATSPD); a bare number after "when", or
-- "then when", is asked
do
  local _, ex = scene({ "CRE OMA62 B738 23.6 58.3 300 FL200 290" })
  check_eq(ex("oma62 reduce speed 250, when speed 250 descend FL120"),
    "SPD OMA62 250 ; ATSPD OMA62 250 ALT OMA62 FL120")
  check_eq(ex("oma62 reduce 260 knots and once at 260 knots turn right heading 340"),
    "SPD OMA62 260 ; ATSPD OMA62 260 HDG OMA62 340 RIGHT")
  check_eq(ex("oma62 reduce speed 250, when slowed to 250 descend FL120"),
    "SPD OMA62 250 ; ATSPD OMA62 250 ALT OMA62 FL120")
  asked(ex("oma62 reduce speed 250, when 250 descend FL120"), "a bare number after when")
  asked(ex("oma62 reduce speed 250, then when speed 250 descend FL120"), "then when")
end

-- Cycle 48 (f110): "confirm the route", "verify your routing" closing the clause asks for the route (LISTRTE); with a
-- place after it, it asks whether a clearance stands, as before
do
  local _, ex = scene({ "CRE KAC12 A320 29.2 47.9 180 FL250 280" })
  check_eq(ex("KAC12, confirm your route"), "LISTRTE KAC12")
  check_eq(ex("KAC12 verify the routing please"), "LISTRTE KAC12")
  asked(ex("KAC12 confirm route direct TOKAR"), "a clearance asked about")
end

-- Cycle 48 (f110): an airline's telephony of several words typed as one word before its flight number ("Gulfair two
-- one four", "Airindia 131") is that airline; Safair (SFR, "FlySafair") is known
do
  local _, ex = scene({ "CRE GFA214 A320 26.2 50.6 090 FL200 280", "CRE AIC131 A321 26.5 50.9 270 FL220 280",
    "CRE SFR20 B738 26.0 50.2 180 FL180 270" })
  check_eq(ex("Gulfair two one four climb FL260"), "ALT GFA214 FL260")
  check_eq(ex("Airindia 131 descend FL180"), "ALT AIC131 FL180")
  check_eq(ex("FlySafair 20 turn right heading 100"), "HDG SFR20 100 RIGHT")
  check_eq(ex("Safair 20 reduce 250 knots"), "SPD SFR20 250")
  asked(ex("Gulfair climb FL260"), "no flight number")
  asked(ex("Airindia 132 descend FL180"), "a flight number no aircraft has")
end

-- Cycle 48 (f110): a latitude and a longitude each said after its hemisphere's word ("north 25 point 5, east 55
-- point 25", "south 1.25 west 3.5") are that position; a latitude alone is asked
do
  local _, ex = scene({ "CRE GFA214 A320 26.2 50.6 090 FL200 280" })
  check_eq(ex("define waypoint HEM1 at north 25 point 5, east 55 point 25"), "DEFWPT HEM1 25.5 55.25")
  check_eq(ex("move GFA214 to south 1.25 west 3.5"), "MOVE GFA214 -1.25 -3.5")
  asked(ex("move GFA214 to south 1.25"), "a latitude alone")
end

-- Cycle 48 (f110): type names written with the maker's letter before a Boeing variant ("B787-9", "B777-300ER"), an
-- Airbus A318-A321 series ("A321-200"), "DHC-8-400", "Dash 8 300", "CRJ-700", "ATR42", "ATR 72 600"; a variant
-- no type has is asked
do
  local _, ex = scene({})
  check_eq(ex("create KQA5 B787-9 at 1 S 37 E heading 090 FL300 280 knots"), "CRE KQA5 B789 -1 37 90 FL300 280")
  check_eq(ex("create KQA6 A321-200 at 1 S 37 E heading 090 FL300 280 knots"), "CRE KQA6 A321 -1 37 90 FL300 280")
  check_eq(ex("create KQA7 DHC-8-400 at 1 S 37 E heading 090 FL200 240 knots"), "CRE KQA7 DH8D -1 37 90 FL200 240")
  check_eq(ex("create KQA8 Dash 8 300 at 1 S 37 E heading 090 FL200 240 knots"), "CRE KQA8 DH8C -1 37 90 FL200 240")
  check_eq(ex("create KQA9 CRJ-700 at 1 S 37 E heading 090 FL200 240 knots"), "CRE KQA9 CRJ7 -1 37 90 FL200 240")
  check_eq(ex("create KQA11 B777-300ER at 1 S 37 E heading 090 FL300 290 knots"), "CRE KQA11 B77W -1 37 90 FL300 290")
  check_eq(ex("create KQA13 ATR 72 600 at 1 S 37 E heading 090 FL150 220 knots"), "CRE KQA13 AT76 -1 37 90 FL150 220")
  asked(ex("create KQA12 B787-5 at 1 S 37 E heading 090 FL300 280 knots"), "a variant no type has")
end

-- Cycle 48 (f110): a route's last place typed in capitals as a navaid's or fix's ident after "to" ("route via ITPOG
-- to ADS") is its last waypoint; a name that is no airport's is asked, as before
do
  local _, nav = navscene({ "CRE ETH1 B738 8.5 38.5 090 FL200 280" }, "a route's last navaid")
  if nav then
    check_eq(nav("ETH1 route via ITPOG to ADS"), "ADDWPT ETH1 ITPOG ; ADDWPT ETH1 ADS")
    check_eq(nav("ETH1 route via ITPOG to HAAB"), "ADDWPT ETH1 ITPOG ; DEST ETH1 HAAB")
    asked(nav("ETH1 route via ITPOG to Addis"), "a name no airport bears")
  end
end

-- Cycle 48 (f110): a place spelled in the phonetic alphabet after a place's word ("until kilo victor") is the
-- waypoint of the route that spells; a value with its own unit before "until X" is an instruction as a verb's
-- ("keep 250 knots until KV"); "add waypoint P5 to the Kenya" gives the one Kenya flying the waypoint; "stop
-- turn" is the heading flown; "fast time x3" is the rate; when passing a waypoint of the route, a speed with its
-- noun or unit and no verb is flown from there (AT DO); "define a new point NAME at ..." defines it
do
  local s = scene({ "CRE KQA7 B738 -1.2 36.9 090 FL200 280", "DEFWPT KV -1.0 37.5", "ADDWPT KQA7 KV",
    "DEFWPT P5 -1.1 38.0" })
  local opts = { sim = s, mode = "offline", waypoints = { "KV", "P5" } }
  local function ex(text) return said(graph.translate(text, opts)) end
  local r = graph.translate("kqa7 maintain 280 knots until kilo victor", opts)
  check(said(r) == "SPD KQA7 280" and (r.note or ""):find("until KV", 1, true) ~= nil, said(r))
  check_eq(ex("kqa7 keep 250 knots until KV"), "SPD KQA7 250")
  asked(ex("kqa7 maintain 280 knots until kilo whiskey"), "spelled letters no waypoint of the route has")
  check_eq(ex("add waypoint P5 to the Kenya please"), "ADDWPT KQA7 P5")
  check_eq(ex("kqa7 stop turn"), "HDG KQA7 90")
  check_eq(ex("kqa7 stop the turn, climb FL320"), "HDG KQA7 90 ; ALT KQA7 FL320")
  asked(ex("kqa7 turn"), "a turn with no heading")
  check_eq(ex("fast time x3"), "DTMULT 3")
  check_eq(ex("set fast-time at x8"), "DTMULT 8")
  asked(ex("fast time x3 for 5 minutes"), "a rate and a duration")
  check_eq(ex("kqa7 when passing KV speed 230"), "AT KQA7 KV DO SPD KQA7 230")
  check_eq(ex("kqa7 after passing KV 230 knots"), "AT KQA7 KV DO SPD KQA7 230")
  check_eq(ex("kqa7 at KV speed 230"), "AT KQA7 KV SPD 230")
  asked(ex("kqa7 descend FL150, once past KV 230 knots"), "a speed with no verb after a comma and 'once past'")
  check_eq(ex("define a new point ENT2 at 52.1 north 4.2 east"), "DEFWPT ENT2 52.1 4.2")
  asked(ex("define a new point at 52.1 north 4.2 east"), "a new point with no name")
  local two = scene({ "CRE KQA7 B738 -1.2 36.9 090 FL200 280", "CRE KQA8 B738 -1.2 36.5 090 FL220 280",
    "DEFWPT P5 -1.1 38.0" })
  asked(said(graph.translate("add waypoint P5 to the Kenya", { sim = two, mode = "offline", waypoints = { "P5" } })),
    "two Kenya aircraft")
end

-- Cycle 48 (f110): courtesy in the languages of Africa and the Gulf ("asante sana", "abeg", "oya", "ishi", "sawa",
-- "chale", "tamam", "no wahala") carries nothing; a word of them said alone that means something ("wahala") is asked
do
  local _, ex = scene({ "CRE KQA7 B738 -1.2 36.9 090 FL200 280" })
  check_eq(ex("asante sana, kqa7 climb FL320"), "ALT KQA7 FL320")
  check_eq(ex("abeg, freeze the sim"), "HOLD")
  check_eq(ex("oya kqa7 descend FL180"), "ALT KQA7 FL180")
  check_eq(ex("KQA7 ishi, turn left heading 020"), "HDG KQA7 20 LEFT")
  check_eq(ex("tamam, continue"), "OP")
  check_eq(ex("kqa7 climb FL320, no wahala"), "ALT KQA7 FL320")
  asked(ex("kqa7 wahala climb FL320"), "'wahala' alone")
end

-- Cycle 48 (hz55): how fast or hard a change is flown, said as its manner beside the instruction ("quickly",
-- "expedite", "hard", "sharply"), is flown at the aircraft's own rate and named in the note; a gentle manner with no
-- rate said ("slowly", "steadily") is asked, a rate said beside it restates it; the instruction with no value asks
do
  local s, ex = scene({ "CRE MNR4 A320 51.2 3.1 120 FL210 270" })
  local function note(text) return graph.translate(text, { sim = s, mode = "offline" }).note or "" end
  local function noted(text, word)
    check(note(text):find("how fast or hard a change is flown ('" .. word .. "')", 1, true) ~= nil, text)
  end
  check_eq(ex("mnr4 descend FL150 quickly"), "ALT MNR4 FL150")
  noted("mnr4 descend FL150 quickly", "quickly")
  check_eq(ex("mnr4 expedite your descent to FL150"), "ALT MNR4 FL150")
  noted("mnr4 expedite your descent to FL150", "expedite")
  check_eq(ex("mnr4 reduce 240 knots, expedite"), "SPD MNR4 240")
  noted("mnr4 reduce 240 knots, expedite", "expedite")
  check_eq(ex("mnr4 turn hard right heading 200"), "HDG MNR4 200 RIGHT")
  noted("mnr4 turn hard right heading 200", "hard")
  check_eq(ex("mnr4 sharply left heading 060"), "HDG MNR4 60 LEFT")
  check_eq(ex("mnr4 expedite descent"), "ASK What altitude should MNR4 descend to?")
  check_eq(ex("mnr4 climb FL250 slowly"), "ASK I have ALT MNR4 FL250. What does 'slowly' mean?")
  check_eq(ex("mnr4 turn left heading 050 steadily"), "ASK I have HDG MNR4 50 LEFT. What does 'steadily' mean?")
  check_eq(ex("mnr4 climb FL250 at 800 fpm, steadily"), "ALT MNR4 FL250 800")
end

-- Cycle 48 (hz55): terrain or weather named bare beside an instruction ("descend FL150, terrain", "thunderstorms,
-- turn right heading 200") is the instruction's reason: flown, and named in the note as not simulated; a noun of
-- the traffic or the airspace said so ("fuel", "the airport", "spacing" with no "for") is asked
do
  local s, ex = scene({ "CRE MNR4 A320 51.2 3.1 120 FL210 270", "DEFWPT RIVET 51.5 3.6", "ADDWPT MNR4 RIVET" })
  local function note(text) return graph.translate(text, { sim = s, mode = "offline" }).note or "" end
  check_eq(ex("mnr4 descend FL150, terrain"), "ALT MNR4 FL150")
  check(note("mnr4 descend FL150, terrain"):find("terrain and weather ('terrain')", 1, true) ~= nil, "terrain noted")
  check_eq(ex("mnr4 thunderstorms, turn right heading 200"), "HDG MNR4 200 RIGHT")
  check_eq(ex("mnr4 turn right heading 200 to avoid the storms"), "HDG MNR4 200 RIGHT")
  check_eq(ex("mnr4 descend FL150 fuel"), "ASK I have ALT MNR4 FL150. What does 'fuel' mean?")
  check_eq(ex("mnr4 speed 250 the airport"), "ASK I have SPD MNR4 250. What does 'airport' mean?")
  check_eq(ex("mnr4 direct RIVET spacing"), "ASK I have DIRECT MNR4 RIVET. What does 'spacing' mean?")
  check_eq(ex("mnr4 turn right heading 200 for spacing"), "HDG MNR4 200 RIGHT")
end

-- Cycle 48 (hz55): a state reported as reached ("reached", "done", "complete") or a time that puts the instruction off
-- ("soon", "shortly", "in a moment") said after a complete instruction is asked, never dropped: after a value, a
-- place or, with no aircraft named, the command's words; "afterwards" before the next instruction orders them, and a
-- time with its number is scheduled
do
  local _, ex = scene({ "CRE MNR4 A320 51.2 3.1 120 FL210 270", "DEFWPT RIVET 51.5 3.6", "ADDWPT MNR4 RIVET" })
  check_eq(ex("mnr4 descend FL150 reached"), "ASK I have ALT MNR4 FL150. What does 'reached' mean?")
  check_eq(ex("mnr4 direct RIVET done"), "ASK I have DIRECT MNR4 RIVET. What does 'done' mean?")
  check_eq(ex("hold the simulation, done"), "ASK I have HOLD. What does 'done' mean?")
  check_eq(ex("mnr4 climb FL250 shortly"), "ASK I have ALT MNR4 FL250. What does 'shortly' mean?")
  check_eq(ex("ff 30 soon"), "ASK I have FF 30. What does 'soon' mean?")
  check_eq(ex("mnr4 turn left heading 050 level"), "ASK I have HDG MNR4 50 LEFT. What does 'level' mean?")
  check_eq(ex("mnr4 climb FL250 in a moment"),
    "ASK How long should the wait before the instruction be? I heard 'in a moment': please give a time (\"in 2 minutes\").")
  check_eq(ex("mnr4 climb FL250 in 2 minutes"), "DELAY 120 ALT MNR4 FL250")
  check_eq(ex("mnr4 climb FL250 and afterwards reduce 250 knots"), "ALT MNR4 FL250 ; SPD MNR4 250")
  check_eq(ex("please delete mnr4, we'll re-create it in a minute"), "DEL MNR4")
end

-- Cycle 48 (hz55): "right" straight before "now" or "away" is urgency, no turn's side ("right now, mnr4 turn left
-- heading 050" turns left); after a turn's word it stays the side; urgency ("at once", "straight away") changes nothing
do
  local _, ex = scene({ "CRE MNR4 A320 51.2 3.1 120 FL210 270" })
  check_eq(ex("right now mnr4 turn left heading 050"), "HDG MNR4 50 LEFT")
  check_eq(ex("mnr4 turn left heading 050 right away"), "HDG MNR4 50 LEFT")
  check_eq(ex("mnr4 heading 050 right now"), "HDG MNR4 50")
  check_eq(ex("mnr4 turn right now heading 050"), "HDG MNR4 50 RIGHT")
  check_eq(ex("mnr4 descend FL150 at once"), "ALT MNR4 FL150")
  check_eq(ex("mnr4 descend FL150 straight away"), "ALT MNR4 FL150")
end

-- Cycle 48 (hz55): a second value said after a complete instruction is asked, never dropped nor taken in silence: the
-- instruction word said again with another value and no correction ("heading 200 heading 100"), a heading or a time
-- with its unit that no command carries ("..., heading 100" after a creation's heading, "for 5 minutes"), a distance
-- closing the request ("direct RIVET 20 miles"); the same value said again, and a correction, stand
do
  local _, ex = scene({ "CRE MNR4 A320 51.2 3.1 120 FL210 270", "DEFWPT RIVET 51.5 3.6", "ADDWPT MNR4 RIVET" })
  check_eq(ex("mnr4 turn left heading 200 heading 100"),
    "ASK I heard '200' and '100' for one instruction, with no correction between: which one stands?")
  asked(ex("mnr4 speed 250 speed 230"), "two speeds")
  check_eq(ex("mnr4 heading 200 heading 200"), "HDG MNR4 200")
  check_eq(ex("mnr4 heading 200 correction heading 100"), "HDG MNR4 100")
  check_eq(ex("create TST5 A320 at 51.3 3.2 heading 180 FL200 250 knots, heading 100"),
    "ASK I have CRE TST5 A320 51.3 3.2 180 FL200 250. What does '100' mean?")
  check_eq(ex("mnr4 climb FL300 for 5 minutes"), "ASK I have ALT MNR4 FL300. What does '5 minutes' mean?")
  check_eq(ex("ff 5 minutes"), "FF 300")
  check_eq(ex("mnr4 direct RIVET 20 miles"), "ASK I have DIRECT MNR4 RIVET. What does '20 miles' mean?")
  check_eq(ex("mnr4 direct RIVET within 20 miles"), "ASK I have DIRECT MNR4 RIVET. What does '20 miles' mean?")
end

-- Cycle 48 (hz55): an instruction word with no value said after a complete instruction of another kind is asked:
-- "level off" after a heading, a descent after a fast-forward; "level off" after a level and a value's name
-- read by the command it is said with ("back to real time speed") stand
do
  local _, ex = scene({ "CRE MNR4 A320 51.2 3.1 120 FL210 270", "CRE BEL7 A320 51.4 3.3 300 FL230 260" })
  check_eq(ex("mnr4 turn right heading 300 and level off"),
    "ASK I have HDG MNR4 300 RIGHT. What altitude should MNR4 fly to?")
  check_eq(ex("mnr4 descend FL150 and level off"), "ALT MNR4 FL150")
  check_eq(ex("ff 60 descend"), "ASK I have FF 60. Which aircraft should change altitude? Please give its callsign.")
  check_eq(ex("back to real time speed"), "DTMULT 1")
end

-- Cycle 48 (f112): a wait said before an instruction is DELAY or asked, never dropped: "in", "after", a verb of
-- waiting joined to the instruction ("wait ... then", "give it ... and then"), "after waiting", "once ... have
-- passed", "... from now"; a time in words ("a minute", "half a minute", "a minute and a half"); a loose one ("a
-- couple of minutes", "a moment", "a minute or two") asked for a time; a time is carried only by a command that takes
-- one, never by a heading of the same figure
do
  local _, ex = scene({ "CRE DLH7 A320 50.1 8.6 180 FL150 280", "CRE SWR22 A320 50.3 8.9 90 FL170 280" })
  check_eq(ex("give it ninety seconds and then turn DLH7 left heading 090"), "DELAY 90 HDG DLH7 90 LEFT")
  check_eq(ex("wait 2 minutes, then SWR22 climb FL210"), "DELAY 120 ALT SWR22 FL210")
  check_eq(ex("wait for 45 seconds and slow DLH7 to 250 knots"), "DELAY 45 SPD DLH7 250")
  check_eq(ex("allow him a minute, then DLH7 descend FL120"), "DELAY 60 ALT DLH7 FL120")
  check_eq(ex("after a minute SWR22 turn right heading 120"), "DELAY 60 HDG SWR22 120 RIGHT")
  check_eq(ex("in half a minute DLH7 turn left heading 150"), "DELAY 30 HDG DLH7 150 LEFT")
  check_eq(ex("SWR22 climb FL200 in a minute and a half"), "DELAY 90 ALT SWR22 FL200")
  check_eq(ex("SWR22 climb FL200 after waiting 3 minutes"), "DELAY 180 ALT SWR22 FL200")
  check_eq(ex("once 2 minutes have gone by, DLH7 descend FL110"), "DELAY 120 ALT DLH7 FL110")
  check_eq(ex("45 seconds from now SWR22 reduce 240 knots"), "DELAY 45 SPD SWR22 240")
  check_eq(ex("give it one more minute, then SWR22 reduce 240 knots"), "DELAY 60 SPD SWR22 240")
  check_eq(ex("give him another minute and DLH7 descend FL110"), "DELAY 60 ALT DLH7 FL110")
  -- (an amount said loosely is asked)
  check_eq(ex("in about a minute DLH7 descend FL110"), "ASK I have ALT DLH7 FL110. What does 'in about a minute' mean?")
  -- (the same figure as the heading: the time is still the wait's, and asked when nothing reads it)
  check_eq(ex("wait 90 seconds then DLH7 left heading 090"), "DELAY 90 HDG DLH7 90 LEFT")
  check_eq(ex("let 90 seconds pass and then DLH7 left heading 090"),
    "ASK I have HDG DLH7 90 LEFT. What does '90 seconds' mean?")
  -- (a loose time is asked for a time)
  check_eq(ex("in a couple of minutes DLH7 descend FL110"),
    "ASK How long should the wait before the instruction be? I heard 'in a couple of minutes': please give a time (\"in 2 minutes\").")
  check(ex("give it a moment and then SWR22 climb FL210"):find("I heard 'give it a moment'", 1, true) ~= nil, "a moment")
  check(ex("wait a minute or two then DLH7 descend FL110"):find("I heard 'wait a minute or two'", 1, true) ~= nil,
    "a minute or two")
  -- (a verb of waiting not joined to the instruction may be "hold on"; one after it is a wait after it; a time in the
  -- speaker's own clause is no wait of the instruction: all asked)
  check_eq(ex("wait a minute, DLH7 descend FL110"), "ASK I have ALT DLH7 FL110. What does 'wait a minute' mean?")
  check_eq(ex("SWR22 climb FL210 and wait 2 minutes"), "ASK I have ALT SWR22 FL210. What does '2 minutes' mean?")
  check_eq(ex("delete SWR22, we'll re-create it in 3 minutes"), "ASK I have DEL SWR22. What does '3 minutes' mean?")
  -- (rates and pauses keep their words: "a minute" there is no wait)
  check_eq(ex("DLH7 descend at 1500 feet a minute"), "VS DLH7 -1500")
  check_eq(ex("pause the sim for a minute"), "HOLD")
end

-- Cycle 48 (f112): "what's X doing?" asks after an aircraft: a place is never shown for it (a name there that is no
-- callsign is an airline's squawk may not know, asked for); "Orange" is TUI fly Netherlands' telephony (TFL)
do
  local _, ex = scene({ "CRE TFL77 B738 52.3 4.8 90 FL200 280", "CRE KLM5 B738 52.1 4.5 270 FL210 280",
    "DEFWPT RIVRA 52.2 4.6" })
  check_eq(ex("what's the Orange doing?"), "POS TFL77")
  check_eq(ex("Orange 77, descend FL150"), "ALT TFL77 FL150")
  check_eq(ex("what is RIVRA doing"), "ASK Which aircraft should be shown? Please give its callsign.")
  check_eq(ex("where is RIVRA"), "POS RIVRA")
  local _, nav = navscene({ "CRE KLM5 B738 52.1 4.5 270 FL210 280" }, "places asked what they are doing")
  if nav then
    check_eq(nav("what's the Rotterdam doing?"), "ASK I have POS KLM5. What does 'Rotterdam' mean?")
    check_eq(nav("where's Rotterdam?"), "POS EHRD")
  end
end

-- Cycle 48 (f112): a value kept ("keep X at 250 knots", "X keep FL140") is maintained, its end "until" a place on the
-- route named as not simulated; "switch to" / "change to" a speed or Mach is a speed instruction; "once he's there",
-- "when she's level", "once it gets there" wait for the level cleared before
do
  local _, ex = scene({ "CRE AFR33 A320 48.9 2.6 90 FL220 290", "DEFWPT KOVAL 49.0 3.4", "DEFWPT MERUE 49.5 3.0",
    "ADDWPT AFR33 KOVAL" })
  check_eq(ex("keep AFR33 at 290 knots until KOVAL"), "SPD AFR33 290")
  check_eq(ex("AFR33 keep FL220 until KOVAL"), "ALT AFR33 FL220")
  check(ex("keep AFR33 at 290 knots until MERUE"):match("^ASK MERUE is not on AFR33's route") ~= nil, "off the route")
  check_eq(ex("AFR33 change to 270 knots"), "SPD AFR33 270")
  check_eq(ex("AFR33 climb FL260 and once he's there switch to mach .78"), "ALT AFR33 FL260 ; ATALT AFR33 FL260 SPD AFR33 M0.78")
  check_eq(ex("AFR33 climb FL260 and when she's level, 280 knots"), "ALT AFR33 FL260 ; ATALT AFR33 FL260 SPD AFR33 280")
  check_eq(ex("AFR33 climb FL260 and once it gets there mach .78"), "ALT AFR33 FL260 ; ATALT AFR33 FL260 SPD AFR33 M0.78")
  -- (no level cleared before: still asked)
  check(ex("AFR33 once he's there switch to mach .78"):match("^ASK") ~= nil, "no level before")
end

-- Cycle 48 (f112): a value said after "instead of", "rather than" or "in place of" is the one replaced, never read;
-- "normal speed" after a clause of its own is real time; "speed things up, times four" is the clock's rate; "this is
-- the conflict scenario" names the scenario running, no file to load
do
  local _, ex = scene({ "CRE AFR33 A320 48.9 2.6 90 FL220 290" })
  check_eq(ex("set the zone radius to four miles rather than five"), "ZONER 4")
  check_eq(ex("AFR33 climb FL260 instead of FL240"), "ALT AFR33 FL260")
  check_eq(ex("AFR33 reduce 250 knots in place of 270"), "SPD AFR33 250")
  check(ex("zoner 4 and zoner 5"):match("^ASK") ~= nil, "two radii")
  check_eq(ex("okay, start again, normal speed"), "OP ; DTMULT 1")
  check_eq(ex("speed things up a little, times three"), "DTMULT 3")
  check(ex("speed things up"):match("^ASK") ~= nil, "no rate said")
  check_eq(ex("right, this is the baseline scenario. Conflict detection on please"), "ASAS ON")
  check_eq(ex("load the baseline scenario"), "ASK Which scenario file should I load?")
end

-- Cycle 48 (f112): one aircraft said by "him", "her" (or "it" straight after the instruction word) with two named
-- before it is asked, never both instructed; one neared ("creeping up on the Easy", "closing on X") is traffic, not
-- instructed; "Quality" is ASL Airlines Belgium's telephony (TAY)
do
  local _, ex = scene({ "CRE AFR33 A320 48.9 2.6 90 FL220 290", "CRE EZY80 A320 49.0 2.9 270 FL220 280",
    "CRE TAY4K B744 49.2 2.4 180 FL180 260" })
  check_eq(ex("AFR33 is close to EZY80, turn her left heading 030"),
    "ASK Which aircraft is 'her': AFR33 or EZY80? Please give its callsign.")
  check_eq(ex("AFR33 and EZY80 are close, descend it FL200"),
    "ASK Which aircraft is 'it': AFR33 or EZY80? Please give its callsign.")
  check_eq(ex("AFR33 and EZY80, turn them left heading 030"), "HDG AFR33 30 LEFT ; HDG EZY80 30 LEFT")
  check_eq(ex("AFR33 is closing on the Easy, give him heading 030"), "HDG AFR33 30")
  check_eq(ex("AFR33 is creeping up on EZY80, slow him to 250"), "SPD AFR33 250")
  check_eq(ex("Quality four kilo, descend FL160"), "ALT TAY4K FL160")
end

-- Cycle 48 (f112): a crossing with no aircraft named asks for the aircraft, not whether the waypoint is meant
do
  local _, ex = scene({ "CRE AFR33 A320 48.9 2.6 90 FL220 290", "DEFWPT KOVAL 49.0 3.4", "ADDWPT AFR33 KOVAL",
    "CRE EZY80 A320 49.0 2.9 270 FL220 280" })
  check_eq(ex("cross KOVAL at FL180"), "ASK Which aircraft should cross KOVAL? Please give its callsign.")
  check_eq(ex("Air France, cross KOVAL at FL180"), "ASK Which aircraft should cross KOVAL? Please give its callsign.")
  check_eq(ex("AFR33, cross KOVAL at FL180"), "AT AFR33 KOVAL ALT FL180")
end

-- Cycle 48 (f115): a level or heading said digit by digit and run on into a speed before "knots" with no break is
-- split where each part is what it can be (lexicon.run_on); digits that split no such way are asked, and a
-- creation's flight level is held to the bounds a climb's is
do
  local _, ex = scene({ "CRE MPH5 B744 52.3 4.8 090 FL200 280" })
  check_eq(ex("mph5 descend flight level nine zero two one zero knots"), "ALT MPH5 FL90 ; SPD MPH5 210")
  check_eq(ex("mph5 climb flight level three three zero two niner zero knots"), "ALT MPH5 FL330 ; SPD MPH5 290")
  check_eq(ex("mph5 descend flight level one twenty two thirty knots"), "ALT MPH5 FL120 ; SPD MPH5 230")
  check_eq(ex("mph5 turn left heading three one zero two thirty knots"), "HDG MPH5 310 LEFT ; SPD MPH5 230")
  check_eq(ex("create TST9 A320 at 52.0 4.0 heading zero niner zero flight level seven zero two five zero knots"),
    "CRE TST9 A320 52 4 90 FL70 250")
  -- (FL12 and 180 kt, or FL121 and 80 kt: neither fits)
  asked(ex("mph5 descend flight level one two one eight zero knots"), "a run that splits no way is asked")
  -- (no unit after the run: the level read is out of bounds)
  asked(ex("mph5 descend flight level seven zero two five zero"), "FL702 is asked")
  asked(ex("create TST9 A320 at 52.0 4.0 heading zero niner zero flight level seven zero two five zero"),
    "a creation at FL702 is asked")
  asked(ex("create TST9 A320 at 52.0 4.0 heading 090 flight level two zero speed 250"), "a spoken FL20 is asked")
  asked(ex("create TST9 A320 at 52.0 4.0 heading 090 flight level 9000 speed 250"), "flight level 9000 is asked")
  asked(ex("create TST9 A320 at 52.0 4.0 heading three one zero two three zero flight level 100"),
    "a heading beyond 360 is asked")
end

-- Cycle 48 (f115): Dutch words in a Dutch or Belgian controller's or sim operator's English are read through
-- lexicon.said_whole.dutch, as German; a Dutch word the table lacks is still asked about by name
do
  local _, ex = scene({ "CRE KLM77 B738 52.1 4.5 180 FL150 250", "CRE TRA6 B738 52.3 4.1 090 FL200 260" })
  check_eq(ex("pauzeer de simulatie graag"), "HOLD")
  check_eq(ex("zet de simulatie op vier keer"), "DTMULT 4")
  check_eq(ex("verwijder klm seven seven"), "DEL KLM77")
  check_eq(ex("gooi transavia six weg"), "DEL TRA6")
  check_eq(ex("klm seven seven draai rechts koers twee zeven nul"), "HDG KLM77 270 RIGHT")
  check_eq(ex("klm seven seven daal naar vliegniveau een twee nul"), "ALT KLM77 FL120")
  check_eq(ex("wat doet transavia six"), "POS TRA6")
  check_eq(ex("conflict detectie aan"), "ASAS ON")
  check_eq(ex("ja klm seven seven descend flight level one two zero"), "ALT KLM77 FL120")
  check_eq(ex("maak een nieuw vliegtuig aan klm one two three a three twenty at 52.0 4.0 heading 090 fl100 250 knots"),
    "CRE KLM123 A320 52 4 90 FL100 250")
  check_eq(ex("trails aan graag snel"), "ASK I have TRAIL ON. What does 'snel' mean?")
  asked(ex("zet een waypoint"), "'een' as an article elsewhere is asked")
  -- (German stays German: "vier" and "acht" are said the same in both)
  check_eq(ex("klm seven seven sinken flight level acht null bitte"), "ALT KLM77 FL80")
  -- an acknowledgement opening the request with no break after it is the aside; after a value it is still asked
  check_eq(ex("oké pauzeer de simulatie"), "HOLD")
  check_eq(ex("alles klar klm seven seven descend flight level one two zero"), "ALT KLM77 FL120")
  asked(ex("klm seven seven descend flight level one two zero oke heading 200"), "'oke' after a value is asked")
end

-- Cycle 48 (f115): a word typed in capitals is a name or a code, never a word of a language said whole ("over OKE":
-- the VOR, where "oké" is Dutch)
do
  local _, ex = navscene({ "CRE LOT7 B738 52.4 20.9 300 FL150 270" }, "a navaid typed in capitals")
  if ex then
    check_eq(ex("LOT7 at 20 miles from OKE descend FL80"), "ATDIST LOT7 OKE 20 ALT LOT7 FL80")
    check_eq(ex("create LOT3921 E190 over OKE heading 270 8000 ft 250 kt"), "CRE LOT3921 E190 OKE 270 8000 250")
  end
end

-- Cycle 48 (f115): a Boeing family's variant said as one number after the family ("seven eight seven nine", "787 8")
-- is that variant when the name is the same designator as its hundreds ("787-9", "787-900"); "737 8" (737-8, the MAX
-- 8, or the 737-800 said short) is still asked. "Boeing seven three eight", the designator's digits after the maker,
-- is that designator; a family's number so said ("Boeing seven three seven") is still asked
do
  local _, ex = scene({ "CRE KLM12 B738 52.0 4.0 090 FL200 280" })
  check_eq(ex("create klm eight seven one boeing seven eight seven nine at 52.2 4.2 heading 270 fl310 280 knots"),
    "CRE KLM871 B789 52.2 4.2 270 FL310 280")
  check_eq(ex("create klm eight seven two boeing 787 8 at 52.2 4.2 heading 270 fl310 280 knots"),
    "CRE KLM872 B788 52.2 4.2 270 FL310 280")
  check_eq(ex("create klm eight seven three boeing seven eight seven ten at 52.2 4.2 heading 270 fl310 280 knots"),
    "CRE KLM873 B78X 52.2 4.2 270 FL310 280")
  check_eq(ex("create klm eight seven four boeing seven three eight at 52.2 4.2 heading 270 fl310 280 knots"),
    "CRE KLM874 B738 52.2 4.2 270 FL310 280")
  check_eq(ex("create klm eight seven five boeing seven four four at 52.2 4.2 heading 270 fl310 280 knots"),
    "CRE KLM875 B744 52.2 4.2 270 FL310 280")
  asked(ex("create klm eight seven six boeing seven three seven eight at 52.2 4.2 heading 270 fl310 280 knots"),
    "737 and 8: the MAX 8 or the 737-800")
  asked(ex("create klm eight seven seven boeing seven three seven at 52.2 4.2 heading 270 fl310 280 knots"),
    "a 737 without its variant")
end

-- Cycle 48 (f115): the telephony of the Netherlands' and Belgium's leisure and regional airlines ("city" KLM
-- Cityhopper, "orange" TUI fly Netherlands, "corendon" Corendon Airlines, "dutch corendon" Corendon Dutch Airlines,
-- "france soleil" Transavia France) is read wherever a callsign stands; an airline heard that the aircraft's is not
-- is still confirmed
do
  local _, ex = scene({ "CRE KLC43X E175 51.95 4.20 150 4000 220", "CRE TFL8HC B38M 51.20 5.95 345 FL140 280",
    "CRE CAI4LT B738 50.90 5.00 250 FL370 275", "CRE CND55B B738 51.30 4.40 020 FL090 260",
    "CRE TVF63RA A320 51.40 4.00 190 FL340 280" })
  check_eq(ex("remove city four three x ray"), "DEL KLC43X")
  check_eq(ex("klm city four three x ray climb flight level one zero zero"), "ALT KLC43X FL100")
  check_eq(ex("list the route of orange eight hotel charlie"), "LISTRTE TFL8HC")
  check_eq(ex("delete corendon four lima tango"), "DEL CAI4LT")
  check_eq(ex("where is dutch corendon five five bravo"), "POS CND55B")
  check_eq(ex("delete france soleil six three romeo alpha"), "DEL TVF63RA")
  check_eq(ex("corendon five five bravo turn left heading 100"), "ASK Did you mean CND55B? I heard CAI55B.")
end

-- Cycle 48 (f115): a level said group-wise after "passing", "leaving" or "reaching" ("passing one hundred") is that
-- flight level for an aircraft at or above lexicon.groupwise_from_ft, as a climb's is; lower down it is asked
do
  local _, ex = scene({ "CRE KLM1234 B738 52.4 6.3 275 FL120 290", "CRE KLM12 B738 52.4 6.3 275 8000 250" })
  check_eq(ex("klm one two three four descend flight level seven zero and passing one hundred reduce two five zero"),
    "ALT KLM1234 FL70 ; ATALT KLM1234 FL100 SPD KLM1234 250")
  check_eq(ex("klm one two three four climb flight level two hundred, leaving one hundred fifty speed two eight zero"),
    "ALT KLM1234 FL200 ; ATALT KLM1234 FL150 SPD KLM1234 280")
  asked(ex("klm one two descend five thousand feet and passing one hundred reduce two two zero"),
    "below 10000 ft 'one hundred' may be feet")
end

-- Cycle 48 (f115): Brussels's airport (BRUSSELS NATL; BRUSSELS SOUTH is Charleroi's) and the ABC islands' airports
-- by the island's name (lexicon.city_airports); a distance from a name navaids bear beside the airport is still asked
do
  local _, ex = navscene({ "CRE KLM1 B738 51 4 90 FL100 250" }, "airports by a city's or an island's name")
  if ex then
    check_eq(ex("klm one destination brussels"), "DEST KLM1 EBBR")
    check_eq(ex("set wind two four zero degrees twenty five knots over brussels airport"), "WIND EBBR 240 25")
    check_eq(ex("klm one origin schiphol destination curacao"), "ORIG KLM1 EHAM ; DEST KLM1 TNCC")
    check_eq(ex("klm one destination aruba"), "DEST KLM1 TNCA")
    asked(ex("klm one at 30 miles from brussels descend fl80"), "the airport or a Brussels navaid")
  end
end

-- Cycle 48 (f115), decisions kept: a creation with its callsign, type and place only is CRE with the command's
-- defaults (some 40 rows of older rounds expect it); a value that would leave one before it at 0 is asked. A climb
-- or descent rate said with no level is VS (some 300 older rows expect it); the verb with neither is asked
do
  local _, ex = scene({ "CRE EZY4612 A320 53.5 5.0 100 FL340 280" })
  check_eq(ex("create klm one two three a three twenty at 52.0 4.0"), "CRE KLM123 A320 52 4")
  asked(ex("create klm one two three a three twenty at 52.0 4.0 flight level one zero zero"), "no heading before it")
  check_eq(ex("easy four six one two climb at one thousand feet per minute"), "VS EZY4612 1000")
  asked(ex("easy four six one two climb"), "no level and no rate")
end

-- Cycle 48 (f114): conflict resolution switched on in a clause of its own beside its vertical method ("turn on
-- MVP resolution and let it use vertical too") sets both, RESO and RMETHV; the resolution named inside the
-- vertical's clause sets the method alone, and vertical-only resolutions are still asked
do
  local _, ex = scene({ "CRE AAL12 B738 41.9 -87.9 090 FL250 280", "CRE UAL34 B739 42.1 -87.5 270 FL250 280" })
  check_eq(ex("enable MVP resolution and allow vertical manoeuvres"), "RESO MVP ; RMETHV V/S")
  check_eq(ex("set reso to MVP, and let it resolve vertically too"), "RESO MVP ; RMETHV V/S")
  check_eq(ex("turn on MVP and no vertical resolutions"), "RESO MVP ; RMETHV OFF")
  check_eq(ex("let MVP use vertical speed in the resolutions"), "RMETHV V/S")
  asked(ex("turn on MVP resolution, vertical only"), "vertical-only resolutions beside the method switched on")
end

-- Cycle 48 (f114): "descend two thousand feet" spoken straight after the verb from the flight levels is asked to
-- or by, as the same typed in figures is; "to", "by", "and maintain", 4000 ft or more, or a descent from below
-- FL120 decide it
do
  local _, ex = scene({ "CRE SKW12 CRJ7 40.5 -103 245 FL180 270", "CRE SKW34 CRJ7 40.5 -104 245 9000 250" })
  check_eq(ex("SKW12 descend two thousand feet"), "ASK Should SKW12 descend to 2000 ft or by 2000 ft?")
  asked(ex("SKW12 descend two thousand five hundred feet"), "a spoken step or level of 2500 ft from FL180")
  check_eq(ex("SKW12 descend to two thousand feet"), "ALT SKW12 2000")
  check_eq(ex("SKW12 descend by two thousand feet"), "ALT SKW12 16000")
  check_eq(ex("SKW12 descend and maintain two thousand feet"), "ALT SKW12 2000")
  check_eq(ex("SKW12 descend five thousand feet"), "ALT SKW12 5000")
  check_eq(ex("SKW34 descend three thousand feet"), "ALT SKW34 3000")
end

-- Cycle 48 (f114): a station's simulator addressed before a comma, colon or dash ("Denver sim, ...", "A80 sim -
-- ...") names the addressee, no callsign needed: a capitalised name or identifier, or a known place in lower case;
-- other words there, and an aircraft flying, are still asked about
do
  local _, ex = scene({ "CRE AAL12 B738 41.9 -87.9 090 FL250 280" })
  check_eq(ex("Denver sim, turn on conflict detection"), "ASAS ON")
  check_eq(ex("A80 sim - run it at four times speed"), "DTMULT 4")
  check_eq(ex("ZNY sim: pause"), "HOLD")
  check_eq(ex("Boston sim, AAL12 climb FL300"), "ALT AAL12 FL300")
  check_eq(ex("flurb sim, pause"), "ASK I have HOLD. What does 'flurb' mean?")
  check_eq(ex("AAL12 sim, pause"), "ASK I have HOLD. What does 'AAL12' mean?")
end

-- Cycle 48 (f114): the conflict probe or a display's conflict alert switched where it is said ("conflict alerts
-- on, lookahead two minutes") is conflict detection beside its look-ahead; unswitched, or with an aircraft named,
-- it names an alert, no setting
do
  local _, ex = scene({ "CRE AAL12 B738 41.9 -87.9 090 FL250 280" })
  check_eq(ex("conflict alerts on, lookahead two minutes"), "ASAS ON ; DTLOOK 120")
  check_eq(ex("conflict probe on, look ahead 3 minutes"), "ASAS ON ; DTLOOK 180")
  check_eq(ex("turn on conflict alerting"), "ASAS ON")
  check_eq(ex("look ahead 2 minutes on the conflict probe"), "DTLOOK 120")
  check_eq(ex("the conflict alert zone 5 miles"), "ZONER 5")
  check_eq(ex("AAL12 conflict alert, turn left heading 360"), "HDG AAL12 360 LEFT")
  asked(ex("conflict alerts"), "conflict alerts named with no switch")
end

-- Cycle 48 (f114): "resume normal speed" (or "published speed") as the whole request to an aircraft flying its
-- route's profile (LNAV and VNAV on) gives the profile's speed back, VNAV ON; to one flying no profile, or beside
-- another instruction VNAV ON would undo, it is named as not simulated or asked, as before
do
  local _, ex = scene({ "DEFWPT AAA 41.5 -82", "DEFWPT BBB 41.8 -82.5", "CRE DAL14 A320 41 -82 280 FL250 290",
    "ADDWPT DAL14 AAA", "ADDWPT DAL14 BBB", "VNAV DAL14 ON", "SPD DAL14 250", "CRE UAL25 B738 41 -81 280 FL250 290",
    "ADDWPT UAL25 AAA" })
  check_eq(ex("DAL14 resume normal speed"), "VNAV DAL14 ON")
  check_eq(ex("DAL14, resume published speed."), "VNAV DAL14 ON")
  check_eq(ex("UAL25 resume normal speed"), "")
  asked(ex("DAL14 turn left heading 250, resume normal speed"), "a heading VNAV ON would undo")
  asked(ex("DAL14 resume normal speed, 250 knots"), "a speed given beside the normal speed")
end

-- Cycle 48 (f114): "comply with restrictions" (the route's published levels and speeds) is VNAV ON, beside a
-- direct-to too; beside a level, heading, rate or speed given it is asked (VNAV ON would replace it), and so is an
-- aircraft with no route, or restrictions of one kind only
do
  local _, ex = scene({ "DEFWPT AAA 41.5 -82", "DEFWPT BBB 41.8 -82.5", "CRE DAL14 A320 41 -82 280 FL250 290",
    "ADDWPT DAL14 AAA", "ADDWPT DAL14 BBB", "CRE N12AB C172 41 -80 90 3000 100" })
  check_eq(ex("DAL14 proceed direct BBB, comply with restrictions"), "DIRECT DAL14 BBB ; VNAV DAL14 ON")
  check_eq(ex("DAL14 comply with published speed and altitude restrictions"), "VNAV DAL14 ON")
  check_eq(ex("DAL14 descend FL240, comply with restrictions"),
    "ASK Should DAL14 fly the level given, or its route's restrictions (VNAV ON), which would replace it?")
  asked(ex("DAL14 reduce speed 250, comply with restrictions"), "a speed VNAV ON would replace")
  asked(ex("N12AB comply with restrictions"), "no route whose restrictions it could fly")
  asked(ex("DAL14 comply with speed restrictions"), "restrictions of one kind only")
end

-- Cycle 48 (f114): a level said straight after "after" before an instruction ("after one two thousand increase
-- speed to 300") is one passed, as "after passing" is (ATALT); a time after it stays a delay, a place a waypoint's
-- condition, and a climb's rate after it is still asked
do
  local _, ex = scene({ "CRE AAL22 A321 40.85 -73.60 035 9000 250" })
  check_eq(ex("AAL22 climb and maintain one seven thousand, after one two thousand increase speed to three hundred knots"),
    "ALT AAL22 17000 ; ATALT AAL22 12000 SPD AAL22 300")
  check_eq(ex("AAL22 climb and maintain 17000, after 12000 turn left heading 300"),
    "ALT AAL22 17000 ; ATALT AAL22 12000 HDG AAL22 300 LEFT")
  check_eq(ex("AAL22 after 2 minutes turn left heading 200"), "DELAY 120 HDG AAL22 200 LEFT")
  asked(ex("AAL22 climb and maintain 17000, after 12000 climb at 1500 fpm"), "a rate after a level passed")
end

-- Cycle 48 (f114): a level straight after "above" or "below" beside an instruction or alone in its clause is a
-- condition or a bound, never the level flown and never dropped: asked unless a command carries it ("250 kt below
-- FL100" is still the speed from that level); a remark on a limit is no instruction
do
  local _, ex = scene({ "CRE AAL22 A321 40.85 -73.60 035 9000 250" })
  -- (a bare bound opening a speed's clause, crossed climbing into "above": the band's level, cycle 53 fus)
  check_eq(ex("AAL22 climb and maintain 17000, above one two thousand increase speed to 300 knots"),
    "ALT AAL22 17000 ; ATALT AAL22 12000 SPD AAL22 300")
  asked(ex("AAL22 climb and maintain 17000 above FL120"), "a bound level beside the level cleared")
  asked(ex("AAL22 above 12000 increase speed to 300 knots"), "a bound before a speed")
  asked(ex("AAL22 reduce speed to 250 knots below 10000"), "a bound after a speed, no unit")
  check_eq(ex("AAL22 reduce speed to 250 knots below one zero thousand"), "ATALT AAL22 10000 SPD AAL22 250")
  check_eq(ex("AAL22 speed 250 knots, this is the normal limit below ten thousand"), "SPD AAL22 250")
end

-- Cycle 48 (f114): a clause opened by "at", "after" or "over" and a waypoint behind a comma or "then", after an
-- instruction's value and before the next instruction ("descend and maintain 12000, at BBB reduce speed to 250"),
-- starts that next instruction there (AT DO); off the route, or with no instruction after it, asked; a value with
-- no verb after the waypoint stays the constraint
do
  local _, ex = scene({ "DEFWPT AAA 39.7 -78", "DEFWPT BBB 39.8 -77.6", "DEFWPT CCC 40 -77",
    "CRE AAL19 A321 39.60 -78.20 100 FL240 290", "ADDWPT AAL19 AAA", "ADDWPT AAL19 BBB" })
  check_eq(ex("AAL19, descend and maintain one two thousand, at BBB reduce speed to two five zero"),
    "ALT AAL19 12000 ; AT AAL19 BBB DO SPD AAL19 250")
  check_eq(ex("AAL19 reduce speed to 250, at BBB descend and maintain 10000"),
    "SPD AAL19 250 ; AT AAL19 BBB DO ALT AAL19 10000")
  check_eq(ex("AAL19 descend FL200 then after BBB turn left heading 300"),
    "ALT AAL19 FL200 ; AT AAL19 BBB DO HDG AAL19 300 LEFT")
  asked(ex("AAL19 descend FL200, at CCC reduce 250"), "a waypoint off the route")
  asked(ex("AAL19 descend FL200, at BBB"), "no instruction after the waypoint")
  check_eq(ex("AAL19, descend FL200, at BBB 250 knots"), "ALT AAL19 FL200 ; AT AAL19 BBB SPD 250")
end

-- Cycle 48 (f114): "once slowed", "when you've slowed down" after a speed given waits for that speed (ATSPD);
-- after a level, or with nothing before it, asked
do
  local _, ex = scene({ "CRE SWA34 B737 39.80 -76.30 205 13000 270" })
  check_eq(ex("SWA34 reduce speed to two three zero, once slowed descend and maintain six thousand"),
    "SPD SWA34 230 ; ATSPD SWA34 230 ALT SWA34 6000")
  check_eq(ex("SWA34 reduce speed to 230, when you've slowed down descend 6000"),
    "SPD SWA34 230 ; ATSPD SWA34 230 ALT SWA34 6000")
  asked(ex("SWA34 descend 8000, once slowed reduce 230"), "slowing after a level")
  asked(ex("SWA34 once slowed descend 6000"), "slowing with no speed before it")
end

-- Cycle 48 (f114): a navaid said by its name where a limit ends ("until Yardley", "until the Yardley VOR") or as a
-- place of a route listed with "then" or "and" ("direct Joliet, then Northbrook", "a route via Joliet and DuPage")
-- is read as its ident typed is; off the route a limit is asked; a name after a comma alone says the place before
-- again ("direct OBK, Northbrook"). "a route: direct A, then B" to an aircraft with no route is the route listed
do
  local nav, pt = navscene({ "CRE UAL12 B738 40.00 -75.30 050 11000 260", "ADDWPT UAL12 ARD", "ADDWPT UAL12 SBJ",
    "CRE SWA7 B737 41.7 -88.2 090 FL200 280" }, "navaids by name in limits and route lists")
  if nav then
    check_eq(pt("UAL12 maintain 250 knots till Yardley"), "SPD UAL12 250")
    check_eq(pt("UAL12 maintain 250 knots until the Yardley VOR"), "SPD UAL12 250")
    asked(pt("UAL12 maintain 250 knots until Robbinsville"), "a limit ending at a navaid off the route")
    check_eq(pt("SWA7 direct Joliet, then Northbrook"), "ADDWPT SWA7 JOT ; DIRECT SWA7 JOT ; ADDWPT SWA7 OBK")
    check_eq(pt("give SWA7 a route: direct Northbrook, then Joliet"), "ADDWPT SWA7 OBK ; ADDWPT SWA7 JOT")
    check_eq(pt("give SWA7 a route via Joliet and DuPage"), "ADDWPT SWA7 JOT ; ADDWPT SWA7 DPA")
    check_eq(pt("SWA7 direct OBK, Northbrook"), "ADDWPT SWA7 OBK ; DIRECT SWA7 OBK")
  end
end

-- Cycle 48 (f114): a name written with "O'" ("O'Hare") is the navdata's, which has no apostrophe; "o'clock" stays
do
  local nav, pt = navscene({ "CRE SWA7 B737 41.7 -88.2 090 FL200 280" }, "a name written with O'")
  if nav then
    check_eq(pt("SWA7's destination is O'Hare"), "DEST SWA7 KORD")
    check_eq(pt("SWA7 direct to Chicago O'Hare"), "ADDWPT SWA7 KORD ; DIRECT SWA7 KORD")
    check_eq(pt("traffic at 2 o'clock, SWA7 turn left heading 300"), "")
  end
end

-- Cycle 48 (f114): a wind's direction in spoken digits before "at" and its speed ("two four zero at three five
-- knots"), and a place named by a distinctive word of a nearby airport's name ("over Midway"), are read for WIND and
-- GETWIND as a destination's are; a name that means no place is still asked
do
  local nav, pt = navscene({ "CRE SWA7 B737 41.7 -88.2 090 FL200 280" }, "a wind over an airport by its name")
  if nav then
    check_eq(pt("set wind two four zero at three five knots over Midway"), "WIND KMDW 240 35")
    check_eq(pt("getwind over Midway"), "GETWIND KMDW")
    asked(pt("set wind 270 at 50 knots over Flurbington"), "a name that means no place")
  end
end

-- Cycle 48 (hz56): "no" straight before an instruction's verb or noun, no comma between ("SAS77 no descend FL090",
-- "no climbing", "no descent", "no left turn"), may refuse it (English as a second language) as well as correct what
-- came before: asked, naming both readings, with no word to ignore; "no, descend", "negative descend" and "no...
-- descend" stay corrections, a side corrected after a value ("090 no right heading 200") too
do
  local s, ex = scene({ "CRE SAS77 A320 55.0 12.0 090 FL200 250", "CRE FIN8 A321 55.2 12.2 270 FL240 260" })
  check_eq(ex("SAS77 no descend FL090"),
    "ASK I have ALT SAS77 FL90. Is 'no descend' a refusal (do not), or a correction ('no, descend')? Please say it again.")
  check(graph.translate("SAS77 no descend FL090", { sim = s, mode = "offline" }).ignorable == nil, "no word to ignore")
  asked(ex("FIN8 no turn right heading 300"), "'no turn'")
  asked(ex("FIN8 no climbing flight level three zero zero"), "'no climbing'")
  asked(ex("SAS77 no descent FL120"), "'no descent'")
  asked(ex("FIN8 no left turn heading 200"), "'no left turn'")
  asked(ex("SAS77 no uh reduce speed 220"), "'no' and a hesitation before the verb")
  asked(ex("FIN8 heading 270, no turn right heading 300"), "'no turn' after a value and a comma")
  asked(ex("no proceed direct to the beacon SAS77"), "'no proceed'")
  check_eq(ex("SAS77 no, descend FL090"), "ALT SAS77 FL90")
  check_eq(ex("SAS77 negative descend FL090"), "ALT SAS77 FL90")
  check_eq(ex("FIN8 no... climb FL300"), "ALT FIN8 FL300")
  check_eq(ex("FIN8 turn left heading 090 no right heading 200"), "HDG FIN8 200 RIGHT")
  check_eq(ex("SAS77 no speed restriction, descend FL150"), "ALT SAS77 FL150")
end

-- Cycle 48 (hz56): a word said where a direct-to's place goes that names no place ("direct DME", "direct the
-- beacon", "direct that fix", "direct there", "direct eleven") is asked about by name, never read as the route's only
-- waypoint; "proceed direct" with nothing after it still flies to that one waypoint
do
  local _, ex = scene({ "DEFWPT HZR1 55.3 12.6", "DEFWPT HZR2 55.1 13.0", "CRE SAS77 A320 55.0 12.0 090 FL200 250",
    "ADDWPT SAS77 HZR1" })
  check_eq(ex("SAS77 direct DME"), "ASK Which waypoint is 'DME'? Please say its name for SAS77 to fly direct to.")
  check_eq(ex("SAS77 proceed direct to the beacon"),
    "ASK Which waypoint is 'the beacon'? Please say its name for SAS77 to fly direct to.")
  asked(ex("SAS77 direct that fix"), "a fix pointed at")
  asked(ex("SAS77 direct there"), "'there' with no place before it")
  asked(ex("SAS77 turn right direct the VOR, climb FL300"), "a navaid's kind alone")
  asked(ex("SAS77 direct eleven"), "a number where the place goes")
  check_eq(ex("SAS77 proceed direct"), "DIRECT SAS77 HZR1")
  check_eq(ex("SAS77 proceed direct, climb FL300"), "DIRECT SAS77 HZR1 ; ALT SAS77 FL300")
  check_eq(ex("SAS77 add HZR2 and then go direct there"), "ADDWPT SAS77 HZR2 ; DIRECT SAS77 HZR2")
end

-- Cycle 48 (hz56): an instruction for an aircraft named before it and another aircraft named after all of it with
-- nothing of its own ("sas77 hdg 100 and fin8", "sas77 fl310, fin8", "sas77 direct HZR1 fin8", after the instruction
-- before: "sas77 climb fl300, heading 100, fin8") is asked: which aircraft it is for, naming both, never offered to
-- the later one alone. Aircraft named together before it ("sas77 and fin8 fl310") or one added ("fin8 too") get it;
-- one with a value of its own has its own request
do
  local _, ex = scene({ "DEFWPT HZR1 55.3 12.6", "CRE SAS77 A320 55.0 12.0 090 FL200 250", "ADDWPT SAS77 HZR1",
    "CRE FIN8 A321 55.2 12.2 270 FL240 260" })
  -- (the question names both aircraft and offers neither the instruction)
  local function which(text, why) check(ex(text):match("^ASK Which aircraft is .*SAS77, FIN8 or both%?") ~= nil, why) end
  check_eq(ex("sas77 hdg 100 and fin8"),
    "ASK Which aircraft is 'heading 100' for: SAS77, FIN8 or both? Please say each aircraft with its own instruction.")
  which("sas77 climb fl310, fin8", "a level, then another aircraft after a comma")
  which("sas77 fl310 fin8", "a verbless level, then another aircraft")
  which("sas77 fl310 and fin8", "a verbless level, then 'and' another aircraft")
  which("sas77 direct HZR1 and fin8", "a direct-to, then another aircraft")
  which("sas77 reduce speed 220 and fin8 thanks", "another aircraft and thanks")
  which("sas77 climb fl300, heading 100, fin8", "an aircraft after the instruction after another's")
  check_eq(ex("sas77 and fin8 fl310"), "ALT SAS77 FL310 ; ALT FIN8 FL310")
  check_eq(ex("sas77 and fin8 climb fl310"), "ALT SAS77 FL310 ; ALT FIN8 FL310")
  check_eq(ex("sas77 hdg 100 and fin8 too"), "HDG SAS77 100 ; HDG FIN8 100")
  check_eq(ex("sas77 hdg 100 and fin8 fl310"), "HDG SAS77 100 ; ALT FIN8 FL310")
  check_eq(ex("heading 100, fin8"), "HDG FIN8 100")
  check_eq(ex("sas77 descend fl120, sas77"), "ALT SAS77 FL120")
end

-- Cycle 48 (hz57): a rate's manner said with no value ("at a good rate", "best rate of climb") is noted as "expedite"
-- is and never makes a later number the rate; a gentler one is asked; a number is a rate only with a rate's unit or
-- after the rate's word, never an altitude with its unit after "to"
do
  local _, ex = scene({ "CRE SVA31 A320 24.7 46.7 250 FL210 270" })
  local r = graph.translate("at a good rate SVA31 descend to 9000 feet", { sim = _, mode = "offline" })
  check(said(r) == "ALT SVA31 9000" and r.note:find("'at a good rate'", 1, true) ~= nil, said(r))
  check_eq(ex("sva31 climb at a high rate to 25000 feet"), "ALT SVA31 25000")
  check_eq(ex("sva31 good rate of descent, descend FL150"), "ALT SVA31 FL150")
  check_eq(ex("sva31 descend FL150 at your best rate of descent"), "ALT SVA31 FL150")
  check_eq(ex("sva31 descend with a healthy rate to 3000 metres"), "ALT SVA31 9843")
  check_eq(ex("sva31 climb FL250 at a good rate of 1800 fpm"), "ALT SVA31 FL250 1800")
  check_eq(ex("sva31 increase your rate of descent to two thousand five hundred"), "VS SVA31 -2500")
  asked(ex("sva31 descend FL150 at a slow rate"), "a gentler rate, none said")
  asked(ex("sva31 descend at a good rate 9000 feet"), "a level or the rate after a manner")
  asked(ex("sva31 descend at a good rate two thousand"), "a bare number in words after a manner")
  check_eq(ex("sva31 descend at a good rate of 2000"), "VS SVA31 -2000")
  check_eq(ex("sva31 descend at a good rate FL150"), "ALT SVA31 FL150")
  asked(ex("sva31 rate of descent to 9000 feet"), "a level after 'to', no rate")
end

-- Cycle 48 (hz57): a climb and a descent both said of one aircraft with no correction between are asked, whichever
-- comes first and whether a level, a rate or a rate's sign ("vs 1500 down") follows; a correction, a motion stopped
-- and one in a note or after "then" leave the other standing
do
  local _, ex = scene({ "CRE SVA31 A320 24.7 46.7 250 FL210 270" })
  asked(ex("climb SVA31 descend at 1500 fpm"), "climb, then descend at a rate")
  asked(ex("descend sva31 climb FL250"), "descend, then climb to a level above")
  asked(ex("sva31 climb, descend at 1500 fpm"), "a comma between the two ways")
  asked(ex("sva31 climb rate of descent 1500"), "a rate of descent after climb")
  asked(ex("sva31 descend vertical speed 1500 climbing"), "a rate's sign word against the verb")
  asked(ex("sva31 climb vs 1500 down"), "a rate's sign after its value against the verb")
  check_eq(ex("sva31 climb correction descend at 1500 fpm"), "VS SVA31 -1500")
  check_eq(ex("sva31 stop the climb and descend at 1500 fpm"), "VS SVA31 -1500")
  check_eq(ex("sva31 climb FL250, expect descent in ten minutes"), "ALT SVA31 FL250")
  check_eq(ex("sva31 descend at 1500 fpm then climb FL250"), "VS SVA31 -1500 ; ALT SVA31 FL250")
  check_eq(ex("sva31 vs 1500 down"), "VS SVA31 -1500")
  asked(ex("sva31 go up, descend at 1500 fpm"), "'go up' against a descent")
  asked(ex("sva31 up 1500 fpm descend"), "a rate's sign said before it against the verb")
  asked(ex("sva31 climb vs minus 1500"), "a negative rate for a climb")
  asked(ex("sva31 descend at plus 1500 fpm"), "'plus' for a descent")
  check_eq(ex("sva31 descend vs -1500"), "VS SVA31 -1500")
  check_eq(ex("sva31 climb up to FL250"), "ALT SVA31 FL250")
end

-- Cycle 48 (hz57): a number with no unit said straight after a rate (a comma or "and" between at most) is a level or
-- a speed said bare: asked, in digits, in words, after a metric rate and in a terse typed list; with its unit, or
-- after "to", it is read
do
  local _, ex = scene({ "CRE SVA31 A320 24.7 46.7 250 FL310 270" })
  asked(ex("sva31 descend at 1800 fpm 240"), "a bare number after a rate")
  asked(ex("descend at 1800 fpm, 240"), "a bare number after a rate and a comma")
  asked(ex("sva31 descend at two thousand feet per minute seven thousand"), "a bare level in words after a rate")
  asked(ex("sva31 descend at eight metres per second 7000"), "a bare number after a metric rate")
  asked(ex("sva31 vs -1800 7000 hdg 200"), "a terse list's bare number after the rate")
  asked(ex("sva31 1800 fpm 7000"), "a bare number after a rate with no verb")
  asked(ex("sva31 rate of descent 1800 then 7000"), "a bare number after a rate and 'then'")
  asked(ex("sva31 vertical speed 1800, 7000"), "a bare number closing a list after a rate")
  check_eq(ex("sva31 speed 240 then 7000"), "SPD SVA31 240 ; ALT SVA31 7000")
  check_eq(ex("sva31 descend at 1800 fpm 240 knots"), "VS SVA31 -1800 ; SPD SVA31 240")
  check_eq(ex("sva31 descend at 1800 fpm to 240"), "ALT SVA31 FL240 1800")
  check_eq(ex("sva31 descend at two thousand feet per minute to seven thousand"), "ALT SVA31 7000 2000")
  check_eq(ex("sva31 descend at eight metres per second to 7000 feet"), "ALT SVA31 7000 1575")
  check_eq(ex("sva31 7000 hdg 200 vs -1800"), "ALT SVA31 7000 ; HDG SVA31 200 ; VS SVA31 -1800")
end

-- Cycle 48 (hz57): a second number said beside a complete instruction restates its value only when, said alone, it
-- gives that value ("FL300, three zero zero", "heading 090, 90", "9000 feet, niner"); one that differs in size or
-- form ("climb FL300 3000", "heading 120 twelve", "speed 250 25") is asked, never taken as the same. A study's
-- label with its number in a remark after a dash ("- run 3") is no value
do
  local _, ex = scene({ "CRE SVA31 A320 24.7 46.7 250 FL210 270" })
  check_eq(ex("sva31 climb FL300 3000"), "ASK I have ALT SVA31 FL300. What does '3000' mean?")
  check_eq(ex("sva31 heading 120 twelve"), "ASK I have HDG SVA31 120. What does 'twelve' mean?")
  asked(ex("sva31 speed 250 twenty five"), "a speed said again a tenth of its size")
  asked(ex("sva31 climb FL300 30"), "a typed 30 after FL300")
  asked(ex("sva31 descend FL150 1500"), "a tenth of the level after it")
  check_eq(ex("sva31 climb FL300 three zero zero"), "ALT SVA31 FL300")
  check_eq(ex("sva31 climb FL300 thirty thousand"), "ALT SVA31 FL300")
  check_eq(ex("sva31 heading 090 90"), "HDG SVA31 90")
  check_eq(ex("sva31 descend 9000 feet niner"), "ALT SVA31 9000")
  check_eq(ex("sva31 climb FL300 - test profile step 2"), "ALT SVA31 FL300")
  check_eq(ex("sva31 climb FL300 - run 3"), "ALT SVA31 FL300")
  asked(ex("sva31 climb FL300, step 3"), "a step's number with no remark set apart")
end

-- Cycle 48 (hz57): "maximum" is kept as typed, never read as "minimum" (two letters from it)
do
  local _, ex = scene({ "CRE SVA31 A320 24.7 46.7 250 FL210 270" })
  check_eq(ex("sva31 descend FL150 at maximum rate"), "ALT SVA31 FL150")
end

-- Cycle 48 (hz59): "which heading/level/speed is X flying/at ...?" asks the aircraft's value (POS), never sets it
do
  local _, ex = scene({ "CRE SVA31 A320 24.7 46.7 250 FL210 270" })
  check_eq(ex("which level is sva31 at right now?"), "POS SVA31")
  check_eq(ex("which speed is sva31 flying at present"), "POS SVA31")
  check_eq(ex("which heading is sva31 flying at the moment?"), "POS SVA31")
  asked(ex("which heading should sva31 fly?"), "a heading to fly, with no value")
end

-- Cycle 48 (hz59): a report of the fuel state or endurance is named as not simulated, never a POS
do
  local s = scene({ "CRE SVA31 A320 24.7 46.7 250 FL210 270" })
  local r = graph.translate("sva31 climb FL300 and report your fuel status", { sim = s, mode = "offline" })
  check(said(r) == "ALT SVA31 FL300" and (r.note or ""):find("fuel", 1, true) ~= nil, said(r))
  r = graph.translate("sva31 say endurance", { sim = s, mode = "offline" })
  check(#r.commands == 0 and (r.note or ""):find("fuel and persons", 1, true) ~= nil, said(r))
  check_eq(said(graph.translate("sva31 report your state", { sim = s, mode = "offline" })), "POS SVA31")
end

-- Cycle 48 (hz59): "allow vertical resolutions" in a clause of its own beside a factor said of the resolutions is
-- RMETHV; a factor said with no resolution word still leaves the request asked
do
  local _, ex = scene({ "CRE SVA31 A320 24.7 46.7 250 FL210 270" })
  check_eq(ex("switch on MVP resolutions with a horizontal factor of 1.2 and permit vertical manoeuvres"),
    "RESO MVP ; RFACH 1.2 ; RMETHV V/S")
  check_eq(ex("MVP resolution, vertical resolution factor 1.3"), "RESO MVP ; RFACV 1.3")
  asked(ex("make the horizontal factor 1.2 and permit vertical resolutions"), "a factor of nothing named")
end

-- Cycle 48 (hz58): a level broken off after its words ("flight level... eh... one", "altitude uh two") and a single
-- number word read as thousands of feet far from the aircraft's level ("descend two" at FL260) are asked, never
-- flown; near the aircraft's level, or with the rest of the number said, they are read
do
  local _, ex = scene({ "CRE AFR512 A320 48.5 2.5 180 FL260 270", "CRE AFR77 A319 48.7 2.8 090 7000 250" })
  asked(ex("air france 512 descend flight level... eh... two"), "a flight level broken off by 'eh'")
  asked(ex("AFR512 descend flight level, um, three"), "a flight level broken off by a comma and 'um'")
  asked(ex("AFR512 descend level... two"), "'level' and a digit after an ellipsis")
  asked(ex("AFR512 descend altitude eh two"), "an altitude broken off by 'eh'")
  asked(ex("AFR512 descend altitude... uh... eight"), "an altitude broken off by an ellipsis")
  asked(ex("AFR512 descend two"), "a single number word 24000 ft below the aircraft")
  asked(ex("AFR512 descend and maintain uh eleven"), "'eleven' alone, 15000 ft below")
  asked(ex("AFR77 climb eighteen"), "'eighteen' alone, 11000 ft above")
  asked(ex("AFR77 turn left heading eh two seven"), "a heading broken off by 'eh'")
  check_eq(ex("AFR512 descend flight level... eh... one four zero"), "ALT AFR512 FL140")
  check_eq(ex("AFR512 descend altitude uh one two thousand"), "ALT AFR512 12000")
  check_eq(ex("AFR77 descend four"), "ALT AFR77 4000")
  check_eq(ex("AFR77 descend altitude five"), "ALT AFR77 5000")
  check_eq(ex("AFR77 climb and maintain niner"), "ALT AFR77 9000")
  check_eq(ex("AFR512 descend one one"), "ALT AFR512 11000")
end

-- Cycle 49 (lead): "no" or "not" before a level's comparative with a level after it ("no higher than FL300", "not
-- lower than 8000 feet") bounds the level and clears none: asked, never flown as the level; "climb to FL300, no
-- higher" (no level after the bound) is read
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 090 FL100 250" })
  asked(ex("KLM12 no higher than FL300"), "a ceiling 20000 ft above the aircraft, no clearance")
  asked(ex("KLM12 no lower than flight level eight zero"), "a floor below the aircraft, no clearance")
  asked(ex("KLM12 not lower than 8000 feet"), "'not' and a floor in feet")
  asked(ex("KLM12 no higher FL300"), "the bound with 'than' left out")
  check_eq(ex("KLM12 climb to FL300, no higher"), "ALT KLM12 FL300")
end

-- Cycle 49 (f121): a word straight after a place's slot ("cross", "after", "until", ...) that sounds like a waypoint
-- of the named aircraft's route is a name heard: confirmed ("Did you mean LANDR? I heard 'lander'."), never dropped
-- with the instruction flown alone and never re-read as an instruction word; "yes" reads it as that waypoint. A word
-- sounding like no waypoint of that route, or said in no place's slot, is still asked about by name
do
  local s = scene({ "CRE KLM12 A320 52.3 4.7 090 FL250 280", "DEFWPT LANDR 52.5 5.0", "ADDWPT KLM12 LANDR",
    "DEFWPT TELLR 52.6 5.5", "ADDWPT KLM12 TELLR", "DEFWPT MACEY 52.7 5.9", "ADDWPT KLM12 MACEY",
    "CRE EZY45 A320 51.9 4.0 270 FL200 260" })
  local ex = select(2, set_up(s, {}))
  -- (cycle 50, f130: a name sounding like one waypoint of the routes as closely as a direct-to's is taken,
  -- G.sure_route_name; the question of one less alike is tested there)
  local function heard(text, _, after) check_eq(ex(text), after) end
  heard("KLM12 cross lander at flight level two one zero", "Did you mean LANDR? I heard 'lander'.", "AT KLM12 LANDR ALT FL210")
  heard("KLM12 after teller descend and maintain flight level one eight zero", "Did you mean TELLR? I heard 'teller'.",
    "AT KLM12 TELLR DO ALT KLM12 FL180")
  heard("KLM12 maintain two eight zero knots until teller", "Did you mean TELLR? I heard 'teller'.", "SPD KLM12 280")
  heard("KLM12 descend and maintain flight level two one zero cross macy at flight level two one zero",
    "Did you mean MACEY? I heard 'macy'.", "ALT KLM12 FL210 ; AT KLM12 MACEY ALT FL210")
  asked(ex("KLM12 cross banana at flight level two one zero"), "a crossing at a word like no waypoint of the route")
  asked(ex("EZY45 cross lander at flight level two one zero"), "LANDR is on no route of EZY45's")
  asked(ex("KLM12 macy flight level two one zero"), "a name heard in no slot, never re-read as 'mach'")
end

-- Cycle 49 (f121): ExpressJet by its ICAO telephony ("Acey") and by its name
do
  local _, ex = scene({ "CRE ASQ4410 E145 52.0 4.2 180 FL240 270", "CRE KLM12 A320 52.3 4.7 090 FL250 280" })
  check_eq(ex("delete acey forty four ten"), "DEL ASQ4410")
  check_eq(ex("acey forty four ten turn left heading one eight zero"), "HDG ASQ4410 180 LEFT")
  check_eq(ex("where is the expressjet"), "POS ASQ4410")
  asked(ex("acey forty four one descend flight level two two zero"), "a digit left unheard")
end

-- Cycle 49 (f121): a decimal fraction below one ("point seven six", ".76", "decimal eight two") is a Mach number's
-- form: read as no Mach number beside a level, heading or rate it is asked, never flown as 700 ft or 1 ft; said
-- with "mach" or "speed", or beside a speed read as Mach, it is the Mach number
do
  local _, ex = scene({ "CRE UAL88 B772 41.9 -87.9 270 FL330 290", "CRE AAL12 A321 41.5 -87.5 090 FL310 280" })
  asked(ex("united eighty eight maintain point eight two"), "a Mach number's form read as 800 ft")
  asked(ex("UAL88 descend .82"), "a typed fraction read as 1 ft")
  asked(ex("united eighty eight maintain max decimal eight two"), "'max' heard for 'mach'")
  check_eq(ex("united eighty eight maintain mach point eight two"), "SPD UAL88 M0.82")
  check_eq(ex("UAL88 climb FL350 speed .82"), "ALT UAL88 FL350 ; SPD UAL88 M0.82")
  check_eq(ex("UAL88 climb FL350, then when level speed .82"), "ALT UAL88 FL350 ; ATALT UAL88 FL350 SPD UAL88 M0.82")
end

-- Cycle 49 (f120): oceanic controllers. A latitude and longitude in whole degrees said for an aircraft whose route
-- holds the named point there ("fifty-six north twenty west", the NAT point 56N20) is that point wherever a
-- waypoint is read; a position said to create, move or for a wind stays the position
do
  local _, ex = navscene({ "CRE UAL82 B763 61.0 -36.0 88 FL380 265", "ADDWPT UAL82 61N30", "ADDWPT UAL82 61N20",
    "CRE ICE9 B752 63.0 -35.0 80 FL350 285" }, "NAT points said in degrees")
  if ex then
    check_eq(ex("UAL82 after passing sixty one north twenty west climb FL390"), "AT UAL82 61N20 DO ALT UAL82 FL390")
    check_eq(ex("United 82, at 61 north 30 west, descend flight level three six zero"),
      "AT UAL82 61N30 DO ALT UAL82 FL360")
    check_eq(ex("UAL82 maintain FL380 until 61 north 20 west then descend FL360"),
      "ALT UAL82 FL380 ; AT UAL82 61N20 DO ALT UAL82 FL360")
    check_eq(ex("UAL82 cross 61 north 20 west at FL390"), "AT UAL82 61N20 ALT FL390")
    check_eq(ex("move UAL82 to 61 north 20 west"), "MOVE UAL82 61 -20")
    asked(ex("UAL82 at 61 north 25 west climb FL390"), "no named point on the route at 61 -25")
    asked(ex("ICE9 at 61 north 20 west climb FL390"), "61N20 is on another aircraft's route only")
  end
end

-- Cycle 49 (f120): a climb or descent to a level to be reached by a waypoint is the level cleared now and the
-- constraint (the constraint alone moves nothing with VNAV off)
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 270 FL300 280", "DEFWPT WPA 52.3 4.0", "ADDWPT KLM12 WPA" })
  check_eq(ex("KLM12 climb FL340 to be level by WPA"), "ALT KLM12 FL340 ; AT KLM12 WPA ALT FL340")
  check_eq(ex("KLM12 climb to reach FL340 by WPA"), "ALT KLM12 FL340 ; AT KLM12 WPA ALT FL340")
  check_eq(ex("KLM12 descend FL240 to be level by WPA"), "ALT KLM12 FL240 ; AT KLM12 WPA ALT FL240")
  asked(ex("KLM12 climb FL340 by WPA"), "'by' with no 'level' or 'reach'")
end

-- Cycle 49 (f120): "when you're at that speed" waits for the speed given before it (ATSPD); with no speed before, or
-- before an instruction it cannot hold, it is asked, never dropped
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 270 FL300 280", "DEFWPT WPA 52.3 4.0", "ADDWPT KLM12 WPA" })
  check_eq(ex("KLM12 reduce speed 250 knots, then when you're at that speed descend FL200"),
    "SPD KLM12 250 ; ATSPD KLM12 250 ALT KLM12 FL200")
  check_eq(ex("KLM12 reduce speed 250 knots, once it's at that speed descend FL200"),
    "SPD KLM12 250 ; ATSPD KLM12 250 ALT KLM12 FL200")
  asked(ex("KLM12 when you're at that speed descend FL200"), "no speed given before")
  asked(ex("KLM12 descend FL200, when you're at that speed turn left heading 200"), "a level before, no speed")
end

-- Cycle 49 (f120): a direct-to whose "via" names no waypoint ("cleared to Dubai via track Charlie") is asked: the route
-- said is no straight line
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 270 FL300 280", "DEFWPT WPA 52.3 4.0", "ADDWPT KLM12 WPA" })
  asked(ex("KLM12 direct WPA via track Charlie"), "a track letter after 'via'")
  asked(ex("KLM12 proceed direct WPA via the flight planned route"), "the route by its name after 'via'")
  check_eq(ex("KLM12 direct WPA"), "DIRECT KLM12 WPA")
end

-- Cycle 49 (f120): a switch asked about ("what's the conflict detection setting", "is conflict detection on") shows
-- its state, never sets it
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 270 FL300 280" })
  check_eq(ex("what's the conflict detection setting"), "ASAS")
  check_eq(ex("is conflict detection on"), "ASAS")
  check_eq(ex("conflict detection on"), "ASAS ON")
end

-- Cycle 49 (f120): "on reaching report" is the report asked for, no condition; a station named before "on" and its
-- frequency, said or typed ("then Gander on one two eight decimal five"), is a hand-off: both noted, not simulated
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 270 FL300 280" })
  check_eq(ex("KLM12 climb FL340, on reaching report"), "ALT KLM12 FL340")
  check_eq(ex("KLM12 climb FL340, then Maastricht on one three two decimal three five"), "ALT KLM12 FL340")
  check_eq(ex("KLM12 climb FL340, Maastricht on 132.35"), "ALT KLM12 FL340")
  check_eq(ex("KLM12 climb FL340, on reaching reduce 250 knots"), "ALT KLM12 FL340 ; ATALT KLM12 FL340 SPD KLM12 250")
  asked(ex("KLM12 climb FL340, Maastricht one three two decimal three five"), "a frequency with no 'on' or verb")
end

-- Cycle 49 (f120): a Mach number said with no verb straight after "then", after a speed given, is the next speed
-- instruction ("speed 290 knots until WPA, then Mach .78"); both at once are asked
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 270 FL300 280", "DEFWPT WPA 52.3 4.0", "ADDWPT KLM12 WPA" })
  check_eq(ex("KLM12 speed 290 knots until WPA, then Mach decimal seven eight"),
    "SPD KLM12 290 ; AT KLM12 WPA DO SPD KLM12 M0.78")
  asked(ex("KLM12 reduce 290 knots, then Mach .78"), "two speeds at once")
end

-- Cycle 49 (f120): a transatlantic destination said by its city or island, whose one large airport the navdata names
-- after a person (lexicon.city_airports), is that airport; a city of several ("Paris") is asked
do
  local _, ex = navscene({ "CRE KLM605 B772 50.5 -38.0 258 FL360 278", "CRE AAL1329 B738 36.5 -66.0 195 FL360 278" },
    "transatlantic destinations by city")
  if ex then
    check_eq(ex("KLM 605 set destination Toronto"), "DEST KLM605 CYYZ")
    check_eq(ex("American 1329 destination Antigua"), "DEST AAL1329 TAPA")
    check_eq(ex("American 1329 set destination Saint Maarten"), "DEST AAL1329 TNCM")
    asked(ex("KLM 605 set destination Paris"), "a city of two large airports")
  end
end

-- Cycle 49 (f120): a time to cross a place ("cross WPA at or after 1215", "not before one two one five") ending its
-- clause is noted as not simulated; with a value after it the crossing is asked as before
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 270 FL300 280", "DEFWPT WPA 52.3 4.0", "ADDWPT KLM12 WPA" })
  check_eq(ex("KLM12 climb FL340, cross WPA at or after one two one five"), "ALT KLM12 FL340")
  check_eq(ex("KLM12 climb FL340, cross WPA not before 1215"), "ALT KLM12 FL340")
  asked(ex("KLM12 cross WPA at or after 1215 at FL340"), "a level after the time: the crossing's")
end

-- Cycle 49 (f123): a small airfield said by its name alone, where an aircraft is put, is the navaid of that name
-- beside it (the CLN VOR, not the EGSQ strip); "airport" said, or an aircraft put on the ground, is the airfield;
-- an aircraft sent there still asks which
do
  local nav, pt = navscene({ "CRE KLM77 A320 51.95 0.6 240 FL150 280", "CRE EZY31 A319 51.7 0.1 300 FL110 250" },
    "a small airfield that shares a navaid's name")
  if nav then
    check_eq(pt("create BAW401 A320 at Clacton heading 090 FL120 280 knots"), "CRE BAW401 A320 CLN 90 FL120 280")
    check_eq(pt("create BAW401 A320 over Clacton heading 090 FL120 280 knots"), "CRE BAW401 A320 CLN 90 FL120 280")
    check_eq(pt("create BAW401 A320 at Clacton airport heading 090 FL120 280 knots"),
      "CRE BAW401 A320 EGSQ 90 FL120 280")
    check_eq(pt("create CLUB1 C172 at Clacton heading 090 on the ground"), "CRE CLUB1 C172 EGSQ 90 0 0")
    asked(pt("EZY31 direct Clacton"), "an aircraft sent to a name an airfield and a navaid share")
  end
end

-- Cycle 49 (f123): where an aircraft comes from said in a relative clause that identifies it ("the Easy that's just
-- departed Luton, Easy 55KJ, ...") describes it: no ORIG; said of the aircraft as a statement it still sets the origin
do
  local nav, pt = navscene({ "CRE EZY55KJ A320 51.88 -0.37 330 5000 250", "CRE RYR4PW B738 51.9 0.25 040 6000 250" },
    "a relative clause naming an airport")
  if nav then
    check_eq(pt("the Ryanair that has just left Southend, Ryanair 4PW, turn left heading 360"), "HDG RYR4PW 360 LEFT")
    check_eq(pt("the Easy which departed from Luton, Easy 55KJ, climb FL100"), "ALT EZY55KJ FL100")
    check_eq(pt("Easy 55KJ departed Luton"), "ORIG EZY55KJ EGGW")
    asked(pt("the Easy that's just departed Luton, Easy 55KJ, set origin Stansted"), "two origins said")
  end
end

-- Cycle 49 (f123): a navaid's name of three words before its kind ("the Isle of Man VOR") is the place, no approach
-- clearance: the level said after it is read; "VOR approach" stays one
do
  local nav, pt = navscene({ "CRE EIN7KL AT76 54.05 -4.9 080 FL070 200" }, "a navaid's name of three words")
  if nav then
    check_eq(pt("move EIN7KL to the Isle of Man VOR at FL100"), "MOVE EIN7KL IOM FL100")
    check_eq(pt("relocate EIN7KL to the Isle of Man VOR, 4000 feet"), "MOVE EIN7KL IOM 4000")
    check_eq(pt("EIN7KL cleared Isle of Man VOR approach"), "")
  end
end

-- Cycle 49 (f123): the Embraer regional jets by their own name ("ERJ-145", "ERJ135") are the E145 and E135; an
-- ERJ name squawk has no designator for is asked
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 090 FL100 250" })
  check_eq(ex("create LOG31 ERJ-145 at 52.5 4.5 heading 180 FL150 250 knots"), "CRE LOG31 E145 52.5 4.5 180 FL150 250")
  check_eq(ex("create LOG31, an ERJ135, at 52.5 4.5 heading 180 FL150 250 knots"),
    "CRE LOG31 E135 52.5 4.5 180 FL150 250")
  asked(ex("create LOG31 ERJ-140 at 52.5 4.5 heading 180 FL150 250 knots"), "an ERJ with no designator")
end

-- Cycle 49 (f123): a city and the whole navdata name of one of its airports ("Belfast City": EGAC "CITY", "Belfast
-- Aldergrove": EGAA "ALDERGROVE") is that airport, also after "divert to"; the city alone stays asked
do
  local nav, pt = navscene({ "CRE EZY68BF A319 54.2 -4.3 300 FL150 270", "CRE BAW836 A320 51.8 -1.0 310 FL200 280" },
    "a city and its airport's whole name")
  if nav then
    check_eq(pt("EZY68BF, new destination Belfast City"), "DEST EZY68BF EGAC")
    check_eq(pt("EZY68BF divert to Belfast Aldergrove"), "DEST EZY68BF EGAA")
    check_eq(pt("BAW836 divert to London City"), "DEST BAW836 EGLC")
    asked(pt("EZY68BF divert to Belfast"), "a city of two airports")
  end
end

-- Cycle 49 (f123): a bare number after "once (you're) at" that the request just gave the aircraft as its speed is
-- that speed reached (ATSPD); another number, or one with no "at" ("when 170"), is asked
do
  local _, ex = scene({ "CRE LOG52 E145 53.4 -1.9 300 FL090 220" })
  check_eq(ex("LOG52 reduce 170 knots, when you're at one seventy turn left heading 200"),
    "SPD LOG52 170 ; ATSPD LOG52 170 HDG LOG52 200 LEFT")
  check_eq(ex("LOG52 slow to 190 knots and once at 190 descend FL70"), "SPD LOG52 190 ; ATSPD LOG52 190 ALT LOG52 FL70")
  asked(ex("LOG52 reduce 170 knots, once you're at 160 descend FL70"), "a number the request gave no speed")
  asked(ex("LOG52 reduce 170 knots, when 170 descend FL70"), "a bare number with no 'at'")
end

-- Cycle 49 (f123): the noun of the level passed said before it ("when passing altitude 6000 feet") is read with
-- the condition; a number too small for an altitude after it is asked
do
  local _, ex = scene({ "CRE TOM41 B738 51.1 -0.1 180 4000 250" })
  check_eq(ex("TOM41 climb FL120, when passing altitude 6000 feet reduce speed 230"),
    "ALT TOM41 FL120 ; ATALT TOM41 6000 SPD TOM41 230")
  check_eq(ex("TOM41 climb FL120, passing altitude 6000 turn left heading 090"),
    "ALT TOM41 FL120 ; ATALT TOM41 6000 HDG TOM41 90 LEFT")
  asked(ex("TOM41 climb FL120, when passing altitude 60 turn left heading 090"), "a number no altitude")
end

-- Cycle 49 (f123): after a direct-to, a clause with a condition of its own ("when passing FL110 reduce 220") waits for
-- that condition, no constraint at the waypoint; "once there" with a heading is still asked
do
  local _, ex = scene({ "DEFWPT WPA 51.7 0.0", "CRE KLM8 E190 51.6 0.2 270 FL130 260", "ADDWPT KLM8 WPA" })
  check_eq(ex("KLM8 direct WPA, when passing FL110 reduce 220 knots, descend FL80"),
    "DIRECT KLM8 WPA ; ATALT KLM8 FL110 SPD KLM8 220 ; ALT KLM8 FL80")
  asked(ex("KLM8 direct WPA, once there turn left heading 200"), "a heading tied to a waypoint")
end

-- Cycle 49 (f123): "acknowledge" after an instruction asks the pilot to acknowledge it (no command); the letter X's
-- word written apart ("92 X-ray", "x ray") is the letter in a callsign
do
  local _, ex = scene({ "CRE RYR92X B738 51.9 -8.0 350 FL090 250", "CRE RYR92A B738 52.0 -8.0 350 FL100 250" })
  check_eq(ex("Ryanair 92 X-ray, climb FL110, acknowledge"), "ALT RYR92X FL110")
  check_eq(ex("Ryanair 92 x ray turn right heading 010"), "HDG RYR92X 10 RIGHT")
  asked(ex("Ryanair 92, climb FL110, acknowledge"), "a callsign with its letter left out")
end

-- Cycle 49 (f123): an aircraft handed to the machine teammate ("give X to the AI", "can you look after X for me",
-- "sort its speed out") is read as the instructions that follow; the teammate named elsewhere is still asked
do
  local _, ex = scene({ "CRE EZY45 A319 51.2 0.9 290 FL120 250", "CRE LOG52 E145 53.4 -1.9 300 FL090 220" })
  check_eq(ex("pass EZY45 to the teammate - teammate, climb it to FL140"), "ALT EZY45 FL140")
  check_eq(ex("could you look after LOG52 for me, turn him right heading 340"), "HDG LOG52 340 RIGHT")
  check_eq(ex("take LOG52 and sort his speed out, 200 knots"), "SPD LOG52 200")
  asked(ex("EZY45 climb FL140, ask the AI"), "the teammate named with no handover")
end

-- Cycle 49 (f123): "course" with three digits up to 360 ("take course 090", "fly course 240") is the heading, as
-- "track 090" is; a course named with a noun before it ("the inbound course 270") is none, and asked
do
  local _, ex = scene({ "CRE AFL17 A333 55.70 36.80 060 FL130 290" })
  check_eq(ex("AFL17 take course 090"), "HDG AFL17 90")
  check_eq(ex("AFL17 fly course 240, descend FL100"), "HDG AFL17 240 ; ALT AFL17 FL100")
  asked(ex("AFL17 the inbound course 270"), "a course named by its noun")
end

-- Cycle 49 (f123): a bare value after "until WPT then" of the limited instruction's kind ("maintain 280 knots until
-- WPB then 250", "maintain FL160 until WPB then FL120") is that instruction again from the waypoint (AT ... DO); a
-- value of another kind there, or a waypoint off the route, is asked
do
  local _, ex = scene({ "DEFWPT WPA 43.9 77.5", "DEFWPT WPB 43.7 77.3", "CRE KZR90 A321 43.95 77.55 220 FL160 280",
    "ADDWPT KZR90 WPA", "ADDWPT KZR90 WPB" })
  check_eq(ex("KZR90 maintain 270 knots until WPB then 240"), "SPD KZR90 270 ; AT KZR90 WPB DO SPD KZR90 240")
  check_eq(ex("KZR90 maintain FL160 until WPB then FL130"), "ALT KZR90 FL160 ; AT KZR90 WPB DO ALT KZR90 FL130")
  asked(ex("KZR90 maintain 270 knots until WPB then FL130"), "a level after a speed's limit")
  asked(ex("KZR90 maintain 270 knots until WPC then 240"), "a waypoint that is none of the route's")
end

-- Cycle 49 (f118): a present value or a level kept beside another instruction ("keep your present level and just
-- turn left", "keep FL200 until PNTA and then descend") is no command when the aircraft holds it with nothing to
-- change; a heading kept on a route (HDG switches LNAV off) and a level it does not fly stay commands; a speed kept
-- until a distance from a place ("until it is 10 miles from PNTB") is asked, never started there
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 090 FL100 250", "CRE AFR9 A320 48.5 2.5 180 FL200 280",
    "DEFWPT PNTA 48.0 2.5", "ADDWPT AFR9 PNTA", "DEFWPT PNTB 47.5 2.5", "ADDWPT AFR9 PNTB" })
  check_eq(ex("KLM12 keep your present level and just turn left heading 050"), "HDG KLM12 50 LEFT")
  check_eq(ex("KLM12 keep the current heading but reduce to 220 knots"), "SPD KLM12 220")
  check_eq(ex("AFR9 keep your current heading but reduce to 250 knots"), "HDG AFR9 180 ; SPD AFR9 250")
  check_eq(ex("AFR9 keep FL200 until PNTA and then descend FL150"), "AT AFR9 PNTA DO ALT AFR9 FL150")
  check_eq(ex("AFR9 keep flying at FL220 until PNTA and then descend FL150"),
    "ALT AFR9 FL220 ; AT AFR9 PNTA DO ALT AFR9 FL150")
  asked(ex("AFR9 keep 280 knots until it is 10 miles from PNTB"), "a speed limited until a distance from a place")
end

-- Cycle 49 (f118): what a polite speaker says around an instruction is no instruction: a relative phrase ("relative
-- to what it is doing now"), the study's reason ("; we are looking at how people notice speed changes"), a report
-- of what someone did ("someone switched it off by mistake"), hedges ("if that is at all possible"), an apology, the
-- protected zone in plain words; an aircraft named in the studied part, or a real condition, is still asked
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 090 FL100 250", "CRE AFR9 A320 48.5 2.5 180 FL200 280",
    "DEFWPT PNTA 48.0 2.5", "ADDWPT AFR9 PNTA", "CRE RZO12 A321 38.7 -27.1 090 FL250 280" })
  check_eq(ex("KLM12 reduce speed by 20 knots, relative to what it is doing now"), "SPD KLM12 230")
  check_eq(ex("KLM12 slow to 220 knots; we are looking at how people notice speed changes"), "SPD KLM12 220")
  asked(ex("KLM12 slow to 220 knots; we are studying how KLM12 turns"), "an aircraft named in the studied part")
  check_eq(ex("Could AFR9 follow its route again? I think someone switched it off by mistake."), "LNAV AFR9 ON")
  check_eq(ex("set the safety distance for the conflict detection to 4 nautical miles"), "ZONER 4")
  check_eq(ex("Would it be too much trouble to ask KLM12 to climb to FL120, if that is at all possible?"),
    "ALT KLM12 FL120")
  check_eq(ex("I apologise for my ignorance of the terminology, but could KLM12 fly at 230 knots?"), "SPD KLM12 230")
  asked(ex("KLM12 climb FL120 if it is clear of traffic"), "a condition, no courtesy")
  check_eq(ex("We pretend that KLM12 climbs now to FL120, please."), "ALT KLM12 FL120")
  check_eq(ex("Could the Azores aeroplane RZO12 turn right heading 120?"), "HDG RZO12 120 RIGHT")
end

-- Cycle 49 (f118): a remark that the place a limit ends at is on the aircraft's route ("which I believe is on its
-- planned route", "? I think PNTA is on its route.") is set aside when it is; for an aircraft that does not pass
-- it, the limit is asked
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 090 FL100 250", "CRE AFR9 A320 48.5 2.5 180 FL200 280",
    "DEFWPT PNTA 48.0 2.5", "ADDWPT AFR9 PNTA" })
  check_eq(ex("AFR9 keep 260 knots until PNTA, which I believe is on its planned route"), "SPD AFR9 260")
  check_eq(ex("AFR9 keep 260 knots until PNTA? I think PNTA is on its route."), "SPD AFR9 260")
  asked(ex("KLM12 keep 260 knots until PNTA, which is on its route"), "a place off the aircraft's route")
end

-- Cycle 49 (f118): a polite request's condition between commas with "to" after it ("and, once it passes FL130, to
-- increase speed"), "that height" and "that speed" reached, and a hand-off in plain words ("talk to Amsterdam
-- control on 121.2", not simulated); a condition with no value for its instruction is still asked
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 090 FL100 250" })
  check_eq(ex("Please ask KLM12 to climb to FL170, and once it passes FL130, to increase speed to 290 knots"),
    "ALT KLM12 FL170 ; ATALT KLM12 FL130 SPD KLM12 290")
  check_eq(ex("Could you ask KLM12 to climb to FL170 and, when it reaches that height, to turn left to heading 230?"),
    "ALT KLM12 FL170 ; ATALT KLM12 FL170 HDG KLM12 230 LEFT")
  check_eq(ex("Please ask KLM12 to reduce to 230 knots and, once it reaches that speed, to climb to FL170."),
    "SPD KLM12 230 ; ATSPD KLM12 230 ALT KLM12 FL170")
  check_eq(ex("KLM12 descend FL080 and then talk to Amsterdam control on 121.2"), "ALT KLM12 FL80")
  asked(ex("KLM12 climb to FL170 and, when it reaches that height, turn left"), "a turn with no heading")
end

-- Cycle 49 (f118): the route's levels flown by the aircraft itself, in plain words ("manage its own altitude along
-- its route", "manage its height by itself"), are VNAV; "manage the altitude 5000" (no "its") is the level
do
  local _, ex = scene({ "CRE AFR9 A320 48.5 2.5 180 FL200 280", "DEFWPT PNTA 48.0 2.5", "ADDWPT AFR9 PNTA" })
  check_eq(ex("Please ask AFR9 to keep following its route but also to manage its height by itself."), "VNAV AFR9 ON")
  check_eq(ex("Could you let AFR9 manage its own altitude along its route? I believe the term is vertical navigation."),
    "VNAV AFR9 ON")
  check_eq(ex("AFR9 manage the altitude 15000"), "ALT AFR9 15000")
end

-- Cycle 49 (hz60): a coordinate with its hemisphere said after it and its label before it ("latitude 52.5 north,
-- longitude 4.2 west") or its decimals said as digit words ("52 point five north") keeps the hemisphere's sign; a
-- hemisphere of the other axis ("latitude 52.5 west") is asked
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 090 FL150 250" })
  check_eq(ex("move KLM12 to latitude 52.5 north, longitude 4.2 west"), "MOVE KLM12 52.5 -4.2")
  check_eq(ex("define waypoint ALPHA1 at latitude 33.9 south and longitude 18.6 east"), "DEFWPT ALPHA1 -33.9 18.6")
  check_eq(ex("move KLM12 to 52 point five north 4 point two west"), "MOVE KLM12 52.5 -4.2")
  check_eq(ex("move KLM12 to north 52 decimal three five, west 4 point eight"), "MOVE KLM12 52.35 -4.8")
  asked(ex("move KLM12 to latitude 52.5 west, longitude 4.2 north"), "a hemisphere of the other axis")
end

-- Cycle 49 (hz60): a correction said after an instruction takes it back or replaces it, never leaves it half
-- applied: a turn's side said again after a self-correction marker ("sorry, I meant to the left") is the side; two
-- sides said for one turn with no marker between are asked
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 090 FL150 250", "DEFWPT HZAA 52.5 5.5", "DEFWPT HZBB 52.7 6.5",
    "ADDWPT KLM12 HZAA", "ADDWPT KLM12 HZBB", "CRE DLH404 A346 52.1 4.2 060 FL130 290" })
  check_eq(ex("KLM12 turn right heading 200, sorry, I meant to the left"), "HDG KLM12 200 LEFT")
  check_eq(ex("KLM12 turn left heading 300, no, to the right, heading 300"), "HDG KLM12 300 RIGHT")
  asked(ex("right KLM12 turn left heading 300"), "two sides, no marker between")
  asked(ex("KLM12 turn left turn right heading 300"), "two sides said for one turn")
  check_eq(ex("KLM12 turn left heading 300, traffic right two o'clock five miles"), "HDG KLM12 300 LEFT")
  -- an airline's telephony split in two ("luft hansa") is the airline, its first part never spelled into a side
  check_eq(ex("luft hansa four oh four turn right heading 090"), "HDG DLH404 90 RIGHT")
  asked(ex("luft hansa four oh four turn left turn right heading 090"), "two sides after the airline joined")
end

-- Cycle 49 (hz60): "belay that", "disregard", "cancel that" take back the instruction before when one with no value
-- is said in its place ("continue on your route"), and a condition before them ("when passing FL140... disregard,
-- descend"); a value said with no verb is taken back by a self-correction as one after a verb; a readback reported
-- by a third person is never the level to fly (what was cleared is)
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 090 FL150 250", "DEFWPT HZAA 52.5 5.5", "DEFWPT HZBB 52.7 6.5",
    "ADDWPT KLM12 HZAA", "ADDWPT KLM12 HZBB" })
  check_eq(ex("KLM12 turn left heading 300... belay that, continue on your route"), "LNAV KLM12 ON")
  check_eq(ex("KLM12 turn right heading 150, disregard, continue on the route"), "LNAV KLM12 ON")
  asked(ex("KLM12 climb FL250, cancel that, turn left heading 300"), "another kind with a value: instead or as well")
  asked(ex("KLM12 climb FL250, correction, turn left heading 300"), "'correction' before another kind: instead or as well")
  asked(ex("KLM12 climb FL200, belay that"), "taken back with nothing in its place")
  asked(ex("KLM12 climb FL200, scratch that"), "taken back with nothing in its place")
  check_eq(ex("KLM12 when passing FL140... disregard, descend FL120"), "ALT KLM12 FL120")
  check_eq(ex("KLM12 when passing FL140, scratch that, reduce speed 220"), "SPD KLM12 220")
  check_eq(ex("KLM12 when passing FL140 reduce speed 220"), "ATALT KLM12 FL140 SPD KLM12 220")
  check_eq(ex("KLM12 go to FL200, no wait, keep it at its current level"), "ALT KLM12 15000")
  asked(ex("KLM12 go to FL200, no wait, turn left heading 300"), "a value of another kind in its place")
  check_eq(ex("KLM12 read back FL130, he was cleared FL120, fix it"), "ALT KLM12 FL120")
  check_eq(ex("KLM12 readback was heading 200, she was cleared heading 210"), "HDG KLM12 210")
  check_eq(ex("KLM12 read back FL130, he was cleared FL120, and reduce speed 220"), "ALT KLM12 FL120 ; SPD KLM12 220")
  check_eq(ex("KLM12 read back FL130, reduce speed 220"), "SPD KLM12 220")
  check_eq(ex("KLM12 read back your route"), "LISTRTE KLM12")
  check_eq(ex("KLM12 continue on your route"), "LNAV KLM12 ON")
  check_eq(ex("KLM12 keep it at its current level"), "ALT KLM12 15000")
end

-- Cycle 49 (f117): a question asked indirectly ("could you tell me what X is doing", "let me know the destination
-- of X", "tell me which resolution method is active") shows what is asked, as the direct question does; a request
-- that names a value, or another verb, is read or asked as before
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 090 FL100 250", "CRE EZY45 A319 52.1 4.2 180 FL120 260" })
  check_eq(ex("Would you mind telling me what KLM12 is currently doing?"), "POS KLM12")
  check_eq(ex("I'd like to know what the easyJet is doing now."), "POS EZY45")
  check_eq(ex("Could you kindly tell me the destination of KLM12?"), "DEST KLM12")
  check_eq(ex("please let me know the origin of EZY45"), "ORIG EZY45")
  check_eq(ex("Do you know whether conflict detection is switched on?"), "ASAS")
  check_eq(ex("Can you tell me which resolution method is in use at the moment?"), "RESO")
  check_eq(ex("could you tell me what the zone radius is?"), "ZONER")
  asked(ex("Please give EZY45 the destination"), "a destination given with no airport")
  asked(ex("Could you tell me what KLM12 is currently doing at FL300?"), "a level said beside the question")
end

-- Cycle 49 (f117): a polite question opening a request of the run ("could you please resume the run?", "would you
-- kindly start the run?") starts or resumes it, as the bare verb does
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 090 FL100 250" })
  check_eq(ex("Could you please resume the run?"), "OP")
  check_eq(ex("Would you kindly start the run?"), "OP")
  asked(ex("Could you please resume the run of KLM12?"), "a run of an aircraft")
end

-- Cycle 49 (f117): a report's asides after a complete instruction are set aside: the speaker's opinion ("in my
-- view"), a past event told with "when" ("when the conflict first became apparent"), a comparison with the record
-- (", contrary to its VFR clearance"), what a defined point stands for (", marking the point of closest approach"),
-- what a shown value includes, a report's section and an air traffic unit's abbreviation; the same clause with a
-- present condition, a value or an aircraft is asked
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 090 FL100 250", "CRE EZY45 A319 52.1 4.2 180 FL120 260" })
  check_eq(ex("Please have KLM12 stop its climb at FL110, which is what the controller should have done, in my "
    .. "opinion, when the first alert occurred."), "ALT KLM12 FL110")
  check_eq(ex("KLM12 was climbing at about 1800 feet per minute when the first alert was generated; set that rate."),
    "VS KLM12 1800")
  check_eq(ex("have KLM12 climb to FL110, contrary to its clearance"), "ALT KLM12 FL110")
  check_eq(ex("Define a waypoint called LOSPT at 52.2 north, 4.5 east, representing the point of loss of separation."),
    "DEFWPT LOSPT 52.2 4.5")
  check_eq(ex("Please indicate where EZY45 is at present, including its speed."), "POS EZY45")
  check_eq(ex("Please give the position of EZY45, as I need it for table 3 of the report."), "POS EZY45")
  check_eq(ex("The look-ahead should be increased to 240 seconds, which matches the STCA used by Amsterdam ACC."),
    "DTLOOK 240")
  asked(ex("KLM12 should climb at 1800 feet per minute when the first alert is generated."), "a present condition")
  asked(ex("have KLM12 climb to FL110, contrary to its clearance of FL090"), "a level in the aside")
  asked(ex("have KLM12 climb to FL110, contrary to EZY45's clearance"), "an aircraft in the aside")
end

-- Cycle 49 (f117): "a half-height of 1000 feet" after "and" names the zone's half height, no fraction left over;
-- the Boeing 747-8 is the B748
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 090 FL100 250" })
  check_eq(ex("I'd like the zone to have a radius of 4 nautical miles and a half-height of 800 feet"),
    "ZONER 4 ; ZONEDH 800")
  check_eq(ex("create a Boeing 747-8 called CLX77 at 52.0 N 4.0 E heading 090 FL300 280 knots"),
    "CRE CLX77 B748 52 4 90 FL300 280")
  asked(ex("KLM12 climb to four thousand and a half"), "a fraction after 'and'")
end

-- Cycle 49 (f117): a bound closing a condition ("once it is above 8000 feet, accelerate", "when below FL100 ...")
-- is the level crossed, which the instruction after it waits for (ATALT); a bare bound before a speed is read only
-- where the aircraft crosses into it (cycle 53, fus), and a level it will not pass is asked
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 090 4000 250" })
  check_eq(ex("Please climb KLM12 to FL150 and, once it is above 9000 feet, accelerate it to 300 knots."),
    "ALT KLM12 FL150 ; ATALT KLM12 9000 SPD KLM12 300")
  check_eq(ex("climb KLM12 to FL150, when above FL100 speed 300 knots"), "ALT KLM12 FL150 ; ATALT KLM12 FL100 SPD KLM12 300")
  check_eq(ex("climb KLM12 to FL150, above 9000 feet speed 300 knots"), "ALT KLM12 FL150 ; ATALT KLM12 9000 SPD KLM12 300")
  asked(ex("climb KLM12 to FL150 and once it is above FL200 accelerate to 300 knots"), "a level it will not pass")
end

-- Cycle 49 (f117): "insert X between A and B" puts X after A when A and B follow each other on the route; two
-- places apart, or in the other order, are asked
do
  local _, ex = scene({ "DEFWPT SPY 52.5 4.8", "DEFWPT PAM 52.6 5.0", "DEFWPT WOODY 52.7 5.2", "DEFWPT EEL 52.55 4.9",
    "CRE KLM12 A320 52.3 4.7 090 FL100 250", "ADDWPT KLM12 SPY", "ADDWPT KLM12 PAM", "ADDWPT KLM12 WOODY" })
  check_eq(ex("Could you please insert EEL between SPY and PAM in the route of KLM12?"), "ADDWPT KLM12 EEL,,,SPY")
  asked(ex("Could you please insert EEL between PAM and SPY in the route of KLM12?"), "the places in the other order")
  asked(ex("Could you please insert EEL between SPY and WOODY in the route of KLM12?"), "two places apart")
end

-- Cycle 49 (f117): "add / set an altitude constraint of FL80 at MAGAT for X" is the constraint at the waypoint (AT),
-- no aircraft created; at a waypoint off the route it is asked
do
  local _, ex = scene({ "DEFWPT SPY 52.5 4.8", "DEFWPT PAM 52.6 5.0", "DEFWPT WOODY 52.7 5.2",
    "CRE KLM12 A320 52.3 4.7 090 FL100 250", "ADDWPT KLM12 SPY", "ADDWPT KLM12 PAM" })
  check_eq(ex("Could you please add an altitude constraint of flight level 90 at PAM for KLM12?"), "AT KLM12 PAM ALT FL90")
  check_eq(ex("Please set a speed restriction of 230 knots at SPY for KLM12"), "AT KLM12 SPY SPD 230")
  asked(ex("Please add an altitude constraint of FL90 at WOODY for KLM12"), "a waypoint off the route")
  -- a report's source said without a comma ("over CASAR according to the letter of agreement") and a time of the
  -- record in an aside (", as it was cleared at 10:44") are set aside; the same time said as the instruction's is
  -- asked
  check_eq(ex("KLM12 was to be at FL120 over PAM according to the letter of agreement; please reproduce that constraint."),
    "AT KLM12 PAM ALT FL120")
  check_eq(ex("KLM12 is to proceed direct to PAM, as it was cleared at 10:44."), "DIRECT KLM12 PAM")
  asked(ex("KLM12 is to proceed direct to PAM at 10:44."), "a time said as the instruction's")
  asked(ex("KLM12 was to be at FL120 over PAM according to EZY45"), "an aircraft as the source")
end

-- Cycle 49 (f117): ", and another A320 called X at ..." after a creation creates one more aircraft; without a
-- callsign or a position it is asked
do
  local _, ex = scene({ "DEFWPT SPY 52.5 4.8", "DEFWPT PAM 52.6 5.0" })
  check_eq(ex("Please create an A320 called KLM501 at SPY with heading 045, FL 290 and 270 knots, and another A320 "
    .. "called KLM502 at PAM with heading 225, FL 290 and 270 knots."),
    "CRE KLM501 A320 SPY 45 FL290 270 ; CRE KLM502 A320 PAM 225 FL290 270")
  asked(ex("Please create an A320 called KLM501 at SPY with heading 045, FL 290 and 270 knots, and another A320 at "
    .. "PAM with heading 225, FL 290 and 270 knots."), "another aircraft with no callsign")
  asked(ex("Please create an A320 called KLM501 at SPY with heading 045, FL 290 and 270 knots, and another A320 "
    .. "called KLM502."), "another aircraft with no position")
end

-- Cycle 49 (f117): the speaker's need of an aircraft denied before it is removed ("we will not need KLM12 any more,
-- so could you please delete it?") is the reason for the removal; the same clause before another instruction, or
-- holding a value, is asked
do
  local _, ex = scene({ "CRE KLM12 A320 52.3 4.7 090 FL100 250" })
  check_eq(ex("We will not need KLM12 any more, so could you please delete it?"), "DEL KLM12")
  check_eq(ex("I don't really need KLM12 anymore, please remove it."), "DEL KLM12")
  asked(ex("We will not need KLM12 any more, so could you please climb it to FL300?"), "no removal after it")
  asked(ex("We will not need KLM12 at FL200, so could you please delete it?"), "a value in the clause")
end

-- Cycle 49 (f122): an instruction cut off after its callsign and taken back ("klm33 dct... uh no, hdg 060") leaves the
-- callsign the subject of the instruction said in its place: no value said before it for another aircraft moves to it
do
  local _, ex = scene({ "CRE KLM33 A320 52.0 4.0 090 FL200 250", "CRE BAW7 A319 52.3 4.6 180 FL240 260" })
  check_eq(ex("baw7 fl220 spd 240 and klm33 dct... uh no, hdg 060"), "ALT BAW7 FL220 ; SPD BAW7 240 ; HDG KLM33 60")
  check_eq(ex("baw7 fl220, klm33 direct... sorry, speed 230"), "ALT BAW7 FL220 ; SPD KLM33 230")
  check_eq(ex("baw7 hdg 200 and klm33 hdg 100"), "HDG BAW7 200 ; HDG KLM33 100")
  asked(ex("baw7 fl220 and klm33 turn... sorry, fl210"), "a value alone after the correction, no instruction word")
end

-- Cycle 49 (f122): the speed just given said again after "at" opening a clause ("spd 300 then at 300 kts fl240",
-- "speed 220 and at 220 descend FL180", "spd 280, when at 280 climb FL300") is what the rest waits for (ATSPD); a
-- different speed there is asked
do
  local _, ex = scene({ "CRE KLM33 A320 52.0 4.0 090 FL200 250" })
  check_eq(ex("klm33 spd 290 then at 290 kts fl260"), "SPD KLM33 290 ; ATSPD KLM33 290 ALT KLM33 FL260")
  check_eq(ex("klm33 speed 230 and at 230 fl160"), "SPD KLM33 230 ; ATSPD KLM33 230 ALT KLM33 FL160")
  check_eq(ex("klm33 reduce 230 kts, at 230 kts descend fl150"), "SPD KLM33 230 ; ATSPD KLM33 230 ALT KLM33 FL150")
  check_eq(ex("klm33 spd 270, when at 270 climb fl300"), "SPD KLM33 270 ; ATSPD KLM33 270 ALT KLM33 FL300")
  check_eq(ex("klm33 240 kts then at 240 kts turn left hdg 010"),
    "SPD KLM33 240 ; ATSPD KLM33 240 HDG KLM33 10 LEFT")
  check_eq(ex("klm33 mach .74 then at mach .74 fl280"), "SPD KLM33 M0.74 ; ATSPD KLM33 M0.74 ALT KLM33 FL280")
  asked(ex("klm33 speed 230 and at 260 fl160"), "a speed after 'at' that is not the one given")
  asked(ex("delay 60 klm33 spd 230, then at 230 kts fl160"), "a speed that waits itself, and a wait for it")
end

-- Cycle 49 (f122): BlueSky's DELAY and SCHEDULE typed by their names opening the request, a time straight after
-- (seconds, or with its unit), time every instruction of it; with a callsign straight after the name it is asked
do
  local _, ex = scene({ "CRE KLM33 A320 52.0 4.0 090 FL200 250", "CRE BAW7 A319 52.3 4.6 180 FL240 260" })
  check_eq(ex("delay 120 klm33 fl250"), "DELAY 120 ALT KLM33 FL250")
  check_eq(ex("delay 90 baw7 hdg 270 and klm33 descend fl150"), "DELAY 90 HDG BAW7 270 ; DELAY 90 ALT KLM33 FL150")
  check_eq(ex("schedule 900 baw7 speed 230"), "SCHEDULE 00:15:00 SPD BAW7 230")
  check_eq(ex("delay 2 min klm33 climb fl260"), "DELAY 120 ALT KLM33 FL260")
  check_eq(ex("in 60 s klm33 fl250 and baw7 hdg 100"), "DELAY 60 ALT KLM33 FL250 ; DELAY 60 HDG BAW7 100")
  asked(ex("delay klm33 fl250"), "'delay' with no time")
  asked(ex("schedule baw7 speed 230"), "'schedule' with no time")
end

-- Cycle 49 (f122): a verbless level closing its clause with a comma before a condition ("klm33 fl260, once level hdg
-- 300") is an instruction of its own, and what follows waits for it; a condition inside the level's clause is asked
do
  local _, ex = scene({ "CRE KLM33 A320 52.0 4.0 090 FL240 250" })
  check_eq(ex("klm33 fl280, once level hdg 120"), "ALT KLM33 FL280 ; ATALT KLM33 FL280 HDG KLM33 120")
  check_eq(ex("klm33 fl280, when level spd 230"), "ALT KLM33 FL280 ; ATALT KLM33 FL280 SPD KLM33 230")
  asked(ex("klm33 fl280 once level, hdg 120"), "the condition inside the level's clause, before the comma")
end

-- Cycle 49 (f122): typed short forms "tgt" (target) and "crecon" (CRECONFS), and "when past FIX" (passing it)
do
  local _, ex = scene({ "DEFWPT WPA 52.1 4.3", "CRE KLM33 A320 52.0 4.0 090 FL150 250", "ADDWPT KLM33 WPA", "CRE BAW7 A319 52.3 4.6 180 FL240 260" })
  check_eq(ex("klm33 tgt fl190 vs 1200"), "ALT KLM33 FL190 ; VS KLM33 1200")
  check_eq(ex("crecon ezy9 a319 tgt baw7 dpsi 90 cpa 1 tlos 240"), "CRECONFS EZY9 A319 BAW7 90 1 240")
  check_eq(ex("klm33 fl120 when past WPA"), "AT KLM33 WPA DO ALT KLM33 FL120")
  asked(ex("klm33 fl120 past WPA"), "'past' with no condition word: after, or passing?")
end

-- Cycle 49 (f122): an arrow typed as its character ("hdg 130 → 100") is the arrow, and one between a flight level and
-- feet ("fl370 -> 35000", "12000 -> FL150") goes from the one to the other; a heading it leaves that the aircraft
-- does not fly is still asked
do
  local _, ex = scene({ "CRE KLM33 A320 52.0 4.0 090 FL330 250", "CRE BAW7 A319 52.3 4.6 180 11000 260" })
  check_eq(ex("klm33 hdg 090 → 120"), "HDG KLM33 120")
  check_eq(ex("klm33 alt fl330 -> 31000"), "ALT KLM33 31000")
  check_eq(ex("klm33 fl330 → 31000"), "ALT KLM33 31000")
  check_eq(ex("baw7 alt 11000 -> FL140"), "ALT BAW7 FL140")
  asked(ex("klm33 hdg 100 → 120"), "the heading it leaves is not the one flown")
end

-- Cycle 49 (f122): "add FIX" after a creation with no callsign of its own adds the waypoint to the aircraft created
do
  local _, ex = scene({ "DEFWPT WPA 52.1 4.3", "CRE KLM33 A320 52.0 4.0 090 FL150 250", "ADDWPT KLM33 WPA" })
  check_eq(ex("cre ezy8 a320 52.2 4.3 180 fl120 240, add WPA"), "CRE EZY8 A320 52.2 4.3 180 FL120 240 ; ADDWPT EZY8 WPA")
  check_eq(ex("cre ezy8 a320 52.2 4.3 180 fl120 240 and add tra9 b738 52.4 4.1 90 fl100 250"),
    "CRE EZY8 A320 52.2 4.3 180 FL120 240 ; CRE TRA9 B738 52.4 4.1 90 FL100 250")
end

-- Cycle 49 (hz62): the experimenter's account of a run in a remark beside a complete request ("faster than I had
-- intended", "we're comparing ...", "the transit phase", "I'll take a screenshot") accounts for its words; a word
-- of manner in the remark ("turning slowly") is still asked
do
  local _, ex = scene({ "CRE KLM33 A320 52.0 4.0 090 FL330 250", "CRE BAW7 A319 52.3 4.6 180 FL240 260" })
  check_eq(ex("Could you slow KLM 33 to 230 knots, please? It's closing on the other traffic sooner than I intended."),
    "SPD KLM33 230")
  check_eq(ex("Could you set KLM 33 to Mach .78, please? We're comparing Mach against fixed CAS in this comparison."),
    "SPD KLM33 M0.78")
  check_eq(ex("Could you speed up the simulation to three times real time? The transit part is boring."), "DTMULT 3")
  check_eq(ex("Please descend KLM33 to FL250. Then I'll take a screenshot of the geometry."), "ALT KLM33 FL250")
  asked(ex("Please turn KLM33 left heading 200. The video should show it turning slowly."),
    "a word of manner in the remark is still asked")
end

-- Cycle 49 (hz62): a place said by its name where the aircraft passes it ("when it passes the Halifax VOR", "once it
-- has passed Halifax", "after the Halifax VOR") is the waypoint of the condition; a name two places bear near the
-- aircraft, off its route, is asked
do
  local _, ex = navscene({ "CRE JZA81 DH8D 44.9 -63.9 090 FL200 250", "ADDWPT JZA81 YHZ",
    "CRE BAW7 A319 45.3 -63.0 180 FL240 260" }, "places passed said by name")
  if ex then
    check_eq(ex("Please have Jazz 81 climb to FL240 when it passes the Halifax VOR."), "AT JZA81 YHZ DO ALT JZA81 FL240")
    check_eq(ex("Please have Jazz 81 descend to 8000 feet once it has passed the Halifax VOR."),
      "AT JZA81 YHZ DO ALT JZA81 8000")
    check_eq(ex("Please have Jazz 81 descend to 8000 feet after the Halifax VOR."), "AT JZA81 YHZ DO ALT JZA81 8000")
    asked(ex("Could BAW7 turn left heading 200 once it has passed Halifax, please?"), "Halifax: airport or VOR")
  end
end
-- Cycle 49 (hz61): a verb that ends fast time before the fast-forward it names ("stop the fast-forward") is OP,
-- never FF; "real time" said after it is that OP's
do
  local _, ex = scene({ "CRE KLM33 A320 52.0 4.0 090 FL200 250" })
  check_eq(ex("cancel the fast forward please"), "OP")
  check_eq(ex("end this fast-forward and continue in real time"), "OP")
  check_eq(ex("stop the fast forward, then pause"), "OP ; HOLD")
  check_eq(ex("fast forward 3 minutes"), "FF 180")
  asked(ex("fast forward a bit"), "a fast-forward with a duration not understood")
end

-- Cycle 49 (hz61): "reset" before a possessive ("reset its starting point") names what of an aircraft is set
-- again, never RESET of the simulation
do
  local _, ex = scene({ "CRE KLM33 A320 52.0 4.0 090 FL200 250" })
  local out = ex("please move KLM33 to 52.2 north 4.1 east, I'd like to reset its position for the next run")
  check(not out:find("RESET", 1, true), out)
  local r = graph.translate("reset the simulation", { sim = squawk.sim.new(), mode = "offline" })
  check(r.ask ~= nil or r.confirm ~= nil or r.confirm_first ~= nil, "RESET of the simulation is still confirmed")
end

-- Cycle 49 (hz61): a value after "instead of" / "rather than" with words of a setting's value between
-- ("instead of the default 1.05", "rather than the current 250") is the one replaced, never issued
do
  local _, ex = scene({ "CRE KLM33 A320 52.0 4.0 090 FL200 280" })
  check_eq(ex("set the vertical resolution margin factor to 1.3 instead of the default 1.05"), "RFACV 1.3")
  check_eq(ex("KLM33 speed 250 rather than the current 280"), "SPD KLM33 250")
  check_eq(ex("KLM33 heading 120 instead of 090"), "HDG KLM33 120")
end

-- Cycle 49 (hz61): "loss of separation" is the conflict's event, no protected zone: a CRECONFS's height above or
-- below, its vertical loss and its speed said after it are CRECONFS's dh, tlosv and spd
do
  local _, ex = scene({ "CRE KLM33 A320 52.0 4.0 090 FL300 280" })
  check_eq(ex("create a conflicting A320 called INT7 against KLM33: 90 degrees relative heading, a CPA of 1 mile, "
    .. "200 seconds to loss of separation, 1000 feet below it, vertical loss at 150 seconds, and 260 knots"),
    "CRECONFS INT7 A320 KLM33 90 1 200 -1000 150 260")
  check_eq(ex("set the vertical separation to 1500 feet"), "ZONEDH 1500")
end

-- Cycle 49 (hz61): a country that is a later word of an airline's telephony, alone before the flight number
-- ("Bulgaria 411" for FLYING BULGARIA), selects no airline: confirmed with other aircraft flying; the telephony
-- whole or its beginning is read
do
  local _, ex = scene({ "CRE LZB207 A320 43.4 23.3 180 FL140 270", "CRE WZZ818 A320 42.1 23.7 350 FL120 260" })
  asked(ex("Bulgaria 207 climb FL160"), "a telephony's later word alone")
  check_eq(ex("Flying Bulgaria 207 climb FL160"), "ALT LZB207 FL160")
  check_eq(ex("Wizz 818 descend FL100"), "ALT WZZ818 FL100")
  -- ("Air" and the country, AIR PORTUGAL, said as the country)
  local _, ex2 = scene({ "CRE TAP55 A320 43.4 23.3 180 FL140 270", "CRE WZZ818 A320 42.1 23.7 350 FL120 260" })
  check_eq(ex2("Portugal 55 climb FL160"), "ALT TAP55 FL160")
  -- (one aircraft flying: no other it might have been meant from)
  local _, ex1 = scene({ "CRE LZB207 A320 43.4 23.3 180 FL140 270" })
  check_eq(ex1("Bulgaria 207 climb FL160"), "ALT LZB207 FL160")
end

-- Cycle 49 (hz61): a lower-case preposition is no airport's name ("along" is VEAN, ALONG): a creation placed
-- "along with" an aircraft has no position and is asked
do
  local nav, pt = navscene({ "CRE BAW215 B772 44.6 -62.0 250 FL370 280" }, "an airport named like a preposition")
  if nav then
    asked(pt("create DLH7 A346 heading west along with the Speedbird at FL360"), "'along with' names no position")
    check_eq(pt("create DLH7 A346 at Halifax heading west at FL360"), "CRE DLH7 A346 CYHZ 270 FL360")
  end
end

-- Cycle 49 (hz61): detection that "uses" a look-ahead named before it is that setting's owner: only the setting
-- asked for is shown
do
  local _, ex = scene({ "CRE KLM33 A320 52.0 4.0 090 FL300 280" })
  check_eq(ex("what look-ahead time is the conflict detection using?"), "DTLOOK")
  check_eq(ex("which lookahead does detection use"), "DTLOOK")
  check_eq(ex("set lookahead 300 and use detection"), "DTLOOK 300 ; ASAS ON")
end

-- Cycle 49 (lead): a value told as what a setting is by default, closing its clause ("RFACH 1.1, the default is
-- 1.05"), is information, never a second setting; anywhere else it stays asked
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 90 FL200 250" })
  check_eq(ex("set RFACH to 1.1, the default is 1.05"), "RFACH 1.1")
  check_eq(ex("set the look-ahead to 300 seconds, the default being 480"), "DTLOOK 300")
  asked(ex("the default is 1.05 climb KLM12 FL300"), "a default's value that does not close its clause")
end

-- Cycle 49 (hz63): a condition said in plain words about the value just cleared is carried: "on/upon reaching
-- it" (the level or speed before, ATALT/ATSPD), "once it's down to 9000 feet" and "when it goes below 6000 feet"
-- (the level crossed, ATALT), and the instruction after it said as "fly at Mach .78" or "set Mach .78" (a speed
-- flown, so the wait is its own); with no value to wait for, or a turn by degrees, it is still asked
do
  local _, ex = scene({ "CRE KLM41 A320 52.0 4.0 090 FL300 280" })
  check_eq(ex("please climb KLM41 to FL340 and, upon reaching it, fly at Mach .78"),
    "ALT KLM41 FL340 ; ATALT KLM41 FL340 SPD KLM41 M0.78")
  check_eq(ex("KLM41 reduce to 240 knots and, on reaching it, descend to FL200"),
    "SPD KLM41 240 ; ATSPD KLM41 240 ALT KLM41 FL200")
  check_eq(ex("KLM41 climb FL360 and, once it passes FL320, set Mach .79"),
    "ALT KLM41 FL360 ; ATALT KLM41 FL320 SPD KLM41 M0.79")
  check_eq(ex("KLM41 descend to 5000 feet and, once it's down to 9000 feet, to slow to 240 knots"),
    "ALT KLM41 5000 ; ATALT KLM41 9000 SPD KLM41 240")
  check_eq(ex("KLM41 descend to 4000 feet and, when it goes below 6000 feet, reduce to 200 knots"),
    "ALT KLM41 4000 ; ATALT KLM41 6000 SPD KLM41 200")
  asked(ex("KLM41 climb FL340 and, upon reaching it, turn right 30 degrees"), "a turn by degrees after a level reached")
  asked(ex("KLM41 descend to 4000 feet and, when it goes below, reduce to 200 knots"), "'below' with no level")
  asked(ex("KLM41 descend to 4000 feet and, once it's down to that, reduce to 200 knots"), "'down to that' unnamed")
  -- ("start its descent": the lead into the instruction after the condition)
  check_eq(ex("KLM41 slow to 250 knots and, once it has slowed down to that, begin its descent to FL220"),
    "SPD KLM41 250 ; ATSPD KLM41 250 ALT KLM41 FL220")
  asked(ex("KLM41 slow to 250 knots and, once it has slowed down, begin its descent"), "a descent with no level")
end

-- Cycle 50 (lead): North American cargo and regional telephony: "Cargojet 580" (CJT), "Eagle Flight 4410"
-- (EGF, American Eagle); a spoken number that differs is still asked
do
  local _, ex = scene({ "CRE CJT580 B763 45.1 -65.5 090 FL280 280", "CRE EGF4410 E175 42.4 -73.9 180 FL190 270" })
  check_eq(ex("please turn Cargojet 580 thirty degrees left"), "HDG CJT580 60 LEFT")
  check_eq(ex("Eagle Flight 4410, turn left heading 150"), "HDG EGF4410 150 LEFT")
  asked(ex("Eagle Flight 4401 climb FL300"), "a flight number that differs")
end

-- Cycle 50 (lead): words whose readings depend on each other ("I'm going to give it headings": "going ... to"
-- looks at "give", "give" at the words before it) end their chain of conditions: read, never a stack overflow
do
  local _, ex = scene({ "CRE BAW968 A320 52.6 9.0 010 FL180 280", "ADDWPT BAW968 52.8 9.0" })
  check_eq(ex("please delete the route of BAW968, I'm going to give it headings instead"), "DELRTE BAW968")
end

-- Cycle 50 (lead): a value corrected inside a creation ("FL230 no FL250") is the corrected value with all it
-- said (its number too), so the checks on a flight level's digits read it; a field still missing is asked
do
  local _, ex = scene({})
  check_eq(ex("create RYR22AB B738 at 52.70 -8.92 heading 090 FL230 no FL250 280 knots"),
    "CRE RYR22AB B738 52.7 -8.92 90 FL250 280")
  asked(ex("create RYR22AB B738 at 52.70 -8.92 heading FL230 no FL250"), "a heading that is a level")
end

-- Cycle 50 (lead): an instruction tied to a waypoint ("when it reaches MARIM") whose command names no aircraft
-- (a simulator command: HOLD) is asked about, never run, never an error
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  asked(ex("pause everything to knots 230 when it reaches MARIM?"), "a pause tied to a waypoint")
end

-- Cycle 50 (f131a): a correction set off by dashes or said as a formal apology ("pardon me", "forgive me", "I beg
-- your pardon", "excuse me") replaces what it follows: a value, a turn's side (an article or "to" before the word
-- said in its place), or an aircraft described ("the KLM -- no, the Lufthansa aircraft", "the second aircraft");
-- what is taken back is never issued, and with nothing said in its place it is still asked
do
  local _, ex = scene({ "CRE KLM12 A320 52.0 4.0 090 FL300 280", "CRE DLH34 A321 52.2 4.4 270 FL280 290",
    "CRE EZY56 A319 52.4 4.8 180 FL260 270" })
  check_eq(ex("Would you climb the KLM -- no, forgive me, the Lufthansa aircraft -- to flight level 320?"),
    "ALT DLH34 FL320")
  check_eq(ex("please descend the easyJet -- sorry, the KLM -- to FL220 at 1500 feet per minute"),
    "ALT KLM12 FL220 1500")
  check_eq(ex("Please slow KLM12 to Mach 0.78 -- pardon me, Mach 0.76."), "SPD KLM12 M0.76")
  check_eq(ex("Please slow KLM12 to Mach 0.78, I beg your pardon, to Mach 0.76."), "SPD KLM12 M0.76")
  check_eq(ex("turn KLM12 left onto heading 300 -- no, the right, I mean a right turn onto heading 060"),
    "HDG KLM12 60 RIGHT")
  check_eq(ex("Please turn KLM12 -- no, the second aircraft, DLH34 -- right by 20 degrees."), "HDG DLH34 290 RIGHT")
  check_eq(ex("Excuse me, could you turn EZY56 left heading 150?"), "HDG EZY56 150 LEFT")
  asked(ex("Please climb the KLM -- no, forgive me, the Ryanair -- to flight level 320."), "no Ryanair flies")
  asked(ex("turn KLM12 left onto heading 300, pardon me."), "an apology closing the request")
  asked(ex("Slow KLM12 to Mach 0.78 -- pardon me, 0.76 or 0.75."), "two values in its place")
end

-- Cycle 50 (f131a): conditions said formally about the value just cleared: "once it has levelled off", "once it
-- levels out" (the level, ATALT), "once it has done so" (the value of the instruction before, ATALT or ATSPD),
-- "once it arrives there" after the instruction, "once it has reached FL290" (the level named); with no value
-- to wait for (a heading before) it is still asked
do
  local _, ex = scene({ "CRE KLM41 A320 52.0 4.0 090 FL300 280" })
  check_eq(ex("I should be grateful if KLM41 could climb to FL340 and, once it has levelled off, turn onto heading 120"),
    "ALT KLM41 FL340 ; ATALT KLM41 FL340 HDG KLM41 120")
  check_eq(ex("KLM41 descend to FL260; once it levels out, reduce to 250 knots"),
    "ALT KLM41 FL260 ; ATALT KLM41 FL260 SPD KLM41 250")
  check_eq(ex("Kindly slow KLM41 to 240 knots and, once it has done so, descend it to FL200."),
    "SPD KLM41 240 ; ATSPD KLM41 240 ALT KLM41 FL200")
  check_eq(ex("descend KLM41 to FL200, and then reduce to 250 knots once it arrives there"),
    "ALT KLM41 FL200 ; ATALT KLM41 FL200 SPD KLM41 250")
  check_eq(ex("Turn KLM41 right heading 150 and, once it has reached flight level 280, descend it to FL240."),
    "HDG KLM41 150 RIGHT ; ATALT KLM41 FL280 ALT KLM41 FL240")
  asked(ex("Turn KLM41 right heading 150 and, once it has done so, descend it to FL240."), "done so after a heading")
  asked(ex("KLM41 turn left heading 200 and, once it has levelled off, reduce to 250 knots"), "no level cleared")
end

-- Cycle 50 (f131a): an aircraft described and added with "as well" or "too", an aircraft noun after its airline
-- ("the Alaska aircraft, and the Frontier aircraft as well, onto heading 200"), gets the instruction: never
-- dropped in silence
do
  local _, ex = scene({ "CRE KLM12 A320 52.0 4.0 090 FL300 280", "CRE DLH34 A321 52.2 4.4 270 FL280 290" })
  check_eq(ex("Please turn the KLM aircraft, and the Lufthansa aircraft as well, onto heading 200."),
    "HDG KLM12 200 ; HDG DLH34 200")
  check_eq(ex("Please turn the KLM aircraft, and the Lufthansa aircraft too, onto heading 200."),
    "HDG KLM12 200 ; HDG DLH34 200")
  asked(ex("Please turn the KLM aircraft, and the Lufthansa aircraft, onto heading 200."), "an aircraft in an aside")
end

-- Cycle 50 (f131a): an abbreviated civil callsign is the prefix and the last three characters of the registration
-- (FAA JO 7110.65 2-4-20) or all of it but the N; four characters of five ("Cessna three eight Charlie Sierra" for
-- N738CS) leave one unsaid: asked
do
  local _, ex = scene({ "CRE N738CS C172 52.0 4.0 030 3500 105", "CRE KLM12 A320 52.2 4.4 270 FL280 290" })
  check_eq(ex("Cessna eight Charlie Sierra turn left heading 360"), "HDG N738CS 360 LEFT")
  check_eq(ex("Cessna seven three eight Charlie Sierra turn left heading 360"), "HDG N738CS 360 LEFT")
  asked(ex("Cessna three eight Charlie Sierra turn left heading 360"), "four characters of five")
end

-- Cycle 50 (f131a): a time counted on the simulation's clock said before "from now" ("ten minutes of simulated time
-- from now, please turn ...") is the wait (DELAY); a turn by degrees and then a heading in its sentence, no
-- correction between ("left by 90 degrees and, in two minutes, onto heading 070"), is asked unless the heading is
-- the one the turn reaches: never the degrees dropped
do
  local _, ex = scene({ "CRE KLM41 A320 52.0 4.0 070 FL300 280" })
  check_eq(ex("Ten minutes of simulated time from now, please turn KLM41 right onto heading 010."),
    "DELAY 600 HDG KLM41 10 RIGHT")
  check_eq(ex("Please turn KLM41 left by 90 degrees onto heading 340."), "HDG KLM41 340 LEFT")
  asked(ex("Please turn KLM41 left by 90 degrees and, in two minutes, turn it onto heading 070."),
    "a heading after a turn's degrees")
  asked(ex("Ten minutes of real time from now, please turn KLM41 right onto heading 010."), "real time is no wait")
end

-- Cycle 50 (f131a): the end of a limit until a place on the route said after it ("...; thereafter it may fly at its
-- own discretion", "..., and then resume its normal speed") is the limit's end, named as not simulated: the value
-- flown; an instruction after it is still read or asked as before
do
  local _, ex = scene({ "CRE KLM41 A320 52.0 4.0 090 FL300 280", "DEFWPT ROBUS 52.0 5.0", "DEFWPT TEBRO 52.0 6.0",
    "ADDWPT KLM41 ROBUS", "ADDWPT KLM41 TEBRO" })
  check_eq(ex("I would like KLM41 to maintain 270 knots until ROBUS; thereafter it may fly at its own discretion."),
    "SPD KLM41 270")
  check_eq(ex("KLM41 should slow to 260 knots until ROBUS, and then resume its normal speed."), "SPD KLM41 260")
  asked(ex("KLM41 maintain 270 knots until ROBUS, then resume normal speed and climb to FL340"), "more after the end")
end

-- Cycle 50 (f131a): "all" and a count of aircraft ("slow all three aircraft by 20 knots") with no aircraft named is
-- every aircraft flying when that many fly, each from its own state; another count is asked; deleting them is still
-- confirmed
do
  local _, ex = scene({ "CRE KLM12 A320 52.0 4.0 090 FL300 280", "CRE DLH34 A321 52.2 4.4 270 FL280 290",
    "CRE EZY56 A319 52.4 4.8 180 FL260 270" })
  check_eq(ex("Please slow all three aircraft by 20 knots."), "SPD KLM12 260 ; SPD DLH34 270 ; SPD EZY56 250")
  check_eq(ex("Would you climb all three aircraft to FL320?"), "ALT KLM12 FL320 ; ALT DLH34 FL320 ; ALT EZY56 FL320")
  asked(ex("Please slow all four aircraft by 20 knots."), "a count that does not fly")
  asked(ex("Please delete all three aircraft."), "deleting several aircraft is confirmed")
end

-- Cycle 50 (fctl): three digits alone in a condition that this request gave the aircraft as its speed, not as its
-- level, are the speed reached (ATSPD), never a flight level above it; given as both, asked
do
  local _, ex = scene({ "CRE VTI21 A20N 19.0 73.0 090 FL190 280" })
  check_eq(ex("Vistara 21, reduce speed two four zero, on reaching two four zero descend flight level one two zero"),
    "SPD VTI21 240 ; ATSPD VTI21 240 ALT VTI21 FL120")
  check_eq(ex("Vistara 21, slow to two six zero, when passing two six zero turn left heading 050"),
    "SPD VTI21 260 ; ATSPD VTI21 260 HDG VTI21 50 LEFT")
  check_eq(ex("Vistara 21, descend flight level one five zero, on reaching one five zero reduce speed 250"),
    "ALT VTI21 FL150 ; ATALT VTI21 FL150 SPD VTI21 250")
  asked(ex("Vistara 21, climb flight level two six zero, speed two six zero, on reaching two six zero turn left "
    .. "heading 050"), "the same digits given as speed and level")
end

-- Cycle 50 (fctl): a city's airport bearing its name, none large, beside the large airport the city table names
-- (within lexicon.city_nm) is that large one; far apart, the airport by the name stays
do
  local _, ex = navscene({ "CRE AIC77 A320 18.4 80.3 230 FL190 280", "CRE ACA5 A320 44.0 -76.0 090 FL190 280" },
    "a city's two airports")
  if ex then
    check_eq(ex("Air India 77, destination Hyderabad"), "DEST AIC77 VOHS")
    check_eq(ex("Air Canada 5 destination Kingston"), "DEST ACA5 CYGK")
  end
end

-- Cycle 50 (fctl): telephony of Australia, New Zealand, the Pacific and India: "Q-Link 37D" (QLK, QantasLink, also
-- "Q Link", "QLink", "QantasLink"), "Pacific 411" (FJI, Fiji Airways), "Allied 9643" (LLR, Alliance Air); "Cathay
-- Pacific 138" stays Cathay's; "Link 37D" (Airlink) and a number that differs are still asked
do
  local _, ex = scene({ "CRE QLK37D DH8D -33.5 150.2 110 11000 220", "CRE FJI411 A332 -35.9 174.9 190 FL280 290",
    "CRE CPA138 A359 -35.1 150.5 230 FL360 280", "CRE LLR9643 AT76 28.2 76.9 030 9000 200" })
  check_eq(ex("Q-Link three seven delta, descend to eight thousand"), "ALT QLK37D 8000")
  check_eq(ex("QLink 37D turn left heading 090"), "HDG QLK37D 90 LEFT")
  check_eq(ex("QantasLink three seven delta descend 9000 feet"), "ALT QLK37D 9000")
  check_eq(ex("Pacific four one one, climb flight level three one zero"), "ALT FJI411 FL310")
  check_eq(ex("Cathay Pacific one three eight, climb flight level three eight zero"), "ALT CPA138 FL380")
  check_eq(ex("Allied niner six four three, descend to seven thousand feet"), "ALT LLR9643 7000")
  asked(ex("Link three seven delta, descend to eight thousand"), "Airlink's telephony for a QantasLink")
  asked(ex("Pacific four one two, climb flight level three one zero"), "a flight number that differs")
end

-- Cycle 50 (fctl): a waypoint's name spelled again in the phonetic alphabet straight after it ("direct SAMUD,
-- spelling Sierra Alpha Mike Uniform Delta", "direct DPN, Delta Papa November") is the name said twice; letters
-- that are not its name are asked about, naming both
do
  local _, ex = scene({ "DEFWPT DUMOS 29.3 77.1", "DEFWPT DPN 28.6 77.2", "CRE AKJ11 B38M 29.1 77.2 200 FL110 240",
    "ADDWPT AKJ11 DUMOS", "ADDWPT AKJ11 DPN" })
  check_eq(ex("Akasa one one, proceed direct DUMOS, spelling Delta Uniform Mike Oscar Sierra"), "DIRECT AKJ11 DUMOS")
  check_eq(ex("Akasa one one, direct DPN, Delta Papa November, descend flight level one zero zero"),
    "DIRECT AKJ11 DPN ; ALT AKJ11 FL100")
  check_eq(ex("Akasa one one, direct DUMOS, I spell Delta Uniform Mike Oscar Sierra"), "DIRECT AKJ11 DUMOS")
  asked(ex("Akasa one one, proceed direct DUMOS, spelling Delta Uniform Mike Oscar Tango"), "a spelling of other letters")
  asked(ex("Akasa one one, proceed direct DPN, Delta Papa Mike"), "three letters that are not DPN")
end

-- Cycle 50 (fctl): a speed or level limited until a place, then the value bare ("280 knots until BOYSE, then 250",
-- "till KAMOL, thereafter 220", a comma after the place or not) or said again after "after" and a place closing
-- its clause ("reduce speed 250, after SUMAG 220"), is that instruction again from the place (AT DO); a value of
-- another kind, or a place off the route, is asked
do
  local _, ex = scene({ "DEFWPT SUMAG 22.5 89.2", "DEFWPT KAMOL 22.9 88.1", "CRE AIC76 A320 22.4 89.6 280 FL150 290",
    "ADDWPT AIC76 SUMAG" })
  check_eq(ex("Air India 76, maintain two eight zero knots until SUMAG, then two five zero"),
    "SPD AIC76 280 ; AT AIC76 SUMAG DO SPD AIC76 250")
  check_eq(ex("Air India 76, maintain two eight zero knots till SUMAG, thereafter two two zero"),
    "SPD AIC76 280 ; AT AIC76 SUMAG DO SPD AIC76 220")
  check_eq(ex("Air India 76, maintain two eight zero knots till SUMAG, thereafter reduce two two zero"),
    "SPD AIC76 280 ; AT AIC76 SUMAG DO SPD AIC76 220")
  check_eq(ex("Air India 76, reduce speed two six zero, after SUMAG two two zero"),
    "SPD AIC76 260 ; AT AIC76 SUMAG DO SPD AIC76 220")
  check_eq(ex("Air India 76, descend flight level one two zero, after SUMAG flight level one zero zero"),
    "ALT AIC76 FL120 ; AT AIC76 SUMAG DO ALT AIC76 FL100")
  asked(ex("Air India 76, turn left heading 250, after SUMAG two two zero"), "a bare value after a heading")
  asked(ex("Air India 76, reduce speed two six zero, after KAMOL two two zero"), "a place off the route")
end

-- Cycle 50 (fctl): "once again" opening a message is the message said again (Indian English for "I say again"),
-- never a condition
do
  local _, ex = scene({ "CRE AXB13 B38M 13.0 79.0 270 FL130 260" })
  check_eq(ex("Express India 13, once again, descend niner thousand feet"), "ALT AXB13 9000")
  check_eq(ex("Express India 13, once again descend FL100, once level reduce 220"),
    "ALT AXB13 FL100 ; ATALT AXB13 FL100 SPD AXB13 220")
  asked(ex("Express India 13, once again"), "nothing said again")
end

-- Cycle 50 (fctl): a distance in DME said straight before its station's name ("at 30 DME Sydney") is counted from
-- that navaid (ATDIST); a distance after "at" with no place it is counted from ("at 30 DME reduce 180") is asked,
-- never dropped
do
  local _, ex = navscene({ "CRE VOZ81 B738 -33.6 151.3 220 6000 220" }, "a DME's station by name")
  if ex then
    check_eq(ex("Velocity 81, at three zero DME Sydney reduce speed one eight zero"), "ATDIST VOZ81 SY 30 SPD VOZ81 180")
  end
  local _, ex2 = scene({ "CRE VOZ81 B738 -33.6 151.3 220 6000 220" })
  asked(ex2("Velocity 81, at 30 DME reduce speed 180"), "a DME with no station")
  asked(ex2("Velocity 81 at 12 miles descend 4000"), "a distance with no place")
  asked(ex2("Velocity 81, reduce speed 180, at 25 DME descend 4000"), "a DME with no station after a value")
end

-- Cycle 50 (fctl): "move X to FL340" with no place said moves it to that level where it is; a bare number or no
-- "to" is still asked
do
  local _, ex = scene({ "CRE CPA13 A359 -35.1 150.5 230 FL360 280" })
  check_eq(ex("move Cathay one three to flight level three four zero"), "MOVE CPA13 -35.1 150.5 FL340")
  asked(ex("move Cathay 13 to 340"), "a bare number")
end

-- Cycle 50 (f131b): a place said by its name with its ident in apposition ("Gila Bend, GBN", "Thermal, that is
-- TRM", "Truth or Consequences (TCS)", "the Stanfield VOR, TFD") is that ident wherever a place is read (direct,
-- route, a condition's place); a name the navdata does not give that ident is asked. A leading "when it passes the
-- NAME VOR" of the route is its condition; "omitting" a place is passing it on a direct-to
do
  local _, ex = navscene({ "CRE SWA55 B737 32.70 -111.60 270 FL260 280", "ADDWPT SWA55 TFD", "ADDWPT SWA55 GBN",
    "CRE AAL7 A321 33.50 -112.50 090 FL300 290" }, "places said by name and ident")
  if ex then
    check_eq(ex("Please send Southwest 55 directly to Gila Bend, GBN."), "DIRECT SWA55 GBN")
    check_eq(ex("When Southwest 55 passes Stanfield, TFD, please have it descend to FL220."),
      "AT SWA55 TFD DO ALT SWA55 FL220")
    check_eq(ex("When Southwest 55 passes the Stanfield VOR, TFD, turn it left heading 200."),
      "AT SWA55 TFD DO HDG SWA55 200 LEFT")
    check_eq(ex("When Southwest 55 passes the Stanfield VOR, turn it left heading 200."),
      "AT SWA55 TFD DO HDG SWA55 200 LEFT")
    check_eq(ex("Kindly add Thermal, that is TRM, to the route of Southwest 55."), "ADDWPT SWA55 TRM")
    check_eq(ex("Route American 7 directly to Truth or Consequences (TCS), please."), "ADDWPT AAL7 TCS ; DIRECT AAL7 TCS")
    check_eq(ex("Southwest 55 should descend to FL200 once it has passed Stanfield, TFD."),
      "AT SWA55 TFD DO ALT SWA55 FL200")
    asked(ex("When Southwest 55 passes Corona, TFD, please have it descend to FL220."), "a name not the ident's")
    asked(ex("Kindly add Zuni, that is TRM, to the route of Southwest 55."), "a name not the ident's")
    check_eq(ex("Southwest 55 should proceed directly to GBN, omitting Stanfield."), "DIRECT SWA55 GBN")
    check_eq(ex("Southwest 55 should fly directly to GBN, omitting the Stanfield VOR."), "DIRECT SWA55 GBN")
    asked(ex("Southwest 55 should descend to FL220, omitting Stanfield."), "omitting with no direct-to")
  end
end

-- Cycle 50 (f131b): simulator settings said formally: verbs of a setting's work ("computed with", "perform",
-- "employing", "restore the zone to ..."), a setting told or asked about ("tell me the ...", "how large is
-- ...?", "is MVP resolution on?", the detection interval shown by DT), the factor's kind said after its value, the
-- detection interval set "to" a time, trails "displayed", resolutions "purely horizontal"; a value missing is asked
do
  local _, ex = scene({ "CRE KLM61 A320 52.0 4.0 090 FL300 280" })
  check_eq(ex("I would like resolutions computed with the modified voltage potential method."), "RESO MVP")
  check_eq(ex("Kindly perform conflict detection every three seconds."), "DT ASAS 3")
  check_eq(ex("Which resolution method is the simulation employing at present?"), "RESO")
  check_eq(ex("Please restore the protected zone to a radius of 5 nautical miles."), "ZONER 5")
  asked(ex("Please restore the protected zone radius."), "no radius said")
  check_eq(ex("Please tell me the radius of the protected zone."), "ZONER")
  check_eq(ex("How big is the protected zone's vertical size?"), "ZONEDH")
  check_eq(ex("Is MVP resolution active at the moment?"), "RESO")
  check_eq(ex("What is the conflict detection interval?"), "DT")
  check_eq(ex("Tell me the simulation time step and the conflict detection interval, please."), "DT")
  check_eq(ex("Set the resolution factor to 1.3 for the vertical direction."), "RFACV 1.3")
  asked(ex("Set the resolution factor to 1.3."), "which factor")
  check_eq(ex("The conflict detection interval should be set to 4 seconds."), "DT ASAS 4")
  check_eq(ex("We would like to see the trails displayed."), "TRAIL ON")
  check_eq(ex("Please make sure the MVP resolutions stay purely horizontal."), "RMETHV OFF")
  check_eq(ex("Let MVP resolutions use vertical speed as well."), "RMETHV V/S")
end

-- Cycle 50 (f131b): an intruder set up formally: "a closest point of approach of zero", "a CPA of 1" (the distance
-- after the word and "of"), and a preamble naming the conflict before the creation ("the experiment requires a
-- crossing conflict: please create a conflicting aircraft ..."); a distance not said is still asked
do
  local _, ex = scene({ "CRE KLM61 A320 52.0 4.0 090 FL300 280", "CRE BAW7 A319 52.5 4.5 180 FL320 270" })
  check_eq(ex("I should like a head-on case: please generate an intruder, callsign Easy 44, an Airbus A320, "
    .. "against KLM61, on a reciprocal track, with a closest point of approach of zero and loss of separation after "
    .. "240 seconds."), "CRECONFS EZY44 A320 KLM61 180 0 240")
  check_eq(ex("The study needs a crossing conflict: please create a conflicting aircraft, callsign Easy 45, a "
    .. "Boeing 737-800, against BAW7, with a track difference of 90 degrees, a CPA of 1 and a time to loss of "
    .. "separation of 200 seconds."), "CRECONFS EZY45 B738 BAW7 90 1 200")
  asked(ex("The study needs a crossing conflict: please create a conflicting aircraft, callsign Easy 45, a "
    .. "Boeing 737-800, against BAW7, with a track difference of 90 degrees and a time to loss of separation of 200 "
    .. "seconds."), "no closest approach said")
end

-- Cycle 50 (f131b): "resume the simulation at normal speed": the OP issued runs at 1x, the rate said after "at" is
-- its own (no DTMULT 1 besides); another rate said with it is set
do
  local _, ex = scene({ "CRE KLM61 A320 52.0 4.0 090 FL300 280" })
  check_eq(ex("Thank you. Please resume the simulation at normal speed."), "OP")
  check_eq(ex("Please resume the simulation at 3x speed."), "OP ; DTMULT 3")
end

-- Cycle 50 (f126a): an aircraft described by how it compares with the traffic ("the highest aircraft", "the slower
-- of the two Boeings"), by its level ("the aircraft at FL190") or by its airline and family number ("the Qatar 777"):
-- read when exactly the aircraft described fit, asked when several, none or a tie do
do
  local _, ex = scene({ "CRE AFR11 A320 47.0 2.0 090 FL250 290", "CRE AFR12 A319 47.2 2.5 270 FL310 260",
    "CRE BEL3 B738 47.4 2.2 180 FL190 300", "CRE SWR7 B77W 47.6 2.8 360 FL250 310" })
  check_eq(ex("the highest aircraft, please descend it to FL290"), "ALT AFR12 FL290")
  check_eq(ex("could the lowest one climb to FL210"), "ALT BEL3 FL210")
  check_eq(ex("please make the fastest of the aircraft slow to 280 knots"), "SPD SWR7 280")
  check_eq(ex("the lower of the two Airbuses should climb to FL270"), "ALT AFR11 FL270")
  check_eq(ex("could the slower of the two Boeings go to 320 knots"), "SPD BEL3 320")
  check_eq(ex("the highest Boeing climb FL400"), "ALT SWR7 FL400")
  check_eq(ex("the slowest Air France, speed 240"), "SPD AFR12 240")
  check_eq(ex("could the aircraft at FL190 turn left heading 150"), "HDG BEL3 150 LEFT")
  check_eq(ex("the two aircraft at flight level 250 should both climb to FL260"), "ALT AFR11 FL260 ; ALT SWR7 FL260")
  asked(ex("the faster of the two aircraft descend FL200"), "four aircraft fly, not two")
  asked(ex("the faster of the three Boeings descend FL200"), "two Boeings fly, not three")
  asked(ex("the aircraft at FL250 climb FL260"), "two aircraft at FL250")
  asked(ex("the aircraft at FL200 climb FL260"), "no aircraft at FL200")
  asked(ex("the smaller Air France climb FL330"), "size words never compare")
  -- (beside a callsign said, the words describe it or are asked about)
  check_eq(ex("turn BEL3 left heading 150, it's the one at FL190"), "HDG BEL3 150 LEFT")
  asked(ex("turn AFR11 left heading 150, it's the one at FL190"), "the description fits another aircraft")
  asked(ex("turn the highest aircraft and BEL3 left heading 200"), "a description beside a callsign")
end
do
  local _, ex = scene({ "CRE QTR8 B77W 25.0 51.0 090 FL350 290", "CRE QTR21 A359 25.3 51.2 270 FL330 280",
    "CRE ETD4 A320 25.1 51.4 180 FL330 280" })
  check_eq(ex("the Qatar 777 descend FL300"), "ALT QTR8 FL300")
  check_eq(ex("the highest aircraft climb FL370"), "ALT QTR8 FL370")
  asked(ex("could the Qatar 787 descend FL300"), "no Qatar 787 flies")
  asked(ex("the higher of the two Airbuses climb FL370"), "both Airbuses at FL330")
  asked(ex("the faster of the two Airbuses slow to 250"), "both Airbuses at 280 knots")
end

-- Cycle 50 (f126a): words that had read as the wrong command: trails made to "vanish" are off; "the altitudes of the
-- route" after "follow" are VNAV; "its current altitude?" is the level kept, no question of state; "after all" counts
-- no aircraft; "it is stopped" tells the run's state; "before we resume" an unpause to come; a condition before a
-- sentence's end is never the next sentence's; "speed up a bit" has no value and is asked
do
  local _, ex = scene({ "CRE AFR11 A320 47.0 2.0 090 FL250 290", "CRE BEL3 B738 47.4 2.2 180 FL190 300",
    "ADDWPT BEL3 47.8 2.2", "ALT BEL3 FL300" })
  check_eq(ex("could you make the trails vanish"), "TRAIL OFF")
  check_eq(ex("show the trails so aircraft disappear slower"), "TRAIL ON")
  check_eq(ex("could BEL3 follow its route again, and the altitudes of its route as well?"), "LNAV BEL3 ON ; VNAV BEL3 ON")
  asked(ex("BEL3 follow its route. The altitudes of the route are fine."), "a remark on the route's altitudes")
  check_eq(ex("could BEL3 stop climbing and keep its current altitude?"), "ALT BEL3 19000")
  check_eq(ex("BEL3 altitude?"), "POS BEL3")
  check_eq(ex("please remove BEL3, we won't use it after all"), "DEL BEL3")
  check_eq(ex("remove them all"), "ASK Delete 2 aircraft (AFR11, BEL3)? (yes or no)")
  check_eq(ex("start the run again, it is stopped"), "OP")
  check_eq(ex("please freeze the run, we'll fix the display before we resume"), "HOLD")
  asked(ex("AFR11 climb FL300 once it reaches 280 knots. Slow it to 280 first, please."), "the condition's sentence")
  asked(ex("AFR11 turn right heading 100 and, er, speed up a little"), "a speed with no value")
end
-- Cycle 50 (f128): an apology closing a remark that states something and instructs nothing ("..., the projector
-- has frozen, sorry!") is for the remark, the request read; "sorry" straight after an instruction, or after a
-- remark that judges what was said ("that was wrong", "I got them mixed up"), is still asked
do
  local _, ex = scene({ "CRE KLM41 A320 52.0 4.0 090 FL300 280" })
  check_eq(ex("could you freeze the simulation please, the projector has frozen, sorry!"), "HOLD")
  check_eq(ex("KLM41 climb to FL340 please. The students are taking notes, sorry."), "ALT KLM41 FL340")
  asked(ex("KLM41 climb to FL340, sorry."), "'sorry' straight after the instruction")
  asked(ex("KLM41 turn left heading 200, the other way, sorry"), "a clause that states nothing")
  asked(ex("KLM41 climb to FL340, that was wrong, sorry"), "a remark judging the instruction")
  asked(ex("KLM41 climb to FL340. I got them mixed up!"), "a remark judging the instruction, no apology")
  check_eq(ex("please delete KLM41, it was created by mistake"), "DEL KLM41")
end

-- Cycle 50 (f128): the brand "Jet2" written as one word is the airline (Channex, EXS) anywhere, as "the Jet2",
-- "the Jet2's route" or before a new callsign; "ooh" and "ah" are interjections. Two Jet2 aircraft are asked
do
  local _, ex = scene({ "CRE EXS31B B738 53.6 -2.6 180 FL180 290", "CRE TOM4BN B38M 53.3 -1.8 320 FL80 250" })
  check_eq(ex("could you turn the Jet2 left heading 140 please"), "HDG EXS31B 140 LEFT")
  check_eq(ex("ah, and send the Jet2's speed down to 230 knots"), "SPD EXS31B 230")
  check_eq(ex("Ooh, please create Jet2 flight EXS5M, a 737-800, at 53 north 2 west, heading 090, FL120, 250 knots"),
    "CRE EXS5M B738 53 -2 90 FL120 250")
  local _, ex2 = scene({ "CRE EXS31B B738 53.6 -2.6 180 FL180 290", "CRE EXS7 A321 53.3 -1.8 320 FL80 250" })
  asked(ex2("could you turn the Jet2 left heading 140 please"), "two Jet2 aircraft")
end

-- Cycle 50 (f128): a waypoint condition naming its place by the navaid's name after a verb of reaching ("when
-- the KLM gets to Ockham, ...", "KLM41, when you reach Mayfield, ...") is that navaid near the aircraft; off the
-- route, or a name squawk does not know, it is still asked
do
  local lon = squawk.sim.new()
  check(lon:exec("CRE KLM41 A320 51.5 -0.6 150 FL120 280"))
  if #lon:navaids_named("ockham", 51.5, -0.6, 100) == 1 then
    check(lon:exec("ADDWPT KLM41 OCK"))
    check(lon:exec("ADDWPT KLM41 MAY"))
    local _, ex = set_up(lon, {})
    check_eq(ex("When the KLM gets to Ockham, could you turn it right heading 200?"), "AT KLM41 OCK DO HDG KLM41 200 RIGHT")
    check_eq(ex("KLM41, when you reach Mayfield, descend to 6000 feet please."), "AT KLM41 MAY DO ALT KLM41 6000")
    asked(ex("When the KLM is over Lambourne, turn it left heading 090."), "a place off the route")
    asked(ex("When the KLM gets to Gotham, turn it left heading 090."), "a name that is no place")
  else
    print("skipped: waypoint conditions by navaid name need navdata (SQUAWK_NAVDATA)")
  end
end

-- Cycle 50 (f126b): a position given from other traffic described by its airline ("20 nm north of the Lufthansa
-- one", "west of the TUI aircraft"), from where the aircraft is ("15 miles farther east"), and after "the" and an
-- airline a distance, not a flight number ("move the Ryanair 20 nautical miles south"); all along a great circle.
-- Two aircraft of the airline, "further north" with no distance, or "further north of" another, are asked
do
  local _, ex = scene({ "CRE RYR1JW B738 52.80 6.20 090 FL230 280", "CRE TUI3KP B738 52.60 10.20 250 FL210 280",
    "CRE DLH4AX A320 52.20 6.40 280 FL200 300", "CRE DLH5AA A320 52.30 6.40 280 FL200 300" })
  check_eq(ex("please add an A320 called TST1 12 nm south of the TUI aircraft, same heading, level and speed"),
    "CRE TST1 A320 52.400135 10.2 250 FL210 280")
  check_eq(ex("could you move the Ryanair 20 miles west of the TUI one"), "MOVE RYR1JW 52.598734 9.651571")
  check_eq(ex("please shift the Ryanair some 15 miles farther east"), "MOVE RYR1JW 52.799282 6.613214")
  check_eq(ex("move the Ryanair twenty nautical miles south of where it is now"), "MOVE RYR1JW 52.466891 6.2")
  asked(ex("add an A320 called TST2 12 nm south of the Lufthansa one, heading 090, FL200, 250 knots"),
    "two Lufthansa aircraft fly")
  asked(ex("move the TUI further north"), "no distance")
  asked(ex("move the TUI 10 nm further north of the Ryanair"), "further than what")
end

-- Cycle 50 (f126b): an encounter said as the purpose of an instruction to traffic flying ("to create a crossing
-- with ...", "I'm hoping to create a conflict", "that should make the conflict a near miss", "that should make it a
-- hard aircraft to follow") creates nothing; "and create a conflict" is still a creation, asked. "quite" is English
-- unless another word marks the sentence Spanish ("I'm quite new to this" removed the aircraft)
do
  local _, ex = scene({ "CRE SAS12 A320 53.9 9.5 200 FL330 280", "CRE RYR4TG B738 52.8 8.2 045 FL260 300" })
  check_eq(ex("please turn SAS12 left 30 degrees to create a crossing with the Ryanair"), "HDG SAS12 170 LEFT")
  check_eq(ex("could RYR4TG climb to FL300? I am hoping to create an encounter the participants must spot."),
    "ALT RYR4TG FL300")
  check_eq(ex("turn the Ryanair right 15 degrees, that would make the conflict a near miss"), "HDG RYR4TG 60 RIGHT")
  check_eq(ex("could SAS12 descend to FL310? That should make it a hard aircraft to follow."), "ALT SAS12 FL310")
  asked(ex("turn SAS12 left 30 degrees and create a conflict"), "a creation said as an instruction")
  check_eq(ex("I'm quite new here - could the Ryanair climb to FL280?"), "ALT RYR4TG FL280")
end

-- Cycle 50 (f126b): a remark after a complete request that instructs nothing: "the scenario feels a bit empty" (the
-- scenario running, no file), "it is going to be the one they sequence" (the future, no destination), "Then we can
-- see the conflict develop" (the speaker's own doing), a count of aircraft or "the one" in it ("when two aircraft get
-- too close", "the two Airbuses"); one naming an aircraft, a value or an instruction is still asked
do
  local _, ex = scene({ "CRE KLM12 E190 52.0 4.0 090 FL200 250", "CRE EZY45 A320 52.2 4.4 180 FL150 240",
    "CRE DLH7 A321 52.4 4.2 270 FL250 280" })
  check_eq(ex("could KLM12 speed up to 270 knots? It lags a little and the scenario looks rather quiet."), "SPD KLM12 270")
  check_eq(ex("could EZY45 descend to FL120? It's going to be the one our participants have to merge."),
    "ALT EZY45 FL120")
  check_eq(ex("please run the simulation 4 times faster. Then we could watch the encounter unfold sooner."), "DTMULT 4")
  check_eq(ex("could KLM12 slow to 220 knots so that it arrives after the two Airbuses?"), "SPD KLM12 220")
  check_eq(ex("please switch on conflict detection. We want them to notice when three aircraft get close."), "ASAS ON")
  check_eq(ex("please run the simulation 4 times faster. Then we can climb DLH7 to FL300."),
    "DTMULT 4 ; ALT DLH7 FL300")  -- (an instruction after "then we" is read, never set aside)
  asked(ex("could KLM12 slow to 220 knots so that it arrives 20 minutes after the other one?"), "a value in the remark")
end

-- Cycle 50 (f126b): "run the scenario 5 times faster" (the scenario running, at a rate), "tell me the route of X"
-- (LISTRTE), "switch off the automatic route following for X" (LNAV OFF); "run the scenario demo" still asks for
-- the file, "tell X to follow its route" instructs, "X is route following now" switches nothing
do
  local _, ex = scene({ "CRE KLM12 E190 52.0 4.0 090 FL200 250", "ADDWPT KLM12 52.5 4.5" })
  check_eq(ex("could you run the scenario 6 times faster for a while?"), "DTMULT 6")
  check_eq(ex("could you tell me the route of KLM12, if it has one?"), "LISTRTE KLM12")
  check_eq(ex("please switch off the automatic route following for KLM12. I'm not sure it needs it."), "LNAV KLM12 OFF")
  check_eq(ex("KLM12 is route following now, climb FL240"), "ALT KLM12 FL240")
  asked(ex("run the scenario demo"), "which file")
end

-- Cycle 50 (f126b): "a slow descent" / "a fast climb" beside a rate said is the rate's manner, no speed; with no
-- rate said, "slow" is still the speed's word
do
  local _, ex = scene({ "CRE DLH8 A320 53.4 7.8 100 FL120 280" })
  check_eq(ex("could DLH8 descend at 700 feet per minute? We'd like a slow descent."), "VS DLH8 -700")
  asked(ex("could DLH8 slow down? We'd like a slow descent."), "no rate and no speed said")
end

-- Cycle 50 (f126b): a limit until the final's miles said "4 miles on final" is flown (the decision), also with a
-- remark set aside after it; an instruction after it is still asked
do
  local _, ex = scene({ "CRE KLM16 E190 52.3 4.9 180 4000 200" })
  check_eq(ex("could KLM16 keep 170 knots until 5 miles on final? I gather that is the usual practice."), "SPD KLM16 170")
  asked(ex("could KLM16 keep 170 knots until 5 miles on final. Then descend to 2000 feet."), "an instruction after it")
end

-- Cycle 50 (fz): a request that opens with a turn's side and an instruction's verb before a hesitation ("left
-- climb err") reads no word before the request as a refusal; it gets one answer and never raises
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  asked(ex("left climb err"), "no level after the hesitation")
  asked(ex("left climb fl130 err fl150"), "a corrected level with a side before it")
end

-- Cycle 50 (fz): a route written as a list for an aircraft squawk does not have ("UAL182 route: direct HZA") is
-- asked about its callsign and never raises; for an aircraft it has, the list is its route
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250", "DEFWPT HZA 52.3 4.6" })
  asked(ex("UAL182 route: direct HZA"), "a route for an aircraft not in the simulation")
  asked(ex("give UAL182 a route: direct HZA"), "a route given to an aircraft not in the simulation")
  check_eq(ex("KLM12 route: direct HZA"), "ADDWPT KLM12 HZA")
end

-- Cycle 50 (f130): a recogniser's levels and turns. A bare number after a correction that takes back a flight
-- level is the flight level ("flight level eight zero correction seven zero": FL70, had issued ALT 0); a level of
-- digits said one by one that is no level ("descend eight five") is asked, never re-read from one digit
-- (had issued 8000) nor from a "zero" (0); "turn left three sixty" (a whole circle said as a number, no
-- "heading") is asked: an orbit, or heading 360
do
  local _, ex = scene({ "CRE TOM72B B738 55.1 -3.2 090 FL140 280", "CRE LOG31 AT76 55.4 -3.9 270 FL80 210" })
  check_eq(ex("tomjet seven two bravo descend flight level one one zero correction niner zero"), "ALT TOM72B FL90")
  check_eq(ex("tomjet seven two bravo descend flight level eight zero correction seven zero"), "ALT TOM72B FL70")
  check_eq(ex("tomjet seven two bravo descend FL110 correction 100"), "ALT TOM72B FL100")
  check_eq(ex("tomjet seven two bravo descend flight level eight zero correction niner"), "ALT TOM72B 9000")
  asked(ex("tomjet seven two bravo descend eight five"), "a level said digit by digit, no flight level")
  asked(ex("tomjet seven two bravo descend seven zero"), "two digits bare: no ALT 0")
  asked(ex("logan three one turn right three sixty"), "an orbit or heading 360")
  asked(ex("logan three one turn left three hundred and sixty"), "an orbit or heading 360")
  check_eq(ex("logan three one turn right heading three sixty"), "HDG LOG31 360 RIGHT")
  check_eq(ex("logan three one turn left three six zero"), "HDG LOG31 360 LEFT")
end

-- Cycle 50 (f130): a flight number's last digit heard as the everyday word "on" ("logan three on descend": one,
-- or a word?) is confirmed when other aircraft fly; "won" and digits said are read as before
do
  local _, ex = scene({ "CRE LOG31 AT76 55.4 -3.9 270 FL80 210", "CRE TOM72B B738 55.1 -3.2 090 FL140 280" })
  asked(ex("logan three on descend flight level six zero"), "'on' closing the flight number")
  check_eq(ex("logan three one descend flight level six zero"), "ALT LOG31 FL60")
  check_eq(ex("logan three won descend flight level six zero"), "ALT LOG31 FL60")
end

-- Cycle 50 (f130): a waypoint's name as a recogniser hears it, after a constraint's, condition's or limit's word,
-- that sounds like exactly one waypoint of the routes flown as closely as a direct-to's name is taken (the same
-- letters or sound key) is that waypoint; one that sounds less alike, a place's own name, or the position of a
-- waypoint being added is still confirmed
do
  local _, ex = scene({ "DEFWPT LIFFY 53.5 -5.5", "DEFWPT BOYNE 53.7 -6.2", "CRE EIN77 A320 53.4 -6.3 090 FL150 280",
    "ADDWPT EIN77 LIFFY", "CRE RYR5K B738 53.0 -6.0 270 FL200 290", "ADDWPT RYR5K BOYNE" })
  check_eq(ex("shamrock seven seven after liffey descend flight level eight zero"), "AT EIN77 LIFFY DO ALT EIN77 FL80")
  check_eq(ex("shamrock seven seven cross liffey at flight level one zero zero"), "AT EIN77 LIFFY ALT FL100")
  asked(ex("ryanair five kilo after boy descend flight level one two zero"), "'boy' only sounds somewhat like BOYNE")
  asked(ex("shamrock seven seven add waypoint boyne after liffey"), "a route position of a waypoint added")
end

-- Cycle 50 (f130): TUI Airways (TOM) by its former telephony "Tomson" as well as "Tomjet"; a number that differs
-- is still asked
do
  local _, ex = scene({ "CRE TOM3KD B738 55.7 -4.5 090 FL90 250", "CRE LOG31 AT76 55.4 -3.9 270 FL80 210" })
  check_eq(ex("delete tomson three kilo delta"), "DEL TOM3KD")
  check_eq(ex("tomson three kilo delta climb flight level one two zero"), "ALT TOM3KD FL120")
  asked(ex("tomson three kilo echo climb flight level one two zero"), "a letter that differs")
end

-- Cycle 50 (g132a): a condition of passing a waypoint closing the request, then a comma (or "if") and framing
-- words only ("..., if you could", "..., if possible", "..., thanks"), runs at the waypoint; a value, name or
-- verb after it is still asked about
do
  local _, ex = scene({ "DEFWPT NAXEL 59.5 18.2", "DEFWPT BALVI 59.7 18.0", "CRE SAS1417 A20N 59.30 18.40 330 FL110 260",
    "ADDWPT SAS1417 NAXEL", "ADDWPT SAS1417 BALVI" })
  check_eq(ex("Could SAS1417 descend to FL90 once it passes BALVI, if that's alright?"), "AT SAS1417 BALVI DO ALT SAS1417 FL90")
  check_eq(ex("Please have SAS1417 reduce to 220 knots after passing NAXEL, thanks."), "AT SAS1417 NAXEL DO SPD SAS1417 220")
  asked(ex("Please make SAS1417 climb to FL150 once it passes NAXEL, if it is below FL200."), "a level in the tail")
  asked(ex("Please make SAS1417 climb to FL150 once it passes NAXEL, if you could turn it left too."), "a verb in the tail")
  asked(ex("Please make SAS1417 climb to FL150 once it passes NAXEL, if not BALVI."), "a name in the tail")
end

-- Cycle 50 (g132a): "if that works" (for you) and "if it works" hedge the whole request, as "if possible"; a
-- value after it is still asked about
do
  local _, ex = scene({ "DEFWPT GOSIV 59.5 18.2", "CRE SAS1417 A20N 59.30 18.40 330 FL110 260" })
  check_eq(ex("Please add GOSIV to the route of SAS1417, if that works."), "ADDWPT SAS1417 GOSIV")
  check_eq(ex("Descend SAS1417 to FL90 if that works for you."), "ALT SAS1417 FL90")
  asked(ex("Descend SAS1417 to FL90 if that works, otherwise FL100."), "another level offered")
end

-- Cycle 50 (g132w): "is it possible to" / "is it ok to" before a switch requests it, not a question about its
-- state; a "whether" after the switch's "on" is the instruction's purpose; a question about the state is still
-- shown
do
  local s, ex = scene({ "CRE KLM12 B738 52.0 4.0 090 FL200 250" })
  check_eq(ex("Is it ok to switch conflict detection on? I'd like to see the alerts."), "ASAS ON")
  local r = graph.translate("Is it possible to switch conflict detection off again?", { sim = s, mode = "offline" })
  check_eq(r.confirm and r.confirm.commands[1], "ASAS OFF")
  check_eq(ex("Please switch on conflict detection and fast-forward 2 minutes to check whether KLM12 gets an alert?"),
    "ASAS ON ; FF 120")
  check_eq(ex("Is it possible to check whether conflict detection is on?"), "ASAS")
  check_eq(ex("Is conflict detection off?"), "ASAS")
end

-- Cycle 50 (g132w): a new aircraft's callsign after "callsign" or "called" must be written as one (digits,
-- capitals, a registration, or a capitalised word squawk does not know); a plain English word is asked for
do
  local _, ex = scene({})
  asked(ex("Create a Boeing 737 at 52.0 4.0, FL100, heading 090, 250 knots; the callsign comes later."),
    "an English word after 'callsign'")
  asked(ex("Create an A320 at 52.0 4.0, FL100, heading 090, 250 knots, callsign still unknown."),
    "an English word after 'callsign'")
  check_eq(ex("Create an A320 at 52.0 4.0, FL100, heading 090, 250 knots, callsign tra123."),
    "CRE TRA123 A320 52 4 90 FL100 250")
end

-- Cycle 50 (g132w): "no wait, just <the last instruction again>" with other instructions said before it takes
-- nothing back and leaves unclear whether those stand: asked; "just <another instruction>" replaces the last
do
  local _, ex = scene({ "CRE KLM12 B738 52.0 4.0 090 FL200 250" })
  asked(ex("KLM12 reduce speed 220 and descend FL150, sorry, just descend FL150 for now"), "speed said before")
  asked(ex("KLM12 turn left heading 040 and climb FL240... no wait, only climb FL240 first"), "heading said before")
  check_eq(ex("KLM12 descend FL150, sorry, just descend FL160"), "ALT KLM12 FL160")
end

-- Cycle 50 (g132w): an airport said by a name that opens with a short capitalised word ("New Chitose") is the
-- airport of the whole name, not the one bearing its last word alone (that name alone is either)
do
  local _, ex = navscene({ "CRE ANA63 B788 42.85 141.10 090 9000 240" }, "an airport's full name")
  if ex then
    check_eq(ex("ANA63, destination New Chitose."), "DEST ANA63 RJCC")
    check_eq(ex("ANA63 destination Chitose"), "ASK Which airport is 'chitose': RJCJ or RJCC?")
  end
end

-- Cycle 50 (lead): a correction after a dash ("to Heathrow - no, hang on, sorry, to Stansted") is never set apart as
-- commentary: the place it names is read or asked, never dropped; a remark after a dash still is
do
  local _, ex = navscene({ "CRE EZY8MX A320 51.05 -0.45 020 4000 200", "DEST EZY8MX EGKK" }, "a dash correction")
  if ex then
    asked(ex("please change the easyJet's destination to Heathrow - no, hang on, sorry, to Stansted"),
      "a destination corrected after a dash")
    check_eq(ex("EZY8MX turn left 70 degrees - hard test of the turn model"), "HDG EZY8MX 310 LEFT")
  end
end

-- Cycle 50 (lead): a spoken value out of range that a shorter run of its words would fit only by leaving out its
-- closing zeros ("speed nine zero zero": 900 or 90?) is asked; a stutter at its start ("two two two zero") and
-- words heard after it ("one nine zero nine") are still re-read
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  asked(ex("klm12 speed nine zero zero knots"), "a speed's closing zero left out")
  asked(ex("klm12 reduce speed two five zero zero"), "250 or 2500")
  check_eq(ex("klm12 speed two two two zero knots"), "SPD KLM12 220")
  check_eq(ex("klm12 reduce speed one nine zero nine"), "SPD KLM12 190")
end

-- Cycle 50 (lead): BlueSky's DELAY typed by name with its time said in words ("delay half a minute then ...") waits
-- that long; a loose time ("a couple of minutes") is asked for, never dropped
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  check_eq(ex("delay a minute then KLM12 climb FL300"), "DELAY 60 ALT KLM12 FL300")
  check_eq(ex("delay half a minute, then KLM12 climb FL300"), "DELAY 30 ALT KLM12 FL300")
  asked(ex("delay a couple of minutes then KLM12 climb FL300"), "a loose time after 'delay'")
end

-- Cycle 51 (lead): a place's name said beside its code is accounted for by one rule (G:name_beside_code): the
-- navdata's name of that code, or capitalised words the navdata gives no place farther than 40 NM from it; a name
-- of a place elsewhere is asked, in a condition's slot, a direct-to and a destination alike
do
  local _, ex = navscene({ "CRE AC301 A320 40.0 -104.0 090 FL200 280", "CRE AC302 A320 45.5 8.8 090 FL200 280",
    "CRE AC303 A320 52.3 13.0 090 FL200 280" }, "a place's name beside its code, checked")
  if ex then
    check_eq(ex("ac301 direct to Tucson, GBN"),
      "ASK I have ADDWPT AC301 GBN ; DIRECT AC301 GBN. What does 'Tucson' mean?")
    check_eq(ex("ac302 dest Milan Malpensa, LIMC"), "DEST AC302 LIMC")
    check_eq(ex("ac303 dest Berlin, EDDB"), "DEST AC303 EDDB")
    asked(ex("ac303 dest Hamburg, EDDB"), "a city whose airport is far from the code")
    asked(ex("ac302 destination LIMC. Nice and simple"), "a capitalised word after a full stop is no name")
  end
end

-- Cycle 51 (f137): a condition in a Spanish or Portuguese speaker's English after "when" or "once" ("when it pass
-- over X", "when you arrive to X", "when arrives to FL250", "when you are at X", "when you are with 240 knots") is
-- the condition English says; "when you arrive" with nothing reached is still asked
do
  local _, ex = scene({ "DEFWPT ROSAL 40.5 -3.5", "DEFWPT NIBOL 40.7 -3.3", "CRE AEA21 B738 40.2 -3.8 030 FL150 280",
    "ADDWPT AEA21 ROSAL", "ADDWPT AEA21 NIBOL" })
  check_eq(ex("AEA21 descend FL90 when it pass over ROSAL"), "AT AEA21 ROSAL DO ALT AEA21 FL90")
  check_eq(ex("AEA21 when you arrive to NIBOL reduce to 210 knots"), "AT AEA21 NIBOL DO SPD AEA21 210")
  check_eq(ex("AEA21 descend FL100 when arrives to NIBOL"), "AT AEA21 NIBOL DO ALT AEA21 FL100")
  check_eq(ex("AEA21 climb FL250 and when you arrive at FL230 turn right heading 090"),
    "ALT AEA21 FL250 ; ATALT AEA21 FL230 HDG AEA21 90 RIGHT")
  check_eq(ex("AEA21 reduce 240 knots and when you are with 240 knots descend FL100"),
    "SPD AEA21 240 ; ATSPD AEA21 240 ALT AEA21 FL100")
  check_eq(ex("AEA21 descend FL100 and when you are at ROSAL reduce 220 knots"),
    "ALT AEA21 FL100 ; AT AEA21 ROSAL DO SPD AEA21 220")
  asked(ex("AEA21 when you arrive descend FL100"), "nothing reached")
  -- ("go down until FL100" after a speed: "until" the level to fly; a speed held "until" a level is still asked)
  check_eq(ex("AEA21 fly at 230 knots and go down until FL100"), "SPD AEA21 230 ; ALT AEA21 FL100")
  asked(ex("AEA21 reduce to 230 knots until FL100"), "a speed held until a level")
end

-- Cycle 51 (f137): Swiftair by its name; "which <state> has?" and "which is the route of ...?" (Spanish "cuál",
-- "tiene") ask for the aircraft's state or route; "which heading has it to fly?" is no such question
do
  local _, ex = scene({ "DEFWPT ROSAL 40.5 -3.5", "CRE AEA21 B738 40.2 -3.8 030 FL150 280", "ADDWPT AEA21 ROSAL",
    "CRE SWT45 AT72 40.0 -3.0 200 FL110 220" })
  check_eq(ex("Swiftair 45 climb FL130"), "ALT SWT45 FL130")
  check_eq(ex("the Swiftair, which speed has?"), "POS SWT45")
  check_eq(ex("which level has the Swiftair?"), "POS SWT45")
  check_eq(ex("Which is the route of the Air Europa?"), "LISTRTE AEA21")
  asked(ex("which heading has it to fly?"), "an instruction asked for")
  -- ("erase X of the route", "quit X of the route": the waypoint taken off; "quit X" with no route noun is asked)
  check_eq(ex("AEA21 erase ROSAL of the route"), "DELWPT AEA21 ROSAL")
  check_eq(ex("please quit ROSAL of the route of AEA21"), "DELWPT AEA21 ROSAL")
  asked(ex("AEA21 quit ROSAL"), "no route noun")
  -- (the clock's false friends: "velocity" after "normal" or "double", "fast the simulation")
  check_eq(ex("put the simulation in double velocity"), "DTMULT 2")
  check_eq(ex("fast the simulation 5 minutes"), "FF 300")
  -- ("connect the LNAV", "conectar": on, as "disconnect" is off)
  check_eq(ex("Air Europa 21 connect the LNAV"), "LNAV AEA21 ON")
  check_eq(ex("disconnect the VNAV of AEA21"), "VNAV AEA21 OFF")
  -- (the look-ahead "looking N minutes in front"; "looking" after no detection's name is no setting)
  check_eq(ex("set the conflict detection looking 5 minutes in front"), "DTLOOK 300")
  asked(ex("conflict detection on, AEA21 looking 5 minutes in front"), "no detection before 'looking'")
end

-- Cycle 51 (f137): a wind "in" a city and a move "until over" a navaid, as a Spanish or Portuguese speaker says them;
-- "in" and a time is still asked
do
  local _, ex = navscene({ "CRE VLG7 A320 41.3 2.0 100 FL200 260" }, "a wind in a city")
  if ex then
    check_eq(ex("put the wind of 250 degrees 30 knots in Barcelona"), "WIND LEBL 250 30")
    check_eq(ex("put the wind from 250 degrees with 30 knots in Girona"), "WIND LEGE 250 30")
    asked(ex("put the wind of 250 degrees 30 knots in 10 minutes"), "a time, no place")
  end
  _, ex = navscene({ "CRE SWT45 AT72 40.0 -3.0 200 FL110 220" }, "a move until over a navaid")
  if ex then
    check_eq(ex("move the Swiftair until over the VOR CJN"), "MOVE SWT45 CJN")
  end
end
-- Cycle 51 (f136): an aircraft named as the object of "got" ("I've got the KLM above at FL240") is described, its
-- level no instruction to it; an instruction given to it after the description is still read or asked
do
  local _, ex = scene({ "CRE BAW31 A320 52 4 090 FL180 280", "CRE KLM12 B738 52.2 4.2 270 FL240 280" })
  check_eq(ex("BAW31, climb FL220 only, I've got the KLM above at two four zero and he's descending."),
    "ALT BAW31 FL220")
  check_eq(ex("BAW31 climb FL220, we've got KLM12 at FL240."), "ALT BAW31 FL220")
  check_eq(ex("I've got KLM12 at FL240, climb him FL260"), "ALT KLM12 FL260")
  asked(ex("I've got KLM12 at FL240."), "a description alone instructs nobody")
end

-- Cycle 51 (f136): "not just" / "not only" adds what follows to the rest, no negation: "use vertical speed too, not
-- just heading" switches vertical resolutions on; a plain "not" still switches them off, "only vertical" asks
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  check_eq(ex("let the resolutions use vertical speed as well, not only heading and speed"), "RMETHV V/S")
  check_eq(ex("resolutions may use vertical too, not just horizontal manoeuvres"), "RMETHV V/S")
  check_eq(ex("the resolutions should not use vertical speed"), "RMETHV OFF")
  asked(ex("resolutions should use vertical only"), "no vertical-only method")
end

-- Cycle 51 (f136): "route direct X, he can skip Y" with Y before X on the route: the direct-to passes Y, no
-- deletion; Y after X on the route is still left out of it
do
  local _, ex = navscene({ "CRE UAE9 A388 51.95 1.00 230 FL180 300", "ADDWPT UAE9 BRAIN", "ADDWPT UAE9 LAM" },
    "a waypoint skipped by a direct-to")
  if ex then
    check_eq(ex("UAE9, route direct LAM, he can skip BRAIN, it's a shortcut."), "DIRECT UAE9 LAM")
    check_eq(ex("UAE9 direct BRAIN, then skip LAM on the route"), "DIRECT UAE9 BRAIN ; DELWPT UAE9 LAM")
  end
end

-- Cycle 51 (f136): a condition said after an instruction, "and once he's at FL280, Mach .78", "and once he's
-- passing FL110, left heading 160", "and when he's got two fifty, descend": the value after it waits for it
do
  local _, ex = scene({ "CRE BAW31 A320 52 4 090 FL180 280" })
  check_eq(ex("BAW31 climb FL330, and once he's at FL300, Mach point seven eight"),
    "ALT BAW31 FL330 ; ATALT BAW31 FL300 SPD BAW31 M0.78")
  check_eq(ex("BAW31 descend FL100, and once he's passing FL140, right heading 200"),
    "ALT BAW31 FL100 ; ATALT BAW31 FL140 HDG BAW31 200 RIGHT")
  check_eq(ex("BAW31 reduce speed 240 knots, and when he's got two forty, descend FL120"),
    "SPD BAW31 240 ; ATSPD BAW31 240 ALT BAW31 FL120")
  asked(ex("BAW31 descend FL120, and when he's got two forty, reduce speed 220"), "a speed had, never given")
end

-- Cycle 51 (f136): an aircraft said not to belong in the exercise ("X shouldn't be in this exercise at all; delete
-- him") is the reason for the deletion that follows; "at all" ending a clause counts no aircraft; the reason alone,
-- or with another aircraft deleted, is asked
do
  local _, ex = scene({ "CRE BAW31 A320 52 4 090 FL180 280", "CRE KLM12 B738 52.2 4.2 270 FL240 280" })
  check_eq(ex("KLM12 isn't part of this scenario at all, remove it"), "DEL KLM12")
  check_eq(ex("KLM12 shouldn't be here at all; delete it"), "DEL KLM12")
  asked(ex("KLM12 shouldn't be in this exercise; delete BAW31"), "another aircraft deleted")
  asked(ex("KLM12 shouldn't be in this exercise at all"), "a reason with nothing done")
  asked(ex("delete them all"), "every aircraft deleted is confirmed")
end

-- Cycle 51 (f136): traffic told "beneath" or "underneath", and an inbound told where it sits, after an instruction:
-- its level is the other aircraft's; an instructor's forecast opening "it'll"/"he'll" and a reason naming a stack
-- after a semicolon are remarks
do
  local _, ex = scene({ "CRE BAW31 A320 52 4 090 FL180 280", "CRE KLM12 B738 52.2 4.2 270 FL240 280" })
  check_eq(ex("BAW31 climb FL200, traffic underneath at one six zero."), "ALT BAW31 FL200")
  check_eq(ex("BAW31 climb FL200, there's an inbound holding at FL210."), "ALT BAW31 FL200")
  check_eq(ex("BAW31 descend FL150; it'll be tight on the KLM otherwise."), "ALT BAW31 FL150")
  asked(ex("BAW31 descend FL150; it'll be tight on the KLM at FL140."), "a level in the forecast")
  asked(ex("BAW31 climb FL200, inbound FL210."), "an inbound's level said bare")
end
do
  local _, ex = navscene({ "CRE BAW31 A320 51.3 0.0 090 FL180 280" }, "a stack named in a reason")
  if ex then
    check_eq(ex("BAW31 turn left heading 300; we need him well clear of the BIG stack."), "HDG BAW31 300 LEFT")
    asked(ex("BAW31 turn left heading 300; we need him well clear of BIG."), "a place with no reason word")
  end
end

-- Cycle 51 (f136): a new aircraft's spoken callsign whose first digit the matcher gave a flying aircraft
-- ("Speedbird seven | seven two Kilo" beside BAW97M) keeps the letters spelled after its flight number
do
  local _, ex = scene({ "CRE BAW97M A319 51.20 -0.10 360 FL080 220" })
  check_eq(ex("Create Speedbird Seven Seven Two Kilo, an A320, at 51 0 heading 135, FL130, 260 knots."),
    "CRE BAW772K A320 51 0 135 FL130 260")
  check_eq(ex("Create Speedbird Seven Four One Lima Mike, an A320, at 51 0 heading 135, FL130, 260 knots."),
    "CRE BAW741LM A320 51 0 135 FL130 260")
  check_eq(ex("Create Speedbird Seven Seven Two, an A320, at 51 0 heading 135, FL130, 260 knots."),
    "CRE BAW772 A320 51 0 135 FL130 260")
end

-- Cycle 51 (f136): "take <aircraft> out of the exercise" deletes it, however long its spoken callsign; out of
-- anything else ("out of the hold") is no deletion
do
  local _, ex = scene({ "CRE SAS1501 A20N 51.56 -0.10 180 7000 230", "CRE BAW97M A319 51.20 -0.10 360 FL080 220" })
  check_eq(ex("Take Scandinavian One Five Zero One out of the scenario, please."), "DEL SAS1501")
  check_eq(ex("take Scandinavian One Five Zero One out"), "DEL SAS1501")
  asked(ex("take Scandinavian One Five Zero One out of the hold"), "a hold left, no deletion")
end

-- Cycle 51 (f136): one word describing a new fix between "new" and its noun ("define a new training point, TRN3,
-- at ...") is no new aircraft; a fix with no name is still asked
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  check_eq(ex("Define a new training point, TP9, at fifty one decimal five north, zero decimal two east."),
    "DEFWPT TP9 51.5 0.2")
  check_eq(ex("define a new reporting waypoint RP7 at 52.1 4.3"), "DEFWPT RP7 52.1 4.3")
  asked(ex("Define a new training point at fifty one decimal five north, zero decimal two east."), "no name")
end
-- Cycle 51 (f139): US en-route typed shorthand. Abbreviations are lexicon entries read as their words where the
-- words beside them allow (dn, pd after a level, trfc, rchg, lvg, fph, corr, vctr, "20 lt", "whats ur hdg");
-- two typed digits of 30 to 99 after a level verb typed short are hundreds of feet, fewer are asked; a
-- lower-case "ff" under half a minute asks seconds or minutes, and "fast forward to <time>" asks clock or span
do
  local _, ex = scene({ "CRE SWA12 B737 41.30 -73.60 090 FL230 280", "CRE N55AB PA28 41.10 -73.40 180 5000 110" })
  check_eq(ex("swa12 dn fl190 rs 250"), "ALT SWA12 FL190 ; SPD SWA12 250")
  check_eq(ex("swa12 dn 70"), "ALT SWA12 7000")
  asked(ex("swa12 dn 14"), "two typed digits under 30 after 'dn': 1400 or 14000 ft")
  check_eq(ex("swa12 dn fl210 pd"), "ALT SWA12 FL210")
  check_eq(ex("n55ab cm 70 pd"), "ALT N55AB 7000")
  check_eq(ex("swa12 tr 30 trfc"), "HDG SWA12 120 RIGHT")
  check_eq(ex("swa12 dn fl200, rchg spd 240"), "ALT SWA12 FL200 ; ATALT SWA12 FL200 SPD SWA12 240")
  check_eq(ex("swa12 dn fl180 lvg fl210 spd 260"), "ALT SWA12 FL180 ; ATALT SWA12 FL210 SPD SWA12 260")
  check_eq(ex("n55ab fph"), "HDG N55AB 180")
  check_eq(ex("swa12 25 lt"), "HDG SWA12 65 LEFT")
  check_eq(ex("n55ab whats ur hdg"), "POS N55AB")
  check_eq(ex("n55ab 90 kts til 4 fnl"), "SPD N55AB 90")
  asked(ex("n55ab 90 kts til 9 fnl"), "a limit further out than the final approach's 6 miles")
  asked(ex("swa12 spd dn 20"), "'dn' after a speed's name is no descent")
  check_eq(ex("ff 45"), "FF 45")
  check_eq(ex("FF 8"), "FF 8")
  check_eq(ex("ff 2 hrs"), "FF 7200")
  asked(ex("ff 8"), "eight seconds or eight minutes")
  asked(ex("fast forward to 2 hrs"), "a time on the clock or a duration")
end
do
  local _, ex = navscene({ "CRE SWA12 B737 41.30 -73.60 090 FL230 280", "ADDWPT SWA12 SAX",
    "CRE N55AB PA28 41.10 -73.40 180 5000 110" }, "lower-case idents in US shorthand")
  if ex then
    check_eq(ex("swa12 x sax at fl200"), "AT SWA12 SAX ALT FL200")
    asked(ex("swa12 x sax 200"), "a crossing with a bare three-digit number")
    check_eq(ex("n55ab hdg 200 vctr cmk"), "HDG N55AB 200")
  end
end

-- Cycle 51 (f134): an aircraft said in place of the one instructed, after the instruction ("climb FL280, no, sorry,
-- I meant DLH2EC", "? No, sorry, I meant the Eurowings, not the Condor", "..., the Eurowings can stay like it is")
-- gets the instruction, the first none; other words after it with no instruction are asked
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250", "CRE AFR34 A320 52.3 4.3 180 FL220 260",
    "CRE BAW56 A319 52.5 4.6 270 FL240 250" })
  check_eq(ex("Please let KLM12 climb to FL300, no, sorry, I meant AFR34."), "ALT AFR34 FL300")
  check_eq(ex("Could you turn KLM12 onto heading 200? No, sorry, I meant AFR34, not KLM12."), "HDG AFR34 200")
  check_eq(ex("Let KLM12 fly heading 200. Sorry, I meant AFR34, KLM12 can stay as it is."), "HDG AFR34 200")
  check_eq(ex("turn KLM12 heading 200 -- sorry, AFR34 and BAW56"), "HDG AFR34 200 ; HDG BAW56 200")
  asked(ex("turn KLM12 heading 200, sorry, I meant AFR34, BAW56 can stay like it is"), "a third aircraft kept")
  check_eq(ex("turn KLM12 heading 200, sorry, AFR34 too"), "HDG KLM12 200 ; HDG AFR34 200")
end

-- Cycle 51 (f134): a condition said after its instruction ("as soon as it has slowed down to 260 knots", "when it has
-- reached FL380") waits for that instruction alone when the clause after it is said to run at once ("..., and reduce
-- to 260 knots now"); with no such word, which of the two waits is asked
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL360 290" })
  check_eq(ex("KLM12 descend to FL320 as soon as it has slowed down to 260 knots, and reduce to 260 knots now"),
    "ATSPD KLM12 260 ALT KLM12 FL320 ; SPD KLM12 260")
  check_eq(ex("KLM12 fly Mach 0.78 when it has reached FL380, and climb to FL380 immediately"),
    "ATALT KLM12 FL380 SPD KLM12 M0.78 ; ALT KLM12 FL380")
  check_eq(ex("KLM12 descend to FL320 as soon as it has slowed to 260 knots"), "ATSPD KLM12 260 ALT KLM12 FL320")
  asked(ex("KLM12 descend to FL320 once it has slowed to 260 knots, and turn left heading 200"), "which one waits")
end

-- Cycle 51 (f134): a decimal comma ("47,5 north", "8,5 degrees east", "factor to 1,1") is a decimal point before a
-- hemisphere in its range or after a value's noun; a grouping ("10,000") and a list glued to a level stay as written
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL360 290" })
  check_eq(ex("Could you move KLM12 to 51,4 north and 3,7 east, please?"), "MOVE KLM12 51.4 3.7")
  check_eq(ex("define a waypoint WPX at 48,25 N and 7,5 degrees east"), "DEFWPT WPX 48.25 7.5")
  check_eq(ex("set the vertical resolution factor to 1,2"), "RFACV 1.2")
  check_eq(ex("KLM12 descend to 10,000 feet"), "ALT KLM12 10000")
  asked(ex("KLM12 heading 270,5 north of the airway"), "a heading is no latitude")
end

-- Cycle 51 (f134): a waypoint condition after its instruction limited by "only" or "but only" ("descend to FL200,
-- but only after BETOS", "climb FL300 only when it is over BUMIL") starts the instruction there (AT ... DO)
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL250 250", "DEFWPT WPA 52 4.5", "DEFWPT WPB 52 5",
    "ADDWPT KLM12 WPA", "ADDWPT KLM12 WPB" })
  check_eq(ex("KLM12 should descend to FL200 only after WPA."), "AT KLM12 WPA DO ALT KLM12 FL200")
  check_eq(ex("Please let KLM12 climb to FL300, but only when it is over WPB."), "AT KLM12 WPB DO ALT KLM12 FL300")
  asked(ex("KLM12 descend to FL200, but EZY45 only after WPA"), "another aircraft named")
end

-- Cycle 51 (f134): "when it is on FL260" (German "auf") closing a condition is "at" the level; "turn on heading"
-- and "stay on FL260" are no condition
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL220 260" })
  check_eq(ex("climb KLM12 to FL260, and when it is on FL260 accelerate to 290 knots"),
    "ALT KLM12 FL260 ; ATALT KLM12 FL260 SPD KLM12 290")
  check_eq(ex("KLM12, when it is on FL240, turn left heading 200"), "ATALT KLM12 FL240 HDG KLM12 200 LEFT")
  check_eq(ex("KLM12 turn on heading 200"), "HDG KLM12 200")
end

-- Cycle 51 (f134): "... and start it" closing a request that named the simulation starts the clock; "start it" after
-- an aircraft's instruction is no clock
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL220 260" })
  check_eq(ex("Please set the speed of the simulation to factor 3 and start it."), "DTMULT 3 ; OP")
  check_eq(ex("set the sim rate to 2 and then run it, please"), "DTMULT 2 ; OP")
  check(not (ex("KLM12 climb FL300 and start it") or ""):find("OP"), "no clock started after an aircraft's instruction")
end

-- Cycle 51 (f134): "better" or "rather" in a self-correction's run ("FL 340. Ah no, wait, better FL 350") is part of
-- the correction; said without a marker ("FL340, better FL350") the second value is still asked about
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL310 260" })
  check_eq(ex("Please let KLM12 climb to FL 340. Ah no, wait, better FL 350."), "ALT KLM12 FL350")
  check_eq(ex("KLM12 reduce to 250 knots, no, rather 240 knots"), "SPD KLM12 240")
  asked(ex("KLM12 climb to FL340, better FL350"), "no correction marker")
end

-- Cycle 51 (f135): an interjection before a question about a setting ("hmm wait is conflict detection even on?")
-- leaves it a question (the setting shown), never switched; said before the switch itself it still switches
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  check_eq(ex("oh wait, is conflict detection actually on?"), "ASAS")
  check_eq(ex("hmm is asas even on rn?"), "ASAS")
  check_eq(ex("hmm, switch conflict detection on"), "ASAS ON")
end

-- Cycle 51 (f135): "not just" / "not only" adds to what follows ("use vertical too, not just heading and speed"
-- is RMETHV V/S); "not heading and speed" takes the horizontal resolutions away, which squawk cannot: asked
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  check_eq(ex("let resolutions go vertical too, not only heading changes"), "RMETHV V/S")
  check_eq(ex("resolutions should be not only lateral"), "RMETHV V/S")
  asked(ex("resolve with vertical, not with heading and speed"), "horizontal resolutions taken away")
  check_eq(ex("resolutions horizontal only please"), "RMETHV OFF")
end

-- Cycle 51 (f135): a loose value closed by a question mark ("heading like 200-ish?") is asked; said loosely
-- without one it is the value said
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  asked(ex("klm12 slow to 230ish?"), "a loose value asked about")
  asked(ex("klm12 turn to like 140-ish?"), "a loose heading asked about")
  check_eq(ex("klm12 slow to 230ish"), "SPD KLM12 230")
end

-- Cycle 51 (f135): "start it up" / "start it back up" starts the clock (OP) when no aircraft is named before it
-- for "it" to stand for; "skip like 30 secs" and "run it for 20 minutes real fast" fast-forward that long
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  check_eq(ex("ok we're ready, start it up"), "OP")
  check_eq(ex("start it back up and then KLM12 climb FL300"), "OP ; ALT KLM12 FL300")
  asked(ex("KLM12 start it up"), "'it' is the aircraft named")
  check_eq(ex("skip like 45 seconds"), "FF 45")
  check_eq(ex("run it for 5 minutes real quick"), "FF 300")
  asked(ex("run it for 5 minutes at real time"), "a rate and a duration")
end

-- Cycle 51 (f135): a chatty speaker's remarks beside an instruction carry none ("tho", "super aggressively",
-- "nothing's really happening", "way too close", "she's consented", "en route"); a block altitude stays asked
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250", "CRE KLM34 A320 52.2 4 090 FL220 250" })
  check_eq(ex("KLM12 bank 20 degrees tho, it rolls super aggressively"), "BANK KLM12 20")
  check_eq(ex("speed up the sim to 3x since nothing is happening"), "DTMULT 3")
  check_eq(ex("KLM12 descend FL180, it and KLM34 are way too close"), "ALT KLM12 FL180")
  check_eq(ex("he consented, so start it back up"), "OP")
  asked(ex("KLM12 climb block FL250 to FL270"), "a block altitude")
end

-- Cycle 51 (f135): "how big is the protected zone rn" (no "?") shows the setting; "zones to 10 miles" sets it
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  check_eq(ex("how large is the protected zone atm"), "ZONER")
  check_eq(ex("ok zones to 8 miles since it is en route"), "ZONER 8")
  asked(ex("how big is KLM12"), "no setting named")
end

-- Cycle 51 (f138): an aircraft described by the way it flies ("the one heading north", "the eastbound 737"), by
-- where it is ("the easternmost aircraft"), by when it was created ("the aircraft I created last") or picked from
-- a group said before ("of the two A320s, the lower one", "the lowest, ..."): one fits -> that aircraft, several
-- or none -> asked; the words are never a heading instructed
do
  local _, ex = scene({ "CRE AAA11 A320 52.0 4.0 020 FL240 280", "CRE BBB22 A320 52.5 4.5 200 FL300 250",
    "CRE CCC33 B738 52.2 5.0 160 FL120 250", "CRE DDD44 B738 51.8 3.6 100 FL200 240" })
  check_eq(ex("the one flying north, climb FL260"), "ALT AAA11 FL260")
  check_eq(ex("the aircraft heading east please descend FL180"), "ALT DDD44 FL180")
  check_eq(ex("the southbound 737, reduce 230 knots"), "SPD CCC33 230")
  asked(ex("the one heading south, reduce 230 knots"), "two aircraft head south (200 and 160)")
  asked(ex("the one heading south-west, climb FL320"), "none within 22.5 degrees of south-west (200, 160)")
  check_eq(ex("of the two A320s, could the higher one descend FL280"), "ALT BBB22 FL280")
  check_eq(ex("of the two 737s, please slow the faster one to 220 knots"), "SPD CCC33 220")
  asked(ex("of the three A320s, the lower one descend FL200"), "the count said is not the group's size")
  check_eq(ex("the lowest, climb FL140"), "ALT CCC33 FL140")
  check_eq(ex("the easternmost aircraft turn left heading 090"), "HDG CCC33 90 LEFT")
  check_eq(ex("the southernmost, descend FL190"), "ALT DDD44 FL190")
  check_eq(ex("the aircraft I created last, delete it"), "DEL DDD44")
  check_eq(ex("please show the position of the one we added first"), "POS AAA11")
  asked(ex("the aircraft I created, climb FL300"), "no word of order: which one")
end

-- Cycle 51 (f138): "the cargo aircraft", "the freighter" are asked (the traffic tells no cargo), never dropped beside
-- another aircraft instructed; "the DHL", "the ASL" are cargo groups' names; an aircraft described that no command
-- names is asked
do
  local _, ex = scene({ "CRE BEL94H AT76 50.60 3.30 090 FL110 210", "CRE BCS5TG A306 50.70 4.60 240 FL070 230",
    "CRE TAY3LK B734 50.70 4.90 090 FL100 250" })
  asked(ex("please delete the ATR and the cargo aircraft"), "the cargo aircraft is not in the traffic's data")
  asked(ex("the freighter, climb FL200"), "a freighter is not in the traffic's data")
  check_eq(ex("the DHL cargo plane, descend to 5000 feet"), "ALT BCS5TG 5000")
  check_eq(ex("the ASL, climb FL150"), "ALT TAY3LK FL150")
  asked(ex("define waypoint LOTUS at 50.8 N 4.1 E and then send the ATR there"), "the ATR's instruction unread")
end

-- Cycle 51 (f138): "switch on X, but without Y": "without" switches Y off, never X
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  local out = ex("please switch on the conflict detection, but without resolution")
  check(type(out) == "string" and not out:find("ASAS OFF", 1, true), "detection switched on, not off")
  check_eq(ex("klm12 lnav off hdg 250"), "LNAV KLM12 OFF ; HDG KLM12 250")
end


-- Cycle 51 (fhz): a condition "when you ..." of a unit or an event squawk does not model is asked, never dropped
-- (only the listener's convenience, "when you get a sec", is a courtesy)
do
  local _, ex = scene({ "CRE AEA21 A320 52 4 90 FL200 250" })
  asked(ex("AEA21 when you are with the tower descend FL100"), "a unit, no condition squawk reads")
  asked(ex("AEA21 descend FL100 when you are with approach"), "a unit, said after")
  asked(ex("AEA21 when you have the traffic in sight descend FL100"), "an event squawk does not model")
  asked(ex("AEA21 once you see the field climb FL300"), "an event squawk does not model")
  check_eq(ex("AEA21 when you get a sec descend FL100"), "ALT AEA21 FL100")
  check_eq(ex("AEA21 descend FL100 once you have a moment"), "ALT AEA21 FL100")
end

-- Cycle 51 (lead): a name a smaller field bears whole that a large airport's name also holds ("Changi": WSAC
-- "CHANGI AIR BASE" or WSSS "SINGAPORE CHANGI INTL") is asked, never the air base; an airline's name that a sister
-- airline's name begins ("AirAsia", "AirAsia X") with both flying is asked
do
  local _, ex = navscene({ "CRE CPA733 A333 1.6 104.3 230 FL120 250" }, "a name an air base bears whole")
  if ex then
    asked(ex("CPA733, when 15 miles from Changi, reduce to 180 knots"), "the air base or the airport")
    check_eq(ex("CPA733 destination WSSS"), "DEST CPA733 WSSS")
  end
  _, ex = scene({ "CRE AXM5106 A320 4.9 116.6 300 FL120 260", "CRE XAX522 A333 6.8 115.0 160 FL300 290" })
  check_eq(ex("the AirAsia one, descend to FL100"), "ASK Which AirAsia: AXM5106 or XAX522?")
  check_eq(ex("AirAsia X 522, descend to FL100"), "ALT XAX522 FL100")
  check_eq(ex("AirAsia 5106 descend FL100"), "ALT AXM5106 FL100")
end

-- Cycle 51 (lead): traffic said "at" a level with no instruction is traffic information, never a clearance to
-- that level or a heading of its digits; an instruction after a comma is still flown
do
  local _, ex = scene({ "CRE BAW2490 A320 51.5 -0.5 090 FL150 280" })
  check_eq(ex("Speedbird 2490, traffic at one one zero."), "")
  check_eq(ex("BAW2490 traffic at FL110"), "")
  check_eq(ex("BAW2490 traffic at FL110, climb FL170"), "ALT BAW2490 FL170")
  check_eq(ex("BAW2490 climb FL170, traffic at FL160"), "ALT BAW2490 FL170")
end

-- Cycle 51 (lead): an aircraft named beside a setting that is every aircraft's ("conflict detection for AEA21") is
-- asked, never dropped; "conflict" naming the setting is no context that excuses it ("to avoid a conflict with
-- AEA21" still is)
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250", "CRE AEA21 B738 40.4 -3.6 090 FL150 250" })
  check_eq(ex("conflict detection for AEA21"), "ASK I have ASAS ON. What does 'AEA21' mean?")
  check_eq(ex("turn on conflict resolution for AEA21"), "ASK I have RESO MVP. What does 'AEA21' mean?")
  check_eq(ex("KLM12 climb FL300 to avoid a conflict with AEA21"), "ALT KLM12 FL300")
end

-- Cycle 51 (lead): "and start it", "and stop it", "then begin" closing a request no clock command came from are
-- asked (the simulation's or the instruction's?), never dropped; with the simulation named it is the clock's
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  check_eq(ex("KLM12 climb FL300 and start it"), "ASK I have ALT KLM12 FL300. What does 'start it' mean?")
  check_eq(ex("KLM12 climb FL300 and stop it"), "ASK I have ALT KLM12 FL300. What does 'stop it' mean?")
  check_eq(ex("set dtmult 5 and start"), "ASK I have DTMULT 5. What does 'start' mean?")
  check_eq(ex("set the speed of the simulation to factor 5 and start it"), "DTMULT 5 ; OP")
  check_eq(ex("ff 2 mins then stop"), "FF 120")
end

-- Cycle 52 (f144): an instruction put as the controller's proposal ("I propose you to ...", "I suggest you ...",
-- closed by "is that ok for you?") is the instruction; a proposal said of someone else stays asked
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  check_eq(ex("KLM12, I propose you to climb flight level two six zero"), "ALT KLM12 FL260")
  check_eq(ex("KLM12, we suggest you a heading of one five zero, is that ok for you?"), "HDG KLM12 150")
  check_eq(ex("KLM12 descend FL150, I recommend you two thousand feet per minute"), "ALT KLM12 FL150 2000")
  asked(ex("KLM12, the pilot proposes flight level two six zero"), "a proposal that is the pilot's")
  asked(ex("KLM12 proposes flight level two six zero"), "the aircraft's proposal")
end

-- Cycle 52 (f144): a French speaker's hesitation "euh" ("heu") is "uh"; a French word read before its value
-- ("cap", "niveau", "vitesse", "monte") cut off and taken back by a correction is its English word, replaced
-- by what follows; cut off with no correction after it, it stays asked
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  check_eq(ex("KLM12, euh, reduce speed two one zero"), "SPD KLM12 210")
  check_eq(ex("KLM12, heu, climb FL250"), "ALT KLM12 FL250")
  check_eq(ex("KLM12, vitesse... sorry, speed two two zero"), "SPD KLM12 220")
  check_eq(ex("KLM12, niveau, correction, flight level two four zero"), "ALT KLM12 FL240")
  asked(ex("KLM12, vitesse... two two zero"), "a French word cut off, no correction")
  asked(ex("KLM12, cap... sorry"), "taken back with nothing after it")
end

-- Cycle 52 (f144): a condition on a speed "had" ("when you have two two zero") waits for the speed this request
-- gave; "when level" and three digits waits for that flight level; a speed had that the request never gave is
-- asked
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  check_eq(ex("KLM12 reduce two two zero knots, when you have two two zero, descend FL150"),
    "SPD KLM12 220 ; ATSPD KLM12 220 ALT KLM12 FL150")
  check_eq(ex("KLM12 descend level one five zero, when level one five zero, reduce speed two two zero knots"),
    "ALT KLM12 FL150 ; ATALT KLM12 FL150 SPD KLM12 220")
  asked(ex("KLM12 reduce two two zero knots, when you have two one zero, descend FL150"), "a speed never given")
  asked(ex("KLM12, when you have two two zero, descend FL150"), "a speed had, none given")
end

-- Cycle 52 (f144): an approach named by its runway ("expect the ILS two four left", "localizer approach 27
-- right") names the runway: its side is no turn's direction; a side said apart from the runway's number is
-- still asked against the turn's
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  check_eq(ex("KLM12, expect vectors for the ILS two four left, turn right heading two zero zero"),
    "HDG KLM12 200 RIGHT")
  check_eq(ex("KLM12, expect localizer approach 27 right, turn left heading 050"), "HDG KLM12 50 LEFT")
  asked(ex("KLM12, expect the ILS, two four left, turn right heading two zero zero"), "a side apart from the ILS")
end

-- Cycle 52 (f144): HOP!, telephony "Air Hop", is "the Hop" said alone; with two flying it is asked
do
  local _, ex = scene({ "CRE HOP45TR E145 46 5 090 FL090 230", "CRE AFR12 A320 46.5 5 180 FL200 250" })
  check_eq(ex("make the Hop descend level eight zero"), "ALT HOP45TR FL80")
  check_eq(ex("Air Hop four five tango romeo, climb FL110"), "ALT HOP45TR FL110")
  _, ex = scene({ "CRE HOP45TR E145 46 5 090 FL090 230", "CRE HOP7 E145 46.5 5 180 FL100 250" })
  asked(ex("make the Hop descend level eight zero"), "two Hops flying")
end

-- Cycle 52 (f144): "directly" before the place a move sets the aircraft over ("put the KLM directly over
-- NIRSI") is the move's manner, never a direct-to; "proceed directly over" a fix still is one
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250", "DEFWPT NIRSI 52.2 4.3" })
  check_eq(ex("can you put the KLM directly over NIRSI, level one two zero?"), "MOVE KLM12 NIRSI FL120")
  check_eq(ex("move KLM12 directly above NIRSI"), "MOVE KLM12 NIRSI")
  check_eq(ex("KLM12 proceed directly over NIRSI"), "ADDWPT KLM12 NIRSI ; DIRECT KLM12 NIRSI")
end

-- Cycle 52 (f144): an airline of two words said with "the" before a value said in words and its unit ("move the
-- Air Portugal ten miles north") is the airline's one aircraft, the value a distance, never a flight number
do
  local _, ex = scene({ "CRE TAP457 A320 48 2 020 FL150 290", "CRE KLM12 A320 52 4 090 FL200 250" })
  check_eq(ex("move the Air Portugal sixty miles to the north"), "MOVE TAP457 48.999326 2")
  check_eq(ex("turn the Air Portugal thirty degrees left"), "HDG TAP457 350 LEFT")
  asked(ex("Air Portugal sixty, climb FL200"), "a flight number no aircraft has")
end

-- Cycle 52 (f144): a new aircraft's registration set off by commas beside its type ("create a C172, HBKOF, at
-- ...") is its callsign; a word squawk knows there is none, asked for
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250", "DEFWPT NIRSI 52.2 4.3" })
  check_eq(ex("create a Cessna 172, HBXYZ, at NIRSI, heading 090, 3000 feet, 100 knots"),
    "CRE HBXYZ C172 NIRSI 90 3000 100")
  asked(ex("create a Cessna 172, HELLO, at NIRSI, heading 090, 3000 feet, 100 knots"), "a known word, no callsign")
end

-- Cycle 52 (f144): "stop the fast time" ends fast time (OP), as "stop the fast forward" does; it had paused the
-- simulation and started fast time with no end (HOLD ; FF). "stop the simulation" is still a pause
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  check_eq(ex("ok, stop the fast time now"), "OP")
  check_eq(ex("stop this fast-time"), "OP")
  check_eq(ex("stop the simulation"), "HOLD")
end

-- Cycle 52 (f144): a move's level said as a difference ("2000 feet higher than the others") is no level: with a
-- level said beside it that level is flown, alone it is asked
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250", "DEFWPT NIRSI 52.2 4.3" })
  check_eq(ex("move KLM12 directly over NIRSI, 2000 feet higher than now, so FL220"), "MOVE KLM12 NIRSI FL220")
  asked(ex("move KLM12 directly over NIRSI, 2000 feet higher"), "a difference, no level")
end

-- Cycle 52 (f142): formal Indian English. "the same may be done for the SpiceJet also", "do the same for", "give
-- the same to", "X also": the request's instructions given to an aircraft named by airline or type too (they had
-- been dropped or asked); a clause that only says "the same" with no aircraft is still asked
do
  local _, ex = scene({ "CRE VTI871 A21N 19 73 090 FL300 270", "CRE SEJ413 B738 19.5 73.5 180 FL320 280",
    "CRE AKJ220 B38M 18.5 72.5 000 FL280 260" })
  check_eq(ex("Vistara 871 climb to FL340. The same may be done for the SpiceJet also."),
    "ALT VTI871 FL340 ; ALT SEJ413 FL340")
  check_eq(ex("Vistara 871 speed 250 knots, do the same for the Akasa."), "SPD VTI871 250 ; SPD AKJ220 250")
  check_eq(ex("Vistara 871 heading 120 and give the same to the Akasa."), "HDG VTI871 120 ; HDG AKJ220 120")
  check_eq(ex("Vistara 871 climb FL340, SpiceJet 413 also."), "ALT VTI871 FL340 ; ALT SEJ413 FL340")
  check_eq(ex("Vistara 871 climb FL340, the same should be done for Akasa 220."), "ALT VTI871 FL340 ; ALT AKJ220 FL340")
  asked(ex("Vistara 871 climb FL340, the same may be done for the Qatar also."), "no Qatar flying")
  asked(ex("Vistara 871 heading 120, the same may be done for the Akasa, and Akasa 220 speed 250."),
    "the same as which instruction")
end

-- Cycle 52 (f142): Indian English office courtesy ("kindly do the needful", "please revert once done") and
-- "prepone the descent", "may be brought down to" are read; "revert to the previous heading" is still asked
do
  local _, ex = scene({ "CRE VTI871 A21N 19 73 090 FL300 270", "CRE AKJ220 B38M 18.5 72.5 000 FL280 260" })
  check_eq(ex("Vistara 871 heading 150, Akasa 220 heading 330, kindly do the needful urgently."),
    "HDG VTI871 150 ; HDG AKJ220 330")
  check_eq(ex("Kindly climb Vistara 871 to FL340. Please revert once done."), "ALT VTI871 FL340")
  check_eq(ex("Kindly prepone the climb of the Vistara to FL340."), "ALT VTI871 FL340")
  check_eq(ex("The Akasa may be brought down to FL200 now itself."), "ALT AKJ220 FL200")
  asked(ex("Vistara 871 kindly revert to the previous heading."), "no heading said")
  check_eq(ex("Akasa 220 kindly revert with its present vertical speed."), "POS AKJ220")
  check_eq(ex("Akasa 220 kindly report its current vertical speed."), "POS AKJ220")
end

-- Cycle 52 (f142): a value ruled out after "and not" or "only, not" is dropped as after "not"; a "not" that rules
-- out no value of the same kind is still asked
do
  local _, ex = scene({ "CRE VTI871 A21N 19 73 090 FL300 270" })
  check_eq(ex("Vistara 871 should climb to FL340 and not FL360."), "ALT VTI871 FL340")
  check_eq(ex("Correction, Vistara 871 heading 120 only, not 150."), "HDG VTI871 120")
  asked(ex("Vistara 871 climb FL340 and not too fast."), "a manner ruled out, no value")
end

-- Cycle 52 (f142): a waypoint of the route before a direct-to's place, said skipped or not required in its own
-- clause, is what the direct-to does; one after the place, or "is required", is asked
do
  local _, ex = scene({ "DEFWPT PUNAX 19.2 74", "DEFWPT TOREM 19.4 75", "CRE VTI871 A21N 19 73 090 FL300 270",
    "ADDWPT VTI871 PUNAX", "ADDWPT VTI871 TOREM" })
  check_eq(ex("Vistara 871 proceed to TOREM directly, PUNAX may be skipped."), "DIRECT VTI871 TOREM")
  check_eq(ex("Vistara 871 direct TOREM, PUNAX is not required."), "DIRECT VTI871 TOREM")
  asked(ex("Vistara 871 direct TOREM, PUNAX is required."), "a waypoint kept, no skip")
  asked(ex("Vistara 871 direct TOREM, PUNAX may be skipped later."), "a clause with more than the skip")
end

-- Cycle 52 (f142): an airline's IATA code typed between its name and the flight number ("SpiceJet SG 413", "IndiGo
-- 6E 702") is the airline said again; the code alone apart from its number is still asked (Cycle 24's decision)
do
  local _, ex = scene({ "CRE SEJ413 B738 19.5 73.5 180 FL320 280", "CRE IGO702 A20N 18.9 72.9 270 FL240 260" })
  check_eq(ex("SpiceJet SG 413 descend FL280."), "ALT SEJ413 FL280")
  check_eq(ex("IndiGo 6E 702 heading 300 please."), "HDG IGO702 300")
  check_eq(ex("create SpiceJet SG 1170, Boeing 737-800, at 19.8 N 73.1 E, heading 090, FL150, 250 knots"),
    "CRE SEJ1170 B738 19.8 73.1 90 FL150 250")
  asked(ex("SG 413 descend FL280."), "a code alone apart from its number")
  asked(ex("6E 702 heading 300 please."), "a digit code alone")
end

-- Cycle 52 (f142): a value given "to the" airline's aircraft names the addressee; "to the" after another verb stays
-- other traffic
do
  local _, ex = scene({ "CRE VTI871 A21N 19 73 090 FL300 270", "CRE UAE508 B77W 19.5 72.5 045 FL360 280" })
  check_eq(ex("Kindly give 260 knots to the Emirates."), "SPD UAE508 260")
  check_eq(ex("Please give a climb of 1500 feet per minute to the Emirates triple seven."), "VS UAE508 1500")
  check_eq(ex("Vistara 871 heading 200 to stay clear of the Emirates."), "HDG VTI871 200")
end

-- Cycle 52 (f142): AirAsia India (IAD) is of the AirAsia brand: "the AirAsia" alone with it the only one flying is
-- that aircraft; with another AirAsia flying it is asked
do
  local _, ex = navscene({ "CRE IAD771 A320 12.9 77.6 090 FL200 260", "CRE IGO852 A320 13 77 180 FL220 260" },
    "the AirAsia India")
  if ex then
    check_eq(ex("The AirAsia may be given 210 knots only."), "SPD IAD771 210")
    _, ex = navscene({ "CRE IAD771 A320 12.9 77.6 090 FL200 260", "CRE AXM5106 A320 4.9 116.6 300 FL120 260" }, "")
    asked(ex("The AirAsia may be given 210 knots only."), "two AirAsia aircraft")
  end
end

-- Cycle 52 (f142): an airline and a type opening a sentence ("IndiGo ATR may be climbed ...") describe the airline's
-- aircraft of that type, as after "the"; the airline alone with two flying, or a number heard as a callsign, is asked
do
  local _, ex = scene({ "CRE IGO640 A20N 14.2 77.5 170 FL130 260", "CRE IGO7730 AT76 13.4 77.8 120 7000 190" })
  check_eq(ex("IndiGo ATR may be climbed to 9000 feet."), "ALT IGO7730 9000")
  check_eq(ex("IndiGo A320 kindly descend to FL110."), "ALT IGO640 FL110")
  asked(ex("IndiGo may be climbed to 9000 feet."), "two IndiGo flying")
  asked(ex("IndiGo 320 descend FL110."), "a number heard as a callsign")
end

-- Cycle 52 (f142): "departing to" a place is where the aircraft goes, a description, never its origin
do
  local _, ex = scene({ "CRE IGO7730 AT76 13.4 77.8 120 7000 190" })
  check(not ex("IndiGo 7730 climb to 9000 feet, it is departing to VOMM."):find("ORIG", 1, true), "no origin")
  check_eq(ex("IndiGo 7730 departed VOBL."), "ORIG IGO7730 VOBL")
  _, ex = navscene({ "CRE IGO7730 AT76 13.4 77.8 120 7000 190", "DEST IGO7730 VOMM" }, "a city departed to")
  if ex then
    check_eq(ex("IndiGo 7730 climb to 9000 feet, it is departing to Chennai."), "ALT IGO7730 9000")
  end
end

-- Cycle 52 (f142): "kindly tell the route of X" and "what is the next waypoint of X" ask for the route (LISTRTE);
-- "tell X to follow the route" still instructs
do
  local _, ex = scene({ "DEFWPT PUNAX 11.9 80", "CRE AIC318 A321 11.5 79.8 035 FL120 260", "ADDWPT AIC318 PUNAX" })
  check_eq(ex("Kindly tell the route of Air India 318."), "LISTRTE AIC318")
  check_eq(ex("What is the next waypoint of Air India 318?"), "LISTRTE AIC318")
  check_eq(ex("Tell the Air India to follow the route."), "LNAV AIC318 ON")
  asked(ex("Air India 318 proceed to the next waypoint."), "no waypoint named")
end
-- Cycle 52 (fwr): "X also" ending a clause, X an airline or type said with "the", gets every instruction of the
-- request (had taken only the last from the aircraft first named)
do
  local _, ex = scene({ "CRE VTI301 A320 19 73 090 FL200 280", "CRE SEJ702 B738 19.5 73.5 270 FL180 270" })
  check_eq(ex("Vistara 301 climb FL240 and increase 290 knots, the SpiceJet also."),
    "ALT VTI301 FL240 ; SPD VTI301 290 ; ALT SEJ702 FL240 ; SPD SEJ702 290")
  check_eq(ex("Vistara 301 climb FL240 and increase 290 knots and the SpiceJet also."),
    "ALT VTI301 FL240 ; SPD VTI301 290 ; ALT SEJ702 FL240 ; SPD SEJ702 290")
  check_eq(ex("Vistara 301 climb FL240 and increase 290 knots, same for the SpiceJet."),
    "ALT VTI301 FL240 ; SPD VTI301 290 ; ALT SEJ702 FL240 ; SPD SEJ702 290")
  asked(ex("Vistara 301 climb FL240 and increase 290 knots, the Qatar also."), "no Qatar flying")
end

-- Cycle 52 (fwr): a type said after "the" with an airline after it ("the A321 IndiGo") is that airline's aircraft of
-- the type; one opening a clause with no instruction word after it is asked, never left to the aircraft before
do
  local _, ex = scene({ "CRE VTI301 A20N 19 73 090 FL200 280", "CRE VTI518 A21N 19.5 73.5 270 FL180 270",
                        "CRE SEJ702 B738 19.2 73.2 180 FL160 260" })
  check_eq(ex("Vistara 301 climb FL240, and the A321 Vistara turn right heading 030."),
    "ALT VTI301 FL240 ; HDG VTI518 30 RIGHT")
  asked(ex("Vistara 301 climb FL240, and the 737 Vistara turn right heading 030."), "no Vistara 737: asked")
  asked(ex("Vistara 301 climb FL240, and the A321 Vistara can be turned right heading 030."), "no instruction word after")
end

-- Cycle 52 (fwr): the second aircraft of "between the X and the Y" said by its airline is context, never instructed
do
  local _, ex = scene({ "CRE DLH4 A320 50 8 090 FL330 M.78", "CRE EZY5 A320 50 9 270 FL330 M.78" })
  check_eq(ex("there is a conflict between the Lufthansa and the easyJet, make the easyJet descend FL310"),
    "ALT EZY5 FL310")
  check_eq(ex("make the Lufthansa and the easyJet descend FL310"), "ALT DLH4 FL310 ; ALT EZY5 FL310")
end

-- Cycle 52 (fwr): a yes-no question about the protected zone's value shows the setting, never sets it; a value
-- said after the question is asked
do
  local _, ex = scene({ "CRE DLH4 A320 50 8 090 FL330 M.78" })
  check_eq(ex("Is the protected zone radius still 5 nm?"), "ZONER")
  check_eq(ex("Are we still at a PZ half height of 1000 ft?"), "ZONEDH")
  asked(ex("Is the protected zone radius 5 nm? Then set it to 3 nm."), "a value after the question")
  check_eq(ex("set the protected zone radius to 3 nm"), "ZONER 3")
end

-- Cycle 52 (fwr): a city said by its English name whose navdata airport of that name is the old, lesser one is its
-- large airport (lexicon.city_airports: "Bangalore" is VOBL, never VOBG, HAL)
do
  local _, ex = navscene({ "CRE IGO11 A20N 13.5 77.5 180 FL120 260" }, "the Bangalore airport checks")
  if ex then
    check_eq(ex("IGO11 change destination to Bangalore"), "DEST IGO11 VOBL")
    check_eq(ex("create IGO12 A320 at Bangalore airport heading 090 FL050 200"), "CRE IGO12 A320 VOBL 90 FL50 200")
  end
end

-- Cycle 52 (f143): self-corrections of a Dutch speaker's English: "nee" (no) is the marker wherever said; one to
-- three words after a comma or a hesitation, then "I mean", are said in place of what came before; a marker with
-- nothing after it is still asked
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250", "CRE AEA21 B738 52.4 4.6 090 FL150 250",
    "CRE TRA5QK B738 52.10 5.40 300 FL200 290", "CRE DLH4AX A321 51.90 5.90 320 FL260 300" })
  check_eq(ex("KLM12 heading 250, nee, 260"), "HDG KLM12 260")
  check_eq(ex("KLM12 climb FL300, nee, FL280"), "ALT KLM12 FL280")
  check_eq(ex("KLM12, eh, AEA21 I mean, climb FL300"), "ALT AEA21 FL300")
  check_eq(ex("Lufthansa, ehm, Transavia 5QK I mean, reduce 250"), "SPD TRA5QK 250")
  check_eq(ex("KLM12 reduce 230, eh, 220 I mean, and climb FL300"), "SPD KLM12 220 ; ALT KLM12 FL300")
  check_eq(ex("KLM12 reduce 230, eh, 220 I mean"), "ASK I have SPD KLM12 230. What does '220' mean?")
  check_eq(ex("KLM12 heading 250, nee"), "ASK You said 'no' with nothing after it. What is the corrected instruction?")
  asked(ex("KLM12 climb FL300, eh, heading 250 I mean, thanks"), "instead or as well")
end

-- Cycle 52 (f143): an aircraft described by its airline ("the Transavia") and named by its callsign in a closing
-- sentence or clause of its own ("Transavia 5QK that is.", "Lufthansa 4AX I mean.") is that aircraft, named once;
-- another aircraft named so is still asked about
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250", "CRE TRA5QK B738 52.10 5.40 300 FL200 290",
    "CRE DLH4AX A321 51.90 5.90 320 FL260 300" })
  check_eq(ex("The Transavia descend FL160. Transavia 5QK that is."), "ALT TRA5QK FL160")
  check_eq(ex("KLM12 and the Lufthansa both 240 knots, Lufthansa 4AX I mean."), "SPD KLM12 240 ; SPD DLH4AX 240")
  check_eq(ex("KLM12 170 knots, the Transavia too. Transavia 5QK I mean."), "SPD KLM12 170 ; SPD TRA5QK 170")
  check_eq(ex("The Transavia descend FL160. KLM12 that is."), "ASK I have ALT TRA5QK FL160. What does 'KLM12' mean?")
end

-- Cycle 52 (f143): a condition's bare value the request already gave the same aircraft ("climb to FL300, and when
-- he is at 300 ...", "reduce to 230 knots and when he has 230, ...") is that level or speed, waited for; a value
-- given to no one, or to another aircraft, is still asked
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250", "CRE AEA21 B738 52.4 4.6 090 FL150 250" })
  check_eq(ex("KLM12 climb to FL300, and when he is at 300 heading 270."),
    "ALT KLM12 FL300 ; ATALT KLM12 FL300 HDG KLM12 270")
  check_eq(ex("KLM12 climb to FL300. Then heading 270, when he is at 300."),
    "ALT KLM12 FL300 ; ATALT KLM12 FL300 HDG KLM12 270")
  check_eq(ex("KLM12 reduce to 230 knots and when he has 230, climb to FL300."),
    "SPD KLM12 230 ; ATSPD KLM12 230 ALT KLM12 FL300")
  asked(ex("KLM12 climb to FL300, and when he is at 290 heading 270."), "a level not given")
  asked(ex("AEA21 climb FL300, and when he is at 300 KLM12 heading 270."), "another aircraft's level")
  asked(ex("KLM12 reduce to 230 knots and when he has 220, climb to FL300."), "a speed not given")
end

-- Cycle 52 (f143): an aircraft said to go on as it flies, in a clause of its own beside instructions to others
-- ("..., and AEA21 stays on his route", "AEA21 keeps his speed."), is no instruction and no unknown word; a clause
-- that says more ("AEA21 stays low") is still asked
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250", "CRE AEA21 B738 52.4 4.6 090 FL150 250",
    "CRE TRA5QK B738 52.10 5.40 300 FL200 290" })
  check_eq(ex("KLM12 climb FL300, and AEA21 stays on his route."), "ALT KLM12 FL300")
  check_eq(ex("KLM12 climb FL300. The Transavia stays where he is."), "ALT KLM12 FL300")
  check_eq(ex("KLM12 climb FL300, AEA21 keeps his speed."), "ALT KLM12 FL300")
  check_eq(ex("KLM12 climb FL300, AEA21 stays low."), "ASK I have ALT KLM12 FL300. What does 'AEA21' mean?")
  asked(ex("AEA21 stays where he is."), "no instruction at all")
  check_eq(ex("KLM12 keep present heading, turn 10 degrees left"), "HDG KLM12 80 LEFT")
end

-- Cycle 52 (fcn): an airline said by a name it is known by (names.common: "Qatar", "Malaysia", "British Airways")
-- before its flight number is that callsign wherever it stands, matched exactly as a telephony is; a verb the
-- matcher glued to an airline it cannot name suggests no aircraft; HK Express, Hong Kong Airlines, Batik Air
do
  local _, ex = scene({ "CRE QTR615 B788 25.2 51.6 120 FL330 280", "CRE CPA615 A359 22.3 114.2 090 FL350 280",
    "CRE BAW615 B77W 51.5 -0.5 090 FL310 280", "CRE MAS615 A333 3.1 101.5 300 FL290 280",
    "CRE HKE329 A320 22.3 114.0 200 FL240 270", "CRE CRK770 A332 22.4 114.1 180 FL260 270",
    "CRE MXD52 B738 3.0 101.6 010 FL220 260" })
  check_eq(ex("descend Qatar 615 to FL290"), "ALT QTR615 FL290")
  check_eq(ex("turn British Airways 615 left heading 270"), "HDG BAW615 270 LEFT")
  check_eq(ex("reduce Malaysia Airlines six one five to 250 knots"), "SPD MAS615 250")
  check_eq(ex("give Qatar Airways 615 a new destination, OMDB"), "DEST QTR615 OMDB")
  check_eq(ex("remove Malaysia 615 from the scenario"), "DEL MAS615")
  check_eq(ex("descend HK Express 329 to FL200"), "ALT HKE329 FL200")
  check_eq(ex("Hong Kong Express 329 climb FL260"), "ALT HKE329 FL260")
  check_eq(ex("turn Hong Kong Airlines 770 right heading 090"), "HDG CRK770 90 RIGHT")
  check_eq(ex("Batik Air 52 descend FL180"), "ALT MXD52 FL180")
  -- a flight number no aircraft of that airline has is asked; a name no aircraft's airline bears suggests none
  asked(ex("descend Qatar 616 to FL290"), "Qatar 616 flies not")
  check_eq(ex("descend Zorbair 615 to FL290"), "ASK There is no aircraft 'Zorbair 615'. Which aircraft do you mean?")
end

-- Cycle 52 (f145): a navaid said by its navdata name in a limit's, a constraint's or a condition's slot ("until
-- ockham", "when you get to lambourne") is the one navaid of that name on the routes flown; a name off the route
-- of the aircraft addressed is still asked
do
  local _, ex = navscene({ "CRE EZY45TC A319 51.25 0.20 300 FL090 250", "ADDWPT EZY45TC BIG", "ADDWPT EZY45TC OCK",
    "CRE RYR8KL B738 51.80 0.40 200 FL150 290", "ADDWPT RYR8KL LAM" }, "a navaid said by its name")
  if ex then
    check_eq(ex("easy four five tango charlie hold two thirty knots till ockham"), "SPD EZY45TC 230")
    check_eq(ex("ryanair eight kilo lima when you reach lambourne climb flight level one six zero"),
      "AT RYR8KL LAM DO ALT RYR8KL FL160")
    check_eq(ex("ryanair eight kilo lima once you get to lambourne turn left heading one eight zero"),
      "AT RYR8KL LAM DO HDG RYR8KL 180 LEFT")
    asked(ex("easy four five tango charlie hold two thirty knots till lambourne"), "a navaid off its route")
  end
end

-- Cycle 52 (f145): a user waypoint named letters then digits (TEST1, WP12) said as the word then each digit ("test
-- one", "wp one two") is that waypoint; a digit more than its name holds ("test one two" with TEST1 only) is asked
do
  local s = scene({ "DEFWPT TEST1 51.6 -0.7", "DEFWPT WP12 51.2 -0.2", "CRE SHT8 A320 51.45 -0.3 250 FL080 250" })
  local function ex(text)
    return said(graph.translate(text, { sim = s, mode = "offline", waypoints = { "TEST1", "WP12" } }))
  end
  check_eq(ex("shuttle eight proceed direct test one"), "ADDWPT SHT8 TEST1 ; DIRECT SHT8 TEST1")
  check_eq(ex("shuttle eight add wp one two to the route"), "ADDWPT SHT8 WP12")
  check_eq(ex("shuttle eight direct wp 1 2"), "ADDWPT SHT8 WP12 ; DIRECT SHT8 WP12")
  asked(ex("shuttle eight direct test one two"), "a digit more than TEST1 holds")
  asked(ex("shuttle eight direct wp one"), "WP1 is no waypoint")
end

-- Cycle 52 (f145): operators a recogniser writes by name: Aurigny (telephony Ayline, AUR) and BA CityFlyer ("the
-- city flyer", CFE), in a list of instructions too; "british airways" with BAW and CFE flying is still asked
do
  local _, ex = scene({ "CRE AUR64 AT76 51.0 -1.0 045 FL050 200", "CRE CFE23 E190 51.5 0.2 090 3000 220",
    "CRE BAW2FN A35K 51.47 -0.8 270 FL100 280" })
  check_eq(ex("speedbird two foxtrot november climb flight level one two zero and ayline six four climb flight "
    .. "level seven zero"), "ALT BAW2FN FL120 ; ALT AUR64 FL70")
  check_eq(ex("the aurigny turn left heading three six zero"), "HDG AUR64 360 LEFT")
  check_eq(ex("the city flyer reduce two hundred knots"), "SPD CFE23 200")
  asked(ex("the british airways one reduce two hundred knots"), "BAW2FN or CFE23")
end

-- Cycle 52 (fcs): a remark in its own sentence or clause in the declarative shape (a subject and its verb, an
-- apology, thanks) beside an instruction is set aside; one that could instruct (a wish or a modal with an
-- instruction word, a present-tense instruction, a correction, a value, an aircraft, a name that may be a place) is
-- still asked or read
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250", "CRE AEA21 B738 52.3 4.5 180 FL150 250" })
  check_eq(ex("Could KLM12 descend to FL150? Sorry, my colleague is calling me."), "ALT KLM12 FL150")
  check_eq(ex("Could KLM12 descend to FL150? I am sorry, I created it a bit too high."), "ALT KLM12 FL150")
  check_eq(ex("KLM12 descend to FL150 please, sorry I climbed it by mistake."), "ALT KLM12 FL150")
  check_eq(ex("Please delete AEA21, I created it by mistake."), "DEL AEA21")
  check_eq(ex("Sorry to bother you, could KLM12 descend to FL150?"), "ALT KLM12 FL150")
  check_eq(ex("Could KLM12 descend to FL150? Then the picture is symmetric."), "ALT KLM12 FL150")
  check_eq(ex("Could KLM12 descend to FL150? Sorry if that is too low for it."), "ALT KLM12 FL150")
  check_eq(ex("Could KLM12 descend to FL150? Cargo traffic isn't part of my study."), "ALT KLM12 FL150")
  check_eq(ex("KLM12 descend to FL150. I defined the point before the run."), "ALT KLM12 FL150")
  check_eq(ex("KLM12 descend to FL150. It's a test of how the vertical geometry affects detection."), "ALT KLM12 FL150")
  check_eq(ex("KLM12 descend to FL150. Then it heads towards Rotterdam, I believe."), "ALT KLM12 FL150")
  check_eq(ex("KLM12 descend to FL150. I created it too high, sorry."), "ALT KLM12 FL150")
  check_eq(ex("KLM12 climb to flight level two one zero? No wait, two two zero. Sorry!"), "ALT KLM12 FL220")
  -- near variants: still asked or read as said
  asked(ex("KLM12 descend to FL150. Sorry!"), "an apology closing the request, no correction before it")
  asked(ex("KLM12 descend to FL150. I typed that wrong, sorry."), "the speaker's own saying judged")
  asked(ex("KLM12 descend to FL150. Then it turns left."), "a present-tense instruction")
  asked(ex("KLM12 descend to FL150. I want it to turn left."), "a wish with an instruction word")
  asked(ex("KLM12 descend to FL150. It should turn left."), "a modal with an instruction word")
  asked(ex("KLM12 descend to FL150. I think it goes to FL100."), "a value in the remark")
  asked(ex("KLM12 descend to FL150. AEA21 is too close."), "an aircraft in the remark")
  asked(ex("KLM12 descend to FL150, sorry I said it by mistake."), "the speaker's own saying judged")
  check_eq(ex("KLM12 descend to FL150. Sorry, FL160."), "ALT KLM12 FL160")
  check_eq(ex("KLM12 descend to FL150, sorry I meant AEA21."), "ALT AEA21 FL150")
  check_eq(ex("KLM12 climb to FL300, if the weather allows."), "ALT KLM12 FL300")
  check_eq(ex("ok so this is the second trial, can KLM12 climb to FL300"), "ALT KLM12 FL300")
  check_eq(ex("Could KLM12 climb to FL300? Real time is too slow for my participants."), "ALT KLM12 FL300")
  asked(ex("KLM12 climb to FL300, so Stuttgart is its destination, I guess."), "a correction's place")
  local _, zone = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  check_eq(zone("Could you make the protected zone radius 3 nautical miles? In my thesis we use a smaller one."), "ZONER 3")
end

-- Cycle 52 (lead): a correction is never a remark set aside. "X? No." takes X back ("Move TULIP? No. Move it to
-- DAHLI") and a remark after "no," gives the reason of a taking back, still asked when nothing replaces what it took
-- back; only an apology opening a remark takes nothing back
do
  local _, ex = scene({ "DEFWPT TULIP 52.3 4.6", "DEFWPT DAHLI 52.5 4.8", "CRE KL204 A320 52.0 4.0 090 FL250 280",
    "ADDWPT KL204 TULIP", "ADDWPT KL204 DAHLI" })
  check_eq(ex("Move TULIP? No. Move KL204 to DAHLI at FL200."), "MOVE KL204 DAHLI FL200")
  asked(ex("Move TULIP? No. Move KL204 to WPZ9 at FL200."), "the place taken back, the other unknown")
  asked(ex("KL204 direct DAHLI, no, that is already the next one. Just speed 250."), "a direct-to taken back")
  check_eq(ex("KL204 speed 250. Sorry, my phone is ringing."), "SPD KL204 250")
end

-- Cycle 52 (h1): corrections and retractions dropped or misread. A present heading said after a self-correction
-- takes the heading and its side back; "no, leave it" takes back what came before as "forget that" does; the
-- aircraft's normal speed after a limit is never the simulation's rate; one level tied to a waypoint said twice is
-- one instruction; where the aircraft flies on, said as a fact, is no destination set
do
  local _, ex = navscene({ "CRE KLM12 B738 52.0 4.5 180 FL150 250", "ADDWPT KLM12 SPY", "ADDWPT KLM12 EHAM",
    "CRE DLH4 A320 51.5 6.8 120 FL200 280", "ADDWPT DLH4 DUS", "CRE AFR7 A320 51.7 6.5 230 FL190 290",
    "ADDWPT AFR7 ELDAR" }, "corrections and retractions")
  if ex then
    check_eq(ex("KLM12 turn right heading 200, sorry, fly present heading"), "HDG KLM12 180")
    check_eq(ex("KLM12 turn left heading 240, no, continue present heading"), "HDG KLM12 180")
    check_eq(ex("KLM12 turn right 20 degrees from present heading"), "HDG KLM12 200 RIGHT")
    check_eq(ex("KLM12 turn twenty degrees to the left of its present heading"), "HDG KLM12 160 LEFT")
    asked(ex("KLM12 turn right heading 200, continue present heading"), "a present heading with no correction")
    asked(ex("KLM12 turn right heading 200, sorry, present heading, right"), "a side said after the correction")
    check_eq(ex("Conflict detection off. No wait, leave it. Resolution MVP on."), "RESO MVP")
    check_eq(ex("KLM12 speed 220. No, leave it as it is. Climb KLM12 to FL170 instead."), "ALT KLM12 FL170")
    asked(ex("Conflict resolution off. No, leave it."), "taken back with nothing in its place")
    check_eq(ex("AFR7 270 knots until ELDAR, after that its normal speed again."), "SPD AFR7 270")
    check_eq(ex("AFR7 270 knots until ELDAR, then back to normal speed."), "SPD AFR7 270")
    check_eq(ex("Set the sim to normal speed again."), "DTMULT 1")
    asked(ex("AFR7 270 knots. After that normal speed again."), "whose normal speed: the aircraft's or the sim's")
    check_eq(ex("After DUS the Lufthansa has to climb to FL240. So: DLH4 at DUS climb FL240."),
      "AT DLH4 DUS DO ALT DLH4 FL240")
    asked(ex("After DUS the Lufthansa has to climb to FL240. So: DLH4 at DUS climb FL250."), "two levels at DUS")
    check_eq(ex("KLM12 speed 220, then it goes on to EHAM."), "SPD KLM12 220")
    asked(ex("KLM12 at SPY speed 220, then he heads to EDDF."), "a place off its route said as where it flies on")
  end
end

-- Cycle 52 (h2): places. A coordinate's degrees and minutes said in words are both read (never the minutes
-- dropped); a direct-to whose place is a hold is asked (no hold is simulated); a waypoint placed by its order on
-- a route ("the next waypoint") is never read as a waypoint's name
do
  local _, ex = scene({ "DEFWPT KOMPA 47.2 6.1", "CRE SWR41 A320 47.0 6.0 090 FL200 260", "ADDWPT SWR41 KOMPA",
    "CRE EZS12 A320 46.5 6.5 180 FL150 250" })
  check_eq(ex("define a waypoint BRAVO at forty-seven degrees thirty north, six degrees fifteen east"), "DEFWPT BRAVO 47.5 6.25")
  check_eq(ex("define waypoint BRAVO at four seven degrees one two minutes north, zero zero six degrees zero east"),
    "DEFWPT BRAVO 47.2 6")
  check_eq(ex("define waypoint BRAVO at 47 degrees twenty north, 6 degrees 0 east"), "DEFWPT BRAVO 47.333333 6")
  asked(ex("define waypoint BRAVO at forty-seven degrees seventy north, six degrees zero east"), "minutes of 70")
  asked(ex("SWR41 proceed to the hold at KOMPA"), "a hold flown to")
  asked(ex("SWR41 proceed into the published holding over KOMPA"), "a hold flown to, another wording")
  check_eq(ex("SWR41 proceed to KOMPA"), "DIRECT SWR41 KOMPA")
  asked(ex("EZS12 proceed to the next waypoint"), "no route to hold a next waypoint")
  asked(ex("EZS12 direct to the last fix"), "no route to hold a last waypoint")
end

-- Cycle 52 (h2): where the scenario names its waypoints (a route's, defined) by the phonetic alphabet, another such word that names a
-- navaid of another ident ("TANGO", the TGO VORTAC) is asked (a waypoint not yet defined is as likely), unless the
-- navaid's kind is said after it
do
  local _, ex = navscene({ "DEFWPT KOMPA 48.3 8.9", "DEFWPT ECHO 48.4 8.5", "CRE DLH7TX A320 48.2 8.7 090 FL200 260",
    "ADDWPT DLH7TX ECHO", "ADDWPT DLH7TX KOMPA" }, "a phonetic word naming a navaid")
  if ex then
    asked(ex("DLH7TX add TANGO after KOMPA"), "TANGO: the navaid TGO or a waypoint not yet defined")
    asked(ex("DLH7TX proceed direct TANGO"), "TANGO in a direct-to")
    check_eq(ex("DLH7TX proceed direct the TANGO VOR"), "ADDWPT DLH7TX TGO ; DIRECT DLH7TX TGO")
    check_eq(ex("define waypoint TANGO at 48.5 9.0"), "DEFWPT TANGO 48.5 9")
  end
  -- (no waypoint of the scenario named by a letter: the navaid of the name, as before)
  local _, near = navscene({ "DEFWPT KOMPA 48.3 8.9", "CRE DLH7TX A320 48.2 8.7 090 FL200 260" }, "a navaid name")
  if near then check_eq(near("DLH7TX add TANGO after KOMPA"), "ADDWPT DLH7TX TGO,,,KOMPA") end
end

-- Cycle 52 (h2): a city said as a destination or an origin whose airport found by name is a small field (LFLG "Grenoble
-- Le Versoud", where the city's traffic flies to LFLS "SAINT GEOIRS") is confirmed, never sent in silence
do
  local _, ex = navscene({ "CRE AFR22KL A320 44.9 5.2 180 FL200 260" }, "a city's small field")
  if ex then
    asked(ex("AFR22KL destination Grenoble"), "Grenoble: the small field LFLG")
    asked(ex("AFR22KL change the destination to Montpellier"), "Montpellier: the small field LFNG")
    asked(ex("AFR22KL origin Grenoble"), "an origin too")
    check_eq(ex("AFR22KL destination Marseille"), "DEST AFR22KL LFML")
    check_eq(ex("AFR22KL destination LFLS"), "DEST AFR22KL LFLS")
  end
end

-- Cycle 52 (h3): aircraft sets. "same to the X" (no verb) and "the X too"/"also" with X an airline, a type or a
-- maker name the one aircraft of it flying, or ask; never a silent drop
do
  local _, ex = scene({ "CRE ETD401 A320 24.0 54.0 090 FL200 280", "CRE QTR77 B738 24.2 54.2 090 FL220 280",
    "CRE UAE9 B77W 24.4 54.4 090 FL240 280" })
  check_eq(ex("ETD401 speed 250, same to the Qatari"), "SPD ETD401 250 ; SPD QTR77 250")
  check_eq(ex("ETD401 speed 250, the same to the Emirates please"), "SPD ETD401 250 ; SPD UAE9 250")
  check_eq(ex("ETD401 climb FL300 and the 737 too"), "ALT ETD401 FL300 ; ALT QTR77 FL300")
  check_eq(ex("ETD401 climb FL300, same for the triple seven"), "ALT ETD401 FL300 ; ALT UAE9 FL300")
  asked(ex("ETD401 climb FL300 and the Boeing also"), "two Boeings flying")
  asked(ex("ETD401 climb FL300 and the Airbus too"), "the only Airbus is the one instructed")
  asked(ex("ETD401 climb FL300 and the Embraer as well"), "no Embraer flying")
  asked(ex("ETD401 speed 250, same to the Lufthansa"), "no Lufthansa flying")
end

-- Cycle 52 (h3): "the same" for a value counted from the aircraft's own state ("turn left 10", "descend by 2000
-- feet") is asked, never copied as the first aircraft's heading or level
do
  local _, ex = scene({ "CRE SAS31 A320 55.0 10.0 090 FL330 280", "CRE NAX7 B77W 55.5 10.5 270 FL330 270" })
  asked(ex("SAS31 turn right 15 degrees, NAX7 too"), "a relative turn copied")
  asked(ex("SAS31 climb by 1000 feet, same for the 777"), "a relative climb copied")
  check_eq(ex("SAS31 turn left heading 080, and the 777 as well"), "HDG SAS31 80 LEFT ; HDG NAX7 80 LEFT")
end

-- Cycle 52 (h3): a yes-no question about a setting's value ("is DTMULT still 5?") is asked, never set
do
  local _, ex = scene({ "CRE KLM12 A320 52 4 090 FL200 250" })
  asked(ex("Is DTMULT still 8?"), "a question about the rate")
  asked(ex("are we still looking ahead 240 seconds?"), "a question about the look-ahead")
  asked(ex("is the sim running at 3x"), "a question about the rate, no question mark")
  check_eq(ex("is it possible to set DTMULT to 8?"), "DTMULT 8")
  check_eq(ex("Is the resolution still MVP?"), "RESO")
end

-- Cycle 52 (h3): a new aircraft's level said against another aircraft's ("1000 feet lower than KLM880") is counted
-- from that aircraft's level, or asked; never the height said taken as the level
do
  local _, ex = scene({ "CRE MAS30 B772 3.0 101.0 270 FL350 290", "CRE AXM5 A320 3.5 101.5 090 FL300 280" })
  check_eq(ex("create MAS31, a B772, at 3.2 N 101.2 E, 2000 ft lower than MAS30, heading 270, 290 knots"),
    "CRE MAS31 B772 3.2 101.2 270 FL330 290")
  check_eq(ex("create MAS31 B772 at 3.2 N 101.2 E, 1000 ft above AXM5, heading 090, 280 knots"),
    "CRE MAS31 B772 3.2 101.2 90 FL310 280")
  asked(ex("create MAS31 B772 at 3.2 N 101.2 E, 1000 ft higher than MAS99, heading 090, 280 knots"), "no such aircraft")
  asked(ex("create MAS31 B772 at 3.2 N 101.2 E, 1000 ft lower, heading 090, 280 knots"), "lower than what")
  asked(ex("create MAS31 B772 at 3.2 N 101.2 E, 1000 ft below the Airbus, heading 090, 280 knots"), "an aircraft described")
end

-- Cycle 52 (h3): a waypoint called skipped that the direct-to does not skip (after its place, or off the route) is
-- asked; one before it is set aside as before
do
  local _, ex = scene({ "DEFWPT ALPHA1 52.1 4.1", "DEFWPT BRAVO2 52.3 4.3", "DEFWPT CHARL3 52.5 4.5",
    "DEFWPT DELTA4 52.0 4.9", "CRE KLM15 A320 52.0 4.0 045 FL200 250", "ADDWPT KLM15 ALPHA1", "ADDWPT KLM15 BRAVO2",
    "ADDWPT KLM15 CHARL3" })
  check_eq(ex("KLM15 direct BRAVO2, ALPHA1 can be skipped"), "DIRECT KLM15 BRAVO2")
  asked(ex("KLM15 direct BRAVO2, CHARL3 can be skipped"), "the place after the direct-to's")
  asked(ex("KLM15 direct ALPHA1, BRAVO2 is not needed"), "the place after the direct-to's, 'not needed'")
  asked(ex("KLM15 direct BRAVO2, DELTA4 may be omitted"), "a place off the route")
end

-- Cycle 52 (lead): "on reaching" before "route direct" or "fly direct" waits for the level cleared before it, as
-- before "direct" or "proceed direct" (the direct-to had been flown at once); with no level cleared it is asked
do
  local _, ex = scene({ "DEFWPT TULIP 52.3 4.6", "CRE KL204 A320 52.0 4.0 090 FL200 280", "ADDWPT KL204 TULIP" })
  check_eq(ex("KL204 climb FL250, on reaching route direct TULIP"), "ALT KL204 FL250 ; ATALT KL204 FL250 DIRECT KL204 TULIP")
  check_eq(ex("KL204 descend FL150 and on reaching fly direct TULIP"), "ALT KL204 FL150 ; ATALT KL204 FL150 DIRECT KL204 TULIP")
  asked(ex("KL204 on reaching route direct TULIP"), "no level cleared to reach")
end

-- Cycle 53 (fnum): a point grouping thousands before feet ("11.000 feet", "1.500 ft per minute"), an apostrophe
-- grouping them ("11'000 ft"), a decimal comma before a distance ("2,5 NM") or after Mach ("Mach ,79") are read; an
-- altitude, rate or zone half height too small to be meant (a few feet, a few ft/min) is asked, never issued
do
  local _, ex = scene({ "CRE DLH41 A320 50.0 8.0 090 FL200 280", "CRE EWG12 A319 49.5 8.5 270 8000 250" })
  check_eq(ex("DLH41 descend to FL 120 with 1.500 ft per minute"), "ALT DLH41 FL120 1500")
  check_eq(ex("EWG12 climb to 11.000 feet"), "ALT EWG12 11000")
  check_eq(ex("EWG12 climb to 11'000 ft"), "ALT EWG12 11000")
  check_eq(ex("EWG12 climb 1.000 ft more"), "ALT EWG12 9000")
  check_eq(ex("EWG12 lose 1.000 ft"), "ALT EWG12 7000")
  check_eq(ex("set the zone height to 1.000 ft"), "ZONEDH 1000")
  check_eq(ex("set the protected zone radius to 2,5 NM"), "ZONER 2.5")
  check_eq(ex("set the zone radius to 4.500 NM"), "ZONER 4.5")
  check_eq(ex("DLH41 fly Mach ,79"), "SPD DLH41 M0.79")
  check_eq(ex("create KLM7 A320 at 50.2 N 8.4 E heading 090, 6.000 ft, 250 knots"), "CRE KLM7 A320 50.2 8.4 90 6000 250")
  check_eq(ex("DLH41 vs 0"), "VS DLH41 0")
  asked(ex("EWG12 descend to 7.000"), "a point before three figures, no unit: 7 or 7000")
  asked(ex("DLH41 descend to FL 120 with 1.500"), "a point before three figures after a level, no unit")
  asked(ex("EWG12 descend to 7 feet"), "an altitude of 7 ft")
  asked(ex("DLH41 descend with 5 fpm"), "a rate of 5 ft/min")
  asked(ex("set the zone height to 2 ft"), "a zone half height of 2 ft")
  asked(ex("create KLM7 A320 at 50.2 N 8.4 E heading 090, 6 ft, 250 knots"), "a new aircraft at 6 ft")
end

-- Cycle 53 (fwr): a remark's words never become a setting ("it's only noise" is no NOISE ON; "I believe it is off"
-- switches nothing, and with no other switching word the switch is asked); "run the sim in fast time" is the fast
-- time alone; a capital A spelled in a callsign is its letter; a field named in a creation is used or asked;
-- "to" after "give"/"assign" names the aircraft instructed; a compass word inside an aircraft's reference is no
-- heading; a compass description with a second aircraft close to the point is asked
do
  local _, ex = scene({ "DEFWPT TULIP 52.3 4.6", "CRE KLM77 B738 52.1 4.5 180 FL150 250",
    "CRE SWA12 B737 52.0 4.0 315 FL200 280", "CRE EZY45 A320 52.2 4.2 290 FL220 280",
    "CRE AZA9 E190 52.4 4.4 120 FL180 260", "CRE DLH4 B738 52.3 4.1 250 FL250 290" })
  check_eq(ex("delete KLM77, it's only noise in this scenario"), "DEL KLM77")
  check_eq(ex("delete KLM77, it's noise"), "DEL KLM77")
  check_eq(ex("KLM77 switch on VNAV, I believe it is off"), "VNAV KLM77 ON")
  asked(ex("KLM77 VNAV, I believe it's on"), "the only switching word is the state told")
  check_eq(ex("please run the sim in fast time until I tell you"), "FF")
  check_eq(ex("run the simulation and fast forward 2 minutes"), "OP ; FF 120")
  check_eq(ex("create Speedbird 4 A C, a B744, at 51.5 N 0.5 W, heading 270, FL 200, 300 knots"),
    "CRE BAW4AC B744 51.5 -0.5 270 FL200 300")
  check_eq(ex("create Speedbird 4 C A, an A320, at 51.5 N 0.5 W, heading 270, FL 200, 300 knots"),
    "CRE BAW4CA A320 51.5 -0.5 270 FL200 300")
  check_eq(ex("create Speedbird 4 A B744 at 51.5 N 0.5 W, heading 270, FL 200, 300 knots"),
    "CRE BAW4 B744 51.5 -0.5 270 FL200 300")
  check_eq(ex("create IBE33 A320 at 40.4 N 3.7 W heading 180 altitude 9000 feet velocity 250"),
    "CRE IBE33 A320 40.4 -3.7 180 9000 250")
  asked(ex("create IBE33 A320 at 40.4 N 3.7 W heading 180 altitude 9000 feet velocity"), "a speed field with no speed")
  asked(ex("create IBE33 A320 at 40.4 N 3.7 W heading 180 altitude 9000 feet speed"), "a speed field with no speed")
  check_eq(ex("assign FL240 to the Airbus and to the Embraer"), "ALT EZY45 FL240 ; ALT AZA9 FL240")
  asked(ex("assign FL240 to the Boeing"), "three Boeings")
  asked(ex("the Airbus and the Boeing climb FL260"), "three Boeings beside the one Airbus")
  check_eq(ex("the Lufthansa one, the Boeing, climb FL260"), "ALT DLH4 FL260")
  asked(ex("the one flying northwest, descend FL190"), "315 and 290 both near northwest")
  check_eq(ex("the one flying southeast, descend FL170"), "ALT AZA9 FL170")
  check_eq(ex("turn the southwest one toward TULIP"), "HDG SWA12 TULIP")
  check_eq(ex("turn the southwest one southeast"), "HDG SWA12 135")
end

-- Cycle 53 (fwr): a navaid said by its name and its kind ("the las vegas vor") is that navaid, never a fix named like
-- one word of the name; a name no navaid of the kind said has is asked
do
  local _, ex = navscene({ "CRE UAL77 B738 36.3 -115.6 090 FL200 280", "CRE SKW5 CRJ9 36.0 -115.3 270 FL120 250",
    "CRE AAL9 A321 35.9 -115.0 300 FL150 260" }, "navaids said with their kind")
  if ex then
    check_eq(ex("UAL77 proceed direct the las vegas vor"), "ADDWPT UAL77 LAS ; DIRECT UAL77 LAS")
    check_eq(ex("UAL77 direct boulder city vortac"), "ADDWPT UAL77 BLD ; DIRECT UAL77 BLD")
    asked(ex("UAL77 direct las vegas ndb"), "no NDB has that name")
  end
end

-- Cycle 53 (fus): US FAA controller phraseology (JO 7110.65) typed as said, over one Chicago Center scene: a
-- speed with a level condition after another speed, "and at FIX" opening the next instruction, a type said with
-- its series in hundreds, CommutAir's telephony, and the clearances read already, kept
do
  local _, ex = scene({ "DEFWPT BOSCO 41.5 -88.5", "DEFWPT LENDY 41.7 -87.8", "DEFWPT WATSN 41.9 -88.1",
    "DEFWPT KRENA 41.3 -87.9", "CRE AAL1036 B738 41.2 -88.0 045 FL240 300", "ADDWPT AAL1036 BOSCO",
    "ADDWPT AAL1036 LENDY", "CRE SKW5432 CRJ7 41.3 -88.3 090 12000 280", "ADDWPT SKW5432 WATSN",
    "CRE N731DK C172 41.6 -88.6 270 4500 110", "CRE RPA4512 E75L 41.0 -87.5 315 FL190 290", "ADDWPT RPA4512 KRENA",
    "CRE EJA525 C56X 41.8 -88.4 180 FL230 270", "CRE JIA5301 CRJ9 41.4 -87.6 250 11000 260",
    "CRE AWE1496 A320 41.1 -88.2 020 FL310 290", "CRE ENY3410 E75L 41.5 -87.7 200 9000 250",
    "CRE LXJ412 CL35 41.7 -88.0 090 FL350 300", "CRE JZA823 DH8D 41.9 -87.6 300 14000 240",
    "CRE UCA4455 E145 41.0 -88.8 090 6000 220" })
  -- a speed band's level said bare ("above FL100 speed 300"): the level crossed into it, climbing into "above",
  -- descending into "below"; the other way, or a level the aircraft will not pass, asked
  check_eq(ex("Commutair forty-four fifty-five, climb and maintain flight level two four zero, above flight level one "
    .. "zero zero speed three zero zero knots"), "ALT UCA4455 FL240 ; ATALT UCA4455 FL100 SPD UCA4455 300")
  check_eq(ex("UCA4455 climb and maintain flight level two four zero, speed two five zero knots, above flight level "
    .. "one zero zero speed three zero zero knots"),
    "ALT UCA4455 FL240 ; SPD UCA4455 250 ; ATALT UCA4455 FL100 SPD UCA4455 300")
  check_eq(ex("Commutair 4455 climb and maintain one two thousand, above one zero thousand increase speed to two eight zero"),
    "ALT UCA4455 12000 ; ATALT UCA4455 10000 SPD UCA4455 280")
  check_eq(ex("Cactus fourteen ninety-six, descend and maintain one one thousand, below flight level two zero zero "
    .. "reduce speed to two five zero"), "ALT AWE1496 11000 ; ATALT AWE1496 FL200 SPD AWE1496 250")
  check_eq(ex("Cactus 1496 descend and maintain one one thousand, reduce speed to two eight zero, below flight level two "
    .. "zero zero speed two five zero"), "ALT AWE1496 11000 ; SPD AWE1496 280 ; ATALT AWE1496 FL200 SPD AWE1496 250")
  asked(ex("UCA4455 climb and maintain eight thousand, above flight level one zero zero speed three zero zero knots"),
    "a band's level the climb never reaches")
  asked(ex("Commutair 4455 speed two five zero, below flight level one zero zero speed two two zero"),
    "'below' for an aircraft already below it")
  asked(ex("Cactus 1496 descend and maintain one one thousand, above flight level two zero zero speed three zero zero"),
    "'above' for a descent: a speed kept until the level, not simulated")
  -- a level passed or levelled at, after a first speed, opens the second speed's clause
  check_eq(ex("American ten thirty-six, reduce speed to two eight zero, passing flight level two three zero reduce "
    .. "speed to two five zero"), "SPD AAL1036 280 ; ATALT AAL1036 FL230 SPD AAL1036 250")
  check_eq(ex("American 1036 reduce speed to two eight zero and passing flight level two three zero reduce speed to "
    .. "two five zero"), "SPD AAL1036 280 ; ATALT AAL1036 FL230 SPD AAL1036 250")
  check_eq(ex("Jazz eight twenty-three, climb and maintain one six thousand, reduce speed to two one zero, when level "
    .. "at one six thousand reduce one niner zero"), "ALT JZA823 16000 ; SPD JZA823 210 ; ATALT JZA823 16000 SPD JZA823 190")
  asked(ex("American 1036 reduce speed to two eight zero, two five zero"), "two speeds, no condition between")
  -- "and at FIX" after an instruction's value opens the next instruction there (AT ... DO); off the route, or a
  -- speed said before "at FIX" (met there or started there?), asked
  check_eq(ex("Brickyard forty-five twelve, descend and maintain one four thousand and at KRENA reduce speed to two "
    .. "five zero"), "ALT RPA4512 14000 ; AT RPA4512 KRENA DO SPD RPA4512 250")
  asked(ex("Brickyard 4512 descend and maintain one four thousand and at WATSN reduce speed to two five zero"),
    "a waypoint off the aircraft's route")
  asked(ex("Brickyard 4512 reduce speed to two three zero at KRENA"), "a speed met at KRENA or started there")
  -- a type said with its series in hundreds
  check_eq(ex("create Skywest fifty-two oh one, CRJ seven hundred, at WATSN, heading zero four five, one zero thousand, "
    .. "two five zero knots"), "CRE SKW5201 CRJ7 WATSN 45 10000 250")
  check_eq(ex("create UPS twelve forty-four, a seven sixty-seven three hundred, at WATSN, heading zero niner zero, four "
    .. "thousand, two one zero knots"), "CRE UPS1244 B763 WATSN 90 4000 210")
  check_eq(ex("create Delta two fifty, a seven thirty-seven niner hundred, at BOSCO, heading one eight zero, one five "
    .. "thousand, two eight zero knots"), "CRE DAL250 B739 BOSCO 180 15000 280")
  check_eq(ex("create Jazz seventy-six twenty-three, dash eight four hundred, at LENDY, heading one five zero, niner "
    .. "thousand, two two zero knots"), "CRE JZA7623 DH8D LENDY 150 9000 220")
  check_eq(ex("create Envoy thirty-four eleven, an E one seventy-five, at KRENA, heading one eight zero, niner thousand, "
    .. "two five zero knots"), "CRE ENY3411 E75L KRENA 180 9000 250")
  check_eq(ex("create United twelve, a seven seventy-seven two hundred, at LENDY, heading one eight zero, flight level "
    .. "three five zero, two eight zero knots"), "CRE UAL12 B772 LENDY 180 FL350 280")
  asked(ex("create Skywest 5202, a CRJ three hundred, at WATSN, heading 045, 10000, 250 knots"), "no CRJ-300")
  asked(ex("create United 13, a seven sixty-seven five hundred, at WATSN, heading 180, FL350, 280 knots"), "no 767-500")
  asked(ex("create Jazz 7624, a dash eight five hundred, at WATSN, heading 150, 9000, 220 knots"), "no Dash 8-500")
  asked(ex("create Delta 251, a seven thirty-seven, at BOSCO, heading 180, 15000, 280 knots"), "the 737 family alone")
  -- CommutAir's telephony
  check_eq(ex("Commutair forty-four fifty-five, turn left heading three six zero"), "HDG UCA4455 360 LEFT")
  -- 7110.65 clearances read already, kept
  check_eq(ex("American ten thirty-six, climb and maintain flight level three one zero"), "ALT AAL1036 FL310")
  check_eq(ex("Skywest fifty-four thirty-two, cross WATSN at and maintain one zero thousand"), "AT SKW5432 WATSN ALT 10000")
  check_eq(ex("American 1036 cross BOSCO at and maintain flight level two zero zero"), "AT AAL1036 BOSCO ALT FL200")
  asked(ex("Skywest 5432 cross WATSN at or above one one thousand"), "only an exact constraint")
  check_eq(ex("Execjet five twenty-five, climb and maintain flight level three five zero, when able proceed direct LENDY"),
    "ALT EJA525 FL350 ; ADDWPT EJA525 LENDY ; DIRECT EJA525 LENDY")
  check_eq(ex("Blue Streak fifty-three oh one, descend and maintain eight thousand, upon reaching eight thousand reduce "
    .. "speed to two one zero"), "ALT JIA5301 8000 ; ATALT JIA5301 8000 SPD JIA5301 210")
  check_eq(ex("Cactus 1496 reduce speed to two five zero, when slowed to two five zero descend and maintain one two "
    .. "thousand"), "SPD AWE1496 250 ; ATSPD AWE1496 250 ALT AWE1496 12000")
  asked(ex("Cactus fourteen ninety-six, descend and maintain flight level two four zero, when slowed to two five zero "
    .. "descend and maintain one two thousand"), "slowed with no speed cleared")
  check_eq(ex("Cactus 1496 increase speed to three one zero"), "SPD AWE1496 310")
  check_eq(ex("Envoy thirty-four ten, maintain two one zero knots or greater"), "SPD ENY3410 210")
  asked(ex("Brickyard 4512 maintain maximum forward speed"), "no speed said")
  check_eq(ex("November seven three one delta kilo, turn right heading three six zero"), "HDG N731DK 360 RIGHT")
  check_eq(ex("N731DK descend and maintain three thousand"), "ALT N731DK 3000")
  check_eq(ex("Skywest 5432 climb and maintain one four thousand, upon reaching proceed direct WATSN"),
    "ALT SKW5432 14000 ; ATALT SKW5432 14000 DIRECT SKW5432 WATSN")
  check_eq(ex("Execjet 525 descend and maintain flight level one niner zero at two thousand feet per minute"),
    "ALT EJA525 FL190 2000")
  check_eq(ex("Flexjet four twelve, turn ten degrees left"), "HDG LXJ412 80 LEFT")
  asked(ex("Flexjet 412 descend via the arrival"), "no level said")
  asked(ex("Envoy 3410 after KRENA descend and maintain four thousand"), "KRENA off its route")
end

-- Cycle 53 (f148): a question about what an aircraft does with an adverb of time between it and "doing" ("what is
-- the Edelweiss actually doing?", German "aktuell": at present) shows it, as without the adverb
do
  local _, ex = scene({ "CRE EDW14 A320 47.0 8.0 090 FL200 260", "CRE SWR2 A333 47.5 8.5 270 FL300 280" })
  check_eq(ex("What is the Edelweiss actually doing?"), "POS EDW14")
  check_eq(ex("what is SWR2 currently doing"), "POS SWR2")
  check_eq(ex("What is the Swiss now doing?"), "POS SWR2")
  asked(ex("What is the Condor actually doing?"), "no Condor flying")
end

-- Cycle 53 (f148): a comma between a verb of telling or knowing and the question clause it opens (German
-- punctuation: "tell me, on which flight level ...") is no break; the clause is that verb's question
do
  local _, ex = scene({ "CRE EDW14 A320 47.0 8.0 090 FL200 260", "CRE SWR2 A333 47.5 8.5 270 FL300 280" })
  check_eq(ex("Could you tell me, at which altitude the Edelweiss is?"), "POS EDW14")
  check_eq(ex("I would like to know, on which level the Swiss flies."), "POS SWR2")
  check_eq(ex("Please tell me, which performance model squawk uses."), "PERF")
  asked(ex("Could you tell me, on which flight level the Condor is?"), "no Condor flying")
end

-- Cycle 53 (f148): "the <name> scenario" said after "with", "for", "of", "in" ("We start now with the Zurich
-- scenario.", "Now we come to the Basel scenario.") is the scenario the study is at, no file to load; after
-- "load", "switch to" or as the object of "start" the file is still asked
do
  local _, ex = scene({ "CRE EDW14 A320 47.0 8.0 090 FL200 260" })
  check_eq(ex("We begin now with the Zurich scenario of the experiment. Please let the Edelweiss climb to FL 240."),
    "ALT EDW14 FL240")
  check_eq(ex("Now we come to the Basel scenario. Please let the Edelweiss descend to FL 120."), "ALT EDW14 FL120")
  asked(ex("Please switch to the Basel scenario."), "a scenario to load")
  asked(ex("Start the Basel scenario."), "a scenario to load")
  asked(ex("Please load the Zurich scenario and let the Edelweiss climb to FL 240."), "a scenario to load")
end

-- Cycle 53 (f148): after a condition set off by commas, the main clause's subject and modal in German word order
-- ("..., when it has reached 300 knots, it shall climb to FL 350", "..., let it ...") are the sentence's grammar:
-- the instruction waits for the condition; another aircraft named there is still asked
do
  local _, ex = scene({ "CRE SWR2 A333 47.5 8.5 270 FL300 280", "CRE EDW14 A320 47.0 8.0 090 FL200 260" })
  check_eq(ex("Please let the Swiss slow down to 250 knots, and when it has reached 250 knots, it should descend to FL 260."),
    "SPD SWR2 250 ; ATSPD SWR2 250 ALT SWR2 FL260")
  check_eq(ex("Please let the Edelweiss climb to FL 240, and when it is at FL 240, let it turn right heading 180."),
    "ALT EDW14 FL240 ; ATALT EDW14 FL240 HDG EDW14 180 RIGHT")
  check_eq(ex("When the Swiss has reached FL 320, it shall reduce to 260 knots."), "ATALT SWR2 FL320 SPD SWR2 260")
  asked(ex("Please let the Swiss slow down to 250 knots, and when it has reached 250 knots, the Edelweiss shall climb to FL 240."),
    "another aircraft after the condition")
end

-- Cycle 53 (f148): "the before created aircraft", "the newly created plane", "the new aircraft" after a request that
-- created exactly one aircraft is that new aircraft; with two created, or none, it is asked
do
  local _, ex = scene({ "CRE SWR2 A333 47.5 8.5 270 FL300 280" })
  check_eq(ex("Please create an Edelweiss A320 with callsign EDW31 at 47.2 N 8.1 E, heading 090, FL 150, 260 knots, and let the before created aircraft climb to FL 220."),
    "CRE EDW31 A320 47.2 8.1 90 FL150 260 ; ALT EDW31 FL220")
  check_eq(ex("Please create EDW31, an A320, at 47.2 N 8.1 E, heading 090, FL 150, 260 knots, and turn the newly created plane left heading 060."),
    "CRE EDW31 A320 47.2 8.1 90 FL150 260 ; HDG EDW31 60 LEFT")
  asked(ex("Please let the before created aircraft climb to FL 220."), "no aircraft created in the request")
  asked(ex("Please create EDW31 A320 at 47.2 N 8.1 E, heading 090, FL 150, 260 knots and EDW32 A320 at 47.3 N 8.1 E, heading 090, FL 170, 260 knots, and let the before created aircraft climb to FL 220."),
    "two aircraft created")
end

-- Cycle 53 (f150): "send X to" a place typed in lower case or in two words: an airport's whole name ("san diego"),
-- a navaid name beside the airport ("oakland"), a large airport's IATA code that is no English word ("sfo"); an
-- English word after "to" ("sea", "the left") is asked
do
  local _, ex = navscene({ "CRE JBU5 A320 37.5 -122.0 300 FL120 260", "CRE SKW12 CRJ9 32.9 -117.0 000 FL110 250" },
    "lower-case destinations after send")
  if ex then
    check_eq(ex("send the skywest to san diego"), "DEST SKW12 KSAN")
    check_eq(ex("pls send JBU5 to San Jose"), "DEST JBU5 KSJC")
    check_eq(ex("send jetblue 5 to oakland"), "DEST JBU5 KOAK")
    check_eq(ex("send the jetblue to sfo"), "DEST JBU5 KSFO")
    asked(ex("send the jetblue to sea"), "'sea' is an English word, no airport code")
    asked(ex("send the jetblue to the left"), "no place after 'to'")
  end
end

-- Cycle 53 (f150): "the triple 7" typed with a digit is the 777, as "the triple seven" is; two 777s flying, asked
do
  local _, ex = scene({ "CRE AAL32 B77W 34.3 -114.8 070 FL370 280", "CRE HAL12 A332 34.0 -113.5 260 FL380 260" })
  check_eq(ex("turn the triple 7 left 20 degrees"), "HDG AAL32 50 LEFT")
  local _, two = scene({ "CRE AAL32 B77W 34.3 -114.8 070 FL370 280", "CRE UAL9 B772 34.0 -113.5 260 FL380 260" })
  asked(two("the triple 7 climb fl390"), "two 777s flying")
end

-- Cycle 53 (f150): "the a300" is the A300 family (A306, the A300-600); none flying, asked
do
  local _, ex = scene({ "CRE FDX603 A306 34.8 -115.9 250 FL310 290", "CRE UAL20 A320 34.2 -117.3 060 FL240 270" })
  check_eq(ex("get rid of the a300"), "DEL FDX603")
  check_eq(ex("the A300 turn right heading 300"), "HDG FDX603 300 RIGHT")
  local _, none = scene({ "CRE UAL20 A320 34.2 -117.3 060 FL240 270", "CRE DAL7 A321 34.0 -117.0 090 FL250 270" })
  asked(none("delete the a300"), "no A300 flying")
end

-- Cycle 53 (f150): digits under 40 typed straight after "speed up" / "slow down" are knots of change; after another
-- verb ("reduce 25"), after "to" or said in words they are still asked
do
  local _, ex = scene({ "CRE FFT20 A20N 39.1 -104.9 010 FL110 250" })
  check_eq(ex("FFT20 speed up 10 pls"), "SPD FFT20 260")
  check_eq(ex("slow FFT20 down 30"), "SPD FFT20 220")
  asked(ex("FFT20 reduce 25"), "250 typed short?")
  asked(ex("FFT20 slow down to 20"), "a speed of 20 kt")
  asked(ex("FFT20 speed up fifteen"), "said in words")
end

-- Cycle 53 (f150): "the X that just took off", "the X departing" ending its clause describe the aircraft (no origin);
-- with two of the airline flying the description chooses none: asked
do
  local _, ex = scene({ "CRE SWA17 B737 39.86 -104.67 180 6500 190", "CRE UAL41 A320 40.3 -104.4 200 FL150 260" })
  check_eq(ex("the southwest that just took off, climb it to FL230"), "ALT SWA17 FL230")
  check_eq(ex("the Southwest departing, turn left heading 150"), "HDG SWA17 150 LEFT")
  local _, two = scene({ "CRE SWA17 B737 39.86 -104.67 180 6500 190", "CRE SWA41 A320 40.3 -104.4 200 FL150 260" })
  asked(two("the southwest that just took off, climb it to FL230"), "two Southwests flying")
  check_eq(ex("SWA17 departing KDEN"), "ORIG SWA17 KDEN")
end

-- Cycle 53 (f150): a route's navaid named in lower case after "skip" or "passes" is that navaid; one "skip" names
-- that the direct-to does not skip (after its place, or the place itself) is asked, in capitals too
do
  local _, ex = navscene({ "CRE UAL15 B739 34.0 -117.2 265 FL140 280", "ADDWPT UAL15 PDZ", "ADDWPT UAL15 SLI" },
    "a navaid skipped by name")
  if ex then
    check_eq(ex("UAL15 direct SLI, skipping paradise"), "DIRECT UAL15 SLI")
    check_eq(ex("when UAL15 passes paradise have it go down to 10000"), "AT UAL15 PDZ DO ALT UAL15 10000")
    asked(ex("UAL15 direct PDZ, skip seal beach"), "SLI comes after PDZ")
    asked(ex("UAL15 direct PDZ, skip SLI"), "SLI comes after PDZ, in capitals")
    asked(ex("UAL15 direct SLI, skip SLI"), "the direct-to's own waypoint")
  end
end

-- Cycle 53 (f150): a level typed as digits with no unit after "after" closing a speed or heading ("speed 250 after
-- 10000") is passed; a number that may be a time of day ("after 1200") is asked
do
  local _, ex = scene({ "CRE SWA13 B737 37.7 -122.2 300 2500 180" })
  check_eq(ex("SWA13 speed 250 after 10000"), "ATALT SWA13 10000 SPD SWA13 250")
  check_eq(ex("SWA13 heading 090 after passing 5000"), "ATALT SWA13 5000 HDG SWA13 90")
  asked(ex("SWA13 speed 250 after 1200"), "a time of day?")
end

-- Cycle 53 (f150): "what's the resolution method" with no question mark shows it; a method or switch said sets it
do
  local _, ex = scene({ "CRE SWA13 B737 37.7 -122.2 300 2500 180" })
  check_eq(ex("what's the resolution method rn"), "RESO")
  check_eq(ex("what's the resolution method, switch it to mvp"), "RESO MVP")
  asked(ex("change the resolution method"), "which method")
end
-- Cycle 53 (f151): a Spanish-speaking technician's English. "velocity" for speed ("velocidad") with no Velocity
-- aircraft flying; "arrive" and "be over" for reaching; "the 737 of Aeromexico"; Spanish words read as their
-- English (lexicon.said_whole.spanish: "vuelo", "perdón", "un momento", "rápido"); "rapid" as a manner; "3000 feet
-- more" after a descent; "in FIX" for "at FIX"; "X is doing what?"
do
  local _, ex = scene({ "DEFWPT TOLPA 19.5 -99.5", "DEFWPT MARGO 19.8 -99.8", "DEFWPT ZUMPA 19.1 -98.9",
    "CRE AMX402 B788 19.80 -99.00 010 FL280 300", "CRE AMX118 B738 19.20 -98.60 100 FL200 280",
    "CRE VOI2019 A321 19.60 -99.70 300 FL230 290", "ADDWPT VOI2019 TOLPA", "ADDWPT VOI2019 MARGO",
    "CRE VIV310 A320 19.0 -99.2 090 FL150 260", "CRE SWG88 B38M 19.4 -99.4 180 FL200 280" })
  -- "velocity" before a number or after an article, with no VOZ aircraft flying
  check_eq(ex("Volaris 2019 put velocity 250 and descend FL200"), "SPD VOI2019 250 ; ALT VOI2019 FL200")
  check_eq(ex("the Volaris, put it in velocity 260 please"), "SPD VOI2019 260")
  check_eq(ex("Aeromexico 118 increase the velocity 20 knots"), "SPD AMX118 300")
  check_eq(ex("Aeromexico 118 set velocity two five zero"), "SPD AMX118 250")
  asked(ex("Velocity 250, climb FL300"), "the request's first word stays a callsign")
  -- reaching said with "arrive" or "be over"; "put" before a speed after the condition
  check_eq(ex("Aeromexico 118 climb FL240 and when you arrive reduce to 250"),
    "ALT AMX118 FL240 ; ATALT AMX118 FL240 SPD AMX118 250")
  check_eq(ex("Aeromexico 118 climb FL240, when it arrives there put the speed 250"),
    "ALT AMX118 FL240 ; ATALT AMX118 FL240 SPD AMX118 250")
  check_eq(ex("Volaris 2019 when you are over MARGO descend FL150"), "AT VOI2019 MARGO DO ALT VOI2019 FL150")
  asked(ex("Volaris 2019 when you are over ZUMPA descend FL150"), "a waypoint off the route")
  -- "in" a waypoint of the route, as "at"
  check_eq(ex("Volaris 2019 in TOLPA reduce to 240 knots"), "AT VOI2019 TOLPA DO SPD VOI2019 240")
  asked(ex("Volaris 2019 in ZUMPA reduce to 240 knots"), "'in' a waypoint off the route")
  -- the airline and the type joined by "of"
  check_eq(ex("the Aeromexico of the 787 climb FL330"), "ALT AMX402 FL330")
  check_eq(ex("the 737 of Aeromexico, reduce the velocity to 250"), "SPD AMX118 250")
  check_eq(ex("the 737 MAX of Sunwing climb FL240"), "ALT SWG88 FL240")
  check_eq(ex("the 737 MAX descend FL180"), "ALT SWG88 FL180")
  asked(ex("the 737 of the Volaris climb FL300"), "no Volaris 737 flying")
  asked(ex("the Airbus of Aeromexico climb FL300"), "no Aeromexico Airbus flying")
  -- Spanish words
  check_eq(ex("vuelo VIV310 realize a climb to FL190 please"), "ALT VIV310 FL190")
  check_eq(ex("Volaris 2019 descend to FL200, perdón, FL210"), "ALT VOI2019 FL210")
  check_eq(ex("Volaris 2019 reduce speed 240, disculpe, 250"), "SPD VOI2019 250")
  asked(ex("Volaris 2019 descend FL200, perdon"), "taken back with nothing after it")
  check_eq(ex("pause, un momento por favor"), "HOLD")
  asked(ex("Volaris 2019 descend FL200, un momento"), "a moment after an instruction")
  check_eq(ex("Aeroenlace 310 climb FL210 rapid, 2500 feet per minute"), "ALT VIV310 FL210 2500")
  check(ex("Aeroenlace 310 descend FL100 rápido"):find("ALT VIV310 FL100", 1, true) ~= nil, "rápido as a manner")
  check_eq(ex("advance 5 minutes rapid please"), "FF 300")
  -- "more" after a descent is further down
  check_eq(ex("Aeroenlace 310 descend 3000 feet more"), "ALT VIV310 12000")
  check_eq(ex("Aeroenlace 310 climb 2000 feet more"), "ALT VIV310 17000")
  asked(ex("Aeroenlace 310 descend 2000 feet more or less"), "an estimate")
  -- the telephony "Aeroenlaces" said in the singular; the question in a statement's order
  check_eq(ex("where is the Aeroenlace actually"), "POS VIV310")
  check_eq(ex("the Aeroenlace is doing what?"), "POS VIV310")
  check_eq(ex("Volaris 2019 is doing what now"), "POS VOI2019")
end

-- Cycle 53 (f151): "in the ground" for "on the ground" in a creation; Central and South American cities and
-- "El Dorado" by the navdata's airport names; a capitalised "El", "La" before a capitalised word opens a name
-- in a sentence a Spanish word marks Spanish ("at El Dorado", never "at the Dorado")
do
  local _, ex = scene({ "CRE KLM12 A320 52.0 4.0 090 FL200 250" })
  check_eq(ex("create KLM13 A320 at 52.1 4.1 heading 090, in the ground"), "CRE KLM13 A320 52.1 4.1 90 0 0")
  check_eq(ex("create KLM13 A320 at 52.1 4.1 heading 090 in ground"), "CRE KLM13 A320 52.1 4.1 90 0 0")
  asked(ex("create KLM13 A320 at 52.1 4.1 heading 090 in the ground, FL100"), "on the ground and a level")
end
do
  local _, ex = navscene({ "CRE AVA154 A319 4.30 -74.50 040 FL140 250", "CRE VOI6120 A20N 14.00 -91.20 080 FL340 275" },
    "Latin American airports by city")
  if ex then
    check_eq(ex("VOI6120 destination Guatemala"), "DEST VOI6120 MGGT")
    check_eq(ex("VOI6120 destination Guatemala la Aurora MGGT"), "DEST VOI6120 MGGT")
    check_eq(ex("AVA154 destination El Dorado"), "DEST AVA154 SKBO")
    check_eq(ex("create the vuelo AVA4456, A320, at El Dorado SKBO heading 130, in ground"),
      "CRE AVA4456 A320 SKBO 130 0 0")
    asked(ex("AVA154 destination Bogota El Dorado"), "a city and an airport name of two words: not read yet")
  end
end

-- Cycle 53 (fpe): the polite plain-word experimenter. Courtesy around "same for" keeps the aircraft it adds; an
-- airline after "same for the" that does not close its clause is asked, never dropped
do
  local _, ex = scene({ "CRE KLM55X B738 52.3 4.7 090 FL200 280", "CRE IGO123 A20N 52.5 4.9 180 FL220 270",
    "CRE AFR12 A320 52.1 4.5 270 FL240 290" })
  check_eq(ex("KLM55X climb FL250, same for the IndiGo kindly"), "ALT KLM55X FL250 ; ALT IGO123 FL250")
  check_eq(ex("KLM55X climb FL250, kindly the same for AFR12"), "ALT KLM55X FL250 ; ALT AFR12 FL250")
  asked(ex("KLM55X climb FL250, same for the Air France sir"), "an unknown word closing 'same for the' airline")
  asked(ex("KLM55X climb FL250, same for the IndiGo thank you"), "thanks after 'same for the' airline")
end

-- Cycle 53 (fpe): a turn's side said with the present heading is asked; the present heading alone is flown
do
  local _, ex = scene({ "CRE KLM56 B738 52.3 4.7 120 FL200 280" })
  asked(ex("KLM56 turn left present heading"), "a side with the present heading")
  asked(ex("KLM56 turn right, present heading please"), "a side with the present heading, comma")
  check_eq(ex("KLM56 continue present heading"), "HDG KLM56 120")
end

-- Cycle 53 (fpe): "pull up the route", "run it forward by N minutes", a remark naming the session's script
do
  local _, ex = scene({ "CRE UAL15 B738 41.95 -88.70 090 FL120 280", "CRE DAL98 A320 42.10 -88.45 135 FL230 300" })
  check_eq(ex("could you bring up the flight plan for the Delta"), "LISTRTE DAL98")
  check_eq(ex("pull up UAL15's route so we can compare it with the protocol"), "LISTRTE UAL15")
  asked(ex("pull up the route"), "no aircraft named")
  check_eq(ex("could you run it forward by 3 minutes"), "FF 180")
  check_eq(ex("run it ahead 45 seconds please"), "FF 45")
  check_eq(ex("run it"), "OP")
end

-- Cycle 53 (fpe): "point"/"aim" an aircraft toward a place: a waypoint is flown to, an airport or a city is the
-- heading to it (an airport said by a distinctive part of its name with navdata)
do
  local _, ex = scene({ "DEFWPT LABQ1 42.0 -87.5", "CRE SKW52 CRJ9 42.40 -87.85 180 8000 240" })
  check_eq(ex("point SKW52 toward LABQ1"), "ADDWPT SKW52 LABQ1 ; DIRECT SKW52 LABQ1")
  asked(ex("aim SKW52 toward the traffic"), "no place after toward")
  local _, nx = navscene({ "CRE SKW52 CRJ9 42.40 -87.85 180 8000 240" }, "airports pointed at by name")
  if nx then
    check_eq(nx("could you point the CRJ toward O'Hare"), "HDG SKW52 KORD")
    check_eq(nx("aim SKW52 towards Midway please"), "HDG SKW52 KMDW")
    asked(nx("point the CRJ toward Flurbo"), "a name no airport bears")
  end
end

-- Cycle 53 (fpe): US regional airlines by their common name ("the Republic flight", "the PSA jet")
do
  local _, ex = scene({ "CRE RPA47 E175 38.70 -77.90 030 FL140 270", "CRE JIA50 CRJ7 39.20 -76.85 230 9000 250",
    "CRE RPA48 E170 38.90 -77.20 090 FL120 260" })
  check_eq(ex("could the PSA jet slow to 220"), "SPD JIA50 220")
  check_eq(ex("Republic 47 descend FL120"), "ALT RPA47 FL120")
  asked(ex("could you have the Republic flight slow to 250"), "two Republic aircraft flying")
end
-- Cycle 53 (hz2): a place named in several words is read on all of them (an airport near the traffic whose name
-- holds them) before an airport anywhere named by one of them; an airport found by name farther than
-- lexicon.region_nm from every aircraft is asked about
do
  local _, ex = navscene({ "CRE FFT2021 A20N 39.10 -104.90 010 FL110 250" }, "US places of several words")
  if ex then
    check_eq(ex("FFT2021 destination colorado springs"), "DEST FFT2021 KCOS")
    check_eq(ex("send FFT2021 direct to colorado springs"), "ADDWPT FFT2021 KCOS ; DIRECT FFT2021 KCOS")
    asked(ex("FFT2021 direct springs"), "FASI in South Africa on one common word")
    asked(ex("FFT2021 direct kuala lumpur"), "another continent")
    asked(ex("FFT2021 destination palm springs"), "far from the aircraft: confirmed")
    asked(ex("FFT2021 destination grand rapids"), "no airport of that name near")
    asked(ex("FFT2021 destination santa barbara"), "no airport of that name near")
    -- (a word said where nothing is known to match it, the next words going on with a place's name: never the
    -- fix of the first word's name)
    asked(ex("FFT2021 direct santa barbara"), "part of a name: not the fix SANTA")
    asked(ex("FFT2021 direct grand rapids"), "part of a name: not the fix GRAND")
    asked(ex("FFT2021 direct las vegas ndb"), "no NDB of that name")
  end
  local _, exv = navscene({ "CRE UAL12 A320 36.5 -115.5 010 FL110 250", "ADDWPT UAL12 BTY" }, "a navaid of two words")
  if exv then
    check_eq(exv("UAL12 direct las vegas"), "ADDWPT UAL12 LAS ; DIRECT UAL12 LAS")
    asked(exv("UAL12 direct las vegas ndb"), "no NDB of that name")
  end
  local _, ex2 = navscene({ "CRE AFR12 A320 48.60 2.30 010 FL110 250" }, "European places of several words")
  if ex2 then
    check_eq(ex2("AFR12 destination le bourget"), "DEST AFR12 LFPB")
    asked(ex2("AFR12 direct springs"), "another continent")
  end
  local _, ex3 = navscene({ "CRE MAS12 A320 3.30 101.30 010 FL110 250" }, "Asian places of several words")
  if ex3 then
    check_eq(ex3("MAS12 destination kuala lumpur"), "DEST MAS12 WMKK")
    asked(ex3("MAS12 direct lumpur springs"), "a part of no name near")
  end
end

-- Cycle 53 (hz3): a remark's words beside a real instruction are no command: a setting's state told with a
-- frame or a told adverb, the copula dropped before a judgement ("just noise"), "no more" a switch's noun, a route
-- told after the deletion's comma, a seed told with a copula, a put-off word in the clause of a command read
do
  local _, ex = scene({ "CRE KLM12 B738 52.3 4.76 090 FL100 250", "CRE C172X C172 52.2 4.9 180 3000 100",
    "CRE DLH4 A320 52.4 4.6 270 FL200 280" })
  check_eq(ex("delete the cessna, just noise"), "DEL C172X")
  check_eq(ex("remove the cessna, only noise"), "DEL C172X")
  check_eq(ex("DLH4 descend FL130, just noise in the background"), "ALT DLH4 FL130")
  check_eq(ex("KLM12 turn right heading 180, the detection is on anyway"), "HDG KLM12 180 RIGHT")
  check_eq(ex("KLM12 heading 200; the resolution is off anyway"), "HDG KLM12 200")
  check_eq(ex("DLH4 descend FL160, in my experiment the noise is off"), "ALT DLH4 FL160")
  check_eq(ex("KLM12 descend FL080, the zone is not active yet"), "ALT KLM12 FL80")
  check_eq(ex("KLM12 climb FL200, no more noise please"), "ALT KLM12 FL200 ; NOISE OFF")
  -- near variants still read or asked: a state said with no frame or told adverb may be wished, a switch said
  check_eq(ex("KLM12 climb FL150, the trails are on"), "ALT KLM12 FL150 ; TRAIL ON")
  check_eq(ex("KLM12 climb FL150, noise on"), "ALT KLM12 FL150 ; NOISE ON")
  check_eq(ex("KLM12 heading 200, make sure the detection is on"), "HDG KLM12 200 ; ASAS ON")
  asked(ex("KLM12 climb FL150, just trails"), "trails after 'just' is no judgement: shown or hidden asked")
  -- the route told after the deletion's comma deletes no route
  asked(ex("delete KLM12, the route is finished"), "the aircraft or a waypoint: no DELRTE")
  check_eq(ex("delete the route of KLM12"), "DELRTE KLM12")
  -- a seed told with a copula beside an instruction is asked; typed as a setting it is set
  asked(ex("KLM12 to FL110, seed is 42 by the way"), "the seed told or set?")
  check_eq(ex("KLM12 to FL110, seed 42"), "ALT KLM12 FL110 ; SEED 42")
  -- a put-off word closing the clause of a command read puts that command off: asked
  asked(ex("KLM12 climb FL190, we should pause soon"), "when to pause")
  asked(ex("KLM12 climb FL190, delete it shortly"), "when to delete")
  check_eq(ex("KLM12 climb FL190, pause"), "ALT KLM12 FL190 ; HOLD")
end
do
  local _, ex = scene({ "CRE KLM12 B738 52.3 4.76 090 FL100 250" })
  check_eq(ex("seed is 42"), "SEED 42")
  check_eq(ex("KLM12 direct SPY, the detection is still on"), "ADDWPT KLM12 SPY ; DIRECT KLM12 SPY")
  check_eq(ex("KLM12 climb FL180, no more trails please"), "ALT KLM12 FL180 ; TRAIL OFF")
end

-- Cycle 53 (hz1): a number said after an airline's name that is no flight number of the aircraft: a type's number
-- or designator names the airline's aircraft of that type (or both readings are asked, never a did-you-mean whose
-- only link is the type's number); a value with its unit after "the", an airline and a verb is the value
do
  local _, ex = scene({ "CRE OAL3KP E190 38.0 23.0 090 FL180 260", "CRE OAL61T A321 38.4 23.4 270 FL250 280",
    "CRE SWR12 A320 38.8 23.8 180 FL300 280" })
  check_eq(ex("the Olympic 321, descend FL200"), "ALT OAL61T FL200")
  check_eq(ex("can the Olympic three twenty one reduce to 250 knots"), "SPD OAL61T 250")
  check_eq(ex("the Olympic A321, turn left heading 200"), "HDG OAL61T 200 LEFT")
  -- no Olympic of the type flies: asked, naming what was said, and no aircraft offered
  local r = ex("the Olympic 737, descend FL200")
  asked(r, "no aircraft of the airline of that type")
  check(not r:find("Did you mean", 1, true) and not r:find("OAL3KP", 1, true), "no did-you-mean from a type's number")
  -- without "the" the number may be a callsign: both readings asked
  r = ex("Olympic 321, descend FL200")
  asked(r, "a type's number without 'the'")
  check(r:find("OAL61T", 1, true) ~= nil and not r:find("Did you mean", 1, true), "the type's reading named")
end
do
  -- a flying callsign that is the airline and the type's number, with another of the airline of that type: both asked
  local _, ex = scene({ "CRE SAS737 A320 59.0 17.0 090 FL200 260", "CRE SAS9RE B738 59.4 17.4 270 FL340 280" })
  local r = ex("the Scandinavian 737, climb FL360")
  asked(r, "a callsign flying and a type of the airline")
  check(r:find("SAS737", 1, true) ~= nil and r:find("SAS9RE", 1, true) ~= nil, "both readings named")
  check_eq(ex("Scandinavian 737, climb FL360"), "ALT SAS737 FL360")
end
do
  local _, ex = scene({ "CRE TAP6WB B752 40.0 -8.0 090 FL200 260", "CRE KLM62 A320 40.4 -8.4 270 FL250 280",
    "CRE IBE8TX A320 40.8 -8.8 180 FL300 280" })
  check_eq(ex("delete the Air Portugal B757"), "DEL TAP6WB")
  check_eq(ex("the Air Portugal seven fifty-seven, climb FL240"), "ALT TAP6WB FL240")
  -- a value with its unit after the airline and a verb: never KLM62's flight number
  check_eq(ex("let the Iberia turn 62 degrees to the left"), "HDG IBE8TX 118 LEFT")
  check_eq(ex("the Iberia now turn 62 degrees right"), "HDG IBE8TX 242 RIGHT")
  asked(ex("let the Iberia turn 62"), "a number with no unit after the airline and a verb")
end

-- Cycle 53 (hz4): corrections that take an instruction back by naming it ("sorry, leave its heading", "no, wait -
-- leave that one"); a route's levels said "included" with following it; a polite question's "?" after a note
do
  local _, ex = scene({ "CRE FIN8LK A320 60.0 24.0 090 FL240 280", "CRE TAP6WB B752 60.4 24.4 270 FL250 280",
    "CRE IBE8TX A321 60.8 24.8 180 FL300 280" })
  check_eq(ex("Might the Finnair take heading 200 - ah, sorry, leave the heading, just descend it to FL200."),
    "ALT FIN8LK FL200")
  check_eq(ex("Would the Iberia turn left onto 150 - no, sorry, leave its heading, reduce it to 250 knots."),
    "SPD IBE8TX 250")
  -- the kind named is not the instruction said before: asked
  asked(ex("Might the Finnair take heading 200 - sorry, leave its speed, just descend it to FL200."),
    "a kind left as it was that was never given")
  -- nothing said in its place: asked
  asked(ex("Might the Finnair take heading 200 - oh, sorry, leave the heading."), "nothing said in its place")
  check_eq(ex("Would you remove the Iberia? Sorry - leave that one, remove the Air Portugal."), "DEL TAP6WB")
  asked(ex("Would you remove the Iberia? No, wait - leave that one."), "a deletion taken back, nothing in its place")
end
do
  local _, ex = scene({ "CRE FIN8LK A320 60.0 24.0 090 FL240 280", "ADDWPT FIN8LK 60.5 25.0", "ADDWPT FIN8LK 61.0 26.0" })
  check_eq(ex("Could the Finnair follow its route, heights and speeds included?"), "LNAV FIN8LK ON ; VNAV FIN8LK ON")
  check_eq(ex("FIN8LK follow the route, the heights included"), "LNAV FIN8LK ON ; VNAV FIN8LK ON")
  -- a value in the clause, or "including" in the route's own clause: no profile read
  asked(ex("FIN8LK follow the route including the altitudes"), "levels named inside the route's clause")
  check(not ex("FIN8LK follow the route, FL200 included"):find("VNAV", 1, true), "a value is no profile")
end
do
  local _, ex = scene({ "CRE FIN8LK A320 60.0 24.0 090 FL240 280" })
  check_eq(ex("Would you put a short note on screen saying Block two is over?"), "ECHO Block two is over")
  -- a note that is a question itself: whether its "?" is printed is asked
  asked(ex("Could you put a note on screen saying is everyone ready?"), "a note that reads as a question")
  check_eq(ex("Put a note on screen saying is everyone ready?"), "ECHO is everyone ready ?")
end

-- Cycle 53 (f152): a British speaker's understatement around an instruction whose value is said: "would you mind
-- awfully/terribly", "a touch", "when it's ready", "no rush", "in its own time", "sorry to be a pain", "would it be
-- terribly inconvenient", "it's just clutter", "skipping ahead", "and I'll say when to stop"
do
  local _, ex = scene({ "CRE KLM12 B738 52.0 4.0 090 FL220 280", "CRE BAW9 A320 52.4 4.4 270 FL300 280" })
  check_eq(ex("Would you mind terribly having the KLM climb to FL240?"), "ALT KLM12 FL240")
  asked(ex("would you mind awfully having the KLM climb?"), "an understated climb with no level")
  check_eq(ex("the KLM could come down a touch, say FL200"), "ALT KLM12 FL200")
  check_eq(ex("the Speedbird ought to turn left a touch, heading 250 say"), "HDG BAW9 250 LEFT")
  asked(ex("the KLM could come down a touch"), "a touch is no value")
  check_eq(ex("the KLM could slow to 250 knots when it's ready, no hurry"), "SPD KLM12 250")
  check_eq(ex("the KLM ought to climb to FL260 in its own time"), "ALT KLM12 FL260")
  asked(ex("the KLM could descend when it's ready, no rush"), "a descent left to the aircraft with no level")
  check_eq(ex("delete the Speedbird please, it's just clutter"), "DEL BAW9")
  check_eq(ex("would it be terribly inconvenient to delete KLM12?"), "DEL KLM12")
  asked(ex("would it be terribly inconvenient?"), "a hedge with no instruction")
  check_eq(ex("sorry to be a pain, but could KLM12 climb to FL260"), "ALT KLM12 FL260")
  check_eq(ex("would you mind skipping ahead 2 minutes?"), "FF 120")
  asked(ex("would you mind skipping ahead to the conflict?"), "fast time until an event")
  check_eq(ex("fast-forward, please, and I'll say when to stop"), "FF")
  asked(ex("fast-forward, and I'll say when to climb"), "a 'when' that is no stop of the fast-forward")
end
do
  -- "taking X out of the picture": the aircraft taken out of the run, as "take X out of the exercise"
  local _, ex = scene({ "CRE KLM12 B738 52.0 4.0 090 FL220 280", "CRE WIF512 DH8D 52.4 4.4 270 FL300 280" })
  check_eq(ex("Would you mind awfully taking the Wideroe out of the picture?"), "DEL WIF512")
  check_eq(ex("could you take the KLM out of the picture"), "DEL KLM12")
  check_eq(ex("would you mind taking KLM12 out of the exercise"), "DEL KLM12")
  asked(ex("would you mind taking the Wideroe out of the hold"), "out of the hold is no deletion")
  asked(ex("the Wideroe is out of the picture"), "a remark that it is out names no instruction")
end

-- Cycle 54 (f156): a US engineer's meeting English: a label before a question ("quick ask:", "quick sanity
-- check,"), "spin up" a new aircraft, turning to an aircraft ("can we circle back to the Delta?"), "extend" a
-- setting, and "let's" after a self-correction
do
  local _, ex = scene({ "CRE DAL88 A321 38.7 -78.1 060 FL240 300", "CRE UAL12 B739 38.9 -78.3 090 FL200 290",
    "CRE UAL14 B738 39.4 -76.3 230 11000 250" })
  check_eq(ex("Quick ask: what's the look-ahead set to right now?"), "DTLOOK")
  check_eq(ex("quick sanity check - which resolution method is on?"), "RESO")
  check_eq(ex("Quick question, is the Delta descending?"), "POS DAL88")
  asked(ex("Quick ask: the Delta"), "a question label before no question")
  check_eq(ex("let's spin up a B738 called SWA41 at 39.1 -77.2 heading 180 FL150 250 knots"),
    "CRE SWA41 B738 39.1 -77.2 180 FL150 250")
  asked(ex("spin up the Delta"), "'spin up' before an aircraft flying creates nothing")
  check_eq(ex("Could we circle back to the Delta? I want it at FL260."), "ALT DAL88 FL260")
  check_eq(ex("ok, moving on to the Delta: turn left heading 020"), "HDG DAL88 20 LEFT")
  asked(ex("Can we go back to the United? Heading 100."), "two United flying")
  asked(ex("Can we circle back to the Delta?"), "turning to an aircraft with nothing said about it")
  check_eq(ex("extend the look-ahead to six minutes"), "DTLOOK 360")
  asked(ex("extend the look-ahead"), "a longer look-ahead with no value")
  check_eq(ex("Delta 88 climb to FL280... no wait, let's climb to FL300"), "ALT DAL88 FL300")
  check_eq(ex("Delta 88, descend to FL200, sorry, let us descend to FL220"), "ALT DAL88 FL220")
  asked(ex("Delta 88 climb to FL280... no wait, let's turn"), "a turn said in place of the climb with no heading")
end
do
  -- the large US airports by their IATA code where an airport is meant (a code not listed is asked)
  local _, ex = navscene({ "CRE JBU12 A320 39.1 -76.9 200 10000 250" }, "US airports by IATA code")
  if ex then
    check_eq(ex("set the JetBlue's destination to BWI"), "DEST JBU12 KBWI")
    check_eq(ex("divert the JetBlue to MSY"), "DEST JBU12 KMSY")
    asked(ex("divert the JetBlue to QQX"), "three capitals no airport's code squawk knows")
  end
end
do
  -- a route shown "(up) on screen", and the "active" waypoint asked as the next one
  local _, ex = scene({ "CRE AAL14 A321 37.3 -76.6 200 FL280 290", "CRE UAL78 B753 37.7 -77.8 030 FL300 290" })
  check_eq(ex("can we get the flight plan of the American up on screen?"), "LISTRTE AAL14")
  check_eq(ex("put the United's route on the screen please"), "LISTRTE UAL78")
  asked(ex("put the United on the screen"), "an aircraft put on screen names no route")
  check_eq(ex("what is the United's active waypoint?"), "LISTRTE UAL78")
  asked(ex("the United's active waypoint"), "the noun alone, no question")
end
do
  -- a self-correction closed by the speaker stopping to think or dropping it ("no wait, let's see", "sorry, let me
  -- think", "no, forget it"): what came before is taken back, nothing issued; a replacement after it is read
  local _, ex = scene({ "CRE DAL77 A321 52 4 090 FL200 280", "CRE KLM12 B738 52.1 4.1 180 FL150 260" })
  asked(ex("climb the Delta to FL280... no wait, let's see"), "'no wait, let's see' takes the climb back")
  asked(ex("KLM12 speed 250... sorry, let me think"), "'sorry, let me think' takes the speed back")
  asked(ex("descend KLM12 to FL100, hmm, actually hold on"), "'hmm, actually hold on' takes the descent back")
  asked(ex("DAL77 climb FL300, actually, let me check something"), "'actually, let me check' takes it back")
  asked(ex("KLM12 speed 250, no, forget it"), "'no, forget it' takes the speed back")
  asked(ex("KLM12 speed 250, no, stand by"), "'no, stand by' takes the speed back")
  asked(ex("KLM12 turn right heading 090... sorry, hold that thought"), "'sorry, hold that thought' takes it back")
  asked(ex("KLM12 heading 200, sorry, I'm not sure"), "'sorry, I'm not sure' takes the heading back")
  asked(ex("KLM12 speed 220, no, cancel that"), "'no, cancel that' takes the speed back")
  asked(ex("DAL77 climb FL300 and KLM12 heading 200, sorry, let me think"), "both taken back")
  asked(ex("DAL77 climb FL300, no, scratch that"), "'no, scratch that' takes the climb back")
  check_eq(ex("KLM12 speed 250, hmm, hold on, make that 240"), "SPD KLM12 240")
  check_eq(ex("DAL77 climb FL300, no, scratch that, FL280"), "ALT DAL77 FL280")
  check_eq(ex("pause the sim, hang on"), "HOLD")
end
do
  -- a condition on the level reached said with an informal verb of changing the speed ("once it's level, bump it
  -- to 280 knots"): ATALT on the level cleared; with no unit after the verb ("bump to 280") asked
  local _, ex = scene({ "CRE DAL77 A321 52 4 090 FL200 280", "CRE KLM12 B738 52.1 4.1 180 FL150 260" })
  check_eq(ex("DAL77 climb FL300, once it's level, bump it to 280 knots"),
    "ALT DAL77 FL300 ; ATALT DAL77 FL300 SPD DAL77 280")
  check_eq(ex("DAL77 climb FL300; when it's level, bump to Mach point eight zero"),
    "ALT DAL77 FL300 ; ATALT DAL77 FL300 SPD DAL77 M0.8")
  check_eq(ex("KLM12 descend FL100, once it's down there, crank it down to 220 knots"),
    "ALT KLM12 FL100 ; ATALT KLM12 FL100 SPD KLM12 220")
  check_eq(ex("DAL77 climb FL300, once level, push it up to 300 knots"),
    "ALT DAL77 FL300 ; ATALT DAL77 FL300 SPD DAL77 300")
  asked(ex("DAL77 climb FL300, when it's level, bump to 280"), "'bump to 280' names no kind of value")
end
