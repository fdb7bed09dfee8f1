#include "gpt2/generate.h"

#include <algorithm>
#include <cmath>

#include "core/rng.h"

namespace squawk::gpt2 {

int sample_top_k(const std::vector<float>& logits, int top_k, Rng& rng) {
  std::vector<int> idx(logits.size());
  for (size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<int>(i);
  const int k = std::max(1, std::min(top_k, static_cast<int>(idx.size())));
  std::partial_sort(idx.begin(), idx.begin() + k, idx.end(),
                    [&](int x, int y) { return logits[x] > logits[y]; });
  std::vector<double> p(k);
  double sum = 0.0;
  for (int i = 0; i < k; ++i)
    sum += p[i] = std::exp(static_cast<double>(logits[idx[i]]) - logits[idx[0]]);
  double u = rng.uniform() * sum;
  for (int i = 0; i < k; ++i)
    if ((u -= p[i]) <= 0) return idx[i];
  return idx[k - 1];
}

Result<std::string> generate(const Model& model, const Tokenizer& tok, const std::string& prompt,
                             const GenerateOptions& opt,
                             const std::function<void(const std::string&)>& on_piece) {
  if (opt.max_tokens < 0 || opt.top_k < 1)
    return Status::invalid("generate: max_tokens must be >= 0 and top_k >= 1");
  SQUAWK_ASSIGN_OR_RETURN(std::vector<int> ids, tok.encode(prompt));
  if (ids.empty()) {
    if (!tok.eot()) return Status::invalid("generate: empty prompt and no <|endoftext|> to start from");
    ids.push_back(*tok.eot());
  }
  PrefixCache cache;
  std::vector<float> hidden, logits;
  SQUAWK_RETURN_IF_ERROR(model.extend(cache, ids, &hidden));
  Rng rng(opt.seed);
  std::string out;
  for (int i = 0; i < opt.max_tokens && cache.len < model.config().n_ctx; ++i) {
    SQUAWK_RETURN_IF_ERROR(model.lm_logits(hidden, logits));
    const int next = sample_top_k(logits, opt.top_k, rng);
    if (tok.eot() && next == *tok.eot()) break;
    SQUAWK_ASSIGN_OR_RETURN(std::string piece, tok.decode(std::vector<int>{next}));
    if (on_piece) on_piece(piece);
    out += piece;
    SQUAWK_RETURN_IF_ERROR(model.extend(cache, std::vector<int>{next}, &hidden));
  }
  return out;
}

}  // namespace squawk::gpt2
