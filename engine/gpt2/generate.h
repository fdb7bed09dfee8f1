// Text generation: the prompt runs once into a KV cache, then one token at a
// time is sampled from the LM logits and appended through the cache.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/status.h"
#include "gpt2/bpe.h"
#include "gpt2/model.h"

namespace squawk::gpt2 {

struct GenerateOptions {
  int max_tokens = 32;  // new tokens at most; generation also stops at
                        // <|endoftext|> and at the model's context length
  int top_k = 40;       // sample among the k most likely tokens (1 = greedy)
  uint64_t seed = 0;    // of the engine Rng drawing the samples
};

// Index of a token drawn from softmax over the top_k largest logits.
int sample_top_k(const std::vector<float>& logits, int top_k, Rng& rng);

// The generated text (without the prompt). An empty prompt starts from
// <|endoftext|>. on_piece, when given, receives each new token's text as it
// is produced. Errors: invalid options, a prompt longer than the context.
Result<std::string> generate(const Model& model, const Tokenizer& tok, const std::string& prompt,
                             const GenerateOptions& opt,
                             const std::function<void(const std::string&)>& on_piece = {});

}  // namespace squawk::gpt2
