// squawk.translate: the translation graph, the extractors the Lua grammar
// reads, and the corpus scorer.
//
//   squawk.translate.run(text, opts) -> graph.translate(text, opts) of
//       scripts/translate/graph.lua (the one translation path)
//   squawk.translate.request(fn, ...) -> fn(...)'s results: fn runs as one translation
//       request (script/translate_graph.h: RequestCollection, the collector stopped and a
//       step owed for after the reply); an error of fn is raised again, the collector
//       restarted first. For the translation of a person's line only, never around
//       commands, a simulation run or a script.
//   squawk.translate.tables(names, phonetic) -> tables   the names the matchers
//       know: names = {airlines = {{telephony, icao}, ...}, types = {{maker,
//       model, icao}, ...}, designators = {...}} (scripts/translate/names.lua),
//       lexicon: scripts/translate/lexicon.lua (phonetic, keywords, fillers,
//       spelling = {targets, common})
//   squawk.translate.utterance(text, world | nil, tables) -> u   the C++ extractors:
//       u:tokens()  {{kind = "word"|"number"|"punct"|"quoted", text, raw, num,
//                    number_word, keyword, filler, alpha}, ...} (spelling fixed)
//       u:refs()    {{kind = "aircraft"|"type"|"waypoint", name, b, e, exists, spoken,
//                    heard = {id, airline, digits} when matched inexactly}, ...}
//       u:quantities(b, e)  {{kind, value, b, e, fl, by, to, turn, number = {...}}, ...}
//                   in tokens [b, e) not yet used (kinds: plain alt speed mach
//                   heading vs lat lon time dist percent mult angle)
//       u:mark_used(b, e), u:used(i), u:number(b, e) (re-read a sub-range)
//       Token ranges are 1-based, [b, e). `world` gives the traffic for
//       callsign matching: {aircraft = {{id=, route = {"WPT", ...}, and
//       sim:aircraft()'s other fields (lat, lon, hdg_deg, alt_ft, cas_kt,
//       sel_mach checked to be numbers in range)}, ...}, waypoints = {"NAME", ...}}.
//   squawk.translate.best_match(spoken, names) -> index, score | nothing
//   squawk.translate.json_decode(text) -> value (objects/arrays as tables, null as nil)
//   squawk.translate.score(produced, asked, expected [, setup]) -> boolean
//       The corpus scoring rules (shared/corpora/README.md): `produced` is
//       "CMD ; CMD", `asked` true when the translator asked instead.
//   squawk.translate.corpus(path) -> {{id=, setup=, utterance=, expected=, category=}, ...}
//   squawk.translate.evaluate(path, translator) -> {cases=, right=, asked=, wrong=}
//       eval-translate's scoring (translate::evaluate, engine/translate/corpus.h):
//       translator(case) is called with each case table as corpus() gives it
//       and returns a graph result ({commands}, {ask}, .confirm, .error); an
//       error raised by it stops the evaluation, naming the case.
#include "script/bindings.h"
#include "script/lua_util.h"
#include "script/vm.h"
#include "script/translate_graph.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "translate/corpus.h"
#include "translate/fuzzy.h"
#include "translate/lexer.h"
#include "translate/number_words.h"
#include "translate/quantities.h"
#include "translate/references.h"
#include "translate/tables.h"
#include "translate/vocabulary.h"
#include "translate/scorer.h"

