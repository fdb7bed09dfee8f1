// squawk.env: the conflict-resolution environment and evaluator from Lua.
//
//   local env = squawk.env.new("scenarios/horizontal_cr.lua" [, "train"|"eval"])
//   local env = squawk.env.new{rules =, env = {..}, reward = {..} | function}
//                                          (a declaration: those fields of a
//                                           scenario table, script/scenario.h;
//                                           a reward function runs in this Vm)
//   env:reset(seed) -> needs_decision, reward, truncated
//                                          (episode drawn from Rng(seed); the
//                                           reward and truncation of the
//                                           automatic steps before the first
//                                           decision, paper rules)
//   env:step(action) -> reward, done, truncated
//                                          (action in [-1, 1], units of 45 deg)
//   env:observation() -> {intruder_distance = {..}, ..., sin_drift = {x}}
//                                          (every field an array: the shape
//                                           prompts/observation.lua renders)
//   env:flat([t]) -> {28 numbers}          (the MLP's input order, as the float it
//                                           is given; written into t when given)
//   env:stats() -> {total_reward, decisions, steps, intrusions, reached, truncated, success}
//   env:state() -> {t, own = {lat, lon, hdg, tas}, intruders = {{..}, ..}, waypoint = {lat, lon}}
//   env:mvp_action() -> number
//   squawk.env.evaluate{scenario = path, policy =
//   "zero"|"constant:V"|"turn-hold:V"|"mvp"|"random"|"mlp"|"gpt2",
//                       checkpoint = file, model = "tiny"|dir (gpt2, fresh head), prompt = file,
//                       episodes = n, seed = s, greedy = bool}
//     -> {success_rate, mean_reward, std_reward, episodes, reached_rate,
//         actions = {["-1"] = n, ["-0.5"] = n, ["0"] = n, ["0.5"] = n, ["1"] = n},
//         most_frequent_share}   (policies built by script/policy_factory.h)
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "core/paths.h"
#include "env/horizontal_cr.h"
#include "env/vec_env.h"
#include "rl/evaluator.h"
#include "script/bindings.h"
#include "script/lua_util.h"
#include "script/policy_factory.h"
#include "script/prompt_renderer.h"
#include "script/scenario.h"
#include "script/vm.h"

