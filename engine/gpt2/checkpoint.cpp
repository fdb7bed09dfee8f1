#include "gpt2/checkpoint.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>

#include <nlohmann/json.hpp>

#include "core/files.h"
#include "core/text.h"

namespace squawk::gpt2 {

namespace {

using nlohmann::json;

const char kPrefix[] = "transformer.";

Status bad_config(const std::string& msg) { return Status::corruption("config.json: " + msg); }

Result<int> int_field(const json& j, const char* key, bool required, int fallback) {
  auto it = j.find(key);
  if (it == j.end() || it->is_null()) {
    if (!required) return fallback;
    return bad_config(std::string("missing integer field \"") + key + "\"");
  }
  if (!it->is_number_integer() || it->get<long long>() < 0 || it->get<long long>() > (1 << 30))
    return bad_config(std::string("field \"") + key + "\" must be a non-negative integer");
  return static_cast<int>(it->get<long long>());
}

bool is_ignored_buffer(const std::string& name) {
  static const std::regex mask(R"(h\.\d+\.attn\.(bias|masked_bias))");
  return std::regex_match(name, mask);
}

}  // namespace

Result<Config> parse_hf_config(const std::string& json_text) {
  const json j = json::parse(json_text, nullptr, false);
  if (j.is_discarded()) return bad_config("not valid JSON");
  if (!j.is_object()) return bad_config("expected a JSON object");
  Config c;
  SQUAWK_ASSIGN_OR_RETURN(c.n_layer, int_field(j, "n_layer", true, 0));
  SQUAWK_ASSIGN_OR_RETURN(c.n_head, int_field(j, "n_head", true, 0));
  SQUAWK_ASSIGN_OR_RETURN(c.n_embd, int_field(j, "n_embd", true, 0));
  SQUAWK_ASSIGN_OR_RETURN(c.vocab_size, int_field(j, "vocab_size", true, 0));
  SQUAWK_ASSIGN_OR_RETURN(int n_ctx, int_field(j, "n_ctx", false, 0));
  SQUAWK_ASSIGN_OR_RETURN(c.n_ctx, int_field(j, "n_positions", n_ctx == 0, n_ctx));
  if (auto it = j.find("layer_norm_epsilon"); it != j.end()) {
    if (!it->is_number()) return bad_config("field \"layer_norm_epsilon\" must be a number");
    c.ln_eps = it->get<float>();
  }
  if (auto it = j.find("activation_function"); it != j.end()) {
    if (!it->is_string() || it->get<std::string>() != "gelu_new")
      return Status::unsupported("config.json: activation_function " + it->dump() +
                                 "; squawk implements GPT-2's \"gelu_new\"");
  }
  SQUAWK_RETURN_IF_ERROR(c.validate());
  return c;
}

std::string hf_config_json(const Config& c) {
  json j = {{"architectures", {"GPT2LMHeadModel"}},
            {"model_type", "gpt2"},
            {"activation_function", "gelu_new"},
            {"n_layer", c.n_layer},
            {"n_head", c.n_head},
            {"n_embd", c.n_embd},
            {"n_positions", c.n_ctx},
            {"n_ctx", c.n_ctx},
            {"vocab_size", c.vocab_size},
            {"layer_norm_epsilon", c.ln_eps},
            {"n_inner", nullptr},
            {"resid_pdrop", 0.0},
            {"embd_pdrop", 0.0},
            {"attn_pdrop", 0.0},
            {"initializer_range", 0.02},
            {"bos_token_id", c.vocab_size - 1},
            {"eos_token_id", c.vocab_size - 1},
            {"tie_word_embeddings", true},
            {"torch_dtype", "float32"}};
  return j.dump(2) + "\n";
}

Status load_weights(const SafetensorsFile& file, Model& model) {
  const ParamLayout& layout = model.layout();
  const Config& cfg = layout.config();
  std::map<std::string, const SafeTensor*> by_name;
  const SafeTensor* lm_head = nullptr;
  const size_t np = sizeof kPrefix - 1;
  for (const SafeTensor& t : file.tensors()) {
    std::string name = t.name.rfind(kPrefix, 0) == 0 ? t.name.substr(np) : t.name;
    if (is_ignored_buffer(name)) continue;
    if (name == "lm_head.weight") {
      const std::vector<int64_t> want = {cfg.vocab_size, cfg.n_embd};
      if (t.shape != want)
        return Status::corruption("checkpoint: lm_head.weight has shape " + shape_str(t.shape) +
                                  ", expected " + shape_str(want) + " (tied to wte)");
      lm_head = &t;
      continue;
    }
    if (!layout.find(name))
      return Status::corruption("checkpoint: unexpected tensor " + text::quoted(t.name) +
                                "; a GPT-2 file holds wte, wpe, h.N.*, ln_f (optionally "
                                "prefixed \"transformer.\"), lm_head and attention-mask buffers");
    if (by_name.count(name))
      return Status::corruption("checkpoint: tensor " + text::quoted(name) +
                                " appears both with and without the \"transformer.\" prefix");
    by_name[name] = &t;
  }
  const size_t extras = layout.extras_start();
  for (const TensorSpec& spec : layout.tensors()) {
    auto it = by_name.find(spec.name);
    if (it == by_name.end()) {
      if (spec.offset >= extras) continue;
      return Status::corruption("checkpoint: missing tensor " + text::quoted(spec.name) +
                                " (shape " + shape_str(spec.shape) + ")");
    }
    const SafeTensor& t = *it->second;
    if (t.shape != spec.shape)
      return Status::corruption("checkpoint: tensor " + text::quoted(t.name) + " has shape " +
                                shape_str(t.shape) + ", expected " + shape_str(spec.shape));
    SQUAWK_RETURN_IF_ERROR(file.read_f32(t, model.tensor(spec.name)));
    for (const float v : model.tensor(spec.name))
      if (!std::isfinite(v))
        return Status::corruption("checkpoint: tensor " + text::quoted(t.name) + " holds NaN or infinite weights");
  }
  if (lm_head) {
    std::vector<float> head(lm_head->numel());
    SQUAWK_RETURN_IF_ERROR(file.read_f32(*lm_head, head));
    auto wte = model.tensor("wte.weight");
    if (!std::equal(head.begin(), head.end(), wte.begin()))
      return Status::unsupported("checkpoint: lm_head.weight differs from wte.weight; squawk's GPT-2 "
                                 "ties the LM head to the token embedding");
  }
  return Status::ok();
}

Result<Model> load_model(const std::string& dir, const std::vector<TensorSpec>& extras) {
  SQUAWK_ASSIGN_OR_RETURN(std::string cfg_text, files::read(dir + "/config.json"));
  auto cfg = parse_hf_config(cfg_text);
  if (!cfg) return cfg.status().with_context(dir);
  SQUAWK_ASSIGN_OR_RETURN(SafetensorsFile file, SafetensorsFile::open(dir + "/model.safetensors"));
  // The weights must fit in the file (at 2 bytes each at least) before the
  // model is allocated: a config that does not match its file fails here.
  const long long params = cfg->num_params();
  if (static_cast<unsigned long long>(params) > file.data_bytes() / 2)
    return Status::corruption(dir + ": config.json describes " + std::to_string(params) +
                              " parameters but model.safetensors holds " + std::to_string(file.data_bytes()) +
                              " bytes of data (at least " + std::to_string(2 * params) + " needed)");
  SQUAWK_ASSIGN_OR_RETURN(Model model, Model::create(*cfg, extras));
  Status st = load_weights(file, model);
  if (!st.is_ok()) return st.with_context(dir + "/model.safetensors");
  return model;
}

Status save_model(const std::string& dir, const Model& model) {
  SQUAWK_RETURN_IF_ERROR(files::make_dirs(dir));
  const ParamLayout& layout = model.layout();
  std::vector<TensorRef> refs;
  for (const TensorSpec& t : layout.tensors()) {
    std::string name = t.offset < layout.extras_start() ? kPrefix : "";
    name.append(t.name);
    refs.push_back({std::move(name), t.shape, model.params().subspan(t.offset, t.size)});
  }
  SQUAWK_RETURN_IF_ERROR(
      write_safetensors(dir + "/model.safetensors", refs, {{"format", "pt"}}));
  return files::write_atomic(dir + "/config.json", hf_config_json(layout.config()));
}

}  // namespace squawk::gpt2
