#include "script/scenario.h"

#include <cmath>
#include <set>
#include <string>

#include "core/files.h"
#include "core/paths.h"
#include "core/units.h"
#include "script/lua_fields.h"
#include "script/lua_util.h"
#include "script/step_fields.h"
#include "script/vm.h"

namespace squawk::script {

namespace {

// Throws ArgError naming the first key of the table at idx not in `known`.
void check_keys(lua_State* L, int idx, const char* table, const std::set<std::string>& known) {
  idx = lua_absindex(L, idx);
  lua_pushnil(L);
  while (lua_next(L, idx) != 0) {
    lua_pop(L, 1);
    std::string key = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "(non-string key)";
    if (!known.count(key)) {
      lua_pop(L, 1);
      std::string all;
      for (const auto& k : known) all.append(all.empty() ? "" : ", ").append(k);
      throw ArgError("scenario table '" + std::string(table) + "' has unknown key '" + key +
                     "'; known keys: " + all);
    }
  }
}

// Pushes field `key` of the table at idx when it is a table; false (nothing
// pushed) when nil; ArgError otherwise.
bool push_table_field(lua_State* L, int idx, const char* key) {
  get_field(L, idx, key);
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    return false;
  }
  if (!lua_istable(L, -1)) {
    std::string t = luaL_typename(L, -1);
    lua_pop(L, 1);
    throw ArgError(std::string("scenario field '") + key + "': expected a table, got " + t);
  }
  return true;
}

std::vector<double> number_list(lua_State* L, int idx, const char* key, std::vector<double> fallback) {
  idx = lua_absindex(L, idx);
  if (!push_table_field(L, idx, key)) return fallback;
  std::vector<double> out;
  const lua_Integer n = length(L, -1);
  for (lua_Integer i = 1; i <= n; ++i) {
    get_index(L, -1, i);
    int ok = 0;
    const double v = lua_tonumberx(L, -1, &ok);
    lua_pop(L, 1);
    if (!ok) {
      lua_pop(L, 1);
      throw ArgError(std::string("scenario field '") + key + "': entry " + std::to_string(i) +
                     " is not a number");
    }
    out.push_back(v);
  }
  lua_pop(L, 1);
  return out;
}

env::IntRange int_range(lua_State* L, int idx, const char* key, env::IntRange fallback) {
  const std::vector<double> v = number_list(L, idx, key, {double(fallback.lo), double(fallback.hi)});
  if (v.size() != 2 || v[0] != static_cast<int>(v[0]) || v[1] != static_cast<int>(v[1]))
    throw ArgError(std::string("scenario field '") + key + "': expected {lo, hi} integers");
  return {static_cast<int>(v[0]), static_cast<int>(v[1])};
}

constexpr long long kMaxCount = 1LL << 53;  // episodes and seeds: whole numbers a double holds exactly

int int_field(lua_State* L, int idx, const char* key, int fallback) {
  return static_cast<int>(field_count(L, idx, key, fallback, -2147483647, 2147483647));
}

const std::set<std::string> kEnvKeys = {
    "intruders", "own_speed_ms", "speed_cap_ms", "accel_ms2", "bank_deg", "dt_s", "substeps",
    "start_lat", "start_lon", "dpsi_deg", "cpa_nm", "tlos_s", "waypoint_km", "zone_radius_nm",
    "reach_radius_km", "heading_step_deg", "max_steps", "lookahead_s", "mvp_margin"};

void read_env(lua_State* L, int idx, env::HorizontalCrConfig& c) {
  c.num_intruders = int_field(L, idx, "intruders", c.num_intruders);
  c.own_speed = field_number(L, idx, "own_speed_ms", c.own_speed);
  c.limits.speed_cap = field_number(L, idx, "speed_cap_ms", c.limits.speed_cap);
  c.limits.accel = field_number(L, idx, "accel_ms2", c.limits.accel);
  c.limits.bank = field_number(L, idx, "bank_deg", c.limits.bank);
  c.dt = field_number(L, idx, "dt_s", c.dt);
  c.substeps = int_field(L, idx, "substeps", c.substeps);
  c.start_lat = field_number(L, idx, "start_lat", c.start_lat);
  c.start_lon = field_number(L, idx, "start_lon", c.start_lon);
  c.dpsi = int_range(L, idx, "dpsi_deg", c.dpsi);
  c.cpa = int_range(L, idx, "cpa_nm", c.cpa);
  c.tlos = int_range(L, idx, "tlos_s", c.tlos);
  c.waypoint_distance = int_range(L, idx, "waypoint_km", c.waypoint_distance);
  c.zone_radius = units::nm_to_m(field_number(L, idx, "zone_radius_nm", units::m_to_nm(c.zone_radius)));
  c.reach_radius = 1000.0 * field_number(L, idx, "reach_radius_km", c.reach_radius / 1000.0);
  c.heading_per_action = field_number(L, idx, "heading_step_deg", c.heading_per_action);
  c.max_steps = int_field(L, idx, "max_steps", c.max_steps);
  c.lookahead = field_number(L, idx, "lookahead_s", c.lookahead);
  c.mvp_margin = field_number(L, idx, "mvp_margin", c.mvp_margin);
}

void read_weights(lua_State* L, int idx, env::RewardWeights& w) {
  check_keys(L, idx, "reward",
             {"reach", "drift_per_rad", "intrusion", "w_i", "w_d", "w_h", "clear_bonus",
              "drift_limit_deg", "drift_beyond", "exp_rate", "delta_norm_deg", "intrusion_at"});
  w.reach = field_number(L, idx, "reach", w.reach);
  w.drift_per_rad = field_number(L, idx, "drift_per_rad", w.drift_per_rad);
  w.intrusion = field_number(L, idx, "intrusion", w.intrusion);
  w.w_i = field_number(L, idx, "w_i", w.w_i);
  w.w_d = field_number(L, idx, "w_d", w.w_d);
  w.w_h = field_number(L, idx, "w_h", w.w_h);
  w.clear_bonus = field_number(L, idx, "clear_bonus", w.clear_bonus);
  w.drift_limit = field_number(L, idx, "drift_limit_deg", w.drift_limit);
  w.drift_beyond = field_number(L, idx, "drift_beyond", w.drift_beyond);
  w.exp_rate = field_number(L, idx, "exp_rate", w.exp_rate);
  w.delta_norm = field_number(L, idx, "delta_norm_deg", w.delta_norm);
  const std::string at = field_string(L, idx, "intrusion_at", "step_end");
  if (at != "step_end" && at != "substep")
    throw ArgError("scenario field 'reward.intrusion_at' is '" + at + "': expected \"step_end\" or \"substep\"");
  w.intrusion_at_substeps = at == "substep";
}

// `env` supplies the mirror map when the table asks for mirror = true.
void read_policy(lua_State* L, int idx, const env::HorizontalCrConfig& env, rl::MlpPolicySpec& p) {
  check_keys(L, idx, "policy", {"hidden", "head", "actions", "init_log_std", "mirror"});
  std::vector<double> hidden_default(p.hidden.begin(), p.hidden.end());
  p.hidden.clear();
  for (double h : number_list(L, idx, "hidden", hidden_default)) p.hidden.push_back(static_cast<int>(h));
  p.head = field_string(L, idx, "head", p.head);
  p.action_values = number_list(L, idx, "actions", p.action_values);
  p.init_log_std = field_number(L, idx, "init_log_std", p.init_log_std);
  get_field(L, idx, "mirror");
  const int type = lua_type(L, -1);
  const bool mirror = type == LUA_TBOOLEAN && lua_toboolean(L, -1) != 0;
  lua_pop(L, 1);
  if (type != LUA_TNIL && type != LUA_TBOOLEAN)
    throw ArgError(std::string("scenario field 'policy.mirror' is a ") + lua_typename(L, type) +
                   ": expected true or false");
  if (!mirror) return;
  Result<env::ObservationMirror> m = env::observation_mirror(env);
  if (!m) throw ArgError("scenario field 'policy.mirror': " + m.status().message());
  p.mirror = std::move(*m);
}

void read_train(lua_State* L, int idx, rl::TrainConfig& t) {
  check_keys(L, idx, "train",
             {"estimator", "episodes", "episodes_per_update", "num_envs", "lr", "lr_final", "gamma",
              "entropy_coef", "entropy_final", "lambda", "epochs", "minibatches", "clip", "grad_clip", "eval_every",
              "eval_episodes", "seed", "branch_fraction"});
  t.estimator = field_string(L, idx, "estimator", t.estimator);
  t.episodes = field_count(L, idx, "episodes", t.episodes, 0, kMaxCount);
  t.episodes_per_update = int_field(L, idx, "episodes_per_update", t.episodes_per_update);
  t.num_envs = int_field(L, idx, "num_envs", t.num_envs);
  t.lr = field_number(L, idx, "lr", t.lr);
  t.lr_final = field_number(L, idx, "lr_final", t.lr);
  t.gamma = field_number(L, idx, "gamma", t.gamma);
  t.entropy_coef = field_number(L, idx, "entropy_coef", t.entropy_coef);
  if (const double ef = field_number(L, idx, "entropy_final", std::nan("")); !std::isnan(ef)) t.entropy_final = ef;
  t.lambda = field_number(L, idx, "lambda", t.lambda);
  t.epochs = int_field(L, idx, "epochs", t.epochs);
  t.minibatches = int_field(L, idx, "minibatches", t.minibatches);
  t.clip = field_number(L, idx, "clip", t.clip);
  t.branch_fraction = field_number(L, idx, "branch_fraction", t.branch_fraction);
  t.grad_clip = field_number(L, idx, "grad_clip", t.grad_clip);
  t.eval_every = field_count(L, idx, "eval_every", t.eval_every, 0, kMaxCount);
  t.eval_episodes = field_count(L, idx, "eval_episodes", t.eval_episodes, 0, kMaxCount);
  t.seed = static_cast<uint64_t>(field_count(L, idx, "seed", static_cast<long long>(t.seed), 0, kMaxCount));
}

constexpr int kMaxScenarioNesting = 8;

// Wraps the Lua function at idx as a reward; errors go to *status.
std::function<double(const env::StepFacts&)> lua_reward(lua_State* L, int idx, std::shared_ptr<Vm> vm,
                                                         std::shared_ptr<Status> status) {
  lua_pushvalue(L, idx);
  const int ref = luaL_ref(L, LUA_REGISTRYINDEX);
  return [vm, status, ref](const env::StepFacts& f) -> double {
    lua_State* S = vm->state();
    const int top = lua_gettop(S);
    lua_rawgeti(S, LUA_REGISTRYINDEX, ref);
    push_fields(S, fields::kStepFacts, f);
    double r = 0.0;
    if (Status st = vm->pcall(1, 1); !st.is_ok()) {
      if (status->is_ok()) *status = Status::invalid("reward function: " + st.message());
    } else if (lua_type(S, -1) != LUA_TNUMBER) {
      if (status->is_ok())
        *status = Status::invalid(std::string("reward function returned ") + luaL_typename(S, -1) +
                                  ", expected a number");
    } else {
      r = lua_tonumber(S, -1);
    }
    lua_settop(S, top);
    return r;
  };
}

void read_scenario(lua_State* L, int top, Scenario& s) {
  const bool env_file = push_table_field(L, top, "declaration");
  if (!env_file)
    check_keys(L, top, "scenario",
               {"rules", "env", "eval", "reward", "policy", "train", "name", "description"});
  env::HorizontalCrConfig& c = s.train_env;
  s.reward_status = std::make_shared<Status>();
  s.lua_reward =
      read_environment_fields(L, env_file ? lua_gettop(L) : top, c, s.vm, s.reward_status);
  if (c.rules == env::Rules::kGym) s.policy.head = "gaussian";
  if (env_file) {
    lua_pop(L, 1);
    s.eval_env = c;
    return;
  }
  if (push_table_field(L, top, "policy")) {
    read_policy(L, -1, c, s.policy);
    lua_pop(L, 1);
  }
  if (push_table_field(L, top, "train")) {
    read_train(L, -1, s.train);
    lua_pop(L, 1);
  }
  s.eval_env = c;
  if (push_table_field(L, top, "eval")) {
    std::set<std::string> keys = kEnvKeys;
    keys.insert({"episodes", "seed"});
    check_keys(L, -1, "eval", keys);
    read_env(L, -1, s.eval_env);
    s.eval_episodes = field_count(L, -1, "episodes", 1000, 0, kMaxCount);
    s.eval_seed = static_cast<uint64_t>(field_count(L, -1, "seed", 0, 0, kMaxCount));
    lua_pop(L, 1);
  }
}

}  // namespace

