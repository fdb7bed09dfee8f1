// Conflict detection and resolution commands: CDMETHOD (ASAS), RESO, ZONER,
// ZONEDH, DTLOOK, RFACH, RFACV, RESNAV, RMETHV.
#include "command/handler_util.h"
#include "core/text.h"
#include "core/units.h"

namespace squawk::command {

namespace {

Result<std::string> cdmethod(Call& c) {
  sim::Simulation& s = c.stack.sim();
  if (!c.has(0)) return std::string("CDMETHOD ") + (s.cd_settings().enabled ? "STATEBASED" : "OFF");
  const std::string& v = c[0].text;
  if (v == "ON" || v == "STATEBASED" || v == "TRUE" || v == "1") s.set_cd(true);
  else if (v == "OFF" || v == "FALSE" || v == "0") s.set_cd(false);
  else return Status::invalid("argument 1: expected ON, OFF or STATEBASED, got " + text::quoted(v));
  return std::string();
}

Result<std::string> reso(Call& c) {
  sim::Simulation& s = c.stack.sim();
  if (!c.has(0)) return std::string("RESO ") + (s.cr_settings().enabled ? "MVP" : "OFF");
  const std::string& v = c[0].text;
  if (v == "MVP" || v == "ON") s.set_reso(true);
  else if (v == "OFF") s.set_reso(false);
  else return Status::invalid("argument 1: expected MVP or OFF, got " + text::quoted(v));
  return std::string();
}

Result<std::string> zoner(Call& c) {
  sim::Simulation& s = c.stack.sim();
  if (!c.has(0)) return "ZONER " + text::fmt_double(units::m_to_nm(s.cd_settings().rpz), 3) + " NM";
  SQUAWK_RETURN_IF_ERROR(s.set_rpz(units::nm_to_m(c[0].num)));
  return std::string();
}

Result<std::string> zonedh(Call& c) {
  sim::Simulation& s = c.stack.sim();
  if (!c.has(0)) return "ZONEDH " + text::fmt_double(units::m_to_ft(s.cd_settings().hpz), 1) + " ft";
  SQUAWK_RETURN_IF_ERROR(s.set_hpz(units::ft_to_m(c[0].num)));
  return std::string();
}

Result<std::string> dtlook(Call& c) {
  sim::Simulation& s = c.stack.sim();
  if (!c.has(0)) return "DTLOOK " + text::fmt_double(s.cd_settings().dtlook, 2) + " s";
  SQUAWK_RETURN_IF_ERROR(s.set_dtlook(c[0].num));
  return std::string();
}

Result<std::string> rfach(Call& c) {
  sim::Simulation& s = c.stack.sim();
  if (!c.has(0)) return "RFACH " + text::fmt_double(s.cr_settings().resofach, 3);
  SQUAWK_RETURN_IF_ERROR(s.set_resofach(c[0].num));
  return std::string();
}

Result<std::string> rfacv(Call& c) {
  sim::Simulation& s = c.stack.sim();
  if (!c.has(0)) return "RFACV " + text::fmt_double(s.cr_settings().resofacv, 3);
  SQUAWK_RETURN_IF_ERROR(s.set_resofacv(c[0].num));
  return std::string();
}

Result<std::string> resnav(Call& c) {
  const bool resume = c.stack.sim().cr_settings().resume;
  if (!c.has(0)) return std::string("RESNAV ") + (resume ? "PASTCPA" : "OFF");
  const std::string& v = c[0].text;
  if (v == "PASTCPA" || v == "ON") {
    if (resume) return std::string();
  } else if (v != "OFF") {
    return Status::invalid("argument 1: expected PASTCPA or OFF, got " + text::quoted(v));
  }
  return Status::unsupported("squawk always resumes navigation past CPA; RESNAV " + v + " cannot change that");
}

Result<std::string> rmethv(Call& c) {
  sim::Simulation& s = c.stack.sim();
  if (!c.has(0)) return std::string("RMETHV ") + (s.cr_settings().vertical ? "ON" : "OFF");
  const std::string& v = c[0].text;
  if (v == "ON" || v == "V/S") s.set_reso_vertical(true);
  else if (v == "OFF" || v == "NONE") s.set_reso_vertical(false);
  else return Status::invalid("argument 1: expected ON, V/S, OFF or NONE, got " + text::quoted(v));
  return std::string();
}

}  // namespace

void add_asas_commands(std::vector<CommandDecl>& out) {
  out.push_back({"CDMETHOD", {"ASAS"}, "[txt]", "CDMETHOD [ON/OFF/STATEBASED]",
                 "Switches conflict detection on (state-based: straight-line extrapolation over the look-ahead "
                 "time) or off, or shows it. Detection starts off.",
                 {"ASAS ON", "CDMETHOD STATEBASED"}, cdmethod, {}});
  out.push_back({"RESO", {}, "[txt]", "RESO [MVP/OFF]",
                 "Selects conflict resolution: MVP (modified voltage potential, which also switches detection "
                 "on) or OFF; without an argument shows it.",
                 {"RESO MVP", "RESO OFF"}, reso, {}});
  out.push_back({"ZONER", {"PZR", "RPZ", "PZRADIUS"}, "[float]", "ZONER [radius_nm]",
                 "Sets the radius of the protected zone around each aircraft in nautical miles (default 5), or "
                 "shows it.",
                 {"ZONER 5"}, zoner, {}});
  out.push_back({"ZONEDH", {"PZDH", "DHPZ", "PZHEIGHT"}, "[float]", "ZONEDH [halfheight_ft]",
                 "Sets the half height of the protected zone in feet (default 1000), or shows it.", {"ZONEDH 1000"},
                 zonedh, {}});
  out.push_back({"DTLOOK", {}, "[time]", "DTLOOK [seconds]",
                 "Sets how far ahead conflict detection looks, in seconds (default 300), or shows it.",
                 {"DTLOOK 300"}, dtlook, {}});
  out.push_back({"RFACH", {"RESOFACH", "HRFAC", "HRESOFAC"}, "[float]", "RFACH [factor]",
                 "Sets the horizontal safety factor resolutions apply to the protected-zone radius (default "
                 "1.05), or shows it.",
                 {"RFACH 1.1"}, rfach, {}});
  out.push_back({"RFACV", {"RESOFACV"}, "[float]", "RFACV [factor]",
                 "Sets the vertical safety factor resolutions apply to the zone half height (default 1.05), or "
                 "shows it.",
                 {"RFACV 1.05"}, rfacv, {}});
  out.push_back({"RESNAV", {}, "[txt]", "RESNAV [PASTCPA/OFF]",
                 "Shows how aircraft resume navigation after a resolution: once past the closest point of "
                 "approach they fly direct to their active waypoint. Only PASTCPA is available.",
                 {"RESNAV PASTCPA"}, resnav, {}});
  out.push_back({"RMETHV", {}, "[txt]", "RMETHV [ON/V/S/OFF/NONE]",
                 "Lets MVP resolutions also change vertical speed (ON or V/S) or keeps them horizontal (OFF, the "
                 "default).",
                 {"RMETHV V/S", "RMETHV OFF"}, rmethv, {}});
}

}  // namespace squawk::command
