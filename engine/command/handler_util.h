// Helpers shared by the command handlers (commands_*.cpp); not a public API.
#pragma once

#include <functional>
#include <string>

#include "command/registry.h"
#include "command/stack.h"
#include "sim/route.h"

namespace squawk::command {

// Applies `fn` to every aircraft of acid argument `i`, all or nothing: with
// several aircraft (`*`) it works on a copy of the simulation that replaces
// the original only when every call succeeded.
Status for_each_acid(Call& c, size_t i,
                     const std::function<Status(sim::Simulation&, const std::string& acid)>& fn);

// The id of the first aircraft of acid argument i.
const std::string& acid_name(const Call& c, size_t i);

// One-line description of aircraft i (POS output).
std::string describe_aircraft(const sim::Traffic& t, int i);

// A route waypoint at a parsed position: named after the position's text, or,
// for an unnamed lat/lon point, ACID + a serial unique within the route.
sim::Waypoint make_waypoint(const sim::Traffic& t, int i, const ArgValue& pos);

// "ON"/"OFF".
const char* on_off(bool on);

}  // namespace squawk::command
