// The field lists of sim/fields.h are what Lua and serve's JSON show: every
// declared field, and nothing else, with the same value in both; a command
// reply's JSON holds script/reply_fields.h's fields and nothing else, a Lua
// reward function sees script/step_fields.h's, env:observation()
// script/observation_fields.h's and a phrasing template
// script/advisory_fields.h's.
#include <doctest/doctest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <lua.hpp>
#include <map>
#include <set>
#include <string>

#include "env/observation.h"
#include "script/advisory_fields.h"
#include "script/lua_util.h"
#include "script/observation_fields.h"
#include "script/reply_fields.h"
#include "script/scenario.h"
#include "script/serve_session.h"
#include "script/step_fields.h"
#include "script/vm.h"
#include "serve/live_sim.h"
#include "serve/state_json.h"
#include "sim/fields.h"

using namespace squawk;
using nlohmann::json;

namespace {

// The keys of the Lua table at the top of the stack.
std::set<std::string> lua_keys(lua_State* L) {
  std::set<std::string> keys;
  lua_pushnil(L);
  while (lua_next(L, -2)) {
    lua_pop(L, 1);
    keys.insert(lua_tostring(L, -1));
  }
  return keys;
}

// The Lua table at the top of the stack and the JSON object `j` both hold
// exactly `list`'s fields (a JSON null where Lua has nil), with equal values.
template <class Row, size_t N>
void check_same(lua_State* L, const json& j, const sim::fields::Field<Row> (&list)[N],
                const std::string& what) {
  REQUIRE(lua_istable(L, -1));
  REQUIRE(j.is_object());
  std::set<std::string> declared, present;
  for (const auto& f : list) {
    declared.insert(f.name);
    CAPTURE(what);
    const std::string field = f.name;
    CAPTURE(field);
    REQUIRE(j.contains(f.name));  // every declared field is in the JSON
    const json& v = j[f.name];
    lua_getfield(L, -1, f.name);
    if (v.is_null()) {
      CHECK(lua_isnil(L, -1));
    } else {
      present.insert(f.name);
      if (v.is_number()) {
        REQUIRE(lua_type(L, -1) == LUA_TNUMBER);
        CHECK(lua_tonumber(L, -1) == v.get<double>());
      } else if (v.is_boolean()) {
        REQUIRE(lua_isboolean(L, -1));
        CHECK((lua_toboolean(L, -1) != 0) == v.get<bool>());
      } else if (v.is_string()) {
        REQUIRE(lua_type(L, -1) == LUA_TSTRING);
        CHECK(std::string(lua_tostring(L, -1)) == v.get<std::string>());
      } else {
        REQUIRE(v.is_array());  // a route: waypoints of kWaypoint
        REQUIRE(lua_rawlen(L, -1) == v.size());
        for (size_t k = 0; k < v.size(); ++k) {
          lua_rawgeti(L, -1, static_cast<lua_Integer>(k + 1));
          check_same(L, v[k], sim::fields::kWaypoint, what + "." + f.name);
          lua_pop(L, 1);
        }
      }
    }
    lua_pop(L, 1);
  }
  CHECK(lua_keys(L) == present);  // ... and nothing undeclared in Lua
  for (const auto& [key, value] : j.items())
    CHECK_MESSAGE(declared.count(key), what << ": undeclared " << key);
}

}  // namespace

