-- HorizontalCR under the paper's rules (§III.C, §IV.C-D; the reward is Eq. 1-4)
-- on BlueSky-Gym's HorizontalCREnv-v0 geometry: an ownship flies due north to a
-- waypoint 100-149 km away while five intruders are placed by BlueSky's
-- CRECONFS to conflict with it. Settings: scenarios/horizontal_cr.lua's
-- evaluation settings (Table 3), which tests/lua/env_horizontal_cr_lua.lua
-- holds these to episode for episode.
--
-- The file declares the environment; squawk.env.new compiles the declaration
-- into the C++ kernel (engine/env/horizontal_cr.h) that flies the fleet
-- (BlueSky's update, 10 x 5 s per step), draws the encounters, predicts
-- conflicts (state-based CPA over every intruder), computes the observation and
-- the reward. One E:step is one kernel call, whatever the number of aircraft.
--
-- The agent is asked only when flying straight at the waypoint would bring an
-- intruder inside the 5 NM zone within the look-ahead; otherwise the ownship
-- steers to the waypoint by itself, and those automatic steps are paid to the
-- action before them (to the first action for those before it). An episode
-- whose conflicts never need the agent runs to its end inside reset: its first
-- step ignores the action and returns that reward with the episode's end.
-- Replace `reward` by function(f) ... end to define another reward; f has step,
-- intrusions, substep_intrusions, cpa_ratio, drift_deg, heading_change_deg,
-- waypoint_distance_m and reached (script/scenario.h), at some cost in speed.
local E = {
  id = "HorizontalCR-paper-v0",
  source = "the paper (../shared/paper) §III.C, §IV.C-D on bluesky_gym/envs/horizontal_cr_env.py",
  -- Gymnasium's flattening of the Dict observation (keys in alphabetical
  -- order), as the float the MLP is given; distances / 150 km, speeds / 150 m/s.
  observation = {
    {name = "cos_difference_pos", size = 5},  -- cos(hdg_own - bearing to intruder i)
    {name = "cos_drift", size = 1},           -- cos(hdg_own - bearing to waypoint)
    {name = "intruder_distance", size = 5},
    {name = "sin_difference_pos", size = 5},
    {name = "sin_drift", size = 1},
    {name = "waypoint_distance", size = 1},
    {name = "x_difference_speed", size = 5},  -- -cos(hdg_own - hdg_i) gs_i
    {name = "y_difference_speed", size = 5},  -- gs_own - sin(hdg_own - hdg_i) gs_i
  },
  action = {low = {-1}, high = {1}},  -- heading change, x 45 deg
  -- Decisions never outnumber the kernel's 300 env steps, whose cap ends the
  -- episode first (truncated, a failure).
  max_episode_steps = 300,
  declaration = {
    rules = "paper",
    env = {
      intruders = 5,
      own_speed_ms = 150,        -- commanded speed [m/s]
      speed_cap_ms = 0,          -- no cap: the nominal 150 m/s
      accel_ms2 = 2, bank_deg = 25,
      dt_s = 5, substeps = 10,   -- one step = 10 x 5 s
      start_lat = 52, start_lon = 4,
      dpsi_deg = {45, 314},      -- conflict angle draws [deg], integers, inclusive
      cpa_nm = {0, 4},           -- distance at closest approach [NM]
      tlos_s = {300, 1000},      -- time to loss of separation [s]
      waypoint_km = {100, 149},  -- due north [km]
      zone_radius_nm = 5, reach_radius_km = 5,
      heading_step_deg = 45,
      max_steps = 300,           -- env steps, agent and automatic
      lookahead_s = 600,         -- conflict look-ahead [s]
      mvp_margin = 1.05,
    },
    reward = {                   -- Eq. 1-4
      w_i = 0.4, clear_bonus = 0.02,              -- Eq. 2
      w_d = -0.005, drift_limit_deg = 90, drift_beyond = -0.5,  -- Eq. 3
      w_h = -0.01,                                -- Eq. 4
      exp_rate = 0.8, delta_norm_deg = 45,
      intrusion_at = "step_end",
    },
  },
}
E.__index = E

-- A new environment of this form for another declaration (rules, env, reward
-- as above); envs/horizontal_cr_gym.lua is one.
function E.with(fields)
  local env = setmetatable({}, E)
  for k, v in pairs(fields) do env[k] = v end
  return env
end

function E:reset(seed)
  self.kernel = self.kernel or squawk.env.new(self.declaration)
  self.obs = self.obs or {}
  local ask, reward, truncated = self.kernel:reset(seed)
  self.pending, self.ended, self.cut = reward, not ask, truncated
  return self.kernel:flat(self.obs), {decision = ask}
end

function E:step(action)
  if self.ended then return self.obs, self.pending, not self.cut, self.cut end
  local reward, done, truncated = self.kernel:step(action[1])
  if self.pending ~= 0 then reward, self.pending = self.pending + reward, 0 end
  return self.kernel:flat(self.obs), reward, done and not truncated, truncated
end

return E
