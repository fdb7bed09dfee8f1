// Independent simulations side by side in one process: four command stacks,
// each on its own thread, end in exactly the state of the same run alone
// (no shared mutable state in engine/sim and engine/command).
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <string>
#include <thread>

#include "command/stack.h"
#include "core/rng.h"

using namespace squawk;

namespace {
// 60 aircraft converging on a point with detection and MVP resolution on,
// a third on a route, deletions and creations queued over time; the seed
// draws the traffic. Returns the stack's snapshot after 300 s.
std::string run(uint64_t seed) {
  command::Stack st(seed);
  Rng rng(seed);
  std::string lines = "ASAS ON;RESO MVP";
  for (int i = 0; i < 60; ++i) {
    const double brg = rng.uniform(0.0, 360.0), d = rng.uniform(0.2, 0.6);
    const double lat = 52.0 + d * std::cos(brg * 0.0174533), lon = 4.0 + d * std::sin(brg * 0.0174533) / 0.6;
    const std::string id = "T" + std::to_string(i);
    lines += ";CRE " + id + " A320 " + std::to_string(lat) + " " + std::to_string(lon) + " " +
             std::to_string(std::fmod(brg + 180.0, 360.0)) + " FL" + std::to_string(200 + 10 * (i % 3)) + " 250";
    if (i % 3 == 0) lines += ";ADDWPT " + id + " 52.0 " + std::to_string(4.5 + 0.01 * i) + ";LNAV " + id + " ON";
    if (i % 7 == 0) st.schedule(rng.uniform(10.0, 200.0), "DEL " + id);
  }
  REQUIRE(st.exec(lines).is_ok());
  st.schedule(150.0, "CRE X1 B744 52.2 4.2 180 FL210 280");
  REQUIRE(st.run_until(300.0).is_ok());
  REQUIRE(st.sim().cd().total_conflicts() > 0);  // resolution was exercised
  return st.snapshot();
}
}  // namespace

TEST_CASE("four simulations on four threads end bit for bit as each alone") {
  std::array<std::string, 4> alone, together;
  for (size_t k = 0; k < 4; ++k) alone[k] = run(k + 1);
  std::array<std::thread, 4> threads;
  for (size_t k = 0; k < 4; ++k) threads[k] = std::thread([&together, k] { together[k] = run(k + 1); });
  for (std::thread& t : threads) t.join();
  for (size_t k = 0; k < 4; ++k) {
    CAPTURE(k);
    CHECK(together[k] == alone[k]);
  }
  // The runs differ from each other, so the comparison can fail.
  CHECK(alone[0] != alone[1]);
}
