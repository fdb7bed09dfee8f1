-- The offline grammar: controller and experimenter English -> TrafScript,
-- with no language model. The `offline` node of the translation graph.
--
-- Data: translate/lexicon.lua (words), translate/names.lua (airline
-- telephony, type designators), translate/types.lua (type names from the
-- performance models' data) and translate/rules.lua (which words
-- ask for which registry command), checked against the command registry
-- when they load; translate/handlers.lua fills each command's arguments.
-- The C++ extractors (squawk.translate.utterance) lex, read numbers and
-- quantities with units, latitude/longitude forms, callsigns, types and
-- waypoint names.
--
-- API:
--   translate(text, world) -> {commands = {"CMD", ...}, note =?} | {commands = {}, ask = "question"}
--     note: a sentence naming what the request asked that squawk does not
--     simulate (holding patterns, approach clearances, transponder codes,
--     radio frequencies; lexicon.not_simulated); those words are not
--     translated, the rest is (commands may then be empty)
--     world: {aircraft = {{id=, type=, lat=, lon=, hdg_deg=, alt_ft=, cas_kt=,
--             sel_mach=, route = {"WPT", ...}}, ...} (sim:aircraft()'s names and units),
--             waypoints = {"NAME", ...}} or nil.
--     world.confirmed: {[id] = true} for callsigns the speaker confirmed.
--     world.ignored: {[word] = true} (lower case) for leftover words the speaker said
--     carry nothing ("ignore it"); a question about a leftover plain word (neither a
--     negation nor a condition) carries ignorable = that word.
--     Never fails: a request it cannot fill completely becomes a question
--     naming what is missing; a question about an inexactly heard callsign
--     carries confirm = {id =, heard =}. A request whose commands are complete but
--     one of them needs a yes first (a relative turn of more than 180 degrees, an
--     airport found by name only far away) carries confirm_first = the question;
--     the yes runs every command of the request (graph.lua).
--   rule(spec), intent(name)(spec)   add a rule / an intent at run time,
--     checked like the file's (an error names the caller's file:line).
--     New rules go before the file's rules, so they win.
--   handler(name, fn)  a new handler fn(g, s, spec) (see translate/handlers.lua)
--   check_command(name, args, level)  the registry check used for both.
--   has_instruction(text) -> true when a word of text starts an instruction.
--   documents() -> {{command =, text =}, ...}  retrieval documents: the
--     words of the rules, per registry command (squawk.rag.index docs)
local lexicon = require("translate.lexicon")
-- the airlines, types and phonetic alphabet, handed to the C++ matchers once
local names = require("translate.names")
local tokens = require("translate.tokens")
local TYPES = require("translate.types").build(names.designators)
-- The spelling fixer never turns a word that means something of its own into another: a
-- registry command's name ("delrte" is no "delete", "zoner" no "zone") and the words that name
-- what squawk does not simulate ("holding" is no "heading") are kept as typed.
-- A registry name that is no English word ("DTMULT", "rfach") is an instruction word too: typed in
-- capitals inside English ("set DTMULT 4", "ZONER 5, DTLOOK 300") it names its command, no waypoint.
-- REGISTRY_WORDS: such a name or alias, lower case -> its command's registry name ("pzdh" -> "ZONEDH").
local REGISTRY_WORDS = {}
do
  local english = {}
  for _, w in ipairs(lexicon.english_command_names) do english[w] = true end
  for _, c in ipairs(squawk.sim.commands()) do
    for _, w in ipairs({ c.name, table.unpack(c.aliases or {}) }) do
      if w:match("^%a+$") and not english[w:lower()] then REGISTRY_WORDS[w:lower()] = c.name:upper() end
    end
  end
end
local function spelling_kept()
  local kept, keywords = {}, {}
  for _, w in ipairs(lexicon.spelling.common) do kept[#kept + 1] = w end
  for _, w in ipairs(lexicon.keywords) do keywords[#keywords + 1] = w end
  for _, c in ipairs(squawk.sim.commands()) do
    kept[#kept + 1] = c.name:lower()
    for _, a in ipairs(c.aliases or {}) do kept[#kept + 1] = a:lower() end
  end
  for w in pairs(REGISTRY_WORDS) do keywords[#keywords + 1] = w end
  for _, n in ipairs(lexicon.not_simulated) do
    for w in n.words:gmatch("%S+") do kept[#kept + 1] = w end
  end
  -- (a word of an airline's telephony is a name of its own: "Air Crete" is no "create")
  for _, a in ipairs(names.airlines) do
    for w in a[1]:gmatch("%S+") do kept[#kept + 1] = w end
  end
  return setmetatable({ spelling = { targets = lexicon.spelling.targets, common = kept }, keywords = keywords },
    { __index = lexicon })
end
-- SETTING_KEYS: the keys of a setting typed key=value ("seed=7", "pz=5nm", "hdg=270"): registry names and
-- aliases, typed shorthand, and lexicon.setting_keys
local SETTING_KEYS = {}
do
  for _, c in ipairs(squawk.sim.commands()) do
    for _, w in ipairs({ c.name, table.unpack(c.aliases or {}) }) do SETTING_KEYS[w:lower()] = true end
  end
  for w in pairs(lexicon.shorthand) do SETTING_KEYS[w] = true end
  for _, w in ipairs(lexicon.setting_keys) do SETTING_KEYS[w] = true end
end
local NAMES = squawk.translate.tables({ airlines = names.airlines, types = TYPES.types,
  designators = TYPES.designators }, spelling_kept())

local M = { lexicon = lexicon, intents = {}, rules = {}, words = {} }

-- ---- the registry check ----

local registry
local function registry_args()
  if registry then return registry end
  registry = {}
  for _, c in ipairs(squawk.sim.commands()) do
    local names = {}
    local rest = c.usage:match("^%S+%s*(.*)$") or ""
    for w in rest:gmatch("[%w_]+") do names[w] = true end
    registry[c.name:upper()] = names
    for _, a in ipairs(c.aliases or {}) do registry[a:upper()] = names end
  end
  return registry
end

-- Errors at `level` (the caller's file:line) unless `name` is a registry
-- command (or alias) whose usage names every one of `args`.
function M.check_command(name, args, level)
  local reg = registry_args()
  local names = reg[tostring(name):upper()]
  if not names then error(string.format("grammar: unknown command '%s'", tostring(name)), level + 1) end
  for _, a in ipairs(args or {}) do
    if not names[a] then
      error(string.format("grammar: command %s has no argument '%s'", name, tostring(a)), level + 1)
    end
  end
end

local handlers  -- translate.handlers, loaded after M is complete

local G = {}
G.__index = G

local function add_intent(name, spec, level)
  if handlers and not G[spec.handler] then
    error("grammar: intent '" .. name .. "' has no handler '" .. tostring(spec.handler) .. "'", level + 1)
  end
  local cmds = spec.cmds or { spec.cmd }
  if #cmds == 0 then error("grammar: intent '" .. name .. "' names no command", level + 1) end
  for _, c in ipairs(cmds) do M.check_command(c, spec.cmds and {} or spec.args, level + 1) end
  for _, c in ipairs(spec.also or {}) do M.check_command(c, {}, level + 1) end
  if spec.cmds then
    for _, a in ipairs(spec.args or {}) do
      M.check_command(cmds[1], { a }, level + 1)
    end
  end
  spec.name = name
  M.intents[name] = spec
end

-- Word lists: "a b @list *" -> set. set_cache maps a list's text to its set and a set to itself
-- (weak keys: a set built per call goes with its caller).
local set_cache = setmetatable({}, { __mode = "k" })
local function word_set(words, level)
  if type(words) == "table" then
    set_cache[words] = words
    return words
  end
  local s = set_cache[words]
  if s then return s end
  s = {}
  for w in words:gmatch("%S+") do
    if w:sub(1, 1) == "@" then
      local list = lexicon[w:sub(2)]
      if type(list) ~= "table" then error("grammar: no word list lexicon." .. w:sub(2), level + 1) end
      for k, v in pairs(list) do s[type(k) == "number" and v or k] = true end
    else
      s[w] = true
    end
  end
  set_cache[words] = s
  return s
end
M.word_set = word_set

-- Every word a rule or the lexicon names, for the check that every word is accounted for
-- (G:unaccounted); lexicon.accounted's phrases are matched whole, never word by word.
local KNOWN = {}
local function know(text)
  for w in tostring(text):lower():gmatch("[%a'%-]+") do KNOWN[w] = true end
end
local function know_all(v, seen)
  if type(v) == "string" then return know(v) end
  -- (lexicon.aside and lexicon.self_correction.just_the say where words are set aside or what they
  -- keep, lexicon.foreign_digits are digits only beside another, lexicon.atc_units name a station only
  -- in the addressing position, lexicon.label_roles and lexicon.bare_labels only a speaker's label; lexicon.city_airports are places,
  -- accounted for only where one is read; lexicon.readback_heard is dropped with its values only, and
  -- lexicon.nationless_registrations are letters of a registration; lexicon.typed_abbreviations are read as
  -- their words only where those fit; lexicon.manner, rate_manner, deadline_places and held_value only where their reading
  -- holds; lexicon.dictated_punctuation is the marks it names; lexicon.said_whole is read as its English: they
  -- account for no word; lexicon.heard_as's words are read only where their neighbours fit, becoming the word
  -- they mean, so a heard form left as it was ("vire a la izquierda": no neighbour fits) is no word squawk knows;
  -- lexicon.name_particles are words of a place's name ("de los reyes"), accounted for only inside the name read,
  -- and lexicon.digit_homophones digits only inside a callsign read ("won", "ate"); lexicon.kept_as_is only
  -- where a value is read as kept; lexicon.id_labels only the letters of a label's id, lexicon.terse_list only
  -- the words of a terse list, lexicon.self_correction.apology only after a value ruled out (.formal_apology read as
  -- "sorry", .described only inside a correction's run, .judged: none, .admitted read as "sorry" where set off),
  -- lexicon.limit_release only after a limit's
  -- place, lexicon.replaced_lead
  -- only before a value replaced, lexicon.ff_ended only before a fast-forward ended, lexicon.countries only
  -- inside a callsign read, lexicon.described_places.regions only as a place that describes an aircraft,
  -- lexicon.screen_position only where an aircraft's place on the screen is read, lexicon.unheard_markers only
  -- to ask a request again; lexicon.listener_address only where it is dropped, opening or closing a request;
  -- lexicon.judged_values, kept_from and speed_direction_verbs only where their pass reads them, lexicon.wish_evaluative
  -- and wish_negation only in a wish framed before "if", same_given and same_compared only beside "same", lexicon.ml_labels
  -- only where dropped; lexicon.remark_not and named_position_leads only where their pass reads them, and
  -- lexicon.french_in_english only where G.french_in_english reads a number or "and": they never
  -- make a word said elsewhere known)
  if type(v) ~= "table" or seen[v] or v == lexicon.accounted.courtesy_phrases or v == lexicon.accounted.value_phrases
      or v == lexicon.typed_abbreviations
      or v == lexicon.aside or v == lexicon.self_correction.just_the or v == lexicon.foreign_digits or v == lexicon.foreign_hesitation_digits
      or v == lexicon.atc_units or v == lexicon.city_airports or v == lexicon.label_roles or v == lexicon.bare_labels
      or v == lexicon.described_places.regions
      or v == lexicon.addressed_roles or v == lexicon.readback_heard or v == lexicon.nationless_registrations
      or v == lexicon.manner or v == lexicon.rate_manner or v == lexicon.deadline_places or v == lexicon.held_value
      or v == lexicon.dictated_punctuation or v == lexicon.acknowledged or v == lexicon.said_whole or v == lexicon.heard_as
      or v == lexicon.name_particles or v == lexicon.digit_homophones or v == lexicon.asides_alone
      or v == lexicon.kept_as_is or v == lexicon.id_labels or v == lexicon.terse_list
      or v == lexicon.self_correction.apology or v == lexicon.replaced_lead or v == lexicon.ff_ended
      or v == lexicon.self_correction.formal_apology or v == lexicon.self_correction.described
      or v == lexicon.self_correction.judged or v == lexicon.self_correction.admitted or v == lexicon.limit_release
      or v == lexicon.countries or v == lexicon.screen_position or v == lexicon.unheard_markers
      or v == lexicon.remark_not or v == lexicon.named_position_leads
      or v == lexicon.listener_address or v == lexicon.judged_values or v == lexicon.kept_from or v == lexicon.ml_labels
      or v == lexicon.speed_direction_verbs or v == lexicon.wish_evaluative or v == lexicon.wish_negation
      or v == lexicon.same_given or v == lexicon.same_compared or v == lexicon.french_in_english then
    return
  end
  seen[v] = true
  for k, x in pairs(v) do
    if type(k) == "string" then know(k) end
    know_all(x, seen)
  end
end
-- The words of a compiled rule are known words.
local function know_rule(r)
  know_all(r.words, {})
  know_all(r.next or {}, {})
  for _, k in ipairs({ "near", "not_near", "prev", "not_prev" }) do
    if r[k] then know_all(r[k][2], {}) end
  end
end

local function compile_rule(spec, level)
  local words, target = spec[1], spec[2]
  if type(words) ~= "string" then error("grammar: a rule starts with its words", level + 1) end
  if target ~= false and not M.intents[target] then
    error(string.format("grammar: rule for '%s' names unknown intent '%s'", words, tostring(target)), level + 1)
  end
  local r = { words = word_set(words, level + 1), any = words == "*", intent = target, when = spec.when }
  r.next = spec.next and word_set(spec.next, level + 1)
  for _, k in ipairs({ "near", "not_near", "prev", "not_prev" }) do
    if spec[k] then r[k] = { spec[k][1], word_set(spec[k][2], level + 1) } end
  end
  -- (r.plain: none of next, near, not_near, prev and not_prev is asked, only r.when: G:intent_at's short way; a
  -- new kind of condition G:intent_at reads must join this list, or a rule with it alone would skip it)
  r.plain = not (r.next or r.near or r.not_near or r.prev or r.not_prev)
  return r
end

-- The rules that may fire on a word, in M.rules' order: RULES_BY_WORD[w] for a word some rule
-- lists, ANY_RULES ("*" rules only) for every other word. CONDITION_SETS[w]: the word sets of the
-- rules' near, not_near, prev and not_prev conditions that hold w. Rebuilt whenever M.rules changes.
local RULES_BY_WORD, ANY_RULES, CONDITION_SETS = {}, {}, {}
local function index_rules()
  RULES_BY_WORD, ANY_RULES, CONDITION_SETS = {}, {}, {}
  for _, r in ipairs(M.rules) do
    for _, k in ipairs({ "near", "not_near", "prev", "not_prev" }) do
      for w, v in pairs(r[k] and r[k][2] or {}) do
        if v then
          CONDITION_SETS[w] = CONDITION_SETS[w] or {}
          CONDITION_SETS[w][r[k][2]] = true
        end
      end
    end
    if r.any then
      ANY_RULES[#ANY_RULES + 1] = r
      for _, list in pairs(RULES_BY_WORD) do list[#list + 1] = r end
    else
      for w, v in pairs(r.words) do
        if v then
          local list = RULES_BY_WORD[w] or table.move(ANY_RULES, 1, #ANY_RULES, 1, {})
          RULES_BY_WORD[w] = list
          list[#list + 1] = r
        end
      end
    end
  end
end

local loading = true
function M.rule(spec)
  local r = compile_rule(spec, 2)
  know_rule(r)
  if loading then
    M.rules[#M.rules + 1] = r
  else
    table.insert(M.rules, 1, r)
    index_rules()
  end
end

function M.intent(name)
  return function(spec) add_intent(name, spec, 2) end
end

-- words(cmd)(text): more words people use for a registry command.
function M.add_words(cmd)
  return function(text)
    M.check_command(cmd, {}, 2)
    M.words[#M.words + 1] = { command = cmd:upper(), text = text }
  end
end

require("translate.rules")(M.intent, M.rule, M.add_words)
-- A registry name typed inside English that no rule lists ("rmethv off", "rfach 1.05", "pzdh 800")
-- starts the intent of its command, after every rule of the file (the words stay unknown to the
-- account of words: said with its command not issued, such a name is asked about)
do
  local listed = {}
  for _, r in ipairs(M.rules) do for w in pairs(r.any and {} or r.words) do listed[w] = true end end
  local names = {}
  for w in pairs(REGISTRY_WORDS) do if not listed[w] then names[#names + 1] = w end end
  table.sort(names)
  for _, w in ipairs(names) do
    for _, spec in pairs(M.intents) do
      for _, c in ipairs(spec.cmds or { spec.cmd }) do
        if c == REGISTRY_WORDS[w] then M.rules[#M.rules + 1] = compile_rule({ w, spec.name }, 1) end
      end
    end
  end
end
loading = false
index_rules()


-- handler(name, fn): a new handler method fn(g, s, spec) for intents to name.
function M.handler(name, fn) G[name] = fn end

-- ---- written forms ----

-- Rewrites written forms the extractors read as other words:
--  * lexicon.shorthand prefixes before a value: "ryr81jc fl240 s270" ->
--    "ryr81jc fl240 speed 270", "l 330" -> "left 330" (only a whole token
--    that is a prefix and digits, or a prefix before a token starting with a
--    digit, not after a number unless it is a turn letter: "33.95 S 151.18 E"
--    is a hemisphere;
--    "dlh4ax" and "fl240" are left alone);
--  * "a thousand", "a hundred" -> "one thousand", "one hundred" (after "another" and "further" too); a typed
--    callsign glued to its level, "klm12fl240" -> "klm12 fl240"; "m78" ->
--    "mach .78"; a level typed digit by digit, "fl 3 4 0" -> "fl 340";
--  * "flightlevel" -> "flight level", "x-ray" / "x ray" -> "xray", "fox trot" -> "foxtrot", and
--    speech recognition's "nine her" -> "niner", and a degree sign ending
--    a number ("rt 30°") -> "degrees" (one inside a coordinate stays);
--  * thousands grouped with a space: "18 000 feet" -> "18000 feet" (a
--    group of three digits that is "000" or is followed by feet);
--  * a turn letter of lexicon.shorthand ("l", "rt") as a word before
--    "hdg"/"heading" or after "hdg NNN": "lt hdg 250" -> "left hdg 250",
--    "hdg 060 l" -> "hdg 060 left".
local HEADING_WORDS = { hdg = true, heading = true, h = true }
local HEADING_PATTERNS = {}  -- a word of HEADING_WORDS whole in " " .. lower-case text .. " "
for w in pairs(HEADING_WORDS) do HEADING_PATTERNS[#HEADING_PATTERNS + 1] = "%s" .. w .. "%s" end
local function turn_letters(text, sh)
  -- (a turn letter is read only beside a heading word: with none said, the text stands)
  local padded, heading = " " .. text:lower() .. " ", false
  for _, p in ipairs(HEADING_PATTERNS) do heading = heading or padded:find(p) ~= nil end
  if not heading then return text end
  -- (a turn letter is a word of letters alone, so one of the text's runs of letters)
  local turn = false
  for letters in text:lower():gmatch("%a+") do
    local d = sh[letters]
    if d == "left" or d == "right" then
      turn = true
      break
    end
  end
  if not turn then return text end
  local toks = {}
  for w in text:gmatch("%S+") do toks[#toks + 1] = w end
  local changed = false
  for i, w in ipairs(toks) do
    local letters, punct = w:match("^(%a+)(%p?)$")
    local d = letters and sh[letters:lower()]
    if d == "left" or d == "right" then
      local nxt, prev = toks[i + 1] and toks[i + 1]:lower(), toks[i - 1]
      if (nxt and HEADING_WORDS[nxt]) or (prev and prev:match("^%d%d%d$") and toks[i - 2]
          and HEADING_WORDS[toks[i - 2]:lower()]) then
        toks[i], changed = d .. punct, true
      end
    end
  end
  return changed and table.concat(toks, " ") or text
end

-- A word that is a number as said or typed ("250", "fl240", "niner", "thirty").
local function set_of(list)
  local s = {}
  for _, w in ipairs(list) do s[w] = true end
  return s
end
local NUMBER_WORDS = set_of({ "zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine",
  "niner", "tree", "fife", "fower", "ten", "eleven", "twelve", "thirteen", "fourteen", "fifteen", "sixteen",
  "seventeen", "eighteen", "nineteen", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety",
  "hundred", "thousand" })
-- Digits said in Spanish or Portuguese (lexicon.foreign_digits) beside another digit of either
-- language, said or typed, or a spelled letter, are those digits in English: "Copa tres one one" ->
-- "Copa three one one", "Speedbird ocho charlie kilo" -> "Speedbird eight charlie kilo".
-- The words of `text` and each in lower case without the punctuation closing it. Callers only read
-- the lists: the last text's are kept (heard_forms mostly reads the text foreign_digits read).
local last_plain, plain_toks, plain_bare
local function plain_words(text)
  if text ~= last_plain then
    plain_toks, plain_bare = {}, {}
    for w in text:gmatch("%S+") do
      plain_toks[#plain_toks + 1] = w
      plain_bare[#plain_bare + 1] = w:lower():match("^(.-)%p*$")
    end
    last_plain = text
  end
  return plain_toks, plain_bare
end
-- True when one of the words `bare` is a key of `set`.
local function any_of(bare, set)
  for k = 1, #bare do
    if set[bare[k]] ~= nil then return true end
  end
  return false
end
local function foreign_digits(text)
  local toks, bare = plain_words(text)
  local F = lexicon.foreign_digits
  if not any_of(bare, F) then return text end
  local function digit(k)
    local w = bare[k]
    return w ~= nil and (F[w] ~= nil or NUMBER_WORDS[w] == true or w:match("^%d+$") ~= nil
      or lexicon.phonetic[w] ~= nil or lexicon.foreign_hesitation_digits[w] ~= nil)
  end
  -- (true when the run of digit words about token i, no punctuation parting them, holds a word of F)
  local function foreign_run(i)
    for step = -1, 1, 2 do
      local k = i + step
      while digit(k) and not toks[math.min(k, k - step)]:match("%p$") do
        if F[bare[k]] then return true end
        k = k + step
      end
    end
    return false
  end
  return tokens.rewrite(text, toks, function(i)
    local en = F[bare[i]]
    if not en then
      en = lexicon.foreign_hesitation_digits[bare[i]]
      if en and foreign_run(i) then return en .. (toks[i]:match("%p+$") or ""), i + 1 end
      return nil
    end
    -- (punctuation closing the word before parts the two: "Iberia tres uno... Iberia three")
    local beside = (digit(i - 1) and not toks[i - 1]:match("%p$")) or (digit(i + 1) and not toks[i]:match("%p$"))
    if beside then return en .. (toks[i]:match("%p+$") or ""), i + 1 end
  end)
end
local function heard_word_is(w, set)
  if not w then return false end
  -- ("#capital": a word typed with a capital, a name: "as soon as Swiss 200 is level", "as soon as KLM12 ...")
  if set["#capital"] and w:match("^%u") then return true end
  -- ("#code": a word of three to five capitals, a fix or navaid as typed: "when it passed ABATU")
  if set["#code"] and w:match("^%u%u%u%u?%u?%p*$") then return true end
  w = w:lower():gsub("%p+$", "")
  return set[w] == true or (set["#number"] == true and (NUMBER_WORDS[w] == true or w:match("^%d") ~= nil
    or w:match("^fl%d+$") ~= nil or NUMBER_WORDS[w:match("^(%a+)%-%a") or ""] == true))  -- ("one-two-zero")
end
-- lexicon.heard_as by the first word of each heard form
local HEARD = {}
for _, h in ipairs(lexicon.heard_as) do
  for _, form in ipairs(h.heard) do
    local words = {}
    for w in form:gmatch("%S+") do words[#words + 1] = w end
    HEARD[words[1]] = HEARD[words[1]] or {}
    table.insert(HEARD[words[1]], { words = words, means = h.means, before = h.before and set_of(h.before),
                                    after = h.after and set_of(h.after), not_after = h.not_after and set_of(h.not_after),
                                    between = h.between and { set_of(h.between[1]), set_of(h.between[2]) } })
  end
end
-- The words that, straight after a form of lexicon.heard_as read before its value, closed by punctuation, take
-- it back ("cap... sorry, heading 240", "niveau, correction, level 120"): the form is its English word, which
-- the self-correction then replaces (lexicon.self_correction.markers of one word, lexicon.correction).
G.heard_taken_back = set_of(lexicon.correction)
for _, w in ipairs(lexicon.self_correction.markers) do
  if not w:find(" ") then G.heard_taken_back[w] = true end
end
-- Speech recognition's sound-alike forms of instruction words
-- (lexicon.heard_as), rewritten only where the instruction word is expected.
local function heard_forms(text)
  local toks, bare = plain_words(text)
  if not any_of(bare, HEARD) then return text end
  return tokens.rewrite(text, toks, function(i)
    local forms = HEARD[bare[i]]
    if not forms then return nil end
    for _, h in ipairs(forms) do
      local n = #h.words
      local ok = true
      -- punctuation may close the last word only ("turn write, heading")
      for k = 2, n do ok = ok and bare[i + k - 1] == h.words[k] end
      for k = 1, n - 1 do ok = ok and not toks[i + k - 1]:match("%p$") end
      if ok and not (h.not_after and heard_word_is(toks[i - 1], h.not_after)) then
        local last = toks[i + n - 1]
        local closed = last:match("%p$") ~= nil
        local joined_before = toks[i - 1] ~= nil and not toks[i - 1]:match("%p$")
        if (h.before and not closed and heard_word_is(toks[i + n], h.before))
            or (h.before and closed and G.heard_taken_back[bare[i + n]])
            or (h.after and joined_before and heard_word_is(toks[i - 1], h.after))
            or (h.between and not closed and joined_before and heard_word_is(toks[i - 1], h.between[1])
                and heard_word_is(toks[i + n], h.between[2])) then
          return h.means .. (last:match("%p+$") or ""), i + n
        end
      end
    end
  end)
end

-- lexicon.said_whole's words and phrases by language, then by their first word: language -> first word ->
-- { {words, means, joining, marks}, ... }, longest first (`means` false: kept as said); `joining` for a form
-- of the language's `joining`, `marks` when the form makes its sentence that language's. Built once, on
-- first use.
function G.said_whole_index()
  if not G.said_whole_built then
    G.said_whole_built = {}
    for language, S in pairs(lexicon.said_whole) do
      local index = {}
      local function add(key, means, joining, marks)
        local words = {}
        for w in key:gmatch("%S+") do words[#words + 1] = w end
        index[words[1]] = index[words[1]] or {}
        table.insert(index[words[1]], { words = words, means = means, joining = joining, marks = marks })
      end
      for key, means in pairs(S.words) do add(key, means, false, not S.shared[key]) end
      for key, means in pairs(S.joining) do add(key, means, true, false) end
      for _, forms in pairs(index) do
        table.sort(forms, function(x, y)
          if #x.words ~= #y.words then return #x.words > #y.words end
          return x.marks and not y.marks
        end)
      end
      G.said_whole_built[language] = index
    end
    -- (G.said_whole_firsts: every language's first words, one set)
    G.said_whole_firsts = {}
    for _, index in pairs(G.said_whole_built) do
      for w in pairs(index) do G.said_whole_firsts[w] = true end
    end
  end
  return G.said_whole_built
end
-- One language said whole (lexicon.said_whole), read as its English: "vire a la izquierda rumbo 170" ->
-- "turn left heading 170", "montez au niveau 140" -> "climb to flight level 140". A sentence holding a
-- marking word of a language (the first of G.said_whole_order holding one) is read in that language alone;
-- one holding none, in every language's words that mark none.
G.said_whole_order = { "spanish", "french", "german", "dutch", "portuguese", "nordic", "malay", "greek", "italian" }
function G.said_whole(text)
  local indexes = G.said_whole_index()
  -- (the form of `index` starting at token i, or nil; punctuation may close its last word only; `joining`
  -- forms only when `marked`)
  -- (a word typed in capitals is a name or a code, never a form: "over OKE", "direct JA")
  -- (a joining word capitalised inside the request before a capitalised word opens a name: "at El Dorado", "la
  -- Aurora" and "Los Angeles" are places, never "the")
  local function form_at(index, toks, bare, i, marked)
    local forms = index[bare[i]]
    if not forms or toks[i]:match("^%u%u+%p*$") then return nil end
    local names = i > 1 and toks[i]:match("^%u%l*$") and toks[i + 1] and toks[i + 1]:match("^%u") ~= nil
    for _, h in ipairs(forms) do
      local ok = (marked or not h.joining) and not (names and h.joining)
      for k = 2, #h.words do ok = ok and bare[i + k - 1] == h.words[k] and not toks[i + k - 2]:match("%p$") end
      if ok then return h end
    end
  end
  local function read(index, marked)
    local toks, bare = plain_words(text)
    if not any_of(bare, index) then return text end
    return tokens.rewrite(text, toks, function(i)
      local h = form_at(index, toks, bare, i, marked)
      local n = h and #h.words or 1
      if h and h.means == false then return table.concat(toks, " ", i, i + n - 1), i + n end
      local en = h and h.means or (marked and lexicon.foreign_digits[bare[i]])
      if en then return en .. (toks[i + n - 1]:match("%p+$") or ""), i + n end
    end)
  end
  local toks, bare = plain_words(text)
  if not any_of(bare, G.said_whole_firsts) then return text end  -- (no form of any language starts here)
  for _, language in ipairs(G.said_whole_order) do
    local index = indexes[language]
    if any_of(bare, index) then
      for i = 1, #toks do
        local h = form_at(index, toks, bare, i, false)
        if h and h.marks then return read(index, true) end
      end
    end
  end
  for _, language in ipairs(G.said_whole_order) do text = read(indexes[language], false) end
  return text
end

-- French inside an English request (lexicon.french_in_english): a run of French number words making one number
-- with a word of tens, hundreds or thousands is its digits ("cap deux cent quatre-vingt-dix" -> "cap 290"); a run
-- that makes none stays as said (asked). "et" (not typed "ET", a code) is "and", "et puis" "and then", unless a
-- value follows it ("speed 250 et FL100" may be "at": asked).
function G.french_in_english(text)
  local L = lexicon.french_in_english
  -- (G.french_opens: the words that open a run or a join; G.french_words: those and every part of a run. Built
  -- once, on first use)
  if not G.french_opens then
    local opens, words = {}, {}
    for _, set in ipairs({ L.units, L.teens, L.tens }) do
      for w in pairs(set) do opens[w], words[w] = true, true end
    end
    for _, w in ipairs({ "cent", "mille", "et", "after", "après", "apres" }) do opens[w], words[w] = true, true end
    words.cents, words.vingts = true, true
    G.french_opens, G.french_words = opens, words
  end
  local opens, words = G.french_opens, G.french_words
  local toks, bare = plain_words(text)
  local found = false
  for k = 1, #bare do
    local w = bare[k]
    if opens[w] or (w:find("-", 1, true) and opens[w:match("^[^%-]+") or ""]) then found = true; break end
  end
  if not found then return text end
  -- (the parts of token k split at its hyphens, or nil when one is no French number word)
  local function parts_of(k, out)
    for part in bare[k]:gmatch("[^%-]+") do
      if not (L.units[part] or L.teens[part] or L.tens[part] or part == "cent" or part == "cents" or part == "mille"
              or part == "vingts" or part == "et") then return nil end
      out[#out + 1] = part
    end
    return out
  end
  -- (the value of parts p from index i under 100: returns value, next index; or nil)
  local function below100(p, i)
    local w, v = p[i], nil
    if w == "quatre" and (p[i + 1] == "vingt" or p[i + 1] == "vingts") then v, i = 80, i + 2
    elseif L.tens[w] then v, i = L.tens[w], i + 1
    elseif L.teens[w] then
      v, i = L.teens[w], i + 1
      if w == "dix" and L.units[p[i]] and L.units[p[i]] >= 7 then v, i = v + L.units[p[i]], i + 1 end
      return v, i
    elseif L.units[w] then return L.units[w], i + 1
    else return nil end
    -- ("vingt et un", "soixante et onze"; "soixante-dix-sept", "quatre-vingt-douze"; "trente-deux")
    if p[i] == "et" then
      if p[i + 1] == "un" and v < 80 then return v + 1, i + 2 end
      if p[i + 1] == "onze" and v == 60 then return 71, i + 2 end
      return nil
    end
    if (v == 60 or v == 80) and L.teens[p[i]] then
      local t, j = below100(p, i)
      return v + t, j
    end
    if L.units[p[i]] then return v + L.units[p[i]], i + 1 end
    return v, i
  end
  local function number(p)
    local i, total, composite = 1, 0, false
    for _, w in ipairs(p) do
      if L.teens[w] or L.tens[w] or w == "cent" or w == "cents" or w == "mille" or w == "vingts" then composite = true end
    end
    -- ("grazie mille": "cent" or "mille" alone is no value said)
    if not composite or (#p == 1 and (p[1] == "cent" or p[1] == "cents" or p[1] == "mille")) then return nil end
    if p[i] == "mille" then total, i = 1000, i + 1
    elseif p[i + 1] == "mille" or (p[i + 2] == "mille") then
      local v, j = below100(p, i)
      if not v or p[j] ~= "mille" or v < 2 then return nil end
      total, i = v * 1000, j + 1
    end
    if p[i] == "cent" then total, i = total + 100, i + 1
    elseif p[i + 1] == "cent" or p[i + 1] == "cents" then
      local u = L.units[p[i]]
      if not u or u < 2 or p[i] == "une" then return nil end
      total, i = total + u * 100, i + 2
    end
    if p[i] then
      local v, j = below100(p, i)
      if not v then return nil end
      total, i = total + v, j
    end
    if p[i] then return nil end
    return total
  end
  return tokens.rewrite(text, toks, function(i)
    if not words[bare[i]] and not bare[i]:find("-", 1, true) then return nil end
    if toks[i]:match("^%u%u+%p*$") then return nil end  -- (a code in capitals: "ET", "SEPT")
    local p = parts_of(i, {})
    if p and not (#p == 1 and p[1] == "et") then
      local j = i
      -- ("et" joins the run only before "un" or "onze": "trente et descend" is "and")
      while not toks[j]:match("%p$") and toks[j + 1] and not toks[j + 1]:match("^%u%u+%p*$")
          and (bare[j + 1] ~= "et" or bare[j + 2] == "un" or bare[j + 2] == "onze") and parts_of(j + 1, p) do
        j = j + 1
      end
      local v = number(p)
      local punct = toks[j]:match("%p+$") or ""
      if v then return tostring(v) .. punct, j + 1 end
      return table.concat(toks, " ", i, j), j + 1
    end
    if (bare[i] == "after" or bare[i] == "après" or bare[i] == "apres") and (bare[i - 1] == "and" or bare[i - 1] == "et") and not toks[i - 1]:match("%p$")
        and not toks[i]:match("%p$") and toks[i + 2] and ((bare[i + 1]:match("^%d+$") and not toks[i + 1]:match("%p$")
        and L.afterwards[bare[i + 2]]) or bare[i + 1] == "mach") then
      return "then", i + 1
    end
    if bare[i] ~= "et" or toks[i]:match("%p$") or not toks[i + 1] then return nil end
    if bare[i + 1] == "puis" then return L.joins["et puis"] .. (toks[i + 1]:match("%p+$") or ""), i + 2 end
    local nxt = bare[i + 1]
    if nxt:match("^%d") or nxt:match("^fl%d*$") or NUMBER_WORDS[nxt] or nxt == "flight" or nxt == "level"
        or nxt == "niveau" or L.units[nxt] or L.teens[nxt] or L.tens[nxt] or nxt == "cent" or nxt == "mille" then
      return nil
    end
    return L.joins.et, i + 1
  end)
end

-- Portuguese "e" (and), typed lower case, between two parts of a request ("turn right 40 degrees e descend FL210",
-- "descend FL230 e speed 270", "LATAM 3302 descend FL160 e Gol 1218 descend FL120") is "and" where no east of a
-- longitude can be meant: the word before it is no number, or closes a value of one number said after its word
-- ("fl", "level", "heading", "speed", ... : "FL230 e", "flight level two three zero e", "speed 230 e"), or a number
-- with its sign ("longitude minus 44.0 e PT02"); and the word after it is no number ("speed 250 e 260" stays
-- asked) and no letter alone ("cross e c k" spells a fix). A number after a position's other number ("52 4 e",
-- "at 52 n 4 e") stays as said: the east; one number beyond 180 alone before it ("climb at 350 e heading 100", Italian
-- "e") is no longitude, and "e" is "and".
-- "desculpa", "desculpe" (sorry) with words after it is "sorry", opening a correction ("heading 075... desculpa,
-- heading 085"); closing the request it is left as said (an apology).
G.portuguese_value_words = { fl = true, level = true, heading = true, hdg = true, speed = true, spd = true,
  mach = true, altitude = true, proa = true, nivel = true, ["nível"] = true, velocidade = true, quota = true }
function G.portuguese_and(text)
  if not (text:find("%f[%w]e%f[%W]") or text:find("[Dd]esculp")) then return text end
  local toks, bare = plain_words(text)
  local function number(k)
    local b = bare[k]
    return b ~= nil and (b:match("^%-?%.?%d[%d%.]*$") ~= nil or NUMBER_WORDS[b] ~= nil
      or lexicon.foreign_digits[b] ~= nil)
  end
  return tokens.rewrite(text, toks, function(i)
    if (bare[i] == "desculpa" or bare[i] == "desculpe") and toks[i + 1] then
      return "sorry" .. (toks[i]:match("%p+$") or ""), i + 1
    end
    if toks[i] ~= "e" or i < 2 or not toks[i + 1] or toks[i - 1]:match("[%.;:]$") then return nil end
    if number(i + 1) or #bare[i + 1] < 2 then return nil end  -- (a letter after it: a name spelled, "cross e c k")
    if number(i - 1) then
      local k, digits = i - 1, 0
      while k >= 1 and number(k) and (k == i - 1 or not toks[k]:match("%p$")) do
        if bare[k]:match("%d") then digits = digits + 1 end
        k = k - 1
      end
      local signed = bare[i - 1]:match("^%-") or (k == i - 2 and (bare[k] == "minus" or bare[k] == "negative"))
      local valued = k >= 1 and (G.portuguese_value_words[bare[k]] or bare[k] == "fl") and digits <= 1
      -- (one number beyond 180 said alone, "climb at 350 e heading 100": no longitude's degrees)
      local beyond = k == i - 2 and tonumber(bare[i - 1]) ~= nil and tonumber(bare[i - 1]) > 180
      if not (signed or valued or beyond) then return nil end
    elseif bare[i - 1]:match("^fl%d+$") == nil and #bare[i - 1] == 1 then
      return nil  -- (a letter before it: "N 52 E", a spelled callsign)
    end
    return "and", i + 1
  end)
end

-- A level or heading whose digits were written apart ("fl 3 4 0", "flight level 1 30", "heading 0 90"):
-- groups of one or two digits straight after "fl", "level", "heading" or "hdg" that make two or three
-- digits together are one value. After the typed abbreviations "fl" and "hdg" only single digits join a
-- first group ("hdg 2 7 0", "fl 16 0"): a typed "hdg 2 70" may have lost or gained a digit and stays apart
-- (asked).
local SPLIT_AFTER = { fl = "^%d$", hdg = "^%d$", level = "^%d%d?$", heading = "^%d%d?$" }
-- Three single digits written apart before a speed's unit are one speed ("maintain 2 1 0 knots"); two, the
-- first no zero and no digit before them, before "thousand" are one count of thousands ("descend to 1 1
-- thousand" is 11 thousand).
local SPLIT_BEFORE = { knots = true, kts = true, kt = true, knot = true }
local function split_digits(text)
  if not text:find("%d%s+%d") then return text end  -- (no two digit groups side by side)
  local toks = {}
  for w in text:gmatch("%S+") do toks[#toks + 1] = w end
  -- (lexicon.speed_split: groups of one or two digits straight after a speed word, or after "to" after one,
  -- that make three digits, 100 to 399, with no digit after them, are one speed: "reduce to 2 5 0", "speed 2
  -- 40"; the last may carry punctuation. Returns the speed and the token after it, or nil)
  local function speed_at(i)
    local w, before = toks[i]:lower(), toks[i - 1] and toks[i - 1]:lower()
    if not (lexicon.speed_split[w] or (w == "to" and lexicon.speed_split[before])) then return nil end
    local j, digits, punct = i + 1, "", ""
    while toks[j] and punct == "" do
      local d, p = toks[j]:match("^(%d%d?)(%p*)$")
      if not d or #digits + #d > 3 then break end
      digits, punct, j = digits .. d, p, j + 1
    end
    if j - i > 2 and digits:match("^[1-3]%d%d$") and not (punct == "" and toks[j] and toks[j]:match("^%d")) then
      return digits .. punct, j
    end
  end
  local out, i, changed = {}, 1, false
  while i <= #toks do
    out[#out + 1] = toks[i]
    local k, joined = i + 1, ""
    local group = SPLIT_AFTER[toks[i]:lower()]
    if group then
      while toks[k] and toks[k]:match(k == i + 1 and "^%d%d?$" or group) and #joined + #toks[k] <= 3 do
        joined, k = joined .. toks[k], k + 1
      end
    end
    local speed, after = speed_at(i)
    if k - i > 2 and #joined >= 2 then
      out[#out + 1], i, changed = joined, k, true
    elseif speed then
      out[#out + 1], i, changed = speed, after, true
    elseif toks[i + 3] and SPLIT_BEFORE[toks[i + 3]:lower()] and (toks[i] .. toks[i + 1] .. toks[i + 2]):match("^%d%d%d$")
        and #toks[i] == 1 and (not toks[i - 1] or not toks[i - 1]:match("^%d$")) then
      out[#out], i, changed = toks[i] .. toks[i + 1] .. toks[i + 2], i + 3, true
    elseif toks[i + 2] and toks[i + 2]:lower():match("^thousand%p*$") and toks[i]:match("^[1-9]$") and toks[i + 1]:match("^%d$")
        and (not toks[i - 1] or not toks[i - 1]:match("%d$")) then
      out[#out], i, changed = toks[i] .. toks[i + 1], i + 2, true
    else
      i = i + 1
    end
  end
  return changed and table.concat(out, " ") or text
end

-- An abbreviation spelled letter by letter, as speech recognition writes it ("q n h", "i l s"): single
-- letters in a row that together are a word of lexicon.spelled, lexicon.not_simulated or lexicon.not_names
-- are that word.
local SPELLED = set_of(lexicon.not_names)
for _, w in ipairs(lexicon.spelled) do SPELLED[w] = true end
for _, n in ipairs(lexicon.not_simulated) do
  for w in n.words:gmatch("%S+") do SPELLED[w] = true end
end
local function spelled(text)
  -- (no single letter before another: "q n", "h,")
  if not (" " .. text .. " "):find("%s%a%s+%a[%s%p]") then return text end
  local toks = {}
  for w in text:gmatch("%S+") do toks[#toks + 1] = w end
  return tokens.rewrite(text, toks, function(i)
    if #toks[i] ~= 1 then return nil end  -- (a run starts with a single letter)
    local k = i
    while toks[k] and toks[k]:match("^%a$") do k = k + 1 end
    -- (the last letter may carry the punctuation: "q n h, one zero one three")
    local last = toks[k] and toks[k]:match("^(%a)%p+$")
    local word = table.concat(toks, "", i, k - 1):lower() .. (last and last:lower() or "")
    if k - i + (last and 1 or 0) >= 2 and SPELLED[word] then
      return word .. (last and toks[k]:sub(2) or ""), k + (last and 1 or 0)
    end
  end)
end

-- A capital "A" spelled in a callsign ("create Lufthansa 1 A B, an A321", "Speedbird 12 C A, heading 090"): after a
-- flight number's digits (spelled capital letters between or not) and before a spelled capital letter, a mark or
-- the end, it is the letter, never the article (a noun follows that); written as its phonetic word, which the
-- callsign reader takes as it takes every other capital letter.
function G.spelled_letter_a(text)
  if not text:find("%f[%w]A%f[%W]") then return text end
  local toks = {}
  for w in text:gmatch("%S+") do toks[#toks + 1] = w end
  return tokens.rewrite(text, toks, function(i)
    local mark = toks[i]:match("^A([,%.;:!%?]*)$")
    if not mark then return nil end
    local k = i - 1
    while k > 1 and toks[k]:match("^%u$") do k = k - 1 end
    if k < 1 or not toks[k]:match("^%d+$") then return nil end
    local nxt = toks[i + 1]
    if mark == "" and nxt and not nxt:match("^%u[,%.;:!%?]*$") then return nil end
    return "Alpha" .. mark, i + 1
  end)
end

-- Self-corrections said in words (lexicon.self_correction) become the word "correction", which the
-- value handlers read: "reduce 270, no wait, 260" is "reduce 270 , correction , 260".
local DIGIT_WORDS = set_of({ "zero", "oh", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine",
  "niner", "tree", "fife", "fower" })
local UNIT_WORDS = set_of({ "feet", "ft", "knots", "knot", "kts", "kt", "degrees" })
local SIDES = set_of({ "left", "right" })
G.refusable = set_of(lexicon.refusable_verbs)
-- The words of `text` as {at, e, raw, bare} (at, e: byte positions of the word and after it; bare: lower
-- case, punctuation trimmed at both ends). Callers only read the list: the last text's is kept, as
-- the rewrites below mostly pass the text on unchanged.
local last_text, last_words
local function bare_words(text)
  if text == last_text then return last_words end
  local toks = {}
  for at, w, e in text:gmatch("()(%S+)()") do
    toks[#toks + 1] = { at = at, e = e, raw = w, bare = w:lower():match("^%p*(.-)%p*$") }
  end
  last_text, last_words = text, toks
  return toks
end
local SC_WORDS, SC_MARKERS, SC_AFTER = set_of(lexicon.self_correction.words),
  set_of(lexicon.self_correction.markers), set_of(lexicon.self_correction.after)
local SC_CLOSING = set_of(lexicon.self_correction.closing)
-- (G.sc_value_words: the words of a run between two values, lexicon.self_correction's words and value_words)
G.sc_value_words = set_of(lexicon.self_correction.value_words)
for w in pairs(SC_WORDS) do G.sc_value_words[w] = true end
-- (G.sc_dropping: the first words of the markers that take back in words, a set)
G.sc_dropping = set_of(lexicon.self_correction.dropping)
-- {word, pattern} of the first word of each marker, the pattern finding it as a whole word in lower-case
-- text (a marker's word is a token's bare text only where one of these finds it)
local SC_MARKER_PATTERNS = {}
for _, m in ipairs(lexicon.self_correction.markers) do
  local w = m:match("^%S+")
  SC_MARKER_PATTERNS[#SC_MARKER_PATTERNS + 1] = { word = w, pattern = "%f[%w]" .. w .. "%f[%W]" }
end
-- True when the lower-case text holds one of the words of `patterns` whole ({word, pattern} as above; the
-- pattern is tried only where a plain find sees the word).
local function holds_word(lower, patterns)
  for k = 1, #patterns do
    local p = patterns[k]
    if lower:find(p.word, 1, true) and lower:find(p.pattern) then return true end
  end
  return false
end
-- "30 degrees right, er, left": a side, hesitations only (lexicon.hesitations, "hmm") and the other side is
-- the side corrected ("right, correction, left")
local SIDE_HESITATIONS = set_of(lexicon.hesitations)
SIDE_HESITATIONS.hmm, SIDE_HESITATIONS.ehm, SIDE_HESITATIONS.erm, SIDE_HESITATIONS.uhm = true, true, true, true
local function hesitated_sides(text)
  local lower = text:lower()
  if not lower:find("%f[%a]left%f[%A]") or not lower:find("%f[%a]right%f[%A]") then return text end
  local toks = bare_words(text)
  local put, done = tokens.splicer(text)
  for k, t in ipairs(toks) do
    local j = k + 1
    while SIDES[t.bare] and toks[j] and SIDE_HESITATIONS[toks[j].bare] do j = j + 1 end
    if j > k + 1 and toks[j] and SIDES[toks[j].bare] and toks[j].bare ~= t.bare then
      put(t.e, ", correction, ", toks[j].at)
    end
  end
  return done()
end
-- "Mach 0.80 -- pardon me, Mach 0.78": a formal apology (lexicon.self_correction.formal_apology) is the marker
-- "sorry", read by the corrections below and by the handlers as that word.
G.formal_apology_patterns = {}
for _, p in ipairs(lexicon.self_correction.formal_apology) do
  G.formal_apology_patterns[#G.formal_apology_patterns + 1] = { last = p:match("(%S+)$"), pattern = "%f[%w]" .. p:gsub(" ", "%%s+") .. "%f[%W]" }
end
function G.formal_apologies(text)
  local lower = text:lower()
  -- (an apology set off as a sentence or clause of its own, with more of the request after it:
  -- lexicon.self_correction.apology_sentence)
  if lower:find("apolog", 1, true) or lower:find("sorry", 1, true) then
    for _, p in ipairs(lexicon.self_correction.apology_sentence) do
      local pattern = "%f[%w]" .. p:gsub(" ", "%%s+") .. "%f[%W]"
      local from = 1
      while true do
        local b, e = lower:find(pattern, from)
        if not b then break end
        local before = lower:sub(1, b - 1):match("(%S?)%s*$")
        local mark, rest = lower:sub(e + 1):match("^%s*([%.,;!%-]+)%s*(.*)$")
        if before ~= "" and before:match("^[%.,;!%-]$") and mark and rest:match("%w") then
          text = text:sub(1, b - 1) .. "sorry" .. text:sub(e + 1)
          lower = text:lower()
          from = b + 5
        else
          from = e + 1
        end
      end
    end
  end
  for _, a in ipairs(G.formal_apology_patterns) do
    if lower:find(a.last, 1, true) then
      local b, e = lower:find(a.pattern)
      while b do
        text = text:sub(1, b - 1) .. "sorry" .. text:sub(e + 1)
        lower = text:lower()
        b, e = lower:find(a.pattern)
      end
    end
  end
  return text
end
-- "Condor, eh, Speedbird 948 I mean, heading 130", "FL240, FL250 I mean, and ...": one to three words said after a
-- comma, or after a hesitation (SIDE_HESITATIONS) and a mark, then "I mean" or "I meant" straight after them, a
-- mark and more words, are said in place of what came before: "I mean" is moved before them, where the
-- self-corrections read it ("Condor, eh, I mean Speedbird 948, heading 130"). Closing the request, "I mean" says
-- who or what was meant ("..., Lufthansa 4AX I mean": handlers.lua m:aircraft_named_after), no replacement.
function G.meant_after_hesitation(text)
  local lower = text:lower()
  if not lower:find("%f[%a]i%s+meant?%f[%A]") then return text end
  local toks = bare_words(text)
  local put, done = tokens.splicer(text)
  for k = 3, #toks - 1 do
    local mean = toks[k + 1]
    if toks[k].bare == "i" and (mean.bare == "mean" or mean.bare == "meant") and not toks[k].raw:match("%p$")
        and mean.raw:match("%p$") and toks[k + 2] and not toks[k - 1].raw:match("%p$") then
      local s = k - 1
      while s > k - 3 and toks[s - 1] and not toks[s - 1].raw:match("%p$") do s = s - 1 end
      local h = toks[s - 1]
      if h and (h.raw:match(",$") or h.raw:match("%p$") and SIDE_HESITATIONS[h.bare] and toks[s - 2]) then
        put(toks[s].at, "I " .. mean.bare .. " ", toks[s].at)
        put(toks[k - 1].e, "", mean.at + #mean.bare)
      end
    end
  end
  return done()
end
-- "instructor, how do I... no, never mind. KLM12 climb FL300", "KLM12, delete waypoint... it has no route. Never
-- mind. KLM12 turn left heading 200": a sentence of its own that takes back in words all said before it
-- (G.withdrawing_sentence: "never mind", "nevermind", "forget it", "forget that", after a mark or at the start, "no",
-- "oh", "ok" before it, "." or "!" after it) with a request after it: what came before is dropped when it holds no
-- value (no digit, no number word) past the words the request after it opens with again (its callsign said again).
-- Anything else stays as said.
G.withdrawing_sentence = { "never mind", "nevermind", "forget it", "forget that" }
function G.withdrawn_sentences(text)
  local lower = text:lower()
  if not (lower:find("mind", 1, true) or lower:find("forget", 1, true)) then return text end
  local cut
  for _, p in ipairs(G.withdrawing_sentence) do
    local from = 1
    while true do
      local b, e = lower:find("%f[%w]" .. p:gsub(" ", "%%s+") .. "%f[%W]", from)
      if not b then break end
      from = e + 1
      local rest = lower:match("^%s*[%.!]+%s*()%w", e + 1)
      local before = lower:sub(1, b - 1):gsub("[%s,]+$", "")
      local prev = before:match("(%a+)$")
      while prev == "no" or prev == "oh" or prev == "ok" or prev == "okay" do
        before = before:sub(1, #before - #prev):gsub("[%s,]+$", "")
        prev = before:match("(%a+)$")
      end
      if rest and before ~= "" and before:match("[%.!?,;:]$") and (not cut or rest > cut.rest) then
        cut = { rest = rest, before = before }
      end
    end
  end
  if not cut then return text end
  local said, again = {}, {}
  for w in cut.before:gmatch("[%w']+") do said[#said + 1] = w end
  for w in lower:sub(cut.rest):gmatch("[%w']+") do again[#again + 1] = w end
  local k = 1
  while said[k] and said[k] == again[k] do k = k + 1 end
  for x = k, #said do
    if said[x]:find("%d") or NUMBER_WORDS[said[x]] then return text end
  end
  return text:sub(cut.rest)
end
-- "speed 250 knots... sorry, I mistook, 230 knots": a slip admitted (lexicon.self_correction.admitted) and set
-- off by a mark with more words after it is the marker "sorry"; anywhere else it is left as said.
G.admitted_patterns = {}
for _, p in ipairs(lexicon.self_correction.admitted) do
  G.admitted_patterns[#G.admitted_patterns + 1] = { last = p:match("(%S+)$"),
    pattern = "%f[%w]" .. p:gsub(" ", "%%s+") .. "()%s*[,;:%.!%-]+%s*%w" }
end
function G.admitted_slips(text)
  local lower = text:lower()
  for _, a in ipairs(G.admitted_patterns) do
    if lower:find(a.last, 1, true) then
      local b, _, e = lower:find(a.pattern)
      while b do
        text = text:sub(1, b - 1) .. "sorry" .. text:sub(e)
        lower = text:lower()
        b, _, e = lower:find(a.pattern)
      end
    end
  end
  return text
end
-- {first, rest} of each phrase of lexicon.self_correction.restated ("it is": "it", {"is"})
G.restated = {}
for _, p in ipairs(lexicon.self_correction.restated) do
  local ws = {}
  for w in p:gmatch("%S+") do ws[#ws + 1] = w end
  G.restated[#G.restated + 1] = ws
end
-- The index of the word after a phrase of G.restated said from toks[j] with no mark inside it, else nil.
function G.after_restated(toks, j)
  for _, ws in ipairs(G.restated) do
    local n = 0
    while n < #ws and toks[j + n] and toks[j + n].bare == ws[n + 1]
        and (n == #ws - 1 or not toks[j + n].raw:match("%p$")) do n = n + 1 end
    if n == #ws and not toks[j + n - 1].raw:match("%p$") and toks[j + n] then return j + n end
  end
  return nil
end
-- True when the words toks[k .. j - 1] are hesitations only (lexicon.hesitations, "erm", "uhm", "hmm") between two
-- digit strings of the same length (two or more digits, each one numeral, "fl250", or digit words said one by
-- one): the first after a word of a value (lexicon.self_correction.after, "to", "at", an instruction's verb) or
-- prefixed by its letters ("fl250"), the second with no unit word or more digits after it.
G.hesitation_words = set_of(lexicon.hesitations)
G.hesitation_words.erm, G.hesitation_words.uhm, G.hesitation_words.hmm = true, true, true
G.valued_before = set_of({ "to", "at", "climb", "descend", "maintain", "reduce", "increase", "hdg", "spd", "alt" })
for _, w in ipairs(lexicon.self_correction.after) do G.valued_before[w] = true end
G.digit_words = set_of({ "zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "niner",
  "tree", "fife", "fower" })
G.hesitation_patterns = {}
for w in pairs(G.hesitation_words) do
  G.hesitation_patterns[#G.hesitation_patterns + 1] = { word = w, pattern = "%f[%w]" .. w .. "%f[%W]" }
end
function G.hesitant_value(toks, k, j)
  for x = k, j - 1 do
    if not (G.hesitation_words[toks[x].bare] or toks[x].bare == "") then return false end
  end
  -- the digits of the string ending at toks[e] (step -1) or starting there (step 1), the token past it
  local function digits(e, step)
    local t = toks[e]
    if not t then return 0, e end
    local numeral = t.bare:match("^%a?%a?(%d+)$")
    if numeral then return #numeral, e + step end
    local n = 0
    while toks[e] and G.digit_words[toks[e].bare] and (n == 0 or not toks[step > 0 and e - 1 or e].raw:match("%p$")) do
      n, e = n + 1, e + step
    end
    return n, e
  end
  local before, b = digits(k - 1, -1)
  local after, e = digits(j, 1)
  if before < 2 or before ~= after then return false end
  local lead = toks[k - 1].bare:match("^%a%a?%d") or (toks[b] and G.valued_before[toks[b].bare])
  return lead and not (toks[e] and not toks[e - 1].raw:match("%p$") and (UNIT_WORDS[toks[e].bare]
    or NUMBER_WORDS[toks[e].bare] or toks[e].bare:match("^%d")))
end
-- True when the words toks[1 .. k-1], from the last sentence mark (".", ";", "!", "?") on, name a value or an
-- instruction (a word of G.valued_before, a unit, a flight level typed "fl300"): a run that takes back in words
-- ("never mind", "forget", "scratch", "belay": lexicon.self_correction.dropping) after them corrects it ("climb
-- FL310 never mind FL300"). After a callsign alone, no mark after the run ("DLH3 never mind FL300"), the run takes
-- back what follows, no correction (G:instruction_withheld asks); with a mark ("DLH3 never mind, FL300") what
-- follows is said in place of an earlier request.
function G.valued_words_before(toks, k)
  for x = k - 1, 1, -1 do
    local t = toks[x]
    if x < k - 1 and t.raw:match("[%.;!%?]$") then return false end
    if G.valued_before[t.bare] or UNIT_WORDS[t.bare] or t.bare:match("^fl%d") or t.bare:match("^%d+%a+$") then
      return true
    end
  end
  return false
end
-- "Turkish 876, descend FL240, sorry, Turkish 876 should climb to FL320", "Aseman 6542 climb FL150, sorry, the
-- Aseman should descend to 11000 feet, not climb": the request's addressee (a word and a number, or a word with
-- digits, opening it) said again straight after "sorry" or "correction" (formal apologies and admitted slips read
-- as "sorry" before), as said or as "the" and its first word, then a modal of lexicon.self_correction.restated_modals
-- or not, is dropped: the instruction after it corrects the one before. A ", not climb" (or descend) closing a
-- request whose "sorry" is followed by the other verb names the instruction taken back, and is dropped too.
G.restated_not_addressee = set_of({ "please", "kindly", "climb", "descend", "turn", "speed", "heading", "reduce",
  "increase", "maintain", "fly", "set", "the", "and", "to", "flight", "level", "fl", "at", "by", "of", "for", "with" })
function G.restated_addressee(text)
  local lower = text:lower()
  if not (lower:find("sorry", 1, true) or lower:find("correction", 1, true)) then return text end
  local a = lower:match("^%s*(%a[%a ]-%s%d+%w*)") or lower:match("^%s*(%a+%d+%w*)")
  if a and #a > 30 then a = nil end
  local airline = a and a:match("^(%a[%a ]-)%s*%d")
  -- (no words of an instruction: "please climb 5000, sorry, ..." opens with no addressee)
  for w in (airline or ""):gmatch("%a+") do
    if G.restated_not_addressee[w] then a = nil end
  end
  local forms = a and { a, "the " .. a, "the " .. airline, "the " .. a:match("^(%a+)") } or {}
  for _, marker in ipairs({ "sorry", "correction" }) do
    local from = 1
    while true do
      local _, me = lower:find(marker .. "[%s,]+", from)
      if not me then break end
      from = me + 1
      for _, f in ipairs(forms) do
        if lower:sub(me + 1, me + #f) == f and lower:sub(me + #f + 1, me + #f + 1):match("[%s,]") then
          local e = me + #f + 1
          local rest = lower:sub(e)
          local sp = rest:match("^[%s,]+") or ""
          local after = rest:sub(#sp + 1)
          local modal = ""
          for _, m in ipairs(lexicon.self_correction.restated_modals) do
            if after:sub(1, #m + 1) == m .. " " then modal = m .. " " break end
          end
          -- (a letter word next, no number: "the KLM 45" names another aircraft)
          if after:sub(#modal + 1):match("^%a") then
            local cut = e + #sp + #modal
            text = text:sub(1, me) .. text:sub(cut)
            lower = text:lower()
            break
          end
        end
      end
    end
  end
  for _, pair in ipairs({ { "climb", "descend" }, { "descend", "climb" } }) do
    local b = lower:find("[%s,]+not%s+" .. pair[1] .. "%a*[%.!]?%s*$")
    if b and lower:find("sorry[%s,]+" .. pair[2]) then text = text:sub(1, b - 1) .. "." end
  end
  return text
end
-- "Mach 0.7, no, better in knots please, 240 knots": after a marker of lexicon.self_correction.markers (one word,
-- its mark) and "better" or "rather", "in" and a unit of lexicon.self_correction.restated_units, "please", then a
-- mark and straight after it a value in that unit: "in UNIT please" and its mark are dropped
-- ("no, better 240 knots"), read by the self-corrections as the value said again; closing the request with no
-- value after it, the phrase is dropped ("Mach 0.7, no,": asked). Anywhere else left as said.
G.unit_restated_markers = { no = true, sorry = true, wait = true, actually = true }
function G.unit_restated(text)
  local lower = text:lower()
  if not lower:find("%f[%a]in%s+%a") then return text end
  for _, unit in ipairs(lexicon.self_correction.restated_units) do
    for _, said in ipairs(unit.said) do
      local b, e = lower:find("%f[%a]in%s+" .. said:gsub(" ", "%%s+") .. "%f[%A]")
      while b do
        local pre = lower:sub(1, b - 1):gsub("[%s,]*$", "")
        pre = pre:gsub("%f[%a]better$", ""):gsub("%f[%a]rather$", ""):gsub("[%s,]*$", "")
        local marker = pre:match("%f[%a](%a+)[%s,%.!]*$")
        local rest = lower:sub(e + 1)
        local cut = rest:match("^%s*please()") or 1
        local mark = rest:match("^%s*[,;:%.%-]+%s*()", cut)
        local valued = false
        if mark and pre:match("[,%.!;%-]%s*%a+$") and marker and G.unit_restated_markers[marker] then
          local ahead = rest:sub(mark, mark + 24)
          for _, v in ipairs(unit.value) do valued = valued or ahead:find(v) ~= nil end
        end
        if marker and G.unit_restated_markers[marker] and pre:match("[,%.!;%-]%s*%a+$")
            and rest:match("^[%s%p]*$", cut) then
          -- (closing the request, the unit asked for with no value: "Mach 0.7, no, better in knots" leaves the
          -- marker closing it, a value taken back with none in its place: asked)
          return text:sub(1, #pre)
        elseif valued then
          text = text:sub(1, b - 1) .. text:sub(e + mark)
          lower = text:lower()
          b, e = lower:find("%f[%a]in%s+" .. said:gsub(" ", "%%s+") .. "%f[%A]")
        else
          b, e = lower:find("%f[%a]in%s+" .. said:gsub(" ", "%%s+") .. "%f[%A]", e + 1)
        end
      end
    end
  end
  return text
end
local function self_corrections(text)
  text = G.restated_addressee(G.meant_after_hesitation(hesitated_sides(G.formal_apologies(G.admitted_slips(
    G.withdrawn_sentences(G.unit_restated(text)))))))
  if not holds_word(text:lower(), SC_MARKER_PATTERNS) and not holds_word(text:lower(), G.hesitation_patterns) then
    return text
  end
  local words, markers, after = G.sc_value_words, SC_MARKERS, SC_AFTER
  local toks = bare_words(text)
  local function value(t) return t and (t.raw:match("%d%p*$") or NUMBER_WORDS[t.bare] or UNIT_WORDS[t.bare]) end
  local put, done = tokens.splicer(text)
  local k = 1
  while k <= #toks do
    local j, marked, dropping = k, false, false
    -- (punctuation alone, "...", belongs to the run)
    while toks[j] and (words[toks[j].bare] or toks[j].bare == "") do
      marked = marked or markers[toks[j].bare] or (toks[j + 1] and markers[toks[j].bare .. " " .. toks[j + 1].bare])
      dropping = dropping or G.sc_dropping[toks[j].bare]
      j = j + 1
    end
    local nxt = toks[j]
    -- (a position corrected: "at 34 30 S 58 50 W, no, at -34.50 -58.83": a hemisphere after a number before,
    -- "at" and a number after)
    local position = toks[k - 1] and toks[k - 1].raw:match("^[NnSsEeWw]%p*$") and value(toks[k - 2])
      and nxt and nxt.bare == "at" and toks[j + 1] and toks[j + 1].raw:match("^%-?%d")
    -- (a turn's side corrected: "turn left... I mean right heading 200")
    -- (a run that takes back in words, "never mind", "forget that", before an instruction's word is no value
    -- corrected: G:self_corrected reads the instruction said in its place)
    -- (an apology after a value ruled out, "fl200 not 180 sorry, ...", corrects nothing: negated_values)
    -- ("PRF441 no left turn": "no" with no mark after it, before a turn's side and an instruction's verb, may refuse
    -- it: G:unaccounted asks)
    local refused = nxt and SIDES[nxt.bare] and toks[j + 1] and G.refusable[toks[j + 1].bare]
      and j > k and toks[j - 1].bare == "no" and not toks[j - 1].raw:match("%p$")
    -- ("heading 330 -- no, the right, I mean a right turn onto heading 030", "Mach 0.80, sorry, to Mach 0.78": an
    -- article or "to" before the side or value said in its place; the word stays with it)
    -- ("Mach .72? Ah, no, sorry, please use knots, 290 knots": the unit chosen, said before the value in place, the
    -- value said with that unit; the words of the choice belong to the run)
    local u = nxt and nxt.bare == "please" and j + 1 or j
    local unit = marked and toks[u] and toks[u].bare == "use" and toks[u + 1] and toks[u + 1].raw:match("%p$")
      and toks[u + 1].bare
    if (unit == "knots" and toks[u + 3] and (toks[u + 3].bare == "knots" or toks[u + 3].bare == "kt"
          or toks[u + 3].bare == "kts"))
        or (unit == "mach" and toks[u + 2] and toks[u + 2].bare == "mach") then
      j = u + 2
      nxt = toks[j]
    end
    local said = nxt
    -- ("climb at 250, no, at 260": "at" before the value, as the value was said the first time)
    if nxt and (nxt.bare == "the" or nxt.bare == "a" or nxt.bare == "to" or nxt.bare == "at") and toks[j + 1]
        and not nxt.raw:match("%p$") then
      said = toks[j + 1]
    end
    -- ("I am sorry, it is 260": the phrase restating is part of the run, the value after it said in place)
    local restated = marked and nxt and G.after_restated(toks, j)
    if restated then nxt, said = toks[restated], toks[restated] end
    -- ("flight level one three zero, uh, one four zero", "heading 270, um, 280": a hesitation alone between two
    -- values of as many digits, the first after a value's word, the second ending its clause with no unit: the
    -- second said in place of the first, G.hesitant_value)
    marked = marked or (j > k and G.hesitant_value(toks, k, j))
    if j > k and marked and not refused and not (dropping and after[nxt and nxt.bare or ""] and not SIDES[nxt.bare])
        and not (dropping and not toks[j - 1].raw:match("%p$") and not G.valued_words_before(toks, k))
        and not (toks[k - 2] and toks[k - 2].bare == "not" and G.apology[toks[k].bare])
        and (value(toks[k - 1]) or (toks[k - 1] and SIDES[toks[k - 1].bare]) or position
          -- ("climb FL290 please, no, I wanted FL300": "please" or "kindly" after the value taken back)
          or (toks[k - 1] and (toks[k - 1].bare == "please" or toks[k - 1].bare == "kindly") and value(toks[k - 2])))
        and nxt
        and (said.bare:match("^%a?%a?%.?%d") or NUMBER_WORDS[said.bare] or after[said.bare] or position) then
      put(toks[k].at, ", correction, ", nxt.at)
      k = j
    else
      k = math.max(j, k + 1)
    end
  end
  return done()
end

-- "reduce speed 220 knots, cancel that, maintain 250 knots", "climb FL330 belay that maintain FL310": "cancel that"
-- (or "cancel" before a comma; "belay": lexicon.cancel_verbs) straight after a value, with more said after it, is a
-- self-correction and becomes the correction word "disregard" (it takes back), which G:parse reads (the instruction after it replaces the one before when both are of one
-- kind, and another kind is asked). With no comma after "that", only a value or a word of
-- lexicon.cancel_correction_next may follow ("cancel that heading, resume own navigation" cancels that instruction).
G.cancel_next, G.cancel_verbs = set_of(lexicon.cancel_correction_next), set_of(lexicon.cancel_verbs)
function G.cancel_corrections(text)
  if not text:find("ancel", 1, true) and not text:find("elay", 1, true) then return text end
  local toks = bare_words(text)
  local function value(t) return t and (t.raw:match("%d%p*$") or NUMBER_WORDS[t.bare] or UNIT_WORDS[t.bare]) end
  local put, done, from = tokens.splicer(text)
  for k = 2, #toks do
    local t = toks[k]
    if G.cancel_verbs[t.bare] and t.at >= from() and value(toks[k - 1]) then
      local j = toks[k + 1] and toks[k + 1].bare == "that" and k + 2 or k + 1
      local marked = toks[j - 1].raw:match("%p$") or (toks[j] and toks[j].bare == "")
      local nx = toks[j]
      while nx and nx.bare == "" do j = j + 1 nx = toks[j] end
      if nx and (marked or (j == k + 2 and (value(nx) or nx.raw:match("^%a?%a?%.?%d")
          or G.cancel_next[nx.bare]))) then
        put(t.at, "disregard, ", nx.at)
      end
    end
  end
  return done()
end

-- "sorry KLM12, I said FL260 but is FL270", "I said heading 200, but it's 210", "I said 250 knots but I meant
-- 240": the speaker names the value said before ("I said" and a run of values and their words, lexicon
-- .said_but.value_words) and, after "but" and a phrase of lexicon.said_but.restating, the value meant; read as
-- "FL260, correction, FL270" (the value said first is taken back, self_corrections' reading). Anything else stays.
function G.said_but(text)
  if not text:find("[Ss][Aa][Ii][Dd]") then return text end
  text = G.said_restated(text)
  local toks = bare_words(text)
  local SB = lexicon.said_but
  for k = 1, #toks - 4 do
    if toks[k].bare == "i" and toks[k + 1].bare == "said" and not toks[k + 1].raw:match("%p$") then
      local j = k + 2
      local valued = false
      while toks[j] and j < k + 8 and (G.said_but_value(toks[j]) or SB.value_words[toks[j].bare]) do
        valued = valued or G.said_but_value(toks[j]) ~= nil
        if toks[j].raw:match("[,;]$") then j = j + 1 break end
        j = j + 1
      end
      if valued and toks[j] and toks[j].bare == "but" and j > k + 2 then
        local v = j + 1
        for _, p in ipairs(SB.restating) do
          local n, ok = v, true
          for w in p:gmatch("%S+") do
            ok = ok and toks[n] ~= nil and toks[n].bare == w
            n = n + 1
          end
          if ok then v = n break end
        end
        local y = toks[v]
        if y and (G.said_but_value(y) or SB.value_words[y.bare]) then
          return text:sub(1, toks[k].at - 1) .. text:sub(toks[k + 2].at, toks[j - 1].e - 1):gsub("%p+$", "")
            .. ", correction, " .. text:sub(y.at)
        end
      end
    end
  end
  return text
end
-- "negative, I said one two zero, descend flight level one two zero", "no, I said 250, speed two five zero": "I
-- said" and a run of values closed by a comma name the value the instruction after it gives again; the words "I
-- said" and that run are dropped when a later run of values in the request holds the same digits (spoken or
-- typed). A run no later value repeats stays as said.
G.said_digit = { zero = "0", one = "1", two = "2", three = "3", tree = "3", four = "4", fower = "4", five = "5",
  fife = "5", six = "6", seven = "7", eight = "8", nine = "9", niner = "9" }
function G.said_restated(text)
  local toks = bare_words(text)
  local function digits(t)
    if t.raw:match("%d") then return (t.raw:gsub("%D", "")) end
    return G.said_digit[t.bare] or ""
  end
  for k = 1, #toks - 3 do
    if toks[k].bare == "i" and toks[k + 1].bare == "said" and not toks[k + 1].raw:match("%p$") then
      local j, key = k + 2, ""
      while toks[j] and j < k + 8 and G.said_but_value(toks[j]) do
        key = key .. digits(toks[j])
        j = j + 1
        if toks[j - 1].raw:match("[,;]$") then break end
      end
      if key ~= "" and j > k + 2 and toks[j] and toks[j - 1].raw:match(",$") then
        local m = j
        while toks[m] do
          local run = ""
          while toks[m] and G.said_but_value(toks[m]) do
            run = run .. digits(toks[m])
            m = m + 1
            if toks[m - 1].raw:match("%p$") then break end
          end
          if run == key then return text:sub(1, toks[k].at - 1) .. text:sub(toks[j].at) end
          if run == "" then m = m + 1 end
        end
      end
    end
  end
  return text
end
-- The value token t holds (digits, a number word, a unit), or nil.
function G.said_but_value(t)
  return t.raw:match("%d%p*$") or NUMBER_WORDS[t.bare] or UNIT_WORDS[t.bare]
end

-- "descend and maintain 6000, you said seven", "negative, it's one zero thousand, readback was one one
-- thousand": a clause opening after a comma with a phrase of lexicon.readback_heard and holding only values
-- up to the end of its sentence names the value the pilot read back wrongly; it is dropped when a value was
-- said before it (the corrected instruction stands). With no value before it, or other words after the
-- values, it stays and is asked about.
local READBACK_HEARD = {}
for _, p in ipairs(lexicon.readback_heard) do
  local first = p:match("^(%S+)")
  READBACK_HEARD[first] = READBACK_HEARD[first] or {}
  table.insert(READBACK_HEARD[first], p)
end
local READBACK_HEARD_PATTERNS = {}
for first in pairs(READBACK_HEARD) do
  READBACK_HEARD_PATTERNS[#READBACK_HEARD_PATTERNS + 1] = { word = first, pattern = "%f[%w]" .. first .. "%f[%W]" }
end
local function readback_heard(text)
  if not holds_word(text:lower(), READBACK_HEARD_PATTERNS) then return text end
  local toks = bare_words(text)
  local function value(t) return t and (t.raw:match("%d%p*$") or NUMBER_WORDS[t.bare] or UNIT_WORDS[t.bare]) end
  local seen_value = false
  for k, t in ipairs(toks) do
    if k > 1 and toks[k - 1].raw:match(",$") and seen_value then
      for _, p in ipairs(READBACK_HEARD[t.bare] or {}) do
        local j, ok = k, true
        for w in p:gmatch("%S+") do
          ok = ok and toks[j] ~= nil and toks[j].bare == w and (j == k or not toks[j - 1].raw:match("%p$"))
          j = j + 1
        end
        local n = j
        while ok and toks[n] and value(toks[n]) and not (n > j and toks[n - 1].raw:match("[,;]$")) do n = n + 1 end
        local last = toks[n - 1]
        if ok and n > j and (not toks[n] or last.raw:match("[%.!;]$")) then
          return text:sub(1, toks[k - 1].e - 2) .. (last.raw:match("([%.!;])$") or "")
            .. (toks[n] and " " .. text:sub(toks[n].at) or "")
        end
      end
    end
    seen_value = seen_value or value(t) ~= nil
  end
  return text
end

-- "EIN3KL read back flight level one one zero, he was cleared flight level niner zero, fix it": a readback reported
-- by a third person (lexicon.readback_reported.verbs, no "you" or "your" before them) and its values ending at a
-- comma, then what was cleared (a word of .cleared or none, "cleared", "to" or not, and its values), ending the
-- request or its clause (one of .fix after it, "fix it", is what it asks), is the clearance to fly: read as
-- "EIN3KL cleared flight level niner zero" (the level read back is the pilot's words, never one to fly). Anything
-- else stays as said.
G.readback_nouns = set_of(lexicon.readback_reported.nouns)
function G.readback_reported(text)
  local RB = lexicon.readback_reported
  local low = text:lower()
  if not low:find("read", 1, true) or not low:find("cleared", 1, true) then return text end
  local toks = bare_words(text)
  local function value(t) return t and (t.raw:match("%d%p*$") or NUMBER_WORDS[t.bare] or G.readback_nouns[t.bare]) end
  -- (the position after one of `list`'s phrases said from k, no mark inside it, else nil)
  local function phrase(k, list)
    for _, p in ipairs(list) do
      local j, ok = k, true
      for w in p:gmatch("%S+") do
        ok = ok and toks[j] ~= nil and toks[j].bare == w and (j == k or not toks[j - 1].raw:match("%p$"))
        j = j + 1
      end
      if ok then return j end
    end
  end
  -- (the end of a run of values from k: the position after it, a mark ending it)
  local function values(k)
    local n = k
    while toks[n] and value(toks[n]) do
      n = n + 1
      if toks[n - 1].raw:match("%p$") then break end
    end
    return n
  end
  for k = 2, #toks - 1 do
    local v = phrase(k, RB.verbs)
    if v and toks[k - 1].bare ~= "you" and toks[k - 1].bare ~= "your" and not toks[k - 1].raw:match("[%.;:!?]$") then
      local n = values(v)
      local c = n > v and toks[n - 1].raw:match(",$") and (phrase(n, RB.cleared) or n)
      if c and toks[c] and toks[c].bare == "cleared" and not toks[c].raw:match("%p$") then
        local b = toks[c + 1] and toks[c + 1].bare == "to" and c + 2 or c + 1
        local m = values(b)
        local last = toks[m - 1]
        -- (one of .fix after them asks for the clearance: the words it said are read as it)
        local fix = m > b and last.raw:match(",$") and phrase(m, RB.fix)
        local rest = fix and (fix > #toks or toks[fix - 1].raw:match("%p$")) and fix or m
        if m > b and (m > #toks or last.raw:match(",$")) and (not fix or rest == fix) then
          return text:sub(1, toks[k].at - 1) .. "cleared " .. text:sub(toks[b].at, last.e - 1):gsub("%p+$", "")
            .. (toks[rest] and ", " .. text:sub(toks[rest].at) or (toks[#toks].raw:match("[%.!]$") or ""))
        end
      end
    end
  end
  return text
end

-- "climb to 4500 metres, wait, sorry, not climb, descend to 3900 metres": after a self-correction's apology or
-- marker (lexicon.self_correction: "sorry", "wait", "no", "correction") and its comma, "not" and one word said
-- before in the request, closed by a comma, rules that word out: dropped, the correction after it stands as said
-- ("..., sorry, descend to 3900 metres"). Words never said before stay, and are read as they are.
function G.denied_word(text)
  if not text:find("not ", 1, true) then return text end
  local low = text:lower()
  local cuts = {}
  for b, word, e in low:gmatch("()not (%a+),%s*()") do
    local before = low:sub(1, b - 1)
    if before:match("[%a]+[,.!]?%s*$") and (before:match("sorry[,.!]?%s*$") or before:match("wait[,.!]?%s*$")
        or before:match("%f[%a]no[,.!]%s*$") or before:match("correction[,.!]?%s*$"))
        and before:find("%f[%a]" .. word .. "%f[%A]") then
      cuts[#cuts + 1] = { b, e }
    end
  end
  for k = #cuts, 1, -1 do text = text:sub(1, cuts[k][1] - 1) .. text:sub(cuts[k][2]) end
  return text
end

-- "flight level two six zero, not two eight zero", "heading 300, not 310": a value said after "not"
-- straight after another value, ending its clause, is the one the speaker rules out (a readback
-- corrected); it is dropped, with its "not", and the value before it stands; so is an apology closing the
-- request after it ("fl200 not 180 sorry", lexicon.self_correction.apology). Anywhere else ("climb FL310
-- not 300 speed 250") the "not" stays, and is asked about. "and not" and "only, not" straight after the value are
-- the same ruling out ("should go to FL370 and not FL380", "FL310 only, not FL330"; "and" dropped with it).
local NEGATED_NOUNS = set_of({ "fl", "flight", "level", "heading", "speed", "mach", "point" })
G.apology = set_of(lexicon.self_correction.apology)
local function negated_values(text)
  if not text:lower():find("not", 1, true) then return text end  -- (no "not" said)
  local toks = bare_words(text)
  local function value(t) return t and (t.raw:match("%d%p*$") or NUMBER_WORDS[t.bare] or UNIT_WORDS[t.bare]) end
  local put, done, from = tokens.splicer(text)
  for k, t in ipairs(toks) do
    -- (`v`: the value ruled out against: straight before "not", or before "and" or "only," there)
    local v = k - 1
    if toks[v] and (toks[v].raw:lower() == "and" or toks[v].raw:lower() == "only,") then v = v - 1 end
    if t.bare == "not" and t.raw:lower() == "not" and value(toks[v]) and v > from() then
      local j, numbers, stop = k + 1, 0, false
      while toks[j] and (value(toks[j]) or (numbers == 0 and NEGATED_NOUNS[toks[j].bare])) do
        if value(toks[j]) then numbers = numbers + 1 end
        stop = toks[j].raw:match("%p$") ~= nil
        j = j + 1
        if stop then break end
      end
      if numbers > 0 and not stop and toks[j] and G.apology[toks[j].bare] and (not toks[j + 1]
          or toks[j].raw:match("[,%.!;]$")) then
        stop, j = true, j + 1
      end
      if numbers > 0 and (stop or not toks[j]) then
        local last = toks[j - 1]
        put(toks[k - 1].raw:lower() == "and" and toks[k - 1].at or t.at, last.raw:match("(%p+)$") or "", last.e)
      end
    end
  end
  return done()
end

-- A speaker's label before the request ("instructor: ...", "ATC here - ...", "sim op: ...", one or two
-- words of lexicon.speaker_roles or label_roles before a colon, or a dash set apart: "simulator-driven"
-- is no label) is dropped, as is a role of one or two words addressed before a comma or "please"
-- ("operator, ...", "pseudo-pilot, ...", "sim op please give ..."). The machine teammate
-- (lexicon.addressed_roles) opening the line is its addressee even without a comma before a word
-- ("AI what's ...", not "AI 101 ..."), and a greeting may come before an addressed role ("ok AI, ...");
-- after a greeting, a name of the voice assistant (lexicon.addressed_roles.greeted: "hey squawk ...") is one.
-- A label of two words (lexicon.bare_labels) opening the line with no colon is dropped when a request
-- follows ("sim op pause the simulation"); said alone it is the line; so is a role of lexicon.speaker_roles
-- alone ("instructor run"). A role's "note:" ("pseudo-pilot note:
-- ...") is such a label too, and so is a note of the exercise (lexicon.note_owners: "exercise note: ...").
local SPEAKER_ROLES = set_of(lexicon.speaker_roles)
for _, w in ipairs(lexicon.label_roles) do SPEAKER_ROLES[w] = true end
local ADDRESSED = set_of(lexicon.addressed_roles.names)
-- (ADDRESSED: a name of `names` -> true; of `greeted` -> "greeted", an addressee only after a greeting)
for _, w in ipairs(lexicon.addressed_roles.greeted) do ADDRESSED[w] = "greeted" end
local GREETINGS = set_of(lexicon.addressed_roles.greetings)
local BARE_LABELS = set_of(lexicon.bare_labels)
G.speaker_words = set_of(lexicon.speaker_roles)
local NOTE_OWNERS = set_of(lexicon.note_owners)
local function all_roles(words)
  for w in words:lower():gmatch("%a+") do
    if not SPEAKER_ROLES[w] then return false end
  end
  return true
end
local function role_dropped(text)
  -- (each form is matched only where the text holds its comma, "lease", colon or dash)
  local colon = text:find(":", 1, true)
  local role, said
  if text:find(",", 1, true) then role, said = text:match("^%s*(%a+[%s%-]?%a*)%s*,%s*(.+)$") end
  if not role and text:find("lease", 1, true) then role, said = text:match("^%s*(%a+[%s%-]?%a*)%s+([Pp]lease%s.+)$") end
  if role and all_roles(role) then return said end
  local label, before, sep, after, rest
  if colon or text:find("-", 1, true) then label, before, sep, after, rest = text:match("^%s*(%a+%s*%a*)(%s*)([:%-])(%s*)(.*)$") end
  if label and rest ~= "" and not (sep == "-" and (before == "" or after == ""))
      and all_roles((label:lower():gsub("%s+here$", ""))) then
    return rest
  end
  if colon then
    -- ("instructor to sim operator: ...": one role to another before the colon)
    local from, to, told = text:match("^%s*(%a+[%s%-]?%a*)%s+[Tt]o%s+(%a+[%s%-]?%a*)%s*:%s*(%S.*)$")
    if from and all_roles(from) and all_roles(to) then return told end
    -- ("pseudo-pilot note: ...", "instructor notes: ...": the role's note is its line, no ECHO)
    local noted, line = text:match("^%s*(%a+[%s%-]?%a*)%s+[Nn]otes?%s*:%s*(%S.*)$")
    if noted and (all_roles(noted) or NOTE_OWNERS[noted:lower()]) then return line end
  end
  local name, next_word = text:match("^%s*(%a+)%s+(%a.*)$")
  if name and ADDRESSED[name:lower()] == true then return next_word end
  -- ("instructor run", "supervisor pause the simulation": a role of lexicon.speaker_roles opening the line
  -- before a word, its colon not written by speech recognition, is the label)
  if name and G.speaker_words[name:lower()] then return next_word end
  local pair, request = text:match("^%s*(%a+%s+%a+)%s+(%S.*)$")
  if pair and BARE_LABELS[pair:lower():gsub("%s+", " ")] then return request end
  return text
end
local ASSENT = set_of(lexicon.assent)
-- "... climb fl150? engineer: yes do it": a second speaker's label and assent after the request are dropped
local function assent_dropped(text)
  if not text:find(":", 1, true) then return text end  -- (no label's colon)
  local said, label, reply = text:match("^(.-[%?%.!])%s*(%a+[%s%-]?%a*)%s*:%s*(.-)%s*[%.!]?$")
  if not said or not all_roles(label) or reply == "" then return text end
  for w in reply:lower():gmatch("[^%s,]+") do
    if not ASSENT[w] then return text end
  end
  -- (a "?" closing the request asked for leave to give it: the assent gives it)
  return (said:gsub("%?$", ""))
end
G.question_labels, G.question_openers = set_of(lexicon.question_labels), set_of(lexicon.echo_question_openers)
-- "Quick ask: what's the look-ahead set to?": a label of lexicon.question_labels opening the line before a colon,
-- comma or dash and a question's first word (lexicon.echo_question_openers) is dropped; before anything else it
-- stays (and is asked about)
function G.question_label_dropped(text)
  local label, question = text:match("^%s*(%a[%a%s]-)%s*[:,%-]%s*(%a.*)$")
  if label and G.question_labels[label:lower():gsub("%s+", " ")]
      and G.question_openers[question:lower():match("^%a+")] then
    return question
  end
  return text
end
G.ml_labels = set_of(lexicon.ml_labels)
-- "obs check: whats X doing", "warmup, ff 2 min": a training run's label (lexicon.ml_labels) and its mark are
-- dropped before the request said after them
function G.ml_label_dropped(text)
  for at in text:sub(1, 40):gmatch("()[:,%-]") do
    local label = text:sub(1, at - 1):lower():gsub("^%s+", ""):gsub("%s+$", ""):gsub("%s+", " ")
    local rest = text:sub(at + 1):match("^%s*(%S.*)$")
    if rest and G.ml_labels[label] then return rest end
  end
  return text
end
G.topic_shift = { leads = set_of(lexicon.topic_shift.leads), verbs = set_of(lexicon.topic_shift.verbs),
  particles = set_of(lexicon.topic_shift.particles) }
-- "Can we circle back to the Delta? I'd like it at 250 knots": the words that turn to an aircraft
-- (lexicon.topic_shift) are dropped before its "the ..." when a mark ends that and more is said after it
function G.topic_shift_dropped(text)
  local toks = bare_words(text)
  local k, ts = 1, G.topic_shift
  while k <= 2 and toks[k] and ts.leads[toks[k].bare] do k = k + 1 end
  local verb, particle, to, the = toks[k], toks[k + 1], toks[k + 2], toks[k + 3]
  if not (the and ts.verbs[verb.bare] and ts.particles[particle.bare] and to.bare == "to" and the.bare == "the")
      or verb.raw:match("%p$") or particle.raw:match("%p$") or to.raw:match("%p$") then
    return text
  end
  for j = k + 3, k + 6 do
    local t = toks[j]
    if not t then return text end
    if t.raw:match("[,%.%?;:!]$") then return toks[j + 1] and text:sub(the.at) or text end
  end
  return text
end
G.listener_openers, G.listener_alone = {}, set_of(lexicon.listener_address.alone)
for w, list in pairs(lexicon.listener_address.openers) do G.listener_openers[w] = set_of(list) end
-- the listener's term of address (lexicon.listener_address) a word or two, or its name alone
function G.listener_term(first, second)
  first = first:lower()
  if second then
    local names = G.listener_openers[first]
    return names ~= nil and names[second:lower()] == true
  end
  return G.listener_alone[first] == true
end
-- "Dear system, Turkish 7AB ...", "what is Azal 068 doing now hocam?": a term of address to the listener opening
-- the request (before a comma, colon, dash or the next word) or closing it (after a comma or word, before the
-- final marks) is dropped when words remain; the request's own words stand as said
function G.listener_address_dropped(text)
  local lower = text:lower()
  if not (lower:find("hoca", 1, true) or lower:find("dear", 1, true) or lower:find("friend", 1, true)
      or lower:find("hey", 1, true) or lower:find("hello", 1, true)) then
    return text
  end
  -- ("Excuse me dear system, ...", "Please, dear system, ...": a courtesy of lexicon.listener_address.led before
  -- the term of address stays, the term goes)
  local lead = ""
  for _, l in ipairs(lexicon.listener_address.led) do
    local n = #l
    if text:sub(1, n):lower() == l and text:sub(n + 1, n + 1):match("[%s,]") then
      local after_lead = text:sub(n + 1):gsub("^[%s,]+", "")
      local a1, b1 = after_lead:match("^(%a+)%s+(%a+)%s*[,:;!%-]?%s+%S")
      local one1 = after_lead:match("^(%a+)%s*[,:;!%-]?%s+%S")
      if (a1 and G.listener_term(a1, b1)) or (one1 and G.listener_term(one1)) then
        lead, text = text:sub(1, n) .. ", ", after_lead
      end
      break
    end
  end
  local a, b, rest = text:match("^%s*(%a+)%s+(%a+)%s*[,:;!%-]?%s+(%S.*)$")
  if lead ~= "" then
    local dropped = G.listener_address_dropped(text)
    if dropped ~= text then return lead .. dropped end
    return lead .. text
  end
  if a and G.listener_term(a, b) then
    text = rest
  else
    local one, after = text:match("^%s*(%a+)%s*[,:;!%-]?%s+(%S.*)$")
    if one and G.listener_term(one) then text = after end
  end
  local said, c, d, marks = text:match("^(.-%S)[%s,;%-]+(%a+)%s+(%a+)%s*([%.%?!]*)%s*$")
  if said and G.listener_term(c, d) then
    return said:gsub("[,;%-]$", "") .. marks
  end
  local said1, e, marks1 = text:match("^(.-%S)[%s,;%-]+(%a+)%s*([%.%?!]*)%s*$")
  if said1 and G.listener_term(e) then return said1:gsub("[,;%-]$", "") .. marks1 end
  return text
end
local function unlabelled(text)
  text = G.topic_shift_dropped(G.question_label_dropped(G.ml_label_dropped(assent_dropped(G.listener_address_dropped(text)))))
  local greeting, after = text:match("^%s*(%a+)%s*,?%s+(.+)$")
  if greeting and GREETINGS[greeting:lower()] then
    local name, next_word = after:match("^(%a+)%s*,?%s+(%a.*)$")
    if name and ADDRESSED[name:lower()] == "greeted" then return role_dropped(next_word) end
    local said = role_dropped(after)
    if said ~= after then return said end
  end
  return role_dropped(text)
end

-- A type designator written with a hyphen after its letter or two ("C-17", "C-130", "MD-11", "DC-10")
-- is that designator when squawk knows it.
local KNOWN_TYPES
local function hyphened_types(text)
  if not KNOWN_TYPES then
    KNOWN_TYPES = {}
    for _, d in ipairs(TYPES.designators) do KNOWN_TYPES[d:upper()] = true end
    for d in pairs(TYPES.aliases) do KNOWN_TYPES[d] = true end  -- ("E-175": the E75L)
  end
  if not text:find("-", 1, true) then return text end
  return (text:gsub("%f[%w](%a%a?)%-(%d%d%d?)%f[%W]", function(a, n)
    if KNOWN_TYPES[(a .. n):upper()] then return a .. n end
    return nil
  end))
end

local HEMISPHERES = set_of({ "north", "south", "east", "west", "n", "s", "e", "w" })
-- a digit said as a word (as ATC says it) -> the digit
local SAID_DIGIT = { zero = "0", oh = "0", one = "1", two = "2", three = "3", tree = "3", four = "4", fower = "4",
  five = "5", fife = "5", six = "6", seven = "7", eight = "8", nine = "9", niner = "9" }

-- A position typed in degrees and minutes whose minutes are 60 or more ("N55 75 W003 20", "51 75N",
-- "55 degrees 75 north", "59 deg 65 min N"): its text, else nil. Such a position is asked about, never
-- re-read as other numbers (the hemisphere dropped, the degrees taken for a heading).
local function impossible_minutes(text)
  local low = text:lower()
  -- (the first two forms hold digits, space and digits; the third "deg")
  if not low:find("%d%s+%d") and not low:find("deg", 1, true) then return nil end
  local function bad(deg, min) return deg:match("^%d+$") and tonumber(deg) <= 180 and tonumber(min) >= 60 end
  local function said(b, e) return (text:sub(b, e - 1):gsub("[%s%.]+$", "")) end
  -- the hemisphere before the degrees: "N55 75 W003 20"
  for b, lat, lat_min, lon, lon_min, e in
      low:gmatch("%f[%w]()[ns](%d%d?)%s+(%d+%.?%d*)[%s,]+[ew](%d%d?%d?)%s+(%d+%.?%d*)()%f[^%w%.]") do
    if bad(lat, lat_min) or bad(lon, lon_min) then return said(b, e) end
  end
  -- the hemisphere after the minutes: "51 75N", "51 75 north"
  for b, deg, min, hemi, e in low:gmatch("%f[%w%.]()(%d+)%s+(%d+%.?%d*)%s*(%a+)()%f[%A]") do
    if HEMISPHERES[hemi] and bad(deg, min) then return said(b, e) end
  end
  -- degrees said with their word, then minutes, before the hemisphere: "55 degrees 75 north", "59 deg 65 min N"
  for b, deg, min, w1, w2, e in low:gmatch("%f[%w%.]()(%d+)%s*deg%a*%.?%s+(%d+%.?%d*)%s*(%a*)%.?%s*(%a*)()") do
    if (HEMISPHERES[w1] or (w1:match("^min") and HEMISPHERES[w2])) and bad(deg, min) then return said(b, e) end
  end
  return nil
end
-- "flight level to for zero", "heading won eight zero": inside three words said as a level's or heading's
-- digits straight after "level", "fl", "heading" or "hdg", a word speech recognition writes for a digit
-- (lexicon.digit_homophones) is that digit; a "to" first stays (the level handler reads it as "two" or no
-- digit), as do words followed by another digit or a distance or time unit ("heading for one zero miles")
local VALUE_ANCHORS = set_of({ "level", "fl", "heading", "hdg" })
local RUN_ENDS = set_of({ "miles", "mile", "nm", "minutes", "minute", "min", "seconds", "km" })
-- The text with the words mark(k, toks, bare, H, convert) sets in convert (convert[k] = true) read as the digit
-- lexicon.digit_homophones (H) gives them, a mark after the word kept
function G.rewrite_homophones(text, mark)
  local toks, bare = plain_words(text)
  local H, convert = lexicon.digit_homophones, {}
  for k = 1, #bare do mark(k, toks, bare, H, convert) end
  if not next(convert) then return text end
  return tokens.rewrite(text, toks, function(i)
    if convert[i] then return H[bare[i]] .. (toks[i]:match("%p+$") or ""), i + 1 end
  end)
end
local function value_homophones(text)
  return G.rewrite_homophones(text, function(k, toks, bare, H, convert)
    local w = bare[k]
    if VALUE_ANCHORS[w] and not toks[k]:match("%p$") then
      local j, said, heard = k + 1, 0, {}
      while j <= k + 3 and bare[j] and (DIGIT_WORDS[bare[j]] or H[bare[j]]) do
        if DIGIT_WORDS[bare[j]] then said = said + 1 elseif not (j == k + 1 and H[bare[j]] == "two") then heard[#heard + 1] = j end
        if toks[j]:match("%p$") then j = j + 1; break end
        j = j + 1
      end
      local after = bare[j]
      if j == k + 4 and said >= 1 and #heard > 0 and not (after and (DIGIT_WORDS[after] or H[after] or RUN_ENDS[after]
          or after:match("^%d"))) then
        for _, h in ipairs(heard) do convert[h] = true end
      end
      -- ("flight level won hundred": one such word, not "to", then "hundred" and no digit after: FL100)
      local last = bare[k + 3]
      if H[bare[k + 1] or ""] and bare[k + 1] ~= "to" and bare[k + 2] == "hundred" and not toks[k + 1]:match("%p$")
          and not (last and (DIGIT_WORDS[last] or H[last] or RUN_ENDS[last] or last:match("^%d"))) then
        convert[k + 1] = true
      end
    end
  end)
end
-- "direct Bombay VOR", "after the Madras VOR": a city's other name (lexicon.navaid_city_names) straight before a
-- navaid's kind (lexicon.navaid_kind_words) is the name the navdata gives the navaid ("Mumbai VOR").
G.navaid_kinds = set_of(lexicon.navaid_kind_words)
function G.navaid_city_names(text)
  local low = text:lower()
  local any = false
  for old in pairs(lexicon.navaid_city_names) do any = any or low:find(old, 1, true) ~= nil end
  if not any then return text end
  local toks, bare = plain_words(text)
  return tokens.rewrite(text, toks, function(i)
    local new = lexicon.navaid_city_names[bare[i]]
    if not new or toks[i]:match("%p$") or not G.navaid_kinds[bare[i + 1] or ""] then return nil end
    return (toks[i]:match("^%u") and (new:sub(1, 1):upper() .. new:sub(2)) or new), i + 1
  end)
end
-- "old the simulation for a moment", "please old the sim": "old" a recogniser wrote for "hold" with its h dropped,
-- in a sim-control position (opening the request or after "please", "ok", "okay", "now", "and" or a mark) before
-- "simulation", "sim" or "scenario" ("the" between or not), is "hold"; "old" anywhere else stays as said.
G.sim_objects = set_of({ "simulation", "sim", "scenario" })
G.sim_old_leads = set_of({ "please", "ok", "okay", "now", "and" })
function G.sim_old(text)
  if not text:lower():find("old", 1, true) then return text end
  local toks, bare = plain_words(text)
  return tokens.rewrite(text, toks, function(i)
    if bare[i] ~= "old" or toks[i]:match("%p$") then return nil end
    if not (i == 1 or toks[i - 1]:match("%p$") or (G.sim_old_leads[bare[i - 1]] and (i == 2 or toks[i - 2]:match("%p$")))) then
      return nil
    end
    local k = bare[i + 1] == "the" and i + 2 or i + 1
    if not G.sim_objects[bare[k] or ""] then return nil end
    return (toks[i]:match("^O") and "Hold" or "hold"), i + 1
  end)
end
-- "170 knots till for miles final", "until fife DME": the count of a distance limit as a recogniser writes it, one
-- word straight after "until", "till" or "to" and straight before its unit (G.limit_units), is that digit: "for" and
-- "fore" 4, the radiotelephony "tree" 3, "fower" 4, "fife" 5 (no "to": "to four DME" is said as it is)
G.limit_digits = { ["for"] = "four", fore = "four", tree = "three", fower = "four", fife = "five" }
G.limit_leads = set_of({ "until", "till", "til", "to" })
G.limit_units = set_of({ "miles", "mile", "nm", "dme", "final" })
function G.limit_homophones(text)
  local low = text:lower()
  if not (low:find("til", 1, true) or low:find("to ", 1, true)) then return text end
  local toks, bare = plain_words(text)
  return tokens.rewrite(text, toks, function(i)
    local d = G.limit_digits[bare[i]]
    if not d or not G.limit_leads[bare[i - 1] or ""] or toks[i - 1]:match("%p$") or toks[i]:match("%p$")
        or not G.limit_units[bare[i + 1] or ""] or (bare[i] == "for" or bare[i] == "fore") and bare[i - 1] == "to" then
      return nil
    end
    return d, i + 1
  end)
end
-- Words speech recognition writes for a digit (lexicon.digit_homophones) where the other reading leaves the
-- value incomplete or impossible, read as that digit:
--  * before "thousand" with no digit before it: "for" or "fore" ("descend to for thousand feet": 4000 ft;
--    "descend for thousand five hundred": 4500 ft), and "to" or "too" after a "to" ("descend to to thousand":
--    2000 ft). A lone "to" stays ("descend to thousand feet" has lost its digit: asked);
--  * a speed of three words straight after "speed", "reduce" or "increase": "to", then "to", "too", "for" or
--    "fore", then a digit word, before "knots" or the clause's end ("reduce speed to to zero knots": 220 kt;
--    "to for zero": 240 kt), where one "to" is the preposition and the other word a digit. A single "to" before
--    two digit words stays ("reduce speed to five zero": 50 kt asked, or 250; "to nine zero" is a light
--    aircraft's 90 kt), as does "to" and a whole three-digit speed ("to two one zero").
G.speed_homophone_anchors = set_of({ "speed", "reduce", "increase" })
G.speed_homophone_ends = set_of({ "knots", "knot", "kts", "kt", "and", "then" })
function G.thousand_speed_homophones(text)
  local low = text:lower()
  if not (low:find("thousand", 1, true) or low:find("to ", 1, true)) then return text end
  return G.rewrite_homophones(text, function(k, toks, bare, H, convert)
    local w = bare[k]
    if w == "thousand" and k > 1 and H[bare[k - 1]] and not toks[k - 1]:match("%p$") then
      local h, before = bare[k - 1], bare[k - 2]
      local loose = not before or not (DIGIT_WORDS[before] or NUMBER_WORDS[before] or before:match("^%d"))
      if (h == "for" or h == "fore") and loose then
        convert[k - 1] = true
      elseif (h == "to" or h == "too") and (before == "to" or before == "too") and not toks[k - 2]:match("%p$") then
        convert[k - 1] = true
      end
    elseif G.speed_homophone_anchors[w] and bare[k + 1] == "to" and not toks[k]:match("%p$") then
      local digits, heard, j = 0, {}, k + 1
      while j <= k + 3 and bare[j] and (DIGIT_WORDS[bare[j]] or H[bare[j]]) do
        if DIGIT_WORDS[bare[j]] then digits = digits + 1
        elseif bare[j] == "to" or bare[j] == "too" or bare[j] == "for" or bare[j] == "fore" then heard[#heard + 1] = j
        else break end
        if toks[j]:match("%p$") and j < k + 3 then j = k + 9; break end
        j = j + 1
      end
      local after = bare[j]
      if j == k + 4 and digits >= 1 and #heard >= 2 and DIGIT_WORDS[bare[k + 3]] and not toks[k + 1]:match("%p$")
          and (toks[k + 3]:match("%p$") or not after or G.speed_homophone_ends[after]) then
        for _, h in ipairs(heard) do convert[h] = true end
      end
    end
  end)
end
-- The axis ("lat" or "lon", lexicon.coordinate_axes.hemispheres) a word of bare_words names as a hemisphere (its
-- initial only in capitals: "N", "W"), else nil.
G.hemisphere_initials = {}
for word, axis in pairs(lexicon.coordinate_axes.hemispheres) do G.hemisphere_initials[word:sub(1, 1):upper()] = axis end
function G.hemisphere_axis(t)
  return t and (lexicon.coordinate_axes.hemispheres[t.bare] or G.hemisphere_initials[t.raw:match("^(%u)%p*$") or ""])
end
-- Coordinates said in words, written as the extractors read them:
--  * "32 point eight north", "north 52 decimal three five", "96 point niner west": decimal places said as digit
--    words after "point" or "decimal" (a number in digits before it, a hemisphere's word or letter straight after
--    the digits or straight before the number) are written as digits ("32 point 8 north"), which written_forms
--    joins to the number; a decimal said anywhere else stays as said;
--  * "latitude 41.4 north, longitude 9.6 west", "longitude 10.1 W", "latitude 32 point 8 south": a coordinate said
--    between its label (lexicon.coordinate_axes.labels) and a hemisphere of the label's axis is written without
--    the label ("41.4 north": after its label the extractors read the number alone, unsigned); a hemisphere of the
--    other axis ("latitude 41.4 west") leaves the text as said.
function G.spoken_coordinates(text)
  local low = text:lower()
  local points = low:find("point", 1, true) or low:find("decimal", 1, true)
  if not (points or low:find("lat", 1, true) or low:find("lon", 1, true)) then return text end
  local toks = bare_words(text)
  -- (the decimal places said from j, numerals or digit words, a mark ending them: their digits and the position
  -- after them)
  local function places(j)
    if toks[j] and toks[j].raw:match("^%d+$") then return toks[j].raw, j + 1 end
    local digits = {}
    while toks[j] and SAID_DIGIT[toks[j].bare] and toks[j].raw:match("^%a+%p?$") do
      digits[#digits + 1] = SAID_DIGIT[toks[j].bare]
      j = j + 1
      if toks[j - 1].raw:match("%p$") then break end
    end
    return table.concat(digits), j
  end
  local function point(k) return toks[k] and G.hemisphere_words.point[toks[k].raw:lower()] end
  local put, done = tokens.splicer(text)
  for k = 1, #toks - 1 do
    local axis = lexicon.coordinate_axes.labels[toks[k].bare]
    local n = axis and toks[k].raw:match("%a$") and toks[k + 1].raw:match("^%d+%.?%d*$") and k + 2
    if n and point(n) and not toks[n - 1].raw:find(".", 1, true) then
      local digits, after = places(n + 1)
      if digits ~= "" then n = after end
    end
    if n and not toks[n - 1].raw:match("%p$") and G.hemisphere_axis(toks[n]) == axis then
      put(toks[k].at, "", toks[k + 1].at)
    end
    if points and k > 1 and point(k) and toks[k - 1].raw:match("^%d+$") and not toks[k + 1].raw:match("^%d") then
      local digits, j = places(k + 1)
      local last = toks[j - 1]
      local after = not last.raw:match("%p$") and G.hemisphere_axis(toks[j])
      local before = G.hemisphere_axis(toks[k - 2]) and not toks[k - 2].raw:match("%p$")
      if digits ~= "" and (after or before) then
        put(toks[k + 1].at, digits .. (last.raw:match("%p+$") or ""), last.e)
      end
    end
  end
  return done()
end
-- digits, "point" or "decimal" in any case, digits, a word: written_forms reads a hemisphere's decimal point
local POINT_SAID = {}  -- {word =, pattern =}
for _, word in ipairs({ "point", "decimal" }) do
  local said = word:gsub("%a", function(c) return "[" .. c:lower() .. c:upper() .. "]" end)
  POINT_SAID[#POINT_SAID + 1] = { word = word, pattern = "%f[%d](%d+)%s+" .. said .. "%s+(%d+)(%s+)(%a+)%f[%A]" }
end
-- "south 1.25, east 36.75", "north 52 decimal 3 east 4 point 5": a latitude and then a longitude, each said after
-- its hemisphere's word (north or south, then east or west) with a number of its own (a decimal point typed or
-- said), are written with each hemisphere after its number ("1.25 south, 36.75 east"), as the extractors read
-- them; anything else stays as typed.
G.hemisphere_words = { lat = set_of({ "north", "south" }), lon = set_of({ "east", "west" }),
  point = set_of({ "point", "decimal" }) }
function G.hemispheres_first(text)
  local H = G.hemisphere_words
  -- (the number typed at `at`, its point typed or said, and the position after it; nil when none)
  local function number(at)
    local whole, e = text:match("^(%d+%.?%d*)()", at)
    if not whole then return nil end
    local word, frac, after = text:match("^%s+(%a+)%s+(%d+)()", e)
    if word and H.point[word:lower()] and not whole:find(".", 1, true) then return whole .. "." .. frac, after end
    return whole, e
  end
  local put, done, from = tokens.splicer(text)
  for at, ns, v in text:gmatch("()%f[%a](%a+)%s+()%d") do
    if at >= from() and H.lat[ns:lower()] then
      local lat, e = number(v)
      local sep, ew, w = text:match("^(%s*,?%s*)(%a+)%s+()%d", e)
      local lon, after = nil, nil
      if ew and H.lon[ew:lower()] then lon, after = number(w) end
      if lon then
        put(at, lat .. " " .. ns .. sep .. lon .. " " .. ew, after)
      end
    end
  end
  return done()
end
-- A clock multiplier typed alone as a clause ("seed 99 then 30 random a320 then x4", "hold, 4x", "x4 and op"), or
-- before the word "speed" or "rate" ending its clause ("x4 speed"): the simulation's rate, written out as "sim speed
-- x4" (a callsign-like "x4" or a bare "4x" names no aircraft, unless an aircraft of that id flies: `world`, when
-- given, holds the traffic). After "fast time" ("set fast time x3", "fast-time at x8"), or "time" opening its clause
-- ("time x5", "sim time at x2"), it is that rate, written "5x".
local function lone_multipliers(text, world)
  if not text:find("%d[xX]") and not text:find("[xX]%d") then return text end
  local words = {}
  for b, w, e in text:gmatch("()(%S+)()") do words[#words + 1] = { b = b, w = w, e = e } end
  local out, last = {}, 1
  local function joins(t) return t ~= nil and (t.w:lower() == "then" or t.w:lower() == "and") end
  local function flies(id)
    for _, a in ipairs(world and world.aircraft or {}) do
      if (a.id or ""):upper() == id:upper() then return true end
    end
    return false
  end
  -- (the words before word k name fast time: "fast time", "fast-time", "at" after them or not; or the clock,
  -- "time" opening its clause, "sim time" or "simulation time": "time x5", "sim time at x2")
  local function fast_time(k)
    local p = words[k - 1] and words[k - 1].w:lower() == "at" and k - 2 or k - 1
    local w = words[p] and words[p].w:lower()
    local q = words[p - 1]
    local opens = not q or q.w:match("[,;%.!:]$") or joins(q) or q.w:lower() == "sim" or q.w:lower() == "simulation"
    return w == "fast-time" or (w == "time" and q ~= nil and q.w:lower() == "fast") or (w == "time" and opens)
  end
  for k, t in ipairs(words) do
    local core, tail = t.w:match("^(.-)([,;%.!]?)$")
    local n = core:match("^[xX](%d+%.?%d*)$") or core:match("^(%d+%.?%d*)[xX]$")
    local prev, nx = words[k - 1], words[k + 1]
    if n and fast_time(k) and not flies(core) then
      out[#out + 1] = text:sub(last, t.b - 1) .. n .. "x" .. tail
      last = t.e
      n = nil
    end
    local noun = tail == "" and nx and nx.w:lower():match("^(%a+)[,;%.!]?$")
    noun = (noun == "speed" or noun == "rate") and (nx.w:match("[,;%.!]$") or not words[k + 2] or joins(words[k + 2]))
    if n and (not prev or prev.w:match("[,;%.!:]$") or joins(prev)) and (tail ~= "" or not nx or joins(nx) or noun)
        and not flies(core) then
      -- (with words after it the factor goes after its figures: "x4 and", "x4, op" read as an aircraft's id)
      local factor = nx and n .. "x" or "x" .. n
      out[#out + 1] = text:sub(last, t.b - 1) .. "sim speed " .. factor .. (noun and nx.w:match("[,;%.!]?$") or tail)
      last = noun and nx.e or t.e
    end
  end
  out[#out + 1] = text:sub(last)
  return table.concat(out)
end

-- lexicon.typed_abbreviations read as the words they stand for, where the words beside them allow
local ABBREVIATIONS = {}
for abbr, readings in pairs(lexicon.typed_abbreviations) do
  ABBREVIATIONS[abbr] = {}
  for _, a in ipairs(readings.word and { readings } or readings) do
    table.insert(ABBREVIATIONS[abbr], { word = a.word, next = a.next and word_set(a.next, 1),
      prev = a.prev and word_set(a.prev, 1), not_prev = a.not_prev and word_set(a.not_prev, 1),
      not_next = a.not_next and word_set(a.not_next, 1), full_run = a.full_run,
      after_next = a.after_next and word_set(a.after_next, 1), hundreds = a.hundreds, caps_kept = a.caps_kept,
      asked_before = a.asked_before and word_set(a.asked_before, 1) })
  end
end
-- A false start cut off inside a word and said again after a hesitation ("descend flight le- eh descend flight level
-- 130", "turn ri uh turn right heading 120"): one to three words, a fragment of one to four letters, hesitations
-- (lexicon.hesitations), then the same words again and a longer word the fragment opens; the first attempt is
-- dropped.
function G.cut_off_restarts(text)
  local low, hesitant = text:lower(), false
  for _, h in ipairs(G.hesitation_patterns) do
    if low:find(h.word, 1, true) and low:find(h.pattern) then hesitant = true break end
  end
  if not hesitant then return text end
  local toks = {}
  for w in text:gmatch("%S+") do toks[#toks + 1] = w end
  local function bare(k) return toks[k] and toks[k]:lower():match("^(.-)%p*$") end
  for f = 2, #toks - 2 do
    local frag = bare(f)
    if #frag >= 1 and #frag <= 4 and frag:match("^%a+$") and not toks[f - 1]:match("[,;:.!?]$") then
      local j = f + 1
      while G.hesitation_words[bare(j) or ""] do j = j + 1 end
      if j == f + 1 then j = #toks + 1 end  -- (no hesitation after the fragment: no restart)
      for n = 1, math.min(3, f - 1) do
        local same = true
        for x = 0, n - 1 do
          if bare(f - n + x) ~= bare(j + x) or bare(j + x) == "" then same = false break end
        end
        local word = bare(j + n)
        if same and word and #word > #frag and word:sub(1, #frag) == frag then
          return G.cut_off_restarts(G.words_without(toks, f - n, j - 1))
        end
      end
    end
  end
  return text
end
-- "Speed... Speedbird 8CK, turn left", "Lufth-- uh, Lufthansa 4AX": a word cut off where the request or a sentence
-- opens, closed by "..." or "-" or followed by hesitations (lexicon.hesitations), and then a longer word it opens:
-- the cut-off word is dropped with the hesitations after it.
function G.cut_off_openings(text)
  if not (text:find("...", 1, true) or text:find("-", 1, true) or text:find("…", 1, true)) then return text end
  local toks = {}
  for w in text:gmatch("%S+") do toks[#toks + 1] = w end
  local function bare(k) return toks[k] and toks[k]:lower():match("^(.-)%p*$") end
  for f = 1, #toks - 1 do
    local frag = bare(f)
    local cut = toks[f]:match("%.%.%.$") or toks[f]:match("%-$") or toks[f]:match("…$")
    if #frag >= 2 and frag:match("^%a+$") and (f == 1 or toks[f - 1]:match("[,;:.!?]$")) then
      local j = f + 1
      while G.hesitation_words[bare(j) or ""] or toks[j] and toks[j]:match("^%p+$") do j = j + 1 end
      local word = bare(j)
      if (cut or j > f + 1) and word and #word > #frag and word:sub(1, #frag) == frag then
        return G.words_without(toks, f, j - 1)
      end
    end
  end
  return text
end
M.cut_off_openings = G.cut_off_openings  -- (graph.lua reads it before a request is split into clauses)
-- The words of toks joined by single spaces, less those at positions a to b
function G.words_without(toks, a, b)
  local out = {}
  for k = 1, a - 1 do out[#out + 1] = toks[k] end
  for k = b + 1, #toks do out[#out + 1] = toks[k] end
  return table.concat(out, " ")
end
-- An instruction broken off inside its spoken value and said again whole with no hesitation between ("climb
-- flight level two climb flight level two six zero", "speed two, speed two five zero"): two to six words, the
-- first no digit word (DIGIT_WORDS) and the last one, then the same words again and at least one more digit
-- word; the broken-off copy is dropped. Returns text unchanged when none is said.
function G.unfinished_restarts(text)
  local toks, bare = {}, {}
  for w in text:gmatch("%S+") do
    toks[#toks + 1] = w
    bare[#toks] = w:lower():match("^(.-)%p*$")
  end
  for j = 3, #toks - 2 do
    -- (j opens the second copy: the word before it ends a run of digit words, and it is no digit word)
    if DIGIT_WORDS[bare[j - 1]] and not DIGIT_WORDS[bare[j]] and not toks[j - 1]:match("[.!?;]$") then
      for n = 2, math.min(6, j - 1) do
        local same = not DIGIT_WORDS[bare[j - n]] and DIGIT_WORDS[bare[j + n]] ~= nil
        for x = 0, n - 1 do
          if not same then break end
          same = bare[j - n + x] == bare[j + x] and bare[j + x] ~= ""
            and (x == n - 1 or not toks[j - n + x]:match("%p$"))
        end
        if same then return G.unfinished_restarts(G.words_without(toks, j - n, j - 1)) end
      end
    end
  end
  return text
end
-- True when `set` (a word set, or nil: always) holds a word of toks before the k-th (bare(j): its letters in lower
-- case): the question an abbreviation's reading follows ("what's your speed, revert")
function G.asked_before(set, toks, k, bare)
  if not set then return true end
  for j = 1, k - 1 do
    if set[bare(j)] then return true end
  end
  return false
end
-- True when reading a's not_next holds before the k-th word: always, or with `full_run` (a count of words) only when
-- that many words before it all fit its prev ("three three zero height 5100": a heading's three digits said whole)
function G.full_run(a, fits, k)
  for j = 1, a.full_run or 0 do
    if not fits(a.prev, k - j) then return false end
  end
  return true
end
local function typed_abbreviations(text)
  -- (a word typed of letters alone is one of its runs of letters: with none an abbreviation, none is read)
  local typed = false
  for letters in text:lower():gmatch("%a[%a%d]*") do
    if ABBREVIATIONS[letters] or ABBREVIATIONS[letters:match("^%a+")] then
      typed = true
      break
    end
  end
  if not typed then return text end
  local toks = {}
  for w in text:gmatch("%S+") do toks[#toks + 1] = w end
  local function bare(k) return toks[k] and toks[k]:lower():match("^(.-)%p*$") end
  local function fits(set, k)
    local w = bare(k)
    if set["#start"] and (k == 0 or (toks[k] and toks[k]:match("[,;:.!]$"))) then return true end
    if set["#end"] and (toks[k] == nil or toks[k - 1]:match("[,;:.!]$")) then return true end
    return w ~= nil and (set[w] or (set["#number"] and (w:match("^%d") or w:match("^fl%d")) ~= nil)
      or (set["#place"] and toks[k]:match("^%u%u%u%u?%u?%p*$") ~= nil)
      or (set["#name"] and w:match("^%a%a%a?%a?%a?$") ~= nil))
  end
  -- (a level change's verb typed short, `hundreds`: two typed digits of 30 to 99 after it are hundreds of feet)
  local function in_hundreds(k)
    local digits, punct = (toks[k] or ""):match("^([3-9]%d)(%p*)$")
    if digits then toks[k] = tostring(tonumber(digits) * 100) .. " ft" .. punct end
  end
  local changed = false
  for k, w in ipairs(toks) do
    -- (an apostrophe typed for a dropped letter opens the word: "'eading")
    -- (and a slash a network's chat command opens with: "/ctc 124.88")
    local letters, punct = w:match("^['/]?(%a[%a%d]*)(%p*)$")
    local readings = letters and ABBREVIATIONS[letters:lower()]
    for j = 1, readings and #readings or 0 do
      local a = readings[j]
      if not (a.caps_kept and letters:match("^%u%u+$")) and (not a.next or fits(a.next, k + 1))
          and (not a.prev or fits(a.prev, k - 1))
          and (not a.after_next or fits(a.after_next, k + 2)) and not (a.not_prev and fits(a.not_prev, k - 1))
          and not (a.not_next and fits(a.not_next, k + 1) and G.full_run(a, fits, k))
          and G.asked_before(a.asked_before, toks, k, bare) then
        toks[k], changed = a.word .. punct, true
        if a.hundreds and punct == "" then in_hundreds(k + 1) end
        break
      end
    end
  end
  return changed and table.concat(toks, " ") or text
end

-- The names after which a signed value with no unit is a change of that value ("speed +20", "alt -2000",
-- "hdg +20", "climb +3000"): name (lower case) -> "speed" | "alt" | "hdg", or "alt+" | "alt-" for a verb that
-- says the direction (the other sign contradicts it: "climb -3000" is left as typed, and asked)
local SIGNED_CHANGE = { speed = "speed", spd = "speed", alt = "alt", altitude = "alt", climb = "alt+",
                        descend = "alt-", heading = "hdg", hdg = "hdg" }

-- Units of a change said with "more"/"less" after its amount or "gain"/"lose" before it ("20 kt less", "lose
-- 4000 ft"): unit (lower case) -> "speed" | "alt"; the words -> +1 (faster, up) | -1 (slower, down)
local UNIT_CHANGE = { kt = "speed", kts = "speed", knots = "speed", ft = "alt", feet = "alt" }
local MORE_LESS = { more = 1, less = -1 }
-- a word of direction said after "more" and an amount ("3000 feet more high", "20 knots more slow"):
-- word -> { quantity of UNIT_CHANGE, +1 up/faster | -1 down/slower }
G.MORE_DIRECTION = { high = { "alt", 1 }, higher = { "alt", 1 }, up = { "alt", 1 }, low = { "alt", -1 },
                     lower = { "alt", -1 }, down = { "alt", -1 }, fast = { "speed", 1 }, faster = { "speed", 1 },
                     quick = { "speed", 1 }, slow = { "speed", -1 }, slower = { "speed", -1 } }
G.descent_words = set_of(lexicon.vertical_motion.down)
local GAIN_LOSE = { gain = 1, lose = -1 }

-- lexicon.value_names as a set (written_forms: a name glued to its value)
G.value_name_set = set_of(lexicon.value_names)

-- A number written with a decimal comma, as German and French write one ("47,5 north", "8,5 degrees east", "the
-- horizontal resolution factor to 1,1"): `whole` (one to three digits) and `part` (one or two) around the comma,
-- [b, e) in `text`, nothing glued before or after, before a hemisphere (a word of
-- lexicon.coordinate_axes.hemispheres or its initial) with "degrees" or not, in its range, before a unit of
-- lexicon.decimal_comma_units, glued or not ("4,5 NM", "2,5nm"), or after a word of
-- lexicon.decimal_comma_after and "to", "of" or "at" or none; returns "whole.part", or nil (kept as written:
-- "41,000", "FL300,250").
G.decimal_comma_after = set_of(lexicon.decimal_comma_after)
G.decimal_comma_units = set_of(lexicon.decimal_comma_units)
function G.decimal_comma(text, b, whole, part, e)
  local glued = text:sub(e):match("^%a+")  -- (only a hemisphere's initial or a unit: "50,3N", "2,5nm")
  if #whole > 3 or #part > 2 or text:sub(b - 1, b - 1):match("[%w%.,]") or text:sub(e, e):match("[%d%.,]")
      or glued and not glued:match("^[NSEWnsew]$") and not G.decimal_comma_units[glued:lower()] then
    return nil
  end
  local after = text:sub(e):lower():gsub("^%s*", ""):gsub("^°%s*", ""):gsub("^degrees?%s+", "")
  local word = after:match("^(%a+)")
  local axis = word and (lexicon.coordinate_axes.hemispheres[word] or (word == "n" or word == "s") and "lat"
    or (word == "e" or word == "w") and "lon")
  local hemisphere = axis and tonumber(whole) <= (axis == "lat" and 90 or 180)
  if hemisphere or G.decimal_comma_units[word] then return whole .. "." .. part end
  local before = text:sub(1, b - 1):lower()
  local noun = before:match("(%a+)%s+%a+%s*$")
  local joined = before:match("(%a+)%s*$")
  if G.decimal_comma_after[joined]
      or (G.decimal_comma_after[noun] and (joined == "to" or joined == "of" or joined == "at")) then
    return whole .. "." .. part
  end
  return nil
end

-- Dutch chat's "ff" (spoken "even": just, for a moment, a softener) inside a request: "klm1234 ff naar fl150",
-- "kun je ff X naar fl260 zetten", "hold the sim ff". Typed lower case after a word of its own clause (no
-- punctuation closing that word, and it none of G.ff_lead: the words that open a fast-forward of its own,
-- "then ff", "and ff", "now ff", "can you ff"), and with no duration, "until" or "forward" after it, it is the
-- softener and is dropped; TrafScript's FF (fast time) is never read from it. "ff" alone, first in its clause
-- or with a duration stays the fast-forward.
G.ff_lead = { ["then"] = true, ["and"] = true, en = true, dan = true, now = true, nu = true, ok = true, okay = true,
  oke = true, so = true, just = true, please = true, pls = true, plz = true, also = true, lets = true,
  ["let's"] = true, can = true, could = true, would = true, will = true, you = true, we = true, i = true,
  to = true, ["+"] = true, ["&"] = true, ["->"] = true, ["do"] = true, ["go"] = true, run = true }
G.ff_duration_after = { ["until"] = true, till = true, tot = true, forward = true, ["for"] = true, a = true,
  an = true, minuten = true, minuut = true, seconden = true, uur = true }
G.dutch_value_ends = { nm = true, ft = true, kt = true, kts = true, knots = true, feet = true, on = true, off = true,
  aan = true, uit = true, min = true, s = true, sec = true, fpm = true }
G.dutch_can = { ["kun je"] = true, ["kun jij"] = true, ["kunt u"] = true, ["kan je"] = true, ["kan jij"] = true }
-- ("kun je", "kunt u", "kan je" opening the request: can you; read here, after "ff" was, and not in
-- lexicon.said_whole, so that "kun" is no word a typing slip could be read as)
function G.dutch_chat(text)
  return (G.dutch_chat_words(text):gsub("^(%s*)(%a+)%s+(%a+)(%s)", function(lead, can, you, sp)
    if G.dutch_can[can:lower() .. " " .. you:lower()] then return lead .. "can you" .. sp end
  end))
end
-- True when "ff" at toks[i] follows a setting typed as TrafScript, a registry command's name and one value of a
-- switch's state, a method or a number ("asas on reso mvp ff", "zoner 5 ff", "CDMETHOD ON FF"): the next command,
-- FF (fast time), never Dutch chat's softener.
function G.after_typed_setting(toks, i)
  local value, name = (toks[i - 1] or ""):upper(), (toks[i - 2] or ""):upper()
  if not G.setting_usages then
    G.setting_usages = {}
    for _, c in ipairs(squawk.sim.commands()) do
      -- (only a command whose first argument is no aircraft: a setting of the simulation)
      if not (c.args or ""):match("^%[?acid") then
        local usage = " " .. (c.usage or ""):gsub("[%[%],/]", " "):upper() .. " "
        G.setting_usages[c.name:upper()] = usage
        for _, a in ipairs(c.aliases or {}) do G.setting_usages[a:upper()] = usage end
      end
    end
  end
  local usage = G.setting_usages[name]
  if not usage then return false end
  return value == "ON" or value == "OFF" or value:match("^%d+%.?%d*$") ~= nil
    or (value:match("^%u+$") ~= nil and usage:find(" " .. value .. " ", 1, true) ~= nil)
end
function G.dutch_chat_words(text)
  if not (text:find("%f[%a]ff%f[%A]") or text:find("%f[%a]en%f[%A]") or text:find("%f[%a]met%f[%A]")) then
    return text
  end
  local toks = {}
  for w in text:gmatch("%S+") do toks[#toks + 1] = w end
  local changed = false
  for i = 2, #toks do
    local prev = toks[i - 1]
    -- (a duration anywhere in the rest of its clause: a number first after it, a unit of time, "until")
    local timed = toks[i + 1] ~= nil and toks[i + 1]:match("^%d") ~= nil
    for k = i + 1, #toks do
      local w = toks[k]:lower():gsub("%p+$", "")
      if G.time_units[w] or G.ff_duration_after[w] or w:match("^%d+[smh]$") or w:match("^%d+mins?$")
          or w:match("^%d+:%d") then
        timed = true
      end
      if toks[k]:match("[,;:]$") then break end
    end
    if toks[i]:match("^ff[%.!?]?$") and not prev:match("%p$") and not G.ff_lead[prev:lower()] and not timed
        and not G.after_typed_setting(toks, i) then
      toks[i] = toks[i]:match("[%.!?]$") and toks[i]:sub(-1) or ""
      changed = true
    end
  end
  -- Dutch "en" (and) and "met" (with) straight after a value or a switch's state, with no other Dutch word to
  -- mark the sentence ("pz 5 nm en 1000 ft", "cd on met lookahead 240"); "en route" stays
  -- (not in a sentence of Spanish or French words, whose "en" is "at", "in": "crear ... 320 en gavol")
  local romance = false
  for _, language in ipairs({ "spanish", "french" }) do
    local index = G.said_whole_index()[language]
    for _, w in ipairs(toks) do
      for _, h in ipairs(index[w:lower():gsub("%p+$", "")] or {}) do romance = romance or h.marks end
    end
  end
  for i = 2, romance and 1 or #toks - 1 do
    local w, prev, nxt = toks[i], toks[i - 1]:lower(), toks[i + 1]:lower()
    if (w == "en" or w == "met") and (prev:match("%d$") or G.dutch_value_ends[prev]) and nxt ~= "route" then
      toks[i] = w == "en" and "and" or "with"
      changed = true
    end
  end
  if not changed then return text end
  local out = {}
  for _, w in ipairs(toks) do if w ~= "" then out[#out + 1] = w end end
  return table.concat(out, " ")
end

-- A level said before its verb, as Korean orders it (text in, text out):
-- - "flight level 220 to 200, descent please", "FL150 to 100 descend": the second number of "level A to B"
--   (two or three digits, then the request's end, a mark, or a verb or "please") is a flight level too, so
--   that "FL A to FL B" is read (A the level left, checked against the aircraft's level);
-- - "flight level 330 to, climb please", "9000 feet to, descend": the comma between "to" and its verb is
--   dropped ("FL330 to climb");
-- - "flight level 280 go", "FL280 go please", "heading 090 fly": "go" or "fly" closing a level or a heading of
--   three digits is no word of its own (it says nothing of the direction: the value is read as if said alone).
G.level_verb_after = { climb = true, descend = true, descent = true, climbing = true, descending = true,
                       please = true, go = true, ["and"] = true, ["then"] = true }
G.vertical_verbs = set_of({ "climb", "descend" })
-- verbs that say nothing of speed by themselves, before a speed with its unit ("fly with 280 knots", "put 270 knots")
G.general_speed_verbs = set_of({ "fly", "flies", "go", "goes", "put" })
-- "fly with 280 knots", "it should go with 250 knots", "put 270 knots", "fly with Mach 0,80" (text in, text out):
-- a speed of three digits said with knots, or a Mach number, after a general verb of flying or setting (and "with"
-- or "at", or nothing between) is said "speed 280 knots", so that a condition before it ("when it is at FL130, fly
-- with 280 knots") reads it as it reads any speed instruction; a value of another unit ("fly with 1500 ft/min") or
-- of none ("fly 270", "fly with 270") is left as said
-- "speed 260 until SPY and afterwards 240 knots", "keep FL250 until SPY, and only then descend FL200", "until SPY,
-- thereafter with 240 knots" (text in, text out): the word that opens what follows a limit "until" or "till" a place
-- of one word (or a level "FL200") is said "then" (G:until_then reads the rest from that place), and "with" straight
-- after it before a speed is said "speed"; a longer place, or a sequel word not straight after the place (a comma
-- and "and" between at most), is left as said
G.until_sequels = { "and only then", "only then", "and afterwards", "afterwards", "and afterward", "afterward",
                    "and thereafter", "thereafter", "and after that", "after that" }
function G.until_sequel_said(text)
  for _, w in ipairs(G.until_sequels) do
    local pat = "(%f[%a][Uu]?[Nn]?[Tt][Ii][Ll]l?%s+[%w]+)(%s*,?%s+)" .. w:gsub("%a", function(c)
      return "[" .. c:upper() .. c .. "]" end):gsub(" ", "%%s+") .. "%f[%A]"
    text = text:gsub(pat, function(limit, sep)
      local word = limit:match("^(%a+)"):lower()
      if word ~= "until" and word ~= "till" then return nil end
      return limit .. (sep:find(",", 1, true) and ", " or " ") .. "then"
    end)
  end
  return (text:gsub("(%f[%a][Tt]hen%s+)[Ww]ith(%s+%d%d%d%s*[Kk][NnTt]%a*%f[%A])", "%1speed%2")
    :gsub("(%f[%a][Tt]hen%s+)[Ww]ith(%s+[Mm][Aa][Cc][Hh]%f[%A])", "%1speed%2"))
end
function G.speed_after_general_verb(text)
  local out, from = {}, 1
  for b, verb, e in text:gmatch("()%f[%a](%a+)%f[%A]()") do
    local v = verb:lower()
    if b >= from and G.general_speed_verbs[v] then
      local rest = text:sub(e)
      local sp, prep, sp2, n, sp3, unit, at = rest:match("^(%s+)(%a*)(%s*)(%d%d%d)(%s*)(%a+)%f[%A]()")
      local pr, u = (prep or ""):lower(), (unit or ""):lower()
      local speed = sp and (pr == "" and sp2 == "" or pr == "with" or pr == "at" and v ~= "put")
        and (u == "knots" or u == "knot" or u == "kts" or u == "kt")
      local mach_sp, mprep, mach, mat = rest:match("^(%s+)(%a+)%s+([Mm][Aa][Cc][Hh]%s*0?[%.,]%d%d?)%f[%D]()")
      -- ("put Mach .78", nothing between, as "put 270 knots")
      if not mach_sp then
        mach_sp, mach, mat = rest:match("^(%s+)([Mm][Aa][Cc][Hh]%s*0?[%.,]%d%d?)%f[%D]()")
        mprep = mach_sp and ""
      end
      local mpr = (mprep or ""):lower()
      if speed then
        out[#out + 1] = text:sub(from, b - 1) .. "speed" .. sp .. n .. sp3 .. unit
        from = e + at - 1
      elseif mach_sp and (mpr == "with" or mpr == "" or mpr == "at" and v ~= "put") then
        out[#out + 1] = text:sub(from, b - 1) .. "speed" .. mach_sp .. mach
        from = e + mat - 1
      end
    end
  end
  if from == 1 then return text end
  out[#out + 1] = text:sub(from)
  return table.concat(out)
end
G.speed_verbs = set_of({ "reduce", "increase" })
G.value_not_reordered = set_of({ "at", "when", "after", "passing", "reaching", "until", "till", "above", "below",
  "from", "to", "leaving", "by", "of", "than", "over", "through", "cross", "crossing", "reach", "reaches", "pass",
  "passes", "maintain", "level", "is", "was", "be", "before", "vacating", "past", "once", "while", "if", "climb",
  "descend", "reduce", "increase", "slow", "speed", "accelerate", "expedite", "stop", "for" })
G.counted_nouns = set_of(lexicon.counted_aircraft)
G.create_verbs = set_of({ "create", "make", "spawn", "generate" })
G.new_articles = { "one more", "another", "a new", "one new", "an extra", "one extra" }
function G.level_before_verb(text)
  -- (each rewrite runs only where `low`, the text in lower case, holds the words it needs; set again after one)
  local low = text:lower()
  local function has(w) return low:find(w, 1, true) ~= nil end
  local function rewrite(pattern, repl)
    local was = text
    text = text:gsub(pattern, repl)
    if text ~= was then low = text:lower() end
  end
  local function closes(rest)
    local nx = rest:match("^%s*(%a+)")
    return rest:match("^%s*$") or rest:match("^%s*[,.;!]") or (nx and G.level_verb_after[nx:lower()])
  end
  local function level_to(pre, a, mid, b, at)
    if not closes(text:sub(at)) then return nil end
    return "FL" .. a .. mid .. "FL" .. b
  end
  if has("fl") and has("to") then
    rewrite("(%f[%a][Ff][Ll]%s*)(%d%d%d?)(%s+[Tt][Oo]%s+)(%d%d%d?)%f[%D]()", level_to)
    rewrite("(%f[%a][Ff]light%s+[Ll]evel%s+)(%d%d%d?)(%s+[Tt][Oo]%s+)(%d%d%d?)%f[%D]()", level_to)
  end
  -- ("FL320 to FL300, descent please": the verb of the two levels said first, "descend FL320 to FL300", so that
  -- the level left is checked against the aircraft's in any clause of the request)
  if has("climb") or has("descen") then rewrite("(%f[%a][Ff][Ll]%s*%d%d%d?%s+[Tt][Oo]%s+[Ff][Ll]%s*%d%d%d?)(%s*,?%s*)(%a+)%f[%A]",
    function(levels, _, verb)
      local v = verb:lower()
      if v == "descent" then v = "descend" end
      if v ~= "climb" and v ~= "descend" then return nil end
      return v .. " " .. levels
    end) end
  if has(",") and has("to") then rewrite("(%d%s*%a*%s+[Tt][Oo])%s*,%s*(%a+)%f[%A]", function(pre, verb)
    local unit = pre:match("%d%s*(%a*)%s+[Tt][Oo]$"):lower()
    if (unit == "" or unit == "feet" or unit == "ft") and G.level_verb_after[verb:lower()]
        and verb:lower() ~= "please" and verb:lower() ~= "and" and verb:lower() ~= "then" then
      return pre .. " " .. verb
    end
    return nil
  end) end
  -- "after reaching 250, flight level 230 descend", "flight level 240 climb when passing ANSIM", "when at 210, 5000
  -- feet descend", "speed 250 reduce": a level or speed said before its verb of climb, descent or speed is said
  -- with the verb first ("descend flight level 230"), so that a condition before or after it is read as with the
  -- English order; not after a word that makes the value a condition's or a limit's ("at FL240 climb ...",
  -- "passing 5000 feet descend"), nor before "rate" ("FL280 climb rate ...")
  local function reorder(pat, verbs)
    rewrite("()" .. pat .. "%s+(%a+)%f[%A]()", function(b, value, verb, e)
      if not verbs[verb:lower()] then return nil end
      local prev = (text:sub(1, b - 1):match("(%a+)%s*$") or ""):lower()
      local nx = (text:match("^%s*(%a+)", e) or ""):lower()
      if G.value_not_reordered[prev] or nx == "rate" or nx == "to" then return nil end
      return verb .. " " .. value
    end)
  end
  if has("climb") or has("descend") then
    if has("flight") then reorder("(%f[%a][Ff]light%s+[Ll]evel%s+%d%d%d?)", G.vertical_verbs) end
    if has("fl") then reorder("(%f[%a][Ff][Ll]%s*%d%d%d?)", G.vertical_verbs) end
    if has("feet") then reorder("(%f[%d]%d[%d,]*%s*[Ff][Ee][Ee][Tt])", G.vertical_verbs) end
    if has("ft") then reorder("(%f[%d]%d[%d,]*%s*[Ff][Tt])", G.vertical_verbs) end
  end
  if has("speed") and (has("reduce") or has("increase")) then reorder("(%f[%a][Ss]peed%s+%d%d%d?)", G.speed_verbs) end
  -- "speed 210, and when 210, 5000 feet descend": a bare number straight after "when" or "once" and before a
  -- comma is said "when at 210" (read as the speed given said again only when it is that speed: G:speed_again_at)
  if has("when") then rewrite("(%f[%a][Ww]hen%s+)(%d%d%d?%s*,)", "%1at %2") end
  if has("once") then rewrite("(%f[%a][Oo]nce%s+)(%d%d%d?%s*,)", "%1at %2") end
  -- "ten random aircraft create please", "20 random planes make": the count, "random" and the aircraft's noun
  -- before the verb of creation are said as "create ten random aircraft"
  if has("random") then rewrite("()(%w+)(%s+[Rr]andom%s+)(%a+)%s+(%a+)%f[%A]", function(b, n, rnd, noun, verb)
    local before = text:sub(1, b - 1)
    if not (n:match("^%d+$") or NUMBER_WORDS[n:lower()]) or not G.counted_nouns[noun:lower()]
        or not G.create_verbs[verb:lower()] or not (before:match("^%s*$") or before:match("[,.;:]%s*$")
          or before:match("%f[%a][Pp]lease%s*$")) then
      return nil
    end
    return "create " .. n .. rnd .. noun
  end) end
  -- "one more aircraft make please, JJA1207, B738, ...", "another plane create": a new aircraft's noun before the
  -- verb of creation is said as "create one more aircraft"
  for _, art in ipairs((has("create") or has("make") or has("spawn") or has("generate")) and G.new_articles or {}) do
    local pat = "(%f[%a]" .. art:gsub("%a", function(c) return "[" .. c:upper() .. c .. "]" end):gsub(" ", "%%s+")
      .. "%s+)(%a+)%s+(%a+)%f[%A]"
    rewrite(pat, function(said, noun, verb)
      if not (G.counted_nouns[noun:lower()] or noun:lower() == "plane") or not G.create_verbs[verb:lower()] then
        return nil
      end
      return "create " .. said .. noun
    end)
  end
  for _, pat in ipairs((has("go") or has("fly")) and { "(%f[%a][Ll]evel%s+%d%d%d?)%s+(%a+)%f[%A]()",
                          "(%f[%a][Ff][Ll]%s*%d%d%d?)%s+(%a+)%f[%A]()", "(%f[%a][Hh]eading%s+%d%d%d)%s+(%a+)%f[%A]()" } or {}) do
    rewrite(pat, function(lv, verb, at)
      local rest = text:sub(at)
      if (verb:lower() == "go" or verb:lower() == "fly") and (rest:match("^%s*$") or rest:match("^%s*[,.;!]")
          or rest:match("^%s+[Pp]lease%f[%A]")) then
        return lv
      end
      return nil
    end)
  end
  return text
end

-- Words in a notebook's "#" comment that may hold, take back or time what is before it (G.written_forms)
G.comment_holds = set_of({ "not", "no", "don't", "dont", "never", "cancel", "wait", "hold", "yet", "later", "until",
  "till", "after", "before", "when", "once", "then", "instead", "meant", "mean", "actually", "oops", "sorry",
  "correction", "disregard", "negative", "undo", "revert", "only", "unless", "if", "but" })

-- A setting's name as a notebook writes it (a field of an aircraft, "klm12.hdg", "alt(DLH4AX)"), and the
-- words its spoken change takes: up (+=), down (-=), the unit of the step, the largest step read.
G.NOTEBOOK_FIELDS = {
  hdg = "hdg", heading = "hdg", alt = "alt", altitude = "alt", fl = "fl", spd = "spd", speed = "spd", cas = "spd",
  vs = "vs", lnav = "lnav", vnav = "vnav", dest = "dest", orig = "orig",
}

-- Programmers' shorthand for a setting of one aircraft, rewritten into words the grammar reads:
-- "klm12.hdg = 240" and "hdg(KLM12)=240" are "klm12 hdg 240"; "hdg -= 30" (degrees) is "turn left by 30
-- degrees", "alt += 2000ft" "climb by 2000 ft", "FL -= 20" (flight levels) "descend by 2000 ft", "spd -= 20kt"
-- "reduce speed by 20 kt"; "hdg = hdg - 30" is "hdg -= 30"; "lnav=False" is "lnav off". A step that is no
-- plain whole number in range (a heading step of 0 or 360 and more, an altitude step under 100 ft or over
-- 20000 ft, a speed step over 100 kt, a decimal, a vertical speed's, a step in another unit) is left as the
-- operator and its number alone, and "hdg = -1" as a turn with no side, so they are asked.
function G.notebook_assignments(text)
  if not (text:find("[%.%(]%s*%a") or text:find("=", 1, true) or text:find("%a%(")) then return text end
  local fields = G.NOTEBOOK_FIELDS
  -- "alt(DLH4AX)=FL310", "dest(EZY45LM) = EHAM": the aircraft in brackets after the setting's name
  text = text:gsub("%f[%w](%a+)%(%s*([%w_]+)%s*%)%s*=%s*", function(field, id)
    if not fields[field:lower()] or not id:find("%d") then return nil end
    return id .. " " .. field .. " "
  end)
  -- "spd(250kt)", "vs(-2000)", "spd(.8)", "hdg(270)": a setting's name called with one number (a sign, a decimal,
  -- a unit typed after it) is the setting and its value; anything else in the brackets (an id, two values) is
  -- left as typed
  text = text:gsub("%f[%w](%a+)%(%s*([%-+]?)%s*(%d*%.?%d+)%s*(%a*)%s*%)", function(field, sign, num, unit)
    local f = fields[field:lower()]
    if not f or (unit ~= "" and not lexicon.notebook_units[unit:lower()]) then return nil end
    -- (a sign is a vertical speed's direction; on another setting it could be a step or no value: left as typed)
    if sign ~= "" and f ~= "vs" then return nil end
    return field .. " " .. (sign == "-" and "-" or "") .. num .. (unit ~= "" and " " .. unit or "")
  end)
  -- "vs=+1200fpm", "vs = +800": a vertical speed set with a plus sign is that rate up
  text = text:gsub("%f[%a]([Vv][Ss])%s*=%s*%+%s*(%d)", "%1 %2")
  -- "klm12.hdg", "ezy45lm.spd": the aircraft's id, a dot, the setting's name
  text = text:gsub("%f[%w](%a[%w_]*%d[%w_]*)%.(%a+)%f[^%w_]", function(id, field)
    if not fields[field:lower()] then return nil end
    return id .. " " .. field
  end)
  -- "hdg = hdg - 30", "ryr2ga hdg = ryr2ga hdg - 30": a setting set to itself plus or minus a step
  local function self_step(field, again, sign)
    if field:lower() ~= again:lower() or not fields[field:lower()] then return nil end
    return field .. " " .. sign .. "= "
  end
  text = text:gsub("%f[%a](%a+)%s*=%s*[%w_]+%s+(%a+)%s*([%-+])%s*%f[%d]", self_step)
  text = text:gsub("%f[%a](%a+)%s*=%s*(%a+)%s*([%-+])%s*%f[%d]", self_step)
  -- "hdg -= 30", "alt += 2000ft", "spd -= 20 kt", "FL += 20"
  text = text:gsub("%f[%a](%a+)%s*([%-+])=%s*([%d%.]+)%s*(%a*)", function(field, sign, num, unit)
    local f = fields[field:lower()]
    if not f then return nil end
    local u, n = unit:lower(), num:match("^%d+$") and tonumber(num)
    local up = sign == "+"
    if f == "hdg" and (u == "" or u == "deg" or u == "degs" or u == "degrees" or u == "degree") then
      if n and n > 0 and n < 360 then
        return "turn " .. (up and "right" or "left") .. " by " .. n .. " degrees"
      end
      return sign .. "= " .. num
    elseif (f == "alt" and (u == "" or u == "ft" or u == "feet")) or (f == "fl" and u == "") then
      local feet = n and (f == "fl" and n * 100 or n)
      if feet and feet >= 100 and feet <= 20000 then
        return (up and "climb" or "descend") .. " by " .. feet .. " ft"
      end
      return sign .. "= " .. num
    elseif f == "spd" and (u == "" or u == "kt" or u == "kts" or u == "knots") then
      if n and n > 0 and n <= 100 then
        return (up and "increase" or "reduce") .. " speed by " .. n .. " kt"
      end
      return sign .. "= " .. num
    end
    -- (a step in another unit, a vertical speed's step, a switch's: the setting's name is left out, with
    -- the unit, so the request is asked)
    if f == "hdg" or f == "alt" or f == "fl" or f == "spd" or f == "vs" then return sign .. "= " .. num end
    return nil
  end)
  -- "hdg=-1": a negative value set is no heading; asked as a turn with no side
  text = text:gsub("%f[%a](%a+)%s*=%s*%-%s*(%d+)", function(field, num)
    if fields[field:lower()] ~= "hdg" then return nil end
    return "turn by " .. num .. " degrees"
  end)
  -- "lnav=False", "vnav = 1": a switch set to a truth value
  text = text:gsub("%f[%a](%a+)%s*=%s*(%w+)%f[^%w]", function(field, value)
    local f, v = fields[field:lower()], value:lower()
    if f ~= "lnav" and f ~= "vnav" then return nil end
    if v == "false" or v == "0" or v == "off" or v == "no" then return field .. " off" end
    if v == "true" or v == "1" or v == "on" or v == "yes" then return field .. " on" end
    return nil
  end)
  return text
end

local function written_forms(text, world)
  -- (each pattern pass runs through where(): only where `low`, the text in lower case, holds what the
  -- pattern requires, its first argument; a rewrite outside where() sets `low` again)
  local low = text:lower()
  text = G.notebook_assignments(text)
  low = text:lower()
  local function where(needle, pattern, repl)
    if low:find(needle) then text, low = tokens.gsub_where(text, low, needle, pattern, repl) end
  end
  -- ".hold", ".run": a command typed with a text client's leading dot is the word
  where("%.", "^(%s*)%.(%a)", "%1%2")
  -- "O'Hare", "Chicago O'Hare": a name written with "O'" is the navdata's, which has no apostrophe (OHARE;
  -- "o'clock" stays)
  where("o'", "%f[%a]([Oo])'(%a%a%a+)", function(o, name)
    if name:lower() == "clock" then return nil end
    return o .. name
  end)
  -- "do a 180 to the left", "a 90 to the right": a turn of that many degrees named by its number after "a", its side
  -- said with "to the", is the turn with its side ("do a 180 left", read as a turn by degrees)
  where("to the", "%f[%a]([Aa]%s+)(%d%d%d?)%s+[Tt][Oo]%s+[Tt][Hh][Ee]%s+(%a+)%f[%A]", function(a, n, side)
    if side:lower() ~= "left" and side:lower() ~= "right" then return nil end
    return a .. n .. " " .. side
  end)
  -- "@ FL200", "x NAXEL @ 250", "@ 120 s ...": an at sign typed apart before a value or a name is "at"
  where("@", "(%s)@%s*(%w)", "%1at %2")
  where("@", "^@%s*(%w)", "at %1")
  -- "47,5 north", "8,5 degrees east", "factor to 1,1": a decimal comma (G.decimal_comma) is the point
  where("%d,%d", "()(%d+),(%d+)()", function(b, whole, part, e) return G.decimal_comma(text, b, whole, part, e) end)
  text = typed_abbreviations(lone_multipliers(tokens.numerals_apart(G.unfinished_restarts(G.cut_off_restarts(text)), DIGIT_WORDS), world))
  text = hyphened_types(spelled(G.spelled_letter_a(heard_forms(negated_values(G.readback_reported(readback_heard(self_corrections(G.said_but(G.cancel_corrections(unlabelled(foreign_digits(G.portuguese_and(G.said_whole(G.french_in_english(G.denied_word(G.dutch_chat(G.condition_then(G.condition_copula(G.recreate_said(text))))))))))))))))))))
  low = text:lower()
  -- a position typed as whole degrees after the hemisphere, then minutes ("N55 50.0 W003 20.0", "S33 57
  -- E151 10"): decimal degrees before their hemisphere ("55.833333 N 3.333333 W"); minutes of 60 or more
  -- leave it as typed
  where("[ns]%d", "%f[%w]([NnSs])(%d%d?)%s+(%d%d?%.?%d*)%s+([EeWw])(%d%d?%d?)%s+(%d%d?%.?%d*)%f[^%w%.]",
    function(ns, lat, lat_min, ew, lon, lon_min)
      lat_min, lon_min = tonumber(lat_min), tonumber(lon_min)
      if not lat_min or not lon_min or lat_min >= 60 or lon_min >= 60 then return nil end
      return string.format("%.6f %s %.6f %s", tonumber(lat) + lat_min / 60, ns, tonumber(lon) + lon_min / 60, ew)
    end)
  -- (a clock time told as the present moment of a report is dropped first: G.clock_now)
  text = G.clock_start(G.clock_now(text))
  low = text:lower()
  -- a simulation time typed h:mm:ss ("at 00:20:00") is that many seconds, also before a colon that opens
  -- what follows ("schedule at 00:15:00: ..."); mm:ss or hh:mm stays as typed
  where("%d:%d", "%f[%d:](%d%d?):([0-5]%d):([0-5]%d)(:?)%f[^%d:]", function(h, m, sec, colon)
    return tostring(tonumber(h) * 3600 + tonumber(m) * 60 + tonumber(sec)) .. " seconds" .. colon
  end)
  -- "CPA half a mile", "a quarter of a mile": a fraction of a mile said in words is that many nautical miles
  where("half", "%f[%a]([Hh]alf)%s+an?%s+(%a+)", function(_, unit)
    if lexicon.fraction_units[unit:lower()] then return "0.5 nm" end
  end)
  -- (not after a whole number and "and": "two and a quarter miles" is the number 2.25 and its unit)
  where("quarter", "()%f[%a][Aa]%s+([Qq]uarter)%s+o?f?%s*a?%s*(%a+)", function(at, _, unit)
    if lexicon.fraction_units[unit:lower()] and not text:sub(1, at - 1):match("%f[%a][Aa][Nn][Dd]%s+$") then
      return "0.25 nm"
    end
  end)
  -- "descend 8 500 m", "12 000 ft": a number with a space between its thousands and its last three digits,
  -- typed with its unit straight after, is one number
  where("%d %d", "%f[%w.](%d%d?) (%d%d%d)(%s*)(%a+)%f[%A]", function(th, rest, space, unit)
    if lexicon.thousands_units[unit:lower()] then return th .. rest .. space .. unit end
  end)
  -- "angels two six", "angels 22": military brevity for an altitude in thousands of feet (one or two digits,
  -- typed or said one by one), read as that many thousand feet
  local function angels(digits)
    for d in digits:gmatch("%a+") do
      if not DIGIT_WORDS[d:lower()] then return nil end
    end
    return digits .. " thousand ft"
  end
  where("angels", "%f[%a][Aa][Nn][Gg][Ee][Ll][Ss]%s+(%d%d?)%f[^%w%.]", "%1000 ft")
  where("angels", "%f[%a][Aa][Nn][Gg][Ee][Ll][Ss]%s+(%a+%s+%a+)%f[%A]", angels)
  where("angels", "%f[%a][Aa][Nn][Gg][Ee][Ll][Ss]%s+(%a+)%f[%A]", angels)
  -- "250-ish", "FL200-ish": the suffix of a loose value is its own word ("ish", lexicon's discourse)
  where("%-ish", "(%w)%-([Ii][Ss][Hh])%f[%A]", "%1 %2")
  -- "un-pause", "un-freeze": the prefix "un-" written with a hyphen is the one word ("unpause")
  where("un%-", "%f[%a]([Uu][Nn])%-(%a)", "%1%2")
  local sh = lexicon.shorthand
  -- "zone r 4 nm": ZONER's name typed apart, no right turn
  where("zone", "%f[%a]([Zz][Oo][Nn][Ee])%s+([Rr])%f[%A]", "%1 radius")
  -- "circle ctr around 52.3 4.76 r 25nm": "r" between the centre's last number and another after a circle's word
  -- is its radius, no right turn
  where("ircle", "(%f[%a][Cc][Ii][Rr][Cc][Ll][Ee]%f[%A][^;]-%d)%s+[Rr]%s*(%d)", "%1 radius %2")
  text = turn_letters(text, sh)
  low = text:lower()
  -- "seed=7", "dt = 0.5", "reso=mvp": a setting typed key=value, read as "seed: 7" (only a key that names
  -- a command or a setting: "t=300" in a note stays as typed, as does all of "log: seed=7 baseline")
  local label = text:match("^%s*(%a+)%s*:")
  if not (label and lexicon.note_labels[label:lower()]) then
    where("=", "%f[%w](%a[%w_]*)(%s*=%s*)([%w%.%-])", function(key, _, v)
      if SETTING_KEYS[key:lower()] then return key .. ": " .. v end
    end)
  end
  -- "ff 2m": minutes after fast-forward's abbreviation (no metres of time)
  where("ff", "%f[%w]([Ff][Ff]%s+%d+%.?%d*)%s?[Mm]%f[%W]", "%1 min")
  -- a contraction written without its apostrophe ("whats DERLA's position", "once youre at 250"),
  -- lexicon.apostrophe_dropped, is the contraction (its first letter's case kept)
  where("%a%a%a", "%f[%a](%a)(%a%a+)%f[%A]", function(first, rest)
    local spelled = lexicon.apostrophe_dropped[(first .. rest):lower()]
    return spelled and first .. spelled:sub(2)
  end)
  -- "descend to FL 80 negative FL 90": "negative" straight before a level's, heading's or speed's name is the
  -- correction, no sign of the value after it (set off by a comma, as "negative, FL90" is written)
  where("negative", "%f[%a]([Nn][Ee][Gg][Aa][Tt][Ii][Vv][Ee])(%s+)(%a+)", function(neg, space, nx)
    local n = nx:lower()
    if n == "flight" or (G.value_name_set[n] and n ~= "vs" and n ~= "rate") then return neg .. "," .. space .. nx end
  end)
  -- "realtime" written as one word
  where("realtime", "%f[%a]([Rr][Ee][Aa][Ll])([Tt][Ii][Mm][Ee])%f[%A]", "%1 %2")
  -- "v/s 2500 down": the vertical speed's abbreviation written with a slash
  where("v/s", "%f[%w]([Vv])/([Ss])%f[%W]", "%1%2")
  -- a typed callsign glued to its level ("klm12fl240"), Mach typed as "m78"
  where("%wfl%d", "%f[%w](%a%a%a?%d+%a?%a?)([Ff][Ll]%d%d%d?)%f[%W]", "%1 %2")
  where("m%d", "%f[%w][Mm](%d%d)%f[%W]", "mach .%1")
  -- "mach.76", "mach0.76", "fl.300", "hdg.240": a value's name glued to its value by a dot is the name,
  -- then the value (Mach keeps its decimal point)
  where("%a0?%.%d", "%f[%a](%a+)(0?)%.(%d)", function(name, zero, d)
    local n = name:lower()
    if n == "mach" then return name .. " " .. zero .. "." .. d end
    if G.value_name_set[n] and zero == "" then return name .. " " .. d end
  end)
  -- a position typed as one word of whole degrees ("55N030W", "37N020W"), as oceanic points are written
  where("%d[ns]%d", "%f[%w](%d%d)([NnSs])(%d%d%d)([EeWw])%f[%W]", "%1 %2 %3 %4")
  -- a rate glued to its unit ("1000ft/min", "1500ft/m")
  where("ft/m", "(%d)([Ff][Tt]/[Mm][Ii]?[Nn]?)%f[%A]", "%1 %2")
  -- "dtmult 50  # batch it": a notebook's comment after an instruction, "#" to the end, is set apart as a
  -- remark after a dash; one with a word that may hold or take back what is before it ("# not cleared yet",
  -- "# no wait 210", "# cancel", "# after DIMSA") stays as typed, for the clause rules to read or ask
  where("#", "(%S)%s+#+%s*(%a.*)$", function(before, remark)
    for w in remark:lower():gmatch("[%a']+") do
      if G.comment_holds[w] then return nil end
    end
    return before .. " - " .. remark
  end)
  -- "hdg 45 (it should drift away from the others)": a bracketed remark is a clause of its own, set apart
  -- as after a dash (set_apart)
  where("%(", "%s*%((%a[^()]*)%)", " - %1,")
  -- "print 'episode 12 start' to the log": text in single quotes (after a space, before a space or the
  -- end) is quoted text, as in double quotes
  if low:find("'", 1, true) then
    text = (" " .. text .. " "):gsub("(%s)'([^'%s][^']-)'([%s,%.;:!%?])", '%1"%2"%3'):sub(2, -2)
    low = text:lower()
  end
  -- "jet2 44m", "Jet 2 one two": the airline's brand name (its telephony is Channex, EXS) before a flight number
  where("jet", "%f[%w][Jj][Ee][Tt]%s?2(%s+)(%w+)", function(space, nx)
    if nx:match("^%d") or DIGIT_WORDS[nx:lower()] then return "channex" .. space .. nx end
  end)
  -- ("the Jet2", "Jet2's route", "a Jet2 flight EXS77K": the brand written as one word is the airline anywhere
  -- but where an aircraft's id is JET2; "the jet 2" apart may count jets, left as said)
  where("jet", "%f[%w][Jj][Ee][Tt]2%f[%W]", function()
    for _, a in ipairs(world and world.aircraft or {}) do
      if (a.id or ""):upper() == "JET2" then return nil end
    end
    return "channex"
  end)
  -- "orig/dest AFR1234: LFPG -> LFML", "origin/destination EZY45 EGKK EHAM": both settings written as one
  -- with a slash, then the aircraft and the two airports in that order (an arrow between them or none)
  where("orig", "%f[%a]([Oo][Rr][Ii][Gg]%a*)%s*/%s*([Dd][Ee][Ss][Tt]%a*)%s+(%w+):?%s+(%a%a%a%a)%s*%-*>?%s*(%a%a%a%a)%f[%A]",
    "%3 origin %4, destination %5")
  -- "dest eidw -> einn": an arrow between two places after the name of an airport setting changes it
  -- from the one to the other: the setting takes the second
  if low:find("->", 1, true) then
    where("%->", "(%a+)(%s+)%a+%s*%-+>%s*(%a+)", function(setting, space, to)
      if not lexicon.arrow_settings[setting:lower()] then return nil end
      return setting .. space .. to
    end)
    -- "bel3pv at NIK -> FL180", "after ROLIS -> spd 250": an arrow after a place the aircraft reaches leads
    -- to what it does there, as "then" ("at NIK then FL180": the instruction starts at NIK); after a level
    -- ("passing FL120 -> spd 280") it stays a comma, below
    where("%->", "%f[%a](%a+)(%s+)([%a_][%w_]*)%s*%-+>%s*", function(word, space, place)
      local w, p = word:lower(), place:lower()
      if not (w == "at" or w == "after" or w == "over" or w == "passing" or w == "reaching")
          or p:match("^fl%d") or lexicon.shorthand[p] then
        return nil
      end
      return word .. space .. place .. " then "
    end)
    -- "KLM1234 -> SUGOL": an arrow typed before a place's name is a direct-to ("alt -> FL330", a value
    -- after a setting's name, is no place); before a word that opens an instruction (a value's name, a verb
    -- of climb or descent, a turn: "KLM56 -> hdg 210 L", "passing FL120 -> spd 280") it separates that
    -- instruction from what is before it, as a comma
    where("%->", "(%w+)%s*%-+>%s*(%a[%w%.]*)", function(before, after)
      local b, a = before:lower(), after:lower()
      if lexicon.shorthand[b] or lexicon.direct_arrow_not[b] or a:match("^m%.?%d") then return nil end
      -- ("klm12 -> FL320, dlh4 -> FL280": before a level the arrow is "to", each aircraft's own)
      if a:match("^fl%d") then return before .. " to " .. after end
      if word_set("turn left right lt rt @instruction_nouns @up @down", 1)[a] then return before .. ", " .. after end
      return before .. " direct " .. after
    end)
  end
  text = G.navaid_city_names(G.sim_old(G.thousand_speed_homophones(value_homophones(G.limit_homophones(split_digits(text))))))
  -- "dlh4ax up 2000", "down 1500 pls": a bare whole or half thousand typed after "up" or "down" is a change of
  -- level by that many feet, as "up 2000 ft" (after a rate's or a speed's name, "vs up 2000", or before a unit,
  -- it stays as typed; "up 20" stays too, and is asked)
  where("%a%s+%d", "()%f[%a]([UuDd][PpOo][Ww]?[Nn]?)(%s+)(%d%d%d%d?)()%f[^%w%.]", function(at, dir, space, digits, e)
    local d, n = dir:lower(), tonumber(digits)
    if (d ~= "up" and d ~= "down") or n < 1000 or n % 500 ~= 0 then return nil end
    local before = text:sub(1, at - 1):lower():match("(%a+)%s*$")
    local unit = text:sub(e):match("^%s*(%a+)")
    if (before and word_set(lexicon.typed_abbreviations.dn.not_prev, 1)[before])
        or (unit and lexicon.level_split_units[unit:lower()]) then
      return nil
    end
    return dir .. space .. digits .. " ft"
  end)
  low = text:lower()
  where("%a%d", "%f[%w](%a+)(%d+)%f[^%w%.]", function(pre, digits)
    local w = sh[pre:lower()]
    return w and (w .. " " .. digits) or nil
  end)
  where("%a%s+%d", "()%f[%w](%a+)(%s+)(%d)", function(at, pre, space, digit)
    local w = sh[pre:lower()]
    -- ("when it's 15 miles from HEL": the letter of a contraction is no shorthand)
    if not w or text:sub(at - 1, at - 1) == "'" or text:sub(math.max(1, at - 3), at - 1) == "\u{2019}" then
      return nil
    end
    local before = text:sub(1, at - 1):match("(%S+)%s*$")
    -- (after a number only a turn letter: "fl 310 rt 320"; "33.95 S" is a hemisphere, "2 h" hours)
    if before and before:match("^[%d%.,%-]+$") and w ~= "left" and w ~= "right" then return nil end
    return w .. space .. digit
  end)
  text = G.spoken_coordinates(text)
  low = text:lower()
  if low:find("north", 1, true) or low:find("south", 1, true) then
    text = G.hemispheres_first(text)
    low = text:lower()
  end
  -- a coordinate typed in digits with its point said ("55 decimal 5 north"): 55.5, only before a hemisphere
  for _, p in ipairs(POINT_SAID) do
    where(p.word, p.pattern, function(whole, frac, space, hemi)
      if HEMISPHERES[hemi:lower()] then return whole .. "." .. frac .. space .. hemi end
      return nil
    end)
  end
  where("a thousand", "%f[%a][Aa] ([Tt][Hh][Oo][Uu][Ss][Aa][Nn][Dd])%f[%A]", "one %1")
  where("a hundred", "%f[%a][Aa] ([Hh][Uu][Nn][Dd][Rr][Ee][Dd])%f[%A]", "one %1")
  -- ("set conflict vertical zone thousand feet", "3 mile radius, thousand feet", "thousand feet vertical": "thousand
  -- feet" opening the text or a clause after a mark, or after a word that is no number, nor a word heard for a
  -- digit ("to thousand"), is one thousand feet)
  where("housand", "()%f[%a]([Tt]housand)(%s+)(%a+)", function(at, th, s2, unit)
    local u, w = unit:lower(), text:sub(1, at - 1):match("(%S+)%s*$")
    local lw = w and w:lower()
    if (u == "feet" or u == "ft" or u == "foot") and (not w or w:match("%p$")
        or (w:match("^%a+$") and not NUMBER_WORDS[lw] and not lexicon.digit_homophones[lw]
          and not lexicon.foreign_digits[lw] and not lexicon.thousand_counted[lw])) then
      return "one " .. th .. s2 .. unit
    end
    return nil
  end)
  -- ("another thousand feet", "a further hundred feet": one more of it)
  where("another thousand", "%f[%a]([Aa]nother) ([Tt]housand)%f[%A]", "%1 one %2")
  where("another hundred", "%f[%a]([Aa]nother) ([Hh]undred)%f[%A]", "%1 one %2")
  where("further thousand", "%f[%a]([Ff]urther) ([Tt]housand)%f[%A]", "%1 one %2")
  where("further hundred", "%f[%a]([Ff]urther) ([Hh]undred)%f[%A]", "%1 one %2")
  where("flightlevel", "%f[%a][Ff][Ll][Ii][Gg][Hh][Tt]([Ll][Ee][Vv][Ee][Ll])%f[%A]", "flight %1")
  -- ("climb to level 380, no, stop, keep 360": "нет, стоп", a self-correction's "no, wait")
  where("stop", "%f[%a]([Nn][Oo]%s*,%s*)[Ss][Tt][Oo][Pp](%s*,)", "%1wait%2")
  -- ("Make so that Aeroflot 1234 flies directly to DEDUM", "Please make it so that ...": "сделайте так, чтобы", the
  -- wish's frame opening the request or a sentence, "please" or "kindly" before it or not; the clause after it is
  -- what is wanted, read as said)
  -- (a colon after it in its sentence, "Please make so that X and Y will not have conflict: X keeps ...", makes it the
  -- purpose of the instructions after the colon, kept)
  where("so that", "()%f[%a]([Mm][Aa][Kk][Ee])%s+(%a*)%s*[Ss][Oo]%s+[Tt][Hh][Aa][Tt]%s+()", function(at, _, it, past)
    if it ~= "" and it:lower() ~= "it" then return nil end
    if (text:sub(past):match("^[^%.!?]*:")) then return nil end
    local before = text:sub(1, at - 1):gsub("%s+$", "")
    local w = before:match("(%a+)$")
    if w and (w:lower() == "please" or w:lower() == "kindly") then before = before:sub(1, -#w - 1):gsub("%s+$", "") end
    if before ~= "" and not before:match("[%.!?:;,]$") then return nil end
    return ""
  end)
  -- ("600 kilometers in hour", "500 kilometres in an hour", "kilometers an hour": "км в час", a speed in km/h)
  for _, p in ipairs({ "[Ii][Nn]%s+[Aa][Nn]", "[Ii][Nn]", "[Aa][Nn]" }) do
    where("hour", "%f[%a]([Kk][Ii][Ll][Oo][Mm][Ee][Tt][RrEe][EeRr][Ss]?)%s+" .. p .. "%s+([Hh][Oo][Uu][Rr])%f[%A]",
      "%1 per %2")
  end
  where("call", "%f[%a]([Cc][Aa][Ll][Ll])[%- ]([Ss][Ii][Gg][Nn])%f[%A]", "%1%2")  -- "call sign"
  -- "Egyptair triple seven", "double two": a digit said twice or three times
  where("double", "%f[%a]([Dd][Oo][Uu][Bb][Ll][Ee])%s+(%a+)%f[%A]", function(_, d)
    if DIGIT_WORDS[d:lower()] then return d .. " " .. d end
    return nil
  end)
  where("triple", "%f[%a]([Tt][Rr][Ii][Pp][Ll][Ee])%s+(%a+)%f[%A]", function(_, d)
    if DIGIT_WORDS[d:lower()] then return d .. " " .. d .. " " .. d end
    return nil
  end)
  -- ("the triple 7", "Egyptair triple 7": one digit typed, the three of them)
  where("triple", "%f[%a][Tt][Rr][Ii][Pp][Ll][Ee]%s+(%d)%f[^%w.,]", "%1%1%1")
  where("ray", "%f[%a]([Xx])[%- ]([Rr][Aa][Yy])%f[%A]", "%1%2")
  where("trot", "%f[%a]([Ff][Oo][Xx])[%- ]([Tt][Rr][Oo][Tt])%f[%A]", "%1%2")
  where("nine her", "%f[%a]([Nn][Ii][Nn])[Ee] [Hh][Ee][Rr]%f[%A]", "%1er")
  where("\xC2\xB0", "(%d)\xC2\xB0(%s)", "%1 degrees%2")
  where("\xC2\xB0", "(%d)\xC2\xB0$", "%1 degrees")
  -- (and before a mark that ends the sentence or clause: "turned left 30°.", "right 20°, then ...")
  where("\xC2\xB0", "(%d)\xC2\xB0([%.,;!?])$", "%1 degrees%2")
  where("\xC2\xB0", "(%d)\xC2\xB0([%.,;!?]%s)", "%1 degrees%2")
  -- a change typed with its sign and unit ("+20 kts", "-1000 ft"): that many faster/slower, up/down; in degrees
  -- ("+30 deg", "-15 degrees") a turn right/left by that much (a number after it, "-33 deg 151 deg", makes it a
  -- coordinate, left as typed)
  where("[%+%-]%d", "%f[^%s]([%+%-])(%d+)%s*(%a+)%f[%A]()", function(sign, n, unit, e)
    local u = unit:lower()
    if (u == "deg" or u == "degrees") and tonumber(n) <= 180 and not text:sub(e):match("^%s*[%+%-]?%d") then
      return "turn " .. (sign == "+" and "right " or "left ") .. n .. " degrees"
    end
    if u == "kts" or u == "kt" or u == "knots" then
      return n .. " " .. unit .. (sign == "+" and " faster" or " slower")
    end
    if u == "ft" or u == "feet" then return (sign == "+" and "up " or "down ") .. n .. " " .. unit end
    return nil
  end)
  -- the same change typed with no unit straight after the value's name ("speed +20", "alt -2000", "climb
  -- +3000", "heading +20"): knots, feet, or degrees of a turn to the right (+) or left (-)
  -- ("vertical speed -2000" is a rate, its sign its direction)
  where("[%+%-]%d", "()%f[%a](%a+)(%s+)([%+%-])(%d+)%f[^%w%.]", function(at, name, space, sign, n)
    local kind = SIGNED_CHANGE[name:lower()]
    if kind == "speed" and (text:sub(1, at - 1):match("(%a+)%s*$") or ""):lower() == "vertical" then return nil end
    if kind == "speed" then return name .. space .. n .. " kt" .. (sign == "+" and " faster" or " slower") end
    if kind == "alt" or kind == "alt" .. sign then
      return name .. space .. (sign == "+" and "up " or "down ") .. n .. " ft"
    end
    if kind == "hdg" then return "turn " .. (sign == "+" and "right " or "left ") .. n .. " degrees" end
    return nil
  end)
  -- an amount with its unit and "more"/"less" after it, or "gain"/"lose" before it ("20 kt less", "lose 4000
  -- ft", "gain 1000 feet"): that many faster/slower, up/down
  -- ("2000 ft more or less", "20 kt less than ...": an estimate or a bound, left as typed; the amount is the whole
  -- number, a point, comma or apostrophe in it included: "2.000 ft more", "1,5 kt less"; "descend 3000 feet
  -- more": "more" after a word of a descent said straight before the amount is that much further down)
  if low:find("more", 1, true) or low:find("less", 1, true) then
    -- "2000 feet more low", "20 knots more slow", "3000 feet more high": "more" and a word of the direction
    -- after an amount's unit is that much in that direction ("more" <- up/faster, "less" <- down/slower);
    -- a direction word of the other quantity ("20 knots more high") or after "less" is left as typed
    text = text:gsub("(%f[%a]%a+%s+)([Mm][Oo][Rr][Ee])%s+(%a+)%f[%A]", function(unit_sp, more, word)
      local kind = UNIT_CHANGE[unit_sp:match("%a+"):lower()]
      local d = G.MORE_DIRECTION[word:lower()]
      if not (kind and d) or d[1] ~= kind then return nil end
      return unit_sp .. (d[2] > 0 and more or "less")
    end)
    text = text:gsub("()%f[%w%.,'](%d+[%.,']?%d*)(%s*)(%a+)%s+(%a+)%f[%A]()", function(b, n, space, unit, word, at)
      local kind, dir = UNIT_CHANGE[unit:lower()], MORE_LESS[word:lower()]
      local nx = (text:match("^%s+(%a+)", at) or ""):lower()
      if not (kind and dir) or nx == "or" or nx == "than" or n:match("%D$") then return nil end
      if kind == "alt" and dir > 0 and G.descent_words[(text:sub(1, b - 1):match("(%a+)%s+$") or ""):lower()] then
        dir = -1
      end
      if kind == "speed" then return n .. space .. unit .. (dir > 0 and " faster" or " slower") end
      return (dir > 0 and "up " or "down ") .. n .. space .. unit
    end)
    -- ("thirty knots less would be better": the amount said as one number word, no number word before it)
    text = text:gsub("()%f[%a](%a+)(%s+)(%a+)%s+(%a+)%f[%A]()", function(b, n, space, unit, word, at)
      local v, kind, dir = G.amount_words[n:lower()], UNIT_CHANGE[unit:lower()], MORE_LESS[word:lower()]
      local nx = (text:match("^%s+(%a+)", at) or ""):lower()
      local before = (text:sub(1, b - 1):match("(%S+)%s+$") or ""):lower()
      if not (v and kind == "speed" and dir) or nx == "or" or nx == "than" or before:match("^%d+$")
          or NUMBER_WORDS[before] then
        return nil
      end
      return v .. space .. unit .. (dir > 0 and " faster" or " slower")
    end)
    low = text:lower()
  end
  if low:find("level", 1, true) or low:find("heading", 1, true) or low:find("fl", 1, true) or low:find("random", 1, true) or low:find("speed", 1, true) or low:find("when", 1, true)
      or low:find("once", 1, true)
      or low:find("f", 1, true) or low:find("more", 1, true) or low:find("new", 1, true) or low:find("other", 1, true) or low:find("extra", 1, true) then
    text = G.level_before_verb(text)
    low = text:lower()
  end
  -- "fly with 280 knots", "it should go with 250 knots", "put 270 knots", "fly with Mach 0,80": a speed said with
  -- its unit (knots or Mach) after a general verb of flying or setting is the speed instruction, said "speed 280
  -- knots", so that a condition before it ("when it is at FL130, fly with 280 knots") reads it as after any speed
  -- verb; a value of another unit ("fly with 1500 ft/min") or none ("fly 270") is left as said
  if low:find("until", 1, true) or low:find("till", 1, true) then
    text = G.until_sequel_said(text)
    low = text:lower()
  end
  if low:find("knot", 1, true) or low:find("kt", 1, true) or low:find("mach", 1, true) then
    text = G.speed_after_general_verb(text)
    low = text:lower()
  end
  if low:find("gain", 1, true) or low:find("lose", 1, true) then
    text = text:gsub("%f[%a](%a+)(%s+)(%d+[%.,']?%d*)(%s*)(%a+)%f[%A]", function(verb, space, n, space2, unit)
      local dir, kind = GAIN_LOSE[verb:lower()], UNIT_CHANGE[unit:lower()]
      if not (kind and dir) or n:match("%D$") then return nil end
      if kind == "speed" then return n .. space2 .. unit .. (dir > 0 and " faster" or " slower") end
      return (dir > 0 and "up" or "down") .. space .. n .. space2 .. unit
    end)
    low = text:lower()
  end
  -- "a 180 heading", "the 090 heading": a heading of three digits said before its name
  where("%d%s+heading", "%f[%a]([Aa]n?%s+)(%d%d%d)%s+([Hh][Ee][Aa][Dd][Ii][Nn][Gg])%f[%A]", "%1%3 %2")
  where("%d%s+heading", "%f[%a]([Tt]he%s+)(%d%d%d)%s+([Hh][Ee][Aa][Dd][Ii][Nn][Gg])%f[%A]", "%1%3 %2")
  -- "45.6,-122.6": a latitude and longitude in decimal degrees typed with a comma and no space between them
  where("%d,", "%f[%d%-](%-?%d%d?%.%d+),(%-?%d%d?%d?%.%d+)%f[^%w%.]", "%1 %2")
  where("%d %d", "%f[%d](%d%d?%d?) (%d%d%d)%f[%D]()", function(a, b, at)
    if b == "000" or text:sub(at):match("^%s*[Ff][Ee]?[Ee]?[Tt]%f[%A]") or text:sub(at):match("^%s*[Ff][Oo][Oo][Tt]") then
      return a .. b
    end
    return nil
  end)
  return text
end

-- ---- the state of one translation ----

-- The tokens b .. e-1 as they were typed, joined by spaces (for questions that quote them).
function G:raw(b, e)
  local words = {}
  for k = b, e - 1 do words[#words + 1] = self.t[k].raw end
  return table.concat(words, " ")
end

-- self.words[i]: the text of token i when it is a word, else false (nil past the end).
local function word_texts(toks)
  local words = {}
  for i = 1, #toks do
    local t = toks[i]
    words[i] = t.kind == "word" and t.text
  end
  return words
end

-- The word at k is a filler from here on, its text blank (it is no word of any list). A token's text
-- changes only here: self.words follows it.
function G:blank(k)
  self.t[k].text, self.t[k].filler = "", true
  self.words[k] = ""
  self.commentary_ends = nil  -- (commentary_end's per-request ends read the marks' texts)
end

function G:word(i, words)
  local w = self.words[i]
  if not w then return false end
  return (set_cache[words] or word_set(words, 2))[w] == true
end

-- The registry name of the command the word at i names when it is a registry name or alias that is
-- no English word ("rfacv" RFACV, "pzdh" ZONEDH), else nil.
function G:registry_word(i)
  local t = self.t[i]
  return t ~= nil and t.kind == "word" and REGISTRY_WORDS[t.text] or nil
end

-- True when one of the words b .. e-1 of texts (G's self.words; e past the end reads as the end) is a
-- word of set s.
local function word_among(texts, b, e, s)
  local last = #texts + 1
  if e < last then last = e end
  for k = b, last - 1 do
    local w = texts[k]
    if w and s[w] then return true end
  end
  return false
end

function G:word_in(b, e, words)
  return self:said(words) and word_among(self.words, b, e, set_cache[words] or word_set(words, 2))
end

-- True when the word at i is "not" said before lexicon.additive_not ("not just heading and speed", "not only
-- horizontally"): an addition to what follows, no negation of it.
function G:additive_not(i)
  return self:word(i, "not") and self:word(i + 1, "@additive_not")
end

-- A fraction said in words after "one" or "a" at i ("one half", "a quarter": lexicon.fractions), not the part
-- of a number after "and" ("one and a half"): the position after it, or nil.
function G:fraction_said(i)
  return self:word(i + 1, "@fractions") and not self:word(i - 1, "and") and (self:word(i, "a one") or (self.t[i] and self.t[i].kind == "number"
    and self.t[i].text == "1" and self.t[i].raw:lower() == "one")) and i + 2 or nil
end

-- The first position in [b, e) holding one of `words`, or e.
function G:find_word(b, e, words)
  if not self:said(words) then return e end
  local s = set_cache[words] or word_set(words, 2)
  local texts = self.words
  local last = #texts + 1
  if e < last then last = e end
  for i = b, last - 1 do
    local w = texts[i]
    if w and s[w] then return i end
  end
  return e
end

do  -- (G:said's tables, its own)
  -- LIST_WORDS[words]: the words of a word list or set (G:word's `words`), as an array
  local LIST_WORDS = setmetatable({}, { __mode = "k" })
  -- SAID_LISTS.of[w]: the word lists given as strings (G:said's `words`) that hold the word w, each list once
  -- it was first asked about; SAID_LISTS.serial[words]: its place in that order (.seen: how many so far).
  local SAID_LISTS = { of = {}, serial = {}, seen = 0 }
  -- True when a word of `words` may be in the request: it was when the request was first asked about (a word
  -- is only ever blanked, so a false stays true). Per request and list; a guard in front of a scan for words
  -- that are seldom said.
  function G:said(words)
    local memo = self.said_memo  -- per request: memo[words] = the answer
    if not memo then
      memo = {}
      self.said_memo = memo
      -- present[w] for each word said; held[words] for each list of SAID_LISTS holding a word said (the lists
      -- seen up to now, self.lists_seen)
      local present, held = {}, {}
      local texts = self.words
      for k = 1, #texts do
        local w = texts[k]
        if w and not present[w] then
          present[w] = true
          local lists = SAID_LISTS.of[w]
          for j = 1, lists and #lists or 0 do held[lists[j]] = true end
        end
      end
      self.present, self.held, self.lists_seen = present, held, SAID_LISTS.seen
    end
    -- (a list seen before the request was first asked about is answered by self.held at once, as below, but
    -- where it is longer than the request: that answer the memo keeps)
    local serial = SAID_LISTS.serial[words]
    if serial and serial <= self.lists_seen then
      if not self.held[words] then return false end
      if #LIST_WORDS[words] <= #self.words then return true end
    end
    local v = memo[words]
    if v ~= nil then return v end
    local list = LIST_WORDS[words]
    if not list then
      list = {}
      for w, x in pairs(set_cache[words] or word_set(words, 2)) do
        if x then list[#list + 1] = w end
      end
      LIST_WORDS[words] = list
      -- (a list holding "", a blanked word's text, is asked about as it stands, as it may come to be said)
      if type(words) == "string" and not (set_cache[words] or word_set(words, 2))[""] then
        local of = SAID_LISTS.of
        SAID_LISTS.seen = SAID_LISTS.seen + 1
        SAID_LISTS.serial[words] = SAID_LISTS.seen
        for k = 1, #list do
          local w = list[k]
          of[w] = of[w] or {}
          of[w][#of[w] + 1] = words
        end
      end
    end
    -- (the shorter of the list and the request is walked; a list seen before the request was first asked about
    -- holds a word said exactly when self.held says so, and the request's words now are among those then)
    local texts = self.words
    local serial = SAID_LISTS.serial[words]
    local known = serial ~= nil and serial <= self.lists_seen
    if known and not self.held[words] then
      v = false
    elseif #list > #texts then
      v = word_among(texts, 1, #texts + 1, set_cache[words] or word_set(words, 2))
    elseif known then
      v = true
    else
      local present = self.present
      v = false
      for k = 1, #list do
        if present[list[k]] then
          v = true
          break
        end
      end
    end
    memo[words] = v
    return v
  end
end

function G:followed_by(i, span, words) return self:word_in(i + 1, math.min(#self.t + 1, i + 1 + span), words) end
-- True when position i lies in a reason given for an instruction, which runs
-- from "because", "since" or "so that/it/they" to the end of the sentence
-- ("climb KLM602 FL220 so that it clears BAW451": BAW451 is not instructed).
local COMMENTARY = lexicon.aside
local CM_SUBJECTS, CM_OWN, CM_LEADS, CM_LABELS = set_of(COMMENTARY.subjects), set_of(COMMENTARY.own),
  set_of(COMMENTARY.leads), set_of(COMMENTARY.labels)
local CM_BLOCKS, CM_DETERMINERS = set_of(COMMENTARY.blocks), set_of(COMMENTARY.determiners)
local CM_WHILE, CM_LATER, CM_LEAD_CONTEXT = set_of(COMMENTARY.while_words), set_of(COMMENTARY.later),
  set_of(COMMENTARY.lead_context)
COMMENTARY.reason_set, COMMENTARY.study_set = set_of(COMMENTARY.reasons), set_of(COMMENTARY.study_labels)
COMMENTARY.put_off_later_set = set_of(COMMENTARY.put_off_later)
COMMENTARY.audience_set = set_of(COMMENTARY.audience)
COMMENTARY.restate_set, COMMENTARY.intention_set = set_of(COMMENTARY.restate_verbs), set_of(COMMENTARY.intention)
COMMENTARY.restated_sets = {}
for intent, nouns in pairs(COMMENTARY.restated) do COMMENTARY.restated_sets[intent] = set_of(nouns) end
local CM_NEGATION = set_of(lexicon.accounted.negation)
for _, w in ipairs(lexicon.accounted.condition) do CM_NEGATION[w] = true end
-- (a person in the room opens a remark as "we" does: "freeze the sim, trainee needs a break")
for _, w in ipairs(lexicon.speaker_roles) do CM_SUBJECTS[w] = true end

-- The end of the commentary span starting at b: the next punctuation other than a comma, hyphen or quote
-- (a closing bracket for one opened at b - 1). With `last`, the scan stops past it: an end beyond last
-- reads as last + 1.
local function commentary_end(self, b, last)
  -- (self.commentary_ends[b]: the end with no `last`, per request; G:blank, which may blank a mark, clears it)
  local ends = self.commentary_ends or {}
  self.commentary_ends = ends
  local e = ends[b]
  if not e then
    e = b
    local toks = self.t
    local stop = #toks
    while e <= stop do
      local x = toks[e]
      if x.kind == "punct" and x.text ~= "," and x.text ~= "-" and x.text ~= "'" then break end
      e = e + 1
    end
    ends[b] = e
  end
  if last and last < #self.t then
    if b > last then return b end
    if e > last + 1 then return last + 1 end
  end
  return e
end

-- True when the word at x is an airline's name said bare, capitalised, as a callsign is ("we want Finnair
-- lower"): an aircraft addressed, never words of a remark.
local function airline_bare(self, x)
  return self.t[x].kind == "word" and self.t[x].raw:match("^%u") ~= nil and not self:word(x - 1, CM_DETERMINERS)
    and self:airline_at(x) ~= nil
end

-- True when the tokens b .. e-1 may be set aside as commentary on an instruction (lexicon.aside):
-- no value, no place, no aircraft first ("- TOM6RT too"), no instruction word (one after a determiner is
-- a noun: "the turn model"), none of commentary.blocks, "too" or "as well" at its end, and no negation or
-- condition unless it opens with commentary.own. (`lead`: a lead-in before a colon, "same" in it aside: "To
-- create a same-level encounter:"; `places`: a place named is the remark's, an airport code that is an airline's
-- too, "- he's inbound to FRA")
-- True when quantity q is a whole number said straight after a word of a study's label (lexicon.aside.study_labels:
-- "- test flight profile step 2", "- run 3"): the label's identifier, no value (`remark`: only inside a remark set
-- apart, G:in_reason).
function G:label_number(q, remark)
  return q.kind == "plain" and not q.number.decimal and self:word(q.b - 1, COMMENTARY.study_set)
    and (not remark or self:in_reason(q.b))
end

-- True when quantity q is a count of aircraft ("when two aircraft get too close", "the two Airbuses": a whole
-- number from 2 to 9 said before a word of lexicon.counted_aircraft or maker_plurals) or "one" standing for an
-- aircraft after a word ("the one the participant sequences", "the long-haul one"; not "the other one", an aircraft
-- meant): no value.
function G:aircraft_count(q)
  if q.kind ~= "plain" or q.number.decimal or q.e ~= q.b + 1 then return false end
  local before = self.t[q.b - 1]
  return (q.value >= 2 and q.value <= 9 and (self:word(q.e, "@counted_aircraft") or self:word(q.e, "@maker_plurals")))
    or (self:word(q.b, "one") and before ~= nil and before.kind == "word" and not before.number_word
      and not self:word(q.b - 1, "other another"))
end

-- True when the tokens b .. e-1 open with the speaker's hedge, its "I'm" dropped (lexicon.aside.hedge: "not sure
-- which way is shorter", "not quite sure that's realistic"): "not", at most two hedge adverbs, "sure" or "certain",
-- then a complement word before e. A bare "not sure" or one about a noun ("not sure about the level") is none.
function G:hedge_opens(b, e)
  local h = COMMENTARY.hedge
  if not self:word(b, "not") then return false end
  h.adverb_set = h.adverb_set or set_of(h.adverbs)
  h.word_set = h.word_set or set_of(h.words)
  h.complement_set = h.complement_set or set_of(h.complements)
  local x = b + 1
  while x < b + 3 and self:word(x, h.adverb_set) do x = x + 1 end
  return x + 1 < e and self:word(x, h.word_set) and self:word(x + 1, h.complement_set)
end

function G:commentary(b, e, lead, record, places)
  if b >= e or self:has_ref(b, b + 1, "aircraft") then return false end
  for _, q in ipairs(self:quantities(b, e)) do
    -- ("- this one is the Linate overflight", "- the long-haul one", "when two aircraft get too close": G:aircraft_count)
    local counted = q.b > b and self:aircraft_count(q)
    -- (`record`: a time after a word of lexicon.record_past is the record's, ", as the controller did at 10:42:15")
    local recorded = record and q.kind == "time" and self:word_in(b, q.b, "@record_past")
    if not (counted or recorded or self:label_number(q)) then return false end
  end
  for _, r in ipairs(places and {} or self:refs_in(b, e, "waypoint")) do
    if not self:word(r.b, "@not_names") then return false end
  end
  local own, studied = self:word(b, CM_OWN) or self:hedge_opens(b, e), false
  for x = b, e - 1 do
    local t = self.t[x]
    if self.noted[x] then return false end  -- (what squawk does not simulate: "- hold TOM6RT")
    if t.kind == "word" then
      local last = x == e - 1 or self.t[x + 1].kind == "punct"
      if (CM_BLOCKS[t.text] and not (lead and t.text == "same"))
          or self:word(x, "@correction") or (airline_bare(self, x) and not places)
          -- ("..., in my view, when the conflict first became apparent": the past told, no condition)
          or (not own and CM_NEGATION[t.text] and not self:past_told(x))
          or (last and (t.text == "too" or (t.text == "well" and self:word(x - 1, "as")))) then
        return false
      end
      -- (a word some rule starts an instruction with, before an aircraft, whether or not it starts one
      -- here: "- hold TOM6RT", "- move the easyJet")
      local verb = RULES_BY_WORD[t.text] and self:has_ref(self:word(x + 1, "the") and x + 2 or x + 1, x + 3, "aircraft")
      -- (`places`: a noun after a reason's word is the reason's, "- ride reports")
      -- (in the speaker's own clause, a question word after its verb opens what the speaker studies, no
      -- question asked and no instruction, naming no aircraft: "we are studying how participants notice speed
      -- changes")
      studied = studied or (own and x > b + 1 and self:word(x, "how what whether") and not self:has_ref(x, e, "aircraft"))
      if (verb or self:intent_at(x)) and not studied and not self:word(x - 1, CM_DETERMINERS)
          and not (places and self:word(x - 1, COMMENTARY.reason_set)) then
        return false
      end
    end
  end
  return true
end

-- True when the clause from b (its verb, one of commentary.restate_verbs) describes again an instruction said
-- before it: a pronoun, then in the clause a noun of commentary.restated for the intent of a word before b
-- (", give him a proper vector off" after a turn), the clause commentary otherwise (G:commentary).
function G:restates(b)
  local e = commentary_end(self, b)
  if not self:word(b + 1, "him her it them") or not self:word_in(b + 2, e, "a an another") then return false end
  for x = 1, b - 1 do
    local nouns = COMMENTARY.restated_sets[self:intent_at(x) or ""]
    if nouns and self:word_in(b + 2, e, nouns) then return self:commentary(b, e) end
  end
  return false
end

-- True when the condition word at c opens the speaker's own intention (", then when clear of BAW87 I'll send him
-- back"): before the end of its clause, commentary.intention (or "i"/"we" and "will") after a condition holding
-- no value, place or instruction word (the traffic it names is the condition's), and commentary naming no aircraft
-- from there on.
function G:intention_after(c)
  local e = commentary_end(self, c + 1)
  for p = c + 2, e - 1 do
    if self:word(p, COMMENTARY.intention_set) or (self:word(p, "i we") and self:word(p + 1, "will")) then
      if #self:quantities(c + 1, p) > 0 or #self:refs_in(c + 1, p, "waypoint") > 0
          or self:has_ref(p, e, "aircraft") then
        return false
      end
      for x = c + 1, p - 1 do
        if self:intent_at(x) then return false end
      end
      return self:commentary(p, e)
    end
  end
  return false
end

-- True when the clause from b names an instruction given "to" someone (", we want the easyJet to descend",
-- ", I need EZY45 to turn") or an airline said bare: what follows is wanted of an aircraft, never a
-- purpose set aside.
local function names_instructed(self, b)
  for x = b, commentary_end(self, b) - 1 do
    if (self:word(x, "to") and self:intent_at(x + 1)) or airline_bare(self, x) then return true end
  end
  return false
end

-- The colon ending a title that opens the request at k ("converging pair please:", "symmetric geometry:"): at most
-- four words before it, none a word any rule starts an instruction with, an airline or a value, place or
-- aircraft (G:commentary), with the request going on after it; nil when there is none.
local function title_end(self, k)
  local e = commentary_end(self, k, k + 4)  -- (a title is four words at most)
  if not (self.t[e] and self.t[e].text == ":" and e < #self.t and e - k <= 4 and self:commentary(k, e, true)) then
    return nil
  end
  for x = k, e - 1 do
    if self.t[x].kind == "word" and (RULES_BY_WORD[self.t[x].text] or self:airline_at(x)) then return nil end
  end
  return e
end

-- The comma or colon ending a lead-in clause at k that opens the request before the new aircraft it lists ("I'd
-- like a head-on pair, AEA10 B738 at ...": the creation rule read them so, G.opening_create); nil when none.
local function creation_label_end(self, k)
  local e = k
  while self.t[e] and self.t[e].kind ~= "punct" do e = e + 1 end
  if not (self.t[e] and (self.t[e].text == "," or self.t[e].text == ":")) then return nil end
  self:intent_at(e + 1)  -- (the creation rule, tried at any word, settles G.opening_create)
  return (self.opening_create or 0) > e and self:commentary(k, e) and e or nil
end

-- The full stop or colon ending an experiment's label that opens a sentence at k ("exp CDR-FR-ES, run 1.",
-- "Trial 3B:"; lexicon.aside.study_labels): label words, each followed by one to three identifiers (plain
-- numbers, words written with a capital or a digit; no aircraft, type or instruction word), commas
-- between, with more of the request after it; nil when there is none.
local CM_STUDY = set_of(COMMENTARY.study_labels)
local function study_label_end(self, k)
  local x = k
  while CM_STUDY[self.words[x] or ""] do
    local ids = 0
    x = x + 1
    while self.t[x] and self.t[x].kind ~= "punct" do
      local t = self.t[x]
      local id = t.kind == "number" or (t.kind == "word" and (t.raw:match("%u") or t.raw:match("%d")))
      if not id or ids == 3 or self:intent_at(x) or self:has_ref(x, x + 1, "aircraft")
          or self:has_ref(x, x + 1, "type") then
        return nil
      end
      ids, x = ids + 1, x + 1
    end
    local stop = self.t[x]
    if ids == 0 or not stop then return nil end
    if stop.text == "." or stop.text == ":" then
      for _, q in ipairs(self:quantities(k, x)) do
        if q.kind ~= "plain" then return nil end
      end
      return x < #self.t and x or nil
    end
    if stop.text ~= "," then return nil end
    x = x + 1
  end
  return nil
end

-- True when an instruction word or an aircraft is said after position e.
function G:instructed_after(e)
  for x = e + 1, #self.t do
    if self:intent_at(x) ~= nil or self:has_ref(x, x + 1, "aircraft") then return true end
  end
  return false
end

-- True when the sentence opening at k (or the clause after the comma at k - 1) tells the state of an aircraft
-- named by a pronoun, after an instruction (`instructed(k)`), to the end of its sentence ("They're both heading
-- east.", "It's at 220 right now, I think.", ", it's about to cross the FedEx's path"; lexicon.aside.state): its
-- subject and copula, adverbs, then a predicate; no wish, modal, correction, condition or sequence word in it
-- (state.blocks), no instruction word after the predicate's (but the verb of "about to") and the sentence ends the
-- request or with a full stop or "!". A question ("It's at 220 now?") or a clause going on to instruct ("it's at
-- 220, take it to 240") is none.
G.state_sets = {}
for key, words in pairs(lexicon.aside.state) do G.state_sets[key] = set_of(words) end
function G:state_sentence(k, instructed)
  local S = G.state_sets
  local e = commentary_end(self, k)
  local stop = self.t[e]
  if stop and not (stop.text == "." or stop.text == "!") then return false end
  local x = self:skip_fillers(k)
  -- (the lexer drops the copula of "it's" before a word it does not keep it for: "It heading east")
  if self:word(x, S.subjects) then x = x + 1
  elseif self:word(x, S.pronouns) and self:word(x + 1, S.copulas) then x = x + 2
  elseif self:word(x, "it he she") and self.t[x].raw:match("^%a+$") then x = x + 1
  else return false end
  while x < e and self:word(x, S.adverbs) do x = x + 1 end
  if x >= e or not self:word(x, S.predicates) or self:word_in(k, e, S.blocks) and not self:about_to(k, e) then
    return false
  end
  for y = x + 1, e - 1 do
    if self:intent_at(y) and not (self:word(y - 1, "to") and self:word(y - 2, "about")) then return false end
  end
  if not instructed(k) then return false end
  self.state_spans = self.state_spans or {}
  self.state_spans[#self.state_spans + 1] = { k, e - 1 }
  return true
end

-- The sentences that tell an aircraft's state (G:state_sentence) are set aside whole: their values, places and
-- aircraft are what is told, no command's.
function G:state_remarks()
  -- (only where a sentence or a clause after a comma opens with a pronoun subject: the reasons are found then)
  local S, opens = G.state_sets, false
  for k = 1, #self.t do
    if (k == 1 or self.t[k - 1].kind == "punct") and self.t[k].kind == "word" then
      local x = self:skip_fillers(k)
      opens = opens or self:word(x, S.subjects) or self:word(x, S.pronouns)
    end
  end
  if not opens then return end
  self:in_reason(1)
  for _, span in ipairs(self.state_spans or {}) do self:set_aside(span[1], span[2]) end
end

-- A state told of aircraft ref `r` (G:past_state, G:present_state): its words from `c` to before `e`, the values
-- `qs` in them. A value the aircraft neither flies nor was given (G.flies) is asked, never sent; told alone, with
-- nothing after it, the request has nothing to send (said so); otherwise the state is set aside (the aircraft's
-- name too where another aircraft is named after it, the one instructed). `tells` ("tells what %s is doing", %s the
-- callsign) and `same` ("which it does here") word the questions. True when it asked.
function G:told_state(r, c, e, qs, tells, same)
  local a, odd = self:state(r.name), nil
  for _, q in ipairs(qs) do
    local v = q.kind == "alt" and self:cleared_level(q) or q.value
    if not G.flies(a, q.kind, v) then odd = odd or q end
  end
  local said, name = self:raw(r.b, e), r.name:upper()
  if odd then
    self:need(string.format("'%s' " .. tells .. ": no instruction, but it flies otherwise here ('%s'). Should I change "
      .. "it? Please say it as an instruction.", said, name, self:raw(odd.b, odd.e)))
    return true
  end
  if r.b == self:skip_fillers(1, false) and (not self.t[e] or e == #self.t) then
    self:need(string.format("'%s' " .. tells .. ", " .. same .. ": nothing to change. What should it do?", said, name))
    return true
  end
  local other = false
  for _, o in ipairs(self.refs) do other = other or (o.kind == "aircraft" and o.b >= e and o.name ~= r.name) end
  self:set_aside(other and r.b or c, e - 1)
end

-- "KLM12 was at FL380 heading 140", "KLM12 was flying Mach 0.79 at FL390", "KLM12 was in level flight at FL380",
-- "KLM12 was on the downwind at 6000 feet, 200 knots": an existing aircraft, "was" or "were", a word of
-- G.past_state_sets.opens, then only words of G.past_state_sets.words and values (levels [ft or FL], speeds [kt
-- CAS], Mach, headings [deg]) to a mark or the end, tells the aircraft's state in a report, no instruction ("was
-- climbing to FL110" has "to": left to the instructions). When the aircraft flies or was given every value
-- (G.flies) the state is set aside and the instructions beside it are read alone; another value, or a value of
-- another kind, is asked, never sent.
G.past_state_sets = {
  opens = "at in flying cruising level levelled leveled steady established on",
  words = "at in on level flight flying cruising steady levelled leveled established the a downwind base final leg "
    .. "heading fl flight altitude feet ft foot knots knot kt kts cas ias mach speed and with of indicated" }
function G:past_state()
  if not self:said("was were") then return end
  local S = G.past_state_sets
  for _, r in ipairs(self.refs) do
    local c = r.e
    if r.kind == "aircraft" and r.exists and self:word(c, "was were") and self:word(c + 1, S.opens) then
      local e = c + 1
      while self.t[e] do
        local t = self.t[e]
        if t.kind == "number" or (t.kind == "word" and self:word(e, S.words)) then e = e + 1
        elseif t.text == "," and self.t[e + 1] and (self.t[e + 1].kind == "number"
            or self:word(e + 1, "fl flight heading mach speed at")) then
          e = e + 1
        else break end
      end
      local stop = self.t[e]
      local qs = self:quantities(c + 1, e)
      if (not stop or stop.kind == "punct") and #qs > 0 and not self:word_in(c + 1, e, "and") then
        if self:told_state(r, c, e, qs, "tells the state of %s in the report", "which it flies here") then return end
      end
    end
  end
end

-- "KLM12 is climbing FL300", "the KLM is now descending to flight level 200", "KLM12, it is turning left heading
-- 100", "KLM12 you are climbing FL300": an existing aircraft, a pronoun (it, he, she, you) or none, "is" or "are",
-- "now", "currently", "already" or "still" or none, a participle of G.present_state_sets.verbs, then only words of
-- G.present_state_sets.words and values (levels [ft or FL], speeds [kt CAS], Mach, headings [deg]) to a mark, the
-- end or "and" before an instruction, tells what the aircraft is doing, no instruction (the readback form "KLM12
-- climbing FL300", no copula, stays the clearance). When the aircraft flies or was given every value (G.flies) the
-- state is set aside and the instructions beside it are read alone; another value is asked, never sent.
G.present_state_sets = {
  verbs = "climbing descending turning flying maintaining cruising levelling leveling holding heading",
  words = "to through at left right heading fl flight level altitude feet ft foot knots knot kt kts mach speed "
    .. "degrees of and climbing descending turning flying maintaining cruising" }
function G:present_state()
  local S = G.present_state_sets
  -- ("KLM12's climbing FL300": the "'s" is gone from the words; read from the request as said)
  local clitic = (self.text_said or ""):lower():match("%w['\226\128\153]+s%s+(%a+)")
  -- ("set KLM12's heading to 110": "'s heading" is the possessive's noun, no state)
  if not clitic or clitic == "heading" or not (" " .. S.verbs .. " "):find(" " .. clitic .. " ", 1, true) then
    clitic = nil
  end
  if not clitic and not self:said("is are") then return end
  for _, r in ipairs(self.refs) do
    local c = r.e
    if self.t[c] and self.t[c].text == "," then c = c + 1 end
    if self:word(c, "it he she you") then c = c + 1 end
    local copula = self:word(c, "is are")
    if not copula and clitic and r.kind == "aircraft" and self.words[c] == clitic
        and not (self.text_said or ""):lower():find("that['\226\128\153]+s%s+" .. clitic) then
      c = c - 1
      copula = true
    end
    if r.kind == "aircraft" and r.exists and copula then
      local v = self:word(c + 1, "now currently already still") and c + 2 or c + 1
      if self:word(v, S.verbs) then
        local e = v + 1
        while self.t[e] do
          local t = self.t[e]
          -- ("... and turn left heading 100": "and" before a word of no state ends the state)
          if self:word(e, "and") and not self:word(e + 1, S.verbs) then break end
          if t.kind == "number" or (t.kind == "word" and (self:word(e, S.words) or t.number_word)) then e = e + 1
          else break end
        end
        local stop = self.t[e]
        local qs = self:quantities(v + 1, e)
        if (not stop or stop.kind == "punct" or self:word(e, "and")) and #qs > 0 then
          if self:told_state(r, c, e, qs, "tells what %s is doing", "which it does here") then return end
        end
      end
    end
  end
end

-- "what was the separation between KLM12 and AFR34 at that point?", "what's the lateral distance between KLM12 and
-- AFR34", "how far apart were KLM12 and AFR34?", "closest point of approach between KLM12 and AFR34": a question
-- about how far apart two existing aircraft are (a word of G.pair_question_sets.about), the two joined by "and"
-- (after "between", or after "were"/"are"), every other word one of G.pair_question_sets.words, no value: their
-- positions (POS of each, in the order said); nil when the request is anything else.
G.pair_question_sets = {
  about = "separation separated distance spacing apart cpa approach",
  words = "what what's whats how was were is are the vertical lateral horizontal separation separated distance "
    .. "spacing closest point of approach cpa minimum between and at that this point moment time then now right far "
    .. "apart please 's did they get close by show tell me give"
}
function G:pair_question()
  local P = G.pair_question_sets
  if not self:said(P.about) or #self:quantities(1, #self.t + 1) > 0 then return nil end
  local pair = {}
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" then
      if not r.exists then return nil end
      pair[#pair + 1] = r
    elseif r.kind ~= "airline" then
      return nil
    end
  end
  if #pair ~= 2 or pair[1].name == pair[2].name or not self:word(pair[1].e, "and") or pair[2].b ~= pair[1].e + 1
      or not self:word(pair[1].b - 1, "between were are") then
    return nil
  end
  local question = self:word(self:skip_fillers(1, false), "what what's whats how show tell give")
  for k = 1, #self.t do
    local t = self.t[k]
    local inside = (k >= pair[1].b and k < pair[1].e) or (k >= pair[2].b and k < pair[2].e)
    if t.text == "?" then question = true end
    if not inside and t.kind ~= "punct" and not t.filler and not self:word(k, P.words) then return nil end
  end
  if not question then return nil end
  self:mark_used(1, #self.t + 1)
  return { "POS " .. pair[1].name:upper(), "POS " .. pair[2].name:upper() }
end

-- True when the only word of lexicon.aside.state.blocks in tokens b .. e - 1 is the "to" of "about to".
function G:about_to(b, e)
  for y = b, e - 1 do
    if self:word(y, G.state_sets.blocks) and not (self:word(y, "to") and self:word(y - 1, "about")) then
      return false
    end
  end
  return true
end

-- True when the sentence opening at k is a remark beside the sentences that instruct: it ends the
-- request or with a full stop or "!" (a question may ask for something, a colon labels what follows),
-- something is instructed before it (`instructed(k)`) or after it, and it is commentary with no aircraft
-- in it (no value, place, aircraft or instruction word).
function G:remark_sentence(k, instructed)
  local e = commentary_end(self, k)
  local stop = self.t[e]
  -- (a question to the audience, one of commentary.audience in it, asks nothing of squawk)
  local asked = stop and stop.text == "?" and self:word_in(k, e, COMMENTARY.audience_set)
  if (stop and not (stop.text == "." or stop.text == "!" or asked)) or self:has_ref(k, e, "aircraft") then return false end
  return (instructed(k) or self:instructed_after(e)) and self:commentary(k, e)
end

COMMENTARY.decl = {}
for key, words in pairs(COMMENTARY.declared) do COMMENTARY.decl[key] = set_of(words) end

-- The position after an apology opening the span b .. e-1 ("sorry", "I am sorry", "I'm sorry", "apologies", then
-- "to" and one of declared.apology_verbs with "you", then a comma: "Sorry to disturb,"), or b when none opens it.
function G:apology_end(b, e)
  local x = b
  if self:word(x, "i'm") and self:word(x + 1, "sorry") then x = x + 1
  elseif self:word(x, "i") and self:word(x + 1, "am") and self:word(x + 2, "sorry") then x = x + 2 end
  if not self:word(x, COMMENTARY.decl.apologies) then return b end
  x = x + 1
  if self:word(x, "to") and self:word(x + 1, COMMENTARY.decl.apology_verbs) then x = x + (self:word(x + 2, "you") and 3 or 2) end
  if x < e and self.t[x].text == "," then x = x + 1 end
  return x
end

-- True when the instruction word at y is the noun a copula predicates ("it is noise", "that's only turbulence",
-- "it's just noise for this run"): a copula right before it or with one of lexicon's declared.predicate_adverbs
-- between, or after a subject whose copula the lexer dropped ("it" of "it's") with such an adverb between or with
-- a word in no verb's third-person or past form ("he climbs too steep" is told with its verb).
function G:predicate_noun(y)
  local D = COMMENTARY.decl
  if self:word(y - 1, D.copulas) then return true end
  if self:word(y - 1, D.predicate_adverbs) then
    return self:word(y - 2, D.copulas) or self:word(y - 2, D.copular_subjects)
  end
  local w = self.t[y].raw:lower()
  return self:word(y - 1, D.copular_subjects) and not (w:match("[^s]s$") or w:match("ed$"))
end

-- True when the tokens b .. e-1 are a remark in the declarative shape (lexicon.aside.declared): a subject before
-- its verb, no aircraft, place or value (but a count of aircraft or a label's number, G:commentary), no
-- instruction word but a noun or a past form, none beside a wish or a modal, and none of declared.blocks or of
-- lexicon.correction: told of the run, the experiment or the speaker, it instructs nothing.
function G:declared(b, e)
  local x = b
  while x < e and self:word(x, COMMENTARY.decl.openers) do x = x + 1 end
  if x >= e or self:has_ref(b, e, "aircraft") then return false end
  -- ("..., if there is no conflict", "if the traffic is clear, ...": "if", "unless" or "provided" before a subject
  -- other than the speaker or listener, with a word of the traffic (G.traffic_condition_words) in its clause, opens a
  -- condition on the traffic, no remark; "if I remember correctly", "if the weather allows", "sorry if that is too
  -- low for it" are none)
  local cond = self:word(x, "provided providing unless") and x + 1 < e and x + 1
    or self:word_in(b, x, "if") and not self:word(b - 1, "sorry") and x
  if cond and not self:word(cond, "i we you i'm we're you're i've we've")
      and self:word_in(cond, e, G.traffic_condition_words) then
    return false
  end
  if self:word(x, COMMENTARY.decl.frames) and self:word(x + 1, COMMENTARY.decl.possessives) then
    -- ("In my thesis we use a smaller one": the frame, then its own subject)
    x = self:find_word(x + 2, e, COMMENTARY.decl.subjects)
    if x >= e then return false end
  end
  -- (an instruction word in the subject before a copula is a noun only in a remark on the study: "Real time is a bit
  -- slow for my supervisor's patience")
  local subject = x
  if G.study_subject(self, x) then
    -- ("the participant made a mistake when creating it": a person of the study as the subject, its verb next)
    subject = x + 2
  elseif not self:word(x, COMMENTARY.decl.subjects) then
    subject = self:find_word(x + 1, e, COMMENTARY.decl.copulas)
    if subject >= e then return false end
    if not self:word_in(b, e, COMMENTARY.decl.study) then subject = x end
  end
  for _, q in ipairs(self:quantities(b, e)) do
    if not ((q.b > b and self:aircraft_count(q)) or self:label_number(q)) then return false end
  end
  for _, r in ipairs(self:refs_in(b, e, "waypoint")) do
    if not self:word(r.b, "@not_names") then return false end
  end
  local wished, instructs = self:word_in(b, e, COMMENTARY.decl.requests), false
  -- (a name in capitals may be a place, "It is going to Jakarta", "so Stuttgart is its destination"; opening the
  -- remark, a word squawk knows is no name: only a belief told with no instruction word names one, "Then it heads
  -- towards Utrecht, I believe")
  local believed, named = self:word_in(b, e, COMMENTARY.decl.believed), false
  for y = b, e - 1 do
    local t = self.t[y]
    if self.noted[y] then return false end
    named = named or (t.kind == "word" and t.raw:match("^%u") ~= nil and (y > b or not KNOWN[t.text])
      and not self:word(y, COMMENTARY.decl.subjects))
    if t.kind == "word" then
      local last = y == e - 1 or self.t[y + 1].kind == "punct"
      if COMMENTARY.decl.blocks[t.text] or self:word(y, "@correction") or (last and t.text == "too")
          or (t.text == "no" and (self:word(y + 1, "wait") or (self.t[y + 1] or t).kind == "punct")) then
        return false
      end
      if self:intent_at(y) then
        local noun = self:word(y - 1, COMMENTARY.decl.nouns_after) or self:word(y - 2, COMMENTARY.decl.nouns_after)
          or self:predicate_noun(y)
        local past = t.raw:lower():match("[^e]ed$") ~= nil and not self:word(y - 1, "to")
        -- (what a question word opens is what is studied or told, "a test of how the geometry affects detection";
        -- a habit told is no instruction, "long-haul aircraft usually fly faster")
        local told = self:word_in(b, y, COMMENTARY.decl.told)
        if not (noun or past or told or y < subject or self:creation_judged(b, y)) then return false end
        instructs = true
      end
    end
  end
  return not (wished and instructs) and not (named and (instructs or not believed))
end

-- "delete SpiceJet 403 and recreate it at ...", "..., re-create it at ...": "recreate" or "re-create" said after
-- "and" or a comma straight before "it" is "create it again" (read by the creation as the aircraft deleted,
-- handlers_other m:recreated); anywhere else ("we'll re-create it later") left as said.
function G.recreate_said(text)
  if not text:lower():find("creat", 1, true) then return text end
  return (text:gsub("([,;]%s*)[Rr][Ee]%-?[Cc][Rr][Ee][Aa][Tt][Ee](%s+[Ii][Tt]%f[%A])", "%1create%2 again")
    :gsub("(%f[%a][Aa][Nn][Dd]%s+)[Rr][Ee]%-?[Cc][Rr][Ee][Aa][Tt][Ee](%s+[Ii][Tt]%f[%A])", "%1create%2 again"))
end

-- True when tokens x, x + 1 are "the", "my" or "our" and a person of the study (lexicon declared.study_people:
-- "the participant", "my supervisor"), a verb in the past after them ("made", "-ed"): a remark's subject.
function G.study_subject(self, x)
  if not (self:word(x, "the my our") and self:word(x + 1, COMMENTARY.decl.study_people)) then return false end
  local v = self.t[x + 2]
  return v ~= nil and v.kind == "word" and (v.raw:lower():match("ed$") ~= nil or self:word(x + 2, COMMENTARY.decl.past_verbs))
end

-- True when the instruction word at y of a remark opened at b is the creating of the aircraft the request is
-- about, judged a slip: a form of "create" ("to create it", "when creating it", "to make it") straight before
-- "it" that closes the clause, after a word of lexicon.self_correction.judged in the remark ("it was my mistake to
-- create it", "I made an error when creating it"): why the aircraft goes, no creation.
function G:creation_judged(b, y)
  local raw = self.t[y].raw:lower()
  if not (raw:match("^creat") or raw:match("^re%-?creat")) or not self:word(y + 1, "it") then return false end
  local after = self.t[y + 2]
  if after and after.kind ~= "punct" then return false end
  for x = b, y - 1 do
    if G.judged[self.words[x]] then return true end
  end
  return false
end

-- True when the clause opening at b (to its next comma or its sentence's end) tells a state beside the request: a
-- remark in the declarative shape (G:declared) whose subject is a noun phrase opened by one of
-- declared.nouns_after before its copula ("the detection is on anyway", "the traffic trails are on already", "in my
-- experiment the noise is off", a frame and its possessive first: "the zone is not active yet"; a switch's state
-- only with the frame or one of declared.state_told), or the predicate whose copula was dropped, one of
-- declared.predicate_adverbs then one of declared.judgements ("just noise", "only noise in the background"). The
-- setting or instruction words in it are nouns of what is told, never switched or sent.
function G:state_remark(b)
  local D = COMMENTARY.decl
  local e = commentary_end(self, b)
  local comma = b
  while comma < e and self.t[comma].text ~= "," do comma = comma + 1 end
  local function instruction(y) local i = self:intent_at(y) return i ~= nil and i ~= false end
  local x = b
  local framed = self:word(x, D.frames) and self:word(x + 1, D.possessives)
  if framed then x = x + 3 end
  if x >= comma or #self:quantities(b, comma) > 0 or self:has_ref(b, comma, "aircraft") then return false end
  if self:word(x, D.predicate_adverbs) then
    return self:word(x + 1, D.judgements) and instruction(x + 1) and not self:word_in(x + 2, comma, "@on @off")
  end
  local copula = self:find_word(x + 1, comma, D.copulas)
  if not (self:word(x, D.nouns_after) and copula < comma and self:declared(x, comma)) then return false end
  -- (a switch's state with no frame or told adverb may be wished: "..., the trails are on" stays read)
  if self:word_in(copula, comma, "@on @off") and not (framed or self:state_told(x, comma)) then
    return false
  end
  for y = x + 1, copula - 1 do
    if instruction(y) then return true end
  end
  return false
end

-- True when tokens b .. e - 1 tell a state, never wish it: a word of declared.state_told ("already", "anyway",
-- "btw"), "by the way", or a copula in the past (declared.past_copulas: "the trails were on").
function G:state_told(b, e)
  local D = COMMENTARY.decl
  if self:word_in(b, e, D.state_told) or self:word_in(b, e, D.past_copulas) then return true end
  for x = b, e - 3 do
    if self:word(x, "by") and self:word(x + 1, "the") and self:word(x + 2, "way") then return true end
  end
  return false
end

-- "the traffic trails are on already", "seed was 3 by the way", "the simulation was paused anyway": a clause (to its
-- mark) with a copula of declared.copulas that tells a state (G:state_told), a word of a setting's intent
-- (declared.settings) as its subject or state, and no aircraft and no wish or modal (declared.requests) in it, not
-- set aside as a remark beside an instruction (G:state_remark), tells how the simulation is or was: asked, never
-- set. Read: "the trails are on" (it may be wished), "trails on", "set the seed to 3".
function G:told_setting()
  local D = COMMENTARY.decl
  if not self:said(D.copulas) then return end
  local b = 1
  for k = 1, #self.t + 1 do
    local t = self.t[k]
    if not t or t.kind == "punct" then
      local copula = self:find_word(b, k, D.copulas)
      -- (its subject before the copula, or a question in the past, "was the seed 3?": "is the resolution still MVP?"
      -- asks for the setting)
      local opens = copula > self:skip_fillers(b) or self:word(copula, D.past_copulas)
      if copula < k and opens and self:state_told(b, k) and not self:word_in(b, k, D.requests)
          and not self:has_ref(b, k, "aircraft") then
        -- (the setting's word is the copula's subject or after it: "the traffic trails are on", "the simulation
        -- was paused", "the sim is already running at 4x"; "speed it up while the aircraft are still apart" tells no
        -- setting's state)
        local told = self:rate_told(b, k)
        for x = math.max(b, copula - 3), k - 1 do
          told = told or D.settings[self:intent_at(x) or ""] and not self:in_reason(x)
        end
        if told then
          return self:need(string.format("'%s' tells how the simulation is or was, no instruction. Should I "
            .. "change anything? Please say it as an instruction.", self:raw(b, k)))
        end
      end
      b = k + 1
    end
  end
end

-- A waypoint said loosely (lexicon.place_hedges: "once it passes RAGID or so", "roughly at RAGID") that a command
-- of self.out runs at or meets ("AT id WPT ..."): the condition would hold exactly there, so it is asked.
local PLACE_HEDGES = {}
for k, list in pairs(lexicon.place_hedges) do PLACE_HEDGES[k] = table.concat(list, " ") end
function G:hedged_place()
  local H = PLACE_HEDGES
  for _, r in ipairs(self.refs) do
    local x = r.b - (self:word(r.b - 1, "at") and 2 or 1)
    local b = self:word(x, H.before) and x or r.b
    local e = (self:word(r.e, H.after) and r.e + 1)
      or (self:word(r.e, "or") and self:word(r.e + 1, H.after_or) and r.e + 2) or r.e
    if r.kind == "waypoint" and r.name and (b < r.b or e > r.e) then
      for _, c in ipairs(self.out) do
        if c:match("^AT %S+ (%S+) ") == r.name:upper() then
          self.ask = string.format("I have %s, run exactly at %s, but you said '%s'. Should it happen at %s, or "
            .. "where?", c, r.name:upper(), self:raw(b, e), r.name:upper())
          return
        end
      end
    end
  end
end

-- An aircraft matched by a callsign whose airline was said with more words than the matcher read ("lufthansa
-- cityline 400" matched to DLH400: "lufthansa cityline" names CLH, Lufthansa CityLine): the longest airline name
-- (G.airline_name_codes, up to three words) opening the reference names another airline than the aircraft's, so
-- a word of it was dropped: asked, never sent to the aircraft of the shorter name. A brand said after the airline's
-- whole name ("british airways cityflyer 31") is read the same way.
-- True when airline name `name` (lower case) is a telephony, common name or brand of the airline of ICAO
-- designator `code` in names.airlines, names.common or names.brands.
function G.name_flies_for(name, code)
  if not G.name_codes_all then
    G.name_codes_all = {}
    for _, list in ipairs({ names.airlines, names.common, names.brands }) do
      for _, a in ipairs(list) do
        local set = G.name_codes_all[a[1]] or {}
        for j = 2, #a do set[a[j]] = true end
        G.name_codes_all[a[1]] = set
      end
    end
  end
  return (G.name_codes_all[name] or {})[code] ~= nil
end

function G:airline_word_dropped()
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" and r.exists and not r.heard then
      -- (only where a shorter name of the same words is the aircraft's airline, "lufthansa": a brand family's
      -- name matched to another of its airlines, "Transavia" TVF, is the matcher's)
      local own, code, seen = r.name:upper():match("^(%u%u%u)%d"), nil, false
      local b = own and r.b or r.e
      -- (a letter or digit said is the flight number's: "Ryanair seven delta whiskey")
      while b < r.e and not code and not (lexicon.phonetic[self.words[b] or ""] or self.t[b].number_word) do
        local found, name, last = nil, nil, b
        local found_name
        for k = b, math.min(b + 2, r.e - 1) do
          if not self.words[k] then break end
          name = name and name .. " " .. self.words[k] or self.words[k]
          if G.airline_name_codes[name] then found, last, found_name = G.airline_name_codes[name], k, name end
          seen = seen or G.airline_name_codes[name] == own
        end
        if found ~= own then code = found end
        -- (the reference opening with a name that no table gives the aircraft's airline, "cityhopper 400" or
        -- "tui 400" matched to DLH400: the matcher read the flight number alone, the airline said dropped)
        -- (only where the flight number follows the name: "Thai Asia 3102" is a telephony the matcher knows)
        local nx = self.t[last + 1]
        local number = nx and (nx.number_word or (self.words[last + 1] or ""):match("^%d")) and true or false
        if code and b == r.b and number and not G.name_flies_for(found_name, own) then seen = true end
        if not found then break end  -- (a name squawk's tables do not hold, "Nor Shuttle": the matcher's)
        b = last + 1
      end
      if code and seen then
        self.ask = string.format("Which aircraft is '%s'? It names %s, an airline other than %s's. Please give its "
          .. "callsign.", self:raw(r.b, r.e), code, r.name:upper())
        return
      end
    end
  end
end

-- True when tokens b .. e - 1 name the simulation's rate by its value alone, a multiplier ("4x", "x4") outside a
-- remark with no instruction word anywhere in them: "the sim is already running at 4x" tells the rate (DTMULT).
function G:rate_told(b, e)
  local rate = false
  for _, q in ipairs(self:quantities(b, e)) do rate = rate or (q.kind == "mult" and not self:in_reason(q.b)) end
  if not rate then return false end
  for x = b, e - 1 do
    if self:intent_at(x) then return false end
  end
  return true
end

-- True when the sentence opening at k is a remark in the declarative shape (G:declared), or opened by an apology
-- ("Sorry, my supervisor is calling me."): it ends the request or with a full stop or "!", and an instruction,
-- aircraft or value is said before it or an instruction or aircraft after it. An apology alone ("Sorry!") is one
-- only after a correction said before it ("one two zero? No wait, one three zero. Sorry!") or before more of the
-- request: closing the request after an instruction, it may announce a correction never said (asked,
-- G:dangling_correction).
function G:declared_remark(k, instructed)
  local e = commentary_end(self, k)
  local stop = self.t[e]
  if stop and not (stop.text == "." or stop.text == "!") then return false end
  local b = self:apology_end(k, e)
  local alone = b > k and b == e
  if not (alone or self:declared(b, e)) then return false end  -- (the shape first: it rules out most sentences)
  local after = self:instructed_after(e)
  if not (after or instructed(k) or self:has_ref(1, k, "aircraft") or #self:quantities(1, k) > 0) then return false end
  return not alone or after or self:word_in(1, k, "@correction") or self:word_in(1, k, SC_MARKERS)
end

-- The end of the remark in the declarative shape (G:declared) that the clause opening at b is, up to its next comma
-- or else to the end of its sentence (commentary_end); nil when it is none.
function G:declared_clause(b)
  self.declared_memo = self.declared_memo or {}
  local memo = self.declared_memo[b]
  if memo ~= nil then return memo or nil end
  local e = commentary_end(self, b)
  local comma = b
  while comma < e and self.t[comma].text ~= "," do comma = comma + 1 end
  memo = false
  for _, stop in ipairs({ comma, e }) do
    if not memo and self:declared(self:apology_end(b, stop), stop) then memo = stop end
  end
  self.declared_memo[b] = memo
  return memo or nil
end

-- The comma ending an apology that opens the request at k ("Sorry to trouble you, could you ...", "Sorry to
-- disturb, may I see ..."): an apology with its verb, nothing else before the comma; nil when none.
function G:apology_lead_end(k)
  local b = self:apology_end(k, #self.t + 1)
  if b > k and self.t[b - 1].text == "," and self:word_in(k, b, COMMENTARY.decl.apology_verbs) then
    return b - 1
  end
  return nil
end

-- True when the colon at k follows "note" or "comment" opening the request and one sentence runs from it to
-- the end ("note: run 3, seed 42, baseline no reso"): the note is the request, text for the log (ECHO),
-- no remark beside an instruction
local function whole_note(self, k)
  if k - 1 ~= self:skip_fillers(1) or not self:word(k - 1, "note comment") or k >= #self.t then return false end
  for x = k + 1, #self.t - 1 do
    local t = self.t[x]
    if t.kind == "punct" and t.text ~= "," and t.text ~= ":" then return false end
  end
  return true
end

-- True when the relative clause at k tells what was done before ("at which it was paused", "where it was
-- stopped", "when the first alert was generated"): one of lexicon.past_relatives, one of past_verbs within four
-- words, then no value, aircraft or instruction word up to the clause's end but the participle right after the
-- past verb.
function G:past_told(k)
  if not self:word(k, "@past_relatives") then return false end
  local p = self:find_word(k + 1, k + 5, "@past_verbs")
  local e = commentary_end(self, k + 1)
  if p >= k + 5 or #self:quantities(k + 1, e) > 0 or self:has_ref(k + 1, e, "aircraft") then return false end
  for x = p + 2, e - 1 do
    if self:intent_at(x) then return false end
  end
  return true
end

-- True when the comma at k ends a diversion ("divert IAH, wx at DFW", "divert to DXB, DOH closed", "send it to
-- MUC instead, crew sick"): the last instruction word before it in its sentence is "divert", "diverting" or
-- "send" read as a destination, and the clause after it, to the sentence's end, holds no instruction word,
-- aircraft or value, opens with none of lexicon.diversion_not_reason and holds a word beside its places: why the
-- aircraft diverts (a place named in it is no second destination).
function G:diversion_reason(k)
  if not self:said("divert diverting send") then return false end  -- (no diversion word said: no walk back)
  local x = k - 1
  while x > 0 and not (self.t[x].kind == "punct" and self.t[x].text ~= ",") and not self:intent_at(x) do x = x - 1 end
  if x < 1 or self:intent_at(x) ~= "dest" or not self:word(x, "divert diverting send") then return false end
  local e = commentary_end(self, k + 1)
  if e == k + 1 or self:word(k + 1, "@diversion_not_reason") or #self:quantities(k + 1, e) > 0
      or self:has_ref(k + 1, e, "aircraft") then
    return false
  end
  local words = 0  -- (words beside the places: a place alone, "Send UPS2971 to Louisville, KSDF", names it again)
  for y = k + 1, e - 1 do
    if self:intent_at(y) then return false end
    if self.t[y].kind == "word" and not self:has_ref(y, y + 1, "waypoint") then words = words + 1 end
  end
  return words > 0
end

-- True when the "but" at k opens a clause of its own that contrasts with what was said before it ("sorry to be a
-- pain, but the Dash 8 should climb", "sorry but the Lufthansa ..."): after a mark, an apology (declared.apologies) or
-- at the request's start, fillers between. "all but the Lufthansa" excepts the aircraft after it.
function G:contrastive_but(k)
  if not self:word(k, "but") then return false end
  local p = k - 1
  while p >= 1 and self.t[p].filler do p = p - 1 end
  return p < 1 or self.t[p].kind == "punct" or self:word(p, COMMENTARY.decl.apologies)
end
-- True when the word at k, before an aircraft described ("the Lufthansa", "the Dash 8", "the lower one"), makes it
-- other traffic, never the aircraft instructed: a word of lexicon.airline_context, aircraft_context, below or above
-- ("too close to the Lufthansa", "above the Dash 8"), a contrastive "but" (G:contrastive_but) excepted.
function G:other_traffic_before(k)
  return self:word(k, "@airline_context @aircraft_context @below @above") and not self:contrastive_but(k)
end

local REASON_WORDS = word_set("@reason")
function G:in_reason(i)
  if not self.reason then
    -- reason[i]: the nearest of a reason word (or a purpose, G:purpose) and a sentence break before
    -- i is the reason word
    self.reason = {}
    local inside = false
    -- intents[x]: self:intent_at(x) or false, asked once while the spans are found (nothing here marks
    -- a word used)
    local intents = {}
    -- true when an instruction word is said before k, outside a reason (asked only where an aside may open)
    local function instructed(k)
      for x = 1, k - 1 do
        if not self.reason[x] then
          local intent = intents[x]
          if intent == nil then
            intent = self:intent_at(x) or false
            intents[x] = intent
          end
          if intent then return true end
        end
      end
      return false
    end
    local commas = 0          -- the commas up to k (self.apart: those that were a dash or a bracket)
    local lead_end            -- the comma that ends a lead-in ("For the overtake case, ...")
    local toks, reason = self.t, self.reason
    local opening = self:skip_fillers(1)  -- (the request's first word)
    local relative_said = self:said("@past_relatives")  -- (G:past_told opens on one)
    for k = 1, #toks do
      reason[k] = inside
      local t = toks[k]
      local w = self.words[k]  -- (false for punctuation and numbers)
      local punct = t.kind == "punct"
      local start = k == 1 or (toks[k - 1].kind == "punct" and toks[k - 1].text ~= ",")
      if punct and t.text == "," then commas = commas + 1 end
      if punct and t.text == ":" and self:word(k - 1, CM_LABELS) and not whole_note(self, k) then
        -- ("descend to FL100, reason: lose the vertical overlap with TOM6RT": to the end of the sentence)
        inside, reason[k - 1] = true, true
      elseif punct and t.text == "," and (self.apart or {})[commas] and instructed(k)
          and not self:word(k + 1, "no wait sorry actually correction")
          and self:commentary(k + 1, commentary_end(self, k + 1)) then
        -- ("left 70 degrees - hard test of the turn model", "800 ft (testing reduced vertical)"; "to Heathrow -
        -- no, hang on, sorry, to Stansted" opens a correction, never set apart)
        inside = true
      elseif punct and (t.text == "," or t.text == ";")
          and (self:word(k + 1, CM_SUBJECTS) or self:hedge_opens(k + 1, commentary_end(self, k + 1))) and instructed(k)
          and self:commentary(k + 1, commentary_end(self, k + 1)) then
        -- ("Fast-forward 20 minutes, we only care about the descent phase"; "...; we are studying how ...";
        -- ", not sure which way is shorter": the speaker's hedge, G:hedge_opens)
        inside = true
      elseif punct and (t.text == "," or t.text == ";")
          and self:word_in(k + 1, commentary_end(self, k + 1), COMMENTARY.reason_set)
          and not self:word_in(k + 1, commentary_end(self, k + 1), "from")
          and (instructed(k) or #self:quantities(1, k) > 0)
          and self:commentary(k + 1, commentary_end(self, k + 1), false, false, true) then
        -- ("reduce 260, sequencing into DXB", "slow to 210, DFW metering", "left 110 degrees; we need him well out
        -- of the way of the BIG stack": the operational reason, its place too;
        -- "inbound from Vigo" names where the aircraft comes from, no reason)
        inside = true
      elseif punct and (t.text == "," or t.text == ";") and instructed(k) and self:state_remark(k + 1) then
        -- ("turn right heading 180, the detection is on anyway", "delete the cessna, just noise": the state told)
        inside = true
      elseif punct and t.text == "," and self:word(k + 1, "@aside_comments") and instructed(k)
          and not self:has_ref(k + 1, commentary_end(self, k + 1), "aircraft")
          and self:commentary(k + 1, commentary_end(self, k + 1), false, true) then
        -- ("Descend KLM12 to FL120, as the transcript shows", ", which is what the controller ought to have done",
        -- ", as the controller did at 10:42:15")
        inside = true
      elseif w == "according" and self:word(k + 1, "to") and not start and (instructed(k) or #self:quantities(1, k) > 0)
          and self:commentary(k, commentary_end(self, k), false, true) then
        -- ("... at FL150 over CASAR according to the letter of agreement": the source of the instruction, no comma
        -- before it)
        inside, reason[k] = true, true
      elseif punct and t.text == "," and self:word(k + 1, COMMENTARY.restate_set) and self:restates(k + 1) then
        -- (", give him a proper vector off": the turn said before it, described again)
        inside = true
      elseif ((w == "then" and self:word(k + 1, "@condition")) or (punct and t.text == "," and self:word(k + 1, "@condition")))
          and instructed(k) and self:intention_after(k + 1) then
        -- (", then when clear of BAW87 I'll send him back": what the speaker will do later, nothing now)
        inside, reason[k] = true, reason[k] or w == "then"
      elseif punct and t.text == "," and self:diversion_reason(k) then
        inside = true
      elseif not start and relative_said and self:past_told(k) then
        -- ("resume the simulation from the point at which it was paused": the past told, nothing instructed)
        inside, reason[k] = true, true
      elseif ((w and CM_WHILE[w] and self:word(k + 1, CM_OWN))
          or (punct and t.text == "," and self:word(k + 1, CM_OWN)
              and self:word_in(k + 2, commentary_end(self, k + 1), CM_LATER)))
          and #self:quantities(k + 1, commentary_end(self, k + 1)) == 0 and instructed(k) then
        -- ("pause the sim while I reset the eye tracker", ", we'll put it back on the route later")
        inside = true
      elseif start and t.kind == "word" and study_label_end(self, k) then
        -- ("exp CDR-FR-ES, run 1. cre AFR1234 ...": an experiment's label, up to its full stop or colon)
        inside, reason[k] = true, true
      elseif k == opening and t.kind == "word" and creation_label_end(self, k) then
        -- ("I'd like a head-on pair, AEA10 B738 at ...")
        inside, lead_end, self.reason[k] = true, creation_label_end(self, k), true
      elseif k == opening and t.kind == "word" and not (CM_LEADS[t.text] or CM_LABELS[t.text])
          and title_end(self, k) then
        -- ("converging pair please: KLM401 B738 at ...": a title opening the request, up to its colon)
        inside, lead_end, self.reason[k] = true, title_end(self, k), true
      elseif start and t.kind == "word" and (CM_LEADS[t.text] or CM_LABELS[t.text]) then
        -- ("For the vertical test: NAX3412 climb ...", "To create a same-level encounter: SAS1410 climb
        -- FL190", "For the overtake case, EZY45 speed 320": a lead-in before a colon, or a comma after
        -- "for" or "to", with no aircraft, value or place, its "to" verb aside)
        local e = k + 1
        while self.t[e] and self.t[e].kind ~= "punct" do e = e + 1 end
        if not (self.t[e] and self.t[e].text == "," and CM_LEADS[t.text]) then e = commentary_end(self, k + 1) end
        local lead = self.t[e] and (self.t[e].text == ":" or self.t[e].text == ",") and not self:has_ref(k, e, "aircraft")
        if lead then
          inside = self:commentary(k, e, true) or (t.text == "to" and self:commentary(k + 2, e, true))
          lead_end = inside and e or nil
        end
      elseif (w == "then" and (self:word(k + 1, "i'll we'll") or self:word(k + 1, "i we") and self:word(k + 2, "@own_modals"))
              and self:commentary(k + 1, commentary_end(self, k + 1))
            or w == "for" and self:word(k + 1, "when") and self:word(k + 2, CM_OWN)
              and self:commentary(k + 2, commentary_end(self, k + 2))) and instructed(k) then
        -- ("fast forward 60 sec then I'll hand over to the pseudo pilot", "... 3 times faster? Then we can see the
        -- conflict develop", "set the sim rate to 5 for when we restart": the experimenter's own doing after the
        -- instruction, or when it is for)
        inside, reason[k] = true, true
      elseif (start or punct and t.text == ",") and self:state_sentence(punct and k + 1 or k, instructed) then
        -- ("Could the Lufthansa and the JetBlue both climb to FL310? They're both heading east.": the state told)
        inside, reason[k] = true, true
      elseif start and t.kind == "word" and self:remark_sentence(k, instructed) then
        -- ("... 290 knots. First arrival of batch B.", "Let's start with the baseline pair. SAS1A A320 ..."
        inside, reason[k] = true, true
      elseif start and t.kind == "word" and self:declared_remark(k, instructed) then
        -- ("Could you please pause? Sorry, my supervisor is calling me.", "... FL140. I created it a bit too low.")
        inside, reason[k] = true, true
      elseif k == opening and t.kind == "word" and self:apology_lead_end(k) then
        -- ("Sorry to disturb, may I see the route of ...")
        inside, lead_end, reason[k] = true, self:apology_lead_end(k), true
      elseif k == opening and t.kind == "word" and self:declared_clause(k) and self.t[self:declared_clause(k)]
          and self.t[self:declared_clause(k)].text == "," and self:instructed_after(self:declared_clause(k)) then
        -- ("ok so this is the minneapolis one, can we run it at 2x": the remark opening the request, to its comma)
        inside, lead_end, reason[k] = true, self:declared_clause(k), true
      elseif punct and (t.text == "," or t.text == ";") and not self:word(k - 1, "no @correction")
          and (self:word(k + 1, COMMENTARY.decl.subjects) or self:word(k + 1, COMMENTARY.decl.openers)
            or G.study_subject(self, k + 1)
            or self:apology_end(k + 1, #self.t + 1) > k + 1)
          and self:declared_clause(k + 1) and (instructed(k) or self:has_ref(1, k, "aircraft")
            or self:instructed_after(self:declared_clause(k + 1))) then
        -- ("Please delete the Hongkong Shuttle flight, I created it by mistake", "climb back to FL120 please, sorry I
        -- descended it by mistake", "..., sorry I know it is not simulated, maybe just descend to 2000 feet")
        inside = true
        local stop = self.t[self:declared_clause(k + 1)]
        if stop and stop.text == "," then lead_end = self:declared_clause(k + 1) end
      elseif k == lead_end then
        inside = false
      elseif punct and t.text ~= "," then
        inside = false
      elseif self:purpose(k) then
        inside = true
      elseif w == "for" and self:for_airport(k) then
        -- ("descend to 6000 feet for Borg El Arab": the airport the value is for, to its end)
        inside, lead_end, reason[k] = true, self:for_airport(k), true
      elseif w == "before" and (instructed(k) or #self:quantities(1, k) > 0) and self:deadline_clause(k) then
        -- ("climb FL340 before it reaches the boundary", "I'd like AFR1234 at FL340 before the boundary":
        -- lexicon.deadline_places)
        inside, reason[k] = true, true
      elseif punct and self:word(k + 1, "@then_words") then
        -- (", then ..." ends the reason: "up to FL320 so it conflicts with TRA6021, then ff 1 min")
        inside = false
      elseif (w and REASON_WORDS[w])
          -- ("ok so the clock is running slow, go 2x": "so" opening the request, with only fillers before it,
          -- gives the reason for nothing said)
          or (w == "so" and self:word(k + 1, "@reason_after_so") and self:skip_fillers(1) < k)
          or (w == "see" and self:word(k + 1, "@see_whether") and instructed(k)) then
        inside = true
      elseif w == "so" and k > 1 and self.t[k - 1].kind ~= "punct" and not self.t[k - 1].filler
          and self:has_ref(k + 1, k + 3, "aircraft") then
        -- ("slow VIR9 to 260 kt so the Speedbird catches up": "so" after an instruction's words, before an
        -- aircraft, says what the instruction brings about; "so" opening a clause is a filler)
        inside = true
      elseif punct and self:word(k + 1, "that this which") and self:word(k + 2, "@purpose_modals")
          and not (self:word_in(k + 3, commentary_end(self, k + 1), "also too likewise same")
            and self:has_ref(k + 3, commentary_end(self, k + 1), "aircraft")) then
        -- (", that should put him across the Beeline's track": what the instruction should bring about;
        -- ", which should also be done for EZY45" names an aircraft the instruction is repeated for)
        inside = true
      elseif punct and (self:word(k + 1, "we") or self:word(k + 1, "i") and not self:word(k + 3, "to"))
          and self:word(k + 2, "@purpose_verbs")
          and not self:word_in(k + 3, math.min(#self.t + 1, k + 5), "you") and not names_instructed(self, k + 3) then
        -- (", we want it crossing the Speedbird's track", ", I want the Beeline to catch him", ", we don't
        -- need fine resolution": the purpose said after the instruction; ", we need you to climb" and
        -- ", I want to have a look at BAW123's position" instruct)
        inside = true
      end
    end
  end
  return self.reason[i] or false
end
-- True when every time written as `text` ("10:44") lies in a remark set aside (G:in_reason) after a word of
-- lexicon.record_time within five words before it (", as it was cleared at 10:44"): a time of the record, which no
-- command reads, so whether it is hours or minutes is never asked
function G:time_set_aside(text)
  local found = false
  for k = 1, #self.t do
    if self:raw(k, k + 1):find(text, 1, true) then
      if not (self:in_reason(k) and self:word_in(math.max(1, k - 5), k, "@record_time")) then return false end
      found = true
    end
  end
  return found
end
-- True when a deletion is said at or after position e (the removal a clause before it gives the reason for).
function G:deletion_from(e)
  for x = e, #self.t do
    if self:intent_at(x) == "delete" then return true end
  end
  return false
end

-- True when the clause [k, e) is the speaker's need of an aircraft, denied, before the aircraft is removed later in
-- the request ("We will not need AFR1142 any more, so could you please delete it?", "I don't need the easyJet
-- anymore, ..."): only words of lexicon.need_denied_before (a negation and a verb of needing among them), one
-- aircraft, then only need_denied_after
function G:need_denied(k, e)
  local r = self:refs_in(k, e, "aircraft")[1]
  if not r or not self:word_in(k, r.b, "not won't don't no") or not self:word_in(k, r.b, "need want require") then
    return false
  end
  for x = k, r.b - 1 do
    if not (self:word(x, "@need_denied_before") or self.t[x].filler) then return false end
  end
  for x = r.e, e - 1 do
    if not self:word(x, "@need_denied_after") then return false end
  end
  return self:deletion_from(e)
end

-- True when the clause [k, e) says an aircraft does not belong in the exercise before it is removed later in the
-- request ("Virgin 27G shouldn't be in this exercise at all; delete him"): the aircraft first, then only words of
-- lexicon.presence_denied, a negation and one of its places among them.
function G:presence_denied(k, e)
  local r = self:refs_in(k, k + 1, "aircraft")[1]
  if not r or not self:word_in(r.e, e, "not shouldn't isn't doesn't") or not self:word_in(r.e, e, "@presence_places") then
    return false
  end
  for x = r.e, e - 1 do
    if not (self:word(x, "@presence_denied @presence_places") or self.t[x].filler) then return false end
  end
  return self:deletion_from(e)
end

-- True when "before" at k opens a clause (to the next punctuation) that names one of lexicon.deadline_places
-- and holds no value, place, type or instruction word ("before it gets to the Spanish boundary").
function G:deadline_clause(k)
  local e = k + 1
  while self.t[e] and self.t[e].kind ~= "punct" do e = e + 1 end
  if not self:word_in(k + 1, e, "@deadline_places") or #self:quantities(k + 1, e) > 0 then return false end
  for _, r in ipairs(self.refs) do
    if r.kind ~= "aircraft" and r.b > k and r.b < e then return false end
  end
  for x = k + 1, e - 1 do
    if self:intent_at(x) then return false end
  end
  return true
end
function G:preceded_by(i, span, words) return self:word_in(math.max(1, i - span), i, words) end
function G:number_at(i) local t = self.t[i] return t ~= nil and not self.u:used(i) and t.number_word end

function G:refs_in(b, e, kind)
  local out, refs = {}, self.refs
  for k = 1, #refs do
    local r = refs[k]
    if r.kind == kind and r.b >= b and r.b < e then out[#out + 1] = r end
  end
  return out
end
-- The waypoint said straight before the verb at i in verb-final order ("SARIZ add between CPX1 and CPX2",
-- "waypoint ORKAN add to end of its route"): its ref when no waypoint is said after the verb but for the one
-- after "between", "after" or "before" straight after it, and a route noun or such a word follows within
-- seven words; nil otherwise
function G:verb_final_waypoint(i)
  local named
  for _, r in ipairs(self:refs_in(math.max(1, i - 4), i, "waypoint")) do
    if r.e == i then named = r end
  end
  -- (a place after "after", "before", "between" or "and" is where the one added goes: "after MAKAG add LAT")
  if not named or self:word(named.b - 1, "after before between and to from of via") then return nil end
  local e = math.min(#self.t + 1, i + 8)
  if self:word(i + 1, "between after before") then
    return self:has_ref(i + 2, i + 3, "waypoint") and named or nil
  end
  if #self:refs_in(i + 1, e, "waypoint") > 0 then return nil end
  return self:word_in(i + 1, e, "@route_nouns") and named or nil
end
-- True when route noun i opens a route said topic-first ("Asiana 371, its route, NOPIK add please", "KAL12 route
-- end, CJU add", "KAL12 route, KWA, MKP, CJU add"): a flying aircraft straight before it ("its"/"the"/"his" and a
-- comma between or none), "end" after it or none, a comma, then waypoints with commas or "and" between and a verb
-- of adding straight after the last
function G:route_topic_first(i)
  local b = self:word(i - 1, "its the his her") and i - 1 or i
  if self.t[b - 1] and self.t[b - 1].text == "," then b = b - 1 end
  local flying = false
  for _, r in ipairs(self:refs_in(1, b, "aircraft")) do flying = flying or (r.e == b and r.exists) end
  if not flying then return false end
  local k = self:word(i + 1, "end") and i + 2 or i + 1
  if not (self.t[k] and self.t[k].text == ",") then return false end
  k = k + 1
  local any = false
  while true do
    local r = self:refs_in(k, k + 1, "waypoint")[1]
    if not r or r.b ~= k then return false end
    any, k = true, r.e
    if self:word(k, "add append insert") then return any end
    if self.t[k] and self.t[k].text == "," then k = k + 1 end
    if self:word(k, "and") then k = k + 1 end
  end
end
function G:has_ref(b, e, kind)
  local last = #self.t + 1
  if e < last then last = e end
  local refs = self.refs
  for k = 1, #refs do
    local r = refs[k]
    if r.kind == kind and r.b >= b and r.b < last then return true end
  end
  return false
end

function G:type_or_aircraft_word(b, e)
  e = math.min(e, #self.t + 1)
  return self:has_ref(b, e, "type") or self:word_in(b, e, "@aircraft_nouns")
end

-- True when heard callsign h (a reference's `heard`) said its airline whole: the airline of the aircraft it was
-- matched to, or one with nothing of it (similarity 0: "Aegean 455" matched to SEH902, which the matcher does
-- only when exactly one aircraft flies): either way its flight number is said as meant.
function G:airline_heard_whole(h) return h.airline >= 1 or h.airline == 0 end

-- True when aircraft reference r names a callsign no aircraft has: not matched to one, or heard with its
-- airline said whole and a flight number no aircraft of that airline has ("Jazz 7455" with JZA7721 flying:
-- a new aircraft, no slip for JZA7721).
function G:new_callsign(r)
  if not r.exists then return true end
  local h = r.heard
  return h ~= nil and self:airline_heard_whole(h) and h.id:match("^%u%u%u?%d+%u*$") ~= nil and not self:state(h.id)
    and not self:airline_and_digits_match(h.id, r.name)
end

-- True when an aircraft type, or a callsign no aircraft has, is named within
-- the three tokens after i (punctuation and fillers not counted).
function G:new_aircraft_follows(i)
  local k, seen = i + 1, 0
  while self.t[k] and seen < 3 do
    if self.t[k].kind ~= "punct" and not self.t[k].filler then seen = seen + 1 end
    for _, r in ipairs(self.refs) do
      if r.b == k and (r.kind == "type" or (r.kind == "aircraft" and self:new_callsign(r))) then return true end
    end
    k = k + 1
  end
  return false
end

-- True when the word at i is the request's only word but for fillers and punctuation.
function G:alone(i)
  for k = 1, #self.t do
    local t = self.t[k]
    if k ~= i and t.kind ~= "punct" and not t.filler then return false end
  end
  return true
end

-- True when every token outside [b, e) is punctuation or a filler.
function G:alone_but(b, e)
  for k = 1, #self.t do
    local t = self.t[k]
    if (k < b or k >= e) and t.kind ~= "punct" and not t.filler then return false end
  end
  return true
end

-- True when [b, e) is a clause of its own in a request of several: every other
-- token between the punctuation before and after it is a filler or "then"
-- ("AAL2307 direct BRAVO, then carry on", "reso MVP, pz 3 nm, then go"), and
-- the clause before it is no callsign alone ("KL204, resume" resumes no clock).
function G:clause_alone(b, e)
  local lo, hi = b - 1, e
  while lo >= 1 and self.t[lo].kind ~= "punct" do lo = lo - 1 end
  while hi <= #self.t and self.t[hi].kind ~= "punct" do hi = hi + 1 end
  if lo < 1 then return false end
  for k = lo + 1, hi - 1 do
    local t = self.t[k]
    if (k < b or k >= e) and not t.filler and not self:word(k, "@then_words") then return false end
  end
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" and r.e == lo then
      for k = 1, r.b - 1 do
        if self.t[k].kind ~= "punct" and not self.t[k].filler then return true end
      end
      return false
    end
  end
  return true
end

-- True when [b, e) opens the request as a clause of its own before another ("go, 3x", "off we go, KLM12 climb
-- FL100"): every token before b is a filler, token e is punctuation and a word that is no filler follows it.
function G:clause_opens(b, e)
  return self:skip_fillers(1) >= b and self.t[e] ~= nil and self.t[e].kind == "punct"
    and self:skip_fillers(e + 1) <= #self.t
end

-- The clause holding token i: [lo, hi), bounded by punctuation and by "and", "then" or "but" between two
-- instructions' words ("turn on MVP resolution and let it use vertical too": "turn on MVP resolution").
function G:clause_around(i)
  local function bound(k) return self.t[k].kind == "punct" or self:word(k, "and but @then_words") end
  local lo, hi = i, i + 1
  while lo > 1 and not bound(lo - 1) do lo = lo - 1 end
  while hi <= #self.t and not bound(hi) do hi = hi + 1 end
  return lo, hi
end

-- True when "vertical" at i is said of conflict resolutions ("let MVP use vertical speed in the
-- resolutions", "resolutions horizontal only, no vertical"), no safety factor or zone size.
-- ("horizontal resolutions only": resolutions without the vertical)
-- A factor, margin or zone said in the request makes "vertical" its direction, unless "vertical" names the
-- resolutions or manoeuvres straight after it in a clause of its own that says none, and each one said
-- elsewhere follows a resolution word in its own clause ("MVP with a horizontal factor of 1.05 and allow
-- vertical resolutions"; "set the horizontal factor to 1.05 and allow vertical resolutions" stays unread).
function G:vertical_resolutions(i)
  -- ("horizontal only", "purely horizontal", "MVP resolutions remain horizontal": horizontal alone)
  local horizontal_only = self:word(i, "horizontal lateral") and (self:word_in(math.max(1, i - 2), i + 4, "only")
    or self:word(i - 1, "purely strictly solely exclusively remain remains stay stays"))
  local sized, reso = "factor margin zone pz rpz zonedh separation sep", "resolution resolutions reso mvp resolver"
  local function sized_apart()
    if not self:word(i + 1, "resolution resolutions manoeuvres maneuvers manoeuvre maneuver") then return false end
    local lo, hi = self:clause_around(i)
    for k = 1, #self.t do
      if self:word(k, sized) and (k >= lo and k < hi or not self:word_in(self:clause_around(k), k, reso)) then
        return false
      end
    end
    return true
  end
  return (self:word(i, "vertical") or horizontal_only) and self:word_in(1, #self.t + 1, reso)
    and (not self:word_in(1, #self.t + 1, sized) or self:word(i, "vertical") and sized_apart())
    -- (aircraft named, "KAL1001, AAR8103, conflict resolution vertical off": only with the resolution's word
    -- straight beside it, the setting being everyone's)
    and (not self:has_ref(1, #self.t + 1, "aircraft")
      or (self:word(i - 1, "resolution resolutions reso") or self:word(i + 1, "resolution resolutions reso"))
        and self:word_in(i + 1, math.min(#self.t + 1, i + 4), "on off @on @off"))
end

-- True when every token but the one at i is punctuation, a filler or part of
-- a callsign, and a callsign is there ("baw836 route?"); tokens [skip_b, skip_e) are left out of the
-- check when given (a verb of showing the caller has read: "KLM12 route, show it").
function G:alone_with_aircraft(i, skip_b, skip_e)
  local named = false
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" then named = true end
  end
  if not named then return false end
  for k = 1, #self.t do
    local t = self.t[k]
    if k ~= i and t.kind ~= "punct" and not t.filler and not (skip_b and k >= skip_b and k < skip_e) then
      local inside = false
      for _, r in ipairs(self.refs) do
        if r.kind == "aircraft" and k >= r.b and k < r.e then inside = true end
      end
      if not inside then return false end
    end
  end
  return true
end

-- True when quantity q is the size of a change said with "of" (lexicon.change_of_verbs: "go down of 2000 feet",
-- "reduce the speed of 40 knots", "turn on the right of 30 degrees"), never a value reached.
function G:change_of(q)
  local of = q and q.b - 1
  if not (of and self:word(of, "of")) then return false end
  if self:word(of - 1, "@change_of_verbs") then return true end
  -- ("descend the Alitalia of 2000 feet": the aircraft said between the verb and "of")
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" and r.e == of then
      local v = self:word(r.b - 1, "the") and r.b - 2 or r.b - 1
      if self:word(v, "@change_of_verbs") then return true end
    end
  end
  if not self:word(of - 1, "@change_of_nouns") then return false end
  local v = self:word(of - 2, "the its") and of - 3 or of - 2
  return self:word(v, "@change_of_verbs")
end

-- "turn on/off ..." / "switch on ...": a switch, not a turn. True when a switch's "on" or "off" follows the verb at
-- i ("turn on the conflict alerts"); "on" before a side, "turn on the left, 45 degrees", "turn on the right of 30",
-- is where the turn goes.
function G:switch_follows(i)
  if self:word(i + 1, "on") and (self:word(i + 2, "left right")
      or (self:word(i + 2, "the") and self:word(i + 3, "left right"))) then
    return false
  end
  local stop = i + 1
  while stop <= #self.t and stop < i + 5 and not self.t[stop].number_word and not self:word(stop, "left right heading") do
    stop = stop + 1
  end
  return self:word_in(i + 1, stop, "on off")
end

-- True when name is a waypoint defined for this run (DEFWPT), not one of the navdata.
function G:user_waypoint(name)
  for _, w in ipairs(self.world.waypoints or {}) do
    if w:upper() == name:upper() then return true end
  end
  return false
end

function G:state(id)
  local lid = id:lower()
  for _, a in ipairs(self.fleet) do
    if a.id:lower() == lid then return a end
  end
  return nil
end

-- The quantities in tokens [b, e), read once per range (mark_used forgets them).
-- A distance said in kilometres is its conversion to nautical miles to 0.01 NM (9 km = 4.86 NM: the tenth the
-- extractor rounds to moves a value said to the kilometre), from the number said.
G.km_words = { km = true, kilometres = true, kilometers = true, kilometre = true, kilometer = true }
-- The level [ft] of altitude quantity q as cleared: a level said in metres is the nearest 100 ft (7200 m =
-- 23600 ft, as handlers_values.lua's metres_level), any other its value as said.
function G:cleared_level(q)
  if q.kind == "alt" and not q.fl and self:word(q.e - 1, "@metres") then return math.floor(q.value / 100 + 0.5) * 100 end
  return q.value
end

function G:quantities(b, e)
  local key = b * 65536 + e
  local q = self.qcache[key]
  if not q then
    q = self.u:quantities(b, e)
    local courtesy = #q > 0 and self:phrase_numbers()
    for k = #q, 1, -1 do
      local x = q[k]
      local unit = self.t[x.e - 1]
      if x.kind == "dist" and unit and G.km_words[unit.text] and x.number then
        x.value = math.floor(x.number.value / 1.852 * 100 + 0.5) / 100
      end
      -- (a number inside a courtesy phrase, "one more thing", is no value)
      if courtesy[x.b] and courtesy[x.e - 1] then table.remove(q, k) end
    end
    self.qcache[key] = q
  end
  return q
end

-- A time said in words at token k that the quantities do not read (lexicon.spoken_units, seconds): {kind =
-- "time", value, b, e} for one unit after "a", "an", "another", "a further" or "one more" ("a minute", "another
-- minute", "one more minute": b is the "one"), a fraction of it ("half a minute", "a quarter of an hour":
-- lexicon.fractions) or one and a half ("a minute and a half"); {kind = "time", loose = true, b, e} for a loose one
-- ("a couple of minutes", "a few minutes", "a minute or two", "a moment", "a bit"); nil for any other word.
function G:spoken_duration(k)
  local units = lexicon.spoken_units
  local function unit(i) return self.t[i] ~= nil and self.t[i].kind == "word" and units[self.t[i].text] end
  local b, n = k, nil  -- (n: the word after the article)
  if self:word(k, "a an another") then n = self:word(k, "a an") and self:word(k + 1, "further") and k + 2 or k + 1 end
  if self:word(k, "more") and self:word(k - 1, "one") and unit(k + 1) then b, n = k - 1, k + 1 end
  local part = (self:word(k, "@fractions") and k) or (n and self:word(n, "@fractions") and n)
  if part then
    local j = self:word(part + 1, "of") and part + 2 or part + 1
    if self:word(j, "a an") and unit(j + 1) then
      return { kind = "time", value = lexicon.fractions[self.words[part]] * unit(j + 1), b = b, e = j + 2 }
    end
    return nil
  end
  if n and unit(n) then
    if self:word(n + 1, "or") and self:word(n + 2, "two so") then return { kind = "time", loose = true, b = b, e = n + 3 } end
    if self:word(n + 1, "and") and self:word(n + 2, "a") and self:word(n + 3, "half") then
      return { kind = "time", value = 1.5 * unit(n), b = b, e = n + 4 }
    end
    return { kind = "time", value = unit(n), b = b, e = n + 1 }
  end
  local j = n and self:word(n, "little") and n + 1 or n
  if j and self:word(j, "@loose_whiles") then return { kind = "time", loose = true, b = b, e = j + 1 } end
  local count = (n and self:word(n, "@loose_counts") and n) or (self:word(k, "@loose_counts") and k)
  j = count and (self:word(count + 1, "of more") and count + 2 or count + 1)
  if j and (unit(j) or self:word(j, "seconds secs")) then return { kind = "time", loose = true, b = b, e = j + 1 } end
  return nil
end

-- The times said in tokens [b, e), in order: the quantities' times and those said in words (G:spoken_duration,
-- marked `spoken`) outside them, on words no part of the parse used ("1500 feet a minute" is a rate, read whole).
function G:durations(b, e)
  local out, inside = {}, {}
  local spoken = self:said("@spoken_units @loose_whiles")  -- (a time in words holds one of these words)
  for _, q in ipairs(self:quantities(b, e)) do
    if spoken then for k = q.b, q.e - 1 do inside[k] = true end end
    if q.kind == "time" then out[#out + 1] = q end
  end
  if not spoken then return out end
  local k = b
  while k < e do
    local x = not inside[k] and not self.u:used(k) and self:spoken_duration(k)
    if x and x.e <= e then
      x.spoken = true
      local at = #out + 1
      while at > 1 and out[at - 1].b > x.b do at = at - 1 end
      table.insert(out, at, x)
      k = x.e
    else
      k = k + 1
    end
  end
  return out
end

function G:mark_used(b, e)
  self.u:mark_used(b, e)
  self.qcache = {}
end

-- Tokens [b, e] are context read as a whole (a declaration, a remark): used, noted as said, and no
-- reference in them stands.
function G:set_aside(b, e)
  self:mark_used(b, e + 1)
  for k = b, e do self.noted[k] = true end
  local refs = {}
  for _, r in ipairs(self.refs) do
    if r.b < b or r.b > e then refs[#refs + 1] = r end
  end
  self.refs = refs
end

function G:need(question)
  if not self.ask then self.ask = question end
end

function G:emit(line) self.out[#self.out + 1] = line end

-- The request's commands run only after a yes to `question` (the first such question stands).
function G:confirm_before(question)
  if not self.confirm_first then self.confirm_first = question end
end

-- Tokens [b, e) were read by a handler (a place's name, "after" a waypoint): no leftover.
function G:explain(b, e)
  self.explained = self.explained or {}
  for k = b, e - 1 do self.explained[k] = true end
end

-- self.said_sets[s]: true when a word of the rule condition set s may be in the request (it was when the
-- request was read: a word blanked since is no longer there), nil when none is.
local function sets_said(self)
  local said, words = {}, self.words
  for k = 1, #words do
    local w = words[k]
    local sets = w and CONDITION_SETS[w]
    if sets then
      for s in pairs(sets) do said[s] = true end
    end
  end
  self.said_sets = said
  return said
end

-- The intent the word at i starts, or nil. A rule's condition may ask for the intents of other words, and
-- through them for the intent of i itself, once (a condition's own per-request cache answers the second
-- reading); a chain of conditions that comes back to i a third time ("I'm going to give it headings":
-- "going" looks at "give", "give" at the words before it) reads no intent there, so every chain ends.
function G:intent_at(i)
  local texts = self.words
  local w = texts[i]
  if not w or (self.u:used(i) and not (self.unheld and self.unheld[i])) then return nil end
  local busy = self.intent_busy
  if not busy then
    busy = {}
    self.intent_busy = busy
  end
  local depth = busy[i] or 0
  if depth >= 2 then return nil end
  local next_word = texts[i + 1]
  local said = self.said_sets or sets_said(self)
  local all = RULES_BY_WORD[w] or ANY_RULES
  -- (per request and list: the rules whose near and prev sets are said, the others never fire)
  local live = self.live_rules
  if not live then
    live = {}
    self.live_rules = live
  end
  local rules = live[all]
  if not rules then
    rules = {}
    for k = 1, #all do
      local r = all[k]
      if (not r.near or said[r.near[2]]) and (not r.prev or said[r.prev[2]]) then rules[#rules + 1] = r end
    end
    live[all] = rules
  end
  local found
  busy[i] = depth + 1
  for k = 1, #rules do
    local r = rules[k]
    local when = r.when
    if r.plain then  -- (compile_rule: no condition but when)
      if not when or when(self, i) then
        found = r.intent or nil
        break
      end
    else
      -- (r.near: followed within r.near[1] tokens by a word of r.near[2]; r.prev: preceded so; a set none
      -- of whose words is said is not looked for)
      local near, not_near, prev, not_prev = r.near, r.not_near, r.prev, r.not_prev
      if (not r.next or (next_word and r.next[next_word] == true))
          and (not near or word_among(texts, i + 1, i + 1 + near[1], near[2]))
          and (not not_near or not (said[not_near[2]] and word_among(texts, i + 1, i + 1 + not_near[1], not_near[2])))
          and (not prev or word_among(texts, i > prev[1] and i - prev[1] or 1, i, prev[2]))
          and (not not_prev
            or not (said[not_prev[2]] and word_among(texts, i > not_prev[1] and i - not_prev[1] or 1, i, not_prev[2])))
          and (not when or when(self, i)) then
        found = r.intent or nil
        break
      end
    end
  end
  busy[i] = depth > 0 and depth or nil
  return found
end

handlers = require("translate.handlers")
for name, fn in pairs(handlers.methods) do G[name] = fn end
for name, spec in pairs(M.intents) do
  if not G[spec.handler] then error("grammar: intent '" .. name .. "' has no handler '" .. tostring(spec.handler) .. "'") end
end

-- ---- conditions: "When AC01 reaches FL200, ..." ----
-- The words that may join a condition word to its value ("ACA102 when you're down to FL150", "ACA871 once it's
-- slowed to 220", "CFG1KZ when you have reached 250 kt", "reduce 250 after it drops below FL150"): who reaches
-- it (LINKING, with the forms of "be" and "have"), and a verb of reaching, passing or slowing ("becomes": "when the
-- speed becomes 250").
local ARRIVING = {}
for w in ([[it it's its he he's she she's they they're you you're you've is are 's 're has have 've had been be
  pass passes passed passing past reach reaches reached reaching hit hits hitting get gets got getting to at level
  through cross crosses crossed crossing down up below above under over drop drops dropped climbs climbed
  descends descended slows slowed slow slowing accelerates accelerated accelerating decelerates decelerated decelerating
  reducing reduced out of leaves left
  leaving become becomes became established]]):gmatch("%S+") do ARRIVING[w] = true end

local LINKING = {}
for w in ([[it it's its he he's she she's they they're you you're you've is are 's 're has have 've had been be
  to]]):gmatch("%S+") do LINKING[w] = true end

-- True when the "above" or "below" at k closes a condition opened by lexicon.condition with at most its subject
-- and a form of "be" between ("once it is above 8000 feet, accelerate", "when below FL100"): the level the
-- aircraft crosses, which the instruction after it waits for (ATALT), no level to fly
-- ("when it goes below 7000 feet", "once it drops below FL100": a verb of moving between is the crossing's too)
function G:bound_condition(k)
  local x = k - 1
  while x > k - 4 and x >= 1 and (LINKING[self.words[x] or ""] or self.t[x].filler
      or self:word(x, "go goes gone get gets got drop drops dropped fall falls fell")) do
    x = x - 1
  end
  return self:word(x, "@condition")
end

-- True when quantity q reads as a level: an altitude or flight level with its unit, or a plain number in thousands
-- of feet ("passing 12000", "when level at eight thousand").
function G.level_value(q)
  return q.kind == "alt" or (q.kind == "plain" and q.number ~= nil and (q.number.thousand or q.value >= 1000))
end

-- True when the words straight before position b open a level condition at a clause's start (after a comma or
-- "and"): "passing" / "reaching" / "leaving", "when level at", or a bare "above" / "below" (G:bare_bound).
function G:level_opening(b)
  local k = b - 1
  local levelled = self:word(k, "at") and self:word(k - 1, "level") and self:word(k - 2, "when once")
  if levelled then k = k - 2 end
  if not (levelled or self:word(k, "passing reaching leaving") or self:bare_bound(k)) then return false end
  if self:word(k - 1, "@condition") then k = k - 1 end
  return k == 1 or self.t[k - 1].kind == "punct" or self:word(k - 1, "and") or self:bound_past_level(k)
end

-- True when "above" or "below" at k is said bare, opening a clause after a comma or "and" with no condition word
-- ("speed 250, above FL100 speed 300"): the level of a speed limit's band, the level the aircraft crosses into it
-- (M:at_altitude reads it only when the aircraft crosses it that way, climbing into "above", descending into
-- "below").
function G:bare_bound(k)
  return self:word(k, "above below") and (k == 1 or self.t[k - 1].kind == "punct" or self:word(k - 1, "and")
    or self:bound_past_level(k))
end
-- True when "above" or "below" at k, said with no mark before it, follows straight after a level value that lies
-- beyond the level said after it ("climb FL200 above one zero thousand increase speed 280": FL200 above 10000 ft, so
-- the climb passes the bound; "below" likewise with a lower level): the level cleared is reached only through the
-- band, so the bound opens the next clause, never the first instruction's condition.
function G:bound_past_level(k)
  local before = self:quantities(math.max(1, k - 6), k)
  local p = before[#before]
  local q = p and p.e == k and self:quantities(k + 1, math.min(#self.t + 1, k + 8))[1]
  if not (q and q.b == self:skip_fillers(k + 1) and G.level_value(p) and G.level_value(q)) then return false end
  local function feet(x) return (x.fl and x.value < 1000) and x.value * 100 or x.value end
  if self:word(k, "above") then return feet(p) > feet(q) end
  return feet(p) < feet(q)
end

-- Where a condition opened at k and said after its instruction ends, its value's quantity ending at e: at the clause
-- after a comma, a semicolon or "and" that holds an instruction and a word saying it runs at once
-- (lexicon.at_once_words: "descend FL320 once it has slowed to 260 knots, and reduce to 260 knots now"), else the
-- request's end. With no such word ("descend FL320 once it has slowed to 260 knots, and turn left heading 200"),
-- which instruction waits is asked (self.ask).
function G:condition_closed(k, e)
  local x = self.t[e] and (self.t[e].text == "," or self.t[e].text == ";") and e + 1 or e
  if self:word(x, "and") then x = x + 1 end
  if x > e and self:any_instruction_in(x, #self.t + 1) then
    if self:word_in(x, #self.t + 1, "@at_once_words") then return x end
    -- (a condition opening a clause after "and" or "then", "climb FL110 and when passing 8000 feet speed up",
    -- is the next instruction's)
    local b = k
    while b > 1 and self.t[b - 1].kind ~= "punct" and not self:word(b - 1, "and @then_words") do b = b - 1 end
    if self:any_instruction_in(b, k) then
      self.ask = string.format("Which should wait for '%s': '%s' or '%s'?", self:raw(k, e),
        self:raw(b, k), (self:raw(x, #self.t + 1):gsub(" ([,.;:])", "%1")))
    end
  end
  return #self.t + 1
end

-- True, asking (self.ask) which instruction waits, when the level, speed or distance condition `at` ("ATALT id
-- FL100") that opens segment k stands between two instructions of one sentence: said straight after the
-- instruction of segment k-1 (no comma or "and" between: "reduce speed 210 when passing 8000 ft and descend to
-- 7000 ft") or set off by commas alone ("reduce speed 250, when passing FL100, turn left heading 200"). Read as
-- segment k's (false) when it opens its clause after "and" ("reduce 240 knots, and when he's got 240, descend
-- FL120"), "then" or a full stop, semicolon, "!" or "?"; when its clause runs on to its verb ("descend to 7000 ft,
-- when passing 8000 ft reduce speed 210"); when it ends a limit ("until 12 miles from TAU, then ..."); or when segment
-- k-1 only cleared the aircraft to the level or speed it waits for, or to levels it crosses the condition's level
-- on the way to ("descend FL80, when passing FL100, reduce speed 220": an instruction never waits for its own
-- value). `before`: #self.out before segment k-1's commands.
function G:condition_between(segs, k, at, before)
  local s, p = segs[k], segs[k - 1]
  local kind, id, value = at:match("^(AT%u*) (%S+) (%S+)")
  if not p or not before or #self.out <= before or not (kind == "ATALT" or kind == "ATSPD" or kind == "ATDIST") then
    return false
  end
  -- (the condition's first word: the first after segment k-1's words that is no mark or "and", or the words
  -- opening it that segment k-1 holds, "on reaching", "upon reaching")
  local c = s.b
  while c < s.trig and (self.t[c].kind == "punct" or self.t[c].filler or self:word(c, "and")) do c = c + 1 end
  while c > p.trig + 1 and self:word(c - 1, "on upon @condition") do c = c - 1 end
  -- (the words between segment k-1's last value and the condition: "descend and maintain 8000, upon reaching ..."
  -- keeps its "and")
  local qs = self:quantities(p.trig, c)
  for x = #qs > 0 and qs[#qs].e or p.trig, c - 1 do
    if self.t[x].kind == "punct" and self.t[x].text ~= "," or self:word(x, "@then_words and until till") then
      return false
    end
  end
  local opened = c > p.trig and self.t[c - 1].kind == "punct"
  local closed = false
  for x = c, s.trig - 1 do
    if self.t[x].kind == "punct" and self.t[x].text == "," or self:word(x, "and") then closed = closed or x end
  end
  if opened and not closed then return false end
  local fl = value:match("^FL(%d+)$")
  local ft = kind == "ATALT" and (fl and tonumber(fl) * 100 or tonumber(value))
  local own, same = kind == "ATALT" and "ALT" or kind == "ATSPD" and "SPD", true
  for x = before + 1, #self.out do
    local cmd, who, v = self.out[x]:match("^(%u+) (%S+) (%S+)")
    same = same and cmd == own and who == id
    if same and v ~= value and not (ft and self:on_the_way(id, ft)) then same = false end
  end
  if same then return false end
  local function said(b, e)
    while e > b and (self.t[e - 1].kind == "punct" or self:word(e - 1, "and")) do e = e - 1 end
    return (self:raw(b, e):gsub(" ([,.;:])", "%1"))
  end
  self:need(string.format("Which should wait for '%s': '%s' or '%s'?", said(c, closed or s.trig), said(p.trig, c),
    said(s.trig, s.e)))
  return true
end

-- A condition said after its instruction, ending the request or a clause said to run at once (G:condition_closed) ("reduce the SAS to 250 knots once it passes
-- flight level 100 on the way down", "slow EZY45 to 220 when it reaches FL120", "250 knots by the time it's
-- passing FL200", "by the time it gets to FL200"): "once", "when" or "by the time", "it" or the aircraft, a
-- verb of reaching, then a level and words with no value, aircraft or instruction of their own to the end;
-- or, after a speed instruction and no level one, "by" and the level alone ("speed 250 by FL200": the speed
-- held from that level); or a speed verb and a speed closing the request ("descend to 8000 once it has slowed
-- to 230"). Returns the position of the condition's first word, the value's quantity and the condition
-- command ("ATALT" or "ATSPD"), or nil; "by the time" with no level so read is asked about (self.ask).
function G:trailing_level_condition()
  if not self:said("by once when after soon at") then return nil end
  for k = 2, #self.t do
    local by_time = self:word(k, "by") and self:word(k + 1, "the") and self:word(k + 2, "time")
    -- ("speed 250 at FL100", "mach .78 at FL280": "at" and the level straight after a speed instruction, as "by")
    local by_level = self:word(k, "by at") and not by_time
    local opened = self:word(k, "once when after") and k + 1 or self:word(k, "as") and self:condition_word(k)
    if opened or by_time or by_level then
      local v = by_time and k + 3 or opened or k + 1
      local subject = v
      if self:word(v, "it it's he he's she she's you you're you've") or self:has_ref(v, v + 1, "aircraft") then
        v = v + 1
      end
      -- ("KLM12 descend FL210 once DLH4 reaches FL200": another aircraft than the one instructed before it is the
      -- condition's subject; the instruction's own aircraft never waits for that level: nil, left to be asked)
      local other = self:refs_in(subject, subject + 1, "aircraft")[1]
      local foreign = other and other.b == subject and opened and other
      for _, r in ipairs(foreign and self:refs_in(1, k, "aircraft") or {}) do
        if r.name:upper() == other.name:upper() then foreign = nil end
      end
      local function found(at, q, cmd, ce)
        if not foreign then return at, q, cmd, ce end
        self.ask = self.ask or string.format("'%s' waits for %s, another aircraft. Should the instruction run now, or "
          .. "when the aircraft it is for reaches a level or speed of its own? Please say it again.",
          self:raw(k, ce), foreign.name:upper())
        return nil
      end
      -- (the words up to the value: ARRIVING only, one of them a verb, no LINKING word nor "at": "but only
      -- when it is at FL210" is G:trailing_level's)
      local first, reached, slowed = self:quantities(v, #self.t + 1)[1], false, false
      if v > subject and first and first.b > v then
        local joined = true
        for x = v, first.b - 1 do
          local w = self.words[x]
          joined = joined and (ARRIVING[w] or self.t[x].filler)
          reached = reached or (ARRIVING[w] and not LINKING[w] and w ~= "at")
          slowed = slowed or self:word(x, "@speed_verbs")
        end
        reached = joined and reached
        if reached then v = first.b - 1 end
      end
      -- ("reduce speed 250 knots then descend FL180 when at 250", "..., descend FL180 once it is at 250 knots": a
      -- speed this request gave with a speed instruction, said again after "when at" or "once at" closing the request,
      -- is the speed the instruction of its clause waits for, ATSPD, as G:speed_again_at reads it said before; a value
      -- the request also gave as a level, or one it never gave, is left to be asked)
      if opened and not by_time and first and first.b > v and self:word(first.b - 1, "at")
          and (first.kind == "speed" or first.kind == "mach" or (first.kind == "plain" and first.value >= 100
            and first.value < 1000)) then
        local only = true
        for x = v, first.b - 2 do only = only and (self.t[x].filler or LINKING[self.words[x]] or false) end
        local given, level = false, false
        for _, p in ipairs(only and self:quantities(1, k) or {}) do
          local w = self:word(p.b - 1, "to") and p.b - 2 or p.b - 1
          if p.value == first.value and (p.kind == "speed" or p.kind == "mach"
              or (p.kind == "plain" and self:intent_at(w) == "spd")) then
            given = true
          end
          level = level or (p.kind == "alt" and (p.value == first.value or p.value == first.value * 100))
            or (p.kind == "plain" and p.value == first.value and self:intent_at(w) == "alt")
        end
        local ce = given and not level and self:condition_closed(k, first.e)
        if ce and #self:quantities(first.e, ce) == 0 and not self:any_instruction_in(first.e, ce) then
          return found(k, first, "ATSPD", ce)
        end
      end
      -- ("descend to 8000 once it has slowed to 230", "... once it's slowed to 230": a speed, ATSPD)
      if reached and slowed and not by_time then
        local q = first
        local ce = self:condition_closed(k, q.e)
        if (q.kind == "speed" or q.kind == "mach" or (q.kind == "plain" and q.value < 1000))
            and #self:quantities(q.e, ce) == 0 and not self:any_instruction_in(q.e, ce) then
          return found(k, q, "ATSPD", ce)
        end
        return nil
      end
      if by_level then v = k end
      if reached or by_level then
        local q = self:quantities(v + 1, #self.t + 1)[1]
        -- (after "at", a bare number of feet too: "heading 250 at 8000")
        local at_feet = by_level and self:word(k, "at") and q and q.kind == "plain" and q.value >= 1000
          and q.value <= 60000 and q.value % 100 == 0
        if not (q and q.b == self:skip_fillers(v + 1) and (q.kind == "alt" or at_feet
            or (q.kind == "plain" and q.value >= 1000 and not by_level))) then
          q = nil
        elseif by_level and self:word(k, "at") then
          q = self:speed_at_level(k, q)
        elseif by_level and not self:speed_before_level(k) then
          return nil
        end
        if q then
          local ce = by_level and #self.t + 1 or self:condition_closed(k, q.e)
          -- (after "at", the clause's end: "speed 250 at FL100, heading 200", the heading runs now)
          if by_level and self:word(k, "at") then
            ce = q.e
            while ce <= #self.t and self.t[ce].kind ~= "punct" and not self:word(ce, "and @then_words") do ce = ce + 1 end
          end
          for x = q.e, ce - 1 do
            if self:intent_at(x) and not self:word(x, "@up @down") or self:has_ref(x, x + 1, "aircraft") then return nil end
          end
          if #self:quantities(q.e, ce) > 0 then return nil end
          return found(k, q, "ATALT", ce)
        end
      end
      -- ("250 knots by the time it's level": a moment squawk cannot wait for, asked about)
      if by_time then
        self.ask = "By the time of what? squawk can wait for a level (ATALT) or a distance from a place (ATDIST): "
          .. "please say the level, or give the instruction when it applies."
      end
      if not by_level and not self:word(k, "after") then return nil end
    end
  end
  return nil
end

-- A level said after "until" ("until passing FL370", "till reaching FL280") ends the instruction before it, a
-- limit squawk's commands do not carry. After a vertical rate, a level cleared said before it ("climb
-- FL380 rate 2000 or greater until passing FL370") the rate is held to the level cleared: the limit is
-- accounted for; after a speed ("maintain Mach .80 until passing FL340") it is asked about, never read as a
-- level to fly. ("climb until FL250", "rate of descent 2000 fpm until FL100": the level to fly, read by the
-- handlers.)
function G:level_limits()
  if not self:said("until till") then return end
  for i = 1, #self.t do
    if self:word(i, "until till") then
      local v = self:skip_fillers(i + 1)
      -- ("until it is ten miles from Porto", "till it's passing FL370": the aircraft's being there; the lexer
      -- keeps "it" of "it's")
      if self:word(v, "@reached_subjects") then v = self:skip_fillers(v + 1) end
      if self:word(v, "@reached_verbs") then v = self:skip_fillers(v + 1) end
      if self:word(v, "passing reaching leaving") then v = self:skip_fillers(v + 1) end
      local q = self:quantities(v, #self.t + 1)[1]
      if q and q.b == v and q.kind == "alt" then
        local b = i
        while b > 1 and self.t[b - 1].kind ~= "punct" do b = b - 1 end
        local rate, speed, cleared = self:word_in(b, i, "rate"), false, false
        for _, p in ipairs(self:quantities(b, i)) do
          rate, speed = rate or p.kind == "vs", speed or p.kind == "speed" or p.kind == "mach"
        end
        for _, p in ipairs(self:quantities(1, i)) do cleared = cleared or p.kind == "alt" end
        if rate and cleared then
          self:mark_used(q.b, q.e)
          self:explain(i, q.e)
        -- ("fly at 210 knots and go down until 7000 feet": "until" straight after a verb of climbing or descending
        -- is the level to fly, "hasta" / "até" in a Spanish or Portuguese speaker's English, read by the handlers)
        -- ("speed 250 until ten thousand, then 300": the level is when the next instruction runs, G:until_level_then)
        elseif self:until_level_end(i) and (speed or self:speed_instructed(b, i)) then
          self:mark_used(q.b, q.e)
          self:explain(i, q.e)
        elseif speed and not (self:word(i - 1, "climb descend") or (self:word(i - 1, "up down") and self:word(i - 2, "go"))) then
          self:need(string.format("squawk cannot end an instruction at a level ('%s'). Should it hold until told "
            .. "otherwise?", self:raw(i, q.e)))
        end
      end
      self:distance_limit(i, v, q)
    end
  end
end

-- True when a speed instruction's word is said in tokens b .. e-1 ("speed 250", "reduce to 250").
function G:speed_instructed(b, e)
  for x = b, e - 1 do
    if self:intent_at(x) == "spd" then return true end
  end
  return false
end

-- A distance from a place after "until" ("maintain 250 knots or greater until 20 miles from FFM", "until 15 miles
-- from TAU descend FL100"; the word at i, the quantity q from v) ends the instruction there, a limit squawk's
-- commands do not carry (ATDIST would start it there instead): asked. With "then" (or "thereafter", "after that")
-- straight after the place ("speed 280 till 10 miles from TAU, then reduce 220") it is when that next
-- instruction runs, read as the condition.
function G:distance_limit(i, v, q)
  if not (q and q.b == v and q.kind == "dist") then return end
  local at = self:word(q.e, "out") and q.e + 1 or q.e
  local from = self:word(at, "from of to before") and self:skip_fillers(at + 1) or at
  local place = self:refs_in(from, from + 1, "waypoint")[1] or self:refs_in(from, from + 1, "airport")[1]
  local e = place and place.e or from
  -- (a callsign straight after the distance is the aircraft addressed, no place: "170 knots till 4 DME KLM 1395")
  if not place and #self:refs_in(from, from + 1, "aircraft") > 0 then return end
  if not place and not (self.t[from] and self.t[from].kind == "word" and self.t[from].raw:match("^%u")) then return end
  if not place then e = from + 1 end
  local k = self.t[e] and self.t[e].kind == "punct" and self.t[e].text == "," and e + 1 or e
  if self:word(k, "and") then k = k + 1 end
  if self:word(k, "then thereafter afterwards") or (self:word(k, "after") and self:word(k + 1, "that")) then return end
  self:need(string.format("squawk cannot end an instruction at a distance ('%s'): ATDIST would start it there. "
    .. "Should it hold until told otherwise?", self:raw(i, e)))
end

-- A level said after "passing" or "leaving" that became a level to fly ("KLM12 passing FL340 Mach .80": a
-- pilot's report of the level passed, or a condition with nothing to hold) is asked about, never issued.
function G:passing_level_flown()
  for _, q in ipairs(self:quantities(1, #self.t + 1)) do
    -- ("passing through FL260": the same)
    local by = self:word(q.b - 1, "through") and q.b - 1 or q.b
    if q.kind == "alt" and self:word(by - 1, "passing leaving") then
      local level = " " .. handlers.format.alt(q.value, q.fl)
      for _, line in ipairs(self.out) do
        if line:match("^ALT %S+ %S+") and (line .. " "):find(level .. " ", 1, true) then
          return self:need(string.format("I have %s. Is '%s' a level to fly to, or a level the aircraft passes?",
            table.concat(self.out, " ; "), self:raw(by - 1, q.e)))
        end
      end
    end
  end
end

-- A level condition the aircraft will not cross is asked about: ATALT runs its command when the aircraft's
-- altitude crosses the level (Stack::test_conditions, as BlueSky's ATALT), never when it has passed it, so a
-- level outside the way from the aircraft's altitude to the level it is cleared to (in this request, else its
-- selected one) would never run it ("ACA871 climb FL170 and when it passes FL100 reduce 230", ACA871 at FL110).
-- An aircraft level with no clearance may get one later: its condition stands.
local function level_feet(text)
  local fl = text:match("^FL(%d+)$")
  return fl and tonumber(fl) * 100 or tonumber(text)
end
function G:level_never_crossed()
  for _, line in ipairs(self.out) do
    local id, at = line:match("^ATALT (%S+) (%S+) ")
    local a, level = id and self:state(id), at and level_feet(at)
    if a and a.alt_ft and level then
      local cleared = a.sel_alt_ft
      for _, other in ipairs(self.out) do
        local who, to = other:match("^ALT (%S+) (%S+)")
        if who and who:upper() == id:upper() then cleared = level_feet(to) end
      end
      local function fl(ft)
        return ft >= 10000 and string.format("FL%03d", math.floor(ft / 100 + 0.5)) or string.format("%d ft", math.floor(ft + 0.5))
      end
      -- (the level the condition waits for lies beyond the one its own command clears to, seen from the aircraft's
      -- altitude: "speed 310, reaching 300 climb FL260" at FL250, "reaching FL270 descend FL200" at FL250; to run,
      -- the aircraft would fly past the new level and come back, with no clearance of its own past the level; "300"
      -- may have been meant as a speed)
      local who, to = line:match("^ATALT %S+ %S+ ALT (%S+) (%S+)")  -- (the waiting command's own aircraft only)
      to = who and who:upper() == id:upper() and level_feet(to)
      local crossed = cleared and (level - a.alt_ft) * (level - cleared) <= 0  -- (its clearance passes the level)
      if to and not crossed and math.abs(level - a.alt_ft) > 50 and (level - a.alt_ft) * (level - to) > 0 then
        return self:need(string.format("I have %s. %s is at %s and the instruction that waits clears it to %s: it "
          .. "would not pass %s on the way, so the instruction would never run. What should it wait for?",
          table.concat(self.out, " ; "), id, fl(a.alt_ft), fl(to), at))
      end
      if cleared and math.abs(cleared - a.alt_ft) > 50 and math.abs(level - a.alt_ft) > 50
          and (level - a.alt_ft) * (level - cleared) > 0 then
        return self:need(string.format("I have %s. %s is at %s and cleared to %s: it will not pass %s, so what waits "
          .. "for that level would never run. Which level should it wait for?", table.concat(self.out, " ; "), id,
          fl(a.alt_ft), fl(cleared), at))
      end
    end
  end
end

-- Level q said after "at" at k, when it is the condition of the speed instruction of its own clause ("speed 250
-- at FL100", "descend FL80, mach .78 at FL280": what the speed waits for, ATALT), else nil. Not when the clause
-- holds a level or vertical rate instruction ("descend FL100 at 250 knots") nor when its aircraft flies that
-- level now ("speed 250 at FL140", at FL140: it would never cross it, no condition).
function G:speed_at_level(k, q)
  local spd, hdg, x = false, false, k - 1
  while x >= 1 and not (self.t[x].kind == "punct" or self:word(x, "and @then_words")) do
    local intent = self:intent_at(x)
    if intent == "alt" or intent == "vs" then return nil end
    spd = spd or intent == "spd" or self:word(x, "mach")
    hdg = hdg or intent == "hdg"
    x = x - 1
  end
  -- (a heading the same: "descend 6000, then heading 250 at 8000", when a clause before cleared a level, so that
  -- the level after "at" is none to fly)
  local cleared = false
  if hdg and not spd then
    for y = x, 1, -1 do
      if self:intent_at(y) == "alt" then cleared = true break end
    end
  end
  for _, r in ipairs(self:refs_in(1, #self.t + 1, "aircraft")) do
    local a = self:state(r.name)
    if a and a.alt_ft and math.abs(a.alt_ft - q.value) <= 50 then return nil end
  end
  -- (a heading alone in the request with a level after "at", "turn left heading 200 at FL100": a level to fly
  -- or one to wait for, asked)
  if hdg and not spd and not cleared then
    local only = true
    for y = 1, #self.t do
      local intent = self:intent_at(y)
      only = only and (not intent or intent == "hdg")
    end
    if only then
      local level = q.kind == "alt" and handlers.format.alt(q.value, q.fl) or handlers.format.int(q.value) .. " ft"
      self.ask = string.format("Should the heading wait until the aircraft passes %s (ATALT), or should it also "
        .. "climb or descend to %s?", level, level)
    end
    return nil
  end
  if not (spd or cleared) then return nil end
  return q
end

-- True when the words before position k give a speed instruction and no level one ("speed 250 by FL200",
-- not "descend by 2000 feet").
function G:speed_before_level(k)
  local spd = false
  for x = 1, k - 1 do
    local intent = self:intent_at(x)
    if intent == "alt" or intent == "vs" then return false end
    spd = spd or intent == "spd"
  end
  return spd
end

-- The position after the words that open a condition at i ("when", "once", "after", "as soon as"), or nil.
function G:condition_word(i)
  if self:word(i, "@condition") then return i + 1 end
  if self:word(i, "as") and self:word(i + 1, "soon") and self:word(i + 2, "as") then return i + 3 end
  return nil
end

-- The position of "speed" (of the value, with no noun) when "at speed N" at i opens a condition on reaching that
-- speed: the number straight after the noun and an instruction after it ("KLM12 at speed 250 descend FL180"), else
-- nil. With "and" or "then" between ("at speed 250 and descend FL180": the speed flown now, or the moment it is
-- reached?) it is asked.
function G:at_speed_word(i)
  if not self:word(i, "at") then return nil end
  -- ("at about 250 knots": a value said loosely is the value said)
  local v = self:word(i + 1, "about around approximately roughly") and i + 2 or i + 1
  local noun = self:word(v, "speed airspeed")
  local q = self:quantities(noun and v + 1 or v, #self.t + 1)[1]
  if not q or q.b ~= (noun and v + 1 or v) then return nil end
  -- ("KLM12 at 250 knots descend FL180", "at Mach .78": without the noun, the speed's own unit)
  if not (q.kind == "speed" or q.kind == "mach" or (noun and q.kind == "plain")) then return nil end
  local k = q.e
  if self.t[k] and self.t[k].kind == "punct" then k = k + 1 end
  if not self:any_instruction_in(k, #self.t + 1) then return nil end
  if self:word(k, "and then") then
    self.ask = string.format("Is speed %s to be flown now, or is the rest to happen on reaching that speed (ATSPD)?",
      self.t[q.b].text)
    return nil
  end
  return v
end

-- "reduce speed 250, when speed 250 descend FL120", "..., once at 250 knots turn left heading 180", "..., when
-- slowed to 250 descend FL120": a condition word in segment s before its instruction word, then words of reaching
-- (ARRIVING) and perhaps the noun "speed", then a speed (knots or Mach, or a bare number of 40 to 700 after the noun
-- or a verb of slowing, or one the request set as the aircraft's speed already), then only the instruction's lead words, is what the instruction waits for: "ATSPD id
-- value" (the value read), else nil.
G.speed_held = { alt = true, hdg = true, vs = true, spd = true, maintain = true, direct = true, lnav = true,
  vnav = true }
function G:at_speed(s)
  -- (G:condition_word opens on one of these words; "reaching" opens alone, before a speed said with its unit:
  -- "speed 310, reaching 300 knots climb FL260", "on reaching Mach .78 descend FL350")
  if not G.speed_held[s.intent] or not self:said("@condition as reaching") then return nil end
  local v, reaching
  for i = s.b, s.trig - 1 do
    v = self:condition_word(i)
    if not v and self:word(i, "reaching") then v, reaching = i + 1, true end
    if v then break end
  end
  local q = v and self:quantities(v, s.trig)[1]
  if not q or (reaching and not (q.b == v and (q.kind == "speed" or q.kind == "mach"))) then return nil end
  local noun, slowed = false, false
  for x = v, q.b - 1 do
    -- (the noun as the subject of a verb of reaching: "when the speed is 230", "once speed reaches 250")
    if not noun and self:word(x, "speed airspeed") then
      noun = true
    -- ("once his speed is 250": the aircraft's own speed)
    elseif not (self.t[x].filler or ARRIVING[self.words[x]]
        or (self:word(x, "his her their your") and self:word(x + 1, "speed airspeed"))) then
      return nil
    end
    slowed = slowed or self:word(x, "@speed_verbs")
  end
  local f = handlers.format
  -- (a bare number after "at" that this request gave the aircraft as its speed already: "reduce 180 knots, and once
  -- you're at one eighty descend FL70"; "when 250" with no "at" is asked)
  local bare = q.kind == "plain" and q.value >= 40 and q.value <= 700
  -- ("and when he's got two fifty, descend", "when you have two eight zero, descend": the speed had, given
  -- already, as "at" says it)
  -- ("and after you reach 300 climb to 14,000": the speed reached, given already)
  local again = bare and not (noun or slowed) and self:word(q.b - 1, "at got have has reach reaches reached hit hits")
  if not (q.kind == "speed" or q.kind == "mach" or (bare and (noun or slowed or again))) then return nil end
  local k = self:skip_fillers(q.e)
  while k < s.trig and ((self.t[k].kind == "punct" and self.t[k].text == ",") or self:word(k, "@condition_lead")
      or LINKING[self.words[k]] or (self:word(k, "go") and self:word(s.trig, "@up @down"))
      -- (", kindly let him descend": courtesy and "let" with the aircraft's pronoun before the instruction word)
      or self:word(k, "kindly") or (self:word(k, "let") and self:word(k + 1, "him her them"))
      or (self:word(k, "him her them") and self:word(k - 1, "let"))) do
    k = self:skip_fillers(k + 1)
  end
  local ids = k == s.trig and self:acids(s) or {}
  if #ids ~= 1 then return nil end
  if again then
    local given = false
    for _, c in ipairs(self.out) do given = given or c == "SPD " .. ids[1] .. " " .. f.int(q.value) end
    if not given then return nil end
  end
  self:mark_used(q.b, q.e)  -- the condition's speed is not the instruction's value
  return "ATSPD " .. ids[1] .. " " .. (q.kind == "mach" and f.mach(q.value) or f.int(q.value))
end

-- The position after a polite or wishing opening at i that asks for what the aircraft named after it should do
-- ("would it be possible to have the Porter, ...": lexicon.request_openings; "could the Porter, once it reaches
-- OAKVL, turn ...": lexicon.polite_openings; "I'd like the Rouge, once ...", "we would like":
-- lexicon.wish_before_like words, then "like"), skipping fillers after it; else i.
function G:request_opening(i)
  -- (G.request_opening_words: lexicon.request_openings, each as the array of its words; built at the first call)
  local openings = G.request_opening_words
  if not openings then
    openings = {}
    for n, p in ipairs(lexicon.request_openings) do
      openings[n] = {}
      for w in p:gmatch("%S+") do table.insert(openings[n], w) end
    end
    G.request_opening_words = openings
    -- (G.request_opening_firsts: the openings' first words, one list for G:word: none of them at i, no opening)
    local firsts = {}
    for n, p in ipairs(openings) do firsts[n] = p[1] end
    G.request_opening_firsts = table.concat(firsts, " ")
  end
  for _, p in ipairs(self:word(i, G.request_opening_firsts) and openings or {}) do
    local k = i
    for _, w in ipairs(p) do
      if not self:word(k, w) then k = nil break end
      k = k + 1
    end
    if k then return self:skip_fillers(k) end
  end
  if self:word(i, "@polite_openings") then return self:skip_fillers(i + 1) end
  local k = i
  while k < i + 3 and self:word(k, "@wish_before_like") do k = k + 1 end
  -- ("I would like that the Qatari, after ...": "that" after "like" before the aircraft)
  if k > i and self:word(k, "like") then return self:skip_fillers(self:word(k + 1, "that") and k + 2 or k + 1) end
  return i
end

function G:condition()
  local i = 1
  while self.t[i] and self.t[i].kind == "word" and self.t[i].filler do i = i + 1 end
  -- "ACA102 when you're down to FL150 slow to 250": a condition said after the aircraft's callsign, its value
  -- joined to its word by ARRIVING words only ("could the Porter, once it reaches OAKVL, ...": after a polite
  -- opening, G:request_opening)
  -- ("excuse me, for the Air Do, when ...": a comma closing the courtesy fillers that open the request, before an
  -- opening and its aircraft)
  local o = i
  if i > 1 and self.t[i] and self.t[i].kind == "punct" and self.t[i].text == "," then o = self:skip_fillers(i + 1) end
  local opened = not self:condition_word(i) and self:request_opening(o)
  if opened == o and o ~= i then opened = i end
  local lead = opened and self:refs_in(opened, opened + 1, "aircraft")[1]
  if lead then
    local c = self:skip_fillers(lead.e)
    if self.t[c] and self.t[c].kind == "punct" and self.t[c].text == "," then c = self:skip_fillers(c + 1) end
    local v = self:condition_word(c) or self:at_speed_word(c)
    local q = v and self:quantities(v, #self.t + 1)[1]
    -- ("DAL415, when you get to ERLIN, go direct ATL": a waypoint reached by a verb of reaching, said before any
    -- value; never with the instruction taken back or said to be flown now)
    local wp = v and self:refs_in(v, #self.t + 1, "waypoint")[1]
    -- (a participle or "past" only with a comma closing the condition at the waypoint: "could the Speedbird, when
    -- it's passing RAGID, descend ...", "once it's past TOTUX, ..."; "after passing NEVRI descend FL90, ..." is read
    -- by the instruction's own condition)
    local verbs = self.t[wp and wp.e or 1] and self.t[wp and wp.e or 1].text == ","
      and "get gets reach reaches reached reaching pass passes passed passing past cross crosses crossed crossing"
      or "get gets reach reaches pass passes cross crosses"
    if wp and (not q or wp.b < q.b) and self:word_in(v, wp.b, verbs)
        and not self:word_in(v, #self.t + 1, "@correction now") then
      q = wp
    end
    -- ("EZY19GH, when you reach Glasgow VOR, turn left ...": a place said by its name closing the condition)
    local cm = v and not (wp and q == wp) and v
    while cm and self.t[cm] and not (self.t[cm].kind == "punct" and self.t[cm].text == ",") do cm = cm + 1 end
    local named = cm and cm <= #self.t and not (q and q.b < cm) and not self:word_in(v, #self.t + 1, "@correction now")
      and self:reached_by_name(v, cm, lead.name)[1]
    if named then q = named end
    if not q then return nil, 1 end
    -- ("the Porter, when it's down at FL200... no, I mean, could it descend to FL200, ...": a self-correction said
    -- after the condition's value, before the next instruction word, takes the condition back: none is read here)
    local nx = q.e
    while nx <= #self.t and not self:intent_at(nx) do nx = nx + 1 end
    local taken = math.min(self:find_word(q.e, nx, "@correction"), self:find_word(q.e, nx, SC_MARKERS))
    if taken < nx then
      self:mark_used(c, taken)
      for k = c, taken - 1 do self.noted[k] = true end
      return nil, 1
    end
    -- ("DLH4AB when reaching speed 250, descend FL200": the speed's noun straight before its number)
    for x = v, q.b - 1 do
      if not (self.t[x].filler or ARRIVING[self.words[x]] or (x == q.b - 1 and self:word(x, "speed airspeed"))) then
        return nil, 1
      end
    end
    i = c
  end
  -- ("at 250 knots AC003 descend FL150", "at speed 250, KLM12 descend FL180": opening the request, for the first
  -- aircraft said after it)
  local at_speed = self:at_speed_word(i)
  if not (self:condition_word(i) or at_speed) then return nil, 1 end
  local comma = i + 1
  while comma <= #self.t and not (self.t[comma].kind == "punct" and self.t[comma].text == ",") do comma = comma + 1 end
  -- ("HVN611 when pass BOKAK descend to FL240, thank you": a comma with only thanks after it ends no condition)
  if comma <= #self.t and G.thanks_to_end(self, comma + 1) then comma = #self.t + 1 end
  local rest = comma + 1
  -- (a speed after "at" ends the condition at its value, a comma after it or not)
  if at_speed then
    comma = self:quantities(at_speed, #self.t + 1)[1].e
    rest = self.t[comma] and self.t[comma].kind == "punct" and comma + 1 or comma
  end
  -- "when passing FL200 reduce speed 250 knots, descend FL120": an instruction said in the condition's clause
  -- after its level or speed waits for it alone (the segment's own condition, m:at_altitude); what follows the
  -- comma runs now. With "and" or "then" after the comma, whether that waits too is asked.
  if not at_speed and comma <= #self.t then
    local q = self:quantities(i, comma)[1]
    if q and (q.kind == "alt" or q.kind == "speed" or q.kind == "mach") and self:any_instruction_in(q.e, comma)
        and not self:has_ref(i, q.b, "waypoint") then
      local nx = comma + 1
      while self.t[nx] and self.t[nx].filler and not self:word(nx, "and") do nx = nx + 1 end
      -- ("..., and now climb to FL200": a word of lexicon.at_once_words in the clause after "and" runs it now)
      local ce = nx + 1
      while ce <= #self.t and self.t[ce].kind ~= "punct" and not self:word(ce, "and") do ce = ce + 1 end
      if self:word(nx, "and") and self:word_in(nx + 1, ce, "@at_once_words") then return nil, 1 end
      -- ("KAC541, after reaching FL230 turn right heading 030, and of course climb it to FL250", KAC541 level at
      -- FL200: the level after "and" lies beyond the condition's from the level the aircraft flies, with no other
      -- clearance, so the condition is met only by that climb or descent: it runs now)
      -- ("and then climb ..." says an order: still asked)
      local a = lead and lead.exists and q.kind == "alt" and self:word(nx, "and")
        and not self:word_in(nx + 1, ce, "@then_words") and self:state(lead.name)
      local q2 = a and a.alt_ft and self:quantities(nx + 1, ce)[1]
      if q2 and q2.kind == "alt" and (not a.sel_alt_ft or math.abs(a.sel_alt_ft - a.alt_ft) <= 50) then
        local level, to = self:cleared_level(q), self:cleared_level(q2)
        if math.abs(level - a.alt_ft) > 50 and (level - a.alt_ft) * (to - level) > 0 then return nil, 1 end
      end
      if self:word(nx, "and @then_words") then
        self.ask = string.format("Should '%s' also wait for '%s', or run now?",
          (self:raw(nx, #self.t + 1):gsub(" ([,.;:])", "%1")), self:raw(i, q.e))
        return nil, rest
      end
      return nil, 1
    end
  end
  -- "when the dash 8 gets to GADUM set its speed to 180", "when WJA661 passes ADLER set speed 220": with no
  -- comma, a waypoint the aircraft reaches (no value before it) ends the condition, an instruction after it
  local reached = comma > #self.t and self:refs_in(i, #self.t + 1, "waypoint")[1]
  if reached and self:word(reached.b - 1, "to at pass passes reach reaches hit hits cross crosses overflies")
      and #self:quantities(i, reached.b) == 0
      and (self:any_instruction_in(reached.e, #self.t + 1) or self:held_value(reached.e)) then
    comma, rest = reached.e, reached.e
  end
  if comma > #self.t then
    -- "when BAW123 reaches FL300 set its speed to 260": with no comma the condition ends at its value,
    -- a level, a speed or Mach ("once AFR1023 slows to 250": a speed by its verb), and an
    -- instruction must follow it
    local q = self:quantities(i, #self.t + 1)[1]
    -- ("when reaching speed 250 descend FL200": by its noun)
    local by_verb = q and q.kind == "plain"
      and self:word(self:word(q.b - 1, "to") and q.b - 2 or q.b - 1, "@speed_verbs speed airspeed")
    -- (a value with its own unit is an instruction too: "ACA102 once you hit FL170 go 260 knots", "once QFA12 is
    -- passing FL340 bring it back to 260 knots")
    local nq = q and self:quantities(q.e, #self.t + 1)[1]
    local valued = nq and (nq.kind == "speed" or nq.kind == "mach" or (nq.kind == "alt" and nq.fl))
    if not q or not (q.kind == "alt" or q.kind == "speed" or q.kind == "mach" or by_verb)
        or not (valued or self:any_instruction_in(q.e, #self.t + 1)) then
      return nil, 1
    end
    -- ("After DUS the Speedbird must descend to FL200. So: ...": a sentence ending at the value holds no
    -- instruction waiting for it; the value is its own sentence's, read there)
    local ends = q.e
    while self.t[ends] and self.t[ends].kind == "word" and self.t[ends].filler do ends = ends + 1 end
    if self.t[ends] and self.t[ends].kind == "punct" and (". ! ? ; :"):find(self.t[ends].text, 1, true) then
      return nil, 1
    end
    comma, rest = q.e, q.e
    -- ("once you pass FL270 on the way up speed 300": the direction said with the level is the condition's)
    local way = self:crossing_way(self:skip_fillers(q.e))
    if way then comma, rest = way + 1, way + 1 end
  end
  -- ("when reaching FL230... disregard, descend FL190", "..., scratch that, descend FL190": a condition taken back
  -- by a correction (lexicon.correction, or self_correction.dropping's words) said before the next instruction
  -- word, no value between, is none; the instruction after it runs now; "when reaching FL230, correction, FL240"
  -- corrects the condition's value)
  local taken = i + 1
  while taken <= #self.t and not self:intent_at(taken) do taken = taken + 1 end
  local c = math.min(self:find_word(i, taken, "@correction"), self:find_word(i, taken, G.sc_dropping))
  if c < taken and #self:quantities(c, taken) == 0 then
    self:mark_used(i, c)
    for k = i, c - 1 do self.noted[k] = true end
    return nil, 1
  end
  local ids = self:refs_in(i, comma, "aircraft")
  if lead and #ids > 0 then return nil, 1 end
  if lead then ids = { lead } end
  if at_speed and #ids == 0 then ids = { self:refs_in(rest, #self.t + 1, "aircraft")[1] } end
  if #ids == 0 then return nil, 1 end
  self.subject = ids[1].name
  local f = handlers.format
  -- "when the Widerøe passes VIBUK, it should descend to 5000 feet", "once DLH2VA gets to MALIX, descend
  -- FL80": a waypoint the aircraft reaches, no value, is a constraint there (G:at_condition)
  local places = self:refs_in(i, comma, "waypoint")
  if #places == 0 and comma <= #self.t and #self:quantities(i, comma) == 0 then
    places = self:reached_by_name(i, comma, self.subject)
  end
  if #places == 1 and #self:quantities(i, comma) == 0 then
    if not places[1].exists or not self:on_route(self.subject, places[1].name) then
      self.ask = self:off_route_question(self.subject, places[1].name)
      return nil, rest
    end
    self.at_place = places[1].name
    self.at_held = self:held_value(rest)
    return "", rest
  end
  for _, q in ipairs(self:quantities(i, comma)) do
    -- ("once you pass FL240 on the way down, ..."): the direction said must be the one the aircraft crosses the
    -- level in from where it is; else asked
    local way = (q.kind == "alt" or q.kind == "plain" and q.value >= 1000) and self:crossing_way(self:skip_fillers(q.e))
    if way and way < comma then
      if not self:way_fits(way, self.subject, q.value) then
        self.ask = string.format("'%s': %s is not %s that level. Which level should it wait for?",
          self:raw(q.b, way + 1), self.subject, self:word(way, "down") and "above" or "below")
        return nil, rest
      end
      self:explain(way - 3, way + 1)
    end
    if q.kind == "alt" then return "ATALT " .. self.subject .. " " .. f.alt(self:cleared_level(q), q.fl), rest end
    if q.kind == "speed" then return "ATSPD " .. self.subject .. " " .. f.int(q.value), rest end
    if q.kind == "mach" then return "ATSPD " .. self.subject .. " " .. f.mach(q.value), rest end
    if q.kind == "plain" and q.value >= 1000 then return "ATALT " .. self.subject .. " " .. f.int(q.value), rest end
    if q.kind == "plain" and (rest == q.e or self:word(q.b - 1, "speed airspeed")) then
      return "ATSPD " .. self.subject .. " " .. f.int(q.value), rest
    end
    -- "when BAW123 is 20 miles from LEKKO, ...", "once the Vueling is 20 miles out from SIJAN": ATDIST [NM]
    local at = self:word(q.e, "out") and q.e + 1 or q.e
    local from = q.kind == "dist" and self:word(at, "from of to before") and self:skip_fillers(at + 1)
    local r = from and self:refs_in(from, from + 1, "waypoint")[1]
    -- ("when the Swiss is 10 miles from Munich airport": a place said by its name, near the aircraft)
    local place = r and r.name or (from and self:place_by_name(from, comma, self:state(self.subject), true))
    if place then return "ATDIST " .. self.subject .. " " .. place .. " " .. f.num(q.value), rest end
  end
  self.ask = "At what altitude or speed should " .. self.subject .. " act?"
  return nil, rest
end

-- How far a condition opening the request holds (G:condition; its instructions from `rest`): every instruction
-- after it, unless a later clause (after a mark or "and", an instruction read before it) holds a word saying it runs
-- at once (lexicon.at_once_words: "once you reach FL150, reduce to 250 knots; descend to FL150 now"): that clause and
-- what follows run now, and its first token is returned. Another instruction after a full stop, a semicolon, "!" or
-- a question mark (the condition's request asked as a question, "when it passes RAGID, could it descend to FL280?
-- And reduce to 250") with no such word may wait too or run now: asked (self.ask). nil when the condition holds all.
function G:condition_scope(rest)
  for x = rest + 1, #self.t do
    local mark = self.t[x].kind == "punct"
    if (mark or self:word(x, "and")) and self:any_instruction_in(rest, x) and self:any_instruction_in(x + 1, #self.t + 1) then
      local e = (mark and self:word(x + 1, "and")) and x + 2 or x + 1  -- (a mark, then "And right now ...")
      while e <= #self.t and self.t[e].kind ~= "punct" and not self:word(e, "and") do e = e + 1 end
      if self:word_in(x + 1, e, "@at_once_words") then return x + 1 end
      -- (after a question, a remark on it, "That's the limit I'm modelling", is no instruction to wait)
      local remark = self.t[x].text == "?" and self:declared_clause(x + 1)
      if mark and (". ; ! ?"):find(self.t[x].text, 1, true) and not remark then
        local c = self:find_word(1, rest, "@condition")
        self.ask = string.format("Should '%s' also wait for '%s', or run now?",
          (self:raw(x + 1, #self.t + 1):gsub(" ([,.;:!])", "%1"):gsub("[%s%p]+$", "")),
          (self:raw(c < rest and c or 1, rest):gsub(" ([,.;:!])", "%1"):gsub("[%s%p]+$", "")))
        return nil
      end
    end
  end
  return nil
end

-- A place said by its name closing the condition i .. comma - 1 straight after a verb of reaching ("when the BA
-- gets to Biggin, ...", "when you reach Glasgow VOR, ...": lexicon.reached_place_words), near aircraft `id`
-- (m:place_by_name): { {name =, exists = true, b =, e =} } (its tokens b .. e - 1, marked used), else {}.
function G:reached_by_name(i, comma, id)
  local v = comma - 1
  while v > i and not self:word(v, "@reached_place_words") do v = v - 1 end
  if v <= i or v >= comma - 1 or self:has_ref(v + 1, comma, "aircraft") or self:has_ref(i, comma, "waypoint") then
    return {}
  end
  -- (only the aircraft and words of arriving before the place: "after DELON proceed to Minsk" is none)
  local x = i + 1
  while x <= v do
    local r = self:refs_in(x, x + 1, "aircraft")[1]
    if r then
      x = r.e
    elseif ARRIVING[self.words[x]] or self.t[x].filler or self:word(x, "the") then
      x = x + 1
    else
      return {}
    end
  end
  self.reached_named = self.reached_named or {}  -- (read once: the words are marked used)
  local found = self.reached_named[v]
  if found == nil then
    local name = self:place_by_name(v + 1, comma, self:state(id), true)
    found = name and { name = name, exists = true, b = v + 1, e = comma } or false
    if name then self:mark_used(v + 1, comma) end
    self.reached_named[v] = found
  end
  return found and { found } or {}
end

-- True when waypoint `wp` is on aircraft `id`'s route (as the simulator has it).
function G:on_route(id, wp)
  for _, w in ipairs((self:state(id) or {}).route or {}) do
    if w:upper() == wp:upper() then return true end
  end
  return false
end

-- The question when an instruction is tied to waypoint `wp` that is not on aircraft `id`'s route (BlueSky's
-- AT acid wp DO needs a waypoint of the route: the simulator refuses any other).
function G:off_route_question(id, wp)
  return string.format("%s is not on %s's route, so squawk cannot run the instruction there. Should it happen "
    .. "now, or at a waypoint of the route? (ADDWPT %s %s adds it first.)", wp, id, id, wp)
end

-- "after passing CPA1 continue to EXIT1", CPA1 ending the route: a place off the route added and flown to once the
-- route's last waypoint is passed ("AT id CPA1 DO ADDWPT id EXIT1 ; AT id CPA1 DO DIRECT id EXIT1") is that place
-- added after it, "ADDWPT id EXIT1,,,CPA1", flown the same; self.out rewritten in place.
function G:added_after_route_end()
  for c = 1, #self.out - 1 do
    local id, wp, x = self.out[c]:match("^AT (%S+) (%S+) DO ADDWPT %S+ ([%w_]+)$")
    local route = id and (self:state(id) or {}).route or {}
    if id and self.out[c] == string.format("AT %s %s DO ADDWPT %s %s", id, wp, id, x)
        and self.out[c + 1] == string.format("AT %s %s DO DIRECT %s %s", id, wp, id, x)
        and #route > 0 and route[#route]:upper() == wp:upper() then
      self.out[c] = string.format("ADDWPT %s %s,,,%s", id, x, wp)
      table.remove(self.out, c + 1)
      return
    end
  end
end

-- True when the last correction of segment s (m:last_correction) has a value straight after it, fillers and marks
-- between ("after EPVOK descend FL200, no sorry, FL220"): the value alone is said again, and what the instruction waits
-- for stands; a verb said again after it ("..., correction, descend now to FL150") may take the condition back too.
function G.value_corrected(self, s)
  local corr = self:last_correction(s)
  if not corr then return false end
  local k = corr + 1
  while self.t[k] and (self.t[k].kind == "punct" or self.t[k].filler) do k = k + 1 end
  local q = self:quantities(k, s.e)[1]
  return q ~= nil and q.b == k
end

-- ("RWD461 after EPVOK descend FL200, no sorry, FL220", "descend FL200 after EPVOK, I mean FL220"): a waypoint said
-- after a word that makes it what an instruction waits for ("after", "at", "passing", "past", "over", "abeam",
-- "reaching"), in a request that corrects itself after it (m:last_correction, or "sorry"), that no command names: the
-- correction has dropped the condition. Asked (does it still wait?), never sent now; "now" or "immediately" said after
-- the correction ("..., correction, descend now to FL150") takes the condition back.
function G:condition_lost_in_correction()
  local n = #self.t + 1
  local corr = self:last_correction({ b = 1, e = n })
  if self:said("sorry") then
    local k = self:find_word(1, n, "sorry")
    while k < n do
      corr = math.max(corr or k, k)
      k = self:find_word(k + 1, n, "sorry")
    end
  end
  if not corr or corr >= n or self:word_in(corr, n, "now immediately") then return end
  for _, r in ipairs(self:refs_in(1, #self.t + 1, "waypoint")) do
    local k = r.b - 1
    while k >= 1 and self.t[k].filler do k = k - 1 end
    if self:word(k, "after at passing past over abeam reaching overhead") and corr > r.b then
      local named = false
      for _, line in ipairs(self.out) do named = named or line:find("%f[%w]" .. r.name .. "%f[^%w]") ~= nil end
      if not named then
        self.ask = string.format("I have %s, but the correction leaves out '%s'. Should it still wait until %s, or "
          .. "run now?", table.concat(self.out, " ; "), self:raw(k, r.e), r.name)
        return
      end
    end
  end
end

-- The commands that wait for a condition before they run (BlueSky's conditional commands).
local CONDITIONAL = { AT = true, ATALT = true, ATSPD = true, ATDIST = true, DELAY = true, SCHEDULE = true }

-- The commands self.out[n0 + 1 ..] (each the aircraft `id`'s own, "CMD id ...") become BlueSky's
-- "AT id WPT DO CMD id ...": they run when the aircraft passes waypoint `wp` of its route. A command of
-- another aircraft or of none is asked about, as is a waypoint off the route, and so is a command that is itself
-- a condition ("I want it at FL250 and heading 200" read as ATALT ... HDG ...): a condition is never nested in
-- another; true when done. With no `id` (the first command names no aircraft: "pause ... when it reaches
-- MARIM") it is asked about too.
function G:do_at(id, wp, n0)
  local function whose()
    self.ask = string.format("I have %s. Which of these should happen at %s, and for which aircraft?",
      table.concat(self.out, " ; "), wp)
    return false
  end
  if not id then return whose() end
  if not self:on_route(id, wp) then
    self.ask = self:off_route_question(id, wp)
    return false
  end
  for c = n0 + 1, #self.out do
    local name = self.out[c]:match("^(%u+)")
    if CONDITIONAL[name] then
      self.ask = string.format("I have %s, a condition of its own, to run at %s, and squawk does not nest one "
        .. "condition in another. What should %s do at %s?", self.out[c], wp, id, wp)
      return false
    end
    if self.out[c]:match("^%u+ (%S+)") ~= id then return whose() end
    -- ("turn left 20 degrees passing LOMKI", "reduce 20 knots after LOMKI": a value counted from what the aircraft
    -- flies now is no value for later, when it may fly another)
    if not self:values_said(self.out[c]) then
      self.ask = string.format("I have %s, counted from what %s flies now, and at %s it may fly otherwise. What "
        .. "should %s do at %s?", self.out[c], id, wp, id, wp)
      return false
    end
  end
  for c = n0 + 1, #self.out do self.out[c] = "AT " .. id .. " " .. wp .. " DO " .. self.out[c] end
  return true
end

-- "keep flying at FL160 until HORTA and then descend FL110", "keep FL230 until PIVON, then descend": segment p,
-- a verb of keeping (lexicon.kept_as_is.verbs) and one level or speed, whose commands are self.out[n0 + 1 .. n1],
-- held until the waypoint where aircraft `id`'s next instruction starts. A level the aircraft is level at, with
-- that level selected (within 50 ft), changes nothing: its command is dropped, the words read as the limit. A speed
-- kept is always issued: it is the restriction said, and the aircraft's present speed may not be the one it will
-- hold ("keep 280 knots until DIPOS, then 250": `SPD X 280 ; AT X DIPOS DO SPD X 250`); so is a level the aircraft
-- passes or was given another of. Returns the number of commands dropped.
function G:kept_until(p, n0, n1, id)
  local qs = p and n1 == n0 + 1 and self:quantities(p.b, p.e) or {}
  if #qs ~= 1 or not self:word_in(p.b, qs[1].b, G.kept_sets.verbs) then return 0 end
  local cmd = self.out[n1]:match("^(%u+) " .. id:gsub("%p", "%%%0") .. " %S+$")
  local a = cmd == "ALT" and self:state(id)
  if not (a and a.alt_ft and math.abs(a.alt_ft - qs[1].value) <= 50
      and (a.sel_alt_ft == nil or math.abs(a.sel_alt_ft - a.alt_ft) <= 50)) then return 0 end
  table.remove(self.out, n1)
  return 1
end

-- "keep 280 knots until RINOR, which I believe is on its planned route", "... until BOSIO? I believe BOSIO is on its
-- route.", "? That is the Viseu beacon, on its planned route.": a clause (after a comma) or a sentence of
-- lexicon.route_remark's words that says "on its ... route" of places that are all on the route of the aircraft
-- named before it, no value and no aircraft in it, is set aside: it places nothing. A place said in it that is
-- off that route leaves it to be asked.
G.route_remark_sets = {}
for k, list in pairs(lexicon.route_remark) do G.route_remark_sets[k] = set_of(list) end
-- "maintain 270 knots until SUNSS; thereafter it may fly at its own discretion", "slow to 260 knots until CIVET, and
-- then resume its normal speed": after a limit until a place, a clause closing the request that opens with a word
-- of lexicon.limit_release.openers ("and" or "after that" too) and holds only its words, one of .release among
-- them, says the limit ends there, as the limit's note names: set aside (used and noted), so the limit is read as
-- said last. Anything else after it stays an instruction of its own.
G.limit_release = { words = set_of(lexicon.limit_release.words), release = set_of(lexicon.limit_release.release),
  openers = set_of(lexicon.limit_release.openers) }
function G:limit_released()
  if not self:said("until till") then return end
  local R = G.limit_release
  -- (a limit at the final approach's distance, "until 6 miles final", "till 4 DME": read as a place's, its last
  -- word the place's end; G:final_limits)
  local limits = {}
  for _, r in ipairs(self.refs) do limits[#limits + 1] = r end
  for _, r in ipairs(self:final_limits()) do limits[#limits + 1] = r end
  for _, r in ipairs(limits) do
    if r.kind == "waypoint" and self:word(r.b - 1, "until till") then
      local k = r.e
      -- ("until MOUAB keep 280 knots, then it is up to him": the limit said before its speed, the release after
      -- the speed; `lead`, the speed's quantity)
      local lead = self:quantities(r.e, #self.t + 1)[1]
      lead = lead and (lead.kind == "speed" or lead.kind == "mach") and #self:quantities(r.b - 1, r.e) == 0
        and not self:has_ref(r.e, lead.b, "waypoint") and lead
      if lead then k = lead.e end
      while self.t[k] and self.t[k].kind == "punct" do k = k + 1 end
      if self:word(k, "and") then k = k + 1 end
      local open = k
      if self:word(k, "after") and self:word(k + 1, "that") then k = k + 2 elseif self:word(k, R.openers) then k = k + 1 end
      local e, released = k, false
      while k > open and self.t[e] and (self.t[e].filler or self:word(e, R.words)) do
        released = released or self:word(e, R.release)
        e = e + 1
      end
      local rest = e
      while self.t[rest] and self.t[rest].kind == "punct" and self.t[rest].text ~= "," do rest = rest + 1 end
      if released and rest > #self.t then
        if lead then
          self:mark_used(r.b - 1, r.e)
          for x = r.b - 1, r.e - 1 do self.noted[x] = true end
          self:mark_used(lead.e, e)
          for x = lead.e, e - 1 do self.noted[x] = true end
        else
          self:mark_used(r.e, e)
          for x = r.e, e - 1 do self.noted[x] = true end
        end
      end
    end
  end
end

-- The limits at the final approach's distance said after "until" or "till": a count 3 to 6, then its unit or
-- "final" ("until 6 miles final", "till 4 DME", "until 5 miles on final"), "final" or "dme" among its words. Each is
-- returned as a place, { kind = "waypoint", b = the count's token, e = the token after its last word }.
G.final_limit_words = set_of({ "dme", "miles", "mile", "nm", "final", "on", "out", "from", "touchdown", "threshold",
  "the" })
function G:final_limits()
  local found = {}
  for i = 1, #self.t - 2 do
    local n = self.t[i + 1]
    if self:word(i, "until till") and n and (n.kind == "number" and n.text:match("^[3-6]$")
        or self:word(i + 1, "three four five six")) then
      local k, final = i + 2, false
      while self.t[k] and self.t[k].kind == "word" and G.final_limit_words[self.t[k].text] do
        final = final or self:word(k, "final dme")
        k = k + 1
      end
      if final then found[#found + 1] = { kind = "waypoint", b = i + 1, e = k } end
    end
  end
  return found
end

-- "CSA6AT descend 5000 feet, he goes to Mosnov": where the aircraft named before goes, told in a clause of its own
-- after an instruction (lexicon.destination_told), is a remark when the place (one to three words to the clause's
-- end: an ident, or an airport's name) is on that aircraft's route or its destination: set aside, nothing set.
-- Told in the progressive ("..., he is going to Hurghada") with no word of lexicon.destination_preface.change in the
-- request, it is a state wherever the place is: set aside. Another place told in the simple present ("he goes
-- to Luxor") is left to the instructions (a new destination may be meant).
G.destination_told_sets = {}
for k, list in pairs(lexicon.destination_told) do G.destination_told_sets[k] = set_of(list) end
function G:destination_told()
  local D = G.destination_told_sets
  if not (self:said(D.subjects) and self:said(D.motion)) then return end
  for b = 2, #self.t - 2 do
    local opens = self.t[b - 1].kind == "punct" or (self:word(b - 1, "and") and b > 2 and self.t[b - 2].kind == "punct")
    if opens and self:word(b, D.subjects) then
      local k, moved, be = b + 1, false, self:word(b, "he's she's it's they're")
      while self:word(k, D.verbs) do
        moved = moved or self:word(k, D.motion)
        be = be or self:word(k, "is are 's")
        k = k + 1
      end
      -- (the progressive, "he is going to Hurghada", "it's heading for Luxor", is a state told: set aside
      -- wherever the place is, unless a word of change is said: "..., he is going to Luxor now")
      local state = be and moved and self.words[k - 1] and self.words[k - 1]:match("ing$") ~= nil
          and not self:said(G.destination_preface_sets.change)
      local e = k + 1
      while e <= #self.t and e < k + 4 and self.t[e].kind == "word" and self.t[e].raw:match("^%u") do e = e + 1 end
      local id
      for _, r in ipairs(self.refs) do
        if r.kind == "aircraft" and r.exists and r.e <= b then id = r.name end
      end
      local a = id and self:state(id)
      if moved and self:word(k, D.to) and e > k + 1 and (e > #self.t or self.t[e].kind == "punct") and a
          and self:any_instruction_in(1, b) and not self:has_ref(b, e, "aircraft") then
        local held = {}
        for _, x in ipairs(a.route or {}) do held[x:upper()] = true end
        if a.dest and a.dest ~= "" then held[a.dest:upper()] = true end
        local phrase = self:raw(k + 1, e)
        local w, found = self.world, held[phrase:upper()] == true or state
        for _, list in ipairs({ w.airports_named and w.airports_named(phrase) or {},
            w.airports_with_words and a.lat and w.airports_with_words(phrase, a.lat, a.lon, lexicon.navaid_range_nm) or {},
            w.airports_of_city and w.airports_of_city(phrase) or {},
            w.airports_named and lexicon.city_airports[phrase:lower()] and w.airports_named(lexicon.city_airports[phrase:lower()]) or {} }) do
          for _, x in ipairs(list) do found = found or held[x:upper()] == true end
        end
        if found then self:set_aside(b, e - 1) end
      end
    end
  end
end

-- "The Korean Air is going to Jeju, please make it descend to FL150": where the aircraft named first goes, stated as a
-- fact in the request's opening clause (lexicon.destination_preface: the aircraft, "is"/"are", a verb of going, "to",
-- the place of one to three words to a comma or full stop) with an instruction said after it, no other aircraft
-- named, is context for that instruction: set aside, nothing set (the aircraft stays named, for "it" after). A word of .change anywhere in the
-- request ("..., it is going to Gimpo now", "set it as destination") leaves it to the rules (DEST), as does the
-- statement said alone.
G.destination_preface_sets = {}
for k, list in pairs(lexicon.destination_preface) do G.destination_preface_sets[k] = set_of(list) end
function G:destination_preface()
  local D = G.destination_preface_sets
  if not (self:said(D.verbs) and self:said(D.to)) or self:said(D.change) then return end
  local r = self.refs[1]
  for _, x in ipairs(self.refs) do
    if x.kind == "aircraft" and (not r or x.b < r.b or r.kind ~= "aircraft") then r = x end
  end
  if not (r and r.kind == "aircraft" and r.exists) or self:any_instruction_in(1, r.b) then return end
  local b = r.e
  if not (self:word(b, D.be) and self:word(b + 1, D.verbs) and self:word(b + 2, D.to)) then return end
  local e = b + 3
  while e <= #self.t and self.t[e].kind == "word" and e < b + 6 do e = e + 1 end
  local t = self.t[e]
  if e == b + 3 or not (t and t.kind == "punct" and (t.text == "," or t.text == ".")) then return end
  -- (only the aircraft named is instructed after it: "..., and the Asiana climb FL300" is another's request)
  if self:has_ref(b + 3, #self.t + 1, "aircraft") or not self:any_instruction_in(e + 1, #self.t + 1) then return end
  self:set_aside(b, e - 1)
end

function G:route_remarks()
  local R = G.route_remark_sets
  if not self:said(R.route_nouns) then return end
  local function sentence_end(k)
    local t = self.t[k]
    return t and t.kind == "punct" and t.text ~= "," and t.text ~= "-" and t.text ~= "'"
  end
  for k = 1, #self.t - 2 do
    if self:word(k, "on") and self:word(k + 1, "its") and not self.noted[k] then
      local n = k + 2
      while self:word(n, "planned filed flight") do n = n + 1 end
      if self:word(n, R.route_nouns) then
        local b = k
        while b > 1 and self.t[b - 1].kind ~= "punct" do b = b - 1 end
        -- (a comma before a clause that describes the place: from the sentence's start, "That is the Viseu
        -- beacon, on its planned route")
        if b > 2 and self.t[b - 1].text == "," and (b == k or not self:word(b, "which that")) then
          local s0 = b - 2
          while s0 > 1 and not sentence_end(s0 - 1) and self.t[s0 - 1].text ~= "," do s0 = s0 - 1 end
          if self:word(s0, "that this it which") then b = s0 end
        end
        local e = n + 1
        if not (b > 1 and (sentence_end(b - 1) or self.t[b - 1].text == ",")) or e <= #self.t and self.t[e].kind ~= "punct" then
          b = nil
        end
        local id
        for _, r in ipairs(self.refs) do
          if b and r.kind == "aircraft" and r.e <= b then id = r.name end
        end
        local ok = b and id and #self:quantities(b, e) == 0 and #self:refs_in(b, e, "aircraft") == 0
        for x = b or 1, ok and e - 1 or 0 do
          local t = self.t[x]
          local place = self:refs_in(x, x + 1, "waypoint")[1]
          if place then
            ok = ok and self:on_route(id, place.name)
          elseif t.kind == "word" and not self:word(x, R.words) then
            -- (a place's name before its noun: "the Viseu beacon")
            ok = ok and t.raw:match("^%u") ~= nil and self:word(x + 1, R.place_nouns)
          elseif t.kind ~= "word" and t.text ~= "," then
            ok = false
          end
        end
        if ok then self:set_aside(b, e - 1) end
      end
    end
  end
end

-- True when the words from k are a level or speed wanted, no instruction word: "I want it at FL250", ", I'd like
-- him at 250 knots", "it should be at FL250" (words of lexicon.held_value, then the value ending the request).
local HELD = set_of(lexicon.held_value)
function G:held_value(k)
  local q = self:quantities(k, #self.t + 1)[1]
  if not q or not ((q.kind == "alt" and q.fl) or q.kind == "speed" or q.kind == "mach") or not self:word(q.b - 1, "at") then
    return false
  end
  for x = k, #self.t do
    local t = self.t[x]
    if (x < q.b or x >= q.e) and not (t.kind == "punct" or t.filler or (x < q.b and HELD[self.words[x]])) then
      return false
    end
  end
  return not self:any_instruction_in(k, #self.t + 1)
end

-- The instructions after a condition at a waypoint (G:condition: self.at_place) run when the condition's
-- aircraft passes it: BlueSky's AT acid wp DO with each full command (G:do_at). A level or speed wanted
-- there (G:held_value: "when AFR1234 gets to GIROM I want it at FL250") is met there: the constraint
-- AT acid wp ALT/SPD, as "be at FL250 over GIROM".
function G:at_condition()
  if not self.at_held then return self:do_at(self.subject, self.at_place, 0) end
  for c = 1, #self.out do
    local cmd, id, v = self.out[c]:match("^(%u+) (%S+) (%S+)$")
    if not ((cmd == "ALT" or cmd == "SPD") and id == self.subject) then
      self.ask = string.format("I have %s. Which of these should be met at %s, and for which aircraft?",
        table.concat(self.out, " ; "), self.at_place)
      return
    end
    self.out[c] = string.format("AT %s %s %s %s", id, self.at_place, cmd, v)
  end
end

-- ---- segments: one instruction each ----
local function same_family(a, b)
  local ia, ib = M.intents[a], M.intents[b]
  return a == b or (ia and ib and ia.family ~= nil and ia.family == ib.family)
end

-- True when another flying aircraft opens a clause straight before the instruction word at i,
-- after segment `last`'s ("AUA123 climb FL250; DLH6CK descend FL200", "... knots. DLH6CK speed 260",
-- "AUA123 reduce 250 DLH6CK reduce 240"): after a punctuation mark, "and" or the previous instruction's
-- value, the aircraft and then (fillers and a turn side aside) the word itself. The instruction is that
-- aircraft's, never merged into the one before.
function G:addressee_between(last, i)
  local before = {}
  for _, r in ipairs(self:refs_in(last.b, last.trig, "aircraft")) do before[r.name:upper()] = true end
  local start = self:word(i - 1, "@left @right") and i - 1 or i
  for _, r in ipairs(self:refs_in(last.trig + 1, start, "aircraft")) do
    local qs = self:quantities(last.trig, r.b)
    local opens = self.t[r.b - 1] and (self.t[r.b - 1].kind == "punct" or self:word(r.b - 1, "and")
      or (qs[1] ~= nil and qs[#qs].e == r.b))
    if r.exists and opens and not before[r.name:upper()] and self:skip_fillers(r.e) == start then return true end
  end
  return false
end

-- True when quantity q (or nil) names what it sets by its own unit: a flight level, knots, a Mach, "heading N".
function G.unit_value(q)
  return q ~= nil and (q.kind == "alt" and q.fl or q.kind == "speed" or q.kind == "mach" or q.kind == "heading")
end

-- The kinds of value an instruction said after its value (verb-final order) takes from before its word.
local VERB_FINAL_KINDS = { alt = { alt = true }, spd = { speed = true, mach = true }, hdg = { heading = true } }
-- "spd 300 then at 300 kts fl240", "speed 220 and at 220 descend FL180", "spd 280, when at 280 climb FL200": the
-- speed just given said again after "at" ("when at", "once at") opening a clause after it (a comma, "and" or a
-- word of lexicon.then_words before) is the speed what follows in that clause waits for (ATSPD). For "at" at
-- token a, G:speed_again_at gives that speed's quantity (knots, Mach or a bare number, "speed" allowed before it)
-- when the last instruction word before it is a speed's and its value is the same; else nil. Kept in
-- self.speed_again[a] by G:segments, for G:at_speed_again.
-- The first token of the opening of the "at" at a: a condition word before it, with the subject and a form of "be"
-- between or not ("when at", "when it is at", Italian-English "when is at"); else a.
function G:speed_again_open(a)
  local c = a - 1
  while c > a - 4 and self:word(c, "it it's is he he's she she's 's") do c = c - 1 end
  if self:word(c, "@condition") then return c end
  return a
end

function G:speed_again_at(a)
  if not self:word(a, "at") then return nil end
  local k = self:speed_again_open(a) - 1
  local t = self.t[k]
  if not (t and ((t.kind == "punct" and t.text == ",") or self:word(k, "and @then_words"))) then return nil end
  local v = self:word(a + 1, "speed airspeed") and a + 2 or a + 1
  -- (the speed and the one given are looked for in a few words each: a value of three tokens at most, "220 kts", its
  -- instruction word at most three before it, "reduce speed to 220")
  local q = self:quantities(v, math.min(#self.t + 1, v + 3))[1]
  if not (q and q.b == v and (q.kind == "speed" or q.kind == "mach" or q.kind == "plain")) then return nil end
  local before = self:quantities(math.max(1, k - 6), k)
  local given = before[#before]
  local j = given and self:skip_fillers(given.e)
  while j and j < a and (self:word(j, "@then_words @condition") or (j >= self:speed_again_open(a) and j < a)) do
    j = self:skip_fillers(j + 1)
  end
  if not (j == a and given.value == q.value) then return nil end
  if given.kind == "speed" or given.kind == "mach" then return q end
  -- (a bare number is the speed given only straight after a speed's instruction word, "to" between at most)
  local p = self:word(given.b - 1, "to") and given.b - 2 or given.b - 1
  return given.kind == "plain" and self:intent_at(p) == "spd" and q or nil
end

-- The condition of segment s opened by a speed said again (G:speed_again_at, kept in self.speed_again): "ATSPD id
-- value" when only "and", "then", a condition word or marks come before its "at" in s, only fillers, commas and
-- lexicon.condition_lead between the speed and s.trig, and this request gave aircraft id that speed already
-- (SPD id value issued). The speed is marked used.
function G:at_speed_again(s)
  local a = s.b
  while a < s.trig and (self.t[a].kind == "punct" or self:word(a, "and @then_words @condition")
      or (self:word(a, "it it's is he he's she she's 's") and self:speed_again_open(self:find_word(a, s.trig, "at")) < a)) do
    a = a + 1
  end
  local q = self.speed_again[a]
  if not q then return nil end
  local k = self:skip_fillers(q.e)
  -- ("turn it on the left heading 300": a turn's side and its preposition, before the heading's word)
  while k < s.trig and (self:word(k, "@condition_lead") or (s.intent == "hdg" and (self:word(k, "left right it")
      or (self:word(k, "on to the") and self:word_in(k + 1, math.min(s.trig, k + 3), "left right"))))) do
    k = self:skip_fillers(k + 1)
  end
  local ids = k == s.trig and self:acids(s) or {}
  local f = handlers.format
  local mach = q.kind == "mach" or (q.kind == "plain" and q.value > 0 and q.value < 1)
  local spd = #ids == 1 and "SPD " .. ids[1] .. " " .. (mach and f.mach(q.value) or f.int(q.value))
  local given
  for _, line in ipairs(spd and self.out or {}) do
    if line:sub(-#spd) == spd and (line == spd or line:sub(-#spd - 1, -#spd - 1) == " ") then given = line end
  end
  if not given then return nil end
  -- (the speed itself waits, "delay 90 klm12 spd 250, then at 250 kts fl300": two waits, which squawk cannot nest)
  if given ~= spd then
    return self:need(string.format("I have %s. '%s' waits already: should what follows wait for it as well as for "
      .. "%s? Please give the two separately.", table.concat(self.out, " ; "), given, self:raw(a, q.e)))
  end
  self:mark_used(q.b, q.e)
  return "AT" .. spd
end

-- Segment k of `segs` ends at token cut, and an "infer" segment from cut to its end, its instruction word at trig,
-- follows it.
function G.split_segment(segs, k, cut, trig)
  table.insert(segs, k + 1, { intent = "infer", b = cut, trig = trig, e = segs[k].e })
  segs[k].e = cut
end

-- "klm501 speed 220 and at 220 fl180": a speed said again (G:speed_again_at) inside a speed instruction's segment,
-- with a value of its own unit but a speed's after it in the clause, opens an instruction of its own (an "infer"
-- segment from the "at", its instruction word the value's first token, in place in `segs`).
function G:speed_again_split(segs)
  for k = #segs, 1, -1 do
    local sg = segs[k]
    for a = (sg.intent == "spd" or sg.intent == "infer") and sg.trig + 1 or sg.e, sg.e - 1 do
      local q = self.speed_again[a]
      local nx = q and self:skip_fillers(q.e)
      local v = nx and self:quantities(nx, sg.e)[1]
      if v and v.b == nx and G.unit_value(v) and v.kind ~= "speed" and v.kind ~= "mach" then
        G.split_segment(segs, k, self:speed_again_open(a), v.b)
        break
      end
    end
  end
end

function G:segments(b, e)
  local trig = {}
  self.speed_again = {}
  -- (G:speed_again_at reads an "at" only)
  for i = self:said("at") and b or e, e - 1 do
    if self.words[i] == "at" then self.speed_again[i] = self:speed_again_at(i) end
  end
  for i = b, e - 1 do
    -- (a word in a reason, "so we get the same run each time", starts no instruction)
    local intent = self:intent_at(i)
    -- ("when level at 8000 reduce 190": "level" after a condition word and before "at" is the condition's)
    if intent and self:word(i, "level") and self:word(i - 1, "when once") and self:word(i + 1, "at") then intent = nil end
    if intent and not self:in_reason(i) then
      trig[#trig + 1] = { intent = intent, pos = i }
      self.triggers[i] = true
      -- ("note for the log: run 4, MVP on"): a note's text after its colon is the note, whole
      local colon = false
      for k = i + 1, math.min(e, i + 5) - 1 do
        colon = colon or (intent == "echo" and self.t[k].kind == "punct" and self.t[k].text == ":")
      end
      if colon then break end
    end
  end
  local segs = {}
  if #trig == 0 then
    local segs = { { intent = "infer", b = b, trig = b, e = e } }
    self:speed_again_split(segs)
    return segs
  end
  -- "KLM601 FL210, then ff 4 min": a callsign and a value with its own unit, a clause before the first
  -- instruction word, are an instruction of their own
  -- (up to a speed said again after "at", "klm12 220 kts then at 220 kts descend FL180": G:speed_again_at)
  local own_e = trig[1].pos
  for a = b, own_e - 1 do if self.speed_again[a] then own_e = a break end end
  local qs = self:quantities(b, own_e)
  -- ("hop7 fl100 in 2 min, hdg 220", "... in 2 min and hdg 220": a wait said after the value is the value's own
  -- clause, which "and" closes too)
  local timed = #qs > 1 and qs[#qs].kind == "time"
  -- (a wait opening the request, "in 2 min klm33 fl200 and ryr8 hdg 240", is no value of the clause)
  if qs[1] and qs[1].kind == "time" and #qs > 1 and not self:has_ref(b, qs[1].b, "aircraft") then table.remove(qs, 1) end
  if timed then qs = { table.unpack(qs, 1, #qs - 1) } end
  local own = G.unit_value(qs[#qs])
  -- ("Wizz Air 3117, negative, flight level 280, descend": a level with only a comma between it and a climb or
  -- descent that has no value of its own is that verb's)
  if own and qs[#qs].kind == "alt" and trig[1].intent == "alt"
      and #self:quantities(trig[1].pos, trig[2] and trig[2].pos or e) == 0 then
    local k = qs[#qs].e
    while k < trig[1].pos and self.t[k].kind == "punct" and self.t[k].text == "," do k = k + 1 end
    own = k ~= trig[1].pos
  end
  -- (a condition said in the clause keeps it whole; one after the clause's end, "klm33 fl260, once level hdg 300",
  -- opens the next instruction)
  if own and self:has_ref(b, qs[1].b, "aircraft") then
    local last_k = trig[1].pos - ((self:word(trig[1].pos, "then") and self:until_then_value(trig[1].pos)) and 0 or 1)
    for k = qs[#qs].e, self:word_in(b, qs[#qs].e, "@level_condition @condition") and 0 or last_k do
      -- ("klm33 fl220 and ryr8 hdg 240", "klm33 fl220 ryr8 hdg 240": another flying aircraft after "and" or
      -- straight after the value parts them as a comma does)
      local at = (self:word(k, "and") and k + 1) or (k == qs[#qs].e and k)
      local other = at and self:refs_in(at, at + 1, "aircraft")[1]
      -- (the aircraft the value is said to: the last named before it, "X and Y: Aeroflot keeps level 230 and X ...")
      local named = other and self:refs_in(b, qs[1].b, "aircraft") or {}
      local first = named[#named]
      -- ("200 knots until MAH and after MAH 180 knots": "and" opening the value again from the same place,
      -- G:after_place_value, parts them as a comma does)
      if self.t[k].kind == "punct" or self:word(k, "@then_words") or (timed and self:word(k, "and"))
          or (self:word(k, "and") and self:word(k + 1, "after") and self:after_place_value(k + 1)) or (other and other.exists
          and other.name:upper() ~= first.name:upper()) then
        -- ("BTI6AL 200 knots until ROKLA then 180": a limit until a place, the value again after it, G:until_then_value)
        if not self:word_in(qs[#qs].e, k, "@level_condition @condition") or self:until_then_value(k) then
          segs[1] = { intent = "infer", b = b, trig = b, e = k }
        end
        break
      end
    end
  end
  for k, tr in ipairs(trig) do
    local last = segs[#segs]
    local this = M.intents[tr.intent]
    -- "descend 4000 then reduce 210": the second waits for the first ("then");
    -- "..., then ..." after a comma, and "... and then ...", are the next instruction in a list ("list")
    local thn_at = self:find_word(k == 1 and b or trig[k - 1].pos, tr.pos, "@then_words")
    local before_then = self.t[thn_at - 1] or {}
    local listed = before_then.kind == "punct" or self:word(thn_at - 1, "and")
    local thn = thn_at < tr.pos and (listed and "list" or "then") or false
    local merged = false
    if last and not thn then
      local li = M.intents[last.intent] or {}
      -- ("add SUGOL at FL200 and speed 250" is one waypoint; "route it via SUGOL and give it 280 knots",
      -- a verb after "and", is a speed of its own)
      local own_verb = last.intent == "addwpt" and self:word(tr.pos - 1, "and")
        and not self:word(tr.pos, "speed spd altitude alt heading hdg level fl")
      -- ("add KWA, and speed 250", "add SPY to the route and altitude FL200": a value's noun after "and", with no
      -- value, "at" or "with" said for the waypoint before it, is an instruction of its own, never its constraint)
      own_verb = own_verb or (last.intent == "addwpt" and self:word(tr.pos - 1, "and")
        and #self:quantities(last.trig, tr.pos) == 0 and not self:word_in(last.trig + 1, tr.pos, "at with"))
      -- ("create JST802 ... 3000 feet, 180 knots, and instruct it to climb to FL280": a verb of its own after a
      -- creation that already holds the value that verb sets is an instruction to the new aircraft)
      -- (its own value said after it: "..., going to climb" with none stays the creation's question)
      local sets = VERB_FINAL_KINDS[tr.intent]
      local next_q = sets and self:quantities(tr.pos, e)[1]
      for _, q in ipairs(last.intent == "create" and next_q and sets[next_q.kind] and self:word(tr.pos, "@clause_verbs")
          and self:quantities(last.trig, tr.pos) or {}) do
        own_verb = own_verb or sets[q.kind] == true
      end
      if (li.absorbs and this.value and not own_verb)
          or (last.intent == "alt" and tr.intent == "vs" and self:word(tr.pos, "rate")
            and not self:word_in(last.trig + 1, tr.pos, "@level_condition"))
          -- ("descend with vertical speed 1000 feet per minute": the climb's or descent's manner, "with" straight
          -- after its verb)
          or (last.intent == "alt" and tr.intent == "vs" and tr.pos == last.trig + 2 and self:word(tr.pos - 1, "with")
            and (self:quantities(tr.pos, e)[1] or {}).kind == "vs") then
        merged = true
      elseif last.intent == "create" and tr.intent == "create" and #self:refs_in(last.trig, tr.pos, "aircraft") == 0 then
        merged = true  -- "make a new ...": one request
      else
        local alt_pair = ((last.intent == "maintain" and tr.intent == "alt") or (last.intent == "alt" and tr.intent == "maintain"))
          and #self:quantities(last.trig, tr.pos) == 0 and not self:word_in(last.trig, tr.pos, "@correction")
        -- ("maintain heading", "maintain your present heading": the heading kept, one instruction; "when level
        -- maintain speed 270": "maintain" straight before "speed" is the speed's verb, its condition with it)
        local kept_noun = last.intent == "maintain" and ((tr.intent == "hdg" and self:word(tr.pos, "heading hdg"))
          or (tr.intent == "spd" and self:word(tr.pos, "speed spd") and tr.pos == last.trig + 1))
        for k = last.trig + 1, kept_noun and tr.pos - 1 or 0 do
          kept_noun = kept_noun and self:word(k, "your the its @present")
        end
        -- ("descend FL300, 25 miles before KOK descend FL260": a distance from a place opening the second
        -- instruction's clause, after the first's value, is that instruction's condition, no repeat)
        local dist_between = false
        local between = (last.intent == tr.intent or alt_pair) and this.value and self:quantities(last.trig, tr.pos)
        for _, q in ipairs(between or {}) do
          local k = self:skip_fillers(q.e)
          dist_between = dist_between or (q.kind == "dist" and #self:quantities(last.trig, q.b) > 0
            and self:word(self:word(k, "out prior") and k + 1 or k, "from of to before"))
          -- ("reduce speed 250 knots, when passing FL150 reduce speed 210 knots": likewise a level passed,
          -- reached or left after a condition word)
            or (q.kind == "alt" and #self:quantities(last.trig, q.b) > 0 and self:word(q.b - 1, "passing reaching leaving")
              and self:word(q.b - 2, "@condition"))
          -- ("reduce 280, passing FL230 reduce 250", "speed 250, above FL100 speed 300", "reduce 210, when level at
          -- 8000 reduce 190": a level passed, crossed or levelled at opening the second's clause, G:level_opening)
            or (G.level_value(q) and tr.intent == "spd" and #self:quantities(last.trig, q.b) > 0 and self:level_opening(q.b))
          -- ("descend FL300, and after 2 minutes descend FL260", "heading 230, then in 3 minutes back to heading
          -- 190": a wait after "and" or "then" and "after" or "in", after the first's value, is the second's; after a
          -- comma alone it stays asked)
            or (q.kind == "time" and #self:quantities(last.trig, q.b) > 0 and self:word(q.b - 1, "after in")
              and self:word(q.b - 2, "and then"))
        end
        -- ("reduce 270 after GAVOL speed 250": a waypoint passed after the first's value, straight before the
        -- second instruction word, is the second's condition)
        if between and #between > 0 then
          local w = self:refs_in(between[1].e, tr.pos, "waypoint")
          local r = w[#w]
          dist_between = dist_between or (r ~= nil and self:skip_fillers(r.e) == tr.pos
            and (self:word(r.b - 1, "after passing over leaving reaching") or self:passes_said(r.b - 1)
              or (self:word(r.b - 1, "pass") and self:word(r.b - 2, "after when once"))))
          -- ("reduce 230, when level reduce 210": the level reached, "when/once (it's) level", likewise)
          local lv = tr.pos - 1
          while lv > between[1].e and self.t[lv].kind == "punct" do lv = lv - 1 end
          local wh = self:word(lv, "level") and self:reached_opening(lv)
          dist_between = dist_between or (wh and wh >= between[1].e)
          -- (likewise a place said by its name, one or two capitalised words: "reduce 220, reaching Taunus reduce 210")
          for n = 1, 2 do
            local p, named = tr.pos - n, true
            for k = p, tr.pos - 1 do
              named = named and self.t[k].kind == "word" and self.t[k].alpha and self.t[k].raw:match("^%u") ~= nil
                and not self.t[k].keyword
            end
            dist_between = dist_between or (named and p - 1 > between[1].e - 1
              and self:word(p - 1, "after passing over leaving reaching"))
          end
        end
        -- ("speed 250 until ten thousand, then 300": the first ended at a level straight before the second's "then",
        -- which waits for it, G:until_level_then)
        if between then
          local u = self:find_word(last.trig + 1, tr.pos, "until till")
          dist_between = dist_between or (u < tr.pos and self:until_level_end(u) == tr.pos)
        end
        -- ("reduce speed 250, after SUMAG 220": a value again from a place opens its own instruction, G:after_place_value)
        if (last.intent == tr.intent or alt_pair or kept_noun) and not this.single
            and not self:addressee_between(last, tr.pos) and not dist_between and not self:word(tr.pos, "after")
            and not (self:word(tr.pos, "then @until_then_words") and self:until_then_value(tr.pos)
              and not (trig[k + 1] and trig[k + 1].pos == self:skip_fillers(tr.pos + 1))) then
          if tr.intent == "alt" or kept_noun then last.intent = tr.intent end
          merged = true
        end
      end
    end
    -- "create NKS1021 A320 ... and then UPS2951 B763 at ...": a new callsign and its type after "then"
    -- open another creation, its values the creation's (M:create makes each aircraft)
    if last and thn and last.intent == "create" and this.value then
      for _, r in ipairs(self:refs_in(thn_at + 1, tr.pos, "aircraft")) do
        merged = merged or (not r.exists and #self:refs_in(r.e, math.min(tr.pos, r.e + 2), "type") > 0)
      end
    end
    if not merged then
      -- an aircraft named just before the instruction word is its subject, not
      -- the previous instruction's ("EZY45 turn left 300 and AFR1234 descend")
      local start = tr.pos
      if last then
        -- "speed 300, DLH9CE, left heading 200": a turn's direction said straight before its
        -- instruction word is the turn's, and so is the aircraft named before that
        if this.cmd == "HDG" and self:word(start - 1, "@left @right") and start - 1 > last.trig then start = start - 1 end
        -- ("... and klm1243 dct... uh no, hdg 060": an instruction cut off and taken back after the callsign,
        -- G:self_corrected's cut_back, parts it from the instruction said in its place no more than a filler)
        for _, r in ipairs(self:refs_in(last.trig + 1, start, "aircraft")) do
          local after = self:skip_fillers(r.e)
          if self.cut_back[after] then after = self:skip_fillers(self.cut_back[after]) end
          -- (the infinitive's "to" between: "..., and Aeroflot 1878 to stop descent at FL240", "UTair 235 to keep
          -- level 360": the aircraft is still this instruction's subject)
          -- (and a verb ending a movement before the instruction word: "..., and Aeroflot stop descent at level 240")
          -- (a possessive after the verb: "Aeroflot 1878 to stop your descent at level 250")
          -- (a verb that names no value of its own between, or courtesy: "..., EZY2 fly heading 310", "..., EZY2
          -- please go to heading 310": the aircraft is this instruction's subject)
          while after < start and self:word(after, "please kindly now fly go") do after = self:skip_fillers(after + 1) end
          if after < start and self:word(after, "to") then after = self:skip_fillers(after + 1) end
          while after < start and self:word(after, "fly go") do after = self:skip_fillers(after + 1) end
          local obj = self:word(after, "@halted") and self:skip_fillers(after + 1)
          if obj and self:word(obj, "your its his her their the") then obj = self:skip_fillers(obj + 1) end
          if obj == start then after = start end
          if after == start then start = r.b end
        end
        -- "heading 070, FL240 climb, speed 300": a value with this instruction's unit said just before its word,
        -- after a comma or "and" closing the instruction before with a value of its own, is this one's
        -- (verb-final order; "to" before the value with it)
        local own_kinds = VERB_FINAL_KINDS[tr.intent]
        local qb = own_kinds and self:quantities(last.trig + 1, start) or {}
        local q, prior = qb[#qb], qb[#qb - 1]
        if prior and own_kinds[q.kind] and self:skip_fillers(q.e) == start then
          local qs = self:word(q.b - 1, "to") and q.b - 1 or q.b
          local closed = false
          for k = prior.e, qs - 1 do
            closed = closed or self:word(k, "and") or (self.t[k].kind == "punct" and self.t[k].text == ",")
          end
          if closed then start = qs end
        end
        -- "..., when passing flight level 130 reduce speed": the condition belongs to what follows it
        local cond = self:find_word(last.trig + 1, start, "@level_condition")
        -- (and ", as soon as it's through FL140 speed 240")
        local soon = self:find_word(last.trig + 1, cond, "soon")
        if soon < cond and self:word(soon - 1, "as") and self:word(soon + 1, "as") then cond = soon - 1 end
        -- ("descend FL100 after 2 minutes turn left": a wait nothing parts from the value before is asked, G:at_time)
        local waited = self:word(cond, "after") and self:quantities(cond + 1, start)[1]
        if waited and waited.kind == "time" and waited.b == cond + 1 and not self:linked(cond) then cond = start end
        if cond < start then start = cond end
        -- (", above FL100 speed 300": a bare bound before a speed's word, after the last instruction's value, opens
        -- the speed's clause, G:bare_bound)
        for _, q in ipairs(tr.intent == "spd" and self:quantities(last.trig + 1, start) or {}) do
          if G.level_value(q) and self:bare_bound(q.b - 1) and #self:quantities(last.trig, q.b) > 0 then
            start = math.min(start, q.b - 1)
            break
          end
        end
        -- (", in 2 minutes turn left heading 220", "and in 2 min EZY45 descend": a wait after "in" opening the clause
        -- straight before the instruction word, after the instruction before's value, is this one's, as "after 2
        -- minutes" is)
        local wait = self:find_word(last.trig + 1, start, "in")
        local tq = wait < start and self:quantities(wait + 1, start)[1]
        -- ("in about 2 minutes", "in like three minutes": a hedge between)
        local tb = wait + 1
        while tq and tb < tq.b and (self.t[tb].filler or self:word(tb, "@wait_hedges like")) do tb = tb + 1 end
        if tq and tq.kind == "time" and tq.b == tb and self:skip_fillers(tq.e) == start and self:linked(wait)
            and #self:quantities(last.trig, wait) > 0 then
          start = wait
        end
        -- (", leave BIG heading 270": "leave" and the waypoint straight before the instruction word open its clause)
        for _, r in ipairs(self:refs_in(last.trig + 1, start, "waypoint")) do
          if self:skip_fillers(r.e) == start and self:word(r.b - 1, "leave") and r.b - 1 > last.trig then
            start = r.b - 1
          end
        end
        -- (the distance of a condition said before the instruction word, with "at" or "within" before it; a
        -- level after "at" opening a clause after the last instruction's value, before a speed or heading:
        -- "climb FL360, at FL350 it shall reduce to Mach .77", "climb FL160 then at FL160 speed 280", "... and
        -- at FL140 ..."; never a creation's "..., at 37,000 feet")
        -- (likewise the speed given said again after "at": G:speed_again_at)
        for a = last.trig + 1, start - 1 do
          if self.speed_again[a] then start = self:speed_again_open(a) break end
        end
        for _, q in ipairs(self:quantities(last.trig + 1, start)) do
          local k = self:skip_fillers(q.e)
          -- (a bare number of 1000 or more after "at" is a level in feet too: "climb 7000, at 7000 turn right")
          local level = q.kind == "alt" or (q.kind == "plain" and q.value >= 1000 and self:word(q.b - 1, "at"))
          if level and (tr.intent == "spd" or tr.intent == "hdg") and last.intent ~= "create"
              and (self:at_clause(q) or self:on_clause(q.b - 1)) and #self:quantities(last.trig, q.b) > 0 then
            start = math.min(start, q.b - 1)
            break
          end
          if q.kind == "dist" and #self:quantities(last.trig, q.b) > 0
              and self:word(self:word(k, "out prior") and k + 1 or k, "from of to before") then
            start = math.min(start, self:word(q.b - 1, "at within") and q.b - 1 or q.b)
            break
          end
        end
        last.e = start
      end
      segs[#segs + 1] = { intent = tr.intent, b = last and start or b, trig = tr.pos, e = e, ["then"] = thn }
    end
  end
  -- "dct PTH, once there fl 80": a value said after "once/when there" closing a direct-to is an
  -- instruction of its own that waits for the waypoint (G:parse)
  for k = #segs, 1, -1 do
    local sg = segs[k]
    if sg.intent == "direct" then
      local c = self:find_word(sg.trig + 1, sg.e, "@condition")
      local v = c < sg.e and self:word(c + 1, "there") and self:skip_fillers(c + 2)
      if v and v < sg.e and (self:quantities(v, sg.e)[1] or {}).b ~= nil then
        local cut = c
        while cut - 1 > sg.trig and (self.t[cut - 1].kind == "punct" or self:word(cut - 1, "and")) do cut = cut - 1 end
        table.insert(segs, k + 1, { intent = "infer", b = cut, trig = v, e = sg.e })
        sg.e = cut
      end
    end
  end
  self:switch_then_value(segs)
  self:speed_again_split(segs)
  -- "descend FL60 and from 10 NM before LNO 180 kt": a distance from a place opening a clause after the
  -- instruction's value ("and" or a comma before it), with a value after the place, is that value's
  -- condition alone: an instruction of its own (G:at_distance)
  for k = #segs, 1, -1 do
    local sg = segs[k]
    local spec = M.intents[sg.intent]
    if spec and spec.value and sg.intent ~= "create" then
      for _, q in ipairs(self:quantities(sg.trig + 1, sg.e)) do
        local c = self:word(q.b - 1, "from at within") and q.b - 1 or q.b
        local p = self:skip_fillers(q.e)
        local value_before = #self:quantities(sg.trig, q.b) > 0
        if q.kind == "dist" and value_before and (self:word(c - 1, "and")
            or (self.t[c - 1] and self.t[c - 1].kind == "punct" and self.t[c - 1].text == ","))
            and self:word(p, "from of to before") and self:has_ref(p + 1, p + 2, "waypoint")
            and #self:quantities(p + 2, sg.e) > 0 then
          G.split_segment(segs, k, c - 1, c)
          break
        end
      end
    end
  end
  -- "descend FL110 when it reaches 250 knots? Please slow it to 250 first.": a condition said before its
  -- instruction's word with the end of a sentence ("?", ".", "!", no ellipsis) between is that sentence's, never the next
  -- instruction's: it goes back to the segment before, or (none before) is a segment of its own
  for k = #segs, 1, -1 do
    local sg, prev = segs[k], segs[k - 1]
    for x = sg.trig - 1, sg.b, -1 do
      local t = self.t[x]
      -- (an ellipsis, "after ROSUN... its already there", trails off: no sentence's end)
      local dots = t.raw:find("..", 1, true) or t.raw == "…" or (self.t[x - 1] or {}).text == "."
        or (self.t[x + 1] or {}).text == "."
      if t.kind == "punct" and (t.text == "?" or t.text == "." or t.text == "!") and not dots then
        if self:word_in(sg.b, x, "@condition") then
          if prev and prev.e == sg.b then
            prev.e, sg.b = x + 1, x + 1
          elseif not prev then
            table.insert(segs, k, { intent = "infer", b = sg.b, trig = sg.b, e = x + 1 })
            sg.b = x + 1
          end
        end
        break
      end
    end
  end
  -- "FL 340, M.79, heading 255 - create FIN6PM, A359, ...", "Heading 015, 6,000 feet, 200 knots, at 55 degrees
  -- 40 north 12 degrees 50 east: create SAS88Y, E195": values said before the creation, for no aircraft
  -- named, are the new aircraft's
  for k, sg in ipairs(segs) do
    if sg.intent == "create" and k > 1 then
      local values_only = #self:refs_in(b, sg.trig, "aircraft") == 0
      for j = 1, k - 1 do
        values_only = values_only and (segs[j].intent == "infer" or ((M.intents[segs[j].intent] or {}).value
          and self:word(segs[j].trig, "heading hdg fl flight level altitude alt speed spd mach")))  -- (no verb)
      end
      if values_only then
        sg.b = segs[1].b
        return { table.unpack(segs, k) }
      end
      break
    end
  end
  return segs
end

-- "hop7 lnav off, fl200", "vnav KLM12 on spd 250": a value with its own unit (a flight level, a speed, a Mach, a
-- heading) said after an aircraft's navigation switch (LNAV, VNAV) and its ON/OFF is an instruction of its own (an
-- "infer" segment cut from the switch's, in place in `segs`); a bare number stays the switch's leftover, asked.
G.nav_switches = { lnav = true, vnav = true }
function G:switch_then_value(segs)
  for k = #segs, 1, -1 do
    local sg = segs[k]
    local q = G.nav_switches[sg.intent] and self:quantities(sg.trig + 1, sg.e)[1]
    if G.unit_value(q) and self:word_in(sg.trig, q.b, "on off") then
      -- ("klm33 lnav off and ryr8 fl310": the value's own aircraft named straight before it opens its request)
      local r = self:refs_in(sg.trig + 1, q.b, "aircraft")
      r = r[#r]
      local cut = r and self:opens_own_request(sg, r, sg.e) and r.b or q.b
      while cut - 1 > sg.trig and (self.t[cut - 1].kind == "punct" or self:word(cut - 1, "and")) do cut = cut - 1 end
      table.insert(segs, k + 1, { intent = "infer", b = cut, trig = q.b, e = sg.e })
      sg.e = cut
    end
  end
end

-- True when flying aircraft r, inside segment `seg` (to e), opens a request of its own: another aircraft than
-- the segment names before it, a value with its own unit straight after it (fillers or "to" between), and
-- before it "and", "then" or a comma, semicolon or full stop (`bare`: or straight a value, "klm33 hdg 100 ryr8
-- fl310"). "klm33 hdg 100 avoiding ryr8 fl310" opens none: the level may be either aircraft's, left to the check.
function G:opens_own_request(seg, r, e, bare)
  if not r.exists then return false end
  for _, o in ipairs(self:refs_in(seg.b, r.b, "aircraft")) do
    if o.name:upper() == r.name:upper() then return false end
  end
  local v = self:skip_fillers(r.e)
  if self:word(v, "to") then v = v + 1 end
  local q = self:quantities(r.e, e)[1]
  if not (G.unit_value(q) and q.b == v) then return false end
  local p = self.t[r.b - 1]
  local before = self:quantities(seg.trig, r.b)
  return p ~= nil and ((p.kind == "punct" and (p.text == "," or p.text == ";" or p.text == "."))
    or self:word(r.b - 1, "and @then_words") or (bare == true and #before > 0 and before[#before].e == r.b))
end

-- "turn EZY45 to 010 and AFR1234 to 200": an aircraft named after a value
-- instruction's value, with a value of its own after it, gets the same
-- instruction with that value (a segment of its own).
function G:split_ellipsis(segs)
  local out = {}
  for _, s in ipairs(segs) do
    local cur, e = s, s.e
    out[#out + 1] = cur
    -- "klm12 fl250 ezy45 fl310", "have the BA at FL260 and the Lufthansa at FL320", "put LOT3CM to FL320
    -- and WZZ1652 to FL360": with no instruction word, an aircraft that flies between values with units of
    -- their own (straight after it, or after "at" or "to") starts a request of its own
    if s.intent == "infer" then
      for _, r in ipairs(self:refs_in(s.b + 1, e, "aircraft")) do
        local before, after = self:quantities(cur.b, r.b), self:quantities(r.e, e)
        local v = self:skip_fillers(r.e)
        if self:word(v, "at to") then v = v + 1 end
        if r.exists and #before > 0 and G.unit_value(before[#before]) and G.unit_value(after[1]) and after[1].b == v then
          cur.e = r.b
          cur = { intent = "infer", b = r.b, trig = r.b, e = e }
          out[#out + 1] = cur
        end
      end
      -- "BAW918 FL300 and DLH9LT FL310, both 280 kt": "both" after values starts one for the two
      for i = s.b + 1, e - 1 do
        local after = self:word(i, "both") and self:quantities(i, e) or {}
        if after[1] and #self:quantities(cur.b, i) > 0 and after[1].b == self:skip_fillers(i + 1) then
          cur.e = i
          cur = { intent = "infer", b = i, trig = i, e = e }
          out[#out + 1] = cur
        end
      end
    end
    local spec = M.intents[s.intent] or {}
    local qs = spec.value and self:quantities(s.trig, e) or {}
    if #qs >= 2 then
      for _, r in ipairs(self:refs_in(qs[1].e, e, "aircraft")) do
        -- only across "and", "then", a comma, a semicolon or a full stop: "heading 160 DLH4AX 2" is no second
        -- instruction; "klm33 hdg 100 ryr8 fl310", another aircraft's own request straight after the value, is
        local joined = self:opens_own_request(cur, r, e, true)
        for k = qs[1].e, r.b - 1 do
          local t = self.t[k]
          if (t.kind == "punct" and (t.text == "," or t.text == ";" or t.text == ".")) or self:word(k, "and @then_words") then
            joined = true
          end
        end
        if qs[#qs].b >= r.e and joined then
          -- ("klm33 hdg 100 and ryr8 fl310": a value with a unit of another kind than the instruction's is that
          -- aircraft's request of its own; a bare one takes the instruction before)
          local v = self:quantities(r.e, e)[1]
          local kinds = VERB_FINAL_KINDS[s.intent]
          local other = s.intent ~= "maintain" and G.unit_value(v) and not (kinds and kinds[v.kind])
          cur.e = r.b
          cur = { intent = other and "infer" or s.intent, b = r.b, trig = r.b, e = e }
          out[#out + 1] = cur
        end
      end
    elseif s.intent ~= "infer" and not spec.single then
      -- "klm33 dct GILOM and ryr8 fl310", "hop7 lnav on, klm33 spd 250": after an instruction without a value
      for _, r in ipairs(self:refs_in(s.trig + 1, e, "aircraft")) do
        if self:opens_own_request(cur, r, e) then
          cur.e = r.b
          cur = { intent = "infer", b = r.b, trig = r.b, e = e }
          out[#out + 1] = cur
        end
      end
    end
  end
  return out
end

-- "add KIMON and then... no, add PELAG to the route", "add MARMA ... sorry, add FATIH": an instruction
-- word of the segment's family (or the same word), then a correction (a correction word, or a run of lexicon.self_correction
-- words holding a marker) straight before the segment's own instruction word: the first instruction was
-- taken back, and the words from it to the second (its place, its value) are accounted for.
local SC_WORDS, SC_MARKERS = set_of(lexicon.self_correction.words), set_of(lexicon.self_correction.markers)
function G:taken_back(s)
  local c, marked = s.trig, false
  while c > s.b and (self.t[c - 1].kind == "punct" or self.t[c - 1].filler or SC_WORDS[self.t[c - 1].text]
      or self:word(c - 1, "@correction")) do
    c = c - 1
    marked = marked or SC_MARKERS[self.t[c].text] or self:word(c, "@correction")
  end
  if not marked then return end
  for i = s.b, c - 1 do
    local intent = self:intent_at(i)
    if self.t[i].text == self.t[s.trig].text or (intent and same_family(intent, s.intent)) then
      return self:explain(i, s.trig)
    end
  end
end

-- "SAS1507 direct... no wait, heading 150", "route: TWEED, then GRICE... actually no, just TWEED at FL90",
-- "climb FL200 and turn left heading 200... actually no, just the climb": a self-correction after punctuation
-- (a run of lexicon.self_correction words holding a marker) that is no value for a value (self_corrections
-- reads those) takes back what it follows. An instruction word cut off before it, with no value, is
-- dropped ("and" before it too); an instruction word after it takes back the last instruction before it,
-- from its instruction word ("direct TWEED... no, make it heading 200"). "just"/"only" after it says what
-- stands: "the" and a noun of
-- lexicon.self_correction.just_the keeps the commands of that kind (self.kept: G:translate drops the others);
-- a name or value replaces the names and values said since the last instruction word ("just TWEED at
-- FL90"); anything else after "just" but an instruction word is asked about. The words taken back are
-- marked used and noted.
local SC = lexicon.self_correction
local SC_KEPT, SC_ONLY, SC_SETTING = {}, set_of(SC.only), set_of(SC.setting)
G.sc_left_named = set_of(SC.left_named)
G.sc_just_bare = set_of(SC.just_bare)
for cmd, nouns in pairs(SC.just_the) do for _, w in ipairs(nouns) do SC_KEPT[w] = cmd end end
G.tail_digits = { zero = "0", one = "1", two = "2", three = "3", four = "4", five = "5", six = "6", seven = "7",
  eight = "8", nine = "9", niner = "9" }
-- The aircraft said before token a named again at n by the characters after its airline alone (digits and letters
-- spelled, digit words, the phonetic alphabet) closing the request: { ref } when exactly one aircraft named before
-- a has them as the whole of its callsign after the airline (the words marked used and noted), else {}.
function G.tail_named(self, n, a)
  local chars, e = {}, n
  while self.t[e] and self.t[e].kind == "word" do
    local w = self.t[e].text
    local c = G.tail_digits[w] or lexicon.phonetic[w] or (w:match("^%w+$") and w:upper())
    if not c then return {} end
    chars[#chars + 1] = c
    e = e + 1
  end
  local k = e
  while self.t[k] and (self.t[k].kind == "punct" or self.t[k].filler) do k = k + 1 end
  local tail = table.concat(chars)
  if k <= #self.t or #tail < 2 then return {} end
  local found
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" and r.exists and r.b < a and r.name:upper():match("^%u%u%u(.+)$") == tail:upper() then
      if found and found.name ~= r.name then return {} end
      found = r
    end
  end
  if not found then return {} end
  self:mark_used(n, e)
  for i = n, e - 1 do self.noted[i] = true end
  return { found }
end

-- "reduce speed 220... no, make it 210", "descend to 26 thousand ft, sorry, 27 thousand": a value alone after
-- the self-correction run [a, c) (after "make it" too), ending its clause, of the kind of the value said since
-- the instruction word at p, replaces it; true when it did. Said "exactly" ("at or below FL090, sorry make it
-- exactly FL090"), it takes back the bound said before the value too (its words noted). self.said_again[b] is the
-- value taken back for the one said again at b (the handlers read an amount of change corrected: "go down 1500
-- feet... no, 2000").
function G:value_said_again(p, a, c)
  -- ("2.5 NM, sorry, please use 4 NM": "use" and the value alone, as "make it")
  -- ("climb to level 380, no, wait, keep 360": "keep" and the value alone, the value kept in place of the one said)
  local v = (self:word(c, "it") and self:word(c - 1, "make") or self:word(c, "use keep")) and c + 1 or c
  local old = self:quantities(p + 1, a)
  -- ("speed 260 reduce, ah no, 250 please": the verb said after its value, Korean order, nothing but fillers after
  -- it before the mark; the value straight before the verb is the one said again)
  local final = false
  if #old == 0 and p >= 2 and self:skip_fillers(p + 1) >= a then
    local before = self:quantities(math.max(1, p - 4), p)
    local q = before[#before]
    if q and self:skip_fillers(q.e) == p then old, final = { q }, true end
  end
  -- ("7800 metres, sorry, not 7800, is 8100", "..., not 7800 but 8100": the value said before, denied with "not"
  -- and said again as it was, then the new one)
  local denied = false
  for _, d in ipairs(#old == 1 and old[1].number and self:quantities(a, #self.t + 1) or {}) do
    if d.b >= v then break end
    if self:word(d.b - 1, "not") and d.number and d.number.value == old[1].number.value then denied = d end
  end
  if self:word(v, "not") then
    local d = self:quantities(v + 1, #self.t + 1)[1]
    if d and d.b == v + 1 and d.number and old[1] and old[1].number and d.number.value == old[1].number.value then
      denied, v = d, d.e
      while self.t[v] and (self.t[v].kind == "punct" or self.t[v].filler) do v = v + 1 end
    end
  end
  if denied and self:word(v, "is but it's its") then v = v + 1 end
  local exact = self:word(v, "exactly precisely")
  if exact then v = v + 1 end
  local new = self:quantities(v, #self.t + 1)[1]
  if not (new and new.b == v and #old == 1 and (new.kind == old[1].kind or new.kind == "plain")) then return false end
  local nx = new.e  -- (a filler after it, "make it 240 please", still ends its clause)
  while self.t[nx] and self.t[nx].filler do nx = nx + 1 end
  if self.t[nx] and self.t[nx].kind ~= "punct" then return false end
  local b = old[1].b
  while exact and b - 1 > p and self:word(b - 1, "or above below least most") do b = b - 1 end
  if final then
    -- (the verb after the old value stays the instruction's word)
    self:mark_used(b, old[1].e)
    for k = b, old[1].e - 1 do self.noted[k] = true end
    b = p + 1
  end
  self:mark_used(b, v)
  for k = b, v - 1 do self.noted[k] = true end
  self.said_again = self.said_again or {}
  self.said_again[new.b] = old[1]
  return true
end

-- True when the word before token a is an instruction whose one command takes no argument ("unpause" OP, "pause"
-- HOLD): complete as said, so "make it" and a value after it ("unpause, make it three times") is no value said
-- again for it but an instruction of its own.
function G:complete_before(a)
  local spec = M.intents[self:intent_at(a - 1) or ""]
  return spec ~= nil and spec.cmd ~= nil and not spec.args and not spec.value
end

-- A pilot's question back to the controller (lexicon.question_back) is asked about, never read as the
-- instruction whose words it holds: "say again the level for FIN7?" (a repeat asked for: no value in its
-- clause) and "confirm cleared FL200?" (a clearance asked about: a value or place in its clause). A clause runs to
-- '.', '?', ';' or the end; "say again? I say, descend FL360" (nothing in it) reads on as before.
local QUESTION_BACK_NOT_AFTER = {}
for _, w in ipairs(lexicon.question_back.not_after) do QUESTION_BACK_NOT_AFTER[w] = true end
local QUESTION_ADDRESSED = table.concat(lexicon.question_back.addressed, " ")
local QUESTION_PAST = {}
for _, w in ipairs(lexicon.question_back.past) do QUESTION_PAST[w] = true end
-- PHRASE_WORDS[phrase]: the phrase's words, split once
local PHRASE_WORDS = setmetatable({}, { __index = function(split, phrase)
  local words = {}
  for w in phrase:gmatch("%S+") do words[#words + 1] = w end
  split[phrase] = words
  return words
end })
function G:question_back()
  local qb = lexicon.question_back
  local toks = self.t
  -- the end (one past) of a phrase of `phrases` said at i, or nil
  local function phrase_end(i, phrases)
    for _, p in ipairs(phrases) do
      local k = i
      for _, w in ipairs(PHRASE_WORDS[p]) do
        local t = toks[k]
        if not (t and t.kind == "word" and t.text == w) then k = nil break end
        k = k + 1
      end
      if k then return k end
    end
  end
  local function said(b, e) return (self:raw(b, e):gsub(" ([,.;:])", "%1"):gsub(",$", "")) end
  local function clause_end(k)
    while k <= #self.t and not (self.t[k].kind == "punct" and self.t[k].text ~= ",") do k = k + 1 end
    return k
  end
  -- "resolution method -- which one did Pablo use last week?": a clause asking what was done, answered by nobody here
  local k = 1
  while k <= #self.t do
    local e = clause_end(k)
    if self.t[e] and self.t[e].text == "?" and self:word_in(k, e, QUESTION_PAST) then
      return self:need(string.format("'%s' asks what was done before: it is a question, no instruction. What "
        .. "should I do?", said(k, e) .. "?"))
    end
    k = e + 1
  end
  -- the words a phrase opens with: a word no phrase opens with starts no question
  local opens = {}
  for _, list in ipairs({ qb.repeat_words, qb.confirm }) do
    for _, p in ipairs(list) do opens[PHRASE_WORDS[p][1]] = true end
  end
  for i = 1, #self.t do
    local before = self.t[i - 1]
    if self.t[i].kind == "word" and opens[self.t[i].text] and not self.u:used(i)
        and not (before and QUESTION_BACK_NOT_AFTER[before.text]) then
      local re = phrase_end(i, qb.repeat_words)
      if re and not self:word(self:skip_fillers(re), QUESTION_ADDRESSED) then
        local e = clause_end(re)
        if e > re and #self:quantities(re, e) == 0 then
          return self:need(string.format("'%s' asks for a repeat: it is a question, no instruction. What "
            .. "should the aircraft do?", said(i, e)))
        end
      end
      local ce = phrase_end(i, qb.confirm)
      if ce then
        local e = clause_end(ce)
        -- ("confirm heading 180? Fly heading 180": the question asked, then the instruction given with its verb
        -- and its own value, which is read; the question itself is no instruction)
        local asked_q = self.t[e] and self.t[e].text == "?"
        local answered = asked_q and self:any_instruction_in(e + 1, #self.t + 1)
          and #self:quantities(e + 1, #self.t + 1) > 0
        -- ("confirm level 290? Maintain": a bare "maintain" after a level asked about keeps that level)
        local qs = self:quantities(ce, e)
        local m = self:skip_fillers(e + 1)
        local kept = asked_q and #qs == 1 and qs[1].kind == "alt" and self:word(m, "maintain")
        for k = m + 1, #self.t do kept = kept and self.t[k].kind == "punct" end
        if answered then
          self:set_aside(i, e)
        elseif kept then
          self:set_aside(i, qs[1].b - 1)
        elseif #self:quantities(ce, e) > 0 or #self:refs_in(ce, e, "waypoint") > 0 then
          return self:need(string.format("'%s' asks whether a clearance stands: it is a question, no "
            .. "instruction. Please give the instruction itself.", said(i, e)))
        end
      end
    end
  end
end

-- The end of the clause of the last instruction of intent `kind` ("hdg", "alt", ...) said before token a: the
-- first comma, "and" or word of lexicon.then_words after its instruction word and its first value; nil when
-- none was said.
function G:kept_clause_end(kind, a)
  local p = a - 1
  while p >= 1 and self:intent_at(p) ~= kind do p = p - 1 end
  if p < 1 then return nil end
  local q = self:quantities(p, a)[1]
  local k = q and q.e or p + 1
  while k < a and not (self.t[k].kind == "punct" or self:word(k, "and @then_words")) do k = k + 1 end
  return k
end

-- True when the clause from token b (to its next punctuation) holds a level, speed, Mach or heading.
function G:clause_value(b)
  local e = b
  while self.t[e] and self.t[e].kind ~= "punct" do e = e + 1 end
  for _, q in ipairs(self:quantities(b, e)) do
    if q.kind == "alt" or q.kind == "speed" or q.kind == "mach" or q.kind == "heading" then return true end
  end
  return false
end

-- "descend to flight level 310... I am sorry, not 310 because the Fuji Dream is there. Please descend to flight
-- level 320", "2.5 NM, sorry, 2.5 is too small, please use 4 NM": after a self-correction run ending at c, the value
-- said last before the run (at a) said again after "not", or before a word of lexicon.ruled_out_verbs, opens the
-- reason it is taken back: a clause of at most twelve words with no instruction in it, ending in a mark with more
-- said after it, no aircraft said first after it. It belongs to the run (what it names is context); the index
-- after it, or c when none is said.
G.ruled_out_verbs = set_of(lexicon.ruled_out_verbs)
function G:ruled_out_reason_end(a, c)
  local before = self:quantities(1, a)
  local old = before[#before]
  if not old then return c end
  local n = self:word(c, "not") and c + 1 or c
  local t = self.t[n]
  if not (t and t.kind ~= "punct" and (n > c or self.t[n + 1] and G.ruled_out_verbs[self.t[n + 1].text])) then return c end
  local same = false
  for k = old.b, old.e - 1 do same = same or self.t[k].text == t.text end
  if not same then return c end
  local k = n + 1
  -- (a word of an instruction after "too" judges the value: "250 is too fast")
  while k < n + 13 and self.t[k] and self.t[k].kind ~= "punct"
      and not (self:intent_at(k) and not self:word(k - 1, "too")) do
    k = k + 1
  end
  if self.t[k] and not (self.t[k].kind == "punct" and self.t[k].text ~= "?") then return c end
  while self.t[k] and (self.t[k].kind == "punct" or self.t[k].filler) do k = k + 1 end
  -- (the reason closing the request, "zone 2.5 NM, sorry, 2.5 is too small.": the value is taken back with
  -- nothing in its place; asked)
  if not self.t[k] then
    self:need(string.format("You said '%s' with no value in its place. What should it be?",
      (self:raw(n, k):gsub(" ([,.;:?!])", "%1"):gsub("[,.;:!]$", ""))))
    return c
  end
  -- (an aircraft said next is another instruction, no replacement: the value ruled out is asked about)
  if self:has_ref(k, k + 1, "aircraft")
      or self:word(k, "the") and self:has_ref(k + 1, k + 2, "aircraft") then
    return c
  end
  for i = c, k - 1 do self.noted[i] = true end
  return k
end

-- True when a value opens at token i: typed ("260") or said in digits ("two six zero", its words one quantity from i).
G.digit_words = { zero = true, one = true, two = true, three = true, four = true, five = true, six = true, seven = true,
  eight = true, nine = true, niner = true }
function G.value_opens(self, i)
  if self:quantities(i, i + 1)[1] ~= nil then return true end
  if not (self.t[i] and G.digit_words[self.t[i].text]) then return false end
  local q = self:quantities(i, math.min(i + 4, #self.t + 1))[1]
  return q ~= nil and q.b == i
end

-- "descend FL210, sorry, after EPVOK descend FL200", "..., no, when passing EPVOK descend FL200": the token at c
-- after a self-correction's run opens a condition (lexicon.self_correction_condition_openers, "as soon as") and its
-- clause goes on to an instruction word: that word's position (the instruction said in the place of the one before
-- the run, waiting as said), else nil. A clause that ends (".", ";", "?", "!") or joins another with "and" before any
-- instruction word says none.
function G:corrected_condition(c)
  local k = self:word(c, "@self_correction_condition_openers") and c + 1
    or self:word(c, "as") and self:word(c + 1, "soon") and self:word(c + 2, "as") and c + 3
  if not k then return nil end
  while self.t[k] do
    if self:intent_at(k) then return k end
    if (self.t[k].kind == "punct" and self.t[k].text:match("^[%.;!%?]$")) or self:word(k, "and") then return nil end
    k = k + 1
  end
  return nil
end

-- ("descend FL210 sorry turn left heading 100", "descend FL210 sorry i mean turn left heading 100"): "sorry" with no
-- mark before it, at `a`, opens a self-correction run too where an instruction word follows the run's words (at
-- `bare`) and one was said before it; the run then replaces or asks as after a comma, never adds silently.
-- (only "i mean", fillers and marks between: "sorry I climbed it by mistake" is an apology with its reason)
function G.bare_sorry_replaces(self, a, bare)
  if bare > #self.t or not self:intent_at(bare) or self:in_reason(bare) or self:word(a - 1, "am i'm") then
    return false
  end
  for k = a + 1, bare - 1 do
    local t = self.t[k]
    if not (t.kind == "punct" or t.filler or self:word(k, "mean") or self:word(k, "i") and self:word(k + 1, "mean")) then
      return false
    end
  end
  for k = a - 1, 1, -1 do
    if self:intent_at(k) and not self:in_reason(k) then return true end
  end
  return false
end
function G:self_corrected()
  local a = 2
  while a <= #self.t do
    local c, marked = a, false
    -- ("desc fl210 sry after TOLPA desc fl200", "descend FL210 sorry I mean after TOLPA ...": "sorry" with no mark
    -- before it opens the run too where a condition and an instruction follow it, G:corrected_condition)
    local bare = self.t[a].kind ~= "punct" and self:word(a, "sorry") and a
    while bare and self.t[bare] and (self.t[bare].kind == "punct" or self.t[bare].filler or SC_WORDS[self.t[bare].text]) do
      bare = bare + 1
    end
    if self.t[a].kind == "punct" or (bare and (self:corrected_condition(bare) or G.bare_sorry_replaces(self, a, bare))) then
      while self.t[c] and (self.t[c].kind == "punct" or self.t[c].filler or SC_WORDS[self.t[c].text]) do
        -- ("no" straight before what it negates is no correction: "conflict detection only, no resolution")
        local nx = self.t[c + 1]
        -- ("250 knots or less... make it 240": "make it" after a mark, its value said alone, G:value_said_again)
        -- (a marker of two words: "never mind")
        marked = marked or (SC_MARKERS[self.t[c].text]
          and (self.t[c].text ~= "no" or (nx and (nx.kind == "punct" or SC_WORDS[nx.text]))))
          or (nx ~= nil and SC_MARKERS[self.t[c].text .. " " .. nx.text])
          or (self.t[c].text == "make" and self:word(c + 1, "it") and G.value_opens(self, c + 2)
            and not self:complete_before(a))
        c = c + 1
      end
      -- ("Could you please pause? Sorry, my supervisor is calling me.": an apology opening a remark set aside,
      -- G:declared_remark, takes nothing back; "Move EXPB? No. Move ..." and "..., no, that is already the next
      -- one." still do)
      marked = marked and not (self:word(a + 1, COMMENTARY.decl.apologies) and self:in_reason(a + 1))
      -- ("..., uhh just the hdg for now": "just/only the" and a kind of instruction ending the request, after a
      -- pause with no marker, says what stands all the same)
      local just_the = not marked and self:word(c, SC_ONLY) and self:word(c + 1, "the") and self.t[c + 2] ~= nil
        and SC_KEPT[self.t[c + 2].text] ~= nil
      if just_the and self:sc_kept_end(c + 3) <= #self.t then
        -- (said with more after it, "..., just the spd for now, and hdg 100", what stands is unclear)
        local e = self:sc_kept_end(c + 3)
        while self.t[e] and self.t[e].kind ~= "punct" do e = e + 1 end
        return self:need(string.format("What stands after '%s'? Please say the instruction again in full.",
          (self:raw(c, e):gsub(" ([,.;:])", "%1"))))
      end
      marked = marked or just_the
    end
    -- ("insert SINCA... no wait, it's already there, add BURNY": the reason the instruction is taken back, a clause
    -- of at most six words opened by a pronoun of lexicon.self_correction_reason_openers and ending in a comma,
    -- no value, place or instruction in it, belongs to the run; "..., ah no, it is already in the route. Then
    -- please let it go direct to MKG": a state told with "already" may end in a full stop too, and the
    -- instruction said after it, "then", "please", "let it", "go" before its word, replaces the one taken back)
    local replaced, withdrawn = false, false
    -- ("descend FL340, no wait, that's the Air France level, 320": another aircraft named by "the" before a noun of
    -- the value's kind is whose value it was, described, no addressee: the clause is set aside)
    -- (the run may hold the opener, "no wait that's the ...": "that" is a word of the run, "the" a filler)
    local opened = marked and not self:word(c, "@self_correction_reason_openers") and c > a
      and (self:word(c - 1, "@self_correction_reason_openers") or self:word(c - 2, "@self_correction_reason_openers")
        and self.t[c - 1].filler)
    if marked and (opened or self:word(c, "@self_correction_reason_openers")) then
      local k, told, owner = opened and c or c + 1, false, false
      if opened and self:word(k, "is") then k = k + 1 end
      while k < c + 9 and self.t[k] and self.t[k].kind == "word" and not self:intent_at(k)
          and #self:quantities(k, k + 1) == 0 do
        local r = self:refs_in(k, k + 1, "aircraft")[1]
        if r and r.b == k and self:word(k - 1, "the") and self:word(r.e, "level altitude heading speed height") then
          owner, k = true, r.e + 1
        elseif self:has_ref(k, k + 1) then
          break
        else
          told = told or self:word(k, "already")
          k = k + 1
        end
      end
      if opened and not owner then
        k = c  -- (no other aircraft's value named: the run ends where it did)
      elseif self.t[k] and (self.t[k].text == "," or told and self.t[k].text == ".") then
        if owner then self:set_aside(c, k - 1) end
        c = k
        while self.t[c] and (self.t[c].kind == "punct" or self.t[c].filler) do c = c + 1 end
        local v = c
        while told and v < c + 6 and self:word(v, "then so please let it just go") and not self:intent_at(v) do
          v = v + 1
        end
        if told and v > c and self:intent_at(v) then c, replaced = v, true end
        withdrawn = told and not self:intent_at(v)
      end
    end
    -- ("heading 180, ah, not heading, I mean speed 180": "not" and the kind of the last instruction before the mark,
    -- then an instruction of another kind, says that one replaces it)
    local kind = self.t[a].kind == "punct" and self:word(c, "not") and self.t[c + 1] and SC_KEPT[self.t[c + 1].text]
    if kind then
      local p = a - 1
      while p >= 1 and not self:intent_at(p) do p = p - 1 end
      local v = c + 2
      while self.t[v] and (self.t[v].kind == "punct" or self.t[v].filler or SC_WORDS[self.t[v].text]) do v = v + 1 end
      local now = self:intent_at(v)
      if p >= 1 and self:intent_at(p) == kind:lower() and now and now ~= kind:lower() then
        c, marked, replaced = v, true, true
      end
    end
    if marked then
      c = self:ruled_out_reason_end(a, c)
    elseif c > a and self:word(c, "am i'm") and self:word(c + 1, "sorry") then
      -- ("310... I am sorry, not 310 because ...": an apology with "am" is a marker only before such a reason)
      local s = c + 2
      while self.t[s] and (self.t[s].kind == "punct" or self.t[s].filler) do s = s + 1 end
      local e = self:ruled_out_reason_end(a, s)
      if e > s then c, marked = e, true end
    end
    -- ("add SHNON... scratch that, let's put TRUPS ...": "let's" (read as "let") or "let us" before the
    -- instruction said in its place belongs to the run)
    if marked then
      local l = self:word(c, "let lets") and (self:word(c + 1, "us") and c + 2 or c + 1)
      if l and self:intent_at(l) then c = l end
    end
    local left_as_is, left_kind = false, nil
    if marked then left_as_is, left_kind = self:left_as_is_end(c) end
    -- ("heading 360, sorry, leave its speed, ...": the kind named is not the instruction said before the run: asked)
    if left_kind and not self:kept_clause_end(left_kind:lower(), a) then
      return self:need(string.format("You said '%s', but no %s was given before it. What stands?",
        self:raw(c, left_as_is), self:word(left_as_is - 1, "route") and "heading" or self.t[c + 2].text))
    end
    if left_as_is then
      c = left_as_is
      while self.t[c] and (self.t[c].kind == "punct" or self.t[c].filler) do c = c + 1 end
    end
    local p = a - 1  -- the last instruction word before the run
    while marked and p >= 1 and not (self:intent_at(p) and not self:in_reason(p)) do p = p - 1 end
    -- (taken back for a state told, "... ah no, it is already there.", with no instruction in its place: the last
    -- instruction before the run, from its instruction word, is dropped)
    if marked and withdrawn and p >= 1 then
      self:set_aside(p, c - 1)
      a, marked = c - 1, false
    end
    -- ("speed 250 and climb FL350... no wait, just climb FL350 first": "just"/"only" and the last instruction's
    -- word said again after the run, with another instruction said before it and none of them said by that
    -- word, takes nothing back but leaves unclear whether the earlier ones stand or wait: asked; "climb FL80,
    -- direct BNN... wait, just climb" names the earlier one that stands; "climb FL260 and direct AUGSB, sorry,
    -- just heading 250" replaces the last one)
    if marked and p > 1 and self:word(c, SC_ONLY) and c + 1 <= #self.t and self:intent_at(c + 1)
        and self.t[p].text == self.t[c + 1].text then
      local other = false
      for k = 1, p - 1 do
        if self:intent_at(k) and not self:in_reason(k) then
          if self.t[k].text == self.t[c + 1].text then other = false break end
          other = true
        end
      end
      if other then
        return self:need(string.format("After '%s', should the instructions said before it still be given, or "
          .. "only this one? Please say what stands in full.", (self:raw(c, #self.t + 1):gsub(" ([,.;:])", "%1"))))
      end
    end
    -- ("add BOBTA then DEBEK, actually just add ERBUS at the end of his route": with no instruction word
    -- before the run, the instruction said in its place names its verb again; the words from that verb's
    -- first saying are taken back)
    local v = marked and self:word(c, SC_ONLY) and c + 1 or c
    if marked and p < 1 and v <= #self.t and self:intent_at(v) and self.t[v].kind == "word" then
      for k = a - 1, 1, -1 do
        if self.t[k].kind == "word" and self.t[k].text == self.t[v].text then
          p = k
          break
        end
      end
    end
    -- ("RZO135 go to flight level 250, no wait, keep it at its current level": with no instruction word before the
    -- run, a level, speed or heading said straight before it is taken back when an instruction is said in its
    -- place, with the words that lead to it from the aircraft named or the last mark; its kind is the value's)
    local valued
    if marked and p < 1 and v <= #self.t and self:intent_at(v) then
      local qs = self:quantities(1, a)
      local q = qs[#qs]
      valued = q and q.e == a and G.value_kinds[q.kind] and ({ alt = "alt", speed = "spd", heading = "hdg" })[
        G.value_kinds[q.kind]]
      if valued then
        p = q.b
        while p > 1 and self.t[p - 1].kind == "word" and not self.t[p - 1].filler and not self:has_ref(p - 1, p, "aircraft") do
          p = p - 1
        end
      end
    end
    -- (with no instruction word before the run, "put the Fedex and the Spirit at FL350 ... actually just the
    -- Spirit", only the aircraft narrowed)
    if marked and c <= #self.t and (p >= 1 or (self:word(c, SC_ONLY) and self:has_ref(c + 1, c + 3, "aircraft"))) then
      local b = a
      -- (a verb said after its value, "speed 260 reduce, ah no, 250", is no instruction cut off: G:value_said_again)
      local before = p == a - 1 and self:quantities(math.max(1, p - 4), p)
      local final = before and before[#before] and self:skip_fillers(before[#before].e) == p
      if p == a - 1 and not final then
        -- an instruction cut off: taken back, with the "and" that joined it
        b = self:word(p - 1, "and") and p - 1 or p
      end
      -- ("..., no forget it, only speed": a noun of lexicon.self_correction.just_bare said without "the", closing
      -- the request, names the kind that stands as "only the speed" does)
      local bare_kept = self:word(c, SC_ONLY) and self:word(c + 1, G.sc_just_bare)
        and (self:sc_kept_end(c + 2) > #self.t or self.t[self:sc_kept_end(c + 2)].kind == "punct")
      if self:word(c, SC_ONLY) and (not self:intent_at(c + 1) or bare_kept) then
        local kept = bare_kept and SC_KEPT[self.t[c + 1].text]
          or self:word(c + 1, "the") and SC_KEPT[self.t[c + 2] and self.t[c + 2].text or ""]
        local e = self:sc_kept_end(bare_kept and c + 2 or c + 3)
        -- the first name or value since the last instruction word, the start of what is said again
        local q = p + 1
        while q < b and not (self:has_ref(q, q + 1, "waypoint") or #self:quantities(q, q + 1) > 0) do q = q + 1 end
        -- ("the Fedex and the Spirit, FL350 ... actually just the Spirit, FL360"): the aircraft named after
        -- "just" are the only ones instructed; the others named before are taken back, and a value said
        -- after them replaces the values said since the last instruction word
        local n = self:word(c + 1, "the") and c + 2 or c + 1
        local only = {}
        for _, r in ipairs(self.refs) do
          local last = only[#only]
          if r.kind == "aircraft" and r.b >= n and (r.b == n or (last and (self:skip_fillers(last.e, true) == r.b
              or (self:word(last.e, "and") and r.b <= last.e + 2)))) then
            only[#only + 1] = r
          end
        end
        -- ("Ryanair three mike charlie and Ryanair eight seven lima alfa, both climb FL150... no, only the three
        -- mike charlie": the aircraft named by the characters after its airline alone, G:tail_named)
        if #only == 0 and not kept then only = G.tail_named(self, n, a) end
        if #only > 0 and not kept then
          local named = {}
          for _, r in ipairs(only) do named[r.name] = true end
          local after = self:skip_fillers(only[#only].e, false)
          if self:word(after, "to at") then after = after + 1 end
          local again = (self:quantities(after, #self.t + 1)[1] or {}).b == after
          local refs = {}
          for _, r in ipairs(self.refs) do
            local back = r.b < a and ((r.kind == "aircraft" and not named[r.name]) or (again and r.b >= q))
            if back then
              self:mark_used(r.b, r.e)
              for k = r.b, r.e - 1 do self.noted[k] = true end
            else
              refs[#refs + 1] = r
            end
          end
          self.refs = refs
          local from = again and q < b and q or b
          self:mark_used(from, n)
          for k = from, n - 1 do self.noted[k] = true end
          a = n
        elseif kept and (e > #self.t or self.t[e].kind == "punct") then
          self.kept = kept
          -- (what was said after the kept instruction's clause is taken back with the rest: "turn left heading
          -- 180, and at 15 miles from ARGAS, hmm, no, just the heading" drops the distance)
          local from = math.min(b, self:kept_clause_end(kept:lower(), a) or b)
          self:set_aside(from, e - 1)
          a = e
        elseif q < b and (self:has_ref(c + 1, c + 2, "waypoint")
            or (self:quantities(c + 1, #self.t + 1)[1] or {}).b == c + 1) then
          self:set_aside(q, c)
          a = c + 1
        else
          local said = self:raw(c, math.min(e, #self.t + 1)):gsub(" ([,.;:])", "%1")
          self:need(string.format("What stands after '%s'? Please say the instruction again in full.", said))
          return
        end
      elseif b < a then
        self:mark_used(b, c)
        for k = b, c - 1 do self.noted[k] = true end
        self.cut_back[b] = c
        a = c
      elseif left_as_is and p >= 1 then
        -- ("direct SPY... no, leave that. KLM12, climb FL280": the last instruction, from its word, taken back
        -- whole with its values and places, and the words of that instruction before its last word, "turn left"
        -- of "turn left heading 200"; what follows is read alone)
        local from = p
        while from > 1 and self.t[from - 1].kind == "word" and not self:has_ref(from - 1, from, "aircraft")
            and (self:intent_at(from - 1) or self:word(from - 1, "@left @right to")) do
          from = from - 1
        end
        self:set_aside(from, c - 1)
        a = c
      elseif self:value_said_again(p, a, c) then
        a = c
      elseif self:intent_at(self:word(c, "it") and self:word(c - 1, "make") and c + 1 or self:word(c, SC_ONLY) and c + 1
            or self:word(c, SC_SETTING) and (self:word(c + 1, "the") and c + 2 or c + 1) or self:corrected_condition(c) or c)
          and (replaced or not self:word_in(a, c, "and also then")) then
        -- another instruction said in its place ("direct TWEED... no, make it heading 200", "half height 1000...
        -- no, set zone half height to 500" after a verb of lexicon.self_correction.setting, "climb FL200,
        -- no wait, descend FL90", "..., sorry, I mean just turn to heading 250"): the last one before the
        -- run, from its instruction word, is taken back ("climb FL200, sorry, and turn left": an
        -- instruction added, none taken back)
        -- (of another kind, with no word saying it replaces, "climb FL200, sorry, turn left heading 250", it is
        -- asked as G:parse asks after "correction")
        local w = self:word(c, SC_ONLY) and c + 1 or c
        -- (the instruction word after a condition said first, "..., sorry, after EPVOK descend FL200")
        local verb = not self:intent_at(c) and self:corrected_condition(c) or c
        -- ("never mind", "forget that", "scratch that" take it back in words; the same verb is no other kind)
        if w == c and not replaced and not self:word(c, "it") and not SC_SETTING[self.words[c]]
            and not left_as_is and not self:word_in(a, c, "never nevermind forget scratch") and self.words[verb] ~= self.words[p]
            and not same_family(self:intent_at(p) or valued, self:intent_at(verb))
            -- ("turn right heading 350, ah no, LNAV on": the route flown again takes a heading's place)
            and not ((self:intent_at(p) or valued) == "hdg" and self:intent_at(verb) == "lnav"
              and not self:word_in(verb, math.min(#self.t + 1, verb + 4), "@off")) then
          local e = c
          while self.t[e] and self.t[e].kind ~= "punct" do e = e + 1 end
          local function said(b, e) return (self:raw(b, e):gsub(" ([,.;:])", "%1"):gsub("[%s%p]+$", "")) end
          return self:need(string.format("Should I do '%s' instead of '%s', or as well?", said(c, e), said(p, a)))
        end
        c = w
        if verb ~= c then
          -- (the condition opens the clause in the place of what was taken back, with the words before the last
          -- instruction word that were its own, "turn left" of "turn left heading 100": G:condition_resumes)
          local from = p
          while from > 1 and self.t[from - 1].kind == "word" and not self:has_ref(from - 1, from, "aircraft")
              and (self:intent_at(from - 1) or self:word(from - 1, "@left @right to")) do
            from = from - 1
          end
          self.condition_resumes = self.condition_resumes or {}
          self.condition_resumes[from] = c
          p = from
        end
        self:set_aside(p, c - 1)
        a = c
      else
        a = a + 1
      end
    else
      a = a + 1
    end
  end
end

-- The token after a phrase of lexicon.self_correction.left_as_is said at c and ending its clause (punctuation or
-- the end after it), else nil. "leave its heading", "keep the speed" (a word of lexicon.self_correction.left_named
-- and a noun of .just_the, ending the clause) is such a phrase too; the command it names (HDG, SPD, ...) is
-- returned second.
function G:left_as_is_end(c)
  -- ("turn right heading 350, ah no, keep route", "..., sorry, stay on your route": the route kept leaves the heading
  -- said before the marker as it was, HDG)
  if self:word(c, "keep stay continue remain") then
    local k = self:word(c + 1, "on with along") and c + 2 or c + 1
    if self:word(k, "the its your his her their") then k = k + 1 end
    if self:word(k, "own") then k = k + 1 end
    if self:word(k, "route") and (not self.t[k + 1] or self.t[k + 1].kind == "punct") then return k + 1, "HDG" end
  end
  if not self:word(c, "leave keep") then return nil end
  local noun = self.t[c + 2]
  local kind = self:word(c + 1, G.sc_left_named) and noun and noun.kind == "word" and SC_KEPT[noun.text]
  if kind and (not self.t[c + 3] or self.t[c + 3].kind == "punct") then return c + 3, kind end
  for _, phrase in ipairs(SC.left_as_is) do
    local k = c
    for _, w in ipairs(PHRASE_WORDS[phrase]) do
      if not (self.t[k] and self.t[k].kind == "word" and self.t[k].text == w) then k = nil break end
      k = k + 1
    end
    if k and (not self.t[k] or self.t[k].kind == "punct") then return k end
  end
  return nil
end

-- "After DUS the Speedbird must descend to FL200. So: Speedbird 948 at DUS descend FL200": one level or speed
-- tied to one aircraft's waypoint said twice in the request (as "AT id wp DO ALT id v" or as the constraint "AT id
-- wp ALT v") is one instruction restated: the first command stands, the later one is dropped. Said twice with two
-- values, which one stands is asked, but for a constraint and then a change after the waypoint ("cross LAM at
-- FL120, thereafter descend FL90").
function G:restated_at_place()
  local seen, kept = {}, {}
  for _, c in ipairs(self.out) do
    local id, wp, cmd, v = c:match("^AT (%S+) (%S+) DO (%u+) %S+ (%S+)$")
    local after = id ~= nil
    if not id then id, wp, cmd, v = c:match("^AT (%S+) (%S+) (%u+) (%S+)$") end
    local key = id and (cmd == "ALT" or cmd == "SPD") and table.concat({ id, wp, cmd }, " ")
    local first = key and seen[key]
    if first and first.v ~= v and not (after and not first.after) then
      return self:need(string.format("I heard '%s' and '%s' for %s at %s: which one stands?", first.c, c, id, wp))
    end
    if key and not first then seen[key] = { v = v, c = c, after = after } end
    if not (first and first.v == v) then kept[#kept + 1] = c end
  end
  self.out = kept
end

-- "KLM12 at SPY speed 200, after that he goes to EHAM": a clause opened by a word of lexicon.onward.openers, then
-- one of its subjects, verbs, "to" or "on to" and one place closing the request, says where the aircraft named
-- before flies on: a place on its route is a remark, set aside (no command); any other is asked, never made its
-- destination.
G.onward = { openers = set_of(lexicon.onward.openers), subjects = set_of(lexicon.onward.subjects) }
function G:onward_remark()
  local O = lexicon.onward
  if not self:said(G.onward.subjects) then return end
  for b = 2, #self.t - 3 do
    local k = self:word(b, "after") and self:word(b + 1, "that") and b + 1
    if self.t[b - 1].kind == "punct" and (k or self:word(b, G.onward.openers)) and self:word((k or b) + 1, G.onward.subjects) then
      k = k or b
      local v = k + 2
      local e
      for _, verb in ipairs(O.verbs) do
        local x = v
        for _, w in ipairs(PHRASE_WORDS[verb]) do x = x and self:word(x, w) and x + 1 or nil end
        if x then e = x break end
      end
      if e and self:word(e, "on") then e = e + 1 end
      local r = e and self:word(e, "to") and self:refs_in(e + 1, e + 2, "waypoint")[1]
      local close = r and r.e
      while close and self.t[close] and self.t[close].kind == "punct" do close = close + 1 end
      local id
      for _, a in ipairs(self.refs) do
        if a.kind == "aircraft" and a.e <= b then id = a.name end
      end
      if r and id and close > #self.t then
        if not self:on_route(id, r.name) then
          return self:need(string.format("Should %s's destination be %s, or is '%s' only where it flies on? "
            .. "Please say it as an instruction.", id, r.name, (self:raw(b, r.e):gsub(" ([,.;:])", "%1"))))
        end
        self:set_aside(b, r.e - 1)
      end
    end
  end
end

-- The token after the words that may close "just the <kind>" from token e on ("change", "instruction", "for now",
-- fillers and marks): e itself when none
function G:sc_kept_end(e)
  if self:word(e, "change instruction") then e = e + 1 end
  if self:word(e, "for") and self:word(e + 1, "now") then e = e + 2 end
  while self.t[e] and (self.t[e].filler or (self.t[e].kind == "punct" and self.t[e].text ~= ",")) do e = e + 1 end
  return e
end

-- "maintain 280 knots until HUMPP... correction, until PAE", "via ALPHA, sorry, via BRAVO": a place, then a
-- run of punctuation and correction words (lexicon.correction, lexicon.self_correction's markers) and the
-- same word before another place: the first place is the one corrected, and it is taken back with its word
-- and the run (marked used and noted).
local PLACE_CORRECTION = set_of(lexicon.correction)
for w in pairs(SC_MARKERS) do PLACE_CORRECTION[w] = true end
function G:places_corrected()
  if not self:said(PLACE_CORRECTION) then return end  -- (both readings need a word of the run)
  local starts = {}
  for _, r in ipairs(self.refs) do
    if r.kind == "waypoint" then starts[r.b] = r end
  end
  for _, before in ipairs(self.refs) do
    local w = before.kind == "waypoint" and before.b > 1 and self.t[before.b - 1]
    local c, marked = before.e, false
    while self.t[c] and (self.t[c].kind == "punct" or self.t[c].filler or SC_WORDS[self.t[c].text]
        or PLACE_CORRECTION[self.t[c].text]) do
      marked = marked or PLACE_CORRECTION[self.t[c].text] ~= nil
      c = c + 1
    end
    if w and w.kind == "word" and marked and self:word(c, w.text) and starts[c + 1] then
      self:set_aside(before.b - 1, c - 1)
      return
    end
  end
  -- "dest bremen? no hamburg EDDH", "orig rotterdam, sorry, EHAM": a place named (one to three words) straight
  -- after a route field's word, then such a run, then a place said by its code (a name of up to two words before
  -- it or none) or by its name ending the request: the first name and the run are taken back
  for d = 1, #self.t - 1 do
    for n = self:word(d, "dest destination orig origin") and 1 or 4, 3 do
      local c, marked = d + 1 + n, false
      while self.t[c] and (self.t[c].kind == "punct" or self.t[c].filler or SC_WORDS[self.t[c].text]
          or PLACE_CORRECTION[self.t[c].text]) do
        marked = marked or PLACE_CORRECTION[self.t[c].text] ~= nil
        c = c + 1
      end
      local k = c
      while marked and k < c + 2 and self.t[k] and self.t[k].kind == "word" and not starts[k] do k = k + 1 end
      -- (or by a name of one or two words ending the request: "dest bremen? no hamburg")
      local named = marked and not starts[k] and (self:sc_kept_end(c + 1) > #self.t and self:place_named(c, c + 1)
        or self:sc_kept_end(c + 2) > #self.t and self:place_named(c, c + 2))
      if marked and (starts[k] or named) and self:place_named(d + 1, d + 1 + n) then
        self:set_aside(d + 1, c - 1)
        return
      end
    end
  end
end

-- True when segment t, said after a correction, is of segment s's kind: of one family, or both level, speed or
-- heading instructions whose first values are of one kind (a Mach number a speed), "maintain" going by its value
-- ("reduce speed 220 knots, correction, maintain 250 knots" is; "climb FL150, correction, maintain 250 knots" is not).
G.value_kinds = { alt = "alt", speed = "speed", mach = "speed", heading = "heading" }
G.value_intents = { alt = true, maintain = true, spd = true, hdg = true }
function G:corrects_in_kind(s, t)
  if G.value_intents[s.intent] and G.value_intents[t.intent] then
    local a, b = self:quantities(s.trig, s.e)[1], self:quantities(t.trig, t.e)[1]
    local ka, kb = a and G.value_kinds[a.kind], b and G.value_kinds[b.kind]
    if ka and kb then return ka == kb end
  end
  -- ("turn right heading 350, ah no, keep route, LNAV on": the route flown again, said in place of a heading, takes
  -- the heading's place)
  if s.intent == "hdg" and t.intent == "lnav" and not self:word_in(t.b, t.e, "@off") then return true end
  return same_family(s.intent, t.intent)
end

-- (defined with G:at_waypoint)
local tied_to_waypoint

-- "Could you tell me the route of JAL515? Ah, it does not have a route. Then please tell me its position", "show
-- the route of KLM12, never mind the route, show its position": the noun of segment k's instruction (no value said
-- in the segment) said again after a mark that ends its clause, a word of lexicon.withdrawn within the
-- four words before it: the speaker takes that request back. True when another instruction follows, said in its
-- place (the words from the withdrawing word to the noun set aside); asked when none does; false otherwise.
function G:withdrawn(segs, k)
  local s = segs[k]
  local p = s.trig + 1
  while p < s.e and self.t[p].kind ~= "punct" do p = p + 1 end
  -- (a value anywhere in it, "zone radius four miles... no, set the zone radius to six", is a self-correction's)
  if #self:quantities(s.trig, s.e) > 0 then return false end
  for x = p + 1, s.e - 1 do
    if self.words[x] == self.words[s.trig] then
      local neg = self:find_word(math.max(p + 1, x - 4), x, "@withdrawn")
      if neg < x then
        if not segs[k + 1] then
          self:need(string.format("'%s' takes back '%s'. What should I do instead?", self:raw(neg, x + 1),
            (self:raw(s.b, p):gsub("^[%s%p]+", ""))))
          return false
        end
        self:set_aside(neg, x)
        return true
      end
    end
  end
  return false
end

function G:parse(b, e)
  self:typed_wait()
  local segs = self:split_ellipsis(self:segments(b, e))
  -- ("turn UTair 235 left 20 degrees and Aeroflot 1878 to stop": an aircraft named after an instruction's word, told
  -- "to" stop with no instruction of its own after it, is no object of the instruction before: asked)
  for _, sg in ipairs(segs) do
    for _, r in ipairs(self:refs_in(sg.trig + 1, sg.e, "aircraft")) do
      local v = self:word(r.e, "to") and self:skip_fillers(r.e + 1)
      if v and self:word(v, "@halted") and not self:word_in(v + 1, sg.e, "@halted") then
        local rest = true
        for k = v + 1, sg.e - 1 do rest = rest and (self.t[k].kind == "punct" or self.t[k].filler) end
        if rest then
          return self:need(string.format("What should %s stop? I heard '%s' after the instruction to another "
            .. "aircraft. Please say its instruction.", r.name:upper(), self:raw(r.b, sg.e):gsub("[%s%p]+$", "")))
        end
      end
    end
  end
  local prev_out = #self.out
  local valueless, issued_by = {}, {}  -- (G:valueless_left)
  local seg_out = {}  -- seg_out[k]: #self.out before segment k's commands
  self:orphan_heading(segs[1])
  for k, s in ipairs(segs) do
    if self.ask then break end
    local skip = false
    -- "descend and maintain four th- correction descend and maintain three
    -- thousand": the corrected instruction replaces the one before it.
    -- "climb FL200, no wait, heading 300": one of another kind said in the place of an instruction that was
    -- issued takes it back, or adds to it; which is not knowable, so it is asked, naming both
    local fixed = k > 1 and self:word_in(segs[k - 1].trig, s.trig, "@correction")
    if fixed and self:corrects_in_kind(segs[k - 1], s) then
      for c = #self.out, prev_out + 1, -1 do self.out[c] = nil end
    elseif fixed and #self.out > prev_out then
      local c = s.trig - 1
      while not self:word(c, "@correction") do c = c - 1 end
      -- (the new instruction's word straight after the correction, with a value or place of its own: "I say again
      -- FL110, reduce 230" says the level again; "no speed restrictions" names no instruction in its place)
      if #self:quantities(c + 1, s.trig) == 0
          and (#self:quantities(s.trig, s.e) > 0 or #self:refs_in(s.trig, s.e, "waypoint") > 0) then
        local function said(b, e) return (self:raw(b, e):gsub(" ([,.;:])", "%1"):gsub("[%s%p]+$", "")) end
        self:need(string.format("Should I do '%s' instead of '%s', or as well?", said(c + 1, s.e):gsub("^[%s%p]+", ""),
          said(segs[k - 1].trig, c)))
        break
      elseif self:word(c, "@correction_taking_back") then
        -- ("turn left heading 360, disregard, continue on your route", "... belay that, resume own navigation": an
        -- instruction with no value of its own after one taken back in words, lexicon.correction_taking_back, is
        -- said in its place: the one before is dropped)
        for x = #self.out, prev_out + 1, -1 do self.out[x] = nil end
      end
    end
    self:taken_back(s)
    -- "slow to 240 knots when it reaches flight level 200", "turn heading 180, but only when it is at
    -- FL250": a level said as a condition after the speed or heading instructions it holds
    prev_out = #self.out
    -- "climb four thousand... negative, maintain seven thousand": an instruction that the next one, of its
    -- family, corrects asks nothing about the value taken back (a climb below the aircraft)
    local nx = segs[k + 1]
    local corrected = nx and s.trig < nx.trig and self:word_in(s.trig, nx.trig, "@correction")
      and self:corrects_in_kind(s, nx)
    -- "Status of BAW45? Altitude, speed, everything": a bare noun after a
    -- handled instruction names what to show, not a new instruction.
    if k > 1 and #self.out > 0 and self.out[#self.out]:match("^POS ") and self:word(s.trig, "@shown")
        and #self:quantities(s.b, s.e) == 0 then
      skip = true
    end
    local withdrawn = self:withdrawn(segs, k)
    if self.ask then break end
    seg_out[k] = #self.out
    if not skip then
      local before = self.last_cond
      self.last_cond = nil
      local n_before = #self.out
      -- ("maintain 250 knots until SULUR then climb FL200": the instruction after "then" starts at the place,
      -- never waits for the value before it)
      local until_wp = self:until_then(segs, k)
      local until_lvl = not until_wp and self:until_level_then(segs, k)
      if until_wp or until_lvl then before = nil end
      local at_next = self.at_next
      self.at_next = nil
      -- (a time the instruction before is held for, "heading 060 for 2 minutes, then ...": this one waits it,
      -- m:held_for; with a condition of its own too, which one is asked)
      local waited = self.wait_next
      self.wait_next = nil
      local at = self:at_altitude(s) or self:at_speed(s) or self:at_speed_again(s) or self:at_distance(s)
        or self:at_time(s) or self.at_all
      if waited and at then
        self:need(string.format("Should the instruction after '%s' wait for it, or for its own condition?",
          waited:gsub("^DELAY ", "") .. " s"))
        break
      end
      at = at or waited
      -- ("reduce speed 210 when passing 8000 ft and descend to 7000 ft": which instruction waits is asked)
      if at and at ~= self.at_all and self:condition_between(segs, k, at, seg_out[k - 1]) then break end
      -- "slow to 240 knots when it reaches flight level 200", "turn heading 180, but only when it is at
      -- FL250": a level said as a condition after the speed or heading instruction it holds
      local held, cut
      if (s.intent == "spd" or s.intent == "hdg" or s.intent == "infer") and not at then held, cut = self:trailing_level(s) end
      -- "descend FL70 and reduce 180 kts when level": the instruction before's value, reached ("reduce 220
      -- when you reach it" with no level before it: asked, never run at once)
      local reached_cut = not held and not at and self:trailing_reached(s)
      local unheld = reached_cut and not before
      local s0 = s
      if reached_cut then
        self:mark_used(reached_cut, s.e)
        for i = reached_cut, s.e - 1 do self.noted[i] = true end
        s = { b = s.b, e = reached_cut, trig = s.trig, intent = s.intent }
      end
      -- ("descend FL100 when passing GOTUR": the instruction starts at the waypoint, G:trailing_fix)
      local tail = not held and not at and not reached_cut and not until_wp and self:trailing_fix(s)
      if tail then
        self:mark_used(tail.b, tail.e)
        self:explain(tail.b, tail.e)
        s = { b = s.b, e = tail.b, trig = s.trig, intent = s.intent }
      end
      local ids = held and self:acids(s) or {}
      if #ids == 1 then
        at = "ATALT " .. ids[1] .. " " .. handlers.format.alt(held.value, held.fl)
        self:mark_used(cut, s.e)
        for i = cut, s.e - 1 do self.noted[i] = true end
        s = { b = s.b, e = cut, trig = s.trig, intent = s.intent }
      end
      local spec = M.intents[s.intent]
      -- ("cross LAM FL110, thereafter descend FL80": what is said "thereafter" or "after that" straight after a
      -- crossing starts at its waypoint; "then" keeps its own reading)
      local crossed = self.crossed
      self.crossed = nil
      -- (a value again after "after" and its place is the instruction's alone: G:until_then)
      self.conditioned_ask = nil
      self.place_ask = nil
      if (until_wp and until_wp.after) or not self:at_waypoint(s, spec) then
        self[spec and spec.handler or "infer"](self, s, spec)
      end
      local c0 = crossed and k > 1 and self:find_word(segs[k - 1].trig, s.trig, "thereafter afterwards after")
      if c0 and c0 < s.trig and (not self:word(c0, "after") or self:word(c0 + 1, "that"))
          and not self:any_instruction_in(c0 + 1, s.trig) and not self.ask and #self.out > n_before then
        self:explain(c0, self:word(c0, "after") and c0 + 2 or c0 + 1)
        if self:do_at(crossed.id, crossed.wp, n_before) then
          self.waypoint_do = { id = crossed.id, wp = crossed.wp, n = #self.out }
        end
      elseif until_wp and not self.ask and #self.out > n_before then
        self:explain(until_wp.u, until_wp.e)
        local id = self.out[n_before + 1]:match("^%u+ (%S+)")
        if self:do_at(id, until_wp.name, n_before) then
          n_before = n_before - self:kept_until(segs[k - 1], seg_out[k - 1], n_before, id)
          -- ("..., after ONOGI Mach .78 and heading 100": what follows of the same aircraft waits for the place
          -- too, joined by "and", or is asked; never sent now unasked)
          if until_wp.after then self.waypoint_do = { id = id, wp = until_wp.name, n = #self.out, e = s.e } end
        end
      elseif until_lvl and not at and not self.ask and #self.out > n_before then
        at = "ATALT " .. self.out[n_before + 1]:match("^%u+ (%S+)") .. " "
          .. handlers.format.alt(until_lvl.q.value, until_lvl.q.fl)
      elseif tail and not self.ask and #self.out > n_before then
        self:do_at(self.out[n_before + 1]:match("^%u+ (%S+)"), tail.name, n_before)
      elseif at_next and not self.ask and #self.out > n_before then
        self:do_at(self.out[n_before + 1]:match("^%u+ (%S+)"), at_next.name, n_before)
      elseif at_next and not self.ask then
        tied_to_waypoint(self, at_next)
      end
      if not self.ask and #self.out > n_before then
        self:leftovers(s)
        self:unexplained(s, n_before)
      end
      -- ("klm33 fl200 250 kts passing LOMKI": a value beside the one tied to the waypoint may be meant there too)
      if tail and not self.ask and #self.out > n_before + 1 and not self.out[#self.out]:match("^AT ") then
        self:need(string.format("I have %s. Which of these should happen at %s?", table.concat(self.out, " ; "),
          tail.name))
      end
      if at then
        for c = n_before + 1, #self.out do
          -- (a wait said after the callsign, G:at_time's `at_all_for`, times that aircraft's commands only)
          if at ~= self.at_all or not self.at_all_for or self.out[c]:match("^%u+ (%S+)") == self.at_all_for then
            self.out[c] = at .. " " .. self.out[c]
          end
        end
      end
      -- ("descend FL80, reduce 230, when level reduce 210": "level" is the level cleared, whatever was said
      -- between)
      local id = not at and not self.ask and #self.out == n_before + 1 and self.out[#self.out]:match("^%u+ (%S+)")
      if id and self:word_in(s.b, s.trig, "level lvl") and self:when_reached(s) then
        for c = n_before, 1, -1 do
          local level = self.out[c]:match("^ALT " .. id:gsub("%p", "%%%0") .. " (%S+)")
          if level then
            before = "ATALT " .. id .. " " .. level
            break
          end
        end
      end
      -- ("reduce 230, once slowed descend 6000": a condition of slowing waits for a speed given, never a level)
      local _, by_speed = self:when_reached(s)
      if by_speed and before and before:sub(1, 5) ~= "ATSPD" then before = nil end
      -- A value instruction said without its value next to other, complete
      -- instructions is left out; it becomes the question only when nothing
      -- else was understood. One whose value is named by what it is ("reduce to minimum clean speed, say
      -- speed") is asked all the same (the words kept out of the lexicon's lists, so that one nothing read
      -- elsewhere is still asked about by name).
      local set_aside = false
      -- (one that waits for a condition, "after NAXEL turn left", "in 2 minutes turn left", is asked all the same:
      -- no condition is dropped)
      if self.ask and spec and spec.value and self:values_after_trigger(s) == 0 and not self:change_word(s.trig)
          and not self.conditioned_ask and not self.place_ask and not (at and at ~= self.at_all)
          and not self:word_in(s.trig + 1, s.e, "minimum maximum min max best optimum optimal clean econ economy") then
        self.pending = self.pending or self.ask
        valueless[#valueless + 1] = { k = k, ask = self.ask }
        self.ask = nil
        set_aside = true
      end
      -- ("descend to 10000, turn left heading 070, and slow to 240 once it's level": the level this request
      -- cleared the same aircraft to, an instruction of another kind between)
      if unheld and not self.ask and #self.out == n_before + 1 then
        local id = self.out[#self.out]:match("^%u+ (%S+)")
        for c = n_before, 1, -1 do
          local level = id and self.out[c]:match("^ALT " .. id:gsub("%p", "%%%0") .. " (%S+)$")
          if level then
            before, unheld = "ATALT " .. id .. " " .. level, false
            break
          end
        end
      end
      if set_aside then
        -- (set aside above, a valueless instruction)
      elseif unheld and not self.ask then
        self:need("I have " .. table.concat(self.out, " ; ") .. ". No level was cleared before '"
          .. self:raw(reached_cut, s0.e) .. "': which level should the last instruction wait for?")
      -- (an instruction with a condition of its own, "when passing FL150 reduce 210", waits for that one only)
      elseif (self:then_after(segs, k) or self:when_reached(s) or reached_cut) and before and #self.out == n_before + 1
          and spec and not at
          and ((spec.value and (self.out[#self.out]:upper():sub(1, 4) == "SPD ") ~= (before:sub(1, 5) == "ATSPD"))
            -- ("climb FL090, on reaching resume own navigation", "when level direct LOREL": a switch of
            -- navigation or a direct-to waits for the value reached as a speed does)
            or (not self:then_after(segs, k) and self.out[#self.out]:match("^[LV]NAV ")
                or self.out[#self.out]:match("^DIRECT %S+ %S+$"))
            -- ("descend FL230 and when level turn right heading 140": a heading said as one waits for the
            -- level reached too; a turn by degrees, counted from the heading now, is asked about)
            or (not self:then_after(segs, k) and self.out[#self.out]:match("^HDG ") and before:match("^ATALT ")
                and self:word_in(s.b, s.e, "heading hdg"))) then
        self.out[#self.out] = before .. " " .. self.out[#self.out]
      elseif self:when_reached(s) and not before and not at and #self.out == n_before + 1 and n_before > 0
          and self.out[n_before]:match("^DIRECT ") and not self.out[#self.out]:match("^AT ") and not self.ask then
        -- "dct PTH, once there FL80": the constraint at the waypoint flown to (AT id WPT ALT/SPD value); never a
        -- clause with a condition of its own ("direct BNN, when passing FL110 reduce 220": ATALT)
        local id, wpt = self.out[n_before]:match("^DIRECT (%S+) (%S+)$")
        local cmd, value = self.out[#self.out]:match("^(%u+) " .. (id or ""):gsub("%p", "%%%0") .. " (%S+)$")
        if id and (cmd == "ALT" or cmd == "SPD") then
          self.out[#self.out] = "AT " .. id .. " " .. wpt .. " " .. cmd .. " " .. value
          local c = self:find_word(s.b, s.trig, "@condition")
          for i = c, s.trig - 1 do self.noted[i] = true end
        else
          self:need("I have " .. table.concat(self.out, " ; ") .. ". squawk can tie only a level or a speed to "
            .. (wpt or "the waypoint") .. ": what should happen there?")
        end
      elseif reached_cut and not self.ask then
        -- (a condition it cannot carry is asked about, never dropped)
        self:need("I have " .. table.concat(self.out, " ; ") .. ". When should the last instruction start: '"
          .. self:raw(reached_cut, s0.e) .. "'?")
      elseif not at and not self.ask and #self.out > n_before and not self.out[#self.out]:match("^AT%u* ")
          and self:when_reached(s) then
        -- ("on reaching turn left 20 degrees", "when you reach it reduce 220" with no level before it: the
        -- condition opening the clause is asked about, never dropped)
        local c, e = self:find_word(s.b, s.trig, "@condition"), s.trig
        if c >= s.trig then c = self:find_word(s.b, s.trig, "reaching") end
        if self:word(c - 1, "on") then c = c - 1 end
        while e > c + 1 and self.t[e - 1].kind == "punct" do e = e - 1 end
        self:need("I have " .. table.concat(self.out, " ; ") .. ". When should the last instruction start: '"
          .. self:raw(c, e) .. "'?")
      end
    end
    if corrected and self.ask then
      self.ask = nil
      self:explain(s.trig, nx.b)
    end
    -- (a request taken back: read for its aircraft, which the next may name as "it", its commands dropped)
    for x = #self.out, withdrawn and seg_out[k] + 1 or #self.out + 1, -1 do self.out[x] = nil end
    issued_by[k] = #self.out > prev_out
  end
  self:valueless_left(segs, valueless, issued_by)
  -- (a time held for with no instruction after it to wait: asked, never dropped)
  if self.wait_next and not self.ask then
    self:need("Which instruction should wait " .. self.wait_next:gsub("^DELAY ", "") .. " s?")
  end
  self.wait_next = nil
  -- (a waypoint said for the next instruction, with none after it)
  if self.at_next and not self.ask then tied_to_waypoint(self, self.at_next) end
  self.at_next = nil
  self:direct_resumes_nav()
  self:direct_beside_lnav_off()
  self:destination_not_waypoint()
end

-- A value instruction with no value of its own (`valueless`: {k, ask} by segment number k of `segs`), left out
-- beside value commands issued (ALT, SPD, HDG, VS; `issued_by[k]`: segment k issued a command), is asked, naming
-- what was issued, when its segment holds only instruction words (triggers, a turn's side, a direction, "and",
-- "then"), the callsign, fillers and marks ("climb FL300 reduce", "slow down KLM12 climb FL300"). It is read as a
-- word of an instruction issued when a command it may issue was issued and no instruction of its kind issued
-- changes the other way ("climb and maintain FL300", "speed 280, maintain"; a level and a rate are one: "descend
-- FL200, expedite"), when it is a rate said with no value ("turn left heading 040, expedite": the manner), when it
-- names what the instruction straight before it asks for ("say alt") or it is said straight before the next
-- instruction's word ("increase the heading by 30"). Refused ("do not descend"), the negation is asked about by
-- the accounting; named after "for" ("standby for descent") it is announced. Other words in its segment say what
-- it is ("no speed restrictions") and leave it out as before.
G.value_intents = { alt = "ALT", maintain = "ALT SPD HDG", spd = "SPD", hdg = "HDG", vs = "VS" }
G.value_commands = { ALT = true, SPD = true, HDG = true, VS = true }
G.negations = {}
for _, w in ipairs(lexicon.accounted.negation) do G.negations[w] = true end
function G:valueless_left(segs, valueless, issued_by)
  if self.ask or #self.out == 0 then return end
  self:dangling_value_name()  -- ("climb fl320 spd": that question first)
  if self.ask then return end
  local function against(a, b)  -- true when the words at a and b change the other way ("climb" and "descend")
    return self:word(a, "@up") and self:word(b, "@down") or self:word(a, "@down") and self:word(b, "@up")
  end
  local issued = {}  -- the value commands issued, a rate's as a level's
  for _, line in ipairs(self.out) do
    for verb in line:gmatch("%f[%w](%u+)%f[%W]") do
      if G.value_commands[verb] then issued[verb] = true end
    end
  end
  issued.ALT = issued.ALT or issued.VS
  for _, v in ipairs(valueless) do
    local s, before, after = segs[v.k], segs[v.k - 1], segs[v.k + 1]
    -- (beside other commands only, an imperative verb of lexicon.clause_verbs, "pause the simulation, climb": a
    -- value's name there, "back to real time speed", "state (alt, spd, hdg)", is the other command's)
    if not next(issued) and not self:word(s.trig, "@clause_verbs") then goto next_valueless end
    local bare = s.intent ~= "vs"
    for i = s.b, s.e - 1 do
      local t = self.t[i]
      -- ("off" after its instruction word is that word's: "and level off")
      bare = bare and (t.kind ~= "word" or t.filler or self.triggers[i] or (t.text == "off" and self.triggers[i - 1])
        or self:word(i, "@left @right @up @down and then") or self:has_ref(i, i + 1, "aircraft")
        -- ("speed up a bit", "slow down slightly": a degree of no size is no value either)
        or self:word(i, "@vague_direction") or (self:word(i, "a") and self:word(i + 1, "@vague_direction")))
    end
    -- (one refused, "do not descend", is the negation's: the accounting asks about it; one named after "for",
    -- "standby for descent", is announced, no instruction)
    local refused = self:word(s.trig - 1, "for")
    for i = math.max(1, s.trig - 2), s.trig - 1 do refused = refused or G.negations[self.t[i].text] end
    local next_word = self:skip_fillers(s.trig + 1)
    if self:word(next_word, "the") then next_word = self:skip_fillers(next_word + 1) end
    -- ("no restriction on speed", "no ATC restrictions on your speed": the restriction lifted, its noun said last)
    local k = self:word(s.trig - 1, "the your its") and s.trig - 2 or s.trig - 1
    local r = self:word(k - 1, "restriction restrictions limit limits") and k - 1
    if r and self:word(r - 1, "atc") then r = r - 1 end
    local lifted = self:word(k, "on") and r and self:word(r - 1, "no")
    for verb in (lifted and G.value_intents[s.intent] or ""):gmatch("%u+") do
      if issued[verb] then
        self:need(string.format("I have %s. Which stands: '%s', or the %s given?", table.concat(self.out, " ; "),
          self:raw(r - 1, s.trig + 1), self:raw(s.trig, s.trig + 1)))
        return
      end
    end
    local read = not bare or refused or lifted
      or (before and issued_by[v.k - 1] and self:skip_fillers(before.trig + 1) == s.trig)
      or (after and issued_by[v.k + 1] and next_word == after.trig)
    for verb in (G.value_intents[s.intent] or ""):gmatch("%u+") do read = read or issued[verb] end
    for j, o in ipairs(segs) do
      if issued_by[j] and G.value_intents[o.intent] == G.value_intents[s.intent] and against(s.trig, o.trig) then
        read = false
      end
    end
    if not read then
      self:need("I have " .. table.concat(self.out, " ; ") .. ". " .. v.ask)
      return
    end
    ::next_valueless::
  end
  -- an instruction word said straight after the value of a value instruction that issued, of another family or
  -- changing the other way ("climb FL300 descend", "... down"), a word the rules read as a stop of the run
  -- closing its clause with no instruction read from it ("climb FL300 stop"), or a turn's side said so after a
  -- value that is no heading ("climb FL300 left")
  for k, s in ipairs(segs) do
    -- (a rate's direction follows its value: "vertical speed 1200 up")
    local q = issued_by[k] and s.intent ~= "vs" and G.value_intents[s.intent] and self:quantities(s.trig + 1, s.e)[1]
    local i = q and q.e
    while i and self.t[i] and (self.t[i].kind == "punct" or self.t[i].filler) do i = i + 1 end
    local intent = i and i < s.e and self.triggers[i] and self:intent_at(i)
    -- (a word the rules read as a stop of the run, never as keeping a value, closing its clause with no
    -- instruction read from it: "climb FL300 stop")
    local nx = i and self:skip_fillers(i + 1)
    local ends = i and (not self.t[nx] or self.t[nx].kind == "punct")
    local stops, keeps = false, false
    for _, r in ipairs(i and i < s.e and not intent and RULES_BY_WORD[self.t[i].text] or {}) do
      stops, keeps = stops or (not r.any and r.intent == "hold"), keeps or r.intent == "maintain"
    end
    local closing = ends and stops and not keeps and not self.u:used(i) and not (self.explained or {})[i]
      and not self.noted[i]
    if i and i < s.e and ((intent and #self:quantities(i + 1, s.e) == 0 and (against(s.trig, i)
          or not (same_family(intent, s.intent) or intent == "maintain"
            or G.value_intents[intent] == "VS" and G.value_intents[s.intent] == "ALT")))
        or (ends and against(s.trig, i)) or closing
        or (s.intent ~= "hdg" and self:word(i, "@left @right") and not self:in_reason(i))) then
      self:need("I have " .. table.concat(self.out, " ; ") .. ". What does '" .. self.t[i].raw .. "' mean?")
      return
    end
  end
end

-- The level a segment's instruction waits for, said after it: "..., (but only) when/once it is at /
-- reaches / passes FL250 (please)" closing the segment, or "passing"/"reaching" and the level straight after the
-- instruction's value ("reduce 250 knots passing FL150"); the level and where its words begin, or nil.
-- A speed's level said after "above" or "below" closing the segment ("Mach .76 above FL300", "250 kt below
-- FL100"): the speed held from that level, the same reading ("not above FL300" is a limit, no condition).
function G:trailing_level(s)
  local c = self:find_word(s.trig + 1, s.e, "when once after")
  -- ("reduce 250 knots passing FL150": "passing" or "reaching" straight after the instruction's own value)
  local bare = false
  if c >= s.e then
    local p = self:find_word(s.trig + 1, s.e, "passing reaching")
    local qs = p < s.e and self:quantities(s.trig, p) or {}
    local v = qs[#qs]
    if v and v.e == p and (v.kind == "speed" or v.kind == "mach" or v.kind == "heading"
        or (v.kind == "plain" and v.b > s.trig)) then
      c, bare = p, true
    end
  end
  if c >= s.e and (s.intent == "spd" or s.intent == "infer") then
    local a = self:find_word(s.trig + 1, s.e, "above below")
    local q = a < s.e and not self:word(a - 1, "not") and self:quantities(a + 1, s.e)[1]
    if not (q and q.kind == "alt" and q.b == self:skip_fillers(a + 1)) then return nil end
    local spd = self:quantities(s.b, a)
    spd = spd[#spd]
    if not (spd and spd.e == a and (spd.kind == "speed" or spd.kind == "mach"
        or (spd.kind == "plain" and s.intent == "spd" and spd.b > s.trig))) then
      return nil
    end
    for i = q.e, s.e - 1 do
      if not (self.t[i].kind == "punct" or self.t[i].filler or self:word(i, "please thanks thank you cheers")) then return nil end
    end
    return q, a
  end
  if c >= s.e then return nil end
  local cut = c
  while cut - 1 > s.trig and (self.t[cut - 1].kind == "punct" or self:word(cut - 1, "but only")) do cut = cut - 1 end
  local q = self:quantities(c + 1, s.e)[1]
  -- (three digits alone, the flight level this request cleared an aircraft to: "..., when he is at 340")
  local given = q and self:level_given(q)
  if given then q = { kind = "alt", value = given, fl = true, b = q.b, e = q.e } end
  -- (digits typed with no unit after "after" or a word of passing, whole hundreds from 2400 to 45000: feet, "speed
  -- 250 after 10000", "..., after passing 12000"; "after 1200" may be a time of day, asked)
  if q and q.kind == "plain" and not q.fl and q.number and q.number.typed and q.value >= 2400 and q.value <= 45000
      and q.value % 100 == 0 then
    q = { kind = "alt", value = q.value, fl = false, b = q.b, e = q.e }
  end
  if not q or not (q.kind == "alt" or (q.kind == "plain" and q.fl)) then return nil end
  -- ("250 after 10000": the level straight after "after" is passed)
  local reached = bare or (self:word(c, "after") and q.b == self:skip_fillers(c + 1))
  for i = c + 1, q.b - 1 do
    if self:word(i, "reaches reaching reach passes passing gets get at through below above crosses crossing") then
      reached = true
    elseif not (self:word(i, "it he she they you you're is are to flight level") or self.t[i].filler
                or #self:refs_in(i, i + 1, "aircraft") > 0) then
      return nil
    end
  end
  for i = q.e, s.e - 1 do
    if not (self.t[i].kind == "punct" or self.t[i].filler or self:word(i, "please")) then return nil end
  end
  if not reached then return nil end
  return q, cut
end

-- True when the word at i asks for a change in one direction ("go left then climb FL320", "go faster
-- and climb FL320", "fly west and slow down", "heading 270 and climb", "speed 250, then left"): with
-- no value said that instruction is asked about, never dropped beside the others. A climb or turn
-- word inside another instruction ("a vertical speed for climbing", "turn the bank angle") is one only
-- where it opens a clause of its own after another (a comma, "and" or "then" before it, or before its
-- callsign), or is a turn side or speed direction said after "go".
function G:change_word(i)
  if self:word(i, "@left @right @faster_slower") and self:word(i - 1, "go") then return true end
  if self:word(i, "slow") and self:word(i + 1, "down") and self:word(i - 1, "and then") then return true end
  if not self:word(i, "@left @right @faster_slower @up @down turn") or self:word(i, "above below") then return false end
  if self:word(i + 1, "@speed_units @feet") then return false end  -- ("two one, uh, turn knots": a garbled digit)
  -- ("climb and turn right heading 300", "turn right, climb FL320": a clause closed after the word)
  local nx = self:word(i + 1, "@left @right") and i + 2 or i + 1
  if self.t[nx] and ((self.t[nx].kind == "punct" and self.t[nx].text == ",") or self:word(nx, "and @then_words")) then
    return true
  end
  local k = i - 1
  while k >= 1 do
    local inside = false
    for _, r in ipairs(self:refs_in(math.max(1, k - 3), k + 1, "aircraft")) do inside = inside or (r.b <= k and k < r.e) end
    if not (inside or (self.t[k].kind == "word" and self.t[k].filler and not self:word(k, "and"))) then break end
    k = k - 1
  end
  return k >= 1 and ((self.t[k].kind == "punct" and self.t[k].text ~= "'") or self:word(k, "and @then_words"))
end

-- True when the word at i follows "then", "and" or a comma.
function G:linked(i)
  return i > 1 and ((self.t[i - 1].kind == "punct" and self.t[i - 1].text == ",") or self:word(i - 1, "and @then_words"))
end


-- "descend FL100 when passing GOTUR", "reduce 210 once it reaches CANUK", "climb FL200 after passing LUX": a
-- condition of passing a waypoint that closes the segment, after its instruction's value; the instruction
-- starts there (AT acid wp DO, G:do_at): { b = the condition's first token, e = the token after the
-- waypoint's name, name }, else nil. "at CANUK" alone after the value is no such condition (a crossing?).
local VALUE_INTENTS = { alt = true, spd = true, hdg = true, vs = true, maintain = true, infer = true }
-- True when the value of a level, speed, heading or rate instruction (segment s) ends straight before token c
-- (fillers and commas between).
function G:value_before(s, c)
  local v = c - 1
  while v > s.trig and (self.t[v].filler or self.t[v].text == ",") do v = v - 1 end
  local last = self:quantities(s.trig, v + 1)
  return VALUE_INTENTS[s.intent] and #last > 0 and last[#last].e == v + 1
end
function G:trailing_fix(s)
  local c = self:find_word(s.trig + 1, s.e, "when once after upon on")
  -- ("reduce 250 knots passing LOMKI", "descend FL200 overflying LOMKI": a verb of passing straight after the
  -- value, with no "when" before it, is the same condition)
  local bare = self:find_word(s.trig + 1, c, "passing passes reaching reaches overflying")
  bare = bare < c and self:has_ref(bare + 1, bare + 2, "waypoint") and self:value_before(s, bare) and bare
  if bare then c = bare end
  if c >= s.e or #self:quantities(s.trig, c) == 0 then return nil end
  local k = bare or self:skip_fillers(c + 1)
  -- ("descend FL200, but only after BETOS", "climb FL300 only when it is over BUMIL": the condition's limiting
  -- words before it, lexicon.condition_limiting, belong to it)
  local lead = c
  while not bare and lead - 1 > s.trig and (self:word(lead - 1, "@condition_limiting") or self.t[lead - 1].text == ",") do
    lead = lead - 1
  end
  while self.t[lead].kind == "punct" do lead = lead + 1 end
  -- ("descend FL250 after Weser", "reduce 250 after WSR": "after" straight after the value of a level, speed,
  -- heading or rate, and the waypoint, its code or a name of the aircraft's route, closing the request;
  -- "expect lower after KURDI" is no such condition, nor ADDWPT's "after")
  -- ("climb 9500 meter after pass XPC": the verb's bare form straight after "after" is read at the verb below)
  if self:word(c, "after") and not self:word(k, "it you passing passes reaching reaches overflying pass reach") then
    if self.u:used(c) or not self:value_before(s, lead) then return nil end
    local e = s.e
    while e > k and self.t[e - 1].kind == "punct" and self.t[e - 1].text ~= "," do e = e - 1 end
    local r = self:refs_in(k, e, "waypoint")[1]
    if r then return r.b == k and r.e == e and { b = lead, e = r.e, name = r.name } or nil end
    local a = self:refs_in(1, s.trig, "aircraft")
    local now = #a == 1 and self:state(a[1].name)
    local name = now and e > k and e <= k + 2 and self:place_by_name(k, e, now, true)
    return name and { b = lead, e = e, name = name } or nil
  end
  if self:word(k, "it you") then k = self:skip_fillers(k + 1) end
  -- ("fl100 when past WYP": typed short, "past" is passing; "climb FL390 once you reach BURAM", "... when you
  -- pass LOHRE": the verb's bare form after "you")
  if self:word(k, "passing passes reaching reaches overflying past reach pass") then
    k = self:skip_fillers(k + 1)
  elseif self:word(k, "has have") and self:word(k + 1, "passed reached") then  -- ("once it has passed YHZ")
    k = self:skip_fillers(k + 2)
  elseif self:word(k, "gets get") and self:word(k + 1, "to") then
    k = self:skip_fillers(k + 2)
  elseif not (self:word(k, "is it's") and self:word(k + 1, "at over")) then  -- ("once it is over BUMIL")
    return nil
  else
    k = self:skip_fillers(k + 2)
  end
  local r = self:refs_in(k, s.e, "waypoint")[1]
  if not r or r.b ~= k then return nil end
  local j = self:skip_fillers(r.e)
  while self.t[j] and self.t[j].kind == "punct" and self.t[j].text ~= "," do j = j + 1 end
  -- ("climb FL150 once it passes NAXEL, if you could", "... after passing VEMAS, if possible", "..., thanks":
  -- framing words only after a comma or "if", closing the request, are courtesy; a value, name or verb is not)
  local opened = self:word(j, "if") or (self.t[j - 1] and self.t[j - 1].text == ",")
  if j < s.e and not (opened and self:framing_only(self:word(j, "if") and j + 1 or j, s.e)) then return nil end
  return { b = lead, e = r.e, name = r.name }
end

-- "maintain 250 knots until SULUR then climb FL200", "speed 220 till VAKNX, then reduce 180": the
-- instruction before ends at a waypoint, "until" or "till" and its name straight before the "then" (a comma or
-- "and" between them at most) that opens
-- segment k, and segment k's starts there (BlueSky's AT acid wp DO, G:do_at): { u = the "until" token, e =
-- the token after the waypoint's name, name }, else nil.
function G:until_then(segs, k)
  local s, p = segs[k], segs[k - 1]
  -- ("reduce speed 250, after SUMAG 220": the segment opened by "after" and its place, G:after_place_value)
  if p and self:word(s.trig, "after") and self:after_place_value(s.trig) then
    local r = self:refs_in(s.trig + 1, s.e, "waypoint")[1]
    return { u = s.trig, e = r.e, name = r.name, after = true }
  end
  -- ("keep 280 knots until CPX1, after that reduce 250": "after that" as "then", straight before the instruction)
  local after_that = self:word(s.trig - 2, "after") and self:word(s.trig - 1, "that") and s.trig - 2
  if not p or not (s["then"] or self:word(s.trig, "@then_words") or self:word_in(p.trig + 1, s.trig + 1, "@until_then_words")
      or after_that) then
    return nil
  end
  for u = p.trig + 1, s.trig - 1 do
    if self:word(u, "until till") then
      local r = self:refs_in(u + 1, s.trig, "waypoint")[1]
      local n = r and self:skip_fillers(r.e)
      if n and self.t[n] and self.t[n].text == "," then n = self:skip_fillers(n + 1) end
      if n and self:word(n, "and") then n = n + 1 end
      if r and r.b == self:skip_fillers(u + 1) and self:word(n, "then @until_then_words") then
        return { u = u, e = r.e, name = r.name }
      end
      if r and r.b == self:skip_fillers(u + 1) and n == after_that then
        return { u = u, e = after_that + 2, name = r.name }
      end
    end
  end
  return nil
end

-- The level said after "until" or "till" at u ("until ten thousand", "till passing FL100", "until it's reaching
-- 8000 feet"; a subject and a verb of reaching between at most): its quantity, a level, else nil. Read once per
-- request and position (G:level_limits marks the level used, which the quantities then leave out).
function G:until_level(u)
  self.until_levels = self.until_levels or {}
  local memo = self.until_levels[u]
  if memo == nil then
    local v = self:skip_fillers(u + 1)
    if self:word(v, "@reached_subjects") then v = self:skip_fillers(v + 1) end
    if self:word(v, "@reached_verbs") then v = self:skip_fillers(v + 1) end
    if self:word(v, "passing reaching") then v = self:skip_fillers(v + 1) end
    local q = self:quantities(v, #self.t + 1)[1]
    memo = q and q.b == v and q.kind == "alt" and q or false
    self.until_levels[u] = memo
  end
  return memo or nil
end

-- The token after the level that "until" or "till" at u names (G:until_level) and a comma and "and" after it, when
-- that token is "then" or one of lexicon.until_then_words ("speed 250 until ten thousand, then 300"); else nil.
function G:until_level_end(u)
  local q = self:until_level(u)
  if not q then return nil end
  local n = self:skip_fillers(q.e)
  if self.t[n] and self.t[n].text == "," then n = self:skip_fillers(n + 1) end
  if self:word(n, "and") then n = n + 1 end
  return self:word(n, "then @until_then_words") and n or nil
end

-- "speed 250 until ten thousand, then 300", "maintain 250 knots till passing FL100, then increase 300": the
-- instruction before ends at a level, "until" or "till" and the level (G:until_level) straight before the "then" (a
-- comma or "and" between at most) that opens segment k; segment k's instructions wait for that level (ATALT):
-- { u = the "until" token, q = the level's quantity }, else nil.
function G:until_level_then(segs, k)
  local s, p = segs[k], segs[k - 1]
  if not p then return nil end
  for u = p.trig + 1, s.trig - 1 do
    local n = self:word(u, "until till") and self:until_level_end(u)
    if n and (n == s.trig or (s["then"] and self:skip_fillers(n + 1) == s.trig)) then
      return { u = u, q = self:until_level(u) }
    end
  end
  return nil
end

-- The kind ("spd" or "alt") of a value said bare after the "then" (or lexicon.until_then_words) at i, straight
-- after "until" (or "till") and a waypoint (a comma between at most), when the clause before holds a value of that kind ("maintain 280 knots until PEKIR then 250": a speed,
-- with or without its unit; "maintain FL160 until PEKIR then FL120": a level by its unit, FL or feet); nil otherwise.
function G:until_then_value(i)
  local r = self.refs and self:refs_in(math.max(1, i - 5), i, "waypoint")[1]
  local n = r and self:skip_fillers(r.e)
  if n and self.t[n] and self.t[n].text == "," then n = self:skip_fillers(n + 1) end
  if not r or n ~= i or not self:word(r.b - 1, "until till") then
    -- (a level after "until" instead of the waypoint: "speed 250 until ten thousand, then 300", G:until_level_then)
    local u = self:find_word(math.max(1, i - 7), i, "until till")
    if u >= i or self:until_level_end(u) ~= i then return nil end
    r = { b = u + 1 }
  end
  local q = self:quantities(i + 1, #self.t + 1)[1]
  if not q or q.b ~= self:skip_fillers(i + 1) then return nil end
  local before = self:quantities(math.max(1, r.b - 8), r.b - 1)
  local p = before[#before]
  if not p or p.e ~= r.b - 1 then return nil end
  return self:value_again_kind(p, q)
end

-- The kind ("spd" or "alt") of value q said bare after a place, when it closes its clause and value p before the
-- place is of that kind (a speed, with or without its unit: p by its unit or its noun or verb of speed; a level
-- by its unit, FL or feet); nil otherwise.
function G:value_again_kind(p, q)
  -- ("until KORRY, and then 220 after that", "then 220 afterwards": the words that say "then" again close it)
  local a = q.e
  if self:word(a, "after") and self:word(a + 1, "that") then
    a = a + 2
  elseif self:word(a, "afterwards afterward thereafter") then
    a = a + 1
  end
  local after = self.t[a]
  if after and after.kind ~= "punct" then return nil end
  if a > q.e then
    self:mark_used(q.e, a)
    self:explain(q.e, a)
  end
  local function speed(x) return x.kind == "speed" or x.kind == "mach" end
  -- ("after UTICA reduce 250, after GAVOL 220", "reduce to 250, ...": a bare number of 100 to 400 after a verb
  -- of changing speed, "to" between or not, is a speed)
  local lead = self:word(p.b - 1, "to") and p.b - 2 or p.b - 1
  local p_speed = speed(p) or (p.kind == "plain" and (self:word(p.b - 1, "speed airspeed @speed_verbs")
    or (self:word(lead, "reduce reducing increase increasing") and p.value >= 100 and p.value <= 400)))
  if p_speed and (speed(q) or (q.kind == "plain" and q.value >= 100 and q.value <= 400)) then return "spd" end
  if p.kind == "alt" and q.kind == "alt" and (q.fl or self:word(q.e - 1, "@feet")) then return "alt" end
  return nil
end

-- "reduce speed 250, after SUMAG 220", "maintain FL230, after BOYSE FL150": the kind (G:value_again_kind) of a
-- value said bare straight after "after" (at i) and a waypoint, opening a clause (a comma or "and" before it) that
-- (or "then") follows a value; the value is that instruction again, from the place (G:until_then). nil otherwise.
-- verbs of passing a waypoint after "when", "once" or "after" and the aircraft's pronoun ("when it passes KONAK")
G.passes_verbs = "passes pass passed crosses cross crossed overflies overfly overflew reaches reach reached"
-- True when the token at v is a verb of G.passes_verbs after the aircraft's pronoun and "when", "once" or "after"
-- ("after it passes NIKAS", "once you cross DIPOS").
-- "after OLMUE reduce 220 knots and descend FL110", "at BOGNA reduce 250 and descend FL110": true when the one
-- instruction after the segment tied to a waypoint (ending at token e) is joined to it by "and" (a comma before it or
-- not) and closes the request with no place, condition, "then" or word of lexicon.at_once_words of its own: it waits
-- for the waypoint too. A comma alone, a full stop or "then" between leaves it asked.
function G:joined_under_waypoint(e)
  -- (the segment holds the joining words before the next instruction's word at e)
  local x, joined = e - 1, false
  while x > 0 and (self.t[x].filler or (self.t[x].kind == "punct" and self.t[x].text == ",")) do
    joined = joined or self.t[x].text == "and"
    x = x - 1
  end
  x = e
  if not joined or not self.t[x] then return false end
  for y = x, #self.t do
    local t = self.t[y]
    if (t.kind == "punct" and not (y == #self.t and t.text:match("^[%.!]$"))) or t.text == "and"
        or self:word(y, "@then_words @at_once_words @condition at after before until till over when once") then
      return false
    end
  end
  return not self:has_ref(x, #self.t + 1, "waypoint")
end
function G:passes_said(v)
  return self:word(v, G.passes_verbs) and self:word(v - 1, "it he she you they") and self:word(v - 2, "when once after")
end
-- ("..., after passing SUMAG 220", "maintain FL340, and after it passes NIKAS, FL300": the aircraft's passing it
-- said between, G.passes_verbs)
function G:after_place_value(i)
  local v = self:skip_fillers(i + 1)
  if self:word(v, "passing") then
    v = self:skip_fillers(v + 1)
  elseif self:word(v, "it he she you they") and self:word(self:skip_fillers(v + 1), G.passes_verbs) then
    v = self:skip_fillers(self:skip_fillers(v + 1) + 1)
  end
  local r = self.refs and self:refs_in(v, math.min(#self.t + 1, v + 4), "waypoint")[1]
  if not r or r.b ~= v then return nil end
  local q = self:quantities(r.e, #self.t + 1)[1]
  -- ("reduce speed to 230 knots, after OTRON to 210": "to" before the value, as the verb said before it)
  local qb = self:skip_fillers(r.e)
  if self:word(qb, "to") then qb = self:skip_fillers(qb + 1) end
  if not q or q.b ~= qb then return nil end
  -- ("speed 250 then after NUKSI 220", "..., and then after NUKSI 220": a "then" before "after" waits for the place
  -- named, never for the value before it)
  local c = i - 1
  local thn = self:word(c, "then")
  if thn then c = c - 1 end
  local anded = self:word(c, "and")
  if anded then c = c - 1 end
  if not (self.t[c] and self.t[c].text == ",") then
    -- ("200 knots until MAH and after MAH 180 knots": "and" alone straight after the value's "until" the same place)
    local u0 = anded and not thn and self:refs_in(math.max(1, c - 3), c + 1, "waypoint")
    u0 = u0 and u0[#u0]
    local same = u0 and u0.e == c + 1 and u0.name:upper() == r.name:upper() and self:word(u0.b - 1, "until till")
    if not (thn or same) then return nil end
    c = c + 1
  end
  -- ("reduce 220 knots until TEXAS, after TEXAS 180 knots": the value kept until the same place, said before)
  local u = self.t[c - 1] and self:refs_in(math.max(1, c - 4), c, "waypoint")
  u = u and u[#u]
  if u and u.e == c and u.name:upper() == r.name:upper() and self:word(u.b - 1, "until till") then c = u.b - 1 end
  local before = self:quantities(math.max(1, c - 8), c)
  local p = before[#before]
  if not p or p.e ~= c then return nil end
  local kind = self:value_again_kind(p, q)
  if kind then return kind end
  -- ("climb FL310, after ONOGI Mach .78", "speed 250, after LOMKI FL200": a value closing the clause by its own
  -- unit, a Mach number, knots, FL or feet, names its instruction whatever the value before)
  local nx = self.t[q.e]
  if nx and nx.kind ~= "punct" and not self:word(q.e, "and") then return nil end
  if q.kind == "mach" or q.kind == "speed" then return "spd" end
  if q.kind == "alt" and (q.fl or self:word(q.e - 1, "@feet")) then return "alt" end
  return nil
end

-- True when segment k follows the one before it by a bare "then" in the formal phraseology of a
-- clearance held until reached ("descend and maintain 4000 then reduce speed to 210": it waits for
-- 4000); in plain English "then" lists the next instruction ("slow to 280 then descend FL170").
function G:then_after(segs, k)
  return k > 1 and segs[k]["then"] == "then" and self:word_in(segs[k - 1].b, segs[k].e, "maintain")
end

-- True when the instruction opens with a condition that names the value of the
-- instruction before it, by "there" or "level" and no value of its own ("climb
-- to FL150, and when it gets there, speed it up to 290": ATALT ... FL150 SPD ...), or by "reaching" alone
-- ("descend FL60, when reaching reduce speed 210"; "reaching" alone opening the clause: "climb FL370, reaching
-- Mach .79").
-- "once level", "when it's level", "once he's there", "when it gets there": the position of "once" or "when"
-- before the word at k ("level", "lvl", "there"), a subject (lexicon.reached_subjects) and a verb of being or
-- getting (lexicon.reached_verbs) between or not; nil when none.
function G:reached_opening(k)
  local c = k - 1
  if self:word(c, "@reached_verbs") then c = c - 1 end
  if self:word(c, "@reached_subjects") then c = c - 1 end
  return self:word(c, "once when") and c or nil
end

function G:when_reached(s)
  local c = self:find_word(s.b, s.trig, "@condition")
  -- (a condition taken back, noted by G:condition, waits for nothing)
  if self.noted[c] then return false end
  if c >= s.trig then
    -- ("climb FL370, reaching Mach .79", "on reaching reduce 250": "reaching" alone opening the clause)
    -- (after the clause's callsign: "RYR8GN on reaching reduce 220")
    if not self:said("reaching") then return false end
    local v = self:skip_fillers(s.b)
    for _, a in ipairs(self:refs_in(v, v + 1, "aircraft")) do v = self:skip_fillers(a.e) end
    if self.t[v] and self.t[v].kind == "punct" then v = self:skip_fillers(v + 1) end
    if self:word(v, "on upon") then v = self:skip_fillers(v + 1) end
    if not self:word(v, "reaching") then return false end
    -- ("on reaching it", "upon reaching that": the level of the instruction before, by a pronoun)
    v = self:skip_fillers(v + 1)
    if self:word(v, "it that") then v = self:skip_fillers(v + 1) end
    return self:instruction_lead(v, s.trig) == s.trig
  end
  if #self:quantities(c, s.trig) > 0 then return false end
  local verb = self:skip_fillers(c + 1)
  if self:word_in(c + 1, s.trig, "there level lvl") then return true end
  -- ("once it has levelled off", "once it levels out": the level of the instruction before, reached; the verb's
  -- particle is part of it, never a switch, G:unread_switch)
  local levelled = self:find_word(c + 1, s.trig, "levelled leveled levels")
  if levelled < s.trig then
    if self:word(levelled + 1, "off out") then self.noted[levelled + 1] = true end
    return true
  end
  -- ("when you're at that speed", "once it is at the speed", "when he arrives at this speed": the speed of the
  -- instruction before, reached; only a subject, "is" or "arrives", "at" and "that", "this" or "the" before
  -- "speed", straight before the instruction)
  local at = self:find_word(c + 1, s.trig, "speed")
  if at < s.trig and self:skip_fillers(at + 1) == s.trig and self:word(at - 1, "that the this")
      and self:word(at - 2, "at") then
    for i = c + 1, at - 3 do
      if not (self.t[i].filler or self:word(i, "you you're are it it's is he he's she she's arrives arrive")) then
        return false
      end
    end
    return true, "speed"
  end
  -- ("when speed reached", "once the speed is reached", "when that speed has been reached": the noun as the subject
  -- of a verb of reaching, with no value: the speed of the instruction before, reached)
  if at < s.trig and self:skip_fillers(self:word(verb, "that the") and verb + 1 or verb) == at then
    local k = self:skip_fillers(at + 1)
    if self:word(k, "is 's has") then k = self:skip_fillers(k + 1) end
    if self:word(k, "been") then k = self:skip_fillers(k + 1) end
    if self:word(k, "reached achieved attained") then
      return self:instruction_lead(self:skip_fillers(k + 1), s.trig) == s.trig, "speed"
    end
  end
  -- ("when reaching", "when you reach it", "once it reaches that", "when you hit it": the level of the
  -- instruction before; "once you have it", "when you've got it": its value, held)
  local subject = self:word(verb, "you it he she they")
  if subject then verb = self:skip_fillers(verb + 1) end
  -- ("once you've got that speed", "when it has got it": the subject and "have" said before "got")
  if self:word(verb, "you've they've it's he's she's") and self:word(self:skip_fillers(verb + 1), "got") then
    subject, verb = true, self:skip_fillers(verb + 1)
  elseif subject and self:word(verb, "has have 've") and self:word(self:skip_fillers(verb + 1), "got") then
    verb = self:skip_fillers(verb + 1)
  end
  -- ("once slowed", "when you've slowed down", "once it has slowed to that": the speed of the instruction before,
  -- reached; true and "speed")
  local slowed = verb
  if self:word(slowed, "you've they've it's he's she's") then slowed = self:skip_fillers(slowed + 1) end
  if self:word(slowed, "has have 've") then slowed = self:skip_fillers(slowed + 1) end
  -- ("reduce speed 250, after reducing descend FL100", "after slowing, ...": "after" and the gerund, the slowing done)
  if self:word(slowed, "@speed_verbs")
      or (self:word(c, "after") and slowed == verb and self:word(slowed, "reducing slowing decelerating")) then
    verb = slowed
    local k = self:skip_fillers(verb + 1)
    if self:word(k, "down up") then k = self:skip_fillers(k + 1) end
    if self:word(k, "to") and self:word(self:skip_fillers(k + 1), "it that") then k = self:skip_fillers(self:skip_fillers(k + 1) + 1) end
    return self:instruction_lead(k, s.trig) == s.trig, "speed"
  end
  -- ("once it has done so", "when it does that": the value of the instruction before, reached)
  -- ("so" may be a filler: read straight after the verb)
  if self:word(slowed, "done does do did") and self:word(slowed + 1, "so that") then
    return self:instruction_lead(self:skip_fillers(slowed + 2), s.trig) == s.trig
  end
  local have = subject and self:word(verb, "have got") and self:word(self:skip_fillers(verb + 1), "it that")
  if not (have or self:word(verb, "reaching reach reaches reached hit hits")) then return false end
  local k = self:skip_fillers(verb + 1)
  -- ("once it reaches that height", "when it reaches that speed": the value named by its kind)
  local kind
  if self:word(k, "that this") and self:word(self:skip_fillers(k + 1), "height altitude level speed") then
    kind = self:word(self:skip_fillers(k + 1), "speed") and "speed" or nil
    k = self:skip_fillers(k + 1)
  end
  -- (the instruction's own word is no noun of the value reached: "after reach, speed 280")
  if k ~= s.trig and self:word(k, "it that height altitude level speed") then k = self:skip_fillers(k + 1) end
  return self:instruction_lead(k, s.trig) == s.trig, kind
end

-- The position after the words at k that lead into the instruction word at trig ("start its descent", "begin the
-- climb", "route direct", "fly direct"): "start" or "begin" and a determiner, or "route", "fly" or "track" before
-- "direct", before trig only; else k.
function G:instruction_lead(k, trig)
  local v = k
  if self:word(v, "start begin") then v = self:skip_fillers(v + 1) end
  if self:word(v, "route fly track") and self:word(v + 1, "direct dct") then v = v + 1 end
  if v > k and self:word(v, "its the your his her their") then v = self:skip_fillers(v + 1) end
  return v == trig and v or k
end

-- The same condition said after the instruction it holds, closing its segment ("reduce 180 kts when
-- level", "speed 250 once there", "when it's level please", "reduce 220 when you reach it", "once it
-- reaches that"): where its words begin, or nil. Only "it", "you", "is", "gets", "that" and fillers may join
-- "when"/"once" to "level", "lvl", "there" or a verb of reaching.
function G:trailing_reached(s)
  local c = self:find_word(s.trig + 1, s.e, "when once")
  -- ("resume own nav on reaching", "reduce 250 after reaching", "... after level", "reduce 250 reaching": "on",
  -- "upon" or "after" before the verb of reaching or "level", or the verb alone)
  local on = self:find_word(s.trig + 1, s.e, "on upon after reaching")
  local named = false
  if on < c and self:word(on, "reaching") then
    c, named = on, true
  elseif on < c then
    -- ("slow to 250 after it levels")
    local nx = self:skip_fillers(on + 1)
    if self:word(on, "after") and self:word(nx, "it he she you") then nx = self:skip_fillers(nx + 1) end
    if self:word(nx, self:word(on, "after") and "reaching level levels levelled leveled" or "reaching") then c = on end
  end
  -- (words another reading took, "report reaching", are no condition)
  if c >= s.e or self.u:used(c) or self.u:used(self:skip_fillers(c + 1)) then return nil end
  for i = c + 1, s.e - 1 do
    if self:word(i, "there level lvl reach reaches reaching levels levelled leveled") then named = true
    elseif not (self.t[i].kind == "punct" or self.t[i].filler
        or self:word(i, "it it's its is gets get you you're are that please arrives arrive has have up down")) then
      return nil
    end
  end
  if not named then return nil end
  while c - 1 > s.trig and self.t[c - 1].kind == "punct" do c = c - 1 end
  return c
end

-- "resume own navigation direct TIMBA": BlueSky's DIRECT switches LNAV on, so
-- an "LNAV id ON" followed by a DIRECT for the same aircraft is that DIRECT's (also one that waits
-- for a condition: "after passing FL100 resume own navigation direct HEMEL": the condition the LNAV
-- waited for is the DIRECT's). The switch typed by its name ("hop7 lnav on dct LIL") is an instruction
-- said, kept.
function G:direct_resumes_nav()
  for c = #self.out, 1, -1 do
    local cond, id = self.out[c]:match("^(.-)LNAV (%S+) ON$")
    if id and (cond == "" or cond:match("^AT%u* ")) and not (self.lnav_typed or {})[id] then
      for d = c + 1, #self.out do
        local o = self.out[d]
        local plain = o:match("^DIRECT " .. id:gsub("%p", "%%%0") .. " ")
        if plain or o:find(" DIRECT " .. id .. " ", 1, true) then
          if plain and cond ~= "" then self.out[d] = cond .. o end
          table.remove(self.out, c)
          break
        end
      end
    end
  end
end

-- "hop7 lnav off dct LIL", "KLM33 direct GILOM, then LNAV off": DIRECT switches LNAV on, so an aircraft's LNAV
-- OFF and a direct-to of the same aircraft, under one condition or none, undo each other in either order (before
-- it the switch is lost, after it the aircraft no longer flies to the waypoint): asked, naming both.
function G:direct_beside_lnav_off()
  for c = 1, self.ask and 0 or #self.out do
    local cond, id = self.out[c]:match("^(.-)LNAV (%S+) OFF$")
    for d = 1, id and #self.out or 0 do
      local wp = self.out[d]:match("^" .. cond:gsub("%p", "%%%0") .. "DIRECT " .. id:gsub("%p", "%%%0") .. " (%S+)$")
      if wp then
        return self:need(string.format("DIRECT %s %s switches LNAV on again. Should %s fly direct to %s along its "
          .. "route (LNAV on), or leave its route (LNAV off)?", id, wp, id, wp))
      end
    end
  end
end

-- "after DELON proceed to Minsk, set destination UMMS": the airport the request sets as an aircraft's
-- destination is the end of its route, no waypoint added to it as well (DEST puts it there; the
-- waypoint it was to follow stays read). Kept when a DIRECT flies to it (DIRECT needs it in the route).
function G:destination_not_waypoint()
  for c = #self.out, 1, -1 do
    local id, dest = self.out[c]:match("^DEST (%S+) (%S+)$")
    if id then
      local acid, place = id:gsub("%p", "%%%0"), dest:gsub("%p", "%%%0")
      local direct = false
      for _, line in ipairs(self.out) do direct = direct or line:match("^DIRECT " .. acid .. " " .. place .. "$") ~= nil end
      for d = #self.out, 1, -1 do
        local after = not direct and (self.out[d] .. " "):match("^ADDWPT " .. acid .. " " .. place .. ",?,?,?(%S*) $")
        if after then
          table.remove(self.out, d)
          for k, t in ipairs(self.t) do
            if after ~= "" and t.raw:upper() == after:upper() then
              self.explained = self.explained or {}
              self.explained[k] = true
            end
          end
        end
      end
    end
  end
end

-- The navaid said by its name after "cross" at token i ("cross Bowie at and maintain 13000", "cross the
-- Bowie VOR at": the UKW VORTAC, one word or two, with "the" before and its kind after, before "at") within
-- lexicon.navaid_range_nm of one aircraft flying, of the kind said if one is: a ref {kind = "waypoint", name,
-- b, e, words (how many words its name has)}, else nil. Reads only; explains nothing.
function G:crossed_navaid(i)
  local named = self.world.navaids_named
  if not named or not self:word(i, "cross crossing crosses") then return nil end
  local b = self:word(i + 1, "the") and i + 2 or i + 1
  for n = 1, 2 do
    local words, ok = {}, true
    for k = b, b + n - 1 do
      local t = self.t[k]
      ok = ok and t ~= nil and t.kind == "word" and t.alpha and not t.keyword and not t.number_word
      words[#words + 1] = t and t.text
    end
    local e = self:word(b + n, "@navaid_kinds") and b + n + 1 or b + n
    local kind = e > b + n and lexicon.navaid_types[self.t[b + n].text] or nil  -- (a navaid of the kind said)
    if ok and self:word(e, "at") then
      for _, a in ipairs(self.fleet) do
        local ids = a.lat and named(table.concat(words, " "), a.lat, a.lon, lexicon.navaid_range_nm, kind) or {}
        if #ids == 1 then return { kind = "waypoint", name = ids[1], b = i + 1, e = e, words = n } end
      end
    end
  end
  return nil
end

-- "cross CAMRN at one one thousand", "cross ARTIP at 220 knots": a crossing
-- restriction at a waypoint of the aircraft's route is BlueSky's AT
-- constraint ("AT id WPT ALT alt" / "SPD spd"); an instruction said with its
-- verb to start there is AT acid wp DO (G:do_at); true when emitted.
-- Any other value instruction tied to a waypoint ("reduce 210 at CANUK": met
-- there, or started there?) is asked, never issued at once.
-- (the question about an instruction tied to waypoint r, said with `word`: "at" unless given)
function tied_to_waypoint(self, r, word)
  return self:need(string.format("Should that happen %s %s? Please say \"cross %s at ...\" for a level or speed "
    .. "to meet there, \"at %s descend ...\" for an instruction to start there, or give it on its own (a waypoint "
    .. "off the route needs ADDWPT first).", word or "at", r.name, r.name, r.name))
end
-- The words of radiotelephony courtesy (lexicon.accounted.radiotelephony), as a set.
local RADIOTELEPHONY = {}
for _, w in ipairs(lexicon.accounted.radiotelephony) do RADIOTELEPHONY[w] = true end
-- True when nothing but fillers and a closing full stop, question or exclamation mark follows token k - 1.
local function ends_request(self, k)
  k = self:skip_fillers(k)
  while self.t[k] and self.t[k].kind == "punct" and self.t[k].text ~= "," do k = k + 1 end
  if k > #self.t then return true end
  -- (or a clause of its own follows, opened by "thereafter" or "after that": "cross LAM FL110, thereafter descend
  -- FL80")
  if self.t[k].kind == "punct" then k = self:skip_fillers(k + 1) end
  if self:word(k, "and") then k = self:skip_fillers(k + 1) end
  return self:word(k, "thereafter afterwards") or (self:word(k, "after") and self:word(k + 1, "that"))
end
function G:at_waypoint(s, spec)
  if not (spec and spec.value) and s.intent ~= "infer" then
    -- "after SMO direct LAX", "at SMO, proceed direct LAX", "after passing Santa Monica direct LAX": the request
    -- opening, after its callsign, with "at", "after" or "over" and a place of the aircraft's route, the direct-to
    -- said after it, to the next waypoint of the route, and nothing more, starts there (AT acid wp DO DIRECT ...,
    -- G:do_at; a place off the route is asked about)
    local ids = s.intent == "direct" and spec and spec.handler and self:acids(s) or {}
    for j = s.e, #self.t do
      if not (self.t[j].filler or self.t[j].kind == "punct") then ids = {} end
    end
    local to = self:refs_in(s.trig + 1, s.e, "waypoint")
    if #ids == 1 and not (#to == 1 and self:on_route(ids[1], to[1].name)) then ids = {} end
    local k = self:skip_fillers(s.b)
    for _, a in ipairs(self:refs_in(k, k + 1, "aircraft")) do k = self:skip_fillers(a.e) end
    if self.t[k] and self.t[k].kind == "punct" then k = self:skip_fillers(k + 1) end
    local opener, verb = k, self:word(s.trig - 1, "proceed go fly") and s.trig - 1 or s.trig
    if self.t[verb - 1] and self.t[verb - 1].kind == "punct" then verb = verb - 1 end
    if #ids == 1 and self:word(opener, "at after over overhead") and verb > opener + 1 then
      k = self:skip_fillers(opener + 1)
      if self:word(opener, "after") and self:word(k, "passing") then k = self:skip_fillers(k + 1) end
      local r = self:refs_in(k, verb, "waypoint")[1]
      local name = r and r.b == k and r.e == verb and r.name
      if not name and not r and self:state(ids[1]) and verb <= k + 3 then
        name = self:place_by_name(k, verb, self:state(ids[1]), true)
      end
      -- (with waypoints of the route between the two, which of them the shortcut leaves out is asked)
      local route, at, target = (self:state(ids[1]) or {}).route or {}, nil, nil
      for i, w in ipairs(route) do
        if name and w:upper() == name:upper() then at = i end
        if w:upper() == to[1].name:upper() then target = i end
      end
      if name and not self.ask and at and target == at + 1 then
        local n0 = #self.out
        self:explain(opener, verb)
        self[spec.handler](self, s, spec)
        if not self.ask then self:do_at(ids[1], name, n0) end
        return true
      end
      if name and not self.ask and at and target and target > at + 1 then
        local skipped = {}
        for i = at + 1, target - 1 do skipped[#skipped + 1] = route[i] end
        return self:need(string.format("Should %s fly direct %s once past %s, leaving out %s of its route (AT %s %s DO "
          .. "DIRECT %s %s), or delete %s from the route?", ids[1], to[1].name, name, table.concat(skipped, ", "),
          ids[1], name, ids[1], to[1].name, table.concat(skipped, ", ")))
      end
    end
    -- ("dct GILOM then FL190 at GILOM", "direct GILOM then at GILOM 250kt": a level or speed with no verb, after
    -- "then", tied to the waypoint the direct-to flies to, is flown once there: the DIRECT, then AT acid wp DO;
    -- `thn` is the "then", q the value; false when it is not so said)
    local function then_there(r, thn, q)
      local ids, to = self:acids(s), self:refs_in(s.trig + 1, s.e, "waypoint")[1]
      if not (self:word(thn, "@then_words") and #ids == 1 and to and to.b < thn and to.name:upper() == r.name:upper()
          and self:skip_fillers(math.max(q.e, r.e)) >= s.e and #self:quantities(to.e, thn) == 0
          and (q.kind == "alt" or q.kind == "speed" or q.kind == "mach")) then
        return false
      end
      self[spec.handler](self, { intent = s.intent, b = s.b, trig = s.trig, e = thn }, spec)
      if self.ask then return true end
      local n0, f = #self.out, handlers.format
      self:emit(q.kind == "alt" and string.format("ALT %s %s", ids[1], f.alt(q.value, q.fl))
        or string.format("SPD %s %s", ids[1], q.kind == "mach" and f.mach(q.value) or f.int(q.value)))
      self:take(q)
      self:explain(thn, s.e)
      self:do_at(ids[1], r.name, n0)
      return true
    end
    -- ("direct CNF1, FL340 at CNF1": a level or speed said straight before "at" and a waypoint, in a direct's
    -- clause)
    for _, r in ipairs(s.intent == "direct" and self:refs_in(s.b, s.e, "waypoint") or {}) do
      local qs = self:word(r.b - 1, "at") and self:quantities(s.b, r.b - 1) or {}
      local q = qs[#qs]
      if q and q.e == r.b - 1 and spec and spec.handler and then_there(r, q.b - 1, q) then return true end
      local aq = self:word(r.b - 1, "at") and spec and spec.handler and self:quantities(r.e, s.e)[1]
      if aq and aq.b == self:skip_fillers(r.e) and then_there(r, r.b - 2, aq) then return true end
      if q and q.e == r.b - 1 and (q.kind == "alt" or q.kind == "speed" or q.kind == "mach") and not self:in_reason(r.b) then
        return tied_to_waypoint(self, r)
      end
      -- ("direct ALFA, at ALFA FL240": a level or speed said straight after "at" and the waypoint)
      local after = (self:quantities(r.e, s.e)[1] or {})
      if r.b - 1 > s.trig and self:word(r.b - 1, "at") and after.b == self:skip_fillers(r.e)
          and (after.kind == "alt" or after.kind == "speed" or after.kind == "mach") and not self:in_reason(r.b) then
        return tied_to_waypoint(self, r)
      end
      -- ("direct HHOOD, then at HHOOD climb FL190": a clause opened by "at" and the waypoint after "then" or a
      -- comma ends there, its instruction the next one: an instruction tied to the waypoint)
      local opener = self.t[r.b - 2] and (self.t[r.b - 2].kind == "punct" or self:word(r.b - 2, "@then_words"))
      -- (the direct-to is made, and the next segment's instruction starts at the waypoint: self.at_next, AT
      -- acid wp DO, G:parse)
      if r.b - 1 > s.trig and self:word(r.b - 1, "at") and opener and self:skip_fillers(r.e) >= s.e and s.e <= #self.t
          and not self:in_reason(r.b) then
        if not (spec and spec.handler) then return tied_to_waypoint(self, r) end
        self[spec.handler](self, { intent = s.intent, b = s.b, trig = s.trig, e = r.b - 1 }, spec)
        self:explain(r.b - 2, r.e)
        self.at_next = r
        return true
      end
    end
    -- "direct MENLO, cross it at FL150", "direct SLI, cross at 10000": a crossing after the direct, of the one
    -- waypoint it names, is the AT constraint there, a level or a speed said straight after "at"
    local cr = s.intent == "direct" and self:find_word(s.trig, s.e, "cross") or s.e
    local k = cr < s.e and self:skip_fillers(cr + 1) or s.e
    if self:word(k, "it") then k = self:skip_fillers(k + 1) end
    local qs = self:word(k, "at") and self:quantities(k + 1, s.e) or {}
    local q = qs[1]
    local kind = #qs == 1 and q.b == self:skip_fillers(k + 1) and self:skip_fillers(q.e) >= s.e
      and ((q.kind == "alt" or (q.kind == "plain" and q.value >= 1000 and q.value <= 60000 and q.value % 100 == 0)) and "ALT"
        or ((q.kind == "speed" or q.kind == "mach") and "SPD"))
    local wps = kind and self:refs_in(s.b, cr, "waypoint") or {}
    local ids = #wps == 1 and self:acids(s) or {}
    if #ids == 1 then
      local f = handlers.format
      self[spec.handler](self, { intent = s.intent, b = s.b, trig = s.trig, e = cr }, spec)
      self:take(q)
      self:explain(cr, q.b)
      self:emit(string.format("AT %s %s %s %s", ids[1], wps[1].name, kind,
        kind == "ALT" and f.alt(q.value, q.fl) or (q.kind == "mach" and f.mach(q.value) or f.int(q.value))))
      return true
    end
    return
  end
  -- "direct to the Arlanda VOR, and then when it's there descend to 4000 feet": "there" is the place the
  -- aircraft was just sent direct to, a level or a speed there its AT constraint
  local there = self:find_word(s.b, s.trig, "there")
  if there < s.trig and self:word_in(math.max(s.b, there - 4), there, "when once") then
    local ids, place = self:acids(s), nil
    for _, line in ipairs(ids[1] and self.out or {}) do
      place = line:match("^DIRECT " .. ids[1]:gsub("%p", "%%%0") .. " (%S+)$") or place
    end
    local qs = self:quantities(s.trig, s.e)
    local q = #ids == 1 and #qs == 1 and qs[1]
    local kind = q and ((q.kind == "alt" and "ALT") or ((q.kind == "speed" or q.kind == "mach") and "SPD"))
    if place and kind then
      local f = handlers.format
      self:take(q)
      self:explain(self:find_word(math.max(s.b, there - 4), there, "when once"), there + 1)
      self:emit(string.format("AT %s %s %s %s", ids[1], place, kind,
        kind == "ALT" and f.alt(q.value, q.fl) or (q.kind == "mach" and f.mach(q.value) or f.int(q.value))))
      return true
    end
  end
  -- (a navaid's name after "cross", over a fix named like one of its words: "cross Cedar Creek at"; a fix
  -- said whole stays that fix: "cross METRO at")
  -- (a place named in a phrase of what squawk does not simulate, "hold at KUDES", is no constraint's; a
  -- navaid's kind read as an ident, "the Phoenix VOR", names no place of its own)
  local refs = {}
  for _, r in ipairs(self:refs_in(s.b, s.e, "waypoint")) do
    if not (self.noted[r.b] and self.u:used(r.b)) and not (r.e == r.b + 1 and self:word(r.b, "@navaid_kinds")) then
      refs[#refs + 1] = r
    end
  end
  for i = s.b, self:said("cross crossing crosses") and s.e - 1 or 0 do
    local r = self:crossed_navaid(i)
    local part = r and #self:refs_in(r.b, r.e, "waypoint") > 0
    for _, f in ipairs(part and self:refs_in(r.b, r.e, "waypoint") or {}) do
      part = part and (f.e - f.b < r.words or (f.e == f.b + 1 and self:word(f.b, "@navaid_kinds")))
    end
    if r and (#refs == 0 or part) then
      refs = { r }
      self:explain(r.b, r.e)
      break
    end
  end
  -- "at Wagram reduce speed 210", "at Oscar Kilo Lima speed 220", "after NERDU descend FL70": the clause
  -- opening, after its callsign, with "at" or "after" and a place (no value; a name of three words at most)
  -- before its instruction word; `opens` is the place's first token. A place said there by its name or spelled in the
  -- phonetic alphabet is the waypoint of the condition (a spelling that names no waypoint of the aircraft's
  -- route is asked about, never dropped). After the place is no constraint at it (BlueSky's AT meets the
  -- value at the waypoint, before it is passed): asked, naming the place.
  -- ("Kindly, Saudia 611, at QTR ...", "MSR985 kindly at SOLAM ...": "kindly", with its comma, before or after the
  -- callsign, as "please")
  local function courtesy(k)
    while self:word(k, "kindly") do
      k = self:skip_fillers(k + 1)
      if self.t[k] and self.t[k].kind == "punct" and self.t[k].text == "," then k = self:skip_fillers(k + 1) end
    end
    return k
  end
  -- ("Run 2 of the Alpine series. ITY577: after SOPER descend ...": the clause opens after the last sentence's end)
  local b0 = s.b
  for x = s.b, s.trig - 1 do
    if self.t[x].kind == "punct" and self.t[x].text:match("^[%.!%?;]$") then b0 = x + 1 end
  end
  local first = courtesy(self:skip_fillers(b0))
  -- ("For JJP501, when it reaches HANWA, please descend ...": "for" before the callsign names the addressee)
  if self:word(first, "for") and #self:refs_in(first + 1, first + 2, "aircraft") > 0 then first = first + 1 end
  for _, a in ipairs(self:refs_in(first, first + 1, "aircraft")) do first = courtesy(self:skip_fillers(a.e)) end
  -- ("RWD461 descend FL210, sorry, after EPVOK descend FL200": an instruction taken back by a self-correction
  -- whose replacement opens with a condition, G:self_corrected; the clause opens after it)
  if self.condition_resumes and self.condition_resumes[first] and self.condition_resumes[first] < s.trig then
    first = courtesy(self:skip_fillers(self.condition_resumes[first]))
  end
  -- ("Aegean 603, efcharistó, at DILOP descend ...": a word of courtesy after the callsign)
  while self:word(first, RADIOTELEPHONY) do first = self:skip_fillers(first + 1) end
  -- (the clause's opening words: "at", "over", "overhead", "after", "after/when/on/upon/once passing",
  -- "leaving", "overflying", "reaching", "past" or "over", "passing", "reaching", "leave", "leaving")
  local opens
  self.place_passed_e, self.place_passes = nil, nil
  local passed = "passing leaving overflying reaching past over"
  if self:word(first, "at over overhead after passing reaching leave leaving") then
    opens = self:skip_fillers(first + 1)
    -- ("CES5511 after AND, descend ...": a waypoint the matcher read from a word kept as a filler, "and")
    for _, r in ipairs(refs) do if r.b == first + 1 and r.b < opens then opens = r.b end end
    -- ("after pass ANDIN climb to 8100 meter": the verb's bare form, as "after passing")
    if self:word(first, "after") and self:word(opens, passed .. " pass") then
      opens = self:skip_fillers(opens + 1)
    elseif self:word(first, "after") and self:passes_said(self:skip_fillers(opens + 1)) then
      -- ("after it passes NIKAS descend FL300": as "after passing")
      opens = self:skip_fillers(self:skip_fillers(opens + 1) + 1)
    end
  elseif self:word(first, "when on upon once") and self:word(self:skip_fillers(first + 1), passed)
      or self:word(first, "when once") and self:word(self:skip_fillers(first + 1), "pass") then
    opens = self:skip_fillers(self:skip_fillers(first + 1) + 1)
  elseif self:word(first, "when once") and self:passes_said(self:skip_fillers(self:skip_fillers(first + 1) + 1)) then
    -- ("when it passes KONAK turn left heading 240", "after it passes NIKAS, FL300", "once you cross DIPOS,
    -- ...": the aircraft's passing the waypoint, as "when passing" says it)
    opens = self:skip_fillers(self:skip_fillers(self:skip_fillers(first + 1) + 1) + 1)
    self.place_passes = true
  elseif self:word(first, "when once") then
    -- ("when ROTAX reached then climb FL150", "once KIRDI is passed, descend FL100": the waypoint, then the verb of
    -- passing it; `passed_e`, the token after that verb)
    local r = self:refs_in(first + 1, s.trig, "waypoint")[1]
    local v = r and r.b == self:skip_fillers(first + 1) and self:skip_fillers(r.e)
    if v and self:word(v, "is has") then v = self:skip_fillers(v + 1) end
    if v and self:word(v, "been") then v = self:skip_fillers(v + 1) end
    if v and v < s.trig and self:word(v, "reached passed") then
      opens = r.b
      self.place_passed_e = v + 1
    end
  elseif self:word(first, "in") then
    -- ("Volaris 3410 in COSCO reduce to 220 knots": "in" for Spanish "en", before a waypoint of the route of the
    -- one aircraft addressed, as "at"; any other place after "in" opens nothing)
    local r, ids = self:refs_in(first + 1, first + 2, "waypoint")[1], self:acids(s)
    if r and r.b == first + 1 and r.exists and #ids == 1 and self:on_route(ids[1], r.name) then opens = first + 1 end
  end
  if opens and #refs == 0 and opens < s.trig and s.trig < s.e and #self:quantities(opens, s.trig) == 0 then
    local ids = self:acids(s)
    local now = #ids == 1 and self:state(ids[1])
    local letters, k = "", opens
    while k < s.trig and self.t[k].kind == "word" and lexicon.phonetic[self.t[k].text] do
      letters, k = letters .. lexicon.phonetic[self.t[k].text], k + 1
    end
    local name
    if #letters >= 2 and k == s.trig then
      for _, w in ipairs(now and now.route or {}) do name = name or (w:upper() == letters and letters) end
      if not name then
        return self:need(string.format("Which waypoint is %s? I heard '%s', which names no waypoint on the route.",
          letters, self:raw(opens, k)))
      end
      self:explain(opens, k)
    -- (after "leave" or "leaving" only a heading is flown from the place: below)
    elseif now and s.trig <= opens + 3 and not (self:word(first, "leave leaving") and not self:word(s.trig, "heading hdg")) then
      name = self:place_by_name(opens, s.trig, now, true)
    end
    if name then refs = { { b = opens, e = s.trig, name = name } } end
  end
  for _, r in ipairs(refs) do
    -- "cross SUGOL at FL200", "set the constraint at ARTIP to FL200", "put a constraint on AEA44 at ORBIS,
    -- FL250", "at NORKU cross FL200", "at ELDAR speed 250": a constraint at a waypoint
    -- ("cross LINSA FL120", "cross KERAB 5000 feet": "at" left out, a level or speed straight after the waypoint
    -- that ends the request; "cross MAXMO FL220, speed 280 knots", the speed now or there, is asked about)
    -- ("cross BUK speed 250", "cross RABAN FL150 speed 250": the number after "speed" is the speed there)
    local after = self:skip_fillers(r.e)
    local next_q = self:word(r.b - 1, "cross crossing crosses") and self:quantities(after, s.e)[1]
    local function speed_said(q)
      return q.kind == "plain" and self:word(q.b - 1, "speed spd") and q.value >= 100 and q.value <= 400
        and not q.number.decimal
    end
    local crossed_q = next_q
    if next_q and next_q.kind == "alt" and next_q.b == after then
      local q2 = self:quantities(next_q.e, s.e)[1]
      if q2 and (q2.kind == "speed" or q2.kind == "mach" or speed_said(q2))
          and self:skip_fillers(next_q.e) == (self:word(q2.b - 1, "speed spd") and q2.b - 1 or q2.b) then
        crossed_q = q2
      end
    end
    -- (a bound after it, "cross RABAN FL150 or above", is one more word of the constraint: confirmed below)
    local last = crossed_q and crossed_q.e
    if last and self:word(last, "or") and self:word(last + 1, "above below higher lower less greater more") then
      last = last + 2
    end
    -- ("once it crosses PAM, 250 knots": the aircraft's passing it, a condition opening the clause, no crossing
    -- restriction: read below as "once passing")
    local crossed = self:word(r.b - 1, "cross crossing crosses")
      and not (self:word(r.b - 2, "it he she you they") and self:word(r.b - 3, "when once after"))
      and (self:word(after, "at")
      or (next_q and (next_q.b == after or (self:word(after, "speed spd") and next_q.b == self:skip_fillers(after + 1)))
        and (next_q.kind == "alt" or next_q.kind == "speed" or next_q.kind == "mach" or speed_said(next_q))
        and ends_request(self, last)))
    if self.t[after] and self.t[after].kind == "punct" then after = self:skip_fillers(after + 1) end
    local constrained = self:word(r.b - 1, "at") and self:word_in(math.max(s.b, r.b - 5), r.b - 1, "constraint restriction")
      and (self:word(self:skip_fillers(r.e), "to of") or (self.t[after] and self.t[after].kind == "number")
        or self:word(after, "fl flight"))
    -- "SULUR speed constraint 230 kt": the constraint named after the waypoint
    constrained = constrained or self:word_in(r.e, r.e + 3, "constraint constraints restriction")
    -- "at ELDAR speed 250", "Delta 889, at PAPPI maintain 250": "at" opening the clause, after its callsign
    local opening = r.b == opens and self:word(first, "at over")
    -- ("descend to FL60 and, when it is at RIGNO, reduce to 210 knots", "once it's at RIGNO, speed 210": a
    -- condition of reaching the waypoint, opening its clause, is a constraint there)
    local k = r.b - 2
    if self:word(k, "is") then k = k - 1 end
    opening = opening or (self:word(r.b - 1, "at") and self:word(k, "it it's") and self:word(k - 1, "when once")
      and (k - 1 == first or self.t[k - 2] and (self.t[k - 2].kind == "punct" or self:word(k - 2, "and @then_words"))))
    -- "to be at AMPEG at FL120", "be at FL200 over ARTIP": the value the aircraft is to be at there, said
    -- after the waypoint or between "be at" and it (`be_at`: the first token of that value)
    local be_at
    -- ("be at PETKA flight level 80": the value straight after the waypoint, "at" left out; "be over AMIKI at
    -- 8000 feet": "over" for "at")
    if self:word(r.b - 1, "at over overhead") and self:word(r.b - 2, "be")
        and (self:word(after, "at") or (self:quantities(after, s.e)[1] or {}).b == after) then
      be_at = r.b
    elseif self:word(r.b - 1, "at over by") then
      local k = self:find_word(s.b, r.b - 1, "be")
      local qs = self:quantities(k + 2, r.b - 1)
      if k < r.b - 1 and self:word(k + 1, "at") and #qs > 0 and qs[#qs].e == r.b - 1 then be_at = k + 2 end
      -- ("an altitude constraint of flight level 80 at MAGAT": the constraint's one value, after "of", straight
      -- before "at" and the waypoint)
      local c = self:find_word(math.max(s.b, r.b - 8), r.b - 1, "constraint restriction")
      local of = c < r.b - 1 and self:word(c + 1, "of") and self:quantities(c + 2, r.b - 1)
      if not be_at and of and #of == 1 and of[1].b == c + 2 and of[1].e == r.b - 1 then be_at = c + 2 end
    end
    -- "descend FL310 level by HELEN", "descend to reach FL300 by FERDI", "be level FL350 at PITES", "be level
    -- one niner zero over PUNPU": the level of a climb or descent, to be reached by a waypoint, is its AT
    -- constraint there (`level_by`: that level, the only value said before "by", "at", "over" or "overhead"; only "level",
    -- "reach", "be", "to" and fillers beside it)
    local level_by
    local from = s.intent == "infer" and first or s.trig + 1
    local said_level = false  -- ("level" said as a word of its own, not in "flight level")
    for i = s.intent == "infer" and first or s.trig, r.b - 2 do
      said_level = said_level or self:word(i, "reach reaching lvl") or (self:word(i, "level") and not self:word(i - 1, "flight"))
    end
    if (s.intent == "alt" or s.intent == "infer") and self:word(r.b - 1, "by at over overhead") and said_level then
      local qs = self:quantities(s.b, r.b - 1)
      level_by = #qs == 1 and qs[1].kind == "alt" and qs[1] or nil
      for i = from, r.b - 2 do
        local inside = level_by and i >= level_by.b and i < level_by.e
        if not (inside or self.t[i].filler or (self.t[i].kind == "punct" and self.t[i].text == ",")
            or self:word(i, "level lvl reach reaching be to and")) then
          level_by = nil
        end
      end
    end
    -- "descend FL300, at VALKO FL250", "descend FL310 then at LIPNI FL270": a clause of its own after the
    -- instruction's value, "at", the waypoint and straight after it a value, with no verb: a constraint there
    local clause_at = self:word(r.b - 1, "at") and r.b - 1 > s.trig and #self:quantities(s.trig, r.b - 1) > 0
      and ((self.t[r.b - 2].kind == "punct" and self.t[r.b - 2].text == ",") or self:word(r.b - 2, "@then_words"))
      and (self:quantities(after, s.e)[1] or {}).b == after
    -- (a comma after the value opens another clause: "at ALFA FL240, 250 knots" is asked about, never tied there)
    for i = after, s.e - 1 do
      clause_at = clause_at and not (self.t[i].kind == "punct" and self.t[i].text == ",")
    end
    -- "show me the constraints AUA123 has at NERDU", "what restrictions does KLM12 have at ARTIP?": asked for
    local shown = self:word(r.b - 1, "at") and self:word_in(s.b, r.b, "constraint constraints restriction restrictions")
      and self:word_in(s.b, r.b, "show list display what which") and #self:quantities(s.b, s.e) == 0
    -- "at DILOP descend flight level 80", "after NERDU descend FL70", "after passing MOSET descend FL180",
    -- "when at GIVMI descend FL220", "once past GIVMI, descend FL220", "when it is at RIGNO, reduce to 210
    -- knots": an instruction said with its verb, after a clause opening with the waypoint, starts when the
    -- aircraft passes it: BlueSky's AT acid wp DO with the full command (G:do_at; a waypoint off the route
    -- is asked about, naming it; "over ZYG reduce speed 250" the same). A value said with no verb ("at ELDAR
    -- speed 250", "over KOPOR FL80") stays the constraint there; so does a crossing. After the waypoint, a
    -- value said with its noun ("after CUERS speed 250 knots") is the instruction there too: no constraint
    -- can be met once the waypoint is passed.
    local cond_b
    -- ("leave NAGMA heading 200": after "leave" or "leaving" only a heading said straight after the waypoint is
    -- flown from it; "leave FDO, fly heading 290" leaves the routing to it now)
    local opened = r.b == opens and not (self:word(first, "leave leaving") and not self:word(r.e, "heading hdg"))
    if opened then
      cond_b = first
    elseif self:word(r.b - 1, "at past") and self:word(r.b - 2, "when once") and r.b - 2 == first then
      cond_b = first
    elseif opening then
      cond_b = self:find_word(math.max(s.b, r.b - 4), r.b, "when once")
    end
    -- ("after passing GOURA descend... correction, descend now to FL150": taken back, the instruction is now)
    -- ("leave NAGMA heading 200": "leave" is the verb, the heading flown from the waypoint on)
    -- ("after CUERS speed 250 knots": a value with its noun after the waypoint is the instruction there)
    -- ("passing VURAL descending FL100", no "when" or "after": a pilot's report, no instruction)
    -- ("when passing KV speed 230", "once past GIVMI 250 knots": a clause that passes the waypoint before its
    -- value, as "after" does)
    -- ("passing IDUMA speed 220": a bare "passing" opening the request's clause, its "when" left out, the same)
    local passed_first = self:word(first, "after") or self.place_passes or (self:word(first, "when on upon once")
      and self:word(self:skip_fillers(first + 1), "passing past overflying leaving"))
      or (self:word(first, "passing") and r.b == self:skip_fillers(first + 1))
    -- ("at UPALA then FL120", "at ELDAR, then speed 250": "then" after the opening waypoint says what follows
    -- is done there, no constraint)
    local re = opened and self.place_passed_e or r.e
    local then_at = opened and self:word(self:skip_fillers(re), "@then_words")
      or (opened and self.t[re] and self.t[re].text == "," and self:word(self:skip_fillers(re + 1), "@then_words"))
    if opened and self.place_passed_e then passed_first = true end
    local verb = s.intent ~= "infer" and (not self:word(s.trig, "@instruction_nouns")
        or (opened and (self:word(first, "leave leaving") or passed_first or then_at)))
      and not (self:word(first, "passing leaving") and self.t[s.trig].text:match("ing$")
        and not self:word(s.trig, "@instruction_nouns"))
      and not self:word_in(s.b, s.e, "cross crossing crosses now immediately")
      and not (self:word_in(s.b, s.e, "@correction") and not G.value_corrected(self, s))
    -- ("over WHISK hdg 010", "after FERDI 250kt": a heading is no constraint a waypoint carries, and once past
    -- the waypoint no speed can be met there: said with no verb after the opening waypoint, the instruction there;
    -- a level with no verb stays the constraint, "after FERDI FL290" asked)
    local never_constraint = false
    if cond_b and opened and (s.intent == "hdg" or s.intent == "infer") and not self:has_ref(s.b, r.b, "waypoint") then
      local qs = self:quantities(r.e, s.e)
      never_constraint = #qs > 0 and #self:quantities(s.b, r.b) == 0
      for _, q in ipairs(qs) do
        never_constraint = never_constraint and (q.kind == "heading" or (s.intent == "hdg" and q.kind == "plain")
          or (passed_first and (q.kind == "speed" or q.kind == "mach")))
      end
    end
    if then_at and cond_b and s.intent == "infer" and not self:has_ref(s.b, r.b, "waypoint")
        and #self:quantities(r.e, s.e) > 0 and #self:quantities(s.b, r.b) == 0 then
      never_constraint = true
    end
    local handler = spec and spec.handler or (never_constraint and s.intent == "infer" and "infer")
    if cond_b and (verb or never_constraint) and (s.trig > r.e - 1 or s.intent == "infer")
        and not (crossed or constrained or be_at or shown or level_by or clause_at)
        and handler and #self:acids(s) == 1 then
      local n0 = #self.out
      self:explain(cond_b, opened and self.place_passed_e or r.e)
      self[handler](self, s, spec)
      self.conditioned_ask = self.ask ~= nil
      if not self.ask and self:do_at(self:acids(s)[1], r.name, n0) then
        self.waypoint_do = { id = self:acids(s)[1], wp = r.name, n = #self.out, e = s.e }
      end
      return true
    end
    if crossed or constrained or opening or be_at or shown or level_by or clause_at then
      local ids = self:acids(s)
      -- ("Scandinavian, cross ARTIP at FL100": no aircraft named, the one to cross is what is asked)
      if #ids == 0 then
        return self:need(string.format("Which aircraft should cross %s? Please give its callsign.", r.name))
      end
      local now = #ids == 1 and self:state(ids[1])
      local in_route = false
      for _, w in ipairs(now and now.route or {}) do in_route = in_route or w:upper() == r.name:upper() end
      if shown and in_route then
        self:emit("AT " .. ids[1] .. " " .. r.name)  -- (AT with no constraint lists those at the waypoint)
        return true
      end
      -- "cross SUGOL at FL200", "cross SUGOL at FL200 and 250 knots": a level and a speed at most, one
      -- AT constraint each (BlueSky's AT acid wpname ALT/SPD value)
      local f = handlers.format
      local alt, spd, other = nil, nil, false
      local said = self:quantities(r.e, s.e)
      if be_at and be_at < r.b then
        -- "be at FL200 over ARTIP": the value before the waypoint, and none after it
        other = #said > 0
        said = self:quantities(be_at, r.b - 1)
      elseif level_by then
        other, said = #said > 0, { level_by }
      end
      -- ("cross AKO at FL280 maintain Mach .78", "cross DIK at 11000 and keep 250 knots": a speed after a verb of
      -- lexicon.keep_verbs following the crossing's level is an instruction of its own, SPD now, beside the constraint)
      local kept
      for _, q in ipairs(crossed and said or {}) do
        if not kept and (q.kind == "speed" or q.kind == "mach") and said[1] ~= q
            and self:find_word(said[1].e, q.b, "@keep_verbs") < q.b then
          kept = self:find_word(said[1].e, q.b, "@keep_verbs")
        end
      end
      if kept then said = self:quantities(r.e, kept) end
      for _, q in ipairs(said) do
        -- ("cross BEBEX at 6000": after a crossing, a bare number in hundreds of feet, 1000 or more, is a level)
        -- (so is one after a climb or descent: "at MIRSI descend 4000", as the climb or descent alone reads it,
        -- and one to "be at": "be at 15000 at ANVIX")
        if not alt and (q.kind == "alt" or (q.kind == "plain" and q.number.thousand)
            or ((crossed or be_at or s.intent == "alt") and q.kind == "plain" and q.value >= 1000 and q.value <= 60000
              and q.value % 100 == 0 and not self:word(q.b - 1, "speed spd"))) then
          alt = q
        elseif not spd and (q.kind == "speed" or q.kind == "mach"
            -- ("at CWRLD reduce speed to 190": the number after "speed" or "speed to")
            or (q.kind == "plain" and s.intent == "spd" and (self:word(q.b - 1, "speed spd")
              or (self:word(q.b - 1, "to") and self:word(q.b - 2, "speed spd"))))
            -- ("cross BUK speed 250": in a crossing, a whole number of knots, 100 to 400, after "speed")
            or (crossed and speed_said(q))
            -- ("at MIRSI reduce 210": a bare number of knots straight after a speed verb)
            or (q.kind == "plain" and s.intent == "spd" and q.value >= 100 and q.value <= 400 and not q.number.decimal
              and (q.b == self:skip_fillers(s.trig + 1) or (self:word(q.b - 1, "to") and q.b - 1 == self:skip_fillers(s.trig + 1))))
            -- "at MRG01 FL100 220": a bare number straight after the level is the speed (FL100/220)
            or (q.kind == "plain" and alt and self:skip_fillers(alt.e) == q.b and q.value >= 100 and q.value <= 400)) then
          spd = q
        else other = true end
      end
      -- ("cross T12 at 3600 metres": a level in metres is the constraint at the nearest 100 ft, as a clearance in
      -- metres is)
      if alt and alt.kind == "alt" and not alt.fl and self:word(alt.e - 1, "@metres") then
        alt = setmetatable({ value = math.floor(alt.value / 100 + 0.5) * 100 }, { __index = alt })
      end
      -- "cross DIK at FL110, speed 250 knots", "cross DIK at FL110 speed 250": a speed said with no verb after the
      -- crossing's level, in a clause of its own, is the crossing's or one for now: asked, never flown at once
      local j = s.e
      while self.t[j] and (self.t[j].filler or self:word(j, "and") or (self.t[j].kind == "punct" and self.t[j].text == ",")) do
        j = j + 1
      end
      local next_spd = self:word(j, "speed") and self:quantities(j, #self.t + 1)[1]
      if crossed and in_route and alt and not spd and next_spd and (next_spd.kind == "speed"
          or next_spd.kind == "plain") and next_spd.b == self:skip_fillers(j + 1) then
        return self:need(string.format("Is '%s' to be met at %s with the level, or flown now? Please say "
          .. "\"cross %s at %s and %s knots\" or give the speed on its own.", self:raw(j, next_spd.e), r.name, r.name,
          f.alt(alt.value, alt.fl), f.int(next_spd.value)))
      end
      if in_route and not other and (alt or spd) then
        -- an instruction with its own value said before the crossing ("descend to FL120, cross DESDI at
        -- or below FL150"): its command first, from the words before the crossing. A level to be reached by
        -- the waypoint ("descend FL100 to be level by BIG") is the level cleared now and the AT constraint,
        -- as in BlueSky, where the constraint alone steers only an aircraft with VNAV on; with VNAV on, a
        -- descent is the constraint alone (VNAV plans its top of descent to meet it)
        local lead = be_at and be_at < r.b and be_at - 2 or r.b - 1
        local climb = level_by and now and now.alt_ft and level_by.value > now.alt_ft + 50
        local planned = level_by and not climb and now and now.vnav == true
        if spec and spec.handler and not planned and s.trig < lead and #self:quantities(s.b, lead) > 0 then
          self[spec.handler](self, { intent = s.intent, b = s.b, trig = s.trig, e = lead }, spec)
        elseif level_by and not planned then
          self:emit("ALT " .. ids[1] .. " " .. f.alt(level_by.value, level_by.fl))  -- ("be level FL240 by ALFA")
        end
        -- "cross SUGOL at or above FL150", "at least 250 knots": BlueSky's AT sets the exact value, so a
        -- bound runs only after a yes to that exact constraint
        -- (a bound taken back by a self-correction, "at or below FL090, sorry make it exactly FL090", is noted)
        local bounds = "above below higher lower least most greater less"
        local bk = self:find_word(be_at or r.e, s.e, bounds)
        while bk < s.e and self.noted[bk] do bk = self:find_word(bk + 1, s.e, bounds) end
        if bk < s.e and (alt or spd) then
          local exact = alt and f.alt(alt.value, alt.fl)
            or (spd.kind == "mach" and f.mach(spd.value) or f.int(spd.value) .. " knots")
          self:confirm_before(string.format("squawk can set only an exact constraint at %s: %s would cross it at "
            .. "exactly %s, not '%s'. Set that?", r.name, ids[1], exact, self:raw(be_at or r.e, s.e)))
        end
        if alt then
          self:emit("AT " .. ids[1] .. " " .. r.name .. " ALT " .. f.alt(alt.value, alt.fl))
          self:take(alt)
        end
        self.crossed = { id = ids[1], wp = r.name }
        if spd then
          self:emit("AT " .. ids[1] .. " " .. r.name .. " SPD "
            .. (spd.kind == "mach" and f.mach(spd.value) or f.int(spd.value)))
          self:take(spd)
        end
        if kept then self:speed({ intent = "spd", b = kept, trig = kept, e = s.e }, M.intents.spd) end
        return true
      end
    end
    -- ("descend and maintain 10000, at MAPEL reduce speed to 250", "climb FL200 then after MAPEL turn left heading
    -- 300", "climb FL170 and at FEVER increase speed to 320"): a clause opened by "at", "after" or "over" and the
    -- waypoint after the instruction's value, behind a comma, "and" or "then", closing the segment: the instruction
    -- is made, and the next one starts at the waypoint (self.at_next: AT acid wp DO, G:parse)
    local lead = r.b - 1
    if lead > s.trig and self:word(lead, "at after over overhead") and #self:quantities(s.trig, lead) > 0
        and self.t[lead - 1] and ((self.t[lead - 1].kind == "punct" and self.t[lead - 1].text == ",")
          or self:word(lead - 1, "@then_words and"))
        and self:skip_fillers(r.e) >= s.e and s.e <= #self.t and spec and spec.handler and not self:in_reason(r.b) then
      self[spec.handler](self, { intent = s.intent, b = s.b, trig = s.trig, e = lead - 1 }, spec)
      self:explain(lead - 1, r.e)
      self.at_next = r
      return true
    end
    if (self:word(r.b - 1, "at cross crossing over abeam overhead") or opened) and not self:in_reason(r.b) then
      return tied_to_waypoint(self, r, opened and (self:word(first, "after") and "after"
        or not self:word(first, "at over overhead") and "after passing") or "at")
    end
  end
end

-- ---- every value accounted for ----

-- The numbers a TrafScript line carries, with the readings a spoken value
-- may have had (FL350 is 35000 ft and 350; M.78 is 0.78); with `only` (a set of
-- registry names), a second list: those of the commands in it only ("DELAY 60 HDG KL204 60": 60 once for DELAY).
local function line_numbers(line, only)
  local nums, picked = {}, only and {}
  local cmd, named  -- (the command the numbers belong to; a name straight after one is its argument: "DT ASAS 2")
  for w in line:gmatch("[^%s,]+") do
    local u = w:upper()
    if only then  -- (the command is tracked only to filter by it)
      local name = w:match("^%u+$") and registry_args()[u] and not named
      if name then cmd = u end
      named = name
    end
    local v = tonumber(w) or (u:match("^FL%d+$") and tonumber(u:sub(3)) * 100)
        or (u:match("^M%.?%d") and tonumber((u:sub(2):gsub("^%.", "0."))))
    if v then
      local fl = u:match("^FL%d+$") and tonumber(u:sub(3))  -- (nil appends nothing)
      nums[#nums + 1] = v
      nums[#nums + 1] = fl
      if only and only[cmd] then
        picked[#picked + 1] = v
        picked[#picked + 1] = fl
      end
    end
  end
  return nums, picked
end

-- True when quantity q's value is one a command carries, as said or as
-- the grammar reads a spoken value: x100 (a level "three five zero"), x1000
-- ("maintain niner"), x10 ("speed two five"), 200 + ("to niner zero"),
-- headings modulo 360 (a heading said with its word only so, a time as said).
-- `again`: q is no value a command read, only said again beside it: it carries the value only as a level says it
-- alone ("FL300, three zero zero", "nine thousand feet, niner": x100 for a number of three figures, x1000 for one
-- spoken under 100), never rescaled otherwise ("FL300 3000", "heading 120 twelve", "speed 250, 25" differ).
local function value_carried(q, nums, again)
  local v, said = q.value, q.number
  local again_as = { v }
  if again and q.kind == "plain" and said and not said.hundred then
    if v >= 100 and v < 1000 then again_as[2] = v * 100 end
    if v < 100 and not said.typed then again_as[2] = v * 1000 end
  end
  -- (a level in metres is cleared to the nearest 100 ft: "6500 metres" is carried by 21300)
  local cleared = q.kind == "alt" and not q.fl and v % 100 ~= 0 and math.floor(v / 100 + 0.5) * 100 or nil
  if cleared then again_as[#again_as + 1] = cleared end
  for _, n in ipairs(nums) do
    -- (a heading said with its word, or a time, is read as said: "heading 100" is never the 300 of FL300)
    local said_as = (q.kind == "heading" or q.kind == "time") and { v } or again and again_as
      or { v, v * 100, v * 1000, v * 10, v + 200, cleared }
    for _, c in ipairs(said_as) do
      if math.abs(c - n) <= math.max(0.5, 1e-6 * math.abs(n)) then return true end
    end
    -- (a heading, 360 said for 0: against a heading's number only, never a level's 30000)
    if q.kind ~= "alt" and v >= 0 and v <= 360 and n >= 0 and n <= 360
        and math.abs((v - n + 180) % 360 - 180) <= 0.5 then
      return true
    end
  end
  return false
end

-- Kinds of quantity a handler reads by itself (times, factors, distances,
-- positions, changes): present whenever the segment gave a command.
local SELF_READ = { time = true, mult = true, dist = true, percent = true, angle = true, lat = true, lon = true,
  vs = true }

-- After a segment's commands: a spoken value in it that no command
-- carries (an instruction dropped, or a fragment such as "DLH4AX 2") is a
-- leftover; the first one becomes the question once the request is read
-- (nothing runs until it is understood).
-- Checked: the value instructions, whose handlers say which value they
-- read (G:take); the others read every value of their stretch.
local CHECKED = { alt = true, spd = true, hdg = true, maintain = true, direct = true, vs = true, infer = true }

function G:take(q)
  if q then self.taken[q.b] = true end
  return q
end

-- Quantity q was read as a change from the aircraft's present value ("left 20 degrees", "reduce 20 knots").
function G:as_change(q)
  self.changes = self.changes or {}
  self.changes[q.b] = true
end

-- True when every number TrafScript line `line` carries is a value said in the request (one counted from the
-- aircraft's state, "left 20 degrees" as HDG 100, is not; a change said, G:as_change, carries none).
function G:values_said(line)
  local qs = self:quantities(1, #self.t + 1)
  for w in line:gmatch("%S+") do
    local nums, said = line_numbers(w), false
    for _, q in ipairs(qs) do said = said or (not (self.changes or {})[q.b] and value_carried(q, nums)) end
    if #nums > 0 and not said then return false end
  end
  return true
end

-- A value with a unit of its own (a level, feet, knots, Mach, "heading N")
-- is an instruction wherever it stands; a bare number counts only after
-- the instruction word or a verb that introduces a value (lexicon.clause_verbs:
-- "fly 270 and maintain 9000"); one elsewhere before it is most often a misheard
-- callsign.
local function own_unit(q)
  return q.kind == "alt" or q.kind == "speed" or q.kind == "mach" or q.kind == "heading"
end

function G:unexplained(s, n_before)
  if self.leftover or not CHECKED[s.intent] then return end
  local nums = {}
  for c = n_before + 1, #self.out do
    for _, n in ipairs(line_numbers(self.out[c])) do nums[#nums + 1] = n end
  end
  local corrected = self:last_correction(s) or 0
  local relative = self:word_in(s.b, s.e, "@relative @same_as @below @above")
  -- with no instruction word the first value with a unit is the instruction ("ezy45 fl120 7", "klm12 1500 fpm 9000")
  local opened = s.intent ~= "infer" and s.trig or nil
  for _, q in ipairs(self:quantities(s.b, s.e)) do
    if not opened and (own_unit(q) or q.kind == "vs") then opened = q.b end
  end
  for _, q in ipairs(self:quantities(s.b, s.e)) do
    -- the aircraft said straight before the value, if any
    local callsign
    for _, r in ipairs(self.refs) do
      if r.kind == "aircraft" and r.e <= q.b and self:skip_fillers(r.e) == q.b then callsign = r end
    end
    -- (a bare value between the callsign and the instruction word, "BAW256 9 climb FL300", is named alone)
    local before_verb = callsign and not (opened and q.b > opened)
    -- (a distance closing its clause that no condition read, beside a level, speed, heading or rate, "maintain
    -- 250 knots for 10 miles", is a limit squawk's commands do not carry: asked, never dropped; "within 10 km"
    -- is where the instruction is flown, and a place after it, "20 miles from Gotham", is asked about by name)
    local k = self:skip_fillers(q.e)
    if q.kind == "dist" and s.intent ~= "direct" and not self.taken[q.b] and not self.u:used(q.b)
        and not (self.explained or {})[q.b] and not self.noted[q.b] and not self:word(q.b - 1, "within")
        and (not self.t[k] or self.t[k].kind == "punct" or self:word(k, "and then")) then
      self.leftover = self:raw(q.b, q.e)
      return
    end
    if not self.taken[q.b] and not SELF_READ[q.kind] and not relative and not q.by and q.turn == 0
        and q.b > corrected
        and ((opened and q.b > opened) or own_unit(q) or self:word(q.b - 1, "@clause_verbs") or before_verb)
        and not value_carried(q, nums, true) and not self:label_number(q, true)
        and not (self:aircraft_count(q) and self:in_reason(q.b)) then
      self.leftover = self:raw((callsign and not before_verb) and callsign.b or q.b, q.e)
      return
    end
  end
end

-- True when the words first .. last closing the request are all apologies (lexicon.self_correction.apology)
-- said after a remark (G:closing_remark): the speaker apologises for the remark, nothing is taken back
-- ("... ten times speed? We haven't got all afternoon, sorry!", "pause the sim, the fire alarm is being tested,
-- sorry"; "descend to 6000 feet, sorry", "pause the sim please, sorry" and "turn left heading 200, the other way,
-- sorry" still ask what was meant)
function G:apology_after_remark(first, last)
  for x = first, last do
    if self.t[x].kind ~= "punct" and not G.apology[self.words[x]] then return false end
  end
  local e = first - 1
  while e > 0 and self.t[e].kind == "punct" do e = e - 1 end
  local b = self:closing_remark(e)
  return b ~= nil and not self:word_in(b, e + 1, G.judged)
end

-- The first token of the clause ending at token e, back to the punctuation before it, when that clause states
-- something (an auxiliary, "is", "haven't", "we're": lexicon.accounted.auxiliaries) and is commentary
-- (G:commentary: no instruction word, value, aircraft or place), else nil.
G.remark_auxiliaries, G.judged = set_of(lexicon.accounted.auxiliaries), set_of(lexicon.self_correction.judged)
function G:closing_remark(e)
  local b = e
  while b > 1 and self.t[b - 1].kind ~= "punct" do b = b - 1 end
  if e <= b or not self:commentary(b, e + 1) then return nil end
  for x = b, e do
    local w = self.words[x]
    if w and (G.remark_auxiliaries[w] or w:match("n't$") or w:match("'[rv]e$")) then return b end
  end
  return nil
end

-- The first token of a clause of at most six words ending at token e, after punctuation, that the speaker opens
-- with a word of lexicon.self_correction_judges and no auxiliary ("I made a mistake", "my mistake", "my error"):
-- a remark when G:commentary reads it as one (no value, place or aircraft in it); else nil. The caller checks it
-- holds a word of lexicon.self_correction.judged.
function G:closing_judgement(e)
  local b = e
  while b > 1 and self.t[b - 1].kind ~= "punct" do b = b - 1 end
  if b <= 1 or e - b > 5 or not self:word(b, "@self_correction_judges") then return nil end
  -- ("..., I meant AFR34", "..., I meant to the left": what it points at is said in it, a correction; "I put it
  -- in by mistake", "in error": why the request is made)
  if self:word_in(b, e + 1, "meant mean by") or #self:refs_in(b, e + 1) > 0 then return nil end
  for x = b + 1, e do
    if self:word(x, "error") and self:word(x - 1, "in") then return nil end
  end
  -- ("140 - no, sorry, 180, my mistake": after a correction and its new value, the apology for the value taken back)
  local m = b - 1
  while m > 1 and not (self:word(m, "@correction") or SC_MARKERS[self.words[m]]) do m = m - 1 end
  if m > 1 and #self:quantities(m + 1, b) > 0 then return nil end
  for x = b, e do
    if self:intent_at(x) then return nil end
  end
  return self:commentary(b, e + 1) and b or nil
end

-- Whether a closing remark b .. e judging what was said, opened by "it", judges the saying: "it" then only a
-- linking verb, an article or a degree word before the judging word that closes it ("it was wrong", "it's all
-- wrong", "it was a mistake"); "it was put in by mistake", "it was created wrong" say why an aircraft goes.
-- A remark opened by another word of lexicon.self_correction_judges is true.
function G:it_judged(b, e)
  if not self:word(b, "it") then return true end
  if not G.judged[self.words[e]] then return false end
  for x = b + 1, e - 1 do
    if not self:word(x, "was is 's a an all completely totally just simply") then return false end
  end
  return true
end

-- The first token of a run closing the request at token last: a phrase of lexicon.self_correction.withheld, and
-- before it self-correction words, apologies, hesitations and punctuation holding a marker, an apology or a
-- hesitation ("no wait, let's see", "sorry, let me think", "hmm, hold on"), with an instruction's words before the
-- run; else nil ("let's" is read as "let").
G.sc_withheld_hesitations = set_of(lexicon.hesitations)
G.sc_withheld_hesitations.hmm, G.sc_withheld_hesitations.hm = true, true
function G:withheld_start(last)
  local by_last = G.sc_withheld_by_last
  if not by_last then
    -- by_last[w]: the phrases of SC.withheld whose last word is w, each as its words with "'s" dropped (built once)
    by_last = {}
    for _, phrase in ipairs(SC.withheld) do
      local words = {}
      for _, w in ipairs(PHRASE_WORDS[phrase]) do words[#words + 1] = (w:gsub("'s$", "")) end
      local w = words[#words]
      by_last[w] = by_last[w] or {}
      by_last[w][#by_last[w] + 1] = words
    end
    G.sc_withheld_by_last = by_last
  end
  local b
  for _, words in ipairs(by_last[self.words[last]] or {}) do
    local k = last - #words + 1
    if k > 1 and (not b or k < b) then
      for j = 1, #words do
        if self.words[k + j - 1] ~= words[j] then k = nil break end
      end
      b = k or b
    end
  end
  if not b then return nil end
  local first, marked = b, false
  while first > 1 do
    local t, w = self.t[first - 1], self.words[first - 1]
    if not (t.kind == "punct" or t.filler or SC_WORDS[w] or G.apology[w] or G.sc_withheld_hesitations[w]) then break end
    -- (a courtesy, "can you pause it please, un momento", marks nothing: the moment asked for is the pause's)
    marked = marked or (t.filler and w ~= "please" and w ~= "kindly") or SC_MARKERS[w] or G.apology[w]
      or G.sc_withheld_hesitations[w] or false
    first = first - 1
  end
  while first < b and self.t[first].kind == "punct" do first = first + 1 end
  return marked and first > 1 and first or nil
end

-- "KLM12 climb FL300, forget it", "..., ignore that", "... disregard that.", "..., just kidding", "..., ignore that,
-- turn left heading 100": a phrase of G.retracting_phrases after an instruction takes back what was said before it.
-- Closing the request (only marks, fillers, thanks or an apology after it), nothing said in its place, it is asked
-- with what it takes back; with an instruction after it, where a value said before it was sent too, which stands is
-- asked. Never are both sent.
G.retracting_phrases = { "forget it", "forget about it", "forget about that", "forget this", "ignore it", "ignore that",
  "ignore this", "ignore my last", "ignore the last one", "ignore the last instruction", "disregard that",
  "disregard it", "disregard this", "strike that", "just kidding", "only kidding", "that was a joke", "don't do it",
  "don't do that", "do not do it", "do not do that", "dont do it", "dont do that" }
G.retracting_after = set_of({ "please", "thanks", "thank", "you", "sorry", "ok", "okay" })
function G:retracted()
  -- ("... no forget it, only speed": what stands is named, G:self_corrected)
  if self.kept then return end
  if not self:said("forget ignore disregard strike kidding joke do") then return end
  local phrases = G.retracting_words
  if not phrases then
    phrases = {}
    for _, p in ipairs(G.retracting_phrases) do
      local w = {}
      for x in p:gmatch("%S+") do w[#w + 1] = x end
      phrases[#phrases + 1] = w
    end
    G.retracting_words = phrases
  end
  for k = 2, #self.t do
    for _, w in ipairs(phrases) do
      local ok = true
      for j = 1, #w do ok = ok and self.words[k + j - 1] == w[j] end
      if ok then
        local e = k + #w
        local x = e
        while self.t[x] and (self.t[x].kind == "punct" or self.t[x].filler or G.retracting_after[self.words[x]]) do
          x = x + 1
        end
        local said = (self:raw(k, e):gsub(" ([,.;:])", "%1"))
        if not self.t[x] then
          return self:need(string.format("You said '%s' with nothing after it, taking back %s. What should stand? "
            .. "Please say the instruction again.", said, table.concat(self.out, " ; ")))
        end
        local out = " " .. table.concat(self.out, " ; ") .. " "
        for _, q in ipairs(self.t[e] and self.t[e].kind == "punct" and self:quantities(1, k) or {}) do
          local d = q.number and q.number.digits
          if d and out:find("[%s%a]" .. d .. "[%s;]") then
            return self:need(string.format("I have %s, but you said '%s' after '%s'. Which stands? Please say the "
              .. "instruction again.", table.concat(self.out, " ; "), said, self:raw(q.b, q.e)))
          end
        end
      end
    end
  end
end

-- "KLM12 unable climb FL300", "KLM12 requests climb FL300", "KLM12 would like FL300", "KLM12 standby for FL300": a
-- value said in the clause (to the next mark) after "unable", after a pilot's request ("request", "requests",
-- "requesting" or "would like" straight after the aircraft, a pronoun or "pilot"; "request you ..." is the
-- controller's instruction) or after "standby for" / "stand by for" is refused, wished or still to come, no
-- clearance: where it was sent, it is asked. A clearance said after a mark ("unable FL350, climb FL310") stands.
-- True when a reference to an aircraft ends just before token k.
function G:aircraft_ends_at(k)
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" and r.e == k then return true end
  end
  return false
end
function G:refused_or_requested()
  if not self:said("unable request requests requesting like standby stand") then return end
  local out = " " .. table.concat(self.out, " ; ") .. " "
  for k = 1, #self.t do
    local from
    if self:word(k, "unable") then from = k + 1
    elseif self:word(k, "standby") and self:word(k + 1, "for") then from = k + 2
    elseif self:word(k, "stand") and self:word(k + 1, "by") and self:word(k + 2, "for") then from = k + 3
    elseif (self:word(k, "request requests requesting") and not self:word(k + 1, "you")
        or self:word(k, "would") and self:word(k + 1, "like") and not self:word(k + 2, "me"))
        and k > 1 and (self:word(k - 1, "he she it pilot crew") or self:aircraft_ends_at(k)) then
      from = self:word(k, "would") and k + 2 or k + 1
    end
    if from then
      local e = from
      while self.t[e] and self.t[e].kind ~= "punct" do e = e + 1 end
      -- (a value said again after the mark is that clearance's: "KLM12 requests FL300, climb FL300 approved")
      local again = {}
      for _, q in ipairs(self:quantities(e, #self.t + 1)) do
        if q.number and q.number.digits then again[q.number.digits] = true end
      end
      for _, q in ipairs(self:quantities(from, e)) do
        local d = q.number and q.number.digits
        if d and not again[d] and out:find("[%s%a]" .. d .. "[%s;]") then
          return self:need(string.format("I have %s, but '%s' is no clearance (refused, requested or to come). "
            .. "Should I give it? Please say it as an instruction.", table.concat(self.out, " ; "),
            (self:raw(k, e):gsub(" ([,.;:])", "%1"))))
        end
      end
    end
  end
end

-- "descend flight level one two zero, uh, correction": a correction with
-- nothing after it says the request is wrong without saying how; asked.
function G:dangling_correction()
  local last = #self.t
  while last > 0 and (self.t[last].kind == "punct" or self.t[last].filler) do last = last - 1 end
  -- (a self-correction closed by the speaker stopping to think or dropping it: G:withheld_start)
  local withheld = last > 0 and #self.out > 0 and self:withheld_start(last)
  if withheld then
    return self:need(string.format("You said '%s' with nothing after it, taking back %s. What is the corrected "
      .. "instruction?", (self:raw(withheld, last + 1):gsub(" ([,.;:])", "%1")), table.concat(self.out, " ; ")))
  end
  if last > 0 and self:word(last, "@correction") then
    self:need(string.format("You said '%s' with nothing after it. What is the corrected instruction?",
      self.t[last].raw:lower()))
    return
  end
  -- ("conflict detection off. No, leave it.": a phrase of lexicon.self_correction.left_as_is after a marker,
  -- closing the request, takes back what was said before with nothing in its place: asked)
  for k = math.max(2, last - 5), last do
    local m = k - 1
    while m > 1 and self.t[m].kind == "punct" do m = m - 1 end
    if SC_MARKERS[self.words[m]] and (self:left_as_is_end(k) or 0) > last then
      return self:need(string.format("You said '%s': should nothing be done? Please say what stands.",
        (self:raw(m, last + 1):gsub(" ([,.;:])", "%1"))))
    end
  end
  -- a remark closing the request that judges what was said, opened by the speaker or "that" ("climb FL100, that
  -- was wrong", "... I got it mixed up, sorry": lexicon.self_correction_judges, lexicon.self_correction.judged),
  -- takes it back with nothing in its place ("delete BAW456, it was put in by mistake" says why)
  local judged_e = last
  while judged_e > 0 and (self.t[judged_e].kind == "punct" or G.apology[self.words[judged_e]]) do
    judged_e = judged_e - 1
  end
  local remark = judged_e > 0 and (self:closing_remark(judged_e) or self:closing_judgement(judged_e))
  if remark and remark > 1 and self:word(remark, "@self_correction_judges")
      and self:word_in(remark, judged_e + 1, G.judged) and self:it_judged(remark, judged_e) then
    self:need(string.format("You said '%s'. What is the corrected instruction?", self:raw(remark, last + 1)))
    return
  end
  -- the same for a self-correction in words closing the request ("turn left 20, sorry", "climb FL300, no
  -- wait"): a run of lexicon.self_correction's words holding one of its closing markers, as said (a typed "err" or
  -- "sry", read as "sorry", is a hesitation there: "hdg 240 err")
  local first = last + 1
  while first > 1 and (self.t[first - 1].kind == "punct" or SC_WORDS[self.words[first - 1]]) do first = first - 1 end
  local said = {}
  if first <= last then  -- (the words as said are read only where such a run closes the request)
    -- (a formal apology as "sorry": "turn left heading 300, pardon me"; a word of another language as its English
    -- word, lexicon.said_whole: "turn left 20, nee")
    for w in G.formal_apologies(G.said_whole(G.unit_restated(self.text_said or ""))):lower():gmatch("[%a']+") do
      said[#said + 1] = w
    end
  end
  local marked = false
  for k = math.max(1, #said - (last - first)), #said do
    marked = marked or SC_CLOSING[said[k]] or (said[k + 1] ~= nil and SC_CLOSING[said[k] .. " " .. said[k + 1]])
      or false
  end
  while first <= last and self.t[first].kind == "punct" do first = first + 1 end
  -- (an apology closing a remark set aside, G:declared_remark: "... 10.9 east? I placed it wrongly at the start,
  -- sorry.", or said alone after a correction: "... one three zero. Sorry!")
  local before = first - 1
  while before > 1 and self.t[before].text == "," do before = before - 1 end
  local opens = before
  while opens > 1 and not (self.t[opens - 1].kind == "punct" and self.t[opens - 1].text ~= ",") do opens = opens - 1 end
  local aside = self:in_reason(first) and ((self.t[before].kind == "word" and self:declared(opens, before + 1))
    or self:word_in(1, first, "@correction") or self:word_in(1, first, SC_MARKERS))
  -- (an apology straight after a correction's new value, "descend FL80 negative FL90 sorry", "heading 200,
  -- correction, 220, sorry": it apologises for the value taken back, the new one stands)
  -- (read only for a closing run that is marked: nothing else asks it)
  local marker = before
  while marked and marker > 1 and not (self:word(marker, "@correction") or SC_MARKERS[self.words[marker]]) do
    marker = marker - 1
  end
  aside = aside or (marked and marker > 1 and #self:quantities(marker + 1, first) > 0)
  if marked and first > 1 and not self:apology_after_remark(first, last) and not aside then
    self:need(string.format("You said '%s' with nothing after it. What is the corrected instruction?",
      self:raw(first, last + 1)))
  end
end

-- "climb fl300 then fl", "climb fl320 spd": a value's name (lexicon.value_names) closing the request after
-- "then", "and", a comma or a value, with no value after it, is an instruction cut off; asked (a list of
-- value names is not).
function G:dangling_value_name()
  local last = #self.t
  while last > 0 and (self.t[last].kind == "punct" or self.t[last].filler) do last = last - 1 end
  if last < 2 or not self:word(last, "@value_names") then return end
  local first = self:word(last, "level") and self:word(last - 1, "flight") and last - 1 or last
  -- (a list of value names is a reference: "the same heading, level and speed"; a typed abbreviation straight
  -- after a value, "climb fl320 spd", was cut off too, where a word may be the value's unit: "0.79 Mach")
  local after_value = self:word(first, "spd hdg fl vs alt")
    and (self.t[first - 1].kind == "number" or self.t[first - 1].raw:match("%d$") ~= nil)
  -- ("KAL1203 where now, and altitude?": asked with "?" after a question of state, POS alone read, the value's name
  -- is what to show)
  if G.state_shown_asked(self) then return end
  -- (marks between the list's names: "say altitude... and speed", "altitude, and speed")
  local prev = first - 2
  while prev > 1 and self.t[prev].kind == "punct" do prev = prev - 1 end
  if (self:linked(first) and not self:word(prev, "@value_names")) or after_value then
    self:need(string.format("I have %s. '%s' ends the request with no value after it: which value do you mean?",
      table.concat(self.out, " ; "), self:raw(first, last + 1)))
  end
end

-- "aua513 dlh1kz climb fl180": two aircraft typed side by side, nothing between them and no word of
-- lexicon.all ("both") in the request, may be a callsign typed again in place of the first; asked
-- (a comma or "and" between lists them). So are two with only an interjection between them ("TAM39, uh, the AZU41
-- climb": G:interjected_between), a slip's pause as likely as a list.
G.slip_interjections = set_of(lexicon.hesitations)
for _, list in ipairs({ lexicon.setting_question_interjections, lexicon.accounted.chat }) do
  for _, w in ipairs(list) do G.slip_interjections[w] = true end
end
-- True when the tokens b .. e-1 are commas, fillers other than "and" and at least one interjection of
-- G.slip_interjections.
function G:interjected_between(b, e)
  local said = false
  for k = b, e - 1 do
    local t = self.t[k]
    if G.slip_interjections[self.words[k] or ""] then said = true
    elseif self:word(k, "and") or not (t.filler or (t.kind == "punct" and t.text == ",")) then return false end
  end
  return said
end
-- "the other" after a self-correction's marker ("Olympic 344 turn right heading 330, no sorry, the other Olympic",
-- "Cyprus 4ZP... ochi, the other Cyprus, turn left", "no, the other one") takes back the aircraft named and means
-- another one not named: asked for its callsign, unless a callsign with its number is said after it ("no, the other
-- one, the LATAM 3511"), which the correction reads as said.
function G:other_taken_back()
  local w = self.words
  for k = 2, #self.t do
    if w[k] == "other" and w[k - 1] == "the" then
      local marked = false
      for j = 1, k - 2 do marked = marked or SC_MARKERS[w[j]] or self:word(j, "@correction") end
      if not marked then return end
      for _, r in ipairs(self.refs) do
        if r.kind == "aircraft" and r.b > k and self:raw(r.b, r.e):find("%d") then return end
      end
      self:need(string.format("You said '%s': which aircraft do you mean? Please give its callsign.",
        self:raw(k - 1, math.min(k + 2, #self.t + 1)):gsub("[%s%p]+$", "")))
      return
    end
  end
end

function G:side_by_side_callsigns()
  local prev
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" and r.exists then
      if prev and (prev.e == r.b or self:interjected_between(prev.e, r.b)) and prev.name:upper() ~= r.name:upper()
          and not self:word_in(1, #self.t + 1, "@all") then
        self:need(string.format("Which aircraft do you mean: %s, %s or both?", prev.name:upper(), r.name:upper()))
        return
      end
      prev = r
    end
  end
end

-- A bare number closing a list of instructions for one aircraft, after a comma or "then" ("direct FINGR, FL170,
-- 250", "speed 210 then 7000"), is the one value that the instructions said leave it able to be: an altitude in
-- feet (whole hundreds, 1000 to 45000: no heading, speed or flight level is so large) when no level was given,
-- a speed (100 to 400 kt) when a level and a direct-to or heading were given and no speed. Any other such
-- number stays a leftover, asked about, and so does one said straight after a rate ("vs 1500, 8000", "rate of
-- climb 1500 then 2000": a level or another rate?). (Another leftover said first stands: nothing is read then.)
G.list_commands = { ALT = true, SPD = true, HDG = true, DIRECT = true, ADDWPT = true, VS = true }
function G:list_value()
  local LIST_COMMANDS = G.list_commands
  if self.leftover and not self.leftover:match("^%d+$") then return end
  local id
  local said, rates = {}, {}  -- (rates[v]: a vertical speed of v ft/min issued, either way)
  for _, line in ipairs(self.out) do
    local cmd, acid = line:match("^(%u+) (%S+)")
    if not (acid and LIST_COMMANDS[cmd]) or (id and acid ~= id) then return end
    id, said[cmd] = acid, true
    local rate = line:match("^VS %S+ (%-?%d+)$") or line:match("^ALT %S+ %S+ (%-?%d+)$")
    if rate then rates[math.abs(tonumber(rate))] = true end
  end
  if not id then return end
  for _, q in ipairs(self:quantities(1, #self.t + 1)) do
    local before, after = self.t[q.b - 1], self.t[q.e]
    if q.kind == "plain" and not self.taken[q.b] and q.number and not q.number.decimal
        and (not self.leftover or self.leftover == self:raw(q.b, q.e))
        and before and (before.text == "," or self:word(q.b - 1, "then"))
        and (not after or after.kind == "punct") and self:has_ref(1, q.b, "aircraft") then
      local p = self:quantities(1, q.b)
      p = p[#p]
      if p and (p.kind == "vs" or (self.taken[p.b] and rates[math.abs(p.value)])) then return end
      local line
      if not said.ALT and q.value >= 1000 and q.value <= 45000 and q.value % 100 == 0 then
        line = string.format("ALT %s %d", id, q.value)
      elseif said.ALT and (said.DIRECT or said.HDG) and not said.SPD and q.value >= 100 and q.value <= 400 then
        line = string.format("SPD %s %d", id, q.value)
      end
      if not line then return end
      self:take(q)
      self.out[#self.out + 1], self.leftover = line, nil
      return
    end
  end
end

-- A time, position, level or speed said that no command carries ("in 5
-- minutes, delete TEST03": a delay the grammar does not give; "define A1 at
-- 52.0 4.0 and A2 at 52.0 5.0": a second waypoint not made) is a leftover,
-- asked about by name. (Values said relative to something, or before a
-- correction, are the instructions' to explain.)
-- The position of "at" when quantity q is a bare number said after it ("at 120", "at time 120", "at about 120"),
-- else nil.
function G:at_number(q)
  if q.kind ~= "plain" then return nil end
  local a = q.b - 1
  while a > 0 and self.t[a].filler do a = a - 1 end
  if self:word(a, "time minute second about around approximately roughly") then a = a - 1 end
  return self:word(a, "at") and a or nil
end

local MUST_CARRY = { time = true, lat = true, lon = true, alt = true, speed = true, mach = true, mult = true,
  heading = true, vs = true }
-- (a time said is carried only by a command that takes a time, lexicon.time_commands: never by a heading, level or
-- speed of the same figure, "give it 60 seconds and then ... heading 060")
G.time_commands = set_of(lexicon.time_commands)
function G:uncarried()
  -- (a value relative to another's, or a change "by" an amount; "as" alone is no comparison: "and slow it
  -- to 250 knots as well"; a position is neither: "cross 30 West at or above FL360", "by 20 West")
  local relative = self:word_in(1, #self.t + 1, "@relative same match @below @above")
  local function position(q) return q.kind == "lat" or q.kind == "lon" end
  local nums, times = {}, {}
  for _, line in ipairs(self.out) do
    local all, timed = line_numbers(line, G.time_commands)
    for _, n in ipairs(all) do nums[#nums + 1] = n end
    for _, n in ipairs(timed) do times[#times + 1] = n end
  end
  local corrected = self:last_correction({ b = 1, e = #self.t + 1 }) or 0
  local first = 1
  -- (a word of direction or motion, "go higher to 36000" unread, opens the instructions as a verb does)
  while first <= #self.t and not self:intent_at(first) and not (self.t[first].kind == "word"
      and not self.u:used(first) and self:word(first, "@up @down go")) do
    first = first + 1
  end
  -- (a value typed with its own unit that a command took opens them too: "hop7 fl100 6000 hdg 220")
  for _, q in ipairs(self:quantities(1, #self.t + 1)) do
    if q.b < first and own_unit(q) and self.taken[q.b] then first = q.b end
  end
  -- (a number straight after an aircraft flying, "at" or "to" between or not, and closed by a comma or "and",
  -- "KLM12 330, turn left 090", "AEA6062 at 330, direct XING2", "the Ryanair to 110 and 230 knots", is a value
  -- said for it, however early)
  local function said_for_aircraft(q)
    if not (self.t[q.e] and ((self.t[q.e].kind == "punct" and self.t[q.e].text == ",") or self:word(q.e, "and"))) then
      return false
    end
    for _, r in ipairs(self:refs_in(1, q.b + 1, "aircraft")) do
      if r.exists and (r.e == q.b or (r.e == q.b - 1 and self:word(r.e, "at to"))) then return true end
    end
    return false
  end
  -- (a bare number after "at", "at 120 AC003 descend FL150", "KLM12 at 250 descend FL180", is a moment or a
  -- speed said with no unit, never callsign noise: asked with its "at"; the position of "at", or nil)
  local function at_word(q)
    local a = self:at_number(q)
    return a and not self:word(q.e, "o'clock oclock") and not self:in_reason(q.b) and a or nil
  end
  -- (a level after "at" opening a clause, "climb FL160, at FL160 vertical speed 500", that a level taken before it
  -- carries by its value is a condition no command carries: asked)
  local function said_again(q)
    if not (q.kind == "alt" and self:at_clause(q)) then return false end
    for _, p in ipairs(self:quantities(1, q.b)) do
      if p.kind == "alt" and self.taken[p.b] and p.value == q.value then return true end
    end
    return false
  end
  -- (a distance closing the request, "direct WP2 10 miles", "pause, 10 miles", "direct WP2 within 20 miles", is said
  -- for the instruction; one in a remark or reason, "the aircraft are still 100 miles apart", is none)
  local function closing(q)
    local k = q.e
    while self.t[k] and self.t[k].kind == "punct" and self.t[k].text ~= "," do k = k + 1 end
    return not self.t[k] and not self:in_reason(q.b)
  end
  for _, q in ipairs(self:quantities(1, #self.t + 1)) do
    -- (a plain number with a decimal point is a coordinate; one of two digits or more said after the first
    -- instruction word is a value said for an instruction, "descend FL130, reducing 250", never dropped in
    -- silence; single digits, and numbers before any instruction, "United 82 82 flight 8180 descend", are
    -- often recognition noise in a callsign)
    -- (a level straight after "above" or "below" beside an instruction, before its word or after its value, or
    -- alone in its clause, "above 10000 increase speed to 300", "reduce 250 knots below 10000", "climb 17000, above
    -- 12000", is a condition or a bound on it, no value relative to another: carried by a command, or asked; "the
    -- normal limit below ten thousand" remarks on one)
    local at = at_word(q)
    local bound = self:word(q.b - 1, "@below @above")
      and (q.kind == "alt" or (q.kind == "plain" and q.value >= 1000 and q.value % 100 == 0))
    local value_before = false
    for _, p in ipairs(bound and self:quantities(math.max(1, q.b - 6), q.b - 1) or {}) do
      value_before = value_before or p.e == q.b - 1
    end
    if bound and self:intent_at(self:skip_fillers(q.e)) == nil and not value_before then
      local lo, hi = self:clause_around(q.b)
      for k = lo, hi - 1 do
        bound = bound and (k == q.b - 1 or (k >= q.b and k < q.e) or self.t[k].filler)
      end
    end
    if (MUST_CARRY[q.kind] or (q.kind == "dist" and closing(q)) or (q.kind == "plain" and (q.number.decimal or at
          or (q.value >= 10 and (q.b > first or said_for_aircraft(q))))))
        and not self.taken[q.b]
        and not ((q.by or (relative and not bound)) and not position(q)) and q.b > corrected
        and not (value_carried(q, q.kind == "time" and times or nums, true) and not said_again(q))
        and not self:label_number(q, true) then
      self.leftover = self:raw(at or (self:at_clause(q) and q.b - 1) or q.b, q.e)
      return
    end
  end
  -- (a time said in words after a word of waiting that no instruction waits for, "wait a minute, turn ...", "in
  -- about a minute ...", is asked with those words, never dropped)
  for _, q in ipairs(self:durations(1, #self.t + 1)) do
    local w = q.b - 1
    while w > 0 and (self.t[w].filler or self:word(w, "@wait_hedges")) do w = w - 1 end
    local lead = q.spoken and (self:word(w, "in after") and w or self:wait_verb(w))
    if lead and not (self.explained or {})[q.b] and not self.noted[q.b] and not self:in_reason(q.b) then
      self.leftover = self:raw(lead, q.e)
      return
    end
  end
end

-- True when aircraft ref r is said with "same" in its clause (to the punctuation around it) as the one to do the
-- same ("DLH6CK should do the same", "and DLH6CK in the same way", "the same for DLH6CK and BAW5"), never the one
-- compared with ("the same level as DLH6CK": G:compared_with) nor beside a value's noun ("the same level", "same
-- speed": lexicon.same_compared): such an aircraft no command carries is asked about, never dropped as context.
function G:same_doer(r)
  if self:compared_with(r.b) then return false end
  local b, e = r.b - 1, r.e
  while b >= 1 and self.t[b].kind ~= "punct" do b = b - 1 end
  while e <= #self.t and self.t[e].kind ~= "punct" do e = e + 1 end
  for k = b + 1, e - 1 do
    if self:word(k, "same") and not self:word(k + 1, "@same_compared") then return true end
  end
  return false
end

-- True when aircraft ref r is added to an instruction by the words around it ("climb FL190 - TOM6RT as well",
-- "same for TOM6RT", "do the same for the Tomjet", "and also TOM6RT") or given a direction of its own (", we want TOM6RT lower").
function G:aircraft_added(r)
  return self:word(r.e, "too also @up @down @faster_slower") or (self:word(r.e, "as") and self:word(r.e + 1, "well"))
    or self:word(r.b - 1, "also likewise ditto") or self:same_opening(r.b) ~= nil
end

-- A name that reads like a callsign no aircraft has, or an aircraft that
-- no command carries ("ezy45 fl150 x7", "pause, then tell me where BAW123
-- is"), is a leftover, asked about by name.
-- "KLM12 climb FL300 and start it", "set dtmult 5 and start", "... then stop it": a verb that starts or stops the
-- clock or the instruction before it, closing a request no clock command (OP, HOLD, FF) came from, is asked about,
-- never dropped
function G:clock_verb_left()
  for _, line in ipairs(self.out) do
    if line:match("^OP") or line:match("^HOLD") or line:match("^FF") then return end  -- ("ff 2 mins then stop")
  end
  local n = #self.t
  while n > 0 and self.t[n].kind == "punct" do n = n - 1 end
  local e = self:word(n, "it") and n - 1 or n
  if e >= 2 and self:word(e, "start stop begin restart") and self:word(e - 1, "and @then_words") then
    self.leftover = self:raw(e, n + 1)
  end
end

function G:unknown_names()
  if #self.fleet == 0 then return end
  local out = table.concat(self.out, " "):upper()
  local function meant(r)  -- a slip the speaker confirmed ("KLM1243" -> yes, KLM1234)
    for _, id in ipairs(self:near_callsigns(r.name)) do
      if (self.world.confirmed or {})[id] then return true end
    end
    return false
  end
  -- an aircraft named as a reference for another's value ("the same heading as AC02") or as the
  -- reason for an instruction ("to avoid a conflict between AC01 and AC02") is explained
  local compared = self:word_in(1, #self.t + 1, "@same_as @below @above @aircraft_context")
  -- ("Add an intruder for VIR9: DLH9KW A321 at ...", "We need a head-on for ICE204: spawn ICE205 ..."):
  -- an aircraft after a word of commentary.lead_context in a lead-in before a colon, when an aircraft
  -- is named after the colon, is other traffic
  local function lead_context(r)
    if not self:word(r.b - 1, CM_LEAD_CONTEXT) then return false end
    local colon = r.e
    while self.t[colon] and self.t[colon].kind == "punct" and self.t[colon].text == "'" do colon = colon + 1 end
    while self.t[colon] and self.t[colon].kind ~= "punct" do colon = colon + 1 end
    for k = r.b - 1, 1, -1 do
      if self.t[k].kind == "punct" and self.t[k].text ~= "," then return false end
    end
    return self.t[colon] ~= nil and self.t[colon].text == ":" and self:has_ref(colon + 1, #self.t + 1, "aircraft")
  end
  -- ("conflict detection for AEA21", "resolution looking at AEA21"): an aircraft a setting every aircraft shares is
  -- said for, a setting's noun up to three words before its "for", "at" or "on", is no context
  local function setting_for(r)
    if not self:word(r.b - 1, "for at on") then return false end
    for k = math.max(1, r.b - 4), r.b - 2 do
      if self:word(k, "detection resolution resolutions alerts probe") then return true end
    end
    return false
  end
  for _, r in ipairs(self.refs) do
    -- (one added, G:aircraft_added, is never context; in a reason, "also" before a verb adds nothing: "because the
    -- A350 also goes through HAGIS"; a direction does: "- we want ICE44 lower")
    if r.kind == "aircraft" and (not r.exists or (self:aircraft_added(r) and not (self:in_reason(r.b) and self:word(r.e, "also")
          and self.t[r.e + 1] and self.t[r.e + 1].kind == "word" and not self:intent_at(r.e + 1)))
          or not ((compared and not setting_for(r) and not self:same_doer(r)) or self:in_reason(r.b) or lead_context(r) or self:as_context(r.b)
            or self:compared_with(r.b)))
        and not r.false_start
        and not (self.explained or {})[r.b]  -- (read as a value: "sim speed x2")
        and not self.noted[r.b]  -- (in a phrase of what squawk does not simulate: "contact Brussels one two seven")
        and not out:find("%f[%w]" .. r.name:upper():gsub("%p", "%%%0") .. "%f[%W]") and not meant(r) then
      self.leftover = self:raw(r.b, r.e)
      return
    end
  end
end

-- After a request that only shows something (POS, LISTRTE), what the speaker wants to see in it, as a
-- sentence of its own or a clause after a comma opening with a subject ("Where's the Norwegian? Is it
-- already at RIGNO?", "show me its route, I want to see if MILTA is before EDISA", "I'm not sure KOGAV is
-- in there"), is the reason for asking and is explained, the places it names too: it runs to the end of the
-- request and holds no instruction word, no value and no aircraft the commands do not name. Nothing is
-- flown by a query, so such a remark changes nothing.
local SHOWS = { POS = true, LISTRTE = true }
function G:info_remarks()
  if #self.out == 0 then return end
  local out = " " .. table.concat(self.out, " ") .. " "
  for _, line in ipairs(self.out) do
    if not SHOWS[line:match("^(%S+)")] then return end
  end
  local b
  for k = 2, #self.t do
    local t = self.t[k - 1]
    if t.kind == "punct" and (t.text == "?" or t.text == "." or t.text == "!"
        or (t.text == "," and self:word(k, CM_SUBJECTS))) then
      b = k
      break
    end
  end
  if not b or b > #self.t then return end
  if #self:quantities(b, #self.t + 1) > 0 then return end
  for k = b, #self.t do
    if self:intent_at(k) then return end
  end
  for _, r in ipairs(self:refs_in(b, #self.t + 1, "aircraft")) do
    if not out:find(" " .. r.name:upper() .. " ", 1, true) then return end
  end
  self:explain(b, #self.t + 1)
end

-- A waypoint, fix or airport named that no command carries ("klm12 dc sugol
-- fl230": an instruction not read; "route EZY45 via TEST1 to EHAM": a
-- destination dropped) is a leftover, asked about by name. Abbreviations
-- that are no names (lexicon.not_names: "VFR", "RPZ"), names inside a reply
-- about what squawk does not simulate or a reason, names passed over by a
-- direct-to ("skip TP1 and go direct TP2") and names in an instruction only
-- announced ("expect direct X", "advise when able direct X") are explained, and so are names a
-- handler explained (a route said to go on as it does: "direct TWEED then GIRVA").
-- True when waypoint ref r is cancelled ("direct LEMON now, cancel GRANT") by the word before it and lies on the
-- route of an aircraft sent direct (self.out) before that direct-to's waypoint: the direct-to leaves it out
-- (the word and the name explained).
-- ("JAL107 does not need to fly over SPENS, so ... go directly to HARIS": a place said not to be needed, before
-- the direct-to's on the route, is the one skipped, with "not", "need"/"have", "to" and a verb of flying over)
function G:cancelled_by_direct(r)
  local from = r.b - 1
  if not self:word(from, "cancel cancelled canceled omit") then
    local v = self:word(r.b - 1, "over via through") and r.b - 2 or r.b - 1
    from = v - 3
    if not (self:word(v, "fly pass overfly go") and self:word(v - 1, "to") and self:word(v - 2, "need needs have has")
        and self:word(from, "not don't doesn't dont doesnt")) then
      return false
    end
  end
  for _, line in ipairs(self.out) do
    local id, to = line:match("^DIRECT (%S+) (%S+)$")
    local at, target
    for i, w in ipairs(id and (self:state(id) or {}).route or {}) do
      if w:upper() == r.name:upper() then at = at or i end
      if w:upper() == to:upper() then target = i end
    end
    if at and target and at < target then
      self:explain(from, r.e)
      return true
    end
  end
  return false
end

function G:uncarried_names()
  local out = " " .. table.concat(self.out, " "):upper():gsub("[,;]", " ") .. " "
  local direct = out:find(" DIRECT ", 1, true) ~= nil
  for _, r in ipairs(self.refs) do
    if r.kind == "waypoint" and not self:word(r.b, "@not_names @navaid_kinds") and not self.noted[r.b]
        and not (self.explained and self.explained[r.b]) and not self:in_reason(r.b)
        and not (direct and (self:preceded_by(r.b, 3, "@passed_over") or self:word(r.e, "skip bypass omit")
          or self:cancelled_by_direct(r)))
        and not self:preceded_by(r.b, 4, "@not_a_clearance advise") then
      local name = r.name:upper()
      -- (an airport said by its three-letter code is carried by its ICAO name: SFO -> KSFO)
      if not out:find("[%s]%w?" .. name:gsub("%p", "%%%0") .. "[%s]") then
        self.leftover = self:raw(r.b, r.e)
        return
      end
    end
  end
end

-- ---- every word accounted for ----

-- Words an instruction may hold (lexicon.accounted, docs/translator_trust.md): every word of every
-- lexicon list and rule (KNOWN), the names squawk knows (telephony, airline names, type makers and
-- models), the registry's command names, and the closed-class, courtesy and radiotelephony classes.
local ACCOUNTED = lexicon.accounted
local CONDITION = set_of(ACCOUNTED.condition)
local MEANING = set_of(ACCOUNTED.negation)
-- the number words that scale a number said before them
G.scale_words = { hundred = true, thousand = true }
for w in pairs(CONDITION) do MEANING[w] = true end
know_all(lexicon, {})
-- (an airline's name of one word is a word squawk knows; the words of a name of several, "el al", "air
-- express", are accounted for only inside the name said whole or beside a callsign of that airline
-- (G:airline_word), and an ICAO prefix only as one. G.name_words[w]: the ICAO prefixes whose names of several
-- words hold w; {} for a name of one word that no list knows as English, "lufthansa": false for "reach")
G.name_words = {}
for _, list in ipairs({ names.airlines, names.common }) do
  for _, a in ipairs(list) do
    if not a[1]:find(" ", 1, true) then
      G.name_words[a[1]] = G.name_words[a[1]] or (not KNOWN[a[1]] and {})
      know(a[1])
    end
    for w in a[1]:gmatch("%S+") do
      if a[1]:find(" ", 1, true) then
        G.name_words[w] = G.name_words[w] or {}
        G.name_words[w][a[2]] = true
      end
    end
  end
end
-- True when the word at i is a word of an airline's name of several words (G.name_words) said whole ("Royal
-- Air Maroc"), or one of the name of the airline of a callsign read within three words after it ("one Korean
-- cargo KAL5933"): a name squawk reads, as one of a single word is.
function G:airline_word(i)
  local of = G.name_words[self.t[i].text]
  if not of or not next(of) then return false end
  for k = math.max(1, i - 3), i do
    local _, e = self:airline_at(k)
    if e and e > i and e - k > 1 then return true end
  end
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" and r.b > i and r.b <= i + 3 and of[r.name:upper():match("^(%u+)%d") or ""] then
      return true
    end
  end
  return false
end
-- True when the word at i is a particle of a place's name (lexicon.name_particles) straight before a place read,
-- as a reference or by a handler ("direct El Palomar": the navaid PAL, a name in capitals): the name's article.
function G:place_particle(i)
  if not self:word(i, "@name_particles") then return false end
  for _, r in ipairs(self.refs) do
    if r.b == i + 1 then return r.kind == "waypoint" end
  end
  local nx = self.t[i + 1]
  return nx ~= nil and nx.kind == "word" and (self.u:used(i + 1) or (self.explained or {})[i + 1]) and nx.raw:match("^%u%l") ~= nil and not nx.keyword
    and not nx.number_word and not self.triggers[i + 1]
end
know_all(TYPES.types, {})
-- A registry command's name or alias that no rule or list knows ("rmethv"), by its lower-case
-- word: the command's lower-case name. Said in English, it is accounted for only by its command.
-- (lexicon.english_command_names, known above, are English words first.)
local COMMAND_ONLY = {}
for _, c in ipairs(squawk.sim.commands()) do
  for _, w in ipairs({ c.name, table.unpack(c.aliases or {}) }) do
    if not KNOWN[w:lower()] then COMMAND_ONLY[w:lower()] = c.name:lower() end
  end
end
-- (the resolution method's name, "mvp", likewise: accounted for only by a command that carries it, RESO MVP,
-- or inside an instruction read whole: "pz 5 nm / mvp" never drops it)
COMMAND_ONLY.mvp = "mvp"
for w, name in pairs(COMMAND_ONLY) do know(w) know(name) end
-- the courtesy and value phrases by their first word, each as its words in the lexer's form ("it's" is "it")
local PHRASES = {}
for _, list in ipairs({ ACCOUNTED.courtesy_phrases, ACCOUNTED.value_phrases }) do
  for _, p in ipairs(list) do
    local words = {}
    for w in p:gmatch("%S+") do words[#words + 1] = (w:gsub("'s$", "")) end
    PHRASES[words[1]] = PHRASES[words[1]] or {}
    table.insert(PHRASES[words[1]], words)
  end
end
-- the amounts of a change said as one number word before its unit and "more"/"less" ("thirty knots less")
G.amount_words = { five = "5", ten = "10", fifteen = "15", twenty = "20", thirty = "30", forty = "40", fifty = "50",
  sixty = "60", seventy = "70", eighty = "80", ninety = "90" }
-- The tokens of the courtesy phrases that hold a number word ("one more thing", "that is two instructions"), as
-- {[k] = true}, found once per request: such a number is no value (G:quantities). A number word is matched by
-- what was said (its raw word), the other words by the lexer's text.
-- (G.numbered_phrases[w]: the phrases whose first word is w, a number word also by its figure, "one" as "1")
G.numbered_phrases, G.no_phrases = {}, {}
for _, p in ipairs(ACCOUNTED.courtesy_phrases) do
  local words, numbered = {}, false
  for w in p:gmatch("%S+") do
    words[#words + 1] = (w:gsub("'s$", ""))
    numbered = numbered or NUMBER_WORDS[w] ~= nil
  end
  if numbered then
    for _, key in ipairs({ words[1], words[1] == "one" and "1" or nil }) do
      G.numbered_phrases[key] = G.numbered_phrases[key] or {}
      table.insert(G.numbered_phrases[key], words)
    end
  end
end
function G:phrase_numbers()
  if self.phrase_nums then return self.phrase_nums end
  local set = {}
  for i = 1, #self.t do
    for _, p in ipairs(G.numbered_phrases[self.t[i].text] or G.no_phrases) do
      local ok = true
      for x = 1, #p do
        local t = self.t[i + x - 1]
        ok = ok and t ~= nil and (t.text == p[x] or (t.raw or ""):lower() == p[x])
        if not ok then break end
      end
      if ok then for x = i, i + #p - 1 do set[x] = true end end
    end
  end
  self.phrase_nums = set
  return set
end
-- the closed classes and courtesy words (a clause of only these frames a request: "if that's alright")
local FRAMING = {}
for _, k in ipairs({ "articles", "pronouns", "auxiliaries", "modals", "prepositions", "conjunctions", "discourse",
    "courtesy", "radiotelephony" }) do
  for _, w in ipairs(ACCOUNTED[k]) do FRAMING[w] = true end
end
-- True when tokens b to e - 1 are punctuation, fillers and framing words only.
function G:framing_only(b, e)
  for k = b, e - 1 do
    local t = self.t[k]
    if not (t.kind == "punct" or t.filler or (t.kind == "word" and FRAMING[t.text])) then return false end
  end
  return true
end
local MODALS = set_of(ACCOUNTED.modals)
local FACILITIES = set_of(ACCOUNTED.facilities)
local AIRPORT_NOUNS = set_of(lexicon.airport_nouns)
local PERSONS = set_of({ "i", "we", "you", "i've", "we've", "you've", "i'm", "we're", "you're" })
local SUBJECTS = set_of(ACCOUNTED.pronouns)
for _, w in ipairs(ACCOUNTED.articles) do SUBJECTS[w] = true end

-- True when "to" (or a modal) at k opens the purpose of the instruction before it ("descend FL240 to put it at the
-- same level as KLM1234", "hdg 120 to close on TRA5GK"): after a value, before a verb no rule or list
-- knows, typed in lower case (no value, name, code or instruction word), with no value in its clause.
local PURPOSE_MODALS = word_set("@purpose_modals")
function G:purpose(k)
  -- ("UAL9 heading 150 - should converge with KLM1877": what should follow, after the value or a dash)
  local w = self.words[k]
  if not w then return false end
  local pv = self.t[k - 1]
  if PURPOSE_MODALS[w] and pv
      and (#self:quantities(k - 1, k) > 0 or (pv.kind == "punct" and k > 2 and #self:quantities(k - 2, k - 1) > 0)) then
    return true
  end
  if w ~= "to" then return false end
  -- ("To create a same-level encounter: SAS1410 climb FL190": a purpose opening the request, up to its colon,
  -- naming no value and no aircraft)
  if self:skip_fillers(1) == k and self:word(k + 1, "create set build make test") then
    for e = k + 2, #self.t do
      local t = self.t[e]
      if t.kind == "punct" then return t.text == ":" and #self:quantities(k, e) == 0 and #self:refs_in(k, e) == 0 end
    end
    return false
  end
  local nx = self.t[k + 1]
  -- ("..., then to blah on something": "to" after "then" opens the next instruction's place or value, no purpose)
  if not nx or nx.kind ~= "word" or not nx.alpha or nx.number_word or not nx.raw:match("^%l+$")
      or #self:refs_in(k + 1, k + 2) > 0 or self:word(k - 1, "@then_words") then
    return false
  end
  -- a value said before it, none in its clause; a verb squawk knows only straight after the value, with
  -- other traffic named in its clause and no instruction of its own ("hdg 060 to cross CFG4RK's track")
  local e = k + 1
  while e <= #self.t and self.t[e].kind ~= "punct" do e = e + 1 end
  -- ("climb VLG2211 to 370 to make it a triple", "... to get them closer": a verb squawk knows with a pronoun
  -- straight after it, no instruction word in its clause, says what the value brings about)
  local effect = KNOWN[nx.text] and not SUBJECTS[nx.text] and not nx.filler and self:word(k + 2, "it them")
  for x = k + 1, effect and e - 1 or 0 do effect = effect and not self:intent_at(x) end
  if KNOWN[nx.text] and not effect and (SUBJECTS[nx.text] or nx.filler or #self:quantities(k - 1, k) == 0
      or not self:has_ref(k + 2, e, "aircraft") or self:intent_at(k + 1)) then
    return false
  end
  local before = self:quantities(1, k)
  return #before > 0 and before[#before].e <= k and #self:quantities(k, e) == 0
end

-- "descend to 6000 feet for Borg El Arab", "FL120 for Amman Marka", "6000 for HEBA": "for" straight after a value,
-- then an airport's name (one to four capitalised words, "airport" after them allowed) or its code to the clause's
-- end, the airport held by the route or the destination of the aircraft named before, or within
-- lexicon.navaid_range_nm of it: the airport the value is for, no instruction. Returns the position after the
-- name, else nil.
function G:for_airport(k)
  local q = self:quantities(1, k)
  if #q == 0 or self:skip_fillers(q[#q].e) ~= k or not self:word(k, "for") then return nil end
  local e = k + 1
  while e <= #self.t and e < k + 5 and self.t[e].kind == "word" and self.t[e].raw:match("^%u")
      and not self:word(e, "@airport_nouns") do
    e = e + 1
  end
  local stop = self:word(e, "@airport_nouns") and e + 1 or e
  local after = self:skip_fillers(stop)
  if e == k + 1 or (after <= #self.t and self.t[after].kind ~= "punct" and not self:word(after, "please")) then return nil end
  local id
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" and r.exists and r.e <= k then id = r.name end
  end
  local a = id and self:state(id)
  if not (a and a.lat) then return nil end
  local held = {}
  for _, x in ipairs(a.route or {}) do held[x:upper()] = true end
  if a.dest and a.dest ~= "" then held[a.dest:upper()] = true end
  local phrase, w = self:raw(k + 1, e), self.world
  local nm = lexicon.navaid_range_nm
  if held[phrase:upper()] and w.airport_class and w.airport_class(phrase:upper()) then return stop end
  local city = lexicon.city_airports[phrase:lower()]
  for _, list in ipairs({ w.airports_named and w.airports_named(phrase, a.lat, a.lon, nm) or {},
      w.airports_with_words and w.airports_with_words(phrase, a.lat, a.lon, nm) or {},
      w.airports_named and city and w.airports_named(city, a.lat, a.lon, nm) or {} }) do
    if #list > 0 then return stop end
  end
  return nil
end

-- The forms a word may be inflected from or to ("keeping" keep, "switched" switch, "pass" passing).
local function inflections(w)
  local out = { w .. "ing", w .. "s", w .. "ed" }
  for _, suffix in ipairs({ "ing", "ed", "es", "s", "ly" }) do
    local stem = w:match("^(%a%a+)" .. suffix .. "$")
    -- ("-es" follows s, x, z, ch, sh or o: "passes" pass, "goes" go; "canes" is no form of "can")
    if stem and suffix == "es" and not (stem:match("[sxzo]$") or stem:match("[cs]h$")) then
      out[#out + 1], out[#out + 2] = stem .. "e", stem .. "ing"
    elseif stem then
      out[#out + 1], out[#out + 2], out[#out + 3] = stem, stem .. "e", stem .. "ing"  -- ("leaves" leaving)
      if stem:match("(%a)%1$") then out[#out + 1] = stem:sub(1, -2) end  -- "running" run
      if stem:match("i$") then out[#out + 1] = stem:sub(1, -2) .. "y" end  -- "carried" carry
    end
  end
  return out
end

-- True when a word of the lexer's text (possessive, hyphenated and inflected forms too) is one squawk
-- knows; an inflection of a negation or condition is no known word ("cancelling").
local function known_word(w)
  if KNOWN[w] then return true end
  local base = w:gsub("'s$", ""):gsub("'$", "")
  if KNOWN[base] then return true end
  for _, form in ipairs(inflections(base)) do
    if KNOWN[form] and not MEANING[form] then return true end
  end
  for part in base:gmatch("[^%-/]+") do
    if not KNOWN[part] then return false end
  end
  return base:find("[%-/]") ~= nil
end
-- True when the word at i is one squawk knows (known_word): English of the lexicon's lists, no name.
function G:known_word(i) return self.t[i] ~= nil and self.t[i].kind == "word" and known_word(self.t[i].text) end
-- True when every aircraft the request refers to is said as a kind only ("acft", "all aircraft", "traffic"), no
-- callsign or airline: "delete acft leaving box ..." names none to delete now.
function G:kind_only_aircraft()
  for _, r in ipairs(self:refs_in(1, #self.t + 1, "aircraft")) do
    for k = r.b, r.e - 1 do
      if not self:word(k, "acft aircraft traffic all any the planes flights") then return false end
    end
  end
  return true
end
-- The point a request names before word i with its position ("the point EXP1, which is at 35 north 139.6 east",
-- "point GATE2 at 52.1 4.3"): "point"/"waypoint"/"fix" and a new name (no aircraft that flies), then "at" (", which
-- is" before it or not) and the position's first number; {name=, b=, e=, at=} (at: the first number's token) or nil.
function G:point_said_before(i)
  for k = i - 1, 1, -1 do
    if self:word(k, "point waypoint fix") then
      local r = self:refs_in(k + 1, k + 2, "waypoint")[1] or self:refs_in(k + 1, k + 2, "aircraft")[1]
      if r and r.b == k + 1 and not r.exists then
        local j = r.e
        if self.t[j] and self.t[j].text == "," then j = j + 1 end
        if self:word(j, "which that") and self:word(j + 1, "is") then j = j + 2 end
        if self:word(j, "at") then
          local q = self:quantities(j + 1, j + 2)[1]
          if q and q.b == j + 1 and (q.kind == "lat" or q.kind == "plain") then
            return { name = r.name:upper(), b = r.b, e = r.e, at = j + 1 }
          end
        end
      end
    end
  end
  return nil
end
-- True when the word at i names a new shape typed straight after its noun ("box tma 51.5 3.5 53 6", "circle ctr
-- around 52.3 4.76"): letters (digits after), ten at most, no keyword or word squawk knows, a position's number or
-- "at"/"around"/"from"/"centred" straight after it.
function G:shape_name_at(i)
  local t, n = self.t[i], self.t[i + 1]
  if not (t and n and t.kind == "word" and t.raw:match("^%a[%a%d]*$") and #t.raw <= 10 and #t.raw >= 2) then
    return false
  end
  if t.keyword or (self:known_word(i) and not self:word(i, "tma ctr cta atz fir uir")) -- (airspace abbreviations)
      or #self:refs_in(i, i + 1, "aircraft") > 0 then
    return false
  end
  local q = self:quantities(i + 1, i + 2)[1]
  return (q ~= nil and q.b == i + 1) or self:word(i + 1, "at around from centred centered centre center")
end

-- True when the negation or condition at i is carried by the parse (`kinds`: G:issued): a condition
-- when a conditional command was issued, a switch word when something was switched off, a place passed
-- over by a direct-to ("not to NEGRA but direct AMIKI"), or one of the readings below. (A word a
-- handler read, "after" a waypoint in ADDWPT, is explained before: G:explain.)
function G:meaning_carried(i, kinds)
  local text, nx = self.t[i].text, self:skip_fillers(i + 1)
  -- "before we add any traffic", "until I say stop", "before creating anything": the speaker's own next
  -- step, which a command run now precedes; "when you get a sec": the listener's convenience (lexicon.convenience;
  -- never "when you reach it", "when you're level": the level reached, a condition; never "when you are with the
  -- tower", "once you see the field": a unit or an event squawk does not model, asked)
  local who = self.t[nx] and self.t[nx].kind == "word" and self.t[nx].text
  if who and (((text == "before" or text == "until") and (PERSONS[who] or who:match("%a%aing$")))
      or ((text == "when" or text == "whenever" or text == "once") and who:match("^you")
        and self:word_in(nx + 1, math.min(nx + 5, #self.t + 1), "@convenience")
        and #self:quantities(nx + 1, math.min(nx + 5, #self.t + 1)) == 0)) then
    return true
  end
  -- "and after reduce the speed": "after" as "afterwards", before the next instruction
  if text == "after" and self.triggers[nx] then return true end
  -- "descend until 7000 feet", "vs -2000 till fl150": "until" as "to", before the value the instruction took
  if (text == "until" or text == "till") and self.taken[nx] then return true end
  -- "to SFO instead of Oakland", "to LFPG instead": the value said replaces another; "no, descend KLM12
  -- instead, FL250", "descend KLM12 instead FL250", "turn KLM12 instead heading 200": the instruction said
  -- replaces another, "instead" before its pause, the value it took or that value's word
  if text == "instead" and (self:word(nx, "of") or not self.t[nx] or self.t[nx].kind == "punct"
      or (self.t[i + 1] and self.t[i + 1].kind == "punct") or self.taken[nx] or self.taken[nx + 1]) then
    return true
  end
  -- "if" opening a polite request ("I'd appreciate it if the Ryanair could turn ...") or a clause of
  -- framing words only ("if that's alright")
  if text == "if" and self:wish_frame(i) then return true end
  if text == "if" then
    local framing, modal = true, false
    local k = i + 1
    while k <= #self.t and not (self.t[k].kind == "punct" and self.t[k].text ~= "'") do
      local t = self.t[k]
      if t.kind == "word" and MODALS[t.text] then modal = true end
      if not (t.kind == "word" and (FRAMING[t.text] or t.filler)) then framing = false end
      k = k + 1
    end
    if modal or (framing and k > i + 1) then return true end
  end
  if CONDITION[text] and kinds.conditional then return true end
  -- "maintain FL130, do not descend": a climb or descent refused after a level maintained, the clause
  -- ending there, says that level again
  if (text == "not" or text == "don't" or text == "dont" or text == "never") and kinds.alt
      and self:word(nx, "climb descend") and self:word_in(1, i, "maintain")
      and (not self.t[nx + 1] or (self.t[nx + 1].kind == "punct" and self.t[nx + 1].text ~= "'")) then
    self:explain(nx, nx + 1)
    return true
  end
  -- (never "don't have to", "doesn't need to": what is not needed switches nothing off)
  if self:word(i, "@off") and kinds.off and not self:word(nx, "have has need needs") then return true end
  -- "cancel that heading, put it back on the route", "undo the vectors, resume own navigation": the heading
  -- taken back by the route resumed
  if self:word(i, "cancel cancels cancelled canceled undo") and kinds.route
      and self:word_in(i + 1, math.min(#self.t + 1, i + 4), "heading headings hdg vector vectors vectoring") then
    return true
  end
  -- "cancel your route": the route deleted
  -- ("flight plan cancel, delete the route": the plan named straight before it)
  if self:word(i, "cancel cancels cancelled canceled") and kinds.delrte
      and (self:word_in(i + 1, math.min(#self.t + 1, i + 3), "route rte") or self:word(i - 1, "plan rte route")) then
    return true
  end
  -- (an instruction word between them negates the instruction: "do not go direct HZA" is no place passed)
  -- ("TGU skip, direct PSN": the verb after the waypoint it passes, as Korean orders it)
  if kinds.direct and self:word(i, "skip bypass omit") then
    for _, r in ipairs(self:refs_in(math.max(1, i - 3), i, "waypoint")) do
      if r.e == i then return true end
    end
  end
  if self:word(i, "@passed_over") and kinds.direct then
    for k = i + 1, math.min(#self.t, i + 3) do
      if self:intent_at(k) then break end
      if self:has_ref(k, k + 1, "waypoint") then return true end
    end
  end
  return false
end

-- The commands issued, as a set of their lower-case words (a name said as it is issued: "direct
-- spijkerboor"), and which kinds were issued: conditional (AT, ATALT, ...), a switch off, a direct-to, the
-- route resumed (LNAV ON), the route deleted (DELRTE). Read once per content of self.out (the checks after
-- the parse each ask; the two tables are read, never changed).
function G:issued()
  local key = table.concat(self.out, "\n")
  local memo = self.issued_memo
  if memo and memo.key == key then return memo.words, memo.kinds end
  local words, kinds = {}, {}
  for _, line in ipairs(self.out) do
    for w in line:lower():gmatch("[^%s,;]+") do words[w] = true end
    for part in (line .. ";"):gmatch("([^;]+);") do
      local name = (part:match("^%s*(%S+)") or ""):upper()
      if CONDITIONAL[name] then kinds.conditional = true end
      if name == "DIRECT" then kinds.direct = true end
      if name == "ALT" then kinds.alt = true end
      if name == "DELRTE" then kinds.delrte = true end
      if name == "LNAV" and part:upper():find("%f[%w]ON%f[%W]") then kinds.route = true end
      if name == "DTMULT" or name == "FF" then kinds.clock = true end
      if part:upper():find("%f[%w]OFF%f[%W]") then kinds.off = true end
    end
  end
  self.issued_memo = { key = key, words = words, kinds = kinds }
  return words, kinds
end

-- The name of the caller's own station, said in the addressing position, is marked used and explained
-- before the parse (no word of it is an instruction: "Scottish Information"): a clause of its own, set
-- off by commas, straight after a callsign ("Shamrock 105, Shanwick, climb ...") or opening the request
-- before one ("Santa Maria, Air Portugal 237, ..."); one to three words, a unit word after them
-- ("Scottish Control", "Gander Oceanic": lexicon.accounted.facilities) or not, that name an air traffic
-- unit (lexicon.atc_units, in any case) or, capitalised, the navdata's airport, city or navaid.
local ATC_UNITS = set_of(lexicon.atc_units)
function G:stations()
  local b = 1
  while b <= #self.t do
    local e = b
    while e <= #self.t and self.t[e].kind ~= "punct" do e = e + 1 end
    local stop = e > b and self.t[e] and self.t[e].text
    local from
    if (stop == "," or stop == ":" or stop == "-") and self:station_sim(b, e) then
      from = b
    elseif stop == "," or stop == ":" then
      -- the station straight after the callsign, no comma between ("Ethiopian 306 Nairobi, climb ...")
      from = b
      for _, r in ipairs(self.refs) do
        if r.kind == "aircraft" and r.b >= b and r.e > r.b and r.e < e and not r.by_airline then from = r.e end
      end
      if not self:station_clause(from, e, from > b) then from = nil end
    end
    if from then
      self:mark_used(from, e)
      for k = from, e - 1 do self.noted[k] = true end
      for k = #self.refs, 1, -1 do
        local r = self.refs[k]
        if r.by_airline and r.b >= from and r.e <= e then table.remove(self.refs, k) end
      end
      for k = #(self.airline_unresolved or {}), 1, -1 do
        local r = self.airline_unresolved[k]
        if r.b >= from and r.e <= e then table.remove(self.airline_unresolved, k) end
      end
    end
    b = e + 1
  end
end

-- The name of an exercise, scenario or simulation, capitalised between "the" and the noun ("run the Budapest
-- exercise at four times real time"), is marked used and explained before the parse: it names the run, no
-- place or aircraft.
local EXERCISE_NOUNS = { exercise = true, scenario = true, simulation = true, sim = true, session = true }
function G:exercise_names()
  for k = 2, #self.t - 1 do
    local t = self.t[k]
    if self.words[k - 1] == "the" and EXERCISE_NOUNS[self.t[k + 1].text] and t.kind == "word" and t.alpha
        and t.raw:match("^%u%l+$") and not t.keyword and #self:refs_in(k, k + 1) == 0 then
      self:mark_used(k, k + 1)
      self.noted[k] = true
    end
  end
end

-- "direct SAMUD, spelling Sierra Alpha Mike Uniform Delta", "direct DPN, Delta Papa November": a waypoint's name
-- spelled again in the phonetic alphabet straight after it (a comma and words of lexicon.spelling_leads between,
-- or none) is the name said twice, set aside. Spelled letters that are not its name, after a word of spelling or
-- as many as its letters and closing the clause, are asked about, naming both: which place is meant is unknown.
G.spelling_leads = set_of(lexicon.spelling_leads)
function G:fixes_spelled()
  for _, r in ipairs(self:refs_in(1, #self.t + 1, "waypoint")) do
    local k, led = r.e, false
    while self.t[k] and (self.t[k].text == "," or self.t[k].filler or G.spelling_leads[self.words[k]]) do
      led = led or G.spelling_leads[self.words[k]] ~= nil
      k = k + 1
    end
    local letters, e = "", k
    while self.t[e] and self.t[e].kind == "word" and lexicon.phonetic[self.words[e]] do
      letters, e = letters .. lexicon.phonetic[self.words[e]], e + 1
    end
    local name = r.name:upper()
    if letters == name and #letters >= 2 then
      self:set_aside(r.e, e - 1)
    elseif #letters >= 2 and (led or (#letters == #name and (not self.t[e] or self.t[e].kind == "punct"))) then
      self:need(string.format("I heard %s, spelled '%s' (%s). Which waypoint do you mean?", name, self:raw(k, e), letters))
    end
  end
end

-- A place's capitalised name of one or two words said after "at", "over" or "near" and set apart by a comma
-- before its latitude ("the wind at Sofia, 42.70 N 23.40 E") is marked used and explained before the parse: the
-- position said after it is the place.
function G:places_by_position()
  local texts = self.words
  for k = 2, #self.t - 2 do
    local w = texts[k - 1]
    if w == "at" or w == "over" or w == "near" then
      local e = k
      while e < k + 2 and self.t[e] and self.t[e].kind == "word" and self.t[e].alpha and self.t[e].raw:match("^%u%l+$")
          and not self.t[e].keyword do
        e = e + 1
      end
      local q = e > k and self.t[e] and self.t[e].text == "," and self:quantities(e + 1, e + 2)[1]
      if q and q.b == e + 1 and q.kind == "lat" and #self:refs_in(k, e, "aircraft") == 0 then
        self:mark_used(k, e + 1)
        for x = k, e do self.noted[x] = true end
      end
    end
  end
  self:place_at_its_position()
end

-- A place's capitalised name of one or two words (an airport noun may follow it) said straight before a latitude
-- and longitude, after a word that places something there (lexicon.named_position_leads: "over Schiphol (52.31 N,
-- 4.76 E)", "to Arlanda, 59.65 north 17.92 east", "around Bremen airport, 53.047 N 8.787 E", "wind at Chengdu 30.6
-- 104.0"; a comma or an opening bracket between, or nothing), names the position said: it is explained when the
-- navdata has a place of that name (G:any_place_named) within lexicon.named_position_nm of it. A name of no place
-- there ("over Schiphol, 48.1 N 11.6 E") stays unexplained and is asked about.
function G:place_at_its_position()
  local near_nm = lexicon.named_position_nm
  if not self:said("@named_position_leads") then return end  -- (G:said's guard before the scan)
  for k = 2, #self.t - 2 do
    if self:word(k - 1, "@named_position_leads") then
      local e = k
      while e < k + 2 and self.t[e] and self.t[e].kind == "word" and self.t[e].alpha and self.t[e].raw:match("^%u%l+$")
          and not self.t[e].keyword and not self.u:used(e) do
        e = e + 1
      end
      local name = e > k and self:plain_name(k, e, true)
      local after = e + (self:word(e, "@airport_nouns") and 1 or 0)
      while self.t[after] and (self.t[after].text == "," or self.t[after].text == "(") and after <= e + 2 do after = after + 1 end
      local qs = name and self:quantities(after, #self.t + 1) or {}
      local lat, lon = qs[1], qs[2]
      if lat and lat.b == after and lat.value and lon and lon.value
          and ((lat.kind == "lat" and lon.kind == "lon") or (lat.kind ~= "lat" and lon.kind ~= "lon"
            and (lat.kind == "plain" or lat.kind == "number") and (lon.kind == "plain" or lon.kind == "number")
            and lon.b == lat.e and math.abs(lat.value) <= 90 and math.abs(lon.value) <= 180
            and lat.value % 1 ~= 0))
          and #self:refs_in(k, e, "aircraft") == 0
          and self:any_place_named(name, function() return true end, lat.value, lon.value, near_nm) then
        self:mark_used(k, after)
        for x = k, after - 1 do self.noted[x] = true end
      end
    end
  end
end

-- True when tokens [b, e), a clause opening the request before a comma, colon or dash, are a station's
-- simulator addressed (lexicon.station_sims after one or two words naming the station: "Chicago sim, ...",
-- "N90 sim - ...", "Potomac simulator: ..."), no callsign said: each word of the name capitalised and no
-- word squawk knows (a facility's identifier typed, "ZAU", "N90", or a name; no aircraft flying, no value),
-- or the name a city, airport or unit the station is named after ("new york sim, ...").
G.station_sims = set_of(lexicon.station_sims)
function G:station_sim(b, e)
  if b ~= self:skip_fillers(1) or e - b < 2 or e - b > 3 or not G.station_sims[self.t[e - 1].text] then return false end
  local words, proper = {}, true
  for k = b, e - 2 do
    local t, ref = self.t[k], self:refs_in(k, k + 1, "aircraft")[1]
    if ref and ref.exists then return false end
    if not ref and (t.kind ~= "word" or #self:quantities(k, k + 1) > 0) then return false end
    words[#words + 1] = t.text
    proper = proper and t.raw:match("^%u") ~= nil and (ref ~= nil or not known_word(t.text))
  end
  local name = table.concat(words, " ")
  return proper or ATC_UNITS[name] ~= nil or lexicon.city_airports[name] ~= nil
    or (self.world.airports_of_city ~= nil and #self.world.airports_of_city(name) > 0)
end

-- True when tokens [b, e), a clause ending in a comma or colon (`after_callsign`: or its part after a
-- callsign), are a station in the addressing position (G:stations).
function G:station_clause(b, e, after_callsign)
  for _, r in ipairs(self.refs) do
    after_callsign = after_callsign or (r.kind == "aircraft" and r.e == b - 1 and self.t[b - 1].text == ",")
  end
  local before_callsign = b == self:skip_fillers(1) and #self:refs_in(e + 1, e + 2, "aircraft") > 0
  if not (after_callsign or before_callsign) then return false end
  local last = e - 1
  if last > b and FACILITIES[self.t[last].text] then last = last - 1 end
  -- (an airline said alone whose name is a city's, "Shamrock 6MA, Brussels, bonjour, ...": in the addressing
  -- position after a callsign it is the station, never a second aircraft; G:stations drops its reference)
  local aircraft = self:refs_in(b, e, "aircraft")
  if after_callsign and #aircraft == 1 and aircraft[1].by_airline and aircraft[1].b == b and aircraft[1].e == last + 1 then
    aircraft = {}
  end
  if last - b > 2 or #self:quantities(b, e) > 0 or #aircraft > 0 then return false end
  local words, proper = {}, true
  for k = b, last do
    local t = self.t[k]
    if t.kind ~= "word" or MEANING[t.text] or self:intent_at(k) then return false end
    words[#words + 1], proper = t.text, proper and t.raw:match("^%u") ~= nil
  end
  local name = table.concat(words, " ")
  if ATC_UNITS[name] or lexicon.city_airports[name] then return true end
  if not proper then return false end
  for _, by in ipairs({ self.world.airports_named, self.world.airports_of_city }) do
    if #by(name) > 0 then return true end
  end
  -- (a place named by its navaid: "Kano, Ethiopian 935, ...", the KANO VOR-DME anywhere in the navdata)
  local navaids = self.world.navaids_named
  return navaids ~= nil and #navaids(name, 0, 0, 1e5) > 0
end

-- The end of the city or airport of one or two capitalised words starting at i (lexicon.city_airports, or words
-- of a navdata airport's name) said to describe an aircraft or airspace, lexicon.described_places: before
-- a noun of `before` ("a Charlotte arrival", "the Madrid TMA"), or after a word of `after` said straight after one
-- of `leads` ("the arrival into Atlanta", "bound for Vigo"); nil when it is none.
function G:described_place(i)
  local D = G.described_sets
  if not D then
    local L = lexicon.described_places
    D = { before = set_of(L.before), after = set_of(L.after), leads = set_of(L.leads) }
    G.described_sets = D
  end
  local function capital(k)
    local t = self.t[k]
    return t ~= nil and t.kind == "word" and t.alpha and t.raw:match("^%u") ~= nil and not t.keyword
      and not MEANING[t.text] and not self.triggers[k] and #self:refs_in(k, k + 1, "aircraft") == 0
  end
  if not capital(i) then return nil end
  local words, w = self.words, self.world
  local after = (words[i - 1] and D.after[words[i - 1]] and words[i - 2] and D.leads[words[i - 2]])
    or self:relative_departure(i - 1) or (words[i - 1] == "from" and self:relative_departure(i - 2))
  for e = capital(i + 1) and i + 2 or i + 1, i + 1, -1 do
    local name = e > i + 1 and self.t[i].text .. " " .. self.t[i + 1].text or self.t[i].text
    if (after or (words[e] and D.before[words[e]])) and (lexicon.city_airports[name]
        or (w.airports_named and #w.airports_named(name) > 0) or (w.airports_with_words and #w.airports_with_words(name) > 0)) then
      return e
    end
  end
  return nil
end

-- The end of a place said at i to describe the aircraft named straight before it, "the" and the aircraft opening
-- its clause and the place closing it at a comma (lexicon.described_places.moving: "the Ryanair out of Cork, up to
-- 17 thousand", "the easyJet going into the Isle of Man, start it down"): one to four words of `moving` between,
-- the first of `moving_leads`; the place an airport's city or name (G:described_place's names) or one of `regions`;
-- nil when it is none.
function G:moving_place(i)
  local L = lexicon.described_places
  local M = G.moving_sets
  if not M then
    M = { moving = set_of(L.moving), leads = set_of(L.moving_leads), regions = set_of(L.regions) }
    G.moving_sets = M
  end
  local t = self.t[i]
  if not (t and t.kind == "word" and t.raw:match("^%u") and self.words[i - 1] and M.moving[self.words[i - 1]]) then
    return nil
  end
  local k = i - 1
  while k >= i - 4 and self.words[k] and M.moving[self.words[k]] do k = k - 1 end
  if not M.leads[self.words[k + 1]] then return nil end
  local ref
  for _, r in ipairs(self:refs_in(math.max(1, k - 4), k + 1, "aircraft")) do
    if r.e == k + 1 and r.exists then ref = r end
  end
  if not ref then return nil end
  local o = ref.b - 2  -- (said with "the": "DLH4AX inbound from Oslo, ..." states where a callsign comes from)
  if not self:word(ref.b - 1, "the") or (o >= 1 and self.t[o].kind ~= "punct" and not self:word(o, "and")) then
    return nil
  end
  local w = self.world
  for e = math.min(#self.t, i + 3), i + 1, -1 do
    local words = {}
    for x = i, e - 1 do words[#words + 1] = self.t[x].text end
    local name = table.concat(words, " ")
    local closes = self.t[e] ~= nil and self.t[e].text == ","
    if closes and (M.regions[name] or (e <= i + 2 and (lexicon.city_airports[name]
        or (w.airports_named and #w.airports_named(name) > 0)
        or (w.airports_with_words and #w.airports_with_words(name) > 0)))) then
      return e
    end
  end
  return nil
end

-- True when the word at i (lexicon.described_places.departs) says where an aircraft comes from in a relative clause
-- that identifies it ("the Easy that's just departed Luton", "the Ryanair which left Dublin"): a word of `relatives`
-- before it, only words of `relative_fill` between; or a pronoun of `narrated` with "just" among those words ("It
-- has just departed Schiphol").
-- lexicon.described_places' word lists of a relative clause, as sets
function G:relative_departure_sets()
  local L = lexicon.described_places
  local R = G.relative_sets
  if not R then
    R = { departs = set_of(L.departs), relatives = set_of(L.relatives), fill = set_of(L.relative_fill),
      narrated = set_of(L.narrated) }
    G.relative_sets = R
  end
  return R
end
function G:relative_departure(i)
  local R = self:relative_departure_sets()
  local words = self.words
  if not (words[i] and R.departs[words[i]]) then return false end
  local k, just = i - 1, false
  while k > i - 4 and words[k] and R.fill[words[k]] do
    just = just or words[k] == "just"
    k = k - 1
  end
  return words[k] ~= nil and (R.relatives[words[k]] == true or (just and R.narrated[words[k]] == true))
end

-- The span [b, e) of words from i that say of the aircraft named straight before them that it has just left the
-- ground, to identify it, no place said: a phrase of lexicon.described_places.departs_alone at i, after the
-- aircraft's reference or after a word of `relatives` (words of `relative_fill` between) that follows it, with
-- punctuation or the request's end after ("the Southwest that just took off, climb ...", "the United departing,
-- climb ..."); nil otherwise.
function G:departure_described(i)
  local L = lexicon.described_places
  local D = G.departs_alone
  if not D then
    D = {}
    for _, p in ipairs(L.departs_alone) do
      local words = {}
      for x in p:gmatch("%S+") do words[#words + 1] = x end
      D[words[1]] = D[words[1]] or {}
      table.insert(D[words[1]], words)
    end
    G.departs_alone = D
  end
  local words = self.words
  local phrases = words[i] and D[words[i]]
  if not phrases then return nil end
  local e
  for _, p in ipairs(phrases) do
    local ok = true
    for x = 2, #p do ok = ok and words[i + x - 1] == p[x] end
    if ok then e = i + #p end
  end
  if not e or (self.t[e] and self.t[e].kind ~= "punct") then return nil end
  local R = self:relative_departure_sets()
  local k = i - 1
  while k > i - 4 and words[k] and R.fill[words[k]] do k = k - 1 end
  if words[k] and R.relatives[words[k]] then k = k - 1 end
  for _, r in ipairs(self:refs_in(math.max(1, k - 4), k + 1, "aircraft")) do
    if r.e == k + 1 then return k + 1, e end
  end
  return nil
end

-- lexicon.asides_alone by their first word, each as its words
G.asides_alone = {}
for _, p in ipairs(lexicon.asides_alone) do
  local words = {}
  for w in p:gmatch("%S+") do words[#words + 1] = w end
  G.asides_alone[words[1]] = G.asides_alone[words[1]] or {}
  table.insert(G.asides_alone[words[1]], words)
end
-- "ist gut, pause", "tui3k climb fl350, alles klar": an aside of lexicon.asides_alone starting at token i, standing
-- alone in its clause (the request's edge or punctuation before and after it, fillers between), or opening the
-- request ("oké continue", transcribed with no break after it: no value before it to call fine), is marked in
-- `inside`
-- "ok guys we stop here five minutes, freeze the simulation please", "let's take a break of ten minutes, pause
-- the sim": a clause opening with the speakers' "we"/"let's" (read "let", its "'s" dropped)/"let us" that says they stop or take a break, with one length
-- of time and no aircraft in it, is a remark set aside when another clause of the request asks for the pause
-- (HOLD: squawk's pause has no length). "pause the simulation for five minutes" (the length said of the pause
-- itself) stays asked.
function G:break_remarks()
  for i = 1, #self.t do
    local w = self.words[i]
    local b = (w == "we" or w == "let's" or w == "lets") and i + 1 or (w == "let" and (self:word(i + 1, "us") and i + 2 or self:word(i + 1, "stop take have") and i + 1))
    local e = i
    while b and e <= #self.t and self.t[e].kind ~= "punct" do e = e + 1 end
    local qs = b and self:quantities(i, e) or {}
    if b and self:word_in(b, math.min(e, b + 3), "stop break") and #qs == 1 and qs[1].kind == "time"
        and #self:refs_in(i, e, "aircraft") == 0 then
      local other = false
      for k = 1, #self.t do other = other or ((k < i or k >= e) and self:intent_at(k) == "hold") end
      if other then self:set_aside(i, e - 1) end
    end
  end
end

function G:aside_alone(i, inside)
  local phrases = G.asides_alone[self.t[i].text]
  if not phrases then return end  -- (called at every token: most start no such phrase)
  local function edge(k, step, start)
    while self.t[k] and self.t[k].filler do k = k + step end
    return self.t[k] == nil or (not start and self.t[k].kind == "punct")
  end
  for _, p in ipairs(phrases) do
    local ok = true
    for x = 2, #p do ok = ok and self.t[i + x - 1] ~= nil and self.t[i + x - 1].text == p[x] end
    if ok and ((edge(i - 1, -1) and edge(i + #p, 1)) or edge(i - 1, -1, true)) then
      for x = i, i + #p - 1 do inside[x] = true end
      return
    end
  end
end

-- The words [b, e) as one lower-case name, or nil when a token there is no plain word (a value, an instruction word,
-- a word with a meaning, an aircraft; English squawk knows too unless `english` is set).
function G:plain_name(b, e, english)
  local words = {}
  for k = b, e - 1 do
    local t = self.t[k]
    if not t or t.kind ~= "word" or not t.alpha or MEANING[t.text] or self.triggers[k]
        or (not english and known_word(t.text)) or self:has_ref(k, k + 1, "aircraft") then
      return nil
    end
    words[#words + 1] = t.text
  end
  return #words > 0 and table.concat(words, " ") or nil
end

-- The codes of the navdata's places called `name` (a navaid's name, an airport's name, its city, the city's English
-- name, lexicon.city_airports, and unless `whole`, words of an airport's name), within `nm` NM of lat, lon when given;
-- f(code) is called for each until it returns true, and then true is returned. The cheaper look-ups go first; false
-- without navdata.
function G:any_place_named(name, f, lat, lon, nm, whole)
  local w = self.world
  if not (w.navaids_named and w.airports_named and w.airports_of_city and w.airports_with_words) then return false end
  for _, said in ipairs({ name, lexicon.city_airports[name] }) do
    for _, by in ipairs({ w.navaids_named, w.airports_named, w.airports_of_city, not whole and w.airports_with_words or nil }) do
      for _, id in ipairs(by(said, lat or 0, lon or 0, nm or 1e5)) do
        if f(id:upper()) then return true end
      end
    end
  end
  return false
end

-- True when the words [b, e) name a place of the navdata (G:any_place_named): the place of code `code` when given
-- (the words may then be English squawk knows: "Nice", "Brussels"), any when nil.
function G:place_named(b, e, code)
  local name = self:plain_name(b, e, code ~= nil)
  return name ~= nil and self:any_place_named(name, function(id) return not code or id == code end)
end

-- "direct to nienburg NIE", "goes to braunschweig, EDVE", "EDDH hamburg", "Milan Malpensa, LIMC": words just before
-- place ref r (commas and kinds of place between) or just after it, one to three of them, that name r (or the place
-- `code` issued for it, when given: "to the PAM VOR, Amsterdam" gives EHAM) are marked in
-- `inside`: the navdata's name of r's code in any case, or capitalised words that name no place of the navdata
-- farther than CITY_NM from r ("Heraklion, LGIR": a name it does not know; "Berlin, EDDB": the city's other airport
-- lies near; a word of a far field's name is no other place). A name it gives only to places elsewhere (a navaid's
-- name, an airport's name or city) stays unexplained (asked: "direct to Tucson, GBN", "direct
-- to hannover NIE"), and so does another navaid's own name beside a navaid or fix, however near ("direct WGM,
-- Sollenau": SNU).
local CITY_NM = 40  -- a place said "near" a city lies this near one of its airports [NM]
G.same_site_nm = 12  -- navaids this near one another stand at one town and may share its name [NM]
function G:name_beside_code(r, inside, code)
  code = code or r.name:upper()
  local lat, lon
  if self.world.user_waypoint_at then lat, lon = self.world.user_waypoint_at(code) end
  local hesitated = false  -- (a hesitation between: only the navdata's own name of code is read)
  local function names(b, e)
    if self:place_named(b, e, code) then return true end
    if hesitated then return false end
    for k = b, e - 1 do
      if not (self.t[k] and self.t[k].raw:match("^%u")) then return false end
    end
    local name = self:plain_name(b, e, true)
    local function any() return true end
    -- (the name of another navaid said beside a navaid's or fix's ident, "direct WGM, Sollenau" with SNU called
    -- SOLLENAU 28 NM away, names that place: unexplained; one within G.same_site_nm of it stands at the same town,
    -- "QPR, Quimper" beside the Quimper NDB, and beside an airport's code, of four letters, a city may share it)
    local named = name and #code ~= 4 and self.world.navaids_named
    if named and #named(name, 0, 0, 1e5) > 0 and not (lat and #named(name, lat, lon, G.same_site_nm) > 0) then
      return false
    end
    return name ~= nil and (not self:any_place_named(name, any, nil, nil, nil, true)
      or lat ~= nil and self:any_place_named(name, any, lat, lon, CITY_NM))
  end
  -- (a mark, a kind of place, or a hesitation, G.hesitation_words: "direct RID, uh, Ried")
  local function between(k)
    if self.t[k] and G.hesitation_words[self.t[k].text] then hesitated = true return true end
    return self.t[k] and (self.t[k].kind == "punct" or self:word(k, "@airport_nouns @navaid_kinds"))
  end
  local e = r.b
  while e > 1 and r.b - e < 3 and between(e - 1) do e = e - 1 end
  for n = 3, 1, -1 do
    if e - n >= 1 and not inside[e - n] and names(e - n, e) then
      for k = e - n, r.b - 1 do inside[k] = true end
      break
    end
  end
  local b = r.e
  hesitated = false
  while b < r.e + 3 and between(b) and self.t[b].text ~= "." do b = b + 1 end
  for n = 2, 1, -1 do
    if not inside[b] and names(b, b + n) then
      for k = r.e, b + n - 1 do inside[k] = true end
      break
    end
  end
end

-- The first token of a wish framed before the "if" at i, from its clause's start ("it would be good if KLM12
-- climbs to FL300", "I think it is better if ...", "would be nice if ...", "I would be grateful if ..."): framing
-- words and a word of lexicon.wish_evaluative only, no word of lexicon.wish_negation, not a question's inverted
-- order ("would it be good if ...?", "is it better if ...": asked); nil when none.
function G:wish_frame(i)
  local k, eval = i - 1, false
  while k >= 1 and not (self.t[k].kind == "punct" and self.t[k].text ~= "'") do
    local t = self.t[k]
    if self:word(k, "@wish_negation") or t.kind ~= "word" then return nil end
    if self:word(k, "@wish_evaluative") then
      eval = true
    elseif not (FRAMING[t.text] or t.filler or self:word(k, "it'd i'd we'd that'd")) then
      return nil
    end
    k = k - 1
  end
  local b = k + 1
  if not eval or (self:word(b, "would will could should is was does") and self:word(b + 1, "it this that you")) then
    return nil
  end
  return b
end

-- The positions of tokens the parse explains beyond the words themselves: callsigns, places, types and
-- values; a place's name beside its issued code; the name "instead of" replaces or a direct-to passes
-- (`kinds`: G:issued); an ATC unit's place; comments and purposes; courtesy and value phrases.
function G:explained_spans(issued, kinds)
  local inside = {}
  -- (a wish framed before "if": G:wish_frame)
  for k = 2, #self.t do
    local b = self.words[k] == "if" and self:wish_frame(k)
    for x = b or 1, b and k or 0 do inside[x] = true end
  end
  for _, r in ipairs(self.refs) do
    for k = r.b, r.e - 1 do inside[k] = true end
  end
  for _, q in ipairs(self:quantities(1, #self.t + 1)) do
    for k = q.b, q.e - 1 do inside[k] = true end
  end
  -- a place said by its name beside its code as issued ("destination Frankfurt, EDDF", "EPKK Krakow",
  -- "London Heathrow, EGLL", "Amsterdam Schiphol (EHAM)", "the Pampus VOR, PAM")
  for _, r in ipairs(self.refs) do
    if r.kind == "waypoint" and issued[r.name:lower()] then
      self:name_beside_code(r, inside)
      -- ("at the RIX VOR near Riga": the city it lies by, a name the navdata gives a place near it)
      local n = self:word(r.e, "@navaid_kinds @airport_nouns") and r.e + 1 or r.e
      local city = self.t[n + 1] and self.t[n + 1].kind == "word" and self.t[n + 1].raw:match("^%u") and self.t[n + 1].text
      local lat, lon
      if self:word(n, "near by") and city and self.world.user_waypoint_at then lat, lon = self.world.user_waypoint_at(r.name) end
      if lat and self:any_place_named(city, function() return true end, lat, lon, CITY_NM, true) then
        inside[n], inside[n + 1] = true, true
      end
      -- ("direct GRM, the Gardermoen VOR": its name after "the", with its kind of navaid or airport after it)
      if self.t[r.e] and self.t[r.e].kind == "punct" and self:word(r.e + 1, "the") then
        local n = r.e + 2
        while n < r.e + 5 and self.t[n] and self.t[n].kind == "word" and self.t[n].raw:match("^%u")
            and not self:word(n, "@navaid_kinds @airport_nouns") and not MEANING[self.t[n].text] do
          n = n + 1
        end
        local words = {}
        for x = r.e + 2, n - 1 do words[#words + 1] = self.t[x].text end
        local named = n > r.e + 2 and self.world.navaids_named
          and self.world.navaids_named(table.concat(words, " "), 0, 0, 1e5) or {}
        local same = false
        for _, id in ipairs(named) do same = same or id:upper() == r.name:upper() end
        if same and self:word(n, "@navaid_kinds @airport_nouns") then
          for x = r.e + 1, n do inside[x] = true end
        end
      end
    end
  end
  -- "another departure out of Modlin: RYR2AB B738 at EPMO": a capitalised word elsewhere in the request that is
  -- the navdata's own name of an airport issued by its code
  local named = self.world.airports_named
  for k = 1, named and #self.t or 0 do
    local t = self.t[k]
    if not inside[k] and t.kind == "word" and t.raw:match("^%u%l+$") and not MEANING[t.text] then
      for _, code in ipairs(named(t.text)) do
        if issued[code:lower()] then inside[k] = true end
      end
    end
  end
  -- "direct to the merge point MRG01", "the metering fix RILAX": a word naming the place's role, before
  -- "point" or a waypoint noun said straight before a place issued (a word with a meaning, "not", never)
  for _, r in ipairs(self.refs) do
    if r.kind == "waypoint" and issued[r.name:lower()] and r.b > 2 and self:word(r.b - 1, "point @waypoint_nouns")
        and self.t[r.b - 2].kind == "word" and not MEANING[self.t[r.b - 2].text] and not self.triggers[r.b - 2] then
      inside[r.b - 2] = true
    end
  end
  local texts = self.words
  local passed = kinds.direct and word_set("@passed_over", 1)
  for i = 1, #self.t do
    local w, nw = texts[i], texts[i + 1]
    -- "to SFO instead of Oakland", "Stansted rather than Luton": the name replaced
    if ((w == "instead" and nw == "of") or (w == "rather" and nw == "than"))
        and self.t[i + 2] and self.t[i + 2].raw:match("^%u") then
      inside[i], inside[i + 2] = true, true
    end
    -- "go straight to Ockham, skipping Mayfield", "omitting the Montreal VOR": a name a direct-to passes (after
    -- "the", its kind of navaid after it)
    if passed and w and passed[w] == true then
      local n = self:word(i + 1, "the") and i + 2 or i + 1
      if self.t[n] and self.t[n].raw:match("^%u") then
        for k = i + 1, n do inside[k] = true end
        if n > i + 1 and self:word(n + 1, "@navaid_kinds") then inside[n + 1] = true end
      end
    end
    -- "New York departure", "Boston approach": the unit's place
    if w and FACILITIES[w] then
      for k = math.max(1, i - 2), i - 1 do
        if self.t[k].kind == "word" and not MEANING[self.t[k].text] and not self.triggers[k] then inside[k] = true end
      end
    end
    -- "hand Easy 45TK to the AI - AI, turn it ...": the machine teammate (lexicon.addressed_roles.names) named as who
    -- an aircraft is handed to ("to (the) AI"), or addressed opening a clause, before its comma
    if w and ADDRESSED[w] == true and (self:word(i - 1, "to") or (self:word(i - 1, "the") and self:word(i - 2, "to"))
        or ((i == 1 or self.t[i - 1].kind == "punct") and self.t[i + 1] and self.t[i + 1].kind == "punct")) then
      inside[i] = true
    end
    -- "a Charlotte arrival", "the arrival into Atlanta": a city named to describe (G:described_place)
    local place_e = self:described_place(i) or self:moving_place(i)
    for k = i, place_e and place_e - 1 or 0 do inside[k] = true end
    -- ("that's just departed Luton", "which departed from Luton": the verb of the relative clause with its place)
    for k = i - 2, place_e and i - 1 or i - 3 do
      if self:relative_departure(k) then for x = k, i - 1 do inside[x] = true end end
    end
    -- ("the Southwest that just took off, climb ...": the relative clause with no place, G:departure_described)
    local dep_b, dep_e = self:departure_described(i)
    for x = dep_b or 0, dep_b and dep_e - 1 or -1 do inside[x] = true end
    -- "climb FL360, not above": the level said is a limit too, when nothing follows in its clause ("not
    -- above FL370" names another level, asked about)
    if w == "not" and (nw == "above" or nw == "below") then
      local nx = self.t[i + 2]
      if not nx or nx.kind == "punct" then inside[i], inside[i + 1] = true, true end
    end
    -- "climb to FL320 but not above 1500 feet a minute", "not exceeding 2000 fpm": a vertical speed said as the
    -- most to fly, which the rate issued carries (a level or speed after it is asked)
    if w == "not" and self:word(i + 1, "above exceeding over") then
      local q = self:quantities(i + 2, i + 3)[1]
      if q and q.kind == "vs" and q.b == i + 2 then inside[i], inside[i + 1] = true, true end
    end
    -- "could you list the route of Alaska 1129 once more?": a request made again, "once more" closing its clause
    -- (before punctuation, "please" or the end); "once more than 10 miles from ..." opens a condition, never this
    if w == "once" and nw == "more" then
      local nx = self.t[i + 2]
      if not nx or nx.kind == "punct" or self:word(i + 2, "please") then inside[i], inside[i + 1] = true, true end
    end
    local phrases = PHRASES[self.t[i].text]
    for k = 1, phrases and #phrases or 0 do
      local p, ok = phrases[k], true
      for x = 2, #p do ok = ok and self.t[i + x - 1] ~= nil and self.t[i + x - 1].text == p[x] end
      if ok then for x = i, i + #p - 1 do inside[x] = true end end
    end
    self:aside_alone(i, inside)
  end
  -- Comments and purposes that name no instruction, value or place, to the end of their clause: a
  -- clause after punctuation that opens with its own subject ("Delete N123AB, we don't need it for this
  -- run"; "The participant is waiting."), "so" before a subject ("so the runs are repeatable"), and
  -- "for" before a determiner after the request's first word ("for the novice participants").
  local function comment(b, e)
    if #self:quantities(b, e) > 0 or #self:refs_in(b, e, "aircraft") > 0 then return end
    for _, r in ipairs(self:refs_in(b, e, "waypoint")) do
      if not self:word(r.b, "@not_names") then return end  -- ("we don't need the VFR traffic")
    end
    -- ("for the cruise segment": a phase of the flight named by its verb before a noun of lexicon.phase_nouns)
    for x = b, e - 1 do
      local phase = self.t[x + 1] and lexicon.phase_nouns[self.t[x + 1].text]
      if (self.triggers[x] or self:intent_at(x)) and not phase then return end
    end
    for x = b, e - 1 do inside[x] = true end
  end
  local k = 1
  while k <= #self.t do
    local e = k
    while e <= #self.t and not (self.t[e].kind == "punct" and self.t[e].text ~= "'") do e = e + 1 end
    for j = k, e - 1 do
      local t, nx, w = self.t[j], self.t[j + 1], texts[j]
      local subject = nx and nx.kind == "word" and SUBJECTS[nx.text]
      -- ("delete KLC21, not needed for this run": a participle's clause, negated)
      local participle = j == k and k > 1 and w == "not" and nx and nx.kind == "word" and nx.text:match("%aed$")
      -- ("WZZ1523 is not needed anymore, remove it": the aircraft, a copula and a participle of
      -- lexicon.unneeded, negated, as the clause's whole predicate)
      local unneeded = false
      if j == k then
        local first = self:refs_in(k, k + 1, "aircraft")[1]
        local v = first and first.b == k and first.e or k
        if self:word(v, "is are") then v = v + 1 end
        unneeded = v > k and self:word(v, "not isn't aren't") and self:word(v + 1, "@unneeded")
          and #self:quantities(v, e) == 0 and #self:refs_in(v, e) == 0 and v
      end
      if unneeded then
        for x = unneeded, e - 1 do inside[x] = true end
        break
      end
      if j == k and (self:need_denied(k, e) or self:presence_denied(k, e)) then
        for x = k, e - 1 do inside[x] = true end
        break
      end
      -- ("freeze sim for debrief": a session's own step named after "for", with no determiner)
      if (j == k and k > 1 and t.kind == "word" and SUBJECTS[t.text]) or participle or (w == "so" and j > 1 and subject)
          or (w == "for" and j > 1 and (subject or (nx and nx.kind == "word" and lexicon.session_steps[nx.text]))) then
        comment(j, e)
        break
      end
    end
    k = e + 1
  end
  return inside
end

-- "run at double speed until the Gander boundary", "fast forward five minutes so the westbounds reach 20
-- West": after the clock's rate or a jump in time is set, a clause from "until" or "so" that names no
-- aircraft and no value but a position says what the run should reach by then: a remark, explained.
function G:clock_remark()
  local _, kinds = self:issued()
  if not kinds.clock then return end
  for i = 1, #self.t do
    if self:word(i, "until so") and not self.u:used(i) then
      local e = i + 1
      while e <= #self.t and self.t[e].kind ~= "punct" do e = e + 1 end
      local plain = e > i + 1 and #self:refs_in(i + 1, e, "aircraft") == 0
      for _, q in ipairs(self:quantities(i + 1, e)) do plain = plain and (q.kind == "lat" or q.kind == "lon") end
      for k = i + 1, e - 1 do plain = plain and not MEANING[self.t[k].text] end
      if plain then
        for k = i, e - 1 do self.noted[k] = true end
        for _, q in ipairs(self:quantities(i + 1, e)) do self:take(q) end
      end
    end
  end
end

-- "AFR6204 and IBE3421 -- no, forget the Iberia. Just AFR6204 heading 220": an aircraft named straight after a
-- word of lexicon.forget ("the" and "about" between at most) is taken out of the request: no command names it.
-- Nothing left asks for the instruction again.
-- "..., and direct RILAX after that, no, forget RILAX": a waypoint named there that the request named before it
-- takes back the instructions naming it (the direct, its ADDWPT); one held by a condition ("at RILAX ...") is
-- asked about, as is a request left with nothing.
function G:forgotten()
  if not self:said("@forget") then return end
  for i = 1, #self.t do
    if self:word(i, "@forget") then
      local k = self:skip_fillers(i + 1)
      while self:word(k, "the about") do k = k + 1 end
      local r = self:refs_in(k, k + 1, "aircraft")[1]
      local w = not r and self:refs_in(k, k + 1, "waypoint")[1]
      local before = false
      for _, o in ipairs(w and self.refs or {}) do
        before = before or (o.kind == "waypoint" and o.e <= i and o.name:upper() == w.name:upper())
      end
      if before then
        local name, kept, held = w.name:upper(), {}, false
        for _, line in ipairs(self.out) do
          if line:upper():find("%f[%w]" .. name .. "%f[^%w]") then
            held = held or CONDITIONAL[line:match("^(%u+)")] or line:find(" DO ") ~= nil
          else
            kept[#kept + 1] = line
          end
        end
        for x = i, w.e - 1 do self.noted[x] = true end
        for _, o in ipairs(self.refs) do  -- (every mention of it)
          if o.kind == "waypoint" and o.name:upper() == name then
            for x = o.b, o.e - 1 do self.noted[x] = true end
          end
        end
        if held or #kept == 0 then
          self.ask = string.format("You said to forget %s. What stands? Please say the instruction again in full.",
            name)
          return
        end
        self.out = kept
      end
      if r and r.exists then
        local id, kept = r.name:upper(), {}
        for _, line in ipairs(self.out) do
          if not line:find("%f[%w]" .. id .. "%f[^%w]") then kept[#kept + 1] = line end
        end
        self.out = kept
        for x = i, r.b - 1 do self.noted[x] = true end
        for _, o in ipairs(self.refs) do  -- (every mention of it)
          if o.kind == "aircraft" and o.name:upper() == id then
            for x = o.b, o.e - 1 do self.noted[x] = true end
          end
        end
        if #kept == 0 then
          self.ask = string.format("I left %s out, as said. Which instruction stands? Please say it again in full.", id)
        end
      end
    end
  end
end

-- "descend FL340, that's the Air France level, FL320", "..., that is the Air France heading, 070": an aircraft named
-- only as whose value "that" or "it" is ("that's the X level") is described, never told: a command for it is asked
-- about, naming the words. ("no wait, it is the Wizz", the aircraft alone, corrects the addressee: G:self_corrected.)
function G:predicated()
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" and r.exists and self:word(r.b - 1, "the")
        and self:word(r.e, "level altitude heading speed height")
        and (self:word(r.b - 2, "that it this") or self:word(r.b - 2, "is was") and self:word(r.b - 3, "that it this")) then
      local id, elsewhere, told = r.name:upper(), false, false
      for _, o in ipairs(self.refs) do
        elsewhere = elsewhere or (o ~= r and o.kind == "aircraft" and o.name:upper() == id)
      end
      for _, line in ipairs(self.out) do
        told = told or line:find("%f[%w]" .. id .. "%f[^%w]") ~= nil
      end
      if told and not elsewhere then
        local b = self:word(r.b - 2, "is was") and r.b - 3 or r.b - 2
        self.ask = string.format("I have %s. Is '%s' an instruction for %s, or only whose it is? Please say again "
          .. "who should do what.", table.concat(self.out, " ; "),
          (self:raw(b, r.e + 1):gsub(" ([,.;:])", "%1")), id)
        return
      end
    end
  end
end

-- "add GATE to the route of Swiss 100": a place added to a route (ADDWPT) by a name that resolves nowhere (no
-- DEFWPT, route, fix, navaid or airport of the navdata holds it, world.locate) is asked about, never added: the
-- word may be no place at all. Only where navdata is loaded (a large airport known); without it nothing changes.
function G:unknown_places()
  local w = self.world
  if not (w.locate and w.airport_class) then return end
  local loaded = false
  for _, code in ipairs({ "EHAM", "EGLL", "KJFK" }) do loaded = loaded or (w.airport_class(code) or "") ~= "" end
  if not loaded then return end
  local defined = {}
  for _, line in ipairs(self.out) do
    local d = line:match("^DEFWPT ([^%s,]+)")
    if d then defined[d:upper()] = true end
  end
  for _, line in ipairs(self.out) do
    local name = line:match("ADDWPT %S+ (%a[%w]*)[%s,]") or line:match("ADDWPT %S+ (%a[%w]*)$")
    if name and not defined[name:upper()] and not w.locate(name:upper()) then
      self.ask = string.format("Which waypoint is %s? It names no waypoint, navaid or airport I know. Please give "
        .. "its name again, or a latitude and longitude.", name:upper())
      return
    end
  end
end

-- A described value's kind -> the command it would be read as (G:described drops that command)
G.described_verb = { alt = "ALT", speed = "SPD", heading = "HDG" }

-- "TVF52KL and AFR1234 are co-altitude at 350, good. Push AFR7516 down to 350 too", "AFR7706 stop at FL170 and
-- the Transavia keeps FL170 -- that's our conflict": aircraft named as the subject of a verb of
-- lexicon.described (and not told to do anything after it: lexicon.described_not) are described, not
-- instructed. A command for such an aircraft, named nowhere else, whose values are all said in the
-- description's clause is the description misread: it is left out. One with a value said elsewhere is the
-- described aircraft's own instruction ("KLM12 is too high, descend FL200") unless another aircraft was named
-- before the description ("Iberia 0842 climb FL390... no wait, the Transavia's there. Make it FL380"): then
-- it is asked about.
function G:described()
  local described, grouped = {}, {}
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" and r.exists and not grouped[r.b] then
      -- (a group: "X and Y are ...", "the X and the Y are ...")
      local k, group = r.e, { r }
      local function next_at(x) return self:word(x, "the") and x + 1 or x end
      while self:word(k, "and") and self:has_ref(next_at(k + 1), next_at(k + 1) + 1, "aircraft") do
        local o = self:refs_in(next_at(k + 1), next_at(k + 1) + 1, "aircraft")[1]
        group[#group + 1], k, grouped[o.b] = o, o.e, true
      end
      -- ("RYR8 at FL210 is traffic": the aircraft's value said before the copula)
      local v = self:word(k, "at") and k + 1 or k
      local held = self:quantities(v, #self.t + 1)[1]
      if held and held.b == v and self:word(held.e, "@described") then k = held.e end
      local verb_at = self:word(k + 1, "@described_quantifiers") and k + 2 or k + 1
      -- ("KLM12 is kindly requested to descend", "is politely asked to": courtesy before the verb of the request)
      if self:word(verb_at, "kindly politely please hereby herewith") then verb_at = verb_at + 1 end
      local before = self:word(r.b - 1, "the a an") and r.b - 2 or r.b - 1
      -- ("I've got the Tomjet above at 170": the object of lexicon.described_object, its clause from after the name)
      if self:word(before, "@described_object") then k = r.e - 1 end
      -- ("Kenya 420 is it possible to slow to 230 knots?", "KQA420 is it ok for you to climb", "is possible to":
      -- a polite opener asking leave, lexicon.leave_asked then "to", is the request, no description)
      local leave = self:word(k, "is") and (self:word(verb_at, "it") and verb_at + 1 or verb_at)
      if leave and self:word(leave, "@leave_asked") then
        leave = self:word(leave + 1, "for") and self:word(leave + 2, "you it him her") and leave + 3 or leave + 1
        leave = self:word(leave, "to")
      else
        leave = false
      end
      if (k == r.e - 1 or self:word(k, "@described") and not self:word(verb_at, "@described_not") and not leave)
          and not self:word(before, "@described_after") then
        -- (the clause ends at punctuation, or at an instruction word after its first value: "KLM12 is at FL300
        -- climb FL320")
        local e = k + 1
        while e <= #self.t and self.t[e].kind ~= "punct" do e = e + 1 end
        local q = self:quantities(k + 1, e)[1]
        for x = q and q.e or e, e - 1 do
          if self:intent_at(x) then e = x break end
        end
        for _, o in ipairs(group) do described[o.name:upper()] = { b = r.b, e = e } end
      end
    end
  end
  for id, span in pairs(described) do
    local elsewhere, other_before = false, false
    for _, o in ipairs(self.refs) do
      if o.kind == "aircraft" and o.name:upper() == id and (o.b < span.b or o.b >= span.e) and not o.false_start then
        elsewhere = true
      end
      if o.kind == "aircraft" and o.b < span.b and not described[o.name:upper()] then other_before = true end
    end
    local values = {}
    for _, q in ipairs(self:quantities(span.b, span.e)) do  -- (a level in feet or in hundreds)
      values[#values + 1] = tostring(math.floor(q.value))
      values[#values + 1] = tostring(math.floor(q.value / 100))
    end
    if not elsewhere then
      local kept = {}
      for _, line in ipairs(self.out) do
        if line:find("%f[%w]" .. id .. "%f[^%w]") then
          local own = false
          for _, v in ipairs(values) do own = own or line:find("%f[%d]" .. v .. "%f[^%d]") ~= nil end
          if not own and self:given_to_named_after(line, id, span.e) then
            kept = kept  -- (the named aircraft's instruction, not the described one's: left out)
          elseif not own and not other_before then
            kept[#kept + 1] = line
          elseif not own then
            self.ask = string.format("I have %s, but %s was only described, not told to do anything. Which "
              .. "aircraft should get it?", line, id)
            return
          end
        else
          kept[#kept + 1] = line
        end
      end
      if #kept < #self.out then
        self.out = kept
        for x = span.b, span.e - 1 do self.noted[x] = true end
        for _, q in ipairs(self:quantities(span.b, span.e)) do self:take(q) end
      end
    else
      -- (named again with an instruction of its own: "KLM12 is at FL350, climb KLM12 to FL370"; each level, speed
      -- or heading of the description drops the one command of its own kind for the aircraft that carries it)
      local dropped = false
      for _, q in ipairs(self:quantities(span.b, span.e)) do
        local verb = G.described_verb[q.kind]
        local v = verb and tostring(math.floor(q.kind == "alt" and q.value / 100 or q.value))
        for i, line in ipairs(verb and self.out or {}) do
          local cv, cid, cval = line:match("^(%u+) (%S+) %a*(%d+)")
          if cv == verb and cid == id and cval == v then
            table.remove(self.out, i)
            self:take(q)
            dropped = true
            break
          end
        end
      end
      if dropped then
        for x = span.b, span.e - 1 do self.noted[x] = true end
      end
    end
  end
end

-- True when command `line` of described aircraft `id` is given alike to another aircraft named by name after token
-- e, not described, with no pronoun or quantifier after e that could take the described one in ("the Ryanair is
-- close, put the Aer Lingus down to FL290": the instruction names its own aircraft; "..., descend it and DLH4"
-- does not say so)
function G:given_to_named_after(line, id, e)
  if self:word_in(e, #self.t + 1, "it him her them both all each everyone everybody") then return false end
  for _, o in ipairs(self.refs) do
    local other = o.kind == "aircraft" and o.exists and o.b >= e and not o.false_start and o.name:upper()
    if other and other ~= id then
      for _, l in ipairs(self.out) do
        if l:gsub("%f[%w]" .. other .. "%f[^%w]", id) == line and l ~= line then return true end
      end
    end
  end
  return false
end

-- Once the request is read, a word no part of the parse explains is a leftover: a negation or a
-- condition the commands do not carry ("climb FL340 unless BAW12 is there"), or a word squawk does not
-- know ("climb FL340 gently"), or a verb of lexicon.clock_verbs no instruction was read from and none follows
-- ("resume everything and climb KLM12 FL300"). Words inside a callsign, place, type or value, a reason, a reply about
-- what squawk does not simulate, or a courtesy phrase ("when you get a chance") are explained.
local MANNER = set_of(lexicon.manner)
-- True when a vertical speed was issued: VS, or ALT with its rate ("ALT KLM1 FL340 1000").
function G:rate_issued()
  for _, c in ipairs(self.out) do
    if c:match("^VS ") or c:match("^ALT %S+ %S+ %S+$") then return true end
  end
  return false
end
-- True when the verb at i is said straight before an instruction word of its own ("resume climb FL300", "resume the
-- descent", "resume own heading", "resume Mach .82"): the instruction's manner, read with it; or after "to", no
-- imperative.
function G:resumes_instruction(i)
  if self:word(i - 1, "to") then return true end  -- ("advise when able to resume": no imperative)
  local k = self:word(i + 1, "the own your normal its") and i + 2 or i + 1
  local q = self:quantities(k, k + 2)[1]
  return self.triggers[k] == true or (q ~= nil and q.b == k)
end
-- "no restriction on speed, reduce 250", "no speed restriction, speed 250", "cancel speed restrictions, 250 knots",
-- "resume normal speed, 250 knots": a speed restriction lifted, then a speed given in one request contradict: which
-- stands is asked. A speed given first ("speed 290, no speed restriction") is flown free of other limits: read.
function G:speed_lifted_and_given()
  local given = {}
  for _, line in ipairs(self.out) do
    local v = line:match("^SPD %S+ M?(%d*%.?%d+)$")
    if v then given[tonumber(v)] = true end
  end
  if not next(given) then return end
  -- (the speed lifted is said with one of these words)
  if not self:said("resume resuming restriction restrictions limit limits restricted") then return end
  -- true when a speed of the request is said after token e, no correction between ("cancel the speed restriction...
  -- no, just maintain 250": the lifting taken back)
  local function given_after(e)
    for _, q in ipairs(self:quantities(e, #self.t + 1)) do
      if given[q.value] and not self:word_in(e, q.b, "@correction just") then return true end
    end
    return false
  end
  for i = 1, #self.t do
    if self:word(i, "resume resuming") and self:word(i + 1, "normal") and self:word(i + 2, "speed")
        and given_after(i + 3) then
      return self:need(string.format("I have %s. Which stands: '%s', or the speed given?",
        table.concat(self.out, " ; "), self:raw(i, i + 3)))
    end
    if self:word(i, "restriction restrictions limit limits restricted") then
      local b = i
      if self:word(b - 1, "speed mach") then
        b = b - 1
      else
        local k = self:word(i + 1, "on") and (self:word(i + 2, "the your its") and i + 3 or i + 2)
        if not (k and self:word(k, "speed mach")) then b = nil end
      end
      if b and self:word(b - 1, "atc") then b = b - 1 end
      -- ("KLM12 no speed restriction": a "no" after a callsign reads as a correction)
      local lift = b and self:word_in(math.max(1, b - 3), b,
        "no cancel cancelled canceled lift lifted remove delete without correction")
      if lift and not self:word_in(math.max(1, b - 4), b, "expect") then
        local e = i + 1
        while e < b do e = e + 1 end
        if self:word(i + 1, "on") then e = (self:word(i + 2, "the your its") and i + 3 or i + 2) + 1 end
        while self.t[e] and self.t[e].kind ~= "punct" and not self:word(e, "and @then_words")
            and not self.triggers[e] do
          e = e + 1
        end
        if not given_after(e) then return end
        local a = b
        while a > 1 and not (self.t[a - 1].kind == "punct" or self.triggers[a - 1]
            or self:has_ref(a - 1, a, "aircraft")) do
          a = a - 1
        end
        if self.t[a - 1] and self.t[a - 1].kind == "punct" and self:word(a - 2, "correction") then a = a - 2 end
        local said = {}
        for x = a, e - 1 do
          if self.t[x].kind ~= "punct" then said[#said + 1] = self:word(x, "correction") and "no" or self.t[x].raw end
        end
        return self:need(string.format("I have %s. Which stands: '%s', or the speed given?",
          table.concat(self.out, " ; "), table.concat(said, " ")))
      end
    end
  end
end

-- "is KLM12 at FL300?", "what's RYR2BA at FL300", "are X and Y level at 240?", "does X climb FL340?": a clause opening
-- with a word of lexicon.state_question and the aircraft it asks about (joined by "and") asks about their state, never
-- instructs them. Said alone (to its "?" and the end) it is read as POS of each; with anything else after it, or an
-- instruction of the request naming one of them outside it, it is asked.
-- (the commands a question's values are misread as: G:state_question)
-- (DEST, ORIG, DIRECT, ADDWPT with a place: "is KLM12 going to EHAM?" sets nothing; alone, a destination or
-- origin asked is shown by DEST or ORIG with the aircraft alone, the rest by POS, whose reply holds the selected
-- altitude, heading, speeds and active waypoint)
G.asked_values = { ALT = true, SPD = true, HDG = true, VS = true, DEST = true, ORIG = true, DIRECT = true,
  ADDWPT = true }
G.asked_shown = { DEST = "DEST", ORIG = "ORIG" }
G.question_opens, G.question_with_is = set_of(lexicon.state_question.opens), set_of(lexicon.state_question.with_is)
-- True when the "is" at i follows a self-correction marker (lexicon.self_correction.markers, one word; a mark or
-- fillers between) in a clause with no "?": "..., no wait, I was wrong, is the Wizz not the easyJet" restates which
-- aircraft is meant ("it is", Italian "è"), no question.
function G.restated_after_marker(self, i)
  if not self:word(i, "is") then return false end
  local p = i - 1
  while p >= 1 and (self.t[p].kind == "punct" or self.t[p].filler) do p = p - 1 end
  if p < 1 or p == i - 1 or not (SC_MARKERS[self.t[p].text] or self:word(p, "@correction")) then return false end
  local e = i
  while self.t[e] and not (self.t[e].kind == "punct" and self.t[e].text ~= ",") do e = e + 1 end
  return not (self.t[e] and self.t[e].text == "?")
end
-- "VJC162 already reach FL180 or not yet?", "Singapore 172 already pass LATHA or not yet sir?", "HVN213 is LNAV on or
-- not?": Vietnamese and Thai English asks about an aircraft's state with the statement's word order and "or not" (or
-- "or not yet") closing it. One aircraft that exists opens the request (fillers before it), then "already", "still"
-- or a copula ("is", "are"), at most six words with no mark between them, "or not" and "yet" or not, then only
-- courtesy ("sir", "krub") to a "?" or the end: the whole request asks its state, shown by POS (true, self.out set);
-- anything else said with it is no such question (false).
-- Vietnamese and Thai English joins a condition to the instruction that waits for it with "then" ("after reach then
-- speed 300", "after speed reach 260 then descend FL200", "when pass BOKAK then descend"): a condition word ("after",
-- "when", "once") opening a clause, then one to five words with no mark that hold a verb of reaching or passing, then
-- "then": the "then" is the comma that ends the condition ("after reach, speed 300"). A bare "reach" there after
-- "speed", "level", "it" or straight after the condition word is "reaches" / "reaching" (never the callsign Reach:
-- "after speed reach 260" names no aircraft RCH260).
G.condition_then_verbs = { reach = true, reaches = true, reached = true, reaching = true, pass = true, passes = true,
  passed = true, passing = true, cross = true, crossed = true, crossing = true }
function G.condition_then(text)
  local lower = text:lower()
  if not lower:find("then", 1, true) then return text end
  if not (lower:find("after", 1, true) or lower:find("when", 1, true) or lower:find("once", 1, true)) then return text end
  local toks = bare_words(text)
  local put, done = tokens.splicer(text)
  for k, t in ipairs(toks) do
    if (t.bare == "after" or t.bare == "when" or t.bare == "once") and not t.raw:match("%p$")
        and (k == 1 or toks[k - 1].raw:match("[,;.!]$")) then
      local j, verb = k + 1, nil
      while toks[j] and j <= k + 6 and toks[j].bare ~= "then" and not toks[j].raw:match("%p$") do
        if G.condition_then_verbs[toks[j].bare] then verb = verb or j end
        j = j + 1
      end
      if verb and toks[j] and toks[j].bare == "then" and j > k + 1 and toks[j + 1] then
        local v = toks[verb]
        if v.bare == "reach" and (verb == k + 1 or toks[verb - 1].bare == "speed" or toks[verb - 1].bare == "level"
            or toks[verb - 1].bare == "it") then
          put(v.at, verb == k + 1 and "reaching" or "reaches", v.e)
        end
        put(toks[j - 1].e, ",", toks[j].e)
      end
    end
  end
  return done()
end
-- Indonesian and Malay English says a condition with "if", and the state waited for with "already" or a bare
-- "reach" ("if it reach FL250 then reduce speed 250", "when the speed already 230 descend FL150", "if already FL330
-- then Mach .78", "when speed reach 250 climb FL350"): a condition word ("if", "when", "once", "after") opening a
-- clause (first, after a mark, or after a word ending in a digit: the callsign's), at most three words of its subject
-- (G.condition_subject), then "already" or "reach" and a value (digits, "FL...", "flight", "mach"). There "already" is
-- "is" after "speed", "level" or "altitude" ("speed already 230": is 230) and "at" otherwise ("already FL330"), "reach"
-- is "reaches" ("reaching" straight after the condition word, and only before a level there: "when Reach 250" is a
-- callsign), and "if" is "when" (also before "reaches", "reached", "reaching", kept as said). Anything else ("if able", "if it is possible", "already at FL300?") stays as said.
G.condition_subject = { it = true, the = true, its = true, speed = true, level = true, altitude = true }
G.condition_copula_nouns = { speed = true, level = true, altitude = true }
-- (the verb said in its English form, kept: only "if" before it is read, "if it reaches FL250 then ...")
G.condition_reached = { reaches = true, reached = true, reaching = true }
function G.condition_copula(text)
  local lower = text:lower()
  if not (lower:find("already", 1, true) or lower:find("reach", 1, true)) then return text end
  local toks = bare_words(text)
  local put, done = tokens.splicer(text)
  for k, t in ipairs(toks) do
    if (t.bare == "if" or t.bare == "when" or t.bare == "once" or t.bare == "after") and not t.raw:match("%p$")
        and (k == 1 or toks[k - 1].raw:match("[,;.!]$") or toks[k - 1].raw:match("%d$")) then
      local j = k + 1
      while toks[j] and j <= k + 3 and G.condition_subject[toks[j].bare] and not toks[j].raw:match("%p$") do j = j + 1 end
      local v, nx = toks[j], toks[j + 1]
      local level = nx and (nx.bare:match("^fl%d*$") or nx.bare == "flight")
      if v and nx and not v.raw:match("%p$") and (nx.raw:match("^%d") or level or nx.bare == "mach")
          and (v.bare == "already" or G.condition_reached[v.bare] or (v.bare == "reach" and (j > k + 1 or level))) then
        if t.bare == "if" then put(t.at, "when", t.e) end
        if G.condition_reached[v.bare] then goto said end
        local reach = j == k + 1 and "reaching" or "reaches"
        local copula = j > k + 1 and G.condition_copula_nouns[toks[j - 1].bare] and "is" or "at"
        put(v.at, v.bare == "reach" and reach or copula, v.e)
      end
      ::said::
    end
  end
  return done()
end
-- True when the tokens from k to the end are thanks and courtesy only ("thank you", "thank you very much sir",
-- "thanks krub", "sir"), marks and fillers between, at least one word that thanks or addresses.
-- (G.thanks_words[w]: true for a word that thanks or addresses, "between" for one said only with them)
G.thanks_words = { thank = true, thanks = true, you = "between", very = "between", much = "between", sir = true,
  madam = true, krub = true, krab = true, khrab = true, khrap = true, ka = true, kha = true, so = "between",
  lot = "between", a = "between" }
function G.thanks_to_end(self, k)
  local thanked = false
  for x = k, #self.t do
    local t = self.t[x]
    if t.kind == "word" and G.thanks_words[self.words[x] or ""] == true then thanked = true end
    if not (t.kind == "punct" or t.filler or (t.kind == "word" and G.thanks_words[self.words[x] or ""])) then
      return false
    end
  end
  return thanked
end
G.not_yet_openers = { already = true, still = true, is = true, are = true, ["'s"] = true }
function G:not_yet_question()
  if not self:said("not") then return false end
  local e = #self.t
  if self.t[e] and self.t[e].kind == "punct" then
    if self.t[e].text ~= "?" then return false end
    e = e - 1
  end
  while e > 0 and (self.t[e].filler or self:word(e, "sir madam krub krab khrab khrap ka kha please")) do e = e - 1 end
  if self:word(e, "yet") then e = e - 1 end
  if not (self:word(e, "not") and self:word(e - 1, "or")) then return false end
  local b = self:skip_fillers(1)
  local r = self:refs_in(b, b + 1, "aircraft")[1]
  if not (r and r.b == b and r.exists) then return false end
  local k = self:skip_fillers(r.e)
  if not G.not_yet_openers[self.words[k] or ""] then return false end
  if e - 1 - (k + 1) > 6 or e - 1 <= k + 1 then return false end
  for x = k + 1, e - 2 do
    if self.t[x].kind == "punct" or #self:refs_in(x, x + 1, "aircraft") > 0 and self:refs_in(x, x + 1, "aircraft")[1].b == x then
      return false
    end
  end
  self.out = { "POS " .. r.name:upper() }
  for x = 1, #self.t do self.noted[x] = true end
  for _, q in ipairs(self:quantities(1, #self.t + 1)) do self:take(q) end
  return true
end
function G:state_question()
  -- (a question opens with a word of lexicon.state_question: none said, none asked)
  if not (self:said(G.question_opens) or self:said(G.question_with_is)) then return end
  for i = 1, #self.t do
    local prev = self.t[i - 1]
    local opens = (not prev or prev.kind == "punct" or prev.filler or self:word(i - 1, "and @then_words"))
      and not G.restated_after_marker(self, i)
    local k = opens and ((self:word(i, G.question_with_is) and self:word(i + 1, self:word(i, "why where")
        and "is are" or "is about") and i + 2)
      or (self:word(i, G.question_opens) and i + 1)) or nil
    if k and self:word(k, "that the") then k = k + 1 end
    -- ("how about CXA8301 turn right 30 degrees", "how about let CCA1831 speed 300 knots": "how about" before an
    -- aircraft, "let" or "we let" between or not, and an instruction word straight after it suggests that
    -- instruction: given, no question)
    if k and self:word(i, "how") and self:word(i + 1, "about") then
      local a = k
      if self:word(a, "we") then a = a + 1 end
      if self:word(a, "let have make") then a = a + 1 end
      local x = self:refs_in(a, a + 1, "aircraft")[1]
      local j = x and self:skip_fillers(x.e)
      local valued = j and self:word(j, "speed heading altitude level mach") and (self:quantities(j + 1, j + 3)[1] or {}).b
      if x and x.b == a and x.exists and (self.triggers[j] or self:intent_at(j) or valued == j + 1) then
        self.noted[i], self.noted[i + 1] = true, true
        k = nil
      end
    end
    local r = k and self:refs_in(k, k + 1, "aircraft")[1]
    -- (the aircraft called before the question, asked about as "you")
    local called = k and self:word(k, "you") and self:refs_in(1, i, "aircraft")
    called = called and called[#called]
    if called and not (called.exists and called.b == self:skip_fillers(1) and self:skip_fillers(called.e) == i) then
      called = nil
    end
    -- (or called at the end of it: "are you at FL300, KLM12?")
    local called_first = called and true or false
    if k and not called and self:word(k, "you") then
      local e = k
      while self.t[e] and not (self.t[e].kind == "punct" and self.t[e].text ~= ",") do e = e + 1 end
      local last = self:refs_in(k, e, "aircraft")
      last = #last == 1 and last[1]
      called = last and last.exists and self:skip_fillers(last.e) >= e and last or nil
    end
    if (r and r.b == k and r.exists) or called then
      local ids, seen = {}, {}
      if called then
        ids[1], seen[called.name:upper()], k = called.name:upper(), true, k + 1
      end
      while not called and r and r.b == k and r.exists do
        if not seen[r.name:upper()] then ids[#ids + 1], seen[r.name:upper()] = r.name:upper(), true end
        k = r.e
        if self:word(k, "and") then k = k + 1 end
        r = self:refs_in(k, k + 1, "aircraft")[1]
      end
      local e = k
      while self.t[e] and not (self.t[e].kind == "punct" and self.t[e].text ~= ",") do
        -- (a comma before an instruction's word, "and" or "then" at most between, ends the question: "what is
        -- X's altitude now, climb FL300" asks nothing of FL300)
        if self.t[e].text == "," then
          local v = self:skip_fillers(e + 1)
          while self:word(v, "and @then_words") do v = self:skip_fillers(v + 1) end
          if self:intent_at(v) then break end
        end
        e = e + 1
      end
      local rest = self:skip_fillers(e)
      -- (a reason asked, "why is X climbing to FL300?", is no state POS shows: asked)
      local alone = (called_first or i == self:skip_fillers(1)) and rest > #self.t and not self:word(i, "why")
      local instructed, shown = false, {}
      for _, line in ipairs(self.out) do
        local name, cid, arg = line:match("^(%u+) (%S+)%s*(%S*)")
        local asked = G.asked_values[name] and seen[cid:upper()] == true
          and (arg ~= "" or not G.asked_shown[name])
        instructed = instructed or asked
        if asked and G.asked_shown[name] then shown[cid:upper()] = G.asked_shown[name] end
      end
      -- (what a question reads that is no value's instruction stands: "what's X's destination?" DEST X)
      if instructed and alone then
        self.out = {}
        for _, id in ipairs(ids) do self.out[#self.out + 1] = (shown[id] or "POS") .. " " .. id end
        for x = 1, #self.t do self.noted[x] = true end
        for _, q in ipairs(self:quantities(1, #self.t + 1)) do self:take(q) end
        return
      elseif instructed then
        return self:need(string.format("'%s' asks about %s: a question, no instruction. What should %s do?",
          self:raw(i, e), table.concat(ids, " and "), table.concat(ids, " and ")))
      end
    end
  end
end

-- "KLM12 direct SPY heading 200", "direct SPY, then heading 200": a heading sent now after a direct-to for the same
-- aircraft takes it off the direct at once (HDG ends LNAV), so the direct is lost: which one is meant, or where the
-- heading starts ("after SPY heading 200", AT ... DO), is asked. A heading before the direct, "heading 230 then direct
-- LORNI", is flown until the direct is given, as said.
function G:heading_after_direct()
  local direct = {}
  for _, line in ipairs(self.out) do
    local id, wp = line:match("^DIRECT (%S+) (%S+)$")
    if id then direct[id] = wp end
    local hid, hdg = line:match("^HDG (%S+) (%d+)")
    if hid and direct[hid] then
      return self:need(string.format("A heading after the direct-to takes %s off it at once: should %s fly direct %s, "
        .. "or heading %s? To fly the heading from %s on, please say \"after %s heading %s\".", hid, hid, direct[hid],
        hdg, direct[hid], direct[hid], hdg))
    end
  end
end

-- "KLM12 climbing FL300?", "DLH34 is reducing speed 250?", "KLM12 now descending to FL200?": one clause, its
-- aircraft named first, a verb's "-ing" form after it ("is", "are", "now", "still", "you are" between at most) and "?"
-- closing it asks what the aircraft does (a typed statement said as a question), no instruction: asked, never sent.
G.participles = set_of({ "climbing", "descending", "turning", "reducing", "increasing", "maintaining", "flying",
  "proceeding", "going", "holding", "slowing", "accelerating", "decelerating" })
-- "KLM12 add SPY, and FL200", "add SPY and then 9000 feet": a level left unread (self.leftover) after a waypoint added
-- to a route (the one command, an ADDWPT with no constraint) is the waypoint's altitude constraint or a level to fly
-- now: asked, naming both (self.ask set).
function G:addwpt_level_left()
  if #self.out ~= 1 then return end
  local id, wp = self.out[1]:match("^ADDWPT (%S+) (%S+)$")
  if not id then return end
  local left = self.leftover:lower()
  for _, q in ipairs(self:quantities(1, #self.t + 1)) do
    if (q.kind == "alt" or (q.kind == "plain" and q.value >= 1000 and q.value % 100 == 0))
        and left:find(self:raw(q.b, q.e):lower(), 1, true) then
      local lv = handlers.format.alt(q.value, q.kind == "alt" and q.fl)
      self.ask = string.format("I have ADDWPT %s %s. Is '%s' the altitude to cross %s at (ADDWPT %s %s %s), or a "
        .. "level to fly now (ALT %s %s)?", id, wp, self.leftover, wp, id, wp, lv, id, lv)
      return
    end
  end
end

-- "klm12 -> FL250 (already?)", "dlh4 hdg 270 (clear of the klm?)": a remark in brackets that holds a question
-- mark, said with instructions (`said`: the request as typed), doubts them: asked, nothing sent.
function G:bracket_question(said)
  if #self.out == 0 then return end
  local remark = said:match("%(([^()]*%?[^()]*)%)")
  if not remark then return end
  return self:need(string.format("I have %s, but the remark '(%s)' asks something about it: no instruction sent. "
    .. "If it should run, please say it without the question.", table.concat(self.out, " ; "), remark))
end

-- So does an instruction's base form there, or its value's name with the value ("KLM12 climb FL300?", "DLH34, turn
-- left heading 180?", "KLM12 heading 180?", "KLM12 is cleared FL300?", and the verb before the aircraft: "climb KLM12
-- FL300?"): is it allowed, should it? A question, asked, never sent ("please" in it, or a modal before it, "could
-- KLM12 climb ...?", is a request, read).
G.instruction_bases = set_of({ "climb", "descend", "turn", "reduce", "increase", "maintain", "fly", "proceed", "go",
  "hold", "slow", "accelerate", "decelerate", "expedite", "direct", "heading", "speed", "level", "altitude", "fl",
  "flight", "mach", "set", "change" })
function G:participle_question()
  if #self.out == 0 then return end
  local last = #self.t
  while last > 0 and self.t[last].filler do last = last - 1 end
  if not (self.t[last] and self.t[last].text == "?") then return end
  for x = 1, last - 1 do
    if self.t[x].kind == "punct" and self.t[x].text ~= "," then return end
  end
  if self:said("please") then return end
  -- (a question word or a modal in it asks something else, or asks politely: "EVA12 speed 250, heading what?",
  -- "Thai 420 turn right heading 120, can or not?")
  local modal = self:said("what how which where why when who can could would will may might ok okay possible able")
  local first = self:skip_fillers(1)
  if not modal and self.t[first] and G.instruction_bases[self.t[first].text] and not self:has_ref(first, first + 1) then
    local r = self:refs_in(first + 1, first + 2, "aircraft")[1]
    if r and r.b == first + 1 and r.exists
        and (#self:quantities(r.e, last) > 0 or #self:refs_in(r.e, last, "waypoint") > 0) then
      return self:need(string.format("'%s?' is an instruction said as a question (is it allowed? should %s do "
        .. "it?): no instruction sent. If %s should do it, please say it without the question mark.",
        (self:raw(first, last):gsub(" ([,.;:])", "%1")), r.name:upper(), r.name:upper()))
    end
  end
  local r = self:refs_in(first, first + 1, "aircraft")[1]
  if not (r and r.b == first and r.exists) then return end
  local k = self:skip_fillers(r.e)
  -- (several aircraft joined, "klm12 and dlh4 climb FL260?", "klm12 + dlh4 -> FL250?": the same question to each)
  local names = { r.name:upper() }
  while self.t[k] do
    local j = (self:word(k, "and") or self.t[k].text == "&" or self.t[k].text == "+") and self:skip_fillers(k + 1)
      or (k > r.e and k) -- ("and" may be a filler, skipped)
    local r2 = j and self:refs_in(j, j + 1, "aircraft")[1]
    if not (r2 and r2.exists and r2.b == j) then break end
    names[#names + 1] = r2.name:upper()
    k = self:skip_fillers(r2.e)
  end
  if self.t[k] and self.t[k].text == "," then k = self:skip_fillers(k + 1) end
  if self:word(k, "you") and self:word(k + 1, "are") then k = k + 2 end
  -- ("klm12 -> FL250?": the arrow before a level is "to", the level's instruction)
  local base = self.t[k] and (G.instruction_bases[self.t[k].text]
    or (self:word(k, "to") and #self:quantities(k + 1, last) > 0))
  while self:word(k, "is are now still currently") do k = k + 1 end
  -- ("KLM12 cleared FL300?", "KLM12 is cleared FL300?": the clearance asked about, never given)
  base = base or self:word(k, "cleared")
  -- (a value or a place after it: "KLM12 heading?" asks its state, shown)
  if base and not modal and (#self:quantities(k, last) > 0 or #self:refs_in(k, last, "waypoint") > 0) then
    local who = table.concat(names, " and ")
    return self:need(string.format("'%s?' is an instruction said as a question (is it allowed? should %s do it?): "
      .. "no instruction sent. If %s should do it, please say it without the question mark.",
      (self:raw(first, last):gsub(" ([,.;:])", "%1")), who, who))
  end
  if not (self.t[k] and G.participles[self.t[k].text]) then return end
  return self:need(string.format("'%s' asks what %s is doing: a question, no instruction. If %s should do it, "
    .. "please say it without the question mark.", self:raw(first, last), r.name:upper(), r.name:upper()))
end

-- "KLM12 climb FL340, show me both", "..., then display KLM12", "..., let me see both": a verb of showing that no
-- command was read from, said after an instruction, is never dropped: the aircraft named alone after it (and only
-- those, joined by "and", to the end of the request) are shown where they are (POS); anything else ("both", "them") is
-- asked.
-- (a request that already shows something, "route please, show it", "show me the constraints X has at Y", is read as
-- it is; so is a noun, "off the display")
-- (a conflict setting's command alone, "RESO", "ASAS", shows that setting: "which resolution method is selected
-- now, can you show?")
G.showing = { POS = true, LISTRTE = true, TRAIL = true }
G.setting_shown = { RESO = true, ASAS = true, ZONER = true, ZONEDH = true, DTLOOK = true, RFACH = true, RFACV = true,
  CDMETHOD = true }
function G:shown_after_instruction()
  if #self.out == 0 then return end
  for _, line in ipairs(self.out) do
    local name = line:match("^(%u+)")
    if G.showing[name] or (name == "AT" and line:match("^AT %S+ %S+$")) or (G.setting_shown[name] and line == name) then
      return
    end
  end
  if not self:said("show display see") then return end  -- (the verbs of showing it reads)
  local explained = self.explained or {}
  for i = 1, #self.t do
    if (self:word(i, "show display") or (self:word(i, "see") and self:word(i - 1, "me us"))) and not self.u:used(i)
        and not self.triggers[i] and not explained[i] and not self.noted[i] and not self:in_reason(i)
        and not self:word(i - 1, "the a on off of to") then
      local k = self:skip_fillers(self:word(i + 1, "me us") and i + 2 or i + 1)
      local ids = {}
      while true do
        local r = self:refs_in(k, k + 1, "aircraft")[1]
        if not (r and r.exists and r.b == k) then break end
        ids[#ids + 1] = r.name:upper()
        k = self:skip_fillers(r.e)
        if self:word(k, "and") then k = self:skip_fillers(k + 1) end
      end
      if #ids > 0 and k > #self.t then
        for _, id in ipairs(ids) do self.out[#self.out + 1] = "POS " .. id end
        for x = i, #self.t do self.noted[x] = true end
        return
      end
      -- (a command read from the words after it, "show trails", "show me its position", is what it shows)
      local e, read = i + 1, false
      while self.t[e] and self.t[e].kind ~= "punct" and not self:word(e, "@then_words") do
        read = read or self.triggers[e] == true
        e = e + 1
      end
      if not read then
        return self:need(string.format("I have %s. Which aircraft should '%s' show? Please name them.",
          table.concat(self.out, " ; "), self:raw(i, e)))
      end
    end
  end
end
-- "KLM12 speed 250 then resume", "..., and continue": "resume" or "continue" closing the request with nothing of its
-- own (a courtesy word at most), read as OP, straight after an aircraft's instruction (no pause before it, the aircraft
-- neither moved, created nor deleted: G.sim_handling) most likely tells that aircraft to resume something (its own
-- navigation, its normal speed): asked, naming the aircraft. "..., then resume the sim" stays OP.
G.sim_handling = { DEL = true, MOVE = true, CRE = true }
-- "fast forward ten minutes. Go.", "FF 10 min and run": OP after FF, no HOLD between, would end the fast forward at
-- once (OP clears fast time and sets DTMULT to 1). FF itself runs the simulation and returns it to real time when its
-- duration has passed, so after an FF of a duration the OP is dropped; after one of no duration ("fast forward, then
-- back to real time") when real time resumes is unclear: asked.
function G:op_after_ff()
  local ff
  for c, line in ipairs(self.out) do
    if line:match("^FF") then ff = c
    elseif line == "HOLD" then ff = nil
    elseif line == "OP" and ff then
      if self.out[ff] == "FF" then
        return self:need(string.format("I have %s. The fast forward has no duration, and OP after it ends it at once. "
          .. "How long should it run before real time resumes?", table.concat(self.out, " ; ")))
      end
      table.remove(self.out, c)
      return self:op_after_ff()
    end
  end
end
function G:resume_after_instruction()
  local op
  for c, line in ipairs(self.out) do
    if line == "OP" then op = c end
  end
  if not op then return end
  local id
  for c = 1, op - 1 do
    local name, cid = self.out[c]:match("^(%u+) (%S+)")
    -- (a pause before it is what resumes: "pause, X descend FL270, resume"; so after an aircraft placed or removed)
    if self.out[c] == "HOLD" then return end
    id = cid and self:state(cid) and not G.sim_handling[name] and cid or nil
  end
  if not id then return end
  for i = #self.t, 1, -1 do
    local t = self.t[i]
    if self:word(i, "resume continue") then
      local k = i + 1
      while self.t[k] and (self.t[k].kind == "punct" or self.t[k].filler or self:word(k, "please now")) do k = k + 1 end
      if k <= #self.t then return end
      local others = {}
      for c, line in ipairs(self.out) do
        if c ~= op then others[#others + 1] = line end
      end
      return self:need(string.format("I have %s. Should %s resume something of its own (its navigation, its normal "
        .. "speed), or the simulation resume? Please say which.", table.concat(others, " ; "), id))
    elseif not (t.kind == "punct" or t.filler or self:word(i, "please now")) then
      return
    end
  end
end
-- (G.bare_left[w]: the kind of a word of lexicon.accounted.bare_asked, "noted" for one of a bare phrase of
-- lexicon.not_simulated, left here when said before the instruction: G:said_bare; G.bare_asks[kind][what]: true
-- when a word of that kind said bare after `what`, "start", "aircraft" or "value", is asked)
G.bare_left = {}
for kind, words in pairs(ACCOUNTED.bare_asked) do
  for _, w in ipairs(words) do G.bare_left[w] = kind end
end
for _, c in ipairs(lexicon.not_simulated) do
  for w in (c.bare and c.words or ""):gmatch("%S+") do G.bare_left[w] = G.bare_left[w] or "noted" end
end
G.bare_asks = { place = { start = true, aircraft = true, value = true }, meaning = { start = true, aircraft = true,
  value = true }, report = { aircraft = true, value = true, place = true, closing = true },
  noun = { aircraft = true, value = true, place = true }, area = { aircraft = true, value = true },
  after = { value = true },
  put_off = { value = true, place = true, closing = true }, noted = { aircraft = true } }
G.bare_beside_place = { report = true, noun = true, area = true, put_off = true }
-- True when the word at i, of G.bare_left, is said bare where its kind is asked (G.bare_asks); a word other than a
-- place's straight before an instruction word is its manner ("continue climb", "cleared descend"), as
-- is "hold" opening the request ("hold KLM12 climb FL300": the simulation's hold, asked)
-- (a word of lexicon.aside.put_off_later closing the request in a clause, after its comma, "and" or "then", that holds a
-- word a command read, with an aircraft named, puts that command off too: "KLM12 climb FL190, we should pause
-- soon", "..., delete it shortly" are asked)
function G:bare_asked(i)
  local kind = G.bare_left[self.t[i].text]
  if self:word(i, COMMENTARY.put_off_later_set) and self:has_ref(1, #self.t + 1, "aircraft") then
    local n = i + 1
    while self.t[n] and self.t[n].kind == "punct" do n = n + 1 end
    local k = i - 1
    while n > #self.t and k >= 1 and self.t[k].kind ~= "punct" and not self:word(k, "and then") do
      if self.triggers[k] then return true end
      k = k - 1
    end
  end
  local what = self:said_bare(i, kind ~= "place")
  return what and (G.bare_asks[kind][what] or (kind == "noted" and what == "start" and self:word(i, "hold"))) or false
end
function G:unaccounted()
  -- the words no list explains, and the negations and conditions: only these need the parse's account
  local explained, said, ignored = self.explained or {}, {}, self.world.ignored or {}
  -- (an airline's name said bare, "we want Finnair lower", when no command names an aircraft of it, none
  -- creates one, "a KLM Cityhopper Embraer", no word before it makes it other traffic, "for Speedbird", and
  -- no correction after it takes it back, "United correction Southwest six eighty six")
  local function airline_left(i)
    -- (in lower case too where the name is no English word: "climb FL300 el al", "... lufthansa")
    local icao, e = self:airline_at(i)
    if not icao or self.t[i].kind ~= "word" or self:word(i - 1, "@airline_context @aircraft_context for")
        or not (airline_bare(self, i) and self.t[i].raw:match("^%u%l")
          or (not self:word(i - 1, CM_DETERMINERS) and (e - i > 1 or G.name_words[self.t[i].text]))) then
      return false
    end
    if self:word(self:skip_fillers(e, false), "@correction") then return false end
    for _, c in ipairs(self.out) do
      if c:find("%f[%w]" .. icao .. "%w") or c:match("^CRE ") then return false end
    end
    return true
  end
  -- ("at x q z descend 8000", "cross j v x at FL190": a place spelled letter by letter that no part of the
  -- parse read, two single letters in a row or more after a word that names a place, is asked, its letters
  -- quoted: the instruction it anchors never goes alone)
  local function letter(k)
    local x = self.t[k]
    return x and x.kind == "word" and #x.text == 1 and x.text:match("^%a$") and not explained[k] and not self.noted[k]
      and not self.u:used(k)
  end
  for i = 1, #self.t do
    local b = letter(i) and letter(i + 1) and not letter(i - 1) and i - 1
    while b and self.t[b] and self.t[b].filler do b = b - 1 end
    if b and self:word(b, "at after over via cross crossing abeam direct from") then
      local e = i
      while letter(e) do e = e + 1 end
      self.leftover = self:raw(i, e)
      return
    end
  end
  -- ("KLM12 no need to climb to FL240", "no need for the descent"): what is not needed is no instruction; "no
  -- need" is asked wherever it stands outside a reason (G:said's guard before the scans for "no")
  local no_said = self:said("no")
  for i = 1, no_said and #self.t or 0 do
    local t = self.t[i]
    if t.text == "no" and self:word(i + 1, "need needs") and self:word(i + 2, "to for") and not explained[i]
        and not self.noted[i] and not self:in_reason(i) then
      self.leftover = self:raw(i, i + 2)
      return
    end
  end
  -- ("PRF441 no descend FL090", "KLM12 heading 100 no turn left heading 120", "no left turn"): "no" straight before
  -- an instruction's verb or noun (lexicon.refusable_verbs; fillers or a turn's side between, no comma) may refuse
  -- it or take back what came before: asked, naming both readings, never read as either ("no, descend" and
  -- "negative descend" are corrections, and so is "wait no descend" straight after a value, m:marker_after_value)
  for i = 1, no_said and #self.t or 0 do
    local t = self.t[i]
    local v = t.text == "no" and not (self:word(i - 1, "wait") and self:marker_after_value(i)) and i + 1
    while v and self.t[v] and (self.t[v].filler or self:word(v, "@left @right")) do v = v + 1 end
    if v and self:word(v, "@refusable_verbs") and not self.noted[i] and not self:in_reason(i) then
      local said = self:raw(i + 1, v + 1)
      self:need(string.format("%sIs 'no %s' a refusal (do not), or a correction ('no, %s')? Please say it again.",
        #self.out > 0 and "I have " .. table.concat(self.out, " ; ") .. ". " or "", said, said))
      return
    end
  end
  -- ("KLM12 no higher than FL300", "not lower than 8000 feet", "no higher FL300"): "no" or "not" before a level's
  -- comparative bounds the level, it clears none, and squawk keeps no level limit: asked, never flown as the level
  -- ("climb FL300, no higher" bounds nothing of its own: no level after it; G:said's guard before the scan)
  for i = 1, self:said("higher lower above below") and #self.t or 0 do
    local t = self.t[i]
    local v = (t.text == "no" or t.text == "not") and self:word(i + 1, "higher lower above below") and i + 2
    if v and self:word(v, "than") then v = v + 1 end
    local q = v and self:quantities(v, v + 6)[1]
    if q and q.kind == "alt" and q.b == v and not self:in_reason(i) then
      self:need(string.format("Is '%s' a level to fly, or a limit? squawk keeps no level limit: please say the "
        .. "level to fly.", self:raw(i, q.e)))
      return
    end
  end
  -- ("KLM12 maintain at least FL200", "at most FL300"): "at least" or "at most" straight before a level that was
  -- drafted as the level to fly bounds it, the same (a rate or a zone's height "at least" is read by its kind)
  for i = 1, self:said("least most") and #self.t or 0 do
    local q = self:word(i, "at") and self:word(i + 1, "least most") and self:quantities(i + 2, i + 8)[1]
    if q and q.kind == "alt" and q.b == i + 2 and not self:in_reason(i) then
      local level = q.fl and string.format("FL%03d", math.floor(q.value / 100 + 0.5))
        or string.format("%d", math.floor(q.value + 0.5))
      for _, line in ipairs(self.out) do
        local drafted = line:match("^ALT %S+ (%S+)")
        if drafted and (drafted == level or drafted:gsub("^FL0*", "FL") == level:gsub("^FL0*", "FL")) then
          self:need(string.format("Is '%s' a level to fly, or a limit? squawk keeps no level limit: please say the "
            .. "level to fly.", self:raw(i, q.e)))
          return
        end
      end
    end
  end
  -- ("climb to four thousand and a half": a fraction said after "and" that no value read is asked, never dropped;
  -- "and a half-height of 1000 feet" names the protected zone's half height, no fraction)
  local function fraction_left(i)
    return self:word(i, "half quarter quarters") and self:word(i - 1, "a one three") and self:word(i - 2, "and")
      and not (self:word(i, "half") and self:word(i + 1, "height"))
  end
  -- ("heading 240 and mach,76", "foo.76"): a word with a digit and a mark inside it is no name and no value
  -- the lexer read; unexplained, it is asked about
  local function glued_value(i)
    local w = self.t[i].text
    if not (w:find("%d") and w:find("[^%w]")) then return false end
    for _, r in ipairs(self.refs) do
      if r.b <= i and r.e > i then return false end
    end
    return true
  end
  -- ("climb FL250, hundred", "radius 5 miles, thousand": a word of scale after an instruction that no value or
  -- name holds counts nothing the parse read: asked; one before any instruction is callsign noise, and one after
  -- "or" and a value is that value misheard, "nine or thousand", as G:alternatives reads it)
  local held  -- (the tokens a value or name holds, gathered at the first word of scale)
  local function scale_left(i)
    if not G.scale_words[self.t[i].text] then return false end
    if not held then
      held = {}
      for _, list in ipairs({ self:quantities(1, #self.t + 1), self.refs }) do
        for _, x in ipairs(list) do
          for k = x.b, x.e - 1 do held[k] = true end
        end
      end
    end
    return not held[i] and not (self:word(i - 1, "or") and held[i - 2])
      and self:instruction_before(i)
  end
  -- (a word said bare is asked beside value instructions only, which read no place or noun: G.bare_left; beside
  -- any other command, when it is no command's word, G.bare_beside_place)
  local values_only, places = #self.out > 0, false
  for _, c in ipairs(self.out) do
    local direct = c:match("^DIRECT ") ~= nil
    places = places or direct
    values_only = values_only and (direct or (c:match("^ALT ") or c:match("^SPD ") or c:match("^HDG ")
      or c:match("^VS ")) ~= nil)
  end
  for i = 1, #self.t do
    local t = self.t[i]
    if t.kind == "word" and not t.filler and (not t.number_word or scale_left(i))
        and not explained[i] and not self.noted[i] and not self.u:used(i) and not ignored[t.text]
        and (scale_left(i) or (t.text:match("^%a[%a'%-/]*$") and (MEANING[t.text] or COMMAND_ONLY[t.text] or MANNER[t.text] or not (known_word(t.text) or self:airline_word(i) or self:place_particle(i))
          or airline_left(i) or fraction_left(i) or (lexicon.clock_verbs[t.text] and not self.triggers[i] and not self:resumes_instruction(i))))
          or glued_value(i) or (G.bare_left[t.text] and (values_only and not places
            or G.bare_beside_place[G.bare_left[t.text]]) and not self.triggers[i] and self:bare_asked(i))) then
      said[#said + 1] = i
    end
  end
  if #said == 0 then return end
  local issued, kinds = self:issued()
  local inside = self:explained_spans(issued, kinds)
  for _, i in ipairs(said) do
    local t = self.t[i]
    if not inside[i] and not issued[COMMAND_ONLY[t.text] or t.text] and not self:in_reason(i)
        and not (MANNER[t.text] and self:rate_issued())
        and not (MEANING[t.text] and self:meaning_carried(i, kinds)) then
      if G.bare_left[t.text] == "place" and values_only then
        self:need(string.format("I have %s. Which place goes with '%s'? Please say it with the place.",
          table.concat(self.out, " ; "), t.raw))
        return
      end
      self.leftover = t.raw
      if not MEANING[t.text] then self.ignorable = t.text end
      return
    end
  end
end

-- "cross macy at FL240", "after camron descend and maintain 7000", "250 knots until robber" (MACEY, CAMRN, ROBER
-- on the route of the aircraft named): a word no part of the parse read, straight after a place's slot
-- (G.heard_slots), that sounds like a waypoint of that route (G.heard_route_name) is a name heard: confirmed
-- ("Did you mean MACEY? I heard 'macy'."), never substituted and never dropped; "yes" reads it as that waypoint
-- (G.confirmed_route_places).
function G:heard_route_place()
  local explained, route = self.explained or {}, {}
  for _, r in ipairs(self.refs) do
    local a = r.kind == "aircraft" and r.exists and self:state(r.name)
    for _, w in ipairs(a and a.route or {}) do route[#route + 1] = w end
  end
  for k = 2, #route > 0 and #self.t or 0 do
    local t = self.t[k]
    local held = false
    for _, r in ipairs(self.refs) do held = held or (r.b <= k and k < r.e) end
    if t.kind == "word" and G.heard_slots[self.words[k - 1] or ""] and not explained[k] and not self.u:used(k)
        and not held then
      local name = G.heard_route_name(t.text, route)
      if name then
        self.confirm = self.confirm or { id = name, heard = t.raw }
        -- (in a request that adds to a route, "after"/"before" place the new waypoint: a name there stays confirmed)
        local placing = G.route_position[self.words[k - 1]] and self:said("add insert addwpt append")
        self.heard_sure = not placing and t.raw:match("^%l+$") and (G.sure_route_name(t.text, route) == name
          and G.heard_nowhere_else(t.text, name, self.world) or self:route_navaid_named(t.text, name)) and name or nil
        return self:need(string.format("Did you mean %s? I heard '%s'.", name, t.raw))
      end
    end
  end
end

-- True when the word w is the navdata's own name of the navaid `name` on the route of an aircraft named in the
-- request, within lexicon.navaid_range_nm of it, and of no other waypoint of that route ("250 knots till comilla"
-- for CML, the Comilla VOR): the place said by its name, as a direct-to reads it, no sound-alike.
function G:route_navaid_named(w, name)
  local named = self.world.navaids_named
  if not named then return false end
  for _, r in ipairs(self.refs) do
    local a = r.kind == "aircraft" and r.exists and self:state(r.name)
    if a and a.lat then
      local ids, on = named(w, a.lat, a.lon, lexicon.navaid_range_nm), {}
      for _, p in ipairs(a.route or {}) do on[p:upper()] = true end
      local mine = 0
      for _, id in ipairs(ids) do
        if on[id:upper()] then mine = mine + (id:upper() == name:upper() and 1 or 2) end
      end
      if mine == 1 then return true end
    end
  end
  return false
end

-- "climb FL300 in a minute", "turn left heading 200 in a moment": a delay said after an instruction with no number
-- (lexicon.vague_delays: no time squawk can schedule) puts it off, where squawk would send it now: the leftover,
-- named from "in" to the end of its clause; in a remark of its own ("we'll re-create it in a minute") it is none.
function G:delay_left()
  if not self:said("in within") then return end
  local explained = self.explained or {}
  for i = 1, #self.t - 1 do
    local k = self:skip_fillers(i + 1)
    if self:word(i, "in within") and self:word(k, "@vague_delays") and not (self.u:used(i) or self.u:used(k)
        or explained[i] or self.noted[i]) and not self:in_reason(i) then
      local e = k + 1
      if not self.t[e] or self.t[e].kind == "punct" or self:word(e, "and then") then
        self.leftover = self:raw(i, e)
        return
      end
    end
  end
end

-- True when the request issued commands and every one is a value instruction (ALT, SPD, HDG, VS), which reads
-- no place, route or manner of its own.
function G:values_only()
  for _, c in ipairs(self.out) do
    if not (c:match("^ALT ") or c:match("^SPD ") or c:match("^HDG ") or c:match("^VS ")) then return false end
  end
  return #self.out > 0
end

-- "reduce 250 knots passing the beacon", "descend FL150 abeam it", "over the VOR turn left heading 200": beside
-- value instructions only (G:values_only), a word of lexicon.passage (or of lexicon.passage_at before a place's
-- noun) that no part of the parse read is a condition on a place squawk did not read: the leftover, named from that
-- word to the end of its clause, never dropped.
function G:passage_left()
  local explained = self.explained or {}
  -- (a word a command carries ends the clause, but a place's noun, which these commands never carry; one only
  -- noted, "the NDB", is in it)
  local nouns = "@passage_nouns @navaid_kinds @airport_nouns"
  local function carried(k) return self.taken[k] or (self.u:used(k) and not self:word(k, nouns)) end
  if not self:said("@passage @passage_at") then return end
  for i in ipairs(self.t) do
    if (self:word(i, "@passage") or (self:word(i, "@passage_at") and self:word(self:skip_fillers(i + 1), nouns)))
        and not (explained[i] or self.noted[i] or carried(i)) and not self:in_reason(i) then
      local e = i + 1
      while self.t[e] and self.t[e].kind ~= "punct" and not self.triggers[e] and not self:word(e, "and then")
          and not carried(e) do
        e = e + 1
      end
      self.leftover = self:raw(i, e)
      return
    end
  end
end

-- "heading 200, then continue on course", "... continue as filed", "... back on track": beside value instructions
-- only (G:values_only), a word of lexicon.going_on ("back" before "on") that no part of the parse read, its clause
-- holding no instruction word or value it is the manner of ("continue climb", "continue on heading 200"), is going
-- on along something squawk did not read: the leftover, named to the end of its clause. ("report back on track" is
-- the pilot's report.)
function G:going_on_left()
  if not self:said("@going_on") then return end
  local explained = self.explained or {}
  for i in ipairs(self.t) do
    if self:word(i, "@going_on") and not (self:word(i, "back") and not self:word(i + 1, "on"))
        and not self:word(i - 1, "report reporting") and not (explained[i] or self.noted[i] or self.u:used(i)
          or self.taken[i] or self.triggers[i]) and not self:in_reason(i) then
      local e, manner = i + 1, false
      while self.t[e] and self.t[e].kind ~= "punct" and not self:word(e, "and then") do
        manner = manner or self.triggers[e] or self.taken[e]
        e = e + 1
      end
      if not manner and e > i + 1 then
        self.leftover = self:raw(i, e)
        return
      end
    end
  end
end

-- Two things of one kind joined by "or" ("KLM12 or KLM21 climb", "aeromexico four five zero or four zero five",
-- "FL240 or FL250", "heading 090 or 100"): a choice squawk may not make for the speaker, asked, naming both. Each
-- side is a value (a token with a digit or a number word) or a callsign or place read, or the first an instruction
-- word after a value ("climb FL300 or turn left heading 200"), or both sides of a turn ("turn left or right
-- heading 200"); an "or" a value holds ("plus or minus 800 ft") joins nothing, and a bound after "or" ("FL240
-- or above", "250 or less") is no second thing, nor is a multiplier ("nine or thousand": "nine thousand" misheard),
-- and an "or" inside a reason is no instruction's.
function G:alternatives()
  local function span(k)  -- the callsign, place or run of value tokens holding token k, as {b, e}; nil if none
    for _, r in ipairs(self.refs) do
      if (r.kind == "aircraft" or r.kind == "waypoint") and r.b <= k and k < r.e then return r.b, r.e end
    end
    for _, q in ipairs(self:quantities(1, #self.t + 1)) do
      if q.b <= k and k < q.e then return q.b, q.e end
    end
    local function value(x)
      local t = self.t[x]
      return t ~= nil and t.kind ~= "punct" and (t.number_word or t.text:find("%d") ~= nil)
    end
    if not value(k) then return nil end
    local b, e = k, k + 1
    while value(b - 1) do b = b - 1 end
    while value(e) do e = e + 1 end
    return b, e
  end
  for i = 1, #self.t do
    local t = self.t[i]
    if t.text == "or" and t.kind == "word" and not self:in_reason(i) and select(2, span(i)) == nil then
      local l, r = i - 1, i + 1
      while self.t[l] and (self.t[l].filler or self.t[l].kind == "punct") do l = l - 1 end
      while self.t[r] and self.t[r].filler do r = r + 1 end
      local lb, re = span(l), select(2, span(r))
      -- (a value or callsign, then an instruction of its own: "climb FL300 or turn left heading 200"; two sides of
      -- a turn: "turn left or right")
      if lb and not re and self.triggers[r] then
        local q = self:quantities(r, #self.t + 1)[1]
        re = q and q.e or r + 1
      end
      if self:word(l, "left right") and self:word(r, "left right") then lb, re = l, r + 1 end
      if lb and re and not self:word(r, "above below higher lower less greater more so faster slower better thousand hundred") then
        self.ask = string.format("You said '%s': which one do you mean? Please say it again with one.",
          self:raw(lb, re))
        return
      end
    end
  end
end

-- The aircraft flying that the digits of plain quantity q (typed or said) name with the airline of an aircraft the
-- request names ("KLM1394 climb and 1349": KLM1349), or nil; digits inside a callsign read are none.
function G:and_digits_aircraft(q)
  local digits = q.number and q.number.digits or self.t[q.b].text
  if q.kind ~= "plain" or not digits:match("^%d+$") then return nil end
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" and r.b <= q.b and q.b < r.e then return nil end
  end
  for _, r in ipairs(self.refs) do
    local airline = r.kind == "aircraft" and r.name:upper():match("^(%a+)%d")
    local a = airline and self:state(airline .. digits)
    if a then return a.id:upper() end
  end
  return nil
end

-- A level, speed or heading said after "from", "out of" or a word of lexicon.level_left ("drop KLM12 from FL350",
-- "reduce from 250", "leaving FL260") is the value the aircraft leaves, never the one it flies to; a number with
-- a decimal fraction ("drop TRA5K at 52.3") is no level, speed or heading: a command issued with either is asked,
-- naming the value. ("away from" is a direction's; the value's noun may stand between: "from heading 090"; a bare
-- number matches a level, speed or heading; a Mach number is no whole value.) Digits after "and" (or "then",
-- "also", "plus", a comma) that name,
-- with the airline of an aircraft named, another aircraft flying ("KLM1394 climb and 1349") may be that aircraft
-- or a value: asked, whatever was read.
function G:values_misread()
  -- the ALT, SPD or HDG line of `verbs` carrying q's value made whole (cut, rounded, or a level in hundreds of
  -- feet: "120.5" ALT 12050), or nil
  local function issued(q, verbs)
    local v = q.value
    local whole = { [math.floor(v)] = true, [math.floor(v + 0.5)] = true, [math.floor(v * 100 + 0.5)] = true }
    if q.kind == "alt" then whole[math.floor(v / 100)] = true end
    for _, line in ipairs(self.out) do
      local cv, cval = line:match("^(%u+) %S+ %a*(%d+)$")
      if not cv then cv, cval = line:match("^(%u+) %S+ %a*(%d+) ") end
      cval = tonumber(cval)
      if cv and verbs:find(cv, 1, true) and whole[cval] then
        return line
      end
    end
  end
  for _, q in ipairs(self:quantities(1, #self.t + 1)) do
    local verbs = G.described_verb[q.kind] or (q.kind == "plain" and "ALT SPD HDG")
    local k = self:word(q.b - 1, "heading speed level altitude") and q.b - 2 or q.b - 1
    local line = verbs and issued(q, verbs)
    if line and ((self:word(k, "from") and not self:word(k - 1, "away")) or (self:word(k, "of") and self:word(k - 1, "out"))
        or self:word(k, "@level_left leave vacate")) then
      self.ask = string.format("I have %s, but '%s' is the value it leaves. What should it fly to?", line,
        self:raw(self:word(k, "of") and k - 1 or k, q.e))
      return
    end
    local joined = self.t[q.b - 1] and (self:word(q.b - 1, "and then also plus") or self.t[q.b - 1].text == ",")
    if joined and self:and_digits_aircraft(q) then
      self.ask = string.format("I heard '%s' after '%s': is it %s, or a value? Please say the instruction again.",
        self:raw(q.b, q.e), self.t[q.b - 1].raw, self:and_digits_aircraft(q))
      return
    end
    -- ("maintain point seven six", "descend .76", "maintain max point seven six": a decimal fraction below one, said or
    -- typed, is a Mach number's form, never a level, heading or rate; one beside such a command and read as no Mach
    -- number is asked, naming it)
    if q.kind == "plain" and q.value > 0 and q.value < 1 and q.number and q.number.decimal then
      local level, mach
      for _, c in ipairs(self.out) do
        level = level or ((c:match("^ALT ") or c:match("^HDG ") or c:match("^VS ")) and c)
        mach = mach or c:match("SPD %S+ M?0?%.%d")
      end
      if level and not mach then
        self.ask = string.format("I have %s, but I heard '%s', a Mach number's form. Which value do you mean?", level,
          self:raw(q.b, q.e))
        return
      end
    end
    if line and q.value ~= math.floor(q.value) and self:raw(q.b, q.e):find("%d[.,]%d") then
      self.ask = string.format("I have %s, but I heard '%s', with a decimal. Which value do you mean?", line,
        self:raw(q.b, q.e))
      return
    end
  end
end

-- A hedge of lexicon.trailing_hedges straight after a value, closing its clause (the request's end or a
-- mark after it: "descend fl300 maybe", "hdg 240, i think"), makes the request uncertain: asked, naming it.
G.hedge_words = table.concat(lexicon.trailing_hedges.words, " ")
G.questioned_hedges = table.concat(lexicon.trailing_hedges.questioned, " ")
-- (every word a hedge opens on: a hedge word, a pair's first word, a questioned one)
G.hedge_openers = G.hedge_words .. " " .. G.questioned_hedges
for _, p in ipairs(lexicon.trailing_hedges.pairs) do G.hedge_openers = G.hedge_openers .. " " .. p[1] end
function G:hedged()
  local h = lexicon.trailing_hedges
  local function closes(k) return self.t[k] == nil or self.t[k].kind == "punct" end
  for _, q in ipairs(self:quantities(1, #self.t + 1)) do
    local k, said = q.e, nil
    if self:word(k, G.hedge_openers) then  -- (each reading opens on one of them)
      if self:word(k, G.hedge_words) and closes(k + 1) then said = self:raw(k, k + 1) end
      for _, p in ipairs(said and {} or h.pairs) do
        if self:word(k, p[1]) and self:word(k + 1, p[2]) and closes(k + 2) then said = self:raw(k, k + 2) end
      end
      if not said and self:word(k, G.questioned_hedges) and self.t[k + 1] and self.t[k + 1].text == "?" then
        said = self:raw(k, k + 1) .. "?"
      end
    end
    if said then
      self.ask = string.format("%s. You said '%s' after '%s': should I send it as said, or which value do you mean?",
        #self.out > 0 and "I have " .. table.concat(self.out, " ; ") or "I have no instruction",
        said, self:raw(q.b, q.e))
      return
    end
  end
end

-- True when the text holds a word that starts an instruction of its own
-- (the dialogue tells an answer to its question from a new request by it).
function M.has_instruction(text)
  local u = squawk.translate.utterance(written_forms(text), nil, NAMES)
  local toks = u:tokens()
  local g = setmetatable({ u = u, t = toks, words = word_texts(toks), refs = u:refs(),
    world = { aircraft = {}, waypoints = {} }, fleet = {}, out = {}, qcache = {}, triggers = {} }, G)
  for i = 1, #g.t do
    if g:intent_at(i) then return true end
  end
  return false
end

-- Retrieval documents from the grammar: for each registry command, the
-- words whose rules lead to it and its `words` lines ({command =, text =}
-- for squawk.rag.index).
function M.documents()
  local words, order, extra = {}, {}, {}
  for _, w in ipairs(M.words) do
    if not extra[w.command] then
      extra[w.command] = w.text
      if not words[w.command] then words[w.command], order[#order + 1] = {}, w.command end
    end
  end
  for _, r in ipairs(M.rules) do
    local spec = r.intent and M.intents[r.intent]
    if spec and not r.any then
      for _, cmd in ipairs(spec.cmds or { spec.cmd }) do
        if not words[cmd] then words[cmd], order[#order + 1] = {}, cmd end
        for w in pairs(r.words) do
          local phrase = w
          if r.next then
            local nexts = {}
            for n in pairs(r.next) do nexts[#nexts + 1] = w .. " " .. n end
            table.sort(nexts)
            phrase = table.concat(nexts, ", ")
          end
          words[cmd][phrase] = true
        end
      end
    end
  end
  local docs = {}
  for _, cmd in ipairs(order) do
    local list = {}
    for w in pairs(words[cmd]) do list[#list + 1] = w end
    table.sort(list)
    local text = "Words people use for " .. cmd .. ": " .. table.concat(list, ", ")
    if extra[cmd] then text = text .. ". " .. extra[cmd] end
    docs[#docs + 1] = { command = cmd, text = text }
  end
  return docs
end

-- True when every word of text is in lexicon[list] ("yes", "affirm").
function M.lexicon_says(text, list)
  local set, any = word_set("@" .. list, 1), false
  -- (letters with accents, as M.translate reads them: "hayır" is "hayir")
  if text:find("[\xC3\xC4\xC5]") then text = text:gsub("[\xC3\xC4\xC5][\x80-\xBF]", lexicon.accents) end
  for w in text:lower():gmatch("[%a']+") do
    if not set[w] then return false end
    any = true
  end
  return any
end

-- ---- what squawk does not simulate ----

-- True when one of `near` (words or typed numbers as written; "#number"
-- any number, "#waypoint" a waypoint name (a navaid's kind alone is none: "until 10 DME", "the VOR"),
-- "#frequency" a radio frequency of the VHF air band, 118.000 to 136.975 MHz with its decimals, typed, "129.2",
-- or said digit by digit with its point, "one two eight decimal five") is within 4 tokens after i.
local function frequency(t)
  local mhz = t.kind == "number" and t.text:match("^1[123]%d%.%d+$") and tonumber(t.text)
  return mhz and mhz >= 118 and mhz < 137
end
function G:frequency_said(k)
  if frequency(self.t[k]) then return true end
  if not self.t[k].number_word then return false end
  local q = self:quantities(k, math.min(#self.t + 1, k + 8))[1]
  return q ~= nil and q.b == k and q.kind == "plain" and q.value >= 118 and q.value < 137 and q.value % 1 ~= 0
end
function G:near_any(i, near, window)
  for k = i + 1, math.min(#self.t, i + (window or 4)) do
    local t = self.t[k]
    for j = 1, #near do
      local w = near[j]
      if (w == "#number" and t.kind == "number") or (w == "#number" and t.number_word)
          or (w == "#frequency" and self:frequency_said(k))
          or (w == "#waypoint" and #self:refs_in(k, k + 1, "waypoint") > 0 and not self:word(k, "@navaid_kinds"))
          or ((t.kind == "word" or t.kind == "number") and t.text == w) then
        return true
      end
    end
  end
  return false
end

-- "KLM12 heading 090 right now", "right away, KLM12 turn left heading 200": "right" straight before "now" or "away"
-- is urgency, no turn's side (a filler); straight after a turn's word ("turn right now") it stays the side.
function G:urgent_right()
  for i = 1, #self.t - 1 do
    if self.words[i] == "right" and self:word(i + 1, "now away") and not self:word(i - 1, "turn turning turns") then
      self:blank(i)
    end
  end
end

-- "Right, for the next trial I'd like the KLM to turn left ...": a request
-- that opens with "right" and a comma, and turns left later, opened with the
-- speaker's "well"; that "right" is a filler, no direction.
function G:opening_right()
  local i = self:skip_fillers(1, false)
  local nxt = self.t[i + 1]
  if self:word(i, "@right") and nxt and nxt.kind == "punct" and nxt.text == ","
      and self:word_in(i + 2, #self.t + 1, "@left") then
    self:blank(i)
  end
end

-- "vectors for runway zero one left", "rwy 27 right", "expect the ILS (approach) two seven right": a runway's
-- number and the side said after it (lexicon.runway_sides) name the runway, never a value or a turn's direction
-- ("zero one left" is no turn of 1 degree left): they are marked used and the side is made a filler.
function G:runway_sides()
  if not self:said("@runway") then return end
  for i = 1, #self.t - 2 do
    if self:word(i, "@runway") then
      -- its number: typed ("27") or said digit by digit ("two seven", "zero one"), after "approach" if said
      local k = self:word(i + 1, "approach") and i + 2 or i + 1
      local first = k
      while k <= first + 1 and self.t[k] and (self.t[k].kind == "number" or self.t[k].number_word) do k = k + 1 end
      if k > first and self:word(k, "@runway_sides") then
        self:blank(k)
        self:mark_used(i + 1, k + 1)
      end
    end
  end
end

-- "fl100 left", "5000ft, rt": a turn's side said straight after a level with no verb before it (a comma between
-- at most) and no heading or amount after the side (nothing, punctuation, "and" or "then") names no turn to fly:
-- asked, the side named, never dropped ("fl100 left heading 270", "fl100 left 20" read the turn; after a verb,
-- "climb FL300 left", the side is asked as a word left over).
function G:side_after_level()
  for _, q in ipairs(self:quantities(1, #self.t + 1)) do
    local c = self.t[q.e]
    local i = q.kind == "alt" and (c and c.kind == "punct" and c.text == "," and q.e + 1 or q.e)
    if i and self:word(i, "@left @right") and not self.u:used(i) and not self:instruction_before(q.b) then
      local nxt = self.t[i + 1]
      if not nxt or nxt.kind == "punct" or self:word(i + 1, "and then") then
        return self:need(string.format("Which turn do you mean by '%s' after '%s'? Please say the heading or the "
          .. "degrees to turn.", self.t[i].raw, self:raw(q.b, q.e)))
      end
    end
  end
end

-- True when an aircraft is named just before token i (fillers and commas between).
function G:callsign_before(i)
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" and r.e <= i and self:skip_fillers(r.e) == i then return true end
  end
  return false
end

-- True when an instruction word stands before token i, or a value with a unit of its own, which is an instruction
-- wherever it stands ("keep 250 knots until KV").
function G:instruction_before(i)
  for k = 1, i - 1 do
    if self:intent_at(k) then return true end
  end
  for _, q in ipairs(self:quantities(1, i)) do
    if own_unit(q) then return true end
  end
  return false
end

-- "unable FL380, maintain FL360", "unable direct BOYNE, fly heading 070", "unable that heading, turn left
-- heading 230", "unable higher due traffic, ...", "unable, maintain present heading": what the controller
-- refuses straight after "unable" (a value, a direct-to, a word of lexicon.acknowledged.refused, or nothing
-- before punctuation), with a reason after it that ends its clause and names no value and no aircraft, is set
-- aside: no instruction of its own. "unable" after a word of lexicon.acknowledged.pilots ("if unable FL380,
-- ...") is a condition on the pilot, left to the parse; "unable" before anything else is left to be asked.
G.refused_sets = { refused = set_of(lexicon.acknowledged.refused),
  articles = set_of(lexicon.acknowledged.refused_articles), pilots = set_of(lexicon.acknowledged.pilots) }
-- "three miles instead of five", "FL300 rather than FL320", "heading 200 in place of 180": the value said straight
-- after the words of replacing, or after up to three words of lexicon.replaced_lead ("instead of the default
-- 1.05"), is the one replaced, never read (used, and its words accounted for); so is the value told as what a
-- setting was or is by default, closing its clause ("RFACH 1.1, the default is 1.05", "the default being 480")
function G:replaced_values()
  if not self:said("instead rather place default") then return end
  for i = 1, #self.t - 2 do
    local e = (self:word(i, "instead rather") and self:word(i + 1, "of than") and i + 2)
      or (self:word(i, "in") and self:word(i + 1, "place") and self:word(i + 2, "of") and i + 3)
    local told = not e and self:word(i, "default") and self:word(i + 1, "is was being") and i + 2
    local v = e and self:skip_fillers(e) or told
    while e and v - e < 4 and self:word(v, "@replaced_lead") do v = self:skip_fillers(v + 1) end
    local q = v and self:quantities(v, math.min(#self.t + 1, v + 4))[1]
    local closes = q and (not self.t[q.e] or self.t[q.e].kind == "punct")
    if q and q.b == v and (e or closes) then
      self:mark_used(i, q.e)
      self:explain(i, q.e)
    end
  end
end

function G:refused()
  if not self:said("unable") then return end
  local R = G.refused_sets
  for i = 1, #self.t - 1 do
    local e  -- the last token refused
    if self:word(i, "unable") and not self:word(i - 1, R.pilots) then
      local q = self:quantities(i + 1, #self.t + 1)[1]
      local k = self:word(i + 1, "direct") and (self:word(i + 2, "to") and i + 3 or i + 2)
      local place = k and self:refs_in(k, k + 1, "waypoint")[1]
      local noun = self:word(i + 1, R.articles) and i + 2 or i + 1
      if q and q.b == i + 1 and (q.kind == "alt" or q.kind == "speed" or q.kind == "mach" or q.kind == "heading") then
        e = q.e - 1
      elseif place then
        e = place.e - 1
      elseif self:word(noun, R.refused) then
        e = noun
      elseif self.t[i + 1].kind == "punct" or self:word(i + 1, "@reason") then
        e = i
      end
    end
    if e then
      -- ("due traffic", "because of the weather": the reason, to its clause's end)
      if self:word(e + 1, "@reason") then
        local p = e + 1
        while self.t[p] and self.t[p].kind ~= "punct" do p = p + 1 end
        if #self:quantities(e + 1, p) == 0 and #self:refs_in(e + 1, p, "aircraft") == 0
            and #self:refs_in(e + 1, p, "waypoint") == 0 then
          self:blank(e + 1)  -- (no reason of the instructions after it)
          e = p - 1
        end
      end
      self:set_aside(i, e)
    end
  end
end

-- True when aircraft state `a` flies or was given value `v` of `kind` ("alt" [ft], "speed" [kt CAS], "mach",
-- "heading" [deg]): within 50 ft, 2 kt, .01 or 1 degree of its selected or present value.
function G.flies(a, kind, v)
  local function near(x, y, tol) return x ~= nil and y ~= nil and math.abs(x - y) <= tol end
  local function turned(x, y) return x ~= nil and y ~= nil and math.abs((x - y + 540) % 360 - 180) <= 1 end
  return a ~= nil and (kind == "alt" and (near(v, a.sel_alt_ft, 50) or near(v, a.alt_ft, 50))
    or kind == "speed" and (near(v, a.sel_cas_kt, 2) or near(v, a.cas_kt, 2))
    or kind == "mach" and near(v, a.mach, 0.01)
    or kind == "heading" and (turned(v, a.sel_hdg_deg) or turned(v, a.hdg_deg)))
end

-- "RYR88F FL370 is fine, just heading 150", "descend FL150, speed 270 is ok", "keep FL370, just heading 150": a
-- level, speed, mach or heading said to be kept (lexicon.kept_as_is), its clause ending there or at another
-- instruction, is no instruction when it is what the aircraft named before it (or, with none before, the one
-- named after it) flies or was given: set aside, the instructions beside it read alone. Another value there,
-- or no aircraft to hold it against, is asked, never issued.
-- An aircraft said to go on as it flies (lexicon.aircraft_kept: "..., and KLM1234 stays on his route", "The KLM
-- stays where he is."): the aircraft opening a clause (the request's start, a mark or "and" before it), a verb of
-- `verbs`, then only `words` to a mark or the end, with instructions to another aircraft said elsewhere in the
-- request (its name before any said after the clause), is no instruction and not instructed (r.false_start): its
-- words are marked used. A value in the clause ("KLM1234
-- stays at FL240") leaves it to the instructions.
G.aircraft_kept_sets = { verbs = set_of(lexicon.aircraft_kept.verbs), words = set_of(lexicon.aircraft_kept.words) }
function G:aircraft_kept()
  local K = G.aircraft_kept_sets
  local unchanged = self:said("change changes unchanged")
  if not (unchanged or self:said(K.verbs)) then return end
  for _, r in ipairs(self.refs) do
    local k = self:skip_fillers(r.e, false)
    local opens = r.b == self:skip_fillers(1, false) or self.t[r.b - 1].kind == "punct" or self:word(r.b - 1, "and")
      or self:word(r.b - 1, "the") and (r.b == 2 or self.t[r.b - 2].kind == "punct" or self:word(r.b - 2, "and"))
    -- ("..., Jin Air 117 no change", "..., KLM12 unchanged": said of the aircraft in place of the verb)
    -- (named elsewhere too, it is left to the acids' reading of a clause of its own)
    local said_so = unchanged and (self:word(k, "unchanged") and k + 1
      or self:word(k, "no") and self:word(k + 1, "change changes") and k + 2)
    for _, o in ipairs(said_so and self.refs or {}) do
      if o ~= r and o.kind == "aircraft" and o.name == r.name then said_so = false end
    end
    -- (after a comma, only where the clause before it names its own aircraft: in "..., and direct HZQ1, BEE71 no
    -- change" BEE71 may be the direct's addressee, asked)
    if said_so and r.b > 1 and self.t[r.b - 1].kind == "punct" then
      local x = r.b - 2
      while x >= 1 and self.t[x].kind ~= "punct" and not self:word(x, "and") do x = x - 1 end
      local own = false
      for _, o in ipairs(self:refs_in(x + 1, r.b - 1, "aircraft")) do own = own or (o.exists and o.name ~= r.name) end
      said_so = own and said_so
    end
    if r.kind == "aircraft" and r.exists and opens and (said_so or self:word(k, K.verbs)) then
      local e = said_so or k + 1
      while self.t[e] and (self.t[e].filler or self:word(e, K.words)) do e = e + 1 end
      local b = self:word(r.b - 1, "the") and r.b - 1 or r.b
      -- (the instructions are another aircraft's: one named before them, "ANA12 keep present heading, turn 10
      -- degrees left" turns ANA12)
      local other = false
      for _, o in ipairs(self.refs) do
        other = other or (o.kind == "aircraft" and o.exists and o.name ~= r.name and (o.e <= b or o.b >= e))
      end
      local x = e
      while x <= #self.t and not self:intent_at(x) do x = x + 1 end
      if (not self.t[e] or self.t[e].kind == "punct") and other
          and (x > #self.t or self:has_ref(e, x, "aircraft"))
          and (self:any_instruction_in(1, b) or self:any_instruction_in(e, #self.t + 1)) then
        self:mark_used(b, e)
        r.false_start = true
      end
    end
  end
end

-- "..., put the Aer Lingus down to FL290 and leave the Ryanair be", "..., keep the easyJet as it is": an aircraft
-- told to be left as it flies (lexicon.aircraft_left_alone: a verb opening a clause, the aircraft, words of
-- leaving to the clause's end), with an instruction to another aircraft said elsewhere, is no instruction and not
-- instructed (r.false_start); its words are marked used. Named in an instruction of its own elsewhere ("climb
-- the Ryanair FL300 and leave the Ryanair be") it is left to the parse, which asks.
G.aircraft_left_sets = { verbs = set_of(lexicon.aircraft_left_alone.verbs),
  words = set_of(lexicon.aircraft_left_alone.words) }
function G:aircraft_left_alone()
  local K = G.aircraft_left_sets
  if not self:said(K.verbs) then return end
  for _, r in ipairs(self.refs) do
    local v = self:word(r.b - 1, "the") and r.b - 2 or r.b - 1
    local opens = v >= 1 and self:word(v, K.verbs)
      and (v == self:skip_fillers(1, false) or self.t[v - 1].kind == "punct" or self:word(v - 1, "and"))
    if r.kind == "aircraft" and r.exists and opens then
      local e = r.e
      while self.t[e] and (self.t[e].filler or self:word(e, K.words)) do e = e + 1 end
      local other, again = false, false
      for _, o in ipairs(self.refs) do
        if o.kind == "aircraft" and o.exists and (o.e <= v or o.b >= e) then
          if o.name ~= r.name then other = true else again = true end
        end
      end
      if e > r.e and (not self.t[e] or self.t[e].kind == "punct") and other
          and (self:any_instruction_in(1, v) or self:any_instruction_in(e, #self.t + 1))
          and not (again and not self:only_described(r.name, v, e)) then
        self:mark_used(v, e)
        r.false_start = true
      end
    end
  end
end

-- True when every reference to aircraft `name` outside [b, e) is the subject of a verb of lexicon.described, alone
-- or in a group joined by "and" ("the Ryanair and the Aer Lingus are crossing")
function G:only_described(name, b, e)
  for _, o in ipairs(self.refs) do
    if o.kind == "aircraft" and o.name == name and (o.e <= b or o.b >= e) then
      local k = o.e
      while self:word(k, "and") do
        local x = self:word(k + 1, "the") and k + 2 or k + 1
        local nx = self:refs_in(x, x + 1, "aircraft")[1]
        if not nx then break end
        k = nx.e
      end
      if not self:word(k, "@described") then return false end
    end
  end
  return true
end

G.kept_sets = {}
for k, list in pairs(lexicon.kept_as_is) do G.kept_sets[k] = set_of(list) end
G.kept_kinds = { alt = true, speed = true, mach = true, heading = true }
function G:kept_values()
  local K = G.kept_sets
  -- (a value kept needs an approval, a copula saying it alone, "all right", "as is" or a verb of keeping with
  -- "just" or "but")
  if not self:said(K.approvals) and not self:said(K.stays) and not (self:said("all") and self:said("right"))
      and not (self:said("as") and self:said("is"))
      and not (self:said(K.verbs) and (self:said(K.only) or self:said(K.but))) then
    return
  end
  local function ends(k)
    local t = self.t[k]
    return not t or t.kind == "punct" or self:word(k, K.only) or self:word(k, "and but then")
      or self:intent_at(k) ~= nil or #self:refs_in(k, k + 1, "aircraft") > 0
  end
  -- the position after "as is" or "as it is" at k, else nil
  local function as_is(k)
    local n = self:word(k + 1, "it") and k + 2 or k + 1
    return self:word(k, "as") and self:word(n, "is") and n + 1 or nil
  end
  -- (last to first: "hdg 135 and FL370 are fine" keeps the heading with the level after it; kept[b]: a value
  -- kept from token b)
  local qs, kept = self:quantities(1, #self.t + 1), {}
  for x = #qs, 1, -1 do
    local q = qs[x]
    -- (a plain number after "speed" is a speed: "speed 270 is fine")
    local kind = q.kind == "plain" and self:word(q.b - 1, "speed") and "speed" or q.kind
    if G.kept_kinds[kind] and not self.u:used(q.b) then
      local b, e = q.b, nil  -- the tokens set aside, [b, e]
      while b > 1 and self:word(b - 1, K.units) do b = b - 1 end
      -- (an instruction's own value, "climb FL200 okay", is no value approved)
      local verb = false
      for y = b - 1, 1, -1 do
        if self.t[y].kind == "punct" or self:word(y, "and but then") then break end
        if self:intent_at(y) then verb = true break end
      end
      local k = q.e
      while self:word(k, K.copulas) do k = k + 1 end
      local approved = self:word(k, K.approvals) or (k > q.e and self:word(k - 1, K.stays))
      if self:word(k, "all") and self:word(k + 1, "right") then  -- ("all right": no turn)
        self:blank(k + 1)
        approved, k = true, k + 2
      elseif k == q.e and as_is(k) then  -- ("FL370 as is")
        approved, k = true, as_is(k)
      end
      -- ("keep FL370, just ...", "keep FL350 but ...", "leave FL370 as is, ...")
      local n = as_is(q.e) or q.e
      if self.t[n] and self.t[n].kind == "punct" and (n == q.e or not ends(n + 1)) then n = n + 1 end
      if self:word(b - 1, K.verbs) and (self:word(n, K.only) or self:word(n, K.but) or (n > q.e and ends(n))) then
        b, e = b - 1, n - 1
        if self.t[e].kind == "punct" then e = e - 1 end
      elseif approved and not verb then
        -- ("FL370 is fine", "FL180 stays", "speed 250 remains unchanged", "... is good as it is")
        if self:word(k, K.approvals) then k = k + 1 end
        while self:word(k, K.rounding) and not ends(k) do k = k + 1 end
        if ends(k) then e = k - 1 end
      elseif not verb and self:word(q.e, "and") and kept[q.e + 1] then
        e = q.e
      end
      if e then
        local id
        for _, r in ipairs(self.refs) do
          if r.kind == "aircraft" and (r.e <= b or not id) then id = r.name end
        end
        local a = id and self:state(id)
        local f = handlers.format
        local v = q.value
        if G.flies(a, kind, v) then
          self:set_aside(b, e)
          kept[b] = true
          -- ("..., nur hdg 150": the word that leaves only the other instruction)
          local n = self.t[e + 1] and self.t[e + 1].kind == "punct" and e + 2 or e + 1
          if self:word(n, K.only) then self:blank(n) end
          -- ("RYR88F FL370 is fine, KLM33 heading 100": the callsign said for the value kept alone, another
          -- aircraft's instruction after it, is set aside with it)
          local after = e + 1  -- (past fillers, "and" and what is set aside: "KLM33 FL180 ok, EWG9 FL250 ok, ...")
          while self.t[after] and (self.t[after].kind == "punct" or self.t[after].filler or self.noted[after]
              or self:word(after, "and")) do
            after = after + 1
          end
          if #self:refs_in(after, after + 1, "aircraft") > 0 then
            for _, r in ipairs(self:refs_in(1, b, "aircraft")) do
              if self:skip_fillers(r.e) == b then self:set_aside(r.b, b - 1) break end
            end
          end
        else
          local said = kind == "alt" and f.alt(v, q.fl) or kind == "mach" and f.mach(v) or f.int(v)
          self:need(a and string.format("'%s': %s does not fly %s now. Should it be given %s, or keep what it "
            .. "flies?", self:raw(b, e + 1), a.id, said, said)
            or string.format("'%s' is said to be kept: which aircraft keeps it?", self:raw(b, e + 1)))
        end
      end
    end
  end
end

-- "keep its present altitude and just turn right to heading 250", "keep your current heading but slow down to 260
-- knots": a verb of keeping, "its"/"your"/"the", a word of lexicon.present and a noun of
-- lexicon.kept_as_is.present_nouns, then "and", "but" or a comma and another instruction of another kind, is no
-- instruction when the aircraft named before it (or, with none, after it) holds that value with nothing to
-- change: its selected level within 50 ft of its level, selected speed within 2 kt of its speed, selected
-- heading within 1 degree of its heading and no route steering it (HDG would switch LNAV off). Set aside, the
-- instruction beside it read alone; otherwise the handlers issue the present value as before.
function G:kept_present()
  local K = G.kept_sets
  if not self:said(K.verbs) or not self:said("@present") then return end
  local nouns, intents = lexicon.kept_as_is.present_nouns, lexicon.kept_as_is.present_intents
  for i = 1, #self.t - 3 do
    if self:word(i, K.verbs) and not self.u:used(i) then
      local k = self:word(i + 1, "flying") and i + 2 or i + 1
      if self:word(k, "its your the their his her") then k = k + 1 end
      local kind = self:word(k, "@present") and nouns[self.words[k + 1]]
      local c = kind and k + 2
      if c and self.t[c] and self.t[c].kind == "punct" and self.t[c].text == "," then c = c + 1 end
      local joined = c and self:word(c, "and") or self:word(c, K.but)
      local n = joined and c + 1 or c
      if n and self:word(n, K.only) then n = n + 1 end
      local other = n and self:intent_at(n)
      local same = false
      for x = n or 1, other and #self.t or 0 do
        same = same or self:intent_at(x) == intents[kind]
      end
      if other and other ~= "maintain" and not same then
        local id
        for _, r in ipairs(self.refs) do
          if r.kind == "aircraft" and (r.e <= i or not id) then id = r.name end
        end
        local a = id and self:state(id)
        local held = a and (kind == "alt" and G.flies(a, "alt", a.alt_ft) and (a.sel_alt_ft == nil
            or math.abs(a.sel_alt_ft - a.alt_ft) <= 50)
          or kind == "speed" and (a.sel_cas_kt == nil or math.abs(a.sel_cas_kt - (a.cas_kt or 0)) <= 2)
          or kind == "heading" and not a.lnav and (a.sel_hdg_deg == nil or G.flies(a, "heading", a.sel_hdg_deg)
            and math.abs((a.sel_hdg_deg - a.hdg_deg + 540) % 360 - 180) <= 1))
        if held then
          self:set_aside(i, k + 1)
          if self:word(n - 1, K.only) then self:blank(n - 1) end
        end
      end
    end
  end
end

-- "ask TAP1732 to climb to FL170 and, once it passes FL130, to speed up to 290 knots": the infinitive's "to" straight
-- after a condition set off by commas (its clause opening with a word of lexicon.condition, "and" or "then" before
-- it), before the instruction word it holds, is the polite request's grammar: a filler, so the instruction reads
-- with its condition.
function G:infinitive_after_condition()
  if not self:said("@condition") then return end
  for k = 3, #self.t - 1 do
    if self:word(k, "to") and self.t[k - 1].text == "," and self:intent_at(k + 1) then
      local c = k - 2
      while c > 1 and self.t[c - 1].kind ~= "punct" do c = c - 1 end
      local w = c
      while self:word(w, "and then") do w = w + 1 end  -- (", and once it passes FL130, to ...")
      if self:word(w, "@condition") and self.t[c - 1] and self.t[c - 1].text == "," then self:blank(k) end
    end
  end
end

-- The grammar of a condition said in Russian (and Kazakh) formal English, words with no meaning of their own in it:
-- fillers, so the condition reads as its English form does.
-- ("will" of the future in such a condition is dropped from the text before, G.future_will.)
-- - "point" before a waypoint named after a word that ties an instruction to it ("after point SELNA", "at the
--   point IBLAN", "till point PINOS", "passing point X": the waypoint itself, as "after SELNA").
-- - "let" and the pronoun after it before an instruction word, in a clause that a condition opened ("and when it
--   will reach level 150 let it increase speed": the instruction of the condition, as "increase speed").
-- - "with" between a waypoint crossed and a speed or level ("cross RANAD with 250 knots": "cross RANAD 250 knots").
-- - "set" opening the request before "for" and the callsign ("Set for Aeroflot 1661 at the point IBLAN level 150":
--   the addressee named, as "for Aeroflot 1661 at IBLAN level 150").
-- Nothing else changes: "will" elsewhere, "point" before no waypoint, "let" with no condition before it stay.
function G:condition_grammar_words()
  if not self:said("point let with set") then return end
  local n = #self.t
  local function wp_at(k)
    local r = self:refs_in(k, k + 1, "waypoint")[1]
    return r and r.b == k and r
  end
  for k = 2, n - 1 do
    if self:word(k, "point") and wp_at(self:skip_fillers(k + 1)) then
      local p = k - 1
      while p > 1 and self.t[p].filler do p = p - 1 end
      if self:word(p, "at after till until over overhead passing pass passes past cross crosses crossing reach "
          .. "reaches reaching before") then
        self:blank(k)
      end
    elseif self:word(k, "let") and self:word(k + 1, "it him her them") and self:intent_at(k + 2) then
      local c = k - 1
      while c > 1 and self.t[c - 1].kind ~= "punct" and not self:word(c - 1, "and @then_words") do c = c - 1 end
      if self:word(c, "when once after") and self:word_in(c, k, "it he she they") then
        self:blank(k)
        self:blank(k + 1)
      end
    elseif self:word(k, "with") then
      local r = self:refs_in(math.max(1, k - 4), k, "waypoint")
      r = r[#r]
      local q = self:quantities(k + 1, n + 1)[1]
      if r and r.e == k and self:word(r.b - 1, "cross crosses crossing") and q and q.b == self:skip_fillers(k + 1)
          and (q.kind == "speed" or q.kind == "alt" or q.kind == "mach") then
        self:blank(k)
      end
    end
  end
  local f = self:skip_fillers(1)
  if self:word(f, "set") and self:word(f + 1, "for") and #self:refs_in(f + 2, f + 3, "aircraft") > 0 then
    self:blank(f)
  end
end

-- "accelerate the KLM to 300 knots, and when it has reached 300 knots, it shall climb to FL 350": after a condition
-- set off by commas (its clause opening with a word of lexicon.condition, after "and", "then" or "only"), the main
-- clause's subject and modal in the German word order ("it shall", "he should", "they will", "both shall", "let it";
-- lexicon.main_clause_subjects and lexicon.main_clause_modals) before the instruction word it holds are the
-- sentence's grammar, no words of their own: fillers, so the instruction reads with its condition.
function G:subject_after_condition()
  if not self:said("@condition") then return end
  for k = 3, #self.t - 2 do
    if self.t[k - 1].text == "," and (self:word(k, "@main_clause_subjects") or self:word(k, "let")) then
      local v = self:word(k, "let") and self:word(k + 1, "@main_clause_subjects") and k + 2
        or not self:word(k, "let") and self:word(k + 1, "@main_clause_modals") and k + 2
      if v and self:intent_at(v) then
        local c = k - 2
        while c > 1 and self.t[c - 1].kind ~= "punct" do c = c - 1 end
        local w = c
        while self:word(w, "and then only") do w = w + 1 end
        if self:word(w, "@condition") and (c == 1 or self.t[c - 1].text == ",") then
          for x = k, v - 1 do self:blank(x) end
        end
      end
    end
  end
end

-- "roger Mayday, descend FL100", "pan pan acknowledged, turn left heading 210", "emergency descent approved,
-- descend and maintain 10000": a distress or urgency call acknowledged, or a request granted
-- (lexicon.acknowledged), is set aside: no command, the instructions beside it read alone. The call's words
-- end there: at punctuation, the end, or an instruction word other than "descent" ("roger the emergency
-- descent ..." asks); a call said with no acknowledgement ("Mayday", "declare an emergency") still asks.
G.acknowledged_sets = {}
for _, k in ipairs({ "calls", "before", "articles", "after" }) do
  G.acknowledged_sets[k] = set_of(lexicon.acknowledged[k])
end
function G:acknowledged()
  local A = G.acknowledged_sets
  if not self:said(A.calls) and not self:said("deviation deviations") then return end
  local function ends(k)
    local t = self.t[k]
    return not t or t.kind == "punct" or (self:intent_at(k) ~= nil and not self:word(k, "descent"))
  end
  for i = 1, #self.t do
    if self:word(i, A.calls) and not self.u:used(i) then
      -- the run of call words ("pan pan pan"), an acknowledgement before or after it
      local b, e = i, i
      while self:word(e + 1, A.calls) do e = e + 1 end
      if self:word(b - 1, A.articles) then b = b - 1 end
      if self.t[b - 1] and self.t[b - 1].text == "," and self:word(b - 2, A.before) then b = b - 1 end
      local before = self:word(b - 1, A.before)
      if before then b = b - 1 end
      local after = self:word(e + 1, A.after)
      if after then e = e + 1 end
      if (before or after) and ends(e + 1) then self:set_aside(b, e) end
    end
    for _, p in ipairs(lexicon.acknowledged.granted) do
      local ok = true
      for x = 1, #p do ok = ok and self:word(i + x - 1, p[x]) end
      local t = self.t[i + #p]
      if ok and (not t or t.kind == "punct") then self:set_aside(i, i + #p - 1) end
    end
  end
end

-- Every word that starts a phrase of lexicon.not_simulated -> the entries whose words hold it, in the lexicon's order.
local NOT_SIMULATED_WORDS = {}
for _, c in ipairs(lexicon.not_simulated) do
  for w in pairs(word_set(c.words, 1)) do
    NOT_SIMULATED_WORDS[w] = NOT_SIMULATED_WORDS[w] or {}
    table.insert(NOT_SIMULATED_WORDS[w], c)
  end
end

-- True when token i is a navaid's kind said beside its name: after it ("relocate to TKT VOR at FL300",
-- "direct Minsk NDB", "over the Spijkerboor VOR at FL180") or before it in the Spanish order ("from the VOR
-- Bogota", "direct VOR BOG"): the place, no approach (a kind followed by "approach", "TKT VOR approach",
-- "VOR approach", is one). The name is an ident read as a waypoint, or the words beside the kind that name a
-- navaid of that kind anywhere in the navdata: one to three before it ("the Isle of Man VOR"), one or two after it.
function G:navaid_named_beside(i)
  if not self:word(i, "@navaid_kinds") or self:word(self:skip_fillers(i + 1), "approach") then return false end
  local after = not self:word(i + 1, "@navaid_kinds") and not self:word(i + 2, "approach")
  for _, r in ipairs(self.refs) do
    if r.kind == "waypoint" and not self:word(r.b, "@navaid_kinds")
        and ((r.b < i and r.e >= i) or (after and r.b == i + 1)) then
      return true
    end
  end
  local named, kind = self.world.navaids_named, lexicon.navaid_types[self.t[i].text]
  local function name_word(k)
    local t = self.t[k]
    return t and t.kind == "word" and t.alpha and not t.keyword and not t.filler and not t.number_word
  end
  local phrase = ""
  for k = i - 1, math.max(1, i - 3), -1 do
    if not named or not name_word(k) then break end
    phrase = self.t[k].text .. (phrase == "" and "" or " " .. phrase)
    if #named(phrase, 0, 0, math.huge, kind) > 0 then return true end
  end
  phrase = ""
  for k = i + 1, after and i + 2 or 0 do
    if not named or not name_word(k) then break end
    phrase = (phrase == "" and "" or phrase .. " ") .. self.t[k].text
    if #named(phrase, 0, 0, math.huge, kind) > 0 then return true end
  end
  return false
end

-- True when the place named just after token i ends the request ("keep speed 280 until VAKNO", a full
-- stop or question mark after it at most); with no place, when the words after it do, each a number, a
-- unit of distance or one of `near` ("reduce 160 knots until 4 DME", "until established"; a comma only where
-- `near` holds ",": "until established, cleared ILS runway 10").
function G:said_last(i, near, own_clause)
  local r = self:refs_in(i + 1, math.min(#self.t + 1, i + 4), "waypoint")[1]
  local k
  if r then
    k = self:skip_fillers(r.e)
  elseif near then
    k = i + 1
    while self.t[k] and (self.t[k].kind == "number" or self.t[k].number_word or self.t[k].filler
        or self:word(k, "@fraction_units") or self:word(k, near)
        or (self.t[k].kind == "punct" and self.t[k].text == "," and near:find(" , ", 1, true))) do
      k = k + 1
    end
    -- (the airport a clearance's runway is at, named last: "until established, cleared ILS 9L Sanford")
    local with = self.world.airports_with_words
    if with and k > i + 1 and (self:word(k - 1, "l r c left right center centre") or self.t[k - 1].kind == "number") and self.t[k]
        and self.t[k].kind == "word" and self.t[k].alpha and not self.t[k].keyword and #with(self.t[k].text) > 0 then
      k = k + 1
    end
  else
    return false
  end
  -- (the one aircraft named, its callsign said after the limit, a comma before it at most: "170 knots until 4 DME,
  -- KLM12", "speed 280 until ARTIP transavia 5KX", a pseudo-pilot's readback; the limit ends where it begins)
  local cs_at = self.t[k] and self.t[k].text == "," and k + 1 or k
  local cs = self:refs_in(cs_at, #self.t + 1, "aircraft")
  if cs[1] and cs[1].b == cs_at and #cs == 1 and #self:refs_in(1, i, "aircraft") == 0 then k = cs[1].e end
  -- (a hand-off closing the request: "until 5 miles final, then contact tower 118.7", G.handoff_to_end)
  if G.handoff_to_end(self, k) then return true end
  -- (`own_clause`: "reduce 160 until 5 miles final, descend to 3000 feet": a clause after a comma, opened by
  -- an imperative verb of lexicon.clause_verbs, is an instruction of its own and waits for no limit)
  local j = self.t[k] and self.t[k].text == "," and self:skip_fillers(k + 1) or k
  if own_clause and (j > k or (self.t[k - 1] and self.t[k - 1].text == ",")) and self:word(j, "@clause_verbs") and self:intent_at(j) then
    return true
  end
  -- (what follows set aside already, punctuation and courtesy between: "until RINOR, which is on its route? Thank
  -- you.", G:route_remarks; "until 6 miles final, thereafter as per the procedure", G:limit_released)
  local rest, remark = k, false
  while self.t[rest] and (self.t[rest].kind == "punct" or self.noted[rest] or FRAMING[self.t[rest].text]) do
    remark = remark or self.noted[rest] == true
    rest = rest + 1
  end
  if remark and rest > #self.t then return true end
  -- (only thanks or "please" after the place and its comma: "until HARIS, thank you.")
  local thanks = k
  while r and self.t[thanks] and (self.t[thanks].kind == "punct" or self:word(thanks, "thank thanks you please")) do
    thanks = thanks + 1
  end
  if r and thanks > k and thanks > #self.t then return true end
  -- (and after a distance: "until 5 mile final, thank you")
  if not r and self.t[k] and G.thanks_to_end(self, k) then return true end
  local stop = k
  while self.t[k] and self.t[k].kind == "punct" and self.t[k].text ~= "," do k = k + 1 end
  -- (a sentence after it set aside as a remark, G:in_reason: "until 4 miles on final? I understand that's what
  -- normally happens."; or one that says nothing to fly, G:remark_sentences: "until OSTER? That's what the
  -- procedure says.")
  local ended = self.t[k - 1] and self.t[k - 1].kind == "punct" and (self.t[k - 1].text == "." or self.t[k - 1].text == "?"
    or self.t[k - 1].text == "!")
  return k > #self.t or (k > stop and self:in_reason(k)) or ((k > stop or ended) and self:remark_sentences(k))
end

-- True when tokens k .. the request's end are a hand-off and nothing else: a comma, "and", "then" ("after that",
-- "thereafter") at most, then "contact" or "monitor", the station (lexicon.handoff_words, or at most two names of
-- its own), a radio frequency (G:frequency_said) and courtesy ("... till 4 miles final, thereafter contact the
-- tower on 119,9", "until LGL then monitor Langen radar 125.2, thank you"). A hand-off is not simulated; it starts
-- nothing, so a limit before it is still said last. Anything else after it (an instruction, a value) is not.
function G.handoff_to_end(g, k)
  local j = k
  while g.t[j] and (g.t[j].text == "," or g:word(j, "and then thereafter afterwards")) do j = j + 1 end
  if g:word(j, "after") and g:word(j + 1, "that") then j = j + 2 end
  if j == k and not (g.t[k - 1] and g.t[k - 1].kind == "punct") then return false end
  if not g:word(j, "contact monitor") then return false end
  local freq, names = false, 0
  j = j + 1
  while g.t[j] do
    local t = g.t[j]
    -- (a decimal comma, "119,9", as typed where it is the decimal sign: one token, the MHz, a comma, up to three
    -- digits)
    local mhz = t.text:match("^1[123]%d,%d%d?%d?$") and tonumber((t.text:gsub(",", ".")))
    if g:frequency_said(j) or (mhz and mhz >= 118 and mhz < 137) then
      freq = true
    elseif not (t.kind == "punct" or t.number_word or g:word(j, "@handoff_words")) then
      if not (t.kind == "word" and t.alpha and not t.keyword and not g.triggers[j] and names < 2
          and #g:refs_in(j, j + 1, "aircraft") == 0) then
        return false
      end
      names = names + 1
    end
    j = j + 1
  end
  return freq
end

-- True when the words from token k to the request's end, whole sentences after a sentence's end, say nothing to
-- fly: no instruction word (G:intent_at), no value, no aircraft or place, and no word of lexicon.remark_not (a
-- negation, a bound, a comparison: "Not below.", "No less.") - a remark on what was said ("That's what the procedure
-- says.", "That is the standard for this arrival.", "Then we'll see.").
function G:remark_sentences(k)
  if k > #self.t or #self:quantities(k, #self.t + 1) > 0 or self:has_ref(k, #self.t + 1, "aircraft")
      or self:has_ref(k, #self.t + 1, "waypoint") or self:any_instruction_in(k, #self.t + 1) then
    return false
  end
  for x = k, #self.t do
    local t = self.t[x]
    if not (t.kind == "punct" or t.kind == "word") or self:word(x, "@remark_not") or self.triggers[x] then return false end
  end
  return true
end

-- What stands before the word at i ("start", "aircraft", "value", "place" or "closing") when it stands alone in its
-- clause beside an instruction said ("climb FL300, squawk", "turn left heading 200 then cross", "KLM12 resume, climb
-- FL300", "hold KLM12 climb FL300", "direct WP2 done"): with fillers, "and", "then" and commas skipped, the text's
-- start, a callsign, a value's end or a place a command read before it, and the text's end (closing marks only), an
-- instruction word or (at the start) a callsign after it, with an instruction word (or a value with its own unit, or,
-- once read, a command issued: "KLM12 level 280 done") and an aircraft somewhere in the request ("ff 120 then hold" holds the simulation). Once
-- read, with no aircraft named, a word closing the request after a word its command read is "closing" it ("pause the
-- simulation done"). With `apart`, an instruction word straight after it stands apart only with "and", "then" or a
-- comma between. A word opening the request before a comma addresses a station ("Approach, KLM12 climb FL300").
-- False when it does not.
function G:said_bare(i, apart)
  local fleet = #self:refs_in(1, #self.t + 1, "aircraft") > 0
  if not fleet and #self.out == 0 then return false end
  local function skip(k, step)
    while self.t[k] and (self.t[k].filler or self:word(k, "and then") or self.t[k].text == ",") do k = k + step end
    return k
  end
  local p, n = skip(i - 1, -1), skip(i + 1, 1)
  if p < 1 and self.t[i + 1] and self.t[i + 1].text == "," then return false end
  local before = p < 1 and "start" or self:has_ref(p, p + 1, "aircraft") and "aircraft"
  for _, q in ipairs(before and {} or self:quantities(math.max(1, p - 3), p + 1)) do
    if q.e == p + 1 then before = "value" end
  end
  for _, r in ipairs(before and {} or self:refs_in(math.max(1, p - 3), p + 1, "waypoint")) do
    if r.e == p + 1 and self.u:used(p) then before = "place" end
  end
  -- (no aircraft named, once read: "closing" the request after a word its command read, "pause the simulation done")
  if not fleet then
    local read = p >= 1 and (self.triggers[p] or self.u:used(p) or self.taken[p] or self.t[p].keyword)
    before = (before == "value" or read) and "closing" or nil
    if n <= #self.t then return false end
  end
  if not before then return false end
  while self.t[n] and self.t[n].kind == "punct" and self.t[n].text ~= "," and self.t[n].text ~= "'" do n = n + 1 end
  if not (n > #self.t or (before == "start" and self:has_ref(n, n + 1, "aircraft"))
      or ((n > i + 1 or not apart) and self:intent_at(n))) then
    return false
  end
  if #self.out > 0 then return before end
  for k = 1, #self.t do
    if k ~= i and self:intent_at(k) then return before end
  end
  -- (a value with its own unit is an instruction wherever it stands: "KLM12 FL280, weather")
  for _, q in ipairs(self:quantities(1, #self.t + 1)) do
    if own_unit(q) then return before end
  end
  return false
end

-- True when the word at i is said as an instruction's manner: alone in its clause beside an instruction (G:said_bare:
-- "climb FL300 quickly", "descend FL200, expedite"), or straight after an instruction word, the callsign or the
-- request's start and before an instruction word, a value, a turn's side, "to", or the change named ("turn hard
-- left", "climb rapidly to FL300", "KLM12 hard left heading 350", "expedite your descent").
function G:said_as_manner(i)
  if self:said_bare(i) then return true end
  local p = i - 1
  while p >= 1 and self.t[p].filler do p = p - 1 end
  if p >= 1 and not (self:intent_at(p) or self:callsign_before(i)) then return false end
  local n = self:skip_fillers(i + 1)
  if self:word(n, "your its their") then n = n + 1 end
  local q = self:quantities(n, n + 3)[1]
  return self:word(n, "@left @right to climb descent descend turn") or self:intent_at(n) ~= nil
    or (q ~= nil and q.b == n)
end

-- The phrase that says a rate as a manner, its word "rate" at i ("at a good rate", "with your best rate of climb",
-- "good rate"): a word of lexicon.rate_manner straight before it (an article, then "at" or "with", before that
-- belong to it), "of" and a climb's or a descent's word after it, and no rate's value straight after (G:rate_value:
-- "at a good rate of 2000 fpm" says the rate; "at a good rate to 9000 feet" a level). Returns its first position,
-- one past its end, true when it wants a gentler rate than the aircraft's own (rate_manner.asked), and the value
-- with no rate's unit said straight after it, a level or the rate ("at a good rate 9000 feet", "... rate 2000"), or
-- nil.
G.rate_manners = { flown = set_of(lexicon.rate_manner.flown), asked = set_of(lexicon.rate_manner.asked) }
G.motion = { up = set_of(lexicon.vertical_motion.up), down = set_of(lexicon.vertical_motion.down) }
function G:rate_manner(i)
  local w, manners = self.words[i - 1], G.rate_manners
  if not (w and (manners.flown[w] or manners.asked[w])) then return nil end
  local e = i + 1
  if self:word(e, "of") and (self:word(e + 1, G.motion.up) or self:word(e + 1, G.motion.down)) then e = e + 2 end
  local v = self:skip_fillers(self:word(e, "of at to") and e + 1 or e)
  local q = self:quantities(e, #self.t + 1)[1]
  local doubt = q and q.b == e and q.kind ~= "vs" and not q.fl and q or nil
  if q and q.b <= v and self:rate_value(i, q) and not doubt then return nil end
  local b = i - 1
  if self:word(b - 1, "a an your its their the") then b = b - 1 end
  if self:word(b - 1, "at with") then b = b - 1 end
  return b, e, manners.asked[w] == true, doubt
end

-- True when the word before token i is one of `subjects` ("already", "has", "had", "was", "were", "just" and
-- fillers between them skipped: "the student has just cleared").
function G:said_after_subject(i, subjects)
  local k = i - 1
  while k >= 1 and (self.t[k].filler or self:word(k, "already has had was were just")) do k = k - 1 end
  return self:word(k, subjects)
end

-- True when a heading value ends just before token i, with only fillers, "to", "vectors" (or "vector",
-- "vectoring") and commas between ("heading 060, vectors to rejoin ...").
function G:after_heading(i)
  local k = i - 1
  while k >= 1 and (self.t[k].filler or self.t[k].text == "," or self:word(k, "to vectors vector vectoring")) do
    k = k - 1
  end
  for _, q in ipairs(self:quantities(math.max(1, k - 2), k + 1)) do
    if q.kind == "heading" and q.e == k + 1 then return true end
  end
  return false
end

-- The aircraft reference named at i (after fillers) when "to" follows it ("expect IBE3142 to climb": the
-- speaker's expectation of that aircraft, asked), else nil.
function G:aircraft_then_to(i)
  local r = self:refs_in(self:skip_fillers(i), self:skip_fillers(i) + 1, "aircraft")[1]
  return r and self:word(r.e, "to") and r or nil
end

-- True, asking, when the place a limit ends at ("maintain 250 knots or greater until KERAX": the word at i,
-- the waypoint within `window` words after it) is on no route of the one aircraft addressed: the value would be
-- flown with an end that names a place the aircraft never passes.
function G:limit_off_route(i, window)
  local wp = self:refs_in(i + 1, i + 1 + (window or 4), "waypoint")[1]
  -- (a distance before it is no place: "till 6 DME")
  if wp and #self:quantities(i + 1, wp.b) > 0 then return false end
  local ids, seen = {}, {}
  for _, r in ipairs(self:refs_in(1, #self.t + 1, "aircraft")) do
    if r.exists and not seen[r.name] then seen[r.name], ids[#ids + 1] = true, r.name end
  end
  if not wp or #ids ~= 1 or self:on_route(ids[1], wp.name) then return false end
  self:need(string.format("%s is not on %s's route, so the limit '%s' ends at a place it does not pass (and squawk "
    .. "does not simulate where a limit ends). Should %s fly the value with no end, or did you mean another "
    .. "waypoint?", wp.name, ids[1], self:raw(i, wp.e), ids[1]))
  return true
end

-- True when a value is said straight after the word at i, its noun before it or not ("hold 250 knots", "hold
-- speed 250", "hold FL150"): the word keeps that value.
function G:value_next(i)
  local v = self:skip_fillers(i + 1)
  if self:word(v, "speed altitude level heading mach") and not self:word(v - 1, "flight") then v = v + 1 end
  local q = self:quantities(v, v + 3)[1]
  return q ~= nil and q.b == v
end

-- Value nouns named with no value in a clause of their own ("..., speeds included", "... and the speeds", "..., with
-- the heights and speeds", "..., speed restrictions too", "Levels included."): words of lexicon.route_value_nouns,
-- "and" between two of them, at most an article or possessive before them, opened by a mark, "and" or "with" and
-- closed by a word of lexicon.route_value_closers or "as well" (after a mark the closer is needed: "..., speed" is a
-- value cut off, G:dangling_value_name; "? Altitude, speed, everything" asks for them), then the end of the request
-- or a mark; no value in it. For the word at i, one of its words: the first token of the clause after its opener,
-- the token after its last word, and its first noun; nil else.
function G:values_named_alone(i)
  local function noun(x) return self:word(x, "@route_value_nouns") end
  if not noun(i) then return nil end
  local n, last = i, i
  while noun(n - 1) or (self:word(n - 1, "and") and noun(n - 2)) do n = noun(n - 1) and n - 1 or n - 2 end
  while noun(last + 1) or (self:word(last + 1, "and") and noun(last + 2)) do
    last = noun(last + 1) and last + 1 or last + 2
  end
  local b = self:word(n - 1, "the its their his her") and n - 1 or n
  local opener = self.t[b - 1]
  if b < 3 or not opener or not (opener.kind == "punct" or self:word(b - 1, "and with")) then return nil end
  -- (a list of values named, "say heading and speed", or "along with" them, asks for them: no clause of its own)
  -- (marks between the names: "say altitude... and speed")
  local named = b - 2
  while named > 1 and self.t[named].kind == "punct" do named = named - 1 end
  if self:word(named, "@value_names @route_value_nouns along") then return nil end
  local k = last + 1
  if self:word(k, "@route_value_closers") then
    k = k + 1
  elseif self:word(k, "as") and self:word(k + 1, "well") then
    k = k + 2
  elseif opener.kind == "punct" then
    return nil
  end
  if (self.t[k] and self.t[k].kind ~= "punct") or #self:quantities(b, k) > 0 then return nil end
  return b, k, n
end
-- True when the clause of G:values_named_alone opening at b follows a route instruction in its sentence (or the one
-- before, when the clause is a sentence of its own): a verb of lexicon.route_value_verbs before a route noun or
-- "navigation" ("follow the route", "resume own navigation"), no direct-to between them and the clause. The values
-- are the route's own, flown with VNAV.
function G:route_values_followed(b)
  local route = false
  for x = b - 2, 1, -1 do
    if (self.t[x].kind == "punct" and self.t[x].text ~= ",") or self:word(x, "direct dct") then return false end
    route = route or self:word(x, "@route_nouns navigation nav")
    if self:word(x, "@route_value_verbs") then return route end
  end
  return false
end
-- "direct ALFA, speeds included", "climb FL200 and the levels too": values named with no value (G:values_named_alone)
-- that no route followed reads (G:route_values_followed) and no VNAV sent carries: asked, naming the words, never
-- dropped.
-- True when the request ends with "?" and shows only an aircraft's state (POS alone read): value names in it are what
-- to show ("KAL1203 where now, and altitude?").
function G.state_shown_asked(self)
  local shown = #self.t > 0 and self.t[#self.t].text == "?" and #self.out > 0
  for _, line in ipairs(self.out) do shown = shown and line:match("^POS ") ~= nil end
  return shown
end
function G:values_named_unread()
  for _, line in ipairs(self.out) do
    if line:match("^VNAV %S+ ON$") then return end
  end
  if G.state_shown_asked(self) then return end
  -- (G:values_named_alone reads a noun at i only: G:said's guard before the scan)
  for i = 1, self:said("@route_value_nouns") and #self.t or 0 do
    local b, k, n = self:values_named_alone(i)
    if n == i and not self:in_reason(i) and not self.noted[i] then
      return self:need(string.format("I have %s. What does '%s' mean: its route's levels and speeds (VNAV ON), or "
        .. "a value to fly? Please say which.", #self.out > 0 and table.concat(self.out, " ; ") or "no instruction",
        self:raw(b, k)))
    end
  end
end
-- True when "resume normal speed" or "resume published speed" at i is the whole request to one aircraft flying its
-- route's profile (LNAV and VNAV on, named before it): the profile's speed given back, VNAV ON. Not beside another
-- instruction ("turn left heading 250, resume normal speed", "climb FL270 and ..."): VNAV ON flies the route's
-- track and levels again, undoing it.
function G:profile_speed_resumed(i)
  if not (self:word(i + 1, "normal published") and self:word(i + 2, "speed speeds")) then return false end
  local refs = self:refs_in(1, i, "aircraft")
  local r = refs[#refs]
  local a = r and self:state(r.name)
  if not (a and a.vnav == true and a.lnav == true) then return false end
  for k = 1, #self.t do
    local t = self.t[k]
    if (k < r.b or (k >= r.e and k < i) or k > i + 2) and t.kind ~= "punct" and not t.filler then return false end
  end
  return true
end

-- Finds the phrases of lexicon.not_simulated, marks their tokens used (the
-- rest of the request is read as if they were not there) and returns the
-- reply naming them, or nil. A phrase runs from its word to the next
-- instruction word, "and"/"then", or punctuation other than a comma (a class
-- with `one_value`: to its first number, inclusive).
-- The end of a clock time of four figures, hours and minutes ("1215", "one two one five"), said straight after
-- "after" or "before" within the four tokens after i ("cross GOMUP at or after 1215", "not before one two one
-- five") and ending its clause (a value after it, "... after 1215 at FL390", is the crossing's: none); nil when none.
function G:clock_limit(i)
  for k = i + 1, math.min(#self.t, i + 4) do
    if self:word(k, "after before") then
      local q = self:quantities(k + 1, math.min(#self.t + 1, k + 6))[1]
      local four = q and (q.e - q.b == 4 or (q.e - q.b == 1 and self.t[q.b].text:match("^%d%d%d%d$") ~= nil))
      local closes = q and (not self.t[q.e] or self.t[q.e].kind == "punct" or self:word(q.e, "and then"))
      if four and closes and q.b == k + 1 and q.kind == "plain" and q.value % 1 == 0 and q.value < 2400
          and q.value % 100 < 60 then
        return q.e
      end
      return nil
    end
  end
  return nil
end
-- True when the clause from token b (to its next punctuation) opens with a vertical speed: a noun of
-- lexicon.clause_rates ("rate", "vertical speed") with a value after it in the clause, or a value with a unit of
-- vertical speed ("3000 fpm", "at 2000 a minute").
function G:clause_opens_rate(b)
  local e = b
  while self.t[e] and self.t[e].kind ~= "punct" do e = e + 1 end
  local qs = self:quantities(b, e)
  local at = self:word(b, "at") and b + 1 or b
  if qs[1] and qs[1].kind == "vs" and qs[1].b == at then return true end
  if not (self:word(b, "@clause_rates") and self:intent_at(b) == "vs") then return false end
  for _, q in ipairs(qs) do
    if q.kind == "vs" or q.kind == "plain" then return true end
  end
  return false
end

function G:not_simulated()
  local found, seen, after = {}, {}, {}
  local i = 1
  while i <= #self.t do
    local t = self.t[i]
    local class
    if t.kind == "word" and NOT_SIMULATED_WORDS[t.text] and (not self.u:used(i) or #self:refs_in(i, i + 1, "waypoint") > 0)
        and not self:navaid_named_beside(i) then
      for _, c in ipairs(NOT_SIMULATED_WORDS[t.text]) do
        if (not c.near or self:near_any(i, c.near, c.window))
            and (not c.and_near or self:near_any(i + (c.window or 4), c.and_near[1], c.and_near[2]))
            and (not c.after_callsign or self:callsign_before(i))
            and (not c.named_after or (self.t[i + 1] and self.t[i + 1].kind == "word"
              and (self.t[i + 1].raw:match("^%u") or #self:refs_in(i + 1, i + 2, "waypoint") > 0)))
            and (not c.last or self:said_last(i, c.last ~= true and c.last or nil, c.own_clause))
            and (not c.subject or self:said_after_subject(i, c.subject))
            and (not c.after_heading or self:after_heading(i))
            and not (c.not_before and self:word(self:skip_fillers(i + 1), c.not_before))
            and not (c.not_to_profile and self:profile_speed_resumed(i))
            and not (c.no_value and self:value_next(i))
            and not (c.no_number_after and self.t[i + 2] and self.t[i + 2].kind == "number")
            and (not c.clock or self:clock_limit(i))
            and not (c.not_after and self:word(i - 1, c.not_after)) and not self:word(i + 1, "not")
            and (not c.bare or self:said_bare(i)) and (not c.manner or self:said_as_manner(i))
            and (not c.rate_manner or self:rate_manner(i))
            and (not c.after_instruction or self:instruction_before(i)) then
          local expected = c.not_aircraft_to and self:aircraft_then_to(i + 1)
          if c.routed and self:limit_off_route(i, c.window) then break end
          if expected then
            self:need(string.format("Is '%s' an instruction to send now, or what you expect to happen? Please "
              .. "say the instruction itself.", self:raw(i, expected.e)))
            break
          end
          class = c
          break
        end
      end
    end
    if class then
      local e, comma, level_at = i + 1, false, nil
      if class.rate_manner then
        local b, rate_e, gentler, doubt = self:rate_manner(i)
        if doubt then
          self:need(string.format("Is '%s' the level to fly or the rate, in feet per minute? I heard '%s' before it.",
            self:raw(doubt.b, doubt.e), self:raw(b, rate_e)))
          break
        elseif gentler then
          self:need(string.format("What vertical speed should it fly, in feet per minute? '%s' names none, and squawk "
            .. "flies the aircraft's own rate.", self:raw(b, rate_e)))
          break
        end
        i, e = b, rate_e
      end
      if class.clock then e = self:clock_limit(i) end
      while e <= #self.t and not class.manner and not class.rate_manner and not class.clock do
        local x = self.t[e]
        comma = comma or (x.kind == "punct" and x.text == ",")
        -- (a comma goes on: "hold at BAKUR, left hand pattern, inbound track 270" is one clearance)
        -- (nor does it take a negation: "hold present level, do not climb to FL350" leaves "do not" to be read,
        -- "cancel speed restriction but no need to ..." leaves "no need")
        if (x.kind == "punct" and x.text ~= ",") or (x.kind == "word" and (x.text == "and" or x.text == "then"))
            or self:word(e, "not never don't dont") or (self:word(e, "do") and self:word(e + 1, "not"))
            or (self:word(e, "no") and self:word(e + 1, "need needs")) then
          break
        end
        if class.stops_at_value and comma and x.kind == "number" then break end
        if class.one_value and x.kind == "number" then
          e = e + 1
          break
        end
        -- (its value in spoken digits, "QNH one zero one one, one seven zero knots": the phrase ends with the
        -- digits' quantity, and the speed after the comma is an instruction)
        if class.one_value and x.kind == "word" and G.digit_words[x.text] then
          local q = self:quantities(e, math.min(#self.t + 1, e + 8))[1]
          if q and q.b == e then
            e = q.e
            break
          end
        end
        -- ("hold at KOK 2000ft", "holding over COA, FL120", "hold at KOK at FL120": a level with its unit straight
        -- after the fix, or after the fix and a comma or "at", is the level flown there, no part of the hold; a bare
        -- number there is asked)
        if class.level_after_place and #self:refs_in(e - 1, e, "waypoint") > 0 then
          local v = (x.text == "," or self:word(e, "at")) and e + 1 or e
          local q = self:quantities(v, v + 3)[1]
          -- (a level the aircraft flies already is the hold's: "hold at GOBAS, FL240" at FL240 changes nothing)
          local a = q and q.kind == "alt" and self:refs_in(1, i, "aircraft")[1]
          local now, ft = a and self:state(a.name), q and q.kind == "alt" and level_feet(handlers.format.alt(q.value, q.fl))
          if q and q.kind == "alt" and q.b == v and not (now and now.alt_ft and ft and math.abs(now.alt_ft - ft) <= 50) then
            level_at = q.e
            break
          end
          if q and q.kind == "plain" and q.b == v then
            self:need(string.format("squawk does not simulate holding patterns. Is '%s' the altitude to fly at %s? "
              .. "Please say it with its unit (\"%s ft\" or a flight level).", self:raw(v, q.e), self:raw(e - 1, e),
              self:raw(v, q.e)))
            break
          end
        end
        -- ("squawk 4721 at GRR descend FL290", "contact Chicago when 40 miles from GRR descend FL290"): a
        -- condition after the phrase of a class that takes no time anchors the instruction said after it with
        -- no punctuation between, so the phrase ends before it
        if not class.takes_time and not class.able and (self:word(e, "@condition") or (self:word(e, "at")
            and #self:refs_in(e + 1, e + 2, "waypoint") > 0)) then
          local k = e + 1
          while self.t[k] and self.t[k].kind ~= "punct" and not self:intent_at(k) do k = k + 1 end
          if self.t[k] and self.t[k].kind ~= "punct" then break end
        end
        -- ("traffic eleven o'clock, turn left 20 degrees": a clause opening with an imperative verb of
        -- lexicon.clause_verbs after a comma is an instruction, also after traffic information)
        if class.to_end and x.text == "," and self:word(e + 1, "@clause_verbs") and self:intent_at(e + 1) then break end
        -- ("expedite descent FL140 traffic below, rate three thousand or more", "..., at 2000 fpm or more": a
        -- vertical-speed noun of lexicon.clause_rates with a value in its clause, or a vertical speed with its unit,
        -- opening the clause after a comma is the rate of the climb or descent said before the traffic, never the
        -- traffic's)
        if class.to_end and x.text == "," and self:intent_at(self:find_word(1, i, "@clause_verbs")) == "alt"
            and self:clause_opens_rate(e + 1) then
          break
        end
        -- ("expect ILS runway 05 right descend 11000": a runway designator, its number and side, completes what
        -- a class with `clause` announces; an imperative verb of lexicon.clause_verbs after it is an instruction)
        if class.clause and self:word(e, "@clause_verbs") and self:intent_at(e) then
          local r = e - 1
          local side = self.t[r] and self.t[r].kind == "word" and self.t[r].raw:lower()
          if side == "left" or side == "right" or side == "center" or side == "centre" or side == "l" or side == "r"
              or side == "c" then
            r = r - 1
          end
          -- (its number typed, or said as one or two digit words: "runway zero two left", "runway tree two right")
          local d = r
          while d > r - 2 and self.t[d] and (self.t[d].kind == "number" or self.t[d].number_word) do d = d - 1 end
          if d < r and self:word(d, "runway rwy") then break end
        end
        -- ("expect further descent in five minutes, for now FL180": a class with `clause` ends at a comma before
        -- a clause said for the meantime, "now" in its first three words, with a level, speed or heading)
        if class.clause and x.text == "," and self:word_in(e + 1, e + 4, "now meanwhile meantime")
            and self:clause_value(e + 1) then
          break
        end
        -- (a turn direction goes on: "make a left three sixty" is one orbit)
        -- (a class with `clause` goes on through instruction words up to its first comma: "expect to resume own
        -- navigation to MNR" announces all of it)
        -- (nor a unit's word straight after its name, said after the phrase's word: "contact Marseille information"
        -- names a station)
        local unit = FACILITIES[self.words[e] or ""] and e - 1 > i and self.t[e - 1].kind == "word"
          and not self.t[e - 1].keyword and not self:intent_at(e - 1) and not self.t[e - 1].number_word
        if not class.to_end and self:intent_at(e) and not self:word(e, "approach cleared hold holding contact left right")
            and not unit and not (class.through and self:word(e, class.through)) and not (class.clause and not comma) then
          break
        end
        -- (a limit said last ends before the callsign said after it, a comma between at most: "until 4 DME, KLM12",
        -- G:said_last)
        if class.last and (#self:refs_in(e, e + 1, "aircraft") > 0
            or (x.text == "," and #self:refs_in(e + 1, e + 2, "aircraft") > 0)) then
          break
        end
        e = e + 1
      end
      -- ("then Gander on 128.5", "Shanwick Oceanic on ..."): with `station_before`, one or two capitalised words
      -- straight before the phrase, no aircraft, keyword or instruction word, are the station named, part of it
      for _ = 1, class.station_before and 2 or 0 do
        local w = self.t[i - 1]
        if not (w and w.kind == "word" and w.raw:match("^%u") and not w.keyword and not self:intent_at(i - 1)
            and #self:refs_in(i - 1, i, "aircraft") == 0) then
          break
        end
        i = i - 1
      end
      -- "when passing FL250 contact Langen 120.8": a condition said before the phrase is part of it; so is
      -- the position it is said at ("at 30 West contact Gander") and the place it waits for ("after DETAK
      -- expect vectors")
      local b = i - 1
      while b >= 1 and self.t[b].kind ~= "punct" and not self:word(b, "@condition and then at") do b = b - 1 end
      local at = self:word(b, "at") and self:quantities(b + 1, i)[1]
      local placed = at and (at.kind == "lat" or at.kind == "lon")
      local place = self:word(b, "after") and #self:refs_in(b + 1, i, "waypoint") > 0
      if b >= 1 and b < i - 1 and (self:word(b, "@condition") and #self:quantities(b + 1, i) > 0 or placed or place)
          and not self:any_instruction_in(b + 1, i) and (b == 1 or self.t[b - 1].kind == "punct" or self:callsign_before(b)) then
        self:mark_used(b, i)
        for k = b, i - 1 do self.noted[k] = true end
      end
      local said = self:raw(i, e)
      -- "make one orbit, then resume own navigation": what follows "then" waits for what is not flown
      local k = self:word(e, "and") and e + 1 or e
      -- ("hold for ten minutes, after that descend 9000": a word of sequence the phrase ran through is the same)
      local later = self:word(k, "then") and k + 1
      -- ("hold at KOK FL90 then heading 200": "then" after the level flown in the hold waits for the hold too)
      if level_at then
        local a = (self.t[level_at] and self.t[level_at].text == ",") and level_at + 1 or level_at
        a = self:word(a, "and") and a + 1 or a
        later = later or (self:word(a, "then") and a + 1)
      end
      for x = i + 1, e - 1 do
        if self:word(x, "afterwards thereafter") or (self:word(x, "after") and self:word(x + 1, "that")) then later = e end
      end
      if class.takes_time and later then
        after[#after + 1] = { at = later, what = class.what, said = said }
      end
      -- (a manner is noted only: its instruction is read with it, "expedite descent FL200")
      if not class.manner then self:mark_used(i, e) end
      for k = i, e - 1 do self.noted[k] = true end
      if not seen[class.what] then
        seen[class.what] = true
        found[#found + 1] = string.format("%s ('%s')", class.what, (said:gsub(" ([,.;:])", "%1"):gsub(",$", "")))
      end
      i = e
    else
      i = i + 1
    end
  end
  if #found == 0 then return nil end
  for _, a in ipairs(after) do
    if self:any_instruction_in(a.at, #self.t + 1) then
      self:need(string.format("squawk does not simulate %s ('%s'), and what is said after it waits for it: "
        .. "please give that instruction when it applies.", a.what, (a.said:gsub(" ([,.;:])", "%1"):gsub(",$", ""))))
    end
  end
  return "squawk does not simulate " .. table.concat(found, ", ") .. ": nothing was sent for that."
end

-- A flight level of one or two figures under FL20 ("KLM77 fl 1 1", "fl 2 10 knots": FL11, FL2) is no level a
-- controller clears, only figures split or cut short: asked, never issued.
function G:short_level()
  for _, line in ipairs(self.out) do
    local id, fl = line:match("^ALT (%S+) FL(%d%d?)%f[%D]")
    if fl and tonumber(fl) < 20 then
      return self:need(string.format("Which level should %s fly? 'FL%s' is %s ft, and a flight level has three "
        .. "figures: please say it again.", id, fl, tonumber(fl) * 100))
    end
  end
end

-- An altitude or a protected zone half height under G.least_told ft, or a vertical speed under G.least_told ft/min,
-- other than 0 (level off, on the ground), in an ALT, VS, CRE, MOVE or ZONEDH line ("descend to 9 ft", a number
-- cut short or written with a point before three figures: "1.000"), is none an aircraft is told: asked, naming the
-- value, its unit and the number heard for it, never issued.
-- "DLH3 speed 250, sorry, 250 is too fast", "climb FL300... no, that's too high", "speed 250, sorry, too fast": a
-- value judged after it is said (lexicon.judged_values: "too" and a word of its `too` list, the subject before them
-- with only words of `between` in the way) is taken back: the value said again as the subject (the same digits) or,
-- straight after a run of self-correction markers that follows the value, a pronoun of `pronouns` or no subject at
-- all. When a command of self.out still carries those digits the request is asked, never issued. ("it is too high
-- for my scenario" after a value with no marker judges the aircraft, the reason for the instruction.)
G.value_judgement = { too = set_of(lexicon.judged_values.too), between = set_of(lexicon.judged_values.between),
             pronouns = set_of(lexicon.judged_values.pronouns) }
function G:value_rejected()
  local J = self.value_judgement
  if not self:said("too") then return end  -- (the judgement's word; G:said's guard before the scan)
  for k = 2, #self.t - 1 do
    if self:word(k, "too") and self.t[k + 1].kind == "word" and J.too[self.t[k + 1].text] then
      local j = k - 1
      while j >= 1 and self.t[j].kind == "word" and J.between[self.t[j].text] and not J.pronouns[self.t[j].text] do
        j = j - 1
      end
      local judged  -- the quantity judged
      local said = self:quantities(1, j + 1)
      local last = said[#said]
      local from = j + 1  -- (where the judgement opens)
      if last and last.e == j + 1 and last.number then
        from = last.b
        for _, o in ipairs(said) do
          if o.e <= last.b and o.number and o.number.digits == last.number.digits then judged = o end
        end
      else
        if J.pronouns[self.words[j] or ""] then from = j end
        local m = (self.t[j] and self.t[j].kind == "word" and J.pronouns[self.t[j].text]) and j - 1 or j
        local marked = false
        while m >= 1 and (self.t[m].kind == "punct" or self.t[m].filler or SC_MARKERS[self.t[m].text]
            or self:word(m, "@correction")) do
          marked = marked or SC_MARKERS[self.t[m].text] or self:word(m, "@correction")
          m = m - 1
        end
        if marked and last and last.e == m + 1 and last.number then judged = last end
      end
      local digits = judged and judged.number.digits
      for _, line in ipairs(digits and self.out or {}) do
        if (" " .. line .. " "):find("[%s%a]" .. digits .. "%s") then
          local e = k + 2
          while self.t[e] and self.t[e].kind ~= "punct" do e = e + 1 end
          return self:need(string.format("I have %s, but you said '%s' after '%s'. What should it be instead?",
            table.concat(self.out, " ; "), (self:raw(from, e):gsub(" ([,.;:])", "%1")), self:raw(judged.b, judged.e)))
        end
      end
    end
  end
end
-- "DLH3 avoid FL300", "DLH3 forget about the climb to FL300", "stay clear of FL300", "hold off on the climb to FL300":
-- a phrase of lexicon.kept_from said before an instruction word or a value (only its `between` words in the way),
-- with no instruction word or value said before it since the aircraft named or the sentence began (after one it
-- corrects: "climb FL300, disregard, FL310"), keeps the aircraft from what it names: when a command of self.out
-- carries a value or a name said in its clause, the request is asked, never issued.
-- (G.withholding.first[w]: the phrases opening with word w, their words each, longest first)
G.withholding = { between = set_of(lexicon.kept_from.between), first = {} }
for _, p in ipairs(lexicon.kept_from.phrases) do
  local words = {}
  for w in p:gmatch("%S+") do words[#words + 1] = w end
  local list = G.withholding.first[words[1]] or {}
  list[#list + 1] = words
  table.sort(list, function(a, b) return #a > #b end)
  G.withholding.first[words[1]] = list
end
function G:instruction_withheld()
  local W = self.withholding
  local out
  for k = 1, #self.t - 1 do
    local e
    for _, words in ipairs(W.first[self.t[k].text] or {}) do
      local x = k
      for _, w in ipairs(words) do
        if not (self.t[x] and self.t[x].kind == "word" and self.t[x].text == w) then x = nil break end
        x = x + 1
      end
      if x then e = x break end
    end
    local n = e
    while n and self.t[n] and self.t[n].kind == "word" and W.between[self.t[n].text] do n = n + 1 end
    local named = n and self.t[n] and (self:intent_at(n) or (self:quantities(n, #self.t + 1)[1] or {}).b == n)
    -- (nothing said before it that it could correct)
    local b = k - 1
    while named and b >= 1 and not (self.t[b].kind == "punct" and self.t[b].text ~= ",") and not self:has_ref(b, b + 1, "aircraft") do
      if self:intent_at(b) or #self:quantities(b, b + 1) > 0 then named = false end
      b = b - 1
    end
    if named then
      out = out or " " .. table.concat(self.out, " ; "):upper() .. " "
      local c = n
      while self.t[c] and self.t[c].kind ~= "punct" do c = c + 1 end
      local carried = false
      for _, q in ipairs(self:quantities(n, c)) do
        local d = q.number and q.number.digits
        carried = carried or (d ~= nil and out:find("[%s%a]" .. d .. "[%s;]") ~= nil)
      end
      for _, r in ipairs(self:refs_in(n, c, "waypoint")) do
        carried = carried or out:find(" " .. r.name:upper() .. " ", 1, true) ~= nil
      end
      if carried then
        return self:need(string.format("I have %s, but you said '%s' before it. Should it be flown? Please say "
          .. "the instruction again.", table.concat(self.out, " ; "), (self:raw(k, c):gsub(" ([,.;:])", "%1"))))
      end
    end
  end
end
G.least_told = 100  -- [ft], [ft/min]
G.told_values = { alt = { "an altitude", "ft" }, vs = { "a vertical speed", "ft/min" },
                  zone = { "a protected zone half height", "ft" } }
G.told_units = set_of({ "ft", "feet", "foot", "fpm", "m", "metres", "meters" })
-- A heading's number said with a unit of another measure after it, no number after that ("heading 200 knots",
-- "turn left heading 200 ft", "heading 090 miles"; "hdg 320 m.80" is the Mach's) is no heading for sure (a speed or a level may be meant): asked, never flown.
G.heading_foreign_units = { knots = true, knot = true, kts = true, kt = true, feet = true, ft = true, foot = true,
  metres = true, meters = true, miles = true, nm = true, fpm = true, kmh = true, mph = true }
function G:heading_unit()
  for _, line in ipairs(self.out) do
    local v = line:match("^HDG %S+ (%d+)")
    v = v and tonumber(v)
    for i, t in ipairs(v and self.t or {}) do
      local after = self.t[i + 1]
      if t.kind == "number" and tonumber(t.num) and math.floor(tonumber(t.num) + 0.5) % 360 == v % 360
          and after and after.kind == "word" and G.heading_foreign_units[after.text]
          and not (self.t[i + 2] and self.t[i + 2].kind == "number")  -- ("hdg 320 kt 250": the next value's unit)
          and self:word_in(math.max(1, i - 3), i, "heading hdg turn") then
        return self:need(string.format("I have %s, but I heard '%s %s' for the heading. Is it a heading, or a "
          .. "speed or level?", table.concat(self.out, " ; "), t.raw, after.raw))
      end
    end
  end
  -- (the heading said in words, "heading two seven zero knots": the heading's number, then the unit's word)
  for _, q in ipairs(self:quantities(1, #self.t + 1)) do
    local n, u = q.number, q.number and self.t[q.number.e]
    if q.kind == "heading" and u and u.kind == "word" and G.heading_foreign_units[u.text]
        and not (self.t[n.e + 1] and self.t[n.e + 1].kind == "number") then
      return self:need(string.format("I have %s, but I heard '%s %s' for the heading. Is it a heading, or a "
        .. "speed or level?", table.concat(self.out, " ; "), self:raw(n.b, n.e), u.raw))
    end
  end
end
-- A Mach number of 1 or more, or under 0.1, in a command ("speed 250 mach": M0250, "speed mach 250": M02.5, "78
-- mach": M078) is no speed meant for traffic squawk flies: asked, naming what was heard, never sent.
function G:implausible_mach()
  for _, line in ipairs(self.out) do
    for m in line:gmatch("%f[%w]M(0[%d%.]*)%f[%W]") do  -- (as f.mach writes a Mach number)
      local v = tonumber(m)
      if v and (v >= 1 or v < 0.1) then
        return self:need(string.format("I have %s, but Mach %s is no speed an airliner flies. Which Mach number "
          .. "(e.g. 0.78) or speed in knots do you mean?", table.concat(self.out, " ; "), m:gsub("^0+(%d)", "%1")))
      end
    end
  end
end
function G:implausible_values()
  local function small(v)
    v = tonumber(v)
    return v ~= nil and v ~= 0 and math.abs(v) < G.least_told
  end
  for _, line in ipairs(self.out) do
    local f = {}
    for w in line:gmatch("%S+") do f[#f + 1] = w end
    -- (the value's kind and field: an ALT's rate after its altitude; CRE's altitude after its position (a place, or
    -- a latitude and longitude) and heading; MOVE's after its position)
    local kind, k
    if f[1] == "ALT" then
      kind, k = small(f[3]) and "alt" or "vs", small(f[3]) and 3 or 4
    elseif f[1] == "VS" then
      kind, k = "vs", 3
    elseif f[1] == "ZONEDH" then
      kind, k = "zone", 2
    elseif f[1] == "CRE" then
      kind, k = "alt", tonumber(f[4]) and 7 or 6
    elseif f[1] == "MOVE" then
      kind, k = "alt", tonumber(f[3]) and 5 or 4
    end
    if kind and small(f[k]) then
      -- (the number heard for it: one with its unit after it first, "8 ft" rather than the "8" of "8 E")
      local v, heard, unit = math.floor(math.abs(tonumber(f[k])) + 0.5), nil, nil
      for pass = 1, 2 do
        for i, t in ipairs(self.t) do
          local after = self.t[i + 1] and self.t[i + 1].kind == "word" and self.t[i + 1]
          if not heard and t.kind == "number" and math.floor(math.abs(t.num) + 0.5) == v
              and (pass == 2 or after and G.told_units[after.text]) then
            heard, unit = t.raw, after and G.told_units[after.text] and " " .. after.raw or ""
          end
        end
      end
      local what = G.told_values[kind]
      local doubt = heard and string.format(" I heard '%s%s'.", heard, unit) or ""
      if heard and heard:match("^%d%d?%d?%.%d%d%d$") then
        doubt = string.format(" I heard '%s%s': %s, with the point grouping thousands?", heard, unit,
          (heard:gsub("%.", "")))
      end
      return self:need(string.format("I have %s, but %s of %s %s is too small to be meant.%s Which value do you "
        .. "mean?", line, what[1], f[k], what[2], doubt))
    end
    -- (a vertical speed above G.most_rate [ft/min], "climb to 30000 feet per minute": a level said with a rate's
    -- unit, no rate an airliner flies)
    local rate = (f[1] == "VS" and tonumber(f[3])) or (f[1] == "ALT" and tonumber(f[4]))
    if rate and math.abs(rate) > G.most_rate then
      return self:need(string.format("I have %s, but a vertical speed of %s ft/min is too large to be meant. Is it a "
        .. "level, or which rate do you mean?", line, math.floor(math.abs(rate) + 0.5)))
    end
  end
end
G.most_rate = 8000  -- [ft/min]

-- One setting of the simulation given two values in one request ("dtmult 8, and then 4x", "zoner 5 then 3"): the
-- second would replace the first at once, with no time between (a fast-forward between them is one: "dtmult 8, ff
-- 60, dtmult 4"), so which value, and from when, is asked. (G.set_once: the commands of one value and no aircraft.)
G.set_once = { DTMULT = "rate should the simulation run at", ZONER = "protected zone radius should be used",
  ZONEDH = "protected zone half height should be used", DTLOOK = "look-ahead time should be used" }
-- M.setting_twice(lines) -> the question for a list of commands, or nil (the list of typed command clauses is
-- asked the same: graph.lua).
function M.setting_twice(lines)
  local first = {}
  for _, line in ipairs(lines) do
    local name, value = line:upper():match("^(%u+) (%S+)$")
    if name and G.set_once[name] then
      if first[name] and first[name] ~= value then
        return string.format("I have %s. Which %s: %s or %s, and from when? Please say the time of the "
          .. "second (\"in 5 minutes\") or one value.", table.concat(lines, " ; "), G.set_once[name], first[name],
          value)
      end
      first[name] = value
    elseif line:upper():match("^FF") then
      first = {}
    end
  end
end
function G:setting_twice()
  local q = M.setting_twice(self.out)
  if q then return self:need(q) end
end

-- "Is DTMULT still 5?", "is the look-ahead still 300 seconds?": a request opening with "is" or "are" and no verb of
-- setting (lexicon.setting_verbs), or asking in a statement's word order ("the seed is 3?", "the trails are on?":
-- m:statement_order_question), asks about a value; a setting given a value (a command with a value and no
-- aircraft) is asked, never set.
-- (a modal or "does" opening a question about a thing, no person: "can the resolution use vertical direction?",
-- "does the resolution use vertical?", "will the detection use 5 NM?": its first sentence ends with "?"; "could"
-- and "would", "be" ("can the detection be switched on?") or "please" in it make a polite request, read)
function G:setting_question()
  local first = self:request_start()
  local ends = self:first_sentence_end()
  local modal = self:word(first, "does do can will") and not self:word(first + 1, "you u we i it someone somebody")
    and self.t[ends].text == "?" and not self:word_in(first, ends, "be please")
  if not (self:word(first, "is are") or modal or self:statement_order_question(first, self:first_sentence_end()))
      or self:word_in(1, #self.t + 1, "@setting_verbs") then
    return
  end
  for _, line in ipairs(self.out) do
    local cmd, value = line:match("^(%u+) (%S+)")
    if cmd and not self:state(value) then
      return self:need(string.format("Should %s be shown, or set to %s? To set it, please say \"set %s\".", cmd,
        line:sub(#cmd + 2), line))
    end
  end
end

-- "trails on, 8 acft", "hold, 5 aircraft": a count of aircraft (G:aircraft_count) set off alone in its clause, with
-- nothing but punctuation, fillers and courtesy around it, that no command took: what it is for is asked
function G:count_alone()
  for _, q in ipairs(self:quantities(1, #self.t + 1)) do
    if self:aircraft_count(q) and self:word(q.e, "@counted_aircraft") and not self.taken[q.b] then
      local function plain(x) return self.t[x].kind == "punct" or self.t[x].filler or self:word(x, "please thanks") end
      local b, e = q.b - 1, q.e + 1
      while b > 0 and self.t[b].kind ~= "punct" and plain(b) do b = b - 1 end
      while e <= #self.t and self.t[e].kind ~= "punct" and plain(e) do e = e + 1 end
      if (b == 0 or self.t[b].kind == "punct") and (e > #self.t or self.t[e].kind == "punct") and b > 0 then
        return self:need(string.format("I have %s. What does '%s' mean?", table.concat(self.out, " ; "),
          self:raw(q.b, q.e + 1)))
      end
    end
  end
end

-- True when a level this request clears an aircraft other than `id` to is not on the side `side` (1 above, -1
-- below, 0 none) of aircraft id's level: "descend to FL220 below DLH7" with DLH7 at FL200.
function G:level_contradicts(id, side)
  local a = side ~= 0 and self:state(id)
  if not a then return false end
  for _, line in ipairs(self.out) do
    local cid, v = line:match("^ALT (%S+) (%S+)")
    local ft = v and (v:match("^FL(%d+)$") and tonumber(v:match("^FL(%d+)$")) * 100 or tonumber(v))
    if ft and cid ~= id and (ft - a.alt_ft) * side <= 0 then return true end
  end
  return false
end
-- An aircraft the request names beside the one it instructs, never silently made an addressee nor dropped:
-- - after a preposition of place or order with another aircraft instructed and a value said before it, when it
--   is instructed too, after "over" or "behind" (a sequence or a crossing squawk cannot wait for: "KLM12 climb
--   FL300 over BAW5", "reduce to 250 behind BAW5"), or after "above"/"below" with the level cleared on the other
--   side of its level: traffic or a reference, asked ("FL190 below SAS310" at FL200, "ahead of", is read);
-- - said before a verb of staying ("BAW5 stays at FL240", "remains", "keeps", "will stay", "is to maintain")
--   with no command of its own: its own statement, asked, never dropped while the rest runs;
-- - instructed after a word taking back what came before ("KLM12 heading 200, sorry, TRA34 climb FL300", "I
--   mean", "correction") when the aircraft before it is instructed too: which stands is asked, never both.
G.reference_prepositions = "over above below beneath under underneath behind"
G.staying_verbs = "stays stay remains remain keeps keep maintains maintain continues holds staying remaining keeping"
G.addressee_taken_back = "sorry correction disregard negative actually rather scratch belay"
function G:aircraft_aside()
  local function commanded(id)
    for _, line in ipairs(self.out) do
      if line:find("%f[%w]" .. id .. "%f[%W]") then return line end
    end
    return nil
  end
  local function other_commanded(id)
    for _, line in ipairs(self.out) do
      local cid = line:match("^%u+ (%S+)")
      if cid and cid ~= id and self:state(cid) then return line end
    end
    return nil
  end
  -- (a distance or a height said straight before k, no flight level: "1000 feet below AC01", "5 miles behind")
  local function measured(k)
    for _, q in ipairs(self:quantities(math.max(1, k - 4), k)) do
      if q.e >= k - 1 and not q.fl and (q.kind == "alt" or q.kind == "dist") then return true end
    end
    return false
  end
  -- (a value said before k: the preposition follows an instruction's value, not a description before it)
  local function valued(k)
    for x = 1, k - 1 do
      if self.t[x].kind ~= "word" and self.t[x].kind ~= "punct" then return true end
    end
    return false
  end
  local prev
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" and r.exists and not r.false_start then
      local id = r.name:upper()
      local k = self:word(r.b - 1, "the") and r.b - 2 or r.b - 1
      -- (none in a reason or purpose, "so it passes over TEST02", nor after a value it measures from, "1000 feet
      -- below AC01", which the value's instruction reads)
      local p = self:word(k, "of") and self:word(k - 1, "ahead") and k - 1 or k
      if (self:word(k, G.reference_prepositions) or p < k) and other_commanded(id) and not self:in_reason(k)
          and not measured(p) and valued(p)
          and (commanded(id) or self:word(k, "behind over") or self:level_contradicts(id, self:word(k, "above") and 1
            or self:word(k, "below beneath under underneath") and -1 or 0)) then
        return self:need(string.format("I have %s. Is %s, named after '%s', to get an instruction, or is it "
          .. "traffic or a reference? Please give each aircraft its own instruction.", table.concat(self.out, " ; "),
          id, self:raw(p, k + 1)))
      end
      -- ("KLM12 climb FL300 and follow BAW5", "..., keep following the BAW5": a sequence squawk cannot fly, told as
      -- an instruction, never dropped while the rest runs)
      if (self:word(k, "follow") and not self:word(k - 1, "to will would should can could") or self:word(k, "following")
          and self:word(k - 1, "keep")) and not self:in_reason(k) then
        return self:need(string.format("I have %s, but squawk cannot make an aircraft '%s %s'. Should I give the rest, "
          .. "or nothing?", table.concat(self.out, " ; "), self.t[k].raw, id))
      end
      local v = r.e
      if self:word(v, "will is shall should") then v = v + 1 end
      if self:word(v, "to") then v = v + 1 end
      if self:word(v, G.staying_verbs) and not commanded(id) then
        -- (no value in its clause, or the level it is at or cleared to, "stays at 200" at FL200: nothing to send,
        -- said in the note; a place or another value is asked)
        local e = v + 1
        while self.t[e] and self.t[e].kind ~= "punct" and not self:has_ref(e, e + 1, "aircraft")
            and not self:word(e, "and @then_words") do
          e = e + 1
        end
        local qs, a = self:quantities(v + 1, e), self:state(id)
        local level = #qs == 1 and (qs[1].kind == "alt" and self:cleared_level(qs[1]) or qs[1].value)
        local held = a and not self:has_ref(v + 1, e, "waypoint") and (#qs == 0 or level and
          (level == a.sel_alt_ft or level == a.alt_ft or level * 100 == a.sel_alt_ft))
        if held then
          self.kept_note = string.format("%s%s keeps what it has ('%s'): nothing was sent for it.",
            self.kept_note and self.kept_note .. " " or "", id, self:raw(r.b, e))
          goto next_ref
        end
        return self:need(string.format("I have %s. What should %s do: keep what it has (nothing to send), or is "
          .. "'%s' an instruction for it? Please say it as one.", table.concat(self.out, " ; "), id,
          self:raw(r.b, v + 1)))
      end
      if prev and prev.id ~= id and commanded(id) and commanded(prev.id) then
        for x = prev.e, r.b - 1 do
          if self:word(x, G.addressee_taken_back) or (self:word(x, "mean meant") and self:word(x - 1, "i")) then
            return self:need(string.format("I have %s. Does '%s' take back what %s was given, or do both stand? "
              .. "Please say again what each aircraft should do.", table.concat(self.out, " ; "),
              self:word(x, "mean meant") and self:raw(x - 1, x + 1) or self.t[x].raw, prev.id))
          end
        end
      end
      ::next_ref::
      prev = { id = id, e = r.e }
    end
  end
end

-- An offer or a question of wish to the pilot ("KLM12, would you like to climb FL300?", "do you want FL300",
-- "would you prefer heading 250") clears nothing: the pilot is asked, no clearance given. The draft is asked about,
-- never sent. lower: the request in lower case.
G.offer_phrases = { "would you like", "would you prefer", "would you want", "do you want", "do you wish",
  "do you prefer", "do you like", "d'you want", "are you happy with", "is that acceptable", "can you accept",
  "could you accept" }
function G:offer_question(lower)
  if not lower:find("you", 1, true) and not lower:find("accept", 1, true) then return end
  for _, p in ipairs(G.offer_phrases) do
    local b, e = lower:find("%f[%a]" .. p:gsub(" ", "%%s+") .. "%f[%A]")
    if b then
      return self:need(string.format("'%s' offers the pilot a choice, no instruction. Should I give %s? Please say "
        .. "it as an instruction.", lower:sub(b, e), table.concat(self.out, " ; ")))
    end
  end
end

-- the words of a condition on the traffic (G:declared)
G.traffic_condition_words = "traffic conflict conflicts conflicting separation separated spacing clear free close "
  .. "closer intruder alert alerts collision proximity crossing converging"
-- the words opening a condition on the traffic that no command waits for, asked with the clause they open
G.condition_openers = { ["if"] = true, unless = true, provided = true, providing = true }
-- ("if 721 reaches FL270 then heading 060", "unless KLM12 is at FL270, heading 060", "provided KLM12 is at FL270
-- then ..."): a word of G.condition_openers straight before an aircraft's callsign, its clause (to the next mark or
-- "then") holding a value or a place, no modal after the callsign ("if KLM12 could climb" is a wish), no wish framed
-- before "if" (G:wish_frame: "it's better if THY7 turns ...") and no
-- "able", "possible" or "ready" in it ("if KLM12 is able, climb ..."), is a
-- condition on that aircraft's state. Asked when no command waits for it (one that begins AT..., ATALT, ATSPD,
-- ATDIST), and always after "unless", "provided", "providing" (never read as waiting): never sent at once.
function G:condition_dropped()
  for _, r in ipairs(self.refs) do
    local i = r.kind == "aircraft" and r.b - 1
    local opener = i and i >= 1 and self.t[i].kind == "word" and G.condition_openers[self.t[i].text] and self.t[i].text
    if opener and not (self.t[r.e] and MODALS[self.t[r.e].text]) and not (opener == "if" and self:wish_frame(i)) then
      local e = r.e
      while self.t[e] and not (self.t[e].kind == "punct" and self.t[e].text ~= "'") and not self:word(e, "then") do
        e = e + 1
      end
      local q = self:quantities(r.e, e)[1]
      local w = self:refs_in(r.e, e, "waypoint")[1]
      if (q or w) and not self:word_in(r.e, e, "able unable possible ready") then
        e = math.min(q and q.e or e, w and w.e or e)
        local waits = opener == "if"
        for _, line in ipairs(self.out) do waits = waits and line:match("^AT") ~= nil end
        if not waits then
          self.ask = string.format("I have %s, but not the condition '%s'. Should it wait for it, or run now?",
            table.concat(self.out, " ; "), self:raw(i, e))
          return
        end
      end
    end
  end
end
-- ("KLM12 climb FL300 and let it run", "..., let her go"): "let" and "it", "her" or "the sim(ulation)", then "run" or
-- "go", said beside commands none of which runs the clock (OP, FF, DTMULT: "let it run for 5 minutes"): whether the clock starts (or the aircraft goes on) is asked, the
-- words never dropped.
function G:run_left()
  for _, line in ipairs(self.out) do
    if line:match("^OP") or line:match("^FF") or line:match("^DTMULT") then return end
  end
  for i = 1, self:said("let") and #self.t or 0 do
    local k = self:word(i, "let") and (self:word(i + 1, "it her") and i + 2
      or (self:word(i + 1, "the") and self:word(i + 2, "@sim") and i + 3))
    local x = k and k + 1
    while x and x <= #self.t and (self.t[x].filler or self:word(x, "now please")) do x = x + 1 end
    -- ("let it go direct to MKG", "let it go down to 10000 feet": "go" with more said after it is the aircraft's)
    if k and self:word(k, "run go") and (x > #self.t or self.t[x].kind == "punct" or self:word(x, "and then")) then
      self.ask = string.format("I have %s. Should the simulation run too ('%s')?", table.concat(self.out, " ; "),
        self:raw(i, k + 1))
      return
    end
  end
end
-- ("climb to level 300 meters", "descend flight level 200 feet", "FL200 ft"): a flight level of one to three digits
-- said with a unit of height straight after it (feet or metres) is a level in hundreds of feet and a height in that
-- unit at once: which is meant is asked, never the unit dropped. `lower`: the request in lower case. A level of four
-- digits or more with metres ("level 9800 meters") is a height in metres, read.
G.level_unit_words = { feet = "feet", foot = "feet", ft = "feet", meters = "metres", metres = "metres",
  meter = "metres", metre = "metres", m = "metres" }
function G:level_with_unit(lower)
  if not (lower:find("level", 1, true) or lower:find("fl", 1, true)) then return end
  for _, lead in ipairs({ "%f[%a]fl%s*", "%f[%a]level%s+" }) do
    for said, n, unit, nx in lower:gmatch("(" .. lead .. "(%d+))%s*(%a+)()") do
      local kind = G.level_unit_words[unit]
      if kind and #n <= 3 and not (unit == "m" and lower:sub(nx, nx):match("[%.%d]")) then
        self.ask = string.format("I have %s, but '%s %s' is a flight level and a height in %s at once. Which do "
          .. "you mean: FL%03d, or %s %s?", table.concat(self.out, " ; "), said, unit, kind, tonumber(n), n, kind)
        return
      end
    end
  end
  -- (the level said in words, "flight level two hundred feet", "FL two zero zero ft": the flight level's number,
  -- then the unit's word)
  for _, q in ipairs(self:quantities(1, #self.t + 1)) do
    local n, u = q.number, q.number and self.t[q.number.e]
    local kind = u and u.kind == "word" and G.level_unit_words[u.text]
    if q.kind == "alt" and q.fl and kind and n.value < 1000 and not (u.text == "m" and self.t[n.e + 1]
        and self.t[n.e + 1].kind == "number") then
      self.ask = string.format("I have %s, but '%s' is a flight level and a height in %s at once. Which do you "
        .. "mean: FL%03d, or %d %s?", table.concat(self.out, " ; "), self:raw(q.b, n.e + 1), kind, n.value, n.value,
        kind)
      return
    end
  end
end
-- The phrases opening a condition (one word or several, lower case) that no command waits for when a word of the
-- traffic (G.traffic_condition_words) follows in its clause: "provided there is no conflict", "as long as BAW5 is
-- clear", "assuming no traffic", "given that the conflict is solved", "so long as", "on condition that".
G.condition_phrases = { "provided", "providing", "as long as", "so long as", "only if", "assuming", "given that",
  "given there", "given no", "on condition that", "on the condition that", "if and only if", "in case of no",
  "subject to", "depending on" }
-- The first clause (from a phrase of G.condition_phrases to the next mark) with a traffic word in it, in the request
-- in lower case; nil when none. Its command is asked, never given with the condition dropped.
function G.traffic_condition_clause(lower)
  for _, p in ipairs(G.condition_phrases) do
    local at = 1
    while true do
      local b = lower:find("%f[%a]" .. p:gsub(" ", "%%s+") .. "%f[%A]", at)
      if not b then break end
      local clause = lower:sub(b):match("^[^,;.!?]+"):gsub("%s+$", "")
      for w in clause:gmatch("%a+") do
        if (" " .. G.traffic_condition_words .. " "):find(" " .. w .. " ", 1, true) then return clause end
      end
      at = b + 1
    end
  end
  return nil
end
-- A request put as a question of the listener's opinion ("do you think KLM12 can climb to FL300?", "maybe KLM12
-- should climb FL300, what do you think?", "should KLM12 climb to FL300?", "shall I clear KLM12 to FL300?", "is it a
-- good idea to ...") or of an aircraft's ability ("can KLM12 reach FL400?", "is KLM12 able to climb FL400?",
-- "would the KLM be able to make FL400?") clears nothing: the draft is asked about. A polite request ("can you
-- climb KLM12 ...", "could KLM12 climb to FL300 please", "do you think you could ...") is not of this class.
-- lower: the request in lower case.
G.opinion_phrases = { "do you think", "what do you think", "what would you think", "what do you reckon",
  "do you reckon", "your opinion", "your view", "would you say", "do you agree", "would you agree", "is it a good idea",
  "would it be a good idea", "is that a good idea", "good idea or not", "is it wise", "would it be wise",
  "would it make sense", "does it make sense", "would that make sense", "does that make sense", "what if",
  "should i", "should we", "shall i", "shall we", "would you recommend", "do you recommend", "would you advise",
  "do you advise", "would you suggest", "do you suggest", "any objection", "any objections" }
G.polite_after_opinion = { "you could", "you can", "you might", "you would", "you'd", "you will", "you could please" }
function G:opinion_question(lower)
  local said
  -- (G.opinion_patterns[p]: the phrase p's first word, which lower holds wherever p is said, and its pattern;
  -- built once per phrase)
  local patterns = G.opinion_patterns
  if not patterns then
    patterns = {}
    G.opinion_patterns = patterns
  end
  for _, p in ipairs(G.opinion_phrases) do
    local pat = patterns[p]
    if not pat then
      pat = { p:match("^%S+"), "%f[%a]" .. p:gsub(" ", "%%s+") .. "%f[%A]" }
      patterns[p] = pat
    end
    local b, e
    if lower:find(pat[1], 1, true) then b, e = lower:find(pat[2]) end
    if b and not said then
      local rest = lower:sub(e + 1):gsub("^[%s,]+", "")
      local polite = false
      for _, q in ipairs(G.polite_after_opinion) do
        if rest:sub(1, #q + 1):match("^" .. q:gsub(" ", "%%s+") .. "%f[%A]") then polite = true end
      end
      -- ("Let's switch the detection on, shall we?": a tag closing a suggestion asks nothing)
      local tag = p:match("^sh") and not rest:find("%a")
      if not polite and not tag then said = lower:sub(b, e) end
    end
  end
  if not said then
    -- ("should KLM12 climb to FL300?": "should" or "shall" opening a question; "should it be needed, ..." opens a
    -- condition, set off by a comma)
    local first = self.t[self:request_start()]
    if first and (first.text == "should" or first.text == "shall") and lower:find("?", 1, true)
        and not lower:find(",", 1, true) then
      said = first.text
    end
  end
  if not said then
    -- (the aircraft's ability: an aircraft named, then "able to", "reach" or "make" after a modal or "is" opening
    -- the request; "would you be able to" asks the listener, a polite request)
    local first = self:request_start()
    if self:word(first, "can could will would is are") then
      for _, r in ipairs(self.refs) do
        if r.kind == "aircraft" and r.b == first + 1 then
          local k = r.e
          if self:word(k, "be") then k = k + 1 end
          if self:word(k, "able") and self:word(k + 1, "to") then said = "able to"
          elseif self:word(first, "can could will would") and (self:word(k, "reach manage")
              or self:word(k, "make") and not self:word(k + 1, "a an the")
                and ((self:quantities(k + 1, k + 5)[1] or {}).b or k + 9) <= k + 2) then
            said = self.t[k].text
          end
        end
      end
    end
  end
  if said then
    -- (a draft that only shows an aircraft, "is KLM12 able to ...": POS, is no instruction to offer)
    local draft = table.concat(self.out, " ; ")
    if draft:find("^POS ") then
      return self:need(string.format("'%s' asks my opinion or the aircraft's ability, no instruction. What should "
        .. "I give? Please say it as an instruction.", said))
    end
    return self:need(string.format("'%s' asks my opinion or the aircraft's ability, no instruction. Should I give %s? "
      .. "Please say it as an instruction.", said, draft))
  end
end

-- "Alaska 1294 and United 1562, descend and maintain 10000 and 9000 respectively": with "respectively",
-- the values said after the aircraft go to them in the order both were said, one value each, when the
-- request issued one ALT, SPD or HDG per aircraft; any other shape is asked about (never one value for all).
local RESPECTIVE = {
  ALT = function(q) return (q.kind == "alt" or (q.kind == "plain" and q.number.thousand)) and handlers.format.alt(q.value, q.fl) end,
  SPD = function(q)
    if q.kind == "mach" then return handlers.format.mach(q.value) end
    return (q.kind == "speed" or q.kind == "plain") and handlers.format.int(q.value)
  end,
  HDG = function(q) return (q.kind == "heading" or q.kind == "plain") and handlers.format.int(q.value) end,
}
function G:respectively()
  local w = self:find_word(1, #self.t + 1, "respectively")
  if w > #self.t then return end
  local ids, seen, last = {}, {}, 0
  for _, r in ipairs(self:refs_in(1, w, "aircraft")) do
    if not seen[r.name] then ids[#ids + 1], seen[r.name] = r.name, true end
    last = math.max(last, r.e)
  end
  local cmd = #ids >= 2 and #self.out == #ids and self.out[1]:match("^(%u+) ")
  local values = {}
  for _, q in ipairs(RESPECTIVE[cmd] and self:quantities(last, w) or {}) do
    local v = RESPECTIVE[cmd](q)
    -- ("flight level one six zero and one eight zero respectively": a bare number of 10 to 600 joined by "and"
    -- to the flight level before it is that flight level's sequel, a flight level too)
    local pv = values[#values]
    if not v and cmd == "ALT" and pv and pv.q.fl and q.kind == "plain" and not q.number.thousand
        and q.value >= 10 and q.value <= 600 and q.value % 1 == 0 and q.b == pv.q.e + 1 and self:word(pv.q.e, "and") then
      v = handlers.format.alt(q.value * 100, true)
    end
    if v then values[#values + 1] = { q = q, text = v } end
  end
  local lines = {}
  for k, id in ipairs(#values == #ids and ids or {}) do
    -- (what follows the value stays: "HDG id 270 LEFT")
    local line = cmd .. " " .. id .. " "
    for _, o in ipairs(self.out) do
      if o:sub(1, #line) == line then lines[k] = line .. values[k].text .. (o:match("^%S+ %S+ %S+( .*)$") or "") end
    end
  end
  if #lines ~= #ids or #ids < 2 then
    self.ask = "Which value goes with which aircraft? Please give each aircraft its own instruction."
    return
  end
  self.out = lines
  for _, v in ipairs(values) do
    self:take(v.q)
    if self.leftover == self:raw(v.q.b, v.q.e) then self.leftover = nil end
  end
  self:explain(w, w + 1)
end

-- "maintain present level, descend when ready": a climb or descent left to the pilot's discretion
-- with no level said after it gives no level to fly; asked (never read as the other instruction's).
local DISCRETION = {}
for _, p in ipairs(lexicon.discretion) do
  local words = {}
  for w in p:gmatch("%S+") do words[#words + 1] = (w:gsub("'s$", "")) end
  DISCRETION[#DISCRETION + 1] = words
end
function G:discretion_without_level()
  if not self:said("climb descend climbing descending") then return end
  for i = 1, #self.t do
    if self:word(i, "climb descend climbing descending") then
      local k = self:skip_fillers(i + 1)
      for _, p in ipairs(DISCRETION) do
        local ok = true
        for j = 1, #p do ok = ok and self.t[k + j - 1] ~= nil and self.t[k + j - 1].text == p[j] end
        -- (the level may follow in a clause of its own: "descend at pilot's discretion, maintain 12000")
        if ok and #self:quantities(i, #self.t + 1) == 0 then
          local ids = self:refs_in(1, #self.t + 1, "aircraft")
          self.ask = string.format("To what level should %s %s? Please give a level or an altitude.",
            #ids == 1 and ids[1].name or "the aircraft", (self.t[i].text:gsub("ing$", "")))
          return
        end
      end
    end
  end
end

-- "X shall cross the fix at FL240", "cross the waypoint at 250 knots": the verb "cross" whose place is a
-- noun (lexicon.waypoint_nouns, "navaid", "beacon") with no place named after it names no place, and the
-- level or speed said with it would be flown at once: the request is asked about ("a crossing point called
-- XNG" is a noun, no crossing).
function G:crossing_without_place()
  if not self:said("cross crosses") then return end
  for i = 1, #self.t do
    if self:word(i, "cross crosses") then
      local k = self:skip_fillers(i + 1)
      if self:word(k, "the a that this") then k = k + 1 end
      if self:word(k, "@waypoint_nouns navaid beacon") and not self:has_ref(k, k + 2, "waypoint") then
        self.ask = string.format("Which %s should it cross? Please name it.", self.t[k].text)
        return
      end
    end
  end
end

-- "proceed to NIKOT directly, KABAR may be skipped", "direct NINAT, GUMIT is not required": a waypoint of the
-- aircraft's route before the place of a DIRECT issued to it, said in a clause of its own that only calls it
-- skipped or not needed, is what that direct-to does: set aside. A place so called skipped that lies after it on
-- the route, or off the route, is asked (the remark does not match the direct-to); a clause with any other word
-- stays and is asked about.
function G:skipped_on_direct()
  -- ("KUBER we skip", "VESAR you can skip", "PDZ skip": the place before its subject and active verb, in verb-final
  -- order; "KUBER we don't skip" is no skip)
  local skip = "may can should could will be is are not no longer required needed skipped omitted bypassed we you i "
    .. "skip bypass omit"
  for _, line in ipairs(self.out) do
    local id, to = line:match("^DIRECT (%S+) (%S+)$")
    local route = id and (self:state(id) or {}).route or {}
    local before = {}
    for _, w in ipairs(route) do
      if w:upper() == (to or ""):upper() then break end
      before[w:upper()] = true
    end
    for _, r in ipairs(id and self.refs or {}) do
      -- ("direct SLI, skip PDZ", "skipping the Paradise VOR": a verb of skipping before the place, which must be
      -- one the direct-to skips too, unless it is deleted: "direct BRAIN, then skip LAM on the route")
      local v = self:word(r.b - 1, "the") and r.b - 2 or r.b - 1
      local deleted = false
      for _, o in ipairs(self.out) do deleted = deleted or o:upper() == ("DELWPT " .. id .. " " .. r.name):upper() end
      if r.kind == "waypoint" and not before[r.name:upper()] and not deleted
          and self:word(v, "skip skipping bypass bypassing omit omitting") then
        return self:need(string.format("I have %s, which skips only the waypoints before %s on %s's route; %s is "
          .. "not one of them. Should %s be deleted from the route, or is another direct-to meant?",
          table.concat(self.out, " ; "), to, id, r.name, r.name))
      end
      if r.kind == "waypoint" and (r.b == 1 or self.t[r.b - 1].kind == "punct") then
        local e, said = r.e, {}
        while self:word(e, skip) do said[self.words[e]] = true; e = e + 1 end
        local negated = said["not"] or said["no"]
        local active = not negated and (said.skip or said.bypass or said.omit)
        if (said.skipped or said.omitted or said.bypassed or active or (negated and (said.required or said.needed)))
            and (not self.t[e] or self.t[e].kind == "punct") then
          if not before[r.name:upper()] then
            -- (the remark does not match what the direct-to does: asked)
            return self:need(string.format("I have %s, which skips only the waypoints before %s on %s's route; %s is "
              .. "not one of them. Should %s be deleted from the route, or is another direct-to meant?",
              table.concat(self.out, " ; "), to, id, r.name, r.name))
          end
          self:set_aside(r.b, e - 1)
          return
        end
      end
    end
  end
end

-- "cleared to Dubai via track Charlie", "direct OMDB via the flight planned route": a direct-to issued in a request
-- whose "via" names no waypoint, quantity or aircraft in its clause (an oceanic track, an airway, a route by its
-- name) is asked: the route said is no straight line to the place, and squawk cannot fly it.
function G:direct_via_unread()
  local direct
  for _, line in ipairs(self.out) do direct = direct or line:match("^DIRECT %S+ (%S+)$") end
  if not direct then return end
  for i = self:find_word(1, #self.t + 1, "via"), #self.t do
    if self:word(i, "via") then
      local e = i + 1
      while self.t[e] and self.t[e].kind ~= "punct" and not self:word(e, "and then") do e = e + 1 end
      local named = false
      for _, r in ipairs(self.refs) do named = named or (r.b > i and r.b < e) end
      if e > i + 1 and not named and #self:quantities(i + 1, e) == 0 then
        return self:need(string.format("I have %s. squawk would fly straight to %s, not '%s': which waypoints "
          .. "does that route pass? Please give them, or say the direct-to alone.", table.concat(self.out, " ; "), direct, self:raw(i, e)))
      end
    end
  end
end

-- "turn left heading 140, then when able direct MABOD": a direct-to left to the pilot's discretion, said with a
-- heading for the same aircraft, is flown later, when the pilot can; squawk would issue both at once and the
-- direct-to would end the heading, so the request is asked about.
function G:direct_when_able()
  local headed = {}
  for _, line in ipairs(self.out) do
    local id = line:match("^HDG (%S+)")
    if id then headed[id] = true end
  end
  local id
  for _, line in ipairs(self.out) do
    local to = line:match("^DIRECT (%S+)")
    if to and headed[to] then id = to end
  end
  if not id then return end
  for i = 1, #self.t do
    for _, p in ipairs(DISCRETION) do
      local ok = true
      for j = 1, #p do ok = ok and self.t[i + j - 1] ~= nil and self.t[i + j - 1].text == p[j] end
      if ok then
        self.ask = string.format("Should %s keep its heading until it can go direct? squawk issues both at once, "
          .. "and the direct-to ends the heading: please give the direct-to when it is due.", id)
        return
      end
    end
  end
end

-- A clause between punctuation that names something and switches it ("QTR7 lateral drift off, fly heading 040":
-- two words or more, then "off" or "on" closing the clause, no callsign after it; one word and the switch, "carry
-- on", "level off", "hands off", is most often a phrase the commands carry) with nothing of it read (no instruction word, no value, no word
-- used, explained, noted or in a reason, none inside what the commands issued explain, the callsign aside) is an instruction squawk did not understand: it becomes the
-- leftover asked about by name, never dropped in silence while the rest runs.
function G:unread_switch()
  if not self:said("off on") then return end  -- (the clause must close with "off" or "on")
  local callsign = {}
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" then for i = r.b, r.e - 1 do callsign[i] = true end end
  end
  local explained = self.explained or {}
  local inside = self:explained_spans(self:issued())
  local b = 1
  for k = 1, #self.t + 1 do
    local t = self.t[k]
    if not t or t.kind == "punct" then
      local first, last, tail, n, read = nil, nil, nil, 0, false
      for i = b, k - 1 do
        local x = self.t[i]
        if not x.filler then tail = i end
        if not callsign[i] then
          read = read or x.kind ~= "word" or explained[i] or inside[i] or self.noted[i] or self.u:used(i)
            or self:intent_at(i) or self:in_reason(i)
          if x.kind == "word" and not x.filler then first, last, n = first or i, i, n + 1 end
        end
      end
      if not read and n >= 3 and tail == last and self:word(last, "off on") then
        self.leftover = self:raw(first, last + 1)
        return
      end
      b = k + 1
    end
  end
end

-- True when some unused word of the request (of tokens b..e-1) still starts an instruction.
function G:any_instruction_in(b, e)
  for i = b, e - 1 do
    if self:intent_at(i) then return true end
  end
  return false
end
function G:any_instruction() return self:any_instruction_in(1, #self.t + 1) end

local UNDERSTOOD = "I did not understand that. Which command, aircraft and value do you mean?"
M.not_understood = UNDERSTOOD

-- An aircraft's id glued to a level or a shorthand value ("klm12fl240", "ezy45s250"), written
-- apart; only the exact id of an aircraft that flies, followed by FL or a lexicon.shorthand prefix
-- and digits.
-- "AUA123 speed 250, DLH6CK the same", "..., DLH6CK too", "..., same for DLH6CK": another flying aircraft
-- said with "same", "too", "likewise", "ditto" or "as well" after it, or after "same for" in a clause of
-- its own, ending its clause, gets the request's instructions too. Returns the aircraft so named (their tokens used, never instructed by the parse).
-- Also the formal passive and its verb ("the same may be done for the SpiceJet also", "the same can be given to
-- DLH6CK", "do the same for the Akasa"): G.same_opening; "also" closing the clause is "too". Called again after
-- the passes that resolve an aircraft named by its airline or type ("the SpiceJet"), for those references.
local SAME_AFTER = { same = true, too = true, likewise = true, ditto = true, also = true }
-- The first token of "same ... for/to" ending just before b (the aircraft's words), with "the", "do the" or
-- "give the" before "same": "same for", "the same may be done for", "give the same to", "do the same for"; nil
-- when none. At most four words of a passive verb between ("may be done", "should also be given").
function G:same_opening(b)
  local SAME_PASSIVE = "may can should must shall could would will to be done given applied also"
  local k = b - 1
  if self:word(k, "the") then k = k - 1 end
  if not self:word(k, "for to with") then return nil end
  k = k - 1
  local stop = k - 4
  while k > stop and k > 1 and self:word(k, SAME_PASSIVE) do k = k - 1 end
  -- ("the same instruction for DLH6CK", "same clearance to the Akasa": the noun of what is given again)
  if self:word(k, "@same_given") and self:word(k - 1, "same") then k = k - 1 end
  if not self:word(k, "same likewise") then return nil end
  if self:word(k - 1, "the") then k = k - 1 end
  if self:word(k - 1, "do give") then k = k - 1 end
  return k
end
-- The span [from, to) of an aircraft's words [b, e) said in that shape with its "same" words, ending its
-- clause; nil when not so said. Courtesy before "same" or closing the clause ("..., kindly same for the IndiGo",
-- "..., same for DLH6CK kindly") carries no instruction and keeps the aircraft named.
function G:same_span(b, e)
  local opens = true
  local k = self:skip_fillers(e, false)
  local to = (self.t[k] and SAME_AFTER[self.t[k].text] and k + 1)
    or (self:word(k, "as") and self:word(k + 1, "well") and k + 2) or nil
  -- ("DLH6CK also the same", "for the Akasa too the same": "the same" said again after "also" or "too")
  if to and self:word(to, "the") and self:word(to + 1, "same") then to = to + 2 end
  local from = self:same_opening(b)
  -- (", also DLH6CK", ", and also for the Akasa", ", also the same for DLH6CK": "also" opening the aircraft's clause
  -- of its own)
  local also = from or b
  if self:word(also - 1, "the") and not from then also = also - 1 end
  if self:word(also - 1, "for") and not from then also = also - 1 end
  if self:word(also - 1, "also") then from = also - 1 end
  if from then
    b = from
    local c = b - 1
    if self:word(c, "please kindly") then c = c - 1 end
    if self:word(c, "also") and c == b - 1 then c = c - 1 end
    opens = c >= 1 and (self.t[c].kind == "punct" or self:word(c, "and"))
    to = to or e
  end
  while to and self.t[to] and (self.t[to].filler or self:word(to, "please kindly")) do to = to + 1 end
  if to and opens and (not self.t[to] or self.t[to].kind == "punct") then return b, to end
  return nil
end
-- True when the words after an aircraft's "same" span [b, e) ("BAW34 same, left 20 degrees": e at the comma) up to
-- the next aircraft or the end say the instruction again, each word and value among those of the earlier
-- aircraft's clause (from the aircraft before r up to b): "same" then only confirms, and the aircraft takes the
-- words said for it. False when nothing follows or a word or value differs ("same, climb FL320" after FL310).
function G:same_restated(r, b, e)
  if not (self.t[e] and self.t[e].kind == "punct") then return false end
  local stop, from = #self.t + 1, 1
  for _, o in ipairs(self.refs) do
    if o.kind == "aircraft" and o ~= r then
      if o.b > e and o.b < stop then stop = o.b end
      if o.e <= b and o.e > from then from = o.e end
    end
  end
  local SKIP = "please kindly and also too then degrees degree feet ft knots kts the"
  -- (the clause's words and values, spoken digits joined into one figure: "two zero" is 20)
  local function items(i, j)
    local list, run = {}, nil
    for k = i, j - 1 do
      local t = self.t[k]
      local w = self.words[k] or t.text
      local digit = t.kind == "number" and w or nil
      if not digit and DIGIT_WORDS[w] then
        digit = ({ zero = "0", oh = "0", one = "1", two = "2", three = "3", tree = "3", four = "4", fower = "4",
          five = "5", fife = "5", six = "6", seven = "7", eight = "8", nine = "9", niner = "9" })[w]
      end
      if digit then
        run = (run or "") .. digit
      else
        if run then list[#list + 1] = run:gsub("^0+(%d)", "%1") run = nil end
        if t.kind ~= "punct" and not t.filler and not self:word(k, SKIP) then list[#list + 1] = w end
      end
    end
    if run then list[#list + 1] = run:gsub("^0+(%d)", "%1") end
    return list
  end
  local said = {}
  for _, w in ipairs(items(from, b)) do said[w] = true end
  local again = items(e + 1, stop)
  if #again == 0 then return false end
  for _, w in ipairs(again) do
    if not said[w] then return false end
  end
  return true
end
-- (the request's only aircraft with "too" or "as well" after it, "could you switch on VNAV for IBEX 51 as well?",
-- is its addressee: the words point back to an earlier request, and nothing here is copied)
function G:same_for()
  local named = {}
  for _, r in ipairs(self.refs) do
    if r.kind == "aircraft" and r.exists and not r.false_start and r.b > 1 then
      local b, e = self:same_span(r.b, r.e)
      local alone = b ~= nil and b == r.b
      for _, o in ipairs(alone and self.refs or {}) do
        alone = alone and (o == r or o.kind ~= "aircraft" or not o.exists or o.false_start)
      end
      if b and not alone and self:same_restated(r, b, e) then
        -- (the instruction said again for the aircraft: its "same" words only confirm it)
        for k = b, e - 1 do
          if k < r.b or k >= r.e then self.t[k].filler = true end
        end
      elseif b and not alone then
        self:mark_used(b, e)
        r.false_start = true
        named[#named + 1] = r.name
      end
    end
  end
  return named
end

-- The request's commands given again to each aircraft of `named` (G:same_for): only when every command
-- is one aircraft's, no creation; else asked about.
function G:same_again(named)
  if #named == 0 or self.ask or #self.out == 0 then return end
  local id
  for _, line in ipairs(self.out) do
    local cmd, acid = line:match("^(%S+) (%S+)")
    if cmd == "CRE" or not acid or not self:state(acid) or (id and acid ~= id) then
      self.ask = string.format("Which instruction should %s get the same as? Please say it for %s.",
        table.concat(named, " and "), table.concat(named, " and "))
      return
    end
    id = acid
  end
  -- (a value counted from the aircraft's own state, "turn left 10" as HDG 080, is no value to copy: asked)
  for _, line in ipairs(self.out) do
    if not self:values_said(line) then
      self.ask = string.format("Should %s make the same change from its own state, or take %s's value (%s)? Please "
        .. "say it for %s.", table.concat(named, " and "), id, line, table.concat(named, " and "))
      return
    end
  end
  local out = {}
  for _, line in ipairs(self.out) do out[#out + 1] = line end
  for _, other in ipairs(named) do
    for _, line in ipairs(self.out) do
      out[#out + 1] = (line:gsub("^(%S+) " .. id:gsub("%p", "%%%0") .. "%f[%s%z]", "%1 " .. other))
    end
  end
  self.out = out
end

-- "dlh4tkdescend fl220", "swr1285climb": an aircraft's id typed against an instruction word
-- (lexicon.spelling.targets, the shorthand, "dct"/"dir") is cut from it
local GLUED_WORDS = set_of(lexicon.spelling.targets)
for w in pairs(lexicon.shorthand) do if #w >= 2 then GLUED_WORDS[w] = true end end
GLUED_WORDS.dct, GLUED_WORDS.dir, GLUED_WORDS.desc = true, true, true
local function unglued_words(text, fleet)
  if #fleet == 0 or not text:find("%d%a%a%a") then return text end
  return (text:gsub("%f[%w](%a+%d%w*%a%a%a+)%f[%W]", function(w)
    local lw = w:lower()
    for _, a in ipairs(fleet) do
      local id = a.id:lower()
      if #lw > #id and lw:sub(1, #id) == id and GLUED_WORDS[lw:sub(#id + 1)] then
        return w:sub(1, #id) .. " " .. w:sub(#id + 1)
      end
    end
    return nil
  end))
end

local function unglued_ids(text, fleet)
  text = unglued_words(text, fleet)
  -- (only a word holding digits, letters and digits again, in that order, is cut)
  if #fleet == 0 or not text:find("%d%a+%d") then return text end
  local ids = {}
  for _, a in ipairs(fleet) do ids[a.id:lower()] = true end
  return (text:gsub("%f[%w]%w+", function(w)
    local lw = w:lower()
    local letters, digits = lw:match("(%a+)(%d+)$")
    if not letters or #letters == #lw - #digits then return nil end
    for cut = #lw - #digits - #letters, #lw - #digits - 1 do
      local pre = lw:sub(cut + 1, #lw - #digits)
      if ids[lw:sub(1, cut)] and (pre == "fl" or lexicon.shorthand[pre]) then
        return w:sub(1, cut) .. " " .. w:sub(cut + 1)
      end
    end
    return nil
  end))
end

-- "descend CLH 2AB": a callsign typed apart after its airline letters is joined when the
-- joined id is exactly an aircraft's (letters after the digits too), and so is a registration
-- written with its hyphen ("C-GKQM", "D-EABC": CGKQM, DEABC); so are a flight number's letters
-- said apart from its digits ("ryanair 81 JC", "Emirates seven KD": digits said as words, the letters
-- typed in capitals) when exactly one aircraft's id ends so.
local function split_ids(text, fleet)
  -- (a registration written in capitals with its hyphen, "D-EABC", "OE-LDA", is the one id, flying or new)
  local hyphen = text:find("-", 1, true)
  if hyphen then text = text:gsub("%f[%w](%u%u?)%-(%u%u%u%u?)%f[%W]", "%1%2") end
  if #fleet == 0 then return text end
  local ids, tails = {}, {}
  -- (`headed`: the letters opening an id before its digits are in the text, as typed or in capitals: a word
  -- and a number are joined only then)
  local low, headed = text:lower(), false
  for _, a in ipairs(fleet) do
    ids[a.id:lower()] = true
    local tail = a.id:lower():match("^%a+(%d+%a+)$")
    if tail then tails[tail] = (tails[tail] or 0) + 1 end
    local head = a.id:lower():match("^%a+%f[%d]")
    headed = headed or (head ~= nil and low:find(head, 1, true) ~= nil)
  end
  local function joined(a, b)
    if ids[(a .. b):lower()] then return a .. b end
    return nil
  end
  if headed then text = text:gsub("%f[%w](%a+)%s+(%d%w*)%f[%W]", joined) end
  if hyphen then text = text:gsub("%f[%w](%a%a?)%-(%w+)%f[%W]", joined) end
  -- ("ph abc descend 1500 ft": a registration of letters alone typed apart after its one or two nationality
  -- letters, joined exactly an aircraft's id)
  for _, a in ipairs(fleet) do
    if a.id:match("^%a%a%a%a%a?%a?$") then
      text = text:gsub("%f[%w](%a%a?)%s+(%a%a%a%a?)%f[%W]", function(x, y)
        if (x .. y):upper() == a.id:upper() then return x .. y end
        return nil
      end)
    end
  end
  if not next(tails) then return text end
  text = text:gsub("%f[%w](%d+)%s+(%a%a?)%f[%W]", function(d, l)
    if tails[(d .. l):lower()] == 1 then return d .. l end
    return nil
  end)
  if not text:find("%f[%w]%u%u?%f[%W]") then return text end
  local toks, bare = plain_words(text)
  for i = #toks, 2, -1 do
    local letters = toks[i]:match("^(%u%u?)%p*$")
    local b, digits = i, ""
    while letters and b > 1 and SAID_DIGIT[bare[b - 1]] and not toks[b - 1]:match("%p$") do
      b, digits = b - 1, SAID_DIGIT[bare[b - 1]] .. digits
    end
    if b < i and tails[(digits .. letters):lower()] == 1 then
      return table.concat(toks, " ", 1, b - 1) .. (b > 1 and " " or "") .. digits .. toks[i]
        .. (i < #toks and " " or "") .. table.concat(toks, " ", i + 1)
    end
  end
  return text
end

-- "where is Charlie Golf Kilo Quebec Mike", "Cessna Charlie Golf Kilo Quebec Mike, climb ...": a
-- registration spelled in the phonetic alphabet anywhere, four letters or more, that is exactly the
-- id of an aircraft flying is written as that id; a maker or model said before it is the aircraft's
-- own and is written into the id too when the aircraft is of that maker or model.
-- G.type_words(): maker or model (lower case, "cessna", "sr22") -> {designator = true}, built once.
function G.type_words()
  if not G.type_words_built then
    local words = {}
    for _, row in ipairs(TYPES.types) do
      for _, w in ipairs({ row[1]:lower(), row[2]:lower() }) do
        words[w] = words[w] or {}
        words[w][row[3]] = true
      end
    end
    G.type_words_built = words
  end
  return G.type_words_built
end
-- "forty-five degrees forty-five north", "five degrees zero east", "four five degrees three zero minutes north": a
-- coordinate's degrees and minutes said in words (digits one by one, or a number below a hundred: tens and a
-- unit, a teen, a unit; or numerals) before "degrees" and before the hemisphere (lexicon.coordinate_axes.hemispheres, "minutes"
-- between or not) are written as numerals ("45 degrees 45 north"), which the position reads as degrees and
-- minutes (minutes of 60 or more are then asked about); a number in words anywhere else stays as said.
G.spoken_teens = { ten = 10, eleven = 11, twelve = 12, thirteen = 13, fourteen = 14, fifteen = 15,
  sixteen = 16, seventeen = 17, eighteen = 18, nineteen = 19 }
function G.spoken_degrees_minutes(text)
  local low = text:lower()
  if not low:find("deg", 1, true) then return text end
  local toks = {}  -- each word: b, e (the text's positions, e past it), w (lower case, no punctuation), bare
  for b, w, e in text:gsub("(%a)%-(%a)", "%1 %2"):gmatch("()(%S+)()") do
    local lw = w:lower()
    toks[#toks + 1] = { b = b, e = e, w = (lw:gsub("[%p]+$", "")), bare = not lw:find("%p$") }
  end
  if #toks < 4 then return text end
  -- the number said in words from word k on: its value and the word after it, else nil
  local function number(k)
    local t = toks[k]
    if not t or not t.bare then return nil end
    if t.w:match("^%d%d?%d?$") then return tonumber(t.w), k + 1 end
    local tens = G.coordinate_tens[t.w]
    if tens then
      local u = toks[k + 1] and toks[k + 1].bare and SAID_DIGIT[toks[k + 1].w]
      if u and u ~= "0" then return tens * 10 + tonumber(u), k + 2 end
      return tens * 10, k + 1
    end
    if G.spoken_teens[t.w] then return G.spoken_teens[t.w], k + 1 end
    local digits, j = "", k
    while toks[j] and toks[j].bare and SAID_DIGIT[toks[j].w] and #digits < 3 do digits, j = digits .. SAID_DIGIT[toks[j].w], j + 1 end
    if digits ~= "" then return tonumber(digits), j end
    return nil
  end
  local HEMI = lexicon.coordinate_axes.hemispheres
  local put, done = require("translate.tokens").splicer(text)
  local k = 1
  while k <= #toks do
    local deg, d = number(k)
    local min, m
    if deg and toks[d] and toks[d].w:match("^deg") and toks[d].bare then min, m = number(d + 1) end
    local h = m and ((toks[m] and toks[m].w:match("^min")) and toks[m].bare and m + 1 or m)
    if min and toks[h] and (HEMI[toks[h].w] or HEMISPHERES[toks[h].w]) then
      put(toks[k].b, string.format("%d %s %d ", deg, text:sub(toks[d].b, toks[d].e - 1), min), toks[m].b)
      k = m
    else
      k = k + 1
    end
  end
  return done()
end
-- "four eight decimal three five one one decimal eight": a latitude and a longitude said digit by digit with a
-- decimal mark each ("decimal", "point") and nothing between them, so that the digits between the two marks
-- hold the latitude's decimals and the longitude's degrees run together. Returns the text and nil when no such
-- run is said; the text with the position typed in its place ("50.1 8.2") when every split that gives a valid
-- pair (latitude up to 90, longitude up to 180 in at most three figures) gives the same one ("five zero decimal
-- one zero eight decimal two": 50.1 8.2 either way); else the text and a question naming the digits and the
-- readings.
G.coordinate_marks = set_of({ "decimal", "point" })
G.coordinate_tens = { twenty = 2, thirty = 3, forty = 4, fifty = 5, sixty = 6, seventy = 7, eighty = 8,
  ninety = 9 }
function G.run_together_position(text)
  local low = text:lower()
  if not low:find("decimal", 1, true) and not low:find("point", 1, true) then return text, nil end
  local toks = {}  -- each word: b, e (the text's positions, e past it), w (lower case), bare (no punctuation)
  for b, w, e in text:gmatch("()(%S+)()") do
    local lw = w:lower()
    toks[#toks + 1] = { b = b, e = e, w = lw:gsub("[%p]+$", ""), bare = not lw:find("%p$") }
  end
  local function digit(k) return toks[k] and toks[k].bare and SAID_DIGIT[toks[k].w] end
  local function mark(k) return toks[k] and toks[k].bare and G.coordinate_marks[toks[k].w] end
  for i = 2, #toks do
    if mark(i) then
      -- the degrees before the first mark: digits said ("four eight") or tens and a digit ("forty eight")
      local lb, deg = i, ""
      while lb > 1 and digit(lb - 1) and #deg < 3 do lb, deg = lb - 1, SAID_DIGIT[toks[lb - 1].w] .. deg end
      if deg == "" and toks[i - 1].bare and G.coordinate_tens[toks[i - 1].w] then
        lb, deg = i - 1, G.coordinate_tens[toks[i - 1].w] .. "0"
      elseif #deg == 1 and lb > 1 and toks[lb - 1].bare and G.coordinate_tens[toks[lb - 1].w] then
        lb, deg = lb - 1, G.coordinate_tens[toks[lb - 1].w] .. deg
      end
      -- the run between the marks, the second mark, the longitude's decimals after it
      local j, run = i + 1, ""
      while digit(j) do run, j = run .. SAID_DIGIT[toks[j].w], j + 1 end
      local last, dec = j, ""  -- (the last word of the longitude's decimals)
      while toks[last + 1] and SAID_DIGIT[toks[last + 1].w] do
        last, dec = last + 1, dec .. SAID_DIGIT[toks[last + 1].w]
        if not toks[last].bare then break end
      end
      if deg ~= "" and tonumber(deg) <= 90 and #run >= 2 and mark(j) and dec ~= "" then
        local readings, seen = {}, {}
        for k = math.max(1, #run - 3), #run - 1 do
          local lat, lon = tonumber(deg .. "." .. run:sub(1, k)), tonumber(run:sub(k + 1) .. "." .. dec)
          if lat <= 90 and lon <= 180 then
            local pair = string.format("%s %s", handlers.format.num(lat), handlers.format.num(lon))
            if not seen[pair] then readings[#readings + 1], seen[pair] = pair, true end
          end
        end
        if #readings > 1 then
          local digits = {}
          for k = i + 1, j - 1 do digits[#digits + 1] = toks[k].w end
          return text, string.format("Which position is '%s'? The digits '%s' between the two decimal marks "
            .. "split more than one way: %s. Please say the latitude and the longitude apart (with a comma, or north "
            .. "and east).", (text:sub(toks[lb].b, toks[last].e - 1):gsub("[%p]+$", "")),
            table.concat(digits, " "), table.concat(readings, " or "))
        end
        if #readings == 1 then
          return text:sub(1, toks[lb].b - 1) .. readings[1] .. text:sub(toks[last].e), nil
        end
      end
    end
  end
  return text, nil
end
-- A level or heading said digit by digit and run on into a speed with no break before the speed's unit ("flight
-- level eight zero two four zero knots", "heading two seven zero two twenty knots"): the digit and tens words
-- between the value's name and the unit split between two words where the value before is what it can be and the
-- speed after is one (lexicon.run_on; "one twenty two fifty" splits after "twenty"). Returns the text with a comma
-- at the split that fits, and nil; the text and a question naming the words when none fits; the text and nil when
-- no value runs on so (three digits or fewer after the name).
G.run_on_names, G.speed_units = {}, set_of(lexicon.speed_units)  -- (the value's name -> "level" or "heading")
for _, w in ipairs(lexicon.run_on.level_words) do G.run_on_names[w] = "level" end
for _, w in ipairs(lexicon.run_on.heading_words) do G.run_on_names[w] = "heading" end
function G.run_on_values(text)
  local low = text:lower()
  if not (low:find("kt", 1, true) or low:find("kno", 1, true)) then return text, nil end
  local RUN_ON, RUN_ON_NAMES, SPEED_UNITS = lexicon.run_on, G.run_on_names, G.speed_units
  local toks = {}  -- each word: b, e (the text's positions, e past it), w (lower case, no punctuation), bare
  for b, w, e in text:gmatch("()(%S+)()") do
    local lw = w:lower()
    toks[#toks + 1] = { b = b, e = e, w = lw:gsub("%p+$", ""), bare = not lw:find("%p$") }
  end
  -- the digits of words [b, e) said as one value ("two twenty" 220, "twenty two" 22: a tens word takes the digit
  -- after it), or nil when a word is no digit or tens word
  local function digits(b, e)
    local out, k = "", b
    while k < e do
      local t = toks[k]
      local tens = t.bare and G.coordinate_tens[t.w]
      local unit = k + 1 < e and toks[k + 1].bare and SAID_DIGIT[toks[k + 1].w]
      if tens then
        out, k = out .. tens .. ((unit and unit ~= "0") and unit or "0"), k + ((unit and unit ~= "0") and 2 or 1)
      elseif t.bare and SAID_DIGIT[t.w] then
        out, k = out .. SAID_DIGIT[t.w], k + 1
      else
        return nil
      end
    end
    return out
  end
  local function within(d, bounds) return tonumber(d) >= bounds[1] and tonumber(d) <= bounds[2] end
  local function fits(kind, d)
    if kind == "heading" then return #d == 3 and within(d, RUN_ON.heading) end
    return (#d == 3 or (#d == 2 and d:sub(1, 1) ~= "0")) and within(d, RUN_ON.level)
  end
  for i = 1, #toks - 1 do
    local kind = toks[i].bare and RUN_ON_NAMES[toks[i].w]
    if kind then
      local k = i + 1
      while toks[k] and digits(k, k + 1) do k = k + 1 end
      if #digits(i + 1, k) > 3 and toks[k] and SPEED_UNITS[toks[k].w] then
        -- (each word adds a digit to the speed before it, so one split at most leaves the speed three digits)
        for at = i + 2, k - 1 do
          local value, speed = digits(i + 1, at), digits(at, k)
          if fits(kind, value) and #speed == 3 and speed:sub(1, 1) ~= "0" and within(speed, RUN_ON.speed) then
            return G.run_on_values(text:sub(1, toks[at - 1].e - 1) .. "," .. text:sub(toks[at - 1].e))
          end
        end
        local from = (kind == "level" and i > 1 and toks[i - 1].bare and toks[i - 1].w == "flight") and i - 1 or i
        return text, string.format("Which %s and speed do you mean? I heard '%s' with no break, and its digits "
          .. "give no %s and speed together.", kind, text:sub(toks[from].b, toks[k].e - 1):gsub("%p+$", ""), kind)
      end
    end
  end
  return text, nil
end
local NATIONLESS = set_of(lexicon.nationless_registrations)
local function spelled_registrations(text, fleet)
  if #fleet == 0 then return text end
  local spelling = false  -- (a phonetic letter said)
  for w in text:lower():gmatch("[%w]+") do
    if lexicon.phonetic[w] then
      spelling = true
      break
    end
  end
  if not spelling then return text end
  local words = {}  -- {text, b, e} of each word
  for b, w, e in text:gmatch("()([%w]+)()") do words[#words + 1] = { w:lower(), b, e } end
  for k, w in ipairs(words) do
    local first = lexicon.phonetic[w[1]] and k or k + 1
    -- (a spelling starts at the first letter of a run, said at k or after a maker or model at k)
    if (not lexicon.phonetic[w[1]] or k == 1 or not lexicon.phonetic[words[k - 1][1]])
        and words[first] and lexicon.phonetic[words[first][1]] then
      local set = G.type_words()[w[1]]
      -- (after two letters or more, digits said or typed and more letters: "Hotel Kilo five zero one two"
      -- is HK5012, "Delta Lima Hotel six Charlie Kilo" DLH6CK, when such an aircraft flies)
      local letters, last, lead = "", nil, 0
      for j = first, #words do
        local l = lexicon.phonetic[words[j][1]]
        if not l and lead >= 2 then l = SAID_DIGIT[words[j][1]] or words[j][1]:match("^%d+$") end
        if not l or (j > first and not text:sub(words[j - 1][3], words[j][2] - 1):match("^%s+$")) then break end
        if l:match("^%a$") and lead == #letters then lead = lead + 1 end
        letters, last = letters .. l, j
      end
      -- (a Canadian registration is said after the aircraft's maker or model without its nationality letter,
      -- "Cessna Golf Kilo Whiskey Alpha" for the C172 C-GKWA: the four letters after C of
      -- lexicon.nationless_registrations, when no aircraft is the four letters themselves; the letters alone
      -- are confirmed)
      local held = {}
      for _, a in ipairs(#letters >= 4 and fleet or {}) do held[a.id:upper()] = true end
      local nationless = #letters == 4 and not held[letters] and first > k and set
      for _, a in ipairs(#letters >= 4 and fleet or {}) do
        local id = a.id:upper()
        if id == letters or (nationless and id:sub(2) == letters and NATIONLESS[id:sub(1, 1) .. letters:sub(1, 1)]
            and a.type and set[a.type:upper()]) then
          local own = first > k and set and a.type and set[a.type:upper()]
          return text:sub(1, (own and w or words[first])[2] - 1) .. a.id .. text:sub(words[last][3])
        end
      end
    end
  end
  return text
end

-- "Skyhawk 3AB", "Cessna three alpha bravo", "King Air 0KA", "November three alpha bravo", "Skyhawk November
-- one two three alpha bravo": a civil aircraft's abbreviated callsign (FAA JO 7110.65 2-4-20), a prefix
-- (November or N, or a maker, model or nickname of types.lua: "Cessna", "Skyhawk", "King Air") and then the
-- last three characters of its US registration holding a letter, or all of them but the N, said in digits, letters
-- or phonetics (or any registration whole), is written as that registration when exactly one aircraft flying
-- has a US registration (N and a digit) ending with them and the prefix fits it (November: any; a type word
-- without digits: the aircraft's type). Returns the text and, when two aircraft end so or the prefix does not
-- fit the one that does (a suffix, not the whole id), the question to ask instead, else nil. Four characters of
-- five ("Cessna three eight Charlie Sierra" for N738CS) are neither: a character went unsaid, asked.
-- G.nickname_heads: the first word of each nickname of two words (types.nicknames), a set
G.nickname_heads = {}
for name in pairs(require("translate.types").nicknames) do
  local head = name:match("^(%S+) ")
  if head then G.nickname_heads[head] = true end
end
local function abbreviated_registrations(text, fleet)
  if #fleet == 0 then return text, nil end
  local nicknames = require("translate.types").nicknames
  -- (the words are read only where one may open a prefix: November or N, a maker, model or nickname, or
  -- the first word of a nickname of two; else only the bare suffix below is)
  local prefixed = false
  for w in text:lower():gmatch("[%w]+") do
    if w == "november" or w == "n" or G.type_words()[w] or nicknames[w] or G.nickname_heads[w] then
      prefixed = true
      break
    end
  end
  local words = {}  -- {text, b, e} of each word, where a prefix may be said
  if prefixed then
    for b, w, e in text:gmatch("()([%w]+)()") do words[#words + 1] = { w:lower(), b, e } end
  end
  local function fits(prefix, a)
    local id, ty = a.id:upper(), (a.type or ""):upper()
    if prefix == "november" or prefix == "n" then return id:match("^N%d") ~= nil end
    if (G.type_words()[prefix] or {})[ty] then return true end
    for _, p in ipairs(nicknames[prefix] or {}) do if ty:match(p) then return true end end
    return false
  end
  for k = 1, #words do
    local w = words[k][1]
    local two = words[k + 1] and (w .. " " .. words[k + 1][1])
    local prefix = (two and nicknames[two] and two) or ((w == "november" or w == "n" or G.type_words()[w]
      or nicknames[w]) and not w:match("%d") and w)
    local first = prefix and k + (prefix == two and 2 or 1)
    -- (the characters said after the prefix, one word apart each, up to the first word that is none)
    local said, ends = {}, {}
    for j = first or #words + 1, #words do
      if not text:sub(words[j - 1][3], words[j][2] - 1):match("^%s+$") then break end
      local c = lexicon.phonetic[words[j][1]] or SAID_DIGIT[words[j][1]]
          or (words[j][1]:match("%d") and words[j][1]:upper())
      if not c then break end
      said[#said + 1] = (said[#said] or "") .. c:upper()
      ends[#said] = j
    end
    for n = #said, 1, -1 do
      local chars = said[n]
      local ending = {}
      if #chars >= 3 and chars:match("%a") then
        for _, a in ipairs(fleet) do
          local id = a.id:upper()
          if id == chars or (id:match("^N%d") and #id > #chars and id:sub(-#chars) == chars
              and (#chars == 3 or #chars == #id - 1)) then ending[#ending + 1] = a end
        end
      end
      if #ending > 0 then
        if #ending == 1 and fits(prefix, ending[1]) then
          -- (read again: a prefix before this one, "Skyhawk November ...", is the same aircraft's)
          return abbreviated_registrations(text:sub(1, words[k][2] - 1) .. ending[1].id .. text:sub(words[ends[n]][3]), fleet)
        end
        local heard = text:sub(words[k][2], words[ends[n]][3] - 1)
        if #ending > 1 then
          local ids = {}
          for _, a in ipairs(ending) do ids[#ids + 1] = a.id end
          return text, string.format("Which aircraft is '%s': %s? Please give its callsign.", heard,
            table.concat(ids, " or "))
        end
        if ending[1].id:upper() ~= chars then
          return text, string.format("Which aircraft is '%s'? %s ends with %s but is a %s. Please give its callsign.",
            heard, ending[1].id, chars, ending[1].type or "other type")
        end
        break
      end
    end
  end
  -- (a bare suffix typed after the request's first word, "reposition 3AB to ...", "from 8ND's route": the
  -- digits and capitals that end exactly one flying US registration, not said whole, are asked about; at the
  -- start the callsign matcher asks whether it is that aircraft)
  local upper = nil
  for b, tok in text:gmatch("()(%d+%u+)%f[%W]") do
    if #tok >= 3 and not text:sub(b - 1, b - 1):match("%w") and text:sub(1, b - 1):match("%w") then
      local ending = {}
      upper = upper or text:upper()
      for _, a in ipairs(fleet) do
        local id = a.id:upper()
        if id:match("^N%d") and #id > #tok and id:sub(-#tok) == tok and not upper:find(id, 1, true) then
          ending[#ending + 1] = a.id
        end
      end
      if #ending == 1 then
        return text, string.format("Which aircraft is '%s'? %s ends with it. Please give its callsign.", tok, ending[1])
      end
      if #ending > 1 then
        return text, string.format("Which aircraft is '%s': %s? Please give its callsign.", tok, table.concat(ending, " or "))
      end
    end
  end
  return text, nil
end

-- "LH400 descend FL210", "EK201 down to 250": an airline's IATA designator typed in capitals against a flight
-- number (names.iata) is the aircraft flying under the airline's ICAO prefix with the same characters after it
-- ("LH400": DLH400), when that aircraft flies, no aircraft flies under the two letters themselves, the word is
-- no aircraft type ("PC12"), not the id after a creation verb (lexicon.creation_verbs) and the two letters are
-- nothing else squawk reads (G.IATA holds only those: no command or alias, "VS", "DT"; no setting key, "FL"; no
-- unit, "FT", "KT"). Else the word stays as typed: a callsign of no aircraft, asked about.
G.IATA, G.IATA_AIRPORTS = {}, names.iata_airports
do
  local read = {}
  for w in pairs(SETTING_KEYS) do read[w] = true end  -- (registry names and aliases, shorthand, setting keys)
  for w in pairs(lexicon.value_units) do read[w] = true end
  for _, w in ipairs(lexicon.speed_units) do read[w] = true end
  for code, icao in pairs(names.iata) do
    if not read[code:lower()] then G.IATA[code] = icao end
  end
  G.IATA_TYPES = {}
  for _, d in ipairs(TYPES.designators) do G.IATA_TYPES[d:upper()] = true end
end

-- The ICAO code of the large airport whose IATA code (names.iata_airports) is the word at k, where a place is
-- said: typed in capitals ("send it to SFO"), or in lower case when it is no English word (squawk's, or
-- lexicon.iata_words: "send united 1725 to sfo"; never "sea", "add", "man"); nil otherwise.
G.IATA_WORDS = set_of(lexicon.iata_words)
function G:iata_airport_at(k)
  local t = self.t[k]
  if t == nil or t.kind ~= "word" or not t.raw:match("^%a%a%a$") then return nil end
  if t.raw:match("^%u%u%u$") then return G.IATA_AIRPORTS[t.raw] end
  if t.raw:match("^%l%l%l$") and not G.IATA_WORDS[t.raw] and not self:known_word(k) then
    return G.IATA_AIRPORTS[t.raw:upper()]
  end
  return nil
end

function G.iata_ids(text, fleet)
  if #fleet == 0 or not text:find("%u%u%d") then return text end
  local ids, own = {}, {}
  for _, a in ipairs(fleet) do
    ids[a.id:upper()] = a.id
    own[a.id:upper():match("^%a*")] = true
  end
  return (text:gsub("()%f[%w](%u%u)(%d%w*)%f[%W]", function(at, code, rest)
    local icao, typed = G.IATA[code], (code .. rest):upper()
    local id = icao and ids[(icao .. rest):upper()]
    -- (the id of an aircraft created, "create LH400, a B738 ...", is new, as typed)
    local before = id and text:sub(math.max(1, at - 12), at - 1):match("(%a+)%W*$")
    if id and not own[code] and not ids[typed] and not G.IATA_TYPES[typed]
        and not (before and lexicon.creation_verbs[before:lower()]) then
      return id
    end
    return nil
  end))
end

-- "turn the Ryanair 20 degrees to the right": after "the" and an airline, a
-- number with a unit is the instruction's value, no flight number (unless an
-- aircraft has that id); a comma keeps the callsign matcher off it.
local SPOKEN_DIGITS = { oh = true }
for w in pairs(NUMBER_WORDS) do SPOKEN_DIGITS[w] = true end
for w in pairs(lexicon.phonetic) do SPOKEN_DIGITS[w] = true end  -- ("the Ryanair one Juliet Charlie")
local AIRLINE_WORDS = {}
-- (one-word telephonies, and one-word names an airline is known by: "the British one")
for _, a in ipairs(names.airlines) do AIRLINE_WORDS[a[1]] = a[2] end
for _, a in ipairs(names.common) do AIRLINE_WORDS[a[1]] = AIRLINE_WORDS[a[1]] or a[2] end
-- (telephonies and common names of one to three words -> the airline's ICAO prefix: "air india" AIC)
G.airline_name_codes = {}
for _, list in ipairs({ names.airlines, names.common }) do
  for _, a in ipairs(list) do G.airline_name_codes[a[1]] = G.airline_name_codes[a[1]] or a[2] end
end
-- "delete the aircraft of Ibex", "the plane of Japan Airlines": "the", a noun of lexicon.aircraft_nouns, "of" and an
-- airline's telephony or common name (G.airline_name_codes, one to three words) with no flight number after it is
-- read as "the Ibex aircraft" (the callsign matcher's airline said alone: its one aircraft flying, several asked);
-- a flight number after the name ("the aircraft of Ibex 31") leaves the text as said. Returns the text.
G.aircraft_nouns = {}
for _, w in ipairs(lexicon.aircraft_nouns) do G.aircraft_nouns[w] = true end
function G.aircraft_of_airline(text)
  if not text:find(" of ", 1, true) then return text end
  local from = 1
  while true do
    local b, noun, p = text:match("()%f[%a][Tt]he%s+(%a+)%s+[Oo]f%s+()", from)
    if not b then return text end
    from = p
    local words, ends, k = {}, {}, p
    while G.aircraft_nouns[noun:lower()] and #words < 3 do
      local w, e = text:match("^(%a+)()", k)
      if not w then break end
      words[#words + 1], ends[#ends + 1] = w, e
      k = text:match("^ +()", e) or e
    end
    -- (the longest name said: "the plane of China Eastern Airlines 5229" is a callsign, never "China Eastern")
    for n = #words, 1, -1 do
      local after = text:sub(ends[n]):match("^[%s,]*(%w+)")
      if G.airline_name_codes[table.concat(words, " ", 1, n):lower()] then
        if not (after and (after:match("^%d") or SAID_DIGIT[after:lower()])) then
          text = text:sub(1, b + 3) .. text:sub(p, ends[n] - 1) .. " " .. noun .. text:sub(ends[n])
        end
        break
      end
    end
  end
end
-- "put in a Transat A321, TSC 302, at FRANX": an airline's ICAO code typed in capitals apart from its flight
-- number is joined to it when the request names that airline by a word of its own ("Transat": TSC).
-- "Create Portugalia 1921, call sign PGA1921, ...": a callsign said by its airline's one-word telephony and
-- then written out after "callsign" (the same airline, the same flight number) is said once, as written.
local function named_airline_ids(text)
  if text:find("[Cc]all[%s%-]*[Ss]ign") then
    text = text:gsub("%f[%a](%a+)%s+(%d+%a*)%s*,%s*[Cc]all[%s%-]*[Ss]ign%s+(%u%u%u)(%w+)%f[%W]", function(w, n, code, num)
      if AIRLINE_WORDS[w:lower()] == code and n:upper() == num:upper() then return code .. num end
      return nil
    end)
  end
  -- ("create SpiceJet SG 2709", "Air India AI 657"): the airline's IATA code typed between its name and the flight
  -- number (names.iata, names.iata_digit) says the airline again, and is dropped
  if text:find("%f[%w][%u%d]%u?%d?%s+%d") then
    text = text:gsub("()%f[%w]([%u%d][%u%d])%s+(%d+%a?)%f[%W]", function(at, code, n)
      local icao = names.iata[code] or names.iata_digit[code]
      local before = icao and text:sub(1, at - 1):lower():match("(%a[%a ]*%a)%s+$")
      for k = 1, before and 3 or 0 do
        local name = before:match(string.rep("%a+%s+", k - 1) .. "%a+$")
        if name and G.airline_name_codes[name] == icao then return n end
      end
      return nil
    end)
  end
  if not text:find("%u%u%u%s+%d") then return text end
  local said = {}
  for w in text:gmatch("%a+") do
    local code = AIRLINE_WORDS[w:lower()]
    if code and code ~= w:upper() then said[code] = true end  -- (the code itself names no airline: "KLM 36 14")
  end
  return (text:gsub("%f[%w](%u%u%u)%s+(%d+%a?)%f[%W]", function(code, n)
    if said[code] then return code .. n end
    return nil
  end))
end
local function airline_values(text, fleet)
  local ids = {}
  for _, a in ipairs(fleet) do ids[a.id:upper()] = true end
  -- the noun's plain word when `w` is the telephony of lexicon.value_noun_airlines and no aircraft of that
  -- airline flies (nil otherwise)
  local function idle_noun(w)
    local noun = lexicon.value_noun_airlines[w:lower()]
    if not noun then return nil end
    for id in pairs(ids) do
      if id:sub(1, #noun[1]) == noun[1] and id:sub(#noun[1] + 1):match("^%d") then return nil end
    end
    return noun[2]
  end
  -- (the passes up to "velocity" read an airline after "the" ("The"): with no "the" said, none changes the text)
  local the_said = text:find("the", 1, true) or text:find("The", 1, true)
  -- "the Ryanair one", "the lufthansa one": "one" is the aircraft, no flight number 1 (unless an
  -- aircraft has that id, or a number follows: "the Ryanair one two three")
  if the_said then
    text = text:gsub("(%f[%a][Tt]he%s+)(%a+)(%s+)[Oo]ne(%f[%A][%s,]*)([%w%-]*)", function(the, w, s1, s2, nx)
      local icao = AIRLINE_WORDS[w:lower()]
      if icao and not ids[icao .. "1"] and not nx:match("%d") and not SPOKEN_DIGITS[nx:lower()] then
        return the .. w .. s1 .. "aircraft" .. s2 .. nx
      end
      return nil
    end)
  end
  -- ("give the easyJet 30 left", "the Air France 20 right": the degrees of a turn, 1 to 180, before its side
  -- with no number after it; "turn the easyJet 30 left 20" keeps the callsign, matched or asked)
  local function turn_by(n, side, pos)
    local nx = text:match("^[%s,]*([%w%-]*)", pos)
    return (side == "left" or side == "right") and tonumber(n) >= 1 and tonumber(n) <= 180
      and not nx:match("^%d") and not NUMBER_WORDS[nx:lower()]
  end
  for _, pattern in ipairs(the_said and { "(%f[%a][Tt]he%s+)(%a+)(%s+)(%d+)(%s+)(%a+)()",
                                          "(%f[%a][Tt]he%s+)(%a+%s+%a+)(%s+)(%d+)(%s+)(%a+)()" } or {}) do
    text = text:gsub(pattern, function(the, w, s1, n, s2, unit, pos)
      local icao = not idle_noun(w) and AIRLINE_WORDS[w:lower():gsub("%s+", " ")]
      if icao and not ids[icao .. n] and (lexicon.value_units[unit:lower()] or turn_by(n, unit:lower(), pos)) then
        return the .. w .. "," .. s1 .. n .. s2 .. unit
      end
      return nil
    end)
  end
  -- ("let the Condor turn 45 degrees right", "the Lufthansa now climb 2000 feet": a number with its unit said after
  -- "the", an airline and a verb of lexicon.airline_value_verbs (one of airline_value_leads before it or none) is the
  -- value, never a flight number with the airline's words misheard before it: a comma keeps the callsign matcher
  -- from reading another aircraft flying with that number, UAE45, out of the words)
  local function value_verb(ws)
    local first, last = ws:match("^(%a+)%s+(%a+)%s+$")
    if not first then return lexicon.airline_value_verbs[ws:match("%a+"):lower()] end
    return lexicon.airline_value_verbs[last:lower()] and lexicon.airline_value_leads[first:lower()]
  end
  for _, pattern in ipairs(the_said and { "(%f[%a][Tt]he%s+)(%a+)(%s+)(%a+%s+)(%d+)(%s+)(%a+)",
                                          "(%f[%a][Tt]he%s+)(%a+)(%s+)(%a+%s+%a+%s+)(%d+)(%s+)(%a+)",
                                          "(%f[%a][Tt]he%s+)(%a+%s+%a+)(%s+)(%a+%s+)(%d+)(%s+)(%a+)" } or {}) do
    text = text:gsub(pattern, function(the, w, s1, between, n, s2, unit)
      if AIRLINE_WORDS[w:lower():gsub("%s+", " ")] and value_verb(between) and lexicon.value_units[unit:lower()] then
        return the .. w .. "," .. s1 .. between .. n .. s2 .. unit
      end
      return nil
    end)
  end
  -- (the value said in words, one or two of them, after an airline of one or two words: "turn the Lufthansa ten
  -- degrees left", "the Finnair thirty five degrees right", "move the Air Portugal twenty miles to the south")
  local function spoken(ws)
    for w in ws:gmatch("[^%s%-]+") do
      if not NUMBER_WORDS[w:lower()] then return false end
    end
    return true
  end
  for _, pattern in ipairs(the_said and { "(%f[%a][Tt]he%s+)(%a+)(%s+)([%a%-]+%s+[%a%-]+)(%s+)(%a+)",
                                          "(%f[%a][Tt]he%s+)(%a+)(%s+)([%a%-]+)(%s+)(%a+)",
                                          "(%f[%a][Tt]he%s+)(%a+%s+%a+)(%s+)([%a%-]+%s+[%a%-]+)(%s+)(%a+)",
                                          "(%f[%a][Tt]he%s+)(%a+%s+%a+)(%s+)([%a%-]+)(%s+)(%a+)" } or {}) do
    text = text:gsub(pattern, function(the, w, s1, n, s2, unit)
      if AIRLINE_WORDS[w:lower():gsub("%s+", " ")] and spoken(n) and lexicon.value_units[unit:lower()] then
        return the .. w .. "," .. s1 .. n .. s2 .. unit
      end
      return nil
    end)
  end
  -- "VLG12AB velocity 250 knots", "increase the velocity of TAP57": an airline's telephony that is also the
  -- noun of a value (lexicon.value_noun_airlines: word -> {ICAO prefix, the noun's plain word}) is that noun
  -- before a number and its unit or after another value's number or unit, unless the airline and the number said
  -- digit by digit are an aircraft flying ("Velocity 250, 280 knots"); and, when no aircraft of the airline flies,
  -- after an article or a possessive, or before a number after a word of the request that is no "and" or "then"
  -- and no punctuation ("put velocity 260", "the Volaris velocity 230": a Spanish or Portuguese speaker's
  -- "velocidad"; the request's first word, "Velocity 250, climb ...", stays a callsign, matched or asked)
  if text:lower():find("velocity", 1, true) then
    local toks = {}
    for w in text:gmatch("%S+") do toks[#toks + 1] = w end
    text = require("translate.tokens").rewrite(text, toks, function(i)
      local noun = not toks[i]:match("%p$") and lexicon.value_noun_airlines[toks[i]:lower()]
      if not noun then return nil end
      local icao, plain = noun[1], noun[2]
      local before = i > 1 and toks[i - 1]:lower()
      if before and idle_noun(toks[i]) and (lexicon.value_noun_before[before] or not before:match("%p$")
          and before ~= "and" and before ~= "then" and toks[i + 1] and (toks[i + 1]:match("^%d")
          or NUMBER_WORDS[toks[i + 1]:lower():gsub("%p+$", "")])) then
        return plain, i + 1
      end
      local k, digits = i + 1, ""
      while toks[k] and not toks[k - 1]:match("%p$") do
        local x = toks[k]:lower()
        if not (NUMBER_WORDS[x] or x:match("^%d+$")) then break end
        digits = digits and (SAID_DIGIT[x] or x:match("^%d+$")) and digits .. (SAID_DIGIT[x] or x) or nil
        k = k + 1
      end
      local unit = k > i + 1 and toks[k] and toks[k]:lower():gsub("%p+$", "")
      if unit and lexicon.value_units[unit] and not (digits and ids[icao .. digits]) then return plain, i + 1 end
      -- (straight after another value's number or unit: the next field of a list, "heading 090 altitude 14000 feet
      -- velocity 240")
      if before and (before:match("^%d[%d%.]*$") or lexicon.value_units[before])
          and not (digits and ids[icao .. digits]) then
        return plain, i + 1
      end
      return nil
    end)
  end
  -- "Shamrock 1 2 3": a flight number typed digit by digit after its airline's telephony, three or four
  -- single digits in a row, is one number
  if not text:find("%d %d %d") then return text end
  return (text:gsub("(%f[%a]%a+%s+)(%d[%d%s]*%d)%f[^%d%s]", function(w, run)
    if not AIRLINE_WORDS[w:match("%a+"):lower()] or not run:match("^%d %d %d$") and not run:match("^%d %d %d %d$") then
      return nil
    end
    return w .. run:gsub("%s", "")
  end))
end

-- "speedbird123", "easy45", "airfrance77": an airline's telephony (or name), its words run together, run
-- into the flight number, as speech recognition writes it, is the id of the aircraft flying with that
-- airline and number (matched exactly; anything else stays as said)
local GLUED_AIRLINES = {}
for _, list in ipairs({ names.airlines, names.common }) do
  for _, a in ipairs(list) do
    local glued = a[1]:gsub("%s", "")
    GLUED_AIRLINES[glued] = GLUED_AIRLINES[glued] or a[2]
  end
end
-- "Airindia 131", "gulfair five two": an airline's telephony of several words typed as one word straight before
-- a flight number (digits, or a digit said) is those words ("Air India 131"); a word that is a telephony of its
-- own ("airbaltic") stays as typed.
G.telephony_joined = {}  -- the words of a telephony run together (lower case) -> the telephony
for _, a in ipairs(names.airlines) do
  local joined = a[1]:gsub("%s", "")
  if joined ~= a[1] and not AIRLINE_WORDS[joined] then
    G.telephony_joined[joined] = G.telephony_joined[joined] or a[1]
  end
end
do  -- G.joined_word: a word and the spaces after it, a word shorter than every telephony run together never matched
  local shortest = math.huge
  for joined in pairs(G.telephony_joined) do shortest = math.min(shortest, #joined) end
  G.joined_word = "%f[%a](" .. ("%a"):rep(shortest) .. "%a*)(%s+)()"
end
function G.joined_telephony(text)
  return (text:gsub(G.joined_word, function(w, space, at)
    local said = G.telephony_joined[w:lower()]
    if not said then return nil end
    local nx = text:match("^%w+", at)
    if not nx or not (nx:match("^%d") or SAID_DIGIT[nx:lower()]) then return nil end
    return (w:match("^%u") and said:gsub("%f[%a]%a", string.upper) or said) .. space
  end))
end
-- In a creation ("create a new aircraft delta1022 b739 ..."), after one of lexicon.creation_verbs, it is the
-- new aircraft's id: the airline's ICAO code and the number, as for an aircraft that flies; typed in capitals
-- as an id of up to eight characters ("create ASCOT42 ..."), it is the id as typed. A word that opens the id
-- of an aircraft flying ("ascot42" with ASCOT41 flying) is an id's prefix, typed as such.
local function glued_telephony(text, fleet)
  local ids, prefixes = {}, {}
  for _, a in ipairs(fleet) do
    ids[a.id:upper()] = a.id
    prefixes[(a.id:match("^%a+") or ""):upper()] = true
  end
  return (text:gsub("()%f[%w](%a+)(%d%w*)%f[%W]", function(at, word, number)
    local icao = not prefixes[word:upper()] and GLUED_AIRLINES[word:lower()]
    local id = icao and ids[(icao .. number):upper()]
    if not G.icao_codes then  -- (every airline's ICAO designator, upper case -> true)
      G.icao_codes = {}
      for _, a in ipairs(names.airlines) do G.icao_codes[a[2]] = true end
    end
    -- (a word that is itself an airline's ICAO designator, "tui1ab" with TUI TUIfly's, is that airline's id)
    if icao and not id and #number <= 4 and number:match("^%d+%a?%a?$")
        and not (word:match("^%u%u+$") and #word + #number <= 8) and not G.icao_codes[word:upper()] then
      for w in text:sub(1, at - 1):lower():gmatch("%a+") do
        if lexicon.creation_verbs[w] then id = (icao .. number):upper() end
      end
    end
    -- (an id typed as such stays as typed, in its case: "klm88v")
    if not id or id:upper() == (word .. number):upper() then return nil end
    return word:find("%u") and id or id:lower()
  end))
end

-- "wizzair to lima papa", "france soleil five to kilo lima", "lufthansa for hundred": a word speech
-- recognition writes for a digit (lexicon.digit_homophones) after an airline's word or a digit or letter
-- said, or before one, is that digit when the text so read names exactly one aircraft flying, matched
-- exactly, that the text as heard does not (nor one whose id begins that aircraft's: with BAW4 and BAW42
-- flying, "speedbird four to ..." stays as said); anything else stays as said (and may be asked about).
local CALLSIGN_WORDS = { hundred = true, thousand = true }
for w in pairs(SPOKEN_DIGITS) do CALLSIGN_WORDS[w] = true end
local AIRLINE_LAST = {}  -- the last word of each airline's telephony or name
for _, list in ipairs({ names.airlines, names.common, names.brands }) do
  for _, a in ipairs(list) do AIRLINE_LAST[a[1]:match("(%S+)$")] = true end
end
-- (`parsed`: text -> its set, the reads of one request already parsed; each parse costs ~10 us)
local function exact_aircraft(text, world, parsed)
  if parsed[text] then return parsed[text] end
  local found = {}
  for _, r in ipairs(squawk.translate.utterance(text, world, NAMES):refs()) do
    if r.kind == "aircraft" and r.exists and not r.heard then found[r.name:upper()] = true end
  end
  parsed[text] = found
  return found
end
-- The one aircraft a re-read of the request names exactly that `said` (the text as heard) did not, and whose
-- callsign no aircraft of `said` begins: its id, or nil when none or several
function G.one_new_aircraft(read, said, world, parsed)
  local new
  for id in pairs(exact_aircraft(read, world, parsed)) do
    if not said[id] then new = new == nil and id or false end
  end
  for id in pairs(new and said or {}) do
    if new:sub(1, #id) == id then new = false end
  end
  return new or nil
end
-- "climb Qatar 846", "delete Malaysia 2608", "direct Hong Kong Airlines 612 to LIMES": a name an airline is known
-- by that is no telephony (names.common; the callsign matcher knows telephony only) said before a flight number
-- (digits, or a digit said), wherever it stands, is read as the airline's telephony (its ICAO designator where
-- squawk knows none) when the text so read names exactly one aircraft flying, matched exactly, that the text as
-- said does not, and keeps every one it does; anything else stays as said. A name said straight after a word of
-- another airline's name ("AirAsia Malaysia 88") is part of that name; one that is an airline's two-letter code
-- ("BA 456") is a partial callsign, asked.
G.common_read = {}  -- {name (lower case), what the matcher reads for it}, longest name first
do
  local telephony, said = {}, {}  -- (an airline's first telephony; the names that are a telephony)
  for _, a in ipairs(names.airlines) do
    telephony[a[2]], said[a[1]] = telephony[a[2]] or a[1], true
  end
  for _, a in ipairs(names.common) do
    if not said[a[1]] and not names.iata[a[1]:upper()] then
      G.common_read[#G.common_read + 1] = { a[1], telephony[a[2]] or a[2] }
    end
  end
  table.sort(G.common_read, function(x, y) return #x[1] > #y[1] end)
  -- G.common_by_first[w]: the places in G.common_read, ascending, of the names whose first word (run of %w) is w
  G.common_by_first = {}
  for k, c in ipairs(G.common_read) do
    local w = c[1]:match("^%w+")
    G.common_by_first[w] = G.common_by_first[w] or {}
    table.insert(G.common_by_first[w], k)
  end
end
function G.common_named(text, world, parsed)
  if #world.aircraft == 0 or not text:find("%d") and not text:find("%a%s+%a") then return text end
  local said, lower = nil, text:lower()
  -- (a name is found whole only where its first word is a word of the text: those names, in G.common_read's order)
  local places, seen = {}, {}
  for w in lower:gmatch("%w+") do
    if not seen[w] then
      seen[w] = true
      local first = G.common_by_first[w]
      for j = 1, first and #first or 0 do places[#places + 1] = first[j] end
    end
  end
  table.sort(places)
  for _, k in ipairs(places) do
    local c = G.common_read[k]
    local at = lower:find(c[1], 1, true) and lower:find("%f[%w]" .. c[1]:gsub("%p", "%%%0") .. "%f[%W]")
    local nx = at and lower:match("^%s+(%w+)", at + #c[1])
    local before = at and lower:sub(1, at - 1):match("(%a+)%s+$")
    if nx and (nx:match("^%d") or SAID_DIGIT[nx]) and not (before and (AIRLINE_WORDS[before] or G.name_words[before])) then
      local read = text:sub(1, at - 1) .. (text:sub(at, at):match("%u") and c[2]:gsub("%f[%a]%a", string.upper) or c[2])
        .. text:sub(at + #c[1])
      parsed = parsed or {}
      said = said or exact_aircraft(text, world, parsed)
      local keeps = G.one_new_aircraft(read, said, world, parsed) ~= nil
      for id in pairs(keeps and said or {}) do keeps = keeps and exact_aircraft(read, world, parsed)[id] end
      if keeps then return G.common_named(read, world, parsed) end
    end
  end
  return text
end
local function homophone_ids(text, world, parsed)
  if #world.aircraft == 0 then return text end
  parsed = parsed or {}
  local toks, bare = plain_words(text)
  local said, held
  for i = 1, #bare do
    local w = bare[i]
    local digit = lexicon.digit_homophones[w]
    local prev, nxt = bare[i - 1], bare[i + 1]
    local glued = digit and prev and not toks[i - 1]:match("%p$") and (not nxt or not toks[i]:match("%p$"))
    if glued and (AIRLINE_LAST[prev] or CALLSIGN_WORDS[prev] or prev:match("^%d+$")
        or (nxt and (CALLSIGN_WORDS[nxt] or nxt:match("^%d+$")))) then
      -- (read with every homophone of the words said with it, "lufthansa for oh oh", else this one alone)
      local words, alone = {}, {}
      for k, t in ipairs(toks) do words[k], alone[k] = t, t end
      alone[i] = digit .. (toks[i]:match("%p+$") or "")
      -- (a read names an aircraft the text does not only by a digit it reads there: the reads are parsed
      -- only when a digit read is in the id of an aircraft flying; `held`: their ids joined)
      if not held then
        held = {}
        for _, a in ipairs(world.aircraft) do held[#held + 1] = a.id end
        held = table.concat(held, " ")
      end
      local holds = false
      for k = i, #toks do
        local h = lexicon.digit_homophones[bare[k]]
        if k > i and (toks[k - 1]:match("%p$") or not (h or CALLSIGN_WORDS[bare[k]] or bare[k]:match("^%d+$"))) then
          break
        end
        if h then
          words[k] = h .. (toks[k]:match("%p+$") or "")
          holds = holds or held:find(SAID_DIGIT[h], 1, true) ~= nil
        end
      end
      said = holds and (said or exact_aircraft(text, world, parsed))
      for _, read in ipairs(holds and { table.concat(words, " "), table.concat(alone, " ") } or {}) do
        if G.one_new_aircraft(read, said, world, parsed) then return homophone_ids(read, world, parsed) end
      end
    end
  end
  return text
end

-- "lufthansafour tango kilo", "luft hansa four tango kilo", "condor sevenalpha bravo": a callsign's words that
-- speech recognition ran together (a word no English squawk knows that is wholly an airline's telephony, its
-- words run together, and the digits and phonetic letters said after it) or split apart (two words that
-- together are such a telephony) are those words when the text so read names exactly one aircraft flying,
-- matched exactly, that the text as heard does not (nor one whose id begins that aircraft's); anything else
-- stays as heard (and is asked about).
function G.recognised_callsigns(text, world, parsed)
  if #world.aircraft == 0 then return text end
  -- (G.split_airlines: the first part of a one-word telephony split in two, two letters or more, -> the
  -- telephonies it begins; built once, on first use)
  if not G.split_airlines then
    G.split_airlines = {}
    for _, list in ipairs({ names.airlines, names.common }) do
      for _, a in ipairs(list) do
        for k = 2, #a[1] - 2 do
          if not a[1]:find("%s") then
            local head = a[1]:sub(1, k)
            G.split_airlines[head] = G.split_airlines[head] or {}
            G.split_airlines[head][a[1]] = true
          end
        end
      end
    end
  end
  local heads = G.split_airlines
  -- (the last three letters of a digit or phonetic letter said, which end a callsign's words run together)
  if not G.spoken_tails then
    G.spoken_tails = {}
    for w in pairs(SPOKEN_DIGITS) do G.spoken_tails[w:sub(-3)] = true end
  end
  -- (a word to read only when some word of the text may be one: a word of six lower-case letters or more
  -- ending as a digit or letter said, no English squawk knows, or a telephony's first part before its rest)
  local maybe = false
  for at, w in text:gmatch("()(%a+)") do
    if #w >= 6 and G.spoken_tails[w:sub(-3)] and not w:find("%u") and not SPOKEN_DIGITS[w] and not known_word(w) then
      maybe = true
      break
    end
    local rest = heads[w] and text:match("^%s+(%a+)", at + #w)
    if rest and heads[w][w .. rest:lower()] then
      maybe = true
      break
    end
  end
  if not maybe then return text end
  local toks, bare = plain_words(text)
  local function part(w) return GLUED_AIRLINES[w] or SPOKEN_DIGITS[w] end
  -- (the words `w` is, run together, in order; nil unless wholly such words, two or more)
  local function apart(w)
    local ends = { [0] = {} }
    for e = 1, #w do
      for b = math.max(1, e - 16), e do
        if ends[b - 1] and not ends[e] and part(w:sub(b, e)) then
          local words = { table.unpack(ends[b - 1]) }
          words[#words + 1] = w:sub(b, e)
          ends[e] = words
        end
      end
    end
    return ends[#w] and #ends[#w] >= 2 and table.concat(ends[#w], " ") or nil
  end
  local reads = {}
  for i, w in ipairs(bare) do
    local lead = i == 1 or not toks[i - 1]:match("%p$")
    if lead and #w >= 6 and w:match("^%l+$") and not SPOKEN_DIGITS[w] and not known_word(w) then
      local words = apart(w)
      if words then reads[#reads + 1] = { i, i, words } end
    end
    local nxt = bare[i + 1]
    if lead and nxt and heads[w] and not toks[i]:match("%p$") and heads[w][w .. nxt] then
      reads[#reads + 1] = { i, i + 1, w .. nxt }
    end
  end
  if #reads == 0 then return text end
  parsed = parsed or {}
  local said = exact_aircraft(text, world, parsed)
  for _, r in ipairs(reads) do
    local words = { table.unpack(toks, 1, r[1] - 1) }
    words[#words + 1] = r[3] .. (toks[r[2]]:match("%p+$") or "")
    for k = r[2] + 1, #toks do words[#words + 1] = toks[k] end
    local read = table.concat(words, " ")
    if G.one_new_aircraft(read, said, world, parsed) or G.same_one_aircraft(read, said, world, parsed) then
      return G.recognised_callsigns(read, world, parsed)
    end
  end
  return text
end
-- True when a re-read of the request names exactly one aircraft, matched exactly, and `said` (the text as heard)
-- names that one alone: "luft hansa four oh four" heard as DLH404 by its "hansa" still reads "lufthansa", so that
-- no part of the airline's word is left over as a word of its own (nor spelled into one: "luft" as "left").
function G.same_one_aircraft(read, said, world, parsed)
  local one
  for id in pairs(exact_aircraft(read, world, parsed)) do
    if one then return false end
    one = id
  end
  for id in pairs(said) do
    if id ~= one then return false end
  end
  return one ~= nil and said[one] == true
end

-- A flight level said in whole hundreds after "flight level", "level" or "FL" ("one hundred", "two hundred"), a
-- digit word and a word of tens or "hundred" straight after it, is the level, the words after another value said
-- in the same breath: "flight level one hundred two fifty knots" -> "flight level 100 two fifty knots" (FL100 and
-- 250 kt; no level is said "one hundred two").
G.level_hundreds_digit = { one = "1", two = "2", three = "3", four = "4" }
G.level_hundreds_next = { twenty = true, thirty = true, forty = true, fifty = true, sixty = true, seventy = true,
  eighty = true, ninety = true, hundred = true }
function G.level_hundreds_apart(text)
  if not text:lower():find("hundred", 1, true) then return text end
  local toks, bare = plain_words(text)
  return tokens.rewrite(text, toks, function(i)
    local d = G.level_hundreds_digit[bare[i] or ""]
    if not (d and bare[i + 1] == "hundred" and (bare[i - 1] == "fl" or bare[i - 1] == "level")
        and G.below_hundred[bare[i + 2] or ""] and (G.below_hundred[bare[i + 2]] or 10) < 10
        and G.level_hundreds_next[bare[i + 3] or ""]) then
      return nil
    end
    if toks[i]:match("%p$") or toks[i + 1]:match("%p$") or toks[i + 2]:match("%p$") then return nil end
    return d .. "00", i + 2
  end)
end

-- "Air Canada four hundred twelve", "Air Canada four-hundred-twelve": a flight number said in hundreds straight
-- after an airline's word (a digit one to nine, "hundred", then one to ninety-nine in words) is its three
-- digits ("Air Canada 412") when the text so read names exactly one aircraft flying, matched exactly, that the
-- text as said does not; else the text stays as said.
G.below_hundred = { one = 1, two = 2, three = 3, four = 4, five = 5, six = 6, seven = 7, eight = 8, nine = 9,
  ten = 10, eleven = 11, twelve = 12, thirteen = 13, fourteen = 14, fifteen = 15, sixteen = 16, seventeen = 17,
  eighteen = 18, nineteen = 19, twenty = 20, thirty = 30, forty = 40, fifty = 50, sixty = 60, seventy = 70,
  eighty = 80, ninety = 90 }
function G.hundreds_callsign(text, world)
  if #world.aircraft == 0 or not text:find("[Hh][Uu][Nn][Dd][Rr][Ee][Dd]") then return text end
  local spaced = text:gsub("%S*[Hh][Uu][Nn][Dd][Rr][Ee][Dd]%S*", function(w) return (w:gsub("(%a)%-(%a)", "%1 %2")) end)
    :gsub("([Hh][Uu][Nn][Dd][Rr][Ee][Dd]%s+%a+)%-(%a)", "%1 %2")
  local toks, bare = plain_words(spaced)
  local N = G.below_hundred
  for i = 2, #toks - 2 do
    local d = SAID_DIGIT[bare[i]]
    local at = bare[i + 2] == "and" and not toks[i + 1]:match("%p$") and i + 3 or i + 2  -- ("four hundred and twelve")
    local n = N[bare[at]]
    if AIRLINE_LAST[bare[i - 1]] and d and d ~= "0" and bare[i + 1] == "hundred" and n
        and not toks[i]:match("%p$") and not toks[at - 1]:match("%p$") then
      local last = at
      local ones = N[bare[at + 1]]
      if n >= 20 and n % 10 == 0 and ones and ones < 10 and not toks[at]:match("%p$") then
        n, last = n + ones, at + 1
      end
      local words = {}
      for k = 1, i - 1 do words[#words + 1] = toks[k] end
      words[#words + 1] = string.format("%s%02d", d, n) .. (toks[last]:match("%p+$") or "")
      for k = last + 1, #toks do words[#words + 1] = toks[k] end
      local read, parsed = table.concat(words, " "), {}
      local said, new = exact_aircraft(text, world, parsed), nil
      for id in pairs(exact_aircraft(read, world, parsed)) do
        if not said[id] then new = new == nil and id or false end
      end
      if new then return read end
    end
  end
  return text
end

-- A dash standing alone (" - ", " -- ", an en or em dash; a bracket written_forms made one: "800 ft
-- (testing reduced vertical)") sets what follows apart: it is read as a comma (the lexer drops dashes),
-- and the ordinals of the commas dashes became are returned as a set (G:in_reason reads commentary after
-- them). A comma between digits ("6,000") is no comma token and is not counted.
local DASHES = { "^%s+%-%-?%s+", "^%s*\xE2\x80[\x93\x94]%s*" }
-- lexicon.spelled_out as case-blind Lua patterns over whole words, built once: { words, pattern, short }
-- "ANA51 - not 515 - please increase ...", "ANA51, not ANA515, climb ...": an aircraft flying, then "not" and
-- another aircraft flying of the same airline (its number alone, or its callsign), set apart by dashes or commas:
-- the speaker rules the other out, so "not" and the other are dropped and the first stays addressed. The other
-- not flying, or of another airline, nothing changes (asked).
function G.other_callsign_denied(text, aircraft)
  if not text:lower():find("not", 1, true) then return text end
  local ids = {}
  for _, a in ipairs(aircraft) do ids[a.id:upper()] = true end
  return (text:gsub("(%f[%w](%a%a%a?)(%d+%a?))(%s*[,%-]%s*)[Nn][Oo][Tt]%s+(%a*)(%d+%a?)%s*([,%-])",
    function(first, prefix, _, sep, other_prefix, number, close)
      local other = (other_prefix ~= "" and other_prefix or prefix):upper() .. number:upper()
      if not (ids[first:upper()] and ids[other] and other ~= first:upper()
          and (other_prefix == "" or other_prefix:upper() == prefix:upper())
          and (sep:find(",", 1, true) ~= nil) == (close == ",")) then
        return nil
      end
      return first .. close
    end))
end
local SPELLED_OUT = {}
for words, short in pairs(lexicon.spelled_out) do
  local pattern = words:gsub("%a", function(c) return "[" .. c:lower() .. c:upper() .. "]" end):gsub(" ", "%%s+")
  SPELLED_OUT[#SPELLED_OUT + 1] = { words = words, pattern = "%f[%a]" .. pattern .. "%f[%A]", short = short }
end
-- (the longest words first: "closest point of approach" before "past the closest point")
table.sort(SPELLED_OUT, function(a, b) return #a.words > #b.words or (#a.words == #b.words and a.words < b.words) end)

local function set_apart(text)
  if not text:find("%s%-") and not text:find("\xE2\x80[\x93\x94]") then return text, nil end
  local out, marks, n, i = {}, {}, 0, 1
  while i <= #text do
    local dash
    for _, pat in ipairs(DASHES) do dash = dash or text:match(pat, i) end
    local c = text:sub(i, i)
    if dash then
      n = n + 1
      marks[n] = true
      out[#out + 1], i = " , ", i + #dash
    else
      if c == "," and not (text:sub(i - 1, i - 1):match("%d") and text:sub(i + 1, i + 1):match("%d")) then n = n + 1 end
      out[#out + 1], i = c, i + 1
    end
  end
  return table.concat(out), marks
end

-- "dlh9mk add betus after nurmo", "dct spi": in a line typed with no capital letter, a word in a place's
-- slot (after "add", "dct", "after", ...; then each name listed straight after it) that is no word squawk
-- knows and that the navdata holds as a fix, navaid or airport (world.place_known) within TYPED_PLACE_NM
-- of an aircraft that flies (a recogniser's word far away, "direct sachs", is no such place) is that
-- place, as if typed in capitals; without navdata nothing changes. In a line with capitals only a word
-- written as a proper name is read so ("Add Willo to Easy 8472's route"; "add willo" there stays a word).
-- A name speech recognition split into
-- syllables ("direct toe bix", "as bin", "u no ko") is joined when the first word alone is no such place and
-- two or three words run together (four or five letters, no punctuation between) are one: a word squawk
-- does not know that is such a fix near the traffic, or one on an aircraft's route.
local PLACE_SLOTS = { add = true, append = true, insert = true, dct = true, dtc = true, drct = true, direct = true,
  after = true, before = true, via = true, over = true, cross = true, at = true, ["then"] = true,
  -- (where a limit ends, what a distance is from and what vectors lead to: "spd 250 til ccc", "20 nm from dca",
  -- "hdg 210 vctr alb")
  ["until"] = true, till = true, from = true, vectors = true, vector = true, vctr = true, vect = true, vects = true }
local TYPED_PLACE_NM = 250
-- the slots of PLACE_SLOTS that are a place's verb: a word straight after one that squawk knows only as
-- another word's inflection ("ezy45 add echos", ECHOS; "echo" is a command) is read as a place too
G.place_verbs = set_of({ "add", "append", "insert", "dct", "dtc", "drct", "direct" })
-- patterns finding a word of PLACE_SLOTS as a whole word in " " .. lower-case text .. " "
local PLACE_SLOT_PATTERNS = {}  -- {word, pattern}
for w in pairs(PLACE_SLOTS) do PLACE_SLOT_PATTERNS[#PLACE_SLOT_PATTERNS + 1] = { word = w, pattern = "%s" .. w .. "%s" } end
-- "destination c y v r", "origin boston k b o s": four single letters spelled in a row (none before or after)
-- that join into an airport's ICAO code the navdata holds (world.airport_class), and no aircraft's id, are
-- that code
local function spelled_airports(text, world)
  if not world.airport_class then return text end
  if not text:find("%l%s+%l%s+%l%s+%l") then return text end  -- (no four letters apart in a row)
  local ids = {}
  for _, a in ipairs(world.aircraft) do ids[(a.id or ""):upper()] = true end
  local toks = {}
  for w in text:gmatch("%S+") do toks[#toks + 1] = w end
  return tokens.rewrite(text, toks, function(i)
    if (toks[i - 1] and toks[i - 1]:match("^%a$")) or not toks[i]:match("^%l$") then return nil end
    for k = i + 1, i + 3 do
      if not (toks[k] and toks[k]:match("^%l$")) then return nil end
    end
    local last = toks[i + 4] and toks[i + 4]:match("^(%l)%p+$")
    if last or (toks[i + 4] and toks[i + 4]:match("^%a$")) then return nil end
    local code = table.concat(toks, "", i, i + 3):upper()
    if ids[code] or (world.airport_class(code) or "") == "" then return nil end
    return code, i + 4
  end)
end
-- "maintain 280 knots until kilo victor", "direct Kilo Alpha Victor": two to five letters spelled in the
-- phonetic alphabet straight after a word of a place's slot (PLACE_SLOTS, "until", "till", "to", "passing") that
-- join into a waypoint on the route of an aircraft flying are that waypoint's ident ("until KV"); others stay as
-- said.
G.spelled_slots = { ["until"] = true, till = true, to = true, passing = true }
G.spelled_dist_units = { miles = true, mile = true, nm = true, nmi = true, dme = true, km = true }
function G.spelled_route_places(text, world)
  local routed = {}
  for _, a in ipairs(world.aircraft) do
    for _, r in ipairs(a.route or {}) do routed[r:upper()] = true end
  end
  if not next(routed) then return text end
  local toks, bare = plain_words(text)
  return tokens.rewrite(text, toks, function(i)
    local slot = bare[i - 1]
    -- ("within 20 miles of lima oscar sierra": "of" after a distance's unit, as "from")
    local of_dist = slot == "of" and G.spelled_dist_units[bare[i - 2] or ""]
    -- ("where is victor tango kilo": the place asked about)
    of_dist = of_dist or ((slot == "is" and bare[i - 2] == "where") or slot == "where's" or slot == "wheres")
    if not (slot and (PLACE_SLOTS[slot] or G.spelled_slots[slot] or of_dist) and lexicon.phonetic[bare[i]])
        or toks[i - 1]:match("%p$") then
      return nil
    end
    local letters, k = "", i
    while k <= #toks and #letters < 5 and lexicon.phonetic[bare[k]] do
      letters, k = letters .. lexicon.phonetic[bare[k]]:upper(), k + 1
      if toks[k - 1]:match("%p$") then break end
    end
    if #letters < 2 or lexicon.phonetic[bare[k] or ""] or not routed[letters] then return nil end
    return letters .. (toks[k - 1]:match("%p+$") or ""), k
  end)
end
-- "create i fly one one to a three twenty one ...", "create Indigo four five for an A320 ...": in a request to create
-- an aircraft, a word speech recognition writes for a digit ("to", "too", "for", "fore") straight after the digit
-- words of the callsign and before "a" or "an" and the type may be the callsign's last digit (IGO112) or a word
-- (IGO11): the question to ask, else nil. Digits typed ("KLM12 to an A320") are read as written.
function G.create_digit_homophone(text)
  local toks, bare = plain_words(text)
  if not (bare[1] == "create" or bare[2] == "create" or bare[1] == "spawn") then return nil end
  for k = 2, #bare - 2 do
    local h = bare[k]
    if (h == "to" or h == "too" or h == "for" or h == "fore") and DIGIT_WORDS[bare[k - 1]]
        and not toks[k - 1]:match("%p$") and not toks[k]:match("%p$") and (bare[k + 1] == "a" or bare[k + 1] == "an") then
      return string.format("I heard '%s' after the callsign's digits: is it a digit of the callsign ('%s'), or no "
        .. "part of it? Please say the callsign again.", toks[k], lexicon.digit_homophones[h])
    end
  end
  return nil
end
-- "cleared direct to ack mill", "after oh pa mo descend", "move it to ah nee ro" (AKMIL, OPAMO, ANIRO on the route of
-- an aircraft flying): two or three short lower-case words a recogniser wrote for one fix name's syllables,
-- straight after a place's slot (PLACE_SLOTS, "to", "passing"), are joined into one word when that word is a
-- waypoint on one aircraft's route that no other waypoint of it sounds like (G.sure_route_name), that sounds as
-- closely like no waypoint of another route and names no navaid or airport (G.heard_nowhere_else), with the same
-- vowel sounds (G.vowel_skeleton: "toe bax" is no TOBIX). The joined word is then read as a name heard; words that
-- join into nothing so sure stay as said (asked).
-- The vowel sounds of a lower-case word in order, repeats run together: "ee", "ea", "ie" and "y" sound "i", "oo"
-- and "ou" "u", "oe", "oa" and "ow" "o", a closing "e" after a consonant is silent ("ah nee ro" and ANIRO: "aio";
-- "toe bax" "oa", TOBIX "oi").
G.vowel_spellings = { { "ee", "i" }, { "ea", "i" }, { "ie", "i" }, { "oo", "u" }, { "ou", "u" }, { "oe", "o" },
  { "oa", "o" }, { "ow", "o" }, { "y", "i" } }
function G.vowel_skeleton(w)
  w = w:gsub("([^aeiouy])e$", "%1")
  for _, v in ipairs(G.vowel_spellings) do w = w:gsub(v[1], v[2]) end
  return (w:gsub("[^aeiou]", ""):gsub("(%a)%1+", "%1"))
end
-- (words of a sentence's frame, never a syllable of a fix name: "add to the route of ...")
G.syllable_stops = set_of({ "the", "to", "a", "an", "of", "and", "then", "at", "for", "from", "with", "via", "it",
  "its", "route", "point", "waypoint", "fix", "over", "direct", "is", "in", "on", "by", "or", "vor", "ndb", "dme",
  "please", "now", "him", "her", "them", "this", "that" })
function G.syllable_route_places(text, world)
  local routes = {}
  for _, a in ipairs(world.aircraft or {}) do
    if a.route and #a.route > 0 then routes[#routes + 1] = a.route end
  end
  if #routes == 0 then return text end
  local toks, bare = plain_words(text)
  local function part(k)
    return toks[k] and toks[k]:match("^%l+%p?$") and #bare[k] <= 5 and #bare[k] >= 1
      and not G.syllable_stops[bare[k]]
  end
  local function sure_name(w)
    if #w < 4 or #w > 8 then return nil end
    local found
    for _, route in ipairs(routes) do
      local name = G.sure_route_name(w, route)
      if name then
        if found and found ~= name then return nil end
        found = name
      end
    end
    return found and G.heard_nowhere_else(w, found, world) and found or nil
  end
  return tokens.rewrite(text, toks, function(i)
    local slot = bare[i - 1]
    if not (slot and (PLACE_SLOTS[slot] or G.spelled_slots[slot]) and part(i)) or toks[i - 1]:match("%p$")
        or toks[i]:match("%p$") then
      return nil
    end
    for n = 3, 2, -1 do
      local k, ok = i + n - 1, true
      for j = i, k do ok = ok and part(j) and (j == k or not toks[j]:match("%p$")) end
      -- (the last syllable is no digit's word: "direct ack one" is a name and a number)
      if ok and not (DIGIT_WORDS[bare[k]] or NUMBER_WORDS[bare[k]]) then
        local w = table.concat(bare, "", i, k)
        local name = sure_name(w)
        if name and G.vowel_skeleton(w) == G.vowel_skeleton(name:lower()) then
          return w .. (toks[k]:match("%p+$") or ""), k + 1
        end
      end
    end
  end)
end
-- The words after which a waypoint of the aircraft's own route is named, a constraint's, a condition's or a limit's
-- place ("cross X at", "after X descend", "until X"), for G.heard_route_place and G.confirmed_route_places.
G.heard_slots = set_of({ "cross", "crossing", "after", "before", "until", "till", "at", "over", "passing", "via" })
-- the words of a request that adds a waypoint to a route, and the slots that then say where it goes
G.route_adding, G.route_position = set_of({ "add", "insert", "addwpt", "append" }), set_of({ "after", "before" })
-- The sound a lower-case word or ident begins with: its first letter, or the letter lexicon.first_sounds gives a
-- spelling of it ("cubs" and KUBBS both begin with "k", "phil" with "f").
function G.first_sound(w)
  for _, s in ipairs(lexicon.first_sounds) do
    if w:find(s[1]) then return s[2] end
  end
  return w:sub(1, 1)
end
-- The waypoint of `route` (idents) that the word w, said in such a slot, sounds like (the same first sound, and
-- squawk.translate.best_match at 0.5 or better, the level at which a direct-to's name is confirmed), or nil. A word
-- squawk knows (KNOWN) is none.
function G.heard_route_name(w, route)
  if #w < 3 or not w:match("^%a+$") or known_word(w) or #route == 0 then return nil end
  local idx, score = squawk.translate.best_match(w, route)
  local name = idx and score >= 0.5 and route[idx]
  return name and G.first_sound(name:lower()) == G.first_sound(w) and name or nil
end
-- The one waypoint of `route` (idents) that the word w sounds like as closely as a direct-to's name is taken
-- (squawk.translate.best_match at lexicon.waypoint_confirm: the same letters or the same sound key, "camron" for
-- CAMRN, "liffey" for LIFFY), when no other waypoint of it sounds like w at all (G.heard_route_name); nil
-- otherwise, and for w that is the ident itself.
function G.sure_route_name(w, route)
  local sure, alike = nil, 0
  for _, r in ipairs(route) do
    if G.heard_route_name(w, { r }) then
      alike = alike + 1
      local _, score = squawk.translate.best_match(w, { r })
      if score >= lexicon.waypoint_confirm and r:lower() ~= w then sure = r end
    end
  end
  return alike == 1 and sure or nil
end
-- True when the word w, heard in a place's slot for the waypoint `name` of the instructed aircraft's route (that
-- route's only one it sounds like, G.sure_route_name), sounds as closely (lexicon.waypoint_confirm, the same first
-- sound) like no other waypoint of any route flown and names no navaid or airport: "cross payton at FL180" for PAITN
-- with PLANO only loosely alike on another route. The request is then read as if the speaker had confirmed it.
function G.heard_nowhere_else(w, name, world)
  if not (world.navaids_named and world.airports_named) or #world.navaids_named(w, 0, 0, 1e5) > 0
      or #world.airports_named(w) > 0 then
    return false
  end
  for _, a in ipairs(world.aircraft) do
    for _, r in ipairs(a.route or {}) do
      if r:upper() ~= name and G.heard_route_name(w, { r }) then
        local _, score = squawk.translate.best_match(w, { r })
        if score >= lexicon.waypoint_confirm then return false end
      end
    end
  end
  return true
end
-- "direct test one", "add test 2 to the route": a waypoint the user defined (world.waypoints) whose name is letters
-- then digits (TEST1, WP12), said as its letters' word then each digit (as a word, SAID_DIGIT, or a numeral), is that
-- name; a digit more after them ("test one two" with TEST1 only) leaves the words as said. The letters may be spelled
-- in the phonetic alphabet, one word a letter ("direct tango one two", "papa three seven", "tango 12" for T12, P37),
-- for such a name the user defined or one on the route of an aircraft flying.
function G.spoken_user_waypoints(text, world)
  local spoken, spelled = {}, {}
  local function know(set, n)
    local letters, digits = n:match("^(%a+)(%d%d?%d?)$")
    if letters then
      local l = letters:lower()
      set[l] = set[l] or {}
      set[l][digits] = n:upper()
    end
  end
  for _, n in ipairs(world.waypoints or {}) do
    know(spoken, n)
    know(spelled, n)
  end
  for _, a in ipairs(world.aircraft or {}) do
    for _, n in ipairs(a.route or {}) do
      if #n <= 6 then know(spelled, n) end
    end
  end
  if not (next(spoken) or next(spelled)) then return text end
  local toks, bare = plain_words(text)
  local function digit(k) return bare[k] and (SAID_DIGIT[bare[k]] or bare[k]:match("^%d$")) end
  return tokens.rewrite(text, toks, function(i)
    local names, k = spoken[bare[i]], i + 1
    if not names and lexicon.phonetic[bare[i]] then
      -- (letters spelled: each word of the phonetic alphabet, no mark between)
      local letters = ""
      k = i
      while lexicon.phonetic[bare[k] or ""] and #letters < 3 and (k == i or not toks[k - 1]:match("%p$")) do
        letters, k = letters .. lexicon.phonetic[bare[k]]:lower(), k + 1
      end
      names = not lexicon.phonetic[bare[k] or ""] and spelled[letters]
      if names and toks[k - 1]:match("%p$") then return nil end
    elseif names and toks[i]:match("%p$") then
      return nil
    end
    if not names then return nil end
    local digits = ""
    -- (the digits typed as one numeral: "tango 12")
    if bare[k] and bare[k]:match("^%d%d%d?$") and names[bare[k]] and not digit(k + 1) then
      return names[bare[k]] .. (toks[k]:match("%p+$") or ""), k + 1
    end
    while digit(k) and #digits < 3 do
      digits, k = digits .. digit(k), k + 1
      if toks[k - 1]:match("%p$") then break end
    end
    if not names[digits] or (digit(k) and not toks[k - 1]:match("%p$")) then return nil end
    return names[digits] .. (toks[k - 1]:match("%p+$") or ""), k
  end)
end
-- The ident of the one navaid on the routes flown (`routed`: a set of upper-case idents) whose navdata name is the
-- word w ("until ockham" for OCK, "when you get to lambourne" for LAM), or nil: a name that gives no navaid of
-- those routes, or two, or an airport's or a city's name too ("to manchester": EGCC or MCT), stays as said (asked).
-- True when the word bare[i] (the plain words of a request) is in a slot where a navaid's name of the routes flown
-- is read (G.routed_navaid_name): after a limit's, a constraint's or a condition's word ("until ockham", "cross
-- ockham", "after ockham", "passes ockham"), a place reached ("reaching ockham", "when you get to ockham") or one a
-- direct-to skips ("skip ockham": G:skipped_on_direct asks about one it does not skip); "at" and a bare "to"
-- ("land at ezeiza", "inbound to boston") may name an airport: none.
G.navaid_slots = set_of({ "until", "till", "cross", "crossing", "after", "before", "over", "passing", "passes", "via",
  "reach", "reaches", "reaching", "skip", "skipping", "bypass", "bypassing", "omit", "omitting" })
G.navaid_reached = set_of({ "get", "gets", "getting", "got" })
function G.navaid_slot(bare, i)
  local w = bare[i - 1]
  if w == "to" then return G.navaid_reached[bare[i - 2] or ""] ~= nil end
  return w ~= nil and G.navaid_slots[w] ~= nil
end
function G.routed_navaid_name(w, routed, world)
  if not (world.navaids_named and world.airports_named and world.airports_of_city) or #w < 4 or not w:match("^%a+$")
      or known_word(w) or #world.airports_named(w) > 0 or #world.airports_of_city(w) > 0 then
    return nil
  end
  local found
  for _, id in ipairs(world.navaids_named(w, 0, 0, 1e5)) do
    local up = id:upper()
    if routed[up] then
      if found and found ~= up then return nil end
      found = up
    end
  end
  return found
end
-- "cross macy at FL240", "after camron descend ...", "until robber": a word straight after a place's slot
-- (G.heard_slots) that sounds like a waypoint the speaker confirmed (world.confirmed, the answer to
-- G:heard_route_place's question) on the route of an aircraft flying is that waypoint's ident; so is one that
-- sounds like exactly one waypoint of the routes flown, as closely as a direct-to's name is taken
-- (G.sure_route_name); others stay as said (and are confirmed).
function G.confirmed_route_places(text, world)
  local confirmed, routed, seen = {}, {}, {}
  for _, a in ipairs(world.aircraft) do
    for _, r in ipairs(a.route or {}) do
      if world.confirmed and (world.confirmed[r] or world.confirmed[r:upper()]) then confirmed[#confirmed + 1] = r:upper() end
      if not seen[r:upper()] then routed[#routed + 1], seen[r:upper()] = r:upper(), true end
    end
  end
  if #routed == 0 then return text end
  local toks, bare = plain_words(text)
  -- (in a request that adds to a route, "after"/"before" place the new waypoint: a name there is confirmed)
  local adding = false
  for _, w in ipairs(bare) do adding = adding or G.route_adding[w] ~= nil end
  return tokens.rewrite(text, toks, function(i)
    local slot = G.heard_slots[bare[i - 1]]
    if not (slot or G.navaid_slot(bare, i)) or toks[i - 1]:match("%p$") then return nil end
    local name = slot and #confirmed > 0 and G.heard_route_name(bare[i], confirmed)
    -- (a word written with a capital, or a navaid's or an airport's name anywhere, "at lille" for LIL, is a
    -- place's name, read as such)
    local sure = slot and not name and toks[i]:match("^%l") and world.navaids_named and world.airports_named
      and not (adding and G.route_position[bare[i - 1]]) and G.sure_route_name(bare[i], routed)
    if sure and #world.navaids_named(bare[i], 0, 0, 1e5) == 0 and #world.airports_named(bare[i]) == 0 then
      name = sure
    end
    name = name or (G.navaid_slot(bare, i) and toks[i]:match("^%l+%p*$") and G.routed_navaid_name(bare[i], seen, world))
    return name and name .. (toks[i]:match("%p+$") or ""), i + 1
  end)
end
-- "hop7 6000 hdg 220 230kt": in a terse typed list, an aircraft that flies then only values, each labelled
-- (lexicon.terse_list) but one, that one a bare number of four or five figures in hundreds of feet (1000 to
-- 60000), with no level, altitude word or transponder code said: that number is the level, written "6000ft".
-- Any other word, a second bare number, one straight after a rate's value ("vs 1500 9000") or none labelled leaves
-- the text as it is (the number is asked about).
G.terse_list = { labels = set_of(lexicon.terse_list.labels), units = set_of(lexicon.terse_list.units),
  level = set_of(lexicon.terse_list.level), joins = set_of(lexicon.terse_list.joins), rate = set_of(lexicon.terse_list.rate) }
-- "after reach 3000 meter, speed up", "after reach 260 then descend": "reach" straight after "after" is the verb
-- of reaching (the matcher reads it so after "when", "once" or a subject only), unless an aircraft of the
-- telephony Reach (RCH) flies: the text with "after reaching" in its place; else the text as said.
function G.after_reach(text, world)
  if not text:lower():find("after%s+reach%f[%A]") then return text end
  for _, a in ipairs(world.aircraft or {}) do
    if (a.id or ""):upper():match("^RCH") then return text end
  end
  return (text:gsub("(%f[%a][Aa][Ff][Tt][Ee][Rr]%s+)([Rr][Ee][Aa][Cc][Hh])(%f[%A])", "%1%2ing%3"))
end

-- "It is now 14:31:40: ...", "Now, at 14:02:10, ...", "We are at 10:04:20 now; ...", "At this point, 14:31:50, ...",
-- "This is 14:03, ...": a clock time told as the present moment of a report is no time to run anything at (no
-- SCHEDULE, no fast-forward): the phrase and the mark after it are dropped (after "at this point" only the time).
-- Each pattern of G.clock_now_patterns is tried on the lower-cased text (same lengths) and cut from the text.
do
  local CLOCK = "%d%d?:%d%d[:%d]*%s*[uU]?[tT]?[cC]?"
  G.clock_now_patterns = {
  "%f[%a]the time is now " .. CLOCK .. "%s*[,:;.%-]?%s*",
  "%f[%a]time is now " .. CLOCK .. "%s*[,:;.%-]?%s*",
  "%f[%a]it is now " .. CLOCK .. "%s*[,:;.%-]?%s*",
  "%f[%a]it's now " .. CLOCK .. "%s*[,:;.%-]?%s*",
  "%f[%a]now,? at " .. CLOCK .. "%s*[,:;%-]%s*",
  "%f[%a]we are at " .. CLOCK .. " now%s*[,:;.%-]?%s*",
  "%f[%a]we're at " .. CLOCK .. " now%s*[,:;.%-]?%s*",
  "%f[%a]this is " .. CLOCK .. "%s*[,:;%-]%s*",
  "%f[%a]at this point,? ()" .. CLOCK .. "%s*[,:;%-]%s*",
  }
end
-- "Sim time zero is 14:30:00 in the report. Step forward to 14:32:30.", "Start time 07:41:00; fast forward until
-- 07:43:30", "The reconstruction starts at 14:30:00 UTC as set up. Now let time run 90 seconds.": a clock time said
-- in a sentence (to ".", ";" or ":") with a word of G.clock_start_sets.starts and no word of
-- G.clock_start_sets.blocks tells the report's time at the simulation's start, no time to run anything at: that
-- sentence is dropped when another follows. A run to a later clock time after it ("to", "until" or "till" and
-- the time, after a word of G.clock_start_sets.runs) is a run for the difference [s] ("for N seconds"); only a
-- request that runs the simulation after it (a word of G.clock_start_sets.runs) is read so; an
-- earlier or equal time, or one of a different form (h:mm against h:mm:ss), leaves the text as said.
G.clock_start_sets = {
  starts = { "start", "starts", "started", "begins", "began", "zero", "reconstruct", "reconstruction", "from" },
  runs = { "run", "advance", "forward", "step", "skip", "go", "jump", "ff", "fast-forward" },
  blocks = { "climb", "descend", "turn", "heading", "speed", "direct", "create", "delete", "level", "fl", "knots",
    "kt", "ft", "feet", "mach", "hold", "pause", "schedule", "at0", "when", "if" },
}
function G.clock_start(text)
  if not text:find("%d:%d%d") then return text end
  local S, low = G.clock_start_sets, text:lower()
  local function has(list, b, e)
    local part = " " .. low:sub(b, e):gsub("[^%w:%-]", " ") .. " "
    for _, w in ipairs(list) do
      if part:find(" " .. w .. " ", 1, true) then return true end
    end
    return false
  end
  local function secs(t)
    local h, m, sec = t:match("^(%d%d?):(%d%d):(%d%d)$")
    if h then return tonumber(h) * 3600 + tonumber(m) * 60 + tonumber(sec), 3 end
    h, m = t:match("^(%d%d?):(%d%d)$")
    if h then return tonumber(h) * 3600 + tonumber(m) * 60, 2 end
    return nil
  end
  local tb, te = low:find("%f[%d]%d%d?:%d%d:?%d?%d?%f[%D]")
  local start, parts = secs(low:sub(tb, te))
  if not start then return text end
  -- (the sentence of the start time: from the mark before it to the mark after it)
  local sb = 1
  for k = tb - 1, 1, -1 do
    if low:sub(k, k):match("[%.;]") then sb = k + 1 break end
  end
  local se = low:find("[%.;:]%s", te + 1) or low:find("[%.;:]$", te + 1)
  if not se or se >= #low or not has(S.starts, sb, se) or has(S.blocks, sb, tb - 1) or has(S.blocks, te + 1, se) then
    return text
  end
  local rest, restlow = text:sub(se + 1), low:sub(se + 1)
  -- (only before a run of the simulation: "start at 10:00:00; climb KLM12 FL300" may time the climb, asked)
  if not has(S.runs, se + 1, #low) then return text end
  local rb, re, t2 = restlow:find("%f[%a][%a]+ (%d%d?:%d%d:?%d?%d?)%f[%D]")
  if rb then
    local word = restlow:sub(rb, re):match("^(%a+)")
    local to, n2 = secs(t2)
    if not (word == "to" or word == "until" or word == "till") or not has(S.runs, 1, rb - 1 + #low - #restlow) then
      return text
    end
    if not to or n2 ~= parts or to <= start then return text end
    rest = rest:sub(1, rb - 1) .. "for " .. (to - start) .. " seconds" .. rest:sub(re + 1)
  end
  return text:sub(1, sb - 1) .. rest:gsub("^%s+", "")
end

function G.clock_now(text)
  if not text:find("%d:%d%d") then return text end
  for _, pat in ipairs(G.clock_now_patterns) do
    local b, e, keep = text:lower():find(pat)
    if b then
      -- (the time is the last of the pattern: "at this point, " stays)
      if type(keep) == "number" then b = keep end
      text = text:sub(1, b - 1) .. text:sub(e + 1)
    end
  end
  return text
end

-- "after it will pass IBLAN", "when it will reach level 150", "when he will be above level 100" (the future tense
-- of Russian formal English in a condition): "will" between the aircraft's pronoun and a verb of passing, reaching
-- or being, after "when", "once", "after", "until" or "till", is dropped: the text as "after it pass IBLAN" reads.
-- The same future in Hungarian, Romanian and Ukrainian English: "when it will have 300 knots" reads as "when it has
-- 300 knots"; "when speed will be 250" as "when speed is 250" (the aircraft's speed reaching the value); "when it
-- will descend to FL250" / "will climb to" as "when it reaches FL250" (the level reached, no clearance to it).
-- "will" anywhere else is kept.
G.future_will_sets = { opens = set_of({ "when", "once", "after", "until", "till" }),
  subjects = set_of({ "it", "he", "she", "they" }),
  verbs = set_of({ "pass", "reach", "cross", "overfly", "be", "get", "descend", "climb", "slow", "leave", "have",
    "arrive" }),
  moving = set_of({ "descend", "climb" }) }
function G.future_will(text)
  if not text:lower():find("%f[%a]will%f[%A]") then return text end
  local F = G.future_will_sets
  text = text:gsub("(%f[%a]%a+)(%s+)(%a+)(%s+)[Ww][Ii][Ll][Ll]%s+(%a+)%s+[Tt][Oo]%f[%A]", function(c, s1, subj, s2, verb)
    if F.opens[c:lower()] and F.subjects[subj:lower()] and F.moving[verb:lower()] then
      return c .. s1 .. subj .. s2 .. "reaches"
    end
    return nil
  end)
  return (text:gsub("(%f[%a]%a+)(%s+)(%a+)(%s+)([Ww][Ii][Ll][Ll])%s+(%a+%f[%A])", function(c, s1, subj, s2, _, verb)
    local o, sb, v = c:lower(), subj:lower(), verb:lower()
    if F.opens[o] and sb == "speed" and v == "be" then return c .. s1 .. subj .. s2 .. "is" end
    if F.opens[o] and F.subjects[sb] and F.verbs[v] then
      return c .. s1 .. subj .. s2 .. (v == "have" and "has" or verb)
    end
    return nil
  end))
end

-- "when he passes 230", "once it reaches 150", "when he will pass 230" (the future dropped by G.future_will first):
-- the aircraft's pronoun and a verb of passing or reaching straight before a number, after "when", "once" or
-- "after", read as "when passing 230" / "when reaching 150" (the level condition said without its subject; the
-- condition's own checks then ask a level the aircraft will never pass).
G.pronoun_reached_sets = { opens = set_of({ "when", "once", "after" }), subjects = set_of({ "he", "it", "she" }),
  verbs = { pass = "passing", passes = "passing", reach = "reaching", reaches = "reaching" } }
function G.pronoun_reached(text)
  local P = G.pronoun_reached_sets
  -- ("when he reaches the 310": the level with an article, Italian "la 310", read as without it)
  text = text:gsub("(%f[%a]%a+)(%s+)(%a+)(%s+)(%a+)%s+[Tt][Hh][Ee](%s+%d)", function(c, s1, subj, s2, verb, rest)
    if P.opens[c:lower()] and P.subjects[subj:lower()] and P.verbs[verb:lower()] then
      return c .. s1 .. subj .. s2 .. verb .. rest
    end
    return nil
  end)
  return (text:gsub("(%f[%a]%a+)(%s+)(%a+)%s+(%a+)(%s+%d)", function(c, s1, subj, verb, rest)
    local v = P.verbs[verb:lower()]
    if P.opens[c:lower()] and P.subjects[subj:lower()] and v then return c .. s1 .. v .. rest end
    return nil
  end))
end

function G.terse_altitude(text, world)
  if not text:find("%d%d%d%d") then return text end
  -- (the first word names an aircraft flying)
  local first, flying = text:match("[^%s,]+"):lower(), false
  for _, a in ipairs(world.aircraft) do flying = flying or (a.id or ""):lower() == first end
  if not flying then return text end
  local L, toks = G.terse_list, {}
  for w in text:gmatch("[^%s,]+") do toks[#toks + 1] = w:lower() end
  local bare, labelled, k = nil, 0, 2
  while k <= #toks do
    local w = toks[k]
    local letters, figures, unit = w:match("^(%a*)(%-?%d+%.?%d*)(%a*)$")
    if L.level[w] or (letters and (L.level[letters] or L.level[unit])) then return text end
    if letters and (L.labels[letters] or L.units[unit]) and (letters == "" or unit == "") then
      labelled = labelled + 1
    elseif letters == "" and unit == "" then
      if L.units[toks[k + 1] or ""] or L.labels[toks[k - 1]] then
        labelled = labelled + 1
      elseif bare or not figures:match("^%d%d%d%d%d?$") or tonumber(figures) % 100 ~= 0
          or tonumber(figures) < 1000 or tonumber(figures) > 60000 or L.rate[toks[k - 1]]
          or (toks[k - 1]:match("%d") and (L.rate[toks[k - 2] or ""] or toks[k - 1]:match("fpm$"))) then
        return text
      else
        bare = figures
      end
    elseif not (L.labels[w] or L.units[w] or L.joins[w]) then
      return text
    end
    k = k + 1
  end
  if not bare or labelled == 0 then return text end
  return (text:gsub("%f[%w]" .. bare .. "%f[%W]", bare .. "ft", 1))
end
-- A navaid said by its name of two or three words with its kind after it ("direct las vegas vortac"), one of the
-- words itself the name of another point (the fix VEGAS): the words, when nav.dat names exactly one navaid of that
-- kind (lexicon.navaid_types) so within lexicon.navaid_range_nm of the traffic (of any aircraft; anywhere when none
-- flies), become its ident, the kind kept after it, so that point is never read instead; a name of several navaids
-- or none, and a name with no word that is a point's (read where it is said: "cross the Phoenix VOR at"), stay as
-- said.
function G.navaids_by_kind(text, world)
  local named, locate = world.navaids_named, world.user_waypoint_at
  if not (named and locate) then return text end
  local lower = text:lower()
  if not (lower:find("vor", 1, true) or lower:find("ndb", 1, true) or lower:find("dme", 1, true)) then return text end
  local toks = {}
  for w in text:gmatch("%S+") do toks[#toks + 1] = w end
  local function found(name, kind)
    local seen, n, only = {}, 0, nil
    local places = #world.aircraft > 0 and world.aircraft or { { lat = 0, lon = 0 } }
    local range = #world.aircraft > 0 and lexicon.navaid_range_nm or 1e5
    for _, a in ipairs(places) do
      for _, id in ipairs(a.lat and named(name, a.lat, a.lon, range, kind) or {}) do
        if not seen[id] then seen[id], n, only = true, n + 1, id end
      end
    end
    return n == 1 and only or nil
  end
  return tokens.rewrite(text, toks, function(i)
    for n = 3, 2, -1 do
      local kw = toks[i + n] and toks[i + n]:lower():match("^(%a+)%p*$")
      local kind = kw and lexicon.navaid_types[kw]
      if kind then
        local words, ok, point = {}, true, false
        for k = i, i + n - 1 do
          ok = ok and toks[k]:match("^%a[%a%-']*$") ~= nil
          point = point or (#toks[k] >= 3 and locate(toks[k]:upper()) ~= nil)
          words[#words + 1] = toks[k]
        end
        local id = ok and point and found(table.concat(words, " "), kind)
        if id then return id:upper(), i + n end
      end
    end
  end)
end

-- A place said by its name with its ident in apposition ("add Thermal, that is TRM, to the route", "passes the
-- Homeland VOR, HDF, ...", "direct to Truth or Consequences, TCS", "Palm Springs International (KPSP)"): one to
-- four capitalised words (lexicon.place_name_joiners between them, "the" before and a word of navaid_kinds or
-- airport_nouns after them), then a comma or a dash standing alone (a bracket, as written_forms writes it), a
-- phrase of lexicon.apposition or none, and an ident of three to five capitals (two, "CB", stay as said:
-- G:explained_spans reads the name beside them). Where the navdata gives that ident that name (a navaid's or an
-- airport's name, words of it or its city; or an airport of the name whose ICAO code is the three-letter navaid's
-- after one letter, as airports_coded reads it: KTCS for TCS), the text keeps the ident alone, as if typed; any
-- other name stays as said (asked about).
function G.named_idents(text, world)
  if not (world.navaids_named and world.airports_named and world.airports_of_city and world.airports_with_words)
      or not (text:find("[,(]") and text:find("%u%u")) then
    return text
  end
  local function names_ident(name, code)
    local function by_name(list)
      for _, id in ipairs(list) do
        local up = id:upper()
        if up == code then return true end
        if #code == 3 and #up == 4 and up:sub(2) == code and world.airports_coded and world.user_waypoint_at then
          local lat, lon = world.user_waypoint_at(up)
          for _, a in ipairs(lat and world.airports_coded(code, lat, lon) or {}) do
            if a:upper() == up then return true end
          end
        end
      end
      return false
    end
    return by_name(world.navaids_named(name, 0, 0, 1e5)) or by_name(world.airports_named(name))
      or by_name(world.airports_of_city(lexicon.city_airports[name] or name))
      or by_name(world.airports_with_words(name))
  end
  local function place_kind(w)
    local lw = w:lower():match("^(%a+)")
    return lw and (set_of(lexicon.navaid_kinds)[lw] or set_of(lexicon.airport_nouns)[lw]) or false
  end
  local joiners, apposition = set_of(lexicon.place_name_joiners), lexicon.apposition
  local cuts = {}  -- {from, to}: text[from, to) is dropped
  for at, opener, after in text:gmatch("()([,%-])()") do
    local k = after + #text:match("^%s*", after)
    for _, phrase in ipairs(apposition) do
      local low = text:sub(k, k + #phrase):lower()
      if low == phrase .. " " then
        k = k + #phrase + #text:match("^%s*", k + #phrase)
        break
      end
    end
    local code, ce = text:match("^(%u%u%u%u?%u?)()", k)
    -- (a dash standing alone: a bracket as written_forms writes it, "Thermal (TRM)" -> "Thermal - TRM,")
    if opener == "-" and not (text:sub(at - 1, at - 1) == " " and k > after) then code = nil end
    if code and not text:sub(ce, ce):match("[%w]") then
      -- the words before the opener, last first: a kind of place, the name's words, "the"
      local words = {}
      for b, w in text:sub(1, at - 1):gmatch("()(%S+)") do words[#words + 1] = { b = b, w = w } end
      local n = #words
      if n > 0 and place_kind(words[n].w) then n = n - 1 end
      local first = n
      while first >= 1 and n - first < 4 and words[first].w:match("^[%a%-']+$")
          and (words[first].w:match("^%u") or (joiners[words[first].w] and first < n)) do
        first = first - 1
      end
      for f = first + 1, n do
        if words[f].w:match("^%u") then
          local parts = {}
          for x = f, n do parts[#parts + 1] = words[x].w:lower() end
          if names_ident(table.concat(parts, " "), code) then
            local from = (f > 1 and words[f - 1].w:lower() == "the") and words[f - 1].b or words[f].b
            cuts[#cuts + 1] = { from, k }
            break
          end
        end
      end
    end
  end
  for c = #cuts, 1, -1 do text = text:sub(1, cuts[c][1] - 1) .. text:sub(cuts[c][2]) end
  return text
end
local function typed_places(text, world)
  if not world.place_known then return text end
  local ids = {}
  for _, a in ipairs(world.aircraft) do ids[(a.id or ""):lower()] = true end
  local function near(w)
    local lat, lon = world.place_known(w:upper())
    if not lat then return false end
    for _, a in ipairs(world.aircraft) do
      local dlat, dlon = lat - (a.lat or 0), (lon - (a.lon or 0)) * math.cos(math.rad(lat))
      if a.lat and 60 * math.sqrt(dlat * dlat + dlon * dlon) <= TYPED_PLACE_NM then return true end
    end
    return #world.aircraft == 0
  end
  -- ("where is the hlz vor": an ident of two to five letters in lower case straight before a kind of navaid,
  -- lexicon.navaid_types, of a place near the traffic, is that place)
  local lower = text:lower()
  if lower:find("vor", 1, true) or lower:find("ndb", 1, true) or lower:find("dme", 1, true) then
    local out, from, prev = {}, 1, nil  -- (prev: the word before, {b, e, text})
    for b, w, e in text:gmatch("()(%a+)()") do
      if prev and lexicon.navaid_types[w:lower()] and text:sub(prev[2], b - 1):match("^%s+$")
          and prev[3]:match("^%l%l%l?%l?%l?$") and not known_word(prev[3]) and not ids[prev[3]]
          and not lexicon.shorthand[prev[3]] and near(prev[3]) then
        out[#out + 1] = text:sub(from, prev[1] - 1) .. prev[3]:upper()
        from = prev[2]
      end
      prev = { b, e, w }
    end
    text = table.concat(out) .. text:sub(from)
  end
  -- (a name is read only after a word of PLACE_SLOTS: with none said, the words stand as they are)
  local padded = " " .. text:lower() .. " "
  local slots = padded:find(" where", 1, true) ~= nil
  for k = 1, #PLACE_SLOT_PATTERNS do
    local p = PLACE_SLOT_PATTERNS[k]
    if padded:find(p.word, 1, true) and padded:find(p.pattern) then
      slots = true
      break
    end
  end
  if not slots then
    -- (the words as the loop below joins them: the text less its trailing white space, %s)
    local e = #text
    while e > 0 and (text:byte(e) == 32 or (text:byte(e) >= 9 and text:byte(e) <= 13)) do e = e - 1 end
    return text:sub(1, e)
  end
  local capitals = text:find("%u") ~= nil
  local routed = {}
  for _, a in ipairs(world.aircraft) do
    for _, r in ipairs(a.route or {}) do routed[r:lower()] = true end
  end
  local parts = {}
  for lead, word in text:gmatch("(%s*)([^%s]+)") do parts[#parts + 1] = { lead, word } end
  local out, slot, k, proper = {}, false, 1, false
  while k <= #parts do
    local lead, word = parts[k][1], parts[k][2]
    local raw, rest = word:match("^(%a[%a%d]*)(.*)$")
    local w = raw and raw:lower()
    -- (a three-letter ident ending in "s" that squawk knows only as an inflection, "from dus" as "due"'s, is no
    -- known word)
    local named = w and slot and #w >= 3 and #w <= 5 and (not capitals or raw:match("^%u%l+$"))
      and (not known_word(w) or (not KNOWN[w] and ((#w == 3 and w:sub(3) == "s") or G.place_verbs[(out[#out] or ""):lower():match("(%a+)$") or ""])))
      and not ids[w] and not lexicon.shorthand[w] and near(w)
    k = k + 1
    -- ("cross e c k at FL190", "at j v l descend ...": an ident spelled letter by letter, the whole run of
    -- two to five single letters, on an aircraft's route or, of three letters or more, near the traffic)
    if w and slot and #w == 1 and rest == "" and parts[k] and parts[k][2]:match("^%a%p*$") then
      local j, joined, punct = k, w, ""
      while parts[j] and #joined < 6 and punct == "" do
        local x, p = parts[j][2]:match("^(%a)(%p*)$")
        if not x then break end
        joined, punct, j = joined .. x:lower(), p, j + 1
      end
      if #joined <= 5 and not (parts[j] and parts[j][2]:match("^%a%p*$")) and not ids[joined]
          and (routed[joined] or (#joined >= 3 and near(joined))) then
        named, w, rest, k = true, joined, punct, j
      end
    end
    if w and not capitals and w:match("^%a+$") and slot and not named and rest == "" and not PLACE_SLOTS[w]
        and w ~= "to" and not routed[w] then
      local joined = w
      for j = k, math.min(k + 1, #parts) do
        local x, punct = parts[j][2]:match("^(%a+)(%p*)$")
        if not x or #joined + #x > 5 then break end
        joined = joined .. x
        if #joined >= 4 and not ids[joined] and (routed[joined] or (not known_word(joined) and near(joined))) then
          named, w, rest, k = true, joined, punct, j + 1
          break
        end
        if punct ~= "" then break end
      end
    end
    out[#out + 1] = lead .. (named and (w:upper() .. rest) or word)
    -- (a list goes on after a name read so: "add willo then timba"; or, in a line with capitals, at "and" or
    -- "then" after a proper name in the slot that is no such place, a navaid's or airport's name: "Add Talla and
    -- Sumin to ...")
    local listed = proper
    proper = slot and capitals and not named and raw ~= nil and raw:match("^%u%l+$") ~= nil and rest == ""
      and not known_word(w)
    slot = (named and rest == "") or ((slot or listed) and (w == "then" or w == "and") and rest == "")
      or (slot and rest == "" and (lexicon.place_nouns[w] ~= nil
        or (w == "the" and parts[k] ~= nil and lexicon.place_nouns[parts[k][2]:lower()] ~= nil)))
      or (w == "where" and (rest == "'s" or (rest == "" and parts[k] and parts[k][2]:lower() == "is")))
      or (w == "is" and slot and (out[#out - 1] or ""):lower():match("where$") ~= nil)
      or (w ~= nil and rest == "" and (PLACE_SLOTS[w] ~= nil
      or (w == "to" and slot and PLACE_SLOTS[(out[#out - 1] and out[#out - 1]:match("(%a+)$") or ""):lower()] ~= nil)))
  end
  return table.concat(out)
end

-- "tell me, on which flight level the A320 is": a comma between one of lexicon.clause_comma_verbs (with "me" or
-- "us" after it, or alone) and one of lexicon.clause_comma_openers (or a preposition and "which") is dropped; the
-- clause it opens is the verb's question, as written with no comma
function G.clause_commas(text)
  return (text:gsub("(%f[%a](%a+)%s*(%a*)),(%s+)(%a+)(%s*)(%a*)", function(said, verb, obj, space, w1, s2, w2)
    local v, o = verb:lower(), obj:lower()
    local told = lexicon.clause_comma_verbs[o] and "" or (o == "me" or o == "us") and lexicon.clause_comma_verbs[v]
    if not told then return nil end
    local a, b = w1:lower(), w2:lower()
    if lexicon.clause_comma_openers[a] or (b == "which" and lexicon.clause_comma_prepositions[a]) then
      return said .. space .. w1 .. s2 .. w2
    end
    return nil
  end))
end
G.state_after_s = set_of(lexicon.state_after_s)
local DESCRIBED_AFTER = { there = true, here = true, already = true, still = true, at = true, currently = true,
  maintaining = true, cruising = true, established = true }
-- A homework answer's label opening the text ("Q3a answer:", "Question 2:", "Answer:"): no instruction
local ANSWER_LABELS = { "^%s*[Qq]%d%d?%a?%)?%s*[Aa]nswer%s*[:.%-]%s*", "^%s*[Qq]uestion%s*%d%d?%a?%)?%s*[:.%-]%s*",
  "^%s*[Aa]nswer%s*[:.%-]%s+", "^%s*[Qq]%d%d?%a?[:)]%s+" }
-- A step's marker ("Step 1:", "step two", "1.", "2)", "3:", "4 -", "(5)"), its number captured; a letter
-- follows it
local STEP_MARKERS = { "^[Ss]tep%s*(%w+)%s*[:.),%-]?%s+", "^(%d%d?)[.):]%s+", "^(%d%d?)%s+%-%s+", "^%((%d%d?)%)%s+" }
local STEP_WORDS = { one = 1, two = 2, three = 3, four = 4, five = 5, six = 6, seven = 7, eight = 8, nine = 9 }
local function step_marker(text, at)
  for _, p in ipairs(STEP_MARKERS) do
    local _, e, n = text:find(p, at)
    -- ("Step 1b:", "Step 6a:": a step's part, lettered, is that step)
    n = n and (tonumber(n) or STEP_WORDS[n:lower()] or tonumber(n:match("^(%d%d?)%l$")))
    if n and text:find("^%a", e + 1) then return n, e end
  end
end
-- "1. descend TRA345 to FL150 2. reduce speed to 240 knots", "Step 1: ... Step 2: ...", "1) ... 2) ...":
-- numbered steps are structure, each step a sentence of its own. The markers count from 1, in order, the
-- first opening the text (after an answer's label); a number that breaks the count is a value and stays.
local function numbered_steps(text)
  for _, p in ipairs(ANSWER_LABELS) do
    local _, e = text:find(p)
    if e and text:find("^%a", e + 1) then
      text = text:sub(e + 1)
      break
    end
  end
  local first = text:find("%S")
  local n, e = step_marker(text, first or 1)
  -- ("Good morning. For the first run please: 1) switch on ..., 2) ...", "Experiment B, Basel: 1. ... 2. ...",
  -- "Run 2 of the Alpine series. (1) ...; (2) ...": a list counted from 1 after a label or a remark ending in a
  -- colon or full stop; the words before it stay a sentence of their own, read as they are)
  local lead = ""
  if not n then
    n = G.list_after_lead(text)
    if not n then return text end
    lead, text = text:sub(1, n - 1):gsub("[%s:;]+$", ""), text:sub(n)
    lead = lead:find("[.!?]$") and lead .. " " or lead .. ". "
    first = 1
    n, e = step_marker(text, 1)
  end
  -- (a protocol's step named by the word, "Step 7: ...", "step 4 - ...", "Step 6a: ...", or a punctuated number
  -- before an instruction, "7: set ...", may open the text at any number: the label is set apart whole and the
  -- count goes on from it; otherwise a number other than 1 is a value)
  local label = text:sub(first, e)
  local punctuated = label:find("[:.)%-]") ~= nil
  local worded = label:find("^[Ss]tep") ~= nil
  local rest = text:sub(e + 1)
  -- (a label with no punctuation is one when an instruction follows it: "Step 7 set time multiplier to 4"; a
  -- time unit after the number is a time step, "step 5 seconds")
  local labelled = (worded or punctuated) and (punctuated and (worded or M.has_instruction(rest))
    or (not lexicon.step_units[rest:match("^%a+"):lower()] and M.has_instruction(rest)))
  if n ~= 1 and not labelled then return text end
  local parts, from, want = {}, e + 1, n + 1
  local at = from
  while true do
    local b = text:find("[%s,;]%S", at)
    if not b then break end
    local m, me = step_marker(text, b + 1)
    if m == want then
      parts[#parts + 1] = (text:sub(from, b):gsub("[%s%.,;]+$", ""))
      from, want = me + 1, want + 1
    end
    at = b + 1
  end
  -- (one step alone marked with no punctuation, "step 1 second", is no list: the words stay)
  if #parts == 0 and not punctuated and not labelled then return text end
  parts[#parts + 1] = text:sub(from)
  return lead .. table.concat(parts, ". ")
end
-- The position of a list's first marker ("1)", "(1)", "1.", "Step 1:", "step one,") after words that end in a
-- colon, full stop or semicolon, when the marker of step 2 follows it; nil when there is none.
function G.list_after_lead(text)
  local at = 1
  while true do
    local b = text:find("[:.;]%s+%S", at)
    if not b then return nil end
    local m0 = text:find("%S", b + 1)
    local n, e = step_marker(text, m0)
    if n == 1 then
      local x = e + 1
      while true do
        local c = text:find("[%s,;]%S", x)
        if not c then break end
        if step_marker(text, c + 1) == 2 then return m0 end
        x = c + 1
      end
    end
    at = b + 1
  end
end
-- The translation of a clearance quoted whole in double quotes that the words outside name to be given again
-- (lexicon.quoted_clearance), else nil. Outside, the words hold no value or word in capitals but a callsign (an
-- aircraft of `fleet`) or a time of day h:mm:ss: the quoted clearance is read alone, for the aircraft named outside
-- when it asks for one; an outside aircraft other than the one the quote instructs is asked about.
M.quoted_words = { frames = set_of(lexicon.quoted_clearance.frames),
  not_frames = set_of(lexicon.quoted_clearance.not_frames) }
function M.quoted_clearance(text, world)
  if not text:find('["\226\128\156]') then return nil end  -- (no byte that may open a quote, as the pattern below requires)
  local pre, quoted, post = text:match('^([^"\226]*)["\226\128\156]+([^"\226]+)["\226\128\157]+([^"\226]*)$')
  if not quoted or not quoted:find("%a") then return nil end
  local outside = pre .. " " .. post
  local framed, rest = false, {}
  for w in outside:lower():gmatch("[%a']+") do
    if M.quoted_words.not_frames[w] then return nil end
    framed = framed or M.quoted_words.frames[w] == true
    if not M.quoted_words.frames[w] then rest[#rest + 1] = w end
  end
  -- (an instruction word outside, "... replay it and pause the simulation", is a request of its own: read whole)
  if not framed or M.has_instruction(table.concat(rest, " ")) then return nil end
  local fleet = world.aircraft
  outside = airline_values(named_airline_ids(split_ids(unglued_ids(G.iata_ids(outside, fleet), fleet), fleet)), fleet)
  outside = outside:gsub("%f[%d:]%d%d?:[0-5]%d:[0-5]%d%f[^%d:]", " ")
  -- (an aircraft named outside: an id of the fleet, or a word with a digit after one to three capitalised words,
  -- "Air Europa 5507"; any other word with a digit is a value)
  local named, words = nil, {}
  for w in outside:gmatch("%S+") do words[#words + 1] = w:gsub("['\226\128\153]s$", ""):gsub("%p+$", "") end
  for i, w in ipairs(words) do
    -- (a word in capitals that is no aircraft of the fleet, "over GIROM", names a place: read whole)
    local caps = w:match("^%u%u+$") ~= nil
    if w:find("%d") or caps then
      local b = i
      local known = false
      for _, a in ipairs(fleet) do known = known or a.id:upper() == w:upper() end
      while not known and not caps and b > 1 and i - b < 3 and words[b - 1]:match("^%u%a+$") do b = b - 1 end
      if named or (b == i and not known) then return nil end
      named = table.concat(words, " ", b, i)
    end
  end
  local r = M.translate(quoted, world)
  if not named then return r end
  local r2 = M.translate(named .. ", " .. quoted, world)
  if #(r.commands or {}) == 0 then return r2 end
  if table.concat(r.commands, ";") ~= table.concat(r2.commands or {}, ";") then
    return { commands = {}, ask = string.format("The quoted clearance is '%s', but '%s' is named outside it. Which "
      .. "aircraft do you mean?", quoted, named) }
  end
  return r
end

-- "exp1: hop7 vs -800", "run3: x4 and op", "t2: ...": an experiment's id (one to five letters, then one to three
-- figures, perhaps a letter) before a colon opening the line, a word after it, is a label set apart, when its
-- letters name no value (lexicon.value_names, shorthand: "fl200:") and are not the letters an id of an aircraft
-- that flies opens with ("klm3:" with KLM33 flying is a callsign typed short, and stays), and either are an
-- experiment's (lexicon.id_labels, lexicon.aside.study_labels) or come before an aircraft that flies
-- ("AC02: heading 180" with no AC02 flying stays the addressee)
G.id_labels = set_of(lexicon.id_labels)
function G.id_label(text, world)
  if not text:find(":", 1, true) then return text end
  local letters, figures, rest = text:match("^%s*(%a%a?%a?%a?%a?)(%d%d?%d?%a?)%s*:%s*(%a.*)$")
  if not letters then return text end
  letters = letters:lower()
  if G.value_name_set[letters] or lexicon.shorthand[letters] or G.terse_list.labels[letters] then return text end
  local first, before = (rest:match("^([%w]+)") or ""):lower(), false
  for _, a in ipairs(world.aircraft) do
    local id = (a.id or ""):lower()
    if (id:match("^%a+") or "") == letters then return text end
    before = before or id == first
  end
  return (G.id_labels[letters] or CM_STUDY[letters] or before) and rest or text
end

-- "after passing fifty-six north twenty west climb FL410", "maintain Mach .84 until 40 north 60 west": a latitude
-- and a longitude in whole degrees said straight after one another (a comma between or none), for an aircraft
-- named in the request whose route holds the one named point the navdata has at exactly that position (the NAT
-- points "56N20", "40N60"), are that point: the text is returned with the position's words replaced by its name,
-- so that every instruction reading a waypoint ("at", "after", "until", "cross ... at", "to be level by") reads
-- it. A request with a word of an instruction that takes a position (create, move, define or add a waypoint, a
-- wind) keeps the position as said, as does one whose degrees have a fraction or whose point no route of an
-- aircraft named holds. `u` is the utterance of `text`, `toks` its u:tokens() (read, never changed); nil when
-- nothing was replaced.
G.position_args = { lat = true, lon = true }
function G.route_points_said(text, u, world, toks)
  if not world.waypoints_at then return nil end
  local qs = u:quantities(1, #toks + 1)
  local lat
  for _, q in ipairs(qs) do lat = lat or (q.kind == "lat" and q) end
  if not lat then return nil end
  local held = {}  -- (upper-case name -> the name as its route holds it)
  for _, r in ipairs(u:refs()) do
    for _, a in ipairs(r.kind == "aircraft" and r.exists and world.aircraft or {}) do
      if (a.id or ""):upper() == r.name:upper() then
        for _, w in ipairs(a.route or {}) do held[w:upper()] = w end
      end
    end
  end
  if not next(held) then return nil end
  for _, t in ipairs(toks) do
    for _, r in ipairs(t.kind == "word" and RULES_BY_WORD[t.text] or {}) do
      for _, arg in ipairs(not r.any and r.intent and M.intents[r.intent].args or {}) do
        if G.position_args[arg] then return nil end
      end
    end
  end
  local spans = {}  -- ({b, e, name}: tokens [b, e) said for the point `name`)
  for k, q in ipairs(qs) do
    local lon = qs[k + 1]
    if q.kind == "lat" and lon and lon.kind == "lon" and q.value % 1 == 0 and lon.value % 1 == 0
        and (lon.b == q.e or (lon.b == q.e + 1 and toks[q.e].text == ",")) then
      local found = {}
      for _, id in ipairs(world.waypoints_at(q.value, lon.value)) do
        if held[id:upper()] then found[#found + 1] = held[id:upper()] end
      end
      if #found == 1 then spans[#spans + 1] = { b = q.b, e = lon.e, name = found[1] } end
    end
  end
  if #spans == 0 then return nil end
  -- (each token's bytes, found in order in the text, case aside; a token not found leaves the text as it is)
  local lower, at, starts, ends = text:lower(), 1, {}, {}
  for k = 1, spans[#spans].e - 1 do
    local b, e = lower:find(toks[k].raw:lower(), at, true)
    if not b then return nil end
    starts[k], ends[k], at = b, e, e + 1
  end
  local put, done = tokens.splicer(text)
  for _, sp in ipairs(spans) do put(starts[sp.b], sp.name, ends[sp.e - 1] + 1) end
  return done()
end

-- A number said in words joined by hyphens ("four-fifty-one", "three-oh-five", "thirty-three-oh-two",
-- "one-double-zero", "six-o-seven"): a word whose every hyphen-separated part is a number word (NUMBER_WORDS,
-- lexicon.hyphen_number_parts) is those words apart ("oh"/"o" after the first part a zero), read as the same words said with spaces, so that the
-- passes over the text before the lexer (self-corrections "... sorry, three-one-zero knots") read its number
-- words (the lexer splits such a word alike: number_words.cpp fold_digit_homophones). A word with any other
-- part ("nine-year", "one-way", "737-800") stays as written.
function G.number_words_apart(text)
  if not text:find("%a%-%a") then return text end
  return (text:gsub("%f[%w][%a%-]+%f[^%w%-]", function(w)
    if not w:find("-", 1, true) then return nil end
    for part in (w .. "-"):gmatch("([^-]*)%-") do
      local p = part:lower()
      if not (NUMBER_WORDS[p] or lexicon.hyphen_number_parts[p]) then return nil end
    end
    -- (an "oh"/"o" after the first part, closing included, is a zero: "two-two-oh" = 220)
    return (w:gsub("%-[Oo][Hh]?%f[^%a]", " zero"):gsub("%-", " "))
  end))
end
-- "five three three zero north zero zero three four five west": a position said digit by digit as degrees and
-- minutes, the latitude four digits (DDMM) before "north"/"south" and the longitude five (DDDMM) before "east"/
-- "west", the two together (a comma or "and" between at most), minutes below 60, degrees in range: written as typed,
-- "5330N 00345W" (read as degrees and minutes). Any other count of digits stays as said (asked).
G.spoken_ddmm_digits = { zero = "0", one = "1", two = "2", three = "3", four = "4", five = "5", six = "6", seven = "7",
  eight = "8", nine = "9", niner = "9", tree = "3", fife = "5", fower = "4" }
function G.spoken_ddmm(text)
  local low = text:lower()
  if not ((low:find("north", 1, true) or low:find("south", 1, true))
      and (low:find("east", 1, true) or low:find("west", 1, true))) then
    return text
  end
  local D = G.spoken_ddmm_digits
  local words = {}
  for b, w, e in text:gmatch("()(%S+)()") do words[#words + 1] = { b = b, e = e, w = w:lower():gsub("[,;]$", "") } end
  -- (the digits said from word k before a hemisphere word of `hs`: the digits and the word after the hemisphere)
  local function run(k, n, hs)
    local ds = ""
    for j = k, k + n - 1 do
      local d = words[j] and D[words[j].w]
      if not d then return nil end
      ds = ds .. d
    end
    local h = words[k + n]
    if not (h and hs[h.w]) or (words[k - 1] and D[words[k - 1].w]) then return nil end
    return ds, h.w, k + n + 1
  end
  local LAT, LON = { north = "N", south = "S" }, { east = "E", west = "W" }
  for k = 1, #words do
    local la, lh, nx = run(k, 4, LAT)
    if la then
      if words[nx] and words[nx].w == "and" then nx = nx + 1 end
      local lo, oh, after = run(nx, 5, LON)
      local lad, lam = tonumber(la:sub(1, 2)), tonumber(la:sub(3, 4))
      local lod, lom = lo and tonumber(lo:sub(1, 3)), lo and tonumber(lo:sub(4, 5))
      if lo and lam < 60 and lom < 60 and lad <= 90 and lod <= 180 then
        local e = words[after - 1].e
        -- (a comma closing the longitude's hemisphere stays)
        local tail = text:sub(words[after - 1].b, e - 1):match("[,;]$") or ""
        return text:sub(1, words[k].b - 1) .. la .. LAT[lh] .. " " .. lo .. LON[oh] .. tail .. G.spoken_ddmm(text:sub(e))
      end
    end
  end
  return text
end
-- A zero said "oh" or "o" inside a number ("heading three oh five", "JetBlue six o seven", "double oh seven"):
-- after a digit word or a number word below a hundred (or "double"/"triple") and before a digit word, with no mark between,
-- it is "zero" (the lexer would read "oh" as a hesitation and drop a lone "o" as a stray letter: "three oh
-- five" read 35). "oh" closing a number ("two two oh") and one after a mark ("two, oh, three") stay.
function G.spoken_zeros(text)
  local low = text:lower()
  if not (low:find(" oh ", 1, true) or low:find(" o ", 1, true)) then return text end
  local toks, bare = plain_words(text)
  local out
  for i = 2, #toks - 1 do
    local before = bare[i - 1]
    if (bare[i] == "oh" or bare[i] == "o") and toks[i] == toks[i]:match("^%a+") and not toks[i - 1]:match("%p$")
        and (DIGIT_WORDS[before] or G.below_hundred[before] or before == "double" or before == "triple")
        and DIGIT_WORDS[bare[i + 1]] then
      out = out or table.move(toks, 1, #toks, 1, {})
      out[i] = "zero"
    end
  end
  return out and table.concat(out, " ") or text
end

-- "then FF 10 min and HOLD", "fast-forward 8 minutes, then hold", "run 15 minutes and hold": a hold joined by
-- "and"/"then" to a fast-forward's time (FF, fast-forward, fast forward, fast-time; the time with its unit) is
-- the simulation's pause after it, said as "pause"; any other "hold" stays as said.
function G.hold_after_ff(text)
  if not text:find("[Hh][Oo][Ll][Dd]") then return text end
  return (text:gsub("()(%d+%.?%d*%s*%a+)(%s*,?%s+)(%a+)(%s+)([Hh][Oo][Ll][Dd])(%f[%A])",
    function(at, time, sep, join, sp, hold, tail)
      local j = join:lower()
      local unit = time:lower():match("%a+$")
      if not (j == "and" or j == "then") or not G.time_units[unit] then return nil end
      local before = text:sub(math.max(1, at - 40), at - 1):lower()
      local clause = (before:match("[^.;,]*$") or before):gsub("%f[%a]for%s*$", "")
      if not (clause:find("%f[%a]ff%s*$") or clause:find("forward%s*$") or clause:find("fast%-time%s*$")
          or clause:find("fast time%s*$") or clause:find("%f[%a]run%s*$")) then
        return nil
      end
      return time .. sep .. join .. sp .. (hold == "HOLD" and "PAUSE" or "pause") .. tail
    end))
end
-- A title opening a script, its own sentence ended by a colon or full stop: one or more parts joined by commas,
-- each a few words ending in a label noun (TITLE_NOUNS) with its id after it ("Alpine crossing experiment:",
-- "Ticino scenario, run 1.", "Hundred series, test 1:", "Test 3 setup, bitte:"), names the script, no
-- instruction: it is set apart and the rest read. The words before a noun are letters only, none a clock or
-- flight verb, nor a pronoun (TITLE_NOT); a part that is a noun alone has its id ("Run 2:"; "Run:" may be the
-- clock's), and a full stop ends a title only after an id.
G.TITLE_NOUNS = { experiment = true, experiments = true, scenario = true, series = true, test = true, trial = true,
  exercise = true, run = true, setup = true, demo = true, session = true, study = true }
G.TITLE_NOT = { now = true, ["then"] = true, first = true, so = true, ["and"] = true, just = true, please = true,
  climb = true, descend = true, turn = true, maintain = true, reduce = true, increase = true, speed = true,
  direct = true, delete = true, create = true, hold = true, pause = true, resume = true, stop = true, start = true,
  go = true, fly = true, set = true, change = true, i = true, we = true, you = true, ["let's"] = true, lets = true,
  let = true, keep = true, make = true, it = true, them = true, this = true, that = true, everything = true,
  all = true, us = true, me = true, him = true, her = true, everyone = true, everybody = true }
G.TITLE_COURTESY = { bitte = true, please = true, merci = true }
function G.title_label(text)
  local head, mark, rest = text:match("^%s*([%a][^:.;!?]-)([:.])%s+(%a.*)$")
  if not head or #head > 60 then return text end
  local parts = {}
  for part in (head .. ","):gmatch("%s*([^,]-)%s*,") do parts[#parts + 1] = part end
  if G.TITLE_COURTESY[parts[#parts]:lower()] and #parts > 1 then parts[#parts] = nil end
  for _, part in ipairs(parts) do
    local words = {}
    for w in part:gmatch("%S+") do words[#words + 1] = w end
    -- (the words before the first label noun; then label nouns, each with an id after it or not)
    local k, pre = 1, 0
    while words[k] and not G.TITLE_NOUNS[words[k]:lower()] do
      if not words[k]:match("^%a[%a%-]*$") or G.TITLE_NOT[words[k]:lower()] then return text end
      k, pre = k + 1, pre + 1
    end
    if not words[k] or pre > 3 then return text end
    while words[k] do
      if not G.TITLE_NOUNS[words[k]:lower()] then return text end
      local id = words[k + 1] and (words[k + 1]:match("^%d%d?%a?$") or words[k + 1]:match("^%u$"))
      if not id and pre == 0 and not words[k + 1] then return text end
      k, pre = k + (id and 2 or 1), 1
      -- (a full stop ends a title only after its id: "let it run." is the clock's)
      if mark == "." and not words[k] and not id and part == parts[#parts] then return text end
    end
  end
  return rest
end
-- "run 4 minutes fast-time", "then 3 min fast-time and pause", "6 min fast forward": a duration with its unit
-- straight before "fast time"/"fast-time"/"fast forward", opening its clause (the text's start, a mark, "then",
-- "and", "run"), is how long to fast-forward: said as "fast-forward 4 minutes" (a "run" before it is that
-- verb). A duration after anything else ("climb within 4 minutes fast time") stays as said.
G.FAST_TIME_OPENERS = { ["then"] = true, ["and"] = true, now = true, next = true }
function G.time_before_fast(text)
  if not text:find("[Ff][Aa][Ss][Tt]") then return text end
  local function said(at, _, n, sp, unit, fast, tail)
    local what = fast:lower():sub(6)
    if not G.time_units[unit:lower()] or not (what == "time" or what == "forward") then return nil end
    local prev = text:sub(1, at - 1):match("(%S+)%s*$")
    if prev and not prev:find("[,;:.]$") and not G.FAST_TIME_OPENERS[prev:lower()] then return nil end
    return "fast-forward " .. n .. sp .. unit .. tail
  end
  text = text:gsub("()([Rr][Uu][Nn]%s+)(%d+%.?%d*)(%s*)(%a+)%s+([Ff][Aa][Ss][Tt][%- ]%a+)(%f[%A])", said)
  return (text:gsub("()(%d+%.?%d*)(%s*)(%a+)%s+([Ff][Aa][Ss][Tt][%- ]%a+)(%f[%A])",
    function(at, ...) return said(at, "", ...) end))
end
G.clock_commands = { HOLD = true, OP = true, FF = true, DTMULT = true }
G.time_units = { s = true, sec = true, secs = true, second = true, seconds = true, min = true, mins = true,
  minute = true, minutes = true, h = true, hr = true, hrs = true, hour = true, hours = true }

function M.translate(text, world)
  local said = text
  world = world or {}
  world.aircraft = world.aircraft or {}
  world.waypoints = world.waypoints or {}
  local quoted = M.quoted_clearance(text, world)
  if quoted then return quoted end
  if text:find("\xC3", 1, true) then text = text:gsub("[\xC3][\x80-\xBF]", lexicon.accents) end  -- (UTF-8 Latin-1 letters)
  -- (the Turkish letters of UTF-8 Latin Extended-A: "hayır", "sağol", "Şile")
  if text:find("[\xC4\xC5]") then text = text:gsub("[\xC4\xC5][\x80-\xBF]", lexicon.accents) end
  text = G.id_label(G.hold_after_ff(G.time_before_fast(numbered_steps(G.title_label(G.spoken_ddmm(G.spoken_zeros(G.number_words_apart(text))))))), world)
  -- ("climb to 10 km", "descend to 7.5 km": a level in kilometres straight after the vertical verb, as metres)
  if text:find("km", 1, true) then
    for _, verb in ipairs({ "[Cc]limbs?%s+to", "[Cc]limbs?", "[Dd]escends?%s+to", "[Dd]escends?" }) do
      text = text:gsub("(%f[%a]" .. verb .. "%s+)(%d+%.?%d*)%s*km%f[%A]", function(said, n)
        local m = tonumber(n) * 1000
        if m >= 300 and m <= 20000 then return string.format("%s%d m", said, math.floor(m + 0.5)) end
      end)
    end
  end
  -- ("at t=120 s", "at t = 2 min": the simulation's time with its unit, as "at time 120 s")
  -- ("at t=600 pause the sim": a whole number with no unit is BlueSky's simulation time in seconds; one with a
  -- decimal or a colon stays as typed)
  if text:find("=", 1, true) then
    text = text:gsub("(%f[%a][Aa]t%s+)[tT]%s*=%s*(%d+%s*[smhSMH])", "%1time %2")
    local label = text:match("^%s*(%a+)%s*:")  -- (a note for the log stays as typed: "log: spike at t=300")
    if not (label and lexicon.note_labels[label:lower()]) then
      text = text:gsub("(%f[%a][Aa]t%s+)[tT]%s*=%s*(%d+)%f[^%w:%.]", "%1time %2 s")
    end
  end
  -- a researcher's symbol, a letter or two and a subscript before its value ("t_lookahead = 480 s", "R_pz = 9.26
  -- km"): the setting its letters name together, else its subscript (SETTING_KEYS); any other stays as typed
  if text:find("_", 1, true) then
    text = text:gsub("%f[%w](%a%a?)_(%a+)(%s*[=:]?%s*%d)", function(a, b, value)
      local key = SETTING_KEYS[(a .. b):lower()] and a .. b or (SETTING_KEYS[b:lower()] and b)
      return key and key .. value
    end)
  end
  -- a decimal said with "point" ("42 point 2", "minus 122 point 4", "0 point 5", "mach point 7 8"): the number
  -- written, with one or two digits after the point, its whole part of one or two digits or after "minus" (a
  -- heading's "270 point 5" stays apart, asked)
  if text:find("point", 1, true) then
    for _, whole in ipairs({ "%f[%w](%d%d?)", "(%f[%a][Mm]inus%s+%d%d%d)" }) do
      text = text:gsub(whole .. "%s+point%s+(%d)%s+(%d)%f[%D]", "%1.%2%3"):gsub(whole .. "%s+point%s+(%d%d?)%f[%D]", "%1.%2")
    end
    text = text:gsub("%f[%a]([Mm]ach)%s+point%s+(%d)%s+(%d)%f[%D]", "%1 .%2%3"):gsub("%f[%a]([Mm]ach)%s+point%s+(%d%d)%f[%D]", "%1 .%2")
  end
  -- "at twelve nautical miles from BRA": a distance said after "at" in nautical miles is that many miles (the
  -- letters of "at" and the number before "nautical" are no callsign)
  if text:find("autical", 1, true) then
    text = text:gsub("(%f[%a][Aa][Tt]%s+[%w%.%-]+%s+)[Nn]autical%s+([Mm]iles?%f[%A])", "%1%2")
  end
  -- punctuation dictated as words: the marks (lexicon.dictated_punctuation)
  for _, d in ipairs(lexicon.dictated_punctuation) do
    -- (only where the text holds the last of the said words, as the pattern requires)
    if text:find(d.said:match("%S+$"), 1, true) then
      text = text:gsub("%s+" .. d.said:gsub(" ", "%%s+") .. "%f[%A]()", function(at)
        if d.not_before and text:match("^%s*(%a+)", at) == d.not_before then return nil end
        return d.mark
      end)
    end
  end
  -- ("hdg 130 → 100": the arrow typed as its character is the arrow)
  if text:find("\xE2\x86\x92", 1, true) then text = text:gsub("%s*\xE2\x86\x92%s*", " -> ") end
  -- "FL240 -> FL250", "fl370 -> 35000", "12000 -> FL150": an arrow between two levels (a flight level, or feet in
  -- four or five figures, on one side at least a flight level), from the one to the other
  if text:find(">", 1, true) then
    text = text:gsub("([Ff][Ll]%s?%d%d%d?)%s*[%-=]+>%s*([Ff][Ll]%s?%d%d%d?)", "from %1 to %2")
    text = text:gsub("([Ff][Ll]%s?%d%d%d?)%s*[%-=]+>%s*(%d%d%d%d%d?%f[^%w%.])", "from %1 to %2 ft")
    text = text:gsub("(%f[%w%.]%d%d%d%d%d?)%s*[%-=]+>%s*([Ff][Ll]%s?%d%d%d?)", "from %1 ft to %2")
  end
  -- "hdg 220 -> 250", "spd 280 -> 250": an arrow between two values after the name of a heading or speed, from
  -- the one to the other
  if text:find(">", 1, true) then
    text = text:gsub("%f[%w](%a+)(%s*)(%d+)%s*[%-=]+>%s*(%d+)%f[^%w%.]", function(name, space, from, to)
      if word_set("heading hdg speed spd", 1)[name:lower()] then return name .. space .. "from " .. from .. " to " .. to end
    end)
  end
  -- "wind ... 270/25(kt)": a wind written as its direction and speed in knots with a slash between
  if text:lower():find("wind", 1, true) then
    text = text:gsub("%f[%w%.](%d%d%d)/(%d%d?%d?)%s*[Kk]?[Tt]?[Ss]?%f[^%w%.]", "from %1 at %2 knots")
    -- ("set the wind ... to 2 7 0 at 50 knots": a direction's three digits said apart after "to" or "from")
    text = text:gsub("(%f[%a][TtFf][or]o?m?%s+)([0-3])%s+(%d)%s+(%d)%f[%D]", function(w, a, b, c)
      if not (w:lower():match("^to%s") or w:lower():match("^from%s")) then return nil end
      return w .. a .. b .. c
    end)
  end
  -- "47.35/15.30": a latitude and longitude in decimal degrees written with a slash between
  if text:find("/", 1, true) then text = text:gsub("(%f[%w%.%-]%-?%d+%.%d+)/(%-?%d+%.%d+%f[^%w%.])", "%1 %2") end
  -- "the Transavia's there", "KLM12's already at FL300", "KLM12's at FL350": a name's "'s" before a word of place,
  -- time or level kept is "is"
  if text:find("'s ", 1, true) or text:find("\xE2\x80\x99s ", 1, true) then
    text = text:gsub("(%f[%w][%u%d][%w]*)['\xE2\x80\x99]+s (%l+)", function(name, w)
      if DESCRIBED_AFTER[w] then return name .. " is " .. w end
    end)
    -- ("detection's on?", "the resolution's switched off": a word's "'s" before a state of lexicon.state_after_s is
    -- "is")
    text = text:gsub("(%f[%a]%a+)['\xE2\x80\x99]+s (%a+)", function(name, w)
      if G.state_after_s[w:lower()] and name:lower() ~= "let" then return name .. " is " .. w end
    end)
  end
  if text:find(",", 1, true) then text = G.clause_commas(text) end
  -- "330/FL350/280kt": values written with slashes between (each part holding a digit) are values apart;
  -- a fraction "1/2" stays whole; "VLG2211 / A320 / 42.3 -2.0 / 040": a slash with spaces on both sides
  -- separates fields as a comma does
  if text:find("/", 1, true) then
    text = text:gsub("(%S)%s+/%s+(%S)", "%1, %2")
    text = text:gsub("[^%s,;]*/[^%s,;]*", function(w)
      if w:match("^%d/%d+$") then return nil end
      for part in (w .. "/"):gmatch("([^/]*)/") do
        if not part:find("%d") then return nil end
      end
      return (w:gsub("/", " "))
    end)
  end
  -- "swr18k ,edw22", "dlh4tk,ewg7ma": a comma typed against the next word closes the word before (a comma
  -- between digits, "12,000" or "48.1,16.5", stays)
  -- (so after a value: "hdg 250,descend fl300")
  if text:find(",%a") then
    text = text:gsub("(%S)%s+,(%a)", "%1, %2"):gsub("(%f[%w]%a[%w]*),(%a)", "%1, %2")
      :gsub("(%f[%w]%d+),(%a%a)", "%1, %2")
  end
  -- "Ryanair 92 X-ray", "x ray": the letter X's phonetic word, written apart, is one word before any callsign is
  -- read
  -- ("four alpha ex-ray", "exray": the letter spelled as it sounds)
  if text:find("[Rr][Aa][Yy]") then
    text = text:gsub("%f[%a]([Xx])[%- ]([Rr][Aa][Yy])%f[%A]", "%1%2")
      :gsub("%f[%a]([Ee])[Xx][%- ]?([Rr][Aa][Yy])%f[%A]", function(e, ray) return (e == "E" and "X" or "x") .. ray end)
  end
  -- "HDG SEL 360", "speed selected 250": a flight-deck selector named after the value's name is that value
  if text:find("[Ss][Ee][Ll]") then
    text = text:gsub("%f[%w]([%a/]+)%s+([Ss][Ee][Ll]%a*)%f[%A]", function(w, sel)
      if lexicon.selector_names[w:lower()] and lexicon.selector_words[sel:lower()] then return w end
    end)
  end
  -- "vs +1500", "V/S +2500", "roc +800": a plus typed before a vertical speed is its sign (a climb)
  -- (and after "vertical speed": "vertical speed +1200")
  if text:find("%+%d") then
    text = text:gsub("()%f[%w]([%a/]+)(%s*)%+(%d)", function(at, w, space, d)
      if lexicon.signed_rate_words[w:lower()] then return w .. space .. d end
      -- (after "vertical speed" the plus is said as the word, the rate's sign: handlers' m:vspeed)
      if w:lower() == "speed" and text:sub(1, at - 1):lower():find("vertical%s+$") then
        return w .. " plus " .. d
      end
    end)
  end
  -- "fl,260": a comma typed after "FL" is no break in the level. "climb FL3 60", "descend fl 2 10", "EZY19AB CLIMB
  -- TO FL3 60": a space inside a typed level's three figures (one figure, then two) may hide a figure lost, doubled
  -- or moved (FL360, FL300, FL3600?): asked, never joined, unless a unit follows ("fl 2 10 knots": no level)
  -- (two figures, then one, "fl 36 0", likewise; figures typed one by one, "FL 3 6 0", and any split after "flight
  -- level" stay read)
  if text:find("[Ff][Ll]") then
    text = text:gsub("%f[%a]([Ff][Ll]),%s*(%d%d%d?)%f[%D]", "%1%2")
    local split
    for _, form in ipairs({ "%f[%a]([Ff][Ll]%s?%d)%s+(%d%d)%f[%D]()", "%f[%a]([Ff][Ll]%s?%d%d)%s+(%d)%f[%D]()" }) do
      for fl, two, at in text:gmatch(form) do
        local unit = text:match("^%s*(%a+)", at)
        -- (a figure after the one split off, "FL 36 0 5", is no level's; one taken back by a correction said straight
        -- after it, "FL 16 0 - sorry, I mean one six zero", is the correction's to read)
        local taken = (text:sub(at):lower():match("^[%s%p\226\128\148\226\128\147]*(%a+ ?%a*)") or ""):match("^(%a+)")
        taken = taken and (lexicon.level_split_taken_back[taken] or text:sub(at):lower():match("^[%s%p\226\128\148\226\128\147]*i mean"))
        if not split and not (unit and lexicon.level_split_units[unit:lower()]) and not text:match("^%s*%d", at)
            and not taken then
          split = { fl .. " " .. two, fl:match("%d+$") .. two }
        end
      end
    end
    if split then
      return { commands = {}, ask = string.format("Which level is '%s': FL%s? A space splits its figures, so one may "
        .. "be lost or out of place: please type the level again in one group.", split[1], split[2]) }
    end
  end
  -- "mach.82": a Mach number typed against its word
  if text:find("[Mm][Aa][Cc][Hh]%.%d") then text = text:gsub("%f[%a]([Mm][Aa][Cc][Hh])%.(%d)", "%1 .%2") end
  -- "spd 2o0", "hdg 12O": a letter O typed for a zero in a value of three figures or more, a digit first
  if text:find("%d[oO]") then
    text = text:gsub("%f[%w](%d[%doO][%doO]+)%f[%W]", function(v) return (v:gsub("[oO]", "0")) end)
  end
  -- "aua131 .82": a Mach number typed alone after a callsign, two figures from .40 on
  if text:find("%s%.[4-9]%d") then
    text = text:gsub("(%S+)(%s+)%.([4-9]%d)%f[^%w%.]", function(id, space, digits)
      for _, a in ipairs(world.aircraft) do
        if a.id:lower() == id:lower() then return id .. space .. "m." .. digits end
      end
    end)
  end
  -- "the closest point of approach": an abbreviation's words said out (lexicon.spelled_out), read as it
  local low = text:lower()
  for _, x in ipairs(SPELLED_OUT) do
    if low:find(x.words, 1, true) then
      text = text:gsub(x.pattern, x.short)
      low = text:lower()
    end
  end
  text = airline_values(named_airline_ids(split_ids(unglued_ids(G.iata_ids(text, world.aircraft), world.aircraft),
    world.aircraft)), world.aircraft)
  text = homophone_ids(G.hundreds_callsign(G.recognised_callsigns(glued_telephony(G.common_named(G.joined_telephony(G.aircraft_of_airline(text)), world),
    world.aircraft), world), world), world)
  text = G.other_callsign_denied(text, world.aircraft)
  text = G.level_hundreds_apart(text)
  local abbreviated
  text, abbreviated = abbreviated_registrations(text, world.aircraft)
  if abbreviated then return { commands = {}, ask = abbreviated } end
  text = spelled_registrations(text, world.aircraft)
  local types = require("translate.types")
  text = G.spoken_degrees_minutes(text)
  local dm = impossible_minutes(text)
  if dm then
    return { commands = {}, ask = string.format("'%s' is no position: minutes run from 0 to 59. Which latitude "
      .. "and longitude do you mean?", dm) }
  end
  local run_together
  text, run_together = G.run_together_position(text)
  if run_together then return { commands = {}, ask = run_together } end
  local create_digit = G.create_digit_homophone(text)
  if create_digit then return { commands = {}, ask = create_digit } end
  text = G.confirmed_route_places(G.spelled_route_places(G.syllable_route_places(typed_places(G.named_idents(
    G.spoken_user_waypoints(G.navaids_by_kind(written_forms(text, world), world), world), world),
    world), world), world), world)
  text = G.terse_altitude(G.after_reach(G.pronoun_reached(G.future_will(spelled_airports(text, world))), world), world)
  local run_on
  text, run_on = G.run_on_values(text)
  if run_on then return { commands = {}, ask = run_on } end
  -- a time typed in two parts ("at 10:30", "schedule at 00:15: ..."): hours and minutes or minutes and
  -- seconds, which squawk does not tell apart (FF reads "ff 1:30" itself); asked when another command
  -- would run without it
  local two_part = text:match("%f[%d:](%d%d?:[0-5]%d):?%f[^%d:]")
  -- type names with their digits said as words, where traffic is created (random traffic too)
  local lower = text:lower()
  -- (a word opening a word of the text, or `whole` one; the pattern is tried only where a plain find sees it)
  local function cue(word, whole)
    return lower:find(word, 1, true) and lower:find("%f[%a]" .. word .. (whole and "%f[%A]" or ""))
  end
  -- ("new traffic: ...", "set up Austrian 719, Embraer one ninety five, ...", "put a CSA ..., A three nineteen",
  -- "chuck a jetstar in at blaka a three twenty ..."; "crea", "crear", "creer": the verb in the speaker's language)
  if cue("crea") or cue("cree") or cue("spawn") or cue("generate") or cue("add") or cue("mcre") or cue("random")
      or cue("new", true) or cue("set up", true) or cue("put", true) or cue("chuck", true) or cue("stick", true) then
    text = types.plurals(types.spoken(text, TYPES, lexicon.phonetic), TYPES, world.aircraft, lexicon.variant_families)
    text = types.short_singular(text, TYPES, lexicon.variant_families)
  end
  local apart
  text, apart = set_apart(types.join(text, TYPES.phrases))
  local u = squawk.translate.utterance(text, world, NAMES)
  local toks = u:tokens()
  local points = G.route_points_said(text, u, world, toks)
  if points then
    text = points
    u = squawk.translate.utterance(text, world, NAMES)
    toks = u:tokens()
  end
  local g = setmetatable({ u = u, t = toks, words = word_texts(toks), refs = u:refs(), world = world,
    fleet = world.aircraft, out = {}, qcache = {}, taken = {}, noted = {}, cut_back = {}, triggers = {}, apart = apart,
    text_said = said }, G)
  g:settle_callsigns()
  local same = g:same_for()
  g:airline_types()
  g:airline_refs()
  g:type_refs()
  g:position_refs()
  g:described_refs()
  g:nationality_refs()
  for _, id in ipairs(g:same_for()) do same[#same + 1] = id end
  g:bearing_refs()
  g:destination_refs()
  g:created_just_said()
  g:creation_refs()
  g:carried_refs()
  g:prefix_refs()
  g:role_refs()
  g:false_starts()
  g:fix_refs()
  g:navaid_name_refs()
  g:named_place_refs()
  g:passed_place_refs()
  g:opening_right()
  g:urgent_right()
  g:runway_sides()
  g:side_after_level()
  g:level_limits()
  -- a latitude beyond a pole or a longitude beyond the antimeridian ("95 N", "190 W") is no position
  for _, q in ipairs(g:quantities(1, #g.t + 1)) do
    if (q.kind == "lat" and math.abs(q.value) > 90) or (q.kind == "lon" and math.abs(q.value) > 180) then
      return { commands = {}, ask = string.format("'%s' is no %s: it runs from 0 to %d degrees %s. Which position "
        .. "do you mean?", g:raw(q.b, q.e), q.kind == "lat" and "latitude" or "longitude", q.kind == "lat" and 90 or 180,
        q.kind == "lat" and "north or south" or "east or west") }
    end
    -- a hemisphere said straight after a coordinate that did not take it ("latitude 41.4 west": the other axis's)
    local t = (q.kind == "lat" or q.kind == "lon") and g.t[q.e]
    if t and t.kind == "word" and G.hemisphere_axis({ raw = t.raw, bare = t.text }) then
      return { commands = {}, ask = string.format("Is '%s' a %s? '%s' is not a hemisphere of it. Which position do "
        .. "you mean?", g:raw(q.b, q.e + 1), q.kind == "lat" and "latitude" or "longitude", t.raw) }
    end
  end
  if g:not_yet_question() then return { commands = g.out } end
  local pair = g:pair_question()
  if pair then return { commands = pair } end
  g:route_remarks()
  g:state_remarks()
  g:past_state()
  g:present_state()
  g:break_remarks()
  g:destination_told()
  g:destination_preface()
  g:onward_remark()
  g:limit_released()
  local note = g:not_simulated()
  g:self_corrected()
  g:places_corrected()
  g:question_back()
  g:refused()
  g:replaced_values()
  g:kept_values()
  g:aircraft_kept()
  g:aircraft_left_alone()
  g:kept_present()
  g:condition_grammar_words()
  g:infinitive_after_condition()
  g:subject_after_condition()
  g:acknowledged()
  g:stations()
  g:exercise_names()
  g:places_by_position()
  g:fixes_spelled()
  -- only what is not simulated was said: no instruction word and no value left
  if note and not g:any_instruction() and #g:quantities(1, #g.t + 1) == 0 then return { commands = {}, note = note } end
  local cond, rest = g:condition()
  local now_from = cond and not g.ask and g:condition_scope(rest)
  if not g.ask then
    local k, level, kind = nil, nil, nil
    local ce  -- (the end of a trailing condition, the clause after it run at once: G:condition_closed)
    if not cond then k, level, kind, ce = g:trailing_level_condition() end
    -- (a trailing condition holds the instruction of its own clause: the one after the last comma, "and"
    -- or "then" before it)
    local clause = rest
    for x = rest, (k or 0) - 1 do
      if g.t[x].kind == "punct" or g:word(x, "and @then_words") then clause = x + 1 end
    end
    -- (a callsign alone before the clause, "Aeroflot 1102, reduce speed 250 when it is below FL100", is the
    -- clause's addressee: parsed with it)
    if clause > rest and k then
      local alone, named = true, 0
      local x = rest
      while alone and x < clause do
        local r = g:refs_in(x, x + 1, "aircraft")[1]
        if r and r.b == x then
          x, named = r.e, named + 1
        else
          alone = g.t[x].filler or (g.t[x].kind == "punct" and g.t[x].text == ",")
          x = x + 1
        end
      end
      if alone and named == 1 then clause = rest end
    end
    if clause > rest then g:parse(rest, clause) end
    local before = #g.out
    g:parse(clause, k or now_from or #g.t + 1)
    if k and not g.ask then
      -- (the condition's words: what the ATALT says)
      g:take(level)
      g:explain(k, ce)
      local f = handlers.format
      local at = level.kind == "alt" and f.alt(level.value, level.fl) or level.kind == "mach" and f.mach(level.value)
        or f.int(level.value)
      for c = before + 1, #g.out do
        local id = g.out[c]:match("^%u+ (%S+)")
        if not id or not g:state(id) then
          g.ask = "Which aircraft's instruction should wait for " .. at .. "? Please say it with its callsign."
          break
        end
        g.out[c] = kind .. " " .. id .. " " .. at .. " " .. g.out[c]
      end
      if ce <= #g.t and not g.ask then g:parse(ce, #g.t + 1) end
    end
    -- ("after DLL descend FL180 and slow to 290": an instruction of the same aircraft after one tied to a waypoint,
    -- itself tied to no place or condition, may wait for the waypoint too or run now: asked, never sent now)
    local wd = g.waypoint_do
    for c = wd and not g.ask and wd.n + 1 or 1, wd and not g.ask and #g.out or 0 do
      if g.out[c]:match("^%u+ (%S+)") == wd.id and not g.out[c]:match("^AT") then  -- (one tied elsewhere stands)
        if c == #g.out and c == wd.n + 1 and wd.e and g:joined_under_waypoint(wd.e) then
          g.out[c] = "AT " .. wd.id .. " " .. wd.wp .. " DO " .. g.out[c]
          break
        end
        g.ask = string.format("I have %s. Should %s also wait until %s passes %s, or run now?",
          table.concat(g.out, " ; "), g.out[c], wd.id, wd.wp)
        break
      end
    end
    if cond and not g.ask then
      if #g.out == 0 then g.ask = "What should happen when the condition is met?" end
      if g.at_place then
        g:at_condition()
      else
        -- (what waits is the condition's aircraft's own instruction: "when passing 15000 resume normal speed"
        -- is no simulation speed)
        for c = 1, #g.out do
          local id = g.out[c]:match("^%u+ (%S+)")
          if not id or id:upper() ~= g.subject:upper() then
            g.ask = "I have " .. table.concat(g.out, " ; ") .. ". What should " .. g.subject
              .. " do when the condition is met?"
            break
          end
          g.out[c] = cond .. " " .. g.out[c]
        end
      end
      if now_from and not g.ask then g:parse(now_from, #g.t + 1) end
    end
  end
  if not g.ask then g:restated_at_place() end
  if not g.ask then g:passing_level_flown() end
  if not g.ask then g:level_never_crossed() end
  if not g.ask then g:respectively() end
  if not g.ask then g:discretion_without_level() end
  if not g.ask then g:crossing_without_place() end
  if not g.ask then g:direct_when_able() end
  if not g.ask then g:direct_via_unread() end
  if not g.ask then g:skipped_on_direct() end
  g:same_again(same)
  if not g.ask then g:forgotten() end
  if not g.ask then g:predicated() end
  if not g.ask then g:unknown_places() end
  if not g.ask then g:described() end
  if not g.ask then g:state_question() end
  if not g.ask then g:bracket_question(said) end
  if not g.ask then g:participle_question() end
  if not g.ask then g:heading_after_direct() end
  if not g.ask then g:speed_lifted_and_given() end
  if not g.ask then g:resume_after_instruction() end
  if not g.ask then g:op_after_ff() end
  if not g.ask then g:shown_after_instruction() end
  if not g.ask and #g.out > 0 then g:condition_dropped() end
  if not g.ask and #g.out > 0 then g:condition_lost_in_correction() end
  if not g.ask and #g.out > 0 then g:run_left() end
  if not g.ask and #g.out > 0 then g:level_with_unit(lower) end
  -- "... actually no, just the descent" (G:self_corrected): only the commands of that kind stand
  if not g.ask and g.kept then
    local kept = {}
    for _, line in ipairs(g.out) do
      if line:find("%f[%w]" .. g.kept .. " ") then kept[#kept + 1] = line end
    end
    if #kept == 0 then g.ask = "Which instruction stands after the correction? Please say it again in full." end
    g.out = kept
  end
  if not g.ask and #g.out == 0 then g.ask = g.pending end
  if not g.ask then g:info_remarks() end
  if not g.ask then g:dangling_correction() end
  if not g.ask and #g.out > 0 then g:retracted() end
  if not g.ask and #g.out > 0 then g:other_taken_back() end
  if not g.ask and #g.out > 0 then g:refused_or_requested() end
  if not g.ask and #g.out > 0 then g:dangling_value_name() end
  if not g.ask and #g.out > 1 then g:side_by_side_callsigns() end
  if not g.ask and #g.out > 0 and #g.refs > 1 then g:aircraft_aside() end
  if not g.ask then g:list_value() end
  if not g.ask then g:setting_twice() end
  if not g.ask then g:setting_question() end
  if not g.ask and #g.out > 0 then g:opinion_question(lower) end
  if not g.ask and #g.out > 0 then g:offer_question(lower) end
  if not g.ask and #g.out > 0 then g:count_alone() end
  if not g.ask then g:short_level() end
  if not g.ask then g:implausible_values() end
  if not g.ask and #g.out > 0 and lower:find("m", 1, true) then g:implausible_mach() end
  if not g.ask and #g.out > 0 and (lower:find("head", 1, true) or lower:find("hdg", 1, true)) then g:heading_unit() end
  if not g.ask and #g.out > 0 then g:value_rejected() end
  if not g.ask and #g.out > 0 then g:instruction_withheld() end
  if not g.ask and not g.leftover and #g.out > 0 then g:clock_verb_left() end
  if not g.ask and not g.leftover then g:unknown_names() end
  if not g.ask and not g.leftover then g:clock_remark() end
  if not g.ask and not g.leftover then g:uncarried() end
  if not g.ask and not g.leftover then g:uncarried_names() end
  if not g.ask and not g.leftover then g:unread_switch() end
  if not g.ask and not g.leftover then g:told_setting() end
  if not g.ask and not g.leftover and #g.out > 0 then g:hedged_place() end
  if not g.ask and #g.out > 0 then g:airline_word_dropped() end
  if not g.ask and not g.leftover then g:values_named_unread() end
  if not g.ask and not g.leftover then g:unaccounted() end
  if not g.ask and not g.leftover and #g.out > 0 then g:described_uninstructed() end
  if not g.ask and not g.leftover and #g.out > 0 then g:delay_left() end
  if not g.ask and not g.leftover and g:values_only() then g:passage_left() end
  if not g.ask and not g.leftover and g:values_only() then g:going_on_left() end
  if not g.ask and not g.leftover then g:hedged() end
  if not g.ask and not g.leftover and lower:find("or", 1, true) then g:alternatives() end
  if not g.ask then g:values_misread() end
  if not g.ask and g.leftover then g:heard_route_place() end
  if not g.ask and #g.out > 0 and (lower:find("provid") or lower:find("long as") or lower:find("assuming")
      or lower:find("given") or lower:find("only if") or lower:find("condition") or lower:find("in case")
      or lower:find("subject to") or lower:find("depending on")) then
    -- ("..., provided there is no conflict", "as long as BAW5 is clear": G.traffic_condition_clause)
    local clause = G.traffic_condition_clause(lower)
    if clause then
      g.ask = string.format("I have %s, but squawk cannot wait for '%s'. Should I give it now, or not at all?",
        table.concat(g.out, " ; "), clause)
    end
  end
  if not g.ask and g.leftover and #g.out > 0 and G.condition_openers[g.leftover:lower()] then
    -- ("..., if there is no conflict", "unless there is traffic": a condition on the traffic no command waits for)
    local b = lower:find("%f[%a]" .. g.leftover:lower() .. "%f[%A]")
    local clause = b and lower:sub(b):match("^[^,;.!?]+"):gsub("%s+$", "")
    local traffic = false
    for w in (clause or ""):gmatch("%a+") do
      traffic = traffic or (" " .. G.traffic_condition_words .. " "):find(" " .. w .. " ", 1, true) ~= nil
    end
    if clause and traffic then
      g.ask = string.format("I have %s, but squawk cannot wait for '%s'. Should I give it now, or not at all?",
        table.concat(g.out, " ; "), clause)
    end
  end
  if not g.ask and g.leftover then g:addwpt_level_left() end
  if not g.ask and g.leftover then
    g.ask = #g.out == 0 and string.format("I have no instruction. What does '%s' mean?", g.leftover)
      or string.format("I have %s. What does '%s' mean?", table.concat(g.out, " ; "), g.leftover)
  end
  if two_part and not g.ask and g.out[1] and not g.out[1]:find("^FF") and not g:time_set_aside(two_part) then
    g.ask = string.format("I have %s. Which time is '%s': hours and minutes, or minutes and seconds? Please "
      .. "type it h:mm:ss.", table.concat(g.out, " ; "), two_part)
  end
  if g.ask then return { commands = {}, ask = g.ask, confirm = g.confirm, ignorable = g.ignorable, heard_sure = g.heard_sure } end
  if #g.out == 0 and note then return { commands = {}, note = note } end
  if #g.out == 0 then return { commands = {}, ask = UNDERSTOOD } end
  g:added_after_route_end()
  -- a command said twice in one request ("send the KLM direct to SPY ... add SPY and then go direct to it")
  -- is one clearance; a clock's command (HOLD, OP, FF, DTMULT) said again after another clock command changed the
  -- run ("pause; ...; fast-forward 8 minutes; pause again") is a second one, in its order
  local out, seen, clock = {}, {}, 0
  for _, line in ipairs(g.out) do
    local clocked = G.clock_commands[line:match("^%u+")]
    if not seen[line] or (clocked and seen[line] ~= clock) then
      if clocked and seen[line] ~= clock then clock = clock + 1 end
      out[#out + 1], seen[line] = line, clocked and clock or true
    end
  end
  if g.kept_note then note = note and note .. " " .. g.kept_note or g.kept_note end
  return { commands = out, note = note, confirm_first = g.confirm_first }
end
-- A request asked about is read again with its typing slips (translate/typos.lua) read as the words they may be.
M.read_typed, M.typos = M.translate, require("translate.typos")
M.typos.not_understood = UNDERSTOOD
-- A waypoint heard as a word that can only be one waypoint of the instructed aircraft's route (G.heard_nowhere_else)
-- is read as confirmed: the request is read again with that ident in world.confirmed; a question then stands as first
-- asked.
function M.read_heard(text, world)
  local r = M.read_typed(text, world)
  if not (r.ask and r.heard_sure) then return r end
  local confirmed = { [r.heard_sure] = true }
  for k, v in pairs(world.confirmed or {}) do confirmed[k] = v end
  local again = M.read_typed(text, setmetatable({ confirmed = confirmed }, { __index = world }))
  r.heard_sure = nil
  return again.ask and r or again
end
-- The transcriber's mark of words not heard (lexicon.unheard_markers) in brackets, parentheses, angle brackets or
-- asterisks, as written, or nil: "descend eight thousand... [unintelligible]... feet" may have lost a digit.
function G.unheard_mark(text)
  if not text:find("[%[%(<%*]") then return nil end
  for _, pattern in ipairs({ "%b[]", "%b()", "%b<>", "%*[^%*]+%*" }) do
    for mark in text:gmatch(pattern) do
      local low = " " .. mark:lower():gsub("[^%a%-]+", " ") .. " "
      for _, w in ipairs(lexicon.unheard_markers) do
        if low:find(" " .. w .. " ", 1, true) then return mark end
      end
    end
  end
  return nil
end
-- "BAW8CK WHEN READY DESCEND TO FL340", "DLH4AX RESUME OWN NAVIGATION", "EIN154 CLIMB AT 1000 FT/MIN": in a line
-- typed with no lower-case letter (a CPDLC uplink in its message set's capitals) the case tells no name from a word,
-- so a word of two letters or more, letters only, that squawk knows as English (known_word) is read in lower case,
-- as if typed so. A word stays as typed when it may be a name or a code: a simulator command's name or alias that
-- is no English word (REGISTRY_WORDS: TrafScript typed in capitals, "HDG", "ADDWPT"), an abbreviation that names nothing
-- (lexicon.not_names) or a navaid's kind, an airline's one-word name squawk knows no other way ("SPEEDBIRD"), an
-- aircraft's id, a waypoint of an aircraft's route, its destination or origin, a DEFWPT's name, or, straight after a
-- word of a place's slot (PLACE_SLOTS, "to", "by", "passing", ...), a fix, navaid or airport the navdata holds within
-- TYPED_PLACE_NM of an aircraft ("DIRECT BIG"). A line with a lower-case letter is returned as it is.
G.capitals_slots = { to = true, by = true, passing = true, abeam = true, crossing = true, past = true, towards = true,
  toward = true, of = true, reaching = true }
function G.capitals_read(text, world)
  if text:find("%l") or not text:find("%u%u") then return text end
  if not G.capitals_kept then
    local kept = {}
    for w in pairs(REGISTRY_WORDS) do kept[w] = true end
    for _, w in ipairs(lexicon.not_names) do kept[w] = true end
    for _, w in ipairs(lexicon.navaid_kinds) do kept[w] = true end
    G.capitals_kept = kept
  end
  local kept, named = G.capitals_kept, {}
  for _, a in ipairs(world.aircraft or {}) do
    named[(a.id or ""):lower()] = true
    for _, r in ipairs(a.route or {}) do named[r:lower()] = true end
    if a.dest and a.dest ~= "" then named[a.dest:lower()] = true end
    if a.orig and a.orig ~= "" then named[a.orig:lower()] = true end
  end
  for _, w in ipairs(world.waypoints or {}) do named[tostring(w):lower()] = true end
  local function near(w)
    if not world.place_known then return false end
    local lat, lon = world.place_known(w:upper())
    if not lat then return false end
    for _, a in ipairs(world.aircraft or {}) do
      local dlat, dlon = lat - (a.lat or 0), (lon - (a.lon or 0)) * math.cos(math.rad(lat))
      if a.lat and 60 * math.sqrt(dlat * dlat + dlon * dlon) <= TYPED_PLACE_NM then return true end
    end
    return false
  end
  local prev  -- (the word before, lower case, when only white space lies between)
  local out, from = {}, 1
  for b, w, e in text:gmatch("()(%a+)()") do
    local low = w:lower()
    local apart = (b == 1 or not text:sub(b - 1, b - 1):match("[%w]")) and not text:sub(e, e):match("[%w]")
    local slot = prev and (PLACE_SLOTS[prev] or G.capitals_slots[prev])
    local name = G.name_words[low]
    if apart and #w >= 2 and known_word(low) and not kept[low] and not named[low]
        and not (name and next(name) == nil) and not (slot and near(w)) then
      out[#out + 1] = text:sub(from, b - 1) .. low
      from = e
    end
    local gap = text:sub(e):match("^%s+")
    prev = (apart and gap) and low or nil
    if prev and text:sub(e + #gap, e + #gap):match("%a") == nil then prev = nil end
  end
  if from == 1 then return text end
  return table.concat(out) .. text:sub(from)
end
function M.translate(text, world)
  text = G.capitals_read(text, world or {})
  local unheard = G.unheard_mark(text)
  if unheard then
    return { commands = {}, ask = string.format("Part of the request was not heard ('%s'). Please say it again.",
      unheard) }
  end
  local first = G.said_first(text, world or {})
  if first then return first end
  local summed = G.summary_closed(text, world or {}) or G.present_told(text, world or {})
  if summed then return summed end
  local r = M.read_heard(text, world)
  if not r.ask then return r end
  return M.typos.reread(text, world or {}, r, M.read_typed)
end

-- "JJA1205 heading 180, JNA432 heading 340, two aircraft please", "AAR8917 speed 300 and FL310 climb, both please",
-- "AAR371 heading 270, FL180, speed 250, all three please": a last clause (after a comma, full stop or semicolon)
-- that only counts what was said ("both", "all" and a count, or a count; an aircraft noun or "instructions" after it;
-- "ok"/"so" before and "please"/"thanks" after at most). The words before it are read alone; their reading stands
-- when it has no question and the count is its aircraft's (two aircraft instructed: "both", "two aircraft") or, said
-- to one aircraft with no aircraft noun, its instructions' ("both" for a speed and a level). Else nil (read whole).
G.summary_counts = { both = 2, two = 2, three = 3, four = 4, five = 5, ["2"] = 2, ["3"] = 3, ["4"] = 4, ["5"] = 5 }
G.summary_nouns = { aircraft = "aircraft", planes = "aircraft", airplanes = "aircraft", aeroplanes = "aircraft",
  flights = "aircraft", instructions = "commands", commands = "commands", clearances = "commands", changes = "commands" }
function G.summary_closed(text, world)
  local cut, body = text:match("()[,.;]%s*([%w%s']+)[%.!]?%s*$")
  if not cut then return nil end
  local w = {}
  for x in body:lower():gmatch("%S+") do w[#w + 1] = x end
  local a, z = 1, #w
  while w[a] == "ok" or w[a] == "okay" or w[a] == "so" or w[a] == "and" do a = a + 1 end
  if w[z] == "you" and w[z - 1] == "thank" then z = z - 2 end
  while w[z] == "please" or w[z] == "thanks" do z = z - 1 end
  if w[a] == "all" or (w[a] == "both" and G.summary_counts[w[a + 1] or ""]) then a = a + 1 end
  local n = G.summary_counts[w[a] or ""]
  if not n then return nil end
  a = a + 1
  local kind
  if a <= z and G.summary_nouns[w[a]] then kind, a = G.summary_nouns[w[a]], a + 1
  elseif w[a] == "of" and w[a + 1] == "them" then a = a + 2 end
  if a <= z then return nil end
  local rest = text:sub(1, cut - 1)
  if not rest:find("%a") then return nil end
  local r = M.read_heard(rest, world)
  if r.ask or r.confirm_first or #(r.commands or {}) == 0 then return nil end
  local fleet, ids, n_ids = {}, {}, 0
  for _, ac in ipairs(world.aircraft or {}) do fleet[(ac.id or ""):upper()] = true end
  for _, c in ipairs(r.commands) do
    local id
    for t in c:gmatch("%S+") do
      if not id and fleet[t:upper()] then id = t:upper() end
    end
    if not id then return nil end
    if not ids[id] then ids[id], n_ids = true, n_ids + 1 end
  end
  if (kind ~= "commands" and n_ids == n) or (kind ~= "aircraft" and n_ids == 1 and #r.commands == n) then return r end
  return nil
end

-- "KAL1001 speed, ah, it is 280 now? then 260 make": the value the aircraft has now, told or asked ("it is N now?",
-- "it's N now?", "is it N now?"), then "then" or "so" and the value to fly: the words from the told value to "then"
-- are read as no value; the rest's reading stands when it is one command with a value other than N. Else nil.
function G.present_told(text, world)
  local low = text:lower()
  local b, n, e
  for _, pat in ipairs({ "()it is (%d+) now%s*%?%s*[,]?%s*then%s+()", "()it's (%d+) now%s*%?%s*[,]?%s*then%s+()",
                         "()is it (%d+) now%s*%?%s*[,]?%s*then%s+()", "()it is (%d+) now%s*%?%s*[,]?%s*so%s+()" }) do
    if not b then b, n, e = low:match(pat) end
  end
  if not b then return nil end
  local rest = text:sub(1, b - 1) .. text:sub(e)
  local r = M.read_heard(rest, world)
  if r.ask or r.confirm_first or #(r.commands or {}) ~= 1 then return nil end
  local v = r.commands[1]:match("^%u+ %S+ (%d+)$")
  if not v or v == n or not r.commands[1]:match("^[SH][PD][DG] ") then return nil end
  return r
end

-- "Create 10 random A320s at FL300; set seed 42 first so that the run is repeatable", "fast-forward 5 minutes,
-- but first pause the simulation": the last clause (after a semicolon, comma, "and" or "but") marked "first" (its
-- last word, before a purpose "so"/"to"/"because" or the end, or "first" opening it) runs before the words before
-- it. Read apart, when the clause alone gives only commands to the simulation (no aircraft of the fleet, no
-- creation) and the words before it give commands: those first, then the rest; nil otherwise (the request is
-- read whole, its commands for aircraft sent at once).
function G.said_first(text, world)
  local low = text:lower()
  if not low:find("first", 1, true) then return nil end
  local cut, clause
  for b, sep, body in low:gmatch("()([;,]%s*)([^;,]+)$") do
    cut, clause = b, body
  end
  if not cut then
    local b, body = low:match("()%s+but%s+(first%s.+)$")
    cut, clause = b, body
  end
  if not cut then return nil end
  local raw = text:sub(cut):gsub("^[;,]?%s*", "")
  local body = raw:gsub("^[Aa]nd%s+", ""):gsub("^[Bb]ut%s+", "")
  local inner
  if body:lower():find("^first[%s,]") then
    inner = body:gsub("^%a+,?%s+", "")
  else
    local head, tail = body:match("^(.-)%s+[Ff]irst%s*([%.!]?%s*)$")
    if not head then head, tail = body:match("^(.-)%s+[Ff]irst(%s+[Ss]o%s.*)$") end
    if not head then head, tail = body:match("^(.-)%s+[Ff]irst(%s+[Bb]ecause%s.*)$") end
    if not head then head, tail = body:match("^(.-)%s+[Ff]irst(%s+to%s.*)$") end
    if not head then return nil end
    inner = head .. tail
  end
  local rest = text:sub(1, cut - 1):gsub("%s+[Bb]ut%s*$", ""):gsub("[%s,;]+$", "")
  if not rest:find("%a") or not inner:find("%a") then return nil end
  local fleet = {}
  for _, a in ipairs(world.aircraft or {}) do fleet[(a.id or ""):upper()] = true end
  local r1 = M.read_heard(inner, world)
  if r1.ask or #(r1.commands or {}) == 0 then return nil end
  for _, c in ipairs(r1.commands) do
    local name = c:match("^%u+")
    if name == "CRE" or name == "MCRE" then return nil end
    for w in c:gmatch("[^%s,;]+") do
      if fleet[w:upper()] then return nil end
    end
  end
  local r2 = M.read_heard(rest, world)
  if r2.ask or #(r2.commands or {}) == 0 then return nil end
  local out = {}
  for _, c in ipairs(r1.commands) do out[#out + 1] = c end
  for _, c in ipairs(r2.commands) do out[#out + 1] = c end
  return { commands = out, note = r2.note or r1.note, confirm_first = r1.confirm_first or r2.confirm_first }
end

return M
