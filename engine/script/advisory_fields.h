// The field lists of an advisory (script/advisory.h) as it crosses to a
// phrasing template's advise(d) (prompts/advisory.lua, AdvisoryPhraser), in
// sim/fields.h's pattern: one row per field, {name, unit, getter}.
//
// Contract: d holds kAdvisory's fields and, when there is traffic to call,
// d.traffic with kAdvisoryTraffic's; heading and clock are Lua integers.
#pragma once

#include <string_view>

#include "script/advisory.h"
#include "sim/fields.h"

namespace squawk::script::fields {

using sim::fields::Field;
using sim::fields::Value;

using D = Advisory;
using T = Advisory::Traffic;
// clang-format off
inline constexpr Field<D> kAdvisory[] = {
    {"callsign", "", [](const D& d) -> Value { return std::string_view(d.callsign); }},
    // Units of 45 deg.
    {"action", "", [](const D& d) -> Value { return d.action; }},
    // The heading to fly, 1..360.
    {"heading", "deg", [](const D& d) -> Value { return static_cast<long long>(d.heading); }},
    {"current_heading", "deg", [](const D& d) -> Value { return d.current_heading; }},
    // "left", "right" or "none".
    {"turn", "", [](const D& d) -> Value { return std::string_view(d.turn); }},
};

inline constexpr Field<T> kAdvisoryTraffic[] = {
    {"id", "", [](const T& t) -> Value { return std::string_view(t.id); }},
    // Clock position 1..12 relative to the nose.
    {"clock", "", [](const T& t) -> Value { return static_cast<long long>(t.clock); }},
    {"distance_nm", "nm", [](const T& t) -> Value { return t.distance_nm; }},
};
// clang-format on

}  // namespace squawk::script::fields
