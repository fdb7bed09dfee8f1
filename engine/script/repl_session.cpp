#include "script/repl_session.h"

#include <lua.hpp>

#include "script/lua_util.h"
#include "script/translate_graph.h"

namespace squawk::script {

namespace {

constexpr const char* kSessionKey = "squawk.repl.session";  // registry slot
constexpr const char* kModule = "translate.repl";

}  // namespace

Status push_new_session(Vm& vm, const char* module, const std::string& scenario, const std::string& mode,
                        double clock) {
  lua_State* L = vm.state();
  const int top = lua_gettop(L);
  lua_getglobal(L, "require");
  lua_pushstring(L, module);
  SQUAWK_RETURN_IF_ERROR(vm.pcall(1, 1));
  // The module's fields are read like any script table's (protected).
  if (Status st = catch_arg_errors(L, std::string(module) + ".new: ", [&] { get_field(L, -1, "new"); });
      !st.is_ok()) {
    lua_settop(L, top);
    return st;
  }
  lua_createtable(L, 0, 4);
  if (!scenario.empty()) {
    lua_pushstring(L, scenario.c_str());
    lua_setfield(L, -2, "scenario");
  }
  if (!mode.empty()) {
    lua_pushstring(L, mode.c_str());
    lua_setfield(L, -2, "mode");
  }
  lua_pushinteger(L, static_cast<lua_Integer>(vm.options().seed));
  lua_setfield(L, -2, "seed");
  if (clock > 0) {
    lua_pushnumber(L, clock);
    lua_setfield(L, -2, "clock");
  }
  Status st = vm.pcall(1, 1);
  if (!st.is_ok()) {
    lua_settop(L, top);
    return st;
  }
  lua_remove(L, -2);  // the module
  return Status::ok();
}

Result<ReplSession> ReplSession::open(Vm& vm, const std::string& scenario, const std::string& mode,
                                      double clock) {
  lua_State* L = vm.state();
  const int top = lua_gettop(L);
  SQUAWK_RETURN_IF_ERROR(push_new_session(vm, kModule, scenario, mode, clock));
  lua_setfield(L, LUA_REGISTRYINDEX, kSessionKey);
  lua_settop(L, top);
  return ReplSession(vm);
}

Status ReplSession::call(const char* method, int nargs, int nresults) {
  lua_State* L = vm_->state();
  const int base = lua_gettop(L) - nargs;
  lua_getfield(L, LUA_REGISTRYINDEX, kSessionKey);
  const Status found = catch_arg_errors(L, std::string(kModule) + " session:" + method + ": ",
                                        [&] { get_field(L, -1, method); });
  if (!found.is_ok()) {
    lua_settop(L, base);
    return found;
  }
  lua_insert(L, -2);                  // method, session
  lua_rotate(L, -2 - nargs, 2);       // method, session, args...
  return vm_->pcall(nargs + 1, nresults);
}

Result<ReplReply> ReplSession::handle(const std::string& line) {
  lua_State* L = vm_->state();
  const int top = lua_gettop(L);
  lua_pushlstring(L, line.data(), line.size());
  SQUAWK_RETURN_IF_ERROR(call("handle", 1, 2));
  ReplReply r;
  size_t n = 0;
  const char* s = lua_tolstring(L, -2, &n);
  if (s) r.text.assign(s, n);
  r.quit = lua_toboolean(L, -1) != 0;
  lua_settop(L, top);
  return r;
}

void ReplSession::collect_after_reply() {
  (void)script::collect_after_reply(*vm_);
}

Result<std::string> ReplSession::text_of(const char* method) {
  lua_State* L = vm_->state();
  const int top = lua_gettop(L);
  SQUAWK_RETURN_IF_ERROR(call(method, 0, 1));
  std::string text = lua_tostring(L, -1) ? lua_tostring(L, -1) : "";
  lua_settop(L, top);
  return text;
}

Result<std::string> ReplSession::banner() { return text_of("banner"); }

Result<std::string> ReplSession::opening() { return text_of("opening"); }

Result<std::string> ReplSession::tick(double wall_s) {
  lua_State* L = vm_->state();
  const int top = lua_gettop(L);
  lua_pushnumber(L, wall_s);
  SQUAWK_RETURN_IF_ERROR(call("tick", 1, 1));
  std::string text = lua_tostring(L, -1) ? lua_tostring(L, -1) : "";
  lua_settop(L, top);
  return text;
}

Result<std::vector<std::string>> ReplSession::complete(const std::string& prefix) {
  lua_State* L = vm_->state();
  const int top = lua_gettop(L);
  lua_pushlstring(L, prefix.data(), prefix.size());
  SQUAWK_RETURN_IF_ERROR(call("complete", 1, 1));
  std::vector<std::string> words;
  const Status read = catch_arg_errors(L, std::string(kModule) + " session:complete(): ", [&] {
    if (!lua_istable(L, -1)) return;
    const lua_Integer n = length(L, -1);
    for (lua_Integer k = 1; k <= n; ++k) {
      get_index(L, -1, k);
      if (const char* w = lua_tostring(L, -1)) words.emplace_back(w);
      lua_pop(L, 1);
    }
  });
  lua_settop(L, top);
  if (!read.is_ok()) return read;
  return words;
}

}  // namespace squawk::script
