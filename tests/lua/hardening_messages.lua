-- Error messages name the function and show numbers as numbers (issue 12 point 18).
local s = squawk.sim.new{}
local ok, err = pcall(s.exec, {}, "ECHO x")
check(not ok)
check(tostring(err):find("'squawk.sim.Sim:exec'", 1, true) ~= nil, tostring(err))
ok, err = pcall(squawk.sim.new, 5)
check(tostring(err):find("'squawk.sim.new'", 1, true) ~= nil, tostring(err))
local names = squawk.translate.tables(require("translate.names"), require("translate.lexicon"))
ok, err = pcall(squawk.translate.utterance, "KL1 climb FL300", { aircraft = { { id = "KL1", alt_ft = 1e308 } } }, names)
check(not ok and tostring(err):find("field 'alt_ft': expected a number in [-2000, 100000], got 1e+308", 1, true) ~= nil, tostring(err))
ok, err = pcall(squawk.translate.utterance, "KL1 turn left heading 270", { aircraft = { { id = "KL1", hdg_deg = 0 / 0 } } }, names)
check(not ok and tostring(err):find("got NaN", 1, true) ~= nil, tostring(err))
-- Absurd values heard in a request are asked about, never printed as wrapped integers or NaN.
s:exec("CRE KL1 B738 52 4 90 FL200 250")
for _, text in ipairs { "KL1 climb to flight level 99999999999999999999", "KL1 turn left heading 1e308",
                        "KL1 increase speed by 1e308 knots" } do
  local r = squawk.translate.run(text, { sim = s })
  check(r.ask ~= nil and r.commands == nil, text)
  check(not tostring(r.ask):find("9223372036854775808", 1, true) and not tostring(r.ask):find("nan"), tostring(r.ask))
end
ok, err = pcall(squawk.env.evaluate, { scenario = "scenarios/horizontal_cr.lua", episodes = 0 / 0 })
check(not ok and tostring(err):find("got NaN", 1, true) ~= nil, tostring(err))
check(tostring(err):find("-9223372036854775808", 1, true) == nil)
