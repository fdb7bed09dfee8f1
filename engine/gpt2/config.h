// GPT-2 hyper-parameters (the fields of a Hugging Face GPT-2 config.json).
#pragma once

#include <string>

#include "core/status.h"

namespace squawk::gpt2 {

struct Config {
  int n_layer = 12;          // transformer blocks (L)
  int n_head = 12;           // attention heads (NH)
  int n_embd = 768;          // channels (C); a multiple of n_head
  int n_ctx = 1024;          // learned positions (maxT); HF "n_positions"
  int vocab_size = 50257;    // token embeddings (V)
  float ln_eps = 1e-5f;      // LayerNorm epsilon; HF "layer_norm_epsilon"

  // Errors name the first field out of range.
  Status validate() const;
  // Parameter count of the model (token/position embeddings, blocks, final LN).
  long long num_params() const;

  // GPT-2 small: 12 layers, 12 heads, 768 wide, 1024 positions, 50257 tokens.
  static Config gpt2_small() { return {}; }
  // The offline tiny model: 2 layers, 4 heads, 64 wide, 256 positions, and the
  // byte-level vocabulary (256 bytes + <|endoftext|>).
  static Config tiny() { return {2, 4, 64, 256, 257, 1e-5f}; }
};

}  // namespace squawk::gpt2
