// HorizontalCrEnv: the horizontal conflict-resolution environment of
// BlueSky-Gym (HorizontalCREnv-v0) on squawk's kinematics, with two rule sets.
//
// Common to both (docs/bluesky_facts.md §1.3-1.5):
//   ownship created at (start_lat, start_lon), heading 0, own_speed [m/s];
//   each intruder by BlueSky's CRECONFS geometry relative to the ownship with
//   integer draws dpsi [deg], cpa [NM], tlos [s] (bounds inclusive), same
//   speed as the ownship; the waypoint due north at an integer distance [km]
//   on the great circle (R = 6371 km).
//   An action a (units of heading_per_action, 45 deg) commands the heading
//   hdg_now + a * 45 deg; one env step = substeps x dt (10 x 5 s) of Fleet
//   updates. The waypoint counts as reached when closer than reach_radius at
//   the end of a step. Observation: observation.h (28 values for 5 intruders).
//   speed_cap: BlueSky-Gym's aircraft sit at 0 m, where BlueSky's OpenAP model
//   limits an A320 to 89 m/s (measured), so the real env flies 150 -> 89 m/s in
//   the first 30 s. Both shipped scenarios keep that cap ON (speed_cap = 89),
//   so squawk reproduces what BlueSky actually does; speed_cap = 0 gives the
//   nominal 150 m/s that the gym code asks for.
//
// rules = kGym: BlueSky-Gym as it is. The agent acts at every step; reward
//   gym_reward (reward.h); the episode terminates when the waypoint is reached
//   and is truncated after max_steps (300) steps. Intrusions are counted at
//   step ends, as gym does; success = no intrusion counted in the episode.
//
// rules = kPaper: the paper's variant (§III.C, §IV.C). Before each step the
//   environment predicts conflicts by flying the ownship's current speed
//   straight at the waypoint: BlueSky's state-based CPA test against every
//   intruder's current velocity with the zone radius and `lookahead` [s]
//   (a pair already inside the zone is a conflict too). With no conflict the
//   ownship is steered at the waypoint by itself (no decision, no reward);
//   with one the agent is asked. Every env step, agent or automatic, earns
//   paper_reward (Eq. 1-4); step() returns the reward of the agent's step plus
//   those of the automatic steps that follow it until the next decision (the
//   consequences of that action), and the episode return is the sum over all
//   its env steps. The episode ends when the waypoint is reached; max_steps
//   env steps (agent and automatic) is a safety cap that counts as a failure.
//   An intrusion is any intruder inside the zone at any sub-step (every 5 s;
//   only at step ends when substep_intrusions is false), whoever was
//   steering; success = waypoint reached with no intrusion.
//   An episode whose conflicts never need the agent ends inside reset().
//
// Randomness: reset(rng) draws the whole scenario from the rng it is given,
// in a fixed order (per intruder dpsi, cpa, tlos; then the waypoint
// distance), so a seed fixes the episode bit for bit on one build.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "core/rng.h"
#include "core/status.h"
#include "env/pair_geometry.h"
#include "env/fleet.h"
#include "env/observation.h"
#include "env/reward.h"

namespace squawk::env {

enum class Rules { kGym, kPaper };

struct IntRange {
  int lo = 0;  // inclusive
  int hi = 0;  // inclusive
};

struct HorizontalCrConfig {
  Rules rules = Rules::kPaper;
  int num_intruders = 5;             // [-]
  double own_speed = 150.0;          // [m/s] commanded TAS (= CAS at 0 m)
  FleetLimits limits;                // accel [m/s^2], bank [deg], speed_cap [m/s]
  double dt = 5.0;                   // [s] one sub-step
  int substeps = 10;                 // [-] sub-steps per env step
  double start_lat = 52.0;           // [deg]
  double start_lon = 4.0;            // [deg]
  IntRange dpsi{45, 314};            // [deg] conflict angle draws
  IntRange cpa{0, 4};                // [NM] distance at CPA draws
  IntRange tlos{100, 999};           // [s] time to loss of separation draws
  IntRange waypoint_distance{100, 149};  // [km]
  double zone_radius = 9260.0;       // [m] protected zone (5 NM)
  double reach_radius = 5000.0;      // [m]
  double heading_per_action = 45.0;  // [deg] per unit of action
  int max_steps = 300;               // [-] env steps before truncation
  double lookahead = 300.0;          // [s] paper rules: conflict look-ahead
  double dist_scale = 150000.0;      // [m] observation distance normaliser
  double speed_scale = 150.0;        // [m/s] observation speed normaliser
  double mvp_margin = 1.05;          // [-] MVP zone factor (BlueSky resofach)
  // Paper rules: look for intrusions at every sub-step (true) or only at the
  // end of each env step, as BlueSky-Gym does (false).
  bool substep_intrusions = true;
  RewardWeights weights;
  // Replaces the built-in reward when set (e.g. a scenario's Lua function).
  std::function<double(const StepFacts&)> reward_fn;

