// squawk env: environments written as Lua files (envs/*.lua, script/lua_env.h).
//
//   squawk env run ENV.lua [--policy random|zero|constant:V[,V...]|script:FILE|mlp:CKPT]
//                          [--greedy] [--episodes N] [--seed S] [--json]
// Episode k (0-based) resets with seed S + k; the random policy draws each
// action uniformly in the declared Box from Rng(S); a script policy
// (script/lua_policy.h) is reset with the episode's seed and asked for every
// action. mlp:CKPT is a checkpoint of `squawk train --env`
// (app/cli_train_env.h): its categorical head picks a class of the action grid
// (script/lua_batch_env.h) from the observation, sampled from Rng(S) (the mode
// with --greedy); a Gaussian head (train --gaussian) samples each action
// component likewise (the means with --greedy), clipped to the Box (box_action()).
// Prints the environment, then the episode statistics of EpisodeStats.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/cli.h"
#include "app/subcommands.h"
#include "app/vm_options.h"
#include "core/files.h"
#include "core/rng.h"
#include "core/text.h"
#include "rl/mlp_policy.h"
#include "script/grid_policy.h"
#include "script/lua_batch_env.h"
#include "script/lua_env.h"
#include "script/lua_policy.h"

namespace squawk::app {

namespace {

struct EnvPolicy {
  bool random = false;
  std::string script;                  // the policy file of script:FILE, or ""
  std::vector<double> constant;        // the action when neither random, scripted nor an MLP
  script::GridPolicy grid;             // mlp:CKPT (grid.mlp null otherwise)
};

// What `squawk env run` reports over its episodes. Success counts episodes
// whose last step's info.success was true, over those that reported one.
// Action shares: for each action component, the fraction of steps whose
// value lies in the lower, middle and upper third of [low, high] (the upper
// third includes high).
struct EpisodeStats {
  long long episodes = 0, steps = 0, terminated = 0, truncated = 0;
  long long success = 0, success_known = 0;
  double reward_sum = 0, reward_sum2 = 0;
  std::vector<std::array<long long, 3>> thirds;  // per action component

  void count_action(std::span<const double> a, const script::LuaEnvSpec& spec) {
    for (size_t k = 0; k < a.size(); ++k) {
      const double u = (a[k] - spec.action_low[k]) / (spec.action_high[k] - spec.action_low[k]);
      ++thirds[k][u < 1.0 / 3 ? 0 : u < 2.0 / 3 ? 1 : 2];
    }
  }
  double mean() const { return reward_sum / static_cast<double>(episodes); }
  double sd() const {
    const double m = mean();
    return std::sqrt(std::max(0.0, reward_sum2 / static_cast<double>(episodes) - m * m));
  }
  double share(size_t k, int third) const {
    return static_cast<double>(thirds[k][static_cast<size_t>(third)]) /
           static_cast<double>(std::max(1LL, steps));
  }
};

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
  if (p.rfind("script:", 0) == 0 && p.size() > 7) {
    pol.script = p.substr(7);
    return pol;
  }
  if (p.rfind("mlp:", 0) == 0) {
    SQUAWK_ASSIGN_OR_RETURN(pol.grid, script::load_grid_policy(p.substr(4), spec));
    return pol;
  }
  return Status::invalid("--policy '" + p +
                         "': expected random, zero, constant:V[,V...], script:FILE or mlp:CKPT");
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
  if (args->has("--greedy") && !policy->grid.mlp)
    return usage_error("env", "--greedy goes with --policy mlp:CKPT");
  const bool greedy = args->has("--greedy");
  std::vector<float> obs(static_cast<size_t>(spec.observation_size));
  const int row = 0;

  std::unique_ptr<script::LuaPolicy> scripted;
  if (!policy->script.empty()) {
    if (!files::exists(policy->script))
      return failure(Status::not_found("no policy file '" + policy->script + "'"));
    auto loaded = script::LuaPolicy::load(policy->script, *opts, spec);
    if (!loaded) return failure(Status::invalid(shown_error(loaded.status().message())));
    scripted = std::move(*loaded);
  }

