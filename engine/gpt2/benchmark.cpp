#include "gpt2/benchmark.h"

#include <chrono>
#include <cstdio>
#include <functional>

#include <nlohmann/json.hpp>

#include "core/rng.h"
#include "gpt2/model.h"

namespace squawk::gpt2 {

namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

using Fn = std::function<void()>;

// Best time of each of fns over interleaved rounds (each fn once per round),
// at least two rounds and fns.size() * min_seconds in all, so that a change
// of the machine's load falls on every fn alike. on_best[i] (optional) runs
// right after a run of fns[i] that is its best so far (to read figures of
// that run).
std::vector<double> best_times(double min_seconds, const std::vector<Fn>& fns,
                               const std::vector<Fn>& on_best = {}) {
  std::vector<double> best(fns.size(), 1e300);
  const double start = now(), total = min_seconds * static_cast<double>(fns.size());
  for (int round = 0; round < 2 || now() - start < total; ++round)
    for (size_t i = 0; i < fns.size(); ++i) {
      const double t0 = now();
      fns[i]();
      const double t = now() - t0;
      if (t < best[i]) {
        best[i] = t;
        if (i < on_best.size() && on_best[i]) on_best[i]();
      }
    }
  return best;
}

// 2048^3 products at each precision (interleaved) [GFLOP/s].
std::vector<double> gemm_peaks(double min_seconds, const std::vector<nn::Precision>& precisions) {
  const int n = 2048;
  const size_t nn2 = static_cast<size_t>(n) * n;
  std::vector<float> a(nn2, 0.5f), b(nn2, 0.25f), c(nn2);
  std::vector<nn::bf16> a16(nn2, nn::to_bf16(0.5f)), b16(nn2, nn::to_bf16(0.25f));
  std::vector<Fn> fns;
  for (nn::Precision p : precisions)
    fns.push_back(p == nn::Precision::kBf16
                      ? Fn([&] { nn::gemm_bf16(false, false, n, n, n, 1.0f, a16.data(), n, b16.data(), n, 0.0f, c.data(), n); })
                      : Fn([&] { nn::gemm(false, false, n, n, n, 1.0f, a.data(), n, b.data(), n, 0.0f, c.data(), n); }));
  std::vector<double> peaks;
  for (double t : best_times(min_seconds, fns)) peaks.push_back(2.0 * n * n * static_cast<double>(n) / t * 1e-9);
  return peaks;
}

// The count of benchmark.h.
double forward_flops(const Config& c, int B, int T) {
  const double C = c.n_embd, L = c.n_layer;
  const double full = 24.0 * T * C * C + 2.0 * C * T * (T + 1.0);
  const double last = 6.0 * T * C * C + 18.0 * C * C + 4.0 * C * T;
  return B * ((L - 1.0) * full + last + 2.0 * C * c.vocab_size);
}

// Ratio of the bf16 run's rate to the fp32 run's for the same threads and B,
// in `what` (forward or fwd+bwd); 0 when either is missing.
double speedup(const BenchReport& r, const BenchRun& x, bool train) {
  const BenchRun* f = nullptr;
  const BenchRun* h = nullptr;
  for (const BenchRun& y : r.runs)
    if (y.threads == x.threads && y.B == x.B)
      (y.precision == nn::Precision::kBf16 ? h : f) = &y;
  if (!f || !h) return 0.0;
  return train ? f->train_s_per_prompt / h->train_s_per_prompt : f->forward_s / h->forward_s;
}

}  // namespace

