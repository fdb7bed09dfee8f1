// Imitation: behaviour cloning with DAgger rounds, a labelled experiment beside
// the policy-gradient learners (vpg.h). It asks what a policy class can hold,
// not what reinforcement learning finds in it, and is never the paper's
// fine-tuning.
//
// Round 0 flies `teacher` (greedy) over config.episodes training episodes;
// round r > 0 flies the student (sampled) over the next config.episodes. Every
// decision is labelled with the teacher's greedy action. After each round the
// student takes config.epochs passes over all labelled decisions so far, in
// shuffled batches of config.batch rows, one Adam step per batch on
//   L = -(1/B) sum_r log pi(y_r | s_r)    (Policy::accumulate_gradient, coef 1/B),
// y_r the teacher's class (discrete heads) or its action values (continuous
// heads: the Gaussian log-likelihood of the teacher's numbers, log sigma
// included unless held: config.held_tail > 0 leaves the last held_tail
// entries of params() where they are, for a Gaussian MlpPolicy its log sigmas,
// so that the means are fitted at a fixed spread, the mean squared error).
// config.saturated_label > 1 (continuous heads) fits every label component at
// the box edge (|y| = 1) at sign(y) * saturated_label instead: the action is
// clipped to [-1, 1] when flown, so a mean pushed past the edge flies the
// rule's full rate where a mean fitted to the edge itself stays inside it.
// config.permute (rl/slot_permutation.h), when it has slots, shows each batch
// row with its slots in a fresh random order (the label unchanged): for a
// teacher that treats those objects alike; the held-out figures read the
// observations as flown.
// Agreement: the share of held-out decisions (config.holdout episodes of
// config.holdout_seed, flown by the teacher) where the student's greedy class
// is the teacher's (continuous: where every component of its greedy action,
// clipped to [-1, 1] as flown, is within kContinuousAgreement of the
// teacher's); action_error the mean over the same decisions of the largest
// absolute difference between the two greedy actions' (clipped) components.
// Shapes: decisions [N, obs_size] row-major, labels [N] actions.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/status.h"
#include "env/batch_env.h"
#include "rl/policy.h"
#include "rl/slot_permutation.h"

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
  size_t held_tail = 0;       // [-] trailing params() entries left unchanged (0: all trained)
  SlotLayout permute{};       // slots shuffled in every batch row (count < 2: none, no draws)
  float saturated_label = 1;  // [-] target of a label component at +-1 (>= 1; 1: as labelled)
};

inline constexpr double kContinuousAgreement = 0.1;  // [-] of the [-1, 1] action range

// The teacher's round-0 flights, episode by episode (what a value baseline
// can be fitted to before fine-tuning): obs [T, obs_size] of all episodes
// concatenated in the order they ended, rewards [T], lengths [episodes].
struct TeacherFlights {
  std::vector<float> obs;
  std::vector<double> rewards;
  std::vector<int> lengths;
};

struct ImitationEpoch {
  int round = 0, epoch = 0;
  bool teacher_flew = true;   // who flew this round's episodes
  double flight_success = 0;  // [-] success rate of this round's flights
  long long decisions = 0;    // [-] labelled decisions so far
  double agreement = 0;       // [-] held-out agreement after this epoch
  double action_error = 0;    // [-] held-out mean |student - teacher| greedy action value
};

// Both policies must have the same discrete classes (action_values), or both
// none (continuous), and the same obs size; the student must be trainable.
// on_epoch runs after every epoch (the caller saves or reports there);
// returning an error stops with that error. `flights`, when given, receives
// round 0's teacher flights.
// `pilot`'s own greedy flights over episodes 0 .. count-1 of `seed` on `envs`
// (the round-0 flights imitate() records of its teacher), for a value baseline
// fitted before fine-tuning a policy that did not come from a rule.
Result<TeacherFlights> greedy_flights(Policy& pilot, env::BatchEnv& envs, uint64_t seed,
                                      uint64_t count);

Status imitate(Policy& student, Policy& teacher, env::BatchEnv& envs, const ImitationConfig& config,
               const std::function<Status(const ImitationEpoch&)>& on_epoch,
               TeacherFlights* flights = nullptr);

}  // namespace squawk::rl
