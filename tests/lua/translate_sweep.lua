-- A sweep of invented requests (templates over callsign forms, instructions, fillers, clauses and
-- punctuation) through the translation graph, offline. Every request gets commands, a question or a
-- note of what squawk does not simulate; no command names an aircraft the request does not name; and an
-- aircraft named only as traffic (a comparison, a reason, a place against it, what is not to change) is
-- never instructed.
local graph = require("translate.graph")

local sim = squawk.sim.new()
for _, line in ipairs({ "CRE KLM12 A320 52 4 090 FL200 250", "CRE EZY45 A319 52.2 4.2 090 FL180 250",
    "CRE IBE3142 A320 52.1 4.1 270 FL150 250", "DEFWPT HZA 52.3 4.6", "ADDWPT KLM12 HZA" }) do
  check(sim:exec(line), line)
end
-- each aircraft: the forms it is said in
local said = {
  KLM12 = { "KLM12", "klm 12", "KLM one two" },
  EZY45 = { "EZY45", "Easy 45", "easyJet four five" },
  IBE3142 = { "IBE3142", "Iberia 3142", "iberia three one four two" },
}
local instructions = { "climb to FL260", "descend and maintain flight level 110", "turn left heading 270",
  "reduce speed to 220 knots", "fly heading 045", "speed 240", "maintain 12000 feet" }
local fillers = { "", "please ", "ok ", "uh ", "now " }
-- clauses after the instruction naming the other aircraft ("%s"), which is never instructed
local traffic = { " to avoid %s", " because of %s", " behind %s", " as %s did", ", as did %s", " like %s",
  ", same as %s", " ahead of %s", " in front of %s", " below %s", " clear of %s", " instead of %s",
  ", keep %s as is", ", %s will follow", " so it clears %s", ", traffic is %s", " away from %s" }
-- (filler, callsign, instruction, clause; "V" puts the instruction's verb before the callsign)
local forms = { "%s%s %s%s", "%s%s, %s%s", "%sI want %s to %s%s", "V", "V" }

local function named(text, id)
  for _, form in ipairs(said[id]) do
    if text:lower():find(form:lower(), 1, true) then return true end
  end
  return false
end
local ids = { "KLM12", "EZY45", "IBE3142" }
local n, bad = 0, 0
for a = 1, 3 do
  for ti, clause in ipairs(traffic) do
    for ii, instr in ipairs(instructions) do
      local me, other = ids[a], ids[(a + ti) % 3 + 1]
      if other == me then other = ids[(a + ti + 1) % 3 + 1] end
      local form = forms[(ti + ii) % #forms + 1]
      local filler = fillers[(ti * 3 + ii) % #fillers + 1]
      local callsign, tail = said[me][(ii + a) % 3 + 1], string.format(clause, said[other][(ti + ii) % 3 + 1])
      local text
      if form == "V" then
        local verb, rest = instr:match("^(%S+) (.*)$")
        text = string.format("%s%s %s %s%s", filler, verb, callsign, rest, tail)
      else
        text = string.format(form, filler, callsign, instr, tail)
      end
      local r = graph.translate(text, { sim = sim, mode = "offline" })
      n = n + 1
      local cmds = table.concat(r.commands or {}, " ; ")
      local ok = r.ask ~= nil or cmds ~= "" or r.note ~= nil
      for id in cmds:gmatch("%u%u%u%d+") do
        if id == other or not named(text, id) then ok = false end
      end
      if not ok then bad = bad + 1 end
      check(ok, text .. " => " .. (r.ask and ("ASK " .. r.ask) or cmds))
    end
  end
end
check(n == 3 * #traffic * #instructions, "requests swept: " .. n)
check_eq(bad, 0)
