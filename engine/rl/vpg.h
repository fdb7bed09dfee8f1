// Policy-gradient learner: the paper's vanilla policy gradient (Eq. 5) and an
// improved estimator, both with nn::Adam.
//
// One update collects `episodes_per_update` whole episodes with the current
// policy (sampling), numbered consecutively over the run (env/vec_env.h), then
// takes one Adam step on the mean over the N agent steps of the batch of
//   "vpg"      (Eq. 5):   L = -(1/N) sum_t log pi(a_t|s_t) r_t
//   "improved":          L = -(1/N) sum_t log pi(a_t|s_t) A_t - c_H (1/N) sum_t H(pi(.|s_t))
//     with G_t = sum_{k>=t} gamma^(k-t) r_k (reward-to-go), the baseline b_t =
//     V(s_t) from a learned value MLP (value_hidden; the batch mean of G when
//     value_hidden is empty), A_t = (G_t - b_t) normalised to zero mean and
//     unit deviation over the batch, c_H = entropy_coef. The value MLP is
//     fitted to G by value_iters Adam steps on the mean squared error after
//     each policy step. With a value MLP and lambda < 1, A_t is GAE(lambda):
//     sum_{k>=0} (gamma lambda)^k delta_{t+k}, delta_t = r_t + gamma V(s_{t+1})
//     - V(s_t), V = 0 after an episode's last step (lambda = 1 gives G_t - V(s_t)).
//   "ppo":      the improved advantages, then `epochs` passes over the batch,
//     each split into `minibatches` parts B (a fresh shuffle of the N samples
//     per pass when there are several; in order when there is one), with one
//     Adam step per part on the clipped-ratio surrogate
//       L_B = -(1/|B|) sum_{t in B} min(rho_t A_t, clip(rho_t, 1 - clip,
//             1 + clip) A_t) - c_H (1/|B|) sum_{t in B} H,
//     rho_t = pi(a_t|s_t) / pi_old(a_t|s_t), pi_old the sampling policy
//     (needs Policy::log_probs): epochs x minibatches steps per batch.
//   "vine":     at a random share `branch_fraction` of the batch's agent steps,
//     Q(s, a) for every action a by branch_returns (branch_returns.h: a, then
//     the greedy policy, deterministic), A(s, a) = Q(s, a) - sum_a pi(a|s) Q(s, a),
//     then `epochs` Adam steps on the all-action surrogate
//       L = -(1/S) sum_s sum_a pi(a|s) A(s, a) / sd(A) - c_H (1/S) sum_s H(pi(.|s))
//     over the S branched states, pi recomputed at every epoch (A fixed;
//     sd over the batch's S K advantages). The sampled trajectories only pick
//     the states; every action of a state is credited with its own outcome.
// The entropy coefficient falls linearly from entropy_coef to entropy_final
// over the run's updates, like the step size.
// Episodes that end without any agent step contribute no sample. The Adam
// step size falls linearly from lr to lr_final over the run's updates.
// The batch of update u is episodes [u M, (u+1) M) of the seed, ordered by
// episode number; episode k's policy samples (and vine's branch draws) come
// from its own stream Rng(episode_seed(seed ^ salt, k)) (episode_streams.h),
// ppo's shuffle of update u from Rng(episode_seed(seed ^ salt, u)). So a run
// resumed from a checkpoint continues exactly as an uninterrupted one, and
// the batch does not depend on num_envs.
// Data-parallel (dist/comm.h): each rank plays its share dist::share(M) of
// the batch's episodes; every sum over the batch (the gradients, the value
// baseline's gradients, the advantages' mean and variance, the mean return,
// entropy, sample counts) runs over all ranks' samples, N is the whole
// batch's, ppo's minibatches are drawn from the whole batch's sample order,
// and every rank takes the same Adam step. Every rank must start from the
// same parameters and learner state; they then stay identical.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "env/batch_env.h"
#include "env/vec_env.h"
#include "nn/adam.h"
#include "nn/mlp.h"
#include "rl/checkpoint.h"
#include "rl/imitation.h"
#include "rl/policy.h"

