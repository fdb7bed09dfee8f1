// `squawk repl` driven through a pipe: English in, the simulation changes.
// Runs the built binary (SQUAWK_BINARY); skips when it has not been built.
// Also `squawk llm chat` against a loopback OpenAI-compatible server.
#include <doctest/doctest.h>

#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "loopback_server.h"
#include "run_binary.h"

using squawk::testing::HttpRequestSeen;
using squawk::testing::LoopbackServer;
using squawk::testing::Reply;

namespace {

std::string run_repl(const std::string& args, const std::string& input) {
  return squawk::testing::run_squawk("repl " + args, input).out;
}

// The heading [deg] on the last state line of aircraft `id`, or -1.
double last_heading(const std::string& out, const std::string& id) {
  double hdg = -1;
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream w(line);
    std::string first;
    w >> first;
    if (first != id) continue;
    const auto at = line.find("hdg");
    if (at != std::string::npos) hdg = std::stod(line.substr(at + 3));
  }
  return hdg;
}

}  // namespace

TEST_CASE("repl from a pipe: create in English, turn, run, heading changed") {
  if (!squawk::testing::binary_built()) {
    MESSAGE("skipped: " << SQUAWK_BINARY << " is not built");
    return;
  }
  const std::string out = run_repl("--mode offline",
                                   "Create aircraft KL204 type A320 at 52 N 4 E heading 90 at FL250, 280 knots\n"
                                   "turn KL204 to heading 180\n"
                                   ":run 120\n"
                                   ":quit\n"
                                   "turn KL204 to heading 90\n");
  INFO(out);
  CHECK(out.find("> CRE KL204 A320 52 4 90 FL250 280") != std::string::npos);
  CHECK(out.find("> HDG KL204 180") != std::string::npos);
  CHECK(out.find("t = 120.0 s") != std::string::npos);
  CHECK(last_heading(out, "KL204") == doctest::Approx(180.0).epsilon(0.005));
  CHECK(out.find("HDG KL204 90") == std::string::npos);  // nothing after :quit
  CHECK(out.find("squawk>") == std::string::npos);      // no prompt on a pipe
}

TEST_CASE("repl from a pipe: FF moves the clock, conflicts are shown, a scenario's failures are counted") {
  if (!squawk::testing::binary_built()) {
    MESSAGE("skipped: " << SQUAWK_BINARY << " is not built");
    return;
  }
  const std::string out = run_repl(std::string("--mode offline ") + SQUAWK_TEST_DATA + "/../lua/repl_failures.scn",
                                   "fast forward 5 minutes\n"
                                   ":state\n"
                                   "!HOLD\n");
  INFO(out);
  CHECK(out.find("scenario commands so far: 3 executed, 0 skipped, 2 failed") != std::string::npos);
  CHECK(out.find("DEST BAW1 QQXA: argument 2") != std::string::npos);
  CHECK(out.find("> FF 300") != std::string::npos);
  CHECK(out.find("fast-forwarded 300 s: t = 0.0 s -> 300.0 s") != std::string::npos);
  CHECK(out.find("conflict BAW1 & DLH2: loss of separation in") != std::string::npos);
  CHECK(out.find("half a minute in") != std::string::npos);
  CHECK(out.find("1 scenario command failed") != std::string::npos);
  CHECK(out.find("t = 300.0 s, 2 aircraft") != std::string::npos);
  CHECK(out.find("clock stopped (HOLD") != std::string::npos);
}

TEST_CASE("repl with an Ollama server: the multi-agent graph, and :trace") {
  if (!squawk::testing::binary_built()) {
    MESSAGE("skipped: " << SQUAWK_BINARY << " is not built");
    return;
  }
  LoopbackServer server([](const HttpRequestSeen& req, int) {
    std::string content = "I cannot help";
    if (req.body.find("Select one command") != std::string::npos) content = "\\boxed{HDG}";
    else if (req.body.find("Determine if the user gave") != std::string::npos) content = "YES";
    else if (req.body.find("valid instance of the command") != std::string::npos) content = "\\boxed{HDG KL204 180}";
    nlohmann::json j = {{"model", "fake"}, {"message", {{"role", "assistant"}, {"content", content}}}, {"done", true}};
    return Reply::json(200, j.dump());
  });
  const std::string out = run_repl("--llm-url " + server.url() + " --llm-model fake --mode multi",
                                   "!CRE KL204 A320 52 4 90 FL250 280\n"
                                   "point KL204 towards the south\n"
                                   ":trace\n"
                                   ":run 120\n");
  INFO(out);
  CHECK(out.find("> HDG KL204 180") != std::string::npos);
  CHECK(out.find("LLM replied: \\boxed{HDG}") != std::string::npos);
  CHECK(out.find("verify") != std::string::npos);
  CHECK(last_heading(out, "KL204") == doctest::Approx(180.0).epsilon(0.005));
  CHECK(server.requests().size() == 3);
}

TEST_CASE("repl with a dead server falls back to the offline grammar") {
  if (!squawk::testing::binary_built()) {
    MESSAGE("skipped: " << SQUAWK_BINARY << " is not built");
    return;
  }
  const int port = squawk::testing::closed_port();
  const std::string out = run_repl("--llm-url http://127.0.0.1:" + std::to_string(port) + " --llm-model m",
                                   "!CRE KL204 A320 52 4 90 FL250 280\nturn KL204 to heading 270\n:trace\n");
  INFO(out);
  CHECK(out.find("> HDG KL204 270") != std::string::npos);
  CHECK(out.find("falling back to the offline translator") != std::string::npos);
}

TEST_CASE("squawk llm chat --stream prints the SSE tokens; a 404 is a clear failure") {
  if (!squawk::testing::binary_built()) {
    MESSAGE("skipped: " << SQUAWK_BINARY << " is not built");
    return;
  }
  LoopbackServer server([](const HttpRequestSeen& req, int) {
    if (req.body.find("nosuchmodel") != std::string::npos)
      return Reply::json(404, R"({"error":{"message":"model 'nosuchmodel' not found"}})");
    Reply r;
    r.chunked = true;
    r.content_type = "text/event-stream";
    for (const char* piece : {"FF", " 600"})
      r.pieces.push_back("data: " + nlohmann::json{{"choices", {{{"index", 0}, {"delta", {{"content", piece}}}}}}}.dump() + "\n\n");
    r.pieces.push_back("data: [DONE]\n\n");
    return r;
  });
  const auto [out, rc] = squawk::testing::run_squawk(
      "llm chat speed it up --stream --llm-url " + server.url() + "/v1 --llm-model fake --seed 7", "");
  INFO(out);
  CHECK(rc == 0);
  CHECK(out.find("FF 600") != std::string::npos);
  CHECK(out.find("openai server " + server.url() + "/v1 (model fake)") != std::string::npos);
  REQUIRE(server.requests().size() == 1);
  CHECK(nlohmann::json::parse(server.requests()[0].body)["seed"] == 7);

  const auto bad = squawk::testing::run_squawk(
      "llm chat hi --llm-url " + server.url() + "/v1 --llm-model nosuchmodel", "");
  INFO(bad.out);
  CHECK(bad.out.find("HTTP 404: model 'nosuchmodel' not found") != std::string::npos);
  CHECK(bad.rc == 1);
}
