// Modified Voltage Potential conflict resolution with PASTCPA resume
// (BlueSky asas/mvp.py and asas/pastcpa.py; docs/bluesky_facts.md §3.3).
//
// Mode: BlueSky's default MVP switches, horizontal resolution with heading and
// speed together. For each conflict pair (i, j) the displacement at CPA is
// pushed out to resofach * R (with the erratum correction when outside the
// zone, the 10 m head-on guard) and both aircraft take their share:
// dv_i -= dv_mvp summed over i's conflicts. The new ground velocity gives
// cr_trk and cr_tas (clipped to the aircraft's [vmin, vmax] as TAS at its
// altitude). The vertical component (docs/bluesky_facts.md §3.3, halved) gives cr_vs
// (clipped to [vsmin, vsmax]); it is flown only when `vertical` is set
// (BlueSky's RMETHV, off by default), with cr_alt = alt + cr_vs * max tcpa
// (a simplification of BlueSky's level-off rule). Otherwise the vertical
// autopilot is unaffected (cr_alt = sel_alt).
//
// Resume (PASTCPA): every detected conflict pair joins a set of resolution
// pairs; an aircraft stays cr_active while one of its pairs is not yet past
// CPA (dot(d_rel, v_rel) <= 0), in horizontal LoS, or "bouncing"
// (|trk_i - trk_j| < 30 deg and distance < R resofach). When it has none
// left, cr_active is cleared and, if its route has an active waypoint, LNAV
// resumes DIRECT to it; otherwise it returns to its selected heading and speed.
// The track difference of the bouncing test is wrapped to (-180, 180].
// With `resume` off (RESNAV OFF), cr_active simply follows "in conflict now".
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "sim/conflict.h"
#include "sim/traffic.h"

namespace squawk::sim {

struct CrSettings {
  bool enabled = false;     // RESO MVP | OFF (BlueSky starts OFF)
  double resofach = 1.05;   // [-] horizontal margin factor (default.cfg asas_marh)
  double resofacv = 1.05;   // [-] vertical margin factor (default.cfg asas_marv)
  bool vertical = false;    // also resolve vertically (RMETHV ON)
  bool resume = true;       // PASTCPA resume navigation (RESNAV)
};

class MvpResolver {
 public:
  // Computes cr_* for every aircraft in a current conflict of `cd` and sets
  // cr_active; then applies the PASTCPA resume rule to all resolution pairs.
  // Needs cd.detect() to have run on the same traffic.
  // `po` supplies the ground cap for the speed clip.
  void resolve(Traffic& traf, const ConflictDetector& cd, const CdSettings& cds,
               const CrSettings& crs, const PerformanceOptions& po);
  // Drops resolution pairs involving the aircraft with this uid.
  void on_erase(uint64_t uid);
  void clear();
  // Resolution pairs as (ownship uid, intruder uid), sorted.
  const std::vector<std::pair<uint64_t, uint64_t>>& reso_pairs() const { return reso_pairs_; }

  void serialize(std::string& out) const;

 private:
  void resume(Traffic& traf, const CdSettings& cds, const CrSettings& crs);

  std::vector<std::pair<uint64_t, uint64_t>> reso_pairs_;
  std::vector<double> dve_, dvn_, dvz_;          // per-aircraft scratch [m/s]
  std::vector<double> tsol_;                     // per-aircraft scratch [s]
  std::vector<int8_t> keep_;                     // per-aircraft scratch: -1 none, 0 off, 1 on
  std::vector<std::pair<uint64_t, uint64_t>> scratch_;
};

}  // namespace squawk::sim
