// Environment unit tests: rewards (paper Eq. 1-4, gym), observation layout,
// CPA geometry, BlueSky's turn and speed dynamics, the paper rules' episode
// logic and reproducibility.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "core/geo.h"
#include "core/units.h"
#include "env/horizontal_cr.h"
#include "env/observation.h"
#include "env/pair_geometry.h"
#include "env/reward.h"
#include "env/vec_env.h"
#include "paper_settings.h"

using namespace squawk;
using namespace squawk::env;

TEST_CASE("paper reward follows Eq. 1-4 with the paper's weights") {
  RewardWeights w;
  StepFacts f;
  f.drift = 45.0;           // delta = 1
  f.heading_change = -22.5; // delta = 0.5
  const double want = 0.02 + -0.005 * (std::exp(0.8) - 1.0) + -0.01 * (std::exp(0.4) - 1.0);
  CHECK(paper_reward(w, f) == doctest::Approx(want).epsilon(1e-12));
  f.drift = -100.0;  // beyond 90 deg: constant -0.5
  CHECK(paper_reward(w, f) == doctest::Approx(0.02 - 0.5 + -0.01 * (std::exp(0.4) - 1.0)));
  f.intrusions = 2;  // intrusion: drift and heading terms vanish
  f.cpa_ratio = 0.5;
  CHECK(paper_reward(w, f) == doctest::Approx(-1.0 + 0.4 * 0.5));
  f.intrusions = 0;  // inside only between step ends: seen with intrusion_at_substeps alone
  f.substep_intrusions = 3;
  CHECK(paper_reward(w, f) == doctest::Approx(0.02 - 0.5 + -0.01 * (std::exp(0.4) - 1.0)));
  w.intrusion_at_substeps = true;
  CHECK(paper_reward(w, f) == doctest::Approx(-1.0 + 0.4 * 0.5));
}

TEST_CASE("step facts count the sub-steps with an intruder inside the zone") {
  HorizontalCrConfig c = test::paper_eval_config(false);
  auto e = HorizontalCrEnv::make(c);
  REQUIRE(e);
  struct Facts : EpisodeObserver {
    int substeps = 0, at_ends = 0, between_only = 0;
    void on_reset(const HorizontalCrEnv&) override {}
    void on_step(const HorizontalCrEnv&, const StepInfo& i) override {
      substeps += i.facts.substep_intrusions;
      at_ends += i.facts.intrusions > 0;
      between_only += i.facts.intrusions == 0 && i.facts.substep_intrusions > 0;
      CHECK(i.facts.substep_intrusions <= 10);
      if (i.facts.substep_intrusions > 0) CHECK(i.facts.cpa_ratio <= 1.0);
    }
    void on_end(const HorizontalCrEnv&, const EpisodeStats&) override {}
  } seen;
  e->set_observer(&seen);
  int total = 0;
  for (uint64_t k = 0; k < 200; ++k) {  // never turning: most episodes intrude
    Rng rng(episode_seed(8, k));
    bool decide = e->reset(rng, k);
    while (decide && !e->done()) e->step(0.0);
    total += e->stats().intrusions;
  }
  CHECK(seen.substeps == total);  // success's count, step by step
  CHECK(seen.at_ends > 0);
  CHECK(seen.between_only > 0);   // what the step-end reading misses
}

TEST_CASE("gym reward: reach, drift in radians, one penalty per intruder") {
  RewardWeights w;
  StepFacts f;
  f.drift = -90.0;
  f.intrusions = 2;
  f.reached = true;
  CHECK(gym_reward(w, f) == doctest::Approx(1.0 - 0.1 * units::kPi / 2 - 2.0));
}

TEST_CASE("flat observation uses Gymnasium's alphabetical key order and round-trips") {
  Observation o;
  for (int i = 0; i < 5; ++i) {
    o.intruder_distance.push_back(10 + i);
    o.cos_difference_pos.push_back(20 + i);
    o.sin_difference_pos.push_back(30 + i);
    o.x_difference_speed.push_back(40 + i);
    o.y_difference_speed.push_back(50 + i);
  }
  o.waypoint_distance = 1;
  o.cos_drift = 2;
  o.sin_drift = 3;
  std::vector<float> flat(28);
  flatten(o, flat);
  const std::vector<float> want = {20, 21, 22, 23, 24, 2, 10, 11, 12, 13, 14, 30, 31, 32,
                                   33, 34, 3,  1,  40, 41, 42, 43, 44, 50, 51, 52, 53, 54};
  CHECK(flat == want);
  auto back = unflatten(flat);
  REQUIRE(back);
  CHECK(back->y_difference_speed[4] == 54);
  CHECK(back->sin_drift == 3);
  auto bad = unflatten(std::span<const float>(flat).first(27));
  CHECK_FALSE(bad);
  CHECK(bad.status().message().find("27 values") != std::string::npos);
}

