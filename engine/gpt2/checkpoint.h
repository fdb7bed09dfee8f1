// Hugging Face GPT-2 folders: config.json + model.safetensors (+ vocab.json,
// merges.txt for the tokenizer, see bpe.h).
//
// Reading accepts both tensor-name layouts found in practice: the hub's gpt2
// file (bare names such as h.0.attn.c_attn.weight, plus causal-mask buffers
// h.N.attn.bias / h.N.attn.masked_bias, which are ignored) and save_pretrained's
// (names prefixed "transformer.", lm_head.weight tied to wte or absent; an
// lm_head.weight that differs from wte is refused).
// Weights may be F32, F16 or BF16; GPT-2's Conv1D weights are stored [in, out],
// the layout of params.h, so no transpose happens. Extra tensors of the model
// (heads) are read when present and left untouched when absent.
// Writing produces save_pretrained's layout in F32 (transformer.-prefixed
// names, no lm_head.weight), extras under their own names.
#pragma once

#include <string>
#include <vector>

#include "core/status.h"
#include "gpt2/config.h"
#include "gpt2/model.h"
#include "gpt2/safetensors.h"

namespace squawk::gpt2 {

// config.json text <-> Config. Required keys: n_layer, n_head, n_embd,
// vocab_size, and n_positions (or n_ctx); layer_norm_epsilon optional;
// activation_function, when present, must be "gelu_new".
Result<Config> parse_hf_config(const std::string& json_text);
std::string hf_config_json(const Config& cfg);

// Copies every tensor of `file` into `model`, checking names, shapes, dtypes.
Status load_weights(const SafetensorsFile& file, Model& model);

// Reads DIR/config.json and DIR/model.safetensors.
Result<Model> load_model(const std::string& dir, const std::vector<TensorSpec>& extras = {});
// Writes DIR/config.json and DIR/model.safetensors (creates DIR).
Status save_model(const std::string& dir, const Model& model);

}  // namespace squawk::gpt2
