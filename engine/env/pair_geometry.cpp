#include "env/pair_geometry.h"

#include <cmath>

#include "core/cpa.h"

namespace squawk::env {

Cpa closest_approach(Vec2 p, Vec2 w, double radius) {
  const cpa::Horizontal h = cpa::horizontal(p.x, p.y, w.x, w.y, radius);
  Cpa c;
  c.tcpa = h.tcpa;
  c.dcpa = std::sqrt(h.dcpa2);
  if (h.enters) {
    c.t_in = h.t_in;
    c.t_out = h.t_out;
  }
  return c;
}

Vec2 mvp_velocity_change(Vec2 p, Vec2 w, double tcpa, double radius) {
  const cpa::Push h = cpa::mvp_horizontal(p.x, p.y, std::sqrt(p.x * p.x + p.y * p.y), w.x, w.y, tcpa, radius);
  return {-h.e, -h.n};
}

}  // namespace squawk::env
