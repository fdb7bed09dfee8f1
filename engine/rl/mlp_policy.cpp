#include "rl/mlp_policy.h"

#include <algorithm>
#include <cmath>

#include "nn/categorical.h"
#include "nn/gaussian.h"
#include "rl/mirror.h"

namespace squawk::rl {

Status MlpPolicySpec::validate() const {
  if (obs_size < 1) return Status::invalid("policy obs_size must be positive");
  if (!obs_mean.empty() || !obs_std.empty()) {
    if (obs_mean.size() != static_cast<size_t>(obs_size) || obs_std.size() != obs_mean.size())
      return Status::invalid("policy obs_mean / obs_std hold " + std::to_string(obs_mean.size()) +
                             " / " + std::to_string(obs_std.size()) +
                             " numbers: expected obs_size = " + std::to_string(obs_size) + " each");
    for (size_t j = 0; j < obs_std.size(); ++j)
      if (!(obs_std[j] > 0.0 && std::isfinite(obs_std[j])) || !std::isfinite(obs_mean[j]))
        return Status::invalid("policy obs_std[" + std::to_string(j) +
                               "] = " + std::to_string(obs_std[j]) +
                               ", obs_mean = " + std::to_string(obs_mean[j]) +
                               ": expected a finite mean and a positive finite deviation");
    if (!mirror.empty()) return Status::invalid("policy mirror does not take obs_mean / obs_std");
  }
  for (int h : hidden)
    if (h < 1 || h > 4096)
      return Status::invalid("policy hidden width " + std::to_string(h) + ": expected 1..4096");
  if (head == "categorical") {
    if (action_size != 1)
      return Status::invalid("policy action_size " + std::to_string(action_size) +
                             ": a categorical head acts through action_values, expected 1");
    if (action_values.size() < 2)
      return Status::invalid("categorical policy needs at least 2 action values");
    for (double v : action_values)
      if (!(v >= -1.0 && v <= 1.0))
        return Status::invalid("action value " + std::to_string(v) + " lies outside [-1, 1]");
    return mirror.empty() ? Status::ok() : validate_mirror(mirror, obs_size, action_values);
  }
  if (head == "gaussian" && (action_size < 1 || action_size > kMaxActionSize))
    return Status::invalid("gaussian policy action_size " + std::to_string(action_size) +
                           ": expected 1.." + std::to_string(kMaxActionSize));
  if (head == "gaussian")
    return mirror.empty() ? Status::ok()
                          : Status::invalid("policy mirror needs the categorical head, not the gaussian one");
  return Status::invalid("policy head '" + head + "': expected \"categorical\" or \"gaussian\"");
}

Result<std::unique_ptr<MlpPolicy>> MlpPolicy::make(const MlpPolicySpec& spec, Rng& rng) {
  SQUAWK_RETURN_IF_ERROR(spec.validate());
  std::vector<int> sizes = {spec.obs_size};
  sizes.insert(sizes.end(), spec.hidden.begin(), spec.hidden.end());
  sizes.push_back(spec.head == "gaussian" ? spec.action_size
                                          : static_cast<int>(spec.action_values.size()));
  SQUAWK_ASSIGN_OR_RETURN(nn::Mlp mlp, nn::Mlp::make(sizes));
  std::unique_ptr<MlpPolicy> p(new MlpPolicy(spec, std::move(mlp)));
  p->mlp_.init(std::span<float>(p->params_).first(p->mlp_.num_params()), rng);
  if (p->gaussian()) std::ranges::fill(p->log_stds(), static_cast<float>(spec.init_log_std));
  return p;
}

MlpPolicy::MlpPolicy(MlpPolicySpec spec, nn::Mlp mlp) : spec_(std::move(spec)), mlp_(std::move(mlp)) {
  const size_t n = mlp_.num_params() + (gaussian() ? static_cast<size_t>(spec_.action_size) : 0);
  params_.assign(n, 0.0f);
  grads_.assign(n, 0.0f);
}

void MlpPolicy::forward(std::span<const float> obs, int n, std::vector<float>& out) {
  const int k = mlp_.out_dim();
  out.resize(static_cast<size_t>(n) * static_cast<size_t>(k));
  if (!spec_.obs_mean.empty()) {
    const size_t d = spec_.obs_mean.size();
    normed_.resize(static_cast<size_t>(n) * d);
    for (size_t i = 0; i < normed_.size(); ++i)
      normed_[i] = static_cast<float>((obs[i] - spec_.obs_mean[i % d]) / spec_.obs_std[i % d]);
    mlp_.forward(params_, normed_.data(), n, out.data(), &cache_);
    return;
  }
  if (spec_.mirror.empty()) {
    mlp_.forward(params_, obs.data(), n, out.data(), &cache_);
    return;
  }
  mirror_rows(spec_.mirror, obs, n, rows_);
  raw_.resize(2 * out.size());
  mlp_.forward(params_, rows_.data(), 2 * n, raw_.data(), &cache_);
  mirror_combine(raw_, n, k, out);
}

void MlpPolicy::act(std::span<const float> obs, int n, std::span<const int> /*slots*/, std::span<Rng> rngs,
                    bool greedy, std::span<ActionSample> out) {
  forward(obs, n, out_);
  const auto k = static_cast<size_t>(mlp_.out_dim());
  if (gaussian()) {
    const std::span<const float> log_std = log_stds();
    for (int r = 0; r < n; ++r) {
      ActionSample& a = out[static_cast<size_t>(r)];
      a = {};
      for (size_t j = 0; j < k; ++j) {
        const float mu = out_[static_cast<size_t>(r) * k + j];
        a.component(static_cast<int>(j)) =
            greedy ? mu : nn::gaussian_sample(mu, log_std[j], row_rng(rngs, r));
      }
    }
    return;
  }
  logp_.resize(k);
  for (int r = 0; r < n; ++r) {
    nn::log_softmax(std::span<const float>(out_).subspan(static_cast<size_t>(r) * k, k), logp_);
    const int a = greedy ? nn::categorical_argmax(logp_) : nn::categorical_sample(logp_, row_rng(rngs, r));
    out[static_cast<size_t>(r)] = {a, static_cast<float>(spec_.action_values[static_cast<size_t>(a)])};
  }
}

void MlpPolicy::log_probs(std::span<const float> obs, int n, std::span<const ActionSample> actions,
                          std::span<float> out) {
  forward(obs, n, out_);
  const auto k = static_cast<size_t>(mlp_.out_dim());
  if (gaussian()) {
    const std::span<const float> log_std = log_stds();
    for (int r = 0; r < n; ++r) {
      const auto i = static_cast<size_t>(r);
      float lp = 0.0f;
      for (size_t j = 0; j < k; ++j)
        lp += nn::gaussian_log_prob(actions[i].component(static_cast<int>(j)), out_[i * k + j],
                                    log_std[j]);
      out[i] = lp;
    }
    return;
  }
  logp_.resize(k);
  for (int r = 0; r < n; ++r) {
    const auto i = static_cast<size_t>(r);
    nn::log_softmax(std::span<const float>(out_).subspan(i * k, k), logp_);
    out[i] = logp_[static_cast<size_t>(actions[i].index)];
  }
}

float MlpPolicy::accumulate_gradient(std::span<const float> obs, int n,
                                     std::span<const ActionSample> actions,
                                     std::span<const float> coef, float ent_coef) {
  forward(obs, n, out_);
  const auto k = static_cast<size_t>(mlp_.out_dim());
  dout_.assign(out_.size(), 0.0f);
  double entropy = 0.0;
  // dout holds dL/d(output) with L = -(coef log pi + ent_coef H).
  if (gaussian()) {
    const std::span<const float> log_std = log_stds();
    d_log_std_.assign(k, 0.0f);
    for (int r = 0; r < n; ++r) {
      const auto i = static_cast<size_t>(r);
      for (size_t j = 0; j < k; ++j) {
        const nn::GaussianGrad g =
            nn::gaussian_grad(actions[i].component(static_cast<int>(j)), out_[i * k + j],
                              log_std[j], coef[i], ent_coef);
        dout_[i * k + j] = -g.d_mu;
        d_log_std_[j] -= g.d_log_std;
        entropy += nn::gaussian_entropy(log_std[j]);
      }
    }
    const std::span<float> g_log_std = std::span<float>(grads_).last(k);
    for (size_t j = 0; j < k; ++j) g_log_std[j] += d_log_std_[j];
  } else {
    logp_.resize(k);
    for (int r = 0; r < n; ++r) {
      const auto off = static_cast<size_t>(r) * k;
      nn::log_softmax(std::span<const float>(out_).subspan(off, k), logp_);
      entropy += nn::categorical_entropy(logp_);
      std::span<float> dz(dout_.data() + off, k);
      nn::categorical_grad(logp_, actions[static_cast<size_t>(r)].index, -coef[static_cast<size_t>(r)],
                           -ent_coef, dz);
    }
  }
  const float* dnet = dout_.data();
  if (!spec_.mirror.empty()) {
    draw_.resize(2 * dout_.size());
    mirror_spread(dout_, n, static_cast<int>(k), draw_);
    dnet = draw_.data();
  }
  mlp_.backward(params_, cache_, dnet, std::span<float>(grads_).first(mlp_.num_params()));
  return n > 0 ? static_cast<float>(entropy / n) : 0.0f;
}

}  // namespace squawk::rl
