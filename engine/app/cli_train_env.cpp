// squawk train --env ENV.lua --out DIR: the MLP learner on an environment
// written in Lua (script/lua_batch_env.h), with the Box action discretised
// into --levels K values per component and a categorical head over the K^d
// grid classes. A multi-agent file (parallel = true) trains one MLP shared
// by all its agents (script/lua_parallel_batch_env.h): each agent's
// trajectory is an episode for the learner. --imitate POLICY.lua first clones
// a scripted rule (rl/imitation.h, script/lua_teacher.h) and fits the value
// baseline to its returns; the learner then fine-tunes the clone.
#include "app/cli_train_env.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "app/cli.h"
#include "app/interrupt.h"
#include "app/learner_flags.h"
#include "app/progress_bar.h"
#include "app/subcommands.h"
#include "app/train_init.h"
#include "app/train_log.h"
#include "app/update_log.h"
#include "app/vm_options.h"
#include "core/files.h"
#include "core/text.h"
#include "dist/comm.h"
#include "rl/checkpoint.h"
#include "rl/imitation.h"
#include "rl/mlp_policy.h"
#include "rl/obs_norm.h"
#include "rl/play.h"
#include "rl/train_run.h"
#include "script/lua_batch_env.h"
#include "script/lua_parallel_batch_env.h"
#include "script/lua_teacher.h"