TEST_CASE("closest approach of a head-on pair") {
  // Intruder 20 km north, closing at 200 m/s: CPA at 100 s, 0 m; zone entry
  // 9260 / 200 = 46.3 s earlier.
  const Cpa c = closest_approach({0, 20000}, {0, -200}, 9260);
  CHECK(c.tcpa == doctest::Approx(100));
  CHECK(c.dcpa == doctest::Approx(0).epsilon(1e-9));
  CHECK(c.t_in == doctest::Approx(100 - 46.3));
  CHECK(c.conflict(300));
  CHECK_FALSE(c.conflict(50));
  // Passing 12 km abeam: no conflict with a 5 NM (9.26 km) zone.
  CHECK_FALSE(closest_approach({12000, 20000}, {0, -200}, 9260).conflict(300));
}

TEST_CASE("fleet: BlueSky's 2 m/s^2 deceleration to 89 m/s and 25 deg bank turn rate") {
  Fleet f;
  f.add(52, 4, 0, 150);
  f.set_heading(0, 90);
  FleetLimits lim;  // 2 m/s^2, 25 deg, cap 89
  f.step(5.0, lim);
  CHECK(f.tas(0) == doctest::Approx(140));
  // Turn rate at the new speed: deg(g0 tan 25 / 140) = 1.8717 deg/s.
  CHECK(f.hdg(0) == doctest::Approx(5 * units::rad_to_deg(units::kG0 * std::tan(25 * units::kDeg) / 140)));
  for (int i = 0; i < 10; ++i) f.step(5.0, lim);
  CHECK(f.tas(0) == 89);
  CHECK(f.hdg(0) == 90);
  // Flat-earth position update: northward flight moves latitude by deg(v dt / R).
  Fleet g;
  g.add(52, 4, 0, 100);
  lim.speed_cap = 0;
  g.step(5.0, lim);
  CHECK(g.lat(0) == doctest::Approx(52 + units::rad_to_deg(500.0 / units::kREarth)).epsilon(1e-14));
}

TEST_CASE("observation matches BlueSky-Gym's formulas computed with kwikqdrdist") {
  HorizontalCrConfig c;
  auto e = HorizontalCrEnv::make(c);
  REQUIRE(e);
  Rng rng(5);
  e->reset(rng);
  for (int k = 0; k < 3 && !e->done(); ++k) e->step(0.5);
  const Fleet& f = e->fleet();
  const Observation& o = e->observation();
  for (int i = 0; i < 5; ++i) {
    const auto qd = geo::kwikqdrdist(f.lat(0), f.lon(0), f.lat(i + 1), f.lon(i + 1));
    const double b = geo::gym_wrap180(f.hdg(0) - qd.qdr_deg) * units::kDeg;
    CHECK(o.intruder_distance[i] == doctest::Approx(qd.dist_nm * 1.852 / 150).epsilon(1e-12));
    CHECK(o.cos_difference_pos[i] == doctest::Approx(std::cos(b)).epsilon(1e-9));
    CHECK(o.sin_difference_pos[i] == doctest::Approx(std::sin(b)).epsilon(1e-9));
    const double dh = (f.hdg(0) - f.hdg(i + 1)) * units::kDeg;
    CHECK(o.x_difference_speed[i] == doctest::Approx(-std::cos(dh) * f.tas(i + 1) / 150).epsilon(1e-9));
    CHECK(o.y_difference_speed[i] ==
          doctest::Approx((f.tas(0) - std::sin(dh) * f.tas(i + 1)) / 150).epsilon(1e-9));
  }
  const auto w = geo::kwikqdrdist(f.lat(0), f.lon(0), e->waypoint_lat(), e->waypoint_lon());
  CHECK(o.waypoint_distance == doctest::Approx(w.dist_nm * 1.852 / 150).epsilon(1e-12));
  CHECK(o.cos_drift == doctest::Approx(std::cos((f.hdg(0) - w.qdr_deg) * units::kDeg)).epsilon(1e-9));
}

