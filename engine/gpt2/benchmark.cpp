#include "gpt2/benchmark.h"

#include <chrono>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "core/rng.h"
#include "gpt2/model.h"
#include "nn/gemm.h"

namespace squawk::gpt2 {

namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Best time of `fn` over at least two runs and min_seconds; on_best() runs
// right after each run that is the best so far (to read figures of that run).
template <class F, class G>
double best_time(double min_seconds, F&& fn, G&& on_best) {
  double best = 1e300, start = now();
  for (int i = 0; i < 2 || now() - start < min_seconds; ++i) {
    const double t0 = now();
    fn();
    const double t = now() - t0;
    if (t < best) {
      best = t;
      on_best();
    }
  }
  return best;
}

template <class F>
double best_time(double min_seconds, F&& fn) {
  return best_time(min_seconds, fn, [] {});
}

double sgemm_peak(double min_seconds) {
  const int n = 2048;
  std::vector<float> a(static_cast<size_t>(n) * n, 0.5f), b(a.size(), 0.25f), c(a.size());
  const double t = best_time(min_seconds, [&] {
    nn::gemm(false, false, n, n, n, 1.0f, a.data(), n, b.data(), n, 0.0f, c.data(), n);
  });
  return 2.0 * n * n * static_cast<double>(n) / t * 1e-9;
}

// The count of benchmark.h.
double forward_flops(const Config& c, int B, int T) {
  const double C = c.n_embd, L = c.n_layer;
  const double full = 24.0 * T * C * C + 2.0 * C * T * (T + 1.0);
  const double last = 6.0 * T * C * C + 18.0 * C * C + 4.0 * C * T;
  return B * ((L - 1.0) * full + last + 2.0 * C * c.vocab_size);
}

}  // namespace

Result<BenchReport> run_benchmark(const BenchOptions& opt) {
  SQUAWK_RETURN_IF_ERROR(opt.cfg.validate());
  if (opt.T < 1 || opt.T > opt.cfg.n_ctx)
    return Status::invalid("gpt2 bench: T = " + std::to_string(opt.T) + " outside 1.." +
                           std::to_string(opt.cfg.n_ctx));
  SQUAWK_ASSIGN_OR_RETURN(Model model, Model::create(opt.cfg));
  Rng rng(1);
  model.init_random(rng);
  SQUAWK_RETURN_IF_ERROR(model.set_trainable_blocks(opt.trainable_blocks));
  BenchReport rep;
  rep.backend = nn::gemm_backend();
  rep.threads = opt.threads;
  if (rep.backend == "openblas") {
    nn::set_gemm_backend("eigen");
    rep.eigen_peak_gflops_1t = sgemm_peak(opt.min_seconds);
    nn::set_gemm_backend("openblas");
  }
  for (int th : opt.threads) {
    nn::set_num_threads(th);
    const double peak = sgemm_peak(opt.min_seconds);
    rep.peak_gflops.push_back(peak);
    for (int B : opt.batches) {
      std::vector<std::vector<int>> seqs(B, std::vector<int>(opt.T));
      for (auto& s : seqs)
        for (int& t : s) t = static_cast<int>(rng.uniform_int(0, opt.cfg.vocab_size - 1));
      std::vector<float> hidden, logits;
      const PrefixCache empty;
      Status st;
      // gflops and matmul_gflops both come from the best repetition.
      nn::GemmStats gs;
      const double fwd = best_time(
          opt.min_seconds,
          [&] {
            nn::reset_gemm_stats();
            st = model.forward_last(empty, seqs, hidden);
            if (st.is_ok()) st = model.lm_logits(hidden, logits);
          },
          [&] { gs = nn::gemm_stats(); });
      SQUAWK_RETURN_IF_ERROR(st);
      BenchRun r;
      r.threads = th;
      r.B = B;
      r.T = opt.T;
      r.forward_s = fwd;
      r.tokens_per_s = B * opt.T / fwd;
      r.gflops = forward_flops(opt.cfg, B, opt.T) / fwd * 1e-9;
      r.fraction_of_peak = r.gflops / peak;
      r.matmul_gflops = gs.seconds > 0 ? static_cast<double>(gs.flops) / gs.seconds * 1e-9 : 0.0;
      r.matmul_fraction = r.matmul_gflops / peak;
      std::vector<float> dh(static_cast<size_t>(B) * opt.cfg.n_embd, 1e-3f);
      const double train = best_time(opt.min_seconds, [&] {
        model.zero_grads();
        st = model.forward_train(empty, seqs, hidden);
        if (st.is_ok()) st = model.backward(dh);
      });
      SQUAWK_RETURN_IF_ERROR(st);
      r.train_s_per_prompt = train / B;
      rep.runs.push_back(r);
    }
  }
  return rep;
}

