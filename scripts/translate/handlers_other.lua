-- Handlers of the traffic, route and simulation-control instructions (CRE,
-- MOVE, DEL, DIRECT, ADDWPT, DEFWPT, DELWPT, DEST/ORIG, LNAV/VNAV, POS,
-- LISTRTE, BANK, FF, DT, DTMULT, SEED, IC, ECHO, ASAS, RESO, ZONER/ZONEDH,
-- DTLOOK, NOISE, TRAIL); see translate/handlers.lua for the handler contract.
local L = require("translate.lexicon")
local PARTICLES = {}
for _, w in ipairs(L.name_particles) do PARTICLES[w] = true end
-- the ICAO codes of the airlines squawk knows (names.lua: "DTA", "LAM")
local AIRLINE_CODES = {}
for _, a in ipairs(require("translate.names").airlines) do AIRLINE_CODES[a[2]] = true end
-- lexicon.registration_marks as a set
local REGISTRATION_MARKS = {}
for mark in L.registration_marks:gmatch("%S+") do REGISTRATION_MARKS[mark] = true end
-- True when `raw` is a registration of five letters typed in lower case, opening with a nationality mark
local function lower_registration(raw)
  return raw:match("^%l%l%l%l%l$") ~= nil and REGISTRATION_MARKS[raw:sub(1, 2):upper()] == true
end

-- The earth's mean radius [NM] (6371 km)
local EARTH_NM = 6371000 / 1852
-- The point `nm` nautical miles from lat, lon [deg] on the true bearing `brg` [deg], along a great circle of
-- the sphere of radius EARTH_NM: lat, lon [deg]
local function great_circle_offset(lat, lon, brg, nm)
  local p1, d, t = math.rad(lat), nm / EARTH_NM, math.rad(brg)
  local p2 = math.asin(math.sin(p1) * math.cos(d) + math.cos(p1) * math.sin(d) * math.cos(t))
  local dl = math.atan(math.sin(t) * math.sin(d) * math.cos(p1), math.cos(d) - math.sin(p1) * math.sin(p2))
  return math.deg(p2), (lon + math.deg(dl) + 540) % 360 - 180
end

-- lexicon.self_correction.markers of one word, as a set (m:corrected_between)
local SC_MARKER_WORD = {}
for _, w in ipairs(L.self_correction.markers) do if not w:find(" ") then SC_MARKER_WORD[w] = true end end

return function(H, f, compass)
  local m = H.methods

  -- A latitude/longitude pair in qs: marked ones, else two bare numbers in a
  -- row after the instruction word ("at 0 0", "position 51.9, 4.4").
  -- (g: the grammar, which takes the minutes of a degrees-and-minutes position as read)
  local function position(qs, trig, g)
    local lat, lon
    for k, q in ipairs(qs) do
      -- degrees and decimal minutes, "52 20.5 N 004 30 E": whole degrees straight before the minutes
      local v, d = q.value, qs[k - 1]
      if (q.kind == "lat" or q.kind == "lon") and d and d.kind == "plain" and d.e == q.b and d.value >= 0
          and d.value == math.floor(d.value) and d.value <= (q.kind == "lat" and 90 or 180) and math.abs(v) < 60 then
        v = (v < 0 and -1 or 1) * (d.value + math.abs(v) / 60)
        g:take(q)
        g:take(d)
      end
      if q.kind == "lat" and not lat then lat = v end
      if q.kind == "lon" and not lon then lon = v end
    end
    if lat and lon then return lat, lon end
    for k = 1, #qs - 1 do
      local a, b = qs[k], qs[k + 1]
      -- (two bare numbers side by side or a mark between; "altitude 0 speed 0" is no position)
      if a.b >= trig and a.kind == "plain" and b.kind == "plain" and b.b - a.e <= 1
          and (b.b == a.e or not g.t[a.e].text:match("%a")) and math.abs(a.value) <= 90 and math.abs(b.value) <= 180 then
        return a.value, b.value
      end
    end
    return lat, lon
  end

  -- Asks which variant of a family flown in several common variants (lexicon.variant_families: "737") is
  -- meant, naming the designators of the family.
  -- (an Airbus family's digits begin with 3, "A330": A332, A333, A339; a Boeing's with 7. A family the type data
  -- holds one designator of is that one, no question: nil, then the designator)
  -- (lexicon.variant_designators: a family its digits do not spell, "A220": BCS1, BCS3)
  local function ask_variant(self, fam)
    local variants = {}
    local maker = fam:sub(1, 1) == "3" and "A" or "B"
    local spelled = L.variant_designators[fam]
    local pattern = spelled and spelled.pattern or "^" .. maker .. fam:sub(1, 2) .. "%w$"
    for _, d in ipairs(require("translate.names").designators) do
      if d:match(pattern) then variants[#variants + 1] = d end
    end
    if #variants == 1 then return nil, variants[1] end
    return self:need(string.format("Which variant of the %s is meant: %s?",
      spelled and spelled.name or maker == "A" and "A" .. fam or fam, table.concat(variants, ", ")))
  end

  function m:create(s)
    -- several aircraft in one request: each new id followed closely by a type starts one
    local starts, last = {}, nil
    for _, r in ipairs(self:refs_in(s.b, s.e, "aircraft")) do
      if not r.exists and (#self:refs_in(r.e, math.min(s.e, r.e + 4), "type") > 0 or #starts == 0) then
        starts[#starts + 1], last = r.b, r.e
      end
    end
    if #starts <= 1 then return self:create_one(s, s.b) end
    -- values said after "both", "all" or "each" at the end are every new aircraft's ("AAA1 A320 at 53 7
    -- heading 090 and BBB2 A320 at 52.7 7.5 heading 000, both FL300 at 280 kts"); an aircraft or a type
    -- named after it leaves unclear whose values follow: asked (after the last new callsign: "All Nippon 201"
    -- is one)
    local shared = self:find_word(last, s.e, "both all each")
    if shared < s.e and (self:has_ref(shared, s.e, "aircraft") or self:has_ref(shared, s.e, "type")) then
      return self:need(string.format("Which of the new aircraft do the values after '%s' belong to?", self.t[shared].raw))
    end
    for k, st in ipairs(starts) do
      local b = k == 1 and s.b or st
      self:create_one({ intent = s.intent, b = b, trig = b, e = starts[k + 1] or s.e, several = true,
                        shared = k < #starts and shared < s.e and { b = shared, e = s.e } or nil }, st)
      if self.ask then return end
    end
  end

  -- The callsign of the new aircraft `r` (an aircraft reference no aircraft has): said with the name
  -- of a brand several airlines fly under (names.lua's brands: "Virgin 1219" is VIR or VOZ, "LATAM 4411"
  -- TAM or LAN or ...), the prefix of the one of them flying now; with none or several flying, the name's
  -- own airline, asked about where the brand is `shared`.
  function m:brand_callsign(r)
    -- ("create SKY 88"): an airline's ICAO designator typed in capitals is that airline, though the word is also
    -- another airline's telephony (Skymark SKY, not Sky Airline SKU)
    local raw, digits = (self.t[r.b] or {}).raw or "", r.name:match("^%a+(%d%w*)$")
    if digits and raw:match("^%u%u%u$") and AIRLINE_CODES[raw] and r.name:upper():sub(1, 3) ~= raw then
      self:explain(r.b, r.e)
      return raw .. digits
    end
    local icao, _, codes = self:airline_at(r.b)
    if not codes or r.name:upper():sub(1, #icao) ~= icao then return r.name end
    local flying = {}
    for _, c in ipairs(codes) do
      if #self:airline_fleet(c) > 0 then flying[#flying + 1] = c end
    end
    if #flying == 1 then
      self:explain(r.b, r.e)
      return flying[1] .. r.name:sub(#icao + 1)
    end
    if not codes.shared then return r.name end
    self:need(string.format("Which airline is the new %s of: %s?", self:raw(r.b, r.e),
      table.concat(codes, " or ")))
    return r.name
  end

  -- A new aircraft's field said again after a correction word ("eastbound... no wait westbound", "heading 090,
  -- no wait 270", "FL360 correction FL370"): the one said before the correction is taken back (accounted for,
  -- never read). Returns `qs` less the values taken back (a bare number after a heading taken back is that
  -- heading) and the set of compass words taken back; nil and the words said when a correction stands between two
  -- fields of different kinds.
  function m:creation_taken_back(s, qs)
    local dropped, points = {}, {}
    local function point(i)
      local t = self.t[i]
      return t and t.kind == "word" and (t.text:match("^(%a+)bound$") or t.text:match("^(%a+)erly$")) ~= nil
    end
    local c = s.b + 1
    while c < s.e do
      -- (the correction: a correction word, or a run of self-correction words holding "no", "wait", "sorry" or
      -- "actually", which the reading of spoken corrections leaves as said before a word that is no value)
      local ce = c
      while ce < s.e and self:word(ce, "correction no wait sorry actually oh i mean make that") do ce = ce + 1 end
      if ce > c and self:word_in(c, ce, "correction no wait sorry actually") then
        local b, a = c - 1, ce
        while b > s.b and self.t[b].kind == "punct" do b = b - 1 end
        while a < s.e and (self.t[a].kind == "punct" or self.t[a].filler) do a = a + 1 end
        local before, after, read = point(b), point(a), false
        local from, to = b, a + 1  -- (the words quoted when asked: both fields and the correction)
        if before and after then
          points[b], read = true, true
          self:explain(b, ce)
        end
        for k, q in ipairs(qs) do
          before, after = before or q.e == b + 1, after or q.b == a
          if q.e == b + 1 then from = q.b end
          if q.b == a then to = q.e end
          local q2 = qs[k + 1]
          if q.e == b + 1 and q2 and q2.b == a and (q2.kind == q.kind or (q.kind == "heading" and q2.kind == "plain"
              and q2.value <= 360)) then
            dropped[q] = true
            local fixed = {}  -- (the correction's value, every field of it, read as q's kind)
            for key, v in pairs(q2) do fixed[key] = v end
            fixed.kind = q.kind
            qs[k + 1] = fixed
            self:explain(q.b, ce)
            read = true
          end
        end
        -- (between two fields of different kinds, "FL360 no wait 300 knots", what is taken back is not known)
        if before and after and not read then return nil, self:raw(from, to) end
      end
      c = math.max(c + 1, ce)
    end
    local out = {}
    for _, q in ipairs(qs) do if not dropped[q] then out[#out + 1] = q end end
    return out, points
  end

  -- True when the word at i, said after "callsign", "called", ..., is written as a new callsign: with digits
  -- ("SAS123", "n123ab"), in capitals ("SEABC"), a registration in lower case ("seabc"), or a capitalised word
  -- squawk does not know ("Rainbow"); a plain English word ("I don't know the callsign yet") is none (asked for).
  function m:callsign_written(i)
    local t = self.t[i]
    if not t or t.kind ~= "word" then return false end
    return t.raw:match("%d") ~= nil or t.raw:match("^%u[%u%-]+$") ~= nil or lower_registration(t.raw)
      or (t.raw:match("^%u") ~= nil and not self:known_word(i))
  end
  -- ("create DTA 110 Boeing 737-700 ...", "create LAM 1200, E190, ...", "a conflicting aircraft ANA 901, Boeing
  -- 777-200, ..."): a known airline's ICAO code written in capitals apart from its flight number (digits written,
  -- four at most), before the type in [s.b, s.e), is the new callsign (its tokens used and explained); a code squawk
  -- knows no airline by is none. Returns the callsign and the code's token, or nil.
  function m:code_apart_callsign(s)
    local first = self:refs_in(s.b, s.e, "type")[1]
    for k = s.b, (first and first.b or s.e) - 2 do
      local w, q = self.t[k], self:quantities(k + 1, k + 2)[1]
      if w.kind == "word" and AIRLINE_CODES[w.raw] and q and q.b == k + 1 and q.kind == "plain"
          and self.t[k + 1].raw:match("^%d%d?%d?%d?$") and not self:refs_in(k, k + 2, "aircraft")[1] then
        self:mark_used(k + 1, k + 2)
        self:explain(k, k + 2)
        return w.raw .. self.t[k + 1].raw, k
      end
    end
    -- ("Create a Rex Saab three forty, RXA two four one, at BOLTY", "callsign VOZ nine one two": the code in capitals
    -- and its flight number said digit by digit, set off by commas or after "callsign", anywhere in the request)
    for k = s.b, s.e - 2 do
      local w = self.t[k]
      local q = w.kind == "word" and AIRLINE_CODES[w.raw] and self:quantities(k + 1, math.min(s.e, k + 6))[1]
      local n = q and q.b == k + 1 and q.kind == "plain" and q.number
      local digits = n and not n.typed and not n.thousand and not n.hundred and n.digits:match("^%d%d?%d?%d?$")
      local apart = digits and (self:word(k - 1, "callsign") or (self.t[k - 1] and self.t[k - 1].text == ","
        and (not self.t[q.e] or self.t[q.e].text == ",")))
      if apart and #digits == q.e - q.b and not self:has_ref(k, q.e, "type") and not self:refs_in(k, q.e, "aircraft")[1] then
        self:mark_used(k + 1, q.e)
        self:explain(k, q.e)
        return w.raw .. digits, k
      end
    end
    return nil
  end
  -- The callsign of the one aircraft this request deletes before the creation s (one delete verb, then that
  -- aircraft, the only one named in the request), when the creation names it by "it" straight after its verb
  -- ("create it again", "recreate it", "re-create it"); else nil. Its values ("same type", "same heading, level and speed") are then that aircraft's (m:create_one).
  function m:recreated(s)
    local v = s.trig or s.b
    -- ("delete the Speedbird and then create BAW832 again at ...": the callsign of an aircraft this request deleted)
    local named = self:refs_in(v, s.e, "aircraft")[1]
    for _, c in ipairs(named and named.exists and self.out or {}) do
      if c == "DEL " .. named.name then return named.name end
    end
    if not (self:intent_at(v) and self:word(v + 1, "it")) then return nil end
    -- (the delete said before it: its verb, then the aircraft, the only one named in the request)
    local del
    for k = 1, v - 1 do
      if self:intent_at(k) == "delete" then
        if del then return nil end
        del = k
      end
    end
    local deleted
    for _, r in ipairs(self.refs) do
      if r.kind == "aircraft" then
        if deleted or not del or r.b < del or r.b > v then return nil end
        deleted = r.name
      end
    end
    return deleted and self:state(deleted) and deleted or nil
  end
  function m:create_one(s, id_from)
    local id
    -- ("create Alaska six eleven" with ASA331 flying: the airline heard whole and a flight number
    -- no aircraft has is the new aircraft's callsign, not a slip for ASA331; so is another airline's callsign
    -- matched to the one aircraft flying, G:airline_heard_whole)
    for _, r in ipairs(self:refs_in(id_from, s.e, "aircraft")) do
      local h = r.heard
      if r.exists and h and self:airline_heard_whole(h) and h.id:match("^%u%u%u?%d+%u*$") then
        -- (the rest of the flight number said straight after: "Frontier one | one five")
        -- ("Southwest thirty-one | oh five": "oh" is a zero)
        local oh = self:word(r.e, "oh o") and 1 or 0
        local q = self:quantities(r.e + oh, s.e)[1]
        local id = h.id
        local rest = q and q.b == r.e + oh and q.kind == "plain" and h.id:match("%d$") and q.number.digits
        -- ("Speedbird seven | seven two Kilo": the letters spelled after the flight number end the callsign)
        local e = rest and q.e
        if rest then
          rest = ("0"):rep(oh) .. rest
          while self.t[e] and self.t[e].kind == "word" and L.phonetic[self.words[e]] and #rest < 8 do
            rest, e = rest .. L.phonetic[self.words[e]], e + 1
          end
          id = h.id .. rest
        end
        if not self:state(id) and not self:airline_and_digits_match(id, r.name) then
          if rest then self:mark_used(q.b, e) end
          r.name, r.exists, r.heard, r.e = id, false, nil, rest and e or r.e
        end
      end
    end
    for _, r in ipairs(self:refs_in(id_from, s.e, "aircraft")) do
      if not r.exists then
        id = self:brand_callsign(r)
        -- ("a second Norstar, NSZ88"): a capitalised word squawk does not know, straight before the new
        -- callsign and opening with its first letter, is the airline's name for it (it changes nothing)
        local k = self.t[r.b - 1] and self.t[r.b - 1].kind == "punct" and self.t[r.b - 1].text == "," and r.b - 2 or r.b - 1
        -- ("an A319 operated as EZY12AB", "flying as RYR7PL": the verb that introduces the new callsign after its type)
        if self:word(k, "as") and self:word(k - 1, "operated operating flying") and not self.u:used(k - 1)
            and self:refs_in(math.max(1, k - 5), k - 1, "type")[1] then
          self:explain(k - 1, k + 1)
        end
        local w = self.t[k]
        if w and w.kind == "word" and w.alpha and #w.text >= 4 and w.raw:match("^%u%l") and not self:known_word(k)
            and not self.u:used(k) and w.raw:sub(1, 1) == id:sub(1, 1):upper() then
          self:explain(k, k + 1)
        end
        break
      end
    end
    local code_at  -- (the token of an airline's code written apart from its flight number: no place)
    if not id then
      local k = self:find_word(s.b, s.e, "@id_words")
      if k + 1 < s.e and self:callsign_written(k + 1) then
        id = self.t[k + 1].raw
        -- ("callsign ANA 55", "callsign ADO 27"): a known airline's ICAO code in capitals, then its flight number
        -- written apart (digits, four at most), is one callsign
        local n = self.t[k + 2]
        if AIRLINE_CODES[id] and k + 2 < s.e and n.kind == "number" and n.raw:match("^%d%d?%d?%d?$") then
          id, code_at = id .. n.raw, k + 1
          self:mark_used(k + 1, k + 3)
          self:explain(k + 1, k + 3)
        end
      end
    end
    if not id then
      id, code_at = self:code_apart_callsign(s)
    end
    -- ("delete Air Macau 872 and create it again at LATOP, ..., same type"): the aircraft deleted before it in
    -- this request, named by "it" (m:recreated)
    local recreated
    if not id then
      recreated = self:recreated(s)
      id = recreated
    end
    -- ("create BCS1 type B744 ..."): with the type named after "type", another designator written as one word
    -- (letters, then digits) is the new callsign; ("create a Cessna 172 D-EABC at ..."): a registration written
    -- in capitals (five letters, no word squawk knows) straight after or before the type is the callsign; so is one
    -- typed in lower case that opens with a nationality mark ("new c172 ooxyz ..."); a comma may set it off
    -- ("create a Cessna 172, HBKOF, at BERSU")
    local id_type
    if not id then
      local types = self:refs_in(s.b, s.e, "type")
      local declared
      for _, t in ipairs(types) do
        if self:word(t.b - 1, "type") then declared = declared or t end
      end
      for _, t in ipairs(declared and types or {}) do
        local raw = self.t[t.b].raw
        if t ~= declared and t.e == t.b + 1 and raw:match("^%u+%d+$") then
          id, id_type = raw, t
          break
        end
      end
      for _, t in ipairs((id or #types ~= 1) and {} or types) do
        local function comma(k) return self.t[k] and self.t[k].kind == "punct" and self.t[k].text == "," end
        for _, k in ipairs({ comma(t.e) and t.e + 1 or t.e, comma(t.b - 1) and t.b - 2 or t.b - 1 }) do
          local w = self.t[k]
          -- (a fix, navaid or airport of that name, the scene's or the navdata's: no callsign)
          local place = w ~= nil and self.world.place_known ~= nil and self.world.place_known(w.raw) ~= nil
          for _, r in ipairs(self:refs_in(k, k + 1, "waypoint")) do place = place or r.exists end
          if not id and w and w.kind == "word" and (w.raw:match("^%u%u%u%u%u$") or lower_registration(w.raw))
              and not self:known_word(k) and not place then
            id = w.raw:upper()
            self:explain(k, k + 1)
          end
        end
      end
    end
    -- ("put an ITA, ITY231 A320, ...", "a Qatar Airways, QTR7, ...", "create ITA Airways A321 callsign ITY123"): the
    -- new callsign's airline by its name
    for a = s.b, id and s.e - 1 or 0 do
      local icao, ae = self:airline_at(a)
      if icao and id:upper():sub(1, #icao) == icao and not self:has_ref(a, ae, "aircraft") then
        self:explain(a, ae)
      end
    end
    -- ("an intruder for VIR9: DLH9KW ...", "a head-on for ICE204: spawn ICE205 ..."): the aircraft flying
    -- that the new one is set up against is named as context
    for _, r in ipairs(self.refs) do
      if r.kind == "aircraft" and r.exists and self:word(r.b - 1, "for on against")
          and self:preceded_by(r.b - 1, 2, "@intruder @head_on") then
        self:explain(r.b, r.e)
      end
    end
    local types = self:refs_in(s.b, s.e, "type")
    for k, t in ipairs(types) do
      if t == id_type then table.remove(types, k) break end
    end
    local actype = types[1] and types[1].name
    -- ("a United triple seven, UAL9, B77W": a designator written as such is the variant meant, over a
    -- family said by its spoken name; two designators written keep the first)
    local written = {}
    for _, r in ipairs(types) do
      if r.e == r.b + 1 and self.t[r.b].raw:upper() == r.name then written[#written + 1] = r.name end
    end
    if #written == 1 then actype = written[1] end
    -- ("type 767-300ER", "a 777-200 ER": a model's name with a hyphen that names no designator the type data
    -- knows is asked, never written as a type: a designator has no hyphen)
    if actype and actype:find("-", 1, true) and not require("translate.types").known_designator(actype:upper()) then
      return self:need(string.format("Which aircraft type is '%s'? Please give its ICAO designator (B763, B77W, ...).",
        actype:upper()))
    end
    -- ("a Boeing 767", "a United 787"): a family flown in several common variants, said by its
    -- name alone, names no one variant (lexicon.variant_families); a variant said or written is that one (an Airbus
    -- family's digits only after "A" or "Airbus": "Saab 340" is no A340)
    -- ("B737 max", "Boeing 737 MAX"): a family's nickname (types.nicknames) said straight after the type, which the
    -- type read does not match, narrows it: B737 is the 737-700, "B737 max" one of the MAXes; the type is the
    -- nickname's, asked about below when several fit)
    local narrowed = false
    do
      local t = types[1]
      local w = t and self.t[t.e] and self.t[t.e].kind == "word" and self.t[t.e].text
      local pats = w and require("translate.types").nicknames[w]
      if pats and actype then
        local fits = false
        for _, p in ipairs(pats) do fits = fits or actype:upper():match(p) ~= nil end
        if not fits then actype, narrowed = nil, true end
      end
    end
    -- (the family's number said in words as typed: "a Delta seven six seven" is a 767)
    local said = not narrowed and #written == 0 and types[1]
      and self:raw(types[1].b, types[1].e):lower():gsub("%a+", L.digit_words):gsub("[%s%-]", "")
    for _, fam in ipairs(said and L.variant_families or {}) do
      local pre = said:sub(1, -#fam - 1)
      if said:sub(-#fam) == fam and not pre:match("%d$")
          and (fam:sub(1, 1) ~= "3" or pre == "" or pre:match("a$") or pre:match("airbus$")) then
        local _, one = ask_variant(self, fam)
        if not one then return end
        actype = one
      end
    end
    -- ("B738... sorry, A320": a type said again after a correction replaces the one before it)
    for k = 2, #types do
      if self:word_in(types[k - 1].e, types[k].b, "@correction") then actype = types[k].name end
    end
    -- ("create a Citation, EJA412, C56X"): a family's name said with a designator of that family describes it
    local nicknames = require("translate.types").nicknames
    for i = s.b, s.e - 1 do
      for _, p in ipairs(actype and self.t[i].kind == "word" and nicknames[self.t[i].text] or {}) do
        if actype:match(p) then self:explain(i, i + 1) end
      end
    end
    -- ("add a dreamliner ACA855 ...", "spawn a caravan ..."): a family's name said with no type is the one
    -- designator of that family, else asked about, naming them
    -- (a name of two words, "a King Air", read whole)
    local family, word
    for i = s.b, actype and s.b - 1 or s.e - 1 do
      local two = self.t[i + 1] and self.t[i].kind == "word" and self.t[i].text .. " " .. self.t[i + 1].text
      if not family and two and nicknames[two] then family, word = i, two end
      if not family and self.t[i].kind == "word" and nicknames[self.t[i].text] then family, word = i, self.t[i].text end
    end
    if family then
      local found = {}
      for _, d in ipairs(require("translate.names").designators) do
        for _, p in ipairs(nicknames[word]) do
          if d:match(p) then found[#found + 1] = d break end
        end
      end
      if #found > 1 and L.nickname_defaults[word] then found = { L.nickname_defaults[word] } end
      if #found > 1 then
        return self:need(string.format("Which type of %s is meant: %s?", word, table.concat(found, ", ")))
      end
      if #found == 1 then
        actype = found[1]
        self:explain(family, family + select(2, word:gsub("%S+", "")))
      end
    end
    local model, near
    for _, r in ipairs(self:refs_in(s.b, s.e, "aircraft")) do
      if r.exists then near = near or r.name end
      if r.exists and self:word_in(s.b, s.e, "same") then model = self:state(r.name) end
    end
    if recreated and self:word_in(s.b, s.e, "same") then model = self:state(recreated) end
    -- ("create AC006 same as AC005 but at 51.7 4.8 hdg 270", "identical to AC003", "a copy of KLM12 at ..."): a
    -- whole copy of an aircraft flying, its type, level, speed and heading where the request says none
    local copied
    for _, r in ipairs(self:refs_in(s.b, s.e, "aircraft")) do
      if r.exists and ((self:word(r.b - 1, "as") and self:word(r.b - 2, "same"))
          or (self:word(r.b - 1, "to") and self:word(r.b - 2, "identical"))
          or (self:word(r.b - 1, "of") and self:word(r.b - 2, "copy clone twin duplicate"))) then
        copied = self:state(r.name)
        model = copied
        self:explain(r.b - 2, r.b)
      end
    end
    if not actype and model and (copied or self:word_in(s.b, s.e, "type")) then actype = model.type end
    local qs = self:quantities(s.b, s.e)
    for _, q in ipairs(s.shared and self:quantities(s.shared.b, s.shared.e) or {}) do qs[#qs + 1] = q end
    local back_qs, points_back = self:creation_taken_back(s, qs)
    if not back_qs then
      return self:need(string.format("Which value of the new aircraft does the correction in '%s' take back? "
        .. "Please say its values again.", points_back))
    end
    qs = back_qs
    -- (values after the type count too: "KLM602 A320, 52.4 6.4, 270 deg, ..." has its instruction word later)
    local lat, lon = position(qs, (types[1] and types[1].e < s.trig and types[1].b > s.b) and types[1].e or s.trig, self)
    local along  -- the aircraft the new one is placed ahead of or behind
    if not lat or not lon then
      -- "10 miles north of KL204", "20 miles east of it" (the aircraft named before), "20 nm ahead of KLM12"
      local la, lo, ref = self:offset_position(qs, s.b, s.e, near)
      if la then lat, lon, along = la, lo, ref elseif lo then return self:need(lo) end
    end
    local hdg, alt, fl, spd, mach, level_q  -- (level_q: the flight level said, its quantity)
    -- placed along an aircraft's track: its course, level and speed said against that aircraft's
    -- ("head-on", "opposite direction", "coming the other way", "same track"; "1000 ft above"; "30 kt faster")
    if along then
      local a = self:state(along)
      model = a
      for i = s.b, s.e - 1 do
        local head_on = self:word(i, "head") and self:word(i + 1, "on")
        local reversed = head_on or self:word(i, "@course_reversed") and (self.t[i].text == "head-on"
          or self:word(i + 1, "@course_nouns") or self:word(i, "reciprocal"))
        if reversed and not hdg then
          hdg = (a.hdg_deg + 180) % 360
          self:explain(i, (head_on or self:word(i + 1, "@course_nouns")) and i + 2 or i + 1)
        elseif self:word(i, "same") and self:word(i + 1, "@course_nouns") and not hdg then
          hdg = a.hdg_deg
          self:explain(i, i + 2)
        end
      end
      for _, q in ipairs(qs) do
        if q.kind == "alt" and not q.fl and not alt and self:word(q.e, "@above @below") then
          alt, fl = a.alt_ft + (self:word(q.e, "@below") and -1 or 1) * self:take(q).value, true
          self:explain(q.e, q.e + 1)
        elseif q.kind == "speed" and not spd and not mach and self:word(q.e, "@faster @slower") then
          spd = a.cas_kt + (self:word(q.e, "@slower") and -1 or 1) * self:take(q).value
          self:explain(q.e, q.e + 1)
        end
      end
    end
    -- "1000 feet lower than KLM880", "2000 ft above the Airbus": a height said against another aircraft flying is
    -- counted from that aircraft's level (feet); a comparative ("lower", "higher than") or "the" and an airline or
    -- type after it with no aircraft flying named straight after is asked ("3000 metres over ARTIP" is a place's)
    for _, q in ipairs(alt and {} or qs) do
      if q.kind == "alt" and not q.fl and not self.taken[q.b] and self:word(q.e, "@level_below @level_above") then
        local than = self:word(q.e + 1, "than")
        local k = than and q.e + 2 or q.e + 1
        if self:word(k, "that") and self:word(k + 1, "of") then k = k + 2 end
        local r = self:refs_in(k, k + 2, "aircraft")[1]
        r = r and (r.b == k or (r.b == k + 1 and self:word(k, "the"))) and r
        local a = r and self:state(r.name)
        -- (an aircraft described, "the Airbus", "the Lufthansa", names no level of its own here: asked)
        local described = self:word(k, "the") and (self:airline_at(k + 1) or self:type_said(k + 1))
        if not a and (r or than or described or self:word(q.e, "lower higher")) then
          return self:need(string.format("What level should %s have? I heard '%s' and no aircraft flying to count it "
            .. "from; please give the level.", id, self:raw(q.b, q.e + 1)))
        end
        if not a then break end
        alt, fl = a.alt_ft + (self:word(q.e, "@level_below") and -1 or 1) * self:take(q).value, true
        self:explain(q.e, r.e)
        break
      end
    end
    -- "heading to seven zero", "speed to to fifty knots": two spoken digits or a tens word straight after a "to"
    -- (lexicon.two_heard) as the heading, or after two as a speed under 100 kt for a type of no light class, have
    -- their "two" in that "to" (270, 250), as the HDG and SPD handlers read them; "heading to one zero" (210 or
    -- 100?) is asked
    for _, q in ipairs(qs) do
      local n = q.number
      if n and not n.typed and #(n.digits or "") == 2 and self:word(q.b - 1, "@two_heard") then
        local after = self.t[q.b - 2] and self.t[q.b - 2].text
        if q.kind == "heading" or (q.kind == "plain" and (after == "heading" or after == "hdg")) then
          if q.value * 10 <= 360 then
            return self:need(string.format("What heading should %s have: %d or %03d? I heard '%s'.",
              (id or "it"):upper(), 200 + q.value, q.value * 10, self:raw(q.b - 1, q.e)))
          end
          q.value = 200 + q.value
        elseif (q.kind == "speed" or self:word(q.b - 3, "speed spd")) and self:word(q.b - 2, "@two_heard") and q.value < 100
            and q.value % 10 == 0 and actype and not require("translate.types").slow_class(actype) then
          q.value = 200 + q.value
        end
      end
    end
    for _, q in ipairs(qs) do
      if q.kind == "heading" and not hdg then hdg = q.value end
      -- "flying 300 deg": an angle with no turn is the heading
      if q.kind == "angle" and q.turn == 0 and not hdg and q.value >= 0 and q.value <= 360 then hdg = q.value end
      if q.kind == "alt" and not alt then
        alt, fl, level_q = q.value, q.fl, q.fl and q or nil
        -- a level in metres, "height 5100 metres", "level 8900 metres" (China's metric level named "level"):
        -- converted to feet, the nearest 100 ft, as a clearance in metres is
        local metres_after = q.fl and q.value >= 1000 and q.value <= 18000 and self:word(q.e, "@metres")
        if metres_after or (not q.fl and self:word(q.e - 1, "@metres")) then
          if metres_after then self:mark_used(q.b, q.e + 1) end
          alt = math.floor((metres_after and q.value / 0.3048 or q.value) / 100 + 0.5) * 100
          fl, level_q = false, nil
        end
      end
      if q.kind == "speed" and not spd and not mach then spd = q.value end
      if q.kind == "mach" and not spd and not mach then mach = q.value end
    end
    -- values said after their noun with no unit: "hdg 180, alt 10000, spd 250"
    for _, q in ipairs(qs) do
      if q.kind == "plain" and q.b > 1 then
        local w = self.t[q.b - 1]
        if w.kind == "word" then
          if not alt and (w.text == "alt" or w.text == "altitude") then alt = q.value end
          -- ("spd .85", "speed point eight two": a decimal fraction below one, a Mach number's form, is the Mach)
          if not spd and not mach and (w.text == "spd" or w.text == "speed") then
            if q.number and q.number.decimal and q.value >= 0.3 and q.value < 1 then mach = q.value else spd = q.value end
          end
          -- ("facing 250": a newcomer's word for the heading)
          if not hdg and (w.text == "hdg" or w.text == "heading" or w.text == "facing") then hdg = q.value end
          -- ("southbound 170": a number straight after a compass point's "-bound" or "-erly" word, within 90
          -- degrees of it, is the heading it describes)
          local c = L.compass[w.text:match("^(%a+)bound$") or w.text:match("^(%a+)erly$") or ""]
          if not hdg and c and q.value <= 360 and math.abs((c - q.value + 180) % 360 - 180) < 90 then
            hdg = q.value
          end
        end
      end
    end
    if not hdg then
      local h = self:find_word(s.b, s.e, "heading hdg facing pointing")  -- ("facing west")
      if self:word(h + 1, "due") then h = h + 1 end  -- ("heading due east")
      if h + 1 < s.e and compass(self.t[h + 1].text) then
        hdg = compass(self.t[h + 1].text, h + 2 < s.e and self.t[h + 2].text or "", h + 3 < s.e and self.t[h + 3].text or "")
      end
    end
    -- "westbound", "on a northerly heading", "flying south": a compass point as the heading (not "10 nm
    -- north of ...", a position; not "northwards", a way to lean that names no heading); with a heading
    -- said, one within 90 degrees of it describes it ("an eastbound, ... heading 080")
    -- (after a verb of going, the point of one to three words: "going north-east" is 045, not north)
    for i = s.b, s.e - 1 do
      local t = self.t[i]
      local point = t.kind == "word" and (t.text:match("^(%a+)bound$") or t.text:match("^(%a+)erly$"))
      local c, e = point and L.compass[point], i + 1
      if not point and t.kind == "word" and self:word(i - 1, "@compass_verbs") then c, e = self:point_said(i) end
      c = c and e and not self:word(e, "of") and not points_back[i] and c
      if c and (not hdg or math.abs((c - hdg + 180) % 360 - 180) < 90) then
        hdg = hdg or c
        self:explain(i, e)
      end
    end
    -- "the same heading, level and speed as KL204", "same FL as WZZ1234"
    if model and (copied or self:word_in(s.b, s.e, "altitude level fl")) and not alt then
      alt, fl = math.floor((model.alt_ft or 0) + 0.5), true  -- (the simulation's feet, to the foot)
    end
    if model and (copied or self:word_in(s.b, s.e, "heading hdg")) and not hdg then hdg = model.hdg_deg end
    if model and (copied or self:word_in(s.b, s.e, "speed")) and not spd and not mach then
      if model.sel_mach then mach = model.sel_mach else spd = model.cas_kt end
    end
    -- "TEST01 ... at FL300 and 280 knots, and TEST02 ..., same level and speed": the values of the aircraft
    -- created before it in this request
    local before = not model and self.created_values
    if before and self:word_in(s.b, s.e, "same") then
      if self:word_in(s.b, s.e, "altitude level fl") and not alt then alt, fl = before.alt, before.fl end
      if self:word_in(s.b, s.e, "speed") and not spd and not mach then spd, mach = before.spd, before.mach end
    end
    -- a position by name: a fix or navaid said as its name ("over LOPIK"), an airport by its name ("at Schiphol");
    -- "the same position as VIR3": that aircraft's (CRE takes an aircraft's id as its position)
    local named_at = (not lat or not lon) and model and self:word_in(s.b, s.e, "position location") and model.id or nil
    if (not lat or not lon) and not named_at then
      -- ("at Zurich... no, sorry, at Munich": the place said after the correction)
      local from = s.b
      for i = s.trig, s.e - 1 do
        if self:word(i, "@correction sorry") then from = i end
      end
      -- ("at JFK": the airport by its VOR's code, nearest the traffic, else anywhere: KJFK)
      -- ("set up LOWW arrival: AUA211 A320 at MASUR": the place said after "at", "over", ... first)
      local places = self:refs_in(from, s.e, "waypoint")
      table.sort(places, function(x, y)
        local px, py = self:word(x.b - 1, "@place_words"), self:word(y.b - 1, "@place_words")
        if px ~= py then return px end
        return x.b < y.b
      end)
      for _, r in ipairs(places) do
        local near = self.fleet[1] or { lat = 0, lon = 0 }
        -- (a navaid's kind said after its name, "over Sparta VOR", is no place of its own)
        if not self:word(r.b, "@navaid_kinds") and r.b ~= code_at then
          -- ("over Cedar Creek": the navaid the words name together, not the fix CREEK)
          local whole
          if named_at == nil then whole = self:whole_place_name(r, from, s.e, nil) end
          if whole == false then return end
          if named_at == nil and not whole then
            named_at = (self:word(r.b - 1, "at") and self:airport_meant(r.name, near)) or r.name
            -- (a code a navaid bears that, after one letter, names an airport standing off it, farther than
            -- lexicon.on_airport_nm, is two places: "at LAX" is asked, "at LAX airport" is the airport; a navaid
            -- on its airport, "at JFK", is one place, the airport)
            if named_at ~= r.name and not self:word(r.e, "@airport_nouns") and self:off_airport(r.name, named_at, near) then
              return self:need(string.format("Which place is meant: the %s navaid or the %s airport?",
                r.name:upper(), named_at))
            end
            -- (said as its name, "over Lambourne", or typed as the ident, "over LAM")
            named_at = self:creation_place(named_at, self.t[r.b].raw:upper() ~= r.name:upper() and self:raw(r.b, r.e))
            if not named_at then return end
          end
          named_at = named_at or whole
        end
      end
      if not named_at then
        -- ("at Kennedy": the airport beside the navaid of that name, as "at JFK" is KJFK)
        local was = {}
        for k in pairs(self.explained or {}) do was[k] = true end
        named_at = self:place_by_name(math.max(from, s.trig) + 1, s.e)
        for k = math.max(from, s.trig) + 1, s.e - 1 do
          if named_at and (self.explained or {})[k] and not was[k] then
            local a = self.fleet[1] or { lat = 0, lon = 0 }
            if self:word(k - 1, "at") then named_at = self:airport_meant(named_at, a) end
            -- ("at Marseille": a navaid said by its name that stands on a large airport is that airport; the
            -- navaid of that ident nearest each aircraft flying, or with none flying the one the simulator
            -- takes where it bears the name, stands on the same one, "at Clacton" is the VOR on a small
            -- airfield)
            local beside, class, on = self.world.airports_beside, self.world.airport_class, nil
            local e = k
            while (self.explained or {})[e] and not was[e] and e < s.e do e = e + 1 end
            -- ("at Kastrup VOR": the navaid, its kind said; "at Santiago airport": the name less "airport")
            local at_place = self:word(k - 1, "at") and not self:word(e, "@navaid_kinds")
            if e - 1 > k and self:word(e - 1, "@airport_nouns") then e = e - 1 end
            local phrase = self:raw(k, e)
            if beside and class and self:word(k - 1, "at") and not named_at:match("^%a%a%a%a$") then
              local at = self.fleet
              if #at == 0 and at_place and self.world.locate and self.world.navaids_named then
                local lat, lon = self.world.locate(named_at, table.concat(self.out, " ; "))
                at = {}
                for _, id in ipairs(lat and self.world.navaids_named(phrase, lat, lon, L.on_airport_nm) or {}) do
                  if id:upper() == named_at:upper() then at = { { lat = lat, lon = lon } } end
                end
              end
              for _, b in ipairs(at) do
                local ids = b.lat and beside(named_at, b.lat, b.lon, L.on_airport_nm) or {}
                on = (#ids == 1 and class(ids[1]) == "LARGE" and (on == nil or on == ids[1])) and ids[1] or false
              end
            end
            if on then named_at = on end
            named_at = self:creation_place(named_at, phrase, at_place)
            if not named_at then return end
            break
          end
        end
      end
      -- ("create ... over mike juliet victor heading 240": two to five letters spelled in the phonetic alphabet
      -- after a place word, "at" or "over", are the ident of the fix, navaid or airport of those letters that the
      -- navdata holds within lexicon.navaid_range_nm of an aircraft flying; a spelling is exact, no sound-alike)
      for i = math.max(from, s.trig) + 1, named_at and 0 or s.e - 1 do
        if self:word(i - 1, "@place_words") then
          local letters, k = "", i
          while k < s.e and not self.u:used(k) and self.t[k].kind == "word" and L.phonetic[self.t[k].text] do
            letters, k = letters .. L.phonetic[self.t[k].text], k + 1
          end
          local fits = #letters >= 2 and #letters <= 5 and not L.phonetic[self.words[k] or ""]
            and self:spelled_place_near(letters)
          if fits then
            named_at = self:creation_place(letters)
            if not named_at then return end
            self:explain(i, k)
            break
          end
        end
      end
    end
    -- ("cre KLM1234 b738 sugol hdg 90 ...": a name typed in CRE's place of the position, straight after the
    -- type, is that waypoint; the command's check asks when navdata has none of that name)
    local typed = types[1] and types[1].e
    if (not lat or not lon) and not named_at and typed and typed < s.e then
      local t = self.t[typed]
      if t.kind == "word" and t.alpha and #t.text >= 3 and #t.text <= 5 and not t.keyword and not t.filler
          and not t.number_word and not L.phonetic[t.text] and not self.u:used(typed) and #self:refs_in(typed, typed + 1) == 0 then
        named_at = self:creation_place(t.text:upper())
        if not named_at then return end
        self:explain(typed, typed + 1)
      end
    end
    -- "on the ground", "on ground", "ready for departure" (or take-off): altitude 0 ft and speed 0 kt; with a
    -- level or speed said as well, asked ("in the ground", "in ground": a Spanish speaker's "en tierra", the same)
    for i = s.trig, s.e - 1 do
      local g = self:word(i + 1, "the") and i + 2 or i + 1
      if not (self:word(i, "on") or (self:word(i, "in") and self:word(g, "ground"))) then g = nil end
      if self:word(i, "ready") and self:word(i + 1, "for") then
        g = self:word(i + 2, "take") and self:word(i + 3, "off") and i + 3 or i + 2
        if not self:word(g, "departure takeoff take-off off") then g = nil end
      end
      if g and self:word(g, "ground departure takeoff take-off off") then
        if alt or spd or mach then
          return self:need(string.format("Should %s be on the ground (altitude 0, speed 0) or at the level and speed said?",
            id and id:upper() or "the new aircraft"))
        end
        alt, spd, fl = 0, 0, false
        self:explain(i, g + 1)
        break
      end
    end
    -- values left unread: one after the level with no speed said is the speed (CRE's
    -- order: heading, altitude, speed: "fl300 290"); others are asked about
    -- (each value read accounts for one value said: "hdg 270 FL350 270" leaves the second 270 to read as the
    -- speed; with the speed said, a value said again is a repeat, "runway heading 240 so 240")
    local read, used = { lat, lon, hdg, alt, spd, mach }, {}
    local left = {}
    local from = s.e  -- values before the callsign or type count aircraft ("create two aircraft: ...")
    for _, r in ipairs(self.refs) do
      if (r.kind == "aircraft" or r.kind == "type") and r.b >= s.b and r.b < from then from = r.b end
    end
    for _, q in ipairs(qs) do
      if q.b < from or self:in_reason(q.b) then goto continue end  -- (nor "one" in a remark: "- the long-haul one")
      local seen = self.taken[q.b] ~= nil  -- (read already: an offset's distance)
      local again = false
      for k = 1, 6 do  -- (read has holes: a position by name leaves lat and lon nil)
        local v = read[k]
        if not seen and v and math.abs(v - q.value) < 1e-9 then
          if used[k] then again = true else seen, used[k] = true, true end
        end
      end
      seen = seen or (again and (spd or mach) ~= nil)
      -- ("United 455, seven three niner, B739": the designator's digits said just before it)
      for _, r in ipairs(types) do
        seen = seen or (r.name == actype and q.kind == "plain" and self:skip_fillers(q.e) == r.b
          and q.value == tonumber(actype:match("^%a+(%d+)%a?$")))
      end
      if not seen and (q.kind == "plain" or q.kind == "dist") then left[#left + 1] = q end
      ::continue::
    end
    -- the three said bare in CRE's order, an altitude in feet between ("cre EZY9TT A319 51 45N 000 30W 180 9000 240")
    if #left == 3 and not (hdg or alt or spd or mach) and left[1].kind == "plain" and left[2].kind == "plain"
        and left[3].kind == "plain" and left[1].value >= 0 and left[1].value <= 360 and left[2].value >= 1000
        and left[2].value <= 60000 and left[3].value >= 40 and left[3].value <= 700 then
      hdg, alt, spd = left[1].value, left[2].value, left[3].value
      left = {}
    end
    -- with no altitude said, the one bare number of whole hundreds from 1000 to 60000 (no heading, no
    -- speed) is the altitude ("at 43.55 -79.2, 6000, heading 260, 210 knots")
    if not alt then
      local at
      for k, q in ipairs(left) do
        if q.kind == "plain" and q.value >= 1000 and q.value <= 60000 and q.value % 100 == 0 then
          at = not at and k or -1
        end
      end
      if at and at > 0 then alt = table.remove(left, at).value end
    end
    -- ("over KEA, heading three four zero, one hundred twenty, two hundred ten knots": with the heading and speed
    -- said, the one number left, said group-wise in words, is the flight level)
    if not alt and hdg and (spd or mach) and #left == 1 and self:groupwise_level(left[1]) then
      alt, fl = self:groupwise_level(table.remove(left, 1)), true
    end
    -- CRE's order for values said bare: heading, altitude, speed ("52.15 4.25 45 fl310 290")
    if #left >= 1 and left[1].kind == "plain" and not hdg and alt and left[1].value >= 0 and left[1].value <= 360
        and (#left == 2 or spd or mach) then
      hdg = table.remove(left, 1).value
    end
    if #left == 1 and left[1].kind == "plain" and alt and not spd and not mach and left[1].value >= 40
        and left[1].value <= 700 then
      spd = left[1].value
      left = {}
    end
    -- a typed ".85" after the level, no speed said, is a Mach number ("fl390 .85")
    if #left == 1 and left[1].kind == "plain" and alt and not spd and not mach
        and self.t[left[1].b].raw:match("^%.%d%d?$") and left[1].value >= 0.4 then
      mach = left[1].value
      left = {}
    end
    if #left > 0 and id and actype then
      return self:need(string.format("To create %s I did not place '%s'. What does it give: a position, heading, "
        .. "altitude or speed?", id, self:raw(left[1].b, left[1].e)))
    end
    local missing = {}
    if not id then missing[#missing + 1] = "callsign" end
    if not actype then missing[#missing + 1] = "aircraft type" end
    if (not lat or not lon) and not named_at then missing[#missing + 1] = "position" end
    if #missing > 0 then
      return self:need("To create the aircraft I need its " .. table.concat(missing, ", ") .. ". What should they be?")
    end
    -- a callsign already flying: CRE would replace that aircraft, so ask (one deleted first in this request
    -- is gone by then)
    if self:state(id) and not recreated then
      return self:need(string.format("%s already exists. Should I move it, or create a new aircraft under "
        .. "another callsign?", id:upper()))
    end
    -- (an aircraft created again with no level or speed said, "same type" alone, would stand at 0 ft and 0 kt:
    -- asked)
    if recreated and not alt and not spd and not mach then
      return self:need(string.format("At what level and speed should %s be created again?", id:upper()))
    end
    local doubt = level_q and alt == level_q.value and self:level_doubt(level_q, alt, id:upper())
    if doubt then return self:need(doubt) end
    -- (a heading's digits run on into the next value with no unit: "heading two seven zero two five zero")
    if hdg and hdg > 360 then
      return self:need(string.format("What heading should %s have? I heard %s.", id:upper(), f.int(hdg)))
    end
    -- a value said but not read would be left as 0: ask instead
    if (spd or mach or alt) and not hdg then
      return self:need("What heading should " .. id .. " have?")
    end
    if ((spd or mach) or s.several) and not alt then return self:need("What altitude should " .. id .. " have?") end
    -- (at a fix, a navaid or a user waypoint standing off every airport, with neither altitude nor speed said, CRE
    -- would put the aircraft there on the ground, 0 ft and 0 kt: asked; at an airport, or typed as a latitude and
    -- longitude, that is the creation)
    if not alt and not spd and not mach and named_at and self:off_airports(named_at) then
      return self:need(string.format("What altitude and speed should %s have at %s? With none said it would stand "
        .. "there at 0 ft and 0 kt.", id:upper(), named_at:upper()))
    end
    -- "create ... FL100 250 knots, going to climb": a climb or descent said after the level with no level
    -- of its own is an instruction the creation cannot carry (its level is then the state at creation): ask
    for i = s.trig + 1, s.e - 1 do
      if self:word(i, "climb climbs descend descends") and self:intent_at(i) == "alt" then
        local after = false
        for _, q in ipairs(qs) do after = after or (q.b > i and q.kind == "alt") end
        if not after then
          return self:need(string.format("Should %s %s after it is created? Please give the level.", id:upper(),
            self.t[i].text:gsub("s$", "")))
        end
      end
    end
    -- (airborne under lexicon.min_airborne_kt, or a known jet, a type of no light class, under 100 kt: "a 747 at
    -- FL350, speed 60")
    local ty = require("translate.types")
    local jet = ty.known_designator(actype:upper()) and not ty.slow_class(actype)
    if spd and (spd < L.min_airborne_kt or (jet and spd < 100)) and alt and alt > 0 then
      return self:need(string.format("%s would fly at %s kt: which speed should it have?", id:upper(), f.int(spd)))
    end
    -- (the speed's field named with no speed read, "... 14000 feet speed", "velocity fast": asked, never left out)
    if not spd and not mach then
      for i = s.trig + 1, s.e - 1 do
        if self:word(i, "speed spd airspeed") and not self:in_reason(i) and not self.noted[i] then
          return self:need(string.format("What speed should %s have?", id:upper()))
        end
      end
    end
    id = id:upper()
    local cmd = "CRE " .. id .. " " .. actype .. " " .. (named_at or (f.num(lat) .. " " .. f.num(lon)))
    if hdg or alt or spd or mach then cmd = cmd .. " " .. f.num(hdg or 0) end
    if alt or spd or mach then cmd = cmd .. " " .. f.alt(alt, fl) end
    if spd then cmd = cmd .. " " .. f.int(spd) end
    if mach then cmd = cmd .. " " .. f.mach(mach) end
    self:emit(cmd)
    self.subject = id
    self.created = self.created or {}
    self.created[id] = true
    self.created_values = { alt = alt, fl = fl, spd = spd, mach = mach }
    -- (where it is created: the place its destination is looked for from)
    local clat, clon = lat, lon
    if named_at and self.world.user_waypoint_at then clat, clon = self.world.user_waypoint_at(named_at) end
    self.created_at = self.created_at or {}
    self.created_at[id] = clat and clon and { lat = clat, lon = clon } or nil
  end

  -- CRECONFS acid,type,targetid,dpsi,cpa,tlosh,[dh,tlosv]: an intruder of a new callsign and a type,
  -- set up against the aircraft flying: its track off the target's ("90 deg off its track", "crossing
  -- from 60 degrees", "head-on": 180), the distance at closest approach ("cpa 0", "passing 1 mile",
  -- "zero miss distance") and the time to loss of separation ("los in 200 s"); "1000 ft above it
  -- with vertical LoS at 180 s" adds dh and tlosv. Each is asked for when not said.
  -- (with its unit, or a bare number after "speed": "..., speed 260")
  local function first_speed(self, s)
    for _, q in ipairs(self:quantities(s.b, s.e)) do
      if (q.kind == "speed" or (q.kind == "plain" and self:word(q.b - 1, "speed spd"))) and not self.taken[q.b] then
        return q
      end
    end
    return nil
  end

  function m:conflict_intruder(s)
    local id, target, target_e, other
    for _, r in ipairs(self:refs_in(s.b, s.e, "aircraft")) do
      if r.exists then
        if target and r.name ~= target then other = other or r.name end
        target, target_e = target or r.name, target_e or r.e
      else
        id = id or self:brand_callsign(r):upper()
      end
    end
    local named = self:find_word(s.b, s.e, "@named")
    if not id and named + 1 < s.e and self.t[named + 1].kind == "word" then id = self.t[named + 1].raw:upper() end
    id = id or self:code_apart_callsign(s)
    local actype = (self:refs_in(s.b, s.e, "type")[1] or {}).name
    if not id or not actype then return self:need("What callsign and aircraft type should the intruder have?") end
    -- ("intruder on the Speedbird, I2, A320": the one aircraft of the airline said, the new one named after it)
    for i = s.b, s.e - 1 do
      local icao, e, codes = self:airline_at(i)
      local fits = not target and icao and self:word(i - 1, "the") and self:airline_fleet(icao, codes) or {}
      if #fits == 1 then
        target, target_e = fits[1], e
        self:explain(i, e)
      end
    end
    if not target then return self:need("Which aircraft should " .. id .. " conflict with?") end
    -- (two aircraft flying named: CRECONFS sets the intruder against one target, which is not said)
    if other then
      return self:need(string.format("Which aircraft should %s conflict with: %s or %s?", id, target, other))
    end
    local dpsi, cpa, tlosh, dh, tlosv
    -- ("crecons INT6 A320 KLM1234 270 1 180": the command's name typed, its values bare after the target
    -- in the command's order, nothing else)
    local bare, at = {}, target_e
    for _, q in ipairs(self:word(s.trig, "creconfs") and self:quantities(target_e, s.e) or {}) do
      if q.kind ~= "plain" or q.b ~= at then bare = {} break end
      bare[#bare + 1], at = q, q.e
    end
    if #bare >= 3 and at == s.e then
      dpsi, cpa, tlosh = self:take(bare[1]).value, self:take(bare[2]).value, self:take(bare[3]).value
      dh, tlosv = bare[4] and self:take(bare[4]).value, bare[5] and self:take(bare[5]).value
    end
    for k = s.b, s.e - 1 do
      if self:word(k, "@head_on") and (self.t[k].text ~= "head" or self:word(k + 1, "on")) then dpsi = 180 end
    end
    -- "from the left" crosses at +dpsi, "from its right" at -dpsi (360 - dpsi), "from the right at ninety"
    -- says it as a bare number; the side said alone is a crossing at 90 degrees
    local from = self:find_word(s.b, s.e, "from")
    local side = from < s.e and (self:word(from + 1, "@left @right") and from + 1
      or self:word(from + 1, "the its his her their") and self:word(from + 2, "@left @right") and from + 2)
    local vertical = self:find_word(s.b, s.e, "vertical")
    local times = {}  -- the times said: one alone, with no vertical part, is the time to loss of separation
    for _, q in ipairs(self:quantities(s.b, s.e)) do
      local near = function(words) return self:word_in(math.max(s.b, q.b - 2), math.min(s.e, q.e + 3), words) end
      if q.kind == "time" then times[#times + 1] = q end
      -- (a bare number beside the closest approach's word is its distance: "cpa 0", "1 mile cpa")
      -- ("a closest point of approach of zero", "a CPA of 0": the number after the word and "of")
      local beside = self:word(q.b - 1, "@closest_approach distance") or self:word(q.e, "@closest_approach")
        or (self:word(q.b - 1, "of") and self:word(q.b - 2, "@closest_approach"))
      -- ("dpsi 180", "conflict angle 45": a bare number after CRECONFS's argument name or "angle"; "relative
      -- heading 45 degrees": the heading relative to the target's)
      local angle = q.kind == "angle" or (side and q.kind == "plain" and q.b == side + 2 and self:word(side + 1, "at"))
        or (q.kind == "plain" and self:word(q.b - 1, "dpsi angle"))
        or ((q.kind == "heading" or q.kind == "plain") and self:word_in(math.max(s.b, q.b - 2), q.b, "relative"))
      if q.kind == "plain" and q.value == 1 and self.t[q.b].number_word and self:word(q.e, "intruder @aircraft_nouns") then
        self:take(q)  -- ("create one intruder INT02": the one aircraft made)
      elseif angle and not dpsi then
        dpsi = self:take(q).value
      elseif q.value == dpsi and (angle or (q.kind == "plain"
          and not self:word(q.b - 1, "@loss_of_separation @closest_approach"))) then
        -- ("head-on, 180 degrees", "head-on (180)": the same angle said twice)
        self:take(q)
      elseif (q.kind == "dist" and not cpa and near("@closest_approach"))
          or (q.kind == "plain" and not cpa and beside) then
        cpa = self:take(q).value
      -- ("vertical loss at 150 s", "90 s to vertical LoS": the time after the vertical part's word or before it)
      elseif q.kind == "time" and dh and not tlosv
          and (q.b > vertical or self:word_in(q.e, math.min(s.e, q.e + 3), "vertical")) then
        tlosv = self:take(q).value
      elseif not tlosh and ((q.kind == "time" and near("@loss_of_separation separation"))
          or (q.kind == "plain" and self:word(q.b - 1, "@loss_of_separation"))) then  -- ("tlos 300")
        tlosh = self:take(q).value
      elseif q.kind == "alt" and not dh and self:word(q.e, "@above @below") then
        dh = (self:word(q.e, "@below") and -1 or 1) * self:take(q).value
      elseif (q.kind == "plain" or q.kind == "alt") and not dh and self:word(q.b - 1, "dh") then  -- ("dh 1000")
        dh = self:take(q).value
      elseif (q.kind == "plain" or q.kind == "time") and dh and not tlosv and self:word(q.b - 1, "tlosv") then
        tlosv = self:take(q).value
      end
    end
    if side and dpsi ~= 180 then
      dpsi = dpsi or 90
      if self:word(side, "@right") then dpsi = (360 - dpsi) % 360 end
    end
    if not dpsi then
      return self:need("At what angle, in degrees, should " .. id .. " cross the track of " .. target .. "?")
    end
    if not cpa then return self:need("How close, in nautical miles, should " .. id .. " pass " .. target .. "?") end
    -- (one time said before the vertical part, no word of loss beside it: "1 mile CPA, 400 seconds, 1000
    -- feet below with vertical loss at 300 s")
    local before = {}
    for _, q in ipairs(times) do if q.b < vertical and not self.taken[q.b] then before[#before + 1] = q end end
    if not tlosh and #before == 1 and (dh or #times == 1) then tlosh = self:take(before[1]).value end
    if not tlosh then
      return self:need("In how many seconds should " .. id .. " lose separation with " .. target .. "?")
    end
    local cmd = string.format("CRECONFS %s %s %s %s %s %s", id, actype, target, f.num(dpsi), f.num(cpa), f.num(tlosh))
    if dh then cmd = cmd .. " " .. f.num(dh) .. (tlosv and " " .. f.num(tlosv) or "") end
    -- its speed, after the vertical part ("..., vertical loss at 300 s, 280 knots")
    local spd = dh and tlosv and (bare[6] or first_speed(self, s))
    if spd then cmd = cmd .. " " .. f.num(self:take(spd).value) end
    -- a value said in the description and read as none of the arguments is asked about, never dropped
    for _, q in ipairs(self:quantities(s.b, s.e)) do
      -- ("new one TVF88AB": "one" after "new" or "another" stands for the intruder, no value)
      local pronoun = q.kind == "plain" and q.e == q.b + 1 and self:word(q.b, "one") and self:word(q.b - 1, "new another")
      if not self.taken[q.b] and not pronoun then
        return self:need(string.format("I have %s. What does '%s' mean?", cmd, self:raw(q.b, q.e)))
      end
    end
    self:emit(cmd)
    self:mark_used(s.b, s.e)  -- the description read whole ("zero miss distance", "LoS after 4 minutes")
    self.created = self.created or {}
    self.created[id] = true
  end

  -- "swap the levels of KLM12 and TRA6021" (headings, speeds): each of the two aircraft named flies the
  -- other's present level, heading or speed (lexicon.swapped), after a yes (two aircraft swapping levels
  -- climb and descend through each other's); anything else is asked
  function m:swap(s)
    local refs = {}
    for _, r in ipairs(self:refs_in(s.b, s.e, "aircraft")) do
      if r.exists then refs[#refs + 1] = r end
    end
    local k = self:find_word(s.trig, s.e, "@swapped")
    if #refs ~= 2 or k >= s.e or refs[1].name == refs[2].name then
      return self:need("Which two aircraft should swap their levels, headings or speeds?")
    end
    local cmd = L.swapped[self.t[k].text]
    local a, b = refs[1].name:upper(), refs[2].name:upper()
    self:confirm_before(string.format("Swap the %ss of %s and %s? (yes or no)", (self.t[k].text:gsub("s$", "")), a, b))
    for _, pair in ipairs({ { a, self:state(b) }, { b, self:state(a) } }) do
      local id, o = pair[1], pair[2]
      if cmd == "ALT" then
        local ft = math.floor((o.alt_ft or 0) + 0.5)
        self:emit("ALT " .. id .. " " .. (ft >= 10000 and f.alt(ft, true) or f.int(ft)))
      elseif cmd == "HDG" then
        self:emit("HDG " .. id .. " " .. f.num(math.floor((o.hdg_deg or 0) + 0.5) % 360))
      else
        self:emit("SPD " .. id .. " " .. (o.sel_mach and f.mach(o.sel_mach) or f.int(o.cas_kt or 0)))
      end
    end
    self:mark_used(s.b, s.e)
  end

  -- A position said as a distance and a compass point from an aircraft ("10 nm north", "20 miles
  -- south of where it is now", "15 nm south of RYR81JC", "20 miles east of it"), or along a named
  -- aircraft's track ("20 nm ahead of KLM12", "dead behind KL001 at 15 nm": the bearing its heading, or
  -- the reverse): lat, lon [deg] along a great circle from the aircraft, with the quantity taken, and for a
  -- place along a track that aircraft's id; nil when no compass point or side follows the distance.
  -- `from`: the aircraft meant when none is named after "of" (the one moved; "it"). Returns nil, question when the aircraft's position is unknown.
  function m:offset_position(qs, b, e, from)
    for _, q in ipairs(qs) do
      -- ("behind KL001 at 15 nm": the side and the aircraft before the distance)
      local r
      for _, x in ipairs(q.kind == "dist" and q.b >= b and q.e <= e and self:word(q.b - 1, "at")
          and self:refs_in(b, q.b - 1, "aircraft") or {}) do
        if x.exists and x.e == q.b - 1 then r = x end
      end
      if r and L.along_track[(self.t[r.b - 1] or {}).text] then
        local a = self:state(r.name)
        self:take(q)
        self:explain(self:word(r.b - 2, "dead right straight directly") and r.b - 2 or r.b - 1, r.e)
        local la, lo = great_circle_offset(a.lat, a.lon, a.hdg_deg + L.along_track[self.t[r.b - 1].text], q.value)
        return la, lo, r.name
      end
      local k = q.e
      if self:word(k, "to") and self:word(k + 1, "the") then k = k + 2 end
      local front = self:word(k, "in") and self:word(k + 1, "front")  -- ("20 nm in front of KLM12")
      if front then k = k + 1 end
      local t = self.t[k]
      local side = q.kind == "dist" and q.b >= b and q.e <= e and t and t.kind == "word" and L.along_track[t.text]
      -- ("ahead of the ownship KL001")
      local at = self:word(k + 1, "of") and k + 2 or k + 1
      while self.t[at] and (self.t[at].filler or self:word(at, "@ownship")) do at = at + 1 end
      r = side and self:refs_in(at, at + 1, "aircraft")[1]
      if r and r.exists then
        local a = self:state(r.name)
        self:take(q)
        self:explain(front and k - 1 or k, r.e)
        if self:word(k - 1, "dead right straight directly") then self:explain(k - 1, k) end
        local la, lo = great_circle_offset(a.lat, a.lon, a.hdg_deg + side, q.value)
        return la, lo, r.name
      end
      -- ("30 nm due north": "due" before the compass point)
      if q.kind == "dist" and self:word(k, "due") and self.t[k + 1] and L.compass[self.t[k + 1].text] then
        self:explain(k, k + 1)
        k, t = k + 1, self.t[k + 1]
      end
      -- ("10 nm further north": on from where the aircraft is)
      local further = self:word(k, "further farther") and not self:word(k + 2, "of") and self.t[k + 1]
      further = further and further.kind == "word" and L.compass[further.text] and further
      if further then k, t = k + 1, further end
      local brg = q.kind == "dist" and q.b >= b and q.e <= e and t and t.kind == "word" and L.compass[t.text]
      if brg then
        if further then self:explain(k - 1, k) end
        local ref = from
        if self:word(k + 1, "of") then
          -- ("of the Lufthansa one", "of the KLM Embraer": the aircraft after "the")
          local at = self:word(k + 2, "the") and k + 3 or k + 2
          local r = self:refs_in(at, at + 1, "aircraft")[1]
          if r then
            ref = r.name
            self.explained = self.explained or {}
            self.explained[r.b] = true  -- the reference, not an aircraft instructed
          elseif not self:word(k + 2, "it where its") then
            return nil
          end
        end
        local a = ref and self:state(ref)
        if not a or not a.lat then return nil, "Where is " .. (ref or "the reference aircraft") .. "?" end
        self:take(q)
        self.explained = self.explained or {}
        self.explained[k] = true
        return great_circle_offset(a.lat, a.lon, brg, q.value)
      end
    end
    return nil
  end

  function m:move(s)
    local id = self:acid(s, "move")
    if not id then return end
    local qs = self:quantities(s.b, s.e)
    local lat, lon = position(qs, s.trig, self)
    if not lat or not lon then
      local la, lo = self:offset_position(qs, s.trig, s.e, id)
      if la then lat, lon = la, lo elseif lo then return self:need(lo) end
    end
    local named_at
    if not lat or not lon then
      -- ("move AAL2307 to Cedar Creek": the navaid the words name together, not the fix CREEK)
      -- ("move JOR1421 to the Floresti VOR FLR": the ident, not the navaid's kind)
      for _, r in ipairs(self:refs_in(s.trig, s.e, "waypoint")) do
        local whole
        if named_at == nil and not self:navaid_kind_said(r) then whole = self:whole_place_name(r, s.trig, s.e, id) end
        if whole == false then return end
        if not self:navaid_kind_said(r) then named_at = named_at or whole or r.name end
      end
      named_at = named_at or self:place_by_name(s.trig + 1, s.e, self:state(id))
      -- ("move Shamrock 3GK to Boyne": a word written as a proper name straight after "to", closing the clause or
      -- before "at", that the navdata holds as a fix within lexicon.navaid_range_nm of the aircraft, is that fix;
      -- so is a fix's ident typed in capitals or said in lower case, no English word, before "at" or the level
      -- moved to: "move Pasco 205 to TAVPI at five thousand", "move arik 104 to erami flight level 150")
      local to, here = self:find_word(s.trig + 1, s.e, "to"), self:state(id)
      local t, known = self.t[to + 1], self.world.place_known
      local lv = self:word(to + 2, "at") and to + 3 or to + 2  -- (the level after "at" too: "to SPY at FL150")
      local level_next = lv < s.e and self:quantities(lv, s.e)[1]
      level_next = level_next and level_next.b == lv and level_next.kind == "alt"
      -- ("move klm18t to spy fl150": a navaid's ident of three letters too, when no airport's IATA code)
      local ident = to + 1 < s.e and t.kind == "word" and (t.raw:match("^%u%u%u%u%u$")
        or (t.raw:match("^%l%l%l%l%l$") and not self:known_word(to + 1))
        or (t.raw:lower():match("^%a%a%a$") and (t.raw:match("^%u%u%u$") or t.raw:match("^%l%l%l$"))
          and not self:known_word(to + 1) and not self:iata_airport_at(to + 1) and level_next))
      if not named_at and to + 1 < s.e and t.kind == "word" and (t.raw:match("^%u%l+$") or ident) and not t.keyword
          and not self.u:used(to + 1) and known and here and here.lat
          and (to + 2 >= s.e or self.t[to + 2].kind == "punct" or self:word(to + 2, "at") or (ident and level_next)) then
        local lat, lon = known(t.raw:upper())
        local dlat, dlon = lat and lat - here.lat, lat and (lon - here.lon) * math.cos(math.rad(lat))
        if lat and 60 * math.sqrt(dlat * dlat + dlon * dlon) <= L.navaid_range_nm then
          named_at = t.raw:upper()
          self:explain(to + 1, to + 2)
        end
      end
      -- ("move klm12 to eham", "move BEL3KN to EBBR at FL100": an airport's ICAO code, four letters in one case and no
      -- English word, straight after "to" and closing the clause (or before "at" or the level) is MOVE's position)
      local code = not named_at and to + 1 < s.e and t.kind == "word" and not t.keyword and not self.u:used(to + 1)
        and (t.raw:match("^%u%u%u%u$") or (t.raw:match("^%l%l%l%l$") and not self:known_word(to + 1)))
        and t.raw:upper()
      if code and self.world.airport_class and (self.world.airport_class(code) or "") ~= "" and not self:state(code)
          and (to + 2 >= s.e or self.t[to + 2].kind == "punct" or self:word(to + 2, "at") or level_next) then
        named_at = code
        self:explain(to + 1, to + 2)
      end
      -- ("move the Easy until over the VOR BCN": "until" for "to", a Spanish or Portuguese speaker's "hasta" /
      -- "até", before the place moved to with no value after it)
      local u = named_at and self:find_word(s.trig + 1, s.e, "until till")
      if u and u < s.e and #self:quantities(u, s.e) == 0 and #self:refs_in(u + 1, s.e, "waypoint") > 0 then
        self:explain(u, u + 1)
      end
    end
    -- ("move the Ryanair to FL360, same position": where it is now, with the values said)
    local same = self:find_word(s.b, s.e, "same")
    local here = self:state(id)
    if (not lat or not lon) and not named_at and same < s.e and self:word(same + 1, "position place spot location")
        and not self:word(same + 2, "as") and here and here.lat then
      lat, lon = here.lat, here.lon
      self:explain(same, same + 2)
    end
    -- ("move Cathay 138 to flight level 340": a level straight after "to", no place said, moves it up or down where
    -- it is)
    local level = qs[1] and qs[1].kind == "alt" and (qs[1].fl or self:word(qs[1].e - 1, "@feet")) and qs[1]
    if (not lat or not lon) and not named_at and level and self:word(level.b - 1, "to")
        and #self:refs_in(s.trig + 1, s.e, "waypoint") == 0 and here and here.lat then
      -- ("Ethiopian 809 move to FL150": the aircraft addressed before the verb, as a controller speaks, may be told
      -- to climb or descend; which is meant is asked)
      if #self:refs_in(1, s.trig, "aircraft") > 0 then
        return self:need(string.format("Should %s climb or descend to %s, or be moved there at once (MOVE)?", id,
          self:raw(level.b, level.e)))
      end
      lat, lon = here.lat, here.lon
    end
    if (not lat or not lon) and not named_at then
      return self:need("Where should " .. id .. " go? Please give a latitude and longitude.")
    end
    for _, q in ipairs(qs) do
      if named_at and q.kind == "dist" then  -- "twenty miles north of Schiphol": an offset squawk does not place
        return self:need(string.format("Where exactly should %s go? I cannot place '%s' from %s: please give a "
          .. "latitude and longitude.", id, f.num(q.value) .. " NM", named_at))
      end
    end
    local opt, by = {}, nil
    for _, q in ipairs(qs) do
      -- ("2000 feet higher than the others, so FL320": a difference said of a level is none; with no level said
      -- beside it, asked)
      by = by or (q.kind == "alt" and self:word(q.e, "higher lower") and q)
      if q.kind == "alt" and not opt[1] and q ~= by then opt[1] = f.alt(q.value, q.fl) end
      if q.kind == "heading" and not opt[2] then opt[2] = f.num(q.value) end
      if q.kind == "speed" and not opt[3] then opt[3] = f.int(q.value) end
      if q.kind == "mach" and not opt[3] then opt[3] = f.mach(q.value) end
      if q.kind == "vs" and not opt[4] then opt[4] = f.int(q.value) end
    end
    -- ("facing north", "pointing south-west", "heading due east", "flying west"): a compass point after a word of
    -- facing or going is MOVE's heading [deg]
    for i = s.trig + 1, opt[2] and 0 or s.e - 1 do
      local deg, e = self:point_said(i)
      local v = self:word(i - 1, "due") and i - 2 or i - 1
      if deg and not self.u:used(i) and not self:word(e, "of") and self:word(v, "heading hdg facing pointing @compass_verbs") then
        opt[2] = f.num(deg == 0 and 360 or deg)
        self:explain(v, e)
        break
      end
    end
    if by and not opt[1] then
      return self:need(string.format("Which level should %s be moved to? '%s' is a difference, not a level.", id,
        self:raw(by.b, by.e + 1)))
    end
    -- a bare number left after the position is the altitude when it reads as one (whole hundreds of feet,
    -- "and keep it at 3500"); the last value, after the level and heading with no speed said, is the speed
    -- (MOVE's order, as CRE's: "to 52.3 5.3, FL200, heading 270, 250"); any other is asked, never dropped
    for k, q in ipairs(qs) do
      local read = self.taken[q.b] ~= nil or (lat and math.abs(q.value - lat) < 1e-9)
        or (lon and math.abs(q.value - lon) < 1e-9)
      if q.kind == "plain" and q.b > s.trig and not read and not self:in_reason(q.b) then
        local now = self:state(id)
        if opt[1] and opt[2] and not opt[3] and k == #qs and q.value >= 40 and q.value <= 700 then
          opt[3] = f.int(q.value)
        elseif not opt[1] and self:groupwise_level(q) and now and (now.alt_ft or 0) >= L.groupwise_from_ft then
          -- ("reposition OAL84 at 40.60 north 23.20 east, one hundred": a level said group-wise in words, for an
          -- aircraft flying flight levels)
          opt[1] = f.alt(self:groupwise_level(q), true)
        elseif opt[1] or q.value < 1000 or q.value > 60000 or q.value % 100 ~= 0 then
          return self:need(string.format("To move %s I did not place '%s'. Is it an altitude, heading or speed?",
            id, self:raw(q.b, q.e)))
        else
          opt[1] = f.int(q.value)
        end
      end
    end
    local last = 0
    for k = 1, 4 do if opt[k] then last = k end end
    local cmd = "MOVE " .. id .. " " .. (named_at or (f.num(lat) .. " " .. f.num(lon)))
    local now = self:state(id)
    for k = 1, last do
      if opt[k] then
        cmd = cmd .. " " .. opt[k]
      else
        -- a gap before a later value: keep the current state there
        if not now then return self:need("Which altitude, heading and speed should " .. id .. " have?") end
        local cur = { now.alt_ft or 0, now.hdg_deg or 0, now.cas_kt or 0, 0 }
        cmd = cmd .. " " .. f.int(cur[k])
      end
    end
    self:emit(cmd)
  end

  function m:remove(s)
    -- "delete waypoint X of AC1" removes a waypoint, never the aircraft (a noun inside a callsign typed apart, "remove
    -- Easy 41WP" lexed "easy 41 wp", is no noun)
    for k = s.b, s.e - 1 do
      if self:word(k, "@waypoint_nouns @route_nouns") and not self:in_callsign(k) then return self:delete_waypoint(s) end
    end
    -- "skip APDAK, take out that point", "remove the point", "skip APDAK, remove it": words pointing back at a place
    -- never delete an aircraft. "point" is the one waypoint named before the verb (DELWPT) or asked; "it" straight
    -- after the verb with a waypoint named before is asked, the waypoint and the aircraft both named
    local before = self:refs_in(1, s.trig, "waypoint")
    local it = self:find_word(s.trig + 1, math.min(s.e, s.trig + 3), "it") < math.min(s.e, s.trig + 3)
    -- ("once SAS902 passes TEB, delete it", "after EKBIL delete it": a waypoint said as the one the aircraft passes
    -- is behind it then; "it" is the aircraft, which the condition's reading deletes there)
    local passed = #before == 1 and self:word(before[1].b - 1, "passes passed passing reaches reached reaching past over "
      .. "crosses crossed overflies overflying after")
    if self:word_in(s.trig + 1, s.e, "point points") or (it and #before > 0 and not passed) then
      local id = self:acid(s, "lose the waypoint")
      if not id then return end
      if #before ~= 1 or it then
        local wp = #before == 1 and before[1].name or "the waypoint"
        return self:need(string.format("Should I remove %s from the route of %s, or delete the aircraft %s?", wp, id, id))
      end
      self:explain(s.trig, s.e)
      return self:emit("DELWPT " .. id .. " " .. before[1].name)
    end
    -- ("delete the wind", "remove all winds", "clear the wind": the wind field, DEL WIND; the wind named beside an
    -- aircraft, "delete KLM12 and the wind", is asked, never an aircraft deleted for it)
    local wind = self:find_word(s.b, s.e, "wind winds")
    if wind < s.e then
      if #self:refs_in(s.b, s.e, "aircraft") > 0 then
        return self:need("Should I delete the aircraft or clear the wind field? Please say them apart.")
      end
      local k = wind - 1
      while k > s.trig and self:word(k, "the all") do k = k - 1 end
      if k == s.trig and (not self.t[wind + 1] or self.t[wind + 1].kind == "punct" or self:word(wind + 1, "field please")) then
        self:explain(s.trig, wind + 1)
        if self:word(wind + 1, "field") then self:explain(wind + 1, wind + 2) end
        return self:emit("DEL WIND")
      end
      return self:need("Should I clear the wind field? Please say \"delete the wind\".")
    end
    local ids = {}
    -- ("we don't need it after all", "X shouldn't be in this exercise at all": "after all" or "at all" ending its
    -- clause is the idiom, no aircraft counted)
    local all = false
    for k = s.b, s.e - 1 do
      local idiom = self:word(k - 1, "after at") and (not self.t[k + 1] or self.t[k + 1].kind == "punct")
      -- (nor "all" opening an airline's name: "delete the All Nippon")
      all = all or (self:word(k, "@all") and not idiom and not self:airline_at(k))
    end
    if all then
      for _, a in ipairs(self.fleet) do ids[#ids + 1] = a.id end
      if #ids == 0 then return self:need("There are no aircraft. Which aircraft should I delete?") end
    else
      ids = self:acids(s)
    end
    if #ids == 0 then return self:need("Which aircraft should I delete? Please give its callsign.") end
    for _, id in ipairs(ids) do self:emit("DEL " .. id) end
  end

  -- True when `heard` is `name` or `name` with one letter more anywhere ("toebix": "tobix").
  local function spelled_within_one(heard, name)
    if heard == name then return true end
    if #heard ~= #name + 1 then return false end
    for k = 1, #heard do
      if heard:sub(1, k - 1) .. heard:sub(k + 1) == name then return true end
    end
    return false
  end

  -- True when `heard` is `name` with two neighbouring letters swapped ("rokli": "rokil"), a typing slip
  -- that may as well name another fix.
  local function swapped_letters(heard, name)
    if #heard ~= #name or heard == name then return false end
    local k = 1
    while heard:byte(k) == name:byte(k) do k = k + 1 end
    return heard:sub(k, k + 1) == name:sub(k + 1, k + 1) .. name:sub(k, k) and heard:sub(k + 2) == name:sub(k + 2)
  end

  -- A waypoint named in [b, e): a known name, an upper-case name, or a
  -- spoken name matched against the world's waypoints and the route; `flown`: the place a direct-to flies to.
  function m:waypoint(b, e, id, flown)
    -- (a navaid's kind typed in capitals is no place: "direct to the Sydney VOR"; nor, with `flown`, is one passed
    -- over, "direct to Pampus, skipping SUGOL")
    for _, r in ipairs(self:refs_in(b, e, "waypoint")) do
      if not (r.e == r.b + 1 and self:word(r.b, "@navaid_kinds"))
          and not (flown and self:preceded_by(r.b, 2, "@passed_over")) then
        local whole = self:whole_place_name(r, b, e, id)
        if whole ~= nil then return whole or nil end
        -- ("direct victor mike romeo then NYLON": a place spelled in the phonetic alphabet before the one named is
        -- never passed over for it; which is meant is asked)
        for k = b, r.b - 2 do
          if not self.u:used(k) and self.t[k].kind == "word" and L.phonetic[self.t[k].text]
              and self.t[k + 1].kind == "word" and L.phonetic[self.t[k + 1].text] then
            local j = k
            while j < r.b and self.t[j].kind == "word" and L.phonetic[self.t[j].text] do j = j + 1 end
            return self:need(string.format("Which waypoint do you mean: the one spelled '%s', or %s? Please say the "
              .. "places in the order to fly them.", self:raw(k, j), r.name))
          end
        end
        -- (a navaid's name in capitals, "direct TEBBY", is its ident already: m:navaid_name_refs)
        return r.name
      end
    end
    local names, seen = {}, {}
    for _, n in ipairs(self.world.waypoints) do names[#names + 1], seen[n] = n, true end
    local a = self:state(id)
    for _, r in ipairs(a and a.route or {}) do
      if not seen[r] then names[#names + 1], seen[r] = r, true end
    end
    -- a navaid said by its name, which its ident abbreviates ("Biggin" -> BIG, "Detling" -> DET); not a name said
    -- before an airport's noun ("Lagos airport" is DNMM, never LAG), nor one the navdata gives navaids of other
    -- idents too near the aircraft ("Lagos": LAG, LOS), read by m:place_by_name below
    local named = self.world.navaids_named
    for i = b, math.min(e, #self.t + 1) - 1 do
      local t = self.t[i]
      if not self.u:used(i) and t.kind == "word" and t.alpha and not t.keyword and #t.text >= 4 then
        local fits = {}
        for _, n in ipairs(names) do
          if #n >= 3 and #n < #t.text and n:match("^%a+$") and t.text:sub(1, #n) == n:lower() then fits[#fits + 1] = n end
        end
        if #fits == 1 and (self:word(i + 1, "@airport_nouns") or named and a and a.lat
            and #named(t.text, a.lat, a.lon, L.navaid_range_nm) > 1) then
          fits = {}
        end
        if #fits == 1 then
          self:explain(i, i + 1)
          return fits[1]
        end
      end
    end
    -- a name spelled in the phonetic alphabet ("direct sierra papa yankee" -> SPY) is exactly a known
    -- one, else asked about (a letter's word is never read alone as a place: "lima")
    for i = b, math.min(e, #self.t + 1) - 1 do
      local letters, k = "", i
      while k < e and not self.u:used(k) and self.t[k].kind == "word" and L.phonetic[self.t[k].text] do
        letters, k = letters .. L.phonetic[self.t[k].text], k + 1
      end
      -- (or the ident of a fix, navaid or airport the navdata holds within lexicon.navaid_range_nm of the aircraft:
      -- "add mike november alpha" near Minna is the MNA VOR; a spelling is exact, no sound-alike)
      local near = #letters >= 2 and not seen[letters] and a and a.lat and self.world.locate
      local plat, plon = nil, nil
      if near then plat, plon = near(letters, nil, a.lat, a.lon) end
      if plat then
        local dlat, dlon = plat - a.lat, ((plon - a.lon + 180) % 360 - 180) * math.cos(math.rad(a.lat))
        if 60 * math.sqrt(dlat * dlat + dlon * dlon) <= L.navaid_range_nm then seen[letters] = true end
      end
      if #letters >= 2 and seen[letters] then
        self:explain(i, k)
        return letters
      end
      if #letters >= 2 then
        return self:need(string.format("Which waypoint is %s? I heard '%s', which names no waypoint I know.",
          letters, self:raw(i, k)))
      end
    end
    local best, best_score, best_word, best_span, best_known
    local slot_first = b
    while slot_first < e and self.t[slot_first] and (self.t[slot_first].kind == "punct" or self.t[slot_first].filler
        or self:word(slot_first, "to the direct via towards toward proceed fly go")) do
      slot_first = slot_first + 1
    end
    for i = b, math.min(e, #self.t + 1) - 1 do
      local t = self.t[i]
      if not self.u:used(i) and t.kind == "word" and not t.number_word and #t.text >= 2
          and (not t.keyword or (t.text == "direct" and not (self.t[i + 1] and self.t[i + 1].kind == "word")))
          and not t.filler and not L.pronouns[t.text] then
        -- (a name speech recognition split into syllables, "direct as bin" -> ASBIN, "toe bix" -> TOBIX:
        -- the two words together, when they spell the name, or the name and one silent letter more, are
        -- kept before one word alone that sounds as well)
        local cands, nx = { { t.text, 1 } }, self.t[i + 1]
        if i + 1 < e and nx.kind == "word" then table.insert(cands, 1, { t.text .. nx.text, 2 }) end
        for _, c in ipairs(cands) do
          local idx, score = squawk.translate.best_match(c[1], names)
          if idx and c[2] == 2 and not spelled_within_one(c[1], names[idx]:lower()) then idx = nil end
          if idx and (not best or score > best_score
              or (score == best_score and c[2] == 2 and best_span[2] == best_span[1] + 1)) then
            best, best_score, best_word, best_span = names[idx], score, c[1], { i, i + c[2] }
            -- ("skip APDAK, take it out of the route" with AVAVA on the route: an English word squawk knows, "of",
            -- "out", "take", is never taken for a name it only sounds like; confirmed, cycle 65)
            -- (a known word where the name is said, first in the slot, "direct alpine" for ALPNE, stays heard)
            best_known = c[2] == 1 and self:known_word(i) and (i ~= slot_first or #t.text <= 2)
          end
        end
      end
    end
    -- ("direct Olno": the name of the navaid LNO near the aircraft, said exactly, before a waypoint of its
    -- route that only sounds like it, HELEN; the place that name means, as m:place_by_name reads it)
    local asked = self.ask
    local navaid = best and best_word ~= best:lower() and self:navaid_by_name(b, e, a)
    self.ask = asked
    if navaid then return self:place_by_name(b, e, a) or navaid end
    -- (a typed name with two letters swapped is confirmed below, never taken as sounding the same)
    if best and best_score >= L.waypoint_confirm and not swapped_letters(best_word, best:lower())
        and not (best_known and best_word ~= best:lower()) then
      self:explain_place(best_span[1], best_span[2])
      return best
    end
    local place = self:place_by_name(b, e, a)
    if place then return place end
    place = self:routed_navaid_by_airport_word(b, e, a) or self:heard_on_routes(b, e, seen)
    if place then return place end
    -- a name that sounds like a known one is confirmed, never substituted,
    -- unless it is the only name it could be
    if best and best_score >= 0.5 and not (self.world.confirmed or {})[best] then
      self.confirm = self.confirm or { id = best, heard = best_word }
      self:need(string.format("Did you mean %s? I heard '%s'.", best, best_word))
    end
    if best and best_score >= 0.5 then
      self:explain(best_span[1], best_span[2])
      return best
    end
    return nil
  end

  -- The one navaid of the route of the aircraft `a` that stands beside (lexicon.city_navaid_nm) an airport whose name
  -- holds a word said in [b, e) ("direct rockford": RFD, "CHICAGO/ROCKFORD", beside KRFD "CHICAGO ROCKFORD INTL"),
  -- or nil: none, or two of its route.
  function m:routed_navaid_by_airport_word(b, e, a)
    local w = self.world
    if not (a and a.lat and w.airports_with_words and w.airports_beside) then return nil end
    for i = b, math.min(e, #self.t + 1) - 1 do
      local t = self.t[i]
      if not self.u:used(i) and t.kind == "word" and t.alpha and not t.keyword and not t.filler and #t.text >= 4 then
        local bears, found = {}, nil
        for _, id in ipairs(w.airports_with_words(t.text, a.lat, a.lon, L.navaid_range_nm)) do bears[id] = true end
        for _, r in ipairs(next(bears) and a.route or {}) do
          for _, id in ipairs(w.airports_beside(r, a.lat, a.lon, L.city_navaid_nm)) do
            if bears[id] then
              if found and found ~= r then return nil end
              found = r
            end
          end
        end
        if found then
          self:explain_place(i, i + 1)
          return found
        end
      end
    end
    return nil
  end

  -- The waypoint of the routes flown, none of the set `known` (the names m:waypoint matched already), that a
  -- lower-case word said in [b, e) sounds like as closely as a direct-to's name is taken, when it sounds like no
  -- other of them and names no navaid or airport (G.sure_route_name, G.heard_nowhere_else: "direct watson" for
  -- WATSN on another aircraft's route), or nil.
  function m:heard_on_routes(b, e, known)
    local routed, seen = {}, {}
    for _, a in ipairs(self.world.aircraft) do
      for _, r in ipairs(a.route or {}) do
        if not seen[r:upper()] then routed[#routed + 1], seen[r:upper()] = r:upper(), true end
      end
    end
    for i = b, math.min(e, #self.t + 1) - 1 do
      local t = self.t[i]
      if not self.u:used(i) and t.kind == "word" and not t.keyword and not t.filler and t.raw:match("^%l+$") then
        local name = #routed > 0 and self.sure_route_name(t.text, routed)
        if name and not known[name] and self.heard_nowhere_else(t.text, name, self.world) then
          self:explain_place(i, i + 1)
          return name
        end
      end
    end
    return nil
  end

  -- A waypoint ref `r` said as one word of a longer name in [b, e) ("direct Cedar Creek" with a fix CREEK
  -- known): the navaid the words around it name together ("Cedar Creek" is the CQY VORTAC), else, with
  -- a capitalised word beside the name that is no word squawk knows, false after asking which place
  -- is meant; nil when the ref is the whole name.
  function m:whole_place_name(r, b, e, id)
    if r.e ~= r.b + 1 or self.t[r.b].raw == r.name then return nil end  -- (typed as its ident: "HONIE")
    local a, named = id and self:state(id), self.world.navaids_named
    local function word(k) return k >= b and k < e and self.t[k] and self.t[k].kind == "word" and self.t[k].alpha end
    for _, k in ipairs({ r.b - 1, r.e }) do
      local lo = math.min(k, r.b)
      for _, near in ipairs(named and word(k) and (a and { a } or self.fleet) or {}) do
        local ids = near.lat and named(self.t[lo].text .. " " .. self.t[lo + 1].text, near.lat, near.lon, L.navaid_range_nm) or {}
        local navaid = self:one_named(ids, "navaid", self:raw(lo, lo + 2), math.huge)
        if navaid then
          self:explain(lo, lo + 2)
          return navaid
        end
      end
    end
    local function proper(k)
      local t = self.t[k]
      return k >= b and k < e and t and t.kind == "word" and t.alpha and not t.keyword and not t.filler
        and t.raw:match("^%u%l+$") ~= nil and not self:has_ref(k, k + 1, "aircraft")
    end
    for _, k in ipairs({ r.b - 1, r.e }) do
      if proper(k) then
        local said = self:raw(math.min(k, r.b), math.max(k, r.b) + 1)
        self:need(string.format("Which place is '%s'? It is no navaid I know, and %s is only part of it.", said, r.name))
        return false
      end
    end
    return nil
  end

  -- The place `ids` (the idents `phrase` names) stand for: the one ident, or with 2..most of
  -- them the first, asking which `kind` ("navaid", "airport") was meant; nil for none or too many.
  -- (one of them written beside the name, "destination Haneda, RJTT", is the one meant)
  function m:one_named(ids, kind, phrase, most)
    if #ids <= 1 then return ids[1] end
    if #ids <= most then
      local named = {}
      for _, id in ipairs(ids) do named[id] = true end
      for k, t in ipairs(self.t) do
        if t.kind == "word" and named[t.raw] then
          self:explain(k, k + 1)
          return t.raw
        end
      end
    end
    if #ids > 1 and #ids <= most then
      self.several_named = { ids = ids, phrase = phrase }
      self:need(string.format("Which %s is '%s': %s?", kind, phrase, table.concat(ids, " or ")))
      return ids[1]
    end
    return nil
  end

  -- The place named by one or two capitalised words from token k (its navaid kind after them or not: "Solberg",
  -- "the Brussels VOR" from "Brussels") for the aircraft `a` (m:place_by_name; `reference`: a place a limit or
  -- distance is measured from; `navaid_only`: a navaid of that name near `a` only), as a waypoint ref put in
  -- self.refs in place of any there; the token after it, or nil when the words name no such place.
  local function place_ref(self, k, a, reference, navaid_only)
    local e = k
    while e < k + 2 and self.t[e] and self.t[e].kind == "word" and self.t[e].alpha and self.t[e].raw:match("^%u%l")
        and not self.t[e].keyword and not self:word(e, "@navaid_kinds") and not self:has_ref(e, e + 1) do
      e = e + 1
    end
    -- (the words are explained only when they are read as the ref: a place refused leaves them to be asked)
    local explained = {}
    for x = k, e - 1 do explained[x] = (self.explained or {})[x] end
    local id = e > k and a and self:place_by_name(k, e, a, reference)
    if id and navaid_only then
      local navaid, named = false, self.world.navaids_named
      for _, n in ipairs(a.lat and named(self:raw(k, e):lower(), a.lat, a.lon, L.navaid_range_nm) or {}) do
        navaid = navaid or n:upper() == id:upper()
      end
      if not navaid then
        for x = k, e - 1 do self.explained[x] = explained[x] end
        return nil
      end
    end
    if not id then return nil end
    local stop = self:word(e, "@navaid_kinds") and e + 1 or e
    local kept = {}
    for _, x in ipairs(self.refs) do
      if x.e <= k or x.b >= stop then kept[#kept + 1] = x end
    end
    local at = 1
    while kept[at] and kept[at].b < k do at = at + 1 end
    table.insert(kept, at, { kind = "waypoint", name = id, b = k, e = stop, exists = true })
    self.refs = kept
    return stop
  end
  -- The aircraft flying named last before token i, or nil.
  local function flying_before(self, i)
    local refs = self:refs_in(1, i, "aircraft")
    local r = refs[#refs]
    return r and r.exists and self:state(r.name) or nil
  end

  -- Places said by their names where a limit ends or a route is listed, read before the parse as waypoint refs so
  -- that the limit and the route read them as they read idents typed: one after "until" or "till" ("maintain 250
  -- knots until Solberg", "till the Solberg VOR": m:place_by_name for the aircraft named before it, a place of
  -- reference), and each place of a list of two or more after "direct", "dct", "via", "through" or a route's
  -- colon, parted by "then" or "and" ("direct Northbrook, then DuPage, then Joliet", "a route: Chievres, then
  -- Brussels VOR, then Antwerp"). A name that means no place stays words (asked about).
  function m:named_place_refs()
    if not self:said("until till direct dct via through route") then return end
    for i = 1, #self.t - 1 do
      local opens = self:word(i, "direct dct via through") or (self.t[i].text == ":" and self:word(i - 1, "route"))
      -- (the aircraft only where a limit ends or a list opens)
      local a = (opens or self:word(i, "until till")) and flying_before(self, i)
      if a and self:word(i, "until till") then
        place_ref(self, self:word(i + 1, "the") and i + 2 or i + 1, a, true)
      end
      local k = opens and self:skip_fillers(self:word(i + 1, "to") and i + 2 or i + 1)
      -- (a list: the first place, then "then" or "and", a comma before it or not, and the next place, two places
      -- at least; a name after a comma alone may say the place before again: "direct to QPR, Quimper")
      local function parted(x)
        local j, worded = x, false
        while self.t[j] and (self.t[j].text == "," or self:word(j, "then and")) do
          worded = worded or self:word(j, "then and")
          j = j + 1
        end
        return worded and j or nil
      end
      local first = k and a and self.t[k] and self.t[k].raw:match("^%u")
      local stops = {}
      while first and k do
        local stop = self:has_ref(k, k + 1, "waypoint") and self:refs_in(k, k + 1, "waypoint")[1].e or nil
        stops[#stops + 1] = { k = k, stop = stop }
        local e = k
        while e < k + 3 and self.t[e] and self.t[e].kind == "word" and not self:word(e, "then and") do e = e + 1 end
        k = parted(e)
        first = k and self.t[k] and self.t[k].raw:match("^%u")
      end
      -- (between the list's places an airport's name is no waypoint flown over: it stays asked about)
      for n = 1, #stops >= 2 and #stops or 0 do
        if not stops[n].stop then place_ref(self, stops[n].k, a, nil, n < #stops) end
      end
    end
  end

  -- A place said by its name where an aircraft passes it, read before the parse as a waypoint ref so that the
  -- condition reads it as it reads an ident typed: after a verb of passing ("once it has passed the Halifax VOR",
  -- "when it passes Kingston") or after "after" with "the" and a kind of navaid ("after the Montreal VOR"), of the
  -- aircraft named before it (m:place_by_name, a place of reference: a name several navaids bear is asked). A name
  -- that means no place there stays words (asked about).
  function m:passed_place_refs()
    if not self:said("passes passing passed overflying overflies past after") then return end
    for i = 1, #self.t - 1 do
      local k = self:word(i + 1, "the") and i + 2 or i + 1
      local navaid = self:word(k + 1, "@navaid_kinds") or self:word(k + 2, "@navaid_kinds")
      local a = (self:word(i, "passes passing passed overflying overflies past")
        or (self:word(i, "after") and k == i + 2 and navaid)) and flying_before(self, i)
      if a and not self:has_ref(k, k + 1, "waypoint") then place_ref(self, k, a, true) end
    end
  end

  -- Where no aircraft is sent, a small airfield said by its name alone (no "airport" after it; airport_said_noun)
  -- whose name a navaid within lexicon.city_nm of it bears under another ident is the navaid ("create ... at
  -- Clacton, FL100": the CLN VOR, not the EGSQ strip), as a navaid named after a town with a small airfield is
  -- (m:place_by_name's "direct Perth"); said of an aircraft put on the ground ("on the ground", "ready for
  -- departure" in [b, e)), the airfield. Of several navaids of one station, the VOR ("at Nakuru": the VOR-DME NAK,
  -- not the NDB NU beside it). Nil when that does not hold: a large or medium airport stays itself.
  function m:small_airfield_navaid(b, e, airport)
    local w, c = self.world, self.world.airport_class(airport)
    if c == "LARGE" or c == "MEDIUM" or self.airport_said_noun or self:word_in(b, e, "ground departure takeoff take-off") then
      return nil
    end
    local lat, lon = w.user_waypoint_at(airport)
    if not lat then return nil end
    local asked = self.ask
    local navaid = self:navaid_by_name(b, e, { lat = lat, lon = lon }, L.city_nm, nil, true)
    self.ask = asked
    return navaid and navaid:upper() ~= airport:upper() and navaid or nil
  end

  -- A place said by its name where an aircraft is put or sent: an airport of that name within
  -- lexicon.navaid_range_nm of the aircraft `a` (of any aircraft when `a` is nil), else a navaid of
  -- that name there ("direct Perth" near Scotland is the PTH VOR, not YPPH), else an airport
  -- anywhere; with no traffic, else the one navaid of that name anywhere ("create ... at Ockham").
  -- A name that an airport and a navaid near the aircraft `a` both bear ("direct Melbourne": YMML
  -- and the ML VOR) is the one of the two its route holds (its destination: the airport's), else
  -- asked about, the airport kept (a direct-to a city names its VOR as often as its airport). `reference`
  -- (true: a place a distance or a waypoint condition is measured from, "30 miles from Frankfurt") makes a
  -- name several navaids there bear beside the airport asked about too, naming them all; `large` (true) reads a
  -- name a large airport and a navaid near both bear as the airport (a heading toward it).
  -- True when the airport's own navdata name holds the words `phrase` (EDDF "FRANKFURT MAIN" for "frankfurt")
  local function G_airport_bears(self, phrase, airport, a)
    local with = self.world.airports_with_words
    if not (with and a and a.lat) then return true end
    for _, id in ipairs(with(phrase, a.lat, a.lon, L.navaid_range_nm)) do
      if id:upper() == airport:upper() then return true end
    end
    return false
  end
  -- True when the navaid `navaid` nearest `near` {lat, lon} [deg] stands within lexicon.navaid_by_airport_nm of the
  -- airport `airport`: one place ("track direct Sydney": the SY VOR-DME 0.3 NM from YSSY), the city said its airport;
  -- never where the request names a destination too ("cleared direct Cork, destination Cork": the place and the
  -- destination said twice, or two things?)
  function m:navaid_by_airport(navaid, airport, near)
    local beside = not self:word_in(1, #self.t + 1, "destination dest") and self.world.airports_beside
    for _, id in ipairs(beside and near.lat and beside(navaid, near.lat, near.lon, L.navaid_by_airport_nm) or {}) do
      if id == airport then return true end
    end
    return false
  end
  function m:place_by_name(b, e, a, reference, large)
    local near = a and { a } or self.fleet
    -- (the longer name first: "direct Zurich East" is the ZUE VOR, not Zurich airport and a word more)
    for _, r in ipairs(near) do
      local id = self:navaid_by_name(b, e, r, nil, true)
      if id then return id end
    end
    local unasked = self.ask
    local airport = a and self:airport_by_name(b, e, a)
    local asked = self.ask
    self.several_named = nil
    local navaid, phrase = nil, nil
    -- (several navaids of the name that are one station are its VOR: "direct Oshima", the XAC VORTAC and the XA NDB
    -- 1.7 NM apart, beside RJTO "OSHIMA" 4.7 NM away, is the VOR or the airport, asked)
    if airport then navaid, phrase = self:navaid_by_name(b, e, a, nil, nil, true) end
    -- (a navaid's name said with a capitalised word after it that the airport's own name holds, "Boston Logan":
    -- KBOS "GENERAL EDWARD LAWRENCE LOGAN", the BOS VOR "BOSTON" a word of it, is the airport)
    local with = self.world.airports_with_words
    if navaid and phrase and with and a.lat then
      local n, k = select(2, phrase:gsub("%S+", "")), b
      while k < e and self.t[k].text ~= phrase:match("^%S+") do k = k + 1 end
      local w = self.t[k + n]
      if k + n < e and w and w.kind == "word" and w.alpha and w.raw:match("^%u") and not w.keyword then
        for _, id in ipairs(with(w.text, a.lat, a.lon, L.navaid_range_nm)) do
          if id:upper() == airport:upper() then navaid = nil break end
        end
      end
    end
    -- (a name several navaids there bear is no one navaid: "direct Frankfurt" is the airport; "30 miles from
    -- Frankfurt" is asked: EDDF, or the FFM or FW navaid?)
    if self.ask ~= asked then
      self.ask, navaid = asked, nil
      local several = self.several_named
      if reference and several then
        local n, k = select(2, several.phrase:gsub("%S+", "")), b
        while k < e and self.t[k].text ~= several.phrase:match("^%S+") do k = k + 1 end
        self:need(string.format("Which place is '%s': the %s airport or the %s navaid?", self:raw(k, k + n), airport,
          table.concat(several.ids, " or ")))
      elseif several and not large and self.going_direct and not G_airport_bears(self, several.phrase, airport, a) then
        -- ("direct Lagos": DNMM "MURTALA MUHAMMED", and the LAG and LOS VORs named LAGOS: the city's name, which
        -- the airport's own name does not hold, is the one of them the aircraft's route or destination holds,
        -- else asked, naming them all; "direct Frankfurt", EDDF "FRANKFURT MAIN", stays the airport; cycle 65)
        local held = {}
        for _, r in ipairs(a.route or {}) do held[r:upper()] = true end
        if a.dest and a.dest ~= "" then held[a.dest:upper()] = true end
        local one
        for _, id in ipairs(several.ids) do
          if held[id:upper()] then one = one == nil and id or false end
        end
        if one and not held[airport:upper()] then
          self.ask = unasked
          return one
        end
        if not held[airport:upper()] then
          local n, k = select(2, several.phrase:gsub("%S+", "")), b
          while k < e and self.t[k].text ~= several.phrase:match("^%S+") do k = k + 1 end
          self:need(string.format("Which place is '%s': the %s airport or the %s navaid?", self:raw(k, k + n),
            airport, table.concat(several.ids, " or ")))
        end
      end
    end
    -- ("direct Geneva" with GVA, the VOR "GENEVA COINTRIN" on LSGG, in the route: the one navaid of the route whose
    -- name holds the words said and that stands on the airport they name, within lexicon.navaid_by_airport_nm)
    local span = airport and not navaid and self.place_spans and self.place_spans[#self.place_spans]
    local with = span and a.lat and self.world.navaids_with_words
    if with then
      local on_route = {}
      for _, id in ipairs(with(self:raw(span.b, span.e):lower(), a.lat, a.lon, L.navaid_range_nm)) do
        for _, r in ipairs(a.route or {}) do
          if r:upper() == id:upper() and self:navaid_by_airport(id, airport, a) then on_route[#on_route + 1] = id end
        end
      end
      if #on_route == 1 and not self.ask then return on_route[1] end
    end
    if navaid then
      local held = {}
      for _, r in ipairs(a.route or {}) do held[r:upper()] = true end
      if a.dest and a.dest ~= "" then held[a.dest:upper()] = true end
      local nav_held, airport_held = held[navaid:upper()], held[airport:upper()]
      -- (the navaid its route holds answers which of a city's airports was meant: "15 miles north of Seattle"
      -- with SEA in the route is SEA, not KSEA or KBFI)
      if nav_held and not airport_held then
        self.ask = unasked
        return navaid
      end
      -- (`large`: a large airport is what the name means, over the navaid its route does not hold: "toward
      -- Tucson" is KTUS)
      local class = self.world.airport_class
      if large and not nav_held and class and class(airport) == "LARGE" then return airport end
      if not nav_held and class and class(airport) == "LARGE" and self:navaid_by_airport(navaid, airport, a) then
        return airport
      end
      -- (a navaid standing on an airport other than a large one, neither held, is one place with it, named as a
      -- waypoint is: "direct Viseu", the VIS VOR-DME 0.2 NM from the medium LPVZ; a distance from it stays the
      -- airport's, "within 15 miles of Dortmund")
      if not reference and not nav_held and not airport_held and self:navaid_by_airport(navaid, airport, a) then
        self.ask = unasked
        return navaid
      end
      if nav_held or not airport_held then
        self:need(string.format("Which place is meant: the %s navaid or the %s airport?", navaid, airport))
      end
      return airport
    end
    -- (where no aircraft is meant, a name said after "over", "above", ... that an airport other than a large
    -- one and a navaid within lexicon.city_nm of it both bear under other idents, "over Sherbrooke": the
    -- medium CYSC and the YSC VORTAC, is asked about, the airport kept; "at Sherbrooke" is the airport, and so
    -- is "over Schiphol", a large airport, as a large airport is what its name means, unless the name is a
    -- city's that several large airports bear, "over Spartanburg": KSPA, KGSP and the SPA VORTAC)
    local function beside(airport)
      local at, class = self.world.user_waypoint_at, self.world.airport_class
      local lat, lon = nil, nil
      local k = self.airport_said_at
      local shared = at and class and not a and k and self:word(k - 1, "@place_words") and self:small_airfield_navaid(b, e, airport)
      if shared then return shared end
      if at and class and (class(airport) ~= "LARGE" or self.airport_said_city) and not a and k
          and self:word(k - 1, "@place_words")
          and not self:word(k - 1, "at") then
        lat, lon = at(airport)
      end
      if not lat then return airport end
      local asked = self.ask
      local navaid = self:navaid_by_name(b, e, { lat = lat, lon = lon }, L.city_nm)
      self.ask = asked
      -- (a navaid of the name standing on the airport, within lexicon.navaid_by_airport_nm, is that one place: "over
      -- Glasgow", the GLW NDB on EGPF)
      if navaid and navaid:upper() ~= airport:upper()
          and not self:navaid_by_airport(navaid, airport, { lat = lat, lon = lon }) then
        self:need(string.format("Which place is meant: the %s navaid or the %s airport?", navaid, airport))
      end
      return airport
    end
    for _, r in ipairs(near) do
      local id = self:airport_by_name(b, e, r)
      if id then return beside(id) end
    end
    -- (a navaid named after a city whose airport lies beside it under a longer name, "direct Sanford": the
    -- SFB NDB and KSFB "ORLANDO SANFORD INTL" within lexicon.city_nm, is the one of the two aircraft `a`'s
    -- route holds; with neither held, asked about when the airport is large or medium, else the navaid:
    -- "direct Perth" over Scotland is the PTH VOR, not the small Perth/Scone. The same for a place no aircraft
    -- is sent to, found near the aircraft `r` ("getwind at Lille", "create ... at Lille"), and, for a city's name
    -- (an airport bears it), for the large (else medium) airport within lexicon.city_navaid_nm of the navaid
    -- when none beside bears the name, the city's airport named otherwise: "Lille" is the LL NDB or LFQQ
    -- "LESQUIN", asked; sim:airports_beside_navaids)
    local function city_airport(navaid, phrase, r)
      local w, p = self.world, a or r
      if not (p and p.lat and phrase and w.airports_beside and w.airports_with_words) then return navaid end
      local held = {}
      for _, x in ipairs(a and a.route or {}) do held[x:upper()] = true end
      if a and a.dest and a.dest ~= "" then held[a.dest:upper()] = true end
      if held[navaid:upper()] then return navaid end
      local bears = {}
      for _, id in ipairs(w.airports_with_words(phrase, p.lat, p.lon, L.navaid_range_nm)) do bears[id] = true end
      local named = {}
      for _, id in ipairs(w.airports_beside(navaid, p.lat, p.lon, L.city_nm)) do
        if bears[id] then named[#named + 1] = id end
      end
      local class = w.airport_class and named[1] and w.airport_class(named[1])
      -- (the name a city's: an airport bears it, a small one there, "LILLE/MARCQ-EN-BAROEUL"; "Canarsie", the CRI
      -- VOR by KJFK, is no city's)
      if not (class == "LARGE" or class == "MEDIUM") and next(bears) and w.airports_beside_navaids then
        local near_it = {}
        for _, id in ipairs(w.airports_beside(navaid, p.lat, p.lon, L.city_navaid_nm)) do near_it[id] = true end
        named = {}
        for _, id in ipairs(w.airports_beside_navaids(phrase, p.lat, p.lon, L.navaid_range_nm)) do
          if near_it[id] then named[#named + 1] = id end
        end
      end
      -- (found near another aircraft, a navaid that stands on the airport is that airport's place: "at Marseille",
      -- the MJ NDB on LFML)
      if not a and #w.airports_beside(navaid, p.lat, p.lon, 1) > 0 then return navaid end
      for _, id in ipairs(named) do
        if held[id:upper()] then return id end
      end
      class = w.airport_class and named[1] and w.airport_class(named[1])
      if class == "LARGE" and self:navaid_by_airport(navaid, named[1], p) then return named[1] end
      if class == "LARGE" or class == "MEDIUM" then
        self:need(string.format("Which place is meant: the %s navaid or the %s airport?", navaid, named[1]))
      end
      return navaid
    end
    for _, r in ipairs(near) do
      local id, phrase = self:navaid_by_name(b, e, r)
      if id then return city_airport(id, phrase, r) end
    end
    -- (a name of several words that an airport near an aircraft holds whole, "direct colorado springs": KCOS,
    -- before an airport anywhere named by a part of it, FASI "SPRINGS")
    for _, r in ipairs(near) do
      local id = r.lat and self:airport_by_words(b, e, r, 2)
      if id then return id end
    end
    -- (one word of an airport's name near an aircraft, said with an airport noun, "toward Oakland airport" over the
    -- Bay: KOAK "METROPOLITAN OAKLAND INTL", before an airport far away whose name starts with it, KPTK "OAKLAND CO
    -- INTL" in Michigan; "over Logan airport": KBOS)
    for _, r in ipairs(near) do
      local id = r.lat and self:airport_by_words(b, e, r, 1, true)
      if id then return id end
    end
    local airport = self:airport_by_name(b, e)
    if airport then
      if a then self:far_from_aircraft(airport, a) end
      return beside(airport)
    end
    if #near > 0 then return nil end
    -- with no traffic to place it near, the name of one navaid anywhere (several are asked about)
    return (self:navaid_by_name(b, e, { lat = 0, lon = 0 }, math.huge))
  end

  -- An airport found by its name anywhere where the aircraft `a` is sent, farther than lexicon.region_nm from it
  -- (another continent: "direct springs" over Colorado is FASI "SPRINGS" in South Africa), is asked about, naming
  -- the words and the airport; never flown to on a word that names a place far away.
  function m:far_from_aircraft(airport, a)
    local at = self.world.user_waypoint_at
    if not (at and a.lat) then return end
    local lat, lon = at(airport)
    if not lat then return end
    local dlat, dlon = lat - a.lat, ((lon - a.lon + 180) % 360 - 180) * math.cos(math.rad(a.lat))
    if 60 * math.sqrt(dlat * dlat + dlon * dlon) <= L.region_nm then return end
    local span = (self.place_spans or {})[#(self.place_spans or {})]
    self:need(string.format("Which place is '%s'? The one I found by that name is the airport %s, more than %d NM "
      .. "from %s. Please give its ICAO code or ident.", span and self:raw(span.b, span.e) or airport, airport,
      L.region_nm, a.id))
  end

  -- A navaid said by its navdata name ("direct Canarsie" -> CRI, "Point Reyes" -> PYE), where no
  -- airport has that name: one or two words in [b, e) that name navaids within
  -- range_nm (default lexicon.navaid_range_nm) of the aircraft `a`; the question names them when
  -- several idents fit; `two_words` (true) reads two-word names only; `station` (true) reads several navaids of one
  -- station as its VOR even where an airport bears the name (m:station_vor). Second result: the name as said,
  -- unless a navaid's kind follows it ("the Atlanta VOR").
  function m:navaid_by_name(b, e, a, range_nm, two_words, station)
    local named = self.world.navaids_named
    if not named or not a or not a.lat then return nil end
    for i = b, math.min(e, #self.t + 1) - 1 do
      local t, nx = self.t[i], self.t[i + 1]
      if not self.u:used(i) and t.kind == "word" and t.alpha and not t.filler and not t.number_word then
        local phrases = {}  -- {words, the position after them}
        -- (a name of three to six words said whole first, as said and as its short form: "san sebastian
        -- de los reyes" is "S S REYES", SSY; lexicon.name_particles)
        local words = { t.text }
        for j = i + 1, math.min(e, i + 6) - 1 do
          local w = self.t[j]
          if self.u:used(j) or w.kind ~= "word" or not w.alpha or w.keyword or w.filler then break end
          words[#words + 1] = w.text
        end
        for n = #words, 3, -1 do
          local short = {}
          for k = 1, n - 1 do
            if not PARTICLES[words[k]] then short[#short + 1] = words[k]:sub(1, 1) end
          end
          phrases[#phrases + 1] = { table.concat(words, " ", 1, n), i + n }
          phrases[#phrases + 1] = { table.concat(short, " ") .. " " .. words[n], i + n }
        end
        if nx and i + 1 < e and nx.kind == "word" and nx.alpha and not self.u:used(i + 1) then
          phrases[#phrases + 1] = { t.text .. " " .. nx.text, i + 2 }
          -- ("saint prex" for the navdata's "ST. PREX", "st gallen" for "SAINT GALLEN")
          local saint = L.saint_forms[t.text]
          if saint then phrases[#phrases + 1] = { saint .. " " .. nx.text, i + 2 } end
          -- (a one-word name a recogniser split in two, "du page" for DUPAGE, DPA)
          phrases[#phrases + 1] = { t.text .. nx.text, i + 2 }
        end
        if #t.text >= 4 and not t.keyword and not two_words then phrases[#phrases + 1] = { t.text, i + 1 } end
        for _, p in ipairs(phrases) do
          local phrase = p[1]
          -- ("Nantucket airport" is the airport, not the navaid of that name)
          -- (with `two_words`, a name an airport bears too stays the airport's: "London City")
          local airport = two_words and self.world.airports_named and #self.world.airports_named(phrase) > 0
          -- (its kind said after it, or before it in the Spanish order: "the VOR Bogota")
          local kind = self.t[p[2]] and self.t[p[2]].kind == "word" and L.navaid_types[self.t[p[2]].text]
            or (i > 1 and self.t[i - 1].kind == "word" and L.navaid_types[self.t[i - 1].text])
          local ids = (airport or self:word(p[2], "@airport_nouns")) and {}
            or named(phrase, a.lat, a.lon, range_nm or L.navaid_range_nm, kind or nil)
          -- ("the Ottawa VOR": the VOR YOW, not the DME IOW of the same name that the navdata types TACAN)
          local first_kind = kind and kind:match("^%S+")
          if #ids > 1 and first_kind ~= kind then
            local only = named(phrase, a.lat, a.lon, range_nm or L.navaid_range_nm, first_kind)
            if #only == 1 then ids = only end
          end
          -- ("move Air Nostrum 8123 to Castejon": several navaids of the name, all of one station, are its VOR, where
          -- no airport bears the name: "Vilnius" is left to the airport's reading)
          local by_airport = self.world.airports_named
          if #ids > 1 and not kind and (station or not (by_airport and #by_airport(phrase) > 0)) then
            ids = self:station_vor(phrase, ids, select(2, named(phrase, a.lat, a.lon, range_nm or L.navaid_range_nm)))
              or ids
          end
          -- (of several navaids of the name, the one the aircraft's route holds: "direct Stornoway" with
          -- STN, not SAY or ISV, in its route)
          local held = {}
          for _, r in ipairs(#ids > 1 and a.route or {}) do
            for _, n in ipairs(ids) do
              if n:upper() == r:upper() then held[#held + 1] = n end
            end
          end
          -- ("direct Quimper" with QPR, "QUIMPER PLUGUFFAN", in the route and the NDB RQ named "QUIMPER" alone: the
          -- one navaid of the route whose name holds the words said, before another named by them whole)
          local with = #ids >= 1 and #held == 0 and a.route and #a.route > 0 and self.world.navaids_with_words
          for _, n in ipairs(with and with(phrase, a.lat, a.lon, range_nm or L.navaid_range_nm) or {}) do
            for _, r in ipairs(a.route) do
              if n:upper() == r:upper() then held[#held + 1] = n end
            end
          end
          if #held == 1 then ids = held end
          local id = self:one_named(ids, "navaid", phrase, math.huge)
          if id then
            self:explain_place(i, p[2])
            return id, not kind and phrase or nil
          end
        end
      end
    end
    return nil
  end

  -- An airport said by its name ("direct to Schiphol" -> EHAM): one or two
  -- words in [b, e) that name exactly one airport of the navdata (within
  -- lexicon.navaid_range_nm of `near` {lat, lon} [deg] when given).
  -- A word said after a place preposition ("at Barajas") is tried before
  -- any other ("a new Iberia aircraft": an airline, though an airport bears its name).
  -- Near: within lexicon.navaid_range_nm of the aircraft `near`; anywhere, a small airfield is no
  -- airport a name alone means ("Amsterdam" is no South African strip). A city said in capitals is
  -- its large airport when no airport bears the name ("Frankfurt" -> EDDF "Frankfurt Main").
  -- `meant` (an airport is meant: a destination, an origin): a city said in capitals that names
  -- navaids is the one large (else medium) airport beside them ("destination Toulouse" -> LFBO
  -- "BLAGNAC" beside the TOULOUSE VOR; sim:airports_beside_navaids); several are asked about.
  function m:airport_by_name(b, e, near, meant)
    local named, city, class = self.world.airports_named, self.world.airports_of_city, self.world.airport_class
    if not named then return nil end
    self.city_airport = self.city_airport or {}
    local function within(list)
      -- (a city said by its English name is read as the navdata names it, lexicon.city_airports, when no
      -- airport kept bears the name; an airport the navdata marks closed is none: "Oslo" is no longer
      -- Fornebu; far from the aircraft, a small one is none either)
      local function kept(ids)
        local out = {}
        for _, id in ipairs(ids) do
          local c = class and class(id)
          if c ~= "CLOSED" and (near or c ~= "SMALL") then out[#out + 1] = id end
        end
        return out
      end
      -- (the name lexicon.city_airports gives is the city's one large airport's: "Bogota" is SKBO "ELDORADO
      -- INTL", not the medium SVED "EL DORADO" in Venezuela)
      -- (with no traffic, a name is also its city's: the large airports whose names start with it are candidates
      -- beside the airports of that name, "Phoenix" is ZJSY "PHOENIX INTL" or KPHX "PHOENIX SKY HARBOR INTL",
      -- asked; not a name said after its city, "Beijing Capital airport", m:airport_named_in)
      local function said(phrase, ...)
        local ids = kept(list(phrase, ...))
        if not near and #self.fleet == 0 and city and list == named and #ids > 0 and not self.name_after_city then
          local known = {}
          for _, id in ipairs(ids) do known[id] = true end
          for _, id in ipairs(kept(city(phrase))) do
            if not known[id] then ids[#ids + 1] = id end
          end
        end
        -- (the city's airport bearing its name, none large, beside the large one lexicon.city_airports names,
        -- within L.city_nm: the large one, where the city's traffic flies; "Hyderabad" is VOHS "RAJIV GANDHI
        -- INTL", not VOHY "HYDERABAD", Begumpet)
        local locate = self.world.user_waypoint_at
        if #ids > 0 and L.city_airports[phrase] and class and locate then
          local large = {}
          for _, id in ipairs(ids) do
            if class(id) == "LARGE" then large = nil break end
            local lat, lon = locate(id)
            for _, x in ipairs(lat and (city or list)(L.city_airports[phrase], lat, lon, L.city_nm) or {}) do
              if class(x) == "LARGE" then large[#large + 1] = x end
            end
          end
          if large and #large > 0 then ids = large end
        end
        -- (a name that a smaller field bears whole, and a large airport's name within L.city_nm of it holds among its
        -- words, is either: "Changi" is WSAC "CHANGI AIR BASE" or WSSS "SINGAPORE CHANGI INTL", asked)
        local with = self.world.airports_with_words
        if #ids > 0 and list == named and class and with and locate then
          local large, known = {}, {}
          for _, id in ipairs(ids) do
            known[id] = true
            if class(id) == "LARGE" then large = nil break end
          end
          for _, id in ipairs(large and ids or {}) do
            local lat, lon = locate(id)
            for _, x in ipairs(lat and with(phrase, lat, lon, L.city_nm) or {}) do
              if class(x) == "LARGE" and not known[x] then large[#large + 1], known[x] = x, true end
            end
          end
          for _, x in ipairs(large or {}) do ids[#ids + 1] = x end
        end
        if #ids == 0 and L.city_airports[phrase] then
          ids = kept(list(L.city_airports[phrase], ...))
          local large = {}
          for _, id in ipairs(class and ids or {}) do
            if class(id) == "LARGE" then large[#large + 1] = id end
          end
          if #large > 0 then ids = large end
          for _, id in ipairs(ids) do self.city_airport[id] = true end
        end
        return ids
      end
      if near then return function(phrase) return said(phrase, near.lat, near.lon, L.navaid_range_nm) end end
      return function(phrase) return said(phrase) end
    end
    if near and not near.lat then return nil end
    for _, placed in ipairs({ true, false }) do
      local id = self:airport_named_in(b, e, within(named), placed, false, near ~= nil)
      if id then return id end
    end
    local beside = self.world.airports_beside_navaids
    -- (a city whose large airports the navdata names otherwise too, beside its navaids, is no one airport:
    -- "Montreal" is CYMX "MONTREAL INTL MIRABEL" or CYUL "PIERRE ELLIOTT TRUDEAU INTL", asked)
    local of_city, navaids, by = city and within(city), self.world.navaids_named, self.world.airports_beside
    local function city_airports(phrase)
      local ids = of_city(phrase)
      if #ids ~= 1 or not near or not navaids or not by or not class then return ids end
      for _, nav in ipairs(navaids(phrase, near.lat, near.lon, L.navaid_range_nm)) do
        for _, id in ipairs(by(nav, near.lat, near.lon, L.beside_navaid_nm)) do
          local known = false
          for _, x in ipairs(ids) do known = known or x == id end
          if not known and class(id) == "LARGE" then ids[#ids + 1] = id end
        end
      end
      return ids
    end
    local id = city and self:airport_named_in(b, e, city_airports, false, true) or nil
    if id or not meant or not beside then return id end
    return self:airport_named_in(b, e, within(beside), false, true)
  end

  -- A city said where an airport is meant (a destination, an origin, a place shown) that names no airport
  -- near the aircraft `near` {lat, lon} [deg], as the region's airport: one to three capitalised words in
  -- [b, e) that large or medium airports bear (sim:airports_named), else that name their city
  -- (sim:airports_of_city) or navaids beside them (sim:airports_beside_navaids: SACO "AMBROSIO L V
  -- TARAVELLA" beside the CORDOBA VOR). Of the first of those kinds that has any, the nearest is the region's
  -- when it lies within lexicon.region_nm of `near` and every other lexicon.region_ratio times as far or
  -- farther ("Cordoba" from Buenos Aires is SACO, 350 NM, not LEBA in Spain); with no `near` (no traffic)
  -- the one there is. Returns its ident (the name explained), nil when there is none; several of the region
  -- are asked about ("Porto Alegre": SBPA or SBCO?).
  function m:airport_of_region(b, e, near)
    local w = self.world
    local at, class = w.user_waypoint_at, w.airport_class
    if not (at and class and w.airports_named and w.airports_beside_navaids) or (near and not near.lat) then return nil end
    local function candidates(phrase, lists)
      local out, seen = {}, {}
      for _, list in ipairs(lists) do
        for _, id in ipairs(list and list(phrase) or {}) do
          local c = class(id)
          local lat, lon = at(id)
          if not seen[id] and (c == "LARGE" or c == "MEDIUM") and lat then
            local dlat, dlon = near and lat - near.lat or 0, near and (lon - near.lon) * math.cos(math.rad(near.lat)) or 0
            out[#out + 1] = { id = id, nm = 60 * math.sqrt(dlat * dlat + dlon * dlon) }
          end
          seen[id] = true
        end
      end
      table.sort(out, function(x, y) return x.nm < y.nm end)
      return out
    end
    local function word(k)
      local t = self.t[k]
      return k < e and t ~= nil and t.kind == "word" and t.alpha and t.raw:match("^%u") ~= nil and not self.u:used(k)
        and not t.keyword and not t.filler and not t.number_word and not L.phonetic[t.text]
    end
    for i = b, math.min(e, #self.t + 1) - 1 do
      for n = 3, 1, -1 do
        -- (a capitalised word of under four letters opens a longer name only: "New Chitose" is RJCC, never
        -- "Chitose" RJCJ with "New" left over)
        local first = self.t[i] or {}
        local ok, words = #first.text >= 4 or (n > 1 and (first.raw or ""):match("^%u%l") ~= nil), {}
        for k = i, i + n - 1 do
          ok = ok and word(k)
          words[#words + 1] = ok and self.t[k].text or nil
        end
        local phrase = ok and table.concat(words, " ")
        for _, lists in ipairs(ok and { { w.airports_named }, { w.airports_of_city, w.airports_beside_navaids } } or {}) do
          local found = candidates(phrase, lists)
          local first = found[1]
          if first and (not near or first.nm <= L.region_nm) then
            local ids = {}
            for _, c in ipairs(found) do
              if (not near or c.nm < L.region_ratio * first.nm) and #ids < 4 then ids[#ids + 1] = c.id end
            end
            -- ("London Heathrow", "Paris Orly": a city's airports, one named by the word after the city)
            local nx = #ids > 1 and self.t[i + n]
            if nx and nx.kind == "word" and nx.alpha and w.airports_named then
              for _, id in ipairs(w.airports_named(nx.text) or {}) do
                for _, c in ipairs(ids) do
                  if c == id then
                    self:explain_place(i, self:word(i + n + 1, "@airport_nouns") and i + n + 2 or i + n + 1)
                    return id
                  end
                end
              end
            end
            self:explain_place(i, self:word(i + n, "@airport_nouns") and i + n + 1 or i + n)
            if #ids > 1 then
              self:need(string.format("Which airport is '%s': %s?", self:raw(i, i + n), table.concat(ids, " or ")))
            end
            return first.id
          end
        end
        if ok and #candidates(phrase, { w.airports_named, w.airports_of_city, w.airports_beside_navaids }) > 0 then
          return nil  -- (airports of that name, none the region's: the caller's lookup anywhere decides)
        end
      end
    end
    return nil
  end

  -- An airport said as its city and a distinctive part of its navdata name ("Toronto Pearson" -> CYYZ
  -- "LESTER B PEARSON INTL", "Montreal Trudeau" -> CYUL, "Boston Logan" -> KBOS), where an airport is meant:
  -- a capitalised word in [b, e) and one or two capitalised words after it, the airports whose names hold
  -- the latter (sim:airports_with_words, within lexicon.navaid_range_nm of the aircraft `near`) that lie
  -- within lexicon.city_nm of a navaid named by the city (sim:airports_beside) or bear the city's name
  -- (sim:airports_named, airports_of_city, lexicon.city_airports). Exactly one is that airport, both words
  -- explained; none or several give nil (the name is read otherwise, or asked about).
  function m:airport_of_city_said(b, e, near)
    local w = self.world
    if not (w.airports_with_words and w.navaids_named and w.airports_beside) or not near or not near.lat then return nil end
    local function proper(k)
      local t = self.t[k]
      return k < e and t ~= nil and t.kind == "word" and t.alpha and t.raw:match("^%u%l") ~= nil and not self.u:used(k)
        and not t.keyword and not t.filler and not t.number_word and not L.phonetic[t.text]
    end
    local range = L.navaid_range_nm
    for i = b, math.min(e, #self.t + 1) - 2 do
      if proper(i) and proper(i + 1) then
        local city = self.t[i].text
        local of_city = {}
        for _, nav in ipairs(w.navaids_named(city, near.lat, near.lon, range)) do
          for _, id in ipairs(w.airports_beside(nav, near.lat, near.lon, L.city_nm)) do of_city[id] = true end
        end
        -- (the airports named after the city anchor it, their neighbours within lexicon.city_nm its airports
        -- too: "Montreal Trudeau" is CYUL, 17 NM from CYMX "MONTREAL INTL MIRABEL"; at most lexicon.city_anchors
        -- of them. A word inside one airport's name names no city: "Ohare Midway" is no Chicago airport)
        local anchors = {}
        for _, list in ipairs({ w.airports_named, w.airports_of_city }) do
          for _, name in ipairs({ city, L.city_airports[city] }) do
            for _, id in ipairs(list and name and list(name, near.lat, near.lon, range) or {}) do
              if not of_city[id] and #anchors < L.city_anchors and w.user_waypoint_at then
                local lat, lon = w.user_waypoint_at(id)
                if lat then anchors[#anchors + 1] = { lat = lat, lon = lon } end
              end
              of_city[id] = true
            end
          end
        end
        for n = 2, 1, -1 do
          if n == 1 or proper(i + 2) then
            local words = {}
            for k = i + 1, i + n do words[#words + 1] = self.t[k].text end
            local phrase = table.concat(words, " ")
            -- (the part said may be the whole of the navdata's name: "Belfast City" is EGAC "CITY", "Belfast
            -- Aldergrove" EGAA "ALDERGROVE")
            local by_city, found, seen = {}, {}, {}
            for _, by in ipairs({ w.airports_with_words, w.airports_named }) do
              for _, at in ipairs(anchors) do
                for _, id in ipairs(by(phrase, at.lat, at.lon, L.city_nm)) do by_city[id] = true end
              end
            end
            for _, by in ipairs({ w.airports_with_words, w.airports_named }) do
              for _, id in ipairs(by(phrase, near.lat, near.lon, range)) do
                if (of_city[id] or by_city[id]) and not seen[id] then found[#found + 1], seen[id] = id, true end
              end
            end
            if #found == 1 then
              self:explain_place(i, self:word(i + n + 1, "@airport_nouns") and i + n + 2 or i + n + 1)
              return found[1]
            end
          end
        end
      end
    end
    return nil
  end

  -- An airport said by a distinctive part of its navdata name, where an airport is meant ("destination
  -- Midway" -> KMDW "CHICAGO MIDWAY INTL", "is going to Kennedy" -> KJFK "JOHN F KENNEDY INTL"): one to
  -- three words in [b, e), the first no English squawk knows, that the name of exactly one airport
  -- within lexicon.navaid_range_nm of `near` {lat, lon} [deg] holds (sim:airports_with_words); the
  -- question names them when several do (at most 4), nil when none; `min_words` (default 1): the fewest words
  -- the name found is said in; `noun` (true): only words an airport noun follows ("Oakland airport"); `large`
  -- (true): only large airports.
  function m:airport_by_words(b, e, near, min_words, noun, large)
    local with = self.world.airports_with_words
    if not with or not near.lat then return nil end
    local function free(k) return k < e and self.t[k] and self.t[k].kind == "word" and self.t[k].alpha
      and not self.u:used(k) and not self.t[k].keyword and not self.t[k].filler and not self.t[k].number_word end
    for i = b, math.min(e, #self.t + 1) - 1 do
      if free(i) and not L.phonetic[self.t[i].text] and not self:known_word(i) then
        for n = 3, 1, -1 do
          local words = {}
          for k = i, i + n - 1 do words[#words + 1] = free(k) and self.t[k].text or nil end
          if #words == n and (n > 1 or #words[1] >= 4) and n >= (min_words or 1)
              and (not noun or self:word(i + n, "@airport_nouns")) then
            local phrase = table.concat(words, " ")
            local ids, class = {}, self.world.airport_class
            for _, x in ipairs(with(phrase, near.lat, near.lon, L.navaid_range_nm)) do
              -- (a closed airport is none)
              if not class or (class(x) ~= "CLOSED" and (not large or class(x) == "LARGE")) then ids[#ids + 1] = x end
            end
            local id = self:one_named(ids, "airport", phrase, 4)
            -- ("destination Paris": one word held inside one airport's long name, LE TOUQUET PARIS PLAGE, that
            -- is also the name of a navaid beside other airports, the PARIS VOR by KPRX, or begins the names of
            -- large airports, a city's: no one airport, asked naming them; "Midway", "Kennedy" name no other)
            local others = id and n == 1 and not self.ask and self:airport_word_elsewhere(words[1], id)
            if others then
              self:need(string.format("Which airport is '%s'? %s holds the word in its name, and %s %s named "
                .. "by it too. Please give its ICAO code.", self.t[i].raw, id, table.concat(others, " or "),
                #others > 1 and "are" or "is"))
              self:explain_place(i, i + 1)
              return id
            end
            if id then
              -- (its city before a name of two or three words: "Paris Charles de Gaulle")
              local from = n > 1 and self:city_before_airport(i, i + n, id) and i - 1 or i
              self:explain_place(from, self:word(i + n, "@airport_nouns") and i + n + 1 or i + n)
              return id
            end
          end
        end
      end
    end
    return nil
  end

  -- The airports other than `id` that the one lower-case word `w` also names (at most 4): those beside a navaid
  -- called `w` (sim:airports_beside_navaids) and the large airports whose names begin with it (a city's,
  -- sim:airports_of_city); nil when none, or when the airport `id` is itself among them or w names it first.
  function m:airport_word_elsewhere(w, id)
    local world = self.world
    if not (world.airports_beside_navaids and world.airports_of_city and world.airports_named) then return nil end
    local out, seen = {}, { [id] = true }
    for _, x in ipairs(world.airports_named(w)) do
      if x == id then return nil end
    end
    for _, by in ipairs({ world.airports_beside_navaids(w), world.airports_of_city(w) }) do
      for _, x in ipairs(by) do
        if x == id then return nil end
        if not seen[x] and #out < 4 then out[#out + 1], seen[x] = x, true end
      end
    end
    return #out > 0 and out or nil
  end

  -- True when the capitalised word before i, where the words [i, e) name airport `id`, is that airport's city ("Paris
  -- Charles de Gaulle"): the navdata has a place named by the word and the words together (G:any_place_named: the
  -- PARIS CHARLES DE GAULLE VOR-DME) within lexicon.city_nm of the airport. Any other word ("Madrid Charles de
  -- Gaulle") is none (asked).
  -- True when the letters `letters` (upper case) are the ident of a fix, navaid or airport the navdata holds within
  -- lexicon.navaid_range_nm of an aircraft flying (world.locate, the one of that ident nearest it).
  function m:spelled_place_near(letters)
    local locate = self.world.locate
    for _, a in ipairs(locate and self.fleet or {}) do
      local plat, plon = nil, nil
      if a.lat then plat, plon = locate(letters, nil, a.lat, a.lon) end
      if plat then
        local dlat, dlon = plat - a.lat, ((plon - a.lon + 180) % 360 - 180) * math.cos(math.rad(a.lat))
        if 60 * math.sqrt(dlat * dlat + dlon * dlon) <= L.navaid_range_nm then return true end
      end
    end
    return false
  end

  -- True when the lower-case city name `word` names airport `id`: among its airports (sim:airports_of_city), the
  -- airports beside the navaids of its name (sim:airports_beside_navaids: "madrid", LEMD "BARAJAS"), or the
  -- airport lexicon.city_airports gives it ("amsterdam": EHAM "SCHIPHOL").
  function m:city_of_airport(word, id)
    local w = self.world
    local lists = { w.airports_of_city and w.airports_of_city(word) or {},
      w.airports_beside_navaids and w.airports_beside_navaids(word) or {},
      L.city_airports[word] and w.airports_named and w.airports_named(L.city_airports[word]) or {} }
    for _, list in ipairs(lists) do
      for _, x in ipairs(list) do
        if x == id then return true end
      end
    end
    return false
  end

  function m:city_before_airport(i, e, id)
    local t, locate = self.t[i - 1], self.world.user_waypoint_at
    if not (t and t.kind == "word" and t.alpha and t.raw:match("^%u%l") and not self.u:used(i - 1) and locate) then
      return false
    end
    local words = { t.text }
    for k = i, e - 1 do
      if not (self.t[k] and self.t[k].kind == "word") then return false end
      words[#words + 1] = self.t[k].text
    end
    local lat, lon = locate(id)
    return lat ~= nil and self:any_place_named(table.concat(words, " "), function() return true end, lat, lon, L.city_nm,
      true)
  end

  -- A phrase with a capitalised word beside it ("Point Reyes", "Amsterdam Schiphol") is part of a
  -- longer name: no airport is named by the phrase alone, unless "airport" follows it ("Beijing
  -- Capital airport": the word before is its city).
  -- (proper: only words typed with a capital, "Frankfurt")
  -- (nearby: `named` reads near an aircraft only)
  -- a preposition typed in lower case ("heading west along with the Speedbird") names no airport, whatever
  -- airport bears it (VEAN is "ALONG"): lexicon.accounted.prepositions as a set
  local PREPOSITIONS = {}
  for _, w in ipairs(L.accounted.prepositions) do PREPOSITIONS[w] = true end

  -- The words [b, e) read as a place's name: explained, and kept in self.place_spans ({b =, e =}; the last
  -- names the place in m:far_from_aircraft's question).
  function m:explain_place(b, e)
    self:explain(b, e)
    self.place_spans = self.place_spans or {}
    self.place_spans[#self.place_spans + 1] = { b = b, e = e }
  end

  -- True when the lower-case word at i opens a name of one or two words that an airport noun closes before e
  -- ("frankfurt airport", "san francisco airport" in a recogniser's lower case): the noun says what a capital
  -- would have.
  function m:named_airport_lower(i, e)
    return (i + 1 < e and self:word(i + 1, "@airport_nouns"))
      or (i + 2 < e and self.t[i + 1].kind == "word" and self:word(i + 2, "@airport_nouns"))
  end

  function m:airport_named_in(b, e, named, placed, proper_only, nearby)
    local function proper(k)
      local t = self.t[k]
      return k > 1 and t ~= nil and t.kind == "word" and t.raw:match("^%u%l") ~= nil and not self.u:used(k)
    end
    for i = b, math.min(e, #self.t + 1) - 1 do
      local t = self.t[i]
      -- (a capitalised word of under four letters opens a longer name only, "New Chitose": RJCC, not
      -- "CHITOSE" RJCJ with "New" left over)
      local short = #t.text < 4 and t.raw:match("^%u%l") ~= nil and i + 1 < e and proper(i + 1)
      if not self.u:used(i) and t.kind == "word" and t.alpha and (#t.text >= 4 or short) and not t.keyword and not t.filler
          and not t.number_word and not L.phonetic[t.text] and (not placed or self:word(i - 1, "@place_words"))
          and (not proper_only or t.raw:match("^%u%l") ~= nil or self:named_airport_lower(i, e))
          and not (PREPOSITIONS[t.text] and t.raw:match("^%l")) then
        local nx, nx2 = self.t[i + 1], self.t[i + 2]
        local phrases = { short and { t.text .. " " .. nx.text, i + 2 } or { t.text, i + 1 } }
        if not short and nx and i + 1 < e and nx.kind == "word" then table.insert(phrases, 1, { t.text .. " " .. nx.text, i + 2 }) end
        -- (three words: "Charles de Gaulle")
        if nx and nx2 and i + 2 < e and nx.kind == "word" and nx2.kind == "word" then
          table.insert(phrases, 1, { t.text .. " " .. nx.text .. " " .. nx2.text, i + 3 })
        end
        for _, p in ipairs(phrases) do
          local phrase, after = p[1], p[2]
          local city = self:word(after, "@airport_nouns")
          -- ("Eelde VOR", "the VOR Bogota" in the Spanish order, is the navaid, not the airport that bears its name)
          -- (self.name_after_city: a capitalised word, its city, said before the phrase; m:airport_by_name)
          self.name_after_city = proper(i - 1)
          local ids = ((proper(i - 1) and not city) or proper(after) or self:word(after, "@navaid_kinds")
              or self:word(i - 1, "@navaid_kinds")) and {}
            or named(phrase)
          self.name_after_city = nil
          -- ("Amsterdam Schiphol", "Groningen Eelde": the city before the only large or medium airport
          -- of the name near the aircraft, when the two words together name none)
          local cls = self.world.airport_class
          local with_city = nearby and #ids == 0 and proper(i - 1) and not proper(after) and after == i + 1 and cls
            and #named(self.t[i - 1].text .. " " .. phrase) == 0
          -- (a word that, with the phrase, is words of another airport's name anywhere may be no city: "Billy
          -- Bishop" before KFNT "BISHOP INTL" is also CYOS "BILLY BISHOP RGNL", or a name the navdata does not
          -- hold (Toronto's CYTZ, "CITY CENTRE"): asked, both named)
          local whole = (with_city or (city and proper(i - 1))) and self.world.airports_with_words
          local others, apart = whole and whole(self.t[i - 1].text .. " " .. phrase) or {}, false
          for _, id in ipairs(#others > 0 and named(phrase) or {}) do
            apart = true
            for _, x in ipairs(others) do apart = apart and x ~= id end
          end
          if apart then
            for _, id in ipairs(named(phrase)) do table.insert(others, 1, id) end
            self:need(string.format("Which airport is '%s': %s? Please give its ICAO code.",
              self:raw(i - 1, after), table.concat(others, " or ")))
            return nil
          end
          if with_city then
            for _, id in ipairs(named(phrase)) do
              if cls(id) == "LARGE" or cls(id) == "MEDIUM" then ids[#ids + 1] = id end
            end
            if #ids > 1 then ids = {} end  -- ("Gotham City": no airport of that city, one of several "City")
          end
          -- (a city's airline airport among several large fields found for it: lexicon.main_airports)
          local main = #ids > 1 and L.main_airports[phrase:lower()]
          for _, x in ipairs(main and ids or {}) do
            if x == main then ids = { main } break end
          end
          local id = self:one_named(ids, "airport", phrase, 4)
          if id then
            self.airport_said_at, self.airport_said_noun = i, city
            -- (a name without "airport" after it that two large airports bear, "Spartanburg": KSPA and
            -- GREENVILLE SPARTANBURG INTL, is a city's name, not one airport's)
            local with, large = not city and cls and self.world.airports_with_words, 0
            for _, a in ipairs(with and with(phrase) or {}) do large = large + (cls(a) == "LARGE" and 1 or 0) end
            self.airport_said_city = large > 1
            -- (with "airport" after it, a capitalised word before the name is its city: "Beijing Capital")
            -- (a capitalised word before a name of two or three words, its city: "Paris Charles de Gaulle", when
            -- the navdata has a place of that name within lexicon.city_nm of the airport; a name of a place elsewhere
            -- stays unexplained, asked)
            local of_city = not (city or with_city) and after > i + 1 and proper(i - 1)
              and self:city_before_airport(i, after, id)
            -- (a city said in lower case straight before the name, a recogniser's "madrid barajas": a word whose
            -- airports, sim:airports_of_city or lexicon.city_airports's, hold this one is its city)
            local low = i > b and self.t[i - 1]
            local low_city = low and low.kind == "word" and low.alpha
              and low.raw:match("^%l") ~= nil and not low.keyword and not self.u:used(i - 1)
              and self:city_of_airport(low.text, id)
            self:explain_place((((city or with_city or of_city) and proper(i - 1)) or low_city) and i - 1 or i,
              city and after + 1 or after)
            -- (the name said again, "go to Stuttgart, so Stuttgart is its destination", is the same place)
            for k = after, math.min(e, #self.t + 1) - 1 do
              if self:word(k, t.text) and not self.u:used(k) then self:explain(k, k + 1) end
            end
            return id
          end
        end
      end
    end
    return nil
  end

  -- Where an aircraft is created at `ident` (a place said as `phrase`, its name, or typed as the ident
  -- when nil): the ident, where the simulator, from the reference position it
  -- has when the command runs (after the commands emitted before), resolves it to the place meant:
  -- an airport, a user waypoint or an aircraft always; a navaid or fix typed as its ident, the one of
  -- that ident nearest the first aircraft flying (any, with none flying); one said by its name, a
  -- navaid of that name. Said by name where the simulator takes another navaid of that ident ("at
  -- Aeroparque": the N NDB nearest 0 0 is no AEROPARQUE), the one airport that bears the name and
  -- stands beside the navaid of that name (`at`: said after "at", its kind not said: SABE), else the
  -- position of the navaids of that name where they are one place ("lat lon"), else nil after asking
  -- which place is meant. An airport found by its name alone with none flying, where large
  -- airports (else medium ones) stand beside navaids of that name farther than lexicon.navaid_range_nm
  -- from it ("Santiago": LEST, and SCEL beside the SANTIAGO VOR in Chile), is asked about: nil.
  function m:creation_place(ident, phrase, at)
    local w = self.world
    if not w.locate or not ident or self:state(ident) then return ident end
    for _, name in ipairs(w.waypoints or {}) do
      if name:upper() == ident:upper() then return ident end
    end
    local lat, lon = w.locate(ident, table.concat(self.out, " ; "))
    if not lat then return ident end  -- (the command's check names what is wrong)
    local named = w.navaids_named
    if w.airport_class and w.airport_class(ident) ~= "" then
      if not phrase or #self.fleet > 0 or not w.airports_beside_navaids then return ident end
      local far = {}
      for _, id in ipairs(w.airports_beside_navaids(phrase)) do
        local alat, alon = w.locate(id)
        if id:upper() ~= ident:upper() and alat
            and math.abs(alat - lat) * 60 + math.abs((alon - lon + 180) % 360 - 180) * 60 * math.cos(math.rad(lat))
              > L.navaid_range_nm then
          far[#far + 1] = id
        end
      end
      if #far == 0 then return ident end
      return self:need(string.format("Which airport is '%s': %s, the airport of that name, or %s beside a %s "
        .. "navaid far from it? Please give the ICAO code.", phrase, ident:upper(), table.concat(far, ", "),
        phrase:upper()))
    end
    -- (within lexicon.on_airport_nm: the SPIJKERBOOR NDB and VOR, both SPY, are one place)
    local function close(lat2, lon2)
      return lat2 and math.abs(lat2 - lat) * 60 + math.abs((lon2 - lon + 180) % 360 - 180) * 60
        * math.cos(math.rad(lat)) <= L.on_airport_nm
    end
    if not phrase then
      -- (the VOR and NDB of one station, within lexicon.navaid_station_nm, are one place: BN)
      local a = self.fleet[1]
      local alat, alon
      if a then alat, alon = w.locate(ident, nil, a.lat, a.lon) end
      if not a or (alat and math.abs(alat - lat) * 60 + math.abs((alon - lon + 180) % 360 - 180) * 60
          * math.cos(math.rad(lat)) <= L.navaid_station_nm) then
        return ident
      end
      return self:need(string.format("Which %s is meant? The simulator would take the one at %s %s, not the one "
        .. "nearest %s. Please give its position.", ident:upper(), f.num(lat), f.num(lon), a.id))
    end
    if not named then return ident end
    for _, id in ipairs(named(phrase, lat, lon, L.on_airport_nm)) do
      if id:upper() == ident:upper() then return ident end
    end
    if at and w.airports_with_words and w.airports_beside_navaids then
      local bears = {}
      for _, id in ipairs(w.airports_with_words(phrase)) do bears[id] = true end
      local both = {}
      for _, id in ipairs(w.airports_beside_navaids(phrase)) do
        if bears[id] then both[#both + 1] = id end
      end
      if #both == 1 then return both[1] end
    end
    -- (the navaids of that name anywhere, where they are one place: its position, which no reference
    -- can move: "at Lambourne" in an empty scene is the LAMBOURNE VOR's latitude and longitude)
    local _, points = named(phrase, 0, 0, 1e5)
    local p = points and points[1]
    if p then
      for k = 2, #points do
        if math.abs(points[k][1] - p[1]) * 60 + math.abs((points[k][2] - p[2] + 180) % 360 - 180) * 60
            * math.cos(math.rad(p[1])) > L.on_airport_nm then
          p = nil
          break
        end
      end
      if p then return f.num(p[1]) .. " " .. f.num(p[2]) end
    end
    return self:need(string.format("Which place is '%s'? The simulator would take %s at %s %s, which is not the "
      .. "%s navaid. Please give its position or the airport's ICAO code.", phrase, ident:upper(), f.num(lat),
      f.num(lon), phrase:upper()))
  end

  -- True when `ident` (a place argument) names a fix, navaid or user waypoint that no airport of the navdata stands
  -- within lexicon.on_airport_nm of (where the simulator resolves it after the commands read so far): no airport,
  -- no aircraft, no latitude and longitude.
  function m:off_airports(ident)
    local w = self.world
    if not (w.locate and w.airport_class and w.airports_beside) or not ident:match("^%w+$") or self:state(ident)
        or w.airport_class(ident) ~= "" then
      return false
    end
    local lat, lon = w.locate(ident, table.concat(self.out, " ; "))
    return lat ~= nil and #w.airports_beside(ident, lat, lon, L.on_airport_nm) == 0
  end

  -- The airport a place name stands for where an airport is meant (a destination, an origin, where
  -- an aircraft is created): a three-letter code of a navaid (the one of that code nearest `near`
  -- {lat, lon} [deg]) beside an airport with that code after one letter ("JFK" -> KJFK), else the
  -- name itself; several such airports are asked about.
  function m:airport_meant(name, near)
    local coded, a = self.world.airports_coded, near
    if not coded or not a or not a.lat or not name:match("^%a%a%a$") then return name end
    for _, w in ipairs(self.world.waypoints or {}) do
      if w:upper() == name:upper() then return name end  -- a user waypoint of that name
    end
    return self:one_named(coded(name, a.lat, a.lon), "airport", name, 4) or name
  end

  -- True when the navaid `code` nearest `near` {lat, lon} [deg] stands farther than lexicon.on_airport_nm from
  -- the airport `airport` (the two are two places to put an aircraft, not one).
  function m:off_airport(code, airport, near)
    local locate = self.world.locate
    if not locate then return false end
    local lat, lon = locate(code, nil, near.lat, near.lon)
    local alat, alon = locate(airport)
    if not (lat and alat) then return false end
    return math.abs(alat - lat) * 60 + math.abs((alon - lon + 180) % 360 - 180) * 60 * math.cos(math.rad(lat))
      > L.on_airport_nm
  end

  -- A name said after "direct (to)" that matches nothing known: the word as
  -- spoken, or letters spelled with the phonetic alphabet. Only when there
  -- is nothing to match against.
  function m:spoken_name(b, e)
    if #self.world.waypoints > 0 then return nil end
    for _, a in ipairs(self.fleet) do if a.route and #a.route > 0 then return nil end end
    local i = b
    while i < e and (self:word(i, "@before_name") or self.u:used(i)) do i = i + 1 end
    local letters = ""
    local k = i
    while k < e and self.t[k].kind == "word" and L.phonetic[self.t[k].text] do
      letters = letters .. L.phonetic[self.t[k].text]
      k = k + 1
    end
    if #letters >= 2 then return letters end
    local t = self.t[i]
    if i < e and t.kind == "word" and t.alpha and #t.text >= 3 and not t.keyword and not t.number_word
        and not self:word(i, "@route_ordinals") then
      -- ("direct to Reagan": a word of an airport's name, "RONALD REAGAN WASHINGTON NATL", that names no place of
      -- the navdata itself is that airport's, said by a name squawk does not read as a place: asked)
      local w = self.world
      local name_e = self:name_goes_on(i, e)
        or (w.place_known and w.airports_with_words and not w.place_known(t.text:upper())
          and #w.airports_with_words(t.text) > 0 and i + 1)
      if name_e then
        return self:need(string.format("Which place is '%s'? Please give its ICAO code or ident.", self:raw(i, name_e)))
      end
      return t.text:upper()
    end
    return nil
  end

  -- The end of a place's name that the word at i opens and one or two unread words after it (before e) go on
  -- with, the words together naming a place of the navdata anywhere (an airport whose name holds them, an
  -- airport or a navaid of that name: "santa barbara", "las vegas"), a navaid kind said after them included
  -- ("las vegas ndb"); nil when the word stands alone. A place read from the word at i alone is read from part of
  -- that name.
  function m:name_goes_on(i, e)
    local w = self.world
    if not (w.airports_with_words and w.airports_named and w.navaids_named) then return nil end
    local words, found = { self.t[i].text }, nil
    for k = i + 1, math.min(e, i + 3) - 1 do
      local x = self.t[k]
      if self.u:used(k) or x.kind ~= "word" or not x.alpha or x.keyword or x.filler or x.number_word then break end
      words[#words + 1] = x.text
      local phrase = table.concat(words, " ")
      if #w.airports_with_words(phrase) > 0 or #w.airports_named(phrase) > 0 or #w.navaids_named(phrase, 0, 0, 1e5) > 0 then
        found = k + 1
      end
    end
    if found and self:word(found, "@navaid_kinds") and found < e then found = found + 1 end
    return found
  end

  -- A position said in degrees where a waypoint is meant ("direct 54 North 020 West", "after 56 North
  -- 30 West"): the named point the navdata holds at exactly that position (the NAT points "54N20",
  -- "5050N"), of several the one aircraft id's route holds. nil when [b, e) says no latitude and
  -- longitude; false, after asking, when no named point lies there or several do and the route holds
  -- none of them.
  function m:point_at(b, e, id)
    -- ("direct 55 30 North 30 West... correction, 55 North 30 West": the position said after a correction)
    local k = self:find_word(b, e, "@correction")
    while k < e do
      b, k = k + 1, self:find_word(k + 1, e, "@correction")
    end
    local qs = self:quantities(b, e)
    local said = false
    for _, q in ipairs(qs) do said = said or q.kind == "lat" end
    local lat, lon = position(qs, b, self)
    if not (said and lat and lon) then return nil end
    -- (the first latitude and longitude, which position() read; a position said after them is no part of it)
    local took = {}
    for _, q in ipairs(qs) do
      if (q.kind == "lat" or q.kind == "lon") and not took[q.kind] then took[q.kind] = self:take(q) end
    end
    local where = string.format("%s %s", f.num(lat), f.num(lon))
    local ids = self.world.waypoints_at and self.world.waypoints_at(lat, lon) or {}
    local held = {}
    for _, r in ipairs((self:state(id) or {}).route or {}) do held[r:upper()] = true end
    local on_route = {}
    for _, n in ipairs(ids) do
      if held[n:upper()] then on_route[#on_route + 1] = n end
    end
    if #on_route == 1 then return on_route[1] end
    if #ids == 1 then return ids[1] end
    if #ids == 0 then
      return self:need(string.format("No named point lies at %s. Which waypoint do you mean?", where)) or false
    end
    return self:need(string.format("Which point at %s is meant: %s?", where, table.concat(ids, " or "))) or false
  end

  -- The words said after a direct-to's word in segment s where its place goes, as said ("direct the beacon", "dct
  -- natro", "direct eleven"): from the first that is no filler, mark, "to", direct-to word or aircraft to the end of
  -- its clause or the first value after it (a value said first is named alone); nil when there is none.
  function m:unplaced_words(s)
    local valued = {}
    for _, q in ipairs(self:quantities(s.trig, s.e)) do
      for k = q.b, q.e - 1 do valued[k] = q end
    end
    local b = s.trig + 1
    while b < s.e and (self.t[b].kind == "punct" or self.t[b].filler or self:has_ref(b, b + 1, "aircraft")
        or self:word(b, "to directly direct dct straight and @then_words")) do
      b = b + 1
    end
    if b >= s.e then return nil end
    local e = valued[b] and valued[b].e or b
    while not valued[b] and e < s.e and not (self.t[e].kind == "punct" or valued[e] or self:word(e, "and @then_words")) do
      e = e + 1
    end
    while b - 1 > s.trig and self:word(b - 1, "the a an") do b = b - 1 end  -- ("the beacon")
    return self:raw(b, e)
  end

  -- "the airBaltic and the Finnair both direct EDISA": each aircraft named flies there
  function m:direct(s)
    local ids = self:acids(s)
    if #ids == 0 then return self:need("Which aircraft should fly direct? Please give its callsign.") end
    -- (self.going_direct: a city's name several navaids and its airport bear is asked, m:place_by_name)
    self.going_direct = true
    for _, id in ipairs(ids) do self:direct_one(s, id) end
    self.going_direct = nil
  end

  -- The clause adding the place gone to (waypoint ref r, named wp) to the route, said after it: a comma or "and"
  -- (with "then", "please", "also"), a verb of adding, then only "it", "this", "to", "in", "into", "on", "the",
  -- "its", "his", "her", fillers and a route noun, ending the request (thanks aside): {b, e} (its tokens), or nil
  function m:route_added_after(r, wp)
    if not r or r.name:upper() ~= wp:upper() then return nil end
    local k = r.e
    while k <= #self.t and (self.t[k].filler or self:word(k, "and then please also") or self.t[k].kind == "punct") do
      k = k + 1
    end
    local b = k
    if not self:word(k, "add append insert put include") then return nil end
    k = k + 1
    local noun = false
    while k <= #self.t and not noun do
      if self:word(k, "@route_nouns") then
        noun = true
      elseif not (self.t[k].filler or self:word(k, "it this to in into on onto the its his her their")) then
        return nil
      end
      k = k + 1
    end
    local e = k
    while k <= #self.t and (self.t[k].filler or self:word(k, "please thank thanks you very much sir")
        or self.t[k].kind == "punct") do
      k = k + 1
    end
    if not noun or k <= #self.t then return nil end
    return { b = b, e = e }
  end

  -- The open airport aircraft state `a`'s route ends at (ICAO code), or nil
  local function route_airport(self, a)
    local last = a and a.route and a.route[#a.route]
    local class = last and self.world.airport_class and self.world.airport_class(last) or ""
    return class ~= "" and class ~= "CLOSED" and last or nil
  end
  function m:direct_one(s, id)
    local a = self:state(id)
    -- "proceed to the hold at MTG", "go into the published holding over MTG": the place flown to is a hold, which
    -- squawk does not simulate; flying direct to its fix and on along the route is not what was said: asked
    local k = s.trig + 1
    while k < s.e and self:word(k, "to into the a an its published") do k = k + 1 end
    if k < s.e and self:word(k, "hold holding") then
      return self:need(string.format("squawk does not simulate holding patterns ('%s'). Should %s fly direct to its "
        .. "fix and on along its route, or is nothing to be sent?", self:raw(k, s.e), id))
    end
    -- "add TABUM to its route and send it direct there", "add SPY and then go direct to it": the
    -- waypoint this request added just before
    local added
    for c = #self.out, 1, -1 do
      added = added or self.out[c]:match("^ADDWPT " .. id:gsub("%p", "%%%0") .. " ([^%s,]+)$")
        or self.out[c]:match("^DEST " .. id:gsub("%p", "%%%0") .. " (%a+)$")  -- ("dest EHAM and direct to it")
    end
    -- "send AEA44 straight to the airport", "direct to its destination": the destination it has, else the open
    -- airport its route ends at; "direct to airport", its article dropped by a second-language speaker, too
    local dest_word = self:find_word(s.trig + 1, s.e, "airport destination")
    local dest = a and a.dest ~= "" and a.dest or route_airport(self, a)
    local to_dest = dest and dest_word < s.e and (self:word(dest_word - 1, "the its his her")
        or (self:word(dest_word - 1, "to") and dest_word - 1 > s.trig))
      and #self:refs_in(s.trig, s.e, "waypoint") == 0 and (dest_word + 1 >= s.e or self.t[dest_word + 1].kind == "punct")
      and dest
    if to_dest then self:explain(dest_word - 1, dest_word + 1) end
    local point = self:point_at(s.trig + 1, s.e, id)
    if point == false then return end
    -- "direct INKIG, correction, MALIX", "straight to INKIG... no, to MALIX, sorry, MALIX": a place said after
    -- a correction replaces the one before it
    local places = self:refs_in(s.trig, s.e, "waypoint")
    if not point and #places >= 2 and self:word_in(places[1].e, places[#places].b, "@correction no sorry wait actually mean scratch") then
      self:explain(places[1].b, places[#places].b)
      point = self:waypoint(places[#places].b, s.e, id)
    end
    -- ("vlg6fx add DOGEX then direct it": the waypoint an add said before names, when the add is read with
    -- the direct, which adds it)
    local before = self:refs_in(s.b, s.trig, "waypoint")
    local prior = before[#before]
    local told = not added and prior and #self:refs_in(s.trig, s.e, "waypoint") == 0 and self:word_in(s.trig, s.e, "there it")
      and self:word_in(math.max(s.b, prior.b - 2), prior.b, "add insert append include") and prior.name:upper()
    if told then self:explain(math.max(s.b, prior.b - 2), prior.e) end
    -- ("EZY82QT to EEL direct": the word closing the clause, the place said after "to" before it; the word
    -- itself is no place's name heard)
    -- ("EVA15 go SHAFU direct", "ANA25 to MAIKO direct go", "to ENKAS go straight": "go" before the place or
    -- after the word, in verb-final order, is the same verb)
    local closing = self:word(s.trig, "directly direct dct straight")
    local go_after = closing and self:word(s.trig + 1, "go") and s.trig + 1
    for x = closing and (go_after or s.trig) + 1 or s.e, s.e - 1 do
      closing = closing and (self.t[x].kind == "punct" or self.t[x].filler)
    end
    local to = closing and self:find_word(s.b, s.trig, "to go") or s.trig
    if self:word(to, "go") and self:word(s.trig - 1, "go") then to = self:find_word(s.b, s.trig - 1, "to") end
    local back = to < s.trig and self:has_ref(to + 1, s.trig, "waypoint") and self:waypoint(to + 1, s.trig, id)
    -- ("JNA312, KWA direct go please", "KLM12 SPY direct": the place straight before the closing word, opening the
    -- clause after its aircraft, a mark or courtesy only before it)
    if not back and closing and to == s.trig then
      local r = self:refs_in(s.b, s.trig, "waypoint")
      r = r[#r]
      local only = r ~= nil and r.e == s.trig
      for x = s.b, only and r.b - 1 or s.b - 1 do
        only = only and (self.t[x].kind == "punct" or self.t[x].filler or self:has_ref(x, x + 1, "aircraft")
          or self:word(x, "please kindly"))
      end
      back = only and self:waypoint(r.b, s.trig, id)
    end
    if back and go_after then self:explain(go_after, go_after + 1) end
    if back and self:word(s.trig - 1, "go") then self:explain(s.trig - 1, s.trig) end
    -- ("make waypoint TESTD at 0.0 105.0 then KLM12 direct there": the one waypoint this request defined before,
    -- none added; two defined stay asked)
    local defined
    for c = 1, added and 0 or #self.out do
      local name = self.out[c]:match("^DEFWPT ([^%s,]+) ")
      if name then defined = not defined and name or false end
    end
    local named_before = added or defined or nil
    -- ("add BONTI to the route of UAE787 and send him direct": nothing said after the word, fillers and marks
    -- aside, is the waypoint named before, as "direct there" is)
    -- ("... and proceed direct": the verb before the word)
    local k = s.trig + 1
    local proceed = self:word(s.trig, "proceed") and self:word(k, "direct directly dct")
    if proceed then k = k + 1 end
    while k < s.e and (self.t[k].filler or self.t[k].kind == "punct" or self:word(k, "please now")) do k = k + 1 end
    local bare = k >= s.e and (proceed or self:word(s.trig, "direct directly dct"))
    local wp = to_dest or point or told or named_before and #self:refs_in(s.trig, s.e, "waypoint") == 0
        and (bare or self:word_in(s.trig, s.e, "there it")) and named_before or back or self:waypoint(s.trig, s.e, id, true)
    -- "send it to TEBBY directly", "go to the Helsinki VOR directly": the place said after "to", before the
    -- adverb that ends the clause
    if not wp and self:word(s.trig, "directly direct") then
      local to = self:find_word(s.b, s.trig, "to")
      if to < s.trig then wp = self:waypoint(to + 1, s.trig, id) end
    end
    -- ("proceed direct": nothing said after the word, fillers, "to" and marks aside, is the route's only waypoint;
    -- a word said there that names no place, "direct DME", "direct the beacon", "direct there", is asked about by
    -- name, never read as that waypoint)
    -- ("proceed direct O'Hare" over Illinois: one word of the name of the one large airport near the aircraft that
    -- bears it, KORD "CHICAGO OHARE INTL", where no place of the route or the navdata took it; a small field's word
    -- alone stays asked, and so does the word where the request names a destination too: "go direct O'Hare, like
    -- set the destination to KORD" may say the destination twice)
    -- ("proceed direct rockford" off the RFD VOR's route: the word names a navaid near the aircraft too, asked)
    if not wp and a and a.lat and not self:word_in(1, #self.t + 1, "destination dest") then
      local port = self:airport_by_words(s.trig + 1, s.e, a, 1, false, true)
      local span = port and self.place_spans[#self.place_spans]
      local with = span and self.world.navaids_with_words
      local navaids = with and with(self:raw(span.b, span.e):lower(), a.lat, a.lon, L.navaid_range_nm) or {}
      if #navaids > 0 then
        return self:need(string.format("Which place is '%s' for %s: the navaid %s or the airport %s?",
          self:raw(span.b, span.e), id, table.concat(navaids, " or "), port))
      end
      wp = port
    end
    local said = not wp and self:unplaced_words(s)
    -- (not after "direct to" with nothing after it: a place cut off, asked)
    if not wp and not said and a and a.route and #a.route == 1 and not self:word(s.trig + 1, "to") then
      wp = a.route[1]
    end
    wp = wp or self:spoken_name(s.trig + 1, s.e)
    if not wp and said then
      return self:need(string.format("Which waypoint is '%s'? Please say its name for %s to fly direct to.", said, id))
    end
    if not wp then return self:need("Direct to which waypoint should " .. id .. " fly?") end
    -- ("send it direct jfk", its destination KJFK: the IATA code of the airport it flies to is that airport, never the
    -- navaid of the same ident beside it, unless that navaid is on its route: "add DUB ..., then direct DUB")
    local routed = false
    for _, r in ipairs(a and a.route or {}) do routed = routed or r:upper() == wp:upper() end
    for c = 1, #self.out do routed = routed or self.out[c]:match("^ADDWPT " .. id .. " " .. wp:upper() .. "$") ~= nil end
    if dest and #wp == 3 and not routed
        and (require("translate.names").iata_airports[wp:upper()] or ""):upper() == dest:upper() then
      wp, to_dest = dest, dest
    end
    -- ("direct SPY then direct EHAM", "direct SPY, descend FL200, then proceed direct PAM"): a second direct-to
    -- for the aircraft after "then" in the request would leave the first place out at once (the second DIRECT
    -- runs straight after the first); the sequence meant, the route through both or the second now, is asked. A
    -- direct-to waiting for a place or level ("then at SPY direct PAM") is the condition's.
    local thn = self:find_word(1, s.trig, "@then_words")
    if thn < s.trig and not self:word_in(thn, s.trig, "at after passing over reaching abeam once when overhead") then
      for _, line in ipairs(self.out) do
        local before = line:match("^DIRECT " .. id:gsub("%p", "%%%0") .. " (%S+)$")
        if before and before:upper() ~= wp:upper() then
          return self:need(string.format("Should %s fly direct %s and then on to %s (both in its route), or direct "
            .. "%s now, leaving %s out?", id, before, wp, wp, before))
        end
      end
    end
    -- DIRECT needs the waypoint in the route: a known aircraft whose route lacks it gets it added first
    if a then
      local in_route, has = false, {}
      for _, r in ipairs(a.route or {}) do
        if r:lower() == wp:lower() then in_route = true end
        has[r:upper()] = true
      end
      if (added and added:lower() == wp:lower()) or wp == to_dest then in_route = true end
      -- "after FYNER proceed direct PTH": from a waypoint of its route on, a new one: inserted after it
      local at = self:find_word(s.b, s.trig, "after")
      local from = at < s.trig and self:refs_in(at + 1, at + 2, "waypoint")[1]
      if from and has[from.name:upper()] and not in_route then
        self:explain(at, at + 1)
        return self:emit("ADDWPT " .. a.id .. " " .. wp .. ",,," .. from.name)
      end
      -- "go direct ENTAS after RABOL": the same said after the place, "after" and the route's waypoint ending the
      -- request (courtesy and marks aside; an instruction after it may be what waits for that waypoint: asked)
      local first = self:refs_in(s.trig, s.e, "waypoint")[1]
      local prior = not from and first and first.name:upper() == wp:upper() and self:word(first.e, "after")
        and self:refs_in(first.e + 1, first.e + 2, "waypoint")[1]
      local j, ends = prior and prior.e or #self.t + 1, #self.t + 1
      while j < ends and (self.t[j].filler or self.t[j].kind == "punct" or self:word(j, "please thank thanks you")) do
        j = j + 1
      end
      if prior and not in_route and has[prior.name:upper()] and j >= ends then
        self:explain(first.e, prior.e)
        return self:emit("ADDWPT " .. a.id .. " " .. wp .. ",,," .. prior.name:upper())
      end
      -- "fly to KRT, add to the route", "go to KRT please, put in the route": the place gone to, with a clause
      -- that adds it to the route (a verb of adding, then only "it"/"to"/"in"/"the"/... and a route noun, no
      -- place of its own) after it, is added to the route, no direct-to: BlueSky flies a route's only waypoint
      -- as it is added, and a route flown goes on as planned
      local ad = self:word(s.trig, "go fly") and self:route_added_after(self:refs_in(s.trig, s.e, "waypoint")[1], wp)
      if ad then
        self:explain(ad.b, ad.e)
        self.last_waypoint = wp:upper()  -- ("add it to the route": the add's "it", m:add_waypoint)
        if not in_route then self:emit("ADDWPT " .. a.id .. " " .. wp) end
        return
      end
      -- "go to CPA2 before CPA1": a place off the route gone to "before" a waypoint of the route (said straight
      -- after it, ending the clause) is inserted before that waypoint (ADDWPT's beforewp), flown to in turn
      local gone = self:word(s.trig, "go fly") and self:refs_in(s.trig, s.e, "waypoint")[1]
      local nxt = gone and gone.name:upper() == wp:upper() and self:word(gone.e, "before")
        and self:refs_in(gone.e + 1, gone.e + 2, "waypoint")[1]
      local k = nxt and nxt.e or s.e
      while k < s.e and (self.t[k].filler or self.t[k].kind == "punct" or self:word(k, "please thank thanks you")) do
        k = k + 1
      end
      if nxt and not in_route and has[nxt.name:upper()] and k >= s.e then
        self:explain(gone.e, nxt.e)
        return self:emit("ADDWPT " .. a.id .. " " .. wp .. ",,,," .. nxt.name:upper())
      end
      if not in_route then self:emit("ADDWPT " .. a.id .. " " .. wp) end
    elseif (self.created or {})[id:upper()] and not (added and added:lower() == wp:lower()) then
      -- ("create ARG1890 ... and route direct FDO": an aircraft created in the request has no route yet; the
      -- waypoint said straight after the direct-to's word, "to" between or not)
      local k = self:skip_fillers(self:word(s.trig + 1, "to") and s.trig + 2 or s.trig + 1)
      local r = self:refs_in(k, k + 1, "waypoint")[1]
      if r and r.b == k and r.name:upper() == wp:upper() then self:emit("ADDWPT " .. id:upper() .. " " .. wp) end
    end
    self:emit("DIRECT " .. id .. " " .. wp)
    local to = self:route_places(s.trig, s.e)[1]
    local route = a and a.route or {}
    local last = a ~= nil and (#route == 0 or route[#route]:upper() == wp:upper() or not (a.route and
      self:listed(a.route, wp)))
    if to and to.name:upper() == wp:upper() then self:route_goes_on(id, wp, to.e, #self.t + 1, last) end
    -- a level said in the same breath without its verb ("direct LIVVN ... six thousand")
    for _, q in ipairs(self:quantities(s.b, s.e)) do
      if q.b > s.trig and q.kind == "alt" and q.number.thousand then
        local ft = self:repaired(q, q.value, 0, 60000, 100)
        if ft then
          self:take(q)
          return self:emit("ALT " .. id .. " " .. f.alt(ft, false))
        end
      end
    end
  end

  -- The places named in tokens [b, e), in order: waypoint references, and
  -- user waypoints whose names read like callsigns ("TEST1"): {{name, b, e}}.
  -- True when the waypoint ref `r` is a kind of navaid said after a name, an ident or an article ("the Walda
  -- VOR, WLD", "the SIE VOR", "the VOR"): no place of its own.
  function m:navaid_kind_said(r)
    local prev = self.t[r.b - 1]
    return self:word(r.b, "@navaid_kinds") and prev ~= nil
      and (prev.raw:match("^%u%l") ~= nil or prev.raw:match("^%u[%u%d]+$") ~= nil or self:word(r.b - 1, "the a"))
  end

  function m:route_places(b, e)
    local user = {}
    for _, w in ipairs(self.world.waypoints or {}) do user[w:upper()] = true end
    local out = {}
    local k = b
    while k < math.min(e, #self.t + 1) do
      local r = self:refs_in(k, k + 1, "waypoint")[1]
      if r and self:navaid_kind_said(r) then
        k = r.e
      elseif r then
        out[#out + 1] = r
        k = r.e
      else
        if self.t[k].kind ~= "punct" and user[self.t[k].raw:upper()] then
          out[#out + 1] = { name = self.t[k].raw:upper(), b = k, e = k + 1 }
        end
        k = k + 1
      end
    end
    return out
  end

  -- The places of m:route_places in [b, e), with a place spelled in the phonetic alphabet between them, two
  -- letters or more ("via NYLON then victor mike romeo"), read as m:waypoint reads a spelling for aircraft id (a
  -- known ident, else asked): { {name, b, e} } in order, or nil when a spelling is asked about.
  function m:route_places_spelled(b, e, id)
    local named, out, k = self:route_places(b, e), {}, b
    local function word(i) return self.t[i] and self.t[i].kind == "word" and L.phonetic[self.t[i].text] end
    local n = 1
    e = math.min(e, #self.t + 1)
    while k < e do
      local r = named[n]
      if r and k >= r.b then
        out[#out + 1], k, n = r, r.e, n + 1
      elseif not self.u:used(k) and word(k) and word(k + 1) and k + 1 < e and not word(k - 1) then
        local j = k
        while j < e and (not r or j < r.b) and word(j) do j = j + 1 end
        local spelled = self:waypoint(k, j, id)
        if not spelled then return nil end
        out[#out + 1], k = { name = spelled, b = k, e = j }, j
      else
        k = k + 1
      end
    end
    return out
  end

  -- "route direct TWEED then GIRVA", "after ABENI add ELTOK, then ROKNI": places said after `from` with
  -- "then" (or a comma or "and") before each, that are the waypoints following `from` in id's route in
  -- that order, say how the route goes on; they are explained, no instruction of their own. With `last`
  -- (`from` ends the route once this request has run: "dct LANAK then TWEED"), places the route does not
  -- hold, said after it, are added after it in that order (ADDWPT).
  function m:route_goes_on(id, from, b, e, last)
    local route = (self:state(id) or {}).route or {}
    local at
    for k, w in ipairs(route) do
      if w:upper() == from:upper() then at = k end
    end
    if not at and not last then return end
    local ended = last
    for _, r in ipairs(self:route_places_spelled(b, e, id) or {}) do
      -- ("direct ALPHA, QNH 1021": a word of lexicon.not_names the route does not hold names no place)
      if self:word(r.b, "@not_names") and not self:listed(route, r.name) then return end
      local sep = r.b - 1
      -- ("then continue PAS as before", "then continue to LFSB", ", before RIPUS": the next place of the route said
      -- after joining words, or after "before")
      local k = sep
      while k >= b and (self:word(k, "then and continue continuing proceed resume to via") or (self.t[k] or {}).text == ",") do
        k = k - 1
      end
      if k < sep and (self:word(k + 1, "then and") or (self.t[k + 1] or {}).text == ",") then
        sep = k + 1
      elseif self:word(sep, "before") and (self:word(sep - 1, "then and") or (self.t[sep - 1] or {}).text == ",") then
        sep = sep - 1
      end
      if not (self:word(sep, "then and") or (self.t[sep] or {}).text == ",") then return end
      if self:word(r.e, "as") and self:word(r.e + 1, "before") then self:explain(r.e, r.e + 2) end
      if ended and not self:listed(route, r.name) then
        self:emit("ADDWPT " .. id .. " " .. r.name:upper())
      elseif not at or not route[at + 1] or route[at + 1]:upper() ~= r.name:upper() then
        return
      else
        at = at + 1
      end
      self:explain(sep, r.e)
    end
  end
  -- True when list (of names) holds name, in any case
  function m:listed(list, name)
    for _, w in ipairs(list) do
      if w:upper() == name:upper() then return true end
    end
    return false
  end

  -- the instructions whose verb ends a waypoint's constraints ("add X, then climb FL300")
  local VALUE_VERBS = { alt = true, spd = true, hdg = true, vs = true }
  -- The two places said after "between" at k ("between TRA and KLO"), when they follow each other on the route of
  -- aircraft id in that order: {first, second} (references), else nil
  local function waypoints_between(self, id, k)
    local first = self:refs_in(k + 1, k + 2, "waypoint")[1]
    local second = first and self:word(first.e, "and") and self:refs_in(first.e + 1, first.e + 2, "waypoint")[1]
    local route = second and (self:state(id) or {}).route or {}
    for i = 1, #route - 1 do
      if route[i]:upper() == first.name:upper() and route[i + 1]:upper() == second.name:upper() then
        return { first, second }
      end
    end
    return nil
  end
  function m:add_waypoint(s)
    local id = self:acid(s, "get the waypoint")
    if not id then return end
    -- ("add SPY to KLM1602 then at SPY heading 200"): a place after "then" or "and" and "at", "over", "passing" or
    -- "reaching" inside this segment, an instruction after it, is a condition on that instruction, which this
    -- segment cannot carry: asked, never dropped
    for k = s.trig + 1, s.e - 2 do
      local c = self:word(k, "then and") and self:skip_fillers(k + 1)
      local wp = c and c < s.e and self:word(c, "at over passing reaching overhead")
        and self:refs_in(c + 1, c + 2, "waypoint")[1]
      if wp and self:any_instruction_in(s.e, #self.t + 1) then
        return self:need(string.format("Should what follows '%s' wait until %s passes %s? Please add the waypoint "
          .. "first, then give that instruction on its own.", self:raw(k, wp.e), id, wp.name))
      end
    end
    local qs = self:quantities(s.b, s.e)
    -- "... after WPC" / "before WPC": ADDWPT's afterwp / beforewp
    -- (also before the verb: "after REMBI add the waypoint ESAMA")
    local at = self:find_word(s.b, s.e, "after before")
    -- ("add the point PIGOR before destination", "... before its destination": where ADDWPT puts it anyway, the
    -- route's end before the destination; the words explained, no waypoint next to it)
    local dest_at = self:word(at + 1, "the its his her their") and at + 2 or at + 1
    if at < s.e and self:word(at, "before") and self:word(dest_at, "destination dest") then
      self:explain(at, dest_at + 1)
      at = s.e
    end
    local next_to = at < s.e and self:refs_in(at + 1, at + 2, "waypoint")[1]
    -- ("insert Midhurst after Compton": the place next to it said by its one-word name)
    -- (or by two capitalised words, "after Queen Alia": the QAA VOR on its route)
    local n_said = 1
    local function capital(k) return self.t[k] and self.t[k].kind == "word" and self.t[k].raw:match("^%u%l") end
    if at + 2 < s.e and capital(at + 1) and capital(at + 2) then n_said = 2 end
    local next_name = at < s.e and not next_to and self:place_by_name(at + 1, at + 1 + n_said, self:state(id))
    if next_name then next_to = { name = next_name, b = at + 1, e = at + 1 + n_said } end
    -- ("insert DALIK between TRA and KLO": the two places next to each other on the route, the new one after the
    -- first; places apart or off the route are asked)
    local between = not next_to and self:find_word(s.b, s.e, "between")
    if between and between < s.e and self:refs_in(between + 1, between + 2, "waypoint")[1] then
      local pair = waypoints_between(self, id, between)
      if not pair then
        return self:need(string.format("Between which two waypoints next to each other on the route of %s should "
          .. "the new one go?", id))
      end
      self:explain(pair[2].b - 1, pair[2].e)
      at, next_to = between, pair[1]
    end
    -- ("after 54 North 30 West add ...": the named point at a position said in degrees after it; the
    -- position added is said apart from it)
    local said = at < s.e and not next_to and qs[1] and self:quantities(at + 1, at + 3)[1]
    if said and said.b == at + 1 then
      local lon
      for _, q in ipairs(qs) do lon = lon or (q.b > at and q.kind == "lon" and q) end
      local name = lon and self:point_at(at + 1, lon.e, id)
      if name == false then return end
      if name then
        next_to = { name = name, b = at + 1, e = lon.e }
        local rest = {}
        for _, q in ipairs(qs) do
          if q.b <= at or q.b >= lon.e then rest[#rest + 1] = q end
        end
        qs = rest
      end
    end
    local lat, lon = position(qs, s.trig, self)
    -- ("ezy73kl at 45.8 8.9 insert wpt": the position said after "at" before the verb, none after it)
    local placed = self:find_word(s.b, s.trig, "at")
    if not (lat and lon) and placed < s.trig and #self:refs_in(s.trig, s.e, "waypoint") == 0 then
      local before = {}
      for _, q in ipairs(qs) do
        if q.b > placed and q.e <= s.trig then before[#before + 1] = q end
      end
      if before[1] and before[1].b == placed + 1 then lat, lon = position(before, placed + 1, self) end
    end
    local name_e = (next_to and at > s.trig) and at or s.e
    -- ("add the Dublin VOR to Speedbird 93D's route and set Dublin airport as its destination": the place added is
    -- said before "to" and the route it joins, never a place said after it; "add, to the route of JTA61, the fix
    -- ALPHA" says it after)
    local before_to = false
    for k = s.trig + 1, name_e - 1 do
      if before_to and self:word(k, "to into onto") and self:followed_by(k, 5, "@route_nouns") then
        name_e = k
        break
      end
      before_to = before_to or (self.t[k].kind ~= "punct" and not self.t[k].filler)
    end
    local where, named
    if lat and lon then
      where = f.num(lat) .. " " .. f.num(lon)
    else
      -- "define WP9 at ... and add it to X's route": "it" is the waypoint just defined
      named = self:route_places(s.trig, name_e)[1] or self:verb_final_waypoint(s.trig)
      -- ("route via victor mike romeo then NYLON": a place spelled in the phonetic alphabet, two letters or more,
      -- before the first place named is the route's first place, read as m:waypoint reads a spelling (a known
      -- ident, else asked), never passed over)
      local upto = named and named.b or math.min(name_e, #self.t + 1)
      if named or self:word_in(s.trig, upto, "via then") then
        for k = s.trig, upto - 2 do
          if not self.u:used(k) and L.phonetic[self.t[k].text] and self.t[k].kind == "word"
              and L.phonetic[self.t[k + 1].text] and self.t[k + 1].kind == "word"
              and not (L.phonetic[(self.t[k - 1] or {}).text or ""]) then
            local e = k
            while e < upto and self.t[e].kind == "word" and L.phonetic[self.t[e].text] do e = e + 1 end
            local spelled = self:waypoint(k, e, id)
            if not spelled then return end
            named = { name = spelled, b = k, e = e }
            break
          end
        end
      end
      local it = self.last_waypoint and self:word_in(s.trig, name_e, "it")
      where = named and named.name or (it and self.last_waypoint) or self:waypoint(s.trig, name_e, id)
      -- ("ezy45hm addwpt nirsi and then lnav on": a fix's ident of five letters typed straight after TrafScript's own
      -- word ADDWPT, in one case and no English word, that the navdata holds within lexicon.navaid_range_nm of
      -- the aircraft)
      local t, here = self.t[s.trig + 1], self:state(id)
      if not where and self.t[s.trig].raw:lower() == "addwpt" and s.trig + 1 < name_e and t.kind == "word"
          and (t.raw:match("^%u%u%u%u%u$") or (t.raw:match("^%l%l%l%l%l$") and not self:known_word(s.trig + 1)))
          and not self.u:used(s.trig + 1) and self.world.place_known and here and here.lat then
        local lat, lon = self.world.place_known(t.raw:upper())
        local dlat, dlon = lat and lat - here.lat, lat and (lon - here.lon) * math.cos(math.rad(lat))
        if lat and 60 * math.sqrt(dlat * dlat + dlon * dlon) <= L.navaid_range_nm then
          where = t.raw:upper()
          self:explain(s.trig + 1, s.trig + 2)
        end
      end
      if not where then
        return self:need("Where should the waypoint for " .. id .. " be? Please give a name or a latitude and longitude.")
      end
    end
    local alt, spd
    -- "via SUGOL and ANDIK and give it 280 knots": values after "and" and a verb of their own
    -- are the next instruction's, no constraint of the waypoint
    local upto = s.e
    -- ("add KWA, and speed 250", "add SPY to the route and altitude FL200"): a value's noun opening a clause of
    -- its own after "and", with no value, "at" or "with" said for the waypoint before it, is an instruction of its
    -- own, never the waypoint's constraint ("add MANEL with FL80 and 220 knots", "at FL200 and speed 250" stay its)
    local own_b = named and named.e or s.trig + 1
    for k = own_b, s.e - 1 do
      if self:word(k, "at with") or self.t[k].kind == "number" or self.t[k].number_word then break end
      if self:word(k, "and") and self:word(k + 1, "speed spd altitude alt level fl") then
        upto = k
        break
      end
    end
    for k = (named and named.e or s.trig + 1), upto - 1 do
      local nx = self.t[k + 1]
      if self:word(k, "and") and nx and nx.kind == "word" and not nx.filler and not nx.number_word
          and not self:word(k + 1, "at with to speed spd altitude alt level fl")
          and not self:refs_in(k + 1, k + 2, "waypoint")[1] then
        upto = k
        break
      end
      -- ("add KORAK to your route, after that climb FL300": the verb of a value instruction of its own;
      -- a value's noun, "at FL300 speed 250", is the waypoint's constraint)
      if self:word(k, "@up @down turn maintain") and VALUE_VERBS[self:intent_at(k) or ""] then
        upto = k
        break
      end
    end
    -- ("add SPY, and FL200", "add SPY and then 250 knots": a level or speed with its unit straight after "and" (or
    -- "and then"), no "at" or "with" said for the waypoint before it, is its constraint or a value to fly now: asked,
    -- naming both)
    for _, q in ipairs(qs) do
      if q.b >= upto or q.b < own_b then break end
      local a = self:word(q.b - 1, "then") and q.b - 2 or q.b - 1
      if self:word(a, "and") and not self:word_in(own_b, q.b, "at with") and (q.kind == "alt" or q.kind == "speed") then
        local v = q.kind == "alt" and f.alt(q.value, q.fl) or f.int(q.value)
        local c = q.kind == "alt" and where .. " " .. v or where .. ",," .. v
        return self:need(string.format("Is '%s' the %s to cross %s at (ADDWPT %s %s), or a %s to fly now (%s %s %s)?",
          self:raw(q.b, q.e), q.kind == "alt" and "altitude" or "speed", where, id, c,
          q.kind == "alt" and "level" or "speed", q.kind == "alt" and "ALT" or "SPD", id, v))
      end
      break
    end
    local level_e  -- (the token after the level said)
    local unread   -- a value after the verb that is neither the level nor the speed ("add RESMI FL60 500")
    for _, q in ipairs(qs) do
      if q.b >= upto then break end
      local had_alt, had_spd = alt, spd
      if q.kind == "alt" and not alt then alt, level_e = f.alt(q.value, q.fl), q.e end
      if q.kind == "speed" and not spd then spd = f.int(q.value) end
      -- "add RESMI FL60 210", "add ARBEK at FL320, 280": a bare number of 100 to 400 straight after the level
      -- (a comma between or none) is the speed (FL60/210)
      local after_level = level_e ~= nil and (q.b == level_e or (q.b == level_e + 1 and self.t[level_e].text == ","))
      if q.kind == "plain" and not spd and after_level and q.value >= 100 and q.value <= 400 then
        spd = f.int(q.value)
      end
      if q.kind == "plain" and not spd and self:word(q.b - 1, "speed spd") then spd = f.int(q.value) end
      -- "at 15000 and 250 knots": a bare number of whole hundreds, 1000 to 60000, after "at" is the altitude
      if q.kind == "plain" and not alt and self:word(q.b - 1, "at") and q.value >= 1000 and q.value <= 60000
          and q.value % 100 == 0 then
        alt = f.alt(q.value, false)
      end
      if q.kind == "mach" and not spd then spd = f.mach(q.value) end
      if named and q.b >= named.e and alt == had_alt and spd == had_spd and not unread
          and (q.kind == "plain" or q.kind == "alt" or q.kind == "speed" or q.kind == "mach" or q.kind == "heading") then
        unread = q
      end
    end
    if unread then
      return self:need(string.format("I have %s to add to the route of %s. What does '%s' mean?", where, id,
        self:raw(unread.b, unread.e)))
    end
    -- ("exs12ab add MCT after rosun", MCT the waypoint after ROSUN already: a place its route holds, inserted again
    -- beside another, would be flown twice: asked)
    if next_to and self:on_route(id, where) then
      return self:need(string.format("%s is already on the route of %s. Should it be added a second time?", where, id))
    end
    if next_to then
      local after = self:word(at, "after between")
      self:explain(at, at + 1)
      if after then self:route_goes_on(id, next_to.name, math.max(at + 2, named and named.e or 0), #self.t + 1) end
      return self:emit("ADDWPT " .. id .. " " .. where .. "," .. (alt or "") .. "," .. (spd or "") .. ","
        .. (after and next_to.name or "," .. next_to.name))
    end
    local cmd = "ADDWPT " .. id .. " " .. where
    if alt then cmd = cmd .. " " .. alt end
    if spd then cmd = cmd .. (alt and " " or ",,") .. spd end  -- (an empty altitude keeps its place)
    -- ("BKP705 go to CPA2 then EXIT1, add to route" with CPA2 ending its route: the first place of a list that
    -- is already the route's last waypoint, with no value of its own, is where the list goes on from, not
    -- added a second time)
    local route = (self:state(id) or {}).route or {}
    local again = named and not alt and not spd and #route > 0 and route[#route]:upper() == where:upper()
      and #self:route_places(named.e, s.e) > 0
    -- ("add GATE1 then ALWYN" with ALWYN on the route, "add ALWYN" likewise: a place its route holds, appended
    -- with no value of its own, would be flown twice: asked)
    local function twice(name)
      return self:need(string.format("%s is already on the route of %s. Should it be added a second time?", name, id))
    end
    if named and not again and not alt and not spd and self:on_route(id, where) then return twice(where) end
    if again then self:explain(named.b, named.e) else self:emit(cmd) end
    if not named then return end
    -- "route EZY45 via TEST1 then NIK to EHAM": the next places of the route in
    -- order; the last one after "to", when an airport (four letters), is the destination
    local rest = self:route_places_spelled(named.e, s.e, id)
    if not rest then return end
    local last = named.e
    for k, r in ipairs(rest) do
      local airport = k == #rest and self:word(r.b - 1, "to into") and self:airport_meant(r.name:upper(), self:state(id))
      if airport and airport:match("^%a%a%a%a$") then
        return self:emit("DEST " .. id .. " " .. airport)
      elseif self:word(r.b - 1, "then via and to over") or (self.t[r.b - 1] or {}).text == "," or r.b == last then
        if self:on_route(id, r.name) then return twice(r.name) end
        self:emit("ADDWPT " .. id .. " " .. r.name)
        last = r.e
        -- ("GATE1 and after to EXIT3": "after to" said for "then to", Italian "e dopo a")
        if self:word(r.b - 1, "to") and self:word(r.b - 2, "after") and self:word(r.b - 3, "and") then
          self:explain(r.b - 2, r.b - 1)
          self:mark_used(r.b - 2, r.b - 1)
        end
      end
    end
    -- ("defwpt ZZ1 ... ; defwpt ZZ2 ... and give KLM1234 a route ZZ1 ZZ2": a waypoint this request defines, said
    -- next in the list, is the next place, as one the scene holds is)
    local defined = {}
    for _, c in ipairs(self.out) do
      local n = c:match("^DEFWPT (%S+)")
      if n then defined[n:upper()] = true end
    end
    while next(defined) and last < s.e do
      local d = last
      while self:word(d, "then and") or (self.t[d] and self.t[d].text == ",") do d = d + 1 end
      if not (d < s.e and defined[self.t[d].raw:upper()]) then break end
      self:explain(last, d + 1)
      self:emit("ADDWPT " .. id .. " " .. self.t[d].raw:upper())
      last = d + 1
    end
    -- ("a route via BIDAC then Bilbao": a place said by its one-word name, capitalised, after "then", "and" or
    -- a comma straight after the route's last place and ending the request, is the next place)
    local k = last
    while self:word(k, "then and") or (self.t[k] and self.t[k].text == ",") do k = k + 1 end
    local nx = self.t[k + 1]
    if k > last and k < s.e and (not nx or nx.kind == "punct") and self.t[k].kind == "word"
        and self.t[k].raw:match("^%u%l") then
      local place = self:place_by_name(k, k + 1, self:state(id))
      if place then
        self:explain(last, k + 1)
        self:emit("ADDWPT " .. id .. " " .. place)
        return
      end
    end
    -- "... and on to Boston", "then into Heathrow": an airport said by its name after the
    -- route's last place and "to"/"into" is the destination; a name that names no airport is
    -- asked about, never dropped
    -- (not "add TEST1 to the end of KLM12's route" nor "to the route": an aircraft, a route)
    local to = self:find_word(last, s.e, "to into")
    if to + 1 < s.e and #self:refs_in(to + 1, s.e, "aircraft") == 0 and #self:quantities(to + 1, s.e) == 0
        and not self:word_in(to + 1, s.e, "@route_nouns") then
      local a = self:state(id)
      local airport = (a and self:airport_by_name(to + 1, s.e, a, true)) or self:airport_by_name(to + 1, s.e)
      if airport then return self:emit("DEST " .. id .. " " .. airport) end
      -- ("route via ARTIP to SPY": a navaid's or fix's ident typed in capitals, no airport's, alone after "to", is
      -- the route's last waypoint)
      local w, ident = self.world, to + 2 == s.e and self.t[to + 1].raw:match("^%u[%u%d]+$")
      if ident and w.place_known and w.airport_class and w.place_known(ident) and w.airport_class(ident) == "" then
        self:explain(to, s.e)
        return self:emit("ADDWPT " .. id .. " " .. ident)
      end
      return self:need(string.format("Which airport is '%s' (the destination of %s)? Please give its ICAO code.",
        self:raw(to + 1, s.e), id))
    end
  end

  -- The name given to a new waypoint or shape in tokens [b, e): a name that is
  -- no flying aircraft ("EXIT1" reads like an id), else the word after
  -- "named"/"called"; nil when none.
  local function new_name(self, b, e)
    -- "name MXPCTR", "call it MILROM", "name it REF1", "named CTR": the name given in words, before any place
    -- said by its name ("circle around LIMC, name MXPCTR, ...": LIMC is where it is, no name)
    for k = b, e - 2 do
      local at = (self:word(k, "@named") or (self:word(k, "name call") and not self:word(k - 1, "the its a")))
        and k + 1
      if at and self:word(at, "it") then at = at + 1 elseif self:word(k, "call") then at = nil end
      if at and at < e and self.t[at].kind == "word" and self.t[at].raw:match("^%w+$") then
        -- (the name read as it was said, a place's name too: "circle name JEJU make" names no place)
        self:explain(k, at + 1)
        self:mark_used(at, at + 1)
        return self.t[at].raw:upper()
      end
    end
    local w = self:refs_in(b, e, "waypoint")
    if #w > 0 then return w[1].name end
    local a = self:refs_in(b, e, "aircraft")
    if #a > 0 and not a[1].exists then return a[1].name:upper() end
    -- ("box tma 51.5 3.5 53 6", "circle ctr around 52.3 4.76 r 25nm": a new name straight after the shape's word)
    for k = b, e - 2 do
      if self:word(k, "box circle polygon poly line") and self:shape_name_at(k + 1) then
        self:mark_used(k + 1, k + 2)
        return self.t[k + 1].raw:upper()
      end
    end
    local k = self:find_word(b, e, "@named")
    if k + 1 < e and self.t[k + 1].kind == "word" then return self.t[k + 1].raw:upper() end
    return nil
  end

  -- Corner or centre points in order: latitude and longitude pairs ("52.5 north 5.0 east", "51.5, 3.5").
  local function points(self, b, e)
    local out, lat = {}, nil
    local qs = self:quantities(b, e)
    local k = 1
    while k <= #qs do
      local q, nx = qs[k], qs[k + 1]
      if q.kind == "lat" then
        lat = q.value
      elseif q.kind == "lon" and lat then
        out[#out + 1] = { lat, q.value }
        lat = nil
      elseif q.kind == "plain" and nx and nx.kind == "plain" and nx.b - q.e <= 1 and math.abs(q.value) <= 90
          and math.abs(nx.value) <= 180 then
        out[#out + 1] = { q.value, nx.value, last = nx }
        k = k + 1
      end
      k = k + 1
    end
    return out
  end

  -- Places said by their name in s that lie at one of the points `p` given in figures (within 0.1 degree:
  -- "line from LIML to LIRF, call it MILROM: 45.445 9.277 41.804 12.251"): the points' names, explained
  local function places_at_points(self, s, p)
    for _, r in ipairs(self:refs_in(s.b, s.e, "waypoint")) do
      local lat, lon
      if self.world.user_waypoint_at then lat, lon = self.world.user_waypoint_at(r.name) end
      for _, c in ipairs(lat and p or {}) do
        if math.abs(c[1] - lat) <= 0.1 and math.abs(c[2] - lon) <= 0.1 then
          self:explain(r.b, r.e)
          break
        end
      end
    end
  end

  -- A new shape's name and its points ("lat lon" strings) in s when `fits(#points)`; else asks `question`
  -- and gives nil.
  local function named_points(self, s, fits, question)
    local name, p = new_name(self, s.b, s.e), points(self, s.b, s.e)
    if not name or not fits(#p) then return self:need(question) end
    places_at_points(self, s, p)
    local corners = {}
    for _, c in ipairs(p) do corners[#corners + 1] = f.num(c[1]) .. " " .. f.num(c[2]) end
    return name, table.concat(corners, " ")
  end
  local function two(n) return n == 2 end

  -- A shape's top and bottom, said as two levels or as one level and the surface ("from the surface up
  -- to FL195"): " top bottom", "" when none is said, or nil after asking (one level alone)
  local SURFACE = "surface ground sfc gnd sea"
  local function shape_levels(self, s, name)
    local levels = {}
    for _, q in ipairs(self:quantities(s.b, s.e)) do
      if q.kind == "alt" then levels[#levels + 1] = q end
    end
    if #levels == 1 and self:word_in(s.b, s.e, SURFACE) then
      levels[2] = { value = 0 }
      local k = self:find_word(s.b, s.e, SURFACE)
      self:explain(k, k + 1)
    end
    if #levels == 2 then
      local hi, lo = levels[1], levels[2]
      if lo.value > hi.value then hi, lo = lo, hi end
      return " " .. f.alt(hi.value, hi.fl) .. " " .. f.alt(lo.value, lo.fl)
    elseif #levels > 0 then
      return self:need("Between which two levels should " .. name .. " lie?")
    end
    return ""
  end

  -- "CIRCLE name lat lon radius [top bottom]": "a circle named CTR around 52.3, 4.76 with a 20 nautical
  -- mile radius", "... radius 30 NM, from the surface up to FL195"
  function m:circle(s)
    local name = new_name(self, s.b, s.e)
    local p = points(self, s.b, s.e)[1]
    local radius
    for _, q in ipairs(self:quantities(s.b, s.e)) do
      if q.kind == "dist" or (q.kind == "plain" and p and q.b > (p.last and p.last.e or q.b) ) then radius = radius or q.value end
    end
    if not name or not p or not radius then
      return self:need("To define the circle I need its name, centre (latitude and longitude) and radius in nautical miles.")
    end
    places_at_points(self, s, { p })
    local levels = shape_levels(self, s, "circle " .. name)
    if not levels then return end
    self:emit(string.format("CIRCLE %s %s %s %s%s", name, f.num(p[1]), f.num(p[2]), f.num(radius), levels))
    self.last_shape = name
  end

  -- "PERF OPENAP" / "PERF CLASS": the performance model named; asked when none or both are
  function m:performance(s)
    local model
    for k = 1, #self.t do
      local named = nil  -- (a hyphenated word by its parts: "class-based")
      for part in (self.t[k].kind == "word" and self.t[k].text or ""):gmatch("[^%-]+") do
        named = named or L.perf_models[part]
      end
      if named then
        if model and model ~= named then
          return self:need("Which performance model should I use: OpenAP or the class model?")
        end
        model = named
      end
    end
    if not model then
      if self:asks_setting() then return self:emit("PERF") end
      return self:need("Which performance model should I use: OpenAP or the class model?")
    end
    self:emit("PERF " .. model)
  end

  -- The place a wind is at, said by its name or code after a place word ("at Salzburg", "over KPT",
  -- "at Munich airport", "overhead BUB"): the ident (WIND and GETWIND take a place for lat, lon), or nil
  local function wind_place(self, s)
    for k = s.b, s.e - 1 do
      local nx = self.t[k + 1]
      -- ("wind from 320 with 25 knots in Lisbon": "in" before a place's name, as Spanish and Portuguese say "en")
      if self:word(k, "at over overhead near around above in") and nx and nx.kind == "word" then
        -- ("at point MK1", "at the waypoint MK1": the place's noun between, the place after it; the noun may be
        -- blanked already, G:condition_grammar_words)
        local a = k + (self:word(k + 1, "the") and 1 or 0)
        local noun = self:word(a + 1, "point waypoint fix") or (self.t[a + 1] and self.t[a + 1].filler)
        if noun and self:refs_in(a + 2, a + 3, "waypoint")[1] then k = a + 1 end
        local r = self:refs_in(k + 1, k + 2, "waypoint")[1]
        if r and not self:word(r.b, "@navaid_kinds") then return r.name:upper() end
        local id = self:place_by_name(k + 1, math.min(s.e, k + 4))
        -- ("over Dulles": a distinctive part of a nearby airport's name, as a destination is read)
        for _, a in ipairs(id and {} or self.fleet) do id = id or self:airport_by_words(k + 1, math.min(s.e, k + 4), a) end
        if id then return id end
      end
    end
    -- ("put jeddah wind 310 at 15 kts", "the Jeddah wind": a place's one-word name straight before "wind")
    local b = s.trig - (self:word(s.trig - 1, "'s") and 2 or 1)
    if b >= s.b and self.t[b].kind == "word" and not self:word(b, "the a set put make add @on @off") then
      return self:place_by_name(b, b + 1)
    end
    return nil
  end

  -- "GETWIND lat lon [alt]": the wind at a position (and level), shown
  function m:get_wind(s)
    local p = points(self, s.b, s.e)
    local place = #p == 0 and wind_place(self, s)
    if #p ~= 1 and not place then return self:need("Where should I show the wind? Please give a latitude and longitude.") end
    local cmd = "GETWIND " .. (place or (f.num(p[1][1]) .. " " .. f.num(p[1][2])))
    for _, q in ipairs(self:quantities(s.b, s.e)) do
      if q.kind == "alt" then
        cmd = cmd .. " " .. f.alt(self:take(q).value, q.fl)
        break
      end
    end
    self:emit(cmd)
  end

  -- "BOX name lat lon lat lon [top bottom]": two corners, and the levels between which it lies
  function m:box(s)
    local name, corners = named_points(self, s, two,
      "To define the box I need its name and two corners (latitude and longitude each).")
    if not name then return end
    local levels = shape_levels(self, s, "box " .. name)
    if not levels then return end
    self:emit("BOX " .. name .. " " .. corners .. levels)
    self.last_shape = name
  end

  -- "POLY name lat lon lat lon lat lon ...": a polygon of three corners or more ("Polygon LTMA: 51.2 -1.0,
  -- 51.9 -1.0, 51.9 0.8, 51.2 0.8"); POLYALT when its top and bottom are said
  function m:polygon(s)
    local name, corners = named_points(self, s, function(n) return n >= 3 end,
      "To define the polygon I need its name and three corners or more (latitude and longitude each).")
    if not name then return end
    local levels = shape_levels(self, s, "polygon " .. name)
    if not levels then return end
    self:emit((levels == "" and "POLY " .. name or "POLYALT " .. name .. levels) .. " " .. corners)
    self.last_shape = name
  end

  -- "LINE name lat lon lat lon": "a reference line REF1 from 55.68 -3.27 to 56.12 -3.20" (drawn only)
  function m:line(s)
    local name, ends = named_points(self, s, two,
      "To draw the line I need its name and its two ends (latitude and longitude each).")
    if name then self:emit("LINE " .. name .. " " .. ends) end
  end

  -- "MCRE n [type [alt [spd [dest]]]]": random traffic; a type is given only when it is a known one
  -- (a plural like "A320s" the lexer took for a callsign is asked about)
  function m:random_traffic(s)
    local n, alt, spd
    -- ("seed 42 then 15 random ac": the count just before "random", in the segment before)
    local from = s.b
    for _, q in ipairs(self:word(s.trig, "random") and self:quantities(math.max(1, s.trig - 2), s.trig) or {}) do
      if q.kind == "plain" and q.e == s.trig and not self.taken[q.b] then from = math.min(from, q.b) end
    end
    for _, q in ipairs(self:quantities(from, s.e)) do
      if q.kind == "plain" and not n and q.value >= 1 and q.value <= 500 and q.value % 1 == 0
          and not self:word(q.b - 1, "speed spd") then
        n = self:take(q)
      end
      if q.kind == "alt" and not alt then alt = self:take(q) end
      -- ("at 4500 and 100 knots": after the count, a bare number of whole hundreds from 1000 to 60000 said
      -- after "at" is the altitude [ft], as in a creation)
      if not alt and n and q ~= n and q.kind == "plain" and self:word(q.b - 1, "at") and q.value >= 1000
          and q.value <= 60000 and q.value % 100 == 0 then
        alt = self:take(q)
      end
      -- "speed 280", "280 kts": MCRE's speed [kt]
      if not spd and (q.kind == "speed" or (q.kind == "plain" and n and q ~= n and self:word(q.b - 1, "speed spd"))) then
        spd = self:take(q)
      end
    end
    -- ("12 random aircraft" with one aircraft flying: the count the callsign matcher read as its flight number;
    -- "add ten random aircraft" over navdata that holds a fix TEN: the count read as a waypoint, before "random")
    local function count_at(x)
      local t = self.t[x]
      local v = t and (t.kind == "number" or t.number_word) and t.num
      return (v and v > 0) and v or (t and self.below_hundred[(t.raw or ""):lower()])
    end
    local k = self:word(s.trig - 1, "@more") and s.trig - 2 or s.trig - 1
    local r = self:find_word(s.trig + 1, s.e, "random")
    if not n and not count_at(k) and r < s.e and r > s.trig + 1 then k = self:word(r - 1, "@more") and r - 2 or r - 1 end
    local counted = not n and count_at(k)
    if counted and counted >= 1 and counted <= 500 and counted % 1 == 0 then
      n = { value = counted, b = k }
      self:explain(k, k + 1)
      self:mark_used(k, k + 1)
    end
    -- ("create minus three random aircraft": a count said negative is no count)
    if not n or (n.b and self:word(n.b - 1, "minus negative")) then
      return self:need("How many random aircraft should I create?")
    end
    -- ("spawn 2 acft head-on @FL300, 10nm apart", "create 4 aircraft converging at FL300"): an encounter's
    -- geometry said for them is none MCRE sets (it places random aircraft anywhere): asked, never dropped
    -- (the segment and the few words after it: "..., 10nm apart"; "head on" is two words)
    for k = s.b, math.min(s.e + 3, #self.t) do
      local w = (self.t[k].raw or self.t[k].text or ""):lower()
      local nx = self.t[k + 1] and (self.t[k + 1].raw or ""):lower()
      if L.random_geometry_words[w] or (w == "head" and nx == "on") then
        return self:need(string.format("Random aircraft (MCRE) are placed anywhere, not '%s': should I create each "
          .. "one with its position and heading (CRE), or random traffic with no geometry?",
          w == "head" and "head on" or self.t[k].raw or w))
      end
    end
    local types = self:refs_in(s.b, s.e, "type")
    -- ("5 random 737s", "ten 787 aircraft"): a family flown in several common variants names no one type, as
    -- in a creation; a word with digits that is no type read ("foo-800s") is asked about, never dropped
    for k = s.b, s.e - 1 do
      local t = self.t[k]
      if #types == 0 and t.kind == "number" and not self.u:used(k) then
        for _, fam in ipairs(L.variant_families) do
          if t.text == fam and not select(2, ask_variant(self, fam)) then return end
        end
      end
      if t.kind == "word" and t.raw:find("%d") and not self.u:used(k) and not self:has_ref(k, k + 1, "type")
          and not self:has_ref(k, k + 1, "aircraft") and not self:has_ref(k, k + 1, "waypoint") then
        return self:need(string.format("Which aircraft type should the random aircraft be? I heard '%s'; "
          .. "please give its ICAO designator.", t.raw))
      end
    end
    local named = 0
    for _, r in ipairs(self:refs_in(s.b, s.e, "aircraft")) do if r.b ~= k or not counted then named = named + 1 end end
    if named > 0 then
      return self:need("Which aircraft type should the random aircraft be? Please give its ICAO designator.")
    end
    -- "all going to Schiphol", "all inbound Barcelona": MCRE's destination (an airport or waypoint said after
    -- "to" or "inbound")
    -- ("all with destination Zurich", "destination LSZH", "dest EHAM": the place after "destination")
    local to = self:find_word(s.trig, s.e, "to inbound destination dest")
    if self:word(to, "inbound") and self:word(to + 1, "to for") then to = to + 1 end
    -- ("all heading for Fiumicino", "bound for LIRF": "for" after a verb of going)
    local going = self:find_word(s.trig, s.e, "heading headed bound going destined")
    if to == s.e and self:word(going + 1, "for") then
      to = going + 1
      self:explain(going, going + 1)
    end
    -- (an airport by its name before a navaid of that name: "all going to Barajas" is LEMD, not the BRA VOR)
    local dest = to < s.e and self.fleet[1] and self:airport_by_name(to + 1, math.min(s.e, to + 3), self.fleet[1], true)
    dest = dest or to < s.e and (self:refs_in(to + 1, to + 2, "waypoint")[1] or {}).name
    if to < s.e and not dest then dest = self:place_by_name(to + 1, math.min(s.e, to + 3), self.fleet[1]) end
    -- ("all with Schiphol as destination", "EHAM as their destination": the place said before "as" and the noun)
    local as = self:find_word(s.trig, s.e, "as")
    local noun = self:word(as + 1, "the their its") and as + 2 or as + 1
    if not dest and as < s.e and as > s.trig + 1 and self:word(noun, "destination") then
      dest = (self:refs_in(as - 1, as, "waypoint")[1] or {}).name or self:typed_airport_code(as - 1)
      for b = as - 1, math.max(s.trig + 1, as - 3), -1 do
        dest = dest or self:place_by_name(b, as, self.fleet[1])
      end
      if not dest then
        return self:need(string.format("Where should the random aircraft fly to? I heard '%s'.", self.t[as - 1].raw))
      end
      self:explain(as, noun + 1)
      to = s.e
    end
    -- ("spawn 5 random acft to eham": an airport's code typed in lower case)
    if to < s.e and not dest and self:typed_airport_code(to + 1) then
      dest = self:typed_airport_code(to + 1)
      self:mark_used(to + 1, to + 2)
      self:explain(to, to + 2)
    end
    -- (a word squawk does not know said after "to", naming no airport or waypoint, one or two words ending the
    -- instruction, is a place asked about, never dropped: MCRE takes the segment's words; "to fill the sky",
    -- "to serve as background traffic" are a purpose)
    if to < s.e and not dest and self:word(to, "to") and self.t[to + 1] and self.t[to + 1].kind == "word"
        and not self:known_word(to + 1) and self:words_said(to + 1, s.e) <= 2 then
      return self:need(string.format("Where should the random aircraft fly to? I heard '%s'.", self:raw(to + 1, s.e)))
    end
    -- (a place after a verb of going that names no airport or waypoint is asked about, never dropped)
    local k = to < s.e and not dest and (self:word(to - 1, "going heading headed bound flying inbound all")
      or self:word(to, "destination"))
      and self:skip_fillers(to + 1)
    if k and k < s.e and self:word(to, "destination") then
      return self:need(string.format("Where should the random aircraft fly to? I heard '%s'.", self:raw(k, s.e)))
    end
    if k and k < s.e and self.t[k].kind == "word" and not self:word(k, "be") then
      return self:need(string.format("Where should the random aircraft fly to? I heard '%s'.", self:raw(k, s.e)))
    end
    local cmd = "MCRE " .. f.int(n.value)
    if #types > 0 or alt or spd or dest then cmd = cmd .. " " .. (types[1] and types[1].name or "*") end
    if alt or spd or dest then cmd = cmd .. " " .. (alt and f.alt(alt.value, alt.fl) or "*") end
    if spd or dest then cmd = cmd .. " " .. (spd and f.int(spd.value) or "*") end
    if dest then cmd = cmd .. " " .. dest end
    self:emit(cmd)
  end

  -- "AREA OFF", "AREA lat lon lat lon", "AREA shape" (one just defined: "make it the deletion area")
  function m:area(s)
    -- (the aircraft leaving it deleted, "delete acft leaving box 51 3 53 6.5": the area set, its words read)
    local leaving = self:word(s.trig, "leaving leave leaves exiting exit exits")
    if self:on_off(s) == 0 or (self:word_in(1, s.trig, "delete remove") and not leaving) then return self:emit("AREA OFF") end
    local p = points(self, s.b, s.e)
    if leaving and #p == 2 then
      for k = 1, s.e - 1 do
        if self:word(k, "delete del remove acft aircraft traffic all any that which the box area") then self:explain(k, k + 1) end
      end
    end
    if #p == 2 then
      return self:emit(string.format("AREA %s %s %s %s", f.num(p[1][1]), f.num(p[1][2]), f.num(p[2][1]), f.num(p[2][2])))
    end
    if #p == 0 and self.last_shape then return self:emit("AREA " .. self.last_shape) end
    -- "Use SECT1 as the deletion area", "the CPHTMA circle as experiment area": the one name said is a
    -- shape defined before (AREA refuses a name no shape has: the request is then asked about)
    local named = {}
    for _, r in ipairs(self.refs) do
      if r.kind == "waypoint" or (r.kind == "aircraft" and not r.exists) then named[#named + 1] = r end
    end
    if #p == 0 and #named == 1 then
      self:mark_used(named[1].b, named[1].e)
      return self:emit("AREA " .. self:raw(named[1].b, named[1].e):upper())
    end
    self:need("Which shape, or which two corners (latitude and longitude each), should the deletion area be?")
  end

  -- DEFWPT name lat lon DELETE: a user waypoint undefined, at the position it was defined at
  function m:forget_waypoint(s)
    local w = self:refs_in(s.trig + 1, s.e, "waypoint")[1]
    local lat, lon
    if w and self.world.user_waypoint_at then lat, lon = self.world.user_waypoint_at(w.name) end
    if not lat then return self:need("Which waypoint defined for this run should I delete?") end
    self:mark_used(w.b, w.e)
    self:emit(string.format("DEFWPT %s %s %s DELETE", w.name:upper(), f.num(lat), f.num(lon)))
  end

  function m:define_waypoint(s)
    -- its type, said as what it is ("as a fix", "type VOR", "make it a FIX": never its name); "define
    -- a fix GOLF" names no type
    local kind, kind_at = "", nil
    for k = s.b, s.e - 1 do
      local t = self.t[k]
      local wt = t.kind == "word" and L.waypoint_types[t.text]
      -- "make it a fix", "it is a fix", "which is a fix"
      local make_it = self:word(k - 1, "a an") and (self:word(k - 2, "it") and self:word(k - 3, "make")
        or self:word(k - 2, "is"))
      if wt and (make_it or self:preceded_by(k, 2, "as type")) then
        kind, kind_at = " " .. wt, k
        self:explain(k, k + 1)
      end
    end
    -- "define A1 at 52.1, 4.1 and A2 at 52.2, 4.4": one waypoint per name, each with the point after it
    local names = {}
    for _, r in ipairs(self.refs) do
      if r.b >= s.b and r.b < s.e and r.b ~= kind_at and (r.kind == "waypoint" or (r.kind == "aircraft" and not r.exists)) then
        names[#names + 1] = r
      end
    end
    if #names > 1 then
      for k, r in ipairs(names) do
        local p = points(self, r.e, names[k + 1] and names[k + 1].b or s.e)
        if #p ~= 1 then
          return self:need("Where is waypoint " .. r.name:upper() .. "? Please give a latitude and longitude.")
        end
      end
      for k, r in ipairs(names) do
        local p = points(self, r.e, names[k + 1] and names[k + 1].b or s.e)[1]
        self:emit("DEFWPT " .. r.name:upper() .. " " .. f.num(p[1]) .. " " .. f.num(p[2]))
        self.last_waypoint = r.name:upper()
      end
      return
    end
    local name
    for _, r in ipairs(self:refs_in(s.b, s.e, "waypoint")) do
      if not name and r.b ~= kind_at then name = r.name end
    end
    if not name then
      local a = self:refs_in(s.b, s.e, "aircraft")  -- "EXIT1" reads like an id
      if #a > 0 and not a[1].exists then name = a[1].name:upper() end
    end
    -- (a name's digits said as words: "tango one", "roma two")
    local DIGITS = L.digit_words
    if not name then
      -- ("define waypoint tango one at ...", "a fix named whiskey two five at ...", "make new point tango five at
      -- ..."): phonetic letters then one to three spoken digits straight after the noun ("point" too) or "named",
      -- then "at" or the position, are the name's letters and digits (T1, W25, T5)
      for k = s.trig, s.e - 2 do
        if not name and (self:word(k, "@waypoint_nouns point") or self:word(k, "@named")) then
          local letters, digits, j = "", "", k + 1
          while j < s.e and self.t[j].kind == "word" and L.phonetic[self.t[j].text] do
            letters, j = letters .. L.phonetic[self.t[j].text], j + 1
          end
          while j < s.e and #digits < 4 and (DIGITS[self.t[j].text]
              or (self.t[j].kind == "number" and self.t[j].text:match("^%d$"))) do
            digits, j = digits .. (DIGITS[self.t[j].text] or self.t[j].text), j + 1
          end
          if #letters >= 1 and #digits >= 1 and #digits <= 3 and j < s.e
              and (self:word(j, "at") or #self:quantities(j, j + 1) > 0) and #self:quantities(j, s.e) >= 2 then
            name = letters .. digits
            self:mark_used(k + 1, j)
            self:explain(k + 1, j)
          end
        end
      end
    end
    if not name then
      local k = self:find_word(s.b, s.e, "@named")
      -- (a name spelled in the phonetic alphabet, two letters or more, is its letters: "named kilo alpha romeo
      -- uniform" is KARU, never KILO with the rest dropped)
      local letters, j = "", k + 1
      while j < s.e and self.t[j].kind == "word" and L.phonetic[self.t[j].text] do
        letters, j = letters .. L.phonetic[self.t[j].text], j + 1
      end
      if #letters >= 2 then
        name = letters
        self:explain(k + 1, j)
      elseif k + 1 < s.e and self.t[k + 1].kind == "word" then
        -- ("called irish one at 54 north ...": the word's spoken digits after it, before "at" or the position,
        -- are the name's, IRISH1)
        local digits, j = "", k + 2
        while j < s.e and #digits < 4 and DIGITS[self.t[j].text] do digits, j = digits .. DIGITS[self.t[j].text], j + 1 end
        name = self.t[k + 1].raw:upper()
        if #digits >= 1 and #digits <= 3 and (self:word(j, "at") or (self:quantities(j, s.e)[1] or {}).b == j) then
          name = name .. digits
          self:mark_used(k + 2, j)
          self:explain(k + 2, j)
        end
      end
    end
    if not name then
      -- "define waypoint DELTA at ...", "define a fix GOLF at ...": a name typed in capitals after the
      -- noun or the verb, also one that is a phonetic word; after "point", or set off by commas ("another
      -- point, LION, at ..."), only straight before "at" or the position (a name typed in capitals that is also
      -- an airline's, LION, REX, which the reference reader never takes for a place)
      for k = s.trig, s.e - 1 do
        if k == s.trig or self:word(k, "@waypoint_nouns point") then
          local j = self:skip_fillers(k + 1)
          local set_off = self.t[j] and self.t[j].text == ","
          if set_off then j = self:skip_fillers(j + 1) end
          local n, a = self.t[j], j + 1
          if self.t[a] and self.t[a].text == "," then a = a + 1 end
          local placed = self:word(a, "at") or (self:quantities(a, a + 1)[1] or {}).b == a
          -- (an English word in capitals straight before "at" or the position is the name too: "define FINAL at ...")
          if n and n.kind == "word" and n.raw:match("^%u[%u%d]+$") and (not n.keyword or placed)
              and (placed or not (set_off or self:word(k, "point"))) then
            name = n.raw
            break
          end
        end
      end
    end
    if not name then
      -- ("make a fix delft at 52.01, 4.36": in lower case, a word no English squawk knows straight after the noun and
      -- straight before "at" and the position)
      -- ("def wpt goalc 52.0 4.6", "define goalc at 51.8 4.0": straight after the noun or the verb "define",
      -- before "at" or straight before the position's first number)
      -- (its digits said as words after it and before "at": "a waypoint roma two at ...", ROMA2)
      for k = s.trig, s.e - 2 do
        local n = self.t[k + 1]
        local digits, j = "", k + 2
        while j < s.e and #digits < 3 and (DIGITS[self.t[j].text]
            or (self.t[j].kind == "number" and self.t[j].text:match("^%d$"))) do
          digits, j = digits .. (DIGITS[self.t[j].text] or self.t[j].text), j + 1
        end
        if digits == "" or not self:word(j, "at") then digits, j = "", k + 2 end
        local pos = self:word(j, "at") and j + 1 or j
        if (self:word(k, "@waypoint_nouns") or (k == s.trig and self:word(k, "define defwpt")))
            and n.kind == "word" and n.raw:match("^%a[%a%d]+$") and #n.raw <= 10
            and not n.keyword and not self:known_word(k + 1)
            and (self:quantities(pos, s.e)[1] or {}).b == pos and #self:quantities(pos, s.e) >= 2 then
          name = n.raw:upper() .. digits
          self:explain(k + 1, j)
          if digits ~= "" then self:mark_used(k + 2, j) end
          break
        end
      end
    end
    -- (a position corrected, "at 34.5 S 58.8 W, no, at -34.50 -58.83": the one after the last correction)
    local from = s.b
    for k = s.trig, s.e - 1 do
      if self:word(k, "@correction") and #self:quantities(k + 1, s.e) >= 2 then from = k + 1 end
    end
    local lat, lon = position(self:quantities(from, s.e), math.max(s.trig, from), self)
    -- ("the point EXP1, which is at 35 north 139.6 east. Please make this point first": the point said before,
    -- its name and position, when the slot names neither)
    if not name and self:word(s.trig + 1, "this that") and self:word(s.trig + 2, "point waypoint fix") then
      local p = self:point_said_before(s.trig)
      local qs = p and self:quantities(p.at, p.at + 8) or {}
      local la, lo = position(qs, p and p.at - 1 or s.trig, self)
      if p and la and lo then
        name, lat, lon = p.name, la, lo
        self:mark_used(p.b, p.e)
        for _, q in ipairs(qs) do
          if q.kind == "lat" or q.kind == "lon" or q.kind == "plain" then self:mark_used(q.b, q.e) end
        end
        self:explain(s.trig + 1, s.trig + 3)
      end
    end
    if not name then return self:need("What should the waypoint be called, and where is it?") end
    if not lat or not lon then return self:need("Where is waypoint " .. name .. "? Please give a latitude and longitude.") end
    self:emit("DEFWPT " .. name .. " " .. f.num(lat) .. " " .. f.num(lon) .. kind)
    self.last_waypoint = name
    -- ("JAL316, define waypoint XP9 at 35.1 139.7 and add it to the route": the one aircraft that flies named as the
    -- request's addressee before the verb is the subject the instructions after it carry)
    local named = {}
    for _, r in ipairs(self.subject and {} or self:refs_in(1, s.trig, "aircraft")) do
      if r.exists and not self:as_context(r.b) then named[r.name:upper()] = r.name end
    end
    local one, n = nil, 0
    for _, id in pairs(named) do one, n = id, n + 1 end
    if n == 1 then self.subject, self.subjects = one, { one } end
  end

  function m:delete_waypoint(s)
    local id = self:acid(s, "lose the waypoint")
    if not id then return end
    -- ("SEREN delete from its route": a waypoint of the scene said before the verb and none after it is the one
    -- meant; the words after the verb are not searched for a sound-alike)
    -- ("skip APDAK, take it out of the route", "delete ARTIP, remove it from the route": "it", "that" or "this"
    -- straight after the verb (or its particle), when this request removed one waypoint of this aircraft's route
    -- before, is that one said again: removed once, cycle 65)
    local p = self:word(s.trig + 1, "out off") and s.trig + 2 or s.trig + 1
    if self:word(p, "it that this") and #self:refs_in(s.trig + 1, s.e, "waypoint") == 0 then
      local before
      for _, c in ipairs(self.out) do
        local who, name = c:match("^DELWPT (%S+) (%S+)$")
        if who == id then before = before == nil and name or false end
      end
      if before then
        self:explain(s.trig, s.e)
        return
      end
    end
    local said_before = s.b < s.trig and #self:refs_in(s.trig + 1, s.e, "waypoint") == 0
      and self:waypoint(s.b, s.trig, id)
    local point
    if not said_before then point = self:point_at(s.trig + 1, s.e, id) end
    if point == false then return end
    -- ("waypoint LOTUS delete": the waypoint said before the verb, in verb-final order)
    local wp = said_before or point or self:waypoint(s.trig, s.e, id) or (s.b < s.trig and self:waypoint(s.b, s.trig, id))
    if not wp then return self:need("Which waypoint should I remove from the route of " .. id .. "?") end
    self:emit("DELWPT " .. id .. " " .. wp)
    -- "delete DEPAX and ROLIS", "remove DEPAX, ROLIS": each further waypoint of its route listed after "and" or
    -- a comma is removed too (one off its route stays unexplained, and is asked about)
    local route = {}
    for _, w in ipairs((self:state(id) or {}).route or {}) do route[w:upper()] = true end
    for _, r in ipairs(self:refs_in(s.trig + 1, s.e, "waypoint")) do
      local sep = self.t[r.b - 1]
      if r.name:upper() ~= wp:upper() and route[r.name:upper()] and sep
          and (self:word(r.b - 1, "and") or (sep.kind == "punct" and sep.text == ",")) then
        self:emit("DELWPT " .. id .. " " .. r.name)
        self:explain(r.b - 1, r.e)
      end
    end
  end

  -- "destination echo hotel alpha mike": an ICAO code spelled in the phonetic alphabet after the
  -- instruction word, four letters exactly, that names an airport of the navdata (without navdata,
  -- or with another count of letters, none)
  -- (each letter in the phonetic alphabet or as a single letter a recogniser writes: "Z S P D")
  local function spelled_letter(t)
    return t.kind == "word" and (L.phonetic[t.text] or (t.text:match("^%a$") and t.text:upper()))
  end
  local function spelled_airport(self, s)
    local class = self.world.airport_class
    local k = s.trig + 1
    while k < s.e and not spelled_letter(self.t[k]) do k = k + 1 end
    local from, code = k, ""
    while k < s.e and spelled_letter(self.t[k]) and #code < 5 do
      code, k = code .. spelled_letter(self.t[k]), k + 1
    end
    if #code ~= 4 or not class or (class(code) or "") == "" then return nil end
    self:mark_used(from, k)
    -- the place's name said just before its code ("Athens, Lima Golf Alpha Victor")
    local b = from - 1
    while b > s.trig and from - b <= 4 and (self.t[b].kind == "punct" or self.t[b].raw:match("^%u%l")) do
      self:explain(b, b + 1)
      b = b - 1
    end
    return code
  end
  -- The first token after slot s's instruction word past the aircraft named and the words of `links` (and
  -- punctuation when `punct`) between: where a place typed straight after the instruction stands
  local function place_start(self, s, links, punct)
    local k = s.trig + 1
    while k < s.e do
      local r = self:refs_in(k, k + 1, "aircraft")[1]
      if r and r.b == k then
        k = r.e
      elseif self:word(k, links) or (punct and self.t[k].kind == "punct") then
        k = k + 1
      else
        break
      end
    end
    return k
  end
  -- "orig eidw", "dest: einn", "destination to eham": an airport's ICAO code typed in lower case straight
  -- after the instruction word ("to", "from", "is", "as", "of", "for", punctuation or the aircraft between or not:
  -- "orig of tra631 is ehrd"): a word of four
  -- letters, no English squawk knows, that names an open airport of the navdata (upper-case codes are
  -- names already). Marked used; nil when none.
  -- the count of words in [b, e) but "please" and "pls"
  function m:words_said(b, e)
    local n = 0
    for k = b, e - 1 do
      if self.t[k] and self.t[k].kind == "word" and not self:word(k, "please pls") then n = n + 1 end
    end
    return n
  end
  -- the airport whose ICAO code token k is, typed in lower case ("to eham"), no English word; nil when none
  function m:typed_airport_code(k)
    local t, class = self.t[k], self.world.airport_class
    if not (class and t and t.kind == "word" and t.raw:match("^%l%l%l%l$")) or self:known_word(k) then return nil end
    local c = class(t.raw:upper()) or ""
    if c == "" or c == "CLOSED" then return nil end
    return t.raw:upper()
  end
  local function typed_airport(self, s)
    local class = self.world.airport_class
    -- (the field's aircraft between, "orig of tra631 is ehrd", "origin tra631 ehrd")
    local k = place_start(self, s, "to from is as of for", true)
    local t = self.t[k]
    if not class or k >= s.e or t.kind ~= "word" or not t.raw:match("^%l%l%l%l$") or self.u:used(k)
        or self:known_word(k) then
      return nil
    end
    local code = t.raw:upper()
    local c = class(code) or ""
    if c == "" or c == "CLOSED" then return nil end
    self:mark_used(k, k + 1)
    self:explain(k, k + 1)
    return code
  end
  -- "divert AUH", "send it to DXB", "destination MUC", "origin is bos": three capitals typed where the place is said,
  -- straight after the instruction word (an aircraft, "the", "to", "it", "him", "her", "them" or "is" between). A large airport's IATA code
  -- (names.iata_airports; in lower case too when no English word, G:iata_airport_at: "send it to sfo") whose
  -- airport the navdata holds is that airport, returned with the code's token (marked used); after "divert" or
  -- "send", three capitals of any other (and any without navdata) are false, asked, never guessed from the
  -- navdata's names; nil when no such word stands there.
  local function iata_airport(self, s)
    local k = place_start(self, s, "to it him her them the is")
    local t = self.t[k]
    if k >= s.e or t.kind ~= "word" then return nil end
    local code, class = self:iata_airport_at(k), self.world.airport_class
    if not code and not t.raw:match("^%u%u%u$") then return nil end
    if code and class and (class(code) or "") ~= "" then
      self:mark_used(k, k + 1)
      self:explain(k, k + 1)
      return code, k
    end
    if self:word(s.trig, "divert diverting send") then return false, k end
    return nil
  end
  -- "Heathrow as its destination": the first token of the place said before "as (its|the)" and the
  -- instruction word at `trig` (at most four words, after "and", "then", "with" or punctuation), and the
  -- token of "as"; nil when the word stands otherwise
  local function placed_as(self, trig)
    local as = self:word(trig - 1, "its the") and trig - 2 or trig - 1
    if not self:word(as, "as") then return nil end
    local b = as
    while b > as - 4 and self.t[b - 1] and self.t[b - 1].kind == "word" and not self:word(b - 1, "and then with")
        and not self.u:used(b - 1) do
      b = b - 1
    end
    if b < as then return b, as end
    return nil
  end
  -- (every aircraft said gets the place: "set YMML as the destination for JST614 and TGW202"; the place is
  -- read from the first one's position)
  local function dest_orig(self, s, cmd, what)
    local ids = self:acids(s)
    if #ids == 0 then return self:need("Which aircraft should get it? Please give its callsign.") end
    local id = ids[1]
    local function each(rest)
      for _, a in ipairs(ids) do self:emit(cmd .. " " .. a .. rest) end
    end
    -- "Amsterdam as its origin and Heathrow as its destination": each place before its own word
    local b, as = nil, nil
    if s.b == s.trig then b, as = placed_as(self, s.trig) end
    local nb = s.e <= #self.t and self:word(s.e, "destination dest origin orig") and placed_as(self, s.e)
    if b or (nb and nb > s.trig) then
      if as then self:explain(as, s.trig) end
      s = { b = b or s.b, trig = s.trig, e = nb and nb > s.trig and nb or s.e, intent = s.intent }
    end
    -- ("EDDB, not Dresden", "EDDB instead of EDDC", "EDDB rather than Leipzig": the place said after the
    -- negation, ending the instruction, is the one replaced, no candidate; "land at Ezeiza, not Aeroparque":
    -- the one said first an airport by its city's navaids near the aircraft)
    local here = self:state(id) or (self.created_at or {})[id:upper()]
    -- (whether an airport is named in [b, e), near the aircraft first: a test, its questions left to the reading
    -- below, which finds a city many airports share by distance: "Alexandria" over Egypt is HEAX, not KAEX)
    local function names_airport(b, e)
      -- (a code typed in lower case that the navdata's airports hold: "dest ehbk instead of eheh")
      for k = b, e - 1 do
        if self:typed_airport_code(k) then return true end
      end
      local asked = self.ask
      local found = (here and self:airport_by_name(b, e, here, true)) or self:airport_by_name(b, e)
      self.ask = asked
      return found ~= nil
    end
    for k = s.trig + 1, s.e - 2 do
      local from = (self:word(k, "not") and k + 1) or (self:word(k, "instead") and self:word(k + 1, "of") and k + 2)
        or (self:word(k, "rather") and self:word(k + 1, "than") and k + 2)
      if from and from < s.e and #self:quantities(from, s.e) == 0 and #self:refs_in(from, s.e, "aircraft") == 0
          and (#self:refs_in(from, s.e, "waypoint") > 0 or names_airport(from, s.e))
          and #self:refs_in(s.b, k, "waypoint") + (names_airport(s.b, k) and 1 or 0) > 0 then
        self:explain(k, s.e)
        s = { b = s.b, trig = s.trig, e = k, intent = s.intent }
        break
      end
    end
    local coded, at = iata_airport(self, s)
    if coded == false then
      return self:need(string.format("Which airport is '%s'? Please give its ICAO code.", self.t[at].raw))
    end
    local w = {}
    for _, r in ipairs(self:refs_in(s.b, s.e, "waypoint")) do
      -- (not the IATA code read, "FRA" beside the FRA VOR, nor a place in the reason: "divert IAH, wx at DFW")
      if r.b ~= at and not self:in_reason(r.b) then w[#w + 1] = r end
    end
    local lat, lon = position(self:quantities(s.b, s.e), s.trig, self)
    -- (an airport of that name near the aircraft before one anywhere: "Birmingham" over England is EGBB)
    local a = here
    -- (a code spelled beside a name, "Athens, Lima Golf Alpha Victor", is the one meant; one typed in lower
    -- case straight after the word, "orig eddf, dest eham", is that airport)
    local spelled = coded or spelled_airport(self, s) or typed_airport(self, s)
    local near = spelled or (a and self:airport_of_city_said(s.b, s.e, a)) or (a and self:airport_by_name(s.b, s.e, a, true))
    local airport = near or self:airport_by_name(s.b, s.e)
    -- (a name of several words that an airport near the aircraft holds whole, "colorado springs": KCOS "CITY OF
    -- COLORADO SPRINGS MUNI", before one anywhere named by a part of it, FASI "SPRINGS" in South Africa)
    if not near and a and #w == 0 then
      near = self:airport_by_words(s.b, s.e, a, 2)
      airport = near or airport
    end
    -- (a city whose airport lies farther, none of its name read through lexicon.city_airports: the region's,
    -- "destination Cordoba" from Buenos Aires SACO, not LEBA in Spain; else the one found, confirmed below)
    if not near and a and #w == 0 and not (airport and (self.city_airport or {})[airport]) then
      near = self:airport_of_region(s.b, s.e, a)
      airport = near or airport
    end
    -- (a part of a name only near the aircraft: "Madrid" anywhere is SKMA, in Colombia)
    if not airport and #w == 0 and a then
      near = self:airport_by_words(s.b, s.e, a)
      airport = near
    end
    -- an airport found by name only far from the aircraft ("London" from over the North Sea is CYXU, in
    -- Canada: the navdata names Heathrow HEATHROW; "Athens" from over Greece is KAHN, Georgia, ATHENS BEN
    -- EPPS): confirmed, never sent
    -- (a city's one airport read through lexicon.city_airports, "origin Amsterdam", is that airport, far or near)
    local class = self.world.airport_class
    if airport and a and a.lat and not near and class and #w == 0 and not (self.city_airport or {})[airport] then
      self:confirm_before(string.format("The airport I found by that name is %s, more than %d NM from %s. Is that the "
        .. "%s? (yes or no; else please give the ICAO code)", airport, L.navaid_range_nm, id, what))
    end
    -- a city said where the airport found by its name is a small field ("destination Montpellier" is LFNG
    -- "Montpellier Candillargues", the city's traffic flying to LFMT "MEDITERRANEE", whose name holds no word of
    -- the city): confirmed, never sent in silence; an airport spelled or typed by its code is the one meant
    if airport and not spelled and class and class(airport) == "SMALL" then
      self:confirm_before(string.format("The airport I found by that name is %s, a small field. Is that the %s of %s? "
        .. "(yes or no; else please give the ICAO code)", airport, what, id))
    end
    -- (two places said for one destination, "fly to PAM next, then on to Schiphol": which?)
    if airport and #w > 0 and w[#w].name:upper() ~= airport and self:airport_meant(w[#w].name, a) ~= airport then
      return self:need(string.format("Which should be the %s of %s: %s or %s?", what, id, w[#w].name, airport))
    end
    if airport then
      each(" " .. airport)
    elseif #w > 0 then
      local code = self:airport_meant(w[#w].name, self:state(id))
      local named = {}
      self:name_beside_code(w[#w], named, code)
      for k in pairs(named) do self:explain(k, k + 1) end
      each(" " .. code)
    elseif lat and lon then
      each(" " .. f.num(lat) .. " " .. f.num(lon))
    elseif (self:word_in(s.b, s.e, "what what's whats which where") or self:noun_asked(s.trig) or self:told_me(s.trig))
        and #self:quantities(s.b, s.e) == 0 then
      each("")  -- "what's the easyJet's destination?": shown
    else
      self:need("Which airport should be the " .. what .. " of " .. id .. "? Please give its ICAO code.")
    end
  end
  -- True when the noun at i is asked for in so many words ("could you please tell me the destination of
  -- EIN655?", "let me know the origin of KL204"): one of lexicon.told_me_verbs, "me" or "us" (a "know" after
  -- "let me"), then at most "the" and a possessive before the noun
  -- True when the request asks to be told something ("could you tell me which ...", "let me know whether ...",
  -- "do you know what ..."): one of lexicon.told_me_verbs and "me" or "us" (and "know" after "let me"), or
  -- "you know", then a word opening a question
  function m:asked_indirectly()
    for k = 2, #self.t - 1 do
      local x
      if self:word(k, "me us") and self:word(k - 1, "@told_me_verbs") then
        x = self:word(k + 1, "know") and k + 2 or k + 1
      elseif self:word(k, "know") and self:word(k - 1, "you") then
        x = k + 1
      end
      if x and self:word(x, "which what whether if how") then return true end
    end
    return false
  end
  function m:told_me(i)
    local k = i - 1
    while k > i - 3 and self:word(k, "the its his her their aircraft's") do k = k - 1 end
    if self:word(k, "know") then k = k - 1 end
    return self:word(k, "me us") and self:word(k - 1, "@told_me_verbs")
  end
  -- True when the request is the word at i and an aircraft, asked ("origin of KL204?", "SAS930
  -- destination?"): every other word is the callsign's, a filler or "of".
  function m:noun_asked(i)
    if self.t[#self.t].text ~= "?" then return false end
    local inside = {}
    for _, r in ipairs(self:refs_in(1, #self.t + 1, "aircraft")) do
      for k = r.b, r.e - 1 do inside[k] = true end
    end
    for k = 1, #self.t do
      local t = self.t[k]
      if k ~= i and not inside[k] and t.kind ~= "punct" and not t.filler and not self:word(k, "of its") then
        return false
      end
    end
    return true
  end
  -- "fly to" an airport, said as an order ("ACA1041 fly to YYZ"), may mean a direct-to or a destination:
  -- asked. Said as a plan ("should/will fly to Frankfurt"), or with the destination named in the same
  -- request ("fly to Salzburg, set Salzburg as destination"), it is the destination.
  function m:dest(s)
    if self:word(s.trig, "fly") and not self:word(s.trig - 1, "@purpose_modals")
        and not self:word_in(1, #self.t + 1, "destination dest bound land landing") then
      local id = self:acid(s, "fly there")
      if not id then return end
      return self:need(string.format("Should %s fly directly to '%s' now (DIRECT), or is it its destination "
        .. "(DEST)?", id, self:raw(s.trig + 2, s.e)))
    end
    -- "destination stays LSGG", "the destination remains EHAM", "destination EHAM unchanged": the destination the
    -- aircraft has kept, no command; another airport said so is asked about
    local kept = self:find_word(s.b, math.min(#self.t + 1, s.e + 2), "stays stay remains remain unchanged")
    local n = #self.out
    dest_orig(self, s, "DEST", "destination")
    if self:word(kept, "stays stay remains remain unchanged") and #self.out > n then
      for k = #self.out, n + 1, -1 do
        local id, apt = self.out[k]:match("^DEST (%S+) (%S+)$")
        local now = id and self:state(id)
        if not (now and now.dest and now.dest:upper() == apt:upper()) then
          return self:need(string.format("%s's destination is %s. Should it change to %s, or stay as it is?", id or "?",
            now and now.dest or "not set", apt or "?"))
        end
        table.remove(self.out, k)
      end
      self:explain(math.min(s.trig, kept), math.max(s.e, kept + 1))
    end
  end
  function m:orig(s) dest_orig(self, s, "ORIG", "origin") end

  local function on_off(self, s)
    local on = self:on_off(s)
    -- ("LNAV and VNAV off", "VNAV and LNAV both switch on": a switch said with none of its own before "and" and the
    -- other switch takes the state said after that one, up to a mark, "and" or "then")
    if on < 0 and s.trig and self:word(s.trig, "lnav vnav") and self:word(s.trig + 1, "and")
        and self:word(s.trig + 2, "lnav vnav") then
      local e = s.trig + 3
      while e <= #self.t and self.t[e].kind ~= "punct" and not self:word(e, "and then") do e = e + 1 end
      local said = self:on_off({ b = s.trig + 2, e = e, trig = s.trig + 2 })
      if said >= 0 then on = said end
    end
    if on < 0 then on = self.last_on or 1 end
    self.last_on = on
    return on == 1 and "ON" or "OFF"
  end
  -- the instructions whose value VNAV ON would replace, by what they give
  local VALUE_GIVEN = { alt = "level", maintain = "value", spd = "speed", hdg = "heading", vs = "rate" }
  local function nav(self, s, cmd)
    local id = self:acid(s, "switch " .. cmd)
    if not id then return end
    if self:switch_told(s) then
      return self:need(string.format("Should %s's %s be switched on or off?", id, cmd))
    end
    if self:nav_asked(s) then
      -- ("is he on LNAV? switch on LNAV", "is it on VNAV? VNAV on please": the switch named again after the
      -- question's "?" with its state said there is set as said there; the question was the speaker's own)
      local q = s.trig
      while q < s.e and not (self.t[q].kind == "punct" and self.t[q].text == "?") do q = q + 1 end
      local t = q < s.e and self:find_word(q + 1, s.e, cmd:lower()) or s.e
      local told = t < s.e and self:on_off({ b = q + 1, e = s.e, trig = t })
      if not (told and told >= 0) then return self:emit(cmd .. " " .. id) end
      s = { b = q + 1, e = s.e, trig = t, intent = s.intent }
    end
    local on, now = on_off(self, s), self:state(id)
    -- "leave own navigation", "exiting own nav": the route left, LNAV OFF; "turn left heading 150, leaving own
    -- navigation": beside a heading given it says what the heading does (HDG leaves the route), nothing more
    local left = self:find_word(math.max(1, s.trig - 1), s.e, "own lnav") - 1
    if cmd == "LNAV" and self:word(left, "leave leaving leaves exit exiting quit quitting") then
      for k = 1, #self.t do
        if self:intent_at(k) == "hdg" then return self:explain(left, s.e) end
      end
      on = "OFF"
    end
    -- "resume own navigation" for an aircraft with no route and no waypoint named: nothing to fly
    -- (the switch named, "lnav on", is set as asked; a direct-to in the request names its place); "comply with
    -- restrictions" likewise has no route's restrictions to fly
    if cmd == "LNAV" and on == "ON" and now and now.route and #now.route == 0
        and not self:word_in(s.b, s.e, "lnav") and not self:has_ref(1, #self.t + 1, "waypoint")
        and not self:word_in(1, #self.t + 1, "direct dct") then
      return self:need(string.format("%s has no route to navigate by. Which waypoint or heading should it fly?", id))
    end
    -- (beside a level, rate, heading or speed given, VNAV, which flies the route's track, levels and speeds,
    -- would undo it)
    if cmd == "VNAV" and self:word(s.trig, "comply") then
      if now and now.route and #now.route == 0 and not self:word_in(1, #self.t + 1, "direct dct") then
        return self:need(string.format("%s has no route whose restrictions it could fly. Which level or speed "
          .. "should it fly?", id))
      end
      for k = 1, #self.t do
        local given = VALUE_GIVEN[self:intent_at(k) or ""]
        if given then
          return self:need(string.format("Should %s fly the %s given, or its route's restrictions (VNAV ON), "
            .. "which would replace it?", id, given))
        end
      end
    end
    -- "resume own navigation to MIKSI", "own navigation LILJA": its route resumed at that place (the waypoint
    -- after "to", or straight after "navigation"), a direct-to (which turns LNAV on)
    if cmd == "LNAV" and on == "ON" then
      for _, r in ipairs(self:refs_in(s.trig + 1, s.e, "waypoint")) do
        if self:word(r.b - 1, "to navigation") then return self:direct(s) end
      end
      -- ("own navigation Wallasey": a navaid or airport said by its name of one or two words there, ending
      -- the clause; "own navigation along the flight plan" names no place)
      local k = self:find_word(s.trig, s.e, "navigation") + 1
      if self:word(k - 1, "navigation") and self:word(k, "to") then k = k + 1 end
      local function ends(x) return x == s.e or (self.t[x] and self.t[x].kind == "punct") end
      if k < s.e and ((ends(k + 1) and self:place_by_name(k, k + 1, now))
          or (ends(k + 2) and self:place_by_name(k, k + 2, now))) then
        return self:direct(s)
      end
    end
    -- (the switch typed by its name, "lnav on", stays beside a direct-to: G:direct_resumes_nav)
    if self:word_in(s.b, s.e, "lnav") then
      self.lnav_typed = self.lnav_typed or {}
      self.lnav_typed[id] = true
    end
    self:emit(cmd .. " " .. id .. " " .. on)
  end
  -- True when the sentence of segment s asks whether an aircraft's switch is on ("is lnav on for KLM12?", "KLM12,
  -- is VNAV engaged?", "is KLM12 on lnav?", "KLM12's lnav is on?"): the request opens with "is"/"are", or the
  -- sentence closes with "?" and holds a copula (lexicon.setting_question_copulas);
  -- no verb of setting in it and no leave asked ("KLM12, is it possible to get lnav on?"). The switch is then shown
  -- (the command with no state), never set. "KLM12 lnav on?" (no copula) is switched as before.
  function m:nav_asked(s)
    local b, e = s.trig, s.trig
    while b > 1 and not (self.t[b - 1].kind == "punct" and self.t[b - 1].text:match("^[.?!]$")) do b = b - 1 end
    while e < #self.t and not (self.t[e].kind == "punct" and self.t[e].text:match("^[.?!]$")) do e = e + 1 end
    if self:word_in(b, e + 1, "@setting_verbs") or self:word_in(b, e + 1, "@leave_asked") then return false end
    if self:word(b == 1 and self:request_start() or self:skip_fillers(b), "is are") then return true end
    -- ("lnav status klm1607?", "vnav state of KLM12", "status of lnav for X": the switch's state named, no
    -- "on" or "off" said, is asked after, never set)
    if self:word_in(math.max(b, s.trig - 2), math.min(e + 1, s.trig + 3), "status state")
        and not self:word_in(b, e + 1, "on off engage engaged disengage disconnect activate deactivate enable disable") then
      return true
    end
    return self.t[e].text == "?" and self:word_in(b, e, "@setting_question_copulas")
  end
  function m:lnav(s) nav(self, s, "LNAV") end
  function m:vnav(s) nav(self, s, "VNAV") end
  -- The position of the request's first word after its fillers and a polite opener that asks leave to act
  -- ("is it possible to", "is it ok to", "is it too much trouble to": the instruction after it is requested,
  -- not asked about; "is it on?" has no opener).
  function m:request_start()
    local first = self:skip_fillers(1)
    -- ("hmm wait is conflict detection on?": the interjections before the question's first word)
    while self:word(first, "@setting_question_interjections") and first < #self.t do
      first = self:skip_fillers(first + 1)
    end
    -- ("kindly tell me, is the conflict detection working?": a polite lead to a comma before the question)
    local k = first
    while self:word(k, "please kindly tell me us") do k = k + 1 end
    if k > first and self:word_in(first, k, "tell") and self.t[k] and self.t[k].text == "," then
      first = self:skip_fillers(k + 1)
    end
    if not (self:word(first, "is") and self:word(first + 1, "it")) then return first end
    local to = self:find_word(first + 2, first + 6, "to")
    if to < first + 6 and self:word_in(first + 2, to, "@leave_asked") then
      return self:skip_fillers(to + 1)
    end
    return first
  end
  -- True when the request asks what a setting is ("Is conflict detection switched on?", "what's the
  -- current zone radius?", "which resolution method is active?"): the bare command shows it.
  -- value: a setting with a value of its own (ZONER, DTLOOK, DT, RFACH), also asked for without "?"
  -- ("what's the current pz radius", "show me the time step") when no number is said
  function m:asks_setting(value)
    local first = self:request_start()
    if value and self:word(first, "what what's whats show display print") and #self:quantities(1, #self.t + 1) == 0 then
      return true
    end
    -- ("how big is the protected zone rn": a size asked, "?" typed or not, no value said)
    if value and self:word(first, "how") and self:word(first + 1, "big large wide tall high") and self:word(first + 2, "is are")
        and #self:quantities(1, #self.t + 1) == 0 then
      return true
    end
    -- ("which resolution method is active": a request opening with "which" asks, "?" or not; so does one asked
    -- indirectly, "could you tell me which resolution method is currently active")
    if (self:word(first, "which") or self:asked_indirectly()) and #self:quantities(1, #self.t + 1) == 0 then
      return true
    end
    -- ("please tell me the vertical size of the protected zone": a setting told, "tell"/"remind" and "me" before
    -- the noun, no value said anywhere)
    local told = self:find_word(1, #self.t + 1, "tell remind")
    if told <= #self.t and self:word(told + 1, "me us") and self:word(told + 2, "the")
        and #self:quantities(1, #self.t + 1) == 0 then
      return true
    end
    -- ("the conflict resolution method, please tell me", "look-ahead time tell me": the setting named first, "tell
    -- me" closing the request, no value said anywhere)
    if told <= #self.t and self:word(told + 1, "me us") and #self:quantities(1, #self.t + 1) == 0 then
      local k = self:skip_fillers(told + 2)
      while self:word(k, "please now") do k = self:skip_fillers(k + 1) end
      if k > #self.t or (self.t[k].kind == "punct" and k == #self.t) then return true end
    end
    -- ("look ahead time is how long now?", "protected zone radius now how big?": the size asked after the setting's
    -- name, in Chinese word order, no value said)
    local how = self:find_word(first, #self.t + 1, "how")
    if value and how >= first and self:word(how + 1, "long big large wide tall high much") and not self:intent_at(how + 2)
        and #self:quantities(1, #self.t + 1) == 0 then
      self:explain(how, how + 2)
      return true
    end
    -- ("horizontal resolution factor, what value now?", "look-ahead time, what is it?": "what" after the setting's
    -- name, Korean order, only "value", "is", "it", "now" after it to the "?" or the end, no value said)
    local what = self:find_word(first + 1, #self.t + 1, "what")
    if value and what <= #self.t and #self:quantities(1, #self.t + 1) == 0 then
      local k = what + 1
      while self:word(k, "value number setting is it now currently") or (self.t[k] and self.t[k].filler) do k = k + 1 end
      if k > #self.t or (self.t[k].kind == "punct" and k == #self.t) then
        self:explain(what, k)
        return true
      end
    end
    -- ("zone radius?", "and rfach?", "rfacv value pls", "list lookahead and reso": a setting named in a few words
    -- (six at most) with a question mark closing the request, or with "value", "list" or "current", no value, no
    -- modal or courtesy opening it ("could you restrict ...?" asks for a change) and no verb of setting said)
    local words = 0
    for k = 1, #self.t do words = words + (self.t[k].kind == "word" and 1 or 0) end
    if value and words <= 6 and #self:quantities(1, #self.t + 1) == 0
        and not self:word_in(1, #self.t + 1, "could can would will shall may please kindly let should must")
        and not self:word_in(1, #self.t + 1, "@setting_verbs "
        .. "set change increase decrease double halve raise lower make put reduce use enable disable activate") then
      local last = self.t[#self.t]
      if (last.kind == "punct" and last.text == "?") or self:word_in(1, #self.t + 1, "value values list current") then
        return true
      end
    end
    -- (a question: "is ... on?", "what is ...?", "can you check which/whether ...?"; its first sentence, a
    -- remark may follow: "Is the conflict detection on now? I can't see any alerts.")
    local ends = self:first_sentence_end()
    -- ("how large is the protected zone radius?": "how" asks a size, no value said)
    -- ("turn on conflict detection to see whether anything happens?": a "whether" after the switch's "on" or
    -- "off" is the purpose of the instruction, not a question about the setting)
    local checked = self:find_word(1, ends, "check whether")
    return self.t[ends].text == "?" and (self:word(first, "is are what what's whats which")
      or self:statement_order_question(first, ends)
      or (checked < ends and not self:word_in(1, checked, "@on @off")) or (self:word(first, "how") and #self:quantities(1, ends) == 0))
  end
  -- The position of the request's first "?", "." or "!" (its last token when none).
  function m:first_sentence_end()
    for k = 1, #self.t do
      local t = self.t[k]
      if t.kind == "punct" and (t.text == "?" or t.text == "." or t.text == "!") then return k end
    end
    return #self.t
  end
  -- True when the sentence first .. ends (its "?") asks about a setting in a statement's word order: the setting's
  -- name (an intent of lexicon.aside.declared.settings) within the three words before a copula of
  -- lexicon.setting_question_copulas ("the detection is on?", "detection's on?" as the text reads it, "resolution is
  -- active?", "the seed is 3?"), and no verb of setting (lexicon.setting_verbs) said: "turn the detection on?" and
  -- "make sure detection is on?" are no such question, nor one a question word opens ("for the detection, what is
  -- the look-ahead?"), nor a copula after a mark ("detection, is that the look-ahead?").
  function m:statement_order_question(first, ends)
    if not (self.t[ends] and self.t[ends].text == "?") then return false end
    if self:word_in(1, ends, "@setting_verbs") or self:word_in(first, ends, "what what's whats which how whether") then
      return false
    end
    for x = first, ends - 1 do
      if L.aside.decl.settings[self:intent_at(x) or ""] then
        local copula = self:find_word(x + 1, math.min(x + 4, ends), "@setting_question_copulas")
        local between = copula < ends and self:raw(x + 1, copula) or ""
        if self:word(copula, "@setting_question_copulas") and not between:find("[%p]") then return true end
      end
    end
    return false
  end
  -- True when segment s names a switch that the request asks about, its state shown, never switched: with no value
  -- and either "status" with no "on" or "off" ("show detection status"), or no "on" or "off" said, no switching word
  -- or request's verb anywhere, and a noun of its settings or a question ("cd settings?", "asas settings", "reso
  -- status?", "cd?"; "could you switch detection and resolution on?" switches both; "could you add the
  -- turbulence?" is asked for)
  function m:switch_asked(s)
    -- (a value of another instruction, "ff 30 s then CD status", is no value of the switch)
    if #self:quantities(s.b, s.e) > 0 then return false end
    if self:word_in(1, #self.t + 1, "status") and not self:word_in(1, #self.t + 1, "on off enable disable activate") then
      return true
    end
    return self:on_off(s) < 0
      and not self:word_in(1, #self.t + 1, "@on @off switch turn could can would will add enable activate start use")
      and (self:word_in(1, #self.t + 1, "settings setting config configuration options status")
        or self.t[self:first_sentence_end()].text == "?")
  end
  -- (a switch asked about: a question, or a request opening with "what" and no "on" or "off" in it, "what's the
  -- conflict detection setting", or with "is" or "are", "is conflict detection on": its state shown, never set)
  function m:switch(s, spec)
    -- ("is the detection of conflicts on? please put it on", "is ASAS on? switch that off please": the question's
    -- answer not awaited, the switch set in the one sentence after it: a verb of setting, "it" and one "on" or
    -- "off", with only fillers and "please" beside them)
    local q = self:first_sentence_end()
    if self.t[q].text == "?" and q < #self.t and s.trig < q then
      local verb = self:skip_fillers(q + 1)
      -- ("is there conflict detection? if not, turn it on": the switch set when the answer is no, as it is set now)
      if self:word(verb, "if") and self:word(verb + 1, "not") then
        verb = self:skip_fillers(verb + 2)
        if self.t[verb] and self.t[verb].text == "," then verb = self:skip_fillers(verb + 1) end
      end
      while self:word(verb, "please kindly now") do verb = self:skip_fillers(verb + 1) end
      if self:word(verb, "@setting_verbs") and self:word(verb + 1, "it that this") and self:word(verb + 2, "@on @off") then
        local k = self:skip_fillers(verb + 3)
        while self:word(k, "please now") do k = self:skip_fillers(k + 1) end
        if k > #self.t then
          self:explain(q + 1, #self.t + 1)
          return self:emit(spec.cmd .. (self:word(verb + 2, "@on") and " ON" or " OFF"))
        end
      end
    end
    -- ("are there conflicts? switch on the detection": the switch named after the question, with its "on" or "off",
    -- is set)
    local set_after = s.trig > q and self:word_in(q + 1, s.e, "@on @off")
    -- (the detection's interval named after it: "conflict detection interval", "... update interval")
    local interval = self:word(s.trig + 1, "update check") and s.trig + 2 or s.trig + 1
    interval = self:word(interval, "interval") and interval
    if not set_after and (self:asks_setting(self:on_off(s) < 0) or self:word(self:request_start(), "is are")) then
      -- ("what is the conflict detection interval?": DT shows it, with the time step, once in the request)
      if spec.cmd == "ASAS" and interval then
        for _, c in ipairs(self.out) do
          if c == "DT" then return self:explain(s.trig, interval + 1) end
        end
        return self:emit("DT")
      end
      -- ("is the conflict detection working now or not?": the question's alternative, closing it)
      local q = self:first_sentence_end()
      if self.t[q].text == "?" and self:word(q - 1, "not") and self:word(q - 2, "or") then self:explain(q - 2, q) end
      return self:emit(spec.cmd)
    end
    if self:switch_asked(s) then return self:emit(spec.cmd) end
    -- "run conflict detection every 2 seconds": the interval of detection (DT ASAS); switched on too
    -- only when said ("turn on detection every 2 seconds")
    if spec.cmd == "ASAS" then
      for _, q in ipairs(self:quantities(s.b, s.e)) do
        -- ("update interval 2 s", "the detection interval could be set to 0.5 seconds")
        if q.kind == "time" and (self:word(q.b - 1, "every each interval")
            or (interval and q.b > s.trig)) then
          -- ("set detection interval on 2 seconds": an "on" straight before the value, no other switching word, says
          -- "to", no switch)
          local to = self:word(q.b - 1, "on") and not self:word_in(s.b, q.b - 1, "@on @off")
            and not self:word_in(q.b, s.e, "@on @off") and q.b - 1
          if to then self:explain(to, to + 1)
          elseif self:on_off(s) >= 0 then self:emit("ASAS " .. on_off(self, s)) end
          return self:emit("DT ASAS " .. f.num(self:take(q).value))
        end
      end
      -- ("set the detection interval on": the interval named with no time, the "on" its missing value's "to")
      if interval then
        self.ask = "What interval should conflict detection run at (seconds)?"
        return
      end
    end
    -- ("CD: 2", "asas 0", "cd=5": a bare number straight after the switch's name, no "on" or "off" said, is no
    -- switch position squawk can read: asked, naming it)
    if spec.cmd == "ASAS" and self:on_off(s) < 0 then
      local q = self:quantities(s.trig + 1, s.e)[1]
      local k = s.trig + 1
      while q and k < q.b and self.t[k].kind == "punct" do k = k + 1 end
      if q and q.kind == "plain" and k == q.b then
        self.ask = string.format("What does '%s' mean after '%s'? Conflict detection can be switched on or off "
          .. "(ASAS ON/OFF), or given an interval, a look-ahead or a zone.", self:raw(q.b, q.e), self:raw(s.trig, s.trig + 1))
        return
      end
    end
    -- ("set the conflict detection radius to five miles": the detection's zone given a size in the request, no "on" or
    -- "off" said, sets the zone only (m:zone), the switch as it is)
    local sized = false
    if spec.cmd == "ASAS" and self:on_off(s) < 0 and not self:word_in(1, #self.t + 1, "@on @off")
        and not self:word(s.trig, "detect")
        and self:word_in(s.trig, math.min(#self.t + 1, s.trig + 3), "radius zone") then
      for _, q in ipairs(self:quantities(1, #self.t + 1)) do sized = sized or q.kind == "dist" end
    end
    if sized then return self:explain(s.trig, s.trig + 1) end
    -- ("look-ahead time 5 minutes, for the conflict detection": the detection named after "for" as what another
    -- setting of the request is for, no "on" or "off" said, switches nothing)
    local k = s.trig - 1
    while k > 1 and self:word(k, "the conflict conflicts") do k = k - 1 end
    if spec.cmd == "ASAS" and self:word(k, "for") and #self.out > 0 and self:on_off(s) < 0
        and not self:word_in(1, #self.t + 1, "@on @off") then
      return self:explain(k, s.trig + 1)
    end
    -- ("but keep detection running", "leave the detection off": the switch kept as it is now, nothing switched)
    local kept = self:find_word(math.max(1, s.trig - 4), s.trig, "leave keep")
    if spec.cmd == "ASAS" and kept < s.trig and self:on_off(s) >= 0 and self.world.detection
        and (self.world.detection() == "OFF") == (self:on_off(s) == 0) then
      return self:explain(kept, s.trig + 1)
    end
    -- "detection statebased", "state-based detection": CDMETHOD's method, which is on
    local method = spec.cmd == "ASAS" and self:find_word(s.b, s.e, "statebased state-based state")
    if method and method < s.e and (not self:word(method, "state") or self:word(method + 1, "based")) then
      self:explain(method, self:word(method, "state") and method + 2 or method + 1)
      self:emit(spec.cmd .. " STATEBASED")
    else
      self:emit(spec.cmd .. " " .. on_off(self, s))
    end
    if spec.cmd ~= "ASAS" then return end
    self:zone_said_with(s.trig, s.e)
  end
  -- "turn on CD with 5 nm and 1000 ft", "MVP, 5 nm by 1000 ft": a distance and a height in feet said in the
  -- segment of a conflict switch, tokens b .. e-1, are the protected zone's radius (ZONER) and half height (ZONEDH)
  function m:zone_said_with(b, e)
    for _, q in ipairs(self:quantities(b, e)) do
      if q.kind == "dist" and not self.taken[q.b] then self:emit("ZONER " .. f.num(self:take(q).value)) end
      if q.kind == "alt" and not q.fl and not self.taken[q.b] and self:word(q.e - 1, "@feet") then
        self:emit("ZONEDH " .. f.num(self:take(q).value))
      end
    end
  end

  function m:one_acid(s, cmd, what)
    local id = self:acid(s, what)
    if id then self:emit(cmd .. " " .. id) end
  end
  function m:listrte(s)
    -- ("the route page", "the flight plan page": the cockpit's page that shows the route)
    if self:word(s.trig + 1, "page") then self:explain(s.trig + 1, s.trig + 2) end
    self:one_acid(s, "LISTRTE", "have its route listed")
  end
  function m:delrte(s) self:one_acid(s, "DELRTE", "have its route cleared") end
  -- POS of an aircraft, else of a place named with no aircraft ("where is TP2?")
  function m:pos(s)
    -- ("how about let CCA1831 speed 300 knots", "how about CXA8301 turn right 30 degrees": a suggestion of the
    -- instruction after the aircraft, G:state_question; the words before it show nothing)
    if self:word(s.trig, "how") and self:word(s.trig + 1, "about") then
      local a = s.trig + 2
      if self:word(a, "we") then a = a + 1 end
      if self:word(a, "let have make") then a = a + 1 end
      local x = self:refs_in(a, a + 1, "aircraft")[1]
      local j = x and self:skip_fillers(x.e)
      local valued = j and self:word(j, "speed heading altitude level mach") and (self:quantities(j + 1, j + 3)[1] or {}).b
      local given = j and (#self:quantities(j, #self.t + 1) > 0 or self:has_ref(j, #self.t + 1, "waypoint"))
      if x and x.b == a and x.exists and given and (self:intent_at(j) or valued == j + 1) then
        return self:explain(s.trig, a)
      end
      -- ("KAL1102, how about speed 300? increase please", "how about flight level 240 for him": a value's noun and
      -- its value straight after "how about", an aircraft named in the request, suggests that value: the words
      -- show nothing, the value is read as said)
      local v = self:word(a, "flight") and a + 1 or a
      local q = self:word(v, "speed heading altitude level mach fl") and self:quantities(v, v + 3)[1]
      if not x and q and (q.b == v or q.b == v + 1) and #self:acids(s) >= 1 then
        return self:explain(s.trig, a)
      end
    end
    -- a navaid's kind said beside its name ("the Pampus VOR, PAM") is no place of its own
    local places, kind_said = {}, false
    for _, r in ipairs(self:refs_in(s.b, s.e, "waypoint")) do
      if self:word(r.b, "@navaid_kinds") then kind_said = true else places[#places + 1] = r end
    end
    local no_aircraft = #self:refs_in(s.b, s.e, "aircraft") == 0
    -- ("what's the Denver doing?", "what is SPY doing": a place does nothing, so a name there is an aircraft's,
    -- an airline's name squawk may not know: no place is shown, the aircraft is asked for)
    local doing = self:word_in(s.b, s.e, "doing")
    if no_aircraft and #places > 0 and not doing then return self:emit("POS " .. places[1].name) end
    -- "where is AFR1234 relative to ANETO", "... in relation to GIROM", "... with respect to LAPOS": the place
    -- the position is wanted from, which POS shows beside the aircraft's own
    if not no_aircraft and #places == 1 and self:word(places[1].b - 1, "to")
        and self:word(places[1].b - 2, "relative relation respect") then
      self:explain(places[1].b - 2, places[1].e)
    end
    -- ("say distance to TELIN", "report your distance from BIG": the distance asked, from the same)
    if not no_aircraft and #places == 1 and self:word(places[1].b - 1, "to from")
        and self:word(places[1].b - 2, "distance range") then
      self:explain(places[1].b - 2, places[1].e)
    end
    -- a place by its name ("where is Schiphol?", "where is Munich airport?", "where the Kempten VOR is"); an
    -- airport said as such by the name of its city's navaids near the traffic ("show me Ezeiza airport": SAEZ
    -- "MINISTRO PISTARINI" beside the EZEIZA VOR), as a destination is
    local named
    if no_aircraft and self:word_in(s.b, s.e, "@airport_nouns") then
      for _, a in ipairs(self.fleet) do
        named = named or self:airport_by_name(s.b, s.e, a, true)
      end
      -- (none near: the traffic's region's, "where is Cordoba airport?" over Argentina is SACO, not LEBA)
      named = named or self:airport_of_region(s.b, s.e, self.fleet[1])
    end
    -- (aircraft described, "where is the Iberia" with Iberias flying, are never a place of that name: they are
    -- read, or asked about, below)
    local described = false
    for i = s.b, no_aircraft and not named and s.e - 1 or 0 do
      local icao, _, codes = self:airline_at(i)
      described = described or (icao ~= nil and #self:airline_fleet(icao, codes) > 0)
    end
    for _, u in ipairs(self.type_unresolved or {}) do described = described or (u.b >= s.b and u.b < s.e) end
    -- ("where's the Belfast City arrival?": a place named before a noun of lexicon.described_places.before describes
    -- an aircraft, G:described_place; never the place shown)
    for i = s.b, no_aircraft and not described and s.e - 1 or 0 do described = described or self:described_place(i) ~= nil end
    named = named or (no_aircraft and not described and not doing and self:place_by_name(s.b, s.e))
    if named then return self:emit("POS " .. named) end
    if kind_said and no_aircraft then return self:need("Which navaid do you mean? Please give its identifier.") end
    -- "show me where TEST01 and TEST03 are": each aircraft named
    local ids = self:acids(s)
    if #ids > 1 then
      for _, id in ipairs(ids) do self:emit("POS " .. id) end
      return
    end
    self:one_acid(s, "POS", "be shown")
  end

  function m:bank(s)
    local id = self:acid(s, "get a bank limit")
    if not id then return end
    for _, q in ipairs(self:quantities(s.b, s.e)) do
      -- ("watch the bank, it's a 105 degree turn": a limit steeper than any aircraft banks is a turn's size, asked)
      if (q.kind == "angle" or q.kind == "plain") and q.value > L.max_bank_deg then
        return self:need(string.format("%s degrees is steeper than any aircraft banks. What bank angle limit, in "
          .. "degrees, should %s have?", f.num(q.value), id))
      end
      if q.kind == "angle" or q.kind == "plain" then return self:emit("BANK " .. id .. " " .. f.num(q.value)) end
    end
    self:need("What bank angle limit, in degrees, should " .. id .. " have?")
  end

  function m:bare(_, spec) self:emit(spec.cmd) end
  -- HELP: a question about squawk's commands (rules.lua's help_asked); HELP NAME when a registry command's name
  -- (or alias) is said straight before or after the noun ("the addwpt command", "command ALT"); the question's
  -- words are all read
  function m:help(s)
    local names = {}
    for _, c in ipairs(squawk.sim.commands()) do
      names[c.name:lower()] = c.name
      for _, a in ipairs(c.aliases or {}) do names[a:lower()] = c.name end
    end
    local named
    for _, k in ipairs({ s.trig - 1, s.trig + 1 }) do
      local t = self.t[k]
      if not named and t and t.kind == "word" and names[t.raw:lower()] then named = names[t.raw:lower()] end
    end
    self:explain(1, #self.t + 1)
    self:emit(named and "HELP " .. named or "HELP")
  end
  -- OP; "resume at 2x", "resume the simulation at x3": a rate said after "at" is a DTMULT too
  function m:resume(s)
    -- An unpause to come, said by its speaker ("when I unpause", "until we resume", "before we continue"), starts
    -- nothing now: "pause until I resume" is the pause alone; a rate said with it would not outlast it (OP runs at
    -- DTMULT 1, as BlueSky's: "pause and go 2x when I unpause" is asked), nor is anything else said to happen then
    if self:word(s.trig - 1, "i we you") and self:word(s.trig - 2, "when once after until till before") then
      local rate = false
      for _, c in ipairs(self.out) do rate = rate or c:match("^DTMULT") ~= nil end
      for _, q in ipairs(self:quantities(1, #self.t + 1)) do rate = rate or q.kind == "mult" end
      if rate then
        return self:need("Unpausing (OP) sets the rate back to 1x, so a rate set now would not hold then: please "
          .. "give the rate as you unpause (\"resume at 2x\").")
      end
      if self:word(s.trig - 2, "until till before") and self.out[#self.out] == "HOLD" then
        return self:explain(s.trig - 2, s.trig + 1)
      end
      return self:need("Nothing is run when you unpause later: what should happen now?")
    end
    -- "back to real time" or "real time" with no word that starts the clock, and "real time speed", read from
    -- the clock's state (world.run_state, or an FF said before in the request): in fast-time OP
    -- (only OP ends it); otherwise DTMULT 1, the rate, which starts nothing (a held clock stays
    -- held). A clock state not known, or another rate said before it, is asked ("real time speed"
    -- is the rate all the same).
    -- "real time again" ("run it in real time again") returns to real time as "back to real time" does; its
    -- "run" and "again" are the return's, no start of the clock
    -- ("the simulation should run again in real time": "run again" straight before "in"/"at real time" is the
    -- return to real time as "real time again" is, read from its "real")
    local rt = s.trig
    if self:word(rt, "run") and self:word(rt + 1, "again") and self:word(rt + 2, "in at") and self:word(rt + 3, "real")
      and self:word(rt + 4, "time") then rt = rt + 3 end
    local again = rt > s.trig or self:word(rt, "real") and self:word(rt + 2, "again")
    local back = again or self:word(rt, "real") and self:word(rt - 1, "to") and self:word(rt - 2, "back")
    -- ("dtmult 1 back to realtime": said after the rate set back to 1, it explains that rate)
    if back and self.out[#self.out] == "DTMULT 1" then return self:explain(s.b, s.e) end
    -- ("stop the fast-forward and carry on in real time": the OP that ended fast time runs in real time)
    if self:word(rt, "real") and self.ff_ended_op == #self.out then return self:explain(s.b, s.e) end
    local speed = self:word(rt, "real") and self:word(rt + 2, "speed")
    local starts = again and "running start resume unpause continue" or "run running start resume unpause continue again"
    if speed or self:word(rt, "real") and not self:word_in(s.b, s.e, starts) then
      local state = self.world.run_state
      for _, c in ipairs(self.out) do
        local cmd = c:match("^(%u+)")
        if cmd == "FF" then state = "ff" elseif cmd == "OP" or cmd == "HOLD" then state = cmd:lower() end
        if cmd == "DTMULT" then state = nil end  -- another rate just said ("dtmult 4 back to real time")
      end
      if state == "ff" then return self:emit("OP") end
      if speed or state == "op" or state == "hold" then return self:emit("DTMULT 1") end
      return self:need("Should the simulation start running (OP), or run at real-time rate again (DTMULT 1)?")
    end
    self:emit("OP")
    -- ("from the point at which it was paused": an "at" opening a remark, G:in_reason, says no rate; "resume
    -- and go 3x": a factor said in the segment is its rate, with or without "at")
    local at = self:find_word(s.trig + 1, s.e, "at")
    local factor = false
    for _, q in ipairs(self:quantities(s.trig + 1, s.e)) do factor = factor or (q.kind == "mult" and not self:in_reason(q.b)) end
    if (at < s.e and not self:in_reason(at + 1)) or factor then self:time_mult(s) end
  end

  -- first quantity of one of `kinds` in the segment, or nil
  -- the first value of one of `kinds` in segment s, none said in a remark ("note to self: episode 14 ...")
  local function first(self, s, kinds)
    for _, q in ipairs(self:quantities(s.b, s.e)) do
      if kinds[q.kind] and not self:in_reason(q.b) then return q end
    end
    return nil
  end

  -- "an hour and a half", "two minutes and a half": [s] and the tokens' end, or nil ("two and a half minutes" is
  -- a time the quantities read whole, 150 s)
  local UNIT_S = { second = 1, seconds = 1, sec = 1, secs = 1, minute = 60, minutes = 60, min = 60, mins = 60,
                   hour = 3600, hours = 3600 }
  local function and_a_half(self, b, e)
    for k = b, e - 2 do
      local unit = UNIT_S[self.t[k + 1].text]
      local q = unit and not self:word(k, "a an") and self:quantities(k, k + 2)[1]
      local said = self:word(k, "a an") and unit or (q and q.b == k and q.e == k + 2 and q.kind == "time" and q.value)
      if said and self:word(k + 2, "and") and self:word(k + 3, "a") and self:word(k + 4, "half") then
        return said + unit / 2, k + 5
      end
    end
    return nil
  end

  -- The duration [s] said in place of time quantity q after a correction in segment s ("ff 5 min, correction, 4":
  -- 240 s, a bare number in the unit of the one taken back; "..., sorry, 4 min": 240 s), both values taken; nil when
  -- no value follows a correction
  local function corrected_time(self, s, q)
    local c = self:find_word(q.e, s.e, "@correction")
    local n = c < s.e and self:quantities(c + 1, s.e)[1]
    local unit = UNIT_S[self.t[q.e - 1].text]
    if not n or not (n.kind == "time" or (n.kind == "plain" and unit)) then return nil end
    self:take(q)
    self:take(n)
    return n.kind == "time" and n.value or n.value * unit
  end

  -- the token of a verb that ends fast time before the fast-forward of segment s ("stop the fast-forward",
  -- "cancel this fast forward"), nil when none is said
  local function ff_ended(self, s)
    local k = s.trig - 1
    while k >= s.b and self:word(k, "the this that our your current") do k = k - 1 end
    if k >= s.b and self:word(k, "@ff_ended") then return k end
    return nil
  end

  function m:fast_forward(s)
    -- a fast-forward ended ("stop the fast-forward"): OP, which alone ends fast time, once in the request; the
    -- verb and its object are read, no duration is (self.ff_ended_op marks the OP for m:resume's "real time")
    local ended = ff_ended(self, s)
    if ended then
      self:explain(ended, s.e)
      for _, c in ipairs(self.out) do if c == "OP" then return end end
      self.ff_ended_op = #self.out + 1
      return self:emit("OP")
    end
    local half, half_e = and_a_half(self, s.trig + 1, s.e)
    if half then
      for _, q in ipairs(self:quantities(s.trig + 1, half_e)) do self:take(q) end
      self:mark_used(s.trig + 1, half_e)
      return self:emit("FF " .. f.num(half))
    end
    local q = first(self, s, { time = true, mult = true })
    -- ("turn right heading 330, and give me five minutes fast forward": a duration straight before the verb, in
    -- the clause the segment before took, read by none)
    local before = not q and s.b == s.trig and self:quantities(math.max(1, s.trig - 3), s.trig)
    before = before and before[#before]
    if before and before.kind == "time" and before.e == s.trig and not self.taken[before.b]
        and not self:word(before.b - 1, "within in for after by before until till") then
      q = before
    end
    -- "FF 120", "ff: 120", "ff=120": TrafScript's own word with a bare number, its seconds
    local plain = first(self, s, { plain = true })
    local set = self.t[s.trig + 1] and self.t[s.trig + 1].raw == ":" and 1 or 0
    if not q and self.t[s.trig].raw:upper() == "FF" and plain and plain.b == s.trig + 1 + set then
      self:take(plain)
      -- ("ff 5", "ff 20": under half a minute, a count of minutes with the unit left out as likely as seconds)
      if plain.value > 0 and plain.value < L.ff_bare_min_s then
        return self:need(string.format("For how long should the simulation fast-forward: %s seconds or %s minutes? "
          .. "Please give the unit.", f.num(plain.value), f.num(plain.value)))
      end
      return self:emit("FF " .. f.num(plain.value))
    end
    -- "speed the simulation up by a factor of ten": a rate, no duration
    local factor = self:find_word(s.trig, s.e, "factor")
    if not q and factor < s.e then return self:time_mult({ b = factor, trig = factor, e = s.e }) end
    -- ("speed the simulation up by ten": a bare number after "by", the simulation named, is the factor)
    local by = self:find_word(s.trig + 1, s.e, "by")
    local n = not q and by < s.e and self:word_in(s.b, s.e, "@sim") and self:quantities(by + 1, s.e)[1]
    if n and n.b == by + 1 and n.kind == "plain" and n.value >= 2 and n.value <= 100 then
      self:take(n)
      self:mark_used(by, by + 1)
      return self:emit("DTMULT " .. f.num(n.value))
    end
    -- "put fast time please, times four": "times" straight before a number names the rate, a multiple of real
    -- time (DTMULT), as "four times" does
    local times = self:find_word(s.trig + 1, s.e, "times")
    local n = not q and times < s.e and self:quantities(times + 1, s.e)[1]
    if n and n.kind == "plain" and n.b == times + 1 and n.value > 1 then
      self:take(n)
      self:mark_used(times, times + 1)
      return self:emit("DTMULT " .. f.num(n.value))
    end
    if not q then
      -- "half an hour", "a quarter of an hour": a fraction of a unit said in words
      local frac = self:find_word(s.trig + 1, s.e, "@fractions")
      local unit = frac < s.e and self:find_word(frac + 1, math.min(s.e, frac + 4), "hour minute") or s.e
      if unit < s.e then
        local seconds = L.fractions[self.t[frac].text] * (self:word(unit, "hour") and 3600 or 60)
        return self:emit("FF " .. f.num(seconds))
      end
      -- "an hour", "a minute": one of the unit
      local one = self:find_word(s.trig + 1, s.e, "a an")
      if one + 1 < s.e and self:word(one + 1, "hour minute second") then
        self:mark_used(one, one + 2)
        return self:emit("FF " .. f.num(UNIT_S[self.t[one + 1].text]))
      end
      -- "fast forward to minutes": a recogniser's "to" for "two", straight before a unit and no number
      local to = self:find_word(s.trig + 1, s.e, "to too")
      if to + 1 < s.e and UNIT_S[self.t[to + 1].text] and self.t[to + 1].text:match("s$")
          and #self:quantities(s.trig + 1, s.e) == 0 then
        self:mark_used(to, to + 2)
        return self:emit("FF " .. f.num(2 * UNIT_S[self.t[to + 1].text]))
      end
      -- "fast forward" alone runs fast-time until stopped ("until I say stop", "I'll tell you when to stop"
      -- say so); more words ("a bit", "an hour and a half") said a duration that was not understood
      local till = self:find_word(s.trig + 1, s.e, "until till")
      local told = self:find_word(s.trig + 1, till, "tell say")
      if told < till and self:word(told + 1, "you when") then
        till = self:word(told - 1, "i i'll ill we we'll") and told - 1 or told
      end
      -- ("until t=20 min", "until 00:20": a time after "until" is when to stop, which squawk does not
      -- turn into a duration: asked)
      for i = till + 1, s.e - 1 do
        if self.t[i].text:find("%d") then
          return self:need("For how long should the simulation fast-forward? I heard 'until "
            .. self:raw(till + 1, s.e) .. "': please give a duration.")
        end
      end
      -- ("until they lose separation", "until it's interesting", "until the conflict": an event, which fast time
      -- does not wait for: asked; only the speaker's own stop, "until I say stop", "until further notice", is
      -- fast time with no end)
      if till < s.e and not self:word_in(till + 1, s.e, "@ff_stopped") then
        return self:need("For how long should the simulation fast-forward? squawk fast-forwards for a time, not "
          .. "until something happens; I heard '" .. self:raw(till, s.e) .. "': please give a duration.")
      end
      self:explain(till, till + 1)
      -- "speed up the simulation", "can you speed this simulation up?": faster, by no rate and for no time
      -- said, is either a rate (DTMULT) or fast time for a while (FF): asked
      if self:word(s.trig, "speed spd airspeed") and till >= s.e then
        return self:need("How should the simulation speed up: at a multiple of real time (DTMULT, by how much?) "
          .. "or in fast time for a while (FF, for how long)?")
      end
      for i = s.trig + 1, till - 1 do
        local t = self.t[i]
        if t.kind ~= "punct" and not t.filler and not self:word(i, "@sim forward ahead up please this it things the fast") then
          return self:need("For how long should the simulation fast-forward? Please give a time.")
        end
      end
      return self:emit("FF")
    end
    if q.kind == "time" then
      -- "fast forward to 1 hour": "to" before the time names a time on the clock as likely as a duration, asked;
      -- "to 15 minutes from now", "to 30 minutes later" say the duration
      if self:word(q.b - 1, "to") and q.b - 1 > s.trig and not self:word(q.e, "from later ahead hence") then
        return self:need(string.format("Should the simulation fast-forward for %s, or until the simulation clock reaches %s?",
          self:raw(q.b, q.e), self:raw(q.b, q.e)))
      end
      -- ("set sim speed to 2 and fast-forward 5 min": a rate said before "and" and the fast-forward's own verb, one
      -- segment, is a DTMULT of its own, first)
      local rate = self:quantities(s.trig + 1, q.b)[1]
      local joined = rate and self:find_word(rate.e, q.b, "and then")
      if rate and rate.kind == "plain" and not self.taken[rate.b] and joined < q.b and self:word_in(s.b, s.e, "@sim")
          and self:word(rate.b - 1, "speed spd to") and self:word_in(joined + 1, q.b, "fast ff forward") then
        self:emit("DTMULT " .. f.num(self:take(rate).value))
      end
      local fixed = corrected_time(self, s, q)
      if fixed then return self:emit("FF " .. f.num(fixed)) end
      return self:emit("FF " .. f.num((self:time_total(q, s.e))))
    end
    self:emit("DTMULT " .. f.num(q.value))  -- "speed the sim up 10 times"
  end
  function m:time_step(s)
    -- ("asas dt 2 sec", "dt asas 2": conflict detection's own interval, DT ASAS)
    local asas = self:word(s.trig - 1, "detection asas cd") and s.trig - 1
      or self:word(s.trig + 1, "detection asas cd") and s.trig + 1
      -- ("check the conflicts every 2 seconds": the conflicts checked, rules.lua)
      or self:word(s.trig, "check checks checking") and self:find_word(s.trig, s.e, "conflict conflicts")
    if asas then self:explain(asas, asas + 1) end
    local q = first(self, s, { time = true, plain = true })
    -- ("trails on, dt 5s": a bare "dt" just after the trails, in their clause or the next, may be their own
    -- interval, TRAIL ON dt, or the simulation's step: asked)
    local last = self.out[#self.out] or ""
    if not asas and q and self:word(s.trig, "dt")
        and (self:find_word(math.max(1, s.trig - 4), s.trig, "trail trails") < s.trig or last:match("^TRAIL O[NF]F?$")) then
      return self:need(string.format("Is %s s the trails' interval (TRAIL ON %s) or the simulation's time step (DT %s)?",
        f.num(q.value), f.num(q.value), f.num(q.value)))
    end
    -- ("tick rate 20 hz": a rate in hertz is a step of its inverse in seconds)
    if q and q.kind == "plain" and self:word(q.e, "hz hertz") then
      if q.value <= 0 then return self:need("What time step, in seconds, should the simulation use?") end
      self:mark_used(q.b, q.e + 1)
      self:explain(q.b, q.e + 1)
      return self:emit((asas and "DT ASAS " or "DT ") .. f.num(1 / q.value))
    end
    if q then return self:emit((asas and "DT ASAS " or "DT ") .. f.num(q.value)) end
    if asas then return self:need("How often, in seconds, should conflict detection run?") end
    -- "a tenth of a second", "half a second": a fraction of a second said in words
    local frac = self:find_word(s.b, s.e, "@fractions")
    local unit = frac < s.e and self:find_word(frac + 1, math.min(s.e, frac + 4), "second seconds") or s.e
    if unit < s.e then
      self:mark_used(frac, unit + 1)
      return self:emit("DT " .. f.num(L.fractions[self.t[frac].text]))
    end
    if self:asks_setting(true) then return self:emit("DT") end
    self:need("What time step, in seconds, should the simulation use?")
  end
  function m:time_mult(s)
    -- "let the sim run, times eight", "let it run. x4", "let her run, x4": the clock started, said as a clause of its own (OP, which
    -- sets DTMULT 1, as BlueSky's does), and its rate after it ("let it run at 5 times speed" is the rate alone)
    local run = self:word(s.trig, "@sim") and s.trig + 1 or s.trig
    local let = self:word(run - 1, "it her") and run - 1 or (self:word(run - 1, "@sim") and self:word(run - 2, "the") and run - 2)
    if let and self:word(let - 1, "let") and self:word(run, "run") and self.t[run + 1] and self.t[run + 1].kind == "punct"
        and self.out[#self.out] ~= "OP" then
      self:emit("OP")
    end
    -- ("sim speed one half": a fraction said in words after "one" or "a")
    for i = s.b, s.e - 1 do
      local e = self:fraction_said(i)
      if e and e <= s.e then
        self:mark_used(i, e)
        return self:emit("DTMULT " .. f.num(L.fractions[self.t[e - 1].text]))
      end
    end
    -- (a bare number after "at" before the instruction word, "at 120 dtmult 4", is no rate: left over, asked)
    local q
    for _, p in ipairs(self:quantities(s.b, s.e)) do
      -- ("run fast for half an hour": a fraction of a time unit is a time, G:spoken_duration, no rate)
      if not q and (p.kind == "mult" or p.kind == "plain") and not self:in_reason(p.b)
          and not (p.b < s.trig and self:at_number(p)) and not self:spoken_duration(p.b) then
        q = p
      end
    end
    if q then
      -- ("set multiplier 8 and run at 4x", "time acceleration 8 and run it at twice real time": two rates for the
      -- one clock, with no time said between, are asked)
      local e = s.e
      for _, p in ipairs(self:quantities(q.e, s.e)) do
        if p.kind == "time" then e = math.min(e, p.b) end
      end
      local other, other_at
      for _, p in ipairs(self:quantities(q.e, e)) do
        if (p.kind == "mult" or p.kind == "plain") and not self:in_reason(p.b) and p.value ~= q.value and not other then
          other, other_at = p.value, p
        end
      end
      -- (a rate in words, "twice", or glued to its x, "then 2x" written "sim speed x2")
      for i = q.e, e - 1 do
        local v = self.t[i].kind == "word"
          and (L.multipliers[self.t[i].text] or tonumber(self.t[i].text:match("^x(%d+%.?%d*)$") or ""))
        if v and v ~= q.value and not other then other, other_at = v, { b = i, e = i + 1 } end
      end
      -- ("two times faster, no, three": a rate after a correction, the self-correction run read as one, replaces
      -- the one before it, which is taken back)
      if other and self:corrected_between(q.e, other_at.b) then
        self:take(q)
        self:mark_used(q.b, other_at.e)
        return self:emit("DTMULT " .. f.num(other))
      end
      if other then
        return self:need(string.format("Which rate should the simulation run at: %s or %s times real time?",
          f.num(q.value), f.num(other)))
      end
      return self:emit("DTMULT " .. f.num(q.value))
    end
    -- "pause, then 3x speed", "and then 5 times faster": a factor said before the instruction word, in
    -- its clause (no comma, "then" or "and" between), no other instruction's
    local k = s.b - 1
    while k >= 1 and self.t[k].kind ~= "punct" and not self:word(k, "then and") and not self.u:used(k) do k = k - 1 end
    for _, p in ipairs(self:quantities(k + 1, s.b)) do
      if p.kind == "mult" and not self.taken[p.b] then
        self:take(p)
        return self:emit("DTMULT " .. f.num(p.value))
      end
    end
    -- "run faster please, 5 times": the factor said after a comma straight after the segment, closing the
    -- request (courtesy and marks only after it)
    local after = s.e
    while self.t[after] and ((self.t[after].kind == "punct" and self.t[after].text == ",") or self.t[after].filler
        or self:word(after, "please")) do
      after = after + 1
    end
    local p = after > s.e and self:quantities(after, #self.t + 1)[1]
    -- ("speed up the simulation, twice": the factor a word of lexicon.multipliers, "twice", "thrice")
    if after > s.e and not (p and p.b == after) and self:word(after, "twice thrice") then
      p = { b = after, e = after + 1, kind = "mult", value = L.multipliers[self.t[after].text], word = true }
    end
    if p and p.b == after and p.kind == "mult" and not self.taken[p.b] then
      local rest = p.e
      while self.t[rest] and (self.t[rest].kind == "punct" or self.t[rest].filler or self:word(rest, "please")) do
        rest = rest + 1
      end
      if rest > #self.t then
        if not p.word then self:take(p) end
        self:mark_used(s.e, p.e)
        return self:emit("DTMULT " .. f.num(p.value))
      end
    end
    -- "sim speed x2": the factor glued to its x
    for i = s.b, s.e - 1 do
      local x = self.t[i].kind == "word" and tonumber(self.t[i].text:match("^x(%d+%.?%d*)$") or "")
      if x then
        self:mark_used(i, i + 1)
        self:explain(i, i + 1)  -- a token that reads like a callsign, explained as the factor
        return self:emit("DTMULT " .. f.num(x))
      end
    end
    -- ("at twice real time": the multiplier said in words, before real time alone; "for half an hour" is a time;
    -- "unfreeze, and double the speed": straight before the segment's word, "the" between, left in the clause before)
    local m = self:word(s.trig - 1, "the") and s.trig - 2 or s.trig - 1
    for i = math.min(s.b, math.max(1, m)), s.e - 1 do
      local v = self.t[i].kind == "word" and L.multipliers[self.t[i].text]
      if v and not self:spoken_duration(i) then
        self:mark_used(i, i + 1)
        return self:emit("DTMULT " .. f.num(v))
      end
    end
    -- "at normal speed again" ("go again, normal speed": "normal" straight before the segment's word, left in the
    -- clause before, with no aircraft named: "DAL14 heading 250, resume normal speed" is the aircraft's speed)
    if self:word_in(s.b, s.e, "normal")
        or (self:word(s.trig - 1, "normal") and not self:has_ref(1, #self.t + 1, "aircraft")) then
      -- ("resume the simulation at normal speed": the rate of the OP just issued, which runs at 1x)
      local normal = self:word_in(s.b, s.e, "normal") and self:find_word(s.b, s.e, "normal") or s.trig - 1
      if self.out[#self.out] == "OP" and self:word(normal - 1, "at") then
        return self:explain(math.min(s.b, normal - 1), s.e)
      end
      -- ("CFG1FD 280 knots. After that normal speed again.": with an aircraft named in the request and no word of
      -- lexicon.sim in the segment, whose normal speed is meant is unclear: asked)
      if self:has_ref(1, #self.t + 1, "aircraft") and not self:word_in(s.b, s.e, "@sim real") then
        return self:need(string.format("Should the aircraft resume its normal speed, or the simulation run at "
          .. "real-time rate (DTMULT 1)? I heard '%s'.", (self:raw(s.b, s.e):gsub(" ([,.;:])", "%1"):gsub("[%s%p]+$", ""))))
      end
      return self:emit("DTMULT 1")
    end
    local real = self:find_word(s.b, s.e, "real")  -- "slow the clock to real time"
    -- ("slower than (the) real time": a comparison, no rate; asked below)
    local than = self:word(real - 1, "than") or (self:word(real - 1, "the") and self:word(real - 2, "than"))
    if real < s.e and self:word(real + 1, "time") and not than then
      -- "N times real time": the factor said before the segment's "real"
      for _, q in ipairs(self:word(real - 1, "times x") and self:quantities(real - 2, real - 1) or {}) do
        if not self.taken[q.b] and (q.kind == "plain" or q.kind == "mult") then
          self:take(q)
          return self:emit("DTMULT " .. f.num(q.value))
        end
      end
      return self:emit("DTMULT 1")
    end
    self:need("How many times real time should the simulation run?")
  end
  -- ("KLM12 to FL110, seed is 42 by the way": a seed told with a copula beside an aircraft's instruction may be the
  -- one the run has; asked)
  function m:seed(s)
    local q = first(self, s, { plain = true })
    if q and self:word(s.trig + 1, "is was") and self:has_ref(1, #self.t + 1, "aircraft") then
      return self:need(string.format("Should I set the random seed to %s now (SEED %s), or is it the seed the run "
        .. "already has?", f.int(q.value), f.int(q.value)))
    end
    if q then return self:emit("SEED " .. f.int(q.value)) end
    self:need("Which random seed should I set?")
  end
  -- A wind as it is reported, "270 at 15": `dir` three digits typed up to 360, "at", and `spd` a bare number
  -- of knots up to 200 straight after it (quantities): true when so
  function m:wind_reported(dir, spd)
    return dir.kind == "plain" and spd.kind == "plain" and dir.number ~= nil and dir.number.typed
      and #(dir.number.digits or "") == 3 and dir.value <= 360 and self:word(dir.e, "at") and spd.b == dir.e + 1
      and spd.value > 0 and spd.value <= 200
  end
  -- True when quantities dir and spd are a wind typed in TrafScript's order, direction then speed, ending the request
  -- ("270 30", "270, 30"): three typed digits up to 360, then a bare speed up to 200 knots straight after
  function m:wind_typed(dir, spd)
    local gap = self.t[dir.e] and self.t[dir.e].kind == "punct" and self.t[dir.e].text == "," and 1 or 0
    local e = spd.e
    while self.t[e] and (self.t[e].kind == "punct" or self.t[e].filler) do e = e + 1 end
    return dir.kind == "plain" and spd.kind == "plain" and dir.number ~= nil and dir.number.typed
      and spd.number ~= nil and spd.number.typed and #(dir.number.digits or "") == 3 and dir.value <= 360
      and spd.b == dir.e + gap and spd.value > 0 and spd.value <= 200 and e > #self.t
  end
  -- WIND lat lon [alt] dir spd: where the wind blows from ("from 270", or the heading said) and its speed
  function m:wind(s)
    local qs = self:quantities(s.b, s.e)
    local lat, lon = position(qs, s.trig, self)
    local place = not (lat and lon) and wind_place(self, s)
    if place then lat, lon = place, "" end
    if not lat or not lon then return self:need("Where should the wind be? Please give a latitude and longitude.") end
    local alt, dir, spd
    for k, q in ipairs(qs) do
      if q.kind == "alt" and not alt then alt = self:take(q) end
      if not dir and not spd and qs[k + 1] and self:wind_typed(q, qs[k + 1]) then
        dir, spd = self:take(q), self:take(qs[k + 1])
      end
      if q.kind == "speed" and not spd then spd = self:take(q) end
      -- (the direction said after "from", after "wind of", or straight before "at" and the speed: "270 at 40 kt",
      -- "270 at 40" as a wind is reported)
      -- (the speed's first token straight after "at": "two seven zero at five zero knots" too)
      local before_speed = self:word(q.e, "at") and self:quantities(q.e + 1, s.e)[1]
      if before_speed and before_speed.b ~= q.e + 1 then before_speed = nil end
      local reported = before_speed and not dir and not spd and self:wind_reported(q, before_speed)
      local said = self:word(q.b - 1, "from") or (self:word(q.b - 1, "of") and self:word(q.b - 2, "wind winds"))
        or (before_speed and before_speed.kind == "speed") or reported
      if (q.kind == "heading" or q.kind == "angle" or (q.kind == "plain" and said))
          and not dir and q.value >= 0 and q.value <= 360 then
        dir = self:take(q)
        if reported then spd = self:take(before_speed) end
      end
    end
    -- ("from the west": a compass point)
    local from = self:find_word(s.b, s.e, "from")
    local point = from < s.e and L.compass[(self.t[self:word(from + 1, "the") and from + 2 or from + 1] or {}).text or ""]
    if not dir and point then
      dir = { value = point }
      self:explain(from, self:word(from + 1, "the") and from + 3 or from + 2)
    end
    -- ("a westerly at 40 knots", "a north-westerly": the wind named by where it blows from)
    for k = math.max(1, s.b - 2), s.e - 1 do
      local named = not dir and self.t[k].kind == "word" and L.wind_points[self.t[k].text]
      if named then
        local p = (self.t[k - 1] or {}).text == "-" and k - 2 or k - 1
        local joined = self:word(p, "north south") and L.wind_points[self.t[p].text .. self.t[k].text]
        dir = { value = joined or named }
        self:explain(joined and p or k, k + 1)
      end
    end
    if not dir or not spd then
      return self:need("From which direction, and how strong in knots, should the wind blow?")
    end
    -- (a wind from the north is 360, as winds are reported: 0 is calm's direction)
    self:emit(string.format("WIND %s%s %s %s", place or (f.num(lat) .. " " .. f.num(lon)),
      alt and " " .. f.alt(alt.value, alt.fl) or "", f.num(dir.value == 0 and 360 or dir.value), f.num(spd.value)))
  end
  function m:scenario(s)
    for i = s.b, s.e - 1 do
      local t = self.t[i]
      if t.kind == "word" and t.raw:lower():find(".scn", 1, true) then return self:emit("IC " .. t.raw) end
    end
    self:need("Which scenario file should I load?")
  end
  function m:echo(s)
    for i = s.b, s.e - 1 do
      -- (an aircraft or a place said before the words, "KLM 1234 at NARSO log 'over NARSO'", is asked: a note shown
      -- when an aircraft gets somewhere is no note shown now)
      local a, w = self:refs_in(s.b, i, "aircraft")[1], self:refs_in(s.b, i, "waypoint")[1]
      if self.t[i].kind == "quoted" and (a or w) then
        return self:need(string.format("Should '%s' be shown now, or when %s? Please say which.", self.t[i].raw,
          a and w and (a.name .. " reaches " .. w.name) or ("something happens to " .. (a or w).name)))
      end
      if self.t[i].kind == "quoted" then return self:emit("ECHO " .. self.t[i].raw) end
    end
    -- the words after a colon, as typed
    for i = s.trig, s.e - 1 do
      if self.t[i].kind == "punct" and self.t[i].text == ":" and i + 1 < s.e then
        self:mark_used(i + 1, s.e)
        -- (a mark closing the message stays on its last word: "welcome Lincoln High!")
        return self:emit("ECHO " .. (self:raw(i + 1, s.e):gsub(" ([!?.])$", "%1")))
      end
    end
    -- "a note on screen saying baseline run", "a message that says trial 2": the words after, as typed
    -- (a "?" closing a polite question, "could you put a note on screen saying trial 3 begins?", closes the
    -- request, not the note; the note read as a question itself, "... saying are you ready?", is asked)
    local saying = self:find_word(s.trig + 1, s.e, "saying says reading")
    if saying + 1 < s.e then
      local e = s.e
      if self.t[e - 1].text == "?" and e - 1 == #self.t and self:word(self:skip_fillers(1), "@polite_openings")
          and self:word(self:skip_fillers(1) + 1, "you") then
        if self:word(saying + 1, "@echo_question_openers") then
          return self:need(string.format("Should the note read '%s' with the question mark, or without it?",
            self:raw(saying + 1, e - 1)))
        end
        e = e - 1
        self:explain(e, s.e)
      end
      -- (the full stop closing the request is its own mark, no part of the words: "... that says welcome visitors.")
      if e - 1 == #self.t and e - 1 > saying + 1 and self.t[e - 1].text == "." then
        e = e - 1
        self:explain(e, s.e)
      end
      self:explain(s.trig + 1, saying + 1)
      self:mark_used(saying + 1, e)
      return self:emit("ECHO " .. self:raw(saying + 1, e))
    end
    -- "print baseline no reso to the console", "print hello_3 in the console": the words between the verb
    -- and where they go, as typed ("echo the text RUN 4 START to the console": after "the text")
    -- ("echo RUN 7 START in the log": the log too)
    local to = self:find_word(s.trig + 1, s.e, "to on in into")
    local at = self:word(to + 1, "the") and to + 2 or to + 1
    local from = self:word(s.trig + 1, "the") and self:word(s.trig + 2, "text message words line") and s.trig + 3
      or s.trig + 1
    if to > from and to < s.e and self:word(at, "console screen display window log") then
      self:explain(s.trig + 1, from)
      self:mark_used(from, to)
      self:explain(to, at + 1)
      -- ("echo 'F1 done' to log": the single quotes around the words are no part of them)
      local said = self:raw(from, to)
      return self:emit("ECHO " .. (said:match("^'(.+)'$") or said))
    end
    -- "instructor: echo exercise starts in 2 minutes": TrafScript's ECHO opening the request after a
    -- speaker's label, the words after it as typed
    -- (a courtesy word closing the request, "echo test start please", is said to us, not printed)
    if s.trig == self:skip_fillers(1) and self:word(s.trig, "echo") and s.trig + 1 < s.e then
      local e = s.e
      while e - 1 > s.trig + 1 and self:word(e - 1, "please pls thanks") do e = e - 1 end
      self:explain(e, s.e)
      self:mark_used(s.trig + 1, e)
      return self:emit("ECHO " .. self:raw(s.trig + 1, e))
    end
    self:need("What text should I print?")
  end
  function m:resolution(s)
    if self.factor_named_upto and s.trig < self.factor_named_upto and self.u:used(s.trig) and self:on_off(s) < 0
        and not self:word_in(s.trig, s.e, "mvp") then
      return
    end
    -- ("vertical reso on, zonedh 1200": the resolutions' vertical speed switched, never the method)
    if self:word(s.trig - 1, "vertical vert") and self:word(s.trig + 1, "@on @off")
        and not self:word_in(1, #self.t + 1, "mvp") then
      return self:reso_vertical(s)
    end
    local b = s.b > 1 and s.b - 1 or s.b
    -- ("what's the resolution method", "?" typed or not: the method asked, when none is named and no switch said)
    local named = self:word_in(1, #self.t + 1, "mvp") or self:word_in(b, s.e, "@mvp") or self:on_off(s) >= 0
    -- ("show reso method": "show" opening the request, no method, value or other switching word said, shows it)
    local first = self:request_start()
    local shown = self:word(first, "show display") and #self:quantities(1, #self.t + 1) == 0
      and not self:word_in(first + 1, #self.t + 1, "mvp @mvp @on @off")
    if shown or self:asks_setting(not named) or not named and self:switch_asked(s) then
      -- ("is MVP resolution currently on?": the method asked about names the setting shown)
      for k = 1, #self.t do
        if self:word(k, "mvp") then self:explain(k, k + 1) end
      end
      return self:emit("RESO")
    end
    -- ("ASAS on and the MVP off", "switch off the MVP": the method named, an off word straight after it or
    -- before it)
    local mvp = self:find_word(b, s.e, "mvp")
    local p = self:word(mvp - 1, "the") and mvp - 2 or mvp - 1
    if mvp < s.e and (self:word(mvp + 1, "@off") or self:word(p, "@off")) then
      self:explain(mvp, mvp + 1)
      return self:emit("RESO OFF")
    end
    -- ("switch MVP resolution off", "MVP conflict resolution off": the method named, its noun, then an off word)
    local off = mvp + 1
    while off < s.e and off <= mvp + 3 and self:word(off, "resolution reso conflict") do off = off + 1 end
    if mvp < s.e and off > mvp + 1 and self:word(off, "@off") then
      self:explain(mvp, mvp + 1)
      return self:emit("RESO OFF")
    end
    if self:word_in(1, #self.t + 1, "mvp") or self:word_in(b, s.e, "@mvp") then
      self:emit("RESO MVP")
      return self:zone_said_with(s.trig, s.e)
    end
    -- ("switch on the conflict detection, but without resolution", "detection on, no resolution": "without" or
    -- "no" straight before the noun, detection switched on in the request, asks for detection alone; with no
    -- method set now ASAS ON detects only, and the words explain it; a method set now is switched off)
    local k = s.trig - 1
    while k > 1 and self:word(k, "the any a conflict") do k = k - 1 end
    if self:word(k, "without no") and not self:in_reason(k) and self.world.reso_method then
      local detects = false
      for _, c in ipairs(self.out) do detects = detects or c == "ASAS ON" or c:match("^CDMETHOD %u") ~= nil end
      if detects then
        if self.world.reso_method() == "OFF" then return self:explain(k, s.trig + 1) end
        return self:emit("RESO OFF")
      end
    end
    -- ("let us leave resolution off", "keep the resolution off" with no method set now: kept as it is, nothing
    -- switched)
    local kept = self:find_word(math.max(1, s.trig - 4), s.trig, "leave keep")
    if kept < s.trig and self:on_off(s) == 0 and self.world.reso_method and self.world.reso_method() == "OFF" then
      return self:explain(kept, s.trig + 1)
    end
    if self:on_off(s) == 0 then return self:emit("RESO OFF") end
    if self:on_off(s) == 1 then return self:emit("RESO MVP") end  -- MVP is the one method RESO has
    -- ("let the computer steer them apart", "have the sim solve the conflicts": the simulation asked to resolve)
    if self:word(s.trig, "solve resolve steer separate") and self:word_in(math.max(1, s.trig - 3), s.trig, "computer @sim") then
      return self:emit("RESO MVP")
    end
    -- "enable conflict detection and resolution": switched on (or off) with the detection before it
    if self:on_off(s) < 0 and self.last_on ~= nil and self:word(s.trig - 1, "and") then
      return self:emit(self.last_on == 1 and "RESO MVP" or "RESO OFF")
    end
    self:need("Which conflict resolution method should I use (for example MVP), or should it be off?")
  end
  -- RFACH / RFACV: the safety factor resolutions apply; each value is the kind said last before it
  -- ("the horizontal resolution margin factor to 1.2 and the vertical one to 1.05"); both kinds joined by "and"
  -- ("the horizontal and vertical resolution margins both to 1.1") set both
  function m:reso_factor(s)
    local b = math.max(1, s.b - 4)  -- ("with horizontal factor 1.1": the kind said before the noun)
    local function kind(e)
      for k = e - 1, b, -1 do
        local named = self:registry_word(k)  -- ("rfacv 1.1", "hrfac 1.2": the command's own name)
        if named == "RFACH" or named == "RFACV" then return { named } end
        -- ("vert", "hor", "v", "h": the directions typed short)
        local v, h = self:word(k, "vertical vert v"), self:word(k, "horizontal lateral hor h")
        if (v or h) and self:word(k - 1, "and") and self:word(k - 2, v and "horizontal lateral hor h" or "vertical vert v") then
          self:explain(k - 2, k + 1)
          return { "RFACH", "RFACV" }
        end
        if v or h then self:explain(k, k + 1) end
        if v then return { "RFACV" } end
        if h then return { "RFACH" } end
      end
      return nil
    end
    -- ("MVP horizontal margin 1.2": the method named before the factor's direction is whose factor it is)
    local m_at = self:skip_fillers(1)
    if self:word(m_at, "mvp") and m_at < s.trig and not self:intent_at(m_at) then self:explain(m_at, m_at + 1) end
    local function emit_all(cmds, value)
      for _, cmd in ipairs(cmds) do self:emit(cmd .. (value and " " .. f.num(value) or "")) end
    end
    if self:asks_setting(true) then return emit_all(kind(s.e) or { "RFACH" }) end
    local before = #self.out
    -- ("a 20 percent margin": a margin in percent, said before the noun, is the factor 1.2)
    local by_margin = self:word(s.trig, "margin margins")
    for _, q in ipairs(self:quantities(by_margin and s.b or s.trig, s.e)) do
      -- ("the vertical one": a pronoun, no value)
      local pronoun = self.t[q.b].text == "one" and self:word(q.b - 1, "vertical horizontal lateral")
      local margin = by_margin and q.kind == "percent"
      -- ("the horizontal resolution margin 1.2": a factor of 1 to 3 said after the noun is the factor itself)
      local factor = by_margin and q.kind == "plain" and not pronoun and q.b > s.trig and q.value >= 1 and q.value <= 3
      if (q.kind == "plain" and not pronoun and not by_margin) or margin or factor then
        -- ("the resolution factor to 1.2 for the horizontal dimension": the kind said after the value, "for" or
        -- "in" before it; a margin's after the noun, "add 10% margin on the horizontal resolution")
        -- ("resolution margin 1.05 horizontal and vertical", "1.2 vertical, 1.1 horizontal": the kinds straight
        -- after it, no value after them, are its own)
        -- ("margins 1.05 both h and v": "both" before them)
        local ka = self:word(q.e, "both") and q.e + 1 or q.e
        local ke = self:word(ka + 1, "and") and self:word(ka + 2, "horizontal lateral vertical hor vert h v") and ka + 3
          or ka + 1
        local after = self:word(ka, "horizontal lateral vertical hor vert h v") and #self:quantities(ke, ke + 1) == 0
          and kind(math.min(s.e, ke))
        if after and ka > q.e then self:explain(q.e, ka) end
        local cmd = after or kind(q.b) or (self:word(q.e, "for in") and kind(math.min(s.e, q.e + 4)))
          or (margin and self:word(s.trig + 1, "on for of to in") and kind(math.min(s.e, s.trig + 5)))
        local value = margin and 1 + q.value / 100 or q.value
        -- ("reso mvp, margins 1.05": the plural with no direction said names both)
        if not cmd and self:word(s.trig, "margins") and factor then cmd = { "RFACH", "RFACV" } end
        if not cmd then
          return self:need(string.format("Should the horizontal or the vertical safety factor be %s?", f.num(value)))
        end
        self:take(q)
        emit_all(cmd, value)
      end
    end
    -- ("safety factor for horizontal resolution put 1.2": the kind, "resolution" and a verb of setting said after the
    -- noun, past its own clause, then the factor of 1 to 3)
    local k = s.e
    while #self.out == before and k <= #self.t and k < s.e + 6
        and self:word(k, "for in of the horizontal lateral vertical resolution resolutions reso put set to please") do
      k = k + 1
    end
    local q = #self.out == before and k > s.e and self:quantities(k, k + 1)[1]
    if q and q.b == k and q.kind == "plain" and q.value >= 1 and q.value <= 3 and not self.u:used(k) and kind(k)
        and (q.e > #self.t or self.t[q.e].kind == "punct" or self:word(q.e, "please and")) then
      self:mark_used(s.e, k)
      self.factor_named_upto = k  -- (the resolution named in it is the factor's: m:resolution reads nothing there)
      self:take(q)
      emit_all(kind(k), q.value)
    end
    if #self.out == before then self:need("What safety factor should conflict resolution apply?") end
  end
  -- RMETHV: resolutions with vertical speed (V/S) or horizontal only (OFF)
  -- (both read their request whole: "allow vertical manoeuvres in the MVP resolutions", "resume nav
  -- once past cpa" say nothing else)
  function m:reso_vertical(s)
    -- ("which vertical reso method", "vertical resolution?": the setting asked about, shown)
    if self:asks_setting(true) and not self:word_in(1, #self.t + 1, "@on @off") then return self:emit("RMETHV") end
    -- ("rmethv off", "reso MVP, rmethv on": the command's own name, and the switch said after it)
    if self:registry_word(s.trig) and self:word(s.trig + 1, "on off") then
      self:emit(self:word(s.trig + 1, "off") and "RMETHV OFF" or "RMETHV V/S")
      return self:mark_used(s.trig, s.trig + 2)
    end
    local all = #self.t + 1
    -- ("MVP can use vertical also or not?", "vertical resolution, allow or not allow?"): "or not"/"or no" is a
    -- yes-no question's other answer, up to punctuation, no switching off; with nothing said after its clause
    -- the request is the question alone, asked; a clause after it ("..., please allow it") is read
    local tag_b, tag_e
    for k = 1, #self.t - 1 do
      if self:word(k, "or") and self:word(k + 1, "not no") then
        tag_b, tag_e = k, k + 2
        while tag_e < all and self.t[tag_e].kind ~= "punct" do tag_e = tag_e + 1 end
        break
      end
    end
    if tag_b then
      local rest = false
      for j = tag_e, #self.t do
        if self.t[j].kind ~= "punct" then rest = true end
      end
      if not rest then
        return self:need("Should conflict resolution use vertical speed too (RMETHV V/S) or stay horizontal only "
          .. "(RMETHV OFF)? 'or not' asks, it chooses neither.")
      end
    end
    -- ("use vertical speed as well, not just heading and speed": "not just" adds, G:additive_not; its "only" or
    -- "just" limits nothing)
    local off, only = false, false
    for k = 1, #self.t do
      local additive = self:additive_not(k) or self:additive_not(k - 1) or (tag_b and k >= tag_b and k < tag_e)
      -- ("vertical reso none": no method, off)
      off = off or (self:word(k, "@off no not never none") and not additive)
        -- ("close vertical resolution", "please close it": "open"'s opposite, as a switch is closed, is off)
        or (self:word(k, "close shut") and self:word(k + 1, "it the vertical resolution resolutions reso rmethv"))
      only = only or (self:word(k, "only") and not additive)
    end
    -- ("turn off lateral resolution", "horizontal resolutions off", "only resolve vertically"): the
    -- horizontal resolutions switched, RMETHH, which squawk lacks: asked, never RMETHV switched instead
    -- (the two words after k, up to punctuation: "vertical reso method off, horizontal only" is RMETHV OFF)
    local function after(k)
      local e = math.min(all, k + 3)
      for j = k + 1, e - 1 do
        if self.t[j].kind == "punct" then return j end
      end
      return e
    end
    for k = 1, #self.t do
      local e = after(k)
      -- (horizontal manoeuvres named by their kind, "not heading and speed")
      local horizontal_off = self:word(k, "@off no not never") and not self:additive_not(k)
        and self:word_in(k + 1, e, "horizontal lateral heading headings speed speeds")
        and not self:word_in(k + 1, e, "vertical vertically")
      local off_horizontal = self:word(k, "horizontal lateral") and self:word_in(k + 1, e, "@off")
      local vertical_only = self:word(k, "only") and not self:additive_not(k - 1) and (self:word(k - 1, "vertical vertically")
        or (self:word_in(k + 1, e, "vertical vertically") and not self:word_in(k + 1, e, "@off no not never")))
      if horizontal_off or off_horizontal or vertical_only then
        return self:need("squawk's resolutions are horizontal only (RMETHV OFF) or horizontal with vertical "
          .. "speed too (RMETHV V/S); horizontal resolutions cannot be switched off: which should it use?")
      end
    end
    -- ("vertical resolutions only": no method of squawk's; resolutions are horizontal, or horizontal
    -- with vertical speed too)
    if only and not off and not self:word_in(1, all, "horizontal lateral") then
      return self:need("squawk's resolutions are horizontal only (RMETHV OFF) or horizontal with vertical "
        .. "speed too (RMETHV V/S): which should it use?")
    end
    -- (read at "horizontal": horizontal alone, G:vertical_resolutions)
    -- ("not only horizontal": horizontal and more, vertical speed too)
    local horizontal_alone = self:word(s.trig, "horizontal lateral") and not self:additive_not(s.trig - 2)
    -- (its clause whole: "turn on MVP resolution and allow vertical manoeuvres" reads "allow" with the vertical;
    -- "MVP with vertical", "MVP and vertical", opening the request: the method named there and read by nothing else
    -- is set first; "let MVP use vertical speed" names whose resolutions they are)
    local lo, hi = self:clause_around(s.trig)
    local from, to = math.min(s.b, lo), math.max(s.e, hi)
    local mvp = self:skip_fillers(1)
    local joined = self.t[mvp + 1] and (self.t[mvp + 1].text == "," or self.t[mvp + 1].raw:lower() == "w/"
      or self.t[mvp + 1].raw == "+")
    if self:word(mvp, "mvp") and (self:word(mvp + 1, "with and plus w no") or joined)
        and not self:word(mvp + 1, "@off") and not self.u:used(mvp) then
      self:emit("RESO MVP")
    end
    self:emit((off or only or horizontal_alone) and "RMETHV OFF" or "RMETHV V/S")
    self:mark_used(from, to)
  end
  function m:resume_nav(s)
    if self:asks_setting() then return self:emit("RESNAV") end
    self:emit("RESNAV PASTCPA")  -- the one way squawk resumes navigation after a resolution
    self:mark_used(s.b, s.e)
  end
  -- True when a correction is said in [b, e): a correction word (lexicon.correction), or a self-correction marker
  -- (lexicon.self_correction.markers, one word) after a mark ("4 times faster, no, 5", "1000 feet, sorry, 1500").
  function m:corrected_between(b, e)
    for i = b, e - 1 do
      if self:word(i, "@correction") then return true end
      if i > 1 and self.t[i - 1].kind == "punct" and self.t[i].kind == "word" and SC_MARKER_WORD[self.t[i].text] then
        return true
      end
    end
    return false
  end
  function m:zone(s)
    local vertical = self:word_in(s.b, s.e, "@vertical") or self:registry_word(s.trig) == "ZONEDH"
    -- ("give IBE32 1000 ft of separation from RYR7QD": one aircraft kept apart from another named, which
    -- squawk does not fly; no protected zone, no level)
    local k = self:word(s.trig, "separation") and self:word(s.trig + 1, "from with")
      and (self:word(s.trig + 2, "the") and s.trig + 3 or s.trig + 2)
    if k and (self:has_ref(s.trig + 2, k + 1, "aircraft") or self:airline_at(k)) then
      return self:need("squawk keeps no aircraft apart from another by itself: what level, heading or speed "
        .. "should it fly?")
    end
    if self:asks_setting(true) and #self:quantities(s.b, s.e) == 0 then
      return self:emit(vertical and "ZONEDH" or "ZONER")
    end
    -- ("Is the protected zone half height still 1000 feet?": a yes-no question about its value shows the
    -- setting, the value said being the one asked about; never set; a value said after the question is asked about)
    if self:word(self:request_start(), "is are") and self:asks_setting(true) then
      local q = 1
      while self.t[q] and self.t[q].text ~= "?" do q = q + 1 end
      if #self:quantities(q + 1, #self.t + 1) > 0 then
        return self:need("Should the protected zone be shown, or set? Please say the value to set alone.")
      end
      self:mark_used(s.b, s.e)
      return self:emit(vertical and "ZONEDH" or "ZONER")
    end
    local before = #self.out
    local heights = {}  -- { value (ft), index of its ZONEDH line in self.out }
    local qs, named = {}, false
    -- a value before the zone's word is its own only with a unit, said just before it ("a 3 mile PZ";
    -- "detection on with a 3 mile PZ", where detection set it already), or the other dimension paired
    -- with that one just before it ("a 5nm / 1000ft zone", "5 nm and 1000 ft zone": a distance and a
    -- height joined by one mark or "and" or "by"); a bare number there ("Run 2 setup: ZONER 5") is not
    local last
    for _, q in ipairs(self:quantities(math.max(1, s.trig - 3), s.trig)) do
      if (q.kind == "dist" or q.kind == "alt") and self:skip_fillers(q.e) == s.trig then
        if self.taken[q.b] then named = true else qs[#qs + 1] = q end
        last = q
      end
    end
    if last and last.b > 2 and (self.t[last.b - 1].kind == "punct" or self:word(last.b - 1, "and by")) then
      local pair = last.kind == "dist" and "alt" or "dist"
      for _, q in ipairs(self:quantities(math.max(1, last.b - 4), last.b - 1)) do
        if q.kind == pair and q.e == last.b - 1 and not q.fl then
          if self.taken[q.b] then named = true else qs[#qs + 1] = q end
        end
      end
    end
    for _, q in ipairs(self:quantities(s.b, s.e)) do
      -- (not "one" standing for a zone in a remark set aside: "? In my thesis we use a smaller one.")
      if (q.kind ~= "plain" or q.b > s.trig) and not (qs[1] and qs[1].b == q.b)
          and not (self:aircraft_count(q) and self:in_reason(q.b)) then
        qs[#qs + 1] = q
      end
    end
    table.sort(qs, function(a, b) return a.b < b.b end)
    for _, q in ipairs(qs) do
      -- a plain value is the dimension named last before it ("zoner 3 zonedh 500")
      local dim, at
      for i = q.b - 1, s.b, -1 do
        if self:word(i, "@vertical") or self:registry_word(i) == "ZONEDH" then vertical, dim, at = true, "v", i break end
        if self:word(i, "@zone_radius") or self:registry_word(i) == "ZONER" then vertical, dim, at = false, "r", i break end
      end
      -- a value whose unit is the other dimension's, said straight after the dimension's name: a radius in metres
      -- is its conversion to 0.01 NM ("zoner 9000 m" = 4.86 NM); a radius in feet or a level, or a half height as
      -- a distance, is asked ("5 miles radius and 1000 ft half height" names each after its value)
      for i = (at or q.b) + 1, q.b - 1 do
        if self:word(i, "and") or not (self.t[i].filler or self.t[i].text == ":" or self:word(i, "to of at is =")) then
          dim = nil
        end
      end
      if (dim == "r" and q.kind == "alt") or (dim == "v" and q.kind == "dist") then
        if dim == "r" and not q.fl and (self:word(q.e - 1, "@metres")) and q.number then
          self:take(q)
          self:emit("ZONER " .. f.num(math.floor(q.number.value / 1852 * 100 + 0.5) / 100))
          goto next_value
        end
        return self:need(string.format("%s, in %s, should the protected zone have? I heard '%s'.",
          dim == "r" and "What radius" or "What half-height", dim == "r" and "nautical miles" or "feet",
          self:raw(q.b, q.e)))
      end
      if q.kind == "dist" or (q.kind == "plain" and not vertical) then self:emit("ZONER " .. f.num(q.value)) end
      if q.kind == "alt" or (q.kind == "plain" and vertical) then
        -- ("PZ height 2000 ft total": the zone's whole height, twice the half ZONEDH takes)
        local total = vertical and self:word(q.e, "total")
        if total then self:mark_used(q.e, q.e + 1) end
        local v = self:take(q).value / (total and 2 or 1)
        self:emit("ZONEDH " .. f.num(v))
        heights[#heights + 1] = { v, #self.out, total, q = q }
      end
      ::next_value::
    end
    -- ("(±1000 ft)": a height either side of the aircraft, the half height itself)
    for x = s.b, s.e - 1 do
      local n = self.t[x].text:match("^\194\177(%d+)$")
      if n and vertical and self:word(x + 1, "@feet") then
        self:mark_used(x, x + 2)
        self:emit("ZONEDH " .. n)
        heights[#heights + 1] = { tonumber(n), #self.out, true }
      end
    end
    if #heights == 2 and heights[1][1] == heights[2][1] then table.remove(self.out, heights[2][2]) end
    -- two vertical values are the separation and its half ("separation 1000 ft, half height 500"):
    -- ZONEDH takes the half; any other pair contradicts itself and is asked, as is any pair of halves that differ
    -- (a whole height halved, "2000 ft total", or one either side, "±1000 ft", is a half already)
    local halves = #heights == 2 and heights[1][3] and heights[2][3]
    -- ("half height 1000 feet, no, 1500 please": the height after a correction replaces the one before it)
    if #heights == 2 and heights[1][1] ~= heights[2][1] and heights[1].q and heights[2].q
        and self:corrected_between(heights[1].q.e, heights[2].q.b) then
      table.remove(self.out, heights[1][2])
      heights = {}
    end
    if #heights == 2 and heights[1][1] ~= heights[2][1] then
      local lo, hi = heights[1], heights[2]
      if lo[1] > hi[1] then lo, hi = hi, lo end
      if halves or hi[1] ~= 2 * lo[1] then
        return self:need("Which half-height, in feet, should the protected zone have: "
          .. f.num(heights[1][1]) .. " or " .. f.num(heights[2][1]) .. "?")
      end
      table.remove(self.out, hi[2])
    end
    -- ("restore the protected zone to the standard 5 NM radius", "5 miles and 1000 feet, like the standard",
    -- "... 1000 feet and radius 5 miles, standard values please"): "standard" or "default" names the values said when
    -- each is BlueSky's own (5 NM radius, 1000 ft half height): the word is accounted for; beside any other value
    -- it is left to ask what it means
    local defaults = #self.out > before
    for x = before + 1, #self.out do
      defaults = defaults and (self.out[x] == "ZONER 5" or self.out[x] == "ZONEDH 1000")
    end
    if defaults then
      for x = 1, #self.t do
        if self:word(x, "standard default") and not self:word(x + 1, "speed rate turn route routing arrival departure star sid") then
          self:mark_used(x, self:word(x + 1, "value values setting settings") and x + 2 or x + 1)
        end
      end
    end
    if #self.out == before and not named then
      self:need(vertical and "What half-height, in feet, should the protected zone have?"
        or "What radius, in nautical miles, should the protected zone have?")
    end
  end
  -- TRAIL acid colour ("show KL204's trail in red"), else TRAIL ON/OFF with
  -- the time between trail points when one is said ("trails every 5 s")
  function m:trail(s)
    local at = self:find_word(s.b, s.e, "@trail_colours")
    if at < s.e then
      -- ("trails on and make Delta 1422's trail red": the trails switched before "and" or a comma, the colour after
      -- it; both run, the switch first)
      local cut = at - 1
      while cut > s.b and not (self:word(cut, "and") or self.t[cut].text == ",") do cut = cut - 1 end
      if cut > s.trig and self:on_off({ b = s.b, e = cut, trig = s.trig }) >= 0 then
        self:emit("TRAIL " .. (self:on_off({ b = s.b, e = cut, trig = s.trig }) == 1 and "ON" or "OFF"))
        s = { b = cut + 1, e = s.e, trig = at, intent = s.intent }
      end
      local id = self:acid(s, "get a trail colour")
      if id then self:emit("TRAIL " .. id .. " " .. self.t[at].text:upper()) end
      return
    end
    local q = first(self, s, { time = true })
    -- ("trails on, one dot every 5 seconds": the trail's points named by what they look like, one per interval)
    for k = s.b, q and q.b or 0 do
      if self:word(k, "dot dots blip blips") and self:word_in(k + 1, q.b, "every each per") then
        self:explain(self:word(k - 1, "one a") and k - 1 or k, k + 1)
      end
    end
    -- ("clear trails": neither shown nor hidden said, no interval and no switch before it: asked)
    -- ("draw trails behind the aircraft", "display the trails", "give every plane a trail", "add trail lines",
    -- "set up trails for all tracks", "to see the trails displayed": shown)
    local drawn = self:word_in(math.max(1, s.b - 4), s.e, "draw display give add drawn displayed")
    for k = math.max(1, s.b - 4), s.e - 1 do
      drawn = drawn or (self:word(k, "set") and self:word(k + 1, "up"))
    end
    if drawn then self.last_on = self:on_off(s) < 0 and 1 or self.last_on end
    if self:on_off(s) < 0 and not q and self.last_on == nil
        and not self:word_in(math.max(1, s.b - 2), s.b, "@on @off") then
      return self:need("Should the trails be shown (TRAIL ON) or hidden (TRAIL OFF)?")
    end
    -- (the switch said just before the segment: "dtmult 6 and hide trails")
    local before = self:on_off(s) < 0 and self:on_off({ b = math.max(1, s.b - 2), e = s.b }) or -1
    local switch = before >= 0 and (before == 1 and "ON" or "OFF") or on_off(self, s)
    self:emit("TRAIL " .. switch .. ((q and switch == "ON") and (" " .. f.num(q.value)) or ""))
  end
  function m:look_ahead(s)
    local q = first(self, s, { time = true, plain = true })
    -- "a 180 s lookahead": the time said just before the word
    for _, b in ipairs(q and {} or self:quantities(math.max(1, s.trig - 3), s.trig)) do
      if b.kind == "time" and b.e == s.trig and not self.taken[b.b] then q = self:take(b) end
    end
    if q then
      -- ("look ahead 5 min, correction, 4": the time said in place of the one taken back)
      local fixed = q.kind == "time" and corrected_time(self, s, q)
      if fixed then return self:emit("DTLOOK " .. f.num(fixed)) end
      self:emit("DTLOOK " .. f.num(q.value))
      -- ("look-ahead 180 s, evaluated every 1 s", "look ahead 300 s, checked each 5 seconds": a time after "every"
      -- or "each" later in the look-ahead's segment is how often detection runs, DT ASAS in seconds)
      for _, r in ipairs(self:quantities(q.e, s.e)) do
        if r.kind == "time" and not self.taken[r.b] and self:word(r.b - 1, "every each") then
          return self:emit("DT ASAS " .. f.num(self:take(r).value))
        end
      end
      return
    end
    if self:asks_setting(true) then return self:emit("DTLOOK") end
    self:need("How far ahead, in seconds, should conflict detection look?")
  end
end
