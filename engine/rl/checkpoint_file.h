// The container every squawk policy checkpoint uses:
//   line 1: a magic string naming the kind and version ("squawk-checkpoint 1")
//   line 2: one JSON object (the header: spec, counters, array lengths)
//   then float32 arrays, little-endian, back to back, in an order and with
//   lengths the kind's header defines.
// Writers go through files::write_atomic (temp file + rename).
#pragma once

#include <cstdint>
#include <initializer_list>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/status.h"
#include "env/observation.h"
#include "rl/checkpoint.h"

namespace squawk::rl {

// Magic line, header line and the arrays, written atomically to `path`.
Status write_checkpoint_file(const std::string& path, std::string_view magic,
                             const nlohmann::json& header,
                             std::initializer_list<const std::vector<float>*> arrays);

struct CheckpointFile {
  nlohmann::json header;
  std::string data;      // the whole file
  size_t tensors = 0;    // offset of the first array in data

  static constexpr size_t kRequired = SIZE_MAX;
  // header[key] (or `absent` when missing, unless kRequired) as an array length, checked
  // against the tensor section: a header cannot make a reader allocate more
  // floats than the file holds. Throws std::runtime_error naming the key
  // otherwise (the loaders' header parsing turns it into a corruption error).
  size_t length(const char* key, size_t absent) const;

  // Fills `arrays` (each already sized) from the tensor section; error, naming
  // `path` and `what` the sizes mean, unless the section has exactly that many bytes.
  Status read_arrays(const std::string& path, const std::string& what,
                     std::initializer_list<std::vector<float>*> arrays) const;
};

// header[key] as a whole number of type T (`absent` when missing, if given).
// Throws std::runtime_error naming the key when it is not a whole number in
// T's range: a float such as 1e300 must never reach an integer conversion.
template <class T>
T whole(const nlohmann::json& h, const char* key, std::optional<T> absent = std::nullopt) {
  if (absent && !h.contains(key)) return *absent;
  const nlohmann::json& v = h.at(key);
  if (v.is_number_unsigned() && std::in_range<T>(v.get<uint64_t>())) return static_cast<T>(v.get<uint64_t>());
  if (v.is_number_integer() && !v.is_number_unsigned() && std::in_range<T>(v.get<int64_t>()))
    return static_cast<T>(v.get<int64_t>());
  throw std::runtime_error(std::string(key) + " = " + v.dump() + ": expected a whole number in [" +
                           std::to_string(std::numeric_limits<T>::min()) + ", " +
                           std::to_string(std::numeric_limits<T>::max()) + "]");
}
// header[key] as an array of whole numbers of type T (same checks).
template <class T>
std::vector<T> wholes(const nlohmann::json& h, const char* key) {
  const nlohmann::json& v = h.at(key);
  if (!v.is_array()) throw std::runtime_error(std::string(key) + ": expected an array of whole numbers");
  std::vector<T> out;
  for (const auto& e : v) out.push_back(whole<T>(nlohmann::json{{key, e}}, key));
  return out;
}

// A policy spec's mirror map (env/observation.h) as the header keys
// "mirror_scale" and "mirror_offset", both absent when the map is empty.
// read_mirror throws std::runtime_error naming the key on a malformed entry;
// the spec's validate() checks sizes and values.
void write_mirror(nlohmann::json& header, const env::ObservationMirror& m);
env::ObservationMirror read_mirror(const nlohmann::json& header);

// Reads `path`, checks the magic line and parses the header line.
Result<CheckpointFile> read_checkpoint_file(const std::string& path, std::string_view magic);

// A checkpoint of any kind: the kind's header fields in `header`, plus the
// TrainState's counters and lengths, then its arrays (params, Adam m, v, value
// params, value m, v; the Adam arrays empty without has_adam), atomically.
// Error: the Adam or value-baseline arrays do not match their parameters.
Status write_train_checkpoint(const std::string& path, std::string_view magic, nlohmann::json header,
                              const TrainState& s);
// The TrainState's counters from `f`'s header, its arrays sized (throws
// std::runtime_error naming the key, as CheckpointFile::length and whole do).
void read_train_header(const CheckpointFile& f, TrainState& s);
// Then its arrays; error, naming `path`, unless the file holds exactly them.
Status read_train_arrays(const CheckpointFile& f, const std::string& path, TrainState& s);

}  // namespace squawk::rl