bool read_environment_fields(lua_State* L, int idx, env::HorizontalCrConfig& c,
                             std::shared_ptr<Vm> vm, std::shared_ptr<Status> reward_status) {
  idx = lua_absindex(L, idx);
  const std::string rules = field_string(L, idx, "rules", "paper");
  if (rules == "gym") {
    c.rules = env::Rules::kGym;
  } else if (rules == "paper") {
    c.rules = env::Rules::kPaper;
  } else {
    throw ArgError("scenario field 'rules' is '" + rules + "': expected \"paper\" or \"gym\"");
  }
  if (push_table_field(L, idx, "env")) {
    check_keys(L, -1, "env", kEnvKeys);
    read_env(L, -1, c);
    lua_pop(L, 1);
  }
  bool lua_function = false;
  get_field(L, idx, "reward");
  if (lua_isfunction(L, -1)) {
    c.reward_fn = lua_reward(L, -1, std::move(vm), std::move(reward_status));
    lua_function = true;
  } else if (lua_istable(L, -1)) {
    read_weights(L, -1, c.weights);
  } else if (!lua_isnil(L, -1)) {
    throw ArgError(
        std::string("scenario field 'reward': expected a table of weights or a function, got ") +
        luaL_typename(L, -1));
  }
  lua_pop(L, 1);
  return lua_function;
}

