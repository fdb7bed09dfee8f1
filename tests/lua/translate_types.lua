-- Aircraft type names generated from the performance models' data and the
-- designators (translate/types.lua): every known designator is reachable by
-- itself and by the names its data or pattern gives.
local types = require("translate.types")
local names = require("translate.names")
local built = types.build(names.designators)
local tables = squawk.translate.tables({ airlines = names.airlines, types = built.types,
  designators = built.designators }, require("translate.lexicon"))
local function type_of(text)
  for _, r in ipairs(squawk.translate.utterance(types.join(text, built.phrases), nil, tables):refs()) do
    if r.kind == "type" then return r.name end
  end
  return nil
end

-- every designator the models know is reachable as typed (but those with no
-- digit, "ATP": an upper-case word of letters reads as a fix name)
local known = 0
for _, t in ipairs(squawk.sim.types()) do
  known = known + 1
  if t.designator:find("%d") then
    check_eq(type_of("create X1 " .. t.designator .. " at 52 4"), t.designator, t.designator)
  end
end
check(known >= 100, "the class model alone names over 100 designators, got " .. known)

-- names and variants by rule, with or without OpenAP data
for text, want in pairs({
  ["a Boeing 737-800"] = "B738", ["737-800"] = "B738", ["Boeing 737"] = "B737", ["747-400"] = "B744",
  ["Boeing 777-300ER"] = "B77W", ["787-9"] = "B789", ["a 737 MAX 8"] = "B38M", ["Boeing 737 max 9"] = "B39M",
  ["A321neo"] = "A21N", ["Airbus A330-200"] = "A332", ["A350-900"] = "A359", ["ATR 72-600"] = "AT76",
  ["Dash 8-400"] = "DH8D", ["Dash 8"] = "DH8D", ["Q400"] = "DH8D", ["Cessna 172"] = "C172", ["Embraer 190"] = "E190",
  ["CRJ900"] = "CRJ9", ["Airbus A220-300"] = "BCS3", ["an A220-100"] = "BCS1", ["Cirrus SR22"] = "SR22",
}) do
  check_eq(type_of("create X1 " .. text .. " at 52 4"), want, text)
end

-- with OpenAP data, its titles name their types too ("Embraer E175 (LR)" -> E75L)
local titled = false
for _, t in ipairs(squawk.sim.types()) do if t.title then titled = true end end
if titled then
  check_eq(type_of("create X1 Embraer E175 at 52 4"), "E75L")
  check_eq(type_of("create X1 Gulfstream G650 at 52 4"), "GLF6")
else
  print("skipped: OpenAP titles need OpenAP data (SQUAWK_OPENAP)")
end

-- a designator that is another's model name is read as that one, never written ("E175": the E75L); the
-- others of its maker are their own
check_eq(built.aliases.E175, "E75L")
for _, d in ipairs(built.designators) do check(d ~= "E175", "E175 is no designator of its own") end
for _, d in ipairs({ "E170", "E190", "E195", "E75L", "E75S" }) do check_eq(built.aliases[d], nil, d) end
check_eq(type_of("create X1 E175 at 52 4"), "E75L")
check_eq(type_of("create X1 Embraer 175 at 52 4"), "E75L")
check_eq(type_of("create X1 E190 at 52 4"), "E190")
