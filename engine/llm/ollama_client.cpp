#include "llm/ollama_client.h"

#include "llm/exchange.h"
#include "llm/messages_json.h"

namespace squawk::llm {

namespace {

// Folds one reply object `j` (a whole reply or one stream line, parsed from
// `text`) into `reply`. Returns true when the object says done.
Result<bool> absorb(const LlmConfig& config, std::string_view text, const nlohmann::json& j,
                    ChatReply& reply, const TokenSink& on_token) {
  if (!j.is_object())
    return Status::corruption(config.describe() + ": reply is not a JSON object");
  if (j.contains("error"))
    return Status::unavailable(config.describe() + ": server error: " +
                               server_error_text(std::string(text)));
  const auto m = j.find("message");
  if (m != j.end() && m->is_object()) {
    SQUAWK_ASSIGN_OR_RETURN(const auto piece, string_field(config, *m, "content", ""));
    reply.content += piece;
    if (on_token && !piece.empty()) on_token(piece);
  }
  SQUAWK_ASSIGN_OR_RETURN(reply.model, string_field(config, j, "model", reply.model));
  SQUAWK_ASSIGN_OR_RETURN(const bool done, bool_field(config, j, "done"));
  if (done) {
    SQUAWK_ASSIGN_OR_RETURN(reply.finish_reason, string_field(config, j, "done_reason", "stop"));
    SQUAWK_ASSIGN_OR_RETURN(reply.prompt_tokens, count_field(config, j, "prompt_eval_count"));
    SQUAWK_ASSIGN_OR_RETURN(reply.completion_tokens, count_field(config, j, "eval_count"));
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
      SQUAWK_ASSIGN_OR_RETURN(bool d, absorb(config_, line, j, reply, on_token));
      done = done || d;
      return Status::ok();
    };
  }
  SQUAWK_ASSIGN_OR_RETURN(auto ex, post_json(*transport_, config_, "/api/chat", body, on_line));
  reply.attempts = ex.attempts;
  if (!stream) {
    SQUAWK_ASSIGN_OR_RETURN(auto j, parse_reply_json(config_, ex.body));
    SQUAWK_ASSIGN_OR_RETURN(done, absorb(config_, ex.body, j, reply, on_token));
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
