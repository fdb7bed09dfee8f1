// squawk train / squawk eval: the conflict-resolution learner and evaluator.
#include <cstdio>
#include <memory>

#include "app/cli.h"
#include "app/cli_train_env.h"
#include "app/gpt2_policy_factory.h"
#include "app/interrupt.h"
#include "app/learner_flags.h"
#include "app/out_guard.h"
#include "app/progress_bar.h"
#include "app/rl_eval.h"
#include "app/subcommands.h"
#include "app/train_log.h"
#include "app/vm_options.h"
#include "core/paths.h"
#include "dist/comm.h"
#include "env/recorder.h"
#include "env/vec_env.h"
#include "rl/baseline_policies.h"
#include "rl/checkpoint.h"
#include "rl/train_run.h"
#include "script/learner.h"
#include "script/scenario.h"

namespace squawk::app {

namespace {

// Rank 0 alone writes checkpoints (dist/comm.h); the other ranks hold the same state.
Status save_on_rank0(script::Learner& l, const std::string& path, rl::Trainer* trainer) {
  return dist::rank() == 0 ? l.save(path, trainer) : Status::ok();
}

}  // namespace

int cmd_train(const ArgV& given) {
  auto argv = resolve_train_argv(given, train_flags(true));
  if (!argv) return usage_error("train", argv.status().message());
  if (auto probe = Args::parse(*argv, train_flags(true)); probe) {
    if (probe->has("--env") && wants_gpt2(*argv))
      return usage_error("train", "--env trains --policy mlp only");
    if (!probe->has("--env") &&
        (probe->has("--levels") || probe->has("--hidden") || probe->has("--gaussian")))
      return usage_error(
          "train", "--levels, --gaussian and --hidden shape the policy of a --env ENV.lua run");
    if (!probe->has("--env") && (probe->has("--obs-norm") || probe->has("--log-std")))
      return usage_error("train",
                         "--obs-norm and --log-std shape the policy of a --env ENV.lua run");
    if (!probe->has("--env") && probe->has("--imitate"))
      return usage_error("train", "--imitate POLICY.lua clones a rule of a --env ENV.lua run");
    if (!probe->has("--env") && probe->has("--update-log"))
      return usage_error("train", "--update-log writes the updates of a --env ENV.lua run");
    if (!probe->has("--env") && probe->has("--agents"))
      return usage_error("train", "--agents sets the agents of a multi-agent --env ENV.lua run");
  }
  if (wants_gpt2(*argv)) return cmd_train_gpt2(*argv);
  auto args = Args::parse(*argv, train_flags(false));
  if (!args) return usage_error("train", args.status().message());
  if (args->has("--env")) return cmd_train_env(*args);
  if (args->has("--init"))
    return usage_error("train", "--init CKPT starts a --env ENV.lua or a --policy gpt2 run");
  if (args->get_or("--policy", "mlp") != "mlp")
    return usage_error("train", "--policy: only 'mlp' trains here, got '" + args->get_or("--policy", "") + "'");
  if (!args->has("--out")) return usage_error("train", "missing --out DIR");
  if (args->positional().size() != 1) return usage_error("train", "expected exactly one SCENARIO.lua");
  script::VmOptions vo;
  script::Scenario sc;
  if (int rc = load_episode_scenario(*args, "train", vo, sc); rc != kExitOk) return rc;
  rl::TrainConfig cfg = sc.train;
  if (Status st = apply_learner_flags(*args, cfg.episodes, cfg.lr, cfg); !st.is_ok())
    return usage_error("train", st.message());
  if (Status st = apply_mirror_flag(*args, sc.train_env, sc.policy.mirror); !st.is_ok())
    return usage_error("train", "--mirror: " + st.message());
  auto validation = validation_seed(*args, sc.eval_seed);
  if (!validation) return usage_error("train", validation.status().message());

  const std::string out = *args->get("--out");
  auto run = open_run_folder(out, *args);
  if (!run) return failure(run.status());
  const std::string best_path = out + "/best.ckpt";

  script::LearnerOptions lo;
  lo.from = run->resuming ? run->checkpoint : "";
  lo.resume = run->resuming;
  lo.seed = cfg.seed;
  auto learner = script::make_learner(lo, sc, vo);
  if (!learner) return failure(learner.status());
  rl::Policy* policy = learner->policy.get();
  rl::TrainProgress& progress = learner->progress();
  if (run->resuming) {
    if (Status st = check_resume_seed(*run, progress.seed, cfg.seed); !st.is_ok())
      return failure(st);
    if (Status st = check_resume_mirror(run->checkpoint, learner->mirror(), sc.policy.mirror);
        !st.is_ok())
      return failure(st);
  }
  progress.estimator = cfg.estimator;
  progress.scenario = sc.path;
  if (Status st = rl::check_learner(*policy, cfg); !st.is_ok()) return usage_error("train", st.message());
  if (Status st = rl::check_obs_size(*policy, env::observation_size(sc.train_env.num_intruders)); !st.is_ok())
    return failure(st);

  auto train_envs = env::VecEnv::make(sc.train_env, cfg.num_envs);
  auto eval_envs = env::VecEnv::make(sc.eval_env, cfg.num_envs);
  if (!train_envs) return failure(train_envs.status());
  if (!eval_envs) return failure(eval_envs.status());
  const long long m = cfg.episodes_per_update;
  rl::Trainer trainer(*policy, *train_envs, cfg, progress.episodes / m);
  if (learner->restore) {
    if (Status st = trainer.restore(*learner->restore); !st.is_ok())
      return failure(st.with_context(run->checkpoint));
  }
  auto log = TrainLog::open(*run, progress.episodes);
  if (!log) return failure(log.status());
  const bool quiet = args->has("--quiet");
  if (!quiet)
    std::printf("training %s on %s (%s rules): %s, estimator %s, %zu parameters, seed %llu%s%s\n",
                policy->name().c_str(), sc.path.c_str(),
                sc.train_env.rules == env::Rules::kGym ? "gym" : "paper", episodes_text(cfg).c_str(),
                cfg.estimator.c_str(), policy->params().size(),
                static_cast<unsigned long long>(cfg.seed), run->resuming ? " (resumed)" : "",
                ranks_text().c_str());
  ProgressBar bar("train", cfg.end_episodes(), !quiet);
  double best_success = -1.0;
  InterruptGuard interrupt;
  auto ended = rl::run_training(
      trainer, *policy, *eval_envs, cfg, *validation, progress,
      [](long long) { return !InterruptGuard::requested(); },
      [&](const rl::UpdateReport& u) -> Result<bool> {
        log->add(progress, u.stats);
        SQUAWK_RETURN_IF_ERROR(sc.reward_error());
        char extra[96];
        std::snprintf(extra, sizeof extra, "return %.3f", u.stats.mean_return);
        bar.update(u.progress.episodes, extra);
        if (!u.eval) return true;
        SQUAWK_RETURN_IF_ERROR(log->row(progress, *u.eval));
        SQUAWK_RETURN_IF_ERROR(save_on_rank0(*learner, run->checkpoint, &trainer));
        if (u.eval->success_rate > best_success) {
          best_success = u.eval->success_rate;
          SQUAWK_RETURN_IF_ERROR(save_on_rank0(*learner, best_path, nullptr));
        }
        if (!quiet) {
          char line[160];
          std::snprintf(line, sizeof line,
                        "%lld episodes, %.0f s: eval success %.1f %%, mean reward %.3f\n",
                        u.progress.episodes, u.progress.wall_s, 100.0 * u.eval->success_rate,
                        u.eval->mean_reward);
          bar.note(line);
        }
        return true;
      });
  if (!ended) {
    bar.finish();
    return failure(ended.status());
  }
  if (*ended == rl::RunEnd::kInterrupted) {
    bar.finish();
    if (Status s = save_on_rank0(*learner, run->checkpoint, &trainer); !s.is_ok())
      return failure(s);
    print_interrupted(*run, progress);
    return kExitInterrupted;
  }
  bar.finish();
  // The policy alone (no optimiser state): what `squawk eval --checkpoint` needs.
  const std::string policy_path = out + "/policy.ckpt";
  if (Status s = save_on_rank0(*learner, policy_path, nullptr); !s.is_ok()) return failure(s);
  if (!quiet)
    std::printf("done: %lld episodes in %s; checkpoint %s, best %s, policy %s, log %s\n", progress.episodes,
                fmt_duration(progress.wall_s).c_str(), run->checkpoint.c_str(), best_path.c_str(),
                policy_path.c_str(), run->log.c_str());
  return kExitOk;
}

}  // namespace squawk::app
