-- Handlers of the value instructions (ALT, SPD, HDG, VS, and "maintain" and
-- bare values that pick one of them); see translate/handlers.lua for the
-- handler contract. Relative values read the aircraft's current state from
-- the traffic; without it they ask.
return function(H, f, wrap, compass)
  local m = H.methods
  local L = require("translate.lexicon")
  local types = require("translate.types")
  -- A level said in metres, converted to feet [ft], as cleared: the nearest 100 ft (within 15 m of the metres
  -- said, as an altitude selector sets it and as China's metric level table reads below 8900 m: 8100 m = 26600)
  local function metres_level(ft) return math.floor(ft / 100 + 0.5) * 100 end
  -- the one-word markers of lexicon.self_correction.markers, a word list (G:word's form), and the markers of
  -- several words as lists of their words ("make that": "that" alone, "That's the Air France, right?", marks
  -- no correction)
  local SIDE_MARKERS, SIDE_PHRASES = {}, {}
  for _, marker in ipairs(L.self_correction.markers) do
    local words = {}
    for w in marker:gmatch("%a+") do words[#words + 1] = w end
    if #words == 1 then SIDE_MARKERS[#SIDE_MARKERS + 1] = words[1] else SIDE_PHRASES[#SIDE_PHRASES + 1] = words end
  end
  SIDE_MARKERS = table.concat(SIDE_MARKERS, " ")
  -- True when a self-correction marker is said in [b, e).
  local function marker_in(self, b, e)
    if self:word_in(b, e, SIDE_MARKERS) then return true end
    for k = b, e - 1 do
      for _, words in ipairs(SIDE_PHRASES) do
        local all = k + #words <= e
        for n = 1, all and #words or 0 do all = all and self.words[k + n - 1] == words[n] end
        if all then return true end
      end
    end
    return false
  end

  function m:infer(s)
    local qs = self:quantities(s.b, s.e)
    for _, q in ipairs(qs) do
      -- ("... below FL120" with no verb: a bound or a condition, never a level to fly)
      if q.kind == "alt" and self:word(q.b - 1, "above below") then
        return self:need(string.format("What should happen %s? A level to fly needs its verb; a speed held "
          .. "from a level is said 'Mach .78 above FL300'.", self:raw(q.b - 1, q.e)))
      end
      if q.kind == "alt" or (q.kind == "plain" and q.number.thousand) then return self:altitude(s) end
      if q.kind == "speed" or q.kind == "mach" then return self:speed(s) end
      if q.kind == "heading" then return self:heading(s) end
      if q.kind == "vs" then return self:vspeed(s) end
      if q.kind == "lat" then
        -- a position with no verb: never a MOVE unless move/reposition/place was said
        return self:need("What should happen at that position: a waypoint, direct to it, or moving the aircraft there?")
      end
      if q.kind == "mult" then return self:time_mult(s) end
      if q.kind == "angle" and q.turn ~= 0 then return self:heading(s) end  -- "15 deg left", "20 right"
    end
    for _, q in ipairs(qs) do
      local n = q.number
      if q.kind == "plain" and not n.typed and n.groups == 3 and n.lead_digit and q.value <= 360 and not n.hundred
          and not n.decimal then
        -- "WZZ1234 to three six zero": a level as much as a heading, with no word to say which
        -- ("come right to zero nine zero": a side said before it makes it a turn)
        if self:word(q.b - 1, "to") and not self:word(q.b - 2, "left right") then
          return self:need(string.format("Heading %s or flight level %s? Please say which.", f.int(q.value),
            f.int(q.value)))
        end
        -- ("BAW5 two four zero", "EWG7, three one zero": three digits said straight after the callsign, no word
        -- before them and none led by zero, name a heading, a flight level or a speed alike: asked)
        -- (a hesitation between, "ah em ...", a mark or a word squawk does not know, is no word before them)
        local p = q.b - 1
        while p > s.b and (self.t[p].filler or self.t[p].kind == "punct" or self:word(p, "@hesitations")
            or (self.t[p].kind == "word" and not self:known_word(p) and #self:refs_in(p, p + 1) == 0)) do
          p = p - 1
        end
        local r = self:refs_in(s.b, q.b, "aircraft")
        r = r[#r]
        if r and r.e == p + 1 and not n.digits:find("^0") then
          return self:need(string.format("Heading %s, flight level %s or %s knots for %s? Please say which.",
            f.int(q.value), f.int(q.value), f.int(q.value), r.name:upper()))
        end
        return self:heading(s)
      end
    end
    -- ("QTR1015 fly 100": a bare number after "fly", said to one aircraft, is a heading or a level: the question that
    -- fits names both, a heading only up to 360)
    local ids = self:acids(s)
    for _, q in ipairs(qs) do
      if q.kind == "plain" and not q.number.decimal and #ids == 1 and self:word(q.b - 1, "fly") then
        if q.value >= 1 and q.value <= 360 then
          return self:need(string.format("Should %s fly heading %03d or flight level %03d? Please say which.", ids[1],
            q.value, q.value))
        end
        return self:need(string.format("Should %s fly flight level %d? Please say the level with 'FL'.", ids[1], q.value))
      end
    end
    -- ("LOT771", "LOT771?": a callsign alone, asked about or not, is shown)
    local e = self.t[s.e - 1] and self.t[s.e - 1].text == "?" and s.e - 1 or s.e
    if #self:acids(s) > 0 and #qs == 0 and #self:refs_in(s.b, e, "aircraft") == 1 and e - s.b == 1 then
      return self:one_acid(s, "POS", "be shown")
    end
    self:need(require("translate.grammar").not_understood)
  end

  -- The question a flight level read from quantity q as ft [ft] raises for aircraft id, or nil: "flight level
  -- 9000" (levels have three digits), a spoken level below 3000 ft (flight levels start above the transition
  -- altitude: "flight level two zero" lost a digit), one above 60000 ft ("flight level eight zero two").
  function m:level_doubt(q, ft, id)
    if q.number.value >= 1000 then
      return "Which flight level for " .. id .. "? I heard flight level " .. f.int(q.number.value) .. "."
    end
    if (ft < 3000 and not q.number.typed) or ft > 60000 then
      return "Which flight level for " .. id .. "? I heard " .. f.alt(ft, true) .. "."
    end
    return nil
  end

  -- The question a spoken number q with no "thousand" or "hundred", about to be read as ft [ft] (its value in
  -- thousands), raises for aircraft id, or nil; now is the aircraft's state (or nil), dir and verb the motion said:
  --  * after level words ("flight level", "level", "fl") the flight level heard is short of its digits; after
  --    "altitude" or "alt" with a hesitation, a filler or punctuation between ("altitude uh one", "flight
  --    level... eh... one") the level was broken off: either way the rest of the number is unheard;
  --  * a single number word read as thousands of feet more than lexicon.bare_thousands_reach [ft] from the
  --    aircraft's present level, the way the verb says or with no way said ("descend one" at FL250): a level cut
  --    short ("one..." of FL1xx) as much as 1000 ft. A reading against the verb is asked after (a climb to a lower
  --    level).
  function m:short_level_doubt(q, ft, now, dir, id, verb)
    local first = q.b
    while first < q.e and not self.t[first].number_word do first = first + 1 end
    local k, broken = first - 1, false
    while k >= 1 and (self.t[k].kind == "punct" or self.t[k].filler) do k, broken = k - 1, true end
    if self:word(k, "level fl") or (broken and self:word(k, "altitude alt")) then
      local said = self:word(k, "level fl") and "flight level" or "altitude"
      return string.format("Which %s for %s? I heard '%s' and then only '%s'.", said, id,
        self:word(k - 1, "flight") and self:raw(k - 1, k + 1) or self.t[k].raw, self:raw(first, q.e))
    end
    local words = 0
    for x = first, q.e - 1 do
      if self.t[x].number_word then words = words + 1 end
    end
    local cur = now and now.alt_ft
    if words ~= 1 or not cur or math.abs(ft - cur) <= L.bare_thousands_reach
        or (dir > 0 and ft < cur) or (dir < 0 and ft > cur) then
      return nil
    end
    return string.format("%s is at %s ft: %s to %s ft? I heard '%s' alone, with no 'thousand' or flight level.",
      id, f.int(cur), verb, f.int(ft), self.t[first].raw)
  end

  function m:maintain(s)
    local qs = self:quantities(s.b, s.e)
    for _, q in ipairs(qs) do
      if q.b >= s.trig then
        if q.kind == "speed" or q.kind == "mach" then return self:speed(s) end
        if q.kind == "alt" then return self:altitude(s) end
      end
    end
    for _, q in ipairs(qs) do
      if q.b >= s.trig then
        if q.kind == "heading" then return self:heading(s) end
        -- ("maintain decimal eight three", "maintain .83": a decimal fraction below one, a Mach number's form, is the
        -- speed kept)
        if q.kind == "plain" and q.number.decimal and q.value >= 0.3 and q.value < 1 then return self:speed(s) end
        if q.kind == "plain" then
          -- "maintain two five zero" is a speed; "maintain four thousand" an altitude.
          -- so is a value with knots one word further on ("maintain two one, uh, turn knots")
          local k = self:skip_fillers(q.e)
          local knots = self:word(k, "@speed_units") or self:word(self:skip_fillers(k + 1), "@speed_units")
            -- ("maintain 280 or greater": a speed's bound; a level's is "or above")
            or (self:word(k, "or") and self:word(k + 1, "greater faster"))
          -- ("climb FL310 and maintain three one zero", "descend to flight level one two zero and maintain, one two
          -- zero": a bare number whose hundreds of feet are a level said before it in the request, no aircraft named
          -- between, is that level restated, no speed)
          if not knots and not q.number.thousand and not q.number.hundred then
            for _, r in ipairs(self:quantities(1, s.trig)) do
              if r.kind == "alt" and math.abs(r.value - q.value * 100) < 1 and #self:refs_in(r.e, s.trig, "aircraft") == 0 then
                self:acids(s)
                self:take(q)
                return
              end
            end
          end
          -- "keep it at 230", typed with no unit: a flight level or a speed? The aircraft's own present
          -- level or speed says which is kept; otherwise asked
          if q.number.typed and not knots and q.value >= 100 and q.value <= 400 and q.value == math.floor(q.value)
              and not q.number.thousand and not q.number.hundred and not q.number.digits:find("^0") then
            local ids = self:acids(s)
            local now = ids[1] and self:state(ids[1])
            local level = now and math.abs((now.alt_ft or 0) - q.value * 100) < 50
            local speed = now and math.abs((now.cas_kt or 0) - q.value) < 3
            if level and not speed then return self:altitude(s) end
            if speed and not level then return self:speed(s) end
            -- ("cancel the speed restriction... no, just maintain 250": the speed named before it, no level
            -- or climb named anywhere, says which)
            if self:word_in(1, s.trig, "speed spd airspeed") and not self:word_in(1, #self.t + 1,
                "level altitude alt fl flight climb climbing descend descending descent feet ft height") then
              return self:speed(s)
            end
            return self:need(string.format("Should %s fly FL%03d or %d knots? I heard '%s'.", ids[1] or "it",
              q.value, q.value, self:raw(q.b, q.e)))
          end
          if (q.value >= 100 and q.value <= 400 or knots) and not q.number.thousand and not q.number.hundred then
            -- (spoken with no unit, "maintain two niner zero" is the level kept when it is the aircraft's own
            -- present level and not its present speed)
            local ids = self:acids(s)
            local now = not knots and ids[1] and self:state(ids[1])
            if now and math.abs((now.alt_ft or 0) - q.value * 100) < 50 and math.abs((now.cas_kt or 0) - q.value) >= 3 then
              return self:altitude(s)
            end
            return self:speed(s)
          end
          return self:altitude(s)
        end
      end
    end
    -- "mach 0.84 maintain please", "FL240 keep": the value with its unit said just before the verb (verb-final
    -- order)
    local last = qs[#qs]
    if last and last.b < s.trig and self:skip_fillers(last.e) == s.trig then
      if last.kind == "speed" or last.kind == "mach" then return self:speed(s) end
      if last.kind == "alt" then return self:altitude(s) end
      if last.kind == "heading" then return self:heading(s) end
    end
    local h = self:find_word(s.trig, s.e, "heading")
    if h < s.e then
      -- ("maintain... ah, whatever, just give it a heading": a verb that gives or sets, said between, opens an
      -- instruction of its own that names no heading; the heading kept is never read across it: asked)
      if self:word_in(s.trig + 1, h, "@recipient_verbs @setting_verbs") then
        local ids = self:acids(s)
        return self:need(string.format("What heading should %s fly? '%s' names no heading.", ids[1] or "it",
          (self:raw(s.trig, h + 1):gsub(" ([,.;:])", "%1"))))
      end
      return self:heading(s)
    end
    -- "maintain present speed": the speed instruction that follows says it
    if #qs == 0 and self:word(s.e, "speed spd airspeed") then
      self:acids(s)  -- the aircraft it names is the speed instruction's subject
      return
    end
    -- "maintain present altitude": the current level, read from the traffic
    self:altitude(s)
  end

  -- The altitude [ft] of a flight level said group-wise in words ("one hundred twenty": FL120, 12000): spoken,
  -- with "hundred", a whole ten within lexicon.groupwise_levels [FL]; nil for any other quantity.
  function m:groupwise_level(q)
    local n = q.number
    if q.kind ~= "plain" or not n or n.typed or not n.hundred then return nil end
    if q.value % 10 ~= 0 or q.value < L.groupwise_levels[1] or q.value > L.groupwise_levels[2] then return nil end
    return q.value * 100
  end

  -- "Climb or descend?" when both are said of one instruction in [b, e) for aircraft `id` (G:opposite_motions);
  -- true when asked.
  function m:motions_asked(b, e, id)
    local up, down = self:opposite_motions(b, e)
    if up then
      self:need(string.format("Climb or descend? I heard '%s' and '%s' for %s, with no correction between.",
        self.t[up].raw, self.t[down].raw, id))
    end
    return up ~= nil
  end

  function m:altitude(s)
    local ids = self:acids(s)
    if #ids == 0 then return self:need("Which aircraft should change altitude? Please give its callsign.") end
    if self:motions_asked(s.b, s.e, ids[1]) then return end
    local qs = self:quantities(s.b, s.e)
    local rate
    local with_unit, plain = {}, {}
    -- ("expedite climb through FL200": a level said after "through" is one to pass, no level to fly to)
    local passed
    for _, q in ipairs(qs) do
      if q.kind == "vs" and not rate then rate = self:take(q) end
      if (q.kind == "alt" or (q.kind == "plain" and q.b >= s.trig)) and self:word(q.b - 1, "through thru") then
        passed = passed or q
      else
        if q.kind == "alt" then with_unit[#with_unit + 1] = q end
        if q.kind == "plain" and q.b >= s.trig then plain[#plain + 1] = q end
      end
    end
    -- ("climb and maintain 17000, above one zero thousand increase speed to 300": a level straight after "above" or
    -- "below" is a bound or a condition, never the level flown while another is said)
    local function unbound(list)
      local kept = {}
      for _, q in ipairs(list) do
        if not self:word(q.b - 1, "@above @below") then kept[#kept + 1] = q end
      end
      return kept
    end
    local free_unit, free_plain = unbound(with_unit), unbound(plain)
    if #free_unit + #free_plain > 0 then with_unit, plain = free_unit, free_plain end
    if passed and #with_unit == 0 and #plain == 0 then
      return self:need(string.format("Which level should %s fly to? '%s' is a level to pass, not one to level off at.",
        ids[1], self:raw(passed.b - 1, passed.e)))
    elseif passed then
      self:take(passed)
      self:explain(passed.b - 1, passed.b)
    end
    -- the first value (plain ones first) that fits, taken out of its list as the vertical speed
    local function take_rate(fits)
      for _, list in ipairs({ plain, with_unit }) do
        for k, q in ipairs(list) do
          if fits(q) then return self:take(table.remove(list, k)) end
        end
      end
    end
    -- "rate fifteen hundred": a plain number after "rate" is the vertical speed (a rate said as a manner, "at a
    -- good rate", G:rate_manner, names none)
    local rate_word = self:find_word(s.b, s.e, "rate")
    if not rate and rate_word < s.e and not self.u:used(rate_word) then
      rate = take_rate(function(q) return not q.fl and self:rate_value(rate_word, q) end)
    end
    -- "descend flight level one two zero at one thousand five hundred": a number with no unit straight after
    -- "at" after the level, in whole hundreds within lexicon.rate_after_level (ft/min; no level or speed of
    -- that size), is the vertical speed; so after a flight level said bare ("descend 340 at 1500": 10 to 600)
    local lvl = with_unit[1]
    if not lvl and plain[1] and plain[1].value >= 10 and plain[1].value <= 600 then
      lvl = { fl = true, e = plain[1].e }
    end
    if not rate and lvl and lvl.fl then
      local at = self:skip_fillers(lvl.e)
      rate = take_rate(function(q)
        return q.b == at + 1 and self:word(at, "at") and not q.fl and q.value % 100 == 0
          and q.value >= L.rate_after_level[1] and q.value <= L.rate_after_level[2]
          and not self:word_in(q.b, q.e, "@feet") and not self:word(q.e, "@feet")
      end)
    end
    local now = self:state(ids[1])
    -- "FL240 -> FL250", "from FL240 to FL250", "leaving FL240 for FL250": the level it leaves, then the one it
    -- flies to
    local a, b = with_unit[1], with_unit[2]
    if b then
      local arrow, words = false, 0
      for k = a.e, b.b - 1 do
        local t = self.t[k]
        if t.kind == "punct" and t.raw:find(">", 1, true) then arrow = true end
        if t.kind ~= "punct" then words = words + 1 end
      end
      if (arrow and words == 0) or self:level_left(a, b) or self:value_left(a, b, now and now.alt_ft, 50) then
        self:take(a)
        self:explain(a.b, b.b)
        table.remove(with_unit, 1)
      end
    end
    -- "alt 4000 -> 2500", "alt 12000 ft -> 15000": a level with no unit on either side of an arrow (nothing else
    -- between), the first the aircraft's present altitude (within 50 ft): the level it leaves, then the one it flies
    -- to (one not its present altitude is left, and asked about)
    local first_q, next_q = plain[1], nil
    if with_unit[1] and (not first_q or with_unit[1].b < first_q.b) then first_q = with_unit[1] end
    for _, q in ipairs(plain) do
      if first_q and q.b > first_q.b and (not next_q or q.b < next_q.b) then next_q = q end
    end
    if first_q and next_q and (first_q.kind == "plain" or next_q.kind == "plain") and now and now.alt_ft
        and math.abs(first_q.value - now.alt_ft) <= 50 and not first_q.fl then
      local arrow, words = false, 0
      for k = first_q.e, next_q.b - 1 do
        local t = self.t[k]
        local arrow_k = t.raw:match("^%-*>$") ~= nil
        arrow = arrow or arrow_k
        if t.kind ~= "punct" and not arrow_k and not self:word(k, "@feet") then words = words + 1 end
      end
      if arrow and words == 0 then
        self:take(first_q)
        self:explain(first_q.b, next_q.b)
        for _, list in ipairs({ with_unit, plain }) do
          for k, q in ipairs(list) do
            if q == first_q then table.remove(list, k) break end
          end
        end
      end
    end
    -- "8900 metres, that is flight level 291": one level said in metres and restated in feet or as a flight
    -- level (China's metric table rounds to within 100 ft); the restatement counts, a disagreement is asked
    a, b = with_unit[1], with_unit[2]
    local function metric(q) return self:word(q.e - 1, "@metres") end
    -- (with only a comma between, "10700 metres, flight level 351", the two agreeing restate one level)
    local comma_only = b ~= nil and b.b > a.e and math.abs(a.value - b.value) <= 100
    if comma_only then
      for k = a.e, b.b - 1 do comma_only = comma_only and self.t[k].kind == "punct" end
    end
    if b and metric(a) ~= metric(b) and (comma_only or self:word_in(a.e, b.b, "that which ie i.e equals meaning thats")) then
      local restates = true
      for k = a.e, b.b - 1 do restates = restates and (self.t[k].kind == "punct" or self:word(k, "@restating")) end
      if restates then
        if math.abs(a.value - b.value) > 100 then
          return self:need(string.format("Which level for %s: %s or %s? They differ.", ids[1],
            f.alt(a.value, a.fl), f.alt(b.value, b.fl)))
        end
        local kept = metric(a) and b or a
        self:take(metric(a) and a or b)
        self:explain(a.e, b.b)
        with_unit = { kept }
      end
    end
    -- "descend at 2000 fpm 250", "... 2000 fpm, eight thousand": a number with no unit said straight after the rate
    -- (a comma or "and" between at most) is a level or a speed said bare: asked, never flown ("to 250" is the level)
    if rate then
      local k = self:skip_fillers(rate.e)
      while self.t[k] and (self.t[k].text == "," or self:word(k, "and")) do k = self:skip_fillers(k + 1) end
      for _, q in ipairs(self:quantities(k, s.e)) do
        if q.b == k and (q.kind == "plain" or (q.kind == "alt" and not q.fl and not self:word(q.e - 1, "@feet @metres"))) then
          return self:need(string.format("Is '%s' after the rate (%s) a level or a speed? Please say a level with 'FL' "
            .. "or feet, a speed with knots.", self:raw(q.b, q.e), self:raw(rate.b, rate.e)))
        end
      end
    end
    -- "CSN6901 it is at 9200 metres yes? please descend to 8100 metres", "KLM12 at FL250 now, climb FL300": a
    -- level said before the instruction word, with the level to fly to after it, that is the aircraft's present
    -- one (within 50 ft; 100 ft in metres, as China's table flies 8900 m at FL291) describes it, no clearance
    local first, second = with_unit[1], with_unit[2]
    if now and now.alt_ft and first and second and first.e <= s.trig and second.b > s.trig
        and math.abs(first.value - now.alt_ft) <= (metric(first) and 100 or 50) then
      self:take(first)
      self:explain(first.b, first.e)
      table.remove(with_unit, 1)
    end
    -- ("descent rate fifteen hundred, eh, correction, one thousand": the one value left, said bare after a
    -- correction that follows the rate, no level said before it, corrects the rate; never a level to fly)
    local corr = rate and #with_unit + #plain == 1 and self:last_correction(s)
    local fix = corr and corr > rate.e and (with_unit[1] or plain[1])
    if fix and fix.b > corr and (fix.kind == "plain" or (fix.kind == "alt" and not fix.fl
        and not self:word(fix.e - 1, "@feet @metres"))) and self:direction(s) ~= 0 then
      self:take(fix)
      for _, id in ipairs(ids) do self:emit("VS " .. id .. " " .. f.int(self:direction(s) * fix.value)) end
      return
    end
    local target = self:pick(self:corrected(#with_unit > 0 and with_unit or plain, with_unit, plain, s), s, "maintain")
    local dir = self:direction(s)
    local verb = dir > 0 and "climb" or dir < 0 and "descend" or "fly"
    -- ("double the altitude": twice the level flown; "double-check the altitude", a verb, doubles nothing)
    local twice = self:find_word(s.b, s.e, "double")
    if twice < s.e and not self:word(twice + 1, "check checked checks checking") and now then
      for _, id in ipairs(ids) do self:emit("ALT " .. id .. " " .. f.int((now.alt_ft or 0) * 2)) end
      return
    end
    -- "put BAW123 at the same level as DLH4AX", "climb to the same altitude as AC01": the other's level
    local refs = self:refs_in(s.b, s.e, "aircraft")
    if not target and #refs >= 2 and self:word_in(s.b, s.e, "same") and self:word_in(s.b, s.e, "as") then
      local src = self:state(refs[#refs].name)
      if not src then return self:need("What is the altitude of " .. refs[#refs].name .. "?") end
      local ft, cur = math.floor((src.alt_ft or 0) + 0.5), (self:state(refs[1].name) or {}).alt_ft or 0
      if (dir > 0 and ft < cur - 50) or (dir < 0 and ft > cur + 50) then
        return self:need(string.format("%s is at %s ft, %s at %s ft: %s %s? Please confirm the altitude.", refs[1].name,
          f.int(cur), refs[#refs].name, f.int(ft), verb, refs[1].name))
      end
      return self:emit("ALT " .. refs[1].name .. " " .. (ft >= 10000 and f.alt(ft, true) or f.int(ft)))
    end
    if not target and rate then return self:vspeed(s) end
    -- "maintain present altitude", "hold your altitude" (a verb of keeping, the aircraft's own level): each
    -- aircraft's current level, read from the traffic
    local own = self:word_in(math.max(1, s.trig - 2), s.trig + 1, "@keep_verbs") and self:word_in(s.b, s.e, "your its their")
    if not target and now and (own or self:word_in(s.b, s.e, "present current"))
        and not self:word_in(s.b, s.e + 1, "heading hdg speed") then
      for _, id in ipairs(ids) do
        if not self:state(id) then return self:need("What is the altitude of " .. id .. "?") end
      end
      for _, id in ipairs(ids) do self:emit("ALT " .. id .. " " .. f.int(self:state(id).alt_ft or 0)) end
      return
    end
    if not target then return self:need("What altitude should " .. ids[1] .. " " .. verb .. " to?") end
    local q = target
    -- ("descend with 1500": a bare number after "with" is the rate flown with as often as a level: asked; "flight
    -- with three seven zero" is a level's noun misheard)
    if q.kind == "plain" and self:word(q.b - 1, "with") and not self:word(q.b - 2, "flight") then
      return self:need(string.format("Should %s %s to %s ft, or at %s ft/min? I heard 'with %s'.", ids[1], verb,
        f.int(q.value), f.int(q.value), self:raw(q.b, q.e)))
    end
    local ft, fl = q.value, q.fl
    -- "CCA1831 and CES5102 same level 8900 metres, head to head": the level every aircraft named already holds
    -- (within 50 ft; 100 ft in metres, China's table), said with "same" and no verb of climbing, descending or
    -- keeping, describes the traffic: no clearance
    local dir0 = self:direction(s)
    if dir0 == 0 and self:word_in(s.b, q.b, "same") and not self:word_in(s.b, s.e, "as @keep_verbs")
        and (q.kind == "alt" or q.kind == "metric") then
      local held, in_m = true, metric(q) or self:word(q.e, "@metres")
      local said_ft = in_m and q.number and q.number.value / 0.3048 or fl and ft < 1000 and ft * 100 or ft
      for _, id in ipairs(ids) do
        local a = self:state(id)
        held = held and a ~= nil and a.alt_ft ~= nil and math.abs(a.alt_ft - said_ft) <= (in_m and 100 or 50)
      end
      if held then
        self:take(q)
        self:explain(s.b, s.e)
        return
      end
    end
    -- "flight level eight zero correction nine zero", "flight level one one zero, make that one hundred": a bare
    -- number of two or three digits, or whole hundreds said, after a correction that takes back a flight level is the
    -- flight level it corrects to (FL090, FL100), never feet
    local relevelled = q.kind == "plain" and not fl and q.value >= 10 and q.value < 1000 and q.value % 1 == 0
      and not q.number.thousand
    if relevelled then
      relevelled = false
      for _, o in ipairs(qs) do
        if o.fl and o.e <= q.b and self:word_in(o.e, q.b, "@correction") then relevelled = true end
      end
      if relevelled then ft, fl = q.value * 100, true end
    end
    -- "climb to 7800 metres, sorry, not 7800, is 8100", "descend 8100 metres, correction, 7800": a bare number
    -- after a correction that takes back a level in metres is metres too, never feet (8100 ft is no correction
    -- of 7800 m); whole hundreds of metres only, else read as said
    local remetred = false
    if q.kind == "plain" and not fl and q.number and q.number.value >= 300 and q.number.value <= 13700 then
      local again = (self.said_again or {})[q.b]
      remetred = again ~= nil and again.kind == "alt" and not again.fl and metric(again)
      for _, o in ipairs(qs) do
        if o.kind == "alt" and not o.fl and o.e <= q.b and metric(o) and self:word_in(o.e, q.b, "@correction") then
          remetred = true
        end
      end
      if remetred and q.number.value % 100 ~= 0 then
        return self:need(string.format("Which altitude for %s? I heard '%s' after a level in metres.", ids[1],
          self:raw(q.b, q.e)))
      end
      if remetred then ft = q.number.value / 0.3048 end
    end
    -- "descend to height 600 metres on QFE": a height above the airfield, no altitude above the sea
    if not fl and self:word_in(s.b, #self.t + 1, "qfe") then
      return self:need(string.format("Which altitude for %s? I heard '%s' on QFE, a height above the airfield, "
        .. "and squawk flies altitudes above the sea.", ids[1], self:raw(q.b, q.e)))
    end
    -- "flight level to eight zero": "to" between "level" and two spoken digits is "two" (FL280) or no
    -- digit (FL080); the verb's direction from the present level decides, else squawk asks
    if q.kind == "plain" and not q.number.typed and q.number.groups == 2 and #q.number.digits == 2
        and self:word(q.b - 1, "@two_heard") and self:word(q.b - 2, "level fl") then
      local two, bare, cur = (200 + q.value) * 100, q.value * 100, now and now.alt_ft
      local function fits(x) return cur ~= nil and ((dir > 0 and x > cur + 50) or (dir < 0 and x < cur - 50)) end
      -- (no transition altitude lies below 3000 ft: "flight level too one zero" is never FL010)
      if bare < 3000 then
        ft, fl = two, true
      elseif fits(two) == fits(bare) then
        return self:need(string.format("Which flight level for %s: %s or %s? I heard 'flight level %s %s'.", ids[1],
          f.alt(two, true), f.alt(bare, true), self.t[q.b - 1].raw, self:raw(q.b, q.e)))
      else
        ft, fl = fits(two) and two or bare, true
      end
    end
    if q.kind == "plain" and not q.number.typed and not q.number.thousand then
      local d = q.number.digits  -- a stutter: "one four fourteen" -> 14 (thousand)
      if #d >= 4 and #d % 2 == 0 and d:sub(1, #d // 2) == d:sub(#d // 2 + 1) then ft = tonumber(d:sub(1, #d // 2)) end
    end
    -- (a level said as "zero" alone, a word between it and "level" unread: "flight level for zero", is asked)
    if q.kind == "plain" and ft == 0 and not q.number.typed then
      return self:need(string.format("What altitude should %s %s to? I heard '%s'.", ids[1], verb, self:raw(q.b, q.e)))
    end
    if q.kind == "plain" and not relevelled and not remetred then
      if q.number.typed and #q.number.digits == 3 and q.number.digits:find("^0[1-9]") then
        ft, fl = ft * 100, true  -- "descend 070": three typed digits led by zero are a flight level
      elseif q.number.typed and q.number.digits:match("^[1-9]%d?$") and not q.number.thousand and not q.number.hundred then
        -- "climb 25" typed: hundreds of feet (2500) or thousands (25000)? Asked, naming the readings in range
        local said = {}
        if ft >= 10 then said[#said + 1] = f.int(ft * 100) .. " ft" end
        if ft <= 60 then said[#said + 1] = f.int(ft * 1000) .. " ft" end
        return self:need(string.format("What altitude should %s %s to: %s? I heard '%s'.", ids[1], verb,
          table.concat(said, " or "), self:raw(q.b, q.e)))
      elseif ft < 100 and not q.number.typed then
        local doubt = self:short_level_doubt(q, ft * 1000, now, dir, ids[1], verb)
        if doubt then return self:need(doubt) end
        ft = ft * 1000  -- "maintain niner (thousand)"
      elseif ft >= 100 and ft < 1000 and (self:change_of(q) or self:change_of_corrected(q, s)) then
        -- ("go up of 500": an amount of change, G:change_of, in hundreds of feet, or a flight level said bare?)
        return self:need(string.format("Should %s %s by %s ft, or to %s? I heard '%s'.", ids[1], verb, f.int(ft),
          f.alt(ft * 100, true), self:raw(q.b - 1, q.e)))
      elseif ft >= 100 and ft < 1000 and not q.number.hundred then
        ft, fl = ft * 100, true  -- "climb three five zero": a flight level
      elseif ft >= 100 and ft < 1000 and not q.by then
        -- "climb one hundred sixty": a level said group-wise is that flight level for an aircraft at or above
        -- 10000 ft; lower down (feet or a level?) or not a whole ten (a word misheard), asked
        if ft % 10 ~= 0 or not now or (now.alt_ft or 0) < 10000 then
          return self:need(string.format("What altitude should %s %s to? I heard '%s'.", ids[1], verb,
            self:raw(q.b, q.e)))
        end
        ft, fl = ft * 100, true
      end
    end
    -- "flight level 9500 metres": a metric flight level (Russia's, China's) is that many metres, converted to
    -- the nearest 100 ft (9500 m = 31168 ft, cleared as 31200: metres_level)
    local metres_after = self:word(q.e, "@metres")
    if fl and q.number.value >= 1000 and q.number.value <= 18000 and (metres_after or self:word(q.e - 1, "@metres")) then
      if metres_after then self:explain(q.e, q.e + 1) end
      ft, fl = metres_level(q.number.value / 0.3048), false
      local m = {}
      for k, v in pairs(q) do m[k] = v end
      m.kind, m.value, m.fl = "metric", ft, false
      q = m
    end
    local doubt = fl and self:level_doubt(q, ft, ids[1])
    if doubt then return self:need(doubt) end
    if not fl and q.kind == "alt" and self:word(q.e - 1, "@metres") and self:word(q.e, "per")
        and self:word(q.e + 1, "min mins minute minutes sec secs second seconds s") then
      -- "climb 1500 m/min": metres per unit of time are a rate, no level (VS is in ft/min): asked; said after
      -- "with" or "at" a rate per minute ("descend with 1000 metres per minute") is the vertical speed, in ft/min
      if self:word(q.b - 1, "with at") and self:word(q.e + 1, "min mins minute minutes") then
        local rated = { rate = q }
        for k, x in pairs(s) do rated[k] = x end
        return self:vspeed(rated)
      end
      return self:need("What altitude or vertical speed for " .. ids[1] .. "? I heard " .. f.int(q.number.value)
        .. " metres per " .. self.t[q.e + 1].text .. ".")
    end
    -- "9800 metres, standard", "6300 metres on standard pressure": a metric level (or a flight level) flown on
    -- the standard altimeter setting, as every level above the transition is; the words restate that
    if fl or q.kind == "metric" or self:word(q.e - 1, "@metres") then
      local k = q.e
      while self:word(k, "@metres") or (self.t[k] and self.t[k].kind == "punct") do k = k + 1 end
      local on = self:word(k, "on") and k + 1 or k
      -- (a "standard" that names something else, "standard speed", "standard rate", is not this)
      if self:word(on, "standard") and not self:word(on + 1, "speed rate turn route routing arrival departure star sid") then
        local last = self:word(on + 1, "pressure setting altimeter") and on + 1 or on
        self:explain(k, last + 1)
      end
    end
    if not fl and ((q.kind == "alt" and self:word(q.e - 1, "@metres")) or remetred) then
      -- a level in metres is the whole number said, converted exactly (8100 m = 26575 ft); a spoken one
      -- is whole hundreds of metres ("eight thousand one hundred metres"), else a word was misheard; above
      -- FL450 (13716 m) no airliner flies: "15000 m" is feet or a slip, asked. Metres are said digit by
      -- digit ("niner five zero zero") or with their multipliers ("nine thousand five hundred"): digits said
      -- one by one before "hundred" with no "thousand" ("nine five hundred metres": 9500, or 500 after a
      -- slip?) are asked, unless the request says the same level again in a clear form ("eight nine hundred
      -- metres, correct, eight thousand nine hundred metres")
      local function unclear(n) return not n.typed and n.hundred and not n.thousand and n.lead_digit and n.groups >= 2 end
      local n = q.number
      local unsure = unclear(n)
      for _, o in ipairs(unsure and self:quantities(s.b, s.e) or {}) do
        if o.b ~= q.b and o.value == q.value and o.number and not unclear(o.number) then unsure = false end
      end
      if ft < 100 or ft > 45000 or (not n.typed and n.value % 100 ~= 0) or unsure then
        return self:need("Which altitude for " .. ids[1] .. "? I heard " .. f.int(q.number.value) .. " metres.")
      end
      -- ("CSN6901 maintain 9200 metres" at FL301: a level kept in metres within 100 ft of the one held is that
      -- one, as China's table flies it, never a 100 ft climb)
      local cur = now and now.alt_ft
      if cur and dir == 0 and self:word_in(s.trig, q.b, "@keep_verbs") and math.abs(cur - ft) <= 100 then
        ft = cur
      else
        ft = metres_level(ft)
      end
    elseif not fl then
      local r = self:repaired(q, ft, 0, 60000, 100, true)
      if not r then
        local n = q.number
        return self:need("Which altitude for " .. ids[1] .. "? I heard " .. (not n.typed and n.groups == #n.digits
          and "'" .. self:raw(q.b, q.e) .. "'" or f.int(ft) .. " ft") .. ".")
      end
      if r < 100 and not q.number.typed then r = r * 1000 end
      ft = r
      -- cleared altitudes are whole hundreds of feet: a spoken 2710 has a
      -- misheard word; the longest run of its words that is one counts
      -- ("eight thousand five", "one zero thousand fifty": a number after "thousand" with no "hundred" may be the
      -- hundreds with their word lost, 8500, as well as a word misheard: asked, never cut to the thousands)
      if not q.number.typed and ft % 100 ~= 0 and q.number.thousand and not q.number.hundred then
        return self:need(string.format("Which altitude for %s? I heard '%s'.", ids[1], self:raw(q.b, q.e)))
      end
      if not q.number.typed and ft % 100 ~= 0 then
        ft = self:whole_hundreds(q)
        if not ft then return self:need("Which altitude for " .. ids[1] .. "? I heard " .. f.int(r) .. " ft.") end
      end
      -- "its altitude, keep 8900" to an aircraft at FL291 (8870 m): a level kept, said with no unit, that is
      -- the aircraft's own level in metres (within 50 m) and far from it in feet, is asked, never a 20000 ft
      -- descent (a bare number stays feet otherwise)
      local cur = now and now.alt_ft
      if cur and q.kind == "plain" and dir == 0 and self:word_in(s.trig, q.b, "@keep_verbs")
          and q.number.value % 100 == 0 and math.abs(cur * 0.3048 - q.number.value) <= 50
          and math.abs(cur - ft) > 1000 then
        return self:need(string.format("%s is at %s ft (%s m): keep %s metres, its level, or fly to %s ft?", ids[1],
          f.int(cur), f.int(cur * 0.3048), f.int(q.number.value), f.int(ft)))
      end
    end
    -- Relative: "by 2000 ft", "1000 ft from its present altitude", "1000 feet below AC01"
    -- (a flight level is a level, and an aircraft in a reason no reference: "FL240 so it passes under AC01").
    local others = self:refs_in(s.b, s.e, "aircraft")
    local below, above = self:word_in(s.b, s.e, "@below"), self:word_in(s.b, s.e, "@above")
    if (below or above) and #others >= 2 and not fl and not self:in_reason(others[#others].b) then
      local ref = self:state(others[#others].name)
      if not ref then return self:need("What is the altitude of " .. others[#others].name .. "?") end
      -- (an offset of 10000 ft or more, a level under the ground, or one on the other side of the verb said,
      -- "climb" or "descend", is no separation anyone gives: "climb to 23000 feet below KLM12" is asked; "put
      -- AC02 1000 ft below AC01" says no direction)
      local target = (ref.alt_ft or 0) + (above and ft or -ft)
      local cur = now and now.alt_ft or target
      local said = self:word(s.trig, "climb climbs climbing") and 1 or self:word(s.trig, "descend descends descending") and -1 or 0
      if ft >= 10000 or target < 0 or (said > 0 and target < cur - 50) or (said < 0 and target > cur + 50) then
        return self:need(string.format("Is %s ft a level for %s, or how far %s %s it should be?",
          f.int(ft), ids[1], above and "above" or "below", others[#others].name:upper()))
      end
      return self:emit("ALT " .. ids[1] .. " " .. f.int(target))
    end
    -- ("by" before the instruction belongs to something else: "time by departure, climb ..."; a
    -- flight level is a level: "FL240 and hold its current heading", "FL130, lower by the time ...")
    -- ("3000 feet from where it is now": a change from the present level)
    local from_here = self:find_word(s.trig, s.e, "from")
    -- True when value o is said as an amount of change by the words beside it
    local function stepped(o)
      return o.by
        -- "down 2000 feet", "up 1000 ft", "drop 4000 feet": an amount in feet straight after the adverb, or
        -- after the everyday verb "drop" (no "to"), is a change
        or (self:word(o.b - 1, "up down drop") and self:word(o.e - 1, "@feet @metres"))
        -- "1000 feet lower", "2000 ft up", "600 metres more": an amount with its unit straight before the
        -- comparative is a change
        or (self:word(o.e, "higher lower up down more") and self:word(o.e - 1, "@feet @metres")
          and not (self:word(o.e, "more") and self:word(o.e + 1, "or than")))
        -- "another thousand feet", "a further 500 ft", "an extra 1000 ft", "climb more 1000 feet" (Portuguese
        -- "mais"): one more step of that size
        or self:word(o.b - 1, "another further extra more")
        -- "go down of 2000 feet", "climb of 1000" (G:change_of)
        or self:change_of(o)
    end
    -- the value a correction takes back when q, said after it with no "to" and no flight level, corrects it
    -- ("go down 1500 feet... eh, no, 2000"; "..., no, to 9000 feet" and "..., no, FL200" name a level)
    -- (or the value a run of self-correction markers took back: G:value_said_again)
    local corr = not fl and not q.to and self:last_correction(s)
    local taken_back = not fl and not q.to and (self.said_again or {})[q.b] or nil
    for _, o in ipairs(corr and q.b > corr and qs or {}) do
      if o.e <= corr and (o.kind == "alt" or o.kind == "plain") then taken_back = o end
    end
    if taken_back and taken_back.fl then taken_back = nil end
    local relative = not fl and (stepped(q) or self:word_in(s.trig, s.e, "@relative")
      or (from_here < s.e and self:word(from_here + 1, "where"))
      -- a value said after a correction of an amount of change corrects the amount: "go down 1500 feet... no,
      -- 2000" and "go down of 1500 feet, no, 2000" are 2000 ft down, never to 2000 ft
      or (taken_back ~= nil and stepped(taken_back)) or self:change_of_corrected(q, s))
    -- ("climb more 37000 feet": a step of 10000 ft or more after "more" or "extra" may be the level itself, "climb
    -- more, to 37000": asked)
    -- (nor is a step of 10000 ft or more said with "of", "go down of 12000 feet": G:change_of)
    if relative and not q.by and ft >= 10000 and (self:word(q.b - 1, "extra more") or self:change_of(q)
        or self:change_of_corrected(q, s)) then
      return self:need(string.format("Should %s %s to %s ft or by %s ft?", ids[1], verb, f.int(ft), f.int(ft)))
    end
    -- "go down 5000 feet" from 8000 ft: the adverb says a step, but below FL120 (the terminal area) a change of
    -- 4000 ft or more is the altitude cleared (as "descend 5000 feet" there is): to 5000 ft or by 5000 ft is
    -- asked when both are flyable and differ. Higher up, or a smaller amount, "down 2000 feet" stays the step;
    -- "by", "another", "from where it is" and "1000 feet lower" are steps everywhere.
    if relative and now and dir ~= 0 and not q.by and ft >= 4000 and (now.alt_ft or 0) < 12000
        and self:word(q.b - 1, "up down drop") and not taken_back
        and not self:word_in(s.trig, s.e, "@relative") and not (from_here < s.e and self:word(from_here + 1, "where")) then
      local cur = now.alt_ft or 0
      local by_target = cur + (dir < 0 and -ft or ft)
      local to_fits = (dir < 0 and ft < cur - 50) or (dir > 0 and ft > cur + 50)
      if to_fits and by_target >= 0 and by_target <= 60000 and math.abs(by_target - ft) > 50 then
        return self:need(string.format("%s is at %s ft: %s to %s ft, or by %s ft to %s ft?", ids[1], f.int(cur), verb,
          f.int(ft), f.int(ft), f.int(by_target)))
      end
    end
    -- (a value said after a correction replaces a level said before it: "climb 9000... correction, 5000"
    -- is a level, never a step)
    -- ("climb 3000" below the aircraft, no "by" said: a climb to a level below it, or a climb by that much?
    -- Asked, naming both; "up 2000 feet", "by 2000 ft", "another 1000 ft" are the step)
    if not relative and now and not q.to and not fl and dir > 0 and not self:word_in(s.trig, q.b, "@correction") then
      local cur = now.alt_ft or 0
      if (ft <= cur - 50 and ft <= 5000) or (ft < 3000 and cur > 10000) then
        if #ids > 1 then
          return self:need(string.format("Should %s each climb by %s ft? I heard '%s' with no 'by'.",
            table.concat(ids, " and "), f.int(ft), self:raw(q.b, q.e)))
        end
        return self:need(string.format("%s is at %s ft: climb to %s ft, or by %s ft? I heard '%s' with no 'by'.",
          ids[1], f.int(cur), f.int(ft), f.int(ft), self:raw(q.b, q.e)))
      end
    end
    -- "descend 3000 ft" or "descend two thousand feet" right after the verb, from higher up: to or by?
    -- Both read as descents, typed or spoken.
    -- (an altitude said with the altimeter setting it is read on, "3000 feet QNH 1008", is a level)
    -- (a value said after a correction of one said so, "descend 1500 feet, no, 2000", is asked as it is)
    local function bare_feet(o) return o.kind == "alt" and o.b == s.trig + 1 and self:word(o.e - 1, "@feet") end
    if not relative and now and not q.to and not fl and dir ~= 0 and (bare_feet(q) or taken_back and bare_feet(taken_back))
        and not self:word_in(q.e, #self.t + 1, "@altimeter") then
      local cur = now.alt_ft or 0
      local by_fits = (dir < 0 and cur - ft >= 0) or (dir > 0 and cur + ft <= 60000)
      local to_fits = (dir < 0 and ft < cur - 50) or (dir > 0 and ft > cur + 50)
      -- (a change of 4000 ft or more is a cleared altitude: nobody clears a 4000 ft step by its size; a
      -- descent from below FL120, in a terminal area, is to the approach altitude said in feet)
      -- (from the flight levels too: "descend 3000 feet" is the step to some, the approach altitude after an
      -- approach clearance to others)
      -- (a climb from below FL120 to an altitude above the aircraft, "climb 3000 feet" at 2000 ft, is the
      -- departure's cleared altitude in feet the same way)
      local approach = cur < 12000
      if by_fits and to_fits and ft < 4000 and not approach then
        return self:need(string.format("Should %s %s to %s ft or by %s ft?", ids[1], verb, f.int(ft), f.int(ft)))
      end
    end
    for _, id in ipairs(ids) do
      local alt, target_ft
      if relative then
        local a = self:state(id)
        if not a then return self:need("What is the current altitude of " .. id .. "?") end
        if dir == 0 then return self:need("Should " .. id .. " climb or descend by " .. f.int(ft) .. " ft?") end
        target_ft = (a.alt_ft or 0) + (dir < 0 and -ft or ft)
        -- (a step said in metres ends on the nearest 100 ft: "climb 600 metres more" from FL291 is 31100)
        if self:word(q.e - 1, "@metres") then target_ft = metres_level(target_ft) end
        alt = f.int(target_ft)
        self:as_change(q)
      else
        target_ft, alt = ft, f.alt(ft, fl)
      end
      -- "descend and maintain to four thousand": a "to" (lexicon.two_heard) between "maintain" (lexicon.keep_verbs,
      -- which takes none) and a spoken number of one digit's thousands may be "two" (24000 ft), as in "flight level
      -- to four zero": the reading the verb allows from the present altitude, asked when both or neither are
      local n = q.number
      if not relative and not fl and not n.typed and n.thousand and n.digits:match("^[1-9]$")
          and self:word(q.b - 1, "@two_heard") and self:word(q.b - 2, "@keep_verbs") then
        local two, cur = (20 + tonumber(n.digits)) * 1000, (self:state(id) or {}).alt_ft
        local function fits(x) return cur ~= nil and ((dir > 0 and x > cur + 50) or (dir < 0 and x < cur - 50)) end
        if fits(two) == fits(target_ft) then
          return self:need(string.format("Should %s %s to %s ft or to %s ft? I heard '%s %s'.", id, verb, f.int(two),
            f.int(target_ft), self.t[q.b - 1].raw, self:raw(q.b, q.e)))
        end
        if fits(two) then target_ft, alt = two, f.alt(two, false) end
      end
      -- a climb to a lower level, or a descent to a higher one, contradicts the verb
      local a = self:state(id)
      if a and dir ~= 0 and self:word_in(s.b, s.e, "climb climbing descend descending descent") then
        local cur = self:level_when_run(id) or a.alt_ft or 0
        -- "descend two eight thousand" straight after the verb may be "descend to eight
        -- thousand" (lexicon.two_heard): the reading the verb allows, asked when both are
        if not relative and not fl and q.b == s.trig + 1 and self:word(s.trig, "climb descend") and not n.typed
            and n.thousand and self.t[q.b].raw:lower() == "two" and #n.digits >= 2 and n.digits:sub(1, 1) == "2"
            and target_ft == tonumber(n.digits) * 1000 then
          local alt_to = tonumber(n.digits:sub(2)) * 1000
          local function fits(x) return x > 0 and ((dir > 0 and x > cur + 50) or (dir < 0 and x < cur - 50)) end
          if fits(alt_to) and fits(target_ft) then
            return self:need(string.format("Should %s %s to %s ft or to %s ft?", id, verb, f.int(target_ft),
              f.int(alt_to)))
          elseif fits(alt_to) then
            target_ft, alt = alt_to, f.alt(alt_to, false)
          end
        end
        if (dir > 0 and target_ft < cur - 50) or (dir < 0 and target_ft > cur + 50) then
          return self:need(string.format("%s is at %s ft: %s to %s? Please confirm the altitude.", id, f.int(cur),
            verb, alt))
        end
      end
      if target_ft < 0 then return self:need("Which altitude for " .. id .. "? " .. alt .. " ft is below the ground.") end
      if target_ft == 0 then return self:need("Which altitude for " .. id .. "? 0 ft is the ground.") end
      -- a level well above the type's ceiling (the performance model's cruise ceiling, with 3000 ft to spare: OpenAP's
      -- is the highest cruise flown, below the certified one) is one it cannot reach: asked
      if a and a.ceiling_ft and target_ft > a.ceiling_ft + 3000 then
        return self:need(string.format("%s (%s) can climb no higher than FL%03d: %s? Please confirm the altitude.", id,
          a.type or "its type", math.floor(a.ceiling_ft / 100), alt))
      end
      -- ("descend FL300, rate of climb 2000": the motion a rate's words name, in the three words before it,
      -- against the way to the level, is asked)
      local cur = a and a.alt_ft
      local way = cur and (target_ft > cur + 50 and 1 or target_ft < cur - 50 and -1 or 0) or dir
      local rb = rate and math.max(s.b, rate.b - 3)
      local named = rate and ((self:word_in(rb, rate.b, "descent descend descending") and -1 or 0)
        + (self:word_in(rb, rate.b, "climb climbing") and 1 or 0))
      if rate and named ~= 0 and way ~= 0 and named ~= way then
        return self:need(string.format("%s: %s to %s at a rate of %s %s ft/min? Please confirm the rate.", id,
          way < 0 and "descend" or "climb", alt, named < 0 and "descent" or "climb", f.int(math.abs(rate.value))))
      end
      local cmd = "ALT " .. id .. " " .. alt
      if rate then cmd = cmd .. " " .. f.int(rate.value) end
      self:emit(cmd)
      self.last_cond = "ATALT " .. id .. " " .. alt
    end
  end

  -- True when q corrects an amount of change said with "of" before it (G:change_of), with no "to": "go down of 1500
  -- feet... no, 2000" is 2000 ft down (the run taken back, G:self_corrected, is used: "of" is the last word before
  -- q outside it), as is "go down of 1500 feet correction 2000".
  function m:change_of_corrected(q, s)
    if q.to then return false end
    local k, number = q.b - 1, false
    while k > s.b and self.u:used(k) do
      number = number or self.t[k].kind == "number"
      k = k - 1
    end
    if number and self:change_of({ b = k + 1 }) then return true end
    local corr = self:last_correction(s)
    if not corr or q.b < corr then return false end
    for _, o in ipairs(self:quantities(s.b, corr)) do
      if self:change_of(o) then return true end
    end
    return false
  end

  function m:speed(s)
    local ids = self:acids(s)
    if #ids == 0 then return self:need("Which aircraft should change speed? Please give its callsign.") end
    local with_unit, plain = {}, {}
    for _, q in ipairs(self:quantities(s.b, s.e)) do
      if q.kind == "speed" or q.kind == "mach" or q.kind == "percent" then with_unit[#with_unit + 1] = q end
      if q.kind == "plain" and (q.b >= s.trig or q.number.typed) then plain[#plain + 1] = q end
    end
    local now = self:state(ids[1])
    for _, list in ipairs({ with_unit, plain }) do
      if now and not now.sel_mach and self:value_left(list[1], list[2], now.cas_kt, 10) then table.remove(list, 1) end
    end
    local q = self:pick(self:corrected(#with_unit > 0 and with_unit or plain, with_unit, plain, s), s, "speed")
    -- "Match AC02's speed to AC01" / "the same speed as AC01"
    local refs = self:refs_in(s.b, s.e, "aircraft")
    if not q and #refs >= 2 and self:word_in(s.b, s.e, "@same_as") then
      local src = self:state(refs[#refs].name)
      if not src then return self:need("What is the speed of " .. refs[#refs].name .. "?") end
      return self:emit("SPD " .. refs[1].name .. " " .. (src.sel_mach and f.mach(src.sel_mach) or f.int(src.cas_kt or 0)))
    end
    -- "maintain present speed": each aircraft's current speed, read from the traffic
    if not q and self:word_in(math.max(1, s.trig - 2), s.trig, "@present") then
      for _, id in ipairs(ids) do
        local now = self:state(id)
        if not now then return self:need("What is the current speed of " .. id .. "?") end
        self:emit("SPD " .. id .. " " .. (now.sel_mach and f.mach(now.sel_mach) or f.int(now.cas_kt or 0)))
      end
      return
    end
    if not q then return self:need("What speed should " .. ids[1] .. " fly? Please give knots or a Mach number.") end
    local dir = self:direction(s)
    -- "take off about 30 knots", "knock 20 knots off": knots taken away
    if dir == 0 and self:word_in(s.b, s.e, "take knock") and self:word_in(s.b, s.e, "off") then dir = -1 end
    -- ("plus thirty knots", "speed minus 20": an amount said with its sign is a change)
    local signed = (q.kind == "speed" or q.kind == "plain") and self:word(q.b - 1, "plus minus")
    if signed and dir == 0 then dir = self:word(q.b - 1, "plus") and 1 or -1 end
    for _, id in ipairs(ids) do
      local spd
      if q.kind == "mach" or (q.kind == "plain" and q.value > 0 and q.value < 1) then
        spd = f.mach(q.value)
      elseif q.kind == "percent" or q.by or signed or (self:word_in(s.b, s.e, "by") and q.value < 100)
          -- an amount followed by its direction ("100 faster", "20 knots slower") is a change, never the new speed
          or ((q.kind == "speed" or q.kind == "plain") and self:word(q.e, "@faster @slower"))
          -- ("10 knots faster"; after a word speech recognition writes for "to" or "two", "reduce speed too two
          -- zero knots", the knots are no change: the speed's first digit may be lost, asked)
          or (q.kind == "speed" and q.value < 40 and dir ~= 0 and not q.to
            and not self:word(q.b - 1, "@two_heard"))
          -- (a number typed in digits under 40, no unit, straight after "speed up" or "slow down": "speed up 15", "slow
          -- it down 20" are knots of change, no speed an aircraft flies; said in words, after "to" or after another
          -- verb, "reduce 25" (250 typed short?), it is still asked)
          or (q.kind == "plain" and q.number.typed and q.value >= 1 and q.value < 40 and dir ~= 0
            and self:word(q.b - 1, "up down"))
          -- "reduce of 10 knots", "reduce the velocity of 40 knots" (G:change_of): a change, asked when 100 kt or
          -- more ("reduce the speed of 250 knots": the speed itself?) or when it leaves under 40 kt
          or ((q.kind == "speed" or q.kind == "plain") and (self:change_of(q) or self:change_of_corrected(q, s))) then
        local a = self:state(id)
        if not a or (a.cas_kt or 0) <= 0 then return self:need("What is the current speed of " .. id .. "?") end
        if dir == 0 then return self:need("Should " .. id .. " fly faster or slower?") end
        -- knots added to an aircraft holding a Mach number: which knots (its CAS now, or the
        -- Mach's equivalent at a level it has not reached) is the speaker's to say
        if a.sel_mach and q.kind ~= "percent" then
          return self:need(string.format("%s holds %s: what speed should it fly, in knots or as a Mach number?",
                                         id, f.mach(a.sel_mach)))
        end
        -- (the change's sign is its direction word's: "minus 20 knots" is 20 knots slower, never faster)
        local delta = math.abs(q.kind == "percent" and a.cas_kt * q.value / 100 or q.value)
        local to_kt = a.cas_kt + (dir < 0 and -delta or delta)
        if q.kind ~= "percent" and not q.by and (delta >= 100 or to_kt < 40 or to_kt > 700)
            and (self:change_of(q) or self:change_of_corrected(q, s)) then
          return self:need(string.format("%s flies %s kt: should it fly %s kt, or change its speed by %s kt? I heard "
            .. "'%s'.", id, f.int(a.cas_kt), f.int(delta), f.int(delta), self:raw(q.b - 1, q.e)))
        end
        spd = f.int(to_kt)
        self:as_change(q)
      else
        local kt = q.value
        -- a speed said in another unit ("400 km/h", "150 m/s") is its conversion, to the nearest knot
        -- (400 km/h = 216 kt): never rounded further, never re-read as knots
        local converted = q.kind == "speed" and q.value ~= q.number.value
        -- an aircraft flying slower than 200 kt (a light aircraft) is given two-digit speeds
        -- ("niner zero knots"); others' assigned speeds are said as three digits: see H.cut_off
        local a = self:state(id)
        local slow = a and (a.cas_kt or 0) > 0 and a.cas_kt < 200 and kt >= 40 and kt < 100
        -- "reduce speed to to five zero", "slow to to seventy": a spoken speed of two digits or a tens word (10-90
        -- kt, whole tens) straight after two words of lexicon.two_heard, to an aircraft flying 200 kt or more of no
        -- light class, has its "two" in the second (250, 270): one preposition, never two, stands before a value. A
        -- single "to" ("speed to five zero": 50 kt, or 250 with the "two" heard as "to"?) is asked
        local two = not converted and not q.number.typed and kt >= 10 and kt < 100 and kt % 10 == 0
          and #q.number.digits == 2 and self:word(q.b - 1, "@two_heard") and self:word(q.b - 2, "@two_heard")
          and a and (a.cas_kt or 0) >= 200 and not types.slow_class(a.type)
        if two then
          kt = 200 + kt
        elseif not q.number.typed and q.number.lead_digit and H.cut_off(q.number) and not slow then
          return self:need("What speed should " .. id .. " fly? I heard " .. q.number.digits .. ".")
        end
        -- ("speed two five": 250, its zero not heard; never past 400 kt, "four five knots" is asked)
        if not converted and not q.number.typed and kt >= 10 and kt < 100 and q.number.groups == 2 and not slow then
          if kt > 40 then
            return self:need("What speed should " .. id .. " fly? I heard " .. self:raw(q.b, q.e) .. ".")
          end
          kt = kt * 10
        end
        local r
        if converted then
          r = kt >= 40 and kt <= 700 and math.floor(kt + 0.5) or nil
        else
          r = self:repaired(q, kt, 40, 700, 10)
          -- assigned speeds are multiples of 5 kt; a spoken odd last digit is a recognition error
          if r and not q.number.typed and r % 5 ~= 0 then r = math.floor(r / 10) * 10 end
        end
        if not r then
          return self:need("What speed should " .. id .. " fly? I heard " .. self:raw(q.b, q.e) .. ".")
        end
        spd = f.int(r)
        -- A direction said with the value, no "to" before it ("reduce 40 knots" flying 280 kt is 240 kt; "reduce
        -- 40", "increase speed 40" asked): m:speed_change_read.
        -- An aircraft flying 200 kt or more is given no speed under 100 kt ("reduce to 40 knots", "speed 180 km/h",
        -- 97 kt, the unit said in place of knots?): asked.
        local change, both = self:speed_change_read(s, id, q, r, dir, converted)
        local heard = self:raw(math.max(s.trig or q.b, q.b - 2), q.e)
        if both then
          return self:need(string.format("%s flies %s kt: should it fly %s kt, or %s kt %s? I heard '%s'.", id,
            f.int(a.cas_kt), f.int(r), f.int(q.value), dir < 0 and "slower" or "faster", heard))
        elseif change == false or (change == nil and a and (a.cas_kt or 0) >= 200 and r < 100) then
          return self:need(string.format("What speed should %s fly? It flies %s kt, and I heard '%s'.", id,
            f.int(a.cas_kt), heard))
        elseif change then
          spd = f.int(change)
          self:as_change(q)
        end
      end
      local against = self:speed_against_verb(s, id, q, spd, dir, q.kind == "speed" and q.value ~= q.number.value)
      if against then return self:need(against) end
      self:emit("SPD " .. id .. " " .. spd)
      self.last_cond = "ATSPD " .. id .. " " .. spd
    end
  end

  -- The question when speed `spd` (as SPD writes it: knots, or a Mach number ".78") that segment s gives aircraft
  -- id lies the other way from the direction its own verb says (the verb of lexicon.speed_direction_verbs nearest
  -- before the value, from the instruction's word on; dir, m:direction's, nonzero): "increase speed 220" flying 260 kt,
  -- "reduce speed to 300" flying 250 kt, "reduce to Mach .80" holding .78. Else nil: no direction, the speed the
  -- aircraft flies or one the way said, a knots speed to an aircraft holding a Mach number (or the reverse), or a
  -- condition in the request (lexicon.condition, level_condition, "then", "until": the speed then is not known).
  -- `converted`: said in another unit ("reduce to 450 km/h", 243 kt): within 5 kt of the speed flown it is the
  -- conversion's rounding, no contradiction.
  function m:speed_against_verb(s, id, q, spd, dir, converted)
    local a = self:state(id)
    if dir == 0 or not a or not s.trig or s.trig > q.b
        or self:word_in(1, #self.t + 1, "@condition @level_condition then until till") then
      return nil
    end
    -- (the direction of the verb nearest before the value in its clause: "increase to 300. No, I mistook, reduce to
    -- 260" reduces; a mark or a correction between leaves the value said in place of another, "speed up to 260
    -- knots? Sorry, I meant 240", and "the Cessna's too slow, bump it to 120 knots" names no direction; "faster"
    -- and "slower" may describe the aircraft, "slow the faster one to 220")
    dir = 0
    for x = q.b - 1, s.trig, -1 do
      if self.t[x].kind == "punct" or self:word(x, "@correction") then break end
      if self:word(x, "@speed_direction_verbs") and not self:word(x, "faster slower") then
        dir = self:word(x, "reduce reducing decrease decreasing decelerate slow slowing down") and -1
          or self:word(x, "increase increasing accelerate add up") and 1 or 0
        break
      end
    end
    if dir == 0 then return nil end
    local mach = spd:match("^%.") and tonumber("0" .. spd)
    local now, value, unit
    if mach and a.sel_mach then
      now, value, unit = a.sel_mach, mach, ""
    elseif not mach and not a.sel_mach and (a.cas_kt or 0) > 0 then
      now, value, unit = a.cas_kt, tonumber(spd), " kt"
    end
    local slack = converted and unit ~= "" and 5 or 1e-6
    if not now or not value or (dir < 0 and value <= now + slack) or (dir > 0 and value >= now - slack) then
      return nil
    end
    local said = mach and f.mach(now) or f.int(now) .. unit
    return string.format("%s flies %s: %s to %s%s? Please confirm the speed.", id, said,
      dir < 0 and "slow" or "speed up", spd, unit)
  end

  -- How speed value q said in segment s for aircraft id with direction dir (-1 slower, 1 faster, 0 none) is read, r its
  -- reading as the new speed (kt): nil to fly r, a speed (kt) to fly r read as a change, false to ask (see
  -- m:speed), with true second when both readings hold. `converted`: the value was said in another unit (always a
  -- speed). The speed is flyable at 100 kt or more, or by an aircraft flying under 200 kt; the change is one under
  -- 100 kt that leaves 40 to 700 kt (100 kt or more at 200 kt or more). A flyable speed the way said is flown (asked
  -- under 100 kt when the change fits too); otherwise the change is flown with its unit said, asked without it;
  -- with no change that fits, a flyable speed against the verb is flown as said, any other asked.
  -- Read so only when the direction is the instruction's own verb, said from its word up to the value
  -- (lexicon.speed_direction_verbs: "reduce 40 knots", "speed up 50 knots"; "set speed 280, it's catching up" says
  -- none), and when no condition is said in the request (lexicon.condition, level_condition, "then", "until": "when
  -- passing FL300 reduce 280" is flown from a speed not yet known).
  function m:speed_change_read(s, id, q, r, dir, converted)
    local a = self:state(id)
    if dir == 0 or q.to or converted or not a or a.sel_mach or (a.cas_kt or 0) <= 0 or q.kind ~= "speed"
        and q.kind ~= "plain" then
      return nil
    end
    if not (s.trig and s.trig < q.b and self:word_in(s.trig, q.b, "@speed_direction_verbs"))
        or self:word_in(1, #self.t + 1, "@condition @level_condition then until till") then
      return nil
    end
    local fast = a.cas_kt >= 200
    local flyable = r >= 100 or not fast
    local goes = dir < 0 and r < a.cas_kt or dir > 0 and r > a.cas_kt
    local to_kt = a.cas_kt + dir * q.value
    local as_change = q.value < 100 and to_kt >= 40 and to_kt <= 700 and (to_kt >= 100 or not fast)
    if flyable and goes then
      if as_change and r < 100 then return false, true end
      return nil
    end
    if as_change then
      if q.kind == "speed" then return to_kt end
      return false, true
    end
    -- (a speed flyable but against the verb with no change it could be, "increase speed 220" flying 260: the speed
    -- said, the verb said loosely)
    if flyable then return nil end
    return false
  end

  function m:heading(s)
    local ids = self:acids(s)
    if #ids == 0 then return self:need("Which aircraft should turn? Please give its callsign.") end
    local abs_c, rel_c = {}, {}
    -- ("240 on the heading": a number of three digits straight before "on the heading" is the heading; "add
    -- 20 on the heading" is no heading)
    local on = self:word(s.trig - 1, "the its") and s.trig - 2 or s.trig - 1
    on = self:word(on, "on") and on
    for _, q in ipairs(self:quantities(s.b, s.e)) do
      if q.kind == "heading" or (q.kind == "plain" and q.b > s.trig and not q.number.thousand)
          or (q.kind == "plain" and on and q.e == on and q.value <= 360 and #(q.number.digits or "") == 3) then
        abs_c[#abs_c + 1] = q
      elseif q.kind == "angle" then
        rel_c[#rel_c + 1] = q
      end
      if q.b > s.trig and (q.kind == "alt" or q.kind == "speed") then break end
    end
    -- "turn right 20", "left thirty": a number of one or two digits, typed or said as a number
    -- (not digit by digit, as headings are), after a turn direction, with no "heading", is the
    -- degrees of the turn (headings have three); after "turn" with no side ("turn 30") it is
    -- asked about below: a turn of that many degrees, or a heading? Straight after "to"/"onto" ("turn left to 90")
    -- the number is the heading turned to
    if #rel_c == 0 and #abs_c == 1 and abs_c[1].kind == "plain"
        and ((abs_c[1].number.typed and #abs_c[1].number.digits <= 2)
             or (not abs_c[1].number.typed and not abs_c[1].number.lead_digit and abs_c[1].value < 100)) and not self:word_in(s.b, s.e, "heading hdg")
        and self:word_in(s.b, abs_c[1].b, "@left @right turn") and not self:word(abs_c[1].b - 1, "to onto") then
      rel_c[1] = { kind = "angle", value = abs_c[1].value, b = abs_c[1].b, e = abs_c[1].e, turn = 0,
                   number = abs_c[1].number }
      abs_c = {}
    end
    -- "turn right by 200": a number after "by" is the degrees of the turn
    if #rel_c == 0 and #abs_c == 1 and abs_c[1].kind == "plain" and self:word(abs_c[1].b - 1, "by")
        and self:word_in(s.b, abs_c[1].b, "@left @right") then
      rel_c[1] = { kind = "angle", value = abs_c[1].value, b = abs_c[1].b, e = abs_c[1].e, turn = 0,
                   number = abs_c[1].number }
      abs_c = {}
    end
    -- "increase SAS9's heading by 30", "heading minus 20", "add 30 to the heading of SAS9", "subtract
    -- 20 from EZY45's heading": the heading changed by an amount, more to the right, less to the left
    if (#rel_c == 0 or (#rel_c == 1 and rel_c[1].turn == 0)) and not self:word_in(s.b, s.e, "@left @right") then
      -- (the verb may open the segment before: "increase" alone starts a speed)
      local vb = math.min(s.b, math.max(1, s.trig - 3))
      local up = self:word_in(vb, s.e, "increase plus add")
      local down = self:word_in(vb, s.e, "decrease minus subtract reduce")
      for _, q in ipairs(up ~= down and self:quantities(s.b, s.e) or {}) do
        if (q.kind == "plain" or q.kind == "heading" or q.kind == "angle")
            and (self:word_in(math.max(1, q.b - 2), q.e, "by plus minus add subtract") or q.value < 0)
            and math.abs(q.value) < 360 then
          rel_c[1] = { kind = "angle", value = math.abs(q.value), b = q.b, e = q.e, turn = up and 1 or -1,
                       number = q.number, changed = true }
          abs_c = {}
          self:take(q)
          break
        end
      end
    end
    -- "the heading of 200 degrees on the right side": an angle said as the
    -- heading is the heading, its side the direction of the turn
    if #abs_c == 0 and #rel_c == 1 and not rel_c[1].changed and self:preceded_by(rel_c[1].b, 2, "heading hdg") then
      abs_c[1] = { kind = "heading", value = rel_c[1].value, b = rel_c[1].b, e = rel_c[1].e, number = rel_c[1].number }
      rel_c = {}
    end
    local now = self:state(ids[1])
    if now and self:value_left(abs_c[1], abs_c[2], now.hdg_deg, 5, true) then table.remove(abs_c, 1) end
    local abs, rel = self:pick(abs_c, s, "heading"), self:pick(rel_c, s, "heading")
    -- ("left ten degrees, no make that fifteen": a bare number under 100, not said digit by digit, after a correction
    -- that follows the turn's degrees and says no side, corrects the degrees; never a heading of 015)
    if abs and rel and abs.kind == "plain" and rel.b < abs.b and abs.value < 100 and not abs.number.lead_digit
        and self:word_in(rel.e, abs.b, "@correction") and not self:word_in(rel.e, abs.e, "@left @right") then
      rel, abs = { kind = "angle", value = abs.value, b = abs.b, e = abs.e, turn = rel.turn, number = abs.number }, nil
    end
    -- ("heading zero zero five zero", "hdg 0050": a heading of four digits or more is no heading said; asked)
    if abs and abs.number and #(abs.number.digits or "") > 3 then
      return self:need(string.format("What heading should %s fly? I heard '%s', %d digits.", ids[1],
        self:raw(abs.b, abs.e), #abs.number.digits))
    end
    local correction = self:word_in(s.b, s.e, "@correction")
    local turn = 0
    -- a direction said after a correction replaces the one before it ("turn left, correction, turn right")
    local tb = s.b
    for i = s.b, correction and s.e - 1 or 0 do
      if self:word(i, "@correction") and self:word_in(i + 1, s.e, "@left @right") then tb = i + 1 end
    end
    if self:word_in(tb, s.e, "@left") then turn = -1 end
    if self:word_in(tb, s.e, "@right") and self:find_word(tb, s.e, "@right") < self:find_word(tb, s.e, "@left") then
      turn = 1
    end
    -- both sides said for the turn with no correction word between ("left DLH404 turn right heading 090", "turn
    -- left heading 180, sorry, I meant to the right"): the later side when a self-correction marker
    -- (lexicon.self_correction.markers' words) is said between them; else asked when both come before the end of
    -- the turn's value or straight after it ("turn left heading 200 right"), or after "turn" ("heading 120 left, turn
    -- right"; a side later, "..., traffic left ten o'clock", "vectors ILS 25 right", is another's)
    local first = math.min(self:find_word(tb, s.e, "@left"), self:find_word(tb, s.e, "@right"))
    local value_end = (abs and abs.e) or (rel and rel.e) or s.e
    for x = first + 1, first < s.e and s.e - 1 or 0 do
      if self:word(x, "@left @right") and self.words[x] ~= self.words[first] and not self.noted[x] then
        if marker_in(self, first + 1, x) then
          turn, tb = self:word(x, "@right") and 1 or -1, x
        elseif x < value_end or x == self:skip_fillers(value_end) or self:word(x - 1, "turn turning") then
          return self:need(string.format("Should %s turn left or right? I heard '%s' and '%s'.", ids[1],
            self.t[first].raw, self.t[x].raw))
        end
      end
    end
    -- (a side corrected after the angle, "30 degrees right, sorry, left": that many degrees the corrected way)
    if rel and rel.turn ~= 0 and turn ~= 0 and tb > rel.b then
      rel = { kind = rel.kind, value = rel.value, b = rel.b, e = rel.e, turn = turn, number = rel.number, to = rel.to,
              changed = rel.changed }
    end
    -- ("turn left heading 100, sorry, fly present heading", "..., no, continue present heading"): the present
    -- heading said after a self-correction marker or "correction" that follows the value takes the value and its
    -- side back (the heading it flies, no turn); a side said after the marker too, or no marker between, is asked
    -- ("from your present heading", "30 degrees right of its present heading" say what a turn counts from)
    local said_value = abs or rel
    local kept = said_value and said_value.e
    while kept and kept < s.e and not (self:word(kept, "@present") and self:word(kept + 1, "heading hdg")) do
      kept = kept + 1
    end
    local from = kept and (self:word(kept - 1, "your its the") and kept - 2 or kept - 1)
    if kept and kept < s.e and not self:word(from, "from of off") then
      -- (said with no marker, "turn right heading 200, continue present heading", which one stands is unclear)
      if not (marker_in(self, said_value.e, kept) or self:word_in(said_value.e, kept, "@correction"))
          or self:word_in(said_value.e, s.e, "@left @right") then
        return self:need(string.format("Should %s turn, or keep its present heading? I heard '%s'.", ids[1],
          (self:raw(s.trig, s.e):gsub(" ([,.;:])", "%1"))))
      end
      abs, rel, turn = nil, nil, 0
    end
    local named
    for i = s.b, s.e - 1 do
      if named then break end
      -- a compass word of a callsign ("Southwest 963", "the southwest one": inside an aircraft's reference) or a
      -- place ("northeast of") is no heading
      local function of_aircraft()
        for _, r in ipairs(self.refs) do
          if r.kind == "aircraft" and r.b <= i and i < r.e then return true end
        end
        return false
      end
      if self.t[i].kind == "word" and compass(self.t[i].text) and not self.u:used(i) and not self:word(i + 1, "of")
          and not of_aircraft() then
        named = compass(self.t[i].text, i + 1 < s.e and self.t[i + 1].text or "", i + 2 < s.e and self.t[i + 2].text or "")
        -- a compass point leaned toward ("more to the north", "a bit further east") names no heading
        local v = named and self:find_word(math.max(s.b, i - 3), i, "@vague_direction") or i
        if v < i or named and self:word_in(i + 1, math.min(s.e, i + 3), "@vague_direction") then
          v = math.min(v, i)
          if self:word(v - 1, "a") then v = v - 1 end
          local last = i
          while last + 1 < math.min(s.e, i + 3) and self:word(last + 1, "a @vague_direction") do last = last + 1 end
          return self:need(string.format("What heading should %s fly? '%s' names no heading.", ids[1], self:raw(v, last + 1)))
        end
      end
    end
    local id = ids[1]
    local refs = self:refs_in(s.b, s.e, "aircraft")
    -- the place said after "towards" / "in the direction of" (a waypoint, or a place by its name)
    local toward
    -- ("turn to face our school": the place faced, after "to face")
    local tw = self:find_word(s.b, s.e, "towards toward direction")
    local face = self:find_word(s.b, s.e, "face")
    if tw == s.e and face < s.e and self:word(face - 1, "to") then tw = face end
    -- ("tra203 hdg to goala", "heading to GOALA": a waypoint straight after "heading to", no number, is faced: a
    -- waypoint of the scene or of the aircraft's route typed as it is named, in any case, or one in capitals)
    local hw, faced = self:find_word(s.b, s.e, "hdg heading"), nil
    if tw == s.e and hw + 2 < s.e + 1 and self:word(hw + 1, "to") then
      local r, t = self:refs_in(hw + 2, hw + 3, "waypoint")[1], self.t[hw + 2]
      if r and r.b == hw + 2 then
        faced = r.name:upper()
      -- (a filler is no place: "heading to the route" faces no navaid THE)
      elseif t and t.kind == "word" and t.alpha and not t.filler and not self.u:used(hw + 2) then
        local a = self:state(ids[1])
        for _, n in ipairs(self.world.waypoints or {}) do
          if n:upper() == t.text:upper() then faced = n:upper() end
        end
        for _, n in ipairs(a and a.route or {}) do
          if n:upper() == t.text:upper() then faced = n:upper() end
        end
        local at = self.world.user_waypoint_at
        if not faced and at and at(t.text:upper()) then faced = t.text:upper() end
      end
      if faced then self:explain(hw + 1, hw + 3) end
    end
    -- (toward_at: where the place said after "toward" starts. A question raised while looking it up, or none found
    -- by its words, is kept as the clause's question (self.place_ask): never set aside as a valueless
    -- instruction's and dropped beside the request's other commands, never the heading flown to a place asked about)
    local toward_at, ask0
    if faced and not abs and not rel then toward = faced end
    if not abs and not rel and tw < s.e and (not self:word(tw, "direction") or self:word(tw + 1, "of")) then
      local at = self:word(tw, "direction") and tw + 2 or tw + 1
      toward_at, ask0 = at, self.ask
      local r = self:refs_in(at, math.min(s.e, at + 3), "waypoint")[1]
      -- ("towards the Pampus VOR": the navaid's kind after its name names no waypoint of its own)
      if r and r.b > at and self:word(r.b, "@navaid_kinds") and not self:word(r.b - 1, "the a") then r = nil end
      if r then self:explain(tw, r.e) end
      toward = r and r.name:upper() or self:place_by_name(at, s.e, now, nil, true)
      -- ("toward O'Hare": an airport said by a distinctive part of its name, as a destination is read)
      if not toward and now and not self.ask then toward = self:airport_by_words(at, math.min(s.e, at + 3), now) end
      -- ("toward Providence airport": a city said with an airport noun is its airport, as a destination is read:
      -- KPVD beside the PROVIDENCE VOR)
      if not toward and now and not self.ask and self:word_in(at, math.min(s.e, at + 4), "@airport_nouns") then
        toward = self:airport_by_name(at, s.e, now, true)
      end
      if self.ask ~= ask0 then
        self.place_ask = true
        return
      end
    end
    local hdg, offset  -- offset: degrees from each aircraft's present heading
    -- ("turn left by 90 degrees and, in two minutes, onto heading 070": a heading said after a turn's degrees in the
    -- turn's sentence, no correction between, is a second heading unless it is the one the turn reaches: asked, as
    -- below, never the degrees dropped)
    -- (so is a turn's degrees said after the heading: "turn left heading 330 by 15 degrees"; or after a bare number
    -- that is read as the heading: "fly heading... oh, 100, okay, left ten degrees")
    local turned = abs and (abs.kind == "heading" or abs.kind == "plain") and rel and not correction and now
      and not self:in_reason(abs.b) and not self:in_reason(rel.b) and (rel.turn ~= 0 and rel.turn or turn)
    local first_e, second_b = rel and math.min(rel.e, abs and abs.e or rel.e), rel and math.max(rel.b, abs and abs.b or rel.b)
    for x = first_e or 1, turned and second_b - 1 or 0 do
      if self.t[x].kind == "punct" and self.t[x].text ~= "," then turned = false end
    end
    -- ("turn right 30 degrees, watch it go from 090", "left 20 degrees, heading was 240": the heading flown now, said
    -- after a word of lexicon.present_heading_words, is where the turn starts, no second heading)
    local function present(q)
      return q and now and self:word(q.b - 1, "@present_heading_words")
        and wrap(q.value) == wrap(math.floor(now.hdg_deg + 0.5))
    end
    if present(abs) and rel then abs = nil end
    local reached = turned and abs and turned ~= 0 and wrap(math.floor(now.hdg_deg + turned * rel.value + 0.5))
    if reached and wrap(abs.value) ~= reached then
      return self:need(string.format("Should %s turn %s by %s degrees, onto %03d, or fly heading %s?", id,
        turned < 0 and "left" or "right", f.num(rel.value), reached, f.num(abs.value)))
    end
    if abs and (abs.kind == "heading" or not (rel and rel.b < abs.b and not correction)) then
      hdg = abs.value
      local n = abs.number
      -- headings are said as three digits; two ("two five") lost their final zero, unless
      -- they end in zero themselves ("three zero": 030 or 300?) or one was said
      -- "heading to niner zero": two digits after "to" are a heading only with "to" as "two";
      -- "heading to one zero" may also be 100 (the final zero lost): asked
      if not n.typed and n.groups == 2 and #n.digits == 2 and self:word(abs.b - 1, "@two_heard") then
        if hdg * 10 <= 360 then
          return self:need(string.format("What heading should %s fly: %d or %03d? I heard '%s %s'.", id, 200 + hdg,
            hdg * 10, self.t[abs.b - 1].raw, self:raw(abs.b, abs.e)))
        end
        hdg = 200 + hdg
      elseif not n.typed and n.lead_digit and H.cut_off(n) then
        return self:need("What heading should " .. id .. " fly? I heard " .. n.digits .. ": headings have three digits.")
      elseif not n.typed and #n.digits < 3 and not n.hundred and self:broken_off(abs.e) then
        -- ("turn right heading zero four... uh": the digits broken off, the rest never said)
        return self:need("What heading should " .. id .. " fly? I heard " .. n.digits .. " and no more: headings have "
          .. "three digits.")
      end
      -- "hdg 27" typed: two digits with no leading zero may have lost the final one (027 or 270?)
      if n.typed and #n.digits == 2 and hdg >= 10 and hdg <= 36 and hdg == math.floor(hdg) then
        return self:need(string.format("What heading should %s fly: %03d or %d? I heard '%s'.", id, hdg, hdg * 10,
          self:raw(abs.b, abs.e)))
      end
      -- "hdg 07" typed: a leading zero and one digit may have lost a final digit as well (007 or 070?)
      if n.typed and #n.digits == 2 and n.digits:sub(1, 1) == "0" and hdg >= 1 then
        return self:need(string.format("What heading should %s fly: %03d or %03d? I heard '%s'.", id, hdg, hdg * 10,
          self:raw(abs.b, abs.e)))
      end
      -- "hdg 2" typed: one digit, no leading zero, is a heading cut short
      if n.typed and #n.digits == 1 and hdg >= 1 and hdg == math.floor(hdg) then
        return self:need("What heading should " .. id .. " fly? I heard " .. n.digits .. ": headings have three digits.")
      end
      if not n.typed and n.lead_digit and n.groups == 2 and hdg < 40 then
        -- only a fluent "two five" lost its final zero; with a hesitation before or inside it
        -- ("heading uh two two", "two uh two") a digit may be missing anywhere
        if self:word_in(abs.b - 1, abs.e, "@hesitations") then
          return self:need("What heading should " .. id .. " fly? I heard " .. n.digits .. ": headings have three digits.")
        end
        hdg = hdg * 10
      end
      if hdg > 360 then
        -- three digits said one by one ("four zero zero") are the heading heard, never re-read from fewer; so is
        -- a number said with "hundred" ("four hundred")
        local r = not (not n.typed and (n.groups == 3 and #n.digits == 3 or n.hundred))
          and self:repaired(abs, hdg, 0, 360, 5)
        if not r then return self:need("What heading should " .. id .. " fly? I heard " .. f.int(hdg) .. ".") end
        hdg = r
      end
    elseif rel and (rel.turn == 0 and turn == 0 or rel.to and rel.value <= 360) then
      -- "to 200 degrees" names the heading, also after a way to turn ("turn right to 200 degrees")
      if not (rel.to or self:word_in(s.b, s.e, "heading")) then
        return self:need(string.format("Should %s turn left or right by %s degrees, or fly heading %s?", id,
          f.num(rel.value), f.num(rel.value)))
      end
      hdg = rel.value  -- "to one hundred and twenty degrees"
    elseif rel then
      if not now then return self:need("What is the current heading of " .. id .. "?") end
      local dir = rel.turn ~= 0 and rel.turn or turn
      if dir == 0 then return self:need("Should " .. id .. " turn left or right?") end
      -- ("turn right 090 degrees": three digits led by a zero are written as a heading is, "degrees" as a turn's
      -- size: asked, unless "by" names the size)
      local d = rel.number and rel.number.digits
      if d and #d == 3 and d:find("^0") and rel.value <= 360 and not self:word(rel.b - 1, "by")
          and self:word_in(rel.b, rel.e + 1, "degrees degree deg") then
        return self:need(string.format("Should %s turn %s by %s degrees, or fly heading %s?", id,
          dir < 0 and "left" or "right", f.num(rel.value), d))
      end
      offset = dir * rel.value
      self:as_change(rel)
      -- (a heading said after the turn's degrees, no correction between, "left 30 degrees then 300", "left 30
      -- degrees, to 270": a second heading in the turn's sentence, asked, unless it is the one the turn reaches)
      local reached = wrap(math.floor(now.hdg_deg + offset + 0.5))
      local second = abs and abs.b > rel.b and not correction and wrap(abs.value) ~= reached
        and not self:in_reason(abs.b)
      for x = rel.e, second and abs.b - 1 or 0 do  -- (in the turn's sentence: "... 35 degrees? We want it closer to 90")
        if self.t[x].kind == "punct" and self.t[x].text ~= "," then second = false end
      end
      if second then
        return self:need(string.format("Should %s turn %s by %s degrees, onto %03d, or fly heading %s?", id,
          dir < 0 and "left" or "right", f.num(rel.value), reached, f.num(abs.value)))
      end
    elseif named then
      hdg = named
    elseif toward then
      -- "towards Kempten", "in the direction of Munich airport": HDG's name, the bearing to that place
      for _, a in ipairs(ids) do self:emit("HDG " .. a .. " " .. toward .. (turn < 0 and " LEFT" or turn > 0 and " RIGHT" or "")) end
      return
    elseif self:word_in(s.b, s.e, "@turn_around") then
      if not now then return self:need("What is the current heading of " .. id .. "?") end
      -- (a reversal with no way said: either way is as short, and the way matters to traffic)
      if turn == 0 then return self:need("Should " .. id .. " turn around to the left or to the right?") end
      offset = 180
    elseif (self:word_in(math.max(1, s.trig - 2), s.e, "@present") or self:word_in(math.max(1, s.trig - 2), s.trig + 1,
        "@keep_verbs") or (self:word(s.trig, "turn turning") and self:word_in(math.max(1, s.trig - 2), s.trig, "stop")))
        and now then
      -- ("maintain present heading"; "maintain heading", "keep your heading" with no value said: the one it flies;
      -- "stop turn", "stop the turn": the one it flies when stopping)
      -- ("turn right present heading": a side said with the heading it flies names no heading to turn to; asked)
      if turn ~= 0 and self:word_in(math.max(1, s.trig - 2), s.e, "@present") then
        return self:need(string.format("Should %s turn %s, or keep its present heading? I heard '%s'.", id,
          turn < 0 and "left" or "right", (self:raw(s.trig, s.e):gsub(" ([,.;:])", "%1"))))
      end
      offset = 0
      -- (the heading flown kept: G:present_kept_by_lnav_off drops it beside that aircraft's LNAV OFF)
      self.present_hdg = self.present_hdg or {}
      self.present_hdg[id] = true
    elseif #refs >= 2 and self:word_in(s.b, s.e, "@same_as") then
      local src = self:state(refs[#refs].name)
      if not src then return self:need("What is the heading of " .. refs[#refs].name .. "?") end
      id, hdg, ids = refs[1].name, src.hdg_deg, { refs[1].name }
    else
      -- ("fly toward Providence airport" far from it: a place said after "toward" that names none found is asked
      -- by its words)
      local last = toward_at and toward_at < s.e and s.e
      while last and last > toward_at and self.t[last - 1].kind == "punct" do last = last - 1 end
      if last and last > toward_at then
        self.place_ask = true
        return self:need(string.format("Which place is '%s'? I found no place by that name for %s. Please give its "
          .. "ICAO code or ident.", self:raw(toward_at, last), id))
      end
      return self:need("What heading should " .. id .. " fly?")
    end
    -- the way to turn, when it was said: HDG's LEFT/RIGHT (a squawk extension)
    local way = (rel and rel.turn ~= 0 and rel.turn) or turn
    -- "turn right 180", "r 360", "l 200" with no "heading" (typed, or a number not said digit by digit): a
    -- heading the long way round (more than half a circle) or a turn of that many degrees (a "360" an
    -- orbit)? Asked. So is a heading straight behind ("turn right 270" from 090: a reversal onto 270, or a
    -- turn of 270 degrees?) unless both readings are one heading. The short way round, "turn" said ("turn
    -- right 190" from 080) reads either way too: asked; without it ("l 230", "left 270, down to 3000", typed
    -- shorthand) it is the heading. A number typed with a leading zero ("turn left 090") is a heading: no
    -- turn's degrees are written so
    -- "turn left three sixty", "turn right three hundred and sixty": a whole circle said as a number (not digit by
    -- digit), with no "heading", is an orbit, which squawk does not fly, or the heading 360: asked; typed, "rt 360
    -- for spacing", so when a purpose of an orbit follows it ("l 360" alone is the heading)
    -- "do a left two-seventy", "make a right 270": "a", a side and straight after it a number, no "heading", names
    -- a turn of that many degrees (a manoeuvre, the noun "a left 270") as well as the heading: asked ("a left turn
    -- to 270" names the heading)
    local article = abs and abs.kind == "plain" and way ~= 0 and not offset and hdg
      and not self:word_in(s.b, s.e, "heading hdg") and self:find_word(s.b, abs.b, "a")
    if article and article < abs.b and self:word(article + 1, "@left @right")
        and self:skip_fillers(article + 2) == abs.b then
      return self:need(string.format("Should %s turn %s by %s degrees, or fly heading %s? I heard '%s'.", id,
        way < 0 and "left" or "right", f.num(abs.value), f.num(wrap(hdg)), self:raw(article, abs.e)))
    end
    local n = abs and abs.number
    local for_orbit = n and n.typed and self:word(abs.e, "for")
      and self:word(abs.e + 1, "spacing sequencing delay separation traffic")
    if hdg and not offset and way ~= 0 and abs and abs.kind == "plain" and abs.value == 360
        and (for_orbit or not n.typed and (n.hundred or n.groups < #n.digits))
        and not self:word_in(s.b, s.e, "heading hdg") then
      return self:need(string.format("Should %s make a full turn %s (an orbit, which squawk does not simulate), or "
        .. "fly heading 360? I heard '%s'.", id, way < 0 and "left" or "right", self:raw(abs.b, abs.e)))
    end
    if hdg and not offset and way ~= 0 and abs and abs.kind == "plain" and now and #ids == 1
        and (abs.number.typed or not abs.number.lead_digit)
        and not self:word_in(s.b, s.e, "heading hdg") and abs.value <= 360 then
      local long = (way * (hdg - now.hdg_deg)) % 360
      local side = way < 0 and "left" or "right"
      if long > 180 then
        return self:need(string.format("Should %s turn %s by %s degrees, or fly heading %s the long way round?",
          id, side, f.num(abs.value), f.num(wrap(hdg))))
      -- (a leading zero names the heading straight behind: "right 090" from 270)
      elseif long == 180 and abs.value ~= 180 and not abs.number.digits:find("^0") then
        return self:need(string.format("Should %s turn %s by %s degrees, or turn %s onto heading %s, straight behind?",
          id, side, f.num(abs.value), side, f.num(wrap(hdg))))
      -- ("turn right to 120", "turn left at 160": "to", "onto" or "at" before the number names the heading reached,
      -- as "climb at 200" names the level)
      elseif self:word_in(s.b, s.e, "turn") and not abs.number.digits:find("^0") and not self:word(abs.b - 1, "to onto at")
          and wrap(now.hdg_deg + way * abs.value) ~= wrap(hdg) then
        return self:need(string.format("Should %s turn %s by %s degrees, or fly heading %s?", id, side,
          f.num(abs.value), f.num(wrap(hdg))))
      end
    end
    -- "turn left one eighty", "turn right one hundred eighty": 180 said as a number (not digit by digit, no
    -- "heading", nothing naming the heading reached before it) after "turn" and a side is a reversal, the turn's
    -- degrees (as "do a 180 to the left"); "turn left one eight zero" stays the heading
    if hdg and not offset and way ~= 0 and abs and abs.kind == "plain" and abs.value == 180 and n and not n.typed
        and (n.hundred or n.groups < #n.digits) and self:word_in(s.b, s.e, "turn")
        and not self:word_in(s.b, s.e, "heading hdg") and not self:word(abs.b - 1, "to onto at") then
      offset, hdg = way * 180, nil
    end
    local suffix = way < 0 and " LEFT" or way > 0 and " RIGHT" or ""
    -- a change from the present heading is each aircraft's own, in whole degrees
    local lines = {}
    for _, a in ipairs(ids) do
      local from = offset and self:state(a)
      if offset and not from then return self:need("What is the current heading of " .. a .. "?") end
      local h = from and math.floor(from.hdg_deg + offset + 0.5) or hdg
      lines[#lines + 1] = "HDG " .. a .. " " .. (from and f.int(wrap(h)) or f.num(wrap(h))) .. suffix
    end
    -- a relative turn of more than half a circle is confirmed before it runs (with the rest of the request)
    if offset and math.abs(offset) > 180 then
      self:confirm_before(string.format("Turn %s %s by %s degrees, the long way round, to %s? (yes or no)",
        table.concat(ids, ", "), way < 0 and "left" or "right", f.num(math.abs(offset)),
        lines[1]:match("^HDG %S+ (%S+)")))
    end
    for _, line in ipairs(lines) do self:emit(line) end
  end

  -- (s.rate: the rate's quantity when the caller has found it, else the first fitting one of the segment)
  function m:vspeed(s)
    local id = self:acid(s, "change its vertical speed")
    if not id then return end
    local v = s.rate
    for _, q in ipairs(v and {} or self:quantities(s.b, s.e)) do
      if (q.kind == "vs" or q.kind == "plain" or (q.kind == "alt" and not q.fl)) and self:rate_value(s.trig, q) then
        v = q
        break
      end
    end
    if not v then return self:need("What vertical speed should " .. id .. " fly, in feet per minute?") end
    self:take(v)
    local fpm = v.value
    -- ("vs 15": below lexicon.min_typed_fpm, hundreds of ft/min with the zeros left out?)
    if fpm ~= 0 and math.abs(fpm) < L.min_typed_fpm then
      return self:need(string.format("What vertical speed should %s fly, in feet per minute? I heard '%s'.", id,
        self:raw(v.b, v.e)))
    end
    -- the sign is the way the aircraft moves, named by the motion when one is said ("increase your rate of
    -- descent to 2500" descends, "reduce your rate of climb to 500" climbs); otherwise the verb's direction
    -- (in the instruction's whole clause, up to the punctuation around it: "descend with vertical speed 2000",
    -- "vertical speed 2000 feet per minute for descend" descend)
    -- (the instruction to this aircraft: from the aircraft reference before the rate to the next one)
    local names = self:refs_in(1, #self.t + 1, "aircraft")
    local ib, ie = 1, #self.t + 1
    for _, r in ipairs(names) do
      local other = (r.name or ""):upper() ~= id:upper()
      if r.e <= s.trig and r.e > ib then ib = r.e end
      if r.b > s.trig and r.b < ie and other then ie = r.b end
    end
    local cb, ce = s.b, s.e
    while cb > ib and self.t[cb - 1].kind ~= "punct" do cb = cb - 1 end
    while ce < ie and self.t[ce].kind ~= "punct" do ce = ce + 1 end
    ce = math.min(ce, ie)
    -- (both ways said in that clause are asked; one said after "then", before or after the rate, is another
    -- instruction's: "climb FL300 then descend at 2000 fpm")
    local mb, me = cb, s.trig
    while me < ce and self.t[me].kind ~= "punct" and not self:word(me, "@then_words") do me = me + 1 end
    for k = cb, s.trig - 1 do
      if self:word(k, "@then_words") then mb = k + 1 end
    end
    if self:motions_asked(mb, me, id) then return end
    local down = self:word_in(cb, ce, "descent descend descending")
    local up = self:word_in(cb, ce, "climb climbing")
    local dir = (down and not up) and -1 or (up and not down) and 1 or self:direction(s)
    -- (none in its clause: a climb's or descent's word said elsewhere in the instruction to this aircraft gives
    -- the way: "expedite descent, vertical speed
    -- 3000" descends; both ways said there are asked)
    if dir == 0 and not down and not up then
      local wu, wd
      for k = ib, ie - 1 do
        if (k < cb or k >= ce) and not (self.noted[k] or self:in_reason(k)) then
          if self:motion_said(k, "@up", names) or self:word(k, "climb climbing") then wu = wu or k end
          if self:motion_said(k, "@down", names) or self:word(k, "descent descend descending") then wd = wd or k end
        end
      end
      if wu and wd then
        return self:need(string.format("Climb or descend? I heard '%s' and '%s' for %s, with no correction between.",
          self.t[math.min(wu, wd)].raw, self.t[math.max(wu, wd)].raw, id))
      end
      dir = wd and -1 or wu and 1 or 0
    end
    -- ("climb FL230, passing 150 reduce rate to 1000": "reduce" or "increase" said of the rate, no motion named,
    -- changes its size, not its way: a level flown to in the request gives the way)
    local resized = not down and not up and self:word_in(cb, ce, "rate") and self:word_in(cb, ce, "reduce increase decrease")
    -- (so "reduce" or "increase" there is no way: "reduce rate to 1000" to a climbing aircraft climbs)
    if resized and self:word_in(cb, ce, "reduce increase decrease") then
      local said_way = false
      for k = ib, ie - 1 do
        if (self:word(k, "@up") or self:word(k, "@down")) and not self:word(k, "reduce increase decrease") then
          said_way = true
        end
      end
      if not said_way then dir = 0 end
    end
    -- ("be at FL300 by LAPOS, rate 2500": no direction said, the way to the level given it before in the
    -- request, a constraint's too; "FL300, rate of climb 2500" said to an aircraft above FL300 names the
    -- other way: asked)
    local now, own = self:state(id), id:gsub("%p", "%%%0")
    local levels = {}  -- feet
    for _, c in ipairs(now and self.out or {}) do
      local fl = c:match("^ALT " .. own .. " FL(%d+)") or c:match("^AT " .. own .. " %S+ ALT FL(%d+)$")
      -- (an altitude in feet too: "descend to 2500, vertical speed 500" descends)
      local ft = c:match("^ALT " .. own .. " (%d+)$") or c:match("^AT " .. own .. " %S+ ALT (%d+)$")
      levels[#levels + 1] = fl and tonumber(fl) * 100 or tonumber(ft)
    end
    -- (a flight level said before the rate's word in its segment, "FL380 rate of descent 2000", is flown too)
    for _, q in ipairs(now and self:quantities(s.b, v.b) or {}) do
      if q.kind == "alt" and q.fl and q.b < s.trig and not self.taken[q.b] then levels[#levels + 1] = q.value end
    end
    -- (and, when no way is said, a flight level said after the rate in the instruction to this aircraft with
    -- "altitude" or "level" before it and no condition's word, "vertical rate 1800 ft/min, altitude FL280": the
    -- level it flies to)
    for _, q in ipairs(now and dir == 0 and self:quantities(v.e, ie) or {}) do
      local lead = math.max(v.e, q.b - 3)
      if q.kind == "alt" and q.fl and self:word_in(lead, q.b + 1, "altitude level")
          and not self:word_in(lead, q.b + 1, "at passing through reaching until when after before then") then
        levels[#levels + 1] = q.value
      end
    end
    for _, ft in ipairs(levels) do
      local cur = now.alt_ft or 0
      if math.abs(ft - cur) > 50 then
        local way = ft > cur and 1 or -1
        if dir ~= 0 and dir ~= way and not resized then
          return self:need(string.format("%s is at %s ft, %s is %s it: %s at %s ft/min? Please confirm the rate.",
            id, f.int(cur), f.alt(ft, true), way < 0 and "below" or "above", dir < 0 and "descend" or "climb",
            f.int(math.abs(fpm))))
        end
        dir = way
      end
    end
    -- a level said after the rate with "to" or "target" ("1200 fpm down to 13000", "VS 1000 up, target
    -- 14000"): the level the rate flies to, an ALT beside the VS; one on the other side of the aircraft's
    -- level from the rate's direction is asked
    local level = self:rate_target(v, ce)
    local now = level and self:state(id)
    if level and now then
      local ft, cur = level.value, now.alt_ft or 0
      local way = ft > cur + 50 and 1 or ft < cur - 50 and -1 or 0
      if way == 0 or (dir ~= 0 and dir ~= way) then
        return self:need(string.format("%s is at %s ft: %s at %s ft/min to %s? Please confirm the level.", id,
          f.int(cur), dir < 0 and "descend" or "climb", f.int(math.abs(fpm)), f.alt(ft, level.fl)))
      end
      dir = way
    end
    -- no way said nor flown to in the request: the aircraft's own climb or descent under way towards its selected
    -- level gives it ("vertical speed 1000" to an aircraft descending to FL100 descends). An aircraft level keeps
    -- BlueSky's reading of the plain number, a climb rate: the rate selected moves nothing until a level is given,
    -- and ALT zeroes a selected rate of the wrong sign (../shared/facts/bluesky.md, ALT); a plus said or typed
    -- before the value ("vertical speed +900") is its sign. A level said elsewhere in the request (a condition's,
    -- "then at FL100 turn") may be the one the rate was meant to reach: asked.
    if dir == 0 and fpm > 0 and not self:word(v.b - 1, "plus") then
      local a = self:state(id)
      local togo = a and a.sel_alt_ft and a.alt_ft and a.sel_alt_ft - a.alt_ft or 0
      if math.abs(togo) > 50 then
        dir = togo > 0 and 1 or -1
      elseif a and not self:word(s.trig, "vs roc") then
        for _, q in ipairs(self:quantities(1, #self.t + 1)) do
          if q.kind == "alt" and (q.b < v.b or q.b >= v.e) and math.abs(q.value - (a.alt_ft or 0)) > 50 then
            return self:need(string.format("Climb or descend at %s ft/min? %s is level at %s; is %s the level to reach?",
              f.int(fpm), id, (a.alt_ft or 0) >= 10000 and f.alt(a.alt_ft, true) or f.int(a.alt_ft or 0) .. " ft",
              f.alt(q.value, q.fl)))
          end
        end
      end
    end
    -- ("climb vs minus 2000", "descend at plus 2000 fpm": a sign said against the motion said is asked)
    if (fpm < 0 and up and not down) or (self:word(v.b - 1, "plus") and down and not up) then
      return self:need(string.format("Climb or descend? I heard '%s' for %s, who was told to %s.", self:raw(
        self:word(v.b - 1, "plus") and v.b - 1 or v.b, v.e), id, up and "climb" or "descend"))
    end
    if fpm > 0 and dir < 0 then fpm = -fpm end
    self:emit("VS " .. id .. " " .. f.int(fpm))
    if level then
      self:take(level)
      self:emit("ALT " .. id .. " " .. f.alt(level.value, level.fl))
    end
  end

  -- True when quantity q is said as the value of the rate named at token k (its word, "rate", "vs", "vertical
  -- speed", or the instruction's): a value with a rate's unit (ft/min, m/s) wherever it stands; a number after k,
  -- unless it is a flight level or an altitude with its unit (feet, metres) after "to", a level flown to ("rate of
  -- descent to 9000 feet"; "increase your rate to two thousand five hundred" is the rate).
  function m:rate_value(k, q)
    return q.kind == "vs" or (q.b > k and not q.fl and not (q.kind == "alt" and self:word(q.b - 1, "to")
      and self:word(q.e - 1, "@feet @metres")))
  end

  -- The level a vertical speed flies to, said after its quantity v with "to" or "target" before it and only
  -- "up", "down", "a", "of" or one comma between ("1000 fpm up to 12000", "VS 1000 up, target 14000"); the
  -- search ends at token e or the clause after that comma: the level's quantity or nil.
  function m:rate_target(v, e)
    local k = v.e
    while k <= #self.t and (self:word(k, "up down a of") or (self.t[k].kind == "punct" and self.t[k].text == ",")) do
      k = k + 1
    end
    if not self:word(k, "to target") then return nil end
    local q = self:quantities(k + 1, math.max(e, k + 4))[1]
    if not q or q.b ~= k + 1 or not (q.kind == "alt" or (q.kind == "plain" and (q.fl or q.value >= 1000))) then
      return nil
    end
    return q
  end
end
