-- Observation prompt for the GPT-2 deconfliction policy (paper §III.C.3).
--
-- The engine calls render(obs) once per decision. `obs` holds the eight named
-- fields of the HorizontalCR observation, each an array of numbers (the same
-- table squawk.env's env:observation() returns):
--   obs.intruder_distance    [5]  distance to each intruder / 150 km
--   obs.cos_difference_pos   [5]  cos of (heading - bearing to intruder)
--   obs.sin_difference_pos   [5]  sin of the same angle
--   obs.x_difference_speed   [5]  relative speed, x component / 150 m/s
--   obs.y_difference_speed   [5]  relative speed, y component / 150 m/s
--   obs.waypoint_distance    [1]  distance to the waypoint / 150 km
--   obs.cos_drift            [1]  cos of (heading - bearing to waypoint)
--   obs.sin_drift            [1]  sin of the same angle
-- It returns the prompt text. The text up to the first observation value is
-- identical for every decision: `prefix` (M.intro, M.instruction and the
-- first line's label, built below from the one copy of each) is exactly that part,
-- so the policy computes it once and reuses it (GPT-2 KV cache).
--
-- Edit freely: number_format and separator change how numbers read; the
-- lines and the request are the paper's, the request before the observation
-- (the paper puts it after; README, "GPT-2 policy", says what the order
-- changed). No recompilation is needed.

local M = {}

M.number_format = "%+.2f" -- string.format pattern for every value (a sign on every value: fixed width)
M.separator = ", "        -- between the values of one field

M.intro = "You are a decision support system that aids in avoiding collisions between the "
  .. "ownship and intruders as the ownship navigates to reach a waypoint.\n"

-- The paper's request, placed before the observation so that the observation
-- ends the prompt (the policy reads the last position's hidden state).
M.instruction = "Please provide a decision on whether to turn left or right or remain unchanged "
  .. "to avoid a collision with the intruder aircraft.\n"
  .. "The decision should be one of the following: [-1 for left, -0.5 for slightly left, "
  .. "0 for unchanged, 0.5 for slightly right, 1 for right].\n"
  .. "Only provide the decision as output. Here is the observation from the environment:\n"

local lines = {
  { "intruder_distance", "1. The intruder distances are [" },
  { "cos_difference_pos", "2. The cosines of the bearing angle differences are [" },
  { "sin_difference_pos", "3. The sines of the bearing angle differences are [" },
  { "x_difference_speed", "4. The differences in the x-component of the speed are [" },
  { "y_difference_speed", "5. The differences in the y-component of the speed are [" },
  { "waypoint_distance", "6. The distances to each waypoint are [" },
  { "cos_drift", "7. The cosines of the drift angles are [" },
  { "sin_drift", "8. The sines of the drift angles are [" },
}

M.prefix = M.intro .. M.instruction .. lines[1][2]

local function values(list)
  local out = {}
  for i, v in ipairs(list) do
    local s = string.format(M.number_format, v)
    if s:match("^%-0%.?0*$") then s = s:sub(2) end  -- no "-0.00"
    out[i] = s
  end
  return table.concat(out, M.separator)
end

function M.render(obs)
  local parts = {}
  for i, line in ipairs(lines) do
    local field = obs[line[1]]
    if field == nil then error("observation has no field '" .. line[1] .. "'", 2) end
    local head = (i == 1) and (M.intro .. M.instruction) or ""
    parts[#parts + 1] = head .. line[2] .. values(field) .. "].\n"
  end
  return table.concat(parts)
end

return M
