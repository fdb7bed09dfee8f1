#include "rl/policy.h"

#include <string>

namespace squawk::rl {

Status check_obs_size(const Policy& policy, int obs_size) {
  if (policy.obs_size() == obs_size) return Status::ok();
  return Status::invalid("policy expects " + std::to_string(policy.obs_size()) +
                         " observation values, the scenario gives " + std::to_string(obs_size));
}

}  // namespace squawk::rl
