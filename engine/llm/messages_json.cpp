#include "llm/messages_json.h"

namespace squawk::llm {

nlohmann::json messages_json(const std::vector<Message>& messages) {
  nlohmann::json arr = nlohmann::json::array();
  for (const auto& m : messages) arr.push_back({{"role", m.role}, {"content", m.content}});
  return arr;
}

Result<std::vector<float>> float_vector(const LlmConfig& config, const nlohmann::json& j,
                                        const std::string& what) {
  if (!j.is_array())
    return Status::corruption(config.describe() + ": " + what + " is not an array of numbers");
  std::vector<float> v;
  v.reserve(j.size());
  for (const auto& x : j) {
    if (!x.is_number())
      return Status::corruption(config.describe() + ": " + what + " holds a non-number");
    v.push_back(x.get<float>());
  }
  return v;
}

}  // namespace squawk::llm
