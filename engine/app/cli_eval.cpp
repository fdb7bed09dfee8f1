// squawk eval: one policy of any kind (script/policy_factory.h) on a
// scenario's evaluation episodes; Table 3's columns and the action histogram.
#include <cstdio>
#include <fstream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli.h"
#include "app/gpt2_policy_factory.h"
#include "app/progress_bar.h"
#include "app/rl_eval.h"
#include "app/subcommands.h"
#include "app/vm_options.h"
#include "core/files.h"
#include "core/paths.h"
#include "dist/comm.h"
#include "env/observation.h"
#include "env/recorder.h"
#include "rl/evaluator.h"
#include "rl/prompt_policy.h"

namespace squawk::app {

namespace {

const char* rules_name(env::Rules r) { return r == env::Rules::kGym ? "gym" : "paper"; }

// Forwards to a PromptPolicy and prints the prompt and the action of its
// first `limit` decisions on stdout.
class PromptShower : public rl::Policy {
 public:
  PromptShower(rl::PromptPolicy& inner, long long limit) : inner_(inner), left_(limit) {}
  std::string name() const override { return inner_.name(); }
  int obs_size() const override { return inner_.obs_size(); }
  Status error() const override { return inner_.error(); }
  void act(std::span<const float> obs, int n, std::span<const int> slots, std::span<Rng> rngs, bool greedy,
           std::span<rl::ActionSample> out) override {
    inner_.act(obs, n, slots, rngs, greedy, out);
    const auto d = static_cast<size_t>(obs_size());
    for (int r = 0; r < n && left_ > 0; ++r, --left_) {
      auto text = inner_.prompt(obs.subspan(static_cast<size_t>(r) * d, d));
      std::printf("--- prompt of decision %lld (slot %d) ---\n%s--- action %g\n", ++shown_,
                  slots[static_cast<size_t>(r)], text ? text->c_str() : text.status().message().c_str(),
                  static_cast<double>(out[static_cast<size_t>(r)].value));
    }
  }

