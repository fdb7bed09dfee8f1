// LLM clients against a loopback HTTP server speaking the Ollama and OpenAI
// wire formats, through the real curl transport.
#include <doctest/doctest.h>

#include <chrono>
#include <cstdlib>

#include "llm/client.h"
#include "llm/llm_config.h"
#include "loopback_server.h"

using squawk::Code;
using squawk::llm::Api;
using squawk::llm::ChatRequest;
using squawk::llm::LlmConfig;
using squawk::testing::HttpRequestSeen;
using squawk::testing::LoopbackServer;
using squawk::testing::Reply;
using json = nlohmann::json;

namespace {

struct Fixture {
  std::vector<double> waits;  // backoff waits the client asked for [s]

  LlmConfig config(const std::string& url, Api api) {
    LlmConfig c;
    c.api = api;
    c.url = api == Api::kOpenAI ? url + "/v1" : url;
    c.model = "qwen2.5:7b";
    c.temperature = 0.0;
    c.seed = 42;
    c.context_size = 8192;
    c.connect_timeout_s = 1.0;
    c.timeout_s = 5.0;
    c.retry.max_attempts = 3;
    c.retry.sleep = [this](double s) { waits.push_back(s); };
    return c;
  }
  std::unique_ptr<squawk::llm::LlmClient> client(const std::string& url, Api api) {
    auto c = squawk::llm::make_client(config(url, api));
    REQUIRE(c.is_ok());
    return std::move(c).value();
  }
};

ChatRequest ask(const std::string& text) {
  ChatRequest r;
  r.messages = {{"system", "You translate to TrafScript."}, {"user", text}};
  return r;
}

std::string ollama_line(const std::string& piece, bool done) {
  json j = {{"model", "qwen2.5:7b"}, {"message", {{"role", "assistant"}, {"content", piece}}}, {"done", done}};
  if (done) {
    j["done_reason"] = "stop";
    j["prompt_eval_count"] = 12;
    j["eval_count"] = 3;
  }
  return j.dump() + "\n";
}

std::string sse(const json& j) { return "data: " + j.dump() + "\n\n"; }

json delta(const std::string& piece) {
  return {{"model", "m"}, {"choices", {{{"index", 0}, {"delta", {{"content", piece}}}, {"finish_reason", nullptr}}}}};
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

TEST_CASE("ollama chat: request carries model, temperature, seed, context; reply parsed") {
  LoopbackServer server([](const HttpRequestSeen&, int) {
    return Reply::json(200, json{{"model", "qwen2.5:7b"},
                                 {"message", {{"role", "assistant"}, {"content", "HDG KL204 270"}}},
                                 {"done", true},
                                 {"done_reason", "stop"},
                                 {"prompt_eval_count", 20},
                                 {"eval_count", 5}}
                                .dump());
  });
  Fixture f;
  auto reply = f.client(server.url(), Api::kOllama)->chat(ask("turn KL204 west"));
  REQUIRE_MESSAGE(reply.is_ok(), reply.status().message());
  CHECK(reply->content == "HDG KL204 270");
  CHECK(reply->completion_tokens == 5);
  CHECK(reply->attempts == 1);
  auto seen = server.requests();
  REQUIRE(seen.size() == 1);
  CHECK(seen[0].path == "/api/chat");
  auto body = json::parse(seen[0].body);
  CHECK(body["model"] == "qwen2.5:7b");
  CHECK(body["stream"] == false);
  CHECK(body["options"]["temperature"] == 0.0);
  CHECK(body["options"]["seed"] == 42);
  CHECK(body["options"]["num_ctx"] == 8192);
  CHECK(body["messages"][1]["content"] == "turn KL204 west");
  CHECK_FALSE(body.contains("format"));
}

TEST_CASE("ollama chat: NDJSON stream split across chunks arrives token by token") {
  LoopbackServer server([](const HttpRequestSeen&, int) {
    const std::string all = ollama_line("HDG ", false) + ollama_line("KL204 ", false) +
                            ollama_line("270", false) + ollama_line("", true);
    Reply r;
    r.chunked = true;
    r.content_type = "application/x-ndjson";
    for (size_t i = 0; i < all.size(); i += 17) r.pieces.push_back(all.substr(i, 17));
    return r;
  });
  Fixture f;
  std::vector<std::string> tokens;
  auto reply = f.client(server.url(), Api::kOllama)
                   ->chat(ask("turn"), [&](std::string_view t) { tokens.emplace_back(t); });
  REQUIRE_MESSAGE(reply.is_ok(), reply.status().message());
  CHECK(reply->content == "HDG KL204 270");
  CHECK(tokens == std::vector<std::string>{"HDG ", "KL204 ", "270"});
  CHECK(reply->prompt_tokens == 12);
  CHECK(json::parse(server.requests()[0].body)["stream"] == true);
}

TEST_CASE("ollama chat: an error object mid-stream fails at once with the server's text") {
  LoopbackServer server([](const HttpRequestSeen&, int) {
    Reply r;
    r.chunked = true;
    r.pieces = {ollama_line("HDG ", false), "{\"error\":\"model runner has unexpectedly stopped\"}\n"};
    return r;
  });
  Fixture f;
  std::string got;
  auto reply = f.client(server.url(), Api::kOllama)
                   ->chat(ask("turn"), [&](std::string_view t) { got += t; });
  REQUIRE_FALSE(reply.is_ok());
  const auto& msg = reply.status().message();
  CHECK(msg.find("model runner has unexpectedly stopped") != std::string::npos);
  CHECK(msg.find("ollama server " + server.url()) != std::string::npos);
  CHECK(msg.find("qwen2.5:7b") != std::string::npos);
  CHECK(got == "HDG ");
  CHECK(server.requests().size() == 1);  // no retry once text was streamed
}

TEST_CASE("a connection lost mid-stream is an error, not retried once text arrived") {
  LoopbackServer server([](const HttpRequestSeen&, int) {
    Reply r;
    r.chunked = true;
    r.truncate = true;
    r.pieces = {ollama_line("HDG ", false)};
    return r;
  });
  Fixture f;
  auto reply = f.client(server.url(), Api::kOllama)->chat(ask("turn"), [](std::string_view) {});
  REQUIRE_FALSE(reply.is_ok());
  CHECK(reply.status().code() == Code::kUnavailable);
  CHECK(reply.status().message().find("the stream broke after it had started") != std::string::npos);
  CHECK(server.requests().size() == 1);
}

TEST_CASE("a 500 then success is retried once with backoff") {
  LoopbackServer server([](const HttpRequestSeen&, int i) {
    if (i == 0) return Reply::json(500, R"({"error":"out of memory"})");
    return Reply::json(200, ollama_line("FF", true));
  });
  Fixture f;
  auto reply = f.client(server.url(), Api::kOllama)->chat(ask("speed up"));
  REQUIRE_MESSAGE(reply.is_ok(), reply.status().message());
  CHECK(reply->content == "FF");
  CHECK(reply->attempts == 2);
  CHECK(server.requests().size() == 2);
  REQUIRE(f.waits.size() == 1);
  CHECK(f.waits[0] == doctest::Approx(0.5));
}

TEST_CASE("persistent 5xx gives up after max attempts with the server's message") {
  LoopbackServer server([](const HttpRequestSeen&, int) { return Reply::json(503, R"({"error":{"message":"loading model"}})"); });
  Fixture f;
  auto reply = f.client(server.url(), Api::kOpenAI)->chat(ask("x"));
  REQUIRE_FALSE(reply.is_ok());
  CHECK(reply.status().code() == Code::kUnavailable);
  const auto& msg = reply.status().message();
  CHECK(msg.find("HTTP 503: loading model") != std::string::npos);
  CHECK(msg.find("after 3 attempts") != std::string::npos);
  CHECK(server.requests().size() == 3);
  CHECK(f.waits == std::vector<double>{0.5, 1.0});
}

TEST_CASE("a 4xx is not retried") {
  LoopbackServer server([](const HttpRequestSeen&, int) { return Reply::json(404, R"({"error":"model 'qwen2.5:7b' not found"})"); });
  Fixture f;
  auto reply = f.client(server.url(), Api::kOllama)->chat(ask("x"));
  REQUIRE_FALSE(reply.is_ok());
  CHECK(reply.status().code() == Code::kInvalidArgument);
  CHECK(reply.status().message().find("HTTP 404: model 'qwen2.5:7b' not found") != std::string::npos);
  CHECK(server.requests().size() == 1);
  CHECK(f.waits.empty());
}

TEST_CASE("a server slower than the timeout fails with kTimeout, bounded in time") {
  LoopbackServer server([](const HttpRequestSeen&, int) {
    Reply r = Reply::json(200, ollama_line("late", true));
    r.delay_ms = 3000;
    return r;
  });
  Fixture f;
  auto cfg = f.config(server.url(), Api::kOllama);
  cfg.timeout_s = 0.3;
  cfg.retry.max_attempts = 2;
  auto client = squawk::llm::make_client(cfg);
  REQUIRE(client.is_ok());
  const auto t0 = std::chrono::steady_clock::now();
  auto reply = (*client)->chat(ask("x"));
  const double took = seconds_since(t0);
  REQUIRE_FALSE(reply.is_ok());
  CHECK(reply.status().code() == Code::kTimeout);
  CHECK(reply.status().message().find("after 2 attempts") != std::string::npos);
  CHECK(server.requests().size() == 2);
  CHECK(took < 2.0);
}

TEST_CASE("malformed JSON is a clear corruption error, not retried") {
  LoopbackServer server([](const HttpRequestSeen&, int) { return Reply::json(200, "{\"message\": {\"content\": \"HDG"); });
  Fixture f;
  auto reply = f.client(server.url(), Api::kOllama)->chat(ask("x"));
  REQUIRE_FALSE(reply.is_ok());
  CHECK(reply.status().code() == Code::kCorruption);
  CHECK(reply.status().message().find("malformed JSON") != std::string::npos);
  CHECK(server.requests().size() == 1);
}

TEST_CASE("connection refused is retried, then names the server and model") {
  const int port = squawk::testing::closed_port();
  Fixture f;
  const std::string url = "http://127.0.0.1:" + std::to_string(port);
  const auto t0 = std::chrono::steady_clock::now();
  auto reply = f.client(url, Api::kOllama)->chat(ask("x"));
  REQUIRE_FALSE(reply.is_ok());
  CHECK(reply.status().code() == Code::kUnavailable);
  const auto& msg = reply.status().message();
  CHECK(msg.find("ollama server " + url + " (model qwen2.5:7b)") != std::string::npos);
  CHECK(msg.find("after 3 attempts") != std::string::npos);
  CHECK(f.waits.size() == 2);
  CHECK(seconds_since(t0) < 5.0);
}

TEST_CASE("a dropped connection is a transport error and is retried") {
  LoopbackServer server([](const HttpRequestSeen&, int i) {
    Reply r = Reply::json(200, ollama_line("HOLD", true));
    r.drop = i == 0;
    return r;
  });
  Fixture f;
  auto reply = f.client(server.url(), Api::kOllama)->chat(ask("pause"));
  REQUIRE_MESSAGE(reply.is_ok(), reply.status().message());
  CHECK(reply->content == "HOLD");
  CHECK(reply->attempts == 2);
}

TEST_CASE("ollama structured output sends the schema as format; grammar is refused") {
  LoopbackServer server([](const HttpRequestSeen&, int) { return Reply::json(200, ollama_line("{\"cmd\":\"FF\"}", true)); });
  Fixture f;
  auto client = f.client(server.url(), Api::kOllama);
  ChatRequest r = ask("x");
  r.json_schema = {{"type", "object"}, {"properties", {{"cmd", {{"type", "string"}}}}}};
  auto reply = client->chat(r);
  REQUIRE(reply.is_ok());
  CHECK(json::parse(server.requests()[0].body)["format"] == r.json_schema);
  r.grammar = "root ::= \"FF\"";
  auto refused = client->chat(r);
  CHECK(refused.status().code() == Code::kUnsupported);
  CHECK(server.requests().size() == 1);
}

TEST_CASE("ollama embed") {
  LoopbackServer server([](const HttpRequestSeen&, int) {
    return Reply::json(200, R"({"model":"e","embeddings":[[0.5,1.0],[0.25,-1]]})");
  });
  Fixture f;
  auto e = f.client(server.url(), Api::kOllama)->embed({"a", "b"});
  REQUIRE_MESSAGE(e.is_ok(), e.status().message());
  REQUIRE(e->size() == 2);
  CHECK((*e)[1][1] == -1.0f);
  auto body = json::parse(server.requests()[0].body);
  CHECK(server.requests()[0].path == "/api/embed");
  CHECK(body["input"] == json::array({"a", "b"}));
}

TEST_CASE("openai chat: request fields, non-streaming reply") {
  LoopbackServer server([](const HttpRequestSeen&, int) {
    return Reply::json(200, R"({"id":"x","object":"chat.completion","model":"m",
      "choices":[{"index":0,"message":{"role":"assistant","content":"ALT KL204 FL300"},"finish_reason":"stop"}],
      "usage":{"prompt_tokens":30,"completion_tokens":6,"total_tokens":36}})");
  });
  Fixture f;
  ChatRequest r = ask("climb");
  r.json_schema = {{"type", "object"}};
  r.grammar = "root ::= [A-Z ]+";
  auto reply = f.client(server.url(), Api::kOpenAI)->chat(r);
  REQUIRE_MESSAGE(reply.is_ok(), reply.status().message());
  CHECK(reply->content == "ALT KL204 FL300");
  CHECK(reply->completion_tokens == 6);
  auto seen = server.requests()[0];
  CHECK(seen.path == "/v1/chat/completions");
  auto body = json::parse(seen.body);
  CHECK(body["seed"] == 42);
  CHECK(body["temperature"] == 0.0);
  CHECK(body["num_ctx"] == 8192);
  CHECK(body["stream"] == false);
  CHECK(body["response_format"]["type"] == "json_schema");
  CHECK(body["response_format"]["json_schema"]["schema"] == r.json_schema);
  CHECK(body["grammar"] == r.grammar);
}

TEST_CASE("openai chat: SSE stream ending in [DONE]") {
  LoopbackServer server([](const HttpRequestSeen&, int) {
    Reply r;
    r.chunked = true;
    r.content_type = "text/event-stream";
    r.pieces = {": keep-alive\n\n", sse(delta("SPD ")), sse(delta("KL204 ")).substr(0, 20),
                sse(delta("KL204 ")).substr(20), sse(delta("250")),
                sse(json{{"choices", {{{"index", 0}, {"delta", json::object()}, {"finish_reason", "stop"}}}}}),
                "data: [DONE]\n\n"};
    return r;
  });
  Fixture f;
  std::vector<std::string> tokens;
  auto reply = f.client(server.url(), Api::kOpenAI)
                   ->chat(ask("slow"), [&](std::string_view t) { tokens.emplace_back(t); });
  REQUIRE_MESSAGE(reply.is_ok(), reply.status().message());
  CHECK(reply->content == "SPD KL204 250");
  CHECK(tokens.size() == 3);
  CHECK(reply->finish_reason == "stop");
}

TEST_CASE("openai chat: error event mid-stream, and a stream without [DONE]") {
  LoopbackServer server([](const HttpRequestSeen& req, int) {
    Reply r;
    r.chunked = true;
    r.content_type = "text/event-stream";
    if (req.body.find("broken") != std::string::npos)
      r.pieces = {sse(delta("HDG")), "data: {\"error\":{\"message\":\"context length exceeded\",\"code\":400}}\n\n"};
    else
      r.pieces = {sse(delta("HDG"))};
    return r;
  });
  Fixture f;
  auto client = f.client(server.url(), Api::kOpenAI);
  auto sink = [](std::string_view) {};
  auto broken = client->chat(ask("broken"), sink);
  REQUIRE_FALSE(broken.is_ok());
  CHECK(broken.status().message().find("context length exceeded") != std::string::npos);
  auto cut = client->chat(ask("cut"), sink);
  REQUIRE_FALSE(cut.is_ok());
  CHECK(cut.status().message().find("[DONE]") != std::string::npos);
  CHECK(server.requests().size() == 2);
}

TEST_CASE("openai embeddings are returned in input order") {
  LoopbackServer server([](const HttpRequestSeen&, int) {
    return Reply::json(200, R"({"object":"list","data":[{"index":1,"embedding":[2.0]},{"index":0,"embedding":[1.0]}]})");
  });
  Fixture f;
  auto e = f.client(server.url(), Api::kOpenAI)->embed({"first", "second"});
  REQUIRE_MESSAGE(e.is_ok(), e.status().message());
  CHECK((*e)[0][0] == 1.0f);
  CHECK((*e)[1][0] == 2.0f);
  CHECK(server.requests()[0].path == "/v1/embeddings");
}

TEST_CASE("retry backoff grows and is capped") {
  squawk::llm::RetryPolicy p;
  p.initial_backoff_s = 1;
  p.multiplier = 3;
  p.max_backoff_s = 5;
  CHECK(p.backoff_before(2) == 1.0);
  CHECK(p.backoff_before(3) == 3.0);
  CHECK(p.backoff_before(4) == 5.0);
}

TEST_CASE("configuration: API inference, validation, environment") {
  CHECK(squawk::llm::infer_api("http://h:8080/v1") == Api::kOpenAI);
  CHECK(squawk::llm::infer_api("http://h:8080/v1/") == Api::kOpenAI);
  CHECK(squawk::llm::infer_api("http://h:11434") == Api::kOllama);
  CHECK_FALSE(squawk::llm::parse_api("grpc").is_ok());

  LlmConfig c;
  c.url = "localhost:11434";
  c.model = "m";
  CHECK(c.validate().message().find("not an http://") != std::string::npos);
  c.url = "http://localhost:11434";
  c.model = "";
  CHECK(c.validate().message().find("no model") != std::string::npos);

  ::setenv("SQUAWK_LLM_URL", "http://127.0.0.1:8080/v1", 1);
  ::setenv("SQUAWK_LLM_MODEL", "qwen", 1);
  auto env = squawk::llm::config_from_env();
  REQUIRE(env.is_ok());
  CHECK(env->api == Api::kOpenAI);
  CHECK(env->model == "qwen");
  ::unsetenv("SQUAWK_LLM_URL");
  CHECK(squawk::llm::config_from_env().status().code() == Code::kNotFound);
  ::unsetenv("SQUAWK_LLM_MODEL");
}
