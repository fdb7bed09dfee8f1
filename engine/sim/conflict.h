// State-based conflict detection (BlueSky asas/statebased.py; docs/bluesky_facts.md §3.2).
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
// Candidate pairs (detect()): a latitude-band x longitude-cell grid whose
// cells are at least the look-ahead reach R + 2 max|gs| dtlook wide in the
// detector's own flat-earth metric (bands touching a pole are one cell;
// longitude cells form a ring across the antimeridian), so every pair that
// can be in conflict or LoS shares a cell or neighbouring cells; see
// docs/whole_sky.md for the argument. Each candidate is then tested exactly as
// detect_all_pairs() tests it (lower index as ownship, same operations), so
// both produce bit-identical pairs, LoS, flags and counts. Cost: O(n + the
// pairs within reach) per detect() for traffic spread over the globe; O(n^2)
// in the worst case (all aircraft within one reach). No trig per pair (cos of
// the mean latitude comes from per-aircraft half-angle sines/cosines) and no
// allocation once the buffers have grown.
//
// Memory: O(n) scratch plus the pairs found, capped: at most
// CdSettings::max_pairs unique conflict pairs and as many LoS pairs are
// stored per detection; beyond that detection goes on without storing and
// truncated() is set (which pairs are kept is then unspecified);
// cap_notice() is the text that tells a user so.
#pragma once

#include <cstdint>
#include <string>
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
  int64_t max_pairs = 100000;       // unique conflict (and LoS) pairs stored per detection
  bool all_pairs = false;           // detect with the all-pairs reference (tests, bench_sim)
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
  // The all-pairs reference: the same results by comparing every pair
  // (tests and bench_sim).
  void detect_all_pairs(const Traffic& traf, const CdSettings& s);
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
  // The last detection hit CdSettings::max_pairs and stored only part of
  // the pairs it found.
  bool truncated() const { return truncated_; }
  // Detections that hit the cap since the last reset of the totals.
  int64_t truncated_detections() const { return truncated_detections_; }
  // Pairs the last detection examined (n(n-1)/2 for all pairs; the grid's
  // candidates otherwise).
  int64_t examined() const { return examined_; }

  void serialize(std::string& out) const;

 private:
  void begin(const Traffic& t, const CdSettings& s);
  // Full state-based test of the pair (a < b, a as ownship); records it.
  void test_pair(const Traffic& t, const CdSettings& s, int a, int b);
  void finish();
  // Pass 1 of aircraft at sorted position p against sorted positions
  // [q0, q1), then test_pair() on the survivors (the grid's inner loop).
  // kEdge: also pass pairs exactly 180 deg of longitude apart to test_pair
  // (needed in one-cell bands only: elsewhere such pairs are beyond reach).
  template <bool kEdge>
  void scan(const Traffic& t, const CdSettings& s, int p, int q0, int q1);
  // Builds the grid; false when the traffic is outside its domain (a
  // position outside [-90, 90] x [-180, 180] or not finite, a speed not
  // finite), where detect() falls back to all pairs.
  bool build_grid(const Traffic& t, const CdSettings& s);

  std::vector<ConflictPair> pairs_;
  std::vector<LosPair> los_;
  std::vector<uint8_t> inconf_;
  // uid pairs (low, high) of the previous detection, sorted, for the counts.
  std::vector<std::pair<uint64_t, uint64_t>> prev_conf_, prev_los_, cur_conf_, cur_los_;
  // Per-aircraft scratch: half-latitude cos/sin, candidate flags.
  std::vector<double> chl_, shl_;
  std::vector<uint8_t> flag_;
  // Grid: per band its first cell and cell count; per cell its first sorted
  // position (cells band-major, one past the end last); aircraft in cell
  // order (ascending index within a cell) with their data gathered.
  std::vector<int> band_cell0_, band_cells_, cell_start_, cell_of_, order_;
  std::vector<double> s_lat_, s_lon_, s_chl_, s_shl_, s_ue_, s_vn_, s_alt_, s_vs_;
  double band_deg_ = 180.0;  // [deg] band height
  int64_t total_conf_ = 0;
  int64_t total_los_ = 0;
  int64_t stored_conf_ = 0, stored_los_ = 0, examined_ = 0;
  bool truncated_ = false;
  int64_t truncated_detections_ = 0;
};

// What a user is told when detections hit the cap: "" when none did since
// the last reset; else how many did, the cap `max_pairs` and the flag that
// raises it (--max-conflict-pairs).
std::string cap_notice(const ConflictDetector& cd, int64_t max_pairs);

}  // namespace squawk::sim
