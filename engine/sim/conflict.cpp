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

// Pass 1 (vectorisable): candidates whose CPA lies inside the zone,
// |dist^2 dv2 - (d.v)^2| < R^2 dv2, minus level pairs that never overlap
// vertically. Symmetric in i and j bit for bit (swapping them negates dx,
// dy, du, dv exactly) except when the raw longitude difference is exactly
// +-180 deg, where both orders wrap to -180.
inline bool pass1(const Rel& g, double r2, double h, double alt_i, double alt_j, double vs_i, double vs_j) {
  const double dd = g.du * g.dx + g.dv * g.dy;
  const bool hor = std::fabs(g.dist2 * g.dv2 - dd * dd) < r2 * g.dv2;
  const bool never_vert = (vs_j == vs_i) & (std::fabs(alt_i - alt_j) >= h);
  return hor & !never_vert;
}
}  // namespace

void ConflictDetector::begin(const Traffic& t, const CdSettings& /*s*/) {
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
  stored_conf_ = stored_los_ = examined_ = 0;
  truncated_ = false;
}

void ConflictDetector::test_pair(const Traffic& t, const CdSettings& s, int i, int j) {
  const double r = s.rpz, r2 = r * r, h = s.hpz;
  const Rel g = relative(t.lat[i], t.lon[i], chl_[i], shl_[i], t.gseast[i], t.gsnorth[i], t.lat[j], t.lon[j],
                         chl_[j], shl_[j], t.gseast[j], t.gsnorth[j]);
  if (!pass1(g, r2, h, t.alt[i], t.alt[j], t.vs[i], t.vs[j])) return;
  const double dx = g.dx, dy = g.dy, dist2 = g.dist2;
  const cpa::Horizontal c = cpa::horizontal(dx, dy, g.du, g.dv, r);
  if (!c.enters) return;
  const double tcpa = c.tcpa, dcpa2 = c.dcpa2, tin_hor = c.t_in, tout_hor = c.t_out;
  const double dalt = t.alt[i] - t.alt[j];
  const double dvs = t.vs[i] - t.vs[j];
  double tin_ver, tout_ver;
  if (dvs == 0.0) {  // IEEE limits of the crossing times (docs/bluesky_facts.md §3.2: both level)
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
    if (stored_los_ < s.max_pairs) {
      ++stored_los_;
      const double dist = std::sqrt(dist2);
      los_.push_back({i, j, dist, dalt});
      los_.push_back({j, i, dist, -dalt});
      cur_los_.push_back(uid_pair(t, i, j));
    } else {
      truncated_ = true;
    }
  }
  if (tin <= tout && tout > 0.0 && tin < s.dtlook) {
    if (stored_conf_ >= s.max_pairs) {
      truncated_ = true;
      return;
    }
    ++stored_conf_;
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

void ConflictDetector::finish() {
  const auto by_own = [](const auto& a, const auto& b) {
    return a.own != b.own ? a.own < b.own : a.intruder < b.intruder;
  };
  std::sort(pairs_.begin(), pairs_.end(), by_own);
  std::sort(los_.begin(), los_.end(), by_own);
  std::sort(cur_conf_.begin(), cur_conf_.end());
  std::sort(cur_los_.begin(), cur_los_.end());
  total_conf_ += count_new(cur_conf_, prev_conf_);
  total_los_ += count_new(cur_los_, prev_los_);
  if (truncated_) ++truncated_detections_;
  prev_conf_.swap(cur_conf_);
  prev_los_.swap(cur_los_);
}

void ConflictDetector::detect_all_pairs(const Traffic& t, const CdSettings& s) {
  begin(t, s);
  const int n = t.n();
  const double r2 = s.rpz * s.rpz, h = s.hpz;
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
    for (int j = i + 1; j < n; ++j) {
      const Rel g = relative(lat_i, lon_i, chl_i, shl_i, u_i, v_i, lat[j], lon[j], chl[j], shl[j], ue[j], vn[j]);
      flag[j] = static_cast<uint8_t>(pass1(g, r2, h, alt_i, alt[j], vs_i, vs[j]));
    }
    for (int j = i + 1; j < n; ++j)
      if (flag[j]) test_pair(t, s, i, j);
  }
  examined_ = static_cast<int64_t>(n) * (n - 1) / 2;
  finish();
}

bool ConflictDetector::build_grid(const Traffic& t, const CdSettings& s) {
  const int n = t.n();
  double gs_max = 0.0;
  for (int i = 0; i < n; ++i) {
    const double lat = t.lat[i], lon = t.lon[i];
    // Negated comparisons so that NaN leaves the domain too.
    if (!(lat >= -90.0 && lat <= 90.0 && lon >= -180.0 && lon <= 180.0)) return false;
    const double gs = std::hypot(t.gseast[i], t.gsnorth[i]);
    if (!std::isfinite(gs)) return false;
    gs_max = std::max(gs_max, gs);
  }
  // Reach [deg of arc]: a pair in conflict or LoS is closer than
  // rpz + |v_rel| max(dtlook, 0) <= rpz + 2 gs_max max(dtlook, 0) now, in
  // the metric of relative(); the factor covers rounding.
  const double reach_m = s.rpz + 2.0 * gs_max * std::max(s.dtlook, 0.0);
  const double reach_deg = reach_m / (kREarth * kDeg) * (1.0 + 1e-6) + 1e-9;
  if (!std::isfinite(reach_deg)) return false;
  // At most about sqrt(n) bands and 2 sqrt(n) cells per band: wider cells
  // stay correct and keep the grid O(n).
  const int side = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(n))));
  band_deg_ = std::max(reach_deg, 180.0 / side);
  const int nb = std::max(1, static_cast<int>(std::ceil(180.0 / band_deg_)));
  band_cell0_.resize(nb);
  band_cells_.resize(nb);
  int cells = 0;
  for (int b = 0; b < nb; ++b) {
    // Largest |lat| of bands b-1 .. b+1: it bounds |mean latitude| of every
    // pair this band's cells must hold (within b, and with b-1 or b+1).
    const double lo = -90.0 + (b - 1) * band_deg_, hi = -90.0 + (b + 2) * band_deg_;
    const double phi = std::min(90.0, std::max(std::fabs(lo), std::fabs(hi)));
    const double c = std::cos(phi * kDeg);
    int m = 1;
    if (c > 1e-6 && reach_deg < 120.0 * c) {
      const double width = reach_deg / c * (1.0 + 1e-6);  // [deg] of longitude
      m = static_cast<int>(std::min(360.0 / width, 2.0 * side));
      if (m < 3) m = 1;  // a ring of 1 or 2 cells would meet itself
    }
    band_cell0_[b] = cells;
    band_cells_[b] = m;
    cells += m;
  }
  // Counting sort by cell, stable: cell_start_[c] counts, then holds the
  // start of cell c, then (after placing) its end, then shifts to the start.
  cell_start_.assign(cells + 1, 0);
  cell_of_.resize(n);
  for (int i = 0; i < n; ++i) {
    const int b = std::min(nb - 1, static_cast<int>((t.lat[i] + 90.0) / band_deg_));
    const int m = band_cells_[b];
    const int k = std::min(m - 1, static_cast<int>((t.lon[i] + 180.0) * (m / 360.0)));
    cell_of_[i] = band_cell0_[b] + k;
    ++cell_start_[cell_of_[i]];
  }
  for (int c = 0, sum = 0; c <= cells; ++c) {
    const int count = cell_start_[c];
    cell_start_[c] = sum;
    sum += count;
  }
  order_.resize(n);
  for (int i = 0; i < n; ++i) order_[cell_start_[cell_of_[i]]++] = i;
  for (int c = cells; c > 0; --c) cell_start_[c] = cell_start_[c - 1];
  cell_start_[0] = 0;
  for (auto* v : {&s_lat_, &s_lon_, &s_chl_, &s_shl_, &s_ue_, &s_vn_, &s_alt_, &s_vs_}) v->resize(n);
  for (int q = 0; q < n; ++q) {
    const int i = order_[q];
    s_lat_[q] = t.lat[i], s_lon_[q] = t.lon[i], s_chl_[q] = chl_[i], s_shl_[q] = shl_[i];
    s_ue_[q] = t.gseast[i], s_vn_[q] = t.gsnorth[i], s_alt_[q] = t.alt[i], s_vs_[q] = t.vs[i];
  }
  return true;
}

