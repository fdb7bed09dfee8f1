// squawk gpt2 imitate SCENARIO.lua OUT.ckpt: behaviour cloning (with DAgger
// rounds, rl/imitation.h) of a trained MLP by the GPT-2 prompt policy. A
// labelled experiment: it measures what the prompt policy can hold, and its
// checkpoints say so (estimator "imitation"); it is never the paper's
// fine-tuned row.
#include <cstdio>

#include "app/cli.h"
#include "app/gpt2_policy_factory.h"
#include "app/learner_flags.h"
#include "app/out_guard.h"
#include "app/vm_options.h"
#include "rl/imitation.h"
#include "rl/prompt_checkpoint.h"
#include "script/scenario.h"

namespace squawk::app {

int cmd_gpt2_imitate(const ArgV& argv) {
  std::vector<std::string> values = {"--teacher", "--episodes", "--rounds", "--epochs", "--batch",
                                     "--lr",      "--seed",     "--holdout", "--envs"};
  values.insert(values.end(), kGpt2PolicyFlags.begin(), kGpt2PolicyFlags.end());
  auto args = Args::parse(argv, with_vm_flags({values, {"--mirror", "--train-embeddings", "--quiet", "--force"}}));
  if (!args) return usage_error("gpt2", args.status().message());
  if (args->positional().size() != 2) return usage_error("gpt2", "imitate expects SCENARIO.lua OUT.ckpt");
  if (Status st = check_absent(args->positional()[1], {args->positional()[1]}, args->has("--force")); !st.is_ok())
    return usage_error("gpt2", "imitate: " + st.message());
  rl::ImitationConfig cfg;
  const std::pair<const char*, long long> defaults[] = {{"--episodes", cfg.episodes}, {"--rounds", cfg.rounds},
                                                        {"--epochs", cfg.epochs},     {"--batch", cfg.batch},
                                                        {"--seed", 1},                {"--holdout", cfg.holdout},
                                                        {"--envs", 32}};
  std::vector<long long> v;
  for (const auto& [flag, def] : defaults) {
    auto x = args->get_int(flag, def);
    if (!x || *x < 1 || *x > 100'000'000) return usage_error("gpt2", std::string(flag) + " expects a positive integer");
    v.push_back(*x);
  }
  cfg.episodes = v[0];
  cfg.rounds = static_cast<int>(v[1]);
  cfg.epochs = static_cast<int>(v[2]);
  cfg.batch = static_cast<int>(v[3]);
  cfg.seed = static_cast<uint64_t>(v[4]);
  cfg.holdout = v[5];
  cfg.holdout_seed = cfg.seed + 1000003;
  auto lr = args->get_double("--lr", cfg.lr);
  if (!lr || !(*lr > 0.0 && *lr < 1.0)) return usage_error("gpt2", "--lr expects a number in (0, 1)");
  cfg.lr = static_cast<float>(*lr);
  auto popts = gpt2_options(*args);
  if (!popts) return usage_error("gpt2", popts.status().message());
  script::VmOptions vo;
  script::Scenario sc;
  if (int rc = load_episode_scenario(*args, "gpt2", vo, sc); rc != kExitOk) return rc;
  if (Status st = apply_mirror_flag(*args, sc.train_env, popts->spec.mirror); !st.is_ok())
    return usage_error("gpt2", "--mirror: " + st.message());
  auto envs = env::VecEnv::make(sc.train_env, static_cast<int>(v[6]));
  if (!envs) return failure(envs.status());
  script::PolicyOptions to;
  to.checkpoint = args->get_or("--teacher", script::kShippedMlpMirrorCheckpoint);
  auto teacher = script::make_policy("mlp", sc, *envs, to, vo);
  if (!teacher) return failure(teacher.status());
  auto g = make_gpt2_policy(*popts, sc.train_env, vo);
  if (!g) return failure(g.status());
  rl::PromptPolicy& student = *g->policy;
  rl::PromptCheckpoint& meta = g->meta;
  meta.progress.seed = cfg.seed;
  meta.progress.estimator = "imitation";
  meta.progress.scenario = sc.path;
  const std::string out = args->positional()[1];
  const bool quiet = args->has("--quiet");
  if (!quiet)
    std::printf("imitation (a labelled experiment, not RL fine-tuning): gpt2 (%s, %zu trainable parameters%s) "
                "clones %s on %s; %d round(s) of %lld episodes, %d epochs of batches of %d, lr %g, seed %llu\n",
                meta.source.c_str(), student.params().size(), meta.spec.mirror.empty() ? "" : ", mirror-symmetric",
                teacher->label.c_str(), sc.path.c_str(), cfg.rounds, cfg.episodes, cfg.epochs, cfg.batch,
                static_cast<double>(cfg.lr), static_cast<unsigned long long>(cfg.seed));
  Status st = rl::imitate(student, *teacher->policy, *envs, cfg, [&](const rl::ImitationEpoch& e) -> Status {
    if (!quiet)
      std::printf("round %d (flown by the %s, success %.1f %%, %lld decisions), epoch %d: held-out agreement %.1f %%\n",
                  e.round + 1, e.teacher_flew ? "teacher" : "student", 100.0 * e.flight_success, e.decisions, e.epoch + 1,
                  100.0 * e.agreement);
    std::fflush(stdout);
    meta.params.assign(student.params().begin(), student.params().end());
    return rl::save_prompt_checkpoint(out, meta);
  });
  if (!st.is_ok()) return failure(st);
  if (!quiet)
    std::printf("wrote %s; evaluate it with squawk eval %s --policy gpt2 --checkpoint %s\n", out.c_str(),
                args->positional()[0].c_str(), out.c_str());
  return kExitOk;
}

}  // namespace squawk::app
