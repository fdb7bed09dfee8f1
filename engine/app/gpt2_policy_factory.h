// The CLI half of GPT-2 policy construction (script/policy_factory.h): the
// flags train, eval and table3 share, and `squawk train/eval --policy gpt2`.
#pragma once

#include <string>
#include <vector>

#include "app/cli.h"
#include "app/subcommands.h"
#include "core/status.h"
#include "script/policy_factory.h"

namespace squawk::app {

using script::Gpt2Policy;
using script::Gpt2PolicyOptions;
using script::gpt2_policy_from_checkpoint;
using script::kDefaultPromptFile;
using script::kShippedGpt2Checkpoint;
using script::kShippedMlpCheckpoint;
using script::make_gpt2_policy;

// The policy flags shared by train, eval and table3.
inline const std::vector<std::string> kGpt2PolicyFlags = {"--model", "--model-seed", "--prompt", "--head",
                                                          "--blocks", "--chunk", "--precision"};
// Gpt2PolicyOptions from --model --model-seed --prompt --head --blocks --chunk;
// applies --precision (apply_precision_flag; `announce` as there).
Result<Gpt2PolicyOptions> gpt2_options(const Args& args, bool announce = true);
// Sets the GPT-2 products' precision from --precision bf16|fp32 (absent: the
// fastest here) and, when `announce`, prints the one line saying which to stderr.
Status apply_precision_flag(const Args& args, bool announce = true);

// True when argv selects --policy gpt2 (the hook of cmd_train).
bool wants_gpt2(const ArgV& argv);
// The flags of `squawk train`: the MLP learner's, and with `gpt2` the GPT-2
// learner's too (--init, --train-embeddings and the policy flags).
Args::Spec train_flags(bool gpt2);
int cmd_train_gpt2(const ArgV& argv);
// squawk gpt2 pretrain SCENARIO.lua OUT_DIR (argv after "pretrain").
int cmd_gpt2_pretrain(const ArgV& argv);
// squawk gpt2 imitate SCENARIO.lua OUT.ckpt (argv after "imitate"; cli_gpt2_imitate.cpp).
int cmd_gpt2_imitate(const ArgV& argv);

}  // namespace squawk::app
