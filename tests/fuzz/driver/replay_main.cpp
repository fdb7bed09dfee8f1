// A libFuzzer-compatible driver for builds without libFuzzer (the CI smoke
// run): feeds LLVMFuzzerTestOneInput every seed file under the given folders,
// then N mutants of them (byte flips, inserts, deletes, splices, repeats),
// drawn from a fixed seed so a failure replays.
//   usage: fuzz_<name>_smoke N SEED_DIR...
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

int run(const std::string& s) {
  return LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(s.data()), s.size());
}

std::string mutate(std::string s, const std::vector<std::string>& seeds, std::mt19937_64& rng) {
  auto pick = [&](size_t n) { return n == 0 ? size_t{0} : static_cast<size_t>(rng() % n); };
  const int edits = 1 + static_cast<int>(rng() % 8);
  for (int e = 0; e < edits; ++e) {
    switch (rng() % 5) {
      case 0:
        if (!s.empty()) s[pick(s.size())] = static_cast<char>(rng());
        break;
      case 1: s.insert(pick(s.size() + 1), 1, "{}[]\":,\n0a-"[pick(12)]); break;
      case 2:
        if (!s.empty()) s.erase(pick(s.size()), 1 + pick(8));
        break;
      case 3: {
        const std::string& o = seeds[pick(seeds.size())];
        if (!o.empty()) s.insert(pick(s.size() + 1), o.substr(pick(o.size())));
        break;
      }
      default:
        if (!s.empty()) {
          const size_t at = pick(s.size());
          const std::string piece = s.substr(at, 1 + pick(16));
          for (size_t k = 0, n = 1 + pick(64); k < n; ++k) s.insert(at, piece);
        }
    }
  }
  return s.substr(0, 1 << 16);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s N SEED_DIR...\n", argv[0]);
    return 2;
  }
  const long n = std::atol(argv[1]);
  std::vector<std::string> seeds;
  for (int i = 2; i < argc; ++i)
    for (const auto& f : std::filesystem::directory_iterator(argv[i])) {
      std::ifstream in(f.path(), std::ios::binary);
      seeds.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
  if (seeds.empty()) seeds.emplace_back();
  for (const auto& s : seeds) run(s);
  std::mt19937_64 rng(12345);
  for (long k = 0; k < n; ++k) run(mutate(seeds[rng() % seeds.size()], seeds, rng));
  std::printf("%zu seeds and %ld mutants ran, no crash\n", seeds.size(), n);
  return 0;
}
