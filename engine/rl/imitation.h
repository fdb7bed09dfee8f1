// Imitation: behaviour cloning with DAgger rounds, a labelled experiment beside
// the policy-gradient learners (vpg.h). It asks what a policy class can hold,
// not what reinforcement learning finds in it, and is never the paper's
// fine-tuning.
//
// Round 0 flies `teacher` (greedy) over config.episodes training episodes;
// round r > 0 flies the student (sampled) over the next config.episodes. Every
// decision is labelled with the teacher's greedy class. After each round the
// student takes config.epochs passes over all labelled decisions so far, in
// shuffled batches of config.batch rows, one Adam step per batch on
//   L = -(1/B) sum_r log pi(y_r | s_r)    (Policy::accumulate_gradient, coef 1/B).
// Agreement: the share of held-out decisions (config.holdout episodes of
// config.holdout_seed, flown by the teacher) where the student's greedy class
// is the teacher's.
// Shapes: decisions [N, obs_size] row-major, labels [N] class indices.
#pragma once

#include <cstdint>
#include <functional>

#include "core/status.h"
#include "env/vec_env.h"
#include "rl/policy.h"

namespace squawk::rl {

struct ImitationConfig {
  long long episodes = 2000;  // [-] episodes flown per round
  int rounds = 1;             // [-] round 0: the teacher flies; later rounds: the student
  int epochs = 8;             // [-] passes over the labelled decisions after each round
  int batch = 64;             // [-] decisions per Adam step
  float lr = 3e-4f;           // [-] Adam step size
  float grad_clip = 1.0f;     // [-] global gradient-norm clip
  uint64_t seed = 1;          // training episodes, shuffling and the student's samples
  long long holdout = 200;    // [-] held-out episodes
  uint64_t holdout_seed = 2;  // must differ from seed
};

struct ImitationEpoch {
  int round = 0, epoch = 0;
  bool teacher_flew = true;   // who flew this round's episodes
  double flight_success = 0;  // [-] success rate of this round's flights
  long long decisions = 0;    // [-] labelled decisions so far
  double agreement = 0;       // [-] held-out agreement after this epoch
};

// Both policies must have the same discrete classes (action_values) and obs
// size; the student must be trainable. on_epoch runs after every epoch (the
// caller saves or reports there); returning an error stops with that error.
Status imitate(Policy& student, Policy& teacher, env::VecEnv& envs, const ImitationConfig& config,
               const std::function<Status(const ImitationEpoch&)>& on_epoch);

}  // namespace squawk::rl