TEST_CASE(
    "every field of sim/fields.h's lists is in Lua's tables and serve's JSON, with the same "
    "value") {
  script::Vm vm(script::VmOptions{});
  lua_State* L = vm.state();
  // Two aircraft in conflict, one on a route with a CAS and a Mach constraint,
  // the other at a selected Mach; a third in a commanded turn.
  REQUIRE(vm.run_string(R"(
    S = squawk.sim.new{}
    for line in ([[ASAS ON
CRE KL204 B744 52 4 90 FL200 280
CRE AF123 A320 52 4.6 270 FL200 0.78
DEFWPT EXIT1 52.0 5.0
DEFWPT EXIT2 52.0 6.0
KL204 ADDWPT EXIT1 FL240 250
KL204 ADDWPT EXIT2 FL300 0.8
CRE BAW1 A320 50 0 0 FL100 250
HDG BAW1 200 LEFT]]):gmatch("[^\n]+") do
      local ok, msg = S:exec(line)
      assert(ok, line .. ": " .. tostring(msg))
    end
    S:run_for(20)
    assert(S:exec("OP"))  -- the JSON then shows the detector's pairs, as Lua does (held: detected afresh)
    AIRCRAFT, CONFLICTS, LOS = S:aircraft(), S:conflicts(), S:los())",
                        "fields")
              .is_ok());
  lua_getglobal(L, "S");
  script::ObjectHeader* h = script::test_header(L, -1, "squawk.sim.Sim");
  REQUIRE(h);
  const command::Stack& stack = reinterpret_cast<script::ObjectBox<command::Stack>*>(h)->value;
  lua_pop(L, 1);
  const json j = serve::state_json(stack);

  REQUIRE(j["aircraft"].size() == 3);
  lua_getglobal(L, "AIRCRAFT");
  REQUIRE(lua_rawlen(L, -1) == 3);
  for (size_t i = 0; i < 3; ++i) {
    lua_rawgeti(L, -1, static_cast<lua_Integer>(i + 1));
    check_same(L, j["aircraft"][i], sim::fields::kAircraft,
               "aircraft " + j["aircraft"][i]["id"].get<std::string>());
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  // Both kinds of selected speed and a route with both kinds of constraint were shown.
  CHECK(j["aircraft"][0]["sel_cas_kt"].is_number());
  CHECK(j["aircraft"][1]["sel_mach"].get<double>() == doctest::Approx(0.78));
  CHECK(j["aircraft"][0]["route"][0]["cas_kt"].get<double>() == doctest::Approx(250.0));
  CHECK(j["aircraft"][0]["route"][1]["mach"].get<double>() == doctest::Approx(0.8));
  CHECK(j["aircraft"][2]["sel_turn"] == "LEFT");
  CHECK(j["aircraft"][0]["sel_turn"].is_null());

  // Conflicts: Lua has both orders, the JSON each pair once (own's id first) plus the CPA points.
  REQUIRE(j["conflicts"].size() == 1);
  json c = j["conflicts"][0];
  CHECK(c["cpa"].size() == 2);
  c.erase("cpa");
  lua_getglobal(L, "CONFLICTS");
  REQUIRE(lua_rawlen(L, -1) == 2);
  bool seen = false;
  for (lua_Integer k = 1; k <= 2; ++k) {
    lua_rawgeti(L, -1, k);
    lua_getfield(L, -1, "own");
    const bool first = std::string(lua_tostring(L, -1)) == c["own"].get<std::string>();
    lua_pop(L, 1);
    if (first) {
      check_same(L, c, sim::fields::kConflict, "conflict");
      seen = true;
    }
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  CHECK(seen);
}

TEST_CASE("a loss of separation has the kLos fields in Lua and in JSON") {
  script::Vm vm(script::VmOptions{});
  lua_State* L = vm.state();
  REQUIRE(vm.run_string(R"(
    S = squawk.sim.new{}
    assert(S:exec("ASAS ON; CRE KL1 A320 52 4 90 FL200 250; CRE KL2 A320 52 4.02 270 FL201 250"))
    S:run_for(2)
    assert(S:exec("OP"))
    LOS = S:los())",
                        "los")
              .is_ok());
  lua_getglobal(L, "S");
  const command::Stack& stack = reinterpret_cast<script::ObjectBox<command::Stack>*>(
                                    script::test_header(L, -1, "squawk.sim.Sim"))
                                    ->value;
  lua_pop(L, 1);
  const json j = serve::state_json(stack);
  REQUIRE(j["los"].size() == 1);
  lua_getglobal(L, "LOS");
  REQUIRE(lua_rawlen(L, -1) == 2);
  lua_rawgeti(L, -1, 1);  // KL1 first: the JSON's order
  check_same(L, j["los"][0], sim::fields::kLos, "los");
  lua_pop(L, 2);
}

