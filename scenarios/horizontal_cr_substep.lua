-- The paper scenario (horizontal_cr.lua) with one change: Eq. 2's "intrusion
-- detected" also fires when an intruder was inside the 5 NM zone at any 5 s
-- sub-step of the 50 s step, not only at its end, so the reward sees every
-- intrusion that success counts. A training variant; evaluate on
-- horizontal_cr.lua to compare with Table 3.
local s = require("horizontal_cr")
s.reward.intrusion_at = "substep"
return s
