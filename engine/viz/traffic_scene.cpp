#include "viz/traffic_scene.h"

#include <cmath>
#include <set>

#include "core/text.h"
#include "core/units.h"

namespace squawk::viz {

namespace {

Frame sample(const sim::Simulation& s) {
  std::set<int> alert;
  for (const auto& c : s.conflicts()) alert.insert({c.own, c.intruder});
  for (const auto& l : s.los()) alert.insert({l.own, l.intruder});
  const sim::Traffic& t = s.traffic();
  Frame f;
  f.t = s.simt();
  for (int i = 0; i < t.n(); ++i) {
    const double fl = units::m_to_ft(t.alt[i]) / 100.0;
    std::string info = "FL" + text::fmt_double(std::round(fl), 0) + " " +
                       text::fmt_double(std::round(units::ms_to_kt(t.cas[i])), 0) + " kt";
    f.aircraft.push_back({t.id[i], t.lat[i], t.lon[i], t.hdg[i], std::move(info), alert.count(i) > 0});
  }
  return f;
}

}  // namespace

Result<Scene> traffic_scene(command::Stack& stack, double t_end, int frames) {
  const double t0 = stack.sim().simt();
  if (!std::isfinite(t_end) || t_end < t0)
    return Status::invalid("time " + text::fmt_double(t_end, 2) + " s: expected a time >= the current " +
                           text::fmt_double(t0, 2) + " s");
  if (frames < 2) return Status::invalid("a traffic scene needs at least 2 frames");
  Scene scene;
  scene.ownship = false;
  scene.waypoint = false;
  scene.rpz_nm = units::m_to_nm(stack.sim().cd_settings().rpz);
  SQUAWK_RETURN_IF_ERROR(stack.run_until(t0));  // the commands due now
  for (int k = 0; k < frames; ++k) {
    const double t = t0 + (t_end - t0) * k / (frames - 1);
    SQUAWK_RETURN_IF_ERROR(stack.run_until(t));
    scene.frames.push_back(sample(stack.sim()));
  }
  return scene;
}

}  // namespace squawk::viz
