-- The handlers of the offline grammar (translate/grammar.lua): one per
-- intent of translate/rules.lua, each filling its command's arguments from
-- the quantities and names of its stretch of the utterance.
--
-- A handler is method(g, s, spec): g the grammar state (tokens g.t, names
-- g.refs, traffic g.fleet, output g.out), s the segment {intent, b, trig, e}
-- ([b, e) token range, trig the instruction word). It appends TrafScript
-- lines with g:emit() or names what is missing with g:need(question); it
-- never guesses a value that was neither said nor read from the traffic.
local L = require("translate.lexicon")

local H = { methods = {} }
local m = H.methods

-- ---- formatting: values as TrafScript text ----
local f = {}
H.format = f
function f.num(v)
  local s = string.format("%.6f", v):gsub("0+$", ""):gsub("%.$", "")
  return s == "-0" and "0" or s
end
-- Whole numbers as heard, also beyond the integer range (asked about, never wrapped).
function f.int(v)
  if v ~= v then return "?" end
  if math.abs(v) >= 2 ^ 53 then return string.format("%.0f", v) end
  return string.format("%d", math.floor(v + 0.5))
end
function f.alt(ft, fl)
  if fl and ft % 100 == 0 then return "FL" .. f.int(ft / 100) end
  return f.int(ft)
end
function f.mach(v)
  local s = string.format("%.3f", v):gsub("0+$", ""):gsub("%.$", "")
  return "M" .. (s:sub(1, 1) == "0" and s or "0" .. s)
end
local function wrap(h)
  local r = math.fmod(h, 360)
  if r <= 0 then r = r + 360 end
  return r
end

local BASE = { north = true, east = true, south = true, west = true }
-- A compass point said in one word ("southwest"), two ("south west": 225) or three
-- ("west-south-west", "north northeast": the point halfway between the cardinal `a` and
-- the intercardinal after it, 247.5 and 22.5); degrees, or nil when the words name none.
local function compass(a, b, c)
  local x, y = L.compass[a], L.compass[b or ""]
  if not x then return nil end
  local inter = BASE[a] and y and (BASE[b] and c and BASE[c] and compass(b, c) or (not BASE[b] and y))
  if inter and inter % 90 ~= 0 and math.abs(inter - (x == 0 and inter > 180 and 360 or x)) == 45 then
    return (inter + (x == 0 and inter > 180 and 360 or x)) / 2
  end
  if not BASE[a] then return x end  -- "southwest"
  if y and not BASE[b] then y = nil end
  if not y then return x == 0 and 360 or x end
  if x == 0 and y == 270 then return 315 end
  if x == 0 then return y / 2 end
  if x == 180 then return (x + y) / 2 end
  return nil
end

-- ---- values ----

-- "zero niner zero": three spoken digits, the first a zero, up to 360.
function H.zero_led_heading(q)
  local n = q.number
  return not n.typed and n.groups == 3 and #n.digits == 3 and n.digits:sub(1, 1) == "0" and q.value <= 360