namespace squawk::rl {

struct TrainConfig {
  std::string estimator = "improved";  // "vpg" | "improved" | "ppo" | "vine"
  long long episodes = 20000;          // [-] total training episodes (the schedules span them)
  long long stop_at = 0;               // [-] the run ends after this many (0: at `episodes`)
  int episodes_per_update = 32;        // [-] M
  int num_envs = 32;                   // [-] VecEnv slots
  double lr = 1e-3;                    // [-] Adam step size at the start ...
  double lr_final = 1e-3;              // [-] ... decayed linearly to this at `episodes`
  double gamma = 0.99;                 // [-] improved: discount of the reward-to-go
  double entropy_coef = 0.01;          // [-] improved/ppo: entropy bonus c_H at the start ...
  std::optional<double> entropy_final; // [-] ... decayed linearly to this at `episodes` (none: constant)
  double lambda = 1.0;                 // [-] improved/ppo: GAE lambda (1 = reward-to-go - V)
  int epochs = 4;                      // [-] ppo: passes over the batch; vine: Adam steps per batch
  int minibatches = 1;                 // [-] ppo: Adam steps per pass (parts of the shuffled batch)
  double branch_fraction = 0.25;       // [-] vine: share of agent steps branched, (0, 1]
  double clip = 0.2;                   // [-] ppo: ratio clip
  double grad_clip = 1.0;              // [-] global gradient-norm clip (0 = none)
  std::vector<int> value_hidden = {64, 64};  // [-] improved: value MLP widths ({} = mean baseline)
  int value_iters = 5;                 // [-] improved: value-fit steps per update
  long long eval_every = 2000;         // [-] episodes between evaluations (0 = none)
  long long eval_episodes = 200;       // [-] episodes per evaluation
  uint64_t seed = 0;

  // Where this run ends: stop_at, or episodes when stop_at is 0.
  long long end_episodes() const { return stop_at > 0 ? stop_at : episodes; }
  // Sets the step size `new_lr` and the final one: `final_lr` when given, else
  // lr_final scaled by new_lr / lr, so the schedule keeps its shape.
  void set_lr(double new_lr, std::optional<double> final_lr);

  Status validate() const;
};

// Ok unless `config` asks for a learner `policy` cannot drive (ppo and vine
// need Policy::log_probs, vine a discrete head). vine also needs the compiled
// HorizontalCR batch (BatchEnv::horizontal()) to branch from snapshots; on
// other batches it takes no step.
Status check_learner(const Policy& policy, const TrainConfig& config);

struct UpdateStats {
  long long episodes = 0;    // [-] episodes in the batch
  int samples = 0;           // [-] agent steps in the batch
  double mean_return = 0.0;  // [-]
  double success_rate = 0.0; // [-] 0..1
  double entropy = 0.0;      // [-] mean policy entropy over the samples
  double grad_norm = 0.0;    // [-] before clipping
  double value_loss = 0.0;   // [-] value MLP mean squared error (improved, before fitting)
  double advantage_sd = 0.0;   // [reward] improved/ppo: advantages' deviation before normalising
  double clip_fraction = 0.0;  // [-] ppo: share of the batch's samples clipped in the last pass
  bool interrupted = false;  // the progress callback stopped the batch: no step was taken
};

// Called during an update's collection with the episodes finished so far in
// its batch (in a job of several ranks: this rank's count times the number of
// ranks, at most M); returning false abandons the batch (no step, updates()
// unchanged, so the next update() redoes the same batch exactly). In a job of
// several ranks, one rank's false abandons the batch on every rank.
using UpdateProgress = std::function<bool(long long done_in_batch)>;

class Trainer {
 public:
  // `update_index` is the number of updates already taken (resume).
  // `envs`: the batch the episodes are played on (env/batch_env.h).
  Trainer(Policy& policy, env::BatchEnv& envs, const TrainConfig& config, long long update_index);
  env::BatchEnv& envs() { return envs_; }
  UpdateStats update(const UpdateProgress& progress = {});
  nn::Adam& adam() { return adam_; }
  long long updates() const { return updates_; }
  // The value baseline's parameters and optimiser, for checkpoints (empty /
  // null without a value baseline).
  std::vector<float>& value_params() { return value_params_; }
  nn::Adam* value_adam() { return value_adam_.get(); }
  // Continues from a checkpoint's learner state (resume): when it holds Adam
  // moments, those, the Adam step and the value baseline with its Adam state.
  // Error unless the sizes are exactly this learner's.
  Status restore(const TrainState& s);
  // restore's inverse: the policy's parameters, Adam moments and step, and
  // the value baseline with its Adam state into `s` (s.progress untouched).
  void save(TrainState& s);
  // Fits the value baseline to the discounted returns (config gamma) of
  // `flights` (a teacher's episodes, rl/imitation.h) before the first update:
  // `epochs` passes over its steps in shuffled minibatches of `batch` rows
  // (a shuffle from Rng(seed)), one step of the value Adam per minibatch on
  // the mean squared error. Returns that error over all the steps before
  // and after. Errors: no value baseline, a job of several ranks, or
  // flights whose sizes disagree.
  struct ValueFit {
    double before = 0.0, after = 0.0;  // [reward^2]
  };
  Result<ValueFit> pretrain_value(const TeacherFlights& flights, int epochs, int batch,
                                  uint64_t seed);