Result<BenchReport> run_benchmark(const BenchOptions& opt) {
  SQUAWK_RETURN_IF_ERROR(opt.cfg.validate());
  if (opt.T < 1 || opt.T > opt.cfg.n_ctx)
    return Status::invalid("gpt2 bench: T = " + std::to_string(opt.T) + " outside 1.." +
                           std::to_string(opt.cfg.n_ctx));
  if (opt.precisions.empty()) return Status::invalid("gpt2 bench: no precision to measure");
  SQUAWK_ASSIGN_OR_RETURN(Model model, Model::create(opt.cfg));
  Rng rng(1);
  model.init_random(rng);
  SQUAWK_RETURN_IF_ERROR(model.set_trainable_blocks(opt.trainable_blocks));
  BenchReport rep;
  rep.backend = nn::gemm_backend();
  rep.bf16_library = nn::bf16_library();
  rep.threads = opt.threads;
  rep.precisions = opt.precisions;
  if (rep.backend == "openblas") {
    nn::set_gemm_backend("eigen");
    rep.eigen_peak_gflops_1t = gemm_peaks(opt.min_seconds, {nn::Precision::kFp32})[0];
    nn::set_gemm_backend("openblas");
  }
  const nn::Precision saved = nn::gemm_precision();
  const size_t P = opt.precisions.size();
  for (int th : opt.threads) {
    nn::set_num_threads(th);
    const std::vector<double> peaks = gemm_peaks(opt.min_seconds, opt.precisions);
    rep.peak_gflops.push_back(peaks);
    for (int B : opt.batches) {
      std::vector<std::vector<int>> seqs(B, std::vector<int>(opt.T));
      for (auto& s : seqs)
        for (int& t : s) t = static_cast<int>(rng.uniform_int(0, opt.cfg.vocab_size - 1));
      std::vector<float> hidden, logits;
      const PrefixCache empty;
      Status st;
      // gflops and matmul_gflops both come from the best repetition.
      std::vector<nn::GemmStats> gs(P);
      std::vector<Fn> fwd, on_best, train;
      std::vector<float> dh(static_cast<size_t>(B) * opt.cfg.n_embd, 1e-3f);
      for (size_t j = 0; j < P; ++j) {
        const nn::Precision p = opt.precisions[j];
        fwd.push_back([&, p] {
          nn::set_gemm_precision(p);
          nn::reset_gemm_stats();
          if (st.is_ok()) st = model.forward_last(empty, seqs, hidden);
          if (st.is_ok()) st = model.lm_logits(hidden, logits);
        });
        on_best.push_back([&, j] { gs[j] = nn::gemm_stats(); });
        train.push_back([&, p] {
          nn::set_gemm_precision(p);
          model.zero_grads();
          if (st.is_ok()) st = model.forward_train(empty, seqs, hidden);
          if (st.is_ok()) st = model.backward(dh);
        });
      }
      const std::vector<double> fwd_s = best_times(opt.min_seconds, fwd, on_best);
      const std::vector<double> train_s = best_times(opt.min_seconds, train);
      nn::set_gemm_precision(saved);
      SQUAWK_RETURN_IF_ERROR(st);
      for (size_t j = 0; j < P; ++j) {
        BenchRun r;
        r.threads = th;
        r.B = B;
        r.T = opt.T;
        r.precision = opt.precisions[j];
        r.forward_s = fwd_s[j];
        r.tokens_per_s = B * opt.T / fwd_s[j];
        r.gflops = forward_flops(opt.cfg, B, opt.T) / fwd_s[j] * 1e-9;
        r.fraction_of_peak = r.gflops / peaks[j];
        r.matmul_gflops = gs[j].seconds > 0 ? static_cast<double>(gs[j].flops) / gs[j].seconds * 1e-9 : 0.0;
        r.matmul_fraction = r.matmul_gflops / peaks[j];
        r.train_s_per_prompt = train_s[j] / B;
        rep.runs.push_back(r);
      }
    }
  }
  return rep;
}