end
-- A value said digit by digit that lost digits beyond repair: one digit, or
-- two ending in zero ("one zero knots": 100 or 210?). Two others ("two
-- five") lost their final zero and read times ten; "zero nine" is 090.
function H.cut_off(n)
  if n.hundred or n.thousand or n.decimal then return false end
  local d = n.digits
  return #d == 1 or (#d == 2 and d:sub(1, 1) ~= "0" and d:sub(2, 2) == "0")
end
-- True when the value ending at token e is broken off: an ellipsis ("...", "…") or a hesitation straight after it,
-- then only marks, hesitations and fillers to the end of the request.
function m:broken_off(e)
  local t = self.t[e]
  local dots = t and t.kind == "punct" and (t.text == "..." or t.text == "…"
    or (t.text == "." and self.t[e + 1] and self.t[e + 1].text == "."))
  if not (dots or self:word(e, "@hesitations")) then
    return false
  end
  for k = e, #self.t do
    if not (self.t[k].kind == "punct" or self.t[k].filler or self:word(k, "@hesitations")) then return false end
  end
  return true
end
function m:values_after_trigger(s)
  local n = 0
  for _, q in ipairs(self:quantities(s.b, s.e)) do if q.b >= s.trig then n = n + 1 end end
  return n
end

-- +1 for up/more words, -1 for down/less words, 0 when none; those after a correction, then those in the
-- instruction's own clause (from the last punctuation before its trigger)
-- first: "the Shuttle is a bit slow, could you speed it up by 40 knots" is up.
-- (a word inside a callsign is no direction: "Ryanair 3UP descend FL90" descends; nor is the object of a
-- verb of lexicon.halted, "stop its climb and descend with 500 feet per minute" descends)
-- True when the word at i is one of `list` said as a way to move: not inside one of `names` (aircraft references)
-- and not the object of a verb of lexicon.halted.
function m:motion_said(i, list, names)
  if not self:word(i, list) then return false end
  for _, r in ipairs(names) do
    if i >= r.b and i < r.e then return false end
  end
  local v = self:word(i - 1, "its the his her their your") and i - 2 or i - 1
  return not self:word(v, "@halted")
end

-- lexicon.self_correction.markers of one word, as a set (m:marker_after_value)
local MARKER_WORDS = {}
for _, w in ipairs(L.self_correction.markers) do if not w:find(" ") then MARKER_WORDS[w] = true end end

-- True when token i (in a segment opening at b) takes back the vertical motion said before it: a correction, a
-- marker after a value (m:marker_after_value) or straight after the verb ("climb sorry descend four thousand",
-- "descend no climb FL120"), or a verb broken off (m:motion_broken_off).
function m:motion_taken_back(i, b)
  return self:word(i, "@correction") or self:marker_after_value(i) or self:motion_broken_off(i, b)
    or (MARKER_WORDS[self.words[i] or ""] ~= nil and self:word(i - 1, "@up @down"))
end

function m:direction(s)
  local names = self:refs_in(s.b, s.e, "aircraft")
  local function said(i, list) return self:motion_said(i, list, names) end
  -- a direction said after a correction replaces the one before it ("climb FL260, correction, descend FL220")
  for i = (self:said("@correction") or self:said(MARKER_WORDS) or self:said("@up") and self:said("@down")) and s.e - 1
      or 0, s.b, -1 do
    if self:motion_taken_back(i, s.b) then
      for k = i + 1, s.e - 1 do
        if said(k, "@up") then return 1 end
        if said(k, "@down") then return -1 end
      end
    end
  end
  local clause = s.trig or s.b
  while clause > s.b and self.t[clause - 1].kind ~= "punct" do clause = clause - 1 end
  for _, b in ipairs({ clause, s.b }) do
    for i = b, s.e - 1 do
      -- (m:motion_said reads a word of its list only: one look at both lists first)
      if self:word(i, "@up @down") then
        if said(i, "@up") then return 1 end
        if said(i, "@down") then return -1 end
      end
    end
  end
  return 0
end

-- True when token i (in a segment opening at b) breaks off the vertical verb said before it, as a correction would:
-- "..." straight after a verb of climb or descent (fillers between: "descend... erm... climb! climb FL100"), or the
-- "?" closing a sentence with no value in it ("no, descend? it's at one hundred... climb, yes, climb 110", "climb...
-- erm, is he climbing or descending, instructor? uh, descend FL110"): the verb said after it counts.
function m:motion_broken_off(i, b)
  local t = self.t[i]
  if not (t and t.kind == "punct") then return false end
  local k = i - 1
  if t.text == "?" then
    while k >= b and not (self.t[k].kind == "punct" and self.t[k].text:match("^[.?!;]$")) do k = k - 1 end
    return #self:quantities(k + 1, i) == 0
  end
  while k >= b and self.t[k].filler do k = k - 1 end
  return t.text == "." and self.t[i + 1] ~= nil and self.t[i + 1].text == "." and k >= b and self:word(k, "@up @down")
end

-- A climb's and a descent's words (lexicon.vertical_motion) both said in [b, e) with no correction between ("climb
-- KLM12 descend at 2000 fpm", "climb rate of descent 1500"): the positions of the first of each, in the order said;
-- else nil. "up" and "down" count as a rate's sign straight beside its value ("climb vs 2000 down", "up 2000 fpm")
-- or as the instruction's word ("go up, descend at 2000 fpm"); a verb after a level ("climb FL300 descend") is a word left over,
-- asked by the accounting. Words noted as not simulated ("expect descent"), in a reason or of a motion stopped
-- ("stop descent, climb FL250") move nothing.
-- True when the word at i is a self-correction marker (lexicon.self_correction.markers, one word) closing a run of
-- such markers and fillers said straight after a value, with no punctuation ("climb flight level three niner zero
-- uh wait no descend ...", a recogniser's transcript): the value before it is taken back as after "correction".
function m:marker_after_value(i)
  if not MARKER_WORDS[self.words[i] or ""] or self:word(i + 1, MARKER_WORDS) then return false end
  local k = i - 1
  while k > 0 and self.t[k].kind == "word" and (self.t[k].filler or MARKER_WORDS[self.words[k]]) do k = k - 1 end
  for _, q in ipairs(self:quantities(math.max(1, k - 6), k + 1)) do
    if q.e == k + 1 then return true end
  end
  return false
end
function m:opposite_motions(b, e)
  -- (no climb's word or no descent's word said in the request: none to oppose)
  if not ((self:said(self.motion.up) or self:said("up")) and (self:said(self.motion.down) or self:said("down"))) then
    return nil
  end
  local names, up, down = self:refs_in(b, e, "aircraft"), nil, nil
  local qs = self:quantities(b, e)
  local last, signs = qs[#qs], {}  -- (signs[i]: "up" or "down" there is a rate's sign, straight beside its value)
  for _, q in ipairs(qs) do
    if q.kind ~= "alt" then signs[q.b - 1], signs[q.e] = true, true end
  end
  for i = b, e - 1 do
    if self:motion_taken_back(i, b) then
      up, down = nil, nil
    end
    local sign = signs[i] or self.triggers[i]
    if not (last and i >= last.e and last.kind == "alt") then
      local u = self:motion_said(i, self.motion.up, names) or (sign and self:word(i, "up"))
      local d = self:motion_said(i, self.motion.down, names) or (sign and self:word(i, "down"))
      if (u or d) and not (self.u:used(i) or self.noted[i] or self:in_reason(i)) then
        if u then up = up or i else down = down or i end
      end
    end
  end
  if up and down then return math.min(up, down), math.max(up, down) end
  return nil
end

-- 1 on, 0 off, -1 not said. A word of a report set aside as not simulated ("I think someone switched that off
-- by accident": what was done, self.noted) switches nothing. A word in a remark set aside (G:in_reason: "switch on
-- LNAV, I think it is off", the state the speaker tells) counts only when no word outside one switches; then the
-- second result is true (told, not asked for: m:switch_told).
function m:on_off(s)
  -- (the switching word just before the segment counts: "disconnect LNAV of X")
  local b = (s.b > 1 and self:word(s.b - 1, "off on @off @on")) and s.b - 1 or s.b
  -- ("..., and switch off the LNAV": the switching word before an article that opens the segment counts too)
  if b == s.b and s.trig == s.b and s.b > 2 and self:word(s.b - 1, "the its your his her their")
      and self:word(s.b - 2, "off on") then
    b = s.b - 2
  end
  -- "drifting off its route, put it back on LNAV": switched back on, whatever went off before
  local back = self:find_word(b, s.e, "back")
  if back < s.e and self:word(back + 1, "on") then return 1 end
  -- "no more noise please", "no more trails": the switch's noun after "no more" is switched off
  if s.trig and self:word(s.trig - 1, "more") and self:word(s.trig - 2, "no") and not self:in_reason(s.trig) then return 0 end
  -- ("switch on the detection, but without resolution": "without" or "no" with only articles after it in the
  -- segment, before the next instruction's word, switches that one off; "lnav off hdg 250" is LNAV's)
  local function next_ones(k)
    if not self:word(k, "without no") then return false end
    local x = k + 1
    while x < s.e and self:word(x, "the any a") do x = x + 1 end
    return x == s.e and s.e <= #self.t and self:intent_at(s.e) ~= nil and self:intent_at(s.e) ~= false
  end
  -- ("can you show which resolution method is selected?", "which method is active, can you show?": "show" asking to
  -- be shown a setting, before a question word or "the current" ("me" between or not), or asked with "can you"
  -- before the request's end or a mark, switches nothing)
  local function shown(k)
    if not self:word(k, "show display") then return false end
    local x = k + 1
    if self:word(x, "me us") then x = x + 1 end
    if self:word(x, "the") then x = x + 1 end
    local asked = self:word(k - 1, "you") and self:word(k - 2, "can could would will")
    return (asked and (x > #self.t or self.t[x].kind == "punct")) or self:word(x, "which what whether current currently")
  end
  local function said(from, words, told)
    for k = from, s.e - 1 do
      if self:word(k, words) and not self.noted[k] and (told or not self:in_reason(k)) and not next_ones(k)
          and not (words == "@on" and shown(k)) then
        return true
      end
    end
    return false
  end
  local function read(told)
    if said(b, "@off", told) or said(s.b, "@off_after", told) then return 0 end
    for k = b, s.e - 1 do
      if self:word(k, "@off_made") and not self:in_reason(k) and self:word_in(math.max(b, k - 5), k, "make let have") then
        return 0
      end
    end
    if said(b, "@on", told) then return 1 end
    return -1
  end
  local on = read(false)
  if on >= 0 then return on end
  on = read(true)
  if on >= 0 then return on, true end
  return self:opened_setting(s), false
end

-- "conflict detection open please", "close the conflict resolution": a conflict setting opened (1) or closed (0),
-- as Turkish and Arabic speakers say for on and off ("aç", "kapat"; "iftah", "sakkir"), the verb straight after the
-- setting's noun (fillers between) or before it with only articles and "conflict" between, an aircraft's VNAV and
-- LNAV too ("CCA1539 open the VNAV", Chinese "da kai"); the trails likewise,
-- by the verb before them only ("close the trails", "open all the trails"); -1 when neither is said so
function m:opened_setting(s)
  local trig = s.trig
  if trig and self:word(trig, "trail trails") then
    local k = trig - 1
    while k >= 1 and self:word(k, "the all") do k = k - 1 end
    if self:word(k, "open") then return 1 end
    return self:word(k, "close shut") and 0 or -1
  end
  if not (trig and self:word(trig, "detection resolution asas cd cr vnav lnav")) then return -1 end
  local function reading(k)
    if self:word(k, "open opened") then return 1 end
    if self:word(k, "close closed shut") then return 0 end
    return -1
  end
  local a = self:skip_fillers(trig + 1)
  if self:word(a, "is are") then a = self:skip_fillers(a + 1) end
  local after = reading(a)
  if after >= 0 then return after end
  local k = trig - 1
  while k >= s.b and self:word(k, "the conflict conflicts its his") do k = k - 1 end
  return k >= 1 and reading(k) or -1
end

-- True when segment s switches only by a word in a remark set aside ("LNAV, I think it is off"): the state the
-- speaker tells, not what to set (asked where a switch would follow it).
function m:switch_told(s)
  local _, told = self:on_off(s)
  return told == true
end

-- "VTI305 and AIC865, you are in conflict, VTI305 turn right heading 240": aircraft said together, words of a clause
-- of their own, then one of them said again straight before the instruction's word, in [b, trig): the instruction is
-- that one's alone (the pair was addressed for the traffic; the words from b to it are explained), returned as a
-- reference. Said again by its airline's word alone ("..., Vistara turn right"), the one of the pair of that
-- airline when one is; which one is asked when both are. Else nil.
function m:readdressed(b, trig)
  local refs = {}
  for _, r in ipairs(self:refs_in(b, trig, "aircraft")) do
    if r.exists and not r.false_start then refs[#refs + 1] = r end
  end
  if #refs < 2 then return nil end
  local k = trig - 1
  while k > b and (self.t[k].kind == "punct" or self.t[k].filler) do k = k - 1 end
  -- (the order said after the one said again: "..., Asiana first heading 180, then ..."; "go" before the value
  -- itself: "..., better Air China 124 go flight level 330")
  if self:word(k, "first go") and k > b then
    k = k - 1
    while k > b and (self.t[k].kind == "punct" or self.t[k].filler) do k = k - 1 end
  end
  -- (a modal between the one said again and the verb: "..., the EgyptAir should climb ...")
  if self:word(k, "should shall must") and k > b then
    k = k - 1
    while k > b and (self.t[k].kind == "punct" or self.t[k].filler) do k = k - 1 end
  end
  -- (a verb ending a movement before the instruction word, the infinitive's "to" before it or not: "..., Aeroflot
  -- stop descent at level 110", "..., Aeroflot to stop climb at FL200")
  if self:word(k, "@halted") and k > b + 1 then
    k = self:word(k - 1, "to") and k - 2 or k - 1
    while k > b and (self.t[k].kind == "punct" or self.t[k].filler) do k = k - 1 end
  end
  local last = refs[#refs]
  -- ("CPA451 and EVA12, EVA12 heading 180, CPA451 speed 240": the last of the pair said again straight after it,
  -- one reference said twice across the comma, is one of the pair said again)
  local twice = false
  for x = last.b + 1, last.e - 1 do
    if self.t[x].kind == "punct" then twice = true end
  end
  twice = twice and last.e == k + 1
  local pair = (last.e == k + 1 and not twice) and #refs - 1 or #refs
  if pair < 2 then return nil end
  local from = refs[pair].e
  local upto = last.e == k + 1 and last.b or k
  local clause = false
  for x = from, twice and 0 or upto - 1 do
    local t = self.t[x]
    if t.kind == "word" and not t.filler and not self:word(x, "and") then clause = true end
  end
  if last.e == k + 1 then
    -- ("Asiana 213 and Jeju Air 1801, Asiana first heading 180, then Jeju Air speed 240", "KLM12 and DLH34, DLH34
    -- heading 180": with no clause too, the one said again is addressed alone, never the pair: the others of the
    -- pair get their own instruction after it or none)
    for i = 1, pair do
      if refs[i].name == last.name then
        self:explain(b, last.b)
        return last
      end
    end
    return nil
  end
  local of, heard, heard_at = {}, nil, nil
  for x = math.max(from, k - 2), k do
    local icao, e, codes = self:airline_at(x)
    if icao and e == k + 1 and not heard then
      heard_at = x
      local said = {}
      for y = x, k do said[#said + 1] = self.t[y].raw end
      heard = table.concat(said, " ")
      of[icao] = true
      for _, c in ipairs(type(codes) == "table" and codes or {}) do of[c] = true end
    end
  end
  local named, fits = {}, nil
  for i = 1, pair do
    if of[refs[i].name:upper():match("^(%u+)%d") or ""] then named[#named + 1], fits = refs[i].name:upper(), refs[i] end
  end
  -- ("Aegean 992 and KLM1234 are in conflict. Aegean turn right", "Turkish 6KC and Sunturk 5MR: Turkish left 30":
  -- the airline's word alone names the one aircraft of the pair it fits, just named in full)
  if #named == 1 then
    self:explain(b, heard_at)
    self:explain(heard_at, k + 1)
    return fits
  end
  if #named >= 1 then
    local all = {}
    for i = 1, pair do all[#all + 1] = refs[i].name:upper() end
    self:need(string.format("Which aircraft should get the instruction: %s? I heard '%s' after %s were named "
      .. "together. Please give its callsign.", table.concat(named, " or "), heard, table.concat(all, " and ")))
  end
  return nil
end

-- True when an aircraft other than reference r's is named from b up to r, or is the subject of the instruction
-- before ("KLM12 FL300 before BAW5 arrives"; never "when DAL877 is 20 miles from CANUK start him down").
function m:other_aircraft_before(b, r)
  if self.subject and self.subject:upper() ~= r.name:upper() then return true end
  for _, o in ipairs(self:refs_in(b, r.b, "aircraft")) do
    if o.exists and not o.false_start and o.name:upper() ~= r.name:upper() then return true end
  end
  return false
end

-- Aircraft a segment talks about: those after its trigger, else before it,
-- else the utterance's subject (all the aircraft named together for the
-- instruction before), else one named later, else the only aircraft.
function m:acids(s)
  local ids, seen = {}, {}
  local any_known = false
  for _, r in ipairs(self.refs) do if r.kind == "aircraft" and r.exists then any_known = true end end
  local function take(b, e)
    for _, r in ipairs(self:refs_in(b, e, "aircraft")) do
      -- (one named as context, "to avoid a conflict with KLM77", is not instructed)
      if (r.exists or not any_known) and not seen[r.name] and not r.false_start
          and not self:as_context(r.b) and (r.said_instead or not self:in_reason(r.b)) and not self:compared_with(r.b) then
        -- ("climb KLM12 to FL260 as EZY45 passes", ", as for EZY45", "while EZY45 holds", "with EZY45": a
        -- second aircraft after "as", "as for", "while" or "with" that is no comparison may be a time, a reason,
        -- a topic or company as well as an aircraft added; after "as" or "while" and the instruction word also
        -- when the instruction before named its own aircraft: asked)
        local k = self:word(r.b - 1, "the") and r.b - 2 or r.b - 1
        if (#ids > 0 and (self:word(k, "as while whilst with") or self:word(k, "for") and self:word(k - 1, "as")))
            or (self.subject and r.b > s.trig and self:word(k, "as while whilst"))
            -- ("KLM12 FL300 before BAW5 arrives", "... until BAW5 passes": after a word opening a clause of time,
            -- reason or condition, with the instruction's aircraft named before it)
            or ((#ids > 0 or self:other_aircraft_before(s.b, r)) and r.b > s.trig
              and (self:word(k, "before after until till once when whenever unless because since")
                or self:word(k, "case") and self:word(k - 1, "in"))) then
          self:need(string.format("Is %s to get this instruction too, or is it named for another reason? "
            .. "Please give each aircraft its own instruction.", r.name:upper()))
        end
        seen[r.name] = true
        ids[#ids + 1] = r.name
      end
    end
  end
  -- a callsign after the instruction's value with a value of its own is
  -- not the subject ("turn right heading 160 DLH4AX 2"); one after a comma,
  -- or ending the request, is the addressee ("heading two seven zero, Air
  -- France one two three four", "hdg 120 for test01"), also after all the
  -- values ("add CNF1 at FL340 270 kt to AFR6204")
  local upto = s.e
  local qs = self:quantities(s.trig, s.e)
  for k, q in ipairs(qs) do
    if q.b > s.trig then
      -- (a latitude and the longitude after it are one value: "add 53 North 50 West to EIN105's route")
      if q.kind == "lat" and qs[k + 1] and qs[k + 1].kind == "lon" then k, q = k + 1, qs[k + 1] end
      local comma = false
      for i = q.e, s.e - 1 do
        if self.t[i].kind == "punct" then comma = true end
      end
      if not comma and qs[k + 1] and self:has_ref(q.e, qs[#qs].b, "aircraft") then upto = q.e end
      break
    end
  end
  -- with the addressee named before the instruction ("DLH4AX descend FL240 to put it at the same level
  -- as KLM1234", "UAL9 heading 150 - should converge with KLM1877"), a callsign said after the
  -- instruction's last value with words of a clause between is context, never instructed
  local last_q = qs[#qs]
  local addressed = false
  if last_q and last_q.b > s.trig and upto > last_q.e and self:has_ref(last_q.e, upto, "aircraft") then
    for _, r in ipairs(self:refs_in(s.b, s.trig, "aircraft")) do
      if r.exists and not self:as_context(r.b) then addressed = true end
    end
  end
  if addressed then
    for _, r in ipairs(self:refs_in(last_q.e, upto, "aircraft")) do
      -- (aircraft said in place of the one named, "..., sorry, I meant KLM21", close the request:
      -- m:aircraft_said_instead)
      if r.said_instead then break end
      local clause = false
      for i = last_q.e, r.b - 1 do
        local t = self.t[i]
        if t.kind == "word" and not t.filler and not self:word(i, "and") then clause = true end
        if self:word(i, "@correction") then clause = false break end  -- ("..., correction KLM21")
      end
      if clause then upto = last_q.e break end
    end
  end
  -- ("Air China 124 and China Eastern 5042 converging, I think better Air China 124 go flight level 330": a value
  -- with no instruction word, one of the pair said again before it, m:readdressed)
  local q1 = s.intent == "infer" and qs[1]
  local again = q1 and #self:refs_in(s.trig, q1.b, "aircraft") > 2 and self:readdressed(s.b, q1.b)
  if again then
    ids[1], seen[again.name] = again.name, true
  else
    take(s.trig, upto)
  end
  -- "AFR1234 and KLM605 are head on, climb the Air France to FL340": with the instruction's aircraft named after
  -- its word, a clause opening the segment that describes aircraft with "is" or "are", holds no value and ends
  -- at a comma is talked about, not instructed (explained)
  if #ids > 0 then
    local comma = s.trig - 1
    while comma > s.b and self.t[comma].kind ~= "punct" do comma = comma - 1 end
    if comma > s.b and self.t[comma].text == "," and self:has_ref(s.b, comma, "aircraft")
        and self:word_in(s.b, comma, "is are") and #self:quantities(s.b, comma) == 0 then
      self:explain(s.b, comma)
    end
  end
  -- "EZY45 reduce to 240, the KLM will come right over it", "..., keep KLM12 as is", "and direct HZA, KLM12 no
  -- change": an aircraft in a clause after a comma that words of its own follow is talked about, not addressed,
  -- when the instruction's own aircraft was named before it (in the segment, for the instruction before, or after the
  -- instruction word before the comma)
  if #ids > 0 and (self:has_ref(s.b, s.trig, "aircraft") or self.subject or #ids > 1) then
    for _, r in ipairs(self:refs_in(s.trig, upto, "aircraft")) do
      local k = r.b - 1
      while k > s.trig and self.t[k].kind == "word" and not self:intent_at(k) and #self:quantities(k, k + 1) == 0 do
        k = k - 1
      end
      local nx = self.t[r.e]
      -- (", as for KLM12, no change": a topic; never one added: "..., KLM12 too", "..., KLM12 as well")
      -- (its clause, to the next punctuation, holds no value and no instruction word: "N52RG at 90 knots" is
      -- an instruction of its own)
      local own = (nx and nx.kind == "word" and not nx.filler) or (self:word(r.b - 1, "for") and self:word(r.b - 2, "as"))
      local e = r.e
      while own and self.t[e] and self.t[e].kind ~= "punct" do
        if self:intent_at(e) or #self:quantities(e, e + 1) > 0 then own = false end
        e = e + 1
      end
      -- (an aircraft noun after an aircraft described belongs to it: "and the Frontier aircraft as well")
      local tail = self:word(r.e, "@aircraft_nouns") and r.e + 1 or r.e
      if seen[r.name] and not r.false_start and self.t[k] and self.t[k].kind == "punct" and own
          and not self:word(tail, "too also")
          and not (self:word(tail, "as") and self:word(tail + 1, "well")) then
        local kept = {}
        for _, id in ipairs(ids) do
          if id ~= r.name then kept[#kept + 1] = id end
        end
        ids, seen = kept, { [r.name] = true }
        for _, id in ipairs(ids) do seen[id] = true end
        if #ids == 0 then take(s.b, s.trig) end
        break
      end
    end
  end
  -- "Argentina 1320 and Flybondi are converging, so Flybondi 5120 turn right": with an aircraft named after
  -- the last "so" or sentence end before the instruction word, those named before it are talked about, not
  -- instructed
  if #ids == 0 then
    local from = s.b
    for k = s.trig - 1, s.b, -1 do
      local t = self.t[k]
      if self.words[k] == "so" or (t.kind == "punct" and (t.text == "." or t.text == ":" or t.text == ";" or t.text == "!")) then
        if self:has_ref(k + 1, s.trig, "aircraft") then from = k + 1 end
        break
      end
    end
    -- (said with "is" or "are" the clause describes them: explained)
    if from > s.b and self:word_in(s.b, from, "is are was were") then self:explain(s.b, from) end
    -- ("..., All Nippon 865 flight level 370 climb please": the value said before its verb, Korean order, is where
    -- the one said again stands before)
    local at = s.trig
    local vq = self:quantities(from, s.trig)
    vq = vq[#vq]
    if vq and self:skip_fillers(vq.e) == s.trig then at = vq.b end
    local again = self:readdressed(from, at)
    if again then
      ids[1], seen[again.name] = again.name, true
    else
      take(from, s.trig)
    end
  end
  -- ("KLM12 is near EZY45, turn him left heading 130": one aircraft said by "him" or "her" beside the instruction
  -- word, or "it" straight after it, with more than one named for it: which one is not known, asked)
  -- ("KAL1114 and AAR8811 converging, the higher one climb FL300", "..., the slower of the two reduce 220", "faster
  -- aircraft speed 250"): one of those named picked by a comparison before the instruction word: which one is
  -- asked, never each of them instructed
  if #ids > 1 then
    for k = s.b, s.trig - 1 do
      local cmp = "higher lower faster slower closer nearer further farther highest lowest fastest slowest"
      if self:word(k, cmp) and (self:word(k - 1, "the") or self:word(k + 1, "one aircraft plane traffic")
          or (self:word(k + 1, "of") and self:word(k + 2, "the them"))) then
        self:need(string.format("Which aircraft is 'the %s one': %s? Please give its callsign.", self.t[k].raw,
          table.concat(ids, " or ")))
        break
      end
    end
  end
  if #ids > 1 then
    local e = math.min(s.e, s.trig + 3)
    local p = self:find_word(math.max(s.b, s.trig - 2), e, "him her")
    if p == e and self:word(s.trig + 1, "it") then p = s.trig + 1 end
    if p < e then
      self:need(string.format("Which aircraft is '%s': %s? Please give its callsign.", self.t[p].raw,
        table.concat(ids, " or ")))
    end
  end
  self:trailing_aircraft(s, ids)
  self:confirm_callsigns(s)
  -- "BAW918 FL300 and DLH9LT FL310, both 280 kt": "both" names the two aircraft instructed before
  -- ("both Lufthansa planes", "both the easyJets": the two aircraft of the airline named after it, when
  -- exactly two of it fly)
  local both = self:find_word(s.b, s.e, "both")
  -- ("put the two Azul at FL120", "the two LATAM, set speed 250": "the two" before an airline or a type names its
  -- aircraft as "both" does; "of the two KLM, the higher one", "one of them" pick one: the reading of "both" left)
  local two = both == s.e and self:find_word(s.b, s.e, "two")
  if two and two < s.e and self:word(two - 1, "the") and not self:word(two - 2, "of") and not self:said("one") then
    both = two
  end
  local icao, ae, codes
  if both < s.e then icao, ae, codes = self:airline_at(self:word(both + 1, "the") and both + 2 or both + 1) end
  -- ("both the Finnair and the airBaltic": two aircraft named, no two of one airline)
  if icao and self:word(ae, "and") then icao = nil end
  local pair = icao and self:airline_fleet(icao, codes) or {}
  -- ("both Boeings", "both the A320s": the two aircraft flying of the maker or type said in the plural, when the
  -- instruction names no aircraft else; "..., so that both Boeings fly the same speed" names none)
  local typed
  if both < s.e and not icao and #ids == 0 then
    typed, ae = self:type_plural(self:word(both + 1, "the") and both + 2 or both + 1)
    pair = typed or pair
  end
  if (icao or typed) and #pair ~= 2 then
    self:need(string.format("Which two aircraft does '%s' mean? Please give their callsigns.",
      self:raw(self:word(both, "both") and both or both - 1, ae)))
  elseif #pair == 2 then
    self:explain(both, ae)
    if two == both then self:mark_used(two, two + 1) end  -- (the count is no value)
    ids = pair
  elseif both < s.e and self:word(both - 1, "lnav vnav") and self:word(both - 2, "and")
      and self:word(both - 3, "lnav vnav") then
    -- ("KLM12, LNAV and VNAV both switch on": "both" the two modes just named, no aircraft)
    self:explain(both, both + 1)
  elseif #ids == 0 and self:word_in(s.b, s.e, "both") then
    local named = {}
    for _, r in ipairs(self:refs_in(1, s.b, "aircraft")) do
      if r.exists and not seen[r.name] and not r.false_start and not self:as_context(r.b) and not self:in_reason(r.b) then
        seen[r.name] = true
        named[#named + 1] = r.name
      end
    end
    -- ("turn both 20 right" with none named before: the two aircraft flying, when only two fly)
    if #named == 0 and #self.fleet == 2 then named = { self.fleet[1].id, self.fleet[2].id } end
    if #named ~= 2 then
      self:need("Which two aircraft does 'both' mean? Please give their callsigns.")
    end
    for k, id in ipairs(named) do ids[k] = id end
  end
  -- "EZY45 heading 180, Luxair heading 270": an airline said alone (capitalised, no flight number) in
  -- the instruction's own words names no aircraft; it is asked about, never read as the aircraft named
  -- before or after (alone in the request, the question below asks for the callsign); in lower case
  -- ("westjet go up to 13000 and the transat ..."), when the instruction's words name no aircraft, so too
  do
    local u = self:airline_said_alone(s) or (#ids == 0 and self:airline_said_alone(s, true))
    for _, id in ipairs(u and ids or {}) do  -- "BAW177 ..., Speedbird diverting": its own name again
      if id:upper():sub(1, #u.icao) == u.icao then u = nil break end
    end
    -- ("Jazz, uh, JIA5301 descend ...": the airline said, then straight after it, commas and hesitations between,
    -- a flying aircraft's exact callsign of that airline, or of another when none of the airline said flies: the
    -- callsign said whole names the aircraft, the airline's name its false start)
    for _, r in ipairs(u and self.refs or {}) do
      if r.kind == "aircraft" and r.exists and r.b >= u.e and (r.name:upper():sub(1, #u.icao) == u.icao
          or #self:airline_fleet(u.icao) == 0) then
        local k = u.e
        while k < r.b and (self.t[k].kind == "punct" or self:word(k, "@hesitations")) do k = k + 1 end
        if k == r.b and k > u.e then
          self:explain(u.b, u.e)
          u = nil
        end
        break
      end
    end
    -- ("Aegean 992 and KLM1234 are in conflict. Aegean turn right 30, KLM descend FL210": in a request that named two
    -- or more aircraft in full before it, the airline's word alone names the one of them of that airline, when only
    -- one is and it was named together with another; the instruction is that aircraft's alone)
    if u and #ids == 0 then
      local before, fits, n = {}, nil, 0
      local refs = self:refs_in(1, u.b, "aircraft")
      for _, r in ipairs(refs) do
        if r.exists and not r.false_start and not before[r.name] then
          before[r.name], n = true, n + 1
          if r.name:upper():sub(1, #u.icao) == u.icao and r.name:upper():sub(#u.icao + 1):match("^%d") then
            fits = fits == nil and r or false
          end
        end
      end
      -- (named together: another aircraft straight before or after it, "and", "ve", "&" or a comma between; one
      -- named as its own instruction's addressee, "RYR77 speed 240, Ryanair descend", is not)
      local together = false
      for _, q in ipairs(fits and refs or {}) do
        if q ~= fits and q.exists then
          local gap_b, gap_e = q.e, fits.b
          if q.b > fits.b then gap_b, gap_e = fits.e, q.b end
          together = together or gap_e == gap_b + 1 and (self:word(gap_b, "and ve") or self.t[gap_b].text == ","
            or self.t[gap_b].text == "&")
        end
      end
      if n >= 2 and fits and together then
        self:explain(u.b, u.e)
        ids[1] = fits.name
        return ids
      end
    end
    local later = false  -- an aircraft named after the instruction ("turn left 090, EZY45")
    for _, r in ipairs(self.refs) do later = later or (r.kind == "aircraft" and r.b >= s.e and not self:in_reason(r.b)) end
    if u and (#ids > 0 or self.subject or later) then
      self:airline_only(u)  -- "Which KLM: KLM1234 or KLM77?" where more than one flies
      self:need(string.format("Which %s aircraft do you mean? Please give its callsign.", self:raw(u.b, u.e)))
      return ids
    end
  end
  -- ("LOG67 and all three jets FL200", "KLM12 and everyone else FL200", "BAW5 and the others ...", "delete NAX7PK
  -- and the intruder", "... and the other one"): a group word, or a description of another aircraft, said
  -- after "and" straight after an aircraft named, which the group reading below takes only with none named: asked,
  -- never sent to the one named alone
  for k = #ids > 0 and s.b or s.e, s.e - 2 do
    local g = self:word(k, "and") and (self:word(k + 1, "the") and k + 2 or k + 1)
    if g and self:word(g, "all everyone everybody others other intruder intruders rest each every "
        .. "@counted_aircraft @maker_plurals")
        and not self:has_ref(g, g + 1, "aircraft") then
      for _, r in ipairs(self:refs_in(s.b, k, "aircraft")) do
        if r.e == k then
          self:need(string.format("Which aircraft does '%s' mean besides %s? Please give their callsigns.",
            self:raw(k + 1, g + 1), r.name:upper()))
          return ids
        end
      end
    end
  end
  -- "KLM12 heading 270. all aircraft climb FL300", "both climb FL300, EZY45 ...": a group said before the
  -- instruction word in its own clause, that no aircraft named in it resolves, is never one aircraft named
  -- before or after it: asked, unless the aircraft instructed together before are that group (two for
  -- "both", every aircraft flying for "all"); "all" with no aircraft instructed before is every aircraft flying,
  -- confirmed by their callsigns
  local before = self.subjects and self.subject == (self.subjects or {})[1] and #self.subjects or 0
  if #ids == 0 and self:said("both everyone everybody all each every") then  -- (none of them said: no group)
    for k = s.trig - 1, 1, -1 do
      local t = self.t[k]
      if t.kind == "punct" or self:intent_at(k) then break end
      -- ("KLM12 heading 270, all climb FL300": "all" or "each" alone straight before the instruction's word is the
      -- group too)
      local both, all = self:word(k, "both"), self:word(k, "everyone everybody")
        or (self:word(k, "all each every") and self:word(k + 1, "aircraft acft traffic planes flights of the"))
        or (self:word(k, "all each") and k == s.trig - 1)
      -- ("Siberia 2060 descend FL120, Siberia 2061 descend FL130, both reduce 250": "both" the two aircraft this
      -- request named before it, each told apart; another count of them named is asked)
      local named = {}
      if both and before ~= 2 then
        local seen = {}
        for _, r in ipairs(self:refs_in(1, k, "aircraft")) do
          if not r.exists or r.false_start or self:as_context(r.b) or self:in_reason(r.b) then
            named = {}
            break
          end
          if not seen[r.name] then seen[r.name], named[#named + 1] = true, r.name end
        end
      end
      if #named == 2 then
        self:explain(k, k + 1)
        for n, id in ipairs(named) do ids[n] = id end
        return ids
      end
      local e = self:word(k, "all each every") and self:word(k + 1, "aircraft acft traffic planes flights of the")
        and k + 2 or k + 1
      -- ("all aircraft reduce 250", "everyone climb FL300": every aircraft flying, two or more, once the
      -- speaker confirms them by their callsigns, a global request)
      if all and not both and before == 0 and #self.fleet >= 2 and not self:word(k + 1, "of the") then
        local list = {}
        for n, a in ipairs(self.fleet) do ids[n], list[n] = a.id, a.id end
        self:explain(k, e)
        self:confirm_before(string.format("'%s' is every aircraft flying: %s. Send this to all %d? (yes or no)",
          self:raw(k, e), table.concat(list, ", "), #list))
        return ids
      end
      if (both and before ~= 2) or (all and not (before >= 2 and before == #self.fleet)) then
        self:need(string.format("Which aircraft does '%s' mean? Please give their callsigns.", self:raw(k, e)))
        return ids
      end
    end
  end
  -- "slow all three aircraft by 20 knots", "turn all four left 20 degrees": "all" and a count said in the segment,
  -- no aircraft named, are every aircraft flying when that many fly (each from its own state); another count asked
  for k = #ids == 0 and s.b or s.e, s.e - 2 do
    local q = self:word(k, "all") and self:quantities(k + 1, k + 2)[1]
    if q and q.kind == "plain" and q.b == k + 1 and q.e == k + 2 and q.value >= 2 and q.value % 1 == 0 then
      local e = self:word(q.e, "@aircraft_nouns @counted_aircraft") and q.e + 1 or q.e
      if q.value ~= #self.fleet then
        self:need(string.format("Which aircraft does '%s' mean? %d are flying. Please give their callsigns.",
          self:raw(k, e), #self.fleet))
        return ids
      end
      self:mark_used(k, e)
      self:explain(k, e)
      for n, a in ipairs(self.fleet) do ids[n] = a.id end
      break
    end
  end
  if #ids == 0 and self.subject then
    -- the aircraft named for the instruction before ("EZY45 and AFR1234 maintain present heading")
    local all = self.subjects and self.subjects[1] == self.subject and self.subjects or { self.subject }
    for k, id in ipairs(all) do ids[k] = id end
    -- ("KLM1009, DLH4AX, BAW123 - everyone 250 knots, and Speedbird also descend FL110": an airline said alone in
    -- the segment picks those of it among them; none or several of it asked)
    for k = #ids > 1 and s.b or s.e, s.e - 1 do
      local icao, e = self:airline_at(k)
      if icao and not self:has_ref(k, e, "aircraft") then
        local of = {}
        for _, id in ipairs(ids) do
          if id:upper():sub(1, #icao) == icao then of[#of + 1] = id end
        end
        if #of ~= 1 then
          self:need(string.format("Which aircraft is '%s': %s? Please give its callsign.", self:raw(k, e),
            table.concat(#of > 1 and of or ids, " or ")))
        else
          self:explain(k, e)
        end
        ids = of
        break
      end
    end
  end
  if #ids == 0 then
    for _, r in ipairs(self.refs) do
      -- (not one named in a reason: "... so he crosses the Lufthansa")
      if r.kind == "aircraft" and r.b >= s.e and not self:in_reason(r.b) then ids[1] = r.name break end
    end
  end
  if #ids == 0 and #self.fleet == 1 then ids[1] = self.fleet[1].id end
  for k, id in ipairs(ids) do
    local q, meant = self:unknown_callsign(id)
    if q then self:need(q) end
    if meant then ids[k] = meant end
  end
  if #ids == 0 then
    self:airline_only(s)
    self:type_only(s)
  end
  -- "delete the easy and the klm": an airline said alone that names no one aircraft is asked
  -- about, never dropped beside the one that does
  for _, u in ipairs(#ids > 0 and self.airline_unresolved or {}) do
    if u.b >= s.b and u.e <= s.e then self:airline_only(u) end
  end
  -- "the Ryanair and the Boeing climb FL260" with two Boeings flying: a type that names no one aircraft, joined by
  -- "and" to one named or said beside one named not of it, likewise ("the American one, the 737" with AAL1960 a
  -- 737 describes that aircraft again)
  for _, u in ipairs(#ids > 0 and self.type_unresolved or {}) do
    local fits_named = false
    for _, id in ipairs(ids) do
      for _, f in ipairs(u.ids) do fits_named = fits_named or f == id end
    end
    local k = self:word(u.b - 1, "the") and u.b - 2 or u.b - 1
    if self:word(k, "to") then k = k - 1 end
    if u.b >= s.b and u.e <= s.e and (self:word(k, "and") or not fits_named) then self:type_only(u) end
  end
  -- "the two jets at FL200, put one of them at FL190", "climb either of them": a selector of
  -- lexicon.partitive_selectors said in the segment picks one of the aircraft named together, never each of them:
  -- asked which
  -- ("KLM1009 and DLH4AX, the first one reduce 240, the second one reduce 260": "the first" or "the second" (and
  -- "one") before the instruction word picks that one of the aircraft named together, in the order said)
  local group = self.ordinal_group or (#ids > 1 and ids)
  for k = group and s.b or s.trig, s.trig - 1 do
    local n = self:word(k, "the") and (self:word(k + 1, "first") and 1 or self:word(k + 1, "second") and 2
      or self:word(k + 1, "third") and 3)
    local e = n and (self:word(k + 2, "one") and k + 3 or k + 2)
    if n and group[n] and (self:intent_at(self:skip_fillers(e)) or self.t[e].kind == "punct") then
      self.ordinal_group = group
      ids = { group[n] }
      self:explain(k, e)
      break
    end
  end
  local picked = #ids > 1 and self:partitive_said(s.b, s.e)
  if picked then
    self:need(string.format("Which aircraft: %s? I heard '%s'.", table.concat(ids, " or "),
      self:raw(picked.b, picked.e)))
  end
  if #ids > 0 then self.subject, self.subjects = ids[1], { table.unpack(ids) } end
  return ids
end

-- The first phrase of lexicon.partitive_selectors, or of lexicon.ordinal_selectors said as a noun of its own (the
-- token after it punctuation, the end, an instruction verb or a word of its `next`), said in [b, e), as { b, e } of
-- its tokens, or nil.
local PARTITIVES = {}
local ORDINAL_NEXT = table.concat(L.ordinal_selectors.next, " ") .. " " .. table.concat(L.clause_verbs, " ")
for _, list in ipairs({ L.partitive_selectors, L.ordinal_selectors.words }) do
  for _, p in ipairs(list) do
    local words = { ordinal = list == L.ordinal_selectors.words }
    for w in p:gmatch("%S+") do words[#words + 1] = w end
    PARTITIVES[#PARTITIVES + 1] = words
  end
end
function m:partitive_said(b, e)
  for k = b, e - 1 do
    for _, words in ipairs(PARTITIVES) do
      local n = #words
      local fits = k + n <= e
      for x = 1, fits and n or 0 do fits = fits and self:word(k + x - 1, words[x]) end
      local nx = self.t[k + n]
      if fits and words.ordinal then
        fits = nx == nil or nx.kind == "punct" or self:word(k + n, ORDINAL_NEXT)
      end
      if fits then return { b = k, e = k + n } end
    end
  end
  return nil
end

-- "klm33 hdg 100 and ryr8", "klm33 fl310, ryr8", "klm33 direct SPY ryr8": an instruction of how to fly (a value's,
-- a direct-to, a navigation switch) for a flying aircraft named before it, in segment s or for the instruction
-- before ("klm33 climb fl300, heading 100, ryr8"), and another that `ids` took after all of it (past its word and
-- its values), its clause holding nothing else but courtesy and no word adding it ("too", "as well", "same for":
-- G:aircraft_added), may be the instruction's second aircraft or one whose own instruction was not said: asked,
-- naming the instruction and both, never given to either alone. Aircraft named together before the instruction
-- ("klm33 and ryr8 fl310") are all instructed.
local FLOWN = { alt = true, maintain = true, spd = true, hdg = true, vs = true, infer = true, direct = true,
  lnav = true, vnav = true }
local CLOSING = {}
for _, list in ipairs({ L.accounted.courtesy, L.accounted.radiotelephony, { "and" } }) do
  for _, w in ipairs(list) do CLOSING[w] = true end
end
function m:trailing_aircraft(s, ids)
  if not FLOWN[s.intent] or #ids == 0 then return end
  local qs = self:quantities(s.trig, s.e)
  local from = s.intent == "infer" and qs[1] and qs[1].b or s.trig  -- the instruction's first word
  local past = qs[#qs] and math.max(qs[#qs].e, from + 1) or from + 1
  local explained, named, before, said, after, at = self.explained or {}, {}, {}, {}, {}, nil
  for _, id in ipairs(ids) do named[id:upper()] = true end
  -- (an aircraft after the instruction is one of those instructed, or there is nothing to ask)
  local trailing = false
  for _, r in ipairs(self:refs_in(past, s.e, "aircraft")) do trailing = trailing or named[r.name:upper()] end
  if not trailing then return end
  -- (nothing else in the clause after aircraft ref r: punctuation, fillers, courtesy, "and", other aircraft)
  local function alone(r)
    for k = r.e, s.e - 1 do
      local t = self.t[k]
      if t.kind == "punct" then return true end
      if not (t.filler or self:word(k, CLOSING) or self:has_ref(k, k + 1, "aircraft")) then return false end
    end
    return true
  end
  for _, r in ipairs(self:refs_in(s.b, s.e, "aircraft")) do
    local name = r.name:upper()
    if r.exists and not r.false_start and not explained[r.b] and not self.noted[r.b] and not self:as_context(r.b)
        and not self:in_reason(r.b) and not self:compared_with(r.b) then
      if r.e <= from and not said[name] then
        before[#before + 1], said[name] = name, true
      elseif r.b >= past and named[name] and not said[name] and not self:aircraft_added(r) and alone(r) then
        after[#after + 1], at = name, at or r.b
      end
    end
  end
  if #before == 0 and self.subject then
    for _, id in ipairs(self.subjects or { self.subject }) do
      if not named[id:upper()] then before[#before + 1] = id:upper() end
    end
  end
  if #before == 0 or #after == 0 then return end
  local e = at
  while e - 1 > from and (self.t[e - 1].kind == "punct" or self.t[e - 1].filler or self:word(e - 1, "and @then_words")) do
    e = e - 1
  end
  self:need(string.format("Which aircraft is '%s' for: %s, %s or both? Please say each aircraft with its own "
    .. "instruction.", self:raw(from, e), table.concat(before, " and "), table.concat(after, " and ")))
end

-- True when the aircraft named at i is context ("to avoid a conflict with KLM77", "to meet BAW123"):
-- a word of lexicon.aircraft_context within the 3 tokens before it, with no instruction word
-- between, and not the object of a verb that instructs it ("set up the conflict, bring EZY45 up to
-- 310" instructs EZY45).
function m:as_context(i)
  if self:word(i - 1, "bring get put send have let make tell ask") then return false end
  -- "For TOM6RT, EXS34M speed 320", "for spacing on TOM6RT, ...": "for" opening its sentence within the
  -- 3 words before an aircraft and a comma, then another aircraft named: the first is the one the
  -- instruction is for the sake of, never instructed
  local lead = false
  for k = i - 1, math.max(1, i - 4), -1 do
    if self:intent_at(k) or self.t[k].kind == "punct" then break end
    local before = self.t[k - 1]
    if self:word(k, "for") and (before == nil or (before.kind == "punct" and before.text ~= ",")) then lead = true end
  end
  if lead then
    for _, r in ipairs(self:refs_in(i, #self.t + 1, "aircraft")) do
      if r.b == i and self.t[r.e] and self.t[r.e].text == "," then
        for _, o in ipairs(self:refs_in(r.e + 1, #self.t + 1, "aircraft")) do
          if o.exists and o.name ~= r.name then return true end
        end
      end
    end
  end
  -- ("traffic alert, DAL2104 turn left heading 360": an aircraft opening its clause after a comma, its
  -- instruction word straight after it, is the one instructed)
  -- ("reduce to 220 ahead of EZY45", "in front of the Iberia", "FL130 below KLM12", "clear of", "away from",
  -- "instead of": the traffic placed against or replaced)
  local k = self:word(i - 1, "the") and i - 2 or i - 1
  -- (the three readings below open on one of these words at k)
  local placed = self:word(k, "of from below under beneath above on upon with")
  if placed and ((self:word(k, "of")
        and (self:word(k - 1, "ahead clear instead") or self:word(k - 1, "front") and self:word(k - 2, "in")))
      or (self:word(k, "from") and self:word(k - 1, "away")) or self:word(k, "below under beneath above")) then
    return true
  end
  -- ("creeping up on the Easy", "closing on EZY45": the traffic neared, lexicon.neared_verbs; "for spacing on the
  -- KLM ahead": the traffic spaced from)
  if placed and self:word(k, "on upon") then
    local v = self:word(k - 1, "up in down") and k - 2 or k - 1
    if self:word(v, "@neared_verbs spacing sequencing separation") then return true end
  end
  -- ("..., head on with KLM605", "converging with the Ryanair": the traffic met)
  if placed and self:word(k, "with") and (self:word(k - 1, "converging converge converges head-on")
      or (self:word(k - 1, "on") and self:word(k - 2, "head"))) then
    return true
  end
  local named = self.t[i - 1] and self.t[i - 1].text == "," and self:refs_in(i, i + 1, "aircraft")[1]
  if named and self:intent_at(self:skip_fillers(named.e)) then return false end
  for k = i - 1, math.max(1, i - 3), -1 do
    -- (nor across a sentence's end: "OK, conflict time. Jetairfly climb FL310")
    if self:intent_at(k) or (self.t[k].kind == "punct" and self.t[k].text ~= ",") then return false end
    if self:word(k, "@aircraft_context") then
      -- ("insert SUGOL into KLM601's route", "into route of KLM601": the aircraft whose route it is, no
      -- traffic turned toward)
      local r = self:word(k, "into towards toward") and self:refs_in(i, i + 1, "aircraft")[1]
      return not (r and (self:word(r.e, "@route_nouns") or (self:word(i - 1, "of") and self:word(i - 2, "@route_nouns"))))
    end
  end
  return false
end

-- True when the aircraft named at i is the one compared with ("on the same level as the Iberia, FL330"):
-- "as" (and "the") before it, "same" within the 5 words before that; "as" before it and a verb of
-- what it did or is after it ("as EZY45 did", "as EZY45 has"); "as did" or "as with" before it;
-- "like" before it, not after a wish ("like EZY45", "just like EZY45 did"; "I'd like EZY45 at FL260"
-- instructs); "similar to" or "identical to" before it. An aircraft compared with is never instructed.
function m:compared_with(i)
  local k = self:word(i - 1, "the") and i - 2 or i - 1
  -- (each reading below opens on one of these words at k)
  if not self:word(k, "as did does has had with to like") then return false end
  if self:word(k, "as") and self:word_in(math.max(1, k - 5), k, "same") then return true end
  local r = self:refs_in(i, i + 1, "aircraft")[1]
  if self:word(k, "as") and r and self:word(r.e, "@compared_doings") then return true end
  if self:word(k, "did does has had with") and self:word(k - 1, "as") then return true end
  -- ("a new aircraft similar to ANA51: ...", "identical to the Qantas"): "to" after a word of likeness
  if self:word(k, "to") and self:word(k - 1, "@compared_likeness") then return true end
  return self:word(k, "like") and not self:word(k - 1, "@wish_before_like")
end

-- True when "and" at k joins the second of two aircraft said after "between" in the same clause ("a conflict
-- between the Air France and the Ryanair"): that aircraft is context, as the first is.
local function second_between(self, k)
  if not self:word(k, "and") then return false end
  for j = k - 1, math.max(1, k - 8), -1 do
    if self.t[j].kind == "punct" or self:intent_at(j) then return false end
    if self:word(j, "between") then return true end
  end
  return false
end

-- An airline said with no flight number ("KLM, climb ..."): the question
-- names its aircraft when more than one fits, and says so when none flies
-- ("the Ryanair" with no RYR aircraft).
function m:airline_only(s)
  for i = s.b, s.e - 1 do
    local icao, e, codes = self:airline_at(i)
    local fits = icao and self:airline_name_shared(self:said_name(i, e), self:airline_fleet(icao, codes)) or {}
    if #fits > 1 then
      -- (said alone as the addressee, one of the callsigns named answers it: confirm.choices, m:alone_confirmed)
      if not self:word(i - 1, "the") and self:alone_addressee(i, e, true) then
        self.confirm = self.confirm or { choices = fits, heard = self:raw(i, e) }
      end
      return self:need(string.format("Which %s: %s?", self:raw(i, e), table.concat(fits, " or ")))
    end
    -- ("Ryanair, turn left 40" with RYR4KP the one Ryanair flying: a callsign cut short, asked by naming the one
    -- it fits; a yes reads the request again with that callsign confirmed, m:alone_confirmed)
    if #fits == 1 and not self:word(i - 1, "the") and self:alone_addressee(i, e, true)
        and not (self.world.confirmed or {})[fits[1]] and not self:names_aircraft(fits[1]) then
      self.confirm = self.confirm or { id = fits[1], heard = self:raw(i, e), choices = fits }
      return self:need(string.format("%s alone is not a callsign: do you mean %s?", self:raw(i, e), fits[1]))
    end
    if icao and #fits == 0 and self:word(i - 1, "the") and #self.fleet > 0 then
      return self:need(string.format("No %s aircraft is flying. Which aircraft do you mean?", self:raw(i, e)))
    end
  end
end

-- Airline names (telephony and translate/names.lua's common names, up to
-- three words) -> ICAO prefix; brand names -> {ICAO prefixes}; the ICAO prefix a brand's name names ->
-- {the brand's prefixes} (TRA -> {TRA, TVF}: a callsign heard with "Transavia" is of either).
-- AIRLINE_FIRST: the first words (up to the first space) of those names.
-- NAMES_OF[icao]: the telephony names (lower case) of an airline; CALLED[icao]: those and its common names
local AIRLINE_NAMES, BRANDS, BRAND_OF, AIRLINE_FIRST, NAMES_OF, CALLED
local function airline_names()
  if AIRLINE_NAMES then return AIRLINE_NAMES, BRANDS, BRAND_OF end
  AIRLINE_NAMES, BRANDS, BRAND_OF, AIRLINE_FIRST, NAMES_OF, CALLED = {}, {}, {}, {}, {}, {}
  local names = require("translate.names")
  for _, list in ipairs({ names.airlines, names.common }) do
    for _, a in ipairs(list) do
      AIRLINE_NAMES[a[1]] = a[2]
      AIRLINE_FIRST[a[1]:match("^[^ ]*")] = true
      CALLED[a[2]] = CALLED[a[2]] or {}
      table.insert(CALLED[a[2]], a[1])
    end
  end
  for _, a in ipairs(names.airlines) do
    NAMES_OF[a[2]] = NAMES_OF[a[2]] or {}
    table.insert(NAMES_OF[a[2]], a[1])
  end
  for _, b in ipairs(names.brands or {}) do
    BRANDS[b[1]] = { table.unpack(b, 2) }
    BRANDS[b[1]].shared, BRANDS[b[1]].every, BRANDS[b[1]].name = b.shared, b.every, b[1]
    BRANDS[b[1]].twins = b.twins
    if AIRLINE_NAMES[b[1]] then BRAND_OF[AIRLINE_NAMES[b[1]]] = BRANDS[b[1]] end
  end
  return AIRLINE_NAMES, BRANDS, BRAND_OF
end

-- True when a callsign said with brand `brand`'s name (names.lua's brands) may be of its airline `icao`: the
-- brand is shared (each licensee is called by it: "Virgin 817" is VOZ817) or `every` (each of its airlines is
-- called by it: "AirAsia 8302" is AWQ8302), squawk knows no telephony of that
-- airline (names.airlines), or one of its telephony names is the brand's name or begins with it ("jetstar
-- asia" bears "jetstar"). Jetstar Japan, called "orange liner", is never "Jetstar 503" (issue 44 point 3).
local function bears(icao, brand)
  if brand.shared or brand.every or not NAMES_OF[icao] then return true end
  for _, n in ipairs(NAMES_OF[icao]) do
    if n == brand.name or n:sub(1, #brand.name + 1) == brand.name .. " " then return true end
  end
  return false
end

-- G:airline_at's reading of the words at i, each time anew.
local function airline_at(self, i)
  local t = self.t[i]
  if not t or t.kind ~= "word" then return nil end
  -- (no name starts with this word: only the designator typed in capitals can match; a word holding
  -- a space is looked up whole)
  if not AIRLINE_NAMES then airline_names() end
  if not AIRLINE_FIRST[t.text] and not t.text:find(" ", 1, true) then
    if #t.raw == 3 and t.raw:match("^%u%u%u$") then
      -- ("ITA Airways": a name of two words or more opening with the capitals is that name)
      local nx = self.t[i + 1]
      local low = t.raw:lower() .. " " .. (nx and nx.kind == "word" and nx.text or "")
      if AIRLINE_FIRST[t.raw:lower()] and AIRLINE_NAMES[low] then return AIRLINE_NAMES[low], i + 2, BRANDS[low] end
      return t.raw, i + 1
    end
    return nil
  end
  local words = {}
  for k = i, i + 2 do
    if not self.t[k] or self.t[k].kind ~= "word" then break end
    words[#words + 1] = self.t[k].text
  end
  for n = #words, 1, -1 do
    local said = table.concat(words, " ", 1, n)
    local icao = AIRLINE_NAMES[said]
    if icao then return icao, i + n, BRANDS[said] end
  end
  if t.raw:match("^%u%u%u$") then return t.raw, i + 1 end
  return nil
end
-- The airline named by the words at i (longest name first; a designator
-- typed in capitals, "the DLH", too): ICAO prefix, first token after it, and the ICAO prefixes of
-- the brand the name is (names.lua's brands; nil for one airline). Read once per request and position.
function m:airline_at(i)
  local found = self.airlines_at  -- per request: found[i] = {icao, e, brand} or false
  if not found then
    found = {}
    self.airlines_at = found
  end
  local a = found[i]
  if a == nil then
    local icao, e, brand = airline_at(self, i)
    a = icao ~= nil and { icao, e, brand }
    found[i] = a
  end
  if a then return a[1], a[2], a[3] end
  return nil
end

-- The positions i where G:airline_at reads an airline, ascending: read once per request, when first asked in
-- the parse (G:blank, which changes what a position reads, runs before it).
local function airline_positions(self)
  local at = self.airline_positions
  if not at then
    at = {}
    for i = 1, #self.t do
      if self:airline_at(i) then at[#at + 1] = i end
    end
    self.airline_positions = at
  end
  return at
end

-- True when token i lies inside a reference (an aircraft's callsign, a type, a place).
local function in_ref(self, i)
  for _, r in ipairs(self.refs) do
    if r.b <= i and i < r.e then return true end
  end
  return false
end

-- The first airline name (names.lua telephony or common name, a capital in its first word as typed:
-- "Luxair", "easyJet"; "reach" and "easy" are words too; in any case with `any_case`) said at a clause's start (the utterance's,
-- or after punctuation, "and" or "then") with no flight number, letters, "heavy" or a correction
-- ("United correction Southwest 686") after it and inside no reference, from the start of s's clause
-- to s.e - 1; nil when there is none. Returns {b, e, icao} (tokens b..e-1, the airline's ICAO prefix).
function m:airline_said_alone(s, any_case)
  local b  -- the start of s's clause, found once an airline is named before s.b
  for _, i in ipairs(airline_positions(self)) do
    if i >= s.e then break end
    if i < s.b and not b and not in_ref(self, i) then  -- (an airline inside a reference is never said alone)
      b = s.b
      while b > 1 and self.t[b - 1].kind ~= "punct" and not self:word(b - 1, "and @then_words") do b = b - 1 end
    end
    if i >= (b or s.b) then
      local icao, e = self:airline_at(i)
      local nxt = self.t[e]
      local inside = in_ref(self, i)
      local starts = i == 1 or self.t[i - 1].kind == "punct" or self:word(i - 1, "and @then_words")
      -- (a name G:stations read as the caller's own station is no airline: "Shamrock 6MA, Brussels, bonjour")
      if self.u:used(i) and (self.noted or {})[i] then starts = false end
      if starts and (e > i + 1 or airline_names()[self.t[i].text]) and (any_case or self.t[i].raw:match("%u")) and not inside
          and not (nxt and (nxt.kind == "number" or nxt.number_word or L.phonetic[nxt.text]
            or self:word(e, "heavy super @correction"))) then
        return { b = i, e = e, icao = icao }
      end
    end
  end
end

-- The flying aircraft of an airline (callsign = prefix, then a digit); `codes`, the prefixes of a
-- brand (airline_at's third value), widens it to every airline flying under the brand's name.
function m:airline_fleet(icao, codes)
  local fits = {}
  for _, a in ipairs(self.fleet) do
    for _, c in ipairs(codes or { icao }) do
      if a.id:upper():sub(1, #c) == c and a.id:sub(#c + 1, #c + 1):match("%d") then fits[#fits + 1] = a.id end
    end
  end
  return fits
end

-- The words b..e-1 (lower case, one space apart): an airline's name as said.
function m:said_name(b, e)
  local words = {}
  for k = b, e - 1 do words[#words + 1] = self.t[k].text end
  return table.concat(words, " ")
end

-- The aircraft flying of airlines other than those in `fits` whose telephony holds the airline's name `said` as a word
-- or, said in four letters or more, as a word's start or end ("swiss" in SWISS AIR FORCE, and in TOPSWISS,
-- easyJet Switzerland's; a common name, "Lufthansa CityLine", is none): `fits` with them added (the airline said
-- then fits more than one aircraft).
function m:airline_name_shared(said, fits)
  airline_names()
  local out, taken = fits, {}
  for _, id in ipairs(fits) do taken[id] = true end
  for _, a in ipairs(self.fleet) do
    local prefix = a.id:upper():match("^(%a+)%d")
    local names = not taken[a.id] and prefix and NAMES_OF[prefix]
    for _, name in ipairs(names or {}) do
      local holds = (" " .. name .. " "):find(" " .. said .. " ", 1, true) ~= nil
      for w in name:gmatch("%S+") do
        holds = holds or (#said >= 4 and w ~= said and (w:sub(1, #said) == said or w:sub(-#said) == said))
      end
      if holds then
        if out == fits then out = { table.unpack(fits) } end
        out[#out + 1], taken[a.id] = a.id, true
        break
      end
    end
  end
  return out
end

-- With exactly one aircraft in `fits` (named by its airline or type over tokens b..e-1), adds
-- it to self.refs as a reference the utterance did not find (kind "aircraft", flag `by` = true),
-- kept in order of first token, and returns e; otherwise returns b + 1 (the next token to look at).
function m:insert_ref(fits, b, e, by)
  if #fits ~= 1 then return b + 1 end
  local k = 1
  while self.refs[k] and self.refs[k].b < b do k = k + 1 end
  table.insert(self.refs, k, { kind = "aircraft", name = fits[1], b = b, e = e, exists = true, [by] = true })
  return e
end

-- True when the request names aircraft `id` by its callsign somewhere ("Speedbird 177, ..., Speedbird diverting",
-- "Norwegian - sorry, NAX3KT - climb ..."): an airline said alone beside it repeats or corrects that callsign.
function m:names_aircraft(id)
  for _, r in ipairs(self.refs or {}) do
    if r.kind == "aircraft" and not r.by_airline and r.name and r.name:upper() == id:upper() then return true end
  end
  return false
end

-- True when the airline over tokens b..e-1, said without "the", stands as a clause's addressee: written with a
-- capital, opening the utterance or a clause (after punctuation, "and" or "then"), no correction after it, and no
-- callsign said in its clause (up to the next punctuation, "and" or "then") or straight after it.
-- True when the airline's name over tokens b..e-1, typed in lower case, is words squawk knows as no other
-- ("ryanair turn right 40 degrees"; "easy" or "delta" in lower case are words).
function m:airline_cased(b, e)
  for k = b, e - 1 do
    if self.name_words[self.t[k].text] == false then return false end
  end
  return true
end
function m:alone_addressee(b, e, asking)
  -- (in lower case only to ask about it, "ryanair turn right 40 degrees": m:airline_only; taken, never)
  if not (self.t[b].raw:match("%u") or (asking and self:airline_cased(b, e))) then return false end
  local function clause_break(k)
    return self.t[k].kind == "punct" or self:word(k, "and @then_words")
  end
  if b > 1 and not clause_break(b - 1) then return false end
  if self:word(self:skip_fillers(e, false), "@correction") then return false end
  local k = e
  while self.t[k] and not clause_break(k) do k = k + 1 end
  return not (self:has_ref(e, k, "aircraft")
    or self:has_ref(self:skip_fillers(e, false), self:skip_fillers(e, false) + 1, "aircraft"))
end

-- True when the airline over tokens b..e-1 stands alone as a clause's addressee (m:alone_addressee) and the speaker
-- confirmed exactly one of the aircraft of it flying (`fits`; world.confirmed: the "yes" or the callsign answering
-- airline_only's "X alone is not a callsign: do you mean ID?" or "Which X: ID1 or ID2?").
function m:alone_confirmed(b, e, fits)
  local n = 0
  for _, id in ipairs(fits) do
    if (self.world.confirmed or {})[id] then n = n + 1 end
  end
  return n == 1 and self:alone_addressee(b, e, true)
end

-- True when the airline named over tokens b..e-1 without "the" is a clause's addressee
-- (lexicon.callsign_confirm.airline_alone_addressee): the request gives more than one kind of
-- instruction or names more than one aircraft ("Ryanair turn left heading 100 and climb FL320",
-- "easyJet 45 heading 180, Luxair heading 270"; one instruction to an airline alone, "Lufthansa,
-- climb FL280", is a callsign cut short and asked about); the airline opens the utterance or a clause (after punctuation, "and" or
-- "then"), is written with a capital ("easy" or "delta" in lower case are words), is said with no
-- correction after it, and no callsign is said in its clause (up to the next punctuation, "and" or
-- "then") or straight after it ("Lufthansa, DLH4AX, ..." names DLH4AX).
function m:addressed_alone(b, e)
  if not L.callsign_confirm.airline_alone_addressee or not self:alone_addressee(b, e) then return false end
  if self.several == nil then
    -- kinds of instruction said ("maintain" is a climb's, a speed's or a heading's), aircraft named
    -- (callsigns, and airlines written with a capital at a clause's start)
    local kinds, n, named = {}, 0, 0
    for i = 1, #self.t do
      local intent = self:intent_at(i)
      if intent and intent ~= "maintain" and not kinds[intent] and not self:in_reason(i) then
        kinds[intent], n = true, n + 1
      end
      local starts = i == 1 or self.t[i - 1].kind == "punct" or self:word(i - 1, "and @then_words")
      if starts and self:airline_at(i) and self.t[i].raw:match("%u") then named = named + 1 end
    end
    for _, r in ipairs(self.refs) do
      if r.kind == "aircraft" and not self:in_reason(r.b) then named = named + 1 end
    end
    self.several = n >= 2 or named >= 2
  end
  return self.several
end

-- True when the airline said alone over tokens b..e-1 names back the one aircraft of it flying (`fits`, exactly
-- one) that the request named by its callsign before b, in a clause naming two or more aircraft of different
-- airlines ("UTair 125 and Aeroflot 1736 are converging, Aeroflot stop descent at level 110, UTair descend ...",
-- "... are in conflict, turn Astanaline right on 30 degrees"): the pair named, then each told apart by its airline.
-- The airline written with a capital, no number, letter or "the" after or before it (airline_refs checks those).
function m:airline_named_back(b, fits)
  if #fits ~= 1 or not self.t[b].raw:match("^%u") then return false end
  -- (named together: another aircraft straight before or after it, "and", "&" or a comma between, as m:acids reads
  -- an airline left unresolved; one named as its own instruction's addressee, "RYR77 speed 240, Ryanair descend",
  -- is not)
  local refs = {}
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" and r.exists and not r.by_airline and r.e <= b then refs[#refs + 1] = r end
  end
  for x, r in ipairs(refs) do
    if r.name:upper() == fits[1]:upper() then
      for _, q in ipairs({ refs[x - 1] or false, refs[x + 1] or false }) do
        if q and q.name:upper() ~= r.name:upper() then
          local gap = q.b > r.b and r.e or q.e
          if (q.b > r.b and q.b or r.b) == gap + 1
              and (self:word(gap, "and") or self.t[gap].text == "," or self.t[gap].text == "&") then
            return true
          end
        end
      end
    end
  end
  return false
end

-- True when the airline said alone over tokens b..e-1 is what a question about an aircraft's
-- whereabouts names ("where is ryanair", "what's Ryanair doing"): a question, never a cut-short callsign
-- given an instruction, so it is the one aircraft of that airline flying (asked about with several).
function m:asked_where(b, e)
  local k = self:word(b - 1, "is are") and b - 2 or b - 1
  return self:word(k, "where wheres") or (self:word(k, "what whats") and self:word(e, "doing"))
end

-- "the two Vuelings", "both easyJets", "both the Air Europas", "all the Ryanairs": an airline said in the
-- plural after "the", "all" or "both" (a count, a digit or a number word, after "the" or "all"; with neither
-- count nor "both", written with a capital), with exactly that many of it flying ("both": two; "the" or "all"
-- with no count: two or more), names each of them: one reference per aircraft over the words (kind
-- "aircraft", by_airline = true), in place of any the callsign matcher heard in them ("three" as AEA3).
-- Another count flying is asked, naming those that fly; aircraft of it named by callsign elsewhere in the
-- request are each their own (no group). Said after a word of other traffic (lexicon.airline_context,
-- aircraft_context, below, above, "from", "of") it is no group. `inside`: the tokens other references hold.
local COUNTS = { two = 2, three = 3, four = 4, ["2"] = 2, ["3"] = 3, ["4"] = 4 }
function m:airline_group_refs(inside)
  if not AIRLINE_NAMES then airline_names() end
  local texts = self.words
  for i = 1, #self.t do
    local w = texts[i]
    if w == "the" or w == "all" or w == "both" then
      -- (other traffic: "away from the Vuelings", "above the two Vuelings", "behind both Vuelings", "clear of the
      -- Vuelings")
      local b = self:word(i, "the all both") and not self:other_traffic_before(i - 1)
        and not self:word(i - 1, "from of") and i
      local k = b and (self:word(i + 1, "the") and i + 2 or i + 1)
      local count = b and COUNTS[self.t[k] and self.t[k].text or ""]
      if count then k = k + 1 end
      if self:word(i, "both") then count = count or 2 end
      for n = 3, 1, -1 do
        local last = b and self.t[k + n - 1]
        if last and last.kind == "word" and last.text:match("%as$") and not inside[k]
            and (count or self.t[k].raw:match("^%a*%u")) then
          local words = {}
          for x = k, k + n - 1 do words[#words + 1] = self.t[x].kind == "word" and self.t[x].text or "" end
          words[n] = words[n]:sub(1, -2)  -- ("vuelings": the airline's name and its plural's "s")
          local said = table.concat(words, " ")
          local icao = AIRLINE_NAMES[said]
          local fits = icao and self:airline_fleet(icao, BRANDS[said]) or {}
          -- ("both Lufthansas, DLH4AX FL210 and DLH9KM FL240": named by their callsigns too, each its own)
          local named = false
          for _, r in ipairs(self.refs) do
            for _, id in ipairs(fits) do
              named = named or (r.kind == "aircraft" and r.name == id and (r.b < b or r.e > k + n))
            end
          end
          -- (the words the callsign matcher heard as an aircraft, "two Vuelings" as VLG21, "three" as AEA3,
          -- are the group's)
          for x = #self.refs, 1, -1 do
            if icao and not named and self.refs[x].b >= b and self.refs[x].e <= k + n then table.remove(self.refs, x) end
          end
          if icao and not named and not (#fits == count or (not count and #fits >= 2)) then
            self:need(string.format("Which aircraft does '%s' mean? %s", self:raw(b, k + n),
              #fits > 0 and ("Those flying: " .. table.concat(fits, ", ") .. ".") or "None of them flies."))
            for x = b, k + n - 1 do inside[x] = true end
            break
          elseif icao and not named then
            local at = 1
            while self.refs[at] and self.refs[at].b < b do at = at + 1 end
            for j, id in ipairs(fits) do
              table.insert(self.refs, at + j - 1, { kind = "aircraft", name = id, b = b, e = k + n, exists = true,
                by_airline = true })
            end
            for x = b, k + n - 1 do inside[x] = true end
            break
          end
        end
      end
    end
  end
end

-- True when "to" at `to` closes a request to add a place to a route with the aircraft whose words end before `e`
-- ("add waypoint P5 to the Kenya"): the one the place is added to, its route left unsaid.
function m:added_to(to, e)
  local after = self.t[self:skip_fillers(e)]
  if not self:word(to, "to") or (after and after.kind ~= "punct") then return false end
  for k = 1, to - 1 do
    if self:intent_at(k) == "addwpt" then return true end
  end
  return false
end

-- True when the airline said at token i, written with a capital, is the object of the request's own preposition with
-- its article dropped (a second-language speaker's "the"): after "of" or "for" straight after a route noun or
-- "destination" ("show me route of Lufthansa", "set destination of Air France to Krakow", "route for Smartwings"),
-- or after "for" or "to" straight after a verb of adding or giving that opens its clause ("add for Smartwings
-- waypoint JAB", "give to Wizz direct AGESI"). Traffic words before the preposition ("clear of Lufthansa",
-- "turn for Wizz") are none of these.
function m:object_article_dropped(i)
  if not self.t[i].raw:match("^%u") then return false end
  if self:word(i - 1, "of for") and self:word(i - 2, "@route_nouns destination") then return true end
  local opens = i == 3 or (self.t[i - 3] and (self.t[i - 3].kind == "punct" or self:word(i - 3, "please and")))
  return self:word(i - 1, "for to") and self:word(i - 2, "add insert give") and opens
end

-- True when "to" at `to` closes a value given to an aircraft whose words follow ("kindly give Mach 0.80 to the
-- Emirates", "a descent of 1000 feet per minute may be given to the Akasa"): a verb of giving earlier in its clause.
function m:given_to(to)
  if not self:word(to, "to") then return false end
  for k = to - 1, math.max(1, to - 12), -1 do
    if self.t[k].kind == "punct" then return false end
    if self:word(k, "give given giving gives assign assigned issue issued") then return true end
  end
  return false
end

-- An airline and a type's number or designator said where the callsign matcher read a callsign of that airline
-- that flies ("the Austrian 767" heard as AUA767 and matched inexactly to AUA7LN; "the Lufthansa 747" with DLH747
-- flying): which reading stands. `r`: that reference (from token i; the type ends before token te); `typed`: ids of
-- the airline's aircraft flying of the type, or nil; `the`: the airline said after "the". Returns the ids the type
-- names (r is then dropped by airline_refs), or nil to keep r as read. The callsign is linked to what was said when
-- it is exact or one slip from what was heard (m:near_callsigns). After "the", the type names its aircraft when the
-- callsign is not linked; a linked callsign of another aircraft and the type's aircraft are both named in a question.
-- A callsign not linked is never offered, its only link being the type's number: with none of the airline's aircraft
-- of the type flying, or without "the", the question names what was heard. A question drops r, so that no yes to it
-- confirms that aircraft.
function m:callsign_or_type(i, te, r, typed, the)
  -- (a callsign said in full with more digits after it, "Egyptair 777 20 miles before FAROE" for MSR777, is linked;
  -- one heard from part of the type's words, "Delta seven" of "the Delta seven fifty-seven", leaves the rest unread)
  local linked, has = not r.heard or r.heard.id:sub(1, #r.name) == r.name:upper(), false
  for _, id in ipairs(r.heard and te == r.e and self:near_callsigns(r.heard.id) or {}) do
    linked = linked or id == r.name
  end
  for _, id in ipairs(typed or {}) do has = has or id == r.name end
  if has then return r.heard and typed or nil end
  if the and typed and not linked then return typed end
  if linked and not typed then return nil end
  local said = self:raw(i, te)
  if typed then
    local kinds = {}
    for _, id in ipairs(typed) do kinds[#kinds + 1] = string.format("%s, a %s", id, (self:state(id).type or "?"):upper()) end
    local call = not r.heard and string.format("%s by its callsign", r.name)
      or linked and string.format("%s by a callsign heard as %s", r.name, r.heard.id) or "no aircraft flies with it"
    self:need(string.format("Which aircraft is '%s'? As a callsign: %s; as the airline's type: %s. Please give its "
      .. "callsign.", said, call, table.concat(kinds, " or ")))
  else
    self:need(string.format("Which aircraft is '%s'? No aircraft of that airline has it for its callsign or its "
      .. "type. Please give its callsign.", said))
  end
  for k = #self.refs, 1, -1 do
    if self.refs[k] == r then table.remove(self.refs, k) end
  end
  return nil
end

-- An aircraft named by "the" and its airline alone ("could the Ryanair come
-- down", "the easyJet's route", "the BA"), with exactly one aircraft of that
-- airline flying, is a reference to it (added to self.refs, kind "aircraft",
-- by_airline = true; lexicon.callsign_confirm.airline_alone). Not when the
-- name is said with a flight number, letters or "heavy" after it (a callsign,
-- matched or asked by the C++ matcher; "Lufthansa, descend ..." in
-- radiotelephony is a callsign cut short and asks too), introduces a new
-- aircraft ("a KLM Airbus", "one more Lufthansa, DLH9CK"), or names other
-- traffic ("too close to the BA", "behind the KLM", "all except the
-- Qantas": lexicon.airline_context). With two or more of the airline
-- flying, airline_only asks which.
function m:airline_refs()
  -- ("the EZY agent": a designator in capitals the lexer took for an unknown place names its airline)
  local function unknown_place(r)
    return r.kind == "waypoint" and not r.exists and r.e == r.b + 1 and self.t[r.b].raw:match("^%u%u%u$")
      and not self:word(r.e, "@navaid_kinds")
  end
  -- ("the LATAM", "to avoid the LATAM": the navdata's fix LATAM, in France) a place named by an airline's
  -- name, one word, with an aircraft of that airline flying, that no aircraft flying has in its route and
  -- that lies beyond lexicon.navaid_range_nm of every aircraft flying, is the airline: its ref is dropped
  local function airline_not_place(r)
    local icao = r.kind == "waypoint" and r.e == r.b + 1 and airline_names()[self.t[r.b].text]
    if not icao or self:word(r.e, "@navaid_kinds") or not self.world.user_waypoint_at
        or #self:airline_fleet(icao, BRANDS[self.t[r.b].text]) == 0 then
      return false
    end
    local lat, lon = self.world.user_waypoint_at(r.name)
    if not lat then return false end
    local any = false
    for _, a in ipairs(self.fleet) do
      for _, w in ipairs(a.route or {}) do
        if w:upper() == r.name:upper() then return false end
      end
      if a.lat then
        local dlat, dlon = a.lat - lat, (a.lon - lon) * math.cos(math.rad(lat))
        if 60 * math.sqrt(dlat * dlat + dlon * dlon) <= L.navaid_range_nm then return false end
        any = true
      end
    end
    return any
  end
  for k = #self.refs, 1, -1 do
    if airline_not_place(self.refs[k]) then table.remove(self.refs, k) end
  end
  -- ("before MTL add LATAM at FL280" with no LATAM aircraft flying: the fix) a name of five capitals, a
  -- fix's, that the callsign matcher kept from places for being an airline's telephony is the place the
  -- navdata or a DEFWPT holds under it when no aircraft of that airline flies, no number follows and no
  -- aircraft type is named (a new aircraft's airline: "create a LATAM A320")
  local typed = self:has_ref(1, #self.t + 1, "type")
  for i = 1, typed and 0 or #self.t do
    local t, nx = self.t[i], self.t[i + 1]
    local icao = t.kind == "word" and #t.raw == 5 and t.raw:match("^%u%u%u%u%u$") and airline_names()[t.text]
    if icao and not self:has_ref(i, i + 1) and #self:airline_fleet(icao, BRANDS[t.text]) == 0
        and not (nx and (nx.kind == "number" or nx.number_word))
        and self.world.user_waypoint_at and self.world.user_waypoint_at(t.raw) then
      local k = 1
      while self.refs[k] and self.refs[k].b < i do k = k + 1 end
      table.insert(self.refs, k, { kind = "waypoint", name = t.raw, b = i, e = i + 1, exists = false })
    end
  end
  -- ("descend FL160, level by Talla": the navaid or airport said by its name of one or two words after
  -- "level by", ending the clause, is the waypoint of that ident; so after "be level" and the level, "descend to be
  -- level flight level one two zero by Talla")
  local texts = self.words
  local function be_level_before(i)
    for k = math.max(2, i - 10), i - 2 do
      if texts[k] == "level" and texts[k - 1] == "be" then return true end
    end
    return false
  end
  for i = 3, #self.t do
    if texts[i - 1] == "by" and (texts[i - 2] == "level" or be_level_before(i)) and not self:has_ref(i, i + 1) then
      for e = math.min(i + 2, #self.t + 1), i + 1, -1 do
        local id = (not self.t[e] or self.t[e].kind == "punct") and self:place_by_name(i, e)
        if id then
          local k = 1
          while self.refs[k] and self.refs[k].b < i do k = k + 1 end
          table.insert(self.refs, k, { kind = "waypoint", name = id, b = i, e = e, exists = true })
          break
        end
      end
    end
  end
  -- "the SAS one, could it ...", "descend the SAS one to FL80": "one" after "the" and an airline, no digit,
  -- number word or spelled letter after it, is the pronoun (the airline's aircraft), no flight number; the
  -- callsign the matcher heard in it is no reference
  local function pronoun_one(k)
    local after = self.t[k + 1]
    return self:word(k, "one") and not (after and (after.kind == "number" or after.number_word
      or L.phonetic[after.text] or self:word(k + 1, "heavy super")))
  end
  for k = #self.refs, 1, -1 do
    local r = self.refs[k]
    local icao, e = self:airline_at(r.b)
    if r.kind == "aircraft" and icao and e == r.e - 1 and self:word(r.b - 1, "the") and pronoun_one(e)
        and (not r.exists or r.heard) then
      table.remove(self.refs, k)
    end
  end
  local inside = {}
  for _, r in ipairs(self.refs) do
    if not unknown_place(r) then
      for k = r.b, r.e - 1 do inside[k] = true end
    end
  end
  if not L.callsign_confirm.airline_alone then return end
  -- ("create the SAS flight SAS902, an A21N, at Arlanda", "create an SAS A320 for us, callsign SAS123": the
  -- airline said before a new callsign of its own, straight before it (an aircraft noun between or none) or
  -- after an article, describes it: no place)
  for _, i in ipairs(airline_positions(self)) do
    local icao, e = self:airline_at(i)
    local at = self:word(e, "@aircraft_nouns") and e + 1 or e
    local upto = self:word(i - 1, "@articles_new") and #self.t + 1 or at + 1
    for _, r in ipairs(self:refs_in(at, upto, "aircraft")) do
      if not r.exists and r.name:upper():sub(1, #icao) == icao then
        for k = #self.refs, 1, -1 do
          if self.refs[k].b == i and unknown_place(self.refs[k]) then table.remove(self.refs, k) end
        end
        self:explain(i, r.b == at and at or e)
      end
    end
  end
  self:airline_group_refs(inside)
  local i = 1
  while i <= #self.t do
    local icao, e, codes = self:airline_at(i)
    if not icao then
      i = i + 1  -- (no airline named at i)
    else
      local nxt = self.t[e]
      -- ("the big FedEx trijet", "the little Jazz": a size word between "the" and the airline narrows nothing;
      -- `p`: the token after "the")
      local p = self:word(i - 1, "big little small large") and self:word(i - 2, "the") and i - 1 or i
      local prev = self.t[p - 1]
      local the = prev and prev.kind == "word" and prev.text == "the" and not second_between(self, p - 2)
          and (not self:other_traffic_before(p - 2)
            or self:word(e, "@route_nouns")  -- "add X to the KLM's route" (the lexer drops "'s")
            or self:added_to(p - 2, e) or self:given_to(p - 2) or self:same_opening(i))
      -- ("show speedbird's route", "what is easy's level": the airline's possessive before a thing an aircraft has,
      -- lexicon.possessed_by_aircraft, names its aircraft as "the Speedbird's" does)
      -- (the lexer drops the "'s": read from the request as said)
      the = the or (self:word(e, "@possessed_by_aircraft") and (self.text_said or ""):lower()
        :find("%f[%w]" .. self.t[e - 1].raw:lower():gsub("%p", "%%%0") .. "['\226\128\153]s%f[%W]") ~= nil)
      if the and p < i then self:explain(p, i) end
      -- ("the regional jet from Republic, climb ...", "the plane from Delta": "the", words of an aircraft described
      -- and "from" before the airline capitalised name its aircraft, as "the Republic jet" does; `from_the`: the
      -- position of that "the")
      local from_the
      if self:word(i - 1, "from") and self.t[i].raw:match("^%u") then
        local k = i - 2
        while k > i - 5 and self:word(k, "@aircraft_nouns @aircraft_described") do k = k - 1 end
        if k < i - 2 and self:word(k, "the") and not self:other_traffic_before(k - 1) then
          from_the = k
        end
      end
      the = the or from_the ~= nil
      -- ("insert PTA after DORVO for Flybondi": the airline capitalised after "for", ending its clause, is the
      -- aircraft the instruction is for)
      local for_it = self:word(i - 1, "for") and self.t[i].raw:match("^%u") ~= nil and (not nxt or nxt.kind == "punct")
      -- ("the Emirates A380 should descend", "the Jetstar A320": a type said straight after "the" and the airline,
      -- no request to create, describes the airline's aircraft flying of that type; `typed`: those, and the token
      -- after the type)
      local typed, type_e
      local test, te
      -- (`said_at`: the callsign the matcher read from the airline's words on; `heard`: one no aircraft flying has,
      -- the matcher's reading of the airline and the number after it)
      local said_at = self:refs_in(i, i + 1, "aircraft")[1]
      said_at = said_at and said_at.b == i and said_at
      local heard = said_at and not said_at.exists and said_at
      -- ("IndiGo ATR may be climbed to FL150": the airline and a type opening a sentence, no number heard as a
      -- callsign, describe the airline's aircraft of that type as after "the"; "Austrian 767, climb ..." matched
      -- inexactly is weighed by m:callsign_or_type)
      local opening = not prev or (prev.kind == "punct" and prev.text ~= ",")
      if (the and (not inside[i] or said_at))
          or (opening and ((said_at and said_at.heard) or (not heard and not inside[i]))) then
        test, te = self:type_said(the and self:after_of(e) or e, true)
      end
      if said_at and te and te < said_at.e then test = nil end
      for k = 1, test and #self.t or 0 do
        if self:intent_at(k) == "create" then test = nil end
      end
      if test then
        for _, a in ipairs(test and self.fleet or {}) do
          for _, id in ipairs(test(a.type and a.type:upper() or "") and self:airline_fleet(icao, codes) or {}) do
            if id == a.id then
              typed = typed or {}
              typed[#typed + 1] = id
            end
          end
        end
        if said_at and said_at.exists then typed = self:callsign_or_type(i, te, said_at, typed, the) end
        type_e = typed and te
      end
      -- ("the Ryanair at flight level 120, turn it left", "make the Ryanair at FL260 descend to FL200": "at" and a
      -- level straight after "the" and the airline describe its aircraft flying within 100 ft of that level)
      -- (with two or more of the airline flying: one alone, "put the Ryanair at FL180 over VIS", is the airline's)
      local at_q = the and not typed and not said_at and self:word(e, "at") and #self:airline_fleet(icao, codes) > 1
        and self:quantities(e + 1, e + 5)[1]
      if at_q and at_q.b == e + 1 and at_q.kind == "alt" then
        for _, id in ipairs(self:airline_fleet(icao, codes)) do
          local a = self:state(id)
          if a and a.alt_ft and math.abs(a.alt_ft - at_q.value) <= 100 then
            typed = typed or {}
            typed[#typed + 1] = id
          end
        end
        if typed then
          self:mark_used(e, at_q.e)
          type_e = at_q.e
        end
      end
      local ok = not inside[i] and not inside[e - 1]
          and (the or for_it or self:addressed_alone(i, e) or self:asked_where(i, e) or self:object_article_dropped(i)
            or self:airline_named_back(i, self:airline_fleet(icao, codes))
            or self:alone_confirmed(i, e, self:airline_name_shared(self:said_name(i, e), self:airline_fleet(icao, codes))))
          and not (nxt and (nxt.kind == "number" or nxt.number_word or L.phonetic[nxt.text]
            or self:word(e, "heavy super")) and not (the and pronoun_one(e)))
          and (typed or not self:new_aircraft_follows(e - 1))
      local fits = typed or (ok and self:airline_fleet(icao, codes)) or {}
      -- ("the Swiss" with SWR2811 and EZS44KP, TOPSWISS, flying: both fit)
      if ok and not typed and #fits > 0 then fits = self:airline_name_shared(self:said_name(i, e), fits) end
      -- (the airline alone answered by the speaker naming one of its aircraft, m:alone_confirmed: that one)
      if ok and not typed and #fits > 1 and not the and self:alone_confirmed(i, e, fits) then
        local one = {}
        for _, id in ipairs(fits) do
          if self.world.confirmed[id] then one[1] = id end
        end
        fits = one
      end
      -- ("Ryanair descend FL200 and RYR4411 speed 250": an airline alone addressed, without "the", whose one
      -- aircraft flying the request names by its callsign elsewhere is a callsign cut short, never that aircraft)
      local back = ok and not the and self:airline_named_back(i, fits)
      for _, r in ipairs(ok and not the and not back and #fits == 1 and self.refs or {}) do
        if r.kind == "aircraft" and r.name == fits[1] and (r.b >= e or r.e <= i) then fits = {} end
      end
      if typed then
        -- ("the Lufthansa 747", "the KLM 777": the airline and a family's number the callsign matcher heard as a
        -- callsign no aircraft flying has, DLH747, describe the airline's aircraft of that family; DLH747 flying is
        -- the callsign, and `typed` is not read)
        for k = #self.refs, 1, -1 do
          local r = self.refs[k]
          if (r.b >= e and r.b < type_e)
              or (r.kind == "aircraft" and r.b == i and r.e <= type_e and (not r.exists or r.heard)) then
            table.remove(self.refs, k)
          end
        end
        self:explain(e, type_e)
        e = type_e
      end
      -- asked about by acids, also beside an aircraft that is resolved (not in a reason; capitals that
      -- name no airline flying, "the ILS", are no airline)
      -- ("The SAS that's coming from the south, SAS 517, could it descend": the airline said again with its
      -- flight number, in the same sentence before any instruction, is the one meant)
      local named_later = false
      for _, r in ipairs(#fits > 1 and self.refs or {}) do
        if r.kind == "aircraft" and r.exists and r.b >= e and r.b <= e + 10 then
          local sentence = true
          for k = e, r.b - 1 do
            local t = self.t[k]
            sentence = sentence and not (t.kind == "punct" and t.text ~= ",") and not self:intent_at(k)
          end
          for _, id in ipairs(fits) do named_later = named_later or (sentence and id == r.name) end
        end
      end
      if ok and named_later then self:explain(i, e) end
      if ok and (#fits > 1 or (#fits == 0 and airline_names()[self.t[i].text])) and not self:in_reason(i)
          and not named_later then
        self.airline_unresolved = self.airline_unresolved or {}
        table.insert(self.airline_unresolved, { b = i, e = e })
      end
      if #fits == 1 then
        for k = #self.refs, 1, -1 do
          if self.refs[k].b == i and unknown_place(self.refs[k]) then table.remove(self.refs, k) end
        end
      end
      if from_the and #fits == 1 and ok then self:explain(from_the, i) end
      if ok and the and pronoun_one(e) then  -- (the pronoun is part of the name, no value)
        self:mark_used(e, e + 1)
        e = e + 1
      end
      i = self:insert_ref(fits, i, e, "by_airline")
    end
  end
end

-- An aircraft named by the letters of its callsign as a word, after a determiner and before an aircraft
-- noun ("our test aircraft" TEST01, "the intruder plane" INTRUDER2), when no airline has that name and
-- exactly one aircraft flying has those letters before its digits: a reference to it, as in airline_refs
-- (by_prefix = true; the noun is part of it). Two of those letters flying ("the test aircraft" with TEST01
-- and TEST02) name neither: the request is asked about as before.
function m:prefix_refs()
  if not self:said("@aircraft_nouns") then return end
  local i = 2
  while i < #self.t do
    local t = self.t[i]
    local fits = {}
    if t.kind == "word" and t.alpha and #t.text >= 2 and self:word(i - 1, "the our this that my your")
        and self:word(i + 1, "@aircraft_nouns")
        and not self:airline_at(i) and not self:has_ref(i, i + 2, "aircraft") then
      for _, a in ipairs(self.fleet) do
        local letters = a.id:match("^(%a+)%d")
        if letters and letters:lower() == t.text then fits[#fits + 1] = a.id end
      end
    end
    i = self:insert_ref(fits, i, i + 2, "by_prefix")
  end
end

-- Roles of a conflict study (lexicon.role_nouns). A declaration names the aircraft a role stands for:
-- "intruder WZZ1652", "subject aircraft is LOT3CM", "WZZ1652 is the intruder". A mention of the role later
-- in the request ("turn the intruder left": "the", the role, an optional aircraft noun, no callsign after)
-- becomes a reference to that aircraft (by_role = true); a role declared for two aircraft binds neither. A
-- sentence (up to ". ; ! ?") holding only declarations, values and lexicon.role_described words, with an
-- aircraft named or mentioned after it, is context: its references are dropped and its
-- words accounted for ("Subject LZB412, intruder AUA651, both FL310." clears no one).
local ROLE_ENDS = { ["."] = true, [";"] = true, ["!"] = true, ["?"] = true }
function m:role_refs()
  if not self:said("@role_nouns") then return end
  local bound, declared, spans = {}, {}, {}
  local function declare(role, r, b, e)
    if bound[role] and bound[role] ~= r.name then bound[role] = false elseif bound[role] == nil then bound[role] = r.name end
    declared[r] = true
    spans[#spans + 1] = { b = b, e = e }
  end
  for i = 1, #self.t do
    if self:word(i, "@role_nouns") and not self:has_ref(i, i + 1, "aircraft") then
      local role = self.t[i].text
      local k = self:word(i + 1, "@aircraft_nouns") and i + 2 or i + 1
      local is = self:word(k, "is") and k + 1 or k
      local after = self:refs_in(is, is + 1, "aircraft")[1]
      local before = self:word(i - 1, "the") and i - 2 or i - 1
      local by = self:word(before, "is") and self:refs_in(1, before, "aircraft")
      by = by and by[#by]
      -- ("..., VOZ917 the intruder: ...": the callsign and the role set apart by punctuation, no "is")
      local appos = self:word(i - 1, "the") and self:refs_in(1, i - 1, "aircraft")
      appos = appos and appos[#appos]
      local apart = function(x) return x < 1 or x > #self.t or self.t[x].kind == "punct" end
      if after and after.exists then
        declare(role, after, self:word(i - 1, "the") and i - 1 or i, after.e)
      elseif by and by.exists and by.e == before then
        declare(role, by, by.b, k)
      elseif appos and appos.exists and appos.e == i - 1 and apart(appos.b - 1) and apart(k) then
        declare(role, appos, appos.b, k)
      end
    end
  end
  local function in_span(i)
    for _, sp in ipairs(spans) do if i >= sp.b and i < sp.e then return true end end
    return false
  end
  -- mentions: "the intruder", "the subject aircraft", "ownship" (lexicon.role_bare: no "the") not part of a
  -- declaration
  local mentions = {}
  for i = 2, #self.t do
    local role = self.t[i].text
    local k = self:word(i + 1, "@aircraft_nouns") and i + 2 or i + 1
    local the = self:word(i - 1, "the")
    local b = the and i - 1 or i
    if bound[role] ~= nil and self:word(i, "@role_nouns") and (the or self:word(i, "@role_bare"))
        and not self:word(b - 1, "is") and not in_span(i)
        and not self:word(k, "is") and not self:has_ref(b, k + 1, "aircraft") then
      if not bound[role] then
        return self:need(string.format("Which aircraft is the %s? It was declared for two.", role))
      end
      mentions[#mentions + 1] = { name = bound[role], b = b, e = k }
    end
  end
  -- a role mentioned: the declarations are context, never addressees
  if #mentions > 0 then
    local refs = {}
    for _, r in ipairs(self.refs) do if not declared[r] then refs[#refs + 1] = r end end
    self.refs = refs
    for _, sp in ipairs(spans) do
      self:mark_used(sp.b, sp.e)
      for x = sp.b, sp.e - 1 do self.noted[x] = true end
    end
  end
  for _, x in ipairs(mentions) do self:insert_ref({ x.name }, x.b, x.e, "by_role") end
  -- sentences that only declare
  local b = 1
  while b <= #self.t do
    local e = b
    while e <= #self.t and not (self.t[e].kind == "punct" and ROLE_ENDS[self.t[e].text]) do e = e + 1 end
    local valued, only, any = {}, true, false
    for _, q in ipairs(self:quantities(b, e)) do for x = q.b, q.e - 1 do valued[x] = true end end
    for x = b, e - 1 do
      any = any or in_span(x)
      local t = self.t[x]
      only = only and (in_span(x) or valued[x] or t.kind == "punct" or self:word(x, "@role_described"))
    end
    local again = false
    if any and only and e < #self.t then
      for _, r in ipairs(self.refs) do again = again or (r.kind == "aircraft" and r.b > e) end
    end
    if again then self:set_aside(b, e) end
    b = e + 1
  end
end

-- "SAS4102 direct BR421", "add BENTI then BR421 to the route": a typed word of letters and digits that no
-- aircraft bears, said where an aircraft flying is named too and nothing is created, is the fix, navaid or
-- airport the navdata holds under it (world.place_known) within lexicon.navaid_range_nm of an aircraft flying:
-- its aircraft ref becomes a waypoint ref. A word no such place bears stays a callsign (asked about).
function m:fix_refs()
  local known = self.world.place_known
  if not known or self:word_in(1, #self.t + 1, "create cre crecon spawn mcre new") then return end
  local flying = false
  for _, r in ipairs(self.refs) do flying = flying or (r.kind == "aircraft" and r.exists) end
  if not flying then return end
  for _, r in ipairs(self.refs) do
    local raw = self.t[r.b].raw
    if r.kind == "aircraft" and not r.exists and not r.spoken and r.e == r.b + 1 and raw:match("%a")
        and raw:match("%d") then
      local lat, lon = known(raw:upper())
      for _, a in ipairs(lat and self.fleet or {}) do
        local dlat, dlon = a.lat and (a.lat - lat), a.lat and (a.lon - lon) * math.cos(math.rad(lat))
        if dlat and 60 * math.sqrt(dlat * dlat + dlon * dlon) <= L.navaid_range_nm then
          r.kind, r.name = "waypoint", raw:upper()
          break
        end
      end
    end
  end
end

-- "put QFA12 over ML at 6000", "create ... at BN heading 010", "direct SY", "over the CB VOR": a word of two
-- capitals (a navaid's ident: the Australian VORs ML, SY, BN, CB) in a line with lower-case letters, in a place's
-- slot (TWO_LETTER_SLOTS, "the" between at most) or before a kind of navaid, no number after it, that no ref holds
-- and no airline or reserved word is, is the navaid of that ident when, with aircraft flying, the one of that ident
-- nearest each of them that lies within lexicon.navaid_range_nm of it is one station (lexicon.navaid_station_nm) for
-- all: a waypoint ref (the callsign matcher reads three capitals or more only). Any other such word is left as it
-- was (G:unaccounted asks about it).
local TWO_LETTER_SLOTS = {
  over = true, at = true, to = true, direct = true, dct = true, via = true, after = true, before = true, from = true,
  cross = true, crossing = true, passing = true, abeam = true, overhead = true, past = true, ["until"] = true,
  till = true, reaching = true, towards = true, toward = true, add = true, ["then"] = true, of = true, by = true }
local TWO_LETTER_RESERVED = { FL = true, NM = true, VS = true, PZ = true, ON = true, OK = true, NO = true, UP = true,
  IN = true, AT = true, TO = true, OF = true, BY = true, OR = true, IF = true, IT = true, IS = true, GO = true,
  DO = true, SO = true, ME = true, MY = true, WE = true, US = true, HI = true, KT = true, FT = true, KM = true,
  AM = true, PM = true, CD = true, CR = true, LT = true, RT = true }
H.two_letter_reserved = TWO_LETTER_RESERVED
function m:two_letter_place_refs()
  local locate, lower, two = self.world.locate, false, false
  for _, t in ipairs(self.t) do
    lower = lower or (t.kind == "word" and t.raw:find("%l") ~= nil)
    two = two or (t.kind == "word" and t.raw:match("^%u%u$") ~= nil and not TWO_LETTER_RESERVED[t.raw])
  end
  if not locate or not lower or not two then return end
  local near = {}
  for _, a in ipairs(self.fleet) do
    if a.lat then near[#near + 1] = a end
  end
  if #near == 0 then return end
  local function nm(lat1, lon1, lat2, lon2)
    local dlat, dlon = lat1 - lat2, (lon1 - lon2) * math.cos(math.rad(lat2))
    return 60 * math.sqrt(dlat * dlat + dlon * dlon)
  end
  for i = 1, #self.t do
    local t, nx = self.t[i], self.t[i + 1]
    local k = self:word(i - 1, "the") and i - 2 or i - 1
    local slot = (self.t[k] and self.t[k].kind == "word" and TWO_LETTER_SLOTS[self.t[k].text])
      or self:word(i + 1, "@navaid_kinds")
    if t.kind == "word" and t.raw:match("^%u%u$") and not TWO_LETTER_RESERVED[t.raw] and slot
        and not (nx and (nx.kind == "number" or nx.number_word)) and not self:airline_at(i) then
      local held = false
      for _, r in ipairs(self.refs) do held = held or (r.b <= i and i < r.e) end
      slot = not held
      local at
      for _, a in ipairs(slot and near or {}) do
        local lat, lon = locate(t.raw, nil, a.lat, a.lon)
        if lat and nm(lat, lon, a.lat, a.lon) <= L.navaid_range_nm then
          if at and nm(lat, lon, at[1], at[2]) > L.navaid_station_nm then
            at = false
            break
          end
          at = at or { lat, lon }
        end
      end
      if at then
        local n = 1
        while self.refs[n] and self.refs[n].b < i do n = n + 1 end
        table.insert(self.refs, n, { kind = "waypoint", name = t.raw, b = i, e = i + 1, exists = false })
      end
    end
  end
end

-- The one VOR among navaids `ids` called `name`, at `at` ({lat, lon} [deg] each, as sim:navaids_named gives), when
-- there are several and they all stand within lexicon.navaid_station_nm of the first: one station ("Rodos": the NDB
-- ROS, the VOR-DME RDS and the TACAN ROD; "Castejon": the VOR-DME CJN, the NDB CTE 1.2 NM away), its name said
-- alone meaning its VOR; else nil.
function m:station_vor(name, ids, at)
  local named = self.world.navaids_named
  local station = named ~= nil and #ids > 1 and at[1] ~= nil
  for k = 2, station and #ids or 0 do
    local dlat = at[1][1] - at[k][1]
    local dlon = (at[1][2] - at[k][2]) * math.cos(math.rad(at[k][1]))
    station = station and 60 * math.sqrt(dlat * dlat + dlon * dlon) <= L.navaid_station_nm
  end
  local vor = station and named(name, at[1][1], at[1][2], L.navaid_station_nm, "VOR") or {}
  for _, id in ipairs(#vor == 1 and ids or {}) do
    if id == vor[1] then return vor end
  end
  return nil
end

-- "at 10 miles from LIMA", "position of the LIMA VOR", "direct TEBBY": a navaid said by its navdata name in
-- capitals. A one-word waypoint ref that no route or DEFWPT holds, whose ident the navdata holds nowhere
-- within lexicon.navaid_range_nm of an aircraft flying (LIMA is an airfield in Italy), and that names
-- navaids within that range of one (anywhere, with none flying), becomes the navaid's ident (LIM) for every
-- instruction that reads places; several navaids of the name are asked about, and so is a place of that
-- ident within range too, unless it lies where the navaid is (the fix LAMAR 40 NM from the LAMAR VOR, LAA:
-- which one?; with none flying, the place of that ident anywhere stays). Letters of a spelled callsign
-- ("two zero LIMA") are no name, nor is the name of a waypoint being defined ("define waypoint TANGO at ..."), nor
-- a name given to a new point or shape after its noun, "named", "called", "name" or "call it" ("create circle JEJU
-- at ...", "define waypoint named JEJU at ...": JEJU, verbatim).
function m:navaid_name_refs()
  local named, locate = self.world.navaids_named, self.world.locate
  if not named or not locate then return end
  local defining = self:word_in(1, #self.t + 1, "create define defwpt make add new draw")
  local new_object = self:word_in(1, #self.t + 1, "create define defwpt make new draw circle box polygon poly")
  -- (a waypoint defined or on a route named by a word of the phonetic alphabet: "SIERRA")
  local lettered = false
  for _, w in ipairs(self.world.waypoints or {}) do lettered = lettered or L.phonetic[w:lower()] ~= nil end
  for _, a in ipairs(self.fleet) do
    for _, w in ipairs(a.route or {}) do lettered = lettered or L.phonetic[w:lower()] ~= nil end
  end
  local near = {}
  for _, a in ipairs(self.fleet) do
    if a.lat then near[#near + 1] = a end
  end
  local flying = #near > 0
  local range = flying and L.navaid_range_nm or math.huge
  if not flying then near = { { lat = 0, lon = 0 } } end
  local function nm(lat1, lon1, lat2, lon2)
    local dlat, dlon = lat1 - lat2, (lon1 - lon2) * math.cos(math.rad(lat2))
    return 60 * math.sqrt(dlat * dlat + dlon * dlon)
  end
  for _, r in ipairs(self.refs) do
    local before = self.t[r.b - 1]
    local no_name = before and (before.kind == "number" or before.number_word or L.phonetic[before.text]
      or (defining and self:word(r.b - 1, "@waypoint_nouns"))
      or (new_object and (self:word(r.b - 1, "@named") or self:word(r.b - 1, "circle box polygon poly name")
        or (self:word(r.b - 1, "it") and self:word(r.b - 2, "call name")))))
    if r.kind == "waypoint" and not r.exists and r.e == r.b + 1 and self.t[r.b].raw == r.name and not no_name
        and not self:word(r.b, "@navaid_kinds") then
      local ids, at, seen = {}, {}, {}
      for _, a in ipairs(near) do
        local found, where = named(r.name, a.lat, a.lon, range)
        for k, id in ipairs(found) do
          if not seen[id] and id:upper() ~= r.name then
            seen[id] = true
            ids[#ids + 1] = id
            at[#ids] = where and where[k]
          end
        end
      end
      -- (the place of that ident within range of an aircraft flying, and whether a navaid of the name is there)
      local other, same = false, false
      for _, a in ipairs(#ids > 0 and near or {}) do
        local lat, lon = locate(r.name, nil, a.lat, a.lon)
        if lat and nm(lat, lon, a.lat, a.lon) <= range then
          other = true
          for k = 1, #ids do same = same or (at[k] ~= nil and nm(lat, lon, at[k][1], at[k][2]) <= 1) end
        end
      end
      -- (with no traffic, a place of that ident anywhere is the one typed)
      if other and not same and flying then
        self:need(string.format("Which place is '%s': the navaid %s of that name, or %s?", r.name,
          table.concat(ids, " or "), r.name))
      elseif #ids > 0 and not other then
        -- ("direct RODOS": several navaids of the name, all of one station, are its one VOR)
        ids = self:station_vor(r.name, ids, at) or ids
        -- ("add TANGO after SIERRA": where the scenario names its own waypoints by words of the phonetic alphabet,
        -- another such word is as likely one of them not yet defined as the navaid of that name: asked; the kind
        -- said after it, "the TANGO VOR", names the navaid)
        if L.phonetic[self.t[r.b].text] and not self:word(r.e, "@navaid_kinds") and lettered then
          return self:need(string.format("Which place is '%s': the navaid %s of that name, or a waypoint %s not yet "
            .. "defined (please give its position)?", r.name, table.concat(ids, " or "), r.name))
        end
        r.name = self:one_named(ids, "navaid", r.name, math.huge)
      end
    end
  end
end

-- Makers (lower case, "cessna") -> {designator = true} of the types squawk
-- knows, model names ("737", "a320") -> designator, and designators said
-- without their maker's letter ("738" -> B738, "319" -> A319: the digits of
-- exactly one Airbus or Boeing designator).
local MAKERS, MODELS, SHORT
local function makers()
  if MAKERS then return MAKERS, MODELS, SHORT end
  local names = require("translate.names")
  local types = require("translate.types").build(names.designators)
  MAKERS, MODELS, SHORT = types.makers, {}, {}
  for _, row in ipairs(types.types) do MODELS[row[2]] = MODELS[row[2]] or row[3] end
  for _, d in ipairs(types.designators) do
    local digits = d:match("^[AB](%d%d%d)$")
    if digits then SHORT[digits] = SHORT[digits] == nil and d or false end
  end
  return MAKERS, MODELS, SHORT
end

-- The one designator of `set` ({[designator] = true}: a maker's types) whose digits are `digits` ("738" -> B738,
-- "195" -> E195), or nil when none or several
local function designator_of_digits(digits, set)
  local found
  for d in pairs(set) do
    if d:match("^%u(%d%d%d)$") == digits then
      if found then return nil end
      found = d
    end
  end
  return found
end

-- "add a Ryanair 737, RYR81JC, ...", "a United 757, UAL1540", "a Ryanair 738, ...": an airline and a
-- model number (or a designator's digits) after an article, with a callsign said straight after, are
-- the new aircraft's airline and type, no flight number (the C++ matcher read
-- RYR737): that reference becomes a type reference to the model's designator.
function m:airline_types()
  local _, models, short = makers()
  for k, r in ipairs(self.refs) do
    local nxt = self.refs[k + 1]
    -- (with one aircraft flying the matcher may have heard "Ryanair 738" as it: inexactly, heard.id)
    local heard = r.kind == "aircraft" and (not r.exists and r.name or (r.heard and r.heard.id ~= "" and r.heard.id))
    local digits = heard and heard:match("^%a+(%d+)$")
    local ty = digits and (models[digits] or short[digits])
    if ty and self:word(r.b - 1, "@articles_new more") and nxt and nxt.kind == "aircraft"
        and nxt.b <= self:skip_fillers(r.e, false) + 1 then
      self.refs[k] = { kind = "type", name = ty, b = r.b, e = r.e }
    end
  end
end

-- Designators read as others (types.build's aliases: E175 -> E75L)
local ALIASES
local function aliases()
  ALIASES = ALIASES or require("translate.types").build(require("translate.names").designators).aliases
  return ALIASES
end

-- Families by their number ("777" -> {B772 = true, B77W = true, ...}, types.build's families); their digits are
-- said as words (lexicon.digit_words: "triple seven" is lexed as "seven seven seven").
local FAMILIES
local function families()
  FAMILIES = FAMILIES or require("translate.types").build(require("translate.names").designators).families
  return FAMILIES
end
local DIGIT_WORDS = L.digit_words
local TENS_WORDS = { twenty = "2", thirty = "3", forty = "4", fifty = "5", sixty = "6", seventy = "7", eighty = "8",
                     ninety = "9" }
-- a designator's letter said before its digits, by its maker ("the a three twenty one" is an Airbus A321)
local DESIGNATOR_LETTERS = { a = "airbus", b = "boeing", e = "embraer" }
-- words that describe an aircraft's size between "the" and its type ("the big Boeing"); they narrow
-- nothing: several aircraft of the type flying are asked about
local SIZE_WORDS = { big = true, bigger = true, biggest = true, large = true, small = true, smaller = true,
                     little = true, huge = true, tiny = true }
-- nouns after "max" that make it the adjective ("the max rate", "the max speed"), never the 737 MAX ("the max
-- climb to FL300" is the MAX told to climb)
local MAX_OF = { rate = true, speed = true, power = true, thrust = true, descent = true, level = true,
                 altitude = true, range = true, bank = true, value = true, performance = true, mach = true }

-- The token after "of" or "of the" at token k, else k: an airline and a type joined as a Spanish or Portuguese
-- speaker joins them with "de" ("the 737 of Aeromexico", "the Aeromexico of the 787": the Aeromexico 737, 787).
function m:after_of(k)
  if not self:word(k, "of") then return k end
  return self:word(k + 1, "the") and k + 2 or k + 1
end

-- The type said at token i ("777", "Boeing 777", "seven seven seven", "dash 8", "Cessna", "MAX",
-- "Dreamliner", "King Air", "A320"): (test, e) with test(designator) true for the types it names and e the token
-- after it, or nil. A family's number names each of its variants; a designator or variant names itself;
-- a maker names its types; a nickname (types.nicknames) its patterns. A nickname said straight after a type
-- narrows it to the types of both ("the 737 MAX", "the Boeing 737 MAX"); when none is both ("the B737 MAX": B737
-- is the 737-700, no MAX) it names no aircraft, never the type alone. `after_airline`: i follows an airline's
-- name, where a family's number said group-wise reads as after "the" ("the Delta seven fifty-seven").
function m:type_said(i, after_airline)
  local test, e = self:type_named(i, after_airline)
  local nick = test and self.t[e] and self.t[e].kind == "word" and require("translate.types").nicknames[self.t[e].text]
  if not nick then return test, e end
  local both = {}
  for _, set in pairs(families()) do
    for d in pairs(set) do
      for _, p in ipairs(nick) do if test(d) and d:match(p) then both[d] = true end end
    end
  end
  return function(d) return both[d] == true end, e + 1
end
function m:type_named(i, after_airline)
  local t = self.t[i]
  if not t then return nil end
  local fams = families()
  local function set_of(set) return function(d) return set[d] == true end end
  local function pattern_of(pats)
    return function(d)
      for _, p in ipairs(pats) do if d:match(p) then return true end end
      return false
    end
  end
  -- ("the dash 8": every Dash 8, the Q400 and its elders)
  if self:word(i, "dash") and self.t[i + 1] and (self.t[i + 1].text == "8" or self.t[i + 1].text == "eight") then
    return pattern_of({ "^DH8%u$" }), i + 2
  end
  if self:word(i, "dash-8 dash8") then return pattern_of({ "^DH8%u$" }), i + 1 end
  -- ("the triple seven", "the seven four seven": a family's number said digit by digit)
  local spoken = ""
  for k = i, i + 2 do spoken = spoken .. (self.t[k] and self.t[k].kind == "word" and DIGIT_WORDS[self.t[k].text] or "-") end
  if fams[spoken] then return set_of(fams[spoken]), i + 3 end
  -- ("the seven three", "the seven seven": after "the", a Boeing 7x7's or an Airbus A3xx's first two digits said
  -- in words name every designator that starts so, B73x, B77x; "the three twenty", "the seven thirty eight": a
  -- family's number, or one Airbus or Boeing designator's digits, said group-wise)
  local said = spoken:gsub("%-.*", "")
  if self:word(i - 1, "the") and #said == 2 and (said:sub(1, 1) == "7" or said:sub(1, 1) == "3") then
    return pattern_of({ "^" .. (said:sub(1, 1) == "7" and "B" or "A") .. said .. "%w$" }), i + 2
  end
  local tens = #said == 1 and (after_airline or self:word(i - 1, "the")) and self.t[i + 1]
    and TENS_WORDS[self.t[i + 1].text]
  if tens then
    local d3 = self.t[i + 2] and self.t[i + 2].kind == "word" and DIGIT_WORDS[self.t[i + 2].text]
    local num, e = said .. tens .. ((d3 and d3 ~= "0") and d3 or "0"), (d3 and d3 ~= "0") and i + 3 or i + 2
    local fam, short = fams[num] or fams["a" .. num], select(3, makers())[num]
    if fam then return set_of(fam), e end
    if short then return function(d) return d == short or aliases()[d] == short end, e end
  end
  for _, r in ipairs(self.refs) do
    if r.kind == "type" and r.b == i then
      -- ("the Boeing 777", "the A330": the family's number, its maker before it or not, is the family)
      local last = self.t[r.e - 1].text
      -- ("the Airbus 330": an Airbus family's number said without its letter)
      local family = (r.e - r.b == 1 or makers()[t.text])
        and (fams[last] or (t.text == "airbus" and r.e - r.b == 2 and fams["a" .. last]))
      -- (a designator read as another names aircraft flying under either: "the E175" is an E75L or an E175)
      return family and set_of(family) or function(d) return d == r.name or aliases()[d] == r.name end, r.e
    end
  end
  if t.kind == "number" and fams[t.text] then return set_of(fams[t.text]), i + 1 end
  -- ("the Condor B757", "the B777": a Boeing family's number typed after the maker's letter as a designator is, no
  -- designator itself, names the family; not where an aircraft flying has it for its callsign)
  local lettered = t.kind == "word" and t.text:match("^b(7%d7)$")
  if lettered and fams[lettered] and not self:state(t.raw) then return set_of(fams[lettered]), i + 1 end
  -- ("the 350", "the 321": an Airbus family's number without its letter, the whole family, when it names no
  -- callsign heard; "the 738": else the digits of one Airbus or Boeing designator, B738)
  if t.kind == "number" and self:word(i - 1, "the") and fams["a" .. t.text]
      and not self:has_ref(i, i + 1, "aircraft") then
    return set_of(fams["a" .. t.text]), i + 1
  end
  local short = select(3, makers())[t.text]
  if t.kind == "number" and short then return function(d) return d == short or aliases()[d] == short end, i + 1 end
  -- ("the 195", "the 175": after "the", the digits of one Embraer E-Jet's designator; aliases read E175 as E75L)
  local ejet = t.kind == "number" and self:word(i - 1, "the") and t.text:match("^1[4-9]%d$")
    and designator_of_digits(t.text, makers().embraer or {})
  if ejet then return function(d) return d == ejet or aliases()[ejet] == d end, i + 1 end
  if t.kind ~= "word" then return nil end
  local nicknames = require("translate.types").nicknames
  local two = self.t[i + 1] and nicknames[t.text .. " " .. self.t[i + 1].text]  -- ("the King Air")
  if two then return pattern_of(two), i + 2 end
  -- (three digits said in words from token k, "three thirty", "three twenty one", "three three zero": the
  -- number and the token after it, or nil)
  local function said_number(k)
    local function said(j) return self.t[j] and self.t[j].kind == "word" and self.t[j].text or "" end
    local d1, tens, d3 = DIGIT_WORDS[said(k)], TENS_WORDS[said(k + 1)], DIGIT_WORDS[said(k + 2)]
    if d1 and tens then
      return d1 .. tens .. ((d3 and d3 ~= "0") and d3 or "0"), (d3 and d3 ~= "0") and k + 3 or k + 2
    elseif d1 and DIGIT_WORDS[said(k + 1)] and d3 then
      return d1 .. DIGIT_WORDS[said(k + 1)] .. d3, k + 3
    end
  end
  -- ("the a three twenty one", "the b seven three eight", "the e one ninety": after "the", a designator's
  -- letter and its digits said in words name that family or designator; the letter alone names nothing)
  local letter = DESIGNATOR_LETTERS[t.text]
  if letter and self:word(i - 1, "the") then
    local num, e = said_number(i + 1)
    local fam = num and (fams[t.text .. num] or (t.text == "b" and fams[num]))
    if fam then return set_of(fam), e end
    local d = num and (t.text .. num):upper()
    if d and (makers()[letter] or {})[d] then return function(x) return x == d or aliases()[x] == d end, e end
    return nil
  end
  if makers()[t.text] then
    local nx = self.t[i + 1]
    if nx and nx.kind == "number" and fams[nx.text] then return set_of(fams[nx.text]), i + 2 end
    -- ("the Boeing 738", "the Boeing 789", "the Embraer 190": a designator's digits after its maker name that one
    -- designator of the maker's)
    local own = nx and nx.kind == "number" and designator_of_digits(nx.text, makers()[t.text])
    if own then return function(d) return d == own or aliases()[own] == d end, i + 2 end
    -- ("the Airbus three thirty", "the Boeing seven eighty seven", "the Airbus three three zero": a family's
    -- number said in words after its maker, the Airbus letter left out)
    local num, e = said_number(i + 1)
    local fam = num and (fams[num] or (t.text == "airbus" and fams["a" .. num]))
    if fam then return set_of(fam), e end
    return set_of(makers()[t.text]), i + 1
  end
  local nick = nicknames[t.text]
  if nick and t.text == "max" and (MAX_OF[self.t[i + 1] and self.t[i + 1].text or ""] or self:word(i - 2, "at to")) then
    return nil
  end
  -- (a role, "the helicopter", "the trijet": an aircraft of a type the type data does not know may be one too, so
  -- it fits as well and the words are asked about, naming both)
  local types = require("translate.types")
  if nick and types.role_words[t.text] then
    local fits = pattern_of(nick)
    return function(d) return fits(d) or not types.known_designator(d) end, i + 1
  end
  if nick then return pattern_of(nick), i + 1 end
  return nil
end

-- An aircraft named by "the" and its type, family, maker or nickname alone ("the Cessna", "the 747",
-- "the triple seven", "the dash 8", "the MAX", "the Boeing 777", "the A346"; a size word between,
-- "the big Boeing", narrows nothing), when no callsign is said in the request (an airline alone may be:
-- "the Cessna ... as the Lufthansa") and exactly one aircraft flying is of a type it names (type_said): a
-- reference to it, as in airline_refs. With several of them flying the words are kept in
-- self.type_unresolved ({b, e, ids}) and type_only asks which, naming them; with none, nothing is read.
-- A type word opening the request before an instruction with no "the" ("Cessna, heading 045", "dash 8
-- turn right 20") calls the aircraft without its registration: kept too ({..., called = true}) and asked,
-- with one aircraft of the type flying as well. A type said after "a"/"an" ("create a 747") is a new aircraft's type, never a reference.
-- ("the A321 IndiGo", "the 737 Ryanair"): an airline said straight after a type, after "the", narrows the type's
-- aircraft `fits` (ids) to that airline's and the words to [i, the airline's end): returns those ids and that end,
-- the airline's own reference (airline_refs) taken out; none of the airline's fits is asked about, naming both
-- words (the airline alone is never read as some other aircraft of it). Without an airline, `fits` and `e` as given.
local function airline_after_type(self, fits, i, e)
  local icao, ae, codes = self:airline_at(self:after_of(e))
  if not icao or (self.t[ae] and (self.t[ae].kind == "number" or self.t[ae].number_word)) then return fits, e end
  local of = {}
  for _, id in ipairs(self:airline_fleet(icao, codes)) do of[id] = true end
  local both = {}
  for _, id in ipairs(fits) do
    if of[id] then both[#both + 1] = id end
  end
  for n = #self.refs, 1, -1 do
    local r = self.refs[n]
    if r.b >= e and r.e <= ae and r.by_airline then table.remove(self.refs, n) end
  end
  if #both == 0 then
    self:need(string.format("Which aircraft is '%s'? Please give its callsign.", self:raw(i, ae)))
  end
  return both, ae
end

function m:type_refs()
  -- ("the Pilatus N48TX", "the Baron N218PK": a type, maker or family said between "the" and the callsign of
  -- a flying aircraft of that type describes it)
  for _, r in ipairs(self.refs) do
    local k = r.b - 1
    if r.kind == "aircraft" and r.exists and self:word(k - 1, "the") and self.t[k].kind == "word" then
      local ty
      for _, a in ipairs(self.fleet) do if a.id == r.name then ty = a.type and a.type:upper() end end
      local of = false
      for _, p in ipairs(ty and require("translate.types").nicknames[self.t[k].text] or {}) do
        of = of or ty:match(p) ~= nil
      end
      for _, t in ipairs(self:refs_in(k, k + 1, "type")) do of = of or t.name == ty end
      if ty and (of or (makers()[self.t[k].text] or {})[ty]) then self:explain(k, k + 1) end
    end
  end
  -- ("the triple seven, descend ..." with GLO1077 and one B77W flying): a family's number said after "the", no
  -- airline with it, heard only as a slip for a callsign, is the type described when exactly one aircraft
  -- flying is of that family (else the callsign heard stays, asked about)
  for n = #self.refs, 1, -1 do
    local r, test, e = self.refs[n], nil, nil
    local h = r.kind == "aircraft" and r.heard
    if h and h.airline == 0 and self:word(r.b - 1, "the") and not self:airline_and_digits_match(h.id, r.name) then
      test, e = self:type_said(r.b)
    end
    if test and e >= r.e then
      local fits = 0
      for _, a in ipairs(self.fleet) do
        if a.type and test(a.type:upper()) then fits = fits + 1 end
      end
      if fits == 1 then table.remove(self.refs, n) end
    end
  end
  -- (with a callsign said in the request, a type names an aircraft only after "the" opening a clause, an
  -- instruction word straight after it, when it fits one aircraft no callsign names: "AFR1234 turn right 20,
  -- and the 777 turn right 20 as well")
  local named = {}
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" and not r.by_airline then named[r.name] = true end
  end
  local callsigns = next(named) ~= nil
  -- ("KLM12, the dreamliner needs to climb FL300", "KLM12 the 777 climb FL300", "KLM12, sorry, the Boeing, descend": a
  -- type said after "the" straight after a callsign, commas and a correction's words between at most, that the callsign's aircraft is not of while
  -- another aircraft flying is, leaves open which of them is meant: asked. One it fits is in apposition ("KLM12, the
  -- A320, climb"); traffic told after it ("KLM12, the 777 is above you") is left to read.)
  for _, r in ipairs(callsigns and self.refs or {}) do
    -- (a correction's word between: "KLM12, sorry, the dreamliner needs to ...")
    local k = r.e
    while k < r.e + 5 and self.t[k] and (self.t[k].text == "," or self:word(k, "sorry no correction i mean rather")) do
      k = k + 1
    end
    if r.kind == "aircraft" and r.exists and not r.by_airline and not r.by_description and self:word(k, "the") then
      local test, e = self:type_said(k + 1)
      local own
      for _, a in ipairs(self.fleet) do if a.id == r.name then own = a.type and a.type:upper() end end
      if test and own and not test(own) and not self:word(e, "is are was were 's at above below ahead behind in on "
          .. "passing near close and or") then
        local fits = {}
        for _, a in ipairs(self.fleet) do
          if a.type and a.id ~= r.name and test(a.type:upper()) then fits[#fits + 1] = a.id end
        end
        if #fits > 0 then
          return self:need(string.format("Which aircraft do you mean: %s (%s) or '%s' (%s)? Please give its callsign.",
            r.name, own, self:raw(k, e), table.concat(fits, ", ")))
        end
      end
    end
  end
  local i = 1
  local last = self:said("the") and #self.t or math.min(#self.t, 1)  -- (a type is read after "the" or opening)
  while i <= last do
    local b = i
    local the = self:word(i - 1, "the")
    if not the and SIZE_WORDS[self.t[i - 1] and self.t[i - 1].text or ""] and self:word(i - 2, "the") then
      b, the = i - 1, true
    end
    local opening = i == 1 and self.t[i].kind == "word"
    local test, e
    if the or opening then test, e = self:type_said(i) end
    if not test then
      i = i + 1  -- (no type said at i)
      goto next_token
    end
    -- (a type opening the request addresses its aircraft only when words or a comma follow it, never a
    -- number, "Cessna 172 ...", a type said with its model, or an article; "dash" opening a request
    -- without its 8 is the English word, "the dash" the Dash 8)
    if test and opening and not the then
      local nx = self.t[e]
      if not nx or nx.kind == "number" or nx.number_word or self:word(e, "a an") or (self:word(i, "dash") and e == i + 1) then
        test = nil
      end
    end
    local k = the and b - 1 or b
    if test and self:other_traffic_before(k - 1) and not self:recipient_to(k - 1) then
      test = nil
    end
    local fits = {}
    for _, a in ipairs(test and self.fleet or {}) do
      if a.type and test(a.type:upper()) then fits[#fits + 1] = a.id end
    end
    if test and the then fits, e = airline_after_type(self, fits, i, e) end
    if callsigns and test then
      local opens = the and (k == 1 or self.t[k - 1].kind == "punct" or self:word(k - 1, "and @then_words"))
      -- (one aircraft no callsign names, said so opening a clause with a modal straight after, "and the A321 may be
      -- turned left", "the 737 should descend", is asked about: the clause's instructions are never left to the
      -- aircraft before; "the 777 is above" describes traffic)
      local after = self:skip_fillers(e, false)
      local said = self:intent_at(after)
      if opens and #fits == 1 and not named[fits[1]] and not said and self:word(after, "@own_modals")
          and not self:in_reason(i) then
        self:need(string.format("Is '%s' %s? Please give its callsign.", self:raw(i, e), fits[1]))
      end
      -- ("AIC543 descend FL90 and the Boeing also", "..., same for the Airbus"): a type or maker said in the
      -- shape of G:same_span names the one aircraft of it flying that no callsign names; several, none or only
      -- the one named already are asked about
      local same = the and self:same_span(i, e)
      local one = #fits == 1 and not named[fits[1]]
      if same and #fits > 1 then
        self:need(string.format("Which %s do you mean: %s? Please give its callsign.", self:raw(i, e),
          table.concat(fits, " or ")))
      elseif same and not one then
        self:need(string.format("Which aircraft is '%s'? No other aircraft flying is of it; please give its callsign.",
          self:raw(i, e)))
      end
      if not ((opens and said or same) and one) then test, fits = nil, {} end
    end
    -- ("the CRJ": a family in capitals the lexer took for an unknown place)
    if #fits == 1 then
      for n = #self.refs, 1, -1 do
        local r = self.refs[n]
        if r.kind == "waypoint" and not r.exists and r.b == i and r.e == e then table.remove(self.refs, n) end
      end
    end
    -- (a type word opening the request with no "the", "Cirrus, descend ...", calls the aircraft by its type
    -- with no registration, as an airline said without its flight number: asked, the one that fits too)
    local called = test and opening and not the
    if (#fits > 1 or (called and #fits == 1)) and not self:in_reason(i) then
      self.type_unresolved = self.type_unresolved or {}
      table.insert(self.type_unresolved, { b = b, e = e, ids = fits, called = called })
    end
    local read = #fits == 1 and not called
    -- ("the Embraer one": "one" after the type, no number or letter after it, is the pronoun, part of the words)
    local nx = self.t[e + 1]
    if read and the and self:word(e, "one") and not (nx and (nx.kind == "number" or nx.number_word
        or L.phonetic[nx.text] or self:word(e + 1, "heavy super"))) then
      e = e + 1
    end
    if read then  -- (its numbers too: "where's the 777")
      self:explain(b, e)
      self:mark_used(i, e)
    end
    i = read and self:insert_ref(fits, i, e, "by_type") or i + 1
    ::next_token::
  end
end

-- True when "to" at k names who receives what a verb of lexicon.recipient_verbs gives, said before it in its
-- sentence ("give Vienna as destination to the Ryanair and to the Embraer", "assign FL200 to the Airbus"): the
-- aircraft after it is instructed, never a place or traffic.
function m:recipient_to(k)
  if not self:word(k, "to") then return false end
  for x = k - 1, 1, -1 do
    local t = self.t[x]
    if t.kind == "punct" and t.text ~= "," then return false end
    if self:word(x, "@recipient_verbs") then return true end
  end
  return false
end

-- A type said alone that several aircraft flying are of (type_refs): the question names them.
function m:type_only(s)
  for _, u in ipairs(self.type_unresolved or {}) do
    if u.b < s.e and u.called and #u.ids == 1 then
      return self:need(string.format("Which aircraft is '%s'? Please give its callsign (or its registration's "
        .. "last three characters after its type).", self:raw(u.b, u.e)))
    end
    if u.b < s.e then
      return self:need(string.format("Which %s do you mean: %s? Please give its callsign.", self:raw(u.b, u.e),
        table.concat(u.ids, " or ")))
    end
  end
end

-- The group of aircraft flying that the words at k name for a comparison (described_refs): its ids in the
-- fleet's order, the token after the words and the count said before them ("the two Boeings": 2), or nil. Every
-- aircraft flying (lexicon.group_nouns and aircraft_nouns, "one"), a maker's ("Boeing", "Boeings", "Airbuses") or
-- a type's (type_said: "737", "A320"), or an airline's ("KLM", "KLMs"); an aircraft noun after a maker, type or
-- airline is part of it ("the highest KLM aircraft").
local function compared_group(self, k)
  local count = COUNTS[self.t[k] and self.t[k].text or ""]
  if count then k = k + 1 end
  local t = self.t[k]
  if not t or (t.kind ~= "word" and t.kind ~= "number") then return nil end  -- ("the eastbound 737")
  local function fleet_where(fits)
    local out = {}
    for _, a in ipairs(self.fleet) do
      if fits(a) then out[#out + 1] = a.id end
    end
    return out
  end
  local function noun_after(e) return self:word(e, "@aircraft_nouns @group_nouns") and e + 1 or e end
  if self:word(k, "@aircraft_nouns @group_nouns one") then
    return fleet_where(function() return true end), k + 1, count
  end
  if not AIRLINE_NAMES then airline_names() end
  for _, stem in ipairs({ t.text:sub(1, -2), t.text:sub(1, -3) }) do  -- ("Boeings", "Airbuses", "KLMs")
    local made = t.text:sub(-1) == "s" and makers()[stem]
    if made then return fleet_where(function(a) return a.type ~= nil and made[a.type:upper()] == true end), noun_after(k + 1), count end
    local icao = t.text:sub(-1) == "s" and AIRLINE_NAMES[stem]
    if icao then return self:airline_fleet(icao, BRANDS[stem]), noun_after(k + 1), count end
  end
  local test, e = self:type_said(k)
  if test and self:word(e, "s") then e = e + 1 end  -- ("the two 737s", said "737 s")
  if test then return fleet_where(function(a) return a.type ~= nil and test(a.type:upper()) end), noun_after(e), count end
  -- ("the two A320s": a family or designator with its plural's "s")
  local stem = t.text:match("^(%w+%d)s$")
  local family = stem and (families()[stem] or families()[stem:sub(2)])
  if family then
    return fleet_where(function(a) return a.type ~= nil and family[a.type:upper()] == true end), noun_after(k + 1), count
  end
  local icao, ae, codes = self:airline_at(k)
  if icao then return self:airline_fleet(icao, codes), noun_after(ae), count end
  return nil
end

-- The aircraft flying of the maker or type said in the plural at token k ("Boeings", "Airbuses", "Embraers",
-- "737s", "A320s", "737 s") and the token after the words; nil for any other words there (an airline's plural,
-- "aircraft", "planes")
function m:type_plural(k)
  local t = self.t[k]
  if not t or (t.text:sub(-1) ~= "s" and not self:word(k + 1, "s")) then return nil end
  if not AIRLINE_NAMES then airline_names() end
  if self:word(k, "@aircraft_nouns @group_nouns one") or AIRLINE_NAMES[t.text:sub(1, -2)]
      or AIRLINE_NAMES[t.text:sub(1, -3)] or self:airline_at(k) then
    return nil
  end
  local ids, e = compared_group(self, k)
  return ids, e
end

-- The words [b, e) that describe aircraft flying (described_refs, bearing_refs), `ids` the group they were picked
-- from and `picked` those that fit: the picked aircraft are references (kind "aircraft", by_description = true) in
-- place of any heard in the words, which are explained; none picked is asked about, naming the group. With
-- aircraft named by callsign elsewhere in the request, the words describe one of them ("turn ACA881 180, it's
-- the one at FL370": explained, no second reference; one not named is asked about, never added). Returns e.
local function describe(self, b, e, ids, picked, outer)
  local named, others = {}, false
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" and r.exists and not r.by_description and (r.b >= e or r.e <= b) then
      named[r.name], others = true, true
    end
  end
  -- (a description opening a clause of its own with an instruction straight after it, "could the one at the
  -- bottom of the screen climb to FL250, and also the Copa to FL230", names the aircraft it picks, named or not)
  local k = b - 1
  if self:word(k, "could can would will please") and (k == 1 or self.t[k - 1].kind == "punct") then k = k - 1 end
  if self:word(k, "also") then k = k - 1 end
  local after = self:skip_fillers(e, false)
  local own = (k < 1 or self.t[k].kind == "punct" or self:word(k, "and @then_words"))
    and self.t[after] ~= nil and self.t[after].kind ~= "punct" and self:intent_at(after) ~= nil
  -- (never in apposition to an aircraft named before it that has no instruction yet: "DAL1960, the one at the
  -- bottom, climb FL260" is one aircraft)
  for _, r in ipairs(own and self.refs or {}) do
    if r.kind == "aircraft" and r.e <= b then
      local told = false
      for x = r.e, b - 1 do told = told or self:intent_at(x) ~= nil end
      own = own and told
    end
  end
  for _, id in ipairs(others and not own and picked or {}) do
    if not named[id] then picked = nil break end
  end
  if not (picked and #picked > 0) then
    self:need(string.format("Which aircraft do you mean by '%s'? Please give its callsign%s.", self:raw(b, e),
      ids and #ids > 0 and (" (it may be " .. table.concat(ids, ", ") .. ")") or ""))
    return e
  end
  if outer then  -- (the group picked from, "of the two A320s,", names no aircraft itself)
    for n = #self.refs, 1, -1 do
      if self.refs[n].b >= outer.b and self.refs[n].e <= outer.e then table.remove(self.refs, n) end
    end
    self:explain(outer.b, outer.e)
    self:mark_used(outer.b, outer.e)
  end
  if not others or own then
    for n = #self.refs, 1, -1 do
      if self.refs[n].b >= b and self.refs[n].e <= e then table.remove(self.refs, n) end
    end
    -- (an airline said inside the words, "the Aer Lingus heading west" with two flying, is picked from: no longer
    -- asked which)
    local unresolved = self.airline_unresolved or {}
    for n = #unresolved, 1, -1 do
      if unresolved[n].b >= b and unresolved[n].e <= e then table.remove(unresolved, n) end
    end
    local at = 1
    while self.refs[at] and self.refs[at].b < b do at = at + 1 end
    for n, id in ipairs(picked) do
      table.insert(self.refs, at + n - 1, { kind = "aircraft", name = id, b = b, e = e, exists = true, by_description = true })
    end
  end
  self:explain(b, e)
  self:mark_used(b, e)
  return e
end

-- True when the token at k is a comma or a colon.
local function clause_mark(self, k) return self.t[k] ~= nil and (self.t[k].text == "," or self.t[k].text == ":") end

-- The ids of `ids` that are in `group` too, in their order.
local function within(ids, group)
  local set, out = {}, {}
  for _, id in ipairs(group) do set[id] = true end
  for _, id in ipairs(ids) do
    if set[id] then out[#out + 1] = id end
  end
  return out
end

-- The group said before the words at b, in their sentence, that they pick from: "of the two A320s" or "the two
-- 737s" (a count needed after "the") opening a clause and ending at a comma or colon, "please" or fillers before
-- it ("Of the two KLM aircraft, the higher one ...", "The two 737s please: the eastbound one ..."). Its ids
-- (compared_group), the count said and its words' span {b, e}, or nil.
local function outer_group(self, b)
  local o = b - 1
  while o >= 1 and not (self.t[o].kind == "punct" and not clause_mark(self, o)) do
    local opens = o == 1 or self.t[o - 1].kind == "punct" or self:word(o - 1, "and")
    local k = self:word(o, "of") and (self:word(o + 1, "the") and o + 2 or o + 1)
      or self:word(o, "the") and COUNTS[self.words[o + 1] or ""] and o + 1
    local ids, e, count
    if opens and k then ids, e, count = compared_group(self, k) end
    local x = e
    while x and x < b and (self.t[x].filler or self:word(x, "please")) do x = x + 1 end
    if x and x < b and clause_mark(self, x) then return ids, count, { b = o, e = x + 1 } end
    o = o - 1
  end
end

-- The aircraft flying described after "the" by how it compares with others or by its level: a word of
-- lexicon.compared_measures over a group (compared_group: "the highest aircraft", "the lowest one", "the slowest
-- of the aircraft", "the fastest Boeing", "the faster of the two Boeings", "the higher of the two Airbuses"), or
-- an aircraft noun and "at" a level ("the aircraft at flight level 230", "the two aircraft at FL250"). A
-- comparative needs "of" and two or more in its group; a count said ("the two Boeings", "both") must be the
-- group's size; the aircraft picked must lead the next by more than lexicon.compared_margin; a level's aircraft
-- fly within 100 ft of it, as many as were counted (one unless said). The aircraft that fit are references
-- (kind "aircraft", by_description = true) in place of any heard in the words, which are explained; otherwise
-- the words are asked about, naming the aircraft of the group. Said after a word of other traffic ("behind the
-- slowest aircraft") they describe no aircraft instructed. Size words never compare (SIZE_WORDS).
function m:described_refs()
  if not self:said("the") then return end  -- (every description opens with "the")
  local function by_id(id)
    for _, a in ipairs(self.fleet) do
      if a.id == id then return a end
    end
  end
  local i = 2
  while i <= #self.t do
    local b, measure = i - 1, self.t[i].kind == "word" and L.compared_measures[self.t[i].text]
    -- ("the slow one": a plain word of lexicon.compared_plain before "one" or an aircraft noun, by a clear lead;
    -- never "of" a group after it, "the slow one of the stream", nor in a request that creates, where it
    -- describes the new aircraft)
    local plain = not measure and self.t[i].kind == "word" and L.compared_plain[self.t[i].text]
      and self:word(i + 1, "one @aircraft_nouns") and not self:word(i + 2, "of")
      and not self:said("@creation_verbs") and L.compared_plain[self.t[i].text]
    measure = measure or plain
    local the = self:word(b, "the") and not self:other_traffic_before(b - 1) and not (self.positioned or {})[b]
    local ids, e, count, picked, outer
    if the and measure then
      if self:word(i + 1, "of") then
        local k = self:word(i + 2, "the both") and i + 3 or i + 2
        ids, e, count = compared_group(self, k)
        if self:word(i + 2, "both") then count = 2 end
      elseif not self.t[i].text:match("er$") then
        ids, e, count = compared_group(self, i + 1)
      else
        -- ("the higher Loganair", "the slower 737": a comparative straight before a group of exactly two flying)
        local two, te, tc = compared_group(self, i + 1)
        if two and #two == 2 and not tc then ids, e = two, te end
      end
      -- ("of the two A320s, ... the lower one": the group said before; "the lowest, climb ...": every aircraft)
      local o_ids, o_count
      if not self:word(i + 1, "of") then o_ids, o_count, outer = outer_group(self, b) end
      if o_ids then
        ids, count = ids and within(ids, o_ids) or o_ids, o_count
        e = e or (self:word(i + 1, "one") and i + 2 or i + 1)
      elseif not ids and not self.t[i].text:match("er$") and clause_mark(self, i + 1) then
        ids, e = {}, i + 1
        for _, a in ipairs(self.fleet) do ids[#ids + 1] = a.id end
      end
      local field, sign, values = measure[1], measure[2], {}
      for _, id in ipairs(ids or {}) do
        local a = by_id(id)
        if a and a[field] then values[#values + 1] = { id = id, v = sign * a[field] } end
      end
      table.sort(values, function(x, y) return x.v > y.v end)
      if ids and #values == #ids and #ids >= (self.t[i].text:match("er$") and 2 or 1) and (not count or count == #ids)
          and (not values[2] or (plain and values[1].v - values[2].v >= L.compared_plain_margin[field])
            or (not plain and values[1].v - values[2].v > L.compared_margin[field])) then
        picked = { values[1].id }
      end
      -- (a plain word that picks no one is left as said: "He is the fast one in this scenario" is a remark)
      if plain and not picked then ids, e = nil, nil end
    elseif the and self:head_on_at(COUNTS[self.t[i].text] == 2 and i + 1 or i) then
      -- ("the two head-on ones", "the head-on pair", "the two head-on aircraft": the pair flying head-on,
      -- m:head_on_pairs; a count of two or a plural noun or "pair" after the words)
      local two = COUNTS[self.t[i].text] == 2
      local k = self:head_on_at(two and i + 1 or i)
      local noun = self:word(k, "ones pair planes aircraft jets flights traffic")
      if noun or two then
        local pairs = self:head_on_pairs()
        ids, e, count, picked = {}, noun and k + 1 or k, 2, nil
        for _, pr in ipairs(pairs) do ids[#ids + 1], ids[#ids + 2] = pr[1], pr[2] end
        if #pairs == 1 then picked = ids end
        if #ids == 0 then ids = nil end
      end
    elseif the then
      -- ("the aircraft at flight level 230", "the two aircraft at FL250": a count, an aircraft noun, "at" a level)
      local k = COUNTS[self.t[i].text] and i + 1 or i
      local q = self:word(k, "@aircraft_nouns @group_nouns one") and self:word(k + 1, "at") and self:quantities(k + 2, k + 6)[1]
      if q and q.b == k + 2 and q.kind == "alt" and not self:word(k, "them all") then
        local ft = q.value  -- (ft, a flight level too)
        ids, e, count, picked = {}, q.e, COUNTS[self.t[i].text] or 1, {}
        for _, a in ipairs(self.fleet) do
          if a.alt_ft and math.abs(a.alt_ft - ft) <= 100 then ids[#ids + 1] = a.id end
        end
        if #ids == count then picked = ids end
        if #ids == 0 then ids = nil end
      end
    end
    i = e and describe(self, b, e, ids, picked, outer) or i + 1
  end
end

-- The aircraft flying described after "the" by its airline's country (lexicon.airline_countries): the adjective,
-- then a type ("the Danish ATR", "the Chilean Dreamliner"), "one" or an aircraft noun ("the German one", "the
-- Irish aircraft"), or nothing before a clause's end, a modal or an instruction ("could the Danish turn right").
-- The words are a description (describe) when the adjective is no airline's name ("the Norwegian" is read by
-- airline_refs): exactly one aircraft of that country (and type) is the aircraft meant when every aircraft flying
-- has a country (an airline of lexicon.airline_countries, a registration of registration_countries); several, none,
-- or an aircraft flying whose country is not known (it could be the one meant) are asked about, "one" included
-- (never the digit of a callsign: "the German one" with XYZ1 flying). Said after a word of other traffic ("behind the Dutch one") or
-- a place relative to it ("clear of", "ahead of", "in front of", "abeam of", "in the wake of the Irish one") they name
-- no aircraft instructed.
function m:nationality_refs()
  if not self:said("the") then return end
  local countries = L.airline_countries
  local function country_fits(id, adj)
    local prefix = id:upper():match("^(%u%u%u)%d")
    if prefix then
      local known = false
      for c, codes in pairs(countries) do
        for _, code in ipairs(codes) do
          if code == prefix then
            known = true
            if c == adj then return true end
          end
        end
      end
      if known then return false end
      return nil
    end
    local mark = id:upper():match("^N%d") and "N"
    for n = 2, 1, -1 do mark = mark or (L.registration_countries[id:upper():sub(1, n)] and id:upper():sub(1, n)) end
    if not mark then return nil end
    return L.registration_countries[mark] == adj
  end
  local i = 2
  while i <= #self.t do
    local adj = self.t[i].kind == "word" and countries[self.t[i].text] and self.t[i].text
    local e
    if adj and self:word(i - 1, "the") and not self:other_traffic_before(i - 2) and not self:has_ref(i, i + 1)
        and not (self:word(i - 2, "of") and self:word(i - 3, "clear ahead front abeam wake"))
        and not self:airline_at(i) and not (self.positioned or {})[i - 1] then
      local ids, known = {}, true
      for _, a in ipairs(self.fleet) do
        local fits = country_fits(a.id, adj)
        if fits == nil then known = false end
        if fits then ids[#ids + 1] = a.id end
      end
      local x = i + 1
      local test, te = self:type_said(x)
      if test and not self:has_ref(x, te, "aircraft") then
        local typed = {}
        for _, a in ipairs(self.fleet) do
          for _, id in ipairs(ids) do
            if id == a.id and a.type and test(a.type:upper()) then typed[#typed + 1] = id end
          end
        end
        ids, x = typed, te
      end
      local noun = x > i + 1
      if self:word(x, "one @aircraft_nouns") and not (self.t[x + 1] and (self.t[x + 1].kind == "number"
          or self.t[x + 1].number_word)) then
        x, noun = x + 1, true
      end
      local nx = self.t[x]
      if noun or not nx or nx.kind == "punct" or self:word(x, "could should ought can will would must may shall to "
          .. "please") or self:intent_at(x) then
        -- (with an aircraft flying of no known country, the one of `ids` named elsewhere in the request is the one
        -- described: "the German one, the Lufthansa, heading 120")
        local named = {}
        for _, r in ipairs(known and {} or self.refs) do
          for _, id in ipairs(ids) do
            if r.kind == "aircraft" and r.exists and r.name == id and (r.b >= x or r.e < i) then named[id] = true end
          end
        end
        local picked = known and ids or {}
        for _, id in ipairs(known and {} or ids) do
          if named[id] then picked[#picked + 1] = id end
        end
        e = describe(self, i - 1, x, ids, #picked == 1 and picked or nil)
      end
    end
    i = e or i + 1
  end
end

-- The token after "head-on" said at k (the lexer splits it: "head on"), or nil.
function m:head_on_at(k)
  if self:word(k, "head-on") then return k + 1 end
  if self:word(k, "head") and self:word(k + 1, "on") then return k + 2 end
end

-- The pairs of aircraft flying head-on ({id, id} in the fleet's order): headings within lexicon.head_on_deg of
-- opposite, each pointing at the other (the bearing to the other within head_on_deg of its heading), and less
-- than lexicon.head_on_ft apart in level (opposite tracks 2000 ft apart are no head-on pair).
function m:head_on_pairs()
  local out, tol = {}, L.head_on_deg
  local function off(a, b) return math.abs((a - b + 540) % 360 - 180) end
  local function bearing(a, b)
    local dlat, dlon = b.lat - a.lat, (b.lon - a.lon) * math.cos(math.rad((a.lat + b.lat) / 2))
    return math.deg(math.atan(dlon, dlat)) % 360
  end
  local fleet = self.fleet
  for x = 1, #fleet do
    for y = x + 1, #fleet do
      local a, b = fleet[x], fleet[y]
      if a.lat and b.lat and a.hdg_deg and b.hdg_deg and off(a.hdg_deg, (b.hdg_deg + 180) % 360) <= tol
          and off(bearing(a, b), a.hdg_deg) <= tol and off(bearing(b, a), b.hdg_deg) <= tol
          and a.alt_ft and b.alt_ft and math.abs(a.alt_ft - b.alt_ft) < L.head_on_ft then
        out[#out + 1] = { a.id, b.id }
      end
    end
  end
  return out
end

-- The compass point said from token k: one word ("south", "southwest"), two or three with or without hyphens
-- between ("south-east", "north north-east"); its degrees (0 for north) and the token after it, or nil.
function m:point_said(k)
  local words, last = {}, nil
  while #words < 3 and self.t[k] and (self.t[k].text == "-" and #words > 0 or L.compass[self.t[k].text]) do
    if self.t[k].text ~= "-" then words[#words + 1], last = self.t[k].text, k end
    k = k + 1
  end
  if not last then return nil end
  -- (the longest run of words that names a point: "south east" 135, "west" alone before "north" of another)
  for n = #words, 1, -1 do
    local deg = compass(words[1], words[2] and n >= 2 and words[2] or nil, n >= 3 and words[3] or nil)
    if deg then
      local e = last + 1
      for _ = n + 1, #words do
        repeat e = e - 1 until self.t[e].text ~= "-"
      end
      return deg % 360, e
    end
  end
end

-- The aircraft of `ids` (in the fleet's order) heading toward the compass point `point` [deg], as bearing_refs
-- reads "the one heading north": those whose heading lies less than lexicon.bearing_margin from a cardinal point
-- (22.5 degrees from an intercardinal, 11.25 from a point between); another of them near the sector's edge, within
-- half the margin beyond it and at most lexicon.bearing_margin from the point, may be the one meant ("heading
-- southwest" with one on 225 and one on 250: both fit; one on 190 is south).
local function heading_toward(self, ids, point)
  local margin = L.bearing_margin / (point % 90 == 0 and 1 or point % 45 == 0 and 2 or 4)
  local band = math.min(1.5 * margin, L.bearing_margin)
  local set, fits, near = {}, {}, {}
  for _, id in ipairs(ids) do set[id] = true end
  for _, a in ipairs(self.fleet) do
    local off = set[a.id] and a.hdg_deg and math.abs((a.hdg_deg - point + 540) % 360 - 180)
    if off and off < margin then fits[#fits + 1] = a.id end
    if off and off < band then near[#near + 1] = a.id end
  end
  if #fits == 1 and #near > 1 then return near end
  return fits
end

-- The place gone to from token k ("go to X", "fly to X": rules.lua) when it is no airport: "the" perhaps, then a
-- waypoint reference that is no four-letter code (a fix, a navaid's ident, a waypoint the simulation defined), or
-- one or two capitalised words and a navaid's noun ("the Caselle VOR", "Saronno NDB"). The token after it, or nil
-- (always in a request ending with a question mark).
function m:place_gone_to(k)
  -- (a question, "does the Ryanair go to GATE2?", is no instruction to go there)
  if self.t[#self.t] and self.t[#self.t].text == "?" then return nil end
  if self:word(k, "the") then k = k + 1 end
  local r = self:refs_in(k, k + 1, "waypoint")[1]
  if r and r.b == k then
    -- (a navaid on an airport that bears its code, "JFK", "YYZ", or a large airport's IATA code: the airport's)
    local w, name = self.world, r.name:upper()
    local lat, lon = nil, nil
    if w.locate then lat, lon = w.locate(name) end
    local coded = #name == 3 and ((require("translate.names").iata_airports or {})[name]
      or lat and lon and w.airports_coded and #w.airports_coded(name, lat, lon) > 0)
    if name:match("^%a%a%a%a$") or coded then return nil end
    if self:word(r.e, "at") then return nil end  -- ("go to EXP1 at FL120": the waypoint's constraint, ADDWPT)
    return r.e
  end
  local e = k
  while e < k + 2 and self.t[e] and self.t[e].kind == "word" and self.t[e].alpha and self.t[e].raw:match("^%u%l")
      and not self:has_ref(e, e + 1, "aircraft") do
    e = e + 1
  end
  if e > k and self:word(e, "vor ndb vortac") then return e + 1 end
  return nil
end

-- True when the token at k is "that" or "which" of "that's"/"which's" before a verb of going or coming (the
-- lexer drops "'s": "the Airbus that's heading east" is read "that heading").
function m:relative_is(k)
  return self:word(k, "that which") and self:word(k + 1, "@compass_verbs @compass_from_verbs @compass_relative_verbs")
end

-- The way an aircraft flies, said from token v (bearing_refs, position_refs): a verb of going (lexicon.compass_verbs),
-- its particles, perhaps "to" or "towards" (and "the"), and a compass point ("flying south-east", "heading out
-- west", "going out to the west", "flying to south-east"), or "-ward(s)" on a point ("flying southward"); or a verb
-- of coming (lexicon.compass_from_verbs), "from" (and "the") and the point it flies away from ("coming from the
-- east": flying west, 270). Its heading's point [deg] and the token after the words, or nil.
function m:way_said(v)
  local from = self:word(v, "@compass_from_verbs") and self:word(v + 1, "from")
  if not (from or self:word(v, "@compass_verbs")
      or self:word(v, "@compass_relative_verbs") and self:word(v - 1, "that which")) then return nil end
  local k = from and v + 2 or v + 1
  while not from and k < v + 3 and self:word(k, "@compass_particles") do k = k + 1 end
  if not from and self:word(k, "to towards") then k = k + 1 end
  if k > v + 1 and self:word(k, "the") then k = k + 1 end
  local point, e = self:point_said(k)
  local stem = not point and self.words[k] and self.words[k]:match("^(%a+)wards?$")
  if stem and L.compass[stem] then point, e = L.compass[stem], k + 1 end
  if point and from then point = (point + 180) % 360 end
  return point, e
end

-- The aircraft flying described after "the" by the way it flies: a group (compared_group: "one", "aircraft", a
-- type, an airline) and a verb of going (lexicon.compass_verbs, "that is" or "which is" before it) with a compass
-- point ("the one heading north", "the Embraer flying south-east", "the aircraft that is going west"), or a
-- "-bound" word before the group ("the eastbound 737", "the westbound one"). The aircraft of the group whose
-- heading lies less than lexicon.bearing_margin degrees from the point fit (half that for an intercardinal point, a
-- quarter between): exactly one, with no other of the group within one and a half times that (at most
-- bearing_margin), is the aircraft described (describe), none or several are asked about. The words are never a heading instructed.
function m:bearing_refs()
  if not self:said("the") then return end  -- (every description opens with "the")
  local bound = false  -- (no verb of going and no "-bound" word: nothing to read)
  local words = self.words
  for k = 1, #words do
    local w = words[k]
    if w and w:sub(-5) == "bound" then
      bound = true
      break
    end
  end
  if not (bound or self:said("@compass_verbs") or self:said("@compass_from_verbs")
      or self:said("@compass_relative_verbs")) then return end
  local i = 1
  while i <= #self.t do
    local b, ids, e, point = i, nil, nil, nil
    if self:word(i, "the") and not self:other_traffic_before(i - 1) and not (self.positioned or {})[i] then
      local bound = self.t[i + 1] and self.t[i + 1].kind == "word" and self.t[i + 1].text:match("^(%a+)bound$")
      if bound and L.compass[bound] then
        ids, e = compared_group(self, i + 2)
        point = e and L.compass[bound]
      else
        ids, e = compared_group(self, i + 1)
        local v = e and (self:word(e, "that which") and self:word(e + 1, "is") and e + 2
          or self:relative_is(e) and e + 1 or e)
        if v then point, e = self:way_said(v) end
        e = point and e
      end
    end
    local o_ids, _, outer = nil, nil, nil
    if point and e then o_ids, _, outer = outer_group(self, b) end
    if o_ids then ids = within(ids, o_ids) end  -- ("of the two Air France, the one heading west")
    if point and e then
      local fits = heading_toward(self, ids, point)
      local picked = #fits == 1 and fits or nil
      -- ("Could the jumbo climb to FL340? It's the one going east, I think.": said after "it's"/"that's" with no
      -- instruction after it, the words describe the aircraft named elsewhere; several fitting, of which exactly
      -- that one is named, it is the one meant)
      local remark = self:word(b - 1, "it that") or (self:word(b - 1, "is") and self:word(b - 2, "it that"))
      if #fits > 1 and remark and not self:intent_at(self:skip_fillers(e, false)) then
        local named = {}
        for _, r in ipairs(self.refs) do
          if r.kind == "aircraft" and r.exists and (r.e <= b or r.b >= e) then named[r.name] = true end
        end
        local one = {}
        for _, id in ipairs(fits) do if named[id] then one[#one + 1] = id end end
        if #one == 1 then picked = one end
      end
      i = describe(self, b, e, #fits > 0 and fits or ids, picked, outer)
    else
      i = i + 1
    end
  end
end

-- The aircraft flying described after "the" by where it is going, in the addressing position: a group
-- (compared_group: an airline, a type, "one") and "for", "to", "bound for", "going to" or "flying to" an airport
-- named by one or two capitalised words (its navdata name, lexicon.city_airports' city, or its ICAO code),
-- opening the request or a clause and ending at a comma ("the Alitalia for Genova, turn left ...", Italian
-- "l'Alitalia per Genova"). The one aircraft of the group whose destination is that airport, none of the others'
-- destinations unknown, is the aircraft described (describe); the group's one aircraft, its destination that
-- airport or unknown, too. Any other case is asked about, naming the group; a name that is no airport is left
-- alone.
function m:destination_refs()
  if not (self:said("the") and self:said("for to")) then return end
  local w = self.world
  if not (w.airports_named and w.locate) then return end
  local i = 1
  while i <= #self.t do
    local b, e, ids = i, nil, nil
    local opens = i == 1 or self.t[i - 1].kind == "punct" or self:word(i - 1, "please")
    if opens and self:word(i, "the") and not self:other_traffic_before(i - 1) and not (self.positioned or {})[i] then
      local count
      ids, e, count = compared_group(self, i + 1)
      if count then ids = nil end
    end
    local p = ids and (self:word(e, "for to") and e + 1
      or self:word(e, "bound") and self:word(e + 1, "for") and e + 2
      or self:word(e, "going flying") and self:word(e + 1, "to") and e + 2)
    local q = p
    while q and q < p + 2 and self.t[q] and self.t[q].kind == "word" and self.t[q].alpha
        and self.t[q].raw:match("^%u") and not self.t[q].keyword do
      q = q + 1
    end
    local codes = {}
    if q and q > p and clause_mark(self, q) then
      local phrase = self:raw(p, q)
      local code = phrase:match("^%u%u%u%u$")
      if code and w.locate(code) then codes[code] = true end
      local city = L.city_airports[phrase:lower()]
      for _, said in ipairs({ phrase, city }) do
        for _, id in ipairs(w.airports_named(said)) do codes[id] = true end
        for _, id in ipairs(w.airports_of_city and w.airports_of_city(said) or {}) do codes[id] = true end
      end
    end
    if next(codes) then
      local fits, unknown = {}, 0
      for _, a in ipairs(self.fleet) do
        for _, id in ipairs(ids) do
          if id == a.id then
            if not a.dest or a.dest == "" then unknown = unknown + 1
            elseif codes[a.dest:upper()] then fits[#fits + 1] = id end
          end
        end
      end
      local picked = nil
      if (#fits == 1 and unknown == 0) or (#ids == 1 and #fits + unknown == 1) then picked = { ids[1] } end
      if #fits == 1 then picked = picked and fits end
      i = describe(self, b, q, ids, picked)
    else
      i = i + 1
    end
  end
end

-- True when the word at i is one of lexicon.screen_position's list `list` (its words or keys).
local SCREEN = {}
local function screen(self, i, list)
  if not SCREEN[list] then
    SCREEN[list] = {}
    for k, v in pairs(L.screen_position[list]) do SCREEN[list][type(k) == "number" and v or k] = true end
  end
  return self.words[i] ~= nil and SCREEN[list][self.words[i]] == true
end

-- The place said at token p after "next to", "near", "by" (position_refs): a waypoint, navaid or airport the
-- request names there (its ref), or one or two capitalised words naming one (m:place_by_name: "Pearson"), that
-- the navdata or the scenario locates; its {lat, lon} and the token after it, or nil.
local function place_at(self, p)
  local locate = self.world.locate
  if not locate then return nil end
  for _, r in ipairs(self.refs) do
    if r.b == p and r.kind ~= "aircraft" then
      local lat, lon = locate(r.name)
      if lat then return { lat, lon }, r.e end
    end
  end
  local e = p
  while e < p + 2 and self.t[e] and self.t[e].kind == "word" and self.t[e].alpha and self.t[e].raw:match("^%u%l")
      and not self.t[e].keyword and not self:has_ref(e, e + 1, "aircraft") do
    e = e + 1
  end
  -- (the airports of the name near the traffic, else its navaids, all within position_lead_nm of the first: one
  -- place; "Pearson" is CYYZ, not also the YTP VOR beside it)
  local w, at = self.world, nil
  local phrase = e > p and self:raw(p, e)
  local function nm(lat, lon, x) return 60 * math.sqrt((lat - x[1]) ^ 2 + ((lon - x[2]) * math.cos(math.rad(lat))) ^ 2) end
  for _, kind in ipairs({ "airports", "navaids" }) do
    for _, a in ipairs(not at and phrase and w.airports_named and w.navaids_named and self.fleet or {}) do
      local ids = {}
      if kind == "navaids" and a.lat then ids = w.navaids_named(phrase:lower(), a.lat, a.lon, L.navaid_range_nm) end
      if kind == "airports" and a.lat then
        for _, id in ipairs(w.airports_named(phrase)) do ids[#ids + 1] = id end
        -- (a city by the name lexicon.city_airports gives its airport: "near Trento", MATTARELLO)
        local city = L.city_airports[phrase:lower()]
        for _, id in ipairs(city and w.airports_named(city) or {}) do ids[#ids + 1] = id end
        for _, id in ipairs(w.airports_with_words and w.airports_with_words(phrase, a.lat, a.lon, L.navaid_range_nm)
            or {}) do
          ids[#ids + 1] = id
        end
      end
      for _, id in ipairs(ids) do
        local lat, lon = locate(id)
        if lat and nm(lat, lon, { a.lat, a.lon }) <= L.navaid_range_nm then
          if at and nm(lat, lon, at) > L.position_lead_nm then return nil end
          at = at or { lat, lon }
        end
      end
    end
  end
  if at then return at, e end
end

-- The side said from token k where an aircraft is on the north-up screen or map (position_refs): "at the top",
-- "on the far left", "up in the top left corner", "at the bottom right of the screen", "down in the south-west",
-- "in the middle", "near the top left", or a place it is next to ("right next to Pearson", "near LINNG"). Returns
-- a spec (dir: the unit vector {east, north} of the side or corner; middle: the traffic's centre; place: {lat,
-- lon}; point and of: the side, in degrees, of a place {lat, lon}, nil where unknown) and the token after the
-- words, or nil.
local function side_said(self, k)
  local x = k
  while screen(self, x, "leaning") do x = x + 1 end
  -- ("furthest north", "farthest to the south", "the most westerly", "most to the east": the one furthest along
  -- that side, as "at the top" reads)
  local most = self:word(x, "furthest farthest most") and x + 1
    -- ("more at north", "more to the south": Italian "più a nord", the comparative said for the superlative, only
    -- with "at" or "to" before the compass point)
    or self:word(x, "more") and self:word(x + 1, "at to") and x + 1
  if most then
    local y = self:word(most, "to at") and most + 1 or most
    if self:word(y, "the") then y = y + 1 end
    local deg, pe = self:point_said(y)
    local ly = not deg and self.words[y] and self.words[y]:match("^(%a+)erly$")
    if ly and L.compass[ly] and L.compass[ly] % 90 == 0 then deg, pe = L.compass[ly], y + 1 end
    if deg then return { dir = { math.sin(math.rad(deg)), math.cos(math.rad(deg)) } }, pe end
    return nil
  end
  local near = screen(self, x, "near") and x + 1
    or screen(self, x, "near_to") and self:word(x + 1, "to") and x + 2
  if near and not self:word(near, "the") then
    local place, e = place_at(self, near)
    if place then return { place = place }, e end
    return nil
  end
  -- ("north-east of the field", "south-east of Pearson": the side of a place; the field is the one airport the
  -- traffic's destinations name, else unknown: nothing fits)
  local deg, pe = self:point_said(x)
  if deg and self:word(pe, "of") then
    if self:word(pe + 1, "the") and screen(self, pe + 2, "fields") then
      local dest, one = nil, true
      for _, a in ipairs(self.fleet) do
        if a.dest and a.dest ~= "" then
          one, dest = one and (dest == nil or dest == a.dest), dest or a.dest
        end
      end
      local lat, lon = nil, nil
      if dest and one and self.world.locate then lat, lon = self.world.locate(dest) end
      return { point = deg, of = lat and { lat, lon } }, pe + 3
    end
    local place, e = place_at(self, pe + 1)
    if place then return { point = deg, of = place }, e end
    return nil
  end
  -- ("out west", "up north", "down in the south" is below): a compass point straight after words of `leaning`,
  -- the side of the map that way
  if deg and x > k then return { dir = { math.sin(math.rad(deg)), math.cos(math.rad(deg)) } }, pe end
  -- ("the one up the top", "the one down the bottom", "over the left": a word of `leaning` straight before "the" is
  -- the side's preposition, as "at")
  local up = x > k and self:word(x - 1, "up down over") and self:word(x, "the") and x
  if not (near or up or screen(self, x, "at")) then return nil end
  x = near or up or x + 1
  if not self:word(x, "the") then return nil end
  x = x + 1
  while self:word(x, "very far") do x = x + 1 end
  local spec
  if screen(self, x, "middle") then
    spec, x = { middle = true }, x + 1
  else
    local east, north, axes = 0, 0, {}
    while self.t[x] and L.screen_position.sides[self.t[x].text] do
      local d = L.screen_position.sides[self.t[x].text]
      local axis = d[1] ~= 0 and "x" or "y"
      if axes[axis] then return nil end  -- ("the left right": no side)
      axes[axis], east, north, x = self.t[x].text, east + d[1], north + d[2], x + 1
      if self.t[x] and self.t[x].text == "-" then x = x + 1 end
    end
    -- ("the upper one", "the lower left", "the upper side": upper and lower only with a side or a noun of
    -- lexicon.screen_position beside them; lower alone compares levels)
    if (axes.y == "upper" or axes.y == "lower") and not axes.x and not screen(self, x, "nouns") then return nil end
    if not axes.x and not axes.y then
      local deg, e = self:point_said(x)
      if not deg then return nil end
      east, north, x = math.sin(math.rad(deg)), math.cos(math.rad(deg)), e
    end
    local n = math.sqrt(east * east + north * north)
    spec = { dir = { east / n, north / n } }
  end
  while screen(self, x, "nouns") do x = x + 1 end
  local d = self:word(x, "of") and (self:word(x + 1, "the") and x + 2 or x + 1)  -- ("of the screen", "of screen")
  if d and screen(self, d, "names") then x = d + 1 end
  return spec, x
end

-- One part of an aircraft's description said between commas (position_refs): an aircraft group after "the" (size
-- words, lexicon.aircraft_described words and a type after an airline narrow or add nothing else: "the big one",
-- "the little Jazz jet", "the Air Canada A320"), then any sides said (side_said) and ways it flies ("heading
-- north-west", "the one going east", way_said) and one superlative after "which is the" or "and" ("the aircraft
-- which is the highest now", "the one flying south and slowest"); a part after a comma may open with a side or a
-- way it flies. Returns { b, e, ids (nil: any aircraft), sides = { {spec, b, e} }, points = { deg }, measure (nil
-- or lexicon.compared_measures' entry) }, or nil.
local function description_part(self, b)
  local part, x = { b = b, sides = {}, points = {} }, b
  if self:word(b, "the") then
    x = b + 1
    while self.t[x] and SIZE_WORDS[self.t[x].text] do x = x + 1 end
    -- ("the furthest east aircraft", "the most westerly one": the superlative of position before the group)
    if self:word(x, "furthest farthest most") then
      local spec, se = side_said(self, x)
      if spec then part.sides[1], x = { spec = spec, b = x, e = se }, se end
    end
    -- ("the low one at the top", "the fast one on the right": a plain word of lexicon.compared_plain before "one" or an
    -- aircraft noun, read with the side: position_refs)
    if self.t[x] and self.t[x].kind == "word" and L.compared_plain[self.t[x].text] and self:word(x + 1, "one @aircraft_nouns") then
      part.plain, x = L.compared_plain[self.t[x].text], x + 1
    end
    local ids, e, count = compared_group(self, x)
    if not ids or count then return nil end  -- ("the two Boeings" are no one aircraft)
    local test, te = self:type_said(e)
    if test then
      local typed = {}
      for _, a in ipairs(self.fleet) do
        if a.type and test(a.type:upper()) then typed[#typed + 1] = a.id end
      end
      ids, e = within(ids, typed), te
    end
    while self:word(e, "@aircraft_described") and not self:word(e, "one") do e = e + 1 end
    part.ids, x = ids, e
  end
  while true do
    local spec, e = side_said(self, x)
    if spec then
      part.sides[#part.sides + 1] = { spec = spec, b = x, e = e }
      x = e
    else
      local v = self:word(x, "that which") and self:word(x + 1, "is") and x + 2 or self:relative_is(x) and x + 1 or x
      local point
      point, e = self:way_said(v)
      -- ("which is the highest now", "flying south and slowest": a superlative of lexicon.compared_measures)
      local k = self:word(v, "and") and v + 1 or v
      if self:word(k, "the") and k > x then k = k + 1 end
      local measure = not point and not part.measure and k > x and L.compared_measures[self.words[k] or ""]
      if measure and not self.words[k]:match("er$") then
        part.measure, x = measure, self:word(k + 1, "now currently") and k + 2 or k + 1
      elseif not point then
        break
      else
        part.points[#part.points + 1], x = point, e
      end
    end
  end
  part.e = x
  if x == b or not (part.ids or #part.sides > 0 or #part.points > 0 or part.measure) then return nil end
  return part
end

-- The aircraft of `ids` that the side `spec` (side_said) picks, or nil and those it could not tell apart. The
-- traffic is laid on the north-up screen in NM about its centre. A side or corner: the one furthest along it,
-- on that side of the screen's centre line (else the words contradict the others: none), leading the runner-up
-- by lexicon.position_lead of the traffic's spread along it and at least position_lead_nm. The middle: the one
-- nearest the traffic's centre by that lead (of the traffic's larger spread). Near a place: the nearest, within
-- position_near_nm (or that fraction of the spread) of it, the runner-up at least twice as far and
-- position_lead_nm further.
local function side_pick(self, ids, spec)
  if spec.point then  -- (the side of a place: a quadrant about the point's bearing)
    local fits = {}
    for _, a in ipairs(spec.of and self.fleet or {}) do
      for _, id in ipairs(ids) do
        if id == a.id and a.lat then
          local dlat, dlon = a.lat - spec.of[1], (a.lon - spec.of[2]) * math.cos(math.rad(a.lat))
          local brg = math.deg(math.atan(dlon, dlat)) % 360
          if math.abs((brg - spec.point + 540) % 360 - 180) < L.bearing_margin then fits[#fits + 1] = id end
        end
      end
    end
    return #fits == 1 and fits[1] or nil, fits
  end
  local lat0, lon0, n = 0, 0, 0
  for _, a in ipairs(self.fleet) do
    if a.lat then lat0, lon0, n = lat0 + a.lat, lon0 + a.lon, n + 1 end
  end
  if n == 0 then return nil, ids end
  lat0, lon0 = lat0 / n, lon0 / n
  local k = 60 * math.cos(math.rad(lat0))
  local function xy(lat, lon) return (lon - lon0) * k, (lat - lat0) * 60 end
  local box = { math.huge, -math.huge, math.huge, -math.huge }
  for _, a in ipairs(self.fleet) do
    if a.lat then
      local x, y = xy(a.lat, a.lon)
      box = { math.min(box[1], x), math.max(box[2], x), math.min(box[3], y), math.max(box[4], y) }
    end
  end
  local cx, cy = (box[1] + box[2]) / 2, (box[3] + box[4]) / 2
  local spread = math.max(box[2] - box[1], box[4] - box[3])
  local function score(a)  -- (the larger the better)
    local x, y = xy(a.lat, a.lon)
    if spec.dir then return x * spec.dir[1] + y * spec.dir[2] end
    local px, py = cx, cy
    if spec.place then px, py = xy(spec.place[1], spec.place[2]) end
    return -math.sqrt((x - px) ^ 2 + (y - py) ^ 2)
  end
  if spec.dir then  -- (the traffic's spread and centre line along the side)
    local lo, hi = math.huge, -math.huge
    for _, a in ipairs(self.fleet) do
      if a.lat then lo, hi = math.min(lo, score(a)), math.max(hi, score(a)) end
    end
    spread, cx = hi - lo, (hi + lo) / 2
  end
  local scored = {}
  for _, a in ipairs(self.fleet) do
    for _, id in ipairs(ids) do
      if id == a.id and a.lat then scored[#scored + 1] = { id = id, v = score(a) } end
    end
  end
  table.sort(scored, function(p, q) return p.v > q.v end)
  local first, second = scored[1], scored[2]
  if not first then return nil, ids end
  local lead = math.max(L.position_lead_nm, L.position_lead * spread)
  if spec.place then lead = math.max(lead, -first.v) end
  local ties = {}
  for _, p in ipairs(scored) do
    if first.v - p.v < lead then ties[#ties + 1] = p.id end
  end
  local fits = (not spec.dir or first.v > cx or spread == 0)
    and (not spec.place or -first.v <= math.max(L.position_near_nm, L.position_lead * spread))
  if not fits then return nil, {} end
  if second and first.v - second.v < lead then return nil, ties end
  return first.id, ties
end

-- The aircraft of `ids` (in their order) that lead on the measure `measure` (lexicon.compared_measures' entry:
-- field, sign): the one furthest ahead and any within lexicon.compared_margin of it (several: a near tie, asked);
-- none where an aircraft lacks the field.
local function measure_leaders(self, ids, measure)
  local field, sign, value = measure[1], measure[2], {}
  for _, a in ipairs(self.fleet) do value[a.id] = a[field] and sign * a[field] end
  local best = -math.huge
  for _, id in ipairs(ids) do
    if not value[id] then return {} end
    best = math.max(best, value[id])
  end
  local out = {}
  for _, id in ipairs(ids) do
    if best - value[id] <= L.compared_margin[field] then out[#out + 1] = id end
  end
  return out
end

-- The aircraft flying described by where it is on the north-up screen or map ("the one at the bottom right of the
-- screen", "the plane on the far left", "the Air Canada down in the south-west", "the plane in the middle", "the
-- little Jazz jet sitting near Pearson"), with the other parts of its description said between commas beside it
-- ("the Delta, the Embraer up in the top left corner, ...", "the plane at the bottom right, the one going west,
-- ...", "the aircraft at the bottom of the screen, heading north-west, ...", "the plane in the middle, right next
-- to Pearson, ..."): of the aircraft that fit every other part (group, type, way it flies), the one each side
-- picks (side_pick) is the aircraft described (describe); sides that pick none, or different ones, and parts that
-- no aircraft fits together are asked about, naming those that could be meant. Runs before described_refs and
-- bearing_refs, which leave the words read here alone (self.positioned).
function m:position_refs()
  if not self:said("the") then return end
  local said = self:said("@compass @compass_verbs @compass_from_verbs @compared_measures furthest farthest most")
  -- ("up the top": looked for only where "up", "down" or "over" is said)
  local leaning = self:said("up down over")
  local k = 1
  while not said and k <= #self.t do
    said = screen(self, k, "at") or screen(self, k, "near") or screen(self, k, "near_to")
      or (leaning and self:word(k, "up down over") and self:word(k + 1, "the"))
    k = k + 1
  end
  if not said then return end
  self.positioned = self.positioned or {}
  local i = 1
  while i <= #self.t do
    local first = self:word(i, "the") and not self:other_traffic_before(i - 1) and description_part(self, i)
    local parts, e = { first or nil }, first and first.e
    while e and clause_mark(self, e) do  -- (the parts said after it between commas)
      local nx = description_part(self, self:word(e + 1, "the") and e + 1 or self:skip_fillers(e + 1))
      if not (nx and (clause_mark(self, nx.e) or self.t[nx.e] and self.t[nx.e].kind == "punct")) then break end
      parts[#parts + 1], e = nx, nx.e
    end
    -- (a part after them this reads no word of, "the four-engine one,", is no part dropped: asked)
    local unread = e and clause_mark(self, e) and self:word(e + 1, "the") and e + 1
    while unread and self.t[unread] and self.t[unread].kind ~= "punct" do unread = unread + 1 end
    if unread and clause_mark(self, unread) and self:word(unread - 1, "one @aircraft_nouns") then e = unread end
    local sides, ways = 0, 0
    for _, p in ipairs(parts) do  -- (none without a first part)
      sides, ways = sides + #p.sides, ways + (p.measure and 1 or 0) + (#parts > 1 and #p.points or 0)
    end
    if sides + ways == 0 then
      i = i + 1
    else
      local ids = {}
      for _, a in ipairs(self.fleet) do ids[#ids + 1] = a.id end
      for _, p in ipairs(parts) do
        if p.ids then ids = within(ids, p.ids) end
        for _, point in ipairs(p.points) do ids = heading_toward(self, ids, point) end
      end
      for _, p in ipairs(parts) do
        if p.measure then ids = measure_leaders(self, ids, p.measure) end
      end
      local picked, named = nil, ids
      if sides == 0 then picked = #ids == 1 and ids[1] or false end
      local plain
      for _, p in ipairs(parts) do
        plain = plain or p.plain
        for _, side in ipairs(p.sides) do
          if side.spec.point and not side.spec.of then
            self:need(string.format("Which airport do you mean by '%s'? The traffic's destinations name no one "
              .. "airport: please name it, or give the aircraft's callsign.", self:raw(side.b, side.e)))
          end
          local id, ties = side_pick(self, ids, side.spec)
          if not id or (picked and picked ~= id) then picked, named = false, #ties > 0 and ties or ids end
          if picked == nil then picked = id end
        end
      end
      -- (a plain word with the side: among the aircraft the side could not tell apart, the one leading the others on
      -- its measure by lexicon.compared_plain_margin; one the side picks must lead every aircraft of the group on it,
      -- within lexicon.compared_margin, else it is asked)
      if plain and sides > 0 then
        local field, sign, value = plain[1], plain[2], {}
        for _, a in ipairs(self.fleet) do value[a.id] = a[field] and sign * a[field] end
        if picked then
          for _, id in ipairs(ids) do
            if not value[id] or not value[picked] or value[id] - value[picked] > L.compared_margin[field] then
              picked, named = false, ids
              break
            end
          end
        elseif picked == false and #named > 1 then
          local best, second
          for _, id in ipairs(named) do
            local v = value[id]
            if not v then best, second = nil, nil break end
            if not best or v > value[best] then best, second = id, best
            elseif not second or v > value[second] then second = id end
          end
          if best and second and value[best] - value[second] >= L.compared_plain_margin[field] then picked = best end
        end
      end
      local b, unresolved = parts[1].b, self.type_unresolved or {}
      for n = #unresolved, 1, -1 do
        if unresolved[n].b >= b and unresolved[n].b < e then table.remove(unresolved, n) end
      end
      for x = b, e - 1 do self.positioned[x] = true end
      self:mark_used(b, e)  -- (asked or read, the words are no value: "the one north-east" is no latitude)
      for _, p in ipairs(picked and parts or {}) do  -- (a side read is no turn's side: "the top left")
        for _, side in ipairs(p.sides) do
          for x = side.b, side.e - 1 do
            if self:word(x, "@left @right") then self:blank(x) end
          end
        end
      end
      if unread and e == unread then named, picked = picked and { picked } or named, nil end
      i = describe(self, b, e, named, picked and { picked } or nil)
    end
  end
end

-- The aircraft flying described after "the" by when it was created: a group (compared_group), who created it
-- or not, a verb of creating (lexicon.created_verbs) and a word of order (lexicon.created_order) after it or
-- before the group ("the aircraft I created last", "the one we added first", "the last KLM I created", "the
-- aircraft created most recently"). The last or first of the group in the order the traffic was created is the
-- aircraft described (describe); with no word of order the words describe no aircraft here.
function m:creation_refs()
  if not self:said("@created_verbs") then return end  -- (no verb of creating: nothing to read)
  local function order_at(k)  -- (true for the latest, false for the first, or nil; the token after it)
    if self:word(k, "most") and self:word(k + 1, "recently") then return true, k + 2 end
    local o = self.t[k] and L.created_order[self.t[k].text]
    if o ~= nil then return o, k + 1 end
    return nil, k
  end
  local i = 1
  while i <= #self.t do
    local latest, ids, e, v
    if self:word(i, "the") and not self:other_traffic_before(i - 1) then
      latest, v = order_at(i + 1)
      ids, e = compared_group(self, v)
      v = e and (self:word(e, "that which who") and e + 1 or e)
      if v and self:word(v, "@created_by") then v = v + 1 end
      if v and self:word(v, "have has had") then v = v + 1 end
      -- ("the one I just made", "the aircraft we've just created", "the one I recently added": the latest; "the
      -- ones I just made" may be several, read as before)
      if v and self:word(v, "just recently") and self:word(v + 1, "@created_verbs")
          and not self:word_in(i, v, "ones planes airplanes flights jets") then
        v = v + 1
        if latest == nil then latest = true end
      end
    end
    if v and self:word(v, "@created_verbs") then
      e = self:word(v + 1, "in") and v + 2 or v + 1  -- ("the one I put in last")
      local after
      after, e = order_at(e)
      if latest == nil then latest = after end
    end
    if latest ~= nil and v and e > v and #ids > 0 then
      i = describe(self, i, e, ids, { latest and ids[#ids] or ids[1] })
    else
      i = i + 1
    end
  end
end

-- "create a Eurowings A320 ... and let the before created aircraft climb to FL 200", "..., then turn the newly
-- created plane left", "... and let the new aircraft climb": "the", perhaps a word of lexicon.created_just, a verb of
-- creating or "new", and an aircraft noun, said after the request created exactly one aircraft (one
-- creation verb, one type named after it), name that new aircraft as "it" would: the words are fillers, so the
-- instruction is the new aircraft's. With two created, or none, they are read as before (a description, asked).
function m:created_just_said()
  if not self:said("@creation_verbs") then return end
  for i = 2, #self.t - 2 do
    if self:word(i, "the") then
      local v = self:word(i + 1, "@created_just") and i + 2 or i + 1
      local n = self:word(v, "@created_verbs new") and v + 1
      if n and self:word(n, "@aircraft_nouns") then
        local made, at = 0, nil
        for k = 1, i - 1 do
          if self:word(k, "@creation_verbs") then made, at = made + 1, at or k end
        end
        if made == 1 and #self:refs_in(at, i, "type") == 1 then
          for k = i, n do self:blank(k) end
        end
      end
    end
  end
end

-- An aircraft named after "the" by what it carries alone (lexicon.carried_described: "the cargo aircraft", "the
-- freighter", "the charter flight"; an aircraft noun or "one" after the word, or a freighter): the traffic does
-- not tell it, so it is asked about, never dropped while another aircraft said beside it is instructed.
function m:carried_refs()
  if not self:said("@carried_described") then return end
  for i = 2, #self.t do
    local e = self:word(i, "@carried_described") and self:word(i - 1, "the") and i + 1
    if e and self:word(e, "@aircraft_nouns @group_nouns one jet jets") then e = e + 1 end
    if e and (e > i + 1 or self:word(i, "freighter freighters")) and #self:refs_in(i - 1, e, "aircraft") == 0 then
      return self:need(string.format("Which aircraft do you mean by '%s'? The traffic does not say what an "
        .. "aircraft carries: please give its callsign.", self:raw(i - 1, e)))
    end
  end
end

-- An aircraft named by a description (type_refs' "the 777", described_refs, bearing_refs, creation_refs) that no
-- command names, beside commands for others: asked about, never dropped ("define LOTUS ..., then send the 777
-- there": the 777's instruction went unread). One named in a reason ("because the A350 goes through HAGIS") or
-- compared with ("same as the A350") is traffic, no aircraft instructed.
function m:described_uninstructed()
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" and (r.by_type or r.by_description) and not r.false_start and not self:in_reason(r.b)
        and not self:compared_with(r.b) then
      local named = false
      for _, line in ipairs(self.out) do named = named or line:find("%f[%w]" .. r.name .. "%f[%W]") ~= nil end
      if not named then
        return self:need(string.format("I have %s. What should '%s' (%s) do?", table.concat(self.out, " ; "),
          self:raw(r.b, r.e), r.name))
      end
    end
  end
end

-- Airline letters, flight digits and trailing letters of a callsign
-- ("BAW96CA" -> "BAW", "96", "CA").
local function airline_digits(id) return (id or ""):match("^(%a*)(%d*)(.*)$") end

-- The first position at or after i that is not a filler, a comma or (with
-- corrections) a correction word.
function m:skip_fillers(i, corrections)
  while self.t[i] and (self.t[i].kind == "punct" or self.t[i].filler
      or (corrections and self:word(i, "@correction"))) do
    i = i + 1
  end
  return i
end

-- Callsigns the speaker restarted or corrected, settled once per request;
-- the corrected-away callsign is never instructed:
--  * "Brickyard eleven correction fourteen eleven", "azul four zero one four
--    correction four zero four one": digits after a correction replace the
--    callsign's digits (the airline kept); an id no aircraft has is asked about;
--  * "KLM12 correction KLM21", "Delta sixty, Delta six forty six": a
--    callsign followed by a correction and another callsign, or an inexactly
--    heard one said again straight after itself, was a false start
--    (r.false_start); the later one counts;
--  * "KLM12 climb FL300, correction KLM21": a callsign after a correction
--    that ends the request replaces the one named before it;
--  * "where is Serene eight four two": the words of a question about where
--    an aircraft is (QUESTION_WORDS) said before a callsign the matcher heard
--    with them are no part of it (its airline's name heard from them or not).
local QUESTION_WORDS = { where = true, wheres = true, ["where's"] = true, is = true, what = true, whats = true,
                         ["what's"] = true, show = true, me = true, tell = true }
-- (the words a flight number said as words opens with: m:settle_callsigns)
local SPOKEN_DIGITS = { zero = true, one = true, two = true, three = true, four = true, five = true, six = true,
  seven = true, eight = true, nine = true, niner = true, oh = true, tree = true, fife = true }
function m:settle_callsigns()
  -- ("..., contact singapore one two three decimal seven": a station and its frequency after "contact" or "monitor",
  -- its digits closed by "decimal" or "point", are no callsign the matcher heard in them)
  for k = #self.refs, 1, -1 do
    local r = self.refs[k]
    if r.kind == "aircraft" and r.spoken and self:word(r.b - 1, "contact monitor") and self:word(r.e, "decimal point") then
      table.remove(self.refs, k)
    end
  end
  -- ("if 721 reaches FL270 then heading 060", "unless 721 is at FL270 ..."): a word that opens a condition
  -- (G.condition_openers) that the matcher took into an aircraft's callsign before its digits is no part of it: left
  -- out of the reference, it stays a word of the request (asked, never dropped)
  for _, r in ipairs(self.refs) do
    local t = r.kind == "aircraft" and r.e - r.b > 1 and self.t[r.b]
    if t and t.kind == "word" and self.condition_openers[t.text] and self.t[r.b + 1].raw:match("^%d") then
      r.b = r.b + 1
    end
  end
  -- ("AirAsia 5517" with AXM88 and AWQ5517 flying, "Batik 112" with BTK100 and MXD112): a callsign heard with a
  -- brand's name that the matcher took for another aircraft of the name's own airline is the one aircraft of the
  -- brand flying with every character heard (m:airline_and_digits_match), when there is exactly one
  for _, r in ipairs(self.refs) do
    local h = r.kind == "aircraft" and r.exists and r.heard
    local a = h and airline_digits(h.id)
    if a and select(3, airline_names())[a] and not self:airline_and_digits_match(h.id, r.name) then
      for _, ac in ipairs(self.fleet) do
        if airline_digits(ac.id) ~= a and self:airline_and_digits_match(h.id, ac.id) then r.name = ac.id break end
      end
    end
  end
  -- "KLM 1394 and 1349, both descend FL80": typed digits after a flying aircraft's callsign and "and" that are,
  -- with its airline, another flying aircraft's callsign exactly name that aircraft too; so do digits after a comma
  -- that "both" follows ("Israir 318, 381, both climb FL170": two aircraft listed)
  local function both_after(x)
    local k = self.t[x + 1] and self.t[x + 1].text == "," and x + 2 or x + 1
    return self:word(k, "both")
  end
  for k = #self.refs, 1, -1 do
    local r = self.refs[k]
    local x = r.e + 1
    local t, nx = self.t[x], self.refs[k + 1]
    local listed = self:word(r.e, "and") or (self.t[r.e] and self.t[r.e].text == "," and both_after(x))
    local a = r.kind == "aircraft" and r.exists and listed and t and t.kind == "number"
      and t.text:match("^%d+$") and not self.u:used(x) and not (nx and nx.b == x) and airline_digits(r.name)
    local id = a and a ~= "" and (a .. t.text):upper()
    local e = x + 1
    -- (said as words, "Shamrock one zero four and one four zero, descend ...": the digits of the plain number said
    -- there, no unit after it, as typed ones are)
    if not id and r.kind == "aircraft" and r.exists and t and t.kind == "word" and SPOKEN_DIGITS[t.text]
        and not self.u:used(x)
        and not (nx and nx.b == x) and airline_digits(r.name) ~= ""
        and (self:word(r.e, "and") or (self.t[r.e] and self.t[r.e].text == ",")) then
      local q = self.u:quantities(x, math.min(#self.t + 1, x + 8))[1]
      if q and q.b == x and q.kind == "plain" and q.number and q.number.digits:match("^%d+$")
          and (self:word(r.e, "and") or both_after(q.e - 1)) then
        id, e = (airline_digits(r.name) .. q.number.digits):upper(), q.e
      end
    end
    if id and id ~= r.name:upper() and self:state(id) and not L.value_units[self.words[e] or ""] then
      table.insert(self.refs, k + 1, { kind = "aircraft", name = self:state(id).id, b = x, e = e, exists = true })
      self:mark_used(x, e)
    end
  end
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" then
      -- (so are the words of an instruction said before the airline's name: "delete Norwegian 741", "position of the
      -- Norwegian 741", NOZ741 having no telephony squawk knows)
      local j = r.b
      while j < r.e - 1 and self.t[j].kind == "word" and self:known_word(j) and not self:airline_at(j) do j = j + 1 end
      if j > r.b and j < r.e - 1 and self:airline_at(j) then
        self.unheld = self.unheld or {}
        for x = r.b, j - 1 do self.unheld[x] = true end
        r.b = j
      end
      while r.e - r.b > 1 and self.t[r.b].kind == "word" and QUESTION_WORDS[self.t[r.b].text]
          and not self:airline_at(r.b) do
        self.unheld = self.unheld or {}  -- (tokens the matcher used that no reference holds now: G:intent_at)
        self.unheld[r.b] = true
        r.b = r.b + 1
      end
    elseif r.kind == "waypoint" and r.e == r.b + 1 and self:word(r.b, "eta") then
      -- ("DLH458 ETA?": the estimate asked, written in capitals as a place is, G:intent_at reads it)
      self.unheld = self.unheld or {}
      self.unheld[r.b] = true
    end
  end
  -- ("get rid of the Condor" with the VOR RID in the scene: "rid" between "get" and "of" is the verb, no place)
  for k = #self.refs, 1, -1 do
    local r = self.refs[k]
    if r.kind == "waypoint" and r.e == r.b + 1 and self:word(r.b, "rid") and self:word(r.b - 1, "get got getting gets")
        and self:word(r.e, "of") then
      self.unheld = self.unheld or {}
      self.unheld[r.b] = true
      table.remove(self.refs, k)
    end
  end
  -- "Austrian 123, AUA123, an A320 ...", "Ryanair 1WT, that's RYR1WT": a callsign said and then written (or
  -- said again) as the same id, with punctuation, "that's" or "callsign" between, is one reference
  for k = #self.refs - 1, 1, -1 do
    local r, nxt = self.refs[k], self.refs[k + 1]
    if r.kind == "aircraft" and nxt.kind == "aircraft" and r.name == nxt.name and nxt.b > r.e then
      local between = true
      for i = r.e, nxt.b - 1 do
        between = between and (self.t[i].kind == "punct" or self.t[i].filler or self:word(i, "that that's is callsign"))
      end
      -- ("scooter four eight one tree scooter four eight one turn right": one spoken digit slipped after the id
      -- and before the id said again whole, the id with it no aircraft's, is the same reference)
      if not between and nxt.b == r.e + 1 and self:word(r.e, "zero one two three tree four fower five fife six seven eight nine niner") then
        between = not self:state(r.name .. ({ zero = 0, one = 1, two = 2, three = 3, tree = 3, four = 4, fower = 4,
          five = 5, fife = 5, six = 6, seven = 7, eight = 8, nine = 9, niner = 9 })[self.words[r.e]])
        if between then self:mark_used(r.e, r.e + 1) end
      end
      if between then
        -- ("Vueling 8826, eh, Vueling 8862, descend": said again as another id, heard inexactly, the later one is
        -- what was meant: its hearing is kept, and m:confirm_callsigns asks)
        local h = nxt.heard
        if h and h.id and not self:airline_and_digits_match(h.id, nxt.name) then r.heard = h end
        r.e = nxt.e
        table.remove(self.refs, k + 1)
      end
    end
  end
  -- "Lufthansa 9CK, 9CK, reduce 250": the flight number said again alone after a comma, up to the next
  -- punctuation, is the same reference
  for _, r in ipairs(self.refs) do
    local suffix = r.kind == "aircraft" and r.name:match("^%a%a%a(%w%w+)$")
    local k = suffix and self.t[r.e] and self.t[r.e].text == "," and r.e + 1
    local said, m = "", k
    while m and self.t[m] and self.t[m].kind ~= "punct" and #said < #suffix do
      said, m = said .. self.t[m].raw:upper(), m + 1
    end
    if said == suffix and self.t[m] and self.t[m].kind == "punct" and #self:refs_in(k, m) == 0 then
      r.e = m
      self:mark_used(k, m)
    end
  end
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" then
      local k = self:skip_fillers(r.e, false)
      if self:word(k, "@correction") then
        local q = self:quantities(self:skip_fillers(k, true), #self.t + 1)[1]
        local airline = (r.heard and r.heard.id or r.name):match("^%a+")
        if q and q.b == self:skip_fillers(k, true) and q.kind == "plain" and airline then
          local id = airline .. q.number.digits
          local known = self:state(id)
          r.name, r.heard, r.e, r.exists = known and known.id or id, nil, q.e, known ~= nil
          self:mark_used(q.b, q.e)
        end
      end
    end
  end
  self:restarted_callsigns()
  self:false_starts()
end

-- "Lufthansa four alpha... Lufthansa four alpha x-ray", "Easy five two tango... tango mike", "KLM one two three
-- four... KLM, uh, one two three four": a callsign cut off (at "..." or a hesitation) and said again, its airline
-- again or not, from its first character or from one said before the cut, to its end. The characters said before
-- the cut up to where the restart picks up, then those said after it, must spell the aircraft's callsign after its
-- airline exactly (the decision: every spoken character matches); the reference then holds both, as heard.
function m:restarted_callsigns()
  local function char(k)
    local t = self.t[k]
    if not t or t.filler then return nil end
    if t.kind == "number" and t.text:match("^%d+$") then return t.text end
    return t.kind == "word" and (L.digit_words[t.text] or L.phonetic[t.text]) or nil
  end
  local function cut_at(k)
    local t = self.t[k]
    return t and (t.filler or t.kind == "punct" and (t.text == "." or t.text == "-" or t.text == ","))
  end
  for _, r in ipairs(self.refs) do
    local icao, ae = nil, nil
    if r.kind == "aircraft" and r.exists then icao, ae = self:airline_at(r.b) end
    local name = r.name:upper()
    local heard = r.heard and r.heard.id and r.heard.id:upper()
    if icao and name:sub(1, #icao) == icao:upper() and (not heard or #heard < #name and name:sub(1, #heard) == heard) then
      local suffix = name:sub(#icao + 1)
      local before, c = "", ae
      while char(c) and c < r.e + 1 do before, c = before .. char(c), c + 1 end
      if cut_at(c) and #before > 0 and suffix:sub(1, #before) == before and self.t[c].text ~= ","
          or cut_at(c) and self.t[c].filler then
        local k = c
        while cut_at(k) do k = k + 1 end
        local again, e2 = self:airline_at(k)
        if again and again:upper() == icao:upper() then
          k = e2
          while cut_at(k) do k = k + 1 end
        end
        local after, e = "", k
        while char(e) do after, e = after .. char(e), e + 1 end
        local closed = not self.t[e] or self.t[e].kind == "punct" or self:intent_at(e)
        local fits = false
        for j = 0, #before do
          fits = fits or (#after > 0 and before:sub(1, j) .. after == suffix)
        end
        -- (said whole again only, when the first was heard exactly: "KLM1234... KLM1234")
        if not heard then fits = after == suffix end
        if fits and closed then
          for x = c, e - 1 do self.noted[x] = true end
          self:mark_used(r.b, e)
          r.e, r.heard = e, nil
        end
      end
    end
  end
end

-- The aircraft references taken back (r.false_start, see m:settle_callsigns); run again once the aircraft
-- described ("the United", "the second aircraft") are references too.
function m:false_starts()
  -- (only an inexactly heard one when said again: "AC01, AC02 climb" names two aircraft)
  local last  -- the last aircraft named before a correction
  for k, r in ipairs(self.refs) do
    local nxt = self.refs[k + 1]
    if r.kind == "aircraft" and nxt and nxt.kind == "aircraft"
        and (self:callsign_taken_back(r.e, nxt.b)
          or (self:skip_fillers(r.e, true) == nxt.b and r.heard
            and airline_digits(r.heard.id) == airline_digits(nxt.name))) then
      r.false_start = true
    end
    if r.kind == "aircraft" and nxt and nxt.kind == "aircraft" and not r.false_start
        and self:verb_said_again(r.e, nxt) then
      r.false_start = true
    end
    if r.kind == "aircraft" and nxt and nxt.kind == "aircraft" and not r.false_start
        and self:instruction_said_again(r, nxt) then
      r.false_start = true
    end
    if r.kind == "aircraft" and not r.false_start and self:aircraft_named_after(r) then
      r.false_start = true
    end
    if r.kind == "aircraft" and not r.false_start then
      local c = r.b - 1
      while c > 0 and (self.t[c].kind == "punct" or self.t[c].filler) do c = c - 1 end
      if last and c >= last.e and self:word(c, "@correction") and self:skip_fillers(r.e, false) > #self.t then
        last.false_start = true
      elseif last and self:aircraft_said_instead(last, r) then
        last.false_start = true
      end
      last = r
    end
  end
end

-- True when aircraft reference r names, after a mark and closing the request, the aircraft an earlier reference
-- described by its airline alone ("the Martinair ... . Martinair 7124 that is.", "the Ryanair also heading 090.
-- Ryanair 8XP I mean."): only punctuation, fillers and "that is", "I mean" or "I meant" follow it. Those words are
-- marked used; r says who was meant and is instructed through the description.
function m:aircraft_named_after(r)
  local c = r.b - 1
  while c > 0 and self.t[c].filler do c = c - 1 end
  if c < 1 or self.t[c].kind ~= "punct" then return false end
  local described = false
  for _, p in ipairs(self.refs) do
    if p.b < r.b and p.kind == "aircraft" and p.by_airline and p.name == r.name then described = true end
  end
  local e = self:skip_fillers(r.e, false)
  if self:word(e, "that") and self:word(e + 1, "is") or self:word(e, "i") and self:word(e + 1, "mean meant") then
    e = self:skip_fillers(e + 2, false)
  end
  if not described or e <= #self.t then return false end
  self:mark_used(r.b, #self.t + 1)
  return true
end

-- True when the words between two callsigns, [b, e), take the first back: punctuation, fillers and
-- lexicon.self_correction words only, holding a correction word or a self-correction marker ("KLM12
-- correction KLM21", "DLH6CK, sorry, AUA123", "DLH6CK, no, I mean AUA123"); words that describe the aircraft said
-- in its place belong to the run ("the United -- no, the Southwest aircraft", "American 100 -- no, the second
-- aircraft, United 200": lexicon.self_correction.described and aircraft nouns).
local SELF_CORRECTION, SC_MARKER = {}, {}
for _, w in ipairs(L.self_correction.words) do SELF_CORRECTION[w] = true end
for _, w in ipairs(L.self_correction.described) do SELF_CORRECTION[w] = true end
for _, w in ipairs(L.aircraft_nouns) do SELF_CORRECTION[w] = true end
for _, w in ipairs(L.self_correction.markers) do SC_MARKER[w] = true end
-- (the words restating after a marker, "no wait, it is the Wizz", "sorry, is the Wizz" in an Italian speaker's
-- English: lexicon.self_correction.restated, said before the aircraft named in place of the one taken back)
for _, p in ipairs(L.self_correction.restated) do
  for w in p:gmatch("%S+") do SELF_CORRECTION[w] = true end
end
function m:callsign_taken_back(b, e)
  local marked = false
  -- ("EIN45A... uh EIN123 speed 260": a callsign trailing off, then a hesitation, is taken back as by "sorry")
  local trailed, hesitated = false, false
  for i = b, e - 1 do
    local t = self.t[i]
    trailed = trailed or (t.kind == "punct" and (t.raw:find("..", 1, true) ~= nil or t.raw == "…"
      or (t.text == "." and (self.t[i + 1] or {}).text == ".")))
    hesitated = hesitated or (t.filler and self:word(i, "uh um erm er ehm uhm"))
  end
  marked = trailed and hesitated
  for i = b, e - 1 do
    local t = self.t[i]
    if t.kind ~= "punct" and not t.filler then
      -- ("KLM12 or rather BAW5 climb FL300": "or rather" takes the callsign back as "I mean" does)
      local rather = (t.text == "or" and self:word(i + 1, "rather") and i + 1 < e)
        or (t.text == "rather" and self:word(i - 1, "or") and i > b)
      if self:word(i, "@correction") or SC_MARKER[t.text] or rather
          or (self.t[i + 1] and i + 1 < e and SC_MARKER[t.text .. " " .. self.t[i + 1].text]) then
        marked = true
      elseif not SELF_CORRECTION[t.text] then
        return false
      end
    end
  end
  return marked
end

-- True when aircraft reference r is followed by an instruction, then a run that takes a callsign back
-- (m:callsign_taken_back: "sorry", "I mean", "correction", "no") and aircraft reference nxt, then the same
-- instruction's first word ("KLM12 heading 200, sorry, TRA34 heading 200", "klm12 hdg, i mean tra34 hdg 200"):
-- the callsign was corrected, the instruction is said for nxt alone.
function m:instruction_said_again(r, nxt)
  local w = self:skip_fillers(r.e, false)
  if w >= nxt.b or not self.t[w] or self.t[w].kind ~= "word" then return false end
  local again = self:skip_fillers(nxt.e, false)
  -- (a typed abbreviation is its word: "hdg" with no value after it stays as typed)
  local full = { hdg = "heading", spd = "speed", alt = "altitude", lvl = "level" }
  local function word(i) return full[self.t[i].text] or self.t[i].text end
  if not self.t[again] or word(again) ~= word(w) then return false end
  for p = w + 1, nxt.b - 1 do
    if self:callsign_taken_back(p, nxt.b) then return true end
  end
  return false
end

-- True when the words from b (after an aircraft) are an instruction's verb, a run taken back (m:callsign_taken_back)
-- and aircraft reference nxt, then the same verb ("make the Skymark to descend... sorry, I mean the China Eastern,
-- to descend to 9000 feet"): the aircraft before the run is taken back, the verb is said for nxt. "to" may precede
-- each verb; a verb said only once ("the Skymark descend, sorry, the China Eastern, climb ...") is no such run.
function m:verb_said_again(b, nxt)
  local function verb_at(k)
    k = self:skip_fillers(k, true)
    if self:word(k, "to") then k = k + 1 end
    local t = self.t[k]
    return t and t.kind ~= "punct" and self:word(k, "@refusable_verbs") and k or nil
  end
  local v = verb_at(b)
  if not v or v + 1 >= nxt.b or not self:callsign_taken_back(v + 1, nxt.b) then return false end
  local again = verb_at(nxt.e)
  return again ~= nil and self.t[again].text == self.t[v].text
end

-- True when aircraft reference r, said after a complete instruction to `last`, replaces it: r (and aircraft said
-- after it with "and" or a comma) closes the request after a run of lexicon.self_correction words holding a marker
-- ("climb FL280, no, sorry, I meant the Lufthansa 2EC", "turn heading 090? No, sorry, I meant the Eurowings"),
-- optionally followed by "not" and `last` said again ("..., not the Condor") or `last` said again with words that
-- keep it as it is (lexicon.kept_as_is, lexicon.said_instead_kept: "..., the Eurowings can stay like it is"). The
-- run and the words after it are marked used and each aircraft said in last's place gets r.said_instead (the parse
-- instructs them, also where "I meant ..." reads as the speaker's own remark: G:in_reason).
local KEPT_AS_IS = {}
for _, list in ipairs({ L.kept_as_is.copulas, L.kept_as_is.approvals, L.kept_as_is.rounding, L.said_instead_kept }) do
  for _, w in ipairs(list) do KEPT_AS_IS[w] = true end
end
function m:aircraft_said_instead(last, r)
  if r.name == last.name then return false end  -- (the same aircraft said again: "Sorry, the Wideroe, I mean")
  local b, marked = r.b, false
  while b > last.e and (self.t[b - 1].kind == "punct" or self.t[b - 1].filler or SELF_CORRECTION[self.t[b - 1].text]) do
    b = b - 1
    marked = marked or SC_MARKER[self.t[b].text] or self:word(b, "@correction")
  end
  if not marked or b == last.e or self:any_instruction_in(b, r.b) then return false end
  local instead, e = { r }, self:skip_fillers(r.e, false)
  local function ref_at(k)  -- (an aircraft said at k, after "the" or not)
    local nx = self:refs_in(k, k + 1, "aircraft")[1] or self:word(k, "the") and self:refs_in(k + 1, k + 2, "aircraft")[1]
    return nx and nx.exists and nx
  end
  local nx = ref_at(e) or self:word(e, "and") and ref_at(e + 1)
  while nx and nx.name ~= last.name do
    instead[#instead + 1] = nx
    e = self:skip_fillers(nx.e, false)
    nx = ref_at(e) or self:word(e, "and") and ref_at(e + 1)
  end
  local again = ref_at(self:word(e, "not") and e + 1 or e)
  if again and again.name == last.name then
    local k = self:skip_fillers(again.e, false)
    while self.t[k] and KEPT_AS_IS[self.t[k].text] and not self:word(e, "not") do k = k + 1 end
    if self:word(e, "not") or k > again.e then e, again.false_start = self:skip_fillers(k, false), true end
  end
  if e <= #self.t then
    -- (another aircraft named in other words after the one said instead, no instruction among them: which
    -- aircraft is meant is unknown)
    if not self:any_instruction_in(r.e, #self.t + 1) and self:has_ref(r.e, #self.t + 1, "aircraft") then
      self:need(string.format("Which aircraft should get the instruction: %s or %s?", last.name:upper(), r.name:upper()))
    end
    return false
  end
  self:mark_used(b, r.b)
  self:mark_used(instead[#instead].e, #self.t + 1)
  for _, x in ipairs(instead) do x.said_instead = true end
  return true
end

-- True when the heard callsign's airline and digits are those of exactly one
-- aircraft, which is `name`, and every letter after them was heard too
-- ("speedbird nine six" is not BAW96CA, "two alpha charlie" not DLH2AB);
-- with one aircraft flying and lexicon.callsign_confirm.alone off, its last
-- letters may have gone unheard.
function m:airline_and_digits_match(heard, name)
  local a, d, rest = airline_digits(heard)
  if a == "" or d == "" or self:letters_conflict(heard, name) then return false end
  if self:strict_callsigns() and rest ~= select(3, airline_digits(name)) then return false end
  -- (an airline of the heard one's brand is that airline: "Transavia 33KP" is TVF33KP, names.lua's brands)
  local brand = select(3, airline_names())[a]
  local function of(a2)
    if a2 == a then return true end
    for _, c in ipairs(brand or {}) do if c == a2 and bears(a2, brand) then return true end end
    return false
  end
  local n = 0
  for _, ac in ipairs(self.fleet) do
    local a2, d2 = airline_digits(ac.id)
    if of(a2) and d2 == d then n = n + 1 end
  end
  local a3, d3 = airline_digits(name)
  return n == 1 and of(a3) and d3 == d
end

-- True when letters heard after the digits do not start the aircraft's
-- ("two alpha charlie" for DLH2AB; "charlie" alone for N978CN fits).
function m:letters_conflict(heard, name)
  local _, _, rest = airline_digits(heard)
  local _, _, rest2 = airline_digits(name)
  return rest2:sub(1, #rest) ~= rest
end

-- True when every inexactly heard callsign is asked about (lexicon.callsign_confirm).
function m:strict_callsigns()
  local c = L.callsign_confirm
  return c.strict and (#self.fleet > 1 or c.alone)
end

-- The words that open spoken aircraft reference r when they are a country (lexicon.countries) that is a later
-- part of its airline's telephony, neither that telephony nor its beginning ("Bulgaria 411" for LZB411, FLYING
-- BULGARIA), with other aircraft flying it might have been meant from: a country names no one airline (as a
-- brand's name selects only an airline whose telephony is it or begins with it); nil otherwise ("Air" and the
-- country, AIR PORTUGAL, is shortened to the country: "Portugal 9148" is the TAP; "Aerobus 1204", no country,
-- is Viva Aerobus)
function m:telephony_part_only(r)
  if not r.spoken or r.heard or #self.fleet < 2 then return nil end
  -- (the country: the first word of r's words, or a later one before its flight number, as the callsign matcher
  -- may take the verb before it: "climb China 124")
  local c = r.b
  while c < r.e and self.t[c].kind == "word" and not self.t[c].number_word and not self:word(c, "@countries") do
    c = c + 1
  end
  if c >= r.e or not self:word(c, "@countries") then return nil end
  if not AIRLINE_NAMES then airline_names() end
  local tels = NAMES_OF[(airline_digits(r.name))]
  if not tels then return nil end
  local said, part = self.t[c].text, nil
  -- (a telephony or common name said whole, from the country or a word before it, is no part: "Air China 124",
  -- "China Eastern 5", "Transavia France 34AB")
  for b = r.b, c do
    for _, n in ipairs(CALLED[(airline_digits(r.name))]) do
      local k, whole = b, true
      for w in n:gmatch("%S+") do
        whole, k = whole and k < r.e and self.t[k].text == w, k + 1
      end
      if whole then return nil end
    end
  end
  local several = m.country_airlines(said) > 1
  for _, n in ipairs(tels) do
    if not several and (n:sub(1, #said + 1) == said .. " " or n == "air " .. said) then return nil end
    if (" " .. n .. " "):find(" " .. said .. " ", 1, true) then part = self:raw(c, r.e) end
  end
  return part
end

-- How many airlines (ICAO prefixes) a country's name `said` (lower case) may be short for: those with a telephony or
-- common name (names.lua) that is `said`, begins with it ("china eastern", "iran airtour") or is "air" before it
-- ("air china"). More than one: "China 124" names no one airline, and is asked.
local country_count = {}
function m.country_airlines(said)
  if country_count[said] then return country_count[said] end
  local codes, n = {}, 0
  for name, icao in pairs(AIRLINE_NAMES) do
    if (name == said or name:sub(1, #said + 1) == said .. " " or name == "air " .. said
        or name:sub(1, #said + 5) == "air " .. said .. " ") and not codes[icao] then
      codes[icao], n = true, n + 1
    end
  end
  country_count[said] = n
  return n
end

-- The words of spoken aircraft reference r when its id's last digit was heard as an everyday word after the
-- other digits said (lexicon.closing_homophones: "easy eight on descend" for EZY81), with other aircraft flying
-- it might have been meant from; nil otherwise
function m:homophone_closing(r)
  if not r.spoken or r.heard or not r.exists or #self.fleet < 2 then return nil end
  local k = r.e - 1
  while k > r.b and self:word(k, "heavy super") do k = k - 1 end
  local t, before = self.t[k], self.t[k - 1]
  local digit = k > r.b and t.kind == "word" and not t.number_word and L.closing_homophones[t.text]
  if digit and before.number_word and r.name:sub(-1) == digit then return self:raw(r.b, k + 1) end
  return nil
end

-- The words of spoken aircraft reference r when they are its flight number's digits alone said in words ("six
-- zero five, climb FL160"), r an airline's callsign (letters, then digits) that no other reference of the request
-- names with its airline: the airline went unsaid, and issue 44 point 3 takes a callsign only when its airline and
-- every character are said, so it is confirmed, never taken; nil otherwise. Not so: digits typed ("1723 direct
-- XING2", a typist's shorthand older rounds read), a registration ("N512TX" has no airline to say), an aircraft
-- described ("the triple seven": "the" before it, or a reference of its own kind, r.by_type, r.by_description,
-- ...), and a number listed after a callsign of its airline ("KLM 1394 and 1349").
function m:number_only(r)
  -- ("the one" alone is a pronoun, never an aircraft described: "the one climb FL300" with SAS1 flying)
  local pronoun = r.e - r.b == 1 and self:word(r.b, "one")
  if not r.name:match("^%a%a%a?%d") or r.name:match("^N%d") or (self:word(r.b - 1, "the") and not pronoun) then
    return nil
  end
  for key in pairs(r) do
    if key:match("^by_") then return nil end
  end
  -- (a typed flight number closed by one or two letters, "4ab fl230" for DLH4AB, is confirmed as a said one is)
  local typed = self.t[r.b].kind == "number" and self:raw(r.b, r.e):match("^%d+%s?%a%a?$")
  for x = r.b, r.e - 1 do
    if not (typed or self.t[x].kind == "word" and (self.t[x].number_word or self.t[x].filler)) then return nil end
  end
  local airline, before = r.name:match("^%a+"), self.t[r.b - 1]
  local listed = before and (self:word(r.b - 1, "and") or (before.kind == "punct" and before.text == ","))
  for _, o in ipairs(self.refs) do
    if o.kind == "aircraft" and o.b ~= r.b and (o.name == r.name
        or (listed and o.e == r.b - 1 and o.name:match("^%a+") == airline)) then
      return nil
    end
  end
  return self:raw(r.b, r.e)
end

-- The words that say the callsign of spoken aircraft reference r when the callsign matcher read r from the
-- request's opening words with words of the request glued before them ("climb Foobar 846" heard as
-- CLIMBFOOBAR846: words squawk knows, none an airline's, lead it) and the words after them, before the flight
-- number, do not name r's airline (its ICAO prefix, a name of it or of its brand, matched better than
-- lexicon.callsign_confirm.airline: "climb quatar 846" names QTR846's): no aircraft may be suggested for them.
-- nil otherwise (and when no word is left after them: "AC 851" may be Air Canada's).
function m:airline_unsaid(r)
  local k = r.b
  while k < r.e and self:known_word(k) and not self.t[k].number_word and not L.phonetic[self.t[k].text]
      and not self:airline_at(k) do
    k = k + 1
  end
  if k == r.b or not r.heard then return nil end
  local said = ""
  for x = k, r.e - 1 do
    if self.t[x].kind ~= "word" or self.t[x].number_word or L.phonetic[self.t[x].text] then break end
    said = said .. self.t[x].text
  end
  local _, score = squawk.translate.best_match(said, m.airline_sounds(airline_digits(r.name)))
  if said == "" or score > L.callsign_confirm.airline then return nil end
  return self:raw(k, r.e)
end

-- The ways airline `prefix` (an ICAO prefix) is said, lower case with no spaces: the prefix itself, its telephony
-- and common names and the names of the brands it flies under ("dlh", "lufthansa", ...).
local sounds_of = {}  -- (m.airline_sounds' lists, by prefix)
function m.airline_sounds(prefix)
  if sounds_of[prefix] then return sounds_of[prefix] end
  local of = { prefix:lower() }
  sounds_of[prefix] = of
  airline_names()
  for name, icao in pairs(AIRLINE_NAMES) do
    if icao == prefix then of[#of + 1] = name:gsub(" ", "") end
  end
  for name, codes in pairs(BRANDS) do
    for _, code in ipairs(codes) do
      if code == prefix then of[#of + 1] = name:gsub(" ", "") end
    end
  end
  return of
end

-- The words of spoken aircraft reference r when the words said before its flight number hold one squawk does not
-- know (no English of the lexicon, no name) and no run of them from their start up to that word sounds like r's
-- airline (m.airline_sounds, squawk.translate.best_match at lexicon.callsign_confirm.airline or better, the bar a
-- callsign heard inexactly is taken at): "Foobar 3" or
-- "zorbax 400" with DLH3 or DLH400 flying, matched by the flight number alone. The word stands where the airline's
-- name would, so it may name another airline, one not flying: confirmed, never taken. A slip of the airline's own
-- name ("Lufthanza 3", "Hansa 3") and known words before the number ("the", "okay") are read as said. nil
-- otherwise.
function m:airline_unknown(r)
  if not r.spoken or r.heard or not r.exists or not r.name:match("^%a%a%a?%d") then return nil end
  local e, unknown = r.b, nil
  while e < r.e and self.t[e].kind == "word" and not self.t[e].number_word and not L.phonetic[self.t[e].text] do
    if not unknown and not self:known_word(e) then unknown = e end
    e = e + 1
  end
  if not unknown then return nil end
  local of = m.airline_sounds(airline_digits(r.name))
  for b = r.b, unknown do
    local said = ""
    for x = b, e - 1 do said = said .. self.t[x].text end
    local _, score = squawk.translate.best_match(said, of)
    if score and score >= L.callsign_confirm.airline then return nil end
  end
  return self:raw(r.b, r.e)
end

-- The callsigns aircraft reference r may be when it is said with the name of a brand several airlines fly under
-- (names.lua's brands: "Braathens 611" is BRX611 or BRA611, "Virgin 27" VIR27 or VOZ27, "Transavia 33" TRA33 or
-- TVF33) and another aircraft of one of the brand's airlines that bears the name (bears, or the brand's `twins`;
-- not Scoot's TGW31 beside Tigerair Taiwan's TTW31) has the same flight number and letters as r's: r's name first, then the others
-- (ascending). nil otherwise (one such aircraft flying, or the designator typed).
function m:brand_twins(r)
  if r.kind ~= "aircraft" or not r.b then return nil end
  local icao, _, codes = self:airline_at(r.b)
  if not codes or #codes < 2 then return nil end
  local a, d, rest = airline_digits(r.name)
  local ofs = {}
  for _, c in ipairs(codes) do ofs[c] = true end
  if not ofs[a] or d == "" then return nil end
  local out = {}
  for _, ac in ipairs(self.fleet) do
    local a2, d2, rest2 = airline_digits(ac.id)
    if ac.id ~= r.name and ofs[a2] and d2 == d and rest2 == rest and (codes.twins or bears(a2, codes)) then out[#out + 1] = ac.id end
  end
  if #out == 0 then return nil end
  table.sort(out)
  table.insert(out, 1, r.name)
  return out
end

-- The one aircraft flying whose registration the callsign `heard` abbreviates as ICAO radiotelephony does after first
-- contact: its first character and its last two ("Golf Charlie Delta", GCD, for G-ABCD), or an N-number's last
-- characters ("three alpha bravo" for N123AB); nil when none or several fit. Only the question names it: an
-- abbreviated callsign is confirmed, never taken.
function m:abbreviated_registration(heard)
  local one
  for _, ac in ipairs(#heard >= 3 and #heard <= 4 and self.fleet or {}) do
    local id = ac.id:upper()
    local fits = #id > #heard and ((heard:match("^%a+$") and id:sub(1, 1) == heard:sub(1, 1)
      and id:sub(-(#heard - 1)) == heard:sub(2)) or (id:match("^N%d") and heard:match("^%d") and id:sub(-#heard) == heard))
    if fits then
      if one then return nil end
      one = id
    end
  end
  return one
end

-- A spoken callsign matched to an aircraft whose airline or digits differ
-- from what was heard is asked about, unless the speaker confirmed it; so is one said with a later part of
-- its airline's telephony only (m:telephony_part_only), or with its last digit heard as a word
-- (m:homophone_closing).
function m:confirm_callsigns(s)
  local c = L.callsign_confirm
  for _, r in ipairs(self:refs_in(s.b, s.e, "aircraft")) do
    local h = r.heard
    local confirmed = (self.world.confirmed or {})[r.name]
    local part = not confirmed and (self:telephony_part_only(r) or self:homophone_closing(r) or self:number_only(r)
      or self:airline_unknown(r))
    if part then
      self.confirm = self.confirm or { id = r.name, heard = part }
      self:need(string.format("Did you mean %s? I heard '%s'.", r.name, part))
    end
    local twins = not confirmed and r.exists and self:brand_twins(r)
    if twins then
      self:need(string.format("Which %s: %s?", self:raw(r.b, r.e), table.concat(twins, " or ")))
    end
    if h and h.id ~= r.name and not r.false_start and not (self.world.confirmed or {})[r.name]
        and not self:airline_and_digits_match(h.id, r.name)
        and (self:strict_callsigns() or h.airline < c.airline or h.digits < c.digits
          or self:letters_conflict(h.id, r.name)) then
      local unsaid = self:airline_unsaid(r)
      if unsaid then
        self:need(string.format("There is no aircraft '%s'. Which aircraft do you mean?", unsaid))
      else
        local meant = self:abbreviated_registration(h.id) or r.name
        self.confirm = self.confirm or { id = meant, heard = h.id }
        self:need(string.format("Did you mean %s? I heard %s.", meant, h.id))
      end
    end
  end
end

-- Aircraft whose callsign is one slip from `heard`: the same airline and
-- digits transposed, one character missing, extra or different.
function m:near_callsigns(heard)
  local function slips(a, b)
    if a == b then return 0 end
    if #a == #b then
      local diff = {}
      for i = 1, #a do if a:sub(i, i) ~= b:sub(i, i) then diff[#diff + 1] = i end end
      if #diff == 1 then return 1 end
      if #diff == 2 and diff[2] == diff[1] + 1 and a:sub(diff[1], diff[1]) == b:sub(diff[2], diff[2])
          and a:sub(diff[2], diff[2]) == b:sub(diff[1], diff[1]) then
        return 1
      end
      return 2
    end
    if math.abs(#a - #b) ~= 1 then return 2 end
    local long, short = a, b
    if #b > #a then long, short = b, a end
    for i = 1, #long do
      if long:sub(1, i - 1) .. long:sub(i + 1) == short then return 1 end
    end
    return 2
  end
  local out = {}
  local ha, hr = heard:upper():match("^(%a*)(.*)$")
  -- (an airline's IATA designator for its ICAO prefix, "LH401" with DLH400 flying: grammar.lua G.iata_ids)
  local icao = #ha == 2 and self.IATA[ha]
  for _, a in ipairs(self.fleet) do
    local aa, ar = a.id:upper():match("^(%a*)(.*)$")
    if ((aa == ha or aa == icao) and slips(ar, hr) == 1) or (ar == hr and slips(aa, ha) == 1) then
      out[#out + 1] = a.id
    end
  end
  return out
end

-- A typed or spoken callsign of no aircraft, when aircraft are flying: a
-- question naming the ones it may have meant, else nil (and the aircraft
-- meant, once the speaker confirmed it).
function m:unknown_callsign(id)
  -- (one this request creates is known: "create BEE12K ... and give it destination EHAM")
  if #self.fleet == 0 or self:state(id) or (self.created or {})[id:upper()] then return nil end
  local near = self:near_callsigns(id)
  if #near == 1 and (self.world.confirmed or {})[near[1]] then return nil, near[1] end
  if #near == 1 then
    self.confirm = self.confirm or { id = near[1], heard = id }
    return string.format("Did you mean %s? There is no %s.", near[1], id)
  end
  if #near > 1 then
    return string.format("Did you mean %s? There is no %s.", table.concat(near, " or "), id)
  end
  return string.format("There is no aircraft %s. Which aircraft do you mean?", id)
end

-- ("BAW8CK, EIN3T vnav off", "KLM1234 and TRA5X trails red", "say alt KLM12 and EZY45"): aircraft of the segment
-- listed next to each other, "and" or a comma only between them, for an instruction that takes one aircraft: the
-- first is instructed, the others are kept in self.listed_too (their words explained) and get the same commands
-- (G:same_again); aircraft named otherwise stay unexplained, asked.
function m:acid(s, what)
  local ids = self:acids(s)
  if #ids == 0 then
    self:need("Which aircraft should " .. what .. "? Please give its callsign.")
    return nil
  end
  local refs = {}
  for _, r in ipairs(#ids > 1 and self:refs_in(s.b, s.e, "aircraft") or {}) do
    if r.exists and not r.false_start then refs[#refs + 1] = r end
  end
  local listed = #refs == #ids
  for k = 2, listed and #refs or 0 do
    local between = refs[k].b - refs[k - 1].e
    local sep = self.t[refs[k - 1].e]
    listed = listed and refs[k].name ~= refs[k - 1].name and (between == 1 and (self:word(refs[k - 1].e, "and")
      or sep.text == ",") or (between == 2 and sep.text == "," and self:word(refs[k - 1].e + 1, "and")))
  end
  if listed and #refs > 1 then
    self.listed_too = self.listed_too or {}
    for k = 2, #refs do
      self.listed_too[#self.listed_too + 1] = refs[k].name
      self:explain(refs[k - 1].e, refs[k].e)
    end
  end
  return ids[1]
end

-- A value that grew out of range from a stutter or a misheard word ("one
-- four fourteen thousand"): re-read from a shorter run of its words, longest
-- first, preferring multiples of `step`. nil when none fits [lo, hi], for a
-- run that reads zero ("nine zero" is never 0), when the first run that fits
-- leaves out the value's closing zeros ("speed nine zero zero": 900 or 90?),
-- and with `whole` for digits said one by one ("descend eight five": a level
-- said digit by digit, one digit dropped from it is a level nobody said).
function m:repaired(q, value, lo, hi, step, whole)
  if value >= lo and value <= hi then return value end
  local n = q.number
  if n.typed or (whole and n.groups == #n.digits and not n.hundred and not n.thousand) then return nil end
  -- a run may not start inside a compound ("seventy six thousand" is not six thousand)
  local function splits(b)
    return b > n.b and self:word(b - 1, "@tens") and self.t[b].number_word and not self:word(b, "@tens")
  end
  -- (true when words [e, n.e) are all "zero": "two five zero zero" read as 250 left one out)
  local function zeros_after(e)
    local all = e < n.e
    for k = e, n.e - 1 do all = all and self:word(k, "zero") end
    return all
  end
  for _, round_only in ipairs({ true, false }) do
    for len = n.e - n.b - 1, 1, -1 do
      for b = n.b, n.e - len do
        local r = not splits(b) and self.u:number(b, b + len)
        if r and r.thousand == n.thousand and r.value >= lo and r.value <= hi and r.value ~= 0
            and (not round_only or r.value % step == 0) then
          return not zeros_after(b + len) and r.value or nil
        end
      end
    end
  end
  return nil
end

-- A spoken altitude that is not whole hundreds of feet ("two thousand seven
-- hundred ten"), re-read from the longest, leftmost run of its words that is
-- (2700; "one three" = 13 thousand, as "maintain niner"); nil when none is.
function m:whole_hundreds(q)
  local n = q.number
  for len = n.e - n.b - 1, 1, -1 do
    for b = n.b, n.e - len do
      local r = self.u:number(b, b + len)
      if r and r.thousand == n.thousand and r.value > 0 then
        local ft = r.value < 100 and r.value * 1000 or r.value
        if ft % 100 == 0 and ft <= 60000 then return ft end
      end
    end
  end
  return nil
end

-- The candidates of a value instruction: `cands` (those with a unit, else
-- the plain ones), unless a correction is followed by a value of either
-- kind ("flight level two four zero correction two six zero"): then the
-- values after the last correction word.
-- The last correction word of segment s ("correction", or a marker straight after a value: m:marker_after_value),
-- else nil.
-- (an apology closing the request straight after a value, "climb FL150, euh, one six zero pardon", is for the slip
-- before it, no correction point: the value before it stands, G:dangling_correction asking where nothing marked it)
function m:last_correction(s)
  local corr
  local any = self:said("@correction") or self:said(MARKER_WORDS)
  for i = s.b, any and s.e - 1 or 0 do
    if self:word(i, "@correction") then
      corr = i
    elseif self:marker_after_value(i) then
      local k = i + 1
      while self.t[k] and (self.t[k].kind == "punct" or self.t[k].filler) do k = k + 1 end
      if self.t[k] or not self:word(i, "sorry pardon") then corr = i end
    end
  end
  return corr
end
function m:corrected(cands, with_unit, plain, s)
  local corr = self:last_correction(s)
  if not corr then return cands end
  local later = {}
  for _, list in ipairs({ with_unit, plain }) do
    for _, q in ipairs(list) do if q.b > corr then later[#later + 1] = q end end
  end
  if #later == 0 then return cands end
  table.sort(later, function(a, b) return a.b < b.b end)
  return later
end

-- Which candidate counts: after "correction" the first one after it; when
-- the instruction word is repeated, the last; else the first.
-- The value picked is taken (G:take): the leftover check knows it was read.
function m:pick(c, s, repeated)
  if #c == 0 then return nil end
  local corr = self:last_correction(s)
  if corr then
    for _, q in ipairs(c) do if q.b > corr then return self:take(q) end end
    return self:take(c[#c])
  end
  local reps = 0
  for i = s.b, self:said(repeated) and s.e - 1 or 0 do if self:word(i, repeated) then reps = reps + 1 end end
  if reps >= 2 then
    -- "maintain 5000 ... maintain 5000": said again, one value; "heading 200 heading 100", two values with no
    -- correction between: which one stands is asked, never the last taken in silence
    for k = 1, #c - 1 do
      -- (a value the aircraft leaves, "away from heading 180", "out of FL200", is none of them)
      local f = self:word(c[k].b - 1, "heading speed level altitude") and c[k].b - 2 or c[k].b - 1
      local left = self:word(f, "from @level_left leave vacate") or (self:word(f, "of") and self:word(f - 1, "out"))
      self:take(c[k])
      if c[k].value ~= c[#c].value and not left then
        self:need(string.format("I heard '%s' and '%s' for one instruction, with no correction between: which one "
          .. "stands?", self:raw(c[k].b, c[k].e), self:raw(c[#c].b, c[#c].e)))
      end
    end
    return self:take(c[#c])
  end
  return self:take(c[1])
end

-- "at four thousand reduce speed to 210", "when you hit FL180 slow to 250", "(when) passing flight level 130
-- reduce speed 250", "leaving FL340 maintain Mach .82", "when level flight level 350, speed Mach .78"
-- ("level" after a condition word, as "reaching"); "after passing FL100 (resume own navigation) direct HEMEL"
-- (a direct-to waits for a level passed, left or reached; so does a switch of navigation: "on reaching FL120
-- resume own navigation"): "ATALT id alt" or nil.
local NAV_INTENTS = { direct = true, lnav = true, vnav = true }
-- The level [ft] a bare number of three digits, 100 to 600, names when this request already cleared aircraft `id`
-- (any aircraft: id nil) to that flight level ("climb to FL340, then heading 270 when he is at 340"), else nil.
function m:level_given(q, id)
  local ft = self:bare_level_ft(q)
  if not ft then return nil end
  for _, c in ipairs(self.out) do
    local who, level = c:match("^ALT (%S+) (%S+)")
    if level == "FL" .. f.int(ft / 100) and (not id or who == id) then return ft end
  end
  return nil
end
-- The level [ft] a bare number may name when a request has cleared the aircraft to it: three digits, its flight
-- level ("220", "060"), or two said as a number, the thousands of a flight level ("twenty two" for FL220); else nil.
function m:bare_level_ft(q)
  if q.kind ~= "plain" or q.number.thousand or q.number.hundred then return nil end
  local n = #q.number.digits
  if n == 3 and ((q.value >= 100 and q.value <= 600) or (q.value >= 10 and q.number.digits:sub(1, 1) == "0")) then
    return q.value * 100
  end
  if n == 2 and q.value >= 10 and q.value <= 60 then return q.value * 1000 end
  return nil
end
-- True when `ft` [ft] lies strictly between aircraft `id`'s altitude and the level this request cleared it to
-- (its ALT line): a level it crosses on the way ("climb FL160 and when passing one hundred turn left" from FL90).
function m:on_the_way(id, ft)
  local a = self:state(id)
  for _, c in ipairs(self.out) do
    local who, to = c:match("^ALT (%S+) (%S+)")
    local fl = to and to:match("^FL(%d+)$")
    local cleared = fl and tonumber(fl) * 100 or tonumber(to or "")
    if who == id and cleared and a and a.alt_ft and (ft - a.alt_ft) * (ft - cleared) < 0 then return true end
  end
  return false
end
-- words between the level and a speed's own word, part of the instruction ("when it passes FL130 drop the
-- speed to 230", "... bring its speed back to 240", "... make its speed 260", "... make decrease speed to 250", "when
-- pass 7200 meter change speed to mach 0.76", "once you reach FL200 go to speed 300")
local SPEED_LEAD = { drop = true, bring = true, cut = true, take = true, pull = true, knock = true, put = true, make = true, the = true,
                     change = true, go = true, to = true,
                     its = true, your = true, his = true, her = true, their = true }
-- words between the level and a rate's own word, part of the instruction ("passing 150 reduce rate to 1000",
-- "leaving FL100 increase your rate to 2000", "after passing FL150 descend rate 1500": the rate's direction)
local RATE_LEAD = { reduce = true, increase = true, decrease = true, the = true, its = true, your = true,
                    his = true, her = true, their = true, descend = true, climb = true }
-- who does it, between the level and any instruction ("when passing FL200 it shall reduce the speed to 220")
local SUBJECT_LEAD = { it = true, he = true, she = true, they = true, you = true, shall = true, should = true,
                       will = true, can = true, must = true }
-- words between the level and a heading's own word, part of the instruction ("once passing FL110, left heading
-- 160", "... turn right heading 130")
local HEADING_LEAD = { left = true, right = true, turn = true }
-- "on the way down", "on its way up" at k: the position of its "down" or "up", else nil.
function m:crossing_way(k)
  return self:word(k, "on") and self:word(k + 1, "the its your his her their") and self:word(k + 2, "way")
    and self:word(k + 3, "down up") and k + 3 or nil
end
-- True when aircraft `id` crosses level `level_ft` [ft] in the direction said at `way` (G:crossing_way): it is above
-- the level for "down", below it for "up".
function m:way_fits(way, id, level_ft)
  local a = id and self:state(id)
  local down = self:word(way, "down")
  return a ~= nil and a.alt_ft ~= nil and level_ft ~= nil
    and (down and a.alt_ft > level_ft or not down and a.alt_ft < level_ft)
end
function m:at_altitude(s)
  if s.intent ~= "spd" and s.intent ~= "hdg" and s.intent ~= "maintain" and s.intent ~= "alt"
      and not NAV_INTENTS[s.intent] and s.intent ~= "vs" then
    return nil
  end
  -- ("after passing FL100 resume own navigation direct HEMEL": the words leading to the direct-to are a
  -- segment of their own, and the condition is said before them, from the clause's start)
  local b = s.b
  if s.intent == "direct" and self:word(b - 1, "@condition_lead") then
    b = b - 1
    while b > 1 and self.t[b - 1].kind ~= "punct" do b = b - 1 end
  end
  local a = self:find_word(b, s.trig, "at passing leaving reaching through passes leaves reaches pass reach reached hit hits crossing crosses after")
  -- ("after one zero thousand increase speed to 300": a level said straight after "after" is passed; "after
  -- passing FL100" is read at its verb)
  local after_q = self:word(a, "after") and self:quantities(a + 1, s.trig)[1]
  if self:word(a, "after") and not (after_q and after_q.b == a + 1) then
    a = self:find_word(a + 1, s.trig, "at passing leaving reaching through passes leaves reaches pass reach reached hit hits crossing crosses")
  end
  -- ("when you get to FL180 reduce 250", "once it gets to FL180": "to" after "get" is the verb's)
  local got = self:find_word(b, s.trig, "get gets getting")
  local got_to = got < a and self:word(got + 1, "to")
  -- ("once it's down to 10000 feet", "when you're down to FL150": "to" after "down" closing a condition, its
  -- subject and a form of "be" between, G:bound_condition)
  local down = self:find_word(b, a, "down")
  if down < a and self:word(down + 1, "to") and self:bound_condition(down) then got, got_to = down, true end
  if got_to then a = got + 1 end
  -- ("when out of 16000 slow to 280": "out of" after a condition word is a level left; "of" is the verb's)
  local out = self:find_word(b, a, "out")
  local left = out < a and self:word(out + 1, "of") and self:word_in(math.max(b, out - 2), out, "@condition")
  if left then a = out + 1 end
  -- ("once it is above 8000 feet, accelerate": a bound closing a condition is the level crossed, G:bound_condition)
  local bound = self:find_word(b, a, "@above @below")
  if bound < a and self:bound_condition(bound) then a = bound end
  -- ("speed 250, above FL100 speed 300": a bare bound opening a speed's clause, G:bare_bound; its direction below)
  local bare = bound < a and s.intent == "spd" and self:bare_bound(bound)
  if bare then a = bound end
  -- ("when it is on FL260 accelerate", German "auf": "on" after a form of "be" closing a condition is "at")
  local on = self:find_word(b, a, "on")
  if on < a and self:word(on - 1, "is it's") and self:bound_condition(on) then a = on end
  -- ("climb FL150, then on FL150 turn left", Italian "poi a FL150": "on" and a level opening a clause after a
  -- comma, "and" or "then", a value said before it, is "at": m:at_clause's reading)
  if on < a and self:on_clause(on) then a = on end
  if a >= s.trig and s.intent ~= "alt" then
    for i = b, self:said("level") and s.trig - 1 or 0 do
      if self:word(i, "level") and not self:word(i - 1, "flight") and self:word_in(math.max(b, i - 3), i, "@condition") then
        a = i
        break
      end
    end
  end
  -- ("descend FL70 and when you have FL70 reduce 210": "have" or "has" after a condition word and its subject, the
  -- level held, a verb of reaching when no other is said)
  if a >= s.trig then a = self:find_word(b, s.trig, "have has") end
  if a >= s.trig then return nil end
  -- ("when you hit FL180 slow to 250", "once it has reached FL290, descend": "hit" and "reached" are verbs of
  -- reaching only after a condition word; so are "reach" and "reaches" before a level or altitude instruction)
  local reached = self:word(a, "hit hits reached reach reaches have has")
    and self:word_in(math.max(b, a - 3), a, "@condition")
  if self:word(a, "hit hits reached have has") and not reached then return nil end
  -- ("fly at 30000 ft and heading 100": the level flown at, an instruction of its own, no condition)
  if self:word(a, "at on") and self:word(a - 1, "fly flies stay remain cruise") then return nil end
  -- a value said before the condition is another instruction's, which must not wait for it
  if #self:quantities(b, a) > 0 then return nil end
  -- ("when level FL370 maintain Mach .80", "once level at FL370 maintain 250 knots", "when at FL370 maintain M.78":
  -- "maintain" whose own value is a speed keeps no level, so a level reached after "when"/"once" is its condition)
  local kept = s.intent == "maintain" and (self:quantities(s.trig, s.e)[1] or {}).kind
  local held_speed = (kept == "speed" or kept == "mach") and (self:word(a, "level")
    or (self:word(a, "at") and (self:word(a - 1, "when once") or (self:word(a - 1, "level") and self:word(a - 2, "when once")))))
  if (s.intent == "maintain" or s.intent == "alt" or NAV_INTENTS[s.intent] or s.intent == "vs") and not held_speed
      and not self:word(a, "passing leaving reaching") and not reached and not got_to and not left then
    return nil
  end
  -- "passing FL355 descending FL340" is a pilot's report; "when passing ... descend" and "leaving 11000
  -- descend at 1000 feet per minute" (the verb an imperative) a condition
  if (s.intent == "alt" or NAV_INTENTS[s.intent] or s.intent == "vs")
      and not self:word_in(math.max(b, a - 2), a, "@condition") and self.t[s.trig].text:match("ing$") then
    return nil
  end
  local qs = self:quantities(a + 1, s.trig)
  local q = qs[1]
  -- ("when passing altitude 7000 feet turn right": the noun of the value passed, said before it)
  local noun = self:word(a + 1, "altitude height") and q and q.b == a + 2
    and (q.kind == "alt" or (q.kind == "plain" and q.value >= 1000)) and a + 1
  -- ("when you reach the flight level 140 you make speed 280": the article before a level with its unit)
  -- (or before three digits alone, the level this request cleared: "when you reach the 060")
  local article = self:word(a + 1, "the") and q and q.b == a + 2
    and (q.kind == "alt" or (self:word(a, "reach reaches reached reaching") and self:level_given(q) ~= nil))
  if not q or (q.b ~= a + 1 and not noun and not article) then return nil end
  local k = self:skip_fillers(q.e)
  -- ("once you pass 15,000 on the way down, slow down to 250", "when passing FL270 on its way up, ..."): the
  -- direction the level is crossed in, said after it (checked below against the aircraft's climb or descent)
  local way = self:crossing_way(k)
  if way then k = self:skip_fillers(way + 1) end
  while k < s.trig and (self:word(k, "@condition_lead") or (self.t[k].kind == "punct" and self.t[k].text == ",")
      or SUBJECT_LEAD[self.words[k]] or (s.intent == "spd" and SPEED_LEAD[self.words[k]])
      or (s.intent == "vs" and RATE_LEAD[self.words[k]]) or (s.intent == "hdg" and HEADING_LEAD[self.words[k]])
      -- ("when passing FL150 kindly let him turn left": courtesy and "let" with the aircraft's pronoun)
      or self:word(k, "kindly") or (self:word(k, "let") and self:word(k + 1, "him her them"))
      or (self:word(k, "him her them") and self:word(k - 1, "let"))
      -- ("turn it on the right heading 240", "turn to the left": the side's preposition and article)
      or (s.intent == "hdg" and self:word(k, "on to the") and self:word_in(k + 1, math.min(s.trig, k + 3), "left right"))) do
    k = self:skip_fillers(k + 1)
  end
  -- ("crossing FL150 ACA102 reduce 250": the instruction's callsign after a verb's condition; "both at
  -- FL150. TAM88 turn" describes the traffic)
  for _, r in ipairs(self:word(a, "at") and {} or self:refs_in(k, k + 1, "aircraft")) do k = self:skip_fillers(r.e) end
  if k ~= s.trig then return nil end
  -- ("passing two two zero increase Mach .78", "when level one three zero, increase speed 290": three digits
  -- alone after a level passed, left, reached or levelled at are a flight level; so is a level said group-wise,
  -- "passing one hundred", for an aircraft flying where a climb to it would be read so, at or above
  -- lexicon.groupwise_from_ft)
  -- ("once it's through 100": a level passed through, as "passing")
  local passed = q.kind == "plain" and (self:word(a, "passing leaving reaching level through") or left)
  local fl_digits = passed and #q.number.digits == 3 and q.value >= 100 and q.value <= 600 and not q.number.thousand
    and not q.number.hundred
  local groupwise = passed and self:groupwise_level(q)
  -- ("climb FL230, and when he is at 230 Mach .78": three digits alone after "at", the level this request cleared
  -- the aircraft to, are that level; checked for the instruction's aircraft below)
  -- (so are they after a verb of reaching: "climb to FL170, and when it reaches 170, direct PERCH")
  -- (and "climb FL220, at twenty two reduce 260": two said as a number, its thousands)
  local given = q.kind == "plain" and (self:word(a, "at") or reached) and self:level_given(q)
  fl_digits = fl_digits or given
  local fl_ft = given or (fl_digits and q.value * 100)
  if q.kind ~= "alt" and not fl_digits and not groupwise
      and not (q.kind == "plain" and (q.number.thousand or q.value >= 1000)) then
    return nil
  end
  local ids = self:acids(s)
  if #ids == 0 then return nil end
  -- ("KLM12 descend FL210, when DLH4 reaches FL200 reduce 250": an aircraft named after the condition word, another
  -- than one the request named before the clause, and no callsign after the condition: whether the one addressed or
  -- the one named waits and slows is unclear, asked)
  local cw = self:find_word(b, a, "@condition")
  local subj = cw < a and self:refs_in(cw + 1, a, "aircraft")[1]
  if subj and #self:refs_in(a, s.trig, "aircraft") == 0 then
    for _, r in ipairs(self:refs_in(1, b, "aircraft")) do
      if r.name:upper() ~= subj.name:upper() then
        self.ask = string.format("'%s': should %s or %s do what follows? Please say the instruction again with "
          .. "its callsign.", self:raw(cw, s.trig), r.name:upper(), subj.name:upper())
        return nil
      end
    end
  end
  if groupwise and ((self:state(ids[1]) or {}).alt_ft or 0) < L.groupwise_from_ft
      and not self:on_the_way(ids[1], groupwise) then
    return nil
  end
  if given and not self:level_given(q, ids[1]) then return nil end
  -- ("reduce speed 250, on reaching two five zero descend FL150": three digits alone that this request gave the
  -- aircraft as its speed [kt], and not as its level, are the speed reached: ATSPD; given as both, asked)
  if fl_digits and q.kind == "plain" then
    local spd, alt = false, false
    for _, c in ipairs(self.out) do
      spd = spd or c == "SPD " .. ids[1] .. " " .. f.int(q.value)
      alt = alt or c == "ALT " .. ids[1] .. " " .. f.alt(fl_ft, true)
    end
    if spd and alt then
      self.ask = string.format("'%s': should %s wait for speed %s or for %s?", self:raw(a, q.e), ids[1],
        f.int(q.value), f.alt(fl_ft, true))
      return nil
    end
    if spd then
      self:mark_used(q.b, q.e)  -- the condition's speed is not the instruction's value
      return "ATSPD " .. ids[1] .. " " .. f.int(q.value)
    end
  end
  -- (a bare bound is crossed into: "above" by an aircraft below the level, "below" by one above it; else asked)
  local level_ft = groupwise or fl_ft or q.value
  local at_ft = bare and (self:state(ids[1]) or {}).alt_ft
  if bare and not (at_ft and (self:word(bound, "above") and at_ft < level_ft or self:word(bound, "below") and at_ft > level_ft)) then
    return nil
  end
  -- (the direction said is the one the aircraft crosses the level in from where it is; else left unread, asked;
  -- whether it will cross it is G:level_never_crossed's)
  if way then
    if not self:way_fits(way, ids[1], level_ft) then return nil end
    self:explain(way - 3, way + 1)
  end
  -- ("KLM12 at FL280 speed 250" with KLM12 level at FL280: "at" and the level it flies, no condition word before
  -- it, describe where it is: the instruction runs now; leaving that level for another, whether it should wait is
  -- unclear, asked; cycle 65)
  local st = self:state(ids[1])
  local here = not groupwise and not fl_digits and q.kind == "alt" and self:cleared_level(q)
  local opens = a == 1 or self.t[a - 1].kind == "punct" or #self:refs_in(a - 1, a, "aircraft") > 0
  if here and opens and self:word(a, "at") and not self:word_in(math.max(b, a - 2), a, "@condition") and st and st.alt_ft
      and math.abs(st.alt_ft - here) <= 50 then
    local away = st.sel_alt_ft and math.abs(st.sel_alt_ft - st.alt_ft) > 50
    for _, c in ipairs(self.out) do
      if c:match("^ALT " .. ids[1]:gsub("%p", "%%%0") .. " ") then away = true end
    end
    if away then
      self.ask = string.format("%s is at %s now and leaving it: should what follows '%s' run now, or wait (for "
        .. "which level)?", ids[1], f.alt(here, q.fl), "at " .. f.alt(here, q.fl))
      return nil
    end
    self:mark_used(q.b, q.e)
    self:explain(a, q.e)
    return nil
  end
  self:mark_used(q.b, q.e)  -- the condition's altitude is not the instruction's value
  if noun then self:explain(noun, noun + 1) end
  if groupwise then return "ATALT " .. ids[1] .. " " .. f.alt(groupwise, true) end
  if fl_digits then return "ATALT " .. ids[1] .. " " .. f.alt(fl_ft, true) end
  return "ATALT " .. ids[1] .. " " .. f.alt(self:cleared_level(q), q.fl)
end

-- The first word of a verb of waiting ending at w ("wait", "wait for", "give it", "allow him"), or nil.
function m:wait_verb(w)
  local v = self:word(w, "for") and w - 1 or w
  if self:word(v, "@wait_verbs") then return v end
  if self:word(w, "@wait_objects") and self:word(w - 1, "@wait_giving") then return w - 1 end
  return nil
end

-- The first word of a wait said before the time at quantity q (the word before it at w, fillers skipped) for the
-- instruction word at trig, with no "in" or "after" of its own: a verb of waiting said before the instruction and
-- joined to it by a word of lexicon.wait_joins ("wait (for) 60 seconds then ...", "give it a minute and then ..."),
-- "after waiting 2 minutes", "once 90 seconds have passed", "30 seconds from now" (the words after the time
-- explained); nil when none. A "wait" after a word of self-correction ("no wait 2 minutes") is the correction's.
function m:wait_lead(w, q, trig)
  local k = q.e
  while self.t[k] and (self.t[k].kind == "punct" or self.t[k].filler) and not self:word(k, "@wait_joins") do k = k + 1 end
  local v = self:wait_verb(w)
  if v and self:word(v, "@wait_verbs") and self:word(v - 1, "after") then return v - 1 end
  if v and v < trig and self:word(k, "@wait_joins") and not self:word(v - 1, "no oh") then return v end
  if self:word(w, "once when after") and self:word(q.e, "have has had is are") then
    local run = self:word(q.e + 1, "@wait_run") and q.e + 2
    if run and self:word(run - 1, "gone") then run = self:word(run, "by") and run + 1 end
    if run then
      self:explain(q.e, run)
      return w
    end
  end
  -- ("ten minutes of simulated time from now": the clock the time is counted on, named before "from now")
  local now = q.e
  if self:word(now, "of") and self:word(now + 1, "simulated simulation sim") and self:word(now + 2, "time") then
    now = now + 3
  end
  if self:word(now, "from") and self:word(now + 1, "now") then
    self:explain(q.e, now + 2)
    return q.b
  end
  return nil
end

-- "in 2 min turn KL204 left heading 180", "pause it at 30 minutes", "when the clock hits 45 minutes
-- pause the sim": the instruction waits for a time, "DELAY s" after "in"/"after" (from now) or a wait said
-- before it (m:wait_lead), "SCHEDULE hh:mm:ss" after "at", "schedule" or the clock reaching it (simulation
-- time); nil when no time is said or the instruction takes its time as a value (FF, DT, DTLOOK, DTMULT;
-- CRECONFS's time to conflict) or its text as typed after it ("echo exercise starts in 2 minutes": the time is
-- ECHO's text). A time said in words is read the same ("in a minute", "give it half a minute and then"), and a
-- loose one ("in a couple of minutes", "wait a moment then") is asked for a time. A rate set by the simulation's
-- speed ("in 300 seconds set the simulation speed to 2") is no fast-forward: its time after "in"/"after" waits
-- as any instruction's does.
local OWN = {}
for _, w in ipairs(L.aside.own) do OWN[w] = true end
local OWN_TIME = { ff = true, dt = true, dtlook = true, creconfs = true }
-- (the instructions whose values a wait may stand between)
local TIMED_VALUES = { alt = true, spd = true, hdg = true, vs = true, maintain = true, infer = true }
-- "SCHEDULE hh:mm:ss" for a simulation time of t seconds
local function schedule_at(t)
  t = math.floor(t + 0.5)
  return string.format("SCHEDULE %02d:%02d:%02d", t // 3600, t % 3600 // 60, t % 60)
end
-- "delay 300 klm302 dct WP2", "schedule 600 klm303 fl300", "delay 5 min ...": BlueSky's DELAY or SCHEDULE typed by
-- its name as the request's first word, the time straight after it (a bare whole number of seconds, as BlueSky
-- reads it, a time with its unit, or one said in words: "delay half a minute"), times every instruction of the
-- request (self.at_all): "DELAY s" from now, "SCHEDULE hh:mm:ss" at that simulation time. With a callsign straight
-- after the name, no time, or a loose time ("delay a couple of minutes"), the wait is asked for. Read before the
-- request's instructions are parted (G:parse), the name and time marked used.
function m:typed_wait()
  local w = self:skip_fillers(1)
  if not self:word(w, "delay schedule") or self.u:used(w) then return nil end
  -- (a time said in words straight after the name, "delay half a minute then ...", G:spoken_duration)
  local q = self:spoken_duration(w + 1) or self:quantities(w + 1, #self.t + 1)[1]
  if q and q.loose then
    return self:need(string.format("How long should the instructions after '%s' wait? I heard '%s': please give a "
      .. "time.", self.t[w].raw, self:raw(w + 1, q.e)))
  end
  local bare = q and q.kind == "plain" and q.number.typed and q.value >= 0 and q.value % 1 == 0
  if not (q and q.b == w + 1 and (bare or q.kind == "time")) then
    -- (said as English, "schedule a pause at 20 min", it is the instruction's verb, read as before)
    if not self:has_ref(w + 1, w + 2, "aircraft") then return nil end
    return self:need(string.format("How long should the instructions after '%s' wait? Please give the time in "
      .. "seconds (\"%s 300 ...\").", self.t[w].raw, self.words[w]))
  end
  self:mark_used(w, q.e)
  self.at_all = self:word(w, "delay") and "DELAY " .. f.num(q.value) or schedule_at(q.value)
  return self.at_all
end
-- "turn right heading 060 for 2 minutes, then return to its own route", "fly heading 200 for 90 seconds and then
-- resume own navigation": a time said after "for" straight after the value of segment s (a heading, level, speed or
-- rate), then "then" (a comma or "and" before it or not) and the next instruction, is how long the value is held:
-- the next instruction waits that long from now ("DELAY s", kept in self.wait_next for the next segment's
-- m:at_time). True when so read (the time and "for" marked used); the instruction of s runs now.
function m:held_for(s, q, w)
  if not (self:word(w, "for") and q.b > s.trig and TIMED_VALUES[s.intent]) or q.spoken or q.loose then return false end
  local p = w - 1
  while p > s.trig and self.t[p].filler do p = p - 1 end
  local v = self:quantities(s.trig, w)
  v = v[#v]
  if not (v and v.e == p + 1 and v.kind ~= "time") then return false end
  local k = q.e
  while self.t[k] and (self.t[k].filler or (self.t[k].kind == "punct" and self.t[k].text == ",") or self:word(k, "and")) do
    k = k + 1
  end
  if not self:word(k, "@then_words") or not self:any_instruction_in(k + 1, #self.t + 1) then return false end
  self:mark_used(w, q.e)
  self.wait_next = "DELAY " .. f.num(q.value)
  return true
end
function m:at_time(s)
  -- ("at 00:12:00 fast forward 10 minutes", "in 5 minutes fast forward 10 minutes": a fast-forward's own duration
  -- after its verb, a time after "at", "in" or "after" before it is when it starts)
  local ts = s.intent == "ff" and self:durations(s.b, s.e) or {}
  -- ("at sim time 00:20:00 fast forward 10 min": the clock's time named before the start's time)
  local pre = ts[1] and ts[1].b - 1
  if pre and self:word(pre, "time") then pre = self:word(pre - 1, "@sim") and pre - 2 or pre - 1 end
  local ff_at = #ts == 2 and ts[1].e <= s.trig and ts[2].b > s.trig and self:word(pre, "at in after")
  if OWN_TIME[s.intent] and not (s.intent == "ff" and self:word(s.trig, "speed spd airspeed")) and not ff_at then
    return nil
  end
  if s.intent == "echo" and s.trig == self:skip_fillers(1) and self:word(s.trig, "echo") then return nil end
  for _, q in ipairs(self:durations(s.b, s.e)) do
    local w = q.b - 1
    while w > 0 and self.t[w].filler do w = w - 1 end
    -- ("in about two minutes", "in like three minutes": a number of minutes said loosely after "in" or "after" is
    -- the time said, as "about 250 knots" is that speed)
    local hedge = w
    while hedge > 1 and (self.t[hedge].filler or self:word(hedge, "@wait_hedges like")) do
      hedge = hedge - 1
    end
    if hedge < w and not q.loose and self:word(hedge, "in after") then
      self:mark_used(hedge + 1, w + 1)
      w = hedge
    end
    -- (a time of the record in an aside set apart, ", as the controller did at 10:42:15", G:in_reason: accounted)
    if not q.spoken and self:in_reason(q.b) and self:word_in(math.max(1, q.b - 6), q.b, "@record_past") then
      self:mark_used(q.b, q.e)
      return nil
    end
    -- (a time in a reason set aside after the instruction, or in a clause of the speaker's own, "delete KLM12,
    -- we'll re-create it in 2 minutes", is no wait of the instruction: left to the accounting)
    if q.b > s.trig and (self:in_reason(q.b) or self:word_in(s.trig, q.b, OWN)) then return nil end
    if self:held_for(s, q, w) then return nil end
    local lead = not self.taken[q.b] and (self:word(w, "in after") and w or self:wait_lead(w, q, s.trig))
    if q.spoken and lead and q.loose then
      return self:need(string.format("How long should the wait before the instruction be? I heard '%s': please "
        .. "give a time (\"in 2 minutes\").", self:raw(lead, q.e)))
    end
    -- ("twenty minutes into the run, switch on MVP": the clock's time, counted from the run's start)
    local into = self:word(q.e, "into") and (self:word(q.e + 1, "the") and q.e + 2 or q.e + 1)
    into = into and self:word(into, "run @sim exercise experiment scenario") and not lead and into
    -- ("pause at exactly 45 minutes": "exactly" between "at" and the time)
    if not lead and self:word(w, "exactly precisely") and self:word(w - 1, "at") then
      self:mark_used(w, w + 1)
      w = w - 1
    end
    if not self.taken[q.b] and (lead or not q.spoken or into) then
      local clock = into or self:word(w, "@clock_reaches") and self:word_in(math.max(1, w - 3), w, "@sim")
      if into then self:mark_used(q.e, into + 1) end
      -- ("at sim time 00:10:00 freeze": the clock's time named before it)
      if self:word(w, "time") and self:word(w - 1, "@sim") and self:word(w - 2, "at") then
        self:mark_used(w - 1, w + 1)
        w = w - 2
      elseif self:word(w, "time") and self:word(w - 1, "at") then  -- ("at time 120 s", "at t=120 s")
        self:mark_used(w, w + 1)
        w = w - 1
      end
      if not lead and not self:word(w, "at schedule") and not clock then return nil end
      w = lead or w
      -- (after "and" past the instruction word it opens the next instruction: "KL204 climb FL300 and in
      -- 2 minutes EZY45 descend": left uncarried, so asked about)
      if q.b > s.trig and self:word_in(s.trig, w, "and then") then return nil end
      -- (a time of the record compared with, "descend FL110, as the controller did at 10:42:15", "as recorded at
      -- 10:42:15, ...", "... at 10:42:15, as recorded", is no time to act)
      local after = self.t[q.e]
      if (q.b > s.trig and self:word_in(s.trig, w, "@record_time")) or self:word(w - 1, "@record_time")
          or (after and after.text == "," and self:word(q.e + 1, "@aside_comments")) then
        return nil
      end
      -- ("in 2 minutes 30 KL204 climb ...": the times said in a row add up)
      if not q.spoken then
        local total, e = self:time_total(q, s.e)
        if e > q.e then q = { kind = "time", value = total, b = q.b, e = e } end
      end
      self:mark_used(q.b, q.e)
      self:mark_used(w, math.min(w + 1, q.b))
      if lead then self:mark_used(lead, q.b) end
      -- ("pause it at the 20 minute mark": the time's noun after it)
      if self:word(q.e, "mark") then self:mark_used(q.e, q.e + 1) end
      local at = lead and "DELAY " .. f.num(q.value) or schedule_at(q.value)
      -- ("hop7 fl100 in 2 min hdg 220", "descend FL100 in 2 minutes turn left heading 220": a wait between two
      -- instructions with nothing to part them may be the one before's, the one after's or both's: asked)
      local before, after = false, false
      for _, v in ipairs(TIMED_VALUES[s.intent] and self:quantities(s.b, s.e) or {}) do
        before = before or (v.kind ~= "time" and v.e <= w)
        after = after or (v.kind ~= "time" and v.b >= q.e)
      end
      local k = q.e
      while k < s.e and self.t[k].filler and not self:word(k, "and @then_words") do k = k + 1 end
      local next_one = not after and q.b > s.trig and s.e <= #self.t and k == s.e
      -- ("turn right heading 060, in 2 minutes return on your route": words of another instruction after the wait,
      -- no value of their own: which one waits is asked, never the heading delayed and the rest dropped)
      next_one = next_one or (not after and q.b > s.trig and k < s.e and self.t[k].kind == "word"
        and not self:word(k, "and @then_words @aside_comments"))
      if before and (after or next_one) then
        return self:need(string.format("Which instruction should wait '%s': the one before it, the one after it, or "
          .. "both?", self:raw(w, q.e)))
      end
      -- (one that opens the request times every instruction in it: "in 30 seconds KL204 climb ... and
      -- EZY45 descend ..."; after the callsign alone, when it names no other aircraft, every instruction of that
      -- aircraft, `at_all_for`: "KL204, in 2 minutes descend FL100 and turn left heading 220")
      local lead, named = self:skip_fillers(1), self:refs_in(1, #self.t + 1, "aircraft")
      local one = named[1] and named[1].b == lead
      for _, r in ipairs(named) do one = one and r.name:upper() == named[1].name:upper() end
      if one then
        lead = self:skip_fillers(named[1].e)
        while self.t[lead] and self.t[lead].kind == "punct" and self.t[lead].text == "," do lead = self:skip_fillers(lead + 1) end
      end
      -- ("schedule at 00:01:00: KLM1795 FL150, TRA5NB FL140": "schedule" opening the request before "at" too)
      local opening = self:skip_fillers(1)
      if self:word(opening, "schedule") and w == opening + 1 then opening = w end
      if w == opening or w == lead then
        self.at_all, self.at_all_for = at, w == lead and one and named[1].name:upper() or nil
      end
      return at
    end
  end
  return nil
end

-- "when fifteen miles from TARTN descend FL80", "within 10 NM of CGT", "alt
-- 8000 at 30nm from cyyz", "at 10 from GOW desc 3000": "ATDIST id NAME dist" [NM] or nil. A distance
-- said after a place ("10 miles past X") is no such condition: its place
-- stays uncarried and is asked about.
function m:at_distance(s)
  if s.intent ~= "spd" and s.intent ~= "hdg" and s.intent ~= "maintain" and s.intent ~= "alt" and s.intent ~= "vs"
      and s.intent ~= "infer" then
    return nil
  end
  for _, q in ipairs(self:quantities(s.b, s.e)) do
    -- ("at 10 from GOW": a bare number between "at" and "from" a place is its distance, NM)
    local bare = q.kind == "plain" and q.value > 0 and q.value < 1000 and self:word(q.b - 1, "at")
      and self:word(q.e, "from")
    -- ("be level 20 miles before ALFA", "descend to be level FL240 20 miles before ALFA": a level to be
    -- reached by a distance, no condition squawk can carry; its words are left over and asked about)
    local level_at = self:word(q.b, "level fl flight")
    for i = s.b, self:said("level") and q.b - 1 or 0 do level_at = level_at or (self:word(i, "level") and not self:word(i - 1, "flight")) end
    if (q.kind == "dist" or bare) and not self.taken[q.b] and not level_at then
      local k = self:skip_fillers(q.e)
      if self:word(k, "out prior") then k = k + 1 end  -- "20 miles out from X", "15 miles prior to X"
      -- ("cross 15 miles north of Seattle at 10000", "... south east of ...": the side of the place the
      -- aircraft comes from)
      local side = k
      while side < k + 2 and self:word(side, "@compass") do side = side + 1 end
      if side > k and self:word(side, "of from") and self:word_in(s.b, q.b, "cross crossing") then
        self:explain(k, side)
        k = side
      end
      local p = self:word(k, "from of to before") and self:skip_fillers(k + 1)
      -- ("at 30 DME Sydney reduce 180": a distance in DME said straight before its station's name or ident, a
      -- navaid)
      local dme = not p and self:word(q.e - 1, "dme") and k < s.trig and self.t[k].kind == "word" and k
      p = p or dme
      -- (the navaid's kind said before its name, "from the VOR Bogota", is no place of its own)
      if p and self:word(p, "@navaid_kinds") and self.t[p + 1] and self.t[p + 1].kind == "word" then p = p + 1 end
      local r = p and self:refs_in(p, p + 1, "waypoint")[1]
      local ids = p and self:acids(s) or {}
      -- ("when 20 miles from Minna descend FL200", "ten miles from Zurich East descend": a navaid or airport
      -- said by its name, of one or two words)
      local state = #ids == 1 and self:state(ids[1])
      -- ("within 20 nm of eham": an airport's ICAO code typed in lower case, no English word, that the navdata holds)
      local code = p and self.t[p] and self.t[p].raw:match("^%l%l%l%l$") and not self:known_word(p)
        and self.world.place_known and self.world.place_known(self.t[p].raw:upper()) and self.t[p].raw:upper()
      local name = r and r.name or (dme and state and self:navaid_by_name(p, math.min(s.trig, p + 2), state))
        or (state and code) or (p and state and self:place_by_name(p, math.min(s.e, p + 2), state, true))
      -- ("20 miles of tango oscar lima": letters spelled in the phonetic alphabet that name no waypoint of the
      -- route, never the navaid named by the first letter's word alone: asked)
      if not r and p and self.words[p + 1] and L.phonetic[self.words[p] or ""] and L.phonetic[self.words[p + 1]] then
        return self:need(string.format("'%s': which place is that? The letters name no waypoint on the route.",
          self:raw(q.b, math.min(s.trig, p + 3))))
      end
      if name then
        if #ids ~= 1 then return nil end
        self:mark_used(q.b, q.e)  -- the condition's distance is not the instruction's value
        self:explain(q.e, p)  -- ("out from", "prior to")
        return "ATDIST " .. ids[1] .. " " .. name .. " " .. f.num(q.value)
      end
      -- ("at 15nm from it descend 4000", "UPS77 10 miles from touchdown reduce 180": a distance opening a
      -- condition, after "at", "when", "once" or the callsign, from words that name no place squawk knows, is a
      -- condition it cannot place either: asked, never dropped; "you're 15 miles from the marker" informs)
      local opens = self:word(q.b - 1, "at when once")
      for _, r in ipairs(opens and {} or self:refs_in(s.b, q.b, "aircraft")) do opens = opens or r.e == q.b end
      -- ("within 20 miles of lima oscar tango descend 3000": "within" a distance of a place, before the
      -- instruction word, opens its condition too)
      local within = self:word(q.b - 1, "within") and q.b < s.trig
      if q.kind == "dist" and p and (self:word(k, "from") or (within and self:word(k, "of"))) and (opens or within) then
        return self:need(string.format("'%s': from which place? squawk waits for a distance from a named fix, "
          .. "navaid or airport (ATDIST).", self:raw(q.b, math.min(s.e, p + 1))))
      end
      -- ("at 30 DME reduce 180", "at 12 miles descend 4000": a distance opening the instruction with no place it
      -- is counted from is a condition squawk cannot place, asked, never dropped)
      if q.kind == "dist" and (self:word(q.b - 1, "at") or within) and not p then
        return self:need(string.format("'%s' from where? Please name the place the distance is counted from.",
          self:raw(q.b - 1, q.e)))
      end
    end
  end
  return nil
end

-- True when level quantity q is the one the aircraft leaves, said straight before level b it flies to:
-- "from FL240 to FL250", a readback's "leaving FL260 for FL200", "leave FL110 for 9000 feet", "out of 9000
-- for 6000" (the words before q are explained).
function m:level_left(q, b)
  if not (b and b.kind == "alt" and b.b == q.e + 1) then return false end
  local left = (self:word(q.b - 1, "from") and self:word(q.e, "to")) and q.b - 1
    or (self:word(q.b - 1, "@level_left leave vacate") and self:word(q.e, "for to") and q.b - 1)
    or (self:word(q.b - 1, "of") and self:word(q.b - 2, "out") and self:word(q.e, "for to") and q.b - 2)
  if left then self:explain(left, q.b) end
  return left and true or false
end

-- "speed 300 to 260 reduce", "heading 090 to 110 change": two values of one kind with only "to" between,
-- the first within `tol` of the aircraft's present value `now` (degrees when `circle`): the value it leaves,
-- then the one it flies to. True, the first value taken and explained, when so; a first value that is not
-- the present one stays a value of its own (the leftover check asks about it).
function m:value_left(a, b, now, tol, circle)
  if not (a and b and now and b.b == a.e + 1 and self:word(a.e, "to")) then return false end
  local d = a.value - now
  if circle then d = (d + 180) % 360 - 180 end
  if math.abs(d) > tol then return false end
  self:take(a)
  self:explain(a.b, b.b)
  return true
end

-- True when value q, said before token `trig`, stands in a sentence that ends (".", "!", ":") before
-- `trig`: "students see: both at FL150 opposite direction. LATAM 3090 turn right 30 degrees" gives no
-- instruction the level. A level after "at" in such a sentence with no aircraft and no instruction word
-- ("both at FL150", "they are at FL150") describes the traffic: it is taken and its sentence explained;
-- any other value there is left for the leftover check to ask about.
function m:sentence_before(q, trig)
  local function ends(k)
    local t = self.t[k]
    return t ~= nil and t.kind == "punct" and (t.text == "." or t.text == "!" or t.text == ":")
  end
  local stop = q.e
  while stop < trig and not ends(stop) do stop = stop + 1 end
  if stop >= trig then return false end
  local start = q.b
  while start > 1 and not ends(start - 1) do start = start - 1 end
  local described = q.kind == "alt" and self:word(q.b - 1, "at") and not self:has_ref(start, stop, "aircraft")
  for k = start, stop - 1 do described = described and not self:intent_at(k) end
  if described then
    self:take(q)
    self:explain(start, stop + 1)
  end
  return true
end

-- True when quantity q is said after "at" that opens a clause after a value said before it: a comma, a full stop or
-- a semicolon (a list's next step: "1. climb FL080, 2. at FL080 turn left"), "and" or "then" before "at" ("climb
-- FL160, at FL160 ...", "... then at FL160 ...", "... and at FL140 ..."), or a level
-- straight before "at" when q is a level too (a recogniser's "climb and maintain FL240 at 15000 increase speed":
-- no level is said "at" another).
function m:at_clause(q)
  local k = q.b - 2
  if not (self:word(q.b - 1, "at") and self.t[k] ~= nil) then return false end
  if (self.t[k].kind == "punct" and (", . ;"):find(self.t[k].text, 1, true)) or self:word(k, "and @then_words") then
    return #self:quantities(1, k) > 0
  end
  if q.kind ~= "alt" then return false end
  local before = self:quantities(1, q.b - 1)
  before = before[#before]
  return before ~= nil and before.kind == "alt" and before.e == q.b - 1
end

-- True when "on" at k opens a clause with a level straight after it (FL or feet), after a comma, "and" or
-- "then" and a value said before ("climb FL150, then on FL150 turn left heading 010"): the level the clause
-- waits for, as "at" (m:at_clause).
function m:on_clause(k)
  if not self:word(k, "on") then return false end
  local q = self:quantities(k + 1, math.min(#self.t + 1, k + 4))[1]
  if not (q and q.b == k + 1 and q.kind == "alt" and (q.fl or self:word(q.e - 1, "@feet"))) then return false end
  local p = self.t[k - 1]
  if not p or not ((p.kind == "punct" and p.text == ",") or self:word(k - 1, "and @then_words")) then return false end
  return #self:quantities(1, k - 1) > 0
end

-- "AC02: heading 180, FL200, 250 kts", "dct NORKU FL200": values with
-- units of another kind around a value instruction or a direct-to are
-- instructions too.
local CARRIES_OTHERS = { hdg = true, alt = true, spd = true, infer = true, maintain = true, vs = true, direct = true }
-- "once level", "when it's level", "once he's there" said straight before the value at b (punctuation between):
-- the token of "once"/"when" (G:reached_opening), or nil
local function level_reached_before(self, b)
  local k = b - 1
  while self.t[k] and self.t[k].kind == "punct" do k = k - 1 end
  return self:word(k, "level lvl there") and self:reached_opening(k) or nil
end
function m:leftovers(s)
  if not CARRIES_OTHERS[s.intent] then return end
  local ids = self:acids(s)
  if #ids ~= 1 then return end
  local out = table.concat(self.out, " ; ")
  local alt_done = s.intent == "alt" or out:find("ALT " .. ids[1] .. " ", 1, true) ~= nil
  local spd_done = s.intent == "spd" or out:find("SPD " .. ids[1], 1, true) ~= nil
  local hdg_done = s.intent == "direct"  -- a direct-to is its lateral instruction
  local qs = self:quantities(s.b, s.e)
  -- (a speed or level a correction takes back, "thereafter Mach .76, no, correction, 280 knots": the value of its
  -- family said after the correction is the one meant)
  local function family(q) return (q.kind == "mach" or q.kind == "speed") and "spd" or q.kind end
  local function taken_back(k)
    local q, corr = qs[k], self:said("@correction") and self:find_word(qs[k].e, s.e, "@correction")
    if not corr or corr >= s.e then return false end
    for j = k + 1, #qs do
      if qs[j].b > corr and family(qs[j]) == family(q) and (q.kind ~= "alt" or q.fl) then return true end
      if qs[j].b > corr then return false end
    end
    return false
  end
  -- (a value said after another flying aircraft named after the instruction word, in its clause, "hdg 100
  -- avoiding RYR8 FL310", "behind RYR8 at FL310", may be that aircraft's: left over, it is asked)
  local theirs = {}
  for _, r in ipairs(self:refs_in(s.trig, s.e, "aircraft")) do
    local k = r.e
    while r.exists and r.name:upper() ~= ids[1]:upper() and k < s.e and self.t[k].kind ~= "punct"
        and not self:word(k, "and @then_words") do
      theirs[k] = true
      k = k + 1
    end
  end
  for k, q in ipairs(qs) do
    -- (the level left, "leaving FL260 for FL200", is no instruction: the one after it is)
    if q.kind == "alt" and not alt_done and self:level_left(q, qs[k + 1]) then self:take(q) end
    if (q.kind == "speed" or q.kind == "mach" or q.kind == "alt") and not self.taken[q.b] and taken_back(k) then
      self:take(q)
    end
    -- a level or speed with its unit, before the instruction word too ("klm1234 fl280 spd 300", "FIN3CA:
    -- 9000ft, spd 220"; a level or height after "below"/"above" is a condition or a limit on something
    -- else, no level to fly: left over, it is asked)
    local bound = self:word(q.b - 1, "@below @above")
    local feet = self:word(q.e - 1, "@feet")
    local unit = (q.kind == "alt" and not bound and (q.fl or feet)) or q.kind == "speed" or q.kind == "mach"
    if bound and q.kind == "alt" and (q.fl or feet) and q.b < s.trig and not self.taken[q.b]
        and not self:bound_condition(q.b - 1) then
      self:need(string.format("What does '%s' mean for %s: a level to fly, or one the instruction waits for or "
        .. "keeps to?", self:raw(q.b - 1, q.e), ids[1]))
    end
    -- in spoken order: one said before the instruction word goes before its command
    local emit = q.b < s.trig and function(line) table.insert(self.out, #self.out, line) end
      or function(line) self:emit(line) end
    if not self.taken[q.b] and not theirs[q.b]
        and (q.b > s.trig or (unit and s.trig > s.b and not self:sentence_before(q, s.trig))) then
      if q.kind == "alt" and not alt_done and (q.fl or self:word(q.e - 1, "@feet")) then
        -- "FL300 at 2000 fpm": the rate said with the level is the climb's or descent's (ALT's vspd)
        local rate = self:quantities(q.e, math.min(#self.t + 1, q.e + 4))[1]
        rate = rate and rate.kind == "vs" and self:skip_fillers(q.e) == rate.b - (self:word(q.e, "at") and 1 or 0)
          and not self.taken[rate.b] and rate
        emit("ALT " .. ids[1] .. " " .. f.alt(q.value, q.fl) .. (rate and " " .. f.int(math.abs(self:take(rate).value)) or ""))
        alt_done = self:take(q)
      elseif (q.kind == "speed" or q.kind == "mach") and not spd_done then
        -- ("descend FL120 and 250 kt below FL100", "climb FL170, Mach .74 when passing FL150": the level
        -- after "above" or "below", or "when"/"once" and a verb of passing, is the one the speed waits for,
        -- G:trailing_level's reading)
        local at = self:word(q.e, "above below") and q.e + 1
        if self:word(q.e, "when once") and self:word(q.e + 1, "passing reaching crossing through") then at = q.e + 2 end
        local held = qs[k + 1]
        held = at and held and held.kind == "alt" and held.b == at and not self:word(q.b - 1, "not")
          and not self.taken[held.b] and held
        -- ("climb FL160, then at FL160 280 knots": a level after "at" opening a clause straight before the speed,
        -- the level given already, is the one the speed waits for)
        -- ("climb FL310, and once he's at FL280, Mach .78": a level closing a condition, G:bound_condition, a comma
        -- between it and the speed)
        local prior = qs[k - 1]
        local comma = prior and self.t[prior.e] and self.t[prior.e].text == "," and prior.e + 1 == q.b
        if not held and alt_done and prior and prior.kind == "alt" and (prior.e == q.b or comma)
            and not self.taken[prior.b]
            and (self:at_clause(prior) or self:word(prior.b - 1, "at passing reaching through leaving crossing")
              and self:bound_condition(prior.b - 1)) then
          held = prior
        end
        -- ("climb FL370 and once level, Mach .80": the speed waits for the level this request gave the aircraft)
        local c = not held and level_reached_before(self, q.b)
        local level = c and table.concat(self.out, " ; "):match("ALT " .. ids[1]:gsub("%p", "%%%0") .. " (FL%d+)")
        if level then self:explain(c, q.b) end
        emit((held and "ATALT " .. ids[1] .. " " .. f.alt(held.value, held.fl) .. " "
            or level and "ATALT " .. ids[1] .. " " .. level .. " " or "") .. "SPD " .. ids[1] .. " "
          .. (q.kind == "mach" and f.mach(q.value) or f.int(q.value)))
        if held then self:take(held) end
        spd_done = self:take(q)
      elseif q.kind == "plain" and q.number.typed and self.t[q.b].raw:match("^%.%d%d?$") and not spd_done
          and q.value >= 0.4 and q.value < 1 then
        -- a typed ".78" beside other values is a Mach number ("dlh402 fl250 .78")
        emit("SPD " .. ids[1] .. " " .. f.mach(q.value))
        spd_done = self:take(q)
      elseif s.intent ~= "hdg" and not hdg_done and q.kind == "plain" and H.zero_led_heading(q) then
        -- three spoken digits led by zero are a heading: no level or speed is said so
        emit("HDG " .. ids[1] .. " " .. f.num(q.value))
        hdg_done = self:take(q)
      end
    end
  end
end

-- Three digits said one by one before the first instruction word, after a
-- recognised callsign: a heading whose "fly heading" was lost.
function m:orphan_heading(s)
  if s.trig == s.b or s.intent == "hdg" or s.intent == "infer" then return end
  for _, q in ipairs(self:quantities(s.b, s.trig)) do
    local n = q.number
    if q.kind == "plain" and not n.typed and n.groups == 3 and n.lead_digit and q.value <= 360 and not n.hundred
        and not (q.b > 1 and self:word(q.b - 1, "at")) then
      local call
      for _, r in ipairs(self.refs) do if r.kind == "aircraft" and r.e <= q.b then call = r end end
      local prev = self.t[q.b - 1]
      if call and q.b > call.e and prev.kind == "word" and not prev.number_word then
        local ids = self:acids(s)
        if #ids ~= 1 then return end
        self:emit("HDG " .. ids[1] .. " " .. f.num(wrap(q.value)))
        self:mark_used(q.b, q.e)
        return
      end
    end
  end
end

require("translate.handlers_values")(H, f, wrap, compass)
require("translate.handlers_other")(H, f, compass)

return H
