-- The paper's horizontal conflict-resolution setup (§III.C, §IV.C-D) on the
-- BlueSky-Gym HorizontalCREnv geometry. `squawk train` / `squawk eval` and
-- squawk.env.new() read this table; every key is listed with its unit.
--
-- The agent is asked only when flying straight at the waypoint would bring an
-- intruder inside the 5 NM zone within `lookahead_s`; otherwise the ownship
-- steers to the waypoint by itself. Actions turn the ownship by
-- {-1, -0.5, 0, 0.5, 1} x 45 deg from its current heading; each decision lasts
-- 10 x 5 s. Reward: Eq. 1-4. Success: waypoint reached with no intruder inside
-- the zone at any 5 s sub-step.
return {
  rules = "paper",

  -- Training settings (the paper: look-ahead 300 s, intruder tLOS in [120, 1000] s).
  env = {
    intruders = 5,
    own_speed_ms = 150,        -- commanded speed [m/s] (gym's AC_SPD, a CAS at 0 m)
    speed_cap_ms = 0,          -- no ground-phase cap: the nominal 150 m/s (89 = what BlueSky does at 0 m)
    accel_ms2 = 2,             -- [m/s^2]
    bank_deg = 25,             -- BlueSky's default bank angle [deg]
    dt_s = 5,                  -- sub-step [s]
    substeps = 10,             -- sub-steps per decision
    start_lat = 52, start_lon = 4,
    dpsi_deg = {45, 314},      -- conflict angle draws [deg], integers, inclusive
    cpa_nm = {0, 4},           -- distance at closest approach [NM]
    tlos_s = {120, 1000},      -- time to loss of separation [s]
    waypoint_km = {100, 149},  -- waypoint distance, due north [km]
    zone_radius_nm = 5,        -- protected zone [NM]
    reach_radius_km = 5,       -- waypoint reached inside this [km]
    heading_step_deg = 45,     -- heading change per unit of action [deg]
    max_steps = 300,           -- safety cap on 50 s steps (15000 s); hitting it is a failure
    lookahead_s = 300,         -- conflict detection look-ahead [s]
    mvp_margin = 1.05,         -- MVP reference policy: zone factor (BlueSky's resofach)
  },

  -- Evaluation settings override the env table (look-ahead 600 s, tLOS [300, 1000] s).
  eval = {
    tlos_s = {300, 1000},
    lookahead_s = 600,
    episodes = 1000,
    seed = 2024,
  },

  -- Eq. 1-4 weights. Replace the table by function(f) ... end to define another
  -- reward; f has step, intrusions, substep_intrusions, cpa_ratio, drift_deg,
  -- heading_change_deg, waypoint_distance_m and reached.
  reward = {
    w_i = 0.4,               -- Eq. 2: weight of |CPA / min dist| during an intrusion
    clear_bonus = 0.02,      -- Eq. 2: reward of a step without intrusion
    w_d = -0.005,            -- Eq. 3: drift weight
    drift_limit_deg = 90,    -- Eq. 3: beyond this |drift| ...
    drift_beyond = -0.5,     -- ... the drift term is this constant
    w_h = -0.01,             -- Eq. 4: heading-change weight
    exp_rate = 0.8,          -- Eq. 3-4: exponent factor
    delta_norm_deg = 45,     -- Eq. 3-4: normaliser of delta [deg]
    intrusion_at = "step_end", -- Eq. 2 "intrusion detected": at the step end, or "substep": at any 5 s sub-step
  },

  -- The paper's network: linear layers with ReLU, categorical over the 5 actions
  -- (28-96-96-5: 12,581 parameters).
  policy = {
    hidden = {96, 96},
    head = "categorical",
    actions = {-1, -0.5, 0, 0.5, 1},
  },

  train = {
    estimator = "improved",   -- "vpg" = Eq. 5 exactly
    episodes = 200000,
    episodes_per_update = 64,
    num_envs = 64,
    lr = 1e-3,
    lr_final = 1e-4,          -- linear decay of the Adam step size over the run
    gamma = 0.95,
    entropy_coef = 0.01,
    grad_clip = 1.0,
    eval_every = 5000,
    eval_episodes = 500,
    seed = 1,
  },
}