TEST_CASE("paper rules: the agent is asked only when flying direct would conflict") {
  HorizontalCrConfig c = test::paper_eval_config(false);
  auto e = HorizontalCrEnv::make(c);
  REQUIRE(e);
  int episodes = 0, reached = 0;
  for (uint64_t s = 0; s < 50; ++s) {
    Rng rng(s);
    bool ask = e->reset(rng, s);
    while (ask && !e->done()) {
      CHECK(e->conflict_ahead());
      e->step(1.0);
      ask = !e->done();
    }
    CHECK(e->done());
    ++episodes;
    reached += e->stats().reached;
    const auto& st = e->stats();
    CHECK(st.success == (st.reached && !st.truncated && st.intrusions == 0));
    CHECK(st.steps >= st.decisions);
  }
  CHECK(reached > 40);
}

TEST_CASE("one seed, one sequence of episodes: identical returns, independent of slot count") {
  HorizontalCrConfig c;
  auto run = [&](int slots) {
    auto v = VecEnv::make(c, slots);
    REQUIRE(v);
    v->start(42, 0, 40);
    Rng policy(7);
    std::vector<double> actions, rewards;
    std::vector<uint8_t> dones;
    while (!v->finished()) {
      const size_t n = v->waiting().size();
      actions.assign(n, 0.0);
      rewards.resize(n);
      dones.resize(n);
      for (size_t r = 0; r < n; ++r) actions[r] = v->observations()[r * 28 + 6] > 0.2 ? 1.0 : -0.5;
      v->step(actions, rewards, dones);
    }
    std::vector<double> returns(40);
    for (const auto& s : v->completed()) returns[s.index] = s.total_reward;
    return returns;
  };
  const auto a = run(8), b = run(8), c3 = run(3);
  CHECK(a == b);
  CHECK(a == c3);
  auto d = VecEnv::make(c, 4);
  REQUIRE(d);
  Rng r1(episode_seed(42, 0)), r2(episode_seed(43, 0));
  auto e = HorizontalCrEnv::make(c);
  REQUIRE(e);
  CHECK(e->draw_setup(r1).intruders[0].lat != e->draw_setup(r2).intruders[0].lat);
}

TEST_CASE("MVP turns away from a head-on intruder") {
  HorizontalCrConfig c;
  c.rules = Rules::kGym;
  c.num_intruders = 1;
  auto e = HorizontalCrEnv::make(c);
  REQUIRE(e);
  EpisodeSetup s;
  s.intruders.push_back(creconfs(c, 180, 0, 200));
  s.waypoint_lat = 53;
  s.waypoint_lon = 4;
  REQUIRE(e->reset_to(s));
  const double a = e->mvp_action();
  CHECK(std::fabs(a) > 0.05);
  bool intruded = false;
  while (!e->done()) {
    e->step(e->mvp_action());
    intruded |= e->stats().intrusions > 0;
  }
  CHECK_FALSE(intruded);
}

TEST_CASE("bad configuration and setups give errors that name the field") {
  HorizontalCrConfig c;
  c.tlos = {500, 100};
  auto e = HorizontalCrEnv::make(c);
  REQUIRE_FALSE(e);
  CHECK(e.status().message().find("tlos") != std::string::npos);
  c = {};
  c.dt = -1;
  CHECK(HorizontalCrEnv::make(c).status().message().find("'dt'") != std::string::npos);
  auto ok = HorizontalCrEnv::make({});
  REQUIRE(ok);
  EpisodeSetup two;
  two.intruders.resize(2);
  auto r = ok->reset_to(two);
  REQUIRE_FALSE(r);
  CHECK(r.status().message().find("expected 5") != std::string::npos);
  CHECK_FALSE(VecEnv::make({}, 0));
}

TEST_CASE("an episode's closest separation is the smallest intruder distance the ownship saw") {
  HorizontalCrConfig c;
  c.rules = Rules::kGym;  // every step is the agent's, so each observation is seen here
  auto e = HorizontalCrEnv::make(c);
  REQUIRE(e);
  Rng rng(episode_seed(4, 0));
  REQUIRE(e->reset(rng));
  double seen = 1e300;
  for (int t = 0; t < 40 && !e->done(); ++t) {
    for (double d : e->observation().intruder_distance) seen = std::min(seen, d * c.dist_scale);
    CHECK(e->stats().min_separation == doctest::Approx(seen).epsilon(1e-12));
    e->step(t % 3 == 0 ? 0.5 : 0.0);
  }
  CHECK(seen < 1e300);
}
