-- squawk.gpt2 on the seeded tiny model (byte-level vocabulary).
local m = squawk.gpt2.load("tiny", 3)
local info = m:info()
check_eq(info.n_layer, 2)
check_eq(info.n_embd, 64)
check_eq(info.vocab_size, 257)

-- Byte-level ids follow GPT-2's byte order: "!" is 0, "A" is 32.
local ids = m:encode("A!")
check_eq(#ids, 2)
check_eq(ids[1], 32)
check_eq(ids[2], 0)
local text = "Turn left heading 270, descend FL120 \u{00e9}\u{65e5}"
check_eq(m:decode(m:encode(text)), text)

-- Last-position logits: one per vocabulary entry; the hidden state is C wide.
local logits = m:logits("climb")
check_eq(#logits, 257)
local h = m:hidden({ m:encode("climb"), m:encode("descend now") })
check_eq(#h, 2)
check_eq(#h[1], 64)

-- Greedy generation is reproducible and respects max_tokens.
local g1 = m:generate("KLM204 ", { max_tokens = 8, top_k = 1 })
local g2 = m:generate("KLM204 ", { max_tokens = 8, top_k = 1 })
check_eq(g1, g2)
check(#g1 <= 8 * 4, "at most 8 tokens of at most 4 bytes")

-- Errors are Lua errors that name the problem.
local ok, err = pcall(m.decode, m, { 300 })
check(not ok)
check(tostring(err):find("not in the vocabulary", 1, true) ~= nil)
ok, err = pcall(squawk.gpt2.load, "models/no/such/folder")
check(not ok)
check(tostring(err):find("config.json", 1, true) ~= nil)
ok, err = pcall(m.generate, m, "x", { top_k = 0 })
check(not ok)
check(tostring(err):find("top_k", 1, true) ~= nil)
ok = pcall(m.generate, m, "x", { seed = -1 })
check(not ok)
ok = pcall(m.hidden, m, {})
check(not ok)
