// libFuzzer target: the safetensors reader and the GPT-2 weight loader must
// turn any byte string into a file or a clear error, never a crash.
#include <cstddef>
#include <cstdint>
#include <string>

#include "gpt2/checkpoint.h"
#include "gpt2/safetensors.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  auto file = squawk::gpt2::SafetensorsFile::parse(std::string(reinterpret_cast<const char*>(data), size));
  if (!file) return 0;
  for (const auto& t : file->tensors()) {
    if (t.numel() > (1u << 20)) continue;
    std::vector<float> out(t.numel());
    (void)file->read_f32(t, out);
  }
  static auto model = squawk::gpt2::Model::create({1, 1, 2, 2, 3, 1e-5f});
  if (model) (void)squawk::gpt2::load_weights(*file, *model);
  return 0;
}
