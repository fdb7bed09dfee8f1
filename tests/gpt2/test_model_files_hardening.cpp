// Model files a hostile or broken folder may hold (issue 12 point 15): sizes
// are checked against the file before allocating, overlapping tensors and
// non-finite weights are refused.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include "core/files.h"
#include "core/rng.h"
#include "gpt2/bpe.h"
#include "gpt2/checkpoint.h"

using namespace squawk;
using namespace squawk::gpt2;

namespace {

std::string folder(const std::string& tag) {
  auto p = std::filesystem::temp_directory_path() / ("squawk_gpt2hard_" + tag + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(p);
  return p.string();
}

std::string header_file(const std::string& header, size_t data_bytes) {
  std::string out(8, '\0');
  for (int i = 0; i < 8; ++i) out[i] = static_cast<char>((header.size() >> (8 * i)) & 0xff);
  return out + header + std::string(data_bytes, '\0');
}

}  // namespace

TEST_CASE("a config far larger than its weights file fails before allocating") {
  const Config small{2, 2, 8, 16, 20, 1e-5f};
  auto m = Model::create(small);
  REQUIRE(m.is_ok());
  Rng rng(1);
  m->init_random(rng, 0.5f);
  const std::string dir = folder("big");
  REQUIRE(save_model(dir, *m).is_ok());
  // GPT-2 medium sizes (355 M parameters, 1.4 GB as float32) beside a small file.
  const Config medium{24, 16, 1024, 1024, 50257, 1e-5f};
  REQUIRE(files::write_atomic(dir + "/config.json", hf_config_json(medium)).is_ok());
  auto r = load_model(dir);
  REQUIRE_FALSE(r.is_ok());
  CHECK(r.status().message().find("config.json describes 354823168 parameters") != std::string::npos);
  // The largest config the validator accepts is refused the same way, not by bad_alloc.
  const Config absurd{256, 256, 16384, 65536, 1000000, 1e-5f};
  REQUIRE(files::write_atomic(dir + "/config.json", hf_config_json(absurd)).is_ok());
  r = load_model(dir);
  REQUIRE_FALSE(r.is_ok());
  CHECK(r.status().message().find("parameters but model.safetensors holds") != std::string::npos);
}

TEST_CASE("overlapping tensor byte ranges are refused") {
  const std::string h =
      R"({"a":{"dtype":"F32","shape":[4],"data_offsets":[0,16]},"b":{"dtype":"F32","shape":[4],"data_offsets":[8,24]}})";
  auto r = SafetensorsFile::parse(header_file(h, 24));
  REQUIRE_FALSE(r.is_ok());
  CHECK(r.status().message().find("overlap") != std::string::npos);
  const std::string ok =
      R"({"a":{"dtype":"F32","shape":[2],"data_offsets":[0,8]},"b":{"dtype":"F32","shape":[4],"data_offsets":[8,24]}})";
  CHECK(SafetensorsFile::parse(header_file(ok, 24)).is_ok());
}

TEST_CASE("NaN or infinite weights are refused with the tensor's name") {
  const Config cfg{2, 2, 8, 16, 20, 1e-5f};
  auto m = Model::create(cfg);
  REQUIRE(m.is_ok());
  Rng rng(2);
  m->init_random(rng, 0.5f);
  m->tensor("h.1.mlp.c_fc.weight")[3] = std::numeric_limits<float>::quiet_NaN();
  const std::string dir = folder("nan");
  REQUIRE(save_model(dir, *m).is_ok());
  auto r = load_model(dir);
  REQUIRE_FALSE(r.is_ok());
  CHECK(r.status().message().find("h.1.mlp.c_fc.weight' holds NaN or infinite weights") != std::string::npos);
}

TEST_CASE("a merges.txt line with a NUL byte is quoted whole in the error (point 18)") {
  auto r = Tokenizer::from_hf("{\"a\": 0, \"b\": 1}", std::string("a\0x b c\n", 8));
  REQUIRE_FALSE(r.is_ok());
  const std::string& m = r.status().message();
  CHECK(m.find('\0') == std::string::npos);
  CHECK(m.find("'a\\x00x b c' is not two tokens") != std::string::npos);
}

TEST_CASE("a device is not read as a file (point 18: /dev/zero as a corpus)") {
  auto r = files::read("/dev/zero");
  REQUIRE_FALSE(r.is_ok());
  CHECK(r.status().message().find("not a regular file") != std::string::npos);
}
