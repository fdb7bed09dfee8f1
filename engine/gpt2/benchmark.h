// Throughput of the GPT-2 forward pass and of the tail backward at fp32 and at
// bf16 products, each against its own peak measured the same way, in one
// process with the two precisions interleaved (shared by `squawk gpt2 bench`
// and bench/bench_gpt2).
//
// FLOPs counted per forward of B sequences of T tokens to the last position's
// logits (Model::forward_last, then the LM head), GPT-2 shapes (C, L, V): in
// each of the first L - 1 blocks matrix products 24 B T C^2 and causal
// attention 2 B C T (T + 1) (the scores and the weighted sum over the keys each
// position sees); in the last block, which only the last position leaves, the
// q/k/v product 6 B T C^2, the other products 18 B C^2 and attention 4 B C T;
// the LM head 2 B C V. A precision's peak is the best rate of a 2048^3 product
// through its GEMM entry point (nn::gemm on fp32 operands, nn::gemm_bf16 on
// bf16 operands) at the same thread count.
#pragma once

#include <string>
#include <vector>

#include "core/status.h"
#include "gpt2/config.h"
#include "nn/gemm.h"

namespace squawk::gpt2 {

struct BenchOptions {
  Config cfg = Config::gpt2_small();
  int T = 256;
  std::vector<int> batches = {1, 8};
  std::vector<int> threads = {1, 2};
  std::vector<nn::Precision> precisions = {nn::Precision::kFp32, nn::Precision::kBf16};
  int trainable_blocks = 1;
  double min_seconds = 1.0;  // per measurement and precision (at least two repetitions)
};

struct BenchRun {
  int threads = 1, B = 1, T = 0;
  nn::Precision precision = nn::Precision::kFp32;
  double forward_s = 0.0;         // one forward of the batch [s]
  double tokens_per_s = 0.0;
  double gflops = 0.0;            // counted FLOPs / forward time
  double fraction_of_peak = 0.0;  // gflops / this precision's peak at these threads
  double matmul_gflops = 0.0;     // inside gemm calls only, same (best) repetition as gflops
  double matmul_fraction = 0.0;
  double train_s_per_prompt = 0.0;  // forward_train + backward, per sequence [s]
};

struct BenchReport {
  std::string backend;       // fp32 GEMM backend
  std::string bf16_library;  // nn::bf16_library()
  std::vector<int> threads;
  std::vector<nn::Precision> precisions;
  // peak_gflops[i][j]: precision j at threads[i].
  std::vector<std::vector<double>> peak_gflops;
  double eigen_peak_gflops_1t = 0.0;  // the Eigen fp32 fallback at one thread, for comparison
  std::vector<BenchRun> runs;  // per thread count, batch, then precision
};

Result<BenchReport> run_benchmark(const BenchOptions& opt);
// One JSON object: gflops, peak_gflops, fraction_of_peak (fp32, or the first
// precision measured, B = first batch at the first thread count), backend,
// bf16 (the same three at bf16 and speedup, when measured), and every run.
std::string bench_json(const BenchReport& r, const BenchOptions& opt);
std::string bench_table(const BenchReport& r, const BenchOptions& opt);

}  // namespace squawk::gpt2
