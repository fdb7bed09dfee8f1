// LLM clients against hostile servers (issue 12 points 2, 3, 11, 12, 13):
// every malformed, deep, huge or mistyped reply is a clean Status.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "llm/client.h"
#include "llm/llm_config.h"
#include "loopback_server.h"
#include "run_binary.h"

using squawk::Code;
using squawk::llm::Api;
using squawk::llm::ChatRequest;
using squawk::llm::LlmConfig;
using squawk::testing::HttpRequestSeen;
using squawk::testing::LoopbackServer;
using squawk::testing::Reply;

namespace {

LlmConfig config(const std::string& url, Api api) {
  LlmConfig c;
  c.api = api;
  c.url = api == Api::kOpenAI ? url + "/v1" : url;
  c.model = "m";
  c.connect_timeout_s = 1.0;
  c.timeout_s = 10.0;
  c.retry.max_attempts = 1;
  return c;
}

squawk::Result<squawk::llm::ChatReply> chat(const LlmConfig& c, bool stream) {
  auto client = squawk::llm::make_client(c);
  REQUIRE(client.is_ok());
  ChatRequest r;
  r.messages = {{"user", "climb"}};
  if (stream) return (*client)->chat(r, [](std::string_view) {});
  return (*client)->chat(r);
}

std::string deep_error() {
  return "{\"error\":" + std::string(100000, '[') + std::string(100000, ']') + "}";
}

Reply body(int status, const std::string& text, bool chunked) {
  Reply r = Reply::json(status, text);
  r.chunked = chunked;
  return r;
}

}  // namespace

TEST_CASE("a reply nested 100000 deep is a clean error in every API and mode (point 2)") {
  for (const int status : {200, 500}) {
    for (const Api api : {Api::kOllama, Api::kOpenAI}) {
      for (const bool stream : {false, true}) {
        std::string text = deep_error();
        if (stream && api == Api::kOpenAI && status == 200) text = "data: " + text + "\n\n";
        if (stream && api == Api::kOllama && status == 200) text += "\n";
        LoopbackServer server([&](const HttpRequestSeen&, int) { return body(status, text, stream); });
        auto reply = chat(config(server.url(), api), stream);
        CAPTURE(status);
        CAPTURE(stream);
        REQUIRE_FALSE(reply.is_ok());
        CHECK(reply.status().message().size() < 2000);
      }
    }
  }
}

TEST_CASE("openai: choices[0].message without content, or not an object (point 3)") {
  for (const std::string text : {R"({"choices":[{"message":{}}]})", R"({"choices":[1]})",
                                 R"({"choices":[{"message":{"content":7}}]})"}) {
    LoopbackServer server([&](const HttpRequestSeen&, int) { return Reply::json(200, text); });
    auto reply = chat(config(server.url(), Api::kOpenAI), false);
    CAPTURE(text);
    if (text == R"({"choices":[{"message":{}}]})") {
      REQUIRE_MESSAGE(reply.is_ok(), reply.status().message());
      CHECK(reply->content.empty());
    } else {
      REQUIRE_FALSE(reply.is_ok());
      CHECK(reply.status().code() == Code::kCorruption);
    }
  }
}

TEST_CASE("wrongly typed fields are corruption errors naming the field (point 13)") {
  struct Case {
    Api api;
    bool stream;
    std::string text;
    std::string field;
  };
  const Case cases[] = {
      {Api::kOllama, false, R"({"message":{"content":"x"},"done":"yes"})", "`done`"},
      {Api::kOllama, true, "{\"message\":{\"content\":\"x\"},\"done\":\"yes\"}\n", "`done`"},
      {Api::kOllama, false, R"({"message":{"content":"x"},"done":true,"eval_count":"x"})", "`eval_count`"},
      {Api::kOllama, false, R"({"message":{"content":5},"done":true})", "`content`"},
      {Api::kOpenAI, false,
       R"({"choices":[{"message":{"content":"x"}}],"usage":{"prompt_tokens":"x"}})", "`prompt_tokens`"},
      {Api::kOpenAI, false, R"({"choices":[{"message":{"content":"x"},"finish_reason":3}]})",
       "`finish_reason`"},
      {Api::kOpenAI, true,
       "data: {\"choices\":[{\"delta\":{\"content\":\"x\"}}],\"usage\":{\"completion_tokens\":[]}}\n\n"
       "data: [DONE]\n\n",
       "`completion_tokens`"},
      {Api::kOpenAI, true, "data: {\"model\":1,\"choices\":[]}\n\ndata: [DONE]\n\n", "`model`"},
  };
  for (const auto& c : cases) {
    LoopbackServer server([&](const HttpRequestSeen&, int) { return body(200, c.text, c.stream); });
    auto reply = chat(config(server.url(), c.api), c.stream);
    CAPTURE(c.text);
    REQUIRE_FALSE(reply.is_ok());
    CHECK(reply.status().code() == Code::kCorruption);
    CHECK(reply.status().message().find(c.field) != std::string::npos);
  }
}

