// squawk gpt2 pretrain SCENARIO.lua OUT_DIR: self-supervised pretraining of the
// tiny GPT-2 on the observation prompts it will read as a policy, the offline
// stand-in for GPT-2's own pretraining (no GPT-2 weights are reachable).
//
// Data: the prompts the template renders for --episodes training episodes of
// the scenario under uniformly random actions (so turned, off-track states
// appear), tokenised by the tiny policy's own BPE; the last --holdout prompts
// are held out. Objective: next-token cross-entropy over every token after the
// static prefix (gpt2::Model::lm_loss_backward), plus, with --readout W > 0, W
// times the read-out loss (gpt2/readout.h: a linear probe recovers the
// observation each prompt renders from its last token's hidden state). Adam on
// every parameter (the probe: its own Adam), no action labels and no reward.
// Output: a Hugging Face folder (config.json,
// model.safetensors, vocab.json, merges.txt) that `squawk train --policy gpt2
// --model OUT_DIR` fine-tunes, and OUT_DIR/pretrain.csv with the losses.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>

#include "app/cli.h"
#include "app/gpt2_policy_factory.h"
#include "app/out_guard.h"
#include "app/vm_options.h"
#include "core/files.h"
#include "core/rng.h"
#include "env/vec_env.h"
#include "gpt2/checkpoint.h"
#include "gpt2/readout.h"
#include "nn/adam.h"
#include "rl/play.h"
#include "script/scenario.h"

