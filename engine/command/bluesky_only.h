// BlueSky commands squawk does not implement: the radar display's and GUI's
// (PAN, ZOOM, SWRAD, SYMBOL, COLOR, "+"/"-" zoom keys...), plugins'
// (TRAFGEN, SETMASS, the ASAS research plugins...) and loggers'. A scenario
// line naming one is a listed skip, not a failure; every other unknown name
// in a scenario is a failure (a typo such as ATL for ALT).
#pragma once

#include <string_view>

namespace squawk::command {

// True for such a command (case-insensitive), and for a run of '+' or '-'.
bool bluesky_only(std::string_view name);

}  // namespace squawk::command
