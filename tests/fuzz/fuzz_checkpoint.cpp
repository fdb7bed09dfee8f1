// libFuzzer target: the policy checkpoint readers (MLP and GPT-2 prompt
// policy) on arbitrary file contents: a checkpoint or an error naming the
// file, never a crash or an allocation larger than the file. Each input is
// written to one temp file of this process, then loaded as both kinds.
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <string>

#include "core/files.h"
#include "rl/checkpoint.h"
#include "rl/mlp_policy.h"
#include "rl/prompt_checkpoint.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path =
      (std::filesystem::temp_directory_path() / ("squawk_fuzz_ckpt_" + std::to_string(getpid()))).string();
  if (!squawk::files::write_atomic(path, std::string(reinterpret_cast<const char*>(data), size))) return 0;
  if (auto c = squawk::rl::load_checkpoint(path)) (void)squawk::rl::policy_from_checkpoint(*c);
  (void)squawk::rl::load_prompt_checkpoint(path);
  return 0;
}
