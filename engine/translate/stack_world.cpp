#include "translate/stack_world.h"

#include "core/text.h"

namespace squawk::translate {

std::vector<AircraftView> StackWorld::aircraft() const {
  const auto& t = stack_.sim().traffic();
  std::vector<AircraftView> out;
  out.reserve(t.id.size());
  for (size_t i = 0; i < t.id.size(); ++i) {
    AircraftView a;
    a.id = t.id[i];
    a.type = t.type[i];
    a.lat_deg = t.lat[i];
    a.lon_deg = t.lon[i];
    a.hdg_deg = t.hdg[i];
    a.alt_m = t.alt[i];
    a.cas_ms = t.cas[i];
    for (const auto& w : t.route[i].waypoints()) a.route.push_back(w.name);
    out.push_back(std::move(a));
  }
  return out;
}

std::vector<std::string> StackWorld::waypoints() const {
  std::vector<std::string> names;
  for (const auto& [name, pos] : stack_.user_waypoints()) names.push_back(name);
  return names;
}

Status setup_stack(command::Stack& stack, std::string_view setup) {
  if (text::trim(setup).empty()) return Status::ok();
  // Queued like a scenario line: commands squawk lacks (display-only ones
  // such as TRAIL) are skipped, real failures are kept in the tally.
  stack.schedule(stack.sim().simt(), std::string(setup));
  stack.process_due();
  const auto& tally = stack.tally();
  if (!tally.failed.empty()) {
    std::string msg = "setup failed: ";
    msg.append(tally.first_failures.empty() ? tally.failed.begin()->first : tally.first_failures.front());
    return Status::invalid(msg);
  }
  return Status::ok();
}

}  // namespace squawk::translate
