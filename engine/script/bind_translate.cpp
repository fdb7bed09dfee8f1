// squawk.translate: the offline translator and the corpus scorer.
//
//   squawk.translate.offline(text, [sim | world]) -> {commands = {"CMD", ...}, ask = nil}
//                                                  | {commands = {}, ask = "question"}
//       The optional second argument gives the current traffic for relative
//       instructions and callsign matching: a squawk.sim object (its aircraft
//       and DEFWPT waypoints are read, nothing is run), or a plain table:
//         {aircraft = {{id=, type=, lat=, lon=, hdg_deg=, alt_ft=, cas_kt=,
//                       mach=, route = {"WPT", ...}}, ...},
//          waypoints = {"NAME", ...}}
//       Missing fields read as 0 / empty.
//   squawk.translate.score(produced, asked, expected) -> boolean
//       The corpus scoring rules (shared/corpora/README.md): `produced` is
//       "CMD ; CMD", `asked` true when the translator asked instead.
//   squawk.translate.corpus(path) -> {{id=, setup=, utterance=, expected=, category=}, ...}
#include "core/units.h"
#include "script/bindings.h"
#include "script/lua_util.h"
#include "script/vm.h"
#include "script/translate_graph.h"
#include "translate/corpus.h"
#include "translate/offline_translator.h"
#include "translate/scorer.h"
#include "translate/stack_world.h"

