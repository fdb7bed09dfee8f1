// The JSON object of one row of a field list (sim/fields.h's Field): each
// declared field under its name; a number, count, flag or text as itself, a
// route as an array of kWaypoint objects, a list of texts or numbers as an
// array; an absent value is null.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <variant>
#include <vector>

#include "sim/fields.h"

namespace squawk::serve {

template <class Row, size_t N>
nlohmann::json fields_json(const sim::fields::Field<Row> (&list)[N], const Row& row) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& f : list) {
    const sim::fields::Value v = f.get(row);
    nlohmann::json& j = out[f.name];
    if (const double* x = std::get_if<double>(&v)) {
      j = *x;
    } else if (const long long* n = std::get_if<long long>(&v)) {
      j = *n;
    } else if (const bool* b = std::get_if<bool>(&v)) {
      j = *b;
    } else if (const auto* s = std::get_if<std::string_view>(&v)) {
      j = std::string(*s);
    } else if (const auto* r = std::get_if<const sim::Route*>(&v)) {
      j = nlohmann::json::array();
      for (const auto& w : (*r)->waypoints()) j.push_back(fields_json(sim::fields::kWaypoint, w));
    } else if (const auto* texts = std::get_if<const std::vector<std::string>*>(&v)) {
      j = **texts;
    } else if (const auto* numbers = std::get_if<std::span<const double>>(&v)) {
      j = std::vector<double>(numbers->begin(), numbers->end());
    }
  }
  return out;
}

}  // namespace squawk::serve
