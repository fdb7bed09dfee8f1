-- BlueSky-Gym HorizontalCREnv-v0 as it is (docs/bluesky_facts.md §1): the agent
-- turns the ownship by a continuous action in [-1, 1] x 45 deg at every
-- 10 x 5 s step; reward = +1 on reaching the waypoint - 0.1 |drift| [rad]
-- - 1 per intruder inside 5 NM at the step end; 300-step cap.
-- BlueSky flies these aircraft at 0 m, where its OpenAP model caps an A320 at
-- 89 m/s, so the real environment slows from 150 to 89 m/s in the first 30 s;
-- speed_cap_ms = 89 reproduces that (the recorded BlueSky-Gym trace matches to
-- 1e-8 deg); set 0 for the nominal 150 m/s.
return {
  rules = "gym",
  env = {
    intruders = 5,
    own_speed_ms = 150,
    speed_cap_ms = 89,
    accel_ms2 = 2,
    bank_deg = 25,
    dt_s = 5,
    substeps = 10,
    start_lat = 52, start_lon = 4,
    dpsi_deg = {45, 314},
    cpa_nm = {0, 4},
    tlos_s = {100, 999},
    waypoint_km = {100, 149},
    zone_radius_nm = 5,
    reach_radius_km = 5,
    heading_step_deg = 45,
    max_steps = 300,
  },
  eval = { episodes = 1000, seed = 2024 },
  reward = {
    reach = 1,
    drift_per_rad = -0.1,
    intrusion = -1,
  },
  -- Gaussian head: mean from the MLP, one learned log sigma.
  policy = { hidden = {96, 96}, head = "gaussian", init_log_std = -0.5 },
  train = {
    estimator = "improved",
    episodes = 20000,
    episodes_per_update = 16,
    num_envs = 16,
    lr = 3e-4,
    gamma = 0.99,
    entropy_coef = 0.0,
    eval_every = 2000,
    eval_episodes = 100,
    seed = 1,
  },
}
