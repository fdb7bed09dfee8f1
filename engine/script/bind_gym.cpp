// squawk.gym: environments written as Lua files (envs/*.lua; the contract in
// script/lua_env.h and docs/gym_envs.md), from Lua.
//
//   squawk.gym.load(path) -> env    the table the file returns (readable paths
//                                    only), used as env:reset(seed [, options]),
//                                    env:step({a1, ...}); no TimeLimit is added.
//                                    The file's folder joins the require path.
#include <string>

#include "core/paths.h"
#include "script/bindings.h"
#include "script/lua_util.h"

namespace squawk::script {

namespace {

int l_load(lua_State* L) {
  const std::string path = readable(L, arg_string(L, 1, "path"), "environment");
  Vm::of(L).add_script_folder(paths::dirname(path));  // the file may require its neighbours
  lua_settop(L, 0);
  lua_pushcfunction(L, traceback_handler);
  if (luaL_loadfilex(L, path.c_str(), "t") != LUA_OK) throw ArgError(error_text(L, -1));
  if (lua_pcall(L, 0, 1, 1) != LUA_OK) throw ArgError(error_text(L, -1));
  if (!lua_istable(L, -1))
    throw ArgError(path + ": expected the file to return a table, got " + luaL_typename(L, -1));
  return 1;
}

}  // namespace

void bind_gym(lua_State* L) {
  push_squawk_subtable(L, "gym");
  lua_pushcfunction(L, guarded<l_load>);
  lua_setfield(L, -2, "load");
  lua_pop(L, 1);
}

}  // namespace squawk::script
