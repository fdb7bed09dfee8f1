// Helpers for binding code (engine/script/bind_*.cpp only).
//
// Rule: a binding body never lets a C++ exception or a longjmp cross live C++
// objects. Bodies are plain functions `int body(lua_State*)` that read their
// arguments with the arg_* helpers below (which throw ArgError), and are
// registered through guarded<body>, which converts any exception into a Lua
// error after every C++ object of the body is destroyed.
#pragma once

#include <cstring>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <lua.hpp>

#include "core/status.h"

namespace squawk::script {

struct ArgError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws ArgError when `st` is not ok (its message becomes the Lua error).
inline void check_status(const Status& st) {
  if (!st.is_ok()) throw ArgError(st.message());
}

template <int (*Body)(lua_State*)>
int guarded(lua_State* L) {
  char msg[2048];
  {
    try {
      return Body(L);
    } catch (const std::exception& e) {
      std::strncpy(msg, e.what(), sizeof msg - 1);
    } catch (...) {
      std::strncpy(msg, "unknown C++ exception", sizeof msg - 1);
    }
  }
  msg[sizeof msg - 1] = '\0';
  luaL_where(L, 1);
  lua_pushstring(L, msg);
  lua_concat(L, 2);
  return lua_error(L);
}

std::string type_error(lua_State* L, int idx, const char* name, const char* expected);

// Message handler for lua_pcall: the error message plus a traceback (a
// non-string error object is described by its __tostring or its type).
int traceback_handler(lua_State* L);

double arg_number(lua_State* L, int idx, const char* name);
double opt_number(lua_State* L, int idx, const char* name, double fallback);
long long arg_integer(lua_State* L, int idx, const char* name);
long long opt_integer(lua_State* L, int idx, const char* name, long long fallback);
std::string arg_string(lua_State* L, int idx, const char* name);
std::string opt_string(lua_State* L, int idx, const char* name, const std::string& fallback);
bool opt_boolean(lua_State* L, int idx, bool fallback);

// Pushes a Lua array (1-based) of the numbers in v.
void push_array(lua_State* L, const std::vector<double>& v);

// Reads field `key` of the table at `idx`, or `fallback` when it is nil.
double field_number(lua_State* L, int idx, const char* key, double fallback);
std::string field_string(lua_State* L, int idx, const char* key, const std::string& fallback);
bool field_boolean(lua_State* L, int idx, const char* key, bool fallback);

// Full userdata holding a T, with metatable `mt` (created by define_class).
template <class T, class... A>
T* new_object(lua_State* L, const char* mt, A&&... a) {
  void* p = lua_newuserdatauv(L, sizeof(T), 0);
  T* t = new (p) T(std::forward<A>(a)...);
  luaL_setmetatable(L, mt);
  return t;
}

template <class T>
T* arg_object(lua_State* L, int idx, const char* mt) {
  void* p = luaL_testudata(L, idx, mt);
  if (!p) throw ArgError(type_error(L, idx, "self", mt));
  return static_cast<T*>(p);
}

template <class T>
int destroy_object(lua_State* L) {
  if (void* p = lua_touserdata(L, 1)) static_cast<T*>(p)->~T();
  return 0;
}

// Creates metatable `mt` with the given methods (also as __index) and a __gc
// that runs ~T. `methods` ends with {nullptr, nullptr}.
template <class T>
void define_class(lua_State* L, const char* mt, const luaL_Reg* methods) {
  luaL_newmetatable(L, mt);
  lua_newtable(L);
  luaL_setfuncs(L, methods, 0);
  lua_setfield(L, -2, "__index");
  lua_pushcfunction(L, destroy_object<T>);
  lua_setfield(L, -2, "__gc");
  lua_pop(L, 1);
}

// Gets (creating if needed) the table squawk.<name> and leaves it on the stack.
void push_squawk_subtable(lua_State* L, const char* name);

}  // namespace squawk::script
