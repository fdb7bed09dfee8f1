#include "sim/conflict.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/cpa.h"
#include "core/units.h"
#include "sim/byte_image.h"

namespace squawk::sim {

using units::kDeg;
using units::kREarth;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

// Counts the elements of sorted `cur` that are not in sorted `prev`.
int64_t count_new(const std::vector<std::pair<uint64_t, uint64_t>>& cur,
                  const std::vector<std::pair<uint64_t, uint64_t>>& prev) {
  int64_t n = 0;
  size_t k = 0;
  for (const auto& p : cur) {
    while (k < prev.size() && prev[k] < p) ++k;
    if (k == prev.size() || prev[k] != p) ++n;
  }
  return n;
}

// Position of j relative to i (kwikqdrdist, east/north [m]) and velocity of
// j relative to i [m/s]. cos of the mean latitude from half-angle terms:
// cos((a+b)/2) = cos(a/2)cos(b/2) - sin(a/2)sin(b/2).
struct Rel {
  double dx, dy;   // [m]
  double du, dv;   // [m/s]
  double dv2;      // [m^2/s^2] floored at 1e-6 as BlueSky
  double dist2;    // [m^2]
};
inline Rel relative(double lat_i, double lon_i, double chl_i, double shl_i, double u_i, double v_i,
                    double lat_j, double lon_j, double chl_j, double shl_j, double u_j, double v_j) {
  double dlon = lon_j - lon_i;
  // Into [-180, 180) with selects, which keep the caller's loop vectorisable.
  dlon = dlon >= 180.0 ? dlon - 360.0 : dlon;
  dlon = dlon < -180.0 ? dlon + 360.0 : dlon;
  const double cavelat = chl_i * chl_j - shl_i * shl_j;
  Rel g;
  g.dx = kREarth * dlon * kDeg * cavelat;
  g.dy = kREarth * (lat_j - lat_i) * kDeg;
  g.du = u_j - u_i;
  g.dv = v_j - v_i;
  g.dv2 = std::max(g.du * g.du + g.dv * g.dv, 1e-6);
  g.dist2 = g.dx * g.dx + g.dy * g.dy;
  return g;
}

std::pair<uint64_t, uint64_t> uid_pair(const Traffic& t, int a, int b) {
  const uint64_t ua = t.uid[a], ub = t.uid[b];
  return ua < ub ? std::make_pair(ua, ub) : std::make_pair(ub, ua);
}
}  // namespace

