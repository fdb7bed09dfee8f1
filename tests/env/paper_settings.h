// The paper scenario's evaluation draws for tests (scenarios/horizontal_cr.lua,
// eval table): intruder time to loss of separation in [300, 1000] s and a
// 600 s conflict look-ahead, on the paper rules. The scenario also lifts the
// ground-phase speed cap (speed_cap = 0); `uncapped` = false keeps the
// config's default cap.
#pragma once

#include "env/horizontal_cr.h"

namespace squawk::test {

inline env::HorizontalCrConfig paper_eval_config(bool uncapped) {
  env::HorizontalCrConfig c;
  if (uncapped) c.limits.speed_cap = 0.0;
  c.tlos = {300, 1000};
  c.lookahead = 600;
  return c;
}

}  // namespace squawk::test
