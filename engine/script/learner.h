// Learner: the trainable policy of a training run, built fresh or from a
// checkpoint, for `squawk train` (MLP and GPT-2) and squawk.rl.train alike.
//
// kind "mlp": a fresh MlpPolicy from the scenario's policy table initialised
// from Rng(seed), or a checkpoint's (rl/checkpoint.h). kind "gpt2": a fresh
// prompt policy (make_gpt2_policy with options.gpt2) or a checkpoint's
// (rl/prompt_checkpoint.h). With `mirror` the policy is mirror-symmetric
// (env::observation_mirror of the scenario's training environment).
// From a checkpoint: `resume` keeps its counters (episodes, updates: the
// schedules go on, `squawk train --resume`); otherwise they start at zero with
// `seed` (`--init`; a GPT-2 checkpoint becomes mirror-symmetric with `mirror`).
// Either way restore holds the learner state (Adam moments, value baseline)
// for Trainer::restore.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "core/path_rules.h"
#include "core/status.h"
#include "rl/checkpoint.h"
#include "rl/policy.h"
#include "rl/prompt_checkpoint.h"
#include "rl/vpg.h"
#include "script/policy_factory.h"
#include "script/scenario.h"
#include "script/vm.h"

namespace squawk::script {

struct LearnerOptions {
  std::string kind = "mlp";  // "mlp" | "gpt2"
  Gpt2PolicyOptions gpt2;    // gpt2: base model, seeds, prompt, spec
  bool mirror = false;
  std::string from;     // checkpoint to start from; "" = a fresh policy
  bool resume = false;  // from: keep its counters
  uint64_t seed = 0;    // the run's seed (mlp: the initialisation)
  // Sandboxed callers: the read check for the files a checkpoint names.
  const paths::PathRules* reads = nullptr;
};

struct Learner {
  std::unique_ptr<rl::Policy> policy;
  bool is_gpt2 = false;
  rl::Checkpoint mlp;  // mlp: spec and counters (what its checkpoint holds besides parameters)
  rl::PromptCheckpoint gpt2;              // gpt2: source, config, tokenizer, spec and counters
  std::optional<rl::TrainState> restore;  // from a checkpoint: the learner state to go on from

  rl::TrainState& state() { return is_gpt2 ? static_cast<rl::TrainState&>(gpt2) : mlp; }
  rl::TrainProgress& progress() { return state().progress; }
  const env::ObservationMirror& mirror() const {
    return is_gpt2 ? gpt2.spec.mirror : mlp.spec.mirror;
  }
  // Writes the checkpoint at `path`: with `trainer`, the policy and its learner
  // state (what resume needs); without, the MLP policy alone.
  Status save(const std::string& path, rl::Trainer* trainer);
};

// `sc`'s policy table takes the mirror (mlp). Errors name the kind, the file or the mismatch.
Result<Learner> make_learner(const LearnerOptions& options, Scenario& sc, const VmOptions& vm);

}  // namespace squawk::script
