#include "script/translate_graph.h"

#include <chrono>

#include "script/lua_util.h"

namespace squawk::script {

namespace {

// Metatable of squawk.sim objects (bind_sim.cpp).
constexpr const char* kSimMt = "squawk.sim.Sim";

void set_field(lua_State* L, const char* k, const std::string& v) {
  lua_pushlstring(L, v.data(), v.size());
  lua_setfield(L, -2, k);
}

// Pushes the opts table of a GraphRequest (the sim as a copy).
void push_request(lua_State* L, const GraphRequest& req) {
  lua_createtable(L, 0, 3);
  set_field(L, "mode", req.mode);
  set_field(L, "setup", req.setup);
  lua_pushboolean(L, req.verify);
  lua_setfield(L, -2, "verify");
  if (req.sim) {
    new_object<command::Stack>(L, kSimMt, *req.sim);
    lua_setfield(L, -2, "sim");
  }
}

// Appends the strings of the list t[key] (t at the stack top) to out; reads
// through the protected accessors (lua_util.h), so call it under catch_arg_errors.
void read_lines(lua_State* L, const char* key, std::vector<std::string>& out) {
  get_field(L, -1, key);
  if (lua_istable(L, -1)) {
    const lua_Integer n = length(L, -1);
    for (lua_Integer i = 1; i <= n; ++i) {
      get_index(L, -1, i);
      if (lua_isstring(L, -1)) out.emplace_back(lua_tostring(L, -1));
      lua_pop(L, 1);
    }
  }
  lua_pop(L, 1);
}

}  // namespace

Result<translate::Translation> read_graph_result(lua_State* L) {
  if (!lua_istable(L, -1))
    return Status::invalid("translation graph: translate() must return {commands = {...}} or {ask = \"...\"}");
  translate::Translation tr;
  SQUAWK_RETURN_IF_ERROR(catch_arg_errors(L, "translation graph's result: ", [&] {
    get_field(L, -1, "ask");
    if (lua_type(L, -1) == LUA_TSTRING) tr.ask = lua_tostring(L, -1);
    lua_pop(L, 1);
    get_field(L, -1, "error");
    if (lua_type(L, -1) == LUA_TSTRING) tr.error = lua_tostring(L, -1);
    lua_pop(L, 1);
    get_field(L, -1, "note");
    if (lua_type(L, -1) == LUA_TSTRING) tr.note = lua_tostring(L, -1);
    lua_pop(L, 1);
    read_lines(L, "commands", tr.commands);
    get_field(L, -1, "confirm");
    if (lua_istable(L, -1)) read_lines(L, "commands", tr.on_yes);
    lua_pop(L, 1);
  }));
  if (!tr.error.empty()) tr.commands.clear();  // a rejected candidate is never issued
  return tr;
}

namespace {

// Runs fn(L) (which leaves one value) under pcall as one request (RequestCollection); the error
// becomes a Status.
template <class F>
Result<translate::Translation> protected_call(Vm& vm, F&& fn) {
  lua_State* L = vm.state();
  const int top = lua_gettop(L);
  struct Ctx { F* fn; } ctx{&fn};
  lua_pushcfunction(L, [](lua_State* S) -> int {
    auto* c = static_cast<Ctx*>(lua_touserdata(S, 1));
    lua_settop(S, 0);
    (*c->fn)(S);
    return 1;
  });
  lua_pushlightuserdata(L, &ctx);
  // (restarts the collector at return: after the result is read, no step before the reply)
  const RequestCollection request(vm);
  const Status st = vm.pcall(1, 1);
  if (!st.is_ok()) {
    lua_settop(L, top);
    return Status::internal("translation graph (scripts/translate/graph.lua): " + st.message());
  }
  auto tr = read_graph_result(L);
  lua_settop(L, top);
  return tr;
}

}  // namespace

// Leaves the translate.graph module on the stack (loaded once per state
// through the sandbox's require); raises the loading error.
void push_graph_module(lua_State* L) {
  lua_getfield(L, LUA_REGISTRYINDEX, "squawk.translate.graph");
  if (!lua_isnil(L, -1)) return;
  lua_pop(L, 1);
  lua_getglobal(L, "require");
  lua_pushstring(L, kTranslationGraphModule);
  lua_call(L, 1, 1);
  lua_pushvalue(L, -1);
  lua_setfield(L, LUA_REGISTRYINDEX, "squawk.translate.graph");
}

RequestCollection::RequestCollection(Vm& vm)
    : L_(vm.state()), restart_(lua_gc(L_, LUA_GCISRUNNING) == 1) {
  if (!restart_) return;  // (an enclosing request, or a script that stopped the collector)
  if (vm.collection_owed())
    lua_gc(L_, LUA_GCSTEP, 0);  // (the last request's, not taken after its reply)
  vm.set_collection_owed(true);
  lua_gc(L_, LUA_GCSTOP);
}

RequestCollection::~RequestCollection() {
  if (restart_) lua_gc(L_, LUA_GCRESTART);
}

ReplyCollection collect_after_reply(Vm& vm) {
  lua_State* L = vm.state();
  if (!vm.collection_owed()) return {};
  auto kb = [L] { return lua_gc(L, LUA_GCCOUNT) + lua_gc(L, LUA_GCCOUNTB) / 1024.0; };
  const double before = kb();
  const auto t0 = std::chrono::steady_clock::now();
  lua_gc(L, LUA_GCSTEP, 0);
  ReplyCollection r;
  r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  r.freed_kb = before - kb();
  vm.set_collection_owed(false);
  return r;
}

Result<translate::Translation> run_translation_graph(Vm& vm, const std::string& text, const GraphRequest& req) {
  return protected_call(vm, [&](lua_State* L) {
    push_graph_module(L);
    lua_getfield(L, -1, "translate");
    lua_pushstring(L, text.c_str());
    push_request(L, req);
    lua_call(L, 2, 1);
  });
}

Result<std::vector<rag::Document>> grammar_documents(Vm& vm) {
  lua_State* L = vm.state();
  const int top = lua_gettop(L);
  lua_getglobal(L, "require");
  lua_pushstring(L, "translate.grammar");
  if (Status st = vm.pcall(1, 1); !st.is_ok()) {
    lua_settop(L, top);
    return Status::internal("grammar (scripts/translate/grammar.lua): " + st.message());
  }
  std::vector<rag::Document> docs;
  Status read = catch_arg_errors(L, "grammar.documents: ", [&] { get_field(L, -1, "documents"); });
  if (read.is_ok())
    if (Status st = vm.pcall(0, 1); !st.is_ok())
      read = Status::invalid("grammar.documents(): " + st.message());
  if (read.is_ok())
    read = catch_arg_errors(L, "grammar.documents(): ", [&] {
      if (!lua_istable(L, -1)) throw ArgError("expected a list of {command=, text=}");
      const lua_Integer n = length(L, -1);
      for (lua_Integer i = 1; i <= n; ++i) {
        get_index(L, -1, i);
        get_field(L, -1, "command");
        get_field(L, -2, "text");
        if (lua_isstring(L, -2) && lua_isstring(L, -1))
          docs.push_back({lua_tostring(L, -2), lua_tostring(L, -1)});
        lua_pop(L, 3);
      }
    });
  lua_settop(L, top);
  if (!read.is_ok()) return Status::internal(read.message());
  return docs;
}

Result<GraphDialogue> GraphDialogue::open(Vm& vm, const GraphRequest& req) {
  int ref = LUA_NOREF;
  auto made = protected_call(vm, [&](lua_State* L) {
    push_graph_module(L);
    lua_getfield(L, -1, "dialogue");
    push_request(L, req);
    lua_call(L, 1, 1);
    lua_pushvalue(L, -1);
    ref = luaL_ref(L, LUA_REGISTRYINDEX);
    lua_newtable(L);  // a well-shaped result for protected_call
  });
  if (!made.is_ok()) return made.status();
  return GraphDialogue(vm, ref);
}

GraphDialogue::~GraphDialogue() {
  if (ref_ >= 0) luaL_unref(vm_->state(), LUA_REGISTRYINDEX, ref_);
}

Result<translate::Translation> GraphDialogue::say(const std::string& text) {
  return protected_call(*vm_, [&](lua_State* L) {
    lua_rawgeti(L, LUA_REGISTRYINDEX, ref_);
    lua_getfield(L, -1, "say");
    lua_insert(L, -2);
    lua_pushstring(L, text.c_str());
    lua_call(L, 2, 1);
  });
}
}  // namespace squawk::script
