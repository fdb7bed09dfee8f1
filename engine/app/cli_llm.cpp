// squawk llm: talk to the configured LLM server directly (a configuration check).
#include <cstdio>

#include "app/cli.h"
#include "app/subcommands.h"
#include "core/text.h"
#include "llm/client.h"

namespace squawk::app {

namespace {

// Writes a server's text to stdout whole (NUL bytes included) with control
// bytes other than newline and tab shown as \xNN, so a reply cannot drive the
// terminal with escape codes.
void print_reply_text(std::string_view s) {
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if ((u < 0x20 && c != '\n' && c != '\t') || u == 0x7f) std::printf("\\x%02x", u);
    else std::fputc(c, stdout);
  }
}

// The configuration from the environment, overridden by the flags.
Result<llm::LlmConfig> config_from(const Args& args) {
  SQUAWK_ASSIGN_OR_RETURN(llm::LlmConfig c, llm::env_fields());
  c.url = args.get_or("--llm-url", c.url);
  c.model = args.get_or("--llm-model", c.model);
  if (auto api = args.get("--llm-api")) {
    SQUAWK_ASSIGN_OR_RETURN(c.api, llm::parse_api(*api));
  } else if (args.has("--llm-url")) {
    c.api = llm::infer_api(c.url);
  }
  SQUAWK_ASSIGN_OR_RETURN(c.temperature, args.get_double("--temperature", c.temperature));
  SQUAWK_ASSIGN_OR_RETURN(c.seed, args.get_int("--seed", c.seed));
  SQUAWK_ASSIGN_OR_RETURN(long long ctx, args.get_int("--context", c.context_size));
  if (ctx < 1 || ctx > 2147483647)
    return Status::invalid("--context " + std::to_string(ctx) + ": expected 1 to 2147483647 tokens");
  c.context_size = static_cast<int>(ctx);
  SQUAWK_ASSIGN_OR_RETURN(long long mb, args.get_int("--max-reply-mb", c.max_reply_bytes >> 20));
  if (mb < 1 || mb > (1 << 20)) return Status::invalid("--max-reply-mb " + std::to_string(mb) + ": expected 1 to 1048576");
  c.max_reply_bytes = static_cast<size_t>(mb) << 20;
  SQUAWK_ASSIGN_OR_RETURN(c.timeout_s, args.get_double("--timeout", c.timeout_s));
  if (c.url.empty()) return Status::invalid("no LLM server named: set SQUAWK_LLM_URL or pass --llm-url URL");
  SQUAWK_RETURN_IF_ERROR(c.validate());
  return c;
}

}  // namespace

int cmd_llm(const ArgV& argv) {
  Args::Spec spec;
  spec.value_flags = {"--llm-url", "--llm-model", "--llm-api", "--system", "--temperature",
                      "--seed",    "--context",   "--timeout",   "--max-reply-mb"};
  spec.bool_flags = {"--stream"};
  auto args = Args::parse(argv, spec);
  if (!args) return usage_error("llm", args.status().message());
  const auto& pos = args->positional();
  if (pos.size() < 2 || (pos[0] != "chat" && pos[0] != "embed"))
    return usage_error("llm", "expected `llm chat TEXT...` or `llm embed TEXT...`");
  auto cfg = config_from(*args);
  if (!cfg) return usage_error("llm", cfg.status().message());
  auto client = llm::make_client(*cfg);
  if (!client) return usage_error("llm", client.status().message());

  if (pos[0] == "embed") {
    auto e = (*client)->embed({pos.begin() + 1, pos.end()});
    if (!e) return failure(e.status());
    for (size_t i = 0; i < e->size(); ++i)
      std::printf("%s: %zu dimensions\n", text::quoted(pos[i + 1]).c_str(), (*e)[i].size());
    return kExitOk;
  }
  llm::ChatRequest req;
  if (auto sys = args->get("--system")) req.messages.push_back({"system", *sys});
  req.messages.push_back({"user", text::join({pos.begin() + 1, pos.end()}, " ")});
  llm::TokenSink sink;
  if (args->has("--stream")) {
    sink = [](std::string_view piece) {
      print_reply_text(piece);
      std::fflush(stdout);
    };
  }
  auto reply = (*client)->chat(req, sink);
  if (!reply) {
    if (sink) std::printf("\n");
    return failure(reply.status());
  }
  if (!sink) print_reply_text(reply->content);
  std::printf("\n");
  std::fprintf(stderr, "[%s: %ld prompt + %ld reply tokens, %d attempt(s), %s]\n",
               (*client)->config().describe().c_str(), reply->prompt_tokens, reply->completion_tokens,
               reply->attempts, reply->finish_reason.c_str());
  return kExitOk;
}

}  // namespace squawk::app
