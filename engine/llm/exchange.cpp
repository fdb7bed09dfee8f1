#include "llm/exchange.h"

#include <algorithm>

#include "core/text.h"

namespace squawk::llm {

namespace {

constexpr size_t kQuoteChars = 160;     // how much of a bad body an error quotes
constexpr size_t kMaxErrorBody = 65536;  // [bytes] of a non-2xx body kept for its message

// True when `text` nests arrays/objects at most `max` deep (strings skipped).
bool depth_within(std::string_view text, int max) {
  int depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > max) return false;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return true;
}

nlohmann::json parse_bounded(std::string_view text) {
  if (!depth_within(text, kMaxReplyDepth)) return nlohmann::json(nlohmann::json::value_t::discarded);
  return nlohmann::json::parse(text, nullptr, false);
}

std::string shorten(std::string_view s) {
  std::string out(s.substr(0, kQuoteChars));
  if (s.size() > kQuoteChars) out += "...";
  return out;
}

// Splits a byte stream into lines, dropping "\n" and a trailing "\r".
// A line longer than `max_line` bytes is an error.
class LineSplitter {
 public:
  LineSplitter(std::string who, size_t max_line) : who_(std::move(who)), max_line_(max_line) {}
  Status feed(std::string_view chunk, const LineHandler& fn) {
    buf_.append(chunk);
    size_t start = 0;
    for (size_t nl; (nl = buf_.find('\n', start)) != std::string::npos; start = nl + 1) {
      if (nl - start > max_line_) return too_long();
      Status st = fn(strip(std::string_view(buf_).substr(start, nl - start)));
      if (!st.is_ok()) return st;
    }
    buf_.erase(0, start);
    if (buf_.size() > max_line_) return too_long();
    return Status::ok();
  }
  Status finish(const LineHandler& fn) {
    if (buf_.empty()) return Status::ok();
    std::string rest = std::move(buf_);
    buf_.clear();
    return fn(strip(rest));
  }

 private:
  Status too_long() const {
    return Status::io_error(who_ + ": a reply line is longer than " + std::to_string(max_line_) +
                                      " bytes (raise max_line_bytes)");
  }
  static std::string_view strip(std::string_view s) {
    if (!s.empty() && s.back() == '\r') s.remove_suffix(1);
    return s;
  }
  std::string who_;
  size_t max_line_;
  std::string buf_;
};

}  // namespace

std::string server_error_text(const std::string& body) {
  const auto j = parse_bounded(body);
  if (j.is_object()) {
    if (j.contains("error")) {
      const auto& e = j["error"];
      if (e.is_string()) return e.get<std::string>();
      if (e.is_object() && e.contains("message") && e["message"].is_string())
        return e["message"].get<std::string>();
    }
    if (j.contains("message") && j["message"].is_string()) return j["message"].get<std::string>();
  }
  const auto trimmed = text::trim(body);
  return trimmed.empty() ? std::string("(empty body)") : shorten(trimmed);
}

Result<nlohmann::json> parse_reply_json(const LlmConfig& config, std::string_view text) {
  if (!depth_within(text, kMaxReplyDepth))
    return Status::corruption(config.describe() + ": reply JSON nests deeper than " +
                              std::to_string(kMaxReplyDepth) + " levels: " + text::quoted(shorten(text)));
  auto j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded())
    return Status::corruption(config.describe() + ": malformed JSON in reply: " +
                              text::quoted(shorten(text)));
  return j;
}

namespace {

Status field_type_error(const LlmConfig& config, const char* key, const char* expected,
                        const nlohmann::json& v) {
  return Status::corruption(config.describe() + ": reply field `" + key + "` is " + v.type_name() +
                            ", expected " + expected);
}

}  // namespace

