// GPT-2 forward pass (batched, with a prefix KV cache) and the backward pass
// of a trainable tail (the last k blocks + final LayerNorm + extra tensors).
//
// Shape legend: B sequences in a batch, T positions (the longest sequence),
// P cached prefix positions, C channels, NH heads, L blocks, V vocabulary.
// The model is exactly GPT-2: h = wte[tok] + wpe[pos]; per block
// h += attn(ln_1(h)); h += mlp(ln_2(h)) with causal attention and tanh GELU;
// out = ln_f(h); logits = out @ wte^T. "Hidden" below always means ln_f's
// output, the input of the LM head or of any other head.
//
// Variable-length sequences in a batch are right-padded internally; causal
// attention makes the padding invisible to each sequence's last position.
// Sequence positions continue after the prefix: token t of a sequence sits at
// position P + t, and P + T must not exceed n_ctx.
//
// Fine-tuning the last block and a head (the paper's setting):
//   auto m = load_model(dir, {{"head.weight", {C, A}}, {"head.bias", {A}}});
//   m->set_trainable_blocks(1);
//   nn::Adam adam(m->trainable_params(), m->grads());  // block L-1, ln_f, head
//   PrefixCache cache;  m->extend(cache, shared_prompt_ids);
//   m->zero_grads();  m->forward_train(cache, observations, hidden);  // [B, C]
//   (head forward/backward: add head gradients into m->grad("head.weight"), ...,
//    and compute dhidden [B, C])
//   m->backward(dhidden);  adam.step();
//   save_model(out_dir, *m);  // the head travels as extra tensors
// The cache stays valid for forward_train across steps; rebuild it before using
// forward_last with updated weights.
//
// Precision: every forward reads nn::gemm_precision(). In bf16 the matrix
// products (the linear layers, the LM head and their backward) take bf16
// operands with fp32 accumulation, against a bf16 rounding of the fp32
// parameters that the model keeps: the trainable range is rounded again at
// each forward (an optimiser writes it through trainable_params()), the rest
// when params(), tensor() of a frozen tensor, init_random or
// set_trainable_blocks was called since the last forward (so reading a
// trainable tensor through tensor() at every step costs no rounding).
// Writing frozen parameters through a span taken before a forward and written
// after it is not seen. LayerNorm, softmax, attention, GELU, the residual
// stream, gradients and the parameters themselves stay fp32. A model is not
// safe to run from two threads at once in bf16 (the rounding is shared).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/rng.h"
#include "core/status.h"
#include "gpt2/config.h"
#include "gpt2/params.h"
#include "nn/gemm.h"

namespace squawk::gpt2 {

// Keys, values and block inputs of a token prefix, per block l: k[l], v[l],
// resid[l] are [P, C]. Built and grown by Model::extend(); valid for the
// parameters it was built with (rebuild it after an optimiser step, except
// for Model::forward_train, which recomputes the trainable blocks itself).
struct PrefixCache {
  int len = 0;  // P
  std::vector<std::vector<float>> k, v, resid;
  std::vector<int> tokens;  // [P] the prefix's token ids
};

class Model {
 public:
  // A zero-filled model; extras are appended after ln_f (see params.h).
  static Result<Model> create(const Config& cfg, const std::vector<TensorSpec>& extras = {});

  const Config& config() const { return layout_.config(); }
  const ParamLayout& layout() const { return layout_; }
  std::span<float> params() {
    frozen16_stale_ = true;
    return params_;
  }
  std::span<const float> params() const { return params_; }
  // The named tensor's floats; empty when there is no such tensor.
  std::span<float> tensor(const std::string& name);

  // GPT-2's initialisation: weights ~ N(0, std), the two residual projections
  // per block N(0, std / sqrt(2 L)), biases 0, LayerNorm weights 1. Extras 0.
  void init_random(Rng& rng, float std = 0.02f);

  // ---- inference -------------------------------------------------------
  // Runs `tokens` (at least one) after the cache's P positions and appends
  // their keys, values and block inputs to the cache. When last_hidden is
  // given it receives the hidden state of the last token [C].
  Status extend(PrefixCache& cache, std::span<const int> tokens,
                std::vector<float>* last_hidden = nullptr) const;
  // Hidden state of the last token of each sequence [B, C], every sequence
  // (each at least one token) continuing the cached prefix (may be empty).
  Status forward_last(const PrefixCache& cache, const std::vector<std::vector<int>>& seqs,
                      std::vector<float>& hidden) const;
  // LM logits of every position of one sequence without cache [T, V].
  Status logits_all(std::span<const int> tokens, std::vector<float>& logits) const;
  // LM-head logits over the whole vocabulary: out [B, V] = hidden [B, C] @ wte^T.
  Status lm_logits(std::span<const float> hidden, std::vector<float>& out) const;
  // LM-head logits of chosen token ids: out[b, j] = hidden[b] . wte[ids[j]],
  // hidden [B, C], out [B, n]. Ids must be in range (checked).
  Status head_logits(std::span<const float> hidden, std::span<const int> ids,
                     std::vector<float>& out) const;
  // Backward of head_logits into the hidden state (wte is frozen):
  // dhidden [B, C] += dlogits [B, n] @ wte[ids].
  Status head_logits_backward(std::span<const float> dlogits, std::span<const int> ids,
                              std::span<float> dhidden) const;

