// Typed quantities in an utterance: the values of an instruction with their
// units worked out from the words around them.
//
// Contract: extract_quantities() scans tokens [begin, end) where `skip` is
// false and returns each number it finds with a kind:
//   altitude ("FL250", "flight level two four zero", "30k", "41,000 ft",
//   "8000 m", "four thousand"), speed in knots or Mach ("250 kt", "M.78",
//   "mach point seven eight", "0.79 Mach", "mark point seven eight" as speech
//   recognition writes Mach), heading ("heading 090"),
//   vertical speed ("1500 fpm", "feet per minute"), latitude/longitude
//   ("52 N", "52.3N", "N52.3", "51 degrees 30 minutes north", "N52°18.6'",
//   chart form "5230N 00445E" (degrees and minutes run together),
//   "latitude 47.46"), time ("10 minutes", "0.5 s", "half a second"),
//   distance ("2.5 NM", "9.26 km" = 5 NM, "20 DME"), percent, multiplier ("5x", "half speed",
//   "double speed", "triple speed"), angle ("20 degrees"), or plain. Values are in aviation units
//   here (ft, kt, deg, fpm, s, NM): they go straight into TrafScript text. Never fails.
#pragma once

#include <string>
#include <vector>

#include "translate/lexer.h"
#include "translate/number_words.h"

namespace squawk::translate {

enum class QKind { kPlain, kAlt, kSpeed, kMach, kHeading, kVs, kLat, kLon, kTime, kDist, kPercent, kMult, kAngle };

struct Quantity {
  QKind kind = QKind::kPlain;
  double value = 0.0;      // ft, kt, Mach, deg, fpm, deg, deg, s, NM, %, factor, deg
  size_t begin = 0;        // first token (including a unit word before it)
  size_t end = 0;          // one past the last token (including units after it)
  bool flight_level = false;  // altitude said as a flight level
  bool by = false;            // "by N": a change, not a target
  bool to = false;            // "to N": a target
  int turn = 0;               // -1 left, +1 right when "left"/"right" is beside the value
  SpokenNumber number;        // the number as read
};

std::vector<Quantity> extract_quantities(const std::vector<Token>& toks, size_t begin, size_t end,
                                         const std::vector<bool>& skip);

}  // namespace squawk::translate
