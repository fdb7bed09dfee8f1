#include "translate/world_view.h"

#include <algorithm>

#include "core/text.h"
#include "core/units.h"

namespace squawk::translate {
namespace {

// Altitude as TrafScript writes it: FL250 or feet.
std::optional<double> alt_ft(std::string_view s) {
  if (text::starts_with_ci(s, "FL")) {
    auto v = text::to_double(s.substr(2));
    if (v) return *v * 100.0;
    return std::nullopt;
  }
  return text::to_double(s);
}

}  // namespace

std::optional<AircraftView> WorldView::find(std::string_view id) const {
  for (auto& a : aircraft())
    if (text::iequals(a.id, id)) return a;
  return std::nullopt;
}

Status StaticWorld::apply_setup(std::string_view trafscript) {
  for (auto& line : text::split(trafscript, ';')) {
    if (text::trim(line).empty()) continue;
    SQUAWK_RETURN_IF_ERROR(apply_line(text::trim(line)));
  }
  return Status::ok();
}

Status StaticWorld::apply_line(std::string_view line) {
  std::string l(line);
  std::replace(l.begin(), l.end(), ',', ' ');
  auto a = text::split_ws(l);
  if (a.empty()) return Status::ok();
  std::string cmd = text::upper(a[0]);
  auto bad = [&](const char* expected) {
    std::string msg = "setup line ";
    msg.append(text::quoted(line)).append(": expected ").append(expected);
    return Status::invalid(msg);
  };
  auto find_it = [&](const std::string& id) {
    return std::find_if(aircraft_.begin(), aircraft_.end(), [&](const AircraftView& v) { return text::iequals(v.id, id); });
  };
  auto speed = [](AircraftView& v, std::string_view s) {
    std::string u = text::upper(s);
    if (!u.empty() && (u[0] == 'M' || u[0] == '.')) {
      std::string m = u[0] == 'M' ? u.substr(1) : u;
      if (!m.empty() && m[0] == '.') m.insert(m.begin(), '0');
      v.mach = text::to_double(m).value_or(0.0);
      v.cas_ms = 0.0;
      return v.mach > 0.0;
    }
    auto kt = text::to_double(u);
    if (!kt) return false;
    if (*kt > 0.1 && *kt < 1.0) {
      v.mach = *kt;
      v.cas_ms = 0.0;
    } else {
      v.cas_ms = units::kt_to_ms(*kt);
      v.mach = 0.0;
    }
    return true;
  };
  if (cmd == "CRE" || cmd == "CREATE") {
    if (a.size() < 5) return bad("CRE acid,type,lat,lon,[hdg,alt,spd]");
    AircraftView v;
    v.id = a[1];
    v.type = text::upper(a[2]);
    auto lat = text::to_double(a[3]), lon = text::to_double(a[4]);
    if (!lat || !lon) return bad("a latitude and longitude in degrees");
    v.lat_deg = *lat;
    v.lon_deg = *lon;
    if (a.size() > 5) v.hdg_deg = text::to_double(a[5]).value_or(0.0);
    if (a.size() > 6) {
      auto ft = alt_ft(a[6]);
      if (!ft) return bad("an altitude as FLnnn or feet");
      v.alt_m = units::ft_to_m(*ft);
    }
    if (a.size() > 7 && !speed(v, a[7])) return bad("a speed in knots or Mach");
    if (find_it(v.id) != aircraft_.end()) return bad("a new aircraft id");
    aircraft_.push_back(std::move(v));
  } else if (cmd == "MOVE") {
    if (a.size() < 4) return bad("MOVE acid,lat,lon,[alt,hdg,spd]");
    auto it = find_it(a[1]);
    if (it == aircraft_.end()) return bad("an existing aircraft");
    it->lat_deg = text::to_double(a[2]).value_or(it->lat_deg);
    it->lon_deg = text::to_double(a[3]).value_or(it->lon_deg);
    if (a.size() > 4) it->alt_m = units::ft_to_m(alt_ft(a[4]).value_or(units::m_to_ft(it->alt_m)));
    if (a.size() > 5) it->hdg_deg = text::to_double(a[5]).value_or(it->hdg_deg);
    if (a.size() > 6) speed(*it, a[6]);
  } else if (cmd == "DEL" || cmd == "DELETE") {
    if (a.size() < 2) return bad("DEL acid");
    auto it = find_it(a[1]);
    if (it != aircraft_.end()) aircraft_.erase(it);
  } else if (cmd == "DEFWPT") {
    if (a.size() < 4) return bad("DEFWPT name,lat,lon");
    waypoints_.push_back(a[1]);
  } else if (cmd == "ADDWPT") {
    if (a.size() < 3) return bad("ADDWPT acid,wpt");
    auto it = find_it(a[1]);
    if (it == aircraft_.end()) return bad("an existing aircraft");
    if (!text::to_double(a[2])) it->route.push_back(text::upper(a[2]));
  }
  return Status::ok();
}

}  // namespace squawk::translate
