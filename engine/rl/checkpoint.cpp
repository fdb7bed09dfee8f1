#include "rl/checkpoint.h"

#include <algorithm>

#include "rl/checkpoint_file.h"

namespace squawk::rl {

namespace {
constexpr const char* kMagic = "squawk-checkpoint 1";
}  // namespace

Status save_checkpoint(const std::string& path, const Checkpoint& c) {
  nlohmann::json spec = {{"obs_size", c.spec.obs_size},
                         {"hidden", c.spec.hidden},
                         {"head", c.spec.head},
                         {"action_values", c.spec.action_values},
                         {"init_log_std", c.spec.init_log_std}};
  write_mirror(spec, c.spec.mirror);
  if (!c.spec.obs_shift.empty()) {
    spec["obs_shift"] = c.spec.obs_shift;
    spec["obs_scale"] = c.spec.obs_scale;
  }
  return write_train_checkpoint(path, kMagic, spec, c);
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
    c.spec.mirror = read_mirror(h);
    c.spec.obs_shift = h.value("obs_shift", std::vector<float>{});
    c.spec.obs_scale = h.value("obs_scale", std::vector<float>{});
    read_train_header(f, c);
  } catch (const std::exception& e) {
    return Status::corruption("checkpoint " + path + ": bad JSON header: " + e.what());
  }
  SQUAWK_RETURN_IF_ERROR(c.spec.validate().with_context("checkpoint " + path));
  SQUAWK_RETURN_IF_ERROR(read_train_arrays(f, path, c));
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
