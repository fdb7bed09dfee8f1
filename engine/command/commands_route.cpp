// Route and navigation commands: ADDWPT, AFTER, BEFORE, AT, DELWPT, DELRTE,
// DIRECT, LISTRTE, DEST, ORIG, LNAV, VNAV, DEFWPT.
#include <cmath>
#include <cstdio>

#include "command/handler_util.h"
#include "command/line.h"
#include "command/registry.h"
#include "core/text.h"
#include "core/units.h"
#include "sim/atmosphere.h"

namespace squawk::command {

namespace {

// The position error of a token that matched only as text.
Status position_error(const Call& c, const std::string& token) {
  ArgReader r(token);
  auto p = parse_position(r, c.stack.parse_context(), {});
  return p ? Status::invalid(text::quoted(token) + " is not a waypoint") : p.status();
}

Result<std::string> addwpt(Call& c) {
  // FLYBY / FLYOVER (FLYTURN: fly-by, squawk has no turn-speed legs) switch
  // the mode of the waypoints added next, as in BlueSky, even where a fix of
  // that name exists.
  if (c[1].text == "FLYBY" || c[1].text == "FLYOVER" || c[1].text == "FLYTURN") {
    const sim::Traffic& t = c.stack.sim().traffic();
    SQUAWK_RETURN_IF_ERROR(c.stack.sim().set_flyover_mode(t.id[c.acid(0)], c[1].text == "FLYOVER"));
    return std::string();
  }
  if (c[1].type == ArgType::kTxt) {
    static const char* kModes[] = {"TAKEOFF", "TURNRAD", "TURNSPD", "TURNBANK", "TURNHDG", "TURNHDGR"};
    for (const char* m : kModes)
      if (c[1].text == m)
        return Status::unsupported("ADDWPT mode " + c[1].text + " is not supported by squawk");
    return position_error(c, c[1].text).with_context("argument 2");
  }
  const sim::Traffic& t = c.stack.sim().traffic();
  const int i = c.acid(0);
  sim::Waypoint wp = make_waypoint(t, i, c[1]);
  if (c.has(2)) wp.alt = c[2].num;
  if (c.has(3)) wp.spd = c[3].spd.value;
  const std::string& id = t.id[i];
  if (c.has(4) && c[4].text != "*") SQUAWK_RETURN_IF_ERROR(c.stack.sim().add_waypoint_after(id, c[4].text, wp));
  else if (c.has(5) && c[5].text != "*") SQUAWK_RETURN_IF_ERROR(c.stack.sim().add_waypoint_before(id, c[5].text, wp));
  else SQUAWK_RETURN_IF_ERROR(c.stack.sim().add_waypoint(id, wp));
  return std::string();
}

// AFTER / BEFORE acid wp ADDWPT newwp [alt spd]
Result<std::string> insert_relative(Call& c, bool after) {
  if (!text::iequals(c[2].text, "ADDWPT"))
    return Status::invalid("argument 3: expected ADDWPT, got " + text::quoted(c[2].text));
  if (c[1].text == "*") return Status::invalid("argument 2: needs a waypoint name, not '*'");
  // BlueSky reads the new waypoint as one token: a latitude there has no longitude after it
  if (is_lat(text::upper(c[3].text)))
    return Status::invalid(
        "argument 4: " + text::quoted(c[3].text) +
        " is a latitude, but the new waypoint is one name: define the point first "
        "(DEFWPT name lat lon), then insert it by name");
  // (the new waypoint's name resolves from the reference, at the aircraft: BlueSky's addwptStack)
  ArgReader r(c[3].text);
  const ParseContext ctx = c.stack.parse_context();
  SQUAWK_ASSIGN_OR_RETURN(ArgValue p, parse_position(r, ctx, ctx.ref));
  const sim::Traffic& t = c.stack.sim().traffic();
  const int i = c.acid(0);
  sim::Waypoint wp = make_waypoint(t, i, p);
  if (c.has(4)) wp.alt = c[4].num;
  if (c.has(5)) wp.spd = c[5].spd.value;
  if (after) SQUAWK_RETURN_IF_ERROR(c.stack.sim().add_waypoint_after(t.id[i], c[1].text, wp));
  else SQUAWK_RETURN_IF_ERROR(c.stack.sim().add_waypoint_before(t.id[i], c[1].text, wp));
  return std::string();
}

Result<std::string> after(Call& c) { return insert_relative(c, true); }
Result<std::string> before(Call& c) { return insert_relative(c, false); }

std::string constraint_text(const sim::Waypoint& wp) {
  std::string out;
  out.append(wp.has_alt() ? "FL" + text::fmt_double(units::m_to_fl(wp.alt), 0) : "-----");
  out.append("/");
  if (!wp.has_spd()) out.append("---");
  else if (sim::is_mach(wp.spd)) out.append("M" + text::fmt_double(wp.spd, 3));
  else out.append(text::fmt_double(units::ms_to_kt(wp.spd), 0));
  return out;
}

// Replaces waypoint `name`'s constraints (delete + re-insert on a copy, with
// the active waypoint and LNAV/VNAV switches kept).
Status set_constraints(sim::Simulation& s, const std::string& id, const std::string& name, std::optional<double> alt,
                       std::optional<double> spd) {
  const int i = s.index_of(id);
  const sim::Route& r = s.traffic().route[i];
  const int k = r.find(name);
  sim::Waypoint wp = r.waypoints()[k];
  if (alt) wp.alt = *alt;
  if (spd) wp.spd = *spd;
  const bool was_active = r.active() == k;
  const bool lnav = s.traffic().lnav[i] != 0;
  const bool vnav = s.traffic().vnav[i] != 0;
  if (!r.dest().empty() && r.dest() == wp.name && k == r.size() - 1) {
    SQUAWK_RETURN_IF_ERROR(s.set_dest(id, wp));
  } else if (k == r.size() - 1) {
    SQUAWK_RETURN_IF_ERROR(s.delete_waypoint(id, name));
    SQUAWK_RETURN_IF_ERROR(s.add_waypoint(id, wp));
  } else {
    const std::string next = r.waypoints()[k + 1].name;
    SQUAWK_RETURN_IF_ERROR(s.delete_waypoint(id, name));
    SQUAWK_RETURN_IF_ERROR(s.add_waypoint_before(id, next, wp));
  }
  if (was_active) SQUAWK_RETURN_IF_ERROR(s.direct_to(id, name));
  SQUAWK_RETURN_IF_ERROR(s.set_lnav(id, lnav));
  return s.set_vnav(id, vnav);
}

// The line AT acid wp DO stores for `cmd`: as BlueSky's Route.at, the
// aircraft's id is put first when the command takes an aircraft first and
// `cmd` names none. Checked against the registry and the state now, so that
// a bad command fails the AT that gives it. Error: argument 4, naming the
// command and the waypoint.
Result<std::string> waypoint_command(const Call& c, const std::string& id, const std::string& name,
                                     std::string_view cmd) {
  const std::vector<std::string> words = tokenize(cmd);
  const std::string where = "argument 4: the command to run at " + name;
  if (words.empty() || words[0].empty()) return Status::invalid(where + " is missing");
  const sim::Traffic& t = c.stack.sim().traffic();
  std::string line(cmd);
  if (t.index_of(words[0]) < 0) {
    const Registry& reg = Registry::instance();
    const CommandDecl* d = reg.find(words[0]);
    if (!d) {
      const std::string near = reg.closest(words[0]);
      return Status::not_found(where + ": unknown command " + text::quoted(words[0]) +
                               (near.empty() ? "" : " (did you mean " + near + "?)"));
    }
    const auto& params = d->signature.params;
    const bool takes_acid = !params.empty() && params[0].alternatives.front() == ArgType::kAcid;
    if (takes_acid && !(words.size() > 1 && t.index_of(words[1]) >= 0)) line = id + " " + line;
  }
  const Status st = c.stack.check(line);
  if (!st.is_ok()) return Status::error(st.code(), where + ": " + st.message());
  return line;
}

// Lists the constraints and the stored commands of route waypoint k, as
// BlueSky's AT acid wp shows them ("Stack:" then one command a line).
std::string waypoint_text(const std::string& id, const sim::Waypoint& wp) {
  std::string out = id + " at " + wp.name + ": " + constraint_text(wp);
  if (!wp.commands.empty()) out.append("\nStack:");
  for (const std::string& line : wp.commands) out.append("\n").append(line);
  return out;
}

// AT acid wp [ALT x | SPD x | alt/spd | DO command]
Result<std::string> at(Call& c) {
  const int i = c.acid(0);
  const std::string id = acid_name(c, 0);
  const std::string& name = c[1].text;
  if (name == "*") return Status::invalid("argument 2: needs a waypoint name, not '*'");
  const sim::Route& r = c.stack.sim().traffic().route[i];
  if (!c.has(2)) return waypoint_text(id, r.waypoints()[r.find(name)]);
  const std::string what = text::upper(c[2].text);
  const std::string value = c.has(3) ? std::string(text::trim(c[3].text)) : std::string();
  std::optional<double> alt, spd;
  if (what == "DO" || what == "STACK") {
    SQUAWK_ASSIGN_OR_RETURN(std::string line, waypoint_command(c, id, name, value));
    SQUAWK_RETURN_IF_ERROR(c.stack.sim().add_waypoint_command(id, name, std::move(line)));
    return std::string();
  }
  if (what == "ALT" || what == "SPD") {
    if (value.empty())
      return Status::invalid("argument 4: missing the " + text::lower(what) + " value");
    if (what == "ALT") {
      SQUAWK_ASSIGN_OR_RETURN(alt, parse_alt(value));
    } else {
      SQUAWK_ASSIGN_OR_RETURN(Speed s, parse_spd(value));
      spd = s.value;
    }
  } else if (what.find('/') != std::string::npos && value.empty()) {
    const auto parts = text::split(what, '/');
    if (parts.size() != 2) return Status::invalid("argument 3: expected alt/spd, got " + text::quoted(what));
    if (!parts[0].empty()) {
      SQUAWK_ASSIGN_OR_RETURN(alt, parse_alt(parts[0]));
    }
    if (!parts[1].empty()) {
      SQUAWK_ASSIGN_OR_RETURN(Speed s, parse_spd(parts[1]));
      spd = s.value;
    }
  } else {
    return Status::unsupported(
        "argument 3: squawk supports AT acid wpt [ALT x | SPD x | alt/spd | DO command], not " +
        text::quoted(what));
  }
  sim::Simulation scratch = c.stack.sim();
  SQUAWK_RETURN_IF_ERROR(set_constraints(scratch, id, name, alt, spd));
  c.stack.sim() = std::move(scratch);
  return std::string();
}

Result<std::string> delwpt(Call& c) {
  const std::string id = acid_name(c, 0);
  if (c[1].text == "*") SQUAWK_RETURN_IF_ERROR(c.stack.sim().delete_route(id));
  else SQUAWK_RETURN_IF_ERROR(c.stack.sim().delete_waypoint(id, c[1].text));
  return std::string();
}

Result<std::string> delrte(Call& c) {
  SQUAWK_RETURN_IF_ERROR(for_each_acid(c, 0, [](sim::Simulation& s, const std::string& id) {
    return s.delete_route(id);
  }));
  return std::string();
}

Result<std::string> direct(Call& c) {
  if (c[1].text == "*") return Status::invalid("argument 2: needs a waypoint name, not '*'");
  SQUAWK_RETURN_IF_ERROR(c.stack.sim().direct_to(acid_name(c, 0), c[1].text));
  return std::string();
}

Result<std::string> listrte(Call& c) {
  constexpr int kPerPage = 7;
  const int i = c.acid(0);
  const sim::Route& r = c.stack.sim().traffic().route[i];
  const int pages = std::max(1, (r.size() + kPerPage - 1) / kPerPage);
  const long long page = c.has(1) ? static_cast<long long>(c[1].num) : 1;
  if (page < 1 || page > pages)
    return Status::invalid("argument 2: page must be 1.." + std::to_string(pages) + ", got " + std::to_string(page));
  std::string out = acid_name(c, 0) + " route page " + std::to_string(page) + "/" + std::to_string(pages);
  if (!r.orig().empty()) out.append(", from ").append(r.orig());
  if (!r.dest().empty()) out.append(", to ").append(r.dest());
  if (r.empty()) out.append(": no waypoints");
  for (int k = static_cast<int>(page - 1) * kPerPage; k < std::min(r.size(), static_cast<int>(page) * kPerPage); ++k) {
    const sim::Waypoint& wp = r.waypoints()[k];
    char buf[160];
    std::snprintf(buf, sizeof buf, "\n%s %-10s %10.5f %11.5f %s", k == r.active() ? "*" : " ", wp.name.c_str(),
                  wp.lat, wp.lon, constraint_text(wp).c_str());
    out.append(buf);
  }
  return out;
}

Result<std::string> dest(Call& c) {
  const int i = c.acid(0);
  const sim::Traffic& t = c.stack.sim().traffic();
  if (!c.has(1)) return t.id[i] + " destination: " + (t.route[i].dest().empty() ? "none" : t.route[i].dest());
  SQUAWK_RETURN_IF_ERROR(c.stack.sim().set_dest(t.id[i], make_waypoint(t, i, c[1])));
  return std::string();
}

Result<std::string> orig(Call& c) {
  const int i = c.acid(0);
  const sim::Traffic& t = c.stack.sim().traffic();
  if (!c.has(1)) return t.id[i] + " origin: " + (t.route[i].orig().empty() ? "none" : t.route[i].orig());
  SQUAWK_RETURN_IF_ERROR(c.stack.sim().set_orig(t.id[i], make_waypoint(t, i, c[1])));
  return std::string();
}

Result<std::string> lnav(Call& c) {
  if (!c.has(1)) return acid_name(c, 0) + " LNAV " + on_off(c.stack.sim().traffic().lnav[c.acid(0)]);
  const bool on = c[1].on;
  SQUAWK_RETURN_IF_ERROR(for_each_acid(c, 0, [on](sim::Simulation& s, const std::string& id) {
    return s.set_lnav(id, on);
  }));
  return std::string();
}

Result<std::string> vnav(Call& c) {
  if (!c.has(1)) return acid_name(c, 0) + " VNAV " + on_off(c.stack.sim().traffic().vnav[c.acid(0)]);
  const bool on = c[1].on;
  SQUAWK_RETURN_IF_ERROR(for_each_acid(c, 0, [on](sim::Simulation& s, const std::string& id) {
    return s.set_vnav(id, on);
  }));
  return std::string();
}

Result<std::string> defwpt(Call& c) {
  if (c.has(2) && (c[2].text == "DEL" || c[2].text == "DELETE")) {
    SQUAWK_RETURN_IF_ERROR(c.stack.delete_user_waypoint(c[0].text));
    return std::string();
  }
  if (c.has(2)) {
    static const char* kTypes[] = {"FIX", "VOR", "DME", "NDB", "TACAN"};
    bool known = false;
    for (const char* k : kTypes) known = known || c[2].text == k;
    if (!known)
      return Status::invalid("argument 3: expected FIX, VOR, DME, NDB, TACAN or DELETE, got " +
                             text::quoted(c[2].text));
  }
  SQUAWK_RETURN_IF_ERROR(c.stack.define_waypoint(c[0].text, c[1].pos));
  return std::string();
}

}  // namespace

void add_route_commands(std::vector<CommandDecl>& out) {
  out.push_back({"ADDWPT", {}, "acid,wpt/txt,[alt,spd,wpinroute,wpinroute]",
                 "ADDWPT acid,wpname/lat,lon,[alt,spd,afterwp,beforewp]",
                 "Adds a waypoint (a lat/lon pair, fix, navaid, airport or DEFWPT name) to an aircraft's route, "
                 "with optional altitude and speed constraints, at the end (before the destination) or after / "
                 "before a named route waypoint. Adding switches LNAV on (flying to the active waypoint). "
                 "ADDWPT acid FLYOVER / FLYBY sets whether the waypoints added next are flown over or cut "
                 "(fly-by, the default).",
                 {"ADDWPT KL204 SPY FL250", "ADDWPT KL204 FLYOVER", "KL204 ADDWPT 52.1 4.3,,280", "ADDWPT KL204 PAM ,, , SPY"}, addwpt, {}});
  out.push_back({"AFTER", {}, "acid,wpinroute,word,word,[alt,spd]", "AFTER acid,wpname,ADDWPT,newwp,[alt,spd]",
                 "Inserts a new waypoint into the route right after an existing one, with optional constraints.",
                 {"KL204 AFTER SPL ADDWPT SSB FL100"}, after, {}});
  out.push_back({"BEFORE", {}, "acid,wpinroute,word,word,[alt,spd]", "BEFORE acid,wpname,ADDWPT,newwp,[alt,spd]",
                 "Inserts a new waypoint into the route right before an existing one, with optional constraints.",
                 {"KL204 BEFORE SSB ADDWPT PAM"}, before, {}});
  out.push_back(
      {"AT",
       {},
       "acid,wpinroute,[word,string]",
       "AT acid,wpname,[ALT alt | SPD spd | alt/spd | DO command]",
       "Shows or changes the altitude and speed constraints at a waypoint of the route, or stores "
       "a "
       "command (DO, or its synonym STACK) that runs once each time the aircraft passes the "
       "waypoint, "
       "at the step after it switches to the next one; the aircraft's id is put first when the "
       "command takes an aircraft and names none. Several DO commands run in the order given; they "
       "go with the waypoint when it is deleted. AT acid wpname alone lists the constraints, then "
       "the stored commands after \"Stack:\".",
       {"KL204 AT SPY ALT FL120", "KL204 AT SPY SPD 250", "KL204 AT SPY FL120/250",
        "KL204 AT SPY DO ALT KL204 FL80", "KL204 AT SPY"},
       at,
       {}});
  out.push_back({"DELWPT", {"DELWP"}, "acid,wpinroute", "DELWPT acid,wpname",
                 "Removes a waypoint from an aircraft's route; * removes the whole route.",
                 {"DELWPT KL204 SPY"}, delwpt, {}});
  out.push_back({"DELRTE", {"DELROUTE"}, "acid", "DELRTE acid",
                 "Clears an aircraft's whole route, origin and destination included, and switches LNAV and "
                 "VNAV off.",
                 {"DELRTE KL204"}, delrte, {}, true});
  out.push_back({"DIRECT", {"DIRECTTO", "DIRTO", "DCT"}, "acid,wpinroute", "DIRECT acid,wpname",
                 "Sends the aircraft straight to a waypoint of its route, skipping the ones before it, and "
                 "switches LNAV on.",
                 {"DIRECT KL204 SPY", "KL204 DCT SUGOL"}, direct, {}});
  out.push_back({"LISTRTE", {}, "acid,[int]", "LISTRTE acid,[page]",
                 "Lists the route of an aircraft, seven waypoints per page, with constraints; * marks the "
                 "active waypoint.",
                 {"LISTRTE KL204", "LISTRTE KL204 2"}, listrte, {}});
  out.push_back({"DEST", {}, "acid,[wpt]", "DEST acid,[airport/waypoint]",
                 "Sets the destination (an airport or any position) as the last waypoint of the route, or shows "
                 "it.",
                 {"DEST KL204 EHAM"}, dest, {}});
  out.push_back({"ORIG", {}, "acid,[wpt]", "ORIG acid,[airport/waypoint]",
                 "Records the origin airport of an aircraft's flight plan, or shows it.", {"ORIG KL204 EGLL"}, orig, {}});
  out.push_back({"LNAV", {}, "acid,[onoff]", "LNAV acid,[ON/OFF]",
                 "Switches lateral navigation along the route on or off, or shows it. On needs a route with an "
                 "active waypoint.",
                 {"LNAV KL204 ON"}, lnav, {}, true});
  out.push_back({"VNAV", {}, "acid,[onoff]", "VNAV acid,[ON/OFF]",
                 "Switches vertical navigation (following the route's altitude and speed constraints) on or "
                 "off, or shows it. On also switches LNAV on.",
                 {"VNAV KL204 ON"}, vnav, {}, true});
  out.push_back({"DEFWPT", {}, "txt,latlon,[txt]", "DEFWPT name,lat,lon,[FIX/VOR/DME/NDB/DELETE]",
                 "Defines a named waypoint for this run (it can then be used wherever a position is expected), "
                 "or deletes one with DELETE.",
                 {"DEFWPT ETPOS N52'35'06.44\" E003'24'51.04\"", "DEFWPT MYFIX 52.0 4.2 FIX"}, defwpt, {}});
}

}  // namespace squawk::command
