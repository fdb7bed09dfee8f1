#include "llm/client.h"

#include "llm/curl_transport.h"
#include "llm/ollama_client.h"
#include "llm/openai_client.h"

namespace squawk::llm {

LlmClient::LlmClient(LlmConfig config, std::shared_ptr<HttpTransport> transport)
    : config_(std::move(config)), transport_(std::move(transport)) {}

Result<std::unique_ptr<LlmClient>> make_client(LlmConfig config,
                                               std::shared_ptr<HttpTransport> transport) {
  SQUAWK_RETURN_IF_ERROR(config.validate());
  if (!transport) transport = std::make_shared<CurlTransport>();
  while (!config.url.empty() && config.url.back() == '/') config.url.pop_back();
  std::unique_ptr<LlmClient> client;
  if (config.api == Api::kOpenAI)
    client = std::make_unique<OpenAiClient>(std::move(config), std::move(transport));
  else
    client = std::make_unique<OllamaClient>(std::move(config), std::move(transport));
  return client;
}

}  // namespace squawk::llm
