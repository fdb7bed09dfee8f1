// Replays BlueSky-Gym's recorded episode (../shared/facts/bsgym_trace_seed42.csv: real
// BlueSky, random policy, seed 42) through the simulator: same initial
// states, same HDG commands, 10 steps of dt 5 s per env step, ground cap on.
// Every aircraft's position, heading and ground speed must follow BlueSky's.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/files.h"
#include "core/geo.h"
#include "core/text.h"
#include "sim/simulation.h"

using namespace squawk;
using namespace squawk::sim;

namespace {
using Row = std::map<std::string, double>;

std::vector<Row> read_trace(const std::string& path) {
  std::vector<Row> rows;
  const Result<std::string> data = files::read(path);
  REQUIRE(data.is_ok());
  std::vector<std::string> lines = text::split(*data, '\n');
  const std::vector<std::string> head = text::split(text::trim(lines[0]), ',');
  for (size_t k = 1; k < lines.size(); ++k) {
    const std::string_view line = text::trim(lines[k]);
    if (line.empty()) continue;
    const std::vector<std::string> f = text::split(line, ',');
    REQUIRE(f.size() == head.size());
    Row r;
    for (size_t c = 0; c < f.size(); ++c) r[head[c]] = text::to_double(f[c]).value_or(NAN);
    rows.push_back(std::move(r));
  }
  return rows;
}
}  // namespace

TEST_CASE("replay of a recorded BlueSky-Gym episode matches BlueSky's trajectories" * doctest::test_suite("shared")) {
  const std::string path = std::string(SQUAWK_SHARED_DIR) + "/facts/bsgym_trace_seed42.csv";
  if (!std::filesystem::exists(path)) {
    MESSAGE("skipped: " << path << " not found (needs the shared facts folder)");
    return;
  }
  const std::vector<Row> rows = read_trace(path);
  REQUIRE(rows.size() == 301);
  Simulation sim;
  REQUIRE(sim.set_dt(5.0).is_ok());
  PerformanceOptions po;
  po.ground_cap = true;
  REQUIRE(sim.set_performance_options(po).is_ok());
  const Row& r0 = rows[0];
  REQUIRE(sim.create("KL001", "A320", r0.at("own_lat"), r0.at("own_lon"), r0.at("own_hdg"), 0.0, 150.0).is_ok());
  const std::vector<std::string> pre = {"own", "int0", "int1", "int2", "int3", "int4"};
  for (int k = 0; k < 5; ++k) {
    const std::string p = pre[k + 1];
    REQUIRE(sim.create(std::to_string(k), "A320", r0.at(p + "_lat"), r0.at(p + "_lon"), r0.at(p + "_hdg"), 0.0,
                       r0.at(p + "_gs"))
                .is_ok());
  }
  const Traffic& t = sim.traffic();
  double max_pos_m = 0.0, max_hdg = 0.0, max_gs = 0.0;
  for (size_t s = 1; s < rows.size(); ++s) {
    const Row& r = rows[s];
    REQUIRE(sim.set_heading("KL001", r.at("hdg_cmd")).is_ok());
    for (int k = 0; k < 10; ++k) sim.step();
    REQUIRE(sim.simt() == r.at("simt"));
    for (int i = 0; i < 6; ++i) {
      const std::string& p = pre[static_cast<size_t>(i)];
      const double d = 1852.0 * geo::kwikdist_nm(t.lat[i], t.lon[i], r.at(p + "_lat"), r.at(p + "_lon"));
      max_pos_m = std::max(max_pos_m, d);
      max_hdg = std::max(max_hdg, std::fabs(geo::wrap180(t.hdg[i] - r.at(p + "_hdg"))));
      max_gs = std::max(max_gs, std::fabs(t.gs[i] - r.at(p + "_gs")));
    }
  }
  MESSAGE("300 env steps (15 000 s): max position error " << max_pos_m << " m, heading " << max_hdg
                                                         << " deg, ground speed " << max_gs << " m/s");
  CHECK(max_pos_m < 0.05);  // the CSV has 10 significant digits (~1 mm)
  CHECK(max_hdg < 1e-6);
  CHECK(max_gs < 1e-6);
}
