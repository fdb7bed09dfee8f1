#include "sim/mvp.h"

#include <algorithm>
#include <cmath>

#include "core/cpa.h"
#include "core/geo.h"
#include "core/units.h"
#include "sim/atmosphere.h"
#include "sim/byte_image.h"

namespace squawk::sim {

using units::kDeg;

namespace {
// Index of the aircraft with this uid, or -1. Traffic keeps uids ascending
// (appended in creation order, erased in place).
int index_of_uid(const Traffic& t, uint64_t uid) {
  const auto it = std::lower_bound(t.uid.begin(), t.uid.end(), uid);
  return (it != t.uid.end() && *it == uid) ? static_cast<int>(it - t.uid.begin()) : -1;
}

struct Dv {
  double e, n, z;  // [m/s]
};

// BlueSky's MVP() (docs/bluesky_facts.md §3.3) for one conflict pair (own i, intruder j).
Dv mvp_pair(const Traffic& t, const ConflictPair& c, double rpz_m, double hpz_m, double dtlook) {
  const int i = c.own, j = c.intruder;
  const double qdr = c.qdr * kDeg;
  const double drel_e = std::sin(qdr) * c.dist, drel_n = std::cos(qdr) * c.dist;
  const double drel_z = t.alt[j] - t.alt[i];
  const double vrel_e = t.gseast[j] - t.gseast[i], vrel_n = t.gsnorth[j] - t.gsnorth[i];
  const double vrel_z = t.vs[j] - t.vs[i];
  const cpa::Push h = cpa::mvp_horizontal(drel_e, drel_n, c.dist, vrel_e, vrel_n, c.tcpa, rpz_m);
  Dv dv{h.e, h.n, 0.0};
  const bool moving_v = std::fabs(vrel_z) > 0.0;
  double i_v = moving_v ? hpz_m : hpz_m - std::fabs(drel_z);
  double tsol_v = moving_v ? std::fabs(drel_z / vrel_z) : c.tlos;
  if (tsol_v > dtlook) {
    tsol_v = c.tlos;
    i_v = hpz_m;
  }
  tsol_v = std::max(tsol_v, 1e-3);
  dv.z = moving_v ? (i_v / tsol_v) * (vrel_z > 0 ? -1.0 : 1.0) : i_v / tsol_v;
  return dv;
}

// Limits [m/s] of the resolution ground speed of aircraft i: the [vmin, vmax]
// CAS envelope numbers taken as they are (BlueSky's MVP caps the ground
// speed with them), with the ground cap when it applies. The performance
// limits then apply to the resulting TAS target as to any other.
std::pair<double, double> gs_limits(const Traffic& t, int i, const PerformanceOptions& po) {
  double vmax = t.perf[i].vmax;
  if (po.ground_cap && t.alt[i] <= po.ground_alt) vmax = std::min(vmax, po.ground_vmax);
  return {t.perf[i].vmin, vmax};
}
}  // namespace

void MvpResolver::resolve(Traffic& t, const ConflictDetector& cd, const CdSettings& cds,
                          const CrSettings& crs, const PerformanceOptions& po) {
  const int n = t.n();
  const std::vector<ConflictPair>& pairs = cd.pairs();
  if (!pairs.empty()) {
    dve_.assign(n, 0.0);
    dvn_.assign(n, 0.0);
    dvz_.assign(n, 0.0);
    tsol_.assign(n, 0.0);
    const double rpz_m = cds.rpz * crs.resofach, hpz_m = cds.hpz * crs.resofacv;
    for (const ConflictPair& c : pairs) {
      const Dv dv = mvp_pair(t, c, rpz_m, hpz_m, cds.dtlook);
      dve_[c.own] -= dv.e;
      dvn_[c.own] -= dv.n;
      dvz_[c.own] -= 0.5 * dv.z;
      tsol_[c.own] = std::max(tsol_[c.own], c.tcpa);
    }
    for (int i = 0; i < n; ++i) {
      if (!cd.inconf()[i]) continue;
      const double ve = t.gseast[i] + dve_[i], vn = t.gsnorth[i] + dvn_[i];
      double trk = std::atan2(ve, vn) / kDeg;
      if (trk < 0.0) trk += 360.0;
      const auto [vmin, vmax] = gs_limits(t, i, po);
      t.cr_trk[i] = trk;
      t.cr_tas[i] = std::min(std::max(std::hypot(ve, vn), vmin), vmax);
      const double vs = std::clamp(t.vs[i] + dvz_[i], t.perf[i].vsmin, t.perf[i].vsmax);
      t.cr_vs[i] = vs;
      t.cr_alt[i] = crs.vertical ? t.alt[i] + vs * tsol_[i] : t.sel_alt[i];
    }
    for (const ConflictPair& c : pairs) reso_pairs_.emplace_back(t.uid[c.own], t.uid[c.intruder]);
    std::sort(reso_pairs_.begin(), reso_pairs_.end());
    reso_pairs_.erase(std::unique(reso_pairs_.begin(), reso_pairs_.end()), reso_pairs_.end());
  }
  if (crs.resume) {
    resume(t, cds, crs);
  } else {  // without PASTCPA an aircraft follows MVP exactly while in conflict
    for (int i = 0; i < n; ++i) t.cr_active[i] = cd.inconf()[i];
    reso_pairs_.clear();
  }
}

// PASTCPA (docs/bluesky_facts.md §3.3, "Which values the aircraft follows").
void MvpResolver::resume(Traffic& t, const CdSettings& cds, const CrSettings& crs) {
  const int n = t.n();
  keep_.assign(n, -1);
  scratch_.clear();
  for (const auto& p : reso_pairs_) {
    const int a = index_of_uid(t, p.first), b = index_of_uid(t, p.second);
    if (a < 0) continue;
    bool keep = false;
    if (b >= 0) {
      const double de = units::kREarth * (t.lon[b] - t.lon[a]) * kDeg *
                        std::cos(0.5 * (t.lat[b] + t.lat[a]) * kDeg);
      const double dn = units::kREarth * (t.lat[b] - t.lat[a]) * kDeg;
      const double ve = t.gseast[b] - t.gseast[a], vn = t.gsnorth[b] - t.gsnorth[a];
      const bool past_cpa = de * ve + dn * vn > 0.0;
      const double hdist = std::hypot(de, dn);
      const bool hor_los = hdist < cds.rpz;
      const bool bouncing = std::fabs(geo::wrap180(t.trk[a] - t.trk[b])) < 30.0 &&
                            hdist < cds.rpz * crs.resofach;
      keep = !past_cpa || hor_los || bouncing;
    }
    if (keep) {
      keep_[a] = 1;
      scratch_.push_back(p);
    } else if (keep_[a] < 0) {
      keep_[a] = 0;
    }
  }
  reso_pairs_.swap(scratch_);
  for (int i = 0; i < n; ++i) {
    if (keep_[i] < 0) continue;
    t.cr_active[i] = static_cast<uint8_t>(keep_[i]);
    if (keep_[i] == 0 && t.route[i].active() >= 0) t.lnav[i] = 1;
  }
}

void MvpResolver::on_erase(uint64_t uid) {
  std::erase_if(reso_pairs_, [uid](const auto& p) { return p.first == uid || p.second == uid; });
}

void MvpResolver::clear() { reso_pairs_.clear(); }

void MvpResolver::serialize(std::string& out) const {
  bytes::put<int64_t>(out, static_cast<int64_t>(reso_pairs_.size()));
  for (const auto& p : reso_pairs_) bytes::put(out, p.first), bytes::put(out, p.second);
}

}  // namespace squawk::sim
