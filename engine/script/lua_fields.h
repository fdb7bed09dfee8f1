// The Lua table of one row of a field list (sim/fields.h's Field): each
// present field under its name; a number, flag or text as itself, a count as
// a Lua integer, a route as an array of kWaypoint tables, a list of texts or
// numbers as an array; an absent value stays nil. Pushes the table.
#pragma once

#include <lua.hpp>
#include <string>
#include <variant>
#include <vector>

#include "sim/fields.h"

namespace squawk::script {

template <class Row, size_t N>
void push_fields(lua_State* L, const sim::fields::Field<Row> (&list)[N], const Row& row) {
  lua_createtable(L, 0, static_cast<int>(N));
  for (const auto& f : list) {
    const sim::fields::Value v = f.get(row);
    if (std::holds_alternative<sim::fields::Absent>(v)) continue;
    if (const double* x = std::get_if<double>(&v)) {
      lua_pushnumber(L, *x);
    } else if (const long long* n = std::get_if<long long>(&v)) {
      lua_pushinteger(L, static_cast<lua_Integer>(*n));
    } else if (const bool* b = std::get_if<bool>(&v)) {
      lua_pushboolean(L, *b);
    } else if (const auto* s = std::get_if<std::string_view>(&v)) {
      lua_pushlstring(L, s->data(), s->size());
    } else if (const auto* numbers = std::get_if<std::span<const double>>(&v)) {
      lua_createtable(L, static_cast<int>(numbers->size()), 0);
      for (size_t k = 0; k < numbers->size(); ++k) {
        lua_pushnumber(L, (*numbers)[k]);
        lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
      }
    } else if (const auto* texts = std::get_if<const std::vector<std::string>*>(&v)) {
      lua_createtable(L, static_cast<int>((*texts)->size()), 0);
      for (size_t k = 0; k < (*texts)->size(); ++k) {
        lua_pushlstring(L, (**texts)[k].data(), (**texts)[k].size());
        lua_seti(L, -2, static_cast<lua_Integer>(k + 1));
      }
    } else {
      const auto& wps = std::get<const sim::Route*>(v)->waypoints();
      lua_createtable(L, static_cast<int>(wps.size()), 0);
      for (size_t k = 0; k < wps.size(); ++k) {
        push_fields(L, sim::fields::kWaypoint, wps[k]);
        lua_seti(L, -2, static_cast<lua_Integer>(k + 1));
      }
    }
    lua_setfield(L, -2, f.name);
  }
}

}  // namespace squawk::script
