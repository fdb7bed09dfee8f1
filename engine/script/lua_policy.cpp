#include "script/lua_policy.h"

#include <cmath>
#include <utility>

#include "core/paths.h"
#include "core/text.h"
#include "script/lua_util.h"

namespace squawk::script {

namespace {

// Registry keys: the file's table and its act and reset functions (read once).
constexpr const char* kPolicyKey = "squawk.policy";
constexpr const char* kActKey = "squawk.policy.act";
constexpr const char* kResetKey = "squawk.policy.reset";

}  // namespace

LuaPolicy::~LuaPolicy() = default;

Result<std::unique_ptr<LuaPolicy>> LuaPolicy::load(const std::string& path,
                                                   const VmOptions& options,
                                                   const LuaEnvSpec& spec) {
  std::unique_ptr<LuaPolicy> p(new LuaPolicy(path, std::make_unique<Vm>(options), spec));
  p->vm_->add_script_folder(paths::dirname(path));  // the file may require its neighbours
  SQUAWK_RETURN_IF_ERROR(p->vm_->load_table(path, kPolicyKey));
  SQUAWK_RETURN_IF_ERROR(p->read_fields());
  return p;
}

Status LuaPolicy::read_fields() {
  lua_State* L = vm_->state();
  lua_getfield(L, LUA_REGISTRYINDEX, kPolicyKey);
  const int t = lua_gettop(L);
  Status st = catch_arg_errors(L, path_ + ": ", [&] {
    const std::string env = field_string(L, t, "env", "");
    if (!env.empty() && env != spec_.id)
      throw ArgError("field 'env': the policy is written for " + env + ", not " + spec_.id);
    get_field(L, t, "act");
    if (!lua_isfunction(L, -1))
      throw ArgError("field 'act' must be a function (P:act(obs) -> action array)");
    lua_setfield(L, LUA_REGISTRYINDEX, kActKey);
    get_field(L, t, "reset");
    has_reset_ = !lua_isnil(L, -1);
    if (has_reset_ && !lua_isfunction(L, -1))
      throw ArgError(std::string("field 'reset' must be a function or absent, got ") +
                     luaL_typename(L, -1));
    lua_setfield(L, LUA_REGISTRYINDEX, kResetKey);
  });
  lua_settop(L, t - 1);
  return st;
}

Status LuaPolicy::reset(uint64_t seed) {
  if (!has_reset_) return Status::ok();
  lua_State* L = vm_->state();
  const int top = lua_gettop(L);
  lua_getfield(L, LUA_REGISTRYINDEX, kResetKey);
  lua_getfield(L, LUA_REGISTRYINDEX, kPolicyKey);
  lua_pushinteger(L, static_cast<lua_Integer>(seed));
  Status st = vm_->pcall(2, 0);
  lua_settop(L, top);
  return st;
}

Status LuaPolicy::act(std::span<const double> obs, std::span<double> action) {
  lua_State* L = vm_->state();
  const int top = lua_gettop(L);
  lua_getfield(L, LUA_REGISTRYINDEX, kActKey);
  lua_getfield(L, LUA_REGISTRYINDEX, kPolicyKey);
  lua_createtable(L, static_cast<int>(obs.size()), 0);
  for (size_t k = 0; k < obs.size(); ++k) {
    lua_pushnumber(L, obs[k]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
  }
  Status st = vm_->pcall(2, 1);
  if (st.is_ok())
    st = catch_arg_errors(L, path_ + ": act: ", [&] {
      const int a = top + 1;
      if (!lua_istable(L, a))
        throw ArgError(std::string("the action: expected an array of numbers, got ") +
                       luaL_typename(L, a));
      const lua_Integer n = length(L, a);
      if (n != spec_.action_size())
        throw ArgError("the action has " + std::to_string(n) + " numbers; " + spec_.id + " takes " +
                       std::to_string(spec_.action_size()));
      for (lua_Integer k = 1; k <= n; ++k) {
        get_index(L, a, k);
        const size_t i = static_cast<size_t>(k - 1);
        const double v = lua_tonumber(L, -1);
        if (!lua_isnumber(L, -1) || !std::isfinite(v))
          throw ArgError(
              "action[" + std::to_string(k) + "]: expected a finite number, got " +
              (lua_isnumber(L, -1) ? text::fmt_exact(v) : std::string(luaL_typename(L, -1))));
        if (v < spec_.action_low[i] || v > spec_.action_high[i])
          throw ArgError("action[" + std::to_string(k) + "] = " + text::fmt_exact(v) +
                         " is outside [" + text::fmt_exact(spec_.action_low[i]) + ", " +
                         text::fmt_exact(spec_.action_high[i]) + "]");
        action[i] = v;
        lua_pop(L, 1);
      }
    });
  lua_settop(L, top);
  return st;
}

}  // namespace squawk::script