 private:
  rl::PromptPolicy& inner_;
  long long left_;
  long long shown_ = 0;
};

}  // namespace

Result<EvalRequest> eval_request(const Args& args, const script::Scenario& sc) {
  EvalRequest r;
  auto episodes = args.get_int("--episodes", sc.eval_episodes);
  auto seed = args.get_int("--seed", static_cast<long long>(sc.eval_seed));
  auto envs_n = args.get_int("--envs", r.envs);
  auto show = args.get_int("--show-prompt", 0);
  for (const Status& st : {episodes.status(), seed.status(), envs_n.status(), show.status()})
    if (!st.is_ok()) return st;
  if (*episodes < 1 || *envs_n < 1) return Status::invalid("--episodes and --envs must be >= 1");
  if (*show < 0) return Status::invalid("--show-prompt must be >= 0");
  r.episodes = *episodes;
  r.seed = *seed;
  r.envs = static_cast<int>(*envs_n);
  r.greedy = args.has("--greedy");
  r.json = args.has("--json");
  r.record = args.get_or("--record", "");
  if (!r.record.empty() && dist::size() > 1)
    return Status::invalid("--record: one process writes the recording; run it without mpirun");
  r.show_prompt = *show;
  return r;
}

Result<script::PolicyOptions> policy_options(const Args& args, long long seed) {
  script::PolicyOptions o;
  // the precision line only where GPT-2 runs
  SQUAWK_ASSIGN_OR_RETURN(o.gpt2, gpt2_options(args, args.get_or("--policy", "") == "gpt2"));
  o.checkpoint = args.get_or("--checkpoint", "");
  o.seed = static_cast<uint64_t>(seed);
  o.gpt2_fresh = args.has("--model");
  if (o.gpt2_fresh && !o.checkpoint.empty())
    return Status::invalid("--checkpoint and --model exclude each other (a checkpoint names its model)");
  return o;
}

std::string trained_elsewhere(const script::MadePolicy& made, const script::Scenario& sc,
                              const script::VmOptions& vm) {
  if (made.trained_on.empty() || made.trained_on == sc.path) return "";
  std::string path = made.trained_on;
  if (!files::exists(path)) path = paths::resource(made.trained_on);
  if (!files::exists(path)) return "";
  script::VmOptions quiet = vm;
  quiet.out_dir.clear();
  auto trained = script::load_scenario(path, quiet);
  if (!trained) return "";
  std::string w;
  if (trained->train_env.rules != sc.eval_env.rules)
    w += std::string("the policy was trained on ") + made.trained_on + " (" + rules_name(trained->train_env.rules) +
         " rules), this scenario has " + rules_name(sc.eval_env.rules) + " rules";
  if (trained->train_env.num_intruders != sc.eval_env.num_intruders)
    w += std::string(w.empty() ? "" : "; ") + "trained with " + std::to_string(trained->train_env.num_intruders) +
         " intruders, this scenario has " + std::to_string(sc.eval_env.num_intruders);
  return w;
}

std::string success_definition(const script::Scenario& sc) {
  return sc.eval_env.rules == env::Rules::kGym
             ? "success = no intruder inside the zone at any step end (BlueSky-Gym's total_intrusions == 0; "
               "reaching the waypoint is not required)"
             : "success = waypoint reached, no intruder inside the zone at any sub-step, no step cap";
}

int run_eval(script::MadePolicy& made, env::VecEnv& envs, const script::Scenario& sc, const EvalRequest& req,
             const script::VmOptions& vm) {
  rl::Policy& base = *made.policy;
  if (Status st = rl::check_obs_size(base, envs.obs_size()); !st.is_ok()) return failure(st);
  const std::string elsewhere = trained_elsewhere(made, sc, vm);
  // Said once, on stderr, before the episodes run (and in --json's "warning").
  if (!elsewhere.empty()) std::fprintf(stderr, "squawk eval: warning: %s\n", elsewhere.c_str());
  std::unique_ptr<PromptShower> shower;
  if (req.show_prompt > 0) {
    auto* pp = dynamic_cast<rl::PromptPolicy*>(&base);
    if (!pp) return usage_error("eval", "--show-prompt goes with --policy gpt2");
    shower = std::make_unique<PromptShower>(*pp, req.show_prompt);
  }
  rl::Policy& policy = shower ? static_cast<rl::Policy&>(*shower) : base;
  std::unique_ptr<files::AtomicWriter> rec_file;  // committed once the episodes ran
  std::unique_ptr<env::JsonlRecorder> recorder;
  if (!req.record.empty()) {
    auto opened = files::AtomicWriter::open(req.record);
    if (!opened) return failure(opened.status());
    rec_file = std::move(*opened);
    recorder = std::make_unique<env::JsonlRecorder>(rec_file->out());
    for (int s = 0; s < envs.size(); ++s) envs.env(s).set_observer(recorder.get());
  }
  ProgressBar bar("eval", req.episodes, !req.json && req.show_prompt == 0);
  auto res = rl::evaluate(policy, envs, {req.episodes, static_cast<uint64_t>(req.seed), req.greedy},
                          [&](long long done, long long) { bar.update(done); });
  bar.finish();
  if (!res) return failure(res.status());
  if (Status ps = policy.error(); !ps.is_ok()) return failure(ps);
  if (Status rs = sc.reward_error(); !rs.is_ok()) return failure(rs);
  if (rec_file) {
    for (int s = 0; s < envs.size(); ++s) envs.env(s).set_observer(nullptr);
    recorder.reset();
    if (Status ws = rec_file->commit(); !ws.is_ok()) return failure(ws);
  }
  nlohmann::json hist = nlohmann::json::object();
  for (size_t k = 0; k < rl::kActionBins.size(); ++k) {
    char key[16];
    std::snprintf(key, sizeof key, "%g", rl::kActionBins[k]);
    hist[key] = res->action_counts[k];
  }
  if (req.json) {
    nlohmann::json j = {{"success_rate", res->success_rate},
                        {"mean_reward", res->mean_reward},
                        {"std_reward", res->std_reward},
                        {"episodes", res->episodes},
                        {"reached_rate", res->reached_rate},
                        {"separation_median_nm", res->separation_median / 1852.0},
                        {"separation_p5_nm", res->separation_p5 / 1852.0},
                        {"decisions", res->decisions()},
                        {"actions", hist},
                        {"most_frequent_share", res->most_frequent_share()},
                        {"greedy", req.greedy}};
    if (!made.prompt.empty()) j["prompt"] = made.prompt;
    if (!elsewhere.empty()) j["warning"] = elsewhere;
    std::printf("%s\n", j.dump().c_str());
    return kExitOk;
  }
  const double decisions = static_cast<double>(res->decisions());
  std::printf("scenario  %s (%s rules; %s)\n", sc.path.c_str(), rules_name(sc.eval_env.rules),
              success_definition(sc).c_str());
  std::printf("policy    %s\n", made.label.c_str());
  if (!made.prompt.empty()) std::printf("prompt    %s\n", made.prompt.c_str());
  std::printf("episodes  %lld, seed %lld, %s actions\n", res->episodes, req.seed,
              req.greedy ? "greedy" : "sampled");
  std::printf("\n  %-10s %-22s %-20s\n", "success", "mean episode reward", "std of episode reward");
  std::printf("  %6.1f %%   %-22.3f %-20.3f\n\n", 100.0 * res->success_rate, res->mean_reward, res->std_reward);
  std::printf("actions  ");
  for (size_t k = 0; k < rl::kActionBins.size(); ++k)
    std::printf(" %g: %lld", rl::kActionBins[k], res->action_counts[k]);
  std::printf("  (most frequent %.1f %% of %.0f decisions)\n", 100.0 * res->most_frequent_share(), decisions);
  std::printf("waypoint reached %.1f %%, %.1f agent decisions and %.1f env steps per episode, %.2f s, "
              "%.0f decisions/s\n",
              100.0 * res->reached_rate, res->mean_decisions, res->mean_steps, res->wall_s,
              res->wall_s > 0 ? decisions / res->wall_s : 0.0);
  std::printf("closest separation per episode (start and step ends): median %.2f NM, 5th percentile %.2f NM\n",
              res->separation_median / 1852.0, res->separation_p5 / 1852.0);
  return kExitOk;
}

int cmd_eval(const ArgV& argv) {
  std::vector<std::string> values = {"--policy", "--checkpoint", "--episodes", "--envs", "--record",
                                     "--show-prompt"};
  values.insert(values.end(), kGpt2PolicyFlags.begin(), kGpt2PolicyFlags.end());
  auto args = Args::parse(argv, with_vm_flags({values, {"--json", "--greedy"}}));
  if (!args) return usage_error("eval", args.status().message());
  if (args->positional().size() != 1) return usage_error("eval", "expected exactly one SCENARIO.lua");
  const std::string kind = args->get_or("--policy", "mlp");
  if (args->has("--checkpoint") && kind != "mlp" && kind != "gpt2")
    return usage_error("eval", "--checkpoint goes with --policy mlp or gpt2");
  script::VmOptions vo;
  script::Scenario sc;
  if (int rc = load_episode_scenario(*args, "eval", vo, sc); rc != kExitOk) return rc;
  auto req = eval_request(*args, sc);
  if (!req) return usage_error("eval", req.status().message());
  auto opts = policy_options(*args, req->seed);
  if (!opts) return usage_error("eval", opts.status().message());
  auto envs = env::VecEnv::make(sc.eval_env, req->envs);
  if (!envs) return failure(envs.status());
  auto made = script::make_policy(kind, sc, *envs, *opts, vo);
  if (!made) {
    if (made.status().code() == Code::kInvalidArgument && made.status().message().rfind("policy '", 0) == 0)
      return usage_error("eval", "--" + made.status().message());
    return failure(made.status());
  }
  if (auto* pp = dynamic_cast<rl::PromptPolicy*>(made->policy.get()); pp && args->has("--chunk"))
    pp->set_chunk_rows(opts->gpt2.spec.chunk_rows);
  return run_eval(*made, *envs, sc, *req, vo);
}

}  // namespace squawk::app
