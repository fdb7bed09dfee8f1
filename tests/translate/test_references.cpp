// References found in an utterance: aircraft, types and waypoints (references.h).
#include <doctest/doctest.h>

#include "translate/lexer.h"
#include "translate/references.h"
#include "translate/tables.h"
#include "translate/world_view.h"

using namespace squawk::translate;

namespace {

const Tables& names() {
  static const Tables t({{"ryanair", "RYR"}}, {}, {"EUFI"}, {{"alpha", 'A'}, {"xray", 'X'}});
  return t;
}

// The aircraft references found in `text` with `ids` flying.
std::vector<std::string> aircraft_in(const std::string& text, const std::vector<std::string>& ids) {
  StaticWorld world;
  for (const auto& id : ids) world.add_aircraft({id, {}});
  const std::vector<Token> toks = lex(text);
  std::vector<bool> used(toks.size(), false);
  std::vector<std::string> found;
  for (const auto& r : find_references(toks, &world, used, names()))
    if (r.kind == RefKind::kAircraft) found.push_back(r.name);
  return found;
}

// The type references found in `text`, nothing flying.
std::vector<std::string> types_in(const std::string& text) {
  StaticWorld world;
  const std::vector<Token> toks = lex(text);
  std::vector<bool> used(toks.size(), false);
  std::vector<std::string> found;
  for (const auto& r : find_references(toks, &world, used, names()))
    if (r.kind == RefKind::kType) found.push_back(r.name);
  return found;
}

// The waypoint references found in `text` with waypoint `defined` defined, each name followed by
// "?" when it names no waypoint of the world.
std::vector<std::string> waypoints_in(const std::string& text, const std::string& defined) {
  StaticWorld world;
  world.add_waypoint(defined);
  const std::vector<Token> toks = lex(text);
  std::vector<bool> used(toks.size(), false);
  std::vector<std::string> found;
  for (const auto& r : find_references(toks, &world, used, names()))
    if (r.kind == RefKind::kWaypoint) found.push_back(r.name + (r.exists ? "" : "?"));
  return found;
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
    "a designator of letters only typed in capitals after a new callsign or 'type' is that type, "
    "elsewhere no "
    "type") {
  CHECK(types_in("create GAF30 EUFI at 48.6 11.4") == std::vector<std::string>{"EUFI"});
  CHECK(types_in("create GAF30 type EUFI at 48.6 11.4") == std::vector<std::string>{"EUFI"});
  // (a place's letters after another word, and the designator in lower case, stay no type)
  CHECK(types_in("GAF30 direct EUFI").empty());
  CHECK(types_in("create GAF30 eufi at 48.6 11.4").empty());
}

TEST_CASE(
    "a flight number typed as one word of digits, letters and digits after the airline is that "
    "aircraft") {
  static const Tables t({{"cool red", "APG"}}, {}, {}, {});
  StaticWorld world;
  world.add_aircraft({"APG2Z221", {}});
  world.add_aircraft({"KLM12", {}});
  auto found = [&](const std::string& text) {
    const std::vector<Token> toks = lex(text);
    std::vector<bool> used(toks.size(), false);
    std::vector<std::string> ids;
    for (const auto& r : find_references(toks, &world, used, t))
      if (r.kind == RefKind::kAircraft) ids.push_back(r.name);
    return ids;
  };
  CHECK(found("cool red 2Z221 maintain FL280") == std::vector<std::string>{"APG2Z221"});
  CHECK(found("KLM12 maintain FL280") == std::vector<std::string>{"KLM12"});
}