std::string bench_json(const BenchReport& r, const BenchOptions& opt) {
  nlohmann::ordered_json j;
  const BenchRun* head = r.runs.empty() ? nullptr : &r.runs.front();
  j["model"] = {{"n_layer", opt.cfg.n_layer}, {"n_head", opt.cfg.n_head}, {"n_embd", opt.cfg.n_embd},
                {"vocab_size", opt.cfg.vocab_size}, {"params", opt.cfg.num_params()}};
  j["backend"] = r.backend;
  j["T"] = opt.T;
  j["B"] = head ? head->B : 0;
  j["threads"] = head ? head->threads : 0;
  j["gflops"] = head ? head->gflops : 0.0;
  j["peak_gflops"] = r.peak_gflops.empty() ? 0.0 : r.peak_gflops.front();
  j["fraction_of_peak"] = head ? head->fraction_of_peak : 0.0;
  j["matmul_fraction_of_peak"] = head ? head->matmul_fraction : 0.0;
  j["eigen_peak_gflops_1t"] = r.eigen_peak_gflops_1t;
  nlohmann::ordered_json runs = nlohmann::ordered_json::array();
  for (const BenchRun& x : r.runs)
    runs.push_back({{"threads", x.threads}, {"B", x.B}, {"T", x.T}, {"forward_s", x.forward_s},
                    {"tokens_per_s", x.tokens_per_s}, {"gflops", x.gflops},
                    {"fraction_of_peak", x.fraction_of_peak}, {"matmul_gflops", x.matmul_gflops},
                    {"matmul_fraction_of_peak", x.matmul_fraction},
                    {"train_ms_per_prompt", x.train_s_per_prompt * 1e3}});
  j["runs"] = runs;
  nlohmann::ordered_json peaks = nlohmann::ordered_json::object();
  for (size_t i = 0; i < r.threads.size(); ++i)
    peaks[std::to_string(r.threads[i])] = r.peak_gflops[i];
  j["sgemm_peak_gflops_by_threads"] = peaks;
  return j.dump();
}

std::string bench_table(const BenchReport& r, const BenchOptions& opt) {
  std::string out;
  char buf[256];
  std::snprintf(buf, sizeof buf, "GPT-2 %d layers x %d wide, %.1fM params, T = %d, gemm: %s\n",
                opt.cfg.n_layer, opt.cfg.n_embd, static_cast<double>(opt.cfg.num_params()) * 1e-6,
                opt.T, r.backend.c_str());
  out += buf;
  for (size_t i = 0; i < r.threads.size(); ++i) {
    std::snprintf(buf, sizeof buf, "sgemm 2048^3 peak, %d thread(s): %.1f GFLOP/s\n", r.threads[i],
                  r.peak_gflops[i]);
    out += buf;
  }
  if (r.eigen_peak_gflops_1t > 0) {
    std::snprintf(buf, sizeof buf, "(Eigen sgemm 2048^3, 1 thread: %.1f GFLOP/s)\n", r.eigen_peak_gflops_1t);
    out += buf;
  }
  out += "threads  B   tokens/s   GFLOP/s  of peak  matmul GFLOP/s  of peak  fwd+bwd ms/prompt\n";
  for (const BenchRun& x : r.runs) {
    std::snprintf(buf, sizeof buf, "%7d %2d %10.0f %9.1f %7.0f%% %15.1f %7.0f%% %18.1f\n", x.threads,
                  x.B, x.tokens_per_s, x.gflops, 100 * x.fraction_of_peak, x.matmul_gflops,
                  100 * x.matmul_fraction, x.train_s_per_prompt * 1e3);
    out += buf;
  }
  return out;
}

}  // namespace squawk::gpt2
