-- The text rewriting helpers of translate/tokens.lua.
local tokens = require("translate.tokens")

-- gsub_where: the pass runs only where the lower-case copy holds the needle, and hands back the text and its
-- lower case, both current
local text = "Descend FL 2 4 0 then Angels 12"
local out, low = tokens.gsub_where(text, text:lower(), "angels", "[Aa]ngels (%d+)", "%1000 ft")
check_eq(out, "Descend FL 2 4 0 then 12000 ft")
check_eq(low, "descend fl 2 4 0 then 12000 ft")
-- (a needle absent from the lower-case copy skips the pass, even where the pattern would match the text)
out, low = tokens.gsub_where(text, "no such words", "angels", "[Aa]ngels (%d+)", "%1000 ft")
check_eq(out, text)
check_eq(low, "no such words")
-- (a needle that is a pattern: a digit, spaces and a digit)
out = tokens.gsub_where(text, text:lower(), "%d%s+%d", "(%d) (%d) (%d)", "%1%2%3")
check_eq(out, "Descend FL 240 then Angels 12")
-- (a pass that rewrites nothing leaves both as they were)
out, low = tokens.gsub_where(text, "descend (as passed)", "descend", "[Dd]escend", function() return nil end)
check_eq(out, text)
check_eq(low, "descend (as passed)")
