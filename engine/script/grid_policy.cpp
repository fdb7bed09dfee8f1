#include "script/grid_policy.h"

#include <array>

#include "rl/checkpoint.h"
#include "script/lua_batch_env.h"

namespace squawk::script {

Result<GridPolicy> load_grid_policy(const std::string& path, const LuaEnvSpec& spec) {
  SQUAWK_ASSIGN_OR_RETURN(rl::Checkpoint ck, rl::load_checkpoint(path));
  GridPolicy pol;
  SQUAWK_ASSIGN_OR_RETURN(pol.mlp, rl::policy_from_checkpoint(ck));
  const rl::MlpPolicySpec& ps = pol.mlp->spec();
  if (ps.head == "gaussian" && ps.action_size != spec.action_size())
    return Status::invalid(path + ": a Gaussian policy of " + std::to_string(ps.action_size) +
                           (ps.action_size == 1 ? " action component; " : " action components; ") +
                           spec.id + " takes " + std::to_string(spec.action_size()));
  if (ps.obs_size != spec.observation_size)
    return Status::invalid(path + ": the policy reads " + std::to_string(ps.obs_size) +
                           " observation numbers; " + spec.id + " gives " +
                           std::to_string(spec.observation_size) + " (trained on " +
                           ck.progress.scenario + ")");
  if (ps.head == "gaussian") return pol;  // levels 0
  const auto classes = static_cast<int>(ps.action_values.size());
  bool grid = ps.head == "categorical";
  for (int c = 0; grid && c < classes; ++c)
    grid = grid_class(ps.action_values[static_cast<size_t>(c)], classes) == c;
  if (!grid)
    return Status::invalid(
        path + ": not a policy over an action grid (squawk train --env writes those; trained on " +
        ck.progress.scenario + ")");
  SQUAWK_ASSIGN_OR_RETURN(pol.levels, grid_levels(spec, classes));
  return pol;
}

void policy_action(const LuaEnvSpec& spec, const GridPolicy& pol, const rl::ActionSample& choice,
                   std::span<double> out) {
  if (pol.levels == 0) {
    std::array<double, rl::kMaxActionSize> v{};
    for (size_t j = 0; j < out.size(); ++j) v[j] = choice.component(static_cast<int>(j));
    box_action(spec, std::span<const double>(v).first(out.size()), out);
  } else {
    grid_action(spec, pol.levels, choice.index, out);
  }
}

}  // namespace squawk::script
