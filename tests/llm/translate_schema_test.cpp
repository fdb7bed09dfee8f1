// The LLM modes of the translation graph ask for output constrained by the
// command registry: a JSON schema (Ollama `format`, OpenAI `response_format`)
// whose command names and argument counts come from the registry, with the
// offline grammar's reading of the request in the prompt; a reply in that
// shape becomes the TrafScript line. Against a loopback server, through the
// built binary's REPL.
#include <doctest/doctest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "loopback_server.h"
#include "run_binary.h"

using nlohmann::json;
using squawk::testing::HttpRequestSeen;
using squawk::testing::LoopbackServer;
using squawk::testing::Reply;

namespace {

// The object schema of command `name` inside a graph schema, or null.
json command_choice(const json& schema, const std::string& name) {
  for (const auto& c : schema["properties"]["commands"]["items"]["anyOf"])
    if (c["properties"]["name"]["enum"][0] == name) return c;
  return nullptr;
}

}  // namespace

TEST_CASE("single mode (Ollama): a registry schema as format, JSON reply -> command") {
  if (!squawk::testing::binary_built()) {
    MESSAGE("skipped: " << SQUAWK_BINARY << " is not built");
    return;
  }
  LoopbackServer server([](const HttpRequestSeen&, int) {
    const json content = {{"commands", {{{"name", "ALT"}, {"args", {"KL204", "FL300"}}}}}, {"ask", ""}};
    return Reply::json(200, json{{"model", "fake"},
                                 {"message", {{"role", "assistant"}, {"content", content.dump()}}},
                                 {"done", true}}.dump());
  });
  const std::string out =
      squawk::testing::run_squawk("repl --llm-url " + server.url() + " --llm-model fake --mode single",
                                  "!CRE KL204 A320 52 4 90 FL250 280\nKL204 climb flight level three zero zero\n")
          .out;
  INFO(out);
  CHECK(out.find("> ALT KL204 FL300") != std::string::npos);
  REQUIRE(server.requests().size() == 1);
  const json body = json::parse(server.requests()[0].body);
  REQUIRE(body.contains("format"));
  const json& schema = body["format"];
  CHECK(schema["required"] == json::array({"commands", "ask"}));
  const json alt = command_choice(schema, "ALT");  // ALT acid,alt,[vspd]
  REQUIRE(alt.is_object());
  CHECK(alt["properties"]["args"]["minItems"] == 2);
  CHECK(alt["properties"]["args"]["maxItems"] == 3);
  const json cre = command_choice(schema, "CRE");  // CRE txt,txt,latlon,[hdg,alt,spd]: latlon is two
  REQUIRE(cre.is_object());
  CHECK(cre["properties"]["args"]["minItems"] == 4);
  CHECK(cre["properties"]["args"]["maxItems"] == 7);
  CHECK(command_choice(schema, "TELEPORT").is_null());
  const std::string prompt = body["messages"].dump();
  CHECK(prompt.find("An offline grammar read this request as: ALT KL204 FL300") != std::string::npos);
}

TEST_CASE("multi mode (OpenAI): the filler's schema holds the selected command only; ask in JSON") {
  if (!squawk::testing::binary_built()) {
    MESSAGE("skipped: " << SQUAWK_BINARY << " is not built");
    return;
  }
  LoopbackServer server([](const HttpRequestSeen& req, int) {
    std::string content = "I cannot help";
    if (req.body.find("Select one command") != std::string::npos) content = "\\boxed{HDG}";
    else if (req.body.find("Determine if the user gave") != std::string::npos) content = "YES";
    else if (req.body.find("response_format") != std::string::npos)
      content = json{{"commands", json::array()}, {"ask", "Which heading, left or right?"}}.dump();
    return Reply::json(200, json{{"choices", {{{"index", 0}, {"message", {{"role", "assistant"}, {"content", content}}}}}}}
                                .dump());
  });
  const std::string out =
      squawk::testing::run_squawk("repl --llm-url " + server.url() + "/v1 --llm-model fake --mode multi",
                                  "!CRE KL204 A320 52 4 90 FL250 280\nKL204 turn please\n")
          .out;
  INFO(out);
  CHECK(out.find("Which heading, left or right?") != std::string::npos);
  const auto reqs = server.requests();
  REQUIRE(reqs.size() == 3);
  const json fill = json::parse(reqs[2].body);
  REQUIRE(fill.contains("response_format"));
  const json& schema = fill["response_format"]["json_schema"]["schema"];
  CHECK(schema["properties"]["commands"]["items"]["anyOf"].size() == 1);
  CHECK(command_choice(schema, "HDG")["properties"]["args"]["maxItems"] == 3);  // acid, hdg, [LEFT/RIGHT]
  CHECK_FALSE(json::parse(reqs[0].body).contains("response_format"));  // the selector answers in words
}
