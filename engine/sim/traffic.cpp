#include "sim/traffic.h"

#include <cmath>
#include <limits>

#include "core/text.h"
#include "core/units.h"

namespace squawk::sim {

namespace {
// Calls f on every per-aircraft vector of t, so append/erase/clear cannot
// miss a column.
template <class F>
void for_each_column(Traffic& t, F&& f) {
  f(t.id), f(t.type), f(t.uid);
  f(t.lat), f(t.lon), f(t.alt), f(t.hdg), f(t.trk), f(t.tas), f(t.cas), f(t.gs), f(t.mach);
  f(t.gsnorth), f(t.gseast), f(t.vs), f(t.coslat), f(t.sinlat);
  f(t.sel_hdg), f(t.sel_turn), f(t.sel_alt), f(t.sel_spd), f(t.sel_vs), f(t.bank), f(t.tan_bank), f(t.lnav), f(t.vnav), f(t.route);
  f(t.perf_class), f(t.perf), f(t.oap), f(t.phase), f(t.ax);
  f(t.wp_lat), f(t.wp_lon), f(t.dist2wp), f(t.nextaltco), f(t.dist2vs), f(t.wp_vs), f(t.vnav_vs), f(t.turndist), f(t.curlegdir);
  f(t.turnspd), f(t.oldturnspd), f(t.vnav_spd), f(t.in_area), f(t.leg_spd), f(t.next_spd);
  f(t.cr_active), f(t.cr_trk), f(t.cr_tas), f(t.cr_vs), f(t.cr_alt);
  f(t.sin_hdg), f(t.cos_hdg), f(t.wp_trig), f(t.tgt_tas), f(t.tgt_tas_alt), f(t.tgt_tas_sel), f(t.vnav_vs_on);
}
}  // namespace

int Traffic::index_of(std::string_view acid) const {
  const auto it = index.find(text::upper(text::trim(acid)));
  return it == index.end() ? -1 : it->second;
}

int Traffic::append(const std::string& acid, const std::string& actype, uint64_t serial) {
  for_each_column(*this, [](auto& v) { v.emplace_back(); });
  const int i = n() - 1;
  id[i] = acid;
  type[i] = actype;
  uid[i] = serial;
  coslat[i] = 1.0;
  cos_hdg[i] = 1.0;
  bank[i] = 25.0 * units::kDeg;
  tan_bank[i] = std::tan(bank[i]);
  perf[i] = perf_limits(PerfClass::kJet);
  tgt_tas_alt[i] = std::numeric_limits<double>::quiet_NaN();
  dist2wp[i] = -999.0;
  nextaltco[i] = -999.0;
  dist2vs[i] = -999.0;
  turnspd[i] = oldturnspd[i] = -999.0;
  leg_spd[i] = next_spd[i] = -999.0;
  index[acid] = i;
  return i;
}

void Traffic::erase(int i) {
  index.erase(id[i]);
  for_each_column(*this, [i](auto& v) { v.erase(v.begin() + i); });
  for (int k = i; k < n(); ++k) index[id[k]] = k;
}

void Traffic::clear() {
  for_each_column(*this, [](auto& v) { v.clear(); });
  index.clear();
}

}  // namespace squawk::sim
