#include "translate/scorer.h"

#include "command/formats.h"
#include "command/registry.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "core/text.h"

namespace squawk::translate {
namespace {

enum class Arg { kWord, kNum, kMagnitude, kVs, kAlt, kSpd, kHdg, kTurn, kLat, kLon, kTime, kRest };

// Words and comma-separated arguments; an argument left out between commas
// ("ADDWPT KL204 SPY,,,AFTERWP") keeps its place as an empty one. A comma
// at either end of a word only separates ("ALT KL204, FL100"), and trailing
// empty arguments are dropped.
std::vector<std::string> tokens(std::string_view cmd) {
  std::vector<std::string> out;
  for (const auto& w : text::split_ws(cmd)) {
    if (w.find_first_not_of(',') == std::string::npos) continue;  // a lone comma separates
    auto parts = text::split(w, ',');
    const size_t b = w.front() == ',' ? 1 : 0, e = parts.size() - (w.size() > 1 && w.back() == ',' ? 1 : 0);
    for (size_t i = b; i < e; ++i) out.push_back(std::move(parts[i]));
  }
  while (!out.empty() && out.back().empty()) out.pop_back();
  return out;
}

std::optional<double> alt_ft(const std::string& s) {
  if (text::starts_with_ci(s, "FL")) {
    auto v = text::to_double(s.substr(2));
    return v ? std::optional<double>(*v * 100.0) : std::nullopt;
  }
  return text::to_double(s);
}

// Speed as (value, is_mach).
std::optional<std::pair<double, bool>> speed(const std::string& s) {
  std::string u = text::upper(s);
  if (u.empty()) return std::nullopt;
  if (u[0] == 'M' || u[0] == '.') {
    std::string m = u[0] == 'M' ? u.substr(1) : u;
    if (!m.empty() && m[0] == '.') m.insert(m.begin(), '0');
    auto v = text::to_double(m);
    if (!v) return std::nullopt;
    return std::make_pair(*v >= 1.0 ? *v / 100.0 : *v, true);
  }
  auto v = text::to_double(u);
  if (!v) return std::nullopt;
  if (*v > 0.1 && *v < 1.0) return std::make_pair(*v, true);
  return std::make_pair(*v, false);
}

// HDG's turn direction (a squawk extension) with its shorthands folded: L -> LEFT, R -> RIGHT.
std::string turn_word(const std::string& s) {
  const std::string u = text::upper(s);
  if (u == "L") return "LEFT";
  if (u == "R") return "RIGHT";
  return u;
}

bool is_turn_word(const std::string& s) {
  const std::string u = turn_word(s);
  return u == "LEFT" || u == "RIGHT";
}

bool same_arg(const std::string& a, const std::string& b, Arg kind) {
  auto num_eq = [](const std::string& x, const std::string& y, double tol) {
    auto u = text::to_double(x), v = text::to_double(y);
    return u && v && std::fabs(*u - *v) <= tol;
  };
  if (a.empty() || b.empty()) return a.empty() && b.empty();
  if (text::iequals(a, b)) return true;
  switch (kind) {
    case Arg::kAlt: {
      auto u = alt_ft(a), v = alt_ft(b);
      return u && v && std::fabs(*u - *v) <= 50.0;
    }
    case Arg::kSpd: {
      auto u = speed(a), v = speed(b);
      if (!u || !v || u->second != v->second) return false;
      return std::fabs(u->first - v->first) <= (u->second ? 0.0005 : 0.5);
    }
    case Arg::kHdg: {
      auto u = text::to_double(a), v = text::to_double(b);
      if (!u || !v) return text::iequals(a, b);
      double d = std::fmod(std::fabs(*u - *v), 360.0);
      return std::min(d, 360.0 - d) <= 0.5;
    }
    case Arg::kTurn:
      return turn_word(a) == turn_word(b);
    case Arg::kMagnitude: {  // a vertical speed's size [ft/min], within 1 ft/min (0.005 m/s)
      auto u = text::to_double(a), v = text::to_double(b);
      return u && v && std::fabs(std::fabs(*u) - std::fabs(*v)) <= 1.0;
    }
    case Arg::kVs:
      return num_eq(a, b, 1.0);
    case Arg::kTime: {  // [s], as the simulator reads it: "1:30" (MM:SS) is 90
      auto u = command::parse_time(a), v = command::parse_time(b);
      return u.is_ok() && v.is_ok() && std::fabs(*u - *v) <= 0.5;
    }
    case Arg::kLat:
    case Arg::kLon:
      return num_eq(a, b, 1e-3) || text::iequals(a, b);
    case Arg::kNum:
    case Arg::kWord:
    case Arg::kRest: {
      if (text::iequals(a, b)) return true;
      auto u = text::to_double(a), v = text::to_double(b);
      return u && v && std::fabs(*u - *v) <= 1e-9 * std::max(1.0, std::fabs(*v));
    }
  }
  return false;
}

// Argument kinds of `args` (after the command name) by the command registry's type list: an
// altitude, a speed, a heading, a vertical speed or a time compared as one (FL080 = FL80 = 8000 ft
// wherever the registry declares an altitude); a position (latlon, wpt) given as two numbers is a
// latitude and a longitude, given as a name one word; every other type a number or a word. Empty
// when the registry does not know the command.
std::vector<Arg> registry_kinds(const std::string& cmd, const std::vector<std::string>& args) {
  const auto* d = command::Registry::instance().find(cmd);
  if (!d || d->signature.params.empty()) return {};
  const auto& params = d->signature.params;
  auto has = [](const command::ParamSpec& p, command::ArgType t) {
    return std::find(p.alternatives.begin(), p.alternatives.end(), t) != p.alternatives.end();
  };
  std::vector<Arg> out;
  for (size_t i = 0, k = 0; i < args.size(); ++k) {
    if (k >= params.size() && !d->signature.repeat_last) break;
    const auto& p = params[std::min(k, params.size() - 1)];
    using T = command::ArgType;
    if ((has(p, T::kLatLon) || has(p, T::kWpt)) && text::to_double(args[i]) &&
        i + 1 < args.size() && text::to_double(args[i + 1])) {
      out.push_back(Arg::kLat);
      out.push_back(Arg::kLon);
      i += 2;
      continue;
    }
    out.push_back(has(p, T::kAlt)    ? Arg::kAlt
                  : has(p, T::kSpd)  ? Arg::kSpd
                  : has(p, T::kHdg)  ? Arg::kHdg
                  : has(p, T::kVspd) ? Arg::kVs
                  : has(p, T::kTime) ? Arg::kTime
                                     : Arg::kNum);
    ++i;
  }
  return out;
}

// Argument kinds after the command name; the last kind repeats.
std::vector<Arg> arg_kinds(const std::string& cmd, const std::vector<std::string>& args) {
  using A = Arg;
  if (cmd == "CRE") {
    if (args.size() >= 3 && !text::to_double(args[2]))  // at a named place: CRE acid type WPT hdg alt spd
      return {A::kWord, A::kWord, A::kWord, A::kHdg, A::kAlt, A::kSpd};
    return {A::kWord, A::kWord, A::kLat, A::kLon, A::kHdg, A::kAlt, A::kSpd};
  }
  if (cmd == "ALT") return {A::kWord, A::kAlt, A::kMagnitude};  // ALT reads |vspd|
  if (cmd == "SPD") return {A::kWord, A::kSpd};
  if (cmd == "VS") return {A::kWord, A::kVs};
  if (cmd == "HDG") return {A::kWord, A::kHdg, A::kTurn};
  if (cmd == "AT" && args.size() >= 4)  // AT acid wpt ALT alt | SPD spd
    return {A::kWord, A::kWord, A::kWord, text::iequals(args[2], "SPD") ? A::kSpd : A::kAlt};
  if (cmd == "FF") return {A::kTime};
  if (cmd == "SCHEDULE" || cmd == "DELAY") return {A::kTime, A::kNum};
  if (cmd == "DEFWPT") return {A::kWord, A::kLat, A::kLon, A::kWord};
  if (cmd == "ADDWPT" || cmd == "DEST" || cmd == "ORIG") {
    if (args.size() >= 3 && text::to_double(args[1]) && text::to_double(args[2]))
      return {A::kWord, A::kLat, A::kLon, A::kAlt, A::kSpd, A::kWord};
    return {A::kWord, A::kWord, A::kAlt, A::kSpd, A::kWord};
  }
  auto kinds = registry_kinds(cmd, args);
  if (!kinds.empty()) return kinds;
  return {A::kNum};
}

}  // namespace

std::vector<std::string> split_commands(std::string_view list) {
  std::vector<std::string> out;
  for (auto& part : text::split(list, ';')) {
    auto t = text::trim(part);
    if (!t.empty()) out.emplace_back(t);
  }
  return out;
}

// Aliases folded by the command registry (CREATE -> CRE, ASAS -> CDMETHOD).
std::string canonical_command(std::string_view name) {
  if (const auto* d = command::Registry::instance().find(name)) return d->name;
  return text::upper(name);
}

namespace {
// BlueSky's callsign-first form ("KL204 SPD 250") as command-first ("SPD KL204 250").
void command_first(std::vector<std::string>& v) {
  if (v.size() >= 2 && !command::Registry::instance().find(v[0]) && command::Registry::instance().find(v[1]))
    std::swap(v[0], v[1]);
}

// True when the commands that follow the first n words of p and e (a condition's or a delay's
// fields) are equal, compared as commands (same_command).
bool same_tail(const std::vector<std::string>& p, const std::vector<std::string>& e, size_t n) {
  auto tail = [n](const std::vector<std::string>& v) {
    return text::join(std::vector<std::string>(v.begin() + n, v.end()), " ");
  };
  return same_command(tail(p), tail(e));
}
}  // namespace

bool same_command(std::string_view produced, std::string_view expected) {
  auto p = tokens(produced), e = tokens(expected);
  if (p.empty() || e.empty()) return p.empty() && e.empty();
  command_first(p);
  command_first(e);
  std::string cmd = canonical_command(p[0]);
  if (cmd != canonical_command(e[0])) return false;
  if (cmd == "ECHO") {
    auto rest = [](const std::vector<std::string>& v) {
      return text::lower(text::join(std::vector<std::string>(v.begin() + 1, v.end()), " "));
    };
    return rest(p) == rest(e);
  }
  if (cmd == "ATALT" || cmd == "ATSPD") {
    if (p.size() < 4 || e.size() < 4) return p.size() == e.size() && text::iequals(text::join(p, " "), text::join(e, " "));
    Arg k = cmd == "ATALT" ? Arg::kAlt : Arg::kSpd;
    if (!text::iequals(p[1], e[1]) || !same_arg(p[2], e[2], k)) return false;
    return same_tail(p, e, 3);
  }
  // AT acid wpt DO CMD ... (STACK is DO): the aircraft and waypoint, then the command run there,
  // compared as one
  auto stored = [](const std::vector<std::string>& v) {
    return v.size() > 4 && (text::iequals(v[3], "DO") || text::iequals(v[3], "STACK"));
  };
  if (cmd == "AT" && (stored(p) || stored(e))) {
    if (!stored(p) || !stored(e) || !text::iequals(p[1], e[1]) || !text::iequals(p[2], e[2]))
      return false;
    return same_tail(p, e, 4);
  }
  // ATDIST acid wpt dist CMD ...: the place and distance [NM], then the command it runs, compared
  // as one
  if (cmd == "ATDIST" && p.size() > 4 && e.size() > 4) {
    if (!text::iequals(p[1], e[1]) || !text::iequals(p[2], e[2]) ||
        !same_arg(p[3], e[3], Arg::kNum))
      return false;
    return same_tail(p, e, 4);
  }
  // DELAY / SCHEDULE time CMD ...: the time (seconds or a clock time), then the command it runs,
  // compared as one
  if ((cmd == "DELAY" || cmd == "SCHEDULE") && p.size() > 2 && e.size() > 2) {
    if (!same_arg(p[1], e[1], Arg::kTime)) return false;
    return same_tail(p, e, 2);
  }
  // RMETHV ON and V/S both switch vertical resolutions on, OFF and NONE off
  // (commands_asas.cpp rmethv).
  if (cmd == "RMETHV") {
    auto fold = [](std::string& v) {
      if (text::iequals(v, "V/S"))
        v = "ON";
      else if (text::iequals(v, "NONE"))
        v = "OFF";
    };
    for (size_t i = 1; i < p.size(); ++i) fold(p[i]);
    for (size_t i = 1; i < e.size(); ++i) fold(e[i]);
  }
  // CDMETHOD (ASAS) ON picks the first detection method, STATEBASED (BlueSky detection.py L93-122)
  if (cmd == "CDMETHOD") {
    for (auto* v : {&p, &e})
      for (size_t i = 1; i < v->size(); ++i)
        if (text::iequals((*v)[i], "STATEBASED")) (*v)[i] = "ON";
  }
  // A turn direction produced where the expected HDG states none: the
  // expected line predates the extension and names the same heading.
  if (cmd == "HDG" && p.size() == 4 && e.size() == 3 && is_turn_word(p[3])) p.pop_back();
  if (p.size() != e.size()) return false;
  std::vector<std::string> args(e.begin() + 1, e.end());
  auto kinds = arg_kinds(cmd, args);
  for (size_t i = 1; i < p.size(); ++i) {
    Arg k = kinds[std::min(i - 1, kinds.size() - 1)];
    if (!same_arg(p[i], e[i], k)) return false;
  }
  return true;
}

namespace {
// "ALT acid alt" and "VS acid vspd" next to each other, in either order, for
// the same aircraft are one clearance: "ALT acid alt vspd" (the simulator's
// ALT with a vertical speed sets the selected altitude and |vspd|, as the two
// commands do; Simulation::set_altitude, set_vs). "LNAV acid ON" right after
// "DIRECT acid wpt" adds nothing (a direct-to switches LNAV on: route_op).
// "AFTER acid wp ADDWPT new [alt spd]" is "ADDWPT acid new,alt,spd,wp" and
// BEFORE its beforewp (commands_route.cpp: both insert the same waypoint).
// "AT acid wp alt/spd" is "AT acid wp ALT alt" and "AT acid wp SPD spd", and
// the two for one waypoint read altitude first (commands_route.cpp `at` sets
// the same constraints either way).
std::vector<std::string> fold_clearances(std::vector<std::string> cmds) {
  auto words = [](const std::string& c) {
    auto v = tokens(c);
    command_first(v);
    if (!v.empty()) v[0] = canonical_command(v[0]);
    return v;
  };
  for (size_t i = 0; i < cmds.size(); ++i) {
    auto v = words(cmds[i]);
    if (v.size() != 4 || v[0] != "AT" || v[3].find('/') == std::string::npos) continue;
    const auto parts = text::split(v[3], '/');
    if (parts.size() != 2) continue;
    const std::string at = "AT " + v[1] + " " + v[2];
    std::vector<std::string> split;
    if (!parts[0].empty()) split.push_back(at + " ALT " + parts[0]);
    if (!parts[1].empty()) split.push_back(at + " SPD " + parts[1]);
    cmds.erase(cmds.begin() + static_cast<std::ptrdiff_t>(i));
    cmds.insert(cmds.begin() + static_cast<std::ptrdiff_t>(i), split.begin(), split.end());
  }
  for (size_t i = 0; i + 1 < cmds.size(); ++i) {
    auto a = words(cmds[i]), b = words(cmds[i + 1]);
    if (a.size() == 5 && b.size() == 5 && a[0] == "AT" && b[0] == "AT" &&
        text::iequals(a[1], b[1]) && text::iequals(a[2], b[2]) && text::iequals(a[3], "SPD") &&
        text::iequals(b[3], "ALT"))
      std::swap(cmds[i], cmds[i + 1]);
  }
  for (auto& c : cmds) {
    auto v = words(c);
    if (v.size() < 5 || (v[0] != "AFTER" && v[0] != "BEFORE") || !text::iequals(v[3], "ADDWPT"))
      continue;
    const std::string alt = v.size() > 5 ? v[5] : "", spd = v.size() > 6 ? v[6] : "";
    c = "ADDWPT " + v[1] + " " + v[4] + "," + alt + "," + spd + "," +
        (v[0] == "AFTER" ? v[2] : "," + v[2]);
  }
  for (size_t i = 0; i + 1 < cmds.size(); ++i) {
    auto a = words(cmds[i]), b = words(cmds[i + 1]);
    if (a.size() == 3 && b.size() == 3 && a[0] == "VS" && b[0] == "ALT") std::swap(a, b);
    if (a.size() == 3 && b.size() == 3 && a[0] == "ALT" && b[0] == "VS" &&
        text::iequals(a[1], b[1])) {
      cmds[i] = "ALT " + a[1] + " " + a[2] + " " + b[2];
      cmds.erase(cmds.begin() + static_cast<std::ptrdiff_t>(i) + 1);
    } else if (a.size() >= 3 && b.size() == 3 && a[0] == "DIRECT" && b[0] == "LNAV" &&
               text::iequals(a[1], b[1]) && text::iequals(b[2], "ON")) {
      cmds.erase(cmds.begin() + static_cast<std::ptrdiff_t>(i) + 1);
    }
  }
  return cmds;
}

// The waypoint each aircraft's route ends with after `setup` (upper-case id -> name), as its ADDWPT
// lines leave it: one with no afterwp or beforewp, or with the end as its afterwp, is the new end;
// DEST adds no waypoint of the route (ADDWPT puts new ones before it); DELRTE, and DELWPT of the
// end, leave the end unknown.
std::map<std::string, std::string> route_ends(std::string_view setup) {
  std::map<std::string, std::string> ends;
  for (const auto& c : split_commands(setup)) {
    auto v = tokens(c);
    command_first(v);
    if (v.size() < 2) continue;
    const std::string cmd = canonical_command(v[0]), id = text::upper(v[1]);
    if (cmd == "DELRTE" || (cmd == "DELWPT" && v.size() > 2 && text::iequals(v[2], ends[id])))
      ends.erase(id);
    if (cmd != "ADDWPT" || v.size() < 3) continue;
    // (a position in degrees, "ADDWPT id 39 -15": a name of its own the text does not give; the end
    // unknown)
    const bool position = v.size() > 3 && text::to_double(v[2]) && text::to_double(v[3]);
    const size_t rest = position ? 4 : 3;
    const std::string after = v.size() > rest + 2 ? v[rest + 2] : "",
                      before = v.size() > rest + 3 ? v[rest + 3] : "";
    if (!before.empty() || (!after.empty() && !text::iequals(after, ends[id]))) continue;
    if (position)
      ends.erase(id);
    else
      ends[id] = text::upper(v[2]);
  }
  return ends;
}

// "ADDWPT id X,alt,spd,END" with END the waypoint id's route ends with after the setup (route_ends)
// as "ADDWPT id X,alt,spd": ADDWPT with no afterwp puts X at the route's end, after END, the same
// route (commands_route.cpp).
std::vector<std::string> plain_after_end(std::vector<std::string> cmds,
                                         const std::map<std::string, std::string>& ends) {
  for (auto& c : cmds) {
    auto v = tokens(c);
    command_first(v);
    if (v.size() < 3 || canonical_command(v[0]) != "ADDWPT") continue;
    const size_t rest = v.size() > 3 && text::to_double(v[2]) && text::to_double(v[3]) ? 4 : 3;
    const auto end = ends.find(text::upper(v[1]));
    if (end == ends.end() || v.size() != rest + 3 || !text::iequals(v[rest + 2], end->second))
      continue;
    std::string plain = "ADDWPT " + v[1] + " " + v[2] + (rest == 4 ? " " + v[3] : "");
    c = plain + "," + v[rest] + "," + v[rest + 1];
  }
  return cmds;
}
}  // namespace

bool score_case(std::string_view produced, bool asked, std::string_view expected,
                std::string_view setup) {
  const auto ends = route_ends(setup);
  for (const auto& alt_raw : text::split(expected, '|')) {
    auto alt = text::trim(alt_raw);
    if (alt.empty()) continue;
    if (text::iequals(alt, "ASK")) {
      if (asked) return true;
      continue;
    }
    if (asked) continue;
    auto p = plain_after_end(fold_clearances(split_commands(produced)), ends),
         e = plain_after_end(fold_clearances(split_commands(alt)), ends);
    if (p.size() != e.size()) continue;
    bool all = true;
    for (size_t i = 0; i < p.size() && all; ++i) all = same_command(p[i], e[i]);
    if (all) return true;
  }
  return false;
}

}  // namespace squawk::translate
