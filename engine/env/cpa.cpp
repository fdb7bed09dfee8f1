#include "env/cpa.h"

#include <algorithm>
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
  const double dist = std::sqrt(p.x * p.x + p.y * p.y);
  Vec2 d{p.x + w.x * tcpa, p.y + w.y * tcpa};  // intruder relative to ownship at CPA
  double dabs = std::sqrt(d.x * d.x + d.y * d.y);
  if (dabs <= 10.0) {  // head-on: pick a side perpendicular to the line of sight
    dabs = 10.0;
    d = {p.y / dist * 10.0, -p.x / dist * 10.0};
  }
  const double t = std::max(std::fabs(tcpa), 1e-6);
  double scale;
  if (radius < dist && dabs < dist) {
    const double erratum = std::cos(std::asin(radius / dist) - std::asin(dabs / dist));
    scale = (radius / erratum - dabs) / (t * dabs);
  } else {
    scale = (radius - dabs) / (t * dabs);
  }
  return {-scale * d.x, -scale * d.y};
}

}  // namespace squawk::env
