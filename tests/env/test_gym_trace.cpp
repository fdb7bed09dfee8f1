// Gym-rules fidelity: replays the real BlueSky-Gym episode recorded in
// shared/facts/bsgym_trace_seed42.csv (random policy, seed 42, 300 steps)
// from its initial state and actions, and compares the states and rewards.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/files.h"
#include "core/text.h"
#include "env/horizontal_cr.h"

using namespace squawk;
using namespace squawk::env;

namespace {

struct Trace {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  double at(size_t row, const std::string& col) const {
    for (size_t i = 0; i < header.size(); ++i)
      if (header[i] == col) return rows[row][i];
    FAIL("no column " << col);
    return 0.0;
  }
};

bool load_trace(Trace& t) {
  const std::string path = std::string(SQUAWK_SHARED_DIR) + "/facts/bsgym_trace_seed42.csv";
  auto text = files::read(path);
  if (!text) return false;
  std::istringstream in(*text);
  std::string line;
  std::getline(in, line);
  t.header = text::split(text::trim(line), ',');
  while (std::getline(in, line)) {
    if (text::trim(line).empty()) continue;
    std::vector<double> row;
    for (const auto& f : text::split(text::trim(line), ','))
      row.push_back(text::to_double(f).value_or(std::nan("")));
    t.rows.push_back(row);
  }
  return true;
}

HorizontalCrConfig gym_config() {
  HorizontalCrConfig c;
  c.rules = Rules::kGym;
  c.limits.speed_cap = 89.0;
  return c;
}

EpisodeSetup setup_from(const Trace& t) {
  EpisodeSetup s;
  for (int i = 0; i < 5; ++i) {
    const std::string p = "int" + std::to_string(i) + "_";
    s.intruders.push_back({t.at(0, p + "lat"), t.at(0, p + "lon"), t.at(0, p + "hdg"), t.at(0, p + "tas")});
  }
  s.waypoint_lat = t.at(0, "wpt_lat");
  s.waypoint_lon = t.at(0, "wpt_lon");
  return s;
}

}  // namespace

TEST_CASE("creconfs and the waypoint reproduce the trace's initial state from integer draws" * doctest::test_suite("shared")) {
  Trace t;
  if (!load_trace(t)) {
    MESSAGE("skipped: ../shared/facts/bsgym_trace_seed42.csv is absent");
    return;
  }
  const HorizontalCrConfig c = gym_config();
  for (int i = 0; i < 5; ++i) {
    const std::string p = "int" + std::to_string(i) + "_";
    const double lat = t.at(0, p + "lat"), lon = t.at(0, p + "lon");
    const double dpsi = std::fmod(t.at(0, p + "hdg") + 360.0, 360.0);
    // Recover the integer cpa [NM] and tlos [s] the run drew, then rebuild.
    double best = 1e9;
    EpisodeSetup::Intruder got{};
    for (int cpa = 0; cpa <= 4; ++cpa)
      for (int tlos = 100; tlos <= 999; ++tlos) {
        const auto in = creconfs(c, dpsi, cpa, tlos);
        const double err = std::fabs(in.lat - lat) + std::fabs(in.lon - lon);
        if (err < best) {
          best = err;
          got = in;
        }
      }
    CHECK(best < 1e-7);
    CHECK(std::fabs(std::fmod(got.hdg - t.at(0, p + "hdg"), 360.0)) < 1e-9);
    CHECK(got.tas == doctest::Approx(t.at(0, p + "tas")).epsilon(1e-6));
  }
  // Waypoint: due north on the great circle at an integer number of km.
  bool found = false;
  for (int km = 100; km <= 149; ++km) {
    Rng unused(0);
    HorizontalCrConfig one = c;
    one.waypoint_distance = {km, km};
    auto env = HorizontalCrEnv::make(one);
    REQUIRE(env);
    const EpisodeSetup s = env->draw_setup(unused);
    if (std::fabs(s.waypoint_lat - t.at(0, "wpt_lat")) < 1e-7 &&
        std::fabs(s.waypoint_lon - t.at(0, "wpt_lon")) < 1e-12)
      found = true;
  }
  CHECK(found);
}

TEST_CASE("gym rules with the 89 m/s ground cap follow the real BlueSky-Gym trace" * doctest::test_suite("shared")) {
  Trace t;
  if (!load_trace(t)) {
    MESSAGE("skipped: ../shared/facts/bsgym_trace_seed42.csv is absent");
    return;
  }
  auto env = HorizontalCrEnv::make(gym_config());
  REQUIRE(env);
  auto started = env->reset_to(setup_from(t));
  REQUIRE(started);
  double max_pos = 0, max_hdg = 0, max_spd = 0, max_rew = 0;
  for (size_t k = 1; k < t.rows.size(); ++k) {
    const double r = env->step(t.at(k, "action"));
    const Fleet& f = env->fleet();
    max_pos = std::max({max_pos, std::fabs(f.lat(0) - t.at(k, "own_lat")),
                        std::fabs(f.lon(0) - t.at(k, "own_lon"))});
    for (int i = 0; i < 5; ++i) {
      const std::string p = "int" + std::to_string(i) + "_";
      max_pos = std::max({max_pos, std::fabs(f.lat(i + 1) - t.at(k, p + "lat")),
                          std::fabs(f.lon(i + 1) - t.at(k, p + "lon"))});
      max_spd = std::max(max_spd, std::fabs(f.tas(i + 1) - t.at(k, p + "tas")));
    }
    double dh = std::fabs(f.hdg(0) - t.at(k, "own_hdg"));
    max_hdg = std::max(max_hdg, std::min(dh, 360.0 - dh));
    max_spd = std::max(max_spd, std::fabs(f.tas(0) - t.at(k, "own_tas")));
    max_rew = std::max(max_rew, std::fabs(r - t.at(k, "reward")));
    CHECK(env->done() == (t.at(k, "terminated") != 0.0 || k == 300));
  }
  MESSAGE("max |dlat|,|dlon| " << max_pos << " deg, |dhdg| " << max_hdg << " deg, |dv| " << max_spd
                               << " m/s, |dreward| " << max_rew);
  CHECK(max_pos < 1e-7);
  CHECK(max_hdg < 1e-6);
  CHECK(max_spd < 1e-6);
  CHECK(max_rew < 1e-6);
  CHECK(env->stats().intrusions == static_cast<int>(t.at(300, "total_intrusions")));
  CHECK(env->stats().total_reward == doctest::Approx(-60.78).epsilon(1e-3));
}

TEST_CASE("without the ground cap the ownship keeps 150 m/s and leaves the trace" * doctest::test_suite("shared")) {
  Trace t;
  if (!load_trace(t)) {
    MESSAGE("skipped: ../shared/facts/bsgym_trace_seed42.csv is absent");
    return;
  }
  HorizontalCrConfig c = gym_config();
  c.limits.speed_cap = 0.0;
  auto env = HorizontalCrEnv::make(c);
  REQUIRE(env);
  REQUIRE(env->reset_to(setup_from(t)));
  env->step(t.at(1, "action"));
  CHECK(env->fleet().tas(0) == doctest::Approx(150.0));
  CHECK(std::fabs(env->fleet().lat(0) - t.at(1, "own_lat")) > 1e-3);
}
