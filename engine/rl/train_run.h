// train_run: the schedule of one policy-gradient run, shared by `squawk train`
// (MLP and GPT-2) and Lua's squawk.rl.train (script/bind_rl.cpp).
//
// run_training() takes Trainer updates (vpg.h) until progress.episodes reaches
// cfg.end_episodes(). After each update it adds the batch to `progress`
// (episodes, updates, and wall_s = its value on entry plus this call's wall
// time), and when progress.episodes reaches the next multiple of
// cfg.eval_every (every update's end counts; with eval_every 0 only the run's
// end) or the run's end, it evaluates the policy (sampled) on
// cfg.eval_episodes episodes of `validation_seed` on `eval_envs`
// (evaluator.h). Then on_update(report) runs: false ends the run (kStopped),
// an error ends it with that error. A policy failure (Policy::error) ends it
// too, before on_update, and so does an environment's (BatchEnv::error of
// the training or the evaluation batch).
// `within` is Trainer::update's progress callback: its false abandons the
// update in progress and ends the run kInterrupted, `progress` as after the
// last finished update.
#pragma once

#include <cstdint>
#include <functional>

#include "core/status.h"
#include "env/batch_env.h"
#include "rl/checkpoint.h"
#include "rl/evaluator.h"
#include "rl/vpg.h"

namespace squawk::rl {

struct UpdateReport {
  const UpdateStats& stats;
  const TrainProgress& progress;  // after this update
  const EvalResult* eval;         // this update's evaluation, nullptr when none was due
  double update_s;                // [s] wall time of the update (collection and steps)
};

enum class RunEnd { kFinished, kStopped, kInterrupted };

using OnUpdate = std::function<Result<bool>(const UpdateReport&)>;

Result<RunEnd> run_training(Trainer& trainer, Policy& policy, env::BatchEnv& eval_envs,
                            const TrainConfig& cfg, uint64_t validation_seed,
                            TrainProgress& progress, const UpdateProgress& within,
                            const OnUpdate& on_update);

}  // namespace squawk::rl
