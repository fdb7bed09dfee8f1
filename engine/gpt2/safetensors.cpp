#include "gpt2/safetensors.h"

#include <algorithm>
#include <cstring>

#include <nlohmann/json.hpp>

#include "core/files.h"
#include "core/text.h"

namespace squawk::gpt2 {

namespace {

using nlohmann::json;

// Bytes per element of the dtypes the format defines; 0 when unknown.
size_t dtype_size(const std::string& d) {
  static const std::map<std::string, size_t> sizes = {
      {"F64", 8}, {"F32", 4}, {"F16", 2}, {"BF16", 2}, {"I64", 8}, {"I32", 4},   {"I16", 2},
      {"I8", 1},  {"U64", 8}, {"U32", 4}, {"U16", 2},  {"U8", 1},  {"BOOL", 1}, {"F8_E4M3", 1},
      {"F8_E5M2", 1}};
  auto it = sizes.find(d);
  return it == sizes.end() ? 0 : it->second;
}


// Byte counts saturate here instead of overflowing.
constexpr size_t kSaturated = size_t{1} << 62;

Status bad(const std::string& msg) { return Status::corruption("safetensors: " + msg); }

uint64_t read_u64_le(const char* p) {
  uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(p[i]);
  return v;
}

}  // namespace

size_t SafeTensor::numel() const {
  size_t n = 1;
  for (int64_t d : shape) n *= static_cast<size_t>(d);
  return n;
}

Result<SafetensorsFile> SafetensorsFile::parse(std::string bytes) {
  if (bytes.size() < 8)
    return bad("file of " + std::to_string(bytes.size()) +
               " bytes is shorter than the 8-byte header length");
  const uint64_t n = read_u64_le(bytes.data());
  if (n > kMaxSafetensorsHeader)
    return bad("header length " + std::to_string(n) + " exceeds the limit of " +
               std::to_string(kMaxSafetensorsHeader) + " bytes");
  if (n > bytes.size() - 8)
    return bad("header length " + std::to_string(n) + " exceeds the " +
               std::to_string(bytes.size() - 8) + " bytes after the length field");
  const json h = json::parse(bytes.begin() + 8, bytes.begin() + 8 + static_cast<long>(n), nullptr,
                             false);
  if (h.is_discarded()) return bad("header is not valid JSON");
  if (!h.is_object()) return bad("header is JSON but not an object of tensors");
  SafetensorsFile f;
  f.data_start_ = 8 + static_cast<size_t>(n);
  const size_t data_size = bytes.size() - f.data_start_;
  for (const auto& [name, v] : h.items()) {
    const std::string who = "tensor " + text::quoted(name);
    if (name == "__metadata__") {
      if (!v.is_object()) return bad("__metadata__ is not an object of strings");
      for (const auto& [k, mv] : v.items()) {
        if (!mv.is_string()) return bad("__metadata__ value of " + text::quoted(k) + " is not a string");
        f.metadata_[k] = mv.get<std::string>();
      }
      continue;
    }
    if (!v.is_object()) return bad(who + ": entry is not an object");
    auto dt = v.find("dtype"), sh = v.find("shape"), off = v.find("data_offsets");
    if (dt == v.end() || !dt->is_string()) return bad(who + ": missing string field \"dtype\"");
    if (sh == v.end() || !sh->is_array()) return bad(who + ": missing array field \"shape\"");
    if (off == v.end() || !off->is_array() || off->size() != 2)
      return bad(who + ": missing field \"data_offsets\" of two integers");
    SafeTensor t;
    t.name = name;
    t.dtype = dt->get<std::string>();
    const size_t es = dtype_size(t.dtype);
    if (es == 0) return bad(who + ": unknown dtype " + text::quoted(t.dtype));
    if (sh->size() > 8) return bad(who + ": shape has " + std::to_string(sh->size()) + " dimensions, at most 8 expected");
    size_t bytes_needed = es;
    for (const auto& d : *sh) {
      if (!d.is_number_unsigned()) return bad(who + ": shape entries must be non-negative integers");
      const uint64_t dv = d.get<uint64_t>();
      if (dv > (uint64_t{1} << 40)) return bad(who + ": shape dimension " + std::to_string(dv) + " is implausibly large");
      bytes_needed = (dv != 0 && bytes_needed > kSaturated / dv) ? kSaturated : bytes_needed * dv;
      t.shape.push_back(static_cast<int64_t>(dv));
    }
    if (!(*off)[0].is_number_unsigned() || !(*off)[1].is_number_unsigned())
      return bad(who + ": data_offsets must be non-negative integers");
    const uint64_t b = (*off)[0].get<uint64_t>(), e = (*off)[1].get<uint64_t>();
    if (b > e || e > data_size)
      return bad(who + ": data_offsets [" + std::to_string(b) + ", " + std::to_string(e) +
                 "] fall outside the data buffer of " + std::to_string(data_size) + " bytes");
    if (e - b != bytes_needed)
      return bad(who + ": " + t.dtype + " " + shape_str(t.shape) + " needs " +
                 (bytes_needed >= kSaturated ? std::string("more bytes than the file holds")
                                           : std::to_string(bytes_needed) + " bytes") +
                 " but data_offsets span " + std::to_string(e - b));
    t.begin = static_cast<size_t>(b);
    t.end = static_cast<size_t>(e);
    f.tensors_.push_back(std::move(t));
  }
  // No two tensors may share bytes (empty tensors take none).
  std::vector<const SafeTensor*> by_start;
  for (const SafeTensor& t : f.tensors_)
    if (t.end > t.begin) by_start.push_back(&t);
  std::sort(by_start.begin(), by_start.end(),
            [](const SafeTensor* a, const SafeTensor* b) { return a->begin < b->begin; });
  for (size_t i = 1; i < by_start.size(); ++i)
    if (by_start[i]->begin < by_start[i - 1]->end)
      return bad("tensors " + text::quoted(by_start[i - 1]->name) + " and " + text::quoted(by_start[i]->name) +
                 " overlap: data_offsets must not share bytes");
  f.bytes_ = std::move(bytes);
  return f;
}

Result<SafetensorsFile> SafetensorsFile::open(const std::string& path) {
  SQUAWK_ASSIGN_OR_RETURN(std::string bytes, files::read(path));
  auto f = parse(std::move(bytes));
  if (!f) return f.status().with_context(path);
  return f;
}

const SafeTensor* SafetensorsFile::find(const std::string& name) const {
  for (const SafeTensor& t : tensors_)
    if (t.name == name) return &t;
  return nullptr;
}

float f16_to_f32(uint16_t h) {
  const uint32_t sign = static_cast<uint32_t>(h & 0x8000u) << 16;
  const uint32_t exp = (h >> 10) & 0x1fu, mant = h & 0x3ffu;
  uint32_t bits;
  if (exp == 0) {
    if (mant == 0) {
      bits = sign;
    } else {  // subnormal: mant * 2^-24
      float v = static_cast<float>(mant) * 5.9604644775390625e-8f;
      std::memcpy(&bits, &v, 4);
      bits |= sign;
    }
  } else if (exp == 31) {
    bits = sign | 0x7f800000u | (mant << 13);
  } else {
    bits = sign | ((exp + 112u) << 23) | (mant << 13);
  }
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

float bf16_to_f32(uint16_t b) {
  const uint32_t bits = static_cast<uint32_t>(b) << 16;
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

Status SafetensorsFile::read_f32(const SafeTensor& t, std::span<float> out) const {
  if (out.size() != t.numel())
    return Status::invalid("safetensors: tensor " + text::quoted(t.name) + " has " +
                           std::to_string(t.numel()) + " elements, the destination " +
                           std::to_string(out.size()));
  const char* p = bytes_.data() + data_start_ + t.begin;
  const size_t n = out.size();
  if (t.dtype == "F32") {
    std::memcpy(out.data(), p, n * 4);
  } else if (t.dtype == "F16" || t.dtype == "BF16") {
    const bool half = t.dtype == "F16";
    for (size_t i = 0; i < n; ++i) {
      const uint16_t v = static_cast<uint16_t>(static_cast<unsigned char>(p[2 * i]) |
                                               (static_cast<unsigned char>(p[2 * i + 1]) << 8));
      out[i] = half ? f16_to_f32(v) : bf16_to_f32(v);
    }
  } else {
    return Status::unsupported("safetensors: tensor " + text::quoted(t.name) + " has dtype " +
                               t.dtype + "; squawk reads F32, F16 and BF16");
  }
  return Status::ok();
}

Result<std::string> serialize_safetensors(const std::vector<TensorRef>& tensors,
                                          const std::map<std::string, std::string>& metadata) {
  json h = json::object();
  if (!metadata.empty()) h["__metadata__"] = metadata;
  size_t off = 0;
  for (const TensorRef& t : tensors) {
    size_t n = 1;
    for (int64_t d : t.shape) n *= static_cast<size_t>(d);
    if (n != t.data.size())
      return Status::invalid("safetensors: tensor " + text::quoted(t.name) + " of shape " +
                             shape_str(t.shape) + " was given " + std::to_string(t.data.size()) +
                             " floats");
    h[t.name] = {{"dtype", "F32"}, {"shape", t.shape}, {"data_offsets", {off, off + 4 * n}}};
    off += 4 * n;
  }
  std::string header = h.dump();
  header.append((8 - header.size() % 8) % 8, ' ');
  std::string out(8, '\0');
  uint64_t len = header.size();
  for (int i = 0; i < 8; ++i) out[i] = static_cast<char>((len >> (8 * i)) & 0xffu);
  out.reserve(8 + header.size() + off);
  out.append(header);
  for (const TensorRef& t : tensors)
    out.append(reinterpret_cast<const char*>(t.data.data()), t.data.size() * 4);
  return out;
}

Status write_safetensors(const std::string& path, const std::vector<TensorRef>& tensors,
                         const std::map<std::string, std::string>& metadata) {
  SQUAWK_ASSIGN_OR_RETURN(std::string bytes, serialize_safetensors(tensors, metadata));
  return files::write_atomic(path, bytes);
}

std::string shape_str(const std::vector<int64_t>& s) {
  std::string r = "[";
  for (size_t i = 0; i < s.size(); ++i) {
    if (i) r.append(", ");
    r.append(std::to_string(s[i]));
  }
  return r.append("]");
}

}  // namespace squawk::gpt2