namespace squawk::app {

namespace {

// The training defaults for Lua environments (flags override each).
rl::TrainConfig lua_train_defaults() {
  rl::TrainConfig c;
  c.episodes = 2000;
  c.episodes_per_update = 16;
  c.num_envs = 8;
  c.lr = c.lr_final = 3e-3;
  c.eval_every = 500;
  c.eval_episodes = 50;
  return c;
}

// `flag` N[,N...] (else `fallback`): integers in 1..4096, each one `what` ("width", "count").
Result<std::vector<int>> int_list(const Args& args, const char* flag, const char* fallback,
                                  const char* what) {
  std::vector<int> out;
  const std::string given = args.get_or(flag, fallback);
  for (const std::string& part : text::split(given, ',')) {
    char* end = nullptr;
    const long n = std::strtol(part.c_str(), &end, 10);
    if (part.empty() || *end != '\0' || n < 1 || n > 4096)
      return Status::invalid(std::string(flag) + " " + given + ": '" + part + "' is not a " + what +
                             " in 1..4096");
    out.push_back(static_cast<int>(n));
  }
  return out;
}

// The training and evaluation batches of `file`, its declaration and the grid's classes.
struct Batches {
  std::unique_ptr<env::BatchEnv> train, eval;
  script::LuaEnvSpec spec;
  int classes = 0;
  script::LuaParallelBatchEnv* parallel = nullptr;  // train, when the file is multi-agent
};

Result<Batches> make_batches(const std::string& file, const script::VmOptions& vo, int num_envs,
                             int levels, const std::vector<int>* agents) {
  Batches b;
  if (agents) {
    SQUAWK_ASSIGN_OR_RETURN(auto t,
                            script::LuaParallelBatchEnv::make(file, vo, num_envs, levels, *agents));
    SQUAWK_ASSIGN_OR_RETURN(auto e,
                            script::LuaParallelBatchEnv::make(file, vo, num_envs, levels, *agents));
    b.spec = t->spec();
    b.classes = t->classes();
    b.parallel = t.get();
    b.train = std::move(t);
    b.eval = std::move(e);
  } else {
    SQUAWK_ASSIGN_OR_RETURN(auto t, script::LuaBatchEnv::make(file, vo, num_envs, levels));
    SQUAWK_ASSIGN_OR_RETURN(auto e, script::LuaBatchEnv::make(file, vo, num_envs, levels));
    b.spec = t->spec();
    b.classes = t->classes();
    b.train = std::move(t);
    b.eval = std::move(e);
  }
  return b;
}

Status save(const std::string& path, const rl::MlpPolicySpec& spec, rl::Policy& policy,
            const rl::TrainProgress& progress, rl::Trainer* trainer) {
  rl::Checkpoint c;
  c.spec = spec;
  if (trainer) {
    trainer->save(c);
  } else {
    c.params.assign(policy.params().begin(), policy.params().end());
  }
  c.progress = progress;
  return rl::save_checkpoint(path, c);
}

// The imitation settings of --imitate-episodes, --imitate-rounds, --imitate-epochs and
// --imitate-lr (Adam), training episodes of seed + kImitateSeedOffset, held out: the validation
// seed.
constexpr uint64_t kImitateSeedOffset = 7919;

Result<rl::ImitationConfig> imitation_config(const Args& args, const rl::TrainConfig& cfg,
                                             uint64_t validation) {
  rl::ImitationConfig ic;
  SQUAWK_ASSIGN_OR_RETURN(ic.episodes, args.get_int("--imitate-episodes", 2000));
  SQUAWK_ASSIGN_OR_RETURN(const long long rounds, args.get_int("--imitate-rounds", 2));
  SQUAWK_ASSIGN_OR_RETURN(const long long epochs, args.get_int("--imitate-epochs", 8));
  if (ic.episodes < 1 || rounds < 1 || rounds > 100 || epochs < 1 || epochs > 1000)
    return Status::invalid(
        "--imitate-episodes must be >= 1, --imitate-rounds 1..100 and --imitate-epochs 1..1000");
  ic.rounds = static_cast<int>(rounds);
  ic.epochs = static_cast<int>(epochs);
  SQUAWK_ASSIGN_OR_RETURN(const double lr, args.get_double("--imitate-lr", 1e-3));
  if (!(lr > 0.0 && lr < 1.0)) return Status::invalid("--imitate-lr must lie in (0, 1)");
  ic.lr = static_cast<float>(lr);
  ic.seed = cfg.seed + kImitateSeedOffset;
  ic.holdout = std::min<long long>(cfg.eval_episodes, 200);
  ic.holdout_seed = validation;
  SQUAWK_ASSIGN_OR_RETURN(const double saturate, args.get_double("--imitate-saturate", 1.0));
  if (!(saturate >= 1.0 && saturate <= 3.0))
    return Status::invalid("--imitate-saturate must lie in [1, 3]");
  ic.saturated_label = static_cast<float>(saturate);
  return ic;
}

// Clones `teacher` (the rule of `teacher_file`) into `policy` on `envs`, saves the clone as
// `cloned_path` and fits the trainer's value baseline (when it has one) to the teacher's returns.
Status imitate_rule(const std::string& teacher_file, rl::Policy& teacher, env::BatchEnv& envs,
                    const rl::ImitationConfig& ic, const rl::MlpPolicySpec& spec,
                    rl::MlpPolicy& policy, rl::Trainer& trainer, const std::string& cloned_path,
                    bool quiet) {
  rl::TeacherFlights flights;
  SQUAWK_RETURN_IF_ERROR(rl::imitate(
      policy, teacher, envs, ic,
      [&](const rl::ImitationEpoch& e) {
        if (!quiet)
          std::printf(
              "imitate %s: round %d (%s flew), epoch %d: %lld decisions, held-out agreement "
              "%.3f, mean |action difference| %.4f\n",
              teacher_file.c_str(), e.round, e.teacher_flew ? "teacher" : "student", e.epoch,
              e.decisions, e.agreement, e.action_error);
        return Status::ok();
      },
      &flights));
  SQUAWK_RETURN_IF_ERROR(save(cloned_path, spec, policy, {}, nullptr));
  return fit_value(trainer, flights, ic, "the teacher's", quiet);
}

}  // namespace

int cmd_train_env(const Args& args) {
  const std::string file = *args.get("--env");
  if (!args.positional().empty())
    return usage_error("train",
                       "--env " + file + " names the environment: no SCENARIO.lua besides it");
  if (args.get_or("--policy", "mlp") != "mlp")
    return usage_error("train",
                       "--env trains --policy mlp only, got '" + args.get_or("--policy", "") + "'");
  if (args.has("--resume") || args.has("--mirror"))
    return usage_error("train", std::string("--env does not take ") +
                                    (args.has("--resume") ? "--resume" : "--mirror"));
  if (!args.has("--out")) return usage_error("train", "missing --out DIR");
  if (!files::exists(file)) return failure(Status::not_found("no environment file '" + file + "'"));
  auto vo = vm_options(args);
  if (!vo) return usage_error("train", vo.status().message());
  vo->out_dir.clear();  // environments write nothing
  auto parallel = script::is_parallel_env(file, *vo);
  if (!parallel) return failure(Status::invalid(shown_error(parallel.status().message())));
  if (args.has("--agents") && !*parallel)
    return usage_error(
        "train", "--agents sets the agents of a multi-agent file; " + file + " is single-agent");
  // --agents: the num_agents a multi-agent file's sector episodes draw from
  auto agents = int_list(args, "--agents", "10", "count");
  if (!agents) return usage_error("train", agents.status().message());
  // [-] learner episodes per sector episode: agent trajectories (1 for a single-agent file)
  const int per_sector = *parallel ? *std::max_element(agents->begin(), agents->end()) : 1;
  rl::TrainConfig cfg = lua_train_defaults();
  cfg.episodes *= per_sector;
  cfg.episodes_per_update *= per_sector;
  cfg.eval_every *= per_sector;
  cfg.eval_episodes *= per_sector;
  if (Status st = apply_learner_flags(args, cfg.episodes, cfg.lr, cfg); !st.is_ok())
    return usage_error("train", st.message());
  for (const auto& [flag, n] :
       {std::pair{"--episodes-per-update", static_cast<long long>(cfg.episodes_per_update)},
        std::pair{"--eval-episodes", cfg.eval_episodes}})
    if (n % per_sector != 0)
      return usage_error("train", std::string(flag) + " " + std::to_string(n) +
                                      ": the learner's episodes are agent trajectories, " +
                                      std::to_string(per_sector) +
                                      " per sector episode (--agents): give a multiple of " +
                                      std::to_string(per_sector));
  if (cfg.estimator == "vine")
    return usage_error("train",
                       "--estimator vine branches the compiled HorizontalCR kernel; on --env use "
                       "\"improved\", \"ppo\" or \"vpg\"");
  const bool gaussian = args.has("--gaussian");
  if (gaussian && *parallel)
    return usage_error("train",
                       "--gaussian trains single-agent files; " + file + " is multi-agent");
  if (gaussian && args.has("--levels"))
    return usage_error("train",
                       "--gaussian acts on the continuous Box: no --levels grid beside it");
  auto levels = args.get_int("--levels", gaussian ? 0 : 5);
  if (!levels) return usage_error("train", levels.status().message());
  if (!gaussian && *levels < 2)
    return usage_error("train", "--levels " + std::to_string(*levels) +
                                    ": expected at least 2 per component (--gaussian for a "
                                    "continuous action)");
  const bool imitate = args.has("--imitate");
  if (imitate && *parallel)
    return usage_error("train",
                       "--imitate clones a single-agent rule; " + file + " is multi-agent");
  if (imitate && dist::size() > 1)
    return usage_error("train", "--imitate runs in a job of one rank");
  if (!imitate)
    for (const char* f :
         {"--imitate-episodes", "--imitate-rounds", "--imitate-epochs", "--imitate-lr",
          "--imitate-means", "--imitate-permute", "--imitate-saturate"})
      if (args.has(f))
        return usage_error("train", std::string(f) + " sets --imitate POLICY.lua's cloning");
  auto hidden = int_list(args, "--hidden", "64,64", "width");  // the policy's hidden widths
  if (!hidden) return usage_error("train", hidden.status().message());
  auto validation = validation_seed(args, 0);
  if (!validation) return usage_error("train", validation.status().message());
  auto ic = imitation_config(args, cfg, *validation);
  if (!ic) return usage_error("train", ic.status().message());

  auto batches = make_batches(file, *vo, cfg.num_envs, static_cast<int>(*levels),
                              *parallel ? &*agents : nullptr);
  if (!batches) return failure(Status::invalid(shown_error(batches.status().message())));
  const script::LuaEnvSpec& es = batches->spec;

  rl::MlpPolicySpec spec;
  spec.obs_size = es.observation_size;
  spec.hidden = *hidden;
  auto log_std = args.get_double("--log-std", spec.init_log_std);
  if (!log_std) return usage_error("train", log_std.status().message());
  if (args.has("--log-std") && (!gaussian || !(*log_std >= -5.0 && *log_std <= 2.0)))
    return usage_error("train",
                       "--log-std " + args.get_or("--log-std", "") +
                           ": the Gaussian head's initial log sigma, in [-5, 2], with --gaussian");
  if (args.has("--imitate-means") && !gaussian)
    return usage_error("train",
                       "--imitate-means holds the Gaussian head's log sigma: add --gaussian");
  if (args.has("--imitate-saturate") && !gaussian)
    return usage_error("train",
                       "--imitate-saturate moves the Gaussian head's labels: add --gaussian");
  // --clone-log-std X: the log sigma the clone is fine-tuned from (cloning learns its own).
  auto clone_log_std = args.get_double("--clone-log-std", 0.0);
  if (!clone_log_std) return usage_error("train", clone_log_std.status().message());
  if (args.has("--clone-log-std") && (!gaussian || !(imitate || args.has("--init")) ||
                                      !(*clone_log_std >= -5.0 && *clone_log_std <= 2.0)))
    return usage_error("train", "--clone-log-std " + args.get_or("--clone-log-std", "") +
                                    ": the cloned Gaussian head's log sigma, in [-5, 2], with "
                                    "--gaussian and --imitate or --init");
  // --imitate-permute COUNT:START,...: the observation's interchangeable slots
  // (rl/slot_permutation.h)
  if (args.has("--imitate-permute")) {
    auto layout = rl::parse_slot_layout(*args.get("--imitate-permute"), es.observation_size);
    if (!layout) return usage_error("train", "--imitate-permute: " + layout.status().message());
    ic->permute = *std::move(layout);
  }
  if (gaussian) {
    spec.head = "gaussian";
    spec.action_size = es.action_size();
    spec.init_log_std = *log_std;
    // --imitate-means: the clone keeps its log sigmas, params()'s tail (rl/mlp_policy.h)
    if (args.has("--imitate-means")) ic->held_tail = static_cast<size_t>(spec.action_size);
  } else {
    spec.action_values = script::grid_values(batches->classes);
  }
  Rng init(cfg.seed);
  auto policy = rl::MlpPolicy::make(spec, init);
  if (!policy) return failure(policy.status());
  // --init CKPT: the run starts from a checkpoint's policy (its spec: widths,
  // head, grid, observation statistics) instead of a fresh network.
  if (args.has("--init")) {
    if (*parallel)
      return usage_error("train", "--init starts single-agent files from a checkpoint; " + file +
                                      " is multi-agent");
    for (const char* f : {"--imitate", "--hidden", "--obs-norm", "--log-std"})
      if (args.has(f))
        return usage_error(
            "train",
            std::string("--init CKPT starts from the checkpoint's policy: no ") + f + " beside it");
    auto start = init_policy(*args.get("--init"), es, spec);
    if (!start) return failure(Status::invalid(shown_error(start.status().message())));
    spec = start->spec;
    policy = std::move(start->policy);
  }
  std::unique_ptr<script::LuaTeacher> teacher;
  if (imitate) {
    // the single-agent training batch is a LuaBatchEnv (make_batches)
    auto t = script::LuaTeacher::load(*args.get("--imitate"), *vo,
                                      static_cast<script::LuaBatchEnv&>(*batches->train));
    if (!t) return failure(Status::invalid(shown_error(t.status().message())));
    teacher = std::move(*t);
  }
  // --obs-norm N: the mean and deviation of each observation number over N
  // episodes of the initial policy, or of the --imitate rule (rl/obs_norm.h);
  // the policy then reads the normalised numbers, from the same initial parameters.
  auto norm_episodes = args.get_int("--obs-norm", 0);
  if (!norm_episodes) return usage_error("train", norm_episodes.status().message());
  if (args.has("--obs-norm")) {
    if (*parallel)
      return usage_error("train",
                         "--obs-norm trains single-agent files; " + file + " is multi-agent");
    auto stats = teacher
                     ? rl::observation_stats(*teacher, *batches->train, cfg.seed, *norm_episodes)
                     : rl::observation_stats(**policy, *batches->eval, cfg.seed, *norm_episodes);
    if (!stats) return failure(Status::invalid(shown_error(stats.status().message())));
    spec.obs_mean = std::move(stats->mean);
    spec.obs_std = std::move(stats->std);
    Rng again(cfg.seed);
    policy = rl::MlpPolicy::make(spec, again);
    if (!policy) return failure(policy.status());
  }

  const std::string out = *args.get("--out");
  auto run = open_run_folder(out, args);
  if (!run) return failure(run.status());
  rl::TrainProgress progress;
  progress.seed = cfg.seed;
  progress.estimator = cfg.estimator;
  progress.scenario = file;
  rl::Trainer trainer(**policy, *batches->train, cfg, 0);
  auto log = TrainLog::open(*run, 0);
  if (!log) return failure(log.status());
  std::optional<UpdateLog> updates;
  if (args.has("--update-log")) {
    auto opened = UpdateLog::open(out + "/updates.csv");
    if (!opened) return failure(opened.status());
    updates = std::move(*opened);
  }
  const bool quiet = args.has("--quiet");
  if (!quiet) {
    char head[96];
    if (gaussian)
      std::snprintf(head, sizeof head, "a Gaussian head over the continuous action (%d components)",
                    es.action_size());
    else
      std::snprintf(head, sizeof head, "%d action classes (%lld levels x %d components)",
                    batches->classes, *levels, es.action_size());
    std::printf("training mlp on %s (%s): %s, %s, estimator %s, %zu parameters, seed %llu%s\n",
                es.id.c_str(), file.c_str(), head, episodes_text(cfg).c_str(),
                cfg.estimator.c_str(), (*policy)->params().size(),
                static_cast<unsigned long long>(cfg.seed),
                spec.obs_mean.empty() ? "" : ", observations normalised");
  }
  if (!quiet && batches->parallel)
    std::printf(
        "one policy shared by every agent: %s agents per sector episode (--agents); an episode "
        "is one agent's trajectory, %d numbered per sector episode\n",
        args.get_or("--agents", "10").c_str(), per_sector);
  const std::string best_path = out + "/best.ckpt", policy_path = out + "/policy.ckpt";
  if (teacher) {
    Status st = imitate_rule(*args.get("--imitate"), *teacher, *batches->train, *ic, spec, **policy,
                             trainer, out + "/cloned.ckpt", quiet);
    if (!st.is_ok()) return failure(Status::invalid(shown_error(st.message())));
  }
  if (args.has("--clone-log-std"))  // the Gaussian log sigmas: the parameters' tail
    std::ranges::fill((*policy)->params().last(static_cast<size_t>(spec.action_size)),
                      static_cast<float>(*clone_log_std));
  if (args.has("--init")) {
    Status st = fit_value_to_policy(**policy, *batches->train, *ic, trainer, quiet);
    if (!st.is_ok()) return failure(Status::invalid(shown_error(st.message())));
  }
  ProgressBar bar("train", cfg.end_episodes(), !quiet);
  double best_reward = 0.0;
  bool have_best = false;
  InterruptGuard interrupt;
  auto ended = rl::run_training(
      trainer, **policy, *batches->eval, cfg, *validation, progress,
      [](long long) { return !InterruptGuard::requested(); },
      [&](const rl::UpdateReport& u) -> Result<bool> {
        log->add(progress, u.stats);
        if (updates) SQUAWK_RETURN_IF_ERROR(updates->add(u.progress.episodes, u.stats));
        char extra[96];
        std::snprintf(extra, sizeof extra, "return %.3f", u.stats.mean_return);
        bar.update(u.progress.episodes, extra);
        if (!u.eval) return true;
        SQUAWK_RETURN_IF_ERROR(log->row(progress, *u.eval));
        SQUAWK_RETURN_IF_ERROR(save(run->checkpoint, spec, **policy, progress, &trainer));
        if (!have_best || u.eval->mean_reward > best_reward) {
          have_best = true;
          best_reward = u.eval->mean_reward;
          SQUAWK_RETURN_IF_ERROR(save(best_path, spec, **policy, progress, nullptr));
        }
        if (!quiet) {
          char line[160];
          std::snprintf(line, sizeof line,
                        "%lld episodes, %.0f s: eval mean reward %.3f (std %.3f), %.1f steps\n",
                        u.progress.episodes, u.progress.wall_s, u.eval->mean_reward,
                        u.eval->std_reward, u.eval->mean_steps);
          bar.note(line);
        }
        return true;
      });
  bar.finish();
  if (!ended) return failure(Status::invalid(shown_error(ended.status().message())));
  if (*ended == rl::RunEnd::kInterrupted) {
    std::printf("interrupted after %lld episodes; %s holds the last evaluated policy\n",
                progress.episodes, run->checkpoint.c_str());
    return kExitInterrupted;
  }
  if (Status s = save(policy_path, spec, **policy, progress, nullptr); !s.is_ok())
    return failure(s);
  if (!quiet)
    std::printf(
        "done: %lld episodes in %s; policy %s (the last), best %s (highest evaluation mean "
        "reward), log %s\n",
        progress.episodes, fmt_duration(progress.wall_s).c_str(), policy_path.c_str(),
        best_path.c_str(), run->log.c_str());
  if (!quiet && batches->parallel)
    std::printf("sector episodes played in training: %lld\n", batches->parallel->sector_episodes());
  return kExitOk;
}

}  // namespace squawk::app
