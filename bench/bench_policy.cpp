// GPT-2 prompt policy speed. First one update of the mirror-symmetric recipe
// (README: the shipped pretrained folder, --mirror --train-embeddings
// --blocks 2, PPO 4 epochs, 32 episodes on 32 envs) with glibc's default heap
// and again after heap::keep_freed_memory(), same seeds, in one process (the
// default first: the heap setting cannot be undone); then, with the heap kept
// as `squawk` keeps it, decisions per second at B = 1 and batched and the time
// of one fine-tuning update, for the tiny offline model and for a GPT-2 small
// folder, the latter with fp32 products and again with bf16 products (same
// seeds, one process), with the projection of the paper's run (20 000
// episodes) at each. Prints figures only; asserts nothing.
//
// usage: bench_policy [--write-small DIR] [--small DIR] [--small-only] [--batch N] [--update-episodes M]
//                     [--threads N] [--precision fp32|bf16]
//   --write-small DIR  writes a GPT-2 small folder with random weights in the
//                      Hugging Face format (config.json, model.safetensors,
//                      vocab.json, merges.txt: the gpt2 checkpoint writer, and
//                      the tiny policy's prompt-trained BPE vocabulary, since
//                      no real GPT-2 vocabulary is reachable offline) and exits
//   --small DIR        also measures the policy on that folder (k = 1), at fp32
//                      then at bf16 products
//   --small-only       skips the heap and tiny-model measurements
//   --precision P      measures the GPT-2 small folder at that precision only
//                      (for profiling one; the projection then names one)
//   --threads N        matrix-product threads (default 1; the other core may
//                      be busy, so compare 1 and 2 from the same machine state)
// Observations come from the training episodes of scenarios/horizontal_cr.lua.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "app/gpt2_policy_factory.h"
#include "core/heap.h"
#include "core/paths.h"
#include "env/horizontal_cr.h"
#include "env/vec_env.h"
#include "gpt2/checkpoint.h"
#include "nn/gemm.h"
#include "rl/vpg.h"
#include "script/scenario.h"

using namespace squawk;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// CPU time of this process [s], every thread: on a machine shared with other
// jobs it counts the work done, where wall time counts the waits too.
double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Observations of the first decisions of a few training episodes [n, obs].
std::vector<float> observations(const env::HorizontalCrConfig& cfg, int n) {
  auto envs = env::VecEnv::make(cfg, n);
  envs->start(1, 0, static_cast<uint64_t>(n));
  return {envs->observations().begin(), envs->observations().end()};
}

// The paper's fine-tuning run [episodes].
constexpr double kPaperEpisodes = 20000;

// Seconds of one update per episode, wall and CPU.
struct PerEpisode {
  double wall = 0.0, cpu = 0.0;
};

// Decisions per second and one update of update_episodes episodes; the
// update's seconds per episode go to *per_episode when given.
int measure(const std::string& model, const script::Scenario& sc, int batch, int update_episodes,
            PerEpisode* per_episode = nullptr) {
  app::Gpt2PolicyOptions o;
  o.model = model;
  auto g = app::make_gpt2_policy(o, sc.train_env, {});
  if (!g) {
    std::fprintf(stderr, "bench_policy: %s\n", g.status().message().c_str());
    return 1;
  }
  rl::PromptPolicy& p = *g->policy;
  const std::vector<float> obs = observations(sc.train_env, batch);
  const int n = static_cast<int>(obs.size()) / p.obs_size();
  auto len = p.suffix_tokens(std::span<const float>(obs).first(static_cast<size_t>(p.obs_size())));
  std::printf("%s: %zu trainable parameters (k = %d), prompt %zu prefix + %zu tokens\n", model.c_str(),
              p.params().size(), p.spec().trainable_blocks, p.prefix_tokens().size(), len ? len->size() : 0);
  Rng rng(1);
  std::vector<rl::ActionSample> out(static_cast<size_t>(n));
  p.act(obs, 1, {}, {&rng, 1}, false, out);  // builds the prefix cache
  for (int b : {1, n}) {
    p.set_chunk_rows(b);
    const int reps = b == 1 ? std::min(n, 8) : 1;
    const auto t0 = std::chrono::steady_clock::now();
    for (int r = 0; r < reps; ++r)
      p.act(std::span<const float>(obs).subspan(static_cast<size_t>(r * b * p.obs_size())), b, {}, {&rng, 1}, false, out);
    const double s = seconds_since(t0);
    std::printf("  B = %-3d  %8.1f ms per decision  %8.1f decisions/s\n", b, 1e3 * s / (reps * b), reps * b / s);
  }
  p.set_chunk_rows(32);
  rl::TrainConfig cfg = sc.train;
  cfg.episodes_per_update = update_episodes;
  cfg.num_envs = update_episodes;
  cfg.estimator = "vpg";
  auto envs = env::VecEnv::make(sc.train_env, cfg.num_envs);
  rl::Trainer trainer(p, *envs, cfg, 0);
  const auto t0 = std::chrono::steady_clock::now();
  const double c0 = cpu_seconds();
  const rl::UpdateStats st = trainer.update();
  const double s = seconds_since(t0), cpu = cpu_seconds() - c0;
  std::printf("  update of %d episodes (%d decisions, rollout + forward/backward + Adam): %.2f s (CPU %.2f s), "
              "%.1f ms per decision\n",
              update_episodes, st.samples, s, cpu, st.samples > 0 ? 1e3 * s / st.samples : 0.0);
  if (per_episode) *per_episode = {s / update_episodes, cpu / update_episodes};
  if (!p.error().is_ok()) std::fprintf(stderr, "bench_policy: %s\n", p.error().message().c_str());
  return p.error().is_ok() ? 0 : 1;
}

