// Stack: line rules, handlers, errors that leave state unchanged, timed and
// conditional commands, scenario files.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>

#include "command/registry.h"
#include "command/stack.h"
#include "core/files.h"
#include "core/geo.h"
#include "core/units.h"
#include "failed_exec.h"

using namespace squawk;
using namespace squawk::command;
using squawk::test::error_of;
namespace fs = std::filesystem;

namespace {

Stack with_kl204() {
  Stack s(1);
  auto r = s.exec("CRE KL204 B744 52.0 4.0 90 FL200 250");
  REQUIRE(r);
  return s;
}

fs::path temp_dir(const char* name) {
  fs::path d = fs::temp_directory_path() / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

}  // namespace

TEST_CASE("CRE then state in SI; acid-first form; bare callsign = POS") {
  Stack s = with_kl204();
  const auto& t = s.sim().traffic();
  REQUIRE(t.n() == 1);
  CHECK(t.alt[0] == doctest::Approx(20000 * 0.3048));
  CHECK(t.hdg[0] == doctest::Approx(90));
  CHECK(t.cas[0] == doctest::Approx(250 * 0.514444).epsilon(1e-6));
  REQUIRE(s.exec("kl204 alt fl300"));
  CHECK(t.sel_alt[0] == doctest::Approx(30000 * 0.3048));
  REQUIRE(s.exec("KL204, SPD, M.80"));
  CHECK(t.sel_spd[0] == doctest::Approx(0.80));
  auto pos = s.exec("KL204");
  REQUIRE(pos);
  CHECK(pos->find("KL204 B744 at 52.00000 4.00000") == 0);
  auto both = s.exec("HDG KL204 180; VS KL204 2000");
  REQUIRE(both);
  CHECK(t.sel_hdg[0] == doctest::Approx(180));
}

TEST_CASE("errors name the argument and the expected form; state unchanged") {
  Stack s = with_kl204();
  CHECK(error_of(s, "ALT KL204 FL9X") ==
        "ALT KL204 FL9X: argument 2: altitude 'FL9X' is not a flight level (FL0..FL1000) or feet "
        "(usage: ALT acid,alt,[vspd])");
  CHECK(error_of(s, "ALT KL999 FL100").find("no aircraft 'KL999'") != std::string::npos);
  CHECK(error_of(s, "KL999 ALT FL100").find("no aircraft 'KL999'") != std::string::npos);
  CHECK(error_of(s, "FROB 1 2").find("unknown command or aircraft 'FROB'") != std::string::npos);
  CHECK(error_of(s, "ALT KL204").find("missing argument 2 (altitude)") != std::string::npos);
  CHECK(error_of(s, "VS KL204 900 12").find("takes 2 arguments, but 3 were given") != std::string::npos);
  CHECK(error_of(s, "HDG KL204 90 LEFT 12").find("takes 3 arguments, but 4 were given") != std::string::npos);
  CHECK(error_of(s, "CRE KL204 B744 52 4 0 FL100 250").find("KL204") != std::string::npos);
  CHECK(error_of(s, "CRE X1 B744 EHAM").find("no navdata loaded") != std::string::npos);
  CHECK(error_of(s, "LNAV KL204 ON").find("KL204") != std::string::npos);
  CHECK(error_of(s, "DIRECT KL204 SPY").find("not in the route") != std::string::npos);
  // Only the failing command of a line is undone; earlier ones stay.
  auto r = s.exec("HDG KL204 10; ALT KL204 nope");
  CHECK_FALSE(r);
  CHECK(s.sim().traffic().sel_hdg[0] == doctest::Approx(10));
}

TEST_CASE("check() validates without running") {
  Stack s = with_kl204();
  const std::string before = s.snapshot();
  CHECK(s.check("ALT KL204 FL100; KL204 SPD 250"));
  CHECK_FALSE(s.check("ALT KL204 FL1X"));
  CHECK_FALSE(s.check("WIBBLE"));
  CHECK(s.snapshot() == before);
}

TEST_CASE("HDG turns at the bank-angle rate; run_until reaches the target") {
  Stack s = with_kl204();
  REQUIRE(s.exec("HDG KL204 180"));
  REQUIRE(s.run_until(5.0));
  const auto& t = s.sim().traffic();
  // Turn rate g0 tan(25 deg) / TAS [deg/s] (BlueSky traffic.py).
  const double rate = units::rad_to_deg(9.80665 * std::tan(units::deg_to_rad(25)) / t.tas[0]);
  CHECK(t.hdg[0] == doctest::Approx(90 + 5 * rate).epsilon(0.02));
  REQUIRE(s.run_until(200.0));
  CHECK(t.hdg[0] == doctest::Approx(180));
}

// Headings seen at each step of dt, until t_end [s].
std::vector<double> headings_until(Stack& s, double t_end) {
  std::vector<double> seen;
  while (s.sim().simt() < t_end - 1e-9) {
    REQUIRE(s.run_until(s.sim().simt() + s.sim().dt()));
    seen.push_back(s.sim().traffic().hdg[0]);
  }
  return seen;
}

bool passes_near(const std::vector<double>& seen, double hdg) {
  for (double h : seen)
    if (std::fabs(geo::wrap180(h - hdg)) < 5.0) return true;
  return false;
}

TEST_CASE("HDG ... RIGHT / LEFT turn the commanded way, the long way round when it must") {
  Stack s(1);
  REQUIRE(s.exec("CRE BAW8CK A320 52.0 4.0 025 FL200 250"));
  REQUIRE(s.exec("HDG BAW8CK 300 RIGHT"));
  CHECK(s.sim().traffic().sel_turn[0] == 1);
  auto seen = headings_until(s, 400.0);
  // 025 -> 300 to the right passes 090 and 180 (the short way, left, passes neither)
  CHECK(passes_near(seen, 90.0));
  CHECK(passes_near(seen, 180.0));
  CHECK(s.sim().traffic().hdg[0] == doctest::Approx(300));
  CHECK(s.sim().traffic().sel_turn[0] == 0);  // captured: the direction is spent

  REQUIRE(s.exec("HDG BAW8CK 020 L"));
  CHECK(s.sim().traffic().sel_turn[0] == -1);
  seen = headings_until(s, 800.0);
  // 300 -> 020 to the left goes via 200 (the short way, right, passes 340)
  CHECK(passes_near(seen, 200.0));
  CHECK_FALSE(passes_near(seen, 340.0));
  CHECK(s.sim().traffic().hdg[0] == doctest::Approx(20));

  // without a direction, BlueSky's meaning: the short way
  REQUIRE(s.exec("HDG BAW8CK 300"));
  CHECK(s.sim().traffic().sel_turn[0] == 0);
  seen = headings_until(s, 1000.0);
  CHECK_FALSE(passes_near(seen, 180.0));
  CHECK(s.sim().traffic().hdg[0] == doctest::Approx(300));

  const std::string msg = error_of(s, "HDG BAW8CK 100 UP");
  CHECK(msg.find("'UP'") != std::string::npos);
  CHECK(msg.find("LEFT, RIGHT") != std::string::npos);
}

TEST_CASE("a .scn file can command a turn direction") {
  const fs::path d = temp_dir("squawk_command_turn_scn");
  REQUIRE(files::write_atomic((d / "turn.scn").string(),
                              "00:00:00.00>CRE KL204 B744 52 4 025 FL200 250\n"
                              "00:00:01.00>KL204 HDG 300 RIGHT\n"));
  Stack s(3);
  s.set_base_dir(d.string());
  REQUIRE(s.exec("IC turn.scn"));
  REQUIRE(s.run_until(1.0));
  CHECK(s.tally().failed.empty());
  CHECK(s.sim().traffic().sel_turn[0] == 1);
  const auto seen = headings_until(s, 400.0);
  CHECK(passes_near(seen, 180.0));
  CHECK(s.sim().traffic().hdg[0] == doctest::Approx(300));
}

TEST_CASE("SCHEDULE, DELAY and ECHO run at their times") {
  Stack s = with_kl204();
  REQUIRE(s.exec("SCHEDULE 00:00:10 KL204 ALT FL100"));
  REQUIRE(s.exec("DELAY 5 ECHO five seconds"));
  CHECK(s.queued() == 2);
  REQUIRE(s.run_until(4.9));
  CHECK(s.take_output().empty());
  REQUIRE(s.run_until(5.0));
  CHECK(s.take_output() == std::vector<std::string>{"five seconds"});
  CHECK(s.sim().traffic().sel_alt[0] == doctest::Approx(20000 * 0.3048));
  REQUIRE(s.run_until(10.0));
  CHECK(s.sim().traffic().sel_alt[0] == doctest::Approx(10000 * 0.3048));
  CHECK(s.queued() == 0);
}

TEST_CASE("ATALT / ATSPD / ATDIST fire once when the threshold is crossed") {
  Stack s = with_kl204();
  REQUIRE(s.exec("ALT KL204 FL210 2000"));
  REQUIRE(s.exec("KL204 ATALT 20500 ECHO passing 20500"));
  REQUIRE(s.exec("KL204 ATDIST 52.0 4.2 5 ECHO within 5"));
  CHECK(s.conditions().size() == 2);
  // Climb at 2000 fpm after the 300 ft/min/s ramp (5.7 s, 80 ft): 500 ft take 18.3 s.
  REQUIRE(s.run_until(17.8));
  CHECK(s.take_output().empty());
  REQUIRE(s.run_until(18.8));
  CHECK(s.take_output() == std::vector<std::string>{"passing 20500"});
  CHECK(s.conditions().size() == 1);
  // 0.2 deg of longitude at 52N is 7.39 NM; at ~300 kt TAS it takes ~29 s to close 2.4 NM.
  REQUIRE(s.run_until(60.0));
  CHECK(s.take_output() == std::vector<std::string>{"within 5"});
  CHECK(s.conditions().empty());
}

TEST_CASE("DEFWPT, ADDWPT, route listing, AT constraints, DIRECT, DELWPT") {
  Stack s = with_kl204();
  REQUIRE(s.exec("DEFWPT ALPHA 52.0 4.5"));
  REQUIRE(s.exec("DEFWPT BRAVO N52'10'00\" E004'50'00\""));
  REQUIRE(s.exec("ADDWPT KL204 ALPHA FL200"));
  REQUIRE(s.exec("ADDWPT KL204 BRAVO,,280"));
  REQUIRE(s.exec("ADDWPT KL204 52.3 5.0"));
  // AT works on a copy that replaces the simulation: read the route afresh.
  auto route = [&s]() -> const sim::Route& { return s.sim().traffic().route[0]; };
  REQUIRE(route().size() == 3);
  CHECK(route().waypoints()[2].name == "KL204003");
  CHECK(route().waypoints()[1].spd == doctest::Approx(280 * 0.514444));
  CHECK(s.sim().traffic().lnav[0] == 1);
  auto list = s.exec("LISTRTE KL204");
  REQUIRE(list);
  CHECK(list->find("* ALPHA") != std::string::npos);
  REQUIRE(s.exec("KL204 AT BRAVO ALT FL150"));
  CHECK(route().waypoints()[1].alt == doctest::Approx(15000 * 0.3048));
  CHECK(route().waypoints()[1].spd == doctest::Approx(280 * 0.514444));
  CHECK(route().active() == 0);
  REQUIRE(s.exec("KL204 AT ALPHA FL180/250"));
  CHECK(route().waypoints()[0].alt == doctest::Approx(18000 * 0.3048));
  CHECK(route().active() == 0);
  REQUIRE(s.exec("DIRECT KL204 BRAVO"));
  CHECK(route().active() == 1);
  CHECK(error_of(s, "KL204 AFTER BRAVO ADDWPT CHARLIE").find("'CHARLIE'") != std::string::npos);
  // a latitude for the new waypoint (BlueSky reads one token there) says how to name the point
  CHECK(error_of(s, "KL204 AFTER BRAVO ADDWPT 52.2 4.9").find("'52.2' is a latitude") !=
        std::string::npos);
  CHECK(route().size() == 3);
  REQUIRE(s.exec("DEFWPT CHARLIE 52.2 4.9"));
  REQUIRE(s.exec("KL204 AFTER BRAVO ADDWPT CHARLIE FL120"));
  CHECK(route().waypoints()[2].name == "CHARLIE");
  REQUIRE(s.exec("DELWPT KL204 CHARLIE"));
  CHECK(route().size() == 3);
  REQUIRE(s.exec("DELRTE KL204"));
  CHECK(route().empty());
  CHECK(s.sim().traffic().lnav[0] == 0);
}

TEST_CASE("IC and PCALL: relative times, %n arguments, CR line ends, unknown commands skipped by name") {
  const fs::path d = temp_dir("squawk_command_scn");
  REQUIRE(files::write_atomic((d / "main.scn").string(),
                              "00:00:00.00>CRE KL204 B744 52 4 90 FL200 250\r"
                              "00:00:00.00>PAN KL204;ZOOM 2\r"
                              "00:00:10.00>PCALL proc.SCN KL204 FL100\r"
                              "00:00:30.00>ECHO done\r"));
  REQUIRE(files::write_atomic((d / "proc.SCN").string(),
                              "00:00:00.00>%0 ALT %1\n"
                              "00:00:05.00>ECHO proc five %0\n"));
  Stack s(3);
  s.set_base_dir(d.string());
  REQUIRE(s.exec("IC main"));
  CHECK(s.sim().n() == 1);
  CHECK(s.tally().skipped.at("PAN") == 1);
  CHECK(s.tally().skipped.at("ZOOM") == 1);
  REQUIRE(s.run_until(10.0));
  CHECK(s.sim().traffic().sel_alt[0] == doctest::Approx(10000 * 0.3048));
  REQUIRE(s.run_until(14.9));
  CHECK(s.take_output().empty());
  REQUIRE(s.run_until(15.0));
  CHECK(s.take_output() == std::vector<std::string>{"proc five KL204"});
  REQUIRE(s.run_until(30.0));
  CHECK(s.take_output() == std::vector<std::string>{"done"});
  CHECK(s.tally().failed.empty());
  // IC resets: the aircraft is recreated at time 0.
  REQUIRE(s.exec("IC main.scn"));
  CHECK(s.sim().simt() == 0.0);
  CHECK(s.sim().n() == 1);
  CHECK(error_of(s, "IC nowhere").find("no scenario file 'nowhere'") != std::string::npos);
}

TEST_CASE("TRAIL: on/off with the point interval, a colour per aircraft; part of the state; RESET clears it") {
  Stack s = with_kl204();
  CHECK(s.exec("TRAIL").value() == "TRAIL OFF, a point every 10 s");
  std::string before = s.snapshot();
  REQUIRE(s.exec("TRAIL ON 5"));
  CHECK(s.snapshot() != before);
  CHECK(s.trails().on);
  CHECK(s.trails().dt == doctest::Approx(5.0));
  REQUIRE(s.exec("TRAILS KL204 RED"));
  CHECK(s.trails().colour.at("KL204") == "RED");
  CHECK(error_of(s, "TRAIL KL204 GREEN").find("BLUE, RED or YELLOW, got 'GREEN'") != std::string::npos);
  CHECK(error_of(s, "TRAIL ON fast").find("seconds, got 'FAST'") != std::string::npos);
  CHECK(error_of(s, "TRAIL ON 0").find("must be > 0 s") != std::string::npos);
  CHECK(error_of(s, "TRAIL KL999 RED").find("no aircraft 'KL999'") != std::string::npos);
  REQUIRE(s.exec("TRAIL OFF"));
  CHECK(s.exec("TRAIL").value() == "TRAIL OFF, a point every 5 s");
  s.reset();
  CHECK(s.trails().colour.empty());
  CHECK(s.trails().dt == doctest::Approx(10.0));
}

TEST_CASE("RESET, SEED and MCRE are reproducible") {
  Stack a(0), b(0);
  REQUIRE(a.exec("SEED 42; MCRE 5"));
  REQUIRE(b.exec("SEED 42; MCRE 5"));
  CHECK(a.sim().n() == 5);
  CHECK(a.snapshot() == b.snapshot());
  REQUIRE(a.exec("RESET"));
  CHECK(a.sim().n() == 0);
  CHECK(a.sim().simt() == 0.0);
}

TEST_CASE("CRECONFS with ASAS ON gives a conflict at the set geometry") {
  Stack s = with_kl204();
  REQUIRE(s.exec("ASAS ON"));
  REQUIRE(s.exec("CRECONFS INT1 A320 KL204 90 0 120"));
  REQUIRE(s.run_until(2.0));
  REQUIRE(s.sim().conflicts().size() == 2);
  const auto& c = s.sim().conflicts()[0];
  CHECK(c.dcpa < 0.05 * 1852.0);  // set to 0 NM; flat-earth placement vs detection differ slightly
  CHECK(c.tlos == doctest::Approx(118.0).epsilon(0.02));
  auto r = s.exec("DTLOOK");
  REQUIRE(r);
  CHECK(*r == "DTLOOK 300 s");
  REQUIRE(s.exec("ZONER 3; ZONEDH 500; RESO MVP; RFACH 1.1"));
  CHECK(s.sim().cd_settings().rpz == doctest::Approx(3 * 1852.0));
  CHECK(s.sim().cd_settings().hpz == doctest::Approx(500 * 0.3048));
  CHECK(s.sim().cr_settings().enabled);
}

TEST_CASE("OP ends fast-time and sets DTMULT 1; DTMULT after OP keeps its rate; RESET sets 1") {
  Stack s(1);
  REQUIRE(s.exec("FF"));
  REQUIRE(s.exec("OP"));
  CHECK(!s.sim().fast());
  CHECK(s.sim().run_state() == sim::RunState::kOp);
  REQUIRE(s.exec("DTMULT 4"));
  REQUIRE(s.exec("OP"));
  CHECK(s.dtmult() == 1.0);
  REQUIRE(s.exec("DTMULT 4"));
  CHECK(s.dtmult() == 4.0);
  CHECK(s.sim().run_state() == sim::RunState::kOp);
  REQUIRE(s.exec("HOLD"));
  CHECK(s.dtmult() == 4.0);
  REQUIRE(s.exec("RESET"));
  CHECK(s.dtmult() == 1.0);
}

TEST_CASE("copies are independent (the translator validates on a scratch copy)") {
  Stack s = with_kl204();
  Stack scratch = s;
  REQUIRE(scratch.exec("DEL KL204"));
  CHECK(scratch.sim().n() == 0);
  CHECK(s.sim().n() == 1);
}

TEST_CASE("navdata: airports, fixes and navaids resolve where BlueSky accepts them" * doctest::test_suite("shared")) {
  const fs::path dir = fs::path(SQUAWK_SHARED_DIR) / "bluesky" / "navdata";
  if (!fs::is_directory(dir)) {
    MESSAGE("skipped: " << dir.string() << " not found (BlueSky navdata is optional)");
    return;
  }
  auto db = NavDb::load(dir.string());
  REQUIRE(db);
  MESSAGE((*db)->airport_count() << " airports, " << (*db)->waypoint_count() << " fixes and navaids");
  Stack s(0);
  s.set_navdb(*db);
  // BlueSky's navdata folder here has no apt.zip: a runway is refused, not
  // placed at the airport's reference point (runways_test.cpp has thresholds).
  auto rwy = s.exec("CRE KL204,B744,EHAM/RW18L,0,2000,150");
  REQUIRE_FALSE(rwy);
  CHECK(rwy.status().message().find("apt.zip") != std::string::npos);
  REQUIRE(s.exec("CRE KL204,B744,EHAM,0,2000,150"));
  const auto& t = s.sim().traffic();
  // EHAM's reference point in airports.dat.
  CHECK(t.lat[0] == doctest::Approx(52.309).epsilon(1e-3));
  CHECK(t.lon[0] == doctest::Approx(4.764).epsilon(1e-3));
  REQUIRE(s.exec("KL204 ADDWPT SPY FL100"));
  REQUIRE(s.exec("DEST KL204 EGLL"));
  REQUIRE(s.exec("ORIG KL204 EHAM"));
  const auto& r = t.route[0];
  REQUIRE(r.size() == 2);
  CHECK(r.waypoints()[0].name == "SPY");
  CHECK(r.waypoints()[1].name == "EGLL");
  // HDG to a name: the bearing from the aircraft to it.
  REQUIRE(s.exec("HDG KL204 EGLL"));
  CHECK(t.sel_hdg[0] == doctest::Approx(geo::kwikqdrdist(t.lat[0], t.lon[0], r.waypoints()[1].lat,
                                                         r.waypoints()[1].lon).qdr_deg));
  auto pos = s.exec("POS SPY");
  REQUIRE(pos);
  CHECK(pos->rfind("SPY at 52.5", 0) == 0);
  CHECK_FALSE(s.exec("ADDWPT KL204 NOSUCHFIX"));
}


TEST_CASE("navdata: airports by name, whole or with a generic word, never a prefix of another name") {
  auto db = NavDb::parse(
      "# code,name,lat,lon,class\n"
      "EHAM, SCHIPHOL, 52.309, 4.764, Large, 12467, NL,-11\n"
      "EGLL, Heathrow Airport, 51.477, -0.461, Large, 12799, UK,83\n"
      "CYSY, Sachs Harbour, 71.99, -125.24, Small, , CA,\n"
      "KDEN, DENVER INTL, 39.862, -104.673, Large, 16000, US/CO,5431\n"
      "KLGA, LA GUARDIA, 40.777, -73.873, Large, 7000, US/NY,22\n",
      "", "", "test");
  REQUIRE(db.is_ok());
  auto ids = [&](const char* name) {
    std::vector<std::string> out;
    for (const NavPoint* a : (*db)->airports_named(name)) out.push_back(a->id);
    return out;
  };
  CHECK(ids("schiphol") == std::vector<std::string>{"EHAM"});
  CHECK(ids("Heathrow") == std::vector<std::string>{"EGLL"});
  CHECK(ids("heathrow airport") == std::vector<std::string>{"EGLL"});
  CHECK(ids("sachs").empty());
  CHECK(ids("sachs harbour") == std::vector<std::string>{"CYSY"});
  // "International" as said is the navdata's INTL
  CHECK(ids("Denver International") == std::vector<std::string>{"KDEN"});
  CHECK(ids("denver intl") == std::vector<std::string>{"KDEN"});
  // said as one word where the navdata writes two
  CHECK(ids("LaGuardia") == std::vector<std::string>{"KLGA"});
  CHECK(ids("la guardia") == std::vector<std::string>{"KLGA"});
  CHECK(ids("guardia").empty());
  CHECK(ids("").empty());
}

TEST_CASE(
    "navdata: a city is the large airport whose name starts with it; classes as airports.dat gives "
    "them") {
  auto db = NavDb::parse(
      "EDDF, FRANKFURT MAIN, 50.026, 8.543, Large, 13123, GM,364\n"
      "EDFH, FRANKFURT HAHN, 49.949, 7.264, Medium, 11483, GM,1649\n"
      "FAAM, Amsterdam Airport, -26.633, 30.6, Small, , SF,4310\n"
      "EHAM, SCHIPHOL, 52.309, 4.764, Large, 12467, NL,-11\n"
      "XXXX, Frankfurter, 1.0, 1.0, Large\n"
      "KPFN, PANAMA CITY BAY CO INTL, 30.212, -85.683, Large, 6308, US/FL,20\n",
      "", "", "test");
  REQUIRE(db.is_ok());
  auto ids = [&](const char* name) {
    std::vector<std::string> out;
    for (const NavPoint* a : (*db)->airports_of_city(name)) out.push_back(a->id);
    return out;
  };
  CHECK(ids("Frankfurt") ==
        std::vector<std::string>{"EDDF"});  // not the medium Hahn, nor "Frankfurter"
  CHECK(ids("frankfurt main").empty());     // the whole name is no city of it
  CHECK(ids("amsterdam").empty());          // a small field named so is no city's
  CHECK(ids("panama").empty());             // the country, not Panama City
  CHECK(ids("panama city") == std::vector<std::string>{"KPFN"});
  CHECK(ids("").empty());
  CHECK((*db)->airport_class("FAAM") == "SMALL");
  CHECK((*db)->airport_class("EDDF") == "LARGE");
  CHECK((*db)->airport_class("NONE").empty());
}

TEST_CASE("navdata: an airport by words its name holds; words of a field's kind alone name none") {
  auto db = NavDb::parse(
      "KMDW, CHICAGO MIDWAY INTL, 41.786, -87.752, Large, 6059, US/IL,620\n"
      "KDAL, DALLAS LOVE FLD, 32.847, -96.852, Large, 8800, US/TX,487\n"
      "KPRC, ERNEST A LOVE FLD, 34.654, -112.42, Large, 7550, US/AZ,5045\n"
      "KXYZ, SOMEWHERE COUNTY RGNL, 1.0, 1.0, Small\n",
      "", "", "test");
  REQUIRE(db.is_ok());
  auto ids = [&](const char* words) {
    std::vector<std::string> out;
    for (const NavPoint* a : (*db)->airports_with_words(words)) out.push_back(a->id);
    return out;
  };
  CHECK(ids("Midway") == std::vector<std::string>{"KMDW"});
  CHECK(ids("chicago midway international") == std::vector<std::string>{"KMDW"});
  CHECK(ids("Dallas Love Field") == std::vector<std::string>{"KDAL"});  // "Field" as written: FLD
  CHECK(ids("love field") == std::vector<std::string>{"KDAL", "KPRC"});
  CHECK(ids("midw").empty());  // whole words only
  CHECK(ids("county regional").empty());
  CHECK(ids("international").empty());
  CHECK(ids("").empty());
}

TEST_CASE(
    "navdata: a city named by its navaids is the large airport within 10 NM of them, else the "
    "medium one") {
  auto db = NavDb::parse(
      "LFBO, BLAGNAC, 43.629, 1.364, Large, 11483, FR,499\n"
      "LFBF, FRANCAZAL, 43.545, 1.368, Medium, 5900, FR,535\n"
      "LSZB, BERN BELP, 46.914, 7.497, Medium, 4594, SZ,1674\n"
      "XXXX, FAR FIELD, 44.0, 3.0, Large\n"
      "EGLL, HEATHROW, 51.477, -0.461, Large, 12799, UK,83\n"
      "EGKK, GATWICK, 51.148, -0.19, Large, 9486, UK,202\n"
      "EGNX, EAST MIDLANDS, 52.831, -1.328, Large, 9491, UK,306\n",
      "3  51.487 -0.467 0 11330 50 0.0 LON  LONDON VOR-DME\n"
      "3  43.68 1.31 0 11710 60 0.0 TOU  TOULOUSE VOR-DME\n"
      "2  46.91 7.50 0 336 50 0.0 BER  BERN NDB\n"
      "3  45.0 5.0 0 11000 40 0.0 NOW  NOWHERE VOR\n",
      "", "test");
  REQUIRE(db.is_ok());
  auto ids = [&](const char* name) {
    std::vector<std::string> out;
    for (const NavPoint* a : (*db)->airports_beside_navaids(name)) out.push_back(a->id);
    return out;
  };
  CHECK(ids("Toulouse") == std::vector<std::string>{"LFBO"});  // the large one, not Francazal
  CHECK(ids("bern") == std::vector<std::string>{"LSZB"});      // a medium one when no large
  CHECK(ids("nowhere").empty());                               // no airport within 10 NM
  // a city of several large airports (within 30 NM) is no one airport; one farther is not its
  CHECK(ids("London") == std::vector<std::string>{"EGLL", "EGKK"});
  CHECK(ids("blagnac").empty());  // an airport's name is no navaid's
  CHECK(ids("").empty());
}

TEST_CASE(
    "navdata: navaids by name less their kind, near a point, nearest first, each ident once") {
  auto db = NavDb::parse(
      "EHAM, SCHIPHOL, 52.309, 4.764, Large, 12467, NL,-11\n",
      "3  37.61947222 -122.37388889      7 11580  40   17.0 SFO  SAN FRANCISCO VOR-DME\n"
      "12  37.61948333 -122.37389167      7 11580  40    0.0 SFO  SAN FRANCISCO VOR-DME\n"
      "3  38.07962500 -122.86786667     16 11390  40   17.0 PYE  POINT REYES VOR-DME\n"
      "3  51.0 1.0 0 11000 40 0.0 PYX  POINT REYES VOR\n",
      "", "test");
  REQUIRE(db.is_ok());
  const double lat = 37.75, lon = -122.55;
  auto idents = [&](const std::vector<const NavPoint*>& points) {
    std::vector<std::string> ids;
    for (const NavPoint* p : points) ids.push_back(p->id);
    return ids;
  };
  CHECK(idents((*db)->navaids_named("san francisco", lat, lon, 250)) ==
        std::vector<std::string>{"SFO"});
  CHECK(idents((*db)->navaids_named("Point Reyes", lat, lon, 250)) ==
        std::vector<std::string>{"PYE"});
  const auto reyes = (*db)->navaids_named("point reyes", lat, lon, 1e5);
  CHECK(idents(reyes) == std::vector<std::string>{"PYE", "PYX"});
  REQUIRE(reyes.size() == 2);
  CHECK(reyes[1]->lat == doctest::Approx(51.0));
  CHECK(reyes[1]->lon == doctest::Approx(1.0));
  CHECK((*db)->navaids_named("reyes", lat, lon, 250).empty());
  CHECK((*db)->navaids_named("vor dme", lat, lon, 250).empty());
  CHECK((*db)->navaids_named("", lat, lon, 250).empty());
  // by a run of whole words of the name: "reyes" is both POINT REYES, near first; "rey" is no word
  // of it
  CHECK(idents((*db)->navaids_named("reyes", lat, lon, 1e5, "", true)) ==
        std::vector<std::string>{"PYE", "PYX"});
  CHECK(idents((*db)->navaids_named("Reyes", lat, lon, 250, "", true)) ==
        std::vector<std::string>{"PYE"});
  CHECK((*db)->navaids_named("rey", lat, lon, 1e5, "", true).empty());
  CHECK((*db)->navaids_named("francisco point", lat, lon, 1e5, "", true).empty());
}

namespace {

// Two navaids that share the ident LAM (nav.dat: the LAMBOURNE VOR-DME near London and the LICA 28
// ILS's LAM in Italy) and a fix of its own.
Stack with_two_lams() {
  Stack s(0);
  s.set_navdb(
      std::make_shared<const NavDb>(std::vector<NavPoint>{{"EGLL", "APT", 51.477, -0.461}},
                                    std::vector<NavPoint>{{"LAM", "VOR", 51.646111, 0.151667},
                                                          {"LAM", "ILS", 38.907314, 16.225853},
                                                          {"SOLO", "FIX", 45.0, 10.0}}));
  return s;
}

bool at(const Stack& s, const char* id, double lat, double lon) {
  const int i = s.sim().index_of(id);
  return i >= 0 && std::abs(s.sim().traffic().lat[i] - lat) < 1e-6 &&
         std::abs(s.sim().traffic().lon[i] - lon) < 1e-6;
}

}  // namespace

TEST_CASE(
    "reference position: kept between commands as BlueSky's bs.ref; (0, 0) at the start and after "
    "RESET") {
  Stack s = with_two_lams();
  CHECK(s.reference().lat == 0.0);
  CHECK(s.reference().lon == 0.0);
  // an empty scene: LAM nearest (0, 0) is the Italian one
  REQUIRE(s.exec("CRE B0 A320 LAM 90 FL100 250"));
  CHECK(at(s, "B0", 38.907314, 16.225853));
  // traffic created over London moves the reference there: the next command's LAM is Lambourne
  REQUIRE(s.exec("CRE A1 A320 51.5 -0.1 90 FL100 250"));
  CHECK(s.reference().lat == doctest::Approx(51.5));
  REQUIRE(s.exec("CRE B1 A320 LAM 90 FL100 250"));
  CHECK(at(s, "B1", 51.646111, 0.151667));
  // an aircraft named moves it to that aircraft (AcidArg); a position that is an aircraft does not
  // (PosArg)
  REQUIRE(s.exec("ALT B0 FL120"));
  CHECK(s.reference().lat == doctest::Approx(38.907314));
  REQUIRE(s.exec("CRE C1 A320 A1 90 FL100 250"));
  CHECK(s.reference().lat == doctest::Approx(38.907314));
  // a waypoint argument reads it and leaves it (WptArg): ADDWPT's acid set it
  REQUIRE(s.exec("ADDWPT A1 LAM"));
  CHECK(s.sim().traffic().route[s.sim().index_of("A1")].waypoints()[0].lat ==
        doctest::Approx(51.646111));
  CHECK(s.reference().lat == doctest::Approx(51.5));
  // AFTER's new waypoint resolves from the reference its aircraft set
  REQUIRE(s.exec("ADDWPT B1 SOLO"));
  REQUIRE(s.exec("B1 AFTER SOLO ADDWPT LAM"));
  CHECK(s.sim().traffic().route[s.sim().index_of("B1")].waypoints().back().lat ==
        doctest::Approx(51.646111));
  // a line's commands run in order, each from the reference the one before left
  REQUIRE(s.exec("ALT B0 FL130; CRE B2 A320 LAM 90 FL100 250"));
  CHECK(at(s, "B2", 38.907314, 16.225853));
  // RESET (and IC) put it back at (0, 0)
  REQUIRE(s.exec("CRE D1 A320 51.5 -0.1 90 FL100 250; RESET"));
  CHECK(s.reference().lat == 0.0);
  REQUIRE(s.exec("CRE B3 A320 LAM 90 FL100 250"));
  CHECK(at(s, "B3", 38.907314, 16.225853));
}

TEST_CASE("reference position: a failed command leaves it and the whole state as they were") {
  Stack s = with_two_lams();
  REQUIRE(s.exec("CRE A1 A320 51.5 -0.1 90 FL100 250"));
  // the parse reached 10 10 before the handler refused the duplicate callsign
  error_of(s, "CRE A1 A320 10 10 90 FL100 250");
  error_of(s, "CRE X1 A320 10 10 90 FL100 -5");
  error_of(s, "NEAR 10 10 CRE A1 A320 LAM 90 FL100 250");
  error_of(s, "NEAR 10 10 WIBBLE");
  CHECK(s.reference().lat == doctest::Approx(51.5));
  REQUIRE(s.exec("CRE B1 A320 LAM 90 FL100 250"));
  CHECK(at(s, "B1", 51.646111, 0.151667));
  // the snapshot holds it: two stacks that differ only in it differ
  Stack a = with_two_lams(), b = with_two_lams();
  REQUIRE(a.exec("NEAR 1 1 ECHO x"));
  REQUIRE(b.exec("NEAR 2 2 ECHO x"));
  CHECK(a.snapshot() != b.snapshot());
}

TEST_CASE(
    "NEAR lat,lon,command: the command runs from that reference; check() carries the reference") {
  Stack s = with_two_lams();
  REQUIRE(s.exec("NEAR 51.6 0.2 CRE B1 A320 LAM 90 FL100 250"));
  CHECK(at(s, "B1", 51.646111, 0.151667));
  REQUIRE(s.exec("NEAR EGLL CRE B2 A320 LAM 90 FL100 250"));
  CHECK(at(s, "B2", 51.646111, 0.151667));
  REQUIRE(s.exec("NEAR 40 15 CRE B3 A320 LAM 90 FL100 250"));
  CHECK(at(s, "B3", 38.907314, 16.225853));
  CHECK_FALSE(s.check("NEAR 40 15"));
  // from a scenario line as typed
  s.schedule(0.0, "NEAR 51.6 0.2 CRE B4 A320 LAM 90 FL100 250");
  s.process_due();
  CHECK(at(s, "B4", 51.646111, 0.151667));
  CHECK(
      error_of(
          s,
          "NEAR 1 1 NEAR 1 1 NEAR 1 1 NEAR 1 1 NEAR 1 1 NEAR 1 1 NEAR 1 1 NEAR 1 1 NEAR 1 1 ECHO x")
          .find("nested") != std::string::npos);
}
