// The field list of an observation (env/observation.h's structured form) as
// it crosses to Lua: env:observation() (script/bind_env.cpp) and a prompt
// template's render(o) (script/prompt_renderer.cpp), in sim/fields.h's
// pattern: one row per field, {name, unit, getter}. It sits in script/, the
// floor that sees both env/ and sim/fields.h.
//
// Contract: every field is a list of numbers, one per intruder, or a
// one-element list for the waypoint's (so a template indexes all alike, o.x[1]);
// the units are env/observation.h's scaled ones ([-]: km / 150, (m/s) / 150,
// cos/sin).
#pragma once

#include <span>

#include "env/observation.h"
#include "sim/fields.h"

namespace squawk::script::fields {

using sim::fields::Field;
using sim::fields::Value;

using O = env::Observation;
// clang-format off
inline constexpr Field<O> kObservation[] = {
    {"intruder_distance", "", [](const O& o) -> Value { return std::span<const double>(o.intruder_distance); }},
    {"cos_difference_pos", "", [](const O& o) -> Value { return std::span<const double>(o.cos_difference_pos); }},
    {"sin_difference_pos", "", [](const O& o) -> Value { return std::span<const double>(o.sin_difference_pos); }},
    {"x_difference_speed", "", [](const O& o) -> Value { return std::span<const double>(o.x_difference_speed); }},
    {"y_difference_speed", "", [](const O& o) -> Value { return std::span<const double>(o.y_difference_speed); }},
    {"waypoint_distance", "", [](const O& o) -> Value { return std::span<const double>(&o.waypoint_distance, 1); }},
    {"cos_drift", "", [](const O& o) -> Value { return std::span<const double>(&o.cos_drift, 1); }},
    {"sin_drift", "", [](const O& o) -> Value { return std::span<const double>(&o.sin_drift, 1); }},
};
// clang-format on

}  // namespace squawk::script::fields
