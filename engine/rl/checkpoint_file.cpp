#include "rl/checkpoint_file.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "core/files.h"

namespace squawk::rl {

static_assert(std::endian::native == std::endian::little, "checkpoints are little-endian float32");

Status write_checkpoint_file(const std::string& path, std::string_view magic,
                             const nlohmann::json& header,
                             std::initializer_list<const std::vector<float>*> arrays) {
  std::string out(magic);
  out += '\n';
  out += header.dump();
  out += '\n';
  for (const auto* v : arrays)
    if (!v->empty()) out.append(reinterpret_cast<const char*>(v->data()), v->size() * sizeof(float));
  return files::write_atomic(path, out);
}

void write_mirror(nlohmann::json& header, const env::ObservationMirror& m) {
  if (m.empty()) return;
  header["mirror_scale"] = m.scale;
  header["mirror_offset"] = m.offset;
}

env::ObservationMirror read_mirror(const nlohmann::json& h) {
  env::ObservationMirror m;
  if (!h.contains("mirror_scale") && !h.contains("mirror_offset")) return m;
  for (auto [key, out] : {std::pair{"mirror_scale", &m.scale}, {"mirror_offset", &m.offset}}) {
    const nlohmann::json& v = h.at(key);
    if (!v.is_array()) throw std::runtime_error(std::string(key) + ": expected an array of numbers");
    for (const auto& e : v) {
      if (!e.is_number() || !(std::fabs(e.get<double>()) <= std::numeric_limits<float>::max()))
        throw std::runtime_error(std::string(key) + ": " + e.dump() + " is not a float32 number");
      out->push_back(static_cast<float>(e.get<double>()));
    }
  }
  return m;
}

Result<CheckpointFile> read_checkpoint_file(const std::string& path, std::string_view magic) {
  CheckpointFile f;
  SQUAWK_ASSIGN_OR_RETURN(f.data, files::read(path));
  const size_t nl1 = f.data.find('\n');
  if (nl1 == std::string::npos || std::string_view(f.data).substr(0, nl1) != magic)
    return Status::corruption("checkpoint " + path + ": first line is not '" + std::string(magic) + "'");
  const size_t nl2 = f.data.find('\n', nl1 + 1);
  if (nl2 == std::string::npos)
    return Status::corruption("checkpoint " + path + ": missing the JSON header line");
  f.header = nlohmann::json::parse(f.data.substr(nl1 + 1, nl2 - nl1 - 1), nullptr, false);
  if (f.header.is_discarded() || !f.header.is_object())
    return Status::corruption("checkpoint " + path + ": the header line is not a JSON object");
  f.tensors = nl2 + 1;
  return f;
}

size_t CheckpointFile::length(const char* key, size_t absent) const {
  if (!header.contains(key) && absent != kRequired) return absent;
  const size_t n = whole<size_t>(header, key);
  const size_t floats = (data.size() - tensors) / sizeof(float);
  if (n > floats)
    throw std::runtime_error(std::string(key) + " = " + std::to_string(n) + " but the file holds " +
                             std::to_string(floats) + " floats");
  return n;
}

Status CheckpointFile::read_arrays(const std::string& path, const std::string& what,
                                   std::initializer_list<std::vector<float>*> arrays) const {
  size_t want = 0;
  for (const auto* v : arrays) want += v->size() * sizeof(float);
  const size_t got = data.size() - tensors;
  if (got != want)
    return Status::corruption("checkpoint " + path + ": " + std::to_string(got) +
                              " bytes of tensors, expected " + std::to_string(want) + " (" + what + ")");
  const char* p = data.data() + tensors;
  for (auto* v : arrays) {
    if (v->empty()) continue;  // an empty vector's data() may be null
    std::memcpy(v->data(), p, v->size() * sizeof(float));
    p += v->size() * sizeof(float);
  }
  return Status::ok();
}

Status write_train_checkpoint(const std::string& path, std::string_view magic, nlohmann::json h,
                              const TrainState& s) {
  const size_t n = s.params.size(), nv = s.value_params.size();
  if (s.has_adam && (s.adam_m.size() != n || s.adam_v.size() != n))
    return Status::internal("checkpoint " + path + ": Adam state size differs from the parameters");
  if (s.value_m.size() != nv || s.value_v.size() != nv)
    return Status::internal("checkpoint " + path + ": value-baseline Adam state size differs");
  h["num_params"] = n;
  h["has_adam"] = s.has_adam;
  h["adam_t"] = s.adam_t;
  h["num_value_params"] = nv;
  h["value_adam_t"] = s.value_t;
  const TrainProgress& p = s.progress;
  h["episodes"] = p.episodes;
  h["updates"] = p.updates;
  h["seed"] = p.seed;
  h["estimator"] = p.estimator;
  h["scenario"] = p.scenario;
  h["wall_s"] = p.wall_s;
  h["interval_return"] = p.interval_return;
  h["interval_success"] = p.interval_success;
  h["interval_updates"] = p.interval_updates;
  const std::vector<float> none;
  return write_checkpoint_file(path, magic, h,
                               {&s.params, s.has_adam ? &s.adam_m : &none, s.has_adam ? &s.adam_v : &none,
                                &s.value_params, &s.value_m, &s.value_v});
}

void read_train_header(const CheckpointFile& f, TrainState& s) {
  const nlohmann::json& h = f.header;
  s.params.resize(f.length("num_params", CheckpointFile::kRequired));
  s.has_adam = h.at("has_adam").get<bool>();
  s.adam_t = whole<long long>(h, "adam_t", 0LL);
  s.value_params.resize(f.length("num_value_params", 0));
  s.value_t = whole<long long>(h, "value_adam_t", 0LL);
  TrainProgress& p = s.progress;
  p.episodes = whole<long long>(h, "episodes", 0LL);
  p.updates = whole<long long>(h, "updates", 0LL);
  p.seed = whole<unsigned long long>(h, "seed", 0ULL);
  p.estimator = h.value("estimator", "");
  p.scenario = h.value("scenario", "");
  p.wall_s = h.value("wall_s", 0.0);
  p.interval_return = h.value("interval_return", 0.0);
  p.interval_success = h.value("interval_success", 0.0);
  p.interval_updates = whole<long long>(h, "interval_updates", 0LL);
}

Status read_train_arrays(const CheckpointFile& f, const std::string& path, TrainState& s) {
  const size_t n = s.params.size(), nv = s.value_params.size();
  if (s.has_adam) s.adam_m.resize(n), s.adam_v.resize(n);
  s.value_m.resize(nv);
  s.value_v.resize(nv);
  return f.read_arrays(path,
                       std::to_string(n) + " parameters" + (s.has_adam ? " + Adam m, v" : "") + " + " +
                           std::to_string(nv) + " value-baseline parameters, Adam m, v",
                       {&s.params, &s.adam_m, &s.adam_v, &s.value_params, &s.value_m, &s.value_v});
}

}  // namespace squawk::rl