template <bool kEdge>
void ConflictDetector::scan(const Traffic& t, const CdSettings& s, int p, int q0, int q1) {
  if (q1 <= q0) return;
  const double r2 = s.rpz * s.rpz, h = s.hpz;
  // Local pointers: the byte stores to `flag` may alias anything, so members
  // read through `this` would be reloaded every iteration (no vectorising).
  const double *lat = s_lat_.data(), *lon = s_lon_.data(), *chl = s_chl_.data(), *shl = s_shl_.data();
  const double *ue = s_ue_.data(), *vn = s_vn_.data(), *alt = s_alt_.data(), *vs = s_vs_.data();
  const double lat_p = lat[p], lon_p = lon[p], chl_p = chl[p], shl_p = shl[p];
  const double u_p = ue[p], v_p = vn[p], alt_p = alt[p], vs_p = vs[p];
  uint8_t* flag = flag_.data() + q0;
  const int len = q1 - q0;
  lat += q0, lon += q0, chl += q0, shl += q0, ue += q0, vn += q0, alt += q0, vs += q0;
  for (int k = 0; k < len; ++k) {
    const Rel g = relative(lat_p, lon_p, chl_p, shl_p, u_p, v_p, lat[k], lon[k], chl[k], shl[k], ue[k], vn[k]);
    const bool edge = kEdge && std::fabs(lon[k] - lon_p) == 180.0;  // pass1 asymmetric: test_pair decides
    flag[k] = static_cast<uint8_t>(pass1(g, r2, h, alt_p, alt[k], vs_p, vs[k]) | edge);
  }
  examined_ += len;
  const int i = order_[p];
  for (int k = 0; k < len; ++k) {
    if (!flag[k]) continue;
    const int j = order_[q0 + k];
    test_pair(t, s, std::min(i, j), std::max(i, j));
  }
}

