#include "sim/route.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geo.h"
#include "core/text.h"
#include "core/units.h"
#include "sim/byte_image.h"

namespace squawk::sim {

namespace {
std::string wp_error(const Waypoint& wp, const char* what) {
  std::string m = "waypoint ";
  m.append(text::quoted(wp.name)).append(": ").append(what);
  return m;
}
Status not_in_route(std::string_view name) {
  return Status::not_found(std::string("waypoint ").append(text::quoted(name)).append(" is not in the route"));
}
constexpr double kUnknownLeg = std::numeric_limits<double>::quiet_NaN();
Waypoint normalized(Waypoint wp, bool flyover_mode) {
  wp.name = text::upper(text::trim(wp.name));
  wp.flyover = wp.flyover || flyover_mode;
  return wp;
}
}  // namespace

void Route::count(const Waypoint& wp, int delta) {
  if ((names_[wp.name] += delta) == 0) names_.erase(wp.name);
  if (wp.has_alt()) n_alt_ += delta;
}

void Route::place(int at, Waypoint wp) {
  count(wp, 1);
  wps_.insert(wps_.begin() + at, std::move(wp));
  leg_.insert(leg_.begin() + at, kUnknownLeg);
  if (at > 0) leg_[at - 1] = kUnknownLeg;
}

void Route::drop(int k) {
  count(wps_[k], -1);
  wps_.erase(wps_.begin() + k);
  leg_.erase(leg_.begin() + k);
  if (k > 0) leg_[k - 1] = kUnknownLeg;
}

int Route::find(std::string_view name) const {
  if (!names_.contains(text::upper(text::trim(name)))) return -1;
  for (size_t k = 0; k < wps_.size(); ++k)
    if (text::iequals(wps_[k].name, name)) return static_cast<int>(k);
  return -1;
}

Status Route::validate(const Waypoint& wp) const {
  if (text::trim(wp.name).empty()) return Status::invalid("waypoint: empty name, expected a waypoint name");
  if (!std::isfinite(wp.lat) || wp.lat < -90.0 || wp.lat > 90.0)
    return Status::invalid(wp_error(wp, "latitude must be a number in [-90, 90] deg"));
  if (!std::isfinite(wp.lon) || wp.lon < -180.0 || wp.lon > 180.0)
    return Status::invalid(wp_error(wp, "longitude must be a number in [-180, 180] deg"));
  if (wp.has_alt() && (!std::isfinite(wp.alt) || wp.alt < -300.0))
    return Status::invalid(wp_error(wp, "altitude constraint must be a finite altitude >= -300 m"));
  if (wp.has_spd() && (!std::isfinite(wp.spd) || wp.spd <= 0.0))
    return Status::invalid(wp_error(wp, "speed constraint must be a positive CAS or Mach"));
  return Status::ok();
}

Status Route::add(Waypoint wp) {
  SQUAWK_RETURN_IF_ERROR(validate(wp));
  const int at = dest_.empty() ? size() : size() - 1;
  place(at, normalized(std::move(wp), flyover_mode_));
  if (active_ < 0) active_ = at;
  else if (active_ > at) ++active_;
  return Status::ok();
}

Status Route::insert_after(std::string_view ref, Waypoint wp) {
  SQUAWK_RETURN_IF_ERROR(validate(wp));
  const int k = find(ref);
  if (k < 0) return not_in_route(ref);
  if (!dest_.empty() && k == size() - 1)
    return Status::invalid(std::string("waypoint ").append(text::quoted(ref)).append(" is the destination; nothing can follow it"));
  place(k + 1, normalized(std::move(wp), flyover_mode_));
  if (active_ > k) ++active_;
  return Status::ok();
}

Status Route::insert_before(std::string_view ref, Waypoint wp) {
  SQUAWK_RETURN_IF_ERROR(validate(wp));
  const int k = find(ref);
  if (k < 0) return not_in_route(ref);
  place(k, normalized(std::move(wp), flyover_mode_));
  if (active_ >= k) ++active_;
  return Status::ok();
}

Status Route::remove(std::string_view name) {
  const int k = find(name);
  if (k < 0) return not_in_route(name);
  if (!dest_.empty() && k == size() - 1) dest_.clear();
  drop(k);
  if (active_ > k) --active_;
  if (active_ >= size()) active_ = -1;
  return Status::ok();
}

void Route::clear() {
  wps_.clear();
  names_.clear();
  n_alt_ = 0;
  leg_.clear();
  flyover_mode_ = false;
  active_ = -1;
  dest_.clear();
  orig_name_.clear();
  orig_lat_ = orig_lon_ = 0.0;
}

Status Route::add_command(std::string_view name, std::string line) {
  const int k = find(name);
  if (k < 0) return not_in_route(name);
  if (text::trim(line).empty()) return Status::invalid("a waypoint command needs a command line");
  wps_[k].commands.push_back(std::move(line));
  return Status::ok();
}

Status Route::direct_to(std::string_view name) {
  const int k = find(name);
  if (k < 0) return not_in_route(name);
  active_ = k;
  return Status::ok();
}

Status Route::set_dest(Waypoint dest) {
  SQUAWK_RETURN_IF_ERROR(validate(dest));
  Waypoint wp = normalized(std::move(dest), flyover_mode_);
  if (!dest_.empty()) {
    drop(size() - 1);
    place(size(), wp);
  } else {
    place(size(), wp);
    if (active_ < 0) active_ = size() - 1;
  }
  dest_ = wp.name;
  return Status::ok();
}

Status Route::set_orig(Waypoint orig) {
  SQUAWK_RETURN_IF_ERROR(validate(orig));
  orig_name_ = text::upper(text::trim(orig.name));
  orig_lat_ = orig.lat;
  orig_lon_ = orig.lon;
  return Status::ok();
}

Route::AltTarget Route::alt_target(int k) const {
  if (n_alt_ == 0) return {kNoConstraint, 0.0};
  double x = 0.0;
  for (int j = k; j >= 0 && j < size(); ++j) {
    if (wps_[j].has_alt()) return {wps_[j].alt, x};
    if (j + 1 < size()) {
      if (std::isnan(leg_[j]))
        leg_[j] = units::nm_to_m(geo::qdrdist(wps_[j].lat, wps_[j].lon, wps_[j + 1].lat, wps_[j + 1].lon).dist_nm);
      x += leg_[j];
    }
  }
  return {kNoConstraint, 0.0};
}

bool Route::advance() {
  if (active_ < 0) return false;
  if (active_ + 1 >= size()) {
    active_ = -1;
    return false;
  }
  ++active_;
  return true;
}

void Route::serialize(std::string& out) const {
  using bytes::put;
  put<int64_t>(out, static_cast<int64_t>(wps_.size()));
  for (const Waypoint& w : wps_) {
    bytes::put_str(out, w.name);
    put(out, w.lat);
    put(out, w.lon);
    put(out, w.has_alt() ? w.alt : -1e300);  // one fixed image for "no constraint"
    put(out, w.has_spd() ? w.spd : -1e300);
    put<uint8_t>(out, w.flyover ? 1 : 0);
    put<int64_t>(out, static_cast<int64_t>(w.commands.size()));
    for (const std::string& c : w.commands) bytes::put_str(out, c);
  }
  put<int64_t>(out, active_);
  put<uint8_t>(out, flyover_mode_ ? 1 : 0);
  bytes::put_str(out, dest_);
  bytes::put_str(out, orig_name_);
  put(out, orig_lat_);
  put(out, orig_lon_);
}

bool waypoint_reached(double dist, double qdr, double curlegdir, double trk, double gs, double turndist) {
  const bool close = dist / std::max(1e-4, std::fabs(gs)) < 4.0;  // [s] within 4 s of flight
  const bool too_close_to_turn = close && std::fabs(geo::wrap180(trk - qdr)) > 90.0;
  const bool passed = std::fabs(geo::wrap180(qdr - curlegdir)) > 90.0;
  return too_close_to_turn || passed || dist < turndist;
}

double turn_distance(double tas, double bank, double qdr, double next_qdr, bool flyby) {
  if (!flyby) return 0.0;
  const double r = tas * tas / (units::kG0 * std::tan(bank));
  return std::fabs(r * std::tan(0.5 * std::fabs(geo::wrap180(qdr - next_qdr)) * units::kDeg));
}

}  // namespace squawk::sim
