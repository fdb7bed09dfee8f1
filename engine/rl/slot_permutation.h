// Interchangeable objects in an observation: StaticObstacleEnv-v0 lists its ten
// restricted areas as four blocks of ten numbers (bearing cos, distance,
// radius, bearing sin), area i at offset i of every block, in an order that
// carries no meaning. A rule that treats the areas alike (envs/policies/
// static_obstacle.lua) gives the same action whatever their order, so every
// labelled decision stands for count! orderings; imitation (rl/imitation.h)
// can show the student a fresh one in every batch.
//
// A layout is `count` slots and the offsets of its blocks: slot i's numbers
// are obs[start + i] for each start. Permuting moves all of a slot's numbers
// together and leaves every number outside the blocks where it is.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/rng.h"
#include "core/status.h"

namespace squawk::rl {

struct SlotLayout {
  int count = 0;            // [-] slots; 0 or 1: nothing to permute
  std::vector<int> starts;  // [-] offset of each block in the observation
};

// "COUNT:START,START,..." for observations of obs_size numbers: COUNT >= 2,
// at least one block, each block inside the observation and no two blocks
// overlapping; the error names the spec and what was expected.
Result<SlotLayout> parse_slot_layout(const std::string& spec, int obs_size);

// Permutes the slots of one observation uniformly at random (Fisher-Yates,
// count - 1 draws from rng).
void permute_slots(std::span<float> obs, const SlotLayout& layout, Rng& rng);

}  // namespace squawk::rl
