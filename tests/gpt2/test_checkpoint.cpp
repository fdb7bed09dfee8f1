// safetensors and Hugging Face GPT-2 folders: both tensor-name layouts, F16 and
// BF16 conversion, and clear errors for every kind of bad file.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "core/files.h"
#include "core/rng.h"
#include "gpt2/checkpoint.h"

using namespace squawk;
using namespace squawk::gpt2;

namespace {

const Config kCfg{2, 2, 8, 16, 20, 1e-5f};

std::string temp_dir(const std::string& tag) {
  auto p = std::filesystem::temp_directory_path() /
           ("squawk_gpt2ck_" + tag + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(p);
  return p.string();
}

Model random_model(uint64_t seed) {
  auto m = Model::create(kCfg);
  REQUIRE(m.is_ok());
  Rng rng(seed);
  m->init_random(rng, 0.5f);
  return std::move(m).value();
}

// A safetensors file from a raw header and data buffer.
std::string raw_file(const std::string& header, const std::string& data) {
  std::string out(8, '\0');
  const uint64_t n = header.size();
  for (int i = 0; i < 8; ++i) out[i] = static_cast<char>((n >> (8 * i)) & 0xff);
  return out + header + data;
}

std::string parse_error(const std::string& bytes) {
  auto r = SafetensorsFile::parse(bytes);
  REQUIRE_FALSE(r.is_ok());
  return r.status().message();
}

bool has(const std::string& s, const std::string& part) {
  const bool ok = s.find(part) != std::string::npos;
  if (!ok) MESSAGE("message was: " << s);
  return ok;
}

}  // namespace

TEST_CASE("half and bfloat16 bit patterns convert exactly") {
  CHECK(f16_to_f32(0x3C00) == 1.0f);
  CHECK(f16_to_f32(0xC000) == -2.0f);
  CHECK(f16_to_f32(0x3555) == 0.333251953125f);
  CHECK(f16_to_f32(0x7BFF) == 65504.0f);
  CHECK(f16_to_f32(0x0001) == std::ldexp(1.0f, -24));  // smallest subnormal
  CHECK(f16_to_f32(0x03FF) == std::ldexp(1023.0f, -24));
  CHECK(std::isinf(f16_to_f32(0x7C00)));
  CHECK(std::isnan(f16_to_f32(0x7E00)));
  CHECK(std::signbit(f16_to_f32(0x8000)));
  CHECK(bf16_to_f32(0x3F80) == 1.0f);
  CHECK(bf16_to_f32(0xC049) == -3.140625f);
  CHECK(bf16_to_f32(0x4049) == 3.140625f);
}

TEST_CASE("save_pretrained and hub layouts load to the same weights") {
  Model model = random_model(1);
  const std::string dir = temp_dir("layouts");
  REQUIRE(save_model(dir, model).is_ok());
  auto pretrained = load_model(dir);
  REQUIRE_MESSAGE(pretrained.is_ok(), pretrained.status().message());
  CHECK(std::equal(pretrained->params().begin(), pretrained->params().end(), model.params().begin()));

  // The hub's layout: bare names, causal-mask buffers, and a tied lm_head.
  std::vector<TensorRef> refs;
  std::vector<float> mask(static_cast<size_t>(kCfg.n_ctx) * kCfg.n_ctx, 1.0f);
  for (const TensorSpec& t : model.layout().tensors()) {
    refs.push_back({t.name, t.shape, model.params().subspan(t.offset, t.size)});
    if (t.name.find("ln_1.weight") != std::string::npos) {
      const std::string h = t.name.substr(0, t.name.find("ln_1"));
      refs.push_back({h + "attn.bias", {1, 1, kCfg.n_ctx, kCfg.n_ctx}, mask});
    }
  }
  refs.push_back({"lm_head.weight", {kCfg.vocab_size, kCfg.n_embd}, model.tensor("wte.weight")});
  REQUIRE(write_safetensors(dir + "/model.safetensors", refs).is_ok());
  auto hub = load_model(dir);
  REQUIRE_MESSAGE(hub.is_ok(), hub.status().message());
  CHECK(std::equal(hub->params().begin(), hub->params().end(), model.params().begin()));
  std::filesystem::remove_all(dir);
}

TEST_CASE("F16 and BF16 tensors convert to float32 on load") {
  Model model = random_model(2);
  nlohmann::json h = nlohmann::json::object();
  std::string data;
  std::vector<float> want;
  int i = 0;
  for (const TensorSpec& t : model.layout().tensors()) {
    const bool half = (i++ % 2) == 0;
    const size_t begin = data.size();
    for (float v : model.tensor(t.name)) {
      uint32_t bits;
      std::memcpy(&bits, &v, 4);
      uint16_t u;
      if (half) {  // round-toward-zero to half for values in the normal range
        const int e = static_cast<int>((bits >> 23) & 0xff) - 127 + 15;
        u = static_cast<uint16_t>(((bits >> 16) & 0x8000) |
                                  (e <= 0 ? 0 : (static_cast<uint32_t>(e) << 10) | ((bits >> 13) & 0x3ff)));
        want.push_back(f16_to_f32(u));
      } else {
        u = static_cast<uint16_t>(bits >> 16);
        want.push_back(bf16_to_f32(u));
      }
      data.push_back(static_cast<char>(u & 0xff));
      data.push_back(static_cast<char>(u >> 8));
    }
    h[t.name] = {{"dtype", half ? "F16" : "BF16"}, {"shape", t.shape}, {"data_offsets", {begin, data.size()}}};
  }
  auto file = SafetensorsFile::parse(raw_file(h.dump(), data));
  REQUIRE(file.is_ok());
  auto loaded = Model::create(kCfg);
  REQUIRE(load_weights(*file, *loaded).is_ok());
  CHECK(std::equal(want.begin(), want.end(), loaded->params().begin()));
  // The conversion is close to the original (half keeps 11 bits, bfloat16 8).
  float worst = 0.0f;
  for (size_t k = 0; k < want.size(); ++k)
    worst = std::max(worst, std::fabs(want[k] - model.params()[k]) / (std::fabs(model.params()[k]) + 1e-3f));
  CHECK(worst < 1.0f / 128);
}

TEST_CASE("bad safetensors files are clear errors") {
  const std::string good_hdr = R"({"a":{"dtype":"F32","shape":[2,2],"data_offsets":[0,16]}})";
  const std::string data16(16, '\0');
  REQUIRE(SafetensorsFile::parse(raw_file(good_hdr, data16)).is_ok());
  CHECK(has(parse_error("abc"), "shorter than the 8-byte header length"));
  CHECK(has(parse_error(raw_file(good_hdr, data16).substr(0, 40)), "exceeds the"));
  CHECK(has(parse_error(raw_file(good_hdr, data16.substr(0, 12))), "fall outside the data buffer of 12 bytes"));
  std::string huge(8, '\xff');
  CHECK(has(parse_error(huge + "{}"), "exceeds the limit"));
  CHECK(has(parse_error(raw_file("{\"a\": [1,", "")), "not valid JSON"));
  CHECK(has(parse_error(raw_file("[1,2]", "")), "not an object"));
  CHECK(has(parse_error(raw_file(R"({"a":{"dtype":"F32","shape":[2,3],"data_offsets":[0,16]}})", data16)),
            "F32 [2, 3] needs 24 bytes but data_offsets span 16"));
  CHECK(has(parse_error(raw_file(R"({"a":{"dtype":"F32","shape":[2,2],"data_offsets":[8,4]}})", data16)),
            "data_offsets [8, 4]"));
  CHECK(has(parse_error(raw_file(R"({"a":{"dtype":"Q4","shape":[2],"data_offsets":[0,1]}})", data16)),
            "unknown dtype 'Q4'"));
  CHECK(has(parse_error(raw_file(R"({"a":{"dtype":"F32","shape":[-2],"data_offsets":[0,8]}})", data16)),
            "non-negative integers"));
  CHECK(has(parse_error(raw_file(R"({"a":{"dtype":"F32","shape":[2]}})", data16)), "data_offsets"));
  CHECK(has(parse_error(raw_file(R"({"a":{"shape":[2],"data_offsets":[0,8]}})", data16)), "dtype"));
  CHECK(has(parse_error(raw_file(R"({"a":{"dtype":"F32","shape":[4294967296,4294967296],"data_offsets":[0,16]}})",
                                 data16)),
            "more bytes than the file holds"));
  CHECK(has(parse_error(raw_file(R"({"__metadata__":{"x":1}})", "")), "__metadata__"));
}

TEST_CASE("checkpoint folders with wrong content are clear errors") {
  Model model = random_model(3);
  const std::string dir = temp_dir("bad");
  REQUIRE(save_model(dir, model).is_ok());
  auto load_error = [&]() {
    auto r = load_model(dir);
    REQUIRE_FALSE(r.is_ok());
    return r.status().message();
  };
  const std::string good_cfg = *files::read(dir + "/config.json");

  auto write_tensors = [&](std::vector<TensorRef> refs) {
    REQUIRE(write_safetensors(dir + "/model.safetensors", refs).is_ok());
  };
  std::vector<TensorRef> all;
  for (const TensorSpec& t : model.layout().tensors())
    all.push_back({t.name, t.shape, model.params().subspan(t.offset, t.size)});

  SUBCASE("missing tensor") {
    auto refs = all;
    refs.erase(refs.begin() + 6);
    write_tensors(refs);
    CHECK(has(load_error(), "missing tensor 'h.0.attn.c_proj.weight' (shape [8, 8])"));
  }
  SUBCASE("wrong shape") {
    auto refs = all;
    refs[5].shape = {4, 6};
    write_tensors(refs);
    CHECK(has(load_error(), "tensor 'h.0.attn.c_attn.bias' has shape [4, 6], expected [24]"));
  }
  SUBCASE("unexpected tensor") {
    auto refs = all;
    std::vector<float> one = {1.0f};
    refs.push_back({"h.0.mlp.dropout", {1}, one});
    write_tensors(refs);
    CHECK(has(load_error(), "unexpected tensor 'h.0.mlp.dropout'"));
  }
  SUBCASE("same tensor under both prefixes") {
    auto refs = all;
    refs.push_back({"transformer.ln_f.bias", {8}, model.tensor("ln_f.bias")});
    write_tensors(refs);
    CHECK(has(load_error(), "both with and without"));
  }
  SUBCASE("untied lm_head") {
    auto refs = all;
    std::vector<float> other(model.tensor("wte.weight").begin(), model.tensor("wte.weight").end());
    other[3] += 1.0f;
    refs.push_back({"lm_head.weight", {kCfg.vocab_size, kCfg.n_embd}, other});
    write_tensors(refs);
    CHECK(has(load_error(), "lm_head.weight differs from wte.weight"));
  }
  SUBCASE("truncated file") {
    const std::string bytes = *files::read(dir + "/model.safetensors");
    REQUIRE(files::write_atomic(dir + "/model.safetensors", bytes.substr(0, bytes.size() - 10)).is_ok());
    CHECK(has(load_error(), "fall outside the data buffer"));
  }
  SUBCASE("config without n_head") {
    auto j = nlohmann::json::parse(good_cfg);
    j.erase("n_head");
    REQUIRE(files::write_atomic(dir + "/config.json", j.dump()).is_ok());
    CHECK(has(load_error(), "missing integer field \"n_head\""));
  }
  SUBCASE("config with another activation") {
    auto j = nlohmann::json::parse(good_cfg);
    j["activation_function"] = "relu";
    REQUIRE(files::write_atomic(dir + "/config.json", j.dump()).is_ok());
    CHECK(has(load_error(), "gelu_new"));
  }
  SUBCASE("config that is not JSON") {
    REQUIRE(files::write_atomic(dir + "/config.json", "{n_layer: 2").is_ok());
    CHECK(has(load_error(), "not valid JSON"));
  }
  SUBCASE("n_embd not a multiple of n_head") {
    auto j = nlohmann::json::parse(good_cfg);
    j["n_head"] = 3;
    REQUIRE(files::write_atomic(dir + "/config.json", j.dump()).is_ok());
    CHECK(has(load_error(), "multiple of n_head"));
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("fine-tuned weights with a head save and load back exactly") {
  const std::vector<TensorSpec> extras = {{"head.weight", {8, 5}, 0, 0}, {"head.bias", {5}, 0, 0}};
  auto m = Model::create(kCfg, extras);
  REQUIRE(m.is_ok());
  Rng rng(8);
  m->init_random(rng, 0.5f);
  REQUIRE(m->set_trainable_blocks(1).is_ok());
  for (float& v : m->trainable_params()) v += static_cast<float>(rng.normal(0.0, 0.1));
  const std::string dir = temp_dir("head");
  REQUIRE(save_model(dir, *m).is_ok());
  auto back = load_model(dir, extras);
  REQUIRE_MESSAGE(back.is_ok(), back.status().message());
  CHECK(std::equal(back->params().begin(), back->params().end(), m->params().begin()));
  // The head's tensors are unknown to a model that does not declare them.
  auto plain = load_model(dir);
  REQUIRE_FALSE(plain.is_ok());
  CHECK(has(plain.status().message(), "unexpected tensor 'head."));
  std::filesystem::remove_all(dir);
}
