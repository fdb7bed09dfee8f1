// squawk.gym: environments written as Lua files (envs/*.lua; the contract in
// script/lua_env.h and docs/gym_envs.md), from Lua.
//
//   squawk.gym.load(path) -> env    the table the file returns (readable paths
//                                    only), used as env:reset(seed [, options]),
//                                    env:step({a1, ...}); no TimeLimit is added.
//                                    The file's folder joins the require path.
//   squawk.gym.mlp(checkpoint, env [, {seed = 0, greedy = false}]) -> policy
//                                    a checkpoint of `squawk train --env` for
//                                    env (a table of squawk.gym.load; per agent
//                                    for a multi-agent file), refused when its
//                                    observation size or action grid does not
//                                    fit (script/grid_policy.h)
//   policy:act(obs) -> {a1, ...}      the action (a point of the grid) for one
//                                    observation (an array of the declared
//                                    size), sampled from Rng(seed), or the
//                                    policy's mode when greedy
#include <string>
#include <vector>

#include "core/paths.h"
#include "core/rng.h"
#include "script/bindings.h"
#include "script/grid_policy.h"
#include "script/lua_batch_env.h"
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

constexpr const char* kPolicyMt = "squawk.GymPolicy";

struct PolicyBox {
  LuaEnvSpec spec;
  GridPolicy grid;
  Rng rng;
  bool greedy = false;
  std::vector<float> obs;
  std::vector<double> action;
};

int l_mlp(lua_State* L) {
  const std::string path = readable(L, arg_string(L, 1, "checkpoint"), "checkpoint");
  if (!lua_istable(L, 2))
    throw ArgError(std::string("env: expected the table of squawk.gym.load, got ") +
                   luaL_typename(L, 2));
  auto spec = read_env_spec(L, 2, "env");
  check_status(spec.status());
  auto grid = load_grid_policy(path, *spec);
  check_status(grid.status());
  uint64_t seed = 0;
  bool greedy = false;
  if (lua_istable(L, 3)) {
    seed = static_cast<uint64_t>(field_count(L, 3, "seed", 0, 0, 9007199254740992LL));
    greedy = field_boolean(L, 3, "greedy", false);
  }
  PolicyBox* box = new_object<PolicyBox>(L, kPolicyMt);
  box->spec = std::move(*spec);
  box->grid = std::move(*grid);
  box->rng = Rng(seed);
  box->greedy = greedy;
  box->obs.resize(static_cast<size_t>(box->spec.observation_size));
  box->action.resize(static_cast<size_t>(box->spec.action_size()));
  return 1;
}

int l_act(lua_State* L) {
  PolicyBox* box = arg_object<PolicyBox>(L, 1, kPolicyMt);
  if (!lua_istable(L, 2))
    throw ArgError(std::string("obs: expected an array of numbers, got ") + luaL_typename(L, 2));
  const lua_Integer n = length(L, 2);
  if (n != box->spec.observation_size)
    throw ArgError("obs has " + std::to_string(n) + " numbers; the policy reads " +
                   std::to_string(box->spec.observation_size));
  for (lua_Integer k = 1; k <= n; ++k) {
    get_index(L, 2, k);
    if (!lua_isnumber(L, -1))
      throw ArgError("obs[" + std::to_string(k) + "]: expected a number, got " +
                     luaL_typename(L, -1));
    box->obs[static_cast<size_t>(k - 1)] = static_cast<float>(lua_tonumber(L, -1));
    lua_pop(L, 1);
  }
  const int row = 0;
  rl::ActionSample choice;
  box->grid.mlp->act(box->obs, 1, {&row, 1}, {&box->rng, 1}, box->greedy, {&choice, 1});
  check_status(box->grid.mlp->error());
  policy_action(box->spec, box->grid, choice, box->action);
  lua_createtable(L, static_cast<int>(box->action.size()), 0);
  for (size_t k = 0; k < box->action.size(); ++k) {
    lua_pushnumber(L, box->action[k]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
  }
  return 1;
}

}  // namespace

void bind_gym(lua_State* L) {
  static const luaL_Reg methods[] = {{"act", guarded<l_act>}, {nullptr, nullptr}};
  define_class(L, kPolicyMt, methods);
  push_squawk_subtable(L, "gym");
  lua_pushcfunction(L, guarded<l_load>);
  lua_setfield(L, -2, "load");
  lua_pushcfunction(L, guarded<l_mlp>);
  lua_setfield(L, -2, "mlp");
  lua_pop(L, 1);
}

}  // namespace squawk::script
