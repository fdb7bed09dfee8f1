#include "rl/vpg.h"

#include <algorithm>
#include <cmath>

#include "dist/comm.h"
#include "rl/branch_returns.h"
#include "rl/episode_streams.h"
#include "rl/play.h"

namespace squawk::rl {

namespace {
constexpr uint64_t kTrainPolicySalt = 0x7EA1ull;
constexpr uint64_t kBranchSalt = 0xB4A7C4ull;
constexpr uint64_t kMinibatchSalt = 0x3B47C8ull;

// x summed over the ranks.
double total(double x) {
  dist::sum(std::span<double>(&x, 1));
  return x;
}
}

Status TrainConfig::validate() const {
  if (estimator != "vpg" && estimator != "improved" && estimator != "ppo" && estimator != "vine")
    return Status::invalid("train estimator '" + estimator +
                           "': expected \"vpg\", \"improved\", \"ppo\" or \"vine\"");
  if (episodes < 1) return Status::invalid("train episodes must be at least 1");
  if (stop_at < 0 || stop_at > episodes)
    return Status::invalid("train --stop-at " + std::to_string(stop_at) + ": expected 1.." + std::to_string(episodes) +
                           " (--episodes)");
  if (episodes_per_update < 1) return Status::invalid("train episodes_per_update must be at least 1");
  if (num_envs < 1) return Status::invalid("train num_envs must be at least 1");
  if (!(lr > 0.0) || !(lr_final > 0.0)) return Status::invalid("train lr and lr_final must be positive");
  if (!(gamma > 0.0 && gamma <= 1.0)) return Status::invalid("train gamma must lie in (0, 1]");
  if (entropy_coef < 0.0 || entropy_final.value_or(0.0) < 0.0)
    return Status::invalid("train entropy_coef and entropy_final must be >= 0");
  if (!(lambda >= 0.0 && lambda <= 1.0)) return Status::invalid("train lambda must lie in [0, 1]");
  if (epochs < 1 || epochs > 100) return Status::invalid("train epochs must lie in 1..100");
  if (minibatches < 1 || minibatches > 1024) return Status::invalid("train minibatches must lie in 1..1024");
  if (!(clip > 0.0 && clip < 1.0)) return Status::invalid("train clip must lie in (0, 1)");
  if (!(branch_fraction > 0.0 && branch_fraction <= 1.0))
    return Status::invalid("train branch_fraction must lie in (0, 1]");
  for (int h : value_hidden)
    if (h < 1 || h > 4096) return Status::invalid("train value_hidden widths must lie in 1..4096");
  if (value_iters < 0) return Status::invalid("train value_iters must be >= 0");
  if (eval_every < 0 || eval_episodes < 1)
    return Status::invalid("train eval_every must be >= 0 and eval_episodes >= 1");
  return Status::ok();
}

void TrainConfig::set_lr(double new_lr, std::optional<double> final_lr) {
  if (final_lr) {
    lr_final = *final_lr;
  } else if (new_lr != lr && lr > 0.0) {
    lr_final = lr_final / lr * new_lr;
  }
  lr = new_lr;
}

Status check_learner(const Policy& policy, const TrainConfig& config) {
  const bool scores = config.estimator == "ppo" || config.estimator == "vine";
  if (scores && !policy.has_log_probs())
    return Status::invalid("train estimator '" + config.estimator +
                           "' needs a policy that scores its actions; " + policy.name() +
                           " does not (use \"improved\")");
  if (config.estimator == "vine" && policy.action_values().empty())
    return Status::invalid("train estimator 'vine' needs a discrete action head; " + policy.name() +
                           " has a continuous one (use \"improved\" or \"ppo\")");
  return Status::ok();
}

Trainer::Trainer(Policy& policy, env::BatchEnv& envs, const TrainConfig& config,
                 long long update_index)
    : policy_(policy),
      envs_(envs),
      cfg_(config),
      adam_(policy.params(), policy.grads(),
            nn::AdamConfig{.lr = static_cast<float>(config.lr),
                           .grad_clip = static_cast<float>(config.grad_clip)}),
      updates_(update_index),
      slot_episode_(static_cast<size_t>(envs.size())),
      slot_index_(static_cast<size_t>(envs.size()), 0) {
  if (cfg_.estimator == "vpg" || cfg_.value_hidden.empty()) return;
  std::vector<int> sizes = {envs.obs_size()};
  sizes.insert(sizes.end(), cfg_.value_hidden.begin(), cfg_.value_hidden.end());
  sizes.push_back(1);
  auto mlp = nn::Mlp::make(sizes);
  if (!mlp) return;  // widths were validated; an empty result keeps the mean baseline
  value_ = std::make_unique<nn::Mlp>(std::move(*mlp));
  value_params_.assign(value_->num_params(), 0.0f);
  value_grads_.assign(value_->num_params(), 0.0f);
  Rng init(cfg_.seed ^ 0xBA5E11Eull);
  value_->init(value_params_, init);
  value_adam_ = std::make_unique<nn::Adam>(value_params_, value_grads_,
                                           nn::AdamConfig{.lr = static_cast<float>(cfg_.lr)});
}

Status Trainer::restore(const TrainState& s) {
  if (!s.has_adam) return Status::ok();
  if (s.adam_m.size() != adam_.m().size() || s.adam_v.size() != adam_.v().size())
    return Status::invalid("checkpoint holds Adam moments for " + std::to_string(s.adam_m.size()) +
                           " parameters, the policy has " + std::to_string(adam_.m().size()));
  const size_t nv = s.value_params.size();
  if (nv != value_params_.size() || s.value_m.size() != nv || s.value_v.size() != nv)
    return Status::invalid("checkpoint holds " + std::to_string(nv) +
                           " value-baseline parameters, the scenario's learner has " +
                           std::to_string(value_params_.size()));
  adam_.m() = s.adam_m;
  adam_.v() = s.adam_v;
  adam_.set_t(s.adam_t);
  if (!value_adam_) return Status::ok();
  value_params_ = s.value_params;
  value_adam_->m() = s.value_m;
  value_adam_->v() = s.value_v;
  value_adam_->set_t(s.value_t);
  return Status::ok();
}

void Trainer::save(TrainState& s) {
  const std::span<float> p = policy_.params();
  s.params.assign(p.begin(), p.end());
  s.has_adam = true;
  s.adam_t = adam_.t();
  s.adam_m = adam_.m();
  s.adam_v = adam_.v();
  s.value_params = value_params_;
  s.value_m = value_adam_ ? value_adam_->m() : std::vector<float>{};
  s.value_v = value_adam_ ? value_adam_->v() : std::vector<float>{};
  s.value_t = value_adam_ ? value_adam_->t() : 0;
}

Result<Trainer::ValueFit> Trainer::pretrain_value(const TeacherFlights& f, int epochs, int batch,
                                                  uint64_t seed) {
  if (!value_)
    return Status::invalid(
        "value pretraining needs the learned value baseline (estimator improved or ppo)");
  if (dist::size() > 1) return Status::invalid("value pretraining runs in a job of one rank");
  if (epochs < 1 || batch < 1)
    return Status::invalid("value pretraining: epochs and batch must be >= 1");
  const auto d = static_cast<size_t>(envs_.obs_size()), n = f.rewards.size();
  long long total_steps = 0;
  for (int len : f.lengths) total_steps += len;
  if (f.obs.size() != n * d || static_cast<size_t>(total_steps) != n)
    return Status::invalid(
        "value pretraining: " + std::to_string(f.obs.size()) + " observation numbers, " +
        std::to_string(n) + " rewards and " + std::to_string(total_steps) +
        " steps in the episode lengths (expected obs_size x steps, steps, steps)");
  std::vector<float> g(n);
  size_t start = 0;
  for (int len : f.lengths) {
    double acc = 0.0;
    for (size_t t = start + static_cast<size_t>(len); t-- > start;) {
      acc = f.rewards[t] + cfg_.gamma * acc;
      g[t] = static_cast<float>(acc);
    }
    start += static_cast<size_t>(len);
  }
  std::vector<float> v(n);
  const auto mse = [&] {
    if (n > 0) value_->forward(value_params_, f.obs.data(), static_cast<int>(n), v.data(), nullptr);
    double e = 0.0;
    for (size_t i = 0; i < n; ++i) e += (v[i] - g[i]) * (v[i] - g[i]);
    return n > 0 ? e / static_cast<double>(n) : 0.0;
  };
  ValueFit fit;
  fit.before = mse();
  const auto b = static_cast<size_t>(batch);
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = i;
  Rng shuffle(seed);
  std::vector<float> rows(b * d), vb(b), dv(b);
  nn::MlpCache cache;
  for (int e = 0; e < epochs; ++e) {
    for (size_t i = n; i-- > 1;)
      std::swap(order[i],
                order[static_cast<size_t>(shuffle.uniform_int(0, static_cast<int64_t>(i)))]);
    for (size_t lo = 0; lo + b <= n; lo += b) {
      for (size_t j = 0; j < b; ++j)
        std::copy_n(f.obs.begin() + static_cast<long>(order[lo + j] * d), d,
                    rows.begin() + static_cast<long>(j * d));
      value_->forward(value_params_, rows.data(), batch, vb.data(), &cache);
      for (size_t j = 0; j < b; ++j)
        dv[j] = static_cast<float>(2.0 * (vb[j] - g[order[lo + j]]) / static_cast<double>(b));
      std::fill(value_grads_.begin(), value_grads_.end(), 0.0f);
      value_->backward(value_params_, cache, dv.data(), value_grads_);
      value_adam_->step();
    }
  }
  fit.after = mse();
  return fit;
}

double Trainer::step_all() {
  dist::sum(policy_.grads());
  return adam_.step();
}

void Trainer::coefficients(std::vector<float>& coef, UpdateStats& st) {
  const size_t n = batch_samples_.size();
  const int rows = static_cast<int>(n);
  coef.assign(n, 0.0f);
  const double inv_n = 1.0 / static_cast<double>(samples_);
  if (cfg_.estimator == "vpg") {
    for (size_t i = 0; i < n; ++i) coef[i] = static_cast<float>(batch_samples_[i].reward * inv_n);
    return;
  }
  std::vector<float> g(n);
  size_t start = 0;
  for (int len : batch_lengths_) {
    double acc = 0.0;
    for (size_t t = start + static_cast<size_t>(len); t-- > start;) {
      acc = batch_samples_[t].reward + cfg_.gamma * acc;
      g[t] = static_cast<float>(acc);
    }
    start += static_cast<size_t>(len);
  }
  std::vector<double> adv(n);
  double value_loss = 0.0;
  if (value_) {
    std::vector<float> v(n);
    nn::MlpCache cache;
    if (rows > 0) value_->forward(value_params_, batch_obs_.data(), rows, v.data(), &cache);
    for (size_t i = 0; i < n; ++i) value_loss += (g[i] - v[i]) * (g[i] - v[i]) * inv_n;
    value_loss = total(value_loss);
    adv = advantages(v, g);
    std::vector<float> dv(n);
    for (int it = 0; it < cfg_.value_iters; ++it) {
      if (it > 0 && rows > 0) value_->forward(value_params_, batch_obs_.data(), rows, v.data(), &cache);
      for (size_t i = 0; i < n; ++i) dv[i] = static_cast<float>(2.0 * (v[i] - g[i]) * inv_n);
      std::fill(value_grads_.begin(), value_grads_.end(), 0.0f);
      if (rows > 0) value_->backward(value_params_, cache, dv.data(), value_grads_);
      dist::sum(value_grads_);
      value_adam_->step();
    }
  } else {
    double sum_g = 0.0;
    for (float x : g) sum_g += x;
    const double mean_g = total(sum_g) * inv_n;
    for (size_t i = 0; i < n; ++i) adv[i] = g[i] - mean_g;
  }
  double sum = 0.0, sq = 0.0;
  for (double a : adv) sum += a;
  const double mean = total(sum) * inv_n;
  for (double a : adv) sq += (a - mean) * (a - mean);
  const double sd = std::sqrt(total(sq) * inv_n);
  for (size_t i = 0; i < n; ++i) coef[i] = static_cast<float>((adv[i] - mean) / (sd + 1e-8) * inv_n);
  st.value_loss = value_loss;
  st.advantage_sd = sd;
}

std::vector<double> Trainer::advantages(const std::vector<float>& v, const std::vector<float>& g) const {
  std::vector<double> adv(g.size());
  if (cfg_.lambda >= 1.0) {
    for (size_t i = 0; i < g.size(); ++i) adv[i] = g[i] - v[i];
    return adv;
  }
  size_t start = 0;
  for (int len : batch_lengths_) {
    double acc = 0.0, next_v = 0.0;
    for (size_t t = start + static_cast<size_t>(len); t-- > start;) {
      const double delta = batch_samples_[t].reward + cfg_.gamma * next_v - v[t];
      acc = delta + cfg_.gamma * cfg_.lambda * acc;
      adv[t] = acc;
      next_v = v[t];
    }
    start += static_cast<size_t>(len);
  }
  return adv;
}

void Trainer::clipped_steps(const std::vector<float>& coef, const std::vector<ActionSample>& acts, double c_h,
                            UpdateStats& st) {
  const size_t local = acts.size(), obs = static_cast<size_t>(envs_.obs_size());
  const auto n = static_cast<size_t>(samples_), offset = static_cast<size_t>(offset_);
  const size_t parts = std::min(n, static_cast<size_t>(cfg_.minibatches));
  std::vector<float> old_logp(local);
  if (local > 0) policy_.log_probs(batch_obs_, static_cast<int>(local), acts, old_logp);
  // The whole batch's sample order; this rank holds samples [offset, offset + local).
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = i;
  Rng shuffle(env::episode_seed(cfg_.seed ^ kMinibatchSalt, static_cast<uint64_t>(updates_)));
  std::vector<float> rows, logp, c;
  std::vector<ActionSample> part_acts;
  std::vector<size_t> mine;  // local indices of this rank's samples in the part
  double clipped_last = 0.0;  // samples clipped in the last pass
  for (int e = 0; e < cfg_.epochs; ++e) {
    if (parts > 1)
      for (size_t i = n; i-- > 1;)
        std::swap(order[i], order[static_cast<size_t>(shuffle.uniform_int(0, static_cast<int64_t>(i)))]);
    for (size_t b = 0; b < parts; ++b) {
      const size_t lo = b * n / parts, m = (b + 1) * n / parts - lo;
      mine.clear();
      for (size_t j = lo; j < lo + m; ++j)
        if (order[j] >= offset && order[j] < offset + local) mine.push_back(order[j] - offset);
      const size_t k = mine.size();
      part_acts.resize(k);
      rows.resize(k * obs);
      for (size_t j = 0; j < k; ++j) {
        part_acts[j] = acts[mine[j]];
        std::copy_n(batch_obs_.begin() + static_cast<long>(mine[j] * obs), obs, rows.begin() + static_cast<long>(j * obs));
      }
      const bool first = e == 0 && b == 0;  // the sampling policy itself: rho = 1
      logp.resize(k);
      if (!first && k > 0) policy_.log_probs(rows, static_cast<int>(k), part_acts, logp);
      c.resize(k);
      const double scale = static_cast<double>(n) / static_cast<double>(m);  // coef holds 1/N; L_B wants 1/|B|
      for (size_t j = 0; j < k; ++j) {
        const size_t i = mine[j];
        // d/dtheta of min(rho A, clip(rho) A) is rho A dlog pi where the
        // unclipped term is the smaller one, 0 where the clip is active.
        const double rho = first ? 1.0 : std::exp(static_cast<double>(logp[j]) - old_logp[i]);
        const bool clipped = (coef[i] > 0.0f && rho > 1.0 + cfg_.clip) || (coef[i] < 0.0f && rho < 1.0 - cfg_.clip);
        if (clipped && e == cfg_.epochs - 1) clipped_last += 1.0;
        c[j] = clipped ? 0.0f : static_cast<float>(rho * coef[i] * scale);
      }
      std::fill(policy_.grads().begin(), policy_.grads().end(), 0.0f);
      // Called with no rows too: a policy with caches learns its parameters are about to change.
      const float h = policy_.accumulate_gradient(rows, static_cast<int>(k), part_acts, c,
                                                  static_cast<float>(c_h / static_cast<double>(m)));
      const double norm = step_all();
      if (e > 0) continue;
      st.entropy += total(h * static_cast<double>(k)) / static_cast<double>(n);
      if (b == 0) st.grad_norm = norm;
    }
  }
  st.clip_fraction = total(clipped_last) / static_cast<double>(n);
}

void Trainer::vine_steps(double c_h, UpdateStats& st) {
  const std::span<const double> values = policy_.action_values();
  const size_t k = values.size(), s = branch_states_.size(), n = s * k;
  const double states = total(static_cast<double>(s)), all = states * static_cast<double>(k);
  if (states == 0.0) return;
  Result<std::vector<double>> q = std::vector<double>{};
  if (s > 0) q = branch_returns(policy_, branch_states_, values, cfg_.gamma);
  if (dist::any(!q)) return;
  const auto obs = static_cast<size_t>(envs_.obs_size());
  std::vector<float> rows(n * obs);
  std::vector<ActionSample> acts(n);
  for (size_t i = 0; i < s; ++i)
    for (size_t j = 0; j < k; ++j) {
      branch_states_[i].observe_flat(std::span<float>(rows).subspan((i * k + j) * obs, obs));
      acts[i * k + j] = {static_cast<int>(j), static_cast<float>(values[j])};
    }
  std::vector<float> logp(n), coef(n);
  std::vector<double> adv(n);
  double sd = 0.0;
  for (int e = 0; e < cfg_.epochs; ++e) {
    if (n > 0) policy_.log_probs(rows, static_cast<int>(n), acts, logp);
    for (size_t i = 0; i < s; ++i) {
      double base = 0.0;
      for (size_t j = 0; j < k; ++j) base += std::exp(static_cast<double>(logp[i * k + j])) * (*q)[i * k + j];
      for (size_t j = 0; j < k; ++j) adv[i * k + j] = (*q)[i * k + j] - base;
    }
    if (e == 0) {
      for (double a : adv) sd += a * a;
      sd = std::sqrt(total(sd) / all) + 1e-8;
    }
    for (size_t i = 0; i < n; ++i)
      coef[i] = static_cast<float>(std::exp(static_cast<double>(logp[i])) * adv[i] / sd / states);
    std::fill(policy_.grads().begin(), policy_.grads().end(), 0.0f);
    const float h = policy_.accumulate_gradient(rows, static_cast<int>(n), acts, coef, static_cast<float>(c_h / all));
    const double norm = step_all();
    if (e > 0) continue;
    st.entropy = total(h * static_cast<double>(n)) / all;
    st.grad_norm = norm;
  }
}

bool Trainer::collect(const UpdateProgress& progress) {
  const auto obs = static_cast<size_t>(envs_.obs_size());
  const auto m = static_cast<uint64_t>(cfg_.episodes_per_update);
  const dist::Share part = dist::share(m);
  first_ = static_cast<uint64_t>(updates_) * m + part.first;
  episodes_.assign(part.count, Episode{});
  for (Episode& e : slot_episode_) e = Episode{};
  EpisodeStreams policy_streams(cfg_.seed ^ kTrainPolicySalt), branch_streams(cfg_.seed ^ kBranchSalt);
  env::VecEnv* const compiled = envs_.horizontal();
  const bool vine = cfg_.estimator == "vine" && compiled;
  const auto act = policy_choice(policy_, envs_, policy_streams, false);
  Driver driver;
  driver.choose = [&](Turn& t) {
    SQUAWK_RETURN_IF_ERROR(act(t));
    const std::span<Rng> branch_rngs = vine ? branch_streams.rows(envs_) : std::span<Rng>();
    for (size_t r = 0; r < t.slots.size(); ++r) {
      const auto s = static_cast<size_t>(t.slots[r]);
      slot_index_[s] = envs_.episode(t.slots[r]);
      auto& so = slot_episode_[s].obs;
      so.insert(so.end(), t.obs.begin() + static_cast<long>(r * obs),
                t.obs.begin() + static_cast<long>((r + 1) * obs));
      if (vine && branch_rngs[r].uniform() < cfg_.branch_fraction)
        slot_episode_[s].branches.push_back(compiled->env(t.slots[r]));
    }
    if (vine) branch_streams.keep(envs_);
    return Status::ok();
  };
  driver.after = [&](const Turn& t) {
    for (size_t r = 0; r < t.slots.size(); ++r) {
      const auto s = static_cast<size_t>(t.slots[r]);
      slot_episode_[s].samples.push_back({t.actions[r], static_cast<float>(t.rewards[r])});
      if (!t.dones[r]) continue;
      episodes_[slot_index_[s] - first_] = std::move(slot_episode_[s]);
      slot_episode_[s] = Episode{};
    }
    const auto done = static_cast<long long>(envs_.completed().size()) * dist::size();
    return !progress || progress(std::min(done, static_cast<long long>(m)));
  };
  // The choice above never fails (policy errors stay in Policy::error()).
  return play(envs_, cfg_.seed, first_, part.count, driver).value_or(false);
}

UpdateStats Trainer::update(const UpdateProgress& progress) {
  const bool played = collect(progress);
  batch_obs_.clear();
  batch_samples_.clear();
  batch_lengths_.clear();
  branch_states_.clear();
  for (Episode& e : episodes_) {
    batch_obs_.insert(batch_obs_.end(), e.obs.begin(), e.obs.end());
    batch_samples_.insert(batch_samples_.end(), e.samples.begin(), e.samples.end());
    if (!e.samples.empty()) batch_lengths_.push_back(static_cast<int>(e.samples.size()));
    for (auto& b : e.branches) branch_states_.push_back(std::move(b));
  }
  // One sum over the ranks: [stopped, episodes, return, success, samples per rank...].
  const auto ranks = static_cast<size_t>(dist::size());
  std::vector<double> sums(4 + ranks, 0.0);
  sums[0] = played ? 0.0 : 1.0;
  sums[1] = static_cast<double>(envs_.completed().size());
  for (const auto& e : envs_.completed()) {
    sums[2] += e.total_reward;
    sums[3] += e.success;
  }
  sums[4 + static_cast<size_t>(dist::rank())] = static_cast<double>(batch_samples_.size());
  dist::sum(sums);
  if (sums[0] > 0.0) {
    UpdateStats stopped;
    stopped.interrupted = true;
    return stopped;
  }
  UpdateStats st;
  st.episodes = static_cast<long long>(sums[1]);
  if (st.episodes > 0) {
    st.mean_return = sums[2] / sums[1];
    st.success_rate = sums[3] / sums[1];
  }
  samples_ = 0;
  offset_ = 0;
  for (size_t r = 0; r < ranks; ++r) {
    if (r == static_cast<size_t>(dist::rank())) offset_ = samples_;
    samples_ += static_cast<long long>(sums[4 + r]);
  }
  st.samples = static_cast<int>(samples_);
  ++updates_;
  if (st.samples == 0) return st;

  const auto m = static_cast<double>(cfg_.episodes_per_update);
  const double span = std::max(1.0, static_cast<double>(cfg_.episodes) / m);
  const double frac = std::min(1.0, static_cast<double>(updates_ - 1) / span);
  const double c_h = cfg_.entropy_coef + (cfg_.entropy_final.value_or(cfg_.entropy_coef) - cfg_.entropy_coef) * frac;
  adam_.config().lr = static_cast<float>(cfg_.lr + (cfg_.lr_final - cfg_.lr) * frac);
  if (cfg_.estimator == "vine") {
    vine_steps(c_h, st);
    return st;
  }
  std::vector<float> coef;
  coefficients(coef, st);
  const size_t local = batch_samples_.size();
  std::vector<ActionSample> batch_acts(local);
  for (size_t i = 0; i < local; ++i) batch_acts[i] = batch_samples_[i].action;
  if (cfg_.estimator == "ppo") {
    clipped_steps(coef, batch_acts, c_h, st);
    return st;
  }
  const float ent = cfg_.estimator == "vpg" ? 0.0f : static_cast<float>(c_h / static_cast<double>(samples_));
  std::fill(policy_.grads().begin(), policy_.grads().end(), 0.0f);
  const float h = policy_.accumulate_gradient(batch_obs_, static_cast<int>(local), batch_acts, coef, ent);
  st.entropy = total(h * static_cast<double>(local)) / static_cast<double>(samples_);
  st.grad_norm = step_all();
  return st;
}

}  // namespace squawk::rl