Result<Scenario> load_scenario(const std::string& path, const VmOptions& options) {
  if (!files::exists(path)) return Status::not_found("no scenario file '" + path + "'");
  // A scenario file may itself load scenarios (squawk.env.new), each in a new
  // Vm on this thread's C stack: the nesting is capped.
  static thread_local int depth = 0;
  if (depth >= kMaxScenarioNesting)
    return Status::invalid("scenario " + path + ": more than " + std::to_string(kMaxScenarioNesting) +
                           " scenario files loading each other (does it load itself?)");
  ++depth;
  struct Leave {
    ~Leave() { --depth; }
  } leave;
  Scenario s;
  s.path = path;
  VmOptions own = options;  // the scenario may read and require files beside it
  own.read_dirs.push_back(paths::dirname(path));
  own.require_dirs.push_back(paths::dirname(path));
  s.vm = std::make_shared<Vm>(std::move(own));
  lua_State* L = s.vm->state();
  const int base = lua_gettop(L);
  if (luaL_loadfilex(L, path.c_str(), "t") != LUA_OK) {
    std::string msg = lua_tostring(L, -1);
    lua_settop(L, base);
    return Status::invalid(msg);
  }
  if (Status st = s.vm->pcall(0, 1); !st.is_ok()) {
    lua_settop(L, base);
    return Status::invalid(st.message());
  }
  if (!lua_istable(L, -1)) {
    std::string t = luaL_typename(L, -1);
    lua_settop(L, base);
    return Status::invalid("scenario " + path + " returned " + t + ", expected a table of parameters");
  }
  std::string error;
  try {
    read_scenario(L, lua_gettop(L), s);
  } catch (const std::exception& e) {
    error = e.what();
  }
  lua_settop(L, base);
  if (!error.empty()) return Status::invalid("scenario " + path + ": " + error);
  SQUAWK_RETURN_IF_ERROR(s.train_env.validate().with_context("scenario " + path));
  SQUAWK_RETURN_IF_ERROR(s.eval_env.validate().with_context("scenario " + path + " (eval)"));
  SQUAWK_RETURN_IF_ERROR(s.policy.validate().with_context("scenario " + path));
  SQUAWK_RETURN_IF_ERROR(s.train.validate().with_context("scenario " + path));
  if (s.eval_episodes < 1) return Status::invalid("scenario " + path + ": eval episodes must be >= 1");
  if (!s.lua_reward) s.vm.reset();
  return s;
}

}  // namespace squawk::script
