#include "gpt2/bundle.h"

#include "core/files.h"
#include "core/rng.h"
#include "gpt2/checkpoint.h"

namespace squawk::gpt2 {

Result<const Tokenizer*> Bundle::text_tokenizer() const {
  if (!tokenizer)
    return Status::not_found(source + ": no vocab.json/merges.txt (and the vocabulary of " +
                             std::to_string(model.config().vocab_size) +
                             " is not the byte-level 257)");
  if (tokenizer->vocab_size() > model.config().vocab_size)
    return Status::invalid(source + ": the tokenizer has " + std::to_string(tokenizer->vocab_size()) +
                           " tokens, the model " + std::to_string(model.config().vocab_size));
  return &*tokenizer;
}

Result<Bundle> load_bundle(const std::string& dir, uint64_t seed) {
  if (dir == "tiny") {
    SQUAWK_ASSIGN_OR_RETURN(Model m, Model::create(Config::tiny()));
    Rng rng(seed);
    m.init_random(rng);
    return Bundle{std::move(m), Tokenizer::bytes_only(),
                  "tiny (random, seed " + std::to_string(seed) + ")"};
  }
  SQUAWK_ASSIGN_OR_RETURN(Model m, load_model(dir));
  Bundle b{std::move(m), std::nullopt, dir};
  if (files::exists(dir + "/vocab.json")) {
    SQUAWK_ASSIGN_OR_RETURN(Tokenizer t, Tokenizer::load(dir));
    b.tokenizer = std::move(t);
  } else if (b.model.config().vocab_size == 257) {
    b.tokenizer = Tokenizer::bytes_only();
  }
  return b;
}

}  // namespace squawk::gpt2
