-- Advisory phrasing for the team demo (`squawk demo`): the deconfliction
-- agent's decision, said the way a controller would say it. The translator
-- then turns this English into TrafScript, so edit freely and watch it cope.
--
-- advise(d) is called once per agent decision with:
--   d.callsign         ownship callsign, e.g. "KL001"
--   d.action           the agent's action in [-1, 1] (units of 45 deg)
--   d.heading          the heading to fly [deg], an integer in 1..360
--   d.current_heading  the ownship's heading now [deg]
--   d.turn             "left", "right" or "none"
--   d.traffic          the nearest intruder in conflict, or nil:
--                      { id = "3", clock = 2, distance_nm = 6.4 }
-- It returns one line of English.

local M = {}

local function heading3(h)
  return string.format("%03d", math.floor(h + 0.5) % 360 == 0 and 360 or math.floor(h + 0.5) % 360)
end

function M.advise(d)
  local s
  if d.turn == "none" then
    s = d.callsign .. ", continue heading " .. heading3(d.heading)
  else
    s = d.callsign .. ", turn " .. d.turn .. " heading " .. heading3(d.heading)
  end
  if d.traffic then
    s = s .. string.format(", traffic %d o'clock, %.0f miles", d.traffic.clock, d.traffic.distance_nm)
  end
  return s
end

return M