namespace squawk::script {

namespace {

constexpr const char* kEnvMt = "squawk.Env";

struct EnvBox {
  Scenario scenario;
  std::unique_ptr<env::HorizontalCrEnv> env;
  std::vector<float> flat;  // observation_size floats, reused by flat()
};

}  // namespace

Scenario scenario_or_throw(lua_State* L, const std::string& path) {
  VmOptions vo = Vm::of(L).options();
  vo.out_dir.clear();
  auto sc = load_scenario(path, vo);
  check_status(sc.status());
  return std::move(*sc);
}

namespace {

// The declaration table at index 1 as a scenario whose train and eval
// settings are both the declared ones.
Scenario declared_or_throw(lua_State* L) {
  Scenario sc;
  sc.path = "(declaration)";
  sc.reward_status = std::make_shared<Status>();
  // The reward function lives in this Vm, which outlives every object in it.
  std::shared_ptr<Vm> here(std::shared_ptr<Vm>(), &Vm::of(L));
  sc.lua_reward = read_environment_fields(L, 1, sc.train_env, here, sc.reward_status);
  sc.eval_env = sc.train_env;
  return sc;
}

int l_new(lua_State* L) {
  const bool declared = lua_istable(L, 1);
  std::string which = "eval";
  Scenario sc;
  if (declared) {
    sc = declared_or_throw(L);
  } else {
    const std::string path = readable(L, arg_string(L, 1, "scenario"), "scenario");
    which = opt_string(L, 2, "settings", "eval");
    if (which != "train" && which != "eval")
      throw ArgError("squawk.env.new: settings '" + which + "': expected \"train\" or \"eval\"");
    sc = scenario_or_throw(L, path);
  }
  auto e = env::HorizontalCrEnv::make(which == "train" ? sc.train_env : sc.eval_env);
  check_status(e.status());
  auto envp = std::make_unique<env::HorizontalCrEnv>(std::move(*e));
  EnvBox* box = new_object<EnvBox>(L, kEnvMt);
  box->flat.assign(static_cast<size_t>(envp->observation_size()), 0.0f);
  box->scenario = std::move(sc);
  box->env = std::move(envp);
  return 1;
}

env::HorizontalCrEnv& self(lua_State* L) { return *arg_object<EnvBox>(L, 1, kEnvMt)->env; }

int l_reset(lua_State* L) {
  EnvBox* box = arg_object<EnvBox>(L, 1, kEnvMt);
  env::HorizontalCrEnv& e = *box->env;
  Rng rng(static_cast<uint64_t>(arg_integer(L, 2, "seed")));
  const bool ask = e.reset(rng);
  check_status(box->scenario.reward_error());
  lua_pushboolean(L, ask);
  lua_pushnumber(L, e.stats().total_reward);
  lua_pushboolean(L, e.stats().truncated);
  return 3;
}

int l_step(lua_State* L) {
  EnvBox* box = arg_object<EnvBox>(L, 1, kEnvMt);
  const double r = box->env->step(arg_number(L, 2, "action"));
  check_status(box->scenario.reward_error());
  lua_pushnumber(L, r);
  lua_pushboolean(L, box->env->done());
  lua_pushboolean(L, box->env->stats().truncated);
  return 3;
}

int l_observation(lua_State* L) {
  const env::Observation& o = self(L).observation();
  push_observation(L, o);
  return 1;
}

int l_flat(lua_State* L) {
  EnvBox* box = arg_object<EnvBox>(L, 1, kEnvMt);
  box->env->observe_flat(box->flat);
  if (lua_istable(L, 2)) {
    lua_settop(L, 2);
  } else if (lua_isnoneornil(L, 2)) {
    lua_createtable(L, static_cast<int>(box->flat.size()), 0);
  } else {
    throw ArgError(type_error(L, 2, "t", "a table or nothing"));
  }
  for (size_t k = 0; k < box->flat.size(); ++k) {
    lua_pushnumber(L, static_cast<double>(box->flat[k]));
    lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
  }
  return 1;
}

int l_stats(lua_State* L) {
  const env::EpisodeStats& s = self(L).stats();
  lua_createtable(L, 0, 7);
  set_number(L, "total_reward", s.total_reward);
  set_number(L, "decisions", s.decisions);
  set_number(L, "steps", s.steps);
  set_number(L, "intrusions", s.intrusions);
  lua_pushboolean(L, s.reached);
  lua_setfield(L, -2, "reached");
  lua_pushboolean(L, s.truncated);
  lua_setfield(L, -2, "truncated");
  lua_pushboolean(L, s.success);
  lua_setfield(L, -2, "success");
  return 1;
}

void push_aircraft(lua_State* L, const env::Fleet& f, int i) {
  lua_createtable(L, 0, 4);
  set_number(L, "lat", f.lat(i));
  set_number(L, "lon", f.lon(i));
  set_number(L, "hdg", f.hdg(i));
  set_number(L, "tas", f.tas(i));
}

int l_state(lua_State* L) {
  const env::HorizontalCrEnv& e = self(L);
  const env::Fleet& f = e.fleet();
  lua_createtable(L, 0, 4);
  set_number(L, "t", e.sim_time());
  push_aircraft(L, f, 0);
  lua_setfield(L, -2, "own");
  lua_createtable(L, static_cast<int>(f.size()) - 1, 0);
  for (int i = 1; i < static_cast<int>(f.size()); ++i) {
    push_aircraft(L, f, i);
    lua_seti(L, -2, i);
  }
  lua_setfield(L, -2, "intruders");
  lua_createtable(L, 0, 2);
  set_number(L, "lat", e.waypoint_lat());
  set_number(L, "lon", e.waypoint_lon());
  lua_setfield(L, -2, "waypoint");
  return 1;
}

int l_mvp_action(lua_State* L) {
  lua_pushnumber(L, self(L).mvp_action());
  return 1;
}

constexpr long long kMaxEpisodes = 1'000'000;  // per evaluate call
constexpr long long kEpisodeCost = 10'000;     // [instructions] charged per episode

}  // namespace

int env_evaluate(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  const std::string path = readable(L, field_string(L, 1, "scenario", ""), "scenario");
  if (path.empty()) throw ArgError("squawk.env.evaluate: field 'scenario' (a scenario file) is required");
  const std::string kind = field_string(L, 1, "policy", "mlp");
  Scenario sc = scenario_or_throw(L, path);
  const long long episodes = field_count(L, 1, "episodes", sc.eval_episodes, 1, kMaxEpisodes);
  const auto seed = static_cast<uint64_t>(
      field_count(L, 1, "seed", static_cast<long long>(sc.eval_seed), 0, 9007199254740992LL));
  charge(L, episodes * kEpisodeCost);
  auto envs = env::VecEnv::make(sc.eval_env, 32);
  check_status(envs.status());
  PolicyOptions opts;
  opts.seed = seed;
  opts.checkpoint = readable(L, field_string(L, 1, "checkpoint", ""), "checkpoint");
  opts.gpt2.model = readable_folder(L, field_string(L, 1, "model", ""), "model");
  opts.gpt2_fresh = !opts.gpt2.model.empty();
  if (!opts.gpt2_fresh) opts.gpt2.model = "tiny";
  opts.gpt2.prompt = readable(L, field_string(L, 1, "prompt", ""), "prompt");
  opts.reads = &Vm::of(L).rules();
  VmOptions vo = Vm::of(L).options();
  vo.out_dir.clear();
  auto made = make_policy(kind, sc, *envs, opts, vo);
  if (!made) throw ArgError("squawk.env.evaluate: " + made.status().message());
  rl::Policy* policy = made->policy.get();
  auto res = rl::evaluate(*policy, *envs, {episodes, seed, field_boolean(L, 1, "greedy", false)});
  check_status(res.status());
  check_status(policy->error());
  check_status(sc.reward_error());
  lua_createtable(L, 0, 7);
  set_number(L, "most_frequent_share", res->most_frequent_share());
  set_number(L, "reached_rate", res->reached_rate);
  lua_createtable(L, 0, static_cast<int>(rl::kActionBins.size()));
  for (size_t k = 0; k < rl::kActionBins.size(); ++k) {
    char key[16];
    std::snprintf(key, sizeof key, "%g", rl::kActionBins[k]);
    lua_pushinteger(L, res->action_counts[k]);
    lua_setfield(L, -2, key);
  }
  lua_setfield(L, -2, "actions");
  set_number(L, "success_rate", res->success_rate);
  set_number(L, "mean_reward", res->mean_reward);
  set_number(L, "std_reward", res->std_reward);
  lua_pushinteger(L, res->episodes);
  lua_setfield(L, -2, "episodes");
  return 1;
}

void bind_env(lua_State* L) {
  static const luaL_Reg methods[] = {{"reset", guarded<l_reset>},
                                     {"step", guarded<l_step>},
                                     {"observation", guarded<l_observation>},
                                     {"flat", guarded<l_flat>},
                                     {"stats", guarded<l_stats>},
                                     {"state", guarded<l_state>},
                                     {"mvp_action", guarded<l_mvp_action>},
                                     {nullptr, nullptr}};
  define_class(L, kEnvMt, methods);
  push_squawk_subtable(L, "env");
  lua_pushcfunction(L, guarded<l_new>);
  lua_setfield(L, -2, "new");
  lua_pushcfunction(L, guarded<env_evaluate>);
  lua_setfield(L, -2, "evaluate");
  lua_pop(L, 1);
}

}  // namespace squawk::script
