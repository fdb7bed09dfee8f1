// step() must not allocate once its buffers have grown (simulation.h).
// This file replaces the global operator new for the whole test_sim
// executable to count allocations; behaviour is otherwise unchanged.
#include <doctest/doctest.h>

#include <atomic>
#include <cstdlib>
#include <string>
#include <new>

#include "core/units.h"
#include "sim/simulation.h"

namespace {
std::atomic<long> g_allocs{0};
}  // namespace

void* operator new(std::size_t n) {
  g_allocs.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

using namespace squawk;
using namespace squawk::sim;

namespace {
// BlueSky-Gym's scene: ownship at altitude 0, five CRECONFS intruders, dt 5 s.
Simulation gym_scene(bool cd) {
  Simulation sim(3);
  REQUIRE(sim.set_dt(5.0).is_ok());
  PerformanceOptions po;
  po.ground_cap = true;
  REQUIRE(sim.set_performance_options(po).is_ok());
  if (cd) sim.set_reso(true);
  REQUIRE(sim.create("KL001", "A320", 52.0, 4.0, 0.0, 0.0, 150.0).is_ok());
  const double dpsi[] = {60, 120, 180, 240, 300};
  for (int k = 0; k < 5; ++k)
    REQUIRE(sim.creconfs(std::to_string(k), "A320", "KL001", dpsi[k], units::nm_to_m(k), 300.0 + 100.0 * k).is_ok());
  return sim;
}
}  // namespace

TEST_CASE("step() does not allocate: env shape with CD off") {
  Simulation sim = gym_scene(false);
  REQUIRE(sim.set_heading("KL001", 45.0).is_ok());
  for (int k = 0; k < 10; ++k) sim.step();
  const long before = g_allocs.load();
  for (int k = 0; k < 3000; ++k) {
    if (k % 10 == 0) REQUIRE(sim.set_heading("KL001", (k % 20 == 0) ? 30.0 : 330.0).is_ok());
    sim.step();
  }
  CHECK(g_allocs.load() - before == 0);
}

TEST_CASE("step() with CD and MVP allocates only while buffers grow") {
  Simulation sim = gym_scene(true);
  for (int k = 0; k < 10; ++k) sim.step();
  const long before = g_allocs.load();
  for (int k = 0; k < 3000; ++k) sim.step();
  CHECK(g_allocs.load() - before <= 20);
  MESSAGE("allocations in 3000 steps with CD+MVP after warm-up: " << g_allocs.load() - before);
}
