#include "script/lua_util.h"

#include <cmath>
#include <cstdio>

#include "core/text.h"
#include "script/vm.h"

namespace squawk::script {

namespace {

// The key under which table `t` holds the value at the stack top, or "".
std::string key_of(lua_State* L, int t) {
  t = lua_absindex(L, t);
  const int fn = lua_gettop(L);
  lua_pushnil(L);
  while (lua_next(L, t)) {
    if (lua_rawequal(L, -1, fn) && lua_type(L, -2) == LUA_TSTRING) {
      std::string k = lua_tostring(L, -2);
      lua_pop(L, 2);
      return k;
    }
    lua_pop(L, 1);
  }
  return "";
}

// The name of the running C function as scripts know it: squawk.sim.new, or
// Class:method for methods; "?" when it is neither.
std::string running_function(lua_State* L) {
  lua_Debug ar;
  if (!lua_getstack(L, 0, &ar) || !lua_getinfo(L, "f", &ar)) return "?";
  const int fn = lua_gettop(L);
  std::string found;
  lua_getglobal(L, "squawk");
  if (lua_istable(L, -1)) {
    lua_pushnil(L);
    while (found.empty() && lua_next(L, -2)) {
      if (lua_istable(L, -1) && lua_type(L, -2) == LUA_TSTRING) {
        lua_pushvalue(L, fn);
        const std::string k = key_of(L, -2);
        lua_pop(L, 1);
        if (!k.empty()) found = std::string("squawk.") + lua_tostring(L, -2) + "." + k;
      }
      lua_pop(L, 1);
    }
    if (!found.empty()) lua_pop(L, 1);  // the key lua_next left
  }
  lua_pop(L, 1);
  lua_pushnil(L);  // methods: the __index tables of the squawk.* metatables
  while (found.empty() && lua_next(L, LUA_REGISTRYINDEX)) {  // key, metatable
    if (lua_type(L, -2) == LUA_TSTRING && std::strncmp(lua_tostring(L, -2), "squawk.", 7) == 0 &&
        lua_istable(L, -1)) {
      if (lua_getfield(L, -1, "__index") == LUA_TTABLE) {  // key, metatable, methods
        lua_pushvalue(L, fn);
        const std::string k = key_of(L, -2);
        lua_pop(L, 1);
        if (!k.empty()) found = std::string(lua_tostring(L, -3)) + ":" + k;
      }
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
  }
  if (!found.empty()) lua_pop(L, 1);
  lua_settop(L, fn - 1);
  return found.empty() ? "?" : found;
}

}  // namespace

std::string type_error(lua_State* L, int idx, const char* name, const char* expected) {
  lua_Debug ar;
  std::string fn;
  if (lua_getstack(L, 0, &ar) && lua_getinfo(L, "n", &ar) && ar.name) fn = ar.name;
  if (fn.empty() || fn == "?") fn = running_function(L);
  return "bad argument #" + std::to_string(idx) + " '" + name + "' to '" + fn + "': expected " +
         expected + ", got " + luaL_typename(L, idx);
}

namespace {

// The text of the error object at index 1 (pushed), never raising.
const char* push_error_text(lua_State* L) {
  if (const char* msg = lua_tostring(L, 1)) return msg;
  if (luaL_getmetafield(L, 1, "__tostring") != LUA_TNIL) {  // raw read: no __index involved
    lua_pushvalue(L, 1);
    if (lua_pcall(L, 1, 1, 0) == LUA_OK && lua_type(L, -1) == LUA_TSTRING) return lua_tostring(L, -1);
    lua_pop(L, 1);
  }
  return lua_pushfstring(L, "(error object is a %s value)", luaL_typename(L, 1));
}

int getfield_op(lua_State* L) {  // (t, k) -> t[k]
  lua_gettable(L, 1);
  return 1;
}

int len_op(lua_State* L) {  // (v) -> #v as an integer
  lua_pushinteger(L, luaL_len(L, 1));
  return 1;
}

int eq_op(lua_State* L) {  // (a, b) -> a == b
  lua_pushboolean(L, lua_compare(L, 1, 2, LUA_OPEQ));
  return 1;
}

int tolstring_op(lua_State* L) {  // (v) -> tostring(v)
  luaL_tolstring(L, 1, nullptr);
  return 1;
}

// True when the value at idx is a table without a metatable: reads of it
// run no metamethod.
bool plain_table(lua_State* L, int idx) {
  if (lua_type(L, idx) != LUA_TTABLE) return false;
  if (!lua_getmetatable(L, idx)) return true;
  lua_pop(L, 1);
  return false;
}

// Calls `op` on the value at idx (and `key` when given, pushed by the caller
// as the value on top) under lua_pcall + message_handler; leaves one result.
void protected_op(lua_State* L, lua_CFunction op, int idx, bool with_key, const std::string& what) {
  idx = lua_absindex(L, idx);
  const int key = with_key ? lua_gettop(L) : 0;
  lua_pushcfunction(L, message_handler);
  const int handler = lua_gettop(L);
  lua_pushcfunction(L, op);
  lua_pushvalue(L, idx);
  if (with_key) lua_pushvalue(L, key);
  if (lua_pcall(L, with_key ? 2 : 1, 1, handler) != LUA_OK) {
    std::string msg = error_text(L, -1);
    lua_settop(L, with_key ? key - 1 : handler - 1);
    throw ArgError(what + ": " + msg);
  }
  lua_remove(L, handler);
  if (with_key) lua_remove(L, key);
}

}  // namespace

int traceback_handler(lua_State* L) {
  luaL_traceback(L, L, push_error_text(L), 1);
  return 1;
}

int message_handler(lua_State* L) {
  push_error_text(L);
  return 1;
}

std::string error_text(lua_State* L, int idx) {
  if (const char* s = lua_tostring(L, idx)) return s;
  return std::string("(error object is a ") + luaL_typename(L, idx) + " value)";
}

int get_field(lua_State* L, int idx, const char* key) {
  if (plain_table(L, idx)) return lua_getfield(L, idx, key);
  idx = lua_absindex(L, idx);
  lua_pushstring(L, key);
  protected_op(L, getfield_op, idx, true, std::string("reading field '") + key + "'");
  return lua_type(L, -1);
}

int get_index(lua_State* L, int idx, lua_Integer i) {
  if (plain_table(L, idx)) return lua_geti(L, idx, i);
  idx = lua_absindex(L, idx);
  lua_pushinteger(L, i);
  protected_op(L, getfield_op, idx, true, "reading entry " + std::to_string(i));
  return lua_type(L, -1);
}

lua_Integer length(lua_State* L, int idx) {
  if (plain_table(L, idx)) return static_cast<lua_Integer>(lua_rawlen(L, idx));
  protected_op(L, len_op, idx, false, "reading the length");
  const lua_Integer n = lua_tointeger(L, -1);
  lua_pop(L, 1);
  return n;
}

bool equal(lua_State* L, int a, int b) {
  if (lua_isnone(L, a) || lua_isnone(L, b)) return false;  // as lua_compare
  if (lua_rawequal(L, a, b)) return true;                   // Lua runs no __eq then either
  a = lua_absindex(L, a);
  lua_pushvalue(L, b);
  protected_op(L, eq_op, a, true, "comparing with ==");
  const bool eq = lua_toboolean(L, -1) != 0;
  lua_pop(L, 1);
  return eq;
}

const char* to_text(lua_State* L, int idx, size_t* len) {
  protected_op(L, tolstring_op, idx, false, "converting to text");
  return lua_tolstring(L, -1, len);
}

double arg_number(lua_State* L, int idx, const char* name) {
  int ok = 0;
  double v = lua_tonumberx(L, idx, &ok);
  if (!ok) throw ArgError(type_error(L, idx, name, "number"));
  return v;
}

double opt_number(lua_State* L, int idx, const char* name, double fallback) {
  return lua_isnoneornil(L, idx) ? fallback : arg_number(L, idx, name);
}

long long arg_integer(lua_State* L, int idx, const char* name) {
  int ok = 0;
  lua_Integer v = lua_tointegerx(L, idx, &ok);
  if (!ok) throw ArgError(type_error(L, idx, name, "integer"));
  return v;
}

long long opt_integer(lua_State* L, int idx, const char* name, long long fallback) {
  return lua_isnoneornil(L, idx) ? fallback : arg_integer(L, idx, name);
}

std::string arg_string(lua_State* L, int idx, const char* name) {
  if (lua_type(L, idx) != LUA_TSTRING && lua_type(L, idx) != LUA_TNUMBER)
    throw ArgError(type_error(L, idx, name, "string"));
  size_t n = 0;
  const char* s = lua_tolstring(L, idx, &n);
  return std::string(s, n);
}

std::string opt_string(lua_State* L, int idx, const char* name, const std::string& fallback) {
  return lua_isnoneornil(L, idx) ? fallback : arg_string(L, idx, name);
}

bool opt_boolean(lua_State* L, int idx, bool fallback) {
  return lua_isnoneornil(L, idx) ? fallback : lua_toboolean(L, idx) != 0;
}

void set_number(lua_State* L, const char* key, double v) {
  lua_pushnumber(L, v);
  lua_setfield(L, -2, key);
}

void set_integer(lua_State* L, const char* key, lua_Integer v) {
  lua_pushinteger(L, v);
  lua_setfield(L, -2, key);
}

void set_string(lua_State* L, const char* key, const std::string& v) {
  lua_pushlstring(L, v.data(), v.size());
  lua_setfield(L, -2, key);
}

void set_boolean(lua_State* L, const char* key, bool v) {
  lua_pushboolean(L, v);
  lua_setfield(L, -2, key);
}

double field_number(lua_State* L, int idx, const char* key, double fallback) {
  idx = lua_absindex(L, idx);
  get_field(L, idx, key);
  double v = fallback;
  if (!lua_isnil(L, -1)) {
    int ok = 0;
    v = lua_tonumberx(L, -1, &ok);
    if (!ok) {
      std::string t = luaL_typename(L, -1);
      lua_pop(L, 1);
      throw ArgError(std::string("field '") + key + "': expected number, got " + t);
    }
  }
  lua_pop(L, 1);
  return v;
}

std::string field_string(lua_State* L, int idx, const char* key, const std::string& fallback) {
  idx = lua_absindex(L, idx);
  get_field(L, idx, key);
  std::string v = fallback;
  if (!lua_isnil(L, -1)) {
    if (lua_type(L, -1) != LUA_TSTRING && lua_type(L, -1) != LUA_TNUMBER) {
      std::string t = luaL_typename(L, -1);
      lua_pop(L, 1);
      throw ArgError(std::string("field '") + key + "': expected string, got " + t);
    }
    size_t n = 0;
    const char* s = lua_tolstring(L, -1, &n);
    v.assign(s, n);
  }
  lua_pop(L, 1);
  return v;
}

bool field_boolean(lua_State* L, int idx, const char* key, bool fallback) {
  idx = lua_absindex(L, idx);
  get_field(L, idx, key);
  bool v = lua_isnil(L, -1) ? fallback : lua_toboolean(L, -1) != 0;
  lua_pop(L, 1);
  return v;
}

const void* class_tag(lua_State* L, const char* mt) {
  luaL_getmetatable(L, mt);
  const void* tag = lua_topointer(L, -1);
  lua_pop(L, 1);
  return tag;
}

ObjectHeader* test_header(lua_State* L, int idx, const char* mt) {
  void* p = luaL_testudata(L, idx, mt);
  if (!p || lua_rawlen(L, idx) < sizeof(ObjectHeader)) return nullptr;
  auto* h = static_cast<ObjectHeader*>(p);
  return h->tag == class_tag(L, mt) ? h : nullptr;
}

ObjectHeader* arg_header(lua_State* L, int idx, const char* name, const char* mt) {
  ObjectHeader* h = test_header(L, idx, mt);
  if (!h) throw ArgError(type_error(L, idx, name, mt));
  if (!h->alive)
    throw ArgError(type_error(L, idx, name, (std::string("a live ") + mt).c_str()) +
                   " already finalized (its __gc ran)");
  return h;
}

Pin::Pin(lua_State* L, int idx) : header_(static_cast<ObjectHeader*>(lua_touserdata(L, idx))) {
  ++header_->pins;
}

Pin::~Pin() {
  if (--header_->pins == 0 && !header_->alive) header_->destroy(header_);
}

int finalize_object(lua_State* L) {
  ObjectHeader* h = test_header(L, 1, lua_tostring(L, lua_upvalueindex(1)));
  if (!h || !h->alive) return 0;  // not ours, or finalized already
  h->alive = false;
  if (h->pins == 0) h->destroy(h);
  return 0;
}

void define_class(lua_State* L, const char* mt, const luaL_Reg* methods) {
  luaL_newmetatable(L, mt);
  lua_newtable(L);
  luaL_setfuncs(L, methods, 0);
  lua_setfield(L, -2, "__index");
  lua_pushstring(L, mt);
  lua_setfield(L, -2, "__metatable");
  lua_pushstring(L, mt);
  lua_pushcclosure(L, finalize_object, 1);
  lua_setfield(L, -2, "__gc");
  lua_pop(L, 1);
}

namespace {

// A number as messages show it: 1e+308, NaN, 2.5.
std::string shown(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return std::isnan(v) ? "NaN" : buf;
}

long long checked_count(double v, const std::string& what, long long lo, long long hi) {
  if (!(v >= static_cast<double>(lo) && v <= static_cast<double>(hi)) || v != std::floor(v))
    throw ArgError(what + ": expected a whole number in [" + std::to_string(lo) + ", " +
                   std::to_string(hi) + "], got " + shown(v));
  return static_cast<long long>(v);
}

}  // namespace

double field_in(lua_State* L, int idx, const char* key, double fallback, double lo, double hi) {
  const double v = field_number(L, idx, key, fallback);
  if (!(v >= lo && v <= hi))
    throw ArgError(std::string("field '") + key + "': expected a number in [" + text::fmt_double(lo) + ", " +
                   text::fmt_double(hi) + "], got " + shown(v));
  return v;
}

long long field_count(lua_State* L, int idx, const char* key, long long fallback, long long lo,
                      long long hi) {
  idx = lua_absindex(L, idx);
  get_field(L, idx, key);
  const bool absent = lua_isnil(L, -1);
  lua_pop(L, 1);
  if (absent) return fallback;
  return checked_count(field_number(L, idx, key, 0), std::string("field '") + key + "'", lo, hi);
}

long long opt_count(lua_State* L, int idx, const char* name, long long fallback, long long lo,
                    long long hi) {
  if (lua_isnoneornil(L, idx)) return fallback;
  return checked_count(arg_number(L, idx, name), std::string("argument '") + name + "'", lo, hi);
}

std::string readable(lua_State* L, const std::string& path, const char* what) {
  if (!path.empty()) check_status(Vm::of(L).rules().check_read(path, what));
  return path;
}

std::string readable_folder(lua_State* L, const std::string& dir, const char* what) {
  if (!dir.empty()) check_status(Vm::of(L).rules().check_read_folder(dir, what));
  return dir;
}

void charge(lua_State* L, long long instructions) { check_status(Vm::of(L).charge(instructions)); }

void push_squawk_subtable(lua_State* L, const char* name) {
  lua_getglobal(L, "squawk");
  if (!lua_istable(L, -1)) {
    lua_pop(L, 1);
    lua_newtable(L);
    lua_pushvalue(L, -1);
    lua_setglobal(L, "squawk");
  }
  if (lua_getfield(L, -1, name) != LUA_TTABLE) {
    lua_pop(L, 1);
    lua_newtable(L);
    lua_pushvalue(L, -1);
    lua_setfield(L, -3, name);
  }
  lua_remove(L, -2);
}

}  // namespace squawk::script
