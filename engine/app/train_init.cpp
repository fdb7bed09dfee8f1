#include "app/train_init.h"

#include <cstdio>
#include <string>

#include "rl/checkpoint.h"

namespace squawk::app {

Result<InitPolicy> init_policy(const std::string& path, const script::LuaEnvSpec& es,
                               const rl::MlpPolicySpec& wanted) {
  auto loaded = rl::load_checkpoint(path);
  if (!loaded) return Status::invalid("--init: " + loaded.status().message());
  const rl::Checkpoint& ck = *loaded;
  const auto& s = ck.spec;
  if (s.obs_size != es.observation_size)
    return Status::invalid("--init " + path + ": its policy reads " + std::to_string(s.obs_size) +
                           " observation numbers; " + es.id + " gives " +
                           std::to_string(es.observation_size));
  if ((s.head == "gaussian") != (wanted.head == "gaussian") ||
      (s.head == "gaussian" ? s.action_size != wanted.action_size
                            : s.action_values != wanted.action_values))
    return Status::invalid(
        "--init " + path + ": its policy's head (" + s.head + ", " +
        std::to_string(s.head == "gaussian" ? s.action_size
                                            : static_cast<int>(s.action_values.size())) +
        (s.head == "gaussian" ? " components" : " classes") + ") is not this run's (" +
        (wanted.head == "gaussian"
             ? "--gaussian, " + std::to_string(wanted.action_size) + " components"
             : std::to_string(wanted.action_values.size()) + " grid classes") +
        ")");
  SQUAWK_ASSIGN_OR_RETURN(auto policy, rl::policy_from_checkpoint(ck));
  return InitPolicy{ck.spec, std::move(policy)};
}

Status fit_value_to_policy(rl::MlpPolicy& policy, env::BatchEnv& envs,
                           const rl::ImitationConfig& ic, rl::Trainer& trainer, bool quiet) {
  if (!trainer.value_adam()) return Status::ok();
  SQUAWK_ASSIGN_OR_RETURN(
      auto flights, rl::greedy_flights(policy, envs, ic.seed, static_cast<uint64_t>(ic.episodes)));
  return fit_value(trainer, flights, ic, "the starting policy's", quiet);
}

Status fit_value(rl::Trainer& trainer, const rl::TeacherFlights& flights,
                 const rl::ImitationConfig& ic, const char* whose, bool quiet) {
  if (!trainer.value_adam()) return Status::ok();
  SQUAWK_ASSIGN_OR_RETURN(auto fit, trainer.pretrain_value(flights, ic.epochs, ic.batch, ic.seed));
  if (!quiet)
    std::printf(
        "value baseline fitted to %s returns (%zu steps): mean squared error %.3f -> %.3f\n", whose,
        flights.rewards.size(), fit.before, fit.after);
  return Status::ok();
}

}  // namespace squawk::app
