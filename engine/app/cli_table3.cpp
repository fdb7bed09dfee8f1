// squawk table3: the paper's Table 3 (§IV.D) on one scenario, the same
// numbered evaluation episodes and one fixed seed for every row, plus the
// baselines that show what a row is worth: always -0.5, always +0.5, never
// turning, and BlueSky's MVP. Every agent is evaluated twice on the same
// episodes: sampled actions (the table's columns) and greedy actions (the
// share of its most frequent greedy action: a policy that plays one action
// whatever the state shows up as ~100 %).
#include <cstdio>
#include <memory>
#include <tuple>

#include <nlohmann/json.hpp>

#include "app/gpt2_policy_factory.h"
#include "app/out_guard.h"
#include "app/progress_bar.h"
#include "app/rl_eval.h"
#include "app/vm_options.h"
#include "core/files.h"
#include "core/paths.h"
#include "dist/comm.h"
#include "env/vec_env.h"
#include "rl/evaluator.h"
#include "rl/prompt_checkpoint.h"
#include "script/policy_factory.h"
#include "script/scenario.h"

namespace squawk::app {

namespace {

// The first line of the --csv file (which table3 may replace without --force).
constexpr const char* kCsvHeader = "agent,success_rate,mean_reward,std_reward,episodes,seed,most_frequent_greedy_share\n";

struct Row {
  std::string agent;
  std::string kind;
  rl::EvalResult sampled, greedy;
};

nlohmann::json histogram(const rl::EvalResult& r) {
  nlohmann::json h = nlohmann::json::object();
  for (size_t k = 0; k < rl::kActionBins.size(); ++k) {
    char key[16];
    std::snprintf(key, sizeof key, "%g", rl::kActionBins[k]);
    h[key] = r.action_counts[k];
  }
  return h;
}

// "+0.5 (97 %)": the most frequent greedy action and its share.
std::string top_action(const rl::EvalResult& r) {
  size_t best = 0;
  for (size_t k = 1; k < r.action_counts.size(); ++k)
    if (r.action_counts[k] > r.action_counts[best]) best = k;
  char buf[48];
  std::snprintf(buf, sizeof buf, rl::kActionBins[best] == 0.0 ? "%g (%.1f %%)" : "%+g (%.1f %%)",
                rl::kActionBins[best], 100.0 * r.most_frequent_share());
  return buf;
}

}  // namespace

int cmd_table3(const ArgV& argv) {
  std::vector<std::string> values = {"--mlp-checkpoint", "--mlp-mirror-checkpoint", "--gpt2-checkpoint", "--gpt2-mirror-checkpoint", "--episodes", "--envs", "--csv"};
  values.insert(values.end(), kGpt2PolicyFlags.begin(), kGpt2PolicyFlags.end());
  auto args = Args::parse(argv, with_vm_flags({values, {"--json", "--force"}}));
  if (!args) return usage_error("table3", args.status().message());
  if (auto path = args->get("--csv")) {
    if (Status st = check_overwrite(*path, kCsvHeader, args->has("--force")); !st.is_ok())
      return usage_error("table3", "--csv: " + st.message());
  }
  if (args->positional().size() != 1) return usage_error("table3", "expected exactly one SCENARIO.lua");
  auto popts = gpt2_options(*args);
  if (!popts) return usage_error("table3", popts.status().message());
  script::VmOptions vo;
  script::Scenario sc;
  if (int rc = load_episode_scenario(*args, "table3", vo, sc); rc != kExitOk) return rc;
  auto episodes = args->get_int("--episodes", 1000);
  auto seed = args->get_int("--seed", static_cast<long long>(sc.eval_seed));
  auto envs_n = args->get_int("--envs", 64);
  for (const Status& st : {episodes.status(), seed.status(), envs_n.status()})
    if (!st.is_ok()) return usage_error("table3", st.message());
  if (*episodes < 1 || *envs_n < 1) return usage_error("table3", "--episodes and --envs must be >= 1");
  auto envs = env::VecEnv::make(sc.eval_env, static_cast<int>(*envs_n));
  if (!envs) return failure(envs.status());

  script::PolicyOptions mlp;
  mlp.checkpoint = args->get_or("--mlp-checkpoint", "");
  mlp.seed = static_cast<uint64_t>(*seed);
  script::PolicyOptions mirrored = mlp;
  mirrored.checkpoint = args->get_or("--mlp-mirror-checkpoint", paths::resource(script::kShippedMlpMirrorCheckpoint));
  script::PolicyOptions tuned;
  tuned.checkpoint = args->get_or("--gpt2-checkpoint", paths::resource(kShippedGpt2Checkpoint));
  tuned.gpt2 = *popts;
  script::PolicyOptions tuned_mirror = tuned;
  tuned_mirror.checkpoint = args->get_or("--gpt2-mirror-checkpoint", paths::resource(script::kShippedGpt2MirrorCheckpoint));
  // The untrained GPT-2 is the fine-tuned one's base with a fresh head unless --model names another.
  script::PolicyOptions untrained = tuned;
  untrained.gpt2_fresh = true;
  if (!args->has("--model")) {
    auto c = rl::load_prompt_checkpoint(tuned.checkpoint);
    if (!c) return failure(c.status());
    untrained.gpt2.model = c->source;
    untrained.gpt2.model_seed = c->model_seed;
    untrained.gpt2.spec.head = c->spec.head;
    untrained.gpt2.spec.trainable_blocks = c->spec.trainable_blocks;
  }
  const std::vector<std::tuple<std::string, std::string, const script::PolicyOptions*>> agents = {
      {"Untrained Neural Network", "random", &mlp},
      {"Untrained GPT-2 LLM", "gpt2", &untrained},
      {"RL Trained Neural Network", "mlp", &mlp},
      {"RL Trained NN, mirror-symmetric (beyond the paper)", "mlp", &mirrored},
      {"RL Fine-Tuned GPT-2 LLM", "gpt2", &tuned},
      {"RL Fine-Tuned GPT-2, mirror-symmetric (beyond the paper)", "gpt2", &tuned_mirror},
      {"Always -0.5 (slightly left)", "constant:-0.5", &mlp},
      {"Always +0.5 (slightly right)", "constant:0.5", &mlp},
      {"Never turning", "zero", &mlp},
      {"Rule: +0.5 when on track, else hold", "turn-hold:0.5", &mlp},
      {"MVP (BlueSky resolution)", "mvp", &mlp},
      {"Lookahead planner (reads the simulator)", "lookahead", &mlp},
      {"Trained NN + one rollout step (reads the simulator)", "rollout:mlp", &mlp}};
  std::vector<Row> rows;
  for (const auto& [name, kind, opts] : agents) {
    auto made = script::make_policy(kind, sc, *envs, *opts, vo);
    if (!made) return failure(made.status().with_context(name));
    rl::Policy& policy = *made->policy;
    if (Status st = rl::check_obs_size(policy, envs->obs_size()); !st.is_ok()) return failure(st.with_context(name));
    if (std::string w = trained_elsewhere(*made, sc, vo); !w.empty())
      std::fprintf(stderr, "table3: warning: %s: %s\n", name.c_str(), w.c_str());
    Row row{name, kind, {}, {}};
    for (bool greedy : {false, true}) {
      if (greedy && !policy.trainable()) {
        row.greedy = row.sampled;  // no distribution: the mode is the action played
        break;
      }
      ProgressBar bar("table3: " + name + (greedy ? " (greedy)" : " (sampled)"), *episodes, true);
      auto res = rl::evaluate(policy, *envs, {*episodes, static_cast<uint64_t>(*seed), greedy},
                              [&](long long done, long long) { bar.update(done); });
      bar.finish();
      if (!res) return failure(res.status());
      if (Status ps = policy.error(); !ps.is_ok()) return failure(ps.with_context(name));
      (greedy ? row.greedy : row.sampled) = *res;
    }
    rows.push_back(row);
  }
  if (Status rs = sc.reward_error(); !rs.is_ok()) return failure(rs);

  if (args->has("--json")) {
    nlohmann::json out = {{"scenario", sc.path}, {"episodes", *episodes}, {"seed", *seed}, {"rows", nlohmann::json::array()}};
    for (const Row& r : rows)
      out["rows"].push_back({{"agent", r.agent},
                             {"policy", r.kind},
                             {"success_rate", r.sampled.success_rate},
                             {"mean_reward", r.sampled.mean_reward},
                             {"std_reward", r.sampled.std_reward},
                             {"actions_sampled", histogram(r.sampled)},
                             {"actions_greedy", histogram(r.greedy)},
                             {"greedy_success_rate", r.greedy.success_rate},
                             {"greedy_mean_reward", r.greedy.mean_reward},
                             {"most_frequent_greedy_share", r.greedy.most_frequent_share()}});
    std::printf("%s\n", out.dump(1).c_str());
  } else {
    std::printf("Table 3 on %s: %lld evaluation episodes, seed %lld, sampled actions; last column: the "
                "most frequent greedy action and its share of the greedy decisions\n\n",
                sc.path.c_str(), *episodes, *seed);
    std::printf("| Agent | Success Rate | Average Reward | Standard Deviation | Top greedy action |\n"
                "|---|---|---|---|---|\n");
    for (const Row& r : rows)
      std::printf("| %s | %.1f%% | %.3f | %.3f | %s |\n", r.agent.c_str(), 100.0 * r.sampled.success_rate,
                  r.sampled.mean_reward, r.sampled.std_reward, top_action(r.greedy).c_str());
  }
  std::string csv = kCsvHeader;
  for (const Row& r : rows) {
    char line[256];
    std::snprintf(line, sizeof line, "%s,%.4f,%.4f,%.4f,%lld,%lld,%.4f\n", r.agent.c_str(), r.sampled.success_rate,
                  r.sampled.mean_reward, r.sampled.std_reward, r.sampled.episodes, *seed,
                  r.greedy.most_frequent_share());
    csv += line;
  }
  if (auto path = args->get("--csv")) {
    if (dist::rank() == 0)  // rank 0 alone writes (dist/comm.h); every rank holds the same rows
      if (Status st = files::write_atomic(*path, csv); !st.is_ok()) return failure(st);
  } else if (!args->has("--json")) {
    std::printf("\n%s", csv.c_str());
  }
  return kExitOk;
}

}  // namespace squawk::app