  // ---- fine-tuning -----------------------------------------------------
  // Makes the last k blocks (0..L), ln_f and the extras trainable and
  // allocates their gradients (zeroed). embeddings = true also trains wte and
  // wpe and needs k = L: then every parameter trains.
  Status set_trainable_blocks(int k, bool embeddings = false);
  int trainable_blocks() const { return trainable_; }
  bool trains_embeddings() const { return embeddings_; }
  // The trainable parameters: one contiguous span at the end of params()
  // (wte and wpe when trained, blocks L-k..L-1, ln_f, extras), and their
  // gradients, same length.
  std::span<float> trainable_params();
  std::span<float> grads() { return grads_; }
  // Gradient of a trainable tensor; empty when the name is not trainable.
  std::span<float> grad(const std::string& name);
  void zero_grads();

  // Like forward_last, storing the activations of the trainable blocks. The
  // prefix part of those blocks is recomputed from the cache's input of the
  // first trainable block (from the cache's tokens when the embeddings
  // train), so gradients through the prefix keys and values are exact and the
  // cache's frozen part stays valid across updates.
  Status forward_train(const PrefixCache& cache, const std::vector<std::vector<int>>& seqs,
                       std::vector<float>& hidden);
  // Accumulates into grads() the gradient of a loss whose derivative with
  // respect to the last forward_train's hidden output is dhidden [B, C].
  Status backward(std::span<const float> dhidden);

  // ---- language-model training (every block and the embeddings) ------
  // Next-token cross-entropy of B sequences from position 0 (no cache), the
  // LM head tied to wte: the mean over every predicted token t+1, t in
  // from..len-2 of each sequence, of -log softmax(hidden[t] @ wte^T)[seq[t+1]]
  // [nats]. Accumulates its gradient into grads(); needs
  // set_trainable_blocks(L, true). Errors as forward_last, or no token to
  // predict.
  Result<double> lm_loss_backward(const std::vector<std::vector<int>>& seqs, int from);

 private:
  // Activations of one block over R rows (kept per trainable block).
  struct Acts {
    std::vector<float> x_in, ln1, ln1_mean, ln1_rstd, qkv, att, atty, x_mid, ln2, ln2_mean,
        ln2_rstd, fch, fch_gelu;
  };
  struct Batch {
    int B = 0, T = 0;
    std::vector<int> tokens;  // [B, T], right-padded with token 0
    std::vector<int> last;    // [B] index of each sequence's last token
  };
  struct AttnArgs;
  Result<Batch> make_batch(int prefix_len, const std::vector<std::vector<int>>& seqs) const;
  void embed(const Batch& batch, int pos0, float* x) const;
  // One block over R rows of x [R,C] (in place). With rows (strictly
  // increasing, not inline-prefix rows), only those queries are computed past
  // the keys and values: the block's output for rows[q] is written to row q.
  void block_forward(nn::Precision prec, int l, float* x, int R, const AttnArgs& attn, Acts& a,
                     bool store, std::span<const int> rows = {}) const;
  // Backward of block_forward with store: dx holds the gradient of its output
  // (the first rows.size() rows when rows are given) and becomes that of its
  // input [R,C].
  void block_backward(nn::Precision prec, int l, Acts& a, float* dx, int R, const AttnArgs& attn,
                      std::span<const int> rows = {});
  // nn::gemm_precision(), after bringing params16_ up to date when it is bf16.
  nn::Precision prepare_precision() const;
  // The bf16 rounding of the parameter at `offset` in bf16, null in fp32.
  const nn::bf16* w16(nn::Precision prec, size_t offset) const;
  // Row of each sequence's last token in a block layout starting at row0.
  static std::vector<int> last_rows(const Batch& batch, int row0);
  // grads of wte and wpe += dx [P + B T, C], the gradient of the block-0 input
  // rows: prefix token p at position p, then row (b, t) at position P + t.
  void embed_backward(const Batch& batch, std::span<const int> prefix, const float* dx);

  ParamLayout layout_;
  std::vector<float> params_;
  int trainable_ = 0;
  bool embeddings_ = false;
  std::vector<float> grads_;
  // State of the last forward_train.
  std::vector<Acts> tail_acts_;
  Batch train_batch_;
  int train_prefix_ = 0;
  std::vector<int> train_prefix_tokens_;  // [P] when the embeddings train
  std::vector<float> lnf_in_, lnf_mean_, lnf_rstd_;
  nn::Precision train_prec_ = nn::Precision::kFp32;  // of the last forward_train
  // bf16 rounding of params_ (bf16 forwards only) and whether its frozen
  // range may be out of date (see the contract at the top).
  mutable std::vector<nn::bf16> params16_;
  mutable bool frozen16_stale_ = true;
};

}  // namespace squawk::gpt2
