-- Aircraft type names, generated from what squawk's performance models know
-- (squawk.sim.types(): OpenAP's types with their titles, "Boeing 777-300ER",
-- when OpenAP data is given; the class model's named designators) and the
-- designators and titles of translate/names.lua, by rules, never row by row:
--   * a title "Maker Model" gives maker + model, the model with its spaces
--     joined or hyphenated ("737 MAX 8" -> "737max8", "737-max-8"), each
--     alternative of "777-200/200ER", Boeing's short MAX names ("737-8"),
--     Airbus models without their letter ("321neo") and "neo" apart;
--   * a designator gives the name its pattern spells: B7FV -> 7F7-V00 and B7F7-V00
--     (B738 -> 737-800, B737-800), A3FV -> A3F0-V00 (A332 -> A330-200), A318-A321 -> their
--     series (A320 -> A320-200), ATFV -> ATR F2-V00 and ATRF2 (AT76 -> ATR 72-600), DH8x ->
--     Dash 8-x00, Q x00 and DHC-8-x00, CRJn -> CRJ n00 and CRJ-n00, CRJX -> CRJ1000,
--     Cnnn -> Cessna nnn, E1nn -> Embraer E1nn (E135/E145 also ERJ-135/145), E75L/E75S -> E175, BCSn -> Airbus A220-n00 and Bombardier CSn00,
--     SRnn -> Cirrus SRnn, PCnn -> Pilatus PC-nn, F28/F50/F70/F100 -> Fokker nn;
--   * a family ("737", "a330") is its base designator when one exists (B737,
--     A320), else its first variant.
-- M.build(designators) -> {types = {{maker, model, icao}, ...}, phrases = {{words, designator}, ...},
--   designators = every designator known (the models' and the given ones), sorted,
--   families = {[family's number, lower case: "777", "a330"] = {[designator] = true}: its variants},
--   makers = {[maker, lower case] = {[designator] = true}: every type of that maker, its E75L as its E175},
--   aliases = {[designator] = designator}: a designator whose spelling is a model's name that the
--   performance data's titles or another designator's pattern give to that other designator ("E175", the
--   Embraer 175's model name, is the E75L): read as the other, never written (its rows name the other)}
--   phrases: names of several words ("737 max 8", "dash 8-400") and their
--   designator, which M.join(text, phrases) writes in their place (the
--   matcher reads one token).
local M = {}

-- (`makers`: maker -> {designator = true}, every designator a maker's name is given to, kept when the
-- name itself is a row of another designator already: "Embraer" names the E75L as well as the E175)
local function add(rows, seen, makers, maker, model, icao)
  makers[maker] = makers[maker] or {}
  makers[maker][icao] = true
  model = model:lower()
  local key = maker .. "|" .. model
  if model == "" or seen[key] then return end
  seen[key] = true
  rows[#rows + 1] = { maker, model, icao }
end

-- The family's number of a model's name in lower case ("737-800", "737 max 8" -> "737"; "a320-200",
-- "a320neo" -> "a320": the neo is a variant of its family), or nil
local function family_of(model)
  return model:match("^(a?%d%d%d)[%-%s]") or model:match("^(a%d%d%d)neo$")
end

-- Spellings of one model of `maker` (lower case) as written in a title ("737 MAX 8", "A321neo"); a Boeing
-- variant also with its designator's letter before it ("B737-800", "B787-9", "B777-300ER").
local function spellings(model, maker)
  local m = model:lower():gsub("%s*%(.-%)", ""):gsub("^%s+", ""):gsub("%s+$", "")
  local out = { m }
  if maker == "boeing" and m:match("^7%d7%-") then out[#out + 1] = "b" .. m end
  if m:find(" ") then
    out[#out + 1] = (m:gsub(" ", ""))
    out[#out + 1] = (m:gsub(" ", "-"))
  end
  local fam, max = m:match("^(%d%d%d) max (%d+)$")
  if fam then out[#out + 1] = fam .. "-" .. max; out[#out + 1] = "max" .. max end
  local base, neo = m:match("^(a%d%d%d)(neo)$")
  if base then
    out[#out + 1] = base:sub(2) .. neo
    out[#out + 1] = base .. " neo"
    out[#out + 1] = base:sub(2) .. " neo"  -- ("Airbus 320 neo")
  end
  return out
end

-- The series of the Airbus A318 to A321 built, each a name of its designator ("A320-200")
local A32_SERIES = { A318 = { "100" }, A319 = { "100" }, A320 = { "100", "200" }, A321 = { "100", "200" } }

-- Names a designator's pattern spells: {{maker, model}, ...}.
local function pattern_names(d)
  local out = {}
  local f, v = d:match("^B7(%d)(%d)$")
  if f then out[#out + 1] = { "boeing", "7" .. f .. "7-" .. v .. "00" } end
  f, v = d:match("^A3(%d)(%d)$")
  if f and tonumber(f) >= 3 then out[#out + 1] = { "airbus", "a3" .. f .. "0-" .. v .. "00" } end
  -- (the A300: A306 is the A300-600, of the family "a300"; A310 is its own designator, below)
  if f == "0" then out[#out + 1] = { "airbus", "a300-" .. v .. "00" } end
  if f and tonumber(f) < 3 then
    out[#out + 1] = { "airbus", d:lower() }
    for _, series in ipairs(A32_SERIES[d] or {}) do out[#out + 1] = { "airbus", d:lower() .. "-" .. series } end
  end
  f, v = d:match("^AT(%d)(%d)$")
  if f then
    out[#out + 1] = { "atr", f .. "2-" .. v .. "00" }
    out[#out + 1] = { "atr", f .. "2" }
    out[#out + 1] = { "atr", "atr" .. f .. "2" }  -- ("ATR72": the maker typed against the model)
  end
  local x = d:match("^DH8(%a)$")
  if x then
    local n = ("ABCD"):find(x, 1, true)
    out[#out + 1] = { "dash", "8-" .. n .. "00" }
    out[#out + 1] = { "bombardier", "q" .. n .. "00" }
    out[#out + 1] = { "bombardier", "dhc-8-" .. n .. "00" }
    if x == "D" then out[#out + 1] = { "dash", "8" } end  -- the family's name is its latest variant
  end
  v = d:match("^B78(%w)$")
  if v then out[#out + 1] = { "boeing", "787-" .. (v == "X" and "10" or v) } end
  v = d:match("^B3(%w)M$")
  if v then out[#out + 1] = { "boeing", "737 max " .. (v == "X" and "10" or v) } end
  v = d:match("^A(%d)(%d)N$")
  if v then out[#out + 1] = { "airbus", "a3" .. d:sub(2, 3) .. "neo" } end
  -- (the 747's last series is named by its digit alone, as the 787s are: "747-8", "747-8i")
  if d == "B748" then out[#out + 1] = { "boeing", "747-8" }; out[#out + 1] = { "boeing", "747-8i" } end
  if d == "B77W" then out[#out + 1] = { "boeing", "777-300er" } end
  -- (the 777 freighter, 777F, flies under the 777-200LR's designator)
  if d == "B77L" then
    out[#out + 1] = { "boeing", "777-200lr" }; out[#out + 1] = { "boeing", "777f" }
    out[#out + 1] = { "boeing", "777 freighter" }
  end
  if d == "A35K" then out[#out + 1] = { "airbus", "a350-1000" } end
  -- (the A330's re-engined series is only a neo: A338 and A339 are the A330-800neo and A330-900neo)
  if d == "A338" or d == "A339" then out[#out + 1] = { "airbus", "a330-" .. d:sub(4) .. "00neo" } end
  local c = d:match("^CRJ(%d)$")
  if c then
    out[#out + 1] = { "bombardier", "crj" .. c .. "00" }
    out[#out + 1] = { "bombardier", "crj-" .. c .. "00" }
    -- (the Canadair Regional Jet: Canadair designed it before Bombardier bought the company)
    out[#out + 1] = { "canadair", "crj" .. c .. "00" }
  end
  if d == "CRJX" then out[#out + 1] = { "bombardier", "crj1000" } end
  c = d:match("^C(%d%d%d)$")
  if c then out[#out + 1] = { "cessna", c } end
  c = d:match("^E(1%d%d)$")
  if c then out[#out + 1] = { "embraer", "e" .. c }; out[#out + 1] = { "embraer", c } end
  -- (the regional jets' own name, ERJ, for the 135 and 145: "ERJ-145", "ERJ145")
  if c == "135" or c == "145" then out[#out + 1] = { "embraer", "erj" .. c }; out[#out + 1] = { "embraer", "erj-" .. c } end
  c = d:match("^BCS(%d)$")  -- (the CSeries became the Airbus A220)
  if c then out[#out + 1] = { "airbus", "a220-" .. c .. "00" }; out[#out + 1] = { "bombardier", "cs" .. c .. "00" } end
  c = d:match("^SR(%d%d)$")
  if c then out[#out + 1] = { "cirrus", "sr" .. c } end
  c = d:match("^PC(%d%d)$")
  if c then out[#out + 1] = { "pilatus", "pc-" .. c } end
  c = d:match("^SF(%d%d)$")
  if c then out[#out + 1] = { "saab", c .. "0" } end
  if d == "SB20" then out[#out + 1] = { "saab", "2000" } end
  -- (Sikorsky's helicopters by their model, "S-92", "S-76")
  c = d:match("^S(%d%d)$")
  if c then out[#out + 1] = { "sikorsky", "s-" .. c }; out[#out + 1] = { "sikorsky", "s" .. c } end
  c = d:match("^F(%d+)$")  -- (Fokker's airliners: F28, F50, F70, F100; never a fighter's F16)
  if c == "28" or c == "50" or c == "70" or c == "100" then out[#out + 1] = { "fokker", c } end
  if d == "B350" then out[#out + 1] = { "beechcraft", "king air 350" } end
  if d == "BE20" then out[#out + 1] = { "beechcraft", "king air 200" } end
  if d == "E75L" or d == "E75S" then out[#out + 1] = { "embraer", "e175" }; out[#out + 1] = { "embraer", "175" } end
  -- military transports and tankers, by the names their air forces give them ("C-17", "KC-135", "E-3", "A400M")
  if d == "C17" then out[#out + 1] = { "boeing", "c-17" } end
  if d == "C130" then out[#out + 1] = { "lockheed", "c-130" } end
  if d == "K35R" then out[#out + 1] = { "boeing", "kc-135" }; out[#out + 1] = { "boeing", "kc-135r" } end
  if d == "E3TF" then out[#out + 1] = { "boeing", "e-3" }; out[#out + 1] = { "boeing", "e-3a" } end
  if d == "A400" then out[#out + 1] = { "airbus", "a400m" } end
  return out
end

-- Names a family of types is known by that spell no designator (lower case, one word, as said after
-- "the": "the Citation") -> the patterns of its ICAO designators: a flying aircraft of any type that
-- matches is one of the family, whether the performance models know its type or not (C525, C56X).
M.nicknames = {
  citation = { "^C5%d%w$", "^C6[58]%w$", "^C7[05]0$", "^C25%u$" },  -- (Cessna's business jets)
  jumbo = { "^B74%w$" },
  dreamliner = { "^B78%w$" },
  learjet = { "^LJ%d%d$" },
  gulfstream = { "^GLF%d$", "^G%d%d%d$" },
  caravan = { "^C208$" },
  skyhawk = { "^C172$" },
  pilatus = { "^PC%d%d$" },
  baron = { "^BE5[58]$" },
  bonanza = { "^BE3[356]$" },
  piper = { "^P28%w$", "^PA%d%d%w?$" },
  archer = { "^P28A$", "^PA28$" },
  cherokee = { "^P28%w$", "^PA28$" },
  skylane = { "^C182$" },
  mooney = { "^M20%w$" },
  -- (Diamond Aircraft's DA20 Katana, DA40 Diamond Star, DA42 Twin Star, DA50, DA62)
  diamond = { "^DV20$", "^DA%d%d$" },
  -- (two words, read together where a nickname opens an abbreviated callsign or follows "the")
  ["king air"] = { "^BE[29]0$", "^B350$" },
  -- (the Super Puma: the AS332 and the EC225 / H225 that followed it)
  ["super puma"] = { "^AS32$", "^EC25$" },
  eurofighter = { "^EUFI$" },
  typhoon = { "^EUFI$" },
  tornado = { "^TOR$" },
  hercules = { "^C130$" },
  herc = { "^C130$" },
  -- (regional families named without their variant: "the CRJ" is a CRJ200 to CRJ1000, "the ATR" an ATR 42 or 72)
  crj = { "^CRJ%w$" },
  atr = { "^AT[4-7]%w$" },
  -- ("the MAX": any 737 MAX; "the bus": any Airbus airliner)
  max = { "^B3%wM$" },
  bus = { "^A3%d%w$", "^A%d%dN$", "^BCS%d$" },
  -- ("the widebody": a wide-body airliner, two aisles: Boeing 747/767/777/787, Airbus A300/A310, A330/A340/A350/A380,
  -- MD-11, DC-10; the 757 is none)
  widebody = { "^B7[4678]%w$", "^A30%d$", "^A310$", "^A3[345]%w$", "^A388$", "^MD11$", "^DC10$" },
  ["wide-body"] = { "^B7[4678]%w$", "^A30%d$", "^A310$", "^A3[345]%w$", "^A388$", "^MD11$", "^DC10$" },
  ["wide body"] = { "^B7[4678]%w$", "^A30%d$", "^A310$", "^A3[345]%w$", "^A388$", "^MD11$", "^DC10$" },
  -- ("the KLM heavy", "the super": ICAO's wake turbulence category said as a noun, heavy a wide-body or heavy military
  -- transport (136 t or more), the A380 "super" alone)
  heavy = { "^B7[4678]%w$", "^A30%d$", "^A310$", "^A3[345]%w$", "^MD11$", "^DC10$", "^IL76$", "^C17$", "^C5M?$" },
  super = { "^A388$" },
  -- ("the E-jet": Embraer's E170 to E195 and the E2s, and the ERJ 135/145 the name is given to as well, R90)
  ejet = { "^E1[79][05]$", "^E75%u$", "^E29[05]$", "^E1[34]5$", "^E[34]5%u$" },
  ["e-jet"] = { "^E1[79][05]$", "^E75%u$", "^E29[05]$", "^E1[34]5$", "^E[34]5%u$" },
  ["e jet"] = { "^E1[79][05]$", "^E75%u$", "^E29[05]$", "^E1[34]5$", "^E[34]5%u$" },
  -- ("the regional jet": a jet airliner of under about 130 seats: the CRJs, the E-jets and ERJs, the Superjet,
  -- ARJ21, BAe 146 / Avro RJ, Fokker 70/100, Dornier 328JET; no turboprop)
  ["regional jet"] = { "^CRJ%w$", "^E1[79][05]$", "^E75%u$", "^E29[05]$", "^E1[34]5$", "^E[34]5%u$", "^SU95$",
    "^AJ27$", "^B46[123]$", "^RJ%w%w$", "^F70$", "^F100$", "^J328$" },
  -- ("the trijet": an airliner or business jet with three engines: MD-11, DC-10, TriStar, 727, Falcon 50/900/7X/8X)
  trijet = { "^MD11$", "^DC10$", "^L101$", "^B72%w$", "^FA50$", "^F900$", "^FA[78]X$" },
  ["tri-jet"] = { "^MD11$", "^DC10$", "^L101$", "^B72%w$", "^FA50$", "^F900$", "^FA[78]X$" },
}

-- ("the helicopter", "the chopper", "the turboprop"): a role named by the performance models' class of a type
-- (squawk.sim.types()' class) is every designator of that class
-- M.role_words: the nicknames that name a role or class rather than a family (an aircraft of an unknown type may be
-- one); M.known_designator(d): true for a designator the type data or names.designators know; M.slow_class(d): the
-- class model's entry of designator d ({class = "piston"|"turboprop"|"helicopter", vmax_kt = its CAS limit [kt]}),
-- nil for a jet (any type the class model does not name)
M.role_words = { helicopter = true, chopper = true, helo = true, turboprop = true, trijet = true, ["tri-jet"] = true }
local known_designators, slow_classes
local function read_types()
  known_designators, slow_classes = {}, {}
  for _, t in ipairs(squawk and squawk.sim and squawk.sim.types and squawk.sim.types() or {}) do
    known_designators[t.designator:upper()] = true
    if t.vmax_kt and t.class ~= "jet" then slow_classes[t.designator:upper()] = t end
  end
  for _, x in ipairs(require("translate.names").designators) do known_designators[x] = true end
end
function M.known_designator(d)
  if not known_designators then read_types() end
  return known_designators[d] == true
end
function M.slow_class(d)
  if not slow_classes then read_types() end
  return slow_classes[(d or ""):upper()]
end
-- M.too_fast(d, kt) -> the class model's entry of designator d when a speed of kt [kt CAS] lies above its CAS limit
-- by more than M.speed_margin (a C172 at 300 kt: piston, 175 kt), else nil; jets are never too fast here (their
-- limit is lexicon.typed_speed.max_kt's, for typed values)
M.speed_margin = 1.3
function M.too_fast(d, kt)
  local slow = M.slow_class(d)
  return slow and kt > slow.vmax_kt * M.speed_margin and slow or nil
end
-- M.too_fast_words(v, d, slow) -> "300 kt, faster than a C172 flies (a piston: about 175 kt at most)"
function M.too_fast_words(v, d, slow)
  return string.format("%s kt, faster than %s %s flies (a %s: about %d kt at most)", v,
    d:match("^[AEIOU]") and "an" or "a", d:upper(), slow.class, math.floor(slow.vmax_kt + 0.5))
end
do
  local CLASS_WORDS = { helicopter = "helicopter", chopper = "helicopter", helo = "helicopter", turboprop = "turboprop" }
  local list = squawk and squawk.sim and squawk.sim.types and squawk.sim.types() or {}
  for word, class in pairs(CLASS_WORDS) do
    local patterns = {}
    for _, t in ipairs(list) do
      if t.class == class then patterns[#patterns + 1] = "^" .. t.designator:upper() .. "$" end
    end
    if #patterns > 0 then M.nicknames[word] = patterns end
  end
end

function M.build(designators)
  local rows, seen, phrases, known, makers = {}, {}, {}, {}, {}
  local given = {}  -- {{name in lower case, designator}, ...}: every name a title or pattern gives, in order
  local list = {}
  for _, t in ipairs(squawk.sim.types()) do list[#list + 1] = t end
  for _, d in ipairs(designators or {}) do list[#list + 1] = { designator = d } end
  -- (a title of names.titles names its model, never a maker's aircraft: "the Cessna" is no Citation Excel)
  for _, t in ipairs(require("translate.names").titles) do
    list[#list + 1] = { designator = t[1], title = t[2], titled = true }
  end
  local families = {}
  for _, t in ipairs(list) do
    local d = t.designator:upper()
    known[d] = true
    if t.title then
      local title = t.title:gsub("%s*%(.-%)", "")
      local maker, model = title:match("^(%S+)%s+(.+)$")
      if maker then
        maker = maker:lower()
        local first = model:match("^[^/]+")
        local alts = { first }
        for alt in model:gmatch("/%s*([^/]+)") do
          -- "777-200/200ER": the alternative keeps the family
          alts[#alts + 1] = alt:match("^%a") and alt or ((first:match("^(.-%-)") or "") .. alt)
        end
        for _, a in ipairs(alts) do
          a = a:gsub("^%s+", ""):gsub("%s+$", "")
          for _, s in ipairs(spellings(a, maker)) do
            add(rows, seen, t.titled and {} or makers, maker, s, d)
            given[#given + 1] = { s, d }
            if s:match("^%d+%a+$") then phrases[#phrases + 1] = { s, d } end
          end
          if a:find(" ") then
            phrases[#phrases + 1] = { a:lower(), d }
            -- the family said as its designator ("B737 MAX 8")
            if maker == "boeing" then phrases[#phrases + 1] = { "b" .. a:lower(), d } end
          end
          local fam = family_of(a:lower())
          if fam then families[#families + 1] = { maker, fam, d } end
        end
      end
    end
    for _, n in ipairs(pattern_names(d)) do
      for _, sp in ipairs(spellings(n[2], n[1])) do
        add(rows, seen, makers, n[1], sp, d)
        given[#given + 1] = { sp, d }
        -- ("a320 neo", "320 neo": the variant said apart is a name of several words too; "320neo", digits glued to
        -- letters, which the lexer reads apart, is joined as a phrase)
        if (sp:find(" ") and not n[2]:find(" ")) or sp:match("^%d+%a+$") then phrases[#phrases + 1] = { sp, d } end
      end
      -- several words, or digits joined by a hyphen the lexer splits ("dash 8-400")
      if n[2]:find(" ") then
        phrases[#phrases + 1] = { n[2], d }
        if n[1] == "boeing" then phrases[#phrases + 1] = { "b" .. n[2], d } end
      end
      -- (and with a space for its hyphen: "dash 8 400", "atr 72 600")
      if n[2]:find("^%d+%-%d") then
        phrases[#phrases + 1] = { n[1] .. " " .. n[2], d }
        phrases[#phrases + 1] = { n[1] .. " " .. n[2]:gsub("%-", " "), d }
      end
      -- ("737 max 8": a MAX is one of the 737s)
      local fam = family_of(n[2])
      if fam then families[#families + 1] = { n[1], fam, d } end
    end
  end
  -- families: the base designator when it exists ("737" -> B737), else the first variant
  table.sort(families, function(a, b) return a[3] < b[3] end)
  for _, fam in ipairs(families) do
    local base = (fam[1] == "boeing" and "B" or "") .. fam[2]:upper()
    add(rows, seen, makers, fam[1], fam[2], known[base] and base or fam[3])
  end
  -- a designator that is another's model name given first ("e175": E75L's title or pattern) is that other
  local aliases = {}
  for _, g in ipairs(given) do
    local d = g[1]:upper()
    if known[d] and d ~= g[2] and not aliases[d] then aliases[d] = g[2] end
  end
  for d in pairs(aliases) do known[d] = nil end
  for _, row in ipairs(rows) do row[3] = aliases[row[3]] or row[3] end
  for _, set in pairs(makers) do
    for d, target in pairs(aliases) do
      if set[d] then set[target] = true end  -- (the alias kept: an aircraft flying as an E175 is an Embraer)
    end
  end
  for _, fam in ipairs(families) do fam[3] = aliases[fam[3]] or fam[3] end
  local all, sets = {}, {}
  for d in pairs(known) do all[#all + 1] = d end
  table.sort(all)
  for _, fam in ipairs(families) do
    sets[fam[2]] = sets[fam[2]] or {}
    sets[fam[2]][fam[3]] = true
    -- (the base designator is of its family too: "a320" names the A320 and the A20N)
    local base = (fam[1] == "boeing" and "B" or "") .. fam[2]:upper()
    if known[base] then sets[fam[2]][base] = true end
  end
  for _, p in ipairs(phrases) do p[2] = aliases[p[2]] or p[2] end
  return { types = rows, phrases = phrases, designators = all, families = sets, makers = makers, aliases = aliases }
end

-- Type names as speech recognition writes them, digits as number words: after a
-- maker or a designator's letter ("a three twenty", "b seven three eight", "e one
-- ninety", "boeing seven six seven three hundred", "airbus a three two one"), the
-- words read by the rules of spoken numbers (digits said singly, "twenty one",
-- "ninety", "oh"; "three hundred" after a family is its -300 variant) become
-- the written name, only when that name is one of `built`'s (M.build's result)
-- and only in a request that creates traffic (`create` true): "a three twenty"
-- anywhere else stays as said. So does a designator spelled in the phonetic
-- alphabet (`phonetic`, lexicon.phonetic: "bravo seven seven whiskey" -> b77w).
-- (and the radiotelephony digits a recogniser writes: "boeing seven tree eight")
local DIGITS = { zero = "0", oh = "0", one = "1", two = "2", three = "3", four = "4", five = "5", six = "6",
                 seven = "7", eight = "8", nine = "9", niner = "9", tree = "3", fower = "4", fife = "5" }
local TEENS = { ten = "10", eleven = "11", twelve = "12", thirteen = "13", fourteen = "14", fifteen = "15",
                sixteen = "16", seventeen = "17", eighteen = "18", nineteen = "19" }
local TENS = { twenty = "2", thirty = "3", forty = "4", fifty = "5", sixty = "6", seventy = "7", eighty = "8",
               ninety = "9" }
local LETTERS = { a = "airbus", b = "boeing", e = "embraer" }
-- Designator letters that are also English words ("at" of AT45, "be" of BE40): read as a designator's letters
-- before its digits said in words only after an article or "type" ("an at seventy-six", "the be forty"); otherwise
-- the word is the preposition or the verb, and the number after it a value ("waypoint GATE2 at forty-five point
-- three north")
local WORD_PREFIXES = { at = true, be = true, an = true, as = true, ["do"] = true, ["in"] = true, is = true, it = true,
  on = true, ["or"] = true, so = true, to = true, up = true, us = true, we = true }
local PREFIX_OPENERS = { a = true, an = true, the = true, type = true }
-- A variant said as one number after its family ("787 9", "seven eight seven nine", "787 ten"): its digits, or ""
local function short_variant(w)
  return DIGITS[w] or TEENS[w] or (w:match("^%d%d?$")) or ""
end
-- True when `family`'s variant `v` said as one number ("787" and "9") is a model of `built` (built.model: a
-- model's name, with its maker's or without -> its designator) that the variant of those hundreds, where there is one, names too: "787-9" and
-- "787-900" are the B789, while "737-8" (the B38M) is also the 737-800 (B738) said short
local function short_name(built, family, v)
  local d = v ~= "" and built.model[family .. "-" .. v]
  return d ~= nil and d ~= false and (built.model[family .. "-" .. v .. "00"] or d) == d
end
-- A designator of four characters spelled in the phonetic alphabet (`phonetic`: word -> letter), its
-- digits said singly, from token i ("bravo seven three eight", "bravo seven seven whiskey", "charlie romeo
-- juliet nine"): {name = the designator in lower case, punctuation closing its last word kept; e = the
-- token after it} when squawk knows that designator, else nil.
local function spelled_designator(toks, i, built, phonetic)
  local first = toks[i]:lower():gsub("%p+$", "")
  if not phonetic[first] then return nil end
  local name, k = "", i
  while toks[k] and #name < 4 do
    local x = toks[k]:lower():gsub("%p+$", "")
    local c = phonetic[x] and phonetic[x]:lower() or DIGITS[x]
    if not c then return nil end
    name, k = name .. c, k + 1
    if toks[k - 1]:match("%p$") and #name < 4 then return nil end
  end
  if #name < 4 or not name:find("%d") or not built.known[name] then return nil end
  return name .. (toks[k - 1]:match("%p+$") or ""), k
end
-- The range suffix of a Boeing variant said after its number, from token k (`toks`): "ER"/"LR" as one word,
-- spelled "E R"/"L R", or said in words "extended range"/"long range" -> "er" or "lr", and the token after it;
-- else nil. (The suffix changes the type, 777-300 B773 and 777-300ER B77W: never dropped.)
local RANGE_WORDS = { extended = "er", long = "lr" }
local function range_suffix(toks, k)
  local function bare(j) return toks[j] and (toks[j]:lower():gsub("%p+$", "")) or "" end
  local function open(j) return toks[j] ~= nil and not toks[j]:match("%p$") end
  local x = bare(k)
  if x == "er" or x == "lr" then return x, k + 1 end
  if (x == "e" or x == "l") and open(k) and bare(k + 1) == "r" then return x .. "r", k + 2 end
  if RANGE_WORDS[x] and open(k) and bare(k + 1) == "range" then return RANGE_WORDS[x], k + 2 end
  return nil
end
M.range_suffix = range_suffix
function M.spoken(text, built, phonetic)
  if not built.known then
    built.known, built.makers, built.prefixes = {}, {}, {}
    built.model = {}
    for _, r in ipairs(built.types) do
      built.known[r[2]] = true
      built.model[r[2]], built.model[r[1] .. " " .. r[2]] = r[3], r[3]
      built.known[r[1] .. " " .. r[2]] = true
      built.makers[r[1]] = true
    end
    for _, d in ipairs(built.designators) do
      built.known[d:lower()] = true
      local letters = d:lower():match("^(%a%a+)%d+$")
      if letters then built.prefixes[letters] = true end
    end
  end
  local toks = {}
  for w in text:gmatch("%S+") do toks[#toks + 1] = w end
  return require("translate.tokens").rewrite(text, toks, function(i)
    local w = toks[i]:lower()
    -- (only a word that may open a designator said in words is read further: a spelled letter, a maker's
    -- letter or name, a designator's letters, "seven" or a Boeing family's number)
    local ph = phonetic or {}
    if not (LETTERS[w] or w == "q" or w == "airbus" or w == "boeing" or w == "embraer" or built.makers[w] or built.prefixes[w]
        or w == "seven" or w:match("^7%d7$") or w == "dash" or ph[w] or (w:find("%p$") and ph[(w:gsub("%p+$", ""))])
        or w:match("^b?7%d7%-%d00$")) then
      return nil
    end
    -- ("777-300 ER", "777-300 extended range": a Boeing variant typed, its range suffix said apart; a name the
    -- data does not know so, "767-300 ER", is written whole and asked as that name typed is)
    if w:match("^b?7%d7%-%d00$") then
      local sfx, after = range_suffix(toks, i + 1)
      if sfx then return w .. sfx .. (toks[after - 1]:match("%p+$") or ""), after end
      return nil
    end
    -- ("dash 8 four hundred", "dash eight four hundred": the Dash 8's variant in hundreds said after it, "dash 8-400")
    if w == "dash" then
      local function word(j) return toks[j] and not toks[j - 1]:match("%p$") and (toks[j]:lower():gsub("%p+$", "")) end
      local name = (word(i + 1) == "8" or word(i + 1) == "eight") and DIGITS[word(i + 2) or ""]
        and word(i + 3) == "hundred" and "dash 8-" .. DIGITS[word(i + 2)] .. "00"
      if name and built.known[name] then return name .. (toks[i + 3]:match("%p+$") or ""), i + 4 end
      -- ("a Widerøe dash eight, WIF84P": the family's number in words, no variant after it)
      if toks[i + 1] and not toks[i]:match("%p$") and toks[i + 1]:lower():gsub("%p+$", "") == "eight" then
        return "dash 8" .. (toks[i + 1]:match("%p+$") or ""), i + 2
      end
      return nil
    end
    -- ("a Q four hundred": the Dash 8's name in hundreds, Q400)
    if w == "q" and not toks[i]:match("%p$") and toks[i + 1] and not toks[i + 1]:match("%p$") and toks[i + 2] then
      local d = DIGITS[toks[i + 1]:lower()]
      local name = d and toks[i + 2]:lower():gsub("%p+$", "") == "hundred" and "q" .. d .. "00"
      if name and built.known[name] then return name .. (toks[i + 2]:match("%p+$") or ""), i + 3 end
      return nil
    end
    -- ("Ryanair two alpha bravo, seven three eight, at LIFFY", "a seven three eight": a Boeing designator's digits
    -- said singly after a comma, an article or "type" is that designator, B738; "seven six seven", a family of
    -- several, stays as said)
    if w == "seven" and not toks[i]:match("%p$") and toks[i + 1] and not toks[i + 1]:match("%p$") and toks[i + 2] then
      local prev = (toks[i - 1] or ""):lower()
      local d2, d3 = DIGITS[toks[i + 1]:lower()], DIGITS[(toks[i + 2]:lower():gsub("%p+$", ""))]
      if d2 and d3 and d3 ~= "7" and (prev:match(",$") or PREFIX_OPENERS[prev]) and built.known["b7" .. d2 .. d3] then
        return "b7" .. d2 .. d3 .. (toks[i + 2]:match("%p+$") or ""), i + 3
      end
    end
    local spelled, after = spelled_designator(toks, i, built, ph)
    if spelled then return spelled, after end
    local maker = LETTERS[w] and w or nil
    local lead = maker and w or ""
    local k = i + 1
    -- a designator's letters said before its digits ("CRJ nine" -> CRJ9): any number of digits
    local prefix = false
    if not maker and (w == "airbus" or w == "boeing" or w == "embraer" or built.makers[w]) then
      maker, lead = w, w .. " "
      if w == "airbus" and toks[k] and toks[k]:lower() == "a" then lead, k = "a", k + 1 end
    elseif not maker and built.prefixes[w]
        and not (WORD_PREFIXES[w] and not PREFIX_OPENERS[(toks[i - 1] or ""):lower():gsub("%p+$", "")]) then
      maker, lead, prefix = w, w, true
    end
    local best
    -- ("seven thirty-seven", "seven eighty seven": a Boeing family said as its number is, "737")
    local tens, unit, after = (toks[i + 1] or ""):lower():match("^(%a+)%-(%a+)(%p*)$")
    local e = i + 2
    if not tens and toks[i + 2] and not toks[i + 1]:match("%p$") then
      tens, unit, after, e = toks[i + 1]:lower(), toks[i + 2]:lower():match("^(%a+)(%p*)$"), nil, i + 3
      after = toks[i + 2]:match("%p*$")
    end
    local family = w == "seven" and tens and TENS[tens] and DIGITS[unit or ""] == "7" and "7" .. TENS[tens] .. "7"
    -- (the family so said, and the token after it where a variant may follow: "seven sixty-seven three hundred")
    local fam, j
    if family and built.known["boeing " .. family] then
      best = { name = family .. (after or ""), e = e }
      maker = nil
      if (after or "") == "" then fam, j = family, e end
    end
    -- ("triple seven 300ER", lexed "seven seven seven 300ER"; "777 300ER"; "seven four seven four hundred"): a
    -- Boeing family said digit by digit, in tens or typed, with one of its variants said straight after it
    -- ("300ER", "300 ER", "three hundred ER"), is that variant; the family so said alone stays as said (digits)
    if not best or fam then
      local function bare(j) return toks[j] and (toks[j]:lower():gsub("%p+$", "")) or "" end
      local function open(j) return toks[j] ~= nil and not toks[j]:match("%p$") end
      if fam then
      elseif w:match("^7%d7$") then
        fam, j = w, i + 1
      elseif w == "seven" and open(i) and open(i + 1) and DIGITS[bare(i + 1)] and bare(i + 2) == "seven" then
        fam, j = "7" .. DIGITS[bare(i + 1)] .. "7", i + 3
      end
      if fam and built.known["boeing " .. fam] and open(j - 1) and toks[j] then
        -- ("787 dash 9", "seven eight seven dash nine": "dash" is the hyphen before a variant said as one
        -- number that names one model, 787-9; "737 dash 8", the 737-8 or the 737-800, stays unread; "seven three
        -- seven dash eight hundred": before the variant's hundreds)
        if bare(j) == "dash" and open(j) and toks[j + 1] and (short_name(built, fam, short_variant(bare(j + 1)))
            or (DIGITS[bare(j + 1)] and open(j + 1) and bare(j + 2) == "hundred")) then
          j = j + 1
        end
        local v, k = bare(j):match("^%-?(%d00%a*)$"), j + 1
        if not v and DIGITS[bare(j)] and open(j) and bare(j + 1) == "hundred" then v, k = DIGITS[bare(j)] .. "00", j + 2 end
        if not v and short_name(built, fam, short_variant(bare(j))) then v = short_variant(bare(j)) end
        local name = v and fam .. "-" .. v
        -- ("triple seven freighter": the family's freighter where one designator is named so, B77L)
        if not v and bare(j) == "freighter" and built.known[fam .. " freighter"] then name, k = fam .. " freighter", j + 1 end
        if name and built.known[name] then best = { name = name .. (toks[k - 1]:match("%p+$") or ""), e = k } end
        -- ("seven three seven max eight", "737 max eight": the MAX's number said as a word after the family)
        if not name and bare(j) == "max" and open(j) and toks[j + 1] and DIGITS[bare(j + 1)] then
          best = { name = fam .. " max " .. DIGITS[bare(j + 1)] .. (toks[j + 1]:match("%p+$") or ""), e = j + 2 }
        end
      end
    end
    if maker then
      -- the digits said after the letter, one spoken group at a time, and the name each step spells
      local digits, variant = "", nil
      -- (a word's trailing punctuation, "nine,", ends the name and stays after it)
      local function bare(j) return toks[j] and (toks[j]:lower():gsub("%p+$", "")) end
      while toks[k] do
        local x, nx = bare(k), toks[k]:match("%p$") == nil and bare(k + 1) or nil
        -- ("seven three seven dash eight hundred": "dash" before the variant's hundreds is its hyphen)
        if x == "dash" and nx and DIGITS[nx] and #digits == 3 and not variant and toks[k + 1]:match("%p$") == nil
            and bare(k + 2) == "hundred" then
          k = k + 1
          x, nx = nx, bare(k + 1)
        end
        -- ("seven eight seven dash nine": "dash" before a variant said as one number naming one model, 787-9)
        if x == "dash" and nx and #digits == 3 and not variant and short_name(built, lead .. digits, short_variant(nx)) then
          k = k + 1
          x, nx = nx, toks[k]:match("%p$") == nil and bare(k + 1) or nil
        end
        local hy_tens, hy_unit = x:match("^(%a+)%-(%a+)$")
        if prefix and digits == "" and DIGITS[x] and nx == "hundred" and built.known[lead .. DIGITS[x]] then
          digits, k = DIGITS[x], k + 2  -- ("CRJ seven hundred": the letters, then the variant's hundreds, CRJ7)
        elseif DIGITS[x] and nx == "hundred" and #digits == 3 and not variant then
          variant, k = DIGITS[x] .. "00", k + 2
        elseif TENS[hy_tens or ""] and DIGITS[hy_unit or ""] and DIGITS[hy_unit] ~= "0" and not variant then
          digits, k = digits .. TENS[hy_tens] .. DIGITS[hy_unit], k + 1  -- ("e one seventy-five": E175)
        elseif #digits == 3 and not variant and short_name(built, lead .. digits, short_variant(x)) then
          variant, k = short_variant(x), k + 1  -- ("boeing seven eight seven nine": the 787-9)
        elseif variant then
          break
        elseif DIGITS[x] then
          digits, k = digits .. DIGITS[x], k + 1
        elseif x:match("^%d%d%d$") and digits == "" and (w == "e" or w == "b") then
          -- ("an e 175", "a b 738": the letter said apart from its digits typed; "a 320" is an article)
          digits, k = x, k + 1
        elseif TEENS[x] then
          digits, k = digits .. TEENS[x], k + 1
        elseif TENS[x] then
          local unit = nx and DIGITS[nx]
          -- ("a three thirty three hundred": the family's tens, then its variant in hundreds, A330-300)
          if unit and unit ~= "0" and #digits == 1 and toks[k + 1]:match("%p$") == nil and bare(k + 2) == "hundred" then
            digits, variant, k = digits .. TENS[x] .. "0", unit .. "00", k + 3
          elseif unit and unit ~= "0" then digits, k = digits .. TENS[x] .. unit, k + 2
          else digits, k = digits .. TENS[x] .. "0", k + 1 end
        else
          break
        end
        local name = lead .. digits .. (variant and ("-" .. variant) or "")
        local punct = toks[k - 1]:match("%p+$") or ""
        -- ("Airbus three twenty": the maker's letter left out)
        if w == "airbus" and lead ~= "a" and #digits == 3 and not built.known[name] then
          name = "airbus a" .. digits .. (variant and ("-" .. variant) or "")
        end
        -- ("ATR seventy two": a maker's name and a model's two digits, "atr 72")
        if (#digits >= 3 or prefix or (built.makers[w] and #digits == 2)) and built.known[name] then
          best = { name = name .. punct, e = k }
        elseif w == "boeing" and #digits == 3 and not variant and not digits:match("^7%d7$") and built.known["b" .. digits] then
          best = { name = "b" .. digits .. punct, e = k }  -- ("boeing seven three eight": the designator, B738)
        end
        if punct ~= "" then break end
      end
    end
    -- ("seven seven seven three hundred ER", "777 300 E R", "767 three hundred extended range": a Boeing variant's
    -- range suffix said after it is part of the name; a name with the suffix the data does not know is written
    -- whole, never as the variant without it, and asked as that name typed is)
    if best and best.name:match("7%d7%-%d00$") and toks[best.e - 1] and not toks[best.e - 1]:match("%p$") then
      local sfx, after = range_suffix(toks, best.e)
      if sfx then best = { name = best.name:gsub("^boeing ", "") .. sfx .. (toks[after - 1]:match("%p+$") or ""), e = after } end
    end
    -- ("seven thirty-seven max eight": the MAX's number said as a word, "737 max 8")
    local bare_max = best and not best.name:match("%p$") and toks[best.e] and toks[best.e]:lower()
    local n = toks[best and best.e + 1 or 0]
    if bare_max == "max" and n and DIGITS[n:lower():gsub("%p+$", "")] then
      best = { name = best.name .. " max " .. DIGITS[n:lower():gsub("%p+$", "")] .. (n:match("%p+$") or ""), e = best.e + 2 }
    end
    if best then return best.name, best.e end
  end)
end

-- The request with each name of several words as its designator ("a 737 MAX 8" -> "a B38M").
-- Designators said in the plural where traffic is created ("5 random A320s", "two B738s"): the
-- designator (a word that is a designator itself, or the id of an aircraft of `fleet`, stays); the digits
-- of exactly one Airbus or Boeing designator in the plural ("8 random 738s", "320s") are that designator,
-- except a family's number that names no one variant (`families`, lexicon.variant_families: "737s"); a
-- model's name with a hyphen in the plural ("737-800s") is that name.
local lower_designators = setmetatable({}, { __mode = "k" })  -- [built] = {[designator in lower case] = true}
local short_designators = setmetatable({}, { __mode = "k" })  -- [built] = {[digits] = designator or false}
local hyphen_models = setmetatable({}, { __mode = "k" })  -- [built] = {[model with a hyphen, lower case] = true}
function M.plurals(text, built, fleet, families)
  local designators = lower_designators[built]
  if not designators then
    designators = {}
    local short = {}
    for _, d in ipairs(built.designators) do
      designators[d:lower()] = true
      local digits = d:match("^[AB](%d%d%d)$")
      if digits then short[digits] = short[digits] == nil and d or false end
    end
    for d in pairs(built.aliases or {}) do designators[d:lower()] = true end  -- ("E175s": read as the E75L)
    for _, fam in ipairs(families or {}) do short[fam] = false end
    local hyphened = {}
    for _, row in ipairs(built.types) do
      if row[2]:find("-", 1, true) then hyphened[row[2]] = true end
    end
    lower_designators[built], short_designators[built], hyphen_models[built] = designators, short, hyphened
  end
  local hyphened = hyphen_models[built]
  local short = short_designators[built]
  local ids = {}
  for _, a in ipairs(fleet or {}) do ids[a.id:lower()] = true end
  local function known(w) return designators[w] or ids[w] end
  text = text:gsub("%f[%w](%w+%-%w+)[sS]%f[%W]", function(d)
    if hyphened[d:lower()] then return d end
  end)
  return (text:gsub("%f[%w](%w+)[sS]%f[%W]", function(d)
    if known(d:lower()) and not known((d .. "s"):lower()) then return d end
    if short[d] then return short[d] end
  end))
end

-- The digits of exactly one Airbus or Boeing designator said alone as a new aircraft's type, where traffic is
-- created: straight after a verb of creating and "a"/"an" (or "a new") ("spawn a 320 callsign BAW456 ...", "create
-- a new 321, EZY5, ..."), or, above 360 (never a heading), straight after a verb of creating and the new callsign
-- ("spawn klm1711 738 at EHAM"): that designator. A family's number that names no one variant (`families`:
-- "737") stays; so do the digits before a unit or value noun ("add a 320 heading"), a decimal or any other word.
local CREATING = { create = true, spawn = true, add = true, generate = true, put = true, insert = true, new = true }
local VALUE_NOUNS = { heading = true, hdg = true, degrees = true, degree = true, deg = true, kt = true, kts = true,
  knots = true, knot = true, ft = true, feet = true, fl = true, track = true, course = true, nm = true, miles = true,
  mach = true, seconds = true, sec = true, s = true, minutes = true, min = true, radial = true, turn = true }
function M.short_singular(text, built, families)
  M.plurals("", built, nil, families)  -- (builds the designators' digits, short_designators[built])
  local short = short_designators[built]
  return (text:gsub("()(%d%d%d)()", function(b, d, e)
    local des = short[d]
    if not des then return nil end
    local before, after = text:sub(1, b - 1), text:sub(e)
    if before:match("[%w%.%-]$") or after:match("^[%w%.%-]") then return nil end
    local nxt = after:match("^[%s,]*(%a+)")
    if nxt and VALUE_NOUNS[nxt:lower()] then return nil end
    local low = before:lower()
    local verb = low:match("(%a+)%s+an?%s+$") or low:match("(%a+)%s+an?%s+new%s+$")
    if verb and CREATING[verb] then return des end
    local verb2 = low:match("(%a+)%s+%a+%d+%w*,?%s+$")
    if verb2 and CREATING[verb2] and tonumber(d) > 360 then return des end
    -- ("create RYR4TQ a 738 ...", "create a Ryanair, RYR4TQ, 738, ..."): the new callsign straight before, after a
    -- verb of creating earlier in the clause; with an article between, or above 360
    -- (or said as the airline's word and the number, a comma and the article after it: "create Ryanair 1HN, a 738,
    -- ..."; "Dash 8 400" is the type's own name)
    local head, article = low:match("^(.-)%f[%w]%a+%d+%w*,?%s+(a?n?)%s*$")
    if not head then head, article = low:match("^(.-)%f[%w]%a+%s+%d%w*,%s+(an?)%s*$") end
    -- (a flight level or a designator before it is no callsign: "at FL160 400", "A320 321")
    local said_before = low:match("%f[%w](%a+%d+%w*),?%s+a?n?%s*$")
    if said_before and (said_before:match("^fl%d") or built.known[said_before:upper()]) then head = nil end
    if head and (article == "" or article == "a" or article == "an") and (article ~= "" or tonumber(d) > 360) then
      for w in (head:match("[^.;:!?]*$")):gmatch("%a+") do
        if CREATING[w] then return des end
      end
    end
    return nil
  end))
end

-- The phrases of M.join grouped by their first word: {firsts = {word, ...} in order of first
-- appearance, at = {[word] = {position in phrases, ...}}}; built once per phrase list, which must not
-- change after its first join.
local function by_first_word(phrases)
  local firsts, at = {}, {}
  for k, p in ipairs(phrases) do
    local first = p[1]:match("^%S+")
    if not at[first] then
      at[first] = {}
      firsts[#firsts + 1] = first
    end
    local list = at[first]
    list[#list + 1] = k
  end
  return { firsts = firsts, at = at }
end

function M.join(text, phrases)
  local index = phrases.by_first or by_first_word(phrases)
  phrases.by_first = index
  -- the phrases whose first word `text` holds (worth a pattern match), in their order in `phrases`
  local lower, hits = text:lower(), {}
  local firsts = index.firsts
  for j = 1, #firsts do
    local first = firsts[j]
    if lower:find(first, 1, true) then
      for _, k in ipairs(index.at[first]) do hits[#hits + 1] = k end
    end
  end
  table.sort(hits)
  for _, k in ipairs(hits) do
    local p = phrases[k]
    p.pattern = p.pattern or ("%f[%w]" .. p[1]:gsub("%p", "%%%0")
      :gsub("%a", function(ch) return "[" .. ch:lower() .. ch:upper() .. "]" end)
      :gsub(" ", "[%%s%%-]+") .. "%f[%W]")
    -- (matched only where `text` holds each word of the phrase: a phrase's code put in before is none of them)
    local words = p.words
    if not words then
      words = {}
      for w in p[1]:lower():gmatch("%S+") do words[#words + 1] = w end
      p.words = words
    end
    local all = true
    for j = 2, #words do all = all and lower:find(words[j], 1, true) ~= nil end
    if all then text = text:gsub(p.pattern, p[2]) end
  end
  return text
end

return M
