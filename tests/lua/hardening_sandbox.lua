-- The read sandbox and io.open's results (issue 12 points 5 and 8).
local here = arg[0]:match("^(.*)/[^/]*$") or "."

-- Point 8: io.open without a mode returns the file, and (nil, msg, errno) on failure.
local f, msg = io.open(arg[0])
check(io.type(f) == "file", "io.open(path) returns a file: " .. tostring(f) .. " " .. tostring(msg))
check_eq(f:read("l"), "-- The read sandbox and io.open's results (issue 12 points 5 and 8).")
f:close()
local none, err, code = io.open(here .. "/no_such_file.txt")
check_eq(none, nil)
check(tostring(err):find("no_such_file", 1, true) ~= nil, tostring(err))
check_eq(math.type(code), "integer")
check(io.type(io.open(arg[0], "r")) == "file")

-- Point 5: reads outside the script's folder and squawk's folders are refused.
for _, path in ipairs({ "/etc/passwd", "/etc/shadow", here .. "/../../../../../etc/passwd", "/proc/self/environ" }) do
  local ok, e = pcall(io.open, path)
  check(not ok, "io.open " .. path)
  check(tostring(e):find("is not allowed", 1, true) ~= nil, tostring(e))
  ok = pcall(io.lines, path)
  check(not ok, "io.lines " .. path)
  ok = pcall(io.input, path)
  check(not ok, "io.input " .. path)
end
check(io.open("scenarios/horizontal_cr.lua") ~= nil, "the shipped scenarios are readable")
check(io.open("prompts/observation.lua") ~= nil, "the shipped prompts are readable")
-- Point 5: the environment is an allow-list.
check_eq(os.getenv("HOME"), nil)
check_eq(os.getenv("PATH"), nil)
check_eq(os.getenv("SQUAWK_LLM_API_KEY"), nil)
-- Point 5: the bindings that open files follow the same rule.
local s = squawk.sim.new{}
local ok, e = s:exec("IC /etc/passwd")
check(not ok and e:find("not allowed", 1, true) ~= nil, tostring(e))
ok, e = s:exec("PCALL /etc/passwd")
check(not ok and e:find("not allowed", 1, true) ~= nil, tostring(e))
ok, e = s:load("/etc/passwd")
check(not ok and e:find("not allowed", 1, true) ~= nil, tostring(e))
for _, f in ipairs({
  function() return squawk.env.new("/etc/passwd") end,
  function() return squawk.env.evaluate{ scenario = "/etc/passwd" } end,
  function() return squawk.env.evaluate{ scenario = "scenarios/horizontal_cr.lua", checkpoint = "/etc/passwd" } end,
  function() return squawk.translate.corpus("/etc/passwd") end,
  function() return squawk.gpt2.load("/etc") end,
}) do
  ok, e = pcall(f)
  check(not ok and tostring(e):find("not allowed", 1, true) ~= nil, tostring(e))
end
