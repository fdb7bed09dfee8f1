// The offline grammar: utterance -> TrafScript or a question.
#include <doctest/doctest.h>

#include "command/stack.h"
#include "core/units.h"
#include "translate/offline_translator.h"
#include "translate/stack_world.h"

using namespace squawk;
using namespace squawk::translate;

namespace {

AircraftView plane(const char* id, double hdg, double alt_ft, double kt, const char* type = "A320") {
  AircraftView a;
  a.id = id;
  a.type = type;
  a.lat_deg = 52.0;
  a.lon_deg = 4.0;
  a.hdg_deg = hdg;
  a.alt_m = units::ft_to_m(alt_ft);
  a.cas_ms = units::kt_to_ms(kt);
  return a;
}

std::string tr(const char* text, const WorldView* w = nullptr) { return translate_offline(text, w).text(); }
bool asks(const char* text, const WorldView* w = nullptr) { return translate_offline(text, w).asked(); }

}  // namespace

TEST_CASE("altitudes: flight levels, feet, thousands, 30k, metres") {
  CHECK(tr("KLM123 climb flight level three five zero") == "ALT KLM123 FL350");
  CHECK(tr("Delta three six two, descend and maintain four thousand") == "ALT DAL362 4000");
  CHECK(tr("American four seven, climb and maintain one one thousand") == "ALT AAL47 11000");
  CHECK(tr("Descend AC02 to 15k ft") == "ALT AC02 15000");
  CHECK(tr("clim AC04 to FL 290") == "ALT AC04 FL290");
  CHECK(tr("I'd like aircraft TEST2 to cruise at 41,000 ft") == "ALT TEST2 41000");
  CHECK(tr("Bring AC03 up to thirty-seven thousand feet") == "ALT AC03 37000");
  CHECK(tr("Climb AC01 to 28000 ft at 1500 fpm") == "ALT AC01 28000 1500");
  CHECK(tr("change AC02 vertical speed to -1000 fpm") == "VS AC02 -1000");
  CHECK(tr("Make AC01 descend at 1500 feet per minute") == "VS AC01 -1500");
}

TEST_CASE("speeds: knots and Mach in every common form") {
  CHECK(tr("KLM one two three, reduce speed to two two zero knots") == "SPD KLM123 220");
  CHECK(tr("Have AC01 fly at M.78") == "SPD AC01 M0.78");
  CHECK(tr("Speedbird seven, reduce speed to mach point seven eight") == "SPD BAW7 M0.78");
  CHECK(tr("Set AC04's speed to 0.79 Mach") == "SPD AC04 M0.79");
  CHECK(tr("slow AC03 to 180 kts") == "SPD AC03 180");
}

TEST_CASE("headings: absolute, compass words, ATC digits") {
  CHECK(tr("Shamrock four five kilo, turn left heading three one zero") == "HDG EIN45K 310");
  CHECK(tr("Point AC01 due south") == "HDG AC01 180");
  CHECK(tr("Make AC03 fly north-east") == "HDG AC03 45");
  CHECK(tr("Set the heading of aircraft TEST3 to one hundred and twenty degrees") == "HDG TEST3 120");
}

TEST_CASE("relative instructions use the current state") {
  StaticWorld w;
  w.add_aircraft(plane("AC01", 90, 25000, 280));
  w.add_aircraft(plane("AC02", 20, 26000, 290));
  CHECK(tr("turn AC01 left 20 degrees", &w) == "HDG AC01 70");
  CHECK(tr("Turn AC02 left by 40 degrees", &w) == "HDG AC02 340");
  CHECK(tr("Turn AC01 30 degrees to the right", &w) == "HDG AC01 120");
  CHECK(tr("Climb AC01 by 2000 feet", &w) == "ALT AC01 27000");
  CHECK(tr("Slow AC01 down by 20 knots", &w) == "SPD AC01 260");
  CHECK(tr("Increase the speed of AC01 by 10%", &w) == "SPD AC01 308");
  CHECK(tr("Turn AC01 around", &w) == "HDG AC01 270");
  CHECK(tr("Give AC02 the same heading as AC01", &w) == "HDG AC02 90");
  // without a world there is no current heading to turn from
  CHECK(asks("turn AC01 left 20 degrees"));
}

TEST_CASE("positions: lat/lon in written forms, types, creation") {
  CHECK(tr("Create AC01, an A320 at 52N 4E heading 90 at FL250 and 280 knots") == "CRE AC01 A320 52 4 90 FL250 280");
  CHECK(tr("Add a Boeing 737-800 named KL1 at 52 deg 18 min N, 4 deg 45 min E heading 90 at 30k ft, 250 kt") ==
        "CRE KL1 B738 52.3 4.75 90 30000 250");
  CHECK(tr("Move AC01 to N52.3 E4.76", nullptr) == "MOVE AC01 52.3 4.76");
  CHECK(tr("Define waypoint EXIT1 at 53.2 north 2.1 east") == "DEFWPT EXIT1 53.2 2.1");
  CHECK(tr("add a 747-400 with id CX520 at 0 0, heading 0, FL200, 400 knots") == "CRE CX520 B744 0 0 0 FL200 400");
}

TEST_CASE("telephony callsigns become ICAO callsigns") {
  CHECK(tr("speedbird 123 turn right heading 090") == "HDG BAW123 90");
  CHECK(tr("Lufthansa four alpha bravo, fly heading zero niner zero") == "HDG DLH4AB 90");
  CHECK(tr("Easy four fife bravo, descend flight level two zero zero") == "ALT EZY45B FL200");
}

