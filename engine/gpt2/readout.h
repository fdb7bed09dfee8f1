// Read-out: a self-supervised pretraining objective beside next-token
// prediction. A linear probe reads a target vector per sequence (for the
// policy's prompts: the observation the prompt renders) from the hidden state
// of the sequence's last token, the position a policy head reads. No action
// labels and no reward take part; the probe is discarded after pretraining.
//
// Shape legend: B sequences, C channels, D targets per sequence.
//   pred [B, D] = hidden [B, C] @ W [C, D] + b [D]
//   L = (1/(B D)) sum_{b,d} (pred[b, d] - target[b, d])^2      [target units^2]
// readout_loss_backward runs Model::forward_train over the sequences after
// the cached prefix, adds `weight` dL/dtheta into model.grads() (through
// Model::backward) and dL/dW, dL/db into probe.grads (unscaled: the probe has
// its own optimiser). readout_loss is the same loss by the inference forward,
// no gradients.
#pragma once

#include <span>
#include <vector>

#include "core/rng.h"
#include "core/status.h"
#include "gpt2/model.h"

namespace squawk::gpt2 {

struct Readout {
  int C = 0, D = 0;
  std::vector<float> params;  // W [C, D] row-major, then b [D]
  std::vector<float> grads;   // same layout

  // W ~ U(-1/sqrt(C), 1/sqrt(C)) (PyTorch's nn.Linear), b = 0, grads 0.
  static Readout make(int C, int D, Rng& rng);
};

// Errors: targets not [B, D], a probe not C wide, and Model::forward_train's.
Result<double> readout_loss_backward(Model& model, const PrefixCache& cache,
                                     const std::vector<std::vector<int>>& seqs, std::span<const float> targets,
                                     Readout& probe, float weight);
Result<double> readout_loss(const Model& model, const PrefixCache& cache, const std::vector<std::vector<int>>& seqs,
                            std::span<const float> targets, const Readout& probe);

}  // namespace squawk::gpt2
