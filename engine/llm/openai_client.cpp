#include "llm/openai_client.h"

#include <map>

#include "core/text.h"
#include "llm/exchange.h"
#include "llm/messages_json.h"

namespace squawk::llm {

namespace {

Status error_object(const LlmConfig& config, const nlohmann::json& j) {
  return Status::unavailable(config.describe() + ": server error: " + server_error_text(j.dump()));
}

void read_usage(const nlohmann::json& j, ChatReply& reply) {
  if (!j.contains("usage") || !j["usage"].is_object()) return;
  reply.prompt_tokens = j["usage"].value("prompt_tokens", 0L);
  reply.completion_tokens = j["usage"].value("completion_tokens", 0L);
}

}  // namespace

Result<ChatReply> OpenAiClient::chat(const ChatRequest& request, const TokenSink& on_token) {
  const bool stream = static_cast<bool>(on_token);
  nlohmann::json body = {{"model", config_.model},
                         {"messages", messages_json(request.messages)},
                         {"temperature", config_.temperature},
                         {"seed", config_.seed},
                         {"max_tokens", config_.max_tokens},
                         {"num_ctx", config_.context_size},
                         {"stream", stream}};
  if (!request.json_schema.is_null())
    body["response_format"] = {
        {"type", "json_schema"},
        {"json_schema", {{"name", "reply"}, {"strict", true}, {"schema", request.json_schema}}}};
  if (!request.grammar.empty()) body["grammar"] = request.grammar;

  ChatReply reply;
  bool done = false;
  bool error_event = false;
  LineHandler on_line;
  if (stream) {
    on_line = [&](std::string_view line) -> Status {
      if (line.empty() || line.front() == ':') return Status::ok();  // separator / comment
      const auto colon = line.find(':');
      const std::string_view field = line.substr(0, colon);
      std::string_view value = colon == std::string_view::npos ? "" : line.substr(colon + 1);
      value = text::trim(value);
      if (field == "event") {
        error_event = value == "error";
        return Status::ok();
      }
      if (field != "data" && field != "error") return Status::ok();
      if (value == "[DONE]") {
        done = true;
        return Status::ok();
      }
      SQUAWK_ASSIGN_OR_RETURN(auto j, parse_reply_json(config_, value));
      if (field == "error" || error_event || (j.is_object() && j.contains("error")))
        return error_object(config_, j);
      if (!j.is_object()) return Status::corruption(config_.describe() + ": event is not an object");
      if (j.contains("model") && j["model"].is_string()) reply.model = j["model"].get<std::string>();
      read_usage(j, reply);
      if (!j.contains("choices") || !j["choices"].is_array() || j["choices"].empty())
        return Status::ok();  // e.g. a final usage-only chunk
      const auto& c = j["choices"][0];
      if (c.contains("delta") && c["delta"].is_object() && c["delta"].contains("content") &&
          c["delta"]["content"].is_string()) {
        const auto piece = c["delta"]["content"].get<std::string>();
        reply.content += piece;
        if (!piece.empty()) on_token(piece);
      }
      if (c.contains("finish_reason") && c["finish_reason"].is_string())
        reply.finish_reason = c["finish_reason"].get<std::string>();
      return Status::ok();
    };
  }
  SQUAWK_ASSIGN_OR_RETURN(auto ex,
                          post_json(*transport_, config_, "/chat/completions", body, on_line));
  reply.attempts = ex.attempts;
  if (stream) {
    if (!done)
      return Status::corruption(config_.describe() + ": the event stream ended before data: [DONE]");
    return reply;
  }
  SQUAWK_ASSIGN_OR_RETURN(auto j, parse_reply_json(config_, ex.body));
  if (j.is_object() && j.contains("error")) return error_object(config_, j);
  if (!j.is_object() || !j.contains("choices") || !j["choices"].is_array() || j["choices"].empty())
    return Status::corruption(config_.describe() + ": reply has no `choices`");
  const auto& c = j["choices"][0];
  if (!c.contains("message") || !c["message"].is_object())
    return Status::corruption(config_.describe() + ": choices[0] has no `message`");
  const auto& content = c["message"]["content"];
  if (content.is_string()) reply.content = content.get<std::string>();
  if (c.contains("finish_reason") && c["finish_reason"].is_string())
    reply.finish_reason = c["finish_reason"].get<std::string>();
  if (j.contains("model") && j["model"].is_string()) reply.model = j["model"].get<std::string>();
  read_usage(j, reply);
  return reply;
}

Result<Embeddings> OpenAiClient::embed(const std::vector<std::string>& texts) {
  nlohmann::json body = {{"model", config_.model}, {"input", texts}};
  SQUAWK_ASSIGN_OR_RETURN(auto ex, post_json(*transport_, config_, "/embeddings", body, {}));
  SQUAWK_ASSIGN_OR_RETURN(auto j, parse_reply_json(config_, ex.body));
  if (!j.is_object() || !j.contains("data") || !j["data"].is_array())
    return Status::corruption(config_.describe() + ": embeddings reply has no `data` array");
  std::map<size_t, std::vector<float>> by_index;
  size_t next = 0;
  for (const auto& item : j["data"]) {
    const size_t idx = item.is_object() && item.contains("index") && item["index"].is_number_unsigned()
                           ? item["index"].get<size_t>()
                           : next;
    ++next;
    if (!item.is_object() || !item.contains("embedding"))
      return Status::corruption(config_.describe() + ": data item without `embedding`");
    SQUAWK_ASSIGN_OR_RETURN(auto v, float_vector(config_, item["embedding"],
                                                 "data[" + std::to_string(idx) + "].embedding"));
    by_index[idx] = std::move(v);
  }
  if (by_index.size() != texts.size() || (!by_index.empty() && by_index.rbegin()->first != texts.size() - 1))
    return Status::corruption(config_.describe() + ": asked for " + std::to_string(texts.size()) +
                              " embeddings, got " + std::to_string(by_index.size()));
  Embeddings out;
  for (auto& [i, v] : by_index) out.push_back(std::move(v));
  return out;
}

}  // namespace squawk::llm