TEST_CASE("a command reply's JSON (POST /api/command) holds exactly kCommandReply's fields") {
  script::Vm vm({});
  auto session = script::ServeSession::open(vm, "", "offline");
  REQUIRE(session.is_ok());
  serve::LiveSim live(**session, {});
  live.start();
  auto reply = [&](const std::string& text, const std::string& selected) {
    auto r = live.call(
        [&](serve::LiveSim& l) {
          return l.command(text, "controller", {"controller", selected});
        },
        std::chrono::seconds(30));
    REQUIRE(r.is_ok());
    const json j = *r;
    std::set<std::string> declared, keys;
    for (const auto& f : script::fields::kCommandReply) declared.insert(f.name);
    for (const auto& [key, value] : j.items()) keys.insert(key);
    CAPTURE(text);
    CHECK(keys == declared);
    CHECK(j["text"] == text);
    CHECK(j["commands"].is_array());
    CHECK(j["ok"].is_boolean());
    CHECK(j["message"].is_string());
    CHECK(j["trace"].is_string());
    CHECK(j["cancelled"].is_boolean());
    return j;
  };
  json j = reply("!CRE KL204 B744 52 4 90 FL200 280", "");
  CHECK(j["ok"] == true);
  CHECK(j["commands"] == json::array({"CRE KL204 B744 52 4 90 FL200 280"}));
  CHECK((j["ask"].is_null() && j["addressed"].is_null() && j["cancelled"] == false));
  reply("!CRE AF123 A320 53 4 90 FL200 280", "");
  j = reply("climb to flight level 300", "");  // two aircraft, none named: a question
  CHECK(j["ok"] == false);
  CHECK(!j["ask"].get<std::string>().empty());
  j = reply("cancel", "");
  CHECK(j["cancelled"] == true);
  j = reply("climb to flight level 300", "KL204");  // said to the selected aircraft
  CHECK(j["addressed"] == "KL204");
  CHECK(j["commands"] == json::array({"ALT KL204 FL300"}));
  CHECK(j["ask"].is_null());
  live.stop();
}

TEST_CASE("a Lua reward function sees exactly kStepFacts's fields, with their values and types") {
  // A scenario whose reward returns what `body` computes from f.
  auto reward_of = [](const std::string& body, const env::StepFacts& facts) {
    const auto path = std::filesystem::temp_directory_path() / "squawk_test_step_fields.lua";
    std::ofstream(path) << "return { reward = function(f) " << body << " end }\n";
    auto s = script::load_scenario(path.string(), {});
    REQUIRE_MESSAGE(s, s.status().message());
    REQUIRE(s->train_env.reward_fn);
    const double r = s->train_env.reward_fn(facts);
    CHECK(s->reward_error().is_ok());
    return r;
  };
  env::StepFacts f;
  f.step = 7;
  f.intrusions = 2;
  f.substep_intrusions = 5;
  f.cpa_ratio = 0.25;
  f.drift = -12.5;
  f.heading_change = 22.5;
  f.waypoint_distance = 1234.5;
  f.reached = true;
  // The names the scenarios read (scenario.h), each with its own value.
  CHECK(
      reward_of("return f.step == 7 and f.intrusions == 2 and f.substep_intrusions == 5 and "
                "f.cpa_ratio == 0.25 and f.drift_deg == -12.5 and f.heading_change_deg == 22.5 and "
                "f.waypoint_distance_m == 1234.5 and f.reached and 1 or 0",
                f) == 1.0);
  CHECK(reward_of("local n = 0 for _ in pairs(f) do n = n + 1 end return n", f) ==
        std::size(script::fields::kStepFacts));
  for (const auto& field : script::fields::kStepFacts) {
    const std::string name = field.name;
    CAPTURE(name);
    const sim::fields::Value v = field.get(f);
    if (const bool* b = std::get_if<bool>(&v)) {
      CHECK(reward_of("return f." + name + " == true and 1 or 0", f) == (*b ? 1.0 : 0.0));
    } else if (const long long* n = std::get_if<long long>(&v)) {
      CHECK(reward_of("return math.type(f." + name + ") == 'integer' and f." + name + " or -1",
                      f) == static_cast<double>(*n));
    } else {
      CHECK(reward_of("return f." + name, f) == std::get<double>(v));
    }
  }
}

