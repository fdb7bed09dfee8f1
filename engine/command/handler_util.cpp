#include "command/handler_util.h"

#include <cstdio>

#include "core/text.h"
#include "core/units.h"

namespace squawk::command {

Status for_each_acid(Call& c, size_t i,
                     const std::function<Status(sim::Simulation&, const std::string& acid)>& fn) {
  const std::vector<int>& idx = c[i].acids;
  const sim::Traffic& t = c.stack.sim().traffic();
  if (idx.size() == 1) return fn(c.stack.sim(), t.id[idx[0]]);
  sim::Simulation scratch = c.stack.sim();
  for (int k : idx) SQUAWK_RETURN_IF_ERROR(fn(scratch, t.id[k]));
  c.stack.sim() = std::move(scratch);
  return Status::ok();
}

const std::string& acid_name(const Call& c, size_t i) { return c.stack.sim().traffic().id[c.acid(i)]; }

std::string describe_aircraft(const sim::Traffic& t, int i) {
  char buf[320];
  const sim::Route& r = t.route[i];
  const sim::Waypoint* wp = r.active_waypoint();
  std::snprintf(buf, sizeof buf,
                "%s %s at %.5f %.5f alt %.0f ft hdg %.1f trk %.1f tas %.1f kt cas %.1f kt gs %.1f kt "
                "vs %.0f fpm; selected hdg %.1f alt %.0f ft; LNAV %s VNAV %s; active wpt %s",
                t.id[i].c_str(), t.type[i].c_str(), t.lat[i], t.lon[i], units::m_to_ft(t.alt[i]), t.hdg[i],
                t.trk[i], units::ms_to_kt(t.tas[i]), units::ms_to_kt(t.cas[i]), units::ms_to_kt(t.gs[i]),
                units::ms_to_fpm(t.vs[i]), t.sel_hdg[i], units::m_to_ft(t.sel_alt[i]), on_off(t.lnav[i]),
                on_off(t.vnav[i]), wp ? wp->name.c_str() : "none");
  return buf;
}

sim::Waypoint make_waypoint(const sim::Traffic& t, int i, const ArgValue& pos) {
  sim::Waypoint wp;
  wp.lat = pos.pos.lat;
  wp.lon = pos.pos.lon;
  wp.name = pos.text;
  if (wp.name.empty()) {
    const sim::Route& r = t.route[i];
    for (int k = r.size() + 1;; ++k) {
      std::string name = t.id[i];
      char num[16];
      std::snprintf(num, sizeof num, "%03d", k);
      name.append(num);
      if (r.find(name) < 0) {
        wp.name = std::move(name);
        break;
      }
    }
  }
  return wp;
}

const char* on_off(bool on) { return on ? "ON" : "OFF"; }

}  // namespace squawk::command
