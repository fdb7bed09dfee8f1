-- squawk.rag and the non-network parts of squawk.llm / squawk.load_config.

-- Retrieval over the registry documentation, with and without notes.
local idx = squawk.rag.index({ docs = require("translate.grammar").documents() })
check(idx:size() > 20, "one document per command")
local hits = idx:search("climb and maintain flight level 300", 3)
check_eq(hits[1].command, "ALT")
check(hits[1].score > 0 and hits[1].text:find("ALT", 1, true) ~= nil)
check_eq(idx:search("tunr left heding 270", 1)[1].command, "HDG", "typing slips still retrieve")
check_eq(#idx:search("", 5), 0)

local plain = squawk.rag.index({ docs = { { command = "HDG", text = "qqzzyx vectoring" } } })
check_eq(plain:search("qqzzyx", 1)[1].command, "HDG", "extra docs attach to their command")
check(not pcall(squawk.rag.index, { notes = "/nonexistent/notes.txt" }), "a missing notes file is an error")
check(not pcall(idx.search, idx, "x", 0), "k must be positive")

-- Clients: configuration errors are raised with what was expected.
local ok, msg = pcall(squawk.llm.client, { url = "localhost:11434", model = "m" })
check(not ok and msg:find("http://", 1, true) ~= nil, msg)
ok, msg = pcall(squawk.llm.client, { url = "http://127.0.0.1:11434", model = "m", api = "grpc" })
check(not ok and msg:find("ollama, openai", 1, true) ~= nil, msg)
local c = squawk.llm.client({ url = "http://127.0.0.1:8080/v1", model = "qwen2.5:7b" })
check_eq(c:describe(), "openai server http://127.0.0.1:8080/v1 (model qwen2.5:7b)")

-- load_config: a table from a Lua file, relative to squawk.home.
local prompts = squawk.load_config("prompts/translator.lua")
check(prompts.selector:find("\\boxed{CRE}", 1, true) ~= nil)
ok, msg = pcall(squawk.load_config, "prompts/does_not_exist.lua")
check(not ok and msg:find("does_not_exist", 1, true) ~= nil, msg)