TEST_CASE("env:observation() holds exactly kObservation's fields, the values of the flat form") {
  script::Vm vm(script::VmOptions{});
  lua_State* L = vm.state();
  REQUIRE(vm.run_string(R"(
    local e = squawk.env.new{rules = "paper"}
    e:reset(3)
    OBS, FLAT = e:observation(), e:flat())",
                        "observation")
              .is_ok());
  lua_getglobal(L, "FLAT");
  std::vector<float> flat(lua_rawlen(L, -1));
  for (size_t k = 0; k < flat.size(); ++k) {
    lua_rawgeti(L, -1, static_cast<lua_Integer>(k + 1));
    flat[k] = static_cast<float>(lua_tonumber(L, -1));
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  auto o = env::unflatten(flat);  // the MLP's view, written by env/observation.cpp
  REQUIRE_MESSAGE(o, o.status().message());
  REQUIRE(o->num_intruders() > 0);
  lua_getglobal(L, "OBS");
  std::set<std::string> declared;
  for (const auto& f : script::fields::kObservation) {
    declared.insert(f.name);
    const std::string name = f.name;
    CAPTURE(name);
    const auto want = std::get<std::span<const double>>(f.get(*o));
    lua_getfield(L, -1, f.name);
    REQUIRE(lua_istable(L, -1));
    REQUIRE(lua_rawlen(L, -1) == want.size());
    for (size_t k = 0; k < want.size(); ++k) {
      lua_rawgeti(L, -1, static_cast<lua_Integer>(k + 1));
      CHECK(static_cast<float>(lua_tonumber(L, -1)) == static_cast<float>(want[k]));
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
  }
  CHECK(lua_keys(L) == declared);
  // Named as the flat form orders them: the fields' arrays in alphabetical order of the names.
  std::vector<float> by_name;
  for (const std::string& name : declared) {
    lua_getfield(L, -1, name.c_str());
    for (lua_Integer k = 1; k <= static_cast<lua_Integer>(lua_rawlen(L, -1)); ++k) {
      lua_rawgeti(L, -1, k);
      by_name.push_back(static_cast<float>(lua_tonumber(L, -1)));
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
  }
  CHECK(by_name == flat);
  lua_pop(L, 1);
}

namespace {

// `list`'s fields of `row` as the dump template below writes them:
// name=kind:value, sorted by name (kind: Lua's math.type of a number).
template <class Row, size_t N>
std::map<std::string, std::string> expected_dump(const sim::fields::Field<Row> (&list)[N],
                                                 const Row& row) {
  std::map<std::string, std::string> out;
  for (const auto& f : list) {
    const sim::fields::Value v = f.get(row);
    char buf[64];
    if (const double* x = std::get_if<double>(&v)) {
      std::snprintf(buf, sizeof buf, "float:%.14g", *x);
      out[f.name] = buf;
    } else if (const long long* n = std::get_if<long long>(&v)) {
      out[f.name] = "integer:" + std::to_string(*n);
    } else {
      out[f.name] = std::string(std::get<std::string_view>(v));
    }
  }
  return out;
}

std::string joined(const std::map<std::string, std::string>& m) {
  std::string s;
  for (const auto& [k, v] : m) s += (s.empty() ? "" : ";") + k + "=" + v;
  return s;
}

}  // namespace

TEST_CASE(
    "a phrasing template's advise(d) sees exactly kAdvisory's fields, and kAdvisoryTraffic's in "
    "d.traffic") {
  const auto path = std::filesystem::temp_directory_path() / "squawk_test_advisory_fields.lua";
  std::ofstream(path) << R"(
    local function dump(t)
      local keys, out = {}, {}
      for k in pairs(t) do keys[#keys + 1] = k end
      table.sort(keys)
      for _, k in ipairs(keys) do
        local v = t[k]
        if type(v) == "table" then
          v = "{" .. dump(v) .. "}"
        elseif math.type(v) then
          v = math.type(v) .. ":" .. tostring(v)
        end
        out[#out + 1] = k .. "=" .. v
      end
      return table.concat(out, ";")
    end
    return { advise = dump })";
  auto phraser = script::AdvisoryPhraser::load(path.string(), {});
  REQUIRE_MESSAGE(phraser, phraser.status().message());
  script::Advisory a{"KL204", 0.5, 270, 87.25, "left", std::nullopt};
  auto plain = phraser->phrase(a);
  REQUIRE_MESSAGE(plain, plain.status().message());
  CHECK(*plain == joined(expected_dump(script::fields::kAdvisory, a)));
  CHECK(
      *plain ==
      "action=float:0.5;callsign=KL204;current_heading=float:87.25;heading=integer:270;turn=left");
  a.traffic = script::Advisory::Traffic{"AF123", 2, 4.5};
  auto with_traffic = phraser->phrase(a);
  REQUIRE_MESSAGE(with_traffic, with_traffic.status().message());
  auto want = expected_dump(script::fields::kAdvisory, a);
  want["traffic"] = "{" + joined(expected_dump(script::fields::kAdvisoryTraffic, *a.traffic)) + "}";
  CHECK(*with_traffic == joined(want));
  CHECK(want["traffic"] == "{clock=integer:2;distance_nm=float:4.5;id=AF123}");
}
