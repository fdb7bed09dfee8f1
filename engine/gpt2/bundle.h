// A model with its tokenizer, loaded from a Hugging Face folder or built as
// the offline tiny model.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "core/status.h"
#include "gpt2/bpe.h"
#include "gpt2/model.h"

namespace squawk::gpt2 {

struct Bundle {
  Model model;
  std::optional<Tokenizer> tokenizer;  // absent when the folder has none
  std::string source;                  // the folder, or "tiny (random, seed N)"
  // The tokenizer, or an error naming the folder when there is none or when
  // it has more tokens than the model.
  Result<const Tokenizer*> text_tokenizer() const;
};

// `dir` is a folder with config.json + model.safetensors (and vocab.json +
// merges.txt; without them a 257-token model gets the byte-level vocabulary),
// or the word "tiny": Config::tiny() initialised by init_random from `seed`,
// with Tokenizer::bytes_only().
Result<Bundle> load_bundle(const std::string& dir, uint64_t seed = 0);

}  // namespace squawk::gpt2
