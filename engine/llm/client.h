// LlmClient: one chat/embedding interface over the two wire protocols.
//
// Contract:
// - chat() sends model, temperature, seed and context size on every request;
//   with a TokenSink it streams and hands each content fragment to the sink as
//   it arrives, and the returned reply holds the whole text either way.
// - ChatRequest::json_schema (a JSON schema object) asks the server to
//   constrain the reply (Ollama: `format`; OpenAI-compatible servers:
//   `response_format` json_schema). ChatRequest::grammar is a GBNF grammar,
//   honoured by llama.cpp's server; Ollama's native API has no grammar and
//   says so with kUnsupported.
// - Transport failures and 5xx replies are retried per config().retry, but
//   never once streamed text has reached the sink. 4xx replies, error objects
//   (also mid-stream) and malformed JSON fail at once.
// - Every error message starts with config().describe(): which API, server
//   and model, then what happened.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/status.h"
#include "llm/http_transport.h"
#include "llm/llm_config.h"

namespace squawk::llm {

struct Message {
  std::string role;  // "system", "user" or "assistant"
  std::string content;
};

struct ChatRequest {
  std::vector<Message> messages;
  nlohmann::json json_schema;  // null: free text
  std::string grammar;         // GBNF; empty: none
};

struct ChatReply {
  std::string content;
  std::string model;          // as the server reports it
  std::string finish_reason;  // "stop", "length", ...
  long prompt_tokens = 0;
  long completion_tokens = 0;
  int attempts = 1;  // HTTP attempts it took
};

using TokenSink = std::function<void(std::string_view fragment)>;
using Embeddings = std::vector<std::vector<float>>;

class LlmClient {
 public:
  LlmClient(LlmConfig config, std::shared_ptr<HttpTransport> transport);
  virtual ~LlmClient() = default;

  virtual Result<ChatReply> chat(const ChatRequest& request, const TokenSink& on_token = {}) = 0;
  // One vector per input text, in input order.
  virtual Result<Embeddings> embed(const std::vector<std::string>& texts) = 0;

  const LlmConfig& config() const { return config_; }

 protected:
  LlmConfig config_;
  std::shared_ptr<HttpTransport> transport_;
};

// A client for config.api; a null transport means a CurlTransport.
// Fails when the configuration does not validate.
Result<std::unique_ptr<LlmClient>> make_client(LlmConfig config,
                                               std::shared_ptr<HttpTransport> transport = nullptr);

}  // namespace squawk::llm
