// squawk.rl: the policy-gradient learner and the evaluator from Lua, over the
// same code as `squawk train` and `squawk eval` (rl/train_run.h, rl/evaluator.h).
//
//   squawk.rl.train{scenario = path, policy = "mlp"|"gpt2", on_update = function(u) ... end, ...}
//     -> {ended = "finished"|"stopped", episodes, updates, wall_s, eval = {..} | nil,
//         precision (gpt2: the GEMM precision line)}
//   keys, each as the `squawk train` flag of the same name (absent: the
//   scenario's train table; gpt2: episodes 20000, lr 1e-5 on a folder):
//     seed, episodes, stop_at, estimator, envs, episodes_per_update, lr, lr_final,
//     gamma, lambda, entropy, entropy_final, epochs, minibatches, clip,
//     value_iters, branch_fraction, eval_every, eval_episodes, validation_seed, mirror
//   gpt2: model ("tiny" | folder), model_seed, prompt, blocks, chunk, head, train_embeddings,
//     precision ("bf16" | "fp32"; absent: the fastest here, as the command line)
//   init = checkpoint     start from its policy and learner state, counters at 0 (--init)
//   resume = checkpoint   go on from it, counters and schedules included (--resume)
//   save = checkpoint     written at the run's end (policy and learner state; needs --out)
//   on_update(u) after every update: u = {update, episodes, samples, mean_return,
//     success_rate, entropy, grad_norm, value_loss, update_s, wall_s, eval}, eval
//     the validation figures {success_rate, mean_reward, std_reward, episodes,
//     reached_rate, most_frequent_share} on evaluation updates, else nil;
//     returning false ends the run ("stopped").
//   squawk.rl.evaluate{...} (also squawk.env.evaluate): one evaluation, bind_env.cpp's keys.
#include <optional>
#include <string>

#include "core/paths.h"
#include "env/vec_env.h"
#include "nn/gemm.h"
#include "rl/evaluator.h"
#include "rl/train_run.h"
#include "script/bindings.h"
#include "script/learner.h"
#include "script/lua_util.h"
#include "script/scenario.h"
#include "script/vm.h"

