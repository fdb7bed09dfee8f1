// References found in an utterance: aircraft, types and waypoints (references.h).
#include <doctest/doctest.h>

#include "translate/lexer.h"
#include "translate/references.h"
#include "translate/tables.h"
#include "translate/world_view.h"

using namespace squawk::translate;

namespace {

const Tables& names() {
  static const Tables t({{"ryanair", "RYR"}, {"cool red", "APG"}}, {}, {"EUFI"},
                        {{"alpha", 'A'}, {"xray", 'X'}});
  return t;
}

// The names of the references of `kind` found in `text` in `world`, a waypoint's followed by "?"
// when it names none of the world's.
std::vector<std::string> found_in(const std::string& text, const StaticWorld& world, RefKind kind) {
  const std::vector<Token> toks = lex(text);
  std::vector<bool> used(toks.size(), false);
  std::vector<std::string> found;
  for (const auto& r : find_references(toks, &world, used, names()))
    if (r.kind == kind)
      found.push_back(r.name + (kind == RefKind::kWaypoint && !r.exists ? "?" : ""));
  return found;
}

// The aircraft references found in `text` with `ids` flying.
std::vector<std::string> aircraft_in(const std::string& text, const std::vector<std::string>& ids) {
  StaticWorld world;
  for (const auto& id : ids) world.add_aircraft({id, {}});
  return found_in(text, world, RefKind::kAircraft);
}

// The type references found in `text`, nothing flying.
std::vector<std::string> types_in(const std::string& text) {
  return found_in(text, StaticWorld(), RefKind::kType);
}

// The waypoint references found in `text` with waypoint `defined` defined.
std::vector<std::string> waypoints_in(const std::string& text, const std::string& defined) {
  StaticWorld world;
  world.add_waypoint(defined);
  return found_in(text, world, RefKind::kWaypoint);
}

}  // namespace

TEST_CASE("digits with an x typed onto them are a rate, no garbled opening callsign") {
  CHECK(aircraft_in("go 2x", {"KLM12"}).empty());
  CHECK(aircraft_in("run it 4x", {"KLM12"}).empty());
  // a flight number typed with its letters after the airline is still that aircraft
  CHECK(aircraft_in("ryanair 8UK climb", {"RYR8UK", "KLM12"}) ==
        std::vector<std::string>{"RYR8UK"});
  CHECK(aircraft_in("ryanair 2X climb", {"RYR2X", "KLM12"}) == std::vector<std::string>{"RYR2X"});
}

TEST_CASE(
    "a defined waypoint's letters said apart from its digits are that waypoint, every digit "
    "joined") {
  CHECK(waypoints_in("direct PKT zero four", "PKT04") == std::vector<std::string>{"PKT04"});
  CHECK(waypoints_in("direct PKT 04", "PKT04") == std::vector<std::string>{"PKT04"});
  // a digit more is another name: the letters stay a name of their own, unknown
  CHECK(waypoints_in("direct PKT zero four five", "PKT04") == std::vector<std::string>{"PKT?"});
}

TEST_CASE(
    "a defined waypoint named by digits and letters after them is that waypoint, the number not "
    "read apart") {
  CHECK(waypoints_in("after 5450N direct", "5450N") == std::vector<std::string>{"5450N"});
  CHECK(waypoints_in("after 5450n direct", "5450N") == std::vector<std::string>{"5450N"});
  // the digits apart from the letter are a number and a word, no waypoint
  CHECK(waypoints_in("after 5450 N direct", "5450N").empty());
  CHECK(waypoints_in("after 5440N direct", "5450N").empty());
}

TEST_CASE(
    "a designator of letters only, in capitals after a new callsign or 'type', is that type") {
  CHECK(types_in("create GAF30 EUFI at 48.6 11.4") == std::vector<std::string>{"EUFI"});
  CHECK(types_in("create GAF30 type EUFI at 48.6 11.4") == std::vector<std::string>{"EUFI"});
  // (a place's letters after another word, and the designator in lower case, stay no type)
  CHECK(types_in("GAF30 direct EUFI").empty());
  CHECK(types_in("create GAF30 eufi at 48.6 11.4").empty());
}

TEST_CASE(
    "a flight number typed as one word of digits, letters and digits after the airline is that "
    "aircraft") {
  CHECK(aircraft_in("cool red 2Z221 maintain FL280", {"APG2Z221", "KLM12"}) ==
        std::vector<std::string>{"APG2Z221"});
  // (a flight number of digits and letters only, "8UK", read as before)
  CHECK(aircraft_in("ryanair 8UK climb", {"RYR8UK", "APG2Z221"}) ==
        std::vector<std::string>{"RYR8UK"});
}
