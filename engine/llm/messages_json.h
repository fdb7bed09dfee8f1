// The `messages` array both chat APIs share: [{role, content}, ...].
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "llm/client.h"

namespace squawk::llm {

nlohmann::json messages_json(const std::vector<Message>& messages);

// Reads an array of numbers as floats, or fails naming `what`.
Result<std::vector<float>> float_vector(const LlmConfig& config, const nlohmann::json& j,
                                        const std::string& what);

}  // namespace squawk::llm
