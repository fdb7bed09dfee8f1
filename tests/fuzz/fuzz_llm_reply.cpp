// libFuzzer target: LLM server replies, both APIs, streamed and not.
// The input's first byte picks the API, streaming, the HTTP status and where
// the body is cut into chunks; the rest is the body a hostile server sends.
// Invariants: no crash, no sanitizer report, no exception; a failed reply
// is a Status with a message that names the server.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <string_view>

#include "llm/client.h"

using namespace squawk;

namespace {

class FuzzTransport : public llm::HttpTransport {
 public:
  FuzzTransport(long status, std::string body, size_t cut) : status_(status), body_(std::move(body)), cut_(cut) {}
  Result<long> post(const llm::HttpRequest&, const llm::BodySink& sink) override {
    const std::string_view b(body_);
    const size_t cut = body_.empty() ? 0 : cut_ % (body_.size() + 1);
    if (sink(status_, b.substr(0, cut))) sink(status_, b.substr(cut));
    return status_;
  }

 private:
  long status_;
  std::string body_;
  size_t cut_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  const uint8_t mode = data[0];
  const size_t cut = data[1];
  std::string body(reinterpret_cast<const char*>(data + 2), size - 2);
  llm::LlmConfig c;
  c.api = (mode & 1) ? llm::Api::kOpenAI : llm::Api::kOllama;
  c.url = "http://127.0.0.1:1";
  c.model = "m";
  c.retry.max_attempts = 1;
  c.max_reply_bytes = 4096;
  c.max_line_bytes = 1024;
  const long status = (mode & 4) ? 500 : ((mode & 8) ? 404 : 200);
  auto client = llm::make_client(c, std::make_shared<FuzzTransport>(status, body, cut));
  if (!client) std::abort();
  const std::string who = c.describe();
  auto expect_named = [&](const Status& st) {
    if (!st.is_ok() && st.message().find(who) == std::string::npos) std::abort();
  };
  if (mode & 16) {
    auto e = (*client)->embed({"a", "b"});
    expect_named(e.status());
    if (e && e->size() != 2) std::abort();
    return 0;
  }
  llm::ChatRequest r;
  r.messages = {{"user", "climb"}};
  std::string streamed;
  auto reply = (mode & 2) ? (*client)->chat(r, [&](std::string_view t) { streamed.append(t); })
                          : (*client)->chat(r);
  expect_named(reply.status());
  if (reply && (mode & 2) && reply->content != streamed) std::abort();
  return 0;
}