  const uint64_t seed = opts->seed;
  Rng rng(seed);
  std::vector<double> action(static_cast<size_t>(spec.action_size()));
  EpisodeStats stats;
  stats.thirds.assign(action.size(), {0, 0, 0});
  const auto t0 = std::chrono::steady_clock::now();
  for (long long k = 0; k < *episodes; ++k) {
    const uint64_t episode_seed = seed + static_cast<uint64_t>(k);
    Status st = e.reset(episode_seed);
    if (st.is_ok() && scripted) st = scripted->reset(episode_seed);
    if (!st.is_ok()) return failure(Status::invalid(shown_error(st.message())));
    double total = 0;
    while (true) {
      if (scripted) {
        if (Status a = scripted->act(e.observation(), action); !a.is_ok())
          return failure(Status::invalid(shown_error(a.message())));
      } else if (policy->grid.mlp) {
        for (size_t j = 0; j < obs.size(); ++j) obs[j] = static_cast<float>(e.observation()[j]);
        rl::ActionSample choice;
        policy->grid.mlp->act(obs, 1, {&row, 1}, {&rng, 1}, greedy, {&choice, 1});
        script::policy_action(spec, policy->grid, choice, action);
      } else {
        for (size_t a = 0; a < action.size(); ++a)
          action[a] = policy->random ? rng.uniform(spec.action_low[a], spec.action_high[a])
                                     : policy->constant[a];
      }
      stats.count_action(action, spec);
      auto r = e.step(action);
      if (!r) return failure(Status::invalid(shown_error(r.status().message())));
      total += r->reward;
      if (r->terminated || r->truncated) {
        stats.terminated += r->terminated;
        stats.truncated += !r->terminated && r->truncated;
        if (r->success) {
          ++stats.success_known;
          stats.success += *r->success;
        }
        break;
      }
    }
    ++stats.episodes;
    stats.steps += e.steps();
    stats.reward_sum += total;
    stats.reward_sum2 += total * total;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double n = static_cast<double>(stats.episodes);
  const double steps_per_s = static_cast<double>(stats.steps) / seconds;
  if (args->has("--json")) {
    std::string shares;
    for (size_t a = 0; a < action.size(); ++a)
      shares += std::string(a ? ", " : "") + "[" + text::fmt_double(stats.share(a, 0)) + ", " +
                text::fmt_double(stats.share(a, 1)) + ", " + text::fmt_double(stats.share(a, 2)) +
                "]";
    const std::string success =
        stats.success_known ? std::to_string(stats.success) : std::string("null");
    std::printf(
        "{\"env\": \"%s\", \"policy\": %s, \"episodes\": %lld, \"seed\": %llu, "
        "\"mean_reward\": %.17g, "
        "\"std_reward\": %.17g, \"mean_length\": %.17g, \"terminated\": %lld, \"truncated\": %lld, "
        "\"success\": %s, \"success_reported\": %lld, \"action_shares\": [%s], "
        "\"steps_per_s\": %.6g}\n",
        spec.id.c_str(), nlohmann::json(policy_name).dump().c_str(), stats.episodes,
        static_cast<unsigned long long>(seed), stats.mean(), stats.sd(),
        static_cast<double>(stats.steps) / n, stats.terminated, stats.truncated, success.c_str(),
        stats.success_known, shares.c_str(), steps_per_s);
    return kExitOk;
  }
  std::printf("%s (%s): observation %d numbers, action %d in [%s, %s], at most %d steps\n",
              spec.id.c_str(), file.c_str(), spec.observation_size, spec.action_size(),
              text::fmt_double(spec.action_low[0]).c_str(),
              text::fmt_double(spec.action_high[0]).c_str(), spec.max_episode_steps);
  std::printf("policy %s, %lld episodes from seed %llu\n", policy_name.c_str(), stats.episodes,
              static_cast<unsigned long long>(seed));
  if (stats.success_known)
    std::printf(
        "  success         %lld of %lld (%.1f %%)\n", stats.success, stats.success_known,
        100.0 * static_cast<double>(stats.success) / static_cast<double>(stats.success_known));
  else
    std::printf("  success         not reported (the file's info has no success)\n");
  std::printf("  mean reward     %.4f (std %.4f)\n", stats.mean(), stats.sd());
  std::printf("  mean length     %.2f steps\n", static_cast<double>(stats.steps) / n);
  std::printf("  terminated      %lld of %lld; truncated %lld\n", stats.terminated, stats.episodes,
              stats.truncated);
  for (size_t a = 0; a < action.size(); ++a)
    std::printf("  action %zu thirds %.3f low, %.3f middle, %.3f high\n", a + 1, stats.share(a, 0),
                stats.share(a, 1), stats.share(a, 2));
  std::printf("  speed           %.0f env steps/s\n", steps_per_s);
  return kExitOk;
}

}  // namespace

int cmd_env(const ArgV& argv) {
  if (argv.empty()) return usage_error("env", "missing action: squawk env run ENV.lua");
  if (argv[0] == "run") return env_run(argv);
  return usage_error("env", "unknown action '" + argv[0] + "': expected run");
}

}  // namespace squawk::app
