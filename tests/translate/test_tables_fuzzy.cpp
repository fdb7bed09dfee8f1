// Data tables, spelling fixes and fuzzy matching.
#include <doctest/doctest.h>

#include "rag/edit_distance.h"

#include "translate/fuzzy.h"
#include "translate/tables.h"
#include "translate/vocabulary.h"

using namespace squawk::translate;

namespace {

// A small table of the shape scripts/translate/names.lua hands over (the
// shipped data is checked by tests/lua/translate_offline.lua).
const Tables& names() {
  static const Tables t({{"speedbird", "BAW"}, {"air france", "AFR"}, {"lufthansa", "DLH"}},
                        {{"boeing", "737-800", "B738"}, {"", "747-400", "B744"}, {"airbus", "a380-800", "A388"},
                         {"airbus", "a330-300", "A333"}, {"cessna", "172", "C172"}},
                        {"A20N"}, {{"alpha", 'A'}, {"bravo", 'B'}});
  return t;
}

}  // namespace

TEST_CASE("telephony designators map to ICAO prefixes and back") {
  CHECK(names().airline_by_telephony("speedbird") == "BAW");
  CHECK(names().airline_by_telephony("Air France") == "AFR");
  CHECK_FALSE(names().airline_by_telephony("heading").has_value());
  CHECK(names().telephony_of("DLH") == std::vector<std::string>{"lufthansa"});
  CHECK(names().max_telephony_words() == 2);
  CHECK(names().phonetic_letter("bravo") == 'B');
  CHECK(names().phonetic_letter("heading") == 0);
}

TEST_CASE("aircraft type names map to ICAO designators") {
  CHECK(names().aircraft_type("boeing", "737-800") == "B738");
  CHECK(names().aircraft_type("", "747-400") == "B744");
  CHECK(names().aircraft_type("airbus", "380-800") == "A388");  // maker's letter left out
  CHECK(names().aircraft_type("Airbus", "A330-300") == "A333");
  CHECK(names().aircraft_type("", "B738") == "B738");
  CHECK_FALSE(names().aircraft_type("boeing", "999").has_value());
  CHECK(names().is_type_designator("a20n"));
  CHECK_FALSE(names().is_type_designator("KLM123"));
  CHECK(names().is_manufacturer("Cessna"));
}

TEST_CASE("spelling fixes reach the target words only") {
  const Vocabulary v({"heading", "turn"}, {"uh"}, {"heading", "turn", "knots", "detection", "angle"}, {"send"});
  CHECK(v.spell_fix("heding") == "heading");
  CHECK(v.spell_fix("tunr") == "turn");  // a swap is one edit
  CHECK(v.spell_fix("kots") == "knots");
  CHECK(v.spell_fix("detction") == "detection");
  CHECK(v.spell_fix("angel") == "angle");
  CHECK(v.spell_fix("train") == "train");  // two edits from "turn": too far for 5 letters
  CHECK(v.spell_fix("send") == "send");    // a common word
  CHECK(v.spell_fix("ac01") == "ac01");
  CHECK(v.is_keyword("turn"));
  CHECK(v.is_filler("uh"));
  CHECK_FALSE(v.is_filler("turn"));
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
