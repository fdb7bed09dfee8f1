// The environment's lean kinematics (env::Fleet) against the general
// simulator (sim::Simulation) on the same episodes: the environment is a
// fast path of the simulator, so both must fly the same trajectories.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "core/rng.h"
#include "env/horizontal_cr.h"
#include "sim/simulation.h"

using namespace squawk;

TEST_CASE("HorizontalCR env and the Simulation fly the same episode (gym rules, ground cap)") {
  env::HorizontalCrConfig cfg;
  cfg.rules = env::Rules::kGym;
  auto made = env::HorizontalCrEnv::make(cfg);
  REQUIRE(made.is_ok());
  env::HorizontalCrEnv& e = made.value();

  for (uint64_t seed : {1u, 2u, 3u}) {
    Rng rng(seed);
    const env::EpisodeSetup setup = e.draw_setup(rng);
    REQUIRE(e.reset_to(setup).is_ok());

    sim::Simulation s;
    REQUIRE(s.set_dt(cfg.dt).is_ok());
    sim::PerformanceOptions perf;
    perf.ground_cap = true;
    perf.ground_vmax = cfg.limits.speed_cap;
    perf.ground_axmax = cfg.limits.accel;
    REQUIRE(s.set_performance_options(perf).is_ok());
    REQUIRE(s.create("KL001", "A320", cfg.start_lat, cfg.start_lon, 0.0, 0.0, cfg.own_speed).is_ok());
    for (size_t i = 0; i < setup.intruders.size(); ++i) {
      const auto& in = setup.intruders[i];
      REQUIRE(s.create(std::to_string(i), "A320", in.lat, in.lon, in.hdg, 0.0, in.tas).is_ok());
    }

    Rng actions(seed + 100);
    double worst_m = 0.0;
    for (int k = 0; k < 40 && !e.done(); ++k) {
      const double a = actions.uniform(-1.0, 1.0);
      const double hdg_cmd = e.fleet().hdg(0) + a * cfg.heading_per_action;
      e.step(a);
      REQUIRE(s.set_heading("KL001", hdg_cmd).is_ok());
      REQUIRE(s.run_for(cfg.dt * cfg.substeps).is_ok());
      const auto& t = s.traffic();
      for (int i = 0; i < static_cast<int>(e.fleet().size()); ++i) {
        const double dn = (t.lat[static_cast<size_t>(i)] - e.fleet().lat(i)) * 111195.0;
        const double de = (t.lon[static_cast<size_t>(i)] - e.fleet().lon(i)) * 111195.0 *
                          std::cos(e.fleet().lat(i) * 3.14159265358979 / 180.0);
        worst_m = std::max(worst_m, std::hypot(dn, de));
        CHECK(t.tas[static_cast<size_t>(i)] == doctest::Approx(e.fleet().tas(i)).epsilon(1e-9));
      }
    }
    CAPTURE(seed);
    MESSAGE("seed " << seed << ": largest env/sim position difference " << worst_m << " m");
    CHECK(worst_m < 1e-3);  // [m] after up to 2000 s of flight
  }
}