namespace squawk::script {

namespace {

// Metatable of squawk.sim objects (bind_sim.cpp): full userdata holding a command::Stack.
constexpr const char* kSimMt = "squawk.sim.Sim";

std::vector<std::string> string_list(lua_State* L, int idx, const char* what) {
  std::vector<std::string> out;
  if (lua_isnil(L, idx)) return out;
  if (!lua_istable(L, idx)) throw ArgError(std::string(what) + ": expected a list of strings");
  const lua_Integer n = length(L, idx);
  for (lua_Integer i = 1; i <= n; ++i) {
    get_index(L, idx, i);
    if (!lua_isstring(L, -1)) throw ArgError(std::string(what) + "[" + std::to_string(i) + "]: expected a string");
    out.emplace_back(lua_tostring(L, -1));
    lua_pop(L, 1);
  }
  return out;
}

translate::StaticWorld read_world(lua_State* L, int idx) {
  translate::StaticWorld w;
  get_field(L, idx, "aircraft");
  if (lua_istable(L, -1)) {
    const lua_Integer n = length(L, -1);
    for (lua_Integer i = 1; i <= n; ++i) {
      get_index(L, -1, i);
      if (!lua_istable(L, -1)) throw ArgError("world.aircraft[" + std::to_string(i) + "]: expected a table");
      translate::AircraftView a;
      a.id = field_string(L, -1, "id", "");
      if (a.id.empty()) throw ArgError("world.aircraft[" + std::to_string(i) + "]: needs an id");
      // The traffic fields the grammar reads (sim/fields.h's names, units) are numbers in range.
      static constexpr struct {
        const char* name;
        double lo, hi;
      } kChecked[] = {{"lat", -90, 90},          {"lon", -180, 180},  {"hdg_deg", -360, 360},
                      {"alt_ft", -2000, 100000}, {"cas_kt", 0, 2000}, {"sel_mach", 0, 10}};
      for (const auto& c : kChecked) field_in(L, -1, c.name, 0.0, c.lo, c.hi);
      get_field(L, -1, "route");
      a.route = string_list(L, lua_gettop(L), "route");
      lua_pop(L, 1);
      w.add_aircraft(std::move(a));
      lua_pop(L, 1);
    }
  } else if (!lua_isnil(L, -1)) {
    throw ArgError("world.aircraft: expected a list of aircraft tables");
  }
  lua_pop(L, 1);
  get_field(L, idx, "waypoints");
  for (auto& name : string_list(L, lua_gettop(L), "world.waypoints")) w.add_waypoint(std::move(name));
  lua_pop(L, 1);
  return w;
}

void push_case(lua_State* L, const translate::CorpusCase& c) {
  lua_createtable(L, 0, 5);
  const std::pair<const char*, const std::string*> fields[] = {
      {"id", &c.id}, {"setup", &c.setup}, {"utterance", &c.utterance}, {"expected", &c.expected},
      {"category", &c.category}};
  for (const auto& [k, v] : fields) {
    lua_pushstring(L, v->c_str());
    lua_setfield(L, -2, k);
  }
}

int l_score(lua_State* L) {
  const std::string produced = arg_string(L, 1, "produced");
  const bool asked = lua_toboolean(L, 2) != 0;
  const std::string expected = arg_string(L, 3, "expected");
  const std::string setup = lua_isnoneornil(L, 4) ? std::string() : arg_string(L, 4, "setup");
  lua_pushboolean(L, translate::score_case(produced, asked, expected, setup));
  return 1;
}

int l_corpus(lua_State* L) {
  auto cases = translate::read_corpus(readable(L, arg_string(L, 1, "path"), "corpus"));
  check_status(cases.status());
  lua_createtable(L, static_cast<int>(cases->size()), 0);
  for (size_t i = 0; i < cases->size(); ++i) {
    push_case(L, (*cases)[i]);
    lua_seti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  return 1;
}

int l_evaluate(lua_State* L) {
  auto cases = translate::read_corpus(readable(L, arg_string(L, 1, "path"), "corpus"));
  check_status(cases.status());
  if (!lua_isfunction(L, 2)) throw ArgError("translator: expected a function(case) -> graph result");
  std::string failure;
  const translate::EvalReport report = translate::evaluate(*cases, [&](const translate::CorpusCase& c) {
    Result<translate::Translation> tr = Status::internal("not run: an earlier case failed");
    if (!failure.empty()) return tr;
    const int top = lua_gettop(L);
    lua_pushvalue(L, 2);
    push_case(L, c);
    if (lua_pcall(L, 1, 1, 0) != LUA_OK) {
      failure = c.id + ": " + error_text(L, -1);
    } else {
      tr = read_graph_result(L);
      if (!tr.is_ok()) failure = c.id + ": " + tr.status().message();
    }
    lua_settop(L, top);
    return tr;
  });
  if (!failure.empty()) throw ArgError("evaluate: " + failure);
  lua_createtable(L, 0, 4);
  const std::pair<const char*, int> counts[] = {
      {"cases", report.cases}, {"right", report.correct}, {"asked", report.asked}, {"wrong", report.wrong}};
  for (const auto& [k, v] : counts) {
    lua_pushinteger(L, v);
    lua_setfield(L, -2, k);
  }
  return 1;
}

// ---- squawk.translate.utterance: the C++ extractors the Lua grammar reads ----

constexpr const char* kUtteranceMt = "squawk.translate.Utterance";
constexpr const char* kTablesMt = "squawk.translate.Tables";

// The string at t[i] of the table at idx, or an ArgError naming where.
std::string string_at(lua_State* L, int idx, lua_Integer i, const std::string& where) {
  get_index(L, idx, i);
  if (!lua_isstring(L, -1)) throw ArgError(where + "[" + std::to_string(i) + "]: expected a string");
  std::string v = lua_tostring(L, -1);
  lua_pop(L, 1);
  return v;
}

// A list of strings at field `key` of the table at idx (nested: "a.b").
std::vector<std::string> field_list(lua_State* L, int idx, const char* key, const char* sub = nullptr) {
  get_field(L, idx, key);
  if (sub) {
    if (!lua_istable(L, -1)) throw ArgError(std::string("lexicon.") + key + ": expected a table");
    get_field(L, -1, sub);
    lua_remove(L, -2);
  }
  auto out = string_list(L, lua_gettop(L), (std::string("lexicon.") + key + (sub ? std::string(".") + sub : "")).c_str());
  lua_pop(L, 1);
  return out;
}

// squawk.translate.tables({airlines = {{telephony, icao}, ...}, types = {{maker,
// model, icao}, ...}, designators = {...}}, lexicon) -> tables
int l_tables(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  luaL_checktype(L, 2, LUA_TTABLE);
  std::vector<translate::Airline> airlines;
  std::vector<translate::TypeName> types;
  std::vector<std::string> designators;
  std::vector<std::pair<std::string, char>> phonetic;
  get_field(L, 1, "airlines");
  for (lua_Integer i = 1; lua_istable(L, -1) && i <= length(L, -1); ++i) {
    get_index(L, -1, i);
    const int row = lua_gettop(L);
    const std::string where = "names.airlines[" + std::to_string(i) + "]";
    airlines.push_back({string_at(L, row, 1, where), string_at(L, row, 2, where)});
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  get_field(L, 1, "types");
  for (lua_Integer i = 1; lua_istable(L, -1) && i <= length(L, -1); ++i) {
    get_index(L, -1, i);
    const int row = lua_gettop(L);
    const std::string where = "names.types[" + std::to_string(i) + "]";
    types.push_back({string_at(L, row, 1, where), string_at(L, row, 2, where), string_at(L, row, 3, where)});
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  get_field(L, 1, "designators");
  designators = string_list(L, lua_gettop(L), "names.designators");
  lua_pop(L, 1);
  translate::Vocabulary vocabulary(field_list(L, 2, "keywords"), field_list(L, 2, "fillers"),
                                  field_list(L, 2, "spelling", "targets"), field_list(L, 2, "spelling", "common"));
  get_field(L, 2, "phonetic");
  if (!lua_istable(L, -1)) throw ArgError("lexicon.phonetic: expected a table {word = \"A\", ...}");
  const int ph = lua_gettop(L);
  lua_pushnil(L);
  while (lua_next(L, ph) != 0) {
    if (lua_type(L, -2) == LUA_TSTRING && lua_type(L, -1) == LUA_TSTRING && lua_rawlen(L, -1) == 1)
      phonetic.emplace_back(lua_tostring(L, -2), lua_tostring(L, -1)[0]);
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  new_object<translate::Tables>(L, kTablesMt, std::move(airlines), std::move(types), std::move(designators),
                                std::move(phonetic), std::move(vocabulary));
  return 1;
}

// Tokens (spelling fixed), the references found in them, and the mask of
// tokens already consumed (by references and by the grammar).
struct Utterance {
  std::vector<translate::Token> tokens;
  std::vector<bool> used;
  std::vector<translate::Reference> refs;
  std::vector<bool> keyword, filler;  // per token, from the vocabulary
};

const char* tok_kind(translate::TokKind k) {
  switch (k) {
    case translate::TokKind::kWord: return "word";
    case translate::TokKind::kNumber: return "number";
    case translate::TokKind::kPunct: return "punct";
    case translate::TokKind::kQuoted: return "quoted";
  }
  return "word";
}

const char* q_kind(translate::QKind k) {
  static const char* const names[] = {"plain", "alt", "speed", "mach", "heading", "vs", "lat",
                                      "lon", "time", "dist", "percent", "mult", "angle"};
  return names[static_cast<int>(k)];
}

// Token indices go to Lua 1-based; ranges are [b, e) with e one past the end.
void push_number(lua_State* L, const translate::SpokenNumber& n, size_t offset) {
  lua_createtable(L, 0, 10);
  set_number(L, "value", n.value);
  set_string(L, "digits", n.digits);
  set_integer(L, "b", static_cast<lua_Integer>(n.begin + offset + 1));
  set_integer(L, "e", static_cast<lua_Integer>(n.end + offset + 1));
  set_boolean(L, "typed", n.typed);
  set_boolean(L, "thousand", n.has_thousand);
  set_boolean(L, "hundred", n.has_hundred);
  set_boolean(L, "decimal", n.has_decimal);
  set_integer(L, "groups", n.groups);
  set_boolean(L, "lead_digit", n.leading_digit_word);
}

int l_utterance(lua_State* L) {
  const std::string text = arg_string(L, 1, "text");
  const auto* names = arg_object<translate::Tables>(L, 3, kTablesMt, "tables");
  lua_settop(L, 3);
  auto* u = new_object<Utterance>(L, kUtteranceMt);
  u->tokens = translate::lex(text);
  for (auto& t : u->tokens)
    if (t.kind == translate::TokKind::kWord) t.text = names->vocabulary().spell_fix(t.text);
  translate::fold_digit_homophones(u->tokens);
  for (const auto& t : u->tokens) {
    u->keyword.push_back(names->vocabulary().is_keyword(t.text));
    u->filler.push_back(names->vocabulary().is_filler(t.text));
  }
  u->used.assign(u->tokens.size(), false);
  if (lua_isnoneornil(L, 2)) {
    u->refs = translate::find_references(u->tokens, nullptr, u->used, *names);
  } else if (lua_istable(L, 2)) {
    translate::StaticWorld w = read_world(L, 2);
    u->refs = translate::find_references(u->tokens, &w, u->used, *names);
  } else {
    throw ArgError(type_error(L, 2, "world", "nil or a world table"));
  }
  return 1;
}

int l_u_tokens(lua_State* L) {
  auto* u = arg_object<Utterance>(L, 1, kUtteranceMt);
  lua_createtable(L, static_cast<int>(u->tokens.size()), 0);
  for (size_t i = 0; i < u->tokens.size(); ++i) {
    const auto& t = u->tokens[i];
    lua_createtable(L, 0, 8);
    lua_pushstring(L, tok_kind(t.kind));
    lua_setfield(L, -2, "kind");
    set_string(L, "text", t.text);
    set_string(L, "raw", t.raw);
    set_number(L, "num", t.num);
    set_boolean(L, "number_word", translate::is_number_word(t));
    if (t.kind == translate::TokKind::kWord) {
      set_boolean(L, "keyword", u->keyword[i]);
      set_boolean(L, "filler", u->filler[i]);
      set_boolean(L, "alpha", translate::is_alpha(t.text));
    }
    lua_seti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  return 1;
}

int l_u_refs(lua_State* L) {
  auto* u = arg_object<Utterance>(L, 1, kUtteranceMt);
  lua_createtable(L, static_cast<int>(u->refs.size()), 0);
  for (size_t i = 0; i < u->refs.size(); ++i) {
    const auto& r = u->refs[i];
    lua_createtable(L, 0, 6);
    lua_pushstring(L, r.kind == translate::RefKind::kAircraft ? "aircraft"
                      : r.kind == translate::RefKind::kType   ? "type"
                                                              : "waypoint");
    lua_setfield(L, -2, "kind");
    set_string(L, "name", r.name);
    set_integer(L, "b", static_cast<lua_Integer>(r.begin + 1));
    set_integer(L, "e", static_cast<lua_Integer>(r.end + 1));
    set_boolean(L, "exists", r.exists);
    set_boolean(L, "spoken", r.spoken);
    if (!r.heard.id.empty()) {
      lua_createtable(L, 0, 3);
      set_string(L, "id", r.heard.id);
      set_number(L, "airline", r.heard.airline);
      set_number(L, "digits", r.heard.digits);
      lua_setfield(L, -2, "heard");
    }
    lua_seti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  return 1;
}

// Clamps a Lua [b, e) range to 0-based token indices.
std::pair<size_t, size_t> range_arg(lua_State* L, const Utterance& u) {
  const long long n = static_cast<long long>(u.tokens.size());
  long long b = arg_integer(L, 2, "b") - 1, e = arg_integer(L, 3, "e") - 1;
  b = std::clamp(b, 0LL, n);
  e = std::clamp(e, b, n);
  return {static_cast<size_t>(b), static_cast<size_t>(e)};
}

int l_u_quantities(lua_State* L) {
  auto* u = arg_object<Utterance>(L, 1, kUtteranceMt);
  auto [b, e] = range_arg(L, *u);
  auto qs = translate::extract_quantities(u->tokens, b, e, u->used);
  lua_createtable(L, static_cast<int>(qs.size()), 0);
  for (size_t i = 0; i < qs.size(); ++i) {
    const auto& q = qs[i];
    lua_createtable(L, 0, 9);
    lua_pushstring(L, q_kind(q.kind));
    lua_setfield(L, -2, "kind");
    set_number(L, "value", q.value);
    set_integer(L, "b", static_cast<lua_Integer>(q.begin + 1));
    set_integer(L, "e", static_cast<lua_Integer>(q.end + 1));
    set_boolean(L, "fl", q.flight_level);
    set_boolean(L, "by", q.by);
    set_boolean(L, "to", q.to);
    set_integer(L, "turn", q.turn);
    push_number(L, q.number, 0);
    lua_setfield(L, -2, "number");
    lua_seti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  return 1;
}

int l_u_mark_used(lua_State* L) {
  auto* u = arg_object<Utterance>(L, 1, kUtteranceMt);
  auto [b, e] = range_arg(L, *u);
  for (size_t i = b; i < e; ++i) u->used[i] = true;
  return 0;
}

int l_u_used(lua_State* L) {
  auto* u = arg_object<Utterance>(L, 1, kUtteranceMt);
  const long long i = arg_integer(L, 2, "i") - 1;
  lua_pushboolean(L, i >= 0 && i < static_cast<long long>(u->used.size()) && u->used[static_cast<size_t>(i)]);
  return 1;
}

// u:number(b, e) -> the number read from tokens [b, e) alone when it spans
// all of them, else nil (re-reading part of a misheard number).
int l_u_number(lua_State* L) {
  auto* u = arg_object<Utterance>(L, 1, kUtteranceMt);
  auto [b, e] = range_arg(L, *u);
  std::vector<translate::Token> part(u->tokens.begin() + static_cast<long>(b), u->tokens.begin() + static_cast<long>(e));
  auto n = translate::read_number(part, 0);
  if (!n || n->end != part.size() || part.empty()) {
    lua_pushnil(L);
    return 1;
  }
  push_number(L, *n, b);
  return 1;
}

// Pushes a JSON value as Lua (objects and arrays as tables, null as nil).
void push_json(lua_State* L, const nlohmann::json& j, int depth) {
  if (depth > 64) throw ArgError("json_decode: nested deeper than 64 levels");
  luaL_checkstack(L, 4, "json_decode");
  if (j.is_object()) {
    lua_createtable(L, 0, static_cast<int>(j.size()));
    for (const auto& [k, v] : j.items()) {
      push_json(L, v, depth + 1);
      lua_setfield(L, -2, k.c_str());
    }
  } else if (j.is_array()) {
    lua_createtable(L, static_cast<int>(j.size()), 0);
    lua_Integer i = 0;
    for (const auto& v : j) {
      push_json(L, v, depth + 1);
      lua_seti(L, -2, ++i);
    }
  } else if (j.is_string()) {
    const auto& str = j.get_ref<const std::string&>();
    lua_pushlstring(L, str.data(), str.size());
  } else if (j.is_boolean()) {
    lua_pushboolean(L, j.get<bool>());
  } else if (j.is_number_integer()) {
    lua_pushinteger(L, j.get<lua_Integer>());
  } else if (j.is_number()) {
    lua_pushnumber(L, j.get<double>());
  } else {
    lua_pushnil(L);
  }
}

// squawk.translate.json_decode(text) -> value; raises on text that is not JSON.
int l_json_decode(lua_State* L) {
  const auto j = nlohmann::json::parse(arg_string(L, 1, "text"), nullptr, false);
  if (j.is_discarded()) throw ArgError("json_decode: the text is not valid JSON");
  push_json(L, j, 0);
  return 1;
}

// squawk.translate.best_match(spoken, {names}) -> index (1-based), score | nil
int l_best_match(lua_State* L) {
  const std::string spoken = arg_string(L, 1, "spoken");
  auto names = string_list(L, 2, "names");
  auto m = translate::best_match(spoken, names);
  if (!m) return 0;
  lua_pushinteger(L, static_cast<lua_Integer>(m->index + 1));
  lua_pushnumber(L, m->score);
  return 2;
}

int l_run(lua_State* L) {
  lua_settop(L, 2);
  push_graph_module(L);
  get_field(L, -1, "translate");
  lua_pushvalue(L, 1);
  lua_pushvalue(L, 2);
  lua_call(L, 2, 1);
  return 1;
}

// squawk.translate.request(fn, ...): no guarded<> (fn's Lua runs outside any binding's
// memory slack); the scope ends before an error is raised again.
int l_request(lua_State* L) {
  luaL_checktype(L, 1, LUA_TFUNCTION);
  int rc;
  {
    const RequestCollection request(Vm::of(L));
    rc = lua_pcall(L, lua_gettop(L) - 1, LUA_MULTRET, 0);
  }
  if (rc != LUA_OK) return lua_error(L);
  return lua_gettop(L);
}

}  // namespace

void bind_translate(lua_State* L) {
  push_squawk_subtable(L, "translate");
  const luaL_Reg fns[] = {{"run", guarded<l_run>},
                          {"request", l_request},
                          {"score", guarded<l_score>},
                          {"corpus", guarded<l_corpus>},
                          {"evaluate", guarded<l_evaluate>},
                          {"utterance", guarded<l_utterance>},
                          {"best_match", guarded<l_best_match>},
                          {"json_decode", guarded<l_json_decode>},
                          {"tables", guarded<l_tables>},
                          {nullptr, nullptr}};
  luaL_setfuncs(L, fns, 0);
  lua_pop(L, 1);
  const luaL_Reg methods[] = {{"tokens", guarded<l_u_tokens>},
                              {"refs", guarded<l_u_refs>},
                              {"quantities", guarded<l_u_quantities>},
                              {"mark_used", guarded<l_u_mark_used>},
                              {"used", guarded<l_u_used>},
                              {"number", guarded<l_u_number>},
                              {nullptr, nullptr}};
  define_class(L, kUtteranceMt, methods);
  const luaL_Reg no_methods[] = {{nullptr, nullptr}};
  define_class(L, kTablesMt, no_methods);
}

}  // namespace squawk::script
