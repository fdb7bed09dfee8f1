-- The translation graph with a scripted stand-in LLM: node order, feedback
-- retries, the verifier's question, single-agent mode, and the fall-back to
-- the offline translator when the server fails.
local graph = require("translate.graph")
local nodes = require("translate.nodes")

-- A fake client: replies[i] answers the i-th chat call (nil, msg = failure).
local function fake_llm(replies)
  local llm = { prompts = {}, n = 0 }
  function llm:describe() return "fake llm" end
  function llm:chat(prompt)
    self.n = self.n + 1
    self.prompts[self.n] = prompt
    local r = replies[self.n]
    if r == false or r == nil then return nil, "fake server: HTTP 500: boom" end
    return r, { attempts = 1 }
  end
  return llm
end

local function path(trace)
  local names = {}
  for _, t in ipairs(trace) do names[#names + 1] = t.node end
  return table.concat(names, " ")
end

local sim = squawk.sim.new()
check(sim:exec("CRE KL204 A320 52 4 90 FL250 280"))

-- Helpers.
check_eq(nodes.boxed("so: \\boxed{ALT KL204 FL300} done"), "ALT KL204 FL300")
check_eq(nodes.boxed("\\boxed{a} then \\boxed{ HDG {x} 90 }"), "HDG {x} 90")
check_eq(nodes.boxed("no box"), nil)
check_eq(nodes.render("[${cmd}] \\boxed{command} ${missing}.", { cmd = "ALT" }), "[ALT] \\boxed{command} .")
check_eq(#nodes.split_commands("ALT A 1 ; ; HDG A 2 "), 2)

-- Multi-agent: select, verify YES, fill with a bad value, feedback, fixed.
do
  local llm = fake_llm({ "\\boxed{ALT}", "YES", "\\boxed{ALT KL204 FL9X}", "\\boxed{ALT KL204 FL300}" })
  local r = graph.translate("climb KL204 to flight level 300", { sim = sim, llm = llm, mode = "multi" })
  check_eq(r.mode, "multi")
  check_eq(r.commands and r.commands[1], "ALT KL204 FL300")
  check_eq(r.error, nil)
  check_eq(llm.n, 4)
  check_eq(path(r.trace), "start retrieve select select verify fill fill validate fill fill validate execute")
  check(llm.prompts[4]:find("FL9X", 1, true) ~= nil, "the retry prompt quotes the failed attempt")
  check(llm.prompts[4]:find("rejected it with this error", 1, true) ~= nil, "the retry prompt carries the error")
  check(llm.prompts[1]:find("\\boxed{CRE}", 1, true) ~= nil, "the selector prompt is the paper's")
  check_eq(sim:get("KL204").alt_ft > 24000 and sim:get("KL204").alt_ft < 26000, true, "the real sim is untouched")
end

-- Multi-agent: the verifier says NO -> a question, no command.
do
  local llm = fake_llm({ "\\boxed{ADDWPT}", "NO" })
  local r = graph.translate("add a waypoint for KL204", { sim = sim, llm = llm, mode = "multi" })
  check(r.ask ~= nil and r.ask:find("ADDWPT", 1, true) ~= nil, "asks about ADDWPT")
  check_eq(r.commands, nil)
end

-- Retries are capped: always wrong -> error after max_retries feedback rounds.
do
  local bad = {}
  for i = 1, 10 do bad[i] = i == 1 and "\\boxed{HDG}" or (i == 2 and "YES" or "\\boxed{HDG KL204 north-ish}") end
  local llm = fake_llm(bad)
  local r = graph.translate("turn KL204 north", { sim = sim, llm = llm, mode = "multi", max_retries = 2 })
  check(r.error ~= nil, "gives up with an error")
  check_eq(llm.n, 2 + 3)
end

-- Single-agent mode: one call, then validate and execute.
do
  local llm = fake_llm({ "Sure. \\boxed{HDG KL204 270}" })
  local r = graph.translate("turn KL204 west", { sim = sim, llm = llm, mode = "single" })
  check_eq(r.commands and r.commands[1], "HDG KL204 270")
  check_eq(path(r.trace), "start retrieve single single validate execute")
  check(llm.prompts[1]:find("KL204 A320", 1, true) ~= nil, "the prompt lists the traffic")
end

-- A failing server: the offline translator answers, and the trace says why.
do
  local llm = fake_llm({ false })
  local r = graph.translate("turn KL204 left heading 180", { sim = sim, llm = llm, mode = "multi" })
  check_eq(r.commands and r.commands[1], "HDG KL204 180 LEFT")
  check(path(r.trace):find("select offline validate execute", 1, true) ~= nil, path(r.trace))
  check(graph.format_trace(r.trace):find("HTTP 500: boom", 1, true) ~= nil)
end

-- No LLM at all: the offline graph, with setup run on a fresh sim.
do
  local r = graph.translate("Lower the altitude of Conflict1 to around 27000 feet",
    { mode = "offline", setup = "CRE Conflict1 A320 52.0 4.0 90 FL300 280" })
  check_eq(r.commands and r.commands[1]:upper(), "ALT CONFLICT1 27000")
  check_eq(r.mode, "offline")
end

-- Bad mode names are errors that say what is allowed.
local ok, msg = pcall(graph.translate, "x", { mode = "triple" })
check(not ok and msg:find("offline, single, multi", 1, true) ~= nil)

-- The prompt file loads through squawk.load_config and holds the templates.
local p = squawk.load_config("prompts/translator.lua")
for _, k in ipairs({ "verifier", "selector", "parameters", "single", "feedback", "ask" }) do
  check_eq(type(p[k]), "string", k)
end

-- Multi-agent without the verifier (the paper's evaluated pipeline).
do
  local llm = fake_llm({ "\\boxed{SPD}", "\\boxed{SPD KL204 250}" })
  local r = graph.translate("slow KL204 to 250 knots", { sim = sim, llm = llm, mode = "multi", verify = false })
  check_eq(r.commands and r.commands[1], "SPD KL204 250")
  check_eq(path(r.trace), "start retrieve select select fill fill validate execute")
end

-- A command that parses but that the simulator refuses when it runs is the
-- translation, not a question: "load scenario nothere.scn" is IC nothere.scn
-- (which, replacing the traffic, waits for a yes), and the missing file is what
-- running it reports. A command that does not parse is still no translation (an
-- LLM with retries left is sent back).
do
  local function on_yes(r) return r.confirm and r.confirm.commands and r.confirm.commands[1] end
  local r = graph.translate("load scenario nothere.scn", { sim = sim, mode = "offline" })
  check_eq(on_yes(r), "IC nothere.scn")
  check(r.ask and r.ask:find("yes or no", 1, true) ~= nil, "IC asks first")
  check_eq(r.error, nil)
  check(graph.format_trace(r.trace):find("the simulator will refuse it: IC nothere.scn: no scenario file", 1, true)
    ~= nil, "the trace names the refusal")
  local llm = fake_llm({ "\\boxed{IC nothere.scn}", "\\boxed{IC nothere.scn}" })
  r = graph.translate("load scenario nothere.scn", { sim = sim, llm = llm, mode = "single", max_retries = 1 })
  check_eq(llm.n, 2, "the LLM was given one retry with the refusal")
  check_eq(on_yes(r), "IC nothere.scn")
  r = graph.translate("KL204 direct QQXQQ", { sim = sim, mode = "offline" })
  -- (with navdata the name is asked about first, G:unknown_places; without, the simulator refuses the direct)
  check(r.error ~= nil or (r.ask ~= nil and #(r.commands or {}) == 0), "an unknown fix does not parse: no translation")
end
