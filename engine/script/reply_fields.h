// The field list of a command reply (serve_session.h's CommandReply) as it
// crosses to serve's JSON (POST /api/command, serve/live_sim.cpp) and so to
// the scope (web/panel.js), in sim/fields.h's pattern: one row per field,
// {name, unit, getter}. The reply is built from translate.session's Lua
// reply (serve_session.cpp) and has no Lua reader of its own.
//
// Contract: texts and flags only; a question, an addressed callsign that is
// empty does not apply: Absent (null in JSON). The events are not a field:
// they go to the log (LiveSim::log_events).
#pragma once

#include <string_view>

#include "script/serve_session.h"
#include "sim/fields.h"

namespace squawk::script::fields {

using sim::fields::Absent;
using sim::fields::Field;
using sim::fields::Value;

inline Value text_or_absent(const std::string& s) {
  return s.empty() ? Value(Absent{}) : Value(std::string_view(s));
}

using R = CommandReply;
// clang-format off
inline constexpr Field<R> kCommandReply[] = {
    {"text", "", [](const R& r) -> Value { return std::string_view(r.text); }},
    {"commands", "", [](const R& r) -> Value { return &r.commands; }},
    {"ok", "", [](const R& r) -> Value { return r.ok; }},
    {"message", "", [](const R& r) -> Value { return std::string_view(r.message); }},
    {"trace", "", [](const R& r) -> Value { return std::string_view(r.trace); }},
    {"ask", "", [](const R& r) -> Value { return text_or_absent(r.ask); }},
    {"cancelled", "", [](const R& r) -> Value { return r.cancelled; }},
    {"addressed", "", [](const R& r) -> Value { return text_or_absent(r.addressed); }},
};
// clang-format on

}  // namespace squawk::script::fields