TEST_CASE("several instructions in one utterance keep their order") {
  CHECK(tr("Speedbird one two three, turn left heading two four zero, descend altitude eight thousand feet, "
           "reduce speed two one zero knots") == "HDG BAW123 240 ; ALT BAW123 8000 ; SPD BAW123 210");
  CHECK(tr("Turn on conflict detection and use MVP for resolution") == "ASAS ON ; RESO MVP");
  CHECK(tr("Reset, then set seed 99 and a time step of 0.05 seconds") == "RESET ; SEED 99 ; DT 0.05");
  CHECK(tr("Set AC01 and AC02 to FL300") == "ALT AC01 FL300 ; ALT AC02 FL300");
  CHECK(tr("AC02: heading 180, FL200, 250 kts") == "HDG AC02 180 ; ALT AC02 FL200 ; SPD AC02 250");
  CHECK(tr("When AC01 reaches FL200, set its speed to 280 knots") == "ATALT AC01 FL200 SPD AC01 280");
  CHECK(tr("Delta 30, descend and maintain 4000, then reduce speed to 210") ==
        "ALT DAL30 4000 ; ATALT DAL30 4000 SPD DAL30 210");
}

TEST_CASE("experimenter requests") {
  CHECK(tr("Can you speed this simulation up?") == "FF");
  CHECK(tr("Fast-forward 10 minutes") == "FF 600");
  CHECK(tr("Pause the simulation") == "HOLD");
  CHECK(tr("Slow the sim down to half speed") == "DTMULT 0.5");
  CHECK(tr("Load the scenario super16.scn and then set the random seed to 7") == "IC super16.scn ; SEED 7");
  CHECK(tr("Print \"phase 2\" to the console") == "ECHO phase 2");
  CHECK(tr("run at double speed") == "DTMULT 2");
  CHECK(tr("speed the simulation up 10 times") == "DTMULT 10");
  CHECK(tr("turn off CD") == "ASAS OFF");
  CHECK(tr("What is the altitude of KLM123?") == "POS KLM123");
  StaticWorld w;
  w.add_aircraft(plane("AC01", 90, 25000, 280));
  w.add_aircraft(plane("AC02", 20, 26000, 290));
  CHECK(tr("Delete all aircraft", &w) == "DEL AC01 ; DEL AC02");
}

TEST_CASE("a missing callsign or value is asked for, never guessed") {
  CHECK(asks("KLM one two three, climb"));
  CHECK(asks("Change the speed"));
  CHECK(asks("Speedbird one two three, turn left"));
  CHECK(asks("Create a new aircraft called TST01"));
  CHECK(asks("Set the simulation time step"));
  CHECK(asks("Add a waypoint for AC01"));
  StaticWorld two;
  two.add_aircraft(plane("AC01", 90, 25000, 280));
  two.add_aircraft(plane("AC02", 20, 26000, 290));
  CHECK(asks("Turn the aircraft to heading 270", &two));
  StaticWorld one;
  one.add_aircraft(plane("TEST9", 90, 25000, 280));
  CHECK(tr("Turn the aircraft to heading 270", &one) == "HDG TEST9 270");
  auto t = translate_offline("Set the altitude of AC01");
  CHECK(t.commands.empty());
  CHECK(t.ask.find("AC01") != std::string::npos);
}

TEST_CASE("spoken callsigns are matched to the aircraft that exist") {
  command::Stack stack;
  REQUIRE(setup_stack(stack, "CRE DAL1153 B738 40 -74 360 5000 250 ; CRE AVA847 A320 40.5 -74 90 11000 250").is_ok());
  StackWorld w(stack);
  CHECK(tr("12,153, climbing, maintain one two twelve thousand.", &w) == "ALT DAL1153 12000");
  CHECK(tr("Abiont eight forty seven descend and maintain four thousand", &w) == "ALT AVA847 4000");
  CHECK(tr("Delta eleven fifty three turn right heading zero one zero", &w) == "HDG DAL1153 10");
}

TEST_CASE("waypoints are matched by sound") {
  command::Stack stack;
  REQUIRE(setup_stack(stack, "CRE ACA326 B738 40 -74 360 12000 250 ; DEFWPT GAYEL 40.5 -73.5 ; ADDWPT ACA326 GAYEL")
              .is_ok());
  StackWorld w(stack);
  CHECK(tr("Air Canada three twenty six cleared direct Gale", &w) == "DIRECT ACA326 GAYEL");
  CHECK(tr("Air Canada three twenty six proceed direct", &w) == "DIRECT ACA326 GAYEL");
}

TEST_CASE("bad input never crashes and gets a question") {
  for (const char* s : {"", "   ", ";;;", "\"", "\xC2\xB0\xC2\xB0", "FL", "M.", "N", "one hundred thousand thousand",
                        "direct direct direct", "12,", "AC01'", "-", "\xff\xfe"}) {
    auto t = translate_offline(s);
    CHECK((t.asked() || !t.commands.empty()));
  }
}

TEST_CASE("navigation and simulation phrases: own navigation, direct to a new fix, run for a time") {
  StaticWorld w;
  AircraftView a = plane("KLM123", 90, 25000, 280);
  a.route = {"SPY"};
  w.add_aircraft(a);
  w.add_waypoint("SUGOL");
  w.add_waypoint("SPY");
  CHECK(tr("KLM123 resume own navigation", &w) == "LNAV KLM123 ON");
  // DIRECT needs the fix in the route: one the route lacks is added first.
  CHECK(tr("KLM123 fly direct SUGOL", &w) == "ADDWPT KLM123 SUGOL ; DIRECT KLM123 SUGOL");
  CHECK(tr("KLM123 proceed direct SPY", &w) == "DIRECT KLM123 SPY");
  CHECK(tr("Run the simulation for ten minutes") == "FF 600");
  CHECK(tr("Run the sim") == "OP");
  CHECK(tr("Run the simulation at 5x real time") == "DTMULT 5");
}