  // Ok, or an error naming the first field out of range.
  Status validate() const;
};

// The scenario of one episode, as drawn (or replayed in tests).
struct EpisodeSetup {
  struct Intruder {
    double lat = 0.0;  // [deg]
    double lon = 0.0;  // [deg]
    double hdg = 0.0;  // [deg] may be negative, as creconfs leaves it
    double tas = 0.0;  // [m/s]
  };
  std::vector<Intruder> intruders;
  double waypoint_lat = 0.0;  // [deg]
  double waypoint_lon = 0.0;  // [deg]
};

// The observation mirror (observation.h) of `config`'s environment; an error
// when the ownship's ground speed is not constant (a speed_cap below
// own_speed slows it in the first steps), where no fixed map is exact.
Result<ObservationMirror> observation_mirror(const HorizontalCrConfig& config);

// BlueSky's CRECONFS against the ownship at the configured start (heading 0,
// own_speed): an intruder at the same speed whose track differs by dpsi [deg],
// that passes at cpa_nm [NM] and enters the zone after tlos [s].
EpisodeSetup::Intruder creconfs(const HorizontalCrConfig& config, double dpsi, double cpa_nm,
                                double tlos);

struct EpisodeStats {
  uint64_t index = 0;       // [-] episode number within its run
  double total_reward = 0;  // [-] sum of the rewards of all env steps
  int decisions = 0;        // [-] agent steps
  int steps = 0;            // [-] env steps, agent and automatic
  int intrusions = 0;       // [-] intrusion count (gym: intruders at step ends; paper: sub-steps with one)
  bool reached = false;     // waypoint reached
  bool truncated = false;   // stopped by max_steps
  bool success = false;     // see the rule sets above
  double sim_time = 0;      // [s]
  double min_separation = 0;  // [m] closest ownship-intruder distance at the start and every step end
};

// Per env step, for recorders: who steered, with what, and the outcome.
struct StepInfo {
  bool agent = false;      // the agent's action (false: automatic steering)
  double action = 0.0;     // [-] units of heading_per_action (agent steps)
  double hdg_cmd = 0.0;    // [deg] heading commanded
  double reward = 0.0;     // [-] reward of this env step
  StepFacts facts;
};

class HorizontalCrEnv;

// Hooks a renderer or logger can implement; called by the environment.
class EpisodeObserver {
 public:
  virtual ~EpisodeObserver() = default;
  virtual void on_reset(const HorizontalCrEnv& env) = 0;
  virtual void on_step(const HorizontalCrEnv& env, const StepInfo& info) = 0;
  virtual void on_end(const HorizontalCrEnv& env, const EpisodeStats& stats) = 0;
};

class HorizontalCrEnv {
 public:
  static Result<HorizontalCrEnv> make(HorizontalCrConfig config);

  // Starts an episode drawn from rng. Returns true when the agent must decide,
  // false when the episode already ended (paper rules, no conflict needed it).
  bool reset(Rng& rng, uint64_t episode_index = 0);
  // Starts the episode `setup` (ownship at the configured start); same
  // meaning as reset(). Error when setup has not num_intruders intruders.
  Result<bool> reset_to(const EpisodeSetup& setup, uint64_t episode_index = 0);
  // The draws of one episode without starting it.
  EpisodeSetup draw_setup(Rng& rng) const;

  // Applies the agent's action (clipped to [-1, 1]), runs the step (and, under
  // the paper rules, the automatic steps that follow until the next
  // conflict); returns the reward of the agent's step.
  double step(double action);

  bool done() const { return done_; }
  const EpisodeStats& stats() const { return stats_; }
  const Observation& observation() const { return obs_; }
  void observe_flat(std::span<float> out) const { flatten(obs_, out); }
  int observation_size() const { return env::observation_size(config_.num_intruders); }

  // MVP resolution toward the waypoint as an action in [-1, 1] (a classical
  // reference policy): BlueSky's MVP over all pairs in conflict when the
  // ownship flies at the waypoint; with none, the turn toward the waypoint.
  double mvp_action() const;

  const HorizontalCrConfig& config() const { return config_; }
  const Fleet& fleet() const { return fleet_; }
  double waypoint_lat() const { return wpt_lat_; }
  double waypoint_lon() const { return wpt_lon_; }
  double sim_time() const { return sim_time_; }
  // Conflict predicted for the ownship flying straight at the waypoint.
  bool conflict_ahead() const;
  void set_observer(EpisodeObserver* obs) { observer_ = obs; }

 private:
  explicit HorizontalCrEnv(HorizontalCrConfig config);
  bool start(const EpisodeSetup& setup, uint64_t episode_index);
  void advance(double hdg_cmd);  // one env step of sub-steps
  void compute_observation();
  StepFacts step_facts(double hdg_before) const;
  int intruders_in_zone() const;
  void finish(bool truncated);
  // Paper rules: automatic steps until a conflict needs the agent or the
  // episode ends; returns the sum of their rewards.
  double run_automatic();
  double reward_of(const StepFacts& f) const;

  HorizontalCrConfig config_;
  Fleet fleet_;
  double wpt_lat_ = 0.0, wpt_lon_ = 0.0;  // [deg]
  double sim_time_ = 0.0;                  // [s]
  int substep_intrusions_ = 0;             // sub-steps with an intrusion in the last env step
  bool done_ = true;
  EpisodeStats stats_;
  Observation obs_;
  double wpt_dist_ = 0.0;   // [m]
  double wpt_qdr_ = 0.0;    // [deg] bearing ownship -> waypoint
  double wpt_cos_lat_ = 1.0, wpt_sin_lat_ = 0.0;
  // Per intruder, refreshed with the observation: position relative to the
  // ownship [m] (east, north; BlueSky's kwikqdrdist) and its length [m].
  std::vector<Vec2> rel_;
  std::vector<double> dist_;
  EpisodeObserver* observer_ = nullptr;
};

}  // namespace squawk::env
