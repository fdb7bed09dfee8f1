#include "rl/train_run.h"

#include <chrono>
#include <optional>

namespace squawk::rl {

Result<RunEnd> run_training(Trainer& trainer, Policy& policy, env::BatchEnv& eval_envs,
                            const TrainConfig& cfg, uint64_t validation_seed,
                            TrainProgress& progress, const UpdateProgress& within,
                            const OnUpdate& on_update) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const double wall0 = progress.wall_s;
  const long long end = cfg.end_episodes();
  long long next_eval =
      cfg.eval_every > 0 ? (progress.episodes / cfg.eval_every + 1) * cfg.eval_every : cfg.episodes;
  while (progress.episodes < end) {
    const auto u0 = Clock::now();
    const UpdateStats st = trainer.update(within);
    SQUAWK_RETURN_IF_ERROR(trainer.envs().error());
    if (st.interrupted) return RunEnd::kInterrupted;
    const auto now = Clock::now();
    SQUAWK_RETURN_IF_ERROR(policy.error());
    progress.episodes += st.episodes;
    progress.updates = trainer.updates();
    progress.wall_s = wall0 + std::chrono::duration<double>(now - t0).count();
    std::optional<EvalResult> ev;
    if (progress.episodes >= next_eval || progress.episodes >= end) {
      next_eval += cfg.eval_every > 0 ? cfg.eval_every : cfg.episodes;
      SQUAWK_ASSIGN_OR_RETURN(
          ev, evaluate(policy, eval_envs, {cfg.eval_episodes, validation_seed, false}));
    }
    const UpdateReport report{st, progress, ev ? &*ev : nullptr,
                              std::chrono::duration<double>(now - u0).count()};
    SQUAWK_ASSIGN_OR_RETURN(bool go_on, on_update(report));
    if (!go_on) return RunEnd::kStopped;
  }
  return RunEnd::kFinished;
}

}  // namespace squawk::rl
