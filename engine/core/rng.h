// Rng: the engine's seeded random source. Every random draw in squawk goes
// through one of these, so one seed reproduces a run bit for bit on a build.
//
// Algorithm: xoshiro256** seeded through splitmix64 (both public-domain
// algorithms by Blackman & Vigna, implemented here from their description).
// The draw functions below are defined by this file, not by the standard
// library's distributions, so results do not change with the C++ library.
#pragma once

#include <cstdint>

namespace squawk {

class Rng {
 public:
  explicit Rng(uint64_t seed = 0) { reseed(seed); }
  void reseed(uint64_t seed);

  uint64_t next_u64();
  // Uniform double in [0, 1) with 53 random bits.
  double uniform();
  // Uniform double in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform integer in [lo, hi] (both inclusive), without modulo bias.
  int64_t uniform_int(int64_t lo, int64_t hi);
  // Standard normal (Box-Muller; the second value is cached).
  double normal();
  double normal(double mean, double sd) { return mean + sd * normal(); }
  // A new generator whose stream is independent of this one's continuation;
  // advances this generator by one draw.
  Rng fork();

  uint64_t seed() const { return seed_; }

 private:
  uint64_t s_[4] = {0, 0, 0, 0};
  uint64_t seed_ = 0;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

}  // namespace squawk
