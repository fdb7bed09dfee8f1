// Runway thresholds: apt.dat and apt.zip (BlueSky's navdata layout), CRE at a
// runway with the runway's heading, and errors that name what is missing.
// Expected values: tests/data/runways/thresholds.py (BlueSky's threshold
// formulas) and runway_cre.bluesky.json (the real BlueSky on runway_cre.scn
// with tests/data/runways/apt.zip as its apt.zip; see tests/data/runways/README.md).
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "command/navdb.h"
#include "command/runways.h"
#include "command/scenario_run.h"
#include "command/stack.h"
#include "core/files.h"
#include "core/geo.h"
#include "core/units.h"
#include "core/zip.h"
#include "sim/openap_data.h"

using namespace squawk;
using namespace squawk::command;
namespace fs = std::filesystem;

namespace {

const std::string kDir = std::string(SQUAWK_TEST_DATA) + "/runways";

struct Expected {
  const char* apt;
  const char* rwy;
  double lat, lon, brg;
};
// /usr/bin/python3 tests/data/runways/thresholds.py
constexpr Expected kExpected[] = {
    {"EHEH", "03", 51.443301239, 5.364550407, 42.078736009},
    {"EHEH", "21", 51.464100000, 5.394700000, 222.103450351},
    {"EHAM", "18L", 52.321400000, 4.780000000, 183.010723929},
    {"EHAM", "36R", 52.293592328, 4.777608700, 3.008587462},
};

void check_expected(const RunwayDb& db) {
  for (const auto& e : kExpected) {
    CAPTURE(e.apt);
    CAPTURE(e.rwy);
    auto t = db.find(e.apt, e.rwy);
    REQUIRE(t);
    CHECK(t->lat == doctest::Approx(e.lat).epsilon(1e-10));
    CHECK(t->lon == doctest::Approx(e.lon).epsilon(1e-10));
    CHECK(t->bearing_deg == doctest::Approx(e.brg).epsilon(1e-8));
  }
}

// A folder with only the given files of tests/data/runways copied in.
fs::path folder_with(const std::string& name, std::initializer_list<const char*> files) {
  const fs::path d = fs::temp_directory_path() / ("squawk_runways_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  for (const char* f : files) fs::copy_file(fs::path(kDir) / f, d / f);
  return d;
}

Stack stack_with_runways() {
  auto db = NavDb::load(kDir);
  REQUIRE(db);
  Stack s(0);
  s.set_navdb(*db);
  return s;
}

}  // namespace

TEST_CASE("runways: apt.dat thresholds follow BlueSky's formulas; grass runways are skipped") {
  auto db = RunwayDb::load(kDir);  // apt.dat is preferred over apt.zip
  REQUIRE(db);
  check_expected(**db);
  CHECK((*db)->find("EHEH", "Y03"));  // "RWY03"
  CHECK((*db)->find("EHAM", "6"));    // padded to "06"
  auto grass = (*db)->find("EHEH", "09");
  REQUIRE_FALSE(grass);
  CHECK(grass.status().message().find("EHEH has runways 03, 21") != std::string::npos);
  auto none = (*db)->find("XSEA", "08");
  REQUIRE_FALSE(none);
  CHECK(none.status().message().find("no asphalt or concrete runways for XSEA") != std::string::npos);
}

TEST_CASE("runways: apt.zip gives the same thresholds; a damaged archive is an error naming it") {
  const fs::path d = folder_with("zip", {"apt.zip"});
  auto db = RunwayDb::load(d.string());
  REQUIRE(db);
  check_expected(**db);

  const std::string zip = files::read((d / "apt.zip").string()).value();
  auto sink = [](std::string_view) { return Status::ok(); };
  // Every truncation and every single-byte change is an error or the same data, never a crash.
  for (size_t n = 0; n < zip.size(); ++n) CHECK_FALSE(zip::read_member(zip.substr(0, n), "apt.dat", "t", sink).is_ok());
  int changed_ok = 0;
  for (size_t i = 0; i < zip.size(); ++i) {
    std::string z = zip;
    z[i] = static_cast<char>(z[i] ^ 0x5a);
    std::string out;
    const Status st = zip::read_member(z, "apt.dat", "t.zip", [&](std::string_view c) {
      out.append(c);
      return Status::ok();
    });
    if (st.is_ok()) {
      ++changed_ok;  // a byte outside what the reader checks (times, attributes)
      CHECK(out == files::read(kDir + "/apt.dat").value());
    } else {
      CHECK(st.message().find("t.zip") != std::string::npos);
    }
  }
  CHECK(changed_ok <= 64);  // header fields it does not use: versions, times, attributes, local copies
  auto missing = zip::read_member(zip, "other.dat", "t.zip", sink);
  CHECK(missing.code() == Code::kNotFound);

  const fs::path empty = folder_with("none", {});
  auto none = RunwayDb::load(empty.string());
  REQUIRE_FALSE(none);
  CHECK(none.status().message().find("no apt.dat or apt.zip") != std::string::npos);
}

TEST_CASE("runways: apt.dat errors name the file and line") {
  auto bad = RunwayDb::parse("1 0 0 0 EHEH x\n100 45 1 0 0.25 1 2 1 03 51.4 5.3 0\n", "a.dat");
  REQUIRE_FALSE(bad);
  CHECK(bad.status().message() == "a.dat:2: runway row has 12 fields, expected at least 21");
  auto orphan = RunwayDb::parse(
      "100 45 1 0 0.25 1 2 1 03 51.4 5.3 0 0 3 0 0 1 21 51.5 5.4 0 0 3 0 0 1\n", "a.dat");
  REQUIRE_FALSE(orphan);
  CHECK(orphan.status().message() == "a.dat:1: runway row before any airport header");
  auto range = RunwayDb::parse(
      "1 0 0 0 X\n100 45 1 0 0.25 1 2 1 03 91 5.3 0 0 3 0 0 1 21 51.5 5.4 0 0 3 0 0 1\n", "a.dat");
  REQUIRE_FALSE(range);
  CHECK(range.status().message().find("a.dat:2: runway end '03'") == 0);
}

TEST_CASE("runways: CRE at a runway threshold takes the runway heading when none is given") {
  Stack s = stack_with_runways();
  const auto& t = s.sim().traffic();
  // BlueSky's own EHEH_SID.scn line; '*' reads as an omitted heading.
  REQUIRE(s.exec("CRE KL204,E190, EHEH, RWY03, *,  0, 0"));
  REQUIRE(s.exec("CRE KL205 E190 EHAM/RW36R"));
  REQUIRE(s.exec("CRE KL206 A320 EHAM RW18L 90 FL100 250"));
  CHECK(t.lat[0] == doctest::Approx(kExpected[0].lat).epsilon(1e-10));
  CHECK(t.lon[0] == doctest::Approx(kExpected[0].lon).epsilon(1e-10));
  CHECK(t.hdg[0] == doctest::Approx(kExpected[0].brg).epsilon(1e-8));
  CHECK(t.hdg[1] == doctest::Approx(kExpected[3].brg).epsilon(1e-8));
  CHECK(t.lat[2] == doctest::Approx(kExpected[2].lat).epsilon(1e-10));
  CHECK(t.hdg[2] == doctest::Approx(90.0));
  // A plain position keeps BlueSky's default heading 0.
  REQUIRE(s.exec("CRE KL207 A320 EHEH * FL100 250"));
  CHECK(t.hdg[3] == doctest::Approx(0.0));
  // Runway names in other commands: the threshold, not the airport's point.
  REQUIRE(s.exec("KL206 ADDWPT EHEH/RW21"));
  CHECK(t.route[2].waypoints().back().lat == doctest::Approx(kExpected[1].lat).epsilon(1e-10));
}

TEST_CASE("runways: an unknown runway, a grass runway or missing data is refused and changes nothing") {
  Stack s = stack_with_runways();
  REQUIRE(s.exec("CRE KL1 A320 52 4 90 FL100 250"));
  const std::string before = s.snapshot();
  auto r = s.exec("CRE KL2 A320 EHEH RW04 * FL100 250");
  REQUIRE_FALSE(r);
  CHECK(r.status().message().find("EHEH has runways 03, 21") != std::string::npos);
  CHECK_FALSE(s.exec("CRE KL2 A320 EHEH/RW09"));  // grass
  CHECK_FALSE(s.exec("CRE KL2 A320 EHEH/RW"));
  CHECK_FALSE(s.exec("HDG KL1 *"));  // '*' stands for an omitted heading only where one may be omitted
  CHECK(s.snapshot() == before);

  // Navdata without runway data: refused, never the airport's reference point.
  auto plain = NavDb::load(folder_with("plain", {"airports.dat", "nav.dat", "fix.dat"}).string());
  REQUIRE(plain);
  Stack p(0);
  p.set_navdb(*plain);
  auto q = p.exec("CRE KL1 A320 EHEH RWY03 * FL100 250");
  REQUIRE_FALSE(q);
  CHECK(q.status().message().find("no apt.dat or apt.zip") != std::string::npos);
  CHECK(p.sim().n() == 0);
  REQUIRE(p.exec("CRE KL1 A320 EHEH 90 FL100 250"));  // the airport alone still resolves
}

TEST_CASE("runways: CRE at runways flies as in the real BlueSky (OpenAP)" * doctest::test_suite("shared")) {
  const std::string openap = std::string(SQUAWK_SOURCE_DIR) + "/../shared/openap/data";
  if (!files::exists(openap)) {
    MESSAGE("skipped: " << openap << " is absent (OpenAP data is not part of squawk)");
    return;
  }
  auto data = sim::OpenapData::load(openap);
  REQUIRE(data.is_ok());
  auto db = NavDb::load(kDir);
  REQUIRE(db);
  const auto j = nlohmann::json::parse(files::read(kDir + "/runway_cre.bluesky.json").value());
  int cases = 0;
  for (const auto& st : j["states"]) {
    Stack stack;
    ScenarioRunOptions opts;
    opts.openap = data.value();
    opts.navdb = *db;
    opts.until = st["t"].get<double>();
    REQUIRE(run_scenario(kDir + "/runway_cre.scn", opts, stack).is_ok());
    const auto& tr = stack.sim().traffic();
    for (const auto& a : st["aircraft"]) {
      const int i = tr.index_of(a["id"].get<std::string>());
      REQUIRE(i >= 0);
      CAPTURE(a["id"].get<std::string>());
      CAPTURE(opts.until.value());
      const auto d = geo::qdrdist(tr.lat[i], tr.lon[i], a["lat"].get<double>(), a["lon"].get<double>());
      CHECK(units::nm_to_m(d.dist_nm) < 100.0);
      CHECK(tr.hdg[i] == doctest::Approx(a["hdg_deg"].get<double>()).epsilon(1e-6));
      ++cases;
    }
  }
  CHECK(cases == 9);
}
