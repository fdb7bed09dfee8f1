#include "rl/checkpoint.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include <nlohmann/json.hpp>

#include "core/files.h"

namespace squawk::rl {

namespace {

constexpr const char* kMagic = "squawk-checkpoint 1";
static_assert(std::endian::native == std::endian::little, "checkpoints are little-endian float32");

void append_floats(std::string& out, const std::vector<float>& v) {
  out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(float));
}

}  // namespace

Status save_checkpoint(const std::string& path, const Checkpoint& c) {
  nlohmann::json h = {{"obs_size", c.spec.obs_size},
                      {"hidden", c.spec.hidden},
                      {"head", c.spec.head},
                      {"action_values", c.spec.action_values},
                      {"init_log_std", c.spec.init_log_std},
                      {"num_params", c.params.size()},
                      {"has_adam", c.has_adam},
                      {"adam_t", c.adam_t},
                      {"episodes", c.progress.episodes},
                      {"updates", c.progress.updates},
                      {"seed", c.progress.seed},
                      {"estimator", c.progress.estimator},
                      {"scenario", c.progress.scenario},
                      {"wall_s", c.progress.wall_s},
                      {"num_value_params", c.value_params.size()},
                      {"value_adam_t", c.value_t}};
  const size_t nv = c.value_params.size();
  if (c.value_m.size() != nv || c.value_v.size() != nv)
    return Status::internal("checkpoint " + path + ": value-baseline Adam state size differs");
  if (c.has_adam && (c.adam_m.size() != c.params.size() || c.adam_v.size() != c.params.size()))
    return Status::internal("checkpoint " + path + ": Adam state size differs from the parameters");
  std::string out = kMagic;
  out += '\n';
  out += h.dump();
  out += '\n';
  append_floats(out, c.params);
  if (c.has_adam) {
    append_floats(out, c.adam_m);
    append_floats(out, c.adam_v);
  }
  append_floats(out, c.value_params);
  append_floats(out, c.value_m);
  append_floats(out, c.value_v);
  return files::write_atomic(path, out);
}

Result<Checkpoint> load_checkpoint(const std::string& path) {
  SQUAWK_ASSIGN_OR_RETURN(std::string data, files::read(path));
  const size_t nl1 = data.find('\n');
  if (nl1 == std::string::npos || data.compare(0, nl1, kMagic) != 0)
    return Status::corruption("checkpoint " + path + ": first line is not '" + kMagic + "'");
  const size_t nl2 = data.find('\n', nl1 + 1);
  if (nl2 == std::string::npos)
    return Status::corruption("checkpoint " + path + ": missing the JSON header line");
  Checkpoint c;
  try {
    const auto h = nlohmann::json::parse(data.substr(nl1 + 1, nl2 - nl1 - 1));
    c.spec.obs_size = h.at("obs_size").get<int>();
    c.spec.hidden = h.at("hidden").get<std::vector<int>>();
    c.spec.head = h.at("head").get<std::string>();
    c.spec.action_values = h.at("action_values").get<std::vector<double>>();
    c.spec.init_log_std = h.value("init_log_std", -0.5);
    c.params.resize(h.at("num_params").get<size_t>());
    c.has_adam = h.at("has_adam").get<bool>();
    c.adam_t = h.value("adam_t", 0LL);
    c.progress.episodes = h.value("episodes", 0LL);
    c.progress.updates = h.value("updates", 0LL);
    c.progress.seed = h.value("seed", 0ULL);
    c.progress.estimator = h.value("estimator", "");
    c.progress.scenario = h.value("scenario", "");
    c.progress.wall_s = h.value("wall_s", 0.0);
    c.value_params.resize(h.value("num_value_params", size_t{0}));
    c.value_t = h.value("value_adam_t", 0LL);
  } catch (const std::exception& e) {
    return Status::corruption("checkpoint " + path + ": bad JSON header: " + e.what());
  }
  SQUAWK_RETURN_IF_ERROR(c.spec.validate().with_context("checkpoint " + path));
  const size_t n = c.params.size(), nv = c.value_params.size();
  const size_t want = ((c.has_adam ? 3 : 1) * n + 3 * nv) * sizeof(float);
  const size_t got = data.size() - nl2 - 1;
  if (got != want)
    return Status::corruption("checkpoint " + path + ": " + std::to_string(got) +
                              " bytes of tensors, expected " + std::to_string(want) + " (" +
                              std::to_string(n) + " parameters" + (c.has_adam ? " + Adam m, v" : "") +
                              ", " + std::to_string(nv) + " value parameters x 3)");
  const char* p = data.data() + nl2 + 1;
  std::memcpy(c.params.data(), p, n * sizeof(float));
  if (c.has_adam) {
    c.adam_m.resize(n);
    c.adam_v.resize(n);
    std::memcpy(c.adam_m.data(), p + n * sizeof(float), n * sizeof(float));
    std::memcpy(c.adam_v.data(), p + 2 * n * sizeof(float), n * sizeof(float));
    p += 3 * n * sizeof(float);
  } else {
    p += n * sizeof(float);
  }
  c.value_m.resize(nv);
  c.value_v.resize(nv);
  std::memcpy(c.value_params.data(), p, nv * sizeof(float));
  std::memcpy(c.value_m.data(), p + nv * sizeof(float), nv * sizeof(float));
  std::memcpy(c.value_v.data(), p + 2 * nv * sizeof(float), nv * sizeof(float));
  return c;
}

Result<std::unique_ptr<MlpPolicy>> policy_from_checkpoint(const Checkpoint& ckpt) {
  Rng unused(0);
  SQUAWK_ASSIGN_OR_RETURN(std::unique_ptr<MlpPolicy> p, MlpPolicy::make(ckpt.spec, unused));
  if (p->params().size() != ckpt.params.size())
    return Status::corruption("checkpoint holds " + std::to_string(ckpt.params.size()) +
                              " parameters, its spec needs " + std::to_string(p->params().size()));
  std::copy(ckpt.params.begin(), ckpt.params.end(), p->params().begin());
  return p;
}

}  // namespace squawk::rl
