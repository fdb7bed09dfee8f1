// GPT-2 parameters: tensor names, shapes and memory layout, stated once.
//
// Shape legend: V vocabulary, maxT positions, C channels, L blocks.
// Tensor table (Hugging Face GPT2Model names; files may prefix "transformer."):
//   wte.weight                 [V, C]     token embedding, also the LM head (tied)
//   wpe.weight                 [maxT, C]  position embedding
//   h.{l}.ln_1.weight, .bias   [C]        pre-attention LayerNorm of block l
//   h.{l}.attn.c_attn.weight   [C, 3C]    input-major (Conv1D); output columns q | k | v
//   h.{l}.attn.c_attn.bias     [3C]
//   h.{l}.attn.c_proj.weight   [C, C]
//   h.{l}.attn.c_proj.bias     [C]
//   h.{l}.ln_2.weight, .bias   [C]        pre-MLP LayerNorm
//   h.{l}.mlp.c_fc.weight      [C, 4C]
//   h.{l}.mlp.c_fc.bias        [4C]
//   h.{l}.mlp.c_proj.weight    [4C, C]
//   h.{l}.mlp.c_proj.bias      [C]
//   ln_f.weight, ln_f.bias     [C]        final LayerNorm
//   extra tensors              any        declared by the caller (e.g. an action head)
// Memory: one float32 buffer with the tensors in exactly this order (blocks in
// increasing l), each row-major. Hence blocks l..L-1, ln_f and the extras form
// one contiguous tail of the buffer: the trainable part when fine-tuning the
// last L-l blocks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/status.h"
#include "gpt2/config.h"

namespace squawk::gpt2 {

struct TensorSpec {
  std::string name;
  std::vector<int64_t> shape;
  size_t offset = 0;  // [floats] into the buffer
  size_t size = 0;    // [floats] product of shape
};

// Offsets [floats] of one block's tensors from the block's first float.
struct BlockOffsets {
  size_t ln1_w, ln1_b, attn_w, attn_b, proj_w, proj_b, ln2_w, ln2_b, fc_w, fc_b, fcproj_w,
      fcproj_b, size;
};

class ParamLayout {
 public:
  // Errors: an invalid config, or an extra tensor whose name is taken, empty,
  // or whose shape has a dimension < 1.
  static Result<ParamLayout> build(const Config& cfg, const std::vector<TensorSpec>& extras = {});

  const Config& config() const { return cfg_; }
  const std::vector<TensorSpec>& tensors() const { return tensors_; }
  const TensorSpec* find(const std::string& name) const;
  size_t total() const { return total_; }
  const BlockOffsets& block() const { return block_; }
  size_t wte() const { return 0; }
  size_t wpe() const { return static_cast<size_t>(cfg_.vocab_size) * cfg_.n_embd; }
  size_t block_start(int l) const { return blocks_start_ + static_cast<size_t>(l) * block_.size; }
  size_t ln_f() const { return block_start(cfg_.n_layer); }
  // Start of the extra tensors (== total() when there are none).
  size_t extras_start() const { return ln_f() + 2 * static_cast<size_t>(cfg_.n_embd); }

 private:
  Config cfg_;
  std::vector<TensorSpec> tensors_;
  std::unordered_map<std::string, size_t> index_;
  BlockOffsets block_{};
  size_t blocks_start_ = 0;
  size_t total_ = 0;
};

}  // namespace squawk::gpt2
