#include "script/lua_env.h"

#include <cmath>
#include <utility>

#include "core/paths.h"
#include "core/text.h"
#include "script/lua_util.h"

namespace squawk::script {

namespace {

// Registry keys: the file's table and its reset and step functions (read
// once, so no metamethod of the table runs outside a protected call).
constexpr const char* kEnvKey = "squawk.gym.env";
constexpr const char* kResetKey = "squawk.gym.reset";
constexpr const char* kStepKey = "squawk.gym.step";

// Pushes the file's table.
void push_env(lua_State* L) {
  lua_getfield(L, LUA_REGISTRYINDEX, kEnvKey);
}

// An array of numbers at `idx` (protected reads; ArgError naming `what`).
std::vector<double> number_array(lua_State* L, int idx, const std::string& what) {
  if (!lua_istable(L, idx))
    throw ArgError(what + ": expected an array of numbers, got " + luaL_typename(L, idx));
  const lua_Integer n = length(L, idx);
  std::vector<double> v;
  v.reserve(static_cast<size_t>(n));
  for (lua_Integer k = 1; k <= n; ++k) {
    get_index(L, idx, k);
    if (!lua_isnumber(L, -1))
      throw ArgError(what + "[" + std::to_string(k) + "]: expected a number, got " +
                     luaL_typename(L, -1));
    v.push_back(lua_tonumber(L, -1));
    lua_pop(L, 1);
  }
  return v;
}

}  // namespace

LuaEnv::~LuaEnv() = default;

Result<std::unique_ptr<LuaEnv>> LuaEnv::load(const std::string& path, const VmOptions& options) {
  std::unique_ptr<LuaEnv> env(new LuaEnv(path, std::make_unique<Vm>(options)));
  env->vm_->add_script_folder(paths::dirname(path));  // the file may require its neighbours
  SQUAWK_RETURN_IF_ERROR(env->vm_->load_table(path, kEnvKey));
  SQUAWK_RETURN_IF_ERROR(env->read_spec());
  return env;
}

Result<LuaEnvSpec> read_env_spec(lua_State* L, int e, const std::string& path) {
  e = lua_absindex(L, e);
  const int top = lua_gettop(L);
  LuaEnvSpec s;
  Status st = catch_arg_errors(L, path + ": ", [&] {
    s.id = field_string(L, e, "id", "");
    if (s.id.empty()) throw ArgError("field 'id' (the environment's name, a string) is required");
    s.source = field_string(L, e, "source", "");
    s.parallel = field_boolean(L, e, "parallel", false);
    get_field(L, e, "observation");
    if (!lua_istable(L, -1))
      throw ArgError("field 'observation' must be an array of {name =, size =}");
    const lua_Integer nf = length(L, -1);
    for (lua_Integer k = 1; k <= nf; ++k) {
      get_index(L, -1, k);
      const std::string where = "observation[" + std::to_string(k) + "]";
      if (!lua_istable(L, -1)) throw ArgError(where + ": expected {name =, size =}");
      LuaEnvSpec::Field f;
      f.name = field_string(L, -1, "name", "");
      if (f.name.empty()) throw ArgError(where + ".name: a non-empty string is required");
      f.size = static_cast<int>(field_count(L, -1, "size", 1, 1, 1 << 20));
      s.observation_size += f.size;
      s.observation.push_back(std::move(f));
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
    if (s.observation.empty()) throw ArgError("field 'observation' declares no slices");
    get_field(L, e, "action");
    if (!lua_istable(L, -1)) throw ArgError("field 'action' must be {low = {..}, high = {..}}");
    get_field(L, -1, "low");
    s.action_low = number_array(L, -1, "action.low");
    lua_pop(L, 1);
    get_field(L, -1, "high");
    s.action_high = number_array(L, -1, "action.high");
    lua_pop(L, 2);
    if (s.action_low.empty() || s.action_low.size() != s.action_high.size())
      throw ArgError("action.low and action.high must have the same length >= 1");
    for (size_t k = 0; k < s.action_low.size(); ++k)
      if (!(s.action_low[k] <= s.action_high[k]) || !std::isfinite(s.action_low[k]) ||
          !std::isfinite(s.action_high[k]))
        throw ArgError("action bounds " + std::to_string(k + 1) +
                       ": expected finite low <= high, got " + text::fmt_exact(s.action_low[k]) +
                       ", " + text::fmt_exact(s.action_high[k]));
    s.max_episode_steps =
        static_cast<int>(field_count(L, e, "max_episode_steps", 0, 1, 1'000'000'000));
    if (s.max_episode_steps == 0)
      throw ArgError("field 'max_episode_steps' (a whole number >= 1) is required");
  });
  lua_settop(L, top);
  if (!st.is_ok()) return st;
  return s;
}

Status store_env_functions(lua_State* L, int e, const std::string& path, const char* reset_key,
                           const char* step_key) {
  e = lua_absindex(L, e);
  const int top = lua_gettop(L);
  Status st = catch_arg_errors(L, path + ": ", [&] {
    for (const auto& [fn, key] : {std::pair{"reset", reset_key}, std::pair{"step", step_key}}) {
      get_field(L, e, fn);
      if (!lua_isfunction(L, -1))
        throw ArgError(std::string("field '") + fn + "' must be a function");
      lua_setfield(L, LUA_REGISTRYINDEX, key);
    }
  });
  lua_settop(L, top);
  return st;
}

Status LuaEnv::read_spec() {
  lua_State* L = vm_->state();
  push_env(L);
  auto s = read_env_spec(L, -1, path_);
  Status st = s.status();
  if (st.is_ok() && s->parallel)
    st = Status::invalid(
        path_ +
        ": field 'parallel' = true: a multi-agent environment (PettingZoo's parallel API, tables "
        "keyed by agent); this driver steps single-agent files (docs/gym_envs.md)");
  if (st.is_ok()) st = store_env_functions(L, -1, path_, kResetKey, kStepKey);
  lua_pop(L, 1);
  if (!st.is_ok()) return st;
  spec_ = std::move(*s);
  obs_.assign(static_cast<size_t>(spec_.observation_size), 0.0);
  return Status::ok();
}

bool LuaEnv::read_plain_observation(int idx) {
  lua_State* L = vm_->state();
  if (!lua_istable(L, idx) ||
      lua_rawlen(L, idx) != static_cast<lua_Unsigned>(spec_.observation_size))
    return false;
  if (lua_getmetatable(L, idx)) {
    lua_pop(L, 1);
    return false;
  }
  for (int k = 1; k <= spec_.observation_size; ++k) {
    int is_number = 0;
    lua_rawgeti(L, idx, k);
    const double v = lua_tonumberx(L, -1, &is_number);
    lua_pop(L, 1);
    if (!is_number || !std::isfinite(v)) return false;
    obs_[static_cast<size_t>(k - 1)] = v;
  }
  return true;
}

Status LuaEnv::read_observation(int idx, const char* fn) {
  lua_State* L = vm_->state();
  idx = lua_absindex(L, idx);
  if (read_plain_observation(idx)) return Status::ok();
  return catch_arg_errors(L, path_ + ": " + fn + ": ", [&] {
    if (!lua_istable(L, idx))
      throw ArgError(std::string("the observation: expected an array of numbers, got ") +
                     luaL_typename(L, idx));
    const lua_Integer n = length(L, idx);
    if (n != spec_.observation_size)
      throw ArgError("the observation has " + std::to_string(n) +
                     " numbers; the declared observation has " +
                     std::to_string(spec_.observation_size));
    for (lua_Integer k = 1; k <= n; ++k) {
      get_index(L, idx, k);
      const double v = lua_tonumber(L, -1);
      if (!lua_isnumber(L, -1) || !std::isfinite(v))
        throw ArgError(
            "observation[" + std::to_string(k) + "]: expected a finite number, got " +
            (lua_isnumber(L, -1) ? text::fmt_exact(v) : std::string(luaL_typename(L, -1))));
      obs_[static_cast<size_t>(k - 1)] = v;
      lua_pop(L, 1);
    }
  });
}

Status LuaEnv::read_success(int idx, LuaStep& r) {
  lua_State* L = vm_->state();
  if (!lua_istable(L, idx)) return Status::ok();
  return catch_arg_errors(L, path_ + ": step: ", [&] {
    get_field(L, idx, "success");
    if (!lua_isnil(L, -1)) {
      if (!lua_isboolean(L, -1))
        throw ArgError(std::string("info.success (5th result) must be a boolean, got ") +
                       luaL_typename(L, -1));
      r.success = lua_toboolean(L, -1) != 0;
    }
    lua_pop(L, 1);
  });
}

Status LuaEnv::reset(uint64_t seed) {
  lua_State* L = vm_->state();
  const int top = lua_gettop(L);
  lua_getfield(L, LUA_REGISTRYINDEX, kResetKey);
  push_env(L);
  lua_pushinteger(L, static_cast<lua_Integer>(seed));
  Status st = vm_->pcall(2, 1);
  if (st.is_ok()) st = read_observation(-1, "reset");
  lua_settop(L, top);
  if (!st.is_ok()) return st;
  steps_ = 0;
  started_ = true;
  return Status::ok();
}

Result<LuaStep> LuaEnv::step(std::span<const double> action) {
  if (!started_) return Status::invalid(path_ + ": step before a successful reset");
  if (static_cast<int>(action.size()) != spec_.action_size())
    return Status::invalid(path_ + ": step: action has " + std::to_string(action.size()) +
                           " numbers, expected " + std::to_string(spec_.action_size()));
  lua_State* L = vm_->state();
  const int top = lua_gettop(L);
  lua_getfield(L, LUA_REGISTRYINDEX, kStepKey);
  push_env(L);
  lua_createtable(L, static_cast<int>(action.size()), 0);
  for (size_t k = 0; k < action.size(); ++k) {
    lua_pushnumber(L, action[k]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
  }
  Status st = vm_->pcall(2, 5);
  LuaStep r;
  if (st.is_ok()) st = read_observation(top + 1, "step");
  if (st.is_ok()) {
    if (!lua_isnumber(L, top + 2) || !std::isfinite(lua_tonumber(L, top + 2)))
      st = Status::invalid(path_ + ": step: the reward (2nd result) must be a finite number, got " +
                           (lua_isnumber(L, top + 2) ? text::fmt_exact(lua_tonumber(L, top + 2))
                                                     : std::string(luaL_typename(L, top + 2))));
    else if (!lua_isboolean(L, top + 3) || !lua_isboolean(L, top + 4))
      st = Status::invalid(
          path_ + ": step: terminated and truncated (3rd and 4th results) must be booleans, got " +
          luaL_typename(L, top + 3) + " and " + luaL_typename(L, top + 4));
    else {
      r.reward = lua_tonumber(L, top + 2);
      r.terminated = lua_toboolean(L, top + 3) != 0;
      r.truncated = lua_toboolean(L, top + 4) != 0;
      if (r.terminated || r.truncated || steps_ + 1 >= spec_.max_episode_steps)
        st = read_success(top + 5, r);
    }
  }
  lua_settop(L, top);
  if (!st.is_ok()) {
    started_ = false;
    return st;
  }
  ++steps_;
  if (!r.terminated && steps_ >= spec_.max_episode_steps) r.truncated = true;
  return r;
}

}  // namespace squawk::script
