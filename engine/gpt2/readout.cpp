#include "gpt2/readout.h"

#include <cmath>
#include <string>

#include "nn/linear.h"

namespace squawk::gpt2 {

namespace {

Status check_shapes(const Model& model, size_t B, std::span<const float> targets, const Readout& probe) {
  if (probe.C != model.config().n_embd || probe.D < 1 ||
      probe.params.size() != static_cast<size_t>(probe.C + 1) * static_cast<size_t>(probe.D))
    return Status::invalid("read-out probe is " + std::to_string(probe.C) + " x " + std::to_string(probe.D) +
                                    "; the model is " + std::to_string(model.config().n_embd) + " channels wide");
  if (targets.size() != B * static_cast<size_t>(probe.D))
    return Status::invalid("read-out targets hold " + std::to_string(targets.size()) + " values; " +
                                    std::to_string(B) + " sequences of " + std::to_string(probe.D) + " expected");
  return Status::ok();
}

// pred [B, D] from hidden [B, C]; returns L and leaves dL/dpred in pred.
double mse_and_grad(std::span<const float> hidden, std::span<const float> targets, const Readout& probe, int B,
                    std::vector<float>& pred) {
  const size_t CD = static_cast<size_t>(probe.C) * static_cast<size_t>(probe.D);
  pred.assign(static_cast<size_t>(B) * static_cast<size_t>(probe.D), 0.0f);
  nn::linear_forward(pred.data(), hidden.data(), probe.params.data(), probe.params.data() + CD, B, probe.C, probe.D);
  const double scale = 1.0 / (static_cast<double>(B) * probe.D);
  double loss = 0.0;
  for (size_t i = 0; i < pred.size(); ++i) {
    const double e = static_cast<double>(pred[i]) - targets[i];
    loss += e * e;
    pred[i] = static_cast<float>(2.0 * e * scale);
  }
  return loss * scale;
}

}  // namespace

Readout Readout::make(int C, int D, Rng& rng) {
  Readout r;
  r.C = C;
  r.D = D;
  const size_t CD = static_cast<size_t>(C) * static_cast<size_t>(D);
  r.params.assign(CD + static_cast<size_t>(D), 0.0f);
  r.grads.assign(r.params.size(), 0.0f);
  const double bound = 1.0 / std::sqrt(static_cast<double>(C));
  for (size_t i = 0; i < CD; ++i) r.params[i] = static_cast<float>(rng.uniform(-bound, bound));
  return r;
}

Result<double> readout_loss_backward(Model& model, const PrefixCache& cache,
                                     const std::vector<std::vector<int>>& seqs, std::span<const float> targets,
                                     Readout& probe, float weight) {
  SQUAWK_RETURN_IF_ERROR(check_shapes(model, seqs.size(), targets, probe));
  std::vector<float> hidden, dpred;
  SQUAWK_RETURN_IF_ERROR(model.forward_train(cache, seqs, hidden));
  const int B = static_cast<int>(seqs.size());
  const double loss = mse_and_grad(hidden, targets, probe, B, dpred);
  const size_t CD = static_cast<size_t>(probe.C) * static_cast<size_t>(probe.D);
  std::vector<float> dhidden(hidden.size(), 0.0f);
  nn::linear_backward(dhidden.data(), probe.grads.data(), probe.grads.data() + CD, dpred.data(), hidden.data(),
                      probe.params.data(), B, probe.C, probe.D);
  for (float& g : dhidden) g *= weight;
  SQUAWK_RETURN_IF_ERROR(model.backward(dhidden));
  return loss;
}

Result<double> readout_loss(const Model& model, const PrefixCache& cache, const std::vector<std::vector<int>>& seqs,
                            std::span<const float> targets, const Readout& probe) {
  SQUAWK_RETURN_IF_ERROR(check_shapes(model, seqs.size(), targets, probe));
  std::vector<float> hidden, pred;
  SQUAWK_RETURN_IF_ERROR(model.forward_last(cache, seqs, hidden));
  return mse_and_grad(hidden, targets, probe, static_cast<int>(seqs.size()), pred);
}

}  // namespace squawk::gpt2
