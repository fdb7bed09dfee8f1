// Construction of the GPT-2 prompt policy (rl/prompt_policy.h) for the CLI:
// base model from "tiny" or a Hugging Face folder, the Lua prompt template
// (script/prompt_renderer.h) as its renderer, and fine-tuned tails from
// checkpoints (rl/prompt_checkpoint.h). Also `squawk train/eval --policy gpt2`.
//
// The offline tiny model: Config::tiny()'s shape (2 blocks, 4 heads, 64 wide)
// with kTinyContext positions (the paper's prompt is ~270 tokens) and a
// vocabulary learned by the BPE trainer (kTinyMerges merges) on the prompts
// the template renders for the first kTinyVocabEpisodes training episodes of
// the scenario (seed 0) under the zero action, so numbers and the fixed lines
// tokenise compactly; weights from init_random(model_seed). Its default
// trainable depth is both blocks (kTinyTrainableBlocks): a random block is no
// pretrained feature extractor worth freezing, so everything above the frozen
// embeddings trains (k = 2 reached 96.5 % in 2048 episodes; k = 1 was not
// tried); a real GPT-2 folder keeps the paper's k = 1.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "app/cli.h"
#include "app/subcommands.h"
#include "core/status.h"
#include "env/horizontal_cr.h"
#include "rl/prompt_checkpoint.h"
#include "rl/prompt_policy.h"
#include "script/vm.h"

namespace squawk::app {

inline constexpr int kTinyMerges = 512;
inline constexpr int kTinyContext = 512;
inline constexpr int kTinyVocabEpisodes = 48;
inline constexpr int kTinyTrainableBlocks = 2;
// The fine-tuned tiny policy `squawk eval --policy gpt2` uses by default.
inline constexpr const char* kShippedGpt2Checkpoint = "models/horizontal_cr_gpt2_tiny.ckpt";
inline constexpr const char* kDefaultPromptFile = "prompts/observation.lua";

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
                                    const script::VmOptions& vm);
// The checkpoint's policy: base rebuilt from its source, tail copied in.
// `prompt` overrides the template recorded in the checkpoint when not empty.
Result<Gpt2Policy> gpt2_policy_from_checkpoint(const rl::PromptCheckpoint& ckpt, const std::string& prompt,
                                               const script::VmOptions& vm);

// The policy flags shared by train, eval and table3.
inline const std::vector<std::string> kGpt2PolicyFlags = {"--model", "--model-seed", "--prompt", "--head",
                                                          "--blocks", "--chunk"};
// Gpt2PolicyOptions from --model --model-seed --prompt --head --blocks --chunk.
Result<Gpt2PolicyOptions> gpt2_options(const Args& args);

// True when argv selects --policy gpt2 (the hook of cmd_train / cmd_eval).
bool wants_gpt2(const ArgV& argv);
int cmd_train_gpt2(const ArgV& argv);
int cmd_eval_gpt2(const ArgV& argv);

}  // namespace squawk::app