TEST_CASE("reply bodies and stream lines are capped (point 12)") {
  const std::string mb(1 << 20, 'x');
  auto huge = [&](int status, bool chunked, const std::string& prefix) {
    Reply r;
    r.status = status;
    r.chunked = chunked;
    r.pieces.push_back(prefix);
    for (int i = 0; i < 8; ++i) r.pieces.push_back(mb);
    return r;
  };
  LlmConfig base = config("", Api::kOllama);
  SUBCASE("a 200 body over max_reply_bytes") {
    LoopbackServer server([&](const HttpRequestSeen&, int) { return huge(200, false, "{\"a\":\""); });
    LlmConfig c = config(server.url(), Api::kOllama);
    c.max_reply_bytes = 2 << 20;
    auto reply = chat(c, false);
    REQUIRE_FALSE(reply.is_ok());
    CHECK(reply.status().code() == Code::kIOError);
    CHECK(reply.status().message().find("max_reply_bytes") != std::string::npos);
  }
  SUBCASE("a streamed line over max_line_bytes") {
    LoopbackServer server([&](const HttpRequestSeen&, int) { return huge(200, true, "data: \""); });
    LlmConfig c = config(server.url(), Api::kOpenAI);
    c.max_line_bytes = 1 << 20;
    auto reply = chat(c, true);
    REQUIRE_FALSE(reply.is_ok());
    CHECK(reply.status().message().find("max_line_bytes") != std::string::npos);
  }
  SUBCASE("an 8 MB error body, streamed or not, is cut to its start") {
    for (const bool stream : {false, true}) {
      LoopbackServer server([&](const HttpRequestSeen&, int) { return huge(500, stream, "oops "); });
      auto reply = chat(config(server.url(), Api::kOllama), stream);
      REQUIRE_FALSE(reply.is_ok());
      CHECK(reply.status().message().find("HTTP 500: oops") != std::string::npos);
      CHECK(reply.status().message().size() < 1000);
    }
  }
  CHECK(base.max_reply_bytes == 16u << 20);
}

TEST_CASE("timeouts must be positive, finite and at least a millisecond (point 11)") {
  LlmConfig c = config("http://127.0.0.1:1", Api::kOllama);
  CHECK(c.validate().is_ok());
  for (const double t : {0.0, -1.0, 1e-9, std::nan(""), HUGE_VAL}) {
    c.timeout_s = t;
    CAPTURE(t);
    CHECK_FALSE(c.validate().is_ok());
  }
  c.timeout_s = 1.0;
  c.connect_timeout_s = std::nan("");
  CHECK_FALSE(c.validate().is_ok());
}

TEST_CASE("llm chat prints the whole reply and no terminal escapes (point 18)") {
  if (!squawk::testing::binary_built()) return;
  const std::string content = std::string("A\0B\x1b[2JC\n", 8);
  for (const bool stream : {false, true}) {
    LoopbackServer server([&](const HttpRequestSeen&, int) {
      nlohmann::json j = {{"message", {{"content", content}}}, {"done", true}};
      return body(200, j.dump() + "\n", stream);
    });
    const auto r = squawk::testing::run_squawk(
        "llm chat hi --llm-url " + server.url() + " --llm-model m" + (stream ? " --stream" : ""), "");
    CAPTURE(r.out);
    CHECK(r.rc == 0);
    CHECK(r.out.find("A\\x00B\\x1b[2JC") != std::string::npos);
    CHECK(r.out.find('\x1b') == std::string::npos);
  }
}

TEST_CASE("an embedding reply with the right count but wrong indices says so (point 18)") {
  LoopbackServer server([](const HttpRequestSeen&, int) {
    return Reply::json(200, R"({"data":[{"index":5,"embedding":[1,2]}]})");
  });
  auto client = squawk::llm::make_client(config(server.url(), Api::kOpenAI));
  REQUIRE(client.is_ok());
  auto e = (*client)->embed({"a"});
  REQUIRE_FALSE(e.is_ok());
  CHECK(e.status().message().find("embedding indices run to 5, expected 0 to 0") != std::string::npos);
}

TEST_CASE("request text that is not UTF-8 is refused before anything is sent") {
  int requests = 0;
  LoopbackServer server([&](const HttpRequestSeen&, int) {
    ++requests;
    return Reply::json(200, "{}");
  });
  for (const Api api : {Api::kOllama, Api::kOpenAI}) {
    auto client = squawk::llm::make_client(config(server.url(), api));
    REQUIRE(client.is_ok());
    ChatRequest r;
    r.messages = {{"user", "KL204 climb \xff"}};
    auto reply = (*client)->chat(r);
    REQUIRE_FALSE(reply.is_ok());
    CHECK(reply.status().code() == Code::kInvalidArgument);
    CHECK(reply.status().message().find("not valid UTF-8 (invalid UTF-8 byte at index 12: 0xFF)") !=
          std::string::npos);
    auto e = (*client)->embed({"x\xc3"});
    REQUIRE_FALSE(e.is_ok());
    CHECK(e.status().message().find("not valid UTF-8") != std::string::npos);
  }
  CHECK(requests == 0);
}
