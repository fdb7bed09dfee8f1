// The cost of the learners' gradient sum (dist::sum, one MPI_Allreduce of
// float32) for GPT-2 small's parameter counts: the trainable tail of the
// paper's recipe (k = 1: the last block 12 C^2 + 13 C, ln_f 2 C and the
// 5-action head 5 C + 5, C = 768: 7 093 253) and every parameter (the 124 439 808
// of Hugging Face's gpt2 plus the head), and the MLP's 12 581.
//   mpirun -np N build/bench_allreduce [--seconds S]
// Rank 0 prints, per size: seconds per sum (median over repeats) and the
// algorithm bandwidth bytes / time. Prints figures only.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "dist/comm.h"

using namespace squawk;
using Clock = std::chrono::steady_clock;

int main(int argc, char** argv) {
  dist::init(&argc, &argv);
  double min_seconds = 2.0;  // [s] per size
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--seconds") == 0) min_seconds = std::atof(argv[i + 1]);
  struct Size {
    const char* what;
    long long floats;
  };
  const Size sizes[] = {{"MLP policy (28-96-96-5)", 12581},
                        {"GPT-2 small, k = 1 trainable tail", 7'093'253},
                        {"GPT-2 small, every parameter", 124'443'653}};
  if (dist::rank() == 0)
    std::printf("dist::sum (MPI_Allreduce, float32) on %d rank(s), %s\n%-36s %14s %12s %12s %8s\n", dist::size(),
                dist::describe().c_str(), "buffer", "floats", "s per sum", "GB/s", "repeats");
  for (const Size& s : sizes) {
    std::vector<float> x(static_cast<size_t>(s.floats), 1.0f);
    dist::sum(x);  // warm-up: pages touched, connections made
    std::vector<double> times;
    double spent = 0.0;
    bool more = true;
    while (more) {
      const auto t0 = Clock::now();
      dist::sum(x);
      const double t = std::chrono::duration<double>(Clock::now() - t0).count();
      times.push_back(t);
      spent += t;
      double go = spent < min_seconds || times.size() < 3 ? 1.0 : 0.0;  // rank 0 decides for all
      std::vector<double> flag(1, dist::rank() == 0 ? go : 0.0);
      dist::sum(flag);
      more = flag[0] > 0.0;
    }
    std::sort(times.begin(), times.end());
    const double med = times[times.size() / 2];
    if (dist::rank() == 0)
      std::printf("%-36s %14lld %12.6f %12.2f %8zu\n", s.what, s.floats, med,
                  static_cast<double>(s.floats) * 4.0 / med / 1e9, times.size());
  }
  dist::finalize();
  return 0;
}
