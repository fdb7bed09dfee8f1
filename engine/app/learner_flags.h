// The learner flags `squawk train` shares between the MLP and the GPT-2
// learners. Each overrides one field of the scenario's train table
// (rl::TrainConfig); see `squawk help train`.
#pragma once

#include <string>
#include <vector>

#include "app/cli.h"
#include "core/status.h"
#include "env/horizontal_cr.h"
#include "rl/vpg.h"

namespace squawk::app {

// --episodes --estimator --envs --eval-every --eval-episodes --lr --lr-final
// --episodes-per-update --gamma --lambda --entropy --entropy-final --epochs
// --clip --value-iters --branch-fraction --stop-at --validation-seed (--seed, which apply_learner_flags also reads, comes
// with the VM flags, vm_options.h)
const std::vector<std::string>& learner_flags();

// Applies the learner flags in `args` to `cfg` and validates it. Absent flags
// keep the scenario's values, except --episodes (`episodes_default`) and --lr
// (`lr_default`). Without --lr-final, a step size other than the scenario's
// scales lr_final by the same factor, so the schedule keeps its shape.
// Error: a flag's value does not parse, or the result is out of range.
Status apply_learner_flags(const Args& args, long long episodes_default, double lr_default, rl::TrainConfig& cfg);

// The seed of the episodes a run evaluates on while it trains: --validation-seed,
// by default the scenario's `eval_seed` + 1000003, so that neither the log nor a
// best-checkpoint choice ever sees the episodes `squawk eval` reads by default.
// Error: the flag's value does not parse or is negative.
Result<uint64_t> validation_seed(const Args& args, uint64_t eval_seed);

// "N episodes" for a run's header line, with ", stopping at S" under --stop-at.
std::string episodes_text(const rl::TrainConfig& cfg);

// ", data-parallel on N ranks (LIBRARY)" in a job of several ranks
// (dist/comm.h), "" for one process: for a run's header line.
std::string ranks_text();

// --mirror (a switch): a mirror-symmetric policy (rl/mirror.h). Sets `mirror`
// to env's observation mirror when the flag is given; keeps it otherwise.
// Error: env has no exact mirror (env::observation_mirror).
Status apply_mirror_flag(const Args& args, const env::HorizontalCrConfig& env, env::ObservationMirror& mirror);

// Error unless a resumed checkpoint's policy is mirror-symmetric exactly when
// the run asks for it (scenario key or --mirror).
Status check_resume_mirror(const std::string& ckpt_path, const env::ObservationMirror& checkpoint,
                           const env::ObservationMirror& wanted);

}  // namespace squawk::app
