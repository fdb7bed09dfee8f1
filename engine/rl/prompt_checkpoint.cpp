#include "rl/prompt_checkpoint.h"

#include <bit>
#include <cstring>

#include <nlohmann/json.hpp>

#include "core/files.h"

namespace squawk::rl {

namespace {

constexpr const char* kMagic = "squawk-gpt2-policy 1";
static_assert(std::endian::native == std::endian::little, "checkpoints are little-endian float32");

void append_floats(std::string& out, const std::vector<float>& v) {
  out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(float));
}

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
                      {"episodes", c.progress.episodes},
                      {"updates", c.progress.updates},
                      {"seed", c.progress.seed},
                      {"estimator", c.progress.estimator},
                      {"scenario", c.progress.scenario},
                      {"wall_s", c.progress.wall_s}};
  std::string out = kMagic;
  out += '\n';
  out += h.dump();
  out += '\n';
  append_floats(out, c.params);
  if (c.has_adam) {
    append_floats(out, c.adam_m);
    append_floats(out, c.adam_v);
  }
  return files::write_atomic(path, out);
}

Result<PromptCheckpoint> load_prompt_checkpoint(const std::string& path) {
  SQUAWK_ASSIGN_OR_RETURN(std::string data, files::read(path));
  const size_t nl1 = data.find('\n');
  if (nl1 == std::string::npos || data.compare(0, nl1, kMagic) != 0)
    return Status::corruption("checkpoint " + path + ": first line is not '" + kMagic + "'");
  const size_t nl2 = data.find('\n', nl1 + 1);
  if (nl2 == std::string::npos)
    return Status::corruption("checkpoint " + path + ": missing the JSON header line");
  PromptCheckpoint c;
  try {
    const auto h = nlohmann::json::parse(data.substr(nl1 + 1, nl2 - nl1 - 1));
    c.source = h.at("source").get<std::string>();
    c.model_seed = h.at("model_seed").get<uint64_t>();
    c.config_json = h.at("config").get<std::string>();
    c.spec.head = h.at("head").get<std::string>();
    c.spec.action_values = h.at("action_values").get<std::vector<double>>();
    c.spec.lm_texts = h.at("lm_texts").get<std::vector<std::string>>();
    c.spec.trainable_blocks = h.at("trainable_blocks").get<int>();
    c.spec.obs_size = h.at("obs_size").get<int>();
    c.vocab_json = h.at("vocab").get<std::string>();
    c.merges_txt = h.at("merges").get<std::string>();
    c.prompt = h.value("prompt", "");
    c.params.resize(h.at("num_params").get<size_t>());
    c.has_adam = h.at("has_adam").get<bool>();
    c.adam_t = h.value("adam_t", 0LL);
    c.progress.episodes = h.value("episodes", 0LL);
    c.progress.updates = h.value("updates", 0LL);
    c.progress.seed = h.value("seed", 0ULL);
    c.progress.estimator = h.value("estimator", "");
    c.progress.scenario = h.value("scenario", "");
    c.progress.wall_s = h.value("wall_s", 0.0);
  } catch (const std::exception& e) {
    return Status::corruption("checkpoint " + path + ": bad JSON header: " + e.what());
  }
  const size_t n = c.params.size();
  const size_t want = (c.has_adam ? 3 : 1) * n * sizeof(float);
  const size_t got = data.size() - nl2 - 1;
  if (got != want)
    return Status::corruption("checkpoint " + path + ": " + std::to_string(got) +
                              " bytes of tensors, expected " + std::to_string(want) + " (" +
                              std::to_string(n) + " parameters" + (c.has_adam ? " + Adam m, v)" : ")"));
  const char* p = data.data() + nl2 + 1;
  std::memcpy(c.params.data(), p, n * sizeof(float));
  if (c.has_adam) {
    c.adam_m.resize(n);
    c.adam_v.resize(n);
    std::memcpy(c.adam_m.data(), p + n * sizeof(float), n * sizeof(float));
    std::memcpy(c.adam_v.data(), p + 2 * n * sizeof(float), n * sizeof(float));
  }
  return c;
}

}  // namespace squawk::rl
