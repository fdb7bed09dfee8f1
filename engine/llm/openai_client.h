// OpenAiClient: the OpenAI-compatible API as served by llama.cpp's server,
// vLLM and Ollama under /v1 (config.url ends in /v1).
//   chat:  POST /chat/completions {model, messages, temperature, seed, max_tokens,
//          num_ctx, stream, response_format?, grammar?}; the reply carries
//          choices[0].message.content; streaming uses server-sent events whose
//          `data:` lines carry choices[0].delta.content and end with `data: [DONE]`.
//   embed: POST /embeddings {model, input: [texts]} -> {data: [{index, embedding}]}.
// The context size travels as the extension field `num_ctx`: these servers fix
// the context at launch and ignore it, but every request states what it assumed.
// An error object ({"error": ...}, also as a `data:` line or after an
// `event: error` line mid-stream) fails the call with the server's text.
#pragma once

#include "llm/client.h"

namespace squawk::llm {

class OpenAiClient : public LlmClient {
 public:
  using LlmClient::LlmClient;
  Result<ChatReply> chat(const ChatRequest& request, const TokenSink& on_token = {}) override;
  Result<Embeddings> embed(const std::vector<std::string>& texts) override;
};

}  // namespace squawk::llm
