// PERF, WIND, AREA, ADDWPT FLYOVER/FLYBY and BlueSky's `0.` heading rule.
#include <doctest/doctest.h>

#include <cmath>

#include "command/stack.h"
#include "core/files.h"
#include "core/geo.h"
#include "core/units.h"

using namespace squawk;
using namespace squawk::command;

namespace {
const std::string kOpenap = std::string(SQUAWK_SOURCE_DIR) + "/../shared/openap/data";
}

TEST_CASE("WIND: a 40 kt west wind drifts a northbound aircraft east; the autopilot holds its track") {
  Stack s(1);
  REQUIRE(s.exec("WIND 52 4 270 40"));
  REQUIRE(s.exec("CRE KL1 A320 52 4 0 FL200 250"));
  const sim::Traffic& t = s.sim().traffic();
  // Heading 0 plus the wind gives the track it keeps: east of north.
  CHECK(t.trk[0] > 5.0);
  CHECK(t.hdg[0] == 0.0);
  REQUIRE(s.run_until(600.0));
  const double east_m = units::nm_to_m(geo::kwikqdrdist(52.0, 4.0, 52.0, t.lon[0]).dist_nm);
  CHECK(east_m == doctest::Approx(600.0 * units::kt_to_ms(40)).epsilon(0.02));
  CHECK(t.gs[0] > t.tas[0]);
  // GETWIND reports it; DEL WIND clears it.
  CHECK(s.exec("GETWIND 52 4 FL200").value() == "WIND AT 52, 4: 270/40");
  REQUIRE(s.exec("DEL WIND"));
  CHECK(s.sim().wind().dim() == 0);
  // A bad definition changes nothing.
  const std::string before = s.snapshot();
  CHECK(!s.exec("WIND 52 4 270 -5"));
  CHECK(!s.exec("WIND 52 4 FL100 270 20 FL50"));
  CHECK(s.snapshot() == before);
}

TEST_CASE("AREA deletes aircraft that leave the box, not those never inside") {
  Stack s(1);
  REQUIRE(s.exec("AREA 51.9 3.9 52.1 4.2"));
  REQUIRE(s.exec("CRE IN1 A320 52 4 270 FL100 250"));
  REQUIRE(s.exec("CRE OUT1 A320 53 4 270 FL100 250"));
  REQUIRE(s.run_until(30.0));
  CHECK(s.sim().n() == 2);
  REQUIRE(s.run_until(120.0));  // IN1 crosses 3.9 E after about 55 s
  CHECK(s.sim().index_of("IN1") < 0);
  CHECK(s.sim().index_of("OUT1") >= 0);
  REQUIRE(s.exec("AREA OFF"));
  CHECK(!s.sim().area_active());
  CHECK(!s.exec("AREA SECTOR1"));  // no such shape
}

TEST_CASE("AREA with named shapes: a circle, then a polygon between altitudes; DEL removes a shape") {
  Stack s(1);
  REQUIRE(s.exec("CIRCLE CTR 52.0 4.2 12"));
  REQUIRE(s.exec("POLYALT UPPER FL250 FL100 52.5 3 53.5 3 53.5 6 52.5 6"));
  REQUIRE(s.exec("AREA CTR"));
  CHECK(s.sim().area_name() == "CTR");
  REQUIRE(s.exec("CRE C1 A320 52.0 4.2 90 FL100 250"));   // leaves the 12 NM circle after ~2 min
  REQUIRE(s.exec("CRE P1 A320 53.0 4.5 0 FL200 250"));
  REQUIRE(s.run_until(60.0));
  CHECK(s.sim().index_of("C1") >= 0);
  REQUIRE(s.run_until(240.0));
  CHECK(s.sim().index_of("C1") < 0);
  CHECK(s.sim().index_of("P1") >= 0);  // never inside the circle
  REQUIRE(s.exec("AREA UPPER"));
  REQUIRE(s.run_until(250.0));
  REQUIRE(s.exec("P1 ALT FL300"));  // climbs out through the polygon's top
  REQUIRE(s.run_until(600.0));
  CHECK(s.sim().index_of("P1") < 0);
  REQUIRE(s.exec("DEL CTR"));
  CHECK(s.sim().shapes().find("CTR") == nullptr);
  auto bad = s.exec("DEL CTR");
  REQUIRE(!bad);
  CHECK(bad.status().message().find("no aircraft or shape 'CTR'") != std::string::npos);
}

