// Data tables, spelling fixes and fuzzy matching.
#include <doctest/doctest.h>

#include "rag/edit_distance.h"

#include "translate/fuzzy.h"
#include "translate/tables.h"
#include "translate/vocabulary.h"

using namespace squawk::translate;

TEST_CASE("telephony designators map to ICAO prefixes and back") {
  CHECK(airline_by_telephony("speedbird") == "BAW");
  CHECK(airline_by_telephony("Air France") == "AFR");
  CHECK(airline_by_telephony("shamrock") == "EIN");
  CHECK_FALSE(airline_by_telephony("heading").has_value());
  auto tel = telephony_of("DLH");
  CHECK(tel == std::vector<std::string>{"lufthansa"});
}

TEST_CASE("aircraft type names map to ICAO designators") {
  CHECK(aircraft_type("boeing", "737-800") == "B738");
  CHECK(aircraft_type("", "747-400") == "B744");
  CHECK(aircraft_type("airbus", "a380-800") == "A388");
  CHECK(aircraft_type("Airbus", "A330-300") == "A333");
  CHECK(aircraft_type("cessna", "172") == "C172");
  CHECK(aircraft_type("embraer", "190") == "E190");
  CHECK(aircraft_type("", "B738") == "B738");
  CHECK_FALSE(aircraft_type("boeing", "999").has_value());
  CHECK(is_type_designator("a20n"));
  CHECK_FALSE(is_type_designator("KLM123"));
}

TEST_CASE("spelling fixes reach instruction words only") {
  CHECK(spell_fix("heding") == "heading");
  CHECK(spell_fix("tunr") == "turn");
  CHECK(spell_fix("kots") == "knots");
  CHECK(spell_fix("dleete") == "delete");
  CHECK(spell_fix("detction") == "detection");
  CHECK(spell_fix("angel") == "angle");
  CHECK(spell_fix("train") == "train");  // everyday words stay
  CHECK(spell_fix("send") == "send");
  CHECK(spell_fix("ac01") == "ac01");
}

TEST_CASE("fuzzy similarity favours how names sound") {
  CHECK(similarity("KLM", "klm") == 1.0);
  CHECK(squawk::rag::edit_distance("kitten", "sitting") == 3);
  CHECK(squawk::rag::edit_distance("tunr", "turn") == 1);  // a swap costs one
  CHECK(similarity("gale", "GAYEL") > similarity("gale", "FINKI"));
  CHECK(similarity("tiger", "TYGGR") > 0.5);
  auto m = best_match("tonci", {"GAYEL", "TONCE", "WAVEY"});
  REQUIRE(m.has_value());
  CHECK(m->index == 1);
  CHECK_FALSE(best_match("x", {}).has_value());
}