std::string bench_json(const BenchReport& r, const BenchOptions& opt) {
  nlohmann::ordered_json j;
  // The headline: the first run of fp32 (or of the first precision), and of bf16.
  const BenchRun* head = nullptr;
  const BenchRun* head16 = nullptr;
  size_t col = 0, col16 = 0;
  for (size_t i = 0; i < r.precisions.size(); ++i)
    if (r.precisions[i] == nn::Precision::kBf16) col16 = i;
    else col = i;
  for (const BenchRun& x : r.runs) {
    if (x.precision == nn::Precision::kBf16 && !head16) head16 = &x;
    if (x.precision == nn::Precision::kFp32 && !head) head = &x;
  }
  if (!head) head = head16;
  const double peak = r.peak_gflops.empty() ? 0.0 : r.peak_gflops.front()[head == head16 ? col16 : col];
  j["model"] = {{"n_layer", opt.cfg.n_layer}, {"n_head", opt.cfg.n_head}, {"n_embd", opt.cfg.n_embd},
                {"vocab_size", opt.cfg.vocab_size}, {"params", opt.cfg.num_params()}};
  j["backend"] = r.backend;
  j["bf16_library"] = r.bf16_library;
  j["T"] = opt.T;
  j["B"] = head ? head->B : 0;
  j["threads"] = head ? head->threads : 0;
  j["precision"] = head ? nn::precision_name(head->precision) : "";
  j["gflops"] = head ? head->gflops : 0.0;
  j["peak_gflops"] = peak;
  j["fraction_of_peak"] = head ? head->fraction_of_peak : 0.0;
  j["matmul_fraction_of_peak"] = head ? head->matmul_fraction : 0.0;
  if (head16 && head16 != head)
    j["bf16"] = {{"gflops", head16->gflops},
                 {"peak_gflops", r.peak_gflops.front()[col16]},
                 {"fraction_of_peak", head16->fraction_of_peak},
                 {"forward_speedup", speedup(r, *head16, false)},
                 {"train_speedup", speedup(r, *head16, true)}};
  j["eigen_peak_gflops_1t"] = r.eigen_peak_gflops_1t;
  nlohmann::ordered_json runs = nlohmann::ordered_json::array();
  for (const BenchRun& x : r.runs)
    runs.push_back({{"threads", x.threads}, {"B", x.B}, {"T", x.T}, {"precision", nn::precision_name(x.precision)},
                    {"forward_s", x.forward_s}, {"tokens_per_s", x.tokens_per_s}, {"gflops", x.gflops},
                    {"fraction_of_peak", x.fraction_of_peak}, {"matmul_gflops", x.matmul_gflops},
                    {"matmul_fraction_of_peak", x.matmul_fraction},
                    {"train_ms_per_prompt", x.train_s_per_prompt * 1e3}});
  j["runs"] = runs;
  nlohmann::ordered_json peaks = nlohmann::ordered_json::object();
  for (size_t i = 0; i < r.threads.size(); ++i)
    for (size_t p = 0; p < r.precisions.size(); ++p)
      peaks[nn::precision_name(r.precisions[p])][std::to_string(r.threads[i])] = r.peak_gflops[i][p];
  j["peak_gflops_by_precision_and_threads"] = peaks;
  return j.dump();
}

std::string bench_table(const BenchReport& r, const BenchOptions& opt) {
  std::string out;
  char buf[320];
  std::snprintf(buf, sizeof buf, "GPT-2 %d layers x %d wide, %.1fM params, T = %d; fp32 gemm: %s, bf16 gemm: %s\n",
                opt.cfg.n_layer, opt.cfg.n_embd, static_cast<double>(opt.cfg.num_params()) * 1e-6, opt.T,
                r.backend.c_str(), r.bf16_library.c_str());
  out += buf;
  for (size_t i = 0; i < r.threads.size(); ++i) {
    std::snprintf(buf, sizeof buf, "2048^3 peak, %d thread(s):", r.threads[i]);
    out += buf;
    for (size_t p = 0; p < r.precisions.size(); ++p) {
      std::snprintf(buf, sizeof buf, "%s %s %.1f GFLOP/s", p ? "," : "", nn::precision_name(r.precisions[p]),
                    r.peak_gflops[i][p]);
      out += buf;
    }
    out += "\n";
  }
  if (r.eigen_peak_gflops_1t > 0) {
    std::snprintf(buf, sizeof buf, "(Eigen sgemm 2048^3, 1 thread: %.1f GFLOP/s)\n", r.eigen_peak_gflops_1t);
    out += buf;
  }
  out += "threads  B  precision   tokens/s   GFLOP/s  of peak  matmul GFLOP/s  of peak  fwd+bwd ms/prompt\n";
  for (const BenchRun& x : r.runs) {
    std::snprintf(buf, sizeof buf, "%7d %2d  %9s %10.0f %9.1f %7.0f%% %15.1f %7.0f%% %18.1f\n", x.threads, x.B,
                  nn::precision_name(x.precision), x.tokens_per_s, x.gflops, 100 * x.fraction_of_peak,
                  x.matmul_gflops, 100 * x.matmul_fraction, x.train_s_per_prompt * 1e3);
    out += buf;
  }
  for (const BenchRun& x : r.runs)
    if (x.precision == nn::Precision::kBf16 && speedup(r, x, false) > 0) {
      std::snprintf(buf, sizeof buf, "bf16 / fp32, %d thread(s), B = %d: forward %.2fx, fwd+bwd %.2fx\n",
                    x.threads, x.B, speedup(r, x, false), speedup(r, x, true));
      out += buf;
    }
  return out;
}

}  // namespace squawk::gpt2