void ConflictDetector::detect(const Traffic& t, const CdSettings& s) {
  const int n = t.n();
  pairs_.clear();
  los_.clear();
  cur_conf_.clear();
  cur_los_.clear();
  inconf_.assign(n, 0);
  chl_.resize(n);
  shl_.resize(n);
  flag_.resize(n);
  for (int i = 0; i < n; ++i) {
    const double h = 0.5 * t.lat[i] * kDeg;
    chl_[i] = std::cos(h);
    shl_[i] = std::sin(h);
  }
  const double r = s.rpz, r2 = r * r, h = s.hpz;
  const double* lat = t.lat.data();
  const double* lon = t.lon.data();
  const double* ue = t.gseast.data();
  const double* vn = t.gsnorth.data();
  const double* alt = t.alt.data();
  const double* vs = t.vs.data();
  const double* chl = chl_.data();
  const double* shl = shl_.data();
  uint8_t* flag = flag_.data();

  for (int i = 0; i < n; ++i) {
    const double lat_i = lat[i], lon_i = lon[i], u_i = ue[i], v_i = vn[i];
    const double alt_i = alt[i], vs_i = vs[i], chl_i = chl[i], shl_i = shl[i];
    // Pass 1 (vectorisable): candidates whose CPA lies inside the zone,
    // |dist^2 dv2 - (d.v)^2| < R^2 dv2, minus level pairs that never overlap
    // vertically.
    for (int j = i + 1; j < n; ++j) {
      const Rel g = relative(lat_i, lon_i, chl_i, shl_i, u_i, v_i, lat[j], lon[j], chl[j], shl[j], ue[j], vn[j]);
      const double dd = g.du * g.dx + g.dv * g.dy;
      const bool hor = std::fabs(g.dist2 * g.dv2 - dd * dd) < r2 * g.dv2;
      const bool never_vert = (vs[j] == vs_i) & (std::fabs(alt_i - alt[j]) >= h);
      flag[j] = static_cast<uint8_t>(hor & !never_vert);
    }
    // Pass 2: full state-based test of the candidates.
    for (int j = i + 1; j < n; ++j) {
      if (!flag[j]) continue;
      const Rel g = relative(lat_i, lon_i, chl_i, shl_i, u_i, v_i, lat[j], lon[j], chl[j], shl[j], ue[j], vn[j]);
      const double dx = g.dx, dy = g.dy, dist2 = g.dist2;
      const cpa::Horizontal c = cpa::horizontal(dx, dy, g.du, g.dv, r);
      if (!c.enters) continue;
      const double tcpa = c.tcpa, dcpa2 = c.dcpa2, tin_hor = c.t_in, tout_hor = c.t_out;
      const double dalt = alt_i - alt[j];
      const double dvs = vs_i - vs[j];
      double tin_ver, tout_ver;
      if (dvs == 0.0) {  // IEEE limits of the crossing times (facts §3.2 step 8)
        const bool inside = std::fabs(dalt) < h;
        tin_ver = inside ? -kInf : kInf;
        tout_ver = inside ? kInf : -kInf;
      } else {
        const double hi = (dalt + h) / -dvs, lo = (dalt - h) / -dvs;
        tin_ver = std::min(hi, lo);
        tout_ver = std::max(hi, lo);
      }
      const double tin = std::max(tin_ver, tin_hor);
      const double tout = std::min(tout_ver, tout_hor);
      const bool is_los = dist2 < r2 && std::fabs(dalt) < h;
      if (is_los) {
        const double dist = std::sqrt(dist2);
        los_.push_back({i, j, dist, dalt});
        los_.push_back({j, i, dist, -dalt});
        cur_los_.push_back(uid_pair(t, i, j));
      }
      if (tin <= tout && tout > 0.0 && tin < s.dtlook) {
        const double dist = std::sqrt(dist2);
        const double dcpa = std::sqrt(dcpa2);
        double qdr = std::atan2(dx, dy) / kDeg;
        if (qdr < 0.0) qdr += 360.0;
        const double qdr_back = qdr >= 180.0 ? qdr - 180.0 : qdr + 180.0;
        pairs_.push_back({i, j, tcpa, dcpa, tin, qdr, dist});
        pairs_.push_back({j, i, tcpa, dcpa, tin, qdr_back, dist});
        inconf_[i] = inconf_[j] = 1;
        cur_conf_.push_back(uid_pair(t, i, j));
      }
    }
  }
  const auto by_own = [](const auto& a, const auto& b) {
    return a.own != b.own ? a.own < b.own : a.intruder < b.intruder;
  };
  std::sort(pairs_.begin(), pairs_.end(), by_own);
  std::sort(los_.begin(), los_.end(), by_own);
  std::sort(cur_conf_.begin(), cur_conf_.end());
  std::sort(cur_los_.begin(), cur_los_.end());
  total_conf_ += count_new(cur_conf_, prev_conf_);
  total_los_ += count_new(cur_los_, prev_los_);
  prev_conf_.swap(cur_conf_);
  prev_los_.swap(cur_los_);
}

void ConflictDetector::clear(bool reset_totals) {
  pairs_.clear();
  los_.clear();
  std::fill(inconf_.begin(), inconf_.end(), 0);
  prev_conf_.clear();
  prev_los_.clear();
  if (reset_totals) total_conf_ = total_los_ = 0;
}

void ConflictDetector::on_erase(int i) {
  const auto shift = [i](auto& v) {
    v.erase(std::remove_if(v.begin(), v.end(), [i](const auto& p) { return p.own == i || p.intruder == i; }),
            v.end());
    for (auto& p : v) {
      if (p.own > i) --p.own;
      if (p.intruder > i) --p.intruder;
    }
  };
  shift(pairs_);
  shift(los_);
  if (i < static_cast<int>(inconf_.size())) inconf_.erase(inconf_.begin() + i);
}

std::vector<std::pair<int, int>> ConflictDetector::unique_conflicts() const {
  std::vector<std::pair<int, int>> out;
  for (const ConflictPair& p : pairs_)
    if (p.own < p.intruder) out.emplace_back(p.own, p.intruder);
  return out;
}

std::vector<std::pair<int, int>> ConflictDetector::unique_los() const {
  std::vector<std::pair<int, int>> out;
  for (const LosPair& p : los_)
    if (p.own < p.intruder) out.emplace_back(p.own, p.intruder);
  return out;
}

void ConflictDetector::serialize(std::string& out) const {
  using bytes::put;
  put<int64_t>(out, static_cast<int64_t>(pairs_.size()));
  for (const ConflictPair& p : pairs_) {
    put(out, p.own), put(out, p.intruder), put(out, p.tcpa), put(out, p.dcpa);
    put(out, p.tlos), put(out, p.qdr), put(out, p.dist);
  }
  put<int64_t>(out, static_cast<int64_t>(los_.size()));
  for (const LosPair& p : los_) put(out, p.own), put(out, p.intruder), put(out, p.dist), put(out, p.dalt);
  bytes::put_vec(out, inconf_);
  put<int64_t>(out, static_cast<int64_t>(prev_conf_.size()));
  for (const auto& p : prev_conf_) put(out, p.first), put(out, p.second);
  put<int64_t>(out, static_cast<int64_t>(prev_los_.size()));
  for (const auto& p : prev_los_) put(out, p.first), put(out, p.second);
  put(out, total_conf_);
  put(out, total_los_);
}

}  // namespace squawk::sim
