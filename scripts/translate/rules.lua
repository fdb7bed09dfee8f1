-- The rules of the offline grammar: which words ask for which registry
-- command. Loaded by translate/grammar.lua, which checks every line against
-- the command registry (squawk.sim.commands()): an intent naming an unknown
-- command or argument is a load error naming this file and line.
--
-- intent NAME { cmd = "CMD" | cmds = {...}, args = {registry argument names},
--               also = {commands it may add}, handler = "fn in translate/handlers.lua", flags... }
--   flags: value (an instruction carrying one value: ALT, SPD, HDG, VS),
--          absorbs (takes the value words after it: "create ... heading 090
--          at FL200"), single (never merges with a neighbour of its kind)
--
-- rule { "word word ...", INTENT | false, conditions... }  (first match wins,
-- in file order; false: the word starts no instruction here)
--   Words: space separated; "@name" stands for the list lexicon.name; "*"
--   matches any word. Conditions on the token at i:
--     next = "w ..."          the next word is one of these
--     near = {n, "w ..."}     one of these within the n words after
--     not_near = {n, "w ..."}
--     prev = {n, "w ..."}     one of these within the n words before
--     not_prev = {n, "w ..."}
--     when = function(g, i)   any other test (g: the grammar state)
--
-- words "CMD" "text"   more words people use for a registry command, for
-- the retrieval documents of the LLM modes (checked against the registry).
return function(intent, rule, words)
  local CITY_AIRPORTS = require("translate.lexicon").city_airports
  local PHONETIC = require("translate.lexicon").phonetic
  local NAVAID_RANGE_NM = require("translate.lexicon").navaid_range_nm
  intent "alt" { cmd = "ALT", args = { "acid", "alt", "vspd" }, handler = "altitude", value = true, family = "alt" }
  intent "maintain" { cmds = { "ALT", "SPD", "HDG" }, handler = "maintain", value = true, family = "alt" }
  intent "spd" { cmd = "SPD", args = { "acid", "spd" }, handler = "speed", value = true }
  intent "hdg" { cmd = "HDG", args = { "acid", "hdg" }, handler = "heading", value = true }
  intent "vs" { cmd = "VS", args = { "acid", "vspd" }, handler = "vspeed", value = true }
  intent "create" { cmd = "CRE", args = { "acid", "type", "lat", "lon", "hdg", "alt", "spd" }, handler = "create",
                    absorbs = true, single = true }
  intent "delete" { cmd = "DEL", args = { "acid" }, handler = "remove", single = true }
  intent "addwpt" { cmd = "ADDWPT", args = { "acid", "wpname", "lat", "lon", "alt", "spd" }, handler = "add_waypoint",
                    absorbs = true }
  intent "defwpt" { cmd = "DEFWPT", args = { "name", "lat", "lon" }, handler = "define_waypoint", absorbs = true }
  intent "delwpt" { cmd = "DELWPT", args = { "acid", "wpname" }, handler = "delete_waypoint" }
  intent "undefwpt" { cmd = "DEFWPT", args = { "name", "lat", "lon" }, handler = "forget_waypoint" }
  intent "direct" { cmd = "DIRECT", also = { "ADDWPT", "ALT" }, args = { "acid", "wpname" }, handler = "direct" }
  intent "dest" { cmd = "DEST", args = { "acid", "airport" }, handler = "dest" }
  intent "orig" { cmd = "ORIG", args = { "acid", "airport" }, handler = "orig" }
  intent "lnav" { cmd = "LNAV", args = { "acid", "ON", "OFF" }, handler = "lnav" }
  intent "vnav" { cmd = "VNAV", args = { "acid", "ON", "OFF" }, handler = "vnav" }
  intent "listrte" { cmd = "LISTRTE", args = { "acid" }, handler = "listrte" }
  intent "delrte" { cmd = "DELRTE", args = { "acid" }, handler = "delrte" }
  intent "pos" { cmd = "POS", args = { "acid" }, handler = "pos" }
  intent "move" { cmd = "MOVE", args = { "acid", "lat", "lon", "alt", "hdg", "spd", "vspd" }, handler = "move",
                  absorbs = true }
  intent "bank" { cmd = "BANK", args = { "acid", "bankangle" }, handler = "bank" }
  intent "hold" { cmd = "HOLD", handler = "bare" }
  intent "op" { cmd = "OP", handler = "resume" }
  intent "reset" { cmd = "RESET", handler = "bare" }
  intent "ff" { cmd = "FF", also = { "DTMULT" }, args = { "seconds" }, handler = "fast_forward" }
  intent "dt" { cmd = "DT", args = { "dt" }, handler = "time_step" }
  intent "dtmult" { cmd = "DTMULT", args = { "multiplier" }, handler = "time_mult" }
  intent "seed" { cmd = "SEED", args = { "value" }, handler = "seed" }
  intent "ic" { cmd = "IC", args = { "filename" }, handler = "scenario" }
  intent "echo" { cmd = "ECHO", args = { "text" }, handler = "echo" }
  intent "wind" { cmd = "WIND", args = { "lat", "lon", "alt", "dir", "spd" }, handler = "wind", absorbs = true,
                  single = true }
  intent "perf" { cmd = "PERF", args = { "OPENAP", "CLASS" }, handler = "performance" }
  intent "getwind" { cmd = "GETWIND", args = { "lat", "lon", "alt" }, handler = "get_wind" }
  intent "asas" { cmd = "ASAS", args = { "ON", "OFF", "STATEBASED" }, handler = "switch" }
  intent "reso" { cmd = "RESO", args = { "MVP", "OFF" }, handler = "resolution" }
  intent "zone" { cmds = { "ZONER", "ZONEDH" }, handler = "zone" }
  intent "rfac" { cmds = { "RFACH", "RFACV" }, args = { "factor" }, handler = "reso_factor" }
  intent "rmethv" { cmd = "RMETHV", args = { "ON", "OFF" }, handler = "reso_vertical" }
  intent "swap" { cmds = { "ALT", "HDG", "SPD" }, handler = "swap" }
  intent "resnav" { cmd = "RESNAV", args = { "PASTCPA" }, handler = "resume_nav" }
  intent "creconfs" { cmd = "CRECONFS", args = { "acid", "type", "targetid", "dpsi", "cpa", "tlosh", "dh", "tlosv" },
                      handler = "conflict_intruder", absorbs = true, single = true }
  intent "dtlook" { cmd = "DTLOOK", args = { "seconds" }, handler = "look_ahead" }
  intent "noise" { cmd = "NOISE", args = { "ON", "OFF" }, handler = "switch" }
  intent "mcre" { cmd = "MCRE", args = { "n" }, handler = "random_traffic", absorbs = true }
  intent "area" { cmd = "AREA", args = { "shapename", "ON", "OFF" }, handler = "area" }
  intent "circle" { cmd = "CIRCLE", args = { "name", "radius" }, handler = "circle" }
  intent "box" { cmd = "BOX", args = { "name" }, handler = "box" }
  intent "poly" { cmds = { "POLY", "POLYALT" }, args = { "name" }, handler = "polygon" }
  intent "line" { cmd = "LINE", args = { "name" }, handler = "line" }
  intent "trail" { cmd = "TRAIL", args = { "acid", "ON", "OFF" }, handler = "trail" }
  intent "help" { cmd = "HELP", args = { "command" }, handler = "help" }

  -- an instruction announced with "expect" is no clearance
  rule { "*", false, prev = { 2, "@not_a_clearance" } }
  -- "what commands are there", "how do I see all the commands", "how does the addwpt command work?": a question
  -- about squawk's commands (a word of asking or showing, no aircraft, no value) is HELP, of the command named
  -- beside the noun when one is (its name is no instruction of its own)
  local function help_asked(g, i)
    if not g:word(i, "commands command cmds") then return false end
    if #g:quantities(1, #g.t + 1) > 0 or g:has_ref(1, #g.t + 1, "aircraft") then return false end
    return g:word_in(1, #g.t + 1, "what which how list show see available exist there explain use work")
  end
  rule { "*", false, next = "command cmd", when = function(g, i) return help_asked(g, i + 1) end }
  rule { "*", false, prev = { 1, "command cmd" }, when = function(g, i) return help_asked(g, i - 1) end }
  rule { "commands command cmds", "help", when = help_asked }
  -- "what does ALT do?", "what does the HDG command mean": a command's name asked about (HELP name, m:help)
  local command_names
  local function command_asked(g, i)
    if not command_names then
      command_names = {}
      for _, c in ipairs(squawk.sim.commands()) do
        command_names[c.name:lower()] = true
        for _, a in ipairs(c.aliases or {}) do command_names[a:lower()] = true end
      end
    end
    local n = g:word(i - 1, "command cmd") and i - 2 or i - 1
    local k = g:word(n - 1, "the") and n - 2 or n - 1
    local t = g.t[n]
    return t ~= nil and t.kind == "word" and command_names[t.raw:lower()] == true and g:word(k, "does")
      and g:word(k - 1, "what") and not g:has_ref(1, #g.t + 1, "aircraft") and #g:quantities(1, #g.t + 1) == 0
  end
  rule { "do mean", "help", when = command_asked }
  rule { "*", false, next = "do mean", when = function(g, i) return command_asked(g, i + 1) end }
  rule { "what does", false, when = function(g, i)
    local k = g:find_word(i, #g.t + 1, "do mean")
    return k <= #g.t and command_asked(g, k)
  end }
  rule { "*", false, prev = { 3, "advise" }, when = function(g, i) return g:preceded_by(i, 2, "able") end }  -- "advise when able direct X"
  -- "set speed to 1x", "speed 4x": a speed given as a multiple, with no aircraft named anywhere, is the clock's rate
  rule { "speed spd", "dtmult", when = function(g, i)
    if g:has_ref(1, #g.t + 1, "aircraft") then return false end
    for _, q in ipairs(g:quantities(i + 1, math.min(#g.t + 1, i + 4))) do
      if q.kind == "mult" then return true end
    end
    return false
  end }
  -- "run fast forward 10 min", "run fast forward until I say stop": "run" before the fast-forward it runs is no verb
  -- of its own
  rule { "run", false, next = "fast", when = function(g, i) return g:word(i + 2, "forward") end }
  -- "klm1234 alt?", "DLH4AX hdg and spd?": the aircraft, then only measures of its state by name and a question
  -- mark ending the request, no value: its state asked (POS), never a level or heading to fly ("ezy45 fl?", the
  -- level's prefix with its number missing, is asked)
  rule { "alt altitude hdg heading spd speed level pos position", "pos", when = function(g, i)
    if not (#g.t > i and g.t[#g.t].text == "?" and g.t[#g.t].kind == "punct") then return false end
    local r = g:refs_in(1, i, "aircraft")[1]
    if not (r and r.b == g:skip_fillers(1)) then return false end
    for k = r.e, #g.t - 1 do
      if not (g:word(k, "alt altitude hdg heading spd speed level pos position and")
          or (g.t[k].kind == "punct" and g.t[k].text == ",")) then return false end
    end
    return true
  end }
  -- "I think it's paused", "is it stopped?": the run's state told or asked, no instruction ("keep it paused"
  -- instructs)
  rule { "pause paused stop stopped freeze frozen", false, prev = { 1, "it is" }, when = function(g, i)
    local raw = g.t[i].raw:lower()  -- (the participle: the lexer reads "paused" as "pause")
    return (raw:match("ed$") ~= nil or raw == "frozen") and not g:word(i - 2, "keep leave get have make")
  end }
  -- "BAW918 A320 @ TEBRO hdg 170 FL320 M0.78", "ac: AAL2307 B772 ...": a request (or its part after a
  -- label and colon) that opens with a callsign no aircraft has and its type, then values: a new aircraft
  -- (before any other rule: the first word after the type, "hdg", starts the creation)
  rule { "*", "create", when = function(g, i)
    if g.opening_create == nil then
      g.opening_create = false  -- (computed once per request: the rule is tried at every word)
      local colon = 0
      for k = 1, #g.t do if g.t[k].kind == "punct" and g.t[k].text == ":" then colon = k break end end
      -- ("Let's start with the baseline pair. SAS1A A320 at VENOM ...": a sentence before it that names no
      -- value and no aircraft is a label too)
      for k = 1, colon == 0 and #g.t or 0 do
        if g.t[k].kind == "punct" and g.t[k].text == "." then
          if #g:quantities(1, k) == 0 and #g:refs_in(1, k, "aircraft") == 0 then colon = k end
          break
        end
      end
      -- ("I'd like a head-on pair, AEA10 B738 at ...": a first clause up to its comma that names no value and
      -- nothing (aircraft, type, place) and holds no instruction word is a label too)
      for k = 1, colon == 0 and #g.t or 0 do
        if g.t[k].kind == "punct" then
          local bare = g.t[k].text == "," and #g:quantities(1, k) == 0
          for _, r0 in ipairs(g.refs) do bare = bare and r0.b >= k end
          for x = 1, bare and k - 1 or 0 do bare = bare and g:intent_at(x) == nil end
          if bare then colon = k end
          break
        end
      end
      local j = colon + 1
      while g.t[j] and (g.t[j].kind == "punct" or g.t[j].filler) do j = j + 1 end
      -- ("first one is KLM88 B789 ...", "can we have a Vueling A320 VLG88 ...": a lead-in of at most four
      -- words before the first name, no value, place or instruction among them, is no instruction either)
      local first = g.refs[1]
      for _, r0 in ipairs(g.refs) do if r0.b < first.b then first = r0 end end
      if first and first.b > j and first.b <= j + 8 and (first.kind == "aircraft" or first.kind == "type") then
        local lead, to, words = true, first.b, 0
        for k = j, first.b - 1 do
          local icao, ae = g:airline_at(k)
          if lead and k < to and ae == first.b and first.kind == "type" then to = k end  -- ("a Vueling A320")
          -- ("first aircraft Air Malta AMC412 A320 ...": the airline of the new callsign said before it)
          local own = ae == first.b and first.kind == "aircraft" and not first.exists
            and first.name:upper():sub(1, #icao) == icao
          lead = lead and (k >= to or (g.t[k].kind == "word" and not g:intent_at(k) and (not ae or own)))
          if k < to and not g.t[k].filler then words = words + 1 end
        end
        lead = lead and words <= 4
        for _, q in ipairs(g:quantities(j, to)) do
          lead = lead and q.kind == "plain" and g:word(q.b, "one") and q.e == q.b + 1
        end
        if lead then j = to end
      end
      local r = g:refs_in(j, j + 1, "aircraft")[1]
      -- ("Westjet 1245 is a 737 MAX 8", "Envoy 3410, an E175, ...": the type after "is", an article, "also";
      -- "United 455, seven three niner, B739": the type's digits said before its designator)
      local k = r and r.e
      while k and g.t[k] and (g.t[k].kind == "punct" or g.t[k].kind == "number"
          or g:word(k, "a an is also type zero one two three four five six seven eight nine niner")) do
        k = k + 1
      end
      local ty = r and g:new_callsign(r) and r.b == j and g:refs_in(k, k + 1, "type")[1]
      if not ty then
        -- ("A320 BAW1 at ...", "a Ryanair 738, RYR4GV, at MAYLA ...": the type first, after its article)
        local a = g:word(j, "a an another") and j + 1 or j
        if g:word(a, "little") then a = a + 1 end  -- ("a little Cessna 172")
        local _, ae = g:airline_at(a)
        if ae and g:refs_in(ae, ae + 1, "type")[1] then a = ae end  -- ("a Vueling A320 VLG88")
        local t1 = g:refs_in(a, a + 1, "type")[1]
        local after = t1 and t1.b == a and t1.e
        while after and g.t[after] and g.t[after].kind == "punct" do after = after + 1 end
        -- ("an A319 operated as EZY12AB ...", "a B738 flying as RYR7PL, ...": the new callsign introduced after the type
        -- by a verb of operating and "as")
        if after and g:word(after, "operated operating flying") and g:word(after + 1, "as") then after = after + 2 end
        local r2 = after and g:refs_in(after, after + 1, "aircraft")[1]
        if r2 and not r2.exists and r2.b == after then ty = r2 end  -- (the creation fires after the callsign)
      end
      -- ("Need a slow one ...:", "One more:": "one" standing for an aircraft is no value; nor is the count of
      -- the aircraft that follow, "two aircraft please:", "make two test aircraft:")
      local values, new = 0, 0
      for _, r in ipairs(colon > 0 and g:refs_in(colon + 1, #g.t + 1, "aircraft") or {}) do
        if not r.exists then new = new + 1 end
      end
      for _, q in ipairs(colon > 0 and g:quantities(1, colon) or {}) do
        local count = q.kind == "plain" and q.value == new
          and (g:word(q.e, "@counted_aircraft") or g:word(q.e + 1, "@counted_aircraft"))
        if not (q.kind == "plain" and g:word(q.b, "one") and q.e == q.b + 1) and not count then values = values + 1 end
      end
      -- ("an intruder for KLM77: XY22 A320 ...": the aircraft the new one is set up against labels it)
      local named = 0
      for _, a in ipairs(colon > 0 and g:refs_in(1, colon, "aircraft") or {}) do
        if not (a.exists and g:word(a.b - 1, "for on against") and g:preceded_by(a.b - 1, 2, "@intruder @head_on")) then
          named = named + 1
        end
      end
      local labelled = colon > 0 and (values > 0 or named > 0)
      if ty and not labelled and #g:quantities(ty.e, #g.t + 1) > 0 then
        local at = ty.e  -- (fired at the first word after the type)
        while g.t[at] and (g.t[at].kind ~= "word" or g.u:used(at)) do at = at + 1 end
        -- ("new ac: BAW77, B744, ...", "intruder on the Europa: T2, B738, ...": said by the label already)
        local said = false
        for k = 1, colon - 1 do said = said or g:intent_at(k) ~= nil end
        g.opening_create = not said and g.t[at] ~= nil and at
      end
    end
    return g.opening_create == i
  end }

  -- "FL310, heading 090, 300 knots, callsign BAW92, A319, at 53.5 -6.8": a new aircraft's fields in any order, no
  -- verb, its callsign named as such ("callsign" straight before a callsign no aircraft has), its type and a
  -- position said, no aircraft flying named: the creation, fired at the request's first word (no number)
  rule { "*", "create", when = function(g, i)
    if g.fields_create == nil and not g:said("callsign") then g.fields_create = false end  -- (none named as such)
    if g.fields_create == nil then
      g.fields_create = false  -- (computed once per request: the rule is tried at every word)
      local new, types, flying = 0, 0, 0
      for _, r in ipairs(g.refs) do
        if r.kind == "aircraft" and r.exists then flying = flying + 1 end
        if r.kind == "aircraft" and not r.exists and g:word(r.b - 1, "callsign") and g:new_callsign(r) then
          new = new + 1
        end
        if r.kind == "type" then types = types + 1 end
      end
      -- (the position: a latitude and longitude read, or two plain numbers after "at" or "position" that fit them)
      local lat, qs = false, g:quantities(1, #g.t + 1)
      for k, q in ipairs(qs) do
        local q2 = qs[k + 1]
        lat = lat or q.kind == "lat" or (q.kind == "plain" and q2 ~= nil and q2.kind == "plain" and q2.b == q.e
          and g:word(q.b - 1, "at position pos") and math.abs(q.value) <= 90 and math.abs(q2.value) <= 180)
      end
      local first = g:skip_fillers(1)
      while g.t[first] and (g.t[first].kind ~= "word" or g.t[first].filler) do first = first + 1 end
      if new == 1 and types == 1 and flying == 0 and lat and g.t[first] then
        g.fields_create = first
      end
    end
    return g.fields_create == i
  end }
  -- ("comply with published speed and altitude restrictions": the kinds of restriction complied with, VNAV)
  rule { "speed altitude level", false, prev = { 6, "comply" }, next = "and restriction restrictions" }
  -- True when a verb of an instruction is said before i in the request, not as a state ("is descending"): a
  -- measure asked after it ("KLM12 please descend... hmm, to what level is good?", "climb to what level?") is
  -- the value the speaker could not give, never a question of the aircraft's state (no POS: the value is asked)
  local function value_unsaid(g, i)
    for x = 1, i - 1 do
      if g:word(x, "climb descend turn reduce increase slow") and not g:word(x - 1, "is are was were") then
        return true
      end
    end
    return false
  end
  -- "swr84c altitude?", "afr1442 speed?", "bel21a lvl?": a state word asked with "?" straight after it, an aircraft named
  -- before it and no value said anywhere: a question of the aircraft's state (POS), no instruction (an
  -- instruction's shorthand, "ezy45 fl?", "hdg?", is a value left out: asked; "stay at its current altitude?" names
  -- the value kept, no question of state)
  -- ("Turkish 6PA, your position?", "THY6PA, your altitude?": "your" opening the clause after the callsign asks the
  -- aircraft itself; "your heading now?", a filler between)
  rule { "altitude level speed heading mach airspeed position", "pos", when = function(g, i)
    local k = i + 1
    while g.t[k] and g.t[k].filler and g.t[k].kind ~= "punct" do k = k + 1 end
    local nx = g.t[k]
    local yours = g:word(i - 1, "your") and i > 2 and (g.t[i - 2].kind == "punct" or g:refs_in(1, i, "aircraft")[1] ~= nil
      and g:skip_fillers(g:refs_in(1, i, "aircraft")[1].e) == i - 1)
    return nx ~= nil and nx.kind == "punct" and nx.text == "?" and g:has_ref(1, i, "aircraft")
      and #g:quantities(1, #g.t + 1) == 0
      and (yours or not g:word(i - 1, "current present same its his her their your"))
      and not value_unsaid(g, i)
  end }

  -- "KAL1203 now altitude is how much?", "AAR8917, heading what is now?", "its speed, how much now?", "its heading,
  -- what?": a state word with the question word after it (Korean order: "what"/"how much", "is", "now" and a comma
  -- around it, nothing else to the "?" or the end), an aircraft named before it and no value in its clause (an
  -- instruction given before the comma, "speed 250, heading what?", stands): the aircraft's state asked (POS)
  local function asked_after(g, i)
    local k = i + 1
    local asked = false
    while g.t[k] and not (g.t[k].kind == "punct" and g.t[k].text ~= ",") do
      if g:word(k, "what") then asked = true
      elseif g:word(k, "how") and g:word(k + 1, "much") then asked, k = true, k + 1
      elseif not (g:word(k, "is now currently value") or g.t[k].filler or g.t[k].kind == "punct") then return false end
      k = k + 1
    end
    return asked and (g.t[k] == nil or g.t[k].text == "?")
  end
  rule { "altitude level speed heading mach airspeed height", "pos", when = function(g, i)
    local b = i - 1
    while b > 1 and not (g.t[b].kind == "punct" and not g:word(b - 1, "its his her their the")) do b = b - 1 end
    return asked_after(g, i) and g:has_ref(1, i, "aircraft") and #g:quantities(b, #g.t + 1) == 0
      and not value_unsaid(g, i)
  end }
  -- "KAL851 how fast going now?", "how high now?": "how fast"/"how high" after the aircraft named, then only a verb
  -- of going or "now" to the "?" or the end
  rule { "how", "pos", next = "fast high", when = function(g, i)
    if not g:has_ref(1, i, "aircraft") or #g:quantities(1, #g.t + 1) > 0 then return false end
    local k = i + 2
    while g:word(k, "going flying travelling traveling now currently is it he she") do k = k + 1 end
    return g.t[k] == nil or g.t[k].text == "?"
  end }
  -- "KAL1114 and AAR8811, which one is higher now?", "which is faster?", "who is lower": aircraft named before a
  -- question comparing their state, no value said: each one's state shown (POS)
  rule { "which who", "pos", when = function(g, i)
    local k = g:word(i + 1, "one aircraft plane") and i + 2 or i + 1
    if not g:word(k, "is 's") then return false end
    k = k + 1
    if g:word(k, "now currently") then k = k + 1 end
    return g:word(k, "higher lower faster slower closer nearer further farther") and #g:refs_in(1, i, "aircraft") >= 2
      and #g:quantities(1, i + 1) == 0 and #g:quantities(i + 2, #g.t + 1) == 0
  end }
  -- "put the sim 3 times faster, the climb takes too long", "the turn was too late": the instruction word after
  -- "the", the subject of a verb of description, is a noun
  rule { "climb descent turn", false, prev = { 1, "the" }, next = "takes took is was seems looks" }
  -- "is SKW44 still climbing?", "is the Delta descending", "what's SKW44 up to": a question about what an
  -- aircraft named is doing, with no value said, asks for its report (POS), never a climb or descent
  rule { "climbing descending", "pos", when = function(g, i)
    local q = g:skip_fillers(1)
    return g:word(q, "is") and g:has_ref(q + 1, i, "aircraft") and #g:quantities(1, #g.t + 1) == 0
  end }
  -- "confirm you are descending", "confirm you're still climbing?": a question to the pilot about the motion
  -- under way, no value in its clause, asks for its report (POS); "confirm you are descending FL100" (a level
  -- in it) is a clearance asked about (G:question_back)
  rule { "climbing descending", "pos", when = function(g, i)
    local k = i - 1
    if g:word(k, "still now") then k = k - 1 end
    if g:word(k, "are") and g:word(k - 1, "you") then k = k - 2
    elseif g:word(k, "you're youre") then k = k - 1
    elseif g:word(k, "re") and g:word(k - 1, "you") then k = k - 2
    else return false end
    if g:word(k, "that") then k = k - 1 end
    if not g:word(k, "confirm") then return false end
    local e = i + 1
    while e <= #g.t and g.t[e].kind ~= "punct" do e = e + 1 end
    return #g:quantities(i, e) == 0 and #g:refs_in(i, e, "waypoint") == 0
  end }
  -- (the aircraft said first, before a comma, and the question of it by a pronoun: "the Delta, what's it up to?")
  rule { "up", "pos", next = "to", when = function(g, i)
    local q = g:skip_fillers(1)
    local fronted = g.t[q] ~= nil and g.t[q].kind ~= "punct" and g:word(i - 1, "it he she")
      and g:word(i - 2, "what's whats what") and g.t[i - 3] ~= nil and g.t[i - 3].text == ","
      and #g:refs_in(q, i - 3, "aircraft") == 1
    -- (a time said after it, "what is the Lufthansa up to at the moment?", "... right now", is part of the question)
    local k = g:skip_fillers(i + 2)
    if g:word(k, "right") and g:word(k + 1, "now") then k = k + 1 end
    if g:word(k, "now currently presently") then k = k + 1 end
    if g:word(k, "at") and g:word(k + 1, "the") and g:word(k + 2, "moment minute") then k = k + 3 end
    if g:word(k, "at") and g:word(k + 1, "present") then k = k + 2 end
    return (fronted or (g:word(q, "what's whats what") and g:has_ref(q + 1, i, "aircraft")))
      and g:skip_fillers(k) > #g.t
  end }
  -- altitude
  -- ("rate of climb 1500", "rate descend 2000": the motion the rate's word names, straight after it or "of")
  rule { "climb climbing descend descending desc dsc clb altitude alt cruise altitudes drop", false, prev = { 2, "rate" },
         when = function(g, i) return g:word(i - 1, "rate") or (g:word(i - 1, "of") and g:word(i - 2, "rate")) end }
  -- "1800 fpm descending", "a thousand foot a minute descent": the word gives the rate's sign
  rule { "descending climbing descent", false, prev = { 2, "fpm minute min" } }
  -- "vertical speed 1500 descending", "vs 1500 descent": the word after a vertical speed's number gives its sign
  rule { "descending climbing descent", false, when = function(g, i)
    return g.t[i - 1] ~= nil and g.t[i - 1].kind == "number"
      and (g:word(i - 2, "vs") or (g:word(i - 2, "speed") and g:word(i - 3, "vertical")))
  end }
  -- "stop the Iberia's descent, vertical speed zero", "stop the climb, level off, VS zero": the climb or
  -- descent stopped by the vertical speed said, no level
  rule { "climb climbing descend descending descent level", false, prev = { 3, "stop halt" },
         near = { 6, "vs vertical" } }
  rule { "level", false, next = "off", prev = { 6, "stop halt" }, near = { 4, "vs vertical" } }
  -- "desc rate 1500": the verb gives the sign of a vertical speed
  rule { "climb descend desc clb", false, next = "rate" }
  -- "cruise at mach .79", "cruise at 280 knots": a speed, when the value after the verb is one
  rule { "cruise", "spd", when = function(g, i)
    local q = g:quantities(i + 1, math.min(#g.t + 1, i + 5))[1]
    return q ~= nil and (q.kind == "speed" or q.kind == "mach")
  end }
  -- "what is the altitude of X and of Y?", "what are the speeds of X and Y?": the state asked by "what" (its rule
  -- reads the aircraft, each one), the noun no instruction of its own
  rule { "altitude speed heading level altitudes speeds headings levels", false, prev = { 1, "the" },
         when = function(g, i) return g:word(i - 2, "is are") and g:word(i - 3, "what") end }
  -- "AAR731 current altitude tell me", "KAL8 speed let me know": the state asked for before the request
  -- for it (verb-final order) is no instruction
  rule { "altitude speed heading level position", false, when = function(g, i)
    local texts = g.words
    for k = i + 1, math.min(#g.t, i + 3) do
      local w = texts[k]
      if (w == "tell" and (texts[k + 1] == "me" or texts[k + 1] == "us")) or (w == "let" and texts[k + 2] == "know") then
        return true
      end
    end
    return false
  end }
  -- "climb via the route", "descend via its route": the route's own levels flown (VNAV), no level said in the
  -- clause ("climb via the route to FL300" is the level; "descend via STAR", a procedure squawk does not fly,
  -- is asked)
  rule { "climb climbing descend descending", "vnav", next = "via", when = function(g, i)
    local e = i + 1
    while g.t[e] and g.t[e].kind ~= "punct" do e = e + 1 end
    local k = g:word(i + 2, "the its") and i + 3 or i + 2
    -- ("descend via VNAV please": the switch named, courtesy after it)
    local x = k + 1
    while x < e and (g.t[x].filler or g:word(x, "please")) do x = x + 1 end
    return g:word(k, "route vnav") and x == e and #g:quantities(i, e) == 0
  end }
  -- "follow its route again, and also the altitudes of the route": the route's levels, said after "follow" in its
  -- sentence and ending their clause, are flown too (VNAV)
  rule { "altitude level height", "vnav", when = function(g, i)  -- (plurals read as these)
    local k = g:word(i + 2, "the its their his her") and i + 3 or i + 2
    if not (g:word(i + 1, "of on in along") and g:word(k, "@route_nouns")) then return false end
    -- (in the sentence of "follow", ending its clause: "The altitudes of the route are fine" is a remark)
    local e = k + 1
    while g:word(e, "too again also") or (g:word(e, "as") and g:word(e + 1, "well")) do
      e = g:word(e, "as") and e + 2 or e + 1
    end
    if g.t[e] and g.t[e].kind ~= "punct" then return false end
    for x = i - 1, 1, -1 do
      if g.t[x].kind == "punct" and g.t[x].text ~= "," then return false end
      if g:word(x, "follow follows following") then return true end
    end
    return false
  end }
  -- "follow its route, heights and speeds included", "follow the route and the speeds", "resume own navigation,
  -- levels too": the route's values named with no value in a clause of their own after following it
  -- (G:values_named_alone, G:route_values_followed) are flown too (VNAV: the route's levels and speeds)
  rule { "@route_value_nouns", "vnav", when = function(g, i)
    local b = g:values_named_alone(i)
    return b ~= nil and g:route_values_followed(b)
  end }
  rule { "climb climbing descend descending altitude alt cruise altitudes desc clb", "alt" }
  -- "rise to FL200", "ascend to FL200": a climb said so, with its level after it
  rule { "ascend rise", "alt", when = function(g, i)
    local q = g:quantities(i + 1, math.min(#g.t + 1, i + 4))[1]
    return q ~= nil and q.kind == "alt"
  end }
  -- "drop in a Southwest 737, SWA455, ...", "pop in an A320 ...": an aircraft put in, a new callsign or a type
  -- straight after the article
  rule { "drop pop", "create", next = "in", when = function(g, i)
    return g:word(i + 2, "a an another") and g:new_aircraft_follows(i + 2)
  end }
  -- "drop LAMUT from AFR7516", "take KOPOR off the Iberia": a known waypoint said straight after the verb
  -- and taken "from" or "off" an aircraft that flies
  rule { "drop remove delete take", "delwpt", when = function(g, i)
    local r = g:refs_in(i + 1, i + 2, "waypoint")[1]
    local k = r and g:word(r.e, "from off") and (g:word(r.e + 1, "the") and r.e + 2 or r.e + 1)
    local a = k and g:refs_in(k, k + 1, "aircraft")[1]
    return a ~= nil and a ~= false and a.exists == true
  end }
  -- ("EIN112 drop ROKNA", "dlh4ax rmv andik": a waypoint of the route of the aircraft named straight before the verb,
  -- said straight after it, ending the request)
  rule { "drop remove skip rmv", "delwpt", when = function(g, i)
    local r, a = g:refs_in(i + 1, i + 2, "waypoint")[1], g:refs_in(1, i, "aircraft")
    a = a[#a]
    return r ~= nil and a ~= nil and a.exists and a.e == i and g:skip_fillers(r.e) > #g.t and g:on_route(a.name, r.name)
  end }
  -- ("aal123 drop wpt dpk", "drop waypoint ROKNA": the waypoint's noun between the verb and the waypoint)
  rule { "drop skip", "delwpt", next = "@waypoint_nouns",
         when = function(g, i) return g:has_ref(i + 2, i + 3, "waypoint") end }
  -- "drop CHARL from united 9's route": a waypoint off the route
  rule { "drop", "delwpt", near = { 8, "@route_nouns" },
         when = function(g, i) return g:has_ref(i + 1, i + 2, "waypoint") end }
  rule { "drop", "delete", next = "him her it them", not_near = { 3, "to down level fl feet ft thousand altitude" } }  -- "out of my airspace, drop him"
  -- an aircraft named at token k (one flying when `flying`) with nothing but fillers and aircraft nouns after it
  local function aircraft_alone(g, k, flying)
    for _, r in ipairs(g:refs_in(k, k + 1, "aircraft")) do
      if r.b == k and (r.exists or not flying) then
        for x = r.e, #g.t do
          if g.t[x].kind ~= "punct" and not g.t[x].filler and not g:word(x, "@aircraft_nouns") then return false end
        end
        return true
      end
    end
    return false
  end
  -- (an aircraft flying set down at a position: a latitude or a decimal straight after one of `words`,
  -- another value after it)
  local function set_down_at(words)
    return function(g, i)
      local r = g:refs_in(i + 1, i + 3, "aircraft")[1]
      if not (r and r.exists and g:word(r.e, words)) then return false end
      local qs = g:quantities(r.e + 1, math.min(#g.t + 1, r.e + 8))
      return qs[1] ~= nil and qs[2] ~= nil and qs[1].b == r.e + 1
        and (qs[1].kind == "lat" or (qs[1].kind == "plain" and qs[1].number.decimal))
    end
  end
  -- "drop TRA5K at 52.3 4.0": moved there
  rule { "drop", "move", when = set_down_at("at") }
  -- "drag SWA3388 to 33.1 -96.9 FL180 heading 270": an aircraft dragged (on the scope) to a position is moved there
  rule { "drag dragged", "move", when = set_down_at("to at") }
  -- "drop KLM1234", "drop the KLM agent": an aircraft and nothing after it
  rule { "drop", "delete", when = function(g, i) return aircraft_alone(g, g:skip_fillers(i + 1), false) end }
  -- "drop Cityjet 62 from the exercise": an aircraft that flies dropped from the run
  rule { "drop", "delete", when = function(g, i)
    local a = g:refs_in(i + 1, i + 2, "aircraft")[1]
    local k = a and a.exists and g:word(a.e, "from") and (g:word(a.e + 1, "the this") and a.e + 2 or a.e + 1)
    return k and g:word(k, "@sim") or false
  end }
  -- "knock out KLM1234", "knock out the Cessna": an aircraft taken out of the simulation, nothing after it
  -- "take N73WX off the scope", "sup: n73wx off the scope": an aircraft taken off the display is deleted (the
  -- aircraft straight before "off", opening the request or after "take"/"get", "the" between them: "get the Air
  -- France off the screen"; "N73WX is off the scope" tells)
  rule { "off", "delete", when = function(g, i)
    local k = g:word(i + 1, "the my your our") and i + 2 or i + 1
    if not g:word(k, "scope screen display radar") then return false end
    local r = g:refs_in(1, i, "aircraft")
    r = r[#r]
    if not (r and r.e == i and r.exists) then return false end
    local b = g:skip_fillers(1)
    local v = g:word(r.b - 1, "the") and r.b - 2 or r.b - 1
    return r.b == b or (g:word(v, "take get") and v == b)
  end }
  rule { "knock", "delete", next = "out", when = function(g, i) return aircraft_alone(g, g:skip_fillers(i + 2), true) end }
  -- "lose the Air Europa", "lose KLM12": an aircraft that flies lost from the simulation, nothing after it
  -- ("lose 2000 feet", "lose the speed" name no aircraft)
  rule { "lose", "delete", when = function(g, i) return aircraft_alone(g, g:skip_fillers(i + 1), true) end }
  -- "erase the American 918", "eliminate the Taca 580 of the simulation" (Spanish "eliminar", "borrar"): an aircraft
  -- that flies, nothing after it but "from" or "of" and the simulation
  rule { "erase eliminate", "delete", when = function(g, i)
    local k = g:skip_fillers(i + 1)
    if aircraft_alone(g, k, true) then return true end
    local r = g:refs_in(k, k + 1, "aircraft")[1]
    if not (r and r.b == k and r.exists and g:word(r.e, "from of")) then return false end
    local x = g:skip_fillers(r.e + 1)
    return g:word(x, "@sim") and g:skip_fillers(x + 1) > #g.t
  end }
  -- ("KLM1234 should drop to 250 knots": a speed's unit straight after the value names the speed dropped)
  rule { "drop", "spd", near = { 3, "knots kts kt knot" } }
  rule { "drop", "alt", not_near = { 2, "speed" } }
  -- "slow the Ryanair down to 250", "speed it up to 300": the particle of a speed verb, its
  -- aircraft between them, is no change of level
  rule { "up down", false, when = function(g, i)
    if g:word(i - 1, "it him her them") and g:word(i - 2, "slow speed") then return true end
    for _, r in ipairs(g.refs) do
      if r.kind == "aircraft" and r.e == i then
        local b = g:word(r.b - 1, "the") and r.b - 1 or r.b
        if g:word(b - 1, "slow speed") then return true end
      end
    end
    return false
  end }
  -- ("go down", "start down to 12000", "should start going down to 6000", "head down to 12,000 feet")
  rule { "up down", "alt", prev = { 1, "go come going coming start starting head heads" }, not_near = { 2, "speed knots" } }
  -- "klm12 move up to FL200", "move KLM12 down to 6000 ft", "klm12 move up": "move" before "up" or "down" (the
  -- aircraft between or not) with no coordinate or place after is a climb or descent (its level asked when none is
  -- said), never a move to a position
  -- the position of "up" or "down" when "move" at i opens a climb or descent: "up" or "down" straight after it (or
  -- after the aircraft said after it) with no coordinate or place after; else nil
  local function move_vertical(g, i)
    if not g:word(i, "move moves moving") then return nil end
    local r = g:refs_in(i + 1, math.min(#g.t + 1, i + 2), "aircraft")[1]
    local k = r and r.b == i + 1 and r.e or i + 1
    if not g:word(k, "up down") then return nil end
    local e = math.min(#g.t + 1, k + 6)
    for _, q in ipairs(g:quantities(k + 1, e)) do
      if q.kind == "lat" or q.kind == "lon" or (q.kind == "plain" and q.number.decimal) then return nil end
    end
    if g:has_ref(k + 1, e, "waypoint") or g:has_ref(k + 1, e, "airport") then return nil end
    -- ("move EIN42 up to FL300, same spot": the place it stands said, a move where it is; so is "move EWG7RT up to
    -- FL90 instantly", the level reached at once)
    if g:word_in(k + 1, #g.t + 1, "instantly instantaneously") then return nil end
    for j = k + 1, #g.t - 1 do
      if g:word(j, "same") and g:word(j + 1, "position place spot location") and not g:word(j + 2, "as") then
        return nil
      end
    end
    return k
  end
  rule { "move moves moving", false, when = function(g, i) return move_vertical(g, i) ~= nil end }
  rule { "up down", "alt", when = function(g, i)
    local r = g:refs_in(math.max(1, i - 2), i, "aircraft")[1]
    local v = r and r.e == i and r.b - 1 or i - 1
    return move_vertical(g, v) == i
  end }
  -- "go higher to 36000", "take it higher to FL360": a level after "higher ... to" ("lower" is read below)
  rule { "higher", "alt", next = "to", not_near = { 3, "speed knots kts" } }
  -- "N123AB go to 3500": a bare number of a thousand or more is no heading or speed, but a level; so is a level
  -- with its unit ("BAW1 go to FL270, EZY2 go to FL310", "go to level FL100": each aircraft's own)
  rule { "go", "alt", next = "to", when = function(g, i)
    local at = g:word(i + 2, "level altitude") and i + 3 or i + 2
    local q = g:quantities(at, at + 3)[1]
    return q ~= nil and (q.b == i + 2 or (q.b == at and q.kind == "alt"))
      and ((q.kind == "plain" and q.value >= 1000 and q.value % 100 == 0) or q.kind == "alt")
  end }
  -- "kl204 up to 300", "EWG7LM up to FL320 so it ...": straight after the callsign
  rule { "up down", "alt", next = "to", not_near = { 3, "speed knots kts" }, not_prev = { 3, "speed spd" },
         when = function(g, i)
    for _, r in ipairs(g.refs) do
      if r.kind == "aircraft" and r.e == i then return true end
    end
    return false
  end }
  -- ("after KERAX speed 250 and down to FL080": after "and" or "then", a flight level after "to", a speed before)
  rule { "up down", "alt", next = "to", when = function(g, i)
    local q = g:quantities(i + 2, math.min(#g.t + 1, i + 6))[1]
    return g:word(i - 1, "then and") and q ~= nil and q.b == i + 2 and q.kind == "alt" and q.fl == true
  end }
  -- "N73WX left 270, down to 3000", "..., then up to FL240": opening a clause, a level after "to"
  rule { "up down", "alt", next = "to", not_near = { 3, "speed knots kts" }, not_prev = { 3, "speed spd" },
         when = function(g, i)
    local p = g.t[i - 1]
    if not (p and (p.kind == "punct" or g:word(i - 1, "then and"))) then return false end
    local q = g:quantities(i + 2, i + 3)[1]
    return q ~= nil and q.b == i + 2
      and (q.kind == "alt" or (q.kind == "plain" and q.value >= 1000 and q.value % 100 == 0))
  end }
  -- "RYR8 down one two zero", "KLM12 up two four zero, BAW5 down three one zero", "..., down seven thousand": clipped
  -- R/T, the adverb straight after the callsign or opening a clause, a level straight after it (hundreds of feet said
  -- as a flight level, or thousands); a rate's or a speed's unit after it is no level
  rule { "up down", "alt", not_near = { 4, "speed knots kts kt fpm minute min feet/min" }, not_prev = { 2, "speed spd slow" },
         when = function(g, i)
    local p = g.t[i - 1]
    local opens = p == nil or p.kind == "punct" or g:word(i - 1, "then and")
    for _, r in ipairs(g.refs) do
      if r.kind == "aircraft" and r.e == i then opens = true end
    end
    local q = opens and g:quantities(i + 1, math.min(#g.t + 1, i + 6))[1]
    return q ~= nil and q ~= false and q.b == i + 1 and (q.kind == "alt"
      or (q.kind == "plain" and (q.number.thousand or (q.value >= 10 and q.value <= 600 and q.value % 1 == 0))))
  end }
  -- "left 40 and down 4000 ft": an amount in feet after the adverb is a change of level
  rule { "up down", "alt", near = { 2, "@feet" }, when = function(g, i)
    local t = g.t[i + 1]
    return t ~= nil and t.kind == "number"
  end }
  -- "could we get United 9 down to 12,000 feet", "bring the KLM up to FL300", "take him up to 340"
  -- ("when you get to OCK slow down to 220": "down" of "slow down" is the speed's)
  rule { "up down", "alt", prev = { 4, "get bring take" }, not_prev = { 3, "speed spd slow slowing" },
         not_near = { 2, "speed knots" } }
  -- ("when it has reached that speed start it down to FL230": the verb and the aircraft's pronoun straight before)
  rule { "up down", "alt", next = "to", when = function(g, i)
    return g:word(i - 1, "it him her them") and g:word(i - 2, "start get bring take")
  end }
  rule { "expedite", "alt", near = { 1, "climb descent descend" } }
  -- ("expedite your descent to FL120", "expedite the climb to ...": the level after it)
  rule { "expedite", "alt", next = "your the", near = { 2, "climb descent" } }
  rule { "descent climbs", false, prev = { 2, "expedite rate" } }
  rule { "descent climbs", "alt" }
  -- "fly at 30000 ft with speed 290 and heading 100", "stay at FL300": the level flown at
  rule { "fly flies stay remain cruise", "alt", next = "at", when = function(g, i)
    local q = g:quantities(i + 2, math.min(#g.t + 1, i + 5))[1]
    return q ~= nil and q.b == i + 2 and q.kind == "alt"
  end }
  rule { "level", "alt", next = "off" }
  -- "is gonna level at niner thousand", "will level at 9000": the level it levels at, an altitude or a bare
  -- number of hundreds of feet straight after "at" ("level at 40" is no level)
  rule { "level levels", "alt", next = "at", not_prev = { 1, "flight" }, when = function(g, i)
    local q = g:quantities(i + 2, math.min(#g.t + 1, i + 5))[1]
    return q ~= nil and q.b == i + 2 and (q.kind == "alt" or (q.kind == "plain" and q.value >= 1000
      and q.value % 100 == 0))
  end }
  -- "occupy flight level 180", "occupy 5700 metres": the level taken (ICAO English of the former USSR)
  rule { "occupy occupies occupying", "alt", when = function(g, i)
    local q = g:quantities(i + 1, math.min(#g.t + 1, i + 5))[1]
    return q ~= nil and q.b <= i + 2 and (q.kind == "alt" or g:word(i + 1, "fl flight level altitude"))
  end }
  rule { "lower raise", "spd", near = { 4, "speed" } }
  rule { "lower raise", "alt" }
  rule { "maintain maintained", "maintain" }
  -- "swap the levels of KLM12 and TRA6021", "exchange their headings": each flies the other's
  rule { "swap exchange", "swap", near = { 4, "@swapped" } }
  -- "put BAW123 at the same level as DLH4AX", "fly at the same height as Delta 1776"; "keep it at FL290 and 270 kts"
  rule { "level altitude height", "alt", prev = { 1, "same" }, next = "as" }
  rule { "level", "alt", prev = { 2, "same" }, next = "as", when = function(g, i) return g:word(i - 1, "flight") end }
  rule { "keep", "maintain", next = "it him her them", when = function(g, i)
    return g:word(i + 2, "at") and g.t[i + 3] ~= nil and (g.t[i + 3].kind == "number" or g:word(i + 3, "fl flight"))
  end }
  -- "keep it at its current level", "keep KLM12 at the present speed", "keep your present heading": the value flown
  -- now, named after the verb (the aircraft, "at" and a possessive between or not), is the value kept
  rule { "keep", "maintain", when = function(g, i)
    local k = g:skip_fillers(i + 1)
    local r = g:refs_in(k, k + 1, "aircraft")[1]
    if r then k = g:skip_fillers(r.e) elseif g:word(k, "it him her them") then k = k + 1 end
    if g:word(k, "at on") then k = k + 1 end
    if g:word(k, "its his her their your the") then k = k + 1 end
    return g:word(k, "@present") and g:word(k + 1, "level altitude speed heading")
  end }
  -- "keep KLM12 at 280 knots", "KLM12 keep FL140", "keep the Easy at mach .78": a value with its own unit said
  -- straight after the verb (the aircraft and "at" between or not) is the value kept
  rule { "keep", "maintain", when = function(g, i)
    local k = g:skip_fillers(i + 1)
    local r = g:refs_in(k, k + 1, "aircraft")[1]
    if r then k = g:skip_fillers(r.e) end
    if g:word(k, "at") then k = k + 1 end
    local q = g:quantities(k, math.min(#g.t + 1, k + 4))[1]
    return q ~= nil and q.b == k and (q.kind == "alt" or q.kind == "speed" or q.kind == "mach")
  end }


  -- speed, and the simulation's speed
  -- ("swap their headings", "exchange the speeds of ..."): what is swapped, no value of its own
  rule { "heading headings speed speeds level levels altitude altitudes", false, prev = { 4, "swap exchange" } }
  rule { "speed spd airspeed", false, prev = { 1, "vertical" } }
  -- "cross ATAGA at speed 280 knots": the value's noun after "at" in a crossing is the constraint's (AT ... SPD)
  rule { "speed spd airspeed", false, prev = { 1, "at" }, when = function(g, i)
    local r = g:refs_in(i - 2, i - 1, "waypoint")[1]
    return r ~= nil and r.e == i - 1 and g:word(r.b - 1, "cross crossing")
  end }
  -- "when you're at that speed descend FL120", "once it is at the speed", "on reaching that speed": the speed of
  -- the instruction before, reached (G:when_reached), no speed instruction of its own
  rule { "speed", false, prev = { 1, "that the this" }, when = function(g, i)
    return g:word(i - 2, "at") and g:find_word(math.max(1, i - 5), i - 2, "when once") < i - 2
      or g:word(i - 2, "reaching") and g:word(i - 3, "on upon")
  end }
  -- "when the speed is 230 descend FL090", "once speed reaches 250", "when speed reached descend", "only after the
  -- speed becomes 250, descend", "after speed reduced to 250, descend": the noun as the
  -- subject of a verb of reaching after a condition word (G:at_speed, G:when_reached), no speed instruction of its own
  rule { "speed airspeed", false, prev = { 2, "@condition" }, when = function(g, i)
    return g:word(i + 1, "is 's reaches reached hits becomes become @speed_verbs")
      and (g:word(i - 1, "@condition") or g:word(i - 1, "the that"))
  end }
  -- "climb FL380, passing FL360 Mach .79", "when passing FL300 M.77", "climb FL370, reaching Mach .79": a
  -- Mach number said with no verb straight after a level passed or reached (or "reaching" alone: the
  -- level cleared) is a speed instruction of its own, which waits for that level (m:at_altitude); only after
  -- an instruction, and not in a report asked for ("report reaching, Mach .79": the Mach is given now)
  rule { "mach", "spd", when = function(g, i)
    local q = g:quantities(i, math.min(#g.t + 1, i + 4))[1]
    if not (q and q.kind == "mach" and q.b == i) then return false end
    local k = i - 1
    while k >= 1 and (g.t[k].filler or (g.t[k].kind == "punct" and g.t[k].text == ",")) do k = k - 1 end
    local verb = k
    if not g:word(k, "reaching") then
      local qs = g:quantities(math.max(1, k - 4), k + 1)
      local lvl = qs[#qs]
      if not (lvl and lvl.kind == "alt" and lvl.e == k + 1 and g:word(lvl.b - 1, "passing reaching leaving")) then
        return false
      end
      verb = lvl.b - 1
    end
    if g:word(verb - 1, "on when once") then verb = verb - 1 end
    return not g:word(verb - 1, "report") and g:any_instruction_in(1, verb)
  end }
  -- "climb flight level two four zero, mach point eight four when level": a Mach number said with no verb after a
  -- comma, a condition straight after it, is a speed instruction of its own, which waits as the condition says
  rule { "mach", "spd", when = function(g, i)
    local q = g:quantities(i, math.min(#g.t + 1, i + 4))[1]
    if not (q and q.kind == "mach" and q.b == i) then return false end
    local k = i - 1
    while k >= 1 and g.t[k].filler do k = k - 1 end
    return g.t[k] ~= nil and g.t[k].text == "," and g:word(q.e, "when once on") and g:any_instruction_in(1, k)
  end }
  -- "speed 290 knots until AKELI, then Mach .84", "reduce 250 knots, then Mach point seven eight": a Mach number said
  -- with no verb straight after "then", in a request that gave a speed before it, is the next speed instruction
  rule { "mach", "spd", prev = { 2, "then" }, when = function(g, i)
    local q = g:quantities(i, math.min(#g.t + 1, i + 4))[1]
    if not (q and q.kind == "mach" and q.b == i) then return false end
    local k = i - 1
    while k >= 1 and (g.t[k].filler or g.t[k].kind == "punct") do k = k - 1 end
    if not g:word(k, "then") then return false end
    for _, before in ipairs(g:quantities(1, k)) do
      if before.kind == "speed" or before.kind == "mach" then return true end
    end
    return false
  end }
  -- "go to 250 knots", "go Mach point eight": a speed with its unit straight after "go" (or "go to") is a speed
  -- instruction (waiting for a level said before it: "when you're passing FL300 go Mach .8", m:at_altitude)
  rule { "go", "spd", when = function(g, i)
    local at = g:word(i + 1, "to") and i + 2 or i + 1
    local q = g:quantities(at, math.min(#g.t + 1, at + 4))[1]
    return q ~= nil and q.b == at and (q.kind == "speed" or q.kind == "mach")
  end }
  -- "switch to Mach .76", "change to 250 knots": the same after "switch" or "change" and "to"
  rule { "switch change", "spd", next = "to", when = function(g, i)
    local q = g:quantities(i + 2, math.min(#g.t + 1, i + 6))[1]
    return q ~= nil and q.b == i + 2 and (q.kind == "speed" or q.kind == "mach")
  end }
  rule { "speed", "dtmult", near = { 3, "factor multiplier" } }  -- "speed-up factor 2"
  -- "set the timescale to 4", "time scale 2x": a game engine's time scale, the simulation's rate
  rule { "timescale", "dtmult" }
  rule { "scale", "dtmult", prev = { 1, "time" } }
  -- ("Delta 1450 resume normal speed" to an aircraft flying its profile: the profile's speed, VNAV ON)
  rule { "speed speeds", false, when = function(g, i) return g:profile_speed_resumed(i - 2) end }
  rule { "speed", "dtmult", prev = { 2, "x times normal" } }  -- "three times normal speed", "at normal speed"
  rule { "speed", "dtmult", prev = { 1, "@sim" }, when = function(g, i)  -- "sim speed x2"
    local nx = g.t[i + 1]
    return nx ~= nil and nx.kind == "word" and nx.text:match("^x%d") ~= nil
  end }
  -- "speed x10": the multiplier typed straight after "speed" opening the request, nothing after it (no aircraft
  -- bears its name: "x10" reads like a callsign)
  rule { "speed", "dtmult", when = function(g, i)
    local nx, last = g.t[i + 1], #g.t
    while last > i + 1 and g.t[last].kind == "punct" do last = last - 1 end
    return g:skip_fillers(1) == i and nx ~= nil and nx.kind == "word" and nx.text:match("^x%d+$") ~= nil
      and last == i + 1 and not (g:refs_in(i + 1, i + 2, "aircraft")[1] or {}).exists
  end }
  -- "sim x4": the multiplier typed straight after the simulation, nothing after it
  rule { "sim simulation simulator", "dtmult", when = function(g, i)
    local nx = g.t[i + 1]
    return nx ~= nil and nx.kind == "word" and nx.text:match("^x%d+$") ~= nil and i + 2 > #g.t
  end }
  -- True when a multiplier typed "x8" ends the request straight after the clock's word at i ("time", "clock"; "to",
  -- "at" or "on" between), no aircraft bearing its name ("x8" reads like a callsign)
  local function clock_x_multiplier(g, i)
    local k = g:word(i + 1, "to at on") and i + 2 or i + 1
    local nx = g.t[k]
    return nx ~= nil and nx.kind == "word" and nx.text:match("^x%d+$") ~= nil and g:skip_fillers(k + 1) > #g.t
      and not (g:refs_in(k, k + 1, "aircraft")[1] or {}).exists
  end
  -- "time x8": the multiplier straight after the clock's "time" opening the request; "put the time x4", "set the
  -- clock to x4": after a verb of setting and "the"
  rule { "time clock", "dtmult", when = function(g, i) return g:skip_fillers(1) == i and clock_x_multiplier(g, i) end }
  rule { "set put make", "dtmult", when = function(g, i)
    local k = g:word(i + 1, "the") and i + 2 or i + 1
    return g:word(k, "time clock") and clock_x_multiplier(g, k)
  end }
  -- "put the simulation at times four", "set the sim to four times": a multiplier ("times" before or after its
  -- number) said of the simulation itself,
  -- no aircraft named and no instruction word before it ("run the simulation at times four" is run's)
  rule { "sim simulation simulator", "dtmult", when = function(g, i)
    for _, q in ipairs(g:quantities(i + 1, math.min(#g.t + 1, i + 5))) do
      if q.kind == "mult" or (q.kind == "plain" and g:word(q.b - 1, "times x")) then
        return not g:has_ref(1, #g.t + 1, "aircraft") and not g:any_instruction_in(1, i)
      end
    end
    return false
  end }
  -- "double the sim speed", "twice the simulation speed": a multiplier said of the sim's speed
  rule { "speed", "dtmult", prev = { 1, "@sim" }, when = function(g, i) return g:preceded_by(i, 4, "@multipliers") end }
  -- "double the speed of the sim", "triple the speed of the simulation": the same, the sim after "of"
  rule { "speed", "dtmult", next = "of", when = function(g, i)
    return (g:word(i + 2, "@sim") or (g:word(i + 2, "the") and g:word(i + 3, "@sim"))) and g:preceded_by(i, 4, "@multipliers")
  end }
  -- "unfreeze, and double the speed", "half the speed please": a multiplier said of "the speed", no aircraft named
  rule { "speed", "dtmult", when = function(g, i)
    local m = g:word(i - 1, "the") and i - 2 or i - 1
    return g:word(m, "@multipliers") and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  rule { "speed", "dtmult", next = "up", near = { 3, "times x" } }  -- "speed up 10x"
  -- "speed it up to times 5": "it" the run, when no aircraft is named
  rule { "speed", "dtmult", next = "it", near = { 5, "times" }, when = function(g, i)
    return g:word(i + 2, "up") and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- "speed things up a bit, times four": "things" the run, as "it" is, with a rate said after it, no aircraft named
  rule { "speed", "dtmult", next = "things", when = function(g, i)
    return g:word(i + 2, "up") and g:followed_by(i, 8, "times x @multipliers") and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- "a speed-up of 8", "speedup factor 4": the clock's rate as a noun, no aircraft named
  rule { "speed speedup speed-up", "dtmult", near = { 4, "of factor" }, when = function(g, i)
    return (g:word(i, "speedup speed-up") or g:word(i + 1, "up")) and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- "speed it up 4x", "speed the sim up x2": a factor glued to its x, no aircraft named ("speed this up to like
  -- four times", "to about 4x": a hedge of lexicon.value_hedges before the factor widens the window by its word)
  rule { "speed", "dtmult", near = { 3, "up" }, when = function(g, i)
    local e = i + 5
    for k = i + 1, i + 4 do if g:word(k, "@value_hedges") then e = e + 1 end end
    for _, q in ipairs(g:quantities(i + 1, math.min(#g.t + 1, e))) do
      if q.kind == "mult" then return not g:has_ref(1, #g.t + 1, "aircraft") end
    end
    -- ("x2" reads like a callsign no aircraft has: no other aircraft named)
    for k = i + 1, math.min(#g.t, i + 4) do
      local t = g.t[k]
      if t.kind == "word" and t.text:match("^x%d+$") then
        return not g:has_ref(1, k, "aircraft") and not g:has_ref(k + 1, #g.t + 1, "aircraft")
          and #g:refs_in(k, k + 1, "aircraft") <= 1 and not (g:refs_in(k, k + 1, "aircraft")[1] or {}).exists
      end
    end
    return false
  end }
  -- "speed it up a bit, run it at twice real time": the clock, no aircraft named and a multiplier said
  rule { "speed", "dtmult", near = { 3, "up" }, when = function(g, i)
    return not g:has_ref(1, #g.t + 1, "aircraft") and g:word_in(1, #g.t + 1, "@multipliers")
  end }
  -- ("speed the sim up heaps, like times ten": a degree of lexicon.speedup_degrees before the factor widens the
  -- window by its word)
  rule { "speed spd airspeed", "dtmult", when = function(g, i)
    local n = 6
    for k = i + 1, i + 5 do if g:word(k, "@speedup_degrees") then n = n + 1 end end
    return g:followed_by(i, n, "times x") and (g:followed_by(i, 3, "@sim") or g:preceded_by(i, 2, "@sim"))
  end }
  -- "set the speed to 20 times real time": a rate of the clock, no aircraft named
  rule { "speed", "dtmult", when = function(g, i)
    return g:followed_by(i, 5, "times x") and g:followed_by(i, 7, "real normal")
      and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- "speed the simulation to x5", "speed the sim up to x3": a multiplier typed with its x after the simulation
  -- ("x5" reads like a callsign no aircraft has: no aircraft named elsewhere)
  rule { "speed", "dtmult", near = { 3, "@sim" }, when = function(g, i)
    for k = i + 1, math.min(#g.t, i + 6) do
      local t = g.t[k]
      if t.kind == "word" and t.text:match("^x%d+$") then
        return not g:has_ref(1, k, "aircraft") and not g:has_ref(k + 1, #g.t + 1, "aircraft")
          and not (g:refs_in(k, k + 1, "aircraft")[1] or {}).exists
      end
    end
    return false
  end }
  -- "sim speed half", "sim speed one half", "sim speed 2": a multiplier, a fraction or a bare number straight after the sim's speed, nothing
  -- after it and no aircraft named, is the clock's rate
  rule { "speed", "dtmult", prev = { 1, "@sim" }, when = function(g, i)
    local q = g:quantities(i + 1, #g.t + 1)[1]
    local said = g:word(i + 1, "@multipliers") and i + 2 or g:fraction_said(i + 1)
      or (q and q.kind == "plain" and q.b == i + 1 and q.e)
    return said and said > #g.t and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- "back to real time, speed one": one straight after "speed", ending the request, with real time said just
  -- before and no aircraft named, is the clock's rate (another number there is asked)
  rule { "speed", "dtmult", when = function(g, i)
    local q = g:quantities(i + 1, #g.t + 1)[1]
    return q ~= nil and q.kind == "plain" and q.value == 1 and q.b == i + 1 and q.e > #g.t
      and g:preceded_by(i, 5, "real") and g:word_in(math.max(1, i - 4), i, "time")
      and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- "set the simulation speed back to normal, real time": the clock's rate back to real time (DTMULT reads the
  -- rate; "normal" alone is asked), never fast time
  rule { "speed", "dtmult", when = function(g, i)
    return g:followed_by(i, 6, "real normal") and (g:preceded_by(i, 2, "@sim") or g:followed_by(i, 3, "@sim"))
      and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- "set the simulation back to the normal, real time speed": the clock's rate named by "normal" and by "real
  -- time" straight before "speed", no aircraft: real time (DTMULT 1); "back to real time speed" alone is real
  -- time read by "real" (OP in fast time), "speed" its noun
  rule { "speed", "dtmult", prev = { 1, "time" }, when = function(g, i)
    return g:word(i - 2, "real") and g:word_in(1, #g.t + 1, "normal") and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  rule { "speed", false, prev = { 1, "time" }, when = function(g, i)
    return g:word(i - 2, "real") and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- "reduce the simulation speed to half", "set the sim speed to 0.5", "bring the speed of the simulation down to
  -- a quarter": the sim's speed (its noun, "speed of the simulation" too) set "to" a rate said as a multiplier
  -- word, a fraction or a bare number that closes its clause is the clock's rate, whatever the verb ("by half",
  -- a change from a rate squawk does not know, stays asked)
  rule { "speed", "dtmult", when = function(g, i)
    local k
    if g:word(i - 1, "@sim") then
      k = i + 1
    elseif g:word(i + 1, "of") then
      k = g:word(i + 2, "the") and i + 3 or i + 2
      if not g:word(k, "@sim") then return false end
      k = k + 1
    else
      return false
    end
    if g:word(k, "down back up") then k = k + 1 end
    if not g:word(k, "to") then return false end
    k = k + 1
    local q = g:quantities(k, #g.t + 1)[1]
    local e = g:word(k, "@multipliers") and k + 1 or g:fraction_said(k)
      or (q and q.b == k and (q.kind == "plain" or q.kind == "mult") and q.e)
    if not e then return false end
    if g:word(e, "speed times x") then e = e + 1 end
    while g:word(e, "please kindly only") or (g.t[e] and g.t[e].filler) do e = e + 1 end
    return g.t[e] == nil or g.t[e].kind == "punct"
  end }
  rule { "speed spd airspeed", "ff", near = { 3, "@sim" } }
  rule { "speed spd airspeed", "ff", next = "up", prev = { 3, "simulation sim" } }
  rule { "speed spd airspeed", "ff", prev = { 1, "simulation sim" } }
  -- "set the simulation to twice speed", "twice speed please": a multiplier word straight before "speed", no aircraft
  -- named, is the clock's rate
  rule { "speed", "dtmult", prev = { 1, "@multipliers" },
         when = function(g) return not g:has_ref(1, #g.t + 1, "aircraft") end }
  rule { "speed spd airspeed", false, prev = { 2, "half double triple quadruple" } }
  rule { "speed spd airspeed", "spd" }
  rule { "slow slower", "dtmult", near = { 3, "@sim" } }
  -- "slow everything down to half speed": the clock, when no aircraft is named
  rule { "slow", "dtmult", near = { 5, "half" }, when = function(g) return not g:has_ref(1, #g.t + 1, "aircraft") end }
  rule { "fast faster", "dtmult", prev = { 2, "twice thrice times x" } }  -- "run twice as fast"
  rule { "multiplier", "dtmult" }
  rule { "compression acceleration", "dtmult", prev = { 1, "time" } }  -- "4x time compression", "time acceleration 8"
  rule { "fast", "ff", next = "time" }  -- "run in fast time": fast time with no end is FF
  -- "run the simulation fast for 30 seconds" (not "run it and fast forward 3 minutes", "let it run. Fast forward 5
  -- minutes", "run fast forward 10 min": an instruction of its own)
  rule { "fast", false, prev = { 4, "run advance" },
         when = function(g, i)
           local apart = g:word(i - 1, "and run") or (g.t[i - 1] ~= nil and g.t[i - 1].kind == "punct")
           return not (apart and g:word(i + 1, "forward"))
         end }
  rule { "fast faster slower", "dtmult", prev = { 4, "@sim" }, not_near = { 1, "forward" } }  -- ("fast-forward": FF)
  rule { "faster slower", false, prev = { 2, "times x" } }
  -- "run faster please, 5 times", "run slower": the clock's rate, "run" straight before the comparative, with no
  -- aircraft named in the request
  rule { "faster slower", "dtmult", prev = { 1, "run" },
         when = function(g) return not g:has_ref(1, #g.t + 1, "aircraft") end }
  -- "the Shuttle is a bit slow": a description ("X is to slow down to 220 knots": the verb after "to", an instruction;
  -- "if it is possible, fast forward ...": a clause after the comma, "fast forward" the run's)
  -- ("when you're level slow to 220": the condition reached, then the verb)
  rule { "slow fast", false, prev = { 3, "is it's are was isn't" }, when = function(g, i)
    if g:word(i - 1, "to level there") then return false end
    return not (g:word(i + 1, "forward") and g.t[i - 1].kind == "punct")
  end }
  rule { "slow fast", false, prev = { 1, "a an" }, next = "one ones aircraft plane mover" }  -- "a slow one": a description
  -- "descend at 800 feet per minute? I want a slow descent": the manner of a climb or descent whose rate is said, no
  -- speed ("a slow descent to FL80" with no rate is asked, as "at a slow rate" is)
  rule { "slow fast", false, prev = { 1, "a an" }, next = "descent climb", when = function(g)
    for _, q in ipairs(g:quantities(1, #g.t + 1)) do
      if q.kind == "vs" then return true end
    end
    return false
  end }
  -- "accelerate the time four times", "decelerate the simulation": the clock's rate, said straight after the verb
  rule { "accelerate decelerate", "dtmult", when = function(g, i)
    return g:word(i + 1, "@sim") or (g:word(i + 1, "the") and g:word(i + 2, "@sim"))
  end }
  -- "accelerate 20 times", "accelerate ten times the simulation", "go faster? five times please": the clock's rate, a
  -- factor of "times" said straight after "accelerate", or within four words after "faster", with no aircraft named
  -- in the request
  rule { "accelerate", "dtmult", when = function(g, i)
    return g.t[i + 1] ~= nil and (g.t[i + 1].kind == "number" or g.t[i + 1].number_word) and g:word(i + 2, "times x")
      and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  rule { "faster", "dtmult", near = { 4, "times x" }, when = function(g) return not g:has_ref(1, #g.t + 1, "aircraft") end }
  -- ("..., when you slow to two five zero proceed direct SUMMA", "once it slows to 250 ..."): the verb of a condition's
  -- subject, what the condition waits for, no instruction
  rule { "slow slows accelerate accelerates decelerate decelerates", false, prev = { 1, "you it he she they" },
         when = function(g, i) return g:word(i - 2, "when once after") end }
  rule { "slow slower faster accelerate decelerate", "spd" }
  -- "once it's level, bump it to 280 knots", "crank it up to Mach .80": an informal verb of changing a value
  -- (lexicon.informal_value_verbs) with a speed's unit or "Mach" within five words after it is a speed; with no
  -- unit ("bump to 280") it names no value's kind and stays unread
  rule { "@informal_value_verbs", "spd", near = { 5, "@speed_units mach" } }
  -- "bump it up to times eight", "crank things up to times 4": the run ("it", "things") sped up by a factor said
  -- after "times", no aircraft named (as "speed it up to times 5")
  rule { "@informal_value_verbs", "dtmult", next = "it things", near = { 5, "times" }, when = function(g, i)
    return g:word(i + 2, "up") and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- "and give it 280 knots": a speed given to the aircraft
  rule { "give", "spd", next = "it him her them", near = { 4, "@speed_units" } }
  -- "after speed reduced to 250, descend FL100", "once the speed is reduced to 250 knots, ...": a verb of slowing
  -- whose subject is the noun "speed" after a condition word says what the instruction waits for (G:at_speed), no
  -- speed instruction of its own
  rule { "reduce reduced reduces decrease decreased decreases", false, prev = { 5, "@condition" }, when = function(g, i)
    local k = i - 1
    while k > 1 and g:word(k, "is 's has been") do k = k - 1 end
    if not g:word(k, "speed airspeed") then return false end
    return g:word(k - 1, "@condition") or (g:word(k - 1, "the his her its their") and g:word(k - 2, "@condition"))
  end }
  -- "increase the level to FL130", "reduce your level to FL070": the level named straight after the verb
  rule { "reduce increase decrease", "alt", next = "the your its his her", when = function(g, i)
    return g:word(i + 2, "level altitude")
  end }
  -- "the look-ahead should be reduced to two minutes", "the zone radius increased to 6 NM": the verb changes the
  -- setting named before it (lexicon.setting_nouns), no aircraft's speed
  rule { "reduce reduced increase increased decrease decreased", false, prev = { 4, "@setting_nouns" },
         when = function(g) return not g:has_ref(1, #g.t + 1, "aircraft") end }
  rule { "reduce increase decrease", "spd", not_near = { 4, "altitude rate vertical" } }
  -- a pilot's readback "reducing 250", "increasing to 280 knots": the participle carries its value (said
  -- right after it); with none it describes ("the gap is reducing"), no instruction
  rule { "reducing increasing decreasing slowing", "spd", not_near = { 4, "altitude rate vertical" },
         when = function(g, i)
           local q = g:quantities(i + 1, math.min(#g.t + 1, i + 4))[1]
           return q ~= nil and (q.kind == "speed" or q.kind == "mach" or q.kind == "plain")
         end }

  -- heading
  -- "it's heading into the other traffic": the aircraft's present course described, no instruction
  rule { "heading", false, prev = { 1, "it's is was are they're" } }
  rule { "heading hdg headings", "hdg" }
  -- "KLM1234 vector 270, climb FL120", "vector two seven zero, angels eight": a heading said after "vector"
  rule { "vector vectors", "hdg", when = function(g, i)
    local q = g:quantities(i + 1, math.min(#g.t + 1, i + 4))[1]
    return q ~= nil and q.b == i + 1 and (q.kind == "plain" or q.kind == "heading") and q.value <= 360
  end }
  -- "NATO01 track 090", "fly track 240", "descend FL250 and track 220": a track of three digits (up to 360) flown
  -- as a heading; a track named with a noun before it ("inbound track 270", "the tanker track") is none; so is a
  -- course ("take course 090", "fly course 240": the Russian-speaking controller's word for the heading)
  -- (said in number words, "take course three hundred": a whole number of degrees up to 360)
  rule { "track course", "hdg", not_prev = { 1, "inbound outbound the a your its tanker" }, when = function(g, i)
    local t = g.t[i + 1]
    if t ~= nil and t.kind ~= "number" and t.number_word then
      local q = g:quantities(i + 1, math.min(#g.t + 1, i + 5))[1]
      return q ~= nil and q.b == i + 1 and (q.kind == "plain" or q.kind == "heading") and q.number ~= nil
        and not q.number.decimal and q.value >= 1 and q.value <= 360
    end
    return t ~= nil and t.kind == "number" and t.text:match("^%d%d%d$") ~= nil and tonumber(t.text) <= 360
  end }
  -- "bank max 30 degrees in turns", "limit the bank to 25 when turning": when a bank limit applies, no turn
  rule { "turn turns turning", false, prev = { 2, "in when while during" }, when = function(g, i)
    for k = i - 1, math.max(1, i - 8), -1 do
      if g:word(k, "bank banking") then return true end
    end
    return false
  end }
  rule { "turn switch", false, when = function(g, i) return g:switch_follows(i) end }
  -- "turn right direct BKK", "turn left and proceed direct RIDEX": the way to turn onto a direct-to, no heading
  rule { "turn turning", false, next = "left right", when = function(g, i)
    local k = g:word(i + 2, "and then") and i + 3 or i + 2
    if g:word(k, "proceed fly") then k = k + 1 end
    return g:word(k, "direct directly dct")
  end }
  rule { "turn turning", "hdg" }
  -- "rotate BAW123 30 degrees to the left", "nudge N123AB 15 degrees left": a turn by an amount
  rule { "rotate nudge veer swing yaw", "hdg", near = { 6, "left right degrees degree" } }
  -- "rotate KLM58 to 180", "yaw to 270": a game's rotation to a heading
  rule { "rotate yaw", "hdg", next = "to", when = function(g, i) return g:number_at(i + 2) end }
  rule { "left right", "hdg", when = function(g, i)
    return g:number_at(i + 1) and not g:preceded_by(i, 2, "turn heading")
  end }
  -- "EWG7LM 10 right and climb ...", "KL204 20 degrees left": a turn by the amount said before it,
  -- straight after the callsign (never "runway 10 right")
  rule { "left right", "hdg", when = function(g, i)
    local n = g:word(i - 1, "degrees degree deg") and i - 2 or i - 1
    local t = g.t[n]
    if not t or t.kind ~= "number" or g.u:used(n) or g:word(n - 1, "runway rwy") then return false end
    for _, r in ipairs(g.refs) do
      if r.kind == "aircraft" and r.e == n then return true end
    end
    return false
  end }
  rule { "left right", "hdg", next = "by", not_prev = { 2, "turn" }, when = function(g, i) return g:number_at(i + 2) end }
  -- "come left about 30 degrees", "bring it right by roughly 20 degrees", "come right about 20, climb FL250": a side
  -- and a number said loosely (lexicon.value_hedges) with "degrees" or nothing after it (its clause ends there) is
  -- the turn as the number said bare ("come right 20")
  rule { "left right", "hdg", not_prev = { 2, "turn heading" }, when = function(g, i)
    local k = g:word(i + 1, "by") and i + 2 or i + 1
    local after = g.t[k + 2]
    return g:word(k, "@value_hedges") and g:number_at(k + 1)
      and (after == nil or after.kind == "punct" or g:word(k + 2, "degrees degree deg and then"))
  end }
  rule { "left right", "hdg", next = "onto", when = function(g, i) return g:number_at(i + 2) end }  -- "round left onto 290"
  -- "come right to three six zero, climb FL120", "bring it left to 250": a side, "to" and a number is the heading to
  -- turn to that way ("left to zero degrees": degrees after it, a recogniser's "two" as likely)
  rule { "left right", "hdg", next = "to", not_prev = { 2, "turn heading" },
         when = function(g, i) return g:number_at(i + 2) and not g:word(i + 3, "degrees degree deg") end }
  rule { "point fly towards toward head send steer face facing", "hdg", near = { 4, "@compass" } }
  -- "fly towards Kempten", "turn the Lufthansa towards the Innsbruck airport", "fly in the direction of
  -- STUDYB": the heading that points at a place (HDG's name: the bearing to it)
  local function toward_place(g, i)
    local e = math.min(#g.t + 1, i + 6)
    local k = g:find_word(i + 1, e, "towards toward direction")
    return k < e and (not g:word(k, "direction") or g:word(k + 1, "of")) and not g:intent_at(k)
  end
  rule { "fly flies turn head steer", "hdg", when = toward_place }
  -- ("fly a heading directly towards the ZUE VOR": "directly" the manner of a heading said toward a place, no
  -- direct-to of its own)
  rule { "directly", false, next = "towards toward", prev = { 2, "heading" } }
  -- "point JST501 to 200 degrees", "point it onto 090 degrees": an aircraft pointed at a number of degrees
  rule { "point", "hdg", when = function(g, i)
    local r = g:refs_in(i + 1, math.min(#g.t + 1, i + 2), "aircraft")[1]
    local k = r and r.e or (g:word(i + 1, "it") and i + 2)
    return k and g:word(k, "to onto") and g:number_at(k + 1) and g:word(k + 2, "degrees degree deg") or false
  end }
  rule { "due", "hdg", next = "@compass" }
  rule { "go turn", "hdg", next = "@compass" }
  rule { "left right", "hdg", prev = { 1, "go bear then" } }  -- "go left then climb", "speed 250, then left": a turn
  -- "maintain 280 knots until PEKIR then 250", "maintain FL160 until PEKIR then FL120": a value of the limited
  -- instruction's kind said bare after "until" a place "then" is that instruction again, from the place
  -- (G:until_then_value)
  rule { "then @until_then_words", "spd", when = function(g, i) return g:until_then_value(i) == "spd" end }
  rule { "then @until_then_words", "alt", when = function(g, i) return g:until_then_value(i) == "alt" end }
  -- "reduce Mach .74, then 280 knots when passing FL200": a speed with its unit said bare after "then" and before a
  -- condition, a speed instruction with its value before it, is that instruction again, waiting for the condition
  -- (G:speed_then_conditioned)
  rule { "then", "spd", when = function(g, i) return g:speed_then_conditioned(i) end }
  -- "reduce speed 250, after SUMAG 220": the same, after a place (G:after_place_value)
  rule { "after", "spd", when = function(g, i) return g:after_place_value(i) == "spd" end }
  rule { "after", "alt", when = function(g, i) return g:after_place_value(i) == "alt" end }
  rule { "@compass", "hdg", prev = { 1, "then" } }  -- "go up to FL320, then east"  -- "go east", "go northeast": the heading of that point
  rule { "around", false, prev = { 3, "turn" } }

  -- conflict resolution in the vertical ("let MVP use vertical speed in the resolutions", "keep
  -- resolutions horizontal only, no vertical"): RMETHV, never a vertical speed or a new method
  rule { "vertical horizontal lateral", "rmethv", when = function(g, i) return g:vertical_resolutions(i) end }
  -- vertical speed and bank
  rule { "sink", "alt", near = { 3, "level fl flight feet ft" } }  -- "sink to flight level 120"
  rule { "vs sink expedite", "vs" }
  rule { "vertical", "vs", next = "speed rate" }
  -- "go vertical 1200 up": a game's vertical speed, its sign said after the value
  rule { "vertical", "vs", prev = { 1, "go" }, when = function(g, i)
    return g:number_at(i + 1) and g:word(i + 2, "up down")
  end }
  rule { "rate", "dtmult", prev = { 2, "@sim" } }  -- "the simulation rate"
  -- "tick rate 20 hz", "the sim's update rate": a game loop's rate, the simulation's time step (DT)
  rule { "rate", false, prev = { 1, "tick update frame" } }
  rule { "tick update", "dt", next = "rate" }
  rule { "tickrate", "dt" }
  rule { "rate", "vs", not_prev = { 1, "vertical" } }
  -- "bank left to heading 200", "bank KLM12 to heading 045": a turn to the heading said (the bank is how), no
  -- bank limit
  rule { "bank banking", "hdg", when = function(g, i)
    local r = g:refs_in(i + 1, math.min(#g.t + 1, i + 2), "aircraft")[1]
    local k = r and r.e or i + 1
    if g:word(k, "@left @right") then k = k + 1 end
    if g:word(k, "to onto") then k = k + 1 end
    return g:word(k, "heading hdg")
  end }
  rule { "bank banking", "bank" }

  -- waypoints, creation and deletion
  -- ("it's spawned in the wrong place": the noun, no verb of placing)
  rule { "place", false, prev = { 1, "wrong right" } }
  rule { "define make put draw", false, near = { 2, "box circle circular polygon poly line" } }  -- the shape's word starts it
  -- ("create a wind at 53.5 north 6 west ...", "define a wind profile at ...": the wind's own word reads it)
  rule { "create define make", false, when = function(g, i)
    local k = g:skip_fillers(i + 1)
    while g:word(k, "a an the new") do k = k + 1 end
    return g:word(k, "wind winds")
  end }
  rule { "define defwpt", "defwpt" }
  rule { "def", "defwpt", next = "@waypoint_nouns" }  -- "def wp XIT2 at 51.25N 004.10E" typed short
  -- "put a waypoint called TEST1 at 52.3 north 4.7 east", "waypoint TEST1 at 52.3N 4.7E": a new
  -- waypoint at a position, when no aircraft that flies and no aircraft type is named
  local function new_fix_at(g, i, span)
    if g:has_ref(1, #g.t + 1, "type") then return false end
    for _, r in ipairs(g:refs_in(1, #g.t + 1, "aircraft")) do
      if r.exists then return false end
    end
    for _, q in ipairs(g:quantities(i + 1, math.min(#g.t + 1, i + (span or 8)))) do
      if q.kind == "lat" or q.kind == "lon" or (q.kind == "plain" and q.number.decimal) then return true end
    end
    return false
  end
  rule { "put place create make add", "defwpt", near = { 2, "@waypoint_nouns" }, when = new_fix_at }
  -- ("create the point EXP1 at 35 north 139.6 east and add it to JAL316's route", "make a point GATE2 at 52.1 4.3,
  -- then ..."): "point" and a new name straight after the verb, a position after "at", no aircraft type said (an
  -- aircraft that flies may be named for the route the point then joins)
  -- ("go to the point EXP1, which is at 35 north 139.6 east. Please make this point first": the point named before
  -- with its position, G:point_said_before)
  rule { "create make", "defwpt", next = "this that", when = function(g, i)
    return g:word(i + 2, "point waypoint fix") and g:point_said_before(i) ~= nil
  end }
  -- ("add a point EX3 at 51.05 -0.45", "put a point ...": the same with a verb of adding)
  -- ("make a point called MYPT at 50.2 8.9": its name after "called" or "named")
  rule { "create make add put place", "defwpt", when = function(g, i)
    local k = g:word(i + 1, "the a an") and i + 2 or i + 1
    if not g:word(k, "point") or g:has_ref(1, #g.t + 1, "type") then return false end
    if g:word(k + 1, "called named") then k = k + 1 end
    local r = g:refs_in(k + 1, k + 2, "waypoint")[1] or g:refs_in(k + 1, k + 2, "aircraft")[1]
    if not r or r.b ~= k + 1 or r.exists or not g:word(r.e, "at") then return false end
    local q = g:quantities(r.e + 1, r.e + 2)[1]
    return q ~= nil and (q.kind == "lat" or (q.kind == "plain" and (g:quantities(q.e, q.e + 1)[1] or {}).kind == "lon")
      or (q.kind == "plain" and q.number.decimal))
  end }
  rule { "waypoint wpt waypoints", "defwpt", not_prev = { 3, "put place create make add define" }, when = new_fix_at }
  -- "new fix IAFN1 at 48.50 N 16.20 E", "a reference point called CENTRE at 52.0N, 3.75E", "the target point
  -- for trial three, call it TGT3, 42.1 N 88.2 W", "place the new southern entry ENTRX at ...": a fix or point
  -- (an airspace design's gate, entry or exit) said new, or named, at a position
  rule { "fix point gate entry exit", "defwpt", not_prev = { 3, "put place create make add define" }, when = function(g, i)
    return (g:preceded_by(i, 3, "new reference target") or g:followed_by(i, 2, "@named")) and new_fix_at(g, i)
  end }
  -- ("put a new waypoint in called GEELO at 38 10 south 144 21 east": a waypoint said new, likewise; "make new
  -- point tango five at ...", the article left out)
  rule { "put place create make add", "defwpt", when = function(g, i)
    local n = g:word(i + 1, "the a an") and i + 2 or i + 1
    return g:word(n, "new")
      and g:followed_by(n, 4, "fix point gate entry exit @waypoint_nouns")
      and new_fix_at(g, i, 11)
  end }
  -- "add a waypoint called ENTRY at 52 N 3.5 E": a new waypoint, when no flying aircraft is named
  rule { "add", "defwpt", near = { 2, "@waypoint_nouns" }, when = function(g, i)
    if not g:followed_by(i, 4, "@named") then return false end
    for _, r in ipairs(g.refs) do
      if r.kind == "aircraft" and r.exists then return false end
    end
    return true
  end }
  rule { "addwpt", "addwpt" }
  rule { "delwpt", "delwpt" }
  rule { "create make", "defwpt", near = { 3, "fix waypoint wpt" } }
  rule { "create", false, prev = { 1, "re" } }  -- "we'll re-create it later"
  -- "create a circle area TMA1 centred at ...", "create a box ...": a shape made, no aircraft (the shape's
  -- own word reads it)
  rule { "create", false, when = function(g, i)
    local k = g:skip_fillers(i + 1)
    while g:word(k, "a an the new") do k = k + 1 end
    return g:word(k, "circle circular box")
  end }
  -- "To create a same-level encounter: SAS1410 climb FL190": the purpose of what follows the colon or comma
  rule { "create set", false, prev = { 1, "to" }, when = function(g, i)
    if g:skip_fillers(1) ~= i - 1 then return false end
    for k = i + 1, math.min(#g.t, i + 6) do
      if g.t[k].kind == "punct" and (g.t[k].text == ":" or g.t[k].text == ",") then
        return #g:refs_in(i + 1, k, "aircraft") == 0 and #g:refs_in(i + 1, k, "type") == 0
      end
    end
    return false
  end }
  -- True when no aircraft type and no new callsign are said after i, and an instruction word and an aircraft
  -- flying before it
  local function after_instruction_no_new(g, i)
    if g:has_ref(i + 1, #g.t + 1, "type") then return false end
    local named = false
    for _, r in ipairs(g.refs) do
      if r.kind == "aircraft" and not r.exists and r.b > i then return false end
      named = named or (r.kind == "aircraft" and r.exists and r.b < i)
    end
    for x = 1, named and i - 1 or 0 do
      if g:intent_at(x) then return true end
    end
    return false
  end
  -- ("turn KLM12 right 20, to create a crossing with the SAS", "... I'm hoping to create a conflict", "that should
  -- be enough to make the conflict a near miss"): an encounter made, said as a purpose ("to" or a modal before the
  -- verb) after an instruction to traffic flying, is what the instruction brings about, no creation, unless a
  -- type or a new callsign is said after it (CRECONFS); "and create a conflict" is still a creation
  rule { "create make", false, when = function(g, i)
    if not (g:word(i - 1, "to") or g:word_in(math.max(1, i - 4), i, "@purpose_modals")) then return false end
    local k = g:skip_fillers(i + 1)
    while k < i + 4 and not g:word(k, "@encounters_made") and g.t[k] and g.t[k].kind == "word" do k = k + 1 end
    return g:word(k, "@encounters_made") and after_instruction_no_new(g, i)
  end }
  -- ("that should make it a difficult aircraft to track"): an aircraft flying made into something after an
  -- instruction to it, no creation
  rule { "make", false, next = "it him her them", when = function(g, i)
    return g:word(i + 2, "@articles_new") and after_instruction_no_new(g, i)
  end }
  -- ("put a new plane over JFK: call it DAL100, make it an Airbus A330-300, ..."): the type of the aircraft being
  -- created, a field of that creation, no creation of its own
  rule { "make", false, next = "it", when = function(g, i)
    return g:word(i + 2, "a an") and g:has_ref(i + 3, math.min(#g.t + 1, i + 6), "type")
      and g:word_in(1, i, "new") and g:word_in(1, i, "call called callsign named")
  end }
  -- "create ten random aircraft", "five random A320s at FL300": random traffic
  rule { "generate generator", false, prev = { 1, "random number" } }  -- "seed the random generator with 42"
  -- ("seed the generator with 7": the noun, the seed's, no creation)
  rule { "generate generator", false, prev = { 1, "the" }, when = function(g) return g:said("seed") end }
  rule { "create cre spawn generate add chuck", "mcre", near = { 3, "random" } }
  rule { "mcre", "mcre" }
  -- "random traffic, 20 aircraft", "random traffic, 12 b738": the count said after, of aircraft or of a type
  rule { "random", "mcre", next = "traffic", when = function(g, i)
    for k = i + 2, math.min(#g.t, i + 5) do
      if g.t[k].kind == "number" and (g:word(k + 1, "@counted_aircraft") or g:has_ref(k + 1, k + 2, "type")) then
        return true
      end
    end
    return false
  end }
  rule { "random", "mcre", when = function(g, i)
    local t = g.t[g:word(i - 1, "@more") and i - 2 or i - 1]  -- ("3 more random ones")
    return t ~= nil and (t.number_word or tonumber(t.text) ~= nil) and not g:followed_by(i, 2, "seed")
  end }
  -- "spawn a conflict for KL204: INT1, A320, 90 deg off its track, cpa 0, los in 200 s", "make an intruder
  -- called TEST1 ... head-on, passing 1 mile, LoS after 4 minutes": an intruder set up to conflict
  -- ("put an intruder 20 nm ahead of KLM12 head-on", "intruder INT4 dead behind KL001 at 15 nm": placed
  -- at a distance along an aircraft's track, the intruder is a creation, CRE)
  local function along_track(g)
    for _, q in ipairs(g:quantities(1, #g.t + 1)) do
      if q.kind == "dist" and (g:word(q.e, "@along_track") or g:word(q.e, "in") and g:word(q.e + 1, "front")
          or g:word(q.b - 1, "at") and g:word_in(math.max(1, q.b - 5), q.b, "@along_track")) then
        return true
      end
    end
    return false
  end
  rule { "create spawn generate creat cre make new add put", "creconfs", when = function(g, i)
    return g:followed_by(i, 4, "@intruder")
      and g:word_in(i + 1, #g.t + 1, "@loss_of_separation @closest_approach @head_on") and not along_track(g)
  end }
  -- "for PGT8YK one intruder create: INT02, B738, 45 degrees, CPA 1 NM, 300 seconds": the verb straight after the
  -- noun (verb-final order), its values after it
  rule { "create spawn generate creat make add put", "creconfs", when = function(g, i)
    return g:word(i - 1, "@intruder") and g:word_in(i + 1, #g.t + 1, "@loss_of_separation @closest_approach @head_on")
      and not along_track(g)
  end }
  rule { "intruder", "create", when = along_track }
  -- ("INT3: A320, 40 nm ahead of the ownship KL001, ...": a new callsign and a type, no other creation word)
  rule { "ahead behind", "create", when = function(g, i)
    if not along_track(g) or not g:has_ref(1, #g.t + 1, "type") then return false end
    for k = 1, i - 1 do if g:intent_at(k) == "create" then return false end end
    for _, r in ipairs(g.refs) do if r.kind == "aircraft" and not r.exists then return true end end
    return false
  end }
  -- ("opposite heading", "same track": the new aircraft's course against the one it is placed by, no turn)
  rule { "heading hdg direction track course", false, prev = { 1, "same opposite reciprocal" }, when = along_track }
  -- "intruder on IBE2604: INT1, B738, from the right, CPA 0, 250 s", "give TAP123 a head-on intruder, INT2,
  -- B738, CPA 2 miles", "conflict on KL001: INT2, A320, 135 deg, cpa 2, tlosh 500": the noun alone, no verb of
  -- creation before it, sets one up when its type and closest approach or loss are said
  rule { "creconfs", "creconfs" }  -- the command's name typed with its values in words ("creconfs INT1 B738 EZY45 dpsi 180 ...")
  -- ("the experiment requires a crossing conflict: please create a conflicting aircraft, ...": the noun naming what
  -- a creation of an intruder said after it sets up, no conflict of its own)
  local function intruder_created_after(g, i)
    -- ("one intruder create: ...": the verb straight after the noun)
    if g:word(i + 1, "create spawn generate creat make add put") and g:word(i, "@intruder") then return true end
    for k = i + 1, #g.t do
      if g:word(k, "create spawn generate creat cre make new add put") and g:followed_by(k, 4, "@intruder") then
        return true
      end
    end
    return false
  end
  rule { "intruder conflict conflicting converger", "creconfs", when = function(g, i)
    return g:find_word(1, #g.t + 1, "intruder conflict conflicting converger") == i  -- (the first one said)
      and not intruder_created_after(g, i)
      and not g:word_in(1, i, "create spawn generate creat cre make new add put") and g:has_ref(i + 1, #g.t + 1, "type")
      and g:word_in(i + 1, #g.t + 1, "@loss_of_separation @closest_approach @head_on") and not along_track(g)
      -- ("conflict pair: CRECONFS INT9 ...": the command's name said after the noun sets the conflict up)
      and not g:word_in(i + 1, #g.t + 1, "creconfs")
  end }
  -- "spawn 3 aircraft", "generate 5 aircraft at FL300, type B738", "sample 8 planes", "create ten aircraft",
  -- "spawn twenty five jets", "create ten A320": a count of aircraft (in digits or in words, a whole number from 2) with no
  -- callsign is random traffic ("create two aircraft: KLM11 ..., and KLM12 ...": the count of the new callsigns
  -- said after it, no random traffic)
  -- ("add 3 more A320s", "make five more a320s": "more" between the count and what is counted)
  rule { "create spawn generate add sample make", "mcre", when = function(g, i)
    local k = g:skip_fillers(i + 1)
    local t = g.t[k]
    local ty = g:word(k + 1, "more") and k + 2 or k + 1
    if t ~= nil and t.kind == "number" and g:word(ty, "@counted_aircraft") then return true end
    -- ("spawn 12 b738 at fl250 280kt": a count of 2 or more typed straight before a type, no new callsign said)
    if t ~= nil and t.kind == "number" and t.num and t.num >= 2 and t.num <= 500 and t.num % 1 == 0
        and g:has_ref(ty, ty + 1, "type") then
      for _, r in ipairs(g:refs_in(1, #g.t + 1, "aircraft")) do
        if not r.exists then return false end
      end
      return true
    end
    -- ("create ten A320 at level three hundred": a count in words before a type too)
    local q = t ~= nil and t.number_word and g:quantities(k, k + 4)[1]
    ty = q and (g:word(q.e, "more") and q.e + 1 or q.e)
    if not (q and q.b == k and q.kind == "plain" and not q.number.decimal and q.value >= 2
        and (g:word(ty, "@counted_aircraft") or (q.value <= 500 and g:has_ref(ty, ty + 1, "type")))) then
      return false
    end
    for _, r in ipairs(g:refs_in(q.e + 1, #g.t + 1, "aircraft")) do
      if not r.exists then return false end
    end
    return true
  end }
  -- "seed 42, 20 acft, cd on", "seed 42 and 10 aircraft please": a count of aircraft in a clause of its own (first
  -- in the request, or after a comma or "and") in a request that sets the random seed is random traffic of that
  -- count; nothing else said in its clause
  rule { "aircraft planes flights", "mcre", when = function(g, i)
    local t, before = g.t[i - 1], g.t[i - 2]
    if not (t and t.kind == "number" and t.num and t.num >= 1 and t.num <= 500 and t.num % 1 == 0) then return false end
    if before and not (before.kind == "punct" and before.text ~= "." or g:word(i - 2, "and")) then return false end
    local nx = g.t[i + 1]
    if nx and not (nx.kind == "punct" or g:word(i + 1, "please pls and then")) then return false end
    return g:word_in(1, #g.t + 1, "seed")
  end }
  -- ("creating N48TX, PC12, ..."; "set the seed before creating anything" names no creation)
  rule { "creating spawning", false, prev = { 1, "before after without" } }
  -- "delete WZZ61B, it's spawned in the wrong place", "it was created too close": how an aircraft came to be,
  -- a reason, no creation
  rule { "spawn spawned create created generate generated", false, when = function(g, i)
    return g.t[i].raw:lower():match("ed$") ~= nil and g:word_in(math.max(1, i - 2), i, "it's it was were been is are s")
  end }
  -- "crea AZA612, A321, at ...": the verb in the speaker's language (Italian, Spanish, French, German), read as
  -- a creation only with an aircraft type said after it and no aircraft of the scene named
  rule { "crea crear creer erstelle erstellen", "create", when = function(g, i)
    if not g:has_ref(i + 1, #g.t + 1, "type") then return false end
    for _, r in ipairs(g:refs_in(i + 1, #g.t + 1, "aircraft")) do if r.exists then return false end end
    return true
  end }
  rule { "create spawn generate creat cre creating spawning", "create" }
  -- "Air Seoul 8501 make, A321, at ...": "make" straight after a callsign no aircraft has (verb-final order, as
  -- Korean says it), a pause or "please" after it and an aircraft type said after
  rule { "make", "create", when = function(g, i)
    if not (g.t[i + 1] and (g.t[i + 1].kind == "punct" or g:word(i + 1, "please"))) then return false end
    local new = false
    for _, r in ipairs(g:refs_in(1, i, "aircraft")) do new = new or (r.e == i and g:new_callsign(r)) end
    return new and g:has_ref(i + 1, #g.t + 1, "type")
  end }
  rule { "pop", "mcre", next = "up", near = { 4, "random" } }  -- "pop up ten random aircraft"
  rule { "pop", "create", next = "up" }  -- "pop up DAL88 B752 ..."
  -- "define a new waypoint called WP9", "define a new point ENT2 at ...": the new fix's noun after it
  rule { "new", false, next = "@waypoint_nouns point gate entry exit" }
  -- ("define a new training point, TRN3, at ...", "a new reporting point": one word describing the fix between)
  rule { "new", false, when = function(g, i)
    return g:word(i + 2, "@waypoint_nouns point gate") and g.t[i + 1].kind == "word" and not g:has_ref(i + 1, i + 2)
  end }
  -- ("creconfs: new one TVF88AB, B738, target AFR6204, ...": the new aircraft of a conflict set up before it is
  -- its intruder, no creation of its own)
  rule { "new", false, when = function(g, i)
    for k = 1, i - 1 do if g:intent_at(k) == "creconfs" then return true end end
    return false
  end }
  rule { "new", "create", when = function(g, i) return g:type_or_aircraft_word(i + 1, i + 3) end }
  -- "new target: Jazz 7310, DH8D, ...": a radar target, when a new callsign or a type follows ("new target
  -- altitude" is no aircraft)
  rule { "new", "create", next = "target", when = function(g, i) return g:new_aircraft_follows(i + 1) end }
  rule { "add append insert give", "addwpt", near = { 4, "@waypoint_nouns" } }
  -- "append 52.6, 4.2 as a waypoint for EZY45": a position added as a waypoint of an aircraft's
  rule { "add append insert", "addwpt", near = { 8, "@waypoint_nouns" }, when = function(g, i)
    return g:word_in(i + 1, math.min(#g.t + 1, i + 8), "as") and g:has_ref(i + 1, #g.t + 1, "aircraft")
  end }
  -- "proceed direct HONIE, cross HONIE at 14000", "cross CAMRN at and maintain FL190": a crossing
  -- restriction (G:at_waypoint) is an instruction of its own wherever it is said in the line
  rule { "cross crossing", "maintain", when = function(g, i)
    local r = g:refs_in(i + 1, i + 2, "waypoint")[1]
    return (r ~= nil and g:word(g:skip_fillers(r.e), "at")) or g:crossed_navaid(i) ~= nil
  end }
  -- "cross two zero miles from Toronto at one one thousand", "cross 15 miles north of SEA at 10000": a crossing
  -- restriction at a distance from a place, its level or speed said after "at" (handlers' at_distance: ATDIST)
  rule { "cross crossing", "maintain", when = function(g, i)
    local q = g:quantities(i + 1, #g.t + 1)[1]
    if not q or q.kind ~= "dist" or q.b ~= g:skip_fillers(i + 1) then return false end
    local k = q.e
    while k < q.e + 2 and g:word(k, "@compass") do k = k + 1 end  -- ("south east of")
    return g:word(k, "from of") and g:word_in(k + 1, #g.t + 1, "at")
  end }
  -- "put a constraint on AEA44 at ORBIS, FL250": a constraint at a waypoint (G:at_waypoint), no move
  rule { "put set", false, near = { 3, "constraint constraints restriction restrictions" } }
  -- ("add an altitude constraint of FL80 at MAGAT": the same, no aircraft or waypoint added)
  rule { "add", false, near = { 3, "constraint constraints restriction restrictions" } }
  -- ("append the Siedlce VOR SIE at the end of the route of LOT3CM": the route noun ten words on)
  rule { "add append insert give put", "addwpt", near = { 10, "@route_nouns" },
         when = function(g, i) return g:has_ref(i + 1, i + 9, "waypoint") end }
  -- ("add bolty to the end of rex two seven four one's route": the waypoint straight after the verb, an aircraft
  -- named after it, a callsign said digit by digit putting the route noun up to fourteen words on)
  rule { "add append insert put", "addwpt", near = { 14, "@route_nouns" },
         when = function(g, i) return g:has_ref(i + 1, i + 2, "waypoint") and g:has_ref(i + 2, i + 14, "aircraft") end }
  rule { "add append insert give", "addwpt", next = "it", near = { 8, "@route_nouns" } }
  -- "add to the route of the Nile Air one zero seven the waypoint LUBOS": the route's owner named before the
  -- waypoint (a callsign said in words may be long); the waypoint, its noun or not, straight after the aircraft
  -- ("add, to the route of ANA65, the fix OCEAN and then HATSU": the owner's phrase set apart by commas)
  rule { "add append insert", "addwpt", when = function(g, i)
    local comma = g.t[i + 1] ~= nil and g.t[i + 1].kind == "punct" and g.t[i + 1].text == ","
    local to = comma and i + 2 or i + 1
    if not g:word(to, "to") then return false end
    local k = g:word(to + 1, "the his its") and to + 2 or to + 1
    if not (g:word(k, "@route_nouns") and g:word(k + 1, "of")) then return false end
    local a = g:refs_in(k + 2, #g.t + 1, "aircraft")[1]
    if not a or a.b > g:skip_fillers(k + 2) + 1 then return false end
    local x = a.e
    if comma and g.t[x] and g.t[x].kind == "punct" and g.t[x].text == "," then x = x + 1 end
    if g:word(x, "the a") then x = x + 1 end
    if g:word(x, "@waypoint_nouns point") then x = x + 1 end
    return g:has_ref(x, x + 1, "waypoint")
  end }
  -- "stick KMCO on the end of Frontier 2231's route", "tack FLYNN onto the end of its route": a waypoint
  -- straight after the verb, put at the route's end (not "stick to the route", which adds nothing)
  -- ("stick our ARTHR point on the end of the easyJet's route": the waypoint after a possessive, "point" after it)
  rule { "stick tack", "addwpt", near = { 10, "@route_nouns" }, when = function(g, i)
    local k = g:word(i + 1, "our my the") and i + 2 or i + 1
    return g:has_ref(k, k + 1, "waypoint") and g:word_in(k + 1, k + 5, "end")
  end }
  -- "add Lambourne to the end of the Air France's route", "add glen rose to skywest 4420's route", "put Wallasey
  -- in the route": a navaid or airport said by its name of one or two words
  rule { "add append insert put", "addwpt", near = { 10, "@route_nouns" }, when = function(g, i)
    local to = g:word(i, "put") and "in into on onto" or "to"
    return (g:word(i + 2, to) and g:place_by_name(i + 1, i + 2) ~= nil)
      or (g:word(i + 3, to) and g:place_by_name(i + 1, i + 3) ~= nil)
  end }
  -- "add mike november alpha to the route": a place spelled in the phonetic alphabet, two letters or more, straight
  -- after the verb and before "to"/"at"/"onto" (the handler reads the letters as a known ident, else asks)
  rule { "add append insert", "addwpt", near = { 10, "@route_nouns" }, when = function(g, i)
    local k = i + 1
    while g.t[k] and g.t[k].kind == "word" and PHONETIC[g.t[k].text] do k = k + 1 end
    return k >= i + 3 and g:word(k, "to at onto")
  end }
  -- "ORKAN add to the end of its route", "waypoint LAVTA add at end of route", "SARIZ add between CPX1 and CPX2":
  -- the verb after the waypoint (verb-final order), a route noun or "between"/"after"/"before" and a waypoint
  -- after it
  rule { "add append insert", "addwpt", when = function(g, i) return g:verb_final_waypoint(i) ~= nil end }
  -- "Add for Astanaline 929 the point PIGOR before destination", "add TIRBA before its destination": a waypoint
  -- straight before "before" and the destination, the verb's within a clause
  rule { "add append insert", "addwpt", when = function(g, i)
    local d = g:find_word(i + 1, math.min(#g.t + 1, i + 12), "destination")
    if d >= math.min(#g.t + 1, i + 12) then return false end
    local k = g:word(d - 1, "the its his her their") and d - 2 or d - 1
    if not g:word(k, "before") then return false end
    local w = g:refs_in(i + 1, k, "waypoint")
    return w[#w] ~= nil and w[#w].e == k
  end }
  -- "add the point EXIT2": a point that is a known waypoint
  rule { "add append insert", "addwpt", near = { 3, "point" },
         when = function(g, i) return g:has_ref(g:find_word(i + 1, i + 4, "point") + 1, i + 5, "waypoint") end }
  -- "add point 40.45,-3.55 to RYR8WH's route": a point given by its latitude and longitude in decimal degrees
  -- (a pair typed with a comma, or two numbers), a route noun after it
  rule { "add append insert", "addwpt", near = { 3, "point" }, when = function(g, i)
    local k = g:find_word(i + 1, i + 4, "point") + 1
    local t, u = g.t[k], g.t[k + 1]
    local pair = t and (t.text:match("^%-?%d+%.%d+,%-?%d+%.%d+$")
      or (t.text:match("^%-?%d+%.%d+$") and u and u.text:match("^%-?%d+%.%d+$")))
    return pair ~= nil and g:word_in(k + 1, math.min(#g.t + 1, k + 8), "@route_nouns")
  end }
  rule { "via through", "addwpt", prev = { 3, "route" } }
  -- ("give DAL881 a route: direct OBK, then DPA, then JOT" to an aircraft with no route: the list's first place,
  -- flown direct as the first waypoint of a route is, no direct-to of its own)
  local function route_list_direct(g, i)
    if not (g:word(i, "direct dct") and g.t[i - 1] and g.t[i - 1].text == ":" and g:word(i - 2, "route rte")
        and g:has_ref(i + 1, i + 2, "waypoint")) then
      return false
    end
    local refs = g:refs_in(1, i, "aircraft")
    local a = refs[#refs] and refs[#refs].exists and g:state(refs[#refs].name)
    if not a then return false end
    return #(a.route or {}) == 0
  end
  rule { "direct dct", false, when = route_list_direct }
  -- ("direct St. Gallen airport as destination", "direct LSZH as its destination", one aircraft named before it, of no
  -- route: the place set as the destination (DEST, which flies there itself when the route is empty), no direct-to
  -- of its own; five words at most between)
  rule { "direct dct", false, when = function(g, i)
    for k = i + 2, math.min(#g.t, i + 6) do
      if g.t[k].kind == "punct" and g.t[k].text ~= "." then return false end
      if g:word(k, "as") then
        local d = g:word(k + 1, "its the") and k + 2 or k + 1
        if not g:word(d, "destination") then return false end
        local refs = g:refs_in(1, i, "aircraft")
        local a = #refs == 1 and refs[1].exists and g:state(refs[1].name)
        return a and #(a.route or {}) == 0 or false
      end
    end
    return false
  end }
  -- "EZY45 route: SPY, BERGI", "route for UAL9: BEDUM, EEL, then ARTIP": a route written as a list
  rule { "route rte", "addwpt", when = function(g, i)
    local k = i + 1
    if g:word(k, "for of") and g:has_ref(k + 1, k + 2, "aircraft") then k = g:refs_in(k + 1, k + 2, "aircraft")[1].e end
    -- ("route AFR1234: BUSIL MADOT MTL": the aircraft straight after the word)
    if g:has_ref(k, k + 1, "aircraft") then k = g:refs_in(k, k + 1, "aircraft")[1].e end
    local t = g.t[k]
    -- (names taken back by a self-correction are skipped: "route: TWEED, then GRICE... no, just TWEED")
    local n = k + 1
    while g.t[n] and g.u:used(n) and g.noted[n] do n = n + 1 end
    if route_list_direct(g, n) then n = n + 1 end
    return t ~= nil and t.kind == "punct" and t.text == ":" and g:has_ref(n, n + 1, "waypoint")
  end }
  -- "VLG2211 route MERGE then ABRIX", "IBE3421: wpt PPG then GIROM": a route or waypoint word straight after
  -- an aircraft that flies (a colon between or none) and straight before a known place
  -- "AAR731 waypoint LOTUS delete": the verb said after its object (verb-final order) takes the
  -- waypoint off the route; the noun before it adds nothing
  rule { "route rte wpt wp wpts waypoint waypoints", false, when = function(g, i)
    return g:followed_by(i, 4, "delete remove del drop erase clear")
  end }
  rule { "route rte wpt wp wpts waypoint waypoints", "addwpt", when = function(g, i)
    local b = (g.t[i - 1] or {}).text == ":" and i - 1 or i
    local flying = false
    for _, r in ipairs(g:refs_in(1, b, "aircraft")) do flying = flying or (r.e == b and r.exists and r) end
    if not (flying and g:has_ref(i + 1, i + 2, "waypoint")) then return false end
    -- ("KAL1114 route SEL, after that Gimpo destination": the one waypoint said that its route already holds, no
    -- adding word in its clause, tells the route flown; nothing is added)
    local a = g:state(flying.name)
    local wp = g:refs_in(i + 1, i + 2, "waypoint")[1]
    local e = wp.e
    while g.t[e] and g.t[e].kind ~= "punct" do e = e + 1 end
    if a and #g:refs_in(i + 1, e, "waypoint") == 1 and not g:word_in(i + 1, e, "add append insert addwpt via then") then
      for _, w in ipairs(a.route or {}) do
        if type(w) == "table" and (w.name or w.id or ""):upper() == wp.name:upper() or type(w) == "string" and w:upper() == wp.name:upper() then
          return false
        end
      end
    end
    return true
  end }
  -- "its route, NOPIK add please", "route end, CJU add", "route, KWA, MKP, CJU add please": the route named first
  -- (Korean topic-first order), set apart by a comma, after a flying aircraft ("its"/"the" and a comma between
  -- or none), then the waypoints (commas or "and" between) and the verb closing them
  rule { "route rte", "addwpt", when = function(g, i) return g:route_topic_first(i) end }
  -- "set the Air France to fly via MAKIL at FL280 and 260 knots": a waypoint flown via is added to the route
  rule { "via", "addwpt", prev = { 2, "fly go" }, when = function(g, i) return g:has_ref(i + 1, i + 2, "waypoint") end }
  -- "Ryanair 82QT via ENTRY1 and EXIT1, destination Dusseldorf": "via" straight after the callsign that opens the
  -- request, before a waypoint, routes it there (the verb left out)
  rule { "via", "addwpt", when = function(g, i)
    local r = g:refs_in(1, i, "aircraft")[1]
    return r ~= nil and r.exists and g:skip_fillers(r.e) == i and g:skip_fillers(1) == r.b
      and g:has_ref(i + 1, i + 2, "waypoint")
  end }
  -- ("could the SAS be routed via TEB and then ARS", "KLM12 to be rerouted via SPY": the passive of route after "be",
  -- a request; "SWR72 was routed via CPA1", "both are routed via ODINA" tell the route flown, nothing added)
  rule { "via", "addwpt", prev = { 1, "routed rerouted" }, when = function(g, i)
    return g:word(i - 2, "be") and g:has_ref(i + 1, i + 2, "waypoint")
  end }
  -- "the Swiss should fly over ALGOI then KPT, please add these to its route", "fly over the Walda VOR, WLD,
  -- could you add this": the places flown over, added where the request asks for them to be added
  rule { "over", "addwpt", prev = { 2, "fly go" }, when = function(g, i)
    return g:has_ref(i + 1, math.min(#g.t + 1, i + 6), "waypoint") and g:word_in(i + 1, #g.t + 1, "add append insert")
  end }
  -- "define TGT2 at ... and send KL204 to it", "... and route UAL9 through it": the waypoint just
  -- defined joins the route
  rule { "send route take", "addwpt", when = function(g, i)
    local defined = false
    for k = 1, i - 1 do defined = defined or g:intent_at(k) == "defwpt" end
    local it = g:find_word(i + 1, math.min(#g.t + 1, i + 6), "it")
    return defined and it <= #g.t and g:word(it - 1, "to through via over")
  end }
  -- "define GOALC at 51.8 4.0 and add it to TRA203", "..., then append it to KLM12": the waypoint just defined
  -- joins the route of the aircraft named straight after "to"
  rule { "add append", "addwpt", next = "it", when = function(g, i)
    local defined = false
    for k = 1, i - 1 do defined = defined or g:intent_at(k) == "defwpt" end
    return defined and g:word(i + 2, "to") and g:has_ref(i + 3, i + 4, "aircraft")
  end }
  -- "create EZY33AB ... routing BAPAG then MAYLA", "..., route ELTOK, dest ENGM", "..., same route, RUVAS then
  -- OKAKI", "..., then give it TWEED at FL120", "..., add NAVAK": the waypoints of the aircraft created in the request
  rule { "routing route via give add append", "addwpt", when = function(g, i)
    local created = false
    for k = 1, i - 1 do created = created or g:intent_at(k) == "create" end
    local k = i + 1
    while g.t[k] and (g.t[k].kind == "punct" or g:word(k, "it")) do k = k + 1 end
    return created and g:has_ref(k, k + 1, "waypoint")
  end }
  -- "CFG4RK add NORKU, dest Bremen", "CFG4RK add NORKU then BANUB": waypoints, a clause of their own, added for
  -- an aircraft that flies;
  -- "WZZ1PM add VALA at 9000 ft", "add BENOT at flight level 180, 250 knots": with the level it is
  -- crossed at ("at" and an altitude straight after it)
  rule { "add append", "addwpt", when = function(g, i)
    local flying = false
    for _, r in ipairs(g:refs_in(1, #g.t + 1, "aircraft")) do flying = flying or r.exists end
    local r = g:refs_in(i + 1, i + 2, "waypoint")[1]
    -- ("add CANES then COTOS", "add WILLO and TIMBA": places listed, "then", "and" or a comma between them)
    local last = r
    while last do
      local k = last.e
      local more = (g:word(k, "then and") or (g.t[k] or {}).text == ",") and g:refs_in(k + 1, k + 2, "waypoint")[1]
      if not more then break end
      last = more
    end
    local nx = r and g.t[r.e]
    local tail = last and g.t[last.e]
    local q = r and g:word(r.e, "at") and g:quantities(r.e + 1, #g.t + 1)[1]
    local level = q and q.b == r.e + 1 and q.kind == "alt"
    -- ("bel3kf add bitbu fl200", "add resmi fl60 210": the level typed straight after the name)
    local typed = r and g:quantities(r.e, #g.t + 1)[1]
    level = level or (typed and typed.b == r.e and typed.kind == "alt" and typed.fl)
    -- ("CFG1KZ add RARUP at the end", typed "add rarup at end": the end of its route, where ADDWPT puts it)
    local the = r and g:word(r.e + 1, "the") and 1 or 0
    local at_end = r and g:word(r.e, "at") and g:word(r.e + 1 + the, "end")
    for x = at_end and r.e + 2 + the or #g.t + 1, #g.t do at_end = at_end and (g.t[x].kind == "punct" or g.t[x].filler) end
    local listed = last ~= r and (not tail or (tail.kind == "punct" and tail.text ~= "."))
    return flying and r ~= nil and (not nx or (nx.kind == "punct" and nx.text ~= ".") or level or at_end or listed)
      and not g:new_aircraft_follows(i) and not g:word_in(1, #g.t + 1, "@correction no")
  end }
  -- "add SUDIK to air malta 77", "add ZAGNB for croatia 7TK", "add WILLO then TIMBA to Speedbird 31F": places
  -- listed straight after the verb ("then", "and" or a comma between) and given, with "to" or "for", to an
  -- aircraft that flies
  rule { "add append", "addwpt", when = function(g, i)
    local r, k = g:refs_in(i + 1, i + 2, "waypoint")[1], nil
    while r do
      k = r.e
      local nx = (g:word(k, "then and") or (g.t[k] or {}).text == ",") and k + 1 or k
      r = nx > k and g:refs_in(nx, nx + 1, "waypoint")[1]
    end
    local a = k and g:word(k, "to for") and g:refs_in(k + 1, k + 2, "aircraft")[1]
    return a ~= nil and a ~= false and a.exists
  end }
  -- "add INTOP after AMDIL", "after NUSMO add LARSO", "after TOMTO route KORAK": a known waypoint put
  -- next to another, the place said after "after"/"before" before or after the verb
  -- ("after NAVPO add Lajes", "insert Midhurst after Compton": either said by its navaid's or airport's
  -- one-word name)
  rule { "add append insert route", "addwpt", when = function(g, i)
    local at = g:find_word(1, #g.t + 1, "after before")
    return at <= #g.t and at ~= i + 1
      and (g:has_ref(at + 1, at + 2, "waypoint") or g:place_by_name(at + 1, at + 2) ~= nil)
      and (g:has_ref(i + 1, i + 2, "waypoint") or g:place_by_name(i + 1, i + 2) ~= nil)
  end }
  -- "put in RUTOL before ERGOM", "put RUTOL after ERGOM", "squeeze MADOT in after BUSIL": the same said with
  -- "put (in)", "squeeze" or "slot", the two waypoints on either side of "before"/"after" ("in" before it or none);
  -- "define NEWPT at ..., then slot it in before ERGOM": "it" the waypoint the request defines before
  rule { "put squeeze slot", "addwpt", when = function(g, i)
    local w = g:word(i + 1, "in") and i + 2 or i + 1
    local at = g:word(w + 1, "in") and w + 2 or w + 1
    local defined = g:word(w, "it") and g:word_in(1, i, "define defwpt")
    return (g:has_ref(w, w + 1, "waypoint") or defined) and g:word(at, "after before")
      and g:has_ref(at + 1, at + 2, "waypoint")
  end }
  -- True when a latitude is said straight after word i (its degrees and minutes too: "55 30 North"),
  -- an aircraft that flies is named and no type is (no creation)
  local function degrees_for_flying(g, i)
    local qs = g:quantities(i + 1, math.min(#g.t + 1, i + 5))
    local lat = qs[1] and qs[1].b == i + 1
      and (qs[1].kind == "lat" or (qs[2] and qs[2].kind == "lat" and qs[2].b == qs[1].e))
    if not lat or g:has_ref(1, #g.t + 1, "type") then return false end
    for _, r in ipairs(g:refs_in(1, #g.t + 1, "aircraft")) do
      if r.exists then return true end
    end
    return false
  end
  -- "add 56 North 40 West after 56 North 30 West", "add 61 North 50 West to the end of your route"
  rule { "add append insert", "addwpt", when = degrees_for_flying }
  -- "after NOVPA route 36 north 45 west", "after BRIZE route to DAVOS": "route" as the verb, a position in degrees or
  -- a waypoint straight after it, a place after "after" before it (the clause's own, fillers and a comma between)
  rule { "route rte", "addwpt", when = function(g, i)
    local k = i - 1
    while k > 0 and (g.t[k].filler or g.t[k].text == ",") do k = k - 1 end
    local wp = g:refs_in(1, k + 1, "waypoint")
    wp = wp[#wp]
    -- (or a position in degrees after "after": "after 35 north 140 west, route 32 north 145 west")
    local qs = g:quantities(math.max(1, k - 8), k + 1)
    local lon, lat = qs[#qs], qs[#qs - 1]
    local said = lon and lat and lon.kind == "lon" and lon.e == k + 1 and lat.kind == "lat" and lat.e == lon.b
      and g:word(lat.b - 1, "after")
    -- (and a waypoint after it, "to" between or none: "after BRIZE route to DAVOS")
    local to = g:word(i + 1, "to") and i + 2 or i + 1
    return (said or wp ~= nil and wp.e == k + 1 and g:word(wp.b - 1, "after"))
      and (degrees_for_flying(g, i) or g:has_ref(to, to + 1, "waypoint"))
  end }
  rule { "add put make need want", "create", near = { 3, "@articles_new" },
         when = function(g, i) return g:type_or_aircraft_word(i + 1, i + 7) end }
  -- "make a Vueling at SOTUK, VLG77, A320, ...": an airline after the article, and a new callsign of it
  rule { "add put make", "create", next = "@articles_new", when = function(g, i)
    local icao = g:airline_at(i + 2)
    for _, r in ipairs(icao and g:refs_in(i + 3, math.min(#g.t + 1, i + 10), "aircraft") or {}) do
      if not r.exists and r.name:upper():sub(1, #icao) == icao then return true end
    end
    return false
  end }
  -- "add a Nor Shuttle seven seven five, Boeing 737-800, at GOTUR": a new aircraft's callsign said in
  -- words before its type, which comes before any place
  rule { "add put", "create", next = "@articles_new", when = function(g, i)
    local ty = g:refs_in(i + 2, math.min(#g.t + 1, i + 12), "type")[1]
    return ty ~= nil and not g:has_ref(i + 2, ty.b, "waypoint")
  end }
  -- "let's start with a Ryanair 737, RYR81JC, at ...", "I'd like an easyJet A320, EZY45, over ...": a new
  -- aircraft's type and callsign after the article
  rule { "start like", "create", near = { 2, "@articles_new" }, when = function(g, i)
    return g:has_ref(i + 1, i + 7, "type") and g:new_aircraft_follows(g:find_word(i + 1, i + 7, "@articles_new"))
  end }
  -- "We begin the reconstruction with IBE3142, an Airbus A320, at ...": a new callsign after "begin", its type
  -- said with it
  rule { "begin", "create", when = function(g, i)
    return g:new_aircraft_follows(i) and g:has_ref(i + 1, i + 10, "type")
  end }
  -- "add a320 ezy12 at ...", "new: DLH9CK A321neo ...", "insert SAS19K B736 at ...": a type or a new callsign
  -- right after the verb
  rule { "add put new spawn insert adding inject injecting", "create", when = function(g, i) return g:new_aircraft_follows(i) end }
  -- "stick a Loganair Twin Otter in over Glasgow", "chuck a Bristow S92 in at ...", "chuck in a Cathay 777":
  -- British "stick" and "chuck" for "put", an article and a type or a new callsign straight after
  -- ("chuck a jetstar in at blaka a three twenty jetstar five five one ...": an airline's name after the article,
  -- "in" after it, and the new aircraft's type or new callsign said later in the request)
  rule { "stick chuck", "create", when = function(g, i)
    local k = g:word(i + 1, "in on") and i + 2 or i + 1
    if not g:word(k, "@articles_new") or g:word_in(1, #g.t + 1, "random") then return false end
    if g:new_aircraft_follows(k) then return true end
    local icao, e = g:airline_at(k + 1)
    if not icao or not g:word(e, "in") then return false end
    for _, r in ipairs(g.refs) do
      if r.b > e and (r.kind == "type" or (r.kind == "aircraft" and g:new_callsign(r))) then return true end
    end
    return false
  end }
  -- "spin up American 601, an A321, ...", "let's spin up a 747 ...": "spin up" (a session's word for starting
  -- something new) before a new callsign or a type
  rule { "spin", "create", next = "up", when = function(g, i) return g:new_aircraft_follows(i + 1) end }
  -- "callsign SWR19, A333, FL360, ...": a request that opens with a new callsign and its type
  rule { "callsign", "create", when = function(g, i)
    return g:skip_fillers(1) == i and g:new_aircraft_follows(i) and g:has_ref(i + 1, i + 6, "type")
  end }
  -- "another Wizz please: WZZ88X, A320, ...": a request that opens with a new aircraft
  rule { "another", "create", when = function(g, i) return g:skip_fillers(1) == i and g:new_aircraft_follows(i) end }
  -- "create an A320 called EDW507 at EXP01 ..., and another A320 called EDW508 at EXP02 ...": one more new aircraft
  -- after a creation in the request, "another" after "and" or a mark, a type straight after it
  rule { "another", "create", when = function(g, i)
    if not (g:word(i - 1, "and") or (g.t[i - 1] and g.t[i - 1].kind == "punct")) or not g:has_ref(i + 1, i + 2, "type") then
      return false
    end
    for k = 1, i - 1 do
      if g:intent_at(k) == "create" then return g:new_aircraft_follows(i) end
    end
    return false
  end }
  -- "Delete my waypoint VALA", "remove the fix WP1": a waypoint defined for this run, when no aircraft
  -- is named and none has it in its route, is undefined (DEFWPT ... DELETE)
  rule { "delete remove del", "undefwpt", near = { 3, "@waypoint_nouns" }, when = function(g, i)
    if g:has_ref(1, #g.t + 1, "aircraft") then return false end
    local w = g:refs_in(i + 1, math.min(#g.t + 1, i + 5), "waypoint")[1]
    if not w or not g:user_waypoint(w.name) then return false end
    for _, a in ipairs(g.fleet) do
      for _, name in ipairs(a.route or {}) do if name:upper() == w.name:upper() then return false end end
    end
    return true
  end }
  -- "delete the deletion area", "remove the experiment area": the area ended
  -- "remove the trails", "remove all trails": the trails switched off (TRAIL's own word), no aircraft deleted
  rule { "remove", false, when = function(g, i)
    local k = g:skip_fillers(i + 1)
    while g:word(k, "the all aircraft") do k = k + 1 end
    return g:word(k, "trail trails")
  end }
  rule { "delete remove", false, near = { 3, "area" }, when = function(g) return not g:has_ref(1, #g.t + 1, "aircraft") end }
  -- ("delete acft leaving box 51 3 53 6.5": the deletion area, rules below; no aircraft deleted now)
  rule { "delete del remove", false, when = function(g, i)
    local k = g:find_word(i + 1, math.min(#g.t + 1, i + 5), "leaving leave leaves exiting exit exits")
    local n = 0
    for _, q in ipairs(k <= #g.t and g:quantities(k + 1, #g.t + 1) or {}) do
      if q.kind == "plain" or q.kind == "lat" or q.kind == "lon" then n = n + 1 end
    end
    return n >= 4 and g:kind_only_aircraft()
  end }
  -- "clear the wind", "clear all winds": the wind field cleared (DEL WIND, m:remove), no aircraft deleted
  rule { "clear", "delete", when = function(g, i)
    local k = g:skip_fillers(i + 1)
    while g:word(k, "the all") do k = k + 1 end
    return g:word(k, "wind winds")
  end }
  -- "the area, so anything leaving it gets deleted": what a setting does, in the passive, no aircraft named
  rule { "delete deleted remove removed", false, prev = { 1, "gets get got" },
         when = function(g, i) return not g:has_ref(math.max(1, i - 5), i, "aircraft") end }
  -- ("skip LANAK, route direct TLA": the direct-to passes it; no deletion)
  -- ("route direct LAM, he can skip BRAIN": a direct-to said before it, to a waypoint that an aircraft named flies
  -- after the one skipped, passes it too; a waypoint after the direct's is still left out of the route)
  local function passed_by_direct(g, i)
    local skipped = g:refs_in(i + 1, i + 2, "waypoint")[1]
    for d = math.max(1, i - 8), i - 1 do
      local target = skipped and g:word(d, "direct directly dct straight") and g:refs_in(d + 1, math.min(d + 4, i), "waypoint")[1]
      for _, r in ipairs(target and g:refs_in(1, #g.t + 1, "aircraft") or {}) do
        local seen = false
        for _, name in ipairs(r.exists and g:state(r.name).route or {}) do
          if name:upper() == target.name:upper() then break end
          seen = seen or name:upper() == skipped.name:upper()
        end
        if seen then return true end
      end
    end
    return false
  end
  -- whether waypoint reference w is on the route of an aircraft the request names
  local function on_a_route(g, w)
    for _, r in ipairs(g:refs_in(1, #g.t + 1, "aircraft")) do
      local st = r.exists and g:state(r.name)
      for _, name in ipairs(st and st.route or {}) do
        if name:upper() == w.name:upper() then return true end
      end
    end
    return false
  end
  local function no_direct(g, i)
    return not g:word(i, "skip") or not (g:followed_by(i, 8, "direct directly dct straight") or passed_by_direct(g, i))
  end
  rule { "remove delete del skip", "delwpt", near = { 2, "waypoint wpt wp" }, when = no_direct }
  -- "baw433 skip redfa", "skip SUGOL for BAW433": "skip" straight before a waypoint on the route of an aircraft the
  -- request names takes it off that route (DELWPT), when no direct-to is said (what one skips is G's to read)
  rule { "skip skipping", "delwpt", when = function(g, i)
    local w = g:refs_in(i + 1, i + 2, "waypoint")[1]
    return w ~= nil and on_a_route(g, w) and not g:word_in(1, #g.t + 1, "direct directly dct straight")
  end }
  -- verb-final order: "APJ301 route delete all", "EVA15 route all clear" delete the whole route,
  -- "ANA25 waypoint HYOGO remove" the waypoint named before the verb
  -- (the verb closes the request, "all" at most after it: "route clear of weather" is no deletion)
  rule { "clear delete remove erase del", "delrte", when = function(g, i)
    if not g:word(g:word(i - 1, "all") and i - 2 or i - 1, "@route_nouns") then return false end
    local k = i + 1
    while g.t[k] and (g.t[k].kind == "punct" or g.t[k].filler or g:word(k, "all please")) do k = k + 1 end
    -- ("KAL12 route delete please, and heading 090 fly": "and" or "then" after a pause opens the next instruction)
    local next_clause = k > i + 1 and (g.t[k - 1].kind == "punct" or g:word(k - 1, "and then"))
    return (k > #g.t or next_clause) and not g:has_ref(1, #g.t + 1, "waypoint")
  end }
  rule { "remove delete del drop erase", "delwpt", prev = { 3, "waypoint wpt wp" },
         when = function(g, i) return g:has_ref(math.max(1, i - 3), i, "waypoint") end }
  -- a verb of deletion after a noun that is no aircraft ("KAL8 altitude delete"): what is deleted is asked,
  -- never the aircraft
  -- ("flight plan cancel, delete the route": the route named after the verb is the whole route, below)
  rule { "remove delete del", "delwpt", prev = { 3, "waypoint wpt wp @route_nouns altitude speed heading level" },
         when = function(g, i) return not g:followed_by(i, 2, "@route_nouns") end }
  -- "UAL9 forget ALPHA", "Qatari 1018 delete MISOD": a waypoint of the aircraft's route, said straight
  -- after the verb, left out of it
  rule { "forget delete remove del", "delwpt", when = function(g, i)
    local k = g:skip_fillers(i + 1)
    local w = g:refs_in(k, k + 1, "waypoint")[1]
    if not w then return false end
    return on_a_route(g, w)
  end }
  rule { "remove delete del skip drop", "delwpt", near = { 8, "@route_nouns" },
         when = function(g, i) return g:has_ref(i + 1, i + 2, "waypoint") and no_direct(g, i) end }
  -- "AUA915 LAKOL delete", "DLH9YE UPALA remove, then direct ERNAS", "DLH4AB MAH from the route remove" (German's
  -- verb last: "LAKOL löschen", "UPALA raus", "MAH aus der route raus"): a waypoint of the aircraft's route said
  -- straight before the verb, or before "from the route" and the verb, is the one left out of it
  rule { "forget delete remove del", "delwpt", when = function(g, i)
    local k = i - 1
    while k > 1 and g:word(k, "from the its @route_nouns") do k = k - 1 end
    local w
    for _, r in ipairs(g:refs_in(math.max(1, k - 2), k + 1, "waypoint")) do
      if r.e == k + 1 then w = r end
    end
    -- ("at OUTW delete SAS1417": the place after "at" is where the deletion waits, no waypoint deleted)
    if not w or g:word(w.b - 1, "at over passing reaching overhead") then return false end
    return on_a_route(g, w)
  end }
  -- "erase BARSA of the route", "I want to quit LALPI of its route" ("quitar" / "tirar", a Spanish or Portuguese
  -- speaker's false friend): the same, the waypoint straight after the verb and a route noun after it
  rule { "erase quit", "delwpt", near = { 8, "@route_nouns" }, when = function(g, i)
    return g:has_ref(i + 1, i + 2, "waypoint") and g:followed_by(i + 1, 7, "@route_nouns") and no_direct(g, i) end }
  -- "Virgin 3 delete 54 North 30 West": a position said in degrees straight after the verb, for an aircraft
  -- that flies, is a point of its route (no deletion of the aircraft)
  rule { "forget delete remove del", "delwpt", when = degrees_for_flying }
  -- "GAF612 remove Leine from the route", "Speedbird 1488 delete Talla": a navaid said by its name (one or two
  -- words straight after the verb, before "from", or ending the request or its clause, or before "and" and an
  -- instruction, when `ending`) that the route
  -- of the one aircraft named holds
  local function navaid_on_route(g, i, ending)
    local f = g:find_word(i + 2, math.min(#g.t + 1, i + 4), "from")
    if ending and not g:word(f, "from") then
      f = i + 1
      local function stop(k)
        if g:word(k, "and") then return g:any_instruction_in(k + 1, k + 2) end
        return g.t[k].kind == "punct" or g.t[k].filler
      end
      while f <= #g.t and f <= i + 3 and not stop(f) do f = f + 1 end
      if f == i + 1 or (f <= #g.t and not stop(f)) then return false end
    end
    local a = g:refs_in(1, #g.t + 1, "aircraft")
    local st = f <= #g.t + (ending and 1 or 0) and #a == 1 and a[1].exists and g.world.navaids_named
      and g:state(a[1].name)
    if not (st and st.lat) then return false end
    local words = {}
    for k = i + 1, f - 1 do
      if g.t[k].kind ~= "word" or not g.t[k].alpha then return false end
      words[#words + 1] = g.t[k].text
    end
    local held = {}
    for _, w in ipairs(st.route or {}) do held[w:upper()] = true end
    for _, id in ipairs(g.world.navaids_named(table.concat(words, " "), st.lat, st.lon, NAVAID_RANGE_NM)) do
      if held[id:upper()] then return true end
    end
    return false
  end
  rule { "remove delete del drop", "delwpt", near = { 8, "@route_nouns" }, when = navaid_on_route }
  rule { "forget delete remove del", "delwpt", when = function(g, i) return navaid_on_route(g, i, true) end }
  -- "clear the route of EWG7LP", "clear UAL485's route completely", "kill the whole route on ASA31": the
  -- whole route, no waypoint named
  -- (the route's noun in the verb's own clause: "delete KLM123, the route is finished" tells why, no comma between)
  -- ("could you clear Lufthansa 9KM's whole route?": a spoken callsign and "whole" between, six words)
  rule { "clear delete remove erase wipe kill scrap", "delrte", near = { 6, "@route_nouns" },
         when = function(g, i)
           if g:has_ref(1, #g.t + 1, "waypoint") then return false end
           for k = math.max(1, i - 4), math.min(#g.t, i + 6) do
             if g:word(k, "@route_nouns") then
               local clause = true
               for x = math.min(i, k), math.max(i, k) do clause = clause and g.t[x].text ~= "," end
               -- ("remove it from the route", "take that off the route": a thing taken out of the route, named by
               -- a pronoun only, is no whole route; asked)
               if clause and k > i and g:word_in(i + 1, k, "from off out") and g:word_in(i + 1, k, "it that this") then
                 return false
               end
               if clause then return true end
             end
           end
           return false
         end }
  -- "cancel your route", "cancel the whole route of CHH7423": the whole route, the noun straight after the verb (or
  -- its article, and "whole" or "entire", or "the rest of"), no waypoint named, and nothing after it that a cancelled route would not
  -- be ("cancel route restrictions": a restriction lifted)
  rule { "cancel", "delrte", when = function(g, i)
    local k = g:word(i + 1, "the your its his her their") and i + 2 or i + 1
    if g:word(k, "whole entire complete") then k = k + 1 end
    -- ("cancel the rest of your route": what is left of it, which is all of it that is still to fly)
    if g:word(k, "rest remainder") and g:word(k + 1, "of") then
      k = g:word(k + 2, "the your its his her their") and k + 3 or k + 2
    end
    return g:word(k, "route rte") and not g:word(k + 1, "restriction restrictions clearance")
      and not g:has_ref(1, #g.t + 1, "waypoint")
  end }
  -- "clr rte", "clr route" typed short, the noun ending the request ("clr route as filed" is no deletion)
  rule { "clr", "delrte", next = "@route_nouns",
         when = function(g, i) return not g:has_ref(1, #g.t + 1, "waypoint") and i + 2 > #g.t end }
  -- ("bin it": British for delete; "I'm deleting United 1542 now": a controller saying what he does)
  -- ("despawn": a game's word for taking an object out of the world)
  rule { "delete del remove rid kill rmv bin deleting removing despawn despawned destroy", "delete" }
  -- "clear the Alaska 31 off the scope": an aircraft cleared off the display, the words after it saying so
  rule { "clear", "delete", when = function(g, i)
    local r = g:refs_in(i + 1, math.min(#g.t + 1, i + 6), "aircraft")[1]
    if not r then return false end
    local k = r.e
    if not g:word(k, "off from") then return false end
    k = g:word(k + 1, "the") and k + 2 or k + 1
    return g:word(k, "scope screen display radar map sim simulation")
  end }
  -- "take out BAGSO", "take BAGSO out", "take away MAGLI from the route": a waypoint taken out of the route of the
  -- aircraft addressed
  rule { "take", "delwpt", near = { 3, "out away" }, when = function(g, i)
    local k = g:word(i + 1, "out away") and i + 2 or i + 1
    local r = g:refs_in(k, k + 1, "waypoint")[1]
    return r ~= nil and (k == i + 2 or g:word(r.e, "out away")) and not g:has_ref(1, #g.t + 1, "type")
  end }
  rule { "take", "delete", near = { 5, "out" } }
  -- "take BEDRK off your route", "take CGT off of Southwest 903's route": a waypoint straight after the verb, "off"
  -- (and "of") after it, a route noun within the six words after
  -- ("take Aberdeen off the route": a name in capitals in the waypoint's place, the handler's to read)
  rule { "take", "delwpt", when = function(g, i)
    local r = g:refs_in(i + 1, i + 2, "waypoint")[1]
    local e = r and r.b == i + 1 and r.e
      or (g.t[i + 1] and g.t[i + 1].kind == "word" and g.t[i + 1].raw:match("^%u%l+$") and i + 2)
    if not (e and g:word(e, "off")) then return false end
    return g:word_in(e + 1, math.min(#g.t + 1, e + 7), "@route_nouns")
  end }
  -- "take Scandinavian one five zero one out of the exercise": a flying aircraft, however long its spoken callsign,
  -- straight after the verb ("the" between), "out" straight after it, and then nothing in its clause or "of" the
  -- exercise (lexicon.presence_places, @sim: "out of the hold" is no deletion); "take the Jet2 off, it's finished":
  -- "off" closing its clause the same ("take the Jet2 off the route" is LNAV's)
  rule { "take taking", "delete", when = function(g, i)
    local k = g:word(i + 1, "the") and i + 2 or i + 1
    local r = g:refs_in(k, k + 1, "aircraft")[1]
    if not (r ~= nil and r.b == k and r.exists and g:word(r.e, "out off")) then return false end
    local o = r.e + 1
    if not g.t[o] or g.t[o].kind == "punct" then return true end
    o = g:word(o + 1, "the this our") and o + 2 or o + 1
    return g:word(r.e, "out") and g:word(r.e + 1, "of") and g:word(o, "@presence_places @sim") or false
  end }

  -- route
  rule { "proceed", false, near = { 3, "heading" } }
  -- "climb to FL370 and proceed at Mach .79", "proceed at 250 knots": the speed flown on
  rule { "proceed", "spd", next = "at", when = function(g, i)
    local q = g:quantities(i + 2, #g.t + 1)[1]
    return q ~= nil and (q.kind == "mach" or q.kind == "speed") and q.b == g:skip_fillers(i + 2)
  end }
  -- "proceed to flight level 120", "proceed to FL80": a level proceeded to is a climb or descent to it
  rule { "proceed", "alt", next = "to", when = function(g, i)
    local q = g:quantities(i + 2, #g.t + 1)[1]
    return q ~= nil and q.kind == "alt" and q.b == g:skip_fillers(i + 2)
  end }
  -- "put the Swiss directly over LAPAT", "move it directly above BIG": "directly" before the place a move sets the
  -- aircraft over is the move's manner, no direct-to
  -- ("please put the Qatari 491 directly at 26.0 north 53.0 east": "at" or "on" the place too)
  rule { "directly", false, next = "over above at on", prev = { 4, "move put place reposition teleport" } }
  -- ("move Channex 12 up to FL120, just put it there directly": the manner of the move, at once, closing its clause)
  rule { "directly", false, prev = { 4, "move put place reposition teleport" }, when = function(g, i)
    local nx = g.t[i + 1]
    return nx == nil or nx.kind == "punct"
  end }
  rule { "direct directly dct dtc drct dir proceed direct-to", "direct" }  -- ("dtc": dct's letters swapped)
  -- "after CPA1 continue to EXIT1", "after passing SYZ it should continue to ISN": "continue to" a place, with
  -- "after" a place said before it in the request, is the way on from that place (m:direct_one adds it after it)
  rule { "continue continues", "direct", next = "to", when = function(g, i)
    local at = g:find_word(1, i, "after")
    if at >= i then return false end
    local k = g:word(at + 1, "pass passing passed") and at + 2 or at + 1
    local r = g:refs_in(k, k + 1, "waypoint")[1]
    if not (r and r.b == k and g:has_ref(i + 2, i + 3, "waypoint")) then return false end
    -- (only a subject, a modal or "please" between the place and the verb: "after NIK add ANDIK, then continue
    -- to EKROS" is the added place's way on, read by the add)
    for x = r.e, i - 1 do
      if not (g.t[x].filler or g.t[x].kind == "punct" or g:word(x, "please it he she they should must will can")) then
        return false
      end
    end
    return true
  end }
  rule { "straight", "direct", next = "to" }  -- "send IBE3141 straight to MITUM"
  -- "KAL123 to ENKAS go straight": the adverb closing the clause after "go", the place said after "to"
  rule { "straight", "direct", prev = { 1, "go" }, when = function(g, i)
    local to = g:find_word(1, i, "to")
    return to < i and g:has_ref(to + 1, i, "waypoint") and g:skip_fillers(i + 1) > #g.t
  end }
  -- "point BAW123 towards SPY", "point it at BRAVO", "UAL9 skip ahead to BRAVO": a waypoint flown to
  -- (the place a waypoint's code, or a navaid's name with its kind after it: "point the Iberia at the Gerona VOR")
  local function to_waypoint(g, i)
    local k = g:find_word(i + 1, math.min(#g.t + 1, i + 5), "towards toward at to")
    local w = g:skip_fillers(k + 1)
    return k <= #g.t and (g:has_ref(w, w + 1, "waypoint")
      or (g:word(w + 1, "@navaid_kinds") and g:place_by_name(w, w + 1) ~= nil))
  end
  rule { "point", "direct", not_near = { 4, "@compass" }, when = to_waypoint }
  -- "point the CRJ toward O'Hare", "aim it towards Baltimore airport": a place no waypoint (an airport, a city) is
  -- the heading that points at it, as "fly towards" (a waypoint pointed at is flown to, above)
  rule { "point aim", "hdg", when = function(g, i) return toward_place(g, i) and not to_waypoint(g, i) end }
  rule { "skip", "direct", next = "ahead", when = function(g, i) return g:word(i + 2, "to") and to_waypoint(g, i) end }
  -- "VOZ1234 track to BURLI": a waypoint (no airport) the aircraft tracks to, flown to directly
  rule { "track", "direct", next = "to", when = function(g, i)
    local k = g:skip_fillers(i + 2)
    local r = g:refs_in(k, k + 1, "waypoint")[1]
    return r ~= nil and not r.name:match("^%a%a%a%a$")
  end }
  -- "set course to DANOK", "set course GRIVA", "take course for ALM" (a Russian speaker's "course to"): a waypoint
  -- straight after the course ("to" or "for" between), flown to directly ("set course 270" stays a heading)
  rule { "course", "direct", prev = { 1, "set take" }, when = function(g, i)
    local k = g:skip_fillers(g:word(i + 1, "to for") and i + 2 or i + 1)
    local r = g:refs_in(k, k + 1, "waypoint")[1]
    return r ~= nil and r.b == k
  end }
  -- "jump ahead to LINNG", "cut the corner to MILLS": a waypoint of the route flown to directly
  rule { "jump", "direct", next = "ahead", when = function(g, i) return g:word(i + 2, "to") and to_waypoint(g, i) end }
  rule { "cut", "direct", near = { 3, "corner corners" }, when = to_waypoint }
  -- "rejoin LISOR", "rejoin the route at OPALA", "rejoin your track at KISMO", "rejoin own navigation at NORKU":
  -- the waypoint where the route is rejoined is flown to directly ("rejoin the route" alone is LNAV)
  rule { "rejoin rejoining", "direct", when = function(g, i)
    local k = g:skip_fillers(i + 1)
    while g:word(k, "the your its his her own @route_nouns track airway navigation nav at to over by") do
      k = g:skip_fillers(k + 1)
    end
    return k <= i + 6 and g:has_ref(k, k + 1, "waypoint")
  end }
  -- ("cleared for the FMS bridge visual runway 28R": an approach clearance, not simulated)
  rule { "cleared", "direct", when = function(g, i)
    return #g.world.waypoints > 0 and not g:followed_by(i, 8, "visual approach ils rnav localizer land landing")
  end }
  -- "create 5 random A320s at FL250, all with destination Zurich", "mcre 10 B738 dest EHAM": the destination of the
  -- random traffic created before it, no aircraft named between (MCRE's destination, read by m:random_traffic)
  rule { "destination dest", false, when = function(g, i)
    for k = i - 1, 1, -1 do
      if g:intent_at(k) == "mcre" then return #g:refs_in(k, i, "aircraft") == 0 end
    end
    return false
  end }
  -- "Add for Astanaline 929 the point PIGOR before destination", "add waypoint EKBUR to the route of UTair 125
  -- before its destination": where ADDWPT puts the waypoint anyway (the route's end, before the destination), no
  -- destination of its own; "before" and the noun closing the request or a clause after an instruction to add
  rule { "destination dest", false, when = function(g, i)
    local k = g:word(i - 1, "the its his her their") and i - 2 or i - 1
    local e = g:skip_fillers(i + 1)
    if not g:word(k, "before") or (g.t[e] and g.t[e].kind ~= "punct") then return false end
    for x = k - 1, 1, -1 do
      if g.t[x].kind == "punct" and g.t[x].text ~= "," then return false end
      if g:intent_at(x) == "addwpt" then return true end
    end
    return false
  end }
  rule { "destination dest", "dest" }
  -- "KL204 is going to Frankfurt", "it's bound for Brussels": where the aircraft flies, said as a fact
  -- ("it is going to be the one the participant sequences": the future said, no place)
  rule { "going", "dest", next = "to", prev = { 1, "is it's are" },
         when = function(g, i) return not g:intent_at(i + 2) and not g:word(i + 2, "be") end }
  rule { "bound", "dest", next = "for", prev = { 1, "is it's are" } }
  -- "create ... going to Orly", "..., bound for Glasgow", "route it via VALB and land it at Kastrup": the place after "to"/"at"
  -- is an airport (its ICAO code, or a name of one or two words of the navdata's airports); a landing
  -- is the destination only at the end of a route given before it ("UAL9 land at EGLL" alone is a
  -- landing clearance, not simulated), and random traffic "all going to Schiphol" is MCRE's
  local function airport_at(g, k)
    for _, r in ipairs(g:refs_in(k, k + 1, "waypoint")) do
      if r.name:match("^%a%a%a%a$") then return true end
    end
    local t, nx, named = g.t[k], g.t[k + 1], g.world.airports_named
    if not named or not t or t.kind ~= "word" or not t.alpha or #t.text < 4 then return false end
    -- (a word said before an airport's code, a comma between or none: "goes to braunschweig, EDVE"; the word is
    -- accounted for only as the navdata's name of that code, G:name_beside_code)
    local code = nx and nx.kind == "punct" and nx.text == "," and k + 2 or k + 1
    for _, r in ipairs(g:refs_in(code, code + 1, "waypoint")) do
      if r.b == code and r.name:match("^%a%a%a%a$") then return true end
    end
    -- (an open airport's ICAO code typed in lower case, no English squawk knows: "goes to eham")
    local class = g.world.airport_class and t.raw:match("^%l%l%l%l$") and not g:known_word(k)
      and g.world.airport_class(t.raw:upper()) or ""
    if class ~= "" and class ~= "CLOSED" then return true end
    -- (or a city whose airport lies by navaids of its name: "Ezeiza", SAEZ beside the EZEIZA VOR)
    local beside = g.world.airports_beside_navaids
    -- (a city named for its airport, lexicon.city_airports: "going to Perpignan", RIVESALTES)
    local city = CITY_AIRPORTS[t.text]
    return #named(t.text) > 0 or (nx ~= nil and nx.kind == "word" and #named(t.text .. " " .. nx.text) > 0)
      or (city ~= nil and #named(city) > 0)
      or (beside ~= nil and t.raw:match("^%u") ~= nil and #beside(t.text) > 0)
  end
  local function earlier(g, i, intent)
    for k = 1, i - 1 do if g:intent_at(k) == intent then return true end end
    return false
  end
  rule { "going goes headed heads bound", "dest", next = "to for", when = function(g, i)
    return not g:intent_at(i + 2) and not earlier(g, i, "mcre") and (earlier(g, i, "create") or airport_at(g, i + 2))
  end }
  -- "Flybondi 5120 will land at Ezeiza, not Aeroparque", "the GOL 1455 should go to Congonhas": where the
  -- aircraft named straight before the modal will land or should go is its destination (an airport named
  -- after "at"/"to"); said of "it" after an instruction ("..., it will go to Riga") it is context
  rule { "land go", "dest", prev = { 1, "will should shall must" }, when = function(g, i)
    local named = false
    for _, r in ipairs(g:refs_in(1, i - 1, "aircraft")) do named = named or r.e == i - 1 end
    return named and g:word(i + 1, g:word(i, "land") and "at in" or "to") and airport_at(g, i + 2)
  end }
  -- "set the ryanair to land at shannon", "make the air france land at orly": an aircraft that a verb of sending
  -- names straight before "(to) land" at an airport, its destination (a newcomer's words; "SWR38F land at Zurich",
  -- no such verb, is a landing clearance, asked)
  rule { "land", "dest", when = function(g, i)
    local k = g:word(i - 1, "to") and i - 2 or i - 1
    local sent = false
    for _, r in ipairs(g:refs_in(1, i, "aircraft")) do
      local v = g:word(r.b - 1, "the") and r.b - 2 or r.b - 1
      sent = sent or (r.e == k + 1 and g:word(v, "set send make have get tell let"))
    end
    -- (a runway or an approach said with it, "land at Schiphol runway 18R", is the landing itself, asked)
    return sent and g:word(i + 1, "at in") and airport_at(g, i + 2)
      and not g:word_in(i + 2, #g.t + 1, "runway rwy ils approach visual")
  end }
  rule { "land landing", "dest", when = function(g, i)
    local at = g:word(i + 1, "at in") and i + 1 or g:word(i + 1, "it him her them") and g:word(i + 2, "at in") and i + 2
    return at and earlier(g, i, "addwpt") and airport_at(g, at + 1) or false
  end }
  -- True when the words from k, two or three alphabetic ones, are the whole name (its generic words, "intl", left
  -- out: sim:airports_named) of a large or medium airport of the navdata ("san diego": KSAN "SAN DIEGO INTL")
  local function named_airport_phrase(g, k)
    local named, class = g.world.airports_named, g.world.airport_class
    if not named or not class then return false end
    local words = {}
    for n = 1, 3 do
      local t = g.t[k + n - 1]
      if t == nil or t.kind ~= "word" or not t.alpha then return false end
      words[n] = t.text
      for _, id in ipairs(n > 1 and named(table.concat(words, " ")) or {}) do
        if class(id) == "LARGE" or class(id) == "MEDIUM" then return true end
      end
    end
    return false
  end
  -- True when the word at k names an airport where one is meant: an airport's ICAO code, a name of the navdata's
  -- airports, a city of lexicon.city_airports, or (`placed`: said where a place is, after "to" or "divert")
  -- three capitals (an IATA code, names.iata_airports, or asked by the handler: "send it to MUC") or a
  -- capitalised word a large airport's name starts with ("Austin") or a navaid beside large or medium airports
  -- bears ("divert to Belfast": EGAA beside the BELFAST VOR; sim:airports_beside_navaids)
  -- (`placed`, in lower case too: a large airport's IATA code that is no English word, "send it to sfo"; a name of
  -- two or three words a large or medium airport bears, "send the alaska to san diego"; a word no English squawk
  -- knows that names navaids beside such airports, "send the ups to oakland")
  local function airport_word(g, k, placed)
    for _, r in ipairs(g:refs_in(k, k + 1, "waypoint")) do
      if r.b == k and r.name:match("^%a%a%a%a$") then return true end
    end
    local t, named, city = g.t[k], g.world.airports_named, g.world.airports_of_city
    if t == nil or t.kind ~= "word" then return false end
    if placed and (t.raw:match("^%u%u%u$") or g:iata_airport_at(k)) then return true end
    if placed and named_airport_phrase(g, k) then return true end
    -- ("route klm87r to eheh": an airport's ICAO code typed in lower case where a place is, no English word)
    local class = g.world.airport_class
    if placed and class and t.text:match("^%a%a%a%a$") and not g:known_word(k) and (class(t.text:upper()) or "") ~= "" then
      return true
    end
    local beside = g.world.airports_beside_navaids
    return named ~= nil and t.alpha and #t.text >= 4 and (#named(t.text) > 0 or CITY_AIRPORTS[t.text] ~= nil
      or (placed and (t.raw:match("^%u") ~= nil or not g:known_word(k)) and ((t.raw:match("^%u") ~= nil and #city(t.text) > 0)
        or (beside ~= nil and #beside(t.text) > 0))))
  end
  -- "Send UPS2971 to Louisville, KSDF", "send AAL100 to KBOS and have it climb": an airport (four letters) sent
  -- to; "send it to Heathrow": the one word after "to" names an airport of the navdata ("divert Ryanair
  -- 23AB to Eindhoven", "KLM1234 divert to EHRD": diverted to an airport, the new destination)
  -- ("route VIR9 to Heathrow", "send him to Charleroi": a city said for its airport, lexicon.city_airports,
  -- is an airport too)
  -- ("send the Jet2 into Newcastle", Scots "intae": the airport it is sent in to land at, as "to")
  local function sent_to_airport(g, i)
    local to = g:find_word(i + 1, math.min(#g.t + 1, i + 5), "to into")
    if g:word(to - 1, "straight direct directly") then return false end  -- ("send it straight to Barcelona")
    for _, r in ipairs(g:refs_in(to + 1, math.min(#g.t + 1, to + 5), "waypoint")) do
      if r.name:match("^%a%a%a%a$") then return true end
    end
    return airport_word(g, to + 1, g:word(to, "to into"))
  end
  rule { "send divert diverting", "dest", when = sent_to_airport }
  -- "Delta 2650 cleared to Atlanta, KATL": a clearance to an airport (no level, no "land") is its destination; one
  -- with its route after it ("via COATT", "then ...") is left to the parse
  rule { "cleared", "dest", next = "to", when = function(g, i)
    return airport_word(g, i + 2, true) and not g:word_in(i + 2, #g.t + 1, "via then")
  end }
  -- "UAE201 divert AUH", "divert Cologne", "divert DLH458 EDDK": the place straight after "divert" (and the
  -- aircraft diverted), no "to"
  rule { "divert diverting", "dest", when = function(g, i)
    local k = i + 1
    for _, r in ipairs(g:refs_in(k, k + 1, "aircraft")) do
      if r.b == k then k = r.e end
    end
    return airport_word(g, k, true)
  end }
  -- "route VIR9 to Heathrow", "reroute the Air France to Lyon": the aircraft straight after the verb, then
  -- "to" and an airport ("route DAL88 via MERIT ..." lists waypoints)
  rule { "route reroute", "dest", when = function(g, i)
    local k = g:word(i + 1, "the") and i + 2 or i + 1
    for _, r in ipairs(g:refs_in(k, k + 1, "aircraft")) do
      if r.b == k and g:word(r.e, "to") then return sent_to_airport(g, r.e - 1) end
    end
    return false
  end }
  -- ("KLM87R route to EHEH", "klm12 reroute to ebbr": the aircraft straight before the verb)
  rule { "route reroute", "dest", next = "to", when = function(g, i)
    local r = g:refs_in(1, i, "aircraft")
    r = r[#r]
    return r ~= nil and r.e == i and sent_to_airport(g, i)
  end }
  -- "create KL207 ... and send it to ARTIP": a waypoint (no airport) for the aircraft just created
  rule { "send", "addwpt", next = "it", when = function(g, i)
    local created = false
    for k = 1, i - 1 do created = created or g:intent_at(k) == "create" end
    local r = created and g:word(i + 2, "to") and g:refs_in(i + 3, i + 4, "waypoint")[1]
    return r and #r.name == 5  -- (a five-letter fix; "send it to JFK" names a destination)
  end }
  -- "go to the Caselle VOR", "fly to GATE1 and then GATE2", "the Volotea, go to GATE1 and after to EXIT3": a place
  -- gone to that is no airport (a fix, a navaid, a waypoint the simulation defined: no four-letter code) is flown
  -- to directly; with a second such place said after "then" or "after" (and "to") the places join the route in
  -- that order (ADDWPT each). An airport gone to stays a destination or is asked (below).
  -- "add PIX into route and fly to there", "..., then go to it", "... and fly there": the waypoint the request
  -- adds before, flown to directly ("there"/"it" closing the clause)
  rule { "go fly head", "direct", when = function(g, i)
    local k = g:word(i + 1, "to") and i + 2 or i + 1
    if not g:word(k, "there it") then return false end
    local nx = g.t[k + 1]
    if nx and not (nx.kind == "punct" or g:word(k + 1, "and then please now directly direct")) then return false end
    for j = 1, i - 1 do
      if g:intent_at(j) == "addwpt" and g:has_ref(j + 1, i, "waypoint") then return true end
    end
    return false
  end }
  -- ("swa3 head to MERIT": "head" as "go"; "send SWA3 to CAMRN": the aircraft sent between the verb and its "to")
  rule { "send", "direct", when = function(g, i)
    local r = g:refs_in(i + 1, i + 2, "aircraft")[1]
    local e = r ~= nil and r.b == i + 1 and g:word(r.e, "to") and g:place_gone_to(r.e + 1)
    return e and not g:word(e, "then after and") or false
  end }
  rule { "go fly head", "direct", next = "to", when = function(g, i)
    local e = not g:word(i - 1, "@purpose_modals") and g:place_gone_to(i + 2)
    if not e then return false end
    local x = g:word(e, "and") and e + 1 or e
    if g:word(x, "after") and not g:word(x + 1, "to") then return false end  -- ("after EXIT3": AFTER's place)
    local n = g:word(x, "then after") and (g:word(x + 1, "to") and x + 2 or x + 1)
    return not (n and g:place_gone_to(n))
  end }
  rule { "go fly head", "addwpt", next = "to", when = function(g, i)
    local e = not g:word(i - 1, "@purpose_modals") and g:place_gone_to(i + 2)
    if not e then return false end
    local x = g:word(e, "and") and e + 1 or e
    local n = g:word(x, "then") and (g:word(x + 1, "to") and x + 2 or x + 1)
      or g:word(x, "after") and g:word(x + 1, "to") and x + 2
    return n and g:place_gone_to(n) and true or false
  end }
  -- "fly to TEST1", "fly to our waypoint STUDYA": a waypoint the simulation knows is flown to directly;
  -- other places are destinations
  rule { "fly", "direct", next = "to", when = function(g, i)
    local k = i + 2
    while g:word(k, "the our my a @waypoint_nouns point") do k = k + 1 end
    local t = g.t[k]
    for _, w in ipairs(g.world.waypoints or {}) do
      if t and w:upper() == t.raw:upper() then return true end
    end
    return false
  end }
  -- "fly to ALGOI directly": a waypoint (no airport) flown to directly, said after it
  rule { "fly", "direct", next = "to", when = function(g, i)
    local k = g:skip_fillers(i + 2)
    local r = g:refs_in(k, k + 1, "waypoint")[1]
    return r ~= nil and not r.name:match("^%a%a%a%a$") and g:word(g:skip_fillers(r.e), "directly direct")
  end }
  -- ("fly to heading 045", "fly to flight level 200": a value, no place)
  rule { "fly", false, next = "to", when = function(g, i)
    return g:word(i + 2, "heading hdg flight fl level altitude speed") or g.t[i + 2] ~= nil and g.t[i + 2].kind == "number"
  end }
  rule { "fly", "dest", next = "to" }
  -- "can it fly .78", "fly point eight two": a Mach number said bare after the verb (a fraction of one, no
  -- unit) is the speed flown
  -- "VLG1003 point seven four": a Mach number said in words after an aircraft, nothing else in the request
  rule { "point", "spd", when = function(g, i)
    local q = g:quantities(i, i + 4)[1]
    if not (q and q.b == i and q.kind == "plain" and q.value >= 0.4 and q.value < 1) then return false end
    for k = 1, #g.t do
      if (k < q.b or k >= q.e) and g.t[k].kind ~= "punct" and not g.t[k].filler and not g:has_ref(k, k + 1, "aircraft") then
        return false
      end
    end
    return g:has_ref(1, i, "aircraft")
  end }
  rule { "fly", "spd", when = function(g, i)
    local q = g:quantities(i + 1, i + 5)[1]
    return q ~= nil and q.b == i + 1 and (q.kind == "mach" or (q.kind == "plain" and q.value >= 0.4 and q.value < 1))
  end }
  -- "fly at Mach 0.80", "set Mach 0.80", "fly at 260 knots": a speed with its unit (knots or Mach) straight after
  -- "fly at" or "set" is the speed flown
  rule { "fly set", "spd", when = function(g, i)
    local v = g:word(i, "fly") and i + 2 or i + 1
    if g:word(i, "fly") and not g:word(i + 1, "at") then return false end
    local q = g:quantities(v, v + 4)[1]
    return q ~= nil and q.b == v and (q.kind == "mach" or q.kind == "speed")
  end }
  -- (no origin where a relative clause says where the aircraft comes from to identify it: G:relative_departure)
  rule { "departed departing", false, when = function(g, i) return g:relative_departure(i) or g:departure_described(i) ~= nil end }
  -- ("it is departing to Chennai", "departing for Delhi": where it goes, a description, lexicon.described_places)
  rule { "departed departing", false, next = "to for towards" }
  rule { "origin departed departing orig", "orig" }
  -- "set departure airport EDDL", "CFG7TK departure aerodrome EDDF": the airport it departed named
  rule { "departure", "orig", next = "airport aerodrome airfield" }
  -- "make WJA3101 come from victoria, CYYJ", "it came from CYHU": an airport's code (four letters) said
  -- after "from", within four words, is where the aircraft comes from ("coming from the north" is none)
  rule { "come comes coming came", "orig", next = "from", when = function(g, i)
    for _, r in ipairs(g:refs_in(i + 2, math.min(#g.t + 1, i + 7), "waypoint")) do
      if r.name:match("^%a%a%a%a$") and g:has_ref(1, i, "aircraft") then return true end
    end
    return false
  end }
  rule { "lnav", "lnav" }
  -- "stop BAW123 following its route": its lateral navigation off
  rule { "stop", "lnav", near = { 4, "following follow" }, when = function(g, i)
    -- ("stop WJA1522 from following its waypoints": the route named by its points)
    return g:followed_by(i, 7, "@route_nouns waypoints") and not g:word_in(math.max(1, i - 2), i, "don't dont not never")
      and (g:has_ref(i + 1, i + 4, "aircraft") or g:has_ref(math.max(1, i - 3), i, "aircraft"))
  end }
  -- "switch off the automatic route following for the KLM": "route following", the noun switched, is lateral
  -- navigation
  rule { "following", "lnav", prev = { 1, "route" }, when = function(g, i)
    return g:word_in(math.max(1, i - 6), math.min(#g.t + 1, i + 6), "on off switch disable enable activate deactivate")
  end }
  -- ("lateral nav off", "vertical nav on": "nav" is navigation's short word)
  rule { "lateral", "lnav", next = "navigation nav" }
  rule { "vnav", "vnav" }
  -- "proceed direct DJB, comply with restrictions", "comply with published speed and altitude restrictions": the
  -- route's levels and speeds flown (VNAV); restrictions of one kind only ("comply with speed restrictions") are
  -- no switch squawk has (beside a level, rate or heading given, which VNAV would undo, asked: m:vnav)
  rule { "comply", "vnav", next = "with", when = function(g, i)
    local k, said = i + 2, {}
    while g:word(k, "the all published charted procedure procedural speed altitude level and") do
      said[g.t[k].text] = true
      k = k + 1
    end
    return g:word(k, "restriction restrictions") and (said.speed or false) == ((said.altitude or said.level) or false)
  end }
  -- "let RYR3PW manage its own altitude along its route", "manage its height by itself": the route's levels flown
  -- by the aircraft itself, in plain words (VNAV)
  rule { "manage", "vnav", near = { 3, "altitude height level levels" }, when = function(g, i)
    return g:word_in(i + 1, math.min(#g.t + 1, i + 3), "its their his her own") and g:has_ref(1, #g.t + 1, "aircraft")
  end }
  rule { "vertical vertically", "vnav", prev = { 4, "plan route" } }  -- "follow its flight plan vertically"
  rule { "vertical", "vnav", next = "profile navigation nav" }
  -- "AAR8917 its route show me please", "KAL12 route display": the verb of showing after the route (verb-final
  -- order), an aircraft named straight before it ("its" between or not), nothing else in its clause but "me"/"us"
  -- and "please": its route listed
  rule { "route rte routing waypoints", "listrte", when = function(g, i)
    local b = g:word(i - 1, "its his her the") and i - 1 or i
    local r = g:refs_in(1, b, "aircraft")
    r = r[#r]
    if not (r and r.exists and g:skip_fillers(r.e) == b) then return false end
    local k = i + 1
    if not g:word(k, "show display list") then return false end
    k = k + 1
    while g:word(k, "me us please") or (g.t[k] and g.t[k].filler) do k = k + 1 end
    return g.t[k] == nil or (g.t[k].kind == "punct" and g.t[k].text ~= ",")
  end }
  -- ("dump the route for speedbird 432", "dump ryanair 82MN route": a programmer's "dump" is "show")
  rule { "route rte routing waypoints", "listrte", prev = { 4, "show list display what print see look where check dump" } }
  -- ("EIN112 wpts?", "KLM12 route?": the route's noun asked about straight after an aircraft flying, nothing else)
  rule { "route rte routing waypoints wpts", "listrte", when = function(g, i)
    local a = g:refs_in(1, i, "aircraft")
    a = a[#a]
    -- ("SAS2204 route plz": "please" closing it as well as a question mark)
    if not (a ~= nil and a.exists and a.e == i and g:skip_fillers(1) == a.b) then return false end
    local k = i + 1
    while g.t[k] and (g.t[k].filler or g:word(k, "please plz pls")) do k = k + 1 end
    return (k > i + 1 and g.t[k] == nil) or (g.t[k] ~= nil and g.t[k].text == "?" and g.t[k + 1] == nil)
  end }
  -- ("Delta 401 flight plan please", "KLM12 flight plan?": the plan's noun straight after an aircraft flying opening the
  -- request, "please" at most after it)
  rule { "plan", "listrte", prev = { 1, "flight" }, when = function(g, i)
    local a = g:refs_in(1, i, "aircraft")
    a = a[#a]
    if not (a and a.exists and a.e == i - 1 and g:skip_fillers(1) == a.b) then return false end
    local k = i + 1
    while g.t[k] and (g.t[k].filler or g.t[k].kind == "punct" or g:word(k, "please")) do k = k + 1 end
    return g.t[k] == nil
  end }
  -- ("which route he has?", "which route has?": an Italian speaker's "che rotta ha?", "which" straight before it)
  -- (its clause ending there)
  rule { "route rte", "listrte", prev = { 1, "which" }, when = function(g, i)
    local k = g:word(i + 1, "he she it") and i + 2 or i + 1
    if not g:word(k, "has have") then return false end
    return g.t[k + 1] == nil or g.t[k + 1].kind == "punct"
  end }
  -- ("which route has the Eurowings 5LP, please?", "which route does KLM12 have?": a German speaker's "welche Route
  -- hat ...", the aircraft flying after "has"/"does", then "have" at most, closing the clause)
  rule { "route rte", "listrte", prev = { 1, "which what" }, when = function(g, i)
    if not g:word(i + 1, "has does") then return false end
    local r = g:refs_in(i + 2, g:word(i + 2, "the") and i + 4 or i + 3, "aircraft")[1]
    if not (r and r.exists and r.b <= i + 3) then return false end
    local k = g:skip_fillers(r.e)
    if g:word(i + 1, "does") and g:word(k, "have") then k = g:skip_fillers(k + 1) end
    while g:word(k, "please currently now") do k = k + 1 end
    return g.t[k] == nil or g.t[k].kind == "punct"
  end }
  -- "the route of Turkish 4KZ please to show", "route for KLM12 to show please": the request opening with the
  -- route of an aircraft flying, the verb of showing last ("please", "to" before it), nothing else in its clause
  rule { "route rte routing", "listrte", when = function(g, i)
    local first = g:skip_fillers(1)
    if not (first == i or (first == i - 1 and g:word(i - 1, "the"))) or not g:word(i + 1, "of for") then return false end
    local r = g:refs_in(i + 2, #g.t + 1, "aircraft")[1]
    if not (r and r.exists and r.b == i + 2) then return false end
    local k = r.e
    while g:word(k, "please to") do k = k + 1 end
    if not g:word(k, "show display list") then return false end
    k = k + 1
    while g:word(k, "me us please") or (g.t[k] and g.t[k].filler) do k = k + 1 end
    return g.t[k] == nil or (g.t[k].kind == "punct" and g.t[k].text ~= ",")
  end }
  -- "show me the position and the route of OAW61", "what are the position and route of DLH44": the route said
  -- after another shown state ("position", "state", "data"), joined by "and", a verb of showing or asking
  -- before it
  rule { "route rte routing waypoints", "listrte", prev = { 3, "and" }, when = function(g, i)
    local k = g:word(i - 1, "the its") and i - 2 or i - 1
    if not g:word(k, "and") or not g:word(k - 1, "position pos state data details") then return false end
    return g:find_word(math.max(1, k - 7), k, "show list display what print see give tell") < k
  end }
  -- "pull up the route for the United", "bring up the flight plan of KLM12", "call up its routing": a phrasal verb
  -- of showing, "up" straight after it, before the noun
  rule { "route rte routing waypoints plan", "listrte", when = function(g, i)
    local k = g:find_word(math.max(1, i - 4), i, "pull bring call")
    return k < i and g:word(k + 1, "up")
  end }
  -- "what is the next waypoint of Akasa 1402": the route's next point, shown with the route
  rule { "waypoint", "listrte", prev = { 1, "next active" }, when = function(g, i) return g:preceded_by(i, 5, "what which") end }
  -- "let's get the route for the American up on screen", "put the United's route on the screen", "put Speedbird
  -- one two three's route up on the board": the route shown, "on (the) screen" (or scope, display, board, map)
  -- within six words after the noun, a verb of showing or placing at most seven before it
  rule { "route rte routing waypoints plan", "listrte", when = function(g, i)
    local k = g:find_word(i + 1, math.min(#g.t + 1, i + 7), "on")
    local e = g:word(k + 1, "the") and k + 2 or k + 1
    return k <= i + 6 and g:word(e, "screen scope display board map")
      and g:find_word(math.max(1, i - 7), i, "get put bring have show") < i
  end }
  -- "tell me the route of the Emirates", "kindly tell the route of Air India 540": the route told to the speaker
  -- ("tell KLM12 to follow its route" instructs)
  -- ("please tell me the Jin Air's route": only "the", the aircraft and its "'s" between "me" and the noun)
  rule { "route rte routing waypoints", "listrte", when = function(g, i)
    local k = g:find_word(math.max(1, i - 4), i, "tell")
    if k < i then return g:word(k + 1, "me us") or (k + 2 == i and g:word(k + 1, "the")) end
    k = g:find_word(math.max(1, i - 8), i, "tell")
    if not (k < i and g:word(k + 1, "me us")) then return false end
    local named, x = false, k + 2
    while x < i do
      local r = g:refs_in(x, i, "aircraft")[1]
      if r and r.b == x then
        x, named = r.e, true
      elseif g:word(x, "the 's s") or (g.t[x].kind == "punct" and g.t[x].text == "'") then
        x = x + 1
      else
        return false
      end
    end
    return named
  end }
  -- ("what's your plan for the Transavia?" asks the addressee's own intentions: no route listed)
  rule { "plan", "listrte", prev = { 4, "show list display what print see look where check" },
         not_prev = { 1, "your our my" } }
  -- ("have a look at Emirates four five's flight plan": "look at" and a spoken callsign's words before "flight plan")
  rule { "plan", "listrte", prev = { 1, "flight" }, when = function(g, i)
    local k = g:find_word(math.max(1, i - 8), i, "look")
    if not (k < i and g:word(k + 1, "at") and g:has_ref(k + 2, i, "aircraft")) then return false end
    for x = k + 2, i - 1 do
      if g.t[x].kind == "punct" then return false end
    end
    return true
  end }
  rule { "list", "listrte", prev = { 1, "waypoint" }, near = { 3, "for of" } }  -- "the waypoint list for BAW123"
  -- "ryr8gn say route", "say your routing": the aircraft asked for its route, as "say altitude" for its state
  rule { "route rte routing", "listrte", prev = { 2, "say" } }
  -- ("KAL123 route information please", "route details for BAW12": the route's noun before a noun of information)
  rule { "route rte routing", "listrte", next = "information info details data" }
  -- "KAC12, confirm the route", "verify your routing": the same, the noun closing its clause ("confirm the route
  -- via X" asks whether a clearance stands)
  rule { "route rte routing", "listrte", prev = { 2, "confirm verify" }, when = function(g, i)
    local k = i + 1
    while g.t[k] and g.t[k].filler do k = k + 1 end
    return not g.t[k] or g.t[k].kind == "punct"
  end }
  -- "read me back your route", "read back the routing": the pilot asked to say the route
  rule { "read", "listrte", next = "back me", when = function(g, i)
    return g:followed_by(i, 4, "route rte routing") and not g:has_ref(1, #g.t + 1, "waypoint")
  end }
  -- "show me KLM one two seven six's route": the verb before the aircraft the route is of
  -- ("pull up Air Canada 871's flight plan", "bring up the KLM's route")
  rule { "route waypoints plan routing", "listrte", when = function(g, i)
    local at = g:word(i - 1, "flight") and g:word(i, "plan") and i - 1 or i
    for _, r in ipairs(g:refs_in(1, i, "aircraft")) do
      if r.e == at and g:preceded_by(r.b, 3, "show list display print see pull bring") then return true end
      -- ("what's Ryanair 8WL's route", "what's the Easy routing": asked with the noun ending the request)
      if r.e == at and g:preceded_by(r.b, 3, "what what's whats") and (not g.t[i + 1] or g.t[i + 1].kind == "punct") then
        return true
      end
    end
    return false
  end }
  -- "baw836 route?", "ryr3nk route pls": an aircraft and the noun alone ask for its route
  rule { "route rte", "listrte", when = function(g, i) return g:alone_with_aircraft(i) end }
  -- "Copa 245 route please, show it", "KLM12 route, display", "CAL502 route list please", "KAL8 position
  -- check": the same, a verb of showing said after the noun (verb-final order; its object "it" or "me" at
  -- most) closing the request
  local function shown_after(g, i)
    local k = i + 1
    while g.t[k] and (g.t[k].kind == "punct" or g.t[k].filler) do k = k + 1 end
    if not g:word(k, "show display check list") then return false end
    local e = g:word(k + 1, "it me") and k + 2 or k + 1
    for x = e, #g.t do
      if g.t[x].kind ~= "punct" and not g.t[x].filler then return false end
    end
    return g:alone_with_aircraft(i, k, e)
  end
  rule { "route rte", "listrte", when = shown_after }
  -- "route of klm1234?", "route of Kenya 480 please": the request opens with the noun and asks, or
  -- names only the aircraft after it
  rule { "route", "listrte", next = "of for", when = function(g, i)
    if not g:alone_but(i, #g.t + 1) then return false end
    if g.t[#g.t].text == "?" then return true end
    local r = g:refs_in(i + 2, i + 3, "aircraft")[1]
    return r ~= nil and g:alone_but(i, r.e)
  end }
  -- "give me the route of LOT3KL", "give us KLM12's waypoints": the route given to the speaker, shown
  rule { "route rte waypoints", "listrte", when = function(g, i)
    for k = math.max(1, i - 5), i - 1 do
      if g:word(k, "give") and g:word(k + 1, "me us") then return true end
    end
    return false
  end }
  rule { "listrte", "listrte" }
  -- "what's IBE32 got left on its flight plan", "what's left of the Vueling's route", "what remains of KLM12's
  -- routing": the rest of its route asked, the question opening the request (no value said)
  rule { "route plan routing waypoints", "listrte", when = function(g, i)
    return g:word(g:skip_fillers(1), "what what's whats") and g:word_in(math.max(1, i - 5), i, "left remaining remains")
      and g:has_ref(1, i, "aircraft") and #g:quantities(1, #g.t + 1) == 0
  end }

  -- information and repositioning
  rule { "where", false, near = { 5, "route" } }  -- "show me where its route goes": the route is listed
  -- "show us where JetBlue 615 is going, like its list of stops", "where is it heading, the route": where it goes,
  -- said with its route or its stops after the verb of going (no value said), is the route listed
  rule { "where where's wheres", "listrte", when = function(g, i)
    local e = math.min(#g.t + 1, i + 7)
    local k = g:find_word(i + 1, e, "going headed heading flying")
    if k == e or #g:quantities(1, #g.t + 1) > 0 then return false end
    local last = math.min(#g.t + 1, k + 9)
    return g:find_word(k + 1, last, "route routing stops waypoints") < last
  end }
  -- "where is the Shamrock routing?", "show me where KLM12 is routed", "where's the Speedbird going next?": the
  -- route asked (the question's verb, or "next" after a verb of going, within the seven words after "where")
  rule { "where where's wheres", "listrte", when = function(g, i)
    local e = math.min(#g.t + 1, i + 8)
    local k = g:find_word(i + 1, e, "routing routed")
    local n = g:find_word(i + 1, e, "next")
    return (k < e or (n < e and g:word_in(i + 1, n, "going heading headed off flying"))) and g:has_ref(i + 1, e, "aircraft")
      and #g:quantities(i, #g.t + 1) == 0
  end }
  -- "where is the Air Portugal going?", "where's TAP447 headed to", "Easy 89QP, where's he going?": where it
  -- goes asked, not the position: its route, which ends at its destination (writers read DEST, LISTRTE or POS;
  -- LISTRTE answers every one); the question opens the request, or follows the aircraft alone, and ends with its
  -- verb ("where is UAL57 going to cross GIPNO?" and "too high for where it's going" are no such question)
  -- (a callsign said in words may take six: "where is Scandinavian four four two one going, show the route")
  rule { "where where's wheres", "listrte", when = function(g, i)
    local e = math.min(#g.t + 1, i + 10)
    local k = g:find_word(i + 1, e, "going headed bound")
    local first = g:skip_fillers(1)
    local r = g:refs_in(first, first + 1, "aircraft")[1]
    local after = r and r.b == first and g:skip_fillers(g.t[r.e] and g.t[r.e].text == "," and r.e + 1 or r.e)
    if k == e or (first ~= i and after ~= i) then return false end
    if g:word(k + 1, "to") then k = k + 1 end
    return g.t[k + 1] == nil or g.t[k + 1].kind == "punct"
  end }
  -- "reduce by 20 knots, relative to what it is doing at the moment", "compared with what it flies now": the
  -- value an amount is counted from (the present one), no question of the aircraft's state
  rule { "what doing", false, prev = { 5, "@counted_from" } }
  rule { "where", "pos", next = "is are 's" }
  -- "Air Peace 7124 where you dey now", "where you are now": the addressee asked where it is, in the statement's
  -- order (Nigerian Pidgin "dey": be); after a verb of staying ("stay where you are") it is no question
  rule { "where", "pos", next = "you", when = function(g, i)
    return g:word(i + 2, "are dey") and not g:word(i - 1, "stay stays remain remains keep keeps hold holds right just from")
  end }
  rule { "where's wheres", "pos" }  -- ("wheres the speedbird": typed without the apostrophe)
  rule { "doing", "pos", prev = { 4, "what what's whats" } }  -- "what's klm12 doing"
  -- ("what are Iberia 3170 and Vueling 22RW doing": two aircraft or more asked about, "what are" before them)
  rule { "doing", "pos", when = function(g, i)
    local named, n = {}, 0
    for _, r in ipairs(g.refs) do
      if r.kind == "aircraft" and r.e <= i then
        n = n + 1
        for k = r.b, r.e - 1 do named[k] = true end
      end
    end
    if n < 2 or not (g:word(1, "what") and g:word(2, "are")) then return false end
    for k = 3, i - 1 do
      if not (named[k] or g.t[k].kind == "punct" or g:word(k, "and the")) then return false end
    end
    return true
  end }
  -- ("how's the Easy getting on?": the aircraft's progress asked)
  rule { "getting", "pos", next = "on", prev = { 5, "how's hows how" } }
  -- "what's Qantas one four one doing", "what is Velocity 923 doing": a callsign said in words of any length;
  -- at most two of lexicon.indirect_question_adverbs between it and "doing" ("what is the Emirates actually
  -- doing?", German "aktuell": at present)
  rule { "doing", "pos", when = function(g, i)
    local e = i
    while e > i - 2 and g:word(e - 1, "@indirect_question_adverbs") do e = e - 1 end
    for _, r in ipairs(g.refs) do
      if r.kind == "aircraft" and r.e == e then
        local k = g:word(r.b - 1, "the") and r.b - 2 or r.b - 1
        k = g:word(k, "is") and k - 1 or k
        -- (a spoken callsign's reference may take in the question's words before it: "what is LOT two eight")
        return g:word(k, "what what's whats") or g:word(r.b, "what what's whats")
      end
    end
    return false
  end }
  -- an indirect question ("could you tell me what Speedbird 8CK is currently doing", "I'd like to know what
  -- the easyJet is doing"), or a Portuguese speaker's direct one in that order ("what the LATAM 3320 is doing?"):
  -- "what", "the" or not, the aircraft, "is" or "are", at most two of lexicon.indirect_question_adverbs, then "doing"
  -- (Nigerian Pidgin's "wetin Arik 104 dey do": "dey" for "is", lexicon.typed_abbreviations)
  rule { "doing", "pos", when = function(g, i)
    local k = i - 1
    while k > i - 3 and g:word(k, "@indirect_question_adverbs") do k = k - 1 end
    if not g:word(k, "is are dey") then return false end
    for _, r in ipairs(g.refs) do
      if r.kind == "aircraft" and r.e == k then
        return g:word(r.b - 1, "what") or g:word(r.b, "what") or (g:word(r.b - 1, "the") and g:word(r.b - 2, "what"))
      end
    end
    return false
  end }
  -- "how's VIR3 doing", "how is the Speedbird doing?", "VIR3, how's it doing": "how" ("is" or its "'s"), the
  -- aircraft or its pronoun, then "doing"
  rule { "doing", "pos", when = function(g, i)
    local k = i - 1
    if g:word(k, "it he she") then
      k = k - 1
    else
      local named = false
      for _, r in ipairs(g.refs) do
        if r.kind == "aircraft" and r.e == i then k, named = g:word(r.b - 1, "the") and r.b - 2 or r.b - 1, true end
      end
      if not named then return false end
    end
    if g:word(k, "is 's") then k = k - 1 end
    return g:word(k, "how how's hows") and (k == 1 or g.t[k - 1].kind == "punct" or g:has_ref(1, k, "aircraft"))
  end }
  -- the question in the order of a statement, "what" closing the request ("the TACA is doing what?", "KLM12 is
  -- doing what now", a Spanish speaker's "está haciendo qué"): the aircraft, "is" or "are" or neither, at most two
  -- of lexicon.indirect_question_adverbs, then "doing what"
  rule { "doing", "pos", when = function(g, i)
    local w = g:word(i + 2, "now") and i + 3 or i + 2
    if not g:word(i + 1, "what") or (g.t[w] and g.t[w].kind ~= "punct") then return false end
    local k = i - 1
    while k > i - 3 and g:word(k, "@indirect_question_adverbs") do k = k - 1 end
    if g:word(k, "is are") then k = k - 1 end
    for _, r in ipairs(g.refs) do
      if r.kind == "aircraft" and r.e == k + 1 then return true end
    end
    return false
  end }
  -- "where's EZY45?" (the lexer drops the 's), "tell me where BAW123 is"
  rule { "where", "pos", when = function(g, i) return g:has_ref(i + 1, i + 5, "aircraft") end }
  -- "where's the MERIT intersection?"
  rule { "where", "pos", when = function(g, i) return g:has_ref(i + 1, i + 4, "waypoint") end }
  rule { "where", "pos", prev = { 3, "know show tell indicate" } }  -- "show me where GATE1 is"
  -- "tell me about the easyJet", "tell us about KLM12", "what do we know about Air Baltic 4WB": an aircraft and
  -- nothing after it, its state asked
  rule { "about", "pos", when = function(g, i)
    local told = g:word(i - 1, "me us") and g:word(i - 2, "tell")
      or g:word(i - 1, "know") and g:word(i - 2, "we you i") and g:word(i - 3, "do")
    return told and aircraft_alone(g, g:skip_fillers(i + 1), true)
  end }
  rule { "where", "pos", when = function(g, i) return g:skip_fillers(1) == i end }  -- "where's Schiphol"
  -- "exp1 where", "KL204 where now?": the question typed after the aircraft, nothing after it
  rule { "where", "pos", when = function(g, i)
    local k = g:word(i + 1, "now") and i + 2 or i + 1
    return (g.t[k] == nil or g.t[k].kind == "punct") and g:has_ref(math.max(1, i - 2), i, "aircraft")
  end }
  -- "what's RYR2BA at", "what is the Ryanair at now?": where an aircraft is (its level and position), asked
  -- with "what" opening the request and "at" ending it after the aircraft
  rule { "what what's whats", "pos", when = function(g, i)
    if g:skip_fillers(1) ~= i then return false end
    local r = g:refs_in(g:word(i + 1, "is") and i + 2 or i + 1, #g.t + 1, "aircraft")[1]
    if not r or r.b > i + 3 or not g:word(r.e, "at") then return false end
    local k = g:word(r.e + 1, "now") and r.e + 2 or r.e + 1
    return g.t[k] == nil or (g.t[k].kind == "punct" and k == #g.t)
  end }
  rule { "state", false, next = "based" }  -- "state-based conflict detection": CDMETHOD's method
  rule { "dump", false, next = "the its", near = { 4, "state position details status" } }  -- "dump the state of ..."
  -- "a320 EIN77 fl 200 pos NIMAT hdg 100": "pos" before a place, in a request that names an aircraft type,
  -- is where a new aircraft is placed (the creation's position), no request to show one
  rule { "pos", false, when = function(g, i)
    local nx = g.t[i + 1]
    return nx ~= nil and (g:has_ref(i + 1, i + 2, "waypoint") or nx.kind == "number")
      and g:has_ref(1, #g.t + 1, "type")
  end }
  -- "lnav status klm1607?", "the vnav state of KLM12", "status of lnav for X": the switch's state, asked by the
  -- switch's own query (handlers_other m:nav_asked), no position report; "cd status", "conflict detection status":
  -- the simulation's switch shown by its own command (m:switch), no aircraft's position
  rule { "status state", false, when = function(g, i)
    return g:word(i - 1, "lnav vnav") or g:word(i - 2, "lnav vnav") and g:word(i - 1, "the its")
      or g:word(i + 1, "of") and g:word(i + 2, "lnav vnav")
      or g:word(i, "status") and (g:word(i - 1, "cd asas detection resolution reso cr")
        or g:word(i + 1, "of") and g:word(g:word(i + 2, "the") and i + 3 or i + 2, "cd asas conflict resolution reso"))
  end }
  -- ("EZY45QM say state", a military controller's question of the fuel left, which squawk does not simulate: no
  -- state shown; "say state of KLM12's altitude" and "show the state" stay POS)
  rule { "state", false, prev = { 1, "say" }, when = function(g, i)
    return g.t[i + 1] == nil or g.t[i + 1].kind == "punct"
  end }
  rule { "details status info information state pos", "pos", not_prev = { 1, "route rte routing" } }
  -- "show me both of them, KLM12 and EIN45", "KLM12 and EIN45 are in conflict, show me the both of them": the
  -- aircraft named shown together, the words after the verb only those aircraft and lexicon.shown_together
  -- ("both" when two are named; "them" or "both" standing for those named before the verb); no value and no instruction
  -- word in the request
  rule { "show display", "pos", when = function(g, i)
    if #g:quantities(1, #g.t + 1) > 0 then return false end
    local named, after, both, them = 0, 0, false, false
    for _, r in ipairs(g.refs) do
      if r.kind == "aircraft" then
        named = named + 1
        if r.b > i then after = after + 1 end
      end
    end
    local k = g:word(i + 1, "me us") and i + 2 or i + 1
    while k <= #g.t do
      local r = g:refs_in(k, k + 1, "aircraft")[1]
      if r then
        k = r.e
      else
        if not (g.t[k].kind == "punct" or g.t[k].filler or g:word(k, "@shown_together")) then return false end
        both, them = both or g:word(k, "both"), them or g:word(k, "them")
        k = k + 1
      end
    end
    for x = 1, i - 1 do
      if g:intent_at(x) then return false end
    end
    return named >= 2 and not (both and named ~= 2) and (after == named or ((them or both) and after == 0))
  end }
  -- "show me Wideroe five one two", "check IBE3421": an aircraft alone after the verb is shown where it is
  -- ("pause, and show me the Swiss three eight foxtrot": the clause of its own; "check Emirates 783 for me", "for
  -- me" or "for us" after it)
  -- ("show me Moonflower 31 data": a noun of its state after it)
  rule { "show display check", "pos", when = function(g, i)
    local k = g:skip_fillers(g:word(i + 1, "me us") and i + 2 or i + 1)
    local r = g:refs_in(k, k + 1, "aircraft")[1]
    local e = r and g:word(r.e, "for") and g:word(r.e + 1, "me us") and r.e + 2 or r and r.e
    if e and g:word(e, "data details info information status state") then e = e + 1 end
    return r ~= nil and (g:alone_but(i, e) or g:clause_alone(i, e))
  end }
  -- "show me Ezeiza airport", "show me the Santiago airport", "show me SAEZ": a place alone after the verb, no
  -- aircraft named, is shown where it is
  rule { "show display", "pos", when = function(g, i)
    if g:has_ref(1, #g.t + 1, "aircraft") then return false end
    local k = g:skip_fillers(g:word(i + 1, "me us") and i + 2 or i + 1)
    local last = #g.t
    while last > k and (g.t[last].kind == "punct" or g.t[last].filler) do last = last - 1 end
    -- (a waypoint of the scene, or an ident the navdata holds: "show me YQB" with no traffic; a waypoint noun
    -- before or after it, "show me waypoint TESTA", "show the TESTA fix", and "where" closing the request, "show me
    -- waypoint TESTA where", ask the same)
    local p, e = k, last
    if g:word(p, "@waypoint_nouns") then p = g:skip_fillers(p + 1) end
    if e > p and g:word(e, "where") then e = e - 1 end
    while e > p and (g.t[e].kind == "punct" or g.t[e].filler) do e = e - 1 end
    if e > p and g:word(e, "@waypoint_nouns") then e = e - 1 end
    local r = g:refs_in(p, p + 1, "waypoint")[1]
    local at = g.world.user_waypoint_at
    if r and r.e == e + 1 and (r.exists or (at and at(r.name) ~= nil)) then return true end
    if not g:word(last, "@airport_nouns") or last - k < 1 or last - k > 3 then return false end
    for x = k, last - 1 do
      if g.t[x].kind ~= "word" or not g.t[x].raw:match("^%u") then return false end
    end
    return true
  end }
  -- "Kindly provide the actual position of RYR72KP", "give the level and speed of RYR5QX": a verb of
  -- giving, then only state nouns (joined by "and", "/" or commas) and "of" or "for" an aircraft, no value
  -- said in the request: a question of the aircraft's state (POS). state_asked gives that aircraft's
  -- reference, or nil.
  -- state_words: from token k, a determiner (one of `determiners`), "present", then the state nouns
  -- (`nouns_said`) joined by "and", "/" or commas; the token after them and how many nouns were said.
  local function state_words(g, k, determiners, nouns_said)
    if g:word(k, determiners) then k = k + 1 end
    if g:word(k, "@present") then k = k + 1 end
    local nouns = 0
    while g:word(k, nouns_said) or g:word(k, "and / ,") do
      if not g:word(k, "and / ,") then nouns = nouns + 1 end
      k = k + 1
    end
    return k, nouns
  end
  local function state_asked(g, i)
    if #g:quantities(1, #g.t + 1) > 0 then return nil end
    local k, nouns = state_words(g, g:skip_fillers(g:word(i + 1, "me us") and i + 2 or i + 1), "the its",
      "position level altitude speed heading mach airspeed vertical ground")
    if nouns == 0 or not g:word(k, "of for") then return nil end
    return g:refs_in(k + 1, k + 2, "aircraft")[1]
  end
  -- ("please help me check speed of Nok Air 315": a verb of looking at the state, the same)
  -- ("say me please the speed of X", "give me the vertical speed of X": "say" too, a courtesy before the noun,
  -- the vertical or ground speed)
  rule { "provide give tell report check say query", "pos", when = function(g, i) return state_asked(g, i) ~= nil end }
  -- "I need the position of TAP1017": the same wanted, when the clause ends with the aircraft (not "I want
  -- the position of TAP1017 changed")
  rule { "need want require", "pos", when = function(g, i)
    local r = state_asked(g, i)
    if not r then return false end
    local k = g:skip_fillers(r.e)
    return k > #g.t or g.t[k].kind == "punct"
  end }
  -- "show me BAW87L's position", "query DLH9KM's position"
  rule { "position", "pos", prev = { 4, "show display see look log record dump query" } }
  -- "show Cyprus seven one six position": a callsign of spoken digits between the verb and the noun
  rule { "position", "pos", prev = { 12, "show display" }, when = function(g, i)
    for _, r in ipairs(g:refs_in(math.max(1, i - 10), i, "aircraft")) do
      local b = g:word(r.b - 1, "me") and r.b - 2 or r.b - 1
      if r.e == i and g:word(b, "show display") then return true end
    end
    return false
  end }
  -- "show me the data of KLM12", "display KLM12's flight data": an aircraft's data shown is its state (POS)
  rule { "data", "pos", prev = { 5, "show display see give" }, when = function(g, i)
    return g:word(i + 1, "of for") and g:has_ref(i + 2, i + 3, "aircraft")
      or g:has_ref(g:word(i - 1, "flight") and i - 2 or i - 1, i, "aircraft")
  end }
  -- "Position of Sunturk two papa alpha?", "KLM1234 position?": the noun and an aircraft ask for it
  rule { "position", "pos", when = function(g, i) return g:alone_with_aircraft(i) end }
  -- "DLH458 ETA?", "eta QTR1015": the estimate asked with the aircraft alone, answered by its state (POS)
  rule { "eta", "pos", when = function(g, i) return g:alone_with_aircraft(i) end }
  rule { "position", "pos", when = shown_after }
  -- "show the route of KLM12 and its position", "display the route and position of KLM12": the noun joined by
  -- "and" (then "its" or "the" at most) to what a verb of showing said before it shows is shown too
  rule { "position", "pos", when = function(g, i)
    local k = g:word(i - 1, "its the his her") and i - 2 or i - 1
    if not g:word(k, "and") then return false end
    return g:word_in(math.max(1, k - 8), k, "show display see list")
  end }
  rule { "position", "pos", next = "of", when = function(g, i) return g:skip_fillers(1) == i end }
  -- "place EZY45, A319, at 38.4 N 6.6 W heading 290", "place a Ryanair, RYR5GH, B738, over LOREL ...": a
  -- callsign no aircraft has, with its type, is created
  rule { "place", "create", when = function(g, i)
    local k = g:word(i + 1, "a an") and g:airline_at(i + 2) and select(2, g:airline_at(i + 2)) or i + 1
    if g.t[k] and g.t[k].kind == "punct" then k = k + 1 end
    local r = g:refs_in(k, math.min(#g.t + 1, k + 2), "aircraft")[1]
    return r ~= nil and not r.exists and g:has_ref(r.e, math.min(#g.t + 1, r.e + 4), "type")
  end }
  -- "place a Boeing 747 with callsign VIR3 at DVR ...", "place an A320 called EZY9 ...": a type, then a callsign
  -- no aircraft has, is created
  rule { "place", "create", when = function(g, i)
    local e = math.min(#g.t + 1, i + 9)
    if not g:has_ref(i + 1, math.min(#g.t + 1, i + 5), "type") then return false end
    for _, r in ipairs(g:refs_in(i + 1, e, "aircraft")) do
      if not r.exists then return true end
    end
    return false
  end }
  -- ("respawn X at FIX": a game's word for putting an object back into the world somewhere)
  rule { "move mv reposition teleport shift place relocate tp teleported respawn", "move" }
  -- "could the Pascan be moved over Quebec airport", "can it get repositioned to ...": the passive asked for
  rule { "moved repositioned relocated", "move", prev = { 1, "be get" } }
  -- "warp KLM58 to GAME2": an aircraft warped to a place ("time warp" is none)
  rule { "warp", "move", when = function(g, i) return g:has_ref(i + 1, i + 3, "aircraft") and g:followed_by(i, 4, "to") end }
  -- ("transfer the Air Portugal 015 to the position -7.9 -34.6", Portuguese "transferir": the aircraft put at a
  -- position said with its noun; a hand-off to a station names no position)
  rule { "transfer", "move", when = function(g, i)
    local r = g:refs_in(i + 1, i + 4, "aircraft")[1]
    return r ~= nil and g:word(r.e, "to") and g:word(g:word(r.e + 1, "the") and r.e + 2 or r.e + 1, "position")
  end }
  -- "pop QFA12 over to -27.3 152.8": an aircraft flying "popped over to" a place is moved there
  rule { "pop", "move", when = function(g, i)
    local r = g:refs_in(i + 1, math.min(#g.t + 1, i + 2), "aircraft")[1]
    return r ~= nil and r.exists and g:word(r.e, "over") and g:word(r.e + 1, "to")
  end }
  rule { "put", "move", near = { 3, "back" },
         not_near = { 8, "lnav vnav navigation nav heading course route normal real simulation sim times" } }
  -- "Put the Cessna N345CS at 42.0 -88.3, 3000 feet", "put BAW123 over SPY at fl200": an aircraft
  -- that flies put at a position or over a place
  rule { "put place", "move", when = function(g, i)
    local named
    for _, r in ipairs(g:refs_in(i + 1, math.min(#g.t + 1, i + 5), "aircraft")) do named = named or (r.exists and r) end
    if not named then return false end
    for _, q in ipairs(g:quantities(i + 1, math.min(#g.t + 1, i + 10))) do
      if q.kind == "lat" or (q.kind == "plain" and q.number.decimal) then return true end
    end
    local w = g:refs_in(named.e, math.min(#g.t + 1, named.e + 3), "waypoint")[1]
    if w ~= nil and g:word(w.b - 1, "over on at") then return true end
    -- ("put SWR38F over Trasadingen at FL200": a navaid's name near the aircraft, nav.dat's)
    local p = g:skip_fillers(named.e)
    local t, a, near = g.t[p + 1], named.exists and g:state(named.name), g.world.navaids_named
    return g:word(p, "over on at") and t ~= nil and t.kind == "word" and t.alpha and #t.text >= 4
      and near ~= nil and a ~= nil and a.lat ~= nil and #near(t.text, a.lat, a.lon, require("translate.lexicon").navaid_range_nm) > 0
  end }

  -- "resume run", "continue the run", "resume the scenario": the run (the simulation's) taken up again, said alone,
  -- as a clause of its own, or opening the request before a mark, "and" or "then" ("resume the run and climb KLM12
  -- FL300"); "start the run and ..." starts it, "stop/hold the run and ..." stops it
  -- The request's first word after fillers, a polite question's opening ("could you (please)", "would you
  -- kindly", lexicon.polite_openings) and "go ahead and": the instruction's verb when it asks for one thing
  local function polite_first(g)
    local k = g:skip_fillers(1)
    if g:word(k, "@polite_openings") and g:word(k + 1, "you") then k = g:skip_fillers(k + 2) end
    -- ("go ahead and start the run": the leave given before the verb)
    if g:word(k, "go") and g:word(k + 1, "ahead") and g:word(k + 2, "and") then k = g:skip_fillers(k + 3) end
    return g:word(k, "kindly") and g:skip_fillers(k + 1) or k
  end
  local function the_run(g, i)
    local k = g:word(i + 1, "the") and i + 2 or i + 1
    local opens = polite_first(g) == i and (g.t[k + 1] == nil or g.t[k + 1].kind == "punct" or g:word(k + 1, "and then"))
    return g:word(k, "run scenario scen") and (opens or g:alone_but(i, k + 1) or g:clause_alone(i, k + 1))
  end
  -- simulation control; "hold present heading" keeps a value, and "KL204 hold"
  -- (a holding pattern) is no pause of the simulation
  rule { "hold", "maintain", near = { 2, "heading hdg altitude level speed" } }
  -- "hold, move EZY45 ...": a first word on its own before a comma pauses the simulation
  rule { "hold pause", "hold", when = function(g, i) return i == 1 and g.t[2] ~= nil and g.t[2].kind == "punct" end }
  rule { "hold", "hold", near = { 3, "@sim" } }
  rule { "hold", "hold", when = the_run }
  -- "... DITON. Hold. Swiss 8 climb ...", "(1) hold; (2) ...": "hold" alone as a sentence or step of its own (a
  -- full stop, semicolon or colon before it, a full stop or semicolon or the end after it) names no aircraft's
  -- holding pattern
  rule { "hold", "hold", when = function(g, i)
    local b, e = g.t[i - 1], g.t[i + 1]
    return (b == nil or b.kind == "punct" and (b.text == "." or b.text == ";" or b.text == ":"))
        and (e == nil or e.kind == "punct" and (e.text == "." or e.text == ";"))
  end }
  -- ("schedule hold at 00:15:00", "sched hold at 00:15:00, then ff": the pause a schedule sets, no aircraft named)
  rule { "hold", "hold", when = function(g, i)
    return (g:word(i - 1, "schedule") or g:time_said_at(i + 1)) and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  rule { "hold", false, when = function(g) return g:has_ref(1, #g.t + 1, "aircraft") end }
  -- "run again from pause", "out of pause": the pause is the state left, no new one
  rule { "pause hold freeze", false, prev = { 2, "from of" } }
  -- "pause release", "release the pause": the pause ended, the run resumed
  rule { "release", "op", when = function(g, i)
    return (g:word(i - 1, "pause") or g:word(g:word(i + 1, "the") and i + 2 or i + 1, "pause"))
      and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  rule { "pause", false, next = "release" }
  rule { "pause", false, prev = { 2, "release" } }
  -- "the simulation may now be resumed (from where it was paused)", "the exercise is to be resumed": the run
  -- resumed, said in the passive of the simulation named before it, no aircraft named
  rule { "resume resumed restarted unpaused continued", "op", prev = { 6, "@sim" }, when = function(g, i)
    return g.t[i].raw:lower():match("ed$") ~= nil and g:word(i - 1, "be been is are")
      and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- "continue the simulation in fast time for 2 minutes", "continue it in fast-forward": the fast time is the way
  -- it goes on, read by FF (which runs the clock for its duration), no OP of its own
  rule { "continue", false, when = function(g, i)
    local k = g:word(i + 1, "the") and i + 2 or i + 1
    if g:word(k, "@sim it") then k = k + 1 end
    return g:word(k, "in") and g:word(k + 1, "fast fast-time fast-forward")
      and (g:word(k + 1, "fast-time fast-forward") or g:word(k + 2, "time forward"))
  end }
  -- "go back to the start of this exercise", "can we return to the beginning of the scenario", "back to the
  -- start please": the start as a place in the run gone back to is the run begun again, a reset (confirmed
  -- first), never the clock started (OP); said with an aircraft named ("back to the start of its route") it is
  -- no run's start
  rule { "start beginning", "reset", prev = { 1, "the this" }, when = function(g, i)
    if not (g:word(i - 2, "to") and g:find_word(math.max(1, i - 5), i - 2, "back return returning") < i - 2) then return false end
    local k = g:word(i + 1, "of") and i + 2 or nil
    if k and g:word(k, "the this that our") then k = k + 1 end
    return (k == nil or g:word(k, "@sim scenario scen run")) and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- "continue from pause", "start again out of the pause": the run resumed from the pause
  rule { "run start continue resume go", "op", when = function(g, i)
    local k = g:word(i + 1, "again") and i + 2 or i + 1
    k = g:word(k, "from") and k + 1 or (g:word(k, "out") and g:word(k + 1, "of") and k + 2) or nil
    if k and g:word(k, "the") then k = k + 1 end
    return k ~= nil and g:word(k, "pause hold freeze") and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  rule { "pause hold freeze pausing freezing", "hold" }
  -- "hit play", "press play": a game's or a player's button, the clock started
  rule { "play", "op", prev = { 2, "hit press click push" } }
  -- ("play the simulation", "play again the simulation": the simulation played, as a recording)
  rule { "play", "op", near = { 3, "@sim" } }
  -- "interrupt the exercise", "the exercise will now be interrupted": a pause of the simulation said of it
  rule { "interrupt interrupted", "hold", near = { 3, "@sim" } }
  rule { "interrupt interrupted", "hold", prev = { 4, "@sim" } }
  -- "run in fast time until I say stop": the stop is when the run ends, not an instruction
  rule { "stop", false, prev = { 3, "until" } }
  -- "stop the fast time", "stop this fast forward", "stop ff": fast time ended (m:fast_forward reads the verb, OP),
  -- never a pause
  rule { "stop", false, when = function(g, i)
    local k = i + 1
    while g:word(k, "the this that our your current") do k = k + 1 end
    return g:word(k, "ff fastforward") or (g:word(k, "fast") and g:word(k + 1, "time forward"))
  end }
  rule { "stop", "hold", near = { 3, "@sim" } }
  -- "sim stop for a moment": the simulation named before its verb (verb-final order), no aircraft named
  rule { "stop", "hold", prev = { 1, "@sim" }, when = function(g) return not g:has_ref(1, #g.t + 1, "aircraft") end }
  -- "stop a moment the simulation", "stop for a minute the sim": the while said before the object
  rule { "stop", "hold", when = function(g, i)
    local k = g:word(i + 1, "for") and i + 2 or i + 1
    if not (g:word(k, "a") and g:word(k + 1, "moment second minute bit while")) then return false end
    k = g:word(k + 2, "the") and k + 3 or k + 2
    return g:word(k, "@sim")
  end }
  -- "stop", "stop pls": the verb alone, the whole request, stops the run (HOLD); in fast time, where it may end
  -- the fast-forward instead, it is left unread (asked)
  rule { "stop", "hold", when = function(g, i)
    for k = 1, #g.t do
      if k ~= i and not (g.t[k].kind == "punct" or g:word(k, "please pls now")) then return false end
    end
    return g.world.run_state ~= "ff"
  end }
  -- "stop it for a moment", "stop everything for a second": the run stopped a while, said with no
  -- aircraft named anywhere in the request ("KLM12, stop it for a moment" is no pause)
  rule { "stop", "hold", next = "it everything", when = function(g, i)
    local k = g:word(i + 2, "for") and i + 3 or i + 2
    return g:word(k, "a") and g:word(k + 1, "moment second minute bit while") and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- "restart the clock", "start the clock again": the clock runs on (OP); the simulation, exercise or
  -- scenario restarted is a reset (confirmed first)
  rule { "restart start", "op", near = { 3, "clock" } }
  rule { "restart", "reset", near = { 3, "@sim" } }
  -- "what is the Air Busan altitude and speed now?": "what" opening the request, the aircraft (its "'s" dropped), then
  -- only measures of its state ("and" or a comma between) and "now" or "currently" at most to the end: its state
  -- asked (POS), no instruction
  rule { "what what's whats", "pos", when = function(g, i)
    if g:skip_fillers(1) ~= i then return false end
    local k = g:word(i + 1, "is are") and i + 2 or i + 1
    if g:word(k, "the") then k = k + 1 end
    local r = g:refs_in(k, k + 1, "aircraft")[1]
    if not (r and r.b == k) then return false end
    k = r.e
    local measured = false
    while g:word(k, "altitude speed heading level position height mach and current present now currently")
        or (g.t[k] and g.t[k].kind == "punct" and g.t[k].text == ",") do
      measured = measured or g:word(k, "altitude speed heading level position height mach")
      k = k + 1
    end
    return measured and (g.t[k] == nil or (g.t[k].kind == "punct" and k == #g.t))
  end }
  -- ("might I ask what the Shuttle seven mike's present heading is?": "what", the aircraft (a callsign said in
  -- words), its measure and "is" closing the request: the measure asked, never the heading kept)
  rule { "what", "pos", when = function(g, i)
    local k = g:word(i + 1, "the") and i + 2 or i + 1
    local r = g:refs_in(k, k + 1, "aircraft")[1]
    if not (r and r.b == k) then return false end
    local e = math.min(#g.t + 1, r.e + 3)
    local m = g:find_word(r.e, e, "altitude speed heading level position height mach")
    return m < e and g:word(m + 1, "is are") and (g.t[m + 2] == nil or g.t[m + 2].kind == "punct")
  end }
  -- (the measure asked by its other names: "what height is it at?", "the Dreamliner, what's its Mach number?")
  -- ("you know" with no auxiliary before it is the spoken filler, "Air Peace 7124 you know, turn left heading
  -- 190", "you know what, climb FL150": no question; "do you know your heading" asks)
  -- ("X and Y both, what are their levels?": the measures in the plural, for the aircraft named together)
  rule { "what how know", "pos", near = { 4, "altitude speed heading position level alt lvl hdg spd height mach "
      .. "altitudes speeds headings positions levels heights" },
    when = function(g, i)
      local k = g:word(i, "what") and i - 1 or i
      if g:word(i, "what") and value_unsaid(g, i) then return false end
      return not (g:word(k, "know") and g:word(k - 1, "you ya")
        and not g:word(k - 2, "do does did don't doesn't didn't can could would will"))
    end }
  -- "what's AC004's current FL": the level flown now, "current" or "present" straight before the abbreviation
  rule { "what", "pos", when = function(g, i)
    local k = g:find_word(i + 1, i + 5, "current present")
    if not (k < i + 5 and g:word(k + 1, "fl")) then return false end
    -- (nothing after it but the aircraft asked about: "... of AC004?")
    for x = k + 2, #g.t do
      if not (g.t[x].kind == "punct" or g:word(x, "of for") or g:has_ref(x, x + 1, "aircraft")) then return false end
    end
    return true
  end }
  -- "which is the altitude of the Azul?": the question asked with "which", as non-native speakers do
  rule { "which", "pos", next = "is", near = { 4, "altitude speed heading position level" }, when = function(g)
    return g.t[#g.t].text == "?" end }
  -- "which heading is the Easy flying at present?", "which level is KLM12 at now?": the state word straight after
  -- "which", then "is" or "are": the aircraft's value asked, no instruction ("which heading should it fly" is none)
  rule { "which", "pos", next = "altitude speed heading level", when = function(g, i)
    return g:word(i + 2, "is are") end }
  -- "the Swiftair, which altitude has?", "which speed has the Iberia?": the same with "has" for "tiene" / "tem"
  -- (a Spanish or Portuguese speaker's word order), a question closed by "?" with no "to" after the verb ("which
  -- heading has it to fly?" asks for an instruction)
  rule { "which", "pos", next = "altitude speed heading level", when = function(g, i)
    return g:word(i + 2, "has have") and g.t[#g.t].text == "?" and not g:word_in(i + 3, #g.t + 1, "to") end }
  -- "which altitude Kenya 412 have now?", "which speed does the Rwandair have?", "which level the Ethiopian is at
  -- now?": the state word after "which", then the aircraft ("does"/"do" and "the" before it at most), then "has",
  -- "have", "is", "is at" or "is flying", only "now"/"currently" after, and "?" closing the request: its state
  -- asked (POS) as a non-native speaker asks it ("which altitude Kenya 412 have to climb?" is none)
  rule { "which", "pos", next = "altitude speed heading level", when = function(g, i)
    if g.t[#g.t].text ~= "?" then return false end
    local k = g:word(i + 2, "does do") and i + 3 or i + 2
    if g:word(k, "the") then k = k + 1 end
    local r = g:refs_in(k, k + 1, "aircraft")[1]
    if not (r and r.b == k and r.exists) then return false end
    k = r.e
    if not g:word(k, "has have is") then return false end
    k = k + 1
    if g:word(k - 1, "is") and g:word(k, "at flying") then k = k + 1 end
    while g:word(k, "now currently") do k = k + 1 end
    return k == #g.t
  end }
  -- "which is the route of the Vueling?": the route asked with "which" ("cuál es"), as the state is above
  rule { "which", "listrte", next = "is", near = { 4, "route routing" }, when = function(g)
    return g.t[#g.t].text == "?" end }
  -- "how fast is the Norwegian flying?", "how high is SAS1421 now?": a question of an aircraft's state
  -- (typed without "?" too, when the request ends at the aircraft or its verb: "how high is afr1442")
  rule { "how", "pos", next = "fast high", when = function(g, i)
    local r = g:refs_in(i + 2, math.min(#g.t + 1, i + 6), "aircraft")[1]
    if not r then return false end
    local k = g:word(r.e, "now flying going climbing descending") and r.e + 1 or r.e
    return g.t[#g.t].text == "?" or k > #g.t
  end }
  -- "SkyWest 5412, how fast are you going?", "United 837, how high are you right now?": the aircraft addressed
  -- before the question about its own state, "are you" after the adjective, nothing but a verb of going or "now"
  -- up to the question's end ("how fast can you go" asks what it could do: no state; a friend addressed in chat
  -- closing it, "how fast r u going m8", is a word of lexicon.accounted.audience)
  rule { "how", "pos", next = "fast high", when = function(g, i)
    if not (g:word(i + 2, "are") and g:word(i + 3, "you") and g:has_ref(1, i, "aircraft")) then return false end
    local k = i + 4
    while g:word(k, "going flying travelling traveling now right currently mate") do k = k + 1 end
    return g.t[k] == nil or (g.t[k].kind == "punct" and g.t[k].text ~= ",")
  end }
  -- "what's happening with United 837?", "what is going on with the SkyWest": the aircraft's state asked
  rule { "happening going", "pos", when = function(g, i)
    local w = g:word(i, "going") and i + 1 or i
    if g:word(i, "going") and not g:word(w, "on") then return false end
    local q = g:word(i - 1, "is 's") and i - 2 or i - 1
    local k = g:skip_fillers(w + 2)
    return g:word(q, "what what's whats") and g:word(w + 1, "with")
      and aircraft_alone(g, g:word(k, "the") and k + 1 or k, true)
  end }
  -- "can you show us everything about Endeavor 5120", "tell us all about the SkyWest": all of its state
  rule { "about", "pos", when = function(g, i)
    return g:word(i - 1, "everything all") and g:word_in(math.max(1, i - 4), i - 1, "show tell")
      and aircraft_alone(g, g:skip_fillers(i + 1), true)
  end }
  rule { "tell", "pos", next = "me us", near = { 5, "altitude speed heading position level" } }
  -- "AAR731 current altitude tell me", "KAL8 speed let me know", "heading please tell": the state word said
  -- before the request for it (verb-final order) asks for the aircraft's report, no instruction
  rule { "tell know", "pos", when = function(g, i)
    local k = i - 1
    if g:word(i, "know") then
      if not (g:word(i - 1, "me us") and g:word(i - 2, "let")) then return false end
      k = i - 3
    elseif not (g:word(i + 1, "me us") or g:word(i - 1, "please")) then
      return false
    end
    if g:word(k, "please") then k = k - 1 end
    return g:word(k, "altitude speed heading position level")
  end }
  -- "give me the position", "give me TEST01's and TEST02's positions"
  rule { "give", "pos", next = "me us", near = { 6, "position positions status details" } }
  -- "THY2KP give me your speed", "give us your present level": the aircraft's own state asked for, no value
  -- said straight after it (POS)
  rule { "give", "pos", next = "me us", when = function(g, i)
    local k, nouns = state_words(g, g:skip_fillers(i + 2), "your its the", "level altitude speed heading mach")
    local q = g:quantities(i, #g.t + 1)[1]
    return nouns > 0 and not (q and q.b <= k + 1)
  end }
  -- "give the position of the Canberra VOR": the same asked with no one named to give it to
  rule { "give", "pos", next = "the", near = { 2, "position positions" } }
  -- "are you able (for) FL370", "confirm on heading south": a question to the pilot, not a clearance
  -- "would you be able to turn the Channex ...", "will you be able to delete it": the operator asked, politely, to
  -- do what the verb after "to" says (no question to the pilot: "be" after "you" frames a request)
  rule { "able", false, prev = { 1, "be" }, next = "to", when = function(g, i) return g:word(i - 2, "you") end }
  rule { "able", "pos", prev = { 2, "you" } }
  -- "confirm you are maintaining FL120", "confirm maintaining 270 knots": the aircraft asked to confirm a state it
  -- holds (G:state_confirmed, its clause set aside by G:question_back) asks for its report
  rule { "confirm", "pos", when = function(g, i) return g.state_asked ~= nil and g.state_asked[i] == true end }
  rule { "confirm", "pos", near = { 3, "heading altitude level speed mach" } }
  -- ("Ethiopian 3802 confirm your position": the report of where it is)
  rule { "confirm", "pos", next = "your", near = { 2, "position" } }
  -- ("Air India 181, your position confirm", "position confirm": the noun before it, closing the request)
  rule { "confirm", "pos", prev = { 1, "position" }, when = function(g, i) return g:skip_fillers(i + 1) > #g.t end }
  -- "verify AC002 state (alt, spd, hdg)", "verify its altitude": the aircraft's values asked for
  rule { "verify", "pos", near = { 3, "state heading altitude level speed mach alt spd hdg fl position" } }
  -- "say altitude", "report your heading": a question about the aircraft's state (POS of the
  -- aircraft named); "say heading 270", a value after the state word, is that instruction's value
  rule { "say", false, when = function(g, i)
    for k = i + 1, math.min(i + 3, #g.t) do
      if g:word(k, "altitude speed heading level airspeed mach alt lvl hdg spd fl") then
        local v = g.t[g:word(k + 1, "of to") and k + 2 or k + 1]
        return v ~= nil and (v.kind == "number" or v.number_word == true) and not g.u:used(k + 1)
      end
    end
    return false
  end }
  -- "report reaching", "report passing": the report of a level the aircraft will reach, no question now
  -- ("report level" alone asks the level flown now: POS, as "say altitude")
  rule { "report", false, next = "reaching passing" }
  -- "advise when able to resume": the pilot's report asked for, not the instruction after "able to"
  rule { "resume", false, when = function(g, i)
    return g:word(i - 1, "to") and g:word(i - 2, "able") and g:preceded_by(i - 2, 3, "advise report")
  end }
  rule { "say report", "pos", near = { 3, "altitude speed heading position level airspeed mach alt lvl hdg spd pos fl vertical" } }
  -- "say distance to TELIN", "report your distance from BIG": the aircraft's position asked, to judge it by
  rule { "say report", "pos", near = { 2, "distance" } }
  -- ("Ryanair 3PF say all": every state the aircraft has)
  rule { "say", "pos", next = "all", when = function(g, i)
    local named = {}
    for _, r in ipairs(g.refs) do
      for k = r.kind == "aircraft" and r.b or 1, r.kind == "aircraft" and r.e - 1 or 0 do named[k] = true end
    end
    for k = 1, #g.t do
      if (k < i or k > i + 1) and g.t[k].kind ~= "punct" and not g.t[k].filler and not named[k] then return false end
    end
    return true
  end }
  -- ("report with your present level": the value "with" the reply; "vertical" of a vertical speed said with "present"
  -- or "current" before it, the speed itself past the window: "revert with its present vertical speed")
  rule { "report", "pos", next = "with", near = { 4, "altitude speed heading position level airspeed mach alt lvl hdg spd pos fl vertical" } }
  -- "request your present heading", "request your level": the controller asking the aircraft's own value
  -- (a report, as "say"), never an instruction to keep it
  rule { "request", "pos", next = "your", near = { 3, "altitude speed heading position level airspeed mach alt lvl hdg spd pos fl" } }
  -- "we then ask for the current heading of Lufthansa 2TA", "ask for its level": the aircraft's value asked for (a
  -- report), never an instruction to keep it; with a value said after it ("I would like to ask for DLH4AX heading
  -- 120") it is the speaker's request of that value
  rule { "ask", "pos", next = "for", near = { 4, "altitude speed heading position level airspeed mach" },
         not_near = { 2, "higher lower more less another new different" },
         when = function(g, i) return #g:quantities(i, #g.t + 1) == 0 end }
  rule { "carry", "op", next = "on", near = { 4, "@sim" } }  -- "carry on with the simulation"
  -- ("ok grand, carry on with it": "it", the run, closing the clause; no aircraft named anywhere)
  rule { "carry", "op", next = "on", when = function(g, i)
    return g:word(i + 2, "with") and g:word(i + 3, "it") and g:clause_alone(i, i + 4)
      and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- "carry on", "go on", "right, crack on" (British: get going)
  rule { "carry go crack", "op", next = "on", when = function(g, i) return g:alone_but(i, i + 2) end }
  -- "..., then carry on", "..., then go", "OK, go on, and run at 2x": a clause of its own; "ok carry on, run it at
  -- three times speed": "carry on" opening the request ("go on, let it fast-forward" urges the next one on)
  rule { "carry go crack", "op", next = "on", when = function(g, i)
    return g:clause_alone(i, i + 2) or (g:word(i, "carry crack") and g:clause_opens(i, i + 2))
  end }
  -- "okay, back to it, and run at normal speed", "right, back to work": the clock taken up again, a clause of its
  -- own with no aircraft named anywhere
  rule { "back", "op", next = "to", when = function(g, i)
    return g:word(i + 2, "it work") and (g:alone_but(i, i + 3) or g:clause_alone(i, i + 3))
      and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  rule { "keep", "op", next = "going", when = function(g, i)
    -- ("ok, let's keep going": "let's" opening the clause before it)
    local b = g:word(i - 1, "let let's lets") and i - 1 or i
    return g:alone_but(b, i + 2) or g:clause_alone(b, i + 2) or g:clause_opens(b, i + 2)
  end }
  rule { "run", "op", next = "it", when = function(g, i) return g:clause_alone(i, i + 2) end }
  -- ("okay uh run it again": the same, "again" closing its clause; "run it again from the start" is no resume)
  -- ("right, run it on again": "on" between, the Irish "run it on")
  rule { "run", "op", next = "it", when = function(g, i)
    local k = g:word(i + 2, "on") and i + 3 or i + 2
    return g:word(k, "again") and (g:alone_but(i, k + 1) or g:clause_alone(i, k + 1))
  end }
  -- "ok resume it", "continue it please": the run taken up again, "it" the simulation (no aircraft named anywhere)
  rule { "resume continue", "op", next = "it", when = function(g, i)
    return (g:alone_but(i, i + 2) or g:clause_alone(i, i + 2)) and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- "run it and fast forward 3 minutes", "run the sim and ff 60 s": the clock started, then moved on
  rule { "run", "op", when = function(g, i)
    local k = i + 1
    if g:word(k, "the") and g:word(k + 1, "@sim") then k = k + 2 elseif g:word(k, "it @sim") then k = k + 1 end
    return g:word(k, "and") and g:word(k + 1, "fast ff")
  end }
  rule { "go resume continue unpause run play", "op", when = function(g, i) return g:clause_alone(i, i + 1) end }
  -- "go, 3x", "play, and make it three times", "go, KLM12 climb FL100": opening the request, a clause of its own
  rule { "go play", "op", when = function(g, i) return g:clause_opens(i, i + 1) end }
  -- "set multiplier 8 and run", "descend FL080 then run (it)": the clock started after another instruction, the
  -- verb ending the text ("and run at 4x" is the rate's); "seed 42 then go": "go" so, no aircraft named
  rule { "run go", "op", prev = { 1, "and then" }, when = function(g, i)
    if g:word(i, "go") and g:has_ref(1, #g.t + 1, "aircraft") then return false end
    local k = i + 1
    if g:word(k, "the") and g:word(k + 1, "@sim") then k = k + 2 elseif g:word(k, "it @sim") then k = k + 1 end
    while k <= #g.t and (g.t[k].kind == "punct" or g.t[k].filler or g:word(k, "now")) do k = k + 1 end
    return k > #g.t
  end }
  rule { "unpause unfreeze op", "op" }
  rule { "resume continue unpause start", "op", when = the_run }
  rule { "stop", "hold", when = the_run }
  rule { "go", "op", next = "again" }  -- "and go again"
  -- ("simulation go, and speed up twice": the run started, said in the noun's order, before a mark or the end)
  rule { "go", "op", prev = { 1, "simulation sim" }, when = function(g, i)
    return g.t[i + 1] == nil or g.t[i + 1].kind == "punct"
  end }
  -- "kick off the episode", "kick off the sim": the run started, said of the simulation
  rule { "kick", "op", next = "off", near = { 3, "@sim" } }
  -- "let it rip", "let her rip": the run started (said with no aircraft named; with one it is asked)
  rule { "rip", "op", when = function(g, i)
    return g:word(i - 1, "it her") and g:word(i - 2, "let") and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- "ok let her run", "let her run": the simulation as "her", as Australian speech names a machine, the clock
  -- started, said alone or as a clause of its own, no aircraft named in the request ("let her go" stays asked:
  -- said of an aircraft as often)
  rule { "run", "op", when = function(g, i)
    return g:word(i - 1, "her") and g:word(i - 2, "let") and not g:has_ref(1, #g.t + 1, "aircraft")
      and (g:alone_but(i - 2, i + 1) or g:clause_alone(i - 2, i + 1))
  end }
  -- "let it go", "let it run", "let the sim run": the clock started, said alone or as a clause of its own ("let
  -- the simulation run further", "let it run on": "further", "farther", "on" after "run" say it goes on); "run" (of
  -- the simulation, "the sim", never "it") also joined by "and"/"then" after another instruction, ending the request
  -- ("KLM12 climb FL300 and then let the simulation run"), or opening it before "and"/"then" and more ("let the
  -- simulation run and KLM12 climb FL300"), or before a comma and an aircraft ("let the sim run, KLM12 climb ...")
  rule { "go run", "op", when = function(g, i)
    local b = g:word(i - 1, "it") and i - 1 or (g:word(i - 1, "@sim") and g:word(i - 2, "the") and i - 2 or nil)
    local e = g:word(i, "run") and g:word(i + 1, "further farther on") and i + 2 or i + 1
    if not (b ~= nil and g:word(b - 1, "let")) then return false end
    if g:alone_but(b - 1, e) or g:clause_alone(b - 1, e) then return true end
    if not (g:word(i, "run") and b < i - 1) then return false end
    local k = e
    while k <= #g.t and (g.t[k].kind == "punct" or g.t[k].filler or g:word(k, "now please")) do k = k + 1 end
    local j = b - 2
    while j >= 1 and g.t[j].filler and not g:word(j, "and then") do j = j - 1 end
    return (k > #g.t and g:word(j, "and then"))
      or (g:skip_fillers(1) == b - 1 and e + 1 <= #g.t and (g:word(e, "and then")
        or (g.t[e] and g.t[e].text == "," and g:has_ref(g:skip_fillers(e + 1), g:skip_fillers(e + 1) + 1, "aircraft"))))
  end }
  -- "ok, let's go", "righto let's go" (the lexer reads "let's" as "let", "righto" as "right"): the run started, said
  -- alone or as a clause of its own, an acknowledgement before it ("let's go with heading 270" is no clause of its
  -- own)
  rule { "go", "op", prev = { 1, "let lets" }, when = function(g, i)
    local b = i - 1
    while b > 1 and g:word(b - 1, "right alright ok okay so well") do b = b - 1 end
    return g:alone_but(b, i + 1) or g:clause_alone(b, i + 1) or g:clause_opens(b, i + 1)
  end }
  -- "pause, time step 0.1, then start again": the clock started again, a clause of its own
  rule { "start", "op", next = "again", when = function(g, i) return g:clause_alone(i, i + 2) end }
  -- ("new scene loaded, start", "last block of the day, go ahead and start": "start" closing the request in a
  -- clause of its own ("go ahead and" before it), no aircraft named)
  rule { "start", "op", when = function(g, i)
    local b = g:word(i - 1, "and") and g:word(i - 2, "ahead") and g:word(i - 3, "go") and i - 3 or i
    local e = i + 1
    while g.t[e] and g.t[e].kind == "punct" do e = e + 1 end
    return e > #g.t and g:clause_alone(b, i + 1) and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- "run it", "start it", "go ahead and start it": the clock, said alone
  rule { "run start", "op", next = "it", when = function(g, i)
    local b = g:word(i - 1, "and") and g:word(i - 2, "ahead") and g:word(i - 3, "go") and i - 3 or i
    return g:alone_but(b, i + 2)
  end }
  -- "could you start it again?", "start it up", "start it back up (and then KLM12 climb)": the clock, no aircraft
  -- named before it for "it" to stand for
  rule { "start", "op", next = "it", when = function(g, i)
    return (g:word(i + 2, "again up") or (g:word(i + 2, "back") and g:word(i + 3, "up")))
      and not g:has_ref(1, i, "aircraft")
  end }
  -- "set the speed of the simulation to factor 5 and start it": "it" the simulation named before, the clause after
  -- "and" or "then" closing the request, no aircraft named
  rule { "run start", "op", next = "it", when = function(g, i)
    return g:word(i - 1, "and @then_words") and g:word_in(1, i - 1, "@sim") and g:skip_fillers(i + 2) > #g.t
      and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  rule { "go", "op", next = "on", near = { 4, "@sim" } }  -- "go on with the simulation"
  -- "set the sim running", "get it running again": the clock started
  rule { "running", "op", prev = { 1, "@sim it" }, not_near = { 4, "speed rate times real normal" }, when = function(g, i)
    local b = g:word(i - 2, "the") and i - 2 or i - 1
    return g:word(b - 1, "set get")
  end }
  -- "set it going again", "get the sim going": the clock started, said alone or as a clause of its own with no
  -- aircraft named anywhere ("get it going north" is said of an aircraft, and asked)
  rule { "going", "op", prev = { 1, "@sim it" }, when = function(g, i)
    local b = g:word(i - 2, "the") and i - 2 or i - 1
    local e = g:word(i + 1, "again") and i + 2 or i + 1
    return g:word(b - 1, "set get") and not g:has_ref(1, #g.t + 1, "aircraft")
      and (g:alone_but(b - 1, e) or g:clause_alone(b - 1, e))
  end }
  -- "off we go", "right, off we go again": the clock started, said alone or as a clause of its own
  rule { "off", "op", when = function(g, i)
    local e = g:word(i + 3, "again") and i + 4 or i + 3
    return g:word(i + 1, "we") and g:word(i + 2, "go") and (g:alone_but(i, e) or g:clause_alone(i, e) or g:clause_opens(i, e))
  end }
  -- "go", "resume (please)": the whole request starts the clock
  rule { "go resume run play", "op", when = function(g, i) return g:alone(i) end }  -- ("ok run", "play")
  -- "go go go", "go, go!": the one word said again, nothing else, starts the clock once
  rule { "go", "op", when = function(g, i)
    for k = 1, #g.t do
      if not (g.t[k].kind == "punct" or g.t[k].filler or g:word(k, "go")) then return false end
    end
    return true
  end }
  -- "sim run", "sim start", "sim stop": the simulation named before its verb, said alone or as a clause
  rule { "go run start", "op", prev = { 1, "@sim" }, when = function(g, i)
    return g:alone_but(i - 1, i + 1) or g:clause_alone(i - 1, i + 1)
  end }
  rule { "stop", "hold", prev = { 1, "@sim" }, when = function(g, i)
    return g:alone_but(i - 1, i + 1) or g:clause_alone(i - 1, i + 1)
  end }
  -- "resume nav past cpa", "resume navigation once past the CPA", "with resumption of navigation past CPA": how
  -- aircraft resume after a resolution
  rule { "resume resumes resumption", "resnav", near = { 6, "cpa" } }
  -- "after they pass CPA send them back on their route", "once past the CPA let them resume their route": how
  -- aircraft resume their route after a resolution (RESNAV PASTCPA), CPA named before it after a word of
  -- lexicon.condition or "past"
  rule { "back rejoin resume resumes", "resnav", near = { 4, "route routes course navigation nav" },
         when = function(g, i)
    local c = g:find_word(1, i, "cpa")
    -- ("after a resolution, the aircraft should go back to their route when they are past the closest point":
    -- CPA after it, within ten words, a resolution named before it and no aircraft)
    if c >= i and g:word_in(1, i, "resolution resolutions resolving") and not g:has_ref(1, #g.t + 1, "aircraft") then
      c = g:find_word(i + 1, math.min(#g.t + 1, i + 11), "cpa")
      return c <= #g.t and g:word(c, "cpa") and g:word_in(math.max(i + 1, c - 3), c, "past passing passed")
    end
    return c < i and g:word_in(math.max(1, c - 4), c, "@condition past passing passed pass passes")
  end }
  rule { "resume", "lnav", near = { 3, "navigation nav route" } }
  -- "Delta 1450 resume normal speed", "resume published speed": the whole request to an aircraft flying its
  -- route's profile (G:profile_speed_resumed), the profile's speed given back (VNAV ON; a speed instruction took it
  -- off). To an aircraft flying no profile it names no speed squawk knows (lexicon.not_simulated: restrictions lifted)
  rule { "resume", "vnav", when = function(g, i) return g:profile_speed_resumed(i) end }
  -- ("rejoin own navigation at NORKU": the rejoining's, a direct-to the waypoint)
  rule { "own", false, prev = { 2, "rejoin rejoining" }, near = { 3, "at to over by" } }
  -- ("after they pass the CPA they should resume their own navigation", "resume own navigation after CPA": the
  -- resumption RESNAV reads, CPA named beside it)
  rule { "own", false, when = function(g, i)
    return g:word_in(math.max(1, i - 3), i, "resume resumes") and g:word_in(math.max(1, i - 8), i + 6, "cpa")
  end }
  rule { "own", "lnav", near = { 2, "navigation nav" } }  -- "its own (route) navigation"
  rule { "own", "lnav", next = "route", prev = { 3, "fly follow back resume" } }  -- "fly its own route again"
  rule { "back", false, prev = { 2, "read" } }  -- ("read me back your route": LISTRTE)
  rule { "back rejoin", "lnav", near = { 3, "route" } }  -- "go back on your route", "rejoin the route"
  -- "continue on your route", "continue along the route", "continue your route": the route flown on (LNAV ON);
  -- a place after it ("continue on your route to LAM") is the route's, read where places are
  rule { "continue", "lnav", when = function(g, i)
    local k = g:word(i + 1, "on along with") and i + 2 or i + 1
    return g:word(k, "your its the his her own") and g:word(k + 1, "route")
  end }
  -- "return to the route", "return to its route", "return on its own route" (Russian "on"): the route flown again
  -- (a place named is a direct-to)
  rule { "return returns", "lnav", next = "to on onto", when = function(g, i)
    local k = g:word(i + 3, "own") and i + 4 or i + 3
    return g:word(i + 2, "the its your his her their") and g:word(k, "route") and not g:has_ref(k + 1, #g.t + 1, "waypoint")
  end }
  -- ("follow its route vertically", "... the altitudes of its route" is VNAV alone; VNAV named as a switch
  -- beside it, "follow its route again with VNAV engaged", is one more instruction)
  rule { "follow", "lnav", next = "your its the", near = { 3, "route" },  -- "follow your route again"
         not_near = { 6, "vertically vertical profile altitude altitudes level levels" } }
  -- "follow again his flight plan route", "follow your filed flight plan": "again" or not, a possessive, then the
  -- route's noun after its modifiers
  rule { "follow", "lnav", not_near = { 7, "vertically vertical profile altitude altitudes level levels" },
         when = function(g, i)
    local k = g:word(i + 1, "again") and i + 2 or i + 1
    if not g:word(k, "your its the his her their") then return false end
    k = k + 1
    while g:word(k, "own filed planned flight original") do k = k + 1 end
    return g:word(k, "route plan")
  end }
  rule { "run", "op", next = "again" }  -- "let it run again"
  rule { "run", "ff", next = "forward ahead" }  -- "run forward 45 seconds"
  -- "run it forward by 2 minutes", "run things ahead 5 minutes": the simulation as the object between
  rule { "run", "ff", next = "it things everything", when = function(g, i) return g:word(i + 2, "forward ahead") end }
  rule { "run", "dtmult", near = { 4, "times x" } }
  -- "run x2", "run x4": the multiplier typed straight after the verb, nothing after it
  rule { "run", "dtmult", when = function(g, i)
    local nx = g.t[i + 1]
    return nx ~= nil and nx.kind == "word" and nx.text:match("^x%d+$") ~= nil and i + 2 > #g.t
  end }
  rule { "run", "dtmult", near = { 4, "@multipliers" } }  -- "run it at twice real time"
  -- ("run simulation at normal speed please": the rate said, 1)
  rule { "run", "dtmult", when = function(g, i)
    local e = math.min(#g.t + 1, i + 6)
    local n = g:find_word(i + 1, e, "normal")
    return n < e and g:word(n + 1, "speed rate pace") and not g:word_in(i + 1, e, "for fast")
  end }
  rule { "dtmult", "dtmult" }
  -- "start the next exercise from file munich_arrivals": a scenario file to load (IC), not the clock
  rule { "start", "ic", near = { 6, "file" } }
  rule { "start", "op", near = { 3, "@sim" } }
  -- "run in fast time", "run the simulation in fast time": the fast time is the instruction (the sim named
  -- after the verb or not)
  rule { "run", false, when = function(g, i)
    local k = i + 1
    if g:word(k, "the") and g:word(k + 1, "@sim") then k = k + 2 elseif g:word(k, "it @sim") then k = k + 1 end
    local f = g:find_word(k, k + 3, "fast")
    return f < k + 3 and g:word(f + 1, "time")
  end }
  -- ("make the simulation run as fast as possible for 20 minutes": the simulation, the verb's subject after a
  -- causative verb, said straight before it)
  rule { "run advance", "ff", near = { 7, "for minutes minute seconds second hours hour min sec" },
         not_near = { 7, "real times faster x twice thrice" },
         when = function(g, i)
    return g:followed_by(i, 3, "@sim") or (g:word(i - 1, "@sim") and g:preceded_by(i - 1, 3, "make let have get"))
  end }
  -- "step the sim 30 seconds", "run 2 minutes", "advance 60 s", "run fast for an hour": a duration straight
  -- after the verb (the sim named between, or nothing; "fast" and "for" before it) is how far to fast-forward
  -- ("sim step 0.5 s", "the simulation step 0.1 s": the step as a noun, the time step, is no verb)
  -- ("run it for 20 minutes real fast": "real" as "very" before "fast" names no rate)
  rule { "run advance step", "ff", not_prev = { 1, "time" }, not_near = { 7, "times faster x twice thrice" },
         when = function(g, i)
    if g:word(i, "step") and g:word(i - 1, "the a sim simulation integration update") then return false end
    for r = math.max(1, i - 7), math.min(#g.t, i + 7) do
      if g:word(r, "real") and not g:word(r + 1, "fast quick quickly") then return false end
    end
    local k = g:skip_fillers(i + 1)
    if g:word(k, "@sim it") then k = g:skip_fillers(k + 1) end  -- ("run it for 90 seconds")
    if g:word(k, "fast quickly ahead") then k = g:skip_fillers(k + 1) end
    if g:word(k, "for") then k = g:skip_fillers(k + 1) end
    -- ("let it run another 45 s", "run for a further 2 minutes": the duration added to the time run so far)
    if g:word(k, "another further extra additional") then k = g:skip_fillers(k + 1) end
    if g:word(k, "hour minute") and g:word(k - 1, "a an") then return true end  -- ("for an hour")
    local q = g:quantities(k, math.min(#g.t + 1, k + 3))[1]
    return q ~= nil and q.b == k and q.kind == "time"
  end }
  -- "run the simulation fast (until I say stop)": fast time with no end, FF (a rate or a duration said
  -- with it is read above)
  rule { "run", "ff", not_near = { 7, "real times faster x twice thrice" }, when = function(g, i)
    local k = g:skip_fillers(i + 1)
    if g:word(k, "the") then k = g:skip_fillers(k + 1) end
    if g:word(k, "@sim it") then k = g:skip_fillers(k + 1) end
    return g:word(k, "fast") and not g:word(k + 1, "forward time")
  end }
  rule { "run advance", "op", near = { 3, "@sim" }, not_near = { 7, "real times faster x twice thrice" } }
  -- "we can continue now", "the simulation can continue now, thank you", "simulation continue please": the run
  -- going on, said with a subject, a modal or a courtesy, and nothing after it but "now", "again" or a courtesy to
  -- the request's end or a mark, no aircraft named in the request
  rule { "continue resume", "op", when = function(g, i)
    if g:has_ref(1, #g.t + 1, "aircraft") then return false end
    local k = i + 1
    while g.t[k] and (g:word(k, "now again please pls") or g.t[k].filler) do k = k + 1 end
    -- (the clause before it says who goes on: "we", "you" or the simulation, after a modal at most, anything before
    -- that subject, "I think we can resume now"; "the route can continue" is no run resumed)
    local b = i - 1
    while b >= 1 and not (g.t[b].kind == "punct" and g.t[b].text ~= "'") and not g:word(b, "we you @sim") do
      if not (g.t[b].filler or g:word(b, "i us let let's lets the can may could shall should will")) then
        return false
      end
      b = b - 1
    end
    return (g.t[k] == nil or g.t[k].kind == "punct" and g.t[k].text ~= "?")
      and (g:word(i - 1, "can may could shall should will") or g:preceded_by(i, 3, "@sim") or k > i + 1)
  end }
  -- ("resume at 2x", "continue at double speed": the clock starts, at that rate; "KLM12 heading 060 continue,
  -- climb FL360": straight after an aircraft's value, with no mark or "then" between, it is that aircraft's and
  -- no clock's)
  rule { "continue resume", "op", when = function(g, i)
    local p = g.t[i - 1]
    if p and (p.kind == "number" or p.number_word) and g:has_ref(1, #g.t + 1, "aircraft") then return false end
    return i + 1 > #g.t or g.t[i + 1].kind == "punct" or g:followed_by(i, 3, "@sim") or g:word(i + 1, "running and")
      or (g:word(i + 1, "at") and (g:word(i + 2, "@multipliers") or (g.t[i + 3] and g:word(i + 3, "x times"))))
  end }
  -- ("could you please continue the run now?": the run, the simulation's, taken up, no aircraft named)
  rule { "continue resume", "op", next = "the", when = function(g, i)
    return g:word(i + 2, "run") and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  rule { "real", false, prev = { 1, "than" } }
  -- ("three times faster than the real time": the rate's comparison, with its article)
  rule { "real", false, prev = { 1, "the" }, when = function(g, i) return g:word(i - 2, "than") end }
  -- ("resume at 5 times real time": the rate of the resume, read by it)
  rule { "real", false, prev = { 1, "x times @multipliers" }, when = function(g, i) return g:preceded_by(i, 7, "continue resume") end }
  rule { "real", "dtmult", next = "time", prev = { 1, "x times @multipliers" } }  -- ("twice real time")
  -- "slow the clock to real time", "back to real time rate, multiplier 1": the rate the clock is set to
  -- (a word of the rate within 6 words before, or its rate or multiplier within 6 after), no start of it
  rule { "real", false, prev = { 1, "to" }, next = "time", when = function(g, i)
    return g:word_in(math.max(1, i - 6), i, "slow slower faster speed multiplier rate")
      or g:word_in(i + 2, math.min(#g.t + 1, i + 7), "multiplier rate")
  end }
  -- "back to normal speed, real time", "back to normal speed, please, real time": real time said again beside
  -- a normal rate (anywhere in the request) names that rate
  rule { "real", false, next = "time", when = function(g, i) return g:word_in(1, #g.t + 1, "normal") end }
  rule { "real", "op", next = "time" }
  -- ("normal time", "back to normal time": real time, said of the clock alone, no aircraft named)
  rule { "normal", "dtmult", next = "time", when = function(g, i)
    local b = g:word(i - 1, "to") and g:word(i - 2, "back") and i - 2 or i
    return g:alone_but(b, i + 2) and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  rule { "fast", "ff", next = "forward" }
  rule { "ff fastforward fwd", "ff" }
  rule { "skip skipping", "ff", next = "ahead forward" }  -- "would you mind skipping ahead 30 seconds?"
  -- ("skip on ten minutes": "on" before the time)
  rule { "skip skipping", "ff", next = "on", when = function(g, i)
    local q = g:quantities(i + 2, math.min(#g.t + 1, i + 5))[1]
    return q ~= nil and q.kind == "time" and q.b == i + 2
  end }
  -- ("skip the next ten minutes (of the scenario)": a time straight after "the next")
  rule { "skip skipping", "ff", next = "the", when = function(g, i)
    local q = g:word(i + 2, "next") and g:quantities(i + 3, math.min(#g.t + 1, i + 7))[1]
    return q and q.kind == "time" and q.b == i + 3 or false
  end }
  rule { "jump", "ff", near = { 3, "ahead forward" } }  -- "jump forward five minutes", "jump us forward"
  -- "go forward 90 seconds", "go forward 2 minutes": a time straight after "forward", no aircraft named
  -- ("forward the simulation 2 minutes": the verb alone, the simulation its object, then the time)
  rule { "forward", "ff", not_prev = { 1, "fast go run" }, near = { 7, "minutes minute seconds second hours hour min sec" },
         when = function(g, i) return g:followed_by(i, 2, "@sim") end }
  rule { "go", "ff", next = "forward", when = function(g, i)
    local q = g:quantities(i + 2, math.min(#g.t + 1, i + 5))[1]
    return q ~= nil and q.b == g:skip_fillers(i + 2) and q.kind == "time" and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  rule { "skip skipping", "ff", near = { 4, "ahead forward" } }  -- "skip one hour forward"
  -- ("simulate ten minutes ahead": the time, then "ahead" or "forward")
  rule { "simulate", "ff", when = function(g, i)
    local q = g:quantities(i + 1, math.min(#g.t + 1, i + 4))[1]
    return q ~= nil and q.kind == "time" and q.b == i + 1 and g:word(q.e, "ahead forward")
  end }
  -- "skip 5 minutes", "skip like 30 secs": a time straight after it (a loose one too), no waypoint or aircraft named
  rule { "skip", "ff", when = function(g, i)
    local k = g:skip_fillers(i + 1)
    if g:word(k, "@wait_hedges like") then k = g:skip_fillers(k + 1) end
    local q = g:quantities(k, math.min(#g.t + 1, k + 3))[1]
    return q ~= nil and q.b == k and q.kind == "time" and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- "play it forward 3 minutes", "roll the sim on 10 minutes", "step forward 30 s": the clock moved on
  -- by a time said after it, no aircraft named
  rule { "play roll step wind push advance", "ff", near = { 4, "forward ahead on" },
         not_prev = { 1, "time the a sim simulation" }, when = function(g, i)
    local q = g:quantities(i + 1, math.min(#g.t + 1, i + 8))[1]
    return q ~= nil and q.kind == "time" and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- ("set dt multiplier 3": the time step's name before the multiplier's, DTMULT's)
  rule { "dt", false, next = "multiplier mult" }
  rule { "dt", false, next = "look lookahead" }  -- "dt look 180": DTLOOK typed apart, no time step
  -- "set the simulation time step multiplier to three": the multiplier of the clock's rate, no time step
  rule { "time", "dtmult", next = "step", when = function(g, i) return g:word(i + 2, "multiplier factor") end }
  rule { "step", false, prev = { 1, "time" }, next = "multiplier factor" }
  rule { "timestep", "dtmult", next = "multiplier factor" }
  rule { "timestep dt", "dt" }
  rule { "time", "dt", next = "step" }
  rule { "step", "dt", next = "size length" }  -- "step size 0.5 s": the simulation's time step, a noun
  -- "set the step to 0.2 s", "the simulation step 0.1": the step as a noun (the verb steps the clock on)
  rule { "step", "dt", prev = { 1, "the a sim simulation integration update" }, not_near = { 3, "forward ahead on" } }
  -- "reset the protected zone to 5 nm": a setting set again, not the simulation
  rule { "reset", false, near = { 3, "protected protection pz rpz zone zoner separation radius" } }
  -- "pause the sim while I reset the eye tracker": the speaker's own doing in a clause of time, no instruction
  rule { "reset restart", false, prev = { 1, "i we" }, when = function(g, i) return g:word(i - 2, "while when as after before until once") end }
  -- "reset KL001 to 50.5, 5.0, FL200, ...": an aircraft put back to a position said is moved there
  rule { "reset", "move", when = function(g, i)
    local r = g:refs_in(i + 1, i + 2, "aircraft")[1]
    local q = r and r.exists and g:word(r.e, "to") and g:quantities(r.e + 1, r.e + 2)[1]
    return q ~= nil and q ~= false and (q.kind == "lat" or q.kind == "plain" and math.abs(q.value) <= 90)
  end }
  -- "reset its starting point", "reset their positions": a possessive after it names what of an aircraft is
  -- set again, never the simulation (the words then read as any other, a remark or asked)
  rule { "reset", false, next = "its his her their" }
  -- ("reset Lufthansa 4AX: put it back at 52.2 5.2, ...", "reset shamrock 4KA: back to ...": an aircraft named straight
  -- after it is what is set again, never the simulation; what follows says how)
  rule { "reset", false, when = function(g, i)
    local r = g:refs_in(i + 1, i + 2, "aircraft")[1]
    return r ~= nil and r.b == i + 1 and r.exists
  end }
  rule { "reset", "reset" }
  rule { "start", "reset", next = "over" }
  rule { "clear", "reset", near = { 3, "@sim" } }
  rule { "seed", "seed" }
  -- "remove the Ryanair from the scenario", "is detection on in this scenario": the scenario running,
  -- no file to load (unless a file is named after it)
  rule { "scenario", false, prev = { 2, "from for in this start of" }, when = function(g, i)
    for k = i + 1, math.min(#g.t, i + 3) do
      if g.t[k].raw:find("[%./]") and g.t[k].kind ~= "punct" then return false end
    end
    return true
  end }
  -- "this is the conflict scenario", "it's the training scenario": the scenario running named as what this is, no
  -- file to load (unless a file is named after it)
  rule { "scenario", false, not_near = { 4, "load open ic" }, when = function(g, i)
    for k = i + 1, math.min(#g.t, i + 3) do
      if g.t[k].raw:find("[%./]") and g.t[k].kind ~= "punct" then return false end
    end
    for k = math.max(1, i - 5), i - 1 do
      if g:word(k, "this that it here") and g:word(k + 1, "is was the our") then return true end
    end
    return false
  end }
  -- "We start now with the Frankfurt scenario of our study.", "Now we come to the Munich scenario.", "some aircraft
  -- for the Stuttgart scenario": a scenario named by one word after "the" or "our", said after one of
  -- lexicon.scenario_spoken_of ("to" only after "come", "came", "coming"), is the one the study is at, no file to
  -- load (unless a file is named after it, or a verb of loading or switching is said)
  rule { "scenario", false, not_near = { 6, "load open ic switch change" }, when = function(g, i)
    if not g:word(i - 2, "the our") or g.t[i - 1].kind ~= "word" then return false end
    for k = i + 1, math.min(#g.t, i + 3) do
      if g.t[k].raw:find("[%./]") and g.t[k].kind ~= "punct" then return false end
    end
    return g:word(i - 3, "@scenario_spoken_of") or g:word(i - 3, "to") and g:word(i - 4, "come came coming")
  end }
  -- "run the scenario 5 times faster": the scenario running, at a rate, no file to load
  rule { "scenario", false, prev = { 2, "run speed" }, near = { 3, "times faster slower quicker" } }
  -- "the scenario feels a bit empty", "the scenario is too quiet": the scenario running, described, no file to load
  rule { "scenario", false, prev = { 1, "the this" }, next = "@scenario_described" }
  -- "fast forward the scenario by 10 minutes", "pause the scenario": the scenario running, the object of a
  -- verb of the clock, no file to load
  rule { "scenario", false, prev = { 2, "forward ff pause freeze unfreeze unpause resume continue hold" } }
  -- "I've now set up an Irish scenario", "we have loaded the scenario": the speaker's own doing told, in the
  -- perfect, no file to load
  rule { "scenario", false, when = function(g, i)
    for k = math.max(1, i - 6), i - 1 do
      if g:word(k, "i've ive we've weve") or (g:word(k, "have") and g:word(k - 1, "i we")) then return true end
    end
    return false
  end }
  -- ("I need finer resolution for my analysis": the detail of the results, no conflict resolution)
  rule { "resolution", false, prev = { 1, "finer fine higher better coarser lower temporal time" } }
  -- "20 random aircraft for background load", "more traffic load": the noun, no file loaded
  rule { "load", false, prev = { 1, "background traffic high low heavy light more extra" } }
  -- "conflict detection open please", "open the conflict resolution": a conflict setting switched on (handlers'
  -- m:opened_setting), no file opened
  rule { "open", false, when = function(g, i)
    local k = i - 1
    -- ("the conflict detection is open now or not?": asked about, "is" between)
    while k > 1 and (g.t[k].filler or g:word(k, "is are")) do k = k - 1 end
    if g:word(k, "detection resolution asas vnav lnav") then return true end
    k = i + 1
    while g:word(k, "the conflict conflicts its his") do k = k + 1 end
    -- ("open the ASAS", "CCA1539 open the VNAV please": the switch named straight after it, as Chinese "da kai")
    if (k > i + 1 and g:word(k, "detection resolution")) or g:word(k, "asas vnav lnav") then return true end
    -- ("open the trails": the trails switched on, m:opened_setting)
    k = i + 1
    while g:word(k, "the all") do k = k + 1 end
    if g:word(k, "trail trails") then return true end
    -- ("the resolution also can use vertical direction? please open it", "open vertical resolution": the vertical
    -- resolutions switched on, RMETHV, G:vertical_resolutions)
    for j = 1, #g.t do
      if g:word(j, "vertical") and g:vertical_resolutions(j) then return true end
    end
    return false
  end }
  -- ("ok new scenario's loaded. Could you bring the Loganair down ...": a scenario said as loaded already, a state, no
  -- file to load)
  rule { "scenario", false, when = function(g, i)
    local k = g:word(i + 1, "is was has 's") and i + 2 or i + 1
    if g:word(k, "been") then k = k + 1 end
    return g:word(k, "loaded opened running ready up set")
  end }
  rule { "scenario load open ic", "ic" }
  -- "print UAL9's flight plan", "print the waypoint list for BAW123": an aircraft's route listed
  rule { "print", "listrte", near = { 4, "route plan waypoint waypoints" },
         when = function(g, i) return g:has_ref(i + 1, i + 7, "aircraft") and not g:word_in(i + 1, #g.t + 1, "log") end }
  -- "print ACA557's state", "dump the state of KLM12": an aircraft's state shown, no text for the log
  rule { "print dump", "pos", near = { 4, "state status info details" },
         when = function(g, i) return g:has_ref(i + 1, i + 6, "aircraft") end }
  rule { "print", "echo" }
  -- "note to self: ...", "note for me: ...": the experimenter's own note, no text for the log
  rule { "note", false, next = "to for", when = function(g, i) return g:word(i + 2, "@note_to_self") end }
  -- "designer's note, no action: ...": a note said to need no action is the speaker's own, no text for the log
  rule { "note", false, when = function(g, i)
    local k = (g.t[i + 1] or {}).kind == "punct" and i + 2 or i + 1
    return g:word(k, "no") and g:word(k + 1, "action")
  end }
  -- "put a note in the log: conflict 3 injected", "log: run 2 started", "write a message for the participant:
  -- Block 1 finished": the text after the colon
  -- ("log 'policy v3 ckpt 2000'", "note 'ep7 terminal: LoS=0'": the text quoted straight after the word; "write the
  -- message 'climb'" says no place it goes: asked)
  rule { "note comment log message", "echo", when = function(g, i)
    if g.t[i + 1] ~= nil and g.t[i + 1].kind == "quoted" and not g:word(i, "message") then return true end
    for k = i + 1, math.min(#g.t, i + 4) do
      if g.t[k].kind == "punct" and g.t[k].text == ":" then return k < #g.t end
    end
    return false
  end }
  -- "put a note on screen saying baseline run", "show a message that says trial 2": the text after "saying"
  rule { "note message", "echo", when = function(g, i)
    local k = g:find_word(i + 1, math.min(#g.t + 1, i + 6), "saying says reading")
    return k < #g.t and g:word(k, "saying says reading") and (not g:word(k, "says") or g:word(k - 1, "that which"))
  end }
  -- "add wind at 52N 4E, FL300, from 270 at 60 knots": a wind where the verb places it
  rule { "wind winds", "wind", prev = { 2, "add set define put create make" } }
  -- "give me a wind over Queenstown, 270 degrees at 20 knots": the instructor's "give me", no aircraft named
  rule { "wind winds", "wind", prev = { 3, "give" }, when = function(g) return not g:has_ref(1, #g.t + 1, "aircraft") end }
  -- "wind set at 35.5 139.8 from 270 degrees 40 knots": the verb said after the noun
  rule { "wind winds", "wind", next = "set" }
  -- ("jetstream: 260 degrees 90 knots at 59.5 11": a wind by its kind, no aircraft named)
  rule { "jetstream jetstreams", "wind", when = function(g) return not g:has_ref(1, #g.t + 1, "aircraft") end }
  rule { "set", false, prev = { 1, "wind winds" } }
  -- "set a westerly at 40 knots over -27.4 153.1": a wind named by where it blows from (lexicon.wind_points),
  -- put somewhere by the verb, no aircraft named
  -- ("put a westerly wind of 40 knots over Willisau": the noun after it is the instruction's word, the point its direction)
  -- ("put a 30 knot westerly over London": its speed between)
  rule { "northerly easterly southerly westerly northeasterly southeasterly southwesterly northwesterly", "wind",
         prev = { 4, "add set define put create" }, when = function(g, i)
    return not g:word(i + 1, "wind winds") and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  rule { "wind winds", "wind", prev = { 1, "northerly easterly southerly westerly northeasterly southeasterly southwesterly "
         .. "northwesterly" }, when = function(g) return not g:has_ref(1, #g.t + 1, "aircraft") end }
  -- "wind from 270 at 40 kt over 55.5 12.5", "a wind of 270 at 40 knots": where it blows from, said after it
  rule { "wind winds", "wind", next = "from of", when = function(g) return not g:has_ref(1, #g.t + 1, "aircraft") end }
  -- "the wind please put from 270 with 40 knots at 47.4 19.2", "the wind for experiment from 300 degrees 50 knots
  -- at ...": "please", a verb of setting or "for (the) experiment" between the noun and "from" (Hungarian, Romanian
  -- and Ukrainian English word order), a number after "from", no aircraft named
  rule { "wind winds", "wind", when = function(g, i)
    local k = i + 1
    while k <= i + 5 and g:word(k, "please kindly put set give make for the experiment simulation scenario exercise") do
      k = k + 1
    end
    return k > i + 1 and g:word(k, "from") and (g:quantities(k + 1, k + 2)[1] or {}).b == k + 1
      and not g:has_ref(1, #g.t + 1, "aircraft") and not g:word_in(math.max(1, i - 3), i, "what what's whats show tell get check")
  end }
  -- "wind 270 at 30 kt at 52 4": its direction straight after it, its speed in knots after that ("wind 270 at
  -- 15 over Phoenix": three digits, "at" and a bare number, as a wind is reported, are the two)
  rule { "wind winds", "wind", when = function(g, i)
    local qs = g:quantities(i + 1, math.min(#g.t + 1, i + 6))
    return qs[1] ~= nil and qs[1].b == i + 1 and qs[2] ~= nil
      and (qs[2].kind == "speed" or g:wind_reported(qs[1], qs[2]))
      and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- "wind at 6.5 north 3.3 east from 220 at 15 knots", "a harmattan wind at 12N 8.5E, from 050, 20 knots": a
  -- position straight after it ("at" before it or none), where it blows from said after that
  -- ("wind at 53.4 -6.3 from 270 at 25 kts": a latitude and longitude in bare decimal degrees; "wind at
  -- 38.8 north 9.1 west, FL100, 310 degrees 25 knots": its direction in degrees and its speed in knots said
  -- after the position, no "from"; "wind 55.9 -3.3 270 at 40": as a wind is reported)
  rule { "wind winds", "wind", when = function(g, i)
    -- ("wind 47.2 11.4 FL200 from 270 at 45 kts": the position straight after it, typed)
    local q = g:word(i + 1, "at over") and g:quantities(i + 2, i + 3)[1] or g:quantities(i + 1, i + 2)[1]
    if q and q.b == i + 1 and not q.number.typed then q = nil end
    local nx = q and q.kind == "plain" and g:quantities(q.e, q.e + 1)[1] or nil
    local pair = nx ~= nil and nx.kind == "plain" and q.number.typed and nx.number.typed
      and math.abs(q.value) <= 90 and math.abs(nx.value) <= 180
      -- ("wind 52 4.5 from 270 at 40kt": a decimal in either number, or "from" straight after the two)
      and ((q.number.digits or ""):find("%.") ~= nil or (nx.number.digits or ""):find("%.") ~= nil
        or g:word(nx.e, "from"))
    local told = g:find_word(i + 3, #g.t + 1, "from") <= #g.t
    local after = q and not told and g:quantities(q.e, #g.t + 1) or {}
    for k, v in ipairs(after) do
      told = told or (v.kind == "angle" and (g:quantities(v.e, v.e + 1)[1] or {}).kind == "speed")
        -- (its direction and speed as a wind is reported, "270 at 40", "270 at 40 knots" (G:wind_reported), or
        -- typed after a typed position, "wind at 52.3 4.7, 270 30" (G:wind_typed))
        or (after[k + 1] ~= nil and (g:wind_reported(v, after[k + 1]) or (pair and g:wind_typed(v, after[k + 1]))
          or (after[k + 1].kind == "speed" and v.kind == "plain" and #(v.number and v.number.digits or "") == 3
            and v.value <= 360 and g:word(v.e, "at") and after[k + 1].b == v.e + 1 and after[k + 1].value <= 200)))
    end
    return q ~= nil and (q.kind == "lat" or q.kind == "lon" or pair) and told
      and not g:has_ref(1, #g.t + 1, "aircraft") and not g:word_in(math.max(1, i - 3), i, "what what's whats show tell get check")
  end }
  -- "wind at Arlanda 270 degrees 25 knots", "wind over ESSA from 250 at 20 knots": the request opening with the
  -- wind at a place, where it blows from told after it (in degrees before its speed, or after "from")
  rule { "wind winds", "wind", next = "at over", when = function(g, i)
    if i ~= g:skip_fillers(1) or g:has_ref(1, #g.t + 1, "aircraft") then return false end
    local told = false
    for _, v in ipairs(g:quantities(i + 2, #g.t + 1)) do
      told = told or ((v.kind == "angle" or g:word(v.b - 1, "from")) and (g:quantities(v.e, v.e + 2)[1] or {}).kind == "speed")
    end
    return told
  end }
  -- "what's the wind at 52.3, 4.7?", "show me the wind at 52N 4E FL300": the wind there, shown
  rule { "wind winds", "getwind", prev = { 3, "what what's whats show tell get check" } }
  -- "wind check at CYVR", "winds check over EHAM": a pilot's "wind check", the wind there shown
  rule { "wind winds", "getwind", next = "check" }
  -- "wind at 30.1 31.4 FL200", "winds over 33N 7W?", "wind 50.8 4.4 fl200?": the request opening with the wind at
  -- a position (typed straight after the word, or after "at"/"over"; a level after it at most) and nothing else,
  -- no direction nor speed told: the wind there, shown; so is the wind at or over a waypoint ("wind over BOKSU at
  -- FL100")
  local function wind_at_position(g, i)
    local p = g:word(i + 1, "at over") and i + 2 or i + 1
    if i ~= g:skip_fillers(1) then return false end
    local place = p == i + 2 and g:refs_in(p, p + 1, "waypoint")[1]
    local qs = g:quantities(place and place.e or p, #g.t + 1)
    local a, b = qs[1], qs[2]
    local e = place and place.b == p and place.e
    if not e then
      if not (a and b and a.b == p and b.b == a.e and a.number.typed and b.number.typed) then return false end
      e, qs = b.e, { nil, nil, qs[3] }
    else
      qs = { nil, nil, qs[1] }
    end
    -- (the level after a comma too, and the question said after it: "wind at 36.7 north 127.5 east, flight level
    -- 310, how much?")
    local l = e
    while g.t[l] and g.t[l].text == "," do l = l + 1 end
    if g:word(l, "at") then l = l + 1 end
    if qs[3] and qs[3].b == l and qs[3].kind == "alt" then e = qs[3].e end
    for x = e, #g.t do
      if g.t[x].kind ~= "punct" and not g.t[x].filler
          and not (g:word(x, "how much what is it now") and g.t[#g.t].text == "?") then
        return false
      end
    end
    return true
  end
  rule { "wind winds", "getwind", when = wind_at_position }
  rule { "echo", "echo", when = function(g, i) return g.t[i + 1] ~= nil and g.t[i + 1].kind == "quoted" end }
  -- "instructor: echo exercise starts in 2 minutes": TrafScript's ECHO opening the request (after a speaker's
  -- label) and a word after it that spells nothing ("echo kilo lima ..." is a registration spelled)
  rule { "echo", "echo", when = function(g, i)
    local nx = g.t[i + 1]
    return i == g:skip_fillers(1) and nx ~= nil and nx.kind == "word" and PHONETIC[nx.text] == nil
  end }
  -- "kindly echo the text RUN 4 START to the console", "echo RUN 7 START in the log": words sent to the console,
  -- screen, window or log
  rule { "echo", "echo", when = function(g, i)
    local k = g:find_word(i + 2, #g.t + 1, "to on in into")
    return k <= #g.t and g:word(g:word(k + 1, "the") and k + 2 or k + 1, "console screen display window log")
  end }
  -- "write 'trial 4 start' into the log", "put 'baseline done' in the log", "put 'Run 3 start' on the
  -- screen", "write 'run 3 starts now' to the console": quoted text for the log, the screen or the console
  rule { "write put add enter show display", "echo", when = function(g, i)
    return g.t[i + 1] ~= nil and g.t[i + 1].kind == "quoted"
      and g:word_in(i + 2, math.min(#g.t + 1, i + 6), "log screen scope console")
  end }

  -- "write a message on the screen, 'session two starts'", "show a note in the log, 'run 2 done'": quoted text
  -- after a message's noun and where it goes, no aircraft named between
  -- ("write a message 'start of run 3' into the log", "show the text 'trial 3 starts' to the participant": where it
  -- goes said in the four words after the quoted text)
  rule { "write put show display", "echo", when = function(g, i)
    for k = i + 1, math.min(#g.t, i + 9) do
      if g.t[k].kind == "quoted" then
        local where = "log screen scope console participant participants"
        return g:word_in(i + 1, k, "message note text")
          and (g:word_in(i + 1, k, where) or g:word(k + 1, "to on in into for")
            and g:word_in(k + 2, math.min(#g.t + 1, k + 5), where))
          and not g:has_ref(i + 1, k, "aircraft")
      end
    end
    return false
  end }
  -- "write on the screen: exercise starts now", "show in the log: run 2 done": the text after the colon, for the
  -- screen or the log named between the verb and the colon
  -- ("put a message up on the screen: welcome!": a message's noun and "up" between)
  rule { "write put show display", "echo", when = function(g, i)
    for k = i + 1, math.min(#g.t - 1, i + 7) do
      if g.t[k].kind == "punct" then
        return g.t[k].text == ":" and g:word_in(i + 1, k, "log screen scope console")
          and (k <= i + 5 or not g:has_ref(i + 1, k, "aircraft"))
      end
    end
    return false
  end }

  -- conflict detection and resolution
  -- "the look-ahead time for conflict detection", "the radius for resolution", "look ahead time 5 minutes
  -- for the detection", "the safety distance used by the conflict detection", "look ahead time 300 seconds for CD":
  -- the setting's owner (the setting named within the ten words before)
  rule { "detection resolution asas cd", false, prev = { 3, "for of by" }, when = function(g, i)
    return g:word_in(math.max(1, i - 10), i, "look lookahead dtlook zone radius separation distance")
  end }
  -- "conflict detection look ahead five minutes", "cd hpz 1000ft", "the conflict detection radius on 5 miles":
  -- detection names the setting's owner, no switch (one is said with an on or off word: "detection on, look ahead 5
  -- minutes"; "on" before a number is the value's, German "auf")
  rule { "detection asas cd", false, near = { 2, "look lookahead dtlook hpz rpz zonedh zoner radius" }, when = function(g, i)
    for k = math.max(1, i - 3), math.min(#g.t, i + 3) do
      local q = g:word(k, "on") and g:quantities(k + 1, k + 2)[1]
      if g:word(k, "@on @off") and not (q and q.b == k + 1) then return false end
    end
    return true
  end }
  -- "look-ahead five minutes on the conflict probe", "probe look-ahead two minutes": the conflict probe is
  -- conflict detection, named as the setting's owner (no switch)
  rule { "probe", false, when = function(g, i)
    return g:word_in(1, #g.t + 1, "look lookahead dtlook") and not g:word_in(1, #g.t + 1, "@on @off")
  end }
  -- "what look-ahead time is the detection using?", "which lookahead does conflict detection use": the detection
  -- that uses the setting named in the eight words before is its owner, no switch
  -- (an on or off word around it switches, the verb of using after it aside: "use" is one of lexicon.on)
  rule { "detection asas cd", false, next = "using use uses used", when = function(g, i)
    return g:word_in(math.max(1, i - 8), i, "look lookahead dtlook") and not g:word_in(math.max(1, i - 3), i, "@on @off")
      and not g:word_in(i + 2, math.min(#g.t + 1, i + 4), "@on @off")
  end }
  -- "asas dt 2 sec", "dt asas 2": the interval of conflict detection (DT ASAS), no switch
  rule { "detection asas cd", false, near = { 1, "dt timestep" } }
  rule { "detection asas cdmethod cd", "asas" }
  -- ("detect conflicts state based", "detect conflicts with a 5 mile radius and 1000 ft": the verb, detection on)
  rule { "detect", "asas", next = "conflicts conflict" }
  -- "check the conflicts every 2 seconds", "check for conflicts every 5 s": how often conflict detection runs (DT
  -- ASAS, m:time_step), "every" and its time straight after the conflicts
  rule { "check checks checking", "dt", near = { 3, "conflict conflicts" }, when = function(g, i)
    local k = g:skip_fillers(i + 1)
    if g:word(k, "for the") then k = g:skip_fillers(k + 1) end
    if g:word(k, "the") then k = g:skip_fillers(k + 1) end
    return g:word(k, "conflict conflicts") and g:word(k + 1, "every")
  end }
  -- a switch said where word i is: an on or off word straight after it, or a switching verb in the four words
  -- before ("conflict alerts on", "turn on the conflict probe"; "on the conflict probe" switches nothing)
  local function switched(g, i)
    return g:word(i + 1, "@on @off") or g:word_in(math.max(1, i - 4), i, "switch turn enable disable activate deactivate")
  end
  -- "switch the conflict probe to state based", "conflict probe off": the conflict probe is conflict detection
  -- (its look-ahead said, it names that setting's owner, "look-ahead five minutes on the conflict probe", unless
  -- switched where it is said: "conflict probe on, lookahead two minutes")
  rule { "probe", "asas", prev = { 1, "conflict conflicts" }, when = function(g, i)
    return not g:word_in(1, #g.t + 1, "look lookahead dtlook") or switched(g, i)
  end }
  -- "conflict alerts on", "turn on conflict alerting": a radar display's conflict alert switched is conflict
  -- detection; unswitched it names an alert ("the moment the conflict alert sounded", "the conflict alerting
  -- zone"), and with an aircraft named it is the reason for its instruction ("KLM12 conflict alert, turn left")
  rule { "alert alerts alerting", "asas", prev = { 1, "conflict conflicts" }, when = function(g, i)
    return switched(g, i) and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- "turn on the crash warnings", "switch the conflict warnings on", "turn on the warning system": a newcomer's
  -- words for conflict detection, switched, no aircraft named
  rule { "warning warnings", "asas", when = function(g, i)
    return (g:word(i - 1, "conflict conflicts crash collision") or g:word(i + 1, "system"))
      and switched(g, g:word(i + 1, "system") and i + 1 or i) and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  rule { "cr", "reso", next = "on off mvp" }  -- "CD on, CR off", "cr mvp": conflict resolution by its letters
  -- ("CR: MVP": the letters as a label, a colon or a dash before the setting)
  rule { "cr", "reso", when = function(g, i)
    local p = g.t[i + 1]
    return p ~= nil and p.kind == "punct" and (p.text == ":" or p.text == "-") and g:word(i + 2, "on off mvp")
  end }
  -- "vertical resolution factor 1.1", "horizontal reso safety factor to 1.15": the safety factor
  -- ("resolution factors: horizontal 1.2, vertical 1.1": both named by the plural)
  -- ("reso mvp, margins 1.05": the method named straight after the word is set, whatever factor is said beside it)
  rule { "reso resolution", "reso", next = "mvp" }
  rule { "resolution resolve reso resolutions resolver", false, near = { 3, "factor factors" } }
  rule { "factor factors", "rfac", prev = { 4, "resolution resolutions reso resolve safety" } }
  -- "give the horizontal resolutions a 20 percent margin": the safety factor said as a margin in percent
  rule { "resolution resolve reso resolutions resolver", false, near = { 5, "margin margins" } }
  rule { "margin margins", "rfac", prev = { 5, "resolution resolutions reso resolve" }, not_near = { 1, "factor" } }
  -- ("add 10% margin on the horizontal resolution": the margin said before the resolutions it widens)
  rule { "resolution resolve reso resolutions resolver", false, prev = { 4, "margin margins" } }
  rule { "margin margins", "rfac", near = { 4, "resolution resolutions reso" }, not_near = { 1, "factor" } }
  -- "Resolution method MVP, horizontal factor 1.2": a factor of a direction, resolution said before
  -- ("please make vertical factor 1.05 also": said alone, no aircraft named, the only factor squawk sets of a
  -- direction is the resolutions')
  rule { "factor", "rfac", prev = { 1, "horizontal lateral vertical" }, when = function(g, i)
    return g:word_in(1, i, "resolution resolutions reso resolve mvp") or not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  -- ("vert margin 1.2", "hor margin back to default 1.05", "margin h to 1.2", "margins 1.05 both h and v": a margin of
  -- a direction, short or long, no aircraft named, is the resolutions' safety factor)
  rule { "margin margins", "rfac", when = function(g, i)
    if g:has_ref(1, #g.t + 1, "aircraft") then return false end
    return g:word(i - 1, "horizontal lateral vertical hor vert h v")
      or g:word(i + 1, "horizontal lateral vertical hor vert h v") or g:word(i + 1, "factor")
      or (g:word(i, "margins") and g:word_in(i + 1, math.min(#g.t + 1, i + 6), "both"))
  end }
  -- (the resolution said of the vertical ones, "let MVP use vertical speed in the resolutions", sets no method;
  -- one switched on in a clause of its own, "turn on MVP resolution and let it use vertical too", does: RESO
  -- MVP beside the RMETHV)
  -- ("use MVP with vertical manoeuvres", "switch on MVP with vertical resolution": the method the object of the verb
  -- of switching, straight before it, is switched on)
  rule { "mvp resolution resolve reso resolutions resolver", false, when = function(g, i)
    if g:word(i, "mvp") and g:preceded_by(i, 2, "@on switch turn") then return false end
    local lo, hi = g:clause_around(i)
    local set_here = g:word_in(lo, hi, "@on mvp")
    for k = 1, #g.t do
      if g:vertical_resolutions(k) and (not set_here or (k >= lo and k < hi)) then return true end
    end
    return false
  end }
  -- "after a resolution aircraft should resume nav once past CPA": when navigation resumes after one (RESNAV)
  rule { "resolution resolutions resolving", false, prev = { 2, "after following" }, when = function(g, i)
    return g:word_in(i + 1, math.min(#g.t + 1, i + 8), "resume resumes") and g:word_in(i + 1, #g.t + 1, "cpa")
  end }
  -- "the resolution should resume navigation after the CPA": what a resolution should do when it ends (RESNAV),
  -- a modal verb straight after it, no method to set
  rule { "resolution resolutions", false, next = "should shall must will", when = function(g, i)
    return g:word_in(i + 2, math.min(#g.t + 1, i + 4), "resume resumes") and g:word_in(i + 2, #g.t + 1, "cpa")
  end }
  -- "LATAM 3090 climb FL160, vertical resolution", "turn left 30 degrees - a lateral resolution": the kind of
  -- resolution an instruction before it is, named after it to the end of the request (no setting)
  rule { "resolution", false, prev = { 2, "vertical lateral horizontal" }, when = function(g, i)
    for k = i + 1, #g.t do
      if g.t[k].kind ~= "punct" and not g.t[k].filler then return false end
    end
    for k = 1, i - 2 do
      local intent = g:intent_at(k)
      if intent == "alt" or intent == "hdg" or intent == "spd" or intent == "vs" then return true end
    end
    return false
  end }
  -- "For the resolution manoeuvre LOT3CM shall turn 15 degrees right", "Resolution: aircraft shall resume
  -- navigation after passing the CPA": the noun naming what an aircraft's instruction said in the same request
  -- is for (a manoeuvre after it, or a heading closed by ":"), no setting of its own
  local AIRCRAFT_INTENTS = { alt = true, hdg = true, spd = true, vs = true, resnav = true, lnav = true, direct = true }
  -- an aircraft's instruction (level, heading, speed) said somewhere in the request but at word i
  local function instructed(g, i)
    for k = 1, #g.t do
      local intent = k ~= i and g:intent_at(k)
      if intent == "alt" or intent == "hdg" or intent == "spd" or intent == "vs" then return true end
    end
    return false
  end
  rule { "resolution", false, when = function(g, i)
    local t = g.t[i + 1]
    if not (g:word(i + 1, "manoeuvre maneuver manoeuvres maneuvers")
        or (t and t.kind == "punct" and t.text == ":" and g:skip_fillers(1) == i)) then
      return false
    end
    for k = i + 2, #g.t do
      if AIRCRAFT_INTENTS[g:intent_at(k) or ""] then return true end
    end
    return false
  end }
  -- ("after a resolution, the aircraft should go back to their route when they are past the CPA": the
  -- resolution after which navigation resumes, CPA named after it, no setting of its own)
  rule { "resolution resolutions", false, prev = { 2, "after following" }, when = function(g, i)
    return g:word_in(i + 1, #g.t + 1, "cpa") and g:word_in(i + 1, #g.t + 1, "route routes navigation nav")
  end }
  -- "resolution only past CPA", "keep resolving until past CPA": when a resolution ends and navigation resumes
  -- (RESNAV PASTCPA); "past" before "CPA" names it
  -- ("resolve past CPA": resolving until past it)
  -- ("reso mvp, resume past cpa": a method named straight after it sets it, the clause after it says when)
  rule { "resolution resolutions resolving reso resolve", false, near = { 4, "past" }, when = function(g, i)
    return g:word_in(i + 1, math.min(#g.t + 1, i + 6), "cpa") and not g:word(i + 1, "mvp @mvp")
  end }
  rule { "past", "resnav", next = "cpa", when = function(g, i)
    return g:word_in(1, i, "resolution resolutions resolving reso resolve")
  end }
  -- ("resume nav past CPA for resolution", "... after resolving"): the resolution whose end past CPA is
  -- said straight before it, no setting of its own
  rule { "resolution resolutions resolving reso", false, prev = { 1, "for after following from of" },
         when = function(g, i) return g:word_in(math.max(1, i - 4), i, "cpa") end }
  -- "resolve the conflict by turning DLH4AB right to heading 300", "turn KLM12 left 20 degrees to solve the
  -- conflict": the conflict an aircraft's instruction in the request is for (a purpose), no method to set
  rule { "resolve solve resolving solving", false, next = "the this that a", when = function(g, i)
    return g:word(i + 2, "conflict conflicts") and instructed(g, i)
  end }
  -- ("fast forward a minute and watch the resolution kick in"): the resolution watched after an instruction is
  -- what the run will show, no method to set
  rule { "resolution resolutions", false, prev = { 3, "watch watching see observe" }, when = function(g, i)
    return g:any_instruction_in(1, i - 1)
  end }
  -- "let the computer steer them apart", "have the simulator solve the conflicts by itself": resolution by the
  -- simulation (the computer or the simulation the agent, no aircraft named)
  rule { "solve resolve steer separate", "reso", when = function(g, i)
    return g:word_in(math.max(1, i - 3), i, "computer @sim") and not g:has_ref(1, #g.t + 1, "aircraft")
      and (g:word_in(i + 1, math.min(#g.t + 1, i + 4), "apart conflicts conflict")
        or g:word(i + 1, "them"))
  end }
  rule { "resolution resolve reso resolver", "reso" }  -- ("switch the resolver on": the resolution's own word)
  -- "enable MVP", "switch to MVP": the method named alone is resolution by it
  rule { "mvp", "reso", prev = { 3, "@on switch" } }
  rule { "mvp", "reso", next = "on" }  -- "and MVP on"
  -- ("turn the MVP off and the ASAS on", "MVP off, detection on": the method switched off is resolution's own
  -- switch, G handlers' m:reso switches it off; never an aircraft's name)
  rule { "mvp", "reso", next = "@off" }
  -- "pz 5 nm, dh 1000, lookahead 300, mvp": the method named alone as an item of a list of conflict
  -- detection settings
  -- ("turn on the ASAS and the MVP and put look ahead 240 seconds": "the" between, "and" after)
  rule { "mvp", "reso", when = function(g, i)
    local b = g:word(i - 1, "the") and i - 2 or i - 1
    local before, after = g.t[b], g.t[i + 1]
    return before ~= nil and (before.kind == "punct" or g:word(b, "and"))
      and (after == nil or after.kind == "punct" or g:word(i + 1, "and"))
      and g:word_in(1, i - 1, "pz rpz zone zoner zonedh dh dtlook lookahead asas cdmethod detection")
  end }
  -- ("3 mile separation horizontally", "a 1000 ft separation"): a distance or height said just before it,
  -- no aircraft named (one kept apart from another is an instruction squawk does not read)
  -- "descend to FL280 to get vertical separation", "climb FL300 for separation from TRA345": the purpose of an
  -- aircraft's instruction in the request, no value of the protected zone said with it
  rule { "separation", false, prev = { 3, "get gain ensure provide keep maintain achieve establish for" },
         when = function(g, i)
    return #g:quantities(i + 1, math.min(#g.t + 1, i + 4)) == 0 and instructed(g, i)
  end }
  -- "give IBE32 some vertical separation from the Ryanair, put it at FL320": separation from an aircraft
  -- named after it is the purpose of the level, heading or speed given, never the protected zone ("give
  -- IBE32 1000 ft of separation from the Ryanair", a height said just before it, is left to the zone's reading,
  -- which asks about the aircraft)
  -- "300 seconds to loss of separation, 2000 feet above it": the separation lost is an event (a conflict's
  -- time to it), never the protected zone, whatever height is said after it
  rule { "separation", false, prev = { 2, "loss lose loses losing" } }
  rule { "separation", false, next = "from with", when = function(g, i)
    local k = g:word(i + 2, "the") and i + 3 or i + 2
    return (g:has_ref(i + 2, k + 1, "aircraft") or g:airline_at(k) ~= nil)
      and #g:quantities(math.max(1, i - 4), i) == 0
  end }
  rule { "separation", "zone", next = "from with", when = function(g, i)
    local k = g:word(i + 2, "the") and i + 3 or i + 2
    return (g:has_ref(i + 2, k + 1, "aircraft") or g:airline_at(k) ~= nil) and #g:quantities(math.max(1, i - 4), i) > 0
  end }
  rule { "separation", "zone", prev = { 1, "nm mile miles ft foot feet" },
         when = function(g) return not g:has_ref(1, #g.t + 1, "aircraft") end }
  rule { "separation", false, not_prev = { 2, "minimum minima horizontal vertical lateral" },
         not_near = { 4, "minimum minima nm nautical mile miles radius ft foot feet horizontally vertically "
           .. "laterally" } }
  rule { "radius", false, prev = { 12, "circle circular" } }  -- "a circle ... with a 20 mile radius"
  -- "the safety distance used for the conflict detection": the protected zone, in plain words, where conflicts are
  -- named and no aircraft is
  rule { "distance", "zone", prev = { 1, "safety" }, when = function(g, i)
    return g:word_in(1, #g.t + 1, "conflict conflicts detection") and not g:has_ref(1, #g.t + 1, "aircraft")
  end }
  rule { "protected protection prot pz rpz hpz separation zone zones zoner zonedh radius", "zone" }  -- ("prot zone", "zones to 10 miles")
  rule { "sep", "zone", prev = { 1, "horizontal lateral vertical" } }  -- "horizontal sep back to 5nm"
  rule { "half", "zone", next = "height" }
  rule { "look", "dtlook", next = "ahead" }
  -- "have the computer look further ahead for conflicts": the look-ahead, said with how far
  rule { "look", "dtlook", next = "further farther", when = function(g, i) return g:word(i + 2, "ahead") end }
  -- "can it look 5 minutes ahead for conflicts?", "make it look 3 minutes ahead": the time said between the verb
  -- and "ahead"
  rule { "look", "dtlook", when = function(g, i)
    local q = g:quantities(i + 1, math.min(#g.t + 1, i + 5))[1]
    return q ~= nil and q.kind == "time" and q.b == i + 1 and g:word(q.e, "ahead")
  end }
  -- "make the safety circle 4 miles", "a bigger safety bubble": the protected zone in a newcomer's words
  rule { "circle bubble", "zone", prev = { 1, "safety" } }
  rule { "look", "dtlook", prev = { 1, "dt" } }
  -- "what does test2 look like rn", "how does DLH4AX look now?": an aircraft's state asked (POS), no value said
  rule { "look", "pos", when = function(g, i)
    local r = g:refs_in(1, i, "aircraft")[1]
    if not r or #g:quantities(1, #g.t + 1) > 0 then return false end
    return g:word(r.b - 1, "does do") and g:skip_fillers(r.e) == i
      and (g:word(i + 1, "like") and g:word_in(1, r.b, "what") or g:word_in(1, r.b, "how"))
  end }
  rule { "lookahead dtlook", "dtlook" }
  -- "UAE45 step down to FL340, turbulence", "... for turbulence": with an aircraft named, turbulence is its reason
  -- or its situation, no switch of the simulation's noise (unless switched: "UAE45 climb, and turbulence on")
  rule { "turbulence", false, when = function(g, i)
    return g:has_ref(1, #g.t + 1, "aircraft")
      and not g:word_in(math.max(1, i - 3), i + 4, "on off enable disable switch activate deactivate noise")
  end }
  rule { "turbulence noise", "noise" }

  -- shapes and the deletion area ("in the area" alone names no area)
  -- the points said after word i: latitude/longitude pairs, marked or two plain numbers in a row
  local function corners_after(g, i)
    local n, lat, k = 0, false, 1
    local qs = g:quantities(i + 1, #g.t + 1)
    while k <= #qs do
      local q, nx = qs[k], qs[k + 1]
      if q.kind == "lat" then
        lat = true
      elseif q.kind == "lon" and lat then
        n, lat = n + 1, false
      elseif q.kind == "plain" and nx and nx.kind == "plain" and nx.b - q.e <= 1 and math.abs(q.value) <= 90
          and math.abs(nx.value) <= 180 then
        n, k = n + 1, k + 1
      end
      k = k + 1
    end
    return n
  end
  rule { "area", "area", prev = { 2, "deletion delete experiment" } }
  -- "delete acft leaving box 51 3 53 6.5", "remove aircraft that leave the area 51 3 53 6": the deletion area, its
  -- two corners after the aircraft's leaving (no aircraft deleted now)
  rule { "leaving leave leaves exiting exit exits", "area", prev = { 4, "delete del remove" }, when = function(g, i)
    return corners_after(g, i) == 2 and g:kind_only_aircraft()
  end }
  -- "restrict sim area to box 45 6 48 13", "limit the simulation area to 45 6 48 13": the area traffic is
  -- kept in (aircraft leaving it are deleted), two corners after it ("box" is its form, no shape named)
  rule { "area", "area", prev = { 2, "@sim" }, when = function(g, i) return corners_after(g, i) == 2 end }
  rule { "area", "area", prev = { 3, "restrict limit confine" }, when = function(g, i) return corners_after(g, i) == 2 end }
  rule { "box", false, prev = { 2, "area" }, when = function(g, i) return corners_after(g, i) == 2 end }
  rule { "circle", "circle", near = { 3, "@named" } }
  -- "circle C1 centred on 52 4, radius 20 nm": a name straight after it and a centre
  rule { "circle", "circle", when = function(g, i)
    return (g:has_ref(i + 1, i + 2, "waypoint") or g:has_ref(i + 1, i + 2, "aircraft")) and corners_after(g, i) >= 1
  end }
  -- "a circle ZONE1 at 52.0 4.5", "a circular area C1 around 52 4": a shape at a position
  rule { "circle circular", "circle", when = function(g, i)
    for _, q in ipairs(g:quantities(i + 1, math.min(#g.t + 1, i + 8))) do
      if q.kind == "lat" or (q.kind == "plain" and q.number.decimal) then return true end
    end
    return false
  end }
  rule { "box", "box", near = { 3, "@named" } }
  -- "Polygon LTMA: 51.2 -1.0, 51.9 -1.0, ...", "a line REF1 from 55.68 -3.27 to 56.12 -3.20": a shape's
  -- word with the corners after it (three or more for a polygon, two for a line)
  rule { "polygon poly", "poly", when = function(g, i) return corners_after(g, i) >= 3 end }
  -- ("draw the box: TANKER1 from 54.0N 005.0E to 54.5N 006.5E": the name after a colon)
  rule { "box", "box", when = function(g, i)
    local k = g.t[i + 1] and g.t[i + 1].text == ":" and i + 2 or i + 1
    return corners_after(g, i) == 2 and (g:has_ref(k, k + 1, "waypoint") or g:has_ref(k, k + 1, "aircraft"))
  end }
  -- ("define box tma 51.5 3.5 53 6": a new name in lower case straight after the word, the corners after it)
  rule { "box", "box", when = function(g, i) return corners_after(g, i) == 2 and g:shape_name_at(i + 1) end }
  rule { "circle", "circle", when = function(g, i) return corners_after(g, i) == 1 and g:shape_name_at(i + 1) end }
  rule { "line", "line", when = function(g, i)
    return corners_after(g, i) == 2 and (g:followed_by(i, 3, "@named") or g:has_ref(i + 1, i + 3, "waypoint")
      or g:has_ref(i + 1, i + 3, "aircraft") or g:shape_name_at(i + 1))
  end }

  -- the performance model ("switch to the simple class-based performance model", "use OpenAP")
  rule { "performance perf", "perf", when = function(g) return g:word_in(1, #g.t + 1, "@perf_models model models") end }
  rule { "openap", "perf", prev = { 3, "@on switch" } }

  -- the radar display
  rule { "trail trails", "trail" }

  -- The words people use for each command, beyond the rule words above:
  -- retrieval documents for the LLM modes (grammar.documents()).
  words "CRE" "add, create, spawn, insert or put a new aircraft or flight of a type (Boeing, Airbus) at a position with heading, altitude and speed"
  words "ALT" "climb, descend, climb and maintain, descend and maintain, cruise at, level off at, flight level FL, feet ft, altitude, higher, lower, raise, put at a level"
  words "HDG" "turn left, turn right, fly heading, point, steer, vector, head north south east west, due, course, degrees, direction"
  words "SPD" "speed, knots kts, Mach, slow down, speed up, reduce, increase, accelerate, decelerate, airspeed of an aircraft"
  words "VS" "vertical speed, vertical rate, rate of climb or descent, feet per minute, fpm, ft/min"
  words "DEL" "delete, remove, take out, get rid of an aircraft from the simulation"
  words "MOVE" "teleport, move, place, reposition, relocate an aircraft to a new position, altitude, heading and speed"
  words "POS" "show, details, status, information, where is, report position, altitude and speed of an aircraft"
  words "FF" "fast forward, fast-time, speed up or accelerate the simulation, skip ahead in time"
  words "HOLD" "pause, freeze, stop or halt the simulation"
  words "OP" "resume, continue, unpause, start or run the simulation"
  words "DT" "simulation time step, timestep, update interval in seconds"
  words "DTMULT" "simulation speed factor, run the sim slower or faster than real time, half speed, double speed"
  words "DEST" "destination, fly to, bound for, land at an airport"
  words "ORIG" "origin, departure airport, coming from"
  words "ADDWPT" "add or insert a waypoint, fix or point to the route or flight plan of an aircraft, crossed at an altitude and speed"
  words "DELWPT" "delete or remove a waypoint from the route or flight plan"
  words "DEFWPT" "define, create or name a custom waypoint or fix at a position"
  words "LISTRTE" "list or show the route, flight plan or waypoints of an aircraft"
  words "DIRECT" "direct to, proceed direct, fly straight to, cleared direct a waypoint"
  words "ATALT" "when or once an aircraft reaches, passes or gets to an altitude or flight level, then do a command"
  words "ATSPD" "when or once an aircraft reaches, slows to or accelerates to a speed, then do a command"
  words "ATDIST" "when or once an aircraft is within a distance in nautical miles of a point, then do a command"
  words "TRAIL" "show, hide, enable or disable aircraft trails, the history or track of where aircraft have been on the radar; trail colour blue, red or yellow"
  words "ECHO" "print, show or display a message or text"
end
