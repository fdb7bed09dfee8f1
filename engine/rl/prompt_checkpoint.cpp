#include "rl/prompt_checkpoint.h"

#include "rl/checkpoint_file.h"

namespace squawk::rl {

namespace {
constexpr const char* kMagic = "squawk-gpt2-policy 1";
}  // namespace

Status save_prompt_checkpoint(const std::string& path, const PromptCheckpoint& c) {
  if (c.has_adam && (c.adam_m.size() != c.params.size() || c.adam_v.size() != c.params.size()))
    return Status::internal("checkpoint " + path + ": Adam state size differs from the parameters");
  nlohmann::json h = {{"source", c.source},
                      {"model_seed", c.model_seed},
                      {"config", c.config_json},
                      {"head", c.spec.head},
                      {"action_values", c.spec.action_values},
                      {"lm_texts", c.spec.lm_texts},
                      {"trainable_blocks", c.spec.trainable_blocks},
                      {"obs_size", c.spec.obs_size},
                      {"vocab", c.vocab_json},
                      {"merges", c.merges_txt},
                      {"prompt", c.prompt},
                      {"num_params", c.params.size()},
                      {"has_adam", c.has_adam},
                      {"adam_t", c.adam_t},
                      {"num_value_params", c.value_params.size()},
                      {"value_adam_t", c.value_t}};
  const size_t nv = c.value_params.size();
  if (c.value_m.size() != nv || c.value_v.size() != nv)
    return Status::internal("checkpoint " + path + ": value-baseline Adam state size differs");
  put_progress(h, c.progress);
  const std::vector<float> none;
  return write_checkpoint_file(path, kMagic, h,
                               {&c.params, c.has_adam ? &c.adam_m : &none, c.has_adam ? &c.adam_v : &none,
                                &c.value_params, &c.value_m, &c.value_v});
}

Result<PromptCheckpoint> load_prompt_checkpoint(const std::string& path) {
  SQUAWK_ASSIGN_OR_RETURN(CheckpointFile f, read_checkpoint_file(path, kMagic));
  PromptCheckpoint c;
  try {
    const auto& h = f.header;
    c.source = h.at("source").get<std::string>();
    c.model_seed = whole<uint64_t>(h, "model_seed");
    c.config_json = h.at("config").get<std::string>();
    c.spec.head = h.at("head").get<std::string>();
    c.spec.action_values = h.at("action_values").get<std::vector<double>>();
    c.spec.lm_texts = h.at("lm_texts").get<std::vector<std::string>>();
    c.spec.trainable_blocks = whole<int>(h, "trainable_blocks");
    c.spec.obs_size = whole<int>(h, "obs_size");
    c.vocab_json = h.at("vocab").get<std::string>();
    c.merges_txt = h.at("merges").get<std::string>();
    c.prompt = h.value("prompt", "");
    c.params.resize(f.length("num_params", CheckpointFile::kRequired));
    c.has_adam = h.at("has_adam").get<bool>();
    c.adam_t = whole<long long>(h, "adam_t", 0LL);
    c.value_params.resize(f.length("num_value_params", 0));
    c.value_t = whole<long long>(h, "value_adam_t", 0LL);
    c.progress = get_progress(h);
  } catch (const std::exception& e) {
    return Status::corruption("checkpoint " + path + ": bad JSON header: " + e.what());
  }
  const size_t n = c.params.size();
  if (c.has_adam) c.adam_m.resize(n), c.adam_v.resize(n);
  const size_t nv = c.value_params.size();
  c.value_m.resize(nv);
  c.value_v.resize(nv);
  SQUAWK_RETURN_IF_ERROR(f.read_arrays(
      path,
      std::to_string(n) + " parameters" + (c.has_adam ? " + Adam m, v" : "") + " + " + std::to_string(nv) +
          " value-baseline parameters, Adam m, v",
      {&c.params, &c.adam_m, &c.adam_v, &c.value_params, &c.value_m, &c.value_v}));
  return c;
}

}  // namespace squawk::rl