// Seconds of one update of the mirror-symmetric recipe from the shipped
// pretrained folder; `params` receives the parameters after it.
Result<double> mirror_recipe_update(const script::Scenario& sc, std::vector<float>& params) {
  app::Gpt2PolicyOptions o;
  o.model = paths::resource("models/horizontal_cr_gpt2_tiny_pretrained");
  o.spec.trainable_blocks = 2;
  o.spec.train_embeddings = true;
  SQUAWK_ASSIGN_OR_RETURN(o.spec.mirror, env::observation_mirror(sc.train_env));
  SQUAWK_ASSIGN_OR_RETURN(app::Gpt2Policy g, app::make_gpt2_policy(o, sc.train_env, {}));
  rl::TrainConfig cfg = sc.train;
  cfg.estimator = "ppo";
  cfg.epochs = 4;
  cfg.episodes_per_update = 32;
  cfg.num_envs = 32;
  auto envs = env::VecEnv::make(sc.train_env, cfg.num_envs);
  rl::Trainer trainer(*g.policy, *envs, cfg, 0);
  const auto t0 = std::chrono::steady_clock::now();
  trainer.update();
  const double s = seconds_since(t0);
  SQUAWK_RETURN_IF_ERROR(g.policy->error());
  params.assign(g.policy->params().begin(), g.policy->params().end());
  return s;
}

int measure_heap(const script::Scenario& sc) {
  std::vector<float> before, after;
  auto t_default = mirror_recipe_update(sc, before);
  heap::keep_freed_memory();
  auto t_kept = t_default.is_ok() ? mirror_recipe_update(sc, after) : t_default;
  if (!t_kept) {
    std::fprintf(stderr, "bench_policy: %s\n", t_kept.status().message().c_str());
    return 1;
  }
  std::printf("mirror recipe update (32 episodes, PPO 4 epochs, every parameter trains): glibc default heap "
              "%.2f s, freed memory kept %.2f s (%.2fx); parameters after it %s\n",
              *t_default, *t_kept, *t_default / *t_kept, before == after ? "bit-identical" : "DIFFER");
  return before == after ? 0 : 1;
}

