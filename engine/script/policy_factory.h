// Policy construction by kind, for the CLI (train, eval, table3, demo) and
// Lua (squawk.env.evaluate): one make_policy(kind, scenario, options).
//
// Kinds: "random" (an untrained MLP initialised from options.seed), "zero"
// (never turn), "constant:V" (always action V, units of the heading step,
// V in [-1, 1]), "turn-hold:V" (action V while flying at the waypoint, else
// 0: the rule baseline), "mvp" (BlueSky's MVP steering the ownship, reads the
// VecEnv's state), "lookahead" (the planner over the simulator, an upper
// reference that reads the true state and the future), "rollout:P" (one step
// of policy improvement over the discrete policy P, e.g. rollout:mlp; reads
// the simulator too), "mlp" (a trained MLP checkpoint, the shipped one by
// default), "gpt2" (the GPT-2 prompt policy: a checkpoint, the shipped
// fine-tuned tiny one by default, or with gpt2.model set a base model with a
// fresh head).
//
// The GPT-2 prompt policy (rl/prompt_policy.h): base model from "tiny" or a
// Hugging Face folder, the Lua prompt template (script/prompt_renderer.h) as
// its renderer, and fine-tuned tails from checkpoints (rl/prompt_checkpoint.h).
// The offline tiny model: Config::tiny()'s shape (2 blocks, 4 heads, 64 wide)
// with kTinyContext positions (the paper's prompt is ~270 tokens) and a
// vocabulary learned by the BPE trainer (kTinyMerges merges) on the prompts
// the template renders for the first kTinyVocabEpisodes training episodes of
// the scenario (seed 0) under the zero action, so numbers and the fixed lines
// tokenise compactly; weights from init_random(model_seed). Its default
// trainable depth is both blocks (kTinyTrainableBlocks): a random block is no
// pretrained feature extractor worth freezing; a real GPT-2 folder keeps the
// paper's k = 1.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/status.h"
#include "env/horizontal_cr.h"
#include "env/vec_env.h"
#include "rl/policy.h"
#include "rl/prompt_checkpoint.h"
#include "rl/prompt_policy.h"
#include "script/scenario.h"
#include "script/vm.h"

namespace squawk::script {

inline constexpr int kTinyMerges = 512;
inline constexpr int kTinyContext = 512;
inline constexpr int kTinyVocabEpisodes = 48;
inline constexpr int kTinyTrainableBlocks = 2;
// The shipped checkpoints (resource paths, core/paths.h).
inline constexpr const char* kShippedMlpCheckpoint = "models/horizontal_cr_mlp.ckpt";
// The same network made mirror-symmetric (rl/mirror.h), trained with --mirror.
inline constexpr const char* kShippedMlpMirrorCheckpoint = "models/horizontal_cr_mlp_mirror.ckpt";
inline constexpr const char* kShippedGpt2Checkpoint = "models/horizontal_cr_gpt2_tiny.ckpt";
// The GPT-2 policy made mirror-symmetric, fine-tuned with --mirror from the same pretrained model.
inline constexpr const char* kShippedGpt2MirrorCheckpoint = "models/horizontal_cr_gpt2_tiny_mirror.ckpt";
inline constexpr const char* kDefaultPromptFile = "prompts/observation.lua";
// GPT-2 training defaults where the scenario's train table is the MLP's:
// the run's episodes, and the Adam step size on a Hugging Face folder.
inline constexpr long long kGpt2TrainEpisodes = 20000;
inline constexpr double kGpt2FolderLr = 1e-5;

struct Gpt2PolicyOptions {
  std::string model = "tiny";  // "tiny" | Hugging Face folder
  uint64_t model_seed = 0;     // tiny: weights; both: action-head init
  std::string prompt;          // template file; "" = the shipped prompts/observation.lua
  // trainable_blocks < 0 (the default here) picks the model's default depth.
  rl::PromptPolicySpec spec{.trainable_blocks = -1};
};

struct Gpt2Policy {
  std::unique_ptr<rl::PromptPolicy> policy;
  rl::PromptCheckpoint meta;  // source, seed, config, tokenizer, spec, prompt (no params)
};

// A fresh policy (untrained head). `env` supplies the tiny vocabulary's prompts.
Result<Gpt2Policy> make_gpt2_policy(const Gpt2PolicyOptions& opts, const env::HorizontalCrConfig& env,
                                    const VmOptions& vm);
// The checkpoint's policy: base rebuilt from its source, tail copied in.
// `prompt` overrides the template recorded in the checkpoint when not empty.
// With `reads`, the files the checkpoint names (its prompt template, its
// model folder) must pass that read check (a sandboxed caller's rules).
Result<Gpt2Policy> gpt2_policy_from_checkpoint(const rl::PromptCheckpoint& ckpt, const std::string& prompt,
                                               const VmOptions& vm, const paths::PathRules* reads = nullptr);

struct PolicyOptions {
  std::string checkpoint;      // mlp, gpt2: "" = the shipped one
  uint64_t seed = 0;           // random: initialisation seed
  bool gpt2_fresh = false;     // gpt2: build gpt2.model with a fresh head instead of a checkpoint
  Gpt2PolicyOptions gpt2;      // gpt2: model (with gpt2_fresh), prompt, spec
  // Sandboxed callers: the read check for files named inside checkpoints
  // (nullptr: the caller trusts them, as the CLI does with its own flags).
  const paths::PathRules* reads = nullptr;
};

struct MadePolicy {
  std::unique_ptr<rl::Policy> policy;
  std::string label;           // what was built, for headers ("mlp (models/...)")
  std::string trained_on;      // scenario file of the checkpoint's training ("" = unknown / none)
  std::string prompt;          // gpt2: the prompt template file in use
};

// The policy of `kind` for `sc`'s environment `envs` (MVP keeps a reference
// to it). Errors name the kind or file and what was expected.
Result<MadePolicy> make_policy(const std::string& kind, const Scenario& sc, const env::VecEnv& envs,
                               const PolicyOptions& options, const VmOptions& vm);

}  // namespace squawk::script
