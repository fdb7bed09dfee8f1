-- Userdata safety (issue 12 point 1): metatables are locked, finalizers are
-- typed and run once, a finalized object answers every method with an error.
local s = squawk.sim.new{}
check_eq(getmetatable(s), "squawk.sim.Sim", "the metatable is hidden behind its name")
check(not pcall(setmetatable, s, {}), "a userdata's metatable cannot be replaced")
check_eq(type(getmetatable(s)), "string", "so __gc is out of reach")

-- Methods check the type of self: another class's object is an argument error.
local m = squawk.gpt2.load("tiny")
local ok, err = pcall(s.exec, m, "CRE KL2 B738 52 4 90 FL200 250")
check(not ok)
check(tostring(err):find("expected squawk.sim.Sim", 1, true) ~= nil, tostring(err))
ok, err = pcall(m.info, s)
check(not ok)
check(tostring(err):find("squawk.gpt2", 1, true) ~= nil, tostring(err))
ok = pcall(s.exec, {}, "CRE KL2 B738 52 4 90 FL200 250")
check(not ok, "a table is not a sim")

-- Resurrection: a finalizer that stores a collected sim in a global. The
-- sim's own finalizer has run by then; its methods must fail cleanly.
do
  local holder = setmetatable({ sim = squawk.sim.new{} }, {
    __gc = function(t) RESURRECTED = t.sim end,
  })
  holder.sim:exec("CRE KL2 B738 52 4 90 FL200 250")
  holder = nil
end
collectgarbage()
collectgarbage()
check(RESURRECTED ~= nil, "the finalizer ran")
ok, err = pcall(RESURRECTED.exec, RESURRECTED, "CRE KL3 B738 52 4 90 FL200 250")
check(not ok, "a method on a finalized sim is an error")
check(tostring(err):find("finalized", 1, true) ~= nil, tostring(err))
ok = pcall(RESURRECTED.count, RESURRECTED)
check(not ok)
ok = pcall(squawk.translate.offline, "KL2 climb FL300", RESURRECTED)
check(not ok, "a finalized sim is not a world either")
RESURRECTED = nil
collectgarbage()
-- The live objects still work.
check(s:exec("CRE KL2 B738 52 4 90 FL200 250"))
check_eq(s:count(), 1)
check_eq(m:info().n_layer, 2)
