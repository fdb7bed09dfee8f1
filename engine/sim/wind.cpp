#include "sim/wind.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/units.h"
#include "sim/byte_image.h"

namespace squawk::sim {

namespace {
constexpr double kAltStep = 100.0 * units::kFt;    // [m] axis step
constexpr double kAltMax = 45000.0 * units::kFt;   // [m] axis top
constexpr int kNAlt = 451;                         // 0..45 000 ft in 100 ft steps
constexpr double kEps = 1e-20;                     // [deg^2] weight guard

Status check_point(double lat, double lon) {
  if (!std::isfinite(lat) || lat < -90.0 || lat > 90.0 || !std::isfinite(lon) || lon < -180.0 || lon > 180.0)
    return Status::invalid("WIND: position must be a latitude in [-90, 90] and a longitude in [-180, 180]");
  return Status::ok();
}
// The strongest jet streams measured blow at about 250 kt.
constexpr double kMaxWindKt = 400.0;
Status check_sample(double dir, double spd) {
  if (!std::isfinite(dir) || !std::isfinite(spd) || spd < 0.0 || spd > units::kt_to_ms(kMaxWindKt))
    return Status::invalid("WIND: expected a direction [deg] and a speed in [0, 400] kt, got " +
                           std::to_string(units::ms_to_kt(spd)) + " kt");
  return Status::ok();
}
// North/east components of a wind from dir_deg at spd.
WindNE components(double dir_deg, double spd) {
  const double a = dir_deg * units::kDeg + units::kPi;
  return {spd * std::cos(a), spd * std::sin(a)};
}
}  // namespace

Status WindField::add_uniform(double lat, double lon, double dir_deg, double spd) {
  SQUAWK_RETURN_IF_ERROR(check_point(lat, lon));
  SQUAWK_RETURN_IF_ERROR(check_sample(dir_deg, spd));
  const WindNE w = components(dir_deg, spd);
  push(lat, lon, std::vector<double>(kNAlt, w.north), std::vector<double>(kNAlt, w.east), false);
  return Status::ok();
}

Status WindField::add_profile(double lat, double lon, const std::vector<WindSample>& s) {
  SQUAWK_RETURN_IF_ERROR(check_point(lat, lon));
  if (s.empty()) return Status::invalid("WIND: expected altitude, direction, speed triples");
  for (size_t k = 0; k < s.size(); ++k) {
    SQUAWK_RETURN_IF_ERROR(check_sample(s[k].dir_deg, s[k].spd));
    if (!std::isfinite(s[k].alt) || (k > 0 && s[k].alt < s[k - 1].alt))
      return Status::invalid("WIND: profile altitudes must be finite and increasing");
  }
  std::vector<double> vn(kNAlt), ve(kNAlt);
  for (int j = 0; j < kNAlt; ++j) {
    const double h = j * kAltStep;
    size_t k = 0;
    while (k + 1 < s.size() && s[k + 1].alt <= h) ++k;
    const WindNE a = components(s[k].dir_deg, s[k].spd);
    if (h <= s.front().alt || k + 1 >= s.size()) {
      vn[j] = h <= s.front().alt ? components(s.front().dir_deg, s.front().spd).north : a.north;
      ve[j] = h <= s.front().alt ? components(s.front().dir_deg, s.front().spd).east : a.east;
      continue;
    }
    const WindNE b = components(s[k + 1].dir_deg, s[k + 1].spd);
    const double f = (h - s[k].alt) / (s[k + 1].alt - s[k].alt);
    vn[j] = a.north + f * (b.north - a.north);
    ve[j] = a.east + f * (b.east - a.east);
  }
  push(lat, lon, std::move(vn), std::move(ve), true);
  return Status::ok();
}

void WindField::push(double lat, double lon, std::vector<double> vn, std::vector<double> ve, bool profile) {
  lat_.push_back(lat);
  lon_.push_back(lon);
  vn_.push_back(std::move(vn));
  ve_.push_back(std::move(ve));
  if (dim_ < 3) dim_ = std::min(2, points());
  if (profile) dim_ = 3;
}

void WindField::clear() { *this = WindField(); }

WindNE WindField::at(double lat, double lon, double alt) const {
  if (dim_ == 0) return {};
  if (dim_ == 1) return {vn_[0][0], ve_[0][0]};
  const int n = points();
  double wsum = 0.0;
  for (int p = 0; p < n; ++p) {
    const double dy = lat - lat_[p], dx = std::cos(0.5 * (lat + lat_[p]) * units::kDeg) * (lon - lon_[p]);
    wsum += 1.0 / (kEps + dx * dx + dy * dy);
  }
  int lo = 0;
  double f = 0.0;
  if (dim_ == 3) {
    const double idx = std::max(0.0, std::min(kAltMax - kEps, alt) / kAltStep);
    lo = static_cast<int>(std::floor(idx));
    f = idx - lo;
  }
  WindNE w;
  for (int p = 0; p < n; ++p) {
    const double dy = lat - lat_[p], dx = std::cos(0.5 * (lat + lat_[p]) * units::kDeg) * (lon - lon_[p]);
    const double h = 1.0 / (kEps + dx * dx + dy * dy) / wsum;
    const int hi = std::min(lo + 1, kNAlt - 1);
    w.north += h * ((1.0 - f) * vn_[p][lo] + f * vn_[p][hi]);
    w.east += h * ((1.0 - f) * ve_[p][lo] + f * ve_[p][hi]);
  }
  return w;
}

void WindField::serialize(std::string& out) const {
  bytes::put<int32_t>(out, dim_);
  bytes::put_vec(out, lat_);
  bytes::put_vec(out, lon_);
  for (const auto& v : vn_) bytes::put_vec(out, v);
  for (const auto& v : ve_) bytes::put_vec(out, v);
}

}  // namespace squawk::sim
