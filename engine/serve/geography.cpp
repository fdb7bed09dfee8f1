#include "serve/geography.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>

#include "core/files.h"

namespace squawk::serve {

namespace {

using nlohmann::json;

void extend(Polyline& p, float lat, float lon) {
  p.pts.push_back(lat);
  p.pts.push_back(lon);
  p.south = std::min(p.south, lat);
  p.north = std::max(p.north, lat);
  p.west = std::min(p.west, lon);
  p.east = std::max(p.east, lon);
}

// Calls fn(line) for each line of `text`, without blanks and carriage
// returns at either end (BlueSky's coastlines.dat ends lines "\r\n\r").
template <class Fn>
void each_line(std::string_view text, Fn fn) {
  while (!text.empty()) {
    const size_t nl = text.find('\n');
    std::string_view line = text.substr(0, nl);
    while (!line.empty() && (line.front() == '\r' || line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.remove_suffix(1);
    fn(line);
    if (nl == std::string_view::npos) break;
    text.remove_prefix(nl + 1);
  }
}

// Two numbers after the first character of `line` ("M 68.18 68.28"), or false.
bool two_numbers(std::string_view line, double& a, double& b) {
  const std::string s(line.substr(1));
  char* end = nullptr;
  a = std::strtod(s.c_str(), &end);
  if (end == s.c_str()) return false;
  const char* second = end;
  b = std::strtod(second, &end);
  return end != second && std::isfinite(a) && std::isfinite(b) && std::fabs(a) <= 90 && std::fabs(b) <= 180;
}

json points_json(const Polyline& p, double step, size_t& budget) {
  json out = json::array();
  const size_t n = p.pts.size() / 2;
  double last_lat = 1e9, last_lon = 1e9;
  for (size_t i = 0; i < n && budget > 0; ++i) {
    const double lat = p.pts[2 * i], lon = p.pts[2 * i + 1];
    if (i + 1 < n && i > 0 && std::max(std::fabs(lat - last_lat), std::fabs(lon - last_lon)) < step) continue;
    out.push_back(std::round(lat * 1e4) / 1e4);  // the files' precision, as short text
    out.push_back(std::round(lon * 1e4) / 1e4);
    last_lat = lat;
    last_lon = lon;
    --budget;
  }
  return out;
}

bool meets(const Polyline& p, const GeoBox& b) {
  return !p.pts.empty() && p.north >= b.lat0 && p.south <= b.lat1 && p.east >= b.lon0 && p.west <= b.lon1;
}

}  // namespace

std::vector<Polyline> Geography::parse_coastlines(std::string_view text) {
  std::vector<Polyline> out;
  each_line(text, [&](std::string_view line) {
    double lat = 0, lon = 0;
    if (line.empty() || (line[0] != 'M' && line[0] != 'D') || !two_numbers(line, lat, lon)) return;
    if (line[0] == 'M' || out.empty()) {
      if (!out.empty() && out.back().pts.size() < 4) out.pop_back();  // a lone point draws nothing
      out.emplace_back();
    }
    extend(out.back(), static_cast<float>(lat), static_cast<float>(lon));
  });
  if (!out.empty() && out.back().pts.size() < 4) out.pop_back();
  return out;
}

double Geography::parse_dms(std::string_view t) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (t.size() < 2) return kNaN;
  const char h = t[0];
  if (h != 'N' && h != 'S' && h != 'E' && h != 'W') return kNaN;
  double parts[4] = {0, 0, 0, 0};
  int k = 0;
  std::string_view rest = t.substr(1);
  while (!rest.empty() && k < 4) {
    const size_t dot = rest.find('.');
    const std::string field(rest.substr(0, dot));
    if (field.empty() || field.find_first_not_of("0123456789") != std::string::npos) return kNaN;
    parts[k++] = std::strtod(field.c_str(), nullptr);
    rest = dot == std::string_view::npos ? std::string_view() : rest.substr(dot + 1);
  }
  if (k < 3 || !rest.empty()) return kNaN;
  const double deg = parts[0] + parts[1] / 60.0 + (parts[2] + parts[3] / 1000.0) / 3600.0;
  if (deg > ((h == 'N' || h == 'S') ? 90.0 : 180.0)) return kNaN;
  return (h == 'S' || h == 'W') ? -deg : deg;
}

Polyline Geography::parse_fir(std::string_view text, std::string name) {
  Polyline p;
  p.name = std::move(name);
  each_line(text, [&](std::string_view line) {
    const size_t sp = line.find_first_of(" \t");
    if (sp == std::string_view::npos) return;
    std::string_view second = line.substr(sp);
    second.remove_prefix(std::min(second.size(), second.find_first_not_of(" \t")));
    second = second.substr(0, second.find_first_of(" \t"));
    const double lat = parse_dms(line.substr(0, sp)), lon = parse_dms(second);
    if (!std::isfinite(lat) || !std::isfinite(lon)) return;
    const size_t n = p.pts.size();
    if (n >= 2 && p.pts[n - 2] == static_cast<float>(lat) && p.pts[n - 1] == static_cast<float>(lon)) return;
    extend(p, static_cast<float>(lat), static_cast<float>(lon));
  });
  return p;
}

Result<Geography> Geography::load(const std::string& dir) {
  namespace fs = std::filesystem;
  Geography g;
  const std::string coast = dir + "/coastlines.dat";
  if (files::exists(coast)) {
    auto text = files::read(coast);
    if (!text) return text.status();
    g.coast_ = parse_coastlines(*text);
  }
  std::error_code ec;
  if (fs::is_directory(dir + "/fir", ec)) {
    std::vector<fs::path> paths;
    for (const auto& e : fs::directory_iterator(dir + "/fir", ec))
      if (e.path().extension() == ".txt") paths.push_back(e.path());
    std::sort(paths.begin(), paths.end());
    for (const auto& p : paths) {
      auto text = files::read(p.string());
      if (!text) return text.status();
      Polyline f = parse_fir(*text, p.stem().string());
      if (f.pts.size() >= 4) g.fir_.push_back(std::move(f));
    }
  }
  return g;
}

json Geography::in_box(const GeoBox& box, double step_deg, size_t max_points) const {
  json out = {{"coast", json::array()}, {"fir", json::array()}, {"truncated", false}};
  size_t budget = max_points;
  for (const auto& f : fir_)
    if (meets(f, box) && budget > 0) out["fir"].push_back({{"name", f.name}, {"pts", points_json(f, step_deg, budget)}});
  for (const auto& c : coast_) {
    if (!meets(c, box)) continue;
    if (budget == 0) {
      out["truncated"] = true;
      break;
    }
    // A coastline smaller than the step is a dot at this zoom: left out.
    if (std::max(c.north - c.south, c.east - c.west) < step_deg) continue;
    out["coast"].push_back(points_json(c, step_deg, budget));
  }
  return out;
}

}  // namespace squawk::serve
