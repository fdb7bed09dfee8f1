// squawk train / eval --policy gpt2: fine-tuning and evaluation of the GPT-2
// prompt policy (paper §III.C.3-5). Reached through the --policy hook of
// cmd_train / cmd_eval (cli_rl.cpp).
#include <chrono>
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
#include "rl/evaluator.h"
#include "rl/vpg.h"
#include "script/scenario.h"

namespace squawk::app {

namespace {

// Adam step size on a Hugging Face folder unless --lr says otherwise.
constexpr double kFolderLr = 1e-5;

}  // namespace

Args::Spec train_flags(bool gpt2) {
  std::vector<std::string> values = learner_flags();
  values.push_back("--policy");
  std::vector<std::string> bools = {"--resume", "--override", "--force", "--quiet", "--mirror"};
  if (gpt2) {
    values.push_back("--init");
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
  const double lr_default = popts->model == "tiny" ? cfg.lr : kFolderLr;
  if (Status st = apply_learner_flags(*args, 20000, lr_default, cfg); !st.is_ok())
    return usage_error("train", st.message());
  auto validation = validation_seed(*args, sc.eval_seed);
  if (!validation) return usage_error("train", validation.status().message());

  auto run = open_run_folder(*args->get("--out"), *args);
  if (!run) return failure(run.status());

  Gpt2Policy g;
  rl::PromptCheckpoint resume;
  const bool resuming = run->resuming;
  const std::string init_path = resuming ? "" : args->get_or("--init", "");
  if (resuming || !init_path.empty()) {
    auto c = rl::load_prompt_checkpoint(resuming ? run->checkpoint : init_path);
    if (!c) return failure(c.status());
    if (resuming) {
      if (Status st = check_resume_seed(*run, c->progress.seed, cfg.seed); !st.is_ok()) return failure(st);
      if (Status st = check_resume_mirror(run->checkpoint, c->spec.mirror, popts->spec.mirror); !st.is_ok())
        return failure(st);
    } else {
      // --init: the learned state (parameters, Adam moments, value baseline)
      // carries over; the counters, and so the schedules, start at zero.
      if (!popts->spec.mirror.empty()) c->spec.mirror = popts->spec.mirror;
      c->progress = rl::TrainProgress{};
      c->progress.seed = cfg.seed;
    }
    auto p = gpt2_policy_from_checkpoint(*c, popts->prompt, vo);
    if (!p) return failure(p.status());
    g = std::move(*p);
    resume = std::move(*c);
  } else {
    auto p = make_gpt2_policy(*popts, sc.train_env, vo);
    if (!p) return failure(p.status());
    g = std::move(*p);
    g.meta.progress.seed = cfg.seed;
  }
  rl::PromptPolicy& policy = *g.policy;
  rl::PromptCheckpoint& meta = g.meta;
  const bool restoring = resuming || !init_path.empty();
  if (restoring) meta.progress = resume.progress;
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
  if (restoring) {
    if (Status st = trainer.restore(resume); !st.is_ok())
      return failure(st.with_context(resuming ? run->checkpoint : init_path));
  }
  auto log = TrainLog::open(*run, meta.progress.episodes);
  if (!log) return failure(log.status());

  const bool quiet = args->has("--quiet");
  if (!quiet)
    std::printf("training gpt2 (%s, %d trainable blocks%s, head %s, %zu trainable parameters) on %s: "
                "%s, estimator %s, lr %g, seed %llu%s%s\n",
                meta.source.c_str(), meta.spec.trainable_blocks, meta.spec.train_embeddings ? " and the embeddings" : "",
                meta.spec.head.c_str(), policy.params().size(),
                sc.path.c_str(), episodes_text(cfg).c_str(), cfg.estimator.c_str(), cfg.lr,
                static_cast<unsigned long long>(cfg.seed),
                resuming ? " (resumed)" : init_path.empty() ? "" : (" (from " + init_path + ")").c_str(),
                ranks_text().c_str());
  const auto t0 = std::chrono::steady_clock::now();
  const double wall0 = meta.progress.wall_s;
  long long next_eval = cfg.eval_every > 0 ? (meta.progress.episodes / cfg.eval_every + 1) * cfg.eval_every
                                           : cfg.episodes;
  // The bar counts episodes as they finish inside an update (a GPT-2 small
  // update takes minutes); its ETA covers the rest of this run.
  ProgressBar bar("train gpt2", cfg.end_episodes(), !quiet);
  InterruptGuard interrupt;
  auto note = [&](const char* f, auto... a) {
    char line[256];
    std::snprintf(line, sizeof line, f, a...);
    if (!quiet) bar.note(line);
  };
  while (meta.progress.episodes < cfg.end_episodes()) {
    const auto u0 = std::chrono::steady_clock::now();
    const rl::UpdateStats st = trainer.update([&](long long done) {
      bar.update(meta.progress.episodes + done, "(update " + std::to_string(trainer.updates() + 1) + ")");
      return !InterruptGuard::requested();
    });
    if (st.interrupted) {
      bar.finish();
      print_interrupted(*run, meta.progress);
      return kExitInterrupted;
    }
    const double update_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - u0).count();
    if (Status ps = policy.error(); !ps.is_ok()) return failure(ps);
    if (Status rs = sc.reward_error(); !rs.is_ok()) return failure(rs);
    meta.progress.episodes += st.episodes;
    meta.progress.updates = trainer.updates();
    meta.progress.wall_s = wall0 + std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    log->add(meta.progress, st);
    note("update %lld: %lld episodes, %d decisions, return %.3f, success %.1f %%, entropy %.3f, %.2f s\n",
         meta.progress.updates, meta.progress.episodes, st.samples, st.mean_return, 100.0 * st.success_rate,
         static_cast<double>(st.entropy), update_s);
    if (meta.progress.episodes >= next_eval || meta.progress.episodes >= cfg.end_episodes()) {
      next_eval += cfg.eval_every > 0 ? cfg.eval_every : cfg.episodes;
      auto ev = rl::evaluate(policy, *eval_envs, {cfg.eval_episodes, *validation, false});
      if (!ev) return failure(ev.status());
      if (Status s = log->row(meta.progress, *ev); !s.is_ok()) return failure(s);
      note("%lld episodes: eval success %.1f %%, mean reward %.3f (%lld episodes), most frequent action %.1f %%\n",
           meta.progress.episodes, 100.0 * ev->success_rate, ev->mean_reward, ev->episodes,
           100.0 * ev->most_frequent_share());
    }
    trainer.save(meta);
    if (dist::rank() == 0)  // rank 0 alone writes; the other ranks hold the same state
      if (Status s = rl::save_prompt_checkpoint(run->checkpoint, meta); !s.is_ok()) return failure(s);
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
