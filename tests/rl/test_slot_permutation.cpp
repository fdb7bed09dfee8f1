// Slot permutation (rl/slot_permutation.h): the layout parser's refusals, and
// permute_slots moving each slot's numbers together, uniformly, and nothing else.
#include <doctest/doctest.h>

#include <cstdlib>
#include <numeric>
#include <vector>

#include "rl/slot_permutation.h"

using namespace squawk;

TEST_CASE("slot layout: StaticObstacle's ten areas, and what is refused") {
  auto l = rl::parse_slot_layout("10:0,13,23,33", 43);
  REQUIRE_MESSAGE(l.is_ok(), l.status().message());
  CHECK(l->count == 10);
  CHECK(l->starts == std::vector<int>{0, 13, 23, 33});
  CHECK(rl::parse_slot_layout("10", 43).status().message() ==
        "slot layout '10': expected COUNT:START[,START...] (integers)");
  CHECK(rl::parse_slot_layout("10:0,x", 43).status().message() ==
        "slot layout '10:0,x': expected COUNT:START[,START...] (integers)");
  CHECK(rl::parse_slot_layout("1:0", 43).status().message() ==
        "slot layout '1:0': expected at least 2 slots");
  CHECK(rl::parse_slot_layout("10:0,34", 43).status().message() ==
        "slot layout '10:0,34': block 34..43 lies outside the observation's 43 numbers");
  CHECK(rl::parse_slot_layout("10:0,5", 43).status().message() ==
        "slot layout '10:0,5': blocks at 0 and 5 overlap (each holds 10 numbers)");
}

TEST_CASE("permute_slots moves every slot's numbers together, uniformly, and nothing else") {
  auto l = rl::parse_slot_layout("10:0,13,23,33", 43);
  REQUIRE(l);
  Rng rng(3);
  std::vector<int> first(10, 0);  // how often each slot lands in position 0
  const int draws = 10000;
  for (int k = 0; k < draws; ++k) {
    std::vector<float> obs(43);
    std::iota(obs.begin(), obs.end(), 0.0f);
    rl::permute_slots(obs, *l, rng);
    for (const int i : {10, 11, 12}) CHECK(obs[static_cast<size_t>(i)] == static_cast<float>(i));
    std::vector<int> seen(10, 0);
    for (int i = 0; i < 10; ++i) {
      const int slot =
          static_cast<int>(obs[static_cast<size_t>(i)]);  // block 0 holds the slot numbers
      REQUIRE(slot >= 0);
      REQUIRE(slot < 10);
      ++seen[static_cast<size_t>(slot)];
      for (const int s : {13, 23, 33})
        CHECK(obs[static_cast<size_t>(s + i)] == static_cast<float>(s + slot));
    }
    CHECK(seen == std::vector<int>(10, 1));
    ++first[static_cast<size_t>(obs[0])];
  }
  for (const int n : first) CHECK(std::abs(n - draws / 10) < 150);  // 1000 +- 5 binomial sd
}
