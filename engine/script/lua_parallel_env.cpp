#include "script/lua_parallel_env.h"

#include <cmath>

#include "core/paths.h"
#include "core/text.h"
#include "script/lua_util.h"

namespace squawk::script {

namespace {

constexpr const char* kEnvKey = "squawk.gym.parallel_env";
constexpr const char* kResetKey = "squawk.gym.parallel_reset";
constexpr const char* kStepKey = "squawk.gym.parallel_step";

// "a number", "a string", ... of the value at idx, or its exact text for a number.
std::string shown(lua_State* L, int idx) {
  if (lua_type(L, idx) == LUA_TNUMBER) return text::fmt_exact(lua_tonumber(L, idx));
  return luaL_typename(L, idx);
}

// Pushes t[name] of the table at idx (raw: no metamethod runs).
void push_entry(lua_State* L, int idx, const std::string& name) {
  lua_pushlstring(L, name.data(), name.size());
  lua_rawget(L, idx);
}

}  // namespace

LuaParallelEnv::~LuaParallelEnv() = default;

Result<bool> is_parallel_env(const std::string& path, const VmOptions& options) {
  Vm vm(options);
  vm.add_script_folder(paths::dirname(path));
  SQUAWK_RETURN_IF_ERROR(vm.load_table(path, kEnvKey));
  lua_State* L = vm.state();
  lua_getfield(L, LUA_REGISTRYINDEX, kEnvKey);
  auto s = read_env_spec(L, -1, path);
  lua_pop(L, 1);
  if (!s) return s.status();
  return s->parallel;
}

Result<std::unique_ptr<LuaParallelEnv>> LuaParallelEnv::load(const std::string& path,
                                                             const VmOptions& options) {
  std::unique_ptr<LuaParallelEnv> env(new LuaParallelEnv(path, std::make_unique<Vm>(options)));
  Vm& vm = *env->vm_;
  vm.add_script_folder(paths::dirname(path));  // the file may require its neighbours
  SQUAWK_RETURN_IF_ERROR(vm.load_table(path, kEnvKey));
  lua_State* L = vm.state();
  lua_getfield(L, LUA_REGISTRYINDEX, kEnvKey);
  auto s = read_env_spec(L, -1, path);
  Status st = s.status();
  if (st.is_ok() && !s->parallel)
    st = Status::invalid(path +
                         ": not a multi-agent environment (no 'parallel = true'); this driver "
                         "steps PettingZoo-shaped files (docs/gym_envs.md)");
  if (st.is_ok()) st = store_env_functions(L, -1, path, kResetKey, kStepKey);
  lua_pop(L, 1);
  if (!st.is_ok()) return st;
  env->spec_ = std::move(*s);
  return env;
}

std::span<const double> LuaParallelEnv::observation(size_t a) const {
  const auto d = static_cast<size_t>(spec_.observation_size);
  return std::span<const double>(obs_).subspan(a * d, d);
}

Status LuaParallelEnv::read_agents(const char* fn) {
  lua_State* L = vm_->state();
  const int top = lua_gettop(L);
  lua_getfield(L, LUA_REGISTRYINDEX, kEnvKey);
  lua_pushliteral(L, "agents");
  lua_rawget(L, -2);
  agents_.clear();
  Status st;
  if (!lua_istable(L, -1)) {
    st = Status::invalid(path_ + ": " + fn + ": E.agents: expected an array of agent names, got " +
                         luaL_typename(L, -1));
  } else {
    const auto n = static_cast<lua_Integer>(lua_rawlen(L, -1));
    for (lua_Integer k = 1; k <= n && st.is_ok(); ++k) {
      lua_rawgeti(L, -1, k);
      if (lua_type(L, -1) != LUA_TSTRING)
        st = Status::invalid(path_ + ": " + fn + ": E.agents[" + std::to_string(k) +
                             "]: expected an agent name (a string), got " + shown(L, -1));
      else
        agents_.emplace_back(lua_tostring(L, -1));
      lua_pop(L, 1);
    }
  }
  lua_settop(L, top);
  return st;
}

Status LuaParallelEnv::read_observations(int idx, const std::vector<std::string>& names,
                                         const char* fn) {
  lua_State* L = vm_->state();
  const std::string where = path_ + ": " + fn + ": ";
  if (!lua_istable(L, idx))
    return Status::invalid(where +
                           "the observations (1st result): expected a table keyed by agent, got " +
                           luaL_typename(L, idx));
  const auto d = static_cast<size_t>(spec_.observation_size);
  obs_.resize(names.size() * d);
  for (size_t a = 0; a < names.size(); ++a) {
    push_entry(L, idx, names[a]);
    const int o = lua_gettop(L);
    Status st;
    if (!lua_istable(L, o)) {
      st = Status::invalid(where + "observations." + names[a] +
                           ": expected an array of numbers, got " + luaL_typename(L, o));
    } else if (lua_rawlen(L, o) != d) {
      st = Status::invalid(where + "observations." + names[a] + " has " +
                           std::to_string(lua_rawlen(L, o)) +
                           " numbers; the declared observation has " + std::to_string(d));
    } else {
      for (size_t j = 0; j < d && st.is_ok(); ++j) {
        lua_rawgeti(L, o, static_cast<lua_Integer>(j + 1));
        int is_number = 0;
        const double v = lua_tonumberx(L, -1, &is_number);
        if (!is_number || !std::isfinite(v))
          st = Status::invalid(where + "observations." + names[a] + "[" + std::to_string(j + 1) +
                               "]: expected a finite number, got " + shown(L, -1));
        obs_[a * d + j] = v;
        lua_pop(L, 1);
      }
    }
    lua_settop(L, o - 1);
    if (!st.is_ok()) return st;
  }
  return Status::ok();
}

Status LuaParallelEnv::reset(uint64_t seed, int num_agents) {
  lua_State* L = vm_->state();
  const int top = lua_gettop(L);
  started_ = false;
  lua_getfield(L, LUA_REGISTRYINDEX, kResetKey);
  lua_getfield(L, LUA_REGISTRYINDEX, kEnvKey);
  lua_pushinteger(L, static_cast<lua_Integer>(seed));
  lua_createtable(L, 0, 1);
  lua_pushinteger(L, num_agents);
  lua_setfield(L, -2, "num_agents");
  Status st = vm_->pcall(3, 1);
  if (st.is_ok()) st = read_agents("reset");
  if (st.is_ok()) st = read_observations(top + 1, agents_, "reset");
  lua_settop(L, top);
  if (!st.is_ok()) return st;
  kept_.resize(agents_.size());
  for (size_t k = 0; k < kept_.size(); ++k) kept_[k] = static_cast<int>(k);
  steps_ = 0;
  started_ = true;
  return Status::ok();
}

Status LuaParallelEnv::step(std::span<const int> commanded,
                            std::span<const std::vector<double>> commands,
                            std::vector<AgentStep>& out) {
  if (!started_) return Status::invalid(path_ + ": step before a successful reset");
  lua_State* L = vm_->state();
  const int top = lua_gettop(L);
  const std::vector<std::string> before = agents_;
  lua_getfield(L, LUA_REGISTRYINDEX, kStepKey);
  lua_getfield(L, LUA_REGISTRYINDEX, kEnvKey);
  lua_createtable(L, 0, static_cast<int>(commanded.size()));
  for (const int a : commanded) {
    const std::vector<double>& act = commands[static_cast<size_t>(a)];
    if (static_cast<int>(act.size()) != spec_.action_size()) {
      lua_settop(L, top);
      return Status::invalid(path_ + ": step: the action of " + before[static_cast<size_t>(a)] +
                             " has " + std::to_string(act.size()) + " numbers, expected " +
                             std::to_string(spec_.action_size()));
    }
    lua_createtable(L, static_cast<int>(act.size()), 0);
    for (size_t k = 0; k < act.size(); ++k) {
      lua_pushnumber(L, act[k]);
      lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
    }
    lua_setfield(L, -2, before[static_cast<size_t>(a)].c_str());
  }
  Status st = vm_->pcall(2, 5);
  out.assign(before.size(), AgentStep{});
  const std::string where = path_ + ": step: ";
  if (st.is_ok()) {
    for (int k = 2; k <= 4 && st.is_ok(); ++k)
      if (!lua_istable(L, top + k))
        st =
            Status::invalid(where +
                            std::string(k == 2   ? "rewards"
                                        : k == 3 ? "terminations"
                                                 : "truncations") +
                            " (result " + std::to_string(k) +
                            "): expected a table keyed by agent, got " + luaL_typename(L, top + k));
  }
  const bool limit = steps_ + 1 >= spec_.max_episode_steps;
  for (size_t a = 0; a < before.size() && st.is_ok(); ++a) {
    const std::string& name = before[a];
    AgentStep& r = out[a];
    push_entry(L, top + 2, name);
    push_entry(L, top + 3, name);
    push_entry(L, top + 4, name);
    const int v = lua_gettop(L) - 2;
    if (!lua_isnumber(L, v) || !std::isfinite(lua_tonumber(L, v)))
      st = Status::invalid(where + "rewards." + name + ": expected a finite number, got " +
                           shown(L, v));
    else if (!lua_isboolean(L, v + 1) || !lua_isboolean(L, v + 2))
      st = Status::invalid(where + "terminations." + name + " and truncations." + name +
                           ": expected booleans, got " + luaL_typename(L, v + 1) + " and " +
                           luaL_typename(L, v + 2));
    else {
      r.reward = lua_tonumber(L, v);
      r.terminated = lua_toboolean(L, v + 1) != 0;
      r.truncated = lua_toboolean(L, v + 2) != 0 || (limit && !r.terminated);
    }
    lua_settop(L, v - 1);
    if (!st.is_ok() || !(r.terminated || r.truncated) || !lua_istable(L, top + 5)) continue;
    push_entry(L, top + 5, name);
    if (lua_istable(L, -1)) {
      lua_pushliteral(L, "success");
      lua_rawget(L, -2);
      if (lua_isboolean(L, -1))
        r.success = lua_toboolean(L, -1) != 0;
      else if (!lua_isnil(L, -1))
        st = Status::invalid(where + "infos." + name + ".success: expected a boolean, got " +
                             luaL_typename(L, -1));
    }
    lua_settop(L, top + 5);
  }
  if (st.is_ok()) st = read_agents("step");
  if (st.is_ok() && limit) agents_.clear();
  kept_.assign(agents_.size(), 0);
  for (size_t k = 0; k < agents_.size() && st.is_ok(); ++k) {
    size_t a = 0;
    while (a < before.size() && before[a] != agents_[k]) ++a;
    kept_[k] = static_cast<int>(a);
    if (a == before.size())
      st = Status::invalid(where + "E.agents holds " + agents_[k] +
                           ", which was not flying before the step");
    else if (out[a].terminated || out[a].truncated)
      st = Status::invalid(where + agents_[k] + " is still in E.agents after its " +
                           (out[a].terminated ? "termination" : "truncation"));
  }
  if (st.is_ok()) {
    size_t flying = 0;
    for (const AgentStep& r : out) flying += !(r.terminated || r.truncated);
    if (flying != agents_.size())
      st = Status::invalid(where + "E.agents holds " + std::to_string(agents_.size()) +
                           " agents after the step; " + std::to_string(flying) +
                           " were neither terminated nor truncated");
  }
  if (st.is_ok()) st = read_observations(top + 1, agents_, "step");
  lua_settop(L, top);
  if (!st.is_ok()) {
    started_ = false;
    return st;
  }
  ++steps_;
  return Status::ok();
}

}  // namespace squawk::script
