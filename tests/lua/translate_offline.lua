-- squawk.translate: the one path (run), the C++ extractors the grammar reads
-- (utterance) and the corpus scorer.
local tr = squawk.translate

-- run() is the graph: commands validated on a scratch copy, the sim only read.
local sim = squawk.sim.new()
check(sim:exec("CRE DAL1153 B738 40 -74 90 5000 250"))
local r = tr.run("Delta eleven fifty three turn left twenty degrees", { sim = sim, mode = "offline" })
check_eq(r.commands[1], "HDG DAL1153 70 LEFT")
check_eq(r.mode, "offline")
check_eq(sim:aircraft()[1].hdg_deg, 90, "the sim is only read")
r = tr.run("turn AC01 left 20 degrees", { mode = "offline" })
check(r.ask ~= nil and r.commands == nil, "a relative turn without traffic asks")

-- The extractors: tokens, names and typed quantities, ranges 1-based [b, e).
local names = tr.tables(require("translate.names"), require("translate.lexicon"))
local u = tr.utterance("KLM123 climb flight level three five zero, then 250 kts", nil, names)
local toks = u:tokens()
check_eq(toks[1].raw, "KLM123")
check_eq(toks[2].text, "climb")
check_eq(toks[5].number_word, true)
local refs = u:refs()
check_eq(refs[1].kind, "aircraft")
check_eq(refs[1].name, "KLM123")
check_eq(refs[1].b, 1)
check_eq(refs[1].e, 2)
local qs = u:quantities(1, #toks + 1)
check_eq(qs[1].kind, "alt")
check_eq(qs[1].value, 35000)
check_eq(qs[1].fl, true)
check_eq(qs[2].kind, "speed")
check_eq(qs[2].value, 250)
u:mark_used(qs[1].b, qs[1].e)
check_eq(u:used(qs[1].b), true)
check_eq(#u:quantities(1, #toks + 1), 1, "used tokens are skipped")
check_eq(u:number(5, 8).value, 350)
check_eq(u:number(4, 8), nil, "a range that is not one number")
check(not pcall(tr.utterance, "climb", { aircraft = { { type = "A320" } } }, names), "an aircraft without id is an error")
check(not pcall(tr.utterance, "climb", 42, names), "a number is no world")
check(not pcall(tr.utterance, "climb"), "the name tables are required")
-- The shipped names (scripts/translate/names.lua) reach the matchers.
local function ref(text) return tr.utterance(text, nil, names):refs()[1] end
check_eq(ref("speedbird one two three climb").name, "BAW123")
check_eq(ref("add a Boeing 737-800").name, "B738")
check_eq(ref("shamrock four five kilo").name, "EIN45K")
check(not pcall(tr.tables, { airlines = { { "x" } } }, require("translate.lexicon")), "an airline row needs telephony and icao")
check(not pcall(tr.tables, require("translate.names"), {}), "the lexicon needs its word lists")
-- Spelling fixes (lexicon.spelling) reach instruction words only.
local function word(text) return tr.utterance(text, nil, names):tokens()[1].text end
check_eq(word("heding"), "heading")
check_eq(word("tunr"), "turn")
check_eq(word("kots"), "knots")
check_eq(word("dleete"), "delete")
check_eq(word("detction"), "detection")
check_eq(word("train"), "train", "everyday words stay")
check_eq(word("send"), "send")
local idx, score = tr.best_match("gale", { "ABC", "GAYEL" })
check_eq(idx, 2)
check(score > 0.5)

-- The scorer follows the corpus rules.
check(tr.score("ALT KL1 30000", false, "ALT KL1 FL300"))
check(tr.score("", true, "ASK"))
check(not tr.score("SPD KL1 250", false, "SPD KL1 M0.78"))
check(not pcall(tr.corpus, "/nonexistent/corpus.tsv"), "a missing corpus is an error")
