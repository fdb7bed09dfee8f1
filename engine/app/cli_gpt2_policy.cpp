// squawk train / eval --policy gpt2: fine-tuning and evaluation of the GPT-2
// prompt policy (paper §III.C.3-5). Reached through the --policy hook of
// cmd_train / cmd_eval (cli_rl.cpp).
#include <cstdio>
#include <cstdlib>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/gpt2_policy_factory.h"
#include "app/interrupt.h"
#include "app/learner_flags.h"
#include "app/progress_bar.h"
#include "app/rl_eval.h"
#include "app/train_log.h"
#include "app/vm_options.h"
#include "core/paths.h"
#include "dist/comm.h"
#include "env/vec_env.h"
#include "nn/gemm.h"
#include "rl/train_run.h"
#include "script/learner.h"
#include "script/scenario.h"

namespace squawk::app {

Args::Spec train_flags(bool gpt2) {
  std::vector<std::string> values = learner_flags();
  values.insert(
      values.end(),
      {"--policy", "--env", "--levels", "--hidden", "--agents", "--obs-norm", "--log-std",
       "--imitate", "--imitate-episodes", "--imitate-rounds", "--imitate-epochs", "--imitate-lr",
       "--imitate-permute", "--imitate-saturate", "--clone-log-std", "--init"});
  std::vector<std::string> bools = {"--resume", "--override", "--force",         "--quiet",
                                    "--mirror", "--gaussian", "--imitate-means", "--update-log"};
  if (gpt2) {
    values.insert(values.end(), kGpt2PolicyFlags.begin(), kGpt2PolicyFlags.end());
    bools.push_back("--train-embeddings");
  }
  return with_vm_flags({std::move(values), std::move(bools)});
}

int cmd_train_gpt2(const ArgV& argv) {
  auto args = Args::parse(argv, train_flags(true));
  if (!args) return usage_error("train", args.status().message());
  if (!args->has("--out")) return usage_error("train", "missing --out DIR");
  auto popts = gpt2_options(*args);
  if (!popts) return usage_error("train", popts.status().message());
  if (args->positional().size() != 1) return usage_error("train", "expected exactly one SCENARIO.lua");
  script::VmOptions vo;
  script::Scenario sc;
  if (int rc = load_episode_scenario(*args, "train", vo, sc); rc != kExitOk) return rc;
  if (Status st = apply_mirror_flag(*args, sc.train_env, popts->spec.mirror); !st.is_ok())
    return usage_error("train", "--mirror: " + st.message());
  rl::TrainConfig cfg = sc.train;
  const double lr_default = popts->model == "tiny" ? cfg.lr : script::kGpt2FolderLr;
  if (Status st = apply_learner_flags(*args, script::kGpt2TrainEpisodes, lr_default, cfg);
      !st.is_ok())
    return usage_error("train", st.message());
  auto validation = validation_seed(*args, sc.eval_seed);
  if (!validation) return usage_error("train", validation.status().message());

  auto run = open_run_folder(*args->get("--out"), *args);
  if (!run) return failure(run.status());

  const bool resuming = run->resuming;
  const std::string init_path = resuming ? "" : args->get_or("--init", "");
  script::LearnerOptions lo;
  lo.kind = "gpt2";
  lo.gpt2 = *popts;
  lo.from = resuming ? run->checkpoint : init_path;
  lo.resume = resuming;
  lo.seed = cfg.seed;
  auto learner = script::make_learner(lo, sc, vo);
  if (!learner) return failure(learner.status());
  if (resuming) {
    if (Status st = check_resume_seed(*run, learner->progress().seed, cfg.seed); !st.is_ok())
      return failure(st);
    if (Status st = check_resume_mirror(run->checkpoint, learner->mirror(), popts->spec.mirror);
        !st.is_ok())
      return failure(st);
  }
  rl::Policy& policy = *learner->policy;
  rl::PromptCheckpoint& meta = learner->gpt2;
  meta.progress.estimator = cfg.estimator;
  meta.progress.scenario = sc.path;
  if (Status st = rl::check_obs_size(policy, env::observation_size(sc.train_env.num_intruders)); !st.is_ok())
    return failure(st);
  if (Status st = rl::check_learner(policy, cfg); !st.is_ok()) return usage_error("train", st.message());
  auto train_envs = env::VecEnv::make(sc.train_env, cfg.num_envs);
  auto eval_envs = env::VecEnv::make(sc.eval_env, cfg.num_envs);
  if (!train_envs) return failure(train_envs.status());
  if (!eval_envs) return failure(eval_envs.status());
  rl::Trainer trainer(policy, *train_envs, cfg, meta.progress.updates);
  if (learner->restore) {
    if (Status st = trainer.restore(*learner->restore); !st.is_ok())
      return failure(st.with_context(lo.from));
  }
  auto log = TrainLog::open(*run, meta.progress.episodes);
  if (!log) return failure(log.status());

  const bool quiet = args->has("--quiet");
  if (!quiet)
    std::printf(
        "training gpt2 (%s, %d trainable blocks%s, head %s, %zu trainable parameters) on %s: "
        "%s, estimator %s, lr %g, seed %llu%s%s\n",
        meta.source.c_str(), meta.spec.trainable_blocks,
        meta.spec.train_embeddings ? " and the embeddings" : "", meta.spec.head.c_str(),
        policy.params().size(), sc.path.c_str(), episodes_text(cfg).c_str(), cfg.estimator.c_str(),
        cfg.lr, static_cast<unsigned long long>(cfg.seed),
        resuming            ? " (resumed)"
        : init_path.empty() ? ""
                            : (" (from " + init_path + ")").c_str(),
        ranks_text().c_str());
  // The bar counts episodes as they finish inside an update (a GPT-2 small
  // update takes minutes); its ETA covers the rest of this run.
  ProgressBar bar("train gpt2", cfg.end_episodes(), !quiet);
  InterruptGuard interrupt;
  auto note = [&](const char* f, auto... a) {
    char line[256];
    std::snprintf(line, sizeof line, f, a...);
    if (!quiet) bar.note(line);
  };
  auto within = [&](long long done) {
    bar.update(meta.progress.episodes + done,
               "(update " + std::to_string(trainer.updates() + 1) + ")");
    return !InterruptGuard::requested();
  };
  auto ended = rl::run_training(
      trainer, policy, *eval_envs, cfg, *validation, meta.progress, within,
      [&](const rl::UpdateReport& u) -> Result<bool> {
        SQUAWK_RETURN_IF_ERROR(sc.reward_error());
        log->add(meta.progress, u.stats);
        note(
            "update %lld: %lld episodes, %d decisions, return %.3f, success %.1f %%, entropy %.3f, "
            "%.2f s\n",
            u.progress.updates, u.progress.episodes, u.stats.samples, u.stats.mean_return,
            100.0 * u.stats.success_rate, u.stats.entropy, u.update_s);
        if (u.eval) {
          SQUAWK_RETURN_IF_ERROR(log->row(meta.progress, *u.eval));
          note(
              "%lld episodes: eval success %.1f %%, mean reward %.3f (%lld episodes), most "
              "frequent action %.1f %%\n",
              u.progress.episodes, 100.0 * u.eval->success_rate, u.eval->mean_reward,
              u.eval->episodes, 100.0 * u.eval->most_frequent_share());
        }
        // rank 0 alone writes; the other ranks hold the same state
        if (dist::rank() == 0) SQUAWK_RETURN_IF_ERROR(learner->save(run->checkpoint, &trainer));
        return true;
      });
  if (!ended) return failure(ended.status());
  if (*ended == rl::RunEnd::kInterrupted) {
    bar.finish();
    print_interrupted(*run, meta.progress);
    return kExitInterrupted;
  }
  bar.finish();
  if (!quiet)
    std::printf("done: %lld episodes in %s; checkpoint %s, log %s\n", meta.progress.episodes,
                fmt_duration(meta.progress.wall_s).c_str(), run->checkpoint.c_str(), run->log.c_str());
  return kExitOk;
}

Status apply_precision_flag(const Args& args, bool announce) {
  std::optional<nn::Precision> want;
  if (auto v = args.get("--precision")) {
    auto p = nn::parse_precision(*v);
    if (!p) return Status::invalid("--precision: " + p.status().message());
    want = *p;
  }
  const std::string line = nn::use_precision(want);
  if (announce && dist::rank() == 0) std::fprintf(stderr, "%s\n", line.c_str());
  return Status::ok();
}

Result<Gpt2PolicyOptions> gpt2_options(const Args& args, bool announce) {
  SQUAWK_RETURN_IF_ERROR(apply_precision_flag(args, announce));
  Gpt2PolicyOptions o;
  o.model = args.get_or("--model", "tiny");
  o.prompt = args.get_or("--prompt", "");
  o.spec.head = args.get_or("--head", "action");
  SQUAWK_ASSIGN_OR_RETURN(long long seed, args.get_int("--model-seed", 0));
  SQUAWK_ASSIGN_OR_RETURN(long long blocks, args.get_int("--blocks", -1));
  SQUAWK_ASSIGN_OR_RETURN(long long chunk, args.get_int("--chunk", o.spec.chunk_rows));
  o.model_seed = static_cast<uint64_t>(seed);
  o.spec.trainable_blocks = static_cast<int>(blocks);
  o.spec.chunk_rows = static_cast<int>(chunk);
  o.spec.train_embeddings = args.has("--train-embeddings");
  return o;
}

bool wants_gpt2(const ArgV& argv) {
  for (size_t i = 0; i < argv.size(); ++i) {
    if (argv[i] == "--policy=gpt2") return true;
    if (argv[i] == "--policy" && i + 1 < argv.size() && argv[i + 1] == "gpt2") return true;
  }
  return false;
}

}  // namespace squawk::app
