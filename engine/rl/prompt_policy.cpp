#include "rl/prompt_policy.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string_view>

#include "nn/categorical.h"
#include "nn/linear.h"
#include "rl/mirror.h"

namespace squawk::rl {

namespace {
constexpr const char* kHeadWeight = "policy.head.weight";
constexpr const char* kHeadBias = "policy.head.bias";
}  // namespace

Status PromptPolicySpec::validate(int n_layer) const {
  if (head != "action" && head != "lm")
    return Status::invalid("gpt2 policy head '" + head + "': expected \"action\" or \"lm\"");
  if (action_values.size() < 2) return Status::invalid("gpt2 policy needs at least 2 action values");
  for (double v : action_values)
    if (!(v >= -1.0 && v <= 1.0))
      return Status::invalid("action value " + std::to_string(v) + " lies outside [-1, 1]");
  if (head == "lm" && lm_texts.size() != action_values.size())
    return Status::invalid("gpt2 policy head \"lm\" needs one text per action: " +
                           std::to_string(lm_texts.size()) + " texts for " +
                           std::to_string(action_values.size()) + " actions");
  if (trainable_blocks < 0 || trainable_blocks > n_layer)
    return Status::invalid("gpt2 trainable blocks " + std::to_string(trainable_blocks) +
                           ": expected 0.." + std::to_string(n_layer));
  if (train_embeddings && (trainable_blocks != n_layer || head != "action"))
    return Status::invalid("gpt2 policy: training the embeddings needs all " + std::to_string(n_layer) +
                           " blocks trainable (got " + std::to_string(trainable_blocks) +
                           ") and the \"action\" head (got \"" + head + "\"); the \"lm\" head reads the tied wte");
  if (chunk_rows < 1) return Status::invalid("gpt2 policy chunk_rows must be >= 1");
  if (obs_size < 8 || (obs_size - 3) % 5 != 0)
    return Status::invalid("gpt2 policy obs_size " + std::to_string(obs_size) + ": expected 3 + 5 n");
  return mirror.empty() ? Status::ok() : validate_mirror(mirror, obs_size, action_values);
}

std::vector<gpt2::TensorSpec> PromptPolicy::head_extras(int C, int K) {
  return {{kHeadWeight, {C, K}, 0, 0}, {kHeadBias, {K}, 0, 0}};
}

PromptPolicy::PromptPolicy(gpt2::Model model, gpt2::Tokenizer tokenizer, PromptRenderFn render,
                           PromptPolicySpec spec)
    : model_(std::move(model)),
      tokenizer_(std::move(tokenizer)),
      render_(std::move(render)),
      spec_(std::move(spec)),
      obs_size_(spec_.obs_size) {}

Result<std::unique_ptr<PromptPolicy>> PromptPolicy::make(gpt2::Model model, gpt2::Tokenizer tokenizer,
                                                         std::string prefix, PromptRenderFn render,
                                                         const PromptPolicySpec& spec) {
  SQUAWK_RETURN_IF_ERROR(spec.validate(model.config().n_layer));
  if (tokenizer.vocab_size() > model.config().vocab_size)
    return Status::invalid("gpt2 policy: tokenizer has " + std::to_string(tokenizer.vocab_size()) +
                           " tokens, the model " + std::to_string(model.config().vocab_size));
  const int C = model.config().n_embd;
  const auto K = static_cast<int64_t>(spec.action_values.size());
  if (spec.head == "action") {
    const gpt2::TensorSpec* w = model.layout().find(kHeadWeight);
    const gpt2::TensorSpec* b = model.layout().find(kHeadBias);
    if (!w || !b || w->shape != std::vector<int64_t>{C, K} || b->shape != std::vector<int64_t>{K})
      return Status::invalid("gpt2 policy: the model lacks the action head tensors " +
                             std::string(kHeadWeight) + " [" + std::to_string(C) + ", " +
                             std::to_string(K) + "] and " + kHeadBias);
  }
  SQUAWK_RETURN_IF_ERROR(model.set_trainable_blocks(spec.trainable_blocks, spec.train_embeddings));
  std::unique_ptr<PromptPolicy> p(
      new PromptPolicy(std::move(model), std::move(tokenizer), std::move(render), spec));
  SQUAWK_ASSIGN_OR_RETURN(p->prefix_tokens_, p->tokenizer_.encode(prefix));
  p->prefix_ = std::move(prefix);
  if (spec.head == "lm") {
    std::set<int> all;
    for (const std::string& t : spec.lm_texts) {
      SQUAWK_ASSIGN_OR_RETURN(std::vector<int> ids, p->tokenizer_.encode(t));
      if (ids.empty()) return Status::invalid("gpt2 policy: lm text '" + t + "' has no tokens");
      all.insert(ids.begin(), ids.end());
      p->lm_ids_.push_back(std::move(ids));
    }
    for (size_t a = 0; a < p->lm_ids_.size(); ++a)
      for (size_t b = a + 1; b < p->lm_ids_.size(); ++b)
        if (std::multiset<int>(p->lm_ids_[a].begin(), p->lm_ids_[a].end()) ==
            std::multiset<int>(p->lm_ids_[b].begin(), p->lm_ids_[b].end()))
          return Status::invalid("gpt2 policy: lm texts '" + spec.lm_texts[a] + "' and '" +
                                 spec.lm_texts[b] + "' have the same tokens");
    p->lm_union_.assign(all.begin(), all.end());
  }
  return p;
}

void PromptPolicy::init_head(Rng& rng) {
  if (spec_.head != "action") return;
  const double bound = 1.0 / std::sqrt(static_cast<double>(model_.config().n_embd));
  for (float& w : model_.tensor(kHeadWeight)) w = static_cast<float>(rng.uniform(-bound, bound));
  for (float& b : model_.tensor(kHeadBias)) b = 0.0f;
  cache_valid_ = false;
}

Status PromptPolicy::ensure_cache() {
  if (cache_valid_) return Status::ok();
  cache_ = {};
  if (!prefix_tokens_.empty()) SQUAWK_RETURN_IF_ERROR(model_.extend(cache_, prefix_tokens_));
  cache_valid_ = true;
  return Status::ok();
}

Result<std::string> PromptPolicy::prompt(std::span<const float> row) const {
  SQUAWK_ASSIGN_OR_RETURN(env::Observation o, env::unflatten(row));
  return render_(o);
}

Result<std::vector<int>> PromptPolicy::suffix_tokens(std::span<const float> row) const {
  SQUAWK_ASSIGN_OR_RETURN(std::string text, prompt(row));
  if (text.compare(0, prefix_.size(), prefix_) != 0)
    return Status::invalid("gpt2 policy: the rendered prompt does not start with the prefix");
  SQUAWK_ASSIGN_OR_RETURN(std::vector<int> ids, tokenizer_.encode(std::string_view(text).substr(prefix_.size())));
  if (ids.empty()) return Status::invalid("gpt2 policy: the prompt has nothing after its prefix");
  const size_t total = prefix_tokens_.size() + ids.size();
  if (total > static_cast<size_t>(model_.config().n_ctx))
    return Status::invalid("gpt2 policy: the prompt has " + std::to_string(total) +
                           " tokens, the model's context " + std::to_string(model_.config().n_ctx));
  return ids;
}

Status PromptPolicy::tokenize_rows(std::span<const float> obs, int n,
                                   std::vector<std::vector<int>>& seqs) const {
  const auto d = static_cast<size_t>(obs_size_);
  if (obs.size() < static_cast<size_t>(n) * d)
    return Status::invalid("gpt2 policy: " + std::to_string(obs.size()) + " observation values for " +
                           std::to_string(n) + " rows of " + std::to_string(obs_size_));
  std::vector<float> rows;
  if (!spec_.mirror.empty()) {
    mirror_rows(spec_.mirror, obs, n, rows);
    obs = rows;
    n *= 2;
  }
  seqs.resize(static_cast<size_t>(n));
  for (int r = 0; r < n; ++r) {
    SQUAWK_ASSIGN_OR_RETURN(seqs[static_cast<size_t>(r)],
                            suffix_tokens(obs.subspan(static_cast<size_t>(r) * d, d)));
  }
  return Status::ok();
}

std::vector<std::vector<int>> PromptPolicy::chunk(const std::vector<std::vector<int>>& seqs, int n, int r0,
                                                  int rows) const {
  std::vector<std::vector<int>> part(seqs.begin() + r0, seqs.begin() + r0 + rows);
  if (!spec_.mirror.empty()) part.insert(part.end(), seqs.begin() + n + r0, seqs.begin() + n + r0 + rows);
  return part;
}

void PromptPolicy::combine(std::vector<float>& raw, int rows) const {
  if (spec_.mirror.empty()) return;
  const int K = static_cast<int>(spec_.action_values.size());
  std::vector<float> z(static_cast<size_t>(rows) * static_cast<size_t>(K));
  mirror_combine(raw, rows, K, z);
  raw = std::move(z);
}

Status PromptPolicy::head_forward(std::span<const float> hidden, int rows, std::vector<float>& logits) {
  const int C = model_.config().n_embd;
  const int K = static_cast<int>(spec_.action_values.size());
  logits.assign(static_cast<size_t>(rows) * K, 0.0f);
  if (spec_.head == "action") {
    nn::linear_forward(logits.data(), hidden.data(), model_.tensor(kHeadWeight).data(),
                       model_.tensor(kHeadBias).data(), rows, C, K);
    return Status::ok();
  }
  std::vector<float> tok;
  SQUAWK_RETURN_IF_ERROR(model_.head_logits(hidden.first(static_cast<size_t>(rows) * C), lm_union_, tok));
  const size_t U = lm_union_.size();
  for (int r = 0; r < rows; ++r)
    for (int k = 0; k < K; ++k) {
      const auto& ids = lm_ids_[static_cast<size_t>(k)];
      double s = 0.0;
      for (int id : ids) {
        const auto u = static_cast<size_t>(std::lower_bound(lm_union_.begin(), lm_union_.end(), id) - lm_union_.begin());
        s += tok[static_cast<size_t>(r) * U + u];
      }
      logits[static_cast<size_t>(r) * K + k] = static_cast<float>(s / static_cast<double>(ids.size()));
    }
  return Status::ok();
}

Status PromptPolicy::head_backward(std::span<const float> hidden, std::span<const float> dlogits, int rows,
                                   std::vector<float>& dhidden) {
  const int C = model_.config().n_embd;
  const int K = static_cast<int>(spec_.action_values.size());
  dhidden.assign(static_cast<size_t>(rows) * C, 0.0f);
  if (spec_.head == "action") {
    nn::linear_backward(dhidden.data(), model_.grad(kHeadWeight).data(), model_.grad(kHeadBias).data(),
                        dlogits.data(), hidden.data(), model_.tensor(kHeadWeight).data(), rows, C, K);
    return Status::ok();
  }
  const size_t U = lm_union_.size();
  std::vector<float> dtok(static_cast<size_t>(rows) * U, 0.0f);
  for (int r = 0; r < rows; ++r)
    for (int k = 0; k < K; ++k) {
      const auto& ids = lm_ids_[static_cast<size_t>(k)];
      const float g = dlogits[static_cast<size_t>(r) * K + k] / static_cast<float>(ids.size());
      for (int id : ids) {
        const auto u = static_cast<size_t>(std::lower_bound(lm_union_.begin(), lm_union_.end(), id) - lm_union_.begin());
        dtok[static_cast<size_t>(r) * U + u] += g;
      }
    }
  return model_.head_logits_backward(dtok, lm_union_, dhidden);
}

Status PromptPolicy::logits(std::span<const float> obs, int n, std::vector<float>& out) {
  SQUAWK_RETURN_IF_ERROR(ensure_cache());
  std::vector<std::vector<int>> seqs;
  SQUAWK_RETURN_IF_ERROR(tokenize_rows(obs, n, seqs));
  const int K = static_cast<int>(spec_.action_values.size());
  out.assign(static_cast<size_t>(n) * K, 0.0f);
  std::vector<float> hidden, chunk_logits;
  for (int r0 = 0; r0 < n; r0 += spec_.chunk_rows) {
    const int rows = std::min(spec_.chunk_rows, n - r0);
    const std::vector<std::vector<int>> part = chunk(seqs, n, r0, rows);
    SQUAWK_RETURN_IF_ERROR(model_.forward_last(cache_, part, hidden));
    SQUAWK_RETURN_IF_ERROR(head_forward(hidden, static_cast<int>(part.size()), chunk_logits));
    combine(chunk_logits, rows);
    std::copy(chunk_logits.begin(), chunk_logits.end(), out.begin() + static_cast<long>(r0) * K);
  }
  return Status::ok();
}

void PromptPolicy::log_probs(std::span<const float> obs, int n, std::span<const ActionSample> actions,
                             std::span<float> out) {
  const auto K = spec_.action_values.size();
  std::vector<float> z;
  if (Status st = logits(obs, n, z); !st.is_ok()) {
    if (error_.is_ok()) error_ = st;
    std::fill(out.begin(), out.begin() + n, 0.0f);
    return;
  }
  std::vector<float> logp(K);
  for (int r = 0; r < n; ++r) {
    nn::log_softmax(std::span<const float>(z).subspan(static_cast<size_t>(r) * K, K), logp);
    out[static_cast<size_t>(r)] = logp[static_cast<size_t>(actions[static_cast<size_t>(r)].index)];
  }
}

void PromptPolicy::act(std::span<const float> obs, int n, std::span<const int> /*slots*/, std::span<Rng> rngs,
                       bool greedy, std::span<ActionSample> out) {
  const auto K = spec_.action_values.size();
  std::vector<float> z;
  if (Status st = logits(obs, n, z); !st.is_ok()) {
    if (error_.is_ok()) error_ = st;
    for (int r = 0; r < n; ++r) out[static_cast<size_t>(r)] = {0, static_cast<float>(spec_.action_values[0])};
    return;
  }
  std::vector<float> logp(K);
  for (int r = 0; r < n; ++r) {
    nn::log_softmax(std::span<const float>(z).subspan(static_cast<size_t>(r) * K, K), logp);
    const int a = greedy ? nn::categorical_argmax(logp) : nn::categorical_sample(logp, row_rng(rngs, r));
    out[static_cast<size_t>(r)] = {a, static_cast<float>(spec_.action_values[static_cast<size_t>(a)])};
  }
}

float PromptPolicy::accumulate_gradient(std::span<const float> obs, int n,
                                        std::span<const ActionSample> actions, std::span<const float> coef,
                                        float ent_coef) {
  const auto K = spec_.action_values.size();
  std::vector<std::vector<int>> seqs;
  Status st = ensure_cache();
  if (st.is_ok()) st = tokenize_rows(obs, n, seqs);
  double entropy = 0.0;
  std::vector<float> hidden, z, dz, dhidden, logp(K);
  for (int r0 = 0; st.is_ok() && r0 < n; r0 += spec_.chunk_rows) {
    const int rows = std::min(spec_.chunk_rows, n - r0);
    const std::vector<std::vector<int>> part = chunk(seqs, n, r0, rows);
    const int net_rows = static_cast<int>(part.size());
    st = model_.forward_train(cache_, part, hidden);
    if (st.is_ok()) st = head_forward(hidden, net_rows, z);
    if (!st.is_ok()) break;
    combine(z, rows);
    // dz = dL/dlogits with L = -(coef log pi + ent_coef H).
    dz.assign(z.size(), 0.0f);
    for (int r = 0; r < rows; ++r) {
      const auto i = static_cast<size_t>(r0 + r);
      const auto off = static_cast<size_t>(r) * K;
      nn::log_softmax(std::span<const float>(z).subspan(off, K), logp);
      entropy += nn::categorical_entropy(logp);
      nn::categorical_grad(logp, actions[i].index, -coef[i], -ent_coef, std::span<float>(dz).subspan(off, K));
    }
    if (!spec_.mirror.empty()) {
      std::vector<float> dz2(2 * dz.size());
      mirror_spread(dz, rows, static_cast<int>(K), dz2);
      dz = std::move(dz2);
    }
    st = head_backward(hidden, dz, net_rows, dhidden);
    if (st.is_ok()) st = model_.backward(dhidden);
  }
  cache_valid_ = false;
  if (!st.is_ok() && error_.is_ok()) error_ = st;
  return n > 0 ? static_cast<float>(entropy / n) : 0.0f;
}

}  // namespace squawk::rl
