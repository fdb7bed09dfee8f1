// squawk.* basics, the assertion API and the engine-seeded math.random.
#include <cmath>
#include <cstdio>
#include <string>

#include "core/paths.h"
#include "core/text.h"
#include "script/bindings.h"
#include "script/lua_util.h"
#include "script/vm.h"

namespace squawk::script {

namespace {

// "file:line" of the Lua code that called the current C function.
std::string caller_where(lua_State* L) {
  lua_Debug ar;
  if (lua_getstack(L, 1, &ar) && lua_getinfo(L, "Sl", &ar) && ar.currentline > 0)
    return std::string(ar.short_src) + ":" + std::to_string(ar.currentline);
  return "?";
}

std::string show(lua_State* L, int idx) {
  if (lua_type(L, idx) == LUA_TNUMBER && !lua_isinteger(L, idx))
    return text::fmt_exact(lua_tonumber(L, idx));
  if (lua_type(L, idx) == LUA_TSTRING) {
    std::string r(1, '"');
    r.append(lua_tostring(L, idx)).append(1, '"');
    return r;
  }
  size_t n = 0;
  const char* s = to_text(L, idx, &n);
  std::string r(s, n);
  lua_pop(L, 1);
  return r;
}

void report(lua_State* L, bool ok, const std::string& what, int msg_idx) {
  CheckCounts& c = Vm::of(L).checks();
  if (ok) {
    ++c.passed;
    return;
  }
  ++c.failed;
  std::string msg = caller_where(L) + ": check failed: " + what;
  if (lua_type(L, msg_idx) == LUA_TSTRING) msg += " (" + std::string(lua_tostring(L, msg_idx)) + ")";
  std::fprintf(stdout, "%s\n", msg.c_str());
  std::fflush(stdout);
}

int l_check(lua_State* L) {
  report(L, lua_toboolean(L, 1) != 0, "condition is " + show(L, 1), 2);
  lua_pushboolean(L, lua_toboolean(L, 1));
  return 1;
}

int l_check_eq(lua_State* L) {
  const bool ok = equal(L, 1, 2);
  report(L, ok, "got " + show(L, 1) + ", want " + show(L, 2), 3);
  lua_pushboolean(L, ok);
  return 1;
}

int l_check_near(lua_State* L) {
  const double got = arg_number(L, 1, "got");
  const double want = arg_number(L, 2, "want");
  const double tol = arg_number(L, 3, "tolerance");
  const bool ok = std::fabs(got - want) <= tol;
  char buf[160];
  std::snprintf(buf, sizeof buf, "got %.17g, want %.17g within %g (off by %.3g)", got, want, tol,
                got - want);
  report(L, ok, buf, 4);
  lua_pushboolean(L, ok);
  return 1;
}

// math.random([m [, n]]) with Lua's semantics, drawn from the engine Rng.
int l_random(lua_State* L) {
  Rng& rng = Vm::of(L).rng();
  const int n = lua_gettop(L);
  if (n == 0) {
    lua_pushnumber(L, rng.uniform());
    return 1;
  }
  long long lo = 1, hi = 0;
  if (n == 1) {
    hi = arg_integer(L, 1, "m");
  } else {
    lo = arg_integer(L, 1, "m");
    hi = arg_integer(L, 2, "n");
  }
  if (lo > hi) throw ArgError("math.random: interval is empty");
  lua_pushinteger(L, rng.uniform_int(lo, hi));
  return 1;
}

int l_randomseed(lua_State* L) {
  Vm::of(L).rng().reseed(static_cast<uint64_t>(arg_integer(L, 1, "seed")));
  return 0;
}

}  // namespace

void bind_core(lua_State* L) {
  const Vm& vm = Vm::of(L);
  push_squawk_subtable(L, "sim");  // ensures `squawk` exists
  lua_pop(L, 1);
  lua_getglobal(L, "squawk");
  lua_pushstring(L, SQUAWK_VERSION);
  lua_setfield(L, -2, "version");
  lua_pushstring(L, paths::home().c_str());
  lua_setfield(L, -2, "home");
  lua_pushinteger(L, static_cast<lua_Integer>(vm.options().seed));
  lua_setfield(L, -2, "seed");
  if (!vm.options().out_dir.empty()) {
    lua_pushstring(L, vm.options().out_dir.c_str());
    lua_setfield(L, -2, "out_dir");
  }
  if (!vm.options().navdata_dir.empty()) {
    lua_pushstring(L, vm.options().navdata_dir.c_str());
    lua_setfield(L, -2, "navdata_dir");
  }
  lua_pop(L, 1);

  lua_register(L, "check", guarded<l_check>);
  lua_register(L, "check_eq", guarded<l_check_eq>);
  lua_register(L, "check_near", guarded<l_check_near>);

  lua_getglobal(L, "math");
  lua_pushcfunction(L, guarded<l_random>);
  lua_setfield(L, -2, "random");
  lua_pushcfunction(L, guarded<l_randomseed>);
  lua_setfield(L, -2, "randomseed");
  lua_pop(L, 1);
}

}  // namespace squawk::script
