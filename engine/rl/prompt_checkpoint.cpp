#include "rl/prompt_checkpoint.h"

#include "rl/checkpoint_file.h"

namespace squawk::rl {

namespace {
constexpr const char* kMagic = "squawk-gpt2-policy 1";
}  // namespace

Status save_prompt_checkpoint(const std::string& path, const PromptCheckpoint& c) {
  nlohmann::json header = {{"source", c.source},
                           {"model_seed", c.model_seed},
                           {"config", c.config_json},
                           {"head", c.spec.head},
                           {"action_values", c.spec.action_values},
                           {"lm_texts", c.spec.lm_texts},
                           {"trainable_blocks", c.spec.trainable_blocks},
                           {"train_embeddings", c.spec.train_embeddings},
                           {"obs_size", c.spec.obs_size},
                           {"vocab", c.vocab_json},
                           {"merges", c.merges_txt},
                           {"prompt", c.prompt}};
  write_mirror(header, c.spec.mirror);
  return write_train_checkpoint(path, kMagic, header, c);
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
    c.spec.train_embeddings = h.value("train_embeddings", false);
    c.spec.obs_size = whole<int>(h, "obs_size");
    c.spec.mirror = read_mirror(h);
    c.vocab_json = h.at("vocab").get<std::string>();
    c.merges_txt = h.at("merges").get<std::string>();
    c.prompt = h.value("prompt", "");
    read_train_header(f, c);
  } catch (const std::exception& e) {
    return Status::corruption("checkpoint " + path + ": bad JSON header: " + e.what());
  }
  SQUAWK_RETURN_IF_ERROR(read_train_arrays(f, path, c));
  return c;
}

}  // namespace squawk::rl
