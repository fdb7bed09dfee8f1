#include "env/cpa.h"

#include <algorithm>
#include <cmath>

namespace squawk::env {

Cpa closest_approach(Vec2 p, Vec2 w, double radius) {
  Cpa c;
  const double w2 = std::max(w.x * w.x + w.y * w.y, 1e-6);
  const double vrel = std::sqrt(w2);
  const double d2 = p.x * p.x + p.y * p.y;
  c.tcpa = -(p.x * w.x + p.y * w.y) / w2;
  const double dcpa2 = std::fabs(d2 - c.tcpa * c.tcpa * w2);
  c.dcpa = std::sqrt(dcpa2);
  const double r2 = radius * radius;
  if (dcpa2 < r2) {
    const double dt = std::sqrt(std::max(0.0, r2 - dcpa2)) / vrel;
    c.t_in = c.tcpa - dt;
    c.t_out = c.tcpa + dt;
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
