-- Word-level rewriting of a request before the grammar reads it.
local M = {}

-- `toks` are the words of `text` (split at spaces). at(i) -> replacement, next: tokens
-- i..next-1 become `replacement`; nil keeps token i. Returns the words joined by single
-- spaces where anything was rewritten, else `text` itself.
function M.rewrite(text, toks, at)
  local out, i = nil, 1  -- out: the words so far, from the first rewrite on
  while i <= #toks do
    local rep, nxt = at(i)
    if rep then
      out = out or table.move(toks, 1, i - 1, 1, {})
      out[#out + 1], i = rep, nxt
    else
      if out then out[#out + 1] = toks[i] end
      i = i + 1
    end
  end
  return out and table.concat(out, " ") or text
end

-- Splices `text` by byte positions, left to right. put(b, s, e) keeps text from where the last put
-- resumed (1 at first) up to b - 1, then s, and resumes at e; at() is that position; done() returns the
-- text spliced (`text` itself when nothing was put).
function M.splicer(text)
  local pieces, from = {}, 1
  local function put(b, s, e) pieces[#pieces + 1], from = text:sub(from, b - 1) .. s, e end
  local function done()
    if #pieces == 0 then return text end
    pieces[#pieces + 1] = text:sub(from)
    return table.concat(pieces)
  end
  return put, done, function() return from end
end

-- string.gsub(text, pattern, repl) run only where `lower`, text in lower case, holds `needle` (a pattern, or
-- a literal without magic characters, which string.find searches plainly): `needle` states what every match
-- of `pattern` holds in lower case, so a plain find stands in for a pattern scan of the whole text where it
-- is absent. Returns the text and its lower case, both current.
function M.gsub_where(text, lower, needle, pattern, repl)
  if not lower:find(needle) then return text, lower end
  local out = text:gsub(pattern, repl)
  if out == text then return text, lower end
  return out, out:lower()
end

-- A value's three digits said one by one and written as numerals apart ("heading 2 7 0", "flight level 1 9 0",
-- "2 niner zero"): a run of exactly three single digits, numerals or words of `digit_words` (a set of lower-case
-- words), one at least a numeral, is read as the digits said: its numerals are written as words, which the
-- extractors read as one value. Punctuation after a digit ends its run ("2 7 0, 3 ..."); "oh" is no digit here.
-- Runs of two or four ("reduce to 2 5", "2 5 0 0") stay as typed, for the grammar to read or ask.
local NUMERAL_WORDS = { ["0"] = "zero", ["1"] = "one", ["2"] = "two", ["3"] = "three", ["4"] = "four", ["5"] = "five",
                        ["6"] = "six", ["7"] = "seven", ["8"] = "eight", ["9"] = "nine" }
function M.numerals_apart(text, digit_words)
  if not text:find("%f[%w]%d%s+%w") then return text end
  local words = {}
  for space, w in text:gmatch("(%s*)(%S+)") do words[#words + 1] = { space = space, w = w } end
  -- the kind of digit word x is ("numeral" or "word"), or nil, and whether punctuation ends it
  local function digit(x)
    local d, tail = x.w:match("^(%d)([,.;:?!]?)$")
    if d then return "numeral", tail ~= "" end
    local word, wtail = x.w:match("^(%a+)([,.;:?!]?)$")
    if word and word:lower() ~= "oh" and digit_words[word:lower()] then return "word", wtail ~= "" end
  end
  local k = 1
  while k <= #words do
    local e, numerals, ends = k, 0, false
    while words[e] and not ends do
      local kind, stop = digit(words[e])
      if not kind then break end
      numerals, ends, e = numerals + (kind == "numeral" and 1 or 0), stop, e + 1
    end
    for x = k, (e - k == 3 and numerals >= 1) and e - 1 or 0 do
      words[x].w = words[x].w:gsub("^%d", NUMERAL_WORDS)
    end
    k = math.max(e, k + 1)
  end
  local out = {}
  for _, x in ipairs(words) do out[#out + 1] = x.space .. x.w end
  return table.concat(out) .. text:match("%s*$")
end

return M