namespace squawk::app {

namespace {

// Every prompt the policy reads while `envs` run `episodes` episodes from
// `seed` under uniformly random actions: its token ids (prefix included) and
// the observation it renders (obs [N, obs_size]).
struct Corpus {
  std::vector<std::vector<int>> seqs;
  std::vector<float> obs;
};

Result<Corpus> prompt_corpus(rl::PromptPolicy& policy, env::VecEnv& envs, long long episodes, uint64_t seed) {
  static const float kActions[] = {-1.0f, -0.5f, 0.0f, 0.5f, 1.0f};
  Corpus out;
  Rng rng(seed ^ 0x9E7Bull);
  const auto d = static_cast<size_t>(envs.obs_size());
  rl::Driver driver;
  driver.choose = [&](rl::Turn& t) -> Status {
    for (size_t i = 0; i < t.slots.size(); ++i) {
      const auto row = t.obs.subspan(i * d, d);
      SQUAWK_ASSIGN_OR_RETURN(std::vector<int> ids, policy.suffix_tokens(row));
      std::vector<int> seq = policy.prefix_tokens();
      seq.insert(seq.end(), ids.begin(), ids.end());
      out.seqs.push_back(std::move(seq));
      out.obs.insert(out.obs.end(), row.begin(), row.end());
    }
    for (rl::ActionSample& a : t.actions) a.value = kActions[rng.uniform_int(0, 4)];
    return Status::ok();
  };
  SQUAWK_RETURN_IF_ERROR(rl::play(envs, seed, 0, static_cast<uint64_t>(episodes), driver).status());
  return out;
}

// Mean over the d columns of obs [N, d] of each column's variance over rows
// from..N-1: the read-out error of a constant answer, the mean.
double mean_variance(const std::vector<float>& obs, size_t from, int d) {
  const auto D = static_cast<size_t>(d);
  const size_t n = obs.size() / D - from;
  double total = 0.0;
  for (size_t c = 0; c < D; ++c) {
    double s = 0.0, s2 = 0.0;
    for (size_t r = from; r < from + n; ++r) {
      const double x = obs[r * D + c];
      s += x;
      s2 += x * x;
    }
    total += s2 / static_cast<double>(n) - (s / static_cast<double>(n)) * (s / static_cast<double>(n));
  }
  return total / static_cast<double>(D);
}

}  // namespace

int cmd_gpt2_pretrain(const ArgV& argv) {
  auto args = Args::parse(argv, with_vm_flags({{"--prompt", "--episodes", "--steps", "--batch", "--lr", "--seed",
                                                "--model-seed", "--holdout", "--log-every", "--readout", "--precision"},
                                               {"--quiet", "--force"}}));
  if (!args) return usage_error("gpt2", args.status().message());
  if (args->positional().size() != 2) return usage_error("gpt2", "pretrain expects SCENARIO.lua OUT_DIR");
  if (Status st = apply_precision_flag(*args); !st.is_ok()) return usage_error("gpt2", st.message());
  const std::pair<const char*, long long> defaults[] = {{"--episodes", 600}, {"--steps", 3000}, {"--batch", 16},
                                                        {"--seed", 1},       {"--model-seed", 0}, {"--holdout", 256},
                                                        {"--log-every", 100}};
  std::vector<long long> v;
  for (const auto& [flag, def] : defaults) {
    auto x = args->get_int(flag, def);
    if (!x || *x < (std::string(flag) == "--model-seed" ? 0 : 1))
      return usage_error("gpt2", std::string(flag) + " expects a positive integer");
    v.push_back(*x);
  }
  const long long episodes = v[0], steps = v[1], batch = v[2], holdout = v[5], log_every = v[6];
  const auto seed = static_cast<uint64_t>(v[3]);
  auto lr = args->get_double("--lr", 1e-3);
  if (!lr || !(*lr > 0.0 && *lr < 1.0)) return usage_error("gpt2", "--lr expects a number in (0, 1)");
  auto readout = args->get_double("--readout", 0.0);
  if (!readout || !(*readout >= 0.0 && *readout <= 1000.0))
    return usage_error("gpt2", "--readout expects a weight in [0, 1000]");
  const double readout_weight = *readout;
  script::VmOptions vo;
  script::Scenario sc;
  if (int rc = load_episode_scenario(*args, "gpt2", vo, sc); rc != kExitOk) return rc;
  const std::string out = args->positional()[1];
  const bool quiet = args->has("--quiet");
  if (Status st = check_absent(out, {out + "/model.safetensors", out + "/pretrain.csv"}, args->has("--force"));
      !st.is_ok())
    return usage_error("gpt2", "pretrain: " + st.message());

  script::Gpt2PolicyOptions po;
  po.model_seed = static_cast<uint64_t>(v[4]);
  po.prompt = args->get_or("--prompt", "");
  po.spec.trainable_blocks = gpt2::Config::tiny().n_layer;
  po.spec.train_embeddings = true;
  auto g = script::make_gpt2_policy(po, sc.train_env, vo);
  if (!g) return failure(g.status());
  rl::PromptPolicy& policy = *g->policy;
  gpt2::Model& model = policy.model();
  auto envs = env::VecEnv::make(sc.train_env, 16);
  if (!envs) return failure(envs.status());
  auto corpus = prompt_corpus(policy, *envs, episodes, seed);
  if (!corpus) return failure(corpus.status());
  const size_t n_all = corpus->seqs.size();
  if (n_all <= static_cast<size_t>(holdout))
    return usage_error("gpt2", std::to_string(n_all) + " prompts from " + std::to_string(episodes) +
                                   " episodes leave none to train on after --holdout " + std::to_string(holdout));
  const size_t n_train = n_all - static_cast<size_t>(holdout);
  const size_t P = policy.prefix_tokens().size();
  const int from = static_cast<int>(P) - 1;
  if (!quiet) {
    std::printf("pretraining the tiny gpt2 (%lld parameters) on %zu prompts (%zu held out) from %lld episodes; "
                "%lld steps of %lld prompts, lr %g\n",
                model.config().num_params(), n_train, static_cast<size_t>(holdout), episodes, steps, batch, *lr);
    if (readout_weight > 0.0)
      std::printf("read-out weight %g; a probe that always answered the held-out mean would score mse %.5f\n",
                  readout_weight, mean_variance(corpus->obs, n_train, envs->obs_size()));
  }

  if (Status st = files::make_dirs(out); !st.is_ok()) return failure(st);
  std::ofstream log(out + "/pretrain.csv");
  if (!log) return failure(Status::io_error("cannot write " + out + "/pretrain.csv"));
  log << "step,prompts,wall_s,train_loss,holdout_loss" << (readout_weight > 0.0 ? ",train_readout,holdout_readout" : "")
      << "\n";
  nn::Adam adam(model.trainable_params(), model.grads(), {.lr = static_cast<float>(*lr), .grad_clip = 1.0f});
  // The read-out probe (only with --readout): its own Adam and draws.
  Rng probe_rng(seed ^ 0x5EAD07ull);
  gpt2::Readout probe = gpt2::Readout::make(model.config().n_embd, envs->obs_size(), probe_rng);
  nn::Adam probe_adam(probe.params, probe.grads, {.lr = static_cast<float>(*lr), .grad_clip = 1.0f});
  gpt2::PrefixCache cache;
  // Next-token and read-out losses of the prompts `idx`; with `train` their
  // gradients accumulate (the read-out's times its weight), else the model's
  // are cleared after. The read-out is 0 without --readout.
  auto losses = [&](const std::vector<size_t>& idx, bool train) -> Result<std::pair<double, double>> {
    std::vector<std::vector<int>> seqs, rests;
    std::vector<float> targets;
    const size_t d = static_cast<size_t>(probe.D);
    for (size_t i : idx) {
      seqs.push_back(corpus->seqs[i]);
      rests.emplace_back(corpus->seqs[i].begin() + static_cast<long>(P), corpus->seqs[i].end());
      targets.insert(targets.end(), corpus->obs.begin() + static_cast<long>(i * d),
                     corpus->obs.begin() + static_cast<long>((i + 1) * d));
    }
    SQUAWK_ASSIGN_OR_RETURN(double lm, model.lm_loss_backward(seqs, from));
    double ro = 0.0;
    if (readout_weight > 0.0) {
      if (train) {
        SQUAWK_ASSIGN_OR_RETURN(ro, gpt2::readout_loss_backward(model, cache, rests, targets, probe,
                                                                static_cast<float>(readout_weight)));
      } else {
        SQUAWK_ASSIGN_OR_RETURN(ro, gpt2::readout_loss(model, cache, rests, targets, probe));
      }
    }
    if (!train) model.zero_grads();
    return std::make_pair(lm, ro);
  };
  // Mean losses over the held-out prompts, in batches; no update.
  auto holdout_losses = [&]() -> Result<std::pair<double, double>> {
    cache = {};
    SQUAWK_RETURN_IF_ERROR(model.extend(cache, policy.prefix_tokens()));
    std::pair<double, double> sum{0.0, 0.0};
    int parts = 0;
    for (size_t i = n_train; i < n_all; i += static_cast<size_t>(batch), ++parts) {
      std::vector<size_t> idx;
      for (size_t j = i; j < std::min(n_all, i + static_cast<size_t>(batch)); ++j) idx.push_back(j);
      SQUAWK_ASSIGN_OR_RETURN(auto l, losses(idx, false));
      sum.first += l.first;
      sum.second += l.second;
    }
    return std::make_pair(sum.first / parts, sum.second / parts);
  };
  if (Status st = model.extend(cache, policy.prefix_tokens()); !st.is_ok()) return failure(st);
  Rng pick(seed);
  const auto t0 = std::chrono::steady_clock::now();
  double run = 0.0, run_ro = 0.0;
  for (long long step = 1; step <= steps; ++step) {
    std::vector<size_t> idx;
    for (long long b = 0; b < batch; ++b)
      idx.push_back(static_cast<size_t>(pick.uniform_int(0, static_cast<int64_t>(n_train) - 1)));
    model.zero_grads();
    std::fill(probe.grads.begin(), probe.grads.end(), 0.0f);
    auto l = losses(idx, true);
    if (!l) return failure(l.status());
    adam.step();
    if (readout_weight > 0.0) probe_adam.step();
    run += l->first;
    run_ro += l->second;
    if (step % log_every == 0 || step == steps) {
      auto h = holdout_losses();
      if (!h) return failure(h.status());
      const double k = static_cast<double>(step % log_every == 0 ? log_every : step % log_every);
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      char row[200];
      std::snprintf(row, sizeof row, "%lld,%lld,%.1f,%.4f,%.4f", step, step * batch, wall, run / k, h->first);
      log << row;
      if (readout_weight > 0.0) {
        std::snprintf(row, sizeof row, ",%.6f,%.6f", run_ro / k, h->second);
        log << row;
      }
      log << "\n" << std::flush;
      if (!quiet) {
        std::printf("step %lld: train loss %.4f, held-out loss %.4f nats per token", step, run / k, h->first);
        if (readout_weight > 0.0) std::printf("; read-out mse %.5f, held-out %.5f", run_ro / k, h->second);
        std::printf(", %.0f s\n", wall);
      }
      run = run_ro = 0.0;
    }
  }
  // A plain GPT-2 folder: the policy's action head (untouched here) stays out.
  auto plain = gpt2::Model::create(model.config());
  if (!plain) return failure(plain.status());
  std::copy_n(model.params().begin(), plain->params().size(), plain->params().begin());
  Status st = gpt2::save_model(out, *plain);
  if (st.is_ok()) st = policy.tokenizer().save(out);
  if (!st.is_ok()) return failure(st);
  if (!quiet)
    std::printf("wrote %s (config.json, model.safetensors, vocab.json, merges.txt, pretrain.csv); fine-tune it with\n"
                "  squawk train %s --policy gpt2 --model %s --train-embeddings --blocks %d --lr 1e-4 \\\n"
                "      --entropy 0.05 --entropy-final 0.002 --episodes-per-update 32 --envs 32 --episodes 32768 --out DIR\n",
                out.c_str(), args->positional()[0].c_str(), out.c_str(), model.config().n_layer);
  return kExitOk;
}

}  // namespace squawk::app
