#include "env/fleet.h"

#include <algorithm>
#include <cmath>

#include "core/geo.h"
#include "core/units.h"

namespace squawk::env {

using units::kDeg;

namespace {
constexpr double kRadToDeg = 1.0 / kDeg;
}  // namespace

void Fleet::clear() {
  for (auto* v : {&lat_, &lon_, &hdg_, &tas_, &sel_hdg_, &sel_tas_, &cos_hdg_, &sin_hdg_,
                  &cos_lat_, &sin_lat_, &dlat_, &cos_dlat_, &sin_dlat_})
    v->clear();
}

int Fleet::add(double lat, double lon, double hdg, double tas) {
  lat_.push_back(lat);
  lon_.push_back(lon);
  hdg_.push_back(hdg);
  tas_.push_back(tas);
  sel_hdg_.push_back(geo::wrap360(hdg));
  sel_tas_.push_back(tas);
  cos_hdg_.push_back(std::cos(hdg * kDeg));
  sin_hdg_.push_back(std::sin(hdg * kDeg));
  cos_lat_.push_back(std::cos(lat * kDeg));
  sin_lat_.push_back(std::sin(lat * kDeg));
  dlat_.push_back(0.0);
  cos_dlat_.push_back(1.0);
  sin_dlat_.push_back(0.0);
  return static_cast<int>(lat_.size()) - 1;
}

void Fleet::set_heading(int i, double hdg_deg) { sel_hdg_[static_cast<size_t>(i)] = geo::wrap360(hdg_deg); }
void Fleet::set_speed(int i, double tas) { sel_tas_[static_cast<size_t>(i)] = tas; }

void Fleet::step(double dt, const FleetLimits& lim) {
  if (lim.bank != bank_) {
    bank_ = lim.bank;
    rate_factor_ = units::rad_to_deg(units::kG0 * std::tan(lim.bank * kDeg));
  }
  const double dv_max = lim.accel * dt;
  const double dlat_per_ms = dt / units::kREarth;  // [rad] per m/s of northward speed
  const double cap = lim.speed_cap > 0.0 ? lim.speed_cap : 1e300;
  // Raw, non-aliasing views: lets the compiler keep values in registers.
  double* __restrict lat = lat_.data();
  double* __restrict lon = lon_.data();
  double* __restrict hdg = hdg_.data();
  double* __restrict tas = tas_.data();
  const double* __restrict sel_hdg = sel_hdg_.data();
  const double* __restrict sel_tas = sel_tas_.data();
  double* __restrict ch = cos_hdg_.data();
  double* __restrict sh = sin_hdg_.data();
  double* __restrict cl = cos_lat_.data();
  double* __restrict sl = sin_lat_.data();
  double* __restrict dl = dlat_.data();
  double* __restrict cd = cos_dlat_.data();
  double* __restrict sd = sin_dlat_.data();
  const size_t n = lat_.size();
  for (size_t i = 0; i < n; ++i) {
    // 1. speed
    const double target = std::min(sel_tas[i], cap);
    double v = tas[i];
    if (v != target) {
      const double dv = target - v;
      v = std::fabs(dv) > dv_max ? v + std::copysign(dv_max, dv) : target;
      tas[i] = v;
    }
    // 2. heading
    const double want = sel_hdg[i];
    if (hdg[i] != want) {
      const double h = hdg[i];
      const double rate = rate_factor_ / std::max(v, 0.01);
      // Both angles lie in [0, 360): BlueSky's (x + 180) % 360 - 180 by branches.
      double del = want - h;
      if (del >= 180.0) del -= 360.0;
      if (del < -180.0) del += 360.0;
      double next = std::fabs(del) > dt * rate ? h + std::copysign(dt * rate, del) : want;
      if (next < 0.0) next += 360.0;
      if (next >= 360.0) next -= 360.0;
      hdg[i] = next;
      ch[i] = std::cos(next * kDeg);
      sh[i] = std::sin(next * kDeg);
    }
    // 3. position; cos/sin of latitude rotated by the step's increment
    const double dlat = dlat_per_ms * v * ch[i];  // [rad]
    if (dlat != dl[i]) {
      dl[i] = dlat;
      if (std::fabs(dlat) < 1e-3) {
        // Taylor series; the first omitted terms (x^6/720, x^7/5040) are below
        // 2e-21 for |x| < 1e-3, i.e. under half an ulp of the results.
        const double x2 = dlat * dlat;
        cd[i] = 1.0 - x2 * (0.5 - x2 * (1.0 / 24.0));
        sd[i] = dlat * (1.0 - x2 * (1.0 / 6.0 - x2 * (1.0 / 120.0)));
      } else {
        cd[i] = std::cos(dlat);
        sd[i] = std::sin(dlat);
      }
    }
    lat[i] += dlat * kRadToDeg;
    const double c = cl[i] * cd[i] - sl[i] * sd[i];
    const double s = sl[i] * cd[i] + cl[i] * sd[i];
    cl[i] = c;
    sl[i] = s;
    lon[i] += dlat_per_ms * kRadToDeg * v * sh[i] / c;
  }
}

}  // namespace squawk::env
