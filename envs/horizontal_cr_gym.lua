-- BlueSky-Gym's HorizontalCREnv-v0 as it is (bluesky_gym/envs/horizontal_cr_env.py;
-- docs/bluesky_facts.md §1): the agent turns the ownship by a continuous action
-- in [-1, 1] x 45 deg at every 10 x 5 s step; reward = +1 on reaching the
-- waypoint - 0.1 |drift| [rad] - 1 per intruder inside 5 NM at the step end;
-- 300 steps. BlueSky flies these aircraft at 0 m, where OpenAP caps an A320 at
-- 89 m/s: speed_cap_ms = 89 reproduces that. The settings are
-- scenarios/horizontal_cr_gym.lua's; the form is envs/horizontal_cr.lua's.
return require("horizontal_cr").with{
  id = "HorizontalCREnv-v0",
  source = "bluesky_gym/envs/horizontal_cr_env.py",
  declaration = {
    rules = "gym",
    env = {
      intruders = 5, own_speed_ms = 150, speed_cap_ms = 89, accel_ms2 = 2, bank_deg = 25,
      dt_s = 5, substeps = 10, start_lat = 52, start_lon = 4,
      dpsi_deg = {45, 314}, cpa_nm = {0, 4}, tlos_s = {100, 999}, waypoint_km = {100, 149},
      zone_radius_nm = 5, reach_radius_km = 5, heading_step_deg = 45, max_steps = 300,
    },
    reward = {reach = 1, drift_per_rad = -0.1, intrusion = -1},
  },
}
