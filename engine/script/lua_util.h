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
#include "script/vm.h"

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
  Vm& vm = Vm::of(L);
  {
    vm.enter_binding();
    try {
      const int n = Body(L);
      if (vm.leave_binding()) return n;
      std::strncpy(msg, vm.memory_message().c_str(), sizeof msg - 1);
    } catch (const std::exception& e) {
      vm.leave_binding();
      std::strncpy(msg, e.what(), sizeof msg - 1);
    } catch (...) {
      vm.leave_binding();
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
// Never raises: a __tostring that raises or returns a non-string is ignored.
int traceback_handler(lua_State* L);
// Message handler for lua_pcall: any error object becomes a string message,
// as traceback_handler, without the traceback.
int message_handler(lua_State* L);
// The error object at `idx` (left by a pcall with either handler above, or
// with none) as text: never null, whatever its type.
std::string error_text(lua_State* L, int idx);

// Protected reads of script values. Each runs the Lua operation inside
// lua_pcall with message_handler, so a metamethod (__index, __len,
// __tostring) that raises an error object of any type becomes an ArgError
// (a C++ exception: the callers' destructors run) instead of a longjmp across
// C++ frames or a panic outside any pcall. A table without a metatable is
// read directly. Same stack effect and result as the call they replace.
int get_field(lua_State* L, int idx, const char* key);  // lua_getfield
int get_index(lua_State* L, int idx, lua_Integer i);   // lua_geti
lua_Integer length(lua_State* L, int idx);              // luaL_len
bool equal(lua_State* L, int a, int b);                 // lua_compare(.., LUA_OPEQ): runs __eq
// luaL_tolstring: pushes the value's text and returns it.
const char* to_text(lua_State* L, int idx, size_t* len);

// Runs fn() outside any binding (C++ code reading a script's table); an
// exception (the ArgError of a protected read) becomes an error Status
// prefixed with `context`, and the stack is put back to its height at entry.
template <class F>
Status catch_arg_errors(lua_State* L, const std::string& context, F&& fn) {
  const int top = lua_gettop(L);
  try {
    fn();
    return Status::ok();
  } catch (const std::exception& e) {
    lua_settop(L, top);
    return Status::invalid(context + e.what());
  }
}

double arg_number(lua_State* L, int idx, const char* name);
double opt_number(lua_State* L, int idx, const char* name, double fallback);
long long arg_integer(lua_State* L, int idx, const char* name);
long long opt_integer(lua_State* L, int idx, const char* name, long long fallback);
std::string arg_string(lua_State* L, int idx, const char* name);
std::string opt_string(lua_State* L, int idx, const char* name, const std::string& fallback);
bool opt_boolean(lua_State* L, int idx, bool fallback);

// Set field `key` of the table on top of the stack.
void set_number(lua_State* L, const char* key, double v);
void set_integer(lua_State* L, const char* key, lua_Integer v);
void set_string(lua_State* L, const char* key, const std::string& v);
void set_boolean(lua_State* L, const char* key, bool v);

// Reads field `key` of the table at `idx`, or `fallback` when it is nil.
double field_number(lua_State* L, int idx, const char* key, double fallback);
std::string field_string(lua_State* L, int idx, const char* key, const std::string& fallback);
bool field_boolean(lua_State* L, int idx, const char* key, bool fallback);
// Field `key` as a number within [lo, hi] (NaN and values outside are
// ArgErrors naming the field and the range), or `fallback` when nil.
double field_in(lua_State* L, int idx, const char* key, double fallback, double lo, double hi);
// Field `key` as a whole number within [lo, hi] (NaN, fractions and values
// outside are ArgErrors naming the field and the range), or `fallback`.
long long field_count(lua_State* L, int idx, const char* key, long long fallback, long long lo,
                      long long hi);
// Argument `idx` likewise (`fallback` when none or nil).
long long opt_count(lua_State* L, int idx, const char* name, long long fallback, long long lo,
                    long long hi);

// Objects: a full userdata holds an ObjectBox<T> (a header, then the T) and
// has the metatable `mt` created by define_class. Safety contract:
// - the metatable is locked (__metatable), so scripts cannot reach __gc or
//   swap metatables;
// - every access checks the metatable and the header's type tag, so a method
//   or finalizer given another object's userdata is a clean error;
// - the finalizer destroys the T once and marks the box dead; a method on a
//   dead (finalized, then resurrected) object is a clean error;
// - a method that calls back into Lua holds a Pin on its object, and a
//   finalizer run meanwhile only marks it dead: the T dies with the last Pin.
struct ObjectHeader {
  const void* tag;                  // the class's metatable (lua_topointer)
  void (*destroy)(ObjectHeader*);   // runs ~T
  int pins = 0;                     // Pins held by running methods
  bool alive = true;
};

template <class T>
struct ObjectBox {
  ObjectHeader header;
  T value;
  template <class... A>
  explicit ObjectBox(const void* tag, A&&... a)
      : header{tag, &destroy_box}, value(std::forward<A>(a)...) {}
  static void destroy_box(ObjectHeader* h) { reinterpret_cast<ObjectBox*>(h)->~ObjectBox(); }
};

// The type tag of class `mt` (its metatable's address).
const void* class_tag(lua_State* L, const char* mt);
// The header of the object of class `mt` at `idx`, or nullptr when the value
// is not one (dead objects included: check ->alive).
ObjectHeader* test_header(lua_State* L, int idx, const char* mt);
// The live object's header, or ArgError naming the argument and the class.
ObjectHeader* arg_header(lua_State* L, int idx, const char* name, const char* mt);

template <class T, class... A>
T* new_object(lua_State* L, const char* mt, A&&... a) {
  const void* tag = class_tag(L, mt);
  void* p = lua_newuserdatauv(L, sizeof(ObjectBox<T>), 0);
  auto* box = new (p) ObjectBox<T>(tag, std::forward<A>(a)...);
  luaL_setmetatable(L, mt);
  return &box->value;
}

template <class T>
T* arg_object(lua_State* L, int idx, const char* mt, const char* name = "self") {
  return &reinterpret_cast<ObjectBox<T>*>(arg_header(L, idx, name, mt))->value;
}

// The live object of class `mt` at `idx`, or nullptr when the value is not
// one; ArgError when it is one that was finalized.
template <class T>
T* test_object(lua_State* L, int idx, const char* mt, const char* name) {
  ObjectHeader* h = test_header(L, idx, mt);
  if (!h) return nullptr;
  return arg_object<T>(L, idx, mt, name);
}

// Keeps the object at `idx` (a live object of any class) from being destroyed
// while a method runs Lua code; see ObjectHeader.
class Pin {
 public:
  Pin(lua_State* L, int idx);
  ~Pin();
  Pin(const Pin&) = delete;
  Pin& operator=(const Pin&) = delete;

 private:
  ObjectHeader* header_;
};

// __gc of every class: upvalue 1 is the metatable name.
int finalize_object(lua_State* L);

// Creates metatable `mt` with the given methods (also as __index), a locked
// __metatable and the checked finalizer. `methods` ends with {nullptr, nullptr}.
void define_class(lua_State* L, const char* mt, const luaL_Reg* methods);

// Returns `path` when the sandbox's read check lets scripts read it
// (Vm::rules, paths::PathRules::check_read) or it is "", else ArgError naming
// `what`, the path and --allow-read.
std::string readable(lua_State* L, const std::string& path, const char* what);
// As readable(), for a folder whose files a loader reads: the symbolic links
// inside it are checked too (paths::PathRules::check_read_folder).
std::string readable_folder(lua_State* L, const std::string& dir, const char* what);

// Charges `instructions` of work done in C to the running VM's budget
// (Vm::charge); ArgError when the budget is spent.
void charge(lua_State* L, long long instructions);

// Gets (creating if needed) the table squawk.<name> and leaves it on the stack.
void push_squawk_subtable(lua_State* L, const char* name);

}  // namespace squawk::script