int write_small(const std::string& dir, const script::Scenario& sc) {
  app::Gpt2PolicyOptions o;
  auto tiny = app::make_gpt2_policy(o, sc.train_env, {});
  if (!tiny) {
    std::fprintf(stderr, "bench_policy: %s\n", tiny.status().message().c_str());
    return 1;
  }
  auto m = gpt2::Model::create(gpt2::Config::gpt2_small());
  Rng rng(124);
  m->init_random(rng);
  Status st = gpt2::save_model(dir, *m);
  if (st.is_ok()) st = tiny->policy->tokenizer().save(dir);
  if (!st.is_ok()) {
    std::fprintf(stderr, "bench_policy: %s\n", st.message().c_str());
    return 1;
  }
  std::printf("wrote a random GPT-2 small folder to %s\n", dir.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string small, write;
  int batch = 32, update_episodes = 8, threads = 1;
  bool small_only = false;
  std::vector<nn::Precision> precisions = {nn::Precision::kFp32, nn::Precision::kBf16};
  for (int i = 1; i < argc; ++i) {
    const bool more = i + 1 < argc;
    if (std::strcmp(argv[i], "--small") == 0 && more) {
      small = argv[++i];
    } else if (std::strcmp(argv[i], "--write-small") == 0 && more) {
      write = argv[++i];
    } else if (std::strcmp(argv[i], "--batch") == 0 && more) {
      batch = std::atoi(argv[++i]);
    } else if (std::strcmp(argv[i], "--update-episodes") == 0 && more) {
      update_episodes = std::atoi(argv[++i]);
    } else if (std::strcmp(argv[i], "--threads") == 0 && more) {
      threads = std::atoi(argv[++i]);
    } else if (std::strcmp(argv[i], "--precision") == 0 && more) {
      auto p = nn::parse_precision(argv[++i]);
      if (!p) {
        std::fprintf(stderr, "bench_policy: --precision: %s\n", p.status().message().c_str());
        return 2;
      }
      precisions = {*p};
    } else if (std::strcmp(argv[i], "--small-only") == 0) {
      small_only = true;
    } else {
      std::fprintf(stderr,
                   "usage: bench_policy [--write-small DIR] [--small DIR] [--small-only] [--batch N] "
                   "[--update-episodes M] [--threads N] [--precision fp32|bf16]\n");
      return 2;
    }
  }
  auto sc = script::load_scenario(paths::resource("scenarios/horizontal_cr.lua"), {});
  if (!sc) {
    std::fprintf(stderr, "bench_policy: %s\n", sc.status().message().c_str());
    return 1;
  }
  if (!write.empty()) return write_small(write, *sc);
  if (threads < 1) {
    std::fprintf(stderr, "bench_policy: --threads must be >= 1\n");
    return 2;
  }
  nn::set_num_threads(threads);
  std::printf("%d matrix-product thread%s\n", threads, threads == 1 ? "" : "s");
  if (small_only && small.empty()) {
    std::fprintf(stderr, "bench_policy: --small-only needs --small DIR\n");
    return 2;
  }
  // Freed memory stays in the heap from here on, as in `squawk` (measure_heap
  // sets it after its default-heap run).
  if (small_only) heap::keep_freed_memory();
  if (!small_only) {
    if (int rc = measure_heap(*sc); rc != 0) return rc;
    if (int rc = measure("tiny", *sc, batch, update_episodes); rc != 0) return rc;
  }
  if (small.empty()) return 0;
  // The same seeds at each precision: the update's episodes start alike.
  PerEpisode s_fp32, s_bf16;
  for (nn::Precision p : precisions) {
    nn::set_gemm_precision(p);
    std::printf("%s products%s\n", nn::precision_name(p),
                p == nn::Precision::kBf16 ? (std::string(", ") + nn::bf16_library()).c_str() : "");
    if (int rc = measure(small, *sc, batch, update_episodes, p == nn::Precision::kBf16 ? &s_bf16 : &s_fp32); rc != 0)
      return rc;
  }
  const double h = kPaperEpisodes / 3600;
  if (precisions.size() == 1) {
    const PerEpisode& one = precisions[0] == nn::Precision::kBf16 ? s_bf16 : s_fp32;
    std::printf("paper run (%.0f episodes, %s): %s %.1f h (CPU %.1f h)\n", kPaperEpisodes, small.c_str(),
                nn::precision_name(precisions[0]), one.wall * h, one.cpu * h);
    return 0;
  }
  std::printf("paper run (%.0f episodes, %s): fp32 %.1f h, bf16 %.1f h (%.2fx faster); CPU time fp32 %.1f h, "
              "bf16 %.1f h (%.2fx)\n",
              kPaperEpisodes, small.c_str(), s_fp32.wall * h, s_bf16.wall * h, s_fp32.wall / s_bf16.wall,
              s_fp32.cpu * h, s_bf16.cpu * h, s_fp32.cpu / s_bf16.cpu);
  return 0;
}