void ConflictDetector::detect(const Traffic& t, const CdSettings& s) {
  begin(t, s);
  if (!build_grid(t, s)) {
    detect_all_pairs(t, s);
    return;
  }
  const int nb = static_cast<int>(band_cells_.size());
  const auto start = [this](int b, int k) { return cell_start_[band_cell0_[b] + k]; };
  for (int b = 0; b < nb; ++b) {
    const int m = band_cells_[b];
    for (int k = 0; k < m; ++k) {
      const int end_k = start(b, k + 1);
      for (int p = start(b, k); p < end_k; ++p) {
        if (m == 1) {
          // One cell (near a pole, or a reach of the globe's size): the rest
          // of the band, where longitudes 180 deg apart can be within reach.
          scan<true>(t, s, p, p + 1, end_k);
        } else {
          // The rest of this cell and the whole next cell of the ring (each
          // neighbouring cell pair once, from its western cell).
          scan<false>(t, s, p, p + 1, end_k);
          const int k1 = (k + 1) % m;
          scan<false>(t, s, p, start(b, k1), start(b, k1 + 1));
        }
        if (b + 1 == nb) continue;
        // Next band: the cells within one cell of this aircraft's longitude.
        const int m1 = band_cells_[b + 1];
        if (m1 == 1) {
          scan<true>(t, s, p, start(b + 1, 0), start(b + 1, 1));
          continue;
        }
        const int kk = std::min(m1 - 1, static_cast<int>((s_lon_[p] + 180.0) * (m1 / 360.0)));
        const int lo = kk - 1, hi = kk + 1;
        if (lo < 0) {
          scan<false>(t, s, p, start(b + 1, 0), start(b + 1, hi + 1));
          scan<false>(t, s, p, start(b + 1, m1 - 1), start(b + 1, m1));
        } else if (hi >= m1) {
          scan<false>(t, s, p, start(b + 1, lo), start(b + 1, m1));
          scan<false>(t, s, p, start(b + 1, 0), start(b + 1, 1));
        } else {
          scan<false>(t, s, p, start(b + 1, lo), start(b + 1, hi + 1));
        }
      }
    }
  }
  finish();
}

void ConflictDetector::clear(bool reset_totals) {
  pairs_.clear();
  los_.clear();
  std::fill(inconf_.begin(), inconf_.end(), 0);
  prev_conf_.clear();
  prev_los_.clear();
  truncated_ = false;
  if (reset_totals) total_conf_ = total_los_ = truncated_detections_ = 0;
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

std::string cap_notice(const ConflictDetector& cd, int64_t max_pairs) {
  const int64_t n = cd.truncated_detections();
  if (n == 0) return "";
  return "conflict detection hit its cap of " + std::to_string(max_pairs) + " stored pairs in " + std::to_string(n) +
         (n == 1 ? " detection" : " detections") +
         ": conflicts beyond it were not listed (--max-conflict-pairs N raises the cap)";
}

}  // namespace squawk::sim
