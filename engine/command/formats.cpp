#include "command/formats.h"

#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "core/geo.h"
#include "core/text.h"
#include "core/units.h"

namespace squawk::command {

namespace {

Status bad(std::string_view what, std::string_view token, std::string_view expected) {
  std::string msg(what);
  msg.append(" ").append(text::quoted(token)).append(" is not ").append(expected);
  return Status::invalid(std::move(msg));
}

void replace_all(std::string& s, std::string_view from, std::string_view to) {
  for (size_t pos = s.find(from); pos != std::string::npos; pos = s.find(from, pos + to.size()))
    s.replace(pos, from.size(), to);
}

// Degrees from "D'M'S" (separators ' " or the degree sign; empty parts are
// skipped) or from a plain decimal number. `s` carries no hemisphere letter;
// a leading '-' makes the result negative.
std::optional<double> degrees_of(std::string s) {
  bool neg = false;
  if (!s.empty() && (s.front() == '-' || s.front() == '+')) {
    neg = s.front() == '-';
    s.erase(0, 1);
  }
  if (s.empty() || s.front() == '-' || s.front() == '+') return std::nullopt;
  replace_all(s, "\xC2\xB0", "'");
  replace_all(s, "\"", "'");
  double v = 0.0;
  if (s.find('\'') == std::string::npos) {
    auto x = text::to_double(s);
    if (!x || *x < 0.0) return std::nullopt;
    v = *x;
  } else {
    double div = 1.0;
    for (const auto& part : text::split(s, '\'')) {
      if (part.empty()) continue;
      auto x = text::to_double(part);
      if (!x || *x < 0.0 || div > 3600.0) return std::nullopt;
      v += *x / div;
      div *= 60.0;
    }
  }
  return neg ? -v : v;
}

// Splits an optional hemisphere prefix (pos/neg letters) off an upper-cased
// token; returns the sign it implies (+1 when none).
double take_hemisphere(std::string& s, char pos, char neg) {
  if (!s.empty() && (s.front() == pos || s.front() == neg)) {
    const double sign = s.front() == neg ? -1.0 : 1.0;
    s.erase(0, 1);
    return sign;
  }
  return 1.0;
}

}  // namespace

Result<double> parse_alt(std::string_view token) {
  const std::string u = text::upper(text::trim(token));
  if (u.size() >= 4 && u.compare(0, 2, "FL") == 0) {
    auto fl = text::to_int(std::string_view(u).substr(2));
    if (!fl || *fl < 0 || *fl > 1000) return bad("altitude", token, "a flight level (FL0..FL1000) or feet");
    return units::fl_to_m(static_cast<double>(*fl));
  }
  auto ft = text::to_double(u);
  if (!ft || *ft < -2000.0 || *ft > 100000.0)
    return bad("altitude", token, "a flight level (FL250) or feet (-2000..100000)");
  return units::ft_to_m(*ft);
}

Result<Speed> parse_spd(std::string_view token) {
  std::string u = text::upper(text::trim(token));
  const bool has_m = u.find('M') != std::string::npos;
  replace_all(u, "M0.", ".");
  replace_all(u, "M", ".");
  replace_all(u, "..", ".");
  auto v = text::to_double(u);
  if (!v || *v < 0.0) return bad("speed", token, "knots CAS (250) or a Mach number (M.78, .78)");
  Speed s;
  if ((*v > 0.1 && *v < 1.0) || has_m) {
    if (*v <= 0.1 || *v >= 2.0) return bad("speed", token, "a Mach number between 0.1 and 2");
    s.is_mach = true;
    s.value = *v;
  } else {
    if (*v > 2000.0) return bad("speed", token, "knots CAS below 2000");
    s.value = units::kt_to_ms(*v);
  }
  return s;
}

Result<double> parse_vspd(std::string_view token) {
  auto v = text::to_double(token);
  if (!v || std::fabs(*v) > 100000.0) return bad("vertical speed", token, "feet per minute (e.g. 1500, -800)");
  return units::fpm_to_ms(*v);
}

bool is_hdg_number(std::string_view token) {
  std::string u = text::upper(text::trim(token));
  if (u.empty()) return false;
  // One T or M, as prefix or suffix.
  if (u.front() == 'T' || u.front() == 'M') u.erase(0, 1);
  else if (u.back() == 'T' || u.back() == 'M') u.pop_back();
  return text::to_double(u).has_value();
}

Result<double> parse_hdg(std::string_view token) {
  std::string u = text::upper(text::trim(token));
  if (!is_hdg_number(u)) return bad("heading", token, "degrees (090, 236.9T, M270)");
  // BlueSky drops leading zeros before reading the number, so "0." (and
  // "00.") become "." and are refused; squawk refuses them too.
  std::string z = u;
  while (z.size() > 1 && z[0] == '0') z.erase(0, 1);
  if (z == "." || z == ".T" || z == ".M")
    return bad("heading", token, "degrees; BlueSky reads `0.` as `.` after dropping leading zeros (write 0)");
  if (u.front() == 'T' || u.front() == 'M') u.erase(0, 1);
  else if (u.back() == 'T' || u.back() == 'M') u.pop_back();
  const double v = *text::to_double(u);
  if (std::fabs(v) > 3600.0) return bad("heading", token, "degrees within +-3600");
  return v;
}

Result<double> parse_time(std::string_view token) {
  const auto parts = text::split(text::trim(token), ':');
  const Status err = bad("time", token, "SS.hh, MM:SS.hh or HH:MM:SS.hh");
  if (parts.empty() || parts.size() > 3) return err;
  auto sec = text::to_double(parts.back());
  if (!sec) return err;
  double t = *sec;
  const double scale[] = {60.0, 3600.0};
  for (size_t k = 1; k < parts.size(); ++k) {
    const std::string& p = parts[parts.size() - 1 - k];
    if (p.empty()) continue;
    auto n = text::to_int(p);
    if (!n || std::llabs(*n) > 1000000) return err;
    t += scale[k - 1] * static_cast<double>(*n);
  }
  if (std::fabs(t) > 1e9) return err;
  return t;
}

bool is_lat(std::string_view token) {
  std::string u = text::upper(text::trim(token));
  while (!u.empty() && (u.front() == '-' || u.front() == '+')) u.erase(0, 1);
  std::string rest;
  for (char c : u)
    if (c != '\'' && c != '"' && c != '.') rest.push_back(c);
  if (rest.size() > 1 && (rest.front() == 'N' || rest.front() == 'S')) rest.erase(0, 1);
  return !rest.empty() && (std::isdigit(static_cast<unsigned char>(rest.front())) != 0) &&
         text::to_double(rest).has_value();
}

Result<double> parse_lat(std::string_view token) {
  std::string u = text::upper(text::trim(token));
  const double sign = take_hemisphere(u, 'N', 'S');
  auto v = degrees_of(u);
  if (!v || std::fabs(*v) > 90.0)
    return bad("latitude", token, "degrees in [-90, 90] (52.3, N52.3, S12'30'00\")");
  return sign * *v;
}

Result<double> parse_lon(std::string_view token) {
  std::string u = text::upper(text::trim(token));
  std::optional<double> v = text::to_double(u);
  if (!v) {
    const double sign = take_hemisphere(u, 'E', 'W');
    v = degrees_of(u);
    if (v) *v *= sign;
  }
  if (!v || std::fabs(*v) > 360.0)
    return bad("longitude", token, "degrees in [-360, 360] (4.5, E004'23'10\", W002')");
  return geo::wrap180(*v) == 180.0 ? -180.0 : geo::wrap180(*v);
}

Result<bool> parse_onoff(std::string_view token) {
  const std::string l = text::lower(text::trim(token));
  for (const char* t : {"true", "yes", "y", "1", "on"})
    if (l == t) return true;
  for (const char* f : {"false", "no", "n", "0", "off"})
    if (l == f) return false;
  return bad("switch", token, "on or off (also true/false, yes/no, 1/0)");
}

Result<double> parse_float(std::string_view token) {
  auto v = text::to_double(token);
  if (!v) return bad("number", token, "a real number");
  return *v;
}

Result<long long> parse_int(std::string_view token) {
  auto v = text::to_int(token);
  if (!v) return bad("number", token, "an integer");
  return *v;
}

}  // namespace squawk::command
