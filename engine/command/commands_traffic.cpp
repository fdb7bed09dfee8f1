// Traffic and autopilot commands: CRE, CRECONFS, MCRE, DEL, MOVE, POS, HDG,
// ALT, VS, SPD, BANK and the conditional ATALT, ATSPD, ATDIST.
#include <cmath>
#include <set>

#include "command/handler_util.h"
#include "command/line.h"
#include "core/geo.h"
#include "core/text.h"
#include "core/units.h"
#include "sim/atmosphere.h"

namespace squawk::command {

namespace {

// CRE: an omitted heading is the runway's when the position is a runway
// threshold, else 0 (BlueSky's ref.hdg).
Result<std::string> cre(Call& c) {
  const double hdg = c.has(3) ? c[3].num : std::isnan(c[2].ref_hdg) ? 0.0 : c[2].ref_hdg;
  const double alt = c.has(4) ? c[4].num : 0.0;
  const double spd = c.has(5) ? c[5].spd.value : 0.0;
  SQUAWK_RETURN_IF_ERROR(c.stack.sim().create(c[0].text, c[1].text, c[2].pos.lat, c[2].pos.lon, hdg, alt, spd));
  return std::string();
}

Result<std::string> creconfs(Call& c) {
  const sim::Traffic& t = c.stack.sim().traffic();
  const int target = c.acid(2);
  std::optional<double> dh, tlosv, gs;
  if (c.has(6)) dh = c[6].num;
  if (c.has(7)) tlosv = c[7].num;
  if (c.has(8)) gs = sim::casormach_to_tas(c[8].spd.value, t.alt[target]);
  SQUAWK_RETURN_IF_ERROR(c.stack.sim().creconfs(c[0].text, c[1].text, t.id[target], c[3].num,
                                                units::nm_to_m(c[4].num), c[5].num, dh, tlosv, gs));
  return std::string();
}

// MCRE n,[type,alt,spd,dest]: random aircraft in a 2 x 2 deg box around
// 52N 4E (BlueSky's default view centre); `*` or an omitted value draws it.
Result<std::string> mcre(Call& c) {
  const long long n = static_cast<long long>(c[0].num);
  if (n < 1 || n > 10000) return Status::invalid("count must be 1..10000, got " + std::to_string(n));
  const bool rand_type = !c.has(1) || c[1].text == "*";
  const bool rand_alt = !c.has(2) || c[2].type == ArgType::kTxt;
  const bool rand_spd = !c.has(3) || c[3].type == ArgType::kTxt;
  for (size_t k : {size_t{2}, size_t{3}})
    if (c.has(k) && c[k].type == ArgType::kTxt && c[k].text != "*")
      return Status::invalid("argument " + std::to_string(k + 1) + ": expected a value or '*', got " +
                             text::quoted(c[k].text));
  std::optional<ArgValue> dest;
  if (c.has(4) && c[4].text != "*") {
    ArgReader r(c[4].text);
    SQUAWK_ASSIGN_OR_RETURN(dest, parse_position(r, c.stack.parse_context(), {52.0, 4.0}));
  }
  static const char* kTypes[] = {"B744", "A320", "B738", "A332", "E190", "B77W"};
  sim::Simulation scratch = c.stack.sim();
  Rng& rng = scratch.rng();
  for (long long k = 0; k < n; ++k) {
    std::string id;
    do {
      id.clear();
      id.push_back(static_cast<char>('A' + rng.uniform_int(0, 25)));
      id.push_back(static_cast<char>('A' + rng.uniform_int(0, 25)));
      id.append(std::to_string(rng.uniform_int(1000, 9999)));
    } while (scratch.index_of(id) >= 0);
    const std::string type = rand_type ? kTypes[rng.uniform_int(0, 5)] : c[1].text;
    const double lat = rng.uniform(51.0, 53.0);
    const double lon = rng.uniform(3.0, 5.0);
    const double hdg = static_cast<double>(rng.uniform_int(1, 359));
    const double alt = rand_alt ? units::ft_to_m(static_cast<double>(rng.uniform_int(2000, 38999))) : c[2].num;
    const double spd = rand_spd ? units::kt_to_ms(static_cast<double>(rng.uniform_int(250, 449))) : c[3].spd.value;
    SQUAWK_RETURN_IF_ERROR(scratch.create(id, type, lat, lon, hdg, alt, spd));
    if (dest) {
      const int i = scratch.index_of(id);
      SQUAWK_RETURN_IF_ERROR(scratch.set_dest(id, make_waypoint(scratch.traffic(), i, *dest)));
    }
  }
  c.stack.sim() = std::move(scratch);
  return "created " + std::to_string(n) + " aircraft";
}

Result<std::string> del(Call& c) {
  std::set<std::string> ids, shapes;
  bool wind = false;
  for (size_t k = 0; k < c.args.size(); ++k) {
    const ArgValue& a = c[k];
    if (!a.present) continue;
    if (a.type == ArgType::kAcid) {
      for (int i : a.acids) ids.insert(c.stack.sim().traffic().id[i]);
    } else if (a.text == "WIND") {
      wind = true;
    } else if (c.stack.sim().shapes().find(a.text)) {
      shapes.insert(a.text);
    } else {
      return Status::not_found("argument " + std::to_string(k + 1) + ": no aircraft or shape " +
                               text::quoted(a.text));
    }
  }
  for (const auto& id : ids) SQUAWK_RETURN_IF_ERROR(c.stack.sim().remove(id));
  for (const auto& name : shapes) c.stack.sim().delete_shape(name);
  if (wind) c.stack.sim().clear_wind();
  return std::string();
}

Result<std::string> move(Call& c) {
  std::optional<double> alt, hdg, spd, vs;
  if (c.has(2)) alt = c[2].num;
  if (c.has(3)) hdg = c[3].num;
  if (c.has(4)) spd = c[4].spd.value;
  if (c.has(5)) vs = c[5].num;
  SQUAWK_RETURN_IF_ERROR(
      c.stack.sim().move(acid_name(c, 0), c[1].pos.lat, c[1].pos.lon, alt, hdg, spd, vs));
  return std::string();
}

Result<std::string> pos(Call& c) {
  if (c[0].type == ArgType::kAcid) {
    std::string out;
    for (int i : c[0].acids) {
      if (!out.empty()) out.push_back('\n');
      out.append(describe_aircraft(c.stack.sim().traffic(), i));
    }
    return out;
  }
  return c[0].text + " at " + text::fmt_double(c[0].pos.lat, 6) + " " + text::fmt_double(c[0].pos.lon, 6);
}

// HDG acid,hdg,[LEFT/RIGHT]: the direction (L and R accepted) is a squawk
// extension; without it the aircraft turns the short way, as in BlueSky.
Result<std::string> hdg(Call& c) {
  const double h = c[1].num;
  int turn = 0;
  if (c.has(2)) {
    const std::string& d = c[2].text;
    if (d == "LEFT" || d == "L") turn = -1;
    else if (d == "RIGHT" || d == "R") turn = 1;
    else return Status::invalid("argument 3: turn direction " + text::quoted(d) + " is not LEFT, RIGHT, L or R");
  }
  SQUAWK_RETURN_IF_ERROR(for_each_acid(c, 0, [h, turn](sim::Simulation& s, const std::string& id) {
    return s.set_heading(id, h, turn);
  }));
  return std::string();
}

Result<std::string> alt(Call& c) {
  const double a = c[1].num;
  std::optional<double> vs;
  if (c.has(2)) vs = std::fabs(c[2].num);
  SQUAWK_RETURN_IF_ERROR(for_each_acid(c, 0, [a, vs](sim::Simulation& s, const std::string& id) {
    return s.set_altitude(id, a, vs);
  }));
  return std::string();
}

Result<std::string> vs(Call& c) {
  const double v = c[1].num;
  SQUAWK_RETURN_IF_ERROR(for_each_acid(c, 0, [v](sim::Simulation& s, const std::string& id) {
    return s.set_vs(id, v);
  }));
  return std::string();
}

Result<std::string> spd(Call& c) {
  const double v = c[1].spd.value;
  SQUAWK_RETURN_IF_ERROR(for_each_acid(c, 0, [v](sim::Simulation& s, const std::string& id) {
    return s.set_speed(id, v);
  }));
  return std::string();
}

Result<std::string> bank(Call& c) {
  if (!c.has(1)) {
    const int i = c.acid(0);
    return acid_name(c, 0) + " bank angle " + text::fmt_double(units::rad_to_deg(c.stack.sim().traffic().bank[i]), 2) +
           " deg";
  }
  const double b = c[1].num;
  SQUAWK_RETURN_IF_ERROR(for_each_acid(c, 0, [b](sim::Simulation& s, const std::string& id) {
    return s.set_bank(id, b);
  }));
  return std::string();
}

Result<std::string> add_condition(Call& c, Condition::Kind kind, double target, double actual, GeoPoint p,
                                  const std::string& cmd) {
  if (text::trim(cmd).empty()) return Status::invalid("missing the command to run when the condition is met");
  for (int i : c[0].acids) {
    Condition cond;
    cond.acid = c.stack.sim().traffic().id[i];
    cond.kind = kind;
    cond.target = target;
    cond.last_diff = target - actual;
    cond.pos = p;
    cond.command = std::string(text::trim(cmd));
    c.stack.add_condition(std::move(cond));
  }
  return std::string();
}

Result<std::string> atalt(Call& c) {
  return add_condition(c, Condition::Kind::kAlt, c[1].num, c.stack.sim().traffic().alt[c.acid(0)], {}, c[2].text);
}

Result<std::string> atspd(Call& c) {
  const sim::Traffic& t = c.stack.sim().traffic();
  const int i = c.acid(0);
  const double target = c[1].spd.is_mach ? sim::mach_to_cas(c[1].spd.value, t.alt[i]) : c[1].spd.value;
  return add_condition(c, Condition::Kind::kSpd, target, t.cas[i], {}, c[2].text);
}

Result<std::string> atdist(Call& c) {
  const sim::Traffic& t = c.stack.sim().traffic();
  const int i = c.acid(0);
  const GeoPoint p = c[1].pos;
  const double d = units::m_to_nm(geo::gc_distance_m(t.lat[i], t.lon[i], p.lat, p.lon));
  if (c[2].num < 0.0) return Status::invalid("argument 3: distance must be >= 0 NM");
  return add_condition(c, Condition::Kind::kDist, c[2].num, d, p, c[3].text);
}

}  // namespace

void add_traffic_commands(std::vector<CommandDecl>& out) {
  out.push_back({"CRE", {"CREATE"}, "txt,txt,latlon,[hdg,alt,spd]", "CRE acid,type,lat,lon,[hdg,alt,spd]",
                 "Creates an aircraft with callsign acid and ICAO type at a position (lat lon, an airport, "
                 "waypoint or aircraft), with heading in degrees (default 0), altitude in feet or FLnnn "
                 "(default 0) and speed in knots CAS or Mach (M.78). The callsign must be new.",
                 {"CRE KL204 B744 52.0 4.0 90 FL200 250", "CRE AF123,A320,N52'18'00,E004'45'00,270,10000,M.72"},
                 cre, {}});
  out.push_back({"CRECONFS", {}, "txt,txt,acid,hdg,float,time,[alt,time,spd]",
                 "CRECONFS acid,type,targetid,dpsi,cpa,tlosh,[dh,tlosv,spd]",
                 "Creates an intruder set up to conflict with the target aircraft: it flies dpsi degrees off the "
                 "target's track, passes at cpa nautical miles at closest approach, and loses horizontal "
                 "separation after tlosh seconds. Optionally dh feet of altitude offset with tlosv seconds to "
                 "vertical loss, and its own speed.",
                 {"CRECONFS INT1 A320 KL204 90 0 200", "CRECONFS INT2 B738 KL204 180 2 300 2000 240 250"},
                 creconfs, {}});
  out.push_back({"MCRE", {}, "int,[txt,alt/txt,spd/txt,txt]", "MCRE n,[type/*,alt/*,spd/*,dest/*]",
                 "Creates n aircraft with random callsigns at random places in a 2 by 2 degree box around 52N "
                 "4E, with random headings; type, altitude (2000-38999 ft), speed (250-449 kt) are random unless "
                 "given, and dest sets a destination. Draws come from the seeded engine RNG.",
                 {"MCRE 10", "MCRE 5 A320 FL300 * EHAM"}, mcre, {}});
  out.push_back({"DEL", {"DELETE"}, "acid/txt,...", "DEL acid,[acid...]",
                 "Deletes aircraft (or all aircraft with *). DEL WIND clears the wind field.",
                 {"DEL KL204", "DEL *"}, del, {}, true});
  out.push_back({"MOVE", {}, "acid,latlon,[alt,hdg,spd,vspd]", "MOVE acid,lat,lon,[alt,hdg,spd,vspd]",
                 "Puts an aircraft at a new position at once; optional altitude, heading, speed and vertical "
                 "speed are set (and selected) too.",
                 {"MOVE KL204 52.3 4.8", "MOVE KL204 EHAM FL50 180 220"}, move, {}});
  out.push_back({"POS", {}, "acid/wpt", "POS acid/waypoint",
                 "Shows an aircraft's state (position, altitude, speeds, selections, LNAV/VNAV, active "
                 "waypoint), or where a named airport, waypoint or navaid is. A bare callsign means POS.",
                 {"POS KL204", "KL204", "POS EHAM"}, pos, {}, true});
  out.push_back({"HDG", {"HEADING", "TURN"}, "acid,hdg,[txt]", "HDG acid,hdg,[LEFT/RIGHT]",
                 "Selects a heading in degrees; the aircraft turns the short way at its bank angle. Switches "
                 "LNAV off. A name instead of a number means the bearing to that airport, waypoint or aircraft. "
                 "LEFT or RIGHT (L, R) is a squawk extension, not BlueSky: the aircraft turns that way even "
                 "when the other way is shorter, until it has the heading.",
                 {"HDG KL204 270", "KL204 HDG 045", "HDG KL204 300 RIGHT"}, hdg, {}, true});
  out.push_back({"ALT", {}, "acid,alt,[vspd]", "ALT acid,alt,[vspd]",
                 "Selects an altitude in feet or as a flight level; the aircraft climbs or descends to it, at "
                 "vspd feet per minute when given. Switches VNAV off.",
                 {"ALT KL204 FL250", "KL204 ALT 5000 1000"}, alt, {}, true});
  out.push_back({"VS", {}, "acid,vspd", "VS acid,vspd",
                 "Selects the vertical speed in feet per minute used to reach the selected altitude. Switches "
                 "VNAV off.",
                 {"VS KL204 2000"}, vs, {}, true});
  out.push_back({"SPD", {"SPEED"}, "acid,spd", "SPD acid,spd",
                 "Selects a speed: knots CAS (250) or a Mach number (M.78, .78). Switches VNAV speed off.",
                 {"SPD KL204 250", "KL204 SPD M.82"}, spd, {}, true});
  out.push_back({"BANK", {"BANKLIM"}, "acid,[float]", "BANK acid,[bankangle]",
                 "Sets the bank angle in degrees an aircraft uses in turns (default 25), or shows it.",
                 {"BANK KL204 30"}, bank, {}, true});
  out.push_back({"ATALT", {}, "acid,alt,string", "ATALT acid,alt,command",
                 "Runs a command once the aircraft's altitude crosses the given altitude.",
                 {"KL204 ATALT FL100 KL204 SPD 300"}, atalt, {}});
  out.push_back({"ATSPD", {}, "acid,spd,string", "ATSPD acid,spd,command",
                 "Runs a command once the aircraft's calibrated airspeed crosses the given speed (a Mach "
                 "value is converted to CAS at the current altitude).",
                 {"KL204 ATSPD 250 KL204 LNAV ON"}, atspd, {}});
  out.push_back({"ATDIST", {}, "acid,latlon,float,string", "ATDIST acid,position,dist,command",
                 "Runs a command once the aircraft comes within dist nautical miles of a position.",
                 {"KL204 ATDIST EHAM 20 KL204 ALT 3000"}, atdist, {}});
}

}  // namespace squawk::command
