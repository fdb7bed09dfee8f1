-- Typing slips in a request the grammar asked about (translate/grammar.lua's M.translate), read again.
--
-- reread(text, world, asked, read) -> a translation: `asked` is read(text, world)'s answer, an ask; read is the
-- grammar's own reading (text, world) -> { commands =, ask =, ... }. The words of text that no list of squawk
-- knows (KNOWN: every word of translate/lexicon.lua and translate/names.lua, the registry's names and aliases)
-- and that a slip of the fingers makes of an instruction word are read again as the words they may be:
--   - one edit (a letter left out, added, changed, or two neighbouring letters swapped) from an instruction word
--     (lexicon.spelling.targets, lexicon.typo_targets) that begins with its letter, or with its first two letters
--     swapped ("nad": and; "unable" is no "enable"): every known word one edit from it is a reading of it ("tun":
--     turn, run, fun, trn, un);
--   - two known words typed with no space between, one an instruction word, six letters in all ("turnright",
--     "leftheading"): those two words.
-- A word holding a digit or a capital after its first letter, a flying aircraft's id or its airline's letters, and
-- a fix, navaid or airport the navdata holds near the traffic (world.place_known) are never such a slip.
-- Only a request whose question names the one word it did not read ("What does 'tun' mean?") is read again, for that
-- word, or one of which nothing was understood (M.not_understood, set by the grammar), for each word, or one asked
-- anything else that holds one unknown word alone ("descend levle 90", asked about its value), for that word. Two
-- unknown words with one space between that join into a known word ("say alti tude") are read joined.
-- Each reading of the slips (at most MAX_READINGS) is translated; when those that issue commands with nothing
-- asked all issue the same ones, one of them reading every slip as an instruction word, that is the answer;
-- otherwise (none, two that differ, or only a word of no instruction read: "abd 250" read as "abv 250") `asked`
-- stands, naming the word as typed. Only an ask comes here, and a word is searched only when KNOWN lacks it.
local lexicon = require("translate.lexicon")
local names = require("translate.names")

local M = {}

local MAX_READINGS = 8
local LETTERS = "abcdefghijklmnopqrstuvwxyz"

-- KNOWN: word -> true (lower case letters), built once; CODES: those that are written in capitals in
-- translate/names.lua (an airline's ICAO letters, a designator), never read alone as a slip's reading (an airline
-- without its flight number is asked)
local KNOWN, CODES = {}, {}
-- LEXICON_WORDS: the words of translate/lexicon.lua alone (no name of names.lua), lower case
local LEXICON_WORDS = {}
do
  -- (lexicon.discourse_words are no words of English a slip could be read as: read by role or left as said)
  local seen = { [lexicon.discourse_words] = true }
  local function walk(t, codes)
    if seen[t] then return end
    seen[t] = true
    for k, v in pairs(t) do
      if type(k) == "string" then
        for w in k:lower():gmatch("%a+") do KNOWN[w] = true end
      end
      if type(v) == "string" then
        for w in v:lower():gmatch("%a+") do KNOWN[w] = true end
        if codes and v:match("^%u+$") then CODES[v:lower()] = true end
      elseif type(v) == "table" then
        walk(v, codes)
      end
    end
  end
  walk(lexicon, false)
  for w in pairs(KNOWN) do LEXICON_WORDS[w] = true end
  walk(names, true)
  -- (number words, which the lexer reads, not the lexicon)
  local numbers = "zero one two three four five six seven eight nine niner ten eleven twelve thirteen fourteen "
    .. "fifteen sixteen seventeen eighteen nineteen twenty thirty forty fifty sixty seventy eighty ninety hundred "
    .. "thousand"
  for w in numbers:gmatch("%a+") do
    KNOWN[w] = true
  end
  for _, c in ipairs(squawk.sim.commands()) do
    KNOWN[c.name:lower()] = true
    for _, a in ipairs(c.aliases or {}) do KNOWN[a:lower()] = true end
  end
end
-- True when the lower-case word w is a word of translate/lexicon.lua ("trial", "turn"), as against a name only
function M.lexicon_word(w) return LEXICON_WORDS[w] == true end
-- TARGETS: the instruction words a slip is read as, three letters or more
local TARGETS = {}
for _, w in ipairs(lexicon.spelling.targets) do TARGETS[w] = true end
for _, w in ipairs(lexicon.typo_targets) do TARGETS[w] = true end

-- The words one edit from w (each once), w itself left out.
local function edits(w)
  local out, seen = {}, { [w] = true }
  local function add(e)
    if not seen[e] then out[#out + 1], seen[e] = e, true end
  end
  for i = 1, #w do add(w:sub(1, i - 1) .. w:sub(i + 1)) end
  for i = 1, #w - 1 do add(w:sub(1, i - 1) .. w:sub(i + 1, i + 1) .. w:sub(i, i) .. w:sub(i + 2)) end
  for i = 1, #w + 1 do
    for c in LETTERS:gmatch(".") do
      if i <= #w then add(w:sub(1, i - 1) .. c .. w:sub(i + 1)) end
      add(w:sub(1, i - 1) .. c .. w:sub(i))
    end
  end
  return out
end

-- DELETED: each instruction word of three letters or more, and each with one letter left out (built once): a
-- word one edit from such a word is in it, or is with one letter of its own left out
local DELETED = {}
for t in pairs(TARGETS) do
  if #t >= 3 then
    DELETED[t] = true
    for i = 1, #t do DELETED[t:sub(1, i - 1) .. t:sub(i + 1)] = true end
  end
end
local function near_target(w)
  if DELETED[w] then return true end
  for i = 1, #w do
    if DELETED[w:sub(1, i - 1) .. w:sub(i + 1)] then return true end
  end
  return false
end

-- The reading of the unknown word w (lower case) as two known words typed with no space between, one an instruction
-- word, six letters in all ("turnright"): { { word = "turn right", instruction = true } }, else empty.
function M.apart(w)
  for k = 2, #w >= 6 and #w - 2 or 0 do
    local a, b = w:sub(1, k), w:sub(k + 1)
    if KNOWN[a] and KNOWN[b] and (TARGETS[a] or TARGETS[b]) then
      return { { word = a .. " " .. b, instruction = true } }
    end
  end
  return {}
end

-- The readings of the unknown word w (lower case): a list of { word =, instruction = true when it is the
-- instruction word the slip was searched for, or two words apart }, empty when w is no slip.
local function readings(w)
  if #w < 3 or #w > 20 then return {} end
  if not near_target(w) then return M.apart(w) end
  local near, target = {}, false
  for _, e in ipairs(edits(w)) do
    -- (an accent's form, lexicon.accented's "tuhn", is what a recogniser writes, never what a slip of the fingers
    -- means: "tun" is no "tuhn")
    if KNOWN[e] and not CODES[e] and not lexicon.accented[e] then
      -- (the instruction word begins as w does, or with its first two letters swapped: "nad" and)
      local instruction = #e >= 3 and TARGETS[e] == true
        and (e:sub(1, 1) == w:sub(1, 1) or e:sub(1, 2) == w:sub(2, 2) .. w:sub(1, 1))
      near[#near + 1] = { word = e, instruction = instruction }
      target = target or instruction
    end
  end
  return target and near or {}
end

-- True when the word (as typed) may be a name: an aircraft's id or its airline's letters, a place near traffic,
-- or a name heard for a waypoint of a flying aircraft's route (the same letters or the same sound:
-- squawk.translate.best_match at lexicon.waypoint_confirm, "macy" for MACEY), which the grammar confirms.
local function named(w, world)
  local lw = w:lower()
  for _, a in ipairs(world.aircraft or {}) do
    local id = (a.id or ""):lower()
    if id == lw or id:match("^%a+") == lw then return true end
    local _, score = squawk.translate.best_match(lw, a.route or {})
    if score and score >= lexicon.waypoint_confirm then return true end
  end
  local lat, lon
  if world.place_known then lat, lon = world.place_known(w:upper()) end
  if not lat then return false end
  for _, a in ipairs(world.aircraft or {}) do
    local dlat, dlon = lat - (a.lat or 0), (lon - (a.lon or 0)) * math.cos(math.rad(lat))
    if a.lat and 60 * math.sqrt(dlat * dlat + dlon * dlon) <= lexicon.typo_place_nm then return true end
  end
  return #(world.aircraft or {}) == 0
end

function M.reread(text, world, asked, read)
  -- (the word asked about, "What does 'tun' mean?", or any word where nothing was understood; besides the word asked about, and with any other question, only two known words typed or heard with no space
  -- between, "descendto one zero thousand reduce speed 250", whose question named what the unread verb left: read
  -- apart, the same agreement asked of the readings)
  -- (with any other question, one unknown word alone in the request is read too: "descend levle 90", asked about
  -- its value, read "level")
  local named_word = asked.ask:match("What does '(%a+)' mean%?$")
  local glued_only = not named_word and asked.ask ~= M.not_understood
  -- unknown: { b =, e = (the word's bytes in text), w = } of each word no list knows
  local unknown = {}
  for b, w, e in text:gmatch("()(%a+)()") do
    local before, after = text:sub(b - 1, b - 1), text:sub(e, e)
    if not KNOWN[w:lower()] and not w:sub(2):find("%u")
        and not before:find("[%w%.%-_/]") and not after:find("[%w%.%-_/']") and not named(w, world) then
      unknown[#unknown + 1] = { b = b, e = e, w = w:lower() }
    end
  end
  -- slips: { b =, e =, options = { readings } }
  local slips = {}
  -- (two unknown words with one space between that join into a known word: a word a recogniser split, "say alti
  -- tude", read joined, both words one slip)
  local k = 1
  while k < #unknown do
    local a, b = unknown[k], unknown[k + 1]
    if b.b == a.e + 1 and KNOWN[a.w .. b.w] and not CODES[a.w .. b.w] then
      slips[#slips + 1] = { b = a.b, e = b.e, options = { { word = a.w .. b.w, instruction = true } } }
      table.remove(unknown, k + 1)
      table.remove(unknown, k)
    else
      k = k + 1
    end
  end
  for _, u in ipairs(unknown) do
    local lw = u.w
    local only_glued = (glued_only and #unknown > 1) or (named_word ~= nil and named_word:lower() ~= lw)
    local options = only_glued and (#lw <= 20 and M.apart(lw) or {}) or readings(lw)
    -- (that lone word, under another question, only where one reading is an instruction word: one reading more)
    if glued_only and not only_glued then
      local instruction = {}
      for _, o in ipairs(options) do
        if o.instruction then instruction[#instruction + 1] = o end
      end
      options = #instruction == 1 and instruction or M.apart(lw)
    end
    if #options > 0 then slips[#slips + 1] = { b = u.b, e = u.e, options = options } end
  end
  if #slips == 0 then return asked end
  table.sort(slips, function(x, y) return x.b < y.b end)
  local n = 1
  for _, s in ipairs(slips) do n = n * #s.options end
  if n > MAX_READINGS then return asked end
  local agreed, instructed
  for k = 0, n - 1 do
    local parts, at, rest, all_targets = {}, 1, k, true
    for _, s in ipairs(slips) do
      local option = s.options[rest % #s.options + 1]
      parts[#parts + 1] = text:sub(at, s.b - 1)
      parts[#parts + 1] = option.word
      all_targets = all_targets and option.instruction
      rest, at = rest // #s.options, s.e
    end
    parts[#parts + 1] = text:sub(at)
    local r = read(table.concat(parts), world)
    if not r.ask and r.commands and #r.commands > 0 then
      local said = table.concat(r.commands, " ; ")
      if agreed and agreed.said ~= said then return asked end
      agreed, instructed = agreed or { said = said, r = r }, instructed or all_targets
    end
  end
  return instructed and agreed.r or asked
end

return M
