// State-based conflict detection (BlueSky asas/statebased.py; facts §3.2).
//
// For every ordered pair (i ownship, j intruder), with kwikqdrdist positions
// (R = 6 371 000 m), ground velocities (gseast, gsnorth) and relative
// position/velocity of j with respect to i:
//   tcpa = -(du dx + dv dy) / dv2,  dcpa^2 = |dist^2 - tcpa^2 dv2|,
//   horizontal window tcpa -+ sqrt(R^2 - dcpa^2)/vrel, vertical window from
//   (dalt -+ H) / -dvs (IEEE infinities when dvs = 0),
//   tLOS = max(tin_hor, tin_ver), conflict when dcpa < R, tin <= tout,
//   tout > 0 and tLOS < dtlook. Loss of separation: dist < R and |dalt| < H.
// The geometry is symmetric, so each unordered pair is computed once and
// reported in both orders, as BlueSky's confpairs are. rpz, hpz and dtlook
// are global (BlueSky's per-aircraft ZONER/ZONEDH values are not modelled).
//
// Cost: O(n^2) per detect() with no trig per pair (cos of the mean latitude
// comes from per-aircraft half-angle sines/cosines) and no allocation once
// the output buffers have grown.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "sim/traffic.h"

namespace squawk::sim {

struct CdSettings {
  bool enabled = false;             // ASAS / CDMETHOD ON|OFF (BlueSky starts OFF)
  double rpz = 5.0 * 1852.0;        // [m] protected-zone radius (5 NM)
  double hpz = 1000.0 * 0.3048;     // [m] protected-zone half height (1000 ft)
  double dtlook = 300.0;            // [s] look-ahead time
  double asas_dt = 1.0;             // [s] interval between detections
};

struct ConflictPair {
  int own;        // ownship index into Traffic
  int intruder;   // intruder index
  double tcpa;    // [s] time to closest point of approach
  double dcpa;    // [m] horizontal distance at CPA
  double tlos;    // [s] time to loss of separation (may be negative when in LoS)
  double qdr;     // [deg] bearing own -> intruder, [0, 360)
  double dist;    // [m] current horizontal distance
};

struct LosPair {
  int own;        // ownship index
  int intruder;   // intruder index
  double dist;    // [m] horizontal distance
  double dalt;    // [m] alt_own - alt_intruder
};

class ConflictDetector {
 public:
  // Runs detection over all aircraft of `traf` with settings `s`.
  // Fills pairs() and los() (both orders, sorted by own then intruder, as
  // BlueSky's confpairs) and updates
  // the per-aircraft inconf flags and the cumulative counts.
  void detect(const Traffic& traf, const CdSettings& s);
  // Forgets current pairs (CD switched off or traffic reset); cumulative
  // counts are kept unless `reset_totals`.
  void clear(bool reset_totals);
  // Re-indexes current pairs after Traffic::erase(i): pairs with i are
  // dropped and indices above i shift down.
  void on_erase(int i);

  const std::vector<ConflictPair>& pairs() const { return pairs_; }
  const std::vector<LosPair>& los() const { return los_; }
  // Unique current conflict / LoS pairs as (lower index, higher index).
  std::vector<std::pair<int, int>> unique_conflicts() const;
  std::vector<std::pair<int, int>> unique_los() const;
  // Per-aircraft flag: in at least one conflict (size n after detect()).
  const std::vector<uint8_t>& inconf() const { return inconf_; }
  // Number of distinct unordered pairs that have entered conflict / LoS since
  // the last reset (a pair counts again after it has left and re-entered).
  int64_t total_conflicts() const { return total_conf_; }
  int64_t total_los() const { return total_los_; }

  void serialize(std::string& out) const;

 private:
  std::vector<ConflictPair> pairs_;
  std::vector<LosPair> los_;
  std::vector<uint8_t> inconf_;
  // uid pairs (low, high) of the previous detection, sorted, for the counts.
  std::vector<std::pair<uint64_t, uint64_t>> prev_conf_, prev_los_, cur_conf_, cur_los_;
  // Per-aircraft scratch: half-latitude cos/sin, candidate flags.
  std::vector<double> chl_, shl_;
  std::vector<uint8_t> flag_;
  int64_t total_conf_ = 0;
  int64_t total_los_ = 0;
};

}  // namespace squawk::sim
