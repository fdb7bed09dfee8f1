// The field list of a step result (env/reward.h's StepFacts) as it crosses to
// a scenario's Lua reward function, reward(f) (script/scenario.cpp), in
// sim/fields.h's pattern: one row per field, {name, unit, getter}. It sits in
// script/, the floor that sees both env/ and sim/fields.h.
//
// Contract: the names carry the unit (drift_deg, heading_change_deg,
// waypoint_distance_m); counts are Lua integers.
#pragma once

#include "env/reward.h"
#include "sim/fields.h"

namespace squawk::script::fields {

using sim::fields::Field;
using sim::fields::Value;

using F = env::StepFacts;
// clang-format off
inline constexpr Field<F> kStepFacts[] = {
    {"step", "", [](const F& f) -> Value { return static_cast<long long>(f.step); }},
    {"intrusions", "", [](const F& f) -> Value { return static_cast<long long>(f.intrusions); }},
    {"substep_intrusions", "", [](const F& f) -> Value { return static_cast<long long>(f.substep_intrusions); }},
    {"cpa_ratio", "", [](const F& f) -> Value { return f.cpa_ratio; }},
    {"drift_deg", "deg", [](const F& f) -> Value { return f.drift; }},
    {"heading_change_deg", "deg", [](const F& f) -> Value { return f.heading_change; }},
    {"waypoint_distance_m", "m", [](const F& f) -> Value { return f.waypoint_distance; }},
    {"reached", "", [](const F& f) -> Value { return f.reached; }},
};
// clang-format on

}  // namespace squawk::script::fields