TEST_CASE("shape commands that fail leave the simulation byte-identical and name the problem") {
  Stack s(1);
  REQUIRE(s.exec("BOX B 51 3 53 5"));
  const std::string before = s.sim().snapshot();
  for (const char* line : {"POLY P 52 4 53 4", "CIRCLE C 52 4 -3", "BOX B2 95 3 53 5", "AREA NOPE",
                           "POLYALT Q FL300 FL100 52 4"}) {
    auto r = s.exec(line);
    CHECK_MESSAGE(!r, line);
    CHECK_MESSAGE(s.sim().snapshot() == before, line);
  }
  CHECK(s.exec("CIRCLE C 52 4 -3").status().message().find("radius -3 NM must be > 0") != std::string::npos);
  CHECK(s.exec("POLY P 52 4 53 4").status().message().find("at least 3 lat,lon points") != std::string::npos);
  REQUIRE(s.exec("BOX B 51 3 53 5 FL100 FL300"));  // top below bottom: swapped, as BlueSky does
  CHECK(s.sim().shapes().find("B")->top > s.sim().shapes().find("B")->bottom);
}

TEST_CASE("ADDWPT FLYOVER / FLYBY switch the mode of the waypoints added next") {
  Stack s(1);
  REQUIRE(s.exec("CRE KL1 A320 52 4 0 FL200 250"));
  REQUIRE(s.exec("ADDWPT KL1 52.2 4.0"));
  REQUIRE(s.exec("ADDWPT KL1 FLYOVER"));
  REQUIRE(s.exec("ADDWPT KL1 52.3 4.3"));
  REQUIRE(s.exec("ADDWPT KL1 FLYBY"));
  REQUIRE(s.exec("ADDWPT KL1 52.4 4.0"));
  const auto& w = s.sim().traffic().route[0].waypoints();
  REQUIRE(w.size() == 3);
  CHECK(!w[0].flyover);
  CHECK(w[1].flyover);
  CHECK(!w[2].flyover);
}

TEST_CASE("`0.` is refused as a heading, as BlueSky does; 0 and 0.5 are not") {
  Stack s(1);
  CHECK(!s.exec("CRE KL1 B744 0. 0. 0. FL200 400"));
  CHECK(s.sim().n() == 0);
  CHECK(s.exec("CRE KL1 B744 0. 0. 0 FL200 400"));
  CHECK(s.exec("CRE KL2 B744 0. 0. 0.5 FL200 400"));
  CHECK(!s.exec("KL1 HDG 00."));
}

TEST_CASE("PERF switches the performance model of every aircraft") {
  Stack s(1);
  REQUIRE(s.exec("CRE KL1 A320 52 4 0 FL200 250"));
  REQUIRE(s.exec("PERF CLASS"));
  CHECK(s.sim().traffic().oap[0] == nullptr);
  CHECK(!s.exec("PERF OPENAP /nonexistent/openap"));
  CHECK(!s.exec("PERF BADA"));
  if (!files::exists(kOpenap)) {
    MESSAGE("OpenAP part skipped: " << kOpenap << " is absent");
    return;
  }
  REQUIRE(s.exec("PERF OPENAP " + kOpenap));
  const sim::Traffic& t = s.sim().traffic();
  REQUIRE(t.oap[0] != nullptr);
  CHECK(t.oap[0]->name == "A320");
  // OpenAP A320: vmax 163 m/s CAS (de_v_cas_const max), MMO 0.8, ceiling 11 060 m.
  CHECK(t.perf[0].vmax == doctest::Approx(163.0));
  CHECK(t.perf[0].mmo == doctest::Approx(0.8));
  CHECK(t.perf[0].hmax == doctest::Approx(11060.0));
  // Unknown types fly as B744.
  REQUIRE(s.exec("CRE KL2 ZZZZ 52 4 0 FL200 250"));
  CHECK(t.oap[1]->name == "B744");
  // A speed above the envelope is held at vmax; the climb to FL400 stops at the ceiling.
  REQUIRE(s.exec("KL1 SPD 400"));
  REQUIRE(s.exec("KL1 ALT FL400"));
  REQUIRE(s.run_until(900.0));
  CHECK(t.alt[0] == doctest::Approx(11060.0));
  CHECK(t.mach[0] <= 0.8 + 1e-9);
}

