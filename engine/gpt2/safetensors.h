// The safetensors file format: read (with every field checked) and write.
//
// Layout: an 8-byte little-endian header length N, N bytes of JSON header,
// then the data buffer. The header maps each tensor name to
//   {"dtype": "F32"|"F16"|"BF16"|..., "shape": [d0, d1, ...],
//    "data_offsets": [begin, end]}   (byte offsets into the data buffer)
// plus an optional "__metadata__" object of strings. Tensors are row-major,
// little-endian. squawk converts F32, F16 and BF16 to float32; other dtypes are
// listed but not converted.
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "core/status.h"

namespace squawk::gpt2 {

struct SafeTensor {
  std::string name;
  std::string dtype;
  std::vector<int64_t> shape;
  size_t begin = 0, end = 0;  // [bytes] into the data buffer
  size_t numel() const;
};

// Refuses headers longer than this [bytes]; the hub's largest are far smaller.
inline constexpr uint64_t kMaxSafetensorsHeader = 100u << 20;

class SafetensorsFile {
 public:
  // Parses a whole file held in memory. Errors (kCorruption) say which field
  // of which tensor is wrong and what was expected: short file, header length
  // beyond the file or the limit, invalid JSON, missing or ill-typed fields,
  // unknown dtype, byte ranges outside the data, not matching the shape or
  // overlapping another tensor's.
  static Result<SafetensorsFile> parse(std::string bytes);
  static Result<SafetensorsFile> open(const std::string& path);

  const std::vector<SafeTensor>& tensors() const { return tensors_; }
  const SafeTensor* find(const std::string& name) const;
  const std::map<std::string, std::string>& metadata() const { return metadata_; }
  // [bytes] of the data buffer (the file after its header).
  size_t data_bytes() const { return bytes_.size() - data_start_; }
  // Converts a tensor to float32; out must hold exactly numel() floats.
  Status read_f32(const SafeTensor& t, std::span<float> out) const;

 private:
  std::string bytes_;
  size_t data_start_ = 0;
  std::vector<SafeTensor> tensors_;
  std::map<std::string, std::string> metadata_;
};

struct TensorRef {
  std::string name;
  std::vector<int64_t> shape;
  std::span<const float> data;  // numel floats, row-major
};

// The file bytes for F32 tensors in the given order; the header is padded with
// spaces to a multiple of 8 bytes. Error when a shape does not match its data.
Result<std::string> serialize_safetensors(const std::vector<TensorRef>& tensors,
                                          const std::map<std::string, std::string>& metadata = {});
Status write_safetensors(const std::string& path, const std::vector<TensorRef>& tensors,
                         const std::map<std::string, std::string>& metadata = {});

// IEEE half and bfloat16 bit patterns to float (exact).
// "[2, 3]": a shape as error messages print it.
std::string shape_str(const std::vector<int64_t>& shape);

float f16_to_f32(uint16_t h);
float bf16_to_f32(uint16_t b);

}  // namespace squawk::gpt2
