#include "script/learner.h"

#include "rl/mlp_policy.h"

namespace squawk::script {

namespace {

rl::TrainProgress fresh_progress(uint64_t seed) {
  rl::TrainProgress p;
  p.seed = seed;
  return p;
}

Result<Learner> mlp_learner(const LearnerOptions& o, Scenario& sc) {
  Learner l;
  if (o.from.empty()) {
    Rng init(o.seed);
    SQUAWK_ASSIGN_OR_RETURN(std::unique_ptr<rl::MlpPolicy> p, rl::MlpPolicy::make(sc.policy, init));
    l.mlp.spec = p->spec();
    l.policy = std::move(p);
    l.mlp.progress = fresh_progress(o.seed);
    return l;
  }
  SQUAWK_ASSIGN_OR_RETURN(rl::Checkpoint c, rl::load_checkpoint(o.from));
  SQUAWK_ASSIGN_OR_RETURN(std::unique_ptr<rl::MlpPolicy> p, rl::policy_from_checkpoint(c));
  l.mlp.spec = c.spec;
  l.mlp.progress = o.resume ? c.progress : fresh_progress(o.seed);
  l.policy = std::move(p);
  l.restore = std::move(c);
  return l;
}

Result<Learner> gpt2_learner(const LearnerOptions& o, const Scenario& sc, const VmOptions& vm) {
  Learner l;
  l.is_gpt2 = true;
  Gpt2Policy g;
  if (o.from.empty()) {
    SQUAWK_ASSIGN_OR_RETURN(g, make_gpt2_policy(o.gpt2, sc.train_env, vm));
    g.meta.progress = fresh_progress(o.seed);
  } else {
    SQUAWK_ASSIGN_OR_RETURN(rl::PromptCheckpoint c, rl::load_prompt_checkpoint(o.from));
    if (!o.resume) {
      if (!o.gpt2.spec.mirror.empty()) c.spec.mirror = o.gpt2.spec.mirror;
      c.progress = fresh_progress(o.seed);
    }
    SQUAWK_ASSIGN_OR_RETURN(g, gpt2_policy_from_checkpoint(c, o.gpt2.prompt, vm, o.reads));
    g.meta.progress = c.progress;
    l.restore = std::move(c);
  }
  l.gpt2 = std::move(g.meta);
  l.policy = std::move(g.policy);
  return l;
}

}  // namespace

Status Learner::save(const std::string& path, rl::Trainer* trainer) {
  if (trainer) trainer->save(state());
  if (is_gpt2) return rl::save_prompt_checkpoint(path, gpt2);
  if (trainer) return rl::save_checkpoint(path, mlp);
  rl::Checkpoint c;
  c.spec = mlp.spec;
  c.params.assign(policy->params().begin(), policy->params().end());
  c.progress = mlp.progress;
  return rl::save_checkpoint(path, c);
}

Result<Learner> make_learner(const LearnerOptions& options, Scenario& sc, const VmOptions& vm) {
  if (options.kind != "mlp" && options.kind != "gpt2")
    return Status::invalid("policy '" + options.kind + "': only \"mlp\" and \"gpt2\" train");
  LearnerOptions o = options;
  if (o.mirror) {
    SQUAWK_ASSIGN_OR_RETURN(env::ObservationMirror m, env::observation_mirror(sc.train_env));
    if (o.kind == "mlp") sc.policy.mirror = m;
    o.gpt2.spec.mirror = m;
  }
  return o.kind == "mlp" ? mlp_learner(o, sc) : gpt2_learner(o, sc, vm);
}

}  // namespace squawk::script
