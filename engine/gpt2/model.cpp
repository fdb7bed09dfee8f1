#include "gpt2/model.h"

#include <algorithm>
#include <cmath>

#include "nn/attention.h"
#include "nn/gelu.h"
#include "nn/gemm.h"
#include "nn/layernorm.h"
#include "nn/linear.h"

namespace squawk::gpt2 {

struct Model::AttnArgs {
  nn::AttentionShape shape;
  std::vector<const float*> k_ext, v_ext;  // per block, null without an external prefix
};

namespace {

std::string str(long long v) { return std::to_string(v); }

}  // namespace

Result<Model> Model::create(const Config& cfg, const std::vector<TensorSpec>& extras) {
  SQUAWK_ASSIGN_OR_RETURN(ParamLayout layout, ParamLayout::build(cfg, extras));
  Model m;
  m.layout_ = std::move(layout);
  m.params_.assign(m.layout_.total(), 0.0f);
  return m;
}

std::span<float> Model::tensor(const std::string& name) {
  const TensorSpec* t = layout_.find(name);
  if (!t) return {};
  if (t->offset < params_.size() - grads_.size()) frozen16_stale_ = true;
  return std::span<float>(params_).subspan(t->offset, t->size);
}

void Model::init_random(Rng& rng, float std) {
  frozen16_stale_ = true;
  const float proj_std = std / std::sqrt(2.0f * static_cast<float>(config().n_layer));
  const size_t extras = layout_.extras_start();
  for (const TensorSpec& t : layout_.tensors()) {
    float* p = params_.data() + t.offset;
    const std::string& n = t.name;
    const bool is_bias = n.size() > 5 && n.compare(n.size() - 5, 5, ".bias") == 0;
    const bool is_ln = n.find("ln_") != std::string::npos;
    if (t.offset >= extras || is_bias) {
      std::fill(p, p + t.size, 0.0f);
    } else if (is_ln) {
      std::fill(p, p + t.size, 1.0f);
    } else {
      const bool is_proj = n.find("c_proj.weight") != std::string::npos;
      const double sd = is_proj ? proj_std : std;
      for (size_t i = 0; i < t.size; ++i) p[i] = static_cast<float>(rng.normal(0.0, sd));
    }
  }
}

Result<Model::Batch> Model::make_batch(int prefix_len,
                                       const std::vector<std::vector<int>>& seqs) const {
  const Config& c = config();
  if (seqs.empty()) return Status::invalid("gpt2: a batch needs at least one sequence");
  Batch b;
  b.B = static_cast<int>(seqs.size());
  for (size_t i = 0; i < seqs.size(); ++i) {
    if (seqs[i].empty())
      return Status::invalid("gpt2: sequence " + str(static_cast<long long>(i)) +
                             " is empty; each needs at least one token");
    b.T = std::max(b.T, static_cast<int>(std::min<size_t>(seqs[i].size(), 1u << 30)));
  }
  if (static_cast<long long>(prefix_len) + b.T > c.n_ctx)
    return Status::invalid("gpt2: " + str(b.T) + " tokens after a prefix of " + str(prefix_len) +
                           " exceed the context of " + str(c.n_ctx) + " positions");
  b.tokens.assign(static_cast<size_t>(b.B) * b.T, 0);
  b.last.resize(b.B);
  for (int i = 0; i < b.B; ++i) {
    const auto& s = seqs[i];
    for (size_t t = 0; t < s.size(); ++t) {
      if (s[t] < 0 || s[t] >= c.vocab_size)
        return Status::invalid("gpt2: token id " + str(s[t]) + " (sequence " + str(i) +
                               ", position " + str(static_cast<long long>(t)) +
                               ") is outside the vocabulary 0.." + str(c.vocab_size - 1));
      b.tokens[static_cast<size_t>(i) * b.T + t] = s[t];
    }
    b.last[i] = static_cast<int>(s.size()) - 1;
  }
  return b;
}

void Model::embed(const Batch& batch, int pos0, float* x) const {
  const int C = config().n_embd;
  const float* wte = params_.data() + layout_.wte();
  const float* wpe = params_.data() + layout_.wpe();
  for (int b = 0; b < batch.B; ++b)
    for (int t = 0; t < batch.T; ++t) {
      float* row = x + (static_cast<size_t>(b) * batch.T + t) * C;
      const float* te = wte + static_cast<size_t>(batch.tokens[static_cast<size_t>(b) * batch.T + t]) * C;
      const float* pe = wpe + static_cast<size_t>(pos0 + t) * C;
      for (int i = 0; i < C; ++i) row[i] = te[i] + pe[i];
    }
}

nn::Precision Model::prepare_precision() const {
  const nn::Precision prec = nn::gemm_precision();
  if (prec != nn::Precision::kBf16) return prec;
  const size_t from = frozen16_stale_ || params16_.size() != params_.size() ? 0 : params_.size() - grads_.size();
  params16_.resize(params_.size());
  nn::to_bf16(params_.data() + from, params_.size() - from, params16_.data() + from);
  frozen16_stale_ = false;
  return prec;
}

const nn::bf16* Model::w16(nn::Precision prec, size_t offset) const {
  return prec == nn::Precision::kBf16 ? params16_.data() + offset : nullptr;
}

void Model::block_forward(nn::Precision prec, int l, float* x, int R, const AttnArgs& attn, Acts& a,
                          bool store, std::span<const int> rows) const {
  const Config& c = config();
  const int C = c.n_embd, Q = rows.empty() ? R : static_cast<int>(rows.size());
  const size_t RC = static_cast<size_t>(R) * C, QC = static_cast<size_t>(Q) * C;
  const size_t base = layout_.block_start(l);
  const float* p = params_.data() + base;
  const BlockOffsets& o = layout_.block();
  a.ln1.resize(RC);
  a.qkv.resize(3 * RC);
  a.atty.resize(QC);
  a.ln2.resize(QC);
  a.fch.resize(4 * QC);
  a.fch_gelu.resize(4 * QC);
  if (store) {
    a.x_in.assign(x, x + RC);
    a.ln1_mean.resize(R);
    a.ln1_rstd.resize(R);
    a.ln2_mean.resize(Q);
    a.ln2_rstd.resize(Q);
    a.att.resize(rows.empty() ? nn::attention_probs_size(attn.shape)
                              : nn::attention_rows_probs_size(attn.shape, Q));
  }
  std::vector<float> proj(QC);
  nn::layernorm_forward(a.ln1.data(), store ? a.ln1_mean.data() : nullptr,
                        store ? a.ln1_rstd.data() : nullptr, x, p + o.ln1_w, p + o.ln1_b, R, C,
                        c.ln_eps);
  nn::linear_forward(prec, a.qkv.data(), a.ln1.data(), p + o.attn_w, w16(prec, base + o.attn_w),
                     p + o.attn_b, R, C, 3 * C);
  float* att = store ? a.att.data() : nullptr;
  if (rows.empty()) {
    nn::attention_forward(a.atty.data(), att, a.qkv.data(), attn.k_ext[l], attn.v_ext[l], C,
                          attn.shape);
  } else {
    nn::attention_forward_rows(a.atty.data(), att, a.qkv.data(), attn.k_ext[l], attn.v_ext[l], C,
                               attn.shape, rows);
    // Rows increase, so row q's source rows[q] >= q is not yet overwritten.
    for (int q = 0; q < Q; ++q)
      std::copy(x + static_cast<size_t>(rows[q]) * C, x + static_cast<size_t>(rows[q] + 1) * C,
                x + static_cast<size_t>(q) * C);
  }
  nn::linear_forward(prec, proj.data(), a.atty.data(), p + o.proj_w, w16(prec, base + o.proj_w),
                     p + o.proj_b, Q, C, C);
  for (size_t i = 0; i < QC; ++i) x[i] += proj[i];
  if (store) a.x_mid.assign(x, x + QC);
  nn::layernorm_forward(a.ln2.data(), store ? a.ln2_mean.data() : nullptr,
                        store ? a.ln2_rstd.data() : nullptr, x, p + o.ln2_w, p + o.ln2_b, Q, C,
                        c.ln_eps);
  nn::linear_forward(prec, a.fch.data(), a.ln2.data(), p + o.fc_w, w16(prec, base + o.fc_w),
                     p + o.fc_b, Q, C, 4 * C);
  nn::gelu_forward(a.fch_gelu.data(), a.fch.data(), 4 * QC);
  nn::linear_forward(prec, proj.data(), a.fch_gelu.data(), p + o.fcproj_w,
                     w16(prec, base + o.fcproj_w), p + o.fcproj_b, Q, 4 * C, C);
  for (size_t i = 0; i < QC; ++i) x[i] += proj[i];
}

void Model::block_backward(nn::Precision prec, int l, Acts& a, float* dx, int R,
                           const AttnArgs& attn, std::span<const int> rows) {
  const int C = config().n_embd, Q = rows.empty() ? R : static_cast<int>(rows.size());
  const size_t RC = static_cast<size_t>(R) * C, QC = static_cast<size_t>(Q) * C;
  const size_t base = layout_.block_start(l);
  const float* p = params_.data() + base;
  float* g = grads_.data() + (base - (params_.size() - grads_.size()));
  const BlockOffsets& o = layout_.block();
  std::vector<float> dfch_gelu(4 * QC, 0.0f), dfch(4 * QC, 0.0f), dln(RC, 0.0f);
  nn::linear_backward(prec, dfch_gelu.data(), g + o.fcproj_w, g + o.fcproj_b, dx, a.fch_gelu.data(),
                      p + o.fcproj_w, w16(prec, base + o.fcproj_w), Q, 4 * C, C);
  nn::gelu_backward(dfch.data(), a.fch.data(), dfch_gelu.data(), 4 * QC);
  nn::linear_backward(prec, dln.data(), g + o.fc_w, g + o.fc_b, dfch.data(), a.ln2.data(),
                      p + o.fc_w, w16(prec, base + o.fc_w), Q, C, 4 * C);
  nn::layernorm_backward(dx, g + o.ln2_w, g + o.ln2_b, dln.data(), a.x_mid.data(), p + o.ln2_w,
                         a.ln2_mean.data(), a.ln2_rstd.data(), Q, C);
  std::vector<float> datty(QC, 0.0f), dqkv(3 * RC, 0.0f);
  nn::linear_backward(prec, datty.data(), g + o.proj_w, g + o.proj_b, dx, a.atty.data(),
                      p + o.proj_w, w16(prec, base + o.proj_w), Q, C, C);
  if (rows.empty()) {
    nn::attention_backward(dqkv.data(), datty.data(), a.att.data(), a.qkv.data(), attn.k_ext[l],
                           attn.v_ext[l], C, attn.shape);
  } else {
    nn::attention_backward_rows(dqkv.data(), datty.data(), a.att.data(), a.qkv.data(),
                                attn.k_ext[l], attn.v_ext[l], C, attn.shape, rows);
    // The residual carries the query rows' gradient back to their input rows.
    const std::vector<float> dres(dx, dx + QC);
    std::fill(dx, dx + RC, 0.0f);
    for (int q = 0; q < Q; ++q)
      std::copy(dres.begin() + static_cast<long>(q) * C, dres.begin() + static_cast<long>(q + 1) * C,
                dx + static_cast<size_t>(rows[q]) * C);
  }
  std::fill(dln.begin(), dln.end(), 0.0f);
  nn::linear_backward(prec, dln.data(), g + o.attn_w, g + o.attn_b, dqkv.data(), a.ln1.data(),
                      p + o.attn_w, w16(prec, base + o.attn_w), R, C, 3 * C);
  nn::layernorm_backward(dx, g + o.ln1_w, g + o.ln1_b, dln.data(), a.x_in.data(), p + o.ln1_w,
                         a.ln1_mean.data(), a.ln1_rstd.data(), R, C);
}

std::vector<int> Model::last_rows(const Batch& batch, int row0) {
  std::vector<int> rows(static_cast<size_t>(batch.B));
  for (int b = 0; b < batch.B; ++b) rows[static_cast<size_t>(b)] = row0 + b * batch.T + batch.last[static_cast<size_t>(b)];
  return rows;
}

namespace {

Status check_cache(const PrefixCache& cache, const Config& c) {
  if (cache.len < 0 || cache.len > c.n_ctx)
    return Status::invalid("gpt2: prefix cache length " + str(cache.len) + " is outside 0.." +
                           str(c.n_ctx));
  if (cache.len == 0 && cache.k.empty()) return Status::ok();
  const size_t want = static_cast<size_t>(cache.len) * c.n_embd;
  const size_t L = static_cast<size_t>(c.n_layer);
  if (cache.k.size() != L || cache.v.size() != L || cache.resid.size() != L)
    return Status::invalid("gpt2: prefix cache has " + str(static_cast<long long>(cache.k.size())) +
                           " blocks, the model " + str(c.n_layer));
  for (size_t l = 0; l < L; ++l)
    if (cache.k[l].size() != want || cache.v[l].size() != want || cache.resid[l].size() != want)
      return Status::invalid("gpt2: prefix cache block " + str(static_cast<long long>(l)) +
                             " does not hold " + str(cache.len) + " x " + str(c.n_embd) +
                             " floats; was it built by another model?");
  return Status::ok();
}

}  // namespace

Status Model::extend(PrefixCache& cache, std::span<const int> tokens,
                     std::vector<float>* last_hidden) const {
  const Config& c = config();
  SQUAWK_RETURN_IF_ERROR(check_cache(cache, c));
  SQUAWK_ASSIGN_OR_RETURN(Batch batch,
                          make_batch(cache.len, {std::vector<int>(tokens.begin(), tokens.end())}));
  const int C = c.n_embd, T = batch.T, L = c.n_layer, P = cache.len;
  if (cache.k.empty()) {
    cache.k.assign(L, {});
    cache.v.assign(L, {});
    cache.resid.assign(L, {});
  }
  AttnArgs attn{{1, T, C, c.n_head, P, false}, {}, {}};
  for (int l = 0; l < L; ++l) {
    attn.k_ext.push_back(P > 0 ? cache.k[l].data() : nullptr);
    attn.v_ext.push_back(P > 0 ? cache.v[l].data() : nullptr);
  }
  std::vector<float> x(static_cast<size_t>(T) * C);
  embed(batch, P, x.data());
  Acts a;
  cache.tokens.insert(cache.tokens.end(), tokens.begin(), tokens.end());
  const nn::Precision prec = prepare_precision();
  for (int l = 0; l < L; ++l) {
    cache.resid[l].insert(cache.resid[l].end(), x.begin(), x.end());
    block_forward(prec, l, x.data(), T, attn, a, false);
    for (int t = 0; t < T; ++t) {
      const float* row = a.qkv.data() + static_cast<size_t>(t) * 3 * C;
      cache.k[l].insert(cache.k[l].end(), row + C, row + 2 * C);
      cache.v[l].insert(cache.v[l].end(), row + 2 * C, row + 3 * C);
    }
    // Block l read cache.k[l]/v[l] above, before this append could move them.
  }
  cache.len += T;
  if (last_hidden) {
    const float* lnf = params_.data() + layout_.ln_f();
    last_hidden->resize(C);
    nn::layernorm_forward(last_hidden->data(), nullptr, nullptr, x.data() + static_cast<size_t>(T - 1) * C,
                          lnf, lnf + C, 1, C, c.ln_eps);
  }
  return Status::ok();
}

Status Model::forward_last(const PrefixCache& cache, const std::vector<std::vector<int>>& seqs,
                           std::vector<float>& hidden) const {
  const Config& c = config();
  SQUAWK_RETURN_IF_ERROR(check_cache(cache, c));
  SQUAWK_ASSIGN_OR_RETURN(Batch batch, make_batch(cache.len, seqs));
  const int C = c.n_embd, P = cache.len, R = batch.B * batch.T;
  AttnArgs attn{{batch.B, batch.T, C, c.n_head, P, false}, {}, {}};
  for (int l = 0; l < c.n_layer; ++l) {
    attn.k_ext.push_back(P > 0 ? cache.k[l].data() : nullptr);
    attn.v_ext.push_back(P > 0 ? cache.v[l].data() : nullptr);
  }
  std::vector<float> x(static_cast<size_t>(R) * C);
  embed(batch, P, x.data());
  Acts a;
  const std::vector<int> last = last_rows(batch, 0);
  const nn::Precision prec = prepare_precision();
  for (int l = 0; l < c.n_layer; ++l)
    block_forward(prec, l, x.data(), R, attn, a, false, l == c.n_layer - 1 ? last : std::vector<int>{});
  const float* lnf = params_.data() + layout_.ln_f();
  hidden.resize(static_cast<size_t>(batch.B) * C);
  nn::layernorm_forward(hidden.data(), nullptr, nullptr, x.data(), lnf, lnf + C, batch.B, C,
                        c.ln_eps);
  return Status::ok();
}

Status Model::logits_all(std::span<const int> tokens, std::vector<float>& logits) const {
  const Config& c = config();
  SQUAWK_ASSIGN_OR_RETURN(Batch batch, make_batch(0, {std::vector<int>(tokens.begin(), tokens.end())}));
  const int C = c.n_embd, T = batch.T;
  AttnArgs attn{{1, T, C, c.n_head, 0, false},
                std::vector<const float*>(c.n_layer, nullptr),
                std::vector<const float*>(c.n_layer, nullptr)};
  std::vector<float> x(static_cast<size_t>(T) * C), out(x.size());
  embed(batch, 0, x.data());
  Acts a;
  const nn::Precision prec = prepare_precision();
  for (int l = 0; l < c.n_layer; ++l) block_forward(prec, l, x.data(), T, attn, a, false);
  const float* lnf = params_.data() + layout_.ln_f();
  nn::layernorm_forward(out.data(), nullptr, nullptr, x.data(), lnf, lnf + C, T, C, c.ln_eps);
  logits.resize(static_cast<size_t>(T) * c.vocab_size);
  nn::gemm(prec, false, true, T, c.vocab_size, C, 1.0f, out.data(), C, params_.data() + layout_.wte(),
           C, 0.0f, logits.data(), c.vocab_size, w16(prec, layout_.wte()));
  return Status::ok();
}

namespace {

Status check_ids(std::span<const int> ids, int V) {
  for (int id : ids)
    if (id < 0 || id >= V)
      return Status::invalid("gpt2: head token id " + str(id) + " is outside the vocabulary 0.." +
                             str(V - 1));
  return Status::ok();
}

}  // namespace

Status Model::lm_logits(std::span<const float> hidden, std::vector<float>& out) const {
  const int C = config().n_embd, V = config().vocab_size;
  if (hidden.size() % C != 0)
    return Status::invalid("gpt2: hidden holds " + str(static_cast<long long>(hidden.size())) +
                           " floats, not a multiple of C = " + str(C));
  const int B = static_cast<int>(hidden.size() / C);
  out.resize(static_cast<size_t>(B) * V);
  const nn::Precision prec = prepare_precision();
  nn::gemm(prec, false, true, B, V, C, 1.0f, hidden.data(), C, params_.data() + layout_.wte(), C, 0.0f,
           out.data(), V, w16(prec, layout_.wte()));
  return Status::ok();
}

Status Model::head_logits(std::span<const float> hidden, std::span<const int> ids,
                          std::vector<float>& out) const {
  const int C = config().n_embd;
  SQUAWK_RETURN_IF_ERROR(check_ids(ids, config().vocab_size));
  if (hidden.size() % C != 0)
    return Status::invalid("gpt2: hidden holds " + str(static_cast<long long>(hidden.size())) +
                           " floats, not a multiple of C = " + str(C));
  const size_t B = hidden.size() / C, n = ids.size();
  const float* wte = params_.data() + layout_.wte();
  out.assign(B * n, 0.0f);
  for (size_t b = 0; b < B; ++b)
    for (size_t j = 0; j < n; ++j) {
      const float* e = wte + static_cast<size_t>(ids[j]) * C;
      const float* h = hidden.data() + b * C;
      float acc = 0.0f;
      for (int i = 0; i < C; ++i) acc += h[i] * e[i];
      out[b * n + j] = acc;
    }
  return Status::ok();
}

Status Model::head_logits_backward(std::span<const float> dlogits, std::span<const int> ids,
                                   std::span<float> dhidden) const {
  const int C = config().n_embd;
  SQUAWK_RETURN_IF_ERROR(check_ids(ids, config().vocab_size));
  const size_t n = ids.size();
  if (dhidden.size() % C != 0 || (n > 0 && dlogits.size() != dhidden.size() / C * n))
    return Status::invalid("gpt2: head_logits_backward expects dlogits [B, " +
                           str(static_cast<long long>(n)) + "] and dhidden [B, " + str(C) + "]");
  const size_t B = dhidden.size() / C;
  const float* wte = params_.data() + layout_.wte();
  for (size_t b = 0; b < B; ++b)
    for (size_t j = 0; j < n; ++j) {
      const float d = dlogits[b * n + j];
      const float* e = wte + static_cast<size_t>(ids[j]) * C;
      float* dh = dhidden.data() + b * C;
      for (int i = 0; i < C; ++i) dh[i] += d * e[i];
    }
  return Status::ok();
}

Status Model::set_trainable_blocks(int k, bool embeddings) {
  const int L = config().n_layer;
  if (k < 0 || k > L)
    return Status::invalid("gpt2: trainable blocks " + str(k) + " outside 0.." + str(L));
  if (embeddings && k != L)
    return Status::invalid("gpt2: training wte and wpe needs all " + str(L) + " blocks trainable, not " + str(k));
  trainable_ = k;
  embeddings_ = embeddings;
  frozen16_stale_ = true;
  const size_t start = embeddings ? layout_.wte() : k > 0 ? layout_.block_start(L - k) : layout_.ln_f();
  grads_.assign(params_.size() - start, 0.0f);
  tail_acts_.clear();
  train_batch_ = {};
  return Status::ok();
}

std::span<float> Model::trainable_params() {
  return std::span<float>(params_).subspan(params_.size() - grads_.size());
}

std::span<float> Model::grad(const std::string& name) {
  const TensorSpec* t = layout_.find(name);
  const size_t start = params_.size() - grads_.size();
  if (!t || t->offset < start || grads_.empty()) return {};
  return std::span<float>(grads_).subspan(t->offset - start, t->size);
}

void Model::zero_grads() { std::fill(grads_.begin(), grads_.end(), 0.0f); }

Status Model::forward_train(const PrefixCache& cache, const std::vector<std::vector<int>>& seqs,
                            std::vector<float>& hidden) {
  const Config& c = config();
  if (grads_.empty())
    return Status::invalid("gpt2: forward_train before set_trainable_blocks");
  SQUAWK_RETURN_IF_ERROR(check_cache(cache, c));
  SQUAWK_ASSIGN_OR_RETURN(Batch batch, make_batch(cache.len, seqs));
  const int C = c.n_embd, L = c.n_layer, P = cache.len, s = L - trainable_;
  const int BT = batch.B * batch.T;
  AttnArgs frozen{{batch.B, batch.T, C, c.n_head, P, false}, {}, {}};
  for (int l = 0; l < L; ++l) {
    frozen.k_ext.push_back(P > 0 ? cache.k[l].data() : nullptr);
    frozen.v_ext.push_back(P > 0 ? cache.v[l].data() : nullptr);
  }
  std::vector<float> x(static_cast<size_t>(BT) * C);
  embed(batch, P, x.data());
  Acts a;
  // The last block computes only each sequence's last row (the rows leading
  // x, or xr, afterwards): nothing reads the others.
  auto rows_at = [&](int l, int row0) { return l == L - 1 ? last_rows(batch, row0) : std::vector<int>{}; };
  const nn::Precision prec = prepare_precision();
  for (int l = 0; l < s; ++l) block_forward(prec, l, x.data(), BT, frozen, a, false, rows_at(l, 0));
  // Trainable blocks: the prefix rows lead, recomputed from the cached input of block s.
  const int inline_rows = s < L ? P : 0;
  std::vector<float> xr;
  xr.reserve(static_cast<size_t>(inline_rows + BT) * C);
  if (embeddings_ && P > 0) {
    if (cache.tokens.size() != static_cast<size_t>(P))
      return Status::invalid("gpt2: the prefix cache holds no tokens to re-embed; build it with extend()");
    xr.resize(static_cast<size_t>(P) * C);
    embed({1, P, cache.tokens, {}}, 0, xr.data());
  } else if (inline_rows > 0) {
    xr.assign(cache.resid[s].begin(), cache.resid[s].end());
  }
  xr.insert(xr.end(), x.begin(), x.end());
  const AttnArgs tail = {{batch.B, batch.T, C, c.n_head, P, true},
                         std::vector<const float*>(L, nullptr),
                         std::vector<const float*>(L, nullptr)};
  tail_acts_.resize(trainable_);
  for (int l = s; l < L; ++l)
    block_forward(prec, l, xr.data(), inline_rows + BT, tail, tail_acts_[l - s], true,
                  rows_at(l, inline_rows));
  const float* out = s < L ? xr.data() : x.data();
  lnf_in_.assign(out, out + static_cast<size_t>(batch.B) * C);
  lnf_mean_.resize(batch.B);
  lnf_rstd_.resize(batch.B);
  const float* lnf = params_.data() + layout_.ln_f();
  hidden.resize(lnf_in_.size());
  nn::layernorm_forward(hidden.data(), lnf_mean_.data(), lnf_rstd_.data(), lnf_in_.data(), lnf,
                        lnf + C, batch.B, C, c.ln_eps);
  train_batch_ = std::move(batch);
  train_prefix_ = inline_rows;
  train_prec_ = prec;
  train_prefix_tokens_ = embeddings_ ? cache.tokens : std::vector<int>{};
  return Status::ok();
}

Status Model::backward(std::span<const float> dhidden) {
  const Config& c = config();
  const int C = c.n_embd, L = c.n_layer, B = train_batch_.B, s = L - trainable_;
  if (B == 0) return Status::invalid("gpt2: backward without a preceding forward_train");
  if (dhidden.size() != static_cast<size_t>(B) * C)
    return Status::invalid("gpt2: backward expects dhidden of " + str(B) + " x " + str(C) +
                           " floats, got " + str(static_cast<long long>(dhidden.size())));
  const size_t start = params_.size() - grads_.size();
  const float* lnf = params_.data() + layout_.ln_f();
  float* glnf = grads_.data() + (layout_.ln_f() - start);
  std::vector<float> dlast(static_cast<size_t>(B) * C, 0.0f);
  nn::layernorm_backward(dlast.data(), glnf, glnf + C, dhidden.data(), lnf_in_.data(), lnf,
                         lnf_mean_.data(), lnf_rstd_.data(), B, C);
  if (s == L) return Status::ok();
  const int P = train_prefix_, T = train_batch_.T, R = P + B * T;
  // The last block's output rows are the sequences' last rows (forward_train).
  std::vector<float> dx(static_cast<size_t>(R) * C, 0.0f);
  std::copy(dlast.begin(), dlast.end(), dx.begin());
  const AttnArgs tail = {{B, T, C, c.n_head, P, true},
                         std::vector<const float*>(L, nullptr),
                         std::vector<const float*>(L, nullptr)};
  const std::vector<int> last = last_rows(train_batch_, P);
  for (int l = L - 1; l >= s; --l)
    block_backward(train_prec_, l, tail_acts_[l - s], dx.data(), R, tail,
                   l == L - 1 ? last : std::vector<int>{});
  if (embeddings_) embed_backward(train_batch_, train_prefix_tokens_, dx.data());
  return Status::ok();
}

void Model::embed_backward(const Batch& batch, std::span<const int> prefix, const float* dx) {
  const int C = config().n_embd, P = static_cast<int>(prefix.size());
  float* gwte = grads_.data() + layout_.wte();
  float* gwpe = grads_.data() + layout_.wpe();
  auto scatter = [&](int row, int token, int pos) {
    const float* d = dx + static_cast<size_t>(row) * C;
    float* te = gwte + static_cast<size_t>(token) * C;
    float* pe = gwpe + static_cast<size_t>(pos) * C;
    for (int i = 0; i < C; ++i) {
      te[i] += d[i];
      pe[i] += d[i];
    }
  };
  for (int p = 0; p < P; ++p) scatter(p, prefix[static_cast<size_t>(p)], p);
  for (int b = 0; b < batch.B; ++b)
    for (int t = 0; t < batch.T; ++t)
      scatter(P + b * batch.T + t, batch.tokens[static_cast<size_t>(b) * batch.T + t], P + t);
}

Result<double> Model::lm_loss_backward(const std::vector<std::vector<int>>& seqs, int from) {
  const Config& c = config();
  const int C = c.n_embd, L = c.n_layer, V = c.vocab_size;
  if (!embeddings_ || trainable_ != L)
    return Status::invalid("gpt2: language-model training needs every block and the embeddings trainable");
  SQUAWK_ASSIGN_OR_RETURN(Batch batch, make_batch(0, seqs));
  const int B = batch.B, T = batch.T, R = B * T;
  // Rows whose next token is predicted, and that token.
  std::vector<int> rows, targets;
  for (int b = 0; b < B; ++b)
    for (int t = std::max(from, 0); t + 1 <= batch.last[static_cast<size_t>(b)]; ++t) {
      rows.push_back(b * T + t);
      targets.push_back(batch.tokens[static_cast<size_t>(b) * T + t + 1]);
    }
  if (rows.empty()) return Status::invalid("gpt2: no token to predict after position " + str(from));
  // Forward: blocks, ln_f, the tied LM head.
  std::vector<float> x(static_cast<size_t>(R) * C);
  embed(batch, 0, x.data());
  const AttnArgs attn = {{B, T, C, c.n_head, 0, true}, std::vector<const float*>(L, nullptr),
                         std::vector<const float*>(L, nullptr)};
  std::vector<Acts> acts(L);
  const nn::Precision prec = prepare_precision();
  for (int l = 0; l < L; ++l) block_forward(prec, l, x.data(), R, attn, acts[l], true);
  const float* lnf = params_.data() + layout_.ln_f();
  std::vector<float> hidden(x.size()), mean(R), rstd(R);
  nn::layernorm_forward(hidden.data(), mean.data(), rstd.data(), x.data(), lnf, lnf + C, R, C, c.ln_eps);
  const int N = static_cast<int>(rows.size());
  std::vector<float> h(static_cast<size_t>(N) * C), logits(static_cast<size_t>(N) * V);
  for (int i = 0; i < N; ++i)
    std::copy_n(hidden.data() + static_cast<size_t>(rows[i]) * C, C, h.data() + static_cast<size_t>(i) * C);
  nn::gemm(prec, false, true, N, V, C, 1.0f, h.data(), C, params_.data() + layout_.wte(), C, 0.0f,
           logits.data(), V, w16(prec, layout_.wte()));
  // Loss and dlogits = (softmax - onehot) / N.
  double loss = 0.0;
  for (int i = 0; i < N; ++i) {
    float* z = logits.data() + static_cast<size_t>(i) * V;
    const float m = *std::max_element(z, z + V);
    double sum = 0.0;
    for (int v = 0; v < V; ++v) sum += std::exp(static_cast<double>(z[v] - m));
    loss += std::log(sum) - static_cast<double>(z[targets[i]] - m);
    for (int v = 0; v < V; ++v) z[v] = static_cast<float>(std::exp(static_cast<double>(z[v] - m)) / sum / N);
    z[targets[i]] -= 1.0f / static_cast<float>(N);
  }
  // Backward: the head (dh and the tied wte), ln_f, the blocks, the embeddings.
  float* gwte = grads_.data() + layout_.wte();
  nn::gemm(prec, true, false, V, C, N, 1.0f, logits.data(), V, h.data(), C, 1.0f, gwte, C);
  std::vector<float> dh(static_cast<size_t>(N) * C), dhidden(x.size(), 0.0f), dx(x.size(), 0.0f);
  nn::gemm(prec, false, false, N, C, V, 1.0f, logits.data(), V, params_.data() + layout_.wte(), C, 0.0f,
           dh.data(), C, w16(prec, layout_.wte()));
  for (int i = 0; i < N; ++i)
    std::copy_n(dh.data() + static_cast<size_t>(i) * C, C, dhidden.data() + static_cast<size_t>(rows[i]) * C);
  float* glnf = grads_.data() + layout_.ln_f();
  nn::layernorm_backward(dx.data(), glnf, glnf + C, dhidden.data(), x.data(), lnf, mean.data(),
                         rstd.data(), R, C);
  for (int l = L - 1; l >= 0; --l) block_backward(prec, l, acts[l], dx.data(), R, attn);
  embed_backward(batch, {}, dx.data());
  return loss / N;
}

}  // namespace squawk::gpt2
