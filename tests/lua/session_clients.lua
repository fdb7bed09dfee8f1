-- One session, several clients (`squawk serve` pages): a question raised by
-- one client is answered only by that client's next line; a line naming no
-- aircraft goes to the client's selected aircraft when it does not
-- translate by itself.
local session = require("translate.session")

do
  local s = session.new({ mode = "offline" })
  s:command("!CRE KL204 A320 52 4 90 FL250 280")
  s:command("!CRE AF123 A320 52 5 270 FL240 280")
  s:command("!CRE BAW31 A320 52.3 4.5 180 FL260 280")
  local a = s:command("KL204 descend", { client = "a" })
  check(a.ask ~= nil and a.ask:find("KL204", 1, true) ~= nil, tostring(a.ask))
  -- Client b's "flight level 100" is not an answer to a's question.
  local b = s:command("flight level 100", { client = "b" })
  check(b.ask == nil or not b.ask:find("KL204", 1, true), tostring(b.ask))
  check_eq(#b.commands, 0)
  check_eq(s.sim:get("KL204").sel_alt_ft, 25000)
  -- Client a's next line answers it.
  a = s:command("flight level 100", { client = "a" })
  check_eq(a.commands[1], "ALT KL204 FL100")
  -- b's own question stays b's: "cancel" from a has nothing of b's to drop.
  b = s:command("AF123 climb", { client = "b" })
  check(b.ask ~= nil, "AF123 climb asks")
  local c = s:command("cancel", { client = "a" })
  check(not c.cancelled, "a had nothing pending")
  b = s:command("flight level 300", { client = "b" })
  check_eq(b.commands[1], "ALT AF123 FL300")
  -- A line without a callsign goes to the selected aircraft.
  local r = s:command("turn left heading 200", { client = "a", selected = "BAW31" })
  check_eq(r.commands[1], "HDG BAW31 200 LEFT")
  check_eq(r.addressed, "BAW31")
  r = s:command("pause the simulation", { client = "a", selected = "BAW31" })
  check_eq(r.commands[1], "HOLD")
  check_eq(r.addressed, nil)
end

-- At most kMaxDialogues client dialogues: the one unheard from longest goes.
do
  local s = session.new({ mode = "offline" })
  s:command("!CRE KL204 A320 52 4 90 FL250 280")
  s:command("!CRE AF123 A320 52 5 270 FL240 280")
  check(s:command("KL204 descend", { client = "first" }).ask ~= nil, "first asks")
  for i = 1, session.kMaxDialogues do
    s:command("AF123 climb", { client = "c" .. i })
    if i == 1 then s:command("cancel", { client = "c1" }) end  -- c1 heard from after "first"
  end
  local n = 0
  for _ in pairs(s.dialogues) do n = n + 1 end
  check_eq(n, session.kMaxDialogues)
  check(s.dialogues.first == nil, "the quietest client's dialogue was forgotten")
  check(s.dialogues["c" .. session.kMaxDialogues] ~= nil and s.dialogues.c1 ~= nil, "the newer ones are kept")
end
