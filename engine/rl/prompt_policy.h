// PromptPolicy: the paper's GPT-2 policy (§III.C.3-5). Each decision renders
// the observation as a text prompt, runs GPT-2 over it and turns the hidden
// state of the last position into a categorical distribution over the K
// discrete actions (the paper's {-1, -0.5, 0, 0.5, 1}).
//
// Shape legend: n rows (decisions), T suffix tokens, P prefix tokens,
// C channels, K actions, V vocabulary.
//
// Prompt: render(obs) must return prefix + rest, where `prefix` is the static
// text before the first observation value. Its tokens encode(prefix) run once
// into a gpt2::PrefixCache; each decision runs only encode(rest) after it, so
// the prompt's tokens are encode(prefix) ++ encode(rest) by definition. All
// rows of one act() call run as batched forwards of up to chunk_rows rows.
//
// Heads (spec.head):
//   "action": logits [n, K] = hidden [n, C] @ W [C, K] + b [K]; W, b are
//             extra model tensors "policy.head.weight" / "policy.head.bias"
//             (head_extras()), initialised U(-1/sqrt(C), 1/sqrt(C)) as a
//             PyTorch nn.Linear, b = 0.
//   "lm":     the paper's other reading: logit of action k = the mean LM-head
//             logit (hidden . wte[id]) over the tokens of lm_texts[k]; one
//             forward for all K actions. No extra tensors.
// Training: the last `trainable_blocks` blocks, ln_f and the head are the
// trainable parameters, with train_embeddings also wte and wpe (then every
// parameter; Model::trainable_params(), one contiguous span), so
// params()/grads() feed nn::Adam and rl::Trainer directly. After an optimiser
// step the trainable blocks' cached prefix keys/values are stale: every
// accumulate_gradient() marks the cache stale and the next act() rebuilds it
// (call invalidate_cache() after changing params() any other way).
// Errors (a render that fails, a prompt longer than n_ctx) cannot leave act():
// the first one is kept in error() and the row gets action index 0; callers
// check error() after a run.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/status.h"
#include "env/observation.h"
#include "gpt2/bpe.h"
#include "gpt2/model.h"
#include "rl/policy.h"

namespace squawk::rl {

using PromptRenderFn = std::function<Result<std::string>(const env::Observation&)>;

struct PromptPolicySpec {
  std::string head = "action";  // "action" | "lm"
  std::vector<double> action_values = {-1, -0.5, 0, 0.5, 1};  // [-] K classes
  std::vector<std::string> lm_texts = {"-1", "-0.5", "0", "0.5", "1"};  // "lm": one per action
  int trainable_blocks = 1;     // [-] k last blocks trained (the paper: 1)
  bool train_embeddings = false;  // wte and wpe train too (needs every block, head "action")
  int chunk_rows = 32;          // [-] rows per batched forward
  int obs_size = 28;            // [-] flat observation size, 3 + 5 intruders
  // When set, the logits are made mirror-symmetric (rl/mirror.h): each
  // observation's prompt and its mirror image's prompt go through the model.
  env::ObservationMirror mirror{};

  Status validate(int n_layer) const;
};

class PromptPolicy : public Policy {
 public:
  // Extra tensors the "action" head needs in a model of width C (params.h).
  static std::vector<gpt2::TensorSpec> head_extras(int C, int K);

  // `model` must carry head_extras() for the "action" head. Encodes the prefix
  // and the lm_texts; marks the tail trainable. Head weights are left as they
  // are in the model (init_head() draws fresh ones).
  static Result<std::unique_ptr<PromptPolicy>> make(gpt2::Model model, gpt2::Tokenizer tokenizer,
                                                    std::string prefix, PromptRenderFn render,
                                                    const PromptPolicySpec& spec);

  void init_head(Rng& rng);

  std::string name() const override { return "gpt2"; }
  int obs_size() const override { return obs_size_; }
  void act(std::span<const float> obs, int n, std::span<const int> slots, std::span<Rng> rngs, bool greedy,
           std::span<ActionSample> out) override;
  bool trainable() const override { return true; }
  std::span<float> params() override { return model_.trainable_params(); }
  std::span<float> grads() override { return model_.grads(); }
  float accumulate_gradient(std::span<const float> obs, int n, std::span<const ActionSample> actions,
                            std::span<const float> coef, float ent_coef) override;
  // log pi(actions[r] | row r) from logits(); the clipped-ratio learner's
  // scores. A failed forward keeps its error in error() and gives 0.
  bool has_log_probs() const override { return true; }
  std::span<const double> action_values() const override { return spec_.action_values; }
  void log_probs(std::span<const float> obs, int n, std::span<const ActionSample> actions,
                 std::span<float> out) override;

  // Action logits [n, K] for obs [n, obs_size] (inference path, prefix cache).
  Status logits(std::span<const float> obs, int n, std::vector<float>& out);
  // The whole prompt text for one flat row (what the model reads).
  Result<std::string> prompt(std::span<const float> row) const;
  // Token ids of the part of the prompt after the prefix, for one flat row.
  Result<std::vector<int>> suffix_tokens(std::span<const float> row) const;

  void invalidate_cache() { cache_valid_ = false; }
  // Rows per batched forward (>= 1); the results do not depend on it.
  void set_chunk_rows(int rows) { spec_.chunk_rows = rows < 1 ? 1 : rows; }
  Status error() const override { return error_; }
  const PromptPolicySpec& spec() const { return spec_; }
  gpt2::Model& model() { return model_; }
  const gpt2::Tokenizer& tokenizer() const { return tokenizer_; }
  const std::vector<int>& prefix_tokens() const { return prefix_tokens_; }

 private:
  PromptPolicy(gpt2::Model model, gpt2::Tokenizer tokenizer, PromptRenderFn render,
               PromptPolicySpec spec);
  Status ensure_cache();
  // seqs [n] (with a mirror: [2n], the images' prompts after the n rows).
  Status tokenize_rows(std::span<const float> obs, int n, std::vector<std::vector<int>>& seqs) const;
  // The sequences of rows [r0, r0 + rows) of n: those rows, then (with a
  // mirror) their images'.
  std::vector<std::vector<int>> chunk(const std::vector<std::vector<int>>& seqs, int n, int r0, int rows) const;
  // logits [rows, K] from the head's raw output of chunk()'s sequences.
  void combine(std::vector<float>& raw, int rows) const;
  // logits [rows, K] from hidden [rows, C].
  Status head_forward(std::span<const float> hidden, int rows, std::vector<float>& logits);
  // dhidden [rows, C] from dlogits [rows, K]; accumulates the head's gradients.
  Status head_backward(std::span<const float> hidden, std::span<const float> dlogits, int rows,
                       std::vector<float>& dhidden);

  gpt2::Model model_;
  gpt2::Tokenizer tokenizer_;
  PromptRenderFn render_;
  PromptPolicySpec spec_;
  int obs_size_ = 0;
  std::string prefix_;
  std::vector<int> prefix_tokens_;
  std::vector<std::vector<int>> lm_ids_;  // "lm": token ids of each action text
  std::vector<int> lm_union_;             // "lm": distinct ids over all texts
  gpt2::PrefixCache cache_;
  bool cache_valid_ = false;
  Status error_;
};

}  // namespace squawk::rl
