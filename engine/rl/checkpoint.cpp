#include "rl/checkpoint.h"

#include <algorithm>

#include "rl/checkpoint_file.h"

namespace squawk::rl {

namespace {
constexpr const char* kMagic = "squawk-checkpoint 1";
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
                      {"num_value_params", c.value_params.size()},
                      {"value_adam_t", c.value_t}};
  const size_t nv = c.value_params.size();
  if (c.value_m.size() != nv || c.value_v.size() != nv)
    return Status::internal("checkpoint " + path + ": value-baseline Adam state size differs");
  if (c.has_adam && (c.adam_m.size() != c.params.size() || c.adam_v.size() != c.params.size()))
    return Status::internal("checkpoint " + path + ": Adam state size differs from the parameters");
  put_progress(h, c.progress);
  const std::vector<float> none;
  return write_checkpoint_file(path, kMagic, h,
                               {&c.params, c.has_adam ? &c.adam_m : &none, c.has_adam ? &c.adam_v : &none,
                                &c.value_params, &c.value_m, &c.value_v});
}

Result<Checkpoint> load_checkpoint(const std::string& path) {
  SQUAWK_ASSIGN_OR_RETURN(CheckpointFile f, read_checkpoint_file(path, kMagic));
  Checkpoint c;
  try {
    const auto& h = f.header;
    c.spec.obs_size = whole<int>(h, "obs_size");
    c.spec.hidden = wholes<int>(h, "hidden");
    c.spec.head = h.at("head").get<std::string>();
    c.spec.action_values = h.at("action_values").get<std::vector<double>>();
    c.spec.init_log_std = h.value("init_log_std", -0.5);
    c.params.resize(f.length("num_params", CheckpointFile::kRequired));
    c.has_adam = h.at("has_adam").get<bool>();
    c.adam_t = whole<long long>(h, "adam_t", 0LL);
    c.progress = get_progress(h);
    c.value_params.resize(f.length("num_value_params", 0));
    c.value_t = whole<long long>(h, "value_adam_t", 0LL);
  } catch (const std::exception& e) {
    return Status::corruption("checkpoint " + path + ": bad JSON header: " + e.what());
  }
  SQUAWK_RETURN_IF_ERROR(c.spec.validate().with_context("checkpoint " + path));
  const size_t n = c.params.size(), nv = c.value_params.size();
  if (c.has_adam) c.adam_m.resize(n), c.adam_v.resize(n);
  c.value_m.resize(nv);
  c.value_v.resize(nv);
  SQUAWK_RETURN_IF_ERROR(f.read_arrays(
      path,
      std::to_string(n) + " parameters" + (c.has_adam ? " + Adam m, v" : "") + ", " +
          std::to_string(nv) + " value parameters x 3",
      {&c.params, &c.adam_m, &c.adam_v, &c.value_params, &c.value_m, &c.value_v}));
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
