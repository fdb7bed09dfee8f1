// One JSON POST to an LLM server with the configured timeouts, headers and
// retries; shared by the Ollama and OpenAI clients.
//
// Contract: posts `body` to config.url + path. When `on_line` is set and the
// server answers 2xx, every complete body line (without its line ending) goes
// to on_line as it arrives; a non-ok Status from on_line ends the exchange
// with that Status and no retry. Otherwise the whole 2xx body comes back.
// Bodies longer than config.max_reply_bytes, and stream lines longer than
// config.max_line_bytes, end the exchange with kIOError (error
// bodies are read up to kMaxErrorBody bytes). Non-2xx replies fail with the
// server's own error text; transport failures
// and 5xx are retried per config.retry while no line has been handed on.
// Every error message starts with config.describe().
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/status.h"
#include "llm/http_transport.h"
#include "llm/llm_config.h"

namespace squawk::llm {

struct ExchangeResult {
  std::string body;  // the whole body when not streamed line by line
  int attempts = 1;
};

using LineHandler = std::function<Status(std::string_view line)>;

Result<ExchangeResult> post_json(HttpTransport& transport, const LlmConfig& config,
                                 const std::string& path, const nlohmann::json& body,
                                 const LineHandler& on_line);

// Deepest nesting of arrays/objects a reply may have; deeper replies are
// refused before parsing (a recursive dump or walk could overflow the stack).
inline constexpr int kMaxReplyDepth = 64;

// The message inside a server's error body: {"error":"..."},
// {"error":{"message":"..."}} or {"message":"..."}; else the body, shortened.
std::string server_error_text(const std::string& body);

// Parses `text` as JSON or fails with kCorruption naming the server and
// quoting the start of the text (also when nested deeper than kMaxReplyDepth).
Result<nlohmann::json> parse_reply_json(const LlmConfig& config, std::string_view text);

// Typed fields of a reply object `j`: `fallback` when absent or null, the
// value when it has the expected type, else kCorruption naming the field.
Result<std::string> string_field(const LlmConfig& config, const nlohmann::json& j, const char* key,
                                 std::string fallback);
Result<long> count_field(const LlmConfig& config, const nlohmann::json& j, const char* key);
Result<bool> bool_field(const LlmConfig& config, const nlohmann::json& j, const char* key);

}  // namespace squawk::llm
