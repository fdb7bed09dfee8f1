#include "llm/ollama_client.h"

#include "llm/exchange.h"
#include "llm/messages_json.h"

namespace squawk::llm {

namespace {

// Folds one reply object (whole reply or one stream line) into `reply`.
// Returns true when the object says done.
Result<bool> absorb(const LlmConfig& config, const nlohmann::json& j, ChatReply& reply,
                    const TokenSink& on_token) {
  if (!j.is_object())
    return Status::corruption(config.describe() + ": reply is not a JSON object");
  if (j.contains("error"))
    return Status::unavailable(config.describe() + ": server error: " + server_error_text(j.dump()));
  if (j.contains("message") && j["message"].is_object()) {
    const auto& m = j["message"];
    if (m.contains("content") && m["content"].is_string()) {
      const auto piece = m["content"].get<std::string>();
      reply.content += piece;
      if (on_token && !piece.empty()) on_token(piece);
    }
  }
  if (j.contains("model") && j["model"].is_string()) reply.model = j["model"].get<std::string>();
  const bool done = j.value("done", false);
  if (done) {
    reply.finish_reason = j.value("done_reason", std::string("stop"));
    reply.prompt_tokens = j.value("prompt_eval_count", 0L);
    reply.completion_tokens = j.value("eval_count", 0L);
  }
  return done;
}

}  // namespace

nlohmann::json OllamaClient::options() const {
  return {{"temperature", config_.temperature},
          {"seed", config_.seed},
          {"num_ctx", config_.context_size},
          {"num_predict", config_.max_tokens}};
}

Result<ChatReply> OllamaClient::chat(const ChatRequest& request, const TokenSink& on_token) {
  if (!request.grammar.empty())
    return Status::unsupported(config_.describe() +
                               ": Ollama's native API has no grammar option; use a JSON schema, "
                               "or llama.cpp's server through the openai API");
  const bool stream = static_cast<bool>(on_token);
  nlohmann::json body = {{"model", config_.model},
                         {"messages", messages_json(request.messages)},
                         {"stream", stream},
                         {"options", options()}};
  if (!request.json_schema.is_null()) body["format"] = request.json_schema;

  ChatReply reply;
  bool done = false;
  LineHandler on_line;
  if (stream) {
    on_line = [&](std::string_view line) -> Status {
      if (line.empty()) return Status::ok();
      SQUAWK_ASSIGN_OR_RETURN(auto j, parse_reply_json(config_, line));
      SQUAWK_ASSIGN_OR_RETURN(bool d, absorb(config_, j, reply, on_token));
      done = done || d;
      return Status::ok();
    };
  }
  SQUAWK_ASSIGN_OR_RETURN(auto ex, post_json(*transport_, config_, "/api/chat", body, on_line));
  reply.attempts = ex.attempts;
  if (!stream) {
    SQUAWK_ASSIGN_OR_RETURN(auto j, parse_reply_json(config_, ex.body));
    SQUAWK_ASSIGN_OR_RETURN(done, absorb(config_, j, reply, on_token));
    if (!j.contains("message"))
      return Status::corruption(config_.describe() + ": reply has no `message`");
  }
  if (!done)
    return Status::corruption(config_.describe() +
                              ": the reply ended before an object with done: true");
  return reply;
}

Result<Embeddings> OllamaClient::embed(const std::vector<std::string>& texts) {
  nlohmann::json body = {{"model", config_.model}, {"input", texts}, {"options", options()}};
  SQUAWK_ASSIGN_OR_RETURN(auto ex, post_json(*transport_, config_, "/api/embed", body, {}));
  SQUAWK_ASSIGN_OR_RETURN(auto j, parse_reply_json(config_, ex.body));
  if (!j.is_object() || !j.contains("embeddings") || !j["embeddings"].is_array())
    return Status::corruption(config_.describe() + ": embed reply has no `embeddings` array");
  const auto& arr = j["embeddings"];
  if (arr.size() != texts.size())
    return Status::corruption(config_.describe() + ": asked for " + std::to_string(texts.size()) +
                              " embeddings, got " + std::to_string(arr.size()));
  Embeddings out;
  for (size_t i = 0; i < arr.size(); ++i) {
    SQUAWK_ASSIGN_OR_RETURN(auto v, float_vector(config_, arr[i], "embeddings[" + std::to_string(i) + "]"));
    out.push_back(std::move(v));
  }
  return out;
}

}  // namespace squawk::llm