namespace squawk::script {

namespace {

constexpr long long kEpisodeCost = 10'000;  // [instructions] charged per training episode
constexpr long long kMaxInteger =
    9007199254740992LL;  // 2^53: the largest a Lua number holds exactly

std::optional<double> opt_field(lua_State* L, const char* key) {
  get_field(L, 1, key);
  const bool given = !lua_isnil(L, -1);
  lua_pop(L, 1);
  if (!given) return std::nullopt;
  return field_number(L, 1, key, 0.0);
}

// The learner keys over `cfg` (the scenario's train table), by the rules of
// apply_learner_flags (app/learner_flags.h).
void apply_learner_keys(lua_State* L, rl::TrainConfig& cfg, long long episodes_default,
                        double lr_default) {
  auto count = [&](const char* key, long long fallback, long long lo, long long hi) {
    return field_count(L, 1, key, fallback, lo, hi);
  };
  cfg.seed = static_cast<uint64_t>(count("seed", static_cast<long long>(cfg.seed), 0, kMaxInteger));
  cfg.episodes = count("episodes", episodes_default, 1, kMaxInteger);
  cfg.stop_at = count("stop_at", 0, 0, cfg.episodes);
  cfg.estimator = field_string(L, 1, "estimator", cfg.estimator);
  cfg.num_envs = static_cast<int>(count("envs", cfg.num_envs, 1, 4096));
  cfg.episodes_per_update =
      static_cast<int>(count("episodes_per_update", cfg.episodes_per_update, 1, 1 << 20));
  cfg.set_lr(field_number(L, 1, "lr", lr_default), opt_field(L, "lr_final"));
  cfg.gamma = field_number(L, 1, "gamma", cfg.gamma);
  cfg.lambda = field_number(L, 1, "lambda", cfg.lambda);
  cfg.entropy_coef = field_number(L, 1, "entropy", cfg.entropy_coef);
  if (auto f = opt_field(L, "entropy_final")) cfg.entropy_final = *f;
  cfg.epochs = static_cast<int>(count("epochs", cfg.epochs, 1, 100));
  cfg.minibatches = static_cast<int>(count("minibatches", cfg.minibatches, 1, 1024));
  cfg.clip = field_number(L, 1, "clip", cfg.clip);
  cfg.value_iters = static_cast<int>(count("value_iters", cfg.value_iters, 0, 1 << 20));
  cfg.branch_fraction = field_number(L, 1, "branch_fraction", cfg.branch_fraction);
  cfg.eval_every = count("eval_every", cfg.eval_every, 0, kMaxInteger);
  cfg.eval_episodes = count("eval_episodes", cfg.eval_episodes, 1, 1'000'000);
  check_status(cfg.validate());
}

// The learner of the table's policy keys (script/learner.h).
Learner learner_of(lua_State* L, const std::string& kind, Scenario& sc, uint64_t seed,
                   const std::string& from, bool resume) {
  VmOptions vo = Vm::of(L).options();
  vo.out_dir.clear();
  LearnerOptions o;
  o.kind = kind;
  o.mirror = field_boolean(L, 1, "mirror", false);
  o.from = from;
  o.resume = resume;
  o.seed = seed;
  o.reads = &Vm::of(L).rules();
  o.gpt2.model = field_string(L, 1, "model", "tiny");
  if (o.gpt2.model != "tiny") o.gpt2.model = readable_folder(L, o.gpt2.model, "model");
  o.gpt2.model_seed = static_cast<uint64_t>(field_count(L, 1, "model_seed", 0, 0, kMaxInteger));
  o.gpt2.prompt = readable(L, field_string(L, 1, "prompt", ""), "prompt");
  o.gpt2.spec.head = field_string(L, 1, "head", "action");
  o.gpt2.spec.trainable_blocks = static_cast<int>(field_count(L, 1, "blocks", -1, -1, 1024));
  o.gpt2.spec.chunk_rows =
      static_cast<int>(field_count(L, 1, "chunk", o.gpt2.spec.chunk_rows, 1, 1 << 20));
  o.gpt2.spec.train_embeddings = field_boolean(L, 1, "train_embeddings", false);
  auto l = make_learner(o, sc, vo);
  if (!l) throw ArgError("squawk.rl.train: " + l.status().message());
  return std::move(*l);
}

// GPT-2's matrix products as the command line sets them: `precision`, absent
// the fastest here (nn::use_precision). Returns the line that says which.
std::string apply_precision(lua_State* L) {
  std::optional<nn::Precision> want;
  if (const std::string p = field_string(L, 1, "precision", ""); !p.empty()) {
    auto got = nn::parse_precision(p);
    check_status(got.status());
    want = *got;
  }
  return nn::use_precision(want);
}

void push_eval(lua_State* L, const rl::EvalResult& e) {
  lua_createtable(L, 0, 6);
  set_number(L, "success_rate", e.success_rate);
  set_number(L, "mean_reward", e.mean_reward);
  set_number(L, "std_reward", e.std_reward);
  set_integer(L, "episodes", e.episodes);
  set_number(L, "reached_rate", e.reached_rate);
  set_number(L, "most_frequent_share", e.most_frequent_share());
}

void push_update(lua_State* L, const rl::UpdateReport& u) {
  lua_createtable(L, 0, 11);
  set_integer(L, "update", u.progress.updates);
  set_integer(L, "episodes", u.progress.episodes);
  set_integer(L, "samples", u.stats.samples);
  set_number(L, "mean_return", u.stats.mean_return);
  set_number(L, "success_rate", u.stats.success_rate);
  set_number(L, "entropy", u.stats.entropy);
  set_number(L, "grad_norm", u.stats.grad_norm);
  set_number(L, "value_loss", u.stats.value_loss);
  set_number(L, "update_s", u.update_s);
  set_number(L, "wall_s", u.progress.wall_s);
  if (u.eval) {
    push_eval(L, *u.eval);
    lua_setfield(L, -2, "eval");
  }
}

int l_train(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  const std::string path = readable(L, field_string(L, 1, "scenario", ""), "scenario");
  if (path.empty())
    throw ArgError("squawk.rl.train: field 'scenario' (a scenario file) is required");
  const std::string kind = field_string(L, 1, "policy", "mlp");
  Scenario sc = scenario_or_throw(L, path);
  rl::TrainConfig cfg = sc.train;
  const bool gpt2 = kind == "gpt2";
  const bool folder = gpt2 && field_string(L, 1, "model", "tiny") != "tiny";
  apply_learner_keys(L, cfg, gpt2 ? kGpt2TrainEpisodes : cfg.episodes,
                     folder ? kGpt2FolderLr : cfg.lr);
  const auto validation = static_cast<uint64_t>(field_count(
      L, 1, "validation_seed", static_cast<long long>(sc.eval_seed + 1000003), 0, kMaxInteger));
  const std::string init = readable(L, field_string(L, 1, "init", ""), "init");
  const std::string resume = readable(L, field_string(L, 1, "resume", ""), "resume");
  if (!init.empty() && !resume.empty())
    throw ArgError("squawk.rl.train: give 'init' or 'resume', not both");
  const std::string save = field_string(L, 1, "save", "");
  if (!save.empty()) check_status(Vm::of(L).rules().check_write(save, "squawk.rl.train save"));
  get_field(L, 1, "on_update");
  const int on_update = lua_gettop(L);
  if (!lua_isnil(L, on_update) && !lua_isfunction(L, on_update))
    throw ArgError(type_error(L, on_update, "on_update", "a function"));
  const std::string precision = gpt2 ? apply_precision(L) : "";
  Learner l = learner_of(L, kind, sc, cfg.seed, resume.empty() ? init : resume, !resume.empty());
  rl::TrainProgress& progress = l.progress();
  progress.estimator = cfg.estimator;
  progress.scenario = sc.path;
  check_status(rl::check_learner(*l.policy, cfg));
  check_status(rl::check_obs_size(*l.policy, env::observation_size(sc.train_env.num_intruders)));
  charge(L, (cfg.end_episodes() - progress.episodes) * kEpisodeCost);
  auto train_envs = env::VecEnv::make(sc.train_env, cfg.num_envs);
  auto eval_envs = env::VecEnv::make(sc.eval_env, cfg.num_envs);
  check_status(train_envs.status());
  check_status(eval_envs.status());
  rl::Trainer trainer(*l.policy, *train_envs, cfg, progress.updates);
  if (l.restore) check_status(trainer.restore(*l.restore));
  std::optional<rl::EvalResult> last_eval;
  auto ended = rl::run_training(trainer, *l.policy, *eval_envs, cfg, validation, progress, {},
                                [&](const rl::UpdateReport& u) -> Result<bool> {
                                  SQUAWK_RETURN_IF_ERROR(sc.reward_error());
                                  if (u.eval) last_eval = *u.eval;
                                  if (lua_isnil(L, on_update)) return true;
                                  lua_pushvalue(L, on_update);
                                  push_update(L, u);
                                  if (lua_pcall(L, 1, 1, 0) != LUA_OK) {
                                    const std::string msg = "on_update: " + error_text(L, -1);
                                    lua_pop(L, 1);
                                    return Status::invalid(msg);
                                  }
                                  const bool stop = lua_isboolean(L, -1) && !lua_toboolean(L, -1);
                                  lua_pop(L, 1);
                                  return !stop;
                                });
  check_status(ended.status());
  if (!save.empty()) check_status(l.save(save, &trainer));
  lua_createtable(L, 0, 5);
  set_string(L, "ended", *ended == rl::RunEnd::kFinished ? "finished" : "stopped");
  set_integer(L, "episodes", progress.episodes);
  set_integer(L, "updates", progress.updates);
  set_number(L, "wall_s", progress.wall_s);
  if (gpt2) set_string(L, "precision", precision);
  if (last_eval) {
    push_eval(L, *last_eval);
    lua_setfield(L, -2, "eval");
  }
  return 1;
}

}  // namespace

void bind_rl(lua_State* L) {
  push_squawk_subtable(L, "rl");
  lua_pushcfunction(L, guarded<l_train>);
  lua_setfield(L, -2, "train");
  lua_pushcfunction(L, guarded<env_evaluate>);
  lua_setfield(L, -2, "evaluate");
  lua_pop(L, 1);
}

}  // namespace squawk::script
