// squawk table3: the four rows of the paper's Table 3 (§IV.D) on one scenario,
// the same numbered evaluation episodes and one fixed seed for every row.
#include <cstdio>
#include <memory>

#include "app/gpt2_policy_factory.h"
#include "app/vm_options.h"
#include "core/files.h"
#include "core/paths.h"
#include "env/vec_env.h"
#include "rl/checkpoint.h"
#include "rl/evaluator.h"
#include "rl/mlp_policy.h"
#include "script/scenario.h"

namespace squawk::app {

namespace {

constexpr const char* kShippedMlpCheckpoint = "models/horizontal_cr_mlp.ckpt";

struct Row {
  std::string agent;
  rl::EvalResult result;
};

}  // namespace

int cmd_table3(const ArgV& argv) {
  std::vector<std::string> values = {"--mlp-checkpoint", "--gpt2-checkpoint", "--episodes", "--envs", "--csv"};
  values.insert(values.end(), kGpt2PolicyFlags.begin(), kGpt2PolicyFlags.end());
  auto args = Args::parse(argv, with_vm_flags({values, {}}));
  if (!args) return usage_error("table3", args.status().message());
  if (args->positional().size() != 1) return usage_error("table3", "expected exactly one SCENARIO.lua");
  auto popts = gpt2_options(*args);
  if (!popts) return usage_error("table3", popts.status().message());
  auto vo = vm_options(*args);
  if (!vo) return usage_error("table3", vo.status().message());
  vo->out_dir.clear();
  auto sc = script::load_scenario(args->positional()[0], *vo);
  if (!sc) return failure(sc.status());
  auto episodes = args->get_int("--episodes", 1000);
  auto seed = args->get_int("--seed", static_cast<long long>(sc->eval_seed));
  auto envs_n = args->get_int("--envs", 64);
  for (const Status& st : {episodes.status(), seed.status(), envs_n.status()})
    if (!st.is_ok()) return usage_error("table3", st.message());
  if (*episodes < 1 || *envs_n < 1) return usage_error("table3", "--episodes and --envs must be >= 1");
  auto envs = env::VecEnv::make(sc->eval_env, static_cast<int>(*envs_n));
  if (!envs) return failure(envs.status());

  auto mlp_ckpt = rl::load_checkpoint(args->get_or("--mlp-checkpoint", paths::resource(kShippedMlpCheckpoint)));
  if (!mlp_ckpt) return failure(mlp_ckpt.status());
  auto gpt2_ckpt =
      rl::load_prompt_checkpoint(args->get_or("--gpt2-checkpoint", paths::resource(kShippedGpt2Checkpoint)));
  if (!gpt2_ckpt) return failure(gpt2_ckpt.status());
  // The untrained GPT-2 is the fine-tuned one's base with a fresh head unless --model names another.
  Gpt2PolicyOptions untrained = *popts;
  if (!args->has("--model")) {
    untrained.model = gpt2_ckpt->source;
    untrained.model_seed = gpt2_ckpt->model_seed;
    untrained.spec.head = gpt2_ckpt->spec.head;
    untrained.spec.trainable_blocks = gpt2_ckpt->spec.trainable_blocks;
  }

  Rng init(static_cast<uint64_t>(*seed));
  auto mlp_untrained = rl::MlpPolicy::make(sc->policy, init);
  if (!mlp_untrained) return failure(mlp_untrained.status());
  auto gpt2_untrained = make_gpt2_policy(untrained, sc->train_env, *vo);
  if (!gpt2_untrained) return failure(gpt2_untrained.status());
  auto mlp_trained = rl::policy_from_checkpoint(*mlp_ckpt);
  if (!mlp_trained) return failure(mlp_trained.status());
  auto gpt2_tuned = gpt2_policy_from_checkpoint(*gpt2_ckpt, popts->prompt, *vo);
  if (!gpt2_tuned) return failure(gpt2_tuned.status());

  const std::vector<std::pair<std::string, rl::Policy*>> agents = {
      {"Untrained Neural Network", mlp_untrained->get()},
      {"Untrained GPT-2 LLM", gpt2_untrained->policy.get()},
      {"RL Trained Neural Network", mlp_trained->get()},
      {"RL Fine-Tuned GPT-2 LLM", gpt2_tuned->policy.get()}};
  std::vector<Row> rows;
  for (const auto& [name, policy] : agents) {
    if (Status st = rl::check_obs_size(*policy, envs->obs_size()); !st.is_ok())
      return failure(st.with_context(name));
    std::fprintf(stderr, "table3: evaluating %s on %lld episodes...\n", name.c_str(), *episodes);
    auto res = rl::evaluate(*policy, *envs, {*episodes, static_cast<uint64_t>(*seed), false});
    if (!res) return failure(res.status());
    rows.push_back({name, *res});
  }
  for (auto* g : {&*gpt2_untrained, &*gpt2_tuned})
    if (Status st = g->policy->error(); !st.is_ok()) return failure(st);
  if (Status rs = sc->reward_error(); !rs.is_ok()) return failure(rs);

  std::printf("Table 3 on %s: %lld evaluation episodes, seed %lld, sampled actions\n\n", sc->path.c_str(),
              *episodes, *seed);
  std::printf("| Agent | Success Rate | Average Reward | Standard Deviation |\n|---|---|---|---|\n");
  for (const Row& r : rows)
    std::printf("| %s | %.1f%% | %.3f | %.3f |\n", r.agent.c_str(), 100.0 * r.result.success_rate,
                r.result.mean_reward, r.result.std_reward);
  std::string csv = "agent,success_rate,mean_reward,std_reward,episodes,seed\n";
  for (const Row& r : rows) {
    char line[256];
    std::snprintf(line, sizeof line, "%s,%.4f,%.4f,%.4f,%lld,%lld\n", r.agent.c_str(), r.result.success_rate,
                  r.result.mean_reward, r.result.std_reward, r.result.episodes, *seed);
    csv += line;
  }
  if (auto path = args->get("--csv")) {
    if (Status st = files::write_atomic(*path, csv); !st.is_ok()) return failure(st);
  } else {
    std::printf("\n%s", csv.c_str());
  }
  return kExitOk;
}

}  // namespace squawk::app
