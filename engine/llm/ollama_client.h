// OllamaClient: Ollama's native API.
//   chat:  POST /api/chat  {model, messages, stream, format?, options{temperature, seed,
//          num_ctx, num_predict}}; the reply (or each NDJSON line when streaming) carries
//          message.content, and the last line has done: true with the token counts.
//   embed: POST /api/embed {model, input: [texts], options} -> {embeddings: [[...]]}.
// An {"error": "..."} object, also as a line in the middle of a stream, fails
// the call with the server's text.
#pragma once

#include "llm/client.h"

namespace squawk::llm {

class OllamaClient : public LlmClient {
 public:
  using LlmClient::LlmClient;
  Result<ChatReply> chat(const ChatRequest& request, const TokenSink& on_token = {}) override;
  Result<Embeddings> embed(const std::vector<std::string>& texts) override;

 private:
  nlohmann::json options() const;
};

}  // namespace squawk::llm
