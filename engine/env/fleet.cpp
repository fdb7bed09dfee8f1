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
  for (size_t i = 0; i < lat_.size(); ++i) {
    // 1. speed
    const double target = std::min(sel_tas_[i], cap);
    double tas = tas_[i];
    if (tas != target) {
      const double dv = target - tas;
      tas = std::fabs(dv) > dv_max ? tas + std::copysign(dv_max, dv) : target;
      tas_[i] = tas;
    }
    // 2. heading
    const double want = sel_hdg_[i];
    if (hdg_[i] != want) {
      const double hdg = hdg_[i];
      const double rate = rate_factor_ / std::max(tas, 0.01);
      double del = std::fmod(want - hdg + 180.0, 360.0);
      if (del < 0) del += 360.0;
      del -= 180.0;
      const double next = geo::wrap360(std::fabs(del) > dt * rate ? hdg + std::copysign(dt * rate, del) : want);
      hdg_[i] = next;
      cos_hdg_[i] = std::cos(next * kDeg);
      sin_hdg_[i] = std::sin(next * kDeg);
    }
    // 3. position; cos/sin of latitude rotated by the step's increment
    const double dlat = dlat_per_ms * tas * cos_hdg_[i];  // [rad]
    if (dlat != dlat_[i]) {
      dlat_[i] = dlat;
      if (std::fabs(dlat) < 1e-3) {
        // Taylor series; the first omitted terms (x^6/720, x^7/5040) are below
        // 2e-21 for |x| < 1e-3, i.e. under half an ulp of the results.
        const double x2 = dlat * dlat;
        cos_dlat_[i] = 1.0 - x2 * (0.5 - x2 * (1.0 / 24.0));
        sin_dlat_[i] = dlat * (1.0 - x2 * (1.0 / 6.0 - x2 * (1.0 / 120.0)));
      } else {
        cos_dlat_[i] = std::cos(dlat);
        sin_dlat_[i] = std::sin(dlat);
      }
    }
    lat_[i] += dlat * kRadToDeg;
    const double c = cos_lat_[i] * cos_dlat_[i] - sin_lat_[i] * sin_dlat_[i];
    const double s = sin_lat_[i] * cos_dlat_[i] + cos_lat_[i] * sin_dlat_[i];
    cos_lat_[i] = c;
    sin_lat_[i] = s;
    lon_[i] += dlat_per_ms * kRadToDeg * tas * sin_hdg_[i] / c;
  }
}

}  // namespace squawk::env
