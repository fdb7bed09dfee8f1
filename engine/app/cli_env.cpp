// squawk env: environments written as Lua files (envs/*.lua, script/lua_env.h).
//
//   squawk env run ENV.lua [--policy random|zero|constant:V[,V...]|mlp:CKPT]
//                          [--greedy] [--episodes N] [--seed S] [--json]
// Episode k (0-based) resets with seed S + k; the random policy draws each
// action uniformly in the declared Box from Rng(S). mlp:CKPT is a checkpoint
// of `squawk train --env` (app/cli_train_env.h): its categorical head picks a
// class of the action grid (script/lua_batch_env.h) from the observation,
// sampled from Rng(S) (the mode with --greedy). Prints the environment,
// then mean episode reward (and its standard deviation), mean episode length,
// the shares of episodes that terminated or were truncated, and env steps/s.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/cli.h"
#include "app/subcommands.h"
#include "app/vm_options.h"
#include "core/files.h"
#include "core/rng.h"
#include "core/text.h"
#include "rl/checkpoint.h"
#include "rl/mlp_policy.h"
#include "script/lua_batch_env.h"
#include "script/lua_env.h"

namespace squawk::app {

namespace {

struct EnvPolicy {
  bool random = false;
  std::vector<double> constant;        // the action when neither random nor an MLP
  std::unique_ptr<rl::MlpPolicy> mlp;  // mlp:CKPT
  int levels = 0;                      // [-] mlp: grid levels per action component
};

// mlp:CKPT: a categorical MLP over `spec`'s action grid that reads its observation.
Status load_mlp(const std::string& path, const script::LuaEnvSpec& spec, EnvPolicy& pol) {
  SQUAWK_ASSIGN_OR_RETURN(rl::Checkpoint ck, rl::load_checkpoint(path));
  SQUAWK_ASSIGN_OR_RETURN(pol.mlp, rl::policy_from_checkpoint(ck));
  const rl::MlpPolicySpec& ps = pol.mlp->spec();
  if (ps.obs_size != spec.observation_size)
    return Status::invalid(path + ": the policy reads " + std::to_string(ps.obs_size) +
                           " observation numbers; " + spec.id + " gives " +
                           std::to_string(spec.observation_size) + " (trained on " +
                           ck.progress.scenario + ")");
  const auto classes = static_cast<int>(ps.action_values.size());
  bool grid = ps.head == "categorical";
  for (int c = 0; grid && c < classes; ++c)
    grid = script::grid_class(ps.action_values[static_cast<size_t>(c)], classes) == c;
  if (!grid)
    return Status::invalid(
        path + ": not a policy over an action grid (squawk train --env writes those; trained on " +
        ck.progress.scenario + ")");
  SQUAWK_ASSIGN_OR_RETURN(pol.levels, script::grid_levels(spec, classes));
  return Status::ok();
}

Result<EnvPolicy> parse_policy(const std::string& p, const script::LuaEnvSpec& spec) {
  EnvPolicy pol;
  const int n = spec.action_size();
  if (p == "random") {
    pol.random = true;
    return pol;
  }
  if (p == "zero") {
    pol.constant.assign(static_cast<size_t>(n), 0.0);
    return pol;
  }
  if (p.rfind("constant:", 0) == 0) {
    for (const std::string& part : text::split(p.substr(9), ',')) {
      char* end = nullptr;
      const double v = std::strtod(part.c_str(), &end);
      if (part.empty() || *end != '\0' || !std::isfinite(v))
        return Status::invalid("--policy " + p + ": '" + part + "' is not a number");
      pol.constant.push_back(v);
    }
    if (static_cast<int>(pol.constant.size()) == 1 && n > 1)
      pol.constant.assign(static_cast<size_t>(n), pol.constant[0]);
    if (static_cast<int>(pol.constant.size()) != n)
      return Status::invalid("--policy " + p + ": the action space has " + std::to_string(n) +
                             " numbers");
    for (int k = 0; k < n; ++k)
      if (pol.constant[k] < spec.action_low[k] || pol.constant[k] > spec.action_high[k])
        return Status::invalid("--policy " + p + ": action " + std::to_string(k + 1) +
                               " is outside [" + text::fmt_double(spec.action_low[k]) + ", " +
                               text::fmt_double(spec.action_high[k]) + "]");
    return pol;
  }
  if (p.rfind("mlp:", 0) == 0) {
    SQUAWK_RETURN_IF_ERROR(load_mlp(p.substr(4), spec, pol));
    return pol;
  }
  return Status::invalid("--policy '" + p +
                         "': expected random, zero, constant:V[,V...] or mlp:CKPT");
}

int env_run(const ArgV& argv) {
  auto args =
      Args::parse(argv, with_vm_flags({{"--policy", "--episodes"}, {"--json", "--greedy"}}));
  if (!args) return usage_error("env", args.status().message());
  if (args->positional().size() != 2)
    return usage_error("env", "usage: squawk env run ENV.lua [flags]");
  const std::string file = args->positional()[1];
  if (!files::exists(file)) return failure(Status::not_found("no environment file '" + file + "'"));
  auto opts = vm_options(*args);
  if (!opts) return usage_error("env", opts.status().message());
  auto episodes = args->get_int("--episodes", 10);
  if (!episodes) return usage_error("env", episodes.status().message());
  if (*episodes < 1) return usage_error("env", "--episodes must be >= 1");
  auto env = script::LuaEnv::load(file, *opts);
  if (!env) return failure(Status::invalid(shown_error(env.status().message())));
  script::LuaEnv& e = **env;
  const script::LuaEnvSpec& spec = e.spec();
  const std::string policy_name = args->get_or("--policy", "random");
  auto policy = parse_policy(policy_name, spec);
  if (!policy) {
    if (policy_name.rfind("mlp:", 0) == 0) return failure(policy.status());
    return usage_error("env", policy.status().message());
  }
  if (args->has("--greedy") && !policy->mlp)
    return usage_error("env", "--greedy goes with --policy mlp:CKPT");
  const bool greedy = args->has("--greedy");
  std::vector<float> obs(static_cast<size_t>(spec.observation_size));
  const int row = 0;

  const uint64_t seed = opts->seed;
  Rng rng(seed);
  std::vector<double> action(static_cast<size_t>(spec.action_size()));
  double sum = 0, sum2 = 0, len_sum = 0;
  long long terminated = 0, truncated = 0, steps = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (long long k = 0; k < *episodes; ++k) {
    if (Status st = e.reset(seed + static_cast<uint64_t>(k)); !st.is_ok())
      return failure(Status::invalid(shown_error(st.message())));
    double total = 0;
    while (true) {
      if (policy->mlp) {
        for (size_t j = 0; j < obs.size(); ++j) obs[j] = static_cast<float>(e.observation()[j]);
        rl::ActionSample choice;
        policy->mlp->act(obs, 1, {&row, 1}, {&rng, 1}, greedy, {&choice, 1});
        script::grid_action(spec, policy->levels, choice.index, action);
      } else {
        for (size_t a = 0; a < action.size(); ++a)
          action[a] = policy->random ? rng.uniform(spec.action_low[a], spec.action_high[a])
                                     : policy->constant[a];
      }
      auto r = e.step(action);
      if (!r) return failure(Status::invalid(shown_error(r.status().message())));
      total += r->reward;
      if (r->terminated || r->truncated) {
        terminated += r->terminated;
        truncated += !r->terminated && r->truncated;
        break;
      }
    }
    steps += e.steps();
    len_sum += e.steps();
    sum += total;
    sum2 += total * total;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double n = static_cast<double>(*episodes);
  const double mean = sum / n;
  const double sd = std::sqrt(std::max(0.0, sum2 / n - mean * mean));
  if (args->has("--json")) {
    std::printf(
        "{\"env\": \"%s\", \"policy\": \"%s\", \"episodes\": %lld, \"seed\": %llu, "
        "\"mean_reward\": %.17g, "
        "\"std_reward\": %.17g, \"mean_length\": %.17g, \"terminated\": %lld, \"truncated\": %lld, "
        "\"steps_per_s\": %.6g}\n",
        spec.id.c_str(), policy_name.c_str(), *episodes, static_cast<unsigned long long>(seed),
        mean, sd, len_sum / n, terminated, truncated, static_cast<double>(steps) / seconds);
    return kExitOk;
  }
  std::printf("%s (%s): observation %d numbers, action %d in [%s, %s], at most %d steps\n",
              spec.id.c_str(), file.c_str(), spec.observation_size, spec.action_size(),
              text::fmt_double(spec.action_low[0]).c_str(),
              text::fmt_double(spec.action_high[0]).c_str(), spec.max_episode_steps);
  std::printf("policy %s, %lld episodes from seed %llu\n", policy_name.c_str(), *episodes,
              static_cast<unsigned long long>(seed));
  std::printf("  mean reward     %.4f (std %.4f)\n", mean, sd);
  std::printf("  mean length     %.2f steps\n", len_sum / n);
  std::printf("  terminated      %lld of %lld; truncated %lld\n", terminated, *episodes, truncated);
  std::printf("  speed           %.0f env steps/s\n", static_cast<double>(steps) / seconds);
  return kExitOk;
}

}  // namespace

int cmd_env(const ArgV& argv) {
  if (argv.empty()) return usage_error("env", "missing action: squawk env run ENV.lua");
  if (argv[0] == "run") return env_run(argv);
  return usage_error("env", "unknown action '" + argv[0] + "': expected run");
}

}  // namespace squawk::app
