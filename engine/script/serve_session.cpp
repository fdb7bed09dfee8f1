#include "script/serve_session.h"

#include <lua.hpp>

#include "script/lua_util.h"
#include "script/repl_session.h"
#include "script/translate_graph.h"

namespace squawk::script {

namespace {

constexpr const char* kSessionKey = "squawk.serve.session";  // registry slot
constexpr const char* kModule = "translate.session";
constexpr const char* kSimMetatable = "squawk.sim.Sim";  // bind_sim.cpp's class

// The readers below go through the protected accessors (lua_util.h): call
// them under catch_arg_errors.
std::string string_field(lua_State* L, int idx, const char* key) {
  get_field(L, idx, key);
  size_t n = 0;
  const char* s = lua_type(L, -1) == LUA_TSTRING ? lua_tolstring(L, -1, &n) : nullptr;
  std::string out = s ? std::string(s, n) : std::string();
  lua_pop(L, 1);
  return out;
}

bool bool_field(lua_State* L, int idx, const char* key) {
  get_field(L, idx, key);
  const bool b = lua_toboolean(L, -1) != 0;
  lua_pop(L, 1);
  return b;
}

// The events array at `idx` (absent: none).
std::vector<SessionEvent> events_at(lua_State* L, int idx) {
  std::vector<SessionEvent> out;
  if (!lua_istable(L, idx)) return out;
  const lua_Integer n = length(L, idx);
  for (lua_Integer k = 1; k <= n; ++k) {
    get_index(L, idx, k);
    const int e = lua_gettop(L);
    if (lua_istable(L, e)) {
      get_field(L, e, "t");
      const double t = lua_tonumber(L, -1);
      lua_pop(L, 1);
      out.push_back({t, string_field(L, e, "kind"), string_field(L, e, "text")});
    }
    lua_pop(L, 1);
  }
  return out;
}

// graph.format_trace(trace) for the trace table at `idx` ("" when absent).
Result<std::string> format_trace(lua_State* L, int idx) {
  if (!lua_istable(L, idx)) return std::string();
  lua_getglobal(L, "require");
  lua_pushstring(L, "translate.graph");
  SQUAWK_RETURN_IF_ERROR(Vm::of(L).pcall(1, 1));
  SQUAWK_RETURN_IF_ERROR(catch_arg_errors(L, "translate.graph.format_trace: ", [&] { get_field(L, -1, "format_trace"); }));
  lua_remove(L, -2);
  lua_pushvalue(L, idx);
  SQUAWK_RETURN_IF_ERROR(Vm::of(L).pcall(1, 1));
  std::string out = lua_tostring(L, -1) ? lua_tostring(L, -1) : "";
  lua_pop(L, 1);
  return out;
}

}  // namespace

Result<std::unique_ptr<ServeSession>> ServeSession::open(Vm& vm, const std::string& scenario,
                                                         const std::string& mode) {
  lua_State* L = vm.state();
  const int top = lua_gettop(L);
  SQUAWK_RETURN_IF_ERROR(push_new_session(vm, kModule, scenario, mode));
  if (Status st = catch_arg_errors(L, std::string(kModule) + " session.sim: ", [&] { get_field(L, -1, "sim"); });
      !st.is_ok()) {
    lua_settop(L, top);
    return st;
  }
  ObjectHeader* h = test_header(L, -1, kSimMetatable);
  command::Stack* stack = h && h->alive ? &reinterpret_cast<ObjectBox<command::Stack>*>(h)->value : nullptr;
  lua_pop(L, 1);
  if (!stack) {
    lua_settop(L, top);
    return Status::internal(std::string(kModule) + ": session.sim is not a squawk.sim");
  }
  lua_setfield(L, LUA_REGISTRYINDEX, kSessionKey);
  lua_settop(L, top);
  return std::unique_ptr<ServeSession>(new ServeSession(vm, stack));
}

ServeSession::~ServeSession() {
  lua_State* L = vm_->state();
  lua_pushnil(L);
  lua_setfield(L, LUA_REGISTRYINDEX, kSessionKey);
}

Status ServeSession::push_method(const char* method) {
  lua_State* L = vm_->state();
  const int top = lua_gettop(L);
  lua_getfield(L, LUA_REGISTRYINDEX, kSessionKey);
  const Status found = catch_arg_errors(L, std::string(kModule) + " session:" + method + ": ",
                                        [&] { get_field(L, -1, method); });
  if (!found.is_ok()) {
    lua_settop(L, top);
    return found;
  }
  lua_insert(L, -2);  // method, session
  return Status::ok();
}

Result<CommandReply> ServeSession::command(const std::string& text, const CommandOptions& opts) {
  lua_State* L = vm_->state();
  const int top = lua_gettop(L);
  SQUAWK_RETURN_IF_ERROR(push_method("command"));
  lua_pushlstring(L, text.data(), text.size());
  lua_createtable(L, 0, 2);
  if (!opts.client.empty()) {
    lua_pushlstring(L, opts.client.data(), opts.client.size());
    lua_setfield(L, -2, "client");
  }
  if (!opts.selected.empty()) {
    lua_pushlstring(L, opts.selected.data(), opts.selected.size());
    lua_setfield(L, -2, "selected");
  }
  Status st = Vm::of(L).pcall(3, 1);
  if (st.is_ok() && !lua_istable(L, -1)) st = Status::internal(std::string(kModule) + ": command() returned no table");
  if (!st.is_ok()) {
    lua_settop(L, top);
    return st;
  }
  const int r = lua_gettop(L);
  CommandReply out;
  const Status read = catch_arg_errors(L, std::string(kModule) + " command()'s reply: ", [&] {
    out.text = string_field(L, r, "text");
    out.ask = string_field(L, r, "ask");
    out.cancelled = bool_field(L, r, "cancelled");
    out.addressed = string_field(L, r, "addressed");
    const std::string error = string_field(L, r, "error");
    get_field(L, r, "commands");
    if (lua_istable(L, -1)) {
      const lua_Integer n = length(L, -1);
      for (lua_Integer k = 1; k <= n; ++k) {
        get_index(L, -1, k);
        if (const char* s = lua_tostring(L, -1)) out.commands.emplace_back(s);
        lua_pop(L, 1);
      }
    }
    lua_pop(L, 1);
    // One result per command run; the first failure stops the rest.
    out.ok = out.ask.empty() && error.empty();
    get_field(L, r, "results");
    if (lua_istable(L, -1)) {
      const int res = lua_gettop(L);
      const lua_Integer n = length(L, res);
      for (lua_Integer k = 1; k <= n; ++k) {
        get_index(L, res, k);
        const bool ok = lua_istable(L, -1) && bool_field(L, -1, "ok");
        const std::string msg = lua_istable(L, -1) ? string_field(L, -1, "message") : std::string();
        lua_pop(L, 1);
        if (!ok) {
          out.ok = false;
          out.message = msg;
          break;
        }
        if (!msg.empty()) out.message += (out.message.empty() ? "" : "\n") + msg;
      }
    }
    lua_pop(L, 1);
    if (!error.empty()) out.message = "could not translate: " + error;
    // "cancel": what was dropped, or that nothing was pending.
    const std::string cancel_note = string_field(L, r, "cancel_note");
    if (!cancel_note.empty()) out.message = cancel_note;
    if (out.ok && out.commands.empty() && cancel_note.empty()) {
      out.ok = false;
      out.message = "nothing to run";
    }
    const std::string clock = string_field(L, r, "clock");
    if (!clock.empty()) out.message += (out.message.empty() ? "" : "\n") + clock;
    get_field(L, r, "events");
    out.events = events_at(L, lua_gettop(L));
    lua_pop(L, 1);
  });
  if (!read.is_ok()) {
    lua_settop(L, top);
    return read;
  }
  Result<std::string> trace = std::string();
  const Status read_trace = catch_arg_errors(L, std::string(kModule) + " command()'s reply: ", [&] {
    get_field(L, r, "trace");
    trace = format_trace(L, lua_gettop(L));
  });
  lua_settop(L, top);
  SQUAWK_RETURN_IF_ERROR(read_trace);
  if (!trace) return trace.status();
  out.trace = *trace;
  return out;
}

void ServeSession::collect_after_reply() {
  (void)script::collect_after_reply(*vm_);
}

Result<std::vector<SessionEvent>> ServeSession::tick(double wall_s) {
  lua_State* L = vm_->state();
  const int top = lua_gettop(L);
  SQUAWK_RETURN_IF_ERROR(push_method("tick"));
  lua_pushnumber(L, wall_s);
  Status st = Vm::of(L).pcall(2, 1);
  if (!st.is_ok()) {
    lua_settop(L, top);
    return st;
  }
  std::vector<SessionEvent> events;
  const Status read = catch_arg_errors(L, std::string(kModule) + " tick()'s events: ",
                                       [&] { events = events_at(L, lua_gettop(L)); });
  lua_settop(L, top);
  if (!read.is_ok()) return read;
  return events;
}

}  // namespace squawk::script
