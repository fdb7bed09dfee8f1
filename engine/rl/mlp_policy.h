// MlpPolicy: the paper's neural-network policy (§IV.C): linear layers with
// ReLU, ending in a linear layer whose outputs parametrise the action
// distribution.
//   head "categorical": K logits over action_values (the paper's
//     {-1, -0.5, 0, 0.5, 1}); default hidden {96, 96} gives 28-96-96-5 =
//     12,581 parameters, the paper's "~12,000".
//   head "gaussian": a diagonal Gaussian over action_size = D components
//     (1 for the gym rules' continuous action): D outputs = the means, plus D
//     free parameters log sigma_j (state-independent); the components are
//     independent, so log pi(a|s) = sum_j log N(a_j; mu_j(s), sigma_j^2) and
//     the entropy is the sum of theirs. A sample draws component 0 .. D-1 in
//     turn from the row's stream (ActionSample::component).
//   mirror (categorical only, beyond the paper): when set, the logits are
//     made mirror-symmetric (rl/mirror.h) from the same network, run on each
//     observation and its mirror image.
//   obs_mean / obs_std (beyond the paper; empty = none, else obs_size each):
//     the network reads (obs - obs_mean) / obs_std instead of obs
//     (rl/obs_norm.h gives them); fixed, not trained.
// Parameter buffer: the Mlp's parameters (nn/mlp.h layout), then log sigma_0
// .. log sigma_{D-1} for the Gaussian head.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/status.h"
#include "env/observation.h"
#include "nn/mlp.h"
#include "rl/policy.h"

namespace squawk::rl {

struct MlpPolicySpec {
  int obs_size = 28;                                      // [-]
  std::vector<int> hidden = {96, 96};                     // [-] hidden layer widths
  std::string head = "categorical";                       // "categorical" | "gaussian"
  std::vector<double> action_values = {-1, -0.5, 0, 0.5, 1};  // categorical classes
  double init_log_std = -0.5;                             // gaussian: initial log sigma
  int action_size = 1;  // gaussian: components D, 1..kMaxActionSize
  env::ObservationMirror mirror{};                        // empty = none
  std::vector<double> obs_mean, obs_std;  // [obs_size] each, or empty: no normalisation

  Status validate() const;
};

class MlpPolicy : public Policy {
 public:
  // A policy with parameters initialised from rng (PyTorch's default scheme).
  static Result<std::unique_ptr<MlpPolicy>> make(const MlpPolicySpec& spec, Rng& rng);

  std::string name() const override { return "mlp"; }
  int obs_size() const override { return spec_.obs_size; }
  void act(std::span<const float> obs, int n, std::span<const int> slots, std::span<Rng> rngs, bool greedy,
           std::span<ActionSample> out) override;
  bool trainable() const override { return true; }
  std::span<float> params() override { return params_; }
  std::span<float> grads() override { return grads_; }
  float accumulate_gradient(std::span<const float> obs, int n, std::span<const ActionSample> actions,
                            std::span<const float> coef, float ent_coef) override;
  bool has_log_probs() const override { return true; }
  std::span<const double> action_values() const override {
    return gaussian() ? std::span<const double>() : std::span<const double>(spec_.action_values);
  }
  void log_probs(std::span<const float> obs, int n, std::span<const ActionSample> actions,
                 std::span<float> out) override;

  const MlpPolicySpec& spec() const { return spec_; }
  bool gaussian() const { return spec_.head == "gaussian"; }
  // Output rows for obs [n, obs_size]: logits [n, K] (categorical) or means [n, D].
  void forward(std::span<const float> obs, int n, std::vector<float>& out);

 private:
  MlpPolicy(MlpPolicySpec spec, nn::Mlp mlp);
  // The Gaussian head's log sigma_0 .. log sigma_{D-1} (the buffer's tail).
  std::span<float> log_stds() {
    return std::span<float>(params_).last(static_cast<size_t>(spec_.action_size));
  }

  MlpPolicySpec spec_;
  nn::Mlp mlp_;
  std::vector<float> params_, grads_;
  nn::MlpCache cache_;
  std::vector<float> out_, dout_, logp_, d_log_std_;
  std::vector<float> rows_, raw_, draw_;  // mirror: [2n, D], [2n, K], [2n, K]
  std::vector<float> normed_;             // obs_mean/obs_std: [n, D]
};

}  // namespace squawk::rl