namespace squawk::script {

namespace {

// Metatable of squawk.sim objects (bind_sim.cpp): full userdata holding a command::Stack.
constexpr const char* kSimMt = "squawk.sim.Sim";

std::vector<std::string> string_list(lua_State* L, int idx, const char* what) {
  std::vector<std::string> out;
  if (lua_isnil(L, idx)) return out;
  if (!lua_istable(L, idx)) throw ArgError(std::string(what) + ": expected a list of strings");
  const lua_Integer n = luaL_len(L, idx);
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_geti(L, idx, i);
    if (!lua_isstring(L, -1)) throw ArgError(std::string(what) + "[" + std::to_string(i) + "]: expected a string");
    out.emplace_back(lua_tostring(L, -1));
    lua_pop(L, 1);
  }
  return out;
}

translate::StaticWorld read_world(lua_State* L, int idx) {
  translate::StaticWorld w;
  lua_getfield(L, idx, "aircraft");
  if (lua_istable(L, -1)) {
    const lua_Integer n = luaL_len(L, -1);
    for (lua_Integer i = 1; i <= n; ++i) {
      lua_geti(L, -1, i);
      if (!lua_istable(L, -1)) throw ArgError("world.aircraft[" + std::to_string(i) + "]: expected a table");
      translate::AircraftView a;
      a.id = field_string(L, -1, "id", "");
      if (a.id.empty()) throw ArgError("world.aircraft[" + std::to_string(i) + "]: needs an id");
      a.type = field_string(L, -1, "type", "");
      a.lat_deg = field_in(L, -1, "lat", 0.0, -90, 90);
      a.lon_deg = field_in(L, -1, "lon", 0.0, -180, 180);
      a.hdg_deg = field_in(L, -1, "hdg_deg", 0.0, -360, 360);
      a.alt_m = units::ft_to_m(field_in(L, -1, "alt_ft", 0.0, -2000, 100000));
      a.cas_ms = units::kt_to_ms(field_in(L, -1, "cas_kt", 0.0, 0, 2000));
      a.mach = field_in(L, -1, "mach", 0.0, 0, 10);
      lua_getfield(L, -1, "route");
      a.route = string_list(L, lua_gettop(L), "route");
      lua_pop(L, 1);
      w.add_aircraft(std::move(a));
      lua_pop(L, 1);
    }
  } else if (!lua_isnil(L, -1)) {
    throw ArgError("world.aircraft: expected a list of aircraft tables");
  }
  lua_pop(L, 1);
  lua_getfield(L, idx, "waypoints");
  for (auto& name : string_list(L, lua_gettop(L), "world.waypoints")) w.add_waypoint(std::move(name));
  lua_pop(L, 1);
  return w;
}

void push_translation(lua_State* L, const translate::Translation& tr) {
  lua_createtable(L, 0, 2);
  lua_createtable(L, static_cast<int>(tr.commands.size()), 0);
  for (size_t i = 0; i < tr.commands.size(); ++i) {
    lua_pushstring(L, tr.commands[i].c_str());
    lua_seti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_setfield(L, -2, "commands");
  if (tr.asked()) {
    lua_pushstring(L, tr.ask.c_str());
    lua_setfield(L, -2, "ask");
  }
}

int l_offline(lua_State* L) {
  const std::string text = arg_string(L, 1, "text");
  translate::Translation tr;
  if (lua_isnoneornil(L, 2)) {
    tr = translate::translate_offline(text, nullptr);
  } else if (const auto* sim = test_object<command::Stack>(L, 2, kSimMt, "world")) {
    translate::StackWorld w(*sim);
    tr = translate::translate_offline(text, &w);
  } else if (lua_istable(L, 2)) {
    translate::StaticWorld w = read_world(L, 2);
    tr = translate::translate_offline(text, &w);
  } else {
    throw ArgError(type_error(L, 2, "world", "nil, a squawk.sim object or a world table"));
  }
  push_translation(L, tr);
  return 1;
}

int l_score(lua_State* L) {
  const std::string produced = arg_string(L, 1, "produced");
  const bool asked = lua_toboolean(L, 2) != 0;
  const std::string expected = arg_string(L, 3, "expected");
  lua_pushboolean(L, translate::score_case(produced, asked, expected));
  return 1;
}

int l_corpus(lua_State* L) {
  auto cases = translate::read_corpus(readable(L, arg_string(L, 1, "path"), "corpus"));
  check_status(cases.status());
  lua_createtable(L, static_cast<int>(cases->size()), 0);
  for (size_t i = 0; i < cases->size(); ++i) {
    const auto& c = (*cases)[i];
    lua_createtable(L, 0, 5);
    const std::pair<const char*, const std::string*> fields[] = {
        {"id", &c.id}, {"setup", &c.setup}, {"utterance", &c.utterance}, {"expected", &c.expected},
        {"category", &c.category}};
    for (const auto& [k, v] : fields) {
      lua_pushstring(L, v->c_str());
      lua_setfield(L, -2, k);
    }
    lua_seti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  return 1;
}

// Calls graph.translate(text, {mode=, setup=}) with the module table on the
// stack top; leaves the result on the stack.
int l_call_graph(lua_State* L) {
  // args: module table, text, mode, setup
  lua_getfield(L, 1, "translate");
  if (!lua_isfunction(L, -1)) throw ArgError("module translate.graph has no function translate(text, opts)");
  lua_pushvalue(L, 2);
  lua_createtable(L, 0, 2);
  lua_pushvalue(L, 3);
  lua_setfield(L, -2, "mode");
  lua_pushvalue(L, 4);
  lua_setfield(L, -2, "setup");
  lua_call(L, 2, 1);
  return 1;
}

}  // namespace

void bind_translate(lua_State* L) {
  push_squawk_subtable(L, "translate");
  const luaL_Reg fns[] = {{"offline", guarded<l_offline>},
                          {"score", guarded<l_score>},
                          {"corpus", guarded<l_corpus>},
                          {nullptr, nullptr}};
  luaL_setfuncs(L, fns, 0);
  lua_pop(L, 1);
}

Result<translate::Translation> run_translation_graph(Vm& vm, const std::string& text, const std::string& mode,
                                                     const std::string& setup) {
  lua_State* L = vm.state();
  const int top = lua_gettop(L);
  // Load the module once per Vm through the sandbox's require.
  lua_getfield(L, LUA_REGISTRYINDEX, "squawk.translate.graph");
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    lua_getglobal(L, "require");
    lua_pushstring(L, kTranslationGraphModule);
    if (lua_pcall(L, 1, 1, 0) != LUA_OK) {
      std::string msg = std::string("cannot load the translation graph (scripts/translate/graph.lua): ") +
                        (lua_isstring(L, -1) ? lua_tostring(L, -1) : "?");
      lua_settop(L, top);
      return Status::not_found(msg);
    }
    lua_pushvalue(L, -1);
    lua_setfield(L, LUA_REGISTRYINDEX, "squawk.translate.graph");
  }
  lua_pushcfunction(L, guarded<l_call_graph>);
  lua_insert(L, -2);
  lua_pushstring(L, text.c_str());
  lua_pushstring(L, mode.c_str());
  lua_pushstring(L, setup.c_str());
  const Vm::Call budget(Vm::of(L));  // a fresh instruction budget
  if (lua_pcall(L, 4, 1, 0) != LUA_OK) {
    std::string msg = std::string("translation graph: ") + (lua_isstring(L, -1) ? lua_tostring(L, -1) : "?");
    lua_settop(L, top);
    return Status::internal(msg);
  }
  translate::Translation tr;
  if (!lua_istable(L, -1)) {
    lua_settop(L, top);
    return Status::invalid("translation graph: translate() must return {commands = {...}} or {ask = \"...\"}");
  }
  lua_getfield(L, -1, "ask");
  if (lua_type(L, -1) == LUA_TSTRING) tr.ask = lua_tostring(L, -1);
  lua_pop(L, 1);
  lua_getfield(L, -1, "commands");
  if (lua_istable(L, -1)) {
    const lua_Integer n = luaL_len(L, -1);
    for (lua_Integer i = 1; i <= n; ++i) {
      lua_geti(L, -1, i);
      if (lua_isstring(L, -1)) tr.commands.emplace_back(lua_tostring(L, -1));
      lua_pop(L, 1);
    }
  }
  lua_settop(L, top);
  return tr;
}

}  // namespace squawk::script
