-- Runs every probe of docs/sandbox_audit.md's path table (probes.lua, written
-- by tests/hardening/paths.sh beside this file) with every hostile path of its
-- kind; arg[1] is the folder paths.sh built. Prints "ok"/"FAIL" per pair.
local t = arg[1]
local s = t .. "/script"
local cases = {
  file = { s .. "/link_file", s .. "/link_dir/secret.txt", s .. "/../secret/secret.txt",
           s .. "/inner/leak", s .. "/link_dir/sub/../secret.txt", "/proc/self/environ",
           "/dev/stdin", s .. "/dangling" },
  folder = { s .. "/link_dir", s .. "/../secret", s .. "/inner", "/proc/self", s .. "/dangling",
             s .. "/link_dir/sub" },
  write = { t .. "/out/dangling_w", t .. "/out/link_dir_w/x.txt", t .. "/out/../secret/x.txt",
            t .. "/out/dangling_rel", "/proc/self/fd/1", s .. "/written_outside.txt" },
  module = { "req_link", "req_dir" },
  checkpoint = { s .. "/evil.ckpt" },
}
local probes = require("probes")
local fails = 0
for _, p in ipairs(probes) do
  local list = cases[p.kind]
  check(list ~= nil, p.api .. ": unknown kind " .. tostring(p.kind))
  for _, path in ipairs(list or {}) do
    local ok, r1, r2 = pcall(p.probe, path)
    local msg = ok and (not r1 and tostring(r2)) or (not ok and tostring(r1)) or nil
    local want = p.kind == "checkpoint" and "checkpoint's prompt file" or "not allowed"
    if msg and msg:find("not allowed", 1, true) and msg:find(want, 1, true) then
      print(("ok   %s refuses %s"):format(p.api, path))
    else
      fails = fails + 1
      print(("FAIL %s accepted %s: %s"):format(p.api, path, tostring(msg or r1)))
    end
  end
end
-- The checks are not blanket refusals: the same APIs take the sandbox's own files.
check(io.open(s .. "/walker.lua") ~= nil, "a file in the script's folder is readable")
local w = assert(io.open(t .. "/out/fine.txt", "w"))
w:write("fine")
w:close()
check(io.open("scenarios/horizontal_cr.lua") ~= nil, "the shipped scenarios are readable")
check(fails == 0, fails .. " paths outside the sandbox were accepted")
