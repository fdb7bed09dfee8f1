// squawk gpt2 info | generate | logits | bench | train-bpe | init (pretrain:
// cli_gpt2_pretrain.cpp; imitate: cli_gpt2_imitate.cpp).
#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "app/cli.h"
#include "app/gpt2_policy_factory.h"
#include "app/subcommands.h"
#include "core/files.h"
#include "core/rng.h"
#include "core/text.h"
#include "gpt2/benchmark.h"
#include "gpt2/bpe.h"
#include "gpt2/bundle.h"
#include "gpt2/checkpoint.h"
#include "gpt2/generate.h"
#include "nn/gemm.h"

namespace squawk::app {

namespace {

int info(const Args& a) {
  if (a.positional().size() != 2) return usage_error("gpt2", "info expects DIR");
  auto seed = a.get_int("--seed", 0);
  if (!seed) return usage_error("gpt2", seed.status().message());
  auto l = gpt2::load_bundle(a.positional()[1], static_cast<uint64_t>(*seed));
  if (!l) return failure(l.status());
  const gpt2::Config& c = l->model.config();
  std::printf("model       %s\n", l->source.c_str());
  std::printf("layers      %d\nheads       %d\nwidth       %d\ncontext     %d\nvocabulary  %d\n",
              c.n_layer, c.n_head, c.n_embd, c.n_ctx, c.vocab_size);
  std::printf("parameters  %lld (%.1f MB as float32)\n", c.num_params(),
              static_cast<double>(c.num_params()) * 4e-6);
  if (l->tokenizer)
    std::printf("tokenizer   %d tokens, %zu merges%s\n", l->tokenizer->vocab_size(),
                l->tokenizer->num_merges(), l->tokenizer->eot() ? ", <|endoftext|>" : "");
  else
    std::printf("tokenizer   none\n");
  std::printf("gemm        %s\nbf16 gemm   %s\nprecision   %s\n", nn::gemm_backend(), nn::bf16_library(),
              nn::precision_name(nn::gemm_precision()));
  return kExitOk;
}

int generate(const Args& a) {
  if (a.positional().size() != 3) return usage_error("gpt2", "generate expects DIR \"prompt\"");
  auto max_tokens = a.get_int("--max-tokens", 32);
  auto top_k = a.get_int("--top-k", 40);
  auto seed = a.get_int("--seed", 0);
  for (const auto* r : {&max_tokens, &top_k, &seed})
    if (!*r) return usage_error("gpt2", r->status().message());
  if (*max_tokens < 0 || *max_tokens > 1000000 || *top_k < 1 || *top_k > 1000000)
    return usage_error("gpt2", "--max-tokens expects 0..1000000 and --top-k 1..1000000");
  auto b = gpt2::load_bundle(a.positional()[1], static_cast<uint64_t>(*seed));
  if (!b) return failure(b.status());
  auto tok = b->text_tokenizer();
  if (!tok) return failure(tok.status());
  const gpt2::GenerateOptions opt{static_cast<int>(*max_tokens), static_cast<int>(*top_k),
                                  static_cast<uint64_t>(*seed)};
  std::fputs(a.positional()[2].c_str(), stdout);
  auto out = gpt2::generate(b->model, **tok, a.positional()[2], opt, [](const std::string& piece) {
    std::fputs(piece.c_str(), stdout);
    std::fflush(stdout);
  });
  std::fputs("\n", stdout);
  if (!out) return failure(out.status());
  return kExitOk;
}

int logits(const Args& a) {
  if (a.positional().size() != 3) return usage_error("gpt2", "logits expects DIR \"text\"");
  auto seed = a.get_int("--seed", 0);
  if (!seed) return usage_error("gpt2", seed.status().message());
  auto l = gpt2::load_bundle(a.positional()[1], static_cast<uint64_t>(*seed));
  if (!l) return failure(l.status());
  auto tok = l->text_tokenizer();
  if (!tok) return failure(tok.status());
  auto ids = (*tok)->encode(a.positional()[2]);
  if (!ids) return failure(ids.status());
  if (ids->empty()) return failure(Status::invalid("the text encodes to no tokens"));
  std::vector<float> hidden, out;
  Status st = l->model.forward_last({}, {*ids}, hidden);
  if (st.is_ok()) st = l->model.lm_logits(hidden, out);
  if (!st.is_ok()) return failure(st);
  if (a.has("--json")) {
    nlohmann::ordered_json j = {{"tokens", *ids}, {"logits", out}};
    std::printf("%s\n", j.dump().c_str());
    return kExitOk;
  }
  std::printf("tokens (%zu):", ids->size());
  for (int id : *ids) std::printf(" %d", id);
  std::printf("\ntop logits at the last position:\n");
  std::vector<int> idx(out.size());
  for (size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<int>(i);
  const size_t k = std::min<size_t>(10, idx.size());
  std::partial_sort(idx.begin(), idx.begin() + static_cast<long>(k), idx.end(),
                    [&](int x, int y) { return out[x] > out[y]; });
  for (size_t i = 0; i < k; ++i) {
    auto piece = (*tok)->decode(std::vector<int>{idx[i]});
    std::printf("  %6d %10.4f  %s\n", idx[i], out[idx[i]], piece ? text::quoted(*piece).c_str() : "?");
  }
  return kExitOk;
}

Result<std::vector<int>> int_list(const std::string& s, const char* flag) {
  std::vector<int> out;
  for (const auto& part : text::split(s, ',')) {
    auto v = text::to_int(part);
    if (!v || *v < 1 || *v > 4096)
      return Status::invalid(std::string("flag ") + flag + " expects comma-separated integers in 1..4096, got " + text::quoted(s));
    out.push_back(static_cast<int>(*v));
  }
  return out;
}

int bench(const Args& a) {
  gpt2::BenchOptions opt;
  if (a.has("--tiny")) opt.cfg = gpt2::Config::tiny();
  auto T = a.get_int("--seq", opt.T);
  if (!T) return usage_error("gpt2", T.status().message());
  opt.T = static_cast<int>(*T);
  if (auto v = a.get("--batch")) {
    auto b = int_list(*v, "--batch");
    if (!b) return usage_error("gpt2", b.status().message());
    opt.batches = *b;
  }
  if (auto v = a.get("--threads")) {
    auto t = int_list(*v, "--threads");
    if (!t) return usage_error("gpt2", t.status().message());
    opt.threads = *t;
  }
  if (auto v = a.get("--precision")) {  // default: both, interleaved
    auto p = nn::parse_precision(*v);
    if (!p) return usage_error("gpt2", "--precision: " + p.status().message());
    opt.precisions = {*p};
  }
  auto secs = a.get_double("--seconds", opt.min_seconds);
  if (!secs) return usage_error("gpt2", secs.status().message());
  opt.min_seconds = *secs;
  auto rep = gpt2::run_benchmark(opt);
  if (!rep) return failure(rep.status());
  if (a.has("--json")) std::printf("%s\n", gpt2::bench_json(*rep, opt).c_str());
  else std::fputs(gpt2::bench_table(*rep, opt).c_str(), stdout);
  return kExitOk;
}

int train_bpe(const Args& a) {
  if (a.positional().size() < 3) return usage_error("gpt2", "train-bpe expects OUT_DIR FILE...");
  auto merges = a.get_int("--merges", 256);
  if (!merges || *merges < 0 || *merges > 100000)
    return usage_error("gpt2", "--merges expects an integer in 0..100000");
  std::string corpus;
  for (size_t i = 2; i < a.positional().size(); ++i) {
    auto t = files::read(a.positional()[i]);
    if (!t) return failure(t.status());
    corpus.append(*t).append("\n");
  }
  const gpt2::Tokenizer tok = gpt2::Tokenizer::train(corpus, static_cast<int>(*merges));
  Status st = tok.save(a.positional()[1]);
  if (!st.is_ok()) return failure(st);
  std::printf("wrote %s/vocab.json (%d tokens) and merges.txt (%zu merges)\n",
              a.positional()[1].c_str(), tok.vocab_size(), tok.num_merges());
  return kExitOk;
}

// A random GPT-2 in Hugging Face format, over the vocabulary of --vocab DIR
// (vocab.json + merges.txt, copied along) or the byte-level 257 tokens.
int init(const Args& a) {
  if (a.positional().size() != 2) return usage_error("gpt2", "init expects OUT_DIR");
  gpt2::Config cfg = gpt2::Config::tiny();
  const std::pair<const char*, int*> dims[] = {{"--layers", &cfg.n_layer}, {"--heads", &cfg.n_head},
                                               {"--width", &cfg.n_embd}, {"--context", &cfg.n_ctx}};
  for (const auto& [flag, field] : dims) {
    auto v = a.get_int(flag, *field);
    if (!v || *v < 1 || *v > 65536) return usage_error("gpt2", std::string(flag) + " expects an integer in 1..65536");
    *field = static_cast<int>(*v);
  }
  auto seed = a.get_int("--seed", 0);
  if (!seed) return usage_error("gpt2", seed.status().message());
  gpt2::Tokenizer tok = gpt2::Tokenizer::bytes_only();
  if (auto dir = a.get("--vocab")) {
    auto t = gpt2::Tokenizer::load(*dir);
    if (!t) return failure(t.status());
    tok = std::move(t).value();
  }
  cfg.vocab_size = tok.vocab_size();
  auto model = gpt2::Model::create(cfg);
  if (!model) return failure(model.status());
  Rng rng(static_cast<uint64_t>(*seed));
  model->init_random(rng);
  const std::string& out = a.positional()[1];
  Status st = gpt2::save_model(out, *model);
  if (st.is_ok()) st = tok.save(out);
  if (!st.is_ok()) return failure(st);
  std::printf("wrote %s: %d layers, %d heads, %d wide, %d positions, %d tokens (%lld parameters)\n",
              out.c_str(), cfg.n_layer, cfg.n_head, cfg.n_embd, cfg.n_ctx, cfg.vocab_size,
              cfg.num_params());
  return kExitOk;
}

}  // namespace

int cmd_gpt2(const ArgV& argv) {
  // `squawk gpt2 ACTION --help`: the subcommand's help, like `squawk gpt2 --help`.
  for (const std::string& x : argv)
    if (x == "--help" || x == "-h") {
      for (const Subcommand& s : subcommands())
        if (std::string(s.name) == "gpt2") std::fputs(s.help, stdout);
      return kExitOk;
    }
  if (!argv.empty() && argv[0] == "pretrain") return cmd_gpt2_pretrain(ArgV(argv.begin() + 1, argv.end()));
  if (!argv.empty() && argv[0] == "imitate") return cmd_gpt2_imitate(ArgV(argv.begin() + 1, argv.end()));
  auto a = Args::parse(argv, {{"--max-tokens", "--top-k", "--seed", "--seq", "--batch", "--threads",
                               "--seconds", "--merges", "--layers", "--heads", "--width", "--context",
                               "--vocab", "--precision"},
                              {"--json", "--tiny"}});
  if (!a) return usage_error("gpt2", a.status().message());
  if (a->positional().empty()) return usage_error("gpt2", "missing action (info, generate, logits, bench, train-bpe, init, pretrain, imitate)");
  const std::string& what = a->positional()[0];
  if (what == "info" || what == "generate" || what == "logits")
    if (Status st = apply_precision_flag(*a); !st.is_ok()) return usage_error("gpt2", st.message());
  if (what == "info") return info(*a);
  if (what == "generate") return generate(*a);
  if (what == "logits") return logits(*a);
  if (what == "bench") return bench(*a);
  if (what == "train-bpe") return train_bpe(*a);
  if (what == "init") return init(*a);
  return usage_error("gpt2", "unknown action " + text::quoted(what));
}

}  // namespace squawk::app
