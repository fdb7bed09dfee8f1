// Names in an utterance: aircraft (typed ids, spoken callsigns), aircraft
// types, waypoints and airports.
//
// Contract: find_references() marks the tokens of each reference in `used`
// and returns them in utterance order.
//  - Aircraft: a typed id ("KLM123", "AC01", "aircraft1"); a telephony
//    designator with the callsign's digits and letters ("speedbird one two
//    three" -> BAW123, "lufthansa four alpha bravo" -> DLH4AB). With a world,
//    a spoken callsign that is not an existing id is matched to the closest
//    existing aircraft (telephony sound + digits); when the utterance opens
//    with an unrecognised callsign and the world holds aircraft, that opening
//    is matched the same way (speech recognition garbles airline names).
//  - Types: ICAO designators ("B738"), maker + model ("Boeing 737-800"),
//    model alone ("747-400").
//  - Waypoints: names defined in the world or in a route; otherwise
//    upper-case tokens of 2-6 letters/digits that are not ids or types.
// Never fails.
#pragma once

#include <string>
#include <vector>

#include "translate/lexer.h"
#include "translate/world_view.h"

namespace squawk::translate {

enum class RefKind { kAircraft, kType, kWaypoint };

// A spoken callsign matched to an existing aircraft it does not spell
// exactly: what was heard and how well its parts matched (0-1).
struct Heard {
  std::string id;        // the callsign as heard ("DLH123"); empty when matched exactly
  double airline = 0.0;  // similarity of the airline (telephony or prefix)
  double digits = 0.0;   // similarity of the digits and letters
};

struct Reference {
  RefKind kind = RefKind::kAircraft;
  std::string name;     // id, ICAO type or waypoint name
  size_t begin = 0;     // first token
  size_t end = 0;       // one past the last token
  bool exists = false;  // aircraft or waypoint known to the world
  bool spoken = false;  // aircraft named by telephony, not typed
  Heard heard;          // set when a spoken callsign was matched inexactly
};

std::vector<Reference> find_references(const std::vector<Token>& toks, const WorldView* world,
                                       std::vector<bool>& used);

// Phonetic alphabet letter ("alpha" -> 'A'), or 0.
char phonetic_letter(const std::string& w);

}  // namespace squawk::translate
