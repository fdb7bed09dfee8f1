#include "llm/llm_config.h"

#include <cstdio>
#include <cstdlib>

#include "core/text.h"

namespace squawk::llm {

namespace {

constexpr double kMinTimeout = 0.001;  // [s] curl counts whole milliseconds; 0 means none
constexpr double kMaxTimeout = 86400;  // [s]

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::string(text::trim(v)) : std::string();
}

}  // namespace

const char* api_name(Api api) { return api == Api::kOpenAI ? "openai" : "ollama"; }

Result<Api> parse_api(const std::string& name) {
  if (text::iequals(name, "ollama")) return Api::kOllama;
  if (text::iequals(name, "openai")) return Api::kOpenAI;
  return Status::invalid("LLM API " + text::quoted(name) + " is not one of: ollama, openai");
}

Api infer_api(const std::string& url) {
  std::string u = url;
  while (!u.empty() && u.back() == '/') u.pop_back();
  return u.size() >= 3 && u.compare(u.size() - 3, 3, "/v1") == 0 ? Api::kOpenAI : Api::kOllama;
}

std::string LlmConfig::describe() const {
  std::string s = api_name(api);
  s.append(" server ").append(url).append(" (model ").append(model.empty() ? "?" : model).append(")");
  return s;
}

Status LlmConfig::validate() const {
  if (!text::starts_with_ci(url, "http://") && !text::starts_with_ci(url, "https://"))
    return Status::invalid("LLM URL " + text::quoted(url) +
                           " is not an http:// or https:// address (e.g. http://127.0.0.1:11434)");
  if (model.empty())
    return Status::invalid("LLM at " + url +
                           ": no model named: set SQUAWK_LLM_MODEL (or --llm-model, or model= in Lua) to a model the server has");
  if (context_size <= 0 || max_tokens <= 0)
    return Status::invalid(describe() + ": context size and max tokens must be positive");
  for (const double t : {timeout_s, connect_timeout_s}) {
    if (!(t >= kMinTimeout && t <= kMaxTimeout)) {
      char shown[32];
      std::snprintf(shown, sizeof shown, "%g", t);
      return Status::invalid(describe() + ": timeout " + shown + " s is not within [0.001, 86400] seconds");
    }
  }
  if (max_reply_bytes == 0 || max_line_bytes == 0)
    return Status::invalid(describe() + ": reply size caps must be positive");
  if (retry.max_attempts < 1) return Status::invalid(describe() + ": retries must be at least 1 attempt");
  return Status::ok();
}

Result<LlmConfig> env_fields() {
  LlmConfig c;
  c.url = env("SQUAWK_LLM_URL");
  c.model = env("SQUAWK_LLM_MODEL");
  c.api_key = env("SQUAWK_LLM_API_KEY");
  const std::string api = env("SQUAWK_LLM_API");
  if (api.empty()) {
    c.api = infer_api(c.url);
  } else {
    auto parsed = parse_api(api);
    if (!parsed) return parsed.status().with_context("SQUAWK_LLM_API");
    c.api = *parsed;
  }
  return c;
}

Result<LlmConfig> config_from_env() {
  SQUAWK_ASSIGN_OR_RETURN(LlmConfig c, env_fields());
  if (c.url.empty()) return Status::not_found("no LLM configured (SQUAWK_LLM_URL is not set)");
  SQUAWK_RETURN_IF_ERROR(c.validate().with_context("SQUAWK_LLM_*"));
  return c;
}

}  // namespace squawk::llm
