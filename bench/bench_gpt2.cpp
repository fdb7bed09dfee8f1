// GPT-2 small (124M, random weights) on the CPU: forward tokens/s and GFLOP/s
// at T = 256, B = 1 and 8, 1 and 2 threads, fp32 and bf16 products
// interleaved, each against its own 2048^3 peak this process measures, plus
// forward+backward time per prompt with the last block trainable, and the
// bf16 / fp32 ratios. Prints figures only; asserts nothing.
//
// usage: bench_gpt2 [--json] [--tiny]
#include <cstdio>
#include <cstring>

#include "gpt2/benchmark.h"

int main(int argc, char** argv) {
  squawk::gpt2::BenchOptions opt;
  bool json = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--json") == 0) {
      json = true;
    } else if (std::strcmp(argv[i], "--tiny") == 0) {
      opt.cfg = squawk::gpt2::Config::tiny();
    } else {
      std::fprintf(stderr, "usage: bench_gpt2 [--json] [--tiny]\n");
      return 2;
    }
  }
  auto rep = squawk::gpt2::run_benchmark(opt);
  if (!rep) {
    std::fprintf(stderr, "bench_gpt2: %s\n", rep.status().message().c_str());
    return 1;
  }
  std::fputs(json ? (squawk::gpt2::bench_json(*rep, opt) + "\n").c_str()
                  : squawk::gpt2::bench_table(*rep, opt).c_str(),
             stdout);
  return 0;
}