TEST_CASE("WIND refuses speeds physics does not give (issue 52); GETWIND stays in range") {
  Stack s(0);
  for (const char* bad : {"WIND 52 4 270 1e20", "WIND 52 4 270 401", "WIND 52 4 270 -1", "WIND 52 4 FL100 270 1e20",
                          "WIND 52 4 270 inf"}) {
    CAPTURE(bad);
    CHECK(!s.exec(bad).is_ok());
  }
  REQUIRE(s.exec("WIND 52 4 FL100 270 400 FL300 90 10"));
  for (const std::string alt : {"0", "FL450", "FL1000", "-2000", "100000"}) {
    CAPTURE(alt);
    auto r = s.exec("GETWIND 52 4 " + alt);
    REQUIRE(r);
    CHECK(r->find("WIND AT 52, 4: ") == 0);
  }
}

// BlueSky's WIND takes profile altitudes as 'float/alt' and multiplies them by ft
// (traffic/windsim.py L12, L43): a plain number is feet, but an FL value is first
// parsed to metres by txt2alt (FL300 -> 9144) and those metres are then read as feet
// (9144 ft = 2787 m). GETWIND's altitude is a plain 'alt' (FL200 = 6096 m).
// Expected strings recorded from BlueSky 22fdf9e via shared/bluesky_ref/run_bluesky.py.
TEST_CASE("WIND profile altitudes as BlueSky reads them: feet, and FL as its metres in feet") {
  Stack s(0);
  SUBCASE("feet: FL200 lies between the layers") {
    REQUIRE(s.exec("WIND 52 4 10000 250 20 30000 270 60"));
    CHECK(s.exec("GETWIND 52 4 FL200").value() == "WIND AT 52, 4: 265/40");
    CHECK(s.exec("GETWIND 52 4 6000").value() == "WIND AT 52, 4: 250/20");
  }
  SUBCASE("FL: the layers sit at 929 m and 2787 m, so FL200 gets the top layer's wind") {
    REQUIRE(s.exec("WIND 52 4 FL100 250 20 FL300 270 60"));
    CHECK(s.exec("GETWIND 52 4 FL200").value() == "WIND AT 52, 4: 270/60");
    CHECK(s.exec("GETWIND 52 4 6000").value() == "WIND AT 52, 4: 265/39");
    CHECK(s.exec("GETWIND 52 4 1000").value() == "WIND AT 52, 4: 250/20");
  }
  SUBCASE("mixed: 10000 ft (3048 m) above FL300 (2787 m) is not increasing and is refused") {
    // BlueSky accepts it and hands the unsorted altitudes to numpy.interp, whose
    // result is undefined for them; squawk refuses and leaves the field empty.
    CHECK(!s.exec("WIND 52 4 10000 250 20 FL300 270 60"));
    CHECK(s.sim().wind().dim() == 0);
  }
}

TEST_CASE("a deadline stops a burst of queued commands inside one instant (--max-time)") {
  Stack s(0);
  REQUIRE(s.exec("CRE KL1 B738 52 4 90 FL200 250"));
  for (int k = 0; k < 1000; ++k) s.schedule(0.0, "ECHO " + std::to_string(k));
  s.set_deadline(std::chrono::steady_clock::now() - std::chrono::seconds(1));
  const Status st = s.run_until(10.0);
  CHECK(st.code() == Code::kTimeout);
  CHECK(s.queued() > 900);  // stopped within the burst, the rest still queued
  CHECK(s.sim().simt() == 0.0);
  s.set_deadline(std::nullopt);
  CHECK(s.run_until(1.0).is_ok());
  CHECK(s.queued() == 0);
}