 private:
  struct Sample {
    ActionSample action;
    float reward = 0.0f;
  };
  // One episode of this rank's share: its agent steps in order.
  struct Episode {
    std::vector<float> obs;  // [T, obs]
    std::vector<Sample> samples;
    std::vector<env::HorizontalCrEnv> branches;  // vine: snapshots before branched agent steps
  };
  // Plays this rank's share of the batch into episodes_; false when `progress` stopped it.
  bool collect(const UpdateProgress& progress);
  // Sums the policy gradients over the ranks and takes the Adam step; returns the norm.
  double step_all();
  // Fills coef (one per batch sample) for the estimator, st.value_loss and st.advantage_sd.
  void coefficients(std::vector<float>& coef, UpdateStats& st);
  // Advantages A_t (before normalisation) from the value MLP's v = V(s_t) and
  // the reward-to-go g.
  std::vector<double> advantages(const std::vector<float>& v, const std::vector<float>& g) const;
  // ppo: `epochs` x `minibatches` clipped-ratio steps from the normalised
  // advantages in coef (each times 1/N) with entropy bonus c_h. Sets
  // st.entropy from the first pass (sample-weighted), st.grad_norm from
  // the first step and st.clip_fraction from the last pass.
  void clipped_steps(const std::vector<float>& coef, const std::vector<ActionSample>& acts, double c_h,
                     UpdateStats& st);
  // vine: the all-action steps on the branched states; sets st.entropy and
  // st.grad_norm from the first step. A policy error leaves the policy as is.
  void vine_steps(double c_h, UpdateStats& st);

  Policy& policy_;
  env::BatchEnv& envs_;
  TrainConfig cfg_;
  nn::Adam adam_;
  long long updates_ = 0;
  // Value baseline (improved estimator with value_hidden).
  std::unique_ptr<nn::Mlp> value_;
  std::vector<float> value_params_, value_grads_;
  std::unique_ptr<nn::Adam> value_adam_;
  // Per slot: the running episode and its number.
  std::vector<Episode> slot_episode_;
  std::vector<uint64_t> slot_index_;
  // This rank's share of the batch: episode first_ + i in episodes_[i].
  uint64_t first_ = 0;
  std::vector<Episode> episodes_;
  // The share's finished episodes, concatenated in episode order.
  std::vector<float> batch_obs_;
  std::vector<Sample> batch_samples_;
  std::vector<int> batch_lengths_;
  std::vector<env::HorizontalCrEnv> branch_states_;  // vine
  // The whole batch (all ranks): its sample count N, and the index of this
  // rank's first sample in the batch's sample order.
  long long samples_ = 0, offset_ = 0;
};

}  // namespace squawk::rl
