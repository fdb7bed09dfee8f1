// play: the act -> step loop. Every run of decisions over numbered episodes
// of an env::BatchEnv (the compiled VecEnv or Lua files) goes through it: evaluation (evaluator.h),
// the learners' collection (vpg.h), imitation (imitation.h), the pretraining corpus and the tiny
// vocabulary of the GPT-2 policy.
//
// play(envs, seed, first, count, driver) clears envs.completed(), starts
// episodes first..first+count-1 of `seed` (env/batch_env.h) and, while any slot
// waits for a decision, runs one turn:
//   1. driver.choose(turn): fill turn.actions[r] for every waiting row r;
//   2. envs.step() with turn.actions[r]'s first envs.action_size() components
//      (what the env's header says they mean: VecEnv units of the heading step,
//      LuaBatchEnv a grid class or the continuous components);
//   3. driver.after(turn): the rewards and ends of that step; false stops the run.
// Turn shapes: slots [n] (the waiting slots, ascending; valid in both
// calls), obs [n, obs_size] row-major (valid in choose only: the step
// replaces it), actions [n], rewards [n] and dones [n] (valid in after).
// Returns true when every episode ended, false when after() stopped the run,
// or choose()'s error, or the environment's (envs.error() after a step). On return envs.completed()
// holds the run's ended episodes in the order they ended (a stopped run: those that ended so far).
//
// policy_choice() is the choose of a Policy: Policy::act on the turn, row r
// drawing from its episode's own stream (episode_streams.h, seeded by
// `streams`), the mode instead of a sample when `greedy`. A policy's failure
// is left in Policy::error() for the caller to check after the run (every
// rank of a data-parallel job then plays the same number of turns).
#pragma once

#include <cstdint>
#include <functional>
#include <span>

#include "core/status.h"
#include "env/batch_env.h"
#include "rl/episode_streams.h"
#include "rl/policy.h"

namespace squawk::rl {

struct Turn {
  std::span<const int> slots;       // [n] waiting slots
  std::span<const float> obs;       // [n, obs_size] (choose only)
  std::span<ActionSample> actions;  // [n] what choose decided
  std::span<const double> rewards;  // [n] (after only)
  std::span<const uint8_t> dones;   // [n] 1 where that slot's episode ended (after only)
};

struct Driver {
  std::function<Status(Turn&)> choose;
  std::function<bool(const Turn&)> after;  // empty: never stops the run
};

Result<bool> play(env::BatchEnv& envs, uint64_t seed, uint64_t first, uint64_t count,
                  const Driver& driver);

std::function<Status(Turn&)> policy_choice(Policy& policy, env::BatchEnv& envs,
                                           EpisodeStreams& streams, bool greedy);

}  // namespace squawk::rl