Result<std::string> string_field(const LlmConfig& config, const nlohmann::json& j, const char* key,
                                 std::string fallback) {
  const auto it = j.find(key);
  if (it == j.end() || it->is_null()) return fallback;
  if (!it->is_string()) return field_type_error(config, key, "a string", *it);
  return it->get<std::string>();
}

Result<long> count_field(const LlmConfig& config, const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  if (it == j.end() || it->is_null()) return 0L;
  if (!it->is_number_integer() || it->get<long long>() < 0)
    return field_type_error(config, key, "a count (integer >= 0)", *it);
  return static_cast<long>(it->get<long long>());
}

Result<bool> bool_field(const LlmConfig& config, const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  if (it == j.end() || it->is_null()) return false;
  if (!it->is_boolean()) return field_type_error(config, key, "true or false", *it);
  return it->get<bool>();
}

Result<ExchangeResult> post_json(HttpTransport& transport, const LlmConfig& config,
                                 const std::string& path, const nlohmann::json& body,
                                 const LineHandler& on_line) {
  HttpRequest req;
  req.url = config.url + path;
  try {
    req.body = body.dump();
  } catch (const nlohmann::json::type_error& e) {  // 316: a string in the request is not UTF-8
    std::string what = e.what();
    if (const auto at = what.find("] "); at != std::string::npos) what.erase(0, at + 2);
    return Status::invalid(config.describe() + ": the request text is not valid UTF-8 (" + what + ")");
  }
  req.headers = {"Content-Type: application/json", "Accept: application/json, text/event-stream"};
  if (!config.api_key.empty()) req.headers.push_back("Authorization: Bearer " + config.api_key);
  req.connect_timeout_s = config.connect_timeout_s;
  req.timeout_s = config.timeout_s;

  const std::string who = config.describe();
  for (int attempt = 1;; ++attempt) {
    ExchangeResult out;
    out.attempts = attempt;
    std::string error_body;
    LineSplitter lines(who, config.max_line_bytes);
    Status line_status;
    Status size_status;
    bool handed_on = false;
    const LineHandler counted = [&](std::string_view line) {
      handed_on = true;
      return on_line(line);
    };
    auto sink = [&](long status, std::string_view chunk) {
      if (status < 200 || status > 299) {
        error_body.append(chunk.substr(0, kMaxErrorBody - std::min(kMaxErrorBody, error_body.size())));
        return error_body.size() < kMaxErrorBody;  // enough to quote the server
      }
      if (!on_line) {
        if (out.body.size() + chunk.size() > config.max_reply_bytes) {
          size_status = Status::io_error(
              who + ": the reply is longer than " + std::to_string(config.max_reply_bytes) +
              " bytes (raise max_reply_bytes)");
          return false;
        }
        out.body.append(chunk);
        return true;
      }
      line_status = lines.feed(chunk, counted);
      return line_status.is_ok();
    };
    auto posted = transport.post(req, sink);
    if (!line_status.is_ok()) return line_status;
    if (!size_status.is_ok()) return size_status;
    const long http = posted ? *posted : 0;
    const Status transport_status = posted ? Status::ok() : posted.status();

    std::string failure;
    if (!posted) {
      failure = transport_status.message();
      if (handed_on) failure += " (the stream broke after it had started)";
    } else if (http < 200 || http > 299) {
      failure = "HTTP " + std::to_string(http) + ": " + server_error_text(error_body);
    } else {
      if (on_line) SQUAWK_RETURN_IF_ERROR(lines.finish(counted));
      return out;
    }
    const bool retry = !handed_on && is_retryable(transport_status, http);
    if (retry && attempt < config.retry.max_attempts) {
      config.retry.wait_before(attempt + 1);
      continue;
    }
    std::string msg = who + ": " + failure;
    if (attempt > 1) msg += " (after " + std::to_string(attempt) + " attempts)";
    if (!posted) return Status::error(transport_status.code(), msg);
    return http >= 500 ? Status::unavailable(msg) : Status::invalid(msg);
  }
}

}  // namespace squawk::llm
