// libFuzzer target: tokenizer files and text. The input is split at the first
// 0xFF byte into a vocab.json / merges.txt pair (split again at the next 0xFF)
// and, independently, used as text: bytes_only must round-trip it exactly and a
// loaded tokenizer must encode it or fail cleanly.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "gpt2/bpe.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string in(reinterpret_cast<const char*>(data), size);
  static const squawk::gpt2::Tokenizer bytes = squawk::gpt2::Tokenizer::bytes_only();
  auto ids = bytes.encode(in);
  if (!ids) std::abort();
  auto back = bytes.decode(*ids);
  if (!back || *back != in) std::abort();

  const size_t a = in.find('\xff');
  const size_t b = a == std::string::npos ? a : in.find('\xff', a + 1);
  const std::string vocab = in.substr(0, a);
  const std::string merges = a == std::string::npos ? "" : in.substr(a + 1, b == std::string::npos ? b : b - a - 1);
  auto tok = squawk::gpt2::Tokenizer::from_hf(vocab, merges);
  if (tok) {
    auto enc = tok->encode(in);
    if (enc) {
      auto dec = tok->decode(*enc);
      if (!dec || *dec != in) std::abort();
    }
  }
  return 0;
}
