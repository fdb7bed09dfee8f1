#include "llm/openai_client.h"

#include <map>

#include "core/text.h"
#include "llm/exchange.h"
#include "llm/messages_json.h"

namespace squawk::llm {

namespace {

// `text` is the reply (or event) the error object came in.
Status error_object(const LlmConfig& config, std::string_view text) {
  return Status::unavailable(config.describe() + ": server error: " + server_error_text(std::string(text)));
}

// Reads model, usage and finish_reason of a reply or stream chunk `j` (an object).
Status read_meta(const LlmConfig& config, const nlohmann::json& j, ChatReply& reply) {
  SQUAWK_ASSIGN_OR_RETURN(reply.model, string_field(config, j, "model", reply.model));
  const auto usage = j.find("usage");
  if (usage != j.end() && usage->is_object()) {
    SQUAWK_ASSIGN_OR_RETURN(reply.prompt_tokens, count_field(config, *usage, "prompt_tokens"));
    SQUAWK_ASSIGN_OR_RETURN(reply.completion_tokens, count_field(config, *usage, "completion_tokens"));
  }
  return Status::ok();
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
        return error_object(config_, value);
      if (!j.is_object()) return Status::corruption(config_.describe() + ": event is not an object");
      SQUAWK_RETURN_IF_ERROR(read_meta(config_, j, reply));
      const auto choices = j.find("choices");
      if (choices == j.end() || !choices->is_array() || choices->empty())
        return Status::ok();  // e.g. a final usage-only chunk
      const auto& c = (*choices)[0];
      if (!c.is_object()) return Status::corruption(config_.describe() + ": choices[0] is not an object");
      const auto delta = c.find("delta");
      if (delta != c.end() && delta->is_object()) {
        SQUAWK_ASSIGN_OR_RETURN(const auto piece, string_field(config_, *delta, "content", ""));
        reply.content += piece;
        if (!piece.empty()) on_token(piece);
      }
      SQUAWK_ASSIGN_OR_RETURN(reply.finish_reason,
                              string_field(config_, c, "finish_reason", reply.finish_reason));
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
  if (j.is_object() && j.contains("error")) return error_object(config_, ex.body);
  if (!j.is_object() || !j.contains("choices") || !j["choices"].is_array() || j["choices"].empty())
    return Status::corruption(config_.describe() + ": reply has no `choices`");
  const auto& c = j["choices"][0];
  const auto message = c.is_object() ? c.find("message") : c.end();
  if (!c.is_object() || message == c.end() || !message->is_object())
    return Status::corruption(config_.describe() + ": choices[0] has no `message`");
  SQUAWK_ASSIGN_OR_RETURN(reply.content, string_field(config_, *message, "content", ""));
  SQUAWK_ASSIGN_OR_RETURN(reply.finish_reason, string_field(config_, c, "finish_reason", ""));
  SQUAWK_RETURN_IF_ERROR(read_meta(config_, j, reply));
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
  if (by_index.size() != texts.size())
    return Status::corruption(config_.describe() + ": asked for " + std::to_string(texts.size()) +
                              " embeddings, got " + std::to_string(by_index.size()) + " distinct indices");
  if (!by_index.empty() && by_index.rbegin()->first != texts.size() - 1)
    return Status::corruption(config_.describe() + ": embedding indices run to " +
                              std::to_string(by_index.rbegin()->first) + ", expected 0 to " +
                              std::to_string(texts.size() - 1));
  Embeddings out;
  for (auto& [i, v] : by_index) out.push_back(std::move(v));
  return out;
}

}  // namespace squawk::llm
