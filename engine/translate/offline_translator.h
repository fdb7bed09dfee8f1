// The offline translator: controller and experimenter English -> TrafScript,
// by grammar rules, with no language model. The embedded default of the
// translation graph and its fallback.
//
// Contract: translate_offline() never fails and never throws. It returns
// either TrafScript command lines (several instructions in one utterance give
// several lines, in the order spoken) or, when a required value is missing
// (no callsign, no altitude after "climb", no position for a new aircraft),
// a question in `ask` and no commands. With a WorldView it reads current
// states for relative instructions ("climb 2000 ft", "turn left 20 degrees",
// "reduce speed by 10 %") and matches spoken callsigns and waypoint names to
// the aircraft and waypoints that exist; without one, relative instructions
// ask for the missing state. Cost: well under a millisecond per utterance.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "translate/world_view.h"

namespace squawk::translate {

struct Translation {
  std::vector<std::string> commands;  // TrafScript lines, in execution order
  std::string ask;                    // a question back; empty when commands were produced
  bool asked() const { return !ask.empty(); }
  // "CMD ; CMD", or the question when one was asked.
  std::string text() const;
};

Translation translate_offline(std::string_view utterance, const WorldView* world = nullptr);

}  // namespace squawk::translate
