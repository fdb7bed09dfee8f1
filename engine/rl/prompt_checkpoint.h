// Checkpoints of a fine-tuned GPT-2 prompt policy: the trainable tail (last k
// blocks, ln_f, action head: PromptPolicy::params()) and Adam's state, with
// what is needed to rebuild the frozen base model, written atomically
// (core/files.h write_atomic) and read back with checks.
//
// Format (version 1):
//   line 1: "squawk-gpt2-policy 1"
//   line 2: a JSON object: source ("tiny" or the Hugging Face folder),
//           model_seed (tiny's init_random seed), config (HF config.json
//           text of the base model), the policy spec, vocab / merges (the
//           tokenizer's vocab.json and merges.txt texts), prompt (template
//           path), num_params, has_adam, adam_t, and the training progress
//   then raw little-endian float32: params[num_params], and when has_adam
//   Adam's m[num_params] and v[num_params].
// Loading rebuilds the base from `source` (tiny: config + seed; folder: its
// model.safetensors) and copies the tail over it (the caller does that).
// Errors name the file and what was expected vs found.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/status.h"
#include "rl/checkpoint.h"
#include "rl/prompt_policy.h"

namespace squawk::rl {

struct PromptCheckpoint : TrainState {
  std::string source;       // "tiny" | Hugging Face folder
  uint64_t model_seed = 0;  // tiny: init_random seed of the base model
  std::string config_json;  // HF config.json text of the base model
  PromptPolicySpec spec;
  std::string vocab_json, merges_txt;  // the tokenizer
  std::string prompt;       // template file the policy was trained with
};

Status save_prompt_checkpoint(const std::string& path, const PromptCheckpoint& ckpt);
Result<PromptCheckpoint> load_prompt_checkpoint(const std::string& path);

}  // namespace squawk::rl
