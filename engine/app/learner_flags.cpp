#include "app/learner_flags.h"

#include "dist/comm.h"

namespace squawk::app {

const std::vector<std::string>& learner_flags() {
  static const std::vector<std::string> flags = {
      "--episodes", "--estimator", "--envs",    "--eval-every", "--eval-episodes", "--lr",
      "--lr-final", "--episodes-per-update",    "--gamma",      "--lambda",        "--entropy",
      "--entropy-final", "--epochs", "--minibatches", "--clip", "--value-iters", "--branch-fraction",
      "--stop-at", "--validation-seed"};
  return flags;
}

Result<uint64_t> validation_seed(const Args& args, uint64_t eval_seed) {
  constexpr uint64_t kOffset = 1000003;
  auto seed = args.get_int("--validation-seed", static_cast<long long>(eval_seed + kOffset));
  if (!seed) return seed.status();
  if (*seed < 0) return Status::invalid("--validation-seed: expected a seed >= 0, got " + std::to_string(*seed));
  return static_cast<uint64_t>(*seed);
}

Status apply_learner_flags(const Args& args, long long episodes_default, double lr_default, rl::TrainConfig& cfg) {
  auto episodes = args.get_int("--episodes", episodes_default);
  auto envs_n = args.get_int("--envs", cfg.num_envs);
  auto eval_every = args.get_int("--eval-every", cfg.eval_every);
  auto eval_eps = args.get_int("--eval-episodes", cfg.eval_episodes);
  auto lr = args.get_double("--lr", lr_default);
  auto lr_final = args.get_double("--lr-final", cfg.lr_final);
  auto seed = args.get_int("--seed", static_cast<long long>(cfg.seed));
  auto per_update = args.get_int("--episodes-per-update", cfg.episodes_per_update);
  auto gamma = args.get_double("--gamma", cfg.gamma);
  auto lambda = args.get_double("--lambda", cfg.lambda);
  auto entropy = args.get_double("--entropy", cfg.entropy_coef);
  auto entropy_final = args.get_double("--entropy-final", 0.0);
  auto epochs = args.get_int("--epochs", cfg.epochs);
  auto minibatches = args.get_int("--minibatches", cfg.minibatches);
  auto clip = args.get_double("--clip", cfg.clip);
  auto value_iters = args.get_int("--value-iters", cfg.value_iters);
  auto branch = args.get_double("--branch-fraction", cfg.branch_fraction);
  auto stop_at = args.get_int("--stop-at", 0);
  for (const Status& st : {episodes.status(), envs_n.status(), eval_every.status(), eval_eps.status(), lr.status(),
                           lr_final.status(), seed.status(), per_update.status(), gamma.status(), lambda.status(),
                           entropy.status(), entropy_final.status(), epochs.status(), minibatches.status(),
                           clip.status(), value_iters.status(), branch.status(), stop_at.status()})
    SQUAWK_RETURN_IF_ERROR(st);
  cfg.set_lr(*lr, args.has("--lr-final") ? std::optional<double>(*lr_final) : std::nullopt);
  if (args.has("--entropy-final")) cfg.entropy_final = *entropy_final;  // else the scenario's (none: constant)
  cfg.episodes = *episodes;
  cfg.stop_at = *stop_at;
  cfg.num_envs = static_cast<int>(*envs_n);
  cfg.eval_every = *eval_every;
  cfg.eval_episodes = *eval_eps;
  cfg.seed = static_cast<uint64_t>(*seed);
  cfg.episodes_per_update = static_cast<int>(*per_update);
  cfg.gamma = *gamma;
  cfg.lambda = *lambda;
  cfg.entropy_coef = *entropy;
  cfg.epochs = static_cast<int>(*epochs);
  cfg.minibatches = static_cast<int>(*minibatches);
  cfg.clip = *clip;
  cfg.value_iters = static_cast<int>(*value_iters);
  cfg.branch_fraction = *branch;
  cfg.estimator = args.get_or("--estimator", cfg.estimator);
  if (args.has("--stop-at") && *stop_at < 1) return Status::invalid("--stop-at expects a positive integer");
  return cfg.validate();
}

std::string episodes_text(const rl::TrainConfig& cfg) {
  std::string s = std::to_string(cfg.episodes) + " episodes";
  if (cfg.stop_at > 0) s += ", stopping at " + std::to_string(cfg.stop_at);
  return s;
}

std::string ranks_text() {
  if (dist::size() == 1) return "";
  return ", data-parallel on " + std::to_string(dist::size()) + " ranks (" + dist::describe() + ")";
}

Status apply_mirror_flag(const Args& args, const env::HorizontalCrConfig& env, env::ObservationMirror& mirror) {
  if (!args.has("--mirror")) return Status::ok();
  SQUAWK_ASSIGN_OR_RETURN(mirror, env::observation_mirror(env));
  return Status::ok();
}

Status check_resume_mirror(const std::string& ckpt_path, const env::ObservationMirror& checkpoint,
                           const env::ObservationMirror& wanted) {
  if (checkpoint.empty() == wanted.empty()) return Status::ok();
  return Status::invalid("checkpoint " + ckpt_path + " holds a policy " +
                         (checkpoint.empty() ? "without" : "with") + " mirror symmetry, but this run asks for " +
                         (wanted.empty() ? "none (no --mirror, no policy.mirror)" : "it (--mirror or policy.mirror)"));
}

}  // namespace squawk::app
