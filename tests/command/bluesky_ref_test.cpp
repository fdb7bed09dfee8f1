// squawk against trajectories recorded from the real BlueSky (OpenAP
// performance) for the single-behaviour scenarios in tests/data/bluesky.
// Each <name>.bluesky.json was made by
//   BSREF_PREFIX=... /usr/bin/python3 ../shared/bluesky_ref/run_bluesky.py
//       --scn tests/data/bluesky/<name>.scn --times 60 300 900 -o tests/data/bluesky/<name>.bluesky.json
// (BlueSky 22fdf9e, OpenAP d9eb824; see tests/data/bluesky/README.md).
// Needs OpenAP's data folder at ../shared/openap/data; skips without it.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "command/scenario_run.h"
#include "core/files.h"
#include "core/units.h"
#include "sim/openap_data.h"

using namespace squawk;

namespace {

const std::string kData = std::string(SQUAWK_TEST_DATA) + "/bluesky";
const std::string kOpenap = std::string(SQUAWK_SOURCE_DIR) + "/../shared/openap/data";

double gc_m(double la1, double lo1, double la2, double lo2) {
  const double p1 = la1 * units::kDeg, p2 = la2 * units::kDeg;
  const double dp = p2 - p1, dl = (lo2 - lo1) * units::kDeg;
  const double a = std::sin(dp / 2) * std::sin(dp / 2) + std::cos(p1) * std::cos(p2) * std::sin(dl / 2) * std::sin(dl / 2);
  return 2.0 * units::kREarth * std::asin(std::min(1.0, std::sqrt(a)));
}

struct Limits {
  double pos_m, alt_ft, cas_kt;
};

// The targets: 100 m / 50 ft / 2 kt at 300 s, 300 m / 100 ft at 900 s.
Limits limits_at(double t) { return t <= 300.0 ? Limits{100.0, 50.0, 2.0} : Limits{300.0, 100.0, 2.0}; }

}  // namespace

TEST_CASE("BlueSky reference: single-behaviour scenarios with OpenAP within 100 m / 50 ft / 2 kt" * doctest::test_suite("shared")) {
  if (!files::exists(kOpenap)) {
    MESSAGE("skipped: " << kOpenap << " is absent (OpenAP data is not part of squawk)");
    return;
  }
  auto data = sim::OpenapData::load(kOpenap);
  REQUIRE(data.is_ok());
  int cases = 0;
  for (const auto& e : std::filesystem::directory_iterator(kData)) {
    if (e.path().extension() != ".scn") continue;
    std::filesystem::path ref = e.path();
    ref.replace_extension(".bluesky.json");
    REQUIRE_MESSAGE(files::exists(ref.string()), "no recording for " << e.path());
    const auto j = nlohmann::json::parse(files::read(ref.string()).value());
    for (const auto& st : j["states"]) {
      const double t = st["t"].get<double>();
      command::Stack stack;
      command::ScenarioRunOptions opts;
      opts.openap = data.value();
      opts.until = t;
      REQUIRE(command::run_scenario(e.path().string(), opts, stack).is_ok());
      const sim::Traffic& tr = stack.sim().traffic();
      const Limits lim = limits_at(t);
      CHECK(tr.n() == static_cast<int>(st["aircraft"].size()));  // same aircraft alive (AREA, DEL)
      for (const auto& a : st["aircraft"]) {
        const std::string id = a["id"].get<std::string>();
        CAPTURE(e.path().filename().string());
        CAPTURE(t);
        CAPTURE(id);
        const int i = tr.index_of(id);
        REQUIRE(i >= 0);
        CHECK(gc_m(tr.lat[i], tr.lon[i], a["lat"].get<double>(), a["lon"].get<double>()) < lim.pos_m);
        CHECK(std::fabs(units::m_to_ft(tr.alt[i]) - a["alt_ft"].get<double>()) < lim.alt_ft);
        CHECK(std::fabs(units::ms_to_kt(tr.cas[i]) - a["cas_kt"].get<double>()) < lim.cas_kt);
        ++cases;
      }
    }
  }
  CHECK(cases >= 30);
}

TEST_CASE("BlueSky reference: the class model without OpenAP runs every scenario") {
  // The default needs no files: the same scenarios run, and the level
  // cruise ones (Mach, LNAV, DIRECT) still match BlueSky to metres.
  for (const char* name : {"mach", "lnav", "direct"}) {
    const std::string scn = kData + "/" + name + ".scn";
    const auto j = nlohmann::json::parse(files::read(kData + "/" + name + ".bluesky.json").value());
    const auto& st = j["states"][1];  // t = 300 s
    command::Stack stack;
    command::ScenarioRunOptions opts;
    opts.openap = std::shared_ptr<const sim::OpenapData>();
    opts.until = st["t"].get<double>();
    REQUIRE(command::run_scenario(scn, opts, stack).is_ok());
    const sim::Traffic& tr = stack.sim().traffic();
    for (const auto& a : st["aircraft"]) {
      const int i = tr.index_of(a["id"].get<std::string>());
      REQUIRE(i >= 0);
      CAPTURE(name);
      CHECK(gc_m(tr.lat[i], tr.lon[i], a["lat"].get<double>(), a["lon"].get<double>()) < 100.0);
    }
  }
}
