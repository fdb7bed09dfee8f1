// LlmConfig: which server and model an LLM client talks to, and how.
//
// Sources, later ones override earlier: defaults, the environment
// (SQUAWK_LLM_URL, SQUAWK_LLM_MODEL, SQUAWK_LLM_API = ollama|openai,
// SQUAWK_LLM_API_KEY), then CLI flags or Lua fields. When the API is not given
// it is inferred from the URL: a path ending in /v1 means the OpenAI-compatible
// API (llama.cpp server, vLLM, Ollama's /v1), anything else Ollama's native API.
#pragma once

#include <string>

#include "core/status.h"
#include "llm/retry.h"

namespace squawk::llm {

enum class Api { kOllama, kOpenAI };

const char* api_name(Api api);  // "ollama" / "openai"
Result<Api> parse_api(const std::string& name);
Api infer_api(const std::string& url);

struct LlmConfig {
  Api api = Api::kOllama;
  std::string url;             // server base URL, e.g. http://127.0.0.1:11434
  std::string model;           // e.g. qwen2.5:7b
  double temperature = 0.0;    // sampling temperature, sent on every request
  long long seed = 0;          // sampling seed, sent on every request
  int context_size = 4096;     // [tokens] context window, sent on every request
  int max_tokens = 512;        // [tokens] reply cap
  double connect_timeout_s = 5.0;  // [s]
  double timeout_s = 120.0;        // [s] whole request
  size_t max_reply_bytes = 16u << 20;  // [bytes] a whole (non-streamed) reply body
  size_t max_line_bytes = 1u << 20;    // [bytes] one line of a streamed reply
  RetryPolicy retry;
  std::string api_key;  // sent as a Bearer token when not empty

  // "ollama server http://host:11434 (model qwen2.5:7b)": the prefix of
  // every error message of a client.
  std::string describe() const;
  // Checks url (http:// or https://), model (not empty) and the numbers
  // (timeouts positive and finite, caps positive).
  Status validate() const;
};

// The configuration from the environment; kNotFound when SQUAWK_LLM_URL is
// unset or empty (no LLM configured), kInvalidArgument when it is malformed
// (the message names the variable: SQUAWK_LLM_MODEL unset, a bad URL or API).
Result<LlmConfig> config_from_env();
// What the environment says, not yet validated (flags may complete it before
// LlmConfig::validate); error only for an unknown SQUAWK_LLM_API.
Result<LlmConfig> env_fields();

}  // namespace squawk::llm
