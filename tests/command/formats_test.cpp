// Argument formats against BlueSky's tools/misc.py conversions (docs/bluesky_facts.md §2.2).
#include <doctest/doctest.h>

#include "command/formats.h"
#include "core/units.h"

using namespace squawk;
using namespace squawk::command;

TEST_CASE("altitude: FLnnn and feet, to metres") {
  CHECK(*parse_alt("FL300") == doctest::Approx(30000 * 0.3048));
  CHECK(*parse_alt("fl050") == doctest::Approx(5000 * 0.3048));
  CHECK(*parse_alt("2000.5") == doctest::Approx(2000.5 * 0.3048));
  CHECK(*parse_alt("0.") == 0.0);
  auto bad = parse_alt("FL9X");
  REQUIRE_FALSE(bad);
  CHECK(bad.status().message() == "altitude 'FL9X' is not a flight level (FL0..FL1000) or feet");
  CHECK_FALSE(parse_alt("FL"));  // too short for FL form, not a number either
  CHECK_FALSE(parse_alt("abc"));
}

TEST_CASE("speed: Mach forms vs knots CAS, as BlueSky's txt2spd") {
  for (const char* m : {"M.78", "M0.78", "M78", ".78", "0.78", "m.78"}) {
    auto s = parse_spd(m);
    REQUIRE_MESSAGE(s, m);
    CHECK(s->is_mach);
    CHECK(s->value == doctest::Approx(0.78));
  }
  auto kt = parse_spd("250");
  REQUIRE(kt);
  CHECK_FALSE(kt->is_mach);
  CHECK(kt->value == doctest::Approx(250 * 0.514444));
  // BlueSky's quirk: 1.2 is knots (not in (0.1, 1)), i.e. 0.617 m/s.
  CHECK(parse_spd("1.2")->value == doctest::Approx(1.2 * 0.514444));
  CHECK_FALSE(parse_spd("M1.2.3"));
  CHECK_FALSE(parse_spd("fast"));
  CHECK_FALSE(parse_spd("-250"));
}

TEST_CASE("vertical speed in ft/min") {
  CHECK(*parse_vspd("1500") == doctest::Approx(1500 * 0.3048 / 60));
  CHECK(*parse_vspd("-800") == doctest::Approx(-800 * 0.3048 / 60));
  CHECK_FALSE(parse_vspd("up"));
}

TEST_CASE("heading: digits with T/M prefix or suffix") {
  CHECK(*parse_hdg("090") == 90.0);
  CHECK(*parse_hdg("236.9T") == doctest::Approx(236.9));
  CHECK(*parse_hdg("M270") == 270.0);
  CHECK(*parse_hdg("-10") == -10.0);
  CHECK(*parse_hdg("T045") == 45.0);
  CHECK_FALSE(parse_hdg("north"));
  CHECK_FALSE(is_hdg_number("SPY"));
}

TEST_CASE("time: SS.hh, MM:SS.hh, HH:MM:SS.hh (txt2tim)") {
  CHECK(*parse_time("90") == 90.0);
  CHECK(*parse_time("12.5") == 12.5);
  CHECK(*parse_time("1:30") == 90.0);
  CHECK(*parse_time("0:04:49") == 289.0);
  CHECK(*parse_time("00:30:00") == 1800.0);
  CHECK(*parse_time("01:00:00.25") == 3600.25);
  CHECK(*parse_time(":30") == 30.0);
  CHECK_FALSE(parse_time("1:2:3:4"));
  CHECK_FALSE(parse_time("soon"));
}

TEST_CASE("latitude and longitude: N/S/E/W prefixes, DMS, decimals") {
  CHECK(*parse_lat("52.3") == 52.3);
  CHECK(*parse_lat("-52.3") == -52.3);
  CHECK(*parse_lat("N52.3") == 52.3);
  CHECK(*parse_lat("S12'30'00\"") == doctest::Approx(-12.5));
  CHECK(*parse_lat("N52'14'13.5") == doctest::Approx(52 + 14 / 60.0 + 13.5 / 3600.0));
  CHECK(*parse_lat("N52'35'06.44\"") == doctest::Approx(52 + 35 / 60.0 + 6.44 / 3600.0));
  CHECK(*parse_lat("n52\xC2\xB0" "30'") == doctest::Approx(52.5));
  CHECK_FALSE(parse_lat("91"));
  CHECK_FALSE(parse_lat("52.3N"));
  CHECK(*parse_lon("4.5") == 4.5);
  CHECK(*parse_lon("4e0") == 4.0);
  CHECK(*parse_lon("E004'23'10\"") == doctest::Approx(4 + 23 / 60.0 + 10 / 3600.0));
  CHECK(*parse_lon("W002'") == doctest::Approx(-2.0));
  CHECK(*parse_lon("W65") == -65.0);
  CHECK(*parse_lon("200") == -160.0);
  CHECK_FALSE(parse_lon("4.5W"));
  CHECK(is_lat("N52'18'00\""));
  CHECK(is_lat("-52.3"));
  CHECK_FALSE(is_lat("EHAM"));
  CHECK_FALSE(is_lat("SPY"));
}

TEST_CASE("on/off words") {
  for (const char* t : {"on", "ON", "true", "Yes", "y", "1"}) CHECK(*parse_onoff(t));
  for (const char* f : {"off", "False", "NO", "n", "0"}) CHECK_FALSE(*parse_onoff(f));
  CHECK_FALSE(parse_onoff("maybe"));
}
