#include "llm/exchange.h"

#include "core/text.h"

namespace squawk::llm {

namespace {

constexpr size_t kQuoteChars = 160;  // how much of a bad body an error quotes

std::string shorten(std::string_view s) {
  std::string out(s.substr(0, kQuoteChars));
  if (s.size() > kQuoteChars) out += "...";
  return out;
}

// Splits a byte stream into lines, dropping "\n" and a trailing "\r".
class LineSplitter {
 public:
  Status feed(std::string_view chunk, const LineHandler& fn) {
    buf_.append(chunk);
    size_t start = 0;
    for (size_t nl; (nl = buf_.find('\n', start)) != std::string::npos; start = nl + 1) {
      Status st = fn(strip(std::string_view(buf_).substr(start, nl - start)));
      if (!st.is_ok()) return st;
    }
    buf_.erase(0, start);
    return Status::ok();
  }
  Status finish(const LineHandler& fn) {
    if (buf_.empty()) return Status::ok();
    std::string rest = std::move(buf_);
    buf_.clear();
    return fn(strip(rest));
  }

 private:
  static std::string_view strip(std::string_view s) {
    if (!s.empty() && s.back() == '\r') s.remove_suffix(1);
    return s;
  }
  std::string buf_;
};

}  // namespace

std::string server_error_text(const std::string& body) {
  auto j = nlohmann::json::parse(body, nullptr, false);
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
  auto j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded())
    return Status::corruption(config.describe() + ": malformed JSON in reply: " +
                              text::quoted(shorten(text)));
  return j;
}

Result<ExchangeResult> post_json(HttpTransport& transport, const LlmConfig& config,
                                 const std::string& path, const nlohmann::json& body,
                                 const LineHandler& on_line) {
  HttpRequest req;
  req.url = config.url + path;
  req.body = body.dump();
  req.headers = {"Content-Type: application/json", "Accept: application/json, text/event-stream"};
  if (!config.api_key.empty()) req.headers.push_back("Authorization: Bearer " + config.api_key);
  req.connect_timeout_s = config.connect_timeout_s;
  req.timeout_s = config.timeout_s;

  const std::string who = config.describe();
  for (int attempt = 1;; ++attempt) {
    ExchangeResult out;
    out.attempts = attempt;
    std::string error_body;
    LineSplitter lines;
    Status line_status;
    bool handed_on = false;
    const LineHandler counted = [&](std::string_view line) {
      handed_on = true;
      return on_line(line);
    };
    auto sink = [&](long status, std::string_view chunk) {
      if (status < 200 || status > 299) {
        error_body.append(chunk);
        return true;
      }
      if (!on_line) {
        out.body.append(chunk);
        return true;
      }
      line_status = lines.feed(chunk, counted);
      return line_status.is_ok();
    };
    auto posted = transport.post(req, sink);
    if (!line_status.is_ok()) return line_status;
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
