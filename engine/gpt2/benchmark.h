// Throughput of the GPT-2 forward pass and of the tail backward, against the
// machine's own sgemm peak (shared by `squawk gpt2 bench` and bench/bench_gpt2).
//
// FLOPs counted per forward of B sequences of T tokens to the last position's
// logits (Model::forward_last, then the LM head), GPT-2 shapes (C, L, V): in
// each of the first L - 1 blocks matrix products 24 B T C^2 and causal
// attention 2 B C T (T + 1) (the scores and the weighted sum over the keys each
// position sees); in the last block, which only the last position leaves, the
// q/k/v product 6 B T C^2, the other products 18 B C^2 and attention 4 B C T;
// the LM head 2 B C V. The sgemm peak is the best rate of a 2048^3 product
// through nn::gemm at the same thread count.
#pragma once

#include <string>
#include <vector>

#include "core/status.h"
#include "gpt2/config.h"

namespace squawk::gpt2 {

struct BenchOptions {
  Config cfg = Config::gpt2_small();
  int T = 256;
  std::vector<int> batches = {1, 8};
  std::vector<int> threads = {1, 2};
  int trainable_blocks = 1;
  double min_seconds = 1.0;  // per measurement (at least two repetitions)
};

struct BenchRun {
  int threads = 1, B = 1, T = 0;
  double forward_s = 0.0;         // one forward of the batch [s]
  double tokens_per_s = 0.0;
  double gflops = 0.0;            // counted FLOPs / forward time
  double fraction_of_peak = 0.0;  // gflops / sgemm peak at these threads
  double matmul_gflops = 0.0;     // inside gemm calls only, same (best) repetition as gflops
  double matmul_fraction = 0.0;
  double train_s_per_prompt = 0.0;  // forward_train + backward, per sequence [s]
};

struct BenchReport {
  std::string backend;
  std::vector<int> threads;
  std::vector<double> peak_gflops;  // per entry of threads
  double eigen_peak_gflops_1t = 0.0;  // the Eigen fallback at one thread, for comparison
  std::vector<BenchRun> runs;
};

Result<BenchReport> run_benchmark(const BenchOptions& opt);
// One JSON object: gflops, peak_gflops, fraction_of_peak (B = 1 at the first
// thread count), backend, and every run.
std::string bench_json(const BenchReport& r, const BenchOptions& opt);
std::string bench_table(const BenchReport& r, const BenchOptions& opt);

}  // namespace squawk::gpt2
