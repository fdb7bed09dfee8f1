#include "script/policy_factory.h"

#include <algorithm>
#include <cstdlib>

#include "core/files.h"
#include "core/paths.h"
#include "env/vec_env.h"
#include "gpt2/checkpoint.h"
#include "rl/baseline_policies.h"
#include "rl/branch_returns.h"
#include "rl/checkpoint.h"
#include "rl/mlp_policy.h"
#include "rl/play.h"
#include "script/prompt_renderer.h"

namespace squawk::script {

namespace {

std::string prompt_path(const std::string& prompt) {
  return prompt.empty() ? paths::resource(kDefaultPromptFile) : prompt;
}

rl::PromptRenderFn render_fn(std::shared_ptr<PromptRenderer> r) {
  return [r](const env::Observation& o) { return r->render(o); };
}

// Prompts for the first kTinyVocabEpisodes episodes of `env` under the zero action.
Result<std::string> vocabulary_text(PromptRenderer& r, const env::HorizontalCrConfig& env) {
  SQUAWK_ASSIGN_OR_RETURN(env::VecEnv envs, env::VecEnv::make(env, 16));
  std::string text;
  const auto d = static_cast<size_t>(envs.obs_size());
  rl::Driver driver;
  driver.choose = [&](rl::Turn& t) -> Status {  // the actions stay 0
    for (size_t i = 0; i < t.slots.size(); ++i) {
      SQUAWK_ASSIGN_OR_RETURN(env::Observation o, env::unflatten(t.obs.subspan(i * d, d)));
      SQUAWK_ASSIGN_OR_RETURN(std::string p, r.render(o));
      text += p;
    }
    return Status::ok();
  };
  SQUAWK_RETURN_IF_ERROR(rl::play(envs, 0, 0, kTinyVocabEpisodes, driver).status());
  return text;
}

Result<gpt2::Model> base_model(const std::string& source, uint64_t seed, const gpt2::Config& tiny_cfg,
                               const std::vector<gpt2::TensorSpec>& extras) {
  if (source != "tiny") return gpt2::load_model(paths::resolve(source), extras);
  SQUAWK_ASSIGN_OR_RETURN(gpt2::Model m, gpt2::Model::create(tiny_cfg, extras));
  Rng rng(seed);
  m.init_random(rng);
  return m;
}

Result<Gpt2Policy> assemble(rl::PromptCheckpoint meta, gpt2::Tokenizer tok,
                            std::shared_ptr<PromptRenderer> r) {
  SQUAWK_ASSIGN_OR_RETURN(gpt2::Config cfg, gpt2::parse_hf_config(meta.config_json));
  const auto extras = meta.spec.head == "action"
                          ? rl::PromptPolicy::head_extras(cfg.n_embd, static_cast<int>(meta.spec.action_values.size()))
                          : std::vector<gpt2::TensorSpec>{};
  SQUAWK_ASSIGN_OR_RETURN(gpt2::Model model, base_model(meta.source, meta.model_seed, cfg, extras));
  SQUAWK_ASSIGN_OR_RETURN(std::unique_ptr<rl::PromptPolicy> p,
                          rl::PromptPolicy::make(std::move(model), std::move(tok), r->prefix(), render_fn(r),
                                                 meta.spec));
  return Gpt2Policy{std::move(p), std::move(meta)};
}

}  // namespace

Result<Gpt2Policy> make_gpt2_policy(const Gpt2PolicyOptions& opts, const env::HorizontalCrConfig& env,
                                    const VmOptions& vm) {
  const std::string prompt = prompt_path(opts.prompt);
  SQUAWK_ASSIGN_OR_RETURN(std::shared_ptr<PromptRenderer> r, PromptRenderer::load(prompt, vm));
  rl::PromptCheckpoint meta;
  const bool tiny = opts.model == "tiny";
  // A folder is stored as @home/REL or absolute, so the checkpoint loads from any folder.
  const std::string dir = tiny ? "" : paths::resolve(opts.model);
  meta.source = tiny ? opts.model : paths::portable(paths::absolute(dir));
  meta.model_seed = opts.model_seed;
  meta.spec = opts.spec;
  meta.spec.obs_size = env::observation_size(env.num_intruders);
  meta.prompt = paths::portable(prompt);  // the checkpoint follows the home it is used in
  if (meta.spec.trainable_blocks < 0) meta.spec.trainable_blocks = tiny ? kTinyTrainableBlocks : 1;
  gpt2::Tokenizer tok = gpt2::Tokenizer::bytes_only();
  gpt2::Config cfg = gpt2::Config::tiny();
  if (tiny) {
    SQUAWK_ASSIGN_OR_RETURN(std::string text, vocabulary_text(*r, env));
    tok = gpt2::Tokenizer::train(text, kTinyMerges);
    cfg.vocab_size = tok.vocab_size();
    cfg.n_ctx = kTinyContext;
  } else {
    if (!files::exists(dir + "/config.json"))
      return Status::not_found("--model " + opts.model + ": no config.json (expected \"tiny\" or a Hugging Face GPT-2 folder)");
    SQUAWK_ASSIGN_OR_RETURN(std::string cj, files::read(dir + "/config.json"));
    SQUAWK_ASSIGN_OR_RETURN(cfg, gpt2::parse_hf_config(cj));
    if (files::exists(dir + "/vocab.json")) {
      SQUAWK_ASSIGN_OR_RETURN(tok, gpt2::Tokenizer::load(dir));
    } else if (cfg.vocab_size != 257) {
      return Status::not_found("--model " + opts.model + ": no vocab.json/merges.txt for its " +
                               std::to_string(cfg.vocab_size) + "-token vocabulary");
    }
  }
  meta.config_json = gpt2::hf_config_json(cfg);
  meta.vocab_json = tok.vocab_json();
  meta.merges_txt = tok.merges_txt();
  SQUAWK_ASSIGN_OR_RETURN(Gpt2Policy g, assemble(std::move(meta), std::move(tok), r));
  Rng head_rng(opts.model_seed ^ 0x4EADull);
  g.policy->init_head(head_rng);
  return g;
}

Result<Gpt2Policy> gpt2_policy_from_checkpoint(const rl::PromptCheckpoint& ckpt, const std::string& prompt,
                                               const VmOptions& vm, const paths::PathRules* reads) {
  rl::PromptCheckpoint meta = ckpt;
  meta.params.clear();
  meta.adam_m.clear();
  meta.adam_v.clear();
  if (!prompt.empty()) meta.prompt = paths::portable(prompt);
  if (meta.prompt.empty() || !files::exists(paths::resolve(meta.prompt))) meta.prompt = paths::portable(prompt_path(""));
  if (reads) {
    SQUAWK_RETURN_IF_ERROR(reads->check_read(paths::resolve(meta.prompt), "the checkpoint's prompt file"));
    if (meta.source != "tiny")
      SQUAWK_RETURN_IF_ERROR(reads->check_read_folder(paths::resolve(meta.source), "the checkpoint's model folder"));
  }
  SQUAWK_ASSIGN_OR_RETURN(std::shared_ptr<PromptRenderer> r, PromptRenderer::load(paths::resolve(meta.prompt), vm));
  SQUAWK_ASSIGN_OR_RETURN(gpt2::Tokenizer tok, gpt2::Tokenizer::from_hf(meta.vocab_json, meta.merges_txt));
  SQUAWK_ASSIGN_OR_RETURN(Gpt2Policy g, assemble(std::move(meta), std::move(tok), r));
  std::span<float> tail = g.policy->params();
  if (tail.size() != ckpt.params.size())
    return Status::corruption("gpt2 checkpoint holds " + std::to_string(ckpt.params.size()) +
                              " tail parameters, the rebuilt policy has " + std::to_string(tail.size()));
  std::copy(ckpt.params.begin(), ckpt.params.end(), tail.begin());
  g.policy->invalidate_cache();
  return g;
}

Result<MadePolicy> make_policy(const std::string& kind, const Scenario& sc, const env::VecEnv& envs,
                               const PolicyOptions& o, const VmOptions& vm) {
  MadePolicy m;
  m.label = kind;
  if (kind == "zero") {
    m.policy = std::make_unique<rl::ConstantPolicy>(envs.obs_size(), 0.0f);
    m.label = "zero (never turn)";
  } else if (kind.rfind("constant:", 0) == 0 || kind.rfind("turn-hold:", 0) == 0) {
    const bool constant = kind[0] == 'c';
    const std::string v = kind.substr(kind.find(':') + 1);
    char* end = nullptr;
    const double value = std::strtod(v.c_str(), &end);
    if (v.empty() || end != v.c_str() + v.size() || !(value >= -1.0 && value <= 1.0))
      return Status::invalid("policy '" + kind + "': expected " + kind.substr(0, kind.find(':')) +
                             ":V with V a number in [-1, 1]");
    using When = rl::ConstantPolicy::When;
    m.policy = std::make_unique<rl::ConstantPolicy>(envs.obs_size(), static_cast<float>(value),
                                                    constant ? When::always : When::on_track);
    m.label = constant ? "constant " + v + " (always the same action)"
                       : "turn-hold " + v + " (turn " + v + " when flying at the waypoint, else hold the heading)";
  } else if (kind == "mvp") {
    m.policy = std::make_unique<rl::MvpPolicy>(envs);
    m.label = "mvp (BlueSky's MVP steering the ownship)";
  } else if (kind == "lookahead") {
    if (envs.env(0).config().rules != env::Rules::kPaper)
      return Status::invalid("policy 'lookahead' plans under the paper rules only (its rollouts run to "
                             "the episode's end; the gym rules' 300-step episodes make that too slow)");
    m.policy = std::make_unique<rl::LookaheadPolicy>(envs, sc.policy.action_values);
    m.label = "lookahead (planner over the simulator: reads the true state and the future)";
  } else if (kind.rfind("rollout:", 0) == 0) {
    const std::string base = kind.substr(8);
    if (base.rfind("rollout:", 0) == 0 || base == "lookahead")
      return Status::invalid("policy '" + kind + "': the base of rollout: must be a learned policy (mlp, gpt2, random)");
    if (envs.env(0).config().rules != env::Rules::kPaper)
      return Status::invalid("policy '" + kind + "' plans under the paper rules only (its rollouts run to "
                             "the episode's end; the gym rules' 300-step episodes make that too slow)");
    SQUAWK_ASSIGN_OR_RETURN(MadePolicy b, make_policy(base, sc, envs, o, vm));
    if (b.policy->action_values().empty())
      return Status::invalid("policy '" + kind + "': " + base + " has no discrete action head to improve on");
    m.label = "rollout:" + b.label + " (one step of policy improvement: reads the true state and the future)";
    m.trained_on = b.trained_on;
    m.prompt = b.prompt;
    m.policy = std::make_unique<rl::RolloutPolicy>(envs, std::move(b.policy));
  } else if (kind == "random") {
    Rng init(o.seed);
    SQUAWK_ASSIGN_OR_RETURN(std::unique_ptr<rl::MlpPolicy> p, rl::MlpPolicy::make(sc.policy, init));
    m.policy = std::move(p);
    m.label = "random (untrained MLP, initialised from seed " + std::to_string(o.seed) + ")";
  } else if (kind == "mlp") {
    const std::string path = o.checkpoint.empty() ? paths::resource(kShippedMlpCheckpoint) : o.checkpoint;
    SQUAWK_ASSIGN_OR_RETURN(rl::Checkpoint c, rl::load_checkpoint(path));
    SQUAWK_ASSIGN_OR_RETURN(std::unique_ptr<rl::MlpPolicy> p, rl::policy_from_checkpoint(c));
    m.policy = std::move(p);
    m.label = "mlp (" + path + (c.spec.mirror.empty() ? ")" : ", mirror-symmetric)");
    m.trained_on = c.progress.scenario;
  } else if (kind == "gpt2") {
    Gpt2Policy g;
    if (o.gpt2_fresh) {
      SQUAWK_ASSIGN_OR_RETURN(g, make_gpt2_policy(o.gpt2, sc.train_env, vm));
      m.label = "gpt2 (" + o.gpt2.model + ", untrained head";
    } else {
      const std::string path = o.checkpoint.empty() ? paths::resource(kShippedGpt2Checkpoint) : o.checkpoint;
      SQUAWK_ASSIGN_OR_RETURN(rl::PromptCheckpoint c, rl::load_prompt_checkpoint(path));
      SQUAWK_ASSIGN_OR_RETURN(g, gpt2_policy_from_checkpoint(c, o.gpt2.prompt, vm, o.reads));
      m.label = "gpt2 (" + path + "; " + g.meta.source;
      m.trained_on = c.progress.scenario;
    }
    m.label += ", head " + g.meta.spec.head + (g.meta.spec.mirror.empty() ? ")" : ", mirror-symmetric)");
    m.prompt = g.meta.prompt;
    m.policy = std::move(g.policy);
  } else {
    return Status::invalid("policy '" + kind + "': expected random, zero, constant:V, turn-hold:V, mvp, lookahead, rollout:P, mlp or gpt2");
  }
  return m;
}

}  // namespace squawk::script
